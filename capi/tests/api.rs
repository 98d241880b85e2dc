//! The C entry points called as a C program calls them (the rlib's `extern "C"` functions):
//! EGL's surfaceless sequence as waffle runs it, OSMesa's buffer layouts, client arrays read at
//! draw time, GetProcAddress's answers, and queries written through C pointers.

use std::ffi::{c_void, CStr};
use std::ptr::{null, null_mut};

use fixedgl::gl;
use fixedgl_capi::egl::*;
use fixedgl_capi::glx::glXGetProcAddressARB;
use fixedgl_capi::manual::*;
use fixedgl_capi::osmesa::*;

extern "C" {
    fn glClearColor(r: f32, g: f32, b: f32, a: f32);
    fn glEnable(cap: u32);
    fn glBlendFunc(src: u32, dst: u32);
    fn glColor4f(r: f32, g: f32, b: f32, a: f32);
    fn glClear(mask: u32);
    fn glEnableClientState(cap: u32);
    fn glVertexPointer(size: i32, ty: u32, stride: i32, p: *const c_void);
    fn glColorPointer(size: i32, ty: u32, stride: i32, p: *const c_void);
    fn glDrawArrays(mode: u32, first: i32, count: i32);
    fn glDrawElements(mode: u32, count: i32, ty: u32, p: *const c_void);
    fn glLightfv(light: u32, pname: u32, params: *const f32);
    fn glNormal3fv(v: *const f32);
    fn glBegin(mode: u32);
    fn glEnd();
    fn glVertex2f(x: f32, y: f32);
    fn glColor3ub(r: u8, g: u8, b: u8);
}

const EGL_NONE: i32 = 0x3038;

/// Runs `f` with a current OSMesa context drawing into a `w` x `h` RGBA buffer; the buffer.
fn with_osmesa(w: i32, h: i32, format: u32, f: impl FnOnce()) -> Vec<u8> {
    let bpp = if format == gl::RGB || format == 0x4 {
        3
    } else {
        4
    };
    let mut buf = vec![0u8; (w * h) as usize * bpp];
    let ctx = OSMesaCreateContextExt(format, 24, 8, 0, null_mut());
    assert!(!ctx.is_null());
    assert_eq!(
        OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), gl::UNSIGNED_BYTE, w, h),
        1
    );
    f();
    // SAFETY: a context is current.
    unsafe { glFinish() };
    OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0);
    OSMesaDestroyContext(ctx);
    buf
}

