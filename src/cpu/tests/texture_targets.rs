//! The lane routes of `texture/targets.rs` against the scalar sampler, bit for bit: 1D, 3D and
//! cube-map textures through `texels_lanes` (every wrap mode, filter pair, mipmapped or not,
//! power-of-two or not, border colours, depth comparison, cube edges and corners, NaN and huge
//! coordinates, q = 0), and COMBINE through `env_lanes_with` (every function, source and
//! operand, each scale).

use std::sync::Arc;

use glam::Vec4;

use crate::cpu::lanes::LANES;
use crate::cpu::texture::tests::{lcg, random_border_lod_compare};
use crate::cpu::texture::Sampler;
use crate::gl;
use crate::state::State;
use crate::texture::{Level, TexObject, MAX_LEVELS};

/// A `w` x `h` x `d` level of base format `base` with random texels (multiples of 1/1000).
fn random_level(w: i32, h: i32, d: i32, base: u32, next: &mut impl FnMut() -> u64) -> Level {
    let texels = (0..w * h * d)
        .map(|_| std::array::from_fn(|_| (next() % 1001) as f32 / 1000.0))
        .collect::<Vec<_>>();
    Level {
        width: w,
        height: h,
        depth: d,
        internal_format: base as i32,
        base,
        texels: texels.into(),
    }
}

/// The sampler of unit 0 with `obj` bound to `target` (enabled) and environment `env`.
fn sampler_on(target: u32, obj: TexObject, env: u32, combine: crate::texture::Combine) -> Sampler {
    let mut state = State::new(4, 4);
    let k = match target {
        gl::TEXTURE_1D => {
            state.enables.texture_1d[0] = true;
            0
        }
        gl::TEXTURE_2D => {
            state.enables.texture_2d[0] = true;
            1
        }
        gl::TEXTURE_3D => {
            state.enables.texture_3d[0] = true;
            2
        }
        _ => {
            state.enables.texture_cube_map[0] = true;
            3
        }
    };
    state.textures.defaults[k] = Arc::new(obj);
    let u = &mut state.textures.units[0];
    u.env_mode = env;
    u.env_color = Vec4::new(1.0, 0.0, 0.5, 0.25);
    u.combine = combine;
    Sampler::new(&state, 0).expect("complete texture")
}

/// Same bits, or both NaN.
fn same(a: [f32; 4], b: [f32; 4]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| x.to_bits() == y.to_bits() || x.is_nan() && y.is_nan())
}

const WRAPS: [u32; 5] = [
    gl::REPEAT,
    gl::CLAMP,
    gl::CLAMP_TO_EDGE,
    gl::CLAMP_TO_BORDER,
    gl::MIRRORED_REPEAT,
];
const MINS: [u32; 6] = [
    gl::NEAREST,
    gl::LINEAR,
    gl::NEAREST_MIPMAP_NEAREST,
    gl::LINEAR_MIPMAP_NEAREST,
    gl::NEAREST_MIPMAP_LINEAR,
    gl::LINEAR_MIPMAP_LINEAR,
];
const BASES: [u32; 6] = [
    gl::ALPHA,
    gl::LUMINANCE,
    gl::LUMINANCE_ALPHA,
    gl::INTENSITY,
    gl::RGB,
    gl::RGBA,
];

/// A random complete object of `target` (1D, 2D, 3D or cube map): random base size (power of two
/// or not), every level down to 1 when `min` mipmaps, random wraps, LOD bounds and bias, a
/// border colour; a depth texture with or without comparison when `depth`.
fn random_object(target: u32, depth: bool, next: &mut impl FnMut() -> u64) -> TexObject {
    let base = if depth {
        [gl::DEPTH_COMPONENT, gl::DEPTH_STENCIL][(next() % 2) as usize]
    } else {
        BASES[(next() % 6) as usize]
    };
    let sizes = [1, 2, 3, 4, 5, 7, 8, 16];
    let pick = |next: &mut dyn FnMut() -> u64| sizes[(next() % sizes.len() as u64) as usize];
    let (mut w, mut h, mut d) = match target {
        gl::TEXTURE_1D => (pick(next), 1, 1),
        gl::TEXTURE_2D => (pick(next), pick(next), 1),
        gl::TEXTURE_3D => (pick(next), pick(next), pick(next)),
        _ => {
            let n = pick(next);
            (n, n, 1)
        }
    };
    let mut o = TexObject::new(target);
    o.min_filter = MINS[(next() % 6) as usize];
    o.mag_filter = if next() % 2 == 0 {
        gl::NEAREST
    } else {
        gl::LINEAR
    };
    let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
    let mut k = 0;
    loop {
        for f in 0..faces {
            o.levels[f * MAX_LEVELS + k] = Some(random_level(w, h, d, base, next));
        }
        if w == 1 && h == 1 && d == 1 {
            break;
        }
        let dim = |n: i32, on: bool| if on { (n / 2).max(1) } else { 1 };
        (w, h, d) = (
            dim(w, true),
            dim(h, target != gl::TEXTURE_1D),
            dim(d, target == gl::TEXTURE_3D),
        );
        k += 1;
    }
    o.wrap_s = WRAPS[(next() % 5) as usize];
    o.wrap_t = WRAPS[(next() % 5) as usize];
    o.wrap_r = WRAPS[(next() % 5) as usize];
    random_border_lod_compare(&mut o, depth, next);
    o
}

