//! The texture entry points against the real driver (Mesa llvmpipe through EGL): the same error
//! sequence as the CPU front end (including short client data, which never reaches the driver),
//! and the texture scenes within their tolerance. Skipped, with a note on stderr, when no GL
//! backend can start (unless FIXEDGL_REQUIRE_GL is set).
#![cfg(feature = "gl")]

use std::io::Write as _;

use crate::common::cpu_vs_gl;
use fixedgl::compare::compare;
use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, scenes, Call, Context};
use image::RgbaImage;

fn backend(width: u32, height: u32) -> Option<GlBackend> {
    crate::common::test_backend(width, height)
}

#[test]
fn texture_errors_match_the_driver() {
    let Some(mut gl) = backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let img = |n: usize| Some(vec![9u8; n]);
    let rows: &[(Call, u32)] = &[
        (Call::GenTextures(2), gl::NO_ERROR),
        (Call::BindTexture(gl::TEXTURE_2D, 2), gl::NO_ERROR),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::RGBA as i32,
                2,
                2,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                img(16),
            ))),
            gl::NO_ERROR,
        ),
        // RGB rows of 6 bytes padded to 8 by UNPACK_ALIGNMENT 4: 14 bytes needed.
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::RGB as i32,
                2,
                2,
                0,
                gl::RGB,
                gl::UNSIGNED_BYTE,
                img(13),
            ))),
            gl::INVALID_OPERATION,
        ),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::RGB as i32,
                2,
                2,
                0,
                gl::RGB,
                gl::UNSIGNED_BYTE,
                img(14),
            ))),
            gl::NO_ERROR,
        ),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                -1,
                gl::RGBA as i32,
                1,
                1,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                img(4),
            ))),
            gl::INVALID_VALUE,
        ),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::RGBA as i32,
                -1,
                1,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                None,
            ))),
            gl::INVALID_VALUE,
        ),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::RGBA as i32,
                1,
                1,
                0,
                gl::DEPTH_COMPONENT,
                gl::FLOAT,
                img(4),
            ))),
            gl::INVALID_OPERATION,
        ),
        (
            Call::TexSubImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                0,
                0,
                2,
                2,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                vec![0; 15],
            ))),
            gl::INVALID_OPERATION,
        ),
        (
            Call::TexSubImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                1,
                1,
                2,
                2,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                vec![0; 16],
            ))),
            gl::INVALID_VALUE,
        ),
        (
            Call::TexSubImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                0,
                0,
                1,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                vec![0; 4],
            ))),
            gl::NO_ERROR,
        ),
        (
            Call::TexSubImage2D(Box::new((
                gl::TEXTURE_2D,
                5,
                0,
                0,
                1,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                vec![0; 4],
            ))),
            gl::INVALID_OPERATION,
        ),
        (
            Call::TexParameteri(
                gl::TEXTURE_2D,
                gl::TEXTURE_MAG_FILTER,
                gl::LINEAR_MIPMAP_LINEAR as i32,
            ),
            gl::INVALID_ENUM,
        ),
        (
            Call::TexParameteri(
                gl::TEXTURE_2D,
                gl::TEXTURE_WRAP_S,
                gl::MIRRORED_REPEAT as i32,
            ),
            gl::NO_ERROR,
        ),
        (
            Call::TexParameteri(gl::TEXTURE_2D, gl::TEXTURE_BASE_LEVEL, -1),
            gl::INVALID_VALUE,
        ),
        (
            Call::TexParameterfv(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, vec![1.0; 3]),
            gl::INVALID_VALUE,
        ),
        (
            Call::TexEnvi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::LINEAR as i32),
            gl::INVALID_ENUM,
        ),
        (
            Call::TexEnvi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::ADD as i32),
            gl::NO_ERROR,
        ),
        (
            Call::TexGeni(gl::R, gl::TEXTURE_GEN_MODE, gl::SPHERE_MAP as i32),
            gl::INVALID_ENUM,
        ),
        (
            Call::TexGeni(gl::Q, gl::TEXTURE_GEN_MODE, gl::EYE_LINEAR as i32),
            gl::NO_ERROR,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA, 0, 0, 4, 4, 0),
            gl::NO_ERROR,
        ),
        (
            Call::CopyTexSubImage2D(gl::TEXTURE_2D, 0, 3, 3, 0, 0, 2, 2),
            gl::INVALID_VALUE,
        ),
        // CopyTexImage refuses the GL 1.0 counts 1..4 and unknown internal formats with
        // INVALID_ENUM (piglit copyteximage.c:638), after an unknown target.
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, 3, 0, 0, 4, 4, 0),
            gl::INVALID_ENUM,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 0),
            gl::INVALID_ENUM,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, -1, 4, 0, 0, 4, 4, 0),
            gl::INVALID_VALUE,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, 4, 0, 0, -4, 4, 1),
            gl::INVALID_ENUM,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, 0x1234, 0, 0, -4, 4, 0),
            gl::INVALID_ENUM,
        ),
        (
            Call::CopyTexImage2D(gl::TEXTURE_1D, 0, 4, 0, 0, 4, 4, 0),
            gl::INVALID_ENUM,
        ),
        // The generic compressed formats (GL 1.3) are taken.
        (
            Call::CopyTexImage2D(gl::TEXTURE_2D, 0, gl::COMPRESSED_RGBA, 0, 0, 4, 4, 0),
            gl::NO_ERROR,
        ),
        (
            Call::TexImage2D(Box::new((
                gl::TEXTURE_2D,
                0,
                gl::COMPRESSED_LUMINANCE as i32,
                2,
                2,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                img(16),
            ))),
            gl::NO_ERROR,
        ),
        (Call::DeleteTextures(1, vec![2]), gl::NO_ERROR),
        (Call::DeleteTextures(-1, vec![]), gl::INVALID_VALUE),
    ];
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), *expected, "GL after row {i}: {call:?}");
    }
}

