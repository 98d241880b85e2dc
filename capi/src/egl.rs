//! EGL 1.4 for headless programs: the surfaceless platform (`EGL_MESA_platform_surfaceless`)
//! and the default display, two configs with 24-bit depth and 8-bit stencil (RGBA8, and RGB8
//! without alpha bits, which a caller not asking for alpha gets first, as from Mesa), pbuffer
//! surfaces, and contexts without a surface (`EGL_KHR_surfaceless_context`). That is what
//! waffle (piglit's window-system layer) and headless renderers use. Window surfaces are not
//! offered: programs with windows use GLX (`EGL_BAD_NATIVE_WINDOW`, said once on stderr).
//!
//! Handles are addresses of values kept in registries, so a handle that is not one of ours is
//! refused with the EGL error for it, never dereferenced.

use std::cell::Cell;
use std::ffi::{c_char, c_void, CStr};
use std::sync::Mutex;

use fixedgl::Context;

use crate::current::{self, guard, Gl, Surface};
use crate::read;

type EGLBoolean = u32;
type EGLint = i32;
type Handle = *mut c_void;

const EGL_FALSE: EGLBoolean = 0;
const EGL_TRUE: EGLBoolean = 1;
const EGL_SUCCESS: EGLint = 0x3000;
const EGL_NOT_INITIALIZED: EGLint = 0x3001;
const EGL_BAD_ACCESS: EGLint = 0x3002;
const EGL_BAD_ATTRIBUTE: EGLint = 0x3004;
const EGL_BAD_CONFIG: EGLint = 0x3005;
const EGL_BAD_CONTEXT: EGLint = 0x3006;
const EGL_BAD_DISPLAY: EGLint = 0x3008;
const EGL_BAD_MATCH: EGLint = 0x3009;
const EGL_BAD_NATIVE_WINDOW: EGLint = 0x300B;
const EGL_BAD_PARAMETER: EGLint = 0x300C;
const EGL_BAD_SURFACE: EGLint = 0x300D;

const EGL_BUFFER_SIZE: EGLint = 0x3020;
const EGL_ALPHA_SIZE: EGLint = 0x3021;
const EGL_BLUE_SIZE: EGLint = 0x3022;
const EGL_GREEN_SIZE: EGLint = 0x3023;
const EGL_RED_SIZE: EGLint = 0x3024;
const EGL_DEPTH_SIZE: EGLint = 0x3025;
const EGL_STENCIL_SIZE: EGLint = 0x3026;
const EGL_CONFIG_CAVEAT: EGLint = 0x3027;
const EGL_CONFIG_ID: EGLint = 0x3028;
const EGL_LEVEL: EGLint = 0x3029;
const EGL_MAX_PBUFFER_HEIGHT: EGLint = 0x302A;
const EGL_MAX_PBUFFER_PIXELS: EGLint = 0x302B;
const EGL_MAX_PBUFFER_WIDTH: EGLint = 0x302C;
const EGL_NATIVE_RENDERABLE: EGLint = 0x302D;
const EGL_NATIVE_VISUAL_ID: EGLint = 0x302E;
const EGL_NATIVE_VISUAL_TYPE: EGLint = 0x302F;
const EGL_SAMPLES: EGLint = 0x3031;
const EGL_SAMPLE_BUFFERS: EGLint = 0x3032;
const EGL_SURFACE_TYPE: EGLint = 0x3033;
const EGL_TRANSPARENT_TYPE: EGLint = 0x3034;
const EGL_NONE: EGLint = 0x3038;
const EGL_BIND_TO_TEXTURE_RGB: EGLint = 0x3039;
const EGL_BIND_TO_TEXTURE_RGBA: EGLint = 0x303A;
const EGL_MIN_SWAP_INTERVAL: EGLint = 0x303B;
const EGL_MAX_SWAP_INTERVAL: EGLint = 0x303C;
const EGL_LUMINANCE_SIZE: EGLint = 0x303D;
const EGL_ALPHA_MASK_SIZE: EGLint = 0x303E;
const EGL_COLOR_BUFFER_TYPE: EGLint = 0x303F;
const EGL_RENDERABLE_TYPE: EGLint = 0x3040;
const EGL_CONFORMANT: EGLint = 0x3042;
const EGL_RGB_BUFFER: EGLint = 0x308E;
const EGL_VENDOR: EGLint = 0x3053;
const EGL_VERSION: EGLint = 0x3054;
const EGL_EXTENSIONS: EGLint = 0x3055;
const EGL_HEIGHT: EGLint = 0x3056;
const EGL_WIDTH: EGLint = 0x3057;
const EGL_LARGEST_PBUFFER: EGLint = 0x3058;
const EGL_DRAW: EGLint = 0x3059;
const EGL_READ: EGLint = 0x305A;
const EGL_TEXTURE_FORMAT: EGLint = 0x3080;
const EGL_TEXTURE_TARGET: EGLint = 0x3081;
const EGL_MIPMAP_TEXTURE: EGLint = 0x3082;
const EGL_RENDER_BUFFER: EGLint = 0x3086;
const EGL_BACK_BUFFER: EGLint = 0x3084;
const EGL_SINGLE_BUFFER: EGLint = 0x3085;
const EGL_CLIENT_APIS: EGLint = 0x308D;
const EGL_CONTEXT_CLIENT_TYPE: EGLint = 0x3097;
const EGL_CONTEXT_MAJOR_VERSION: EGLint = 0x3098;
const EGL_CONTEXT_MINOR_VERSION: EGLint = 0x30FB;
const EGL_CONTEXT_FLAGS: EGLint = 0x30FC;
const EGL_CONTEXT_OPENGL_PROFILE_MASK: EGLint = 0x30FD;
const EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT: EGLint = 0x1;
const EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY: EGLint = 0x31BD;
const EGL_CONTEXT_OPENGL_ROBUST_ACCESS: EGLint = 0x31B2;
const EGL_OPENGL_API: u32 = 0x30A2;
const EGL_OPENGL_BIT: EGLint = 0x0008;
const EGL_PBUFFER_BIT: EGLint = 0x0001;
const EGL_PLATFORM_SURFACELESS_MESA: u32 = 0x31DD;
const EGL_DONT_CARE: EGLint = -1;

