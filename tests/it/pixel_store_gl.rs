//! Pixel storage modes against the real driver (Mesa llvmpipe through EGL): the same stored
//! values after the same PixelStore calls, textures uploaded under UNPACK skips, row length and
//! byte swapping drawn alike, ReadPixels placing bytes under the PACK modes exactly as the
//! driver's glReadPixels does, `read_image` unaffected by the pack modes, and short recorded
//! data never reaching the driver. Skipped, with a note on stderr, when no GL backend can start
//! (unless FIXEDGL_REQUIRE_GL is set).
#![cfg(feature = "gl")]

use fixedgl::compare::compare;
use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context};

fn backend(width: u32, height: u32) -> Option<GlBackend> {
    crate::common::test_backend(width, height)
}

fn ctx(w: u32, h: u32) -> Context {
    let Ok(c) = Context::new(w, h) else {
        panic!("CPU context")
    };
    c
}

/// Runs `calls` on both, requiring the same error after each.
fn both(cpu: &mut Context, drv: &mut GlBackend, calls: &[Call]) {
    for call in calls {
        cpu.execute(call);
        drv.execute(call);
        assert_eq!(cpu.get_error(), drv.get_error(), "{call:?}");
    }
}

const PNAMES: [u32; 16] = [
    gl::UNPACK_SWAP_BYTES,
    gl::UNPACK_LSB_FIRST,
    gl::UNPACK_ROW_LENGTH,
    gl::UNPACK_IMAGE_HEIGHT,
    gl::UNPACK_SKIP_ROWS,
    gl::UNPACK_SKIP_PIXELS,
    gl::UNPACK_SKIP_IMAGES,
    gl::UNPACK_ALIGNMENT,
    gl::PACK_SWAP_BYTES,
    gl::PACK_LSB_FIRST,
    gl::PACK_ROW_LENGTH,
    gl::PACK_IMAGE_HEIGHT,
    gl::PACK_SKIP_ROWS,
    gl::PACK_SKIP_PIXELS,
    gl::PACK_SKIP_IMAGES,
    gl::PACK_ALIGNMENT,
];

fn values(cpu: &mut Context, drv: &mut GlBackend) -> Vec<(u32, i32, i32)> {
    PNAMES
        .iter()
        .map(|&p| {
            let (mut a, mut b) = ([-9], [-9]);
            cpu.get_integerv(p, &mut a);
            drv.get_integerv(p, &mut b);
            (p, a[0], b[0])
        })
        .collect()
}

#[test]
fn stored_values_match_the_driver() {
    let Some(mut drv) = backend(8, 8) else {
        return;
    };
    let mut cpu = ctx(8, 8);
    let differ = |v: Vec<(u32, i32, i32)>| -> Vec<(u32, i32, i32)> {
        v.into_iter().filter(|(_, a, b)| a != b).collect()
    };
    assert_eq!(differ(values(&mut cpu, &mut drv)), [], "initial");
    // Every pname, each form, values in range, out of range, and the f form's conversions
    // (§3.6.1: booleans nonzero TRUE, integers rounded; NaN and values beyond GLint refused).
    let mut calls = Vec::new();
    for (k, &p) in PNAMES.iter().enumerate() {
        let k = k as i32;
        calls.extend([
            Call::PixelStorei(p, 2 + k % 3 * 2),
            Call::PixelStorei(p, -1),
            Call::PixelStoref(p, 7.5),
            Call::PixelStoref(p, f32::NAN),
            Call::PixelStoref(p, 3e9),
            Call::PixelStoref(p, -0.4),
            Call::PixelStorei(p, 256),
            Call::PixelStoref(p, 0.25),
            Call::PixelStorei(p, 8),
            Call::PixelStoref(p, 1.5),
        ]);
    }
    calls.push(Call::PixelStorei(gl::PIXEL_PACK_BUFFER, 1));
    calls.push(Call::PixelStorei(0x8758, 1)); // PACK_INVERT_MESA: not GL 2.1
    for call in &calls {
        both(&mut cpu, &mut drv, std::slice::from_ref(call));
        assert_eq!(differ(values(&mut cpu, &mut drv)), [], "after {call:?}");
    }
    // PushClientAttrib / PopClientAttrib on both.
    both(
        &mut cpu,
        &mut drv,
        &[
            Call::PushClientAttrib(gl::CLIENT_PIXEL_STORE_BIT),
            Call::PixelStorei(gl::UNPACK_SKIP_ROWS, 5),
            Call::PixelStorei(gl::PACK_SWAP_BYTES, 0),
        ],
    );
    assert_eq!(differ(values(&mut cpu, &mut drv)), [], "changed");
    both(&mut cpu, &mut drv, &[Call::PopClientAttrib]);
    let v = values(&mut cpu, &mut drv);
    assert_eq!(differ(v.clone()), [], "restored");
    assert!(v
        .iter()
        .any(|&(p, a, _)| p == gl::PACK_SWAP_BYTES && a == 1));
}

