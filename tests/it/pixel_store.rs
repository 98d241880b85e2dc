//! Pixel storage modes on the CPU front end (GL 2.1 §3.6.1, §3.6.4, §4.3.2): every mode of
//! table 3.1 stored, queried and saved by PushClientAttrib, the unpack modes honoured by
//! TexImage2D, TexSubImage2D and gluBuild2DMipmaps, the pack modes by ReadPixels and
//! GetTexImage, and client data too short for the skips an error that changes nothing.
//!
//! Client buffers here are laid out by `embed`, written from the spec's formulas independently
//! of `fixedgl::pixel_store`, so the library is checked against the spec and not against itself.

use fixedgl::{gl, glu, Context};

/// The sixteen pnames of table 3.1: (pname, initial value, a non-initial valid value).
const PNAMES: [(u32, i32, i32); 16] = [
    (gl::UNPACK_SWAP_BYTES, 0, 1),
    (gl::UNPACK_LSB_FIRST, 0, 1),
    (gl::UNPACK_ROW_LENGTH, 0, 11),
    (gl::UNPACK_IMAGE_HEIGHT, 0, 12),
    (gl::UNPACK_SKIP_ROWS, 0, 13),
    (gl::UNPACK_SKIP_PIXELS, 0, 14),
    (gl::UNPACK_SKIP_IMAGES, 0, 15),
    (gl::UNPACK_ALIGNMENT, 4, 2),
    (gl::PACK_SWAP_BYTES, 0, 1),
    (gl::PACK_LSB_FIRST, 0, 1),
    (gl::PACK_ROW_LENGTH, 0, 21),
    (gl::PACK_IMAGE_HEIGHT, 0, 22),
    (gl::PACK_SKIP_ROWS, 0, 23),
    (gl::PACK_SKIP_PIXELS, 0, 24),
    (gl::PACK_SKIP_IMAGES, 0, 25),
    (gl::PACK_ALIGNMENT, 4, 8),
];

fn is_boolean(pname: u32) -> bool {
    matches!(
        pname,
        gl::UNPACK_SWAP_BYTES | gl::UNPACK_LSB_FIRST | gl::PACK_SWAP_BYTES | gl::PACK_LSB_FIRST
    )
}

fn get_i(c: &mut Context, pname: u32) -> i32 {
    let mut v = [-99];
    c.get_integerv(pname, &mut v);
    v[0]
}

fn get_b(c: &mut Context, pname: u32) -> bool {
    let mut v = [false];
    c.get_booleanv(pname, &mut v);
    v[0]
}

fn ctx() -> Context {
    let Ok(c) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    c
}

/// Pixel modes as the spec's formulas use them (§3.6.4).
#[derive(Clone, Copy, Default)]
struct Modes {
    row_length: usize,
    skip_rows: usize,
    skip_pixels: usize,
    alignment: usize,
    swap: bool,
}

/// A client buffer holding `w` x `h` pixels of `elems[pixel]` (n elements of `size` bytes,
/// native order, the low `size` bytes of each u32) where the modes put them: rows
/// ROW_LENGTH (or w) pixels apart, padded to the alignment when the element is smaller, after
/// SKIP_ROWS rows and SKIP_PIXELS pixels; each element's bytes reversed under SWAP_BYTES.
/// Everything else is 0xEE. Exactly as long as the image needs.
fn embed(m: Modes, w: usize, h: usize, n: usize, size: usize, elems: &[u32]) -> Vec<u8> {
    let l = if m.row_length > 0 { m.row_length } else { w };
    let a = m.alignment.max(1);
    let k = if size >= a {
        n * l
    } else {
        a / size * (size * n * l).div_ceil(a)
    };
    let stride = k * size;
    let start = m.skip_rows * stride + m.skip_pixels * n * size;
    let len = start + stride * (h - 1) + w * n * size;
    let mut out = vec![0xEE; len];
    for j in 0..h {
        for i in 0..w {
            for c in 0..n {
                let v = elems[(j * w + i) * n + c];
                let mut b = v.to_ne_bytes()[..4].to_vec();
                // The low `size` bytes of v in native order.
                let mut e: Vec<u8> = if cfg!(target_endian = "little") {
                    b.truncate(size);
                    b
                } else {
                    b[4 - size..].to_vec()
                };
                if m.swap {
                    e.reverse();
                }
                let at = start + j * stride + (i * n + c) * size;
                out[at..at + size].copy_from_slice(&e);
            }
        }
    }
    out
}

