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
        texels: texels.into(),
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

/// Random sampling parameters beside the wraps: the border colour, now and then LOD bounds and
/// a bias, and for a depth texture the comparison mode, function and DEPTH_TEXTURE_MODE (the
/// 2D and the other targets' lane tests draw them alike).
pub(super) fn random_border_lod_compare(
    o: &mut TexObject,
    depth: bool,
    next: &mut impl FnMut() -> u64,
) {
    o.border_color = Vec4::new(0.25, 0.5, 0.75, 0.125);
    if next() % 3 == 0 {
        o.min_lod = (next() % 40) as f32 * 0.125 - 1.0;
        o.max_lod = (next() % 40) as f32 * 0.125 - 1.0;
        o.lod_bias = (next() % 17) as f32 * 0.25 - 2.0;
    }
    if depth {
        o.compare_mode = if next() % 4 == 0 {
            gl::NONE
        } else {
            gl::COMPARE_R_TO_TEXTURE
        };
        o.compare_func = [
            gl::LEQUAL,
            gl::GEQUAL,
            gl::LESS,
            gl::GREATER,
            gl::EQUAL,
            gl::NOTEQUAL,
            gl::ALWAYS,
            gl::NEVER,
        ][(next() % 8) as usize];
        o.depth_texture_mode = [gl::LUMINANCE, gl::INTENSITY, gl::ALPHA][(next() % 3) as usize];
    }
}

/// A 64-bit linear congruential generator seeded with `seed`: each call gives its next state's
/// top 53 bits (the tests' source of random planes, coordinates and masks).
pub(super) fn lcg(mut seed: u64) -> impl FnMut() -> u64 {
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        seed >> 11
    }
}

/// A primitive's planes for the λ tests: the 1/w plane and 1 to 9 varyings' planes, with zeros,
/// random bit patterns (NaN, infinities, subnormals), small negatives and values around 0.
fn random_planes(next: &mut impl FnMut() -> u64) -> Vec<f32> {
    let np = 3 + 3 * (1 + (next() % 9) as usize);
    (0..np)
        .map(|_| match next() % 8 {
            0 => 0.0,
            1 => f32::from_bits(next() as u32),
            2 => -((next() % 1000) as f32) * 1e-3,
            _ => (next() % 100_000) as f32 * 1e-4 - 2.0,
        })
        .collect()
}

