//! Pixel rectangles and bitmaps against the real driver (GL 2.1 §3.6, §3.7, §4.3): DrawPixels of
//! every format and type under the unpack modes, zoomed, through scale and bias, colour maps and
//! the fragment operations; Bitmap with its unpack modes and raster moves; CopyPixels of colour,
//! depth and stencil; ReadPixels through the transfer; PixelMap and GetPixelMap; and the errors of
//! each, pixel for pixel and byte for byte.
//!
//! Where llvmpipe departs from GL 2.1 (docs/conformance.md lists each, measured) the cases here
//! stay clear of it: no pixel centre on a zoomed rectangle's edge or on a group boundary, no
//! fog on pixel rectangles, colour maps only with B = R and A = G images, no INDEX_SHIFT or
//! INDEX_OFFSET with COLOR_INDEX, no STENCIL_INDEX bitmaps; `tests/it/pixels.rs` checks the GL
//! 2.1 behaviour there on the CPU alone. Skipped (with `SKIPPED:` on stderr) where no EGL device
//! exists.
#![cfg(feature = "gl")]

use crate::common::test_backend;
use fixedgl::{gl, Context};

/// A labelled sequence of calls.
type Named = (&'static str, fn(&mut Context));

/// Draws `f` on both backends under a pixel-aligned ortho projection and returns the pixels
/// whose largest channel difference exceeds `tol`, the largest difference and both errors; None
/// when GL is unavailable.
fn compare(w: u32, h: u32, tol: u8, f: impl FnOnce(&mut Context)) -> Option<(usize, u8, u32, u32)> {
    let mut drv = test_backend(w, h)?;
    let mut cpu = Context::new(w, h).expect("context");
    cpu.start_recording();
    cpu.matrix_mode(gl::PROJECTION);
    cpu.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    cpu.matrix_mode(gl::MODELVIEW);
    f(&mut cpu);
    drv.replay(&cpu.stop_recording());
    let (a, b) = (cpu.to_image(), drv.read_image());
    let (mut n, mut max) = (0, 0u8);
    for (p, q) in a.pixels().zip(b.pixels()) {
        let d = (0..4).map(|k| p.0[k].abs_diff(q.0[k])).max().unwrap_or(0);
        n += usize::from(d > tol);
        max = max.max(d);
    }
    Some((n, max, cpu.get_error(), drv.get_error()))
}

/// Asserts that `f` draws the same pixels (within `tol`) with no error on both backends.
#[track_caller]
fn same(label: &str, w: u32, h: u32, tol: u8, f: impl FnOnce(&mut Context)) {
    if let Some((n, max, a, b)) = compare(w, h, tol, f) {
        assert_eq!((a, b), (gl::NO_ERROR, gl::NO_ERROR), "{label}: errors");
        assert_eq!(
            n, 0,
            "{label}: {n} pixels differ by more than {tol} (max {max})"
        );
    }
}

/// A `w` x `h` RGBA8 image with every channel varying.
fn image(w: usize, h: usize) -> Vec<u8> {
    let mut v = Vec::with_capacity(w * h * 4);
    for j in 0..h {
        for i in 0..w {
            v.extend_from_slice(&[
                (i * 7 + j * 3) as u8,
                ((i * 13) ^ (j * 5)) as u8,
                (200 - i - j) as u8,
                (255 - (i * j) % 256) as u8,
            ]);
        }
    }
    v
}

#[test]
fn zoomed_images_land_on_the_drivers_pixels() {
    // 21 rows: every vertical zoom below spans a whole number of pixels (llvmpipe, drawing into
    // a framebuffer object, shifts a rectangle whose top edge is not on a pixel boundary).
    let img = image(37, 21);
    // Zoom factors whose group edges never meet a pixel centre from an integer raster
    // position: integers, and fractions with odd denominators (see the module docs).
    for (zx, zy, x, y) in [
        (1.0, 1.0, 5.0, 6.0),
        (2.0, 2.0, 5.0, 6.0),
        (-1.0, 1.0, 60.0, 6.0),
        (1.0, -1.0, 5.0, 40.0),
        (-2.0, -2.0, 90.0, 70.0),
        (3.0, -1.0, 2.0, 30.0),
        (4.0 / 3.0, 2.0 / 3.0, 5.5, 40.4),
        (-4.0 / 3.0, -2.0 / 3.0, 80.4, 60.0),
        (1.0, 1.0, 5.49, 6.51),
        (1.0, 1.0, 5.5, -6.5),
        (1.0, 1.0, -10.0, 70.0),
    ] {
        let img = img.clone();
        same(
            &format!("zoom ({zx}, {zy}) at ({x}, {y})"),
            100,
            80,
            0,
            move |c| {
                c.pixel_zoom(zx, zy);
                c.window_pos2f(x, y);
                c.draw_pixels(37, 21, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            },
        );
    }
}

#[test]
fn every_format_and_type_unpacks_as_the_driver() {
    // (format, type, bytes per pixel, tolerance): 1 where llvmpipe converts differently
    // (signed types as c/127, 5- and 6-bit fields by bit replication; docs/conformance.md).
    let cases = [
        (gl::RGBA, gl::UNSIGNED_BYTE, 4, 0),
        (gl::RGB, gl::UNSIGNED_BYTE, 3, 0),
        (gl::BGRA, gl::UNSIGNED_BYTE, 4, 0),
        (gl::BGR, gl::UNSIGNED_BYTE, 3, 0),
        (gl::RED, gl::UNSIGNED_BYTE, 1, 0),
        (gl::GREEN, gl::UNSIGNED_BYTE, 1, 0),
        (gl::BLUE, gl::UNSIGNED_BYTE, 1, 0),
        (gl::ALPHA, gl::UNSIGNED_BYTE, 1, 0),
        (gl::LUMINANCE, gl::UNSIGNED_BYTE, 1, 0),
        (gl::LUMINANCE_ALPHA, gl::UNSIGNED_BYTE, 2, 0),
        (gl::RGBA, gl::UNSIGNED_SHORT, 8, 0),
        (gl::RGB, gl::UNSIGNED_INT, 12, 0),
        (gl::RGBA, gl::BYTE, 4, 1),
        (gl::RGB, gl::SHORT, 6, 0),
        (gl::LUMINANCE_ALPHA, gl::INT, 8, 0),
        (gl::RGB, gl::UNSIGNED_BYTE_3_3_2, 1, 0),
        (gl::RGB, gl::UNSIGNED_BYTE_2_3_3_REV, 1, 0),
        (gl::RGB, gl::UNSIGNED_SHORT_5_6_5, 2, 1),
        (gl::RGB, gl::UNSIGNED_SHORT_5_6_5_REV, 2, 1),
        (gl::RGBA, gl::UNSIGNED_SHORT_4_4_4_4, 2, 0),
        (gl::BGRA, gl::UNSIGNED_SHORT_4_4_4_4_REV, 2, 0),
        (gl::RGBA, gl::UNSIGNED_SHORT_5_5_5_1, 2, 1),
        (gl::BGRA, gl::UNSIGNED_SHORT_1_5_5_5_REV, 2, 1),
        (gl::RGBA, gl::UNSIGNED_INT_8_8_8_8, 4, 0),
        (gl::BGRA, gl::UNSIGNED_INT_8_8_8_8_REV, 4, 0),
        (gl::RGBA, gl::UNSIGNED_INT_10_10_10_2, 4, 0),
        (gl::BGRA, gl::UNSIGNED_INT_2_10_10_10_REV, 4, 0),
    ];
    for (format, ty, bpp, tol) in cases {
        let data: Vec<u8> = (0..20 * 10 * bpp).map(|k| (k * 37 + k / 7) as u8).collect();
        same(&format!("{format:#x}/{ty:#x}"), 64, 32, tol, move |c| {
            c.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
            c.raster_pos2i(3, 4);
            c.draw_pixels(20, 10, format, ty, &data);
        });
    }
    let floats: Vec<u8> = (0..20 * 10 * 4)
        .flat_map(|k: usize| (((k * 37) % 101) as f32 / 100.0).to_ne_bytes())
        .collect();
    same("RGBA/FLOAT", 64, 32, 0, move |c| {
        c.raster_pos2i(3, 4);
        c.draw_pixels(20, 10, gl::RGBA, gl::FLOAT, &floats);
    });
}

#[test]
fn unpack_modes_place_the_groups_as_the_drivers() {
    let data: Vec<u8> = (0..4096).map(|k: usize| (k * 29 + k / 5) as u8).collect();
    // SWAP_BYTES is not combined with skips: llvmpipe applies the skips twice then
    // (docs/conformance.md, "UNPACK_SWAP_BYTES with UNPACK_SKIP_ROWS").
    let modes: [(i32, i32, i32, i32, i32); 4] = [
        // (row length, skip rows, skip pixels, alignment, swap bytes)
        (0, 0, 0, 4, 0),
        (31, 2, 3, 8, 0),
        (0, 0, 0, 2, 1),
        (25, 0, 0, 1, 1),
    ];
    for (row, rows, pixels, align, swap) in modes {
        for (format, ty) in [
            (gl::RGB, gl::UNSIGNED_BYTE),
            (gl::RGBA, gl::UNSIGNED_SHORT),
            (gl::RGB, gl::UNSIGNED_SHORT_5_6_5),
            (gl::LUMINANCE, gl::FLOAT),
        ] {
            let data = data.clone();
            let label = format!(
                "{format:#x}/{ty:#x} under {:?}",
                (row, rows, pixels, align, swap)
            );
            // Floats from arbitrary bytes can be NaN: colours only from whole bytes then.
            let tol = if ty == gl::FLOAT { 255 } else { 1 };
            same(&label, 48, 32, tol, move |c| {
                c.pixel_storei(gl::UNPACK_ROW_LENGTH, row);
                c.pixel_storei(gl::UNPACK_SKIP_ROWS, rows);
                c.pixel_storei(gl::UNPACK_SKIP_PIXELS, pixels);
                c.pixel_storei(gl::UNPACK_ALIGNMENT, align);
                c.pixel_storei(gl::UNPACK_SWAP_BYTES, swap);
                c.raster_pos2i(2, 3);
                c.draw_pixels(17, 9, format, ty, &data);
            });
        }
    }
}

#[test]
fn scale_bias_and_colour_maps_match_the_driver() {
    let img = image(37, 23);
    let i2 = img.clone();
    // Scales and biases whose results never fall on a rounding tie of the 8-bit conversion.
    same("scale and bias", 100, 80, 0, move |c| {
        c.pixel_transferf(gl::RED_SCALE, 0.8);
        c.pixel_transferf(gl::GREEN_BIAS, 0.05);
        c.pixel_transferf(gl::BLUE_SCALE, 0.3);
        c.pixel_transferf(gl::BLUE_BIAS, 0.31);
        c.pixel_transferf(gl::ALPHA_SCALE, 0.9);
        c.pixel_transferf(gl::ALPHA_BIAS, 0.003);
        c.raster_pos2i(5, 6);
        c.draw_pixels(37, 23, gl::RGBA, gl::UNSIGNED_BYTE, &i2);
    });
    // Colour maps of 256 entries, red and green written only: llvmpipe's blue and alpha come
    // out wrong under MAP_COLOR (docs/conformance.md).
    same("colour maps", 100, 80, 0, move |c| {
        let wave: Vec<f32> = (0..256)
            .map(|k| ((k as f32 / 255.0) * 3.0).fract())
            .collect();
        let inverse: Vec<u16> = (0..256).map(|k| 65535 - k * 257).collect();
        c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 256, &wave);
        c.pixel_mapusv(gl::PIXEL_MAP_G_TO_G, 256, &inverse);
        c.pixel_transferi(gl::MAP_COLOR, 1);
        c.color_mask(true, true, false, false);
        c.raster_pos2i(5, 6);
        c.draw_pixels(37, 23, gl::RGBA, gl::UNSIGNED_BYTE, &img);
    });
    same("colour index through I_TO_R/G/B/A", 64, 32, 0, |c| {
        c.pixel_mapfv(gl::PIXEL_MAP_I_TO_R, 4, &[0.0, 0.3, 0.6, 1.0]);
        c.pixel_mapfv(gl::PIXEL_MAP_I_TO_G, 2, &[0.2, 0.8]);
        c.pixel_mapuiv(gl::PIXEL_MAP_I_TO_B, 1, &[u32::MAX / 2]);
        c.pixel_mapfv(gl::PIXEL_MAP_I_TO_A, 1, &[1.0]);
        c.raster_pos2i(3, 4);
        let d: Vec<u8> = (0..200).map(|k| k as u8).collect();
        c.draw_pixels(20, 10, gl::COLOR_INDEX, gl::UNSIGNED_BYTE, &d);
        let s: Vec<u8> = (0..200u16).flat_map(|k| (k * 3).to_ne_bytes()).collect();
        c.raster_pos2i(30, 20);
        c.draw_pixels(20, 5, gl::COLOR_INDEX, gl::UNSIGNED_SHORT, &s);
        // A one-row COLOR_INDEX bitmap.
        c.raster_pos2i(3, 25);
        c.draw_pixels(
            16,
            1,
            gl::COLOR_INDEX,
            gl::BITMAP,
            &[0b1100_0000, 0b0000_0001],
        );
    });
}

#[test]
fn bitmaps_match_the_driver() {
    let bits: Vec<u8> = (0..200).map(|k: usize| (k * 91 + 7) as u8).collect();
    let b2 = bits.clone();
    same(
        "bitmap at a fractional raster position, moved",
        64,
        32,
        0,
        move |c| {
            c.color3f(1.0, 0.5, 0.25);
            c.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
            c.raster_pos2f(10.3, 5.7);
            c.bitmap(13, 10, 2.5, 1.0, 20.0, 0.5, Some(&b2));
            c.bitmap(13, 10, 0.0, 0.0, 0.0, 0.0, Some(&b2));
            // Partly outside the window, and with a negative origin.
            c.window_pos2i(58, 27);
            c.bitmap(13, 10, -1.0, 0.0, 0.0, 0.0, Some(&b2));
            c.window_pos2i(-5, -4);
            c.bitmap(13, 10, 0.0, 0.0, 0.0, 0.0, Some(&b2));
        },
    );
    same("LSB_FIRST, skips, row length", 64, 32, 0, move |c| {
        c.color3f(0.0, 0.5, 1.0);
        c.pixel_storei(gl::UNPACK_LSB_FIRST, 1);
        c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 3);
        c.pixel_storei(gl::UNPACK_SKIP_ROWS, 2);
        c.pixel_storei(gl::UNPACK_ROW_LENGTH, 30);
        c.raster_pos2i(10, 5);
        c.bitmap(17, 9, 0.0, 0.0, 0.0, 0.0, Some(&bits));
        c.pixel_storei(gl::UNPACK_LSB_FIRST, 0);
        c.pixel_storei(gl::UNPACK_ALIGNMENT, 8);
        c.color3f(1.0, 1.0, 1.0);
        c.raster_pos2i(35, 12);
        c.bitmap(17, 9, 0.0, 0.0, 0.0, 0.0, Some(&bits));
    });
    same(
        "bitmap fragments through the fragment operations",
        64,
        32,
        0,
        |c| {
            let ones = [0xFFu8; 64];
            c.enable(gl::DEPTH_TEST);
            c.color3f(1.0, 0.0, 0.0);
            c.rectf(0.0, 0.0, 32.0, 32.0);
            c.enable(gl::BLEND);
            c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
            c.color4f(0.0, 1.0, 0.0, 0.6);
            // z -0.5 (window 0.25): in front of the rectangle; then behind it.
            c.raster_pos3f(8.0, 8.0, -0.5);
            c.bitmap(32, 16, 0.0, 0.0, 0.0, 0.0, Some(&ones));
            c.color4f(0.0, 0.0, 1.0, 1.0);
            c.raster_pos3f(8.0, 20.0, 0.5);
            c.bitmap(32, 8, 0.0, 0.0, 0.0, 0.0, Some(&ones));
        },
    );
}

