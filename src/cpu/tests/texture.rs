//! Sampling and environment tests; every expected value is worked out by hand from the GL 2.1
//! formulas cited on each test (§3.8.7 wrap, §3.8.8 filters and λ, §3.8.13 table 3.21,
//! §3.8.14 depth comparison).

use std::sync::Arc;

use glam::Vec4;

use super::*;
use crate::cpu::lanes::LANES;
use crate::texture::{Level, TexObject};

/// A level of `w` x `h` texels of base format `base`, from `f(i, j)`.
fn level(w: i32, h: i32, base: u32, f: impl Fn(i32, i32) -> [f32; 4]) -> Level {
    let mut texels = Vec::new();
    for j in 0..h {
        for i in 0..w {
            texels.push(f(i, j));
        }
    }
    Level {
        depth: 1,
        width: w,
        height: h,
        internal_format: base as i32,
        base,
        texels,
    }
}

/// A sampler over `obj` with the given environment, as `Sampler::new` would make it.
fn sampler(obj: TexObject, env: u32) -> Sampler {
    let mut state = State::new(4, 4);
    state.enables.texture_2d[0] = true;
    state.textures.defaults[1] = Arc::new(obj);
    state.textures.units[0].env_mode = env;
    state.textures.units[0].env_color = Vec4::new(1.0, 0.0, 0.5, 0.25);
    Sampler::new(&state, 0).expect("complete texture")
}

fn obj_with(levels: Vec<Level>, min: u32, mag: u32) -> TexObject {
    let mut o = TexObject {
        min_filter: min,
        mag_filter: mag,
        ..TexObject::default()
    };
    for (k, l) in levels.into_iter().enumerate() {
        o.levels[k] = Some(l);
    }
    o
}

fn close(a: [f32; 4], b: [f32; 4]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-5)
}

#[test]
fn wrap_modes_pick_the_spec_texels() {
    // §3.8.7/3.8.8, n = 4: i = floor(u) with u = 4s, then the wrap rule.
    assert_eq!(wrap_nearest(gl::REPEAT, 1.25, 4), Some(1)); // floor(5) mod 4
    assert_eq!(wrap_nearest(gl::REPEAT, -0.1, 4), Some(3)); // floor(-0.4) = -1 mod 4
    assert_eq!(wrap_nearest(gl::CLAMP_TO_EDGE, -0.3, 4), Some(0));
    assert_eq!(wrap_nearest(gl::CLAMP_TO_EDGE, 1.0, 4), Some(3)); // i = 4 taken as 3
    assert_eq!(wrap_nearest(gl::CLAMP, 1.7, 4), Some(3));
    assert_eq!(wrap_nearest(gl::CLAMP_TO_BORDER, -0.1, 4), None);
    assert_eq!(wrap_nearest(gl::CLAMP_TO_BORDER, 0.6, 4), Some(2));
    // Mirrored: floor(1.25) = 1 is odd, s' = 1 - 0.25 = 0.75, i = 3.
    assert_eq!(wrap_nearest(gl::MIRRORED_REPEAT, 1.25, 4), Some(3));
    assert_eq!(wrap_nearest(gl::MIRRORED_REPEAT, 2.25, 4), Some(1));
    // LINEAR, s = 0: u = -0.5, i0 = -1, i1 = 0, α = 0.5.
    assert_eq!(wrap_linear(gl::REPEAT, 0.0, 4), (Some(3), Some(0), 0.5));
    assert_eq!(
        wrap_linear(gl::CLAMP_TO_EDGE, 0.0, 4),
        (Some(0), Some(0), 0.5)
    );
    assert_eq!(wrap_linear(gl::CLAMP, -2.0, 4), (None, Some(0), 0.5));
    assert_eq!(
        wrap_linear(gl::CLAMP_TO_BORDER, 1.0, 4),
        (Some(3), None, 0.5)
    );
    // s = 0.3: u = 0.7, i0 = 0, i1 = 1, α = 0.7.
    let (i0, i1, a) = wrap_linear(gl::REPEAT, 0.3, 4);
    assert_eq!((i0, i1), (Some(0), Some(1)));
    assert!((a - 0.7).abs() < 1e-6);
}

