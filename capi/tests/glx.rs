//! GLX through its C entry points (called directly from the library, as a C program would),
//! on a private Xvfb: visuals and FBConfigs in Xlib/malloc memory, windows presenting at
//! SwapBuffers and following resizes, single-buffered windows presenting at glFlush, pixmaps,
//! pbuffers, GLX_ARB_create_context, GLX_MESA_swap_control, one thread per context, and handles
//! that are not (or no longer) GLX objects failing cleanly instead of crashing.

mod xsupport;

use std::ffi::{c_int, c_uint, c_ulong, c_void, CString};
use std::ptr::null_mut;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{RwLock, RwLockReadGuard, RwLockWriteGuard};
use std::time::{Duration, Instant};

use fixedgl_capi::glx::*;
use x11_dl::xlib::{self, Display, XErrorEvent, XVisualInfo};
use xsupport::{xlib, Connection, Image, Xvfb};

const GLX_RGBA: c_int = 4;
const GLX_DOUBLEBUFFER: c_int = 5;
const GLX_RED_SIZE: c_int = 8;
const GLX_ALPHA_SIZE: c_int = 11;
const GLX_BUFFER_SIZE: c_int = 2;
const GLX_DEPTH_SIZE: c_int = 12;
const GLX_STENCIL_SIZE: c_int = 13;
const GLX_ACCUM_RED_SIZE: c_int = 14;
const GLX_BAD_ATTRIBUTE: c_int = 2;
const GLX_BAD_CONTEXT: c_int = 5;
const GLX_DONT_CARE: c_int = -1;
const GLX_X_RENDERABLE: c_int = 0x8012;
const GLX_DRAWABLE_TYPE: c_int = 0x8010;
const GLX_RENDER_TYPE: c_int = 0x8011;
const GLX_FBCONFIG_ID: c_int = 0x8013;
const GLX_VISUAL_ID: c_int = 0x800B;
const GLX_WINDOW_BIT: c_int = 1;
const GLX_PIXMAP_BIT: c_int = 2;
const GLX_RGBA_BIT: c_int = 1;
const GLX_RGBA_TYPE: c_int = 0x8014;
const GLX_WIDTH: c_int = 0x801D;
const GLX_HEIGHT: c_int = 0x801E;
const GLX_PBUFFER_WIDTH: c_int = 0x8041;
const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
const GLX_EXTENSIONS: c_int = 3;
const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 1;

const GL_COLOR_BUFFER_BIT: u32 = 0x4000;
const GL_VIEWPORT: u32 = 0x0BA2;
const GL_RGB: u32 = 0x1907;
const GL_UNSIGNED_BYTE: u32 = 0x1401;
const GL_PACK_ALIGNMENT: u32 = 0x0D05;
const GL_DOUBLEBUFFER: u32 = 0x0C32;
const GL_DRAW_BUFFER: u32 = 0x0C01;
const GL_READ_BUFFER: u32 = 0x0C02;
const GL_FRONT: i32 = 0x0404;
const GL_BACK: i32 = 0x0405;

/// The GL functions a test calls, looked up as a C program would (glXGetProcAddress).
struct Gl {
    clear_color: extern "C" fn(f32, f32, f32, f32),
    clear: extern "C" fn(u32),
    viewport: extern "C" fn(i32, i32, i32, i32),
    flush: extern "C" fn(),
    finish: extern "C" fn(),
    get_integerv: unsafe extern "C" fn(u32, *mut i32),
    read_pixels: unsafe extern "C" fn(i32, i32, i32, i32, u32, u32, *mut c_void),
    pixel_storei: extern "C" fn(u32, i32),
}

fn proc(name: &str) -> *const c_void {
    let c = CString::new(name).expect("name");
    // SAFETY: a NUL-terminated name.
    unsafe { glXGetProcAddressARB(c.as_ptr()) }
}

fn gl() -> Gl {
    macro_rules! f {
        ($name:literal: $t:ty) => {{
            let p = proc($name);
            assert!(!p.is_null(), "{} is NULL", $name);
            // SAFETY: the address of the GL command of that name and C signature.
            unsafe { std::mem::transmute::<*const c_void, $t>(p) }
        }};
    }
    Gl {
        clear_color: f!("glClearColor": extern "C" fn(f32, f32, f32, f32)),
        clear: f!("glClear": extern "C" fn(u32)),
        viewport: f!("glViewport": extern "C" fn(i32, i32, i32, i32)),
        flush: f!("glFlush": extern "C" fn()),
        finish: f!("glFinish": extern "C" fn()),
        get_integerv: f!("glGetIntegerv": unsafe extern "C" fn(u32, *mut i32)),
        read_pixels: f!("glReadPixels": unsafe extern "C" fn(i32, i32, i32, i32, u32, u32, *mut c_void)),
        pixel_storei: f!("glPixelStorei": extern "C" fn(u32, i32)),
    }
}

impl Gl {
    fn fill(&self, rgb: [f32; 3]) {
        (self.clear_color)(rgb[0], rgb[1], rgb[2], 1.0);
        (self.clear)(GL_COLOR_BUFFER_BIT);
    }

    fn integer(&self, pname: u32) -> i32 {
        let mut v = [0; 4];
        // SAFETY: room for the four values the largest query writes.
        unsafe { (self.get_integerv)(pname, v.as_mut_ptr()) };
        v[0]
    }