#[test]
fn egl_surfaceless_sequence_as_waffle_runs_it() {
    // SAFETY: the calls as EGL documents them, with valid pointers.
    unsafe {
        let client = CStr::from_ptr(eglQueryString(null_mut(), 0x3055))
            .to_str()
            .unwrap();
        assert!(client.contains("EGL_MESA_platform_surfaceless"), "{client}");
        let get: extern "C" fn(u32, *mut c_void, *const isize) -> *mut c_void =
            std::mem::transmute(eglGetProcAddress(c"eglGetPlatformDisplay".as_ptr()));
        let dpy = get(0x31DD, null_mut(), null());
        assert!(!dpy.is_null());
        assert_eq!(
            get(0x31D5, null_mut(), null()),
            null_mut(),
            "X11 platform refused"
        );
        assert_eq!(eglGetError(), 0x300C);
        let (mut major, mut minor) = (0, 0);
        assert_eq!(eglInitialize(dpy, &mut major, &mut minor), 1);
        assert_eq!((major, minor), (1, 4));
        let apis = CStr::from_ptr(eglQueryString(dpy, 0x308D))
            .to_str()
            .unwrap();
        assert!(apis.contains("OpenGL"));
        let attribs = [
            0x3024, 8, 0x3023, 8, 0x3022, 8, 0x3025, 24, 0x3026, 1, 0x3033, 1, 0x3040, 8, EGL_NONE,
        ];
        let mut config = null_mut();
        let mut n = 0;
        assert_eq!(
            eglChooseConfig(dpy, attribs.as_ptr(), &mut config, 1, &mut n),
            1
        );
        assert_eq!(n, 1);
        // Two configs: RGB8 first for a caller that does not ask for alpha (as Mesa's
        // XRGB8888, EGL 1.4 §3.4.1.2's smaller EGL_BUFFER_SIZE), RGBA8 alone when it does.
        let mut two = [null_mut(); 2];
        assert_eq!(
            eglChooseConfig(dpy, attribs.as_ptr(), two.as_mut_ptr(), 2, &mut n),
            1
        );
        assert_eq!(n, 2);
        let attrib = |c, a| {
            let mut v = -1;
            assert_eq!(eglGetConfigAttrib(dpy, c, a, &mut v), 1);
            v
        };
        // EGL_ALPHA_SIZE, EGL_BUFFER_SIZE, EGL_CONFIG_ID.
        let sizes = |c| [attrib(c, 0x3021), attrib(c, 0x3020), attrib(c, 0x3028)];
        assert_eq!(sizes(two[0]), [0, 24, 2]);
        assert_eq!(sizes(two[1]), [8, 32, 1]);
        let rgba = two[1];
        let with_alpha = [0x3021, 1, EGL_NONE];
        assert_eq!(
            eglChooseConfig(dpy, with_alpha.as_ptr(), two.as_mut_ptr(), 2, &mut n),
            1
        );
        assert_eq!((n, two[0]), (1, rgba));
        assert_eq!(eglGetConfigs(dpy, null_mut(), 0, &mut n), 1);
        assert_eq!(n, 2);
        // OpenGL ES is not offered: no config.
        let es = [0x3040, 0x4, EGL_NONE];
        assert_eq!(eglChooseConfig(dpy, es.as_ptr(), &mut config, 1, &mut n), 1);
        assert_eq!(n, 0);
        eglChooseConfig(dpy, attribs.as_ptr(), &mut config, 1, &mut n);
        assert_eq!(eglBindAPI(0x30A2), 1);
        let ctx_attribs = [0x3098, 1, 0x30FB, 0, EGL_NONE];
        let ctx = eglCreateContext(dpy, config, null_mut(), ctx_attribs.as_ptr());
        assert!(!ctx.is_null());
        let too_new = [0x3098, 3, 0x30FB, 2, EGL_NONE];
        assert!(eglCreateContext(dpy, config, null_mut(), too_new.as_ptr()).is_null());
        assert_eq!(eglGetError(), 0x3009);
        let pb = [0x3057, 160, 0x3056, 160, EGL_NONE];
        let surface = eglCreatePbufferSurface(dpy, config, pb.as_ptr());
        assert!(!surface.is_null());
        assert_eq!(eglMakeCurrent(dpy, surface, surface, ctx), 1);
        let mut vp = [0i32; 4];
        glGetIntegerv(gl::VIEWPORT, vp.as_mut_ptr());
        assert_eq!(vp, [0, 0, 160, 160]);
        // The first config chosen has no alpha bits.
        let mut bits = [-1i32];
        glGetIntegerv(gl::ALPHA_BITS, bits.as_mut_ptr());
        assert_eq!(bits, [0]);
        let mut id = 0;
        assert_eq!(eglQueryContext(dpy, ctx, 0x3028, &mut id), 1);
        assert_eq!(id, 2);
        assert_eq!(eglGetCurrentContext(), ctx);
        // A stale handle is refused, not followed.
        assert_eq!(
            eglMakeCurrent(dpy, surface, surface, 0x1234 as *mut c_void),
            0
        );
        assert_eq!(eglGetError(), 0x3006);
        assert_eq!(eglMakeCurrent(dpy, null_mut(), null_mut(), null_mut()), 1);
        assert_eq!(eglDestroySurface(dpy, surface), 1);
        assert_eq!(eglDestroySurface(dpy, surface), 0);
        assert_eq!(eglDestroyContext(dpy, ctx), 1);
        assert_eq!(eglDestroyContext(dpy, ctx), 0);
        assert_eq!(eglGetError(), 0x3006);
    }
}