#[test]
fn nearest_linear_and_border_on_a_known_texture() {
    // 2x2 luminance: (0,0) 0, (1,0) 0.2, (0,1) 0.4, (1,1) 1.0.
    let v = [[0.0, 0.2], [0.4, 1.0]];
    let lv = level(2, 2, gl::LUMINANCE, |i, j| {
        [v[j as usize][i as usize], 0.0, 0.0, 0.0]
    });
    let mut o = obj_with(vec![lv.clone()], gl::NEAREST, gl::NEAREST);
    let s = sampler(o.clone(), gl::REPLACE);
    // NEAREST at (0.3, 0.7): i = floor(0.6) = 0, j = floor(1.4) = 1.
    assert!(close(s.sample(0.3, 0.7, 0.0, 0.0), [0.4, 0.0, 0.0, 0.0]));
    o.mag_filter = gl::LINEAR;
    let s = sampler(o.clone(), gl::REPLACE);
    // LINEAR at the centre: u = v = 0.5, all four weights 1/4: (0 + 0.2 + 0.4 + 1) / 4.
    assert!(close(s.sample(0.5, 0.5, 0.0, 0.0), [0.4, 0.0, 0.0, 0.0]));
    // LINEAR at (0.25, 0.25): u = 0, i0 = -1 → REPEAT → 1, i1 = 0, α = 0... u = 0.5·2 - 0.5
    // = 0 exactly, so i0 = 0 with α = 0 and the texel (0, 0) alone.
    assert!(close(s.sample(0.25, 0.25, 0.0, 0.0), [0.0; 4]));
    // CLAMP_TO_BORDER with border (0.5, ...): at s = 0, u = -0.5: α = 0.5 between the border
    // and texel 0; t = 0.25 → v = 0 → row 0 only: 0.5·0.5 + 0.5·0 = 0.25.
    o.wrap_s = gl::CLAMP_TO_BORDER;
    o.border_color = Vec4::new(0.5, 0.5, 0.5, 0.5);
    let s = sampler(o, gl::REPLACE);
    assert!(close(s.sample(0.0, 0.25, 0.0, 0.0), [0.25, 0.0, 0.0, 0.0]));
}

/// Levels 0, 1, 2 of a 4x4 texture, uniformly 0, 0.5 and 1 in R.
fn three_levels(min: u32, mag: u32) -> TexObject {
    let lv = |n: i32, c: f32| level(n, n, gl::LUMINANCE, move |_, _| [c, 0.0, 0.0, 0.0]);
    obj_with(vec![lv(4, 0.0), lv(2, 0.5), lv(1, 1.0)], min, mag)
}

#[test]
fn mipmap_level_selection() {
    // §3.8.8: *_MIPMAP_NEAREST uses level ceil(λ + 1/2) - 1 for λ > 1/2, else 0, at most q = 2.
    let s = sampler(
        three_levels(gl::NEAREST_MIPMAP_NEAREST, gl::NEAREST),
        gl::REPLACE,
    );
    for (lambda, want) in [(0.4, 0.0), (0.6, 0.5), (1.4, 0.5), (1.7, 1.0), (5.0, 1.0)] {
        assert!(
            close(s.sample(0.5, 0.5, 0.0, lambda), [want, 0.0, 0.0, 0.0]),
            "λ = {lambda}"
        );
    }
    // *_MIPMAP_LINEAR: (1 - frac λ)·level floor(λ) + frac λ·level floor(λ) + 1.
    let s = sampler(
        three_levels(gl::LINEAR_MIPMAP_LINEAR, gl::NEAREST),
        gl::REPLACE,
    );
    for (lambda, want) in [(0.25, 0.125), (1.5, 0.75), (3.0, 1.0), (-1.0, 0.0)] {
        assert!(
            close(s.sample(0.5, 0.5, 0.0, lambda), [want, 0.0, 0.0, 0.0]),
            "λ = {lambda}"
        );
    }
    // §3.8.9: with MAG LINEAR and MIN NEAREST_MIPMAP_NEAREST, c = 0.5: λ = 0.4 magnifies.
    let s = sampler(
        three_levels(gl::NEAREST_MIPMAP_NEAREST, gl::LINEAR),
        gl::REPLACE,
    );
    assert_eq!(s.c, 0.5);
    // MIN_LOD clamps λ from below: λ = 0 with MIN_LOD 2 reads level 2.
    let mut o = three_levels(gl::NEAREST_MIPMAP_NEAREST, gl::NEAREST);
    o.min_lod = 2.0;
    let s = sampler(o, gl::REPLACE);
    assert!(close(s.sample(0.5, 0.5, 0.0, 0.0), [1.0, 0.0, 0.0, 0.0]));
}

