//! Texture images from every kind of client pixel data against the real driver (Mesa llvmpipe):
//! the packed types of GL 1.2 (table 3.8) with RGB, RGBA, BGRA and EXT_abgr's ABGR, with and
//! without UNPACK_SWAP_BYTES; colour indices (UNSIGNED_BYTE and BITMAP) made RGBA through the
//! I_TO_* maps; the pixel transfer on the way in; the format/type errors; GetTexImage packing
//! into the packed types. Skipped, with a note on stderr, when no GL backend can start.
#![cfg(feature = "gl")]

use crate::common::cpu_vs_gl;
use fixedgl::{gl, Call, Context};

/// Draws the bound 2D texture over the whole viewport with REPLACE and NEAREST.
fn draw_textured(c: &mut Context) {
    use fixedgl::gl::*;
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    c.enable(TEXTURE_2D);
    c.begin(QUADS);
    for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        c.tex_coord2f((x + 1.0) / 2.0, (y + 1.0) / 2.0);
        c.vertex2f(x, y);
    }
    c.end();
    c.disable(TEXTURE_2D);
}

/// 16 elements of `bytes` bytes each with varied bits (every field of every packed type sees
/// low, high and middle values).
fn packed_data(bytes: usize) -> Vec<u8> {
    (0..16 * bytes as u32)
        .map(|k| (k.wrapping_mul(0x9E37_79B9) >> 13 ^ (k << 3) ^ 0xA5) as u8)
        .collect()
}

const PACKED4: [(u32, usize); 10] = [
    (gl::UNSIGNED_SHORT_4_4_4_4, 2),
    (gl::UNSIGNED_SHORT_4_4_4_4_REV, 2),
    (gl::UNSIGNED_SHORT_5_5_5_1, 2),
    (gl::UNSIGNED_SHORT_1_5_5_5_REV, 2),
    (gl::UNSIGNED_INT_8_8_8_8, 4),
    (gl::UNSIGNED_INT_8_8_8_8_REV, 4),
    (gl::UNSIGNED_INT_10_10_10_2, 4),
    (gl::UNSIGNED_INT_2_10_10_10_REV, 4),
    (gl::UNSIGNED_BYTE, 4),
    (gl::UNSIGNED_SHORT, 8),
];

const PACKED3: [(u32, usize); 4] = [
    (gl::UNSIGNED_BYTE_3_3_2, 1),
    (gl::UNSIGNED_BYTE_2_3_3_REV, 1),
    (gl::UNSIGNED_SHORT_5_6_5, 2),
    (gl::UNSIGNED_SHORT_5_6_5_REV, 2),
];

#[test]
fn packed_types_make_the_textures_the_driver_makes() {
    use fixedgl::gl::*;
    let mut cases = Vec::new();
    for format in [RGBA, BGRA] {
        for (ty, bytes) in PACKED4 {
            cases.push((format, ty, bytes));
        }
    }
    // ABGR_EXT: the test's driver context raises INVALID_OPERATION for it with 5_5_5_1 (where
    // Mesa's format/type table takes it, and piglit's texture-packed-formats passes on both):
    // the 4_4_4_4 types and the unpacked ones are compared.
    for (ty, bytes) in [
        (UNSIGNED_SHORT_4_4_4_4, 2),
        (UNSIGNED_SHORT_4_4_4_4_REV, 2),
        (UNSIGNED_BYTE, 4),
        (UNSIGNED_SHORT, 8),
    ] {
        cases.push((ABGR_EXT, ty, bytes));
    }
    for (ty, bytes) in PACKED3 {
        cases.push((RGB, ty, bytes));
    }
    for (format, ty, bytes) in cases {
        // 8-bit internal formats: llvmpipe stores RGB5_A1, RGBA4 ... at their own precision
        // where fixedgl keeps 8 bits (docs/conformance.md §3.8).
        for internal in [RGBA8, RGB, LUMINANCE_ALPHA, INTENSITY8] {
            for swap in [false, true] {
                let data = packed_data(bytes);
                let Some((n, first)) = cpu_vs_gl(16, 1, |c| {
                    c.clear_color(0.2, 0.3, 0.4, 1.0);
                    c.clear(COLOR_BUFFER_BIT);
                    c.pixel_storei(UNPACK_SWAP_BYTES, i32::from(swap));
                    c.pixel_storei(UNPACK_ALIGNMENT, 1);
                    c.tex_image_2d(
                        TEXTURE_2D,
                        0,
                        internal as i32,
                        4,
                        4,
                        0,
                        format,
                        ty,
                        Some(&data),
                    );
                    draw_textured(c);
                }) else {
                    return;
                };
                assert_eq!(
                    n, 0,
                    "format {format:#x} type {ty:#x} internal {internal:#x} swap {swap}: {first}"
                );
            }
        }
    }
}

