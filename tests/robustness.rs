//! Regression tests for issue #11: inputs GL accepts (or must reject with an error) that made
//! the crate panic, hang, overflow or abort. Each test failed before its fix. A "prompt" test
//! runs its calls on a thread and fails when they take more than a few seconds: a bound on
//! correctness (the call must not loop over a huge user-chosen count), not a speed test.

use std::sync::mpsc;
use std::time::Duration;

use fixedgl::{gl, Context};

/// Runs `f` on a thread; fails the test if it panics or does not finish within `secs` seconds.
/// (A thread that never finishes is left behind; the test process ends all the same.)
fn within<T: Send + 'static>(secs: u64, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    match rx.recv_timeout(Duration::from_secs(secs)) {
        Ok(v) => v,
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("did not finish within {secs} s"),
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("panicked"),
    }
}

fn ctx(w: u32, h: u32) -> Context {
    match Context::new(w, h) {
        Ok(c) => c,
        Err(e) => panic!("Context::new({w}, {h}): {e}"),
    }
}

/// Texture LOD parameters GL accepts in any order and any float value (GL 2.1 §3.8.4, §3.8.8).
mod lod {
    use super::*;

    /// A 1x1 texture, NEAREST, bound and enabled on unit 0.
    fn one_texel(c: &mut Context) {
        c.bind_texture(gl::TEXTURE_2D, 1);
        c.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            1,
            1,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Some(&[255, 0, 0, 255]),
        );
        c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
        c.enable(gl::TEXTURE_2D);
    }

    fn triangle(c: &mut Context) {
        c.begin(gl::TRIANGLES);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (0.0, 1.0)] {
            c.tex_coord2f(x, y);
            c.vertex2f(x, y);
        }
        c.end();
    }

    /// The repro: MIN_LOD 2000 > MAX_LOD 1000 made `f32::clamp` panic in the sampler.
    #[test]
    fn min_lod_above_max_lod_draws() {
        let mut c = ctx(16, 16);
        one_texel(&mut c);
        c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_MIN_LOD, 2000.0);
        triangle(&mut c);
        let _ = c.to_image();
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    /// NaN in either LOD bound (accepted by TexParameterf) must not panic either.
    #[test]
    fn nan_lod_bounds_draw() {
        for (min, max) in [
            (f32::NAN, 1000.0),
            (-1000.0, f32::NAN),
            (f32::NAN, f32::NAN),
        ] {
            let mut c = ctx(16, 16);
            one_texel(&mut c);
            c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_MIN_LOD, min);
            c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_MAX_LOD, max);
            c.tex_envf(gl::TEXTURE_FILTER_CONTROL, gl::TEXTURE_LOD_BIAS, f32::NAN);
            triangle(&mut c);
            let _ = c.to_image();
            assert_eq!(c.get_error(), gl::NO_ERROR);
        }
    }

    /// MIN_LOD > MAX_LOD: λ is min(λ, MAX_LOD) then max(·, MIN_LOD), llvmpipe's order, so MIN_LOD
    /// wins. A mipmapped 4x4 texture with one colour per level, drawn at λ = 0: MIN_LOD 2 and
    /// MAX_LOD 1 select level 2.
    #[test]
    fn min_lod_wins_over_max_lod() {
        let mut c = ctx(4, 4);
        c.bind_texture(gl::TEXTURE_2D, 1);
        let colours: [[u8; 4]; 3] = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]];
        for (level, size) in [(0, 4), (1, 2), (2, 1)] {
            let texels: Vec<u8> = colours[level as usize].repeat(size * size);
            c.tex_image_2d(
                gl::TEXTURE_2D,
                level,
                gl::RGBA as i32,
                size as i32,
                size as i32,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                Some(&texels),
            );
        }
        c.tex_parameteri(
            gl::TEXTURE_2D,
            gl::TEXTURE_MIN_FILTER,
            gl::NEAREST_MIPMAP_NEAREST as i32,
        );
        c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_MIN_LOD, 2.0);
        c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_MAX_LOD, 1.0);
        c.enable(gl::TEXTURE_2D);
        c.begin(gl::QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            c.tex_coord2f((x + 1.0) / 2.0, (y + 1.0) / 2.0);
            c.vertex2f(x, y);
        }
        c.end();
        let img = c.to_image();
        assert_eq!(img.get_pixel(1, 1).0, colours[2]);
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }
}