#[test]
fn lambda_from_the_quad_derivatives() {
    // A 16x16 texture; s = x/8 and t = y/4 over the window with w = 1 (planes: 1/w, then s, t,
    // r, q as the varyings 0..4): ∂u/∂x = 16/8 = 2, ∂v/∂y = 16/4 = 4, ρ = 4, λ = 2.
    let lv = level(16, 16, gl::RGBA, |_, _| [1.0; 4]);
    let s = sampler(obj_with(vec![lv], gl::LINEAR, gl::LINEAR), gl::REPLACE);
    #[rustfmt::skip]
    let planes = [
        1.0, 0.0, 0.0, // 1/w
        0.0, 0.125, 0.0, // s/w
        0.0, 0.0, 0.25, // t/w
        0.0, 0.0, 0.0, // r/w
        1.0, 0.0, 0.0, // q/w
    ];
    assert!((s.quad_lambda(&planes, 0, 6.0, 10.0) - 2.0).abs() < 1e-5);
    // Under perspective, q = 1/w varies: s/q and t/q are what is differentiated. With
    // q/w = 1 + x/2 (and s/w = x/8): s/q = (x/8)/(1 + x/2); at x = 0 → 0, x = 1 → 1/12:
    // ∂u/∂x = 16/12; ∂v/∂y = 4 still dominates: λ = 2 exactly.
    let mut p = planes;
    p[13] = 0.5;
    assert!((s.quad_lambda(&p, 0, 0.0, 0.0) - 2.0).abs() < 1e-5);
}

#[test]
fn every_env_mode_and_base_format_follows_table_3_21() {
    // Cf = (0.5, 0.25, 1, 0.8); Cc = (1, 0, 0.5, 0.25); the texel is Ct = (0.5, 0.75, 0.25),
    // At = 0.5; L = I = 0.5 (its R); the expected rows are table 3.21 worked by hand.
    let cf = Vec4::new(0.5, 0.25, 1.0, 0.8);
    let texel = [0.5, 0.75, 0.25, 0.5];
    let rows: &[(u32, u32, [f32; 4])] = &[
        (gl::REPLACE, gl::ALPHA, [0.5, 0.25, 1.0, 0.5]),
        (gl::REPLACE, gl::LUMINANCE, [0.5, 0.5, 0.5, 0.8]),
        (gl::REPLACE, gl::LUMINANCE_ALPHA, [0.5, 0.5, 0.5, 0.5]),
        (gl::REPLACE, gl::INTENSITY, [0.5, 0.5, 0.5, 0.5]),
        (gl::REPLACE, gl::RGB, [0.5, 0.75, 0.25, 0.8]),
        (gl::REPLACE, gl::RGBA, [0.5, 0.75, 0.25, 0.5]),
        (gl::MODULATE, gl::ALPHA, [0.5, 0.25, 1.0, 0.4]),
        (gl::MODULATE, gl::LUMINANCE, [0.25, 0.125, 0.5, 0.8]),
        (gl::MODULATE, gl::LUMINANCE_ALPHA, [0.25, 0.125, 0.5, 0.4]),
        (gl::MODULATE, gl::INTENSITY, [0.25, 0.125, 0.5, 0.4]),
        (gl::MODULATE, gl::RGB, [0.25, 0.1875, 0.25, 0.8]),
        (gl::MODULATE, gl::RGBA, [0.25, 0.1875, 0.25, 0.4]),
        (gl::DECAL, gl::RGB, [0.5, 0.75, 0.25, 0.8]),
        (gl::DECAL, gl::RGBA, [0.5, 0.5, 0.625, 0.8]),
        (gl::BLEND, gl::ALPHA, [0.5, 0.25, 1.0, 0.4]),
        (gl::BLEND, gl::LUMINANCE, [0.75, 0.125, 0.75, 0.8]),
        (gl::BLEND, gl::LUMINANCE_ALPHA, [0.75, 0.125, 0.75, 0.4]),
        (gl::BLEND, gl::INTENSITY, [0.75, 0.125, 0.75, 0.525]),
        (gl::BLEND, gl::RGB, [0.75, 0.0625, 0.875, 0.8]),
        (gl::BLEND, gl::RGBA, [0.75, 0.0625, 0.875, 0.4]),
        (gl::ADD, gl::ALPHA, [0.5, 0.25, 1.0, 0.4]),
        (gl::ADD, gl::LUMINANCE, [1.0, 0.75, 1.0, 0.8]),
        (gl::ADD, gl::LUMINANCE_ALPHA, [1.0, 0.75, 1.0, 0.4]),
        (gl::ADD, gl::INTENSITY, [1.0, 0.75, 1.0, 1.0]),
        (gl::ADD, gl::RGB, [1.0, 1.0, 1.0, 0.8]),
        (gl::ADD, gl::RGBA, [1.0, 1.0, 1.0, 0.4]),
    ];
    for &(env, base, want) in rows {
        let lv = level(1, 1, base, |_, _| crate::texture::keep(base, texel));
        let s = sampler(obj_with(vec![lv], gl::NEAREST, gl::NEAREST), env);
        let t = s.sample(0.5, 0.5, 0.0, 0.0);
        let got = s.env(cf, t).to_array();
        assert!(
            close(got, want),
            "env {env:#x} base {base:#x}: {got:?} != {want:?}"
        );
    }
}

