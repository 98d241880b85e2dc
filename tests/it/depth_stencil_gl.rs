//! GL_EXT_packed_depth_stencil's internal formats (issue #14): DEPTH_STENCIL and
//! DEPTH24_STENCIL8 textures (TexImage1D/2D and cube faces, proxies, TexSubImage of
//! DEPTH_STENCIL and DEPTH_COMPONENT data, CopyTex(Sub)Image from the depth and stencil
//! buffers, GetTexImage, the level queries, sampling as a depth texture) and renderbuffers
//! (RenderbufferStorage, one image on both the depth and the stencil attachment point, drawn
//! into with the depth and stencil tests), each against the real driver (Mesa llvmpipe through
//! EGL): errors, state, bytes and pixels. Skipped, with a note on stderr, when no GL backend
//! can start.
#![cfg(feature = "gl")]

use crate::common::{cpu_vs_gl, test_backend};
use fixedgl::gl::*;
use fixedgl::glbackend::GlBackend;
use fixedgl::{Call, Context};

/// GL_TEXTURE_STENCIL_SIZE_EXT (not among the GL 2.1 constants).
const TEXTURE_STENCIL_SIZE: u32 = 0x88F1;

/// `n` packed 24_8 words with varied depths and indices.
fn ds_words(n: u32) -> Vec<u32> {
    (0..n)
        .map(|k| (((k * 0x0F_1234 + 0x3456) & 0xFF_FFFF) << 8) | ((k * 41 + 7) & 0xFF))
        .collect()
}

fn bytes_of(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_ne_bytes()).collect()
}

/// TexImage1D/2D/3D of a 2 (x 2 (x 2)) image of `ifmt` from `format`/`type_` data.
fn tex_image(target: u32, ifmt: u32, format: u32, type_: u32) -> Call {
    let data = Some(bytes_of(&ds_words(8)));
    match target {
        TEXTURE_1D | PROXY_TEXTURE_1D => Call::TexImage1D(Box::new((
            target,
            0,
            ifmt as i32,
            2,
            0,
            format,
            type_,
            data,
        ))),
        TEXTURE_3D | PROXY_TEXTURE_3D => Call::TexImage3D(Box::new((
            target,
            0,
            ifmt as i32,
            2,
            2,
            2,
            0,
            format,
            type_,
            data,
        ))),
        _ => Call::TexImage2D(Box::new((
            target,
            0,
            ifmt as i32,
            2,
            2,
            0,
            format,
            type_,
            data,
        ))),
    }
}

/// The level parameters of `target`'s level 0 on the CPU and on the driver.
fn levels(cpu: &mut Context, drv: &GlBackend, target: u32) -> (Vec<i32>, Vec<i32>) {
    let mut got = Vec::new();
    let mut want = Vec::new();
    for p in [
        TEXTURE_WIDTH,
        TEXTURE_INTERNAL_FORMAT,
        TEXTURE_DEPTH_SIZE,
        TEXTURE_STENCIL_SIZE,
        TEXTURE_RED_SIZE,
        TEXTURE_ALPHA_SIZE,
        TEXTURE_LUMINANCE_SIZE,
        TEXTURE_INTENSITY_SIZE,
    ] {
        let mut a = [-7];
        cpu.get_tex_level_parameteriv(target, 0, p, &mut a);
        let mut b = -7;
        // SAFETY: the backend's context is current for its own calls; one value written.
        unsafe { drv.raw().GetTexLevelParameteriv(target, 0, p, &mut b) };
        got.push(a[0]);
        want.push(b);
    }
    (got, want)
}