/// How the texture tests lay out client data: ROW_LENGTH 7 and UNPACK_ALIGNMENT 8 always, then
/// SKIP_ROWS 2 and SKIP_PIXELS 3, and/or SWAP_BYTES.
#[derive(Clone, Copy, Debug)]
struct Unpack {
    skips: bool,
    swap: bool,
}

/// A 4x4 RGBA image of `size`-byte elements whose bytes all differ, laid out in a client buffer
/// under `m` (§3.6.4): rows of ROW_LENGTH 7 pixels padded to 8 bytes, after the skips; each
/// element's bytes most significant first when swapped (this machine is little-endian), least
/// significant first otherwise. 0xEE elsewhere.
fn embedded(size: usize, m: Unpack) -> Vec<u8> {
    let stride = (7 * 4 * size).next_multiple_of(8);
    let start = if m.skips {
        2 * stride + 3 * 4 * size
    } else {
        0
    };
    let mut out = vec![0xEE; start + 3 * stride + 4 * 4 * size];
    for j in 0..4 {
        for i in 0..4 {
            for c in 0..4 {
                let k = (j * 4 + i) * 4 + c;
                let hi = (k * 53 % 256) as u8;
                // Most significant byte first.
                let mut e: Vec<u8> = (0..size)
                    .map(|b| hi ^ (b as u8).wrapping_mul(0x5A))
                    .collect();
                if !m.swap {
                    e.reverse();
                }
                let at = start + j * stride + (i * 4 + c) * size;
                out[at..at + size].copy_from_slice(&e);
            }
        }
    }
    out
}

fn unpack_modes(m: Unpack) -> Vec<Call> {
    let skip = |on: bool, v: i32| if on { v } else { 0 };
    vec![
        Call::PixelStorei(gl::UNPACK_ROW_LENGTH, 7),
        Call::PixelStorei(gl::UNPACK_SKIP_ROWS, skip(m.skips, 2)),
        Call::PixelStorei(gl::UNPACK_SKIP_PIXELS, skip(m.skips, 3)),
        Call::PixelStorei(gl::UNPACK_ALIGNMENT, 8),
        Call::PixelStorei(gl::UNPACK_SWAP_BYTES, i32::from(m.swap)),
    ]
}

#[test]
fn textures_uploaded_with_skips_and_swap_draw_as_the_driver() {
    // Mesa 22.3's llvmpipe unpacks SWAP_BYTES together with SKIP_ROWS or SKIP_PIXELS wrongly
    // (texels from outside the image: it swaps into a temporary copy, then applies the skips
    // again); fixedgl follows §3.6.4 there, which tests/pixel_store.rs checks against plain
    // uploads. Each is compared with the driver on its own.
    let modes = [
        Unpack {
            skips: true,
            swap: false,
        },
        Unpack {
            skips: false,
            swap: true,
        },
    ];
    for (ty, size) in [(gl::UNSIGNED_SHORT, 2), (gl::UNSIGNED_INT, 4)] {
        for (m, sub) in modes.into_iter().flat_map(|m| [(m, false), (m, true)]) {
            let Some(mut drv) = backend(32, 32) else {
                return;
            };
            let mut cpu = ctx(32, 32);
            let data = embedded(size, m);
            cpu.start_recording();
            for call in unpack_modes(m) {
                cpu.execute(&call);
            }
            let (tex, sub_data) = if sub {
                (None, Some(data))
            } else {
                (Some(data), None)
            };
            cpu.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA8 as i32,
                4,
                4,
                0,
                gl::RGBA,
                ty,
                tex.as_deref(),
            );
            if let Some(d) = &sub_data {
                cpu.tex_sub_image_2d(gl::TEXTURE_2D, 0, 0, 0, 4, 4, gl::RGBA, ty, d);
            }
            cpu.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
            cpu.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
            cpu.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
            cpu.enable(gl::TEXTURE_2D);
            cpu.begin(gl::QUADS);
            for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                cpu.tex_coord2f((x + 1.0) / 2.0, (y + 1.0) / 2.0);
                cpu.vertex2f(x, y);
            }
            cpu.end();
            let calls = cpu.stop_recording();
            assert_eq!(cpu.get_error(), gl::NO_ERROR);
            drv.replay(&calls);
            assert_eq!(drv.get_error(), gl::NO_ERROR);
            let (ci, gi) = (cpu.to_image(), drv.read_image());
            // The texture tolerance of texture_gl.rs: no channel off by more than 1.
            let cmp = compare(&ci, &gi, 1);
            assert_eq!(
                cmp.differing_pixels,
                0,
                "type {ty:#x} {m:?} sub {sub}: {cmp:?}; (4,4) cpu {:?} gl {:?}",
                ci.get_pixel(4, 4),
                gi.get_pixel(4, 4)
            );
            // And the picture is the texture, not the 0xEE filler a wrong skip would read.
            let distinct: std::collections::BTreeSet<[u8; 4]> = ci.pixels().map(|p| p.0).collect();
            assert!(distinct.len() >= 16, "{} colours", distinct.len());
        }
    }
}