#[test]
fn every_mode_is_stored_queried_and_pushed() {
    let mut c = ctx();
    for (pname, initial, _) in PNAMES {
        assert_eq!(get_i(&mut c, pname), initial, "{pname:#x} initial");
        assert_eq!(
            get_b(&mut c, pname),
            initial != 0,
            "{pname:#x} initial bool"
        );
    }
    c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
    for (pname, _, v) in PNAMES {
        c.pixel_storei(pname, v);
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
    for (pname, _, v) in PNAMES {
        assert_eq!(get_i(&mut c, pname), v, "{pname:#x} set");
        assert!(get_b(&mut c, pname), "{pname:#x} as boolean");
    }
    // The vertex-array group alone does not restore them.
    c.push_client_attrib(gl::CLIENT_VERTEX_ARRAY_BIT);
    c.pop_client_attrib();
    assert_eq!(get_i(&mut c, gl::PACK_SKIP_PIXELS), 24);
    c.pop_client_attrib();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    for (pname, initial, _) in PNAMES {
        assert_eq!(get_i(&mut c, pname), initial, "{pname:#x} restored");
    }
    // PushAttrib(ALL_ATTRIB_BITS) is server state only: pixel store is not in it.
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, 3);
    c.push_attrib(gl::ALL_ATTRIB_BITS);
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, 4);
    c.pop_attrib();
    assert_eq!(get_i(&mut c, gl::UNPACK_SKIP_ROWS), 4);
}

#[test]
fn values_booleans_and_float_conversion() {
    let mut c = ctx();
    // §3.6.1: a boolean is TRUE for any nonzero value, through either form.
    c.pixel_storei(gl::UNPACK_SWAP_BYTES, -5);
    assert_eq!(get_i(&mut c, gl::UNPACK_SWAP_BYTES), 1);
    c.pixel_storef(gl::PACK_LSB_FIRST, 0.25);
    assert!(get_b(&mut c, gl::PACK_LSB_FIRST));
    c.pixel_storef(gl::PACK_LSB_FIRST, 0.0);
    assert!(!get_b(&mut c, gl::PACK_LSB_FIRST));
    // An integer is rounded to the nearest.
    c.pixel_storef(gl::UNPACK_ROW_LENGTH, 6.5);
    assert_eq!(get_i(&mut c, gl::UNPACK_ROW_LENGTH), 7);
    c.pixel_storef(gl::PACK_SKIP_ROWS, -0.4);
    assert_eq!(get_i(&mut c, gl::PACK_SKIP_ROWS), 0);
    c.pixel_storef(gl::PACK_ALIGNMENT, 1.6);
    assert_eq!(get_i(&mut c, gl::PACK_ALIGNMENT), 2);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    // Table 3.1's ranges: INVALID_VALUE, nothing changed.
    for (pname, _, _) in PNAMES.iter().filter(|p| !is_boolean(p.0)) {
        let before = get_i(&mut c, *pname);
        c.pixel_storei(*pname, -1);
        assert_eq!(c.get_error(), gl::INVALID_VALUE, "{pname:#x} -1");
        c.pixel_storef(*pname, f32::NAN);
        assert_eq!(c.get_error(), gl::INVALID_VALUE, "{pname:#x} NaN");
        c.pixel_storef(*pname, 3e9);
        assert_eq!(c.get_error(), gl::INVALID_VALUE, "{pname:#x} 3e9");
        assert_eq!(get_i(&mut c, *pname), before);
    }
    for a in [0, 3, 5, 16] {
        c.pixel_storei(gl::UNPACK_ALIGNMENT, a);
        assert_eq!(c.get_error(), gl::INVALID_VALUE, "alignment {a}");
    }
    // PIXEL_PACK_BUFFER and friends are no pixel-store pname.
    c.pixel_storei(gl::PIXEL_PACK_BUFFER, 0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
}

/// The texels of level 0 as RGBA UNSIGNED_SHORT, read with the default pack modes.
fn texels16(c: &mut Context, w: usize, h: usize) -> Vec<u8> {
    let mut out = vec![0u8; w * h * 8];
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_SHORT, &mut out);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    out
}