/// Scene `name` at its own size (the size its tolerance is stated for): the scene, its CPU image
/// and the driver's image of the same recorded calls; `None` when no EGL device exists.
fn both_images(name: &str) -> Option<(&'static scenes::Scene, RgbaImage, RgbaImage)> {
    let Some(scene) = scenes::find(name) else {
        panic!("{name} is registered")
    };
    let (w, h) = scene.default_size;
    let mut gl = backend(w, h)?;
    let Ok((mut ctx, calls)) = scene.record(w, h) else {
        panic!("{name} records")
    };
    gl.replay(&calls);
    Some((scene, ctx.to_image(), gl.read_image()))
}

#[test]
fn texture_scenes_hold_their_tolerance() {
    for name in ["textured-cube", "projective-texture", "shadow-map"] {
        let Some((scene, cpu, drv)) = both_images(name) else {
            return;
        };
        let cmp = compare(&cpu, &drv, scene.tolerance.channel);
        assert!(cmp.passes(scene.tolerance.max_percent), "{name}: {cmp:?}");
    }
}

/// textured-cube's whole-image tolerance (0.75%) is set by its two NEAREST_MIPMAP_* panels, where
/// fixedgl keeps GL 2.1's switch point c = 0.5 and llvmpipe uses 0 (docs/conformance.md,
/// "textured-cube and the switch point c"). Each panel is held to its own bound here, so the other
/// four cannot drift behind that allowance. Bounds: percent of a 320x320 panel's pixels with a
/// channel off by more than 2/255; measured 22 Nov 2026: 0.009, 0.220, 1.979, 0, 1.979, 0.
#[test]
fn textured_cube_panels_hold_their_own_bounds() {
    let Some((scene, cpu, drv)) = both_images("textured-cube") else {
        return;
    };
    let (w, h) = scene.default_size;
    // Panels in reading order (top-down image rows), one MIN filter each.
    let bounds = [
        ("NEAREST", 0.05),
        // Unmipmapped bilinear on the far floor: weights' rounding, at most 3/255.
        ("LINEAR", 0.3),
        ("NEAREST_MIPMAP_NEAREST", 2.2),
        ("LINEAR_MIPMAP_NEAREST", 0.05),
        ("NEAREST_MIPMAP_LINEAR", 2.2),
        ("LINEAR_MIPMAP_LINEAR", 0.05),
    ];
    let (pw, ph) = (w / 3, h / 2);
    for (k, (filter, max_percent)) in bounds.into_iter().enumerate() {
        let (x, y) = ((k as u32 % 3) * pw, (k as u32 / 3) * ph);
        let crop = |img: &RgbaImage| image::imageops::crop_imm(img, x, y, pw, ph).to_image();
        let cmp = compare(&crop(&cpu), &crop(&drv), scene.tolerance.channel);
        assert!(cmp.passes(max_percent), "panel {filter}: {cmp:?}");
    }
}