#[test]
fn short_recorded_data_with_skips_never_reaches_the_driver() {
    let Some(mut drv) = backend(8, 8) else {
        return;
    };
    let mut cpu = ctx(8, 8);
    let m = Unpack {
        skips: true,
        swap: true,
    };
    let data = embedded(2, m);
    let short = data[..data.len() - 1].to_vec();
    let tex = |pixels: Option<Vec<u8>>| {
        Call::TexImage2D(Box::new((
            gl::TEXTURE_2D,
            0,
            gl::RGBA8 as i32,
            4,
            4,
            0,
            gl::RGBA,
            gl::UNSIGNED_SHORT,
            pixels,
        )))
    };
    let sub = |pixels: Vec<u8>| {
        Call::TexSubImage2D(Box::new((
            gl::TEXTURE_2D,
            0,
            0,
            0,
            4,
            4,
            gl::RGBA,
            gl::UNSIGNED_SHORT,
            pixels,
        )))
    };
    let mut calls = unpack_modes(m);
    calls.extend([
        tex(Some(short.clone())),
        tex(Some(data.clone())),
        sub(short.clone()),
        sub(data.clone()),
        // Skips no recording can hold.
        Call::PixelStorei(gl::UNPACK_SKIP_ROWS, i32::MAX),
        Call::PixelStorei(gl::UNPACK_ROW_LENGTH, i32::MAX),
        tex(Some(data.clone())),
        sub(data.clone()),
        tex(None),
    ]);
    both(&mut cpu, &mut drv, &calls);
}

/// A 7x5 frame of four solid rectangles by scissored clears, colours k/255 (exact on both).
/// `binary`: components 0 and 255 only, whose FLOAT forms 0.0 and 1.0 are exact too (for other
/// k the driver's k/255 as a float can differ from fixedgl's in the last bit, a conversion
/// that has nothing to do with the pack modes).
fn frame(binary: bool) -> Vec<Call> {
    let mut calls = vec![Call::Enable(gl::SCISSOR_TEST)];
    let rects = [
        ([0, 0, 7, 5], [10, 20, 30, 40]),
        ([0, 0, 3, 2], [200, 100, 50, 255]),
        ([3, 2, 4, 3], [1, 128, 254, 77]),
        ([1, 3, 2, 2], [255, 0, 90, 180]),
    ];
    for (rect, rgba) in rects {
        let rgba = if binary {
            rgba.map(|v| if v >= 128 { 255 } else { 0 })
        } else {
            rgba
        };
        let k = |v: i32| v as f32 / 255.0;
        calls.push(Call::Scissor(rect[0], rect[1], rect[2], rect[3]));
        calls.push(Call::ClearColor(
            k(rgba[0]),
            k(rgba[1]),
            k(rgba[2]),
            k(rgba[3]),
        ));
        calls.push(Call::Clear(gl::COLOR_BUFFER_BIT));
    }
    calls.push(Call::Disable(gl::SCISSOR_TEST));
    calls
}