/// ReadPixels sizes: every product of user values is checked (GL 2.1 §4.3.2).
mod readback {
    use super::*;

    /// The repro: the size check overflowed to 0 and the loop ran ~2^60 times.
    #[test]
    fn huge_read_into_empty_slice_is_invalid_value_promptly() {
        let err = within(10, || {
            let mut c = ctx(8, 8);
            c.read_pixels(0, 0, 1 << 30, 1 << 30, gl::RGBA, gl::FLOAT, &mut []);
            c.get_error()
        });
        assert_eq!(err, gl::INVALID_VALUE);
    }

    /// Every combination of extreme sizes and types: a prompt INVALID_VALUE, never a wrap.
    #[test]
    fn extreme_sizes_are_invalid_value_promptly() {
        within(10, || {
            let mut c = ctx(8, 8);
            for ty in [gl::UNSIGNED_BYTE, gl::UNSIGNED_SHORT, gl::FLOAT] {
                for (w, h) in [
                    (i32::MAX, i32::MAX),
                    (i32::MAX, 2),
                    (2, i32::MAX),
                    (1 << 16, 1 << 16),
                ] {
                    let mut out = [0u8; 64];
                    c.read_pixels(0, 0, w, h, gl::RGBA, ty, &mut out);
                    assert_eq!(c.get_error(), gl::INVALID_VALUE, "{w}x{h} type {ty:#x}");
                }
            }
        });
    }

    /// A zero width with a huge height (or the reverse) needs no bytes, and reads nothing: it
    /// must not walk 2^31 empty rows.
    #[test]
    fn empty_read_with_huge_other_side_is_prompt() {
        within(10, || {
            let mut c = ctx(8, 8);
            c.read_pixels(0, 0, 0, i32::MAX, gl::RGBA, gl::UNSIGNED_BYTE, &mut []);
            c.read_pixels(0, 0, i32::MAX, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut []);
            assert_eq!(c.get_error(), gl::NO_ERROR);
        });
    }

    /// A request far outside the window, with a buffer big enough, reads (and writes) nothing
    /// and visits only the window's pixels, not the whole rectangle.
    #[test]
    fn read_far_outside_the_window_is_prompt() {
        within(10, || {
            let mut c = ctx(8, 8);
            let mut out = vec![7u8; 1 << 20];
            c.read_pixels(
                i32::MIN,
                i32::MIN,
                1 << 18,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                &mut out,
            );
            c.read_pixels(
                i32::MAX,
                i32::MAX,
                1 << 18,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                &mut out,
            );
            c.read_pixels(
                -4,
                -4,
                1 << 9,
                1 << 9,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                &mut out,
            );
            assert_eq!(c.get_error(), gl::NO_ERROR);
            // The first pixel read of the last call lies outside the window: untouched.
            assert_eq!(out[..4], [7, 7, 7, 7]);
        });
    }
}

/// Pixel store arithmetic (GL 2.1 §3.6.4): sizes from the caller never wrap.
mod pixel_store {
    use fixedgl::texture::unpack_extent;

    /// 2^31 x 2^31 pixels of 16 bytes, or ROW_LENGTH 2^31 - 1: more bytes than a usize counts.
    /// The extent saturates, so no slice passes the length check that follows it.
    #[test]
    fn unpack_extent_saturates() {
        let (_, need) = unpack_extent(i32::MAX, i32::MAX, 4, 4, 4, 0);
        assert_eq!(need, usize::MAX);
        let (stride, need) = unpack_extent(1, i32::MAX, 4, 4, 8, i32::MAX);
        assert!(stride >= 16 * (i32::MAX as usize));
        assert_eq!(need, usize::MAX);
    }
}

/// Rasterisation of extreme window coordinates (GL 2.1 §2.11.1, §3.4, §3.5): nothing may
/// overflow an integer, whatever the vertices, viewport and mode. Run with
/// `-C overflow-checks=on` to see a wrap as a panic.
mod raster {
    use super::*;

