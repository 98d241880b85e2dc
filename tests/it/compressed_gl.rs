//! GL 1.3's compressed-texture commands and SampleCoverage (GL 2.1 §3.8.3, §4.1.3, §6.1.4)
//! against the real driver (Mesa llvmpipe through EGL), issue #14. fixedgl offers no
//! compressed format, so every CompressedTex*Image call is an error; the driver, which offers
//! S3TC and more, gets the calls whose error cannot depend on that (the others get fixedgl's
//! error from the backend: glbackend/compressed.rs), and both must agree, in display lists
//! too. Each test runs the same calls on the CPU front end and on the driver. Skipped, with a
//! note on stderr, when no GL backend can start.
#![cfg(feature = "gl")]

use crate::common::{cpu_vs_gl, test_backend};
use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context};

/// EXT_texture_compression_s3tc's COMPRESSED_RGB_S3TC_DXT1: the driver takes it, fixedgl not.
const DXT1: u32 = 0x83F0;
/// GL 3.0's TEXTURE_2D_ARRAY, a target the driver takes and GL 2.1 does not have.
const TEXTURE_2D_ARRAY: u32 = 0x8C1A;

fn img1(target: u32, level: i32, ifmt: u32, size: i32, data: Option<Vec<u8>>) -> Call {
    Call::CompressedTexImage1D(Box::new((target, level, ifmt, 4, 0, size, data)))
}

fn img2(target: u32, level: i32, ifmt: u32, w: i32, size: i32, data: Option<Vec<u8>>) -> Call {
    Call::CompressedTexImage2D(Box::new((target, level, ifmt, w, w, 0, size, data)))
}

fn img3(target: u32, ifmt: u32, size: i32, data: Option<Vec<u8>>) -> Call {
    Call::CompressedTexImage3D(Box::new((target, 0, ifmt, 4, 4, 4, 0, size, data)))
}

fn sub1(target: u32, format: u32, size: i32) -> Call {
    Call::CompressedTexSubImage1D(Box::new((
        target,
        0,
        0,
        4,
        format,
        size,
        Some(vec![0; size.max(0) as usize]),
    )))
}

fn sub2(target: u32, level: i32, format: u32, size: i32) -> Call {
    Call::CompressedTexSubImage2D(Box::new((
        target,
        level,
        0,
        0,
        4,
        4,
        format,
        size,
        Some(vec![0; size.max(0) as usize]),
    )))
}

fn sub3(target: u32, format: u32, size: i32) -> Call {
    Call::CompressedTexSubImage3D(Box::new((
        target,
        0,
        0,
        0,
        0,
        4,
        4,
        4,
        format,
        size,
        Some(vec![0; size.max(0) as usize]),
    )))
}

/// Uncompressed images on TEXTURE_1D, _2D, _3D and the +X face, 4 texels wide.
fn images() -> Vec<Call> {
    let rgba = |n: usize| Some(vec![200u8; n * 4]);
    vec![
        Call::TexImage1D(Box::new((
            gl::TEXTURE_1D,
            0,
            gl::RGBA as i32,
            4,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            rgba(4),
        ))),
        Call::TexImage2D(Box::new((
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            4,
            4,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            rgba(16),
        ))),
        Call::TexImage3D(Box::new((
            gl::TEXTURE_3D,
            0,
            gl::RGBA as i32,
            4,
            4,
            4,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            rgba(64),
        ))),
        Call::TexImage2D(Box::new((
            gl::TEXTURE_CUBE_MAP_POSITIVE_X,
            0,
            gl::RGB as i32,
            4,
            4,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            rgba(16),
        ))),
    ]
}

/// Runs `calls` on both, each expected to leave `expected`.
fn run_rows(cpu: &mut Context, gl: &mut GlBackend, rows: &[(Call, u32)]) {
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), *expected, "GL after row {i}: {call:?}");
    }
}

/// A level parameter of `target`'s level 0 on both: (cpu, driver).
fn level_param(cpu: &mut Context, gl: &GlBackend, target: u32, pname: u32) -> (i32, i32) {
    let mut a = [-7];
    cpu.get_tex_level_parameteriv(target, 0, pname, &mut a);
    let mut b = -7;
    // SAFETY: the backend's context is current for its own calls; one value written.
    unsafe { gl.raw().GetTexLevelParameteriv(target, 0, pname, &mut b) };
    (a[0], b)
}