    fn viewport_now(&self) -> [i32; 4] {
        let mut v = [0; 4];
        // SAFETY: four values.
        unsafe { (self.get_integerv)(GL_VIEWPORT, v.as_mut_ptr()) };
        v
    }
}

/// Whether every pixel of `image` is `rgb`.
fn all(image: &Image, rgb: [u8; 3]) -> bool {
    image.rgb.chunks_exact(3).all(|p| p == rgb)
}

/// Xlib's error handler is one per process, and the tests run on parallel threads: a test that
/// installs a handler of its own holds this for writing (no other test's GLX call saves and
/// restores the handler meanwhile, which would drop the test's handler); the others hold it for
/// reading.
static ERROR_HANDLER: RwLock<()> = RwLock::new(());

/// An X server and a connection to it, with the shared hold on the error handler; `None`:
/// skipped (no Xvfb).
fn server() -> Option<(Xvfb, Connection, RwLockReadGuard<'static, ()>)> {
    let held = ERROR_HANDLER.read().unwrap_or_else(|e| e.into_inner());
    let x = Xvfb::start()?;
    let c = x.open();
    Some((x, c, held))
}

/// As `server`, for a test that sets its own X error handler: no other test runs GLX meanwhile.
fn server_alone() -> Option<(Xvfb, Connection, RwLockWriteGuard<'static, ()>)> {
    let held = ERROR_HANDLER.write().unwrap_or_else(|e| e.into_inner());
    let x = Xvfb::start()?;
    let c = x.open();
    Some((x, c, held))
}

fn dpy(c: &Connection) -> *mut Display {
    c.0
}

/// A mapped top-level window of `vis`'s visual at (0, 0).
fn window(c: &Connection, vis: *const XVisualInfo, w: u32, h: u32) -> c_ulong {
    let x = xlib();
    // SAFETY: an open display and a visual of it.
    unsafe {
        let v = &*vis;
        let root = (x.XRootWindow)(c.0, v.screen);
        let mut attrs: xlib::XSetWindowAttributes = std::mem::zeroed();
        attrs.colormap = (x.XCreateColormap)(c.0, root, v.visual, xlib::AllocNone);
        attrs.border_pixel = 0;
        let win = (x.XCreateWindow)(
            c.0,
            root,
            0,
            0,
            w,
            h,
            0,
            v.depth,
            xlib::InputOutput as c_uint,
            v.visual,
            xlib::CWColormap | xlib::CWBorderPixel,
            &mut attrs,
        );
        (x.XMapWindow)(c.0, win);
        (x.XSync)(c.0, xlib::False);
        win
    }
}

fn choose_visual(c: &Connection, attribs: &[c_int]) -> *mut XVisualInfo {
    // SAFETY: a None-terminated list.
    unsafe { glXChooseVisual(dpy(c), 0, attribs.as_ptr()) }
}

fn xfree<T>(p: *mut T) {
    // SAFETY: memory GLX handed out for the caller to XFree.
    unsafe { (xlib().XFree)(p.cast()) };
}

/// The configs glXChooseFBConfig picks for `attribs`, as handles, freed with XFree as a
/// program does.
fn choose_configs(c: &Connection, attribs: &[c_int]) -> Vec<*mut c_void> {
    let mut n = -1;
    // SAFETY: a None-terminated list and a count.
    let list = unsafe { glXChooseFBConfig(dpy(c), 0, attribs.as_ptr(), &mut n) };
    if list.is_null() {
        assert_eq!(n, 0);
        return Vec::new();
    }
    // SAFETY: `n` handles.
    let v = unsafe { std::slice::from_raw_parts(list, n as usize) }.to_vec();
    xfree(list);
    v
}

fn attrib(c: &Connection, config: *mut c_void, a: c_int) -> c_int {
    let mut v = -12345;
    // SAFETY: one value.
    let r = unsafe { glXGetFBConfigAttrib(dpy(c), config, a, &mut v) };
    assert_eq!(r, 0, "attribute {a:#x}");
    v
}

