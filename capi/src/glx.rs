//! GLX 1.4 over Xlib, the way Mesa's software Xlib driver did it: fixedgl renders on the CPU
//! and shows each frame in the window with `XPutImage` (`XShmPutImage` when MIT-SHM is there
//! and the display is local). The X server needs no GLX extension of its own, so this works on
//! Xvfb, a desktop, or a remote display alike.
//!
//! - Visuals: the screen's 24-bit TrueColor visual (`XMatchVisualInfo`), handed out in
//!   Xlib-allocated memory (`XGetVisualInfo`), which the caller `XFree`s.
//! - FBConfigs: four, RGB8 (GLX_ALPHA_SIZE 0: ALPHA_BITS 0, destination alpha reads 1) and
//!   RGBA8, each with 24-bit depth and 8-bit stencil, single-buffered (window, pixmap, pbuffer)
//!   and double-buffered (window, pbuffer), as handles into a static table in GLX 1.4 §3.3.3's
//!   order (the RGB8 ones first: a request without alpha gets no alpha, as from Mesa); the arrays
//!   of them are `malloc`ed (XFree is free()).
//! - Contexts are the C layer's (`current.rs`) with the config they were made for; a window is
//!   a `Surface` (`xwin.rs`) whose size is read at MakeCurrent, glViewport and after each
//!   present, so the framebuffer follows resizes. Double-buffered drawables present at
//!   glXSwapBuffers, single-buffered ones at glFlush/glFinish.
//! - GLX errors are reported by the return value (NULL, False, 0, a GLX_BAD_* code) and a line
//!   on stderr; no X protocol error is raised for them (the server's GLX is not involved), so a
//!   program's X error handler sees none.
//!
//! Handles the program passes back (contexts, configs, drawables, visuals) are looked up in
//! registries, never dereferenced unchecked; a NULL display or a stale context fails cleanly.

use std::cell::Cell;
use std::ffi::{c_char, c_int, c_uint, c_ulong, c_void, CStr};
use std::sync::Mutex;

use x11_dl::xlib::{self, Display, XVisualInfo, Xlib};

use fixedgl::ContextConfig;

use crate::current::{self, guard, with_gl, Gl};
use crate::read;
use crate::xwin::{self, Kind, XDrawable, XSurface};

type Bool = c_int;
const TRUE: Bool = 1;
const FALSE: Bool = 0;

const GLX_USE_GL: c_int = 1;
const GLX_BUFFER_SIZE: c_int = 2;
const GLX_LEVEL: c_int = 3;
const GLX_RGBA: c_int = 4;
const GLX_DOUBLEBUFFER: c_int = 5;
const GLX_STEREO: c_int = 6;
const GLX_AUX_BUFFERS: c_int = 7;
const GLX_RED_SIZE: c_int = 8;
const GLX_GREEN_SIZE: c_int = 9;
const GLX_BLUE_SIZE: c_int = 10;
const GLX_ALPHA_SIZE: c_int = 11;
const GLX_DEPTH_SIZE: c_int = 12;
const GLX_STENCIL_SIZE: c_int = 13;
const GLX_ACCUM_RED_SIZE: c_int = 14;
const GLX_ACCUM_GREEN_SIZE: c_int = 15;
const GLX_ACCUM_BLUE_SIZE: c_int = 16;
const GLX_ACCUM_ALPHA_SIZE: c_int = 17;

const GLX_BAD_ATTRIBUTE: c_int = 2;
const GLX_NO_EXTENSION: c_int = 3;
const GLX_BAD_VISUAL: c_int = 4;
const GLX_BAD_CONTEXT: c_int = 5;
const GLX_BAD_VALUE: c_int = 6;

const GLX_VENDOR: c_int = 1;
const GLX_VERSION: c_int = 2;
const GLX_EXTENSIONS: c_int = 3;

const GLX_CONFIG_CAVEAT: c_int = 0x20;
const GLX_DONT_CARE: c_int = -1;
const GLX_X_VISUAL_TYPE: c_int = 0x22;
const GLX_TRANSPARENT_TYPE: c_int = 0x23;
const GLX_TRANSPARENT_INDEX_VALUE: c_int = 0x24;
const GLX_TRANSPARENT_RED_VALUE: c_int = 0x25;
const GLX_TRANSPARENT_GREEN_VALUE: c_int = 0x26;
const GLX_TRANSPARENT_BLUE_VALUE: c_int = 0x27;
const GLX_TRANSPARENT_ALPHA_VALUE: c_int = 0x28;
const GLX_WINDOW_BIT: c_int = 0x1;
const GLX_PIXMAP_BIT: c_int = 0x2;
const GLX_PBUFFER_BIT: c_int = 0x4;
const GLX_NONE: c_int = 0x8000;
const GLX_TRUE_COLOR: c_int = 0x8002;
const GLX_VISUAL_ID: c_int = 0x800B;
const GLX_SCREEN: c_int = 0x800C;
const GLX_DRAWABLE_TYPE: c_int = 0x8010;
const GLX_RENDER_TYPE: c_int = 0x8011;
const GLX_X_RENDERABLE: c_int = 0x8012;
const GLX_FBCONFIG_ID: c_int = 0x8013;
const GLX_RGBA_TYPE: c_int = 0x8014;
const GLX_MAX_PBUFFER_WIDTH: c_int = 0x8016;
const GLX_MAX_PBUFFER_HEIGHT: c_int = 0x8017;
const GLX_MAX_PBUFFER_PIXELS: c_int = 0x8018;
const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
const GLX_LARGEST_PBUFFER: c_int = 0x801C;
const GLX_WIDTH: c_int = 0x801D;
const GLX_HEIGHT: c_int = 0x801E;
const GLX_EVENT_MASK: c_int = 0x801F;
const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
const GLX_PBUFFER_WIDTH: c_int = 0x8041;
const GLX_RGBA_BIT: c_int = 0x1;
const GLX_SAMPLE_BUFFERS: c_int = 100_000;
const GLX_SAMPLES: c_int = 100_001;
const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;

const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
const GLX_CONTEXT_FLAGS_ARB: c_int = 0x2094;
const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 0x1;
const GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB: c_int = 0x2;

/// The largest pbuffer side (fixedgl's MAX_VIEWPORT_DIMS).
const MAX_SIDE: c_int = 16384;
/// The most swap-interval frames GLX_MESA_swap_control accepts.
const MAX_SWAP_INTERVAL: c_uint = 8;

/// What GLX offers, client and "server" alike (the server's own GLX is not used).
const EXTENSIONS: &CStr = c"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_MESA_swap_control";
const VENDOR: &CStr = c"fixedgl";
const VERSION: &CStr = c"1.4";

/// Says on stderr why a GLX call failed, once for each call and reason (at most 256 lines).
fn say(call: &'static str, message: impl FnOnce() -> String) {
    static SAID: Mutex<Vec<String>> = Mutex::new(Vec::new());
    let line = format!("fixedgl: {call}: {}", message());
    let mut said = SAID.lock().unwrap_or_else(|e| e.into_inner());
    if said.len() < 256 && !said.contains(&line) {
        eprintln!("{line}");
        said.push(line);
    }
}

// ----- FBConfigs ------------------------------------------------------------------------------

/// One framebuffer configuration: RGB8 or RGBA8, depth 24, stencil 8 (fixedgl's framebuffer
/// formats); they differ in alpha bits, double-buffering and the drawables they allow.
#[derive(Debug)]
pub struct FbConfig {
    id: c_int,
    double: bool,
    /// 8 alpha bits (RGBA8); without them ALPHA_BITS is 0 (`ContextConfig::alpha`).
    alpha: bool,
}