/// The GL functions capi/src/generated.rs exports as `unimplemented(..)` stubs.
fn unimplemented_names() -> Vec<&'static str> {
    include_str!("../src/generated.rs")
        .split("unimplemented(\"")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect()
}

#[test]
fn get_proc_address_answers_only_what_works() {
    // SAFETY: NUL-terminated names.
    unsafe {
        assert!(!glXGetProcAddressARB(c"glBegin".as_ptr()).is_null());
        assert!(!glXGetProcAddressARB(c"glActiveTextureARB".as_ptr()).is_null());
        assert!(!eglGetProcAddress(c"glLightfv".as_ptr()).is_null());
        assert!(!OSMesaGetProcAddress(c"glDrawArrays".as_ptr()).is_null());
        assert!(!OSMesaGetProcAddress(c"OSMesaMakeCurrent".as_ptr()).is_null());
        assert!(!glXGetProcAddressARB(c"glSampleCoverage".as_ptr()).is_null());
        assert!(!glXGetProcAddressARB(c"glCompressedTexImage2DARB".as_ptr()).is_null());
        assert!(!glXGetProcAddressARB(c"glGetCompressedTexImage".as_ptr()).is_null());
        // Not implemented: NULL, so that a program can tell. The names are those the generated
        // exports still leave unimplemented (derived, so the test follows the table; when none
        // remains there is nothing to answer NULL for but unknown names).
        for name in unimplemented_names() {
            let c = std::ffi::CString::new(name).expect("a C name");
            assert!(glXGetProcAddressARB(c.as_ptr()).is_null(), "{name}");
        }
        assert!(glXGetProcAddressARB(c"glNoSuchThing".as_ptr()).is_null());
        assert!(glXGetProcAddressARB(null()).is_null());
    }
}

#[test]
fn osmesa_writes_the_frame_as_each_format_lays_it_out() {
    let draw = || {
        // SAFETY: a context is current.
        unsafe {
            glClearColor(0.0, 0.0, 1.0, 1.0);
            glClear(gl::COLOR_BUFFER_BIT);
            glBegin(gl::QUADS);
            glColor3ub(255, 128, 0);
            glVertex2f(-1.0, -1.0);
            glVertex2f(0.0, -1.0);
            glVertex2f(0.0, 0.0);
            glVertex2f(-1.0, 0.0);
            glEnd();
        }
    };
    // 4x2: the bottom-left quarter (x 0..2, y 0) is orange, the rest blue. Y_UP (the default):
    // memory row 0 is the bottom row.
    let rgba = with_osmesa(4, 2, gl::RGBA, draw);
    assert_eq!(&rgba[0..4], &[255, 128, 0, 255]);
    assert_eq!(&rgba[8..12], &[0, 0, 255, 255]);
    assert_eq!(&rgba[16..20], &[0, 0, 255, 255], "row 1 (top) is blue");
    let bgra = with_osmesa(4, 2, 0x1, draw);
    assert_eq!(&bgra[0..4], &[0, 128, 255, 255]);
    let argb = with_osmesa(4, 2, 0x2, draw);
    assert_eq!(&argb[0..4], &[255, 255, 128, 0]);
    let rgb = with_osmesa(4, 2, gl::RGB, draw);
    assert_eq!(&rgb[0..6], &[255, 128, 0, 255, 128, 0]);
    let bgr = with_osmesa(4, 2, 0x4, draw);
    assert_eq!(&bgr[0..3], &[0, 128, 255]);
    // Y_UP off: memory row 0 is the top row.
    let top_down = with_osmesa(4, 2, gl::RGBA, || {
        OSMesaPixelStore(0x11, 0);
        draw();
    });
    assert_eq!(&top_down[0..4], &[0, 0, 255, 255]);
    assert_eq!(&top_down[16..20], &[255, 128, 0, 255]);
}