/// Versions, strings, FBConfigs as GLX 1.3 lists them and as freeglut asks for them, visuals in
/// Xlib memory, GetProcAddress.
#[test]
fn queries_configs_and_visuals() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let (mut major, mut minor, mut eb, mut ev) = (0, 0, -1, -1);
    // SAFETY: out-pointers to locals.
    unsafe {
        assert_eq!(glXQueryExtension(dpy(&c), &mut eb, &mut ev), 1);
        assert_eq!(glXQueryVersion(dpy(&c), &mut major, &mut minor), 1);
    }
    assert_eq!((major, minor), (1, 4));
    // SAFETY: NUL-terminated strings of the library.
    let ext = unsafe { std::ffi::CStr::from_ptr(glXQueryExtensionsString(dpy(&c), 0)) };
    let ext = ext.to_str().expect("ASCII");
    for e in [
        "GLX_ARB_get_proc_address",
        "GLX_ARB_create_context",
        "GLX_MESA_swap_control",
    ] {
        assert!(ext.split(' ').any(|x| x == e), "{e} missing from {ext}");
    }
    assert!(!glXGetClientString(dpy(&c), GLX_EXTENSIONS).is_null());

    // All configs: four, RGB8 before RGBA8 (the smaller GLX_BUFFER_SIZE), single-buffered
    // first within each.
    let mut n = 0;
    // SAFETY: a count.
    let list = unsafe { glXGetFBConfigs(dpy(&c), 0, &mut n) };
    assert_eq!(n, 4);
    xfree(list);
    let any = choose_configs(&c, &[GLX_DOUBLEBUFFER, GLX_DONT_CARE, 0]);
    assert_eq!(any.len(), 4);
    let order: Vec<_> = any
        .iter()
        .map(|&k| {
            (
                attrib(&c, k, GLX_ALPHA_SIZE),
                attrib(&c, k, GLX_BUFFER_SIZE),
                attrib(&c, k, GLX_DOUBLEBUFFER),
            )
        })
        .collect();
    assert_eq!(order, [(0, 24, 0), (0, 24, 1), (8, 32, 0), (8, 32, 1)]);
    // What freeglut 3 asks for GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH.
    let glut = choose_configs(
        &c,
        &[
            GLX_DRAWABLE_TYPE,
            GLX_WINDOW_BIT,
            GLX_RENDER_TYPE,
            GLX_RGBA_BIT,
            GLX_DOUBLEBUFFER,
            1,
            GLX_RED_SIZE,
            1,
            GLX_DEPTH_SIZE,
            1,
            0,
        ],
    );
    // The RGB8 one first: GLUT_RGB does not ask for alpha, and gets none, as from Mesa.
    assert_eq!(glut.len(), 2);
    assert_eq!(attrib(&c, glut[0], GLX_ALPHA_SIZE), 0);
    assert_eq!(attrib(&c, glut[1], GLX_ALPHA_SIZE), 8);
    let cfg = glut[0];
    for (a, want) in [
        (GLX_DEPTH_SIZE, 24),
        (GLX_STENCIL_SIZE, 8),
        (GLX_RED_SIZE, 8),
        (GLX_X_RENDERABLE, 1),
    ] {
        assert_eq!(attrib(&c, cfg, a), want, "attribute {a:#x}");
    }
    assert_eq!(
        attrib(&c, any[0], GLX_DRAWABLE_TYPE) & GLX_PIXMAP_BIT,
        GLX_PIXMAP_BIT
    );
    assert_eq!(attrib(&c, cfg, GLX_DRAWABLE_TYPE) & GLX_PIXMAP_BIT, 0);
    // Every config has llvmpipe's 16-bit accumulation buffer.
    assert_eq!(attrib(&c, cfg, GLX_ACCUM_RED_SIZE), 16);
    assert_eq!(choose_configs(&c, &[GLX_ACCUM_RED_SIZE, 16, 0]).len(), 4);
    // What fixedgl does not have: no config; an attribute GLX does not define: none either.
    assert!(choose_configs(&c, &[GLX_ACCUM_RED_SIZE, 32, 0]).is_empty());
    assert!(choose_configs(&c, &[0x7777, 1, 0]).is_empty());
    // GLX_FBCONFIG_ID picks that config whatever else is asked.
    let id = attrib(&c, cfg, GLX_FBCONFIG_ID);
    assert_eq!(
        choose_configs(&c, &[GLX_FBCONFIG_ID, id, GLX_ACCUM_RED_SIZE, 9, 0]),
        vec![cfg]
    );

    // The config's visual: 24-bit TrueColor, the same ID as GLX_VISUAL_ID, Xlib memory.
    let vis = glXGetVisualFromFBConfig(dpy(&c), cfg);
    assert!(!vis.is_null());
    // SAFETY: the XVisualInfo just handed out.
    let (depth, class, id) = unsafe { ((*vis).depth, (*vis).class, (*vis).visualid) };
    assert_eq!((depth, class), (24, xlib::TrueColor));
    assert_eq!(attrib(&c, cfg, GLX_VISUAL_ID) as c_ulong, id);
    xfree(vis);

    // GLX 1.2: double-buffered only when asked; colour index refused.
    let vis = choose_visual(&c, &[GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, 0]);
    let single = choose_visual(&c, &[GLX_RGBA, 0]);
    assert!(!vis.is_null() && !single.is_null());
    let (mut db, mut sb) = (-1, -1);
    // SAFETY: visuals GLX handed out, one value each.
    unsafe {
        assert_eq!(glXGetConfig(dpy(&c), vis, GLX_DOUBLEBUFFER, &mut db), 0);
        assert_eq!(glXGetConfig(dpy(&c), single, GLX_DOUBLEBUFFER, &mut sb), 0);
    }
    assert_eq!((db, sb), (1, 0));
    xfree(vis);
    xfree(single);
    assert!(choose_visual(&c, &[GLX_DOUBLEBUFFER, 0]).is_null());
    // GLUT_ACCUM's request (at least 8 bits) finds the 16-bit accumulation buffer; more than
    // that, nothing.
    let accum = choose_visual(&c, &[GLX_RGBA, GLX_ACCUM_RED_SIZE, 8, 0]);
    assert!(!accum.is_null());
    xfree(accum);
    assert!(choose_visual(&c, &[GLX_RGBA, GLX_ACCUM_RED_SIZE, 32, 0]).is_null());

    // GetProcAddress: GLX and GL functions that work; NULL for what is not offered.
    for name in [
        "glXCreateContextAttribsARB",
        "glXSwapIntervalMESA",
        "glXChooseFBConfig",
        "glBegin",
    ] {
        assert!(!proc(name).is_null(), "{name}");
    }
    for name in ["glXSwapIntervalEXT", "glXBindTexImageEXT", "glNoSuchThing"] {
        assert!(proc(name).is_null(), "{name}");
    }
}