/// In GLX's sort order (GLX 1.4 §3.3.3): whatever colour sizes are asked, the two formats tie
/// on the colour bits counted (alpha counts only when asked for, and then only RGBA8 matches),
/// so the smaller GLX_BUFFER_SIZE (24, RGB8) comes first, as Mesa lists its alpha-less configs
/// first (`fbconfig_compare`: PREFER_LARGER_OR_ZERO on alpha); then single-buffered first
/// (GLX_DOUBLEBUFFER "smaller"). The RGBA8 configs keep IDs 1 and 2, which they had alone.
static CONFIGS: [FbConfig; 4] = [
    FbConfig {
        id: 3,
        double: false,
        alpha: false,
    },
    FbConfig {
        id: 4,
        double: true,
        alpha: false,
    },
    FbConfig {
        id: 1,
        double: false,
        alpha: true,
    },
    FbConfig {
        id: 2,
        double: true,
        alpha: true,
    },
];
/// The config of a visual GLX 1.2 programs got elsewhere (XMatchVisualInfo, say): RGBA8 and
/// double-buffered, what Mesa 22.3's GLX on Xvfb gives the screen's default 24-bit TrueColor
/// visual (GLX_ALPHA_SIZE 8, GLX_DOUBLEBUFFER 1, ALPHA_BITS 8 in a context made on it).
const DOUBLE: usize = 3;

fn config_handle(i: usize) -> *mut c_void {
    std::ptr::addr_of!(CONFIGS[i]).cast_mut().cast()
}

/// The index of a config handle; `None` for what is not one.
fn config_index(h: *const c_void) -> Option<usize> {
    (0..CONFIGS.len()).find(|&i| config_handle(i).cast_const() == h)
}

fn drawable_types(i: usize) -> c_int {
    if CONFIGS[i].double {
        GLX_WINDOW_BIT | GLX_PBUFFER_BIT
    } else {
        GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT
    }
}

fn default_screen(x: &Xlib, dpy: *mut Display) -> c_int {
    // SAFETY: an open display (checked non-null by the callers).
    unsafe { (x.XDefaultScreen)(dpy) }
}

/// Attribute `attr` of config `i` on `screen` of `dpy`; `None` when it is no attribute.
fn config_attrib(
    x: &Xlib,
    dpy: *mut Display,
    screen: c_int,
    i: usize,
    attr: c_int,
) -> Option<c_int> {
    let visual = xwin::true_color(x, dpy, screen);
    Some(match attr {
        GLX_FBCONFIG_ID => CONFIGS[i].id,
        GLX_BUFFER_SIZE => 24 + 8 * c_int::from(CONFIGS[i].alpha),
        GLX_LEVEL | GLX_STEREO | GLX_AUX_BUFFERS => 0,
        GLX_DOUBLEBUFFER => c_int::from(CONFIGS[i].double),
        GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE => 8,
        GLX_ALPHA_SIZE => 8 * c_int::from(CONFIGS[i].alpha),
        GLX_DEPTH_SIZE => 24,
        GLX_STENCIL_SIZE => 8,
        // 16 bits a channel, signed, as llvmpipe's (fixedgl's accumulation buffer).
        GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE => {
            16
        }
        GLX_RENDER_TYPE => GLX_RGBA_BIT,
        GLX_DRAWABLE_TYPE => drawable_types(i),
        GLX_X_RENDERABLE => c_int::from(visual.is_some()),
        GLX_VISUAL_ID => visual.map_or(0, |v| v.visualid as c_int),
        GLX_X_VISUAL_TYPE => visual.map_or(GLX_NONE, |_| GLX_TRUE_COLOR),
        GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE => GLX_NONE,
        GLX_TRANSPARENT_INDEX_VALUE
        | GLX_TRANSPARENT_RED_VALUE
        | GLX_TRANSPARENT_GREEN_VALUE
        | GLX_TRANSPARENT_BLUE_VALUE
        | GLX_TRANSPARENT_ALPHA_VALUE => 0,
        GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT => MAX_SIDE,
        GLX_MAX_PBUFFER_PIXELS => MAX_SIDE * MAX_SIDE / 4,
        GLX_SAMPLE_BUFFERS | GLX_SAMPLES => 0,
        GLX_SCREEN => screen,
        _ => return None,
    })
}

/// How a requested value is matched (GLX 1.4 table 3.4).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Rule {
    Exact,
    AtLeast,
    Mask,
    Ignored,
}

fn rule(attr: c_int) -> Option<Rule> {
    Some(match attr {
        GLX_BUFFER_SIZE | GLX_AUX_BUFFERS | GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE
        | GLX_ALPHA_SIZE | GLX_DEPTH_SIZE | GLX_STENCIL_SIZE | GLX_ACCUM_RED_SIZE
        | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE
        | GLX_SAMPLE_BUFFERS | GLX_SAMPLES => Rule::AtLeast,
        GLX_RENDER_TYPE | GLX_DRAWABLE_TYPE => Rule::Mask,
        GLX_MAX_PBUFFER_WIDTH
        | GLX_MAX_PBUFFER_HEIGHT
        | GLX_MAX_PBUFFER_PIXELS
        | GLX_VISUAL_ID
        | GLX_SCREEN => Rule::Ignored,
        GLX_FBCONFIG_ID
        | GLX_LEVEL
        | GLX_DOUBLEBUFFER
        | GLX_STEREO
        | GLX_X_RENDERABLE
        | GLX_X_VISUAL_TYPE
        | GLX_CONFIG_CAVEAT
        | GLX_TRANSPARENT_TYPE
        | GLX_TRANSPARENT_INDEX_VALUE
        | GLX_TRANSPARENT_RED_VALUE
        | GLX_TRANSPARENT_GREEN_VALUE
        | GLX_TRANSPARENT_BLUE_VALUE
        | GLX_TRANSPARENT_ALPHA_VALUE => Rule::Exact,
        _ => return None,
    })
}

/// The pairs of a None-terminated attribute list (at most 128 pairs; NULL is empty).
unsafe fn pairs(list: *const c_int) -> Vec<(c_int, c_int)> {
    let mut out = Vec::new();
    for i in 0..128 {
        // SAFETY: a None-terminated list of pairs (GLX's contract).
        let Some([k, v]) = (unsafe { read::array::<c_int, 2>(list.wrapping_add(2 * i)) }) else {
            break;
        };
        if k == 0 {
            break;
        }
        out.push((k, v));
    }
    out
}

/// glXChooseFBConfig's choice: the configs meeting every request, in GLX's order; `Err` with
/// the reason for an attribute GLX does not define.
fn choose(
    x: &Xlib,
    dpy: *mut Display,
    screen: c_int,
    wanted: &[(c_int, c_int)],
) -> Result<Vec<usize>, String> {
    let mut want: Vec<(c_int, c_int)> = vec![
        (GLX_RENDER_TYPE, GLX_RGBA_BIT),
        (GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT),
        (GLX_LEVEL, 0),
        (GLX_STEREO, FALSE),
        (GLX_TRANSPARENT_TYPE, GLX_NONE),
    ];
    for &(k, v) in wanted {
        if rule(k).is_none() {
            return Err(format!(
                "attribute {k:#x} is not one fixedgl's configs have"
            ));
        }
        want.retain(|(a, _)| *a != k);
        want.push((k, v));
    }
    // GLX_FBCONFIG_ID: that config alone, whatever else was asked (GLX 1.4 §3.3.3).
    if let Some(&(_, id)) = want
        .iter()
        .find(|(k, v)| *k == GLX_FBCONFIG_ID && *v != GLX_DONT_CARE)
    {
        return Ok((0..CONFIGS.len())
            .filter(|&i| CONFIGS[i].id == id)
            .collect());
    }
    Ok((0..CONFIGS.len())
        .filter(|&i| {
            want.iter().all(|&(k, v)| {
                if v == GLX_DONT_CARE {
                    return true;
                }
                let have = config_attrib(x, dpy, screen, i, k).unwrap_or(0);
                match rule(k) {
                    Some(Rule::AtLeast) => have >= v,
                    Some(Rule::Mask) => have & v == v,
                    Some(Rule::Exact) => have == v,
                    Some(Rule::Ignored) | None => true,
                }
            })
        })
        .collect())
}