#[test]
fn compressed_commands_raise_the_drivers_errors_and_change_nothing() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    for c in images() {
        cpu.execute(&c);
        gl.execute(&c);
    }
    assert_eq!(cpu.get_error(), NO_ERROR);
    assert_eq!(gl.get_error(), NO_ERROR);
    let before = cpu.state().clone();
    let d = |n: usize| Some(vec![0u8; n]);
    let rows = [
        // CompressedTexImage: every format is INVALID_ENUM, generic or not, whatever else is
        // wrong; so is a target the command does not take.
        (
            img2(TEXTURE_2D, 0, COMPRESSED_RGB, 4, 8, d(8)),
            INVALID_ENUM,
        ),
        (
            img2(TEXTURE_2D, 0, COMPRESSED_RGBA, 4, 16, d(16)),
            INVALID_ENUM,
        ),
        (
            img2(TEXTURE_2D, 0, COMPRESSED_LUMINANCE, 4, 8, None),
            INVALID_ENUM,
        ),
        (img2(TEXTURE_2D, 0, RGBA, 4, 64, d(64)), INVALID_ENUM),
        (img2(TEXTURE_2D, 0, RGBA8, 4, 64, None), INVALID_ENUM),
        (
            img2(TEXTURE_2D, -1, COMPRESSED_RGBA, -4, -1, d(0)),
            INVALID_ENUM,
        ),
        (
            img2(TEXTURE_2D, 40, COMPRESSED_INTENSITY, 4, 8, d(8)),
            INVALID_ENUM,
        ),
        (
            img2(TEXTURE_CUBE_MAP_POSITIVE_X, 0, RGB, 4, 48, d(48)),
            INVALID_ENUM,
        ),
        (
            img2(PROXY_TEXTURE_2D, 0, COMPRESSED_RGB, 4, 8, None),
            INVALID_ENUM,
        ),
        (
            img2(PROXY_TEXTURE_CUBE_MAP, 0, COMPRESSED_RGB, 4, 8, None),
            INVALID_ENUM,
        ),
        (img2(TEXTURE_1D, 0, RGBA, 4, 64, None), INVALID_ENUM),
        (img2(TEXTURE_CUBE_MAP, 0, RGBA, 4, 64, None), INVALID_ENUM),
        (img2(0x1234, 0, RGBA, 4, 64, None), INVALID_ENUM),
        (img1(TEXTURE_1D, 0, COMPRESSED_RGB, 8, d(8)), INVALID_ENUM),
        (img1(PROXY_TEXTURE_1D, 0, ALPHA, 4, None), INVALID_ENUM),
        (img1(TEXTURE_2D, 0, RGBA, 16, None), INVALID_ENUM),
        (img3(TEXTURE_3D, COMPRESSED_RGBA, 64, d(64)), INVALID_ENUM),
        (img3(PROXY_TEXTURE_3D, RGBA, 256, None), INVALID_ENUM),
        (img3(TEXTURE_2D, RGBA, 256, None), INVALID_ENUM),
        // What the driver would take, fixedgl's errors: a format it offers, a GL 3.0 target,
        // data shorter than imageSize.
        (img2(TEXTURE_2D, 0, DXT1, 4, 8, d(8)), INVALID_ENUM),
        (img2(PROXY_TEXTURE_2D, 0, DXT1, 4, 8, None), INVALID_ENUM),
        (img3(TEXTURE_2D_ARRAY, DXT1, 8, d(8)), INVALID_ENUM),
        (img2(TEXTURE_2D, 0, RGBA, 4, 64, d(3)), INVALID_ENUM),
        // CompressedTexSubImage: on a 2D image a generic format is INVALID_ENUM, any other
        // INVALID_OPERATION; a 1D target INVALID_ENUM; TEXTURE_3D INVALID_OPERATION.
        (sub2(TEXTURE_2D, 0, RGBA, 64), INVALID_OPERATION),
        (sub2(TEXTURE_2D, 0, COMPRESSED_RGBA, 16), INVALID_ENUM),
        (
            sub2(TEXTURE_2D, 0, COMPRESSED_LUMINANCE_ALPHA, 16),
            INVALID_ENUM,
        ),
        (sub2(TEXTURE_2D, 5, RGBA, 64), INVALID_OPERATION),
        (sub2(TEXTURE_2D, -1, LUMINANCE8, 64), INVALID_OPERATION),
        (
            sub2(TEXTURE_CUBE_MAP_POSITIVE_Y, 0, RGB, 48),
            INVALID_OPERATION,
        ),
        (
            sub2(TEXTURE_CUBE_MAP_POSITIVE_X, 0, COMPRESSED_RGB, 8),
            INVALID_ENUM,
        ),
        (sub2(PROXY_TEXTURE_2D, 0, RGBA, 64), INVALID_ENUM),
        (sub2(TEXTURE_1D, 0, RGBA, 64), INVALID_ENUM),
        (sub2(TEXTURE_CUBE_MAP, 0, RGBA, 64), INVALID_ENUM),
        (sub1(TEXTURE_1D, RGBA, 16), INVALID_ENUM),
        (sub1(TEXTURE_1D, COMPRESSED_RGB, 8), INVALID_ENUM),
        (sub1(TEXTURE_2D, RGBA, 16), INVALID_ENUM),
        (sub3(TEXTURE_3D, RGBA, 256), INVALID_OPERATION),
        (sub3(TEXTURE_3D, COMPRESSED_RGBA, 64), INVALID_OPERATION),
        (sub3(TEXTURE_2D, RGBA, 256), INVALID_ENUM),
        (sub3(PROXY_TEXTURE_3D, RGBA, 256), INVALID_ENUM),
        // The driver's own: fixedgl's errors.
        (sub2(TEXTURE_2D, 0, DXT1, 8), INVALID_OPERATION),
        (sub3(TEXTURE_2D_ARRAY, RGBA, 256), INVALID_ENUM),
        (sub2(TEXTURE_2D, 0, COMPRESSED_SRGB, 8), INVALID_ENUM),
    ];
    run_rows(&mut cpu, &mut gl, &rows);
    assert!(
        cpu.state() == &before,
        "an erroneous call changed the state"
    );
    for (target, ifmt) in [
        (TEXTURE_1D, RGBA),
        (TEXTURE_2D, RGBA),
        (TEXTURE_3D, RGBA),
        (TEXTURE_CUBE_MAP_POSITIVE_X, RGB),
    ] {
        for pname in [TEXTURE_WIDTH, TEXTURE_INTERNAL_FORMAT, TEXTURE_COMPRESSED] {
            let (a, b) = level_param(&mut cpu, &gl, target, pname);
            assert_eq!(a, b, "{target:#x} {pname:#x} (cpu, driver)");
        }
        let (a, _) = level_param(&mut cpu, &gl, target, TEXTURE_INTERNAL_FORMAT);
        assert_eq!(a, ifmt as i32, "{target:#x}: the image stays");
    }
    // Between Begin and End: INVALID_OPERATION first.
    for call in [
        img2(TEXTURE_2D, 0, DXT1, 4, 8, d(8)),
        img2(TEXTURE_2D, 0, RGBA, 4, 64, None),
        sub2(TEXTURE_2D, 0, RGBA, 64),
        sub1(TEXTURE_1D, RGBA, 16),
        Call::SampleCoverage(0.5, true),
    ] {
        for c in [Call::Begin(POINTS), call.clone(), Call::End] {
            cpu.execute(&c);
            gl.execute(&c);
        }
        assert_eq!(cpu.get_error(), INVALID_OPERATION, "CPU: {call:?}");
        assert_eq!(gl.get_error(), INVALID_OPERATION, "GL: {call:?}");
    }
}