/// The formats without alpha (RGB, BGR, RGB_565) get a framebuffer without alpha bits, and
/// RGB_565 stores each colour rounded to 5/6/5 bits. The expected values are what Mesa's
/// libOSMesa 8 gave for the same calls (a clear to (0.06, 0.5, 0.1, 0.3), then a quad over the
/// left half blended with ONE_MINUS_DST_ALPHA, DST_ALPHA; measured with a C program): without
/// alpha the destination alpha reads 1, so the quad leaves the cleared colour; with alpha it
/// blends. (Mesa's libOSMesa 8 refuses BGR with UNSIGNED_BYTE; fixedgl takes it.)
#[test]
fn osmesa_formats_without_alpha_have_no_alpha_bits() {
    let run = |format: u32, ty: u32, bpp: usize| {
        let mut buf = vec![0xABu8; 4 * 4 * bpp];
        let ctx = OSMesaCreateContextExt(format, 24, 8, 0, null_mut());
        assert!(!ctx.is_null());
        assert_eq!(OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), ty, 4, 4), 1);
        let (mut bits, mut px) = ([0i32; 4], [0u8; 4]);
        // SAFETY: a context is current; room for one value each and one pixel.
        unsafe {
            for (b, pname) in
                bits.iter_mut()
                    .zip([gl::RED_BITS, gl::GREEN_BITS, gl::BLUE_BITS, gl::ALPHA_BITS])
            {
                glGetIntegerv(pname, b);
            }
            glClearColor(0.06, 0.5, 0.1, 0.3);
            glClear(gl::COLOR_BUFFER_BIT);
            glEnable(gl::BLEND);
            glBlendFunc(gl::ONE_MINUS_DST_ALPHA, gl::DST_ALPHA);
            glColor4f(1.0, 0.2, 0.7, 0.5);
            glBegin(gl::QUADS);
            glVertex2f(-1.0, -1.0);
            glVertex2f(0.0, -1.0);
            glVertex2f(0.0, 1.0);
            glVertex2f(-1.0, 1.0);
            glEnd();
            glFinish();
            glReadPixels(
                0,
                0,
                1,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                px.as_mut_ptr().cast(),
            );
        }
        OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0);
        OSMesaDestroyContext(ctx);
        (bits[3], px, buf)
    };
    let (alpha, px, buf) = run(gl::RGBA, gl::UNSIGNED_BYTE, 4);
    assert_eq!((alpha, px), (8, [183, 74, 133, 113]));
    assert_eq!(&buf[..4], &[183, 74, 133, 113]);
    assert_eq!(&buf[12..16], &[15, 128, 26, 76]);
    let (alpha, px, buf) = run(gl::RGB, gl::UNSIGNED_BYTE, 3);
    assert_eq!((alpha, px), (0, [15, 128, 26, 255]));
    assert_eq!(&buf[..12], &[15, 128, 26].repeat(4)[..]);
    let (alpha, px, buf) = run(0x4, gl::UNSIGNED_BYTE, 3);
    assert_eq!((alpha, px), (0, [15, 128, 26, 255]), "BGR");
    assert_eq!(&buf[..6], &[26, 128, 15, 26, 128, 15]);
    // RGB_565: red 2, green 32, blue 3 (round(0.06·31), round(0.5·63), round(0.1·31)) in a
    // native-endian u16, every pixel. (Mesa also renders in 5/6/5 bits and reports RED_BITS 5,
    // GREEN_BITS 6, BLUE_BITS 5, and ReadPixels gives 16, 130, 24; fixedgl renders at 8 bits,
    // docs/conformance.md §4.2.)
    let (alpha, _, buf) = run(0x5, gl::UNSIGNED_SHORT_5_6_5, 2);
    assert_eq!(alpha, 0);
    let want = ((2u16 << 11) | (32 << 5) | 3).to_ne_bytes();
    for p in buf.chunks_exact(2) {
        assert_eq!(p, want);
    }
}