/// `items` in memory from `malloc` (GLX hands arrays out that the caller frees with XFree, which
/// is free()); NULL when empty or out of memory.
fn malloc_array<T: Copy>(items: &[T]) -> *mut T {
    if items.is_empty() {
        return std::ptr::null_mut();
    }
    // SAFETY: malloc of the array's size; filled before it is handed out.
    unsafe {
        let p = libc::malloc(std::mem::size_of_val(items)).cast::<T>();
        if !p.is_null() {
            std::ptr::copy_nonoverlapping(items.as_ptr(), p, items.len());
        }
        p
    }
}

// ----- Visuals handed out ---------------------------------------------------------------------

/// XVisualInfo addresses handed out, with the config each stands for (GLX 1.2 programs pass
/// them back to glXCreateContext); the most recent 256.
static VISUALS: Mutex<Vec<(usize, usize)>> = Mutex::new(Vec::new());

/// The XVisualInfo of config `i` on `screen`, in Xlib's memory; NULL without a usable visual.
fn visual_of(x: &Xlib, dpy: *mut Display, screen: c_int, i: usize) -> *mut XVisualInfo {
    let Some(vi) = xwin::true_color(x, dpy, screen) else {
        say("glXChooseVisual", || {
            "the screen has no 24-bit TrueColor visual, the one fixedgl renders for".into()
        });
        return std::ptr::null_mut();
    };
    // SAFETY: XVisualInfo is plain data; the template names the visual and screen.
    let mut template: XVisualInfo = unsafe { std::mem::zeroed() };
    template.visualid = vi.visualid;
    template.screen = screen;
    let mut n = 0;
    // SAFETY: an open display; Xlib allocates the answer (the caller XFrees it).
    let p = unsafe {
        (x.XGetVisualInfo)(
            dpy,
            xlib::VisualIDMask | xlib::VisualScreenMask,
            &mut template,
            &mut n,
        )
    };
    if !p.is_null() {
        let mut all = VISUALS.lock().unwrap_or_else(|e| e.into_inner());
        all.retain(|(a, _)| *a != p as usize);
        if all.len() >= 256 {
            all.remove(0);
        }
        all.push((p as usize, i));
    }
    p
}

/// The config a visual stands for: the one it was handed out for, else (a visual the program
/// found itself) double-buffered if fixedgl can render for it at all.
unsafe fn config_of_visual(vis: *const XVisualInfo) -> Option<usize> {
    if vis.is_null() {
        return None;
    }
    let known = VISUALS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(&(_, i)) = known.iter().find(|(a, _)| *a == vis as usize) {
        return Some(i);
    }
    // SAFETY: an XVisualInfo (GLX's contract).
    let v = unsafe { &*vis };
    xwin::presentable(v.class, v.depth).then_some(DOUBLE)
}

// ----- Contexts -------------------------------------------------------------------------------

/// What a GLX context is beyond its `Gl`: the config and screen it was made for.
#[derive(Clone, Copy, Debug)]
struct GlxContext {
    config: usize,
    screen: c_int,
}

static CONTEXTS: Mutex<Vec<(usize, GlxContext)>> = Mutex::new(Vec::new());

fn glx_context(ctx: *const c_void) -> Option<GlxContext> {
    if !current::is_live(ctx.cast()) {
        return None;
    }
    let all = CONTEXTS.lock().unwrap_or_else(|e| e.into_inner());
    all.iter()
        .find(|(a, _)| *a == ctx as usize)
        .map(|(_, c)| *c)
}

fn create_context(config: usize, screen: c_int, share: *mut c_void) -> *mut c_void {
    if !share.is_null() && glx_context(share).is_none() {
        say("glXCreateContext", || {
            "the share context is not a GLX context".into()
        });
        return std::ptr::null_mut();
    }
    // The config's buffers: a back buffer when double-buffered (DrawBuffer and ReadBuffer
    // default to BACK, SwapBuffers exchanges them), and the accumulation buffer every config has.
    let buffers = ContextConfig {
        double_buffered: CONFIGS.get(config).is_some_and(|c| c.double),
        accum: true,
        alpha: CONFIGS.get(config).map_or(true, |c| c.alpha),
        ..ContextConfig::default()
    };
    // A share context shares its display lists, textures and buffer objects (appendix D).
    let Some(gl) = Gl::with_config_shared(1, 1, buffers, share.cast()) else {
        return std::ptr::null_mut();
    };
    let p = current::register(gl);
    let mut all = CONTEXTS.lock().unwrap_or_else(|e| e.into_inner());
    all.retain(|(a, _)| *a != p as usize);
    all.push((p as usize, GlxContext { config, screen }));
    p.cast()
}

thread_local! {
    /// The calling thread's current GLX display, draw and read drawables.
    static CUR_DISPLAY: Cell<usize> = const { Cell::new(0) };
    static CUR_DRAW: Cell<c_ulong> = const { Cell::new(0) };
    static CUR_READ: Cell<c_ulong> = const { Cell::new(0) };
}

fn set_current(dpy: *mut Display, draw: c_ulong, read: c_ulong) {
    let _ = CUR_DISPLAY.try_with(|c| c.set(dpy as usize));
    let _ = CUR_DRAW.try_with(|c| c.set(draw));
    let _ = CUR_READ.try_with(|c| c.set(read));
}

/// The current context if it is a GLX one (null otherwise).
fn current_glx() -> *mut c_void {
    let p = current::current();
    if glx_context(p.cast()).is_some() {
        p.cast()
    } else {
        std::ptr::null_mut()
    }
}

/// The drawable `xid` of `dpy` as fixedgl renders to it: known already, or an X window met
/// for the first time (GLX 1.2 programs pass their windows directly). `None` (said once) when
/// it is neither.
fn drawable_for(
    x: &Xlib,
    dpy: *mut Display,
    xid: c_ulong,
) -> Option<std::sync::Arc<Mutex<XDrawable>>> {
    if let Some(d) = xwin::find(dpy, xid) {
        let reused = {
            let mut g = xwin::lock(&d);
            // A window fixedgl met by itself may have been destroyed and its XID reused.
            g.kind == Kind::Window && g.config.is_none() && !g.exists()
        };
        if !reused {
            return Some(d);
        }
    }
    match XDrawable::window(x, dpy, xid, None) {
        Ok(d) => Some(xwin::insert(d)),
        Err(e) => {
            say("glXMakeCurrent", || format!("{e} (GLXBadDrawable)"));
            None
        }
    }
}

