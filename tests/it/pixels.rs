//! Pixel rectangles and bitmaps on the CPU alone (GL 2.1 §3.6, §3.7, §4.3): the behaviours the
//! driver comparison (`pixels_gl.rs`) stays clear of because llvmpipe departs from GL 2.1 there
//! (docs/conformance.md), each checked against values worked out from the spec; the errors that
//! leave everything unchanged; attribute groups; bounded work.

use fixedgl::{gl, Context};

/// A `w` x `h` context with a pixel-aligned projection, cleared to black.
fn ctx(w: u32, h: u32) -> Context {
    let mut c = Context::new(w, h).expect("context");
    c.matrix_mode(gl::PROJECTION);
    c.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    c.matrix_mode(gl::MODELVIEW);
    c
}

/// The RGBA bytes of pixel (x, y).
fn px(c: &mut Context, x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    c.read_pixels(x, y, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut p);
    p
}

/// Which pixels of row `y` (from x = 0, `n` of them) are not black.
fn row(c: &mut Context, y: i32, n: usize) -> Vec<bool> {
    let mut v = vec![0u8; n * 4];
    c.read_pixels(0, y, n as i32, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut v);
    v.chunks(4).map(|p| p[..3] != [0, 0, 0]).collect()
}

/// A one-row image of `n` groups, red channel 10, 20, 30, ... (alpha 255).
fn ramp(n: usize) -> Vec<u8> {
    (0..n)
        .flat_map(|i| [10 * (i as u8 + 1), 0, 0, 255])
        .collect()
}

#[test]
fn zoomed_groups_follow_section_3_6_5_at_ties() {
    // Zoom 0.5: every pixel centre lies on a group boundary; it belongs to the group whose left
    // boundary it is (§3.6.5): pixel 10 + k takes group 2k + 1.
    let mut c = ctx(32, 8);
    c.pixel_zoom(0.5, 1.0);
    c.window_pos2i(10, 2);
    c.draw_pixels(8, 1, gl::RGBA, gl::UNSIGNED_BYTE, &ramp(8));
    let reds: Vec<u8> = (9..15).map(|x| px(&mut c, x, 2)[0]).collect();
    assert_eq!(reds, [0, 20, 40, 60, 80, 0]);
    // Zoom -0.5 from 20: group k covers [20 − (k + 1)/2, 20 − k/2], its left boundary included:
    // pixel 19 (centre 19.5) takes group 0, pixel 16 group 6.
    let mut c = ctx(32, 8);
    c.pixel_zoom(-0.5, 1.0);
    c.window_pos2i(20, 2);
    c.draw_pixels(8, 1, gl::RGBA, gl::UNSIGNED_BYTE, &ramp(8));
    let reds: Vec<u8> = (15..21).map(|x| px(&mut c, x, 2)[0]).collect();
    assert_eq!(reds, [0, 70, 50, 30, 10, 0]);
    // Zoom 0.5 vertically over 3 rows from y = 2: the rectangle [2, 3.5) holds the centre 2.5
    // only (the top edge's 3.5 is outside), group 1.
    let mut c = ctx(8, 8);
    c.pixel_zoom(1.0, 0.5);
    c.window_pos2i(1, 2);
    let column: Vec<u8> = (0..3).flat_map(|j| [10 * (j + 1), 0, 0, 255]).collect();
    c.draw_pixels(1, 3, gl::RGBA, gl::UNSIGNED_BYTE, &column);
    let reds: Vec<u8> = (1..5).map(|y| px(&mut c, 1, y)[0]).collect();
    assert_eq!(reds, [0, 20, 0, 0]);
}

#[test]
fn pixel_rectangles_are_fogged_at_the_raster_distance() {
    // LINEAR fog (§3.10) of pixel rectangles uses the raster distance as the fog coordinate.
    let mut c = ctx(16, 16);
    c.enable(gl::FOG);
    c.fogi(gl::FOG_MODE, gl::LINEAR as i32);
    c.fogf(gl::FOG_START, 0.0);
    c.fogf(gl::FOG_END, 2.0);
    c.fogfv(gl::FOG_COLOR, &[0.0, 0.0, 1.0, 1.0]);
    // The eye distance of (2, 2, −1) is 3 (FOG_COORD_SRC FRAGMENT_DEPTH).
    c.raster_pos3f(2.0, 2.0, -1.0);
    let mut d = [0.0f32];
    c.get_floatv(gl::CURRENT_RASTER_DISTANCE, &mut d);
    assert_eq!(d, [3.0]);
    // f = (2 − 3) / 2 < 0 → 0: all fog colour.
    c.draw_pixels(2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &[255; 16]);
    assert_eq!(px(&mut c, 2, 2), [0, 0, 255, 255]);
    // FOG_END 12: f = (12 − 3) / 12 = 0.75: 0.75 · 255 = 191.25 → 191; blue 255.
    c.fogf(gl::FOG_END, 12.0);
    c.draw_pixels(2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &[255; 16]);
    assert_eq!(px(&mut c, 2, 2), [191, 191, 255, 255]);
}

