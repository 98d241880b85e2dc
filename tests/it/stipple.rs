//! Line stipple (GL 2.1 §3.4.2) and polygon stipple (§3.5.6): state, queries, unpack and pack
//! modes, display lists, attribute groups, errors, and pictures pixel for pixel against the
//! driver (llvmpipe's draw-module stipple: restart at every LINES segment, a strip running on
//! over whole stipple pixels, each run drawn as a line of its own; the polygon pattern aligned
//! to the window, for filled polygons only).

use fixedgl::{gl, Context};

const SIZE: u32 = 96;

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

fn int(c: &mut Context, pname: u32) -> i32 {
    let mut v = [i32::MIN];
    c.get_integerv(pname, &mut v);
    v[0]
}

/// A pattern with a different bit in every row and column: row r has bits r and 31 - r, and
/// the bits of r's binary digits.
fn pattern() -> [u8; 128] {
    let mut p = [0u8; 128];
    for r in 0..32 {
        for x in [r, 31 - r, (r * 7) % 32] {
            p[r * 4 + x / 8] |= 0x80 >> (x % 8);
        }
    }
    p
}

#[test]
fn line_stipple_state() {
    let mut c = ctx();
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_PATTERN), 0xFFFF);
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_REPEAT), 1);
    c.line_stipple(0, 0xAAAA);
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_REPEAT), 1);
    c.line_stipple(300, 0x1234);
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_REPEAT), 256);
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_PATTERN), 0x1234);
    let mut f = [0.0];
    c.get_floatv(gl::LINE_STIPPLE_PATTERN, &mut f);
    assert_eq!(f, [4660.0]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.begin(gl::POINTS);
    c.line_stipple(2, 1);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(int(&mut c, gl::LINE_STIPPLE_REPEAT), 256);
}

#[test]
fn polygon_stipple_unpacks_and_packs_with_the_pixel_modes() {
    let mut c = ctx();
    // Initially all ones.
    let mut out = [0u8; 128];
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, [0xFF; 128]);
    let p = pattern();
    c.polygon_stipple(&p);
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, p);
    // The same pattern given LSB first, two bytes of row padding and a skipped row and pixel.
    c.pixel_storei(gl::UNPACK_LSB_FIRST, 1);
    c.pixel_storei(gl::UNPACK_ROW_LENGTH, 40);
    c.pixel_storei(gl::UNPACK_ALIGNMENT, 2);
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, 1);
    c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 1);
    let mut moved = vec![0u8; 6 * 33];
    for r in 0..32 {
        for x in 0..32 {
            if p[r * 4 + x / 8] & (0x80 >> (x % 8)) != 0 {
                let bit = x + 1;
                moved[(r + 1) * 6 + bit / 8] |= 1 << (bit % 8);
            }
        }
    }
    c.polygon_stipple(&[0u8; 128]);
    c.polygon_stipple(&moved);
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, p);
    // Too short for these modes: INVALID_OPERATION, nothing changes.
    c.polygon_stipple(&moved[..6 * 32 + 4]);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, p);
    // Packed the same way.
    c.pixel_storei(gl::PACK_LSB_FIRST, 1);
    c.pixel_storei(gl::PACK_ROW_LENGTH, 40);
    c.pixel_storei(gl::PACK_ALIGNMENT, 2);
    c.pixel_storei(gl::PACK_SKIP_ROWS, 1);
    c.pixel_storei(gl::PACK_SKIP_PIXELS, 1);
    let mut packed = vec![0u8; 6 * 33];
    c.get_polygon_stipple(&mut packed);
    assert_eq!(packed[6..], moved[6..]);
    let mut short = vec![0u8; 100];
    c.get_polygon_stipple(&mut short);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(short, vec![0u8; 100]);
}

#[test]
fn lists_keep_the_pattern_unpacked_at_compile_time() {
    let mut c = ctx();
    let p = pattern();
    let list = c.gen_lists(1);
    c.pixel_storei(gl::UNPACK_LSB_FIRST, 1);
    c.new_list(list, gl::COMPILE);
    c.polygon_stipple(&p);
    c.end_list();
    // Not executed under COMPILE.
    let mut out = [0u8; 128];
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, [0xFF; 128]);
    // Run with other modes: the pattern as unpacked LSB first at compile time.
    c.pixel_storei(gl::UNPACK_LSB_FIRST, 0);
    c.pixel_storei(gl::UNPACK_SKIP_ROWS, 3);
    c.call_list(list);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.get_polygon_stipple(&mut out);
    let reversed: Vec<u8> = p.iter().map(|b| b.reverse_bits()).collect();
    assert_eq!(out[..], reversed[..]);
}