fn make_current(dpy: *mut Display, draw: c_ulong, read: c_ulong, ctx: *mut c_void) -> Bool {
    if ctx.is_null() {
        if draw != 0 || read != 0 {
            say("glXMakeCurrent", || {
                "a drawable without a context (BadMatch)".into()
            });
            return FALSE;
        }
        current::release_current();
        set_current(std::ptr::null_mut(), 0, 0);
        return TRUE;
    }
    let Some(info) = glx_context(ctx) else {
        say("glXMakeCurrent", || {
            "not a GLX context, or one destroyed (GLXBadContext)".into()
        });
        return FALSE;
    };
    if draw == 0 || read == 0 {
        say("glXMakeCurrent", || {
            "a context without a drawable (BadMatch)".into()
        });
        return FALSE;
    }
    if dpy.is_null() {
        return FALSE;
    }
    let Some(x) = xwin::xlib() else { return FALSE };
    let Some(d) = drawable_for(x, dpy, draw) else {
        return FALSE;
    };
    if read != draw {
        if drawable_for(x, dpy, read).is_none() {
            return FALSE;
        }
        say("glXMakeContextCurrent", || {
            "a read drawable other than the draw drawable: fixedgl reads from the draw drawable"
                .into()
        });
    }
    let double = {
        let g = xwin::lock(&d);
        g.kind != Kind::Pixmap && CONFIGS[g.config.unwrap_or(info.config)].double
    };
    let surface = XSurface {
        drawable: d,
        double,
    };
    if current::make_current(ctx.cast(), Some(Box::new(surface))).is_err() {
        say("glXMakeCurrent", || {
            "the context is current on another thread (BadAccess)".into()
        });
        return FALSE;
    }
    set_current(dpy, draw, read);
    TRUE
}

/// glXSwapBuffers on the current drawable: presents the back buffer (the frame just drawn),
/// then exchanges the buffers (`Context::swap_buffers`: the back buffer becomes the front one).
/// The frame is recorded and shown before the swap, so that a recording's replay reads the same
/// buffer; the swap itself goes into the next frame's calls. A single-buffered context's swap
/// changes no buffer (GLX: no effect), but still presents.
fn swap_buffers(gl: &mut Gl) {
    gl.present_frame();
    gl.ctx.swap_buffers();
}