#[test]
fn display_lists_compile_compressed_calls_and_run_proxies_at_once() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    for c in images() {
        cpu.execute(&c);
        gl.execute(&c);
    }
    let body = [
        // Executed now, not compiled (Mesa's dlist.c; GL 2.1 §5.4 for TexImage): INVALID_ENUM
        // at NewList time. The cube-map proxy is compiled.
        img2(PROXY_TEXTURE_2D, 0, COMPRESSED_RGB, 4, 8, None),
        img2(PROXY_TEXTURE_CUBE_MAP, 0, COMPRESSED_RGB, 4, 8, None),
        // A format the driver would take: the backend expands the list to raise fixedgl's
        // error when it runs.
        img2(TEXTURE_2D, 0, DXT1, 4, 8, Some(vec![7; 8])),
        sub2(TEXTURE_2D, 0, RGBA, 64),
        img1(PROXY_TEXTURE_1D, 0, RGBA, 16, None),
        img3(PROXY_TEXTURE_3D, RGBA, 256, None),
        Call::SampleCoverage(0.25, true),
    ];
    for c in [Call::NewList(1, COMPILE)].iter().chain(&body) {
        cpu.execute(c);
        gl.execute(c);
    }
    cpu.execute(&Call::EndList);
    gl.execute(&Call::EndList);
    assert_eq!(cpu.get_error(), INVALID_ENUM, "CPU: the proxies ran");
    assert_eq!(gl.get_error(), INVALID_ENUM, "GL: the proxies ran");
    let held = cpu.list_calls(1).expect("list 1").to_vec();
    assert_eq!(
        held,
        vec![
            body[1].clone(),
            body[2].clone(),
            body[3].clone(),
            body[6].clone()
        ],
        "the list holds the compiled calls with their data"
    );
    // COMPILE changed nothing.
    let mut v = [0.0f32];
    cpu.get_floatv(SAMPLE_COVERAGE_VALUE, &mut v);
    assert_eq!(v[0], 1.0);
    cpu.execute(&Call::CallList(1));
    gl.execute(&Call::CallList(1));
    assert_eq!(cpu.get_error(), INVALID_ENUM, "CPU: the list's first error");
    assert_eq!(gl.get_error(), INVALID_ENUM, "GL: the list's first error");
    for pname in [TEXTURE_INTERNAL_FORMAT, TEXTURE_COMPRESSED, TEXTURE_WIDTH] {
        let (a, b) = level_param(&mut cpu, &gl, TEXTURE_2D, pname);
        assert_eq!(a, b, "{pname:#x} after the list (cpu, driver)");
    }
    let (a, _) = level_param(&mut cpu, &gl, TEXTURE_2D, TEXTURE_INTERNAL_FORMAT);
    assert_eq!(a, RGBA as i32, "the DXT1 image was refused");
    assert_eq!(sample_coverage(&mut cpu, &gl), ((0.25, true), (0.25, true)));
}