/// A double-buffered GLX 1.2 window: nothing shows before SwapBuffers; the frame shows after;
/// the viewport starts at the window's size; the framebuffer follows resizes, at glViewport (the
/// program's reshape) and after a swap (a program that never calls glViewport again).
#[test]
fn window_presents_at_swap_and_follows_resizes() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let gl = gl();
    let vis = choose_visual(&c, &[GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 24, 0]);
    let win = window(&c, vis, 160, 120);
    // SAFETY: a visual GLX handed out.
    let ctx = unsafe { glXCreateContext(dpy(&c), vis, null_mut(), 1) };
    xfree(vis);
    assert!(!ctx.is_null());
    assert_eq!(glXIsDirect(dpy(&c), ctx), 1);
    assert_eq!(glXMakeCurrent(dpy(&c), win, ctx), 1);
    assert_eq!(glXGetCurrentContext(), ctx);
    assert_eq!(glXGetCurrentDrawable(), win);
    assert_eq!(glXGetCurrentDisplay(), dpy(&c));
    assert_eq!(gl.viewport_now(), [0, 0, 160, 120]);

    gl.fill([1.0, 0.0, 0.0]);
    (gl.finish)();
    assert!(
        !all(&c.read(win), [255, 0, 0]),
        "a double-buffered window showed a frame before the swap"
    );
    glXSwapBuffers(dpy(&c), win);
    assert!(all(&c.read(win), [255, 0, 0]));
    // A double-buffered visual's context: a back buffer, drawn into by default.
    assert_eq!(gl.integer(GL_DOUBLEBUFFER), 1);
    assert_eq!(gl.integer(GL_DRAW_BUFFER), GL_BACK);
    assert_eq!(gl.integer(GL_READ_BUFFER), GL_BACK);

    // The program's reshape: glViewport with the new size.
    c.resize(win, 200, 150);
    (gl.viewport)(0, 0, 200, 150);
    gl.fill([0.0, 1.0, 0.0]);
    glXSwapBuffers(dpy(&c), win);
    let shown = c.read(win);
    assert_eq!((shown.width, shown.height), (200, 150));
    assert!(
        all(&shown, [0, 255, 0]),
        "the frame does not cover the resized window"
    );

    // No glViewport: the frame drawn at the old size shows, and the next one has the new size.
    c.resize(win, 260, 190);
    gl.fill([0.0, 0.0, 1.0]);
    glXSwapBuffers(dpy(&c), win);
    gl.fill([1.0, 1.0, 0.0]);
    glXSwapBuffers(dpy(&c), win);
    assert!(
        all(&c.read(win), [255, 255, 0]),
        "the framebuffer did not follow the window"
    );

    assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
    assert!(glXGetCurrentContext().is_null());
    assert_eq!(glXGetCurrentDrawable(), 0);
    glXDestroyContext(dpy(&c), ctx);
}

/// GLX 1.3: a single-buffered FBConfig, a GLXWindow and CreateNewContext. The frame shows at
/// glFlush; QueryDrawable and QueryContext answer.
#[test]
fn single_buffered_window_presents_at_flush() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let gl = gl();
    let cfg = choose_configs(&c, &[GLX_DOUBLEBUFFER, 0, 0])[0];
    let vis = glXGetVisualFromFBConfig(dpy(&c), cfg);
    let xwin = window(&c, vis, 90, 70);
    xfree(vis);
    // SAFETY: no attributes.
    let glxwin = unsafe { glXCreateWindow(dpy(&c), cfg, xwin, std::ptr::null()) };
    assert_ne!(glxwin, 0);
    let ctx = glXCreateNewContext(dpy(&c), cfg, GLX_RGBA_TYPE, null_mut(), 1);
    assert!(!ctx.is_null());
    assert_eq!(glXMakeContextCurrent(dpy(&c), glxwin, glxwin, ctx), 1);
    assert_eq!(glXGetCurrentReadDrawable(), glxwin);
    gl.fill([0.0, 1.0, 1.0]);
    (gl.flush)();
    assert!(all(&c.read(xwin), [0, 255, 255]));
    // A single-buffered config's context: only the front buffer.
    assert_eq!(gl.integer(GL_DOUBLEBUFFER), 0);
    assert_eq!(gl.integer(GL_DRAW_BUFFER), GL_FRONT);

    let (mut w, mut h, mut id) = (0, 0, 0);
    let mut ctx_id = 0;
    // SAFETY: one value each.
    unsafe {
        glXQueryDrawable(dpy(&c), glxwin, GLX_WIDTH, &mut w);
        glXQueryDrawable(dpy(&c), glxwin, GLX_HEIGHT, &mut h);
        glXQueryDrawable(dpy(&c), glxwin, GLX_FBCONFIG_ID as c_int, &mut id);
        assert_eq!(
            glXQueryContext(dpy(&c), ctx, GLX_FBCONFIG_ID, &mut ctx_id),
            0
        );
    }
    assert_eq!((w, h), (90, 70));
    assert_eq!(id as c_int, attrib(&c, cfg, GLX_FBCONFIG_ID));
    assert_eq!(ctx_id, attrib(&c, cfg, GLX_FBCONFIG_ID));
    assert_eq!(glXMakeContextCurrent(dpy(&c), 0, 0, null_mut()), 1);
    glXDestroyWindow(dpy(&c), glxwin);
    glXDestroyContext(dpy(&c), ctx);
}

