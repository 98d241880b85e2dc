//! The per-fragment operations of `fragops` (fog §3.10, alpha test §4.1.4, stencil §4.1.5,
//! depth §4.1.6, blending §4.1.8, logic op §4.1.10) on groups of `LANES` fragments of a span,
//! for `FragCtx::ops_rows`: a span runs stage by stage over eight fragments at a time with a
//! coverage mask (bit l for lane l), each stage chosen once per group from the flush's `Ops`
//! (the `match` on the mode, function, factor or equation sits outside the loop over lanes, so
//! the compiler turns the loop into SIMD instructions), in the order of §4.1: alpha test,
//! stencil test, depth test, stencil update, fog, blend or logic op, masked write. Fog (§3.10)
//! comes before the alpha test in the spec, but it changes only R, G and B, which no test
//! reads, so it runs after the tests on the surviving lanes alone (the same bytes; EXP and EXP2
//! call `expf` only for fragments that are written). Blending works on 16-bit lanes (eight
//! in one SSE2 register), the usual SRC_ALPHA/ONE_MINUS_SRC_ALPHA and ONE/ONE states by a
//! direct route; the RGBA8 loads and the masked store take a whole group at once.
//!
//! Design decision: as in `lanes`, every lane computes exactly the scalar expression of
//! `fragops` and `FragCtx::full`, operation for operation and in the same order, so the images
//! are byte for byte those of one fragment at a time; the unit tests below compare each kernel
//! with the scalar code bit for bit. Fragments of one span lie on distinct pixels, so running a
//! stage over a group before the next stage gives what running each fragment through all the
//! stages gives. Lanes outside the mask are computed and thrown away.

use super::fragops::{compare, BlendEval, FogEval, StencilSide};
use super::lanes::LANES;
use super::libm8::expf;
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

/// `FogEval::factor` on every lane of `live`: LINEAR on lanes; EXP and EXP2 with their
/// arguments (−density·c, −(density·c)², the scalar products in the scalar order) on lanes,
/// the scalar `exp` for the lanes of `live` only (`exp_live`; the others are thrown away),
/// then the clamp on lanes.
#[inline(always)]
pub fn fog_factor(fog: &FogEval, coord: F, live: u8) -> F {
    let mut out = [0.0; LANES];
    let f = if fog.mode != gl::LINEAR {
        let mut arg = [0.0; LANES];
        if fog.mode == gl::EXP {
            let nd = -fog.density;
            for l in 0..LANES {
                arg[l] = nd * coord[l];
            }
        } else {
            for l in 0..LANES {
                let dc = fog.density * coord[l];
                arg[l] = -dc * dc;
            }
        }
        exp_live(&arg, live)
    } else {
        let scale = -1.0 / (fog.end - fog.start);
        let e = fog.end * -scale;
        let mut f = [0.0; LANES];
        for l in 0..LANES {
            f[l] = coord[l] * scale + e;
        }
        f
    };
    for l in 0..LANES {
        // `f32::clamp(0, 1)` with a NaN counted as 0: the same selects as `FogEval::factor`.
        let f = if f[l].is_nan() { 0.0 } else { f[l] };
        let f = if f < 0.0 { 0.0 } else { f };
        out[l] = if f > 1.0 { 1.0 } else { f };
    }
    out
}

/// `exp` of the lanes of `live` (the others unspecified): `f32::exp`'s bits. Where libm's
/// `expf` is glibc's FMA variant (`libm8::expf::expf8`'s self-check, once) the lanes in its main range
/// come from `libm8::expf::expf8` eight at a time, the others from libm; elsewhere one libm call a
/// lane. A function of its own, so that only this loop waits on the calls (inlined into the
/// group loop, every call made the caller spill and reload a dozen vector registers, ≈25
/// instructions a call).
#[inline(never)]
fn exp_live(arg: &F, live: u8) -> F {
    let mut out = [0.0; LANES];
    let mut m = live;
    #[cfg(target_arch = "x86_64")]
    if expf::usable() {
        // SAFETY: `usable` is true only where the CPU has AVX2 and FMA.
        m &= unsafe { expf::expf8(arg, &mut out) };
    }
    while m != 0 {
        let l = m.trailing_zeros() as usize;
        m &= m - 1;
        if let (Some(o), Some(a)) = (out.get_mut(l), arg.get(l)) {
            *o = a.exp();
        }
    }
    out
}