/// (SAMPLE_COVERAGE_VALUE, SAMPLE_COVERAGE_INVERT) on both: (cpu, driver).
fn sample_coverage(cpu: &mut Context, gl: &GlBackend) -> ((f32, bool), (f32, bool)) {
    let (mut v, mut i) = ([-1.0f32], [false]);
    cpu.get_floatv(gl::SAMPLE_COVERAGE_VALUE, &mut v);
    cpu.get_booleanv(gl::SAMPLE_COVERAGE_INVERT, &mut i);
    let (mut gv, mut gi) = (-1.0f32, 7u8);
    // SAFETY: the backend's context is current for its own calls; one value each.
    unsafe {
        gl.raw().GetFloatv(gl::SAMPLE_COVERAGE_VALUE, &mut gv);
        gl.raw().GetBooleanv(gl::SAMPLE_COVERAGE_INVERT, &mut gi);
    }
    ((v[0], i[0]), (gv, gi != 0))
}

#[test]
fn get_compressed_tex_image_errors_agree() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    for c in images() {
        cpu.execute(&c);
        gl.execute(&c);
    }
    let rows = [
        (TEXTURE_2D, 0, INVALID_OPERATION),
        (TEXTURE_1D, 0, INVALID_OPERATION),
        (TEXTURE_3D, 0, INVALID_OPERATION),
        (TEXTURE_CUBE_MAP_POSITIVE_X, 0, INVALID_OPERATION),
        (TEXTURE_2D, -1, INVALID_VALUE),
        (TEXTURE_2D, 40, INVALID_VALUE),
        (PROXY_TEXTURE_2D, 0, INVALID_ENUM),
        (TEXTURE_CUBE_MAP, 0, INVALID_ENUM),
        (0x1234, 0, INVALID_ENUM),
        // A level without an image: Mesa's size check (a 1D image 1 high, a 2D one 1 deep).
        (TEXTURE_2D, 3, INVALID_VALUE),
        (TEXTURE_1D, 2, INVALID_VALUE),
        (TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, NO_ERROR),
        (TEXTURE_3D, 1, NO_ERROR),
    ];
    for (target, level, expected) in rows {
        let mut out = [0xA5u8; 4096];
        cpu.get_compressed_tex_image(target, level, &mut out);
        let mut drv = [0xA5u8; 4096];
        // SAFETY: the context is current; no image is compressed, so the driver writes nothing,
        // and 4096 bytes hold any 4x4x4 image it could.
        unsafe {
            gl.raw()
                .GetCompressedTexImage(target, level, drv.as_mut_ptr().cast())
        };
        assert_eq!(cpu.get_error(), expected, "CPU {target:#x} level {level}");
        assert_eq!(gl.get_error(), expected, "GL {target:#x} level {level}");
        assert!(out.iter().all(|&b| b == 0xA5), "nothing written");
    }
    cpu.execute(&Call::Begin(POINTS));
    cpu.get_compressed_tex_image(TEXTURE_2D, 0, &mut []);
    cpu.execute(&Call::End);
    assert_eq!(cpu.get_error(), INVALID_OPERATION);
}