/// A GLXPixmap is drawn into at glFinish; a pbuffer is a drawable of its own size; a
/// double-buffered config makes no pixmap.
#[test]
fn pixmaps_and_pbuffers() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let gl = gl();
    let single = choose_configs(&c, &[GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, 0]);
    assert_eq!(single.len(), 2, "RGB8 and RGBA8, single-buffered");
    let x = xlib();
    // SAFETY: an open display.
    let pixmap = unsafe { (x.XCreatePixmap)(c.0, (x.XDefaultRootWindow)(c.0), 48, 40, 24) };
    // SAFETY: no attributes.
    let glxpixmap = unsafe { glXCreatePixmap(dpy(&c), single[0], pixmap, std::ptr::null()) };
    assert_ne!(glxpixmap, 0);
    let ctx = glXCreateNewContext(dpy(&c), single[0], GLX_RGBA_TYPE, null_mut(), 1);
    assert_eq!(glXMakeCurrent(dpy(&c), glxpixmap, ctx), 1);
    assert_eq!(gl.viewport_now(), [0, 0, 48, 40]);
    gl.fill([1.0, 0.0, 1.0]);
    (gl.finish)();
    let shown = c.read(pixmap);
    assert!(
        all(&shown, [255, 0, 255]),
        "{:?} {}x{}",
        shown.at(0, 0),
        shown.width,
        shown.height
    );

    let double = choose_configs(&c, &[GLX_DOUBLEBUFFER, 1, 0])[0];
    // SAFETY: no attributes.
    assert_eq!(
        unsafe { glXCreatePixmap(dpy(&c), double, pixmap, std::ptr::null()) },
        0
    );

    let attrs = [GLX_PBUFFER_WIDTH, 64, GLX_PBUFFER_HEIGHT, 32, 0];
    // SAFETY: a None-terminated list.
    let pbuffer = unsafe { glXCreatePbuffer(dpy(&c), double, attrs.as_ptr()) };
    assert_ne!(pbuffer, 0);
    let ctx2 = glXCreateNewContext(dpy(&c), double, GLX_RGBA_TYPE, null_mut(), 1);
    assert_eq!(glXMakeContextCurrent(dpy(&c), pbuffer, pbuffer, ctx2), 1);
    assert_eq!(gl.viewport_now(), [0, 0, 64, 32]);
    gl.fill([0.0, 0.0, 1.0]);
    let mut px = vec![0u8; 64 * 32 * 3];
    (gl.pixel_storei)(GL_PACK_ALIGNMENT, 1);
    // SAFETY: room for the 64 x 32 RGB image.
    unsafe {
        (gl.read_pixels)(
            0,
            0,
            64,
            32,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            px.as_mut_ptr().cast(),
        )
    };
    assert!(px.chunks_exact(3).all(|p| p == [0, 0, 255]));
    let mut w = 0;
    // SAFETY: one value.
    unsafe { glXQueryDrawable(dpy(&c), pbuffer, GLX_WIDTH, &mut w) };
    assert_eq!(w, 64);

    assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
    glXDestroyPbuffer(dpy(&c), pbuffer);
    glXDestroyPixmap(dpy(&c), glxpixmap);
    glXDestroyContext(dpy(&c), ctx);
    glXDestroyContext(dpy(&c), ctx2);
    // SAFETY: the pixmap this test made.
    unsafe { (x.XFreePixmap)(c.0, pixmap) };
}