#[test]
fn depth_and_stencil_rectangles_match_the_driver() {
    let depths: Vec<u8> = (0..200)
        .flat_map(|k| ((k % 20) as f32 / 20.0 + 0.013).to_ne_bytes())
        .collect();
    let d2 = depths.clone();
    same(
        "DEPTH_COMPONENT against a plane, depth test on and off",
        64,
        32,
        0,
        move |c| {
            c.enable(gl::DEPTH_TEST);
            c.color3f(1.0, 0.0, 0.0);
            c.rectf(0.0, 0.0, 64.0, 32.0);
            c.color3f(0.0, 1.0, 0.0);
            c.raster_pos2i(4, 4);
            c.draw_pixels(20, 10, gl::DEPTH_COMPONENT, gl::FLOAT, &d2);
            // Depth test off: colour only, the depth buffer untouched (§4.1.6).
            c.disable(gl::DEPTH_TEST);
            c.color3f(0.0, 0.0, 1.0);
            c.raster_pos2i(30, 4);
            c.draw_pixels(20, 10, gl::DEPTH_COMPONENT, gl::FLOAT, &d2);
            c.enable(gl::DEPTH_TEST);
            c.color3f(1.0, 1.0, 0.0);
            c.rectf(28.0, 0.0, 64.0, 32.0);
        },
    );
    same(
        "DEPTH_COMPONENT as UNSIGNED_SHORT, zoomed, DEPTH_SCALE and BIAS",
        64,
        32,
        0,
        |c| {
            let d: Vec<u8> = (0..120u32)
                .flat_map(|k| ((k * 523) as u16).to_ne_bytes())
                .collect();
            c.enable(gl::DEPTH_TEST);
            c.depth_func(gl::ALWAYS);
            c.pixel_transferf(gl::DEPTH_SCALE, 0.5);
            c.pixel_transferf(gl::DEPTH_BIAS, 0.2);
            c.pixel_zoom(2.0, 2.0);
            c.raster_pos2i(2, 2);
            c.draw_pixels(12, 10, gl::DEPTH_COMPONENT, gl::UNSIGNED_SHORT, &d);
            c.depth_func(gl::LESS);
            c.color3f(1.0, 1.0, 1.0);
            c.rectf(0.0, 0.0, 64.0, 32.0);
        },
    );
    // llvmpipe's DrawPixels(STENCIL_INDEX) ignores the index transfer (docs/conformance.md):
    // the write mask only here, the transfer in tests/it/pixels.rs.
    same(
        "STENCIL_INDEX, zoomed, and through the write mask",
        64,
        32,
        0,
        |c| {
            let d: Vec<u8> = (0..200).map(|k| (k % 7) as u8).collect();
            c.raster_pos2i(4, 4);
            c.draw_pixels(20, 10, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &d);
            c.pixel_zoom(1.0, 2.0);
            c.stencil_mask(0x03);
            c.raster_pos2i(30, 10);
            c.draw_pixels(20, 10, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &d);
            c.stencil_mask(0xFF);
            c.enable(gl::STENCIL_TEST);
            for (v, col) in [
                (1, [1.0, 1.0, 0.0]),
                (2, [0.0, 1.0, 1.0]),
                (3, [1.0, 0.0, 1.0]),
            ] {
                c.stencil_func(gl::EQUAL, v, 0xFF);
                c.color3f(col[0], col[1], col[2]);
                c.rectf(0.0, 0.0, 64.0, 32.0);
            }
        },
    );
}