#[test]
fn generic_compressed_formats_are_stored_uncompressed_as_mesa_answers() {
    use fixedgl::gl::*;
    use std::io::Write as _;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    let mut driver = Vec::new();
    for (generic, base) in [
        (COMPRESSED_ALPHA, ALPHA),
        (COMPRESSED_LUMINANCE, LUMINANCE),
        (COMPRESSED_LUMINANCE_ALPHA, LUMINANCE_ALPHA),
        (COMPRESSED_INTENSITY, INTENSITY),
        (COMPRESSED_RGB, RGB),
        (COMPRESSED_RGBA, RGBA),
    ] {
        for target in [TEXTURE_2D, PROXY_TEXTURE_2D] {
            let c = Call::TexImage2D(Box::new((
                target,
                0,
                generic as i32,
                4,
                4,
                0,
                RGBA,
                UNSIGNED_BYTE,
                Some(vec![90; 64]),
            )));
            cpu.execute(&c);
            gl.execute(&c);
            assert_eq!(cpu.get_error(), NO_ERROR);
            assert_eq!(gl.get_error(), NO_ERROR);
            let what = format!("{generic:#x} on {target:#x}");
            // fixedgl: stored uncompressed, answering its base format (GL 1.3 §3.8.1).
            let (ifmt, g_ifmt) = level_param(&mut cpu, &gl, target, TEXTURE_INTERNAL_FORMAT);
            let (comp, g_comp) = level_param(&mut cpu, &gl, target, TEXTURE_COMPRESSED);
            assert_eq!((ifmt, comp), (base as i32, 0), "{what}");
            let (_, g_size) = level_param(&mut cpu, &gl, target, TEXTURE_COMPRESSED_IMAGE_SIZE);
            let g_err = gl.get_error();
            assert_eq!(cpu.get_error(), INVALID_OPERATION, "{what}: image size");
            // The driver answers the same where it stores the image uncompressed; where it
            // has a format for it (S3TC, LATC) it compresses and says so (Mesa answers the
            // specific format it chose).
            if g_comp == 0 {
                assert_eq!((g_ifmt, g_err), (ifmt, INVALID_OPERATION), "driver {what}");
            } else {
                assert_ne!(g_ifmt, generic as i32, "driver {what}");
                let proxy = target == PROXY_TEXTURE_2D;
                assert_eq!(
                    g_err != NO_ERROR,
                    proxy,
                    "driver {what}: image size {g_size}"
                );
            }
            driver.push(format!("{what}: {g_ifmt:#x} compressed {g_comp}"));
        }
    }
    let _ = writeln!(std::io::stderr(), "driver: {driver:#?}");
    // A level without an image is uncompressed too: INVALID_OPERATION, nothing written.
    let mut a = [-7];
    cpu.get_tex_level_parameteriv(TEXTURE_2D, 5, TEXTURE_COMPRESSED_IMAGE_SIZE, &mut a);
    let mut b = -7;
    // SAFETY: as in `level_param`.
    unsafe {
        gl.raw()
            .GetTexLevelParameteriv(TEXTURE_2D, 5, TEXTURE_COMPRESSED_IMAGE_SIZE, &mut b)
    };
    assert_eq!((a[0], b), (-7, -7));
    assert_eq!(
        (cpu.get_error(), gl.get_error()),
        (INVALID_OPERATION, INVALID_OPERATION)
    );
    // Queries a context with no compressed format answers.
    let mut n = [-1];
    cpu.get_integerv(NUM_COMPRESSED_TEXTURE_FORMATS, &mut n);
    assert_eq!(n[0], 0);
    assert_eq!(cpu.get_count(COMPRESSED_TEXTURE_FORMATS), Some(0));
    for pname in [SAMPLE_BUFFERS, SAMPLES] {
        let mut v = [-1];
        cpu.get_integerv(pname, &mut v);
        let mut w = -1;
        // SAFETY: one value.
        unsafe { gl.raw().GetIntegerv(pname, &mut w) };
        assert_eq!((v[0], w), (0, 0), "{pname:#x}: single-sampled");
    }
}