/// Client extensions (`eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)`).
const CLIENT_EXTENSIONS: &CStr =
    c"EGL_EXT_client_extensions EGL_EXT_platform_base EGL_MESA_platform_surfaceless";
const DISPLAY_EXTENSIONS: &CStr = c"EGL_KHR_create_context EGL_KHR_surfaceless_context";
/// The one display.
static DISPLAY: u8 = 0;
/// The RGBA8 config (EGL_CONFIG_ID 1): depth 24, stencil 8, pbuffers, OpenGL.
static CONFIG: u8 = 1;
/// The RGB8 config (EGL_CONFIG_ID 2): as [`CONFIG`] without alpha bits (ALPHA_BITS 0), as
/// Mesa's XRGB8888 configs. EGL 1.4 §3.4.1.2 sorts it first for a caller that does not ask for
/// alpha (equal colour bits counted over the components asked for, then the smaller
/// EGL_BUFFER_SIZE), which is how piglit's RGB visuals get a framebuffer without alpha.
static CONFIG_RGB: u8 = 2;
const MAX_SIDE: EGLint = 16384;

thread_local! {
    static ERROR: Cell<EGLint> = const { Cell::new(EGL_SUCCESS) };
    static API: Cell<u32> = const { Cell::new(EGL_OPENGL_API) };
    static DRAW: Cell<usize> = const { Cell::new(0) };
    static READ: Cell<usize> = const { Cell::new(0) };
}

static INITIALIZED: Mutex<bool> = Mutex::new(false);
/// Live pbuffer surfaces: address → size.
static SURFACES: Mutex<Vec<(usize, (u32, u32))>> = Mutex::new(Vec::new());
/// The EGL_CONFIG_ID each live surface and context was made with (RGBA8's 1 when missing).
static CONFIG_IDS: Mutex<Vec<(usize, EGLint)>> = Mutex::new(Vec::new());

fn remember_config(handle: usize, id: EGLint) {
    let mut all = CONFIG_IDS.lock().unwrap_or_else(|e| e.into_inner());
    all.retain(|(h, _)| *h != handle);
    all.push((handle, id));
}

fn forget_config(handle: usize) {
    let mut all = CONFIG_IDS.lock().unwrap_or_else(|e| e.into_inner());
    all.retain(|(h, _)| *h != handle);
}

