//! GLU quadrics (`fixedgl::glu`) against the real libGLU (Mesa's libGLU 9.0, loaded with
//! `dlopen`) running on llvmpipe: for every draw style, normal mode, orientation and texture
//! setting of spheres, cylinders, cones, disks and partial disks, the driver's feedback buffer
//! (GL_4D_COLOR_TEXTURE, lit, so normals show in the colours) is the same, float for float,
//! whether libGLU issues the calls or fixedgl's recorded calls are replayed; the same errors
//! reach the error callback; `gluErrorString` gives the same text; and the CPU pipeline's
//! picture of fixedgl's quadrics matches llvmpipe's picture of libGLU's.
//!
//! Without libGLU.so.1 or an EGL device the driver tests print `SKIPPED` and return.

use fixedgl::glu::{self, Quadric, GLU_FILL, GLU_FLAT, GLU_LINE, GLU_NONE, GLU_POINT};
use fixedgl::glu::{GLU_INSIDE, GLU_OUTSIDE, GLU_SILHOUETTE, GLU_SMOOTH};
use fixedgl::{gl, Context};

/// One quadric call.
#[derive(Clone, Copy, Debug)]
enum Shape {
    Sphere(f64, i32, i32),
    Cylinder(f64, f64, f64, i32, i32),
    Disk(f64, f64, i32, i32),
    PartialDisk(f64, f64, i32, i32, f64, f64),
}

/// The quadric settings of one case.
#[derive(Clone, Copy, Debug)]
struct Style {
    draw: u32,
    normals: u32,
    orientation: u32,
    texture: bool,
}

fn quadric(s: Style) -> Quadric {
    let mut q = glu::new_quadric();
    glu::quadric_draw_style(&mut q, s.draw);
    glu::quadric_normals(&mut q, s.normals);
    glu::quadric_orientation(&mut q, s.orientation);
    glu::quadric_texture(&mut q, s.texture);
    q
}

fn draw(ctx: &mut Context, q: &mut Quadric, shape: Shape) {
    match shape {
        Shape::Sphere(r, sl, st) => glu::sphere(ctx, q, r, sl, st),
        Shape::Cylinder(b, t, h, sl, st) => glu::cylinder(ctx, q, b, t, h, sl, st),
        Shape::Disk(i, o, sl, l) => glu::disk(ctx, q, i, o, sl, l),
        Shape::PartialDisk(i, o, sl, l, s, w) => glu::partial_disk(ctx, q, i, o, sl, l, s, w),
    }
}

const SHAPES: &[Shape] = &[
    Shape::Sphere(1.2, 12, 8),
    Shape::Sphere(0.9, 7, 7),
    Shape::Sphere(1.0, 5, 1),
    Shape::Cylinder(1.0, 0.4, 1.5, 11, 3),
    Shape::Cylinder(0.8, 0.0, 1.2, 9, 2),
    Shape::Cylinder(0.5, 0.5, 1.0, 6, 1),
    Shape::Disk(0.3, 1.2, 10, 3),
    Shape::Disk(0.0, 1.1, 9, 2),
    Shape::PartialDisk(0.2, 1.3, 7, 3, 30.0, 250.0),
    Shape::PartialDisk(0.0, 1.3, 8, 2, 100.0, -100.0),
    Shape::PartialDisk(0.6, 0.6, 8, 2, 10.0, 120.0),
    Shape::PartialDisk(0.4, 1.0, 5, 1, 0.0, 400.0),
    Shape::PartialDisk(0.4, 1.0, 5, 2, 20.0, -500.0),
];

/// Calls that must raise GLU_INVALID_VALUE and draw nothing.
const BAD: &[Shape] = &[
    Shape::Sphere(1.0, 1, 4),
    Shape::Sphere(1.0, 4, 0),
    Shape::Sphere(-1.0, 4, 4),
    Shape::Cylinder(-0.1, 1.0, 1.0, 5, 2),
    Shape::Cylinder(1.0, 1.0, -1.0, 5, 2),
    Shape::Cylinder(0.0, 0.0, 0.0, 5, 2),
    Shape::Disk(0.5, 0.4, 5, 2),
    Shape::Disk(0.0, 0.0, 5, 2),
    Shape::Disk(0.1, 1.0, 5, 0),
];