#[test]
fn copy_pixels_matches_the_driver() {
    let img = image(37, 23);
    same(
        "COLOR: flipped, zoomed, scaled, overlapping",
        100,
        80,
        0,
        move |c| {
            c.raster_pos2i(5, 6);
            c.draw_pixels(37, 23, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.raster_pos2i(50, 40);
            c.pixel_zoom(1.0, -1.0);
            c.copy_pixels(10, 10, 20, 15, gl::COLOR);
            c.pixel_zoom(2.0, 1.0);
            c.pixel_transferf(gl::RED_SCALE, 0.8);
            c.pixel_transferf(gl::BLUE_BIAS, 0.05);
            c.raster_pos2i(40, 3);
            c.copy_pixels(0, 0, 30, 30, gl::COLOR);
            // Onto itself, shifted by one pixel: read whole before written.
            c.pixel_zoom(1.0, 1.0);
            c.pixel_transferf(gl::RED_SCALE, 1.0);
            c.pixel_transferf(gl::BLUE_BIAS, 0.0);
            c.raster_pos2i(6, 7);
            c.copy_pixels(5, 6, 30, 20, gl::COLOR);
            // A source partly outside the window.
            c.raster_pos2i(70, 50);
            c.copy_pixels(-10, -5, 25, 25, gl::COLOR);
        },
    );
    same("DEPTH", 64, 32, 0, |c| {
        c.enable(gl::DEPTH_TEST);
        c.color3f(1.0, 0.0, 0.0);
        c.begin(gl::TRIANGLES);
        c.vertex3f(0.0, 0.0, -0.9);
        c.vertex3f(40.0, 0.0, 0.5);
        c.vertex3f(0.0, 30.0, 0.9);
        c.end();
        c.depth_func(gl::ALWAYS);
        c.color3f(0.0, 1.0, 0.0);
        c.raster_pos2i(30, 2);
        c.copy_pixels(0, 0, 20, 20, gl::DEPTH);
        c.depth_func(gl::LESS);
        c.color3f(0.0, 0.0, 1.0);
        c.rectf(25.0, 0.0, 64.0, 32.0);
    });
    same("STENCIL, zoomed", 64, 32, 0, |c| {
        let d: Vec<u8> = (0..200).map(|k| (k % 5) as u8).collect();
        c.raster_pos2i(4, 4);
        c.draw_pixels(20, 10, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &d);
        c.raster_pos2i(30, 10);
        c.pixel_zoom(1.0, 2.0);
        c.copy_pixels(4, 4, 20, 10, gl::STENCIL);
        c.enable(gl::STENCIL_TEST);
        c.stencil_func(gl::EQUAL, 2, 0xFF);
        c.color3f(1.0, 1.0, 0.0);
        c.rectf(0.0, 0.0, 64.0, 32.0);
    });
    // GL_EXT_packed_depth_stencil: both buffers copied and written as GL 3.0 §4.3.1 says: the
    // depth and stencil tests and the stencil operations (all set to change things here) are
    // ignored; the scissor box, the stencil write mask and DepthMask hold. Zoomed and
    // overlapping, llvmpipe draws it with a stencil-exporting shader; unzoomed and apart, it
    // blits (which honours the scissor box but not the write masks: those stay at their
    // defaults there). The transfer stays the identity (llvmpipe ignores it, see the docs).
    let scene = |c: &mut Context| {
        c.enable(gl::DEPTH_TEST);
        c.enable(gl::STENCIL_TEST);
        c.stencil_op(gl::KEEP, gl::KEEP, gl::REPLACE);
        c.stencil_func(gl::ALWAYS, 3, 0xFF);
        c.color3f(1.0, 0.0, 0.0);
        c.begin(gl::TRIANGLES);
        c.vertex3f(0.0, 0.0, -0.9);
        c.vertex3f(40.0, 0.0, 0.5);
        c.vertex3f(0.0, 30.0, 0.9);
        c.end();
        c.stencil_func(gl::ALWAYS, 7, 0xFF);
        c.rectf(20.0, 5.0, 30.0, 25.0);
        c.stencil_func(gl::EQUAL, 3, 0xFF);
        c.stencil_op(gl::INCR, gl::INCR, gl::DECR);
        c.depth_func(gl::LESS);
        c.color3f(0.0, 1.0, 0.0);
    };
    // What the buffers hold, shown in colour: a rectangle for each stencil value, then a quad
    // at depth 0.5 where the stored depth is less.
    let show = |c: &mut Context| {
        c.disable(gl::SCISSOR_TEST);
        c.stencil_mask(0xFF);
        c.stencil_op(gl::KEEP, gl::KEEP, gl::KEEP);
        c.depth_func(gl::ALWAYS);
        c.depth_mask(false);
        for (k, col) in [
            (1, [0.5, 0.0, 0.0]),
            (2, [0.5, 0.5, 0.5]),
            (3, [0.0, 0.0, 1.0]),
            (4, [1.0, 1.0, 0.0]),
            (5, [0.0, 0.0, 0.5]),
            (6, [0.0, 0.5, 0.0]),
            (7, [1.0, 0.0, 1.0]),
        ] {
            c.stencil_func(gl::EQUAL, k, 0xFF);
            c.color3f(col[0], col[1], col[2]);
            c.rectf(0.0, 0.0, 64.0, 32.0);
        }
        c.disable(gl::STENCIL_TEST);
        c.depth_func(gl::GREATER);
        c.color3f(0.0, 1.0, 1.0);
        c.begin(gl::QUADS);
        c.vertex3f(0.0, 0.0, 0.0);
        c.vertex3f(64.0, 0.0, 0.0);
        c.vertex3f(64.0, 32.0, 0.0);
        c.vertex3f(0.0, 32.0, 0.0);
        c.end();
    };
    same(
        "DEPTH_STENCIL, zoomed, overlapping, masked",
        64,
        32,
        0,
        |c| {
            scene(c);
            c.raster_pos2i(6, 3);
            c.pixel_zoom(2.0, 1.0);
            c.stencil_mask(0x05);
            c.copy_pixels(0, 0, 28, 24, gl::DEPTH_STENCIL);
            // DepthMask FALSE: only the indices (all bits) move.
            c.stencil_mask(0xFF);
            c.depth_mask(false);
            c.pixel_zoom(1.0, 2.0);
            c.raster_pos2i(40, 2);
            c.copy_pixels(10, 4, 12, 14, gl::DEPTH_STENCIL);
            c.pixel_zoom(1.0, 1.0);
            show(c);
        },
    );
    same("DEPTH_STENCIL, unzoomed, scissored", 64, 32, 0, |c| {
        scene(c);
        c.enable(gl::SCISSOR_TEST);
        c.scissor(36, 4, 20, 30);
        c.raster_pos2i(34, 3);
        c.copy_pixels(0, 0, 28, 24, gl::DEPTH_STENCIL);
        show(c);
    });
}

#[test]
fn pixel_rectangles_take_the_fragment_operations() {
    let img = image(40, 20);
    same(
        "alpha test, blending, scissor, colour mask, logic op, texturing",
        100,
        60,
        0,
        move |c| {
            c.clear_color(0.2, 0.3, 0.4, 1.0);
            c.clear(gl::COLOR_BUFFER_BIT);
            c.enable(gl::ALPHA_TEST);
            c.alpha_func(gl::GREATER, 0.5);
            c.raster_pos2i(2, 2);
            c.draw_pixels(40, 20, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.disable(gl::ALPHA_TEST);
            c.enable(gl::BLEND);
            c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
            c.raster_pos2i(50, 2);
            c.draw_pixels(40, 20, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.disable(gl::BLEND);
            c.enable(gl::SCISSOR_TEST);
            c.scissor(10, 30, 20, 10);
            c.color_mask(true, false, true, true);
            c.raster_pos2i(2, 25);
            c.draw_pixels(40, 20, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.color_mask(true, true, true, true);
            c.disable(gl::SCISSOR_TEST);
            c.enable(gl::COLOR_LOGIC_OP);
            c.logic_op(gl::XOR);
            c.raster_pos2i(45, 25);
            c.draw_pixels(40, 20, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.disable(gl::COLOR_LOGIC_OP);
            // Texturing at the raster position's (constant) texture coordinates.
            let tex = fixedgl::checkerboard(8, 2, [255, 0, 0, 255], [0, 255, 0, 255]);
            c.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA as i32,
                8,
                8,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                Some(&tex),
            );
            c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
            c.enable(gl::TEXTURE_2D);
            c.tex_coord2f(0.7, 0.3);
            c.raster_pos2i(85, 45);
            c.draw_pixels(10, 10, gl::RGBA, gl::UNSIGNED_BYTE, &vec![200; 400]);
            c.bitmap(8, 1, 0.0, -12.0, 0.0, 0.0, Some(&[0xFF]));
        },
    );
}

#[test]
fn display_lists_hold_pixels_unpacked_at_compile_time() {
    // Run by the driver's own lists, and (under PHONG_WIN, whose emulation makes the backend
    // replay every list call by call from its mirror) expanded by the backend.
    for expanded in [false, true] {
        lists_of_pixels(expanded);
    }
}

fn lists_of_pixels(expanded: bool) {
    let img = image(16, 8);
    let bits: Vec<u8> = (0..64).map(|k: usize| (k * 77 + 5) as u8).collect();
    same(
        &format!("DrawPixels and Bitmap compiled under skips, run under other modes ({expanded})"),
        64,
        32,
        0,
        move |c| {
            if expanded {
                c.shade_model(gl::PHONG_WIN);
            }
            c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 2);
            c.pixel_storei(gl::UNPACK_ROW_LENGTH, 16);
            c.pixel_storei(gl::UNPACK_LSB_FIRST, 1);
            c.new_list(1, gl::COMPILE);
            c.raster_pos2i(2, 2);
            c.draw_pixels(12, 8, gl::RGBA, gl::UNSIGNED_BYTE, &img);
            c.color3f(1.0, 1.0, 0.0);
            c.raster_pos2i(20, 20);
            c.bitmap(13, 6, 0.0, 0.0, 5.0, 0.0, Some(&bits));
            c.end_list();
            // The modes at CallList are not those the data was unpacked under.
            c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
            c.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
            c.pixel_storei(gl::UNPACK_LSB_FIRST, 0);
            c.pixel_storei(gl::UNPACK_ALIGNMENT, 8);
            c.call_list(1);
            c.translatef(30.0, 0.0, 0.0);
            c.call_list(1);
        },
    );
}

#[test]
fn read_pixels_through_the_transfer_matches_the_driver() {
    let Some(mut drv) = test_backend(16, 8) else {
        return;
    };
    let mut cpu = Context::new(16, 8).expect("context");
    let setup = |c: &mut Context| {
        c.window_pos2i(0, 0);
        let d: Vec<u8> = (0..16 * 8 * 4).map(|k: usize| (k * 29 + 3) as u8).collect();
        c.draw_pixels(16, 8, gl::RGBA, gl::UNSIGNED_BYTE, &d);
        c.clear_depth(0.375);
        c.clear_stencil(0x5A);
        c.clear(gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    };
    cpu.start_recording();
    setup(&mut cpu);
    drv.replay(&cpu.stop_recording());
    type Setup = Box<dyn Fn(&mut Context)>;
    // (label, transfer, format, type, bytes per pixel, tolerance in units of the last byte)
    let cases: Vec<(&str, Setup, u32, u32, usize)> = vec![
        ("RGBA", Box::new(|_| {}), gl::RGBA, gl::UNSIGNED_BYTE, 4),
        (
            "scale and bias",
            Box::new(|c| {
                c.pixel_transferf(gl::RED_SCALE, 0.8);
                c.pixel_transferf(gl::GREEN_BIAS, 0.05);
                c.pixel_transferf(gl::ALPHA_SCALE, 0.3);
            }),
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            4,
        ),
        (
            "colour maps",
            Box::new(|c| {
                let m: Vec<f32> = (0..256).map(|k| 1.0 - k as f32 / 255.0).collect();
                c.pixel_mapfv(gl::PIXEL_MAP_B_TO_B, 256, &m);
                c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 3, &[0.2, 0.5, 0.7]);
                c.pixel_transferi(gl::MAP_COLOR, 1);
            }),
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            4,
        ),
        (
            "LUMINANCE = R + G + B",
            Box::new(|_| {}),
            gl::LUMINANCE_ALPHA,
            gl::UNSIGNED_BYTE,
            2,
        ),
        ("BGR", Box::new(|_| {}), gl::BGR, gl::UNSIGNED_BYTE, 3),
        (
            "5_6_5",
            Box::new(|_| {}),
            gl::RGB,
            gl::UNSIGNED_SHORT_5_6_5,
            2,
        ),
        (
            "4_4_4_4_REV",
            Box::new(|_| {}),
            gl::RGBA,
            gl::UNSIGNED_SHORT_4_4_4_4_REV,
            2,
        ),
        (
            "8_8_8_8",
            Box::new(|_| {}),
            gl::BGRA,
            gl::UNSIGNED_INT_8_8_8_8,
            4,
        ),
        ("BYTE", Box::new(|_| {}), gl::RGBA, gl::BYTE, 4),
        ("SHORT", Box::new(|_| {}), gl::RGB, gl::SHORT, 6),
        (
            "stencil shift and offset",
            Box::new(|c| {
                c.pixel_transferi(gl::INDEX_SHIFT, 1);
                c.pixel_transferi(gl::INDEX_OFFSET, 3);
            }),
            gl::STENCIL_INDEX,
            gl::UNSIGNED_SHORT,
            2,
        ),
        (
            "stencil map",
            Box::new(|c| {
                c.pixel_mapfv(gl::PIXEL_MAP_S_TO_S, 4, &[9.0, 8.0, 7.0, 6.0]);
                c.pixel_transferi(gl::MAP_STENCIL, 1);
            }),
            gl::STENCIL_INDEX,
            gl::UNSIGNED_BYTE,
            1,
        ),
        (
            "stencil as INT",
            Box::new(|_| {}),
            gl::STENCIL_INDEX,
            gl::INT,
            4,
        ),
    ];
    for (label, transfer, format, ty, bpp) in cases {
        cpu.start_recording();
        cpu.push_attrib(gl::PIXEL_MODE_BIT);
        transfer(&mut cpu);
        drv.replay(&cpu.stop_recording());
        let n = 16 * 8 * bpp;
        let (mut a, mut b) = (vec![0xEEu8; n + 8], vec![0xEEu8; n + 8]);
        cpu.read_pixels(0, 0, 16, 8, format, ty, &mut a);
        // SAFETY: the backend's context is current (replay made it so); the driver writes 16x8
        // pixels of `bpp` bytes, rows 4-aligned (a multiple of 4 here), into `n + 8` bytes.
        unsafe {
            drv.raw()
                .ReadPixels(0, 0, 16, 8, format, ty, b.as_mut_ptr().cast())
        };
        assert_eq!(cpu.get_error(), gl::NO_ERROR, "{label}");
        assert_eq!(drv.get_error(), gl::NO_ERROR, "{label}");
        let first = a.iter().zip(&b).position(|(p, q)| p != q);
        assert!(
            first.is_none(),
            "{label}: first difference at byte {first:?}"
        );
        cpu.start_recording();
        cpu.pop_attrib();
        drv.replay(&cpu.stop_recording());
    }
}

#[test]
fn errors_match_the_driver() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).expect("context");
    // Every GL 2.1 format and type, and near misses; the driver called directly, so its own
    // validation is what is compared (the backend's guards would answer as the front end).
    let formats = [
        gl::COLOR_INDEX,
        gl::STENCIL_INDEX,
        gl::DEPTH_COMPONENT,
        gl::RED,
        gl::GREEN,
        gl::BLUE,
        gl::ALPHA,
        gl::RGB,
        gl::RGBA,
        gl::BGR,
        gl::BGRA,
        gl::LUMINANCE,
        gl::LUMINANCE_ALPHA,
        gl::DEPTH_STENCIL,
        gl::TRIANGLES,
        gl::RGBA8,
    ];
    let types = [
        gl::BITMAP,
        gl::UNSIGNED_BYTE,
        gl::BYTE,
        gl::UNSIGNED_SHORT,
        gl::SHORT,
        gl::UNSIGNED_INT,
        gl::INT,
        gl::FLOAT,
        gl::UNSIGNED_BYTE_3_3_2,
        gl::UNSIGNED_BYTE_2_3_3_REV,
        gl::UNSIGNED_SHORT_5_6_5,
        gl::UNSIGNED_SHORT_5_6_5_REV,
        gl::UNSIGNED_SHORT_4_4_4_4,
        gl::UNSIGNED_SHORT_4_4_4_4_REV,
        gl::UNSIGNED_SHORT_5_5_5_1,
        gl::UNSIGNED_SHORT_1_5_5_5_REV,
        gl::UNSIGNED_INT_8_8_8_8,
        gl::UNSIGNED_INT_8_8_8_8_REV,
        gl::UNSIGNED_INT_10_10_10_2,
        gl::UNSIGNED_INT_2_10_10_10_REV,
        gl::UNSIGNED_INT_24_8,
        gl::RGBA,
        gl::DOUBLE,
    ];
    let buf = vec![0u8; 4096];
    let mut out = vec![0u8; 4096];
    let mut mismatches = Vec::new();
    let mut check = |what: String, a: u32, b: u32| {
        if a != b {
            mismatches.push(format!("{what}: cpu {a:#x}, driver {b:#x}"));
        }
    };
    for f in formats {
        for t in types {
            // Mesa's glDrawPixels(STENCIL_INDEX, BITMAP) never returns (docs/conformance.md).
            if f == gl::STENCIL_INDEX && t == gl::BITMAP {
                continue;
            }
            for (w, h) in [(2, 2), (-1, 2), (2, -3)] {
                cpu.draw_pixels(w, h, f, t, &buf);
                // SAFETY: context current after the previous backend call (get_error); 2x2
                // groups of at most 16 bytes, or a negative size, read from 4096 bytes.
                unsafe { drv.raw().DrawPixels(w, h, f, t, buf.as_ptr().cast()) };
                check(
                    format!("DrawPixels({w}, {h}, {f:#x}, {t:#x})"),
                    cpu.get_error(),
                    drv.get_error(),
                );
                cpu.read_pixels(0, 0, w, h, f, t, &mut out);
                // SAFETY: as above, written into 4096 bytes.
                unsafe {
                    drv.raw()
                        .ReadPixels(0, 0, w, h, f, t, out.as_mut_ptr().cast())
                };
                check(
                    format!("ReadPixels({w}, {h}, {f:#x}, {t:#x})"),
                    cpu.get_error(),
                    drv.get_error(),
                );
            }
        }
    }
    for t in [
        gl::COLOR,
        gl::DEPTH,
        gl::STENCIL,
        gl::DEPTH_STENCIL,
        gl::RGBA,
        0,
    ] {
        for (w, h) in [(2, 2), (-1, 2)] {
            cpu.copy_pixels(0, 0, w, h, t);
            // SAFETY: context current; no pointers.
            unsafe { drv.raw().CopyPixels(0, 0, w, h, t) };
            check(
                format!("CopyPixels({w}, {h}, {t:#x})"),
                cpu.get_error(),
                drv.get_error(),
            );
        }
    }
    for (w, h) in [(8, 1), (-1, 1), (1, -1), (0, 0)] {
        cpu.bitmap(w, h, 0.0, 0.0, 1.0, 1.0, Some(&buf));
        // SAFETY: context current; at most one row of one byte read.
        unsafe { drv.raw().Bitmap(w, h, 0.0, 0.0, 1.0, 1.0, buf.as_ptr()) };
        check(
            format!("Bitmap({w}, {h})"),
            cpu.get_error(),
            drv.get_error(),
        );
    }
    let values = vec![0.5f32; 300];
    // I_TO_I is left out: Mesa does not require a power of two there (GL 2.1 does; the
    // backend raises it, `pixel_map_sizes_follow_gl_2_1` below).
    for map in gl::PIXEL_MAP_S_TO_S..=gl::PIXEL_MAP_A_TO_A + 1 {
        for size in [0, 1, 3, 4, 256, 257, -1] {
            cpu.pixel_mapfv(map, size, &values);
            // SAFETY: context current; at most 256 values read from 300.
            unsafe { drv.raw().PixelMapfv(map, size, values.as_ptr()) };
            check(
                format!("PixelMapfv({map:#x}, {size})"),
                cpu.get_error(),
                drv.get_error(),
            );
        }
        let (mut a, mut b) = (vec![0f32; 256], vec![0f32; 256]);
        cpu.get_pixel_mapfv(map, &mut a);
        // SAFETY: context current; a map holds at most 256 values.
        unsafe { drv.raw().GetPixelMapfv(map, b.as_mut_ptr()) };
        check(
            format!("GetPixelMapfv({map:#x})"),
            cpu.get_error(),
            drv.get_error(),
        );
        assert_eq!(a, b, "GetPixelMapfv({map:#x})");
    }
    // Inside Begin/End, every command here is INVALID_OPERATION.
    let calls: [Named; 8] = [
        ("DrawPixels", |c| {
            c.draw_pixels(1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &[0; 4])
        }),
        ("Bitmap", |c| c.bitmap(0, 0, 0.0, 0.0, 0.0, 0.0, None)),
        ("CopyPixels", |c| c.copy_pixels(0, 0, 1, 1, gl::COLOR)),
        ("PixelZoom", |c| c.pixel_zoom(2.0, 2.0)),
        ("PixelTransferf", |c| c.pixel_transferf(gl::RED_SCALE, 2.0)),
        ("PixelMapfv", |c| {
            c.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 1, &[0.5])
        }),
        ("RasterPos2f", |c| c.raster_pos2f(0.0, 0.0)),
        ("Rectf", |c| c.rectf(0.0, 0.0, 1.0, 1.0)),
    ];
    for (name, f) in calls {
        cpu.start_recording();
        cpu.begin(gl::POINTS);
        f(&mut cpu);
        cpu.end();
        drv.replay(&cpu.stop_recording());
        check(
            format!("{name} inside Begin/End"),
            cpu.get_error(),
            drv.get_error(),
        );
    }
    assert!(mismatches.is_empty(), "{}", mismatches.join("\n"));
}