/// Every target x internal format x data combination: the error (the driver's, measured) on
/// both, and the level state after on both.
#[test]
fn tex_image_errors_and_levels_match_the_driver() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let data = [
        (DEPTH_STENCIL, UNSIGNED_INT_24_8),
        (DEPTH_COMPONENT, UNSIGNED_INT),
        (DEPTH_COMPONENT, FLOAT),
        (RGBA, UNSIGNED_BYTE),
        (STENCIL_INDEX, UNSIGNED_BYTE),
        (DEPTH_STENCIL, UNSIGNED_INT),
        (DEPTH_COMPONENT, UNSIGNED_INT_24_8),
        (RGBA, UNSIGNED_INT_24_8),
    ];
    // (target, binding to make first, the level target to query, 3D?)
    let targets = [
        (TEXTURE_1D, TEXTURE_1D, TEXTURE_1D),
        (TEXTURE_2D, TEXTURE_2D, TEXTURE_2D),
        (
            TEXTURE_CUBE_MAP_POSITIVE_X,
            TEXTURE_CUBE_MAP,
            TEXTURE_CUBE_MAP_POSITIVE_X,
        ),
        (TEXTURE_3D, TEXTURE_3D, TEXTURE_3D),
        (PROXY_TEXTURE_1D, 0, PROXY_TEXTURE_1D),
        (PROXY_TEXTURE_2D, 0, PROXY_TEXTURE_2D),
        (PROXY_TEXTURE_CUBE_MAP, 0, PROXY_TEXTURE_CUBE_MAP),
        (PROXY_TEXTURE_3D, 0, PROXY_TEXTURE_3D),
    ];
    let mut rows = 0;
    for (n, &(target, bind, query)) in targets.iter().enumerate() {
        if bind != 0 {
            let b = Call::BindTexture(bind, n as u32 + 1);
            cpu.execute(&b);
            drv.execute(&b);
        }
        for ifmt in [DEPTH_STENCIL, DEPTH24_STENCIL8, RGBA8, DEPTH_COMPONENT24] {
            for &(format, type_) in &data {
                let call = tex_image(target, ifmt, format, type_);
                cpu.execute(&call);
                drv.execute(&call);
                let (e_cpu, e_drv) = (cpu.get_error(), drv.get_error());
                assert_eq!(e_cpu, e_drv, "error of {call:?}");
                if e_cpu == NO_ERROR {
                    let (got, want) = levels(&mut cpu, &drv, query);
                    assert_eq!(got, want, "level state after {call:?}");
                }
                rows += 1;
            }
        }
    }
    assert_eq!(rows, 8 * 4 * 8);
}

/// TexSubImage and CopyTex(Sub)Image into DEPTH_STENCIL images, and into colour images from
/// DEPTH_STENCIL data: each call's error on both.
#[test]
fn sub_image_and_copy_errors_match_the_driver() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let ds = bytes_of(&ds_words(4));
    let sub = |format: u32, type_: u32| {
        Call::TexSubImage2D(Box::new((
            TEXTURE_2D,
            0,
            1,
            1,
            1,
            1,
            format,
            type_,
            ds.clone(),
        )))
    };
    let rows: Vec<(Call, u32)> = vec![
        (Call::BindTexture(TEXTURE_2D, 1), NO_ERROR),
        (
            tex_image(
                TEXTURE_2D,
                DEPTH24_STENCIL8,
                DEPTH_STENCIL,
                UNSIGNED_INT_24_8,
            ),
            NO_ERROR,
        ),
        (sub(DEPTH_STENCIL, UNSIGNED_INT_24_8), NO_ERROR),
        (sub(DEPTH_COMPONENT, UNSIGNED_INT), NO_ERROR),
        (sub(DEPTH_COMPONENT, FLOAT), NO_ERROR),
        (sub(RGBA, UNSIGNED_BYTE), INVALID_OPERATION),
        (sub(STENCIL_INDEX, UNSIGNED_BYTE), INVALID_OPERATION),
        (sub(DEPTH_STENCIL, UNSIGNED_INT), INVALID_ENUM),
        (sub(DEPTH_COMPONENT, UNSIGNED_INT_24_8), INVALID_OPERATION),
        (
            Call::CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 0, 1, 2),
            NO_ERROR,
        ),
        (
            Call::CopyTexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 0, 0, 2, 2, 0),
            NO_ERROR,
        ),
        (
            Call::CopyTexImage2D(TEXTURE_2D, 0, DEPTH_STENCIL, 1, 1, 4, 4, 0),
            NO_ERROR,
        ),
        (
            Call::CopyTexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 0, 0, 4, 4, 1),
            NO_ERROR,
        ),
        (tex_image(TEXTURE_2D, RGBA8, RGBA, UNSIGNED_BYTE), NO_ERROR),
        (sub(DEPTH_STENCIL, UNSIGNED_INT_24_8), INVALID_OPERATION),
        (
            tex_image(TEXTURE_2D, DEPTH_COMPONENT24, DEPTH_COMPONENT, FLOAT),
            NO_ERROR,
        ),
        (sub(DEPTH_STENCIL, UNSIGNED_INT_24_8), NO_ERROR),
        (Call::BindTexture(TEXTURE_1D, 2), NO_ERROR),
        (
            Call::CopyTexImage1D(TEXTURE_1D, 0, DEPTH24_STENCIL8, 0, 0, 4, 0),
            NO_ERROR,
        ),
        (Call::CopyTexSubImage1D(TEXTURE_1D, 0, 1, 2, 2, 2), NO_ERROR),
        (Call::BindTexture(TEXTURE_CUBE_MAP, 3), NO_ERROR),
        (
            Call::CopyTexImage2D(TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, DEPTH_STENCIL, 0, 0, 4, 4, 0),
            NO_ERROR,
        ),
    ];
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        drv.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(drv.get_error(), *expected, "GL after row {i}: {call:?}");
    }
}