/// Every combination whose calls libGLU fully defines: it reads tables it never filled for FLAT
/// normals with POINT or SILHOUETTE on spheres and cylinders (see `glu/quadric.rs`).
fn styles(shape: Shape) -> Vec<Style> {
    let mut out = Vec::new();
    for draw in [GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT] {
        for normals in [GLU_SMOOTH, GLU_FLAT, GLU_NONE] {
            let round = matches!(shape, Shape::Sphere(..) | Shape::Cylinder(..));
            if round && normals == GLU_FLAT && matches!(draw, GLU_POINT | GLU_SILHOUETTE) {
                continue;
            }
            for orientation in [GLU_OUTSIDE, GLU_INSIDE] {
                for texture in [false, true] {
                    out.push(Style {
                        draw,
                        normals,
                        orientation,
                        texture,
                    });
                }
            }
        }
    }
    out
}

#[test]
fn settings_and_errors() {
    let mut q = glu::new_quadric();
    assert_eq!(
        (
            q.draw_style(),
            q.normals(),
            q.orientation(),
            q.texture_coords()
        ),
        (GLU_FILL, GLU_SMOOTH, GLU_OUTSIDE, false)
    );
    let seen = std::rc::Rc::new(std::cell::RefCell::new(Vec::new()));
    let log = seen.clone();
    glu::quadric_callback(
        &mut q,
        glu::GLU_ERROR,
        Some(Box::new(move |e| log.borrow_mut().push(e))),
    );
    glu::quadric_draw_style(&mut q, gl::FILL);
    glu::quadric_normals(&mut q, GLU_FILL);
    glu::quadric_orientation(&mut q, 0);
    assert_eq!(q.draw_style(), GLU_FILL);
    let mut c = match Context::new(8, 8) {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    };
    c.start_recording();
    for &shape in BAD {
        draw(&mut c, &mut q, shape);
    }
    assert!(c.stop_recording().is_empty(), "an erroneous quadric drew");
    let ie = glu::GLU_INVALID_ENUM as u32;
    let iv = glu::GLU_INVALID_VALUE as u32;
    let mut want = vec![ie, ie, ie];
    want.extend(std::iter::repeat(iv).take(BAD.len()));
    assert_eq!(*seen.borrow(), want);
    assert_eq!(q.take_error(), iv);
    assert_eq!(q.take_error(), 0);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn every_shape_draws_its_primitives() {
    for &shape in SHAPES {
        for style in styles(shape) {
            let mut c = match Context::new(8, 8) {
                Ok(c) => c,
                Err(e) => panic!("{e}"),
            };
            let mut q = quadric(style);
            c.start_recording();
            draw(&mut c, &mut q, shape);
            let calls = c.stop_recording();
            assert_eq!(c.get_error(), gl::NO_ERROR, "{shape:?} {style:?}");
            assert_eq!(q.take_error(), 0, "{shape:?} {style:?}");
            let begins = calls
                .iter()
                .filter(|c| matches!(c, fixedgl::Call::Begin(_)))
                .count();
            assert!(begins > 0, "{shape:?} {style:?}: nothing drawn");
        }
    }
}

#[cfg(feature = "gl")]
mod with_libglu {
    use super::*;
    use fixedgl::compare::compare;
    use fixedgl::glbackend::GlBackend;
    use std::ffi::{c_char, c_int, c_void, CStr};
    use std::sync::atomic::{AtomicU32, Ordering};

    extern "C" {
        fn dlopen(file: *const c_char, mode: c_int) -> *mut c_void;
        fn dlsym(handle: *mut c_void, name: *const c_char) -> *mut c_void;
    }
    const RTLD_NOW: c_int = 2;

    type Q = *mut c_void;
    type Callback = unsafe extern "C" fn(Q, u32, Option<unsafe extern "C" fn(u32)>);
    type Cylinder = unsafe extern "C" fn(Q, f64, f64, f64, i32, i32);
    type PartialDisk = unsafe extern "C" fn(Q, f64, f64, i32, i32, f64, f64);

    /// The libGLU entry points the tests call.
    struct LibGlu {
        new_quadric: unsafe extern "C" fn() -> Q,
        delete_quadric: unsafe extern "C" fn(Q),
        draw_style: unsafe extern "C" fn(Q, u32),
        normals: unsafe extern "C" fn(Q, u32),
        orientation: unsafe extern "C" fn(Q, u32),
        texture: unsafe extern "C" fn(Q, u8),
        callback: Callback,
        sphere: unsafe extern "C" fn(Q, f64, i32, i32),
        cylinder: Cylinder,
        disk: unsafe extern "C" fn(Q, f64, f64, i32, i32),
        partial_disk: PartialDisk,
        error_string: unsafe extern "C" fn(u32) -> *const c_char,
    }

    fn libglu() -> Option<LibGlu> {
        // SAFETY: dlopen/dlsym with NUL-terminated names; each symbol is cast to the type of
        // the libGLU function of that name (GL/glu.h).
        unsafe {
            let h = dlopen(c"libGLU.so.1".as_ptr(), RTLD_NOW);
            if h.is_null() {
                use std::io::Write as _;
                let _ = writeln!(std::io::stderr(), "SKIPPED: libGLU.so.1 not found");
                return None;
            }
            macro_rules! sym {
                ($name:literal, $ty:ty) => {{
                    let p = dlsym(h, $name.as_ptr());
                    if p.is_null() {
                        return None;
                    }
                    std::mem::transmute::<*mut c_void, $ty>(p)
                }};
            }
            type Set = unsafe extern "C" fn(Q, u32);
            Some(LibGlu {
                new_quadric: sym!(c"gluNewQuadric", unsafe extern "C" fn() -> Q),
                delete_quadric: sym!(c"gluDeleteQuadric", unsafe extern "C" fn(Q)),
                draw_style: sym!(c"gluQuadricDrawStyle", Set),
                normals: sym!(c"gluQuadricNormals", Set),
                orientation: sym!(c"gluQuadricOrientation", Set),
                texture: sym!(c"gluQuadricTexture", unsafe extern "C" fn(Q, u8)),
                callback: sym!(c"gluQuadricCallback", Callback),
                sphere: sym!(c"gluSphere", unsafe extern "C" fn(Q, f64, i32, i32)),
                cylinder: sym!(c"gluCylinder", Cylinder),
                disk: sym!(c"gluDisk", unsafe extern "C" fn(Q, f64, f64, i32, i32)),
                partial_disk: sym!(c"gluPartialDisk", PartialDisk),
                error_string: sym!(
                    c"gluErrorString",
                    unsafe extern "C" fn(u32) -> *const c_char
                ),
            })
        }
    }

    static LAST_ERROR: AtomicU32 = AtomicU32::new(0);
    unsafe extern "C" fn on_error(e: u32) {
        LAST_ERROR.store(e, Ordering::SeqCst);
    }

    impl LibGlu {
        /// libGLU draws `shape` with `style` on `gl`'s context (current on this thread).
        fn draw(&self, gl: &GlBackend, style: Style, shape: Shape) {
            // SAFETY: the quadric is created and deleted here; the backend's context is made
            // current by `raw()`, and libGLU's GL calls go to it; no Begin is left open.
            unsafe {
                let _ = gl.raw();
                let q = (self.new_quadric)();
                assert!(!q.is_null());
                (self.callback)(q, glu::GLU_ERROR, Some(on_error));
                (self.draw_style)(q, style.draw);
                (self.normals)(q, style.normals);
                (self.orientation)(q, style.orientation);
                (self.texture)(q, u8::from(style.texture));
                match shape {
                    Shape::Sphere(r, sl, st) => (self.sphere)(q, r, sl, st),
                    Shape::Cylinder(b, t, h, sl, st) => (self.cylinder)(q, b, t, h, sl, st),
                    Shape::Disk(i, o, sl, l) => (self.disk)(q, i, o, sl, l),
                    Shape::PartialDisk(i, o, sl, l, s, w) => {
                        (self.partial_disk)(q, i, o, sl, l, s, w)
                    }
                }
                (self.delete_quadric)(q);
            }
        }
    }

    /// Lit, textured-looking state so that normals and texture coordinates reach feedback.
    fn setup(c: &mut Context) {
        c.matrix_mode(gl::PROJECTION);
        c.ortho(-2.0, 2.0, -2.0, 2.0, -10.0, 10.0);
        c.matrix_mode(gl::MODELVIEW);
        c.rotatef(-50.0, 1.0, 0.0, 0.0);
        c.rotatef(20.0, 0.0, 0.0, 1.0);
        c.enable(gl::LIGHTING);
        c.enable(gl::LIGHT0);
        c.lightfv(gl::LIGHT0, gl::POSITION, &[0.4, 0.7, 1.0, 0.0]);
        c.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1);
        c.materialfv(gl::FRONT, gl::DIFFUSE, &[0.9, 0.6, 0.2, 1.0]);
        c.materialfv(gl::BACK, gl::DIFFUSE, &[0.2, 0.5, 0.9, 1.0]);
        c.normal3f(0.3, -0.2, 0.9);
        c.tex_coord2f(0.25, 0.75);
    }

    /// The driver's feedback buffer of `draw` (GL_4D_COLOR_TEXTURE), from the same current
    /// normal and texture coordinates each time (a FLAT sphere's pole takes the current one).
    fn feedback(gl: &mut GlBackend, draw: impl FnOnce(&mut GlBackend)) -> Vec<u32> {
        gl.replay(&[
            fixedgl::Call::Normal3f(0.3, -0.2, 0.9),
            fixedgl::Call::TexCoord2f(0.25, 0.75),
        ]);
        const N: usize = 1 << 23;
        let mut buf = vec![0.0f32; N];
        // SAFETY: the buffer outlives feedback mode, which ends below; N floats of room.
        unsafe {
            let raw = gl.raw();
            raw.FeedbackBuffer(N as i32, gl::GL_4D_COLOR_TEXTURE, buf.as_mut_ptr());
            raw.RenderMode(gl::FEEDBACK);
        }
        draw(gl);
        // SAFETY: leaves feedback mode; no pointers.
        let n = unsafe { gl.raw().RenderMode(gl::RENDER) };
        assert!(n >= 0, "feedback overflow");
        buf.truncate(n as usize);
        buf.into_iter().map(f32::to_bits).collect()
    }

    #[test]
    fn every_call_stream_is_libglus() {
        let Some(lib) = libglu() else { return };
        let Some(mut gl) = crate::common::test_backend(64, 64) else {
            return;
        };
        let mut base = match Context::new(64, 64) {
            Ok(c) => c,
            Err(e) => panic!("{e}"),
        };
        base.start_recording();
        setup(&mut base);
        gl.replay(&base.stop_recording());
        let mut cases = 0;
        let mut shapes: Vec<Shape> = SHAPES.to_vec();
        // More than 239 slices and stacks: both drawn as 239.
        shapes.push(Shape::Sphere(1.0, 300, 260));
        for shape in shapes {
            let all = styles(shape);
            let styles = if matches!(shape, Shape::Sphere(_, 300, _)) {
                all.into_iter().take(4).collect()
            } else {
                all
            };
            for style in styles {
                let theirs = feedback(&mut gl, |gl| lib.draw(gl, style, shape));
                let mut c = match Context::new(64, 64) {
                    Ok(c) => c,
                    Err(e) => panic!("{e}"),
                };
                let mut q = quadric(style);
                c.start_recording();
                draw(&mut c, &mut q, shape);
                let calls = c.stop_recording();
                let ours = feedback(&mut gl, |gl| gl.replay(&calls));
                assert!(
                    theirs.len() > 20,
                    "{shape:?} {style:?}: libGLU drew nothing"
                );
                if theirs != ours {
                    let at = theirs.iter().zip(&ours).position(|(a, b)| a != b);
                    panic!(
                        "{shape:?} {style:?}: feedback differs ({} vs {} values, first at {at:?})",
                        theirs.len(),
                        ours.len()
                    );
                }
                assert_eq!(LAST_ERROR.load(Ordering::SeqCst), 0);
                cases += 1;
            }
        }
        assert!(cases > 300, "{cases} cases");
        assert_eq!(gl.get_error(), gl::NO_ERROR);
    }

    #[test]
    fn errors_reach_the_callback_as_in_libglu() {
        let Some(lib) = libglu() else { return };
        let Some(gl) = crate::common::test_backend(16, 16) else {
            return;
        };
        let style = Style {
            draw: GLU_FILL,
            normals: GLU_SMOOTH,
            orientation: GLU_OUTSIDE,
            texture: false,
        };
        for &shape in BAD {
            LAST_ERROR.store(0, Ordering::SeqCst);
            lib.draw(&gl, style, shape);
            let theirs = LAST_ERROR.swap(0, Ordering::SeqCst);
            let mut q = quadric(style);
            let mut c = match Context::new(8, 8) {
                Ok(c) => c,
                Err(e) => panic!("{e}"),
            };
            draw(&mut c, &mut q, shape);
            assert_eq!(q.take_error(), theirs, "{shape:?}");
            assert_eq!(theirs, glu::GLU_INVALID_VALUE as u32, "{shape:?}");
        }
    }

    #[test]
    fn error_strings_are_libglus() {
        let Some(lib) = libglu() else { return };
        let codes = (0..=0x600u32)
            .chain([0x8031])
            .chain(100_000..=101_000)
            .chain([u32::MAX]);
        for code in codes {
            // SAFETY: gluErrorString returns NULL or a static NUL-terminated string.
            let theirs = unsafe {
                let p = (lib.error_string)(code);
                (!p.is_null()).then(|| CStr::from_ptr(p).to_string_lossy().into_owned())
            };
            assert_eq!(
                glu::error_string(code).map(str::to_string),
                theirs,
                "{code}"
            );
        }
    }

    /// fixedgl's quadrics on the CPU pipeline against libGLU's on llvmpipe: the same picture.
    #[test]
    fn cpu_pictures_match_libglu_on_the_driver() {
        let Some(lib) = libglu() else { return };
        let Some(mut gl) = crate::common::test_backend(256, 256) else {
            return;
        };
        let mut c = match Context::new(256, 256) {
            Ok(c) => c,
            Err(e) => panic!("{e}"),
        };
        c.start_recording();
        setup(&mut c);
        c.enable(gl::DEPTH_TEST);
        c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        gl.replay(&c.stop_recording());
        let placed = [
            (Shape::Sphere(0.5, 16, 12), [-1.0, 1.0], GLU_FILL),
            (Shape::Cylinder(0.4, 0.2, 0.8, 12, 3), [0.9, 1.0], GLU_FILL),
            (Shape::Disk(0.2, 0.6, 14, 3), [-1.0, -0.9], GLU_LINE),
            (
                Shape::PartialDisk(0.0, 0.6, 10, 2, 45.0, 200.0),
                [0.9, -0.9],
                GLU_FILL,
            ),
            (Shape::Sphere(0.4, 10, 8), [0.0, 0.0], GLU_SILHOUETTE),
        ];
        for (shape, [x, y], draw_style) in placed {
            let style = Style {
                draw: draw_style,
                normals: GLU_SMOOTH,
                orientation: GLU_OUTSIDE,
                texture: false,
            };
            c.start_recording();
            c.push_matrix();
            c.translatef(x, y, 0.0);
            let moved = c.stop_recording();
            gl.replay(&moved);
            lib.draw(&gl, style, shape);
            let mut q = quadric(style);
            draw(&mut c, &mut q, shape);
            c.start_recording();
            c.pop_matrix();
            gl.replay(&c.stop_recording());
        }
        assert_eq!(c.get_error(), gl::NO_ERROR);
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        let cmp = compare(&c.to_image(), &gl.read_image(), 2);
        assert!(
            cmp.passes(0.05),
            "{} pixels differ (max {:?})",
            cmp.differing_pixels,
            cmp.max_diff
        );
    }
}