fn config_id_of(handle: Handle) -> EGLint {
    let all = CONFIG_IDS.lock().unwrap_or_else(|e| e.into_inner());
    all.iter()
        .find(|(h, _)| *h == handle as usize)
        .map_or(1, |(_, id)| *id)
}

fn set_error(e: EGLint) {
    let _ = ERROR.try_with(|c| c.set(e));
}

fn fail<T>(e: EGLint, value: T) -> T {
    set_error(e);
    value
}

fn display() -> Handle {
    std::ptr::addr_of!(DISPLAY).cast_mut().cast()
}

fn config() -> Handle {
    std::ptr::addr_of!(CONFIG).cast_mut().cast()
}

fn config_rgb() -> Handle {
    std::ptr::addr_of!(CONFIG_RGB).cast_mut().cast()
}

/// EGL_CONFIG_ID of the RGBA8 config (`alpha`) or the RGB8 one.
fn config_id(alpha: bool) -> EGLint {
    if alpha {
        1
    } else {
        2
    }
}

/// Whether `cfg`, one of our configs, has alpha bits; `None` for what is not a config of ours.
fn config_alpha(cfg: Handle) -> Option<bool> {
    if cfg == config() {
        Some(true)
    } else if cfg == config_rgb() {
        Some(false)
    } else {
        None
    }
}

/// `Ok` for our display once initialised; the EGL error otherwise.
fn check_display(dpy: Handle) -> Result<(), EGLint> {
    if dpy != display() {
        return Err(EGL_BAD_DISPLAY);
    }
    if !*INITIALIZED.lock().unwrap_or_else(|e| e.into_inner()) {
        return Err(EGL_NOT_INITIALIZED);
    }
    Ok(())
}

/// The key/value pairs of an EGL_NONE-terminated attribute list (at most 64 pairs).
unsafe fn attributes(list: *const EGLint) -> Vec<(EGLint, EGLint)> {
    let mut out = Vec::new();
    for i in 0..64 {
        // SAFETY: an EGL_NONE-terminated list of pairs (the API's contract); NULL is empty.
        let Some([k, v]) = (unsafe { read::array::<EGLint, 2>(list.wrapping_add(2 * i)) }) else {
            break;
        };
        if k == EGL_NONE {
            break;
        }
        out.push((k, v));
    }
    out
}

/// A config's attributes (`alpha`: the RGBA8 one, else the RGB8 one); `None` for what is not a
/// config attribute.
fn config_attrib(alpha: bool, attr: EGLint) -> Option<EGLint> {
    Some(match attr {
        EGL_BUFFER_SIZE => 24 + if alpha { 8 } else { 0 },
        EGL_ALPHA_SIZE => 8 * EGLint::from(alpha),
        EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE => 8,
        EGL_DEPTH_SIZE => 24,
        EGL_STENCIL_SIZE => 8,
        EGL_CONFIG_CAVEAT => EGL_NONE,
        EGL_CONFIG_ID => config_id(alpha),
        EGL_LEVEL => 0,
        EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_HEIGHT => MAX_SIDE,
        EGL_MAX_PBUFFER_PIXELS => MAX_SIDE * MAX_SIDE / 4,
        EGL_NATIVE_RENDERABLE => 0,
        EGL_NATIVE_VISUAL_ID | EGL_NATIVE_VISUAL_TYPE => 0,
        EGL_SAMPLES | EGL_SAMPLE_BUFFERS => 0,
        EGL_SURFACE_TYPE => EGL_PBUFFER_BIT,
        EGL_TRANSPARENT_TYPE => EGL_NONE,
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => 0,
        EGL_MIN_SWAP_INTERVAL | EGL_MAX_SWAP_INTERVAL => 0,
        EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => 0,
        EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
        EGL_RENDERABLE_TYPE | EGL_CONFORMANT => EGL_OPENGL_BIT,
        _ => return None,
    })
}

/// Whether a config meets one requested attribute (EGL 1.4 table 3.4's matching rules).
fn matches(alpha: bool, attr: EGLint, want: EGLint) -> Result<bool, EGLint> {
    if want == EGL_DONT_CARE {
        return Ok(true);
    }
    let have = config_attrib(alpha, attr).ok_or(EGL_BAD_ATTRIBUTE)?;
    Ok(match attr {
        // Bit masks: every requested bit.
        EGL_SURFACE_TYPE | EGL_RENDERABLE_TYPE | EGL_CONFORMANT => have & want == want,
        // Sizes: at least.
        EGL_BUFFER_SIZE | EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_ALPHA_SIZE
        | EGL_DEPTH_SIZE | EGL_STENCIL_SIZE | EGL_SAMPLES | EGL_SAMPLE_BUFFERS
        | EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => have >= want,
        // Ignored for choosing (EGL 1.4 table 3.4).
        EGL_MAX_PBUFFER_WIDTH
        | EGL_MAX_PBUFFER_HEIGHT
        | EGL_MAX_PBUFFER_PIXELS
        | EGL_NATIVE_VISUAL_ID => true,
        _ => have == want,
    })
}