#[test]
fn pixel_map_values_convert_as_the_drivers() {
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).expect("context");
    let us: [u16; 8] = [0, 1, 1000, 32767, 32768, 65534, 65535, 12345];
    let ui: [u32; 8] = [
        0,
        1,
        1000,
        0x7fff_ffff,
        0x8000_0000,
        0xffff_fffe,
        u32::MAX,
        123_456_789,
    ];
    let fv: [f32; 8] = [-0.5, 0.25, 1.5, 2.5, 3.49, 100.7, 0.0, 0.75];
    for map in [
        gl::PIXEL_MAP_R_TO_R,
        gl::PIXEL_MAP_I_TO_G,
        gl::PIXEL_MAP_I_TO_I,
        gl::PIXEL_MAP_S_TO_S,
    ] {
        let index = map == gl::PIXEL_MAP_I_TO_I || map == gl::PIXEL_MAP_S_TO_S;
        for load in 0..3 {
            cpu.start_recording();
            match load {
                0 => cpu.pixel_mapusv(map, 8, &us),
                1 => cpu.pixel_mapuiv(map, 8, &ui),
                _ => cpu.pixel_mapfv(map, 8, &fv),
            }
            drv.replay(&cpu.stop_recording());
            let (mut a, mut b) = ([0f32; 8], [0f32; 8]);
            cpu.get_pixel_mapfv(map, &mut a);
            // SAFETY: context current (replay made it so); the map holds 8 values.
            unsafe { drv.raw().GetPixelMapfv(map, b.as_mut_ptr()) };
            assert_eq!(a, b, "{map:#x} load {load}: GetPixelMapfv");
            let (mut a, mut b) = ([0u16; 8], [0u16; 8]);
            cpu.get_pixel_mapusv(map, &mut a);
            // SAFETY: as above.
            unsafe { drv.raw().GetPixelMapusv(map, b.as_mut_ptr()) };
            assert_eq!(a, b, "{map:#x} load {load}: GetPixelMapusv");
            // Mesa's GetPixelMapuiv of an index map is wrong (negated or a float's bits; see
            // docs/conformance.md): compared for the colour maps only.
            if !index {
                let (mut a, mut b) = ([0u32; 8], [0u32; 8]);
                cpu.get_pixel_mapuiv(map, &mut a);
                // SAFETY: as above.
                unsafe { drv.raw().GetPixelMapuiv(map, b.as_mut_ptr()) };
                assert_eq!(a, b, "{map:#x} load {load}: GetPixelMapuiv");
            }
            let (mut a, mut b) = ([0i32], [0i32]);
            cpu.get_integerv(
                map - gl::PIXEL_MAP_I_TO_I + gl::PIXEL_MAP_I_TO_I_SIZE,
                &mut a,
            );
            drv.get_integerv(
                map - gl::PIXEL_MAP_I_TO_I + gl::PIXEL_MAP_I_TO_I_SIZE,
                &mut b,
            );
            assert_eq!((a, b), ([8], [8]));
        }
    }
    // PixelTransfer's values as the queries report them, truncation of the index parameters
    // included.
    for (pname, v) in [
        (gl::INDEX_SHIFT, -2.7),
        (gl::INDEX_OFFSET, 3.9),
        (gl::MAP_COLOR, 0.25),
        (gl::DEPTH_BIAS, -0.125),
        (gl::ALPHA_SCALE, 7.5),
    ] {
        cpu.start_recording();
        cpu.pixel_transferf(pname, v);
        drv.replay(&cpu.stop_recording());
        let (mut a, mut b) = ([0f32], [0f32]);
        cpu.get_floatv(pname, &mut a);
        drv.get_floatv(pname, &mut b);
        assert_eq!(a, b, "{pname:#x}");
    }
    assert_eq!(cpu.get_error(), gl::NO_ERROR);
    assert_eq!(drv.get_error(), gl::NO_ERROR);
}