/// Reads level 0 of the bound 2D texture as `format`/`type_` (4-byte groups) on both.
fn get_both(
    cpu: &mut Context,
    drv: &GlBackend,
    n: usize,
    format: u32,
    type_: u32,
) -> (Vec<u32>, Vec<u32>) {
    let mut bytes = vec![0u8; n * 4];
    cpu.get_tex_image(TEXTURE_2D, 0, format, type_, &mut bytes);
    let a = bytes
        .chunks(4)
        .map(|q| u32::from_ne_bytes([q[0], q[1], q[2], q[3]]))
        .collect();
    let mut b = vec![0u32; n];
    // SAFETY: the backend's context is current; the driver writes n 4-byte groups into `b`
    // (PACK_ALIGNMENT 4, rows of 4-byte groups).
    unsafe {
        drv.raw()
            .GetTexImage(TEXTURE_2D, 0, format, type_, b.as_mut_ptr().cast())
    };
    (a, b)
}

/// GetTexImage of DEPTH_STENCIL images: what TexImage, TexSubImage (both kinds of data) and
/// CopyTex(Sub)Image stored, read back as DEPTH_STENCIL (byte for byte) and as
/// DEPTH_COMPONENT.
#[test]
fn get_tex_image_round_trips_match_the_driver() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let words = ds_words(16);
    cpu.start_recording();
    cpu.bind_texture(TEXTURE_2D, 1);
    cpu.tex_image_2d(
        TEXTURE_2D,
        0,
        DEPTH24_STENCIL8 as i32,
        4,
        4,
        0,
        DEPTH_STENCIL,
        UNSIGNED_INT_24_8,
        Some(&bytes_of(&words)),
    );
    // The index through the index transfer, the depth through DEPTH_SCALE/BIAS.
    cpu.pixel_transferi(INDEX_OFFSET, 3);
    cpu.pixel_transferf(DEPTH_SCALE, 0.5);
    cpu.tex_sub_image_2d(
        TEXTURE_2D,
        0,
        2,
        0,
        2,
        2,
        DEPTH_STENCIL,
        UNSIGNED_INT_24_8,
        &bytes_of(&words[3..]),
    );
    cpu.pixel_transferi(INDEX_OFFSET, 0);
    cpu.pixel_transferf(DEPTH_SCALE, 1.0);
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), NO_ERROR);
    assert_eq!(drv.get_error(), NO_ERROR);
    let (a, b) = get_both(&mut cpu, &drv, 16, DEPTH_STENCIL, UNSIGNED_INT_24_8);
    assert_eq!(a, b, "DEPTH_STENCIL bytes (cpu, driver)");
    let (a, b) = get_both(&mut cpu, &drv, 16, DEPTH_COMPONENT, UNSIGNED_INT);
    // llvmpipe converts through a float: the low bits below the 24 stored ones differ.
    for (k, (x, y)) in a.iter().zip(&b).enumerate() {
        assert!(
            (x >> 8).abs_diff(y >> 8) <= 1,
            "depth {k}: {x:#x} vs {y:#x}"
        );
    }
    // DEPTH_COMPONENT data replaces the depths; llvmpipe's stencil there is undefined
    // (measured: other bytes), fixedgl keeps it. Compared: the depths everywhere, the
    // indices of the texels not replaced.
    cpu.start_recording();
    let depths: Vec<u8> = [0.25f32, 0.5, 0.75, 1.0]
        .iter()
        .flat_map(|d| d.to_ne_bytes())
        .collect();
    cpu.tex_sub_image_2d(TEXTURE_2D, 0, 1, 1, 2, 2, DEPTH_COMPONENT, FLOAT, &depths);
    drv.replay(&cpu.stop_recording());
    let (a, b) = get_both(&mut cpu, &drv, 16, DEPTH_STENCIL, UNSIGNED_INT_24_8);
    let before = get_stencils_before(&words);
    for k in 0..16 {
        let (x, y) = (k % 4, k / 4);
        let replaced = (1..3).contains(&x) && (1..3).contains(&y);
        // Float depths: llvmpipe truncates where fixedgl rounds (within 1 of 2^24 - 1).
        assert!((a[k] >> 8).abs_diff(b[k] >> 8) <= 1, "depth of texel {k}");
        if replaced {
            assert_eq!(
                a[k] & 0xFF,
                before[k],
                "fixedgl keeps the index of texel {k}"
            );
        } else {
            assert_eq!(a[k] & 0xFF, b[k] & 0xFF, "index of texel {k}");
        }
    }
    // CopyTexSubImage and CopyTexImage from the depth and stencil buffers, into an image
    // whose every index is defined on both.
    cpu.start_recording();
    cpu.tex_image_2d(
        TEXTURE_2D,
        0,
        DEPTH24_STENCIL8 as i32,
        4,
        4,
        0,
        DEPTH_STENCIL,
        UNSIGNED_INT_24_8,
        Some(&bytes_of(&words)),
    );
    cpu.clear_depth(0.25);
    cpu.clear_stencil(0x5A);
    cpu.clear(DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    cpu.draw_pixels(
        2,
        2,
        DEPTH_STENCIL,
        UNSIGNED_INT_24_8,
        &bytes_of(&words[5..9]),
    );
    // The raster position (0, 0, 0) is window (4, 4): the copies take in the drawn groups.
    cpu.copy_tex_sub_image_2d(TEXTURE_2D, 0, 0, 0, 3, 3, 2, 3);
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), NO_ERROR);
    assert_eq!(drv.get_error(), NO_ERROR);
    let (a, b) = get_both(&mut cpu, &drv, 16, DEPTH_STENCIL, UNSIGNED_INT_24_8);
    assert_ds_close(&a, &b, "CopyTexSubImage2D");
    cpu.start_recording();
    cpu.copy_tex_image_2d(TEXTURE_2D, 0, DEPTH_STENCIL, 2, 2, 4, 4, 0);
    drv.replay(&cpu.stop_recording());
    assert_eq!(drv.get_error(), NO_ERROR);
    let (a, b) = get_both(&mut cpu, &drv, 16, DEPTH_STENCIL, UNSIGNED_INT_24_8);
    assert_ds_close(&a, &b, "CopyTexImage2D");
    // A colour or depth-only image has no DEPTH_STENCIL to read; RGBA from a depth-stencil one
    // is refused too.
    let mut out = vec![0u8; 64];
    cpu.get_tex_image(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, &mut out);
    assert_eq!(cpu.get_error(), INVALID_OPERATION);
    // SAFETY: as above, 16 groups of 4 bytes.
    unsafe {
        drv.raw()
            .GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, out.as_mut_ptr().cast())
    };
    assert_eq!(drv.get_error(), INVALID_OPERATION);
}