/// `FogEval::apply` on the lanes of `live`: `rgb` (clamped) becomes `C_f + f·(C − C_f)`; alpha
/// is left alone. Lanes outside `live` hold unspecified values afterwards.
#[inline(always)]
pub fn fog(fog: &FogEval, rgb: &mut [F; 3], coord: F, live: u8) {
    let f = fog_factor(fog, coord, live);
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
    #[cfg(target_arch = "x86_64")]
    if let Some(r) = row.get_mut(..LANES) {
        return depth_group(func, write, r, d, live);
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

/// `depth_test` on a whole group (`row` holds eight values) with SSE2: the unsigned
/// comparison as a signed one of both sides with the top bit flipped (`pcmpgtd`/`pcmpeqd`),
/// the lanes' pass mask by `movmskps`, the write as a select. The same mask and stores as
/// the per-lane loop.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn depth_group(func: u32, write: bool, row: &mut [u32], d: [u32; LANES], live: u8) -> u8 {
    use std::arch::x86_64::{
        __m128i, _mm_and_si128, _mm_andnot_si128, _mm_castsi128_ps, _mm_cmpeq_epi32,
        _mm_cmpgt_epi32, _mm_loadu_si128, _mm_movemask_ps, _mm_or_si128, _mm_set1_epi32,
        _mm_set_epi32, _mm_setzero_si128, _mm_storeu_si128, _mm_xor_si128,
    };
    if row.len() < LANES {
        return 0;
    }
    // SAFETY: SSE2 is part of the x86-64 baseline; `row` holds at least eight u32 (checked
    // above) and `d` eight, so the unaligned 16-byte loads and stores at offsets 0 and 4 are
    // in bounds; `__m128i` has the layout of `[u32; 4]`.
    unsafe {
        let sign = _mm_set1_epi32(i32::MIN);
        let ones = _mm_set1_epi32(-1);
        let base = row.as_mut_ptr();
        let half = |k: usize| {
            let rp = base.add(k).cast::<__m128i>();
            let s = _mm_loadu_si128(rp);
            let dv = _mm_loadu_si128(d.as_ptr().add(k).cast::<__m128i>());
            let (a, b) = (_mm_xor_si128(dv, sign), _mm_xor_si128(s, sign));
            let pass = match func {
                gl::NEVER => _mm_setzero_si128(),
                gl::LESS => _mm_cmpgt_epi32(b, a),
                gl::EQUAL => _mm_cmpeq_epi32(a, b),
                gl::LEQUAL => _mm_xor_si128(_mm_cmpgt_epi32(a, b), ones),
                gl::GREATER => _mm_cmpgt_epi32(a, b),
                gl::NOTEQUAL => _mm_xor_si128(_mm_cmpeq_epi32(a, b), ones),
                gl::GEQUAL => _mm_xor_si128(_mm_cmpgt_epi32(b, a), ones),
                _ => ones,
            };
            let bits = _mm_set_epi32(8, 4, 2, 1);
            let lv = _mm_set1_epi32(i32::from(live >> k));
            let on = _mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits);
            let pass = _mm_and_si128(pass, on);
            if write {
                let v = _mm_or_si128(_mm_and_si128(pass, dv), _mm_andnot_si128(pass, s));
                _mm_storeu_si128(rp, v);
            }
            _mm_movemask_ps(_mm_castsi128_ps(pass)) as u8
        };
        half(0) | half(4) << 4
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
    #[cfg(target_arch = "x86_64")]
    if let (Some(st), Some(dp)) = (st.get_mut(..LANES), dp.get_mut(..LANES)) {
        return stencil_group(side, depth, st, dp, GroupZ::Lanes(d), live);
    }
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

/// The depths of a group for `stencil_group`: eight values, or (AVX2 only) the plane they come
/// from, `depth_lanes(lin_lanes(zrow, dz, &lane_x(fx0)))`, computed with the depth test by
/// `avx2::depth_test` (the same values and stores, eight lanes a register).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
enum GroupZ {
    Lanes([u32; LANES]),
    /// Made only where the CPU has AVX2 (`avx2::stencil_depth`).
    Plane {
        zrow: f32,
        dz: f32,
        fx0: i32,
    },
}

/// `stencil_depth` on a whole group (`st` and `dp` hold eight values each) with SSE2: the
/// stencil comparison of `(ref & mask)` with `(s & mask)` as unsigned byte compares (`pminub`,
/// `pcmpeqb`; the function chosen once), the depth test of the stencil survivors by
/// `depth_group`, then each of the three stencil operations (the operation chosen once; KEEP
/// and an empty class skipped) computed on all eight bytes from the stored values and selected
/// into its class's lanes through the write mask. The same stores and mask as the per-lane
/// loop: each lane falls in exactly one class, and `StencilSide::update` reads the stored
/// value from before the test.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn stencil_group(
    side: &StencilSide,
    depth: Option<(u32, bool)>,
    st: &mut [u8],
    dp: &mut [u32],
    z: GroupZ,
    live: u8,
) -> u8 {
    use std::arch::x86_64::{
        __m128i, _mm_add_epi8, _mm_adds_epu8, _mm_and_si128, _mm_andnot_si128, _mm_cmpeq_epi8,
        _mm_loadl_epi64, _mm_min_epu8, _mm_movemask_epi8, _mm_or_si128, _mm_set1_epi8,
        _mm_set_epi8, _mm_setzero_si128, _mm_storel_epi64, _mm_sub_epi8, _mm_subs_epu8,
        _mm_xor_si128,
    };
    if st.len() < LANES || dp.len() < LANES {
        return 0;
    }
    // SAFETY: SSE2 is part of the x86-64 baseline; `st` holds at least eight bytes (checked
    // above), so the 8-byte load and store at its start are in bounds (no alignment needed);
    // `__m128i` is plain bits; `avx2::depth_test` runs only for a `GroupZ::Plane`, made only
    // where the CPU has AVX2.
    unsafe {
        let p = st.as_mut_ptr().cast::<__m128i>();
        let s = _mm_loadl_epi64(p);
        let ones = _mm_set1_epi8(-1);
        // Lane l's byte all ones when bit l of `bits` is set.
        let lanes = |bits: u8| {
            let sel = _mm_set_epi8(0, 0, 0, 0, 0, 0, 0, 0, -128, 64, 32, 16, 8, 4, 2, 1);
            let b = _mm_and_si128(_mm_set1_epi8(bits as i8), sel);
            _mm_cmpeq_epi8(b, sel)
        };
        let live_v = lanes(live);
        let a = _mm_set1_epi8((side.reference & side.mask) as i8);
        let b = _mm_and_si128(s, _mm_set1_epi8(side.mask as i8));
        // Unsigned a <= b as min(a, b) == a.
        let le = |x: __m128i, y: __m128i| _mm_cmpeq_epi8(_mm_min_epu8(x, y), x);
        let pass = match side.func {
            gl::NEVER => _mm_setzero_si128(),
            gl::LESS => _mm_xor_si128(le(b, a), ones),
            gl::EQUAL => _mm_cmpeq_epi8(a, b),
            gl::LEQUAL => le(a, b),
            gl::GREATER => _mm_xor_si128(le(a, b), ones),
            gl::NOTEQUAL => _mm_xor_si128(_mm_cmpeq_epi8(a, b), ones),
            gl::GEQUAL => le(b, a),
            _ => ones,
        };
        let spass = _mm_and_si128(pass, live_v);
        let sbits = (_mm_movemask_epi8(spass) & 0xFF) as u8;
        let zbits = match (depth, z) {
            (Some((func, write)), GroupZ::Lanes(d)) if sbits != 0 => {
                depth_group(func, write, dp, d, sbits)
            }
            (Some((func, write)), GroupZ::Plane { zrow, dz, fx0 }) if sbits != 0 => {
                avx2::depth_test(func, write, dp, zrow, dz, fx0, sbits)
            }
            (Some(_), _) => 0,
            (None, _) => sbits,
        };
        let zpass = lanes(zbits);
        let classes = [
            _mm_andnot_si128(spass, live_v),
            _mm_andnot_si128(zpass, spass),
            zpass,
        ];
        let wr = _mm_set1_epi8(side.write as i8);
        let reference = _mm_set1_epi8(side.reference as i8);
        let one = _mm_set1_epi8(1);
        let mut out = s;
        let mut changed = false;
        for (class, &op) in classes.iter().zip(&side.ops) {
            if op == gl::KEEP || _mm_movemask_epi8(*class) & 0xFF == 0 {
                continue;
            }
            let v = match op {
                gl::ZERO => _mm_setzero_si128(),
                gl::REPLACE => reference,
                gl::INCR => _mm_adds_epu8(s, one),
                gl::DECR => _mm_subs_epu8(s, one),
                gl::INVERT => _mm_xor_si128(s, ones),
                gl::INCR_WRAP => _mm_add_epi8(s, one),
                gl::DECR_WRAP => _mm_sub_epi8(s, one),
                _ => s,
            };
            let sel = _mm_and_si128(*class, wr);
            out = _mm_or_si128(_mm_andnot_si128(sel, out), _mm_and_si128(sel, v));
            changed = true;
        }
        if changed {
            _mm_storel_epi64(p, out);
        }
        zbits
    }
}

/// One unorm8 value a lane, widened to 16 bits: the blend arithmetic's lanes (a product of
/// two unorm8 values and `mul8`'s rounding terms fit in 16 bits, so eight lanes take one SSE2
/// register and the loops below become `pmullw`/`psrlw`/`paddw`).
type W = [u16; LANES];

/// `v` widened to 16-bit lanes (SSE2 `punpcklbw` with zero on x86-64).
#[inline(always)]
fn widen(v: B) -> W {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128i, _mm_loadl_epi64, _mm_setzero_si128, _mm_unpacklo_epi8};
        // SAFETY: SSE2 is part of the x86-64 baseline; the 8-byte load reads exactly `v`
        // (no alignment needed); `__m128i` has the layout of `[u16; 8]` and every bit
        // pattern is valid for both.
        unsafe {
            let x = _mm_loadl_epi64(v.as_ptr().cast::<__m128i>());
            std::mem::transmute::<__m128i, W>(_mm_unpacklo_epi8(x, _mm_setzero_si128()))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        v.map(u16::from)
    }
}

/// `v` (every lane in 0..=255) narrowed to bytes (SSE2 `packuswb` on x86-64).
#[inline(always)]
fn narrow(v: W) -> B {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128i, _mm_packus_epi16};
        // SAFETY: SSE2 is part of the x86-64 baseline; `__m128i` has the layout of
        // `[u16; 8]` and of `[u8; 16]`, and every bit pattern is valid for all three.
        unsafe {
            let x = std::mem::transmute::<W, __m128i>(v);
            super::lanes::low8(_mm_packus_epi16(x, x))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        v.map(|x| x as u8)
    }
}

/// `255 − v` on every lane.
#[inline(always)]
fn inv(v: W) -> W {
    let mut o = [0u16; LANES];
    for l in 0..LANES {
        o[l] = 255 - v[l];
    }
    o
}

/// `fragops::factor` for component `k` on every lane (the factor chosen once).
#[inline(always)]
fn factor_lanes(f: u32, k: usize, s: &[W; 4], d: &[W; 4], c: [u8; 4]) -> W {
    let (sk, dk, ck) = (s[k & 3], d[k & 3], u16::from(c[k & 3]));
    let ca = u16::from(c[3]);
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
        gl::CONSTANT_ALPHA => [ca; LANES],
        gl::ONE_MINUS_CONSTANT_ALPHA => [255 - ca; LANES],
        gl::SRC_ALPHA_SATURATE if k < 3 => {
            let (sa, ida) = (s[3], inv(d[3]));
            let mut o = [0u16; LANES];
            for l in 0..LANES {
                o[l] = sa[l].min(ida[l]);
            }
            o
        }
        _ => [255; LANES],
    }
}

/// `fragops::equation` on every lane (the equation chosen once); every value is in 0..=255,
/// so the 16-bit forms give the unorm8 results (the sum saturates at 255 by `min`).
#[inline(always)]
fn equation_lanes(eq: u32, s: W, d: W, sf: W, df: W) -> W {
    let mut o = [0u16; LANES];
    match eq {
        gl::FUNC_SUBTRACT => {
            for l in 0..LANES {
                o[l] = sf[l].saturating_sub(df[l]);
            }
        }
        gl::FUNC_REVERSE_SUBTRACT => {
            for l in 0..LANES {
                o[l] = df[l].saturating_sub(sf[l]);
            }
        }
        gl::MIN => {
            for l in 0..LANES {
                o[l] = s[l].min(d[l]);
            }
        }
        gl::MAX => {
            for l in 0..LANES {
                o[l] = s[l].max(d[l]);
            }
        }
        _ => {
            for l in 0..LANES {
                o[l] = (sf[l] + df[l]).min(255);
            }
        }
    }
    o
}

/// `mul8` on every lane, in 16 bits: `x = ab` ≤ 65025 and `x + (x >> 8) + 128` ≤ 65407, so
/// nothing wraps and the result is `mul8`'s.
#[inline(always)]
fn mul8_lanes(a: W, b: W) -> W {
    let mut o = [0u16; LANES];
    for l in 0..LANES {
        let x = a[l] * b[l];
        o[l] = (x + (x >> 8) + 128) >> 8;
    }
    o
}