/// RGB8 configs and visuals (GLX_ALPHA_SIZE 0) make contexts without alpha bits: ALPHA_BITS 0,
/// alpha writes dropped and the destination alpha reading 1 (GL 2.1 §4.1.8, §4.3.2); asking
/// for alpha (GLX_ALPHA_SIZE 1 or 8) gets RGBA8. Drawn into a pbuffer and read back.
#[test]
fn configs_and_visuals_without_alpha() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let gl = gl();
    macro_rules! f {
        ($name:literal: $t:ty) => {{
            let p = proc($name);
            assert!(!p.is_null(), "{} is NULL", $name);
            // SAFETY: the address of the GL command of that name and C signature.
            unsafe { std::mem::transmute::<*const c_void, $t>(p) }
        }};
    }
    let enable = f!("glEnable": extern "C" fn(u32));
    let blend_func = f!("glBlendFunc": extern "C" fn(u32, u32));
    let color4f = f!("glColor4f": extern "C" fn(f32, f32, f32, f32));
    let rectf = f!("glRectf": extern "C" fn(f32, f32, f32, f32));
    const GL_ALPHA_BITS: u32 = 0x0D55;
    const GL_RGBA: u32 = 0x1908;
    const GL_BLEND: u32 = 0x0BE2;
    const GL_DST_ALPHA: u32 = 0x0304;
    const GL_ONE_MINUS_DST_ALPHA: u32 = 0x0305;

    // GLX 1.2: a visual without GLX_ALPHA_SIZE has none; GLX_ALPHA_SIZE 1 finds 8 bits.
    for (attribs, want) in [
        (&[GLX_RGBA, GLX_DOUBLEBUFFER, 0][..], 0),
        (&[GLX_RGBA, GLX_ALPHA_SIZE, 0, 0][..], 0),
        (&[GLX_RGBA, GLX_ALPHA_SIZE, 1, 0][..], 8),
        (&[GLX_RGBA, GLX_DOUBLEBUFFER, GLX_ALPHA_SIZE, 8, 0][..], 8),
    ] {
        let vis = choose_visual(&c, attribs);
        assert!(!vis.is_null());
        let mut a = -1;
        // SAFETY: a visual GLX handed out, one value.
        assert_eq!(
            unsafe { glXGetConfig(dpy(&c), vis, GLX_ALPHA_SIZE, &mut a) },
            0
        );
        assert_eq!(a, want, "{attribs:?}");
        xfree(vis);
    }
    assert!(choose_configs(&c, &[GLX_ALPHA_SIZE, 9, 0]).is_empty());

    // A visual the program matched itself (XMatchVisualInfo, not glXChooseVisual): Mesa 22.3's
    // GLX on Xvfb gives the screen's 24-bit TrueColor visual (0x21) GLX_ALPHA_SIZE 8 and
    // GLX_DOUBLEBUFFER 1, and a context made on it reads ALPHA_BITS 8 (measured with the
    // system's libGL); so does fixedgl.
    // SAFETY: an open display; `found` is written by XMatchVisualInfo before it is read.
    let mut found = unsafe {
        let mut v: XVisualInfo = std::mem::zeroed();
        let ok = (xlib().XMatchVisualInfo)(dpy(&c), 0, 24, xlib::TrueColor, &mut v);
        assert_ne!(ok, 0, "no 24-bit TrueColor visual");
        v
    };
    for (attr, want) in [(GLX_ALPHA_SIZE, 8), (GLX_DOUBLEBUFFER, 1), (GLX_RGBA, 1)] {
        let mut v = -1;
        // SAFETY: a visual of the display, one value.
        assert_eq!(
            unsafe { glXGetConfig(dpy(&c), &mut found, attr, &mut v) },
            0
        );
        assert_eq!(v, want, "attribute {attr:#x} of a matched visual");
    }
    let win = window(&c, &found, 8, 8);
    // SAFETY: a visual of the display.
    let ctx = unsafe { glXCreateContext(dpy(&c), &mut found, null_mut(), 1) };
    assert!(!ctx.is_null());
    assert_eq!(glXMakeCurrent(dpy(&c), win, ctx), 1);
    assert_eq!(gl.integer(GL_ALPHA_BITS), 8);
    assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
    glXDestroyContext(dpy(&c), ctx);

    // Per config: ALPHA_BITS, then a clear to alpha 0.3 and a rectangle blended with
    // (ONE_MINUS_DST_ALPHA, DST_ALPHA) over the left half, read back as RGBA.
    for (alpha_size, bits, left, right) in [
        // No alpha: the destination alpha is 1, the rectangle leaves the clear colour.
        (0, 0, [15, 128, 26, 255], [15, 128, 26, 255]),
        // RGBA8: 0.7·(1, 0.2, 0.7, 0.5) + 0.3·(0.06, 0.5, 0.1, 0.3), as llvmpipe and Mesa's
        // OSMesa blend it.
        (8, 8, [183, 74, 133, 113], [15, 128, 26, 76]),
    ] {
        let cfg = choose_configs(&c, &[GLX_ALPHA_SIZE, alpha_size, GLX_DOUBLEBUFFER, 1, 0])[0];
        assert_eq!(attrib(&c, cfg, GLX_ALPHA_SIZE), alpha_size);
        let attrs = [GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, 0];
        // SAFETY: a None-terminated list.
        let pbuffer = unsafe { glXCreatePbuffer(dpy(&c), cfg, attrs.as_ptr()) };
        assert_ne!(pbuffer, 0);
        let ctx = glXCreateNewContext(dpy(&c), cfg, GLX_RGBA_TYPE, null_mut(), 1);
        assert_eq!(glXMakeContextCurrent(dpy(&c), pbuffer, pbuffer, ctx), 1);
        assert_eq!(gl.integer(GL_ALPHA_BITS), bits);
        (gl.clear_color)(0.06, 0.5, 0.1, 0.3);
        (gl.clear)(GL_COLOR_BUFFER_BIT);
        enable(GL_BLEND);
        blend_func(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
        color4f(1.0, 0.2, 0.7, 0.5);
        rectf(-1.0, -1.0, 0.0, 1.0);
        let mut px = [0u8; 8 * 4];
        // SAFETY: room for one row of 8 RGBA pixels.
        unsafe {
            (gl.read_pixels)(
                0,
                0,
                8,
                1,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                px.as_mut_ptr().cast(),
            )
        };
        assert_eq!(&px[..4], &left, "ALPHA_SIZE {alpha_size}: left");
        assert_eq!(&px[28..], &right, "ALPHA_SIZE {alpha_size}: right");
        assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
        glXDestroyPbuffer(dpy(&c), pbuffer);
        glXDestroyContext(dpy(&c), ctx);
    }
}