/// The indices TexImage stored from `words` (4x4) after the TexSubImage of the first test step
/// (texels x 2..4, y 0..2 from words[3..] with INDEX_OFFSET 3).
fn get_stencils_before(words: &[u32]) -> Vec<u32> {
    (0..16)
        .map(|k| {
            let (x, y) = (k % 4, k / 4);
            if x >= 2 && y < 2 {
                ((words[3 + (y * 2 + x - 2)] & 0xFF) + 3) & 0xFF
            } else {
                words[k] & 0xFF
            }
        })
        .collect()
}

/// DEPTH_STENCIL groups equal in the index and within 1 in the 24-bit depth (llvmpipe's depth
/// buffer passes through a float on the way from DrawPixels).
fn assert_ds_close(a: &[u32], b: &[u32], what: &str) {
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert_eq!(
            x & 0xFF,
            y & 0xFF,
            "{what}: index of texel {k} ({x:#x} vs {y:#x})"
        );
        assert!(
            (x >> 8).abs_diff(y >> 8) <= 1,
            "{what}: depth of texel {k} ({x:#x} vs {y:#x})"
        );
    }
}

/// A DEPTH24_STENCIL8 texture sampled as a depth texture: DEPTH_TEXTURE_MODE LUMINANCE,
/// INTENSITY and ALPHA, and TEXTURE_COMPARE_MODE with LEQUAL and GREATER against r; the
/// indices are never sampled.
#[test]
fn depth_stencil_textures_sample_as_depth_textures() {
    let words = ds_words(16);
    let Some((n, first)) = cpu_vs_gl(32, 1, |c| {
        c.clear_color(0.2, 0.3, 0.4, 1.0);
        c.clear(COLOR_BUFFER_BIT);
        c.bind_texture(TEXTURE_2D, 1);
        c.tex_image_2d(
            TEXTURE_2D,
            0,
            DEPTH24_STENCIL8 as i32,
            4,
            4,
            0,
            DEPTH_STENCIL,
            UNSIGNED_INT_24_8,
            Some(&bytes_of(&words)),
        );
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
        c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
        c.enable(TEXTURE_2D);
        let quads: [(f32, f32, u32, u32, u32); 5] = [
            (-1.0, -1.0, LUMINANCE, NONE, LEQUAL),
            (0.0, -1.0, INTENSITY, NONE, LEQUAL),
            (-1.0, 0.0, ALPHA, NONE, LEQUAL),
            (0.0, 0.0, LUMINANCE, COMPARE_R_TO_TEXTURE, LEQUAL),
            (-0.5, -0.5, INTENSITY, COMPARE_R_TO_TEXTURE, GREATER),
        ];
        for (x0, y0, mode, compare, func) in quads {
            c.tex_parameteri(TEXTURE_2D, DEPTH_TEXTURE_MODE, mode as i32);
            c.tex_parameteri(TEXTURE_2D, TEXTURE_COMPARE_MODE, compare as i32);
            c.tex_parameteri(TEXTURE_2D, TEXTURE_COMPARE_FUNC, func as i32);
            c.color4f(1.0, 0.8, 0.6, 0.9);
            c.begin(QUADS);
            for (dx, dy) in [(0.0f32, 0.0f32), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                // r runs across the quad, so the comparison passes and fails in it.
                c.tex_coord3f(dx, dy, 0.1 + 0.8 * dx);
                c.vertex2f(x0 + dx, y0 + dy);
            }
            c.end();
        }
        c.disable(TEXTURE_2D);
    }) else {
        return;
    };
    assert_eq!(n, 0, "{first}");
}