#[test]
fn two_units_match_the_driver() {
    let Some(mut gl) = backend(16, 16) else {
        return;
    };
    let Ok(mut cpu) = Context::new(16, 16) else {
        panic!("CPU context")
    };
    cpu.start_recording();
    {
        use fixedgl::gl::*;
        let c = &mut cpu;
        c.pixel_storei(UNPACK_ALIGNMENT, 1);
        let board = fixedgl::checkerboard(8, 2, [255, 200, 0, 255], [0, 80, 255, 255]);
        let lum: Vec<u8> = (0..16u8).map(|i| i * 16).collect();
        for (unit, w, fmt, data, env) in [
            (TEXTURE0, 8, RGBA, &board[..], MODULATE),
            (TEXTURE1, 4, LUMINANCE, &lum[..], BLEND),
        ] {
            c.active_texture(unit);
            c.bind_texture(TEXTURE_2D, unit - TEXTURE0 + 1);
            c.tex_image_2d(
                TEXTURE_2D,
                0,
                fmt as i32,
                w,
                w,
                0,
                fmt,
                UNSIGNED_BYTE,
                Some(data),
            );
            c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
            c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
            c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, env as i32);
            c.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[0.2, 0.9, 0.4, 1.0]);
            c.enable(TEXTURE_2D);
        }
        c.color3f(0.9, 0.8, 0.7);
        c.begin(QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            c.multi_tex_coord2f(TEXTURE0, (x + 1.0) / 2.0, (y + 1.0) / 2.0);
            c.multi_tex_coord2f(TEXTURE1, (1.0 - y) / 2.0, (x + 1.0) / 2.0);
            c.vertex2f(x, y);
        }
        c.end();
    }
    let calls = cpu.stop_recording();
    gl.replay(&calls);
    let cmp = compare(&cpu.to_image(), &gl.read_image(), 1);
    let (ci, gi) = (cpu.to_image(), gl.read_image());
    assert_eq!(
        cmp.differing_pixels,
        0,
        "cpu {:?} gl {:?} cpu {:?} gl {:?}",
        ci.get_pixel(15, 8),
        gi.get_pixel(15, 8),
        ci.get_pixel(15, 0),
        gi.get_pixel(15, 0)
    );
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