#[test]
fn pixel_map_sizes_follow_gl_2_1() {
    // GL 2.1 §3.6.3: an index map's size is a power of two, I_TO_I's too; Mesa does not check
    // I_TO_I, so the backend raises the error itself and both answer INVALID_VALUE.
    let Some(mut drv) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).expect("context");
    cpu.start_recording();
    cpu.pixel_mapfv(gl::PIXEL_MAP_I_TO_I, 3, &[1.0, 2.0, 3.0]);
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), gl::INVALID_VALUE);
    assert_eq!(drv.get_error(), gl::INVALID_VALUE);
    // A slice shorter than the size: INVALID_VALUE on both, nothing read.
    cpu.start_recording();
    cpu.pixel_mapfv(gl::PIXEL_MAP_R_TO_R, 4, &[1.0, 2.0]);
    cpu.draw_pixels(4, 4, gl::RGBA, gl::UNSIGNED_BYTE, &[0; 63]);
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), gl::INVALID_VALUE);
    assert_eq!(drv.get_error(), gl::INVALID_VALUE);
    // (The DrawPixels above was short too: its INVALID_OPERATION lost to the first error.)
    cpu.start_recording();
    cpu.draw_pixels(4, 4, gl::RGBA, gl::UNSIGNED_BYTE, &[0; 63]);
    cpu.bitmap(9, 2, 0.0, 0.0, 0.0, 0.0, Some(&[0; 7]));
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
    assert_eq!(drv.get_error(), gl::INVALID_OPERATION);
}