fn set_unpack(c: &mut Context, m: Modes) {
    c.pixel_storei(gl::UNPACK_ROW_LENGTH, m.row_length as i32);
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, m.skip_rows as i32);
    c.pixel_storei(gl::UNPACK_SKIP_PIXELS, m.skip_pixels as i32);
    c.pixel_storei(gl::UNPACK_ALIGNMENT, m.alignment.max(1) as i32);
    c.pixel_storei(gl::UNPACK_SWAP_BYTES, i32::from(m.swap));
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// 3x2 RGBA elements whose two (or four) bytes all differ, so a swap that is not done shows.
fn elems(size: usize) -> Vec<u32> {
    (0..24u32)
        .map(|k| {
            let hi = 20 + k * 9;
            if size == 2 {
                (hi << 8) | (255 - hi)
            } else {
                (hi << 24) | ((255 - hi) << 16) | (k << 8) | 7
            }
        })
        .collect()
}

#[test]
fn unpack_skips_row_length_and_swap_are_honoured() {
    for (ty, size) in [
        (gl::UNSIGNED_SHORT, 2),
        (gl::SHORT, 2),
        (gl::UNSIGNED_INT, 4),
        (gl::INT, 4),
        (gl::FLOAT, 4),
        (gl::UNSIGNED_BYTE, 1),
    ] {
        let e: Vec<u32> = match ty {
            gl::FLOAT => (0..24).map(|k| (k as f32 / 23.0).to_bits()).collect(),
            gl::UNSIGNED_BYTE => (0..24).map(|k| 10 * k).collect(),
            _ => elems(size),
        };
        let plain = embed(Modes::default(), 3, 2, 4, size, &e);
        let mut a = ctx();
        a.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
        a.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA16 as i32,
            3,
            2,
            0,
            gl::RGBA,
            ty,
            Some(&plain),
        );
        let want = texels16(&mut a, 3, 2);
        for m in [
            Modes {
                skip_rows: 2,
                skip_pixels: 1,
                row_length: 5,
                alignment: 8,
                swap: true,
            },
            Modes {
                skip_rows: 1,
                skip_pixels: 0,
                row_length: 0,
                alignment: 1,
                swap: true,
            },
            Modes {
                skip_rows: 0,
                skip_pixels: 3,
                row_length: 7,
                alignment: 4,
                swap: false,
            },
        ] {
            let data = embed(m, 3, 2, 4, size, &e);
            let mut b = ctx();
            set_unpack(&mut b, m);
            b.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA16 as i32,
                3,
                2,
                0,
                gl::RGBA,
                ty,
                Some(&data),
            );
            assert_eq!(b.get_error(), gl::NO_ERROR);
            assert_eq!(texels16(&mut b, 3, 2), want, "TexImage2D type {ty:#x}");
            // TexSubImage2D: the same data over a cleared level.
            set_unpack(
                &mut b,
                Modes {
                    alignment: 4,
                    ..Modes::default()
                },
            );
            b.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA16 as i32,
                3,
                2,
                0,
                gl::RGBA,
                ty,
                None,
            );
            set_unpack(&mut b, m);
            b.tex_sub_image_2d(gl::TEXTURE_2D, 0, 0, 0, 3, 2, gl::RGBA, ty, &data);
            assert_eq!(b.get_error(), gl::NO_ERROR);
            assert_eq!(texels16(&mut b, 3, 2), want, "TexSubImage2D type {ty:#x}");
        }
    }
}