#[test]
fn depth_comparison_and_depth_texture_mode() {
    // §3.8.14: with COMPARE_R_TO_TEXTURE and LEQUAL the result is 1 where r <= D, else 0;
    // DEPTH_TEXTURE_MODE ALPHA puts it in alpha, LUMINANCE in r, g, b.
    let lv = level(1, 1, gl::DEPTH_COMPONENT, |_, _| [0.5, 0.0, 0.0, 0.0]);
    let mut o = obj_with(vec![lv], gl::NEAREST, gl::NEAREST);
    o.compare_mode = gl::COMPARE_R_TO_TEXTURE;
    o.compare_func = gl::LEQUAL;
    o.depth_texture_mode = gl::LUMINANCE;
    let s = sampler(o.clone(), gl::MODULATE);
    let cf = Vec4::new(0.8, 0.6, 0.4, 1.0);
    let lit = s.shade(cf, cf, [0.5, 0.5, 0.4, 1.0], 0.0).to_array();
    assert!(close(lit, [0.8, 0.6, 0.4, 1.0]));
    let shadowed = s.shade(cf, cf, [0.5, 0.5, 0.6, 1.0], 0.0).to_array();
    assert!(close(shadowed, [0.0, 0.0, 0.0, 1.0]));
    // r is divided by q: r/q = 1.2/2 = 0.6 > 0.5.
    let q2 = s.shade(cf, cf, [1.0, 1.0, 1.2, 2.0], 0.0).to_array();
    assert!(close(q2, [0.0, 0.0, 0.0, 1.0]));
    o.compare_func = gl::GREATER;
    o.depth_texture_mode = gl::ALPHA;
    let s = sampler(o.clone(), gl::MODULATE);
    let a = s.shade(cf, cf, [0.5, 0.5, 0.6, 1.0], 0.0).to_array();
    assert!(close(a, [0.8, 0.6, 0.4, 1.0]));
    let b = s.shade(cf, cf, [0.5, 0.5, 0.4, 1.0], 0.0).to_array();
    assert!(close(b, [0.8, 0.6, 0.4, 0.0]));
    // Without comparison the depth itself is the luminance: MODULATE by 0.5.
    o.compare_mode = gl::NONE;
    o.depth_texture_mode = gl::LUMINANCE;
    let s = sampler(o, gl::MODULATE);
    let d = s.shade(cf, cf, [0.5, 0.5, 0.0, 1.0], 0.0).to_array();
    assert!(close(d, [0.4, 0.3, 0.2, 1.0]));
}