#[test]
fn packed_sub_images_and_the_transfer_match_the_driver() {
    use fixedgl::gl::*;
    let Some((n, first)) = cpu_vs_gl(16, 1, |c| {
        c.tex_image_2d(
            TEXTURE_2D,
            0,
            RGBA as i32,
            4,
            4,
            0,
            RGBA,
            UNSIGNED_BYTE,
            None,
        );
        // Scale and bias on the way in (§3.8.1 through §3.6.5), then a packed sub-image.
        c.pixel_transferf(RED_SCALE, 0.5);
        c.pixel_transferf(BLUE_BIAS, 0.25);
        let data = packed_data(2);
        c.tex_sub_image_2d(
            TEXTURE_2D,
            0,
            1,
            1,
            2,
            2,
            BGRA,
            UNSIGNED_SHORT_4_4_4_4,
            &data,
        );
        c.tex_sub_image_2d(TEXTURE_2D, 0, 0, 0, 1, 4, RGB, UNSIGNED_SHORT_5_6_5, &data);
        c.pixel_transferf(RED_SCALE, 1.0);
        c.pixel_transferf(BLUE_BIAS, 0.0);
        draw_textured(c);
    }) else {
        return;
    };
    assert_eq!(n, 0, "{first}");
}

#[test]
fn colour_index_data_is_mapped_to_rgba_as_the_driver_maps_it() {
    use fixedgl::gl::*;
    for (ty, shift, offset) in [
        (UNSIGNED_BYTE, 0, 0),
        (UNSIGNED_BYTE, 1, 3),
        (SHORT, -1, 2),
        (FLOAT, 0, 1),
        (BITMAP, 0, 0),
        (BITMAP, 2, 1),
    ] {
        let Some((n, first)) = cpu_vs_gl(16, 1, |c| {
            let r: Vec<f32> = (0..8).map(|k| k as f32 / 7.0).collect();
            let g: Vec<f32> = (0..8).map(|k| 1.0 - k as f32 / 7.0).collect();
            let b: Vec<f32> = (0..8).map(|k| (k % 3) as f32 / 2.0).collect();
            let a: Vec<f32> = (0..8).map(|k| if k % 2 == 0 { 1.0 } else { 0.5 }).collect();
            c.pixel_mapfv(PIXEL_MAP_I_TO_R, 8, &r);
            c.pixel_mapfv(PIXEL_MAP_I_TO_G, 8, &g);
            c.pixel_mapfv(PIXEL_MAP_I_TO_B, 8, &b);
            c.pixel_mapfv(PIXEL_MAP_I_TO_A, 8, &a);
            c.pixel_transferi(INDEX_SHIFT, shift);
            c.pixel_transferi(INDEX_OFFSET, offset);
            c.pixel_storei(UNPACK_ALIGNMENT, 1);
            // BITMAP: one row of 8 (llvmpipe reads the rows of a COLOR_INDEX bitmap at another
            // stride than UNPACK_ALIGNMENT gives, as for DrawPixels: docs/conformance.md).
            let (w, h) = if ty == BITMAP { (8, 1) } else { (4, 4) };
            let data: Vec<u8> = match ty {
                BITMAP => vec![0b1011_0010],
                SHORT => (0..16i16).flat_map(|k| (k * 5 - 7).to_ne_bytes()).collect(),
                FLOAT => (0..16)
                    .flat_map(|k| (k as f32 * 0.75).to_ne_bytes())
                    .collect(),
                _ => (0..16u8).map(|k| k.wrapping_mul(37)).collect(),
            };
            c.tex_image_2d(
                TEXTURE_2D,
                0,
                RGBA as i32,
                w,
                h,
                0,
                COLOR_INDEX,
                ty,
                Some(&data),
            );
            c.pixel_transferi(INDEX_SHIFT, 0);
            c.pixel_transferi(INDEX_OFFSET, 0);
            c.clear_color(0.9, 0.1, 0.1, 1.0);
            c.clear(COLOR_BUFFER_BIT);
            c.enable(BLEND);
            c.blend_func(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
            draw_textured(c);
            c.disable(BLEND);
        }) else {
            return;
        };
        assert_eq!(n, 0, "type {ty:#x} shift {shift} offset {offset}: {first}");
    }
}

#[test]
fn pixel_data_errors_match_the_driver() {
    use fixedgl::gl::*;
    let Some(mut gl) = crate::common::test_backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let tex = |internal: u32, format: u32, ty: u32, n: usize| {
        Call::TexImage2D(Box::new((
            TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            format,
            ty,
            Some(vec![7u8; n]),
        )))
    };
    let sub = |format: u32, ty: u32, n: usize| {
        Call::TexSubImage2D(Box::new((
            TEXTURE_2D,
            0,
            0,
            0,
            2,
            2,
            format,
            ty,
            vec![7u8; n],
        )))
    };
    let rows: &[(Call, u32)] = &[
        (Call::PixelStorei(UNPACK_ALIGNMENT, 1), NO_ERROR),
        (tex(RGBA, RGBA, UNSIGNED_SHORT_4_4_4_4, 8), NO_ERROR),
        (tex(RGBA, ABGR_EXT, UNSIGNED_INT_8_8_8_8, 16), NO_ERROR),
        (tex(RGB, RGB, UNSIGNED_BYTE_3_3_2, 4), NO_ERROR),
        // Short by one element.
        (tex(RGB, RGB, UNSIGNED_SHORT_5_6_5, 7), INVALID_OPERATION),
        // Table 3.8: a packed type of the wrong component count for the format.
        (tex(RGBA, RGB, UNSIGNED_SHORT_4_4_4_4, 8), INVALID_OPERATION),
        (tex(RGBA, RGBA, UNSIGNED_SHORT_5_6_5, 8), INVALID_OPERATION),
        (
            tex(RGBA, LUMINANCE, UNSIGNED_INT_8_8_8_8, 16),
            INVALID_OPERATION,
        ),
        (tex(RGBA, BGR, UNSIGNED_BYTE_3_3_2, 4), INVALID_OPERATION),
        // BITMAP only with an index format.
        (tex(RGBA, RGBA, BITMAP, 4), INVALID_ENUM),
        (tex(RGBA, COLOR_INDEX, BITMAP, 2), NO_ERROR),
        (tex(LUMINANCE, COLOR_INDEX, UNSIGNED_SHORT, 8), NO_ERROR),
        // Stencil indices make no texture; colour indices no depth texture.
        (
            tex(RGBA, STENCIL_INDEX, UNSIGNED_BYTE, 4),
            INVALID_OPERATION,
        ),
        (
            tex(DEPTH_COMPONENT, COLOR_INDEX, UNSIGNED_BYTE, 4),
            INVALID_OPERATION,
        ),
        // GL_EXT_packed_depth_stencil: DEPTH_STENCIL data is depth data to a depth texture;
        // UNSIGNED_INT_24_8 only with DEPTH_STENCIL and the reverse.
        (
            tex(DEPTH_COMPONENT, DEPTH_STENCIL, UNSIGNED_INT_24_8, 16),
            NO_ERROR,
        ),
        (sub(DEPTH_STENCIL, UNSIGNED_INT_24_8, 16), NO_ERROR),
        (
            sub(DEPTH_COMPONENT, UNSIGNED_INT_24_8, 16),
            INVALID_OPERATION,
        ),
        (sub(DEPTH_STENCIL, UNSIGNED_INT, 16), INVALID_ENUM),
        (
            tex(RGBA, DEPTH_STENCIL, UNSIGNED_INT_24_8, 16),
            INVALID_OPERATION,
        ),
        (
            tex(DEPTH_COMPONENT, DEPTH_COMPONENT, UNSIGNED_INT_24_8, 16),
            INVALID_OPERATION,
        ),
        (tex(DEPTH_COMPONENT, DEPTH_STENCIL, FLOAT, 16), INVALID_ENUM),
        (tex(RGBA, RGBA, UNSIGNED_BYTE, 16), NO_ERROR),
        (sub(DEPTH_STENCIL, UNSIGNED_INT_24_8, 16), INVALID_OPERATION),
        // §3.8.2: no proxy target for TexSubImage, even with a proxy image there.
        (
            Call::TexImage2D(Box::new((
                PROXY_TEXTURE_2D,
                0,
                RGBA as i32,
                2,
                2,
                0,
                RGBA,
                UNSIGNED_BYTE,
                None,
            ))),
            NO_ERROR,
        ),
        (
            Call::TexSubImage2D(Box::new((
                PROXY_TEXTURE_2D,
                0,
                0,
                0,
                2,
                2,
                RGBA,
                UNSIGNED_BYTE,
                vec![7u8; 16],
            ))),
            INVALID_ENUM,
        ),
        (sub(BGRA, UNSIGNED_SHORT_1_5_5_5_REV, 8), NO_ERROR),
        (sub(RGB, UNSIGNED_SHORT_1_5_5_5_REV, 8), INVALID_OPERATION),
        (sub(COLOR_INDEX, UNSIGNED_BYTE, 4), NO_ERROR),
        (sub(COLOR_INDEX, BITMAP, 2), NO_ERROR),
        (sub(STENCIL_INDEX, UNSIGNED_BYTE, 4), INVALID_OPERATION),
        (sub(DEPTH_COMPONENT, UNSIGNED_BYTE, 4), INVALID_OPERATION),
    ];
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), *expected, "GL after row {i}: {call:?}");
    }
}