/// Runs the attachment steps on both, the status and the bound renderbuffer's parameters
/// compared after each.
fn fbo_statuses(c: &mut Context, drv: &mut GlBackend) {
    // One step: renderbuffer `name` attached to `point` of the bound framebuffer.
    let attach = |point: u32, name: u32| {
        vec![Call::FramebufferRenderbuffer(
            FRAMEBUFFER,
            point,
            RENDERBUFFER,
            name,
        )]
    };
    let steps: Vec<Vec<Call>> = vec![
        vec![
            Call::BindRenderbuffer(RENDERBUFFER, 1),
            Call::RenderbufferStorage(RENDERBUFFER, DEPTH24_STENCIL8, 8, 8),
            Call::BindRenderbuffer(RENDERBUFFER, 2),
            Call::RenderbufferStorage(RENDERBUFFER, RGBA8, 8, 8),
            Call::BindRenderbuffer(RENDERBUFFER, 3),
            Call::RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT24, 8, 8),
            Call::BindRenderbuffer(RENDERBUFFER, 4),
            Call::RenderbufferStorage(RENDERBUFFER, STENCIL_INDEX8, 8, 8),
            Call::BindRenderbuffer(RENDERBUFFER, 5),
            Call::RenderbufferStorage(RENDERBUFFER, DEPTH_STENCIL, 8, 8),
            Call::BindFramebuffer(FRAMEBUFFER, 1),
            Call::FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, 2),
        ],
        attach(DEPTH_ATTACHMENT, 1),
        attach(STENCIL_ATTACHMENT, 1),
        attach(DEPTH_ATTACHMENT, 0),
        attach(DEPTH_ATTACHMENT, 3),
        attach(STENCIL_ATTACHMENT, 4),
        attach(DEPTH_ATTACHMENT, 0),
        attach(DEPTH_ATTACHMENT, 1),
        attach(STENCIL_ATTACHMENT, 5),
        attach(DEPTH_ATTACHMENT, 5),
        attach(STENCIL_ATTACHMENT, 3),
        vec![
            Call::FramebufferRenderbuffer(FRAMEBUFFER, STENCIL_ATTACHMENT, RENDERBUFFER, 0),
            Call::BindTexture(TEXTURE_2D, 1),
            tex_image(
                TEXTURE_2D,
                DEPTH24_STENCIL8,
                DEPTH_STENCIL,
                UNSIGNED_INT_24_8,
            ),
            Call::FramebufferTexture2D(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, 1, 0),
        ],
        vec![Call::FramebufferTexture2D(
            FRAMEBUFFER,
            STENCIL_ATTACHMENT,
            TEXTURE_2D,
            1,
            0,
        )],
        attach(STENCIL_ATTACHMENT, 5),
        vec![
            Call::BindTexture(TEXTURE_2D, 2),
            tex_image(TEXTURE_2D, DEPTH_COMPONENT24, DEPTH_COMPONENT, FLOAT),
            Call::FramebufferTexture2D(FRAMEBUFFER, STENCIL_ATTACHMENT, TEXTURE_2D, 2, 0),
        ],
        vec![Call::BindFramebuffer(FRAMEBUFFER, 0)],
    ];
    for (i, step) in steps.iter().enumerate() {
        for call in step {
            c.execute(call);
            drv.execute(call);
        }
        assert_eq!(c.get_error(), NO_ERROR, "CPU step {i}");
        assert_eq!(drv.get_error(), NO_ERROR, "driver step {i}");
        let got = c.check_framebuffer_status(FRAMEBUFFER);
        let want = drv.check_framebuffer_status(FRAMEBUFFER);
        assert_eq!(got, want, "status after step {i}: {step:?}");
        let mut got = Vec::new();
        let mut want = Vec::new();
        for p in [
            RENDERBUFFER_INTERNAL_FORMAT,
            RENDERBUFFER_DEPTH_SIZE,
            RENDERBUFFER_STENCIL_SIZE,
            RENDERBUFFER_RED_SIZE,
        ] {
            let mut a = [-7];
            c.get_renderbuffer_parameteriv(RENDERBUFFER, p, &mut a);
            let mut b = -7;
            // SAFETY: the backend's context is current; one value written.
            unsafe {
                drv.raw()
                    .GetRenderbufferParameteriv(RENDERBUFFER, p, &mut b)
            };
            got.push(a[0]);
            want.push(b);
        }
        assert_eq!(got, want, "renderbuffer parameters after step {i}");
    }
}