#[test]
fn glu_build_2d_mipmaps_reads_with_the_skips_and_restores_them() {
    let e: Vec<u32> = (0..64).map(|k| (k * 37 % 256) as u32).collect();
    let mut a = ctx();
    let plain = embed(
        Modes {
            alignment: 1,
            ..Modes::default()
        },
        4,
        4,
        4,
        1,
        &e,
    );
    assert_eq!(
        glu::build_2d_mipmaps(
            &mut a,
            gl::TEXTURE_2D,
            4,
            4,
            4,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            &plain
        ),
        0
    );
    let m = Modes {
        skip_rows: 3,
        skip_pixels: 2,
        row_length: 9,
        alignment: 8,
        swap: true,
    };
    let data = embed(m, 4, 4, 4, 1, &e);
    let mut b = ctx();
    set_unpack(&mut b, m);
    assert_eq!(
        glu::build_2d_mipmaps(
            &mut b,
            gl::TEXTURE_2D,
            4,
            4,
            4,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            &data
        ),
        0
    );
    assert_eq!(b.get_error(), gl::NO_ERROR);
    for level in 0..3 {
        let mut x = vec![0u8; 64];
        let mut y = vec![0u8; 64];
        a.get_tex_image(gl::TEXTURE_2D, level, gl::RGBA, gl::UNSIGNED_BYTE, &mut x);
        b.get_tex_image(gl::TEXTURE_2D, level, gl::RGBA, gl::UNSIGNED_BYTE, &mut y);
        assert_eq!(x, y, "level {level}");
    }
    for (pname, v) in [
        (gl::UNPACK_SKIP_ROWS, 3),
        (gl::UNPACK_SKIP_PIXELS, 2),
        (gl::UNPACK_ROW_LENGTH, 9),
        (gl::UNPACK_ALIGNMENT, 8),
        (gl::UNPACK_SWAP_BYTES, 1),
    ] {
        assert_eq!(get_i(&mut b, pname), v, "{pname:#x} restored");
    }
    // One byte short of the skips and the image: GLU_INVALID_VALUE, nothing specified.
    let mut c = ctx();
    set_unpack(&mut c, m);
    let short = &data[..data.len() - 1];
    assert_eq!(
        glu::build_2d_mipmaps(
            &mut c,
            gl::TEXTURE_2D,
            4,
            4,
            4,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            short
        ),
        glu::GLU_INVALID_VALUE
    );
    let mut x = vec![7u8; 64];
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut x);
    assert!(x.iter().all(|&b| b == 7), "no level 0");
}