/// `BlendEval::apply` on every lane: source `s` over destination `d`, channel-major. The
/// usual states take a direct route (the factors and equations checked once per group):
/// SRC_ALPHA, ONE_MINUS_SRC_ALPHA with FUNC_ADD for RGB and alpha, and ONE, ONE with FUNC_ADD
/// (`mul8(x, 255)` is `x`, so the sum alone, saturating).
#[inline(always)]
pub fn blend(b: &BlendEval, s: &[B; 4], d: &[B; 4]) -> [B; 4] {
    let mut out = [[0u8; LANES]; 4];
    let usual = b.eq_rgb == gl::FUNC_ADD
        && b.eq_alpha == gl::FUNC_ADD
        && b.src_rgb == b.src_alpha
        && b.dst_rgb == b.dst_alpha;
    if usual && b.src_rgb == gl::ONE && b.dst_rgb == gl::ONE {
        for k in 0..4 {
            for l in 0..LANES {
                out[k][l] = s[k][l].saturating_add(d[k][l]);
            }
        }
        return out;
    }
    let s = [widen(s[0]), widen(s[1]), widen(s[2]), widen(s[3])];
    let d = [widen(d[0]), widen(d[1]), widen(d[2]), widen(d[3])];
    if usual && b.src_rgb == gl::SRC_ALPHA && b.dst_rgb == gl::ONE_MINUS_SRC_ALPHA {
        let (fs, fd) = (s[3], inv(s[3]));
        for (k, o) in out.iter_mut().enumerate() {
            let (sf, df) = (mul8_lanes(s[k], fs), mul8_lanes(d[k], fd));
            let mut v = [0u16; LANES];
            for l in 0..LANES {
                v[l] = (sf[l] + df[l]).min(255);
            }
            *o = narrow(v);
        }
        return out;
    }
    for (k, o) in out.iter_mut().enumerate() {
        let (sfac, dfac, eq) = if k < 3 {
            (b.src_rgb, b.dst_rgb, b.eq_rgb)
        } else {
            (b.src_alpha, b.dst_alpha, b.eq_alpha)
        };
        let sf = mul8_lanes(s[k], factor_lanes(sfac, k, &s, &d, b.constant));
        let df = mul8_lanes(d[k], factor_lanes(dfac, k, &s, &d, b.constant));
        *o = narrow(equation_lanes(eq, s[k], d[k], sf, df));
    }
    out
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
/// lanes; lanes past its end read 0. A whole group (eight pixels in `row`) is two 16-byte
/// loads, a shift and mask per channel and two packs (SSE2).
#[inline(always)]
pub fn load(row: &[[u8; 4]]) -> [B; 4] {
    let mut out = [[0u8; LANES]; 4];
    #[cfg(target_arch = "x86_64")]
    if let Some(px) = row.get(..LANES) {
        use std::arch::x86_64::{
            __m128i, _mm_and_si128, _mm_loadu_si128, _mm_packs_epi32, _mm_packus_epi16,
            _mm_set1_epi32, _mm_srli_epi32,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; `px` holds eight `[u8; 4]`, 32
        // contiguous bytes, and `_mm_loadu_si128` reads 16 bytes at offsets 0 and 16 (in
        // bounds, no alignment needed); `__m128i` has the layout of `[u8; 16]`.
        unsafe {
            let p = px.as_ptr().cast::<__m128i>();
            let (lo, hi) = (_mm_loadu_si128(p), _mm_loadu_si128(p.add(1)));
            let low = _mm_set1_epi32(0xFF);
            let ch = |lo: __m128i, hi: __m128i| {
                let w = _mm_packs_epi32(_mm_and_si128(lo, low), _mm_and_si128(hi, low));
                super::lanes::low8(_mm_packus_epi16(w, w))
            };
            out[0] = ch(lo, hi);
            out[1] = ch(_mm_srli_epi32(lo, 8), _mm_srli_epi32(hi, 8));
            out[2] = ch(_mm_srli_epi32(lo, 16), _mm_srli_epi32(hi, 16));
            out[3] = ch(_mm_srli_epi32(lo, 24), _mm_srli_epi32(hi, 24));
        }
        return out;
    }
    for (l, px) in row.iter().take(LANES).enumerate() {
        for (k, ch) in out.iter_mut().enumerate() {
            ch[l] = px[k];
        }
    }
    out
}

/// Writes lanes `m` of `c` (channel-major) over `row[0..LANES]` through ColorMask `mask`
/// (§4.2.2): the masked channels of a written pixel and every channel of an unwritten one
/// keep their stored bytes. A whole group is selected and stored at once (the unwritten pixels
/// are stored back unchanged; the tile belongs to this thread alone).
#[inline(always)]
pub fn store(row: &mut [[u8; 4]], c: &[B; 4], m: u8, mask: [bool; 4]) {
    let cm = u32::from_le_bytes(mask.map(|on| if on { 0xFF } else { 0 }));
    let Some(px) = row.get_mut(..LANES) else {
        for (l, dst) in row.iter_mut().take(LANES).enumerate() {
            if m & (1 << l) != 0 {
                for (k, d) in dst.iter_mut().enumerate() {
                    if mask[k] {
                        *d = c[k][l];
                    }
                }
            }
        }
        return;
    };
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128i, _mm_and_si128, _mm_andnot_si128, _mm_cmpeq_epi32, _mm_loadl_epi64,
            _mm_loadu_si128, _mm_or_si128, _mm_set1_epi32, _mm_set_epi32, _mm_storeu_si128,
            _mm_unpackhi_epi16, _mm_unpacklo_epi16, _mm_unpacklo_epi8,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; each `_mm_loadl_epi64` reads exactly
        // one `[u8; 8]` of `c`; `px` holds eight `[u8; 4]`, 32 contiguous bytes, read and
        // written 16 bytes at offsets 0 and 16 (in bounds, no alignment needed).
        unsafe {
            let ch = |k: usize| _mm_loadl_epi64(c[k].as_ptr().cast::<__m128i>());
            // r0 g0 r1 g1 ... and b0 a0 b1 a1 ..., then RGBA of pixels 0-3 and 4-7.
            let (rg, ba) = (
                _mm_unpacklo_epi8(ch(0), ch(1)),
                _mm_unpacklo_epi8(ch(2), ch(3)),
            );
            let halves = [_mm_unpacklo_epi16(rg, ba), _mm_unpackhi_epi16(rg, ba)];
            let bits = _mm_set_epi32(8, 4, 2, 1);
            let cmv = _mm_set1_epi32(cm as i32);
            let p = px.as_mut_ptr().cast::<__m128i>();
            for (h, v) in halves.into_iter().enumerate() {
                let lv = _mm_set1_epi32(i32::from(m >> (4 * h)));
                let sel = _mm_and_si128(_mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits), cmv);
                let old = _mm_loadu_si128(p.add(h));
                let out = _mm_or_si128(_mm_andnot_si128(sel, old), _mm_and_si128(sel, v));
                _mm_storeu_si128(p.add(h), out);
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    for (l, dst) in px.iter_mut().enumerate() {
        let v = u32::from(c[0][l])
            | u32::from(c[1][l]) << 8
            | u32::from(c[2][l]) << 16
            | u32::from(c[3][l]) << 24;
        let sel = 0u32.wrapping_sub(u32::from((m >> l) & 1)) & cm;
        let old = u32::from_le_bytes(*dst);
        *dst = ((old & !sel) | (v & sel)).to_le_bytes();
    }
}

/// Pixels `4h..4h + 4` (`h` 0 or 1) of a group as four RGBA8 words, red in the low byte: each
/// channel through `unorm8`'s arithmetic (clamped to [0, 1], times 255/256 plus 32768, the low
/// byte of the sum's bits), four lanes at a time.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn pack4(rgb: &[F; 3], a: &F, h: usize) -> std::arch::x86_64::__m128i {
    use std::arch::x86_64::{
        _mm_add_ps, _mm_and_si128, _mm_castps_si128, _mm_loadu_ps, _mm_max_ps, _mm_min_ps,
        _mm_mul_ps, _mm_or_si128, _mm_set1_epi32, _mm_set1_ps, _mm_setzero_ps, _mm_slli_epi32,
    };
    let o = 4 * (h & 1);
    // SAFETY: SSE2 is part of the x86-64 baseline; each load reads four f32 of a `[f32; 8]`
    // at offset 0 or 4 (in bounds, no alignment needed).
    unsafe {
        let (zero, one) = (_mm_setzero_ps(), _mm_set1_ps(1.0));
        let (k, b) = (_mm_set1_ps(255.0 / 256.0), _mm_set1_ps(32768.0));
        let low = _mm_set1_epi32(0xFF);
        let conv = |p: *const f32| {
            let c = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(p), zero), one);
            _mm_and_si128(_mm_castps_si128(_mm_add_ps(_mm_mul_ps(c, k), b)), low)
        };
        _mm_or_si128(
            _mm_or_si128(
                conv(rgb[0].as_ptr().add(o)),
                _mm_slli_epi32::<8>(conv(rgb[1].as_ptr().add(o))),
            ),
            _mm_or_si128(
                _mm_slli_epi32::<16>(conv(rgb[2].as_ptr().add(o))),
                _mm_slli_epi32::<24>(conv(a.as_ptr().add(o))),
            ),
        )
    }
}

