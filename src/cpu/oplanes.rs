//! The per-fragment operations of `fragops` (fog §3.10, alpha test §4.1.4, stencil §4.1.5,
//! depth §4.1.6, blending §4.1.8, logic op §4.1.10) on groups of `LANES` fragments of a span,
//! for `FragCtx::full_span`: the span runs stage by stage over eight fragments at a time with a
//! coverage mask (bit l for lane l), each stage chosen once per group from the flush's `Ops`
//! (the `match` on the mode, function, factor or equation sits outside the loop over lanes, so
//! the compiler turns the loop into SIMD instructions), in the order of §4.1: fog, alpha test,
//! stencil test, depth test, stencil update, blend or logic op, masked write.
//!
//! Design decision: as in `lanes`, every lane computes exactly the scalar expression of
//! `fragops` and `FragCtx::full`, operation for operation and in the same order, so the images
//! are byte for byte those of one fragment at a time; the unit tests below compare each kernel
//! with the scalar code bit for bit. Fragments of one span lie on distinct pixels, so running a
//! stage over a group before the next stage gives what running each fragment through all the
//! stages gives. Lanes outside the mask are computed and thrown away.

use super::fragops::{compare, mul8, BlendEval, FogEval, StencilSide};
use super::lanes::LANES;
use crate::gl;

/// One float a lane.
pub type F = [f32; LANES];
/// One unorm8 value a lane.
pub type B = [u8; LANES];