/// Reads `format`/`ty` (`bpp` bytes a pixel) of the whole `w` x `h` window from both backends.
fn read_both(
    cpu: &mut Context,
    drv: &mut fixedgl::glbackend::GlBackend,
    (w, h): (i32, i32),
    format: u32,
    ty: u32,
    bpp: usize,
) -> (Vec<u8>, Vec<u8>) {
    let n = w as usize * h as usize * bpp;
    let (mut a, mut b) = (vec![0xEEu8; n + 8], vec![0xEEu8; n + 8]);
    cpu.read_pixels(0, 0, w, h, format, ty, &mut a);
    // SAFETY: the backend's context is current (replay made it so); the driver writes w x h
    // pixels of `bpp` bytes (rows 4-aligned: `bpp` · w is a multiple of 4 here) into n + 8 bytes.
    unsafe {
        drv.raw()
            .ReadPixels(0, 0, w, h, format, ty, b.as_mut_ptr().cast())
    };
    assert_eq!(cpu.get_error(), gl::NO_ERROR, "{format:#x} {ty:#x}");
    assert_eq!(drv.get_error(), gl::NO_ERROR, "{format:#x} {ty:#x}");
    (a, b)
}

/// Asserts that two UNSIGNED_INT_24_8 images (`n` words) hold the same indices and depths
/// within 1 in 2^24 − 1: llvmpipe draws depths through a 32-bit float, whose rounding moves some
/// 24-bit values by one (docs/conformance.md); fixedgl keeps them exactly.
fn same_24_8(label: &str, a: &[u8], b: &[u8], n: usize) {
    let words = |v: &[u8]| -> Vec<u32> {
        v.chunks_exact(4)
            .take(n)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    let (a, b) = (words(a), words(b));
    for (k, (p, q)) in a.iter().zip(&b).enumerate() {
        assert_eq!(p & 0xFF, q & 0xFF, "{label}: index of pixel {k}");
        assert!(
            (p >> 8).abs_diff(q >> 8) <= 1,
            "{label}: depth of pixel {k}: {:#x} {:#x}",
            p >> 8,
            q >> 8
        );
    }
}

/// GL_EXT_packed_depth_stencil's DrawPixels and ReadPixels of DEPTH_STENCIL / UNSIGNED_INT_24_8:
/// both buffers written (the depth and stencil tests ignored, the write masks and the zoom
/// applied, GL 3.0 §4.3.1) and read back through the transfer: the indices exactly the
/// driver's, the depths within 1 (see `same_24_8`), and fixedgl's depths exactly the values
/// drawn.
#[test]
fn depth_stencil_pixels_match_the_driver() {
    let (w, h) = (16i32, 8i32);
    let Some(mut drv) = test_backend(w as u32, h as u32) else {
        return;
    };
    let mut cpu = Context::new(w as u32, h as u32).expect("context");
    let packed: Vec<u32> = (0..(w * h) as u32)
        .map(|k| ((k.wrapping_mul(104_729) + 12_345) & 0xFF_FFFF) << 8 | ((k * 37 + 5) & 0xFF))
        .collect();
    let bytes: Vec<u8> = packed.iter().flat_map(|v| v.to_ne_bytes()).collect();
    cpu.start_recording();
    cpu.enable(gl::DEPTH_TEST);
    cpu.depth_func(gl::NEVER);
    cpu.enable(gl::STENCIL_TEST);
    cpu.stencil_func(gl::NEVER, 0, 0xFF);
    cpu.stencil_op(gl::INCR, gl::INCR, gl::INCR);
    cpu.window_pos2i(0, 0);
    cpu.draw_pixels(w, h, gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8, &bytes);
    drv.replay(&cpu.stop_recording());
    let (a, b) = read_both(
        &mut cpu,
        &mut drv,
        (w, h),
        gl::DEPTH_STENCIL,
        gl::UNSIGNED_INT_24_8,
        4,
    );
    let n = (w * h) as usize;
    same_24_8("DEPTH_STENCIL read back", &a, &b, n);
    assert_eq!(a[..bytes.len()], bytes[..], "the values drawn");
    let (a, b) = read_both(
        &mut cpu,
        &mut drv,
        (w, h),
        gl::STENCIL_INDEX,
        gl::UNSIGNED_BYTE,
        1,
    );
    assert_eq!(a, b, "STENCIL_INDEX");
    // Read through the depth and index transfers.
    cpu.start_recording();
    cpu.push_attrib(gl::PIXEL_MODE_BIT);
    cpu.pixel_transferf(gl::DEPTH_SCALE, 0.5);
    cpu.pixel_transferf(gl::DEPTH_BIAS, 0.25);
    cpu.pixel_transferi(gl::INDEX_SHIFT, 1);
    cpu.pixel_transferi(gl::INDEX_OFFSET, 3);
    drv.replay(&cpu.stop_recording());
    let (a, b) = read_both(
        &mut cpu,
        &mut drv,
        (w, h),
        gl::DEPTH_STENCIL,
        gl::UNSIGNED_INT_24_8,
        4,
    );
    same_24_8("DEPTH_STENCIL through the transfer", &a, &b, n);
    // Zoomed, through the stencil write mask, DepthMask FALSE then TRUE.
    cpu.start_recording();
    cpu.pop_attrib();
    cpu.stencil_mask(0x0F);
    cpu.depth_mask(false);
    cpu.pixel_zoom(2.0, 1.0);
    cpu.window_pos2i(3, 1);
    let rev: Vec<u8> = bytes.iter().rev().copied().collect();
    cpu.draw_pixels(5, 4, gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8, &rev);
    cpu.stencil_mask(0xF0);
    cpu.depth_mask(true);
    cpu.pixel_zoom(1.0, 2.0);
    cpu.window_pos2i(9, 2);
    cpu.draw_pixels(6, 3, gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8, &rev);
    drv.replay(&cpu.stop_recording());
    let (a, b) = read_both(
        &mut cpu,
        &mut drv,
        (w, h),
        gl::DEPTH_STENCIL,
        gl::UNSIGNED_INT_24_8,
        4,
    );
    same_24_8("zoomed and masked", &a, &b, n);
    assert_ne!(
        a[..bytes.len()],
        bytes[..],
        "the second draws changed something"
    );
}