#[test]
fn attribute_groups_save_the_stipples() {
    let mut c = ctx();
    let p = pattern();
    c.push_attrib(gl::POLYGON_STIPPLE_BIT);
    c.polygon_stipple(&p);
    c.pop_attrib();
    let mut out = [0u8; 128];
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, [0xFF; 128]);
    // POLYGON_BIT does not hold the pattern; ENABLE_BIT holds the enables.
    c.push_attrib(gl::POLYGON_BIT);
    c.polygon_stipple(&p);
    c.pop_attrib();
    c.get_polygon_stipple(&mut out);
    assert_eq!(out, p);
    c.push_attrib(gl::ENABLE_BIT);
    c.enable(gl::POLYGON_STIPPLE);
    c.enable(gl::LINE_STIPPLE);
    c.pop_attrib();
    assert!(!c.is_enabled(gl::POLYGON_STIPPLE) && !c.is_enabled(gl::LINE_STIPPLE));
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// A named drawing.
type Picture = (&'static str, fn(&mut Context));

/// Pictures whose every pixel is compared with the driver's.
fn pictures() -> Vec<Picture> {
    vec![
        ("lines restart, strips run on", |c| {
            c.ortho(0.0, 96.0, 0.0, 96.0, -1.0, 1.0);
            c.enable(gl::LINE_STIPPLE);
            c.line_stipple(1, 0x1C47);
            c.begin(gl::LINE_STRIP);
            for (x, y) in [(2.0, 5.0), (30.3, 9.0), (61.7, 5.0), (93.0, 20.2)] {
                c.vertex2f(x, y);
            }
            c.end();
            c.begin(gl::LINES);
            for (x, y) in [(2.0, 15.0), (30.3, 19.0), (30.3, 19.0), (61.7, 15.0)] {
                c.vertex2f(x, y);
            }
            c.end();
            c.line_stipple(3, 0x00FF);
            c.begin(gl::LINE_LOOP);
            for (x, y) in [(10.2, 30.1), (85.3, 33.3), (80.1, 90.2), (12.2, 70.9)] {
                c.vertex2f(x, y);
            }
            c.end();
        }),
        ("wide, steep, coloured, perspective", |c| {
            c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
            c.translatef(0.0, 0.0, -3.0);
            c.rotatef(60.0, 1.0, 0.0, 0.0);
            c.enable(gl::LINE_STIPPLE);
            c.line_stipple(2, 0x3F3F);
            c.line_width(4.0);
            c.begin(gl::LINES);
            c.color3f(1.0, 0.0, 0.0);
            c.vertex3f(-1.5, -1.0, 0.0);
            c.color3f(0.0, 0.0, 1.0);
            c.vertex3f(1.4, 1.3, 0.2);
            c.end();
            c.line_width(1.0);
            c.line_stipple(1, 0xA5A5);
            c.begin(gl::LINE_STRIP);
            c.color3f(0.0, 1.0, 0.0);
            c.vertex3f(-0.2, -1.8, 0.0);
            c.color3f(1.0, 1.0, 0.0);
            c.vertex3f(0.1, 1.9, 0.5);
            c.vertex3f(0.9, -1.2, -0.3);
            c.end();
        }),
        (
            "polygons: window-aligned, depth untouched where stippled out",
            |c| {
                c.polygon_stipple(&pattern());
                c.enable(gl::DEPTH_TEST);
                c.enable(gl::POLYGON_STIPPLE);
                c.color3f(1.0, 0.5, 0.0);
                c.begin(gl::TRIANGLES);
                c.vertex3f(-0.93, -0.9, 0.0);
                c.vertex3f(0.87, -0.7, 0.0);
                c.vertex3f(-0.1, 0.91, 0.0);
                c.end();
                // Behind the first: drawn only where the first one's stipple let nothing through.
                c.disable(gl::POLYGON_STIPPLE);
                c.color3f(0.0, 0.4, 1.0);
                c.begin(gl::QUADS);
                for (x, y) in [(-0.8, -0.8), (0.8, -0.8), (0.8, 0.8), (-0.8, 0.8)] {
                    c.vertex3f(x, y, 0.5);
                }
                c.end();
                // Lines, points and LINE-mode polygons are never polygon-stippled; with blending
                // (the general fragment path) the pattern still applies to filled polygons.
                c.enable(gl::POLYGON_STIPPLE);
                c.disable(gl::DEPTH_TEST);
                c.color3f(1.0, 1.0, 1.0);
                c.line_width(3.0);
                c.begin(gl::LINES);
                c.vertex2f(-0.95, 0.95);
                c.vertex2f(0.95, 0.9);
                c.end();
                c.point_size(7.0);
                c.begin(gl::POINTS);
                c.vertex2f(0.8, 0.8);
                c.end();
                c.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
                c.begin(gl::TRIANGLES);
                c.vertex2f(-0.9, 0.5);
                c.vertex2f(-0.5, 0.5);
                c.vertex2f(-0.7, 0.8);
                c.end();
                c.polygon_mode(gl::FRONT_AND_BACK, gl::FILL);
                c.enable(gl::BLEND);
                c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
                c.color4f(0.2, 1.0, 0.2, 0.5);
                c.begin(gl::QUADS);
                for (x, y) in [(0.3, 0.3), (0.95, 0.3), (0.95, 0.7), (0.3, 0.7)] {
                    c.vertex2f(x, y);
                }
                c.end();
            },
        ),
    ]
}

#[test]
fn stippled_pictures_are_stippled() {
    for (name, draw) in pictures() {
        let mut plain = ctx();
        let mut c = ctx();
        draw(&mut c);
        assert_eq!(c.get_error(), gl::NO_ERROR, "{name}");
        // The same without the stipple enables draws more.
        plain.start_recording();
        draw(&mut plain);
        let calls: Vec<_> = plain
            .stop_recording()
            .into_iter()
            .filter(|call| {
                !matches!(
                    call,
                    fixedgl::Call::Enable(gl::LINE_STIPPLE | gl::POLYGON_STIPPLE)
                )
            })
            .collect();
        let mut unstippled = ctx();
        unstippled.replay(&calls);
        let lit = |c: &mut Context| {
            c.to_image()
                .pixels()
                .filter(|p| p.0[..3] != [0, 0, 0])
                .count()
        };
        let (a, b) = (lit(&mut c), lit(&mut unstippled));
        assert!(
            a > 50 && a < b,
            "{name}: {a} lit pixels stippled, {b} without"
        );
    }
}

#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;

    #[test]
    fn pictures_match_the_driver_pixel_for_pixel() {
        for (name, draw) in pictures() {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            c.start_recording();
            draw(&mut c);
            let calls = c.stop_recording();
            gl.replay(&calls);
            assert_eq!(gl.get_error(), gl::NO_ERROR, "{name}");
            let cmp = compare(&c.to_image(), &gl.read_image(), 1);
            assert_eq!(cmp.differing_pixels, 0, "{name}: max {:?}", cmp.max_diff);
        }
    }

    /// The driver's GetPolygonStipple after the same calls, with unpack and pack modes and a
    /// display list compiled under other modes than it runs with.
    #[test]
    fn patterns_read_back_as_the_driver_reads_them() {
        let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
            return;
        };
        let mut c = ctx();
        c.start_recording();
        c.pixel_storei(gl::UNPACK_LSB_FIRST, 1);
        c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 3);
        c.pixel_storei(gl::UNPACK_ROW_LENGTH, 37);
        let mut data = pattern().to_vec();
        data.extend_from_slice(&pattern()[..60]);
        let list = c.gen_lists(1);
        c.new_list(list, gl::COMPILE);
        c.polygon_stipple(&data);
        c.end_list();
        c.pixel_storei(gl::UNPACK_LSB_FIRST, 0);
        c.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
        c.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
        c.polygon_stipple(&pattern());
        let mut first = vec![0x5Au8; 300];
        c.get_polygon_stipple(&mut first);
        assert_eq!(first[..128], pattern()[..]);
        c.call_list(list);
        c.pixel_storei(gl::PACK_SKIP_PIXELS, 5);
        c.pixel_storei(gl::PACK_SKIP_ROWS, 2);
        c.pixel_storei(gl::PACK_ALIGNMENT, 8);
        let calls = c.stop_recording();
        gl.replay(&calls);
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        let mut cpu = vec![0x5Au8; 300];
        c.get_polygon_stipple(&mut cpu);
        let mut driver = vec![0x5Au8; 300];
        // SAFETY: with these pack modes the driver writes 2 * 8 + 31 * 8 + 5 bytes < 300.
        unsafe { gl.raw().GetPolygonStipple(driver.as_mut_ptr()) };
        assert_eq!(cpu, driver);
        let mut r = [0; 2];
        // SAFETY: each query writes one integer.
        unsafe {
            gl.raw().GetIntegerv(gl::LINE_STIPPLE_PATTERN, &mut r[0]);
            gl.raw().GetIntegerv(gl::LINE_STIPPLE_REPEAT, &mut r[1]);
        }
        assert_eq!(r, [0xFFFF, 1]);
    }
}