// ----- Entry points ---------------------------------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(name: *const c_char) -> *const c_void {
    guard("glXGetProcAddress", std::ptr::null(), || {
        if name.is_null() {
            return std::ptr::null();
        }
        // SAFETY: a NUL-terminated name (the API's contract).
        let name = unsafe { CStr::from_ptr(name) }.to_bytes();
        glx_proc(name)
            .or_else(|| crate::proc_address(name))
            .unwrap_or(std::ptr::null())
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(name: *const c_char) -> *const c_void {
    // SAFETY: the same contract.
    unsafe { glXGetProcAddress(name) }
}

#[no_mangle]
pub unsafe extern "C" fn glXQueryExtension(
    dpy: *mut Display,
    error_base: *mut c_int,
    event_base: *mut c_int,
) -> Bool {
    guard("glXQueryExtension", FALSE, || {
        let Some(x) = xwin::xlib() else { return FALSE };
        if dpy.is_null() {
            return FALSE;
        }
        // The bases of the server's GLX if it has one (GLX itself is client-side here).
        let (mut op, mut ev, mut er) = (0, 0, 0);
        // SAFETY: an open display.
        unsafe { (x.XQueryExtension)(dpy, c"GLX".as_ptr(), &mut op, &mut ev, &mut er) };
        // SAFETY: one value each, where given.
        unsafe {
            if let Some(s) = read::slice_mut(error_base, 1).first_mut() {
                *s = er;
            }
            if let Some(s) = read::slice_mut(event_base, 1).first_mut() {
                *s = ev;
            }
        }
        TRUE
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXQueryVersion(
    dpy: *mut Display,
    major: *mut c_int,
    minor: *mut c_int,
) -> Bool {
    guard("glXQueryVersion", FALSE, || {
        if dpy.is_null() {
            return FALSE;
        }
        // SAFETY: one value each, where given.
        unsafe {
            if let Some(s) = read::slice_mut(major, 1).first_mut() {
                *s = 1;
            }
            if let Some(s) = read::slice_mut(minor, 1).first_mut() {
                *s = 4;
            }
        }
        TRUE
    })
}

#[no_mangle]
pub extern "C" fn glXQueryExtensionsString(dpy: *mut Display, _screen: c_int) -> *const c_char {
    guard("glXQueryExtensionsString", std::ptr::null(), || {
        if dpy.is_null() {
            return std::ptr::null();
        }
        EXTENSIONS.as_ptr()
    })
}

fn string(name: c_int) -> *const c_char {
    match name {
        GLX_VENDOR => VENDOR.as_ptr(),
        GLX_VERSION => VERSION.as_ptr(),
        GLX_EXTENSIONS => EXTENSIONS.as_ptr(),
        _ => std::ptr::null(),
    }
}

#[no_mangle]
pub extern "C" fn glXGetClientString(_dpy: *mut Display, name: c_int) -> *const c_char {
    guard("glXGetClientString", std::ptr::null(), || string(name))
}

#[no_mangle]
pub extern "C" fn glXQueryServerString(
    dpy: *mut Display,
    _screen: c_int,
    name: c_int,
) -> *const c_char {
    guard("glXQueryServerString", std::ptr::null(), || {
        if dpy.is_null() {
            return std::ptr::null();
        }
        string(name)
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXChooseVisual(
    dpy: *mut Display,
    screen: c_int,
    attribs: *const c_int,
) -> *mut XVisualInfo {
    guard("glXChooseVisual", std::ptr::null_mut(), || {
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        // GLX 1.2 lists: booleans (RGBA, DOUBLEBUFFER, STEREO, USE_GL) stand alone, the rest
        // take a value; DOUBLEBUFFER absent means single-buffered.
        let (mut rgba, mut double, mut want) = (false, false, Vec::new());
        let mut i = 0;
        while i < 256 {
            // SAFETY: a None-terminated list (GLX's contract); NULL is empty.
            let Some([k]) = (unsafe { read::array::<c_int, 1>(attribs.wrapping_add(i)) }) else {
                break;
            };
            i += 1;
            match k {
                0 => break,
                GLX_USE_GL => {}
                GLX_RGBA => rgba = true,
                GLX_DOUBLEBUFFER => double = true,
                GLX_STEREO => want.push((GLX_STEREO, TRUE)),
                _ if rule(k).is_some() => {
                    // SAFETY: as above.
                    let Some([v]) = (unsafe { read::array::<c_int, 1>(attribs.wrapping_add(i)) })
                    else {
                        break;
                    };
                    i += 1;
                    want.push((k, v));
                }
                _ => {
                    say("glXChooseVisual", || {
                        format!("attribute {k:#x} is not one fixedgl's visuals have")
                    });
                    return std::ptr::null_mut();
                }
            }
        }
        if !rgba {
            say("glXChooseVisual", || {
                "colour-index visuals (no GLX_RGBA) are not supported; fixedgl renders RGBA".into()
            });
            return std::ptr::null_mut();
        }
        want.push((GLX_DOUBLEBUFFER, c_int::from(double)));
        // GLX_BUFFER_SIZE counts colour-index bits: ignored for RGBA visuals.
        want.retain(|(k, _)| *k != GLX_BUFFER_SIZE);
        match choose(x, dpy, screen, &want) {
            Ok(found) => match found.first() {
                Some(&c) => visual_of(x, dpy, screen, c),
                None => {
                    say("glXChooseVisual", || {
                        "no visual meets the request (fixedgl has RGB8 and RGBA8, depth 24, stencil 8, a 16-bit accumulation buffer, no stereo, no multisampling)".into()
                    });
                    std::ptr::null_mut()
                }
            },
            Err(e) => {
                say("glXChooseVisual", || e);
                std::ptr::null_mut()
            }
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetConfig(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    attrib: c_int,
    value: *mut c_int,
) -> c_int {
    guard("glXGetConfig", GLX_BAD_VISUAL, || {
        let Some(x) = xwin::xlib() else {
            return GLX_NO_EXTENSION;
        };
        if dpy.is_null() {
            return GLX_NO_EXTENSION;
        }
        // SAFETY: an XVisualInfo from the program (GLX's contract).
        let config = unsafe { config_of_visual(vis) };
        let v = match (config, attrib) {
            (None, GLX_USE_GL) if !vis.is_null() => FALSE,
            (None, _) => return GLX_BAD_VISUAL,
            (Some(_), GLX_USE_GL | GLX_RGBA) => TRUE,
            (Some(i), _) => {
                // SAFETY: as above.
                let screen = unsafe { (*vis).screen };
                match config_attrib(x, dpy, screen, i, attrib) {
                    Some(v) => v,
                    None => return GLX_BAD_ATTRIBUTE,
                }
            }
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return GLX_BAD_VALUE,
        }
        0
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXChooseFBConfig(
    dpy: *mut Display,
    screen: c_int,
    attribs: *const c_int,
    n: *mut c_int,
) -> *mut *mut c_void {
    guard("glXChooseFBConfig", std::ptr::null_mut(), || {
        // SAFETY: one count.
        let count = unsafe { read::slice_mut(n, 1) };
        if let Some(c) = count.first_mut() {
            *c = 0;
        }
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        // SAFETY: an open display.
        if dpy.is_null() || screen < 0 || screen >= unsafe { (x.XScreenCount)(dpy) } {
            return std::ptr::null_mut();
        }
        // SAFETY: GLX's attribute list.
        let want = unsafe { pairs(attribs) };
        let found = match choose(x, dpy, screen, &want) {
            Ok(f) => f,
            Err(e) => {
                say("glXChooseFBConfig", || e);
                return std::ptr::null_mut();
            }
        };
        let handles: Vec<*mut c_void> = found.iter().map(|&i| config_handle(i)).collect();
        let p = malloc_array(&handles);
        if let (Some(c), false) = (count.first_mut(), p.is_null()) {
            *c = handles.len() as c_int;
        }
        p
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigs(
    dpy: *mut Display,
    screen: c_int,
    n: *mut c_int,
) -> *mut *mut c_void {
    guard("glXGetFBConfigs", std::ptr::null_mut(), || {
        // SAFETY: one count.
        let count = unsafe { read::slice_mut(n, 1) };
        if let Some(c) = count.first_mut() {
            *c = 0;
        }
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        // SAFETY: an open display.
        if dpy.is_null() || screen < 0 || screen >= unsafe { (x.XScreenCount)(dpy) } {
            return std::ptr::null_mut();
        }
        let handles: Vec<*mut c_void> = (0..CONFIGS.len()).map(config_handle).collect();
        let p = malloc_array(&handles);
        if let (Some(c), false) = (count.first_mut(), p.is_null()) {
            *c = handles.len() as c_int;
        }
        p
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigAttrib(
    dpy: *mut Display,
    config: *mut c_void,
    attribute: c_int,
    value: *mut c_int,
) -> c_int {
    guard("glXGetFBConfigAttrib", GLX_BAD_ATTRIBUTE, || {
        let Some(x) = xwin::xlib() else {
            return GLX_NO_EXTENSION;
        };
        if dpy.is_null() {
            return GLX_NO_EXTENSION;
        }
        let Some(i) = config_index(config) else {
            say("glXGetFBConfigAttrib", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return GLX_BAD_ATTRIBUTE;
        };
        let Some(v) = config_attrib(x, dpy, default_screen(x, dpy), i, attribute) else {
            return GLX_BAD_ATTRIBUTE;
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return GLX_BAD_VALUE,
        }
        0
    })
}

#[no_mangle]
pub extern "C" fn glXGetVisualFromFBConfig(
    dpy: *mut Display,
    config: *mut c_void,
) -> *mut XVisualInfo {
    guard("glXGetVisualFromFBConfig", std::ptr::null_mut(), || {
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        let Some(i) = config_index(config) else {
            return std::ptr::null_mut();
        };
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        visual_of(x, dpy, default_screen(x, dpy), i)
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXCreateContext(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    share: *mut c_void,
    _direct: Bool,
) -> *mut c_void {
    guard("glXCreateContext", std::ptr::null_mut(), || {
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        // SAFETY: an XVisualInfo from the program (GLX's contract).
        let Some(config) = (unsafe { config_of_visual(vis) }) else {
            say("glXCreateContext", || {
                "the visual is not a 24- or 32-bit TrueColor one fixedgl renders for (BadValue)"
                    .into()
            });
            return std::ptr::null_mut();
        };
        // SAFETY: as above (non-null: a config was found).
        let screen = unsafe { (*vis).screen };
        create_context(config, screen, share)
    })
}

#[no_mangle]
pub extern "C" fn glXCreateNewContext(
    dpy: *mut Display,
    config: *mut c_void,
    render_type: c_int,
    share: *mut c_void,
    _direct: Bool,
) -> *mut c_void {
    guard("glXCreateNewContext", std::ptr::null_mut(), || {
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        let Some(i) = config_index(config) else {
            say("glXCreateNewContext", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return std::ptr::null_mut();
        };
        if render_type != GLX_RGBA_TYPE {
            say("glXCreateNewContext", || {
                format!("render type {render_type:#x}: fixedgl renders RGBA (GLX_RGBA_TYPE) only")
            });
            return std::ptr::null_mut();
        }
        create_context(i, default_screen(x, dpy), share)
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXCreateContextAttribsARB(
    dpy: *mut Display,
    config: *mut c_void,
    share: *mut c_void,
    _direct: Bool,
    attribs: *const c_int,
) -> *mut c_void {
    guard("glXCreateContextAttribsARB", std::ptr::null_mut(), || {
        let Some(x) = xwin::xlib() else {
            return std::ptr::null_mut();
        };
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        let Some(i) = config_index(config) else {
            say("glXCreateContextAttribsARB", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return std::ptr::null_mut();
        };
        let (mut major, mut minor, mut flags, mut profile) = (1, 0, 0, 0);
        // SAFETY: GLX's attribute list.
        for (k, v) in unsafe { pairs(attribs) } {
            match k {
                GLX_CONTEXT_MAJOR_VERSION_ARB => major = v,
                GLX_CONTEXT_MINOR_VERSION_ARB => minor = v,
                GLX_CONTEXT_FLAGS_ARB => flags = v,
                GLX_CONTEXT_PROFILE_MASK_ARB => profile = v,
                GLX_RENDER_TYPE if v == GLX_RGBA_TYPE => {}
                _ => {
                    say("glXCreateContextAttribsARB", || {
                        format!("attribute {k:#x} = {v:#x} is not supported (BadValue)")
                    });
                    return std::ptr::null_mut();
                }
            }
        }
        // Flags beyond debug (1) and forward-compatible (2, meaningful from 3.0) are not
        // defined; the profile mask only counts from 3.2 (ARB_create_context_profile).
        let core = (major, minor) >= (3, 2) && profile & GLX_CONTEXT_CORE_PROFILE_BIT_ARB != 0;
        if (major, minor) > (1, 5) || flags & !3 != 0 || core || major < 1 {
            say("glXCreateContextAttribsARB", || {
                format!(
                    "OpenGL {major}.{minor}{}{} asked for; fixedgl is OpenGL 1.5 (BadMatch)",
                    if core { " core" } else { "" },
                    if flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB != 0 {
                        " forward-compatible"
                    } else {
                        ""
                    }
                )
            });
            return std::ptr::null_mut();
        }
        create_context(i, default_screen(x, dpy), share)
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyContext(_dpy: *mut Display, ctx: *mut c_void) {
    guard("glXDestroyContext", (), || {
        if glx_context(ctx).is_none() {
            say("glXDestroyContext", || {
                "not a GLX context, or one destroyed (GLXBadContext)".into()
            });
            return;
        }
        let was_current = current::current() == ctx.cast();
        if current::destroy(ctx.cast()) {
            CONTEXTS
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .retain(|(a, _)| *a != ctx as usize);
            if was_current {
                set_current(std::ptr::null_mut(), 0, 0);
            }
        }
    })
}

#[no_mangle]
pub extern "C" fn glXIsDirect(_dpy: *mut Display, ctx: *mut c_void) -> Bool {
    guard("glXIsDirect", FALSE, || {
        Bool::from(glx_context(ctx).is_some())
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXQueryContext(
    _dpy: *mut Display,
    ctx: *mut c_void,
    attribute: c_int,
    value: *mut c_int,
) -> c_int {
    guard("glXQueryContext", GLX_BAD_CONTEXT, || {
        let Some(c) = glx_context(ctx) else {
            return GLX_BAD_CONTEXT;
        };
        let v = match attribute {
            GLX_FBCONFIG_ID => CONFIGS[c.config].id,
            GLX_RENDER_TYPE => GLX_RGBA_TYPE,
            GLX_SCREEN => c.screen,
            _ => return GLX_BAD_ATTRIBUTE,
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return GLX_BAD_VALUE,
        }
        0
    })
}

#[no_mangle]
pub extern "C" fn glXMakeCurrent(dpy: *mut Display, drawable: c_ulong, ctx: *mut c_void) -> Bool {
    guard("glXMakeCurrent", FALSE, || {
        make_current(dpy, drawable, drawable, ctx)
    })
}

#[no_mangle]
pub extern "C" fn glXMakeContextCurrent(
    dpy: *mut Display,
    draw: c_ulong,
    read: c_ulong,
    ctx: *mut c_void,
) -> Bool {
    guard("glXMakeContextCurrent", FALSE, || {
        make_current(dpy, draw, read, ctx)
    })
}

#[no_mangle]
pub extern "C" fn glXGetCurrentContext() -> *mut c_void {
    guard("glXGetCurrentContext", std::ptr::null_mut(), current_glx)
}

#[no_mangle]
pub extern "C" fn glXGetCurrentDrawable() -> c_ulong {
    guard("glXGetCurrentDrawable", 0, || {
        if current_glx().is_null() {
            return 0;
        }
        CUR_DRAW.try_with(Cell::get).unwrap_or(0)
    })
}

#[no_mangle]
pub extern "C" fn glXGetCurrentReadDrawable() -> c_ulong {
    guard("glXGetCurrentReadDrawable", 0, || {
        if current_glx().is_null() {
            return 0;
        }
        CUR_READ.try_with(Cell::get).unwrap_or(0)
    })
}

#[no_mangle]
pub extern "C" fn glXGetCurrentDisplay() -> *mut Display {
    guard("glXGetCurrentDisplay", std::ptr::null_mut(), || {
        if current_glx().is_null() {
            return std::ptr::null_mut();
        }
        CUR_DISPLAY.try_with(Cell::get).unwrap_or(0) as *mut Display
    })
}

#[no_mangle]
pub extern "C" fn glXSwapBuffers(dpy: *mut Display, drawable: c_ulong) {
    guard("glXSwapBuffers", (), || {
        let current_draw = CUR_DRAW.try_with(Cell::get).unwrap_or(0);
        if !current_glx().is_null() && drawable != 0 && drawable == current_draw {
            with_gl("glXSwapBuffers", |gl| {
                // The implicit glFlush (recorded: a frame ends here), then the swap.
                gl.ctx.flush();
                swap_buffers(gl);
            });
        } else if xwin::find(dpy, drawable).is_some() {
            say("glXSwapBuffers", || {
                "a drawable not current on this thread: fixedgl keeps a frame in its context, so there is nothing to show".into()
            });
        } else {
            say("glXSwapBuffers", || {
                "not a drawable fixedgl renders to (GLXBadDrawable)".into()
            });
        }
    })
}

#[no_mangle]
pub extern "C" fn glXWaitGL() {
    guard("glXWaitGL", (), || {
        if !current_glx().is_null() {
            with_gl("glXWaitGL", |gl| {
                gl.ctx.finish();
                gl.flushed();
            });
        }
    })
}

#[no_mangle]
pub extern "C" fn glXWaitX() {
    guard("glXWaitX", (), || {
        let dpy = CUR_DISPLAY.try_with(Cell::get).unwrap_or(0) as *mut Display;
        if current_glx().is_null() || dpy.is_null() {
            return;
        }
        if let Some(x) = xwin::xlib() {
            // SAFETY: the display the current context was made current with.
            unsafe { (x.XSync)(dpy, FALSE) };
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXCreateWindow(
    dpy: *mut Display,
    config: *mut c_void,
    win: c_ulong,
    _attribs: *const c_int,
) -> c_ulong {
    guard("glXCreateWindow", 0, || {
        let Some(x) = xwin::xlib() else { return 0 };
        let Some(i) = config_index(config) else {
            say("glXCreateWindow", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return 0;
        };
        match XDrawable::window(x, dpy, win, Some(i)) {
            // A GLXWindow is its X window's XID here.
            Ok(d) => {
                xwin::insert(d);
                win
            }
            Err(e) => {
                say("glXCreateWindow", || format!("{e} (BadWindow)"));
                0
            }
        }
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyWindow(dpy: *mut Display, win: c_ulong) {
    guard("glXDestroyWindow", (), || {
        if xwin::remove(dpy, win, Kind::Window).is_none() {
            say("glXDestroyWindow", || {
                "not a GLXWindow (GLXBadWindow)".into()
            });
        }
    })
}

/// A GLXPixmap of `pixmap` for config `i` drawn through `visual`.
fn create_pixmap(
    x: &Xlib,
    dpy: *mut Display,
    pixmap: c_ulong,
    visual: *mut xlib::Visual,
    i: usize,
) -> c_ulong {
    match XDrawable::pixmap(x, dpy, pixmap, visual, Some(i)) {
        // A GLXPixmap is its X pixmap's XID here.
        Ok(d) => {
            xwin::insert(d);
            pixmap
        }
        Err(e) => {
            say("glXCreatePixmap", || format!("{e} (BadPixmap)"));
            0
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn glXCreatePixmap(
    dpy: *mut Display,
    config: *mut c_void,
    pixmap: c_ulong,
    _attribs: *const c_int,
) -> c_ulong {
    guard("glXCreatePixmap", 0, || {
        let Some(x) = xwin::xlib() else { return 0 };
        let Some(i) = config_index(config) else {
            say("glXCreatePixmap", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return 0;
        };
        if drawable_types(i) & GLX_PIXMAP_BIT == 0 || dpy.is_null() {
            say("glXCreatePixmap", || {
                "the config does not render to pixmaps (single-buffered configs do) (BadMatch)"
                    .into()
            });
            return 0;
        }
        let Some(vi) = xwin::true_color(x, dpy, default_screen(x, dpy)) else {
            return 0;
        };
        create_pixmap(x, dpy, pixmap, vi.visual, i)
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXCreateGLXPixmap(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    pixmap: c_ulong,
) -> c_ulong {
    guard("glXCreateGLXPixmap", 0, || {
        let Some(x) = xwin::xlib() else { return 0 };
        // SAFETY: an XVisualInfo from the program (GLX's contract).
        let Some(i) = (unsafe { config_of_visual(vis) }) else {
            say("glXCreateGLXPixmap", || {
                "the visual is not one fixedgl renders for (BadMatch)".into()
            });
            return 0;
        };
        // SAFETY: as above (non-null: a config was found).
        create_pixmap(x, dpy, pixmap, unsafe { (*vis).visual }, i)
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyPixmap(dpy: *mut Display, pixmap: c_ulong) {
    guard("glXDestroyPixmap", (), || {
        if xwin::remove(dpy, pixmap, Kind::Pixmap).is_none() {
            say("glXDestroyPixmap", || {
                "not a GLXPixmap (GLXBadPixmap)".into()
            });
        }
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyGLXPixmap(dpy: *mut Display, pixmap: c_ulong) {
    glXDestroyPixmap(dpy, pixmap)
}

/// Pbuffer handles: numbers with the top bit of 32 set, which no X resource ID has (they have
/// 29 bits), so they never name a window or pixmap.
static NEXT_PBUFFER: Mutex<c_ulong> = Mutex::new(0x8000_0001);

#[no_mangle]
pub unsafe extern "C" fn glXCreatePbuffer(
    dpy: *mut Display,
    config: *mut c_void,
    attribs: *const c_int,
) -> c_ulong {
    guard("glXCreatePbuffer", 0, || {
        let Some(i) = config_index(config) else {
            say("glXCreatePbuffer", || {
                "not a GLXFBConfig of fixedgl (GLXBadFBConfig)".into()
            });
            return 0;
        };
        if dpy.is_null() {
            return 0;
        }
        let (mut w, mut h) = (0, 0);
        // SAFETY: GLX's attribute list.
        for (k, v) in unsafe { pairs(attribs) } {
            match k {
                GLX_PBUFFER_WIDTH => w = v,
                GLX_PBUFFER_HEIGHT => h = v,
                GLX_LARGEST_PBUFFER | GLX_PRESERVED_CONTENTS => {}
                _ => {
                    say("glXCreatePbuffer", || {
                        format!("attribute {k:#x} is not a pbuffer attribute (BadValue)")
                    });
                    return 0;
                }
            }
        }
        if !(0..=MAX_SIDE).contains(&w) || !(0..=MAX_SIDE).contains(&h) {
            say("glXCreatePbuffer", || {
                format!("{w}x{h} is larger than fixedgl's {MAX_SIDE}x{MAX_SIDE} (BadAlloc)")
            });
            return 0;
        }
        let id = {
            let mut next = NEXT_PBUFFER.lock().unwrap_or_else(|e| e.into_inner());
            let id = *next;
            *next = if id >= 0xFFFF_FFFF {
                0x8000_0001
            } else {
                id + 1
            };
            id
        };
        xwin::insert(XDrawable::pbuffer(dpy, id, (w as u32, h as u32), Some(i)));
        id
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyPbuffer(dpy: *mut Display, pbuf: c_ulong) {
    guard("glXDestroyPbuffer", (), || {
        if xwin::remove(dpy, pbuf, Kind::Pbuffer).is_none() {
            say("glXDestroyPbuffer", || {
                "not a GLXPbuffer (GLXBadPbuffer)".into()
            });
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXQueryDrawable(
    dpy: *mut Display,
    draw: c_ulong,
    attribute: c_int,
    value: *mut c_uint,
) {
    guard("glXQueryDrawable", (), || {
        let Some(x) = xwin::xlib() else { return };
        let d = match xwin::find(dpy, draw) {
            Some(d) => d,
            None => match XDrawable::window(x, dpy, draw, None) {
                Ok(d) => xwin::insert(d),
                Err(e) => {
                    say("glXQueryDrawable", || format!("{e} (GLXBadDrawable)"));
                    return;
                }
            },
        };
        let mut g = xwin::lock(&d);
        let config = g.config.or_else(|| {
            // An X window used directly has the config of the context current on it.
            let on_it = CUR_DRAW.try_with(Cell::get).unwrap_or(0) == draw;
            glx_context(current_glx())
                .filter(|_| on_it)
                .map(|c| c.config)
        });
        let v = match attribute {
            GLX_WIDTH | GLX_HEIGHT => {
                g.refresh();
                if attribute == GLX_WIDTH {
                    g.size.0
                } else {
                    g.size.1
                }
            }
            GLX_PRESERVED_CONTENTS => c_uint::from(g.kind == Kind::Pbuffer),
            GLX_LARGEST_PBUFFER => 0,
            GLX_FBCONFIG_ID => CONFIGS[config.unwrap_or(DOUBLE)].id as c_uint,
            GLX_EVENT_MASK => g.event_mask as c_uint,
            GLX_SWAP_INTERVAL_EXT => g.swap_interval,
            GLX_MAX_SWAP_INTERVAL_EXT => MAX_SWAP_INTERVAL,
            _ => {
                say("glXQueryDrawable", || {
                    format!("attribute {attribute:#x} is not a drawable attribute (BadValue)")
                });
                return;
            }
        };
        // SAFETY: one value.
        if let Some(s) = unsafe { read::slice_mut(value, 1) }.first_mut() {
            *s = v;
        }
    })
}

#[no_mangle]
pub extern "C" fn glXSelectEvent(dpy: *mut Display, draw: c_ulong, mask: c_ulong) {
    guard("glXSelectEvent", (), || {
        if let Some(d) = xwin::find(dpy, draw) {
            xwin::lock(&d).event_mask = mask;
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetSelectedEvent(dpy: *mut Display, draw: c_ulong, mask: *mut c_ulong) {
    guard("glXGetSelectedEvent", (), || {
        let m = xwin::find(dpy, draw).map_or(0, |d| xwin::lock(&d).event_mask);
        // SAFETY: one value.
        if let Some(s) = unsafe { read::slice_mut(mask, 1) }.first_mut() {
            *s = m;
        }
    })
}

/// The current drawable, for the swap-interval calls.
fn current_drawable() -> Option<std::sync::Arc<Mutex<XDrawable>>> {
    if current_glx().is_null() {
        return None;
    }
    let dpy = CUR_DISPLAY.try_with(Cell::get).unwrap_or(0) as *mut Display;
    let draw = CUR_DRAW.try_with(Cell::get).unwrap_or(0);
    xwin::find(dpy, draw)
}

#[no_mangle]
pub extern "C" fn glXSwapIntervalMESA(interval: c_uint) -> c_int {
    guard("glXSwapIntervalMESA", GLX_BAD_CONTEXT, || {
        let Some(d) = current_drawable() else {
            return GLX_BAD_CONTEXT;
        };
        if interval > MAX_SWAP_INTERVAL {
            return GLX_BAD_VALUE;
        }
        xwin::lock(&d).swap_interval = interval;
        0
    })
}

#[no_mangle]
pub extern "C" fn glXGetSwapIntervalMESA() -> c_int {
    guard("glXGetSwapIntervalMESA", 0, || {
        current_drawable().map_or(0, |d| xwin::lock(&d).swap_interval as c_int)
    })
}

#[no_mangle]
pub extern "C" fn glXSwapIntervalSGI(interval: c_int) -> c_int {
    guard("glXSwapIntervalSGI", GLX_BAD_CONTEXT, || {
        if interval <= 0 {
            return GLX_BAD_VALUE;
        }
        glXSwapIntervalMESA(interval as c_uint)
    })
}

#[no_mangle]
pub extern "C" fn glXCopyContext(
    _dpy: *mut Display,
    _src: *mut c_void,
    _dst: *mut c_void,
    _mask: c_ulong,
) {
    guard("glXCopyContext", (), || {
        crate::unimplemented("glXCopyContext")
    });
}

#[no_mangle]
pub extern "C" fn glXUseXFont(_font: c_ulong, _first: c_int, _count: c_int, _list_base: c_int) {
    guard("glXUseXFont", (), || crate::unimplemented("glXUseXFont"));
}

/// The GLX functions GetProcAddress answers (those that work).
fn glx_proc(name: &[u8]) -> Option<*const c_void> {
    let f: *const c_void = match name {
        b"glXGetProcAddress" => glXGetProcAddress as *const c_void,
        b"glXGetProcAddressARB" => glXGetProcAddressARB as *const c_void,
        b"glXQueryExtension" => glXQueryExtension as *const c_void,
        b"glXQueryVersion" => glXQueryVersion as *const c_void,
        b"glXQueryExtensionsString" => glXQueryExtensionsString as *const c_void,
        b"glXGetClientString" => glXGetClientString as *const c_void,
        b"glXQueryServerString" => glXQueryServerString as *const c_void,
        b"glXChooseVisual" => glXChooseVisual as *const c_void,
        b"glXGetConfig" => glXGetConfig as *const c_void,
        b"glXChooseFBConfig" => glXChooseFBConfig as *const c_void,
        b"glXGetFBConfigs" => glXGetFBConfigs as *const c_void,
        b"glXGetFBConfigAttrib" => glXGetFBConfigAttrib as *const c_void,
        b"glXGetVisualFromFBConfig" => glXGetVisualFromFBConfig as *const c_void,
        b"glXCreateContext" => glXCreateContext as *const c_void,
        b"glXCreateNewContext" => glXCreateNewContext as *const c_void,
        b"glXCreateContextAttribsARB" => glXCreateContextAttribsARB as *const c_void,
        b"glXDestroyContext" => glXDestroyContext as *const c_void,
        b"glXIsDirect" => glXIsDirect as *const c_void,
        b"glXQueryContext" => glXQueryContext as *const c_void,
        b"glXMakeCurrent" => glXMakeCurrent as *const c_void,
        b"glXMakeContextCurrent" => glXMakeContextCurrent as *const c_void,
        b"glXGetCurrentContext" => glXGetCurrentContext as *const c_void,
        b"glXGetCurrentDrawable" => glXGetCurrentDrawable as *const c_void,
        b"glXGetCurrentReadDrawable" => glXGetCurrentReadDrawable as *const c_void,
        b"glXGetCurrentDisplay" => glXGetCurrentDisplay as *const c_void,
        b"glXSwapBuffers" => glXSwapBuffers as *const c_void,
        b"glXWaitGL" => glXWaitGL as *const c_void,
        b"glXWaitX" => glXWaitX as *const c_void,
        b"glXCreateWindow" => glXCreateWindow as *const c_void,
        b"glXDestroyWindow" => glXDestroyWindow as *const c_void,
        b"glXCreatePixmap" => glXCreatePixmap as *const c_void,
        b"glXCreateGLXPixmap" => glXCreateGLXPixmap as *const c_void,
        b"glXDestroyPixmap" => glXDestroyPixmap as *const c_void,
        b"glXDestroyGLXPixmap" => glXDestroyGLXPixmap as *const c_void,
        b"glXCreatePbuffer" => glXCreatePbuffer as *const c_void,
        b"glXDestroyPbuffer" => glXDestroyPbuffer as *const c_void,
        b"glXQueryDrawable" => glXQueryDrawable as *const c_void,
        b"glXSelectEvent" => glXSelectEvent as *const c_void,
        b"glXGetSelectedEvent" => glXGetSelectedEvent as *const c_void,
        b"glXSwapIntervalMESA" => glXSwapIntervalMESA as *const c_void,
        b"glXGetSwapIntervalMESA" => glXGetSwapIntervalMESA as *const c_void,
        b"glXSwapIntervalSGI" => glXSwapIntervalSGI as *const c_void,
        _ => return None,
    };
    Some(f)
}

/// The other glX* functions libglvnd's libGL.so.1 exports (extensions fixedgl does not offer):
/// they exist so that programs linked against them load, do nothing, say so once, return
/// 0/NULL/False, and are NULL from glXGetProcAddress. Declared without parameters: in the C
/// calling convention the caller passes and removes the arguments, and every one of these
/// returns an integer, a pointer or nothing, for which 0 in the return register is the answer.
macro_rules! absent {
    ($($name:ident)*) => {$(
        #[no_mangle]
        pub extern "C" fn $name() -> usize {
            guard(stringify!($name), (), || crate::unimplemented(stringify!($name)));
            0
        }
    )*};
}

absent! {
    glXAllocateMemoryNV glXBindChannelToWindowSGIX glXBindHyperpipeSGIX glXBindSwapBarrierNV
    glXBindSwapBarrierSGIX glXBindTexImageEXT glXBindVideoCaptureDeviceNV glXBindVideoDeviceNV
    glXBindVideoImageNV glXBlitContextFramebufferAMD glXChannelRectSGIX glXChannelRectSyncSGIX
    glXChooseFBConfigSGIX glXCopyBufferSubDataNV glXCopyImageSubDataNV glXCopySubBufferMESA
    glXCreateAssociatedContextAMD glXCreateAssociatedContextAttribsAMD
    glXCreateContextWithConfigSGIX glXCreateGLXPbufferSGIX glXCreateGLXPixmapMESA
    glXCreateGLXPixmapWithConfigSGIX glXCushionSGI glXDelayBeforeSwapNV
    glXDeleteAssociatedContextAMD glXDestroyGLXPbufferSGIX glXDestroyHyperpipeConfigSGIX
    glXEnumerateVideoCaptureDevicesNV glXEnumerateVideoDevicesNV glXFreeContextEXT
    glXFreeMemoryNV glXGetAGPOffsetMESA glXGetContextGPUIDAMD glXGetContextIDEXT
    glXGetCurrentAssociatedContextAMD glXGetCurrentDisplayEXT glXGetCurrentReadDrawableSGI
    glXGetDriverConfig glXGetFBConfigAttribSGIX glXGetFBConfigFromVisualSGIX glXGetGPUIDsAMD
    glXGetGPUInfoAMD glXGetMscRateOML glXGetRefreshRateSGI glXGetScreenDriver
    glXGetSelectedEventSGIX glXGetSyncValuesOML glXGetTransparentIndexSUN glXGetVideoDeviceNV
    glXGetVideoInfoNV glXGetVideoSyncSGI glXGetVisualFromFBConfigSGIX glXHyperpipeAttribSGIX
    glXHyperpipeConfigSGIX glXImportContextEXT glXJoinSwapGroupNV glXJoinSwapGroupSGIX
    glXLockVideoCaptureDeviceNV glXMakeAssociatedContextCurrentAMD glXMakeCurrentReadSGI
    glXNamedCopyBufferSubDataNV glXQueryChannelDeltasSGIX glXQueryChannelRectSGIX
    glXQueryContextInfoEXT glXQueryCurrentRendererIntegerMESA
    glXQueryCurrentRendererStringMESA glXQueryFrameCountNV glXQueryGLXPbufferSGIX
    glXQueryHyperpipeAttribSGIX glXQueryHyperpipeBestAttribSGIX glXQueryHyperpipeConfigSGIX
    glXQueryHyperpipeNetworkSGIX glXQueryMaxSwapBarriersSGIX glXQueryMaxSwapGroupsNV
    glXQueryRendererIntegerMESA glXQueryRendererStringMESA glXQuerySwapGroupNV
    glXQueryVideoCaptureDeviceNV glXReleaseBuffersMESA glXReleaseTexImageEXT
    glXReleaseVideoCaptureDeviceNV glXReleaseVideoDeviceNV glXReleaseVideoImageNV
    glXResetFrameCountNV glXSelectEventSGIX glXSendPbufferToVideoNV glXSet3DfxModeMESA
    glXSwapBuffersMscOML glXSwapIntervalEXT glXWaitForMscOML glXWaitForSbcOML
    glXWaitVideoSyncSGI
}
