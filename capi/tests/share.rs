//! Contexts sharing objects through the C APIs: a C program written for Mesa makes two OSMesa
//! contexts, the second with the first as sharelist, draws in the second with a texture and a
//! display list made in the first, and checks what GL appendix D says (names seen, bindings per
//! context, deletion seen, a bad sharelist refused). Run on fixedgl's libOSMesa.so.8 and on
//! Mesa's; the two pictures are compared within the scenes' tolerance. The same through GLX
//! (glXCreateContext's shareList) on a private Xvfb, the second context drawing on a second
//! thread while the first stays current on the main one. And through EGL in this process
//! (eglCreateContext's share_context), with the errors a bad share context gets.

mod xsupport;

use std::ffi::c_void;
use std::path::Path;
use std::process::Command;
use std::ptr::{null, null_mut};
use std::time::Duration;

use fixedgl::gl;
use fixedgl_capi::egl::*;
use fixedgl_capi::manual::*;
use fixedgl_capi::osmesa::*;
use xsupport::{assert_close, available, has_header, has_program, on, run, Gl, Image, Xvfb};

const LIMIT: Duration = Duration::from_secs(120);

/// tests/c_share/NAME.c compiled with `cc` against `libs`; `None`: skipped (no compiler or
/// header).
fn compile(
    name: &str,
    header: &str,
    libs: &[&str],
) -> Option<(std::path::PathBuf, std::path::PathBuf)> {
    if !available(has_program("cc"), "a C compiler (cc)")
        || !available(has_header(header), &format!("the header {header}"))
    {
        return None;
    }
    let dir = xsupport::profile_dir().join("c-share");
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let bin = dir.join(name);
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/c_share/{name}.c"));
    let mut cc = Command::new("cc");
    cc.args(["-O2", "-Wall", "-Wextra", "-Werror", "-std=c99", "-o"])
        .arg(&bin)
        .arg(&src)
        .args(libs);
    run(cc, LIMIT);
    Some((bin, dir))
}

/// Runs `bin` (writing `<prefix>-<gl>.ppm` into `dir`) on fixedgl and on Mesa, with `display` or
/// none, checks that each ran on the library it should and said nothing of sharing, and returns
/// both images, fixedgl's first.
fn on_both(bin: &Path, dir: &Path, prefix: &str, display: Option<&str>) -> Vec<Image> {
    let mut images = Vec::new();
    for gl in [Gl::Fixedgl, Gl::Mesa] {
        let out = dir.join(format!("{prefix}-{gl:?}.ppm"));
        let mut cmd = on(gl, Command::new(bin));
        match display {
            Some(d) => cmd.env("DISPLAY", d),
            None => cmd.env_remove("DISPLAY"),
        };
        cmd.arg(&out);
        let log = run(cmd, LIMIT);
        let renderer = if gl == Gl::Fixedgl {
            "fixedgl"
        } else {
            "llvmpipe"
        };
        assert!(
            log.contains(renderer),
            "{gl:?} ran on something else:\n{log}"
        );
        assert!(
            !log.contains("share"),
            "{gl:?} said something of sharing:\n{log}"
        );
        images.push(Image::load_ppm(&out));
    }
    assert_eq!((images[0].width, images[0].height), (128, 96));
    images
}

#[test]
fn osmesa_sharelist_matches_mesa() {
    let Some((bin, dir)) = compile("share_osmesa", "GL/osmesa.h", &["-lOSMesa", "-lGL"]) else {
        return;
    };
    let images = on_both(&bin, &dir, "osmesa", None);
    assert_close("share_osmesa", &images[0], &images[1]);
}

#[test]
fn glx_share_list_on_two_threads_matches_mesa() {
    let Some((bin, dir)) = compile("share_glx", "GL/glx.h", &["-lGL", "-lX11", "-lpthread"]) else {
        return;
    };
    let Some(x) = Xvfb::start() else {
        return;
    };
    let images = on_both(&bin, &dir, "glx", Some(&x.display));
    assert_close("share_glx", &images[0], &images[1]);
}

extern "C" {
    fn glGenTextures(n: i32, names: *mut u32);
    fn glBindTexture(target: u32, name: u32);
    fn glTexImage2D(
        t: u32,
        l: i32,
        i: i32,
        w: i32,
        h: i32,
        b: i32,
        f: u32,
        ty: u32,
        p: *const c_void,
    );
    fn glTexParameteri(t: u32, p: u32, v: i32);
    fn glTexEnvi(t: u32, p: u32, v: i32);
    fn glEnable(cap: u32);
    fn glGenLists(n: i32) -> u32;
    fn glNewList(l: u32, mode: u32);
    fn glEndList();
    fn glCallList(l: u32);
    fn glIsList(l: u32) -> u8;
    fn glIsTexture(t: u32) -> u8;
    fn glBegin(mode: u32);
    fn glEnd();
    fn glTexCoord2f(s: f32, t: f32);
    fn glVertex2f(x: f32, y: f32);
    fn glReadPixels(x: i32, y: i32, w: i32, h: i32, f: u32, ty: u32, p: *mut c_void);
    fn glDeleteTextures(n: i32, names: *const u32);
}