#[test]
fn colour_indices_are_shifted_and_offset_before_the_lookup() {
    let mut c = ctx(8, 8);
    c.pixel_mapfv(
        gl::PIXEL_MAP_I_TO_R,
        8,
        &[0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 1.0],
    );
    c.pixel_mapfv(gl::PIXEL_MAP_I_TO_A, 1, &[1.0]);
    c.pixel_transferi(gl::INDEX_SHIFT, 1);
    c.pixel_transferi(gl::INDEX_OFFSET, 1);
    c.window_pos2i(0, 0);
    // Index 3 → 3·2 + 1 = 7 → I_TO_R[7 & 7] = 1.0; index 6 → 13 & 7 = 5 → 0.5 → 128.
    c.draw_pixels(2, 1, gl::COLOR_INDEX, gl::UNSIGNED_BYTE, &[3, 6, 0, 0]);
    assert_eq!(px(&mut c, 0, 0), [255, 0, 0, 255]);
    assert_eq!(px(&mut c, 1, 0), [128, 0, 0, 255]);
    // Negative shift: right.
    c.pixel_transferi(gl::INDEX_SHIFT, -2);
    c.pixel_transferi(gl::INDEX_OFFSET, 0);
    c.window_pos2i(2, 0);
    c.draw_pixels(1, 1, gl::COLOR_INDEX, gl::UNSIGNED_BYTE, &[13, 0, 0, 0]);
    // 13 >> 2 = 3 → 0.3 → 76 (the 8-bit conversion rounds 76.5 to even).
    assert_eq!(px(&mut c, 2, 0), [76, 0, 0, 255]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn colour_maps_map_every_component() {
    let mut c = ctx(8, 8);
    // Two-entry maps: below 0.5 → entry 0, above → entry 1 (§3.6.5 rounds c·(size − 1)).
    for (m, t) in [
        (gl::PIXEL_MAP_R_TO_R, [0.2, 0.8]),
        (gl::PIXEL_MAP_G_TO_G, [0.8, 0.2]),
        (gl::PIXEL_MAP_B_TO_B, [0.4, 0.6]),
        (gl::PIXEL_MAP_A_TO_A, [1.0, 0.0]),
    ] {
        c.pixel_mapfv(m, 2, &t);
    }
    c.pixel_transferi(gl::MAP_COLOR, 1);
    c.window_pos2i(0, 0);
    c.draw_pixels(1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &[0, 255, 0, 255]);
    // (ReadPixels maps too: off for the read.)
    c.pixel_transferi(gl::MAP_COLOR, 0);
    // 0.2 → 51, 0.2 → 51, 0.4 → 102, 0.0 → 0.
    assert_eq!(px(&mut c, 0, 0), [51, 51, 102, 0]);
}

#[test]
fn copy_pixels_applies_depth_scale_and_index_offset() {
    let mut c = ctx(16, 8);
    c.clear_depth(0.5);
    c.clear_stencil(3);
    c.clear(gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    c.enable(gl::DEPTH_TEST);
    c.depth_func(gl::ALWAYS);
    c.pixel_transferf(gl::DEPTH_SCALE, 0.5);
    c.pixel_transferf(gl::DEPTH_BIAS, 0.125);
    c.window_pos2i(8, 0);
    c.copy_pixels(0, 0, 4, 4, gl::DEPTH);
    // (ReadPixels scales depths too: back to the identity for the read.)
    c.pixel_transferf(gl::DEPTH_SCALE, 1.0);
    c.pixel_transferf(gl::DEPTH_BIAS, 0.0);
    // Pixel 7 untouched (0.5); pixel 8 0.5·0.5 + 0.125 = 0.375 (to 24-bit precision).
    let mut raw = [0u8; 8];
    c.read_pixels(7, 0, 2, 1, gl::DEPTH_COMPONENT, gl::FLOAT, &mut raw);
    let v: Vec<f32> = raw
        .chunks(4)
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert!(
        (v[0] - 0.5).abs() < 1e-6 && (v[1] - 0.375).abs() < 1e-6,
        "{v:?}"
    );
    c.pixel_transferi(gl::INDEX_OFFSET, 2);
    c.window_pos2i(8, 4);
    c.copy_pixels(0, 0, 4, 4, gl::STENCIL);
    let mut s = [0u8; 2];
    c.read_pixels(7, 4, 2, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut s);
    // ReadPixels applies the offset too: 3 + 2 = 5 untouched, (3 + 2) + 2 = 7 copied.
    assert_eq!(s, [5, 7]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn copy_pixels_depth_stencil_copies_both_buffers() {
    let mut c = ctx(16, 8);
    c.clear_depth(0.5);
    c.clear_stencil(3);
    c.clear(gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    // GL 3.0 §4.3.1: the depth and stencil tests are ignored.
    c.enable(gl::DEPTH_TEST);
    c.depth_func(gl::NEVER);
    c.enable(gl::STENCIL_TEST);
    c.stencil_func(gl::NEVER, 0, 0xFF);
    c.pixel_transferf(gl::DEPTH_BIAS, 0.125);
    c.pixel_transferi(gl::INDEX_OFFSET, 2);
    c.window_pos2i(8, 0);
    c.copy_pixels(0, 0, 4, 4, gl::DEPTH_STENCIL);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.pixel_transferf(gl::DEPTH_BIAS, 0.0);
    c.pixel_transferi(gl::INDEX_OFFSET, 0);
    // Pixel 7 untouched; pixel 8 copied through each buffer's own transfer.
    let mut raw = [0u8; 8];
    c.read_pixels(7, 0, 2, 1, gl::DEPTH_COMPONENT, gl::FLOAT, &mut raw);
    let v: Vec<f32> = raw
        .chunks(4)
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert!(
        (v[0] - 0.5).abs() < 1e-6 && (v[1] - 0.625).abs() < 1e-6,
        "{v:?}"
    );
    let mut s = [0u8; 2];
    c.read_pixels(7, 0, 2, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut s);
    assert_eq!(s, [3, 5]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    // Both buffers are needed: INVALID_OPERATION, nothing written.
    for (depth, stencil) in [(true, false), (false, true)] {
        let config = fixedgl::ContextConfig {
            depth,
            stencil,
            ..fixedgl::ContextConfig::default()
        };
        let mut c = fixedgl::Context::with_config(4, 4, config).expect("context");
        c.copy_pixels(0, 0, 1, 1, gl::DEPTH_STENCIL);
        assert_eq!(c.get_error(), gl::INVALID_OPERATION, "{depth} {stencil}");
    }
}

#[test]
fn stencil_indices_take_the_index_transfer() {
    let mut c = ctx(8, 4);
    c.pixel_transferi(gl::INDEX_SHIFT, 1);
    c.pixel_transferi(gl::INDEX_OFFSET, 1);
    c.window_pos2i(0, 0);
    // 3 → 7, 200 → 401 & 0xFF = 145.
    c.draw_pixels(2, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &[3, 200, 0, 0]);
    c.pixel_transferi(gl::INDEX_SHIFT, 0);
    c.pixel_transferi(gl::INDEX_OFFSET, 0);
    c.pixel_mapfv(gl::PIXEL_MAP_S_TO_S, 4, &[9.0, 8.0, 7.0, 6.0]);
    c.pixel_transferi(gl::MAP_STENCIL, 1);
    c.window_pos2i(2, 0);
    // 5 & 3 = 1 → 8; 2 → 7.
    c.draw_pixels(2, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &[5, 2, 0, 0]);
    c.pixel_transferi(gl::MAP_STENCIL, 0);
    let mut s = [0u8; 4];
    c.read_pixels(0, 0, 4, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut s);
    assert_eq!(s, [7, 145, 8, 7]);
}

#[test]
fn colour_index_bitmaps_use_the_row_alignment() {
    // Rows of 9 bits: 2 bytes, padded to 4 by UNPACK_ALIGNMENT 4.
    let mut c = ctx(16, 4);
    c.pixel_mapfv(gl::PIXEL_MAP_I_TO_R, 2, &[0.0, 1.0]);
    c.pixel_mapfv(gl::PIXEL_MAP_I_TO_A, 1, &[1.0]);
    c.window_pos2i(0, 0);
    c.draw_pixels(
        9,
        2,
        gl::COLOR_INDEX,
        gl::BITMAP,
        &[0x80, 0x80, 0, 0, 0x40, 0x00, 0, 0],
    );
    assert_eq!(
        row(&mut c, 0, 9),
        [true, false, false, false, false, false, false, false, true]
    );
    assert_eq!(
        row(&mut c, 1, 9),
        [false, true, false, false, false, false, false, false, false]
    );
}

#[test]
fn stencil_bitmaps_and_reads() {
    let mut c = ctx(16, 4);
    c.window_pos2i(0, 0);
    c.draw_pixels(
        10,
        1,
        gl::STENCIL_INDEX,
        gl::BITMAP,
        &[0b1010_0000, 0b0100_0000, 0, 0],
    );
    let mut s = [0u8; 10];
    c.read_pixels(0, 0, 10, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut s);
    assert_eq!(s, [1, 0, 1, 0, 0, 0, 0, 0, 0, 1]);
    // Packed back to bits, least significant bit first: bits 0, 2, 9.
    c.pixel_storei(gl::PACK_LSB_FIRST, 1);
    let mut b = [0xFFu8; 2];
    c.read_pixels(0, 0, 10, 1, gl::STENCIL_INDEX, gl::BITMAP, &mut b);
    assert_eq!(b, [0b0000_0101, 0b1111_1110]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn errors_change_nothing() {
    let mut c = ctx(8, 8);
    c.window_pos2i(1, 1);
    let before = c.state().clone();
    let image = c.to_image();
    // A slice shorter than the image under the unpack modes: INVALID_OPERATION.
    c.draw_pixels(2, 2, gl::RGB, gl::UNSIGNED_BYTE, &[255; 13]);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    // Rows of 2 bytes padded to 4: 4 + 2 bytes needed.
    c.bitmap(9, 2, 0.0, 0.0, 1.0, 1.0, Some(&[255; 5]));
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    // Format and type.
    c.draw_pixels(1, 1, gl::RGBA, gl::UNSIGNED_SHORT_5_6_5, &[255; 8]);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.draw_pixels(1, 1, gl::RGBA, gl::BITMAP, &[255; 8]);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.draw_pixels(1, 1, 0x8227, gl::UNSIGNED_BYTE, &[255; 8]); // RG: GL 3.0
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.draw_pixels(-1, 1, gl::TRIANGLES, gl::UNSIGNED_BYTE, &[255; 8]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.copy_pixels(0, 0, 2, 2, gl::RGBA);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.pixel_transferf(gl::ZOOM_X, 2.0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.pixel_mapfv(gl::PIXEL_MAP_I_TO_R, 3, &[0.5; 3]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 257, &[0.5; 300]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R + 10, 1, &[0.5]);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    let mut short = [0f32; 1];
    c.pixel_mapfv(gl::PIXEL_MAP_G_TO_G, 1, &[0.5]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let mut values = [0f32; 2];
    c.get_pixel_mapfv(gl::PIXEL_MAP_G_TO_G, &mut values);
    assert_eq!(values, [0.5, 0.0]);
    c.pixel_mapfv(gl::PIXEL_MAP_G_TO_G, 2, &[0.25, 0.75]);
    c.get_pixel_mapfv(gl::PIXEL_MAP_G_TO_G, &mut short);
    assert_eq!((c.get_error(), short), (gl::INVALID_VALUE, [0.0]));
    // Undo the two valid maps, then everything is as it was.
    c.pixel_mapfv(gl::PIXEL_MAP_G_TO_G, 1, &[0.0]);
    assert_eq!(c.state(), &before);
    assert_eq!(c.to_image(), image);
}

#[test]
fn an_invalid_raster_position_draws_nothing() {
    let mut c = ctx(8, 8);
    c.raster_pos2f(100.0, 0.0);
    assert!(!c.state().raster_pos.valid);
    let image = c.to_image();
    c.draw_pixels(2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &[255; 16]);
    c.bitmap(8, 1, 0.0, 0.0, 5.0, 5.0, Some(&[0xFF]));
    c.copy_pixels(0, 0, 2, 2, gl::COLOR);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(c.to_image(), image);
    // Bitmap did not move it either.
    assert_eq!(c.state().raster_pos.window.x, 0.0);
}

#[test]
fn pixel_maps_are_in_no_attribute_group() {
    let mut c = ctx(8, 8);
    c.push_attrib(gl::ALL_ATTRIB_BITS);
    c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 2, &[0.25, 0.75]);
    c.pixel_zoom(2.0, 3.0);
    c.pixel_transferi(gl::MAP_COLOR, 1);
    c.pop_attrib();
    let mut size = [0];
    c.get_integerv(gl::PIXEL_MAP_R_TO_R_SIZE, &mut size);
    let mut z = [0.0f32; 1];
    c.get_floatv(gl::ZOOM_X, &mut z);
    let mut m = [true];
    c.get_booleanv(gl::MAP_COLOR, &mut m);
    assert_eq!((size, z, m), ([2], [1.0], [false]));
}

#[test]
fn work_is_bounded_by_the_window() {
    // A million groups drawn mostly outside a 16x16 window, a huge zoom, a huge source rectangle:
    // each converts only the groups some window pixel takes.
    let mut c = ctx(16, 16);
    let wide = vec![200u8; 1 << 20];
    c.window_pos2i(-1000, 3);
    c.draw_pixels(1 << 20, 1, gl::LUMINANCE, gl::UNSIGNED_BYTE, &wide);
    c.pixel_zoom(1.0e6, 1.0e6);
    c.window_pos2i(2, 2);
    c.draw_pixels(2, 1, gl::LUMINANCE, gl::UNSIGNED_BYTE, &[50, 100]);
    c.pixel_zoom(1.0, 1.0);
    c.copy_pixels(0, 0, i32::MAX, i32::MAX, gl::COLOR);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(px(&mut c, 15, 15), [50, 50, 50, 255]);
}

#[test]
fn the_plain_and_full_fragment_paths_agree() {
    // With nothing but the colour write after it, DrawPixels converts the groups to 8 bits
    // itself; with a depth test that always passes and writes nothing, every fragment takes the
    // full sequence. The pixels must be the same for every transfer and format.
    let data: Vec<u8> = (0..24 * 10 * 8)
        .map(|k: usize| (k * 37 + k / 3) as u8)
        .collect();
    type Setup = fn(&mut Context);
    let transfers: [Setup; 4] = [
        |_| {},
        |c| {
            c.pixel_transferf(gl::RED_SCALE, 0.6);
            c.pixel_transferf(gl::BLUE_BIAS, 0.3);
            c.pixel_transferf(gl::ALPHA_SCALE, -1.0);
            c.pixel_transferf(gl::ALPHA_BIAS, 1.0);
        },
        |c| {
            c.pixel_mapfv(gl::PIXEL_MAP_G_TO_G, 4, &[0.9, 0.1, 0.6, 0.3]);
            c.pixel_transferi(gl::MAP_COLOR, 1);
        },
        |c| c.pixel_zoom(-1.5, 2.0),
    ];
    for (k, transfer) in transfers.iter().enumerate() {
        for (format, ty) in [
            (gl::RGBA, gl::UNSIGNED_BYTE),
            (gl::LUMINANCE_ALPHA, gl::UNSIGNED_BYTE),
            (gl::BGR, gl::UNSIGNED_BYTE),
            (gl::RGBA, gl::UNSIGNED_SHORT),
            (gl::RGB, gl::UNSIGNED_SHORT_5_6_5),
        ] {
            let draw = |full: bool| {
                let mut c = ctx(64, 32);
                transfer(&mut c);
                if full {
                    c.enable(gl::DEPTH_TEST);
                    c.depth_func(gl::ALWAYS);
                    c.depth_mask(false);
                }
                c.window_pos2i(40, 4);
                c.draw_pixels(24, 10, format, ty, &data);
                // The read must not go through the transfer under test.
                c.pixel_transferi(gl::MAP_COLOR, 0);
                for p in [gl::RED_SCALE, gl::ALPHA_SCALE] {
                    c.pixel_transferf(p, 1.0);
                }
                for p in [gl::BLUE_BIAS, gl::ALPHA_BIAS] {
                    c.pixel_transferf(p, 0.0);
                }
                assert_eq!(c.get_error(), gl::NO_ERROR);
                c.to_image()
            };
            assert_eq!(draw(false), draw(true), "transfer {k}, {format:#x}/{ty:#x}");
        }
    }
}