/// Statuses of framebuffers with packed depth-stencil renderbuffers and textures on the depth
/// and stencil points (one image on both, either alone, two images, a depth-only format on the
/// stencil point), and the renderbuffer queries, after each step on both.
#[test]
fn packed_attachments_complete_as_the_driver_says() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let Ok(mut c) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    fbo_statuses(&mut c, &mut drv);
}

/// A framebuffer with one DEPTH24_STENCIL8 renderbuffer on both points drawn with the stencil
/// and depth tests, then shown through its colour texture; its depth and stencil read back
/// with ReadPixels(DEPTH_STENCIL); and a DEPTH24_STENCIL8 texture attached on both points,
/// drawn into, then sampled as a depth texture.
#[test]
fn packed_framebuffers_draw_as_the_driver_draws() {
    let Some(mut drv) = test_backend(32, 32) else {
        return;
    };
    let Ok(mut c) = Context::new(32, 32) else {
        panic!("CPU context")
    };
    c.start_recording();
    // Colour texture 1, depth-stencil renderbuffer 1, framebuffer 1.
    c.bind_texture(TEXTURE_2D, 1);
    c.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA8 as i32,
        16,
        16,
        0,
        RGBA,
        UNSIGNED_BYTE,
        None,
    );
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    c.bind_renderbuffer(RENDERBUFFER, 1);
    c.renderbuffer_storage(RENDERBUFFER, DEPTH24_STENCIL8, 16, 16);
    c.bind_framebuffer(FRAMEBUFFER, 1);
    c.framebuffer_texture_2d(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 1, 0);
    c.framebuffer_renderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, 1);
    c.framebuffer_renderbuffer(FRAMEBUFFER, STENCIL_ATTACHMENT, RENDERBUFFER, 1);
    stencil_scene(&mut c, 16);
    // Away and back: the renderbuffer keeps depth and stencil; a second pass tests them.
    c.bind_framebuffer(FRAMEBUFFER, 0);
    c.bind_framebuffer(FRAMEBUFFER, 1);
    c.enable(STENCIL_TEST);
    c.stencil_func(EQUAL, 2, 0xFF);
    c.stencil_op(KEEP, KEEP, INCR);
    c.enable(DEPTH_TEST);
    c.depth_func(LESS);
    quad(&mut c, -1.0, -1.0, 2.0, 0.5, [0.9, 0.9, 0.1]);
    c.disable(STENCIL_TEST);
    c.disable(DEPTH_TEST);
    drv.replay(&c.stop_recording());
    assert_eq!(c.get_error(), NO_ERROR);
    assert_eq!(drv.get_error(), NO_ERROR);
    let mut bytes = vec![0u8; 16 * 16 * 4];
    c.read_pixels(0, 0, 16, 16, DEPTH_STENCIL, UNSIGNED_INT_24_8, &mut bytes);
    let a: Vec<u32> = bytes
        .chunks(4)
        .map(|q| u32::from_ne_bytes([q[0], q[1], q[2], q[3]]))
        .collect();
    let mut b = vec![0u32; 256];
    // SAFETY: the backend's context is current, framebuffer 1 bound; 16x16 4-byte groups.
    unsafe {
        drv.raw().ReadPixels(
            0,
            0,
            16,
            16,
            DEPTH_STENCIL,
            UNSIGNED_INT_24_8,
            b.as_mut_ptr().cast(),
        )
    };
    assert_eq!(drv.get_error(), NO_ERROR);
    assert_ds_close(&a, &b, "ReadPixels of the packed renderbuffer");
    // The colour texture on the window, and a DEPTH24_STENCIL8 texture drawn into, then
    // sampled.
    c.start_recording();
    c.bind_framebuffer(FRAMEBUFFER, 0);
    c.clear_color(0.0, 0.0, 0.0, 1.0);
    c.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    show(&mut c, 1, -1.0);
    c.bind_texture(TEXTURE_2D, 2);
    c.tex_image_2d(
        TEXTURE_2D,
        0,
        DEPTH24_STENCIL8 as i32,
        16,
        16,
        0,
        DEPTH_STENCIL,
        UNSIGNED_INT_24_8,
        None,
    );
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    c.bind_texture(TEXTURE_2D, 3);
    c.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA8 as i32,
        16,
        16,
        0,
        RGBA,
        UNSIGNED_BYTE,
        None,
    );
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    c.bind_framebuffer(FRAMEBUFFER, 2);
    c.framebuffer_texture_2d(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 3, 0);
    c.framebuffer_texture_2d(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, 2, 0);
    c.framebuffer_texture_2d(FRAMEBUFFER, STENCIL_ATTACHMENT, TEXTURE_2D, 2, 0);
    stencil_scene(&mut c, 16);
    c.bind_framebuffer(FRAMEBUFFER, 0);
    show(&mut c, 3, 0.0);
    c.bind_texture(TEXTURE_2D, 2);
    c.tex_parameteri(TEXTURE_2D, DEPTH_TEXTURE_MODE, LUMINANCE as i32);
    show_at(&mut c, 2, -1.0, 0.0);
    drv.replay(&c.stop_recording());
    assert_eq!(c.get_error(), NO_ERROR);
    assert_eq!(drv.get_error(), NO_ERROR);
    let (ci, gi) = (c.to_image(), drv.read_image());
    let cmp = fixedgl::compare::compare(&ci, &gi, 1);
    assert_eq!(cmp.differing_pixels, 0, "window pixels off by more than 1");
    // The texture's indices after drawing, byte for byte.
    c.bind_texture(TEXTURE_2D, 2);
    let mut bytes = vec![0u8; 256 * 4];
    c.get_tex_image(TEXTURE_2D, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, &mut bytes);
    let a: Vec<u32> = bytes
        .chunks(4)
        .map(|q| u32::from_ne_bytes([q[0], q[1], q[2], q[3]]))
        .collect();
    let mut b = vec![0u32; 256];
    // SAFETY: the backend's context is current, texture 2 bound; 16x16 4-byte groups.
    unsafe {
        drv.raw().BindTexture(TEXTURE_2D, 2);
        drv.raw().GetTexImage(
            TEXTURE_2D,
            0,
            DEPTH_STENCIL,
            UNSIGNED_INT_24_8,
            b.as_mut_ptr().cast(),
        );
    }
    assert_eq!(drv.get_error(), NO_ERROR);
    assert_ds_close(&a, &b, "GetTexImage of the drawn texture");
}