/// GL_EXT_packed_depth_stencil's DEPTH_STENCIL / UNSIGNED_INT_24_8 data makes a DEPTH_COMPONENT
/// texture of its depths (the indices dropped, as Mesa drops them), by TexImage and by
/// TexSubImage through DEPTH_SCALE and DEPTH_BIAS; drawn as luminance.
#[test]
fn depth_stencil_data_makes_the_depth_textures_the_driver_makes() {
    use fixedgl::gl::*;
    let data: Vec<u8> = (0..16u32)
        .flat_map(|k| {
            ((((k * 0x0F_1234 + 0x3456) & 0xFF_FFFF) << 8) | ((k * 41) & 0xFF)).to_ne_bytes()
        })
        .collect();
    let Some((n, first)) = cpu_vs_gl(16, 1, |c| {
        c.tex_image_2d(
            TEXTURE_2D,
            0,
            DEPTH_COMPONENT as i32,
            4,
            4,
            0,
            DEPTH_STENCIL,
            UNSIGNED_INT_24_8,
            Some(&data),
        );
        c.pixel_transferf(DEPTH_SCALE, 0.5);
        c.pixel_transferf(DEPTH_BIAS, 0.25);
        c.tex_sub_image_2d(
            TEXTURE_2D,
            0,
            1,
            1,
            2,
            2,
            DEPTH_STENCIL,
            UNSIGNED_INT_24_8,
            &data,
        );
        c.pixel_transferf(DEPTH_SCALE, 1.0);
        c.pixel_transferf(DEPTH_BIAS, 0.0);
        draw_textured(c);
    }) else {
        return;
    };
    assert_eq!(n, 0, "{first}");
}