/// GLX_ARB_create_context: OpenGL up to 1.5 (any profile bit below 3.2) makes a context; 2.1,
/// 3.2 core and unknown attributes make none.
#[test]
fn create_context_attribs() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let cfg = choose_configs(&c, &[GLX_DOUBLEBUFFER, 1, 0])[0];
    let make = |attribs: &[c_int]| {
        // SAFETY: a None-terminated list.
        unsafe { glXCreateContextAttribsARB(dpy(&c), cfg, null_mut(), 1, attribs.as_ptr()) }
    };
    for ok in [
        &[0][..],
        &[
            GLX_CONTEXT_MAJOR_VERSION_ARB,
            1,
            GLX_CONTEXT_MINOR_VERSION_ARB,
            5,
            0,
        ],
        &[
            GLX_CONTEXT_MAJOR_VERSION_ARB,
            1,
            GLX_CONTEXT_PROFILE_MASK_ARB,
            GLX_CONTEXT_CORE_PROFILE_BIT_ARB,
            0,
        ],
    ] {
        let ctx = make(ok);
        assert!(!ctx.is_null(), "{ok:?}");
        glXDestroyContext(dpy(&c), ctx);
    }
    for bad in [
        &[
            GLX_CONTEXT_MAJOR_VERSION_ARB,
            2,
            GLX_CONTEXT_MINOR_VERSION_ARB,
            1,
            0,
        ][..],
        &[
            GLX_CONTEXT_MAJOR_VERSION_ARB,
            3,
            GLX_CONTEXT_MINOR_VERSION_ARB,
            2,
            GLX_CONTEXT_PROFILE_MASK_ARB,
            1,
            0,
        ],
        &[0x7777, 1, 0],
    ] {
        assert!(make(bad).is_null(), "{bad:?}");
    }
}

/// GLX_MESA_swap_control: an interval of 2 spaces swaps at least two 60 Hz frames apart.
#[test]
fn swap_interval_paces_swaps() {
    let Some((_x, c, _held)) = server() else {
        return;
    };
    let gl = gl();
    let vis = choose_visual(&c, &[GLX_RGBA, GLX_DOUBLEBUFFER, 0]);
    let win = window(&c, vis, 32, 32);
    // SAFETY: a visual GLX handed out.
    let ctx = unsafe { glXCreateContext(dpy(&c), vis, null_mut(), 1) };
    xfree(vis);
    assert_eq!(glXSwapIntervalMESA(1), GLX_BAD_CONTEXT);
    assert_eq!(glXMakeCurrent(dpy(&c), win, ctx), 1);
    assert_eq!(glXGetSwapIntervalMESA(), 0);
    assert_eq!(glXSwapIntervalMESA(2), 0);
    assert_eq!(glXGetSwapIntervalMESA(), 2);
    let start = Instant::now();
    for _ in 0..6 {
        gl.fill([0.5, 0.5, 0.5]);
        glXSwapBuffers(dpy(&c), win);
    }
    // Five gaps of at least 2/60 s.
    assert!(
        start.elapsed() >= Duration::from_millis(5 * 33),
        "{:?}",
        start.elapsed()
    );
    assert_eq!(glXSwapIntervalMESA(0), 0);
    assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
    glXDestroyContext(dpy(&c), ctx);
}

/// A program that closes its display and opens another (at the same address, on a server that
/// hands the new connection the same XIDs) presents into the new window: the closed display's
/// drawables were forgotten at XCloseDisplay, not met again under the same (display, XID).
#[test]
fn a_display_closed_and_opened_again_presents_into_its_own_window() {
    let Some((x, _c, _held)) = server() else {
        return;
    };
    let gl = gl();
    let mut seen = Vec::new();
    for rgb in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
        let c = x.open();
        let vis = choose_visual(&c, &[GLX_RGBA, GLX_DOUBLEBUFFER, 0]);
        let win = window(&c, vis, 64, 48);
        // SAFETY: a visual GLX handed out.
        let ctx = unsafe { glXCreateContext(dpy(&c), vis, null_mut(), 1) };
        xfree(vis);
        assert_eq!(glXMakeCurrent(dpy(&c), win, ctx), 1);
        gl.fill(rgb);
        glXSwapBuffers(dpy(&c), win);
        let want = rgb.map(|v| (v * 255.0) as u8);
        assert!(all(&c.read(win), want), "frame {want:?} not shown");
        assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
        glXDestroyContext(dpy(&c), ctx);
        seen.push((dpy(&c) as usize, win));
        // The window is left for XCloseDisplay to destroy, as programs do.
    }
    // What makes this test bite: the same address and XID again (else it proves less).
    eprintln!("displays and windows: {seen:x?}");
}