/// An awkward coordinate: 0, random bits (NaN, infinities, subnormals), ±1 and ±0.5 (cube
/// edges and corners when the three agree in magnitude), huge, small steps, or spread values.
fn coord(next: &mut dyn FnMut() -> u64) -> f32 {
    match next() % 16 {
        0 => 0.0,
        1 => f32::from_bits(next() as u32),
        2 => [f32::NAN, f32::INFINITY, -f32::INFINITY, 1e9, -1e9, -0.0][(next() % 6) as usize],
        3 => (next() % 64) as f32 / 8.0,
        4 | 5 => [1.0, -1.0, 0.5, -0.5, 0.25, -0.25][(next() % 6) as usize],
        _ => (next() % 100_000) as f32 * 6e-5 - 3.0,
    }
}

/// Eight lanes of coordinates (s, t, r, q) and λ.
#[allow(clippy::type_complexity)]
fn random_lanes(next: &mut dyn FnMut() -> u64) -> ([[f32; LANES]; 4], [f32; LANES]) {
    let lanes =
        |next: &mut dyn FnMut() -> u64| -> [f32; LANES] { std::array::from_fn(|_| coord(next)) };
    let (s, t, r) = (lanes(next), lanes(next), lanes(next));
    let q = std::array::from_fn(|_| match next() % 8 {
        0 => 0.0,
        1 => -1.5,
        2 => coord(next),
        _ => 1.0 + (next() % 100) as f32 * 0.01,
    });
    let lambda = std::array::from_fn(|_| match next() % 10 {
        0 => f32::NAN,
        1 => f32::INFINITY,
        2 => -f32::INFINITY,
        3 => (next() % 16) as f32 * 0.5 - 1.0,
        _ => (next() % 10_000) as f32 * 1e-3 - 2.0,
    });
    ([s, t, r, q], lambda)
}

#[test]
fn target_lanes_are_the_scalar_texel_bit_for_bit() {
    let mut next = lcg(29);
    let mut checked = [0usize; 3];
    for round in 0..3000 {
        let (ti, target) = [
            (0, gl::TEXTURE_1D),
            (1, gl::TEXTURE_3D),
            (2, gl::TEXTURE_CUBE_MAP),
        ][round % 3];
        let depth = round % 5 == 4;
        let obj = random_object(target, depth, &mut next);
        let s = sampler_on(target, obj, gl::MODULATE, Default::default());
        assert!(s.lanes_ok());
        for _ in 0..6 {
            let ([cs, ct, cr, cq], lambda) = random_lanes(&mut next);
            let m = (next() % 256) as u8;
            let got = s.texels_lanes([&cs, &ct, &cr, &cq], &lambda, m);
            for l in 0..LANES {
                if m & (1 << l) == 0 {
                    continue;
                }
                let want = s.texel([cs[l], ct[l], cr[l], cq[l]], lambda[l]);
                assert!(
                    same(got[l], want),
                    "round {round} target {target:#x} lane {l}: {:?} vs {want:?} \
                     ({}, {}, {}, {}) λ {}",
                    got[l],
                    cs[l],
                    ct[l],
                    cr[l],
                    cq[l],
                    lambda[l]
                );
                checked[ti] += 1;
            }
        }
    }
    assert!(checked.iter().all(|&n| n > 20_000), "{checked:?}");
}

/// Cube-map directions on the faces' edges and corners (|x| = |y| = |z| ties, signed zeros),
/// where the face choice is decided by the tie order: every lane the scalar texel.
#[test]
fn cube_edges_and_corners_pick_the_scalar_face() {
    let mut next = lcg(5);
    let vals = [1.0f32, -1.0, 0.0, -0.0, 0.5, -0.5, 2.0, -2.0];
    for round in 0..200 {
        let obj = random_object(gl::TEXTURE_CUBE_MAP, false, &mut next);
        let s = sampler_on(gl::TEXTURE_CUBE_MAP, obj, gl::REPLACE, Default::default());
        for a in 0..vals.len() {
            let mut c = [[0.0f32; LANES]; 3];
            for (l, _) in vals.iter().enumerate() {
                c[0][l] = vals[a];
                c[1][l] = vals[l];
                c[2][l] = vals[(a + l + round) % vals.len()];
            }
            let q = [1.0; LANES];
            let lambda = [0.0f32; LANES].map(|_| (next() % 40) as f32 * 0.25 - 2.0);
            let got = s.texels_lanes([&c[0], &c[1], &c[2], &q], &lambda, 0xff);
            for l in 0..LANES {
                let want = s.texel([c[0][l], c[1][l], c[2][l], 1.0], lambda[l]);
                assert!(same(got[l], want), "round {round} a {a} lane {l}");
            }
        }
    }
}

/// COMBINE's eight RGB functions; the alpha ones are the first six.
const COMBINE_FUNCS: [u32; 8] = [
    gl::REPLACE,
    gl::MODULATE,
    gl::ADD,
    gl::ADD_SIGNED,
    gl::INTERPOLATE,
    gl::SUBTRACT,
    gl::DOT3_RGB,
    gl::DOT3_RGBA,
];

