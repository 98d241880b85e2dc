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
    use fixedgl::pixel_store::PixelModes;

    /// 2^31 x 2^31 pixels of 16 bytes, ROW_LENGTH 2^31 - 1, or SKIP_ROWS 2^31 - 1 rows of
    /// 2^31 - 1 pixels: more bytes than a usize counts. The layout is None (every caller's
    /// short-data error), never a wrapped size a slice could pass.
    #[test]
    fn layout_overflow_is_none() {
        let modes = PixelModes::default();
        assert_eq!(modes.layout(i32::MAX, i32::MAX, 4, 4), None);
        let long_rows = PixelModes {
            row_length: i32::MAX,
            alignment: 8,
            ..modes
        };
        assert_eq!(long_rows.layout(1, i32::MAX, 4, 4), None);
        let skips = PixelModes {
            row_length: i32::MAX,
            skip_rows: i32::MAX,
            skip_pixels: i32::MAX,
            ..modes
        };
        assert_eq!(skips.layout(1, 1, 4, 4), None);
        // The same skips with one-byte pixels fit 64 bits, and need all of them.
        let l = skips.layout(1, 1, 1, 1).map(|l| l.need);
        let (r, p) = (i32::MAX as usize, i32::MAX as usize);
        assert_eq!(l, Some(r.next_multiple_of(4) * r + p + 1));
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

/// Allocation failure is GL_OUT_OF_MEMORY (or `Err` from `Context::new`), never an abort.
/// The real scenario runs in a child process under `ulimit -v` (see `limited`); the in-process
/// tests use requests no allocator can meet.
mod memory {
    use super::*;

    /// A data-less BufferData far past what any machine holds: OUT_OF_MEMORY, promptly, and the
    /// buffer keeps its old store.
    #[test]
    fn impossible_buffer_is_out_of_memory() {
        let mut c = ctx(8, 8);
        let mut b = [0u32; 1];
        c.gen_buffers(1, &mut b);
        c.bind_buffer(gl::ARRAY_BUFFER, b[0]);
        c.buffer_data(gl::ARRAY_BUFFER, 16, &[1u8; 16][..], gl::STATIC_DRAW);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        let before = c.state().clone();
        c.buffer_data(
            gl::ARRAY_BUFFER,
            isize::MAX / 2,
            fixedgl::Pointer::NULL,
            gl::STATIC_DRAW,
        );
        assert_eq!(c.get_error(), gl::OUT_OF_MEMORY);
        assert!(
            c.state() == &before,
            "an OUT_OF_MEMORY call changed the state"
        );
    }

    /// GenTextures(65536) until the namespace is spent: 2^32 - 1 names generated and never
    /// bound cost a few bytes in all (one run), not a tree node per name (tens of GiB; the
    /// issue measured 1.66 GB for 38 KB of such calls). Past the last name GenTextures is
    /// OUT_OF_MEMORY.
    #[test]
    fn generated_names_cost_no_memory_per_name() {
        within(60, || {
            let mut c = ctx(8, 8);
            let mut names = vec![0u32; 1 << 16];
            for _ in 0..(1 << 16) - 1 {
                c.gen_textures(1 << 16, &mut names);
            }
            assert_eq!(c.get_error(), gl::NO_ERROR);
            assert_eq!(names[(1 << 16) - 1], u32::MAX - ((1 << 16) - 1));
            c.gen_textures(1 << 16, &mut names);
            assert_eq!(c.get_error(), gl::OUT_OF_MEMORY);
            c.gen_textures((1 << 16) - 1, &mut names);
            assert_eq!(c.get_error(), gl::NO_ERROR);
            assert_eq!(names[(1 << 16) - 2], u32::MAX);
            assert_eq!(c.state().textures.names.len(), u64::from(u32::MAX));
            // A bound name becomes an object; a name only generated is not a texture.
            c.bind_texture(gl::TEXTURE_2D, 7);
            assert!(c.is_texture(7));
            assert!(!c.is_texture(8));
            c.delete_textures(2, &[9, 7]);
            assert_eq!(c.state().textures.names.len(), u64::from(u32::MAX) - 2);
            // GenTextures hands out names above every name in use (as Mesa does): with u32::MAX
            // in use there are none left, which it must say rather than search or wrap.
            c.gen_textures(1, &mut names);
            assert_eq!(c.get_error(), gl::OUT_OF_MEMORY);
        });
    }
}

/// The allocation-failure scenarios, each in a child process (this test binary, one
/// ignored test) under an address-space limit: they must end in OUT_OF_MEMORY, not an abort.
#[cfg(unix)]
mod limited {
    use super::*;
    use std::process::Command;

    /// Set by the parent, so that the child tests do nothing when run by `--ignored` without a
    /// limit (they would then really allocate gigabytes).
    const ENV: &str = "FIXEDGL_ROBUSTNESS_LIMITED";

    /// Runs ignored test `name` of this binary under `ulimit -v kib`; true when it passed.
    fn run_child(name: &str, kib: u64) -> bool {
        let Ok(exe) = std::env::current_exe() else {
            panic!("no current_exe");
        };
        // The test's path in the one integration binary (tests/it/main.rs).
        let name = format!("robustness::{name}");
        let script = format!(
            "ulimit -v {kib} && exec \"$0\" --exact {name} --ignored --test-threads=1 --quiet"
        );
        let out = Command::new("sh")
            .arg("-c")
            .arg(script)
            .arg(exe)
            .env(ENV, "1")
            .env("RAYON_NUM_THREADS", "2")
            .output();
        match out {
            Ok(o) if o.status.success() => true,
            Ok(o) => {
                eprintln!(
                    "child {name} under ulimit -v {kib}: {}\n{}{}",
                    o.status,
                    String::from_utf8_lossy(&o.stdout),
                    String::from_utf8_lossy(&o.stderr)
                );
                false
            }
            Err(e) => panic!("could not run the child: {e}"),
        }
    }

    fn limited() -> bool {
        std::env::var_os(ENV).is_some()
    }

    /// 40 x BufferData(256 MiB, NULL) under a 1 GB limit: OUT_OF_MEMORY after a few, and the
    /// context goes on working.
    #[test]
    fn buffers_past_the_address_space_are_out_of_memory() {
        assert!(run_child("limited::child_buffers", 1_000_000));
    }

    #[test]
    #[ignore = "run by buffers_past_the_address_space_are_out_of_memory under ulimit -v"]
    fn child_buffers() {
        if !limited() {
            return;
        }
        let mut c = ctx(8, 8);
        let mut names = [0u32; 40];
        c.gen_buffers(40, &mut names);
        let mut oom = false;
        for &b in &names {
            c.bind_buffer(gl::ARRAY_BUFFER, b);
            c.buffer_data(
                gl::ARRAY_BUFFER,
                256 << 20,
                fixedgl::Pointer::NULL,
                gl::STATIC_DRAW,
            );
            match c.get_error() {
                gl::NO_ERROR => {}
                gl::OUT_OF_MEMORY => oom = true,
                e => panic!("error {e:#x}"),
            }
        }
        assert!(oom, "40 x 256 MiB fitted in 1 GB?");
        c.clear(gl::COLOR_BUFFER_BIT);
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    /// 40 textures of 2048 x 2048 (64 MiB of texels each) under an 800 MB limit:
    /// OUT_OF_MEMORY after a few, the failed call changing nothing, and drawing goes on.
    #[test]
    fn textures_past_the_address_space_are_out_of_memory() {
        assert!(run_child("limited::child_textures", 800_000));
    }

    #[test]
    #[ignore = "run by textures_past_the_address_space_are_out_of_memory under ulimit -v"]
    fn child_textures() {
        if !limited() {
            return;
        }
        let mut c = ctx(8, 8);
        let mut oom = false;
        for name in 1..=40 {
            c.bind_texture(gl::TEXTURE_2D, name);
            let before = c.state().clone();
            c.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA as i32,
                2048,
                2048,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                None,
            );
            match c.get_error() {
                gl::NO_ERROR => {}
                gl::OUT_OF_MEMORY => {
                    oom = true;
                    assert!(
                        c.state() == &before,
                        "an OUT_OF_MEMORY call changed the state"
                    );
                }
                e => panic!("error {e:#x}"),
            }
        }
        assert!(oom, "40 x 64 MiB fitted in 800 MB?");
        c.begin(gl::POINTS);
        c.vertex2f(0.0, 0.0);
        c.end();
        let _ = c.to_image();
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    /// A DrawElements of 64M UNSIGNED_BYTE indices compiled into a list expands to 64M calls:
    /// under a 1 GB limit that is OUT_OF_MEMORY at compile time, not an abort.
    #[test]
    fn huge_compiled_draw_elements_is_out_of_memory() {
        assert!(run_child("limited::child_compiled_elements", 1_000_000));
    }

    #[test]
    #[ignore = "run by huge_compiled_draw_elements_is_out_of_memory under ulimit -v"]
    fn child_compiled_elements() {
        if !limited() {
            return;
        }
        let mut c = ctx(8, 8);
        c.enable_client_state(gl::VERTEX_ARRAY);
        let verts = vec![0.0f32; 2 * 256];
        c.vertex_pointer(2, gl::FLOAT, 0, &verts[..]);
        let idx = vec![0u8; 64 << 20];
        c.new_list(1, gl::COMPILE);
        c.draw_elements(gl::POINTS, 64 << 20, gl::UNSIGNED_BYTE, &idx[..]);
        assert_eq!(c.get_error(), gl::OUT_OF_MEMORY);
        c.end_list();
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    /// A 16384 x 16384 context needs ~2.3 GiB: under a 1 GB limit `Context::new` is `Err`.
    #[test]
    fn huge_context_is_err() {
        assert!(run_child("limited::child_context", 1_000_000));
    }

    #[test]
    #[ignore = "run by huge_context_is_err under ulimit -v"]
    fn child_context() {
        if !limited() {
            return;
        }
        assert!(Context::new(16384, 16384).is_err());
        assert!(Context::new(64, 64).is_ok());
    }
}

/// The run-length name set behind GenTextures: merging, splitting, equality by content.
mod name_set {
    use fixedgl::texture::NameSet;

    #[test]
    fn runs_merge_split_and_compare_by_content() {
        let mut a = NameSet::default();
        a.insert_range(1, 10);
        a.insert_range(12, 20);
        a.insert(11); // joins the two runs
        a.remove(5); // splits one
        a.insert_range(u32::MAX - 1, u32::MAX);
        assert!(a.contains(4) && !a.contains(5) && a.contains(6) && a.contains(11));
        assert!(a.contains(u32::MAX) && !a.contains(0) && !a.contains(21));
        assert_eq!(a.len(), 19 + 2);
        assert_eq!(a.last(), Some(u32::MAX));
        let mut b = NameSet::default();
        for n in (1..=20).filter(|&n| n != 5) {
            b.insert(n);
        }
        b.insert(u32::MAX);
        b.insert(u32::MAX - 1);
        assert_eq!(a, b);
        a.insert_range(0, u32::MAX);
        assert_eq!(a.len(), 1 << 32);
    }
}

/// Display-list nesting (GL 2.1 §5.4, MAX_LIST_NESTING): a list that calls itself is legal
/// GL; once it runs MAX_LIST_NESTING deep, further CallLists are ignored. The recursion is
/// that deep at most, and must fit an ordinary thread's stack (the test harness's 2 MiB).
mod list_nesting {
    use super::*;

    #[test]
    fn self_calling_list_stops_at_max_nesting() {
        let err = within(10, || {
            let mut c = ctx(8, 8);
            c.new_list(1, gl::COMPILE);
            c.color3f(1.0, 0.0, 0.0);
            c.call_list(1);
            c.end_list();
            c.call_list(1);
            c.call_lists(3, gl::UNSIGNED_BYTE, &[1, 1, 1]);
            c.get_error()
        });
        assert_eq!(err, gl::NO_ERROR);
    }
}

/// GenBuffers names (GL 2.1 §2.9): many generated names cost nothing each, the search for
/// unused names does not rescan them, and a spent namespace is OUT_OF_MEMORY, not a hang.
mod buffer_names {
    use super::*;

    #[test]
    fn gen_buffers_through_the_namespace_is_prompt() {
        within(60, || {
            let mut c = ctx(8, 8);
            let mut names = vec![0u32; 1 << 16];
            for _ in 0..(1 << 16) - 1 {
                c.gen_buffers(1 << 16, &mut names);
            }
            assert_eq!(c.get_error(), gl::NO_ERROR);
            assert_eq!(names[(1 << 16) - 1], u32::MAX - ((1 << 16) - 1));
            let before = c.state().clone();
            c.gen_buffers(1 << 16, &mut names);
            assert_eq!(c.get_error(), gl::OUT_OF_MEMORY);
            assert!(
                c.state() == &before,
                "an OUT_OF_MEMORY GenBuffers reserved names"
            );
            // Freed names are found again, lowest first.
            c.delete_buffers(2, &[70_000, 5]);
            let mut two = [0u32; 2];
            c.gen_buffers(2, &mut two);
            assert_eq!((c.get_error(), two), (gl::NO_ERROR, [5, 70_000]));
        });
    }
}