#[test]
fn combine_matches_the_driver() {
    use fixedgl::gl::*;
    /// COMBINE_RGB, COMBINE_ALPHA, sources, operands, RGB_SCALE, ALPHA_SCALE.
    type Run = (u32, u32, [u32; 3], [u32; 3], f32, f32);
    let runs: &[Run] = &[
        (
            MODULATE,
            MODULATE,
            [TEXTURE, PREVIOUS, CONSTANT],
            [SRC_COLOR, SRC_COLOR, SRC_ALPHA],
            1.0,
            1.0,
        ),
        (
            ADD_SIGNED,
            ADD,
            [TEXTURE, PRIMARY_COLOR, CONSTANT],
            [SRC_COLOR, ONE_MINUS_SRC_COLOR, SRC_ALPHA],
            2.0,
            1.0,
        ),
        (
            INTERPOLATE,
            SUBTRACT,
            [TEXTURE, CONSTANT, PREVIOUS],
            [SRC_COLOR, SRC_COLOR, SRC_ALPHA],
            1.0,
            2.0,
        ),
        (
            SUBTRACT,
            REPLACE,
            [CONSTANT, TEXTURE, PREVIOUS],
            [SRC_COLOR, ONE_MINUS_SRC_ALPHA, SRC_ALPHA],
            4.0,
            1.0,
        ),
        (
            DOT3_RGB,
            INTERPOLATE,
            [TEXTURE, CONSTANT, PREVIOUS],
            [SRC_COLOR, SRC_COLOR, SRC_ALPHA],
            1.0,
            1.0,
        ),
        (
            DOT3_RGBA,
            MODULATE,
            [TEXTURE, CONSTANT, PREVIOUS],
            [SRC_COLOR, SRC_COLOR, SRC_ALPHA],
            1.0,
            2.0,
        ),
    ];
    for (i, &(rgb, alpha, src, op, rs, as_)) in runs.iter().enumerate() {
        let Some(mut gl) = backend(8, 8) else {
            return;
        };
        let Ok(mut cpu) = Context::new(8, 8) else {
            panic!("CPU context")
        };
        cpu.start_recording();
        let c = &mut cpu;
        let tex: Vec<u8> = (0..16u8)
            .flat_map(|k| [k * 16, 255 - k * 12, 40 + k * 8, 60 + k * 10])
            .collect();
        c.tex_image_2d(
            TEXTURE_2D,
            0,
            RGBA as i32,
            4,
            4,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&tex),
        );
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
        c.enable(TEXTURE_2D);
        c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32);
        c.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[0.3, 0.6, 0.9, 0.4]);
        c.tex_envi(TEXTURE_ENV, COMBINE_RGB, rgb as i32);
        c.tex_envi(TEXTURE_ENV, COMBINE_ALPHA, alpha as i32);
        for k in 0..3 {
            c.tex_envi(TEXTURE_ENV, SRC0_RGB + k as u32, src[k] as i32);
            c.tex_envi(TEXTURE_ENV, SRC0_ALPHA + k as u32, src[k] as i32);
            c.tex_envi(TEXTURE_ENV, OPERAND0_RGB + k as u32, op[k] as i32);
        }
        c.tex_envf(TEXTURE_ENV, RGB_SCALE, rs);
        c.tex_envf(TEXTURE_ENV, ALPHA_SCALE, as_);
        c.color4f(0.8, 0.5, 0.2, 0.7);
        c.begin(QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            c.tex_coord2f((x + 1.0) / 2.0, (y + 1.0) / 2.0);
            c.vertex2f(x, y);
        }
        c.end();
        let calls = cpu.stop_recording();
        assert_eq!(cpu.get_error(), gl::NO_ERROR, "run {i}");
        gl.replay(&calls);
        assert_eq!(gl.get_error(), gl::NO_ERROR, "run {i}");
        let (ci, gi) = (cpu.to_image(), gl.read_image());
        let cmp = compare(&ci, &gi, 1);
        assert_eq!(
            cmp.differing_pixels,
            0,
            "run {i}: cpu {:?} gl {:?}",
            ci.get_pixel(1, 1),
            gi.get_pixel(1, 1)
        );
    }
}

#[test]
fn wrap_modes_and_filters_match_the_driver() {
    use fixedgl::gl::*;
    for wrap in [
        REPEAT,
        CLAMP,
        CLAMP_TO_EDGE,
        CLAMP_TO_BORDER,
        MIRRORED_REPEAT,
    ] {
        for filter in [NEAREST, LINEAR] {
            let Some((n, first)) = cpu_vs_gl(64, 1, |c| {
                let tex: Vec<u8> = (0..16u8)
                    .flat_map(|k| [k * 16, 255 - k * 16, (k % 3) * 100, 255])
                    .collect();
                c.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    4,
                    4,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&tex),
                );
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, filter as i32);
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, filter as i32);
                c.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, wrap as i32);
                c.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, wrap as i32);
                c.tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &[0.2, 0.4, 0.9, 1.0]);
                c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
                c.enable(TEXTURE_2D);
                c.begin(QUADS);
                for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    c.tex_coord2f(x * 1.7 + 0.3, y * 1.3 + 0.4);
                    c.vertex2f(x, y);
                }
                c.end();
            }) else {
                return;
            };
            assert_eq!(n, 0, "wrap {wrap:#x} filter {filter:#x}: first {first}");
        }
    }
}

