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
        for (min, max) in [(f32::NAN, 1000.0), (-1000.0, f32::NAN), (f32::NAN, f32::NAN)] {
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