#[test]
fn read_pixels_matches_the_driver_byte_for_byte() {
    let Some(mut drv) = backend(7, 5) else {
        return;
    };
    let mut cpu = ctx(7, 5);
    // (format, type, pack modes: swap, row length, skip rows, skip pixels, alignment, rect)
    type Case = (u32, u32, [i32; 5], [i32; 4]);
    let cases: &[Case] = &[
        (gl::RGBA, gl::UNSIGNED_BYTE, [0, 0, 0, 0, 4], [0, 0, 7, 5]),
        (gl::RGB, gl::UNSIGNED_BYTE, [0, 0, 0, 0, 4], [0, 0, 7, 5]),
        (gl::RGB, gl::UNSIGNED_BYTE, [0, 0, 0, 0, 1], [1, 1, 5, 3]),
        (gl::RGB, gl::UNSIGNED_BYTE, [0, 9, 2, 3, 8], [1, 0, 5, 4]),
        (gl::RGBA, gl::UNSIGNED_BYTE, [1, 8, 1, 2, 2], [0, 1, 6, 4]),
        (gl::RGB, gl::UNSIGNED_SHORT, [1, 10, 1, 1, 8], [0, 0, 7, 5]),
        (gl::RGBA, gl::UNSIGNED_SHORT, [0, 7, 3, 0, 2], [2, 1, 3, 3]),
        (gl::RGB, gl::FLOAT, [1, 9, 2, 4, 8], [0, 0, 5, 5]),
        (gl::RGBA, gl::FLOAT, [0, 0, 1, 1, 4], [1, 1, 4, 2]),
        (gl::RED, gl::UNSIGNED_BYTE, [0, 11, 1, 5, 8], [0, 0, 6, 5]),
        (gl::ALPHA, gl::UNSIGNED_SHORT, [1, 6, 0, 2, 4], [1, 0, 3, 5]),
        // Partly outside the window: those pixels are left as they were, on both.
        (
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            [0, 12, 1, 2, 4],
            [-2, -1, 9, 4],
        ),
    ];
    for (binary, &(format, ty, [swap, row, rows, pixels, align], [x, y, w, h])) in [false, true]
        .into_iter()
        .flat_map(|b| cases.iter().map(move |c| (b, c)))
    {
        if !binary && ty == gl::FLOAT {
            continue;
        }
        both(&mut cpu, &mut drv, &frame(binary));
        let modes = [
            Call::PixelStorei(gl::PACK_SWAP_BYTES, swap),
            Call::PixelStorei(gl::PACK_ROW_LENGTH, row),
            Call::PixelStorei(gl::PACK_SKIP_ROWS, rows),
            Call::PixelStorei(gl::PACK_SKIP_PIXELS, pixels),
            Call::PixelStorei(gl::PACK_ALIGNMENT, align),
        ];
        both(&mut cpu, &mut drv, &modes);
        // read_image resets the pack modes for its own read: the comparison image is unshifted.
        assert_eq!(
            drv.read_image(),
            cpu.to_image(),
            "read_image under {modes:?}"
        );
        let mut a = vec![0xABu8; 4096];
        let mut b = vec![0xABu8; 4096];
        cpu.read_pixels(x, y, w, h, format, ty, &mut a);
        assert_eq!(cpu.get_error(), gl::NO_ERROR);
        // Bounds for the driver's writes: at most 12 rows of 12 pixels of 16 bytes, 8-aligned.
        assert!(row.max(w) <= 12 && rows + h <= 12 && pixels + w <= 12);
        // SAFETY: the backend's context is current (read_image made it so and bound its FBO for
        // reading); the driver writes within (SKIP_ROWS + h) rows of max(ROW_LENGTH, w) pixels
        // of at most 16 bytes, padded to 8, after SKIP_PIXELS: under 12·(12·16 + 8) = 2400
        // bytes of the 4096. The pack modes are set back to their initial values below.
        unsafe {
            let raw = drv.raw();
            raw.ReadPixels(x, y, w, h, format, ty, b.as_mut_ptr().cast());
        }
        assert_eq!(drv.get_error(), gl::NO_ERROR);
        let first = a.iter().zip(&b).position(|(p, q)| p != q);
        assert!(
            first.is_none(),
            "binary {binary} {format:#x} {ty:#x} modes {:?} rect {:?}: first difference at byte {first:?}: cpu {:?} driver {:?}",
            [swap, row, rows, pixels, align],
            [x, y, w, h],
            first.map(|i| &a[i.saturating_sub(4)..(i + 8).min(a.len())]),
            first.map(|i| &b[i.saturating_sub(4)..(i + 8).min(b.len())]),
        );
    }
    both(
        &mut cpu,
        &mut drv,
        &[
            Call::PixelStorei(gl::PACK_SWAP_BYTES, 0),
            Call::PixelStorei(gl::PACK_ROW_LENGTH, 0),
            Call::PixelStorei(gl::PACK_SKIP_ROWS, 0),
            Call::PixelStorei(gl::PACK_SKIP_PIXELS, 0),
            Call::PixelStorei(gl::PACK_ALIGNMENT, 4),
        ],
    );
}