#[test]
fn mipmap_filters_match_the_driver() {
    use fixedgl::gl::*;
    for min in [
        NEAREST_MIPMAP_NEAREST,
        LINEAR_MIPMAP_NEAREST,
        NEAREST_MIPMAP_LINEAR,
        LINEAR_MIPMAP_LINEAR,
    ] {
        let Some((n, first)) = cpu_vs_gl(128, 2, |c| {
            c.tex_parameteri(TEXTURE_2D, GENERATE_MIPMAP, 1);
            let board = fixedgl::checkerboard(64, 8, [250, 250, 250, 255], [10, 60, 200, 255]);
            c.tex_image_2d(
                TEXTURE_2D,
                0,
                RGBA as i32,
                64,
                64,
                0,
                RGBA,
                UNSIGNED_BYTE,
                Some(&board),
            );
            c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, min as i32);
            // MAG NEAREST keeps the switch point c at 0 (§3.8.9), where llvmpipe has it always;
            // with MAG LINEAR and a NEAREST_MIPMAP_* filter the spec's c = 0.5 differs.
            c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
            c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
            c.enable(TEXTURE_2D);
            // A floor receding in perspective: λ from about -1 to 5 across the picture.
            c.matrix_mode(PROJECTION);
            c.frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 50.0);
            c.matrix_mode(MODELVIEW);
            c.begin(QUADS);
            for (s, t, x, z) in [
                (0.0, 0.0, -4.0, -0.2),
                (8.0, 0.0, 4.0, -0.2),
                (8.0, 24.0, 4.0, -40.0),
                (0.0, 24.0, -4.0, -40.0),
            ] {
                c.tex_coord2f(s, t);
                c.vertex3f(x, -1.0, z);
            }
            c.end();
        }) else {
            return;
        };
        // Measured, not exact: λ differs from llvmpipe's in the last bits, which moves mip-blended
        // texels on checker edges by a few levels.
        assert!(n <= 128 * 128 / 200, "min {min:#x}: {n} px, first {first}");
        let _ = writeln!(
            std::io::stderr(),
            "min {min:#x}: {n} of {} px off by more than 2",
            128 * 128
        );
    }
}