/// Clears depth 1 and stencil 0, then draws three overlapping quads at different depths:
/// the first marks stencil 1 (ALWAYS, REPLACE), the second only where the stencil is 1
/// (EQUAL, INCR on depth pass), the third with the depth test alone.
fn stencil_scene(c: &mut Context, size: i32) {
    c.viewport(0, 0, size, size);
    c.clear_color(0.1, 0.1, 0.1, 1.0);
    c.clear_depth(1.0);
    c.clear_stencil(0);
    c.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    c.enable(DEPTH_TEST);
    c.depth_func(LESS);
    c.enable(STENCIL_TEST);
    c.stencil_func(ALWAYS, 1, 0xFF);
    c.stencil_op(KEEP, KEEP, REPLACE);
    quad_z(c, -0.75, -0.75, 1.0, 1.0, 0.5, [1.0, 0.0, 0.0]);
    c.stencil_func(EQUAL, 1, 0xFF);
    c.stencil_op(KEEP, ZERO, INCR);
    quad_z(c, -0.5, -0.5, 1.25, 1.0, 0.2, [0.0, 1.0, 0.0]);
    c.disable(STENCIL_TEST);
    quad_z(c, 0.0, -1.0, 0.5, 2.0, -0.3, [0.0, 0.0, 1.0]);
    c.disable(DEPTH_TEST);
}