/// The COMBINE state of round `round`: every RGB function in turn and every alpha function
/// after it, sources from `sources`, operands and scales drawn from `next`.
fn random_combine(
    round: usize,
    sources: &[u32],
    next: &mut dyn FnMut() -> u64,
) -> crate::texture::Combine {
    let operands_rgb = [
        gl::SRC_COLOR,
        gl::ONE_MINUS_SRC_COLOR,
        gl::SRC_ALPHA,
        gl::ONE_MINUS_SRC_ALPHA,
    ];
    let operands_a = [gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA];
    let scales = [1.0, 2.0, 4.0];
    let n = COMBINE_FUNCS.len();
    let mut pick = |v: &[u32]| v[(next() % v.len() as u64) as usize];
    let src_rgb = std::array::from_fn(|_| pick(sources));
    let src_alpha = std::array::from_fn(|_| pick(sources));
    let operand_rgb = std::array::from_fn(|_| pick(&operands_rgb));
    let operand_alpha = std::array::from_fn(|_| pick(&operands_a));
    crate::texture::Combine {
        rgb: COMBINE_FUNCS[round % n],
        alpha: COMBINE_FUNCS[(round / n) % 6],
        src_rgb,
        src_alpha,
        operand_rgb,
        operand_alpha,
        rgb_scale: scales[(next() % 3) as usize],
        alpha_scale: scales[(next() % 3) as usize],
    }
}