/// GetTexImage packs into the packed types field by field (§6.1.4 through §4.3.2, table 3.8):
/// an RGBA8 texture of known bytes read back as each packed type gives each field's rounding.
#[test]
fn get_tex_image_packs_the_packed_types() {
    use fixedgl::gl::*;
    let Ok(mut c) = Context::new(4, 4) else {
        panic!("CPU context")
    };
    let texel = [255u8, 0, 128, 64];
    c.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA8 as i32,
        1,
        1,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&texel),
    );
    let field = |v: u8, bits: u32| -> u32 {
        let max = f64::from((1u32 << bits) - 1);
        (f64::from(v) / 255.0 * max).round() as u32
    };
    let [r, g, b, a] = texel;
    let rows: [(u32, u32, u32); 5] = [
        (
            RGBA,
            UNSIGNED_SHORT_4_4_4_4,
            (field(r, 4) << 12) | (field(g, 4) << 8) | (field(b, 4) << 4) | field(a, 4),
        ),
        (
            BGRA,
            UNSIGNED_SHORT_1_5_5_5_REV,
            field(b, 5) | (field(g, 5) << 5) | (field(r, 5) << 10) | (field(a, 1) << 15),
        ),
        (
            RGB,
            UNSIGNED_SHORT_5_6_5,
            (field(r, 5) << 11) | (field(g, 6) << 5) | field(b, 5),
        ),
        (
            RGBA,
            UNSIGNED_INT_10_10_10_2,
            (field(r, 10) << 22) | (field(g, 10) << 12) | (field(b, 10) << 2) | field(a, 2),
        ),
        (
            ABGR_EXT,
            UNSIGNED_INT_8_8_8_8,
            (u32::from(a) << 24) | (u32::from(b) << 16) | (u32::from(g) << 8) | u32::from(r),
        ),
    ];
    for (format, ty, want) in rows {
        let mut out = [0u8; 4];
        c.get_tex_image(TEXTURE_2D, 0, format, ty, &mut out);
        assert_eq!(c.get_error(), NO_ERROR, "{format:#x} {ty:#x}");
        let got = match ty {
            UNSIGNED_INT_10_10_10_2 | UNSIGNED_INT_8_8_8_8 => u32::from_ne_bytes(out),
            _ => u32::from(u16::from_ne_bytes([out[0], out[1]])),
        };
        assert_eq!(got, want, "{format:#x} {ty:#x}");
    }
    // Errors: a mismatched packed type, and the index formats (§6.1.4).
    let mut out = [0u8; 16];
    for (format, ty, want) in [
        (RGB, UNSIGNED_SHORT_4_4_4_4, INVALID_OPERATION),
        (COLOR_INDEX, UNSIGNED_BYTE, INVALID_ENUM),
        (STENCIL_INDEX, UNSIGNED_BYTE, INVALID_ENUM),
        (COLOR_INDEX, BITMAP, INVALID_ENUM),
        (RGBA, BITMAP, INVALID_ENUM),
        // DEPTH_STENCIL only from a depth-stencil image (Mesa's format mismatch).
        (DEPTH_STENCIL, UNSIGNED_INT_24_8, INVALID_OPERATION),
    ] {
        c.get_tex_image(TEXTURE_2D, 0, format, ty, &mut out);
        assert_eq!(c.get_error(), want, "{format:#x} {ty:#x}");
    }
}