/// `store` of the unorm8 conversion (`lanes::unorm8_lanes`) of `rgb` and `a`, without the
/// channel-major bytes between: on x86-64 each lane's converted values (0..=255 in the low
/// byte of its 32-bit lane, `unorm8_lanes`'s `maxps`, `minps`, `mulps`, `addps` and mask) are
/// assembled as `r | g << 8 | b << 16 | a << 24`, the lane's pixel (`[u8; 4]` in memory
/// order), and the group selected and stored as `store` does. The same bytes as `store` of
/// the four `unorm8_lanes`.
#[inline(always)]
pub fn store_unorm8(row: &mut [[u8; 4]], rgb: &[F; 3], a: &F, m: u8, mask: [bool; 4]) {
    #[cfg(target_arch = "x86_64")]
    if let Some(px) = row.get_mut(..LANES) {
        use std::arch::x86_64::__m128i;
        use std::arch::x86_64::{
            _mm_and_si128, _mm_andnot_si128, _mm_cmpeq_epi32, _mm_loadu_si128, _mm_or_si128,
            _mm_set1_epi32, _mm_set_epi32, _mm_storeu_si128,
        };
        let cm = u32::from_le_bytes(mask.map(|on| if on { 0xFF } else { 0 }));
        // SAFETY: SSE2 is part of the x86-64 baseline; `px` holds eight `[u8; 4]`, 32
        // contiguous bytes, read and written 16 bytes at offsets 0 and 16 (in bounds, no
        // alignment needed).
        unsafe {
            let bits = _mm_set_epi32(8, 4, 2, 1);
            let cmv = _mm_set1_epi32(cm as i32);
            let p = px.as_mut_ptr().cast::<__m128i>();
            for h in 0..2 {
                let o = 4 * h;
                let v = pack4(rgb, a, h);
                let lv = _mm_set1_epi32(i32::from(m >> o));
                let sel = _mm_and_si128(_mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits), cmv);
                let old = _mm_loadu_si128(p.add(h));
                let out = _mm_or_si128(_mm_andnot_si128(sel, old), _mm_and_si128(sel, v));
                _mm_storeu_si128(p.add(h), out);
            }
        }
        return;
    }
    use super::lanes::unorm8_lanes;
    let src = [
        unorm8_lanes(rgb[0]),
        unorm8_lanes(rgb[1]),
        unorm8_lanes(rgb[2]),
        unorm8_lanes(*a),
    ];
    store(row, &src, m, mask);
}

/// The usual blends of `blend` (FUNC_ADD for RGB and alpha with SRC_ALPHA,
/// ONE_MINUS_SRC_ALPHA, ONE, ONE, SRC_ALPHA, ONE or CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA for
/// both) of the unorm8 conversion of `rgb` and `a` over a
/// whole group of `row` (eight pixels), stored as `store` stores; false (nothing written) for
/// another state, a shorter row or another architecture. On x86-64 every step stays
/// pixel-major (no channel-major bytes between): the source pixels are assembled as in
/// `store_unorm8`; ONE, ONE is the saturating byte sum (`paddusb`); SRC_ALPHA,
/// ONE_MINUS_SRC_ALPHA widens both sides to 16 bits (two pixels a register), broadcasts each
/// source pixel's alpha over its four channels (`pshuflw`/`pshufhw`), takes `mul8_lanes`'s
/// products and rounding (`pmullw`, `psrlw`, `paddw`) and their sum (at most 510), which the
/// unsigned saturating pack (`packuswb`) limits to 255 as `min(255)` does; SRC_ALPHA, ONE
/// packs the source's `mul8` products (each at most 255) and adds the destination with
/// `paddusb` (`mul8(d, 255)` is d). The same bytes as
/// `store` of `blend` of the four `unorm8_lanes` over `load`.
#[inline(always)]
pub fn blend_unorm8(
    b: &BlendEval,
    row: &mut [[u8; 4]],
    rgb: &[F; 3],
    a: &F,
    m: u8,
    mask: [bool; 4],
) -> bool {
    let usual = b.eq_rgb == gl::FUNC_ADD
        && b.eq_alpha == gl::FUNC_ADD
        && b.src_rgb == b.src_alpha
        && b.dst_rgb == b.dst_alpha;
    let add = usual && b.src_rgb == gl::ONE && b.dst_rgb == gl::ONE;
    let over = usual && b.src_rgb == gl::SRC_ALPHA && b.dst_rgb == gl::ONE_MINUS_SRC_ALPHA;
    // SRC_ALPHA, ONE (additive glow, point sprites): mul8(s, αs) + mul8(d, 255), and
    // mul8(d, 255) is d, so the sum saturating in bytes.
    let glow = usual && b.src_rgb == gl::SRC_ALPHA && b.dst_rgb == gl::ONE;
    // CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA (a panel weighted by the constant alpha):
    // mul8(s, αc) + mul8(d, 255 − αc), as `over` with the constant for the source alpha.
    let konst =
        usual && b.src_rgb == gl::CONSTANT_ALPHA && b.dst_rgb == gl::ONE_MINUS_CONSTANT_ALPHA;
    if !(add || over || glow || konst) {
        return false;
    }
    if konst {
        return blend_konst(b, row, rgb, a, m, mask);
    }
    blend_group::<false>(b, row, rgb, a, m, mask, add, glow)
}

/// `blend_unorm8`'s CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA route, a function of its own:
/// inlined beside the others, it cost the group loop of every other state 1–3% (register
/// allocation).
#[inline(never)]
fn blend_konst(
    b: &BlendEval,
    row: &mut [[u8; 4]],
    rgb: &[F; 3],
    a: &F,
    m: u8,
    mask: [bool; 4],
) -> bool {
    blend_group::<true>(b, row, rgb, a, m, mask, false, false)
}

/// `blend_unorm8`'s stores: ONE, ONE when `add`, SRC_ALPHA, ONE when `glow`, CONSTANT_ALPHA,
/// ONE_MINUS_CONSTANT_ALPHA when `KONST`, else SRC_ALPHA, ONE_MINUS_SRC_ALPHA.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn blend_group<const KONST: bool>(
    b: &BlendEval,
    row: &mut [[u8; 4]],
    rgb: &[F; 3],
    a: &F,
    m: u8,
    mask: [bool; 4],
    add: bool,
    glow: bool,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if let Some(px) = row.get_mut(..LANES) {
        use std::arch::x86_64::{
            __m128i, _mm_add_epi16, _mm_adds_epu8, _mm_and_si128, _mm_andnot_si128,
            _mm_cmpeq_epi32, _mm_loadu_si128, _mm_mullo_epi16, _mm_or_si128, _mm_packus_epi16,
            _mm_set1_epi16, _mm_set1_epi32, _mm_set_epi32, _mm_setzero_si128, _mm_shufflehi_epi16,
            _mm_shufflelo_epi16, _mm_srli_epi16, _mm_storeu_si128, _mm_sub_epi16,
            _mm_unpackhi_epi8, _mm_unpacklo_epi8,
        };
        let cm = u32::from_le_bytes(mask.map(|on| if on { 0xFF } else { 0 }));
        // SAFETY: SSE2 is part of the x86-64 baseline; `px` holds eight `[u8; 4]`, 32
        // contiguous bytes, read and written 16 bytes at offsets 0 and 16 (in bounds, no
        // alignment needed).
        unsafe {
            let z = _mm_setzero_si128();
            let (c255, c128) = (_mm_set1_epi16(255), _mm_set1_epi16(128));
            // `mul8_lanes` of eight 16-bit lanes.
            let mul8 = |x: __m128i, y: __m128i| {
                let p = _mm_mullo_epi16(x, y);
                _mm_srli_epi16::<8>(_mm_add_epi16(
                    _mm_add_epi16(p, _mm_srli_epi16::<8>(p)),
                    c128,
                ))
            };
            // Two pixels' source over destination, widened.
            let over2 = |s: __m128i, d: __m128i| {
                let sa = _mm_shufflehi_epi16::<0xFF>(_mm_shufflelo_epi16::<0xFF>(s));
                _mm_add_epi16(mul8(s, sa), mul8(d, _mm_sub_epi16(c255, sa)))
            };
            // The constant route's two factors on every 16-bit lane.
            let ca = _mm_set1_epi16(i16::from(b.constant[3]));
            let ica = _mm_sub_epi16(c255, ca);
            let bits = _mm_set_epi32(8, 4, 2, 1);
            let cmv = _mm_set1_epi32(cm as i32);
            let p = px.as_mut_ptr().cast::<__m128i>();
            for h in 0..2 {
                let o = 4 * h;
                let src = pack4(rgb, a, h);
                let old = _mm_loadu_si128(p.add(h));
                let v = if add {
                    _mm_adds_epu8(src, old)
                } else if glow {
                    let sa =
                        |s: __m128i| _mm_shufflehi_epi16::<0xFF>(_mm_shufflelo_epi16::<0xFF>(s));
                    let (lo, hi) = (_mm_unpacklo_epi8(src, z), _mm_unpackhi_epi8(src, z));
                    // Each product is at most 255: the pack keeps it.
                    let sf = _mm_packus_epi16(mul8(lo, sa(lo)), mul8(hi, sa(hi)));
                    _mm_adds_epu8(sf, old)
                } else if KONST {
                    let w = |s: __m128i, d: __m128i| _mm_add_epi16(mul8(s, ca), mul8(d, ica));
                    _mm_packus_epi16(
                        w(_mm_unpacklo_epi8(src, z), _mm_unpacklo_epi8(old, z)),
                        w(_mm_unpackhi_epi8(src, z), _mm_unpackhi_epi8(old, z)),
                    )
                } else {
                    _mm_packus_epi16(
                        over2(_mm_unpacklo_epi8(src, z), _mm_unpacklo_epi8(old, z)),
                        over2(_mm_unpackhi_epi8(src, z), _mm_unpackhi_epi8(old, z)),
                    )
                };
                let lv = _mm_set1_epi32(i32::from(m >> o));
                let sel = _mm_and_si128(_mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits), cmv);
                let out = _mm_or_si128(_mm_andnot_si128(sel, old), _mm_and_si128(sel, v));
                _mm_storeu_si128(p.add(h), out);
            }
        }
        return true;
    }
    let _ = (b, row, rgb, a, m, mask, add, glow);
    false
}