/// Every COMBINE function, source, operand and scale on 1D, 2D, 3D and cube textures (depth
/// ones included): `texels_lanes` then `env_lanes_with` hold what `shade` gives for each
/// lane's fragment with its own previous and primary colours.
#[test]
fn combine_lanes_are_shade_bit_for_bit() {
    let mut next = lcg(71);
    let sources = [gl::CONSTANT, gl::PRIMARY_COLOR, gl::PREVIOUS, gl::TEXTURE];
    let targets = [
        gl::TEXTURE_1D,
        gl::TEXTURE_2D,
        gl::TEXTURE_3D,
        gl::TEXTURE_CUBE_MAP,
    ];
    let mut checked = 0;
    for round in 0..2000 {
        let target = targets[round % 4];
        let depth = round % 7 == 6 && target != gl::TEXTURE_3D;
        let obj = random_object(target, depth, &mut next);
        let combine = random_combine(round, &sources, &mut next);
        let s = sampler_on(target, obj, gl::COMBINE, combine);
        assert!(s.lanes_ok());
        for _ in 0..4 {
            let ([cs, ct, cr, cq], lambda) = random_lanes(&mut next);
            let colour = |next: &mut dyn FnMut() -> u64| -> [Vec4; LANES] {
                std::array::from_fn(|_| {
                    Vec4::from_array(std::array::from_fn(|_| (next() % 300) as f32 / 256.0))
                })
            };
            let (cf, prim) = (colour(&mut next), colour(&mut next));
            let m = (next() % 256) as u8;
            let texels = s.texels_lanes([&cs, &ct, &cr, &cq], &lambda, m);
            let mut got = cf;
            s.env_lanes_with(&mut got, &prim, &texels, m);
            for l in 0..LANES {
                if m & (1 << l) == 0 {
                    continue;
                }
                let want = s.shade(cf[l], prim[l], [cs[l], ct[l], cr[l], cq[l]], lambda[l]);
                assert!(
                    same(got[l].to_array(), want.to_array()),
                    "round {round} lane {l}: {} vs {want} {combine:?}",
                    got[l]
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 25_000, "{checked}");
}

/// COMBINE on lanes, the AVX2 route (channel registers, `combine8`) and the SSE2 one
/// (`combine_lanes`), against the scalar `shade_texel` on awkward inputs: raw texels, previous
/// and primary colours with NaN, infinities, negative, huge, tiny and above-one channels, every
/// function, source (an unknown one too), operand and scale, every base format and depth texture
/// mode; lanes outside the mask keep their colour's bits.
#[test]
fn combine_lanes_on_awkward_values_are_shade_texel_bit_for_bit() {
    let mut next = lcg(313);
    let sources = [
        gl::CONSTANT,
        gl::PRIMARY_COLOR,
        gl::PREVIOUS,
        gl::TEXTURE,
        0,
    ];
    let odd = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -0.0,
        0.0,
        1.0,
        -1.5,
        3.0e38,
        1.0e-40,
        0.5,
    ];
    let mut checked = 0;
    for round in 0..3000 {
        let depth = round % 5 == 4;
        let obj = random_object(gl::TEXTURE_2D, depth, &mut next);
        let combine = random_combine(round, &sources, &mut next);
        let mut s = sampler_on(gl::TEXTURE_2D, obj, gl::COMBINE, combine);
        if depth {
            s.depth_mode = [gl::LUMINANCE, gl::INTENSITY, gl::ALPHA][round % 3];
            // The choices `Sampler::new` made for the old mode.
            s.comb_pick = super::CombinePick::of(&s);
        }
        let mut value = || -> f32 {
            match next() % 4 {
                0 => odd[(next() % odd.len() as u64) as usize],
                _ => (next() % 3000) as f32 / 1000.0 - 1.0,
            }
        };
        let mut colour = || -> [Vec4; LANES] {
            std::array::from_fn(|_| Vec4::new(value(), value(), value(), value()))
        };
        let (cf, prim) = (colour(), colour());
        let texels: [[f32; 4]; LANES] = colour().map(|v| v.to_array());
        let m = (next() % 256) as u8;
        for off in [false, true] {
            let mut got = cf;
            crate::cpu::lanes::NO_AVX2.with(|x| x.set(off));
            s.env_lanes_with(&mut got, &prim, &texels, m);
            crate::cpu::lanes::NO_AVX2.with(|x| x.set(false));
            for l in 0..LANES {
                let want = match m & (1 << l) != 0 {
                    true => s.shade_texel(cf[l], prim[l], texels[l], &[]),
                    false => cf[l],
                };
                assert_eq!(
                    got[l].to_array().map(f32::to_bits),
                    want.to_array().map(f32::to_bits),
                    "round {round} lane {l} avx2 off {off}: {combine:?}",
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 3000 * LANES * 2);
}

/// The other environments through `env_lanes_with` are `env_lanes`, on every target.
#[test]
fn env_lanes_with_other_environments_is_shade() {
    let mut next = lcg(3);
    let envs = [gl::REPLACE, gl::MODULATE, gl::DECAL, gl::BLEND, gl::ADD];
    for round in 0..500 {
        let target = [gl::TEXTURE_1D, gl::TEXTURE_3D, gl::TEXTURE_CUBE_MAP][round % 3];
        let obj = random_object(target, round % 6 == 5, &mut next);
        let s = sampler_on(target, obj, envs[round % 5], Default::default());
        let ([cs, ct, cr, cq], lambda) = random_lanes(&mut next);
        let cf: [Vec4; LANES] = std::array::from_fn(|_| {
            Vec4::from_array(std::array::from_fn(|_| (next() % 300) as f32 / 256.0))
        });
        let texels = s.texels_lanes([&cs, &ct, &cr, &cq], &lambda, 0xff);
        let mut got = cf;
        s.env_lanes_with(&mut got, &cf, &texels, 0xff);
        for l in 0..LANES {
            let want = s.shade(cf[l], cf[l], [cs[l], ct[l], cr[l], cq[l]], lambda[l]);
            assert!(
                same(got[l].to_array(), want.to_array()),
                "round {round} lane {l}"
            );
        }
    }
}

/// A cube map's λ on lanes (`quad_lambda_lanes`, by `cube_lambda_lanes`) is `quad_lambda` per
/// quad: random planes with NaN, infinities and zeros, directions near the faces' edges and
/// corners (planes of equal magnitude), face sizes 1 to 64.
#[test]
fn cube_lambda_lanes_is_the_scalar_lambda() {
    let mut next = lcg(17);
    let mut samplers = Vec::new();
    for n in [1, 4, 5, 64] {
        let mut o = TexObject::new(gl::TEXTURE_CUBE_MAP);
        o.min_filter = gl::NEAREST;
        for f in 0..6 {
            o.levels[f * MAX_LEVELS] = Some(random_level(n, n, 1, gl::RGB, &mut next));
        }
        samplers.push(sampler_on(
            gl::TEXTURE_CUBE_MAP,
            o,
            gl::MODULATE,
            Default::default(),
        ));
    }
    for round in 0..20_000 {
        let s = &samplers[round % samplers.len()];
        let np = 3 + 3 * (1 + (next() % 8) as usize);
        let planes: Vec<f32> = (0..np)
            .map(|_| match next() % 10 {
                0 => 0.0,
                1 => f32::from_bits(next() as u32),
                2 => [1.0, -1.0, 0.5, -0.5][(next() % 4) as usize],
                3 => [f32::NAN, f32::INFINITY, -f32::INFINITY][(next() % 3) as usize],
                _ => (next() % 100_000) as f32 * 1e-4 - 5.0,
            })
            .collect();
        let to = (next() % 4) as usize;
        let qx: [f32; LANES] = std::array::from_fn(|_| ((next() % 400) as i32 - 50) as f32);
        let qy = ((next() % 400) as i32 - 50) as f32;
        let got = s.quad_lambda_lanes(&planes, to, qx, qy);
        for l in 0..LANES {
            let want = s.quad_lambda(&planes, to, qx[l], qy);
            let same = got[l].to_bits() == want.to_bits() || got[l].is_nan() && want.is_nan();
            assert!(
                same,
                "round {round} lane {l}: {} vs {want} {planes:?}",
                got[l]
            );
        }
    }
}

/// Lanes close together (a small step from lane to lane, one λ or nearby ones), as the
/// fragments of a span give them: most groups have every lane on one face and level, the
/// passes' one-image route; each lane the scalar texel bit for bit.
#[test]
fn coherent_lanes_are_the_scalar_texel_bit_for_bit() {
    let mut next = lcg(41);
    let mut checked = [0usize; 3];
    for round in 0..3000 {
        let (ti, target) = [
            (0, gl::TEXTURE_1D),
            (1, gl::TEXTURE_3D),
            (2, gl::TEXTURE_CUBE_MAP),
        ][round % 3];
        let obj = random_object(target, round % 7 == 6, &mut next);
        let s = sampler_on(target, obj, gl::MODULATE, Default::default());
        for _ in 0..6 {
            let base: [f32; 4] = std::array::from_fn(|_| coord(&mut next));
            let step: [f32; 4] = std::array::from_fn(|_| (next() % 2001) as f32 * 1e-5 - 0.01);
            let c: [[f32; LANES]; 4] = std::array::from_fn(|k| {
                std::array::from_fn(|l| match k {
                    3 => 1.0,
                    _ => base[k] + step[k] * l as f32,
                })
            });
            let l0 = (next() % 4000) as f32 * 1e-3 - 1.0;
            let dl = if next() % 2 == 0 { 0.0 } else { 0.01 };
            let lambda: [f32; LANES] = std::array::from_fn(|l| l0 + dl * l as f32);
            let m = match next() % 3 {
                0 => 0xff,
                _ => (next() % 256) as u8,
            };
            let got = s.texels_lanes([&c[0], &c[1], &c[2], &c[3]], &lambda, m);
            for l in 0..LANES {
                if m & (1 << l) == 0 {
                    continue;
                }
                let want = s.texel([c[0][l], c[1][l], c[2][l], c[3][l]], lambda[l]);
                assert!(
                    same(got[l], want),
                    "round {round} target {target:#x} lane {l}: {:?} vs {want:?}",
                    got[l]
                );
                checked[ti] += 1;
            }
        }
    }
    assert!(checked.iter().all(|&n| n > 20_000), "{checked:?}");
}

/// A 2D depth texture of power-of-two size with NEAREST filters and a wrap mode the dense
/// kernels take (REPEAT, CLAMP, CLAMP_TO_EDGE), comparison on with every function: the
/// kernel's gather then `depth_compare_lanes` (`pass_level`), each lane the scalar texel bit
/// for bit, over every coverage mask.
#[test]
fn dense_depth_nearest_is_the_scalar_texel_bit_for_bit() {
    let mut next = lcg(59);
    let mut checked = 0usize;
    let funcs = [
        gl::LEQUAL,
        gl::GEQUAL,
        gl::LESS,
        gl::GREATER,
        gl::EQUAL,
        gl::NOTEQUAL,
        gl::ALWAYS,
        gl::NEVER,
    ];
    let wraps = [gl::REPEAT, gl::CLAMP, gl::CLAMP_TO_EDGE];
    for round in 0..2000 {
        let sizes = [1, 2, 4, 8, 16, 64];
        let (w, h) = (sizes[(next() % 6) as usize], sizes[(next() % 6) as usize]);
        let mut o = TexObject::new(gl::TEXTURE_2D);
        // Depths in [0, 1] in steps of 1/1000, so that r often equals a texel.
        o.levels[0] = Some(random_level(w, h, 1, gl::DEPTH_COMPONENT, &mut next));
        o.min_filter = gl::NEAREST;
        o.mag_filter = gl::NEAREST;
        o.wrap_s = wraps[(next() % 3) as usize];
        o.wrap_t = wraps[(next() % 3) as usize];
        o.compare_mode = gl::COMPARE_R_TO_TEXTURE;
        o.compare_func = funcs[round % 8];
        o.depth_texture_mode = gl::LUMINANCE;
        let s = sampler_on(gl::TEXTURE_2D, o, gl::MODULATE, Default::default());
        for _ in 0..6 {
            let ([cs, ct, mut cr, cq], lambda) = random_lanes(&mut next);
            if next() % 2 == 0 {
                for r in &mut cr {
                    *r = (next() % 1201) as f32 / 1000.0 - 0.1;
                }
            }
            let m = (next() % 256) as u8;
            // The AVX2 kernel (gather and comparison in one, `dense_depth`) where the CPU has
            // it, and the SSE2 route (the gather, then `depth_compare_lanes`).
            for off in [false, true] {
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(off));
                let got = s.texels_lanes([&cs, &ct, &cr, &cq], &lambda, m);
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(false));
                for l in 0..LANES {
                    if m & (1 << l) == 0 {
                        continue;
                    }
                    let want = s.texel([cs[l], ct[l], cr[l], cq[l]], lambda[l]);
                    assert_eq!(
                        got[l].map(f32::to_bits),
                        want.map(f32::to_bits),
                        "round {round} off {off} lane {l}: ({}, {}, {}, {})",
                        cs[l],
                        ct[l],
                        cr[l],
                        cq[l]
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 80_000, "{checked}");
}

/// The kernels of the one-image route of `pass_targets` (a cube face by the 2D
/// `dense_kernel`, a 1D or 3D LINEAR level by the AVX2 `dense_targets`) against the scalar
/// `texel`, bit for bit, with the AVX2 routes on (where the CPU has them) and off (then the
/// cube face takes the SSE2 kernel and the 1D/3D levels `pass_dense`): power-of-two 1D, 3D
/// and cube objects of every base format, REPEAT and CLAMP_TO_EDGE on most axes (the other
/// modes now and then, which keep the lane passes), NEAREST, LINEAR and mipmapped filters,
/// lanes a small step apart (one face and level: the kernels) or awkward ones (NaN, ±∞, huge),
/// random masks and λ.
#[test]
fn dense_target_kernels_are_the_scalar_texel_bit_for_bit() {
    let mut next = lcg(67);
    let mut checked = [0usize; 3];
    let mut kernel_groups = 0usize;
    let sizes = [1, 2, 4, 8, 16, 32];
    for round in 0..3000 {
        let (ti, target) = [
            (0, gl::TEXTURE_1D),
            (1, gl::TEXTURE_3D),
            (2, gl::TEXTURE_CUBE_MAP),
        ][round % 3];
        let base = BASES[(next() % 6) as usize];
        let pick = |next: &mut dyn FnMut() -> u64| sizes[(next() % sizes.len() as u64) as usize];
        let (mut w, mut h, mut d) = match target {
            gl::TEXTURE_1D => (pick(&mut next), 1, 1),
            gl::TEXTURE_3D => (pick(&mut next), pick(&mut next), pick(&mut next)),
            _ => {
                let n = pick(&mut next);
                (n, n, 1)
            }
        };
        let mut o = TexObject::new(target);
        o.min_filter = [
            gl::LINEAR,
            gl::LINEAR_MIPMAP_LINEAR,
            gl::NEAREST,
            MINS[(next() % 6) as usize],
        ][(next() % 4) as usize];
        o.mag_filter = if next() % 4 == 0 {
            gl::NEAREST
        } else {
            gl::LINEAR
        };
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        let mut k = 0;
        loop {
            for f in 0..faces {
                o.levels[f * MAX_LEVELS + k] = Some(random_level(w, h, d, base, &mut next));
            }
            if w == 1 && h == 1 && d == 1 {
                break;
            }
            let dim = |n: i32, on: bool| if on { (n / 2).max(1) } else { 1 };
            (w, h, d) = (
                dim(w, true),
                dim(h, target != gl::TEXTURE_1D),
                dim(d, target == gl::TEXTURE_3D),
            );
            k += 1;
        }
        let wrap = |next: &mut dyn FnMut() -> u64| match next() % 8 {
            0 => WRAPS[(next() % 5) as usize],
            1..=3 => gl::REPEAT,
            _ => gl::CLAMP_TO_EDGE,
        };
        o.wrap_s = wrap(&mut next);
        o.wrap_t = wrap(&mut next);
        o.wrap_r = wrap(&mut next);
        random_border_lod_compare(&mut o, false, &mut next);
        let s = sampler_on(target, o, gl::MODULATE, Default::default());
        for _ in 0..8 {
            let c: [[f32; LANES]; 4] = if next() % 4 == 0 {
                random_lanes(&mut next).0
            } else {
                let base: [f32; 4] = std::array::from_fn(|_| match next() % 4 {
                    0 => coord(&mut next),
                    _ => (next() % 4000) as f32 * 1e-3 - 1.5,
                });
                let step: [f32; 4] = std::array::from_fn(|_| (next() % 2001) as f32 * 1e-4 - 0.1);
                std::array::from_fn(|k| {
                    std::array::from_fn(|l| match k {
                        3 => 1.0,
                        _ => base[k] + step[k] * l as f32,
                    })
                })
            };
            let l0 = (next() % 4000) as f32 * 1e-3 - 1.0;
            let dl = if next() % 2 == 0 { 0.0 } else { 0.01 };
            let lambda: [f32; LANES] = std::array::from_fn(|l| l0 + dl * l as f32);
            let m = match next() % 3 {
                0 => 0xff,
                _ => (next() % 256) as u8,
            };
            if m.count_ones() > 3 {
                kernel_groups += 1;
            }
            for off in [false, true] {
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(off));
                let got = s.texels_lanes([&c[0], &c[1], &c[2], &c[3]], &lambda, m);
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(false));
                for l in 0..LANES {
                    if m & (1 << l) == 0 {
                        continue;
                    }
                    let want = s.texel([c[0][l], c[1][l], c[2][l], c[3][l]], lambda[l]);
                    assert_eq!(
                        got[l].map(f32::to_bits),
                        want.map(f32::to_bits),
                        "round {round} target {target:#x} off {off} lane {l}: {:?}",
                        [c[0][l], c[1][l], c[2][l]]
                    );
                    checked[ti] += 1;
                }
            }
        }
    }
    assert!(
        checked.iter().all(|&n| n > 40_000) && kernel_groups > 10_000,
        "{checked:?}"
    );
}

/// The scalar LINEAR's 3D in-image route (`linear_on::<true>`: the eight texels read directly,
/// no per-texel border or comparison choice) against its `fetch` route (`linear_on::<false>`)
/// on random 3D textures (every wrap mode, power-of-two or not, depth ones with and without
/// comparison), every level and awkward coordinates: the same bits (or both NaN).
#[test]
fn scalar_linear_3d_in_image_is_the_fetch_route_bit_for_bit() {
    let mut next = lcg(113);
    let mut fast = 0usize;
    for round in 0..2000 {
        let depth = round % 5 == 4;
        let obj = random_object(gl::TEXTURE_3D, depth, &mut next);
        let s = sampler_on(gl::TEXTURE_3D, obj, gl::MODULATE, Default::default());
        for _ in 0..40 {
            let (cs, ct, cr) = (coord(&mut next), coord(&mut next), coord(&mut next));
            let level = (next() % 6) as i32 - 1;
            let got = s.linear_on::<true>(0, level, cs, ct, cr);
            let want = s.linear_on::<false>(0, level, cs, ct, cr);
            assert!(
                same(got, want),
                "round {round} level {level}: {got:?} vs {want:?} ({cs}, {ct}, {cr})"
            );
            fast += usize::from(cs.is_finite() && !depth);
        }
    }
    assert!(fast > 20_000, "{fast}");
}

/// `lod_dense` (both levels of a 1D or 3D LINEAR_MIPMAP_LINEAR group and their blend in one
/// AVX2 kernel): power-of-two mipmapped textures with REPEAT and CLAMP_TO_EDGE axes, groups
/// of nearby coordinates with one λ (all lanes on one level, most blending two), every
/// coverage mask; `texels_lanes` on both routes (AVX2 on and off) is the scalar texel bit for
/// bit, and `lod_dense` itself, given `select_lanes`' levels and weights as `lod_targets`
/// gives them, takes most groups and writes the same texels.
#[test]
fn lod_dense_kernel_is_the_scalar_texel_bit_for_bit() {
    let mut next = lcg(83);
    let mut taken = [0usize; 2];
    let sizes = [1, 2, 4, 8, 16, 32];
    for round in 0..2000 {
        let (ti, target) = [(0, gl::TEXTURE_1D), (1, gl::TEXTURE_3D)][round % 2];
        let base = BASES[(next() % 6) as usize];
        let pick = |next: &mut dyn FnMut() -> u64| sizes[(next() % sizes.len() as u64) as usize];
        let (mut w, mut h, mut d) = match target {
            gl::TEXTURE_1D => (pick(&mut next), 1, 1),
            _ => (pick(&mut next), pick(&mut next), pick(&mut next)),
        };
        let mut o = TexObject::new(target);
        o.min_filter = gl::LINEAR_MIPMAP_LINEAR;
        o.mag_filter = gl::LINEAR;
        let mut k = 0;
        loop {
            o.levels[k] = Some(random_level(w, h, d, base, &mut next));
            if w == 1 && h == 1 && d == 1 {
                break;
            }
            let dim = |n: i32, on: bool| if on { (n / 2).max(1) } else { 1 };
            (w, h, d) = (
                dim(w, true),
                dim(h, target != gl::TEXTURE_1D),
                dim(d, target == gl::TEXTURE_3D),
            );
            k += 1;
        }
        let wrap = |next: &mut dyn FnMut() -> u64| match next() % 2 {
            0 => gl::REPEAT,
            _ => gl::CLAMP_TO_EDGE,
        };
        o.wrap_s = wrap(&mut next);
        o.wrap_t = wrap(&mut next);
        o.wrap_r = wrap(&mut next);
        let s = sampler_on(target, o, gl::MODULATE, Default::default());
        for _ in 0..8 {
            let base: [f32; 3] = std::array::from_fn(|_| match next() % 8 {
                0 => coord(&mut next),
                _ => (next() % 4000) as f32 * 1e-3 - 1.5,
            });
            let step: [f32; 3] = std::array::from_fn(|_| (next() % 2001) as f32 * 1e-4 - 0.1);
            let c: [[f32; LANES]; 3] =
                std::array::from_fn(|k| std::array::from_fn(|l| base[k] + step[k] * l as f32));
            let q = [1.0f32; LANES];
            let lambda = [match next() % 8 {
                0 => coord(&mut next),
                _ => (next() % 7000) as f32 * 1e-3 - 1.0,
            }; LANES];
            let m = match next() % 3 {
                0 => 0xff,
                _ => (next() % 256) as u8 | 0x81,
            };
            for off in [false, true] {
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(off));
                let got = s.texels_lanes([&c[0], &c[1], &c[2], &q], &lambda, m);
                // `lod_dense` alone, with the levels and weights `lod_targets` gives it.
                let (lv, linear, f) = s.select_lanes(&lambda);
                let second = super::mask_ne_zero(&f) & m;
                let mut direct = [[f32::NAN; 4]; LANES];
                let took = linear & m == m
                    && s.lod_dense(&lv, &c[0], &c[1], &c[2], &f, second, m, &mut direct);
                crate::cpu::lanes::NO_AVX2.with(|x| x.set(false));
                assert!(!(off && took), "round {round}: the kernel ran without AVX2");
                taken[ti] += usize::from(took);
                for l in (0..LANES).filter(|l| m & (1 << l) != 0) {
                    let want = s.texel([c[0][l], c[1][l], c[2][l], 1.0], lambda[l]);
                    let what = format!("round {round} target {target:#x} off {off} lane {l}");
                    assert_eq!(got[l].map(f32::to_bits), want.map(f32::to_bits), "{what}");
                    if took {
                        assert_eq!(
                            direct[l].map(f32::to_bits),
                            want.map(f32::to_bits),
                            "{what}"
                        );
                    }
                }
            }
        }
    }
    // The kernel needs AVX2; where the CPU has it, it takes most groups.
    if crate::cpu::lanes::has_avx2() {
        assert!(taken.iter().all(|&n| n > 3000), "{taken:?}");
    }
}

/// [`cube8`](crate::cpu::texture::cube8) (the AVX2 cube route's faces) against `cube_face`
/// and `cube_project` lane by lane, bit for bit: awkward directions (NaN, infinities,
/// subnormals, signed zeros, huge) and the faces' edges and corners (ties of |x|, |y|, |z| in
/// every order and sign).
#[cfg(target_arch = "x86_64")]
#[test]
fn cube8_is_cube_face_and_project_bit_for_bit() {
    use crate::cpu::texture::{cube8, cube_face, cube_project};
    use std::arch::x86_64::{__m256, __m256i};
    if !crate::cpu::lanes::has_avx2() {
        return;
    }
    let mut next = lcg(41);
    let ties = [1.0f32, -1.0, 0.0, -0.0, 0.5, -0.5, f32::NAN, f32::INFINITY];
    let mut faces = [0usize; 6];
    for round in 0..20_000 {
        let p: [[f32; LANES]; 3] = std::array::from_fn(|_| {
            std::array::from_fn(|_| match round % 3 {
                0 => coord(&mut next),
                _ => ties[(next() % ties.len() as u64) as usize],
            })
        });
        // SAFETY: AVX2 is present (checked above); `__m256`/`__m256i` have the layout of
        // `[f32; 8]`/`[i32; 8]`, every bit pattern valid for both.
        let (f, s, t) = unsafe {
            let v = |x: [f32; LANES]| std::mem::transmute::<[f32; LANES], __m256>(x);
            let (f, s, t) = cube8(v(p[0]), v(p[1]), v(p[2]));
            (
                std::mem::transmute::<__m256i, [i32; LANES]>(f),
                std::mem::transmute::<__m256, [f32; LANES]>(s),
                std::mem::transmute::<__m256, [f32; LANES]>(t),
            )
        };
        for l in 0..LANES {
            let d = [p[0][l], p[1][l], p[2][l]];
            let (face, _) = cube_face(d);
            let (ws, wt) = cube_project(face, d);
            assert!(
                f[l] == face as i32
                    && s[l].to_bits() == ws.to_bits()
                    && t[l].to_bits() == wt.to_bits(),
                "round {round} lane {l} {d:?}: ({}, {}, {}) vs ({face}, {ws}, {wt})",
                f[l],
                s[l],
                t[l]
            );
            faces[face] += 1;
        }
    }
    assert!(faces.iter().all(|&n| n > 5000), "{faces:?}");
}

/// The packed route of the general path (`FragCtx::packed_rows`: a primitive's fragments that
/// pass the depth test, eight to a group across its rows, each lane's varyings and λ at its
/// own pixel) against the row route (the SSE2 routes, which never pack: each span's groups
/// from its first pixel) byte for byte: colours, depths and the occlusion count, for one to
/// four units of any target (1D, 2D, 3D, cube map; a cube map that needs λ is not packed),
/// any filter, environment or COMBINE, small triangles of a few rows in random tiles, random
/// depth tests and stipples, and now and then a NaN, infinite or zero plane term.
#[cfg(target_arch = "x86_64")]
#[test]
fn packed_groups_are_the_row_route_byte_for_byte() {
    use crate::cpu::fragment::tex_units;
    use crate::cpu::setup::{PrimKind, RPrim};
    use crate::state::MAX_TEXTURE_UNITS;
    if !crate::cpu::lanes::has_avx2() {
        eprintln!("packed_groups_are_the_row_route_byte_for_byte: no AVX2 here, no packed route");
        return;
    }
    let mut next = lcg(89);
    let targets = [
        gl::TEXTURE_1D,
        gl::TEXTURE_2D,
        gl::TEXTURE_3D,
        gl::TEXTURE_CUBE_MAP,
    ];
    let envs = [
        gl::MODULATE,
        gl::REPLACE,
        gl::DECAL,
        gl::ADD,
        gl::BLEND,
        gl::COMBINE,
    ];
    let sources = [gl::CONSTANT, gl::PRIMARY_COLOR, gl::PREVIOUS, gl::TEXTURE];
    let (mut packed, mut frags) = (0, 0usize);
    for round in 0..1500 {
        let units = 1 + round % MAX_TEXTURE_UNITS;
        let mut state = State::new(4, 4);
        for u in 0..units {
            let target = targets[(next() % 4) as usize];
            let k = match target {
                gl::TEXTURE_1D => {
                    state.enables.texture_1d[u] = true;
                    0
                }
                gl::TEXTURE_2D => {
                    state.enables.texture_2d[u] = true;
                    1
                }
                gl::TEXTURE_3D => {
                    state.enables.texture_3d[u] = true;
                    2
                }
                _ => {
                    state.enables.texture_cube_map[u] = true;
                    3
                }
            };
            // Units of one target share its (default) object.
            state.textures.defaults[k] = Arc::new(random_object(target, false, &mut next));
            let unit = &mut state.textures.units[u];
            unit.env_mode = envs[(next() % envs.len() as u64) as usize];
            unit.env_color = Vec4::new(1.0, 0.0, 0.5, 0.25);
            unit.combine = random_combine(round, &sources, &mut next);
        }
        let samplers: Vec<Sampler> = (0..units)
            .map(|u| Sampler::new(&state, u).expect("complete texture"))
            .collect();
        let mut slots: [Option<Sampler>; MAX_TEXTURE_UNITS] = Default::default();
        for (slot, s) in slots.iter_mut().zip(samplers) {
            *slot = Some(s);
        }
        let rl = crate::cpu::testgen::tex_layout(units);
        let tex = tex_units(&slots, &rl);
        let f = crate::cpu::testgen::tex_ctx(rl, tex, &mut next);
        let (tx, ty) = (64 * (next() % 4) as i32, 64 * (next() % 4) as i32);
        let bbox = [
            tx + (next() % 40) as i32 - 20,
            ty + (next() % 40) as i32 - 20,
        ];
        let p = RPrim {
            kind: PrimKind::Tri,
            flags: 0,
            bbox: [bbox[0], bbox[1], bbox[0] + 100, bbox[1] + 100],
            mat: 0,
            voff: 0,
            xy: [0; 6],
            owns: 0,
            cover: 0,
            z: [
                (next() % 1000) as f32 * 1e-3,
                (next() % 100) as f32 * 1e-3 - 0.05,
                1e-3,
            ],
        };
        // 1/w, the colour (around [0, 1]) and coordinates spanning a few repeats, with
        // derivatives large and small so that λ crosses the levels.
        let unit = |n: &mut dyn FnMut() -> u64| (n() % 1_000_000) as f32 * 1.5e-6 - 0.25;
        let mut planes = vec![0.5 + (next() % 100) as f32 * 0.01, 1e-3, -2e-3];
        for j in 0..rl.n {
            let d = if j < 4 {
                1e-2
            } else {
                [1e-3, 3e-2, 0.3][(next() % 3) as usize]
            };
            let (a, b, c) = (unit(&mut next), unit(&mut next), unit(&mut next));
            planes.extend([a, b * d, c * d]);
        }
        if next() % 10 == 0 {
            let k = 3 + 3 * 4 + (next() % (3 * 4 * units as u64)) as usize;
            if let Some(v) = planes.get_mut(k) {
                *v = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0][(next() % 4) as usize];
            }
        }
        // A small triangle's rows: consecutive, a few pixels each, drifting, in the tile.
        let rows = crate::cpu::testgen::tri_rows_in_tile(&mut next, tx, ty, 14);
        let (packs, _, n) =
            crate::cpu::testgen::tri_rows_agree(&f, &p, &planes, &rows, (tx, ty), &mut next);
        if packs {
            packed += 1;
            frags += n;
        }
    }
    assert!(packed > 600, "{packed} rounds packed");
    assert!(frags > 10_000, "{frags} fragments in packed rounds");
}