fn quad(c: &mut Context, x: f32, y: f32, w: f32, h: f32, rgb: [f32; 3]) {
    quad_z(c, x, y, w, h, 0.0, rgb);
}

fn quad_z(c: &mut Context, x: f32, y: f32, w: f32, h: f32, z: f32, [r, g, b]: [f32; 3]) {
    c.color3f(r, g, b);
    c.begin(QUADS);
    c.vertex3f(x, y, z);
    c.vertex3f(x + w, y, z + 0.3);
    c.vertex3f(x + w, y + h, z + 0.3);
    c.vertex3f(x, y + h, z);
    c.end();
}

/// Texture `tex` on the window's quad from (x, -1), 1 wide and 1 high in NDC.
fn show(c: &mut Context, tex: u32, x: f32) {
    show_at(c, tex, x, -1.0);
}

fn show_at(c: &mut Context, tex: u32, x: f32, y: f32) {
    c.viewport(0, 0, 32, 32);
    c.bind_texture(TEXTURE_2D, tex);
    c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    c.enable(TEXTURE_2D);
    c.color3f(1.0, 1.0, 1.0);
    c.begin(QUADS);
    for (dx, dy) in [(0.0f32, 0.0f32), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        c.tex_coord2f(dx, dy);
        c.vertex2f(x + dx, y + dy);
    }
    c.end();
    c.disable(TEXTURE_2D);
}