/// Eight-lane AVX2 versions of the group kernels above, for `FragCtx::plain_rows_avx2`: each
/// lane computes the same operations in the same order as the SSE2 kernel it replaces
/// (`clamp01`, `depth_lanes` of `lin_lanes` with `depth_test`, `fog`, `store_unorm8`,
/// `blend_unorm8`), one 256-bit instruction where that kernel takes two 128-bit halves, so
/// the same bits (no FMA: nothing is fused). A row shorter than a group, and the states a
/// kernel has no route for, take the SSE2 kernel.
///
/// Each kernel is an `#[inline(always)]` `unsafe fn` rather than a `#[target_feature]` one
/// (which cannot be `inline(always)`; LLVM left the depth test and the store out of line,
/// each call passing its lanes through memory): inlined into a function compiled for AVX2
/// (`plain_rows_avx2`), the intrinsics are inlined there too.
///
/// # Safety
/// Every kernel needs a CPU with AVX2 (`lanes::has_avx2`).
#[cfg(target_arch = "x86_64")]
pub(super) mod avx2 {
    use super::{BlendEval, FogEval, StencilSide, F, LANES};
    use crate::gl;
    use std::arch::x86_64::{
        __m256, __m256i, _mm256_add_epi16, _mm256_add_pd, _mm256_add_ps, _mm256_adds_epu8,
        _mm256_and_si256, _mm256_andnot_ps, _mm256_andnot_si256, _mm256_castps256_ps128,
        _mm256_castsi256_ps, _mm256_cmp_ps, _mm256_cmpeq_epi32, _mm256_cmpgt_epi32,
        _mm256_cvtps_pd, _mm256_cvttpd_epi32, _mm256_extractf128_ps, _mm256_loadu_ps,
        _mm256_loadu_si256, _mm256_max_pd, _mm256_max_ps, _mm256_min_pd, _mm256_min_ps,
        _mm256_movemask_ps, _mm256_mul_pd, _mm256_mul_ps, _mm256_mullo_epi16, _mm256_or_si256,
        _mm256_packus_epi16, _mm256_set1_epi16, _mm256_set1_epi32, _mm256_set1_pd, _mm256_set1_ps,
        _mm256_set_m128i, _mm256_setr_ps, _mm256_setzero_pd, _mm256_setzero_ps,
        _mm256_setzero_si256, _mm256_shufflehi_epi16, _mm256_shufflelo_epi16, _mm256_slli_epi32,
        _mm256_srli_epi16, _mm256_storeu_si256, _mm256_sub_epi16, _mm256_sub_ps,
        _mm256_unpackhi_epi8, _mm256_unpacklo_epi8, _mm256_xor_ps, _mm256_xor_si256, _CMP_UNORD_Q,
    };

    /// Eight lanes in a register.
    #[inline(always)]
    unsafe fn ld(c: &F) -> __m256 {
        // SAFETY: `c` holds eight f32, 32 bytes (no alignment needed).
        unsafe { _mm256_loadu_ps(c.as_ptr()) }
    }

    /// A register's eight lanes.
    #[inline(always)]
    unsafe fn out(v: __m256) -> F {
        // SAFETY: `__m256` has the layout of `[f32; 8]`; every bit pattern is valid for both.
        unsafe { std::mem::transmute::<__m256, F>(v) }
    }

    /// The lane-select mask of coverage bits `m` (lane l all ones when bit l is set).
    #[inline(always)]
    unsafe fn lanes_of(m: u8) -> __m256i {
        // SAFETY: inlined into this module's AVX2 kernels only.
        unsafe { crate::cpu::lanes::lane_mask8(m) }
    }