#[no_mangle]
pub extern "C" fn eglGetError() -> EGLint {
    ERROR
        .try_with(|c| c.replace(EGL_SUCCESS))
        .unwrap_or(EGL_SUCCESS)
}

#[no_mangle]
pub extern "C" fn eglGetDisplay(native: *mut c_void) -> Handle {
    guard("eglGetDisplay", std::ptr::null_mut(), || {
        if !native.is_null() {
            eprintln!("fixedgl: eglGetDisplay of a native display is not supported: EGL here is headless (EGL_DEFAULT_DISPLAY or the surfaceless platform); windows go through GLX");
            return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
        }
        set_error(EGL_SUCCESS);
        display()
    })
}

#[no_mangle]
pub extern "C" fn eglGetPlatformDisplay(
    platform: u32,
    _native: *mut c_void,
    _attribs: *const isize,
) -> Handle {
    guard("eglGetPlatformDisplay", std::ptr::null_mut(), || {
        if platform != EGL_PLATFORM_SURFACELESS_MESA {
            eprintln!("fixedgl: EGL platform {platform:#x} is not supported; fixedgl's EGL offers the surfaceless platform (EGL_MESA_platform_surfaceless) only");
            return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
        }
        set_error(EGL_SUCCESS);
        display()
    })
}

#[no_mangle]
pub extern "C" fn eglGetPlatformDisplayEXT(
    platform: u32,
    native: *mut c_void,
    _attribs: *const EGLint,
) -> Handle {
    eglGetPlatformDisplay(platform, native, std::ptr::null())
}