#[test]
fn sample_coverage_is_state_that_agrees_with_the_driver() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    assert_eq!(sample_coverage(&mut cpu, &gl), ((1.0, false), (1.0, false)));
    let run = |cpu: &mut Context, gl: &mut GlBackend, c: Call| {
        cpu.execute(&c);
        gl.execute(&c);
        assert_eq!(cpu.get_error(), NO_ERROR, "{c:?}");
        assert_eq!(gl.get_error(), NO_ERROR, "{c:?}");
    };
    for (value, invert, want) in [
        (0.25, true, 0.25),
        (1.5, false, 1.0),
        (-2.0, true, 0.0),
        (f32::NAN, false, 0.0),
        (0.6, true, 0.6),
    ] {
        run(&mut cpu, &mut gl, Call::SampleCoverage(value, invert));
        let ((v, i), (gv, gi)) = sample_coverage(&mut cpu, &gl);
        assert_eq!((v, i), (want, invert), "{value}");
        assert_eq!((gv, gi), (want, invert), "driver {value}");
    }
    // GetIntegerv rounds the float; GetBooleanv says nonzero.
    let (mut n, mut b) = ([-1], [false]);
    cpu.get_integerv(SAMPLE_COVERAGE_VALUE, &mut n);
    cpu.get_booleanv(SAMPLE_COVERAGE_VALUE, &mut b);
    let mut gn = -1;
    // SAFETY: one value.
    unsafe { gl.raw().GetIntegerv(SAMPLE_COVERAGE_VALUE, &mut gn) };
    assert_eq!((n[0], b[0]), (gn, true));
    // The multisample group (table 6.15) saves and restores both.
    run(&mut cpu, &mut gl, Call::PushAttrib(MULTISAMPLE_BIT));
    run(&mut cpu, &mut gl, Call::SampleCoverage(0.125, false));
    run(&mut cpu, &mut gl, Call::PopAttrib);
    assert_eq!(sample_coverage(&mut cpu, &gl), ((0.6, true), (0.6, true)));
    // Another group does not.
    run(&mut cpu, &mut gl, Call::PushAttrib(COLOR_BUFFER_BIT));
    run(&mut cpu, &mut gl, Call::SampleCoverage(0.125, false));
    run(&mut cpu, &mut gl, Call::PopAttrib);
    assert_eq!(
        sample_coverage(&mut cpu, &gl),
        ((0.125, false), (0.125, false))
    );
}

#[test]
fn sample_coverage_does_not_change_single_sampled_rendering() {
    use fixedgl::gl::*;
    let Some((bad, first)) = cpu_vs_gl(16, 1, |c| {
        c.clear_color(0.1, 0.2, 0.3, 1.0);
        c.clear(COLOR_BUFFER_BIT);
        c.enable(SAMPLE_COVERAGE);
        c.enable(SAMPLE_ALPHA_TO_COVERAGE);
        c.sample_coverage(0.0, false);
        c.color3f(0.9, 0.5, 0.1);
        c.begin(TRIANGLES);
        c.vertex2f(-1.0, -1.0);
        c.vertex2f(1.0, -1.0);
        c.vertex2f(0.0, 1.0);
        c.end();
        c.sample_coverage(0.5, true);
        c.color4f(0.1, 0.9, 0.1, 0.2);
        c.rectf(-0.5, -0.5, 0.5, 0.5);
    }) else {
        return;
    };
    assert_eq!(bad, 0, "{first}");
    // The CPU image is the one without the coverage calls.
    let draw = |c: &mut Context, coverage: bool| {
        c.clear_color(0.1, 0.2, 0.3, 1.0);
        c.clear(COLOR_BUFFER_BIT);
        if coverage {
            c.enable(SAMPLE_COVERAGE);
            c.sample_coverage(0.0, false);
        }
        c.color3f(0.9, 0.5, 0.1);
        c.rectf(-0.5, -0.5, 0.5, 0.5);
    };
    let mut a = Context::new(16, 16).unwrap();
    let mut b = Context::new(16, 16).unwrap();
    draw(&mut a, true);
    draw(&mut b, false);
    assert_eq!(a.to_image(), b.to_image());
}