/// One context is current on one thread at a time (BadAccess: False), and is free for another
/// thread once released.
#[test]
fn context_is_current_on_one_thread() {
    let Some((x, c, _held)) = server() else {
        return;
    };
    let vis = choose_visual(&c, &[GLX_RGBA, GLX_DOUBLEBUFFER, 0]);
    let win = window(&c, vis, 32, 32);
    // SAFETY: a visual GLX handed out.
    let ctx = unsafe { glXCreateContext(dpy(&c), vis, null_mut(), 1) };
    xfree(vis);
    assert_eq!(glXMakeCurrent(dpy(&c), win, ctx), 1);
    let (ctx_addr, display) = (ctx as usize, x.display.clone());
    let other = move |expect: c_int| {
        let display = display.clone();
        std::thread::spawn(move || {
            let name = CString::new(display).expect("name");
            // SAFETY: a NUL-terminated name; the thread's own connection.
            let d = unsafe { (xlib().XOpenDisplay)(name.as_ptr()) };
            let got = glXMakeCurrent(d, win, ctx_addr as *mut c_void);
            assert_eq!(got, expect);
            glXMakeCurrent(d, 0, null_mut());
            // SAFETY: the connection this thread opened.
            unsafe { (xlib().XCloseDisplay)(d) };
        })
        .join()
        .expect("thread");
    };
    other(0);
    assert_eq!(glXMakeCurrent(dpy(&c), 0, null_mut()), 1);
    other(1);
    glXDestroyContext(dpy(&c), ctx);
}

static PROGRAM_ERRORS: AtomicUsize = AtomicUsize::new(0);

unsafe extern "C" fn count_errors(_dpy: *mut Display, _e: *mut XErrorEvent) -> c_int {
    PROGRAM_ERRORS.fetch_add(1, Ordering::SeqCst);
    0
}

/// What is not (or no longer) a GLX object fails with GLX's failure value and never crashes or
/// ends the process: NULL displays, foreign and destroyed contexts, foreign configs, windows
/// that do not exist (the X error is caught, not handed to Xlib's default handler, which would
/// exit). An X error of the program's own is still reported to the program's handler.
#[test]
fn bad_handles_fail_cleanly() {
    let Some((_x, c, _held)) = server_alone() else {
        return;
    };
    let d = dpy(&c);
    let garbage = Box::into_raw(Box::new([0u64; 16])).cast::<c_void>();
    let nul: *mut Display = null_mut();
    let mut v = 0;
    let mut n = 0;
    let none = [0];
    // SAFETY: the calls' contracts, with handles that are not GLX objects.
    unsafe {
        assert_eq!(glXQueryExtension(nul, &mut v, &mut v), 0);
        assert!(glXChooseVisual(nul, 0, none.as_ptr()).is_null());
        assert!(glXChooseFBConfig(nul, 0, none.as_ptr(), &mut n).is_null());
        assert!(glXGetFBConfigs(d, 7, &mut n).is_null());
        assert_eq!(
            glXGetFBConfigAttrib(d, garbage, GLX_DOUBLEBUFFER, &mut v),
            GLX_BAD_ATTRIBUTE
        );
        assert!(glXGetVisualFromFBConfig(d, garbage).is_null());
        assert!(glXCreateNewContext(d, garbage, GLX_RGBA_TYPE, null_mut(), 1).is_null());
        assert!(glXCreateContext(d, null_mut(), null_mut(), 1).is_null());
        assert_eq!(glXMakeCurrent(d, 0x3f_ffff, garbage), 0);
        assert_eq!(glXMakeCurrent(nul, 0x3f_ffff, null_mut()), 0);
        glXDestroyContext(d, garbage);
        assert_eq!(glXIsDirect(d, garbage), 0);
        assert_eq!(
            glXQueryContext(d, garbage, GLX_FBCONFIG_ID, &mut v),
            GLX_BAD_CONTEXT
        );
        glXSwapBuffers(d, 0x3f_ffff);
        glXSwapBuffers(nul, 0);
        glXQueryDrawable(d, 0x3f_ffff, GLX_WIDTH, &mut (v as c_uint));
        assert_eq!(glXCreateWindow(d, garbage, 0x3f_ffff, std::ptr::null()), 0);
    }

    // A destroyed context, and one destroyed twice.
    let cfg = choose_configs(&c, &[GLX_DOUBLEBUFFER, 1, 0])[0];
    let vis = glXGetVisualFromFBConfig(d, cfg);
    let win = window(&c, vis, 32, 32);
    xfree(vis);
    let ctx = glXCreateNewContext(d, cfg, GLX_RGBA_TYPE, null_mut(), 1);
    assert_eq!(glXMakeCurrent(d, win, ctx), 1);
    glXDestroyContext(d, ctx);
    assert!(
        glXGetCurrentContext().is_null(),
        "a destroyed context is still current"
    );
    glXDestroyContext(d, ctx);
    assert_eq!(glXMakeCurrent(d, win, ctx), 0);
    gl().fill([1.0, 1.0, 1.0]); // no current context: does nothing
    glXSwapBuffers(d, win);

    // A window that does not exist: caught; the program's own error still reaches its handler.
    let x = xlib();
    let ctx = glXCreateNewContext(d, cfg, GLX_RGBA_TYPE, null_mut(), 1);
    // SAFETY: the test's own display and handler.
    unsafe {
        let previous = (x.XSetErrorHandler)(Some(count_errors));
        (x.XMapWindow)(d, 0x3f_fffe); // the program's own bad request, not yet answered
        assert_eq!(glXMakeCurrent(d, 0x3f_ffff, ctx), 0);
        (x.XSync)(d, xlib::False);
        assert_eq!(
            PROGRAM_ERRORS.load(Ordering::SeqCst),
            1,
            "the program's X error was lost or doubled"
        );
        (x.XSetErrorHandler)(previous);
    }
    glXDestroyContext(d, ctx);
    // SAFETY: made above with Box::into_raw.
    drop(unsafe { Box::from_raw(garbage.cast::<[u64; 16]>()) });
}