    const VALUES: [f32; 10] = [
        0.0,
        0.5,
        -1.0,
        1e10,
        -3e38,
        3e38,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        1e-30,
    ];

    fn draw_extremes(c: &mut Context, mode: u32) {
        for (i, &a) in VALUES.iter().enumerate() {
            for &b in &VALUES {
                c.begin(mode);
                c.vertex4f(a, b, 0.0, 1.0);
                c.vertex4f(b, -a, 0.5, VALUES[(i + 3) % VALUES.len()]);
                c.vertex4f(0.25, 0.75, a, 1.0);
                c.end();
            }
        }
    }

    /// Filled, line and point polygons, and lines and points, with huge, infinite and NaN
    /// coordinates under ordinary and extreme viewports, wide lines and big points.
    #[test]
    fn extreme_coordinates_never_overflow() {
        within(120, || {
            let mut c = ctx(64, 64);
            let viewports = [
                [0, 0, 64, 64],
                [i32::MAX, i32::MAX, 16384, 16384],
                [i32::MIN, i32::MIN, 16384, 16384],
                [i32::MIN / 2, -8000, i32::MAX, i32::MAX],
                [-1_000_000_000, -1_000_000_000, 16384, 16384],
                [-8160, -8160, 16384, 16384],
            ];
            for vp in viewports {
                c.viewport(vp[0], vp[1], vp[2], vp[3]);
                for (poly, width) in [(gl::FILL, 1.0), (gl::LINE, 1e9), (gl::POINT, f32::MAX)] {
                    c.polygon_mode(gl::FRONT_AND_BACK, poly);
                    c.line_width(width);
                    c.point_size(width);
                    for mode in [gl::TRIANGLES, gl::LINES, gl::POINTS, gl::LINE_LOOP] {
                        draw_extremes(&mut c, mode);
                    }
                    let _ = c.to_image();
                }
            }
            assert_eq!(c.get_error(), gl::NO_ERROR);
        });
    }
}

/// Draw calls whose counts nothing bounds (GL 2.1 §2.8, §5.4): no allocation or loop may be
/// proportional to a count that no data backs.
mod draw_counts {
    use super::*;

    /// The repro: compiling DrawArrays(POINTS, 0, i32::MAX) with no array enabled
    /// collected 2^31 indices (16 GiB) and aborted. Nothing is drawn (VERTEX_ARRAY is
    /// disabled), so nothing is stored, and compiling, calling and drawing it are prompt.
    #[test]
    fn compiled_draw_of_huge_count_without_arrays_is_prompt() {
        let err = within(10, || {
            let mut c = ctx(8, 8);
            c.new_list(1, gl::COMPILE);
            c.draw_arrays(gl::POINTS, 0, i32::MAX);
            c.draw_arrays(gl::TRIANGLES, i32::MAX, i32::MAX);
            c.end_list();
            c.call_list(1);
            c.draw_arrays(gl::POINTS, 0, i32::MAX);
            c.new_list(2, gl::COMPILE_AND_EXECUTE);
            c.draw_arrays(gl::POINTS, 0, i32::MAX);
            c.end_list();
            c.get_error()
        });
        assert_eq!(err, gl::NO_ERROR);
    }

    /// With a vertex array of 3 elements, a huge count is INVALID_OPERATION when the list
    /// runs (the draw compiles as it is), and nothing is expanded at compile time.
    #[test]
    fn compiled_draw_past_the_array_errs_when_run() {
        let err = within(10, || {
            let mut c = ctx(8, 8);
            c.enable_client_state(gl::VERTEX_ARRAY);
            c.vertex_pointer(2, gl::FLOAT, 0, &[0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0][..]);
            c.new_list(1, gl::COMPILE);
            c.draw_arrays(gl::POINTS, 0, i32::MAX);
            c.end_list();
            assert_eq!(c.get_error(), gl::NO_ERROR);
            c.call_list(1);
            c.get_error()
        });
        assert_eq!(err, gl::INVALID_OPERATION);
    }
}