#[test]
fn incomplete_textures_disable_the_unit() {
    // §3.8.10: the default MIN filter needs mipmaps, so level 0 alone is incomplete.
    let mut state = State::new(4, 4);
    state.enables.texture_2d[0] = true;
    let one = level(4, 4, gl::RGBA, |_, _| [1.0; 4]);
    let mut o = obj_with(vec![one.clone()], gl::NEAREST_MIPMAP_LINEAR, gl::LINEAR);
    state.textures.defaults[1] = Arc::new(o.clone());
    assert!(Sampler::new(&state, 0).is_none());
    // A full chain 4, 2, 1 is complete...
    let half = level(2, 2, gl::RGBA, |_, _| [1.0; 4]);
    let quarter = level(1, 1, gl::RGBA, |_, _| [1.0; 4]);
    o.levels[1] = Some(half.clone());
    o.levels[2] = Some(quarter);
    state.textures.defaults[1] = Arc::new(o.clone());
    assert!(Sampler::new(&state, 0).is_some());
    // ...unless a level has the wrong size, or the internal format differs...
    o.levels[2] = Some(level(2, 2, gl::RGBA, |_, _| [1.0; 4]));
    assert!(!o.is_complete());
    o.levels[2] = Some(level(1, 1, gl::RGB, |_, _| [1.0; 4]));
    assert!(!o.is_complete());
    // ...while MAX_LEVEL 1 needs only levels 0 and 1.
    o.max_level = 1;
    assert!(o.is_complete());
    // BASE_LEVEL above MAX_LEVEL is incomplete under a mipmap filter.
    o.base_level = 2;
    assert!(!o.is_complete());
    // A non-mipmap filter needs only the base level.
    let o = obj_with(vec![one], gl::LINEAR, gl::LINEAR);
    assert!(o.is_complete());
    // Disabled: no sampler even when complete.
    state.enables.texture_2d[0] = false;
    state.textures.defaults[1] = Arc::new(o);
    assert!(Sampler::new(&state, 0).is_none());
}

#[test]
fn combine_interpolate_by_hand() {
    // Table 3.23 INTERPOLATE: a0·a2 + a1·(1 - a2) with a0 = the texel (0.5, 0.75, 0.25),
    // a1 = Cc (1, 0, 0.5), a2 = the previous alpha 0.8: (0.6, 0.6, 0.3); alpha MODULATE of the
    // initial sources TEXTURE and PREVIOUS: 0.5 · 0.8 = 0.4.
    let lv = level(1, 1, gl::RGBA, |_, _| [0.5, 0.75, 0.25, 0.5]);
    let mut s = sampler(obj_with(vec![lv], gl::NEAREST, gl::NEAREST), gl::COMBINE);
    s.combine.rgb = gl::INTERPOLATE;
    s.combine.src_rgb = [gl::TEXTURE, gl::CONSTANT, gl::PREVIOUS];
    s.combine.operand_rgb = [gl::SRC_COLOR, gl::SRC_COLOR, gl::SRC_ALPHA];
    let cf = Vec4::new(0.5, 0.25, 1.0, 0.8);
    let got = s.shade(cf, cf, [0.5, 0.5, 0.0, 1.0], 0.0).to_array();
    assert!(close(got, [0.6, 0.6, 0.3, 0.4]), "{got:?}");
}

#[test]
fn lod_log2_is_piecewise_linear_like_llvmpipe() {
    // Exact at powers of two, linear in between: 3 = 2^1 · 1.5 → 1 + 0.5; 0.75 = 2^-1 · 1.5.
    assert_eq!(fast_log2(4.0), 2.0);
    assert_eq!(fast_log2(3.0), 1.5);
    assert_eq!(fast_log2(0.75), -0.5);
    assert_eq!(fast_log2(0.0), f32::NEG_INFINITY);
}

#[test]
fn repeat_index_is_rem_euclid_for_every_size() {
    // The mask of a power-of-two size gives rem_euclid's value for every i32 (extremes too),
    // and other sizes take rem_euclid itself.
    let is = [
        i32::MIN,
        i32::MIN + 1,
        -65537,
        -64,
        -63,
        -1,
        0,
        1,
        63,
        64,
        65,
        1 << 30,
        i32::MAX,
    ];
    for n in 1..=257 {
        for &i in &is {
            assert_eq!(repeat(i, n), i.rem_euclid(n), "i {i} n {n}");
        }
        for i in -600..600 {
            assert_eq!(repeat(i, n), i.rem_euclid(n), "i {i} n {n}");
        }
    }
}