    /// `super::clamp01`: `maxps` with 0, then `minps` with 1.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    pub unsafe fn clamp01(c: F) -> F {
        out(_mm256_min_ps(
            _mm256_max_ps(ld(&c), _mm256_setzero_ps()),
            _mm256_set1_ps(1.0),
        ))
    }

    /// `super::depth_test(func, write, row, depth_lanes(lin_lanes(zrow, dz, &lane_x(fx0))),
    /// live)`: lane x `fx0 as f32 + l` (exact, as `lane_x`), `zrow + dz·x`, the conversion in
    /// double precision (`vcvtps2pd`, `vmaxpd` with 0 — a NaN or −0 gives +0 —, `vminpd` with
    /// 1, `vmulpd`, `vaddpd`, `vcvttpd2dq`), the unsigned compare on values with the top bit
    /// flipped, the select for the write.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    pub unsafe fn depth_test(
        func: u32,
        write: bool,
        row: &mut [u32],
        zrow: f32,
        dz: f32,
        fx0: i32,
        live: u8,
    ) -> u8 {
        let iota = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
        let x = _mm256_add_ps(_mm256_set1_ps(fx0 as f32), iota);
        let z = _mm256_add_ps(_mm256_set1_ps(zrow), _mm256_mul_ps(_mm256_set1_ps(dz), x));
        let Some(r) = row.get_mut(..LANES) else {
            let d = super::super::lanes::depth_lanes(out(z));
            return super::depth_test(func, write, row, d, live);
        };
        let (zd, oned) = (_mm256_setzero_pd(), _mm256_set1_pd(1.0));
        let (kd, hd) = (
            _mm256_set1_pd(f64::from(crate::cpu::framebuffer::DEPTH_MAX)),
            _mm256_set1_pd(0.5),
        );
        // (Macros, not closures, here and below: a closure is not always inlined, and out of
        // line its intrinsics would be calls.)
        macro_rules! depth4 {
            ($z:expr) => {{
                let z = _mm256_min_pd(_mm256_max_pd(_mm256_cvtps_pd($z), zd), oned);
                _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(z, kd), hd))
            }};
        }
        let d = _mm256_set_m128i(
            depth4!(_mm256_extractf128_ps::<1>(z)),
            depth4!(_mm256_castps256_ps128(z)),
        );
        let (sign, ones) = (_mm256_set1_epi32(i32::MIN), _mm256_set1_epi32(-1));
        let rp = r.as_mut_ptr().cast::<__m256i>();
        // SAFETY: `r` holds eight u32, 32 bytes (no alignment needed).
        let s = unsafe { _mm256_loadu_si256(rp) };
        let (a, b) = (_mm256_xor_si256(d, sign), _mm256_xor_si256(s, sign));
        let pass = match func {
            gl::NEVER => _mm256_setzero_si256(),
            gl::LESS => _mm256_cmpgt_epi32(b, a),
            gl::EQUAL => _mm256_cmpeq_epi32(a, b),
            gl::LEQUAL => _mm256_xor_si256(_mm256_cmpgt_epi32(a, b), ones),
            gl::GREATER => _mm256_cmpgt_epi32(a, b),
            gl::NOTEQUAL => _mm256_xor_si256(_mm256_cmpeq_epi32(a, b), ones),
            gl::GEQUAL => _mm256_xor_si256(_mm256_cmpgt_epi32(b, a), ones),
            _ => ones,
        };
        let pass = _mm256_and_si256(pass, lanes_of(live));
        if write {
            let v = _mm256_or_si256(_mm256_and_si256(pass, d), _mm256_andnot_si256(pass, s));
            // SAFETY: as the load above.
            unsafe { _mm256_storeu_si256(rp, v) };
        }
        _mm256_movemask_ps(_mm256_castsi256_ps(pass)) as u8
    }

    /// `super::stencil_depth(side, depth, st, dp, depth_lanes(lin_lanes(zrow, dz,
    /// &lane_x(fx0))), live)`: on a whole group the stencil test and operations as there (SSE2,
    /// eight bytes) and the depth test of the stencil survivors by `depth_test` above (the
    /// depths computed only when some lane passes the stencil test); a shorter row takes
    /// `super::stencil_depth` with the lanes' depths.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub unsafe fn stencil_depth(
        side: &StencilSide,
        depth: Option<(u32, bool)>,
        st: &mut [u8],
        dp: &mut [u32],
        zrow: f32,
        dz: f32,
        fx0: i32,
        live: u8,
    ) -> u8 {
        use super::super::lanes::{depth_lanes, lane_x, lin_lanes};
        if let (Some(st), Some(dp)) = (st.get_mut(..LANES), dp.get_mut(..LANES)) {
            let z = super::GroupZ::Plane { zrow, dz, fx0 };
            return super::stencil_group(side, depth, st, dp, z, live);
        }
        let d = if depth.is_some() {
            depth_lanes(lin_lanes(zrow, dz, &lane_x(fx0)))
        } else {
            [0; LANES]
        };
        super::stencil_depth(side, depth, st, dp, d, live)
    }

    /// `super::fog`: the factor (LINEAR `c·scale + e`; EXP and EXP2 their arguments on lanes,
    /// `exp_live` for the lanes of `live`), the clamp (a NaN gives +0, then `vmaxps(0, f)` and
    /// `vminps(1, f)`, which are `if f < 0 {0} else {f}` and `if f > 1 {1} else {f}`, −0 kept),
    /// then `C_f + (C − C_f)·f` on R, G and B.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    pub unsafe fn fog(fog: &FogEval, rgb: &mut [F; 3], coord: F, live: u8) {
        let c = ld(&coord);
        let f = if fog.mode != gl::LINEAR {
            let arg = if fog.mode == gl::EXP {
                _mm256_mul_ps(_mm256_set1_ps(-fog.density), c)
            } else {
                let dc = _mm256_mul_ps(_mm256_set1_ps(fog.density), c);
                _mm256_mul_ps(_mm256_xor_ps(dc, _mm256_set1_ps(-0.0)), dc)
            };
            ld(&super::exp_live(&out(arg), live))
        } else {
            let scale = -1.0 / (fog.end - fog.start);
            let e = fog.end * -scale;
            _mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(scale)), _mm256_set1_ps(e))
        };
        let f = _mm256_andnot_ps(_mm256_cmp_ps::<_CMP_UNORD_Q>(f, f), f);
        let f = _mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_setzero_ps(), f));
        let cf = fog.color.to_array();
        for (ch, cf) in rgb.iter_mut().zip(cf) {
            let cf = _mm256_set1_ps(cf);
            *ch = out(_mm256_add_ps(
                cf,
                _mm256_mul_ps(_mm256_sub_ps(ld(ch), cf), f),
            ));
        }
    }

    /// `super::pack4` of all eight lanes: each pixel as an RGBA8 word, red in the low byte.
    #[inline(always)]
    unsafe fn pack8(rgb: &[F; 3], a: &F) -> __m256i {
        macro_rules! conv {
            ($c:expr) => {
                crate::cpu::lanes::unorm8_bits8(ld($c))
            };
        }
        _mm256_or_si256(
            _mm256_or_si256(conv!(&rgb[0]), _mm256_slli_epi32::<8>(conv!(&rgb[1]))),
            _mm256_or_si256(
                _mm256_slli_epi32::<16>(conv!(&rgb[2])),
                _mm256_slli_epi32::<24>(conv!(a)),
            ),
        )
    }

    /// The select of `store`: lanes of `m`, bytes of `mask`, from `v` over `old`.
    #[inline(always)]
    unsafe fn select(old: __m256i, v: __m256i, m: u8, mask: [bool; 4]) -> __m256i {
        let [r, g, b, a] = mask.map(u32::from);
        let cm = (r | g << 8 | b << 16 | a << 24) * 0xFF;
        let sel = _mm256_and_si256(lanes_of(m), _mm256_set1_epi32(cm as i32));
        _mm256_or_si256(_mm256_andnot_si256(sel, old), _mm256_and_si256(sel, v))
    }

    /// `super::store_unorm8`.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    pub unsafe fn store_unorm8(row: &mut [[u8; 4]], rgb: &[F; 3], a: &F, m: u8, mask: [bool; 4]) {
        let Some(px) = row.get_mut(..LANES) else {
            return super::store_unorm8(row, rgb, a, m, mask);
        };
        let p = px.as_mut_ptr().cast::<__m256i>();
        let v = pack8(rgb, a);
        // SAFETY: `px` holds eight `[u8; 4]`, 32 contiguous bytes (no alignment needed).
        unsafe {
            let old = _mm256_loadu_si256(p);
            _mm256_storeu_si256(p, select(old, v, m, mask));
        }
    }

    /// `super::blend_unorm8`: ONE, ONE (`vpaddusb`), SRC_ALPHA, ONE and SRC_ALPHA,
    /// ONE_MINUS_SRC_ALPHA on sixteen 16-bit lanes (the unpacks and packs work within each
    /// 128-bit half, so the pixels come back in their order); CONSTANT_ALPHA,
    /// ONE_MINUS_CONSTANT_ALPHA and a short row take the SSE2 kernel. False (nothing written)
    /// for another state.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline(always)]
    pub unsafe fn blend_unorm8(
        b: &BlendEval,
        row: &mut [[u8; 4]],
        rgb: &[F; 3],
        a: &F,
        m: u8,
        mask: [bool; 4],
    ) -> bool {
        let usual = b.eq_rgb == gl::FUNC_ADD
            && b.eq_alpha == gl::FUNC_ADD
            && b.src_rgb == b.src_alpha
            && b.dst_rgb == b.dst_alpha;
        let add = usual && b.src_rgb == gl::ONE && b.dst_rgb == gl::ONE;
        let over = usual && b.src_rgb == gl::SRC_ALPHA && b.dst_rgb == gl::ONE_MINUS_SRC_ALPHA;
        let glow = usual && b.src_rgb == gl::SRC_ALPHA && b.dst_rgb == gl::ONE;
        let px = match row.get_mut(..LANES) {
            Some(px) if add || over || glow => px,
            _ => return super::blend_unorm8(b, row, rgb, a, m, mask),
        };
        let p = px.as_mut_ptr().cast::<__m256i>();
        let src = pack8(rgb, a);
        // SAFETY: `px` holds eight `[u8; 4]`, 32 contiguous bytes (no alignment needed).
        let old = unsafe { _mm256_loadu_si256(p) };
        let z = _mm256_setzero_si256();
        let (c255, c128) = (_mm256_set1_epi16(255), _mm256_set1_epi16(128));
        macro_rules! mul8 {
            ($x:expr, $y:expr) => {{
                let p = _mm256_mullo_epi16($x, $y);
                _mm256_srli_epi16::<8>(_mm256_add_epi16(
                    _mm256_add_epi16(p, _mm256_srli_epi16::<8>(p)),
                    c128,
                ))
            }};
        }
        macro_rules! sa {
            ($s:expr) => {
                _mm256_shufflehi_epi16::<0xFF>(_mm256_shufflelo_epi16::<0xFF>($s))
            };
        }
        let v = if add {
            _mm256_adds_epu8(src, old)
        } else if glow {
            let (lo, hi) = (_mm256_unpacklo_epi8(src, z), _mm256_unpackhi_epi8(src, z));
            let sf = _mm256_packus_epi16(mul8!(lo, sa!(lo)), mul8!(hi, sa!(hi)));
            _mm256_adds_epu8(sf, old)
        } else {
            macro_rules! over2 {
                ($s:expr, $d:expr) => {{
                    let (s, d) = ($s, $d);
                    let sa = sa!(s);
                    _mm256_add_epi16(mul8!(s, sa), mul8!(d, _mm256_sub_epi16(c255, sa)))
                }};
            }
            _mm256_packus_epi16(
                over2!(_mm256_unpacklo_epi8(src, z), _mm256_unpacklo_epi8(old, z)),
                over2!(_mm256_unpackhi_epi8(src, z), _mm256_unpackhi_epi8(old, z)),
            )
        };
        // SAFETY: as the load above.
        unsafe { _mm256_storeu_si256(p, select(old, v, m, mask)) };
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The eight stencil operations (§4.1.5).
    const STENCIL_OPS: [u32; 8] = [
        gl::KEEP,
        gl::ZERO,
        gl::REPLACE,
        gl::INCR,
        gl::DECR,
        gl::INVERT,
        gl::INCR_WRAP,
        gl::DECR_WRAP,
    ];
    use crate::cpu::fragops::{logic_op, BlendEval};
    use crate::cpu::framebuffer::unorm8;
    use crate::cpu::testgen::{Gen, COMPARE_FUNCS};
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
            let live = if g.next() % 2 == 0 {
                0xFF
            } else {
                g.next() as u8
            };
            fog(&f, &mut got, coord, live);
            for l in (0..LANES).filter(|l| live & (1 << l) != 0) {
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

    /// `libm8::expf::expf8` against libm's `expf` (`f32::exp`) bit for bit on 400 000 lanes: any
    /// bits (NaN, ±∞, denormals, huge), the main range's bits, and arguments the fog scene
    /// gives (−density·c, −(density·c)²). Where the kernel is not usable (no AVX2/FMA, or
    /// libm's `expf` is another function) `exp_live` alone is compared.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn expf8_is_libm_expf_bit_for_bit() {
        let mut g = Gen(17);
        let usable = super::expf::usable();
        for round in 0..50_000 {
            let a: F = std::array::from_fn(|_| match g.next() % 4 {
                0 => f32::from_bits(g.next() as u32),
                1 => f32::from_bits(g.next() as u32 & 0xC2AF_FFFF),
                2 => -((g.next() % 4000) as f32 * 0.01) * g.float().abs(),
                _ => {
                    let dc = (g.next() % 100) as f32 * 0.05 * g.float();
                    -dc * dc
                }
            });
            let live = if round % 2 == 0 { 0xFF } else { g.next() as u8 };
            let got = exp_live(&a, live);
            for l in (0..LANES).filter(|l| live & (1 << l) != 0) {
                assert_eq!(got[l].to_bits(), a[l].exp().to_bits(), "exp_live {}", a[l]);
            }
            if usable {
                let mut out = [0.0; LANES];
                // SAFETY: `usable` says AVX2 and FMA are present.
                let left = unsafe { super::expf::expf8(&a, &mut out) };
                for l in 0..LANES {
                    let top = (a[l].to_bits() >> 20) & 0x7ff;
                    assert_eq!(left & (1 << l) != 0, top > 0x42a, "{}", a[l]);
                    if top <= 0x42a {
                        assert_eq!(out[l].to_bits(), a[l].exp().to_bits(), "expf8 {}", a[l]);
                    }
                }
            }
        }
    }

    /// Every argument of `expf8`'s main range (2.2·10^9 floats) against libm; about a minute
    /// in release: `cargo test --release --lib expf8_every -- --ignored`.
    #[cfg(target_arch = "x86_64")]
    #[test]
    #[ignore]
    fn expf8_every_main_range_argument_is_libm_expf() {
        if !super::expf::usable() {
            return;
        }
        let mut bad = 0u64;
        for sign in [0u32, 0x8000_0000] {
            let mut b = 0u32;
            while b <= 0x42AF_FFFF {
                let a: F = std::array::from_fn(|l| f32::from_bits(sign | (b + l as u32)));
                let mut out = [0.0; LANES];
                // SAFETY: `usable` says AVX2 and FMA are present.
                unsafe { super::expf::expf8(&a, &mut out) };
                for l in 0..LANES {
                    if out[l].to_bits() != a[l].exp().to_bits() {
                        bad += 1;
                    }
                }
                b += LANES as u32;
            }
        }
        assert_eq!(bad, 0);
    }

    #[test]
    fn alpha_test_is_the_scalar_comparison() {
        let mut g = Gen(9);
        let funcs = COMPARE_FUNCS;
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
        let funcs = COMPARE_FUNCS;
        let ops = STENCIL_OPS;
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
            // Rows of eight and more take the whole-group route.
            let n = (g.next() % 13) as usize;
            // Few distinct depths so that EQUAL passes now and then.
            // Now and then any value, the top bit set among them (the SSE2 comparison is
            // signed with that bit flipped).
            let dv = |g: &mut Gen| match g.next() % 8 {
                0 => g.next() as u32,
                _ => (g.next() % 4) as u32 * 1000,
            };
            let d: [u32; LANES] = std::array::from_fn(|_| dv(&mut g));
            let st0: Vec<u8> = (0..n).map(|_| g.byte()).collect();
            // Now and then a shorter depth row: its missing lanes fail the depth test.
            let nd = if g.next() % 8 == 0 { n / 2 } else { n };
            let dp0: Vec<u32> = (0..nd).map(|_| dv(&mut g)).collect();
            let live = g.next() as u8;
            let (mut st, mut dp) = (st0.clone(), dp0.clone());
            let m = stencil_depth(&side, depth, &mut st, &mut dp, d, live);
            let (mut wst, mut wdp, mut wm) = (st0.clone(), dp0.clone(), 0u8);
            for l in 0..n.min(LANES) {
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
            for l in 0..nd.min(LANES) {
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
            let mut b = BlendEval {
                src_rgb: pick(&mut g),
                dst_rgb: pick(&mut g),
                src_alpha: pick(&mut g),
                dst_alpha: pick(&mut g),
                eq_rgb: eqs[(g.next() % 5) as usize],
                eq_alpha: eqs[(g.next() % 5) as usize],
                constant: std::array::from_fn(|_| g.byte()),
            };
            // The direct routes (and near misses of them) a third of the time.
            let usual = [(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA), (gl::ONE, gl::ONE)];
            if g.next() % 3 == 0 {
                let (sf, df) = usual[(g.next() % 2) as usize];
                (b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha) = (sf, df, sf, df);
                (b.eq_rgb, b.eq_alpha) = (gl::FUNC_ADD, gl::FUNC_ADD);
                match g.next() % 6 {
                    0 => b.eq_alpha = eqs[(g.next() % 5) as usize],
                    1 => b.dst_alpha = pick(&mut g),
                    _ => {}
                }
            }
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
        let row: Vec<[u8; 4]> = (0..11u8).map(|i| [i, i + 100, 255 - i, i ^ 0x80]).collect();
        for o in 0..4 {
            let got = load(&row[o..]);
            for l in 0..LANES {
                assert_eq!(got.map(|c| c[l]), row[o + l], "offset {o} lane {l}");
            }
        }
    }

    #[test]
    fn store_writes_the_covered_lanes_through_the_colour_mask() {
        let mut g = Gen(23);
        for _ in 0..3000 {
            let n = (g.next() % 12) as usize;
            let row0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let c: [B; 4] = std::array::from_fn(|_| g.bytes());
            let m = g.next() as u8;
            let mask: [bool; 4] = std::array::from_fn(|_| g.next() % 3 != 0);
            let mut got = row0.clone();
            store(&mut got, &c, m, mask);
            let mut want = row0.clone();
            for (l, dst) in want.iter_mut().take(LANES).enumerate() {
                for k in 0..4 {
                    if m & (1 << l) != 0 && mask[k] {
                        dst[k] = c[k][l];
                    }
                }
            }
            assert_eq!(got, want, "m {m:#x} mask {mask:?}");
        }
    }

    #[test]
    fn store_unorm8_is_store_of_the_unorm8_bytes() {
        let mut g = Gen(29);
        for _ in 0..3000 {
            let n = (g.next() % 12) as usize;
            let row0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            // Around [0, 1], with NaNs, infinities, −0 and values past the ends now and then.
            let mut f = || match g.next() % 16 {
                0 => f32::NAN,
                1 => f32::INFINITY,
                2 => -0.0,
                3 => f32::NEG_INFINITY,
                _ => g.float(),
            };
            let c: [F; 4] = std::array::from_fn(|_| std::array::from_fn(|_| f()));
            let m = g.next() as u8;
            let mask: [bool; 4] = std::array::from_fn(|_| g.next() % 3 != 0);
            let mut got = row0.clone();
            store_unorm8(&mut got, &[c[0], c[1], c[2]], &c[3], m, mask);
            let mut want = row0.clone();
            let bytes = c.map(super::super::lanes::unorm8_lanes);
            store(&mut want, &bytes, m, mask);
            assert_eq!(got, want, "m {m:#x} mask {mask:?} {c:?}");
        }
    }

    #[test]
    fn blend_unorm8_is_store_of_blend_of_the_unorm8_bytes() {
        let mut g = Gen(31);
        let factors = [gl::ONE, gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA, gl::ZERO];
        let mut done = 0;
        for _ in 0..8000 {
            let n = (g.next() % 12) as usize;
            let row0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let c: [F; 4] = std::array::from_fn(|_| g.lanes());
            let m = g.next() as u8;
            let mask: [bool; 4] = std::array::from_fn(|_| g.next() % 3 != 0);
            let (sf, df) = match g.next() % 5 {
                0 => (gl::ONE, gl::ONE),
                1 => (gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA),
                2 => (gl::SRC_ALPHA, gl::ONE),
                3 => (gl::CONSTANT_ALPHA, gl::ONE_MINUS_CONSTANT_ALPHA),
                _ => (g.pick(&factors), g.pick(&factors)),
            };
            let b = BlendEval {
                src_rgb: sf,
                dst_rgb: df,
                src_alpha: if g.next() % 8 == 0 { gl::ONE } else { sf },
                dst_alpha: df,
                eq_rgb: gl::FUNC_ADD,
                eq_alpha: if g.next() % 8 == 0 {
                    gl::FUNC_SUBTRACT
                } else {
                    gl::FUNC_ADD
                },
                constant: [
                    g.byte(),
                    g.byte(),
                    g.byte(),
                    [0, 255, g.byte()][(g.next() % 3) as usize],
                ],
            };
            let mut got = row0.clone();
            if !blend_unorm8(&b, &mut got, &[c[0], c[1], c[2]], &c[3], m, mask) {
                assert_eq!(got, row0, "nothing written when not handled");
                continue;
            }
            done += 1;
            let mut want = row0.clone();
            let bytes = c.map(super::super::lanes::unorm8_lanes);
            let out = blend(&b, &bytes, &load(&want));
            store(&mut want, &out, m, mask);
            assert_eq!(got, want, "{b:?} m {m:#x} mask {mask:?} {c:?}");
        }
        assert!(done > 1000, "{done} handled");
    }

    /// The eight-lane AVX2 kernels (`avx2::*`) against the SSE2 ones bit for bit, where the
    /// CPU has AVX2: clamp, fog (every mode, NaN/±∞/−0/denormal coordinates and colours),
    /// the depth test with its plane (every DepthFunc, DepthMask on and off, rows shorter
    /// than a group), the unorm8 store and the blends (handled and unhandled states, short
    /// rows, every ColorMask).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn avx2_kernels_are_the_sse2_kernels_bit_for_bit() {
        if !super::super::lanes::has_avx2() {
            return;
        }
        use super::super::lanes::{depth_lanes, lane_x, lin_lanes};
        let mut g = Gen(37);
        let bits = |c: &[F]| -> Vec<u32> { c.iter().flatten().map(|v| v.to_bits()).collect() };
        let f = |g: &mut Gen| match g.next() % 16 {
            0 => f32::NAN,
            1 => f32::INFINITY,
            2 => f32::NEG_INFINITY,
            3 => f32::from_bits((g.next() as u32) & 0x807F_FFFF),
            _ => g.float(),
        };
        let (mut written, mut blended, mut stenciled) = (0, 0, 0);
        for _ in 0..20_000 {
            let c: [F; 4] = std::array::from_fn(|_| std::array::from_fn(|_| f(&mut g)));
            // SAFETY: the CPU has AVX2 (checked above).
            let got = unsafe { c.map(|c| avx2::clamp01(c)) };
            assert_eq!(bits(&got), bits(&c.map(clamp01)), "clamp {c:?}");

            let fe = FogEval {
                mode: [gl::LINEAR, gl::EXP, gl::EXP2][(g.next() % 3) as usize],
                density: if g.next() % 8 == 0 {
                    f(&mut g)
                } else {
                    g.float().abs()
                },
                start: f(&mut g),
                end: if g.next() % 8 == 0 {
                    f32::NAN
                } else {
                    g.float()
                },
                color: Vec3::new(f(&mut g), g.float(), g.float()),
            };
            let coord: F = std::array::from_fn(|_| f(&mut g) * 4.0);
            let live = g.next() as u8;
            let rgb = [got[0], got[1], got[2]];
            let (mut want, mut have) = (rgb, rgb);
            fog(&fe, &mut want, coord, live);
            // SAFETY: as above.
            unsafe { avx2::fog(&fe, &mut have, coord, live) };
            for l in (0..LANES).filter(|l| live & (1 << l) != 0) {
                for k in 0..3 {
                    assert_eq!(
                        have[k][l].to_bits(),
                        want[k][l].to_bits(),
                        "fog {fe:?} coord {} c {}",
                        coord[l],
                        rgb[k][l]
                    );
                }
            }

            let n = (g.next() % 12) as usize;
            let row0: Vec<u32> = (0..n)
                .map(|_| match g.next() % 3 {
                    0 => (g.next() % 5) as u32 * (crate::cpu::framebuffer::DEPTH_MAX / 4),
                    1 => g.next() as u32,
                    _ => g.next() as u32 & crate::cpu::framebuffer::DEPTH_MAX,
                })
                .collect();
            let func = g.pick(&COMPARE_FUNCS);
            let write = g.next() % 2 == 0;
            let zrow = f(&mut g);
            let dz = if g.next() % 2 == 0 { f(&mut g) } else { 1e-3 };
            let fx0 = (g.next() % 300) as i32 - 20;
            let (mut want, mut have) = (row0.clone(), row0.clone());
            let d = depth_lanes(lin_lanes(zrow, dz, &lane_x(fx0)));
            let mw = depth_test(func, write, &mut want, d, live);
            // SAFETY: as above.
            let mh = unsafe { avx2::depth_test(func, write, &mut have, zrow, dz, fx0, live) };
            assert_eq!(
                (mh, &have),
                (mw, &want),
                "depth {func:#x} {write} {zrow} {dz} {fx0}"
            );

            // The stencil test and operations with the depth test of the plane.
            let ops = STENCIL_OPS;
            let side = StencilSide {
                func: g.pick(&COMPARE_FUNCS),
                reference: g.byte(),
                mask: if g.next() % 2 == 0 { 0xFF } else { g.byte() },
                ops: std::array::from_fn(|_| ops[(g.next() % 8) as usize]),
                write: if g.next() % 2 == 0 { 0xFF } else { g.byte() },
            };
            let depth = (g.next() % 4 != 0).then_some((func, write));
            let ns = if g.next() % 8 == 0 { n / 2 } else { n };
            let st0: Vec<u8> = (0..ns)
                .map(|_| {
                    if g.next() % 2 == 0 {
                        side.reference
                    } else {
                        g.byte()
                    }
                })
                .collect();
            let (mut wst, mut wdp) = (st0.clone(), row0.clone());
            let (mut hst, mut hdp) = (st0, row0.clone());
            let mw = stencil_depth(&side, depth, &mut wst, &mut wdp, d, live);
            // SAFETY: as above.
            let mh = unsafe {
                avx2::stencil_depth(&side, depth, &mut hst, &mut hdp, zrow, dz, fx0, live)
            };
            assert_eq!(
                (mh, &hst, &hdp),
                (mw, &wst, &wdp),
                "stencil {side:?} {depth:?} {zrow} {dz} {fx0}"
            );
            stenciled += usize::from(ns >= LANES && n >= LANES && mw != 0);

            let px0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let mask: [bool; 4] = std::array::from_fn(|_| g.next() % 3 != 0);
            let (mut want, mut have) = (px0.clone(), px0.clone());
            store_unorm8(&mut want, &rgb, &c[3], live, mask);
            // SAFETY: as above.
            unsafe { avx2::store_unorm8(&mut have, &rgb, &c[3], live, mask) };
            assert_eq!(have, want, "store m {live:#x} mask {mask:?} {c:?}");
            written += usize::from(n >= LANES);

            let (sf, df) = match g.next() % 6 {
                0 => (gl::ONE, gl::ONE),
                1 | 5 => (gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA),
                2 => (gl::SRC_ALPHA, gl::ONE),
                3 => (gl::CONSTANT_ALPHA, gl::ONE_MINUS_CONSTANT_ALPHA),
                _ => (gl::ONE_MINUS_SRC_ALPHA, gl::ZERO),
            };
            let b = BlendEval {
                src_rgb: sf,
                dst_rgb: df,
                src_alpha: if g.next() % 8 == 0 { gl::ONE } else { sf },
                dst_alpha: df,
                eq_rgb: gl::FUNC_ADD,
                eq_alpha: gl::FUNC_ADD,
                constant: [g.byte(), g.byte(), g.byte(), g.byte()],
            };
            let (mut want, mut have) = (px0.clone(), px0);
            let ow = blend_unorm8(&b, &mut want, &rgb, &c[3], live, mask);
            // SAFETY: as above.
            let oh = unsafe { avx2::blend_unorm8(&b, &mut have, &rgb, &c[3], live, mask) };
            assert_eq!(
                (oh, &have),
                (ow, &want),
                "blend {b:?} m {live:#x} mask {mask:?}"
            );
            blended += usize::from(ow && n >= LANES);
        }
        assert!(
            written > 5000 && blended > 3000 && stenciled > 1000,
            "{written} {blended} {stenciled}"
        );
    }
}