/// TEXTURE_LOD_BIAS of the texture object (GL 1.4, table 6.16) with and without the unit's
/// TEXTURE_FILTER_CONTROL bias: λ' = log2 ρ + clamp(object + unit, ±MAX_TEXTURE_LOD_BIAS)
/// (§3.8.8 eq. 3.18), on the receding mipmapped floor of `mipmap_filters_match_the_driver`,
/// held to the texture scenes' tolerance (textured-cube's, as registered: channel 2, 0.75% of
/// pixels; NEAREST_MIPMAP_NEAREST with bias -1 measured 84 px of 16384 = 0.51%, level switches
/// on checker edges as in `mipmap_filters_match_the_driver`; a bias ignored or misapplied costs
/// thousands).
#[test]
fn object_lod_bias_matches_the_driver() {
    use fixedgl::gl::*;
    let Some(scene) = fixedgl::scenes::find("textured-cube") else {
        panic!("textured-cube is registered")
    };
    let (tol, max_percent) = (scene.tolerance.channel, scene.tolerance.max_percent);
    for min in [NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_LINEAR] {
        // (object bias, unit bias); the last: the driver clamps the object's bias before the sum
        // (16 - 15 = 1; the spec's 20 - 15 = 5 differs in 5096 px).
        for (object, unit) in [
            (1.5, 0.0),
            (-1.0, 0.0),
            (1.5, -0.5),
            (-1.0, 2.0),
            (20.0, -15.0),
        ] {
            let Some((n, first)) = cpu_vs_gl(128, tol, |c| {
                c.tex_parameteri(TEXTURE_2D, GENERATE_MIPMAP, 1);
                let board = fixedgl::checkerboard(64, 8, [250, 250, 250, 255], [10, 60, 200, 255]);
                c.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    64,
                    64,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&board),
                );
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, min as i32);
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
                c.tex_parameterf(TEXTURE_2D, TEXTURE_LOD_BIAS, object);
                c.tex_envf(TEXTURE_FILTER_CONTROL, TEXTURE_LOD_BIAS, unit);
                c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
                c.enable(TEXTURE_2D);
                c.matrix_mode(PROJECTION);
                c.frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 50.0);
                c.matrix_mode(MODELVIEW);
                c.begin(QUADS);
                for (s, t, x, z) in [
                    (0.0, 0.0, -4.0, -0.2),
                    (8.0, 0.0, 4.0, -0.2),
                    (8.0, 24.0, 4.0, -40.0),
                    (0.0, 24.0, -4.0, -40.0),
                ] {
                    c.tex_coord2f(s, t);
                    c.vertex3f(x, -1.0, z);
                }
                c.end();
            }) else {
                return;
            };
            let percent = 100.0 * n as f64 / (128.0 * 128.0);
            assert!(
                percent <= max_percent,
                "min {min:#x} bias {object} + {unit}: {n} px, first {first}"
            );
            let _ = writeln!(
                std::io::stderr(),
                "min {min:#x} bias {object} + {unit}: {n} of {} px off by more than {tol}",
                128 * 128
            );
        }
    }
}

/// Enabling TEXTURE_1D, _3D or _CUBE_MAP beside TEXTURE_2D (their textures have no images, so
/// they are incomplete) draws what the driver draws: the first enabled target in the order
/// CUBE_MAP > 3D > 2D > 1D whose texture is complete, here the 2D one; alone, nothing.
#[test]
fn enabled_texture_targets_draw_what_the_driver_draws() {
    use fixedgl::gl::*;
    let combos: &[&[u32]] = &[
        &[TEXTURE_2D],
        &[TEXTURE_1D],
        &[TEXTURE_3D],
        &[TEXTURE_CUBE_MAP],
        &[TEXTURE_2D, TEXTURE_1D],
        &[TEXTURE_2D, TEXTURE_3D],
        &[TEXTURE_2D, TEXTURE_CUBE_MAP],
        &[TEXTURE_1D, TEXTURE_3D, TEXTURE_CUBE_MAP],
        &[TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP],
    ];
    for &enables in combos {
        // Unit 0 and unit 1, each with its own 2D texture and objects bound to the other targets.
        let Some((n, first)) = cpu_vs_gl(16, 1, |c| {
            let board = fixedgl::checkerboard(4, 2, [255, 40, 0, 255], [0, 200, 90, 255]);
            for unit in [TEXTURE0, TEXTURE1] {
                c.active_texture(unit);
                let base = 10 * (unit - TEXTURE0 + 1);
                for (k, target) in [TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP]
                    .into_iter()
                    .enumerate()
                {
                    c.bind_texture(target, base + k as u32);
                }
                c.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    4,
                    4,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&board),
                );
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
                c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
                c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
                for &e in enables {
                    c.enable(e);
                }
            }
            c.color3f(0.9, 0.7, 0.5);
            c.begin(QUADS);
            for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                c.multi_tex_coord2f(TEXTURE0, (x + 1.0) / 2.0, (y + 1.0) / 2.0);
                c.multi_tex_coord2f(TEXTURE1, (1.0 - y) / 2.0, (x + 1.0) / 2.0);
                c.vertex2f(x, y);
            }
            c.end();
        }) else {
            return;
        };
        assert_eq!(n, 0, "enabled {enables:x?}: first {first}");
    }
}