#[test]
fn quad_lambda_lanes_is_the_scalar_lambda_bit_for_bit() {
    // Every target's sampler (1D, 2D, 3D, cube) over awkward planes: each lane holds exactly
    // what `quad_lambda` gives for its quad.
    let mut seed = 3u64;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        seed >> 11
    };
    let lv = |w, h| level(w, h, gl::RGBA, |_, _| [0.5; 4]);
    let mut samplers = Vec::new();
    for dims in [1, 2, 3] {
        let mut s = sampler(
            obj_with(vec![lv(64, 32)], gl::NEAREST, gl::LINEAR),
            gl::MODULATE,
        );
        s.dims = dims;
        s.size = [
            64.0,
            if dims >= 2 { 32.0 } else { 0.0 },
            if dims == 3 { 8.0 } else { 0.0 },
        ];
        samplers.push(s.clone());
        if dims == 2 {
            s.cube = true;
            samplers.push(s);
        }
    }
    for round in 0..3000 {
        let s = &samplers[round % samplers.len()];
        let np = 3 + 3 * (1 + (next() % 9) as usize);
        let planes: Vec<f32> = (0..np)
            .map(|_| match next() % 8 {
                0 => 0.0,
                1 => f32::from_bits(next() as u32),
                2 => -((next() % 1000) as f32) * 1e-3,
                _ => (next() % 100_000) as f32 * 1e-4 - 2.0,
            })
            .collect();
        let to = (next() % 4) as usize;
        let qx: [f32; LANES] = std::array::from_fn(|_| ((next() % 400) as i32 - 50) as f32);
        let qy = ((next() % 400) as i32 - 50) as f32;
        let got = s.quad_lambda_lanes(&planes, to, qx, qy);
        for l in 0..LANES {
            let want = s.quad_lambda(&planes, to, qx[l], qy);
            // A NaN's payload may differ (operand order); every use of λ treats NaN alike.
            let same = got[l].to_bits() == want.to_bits() || got[l].is_nan() && want.is_nan();
            assert!(same, "lane {l}: {} vs {want} {planes:?}", got[l]);
        }
    }
}