#[test]
fn client_arrays_are_read_when_the_draw_happens() {
    let mut vertices = [-1.0f32, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0];
    let colors = [255u8, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0];
    let buf = with_osmesa(2, 2, gl::RGBA, || {
        // SAFETY: a context is current; the arrays outlive the draw.
        unsafe {
            glEnableClientState(gl::VERTEX_ARRAY);
            glEnableClientState(gl::COLOR_ARRAY);
            glVertexPointer(2, gl::FLOAT, 0, vertices.as_ptr().cast());
            glColorPointer(3, gl::UNSIGNED_BYTE, 0, colors.as_ptr().cast());
            // Moved after the pointer call: GL reads it at the draw, so the quad covers only
            // the left column.
            vertices[2] = 0.0;
            vertices[4] = 0.0;
            let indices = [0u8, 1, 2, 0, 2, 3];
            glDrawElements(gl::TRIANGLES, 6, gl::UNSIGNED_BYTE, indices.as_ptr().cast());
            let mut error = glGetError();
            assert_eq!(error, gl::NO_ERROR);
            // NULL arrays are an error, not a crash.
            glVertexPointer(2, gl::FLOAT, 0, null());
            glDrawArrays(gl::TRIANGLES, 0, 3);
            error = glGetError();
            assert_eq!(error, gl::INVALID_OPERATION);
        }
    });
    assert_eq!(&buf[0..4], &[255, 0, 0, 255]);
    assert_eq!(&buf[4..8], &[0, 0, 0, 0], "the right column is not drawn");
}

#[test]
fn queries_write_exactly_the_pname_s_values() {
    let _ = with_osmesa(8, 8, gl::RGBA, || {
        // SAFETY: a context is current; every buffer holds what the pname writes and more.
        unsafe {
            let mut m = [7.0f32; 20];
            glGetFloatv(gl::MODELVIEW_MATRIX, m.as_mut_ptr());
            assert_eq!(
                &m[..16],
                &[1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.]
            );
            assert_eq!(m[16], 7.0, "nothing past the 16 values");
            let mut b = [9u8; 4];
            glGetBooleanv(gl::DEPTH_TEST, b.as_mut_ptr());
            assert_eq!(b, [0, 9, 9, 9]);
            // An unknown pname writes nothing and is INVALID_ENUM; NULL is INVALID_VALUE.
            let mut v = [5i32; 4];
            glGetIntegerv(0xFFFF, v.as_mut_ptr());
            assert_eq!(v, [5; 4]);
            assert_eq!(glGetError(), gl::INVALID_ENUM);
            glGetIntegerv(gl::VIEWPORT, null_mut());
            assert_eq!(glGetError(), gl::INVALID_VALUE);
            let pos = [1.0f32, 2.0, 3.0, 0.0];
            glLightfv(gl::LIGHT0, gl::POSITION, pos.as_ptr());
            let mut out = [0.0f32; 5];
            glGetLightfv(gl::LIGHT0, gl::POSITION, out.as_mut_ptr());
            assert_eq!(&out[..4], &pos);
            // A fixed-size vector given as NULL is INVALID_VALUE.
            glNormal3fv(null());
            assert_eq!(glGetError(), gl::INVALID_VALUE);
            let version = CStr::from_ptr(glGetString(gl::VERSION).cast())
                .to_str()
                .unwrap();
            assert!(version.starts_with("1.5 fixedgl"), "{version}");
            assert!(glGetString(0x1234).is_null());
            assert_eq!(glGetError(), gl::INVALID_ENUM);
        }
    });
}

#[test]
fn calls_without_a_current_context_do_nothing() {
    // SAFETY: no context is current on this thread: every call is a no-op.
    unsafe {
        glClear(gl::COLOR_BUFFER_BIT);
        assert_eq!(glGetError(), 0);
        assert!(glGetString(gl::VERSION).is_null());
    }
}