#[no_mangle]
pub unsafe extern "C" fn eglInitialize(
    dpy: Handle,
    major: *mut EGLint,
    minor: *mut EGLint,
) -> EGLBoolean {
    guard("eglInitialize", EGL_FALSE, || {
        if dpy != display() {
            return fail(EGL_BAD_DISPLAY, EGL_FALSE);
        }
        *INITIALIZED.lock().unwrap_or_else(|e| e.into_inner()) = true;
        // SAFETY: one value each, where given.
        unsafe {
            if let Some(m) = read::slice_mut(major, 1).first_mut() {
                *m = 1;
            }
            if let Some(m) = read::slice_mut(minor, 1).first_mut() {
                *m = 4;
            }
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglTerminate(dpy: Handle) -> EGLBoolean {
    guard("eglTerminate", EGL_FALSE, || {
        if dpy != display() {
            return fail(EGL_BAD_DISPLAY, EGL_FALSE);
        }
        *INITIALIZED.lock().unwrap_or_else(|e| e.into_inner()) = false;
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglQueryString(dpy: Handle, name: EGLint) -> *const c_char {
    guard("eglQueryString", std::ptr::null(), || {
        if dpy.is_null() && name == EGL_EXTENSIONS {
            return fail(EGL_SUCCESS, CLIENT_EXTENSIONS.as_ptr());
        }
        if let Err(e) = check_display(dpy) {
            return fail(e, std::ptr::null());
        }
        let s: &CStr = match name {
            EGL_VENDOR => c"fixedgl",
            EGL_VERSION => c"1.4 fixedgl",
            EGL_CLIENT_APIS => c"OpenGL",
            EGL_EXTENSIONS => DISPLAY_EXTENSIONS,
            _ => return fail(EGL_BAD_PARAMETER, std::ptr::null()),
        };
        fail(EGL_SUCCESS, s.as_ptr())
    })
}

#[no_mangle]
pub unsafe extern "C" fn eglGetConfigs(
    dpy: Handle,
    configs: *mut Handle,
    size: EGLint,
    num: *mut EGLint,
) -> EGLBoolean {
    guard("eglGetConfigs", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        let all = [config(), config_rgb()];
        // SAFETY: `size` handles where given; one count.
        unsafe {
            let mut n = all.len() as EGLint;
            if !configs.is_null() {
                n = size.clamp(0, n);
                for (c, h) in read::slice_mut(configs, n as usize).iter_mut().zip(all) {
                    *c = h;
                }
            }
            match read::slice_mut(num, 1).first_mut() {
                Some(c) => *c = n,
                None => return fail(EGL_BAD_PARAMETER, EGL_FALSE),
            }
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub unsafe extern "C" fn eglChooseConfig(
    dpy: Handle,
    attribs: *const EGLint,
    configs: *mut Handle,
    size: EGLint,
    num: *mut EGLint,
) -> EGLBoolean {
    guard("eglChooseConfig", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        // SAFETY: EGL's attribute list.
        let wanted = unsafe { attributes(attribs) };
        // EGL 1.4 §3.4.1.2's order: the two differ only in alpha, and the RGB8 one comes
        // first whenever both match (equal colour bits over the components asked for, a
        // smaller EGL_BUFFER_SIZE); asking for alpha leaves the RGBA8 one alone.
        let mut chosen = Vec::new();
        for (alpha, handle) in [(false, config_rgb()), (true, config())] {
            let mut ok = true;
            for &(k, v) in &wanted {
                match matches(alpha, k, v) {
                    Ok(m) => ok &= m,
                    Err(e) => return fail(e, EGL_FALSE),
                }
            }
            if ok {
                chosen.push(handle);
            }
        }
        let n = chosen.len() as EGLint;
        // SAFETY: `size` handles where given; one count.
        unsafe {
            let n = if configs.is_null() {
                n
            } else {
                n.min(size.max(0))
            };
            for (c, h) in read::slice_mut(configs, n as usize).iter_mut().zip(chosen) {
                *c = h;
            }
            match read::slice_mut(num, 1).first_mut() {
                Some(c) => *c = n,
                None => return fail(EGL_BAD_PARAMETER, EGL_FALSE),
            }
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub unsafe extern "C" fn eglGetConfigAttrib(
    dpy: Handle,
    cfg: Handle,
    attr: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    guard("eglGetConfigAttrib", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        let Some(alpha) = config_alpha(cfg) else {
            return fail(EGL_BAD_CONFIG, EGL_FALSE);
        };
        let Some(v) = config_attrib(alpha, attr) else {
            return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return fail(EGL_BAD_PARAMETER, EGL_FALSE),
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglBindAPI(api: u32) -> EGLBoolean {
    guard("eglBindAPI", EGL_FALSE, || {
        if api != EGL_OPENGL_API {
            eprintln!("fixedgl: eglBindAPI({api:#x}): fixedgl offers desktop OpenGL only (EGL_OPENGL_API)");
            return fail(EGL_BAD_PARAMETER, EGL_FALSE);
        }
        let _ = API.try_with(|c| c.set(api));
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglQueryAPI() -> u32 {
    API.try_with(Cell::get).unwrap_or(EGL_OPENGL_API)
}

#[no_mangle]
pub unsafe extern "C" fn eglCreateContext(
    dpy: Handle,
    cfg: Handle,
    share: Handle,
    attribs: *const EGLint,
) -> Handle {
    guard("eglCreateContext", std::ptr::null_mut(), || {
        if let Err(e) = check_display(dpy) {
            return fail(e, std::ptr::null_mut());
        }
        // EGL_NO_CONFIG_KHR (NULL): the RGBA8 framebuffer.
        let Some(alpha) = (if cfg.is_null() {
            Some(true)
        } else {
            config_alpha(cfg)
        }) else {
            return fail(EGL_BAD_CONFIG, std::ptr::null_mut());
        };
        if !share.is_null() && !current::is_live(share.cast()) {
            return fail(EGL_BAD_CONTEXT, std::ptr::null_mut());
        }
        let (mut major, mut minor) = (1, 0);
        // SAFETY: EGL's attribute list.
        for (k, v) in unsafe { attributes(attribs) } {
            match k {
                EGL_CONTEXT_MAJOR_VERSION => major = v,
                EGL_CONTEXT_MINOR_VERSION => minor = v,
                EGL_CONTEXT_OPENGL_PROFILE_MASK
                    if v & EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT != 0 && major >= 3 =>
                {
                    return fail(EGL_BAD_MATCH, std::ptr::null_mut());
                }
                EGL_CONTEXT_OPENGL_PROFILE_MASK | EGL_CONTEXT_FLAGS => {}
                EGL_CONTEXT_OPENGL_ROBUST_ACCESS
                | EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY => {}
                _ => return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut()),
            }
        }
        if (major, minor) > (1, 5) {
            if crate::say_once("egl version") {
                eprintln!("fixedgl: eglCreateContext asks for OpenGL {major}.{minor}; fixedgl is OpenGL 1.5");
            }
            return fail(EGL_BAD_MATCH, std::ptr::null_mut());
        }
        // share_context: display lists, textures and buffer objects shared (GL appendix D).
        let config = fixedgl::ContextConfig {
            alpha,
            ..Default::default()
        };
        match Gl::with_config_shared(1, 1, config, share.cast()) {
            Some(gl) => {
                let p = current::register(gl);
                remember_config(p as usize, config_id(alpha));
                fail(EGL_SUCCESS, p.cast())
            }
            None => fail(EGL_BAD_ALLOC, std::ptr::null_mut()),
        }
    })
}

const EGL_BAD_ALLOC: EGLint = 0x3003;

#[no_mangle]
pub extern "C" fn eglDestroyContext(dpy: Handle, ctx: Handle) -> EGLBoolean {
    guard("eglDestroyContext", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        if current::destroy(ctx.cast()) {
            forget_config(ctx as usize);
            fail(EGL_SUCCESS, EGL_TRUE)
        } else {
            fail(EGL_BAD_CONTEXT, EGL_FALSE)
        }
    })
}

fn surface_size(s: Handle) -> Option<(u32, u32)> {
    let all = SURFACES.lock().unwrap_or_else(|e| e.into_inner());
    all.iter()
        .find(|(a, _)| *a == s as usize)
        .map(|(_, size)| *size)
}

#[no_mangle]
pub unsafe extern "C" fn eglCreatePbufferSurface(
    dpy: Handle,
    cfg: Handle,
    attribs: *const EGLint,
) -> Handle {
    guard("eglCreatePbufferSurface", std::ptr::null_mut(), || {
        if let Err(e) = check_display(dpy) {
            return fail(e, std::ptr::null_mut());
        }
        let Some(alpha) = config_alpha(cfg) else {
            return fail(EGL_BAD_CONFIG, std::ptr::null_mut());
        };
        let (mut w, mut h) = (0, 0);
        // SAFETY: EGL's attribute list.
        for (k, v) in unsafe { attributes(attribs) } {
            match k {
                EGL_WIDTH => w = v,
                EGL_HEIGHT => h = v,
                EGL_LARGEST_PBUFFER | EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET
                | EGL_MIPMAP_TEXTURE => {}
                _ => return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut()),
            }
        }
        if !(0..=MAX_SIDE).contains(&w) || !(0..=MAX_SIDE).contains(&h) {
            return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
        }
        // A surface is a heap cell whose address is the handle.
        let p = Box::into_raw(Box::new(0u64)) as usize;
        SURFACES
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push((p, (w as u32, h as u32)));
        remember_config(p, config_id(alpha));
        fail(EGL_SUCCESS, p as Handle)
    })
}

#[no_mangle]
pub extern "C" fn eglCreateWindowSurface(
    dpy: Handle,
    _cfg: Handle,
    _win: usize,
    _attribs: *const EGLint,
) -> Handle {
    guard("eglCreateWindowSurface", std::ptr::null_mut(), || {
        if let Err(e) = check_display(dpy) {
            return fail(e, std::ptr::null_mut());
        }
        if crate::say_once("eglCreateWindowSurface") {
            eprintln!("fixedgl: EGL window surfaces are not supported (EGL here is headless); use GLX for windows");
        }
        fail(EGL_BAD_NATIVE_WINDOW, std::ptr::null_mut())
    })
}

#[no_mangle]
pub extern "C" fn eglCreatePixmapSurface(
    dpy: Handle,
    cfg: Handle,
    _pixmap: usize,
    _attribs: *const EGLint,
) -> Handle {
    eglCreateWindowSurface(dpy, cfg, 0, std::ptr::null())
}

#[no_mangle]
pub extern "C" fn eglDestroySurface(dpy: Handle, surface: Handle) -> EGLBoolean {
    guard("eglDestroySurface", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        let mut all = SURFACES.lock().unwrap_or_else(|e| e.into_inner());
        let Some(i) = all.iter().position(|(a, _)| *a == surface as usize) else {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        };
        let (a, _) = all.remove(i);
        forget_config(a);
        // SAFETY: made by eglCreatePbufferSurface, removed from the registry just now.
        drop(unsafe { Box::from_raw(a as *mut u64) });
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub unsafe extern "C" fn eglQuerySurface(
    dpy: Handle,
    surface: Handle,
    attr: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    guard("eglQuerySurface", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        let Some((w, h)) = surface_size(surface) else {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        };
        let v = match attr {
            EGL_WIDTH => w as EGLint,
            EGL_HEIGHT => h as EGLint,
            EGL_CONFIG_ID => config_id_of(surface),
            EGL_LARGEST_PBUFFER => 0,
            EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
            _ => return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE),
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return fail(EGL_BAD_PARAMETER, EGL_FALSE),
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

/// A pbuffer as a context's drawable: nothing to present to.
struct Pbuffer((u32, u32));

impl Surface for Pbuffer {
    fn size(&self) -> (u32, u32) {
        self.0
    }

    fn double_buffered(&self) -> bool {
        false
    }

    fn present(&mut self, _ctx: &mut Context) {}
}

#[no_mangle]
pub extern "C" fn eglMakeCurrent(
    dpy: Handle,
    draw: Handle,
    read: Handle,
    ctx: Handle,
) -> EGLBoolean {
    guard("eglMakeCurrent", EGL_FALSE, || {
        if ctx.is_null() {
            if !draw.is_null() || !read.is_null() {
                return fail(EGL_BAD_MATCH, EGL_FALSE);
            }
            current::release_current();
            let _ = DRAW.try_with(|c| c.set(0));
            let _ = READ.try_with(|c| c.set(0));
            return fail(EGL_SUCCESS, EGL_TRUE);
        }
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        if !current::is_live(ctx.cast()) {
            return fail(EGL_BAD_CONTEXT, EGL_FALSE);
        }
        if draw.is_null() != read.is_null() {
            return fail(EGL_BAD_MATCH, EGL_FALSE);
        }
        let surface: Option<Box<dyn Surface>> = if draw.is_null() {
            None
        } else {
            let (Some(d), Some(_)) = (surface_size(draw), surface_size(read)) else {
                return fail(EGL_BAD_SURFACE, EGL_FALSE);
            };
            Some(Box::new(Pbuffer(d)))
        };
        if current::make_current(ctx.cast(), surface).is_err() {
            return fail(EGL_BAD_ACCESS, EGL_FALSE);
        }
        let _ = DRAW.try_with(|c| c.set(draw as usize));
        let _ = READ.try_with(|c| c.set(read as usize));
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglGetCurrentContext() -> Handle {
    current::current().cast()
}

#[no_mangle]
pub extern "C" fn eglGetCurrentDisplay() -> Handle {
    if current::current().is_null() {
        std::ptr::null_mut()
    } else {
        display()
    }
}

#[no_mangle]
pub extern "C" fn eglGetCurrentSurface(which: EGLint) -> Handle {
    let cell = if which == EGL_READ { &READ } else { &DRAW };
    if which != EGL_READ && which != EGL_DRAW {
        return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
    }
    cell.try_with(Cell::get).unwrap_or(0) as Handle
}

#[no_mangle]
pub unsafe extern "C" fn eglQueryContext(
    dpy: Handle,
    ctx: Handle,
    attr: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    guard("eglQueryContext", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        if !current::is_live(ctx.cast()) {
            return fail(EGL_BAD_CONTEXT, EGL_FALSE);
        }
        let v = match attr {
            EGL_CONFIG_ID => config_id_of(ctx),
            EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_API as EGLint,
            EGL_RENDER_BUFFER => EGL_SINGLE_BUFFER,
            _ => return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE),
        };
        // SAFETY: one value.
        match unsafe { read::slice_mut(value, 1) }.first_mut() {
            Some(s) => *s = v,
            None => return fail(EGL_BAD_PARAMETER, EGL_FALSE),
        }
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglSwapBuffers(dpy: Handle, surface: Handle) -> EGLBoolean {
    guard("eglSwapBuffers", EGL_FALSE, || {
        if let Err(e) = check_display(dpy) {
            return fail(e, EGL_FALSE);
        }
        if surface_size(surface).is_none() {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        }
        // A pbuffer has no back buffer: SwapBuffers does nothing to it (EGL 1.4 §3.9.3), but it
        // ends a frame, which `fixedgl run` records.
        crate::current::with_gl("eglSwapBuffers", |gl| gl.present_frame());
        fail(EGL_SUCCESS, EGL_TRUE)
    })
}

#[no_mangle]
pub extern "C" fn eglSwapInterval(dpy: Handle, _interval: EGLint) -> EGLBoolean {
    match check_display(dpy) {
        Ok(()) => fail(EGL_SUCCESS, EGL_TRUE),
        Err(e) => fail(e, EGL_FALSE),
    }
}

#[no_mangle]
pub extern "C" fn eglWaitClient() -> EGLBoolean {
    crate::current::with_gl("eglWaitClient", |gl| gl.ctx.finish());
    EGL_TRUE
}

#[no_mangle]
pub extern "C" fn eglWaitGL() -> EGLBoolean {
    eglWaitClient()
}

#[no_mangle]
pub extern "C" fn eglWaitNative(_engine: EGLint) -> EGLBoolean {
    EGL_TRUE
}

#[no_mangle]
pub extern "C" fn eglReleaseThread() -> EGLBoolean {
    guard("eglReleaseThread", EGL_FALSE, || {
        current::release_current();
        let _ = API.try_with(|c| c.set(EGL_OPENGL_API));
        EGL_TRUE
    })
}

#[no_mangle]
pub unsafe extern "C" fn eglGetProcAddress(name: *const c_char) -> *const c_void {
    guard("eglGetProcAddress", std::ptr::null(), || {
        if name.is_null() {
            return std::ptr::null();
        }
        // SAFETY: a NUL-terminated name (the API's contract).
        let name = unsafe { CStr::from_ptr(name) }.to_bytes();
        let f: *const c_void = match name {
            b"eglGetPlatformDisplay" => eglGetPlatformDisplay as *const c_void,
            b"eglGetPlatformDisplayEXT" => eglGetPlatformDisplayEXT as *const c_void,
            b"eglGetError" => eglGetError as *const c_void,
            b"eglGetDisplay" => eglGetDisplay as *const c_void,
            b"eglInitialize" => eglInitialize as *const c_void,
            b"eglTerminate" => eglTerminate as *const c_void,
            b"eglQueryString" => eglQueryString as *const c_void,
            b"eglGetConfigs" => eglGetConfigs as *const c_void,
            b"eglChooseConfig" => eglChooseConfig as *const c_void,
            b"eglGetConfigAttrib" => eglGetConfigAttrib as *const c_void,
            b"eglBindAPI" => eglBindAPI as *const c_void,
            b"eglQueryAPI" => eglQueryAPI as *const c_void,
            b"eglCreateContext" => eglCreateContext as *const c_void,
            b"eglDestroyContext" => eglDestroyContext as *const c_void,
            b"eglCreatePbufferSurface" => eglCreatePbufferSurface as *const c_void,
            b"eglCreateWindowSurface" => eglCreateWindowSurface as *const c_void,
            b"eglCreatePixmapSurface" => eglCreatePixmapSurface as *const c_void,
            b"eglDestroySurface" => eglDestroySurface as *const c_void,
            b"eglQuerySurface" => eglQuerySurface as *const c_void,
            b"eglMakeCurrent" => eglMakeCurrent as *const c_void,
            b"eglGetCurrentContext" => eglGetCurrentContext as *const c_void,
            b"eglGetCurrentDisplay" => eglGetCurrentDisplay as *const c_void,
            b"eglGetCurrentSurface" => eglGetCurrentSurface as *const c_void,
            b"eglQueryContext" => eglQueryContext as *const c_void,
            b"eglSwapBuffers" => eglSwapBuffers as *const c_void,
            b"eglSwapInterval" => eglSwapInterval as *const c_void,
            b"eglWaitClient" => eglWaitClient as *const c_void,
            b"eglWaitGL" => eglWaitGL as *const c_void,
            b"eglWaitNative" => eglWaitNative as *const c_void,
            b"eglReleaseThread" => eglReleaseThread as *const c_void,
            b"eglGetProcAddress" => eglGetProcAddress as *const c_void,
            _ => return crate::proc_address(name).unwrap_or(std::ptr::null()),
        };
        f
    })
}