#[test]
fn texels_lanes_and_env_lanes_are_shade_bit_for_bit() {
    // 2D samplers of every base format, environment, wrap mode, filter pair, mipmapped or
    // not, power-of-two or not, with random LOD bounds and bias, over awkward coordinates
    // (outside [0, 1], huge, q = 0, negative q, NaN, infinities) and λ: each lane of
    // `texels_lanes` then `env_lanes` holds exactly what `shade` gives for its fragment.
    let mut seed = 11u64;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        seed >> 11
    };
    let bases = [
        gl::ALPHA,
        gl::LUMINANCE,
        gl::LUMINANCE_ALPHA,
        gl::INTENSITY,
        gl::RGB,
        gl::RGBA,
    ];
    let envs = [gl::REPLACE, gl::MODULATE, gl::DECAL, gl::BLEND, gl::ADD];
    let wraps = [
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::CLAMP_TO_BORDER,
        gl::MIRRORED_REPEAT,
    ];
    let mins = [
        gl::NEAREST,
        gl::LINEAR,
        gl::NEAREST_MIPMAP_NEAREST,
        gl::LINEAR_MIPMAP_NEAREST,
        gl::NEAREST_MIPMAP_LINEAR,
        gl::LINEAR_MIPMAP_LINEAR,
    ];
    let sizes = [(1, 1), (4, 4), (8, 2), (5, 3), (16, 16), (7, 1), (64, 32)];
    let mut checked = 0;
    for round in 0..1500 {
        // Every seventh round a depth (or depth-stencil) texture, with or without comparison.
        let depth = round % 7 == 6;
        let base = if depth {
            [gl::DEPTH_COMPONENT, gl::DEPTH_STENCIL][round / 7 % 2]
        } else {
            bases[round % bases.len()]
        };
        let env = envs[(next() % 5) as usize];
        let (w, h) = sizes[(next() % sizes.len() as u64) as usize];
        let min = mins[(next() % 6) as usize];
        let mag = if next() % 2 == 0 {
            gl::NEAREST
        } else {
            gl::LINEAR
        };
        let mut levels = Vec::new();
        let (mut lw, mut lh) = (w, h);
        loop {
            let mut vals = Vec::new();
            for _ in 0..lw * lh {
                vals.push(std::array::from_fn(|_| (next() % 1001) as f32 / 1000.0));
            }
            levels.push(level(lw, lh, base, |i, j| vals[(j * lw + i) as usize]));
            if lw == 1 && lh == 1 {
                break;
            }
            (lw, lh) = ((lw / 2).max(1), (lh / 2).max(1));
        }
        let mut obj = obj_with(levels, min, mag);
        obj.wrap_s = wraps[(next() % 5) as usize];
        obj.wrap_t = wraps[(next() % 5) as usize];
        obj.border_color = Vec4::new(0.25, 0.5, 0.75, 0.125);
        if next() % 3 == 0 {
            obj.min_lod = (next() % 40) as f32 * 0.125 - 1.0;
            obj.max_lod = (next() % 40) as f32 * 0.125 - 1.0;
            obj.lod_bias = (next() % 17) as f32 * 0.25 - 2.0;
        }
        if depth {
            obj.compare_mode = if next() % 4 == 0 {
                gl::NONE
            } else {
                gl::COMPARE_R_TO_TEXTURE
            };
            obj.compare_func = [
                gl::LEQUAL,
                gl::GEQUAL,
                gl::LESS,
                gl::GREATER,
                gl::EQUAL,
                gl::NOTEQUAL,
                gl::ALWAYS,
                gl::NEVER,
            ][(next() % 8) as usize];
            obj.depth_texture_mode =
                [gl::LUMINANCE, gl::INTENSITY, gl::ALPHA][(next() % 3) as usize];
        }
        let s = sampler(obj, env);
        assert!(s.lanes_ok());
        assert_eq!(s.compare.is_some(), depth && obj_compare(&s));
        let coord = |next: &mut dyn FnMut() -> u64| match next() % 16 {
            0 => 0.0,
            1 => f32::from_bits(next() as u32),
            2 => [f32::NAN, f32::INFINITY, -f32::INFINITY, 1e9, -1e9][(next() % 5) as usize],
            3 => (next() % 64) as f32 / 8.0,
            _ => (next() % 100_000) as f32 * 6e-5 - 3.0,
        };
        for _ in 0..8 {
            let lanes = |next: &mut dyn FnMut() -> u64| -> [f32; LANES] {
                std::array::from_fn(|_| coord(next))
            };
            let (cs, ct, cr) = (lanes(&mut next), lanes(&mut next), lanes(&mut next));
            let cq: [f32; LANES] = std::array::from_fn(|_| match next() % 8 {
                0 => 0.0,
                1 => -1.5,
                2 => coord(&mut next),
                _ => 1.0 + (next() % 100) as f32 * 0.01,
            });
            let lambda: [f32; LANES] = std::array::from_fn(|_| match next() % 10 {
                0 => f32::NAN,
                1 => f32::INFINITY,
                2 => -f32::INFINITY,
                3 => (next() % 16) as f32 * 0.5 - 1.0,
                _ => (next() % 10_000) as f32 * 1e-3 - 2.0,
            });
            let cf: [Vec4; LANES] = std::array::from_fn(|_| {
                Vec4::from_array(std::array::from_fn(|_| (next() % 300) as f32 / 256.0))
            });
            let m = (next() % 256) as u8;
            let texels = s.texels_lanes([&cs, &ct, &cr, &cq], &lambda, m);
            let mut got = cf;
            s.env_lanes(&mut got, &texels, m);
            for l in 0..LANES {
                if m & (1 << l) == 0 {
                    continue;
                }
                let want = s.shade(cf[l], cf[l], [cs[l], ct[l], cr[l], cq[l]], lambda[l]);
                let (g, w) = (got[l].to_array(), want.to_array());
                let same = g
                    .iter()
                    .zip(w)
                    .all(|(a, b)| a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan());
                assert!(
                    same,
                    "round {round} lane {l}: {g:?} vs {w:?} ({}, {}, {}, {}) λ {}",
                    cs[l], ct[l], cr[l], cq[l], lambda[l]
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 40_000, "{checked}");
}

/// Did `Sampler::new` turn comparison on (COMPARE_R_TO_TEXTURE on a depth texture)?
fn obj_compare(s: &Sampler) -> bool {
    s.obj.compare_mode == gl::COMPARE_R_TO_TEXTURE
}