/// `Vec4::clamp(ZERO, ONE)` on every lane, with glam's own SSE2 instructions (`maxps` with 0,
/// then `minps` with 1: a NaN gives 0, −0 gives +0); LLVM kept the equivalent selects scalar.
#[inline(always)]
pub fn clamp01(c: F) -> F {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_loadu_ps, _mm_max_ps, _mm_min_ps, _mm_set1_ps};
        // SAFETY: SSE is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from a
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128` has the
        // layout of `[f32; 4]` and every bit pattern is valid for both.
        unsafe {
            let (zero, one) = (_mm_set1_ps(0.0), _mm_set1_ps(1.0));
            let lo = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(c.as_ptr()), zero), one);
            let hi = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(c.as_ptr().add(4)), zero), one);
            let lo = std::mem::transmute::<__m128, [f32; 4]>(lo);
            let hi = std::mem::transmute::<__m128, [f32; 4]>(hi);
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let mut out = [0.0; LANES];
        for l in 0..LANES {
            let c = if c[l] > 0.0 { c[l] } else { 0.0 };
            out[l] = if c < 1.0 { c } else { 1.0 };
        }
        out
    }
}

/// `FogEval::factor` on every lane: LINEAR on lanes, EXP and EXP2 through the scalar `exp`.
#[inline(always)]
pub fn fog_factor(fog: &FogEval, coord: F) -> F {
    if fog.mode != gl::LINEAR {
        return coord.map(|c| fog.factor(c));
    }
    let scale = -1.0 / (fog.end - fog.start);
    let e = fog.end * -scale;
    let mut out = [0.0; LANES];
    for l in 0..LANES {
        let f = coord[l] * scale + e;
        // `f32::clamp(0, 1)` with a NaN counted as 0: the same selects as `FogEval::factor`.
        let f = if f.is_nan() { 0.0 } else { f };
        let f = if f < 0.0 { 0.0 } else { f };
        out[l] = if f > 1.0 { 1.0 } else { f };
    }
    out
}

/// `FogEval::apply` on every lane: `rgb` (clamped) becomes `C_f + f·(C − C_f)`; alpha is
/// left alone.
#[inline(always)]
pub fn fog(fog: &FogEval, rgb: &mut [F; 3], coord: F) {
    let f = fog_factor(fog, coord);
    let cf = fog.color.to_array();
    for k in 0..3 {
        let ch = &mut rgb[k];
        for l in 0..LANES {
            ch[l] = cf[k] + (ch[l] - cf[k]) * f[l];
        }
    }
}

/// The alpha test (§4.1.4) on every lane: bit l set when `unorm8(a[l]) func reference`.
#[inline(always)]
pub fn alpha_test(func: u32, reference: u8, a: F) -> u8 {
    let a = super::lanes::unorm8_lanes(a);
    let mut m = 0u8;
    for (l, a) in a.into_iter().enumerate() {
        m |= u8::from(compare(func, a, reference)) << l;
    }
    m
}

/// The depth test and write (§4.1.6) of lanes `live` against `row` (lane l at `row[l]`, lanes
/// past its end dropped), with DepthFunc `func` and DepthMask `write`; the survivors' mask.
#[inline(always)]
pub fn depth_test(func: u32, write: bool, row: &mut [u32], d: [u32; LANES], live: u8) -> u8 {
    #[inline(always)]
    fn run(row: &mut [u32], d: [u32; LANES], live: u8, write: bool, f: fn(u32, u32) -> bool) -> u8 {
        let mut m = 0u8;
        for (l, stored) in row.iter_mut().take(LANES).enumerate() {
            if live & (1 << l) != 0 && f(d[l], *stored) {
                if write {
                    *stored = d[l];
                }
                m |= 1 << l;
            }
        }
        m
    }
    match func {
        gl::NEVER => 0,
        gl::LESS => run(row, d, live, write, |d, s| d < s),
        gl::EQUAL => run(row, d, live, write, |d, s| d == s),
        gl::LEQUAL => run(row, d, live, write, |d, s| d <= s),
        gl::GREATER => run(row, d, live, write, |d, s| d > s),
        gl::NOTEQUAL => run(row, d, live, write, |d, s| d != s),
        gl::GEQUAL => run(row, d, live, write, |d, s| d >= s),
        _ => run(row, d, live, write, |_, _| true),
    }
}

/// The stencil test, the depth test (when `depth` is `Some((DepthFunc, DepthMask))`) and the
/// stencil update (§4.1.5, §4.1.6) of lanes `live`: lane l's stored values are `st[l]` and
/// `dp[l]` (lanes past `st`'s end are dropped; a lane past `dp`'s end fails the depth test, as
/// in `FragCtx::depth`). The stencil operation is the one for stencil fail, depth fail or depth
/// pass; the survivors' mask is returned.
#[inline(always)]
pub fn stencil_depth(
    side: &StencilSide,
    depth: Option<(u32, bool)>,
    st: &mut [u8],
    dp: &mut [u32],
    d: [u32; LANES],
    live: u8,
) -> u8 {
    let mut m = 0u8;
    for (l, s) in st.iter_mut().take(LANES).enumerate() {
        if live & (1 << l) == 0 {
            continue;
        }
        let which = if !side.test(*s) {
            0
        } else if let Some((func, write)) = depth {
            match dp.get_mut(l) {
                Some(stored) if compare(func, d[l], *stored) => {
                    if write {
                        *stored = d[l];
                    }
                    2
                }
                _ => 1,
            }
        } else {
            2
        };
        *s = side.update(which, *s);
        if which == 2 {
            m |= 1 << l;
        }
    }
    m
}

/// `fragops::factor` for component `k` on every lane (the factor chosen once).
#[inline(always)]
fn factor_lanes(f: u32, k: usize, s: &[B; 4], d: &[B; 4], c: [u8; 4]) -> B {
    let inv = |v: B| v.map(|x| 255 - x);
    let (sk, dk, ck) = (s[k & 3], d[k & 3], c[k & 3]);
    match f {
        gl::ZERO => [0; LANES],
        gl::ONE => [255; LANES],
        gl::SRC_COLOR => sk,
        gl::ONE_MINUS_SRC_COLOR => inv(sk),
        gl::DST_COLOR => dk,
        gl::ONE_MINUS_DST_COLOR => inv(dk),
        gl::SRC_ALPHA => s[3],
        gl::ONE_MINUS_SRC_ALPHA => inv(s[3]),
        gl::DST_ALPHA => d[3],
        gl::ONE_MINUS_DST_ALPHA => inv(d[3]),
        gl::CONSTANT_COLOR => [ck; LANES],
        gl::ONE_MINUS_CONSTANT_COLOR => [255 - ck; LANES],
        gl::CONSTANT_ALPHA => [c[3]; LANES],
        gl::ONE_MINUS_CONSTANT_ALPHA => [255 - c[3]; LANES],
        gl::SRC_ALPHA_SATURATE if k < 3 => std::array::from_fn(|l| s[3][l].min(255 - d[3][l])),
        _ => [255; LANES],
    }
}

/// `fragops::equation` on every lane (the equation chosen once).
#[inline(always)]
fn equation_lanes(eq: u32, s: B, d: B, sf: B, df: B) -> B {
    match eq {
        gl::FUNC_SUBTRACT => std::array::from_fn(|l| sf[l].saturating_sub(df[l])),
        gl::FUNC_REVERSE_SUBTRACT => std::array::from_fn(|l| df[l].saturating_sub(sf[l])),
        gl::MIN => std::array::from_fn(|l| s[l].min(d[l])),
        gl::MAX => std::array::from_fn(|l| s[l].max(d[l])),
        _ => std::array::from_fn(|l| sf[l].saturating_add(df[l])),
    }
}

/// `mul8` on every lane.
#[inline(always)]
fn mul8_lanes(a: B, b: B) -> B {
    std::array::from_fn(|l| mul8(a[l], b[l]))
}

/// `BlendEval::apply` on every lane: source `s` over destination `d`, channel-major.
#[inline(always)]
pub fn blend(b: &BlendEval, s: &[B; 4], d: &[B; 4]) -> [B; 4] {
    std::array::from_fn(|k| {
        let (sfac, dfac, eq) = if k < 3 {
            (b.src_rgb, b.dst_rgb, b.eq_rgb)
        } else {
            (b.src_alpha, b.dst_alpha, b.eq_alpha)
        };
        let sf = mul8_lanes(s[k], factor_lanes(sfac, k, s, d, b.constant));
        let df = mul8_lanes(d[k], factor_lanes(dfac, k, s, d, b.constant));
        equation_lanes(eq, s[k], d[k], sf, df)
    })
}

/// `fragops::logic_op` on every lane and channel (the operation chosen once).
#[inline(always)]
pub fn logic(op: u32, s: &[B; 4], d: &[B; 4]) -> [B; 4] {
    #[inline(always)]
    fn run(s: &[B; 4], d: &[B; 4], f: fn(u8, u8) -> u8) -> [B; 4] {
        std::array::from_fn(|k| std::array::from_fn(|l| f(s[k][l], d[k][l])))
    }
    match op {
        gl::CLEAR => run(s, d, |_, _| 0),
        gl::AND => run(s, d, |s, d| s & d),
        gl::AND_REVERSE => run(s, d, |s, d| s & !d),
        gl::COPY => run(s, d, |s, _| s),
        gl::AND_INVERTED => run(s, d, |s, d| !s & d),
        gl::NOOP => run(s, d, |_, d| d),
        gl::XOR => run(s, d, |s, d| s ^ d),
        gl::OR => run(s, d, |s, d| s | d),
        gl::NOR => run(s, d, |s, d| !(s | d)),
        gl::EQUIV => run(s, d, |s, d| !(s ^ d)),
        gl::INVERT => run(s, d, |_, d| !d),
        gl::OR_REVERSE => run(s, d, |s, d| s | !d),
        gl::COPY_INVERTED => run(s, d, |s, _| !s),
        gl::OR_INVERTED => run(s, d, |s, d| !s | d),
        gl::NAND => run(s, d, |s, d| !(s & d)),
        _ => run(s, d, |_, _| 255),
    }
}

/// The stored colours of lanes `0..LANES` from `row` (RGBA8, pixel-major) into channel-major
/// lanes; lanes past its end read 0.
#[inline(always)]
pub fn load(row: &[[u8; 4]]) -> [B; 4] {
    let mut out = [[0u8; LANES]; 4];
    for (l, px) in row.iter().take(LANES).enumerate() {
        for (k, ch) in out.iter_mut().enumerate() {
            ch[l] = px[k];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::fragops::{logic_op, BlendEval};
    use crate::cpu::framebuffer::unorm8;
    use crate::cpu::testgen::Gen;
    use glam::{Vec3, Vec4};

    /// Whole lanes of the generator's floats and bytes.
    trait Lanes {
        fn lanes(&mut self) -> F;
        fn bytes(&mut self) -> B;
    }
    impl Lanes for Gen {
        fn lanes(&mut self) -> F {
            std::array::from_fn(|_| self.float())
        }
        fn bytes(&mut self) -> B {
            std::array::from_fn(|_| self.byte())
        }
    }

    #[test]
    fn clamp_and_fog_are_the_scalar_expressions_bit_for_bit() {
        let mut g = Gen(3);
        for _ in 0..4000 {
            let mode = [gl::LINEAR, gl::EXP, gl::EXP2][(g.next() % 3) as usize];
            let (start, end) = match g.next() % 4 {
                0 => (1.0, 1.0),
                _ => (g.float(), g.float()),
            };
            let f = FogEval {
                mode,
                density: g.float().abs(),
                start,
                end,
                color: Vec3::new(g.float(), g.float(), g.float()),
            };
            let c: [F; 4] = std::array::from_fn(|_| g.lanes());
            let coord = g.lanes();
            let mut got = [clamp01(c[0]), clamp01(c[1]), clamp01(c[2])];
            let a = clamp01(c[3]);
            fog(&f, &mut got, coord);
            for l in 0..LANES {
                let v = Vec4::new(c[0][l], c[1][l], c[2][l], c[3][l]).clamp(Vec4::ZERO, Vec4::ONE);
                let want = f.apply(v, coord[l]);
                let got = Vec4::new(got[0][l], got[1][l], got[2][l], a[l]);
                assert_eq!(
                    got.to_array().map(f32::to_bits),
                    want.to_array().map(f32::to_bits),
                    "{f:?} c {v} coord {}",
                    coord[l]
                );
            }
        }
    }

    #[test]
    fn alpha_test_is_the_scalar_comparison() {
        let mut g = Gen(9);
        let funcs = [
            gl::NEVER,
            gl::LESS,
            gl::EQUAL,
            gl::LEQUAL,
            gl::GREATER,
            gl::NOTEQUAL,
            gl::GEQUAL,
            gl::ALWAYS,
        ];
        for _ in 0..2000 {
            let func = funcs[(g.next() % 8) as usize];
            let r = g.byte();
            let a = g.lanes();
            let m = alpha_test(func, r, a);
            for (l, a) in a.into_iter().enumerate() {
                assert_eq!(
                    m & (1 << l) != 0,
                    compare(func, unorm8(a), r),
                    "{func} {r} {a}"
                );
            }
        }
    }

    #[test]
    fn depth_and_stencil_are_the_scalar_sequence() {
        let mut g = Gen(13);
        let funcs = [
            gl::NEVER,
            gl::LESS,
            gl::EQUAL,
            gl::LEQUAL,
            gl::GREATER,
            gl::NOTEQUAL,
            gl::GEQUAL,
            gl::ALWAYS,
        ];
        let ops = [
            gl::KEEP,
            gl::ZERO,
            gl::REPLACE,
            gl::INCR,
            gl::DECR,
            gl::INVERT,
            gl::INCR_WRAP,
            gl::DECR_WRAP,
        ];
        for _ in 0..4000 {
            let side = StencilSide {
                func: funcs[(g.next() % 8) as usize],
                reference: g.byte(),
                mask: g.byte(),
                ops: std::array::from_fn(|_| ops[(g.next() % 8) as usize]),
                write: g.byte(),
            };
            let dfunc = funcs[(g.next() % 8) as usize];
            let write = g.next() % 2 == 0;
            let depth = (g.next() % 4 != 0).then_some((dfunc, write));
            let n = (g.next() % 9) as usize;
            // Few distinct depths so that EQUAL passes now and then.
            let dv = |g: &mut Gen| (g.next() % 4) as u32 * 1000;
            let d: [u32; LANES] = std::array::from_fn(|_| dv(&mut g));
            let st0: Vec<u8> = (0..n).map(|_| g.byte()).collect();
            // Now and then a shorter depth row: its missing lanes fail the depth test.
            let nd = if g.next() % 8 == 0 { n / 2 } else { n };
            let dp0: Vec<u32> = (0..nd).map(|_| dv(&mut g)).collect();
            let live = g.next() as u8;
            let (mut st, mut dp) = (st0.clone(), dp0.clone());
            let m = stencil_depth(&side, depth, &mut st, &mut dp, d, live);
            let (mut wst, mut wdp, mut wm) = (st0.clone(), dp0.clone(), 0u8);
            for l in 0..n {
                if live & (1 << l) == 0 {
                    continue;
                }
                let s = wst[l];
                let which = if !side.test(s) {
                    0
                } else {
                    match depth {
                        Some((f, w)) if l < nd && compare(f, d[l], wdp[l]) => {
                            if w {
                                wdp[l] = d[l];
                            }
                            2
                        }
                        Some(_) => 1,
                        None => 2,
                    }
                };
                wst[l] = side.update(which, s);
                wm |= u8::from(which == 2) << l;
            }
            assert_eq!((m, &st, &dp), (wm, &wst, &wdp), "{side:?} {depth:?}");
            // Depth alone.
            let mut dp = dp0.clone();
            let m = depth_test(dfunc, write, &mut dp, d, live);
            let (mut wdp, mut wm) = (dp0.clone(), 0u8);
            for l in 0..nd {
                if live & (1 << l) != 0 && compare(dfunc, d[l], wdp[l]) {
                    if write {
                        wdp[l] = d[l];
                    }
                    wm |= 1 << l;
                }
            }
            assert_eq!((m, &dp), (wm, &wdp), "{dfunc} {write}");
        }
    }

    #[test]
    fn blend_and_logic_op_are_the_scalar_arithmetic() {
        let factors = [
            gl::ZERO,
            gl::ONE,
            gl::SRC_COLOR,
            gl::ONE_MINUS_SRC_COLOR,
            gl::DST_COLOR,
            gl::ONE_MINUS_DST_COLOR,
            gl::SRC_ALPHA,
            gl::ONE_MINUS_SRC_ALPHA,
            gl::DST_ALPHA,
            gl::ONE_MINUS_DST_ALPHA,
            gl::CONSTANT_COLOR,
            gl::ONE_MINUS_CONSTANT_COLOR,
            gl::CONSTANT_ALPHA,
            gl::ONE_MINUS_CONSTANT_ALPHA,
            gl::SRC_ALPHA_SATURATE,
        ];
        let eqs = [
            gl::FUNC_ADD,
            gl::FUNC_SUBTRACT,
            gl::FUNC_REVERSE_SUBTRACT,
            gl::MIN,
            gl::MAX,
        ];
        let mut g = Gen(17);
        for _ in 0..6000 {
            let pick = |g: &mut Gen| factors[(g.next() % factors.len() as u64) as usize];
            let b = BlendEval {
                src_rgb: pick(&mut g),
                dst_rgb: pick(&mut g),
                src_alpha: pick(&mut g),
                dst_alpha: pick(&mut g),
                eq_rgb: eqs[(g.next() % 5) as usize],
                eq_alpha: eqs[(g.next() % 5) as usize],
                constant: std::array::from_fn(|_| g.byte()),
            };
            let s: [B; 4] = std::array::from_fn(|_| g.bytes());
            let d: [B; 4] = std::array::from_fn(|_| g.bytes());
            let got = blend(&b, &s, &d);
            let op = gl::CLEAR + (g.next() % 16) as u32;
            let lo = logic(op, &s, &d);
            for l in 0..LANES {
                let (sp, dp) = (s.map(|c| c[l]), d.map(|c| c[l]));
                let want = b.apply(sp, dp);
                assert_eq!(got.map(|c| c[l]), want, "{b:?} s {sp:?} d {dp:?}");
                let want: [u8; 4] = std::array::from_fn(|k| logic_op(op, sp[k], dp[k]));
                assert_eq!(lo.map(|c| c[l]), want, "logic {op:#x}");
            }
        }
    }

    #[test]
    fn load_reads_channel_major_and_zero_past_the_end() {
        let row: Vec<[u8; 4]> = (0..5u8).map(|i| [i, i + 10, i + 20, i + 30]).collect();
        let got = load(&row);
        assert_eq!(got[1], [10, 11, 12, 13, 14, 0, 0, 0]);
        assert_eq!(got[3][4], 34);
    }
}