const EGL_NONE: i32 = 0x3038;

/// EGL (surfaceless display, pbuffers): B made with A as share_context sees A's texture and
/// list and draws with them; A's deletion is seen by B; a share context that is no context is
/// EGL_BAD_CONTEXT; OSMesa refuses a sharelist that is no OSMesa context (NULL).
#[test]
fn egl_share_context_sees_the_texture_and_list() {
    // SAFETY: the calls as EGL and GL document them, with valid pointers.
    unsafe {
        let get: extern "C" fn(u32, *mut c_void, *const isize) -> *mut c_void =
            std::mem::transmute(eglGetProcAddress(c"eglGetPlatformDisplay".as_ptr()));
        let dpy = get(0x31DD, null_mut(), null());
        let (mut major, mut minor) = (0, 0);
        assert_eq!(eglInitialize(dpy, &mut major, &mut minor), 1);
        let attribs = [
            0x3024, 8, 0x3023, 8, 0x3022, 8, 0x3033, 1, 0x3040, 8, EGL_NONE,
        ];
        let (mut config, mut n) = (null_mut(), 0);
        assert_eq!(
            eglChooseConfig(dpy, attribs.as_ptr(), &mut config, 1, &mut n),
            1
        );
        assert_eq!(eglBindAPI(0x30A2), 1);
        let pb = [0x3057, 8, 0x3056, 8, EGL_NONE];
        let surface = eglCreatePbufferSurface(dpy, config, pb.as_ptr());
        let a = eglCreateContext(dpy, config, null_mut(), null());
        assert!(!a.is_null());
        assert_eq!(eglMakeCurrent(dpy, surface, surface, a), 1);
        let mut tex = 0;
        glGenTextures(1, &mut tex);
        glBindTexture(gl::TEXTURE_2D, tex);
        let texel = [200u8, 100, 50, 255];
        glTexImage2D(
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            1,
            1,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            texel.as_ptr().cast(),
        );
        glTexParameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
        let list = glGenLists(1);
        glNewList(list, gl::COMPILE);
        glBegin(gl::QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            glTexCoord2f(0.5, 0.5);
            glVertex2f(x, y);
        }
        glEnd();
        glEndList();
        // A share context that is no context.
        let bogus = [0u8; 64];
        assert!(eglCreateContext(dpy, config, bogus.as_ptr() as *mut c_void, null()).is_null());
        assert_eq!(eglGetError(), 0x3006, "EGL_BAD_CONTEXT");
        let b = eglCreateContext(dpy, config, a, null());
        assert!(!b.is_null());
        assert_eq!(eglMakeCurrent(dpy, surface, surface, b), 1);
        assert_eq!((glIsTexture(tex), glIsList(list)), (1, 1));
        glEnable(gl::TEXTURE_2D);
        glBindTexture(gl::TEXTURE_2D, tex);
        glTexEnvi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
        glCallList(list);
        let mut px = [0u8; 4];
        glReadPixels(
            4,
            4,
            1,
            1,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            px.as_mut_ptr().cast(),
        );
        assert_eq!(px, texel);
        assert_eq!(glGetError(), gl::NO_ERROR);
        // A deletes the texture: B no longer has it.
        assert_eq!(eglMakeCurrent(dpy, surface, surface, a), 1);
        glDeleteTextures(1, &tex);
        assert_eq!(eglMakeCurrent(dpy, surface, surface, b), 1);
        assert_eq!(glIsTexture(tex), 0);
        assert_eq!(eglMakeCurrent(dpy, null_mut(), null_mut(), null_mut()), 1);
        assert_eq!(eglDestroyContext(dpy, b), 1);
        assert_eq!(eglDestroyContext(dpy, a), 1);
        assert_eq!(eglDestroySurface(dpy, surface), 1);
        // OSMesa: a sharelist that is no OSMesa context is refused.
        let o = OSMesaCreateContextExt(gl::RGBA, 24, 8, 0, null_mut());
        assert!(!o.is_null());
        assert!(
            OSMesaCreateContextExt(gl::RGBA, 24, 8, 0, bogus.as_ptr() as *mut c_void).is_null()
        );
        let o2 = OSMesaCreateContext(gl::RGBA, o);
        assert!(!o2.is_null());
        OSMesaDestroyContext(o2);
        OSMesaDestroyContext(o);
    }
}