/// The current colour index (GL 2.1 §2.7): CURRENT_INDEX after each Index command, inside
/// Begin/End, from a display list, and across PushAttrib(CURRENT_BIT), as the driver answers;
/// an RGBA drawing is unchanged by it.
#[test]
fn index_commands_set_current_index_as_the_driver() {
    use fixedgl::gl::*;
    let Some(mut gl) = crate::common::test_backend(8, 8) else {
        return;
    };
    let Ok(mut cpu) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    let rows: &[(Call, f32)] = &[
        (Call::Indexf(2.5), 2.5),
        (Call::Indexi(-7), -7.0),
        (Call::Indexs(300), 300.0),
        (Call::Indexd(4.25), 4.25),
        (Call::Indexub(200), 200.0),
        (Call::Indexfv([6.0]), 6.0),
        (Call::Indexiv([9]), 9.0),
        (Call::Indexsv([-3]), -3.0),
        (Call::Indexdv([1.5]), 1.5),
        (Call::Indexubv([255]), 255.0),
        // Allowed between Begin and End.
        (Call::Begin(POINTS), 255.0),
        (Call::Indexf(11.0), 11.0),
        (Call::End, 11.0),
        // Pushed with CURRENT_BIT.
        (Call::PushAttrib(CURRENT_BIT), 11.0),
        (Call::Indexf(12.0), 12.0),
        (Call::PopAttrib, 11.0),
        // Compiled into a list, then executed from it.
        (Call::NewList(5, COMPILE), 11.0),
        (Call::Indexf(13.0), 11.0),
        (Call::EndList, 11.0),
        (Call::CallList(5), 13.0),
    ];
    let mut cpu_v = [0.0f32; 1];
    let mut gl_v = [0.0f32; 1];
    cpu.get_floatv(CURRENT_INDEX, &mut cpu_v);
    gl.get_floatv(CURRENT_INDEX, &mut gl_v);
    assert_eq!((cpu_v[0], gl_v[0]), (1.0, 1.0), "initial CURRENT_INDEX");
    for (i, (call, want)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        if i == 10 || i == 11 {
            continue; // no query between Begin and End
        }
        assert_eq!(cpu.get_error(), NO_ERROR, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), NO_ERROR, "GL after row {i}: {call:?}");
        cpu.get_floatv(CURRENT_INDEX, &mut cpu_v);
        gl.get_floatv(CURRENT_INDEX, &mut gl_v);
        assert_eq!(cpu_v[0], *want, "CPU after row {i}: {call:?}");
        assert_eq!(gl_v[0], *want, "GL after row {i}: {call:?}");
    }
    // No effect on RGBA drawing.
    let Some((n, first)) = cpu_vs_gl(8, 0, |c| {
        c.color3f(0.25, 0.5, 0.75);
        c.begin(TRIANGLES);
        c.indexf(3.0);
        c.vertex2f(-1.0, -1.0);
        c.indexi(0);
        c.vertex2f(1.0, -1.0);
        c.indexub(255);
        c.vertex2f(0.0, 1.0);
        c.end();
    }) else {
        return;
    };
    assert_eq!(n, 0, "{first}");
}