#[test]
fn short_data_with_skips_is_an_error_that_changes_nothing() {
    let m = Modes {
        skip_rows: 2,
        skip_pixels: 1,
        row_length: 5,
        alignment: 4,
        swap: false,
    };
    let e: Vec<u32> = (0..16).map(|k| 200 - k * 9).collect();
    let data = embed(m, 2, 2, 4, 1, &e);
    let mut c = ctx();
    // A level of known texels, then the uploads that must not touch it.
    let known = vec![99u8; 16];
    c.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&known),
    );
    set_unpack(&mut c, m);
    let short = &data[..data.len() - 1];
    let before = {
        let mut x = vec![0u8; 16];
        c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut x);
        x
    };
    // Without the skips (20-byte rows, 28 bytes) the short slice would be long enough: they are
    // in the check.
    assert!(short.len() >= 20 + 8);
    c.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(short),
    );
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        2,
        2,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        short,
    );
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    // Skips no slice can hold: the same error, no overflow.
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, i32::MAX);
    c.pixel_storei(gl::UNPACK_ROW_LENGTH, i32::MAX);
    c.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        2,
        2,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &data,
    );
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&data),
    );
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    let mut after = vec![0u8; 16];
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut after);
    assert_eq!(after, before, "the level is unchanged");
    // NULL data reads nothing: no error whatever the skips.
    c.tex_image_2d(
        gl::TEXTURE_2D,
        1,
        gl::RGBA as i32,
        1,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None,
    );
    assert_eq!(c.get_error(), gl::NO_ERROR);
    // The exact length passes.
    set_unpack(&mut c, m);
    c.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        2,
        2,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &data,
    );
    assert_eq!(c.get_error(), gl::NO_ERROR);

    // ReadPixels: a slice short of the pack skips is INVALID_VALUE, nothing written.
    c.pixel_storei(gl::PACK_SKIP_ROWS, 2);
    c.pixel_storei(gl::PACK_SKIP_PIXELS, 1);
    c.pixel_storei(gl::PACK_ROW_LENGTH, 5);
    let need = 2 * 20 + 4 + 20 + 8;
    let mut out = vec![7u8; need - 1];
    c.read_pixels(0, 0, 2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert!(out.iter().all(|&b| b == 7));
    let mut out = vec![7u8; need];
    c.read_pixels(0, 0, 2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.pixel_storei(gl::PACK_SKIP_ROWS, i32::MAX);
    c.pixel_storei(gl::PACK_ROW_LENGTH, i32::MAX);
    let mut out = vec![7u8; 4096];
    c.read_pixels(0, 0, 2, 2, gl::RGBA, gl::UNSIGNED_SHORT, &mut out);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert!(out.iter().all(|&b| b == 7));
    // GetTexImage: the same, INVALID_OPERATION.
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert!(out.iter().all(|&b| b == 7));
}

#[test]
fn read_pixels_places_pixels_under_the_pack_modes() {
    // A 4x3 frame: the clear colour (10, 20, 30, 40)/255, pixel (1, 1) written by a scissored
    // clear to (200, 100, 50, 255)/255.
    let mut c = ctx();
    let k = |v: f32| v / 255.0;
    c.clear_color(k(10.0), k(20.0), k(30.0), k(40.0));
    c.clear(gl::COLOR_BUFFER_BIT);
    c.enable(gl::SCISSOR_TEST);
    c.scissor(1, 1, 1, 1);
    c.clear_color(k(200.0), k(100.0), k(50.0), 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.disable(gl::SCISSOR_TEST);
    let bg = [10u8, 20, 30, 40];
    let fg = [200u8, 100, 50, 255];
    // 2x2 from (0, 0) as RGB FLOAT, swapped, row length 3, skip 1 row and 2 pixels, alignment
    // 8: rows of 3·12 = 36 bytes padded to 40; the first pixel at 40 + 24 = 64, 128 in all.
    c.pixel_storei(gl::PACK_SWAP_BYTES, 1);
    c.pixel_storei(gl::PACK_ROW_LENGTH, 3);
    c.pixel_storei(gl::PACK_SKIP_ROWS, 1);
    c.pixel_storei(gl::PACK_SKIP_PIXELS, 2);
    c.pixel_storei(gl::PACK_ALIGNMENT, 8);
    let mut out = vec![0xEEu8; 128 + 5];
    c.read_pixels(0, 0, 2, 2, gl::RGB, gl::FLOAT, &mut out);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let mut want = vec![0xEEu8; out.len()];
    for (j, i, px) in [(0, 0, bg), (0, 1, bg), (1, 0, bg), (1, 1, fg)] {
        for (n, &v) in px[..3].iter().enumerate() {
            // v/255 as a float, its bytes the other way round from the native order.
            let mut b = ((f64::from(v) / 255.0) as f32).to_ne_bytes();
            b.reverse();
            let at = 64 + j * 40 + i * 12 + n * 4;
            want[at..at + 4].copy_from_slice(&b);
        }
    }
    assert_eq!(out, want);
    // One byte short: INVALID_VALUE, nothing written.
    let mut short = vec![0xEEu8; 127];
    c.read_pixels(0, 0, 2, 2, gl::RGB, gl::FLOAT, &mut short);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert!(short.iter().all(|&b| b == 0xEE));
}