/// One sampler of a 64x32 image per kind of λ: 1D, 2D, 3D (8 deep) and cube map.
fn lambda_samplers() -> Vec<Sampler> {
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
    samplers
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
fn fast_log2_lane_is_fast_log2() {
    // Every special class (±0, ±∞, NaN payloads, negatives, subnormals) and random bits: the
    // lane version gives `fast_log2`'s bits (any NaN for a NaN).
    let mut next = lcg(23u64);
    let special = [
        0.0,
        -0.0,
        f32::INFINITY,
        -f32::INFINITY,
        f32::NAN,
        -f32::NAN,
        f32::from_bits(0x7f80_0001),
        f32::from_bits(0xffc0_1234),
        f32::MIN_POSITIVE,
        f32::MIN_POSITIVE / 8.0,
        -f32::MIN_POSITIVE / 8.0,
        f32::MAX,
        f32::MIN,
        1.0,
        -1.0,
        3.0,
    ];
    for k in 0..200_000u32 {
        let x = match k as usize {
            i if i < special.len() => special[i],
            _ => f32::from_bits(next() as u32),
        };
        let (a, b) = (fast_log2_lane(x), fast_log2(x));
        assert!(
            a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan(),
            "{x:e} ({:#x}): {a} vs {b}",
            x.to_bits()
        );
    }
    // `fast_log2_lanes`: each lane `fast_log2_lane`'s bits (its NaN is `f32::NAN`'s), the
    // specials in every lane position.
    for k in 0..40_000usize {
        let x: [f32; LANES] = std::array::from_fn(|l| match (k + l) % 3 {
            0 => special[(k * LANES + l) % special.len()],
            _ => f32::from_bits(next() as u32),
        });
        let got = fast_log2_lanes(&x);
        for l in 0..LANES {
            let want = fast_log2_lane(x[l]);
            assert_eq!(
                got[l].to_bits(),
                want.to_bits(),
                "{:e} ({:#x})",
                x[l],
                x[l].to_bits()
            );
        }
    }
}

#[test]
fn lane_masks_are_the_lane_compares() {
    // `mask_ne_zero`, `mask_le` and `mask_eq` against the Rust comparisons lane by lane: NaN,
    // ±0, ±∞, equal and neighbouring values, random bits.
    let mut next = lcg(29u64);
    let pick = |next: &mut dyn FnMut() -> u64| match next() % 8 {
        0 => f32::NAN,
        1 => 0.0,
        2 => -0.0,
        3 => [f32::INFINITY, -f32::INFINITY, 0.5, 1.0][(next() % 4) as usize],
        4 => f32::from_bits(0x3f00_0001),
        _ => f32::from_bits(next() as u32),
    };
    for _ in 0..50_000 {
        let x: [f32; LANES] = std::array::from_fn(|_| pick(&mut next));
        let c = pick(&mut next);
        let i: [i32; LANES] = std::array::from_fn(|_| (next() % 4) as i32 - 2);
        let v = (next() % 4) as i32 - 2;
        let (ne, le, eq) = (mask_ne_zero(&x), mask_le(&x, c), mask_eq(&i, v));
        for l in 0..LANES {
            assert_eq!(ne >> l & 1 == 1, x[l] != 0.0, "{:?}", x[l]);
            assert_eq!(le >> l & 1 == 1, x[l] <= c, "{:?} <= {c:?}", x[l]);
            assert_eq!(eq >> l & 1 == 1, i[l] == v);
        }
    }
}

#[test]
fn dense_gathers_only_on_whole_power_of_two_levels() {
    // `dense_level`: the masked gather only where every in-image index is below the texel
    // count; a level whose texel vector is longer or shorter than w·h (not made by the GL
    // entry points, but a `Level` allows it) and NPOT levels take the checked gather, and all
    // of them sample as `shade` does (a missing texel reads (0, 0, 0, 0) on both paths).
    assert!(dense_level(&[[0.0; 4]; 64], 8, 8));
    assert!(dense_level(&[[0.0; 4]; 1], 1, 1));
    assert!(dense_level(&[[0.0; 4]; 8], 8, 1));
    assert!(!dense_level(&[[0.0; 4]; 64], 4, 4));
    assert!(!dense_level(&[[0.0; 4]; 8], 4, 4));
    assert!(!dense_level(&[[0.0; 4]; 15], 5, 3));
    assert!(!dense_level(&[], 0, 0));
    assert!(!dense_level(&[[0.0; 4]; 4], -2, -2));
    assert!(!dense_level(&[[0.0; 4]; 4], 4, 0));
    let mut next = lcg(31u64);
    let wraps = [
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::CLAMP_TO_BORDER,
        gl::MIRRORED_REPEAT,
    ];
    // (width, height, texels stored)
    let shapes = [
        (4, 4, 16),
        (4, 4, 32),
        (4, 4, 8),
        (8, 2, 16),
        (5, 3, 15),
        (2, 2, 2),
    ];
    for round in 0..600 {
        let (w, h, n) = shapes[round % shapes.len()];
        let vals: Vec<[f32; 4]> = (0..n)
            .map(|_| std::array::from_fn(|_| (next() % 1001) as f32 / 1000.0))
            .collect();
        let mut lv = level(w, h, gl::RGBA, |_, _| [0.0; 4]);
        lv.texels = Arc::new(vals);
        let filter = [gl::NEAREST, gl::LINEAR][round / shapes.len() % 2];
        let mut obj = obj_with(vec![lv], filter, filter);
        obj.wrap_s = wraps[(next() % 5) as usize];
        obj.wrap_t = wraps[(next() % 5) as usize];
        let s = sampler(obj, gl::REPLACE);
        for _ in 0..4 {
            let lanes = |next: &mut dyn FnMut() -> u64| -> [f32; LANES] {
                std::array::from_fn(|_| (next() % 4000) as f32 / 1000.0 - 2.0)
            };
            let (cs, ct) = (lanes(&mut next), lanes(&mut next));
            let (cr, cq) = ([0.0; LANES], [1.0; LANES]);
            let m = (next() % 256) as u8;
            let got = s.texels_lanes([&cs, &ct, &cr, &cq], &[0.0; LANES], m);
            for l in (0..LANES).filter(|l| m & (1 << l) != 0) {
                let want = s.texel([cs[l], ct[l], 0.0, 1.0], 0.0);
                assert_eq!(
                    got[l].map(f32::to_bits),
                    want.map(f32::to_bits),
                    "round {round} {w}x{h} ({n} texels) lane {l}"
                );
            }
        }
    }
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
    let mut next = lcg(3u64);
    let samplers = lambda_samplers();
    for round in 0..3000 {
        let s = &samplers[round % samplers.len()];
        let planes = random_planes(&mut next);
        let to = (next() % 4) as usize;
        let qx: [f32; LANES] = std::array::from_fn(|_| ((next() % 400) as i32 - 50) as f32);
        let qy = ((next() % 400) as i32 - 50) as f32;
        // The AVX2 route (`quad_lambda8`, where the CPU has AVX2) and the SSE2 one.
        let mut both = [[0.0f32; LANES]; 2];
        for (off, b) in [false, true].into_iter().zip(&mut both) {
            crate::cpu::lanes::NO_AVX2.with(|c| c.set(off));
            *b = s.quad_lambda_lanes(&planes, to, qx, qy);
            crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
        }
        // The two routes agree bit for bit, NaNs included (both end in `fast_log2`'s NaN).
        assert_eq!(
            both[0].map(f32::to_bits),
            both[1].map(f32::to_bits),
            "{planes:?}"
        );
        let got = both[0];
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
    let mut next = lcg(11u64);
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
    let mins = crate::cpu::testgen::MIN_FILTERS;
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
        random_border_lod_compare(&mut obj, depth, &mut next);
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
            let pick = |next: &mut dyn FnMut() -> u64| match next() % 10 {
                0 => f32::NAN,
                1 => f32::INFINITY,
                2 => -f32::INFINITY,
                3 => (next() % 16) as f32 * 0.5 - 1.0,
                _ => (next() % 10_000) as f32 * 1e-3 - 2.0,
            };
            // λ per lane, one λ for the group, or λ per quad (lane pair) near one value: the
            // last two mostly put every lane on one level (`lod_lanes`' one-level pass), with
            // or without a second level, and sometimes straddle a level boundary.
            let lambda: [f32; LANES] = match next() % 3 {
                0 => std::array::from_fn(|_| pick(&mut next)),
                1 => [pick(&mut next); LANES],
                _ => {
                    let c = (next() % 8) as f32 * 0.5 - 0.75;
                    let q: [f32; 4] = std::array::from_fn(|_| c + (next() % 100) as f32 * 2e-3);
                    std::array::from_fn(|l| q[l / 2])
                }
            };
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

/// The wrap functions as they were written before the lane rewrite (`Option` indices,
/// `clamp`, `contains`, `repeat`'s own power-of-two test): the reference the rewritten
/// `wrap_nearest_i` / `wrap_linear_i` and their lane forms must reproduce.
fn ref_wrap_nearest(mode: u32, s: f32, n: i32) -> Option<i32> {
    let n = n.max(1);
    match mode {
        gl::REPEAT => Some(ifloor(s * n as f32).rem_euclid(n)),
        gl::MIRRORED_REPEAT => Some(ifloor(mirror(s) * n as f32).clamp(0, n - 1)),
        gl::CLAMP_TO_BORDER => {
            let i = ifloor(s * n as f32);
            (0..n).contains(&i).then_some(i)
        }
        _ => Some(ifloor(s * n as f32).clamp(0, n - 1)),
    }
}

fn ref_wrap_linear(mode: u32, s: f32, n: i32) -> (Option<i32>, Option<i32>, f32) {
    let n = n.max(1);
    let nf = n as f32;
    let s = match mode {
        gl::MIRRORED_REPEAT => mirror(s),
        gl::CLAMP => s.clamp(0.0, 1.0),
        _ => s,
    };
    let u = s * nf - 0.5;
    let u = if u.is_nan() { 0.0 } else { u };
    let i0 = ifloor(u);
    let a = (u - i0 as f32).clamp(0.0, 1.0);
    let i1 = i0.saturating_add(1);
    let inside = |i: i32| (0..n).contains(&i).then_some(i);
    match mode {
        gl::REPEAT => (Some(i0.rem_euclid(n)), Some(i1.rem_euclid(n)), a),
        gl::CLAMP_TO_BORDER | gl::CLAMP => (inside(i0), inside(i1), a),
        _ => (Some(i0.clamp(0, n - 1)), Some(i1.clamp(0, n - 1)), a),
    }
}

#[test]
fn wrap_lanes_are_the_reference_wraps_for_every_mode() {
    // Every wrap mode, lanes on axes of different sizes (all powers of two, or mixed), over
    // awkward coordinates: each lane's index, inside flag and weight are the reference's.
    let mut next = lcg(5u64);
    let modes = [
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::CLAMP_TO_BORDER,
        gl::MIRRORED_REPEAT,
    ];
    let special = [
        f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        f32::MIN_POSITIVE / 4.0,
        -f32::MIN_POSITIVE / 4.0,
        8_388_608.5,
        16_777_217.0,
        -16_777_216.0,
        3e9,
        -3e9,
        1e30,
        -1e30,
        f32::MAX,
        f32::MIN,
    ];
    let mut checked = 0;
    for round in 0..20_000 {
        let mode = modes[round % modes.len()];
        let n: [i32; LANES] = std::array::from_fn(|_| match round / modes.len() % 3 {
            0 => 1 << (next() % 12),
            1 => 1 + (next() % 300) as i32,
            _ => [0, 1, 2, 3, 5, 64, 1 << 20][(next() % 7) as usize],
        });
        let s: [f32; LANES] = std::array::from_fn(|_| match next() % 6 {
            0 => special[(next() % special.len() as u64) as usize],
            1 => f32::from_bits(next() as u32),
            2 => (next() % 64) as f32 / 16.0 - 2.0,
            _ => (next() % 1_000_000) as f32 * 1e-5 - 5.0,
        });
        let (i, inside) = wrap_nearest_lanes(mode, &s, &n);
        let lin = wrap_linear_lanes(mode, &s, &n);
        // One size for all lanes (the one-level pass): the same as the per-lane sizes.
        let one = [n[0]; LANES];
        let (i1, inside1) = wrap_nearest_lanes(mode, &s, n[0]);
        let (i2, inside2) = wrap_nearest_lanes(mode, &s, &one);
        assert_eq!((i1, inside1), (i2, inside2), "NEAREST {mode:#x} n {}", n[0]);
        let (a, b) = (
            wrap_linear_lanes(mode, &s, n[0]),
            wrap_linear_lanes(mode, &s, &one),
        );
        assert_eq!(
            (a.i0, a.i1, a.in0, a.in1, a.w.map(f32::to_bits)),
            (b.i0, b.i1, b.in0, b.in1, b.w.map(f32::to_bits)),
            "LINEAR {mode:#x} n {}",
            n[0]
        );
        for l in 0..LANES {
            let want = ref_wrap_nearest(mode, s[l], n[l]);
            assert_eq!(
                inside[l].then_some(i[l]),
                want,
                "NEAREST {mode:#x} {} n {}",
                s[l],
                n[l]
            );
            assert_eq!(wrap_nearest(mode, s[l], n[l]), want);
            let (w0, w1, wa) = ref_wrap_linear(mode, s[l], n[l]);
            let got = (
                lin.in0[l].then_some(lin.i0[l]),
                lin.in1[l].then_some(lin.i1[l]),
            );
            assert_eq!(got, (w0, w1), "LINEAR {mode:#x} {} n {}", s[l], n[l]);
            assert_eq!(
                lin.w[l].to_bits(),
                wa.to_bits(),
                "LINEAR {mode:#x} {}",
                s[l]
            );
            assert_eq!(wrap_linear(mode, s[l], n[l]), (w0, w1, wa));
            checked += 1;
        }
    }
    assert_eq!(checked, 20_000 * LANES);
}

#[test]
fn level_selection_is_the_reference_selection() {
    // `select` (ceil and floor by truncation) against §3.8.8's selection as `sample_face`
    // wrote it with `f32::ceil` / `floor`, for every minification filter, both switch points,
    // random LOD bounds (min > max and NaN among them), biases and λ (NaN, infinities, huge).
    let mut next = lcg(17u64);
    let mins = crate::cpu::testgen::MIN_FILTERS;
    let lv = |n: i32| level(n, n, gl::LUMINANCE, |_, _| [0.5, 0.0, 0.0, 0.0]);
    let pick = |next: &mut dyn FnMut() -> u64| match next() % 8 {
        0 => [f32::NAN, f32::INFINITY, -f32::INFINITY, 1e30, -1e30][(next() % 5) as usize],
        1 => (next() % 64) as f32 * 0.25 - 4.0,
        _ => (next() % 100_000) as f32 * 3e-4 - 6.0,
    };
    let mut lanes_checked = 0;
    for round in 0..6000 {
        let min = mins[round % mins.len()];
        let mag = [gl::NEAREST, gl::LINEAR][round / mins.len() % 2];
        let size = 1 << (next() % 9);
        let mut levels = Vec::new();
        let mut n = size;
        loop {
            levels.push(lv(n));
            if n == 1 {
                break;
            }
            n /= 2;
        }
        let mut obj = obj_with(levels, min, mag);
        obj.base_level = (next() % 2) as i32;
        if next() % 2 == 0 {
            obj.min_lod = pick(&mut next);
            obj.max_lod = pick(&mut next);
            obj.lod_bias = pick(&mut next).clamp(-20.0, 20.0);
        }
        if obj.base_level > 0 && size == 1 {
            obj.base_level = 0;
        }
        let s = sampler(obj, gl::MODULATE);
        let mut lambdas = [0.0f32; 16];
        for lambda in &mut lambdas {
            *lambda = pick(&mut next);
            let lambda = *lambda;
            // The reference: `sample_face`'s choice before the rewrite.
            let want = {
                let lambda = lambda + s.bias;
                let lambda = if lambda.is_nan() { 0.0 } else { lambda };
                let lambda = lambda.min(s.max_lod).max(s.min_lod);
                let span = (s.last - s.base_level) as f32;
                let l = |f: u32| lin(f) == gl::LINEAR;
                if lambda <= s.c {
                    (s.base_level, s.mag == gl::LINEAR, 0.0)
                } else {
                    match s.min {
                        gl::NEAREST_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_NEAREST => {
                            let d = if lambda <= 0.5 {
                                0.0
                            } else {
                                ((lambda + 0.5).ceil() - 1.0).min(span)
                            };
                            (s.base_level + d as i32, l(s.min), 0.0)
                        }
                        gl::NEAREST_MIPMAP_LINEAR | gl::LINEAR_MIPMAP_LINEAR => {
                            if lambda >= span {
                                (s.last, l(s.min), 0.0)
                            } else {
                                let d1 = lambda.floor();
                                (s.base_level + d1 as i32, l(s.min), lambda - d1)
                            }
                        }
                        f => (s.base_level, f == gl::LINEAR, 0.0),
                    }
                }
            };
            let got = s.select(lambda);
            assert_eq!(
                (got.0, got.1, got.2.to_bits()),
                (want.0, want.1, want.2.to_bits()),
                "min {min:#x} λ {lambda} bias {} lod [{}, {}]",
                s.bias,
                s.min_lod,
                s.max_lod
            );
        }
        // `select_lanes` on groups of eight of these λ: each lane is `select`'s choice.
        for g in lambdas.chunks_exact(LANES) {
            let g: [f32; LANES] = g.try_into().expect("eight λ");
            let (lv, linear, f) = s.select_lanes(&g);
            for l in 0..LANES {
                let want = s.select(g[l]);
                assert_eq!(
                    (lv[l], linear & (1 << l) != 0, f[l].to_bits()),
                    (want.0, want.1, want.2.to_bits()),
                    "lanes: min {min:#x} λ {} bias {} lod [{}, {}]",
                    g[l],
                    s.bias,
                    s.min_lod,
                    s.max_lod
                );
                lanes_checked += 1;
            }
        }
    }
    assert_eq!(lanes_checked, 6000 * 16);
}

#[test]
fn span_lambda_is_quad_lambda_per_pixel_bit_for_bit() {
    // Spans of every alignment (odd and even first pixel, odd and even plane origin), lengths
    // up to and past the row buffer, groups visited with gaps as a span's coverage skips them:
    // each lane's λ is `quad_lambda` of its pixel's quad, bit for bit. Likewise the general
    // path's (`FragCtx::tri_span_in`): the quads of the groups from the first visited (ga) to
    // the last within 64 pixels of it (gb), eight a call of `quad_lambda_row` (the AVX2
    // kernels called directly in a third of the rounds where the CPU has them, else through
    // `quad_lambda_lanes`, on AVX2 or SSE2), each group's lanes by `spread_quads`.
    let mut next = lcg(23u64);
    let samplers = lambda_samplers();
    let avx2 = crate::cpu::lanes::has_avx2();
    let mut checked = 0;
    for round in 0..3000 {
        let s = &samplers[round % samplers.len()];
        let planes = random_planes(&mut next);
        let to = (next() % 4) as usize;
        let ox = (next() % 300) as i32 - 100;
        let oy = (next() % 300) as i32 - 100;
        let x0 = ox + (next() % 200) as i32;
        let y = oy + (next() % 200) as i32;
        let qy = ((y & !1) - oy) as f32;
        let n = 1 + (next() % 90) as usize;
        // Every other round on the SSE2 λ (the AVX2 one where the CPU has it otherwise).
        crate::cpu::lanes::NO_AVX2.with(|c| c.set(round % 2 == 1));
        let mut sl = SpanLambda::new(x0, ox, qy);
        let mut check = |g: usize, got: [f32; LANES]| {
            for (l, got) in got.iter().enumerate() {
                let qx = (((x0 + (g + l) as i32) & !1) - ox) as f32;
                let want = s.quad_lambda(&planes, to, qx, qy);
                let same = got.to_bits() == want.to_bits() || got.is_nan() && want.is_nan();
                assert!(same, "x0 {x0} ox {ox} g {g} lane {l}: {got} vs {want}");
                checked += 1;
            }
        };
        let mut visited = Vec::new();
        let mut g = 0;
        while g < n {
            if next() % 4 != 0 {
                check(g, sl.lanes(s, &planes, to, x0 + g as i32));
                visited.push(g);
            }
            g += LANES;
        }
        let Some(&ga) = visited.first() else { continue };
        let gb = visited
            .iter()
            .copied()
            .filter(|&g| g < ga + 64)
            .max()
            .unwrap_or(ga);
        let qa = (x0 + ga as i32) >> 1;
        let nq = (((x0 + gb as i32 + 7) >> 1) - qa + 1) as usize;
        let mut lq = [[f32::NAN; LANES]; 5];
        let out = &mut lq[..nq.div_ceil(LANES)];
        if avx2 && round % 3 == 0 {
            s.quad_lambda_row::<true>(&planes, to, ox, qy, qa, out);
        } else {
            s.quad_lambda_row::<false>(&planes, to, ox, qy, qa, out);
        }
        for g in (ga..=gb).step_by(LANES) {
            let x = x0 + g as i32;
            check(
                g,
                spread_quads(lq.as_flattened(), ((x >> 1) - qa) as usize, x),
            );
        }
    }
    crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
    assert!(checked > 80_000, "{checked}");
}

#[test]
fn span_lambda_spans_of_many_rows_are_quad_lambda() {
    // Spans of both pixel rows of quad rows, of a few primitives (plane sets) and samplers
    // that differ only in size or dimensions, all on unit 0, in a random order, with groups
    // skipped (so that a span's eight kept quads are reused, passed and started over): every
    // lane is `quad_lambda` of its quad, bit for bit. (Written when the spans of one quad row
    // shared a per-thread row of quads keyed by the planes; that row is gone.)
    let mut next = lcg(41u64);
    let mut samplers = lambda_samplers();
    let mut wide = samplers[1].clone();
    wide.size[0] = 128.0;
    samplers.push(wide);
    let mut checked = 0;
    for round in 0..400 {
        let planes: Vec<Vec<f32>> = (0..3).map(|_| random_planes(&mut next)).collect();
        let ox = (next() % 300) as i32 - 150;
        for _ in 0..24 {
            let s = &samplers[(next() % samplers.len() as u64) as usize];
            let pl = &planes[(next() % 3) as usize];
            let to = (next() % 2) as usize;
            // Mostly one quad row (two pixel rows), sometimes the next.
            let qrow = (round % 5) * 2 + if next() % 6 == 0 { 2 } else { 0 };
            let qy = qrow as f32;
            let x0 = ox + (next() % 200) as i32 - 40;
            let n = 1 + (next() % 70) as usize;
            let mut sl = SpanLambda::new(x0, ox, qy);
            let mut g = 0;
            while g < n {
                if next() % 5 != 0 {
                    let got = sl.lanes(s, pl, to, x0 + g as i32);
                    for (l, got) in got.iter().enumerate() {
                        let qx = (((x0 + (g + l) as i32) & !1) - ox) as f32;
                        let want = s.quad_lambda(pl, to, qx, qy);
                        let same = got.to_bits() == want.to_bits() || got.is_nan() && want.is_nan();
                        assert!(
                            same,
                            "round {round} x0 {x0} g {g} lane {l}: {got} vs {want}"
                        );
                        checked += 1;
                    }
                }
                g += LANES;
            }
        }
    }
    assert!(checked > 100_000, "{checked}");
}

#[test]
fn ifloor_lanes_is_ifloor() {
    // The SSE2 truncation with `as i32`'s saturation and the step down, against `ifloor`:
    // the edges of the i32 range, NaN, infinities, signed zeros, subnormals, random bits.
    let mut next = lcg(29u64);
    let edges = [
        f32::NAN,
        -f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        0.0,
        -0.0,
        -0.5,
        0.5,
        -1.0,
        f32::MIN_POSITIVE / 8.0,
        -f32::MIN_POSITIVE / 8.0,
        2_147_483_648.0,
        2_147_483_520.0,
        -2_147_483_648.0,
        -2_147_483_904.0,
        -2_147_483_520.5,
        8_388_607.5,
        -8_388_607.5,
        f32::MAX,
        f32::MIN,
    ];
    for round in 0..20_000 {
        let x: [f32; LANES] = std::array::from_fn(|_| match (round + next() as usize) % 3 {
            0 => edges[(next() % edges.len() as u64) as usize],
            1 => f32::from_bits(next() as u32),
            _ => (next() % 2_000_000) as f32 * 1e-3 - 1000.0,
        });
        let got = ifloor_lanes(&x);
        // `ifloor8` (AVX2: `vroundps`' floor, then the truncation) on the same lanes.
        #[cfg(target_arch = "x86_64")]
        // SAFETY: the CPU has AVX2 (tested first); `__m256`/`__m256i` have the layouts of
        // `[f32; 8]`/`[i32; 8]`, every bit pattern valid.
        let got8 = crate::cpu::lanes::has_avx2().then(|| unsafe {
            std::mem::transmute::<std::arch::x86_64::__m256i, [i32; LANES]>(ifloor8(
                std::mem::transmute::<[f32; LANES], std::arch::x86_64::__m256>(x),
            ))
        });
        #[cfg(not(target_arch = "x86_64"))]
        let got8: Option<[i32; LANES]> = None;
        for l in 0..LANES {
            let want = ifloor(x[l]);
            assert_eq!(got[l], want, "{} ({:#x})", x[l], x[l].to_bits());
            if let Some(g) = got8 {
                assert_eq!(g[l], want, "ifloor8 {} ({:#x})", x[l], x[l].to_bits());
            }
        }
    }
}

#[test]
#[cfg(target_arch = "x86_64")]
fn dense_kernels_are_the_lane_pass_bit_for_bit() {
    // `dense_kernel` (the NEAREST and LINEAR kernels of a whole power-of-two level: SSE2,
    // and AVX2 where the CPU has it, each route run on its own) against `pass_on`'s lane
    // loops on the same level, and against the scalar `texel`, on
    // every wrap pair `kernel_kind` takes (and none it refuses), levels from 1x1 to 64x32,
    // coordinates with NaN, infinities, signed zeros, subnormals, huge values, texel centres
    // and edges, random masks: the same bits on the lanes of the mask, and the lanes outside it
    // left as they were.
    let mut next = lcg(37u64);
    let wraps = [
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::CLAMP_TO_BORDER,
        gl::MIRRORED_REPEAT,
    ];
    let sizes = [
        (1, 1),
        (1, 8),
        (8, 1),
        (2, 2),
        (4, 16),
        (16, 4),
        (64, 32),
        (32, 64),
    ];
    let specials = [
        f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        1e9,
        -1e9,
        2_147_483_648.0,
        -2_147_483_904.0,
        f32::MIN_POSITIVE / 8.0,
        f32::MAX,
        f32::MIN,
    ];
    let (mut taken, mut refused, mut wide_runs) = (0, 0, 0usize);
    for round in 0..3000 {
        let (w, h) = sizes[round % sizes.len()];
        let linear = round / sizes.len() % 2 == 1;
        let vals: Vec<[f32; 4]> = (0..w * h)
            .map(|_| std::array::from_fn(|_| (next() % 1001) as f32 / 1000.0))
            .collect();
        let filter = if linear { gl::LINEAR } else { gl::NEAREST };
        let mut obj = obj_with(
            vec![level(w, h, gl::RGBA, |i, j| vals[(j * w + i) as usize])],
            filter,
            filter,
        );
        obj.wrap_s = wraps[(next() % 5) as usize];
        obj.wrap_t = wraps[(next() % 5) as usize];
        let smp = sampler(obj, gl::REPLACE);
        let lv = smp.obj.face_level(0, 0).expect("level 0");
        let tx: &[[f32; 4]] = &lv.texels;
        assert!(dense_level(tx, w, h));
        let Some(kind) = kernel_kind(linear, smp.wrap) else {
            refused += 1;
            continue;
        };
        for _ in 0..16 {
            let coord = |next: &mut dyn FnMut() -> u64, n: i32| match next() % 8 {
                0 => specials[(next() % specials.len() as u64) as usize],
                1 => f32::from_bits(next() as u32),
                // Texel centres and edges (and their neighbours), inside and outside [0, 1].
                2 => ((next() % (8 * n as u64)) as f32 - 2.0 * n as f32) / (2.0 * n as f32),
                3 => f32::from_bits(
                    ((next() % (4 * n as u64)) as f32 / n as f32 - 1.0).to_bits() + 1,
                ),
                _ => (next() % 100_000) as f32 * 6e-5 - 3.0,
            };
            let cs: [f32; LANES] = std::array::from_fn(|_| coord(&mut next, w));
            let ct: [f32; LANES] = std::array::from_fn(|_| coord(&mut next, h));
            let m = (next() % 256) as u8;
            let fill = [f32::from_bits(0x7fc0_dead); 4];
            let (mut got, mut want) = ([fill; LANES], [fill; LANES]);
            dense_kernel(kind, tx, w, h, &cs, &ct, m, &mut got);
            smp.pass_on(linear, tx, Some(tx), w, h, &cs, &ct, m, &mut want, |_, t| t);
            // Both routes: the SSE2 kernels, and the AVX2 ones where the CPU has AVX2.
            let mut routes = vec![("any", got)];
            for wide in [false, true] {
                if wide && !avx2() {
                    continue;
                }
                let mut o = [fill; LANES];
                dense_kernel_on(wide, kind, tx, w, h, &cs, &ct, m, &mut o);
                routes.push((if wide { "avx2" } else { "sse2" }, o));
                wide_runs += usize::from(wide);
            }
            for l in 0..LANES {
                let bits = |t: [f32; 4]| t.map(f32::to_bits);
                for (name, got) in &routes {
                    assert_eq!(
                        bits(got[l]),
                        bits(want[l]),
                        "round {round} {w}x{h} kind {kind} {name} lane {l} m {m:#x}: ({}, {})",
                        cs[l],
                        ct[l]
                    );
                }
                if m & (1 << l) != 0 {
                    let scalar = smp.texel([cs[l], ct[l], 0.0, 1.0], 0.0);
                    assert_eq!(bits(got[l]), bits(scalar), "round {round} lane {l}");
                    taken += 1;
                }
            }
        }
    }
    assert!(taken > 40_000 && refused > 500, "{taken} {refused}");
    assert!(!avx2() || wide_runs > 10_000, "{wide_runs}");
}

#[test]
#[cfg(target_arch = "x86_64")]
fn dense_border_kernels_are_the_lane_pass_bit_for_bit() {
    // `dense_border` (the AVX2 kernels of a whole power-of-two level with a border texel:
    // CLAMP_TO_BORDER, and LINEAR's CLAMP, on one axis or both) against `pass_on`'s lane loops
    // (the route every CPU without AVX2 keeps) and the scalar `texel`, on every wrap pair
    // `border_kind` takes and none it refuses, NEAREST and LINEAR, levels from 1x1 to 64x32,
    // random border colours in several base formats, coordinates with NaN, infinities, signed
    // zeros, subnormals, huge values, texel centres and edges inside and far outside [0, 1],
    // random masks: the same bits on the lanes of the mask, the others left as they were; then
    // the same groups through `texels_lanes` (the dispatch in `pass_level`, depth textures
    // with their comparison included) against `texel`, with the AVX2 routes on and off.
    let mut next = lcg(41u64);
    let wraps = [
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::CLAMP_TO_BORDER,
        gl::MIRRORED_REPEAT,
    ];
    let sizes = [
        (1, 1),
        (1, 8),
        (8, 1),
        (2, 2),
        (4, 16),
        (16, 4),
        (64, 32),
        (32, 64),
        (64, 64),
    ];
    let bases = [
        gl::RGBA,
        gl::RGB,
        gl::LUMINANCE,
        gl::LUMINANCE_ALPHA,
        gl::ALPHA,
        gl::INTENSITY,
        gl::DEPTH_COMPONENT,
    ];
    let specials = [
        f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        1e9,
        -1e9,
        2_147_483_648.0,
        -2_147_483_904.0,
        f32::MIN_POSITIVE / 8.0,
        f32::MAX,
        f32::MIN,
    ];
    let (mut taken, mut refused, mut lanes_checked) = (0usize, 0usize, 0usize);
    let mut kinds = std::collections::BTreeSet::new();
    for round in 0..4000 {
        let (w, h) = sizes[round % sizes.len()];
        let linear = round / sizes.len() % 2 == 1;
        let base = bases[(next() % bases.len() as u64) as usize];
        let vals: Vec<[f32; 4]> = (0..w * h)
            .map(|_| std::array::from_fn(|_| (next() % 1001) as f32 / 1000.0))
            .collect();
        let filter = if linear { gl::LINEAR } else { gl::NEAREST };
        let mut obj = obj_with(
            vec![level(w, h, base, |i, j| vals[(j * w + i) as usize])],
            filter,
            filter,
        );
        random_border_lod_compare(&mut obj, base == gl::DEPTH_COMPONENT, &mut next);
        obj.border_color = Vec4::from_array(std::array::from_fn(|_| match next() % 5 {
            0 => 0.0,
            1 => 1.0,
            _ => (next() % 1001) as f32 / 1000.0,
        }));
        obj.wrap_s = wraps[(next() % 5) as usize];
        obj.wrap_t = wraps[(next() % 5) as usize];
        let smp = sampler(obj, gl::REPLACE);
        let lv = smp.obj.face_level(0, 0).expect("level 0");
        let tx: &[[f32; 4]] = &lv.texels;
        assert!(dense_level(tx, w, h));
        let border_axis = |mode: u32| mode == gl::CLAMP_TO_BORDER || (linear && mode == gl::CLAMP);
        let other_ok = |mode: u32| mode != gl::MIRRORED_REPEAT;
        let expect = (border_axis(smp.wrap[0]) || border_axis(smp.wrap[1]))
            && other_ok(smp.wrap[0])
            && other_ok(smp.wrap[1]);
        let kind = border_kind(linear, smp.wrap);
        assert_eq!(kind.is_some(), expect && avx2(), "{linear} {:?}", smp.wrap);
        // The two kinds of kernel never overlap.
        assert!(kind.is_none() || kernel_kind(linear, smp.wrap).is_none());
        if kind.is_none() {
            refused += 1;
        }
        let border = crate::texture::keep(smp.base, smp.border);
        for _ in 0..16 {
            let coord = |next: &mut dyn FnMut() -> u64, n: i32| match next() % 8 {
                0 => specials[(next() % specials.len() as u64) as usize],
                1 => f32::from_bits(next() as u32),
                2 => ((next() % (8 * n as u64)) as f32 - 2.0 * n as f32) / (2.0 * n as f32),
                3 => f32::from_bits(
                    ((next() % (4 * n as u64)) as f32 / n as f32 - 1.0).to_bits() + 1,
                ),
                _ => (next() % 100_000) as f32 * 6e-5 - 3.0,
            };
            let cs: [f32; LANES] = std::array::from_fn(|_| coord(&mut next, w));
            let ct: [f32; LANES] = std::array::from_fn(|_| coord(&mut next, h));
            let cr: [f32; LANES] = std::array::from_fn(|_| (next() % 1201) as f32 / 1000.0 - 0.1);
            let m = (next() % 256) as u8;
            let bits = |t: [f32; 4]| t.map(f32::to_bits);
            if let Some(kind) = kind {
                kinds.insert(kind);
                let fill = [f32::from_bits(0x7fc0_dead); 4];
                let (mut got, mut want) = ([fill; LANES], [fill; LANES]);
                dense_border(kind, tx, w, h, border, &cs, &ct, m, &mut got);
                smp.pass_on(linear, tx, Some(tx), w, h, &cs, &ct, m, &mut want, |_, t| t);
                for l in 0..LANES {
                    assert_eq!(
                        bits(got[l]),
                        bits(want[l]),
                        "round {round} {w}x{h} kind {kind:#x} lane {l} m {m:#x}: ({}, {})",
                        cs[l],
                        ct[l]
                    );
                    taken += usize::from(m & (1 << l) != 0);
                }
            }
            // Through the sampler's own dispatch, AVX2 on (where the CPU has it) and off.
            let q = [1.0f32; LANES];
            for off in [false, true] {
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(off));
                let got = smp.texels_lanes([&cs, &ct, &cr, &q], &[0.0; LANES], m);
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
                for l in 0..LANES {
                    if m & (1 << l) != 0 {
                        let want = smp.texel([cs[l], ct[l], cr[l], 1.0], 0.0);
                        assert_eq!(
                            bits(got[l]),
                            bits(want),
                            "round {round} {w}x{h} off {off} lane {l}: ({}, {}, {})",
                            cs[l],
                            ct[l],
                            cr[l]
                        );
                        lanes_checked += 1;
                    }
                }
            }
        }
    }
    assert!(
        refused > 1000 && lanes_checked > 200_000,
        "{refused} {lanes_checked}"
    );
    assert!(
        !avx2() || (taken > 50_000 && kinds.len() == 17),
        "{taken} {kinds:?}"
    );
}
