//! Fragment kernels over groups of `LANES` pixels of a span: the same arithmetic as the scalar
//! per-fragment code in `fragment`, written on fixed-size arrays of lanes so that the compiler
//! turns each step into one SIMD instruction (SSE2 on the x86-64 baseline: `divps`, `cvtdq2ps`,
//! `minps`/`maxps`-style selects), with a coverage mask choosing which lanes are stored.
//!
//! Design decision: every lane computes exactly the scalar expression, operation for operation
//! and in the same order (IEEE single and double precision give the same bits in a vector
//! register as in a scalar one, and Rust never fuses a multiply and an add), so the images are
//! byte for byte those of the scalar code; the unit tests below compare the two bit for bit.
//! Lanes past the span's end or outside the mask are computed and thrown away.

use super::framebuffer::DEPTH_MAX;
use super::setup::Win;
use super::vertex::LANES as VERTEX_LANES;

/// Pixels a kernel handles at once.
pub const LANES: usize = 8;

/// The lanes of coverage bits `m` as a 256-bit select mask: 32-bit lane l all ones when bit
/// l is set. Only inlined into functions compiled for AVX2 (the caller's contract).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn lane_mask8(m: u8) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::{
        _mm256_and_si256, _mm256_cmpeq_epi32, _mm256_set1_epi32, _mm256_setr_epi32,
    };
    // SAFETY: the caller runs on a CPU with AVX2.
    unsafe {
        let bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        _mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_set1_epi32(i32::from(m)), bits),
            bits,
        )
    }
}

/// `unorm8_lanes`' conversion of eight floats: each clamped to [0, 1] (`maxps` with 0, then
/// `minps` with 1), then c · (255/256) + 32768, whose low byte is `framebuffer::unorm8` of
/// c, left in the low bits of its 32-bit lane (the rest zero). Only inlined into functions
/// compiled for AVX2 (the caller's contract).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn unorm8_bits8(c: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::{
        _mm256_add_ps, _mm256_and_si256, _mm256_castps_si256, _mm256_max_ps, _mm256_min_ps,
        _mm256_mul_ps, _mm256_set1_epi32, _mm256_set1_ps, _mm256_setzero_ps,
    };
    // SAFETY: the caller runs on a CPU with AVX2.
    unsafe {
        let c = _mm256_min_ps(_mm256_max_ps(c, _mm256_setzero_ps()), _mm256_set1_ps(1.0));
        let t = _mm256_add_ps(
            _mm256_mul_ps(c, _mm256_set1_ps(255.0 / 256.0)),
            _mm256_set1_ps(32768.0),
        );
        _mm256_and_si256(_mm256_castps_si256(t), _mm256_set1_epi32(0xFF))
    }
}

/// `x`, `x` + 1, ... as floats, one a lane: the same values as `(x + l) as f32`, since every
/// integer involved is far below 2^24 (window offsets are at most 16384) and so exact.
#[inline(always)]
pub(super) fn lane_x(x: i32) -> [f32; LANES] {
    const IOTA: [f32; LANES] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
    let b = x as f32;
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_add_ps, _mm_loadu_ps, _mm_set1_ps};
        // SAFETY: SSE is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from a
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128` has the
        // layout of `[f32; 4]` and every bit pattern is valid for both. (LLVM kept the
        // `map` below as eight scalar additions.)
        unsafe {
            let bv = _mm_set1_ps(b);
            let lo = _mm_add_ps(bv, _mm_loadu_ps(IOTA.as_ptr()));
            let hi = _mm_add_ps(bv, _mm_loadu_ps(IOTA.as_ptr().add(4)));
            let lo = std::mem::transmute::<__m128, [f32; 4]>(lo);
            let hi = std::mem::transmute::<__m128, [f32; 4]>(hi);
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        IOTA.map(|l| b + l)
    }
}

/// `1.0 / d` on every lane. LLVM keeps this division scalar (its cost model for SSE2); the
/// SSE2 `divps` of the x86-64 baseline gives the same correctly rounded quotients four at a
/// time.
#[inline(always)]
pub(super) fn recip(d: [f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_div_ps, _mm_set1_ps, _mm_set_ps};
        // SAFETY: SSE is part of the x86-64 baseline, so these intrinsics are available on
        // every x86-64 CPU; `__m128` is four f32 lanes in memory order, the layout of
        // `[f32; 4]`, and every bit pattern is valid for both.
        let (lo, hi) = unsafe {
            let one = _mm_set1_ps(1.0);
            let lo = _mm_div_ps(one, _mm_set_ps(d[3], d[2], d[1], d[0]));
            let hi = _mm_div_ps(one, _mm_set_ps(d[7], d[6], d[5], d[4]));
            (
                std::mem::transmute::<__m128, [f32; 4]>(lo),
                std::mem::transmute::<__m128, [f32; 4]>(hi),
            )
        };
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        d.map(|d| 1.0 / d)
    }
}

/// `framebuffer::unorm8` on every lane: NaN and negative to 0, above 1 to 1, then
/// `c·(255/256) + 2^15`, whose low mantissa byte is the result. On x86-64 with SSE2's
/// `maxps`/`minps` (a NaN or −0 gives +0, whose result is the same byte 0 as the scalar
/// `-0.0`), `mulps`, `addps`, a mask and two packs; LLVM kept the scalar form's selects and
/// narrowing per lane (≈8 instructions a value, 6% of the fog scene).
#[inline(always)]
pub(super) fn unorm8_lanes(c: [f32; LANES]) -> [u8; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            _mm_add_ps, _mm_and_si128, _mm_castps_si128, _mm_loadu_ps, _mm_max_ps, _mm_min_ps,
            _mm_mul_ps, _mm_packs_epi32, _mm_packus_epi16, _mm_set1_epi32, _mm_set1_ps,
            _mm_setzero_ps,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from a
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128i` has the
        // layout of `[u8; 16]` and every bit pattern is valid for both.
        unsafe {
            let (zero, one) = (_mm_setzero_ps(), _mm_set1_ps(1.0));
            let (k, b) = (_mm_set1_ps(255.0 / 256.0), _mm_set1_ps(32768.0));
            let low = _mm_set1_epi32(0xFF);
            let conv = |p: *const f32| {
                let c = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(p), zero), one);
                _mm_and_si128(_mm_castps_si128(_mm_add_ps(_mm_mul_ps(c, k), b)), low)
            };
            let (lo, hi) = (conv(c.as_ptr()), conv(c.as_ptr().add(4)));
            // Every value is in 0..=255: the signed packs keep it.
            let w = _mm_packs_epi32(lo, hi);
            low8(_mm_packus_epi16(w, w))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let mut out = [0u8; LANES];
        for (o, c) in out.iter_mut().zip(c) {
            // `!(c >= 0)` is true for NaN as for negatives: both give 0, as `unorm8` does.
            let c = if c >= 0.0 { c } else { 0.0 };
            let c = if c > 1.0 { 1.0 } else { c };
            let t = c * (255.0 / 256.0) + 32768.0;
            *o = (t.to_bits() & 0xFF) as u8;
        }
        out
    }
}

/// The low eight bytes of `x` (one `movq` store; taking them from a `[u8; 16]` made LLVM
/// assemble the array byte by byte through general registers).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn low8(x: std::arch::x86_64::__m128i) -> [u8; LANES] {
    let mut o = [0u8; LANES];
    // SAFETY: SSE2 is part of the x86-64 baseline; the 8-byte store writes exactly `o`'s
    // eight bytes (no alignment needed).
    unsafe { std::arch::x86_64::_mm_storel_epi64(o.as_mut_ptr().cast(), x) };
    o
}

/// The smooth primary colour of a span (the fast path of `FragCtx::tri_span`): for fragment k,
/// fx = `fx0` + k and colour channel c = (`co[2+2c]` + `co[3+2c]`·fx) · 1/(`co[0]` + `co[1]`·fx),
/// the row's terms already in `co[0]`, `co[2]`, ... Stores the unorm8 colour of every fragment
/// whose bit is set in `mask` into `dst[k]`.
pub fn smooth_rgba(dst: &mut [[u8; 4]], mask: u64, fx0: i32, co: &[f32; 10]) {
    let [w0, wx, r0, rx, g0, gx, b0, bx, a0, ax] = *co;
    let mut c = 0;
    while c < dst.len().min(64) {
        let m = (mask >> c) & ((1 << LANES) - 1);
        if m != 0 {
            let fx = lane_x(fx0.wrapping_add(c as i32));
            let inv = recip(lin_lanes(w0, wx, &fx));
            let ch = |o: f32, d: f32| -> [u8; LANES] {
                unorm8_lanes(mul_lanes(&lin_lanes(o, d, &fx), &inv))
            };
            let (r, g, b, a) = (ch(r0, rx), ch(g0, gx), ch(b0, bx), ch(a0, ax));
            if let Some(out) = dst.get_mut(c..) {
                put(out, m as u8, &[r, g, b, a]);
            }
        }
        c += LANES;
    }
}

/// The one colour of every fragment of `flat_rgba`'s spans when its planes `co` are those setup
/// gives a FLAT varying, (value, ±0, ±0) in each channel; None when a step is nonzero.
/// (o + 0·fx) + 0·fy is o for any finite fx and fy (fragment positions are) unless o is ±0,
/// where it is ±0 — the same byte, 0, either way; a NaN stays NaN. So fragment (`fx0`, `fy`)'s
/// bytes are every fragment's, whatever its position: `FragCtx::const_rows` takes them once
/// per primitive (at 0, 0). The four channels share one conversion, a lane each (the lanes
/// are independent: each byte is the one `unorm8_lanes` gives that value alone; four
/// conversions of a broadcast value were ≈60 instructions a span in transforms).
#[inline(always)]
pub fn flat_px(co: &[f32; 12], fx0: i32, fy: f32) -> Option<[u8; 4]> {
    if !(0..4).all(|c| co[3 * c + 1] == 0.0 && co[3 * c + 2] == 0.0) {
        return None;
    }
    let v: [f32; 4] =
        std::array::from_fn(|c| (co[3 * c] + co[3 * c + 1] * fx0 as f32) + co[3 * c + 2] * fy);
    let b = unorm8_lanes([v[0], v[1], v[2], v[3], 0.0, 0.0, 0.0, 0.0]);
    Some([b[0], b[1], b[2], b[3]])
}

/// The flat primary colour of a span (`FragCtx::tri_span` with FLAT shading and no other
/// varying): channel c of fragment k is (`co[3c]` + `co[3c+1]`·fx) + `co[3c+2]`·fy with fx =
/// `fx0` + k, not divided by w (the general path's expression for a flat varying). Stores the
/// unorm8 colour of every fragment whose bit is set in `mask` into `dst[k]`.
pub fn flat_rgba(dst: &mut [[u8; 4]], mask: u64, fx0: i32, fy: f32, co: &[f32; 12]) {
    if let Some(px) = flat_px(co, fx0, fy) {
        // Every fragment has the same colour: the first fragment's bytes, stored in runs.
        let n = dst.len().min(64);
        let mut m = mask & (u64::MAX >> (64 - n.max(1)));
        if n == 0 {
            m = 0;
        }
        while m != 0 {
            let s = m.trailing_zeros() as usize;
            let run = (!(m >> s)).trailing_zeros() as usize;
            if let Some(out) = dst.get_mut(s..s + run) {
                out.fill(px);
            }
            m &= !(u64::MAX >> (64 - run) << s);
        }
        return;
    }
    // `pl(o + 2) * fy` is the same product for every fragment of the row.
    let ch: [(f32, f32, f32); 4] =
        std::array::from_fn(|c| (co[3 * c], co[3 * c + 1], co[3 * c + 2] * fy));
    let mut c = 0;
    while c < dst.len().min(64) {
        let m = (mask >> c) & ((1 << LANES) - 1);
        if m != 0 {
            let fx = lane_x(fx0.wrapping_add(c as i32));
            let v = ch.map(|(o, dx, yt)| unorm8_lanes(fx.map(|x| (o + dx * x) + yt)));
            if let Some(out) = dst.get_mut(c..) {
                for (l, px) in out.iter_mut().take(LANES).enumerate() {
                    if m & (1 << l) != 0 {
                        *px = [v[0][l], v[1][l], v[2][l], v[3][l]];
                    }
                }
            }
        }
        c += LANES;
    }
}

/// `framebuffer::depth_unorm(f64::from(z))` on every lane (a NaN gives 0, as there). On
/// x86-64 two lanes a step with SSE2's `cvtps2pd`, `maxpd` with 0 (a NaN or −0 gives +0, whose
/// result 0.5 truncates to 0 as the scalar NaN and −0 do), `minpd` with 1, `mulpd`, `addpd`
/// and the truncating `cvttpd2dq` (every value is in [0.5, DEPTH_MAX + 0.5] < 2^31).
#[inline(always)]
pub(super) fn depth_lanes(z: [f32; LANES]) -> [u32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128i, _mm_add_pd, _mm_cvtps_pd, _mm_cvttpd_epi32, _mm_loadu_ps, _mm_max_pd,
            _mm_min_pd, _mm_movehl_ps, _mm_mul_pd, _mm_set1_pd, _mm_setzero_pd, _mm_unpacklo_epi64,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from a
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128i` has the
        // layout of `[u32; 4]` and every bit pattern is valid for both.
        unsafe {
            let (zero, one) = (_mm_setzero_pd(), _mm_set1_pd(1.0));
            let (k, h) = (_mm_set1_pd(f64::from(DEPTH_MAX)), _mm_set1_pd(0.5));
            let conv = |z| {
                let z = _mm_min_pd(_mm_max_pd(z, zero), one);
                _mm_cvttpd_epi32(_mm_add_pd(_mm_mul_pd(z, k), h))
            };
            let four = |p: *const f32| {
                let z = _mm_loadu_ps(p);
                let lo = conv(_mm_cvtps_pd(z));
                let hi = conv(_mm_cvtps_pd(_mm_movehl_ps(z, z)));
                std::mem::transmute::<__m128i, [u32; 4]>(_mm_unpacklo_epi64(lo, hi))
            };
            let (lo, hi) = (four(z.as_ptr()), four(z.as_ptr().add(4)));
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let mut out = [0u32; LANES];
        for (o, z) in out.iter_mut().zip(z) {
            let z = f64::from(z);
            // `clamp` keeps a NaN, which the final cast turns into 0; so do these comparisons.
            let z = if z < 0.0 { 0.0 } else { z };
            let z = if z > 1.0 { 1.0 } else { z };
            // At most DEPTH_MAX + 0.5 < 2^31: the i32 cast gives what `as u32` gives.
            *o = (z * f64::from(DEPTH_MAX) + 0.5) as i32 as u32;
        }
        out
    }
}

/// The depth test and write of a span (`FragCtx::depth_mask_span`): fragment k (bit k of
/// `live`, k < `n` ≤ 64, `n` ≤ `row.len()`) has z = `zrow` + `dz`·(`fx0` + k) in single
/// precision; it survives when `d func stored` (DepthFunc `func`), and then `d` is stored if
/// `write`. Returns the survivors' mask. Each group of eight goes through
/// `oplanes::depth_test` (SSE2 compares and a select when eight values of `row` follow; `row`
/// may run past the span, and its values outside `live` are kept).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn depth_span(
    row: &mut [u32],
    n: usize,
    zrow: f32,
    dz: f32,
    fx0: i32,
    live: u64,
    write: bool,
    func: u32,
) -> u64 {
    live_groups(row, n, live, |out, c, m| {
        let fx = lane_x(fx0.wrapping_add(c as i32));
        let d = depth_lanes(lin_lanes(zrow, dz, &fx));
        super::oplanes::depth_test(func, write, out, d, m)
    })
}

/// The group loop of `depth_span` and `depth_groups_avx2`: for each group of eight of the
/// first `n` (≤ 64) pixels of `row` with a lane in `live`, `group(row from the group's first
/// pixel, its offset c, its live lanes)` returns the group's survivors, gathered into the
/// span's mask.
#[inline(always)]
fn live_groups(
    row: &mut [u32],
    n: usize,
    live: u64,
    mut group: impl FnMut(&mut [u32], usize, u8) -> u8,
) -> u64 {
    let n = n.min(64).min(row.len());
    let mut mask = 0u64;
    let mut c = 0;
    while c < n {
        let m = ((live >> c) & ((1 << LANES) - 1)) as u8;
        if m != 0 {
            if let Some(out) = row.get_mut(c..) {
                mask |= u64::from(group(out, c, m)) << c;
            }
        }
        c += LANES;
    }
    mask
}

/// `depth_span` with eight lanes a register (AVX2): each group through
/// `oplanes::avx2::depth_test` (the same lane x, `zrow + dz·x`, double-precision conversion,
/// unsigned compare and select as `depth_lanes` and `oplanes::depth_test`, so the same mask and
/// stores), the compare compiled in for the common states — LESS or LEQUAL with the depth mask
/// on — rather than chosen by a jump per group.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn depth_span_avx2(
    row: &mut [u32],
    n: usize,
    zrow: f32,
    dz: f32,
    fx0: i32,
    live: u64,
    write: bool,
    func: u32,
) -> u64 {
    use crate::gl::{LEQUAL, LESS};
    let a = (row, n, zrow, dz, fx0, live);
    // SAFETY: the CPU has AVX2 (this function's contract).
    unsafe {
        match (func, write) {
            (LESS, true) => depth_groups_avx2::<LESS>(a, func, write, |_, _| {}),
            (LEQUAL, true) => depth_groups_avx2::<LEQUAL>(a, func, write, |_, _| {}),
            _ => depth_groups_avx2::<0>(a, func, write, |_, _| {}),
        }
    }
}

/// The groups of `depth_span_avx2` (`a`: its row, pixel count, depth terms, lane x and live
/// lanes); `F` other than 0 is DepthFunc known for the call with the depth mask on (`func` and
/// `write` then not read). `then(c, m)` runs after each tested group, with its first pixel's
/// offset and its survivors (`FragCtx::const_rows`' flat colour; nothing for `depth_span`).
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn depth_groups_avx2<const F: u32>(
    (row, n, zrow, dz, fx0, live): (&mut [u32], usize, f32, f32, i32, u64),
    func: u32,
    write: bool,
    mut then: impl FnMut(usize, u8),
) -> u64 {
    let (func, write) = if F != 0 { (F, true) } else { (func, write) };
    live_groups(row, n, live, |out, c, m| {
        let fx = fx0.wrapping_add(c as i32);
        // SAFETY: the CPU has AVX2.
        let m = unsafe { super::oplanes::avx2::depth_test(func, write, out, zrow, dz, fx, m) };
        then(c, m);
        m
    })
}

/// Lanes `m` of the eight pixels of `dst` from index `c` set to `px` (one `vpmaskmovd` when
/// eight pixels follow, else lane by lane), the others left as they are: what `flat_rgba`
/// stores for a group of a FLAT span whose colour is `px` (`flat_px`).
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn flat_group_avx2(dst: &mut [[u8; 4]], c: usize, m: u8, px: [u8; 4]) {
    use std::arch::x86_64::{
        _mm256_maskstore_epi32, _mm256_set1_epi32, _mm256_setr_epi32, _mm256_sllv_epi32,
    };
    if m == 0 {
        return;
    }
    if let Some(g) = dst.get_mut(c..c.wrapping_add(LANES)) {
        // SAFETY: the CPU has AVX2 (this function's contract); `g` holds eight `[u8; 4]`, 32
        // contiguous bytes, each lane's four bytes an i32 (no alignment needed); lane l's
        // mask is bit l of `m` moved to its sign bit.
        unsafe {
            let sel = _mm256_sllv_epi32(
                _mm256_set1_epi32(i32::from(m)),
                _mm256_setr_epi32(31, 30, 29, 28, 27, 26, 25, 24),
            );
            let v = _mm256_set1_epi32(i32::from_le_bytes(px));
            _mm256_maskstore_epi32(g.as_mut_ptr().cast::<i32>(), sel, v);
        }
        return;
    }
    let rest = dst.get_mut(c..).unwrap_or_default();
    for (l, d) in rest.iter_mut().enumerate().take(LANES) {
        if m & (1 << l) != 0 {
            *d = px;
        }
    }
}

/// The depth test and the smooth primary colour of a span in one pass (`FragCtx::smooth_row`,
/// the route of a triangle that `tri_span`'s fast path with `depth_mask_span` and
/// `smooth_rgba` would take): fragment k < `n` (≤ 64) has fx = `fx0` + k, z = `zrow` +
/// `dz`·fx and colour channel c = (`co[2+2c]` + `co[3+2c]`·fx) · 1/(`co[0]` + `co[1]`·fx).
/// With `test` = (DepthFunc, DepthMask) each group of eight goes through
/// `oplanes::depth_test` on `depth` from the group's first pixel; the survivors' colours are
/// stored into `color` (whole groups when eight pixels follow: the rows run on to the tile's
/// end, and the lanes outside the mask are stored back unchanged). Returns the survivors'
/// mask. The same values, tests and stores as `depth_span` then `smooth_rgba`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn smooth_depth_span(
    color: &mut [[u8; 4]],
    depth: &mut [u32],
    n: usize,
    fx0: i32,
    zrow: f32,
    dz: f32,
    test: Option<(u32, bool)>,
    co: &[f32; 10],
) -> u64 {
    let n = n.min(64);
    let mut out = 0u64;
    let mut c = 0;
    while c < n {
        let left = n - c;
        let mut m: u8 = if left >= LANES {
            0xFF
        } else {
            (1u8 << left) - 1
        };
        let fx = lane_x(fx0.wrapping_add(c as i32));
        if let Some((func, write)) = test {
            let d = depth_lanes(lin_lanes(zrow, dz, &fx));
            let row = depth.get_mut(c..).unwrap_or_default();
            m = super::oplanes::depth_test(func, write, row, d, m);
        }
        if m != 0 {
            smooth_group(color.get_mut(c..).unwrap_or_default(), m, &fx, co);
            out |= u64::from(m) << c;
        }
        c += LANES;
    }
    out
}

/// One group of `smooth_depth_span`: the colours of lanes `m` at `fx` into `dst[l]`. On x86-64
/// the arithmetic of `smooth_rgba` (`mulps`, `addps`, `divps`, `mul_lanes`' product order) and
/// `unorm8_lanes`' conversion stay in registers, the four channels are assembled pixel-major
/// (`r | g << 8 | b << 16 | a << 24`, as `oplanes::store_unorm8`) and a whole group is
/// selected and stored at once; a shorter `dst` takes the lanes one by one.
#[inline(always)]
fn smooth_group(dst: &mut [[u8; 4]], m: u8, fx: &[f32; LANES], co: &[f32; 10]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128, __m128i, _mm_add_ps, _mm_and_si128, _mm_andnot_si128, _mm_castps_si128,
            _mm_cmpeq_epi32, _mm_div_ps, _mm_loadu_ps, _mm_loadu_si128, _mm_max_ps, _mm_min_ps,
            _mm_mul_ps, _mm_or_si128, _mm_set1_epi32, _mm_set1_ps, _mm_set_epi32, _mm_setzero_ps,
            _mm_slli_epi32, _mm_storeu_si128,
        };
        let [w0, wx, r0, rx, g0, gx, b0, bx, a0, ax] = *co;
        // SAFETY: SSE2 is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 of the
        // `[f32; 8]` `fx` at offsets 0 and 4; `px` below holds eight `[u8; 4]`, 32 contiguous
        // bytes, read and written 16 bytes at offsets 0 and 16 (no alignment needed);
        // `__m128i` has the layout of `[u32; 4]` and every bit pattern is valid for both.
        unsafe {
            let (zero, one) = (_mm_setzero_ps(), _mm_set1_ps(1.0));
            let (k, b) = (_mm_set1_ps(255.0 / 256.0), _mm_set1_ps(32768.0));
            let low = _mm_set1_epi32(0xFF);
            let lin = |o: f32, d: f32, x: __m128| {
                _mm_add_ps(_mm_set1_ps(o), _mm_mul_ps(_mm_set1_ps(d), x))
            };
            let conv = |c: __m128| {
                let c = _mm_min_ps(_mm_max_ps(c, zero), one);
                _mm_and_si128(_mm_castps_si128(_mm_add_ps(_mm_mul_ps(c, k), b)), low)
            };
            let half = |x: __m128| -> __m128i {
                let inv = _mm_div_ps(one, lin(w0, wx, x));
                let ch = |o: f32, d: f32| conv(_mm_mul_ps(lin(o, d, x), inv));
                _mm_or_si128(
                    _mm_or_si128(ch(r0, rx), _mm_slli_epi32::<8>(ch(g0, gx))),
                    _mm_or_si128(
                        _mm_slli_epi32::<16>(ch(b0, bx)),
                        _mm_slli_epi32::<24>(ch(a0, ax)),
                    ),
                )
            };
            let v = [
                half(_mm_loadu_ps(fx.as_ptr())),
                half(_mm_loadu_ps(fx.as_ptr().add(4))),
            ];
            if let Some(px) = dst.get_mut(..LANES) {
                let bits = _mm_set_epi32(8, 4, 2, 1);
                let p = px.as_mut_ptr().cast::<__m128i>();
                for (h, v) in v.into_iter().enumerate() {
                    let lv = _mm_set1_epi32(i32::from(m >> (4 * h)));
                    let sel = _mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits);
                    let old = _mm_loadu_si128(p.add(h));
                    let out = _mm_or_si128(_mm_andnot_si128(sel, old), _mm_and_si128(sel, v));
                    _mm_storeu_si128(p.add(h), out);
                }
                return;
            }
            let v = std::mem::transmute::<[__m128i; 2], [u32; LANES]>(v);
            for (l, px) in dst.iter_mut().take(LANES).enumerate() {
                if m & (1 << l) != 0 {
                    *px = v[l].to_le_bytes();
                }
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let [w0, wx, r0, rx, g0, gx, b0, bx, a0, ax] = *co;
        let inv = recip(lin_lanes(w0, wx, fx));
        let ch = |o: f32, d: f32| unorm8_lanes(mul_lanes(&lin_lanes(o, d, fx), &inv));
        put(dst, m, &[ch(r0, rx), ch(g0, gx), ch(b0, bx), ch(a0, ax)]);
    }
}

/// Whether the AVX2 routes may run (`smooth_depth_span_avx2`, `FragCtx::smooth_rows_avx2`,
/// the sampler's eight-lane dense kernels):
/// the CPU has AVX2 and POPCNT (std caches the detection).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn has_avx2() -> bool {
    #[cfg(test)]
    if NO_AVX2.with(|c| c.get()) {
        return false;
    }
    is_x86_feature_detected!("avx2") && is_x86_feature_detected!("popcnt")
}

#[cfg(all(test, target_arch = "x86_64"))]
thread_local! {
    /// Tests: the AVX2 routes turned off on this thread (`has_avx2` false), to compare the
    /// SSE2 routes with them.
    pub(super) static NO_AVX2: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// The planes of a primitive's smooth rows for `smooth_depth_span_avx2`, one lane each for
/// depth, 1/w, red, green, blue and alpha (the last two lanes 0): a row's terms are
/// `base + ystep·fy` ([`SmoothPlanes8::row`], each lane the scalar `a + dy·fy` of
/// `FragCtx::smooth_row`), its x steps `dx`.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct SmoothPlanes8 {
    /// The constants.
    pub base: [f32; LANES],
    /// The y steps.
    pub ystep: [f32; LANES],
    /// The x steps, `smooth_depth_span_avx2`'s `dx`.
    pub dx: [f32; LANES],
}

impl SmoothPlanes8 {
    /// From the depth plane `z` (constant, x step, y step, as `RPrim::z`) and the smooth
    /// planes `pl` (1/w, r, g, b, a, each constant, x step, y step).
    pub fn new(z: &[f32; 3], pl: &[f32; 15]) -> Self {
        let lane = |i: usize, k: usize| match i {
            0 => z[k],
            1..=5 => pl[(i - 1) * 3 + k],
            _ => 0.0,
        };
        SmoothPlanes8 {
            base: std::array::from_fn(|i| lane(i, 0)),
            ystep: std::array::from_fn(|i| lane(i, 2)),
            dx: std::array::from_fn(|i| lane(i, 1)),
        }
    }

    /// The terms of row `fy`: `base + ystep·fy` on every lane (`vmulps`, `vaddps`: the
    /// scalar expression's rounding, no FMA).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub unsafe fn row(&self, fy: f32) -> [f32; LANES] {
        use std::arch::x86_64::{
            __m256, _mm256_add_ps, _mm256_loadu_ps, _mm256_mul_ps, _mm256_set1_ps,
        };
        // SAFETY: `base` and `ystep` hold eight f32, 32 bytes (no alignment needed); `__m256`
        // has the layout of `[f32; 8]`, every bit pattern valid for both.
        unsafe {
            let (b, y) = (
                _mm256_loadu_ps(self.base.as_ptr()),
                _mm256_loadu_ps(self.ystep.as_ptr()),
            );
            let v = _mm256_add_ps(b, _mm256_mul_ps(y, _mm256_set1_ps(fy)));
            std::mem::transmute::<__m256, [f32; LANES]>(v)
        }
    }
}

/// `smooth_depth_span` with eight lanes a register (AVX2): the same operations in the same
/// order on each lane — `lane_x`'s `(fx0 + c) as f32 + l`, `lin_lanes`' `zrow + dz·x`,
/// `depth_lanes`' clamp, scale, bias and truncation in double precision and `depth_group`'s
/// unsigned compare and select (both `oplanes::avx2::depth_test`), `smooth_group`'s
/// `addps`/`mulps`/`divps` and `unorm8` conversion, assembled pixel-major and stored as a
/// whole group (unwritten lanes stored back unchanged) — so the same bits.
///
/// The span starts at index `base` of `color` and `depth` (`smooth_depth_span`'s rows are
/// their tails from there). The row's terms `o` and x steps `dx` are those of depth, 1/w,
/// red, green, blue and alpha (`SmoothPlanes8`): `o[0]`, `dx[0]` are `smooth_depth_span`'s
/// `zrow`, `dz`, the others its `co` in pairs.
///
/// `F` other than 0 is the depth test known for the whole call: on, DepthFunc `F`, the
/// depth mask true (`test` is then not read), so each group's compare is chosen when the
/// function is compiled rather than by a jump per group. The groups run over the rows
/// rounded up to whole groups, the lanes past `n` masked, a span of one group without a
/// loop (most spans of a dense mesh's triangles); a row whose last group would run
/// past the end of `color` or `depth` (a tile's last pixels) goes through a copy of its
/// pixels, the lanes past a shorter depth row failing the test and those past a shorter
/// colour row not written, as the per-lane code does.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn smooth_depth_span_avx2<const F: u32>(
    color: &mut [[u8; 4]],
    depth: &mut [u32],
    base: usize,
    n: usize,
    fx0: i32,
    o: &[f32; LANES],
    dx: &[f32; LANES],
    test: Option<(u32, bool)>,
) -> u64 {
    let test = if F != 0 { Some((F, true)) } else { test };
    let n = n.min(64);
    let live = u64::MAX.checked_shr(64 - n as u32).unwrap_or(0);
    let n8 = n.next_multiple_of(LANES);
    let end = base.wrapping_add(n8);
    if let (Some(c), Some(d)) = (color.get_mut(base..end), depth.get_mut(base..end)) {
        // SAFETY: the CPU has AVX2 (this function's contract).
        return unsafe {
            if n8 == LANES {
                // One group (most spans of a dense mesh): no loop.
                u64::from(smooth_group_depth_avx2(c, d, live as u8, fx0, o, dx, test))
            } else {
                smooth_groups_avx2(c, d, live, fx0, o, dx, test)
            }
        };
    }
    let color = color.get_mut(base..).unwrap_or_default();
    let depth = depth.get_mut(base..).unwrap_or_default();
    let (mut cb, mut db) = ([[0u8; 4]; 64], [0u32; 64]);
    for (b, c) in cb.iter_mut().zip(color.iter()).take(n) {
        *b = *c;
    }
    for (b, d) in db.iter_mut().zip(depth.iter()).take(n) {
        *b = *d;
    }
    let live = match test {
        Some(_) => {
            live & u64::MAX
                .checked_shr(64 - depth.len().min(64) as u32)
                .unwrap_or(0)
        }
        None => live,
    };
    let (c8, d8) = (
        cb.get_mut(..n8).unwrap_or_default(),
        db.get_mut(..n8).unwrap_or_default(),
    );
    // SAFETY: as above.
    let out = unsafe { smooth_groups_avx2(c8, d8, live, fx0, o, dx, test) };
    for (c, b) in color.iter_mut().zip(cb.iter()).take(n) {
        *c = *b;
    }
    for (d, b) in depth.iter_mut().zip(db.iter()).take(n) {
        *d = *b;
    }
    out
}

/// The groups of `smooth_depth_span_avx2`: `color` and `depth` of the same whole number of
/// groups, the lanes `live` (bit k for pixel k) taking part.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::too_many_arguments)]
unsafe fn smooth_groups_avx2(
    color: &mut [[u8; 4]],
    depth: &mut [u32],
    live: u64,
    fx0: i32,
    o: &[f32; LANES],
    dx: &[f32; LANES],
    test: Option<(u32, bool)>,
) -> u64 {
    let mut out = 0u64;
    // The lanes of the groups still to come (the next group's eight in the low bits), the
    // next group's first pixel and its lane x.
    let (mut rest, mut c, mut fxc) = (live, 0u32, fx0);
    let groups = color
        .chunks_exact_mut(LANES)
        .zip(depth.chunks_exact_mut(LANES));
    for (px, row) in groups.take(64 / LANES) {
        // SAFETY: the CPU has AVX2.
        let m = unsafe { smooth_group_depth_avx2(px, row, rest as u8, fxc, o, dx, test) };
        out |= u64::from(m) << c;
        rest >>= LANES;
        c += LANES as u32;
        fxc = fxc.wrapping_add(LANES as i32);
    }
    out
}

/// One group of `smooth_groups_avx2` (`row` and `px` eight long): the depth test of lanes
/// `m` (`oplanes::avx2::depth_test`, where `test` is on), then the colours of its survivors
/// (`smooth_group_avx2`); the survivors' mask.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn smooth_group_depth_avx2(
    px: &mut [[u8; 4]],
    row: &mut [u32],
    m: u8,
    fxc: i32,
    o: &[f32; LANES],
    dx: &[f32; LANES],
    test: Option<(u32, bool)>,
) -> u8 {
    let mut m = m;
    if let Some((func, write)) = test {
        // SAFETY: the CPU has AVX2.
        m = unsafe { super::oplanes::avx2::depth_test(func, write, row, o[0], dx[0], fxc, m) };
    }
    if m != 0 {
        // SAFETY: as above.
        unsafe { smooth_group_avx2(px, m, fxc, o, dx) };
    }
    m
}

/// One group of `smooth_groups_avx2`: the colours of lanes `m` (lane x `fxc as f32 + l`)
/// selected into the eight pixels of `px` (a shorter `px` is left as it is).
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn smooth_group_avx2(
    px: &mut [[u8; 4]],
    m: u8,
    fxc: i32,
    o: &[f32; LANES],
    dx: &[f32; LANES],
) {
    use std::arch::x86_64::{
        __m256, __m256i, _mm256_add_ps, _mm256_and_si256, _mm256_andnot_si256, _mm256_div_ps,
        _mm256_loadu_si256, _mm256_mul_ps, _mm256_or_si256, _mm256_set1_ps, _mm256_setr_ps,
        _mm256_slli_epi32, _mm256_storeu_si256,
    };
    let Some(px) = px.get_mut(..LANES) else {
        return;
    };
    let [_, w0, r0, g0, b0, a0, ..] = *o;
    let [_, wx, rx, gx, bx, ax, ..] = *dx;
    let iota = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
    let one = _mm256_set1_ps(1.0);
    // `o + d·x` on every lane.
    macro_rules! lin {
        ($o:expr, $d:expr, $x:expr) => {
            _mm256_add_ps(_mm256_set1_ps($o), _mm256_mul_ps(_mm256_set1_ps($d), $x))
        };
    }
    let fx: __m256 = _mm256_add_ps(_mm256_set1_ps(fxc as f32), iota);
    let inv = _mm256_div_ps(one, lin!(w0, wx, fx));
    macro_rules! ch {
        ($o:expr, $d:expr) => {
            unorm8_bits8(_mm256_mul_ps(lin!($o, $d, fx), inv))
        };
    }
    let v = _mm256_or_si256(
        _mm256_or_si256(ch!(r0, rx), _mm256_slli_epi32::<8>(ch!(g0, gx))),
        _mm256_or_si256(
            _mm256_slli_epi32::<16>(ch!(b0, bx)),
            _mm256_slli_epi32::<24>(ch!(a0, ax)),
        ),
    );
    let sel = lane_mask8(m);
    let p = px.as_mut_ptr().cast::<__m256i>();
    // SAFETY: `px` holds eight `[u8; 4]`, 32 contiguous bytes (no alignment needed).
    unsafe {
        let old = _mm256_loadu_si256(p);
        let o = _mm256_or_si256(_mm256_andnot_si256(sel, old), _mm256_and_si256(sel, v));
        _mm256_storeu_si256(p, o);
    }
}

/// The covered pixels of a triangle whose covered pixels setup found (`RPrim::cover`, a
/// bounding box of at most 2x2 pixels inside the tile), each through the depth test alone:
/// bit `2·row + column` of `cover` is the pixel at tile index `at + row·TILE + column` (row
/// and column relative to the bounding box's corner, the planes' origin, so its `fy` and `fx`
/// are 0 or 1, which `(y − oy) as f32` and `(fxc as f32) + l` are exactly). `z(k)` gives
/// pixel k's depth in the low lane and what its colour needs; the depth is converted as
/// `oplanes::avx2::depth_test` converts a lane (`maxsd`, `minsd` with `maxpd`'s and
/// `minpd`'s operand order, so NaN clamps alike; scale, bias, truncation) and tested with
/// `F` (LEQUAL, or else LESS; the depth mask true); a survivor's depth is stored and
/// `hit(index, what z gave)` stores its colour. Returns the bits of `cover` that passed.
///
/// Design decision: an eight-lane group spent on a dense mesh's triangle (one or two
/// fragments) computed eight of everything and loaded, selected and stored eight pixels of
/// each buffer; here each covered pixel is computed alone, with each value's operations those
/// of its lane in the group route in the same order, so the same bits.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn tiny_pixels<const F: u32, T>(
    depth: &mut [u32],
    at: usize,
    cover: u8,
    mut z: impl FnMut(usize) -> (std::arch::x86_64::__m128, T),
    mut hit: impl FnMut(usize, T),
) -> u8 {
    use std::arch::x86_64::{
        _mm_add_sd, _mm_cvtss_sd, _mm_cvttsd_si32, _mm_max_sd, _mm_min_sd, _mm_mul_sd, _mm_set_sd,
        _mm_setzero_pd,
    };
    let (zero, one) = (_mm_setzero_pd(), _mm_set_sd(1.0));
    let (kd, hd) = (_mm_set_sd(f64::from(DEPTH_MAX)), _mm_set_sd(0.5));
    let mut pass = 0u8;
    let mut rest = cover & 15;
    while rest != 0 {
        let k = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        let i = at + TINY_AT[k & 3];
        let Some(d) = depth.get_mut(i) else {
            continue;
        };
        let (zk, then) = z(k);
        // `depth4!`: clamp, scale, bias, truncate.
        let zc = _mm_min_sd(_mm_max_sd(_mm_cvtss_sd(zero, zk), zero), one);
        let dz = _mm_cvttsd_si32(_mm_add_sd(_mm_mul_sd(zc, kd), hd)) as u32;
        let ok = match F {
            crate::gl::LEQUAL => dz <= *d,
            _ => dz < *d,
        };
        if ok {
            *d = dz;
            pass |= 1 << k;
            hit(i, then);
        }
    }
    pass
}

/// A covered bit's offset from the box's corner in the tile (`tiny_pixels`). A static, read
/// from memory: the same table written inside the loop was stored to the stack from a
/// register for every pixel before its one element was read back.
#[cfg(target_arch = "x86_64")]
static TINY_AT: [usize; 4] = [0, 1, super::framebuffer::TILE, super::framebuffer::TILE + 1];

/// A covered bit's column and row (`fx`, `fy`: `tiny_pixels`).
#[cfg(target_arch = "x86_64")]
const TINY_FX: [f32; 4] = [0.0, 1.0, 0.0, 1.0];
#[cfg(target_arch = "x86_64")]
const TINY_FY: [f32; 4] = [0.0, 0.0, 1.0, 1.0];

/// What `tiny_avx2` stores for a triangle's surviving pixels.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(super) enum TinyFill<'a> {
    /// The smooth colour of its planes (1/w, r, g, b, a: `SmoothPlanes8::new`'s `pl`), as
    /// `smooth_depth_span_avx2` computes it.
    Smooth(&'a [f32; 15]),
    /// One colour (a FLAT triangle's, `flat_px`), as `FragCtx::const_rows` stores it.
    Flat([u8; 4]),
}

/// The depth test and colour `fill` of a triangle's covered pixels (`tiny_pixels`: `cover`,
/// `at`, `F`), its depth plane `z`.
///
/// `Smooth`: `smooth_depth_span_avx2` of each pixel, the lanes the planes instead of the
/// pixels — red, green, blue, alpha, depth, 1/w (`SmoothPlanes8`'s in another order, the
/// colours in the low half so that a pixel's four are one 128-bit register) — each pixel one
/// `base + ystep·fy` (`SmoothPlanes8::row`) and one `+ dx·fx` (`smooth_group_avx2`'s `lin!`)
/// for all six, then one `divss` for its 1/w and `unorm8_bits8`'s clamp, scale and bias on its
/// four colours: each lane's operations in the group route's order (`vmulps`, `vaddps`, no
/// FMA), so the same bits.
///
/// `Flat`: each pixel's depth `(z[0] + z[2]·fy) + z[1]·fx` (`const_rows_on`'s `zrow`, then
/// `depth_test`'s lane), the colour stored as it is.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn tiny_avx2<const F: u32>(
    color: &mut [[u8; 4]],
    depth: &mut [u32],
    at: usize,
    cover: u8,
    z: &[f32; 3],
    fill: TinyFill,
) -> u8 {
    use std::arch::x86_64::{
        __m256, _mm256_add_ps, _mm256_blend_ps, _mm256_castps256_ps128, _mm256_extractf128_ps,
        _mm256_loadu_ps, _mm256_mul_ps, _mm256_permutevar8x32_ps, _mm256_set1_ps,
        _mm256_setr_epi32, _mm_add_ps, _mm_broadcastss_ps, _mm_castps_si128, _mm_cvtsi128_si32,
        _mm_div_ss, _mm_max_ps, _mm_min_ps, _mm_movehdup_ps, _mm_mul_ps, _mm_set1_ps, _mm_set_ss,
        _mm_setr_epi8, _mm_setzero_ps, _mm_shuffle_epi8,
    };
    let pl = match fill {
        TinyFill::Smooth(pl) => pl,
        TinyFill::Flat(px) => {
            let depth_at = |k: usize| {
                let zrow = z[0] + z[2] * TINY_FY[k & 3];
                (_mm_set_ss(zrow + z[1] * TINY_FX[k & 3]), ())
            };
            let store = |i: usize, ()| {
                if let Some(c) = color.get_mut(i) {
                    *c = px;
                }
            };
            // SAFETY: the CPU has AVX2 (this function's contract).
            return unsafe { tiny_pixels::<F, ()>(depth, at, cover, depth_at, store) };
        }
    };
    // SAFETY: the CPU has AVX2 (this function's contract); `pl` holds fifteen f32, so the
    // loads of eight at offsets 0 and 7 are in bounds (no alignment needed); the rest is
    // register arithmetic, and the buffers are reached through `get_mut`.
    unsafe {
        // pl[0..8] and pl[7..15]: lane c < 4 of plane term k (0 the constant, 1 the x step, 2
        // the y step) is pl[3 + 3c + k], lane 4 z[k], lane 5 pl[k] (1/w); lanes 6 and 7
        // unused.
        let (a, b) = (
            _mm256_loadu_ps(pl.as_ptr()),
            _mm256_loadu_ps(pl.as_ptr().add(7)),
        );
        macro_rules! term {
            ($k:literal, $a0:literal, $a1:literal, $a5:literal, $b1:literal, $b2:literal,
             $b3:literal, $m:literal) => {{
                let ia = _mm256_setr_epi32($a0, $a1, 0, 0, 0, $a5, 0, 0);
                let ib = _mm256_setr_epi32(0, $b1, $b2, $b3, 0, 0, 0, 0);
                let v = _mm256_blend_ps::<$m>(
                    _mm256_permutevar8x32_ps(a, ia),
                    _mm256_permutevar8x32_ps(b, ib),
                );
                _mm256_blend_ps::<0x10>(v, _mm256_set1_ps(z[$k]))
            }};
        }
        // Constants pl[3, 6 | 9, 12 | 0]; x steps pl[4, 7 | 10, 13 | 1]; y steps
        // pl[5 | 8, 11, 14 | 2] (lanes from `a` | from `b` | lane 5).
        let base = term!(0, 3, 6, 0, 0, 2, 5, 0b1100);
        let dx = term!(1, 4, 7, 1, 0, 3, 6, 0b1100);
        let ystep = term!(2, 5, 0, 2, 1, 4, 7, 0b1110);
        let bytes = _mm_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
        let planes = |k: usize| {
            let o = _mm256_add_ps(base, _mm256_mul_ps(ystep, _mm256_set1_ps(TINY_FY[k & 3])));
            let v = _mm256_add_ps(o, _mm256_mul_ps(dx, _mm256_set1_ps(TINY_FX[k & 3])));
            (_mm256_extractf128_ps::<1>(v), v)
        };
        let store = |i: usize, v: __m256| {
            let Some(c) = color.get_mut(i) else {
                return;
            };
            let w = _mm_movehdup_ps(_mm256_extractf128_ps::<1>(v));
            let inv = _mm_div_ss(_mm_set_ss(1.0), w);
            let rgba = _mm_mul_ps(_mm256_castps256_ps128(v), _mm_broadcastss_ps(inv));
            let rgba = _mm_min_ps(_mm_max_ps(rgba, _mm_setzero_ps()), _mm_set1_ps(1.0));
            let t = _mm_add_ps(
                _mm_mul_ps(rgba, _mm_set1_ps(255.0 / 256.0)),
                _mm_set1_ps(32768.0),
            );
            let px = _mm_cvtsi128_si32(_mm_shuffle_epi8(_mm_castps_si128(t), bytes));
            *c = (px as u32).to_le_bytes();
        };
        tiny_pixels::<F, __m256>(depth, at, cover, planes, store)
    }
}

/// `1.0 / d` on every lane, correctly rounded (SSE2 `divps` on x86-64): for other modules'
/// lane kernels (texture λ).
#[inline(always)]
pub fn recip_lanes(d: [f32; LANES]) -> [f32; LANES] {
    recip(d)
}

/// `(a + dx·fx[l]) + yt` on every lane (`mulps`, `addps`, `addps` on x86-64, two lanes of
/// four; LLVM kept the plain loop's form scalar).
#[inline(always)]
fn plane_lanes(a: f32, dx: f32, yt: f32, fx: &[f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_add_ps, _mm_loadu_ps, _mm_mul_ps, _mm_set1_ps};
        // SAFETY: SSE is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from a
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128` has the
        // layout of `[f32; 4]` and every bit pattern is valid for both.
        unsafe {
            let (a, dx, yt) = (_mm_set1_ps(a), _mm_set1_ps(dx), _mm_set1_ps(yt));
            let f = |p: *const f32| {
                let v = _mm_add_ps(_mm_add_ps(a, _mm_mul_ps(dx, _mm_loadu_ps(p))), yt);
                std::mem::transmute::<__m128, [f32; 4]>(v)
            };
            let (lo, hi) = (f(fx.as_ptr()), f(fx.as_ptr().add(4)));
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        fx.map(|x| (a + dx * x) + yt)
    }
}

/// `a + dx·fx[l]` on every lane (`mulps`, `addps` on x86-64).
#[inline(always)]
pub(super) fn lin_lanes(a: f32, dx: f32, fx: &[f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_add_ps, _mm_loadu_ps, _mm_mul_ps, _mm_set1_ps};
        // SAFETY: as in `plane_lanes`.
        unsafe {
            let (a, dx) = (_mm_set1_ps(a), _mm_set1_ps(dx));
            let f = |p: *const f32| {
                let v = _mm_add_ps(a, _mm_mul_ps(dx, _mm_loadu_ps(p)));
                std::mem::transmute::<__m128, [f32; 4]>(v)
            };
            let (lo, hi) = (f(fx.as_ptr()), f(fx.as_ptr().add(4)));
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        fx.map(|x| a + dx * x)
    }
}

/// `u[l] · v[l]` on every lane (`mulps` on x86-64).
#[inline(always)]
fn mul_lanes(u: &[f32; LANES], v: &[f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_loadu_ps, _mm_mul_ps};
        // SAFETY: as in `plane_lanes`.
        unsafe {
            let f = |k: usize| {
                let p = _mm_mul_ps(
                    _mm_loadu_ps(u.as_ptr().add(k)),
                    _mm_loadu_ps(v.as_ptr().add(k)),
                );
                std::mem::transmute::<__m128, [f32; 4]>(p)
            };
            let (lo, hi) = (f(0), f(4));
            [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        std::array::from_fn(|l| u[l] * v[l])
    }
}

/// The perspective-correct varyings of eight fragments of a span (the general path of
/// `FragCtx::tri_span`, textured spans among them): with fx = `fx0` + l for lane l and `pl(j)`
/// the j-th pool float of `planes` (0 past its end), 1/w = (pl(0) + pl(1)·fx) + pl(2)·`fy`, and
/// varying j < `out.len()` (its plane at o = 3 + 3j) is (pl(o) + pl(o+1)·fx) + pl(o+2)·`fy`,
/// multiplied by w = 1/(1/w) unless j < `nflat` (a flat varying is not divided). Lane l of
/// `out[j]` receives it, exactly the scalar expression's bits.
#[inline(always)]
pub fn varyings(planes: &[f32], nflat: usize, fx0: i32, fy: f32, out: &mut [[f32; LANES]]) {
    #[cfg(target_arch = "x86_64")]
    if let Some(pl) = planes.get(..3 + 3 * out.len()) {
        return varyings_sse(pl, nflat, fx0, fy, out);
    }
    let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
    let fx = lane_x(fx0);
    // `pl(2) * fy` is the same product in every lane.
    let (w0, wx, wy) = (pl(0), pl(1), pl(2) * fy);
    let inv = recip(plane_lanes(w0, wx, wy, &fx));
    for (j, o) in out.iter_mut().enumerate() {
        let k = 3 + 3 * j;
        let val = plane_lanes(pl(k), pl(k + 1), pl(k + 2) * fy, &fx);
        *o = if j < nflat {
            val
        } else {
            mul_lanes(&val, &inv)
        };
    }
}

/// The eight lanes' x, `fx0 + 0` to `fx0 + 7`, as two SSE vectors.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lane_xs_sse(fx0: i32) -> (std::arch::x86_64::__m128, std::arch::x86_64::__m128) {
    use std::arch::x86_64::{_mm_add_ps, _mm_loadu_ps, _mm_set1_ps};
    const IOTA: [f32; LANES] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
    // SAFETY: SSE is part of the x86-64 baseline; the loads read four f32 at offsets 0 and 4
    // of the eight-float `IOTA` (in bounds, no alignment needed).
    unsafe {
        let b = _mm_set1_ps(fx0 as f32);
        (
            _mm_add_ps(b, _mm_loadu_ps(IOTA.as_ptr())),
            _mm_add_ps(b, _mm_loadu_ps(IOTA.as_ptr().add(4))),
        )
    }
}

/// The plane `a + dx·x + yt` at the lanes' x (`lane_xs_sse`), in that order of operations.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn plane_sse(
    (xlo, xhi): (std::arch::x86_64::__m128, std::arch::x86_64::__m128),
    a: f32,
    dx: f32,
    yt: f32,
) -> (std::arch::x86_64::__m128, std::arch::x86_64::__m128) {
    use std::arch::x86_64::{_mm_add_ps, _mm_mul_ps, _mm_set1_ps};
    // SAFETY: SSE is part of the x86-64 baseline; register arithmetic only.
    unsafe {
        let (a, dx, yt) = (_mm_set1_ps(a), _mm_set1_ps(dx), _mm_set1_ps(yt));
        (
            _mm_add_ps(_mm_add_ps(a, _mm_mul_ps(dx, xlo)), yt),
            _mm_add_ps(_mm_add_ps(a, _mm_mul_ps(dx, xhi)), yt),
        )
    }
}

/// `varyings` when `planes` holds every plane (`3 + 3·out.len()` floats): the same
/// instructions as `plane_lanes`, `recip` and `mul_lanes` (`mulps`, `addps`, `divps`), with
/// the lanes kept in registers and each varying stored straight into `out` (the array form
/// copied every intermediate through memory: ≈340 instructions a group of eight with eight
/// varyings).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn varyings_sse(planes: &[f32], nflat: usize, fx0: i32, fy: f32, out: &mut [[f32; LANES]]) {
    use std::arch::x86_64::{_mm_div_ps, _mm_mul_ps, _mm_set1_ps, _mm_storeu_ps};
    // SAFETY: SSE is part of the x86-64 baseline; the stores write four f32 at offsets 0 and
    // 4 of a `[f32; 8]` (in bounds, no alignment needed).
    unsafe {
        let xs = lane_xs_sse(fx0);
        let plane = |a: f32, dx: f32, yt: f32| plane_sse(xs, a, dx, yt);
        let (wlo, whi) = match planes {
            [w0, wx, wy, ..] => plane(*w0, *wx, *wy * fy),
            _ => return,
        };
        let one = _mm_set1_ps(1.0);
        let (ilo, ihi) = (_mm_div_ps(one, wlo), _mm_div_ps(one, whi));
        let rest = planes.get(3..).unwrap_or_default();
        for (j, (o, p)) in out.iter_mut().zip(rest.chunks_exact(3)).enumerate() {
            let (mut lo, mut hi) = plane(p[0], p[1], p[2] * fy);
            if j >= nflat {
                lo = _mm_mul_ps(lo, ilo);
                hi = _mm_mul_ps(hi, ihi);
            }
            _mm_storeu_ps(o.as_mut_ptr(), lo);
            _mm_storeu_ps(o.as_mut_ptr().add(4), hi);
        }
    }
}

/// `varyings` with eight lanes a register (AVX2): the same `addps`, `mulps` and `divps` of
/// each lane as `varyings_sse` (lane x `fx0 as f32 + l`, `(a + dx·x) + dy·y`, 1/w by a divide,
/// the product by it), each varying one 256-bit plane and one store instead of two halves
/// (≈23 → ≈12 instructions a varying a group). Where `planes` lacks a plane it is
/// `varyings`' route.
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn varyings_avx2(
    planes: &[f32],
    nflat: usize,
    fx0: i32,
    fy: f32,
    out: &mut [[f32; LANES]],
) {
    use std::arch::x86_64::{_mm256_add_ps, _mm256_set1_ps, _mm256_setr_ps};
    if planes.len() < 3 + 3 * out.len() {
        return varyings(planes, nflat, fx0, fy, out);
    }
    let xs = _mm256_add_ps(
        _mm256_set1_ps(fx0 as f32),
        _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0),
    );
    varyings8(planes, nflat, xs, _mm256_set1_ps(fy), out);
}

/// The varyings of eight fragments of one primitive anywhere in it, lane l's at (`fx[l]`,
/// `fy[l]`) relative to the planes' origin (a packed group of `FragCtx::packed_rows`): lane
/// l of each row the bits `varyings` gives the fragment in its own row (the same operations
/// on each lane: the product ∂y·y, which `varyings` takes once for its row, is the same
/// product). `planes` must hold `3 + 3·out.len()` floats (else nothing is written).
///
/// # Safety
/// The CPU must have AVX2 (`has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn varyings_xy_avx2(
    planes: &[f32],
    nflat: usize,
    fx: &[f32; LANES],
    fy: &[f32; LANES],
    out: &mut [[f32; LANES]],
) {
    use std::arch::x86_64::_mm256_loadu_ps;
    // SAFETY: each load reads the eight floats of a `[f32; 8]` (no alignment needed).
    let (xs, ys) = unsafe { (_mm256_loadu_ps(fx.as_ptr()), _mm256_loadu_ps(fy.as_ptr())) };
    varyings8(planes, nflat, xs, ys, out);
}

/// The kernel of `varyings_avx2` and `varyings_xy_avx2`: 1/w and the varyings at x `xs` and
/// y `ys` per lane, `(a + dx·x) + dy·y` each, the divided ones times w. The planes are read
/// through a pointer, the divided varyings two a turn (the zip of `chunks_exact(3)` over the
/// pool and `iter_mut` over the rows cost a division by 3 a call and four instructions of loop
/// a varying). Nothing is written unless `planes` holds `3 + 3·out.len()` floats.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn varyings8(
    planes: &[f32],
    nflat: usize,
    xs: std::arch::x86_64::__m256,
    ys: std::arch::x86_64::__m256,
    out: &mut [[f32; LANES]],
) {
    use std::arch::x86_64::{
        _mm256_add_ps, _mm256_div_ps, _mm256_mul_ps, _mm256_set1_ps, _mm256_storeu_ps,
    };
    let n = out.len();
    let Some(pl @ [w0, wx, wy, ..]) = planes.get(..3 + 3 * n) else {
        return;
    };
    let nf = nflat.min(n);
    // SAFETY: `pl` holds 3 + 3n floats, so the plane of row j < n, floats 3 + 3j..6 + 3j, is
    // inside it (`p(j)` reads it for j < n only); each store writes the eight f32 of row
    // j < n of `out` (in bounds, no alignment needed).
    unsafe {
        let plane = |a: f32, dx: f32, dy: f32| {
            _mm256_add_ps(
                _mm256_add_ps(_mm256_set1_ps(a), _mm256_mul_ps(_mm256_set1_ps(dx), xs)),
                _mm256_mul_ps(_mm256_set1_ps(dy), ys),
            )
        };
        let inv = _mm256_div_ps(_mm256_set1_ps(1.0), plane(*w0, *wx, *wy));
        let (src, dst) = (pl.as_ptr().add(3), out.as_mut_ptr().cast::<f32>());
        let p = |j: usize| {
            let q = src.add(3 * j);
            plane(*q, *q.add(1), *q.add(2))
        };
        // The flat varyings first, then those divided (no test of j in the loops).
        let mut j = 0;
        while j < nf {
            _mm256_storeu_ps(dst.add(LANES * j), p(j));
            j += 1;
        }
        while j + 2 <= n {
            _mm256_storeu_ps(dst.add(LANES * j), _mm256_mul_ps(p(j), inv));
            _mm256_storeu_ps(dst.add(LANES * (j + 1)), _mm256_mul_ps(p(j + 1), inv));
            j += 2;
        }
        if j < n {
            _mm256_storeu_ps(dst.add(LANES * j), _mm256_mul_ps(p(j), inv));
        }
    }
}

/// Chosen varyings of one span row, for spans that read a few of the layout's varyings: their
/// planes looked up (and their y terms multiplied out) once per span, so that each group of
/// eight only evaluates them. [`RowVaryings::eval`] gives row i < `k` varying `sel[i]` of a
/// span whose first `nv` varyings `varyings` would compute, with exactly the bits `varyings`
/// gives it there (the same plane expressions, the same `divps` for 1/w, the same `mulps`),
/// or +0 in every lane when `sel[i]` ≥ `nv` (what the zeroed rows past those `varyings`
/// writes hold: its plane is taken as 0, 0, 0 and not divided, and (0 + 0·x) + 0 is +0 for
/// every finite x).
pub struct RowVaryings<const K: usize> {
    /// 1/w's plane: constant, x step, y term.
    w: [f32; 3],
    /// Each chosen varying's plane, as `w`.
    p: [[f32; 3]; K],
    /// Multiplied by w (not flat, not past `nv`).
    div: [bool; K],
    /// Rows evaluated.
    k: usize,
}

impl<const K: usize> RowVaryings<K> {
    /// The row `fy` of the varyings `sel[..k]` of `planes` (see [`varyings`]: `nflat` flat
    /// varyings first, `pl(j)` 0 past the pool's end).
    #[inline(always)]
    pub fn new(
        planes: &[f32],
        nflat: usize,
        nv: usize,
        fy: f32,
        sel: &[usize; K],
        k: usize,
    ) -> Self {
        let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
        let k = k.min(K);
        let mut p = [[0.0; 3]; K];
        let mut div = [false; K];
        for ((p, d), &j) in p.iter_mut().zip(&mut div).zip(sel).take(k) {
            if j < nv {
                let q = 3 + 3 * j;
                *p = [pl(q), pl(q + 1), pl(q + 2) * fy];
                *d = j >= nflat;
            }
        }
        RowVaryings {
            w: [pl(0), pl(1), pl(2) * fy],
            p,
            div,
            k,
        }
    }

    /// The chosen varyings of the group whose first lane is at x offset `fx0`: `out[i]` for
    /// i < `k` (rows past it are left as they are).
    #[inline(always)]
    pub fn eval(&self, fx0: i32, out: &mut [[f32; LANES]; K]) {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{_mm_div_ps, _mm_mul_ps, _mm_set1_ps, _mm_storeu_ps};
            // SAFETY: as in `varyings_sse`: SSE is part of the x86-64 baseline; the stores
            // write four f32 at offsets 0 and 4 of a `[f32; 8]` (in bounds, no alignment
            // needed).
            unsafe {
                let xs = lane_xs_sse(fx0);
                let plane = |p: &[f32; 3]| plane_sse(xs, p[0], p[1], p[2]);
                let (wlo, whi) = plane(&self.w);
                let one = _mm_set1_ps(1.0);
                let (ilo, ihi) = (_mm_div_ps(one, wlo), _mm_div_ps(one, whi));
                for ((o, p), &d) in out.iter_mut().zip(&self.p).zip(&self.div).take(self.k) {
                    let (mut lo, mut hi) = plane(p);
                    if d {
                        lo = _mm_mul_ps(lo, ilo);
                        hi = _mm_mul_ps(hi, ihi);
                    }
                    _mm_storeu_ps(o.as_mut_ptr(), lo);
                    _mm_storeu_ps(o.as_mut_ptr().add(4), hi);
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let fx = lane_x(fx0);
            let inv = recip(plane_lanes(self.w[0], self.w[1], self.w[2], &fx));
            for ((o, p), &d) in out.iter_mut().zip(&self.p).zip(&self.div).take(self.k) {
                let val = plane_lanes(p[0], p[1], p[2], &fx);
                *o = if d { mul_lanes(&val, &inv) } else { val };
            }
        }
    }

    /// `eval` with eight lanes a register (AVX2): lane x `fx0 as f32 + l` (`lane_xs_sse`'s
    /// values), each plane `(a + dx·x) + yt`, 1/w by `vdivps`, the product by `vmulps`, the
    /// same operations in the same order, so the same bits. (The rows use `RowPlanes8`, its
    /// per-primitive form; this one is the tests' reference between the two.)
    #[cfg(all(target_arch = "x86_64", test))]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub fn eval_avx2(&self, fx0: i32, out: &mut [[f32; LANES]; K]) {
        use std::arch::x86_64::{
            _mm256_add_ps, _mm256_div_ps, _mm256_mul_ps, _mm256_set1_ps, _mm256_setr_ps,
            _mm256_storeu_ps,
        };
        let iota = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
        let x = _mm256_add_ps(_mm256_set1_ps(fx0 as f32), iota);
        let plane = |p: &[f32; 3]| {
            _mm256_add_ps(
                _mm256_add_ps(_mm256_set1_ps(p[0]), _mm256_mul_ps(_mm256_set1_ps(p[1]), x)),
                _mm256_set1_ps(p[2]),
            )
        };
        let inv = _mm256_div_ps(_mm256_set1_ps(1.0), plane(&self.w));
        for ((o, p), &d) in out.iter_mut().zip(&self.p).zip(&self.div).take(self.k) {
            let mut v = plane(p);
            if d {
                v = _mm256_mul_ps(v, inv);
            }
            // SAFETY: `o` holds eight f32, 32 bytes (no alignment needed).
            unsafe { _mm256_storeu_ps(o.as_mut_ptr(), v) };
        }
    }
}

/// `RowVaryings` for the AVX2 route, split by what changes: the chosen planes' constants and
/// x steps, broadcast to eight lanes once per primitive ([`RowPlanes8::new`], with each y
/// step), and per row only the y terms ([`RowPlanes8::row`]: `dy·fy` as `RowVaryings::new`
/// multiplies it, broadcast). [`RowPlanes8::eval`] is `RowVaryings::eval_avx2` with those
/// vectors: `(a + dx·x) + yt`, 1/w by `vdivps`, the product by `vmulps`, the same operations
/// in the same order, so the same bits. (Building `RowVaryings` a row, its bounds-checked
/// look-ups and its broadcasts were ≈180 instructions a row, with 2.7 groups a row in fog.)
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
pub struct RowPlanes8<const K: usize> {
    /// 1/w's plane: constant and x step broadcast, y step.
    wa: std::arch::x86_64::__m256,
    wdx: std::arch::x86_64::__m256,
    wdy: f32,
    /// Each chosen varying's plane, as `w` (all 0 past `nv`).
    a: [std::arch::x86_64::__m256; K],
    dx: [std::arch::x86_64::__m256; K],
    dy: [f32; K],
    /// The plane is the pool's (the varying is before `nv`): its y term is `dy·fy`, else +0.
    live: [bool; K],
    /// Multiplied by w (not flat, not past `nv`).
    div: [bool; K],
    /// Rows evaluated.
    k: usize,
}

/// The y terms of one row for [`RowPlanes8`].
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
pub struct RowY8<const K: usize> {
    w: std::arch::x86_64::__m256,
    y: [std::arch::x86_64::__m256; K],
}

#[cfg(target_arch = "x86_64")]
impl<const K: usize> RowY8<K> {
    /// Every lane +0 (a placeholder where the AVX2 route is not taken).
    #[inline(always)]
    pub fn zeroed() -> Self {
        // SAFETY: all zero bits are a valid `__m256` (eight +0.0).
        unsafe { std::mem::zeroed() }
    }
}

#[cfg(target_arch = "x86_64")]
impl<const K: usize> RowPlanes8<K> {
    /// Every plane 0 and no row (a placeholder where the AVX2 route is not taken).
    #[inline(always)]
    pub fn zeroed() -> Self {
        // SAFETY: all zero bits are valid for every field: `__m256` (+0.0 lanes), `f32`,
        // `bool` (false) and `usize`.
        unsafe { std::mem::zeroed() }
    }

    /// The varyings `sel[..k]` of `planes` (as [`RowVaryings::new`], without the row).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`has_avx2`); meant to be inlined into a function compiled for it.
    #[inline(always)]
    pub unsafe fn new(planes: &[f32], nflat: usize, nv: usize, sel: &[usize; K], k: usize) -> Self {
        use std::arch::x86_64::{_mm256_set1_ps, _mm256_setzero_ps};
        let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
        let k = k.min(K);
        // SAFETY: the caller's CPU has AVX; register operations only.
        let zero = unsafe { _mm256_setzero_ps() };
        let mut a = [zero; K];
        let mut dx = [zero; K];
        let mut dy = [0.0; K];
        let mut live = [false; K];
        let mut div = [false; K];
        for (i, &j) in sel.iter().enumerate().take(k) {
            if j < nv {
                let q = 3 + 3 * j;
                if let (Some(a), Some(dx), Some(dy), Some(l), Some(d)) = (
                    a.get_mut(i),
                    dx.get_mut(i),
                    dy.get_mut(i),
                    live.get_mut(i),
                    div.get_mut(i),
                ) {
                    // SAFETY: as above.
                    unsafe {
                        *a = _mm256_set1_ps(pl(q));
                        *dx = _mm256_set1_ps(pl(q + 1));
                    }
                    *dy = pl(q + 2);
                    *l = true;
                    *d = j >= nflat;
                }
            }
        }
        // SAFETY: as above.
        let (wa, wdx) = unsafe { (_mm256_set1_ps(pl(0)), _mm256_set1_ps(pl(1))) };
        RowPlanes8 {
            wa,
            wdx,
            wdy: pl(2),
            a,
            dx,
            dy,
            live,
            div,
            k,
        }
    }

    /// The y terms of row `fy`: `dy·fy` (+0 for a plane past `nv`), broadcast.
    ///
    /// # Safety
    /// As [`RowPlanes8::new`].
    #[inline(always)]
    pub unsafe fn row(&self, fy: f32) -> RowY8<K> {
        use std::arch::x86_64::{_mm256_set1_ps, _mm256_setzero_ps};
        // SAFETY: the caller's CPU has AVX; register operations only.
        unsafe {
            let mut y = [_mm256_setzero_ps(); K];
            for ((o, &dy), &l) in y.iter_mut().zip(&self.dy).zip(&self.live).take(self.k) {
                if l {
                    *o = _mm256_set1_ps(dy * fy);
                }
            }
            RowY8 {
                w: _mm256_set1_ps(self.wdy * fy),
                y,
            }
        }
    }

    /// The chosen varyings of the group whose first lane is at x offset `fx0` in the row `y`:
    /// `out[i]` for i < `k` (rows past it are left as they are).
    ///
    /// # Safety
    /// As [`RowPlanes8::new`].
    #[inline(always)]
    pub unsafe fn eval(&self, y: &RowY8<K>, fx0: i32, out: &mut [[f32; LANES]; K]) {
        use std::arch::x86_64::{
            _mm256_add_ps, _mm256_div_ps, _mm256_mul_ps, _mm256_set1_ps, _mm256_setr_ps,
            _mm256_storeu_ps,
        };
        // SAFETY: the caller's CPU has AVX; each store writes eight f32, 32 bytes, into a
        // `[f32; 8]` (no alignment needed).
        unsafe {
            let iota = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
            let x = _mm256_add_ps(_mm256_set1_ps(fx0 as f32), iota);
            let w = _mm256_add_ps(_mm256_add_ps(self.wa, _mm256_mul_ps(self.wdx, x)), y.w);
            let inv = _mm256_div_ps(_mm256_set1_ps(1.0), w);
            let rows = self.a.iter().zip(&self.dx).zip(&y.y).zip(&self.div);
            for (o, (((a, dx), yt), &d)) in out.iter_mut().zip(rows).take(self.k) {
                let mut v = _mm256_add_ps(_mm256_add_ps(*a, _mm256_mul_ps(*dx, x)), *yt);
                if d {
                    v = _mm256_mul_ps(v, inv);
                }
                _mm256_storeu_ps(o.as_mut_ptr(), v);
            }
        }
    }
}

/// The eight lanes' colours as pixel-major vectors: `out[l]` = (r[l], g[l], b[l], a[l]) (SSE
/// unpacks and moves on x86-64, a 4x4 transposition per half; only moves, so every bit is
/// kept).
#[inline(always)]
pub(super) fn to_pixels(c: [&[f32; LANES]; 4]) -> [glam::Vec4; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128, _mm_loadu_ps, _mm_movehl_ps, _mm_movelh_ps, _mm_unpackhi_ps, _mm_unpacklo_ps,
        };
        let [r, g, b, a] = c;
        let v = |x: __m128| {
            // SAFETY: `__m128` has the layout of `[f32; 4]`; every bit pattern is valid.
            glam::Vec4::from_array(unsafe { std::mem::transmute::<__m128, [f32; 4]>(x) })
        };
        let half = |k: usize| {
            // SAFETY: SSE is part of the x86-64 baseline; each load reads four f32 at offset
            // 0 or 4 of a `[f32; 8]` (in bounds, no alignment needed).
            let (t0, t1, t2, t3) = unsafe {
                let (r, g) = (
                    _mm_loadu_ps(r.as_ptr().add(k)),
                    _mm_loadu_ps(g.as_ptr().add(k)),
                );
                let (b, a) = (
                    _mm_loadu_ps(b.as_ptr().add(k)),
                    _mm_loadu_ps(a.as_ptr().add(k)),
                );
                (
                    _mm_unpacklo_ps(r, g),
                    _mm_unpacklo_ps(b, a),
                    _mm_unpackhi_ps(r, g),
                    _mm_unpackhi_ps(b, a),
                )
            };
            // SAFETY: as above (register moves only).
            unsafe {
                [
                    v(_mm_movelh_ps(t0, t1)),
                    v(_mm_movehl_ps(t1, t0)),
                    v(_mm_movelh_ps(t2, t3)),
                    v(_mm_movehl_ps(t3, t2)),
                ]
            }
        };
        let (lo, hi) = (half(0), half(4));
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let [r, g, b, a] = c;
        std::array::from_fn(|l| glam::Vec4::new(r[l], g[l], b[l], a[l]))
    }
}

/// The inverse of `to_pixels`: channel-major lanes from eight pixel-major colours.
#[inline(always)]
pub(super) fn from_pixels(p: &[glam::Vec4; LANES]) -> [[f32; LANES]; 4] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128, _mm_loadu_ps, _mm_movehl_ps, _mm_movelh_ps, _mm_unpackhi_ps, _mm_unpacklo_ps,
        };
        let a = |x: __m128| {
            // SAFETY: `__m128` has the layout of `[f32; 4]`; every bit pattern is valid.
            unsafe { std::mem::transmute::<__m128, [f32; 4]>(x) }
        };
        let half = |k: usize| {
            let q: [[f32; 4]; 4] = std::array::from_fn(|i| p[k + i].to_array());
            // SAFETY: SSE is part of the x86-64 baseline; each load reads a `[f32; 4]`.
            unsafe {
                let (p0, p1) = (_mm_loadu_ps(q[0].as_ptr()), _mm_loadu_ps(q[1].as_ptr()));
                let (p2, p3) = (_mm_loadu_ps(q[2].as_ptr()), _mm_loadu_ps(q[3].as_ptr()));
                let (t0, t1) = (_mm_unpacklo_ps(p0, p1), _mm_unpacklo_ps(p2, p3));
                let (t2, t3) = (_mm_unpackhi_ps(p0, p1), _mm_unpackhi_ps(p2, p3));
                [
                    a(_mm_movelh_ps(t0, t1)),
                    a(_mm_movehl_ps(t1, t0)),
                    a(_mm_movelh_ps(t2, t3)),
                    a(_mm_movehl_ps(t3, t2)),
                ]
            }
        };
        let (lo, hi) = (half(0), half(4));
        std::array::from_fn(|k| {
            let (l, h) = (lo[k], hi[k]);
            [l[0], l[1], l[2], l[3], h[0], h[1], h[2], h[3]]
        })
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        std::array::from_fn(|k| std::array::from_fn(|l| p[l].to_array()[k]))
    }
}

/// Stores the unorm8 colour (`framebuffer::unorm8` of each channel of `c`, channel-major) of
/// every lane whose bit is set in `m` into `dst[l]`: a colour write with ColorMask all true.
#[inline(always)]
pub fn store_rgba(dst: &mut [[u8; 4]], m: u64, c: &[[f32; LANES]; 4]) {
    let (r, g, b, a) = (
        unorm8_lanes(c[0]),
        unorm8_lanes(c[1]),
        unorm8_lanes(c[2]),
        unorm8_lanes(c[3]),
    );
    put(dst, m as u8, &[r, g, b, a]);
}

/// Stores the unorm8 colour of each pixel-major colour `c[l]` (`framebuffer::unorm8` of each
/// channel) into `dst[l]` for the lanes of `m`: `store_rgba` without going through
/// channel-major lanes. On x86-64 with a whole group in `dst`, each colour is converted as
/// `unorm8_lanes` converts a lane (`maxps`, `minps`, `mulps`, `addps`, mask), the packs give
/// the RGBA8 pixels in memory order, and one select and two 16-byte stores write the group
/// (unwritten pixels stored back unchanged; the tile belongs to one thread).
#[inline(always)]
pub fn store_pixels(dst: &mut [[u8; 4]], m: u8, c: &[glam::Vec4; LANES]) {
    #[cfg(target_arch = "x86_64")]
    if let Some(px) = dst.get_mut(..LANES) {
        use std::arch::x86_64::{
            __m128i, _mm_add_ps, _mm_and_si128, _mm_andnot_si128, _mm_castps_si128,
            _mm_cmpeq_epi32, _mm_loadu_ps, _mm_loadu_si128, _mm_max_ps, _mm_min_ps, _mm_mul_ps,
            _mm_or_si128, _mm_packs_epi32, _mm_packus_epi16, _mm_set1_epi32, _mm_set1_ps,
            _mm_set_epi32, _mm_setzero_ps, _mm_storeu_si128,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; each `_mm_loadu_ps` reads a `[f32; 4]`;
        // `px` holds eight `[u8; 4]`, 32 contiguous bytes, read and written 16 bytes at
        // offsets 0 and 16 (in bounds, no alignment needed); `__m128i` is plain bits.
        unsafe {
            let (zero, one) = (_mm_setzero_ps(), _mm_set1_ps(1.0));
            let (k, b) = (_mm_set1_ps(255.0 / 256.0), _mm_set1_ps(32768.0));
            let low = _mm_set1_epi32(0xFF);
            let conv = |v: &glam::Vec4| {
                let a = v.to_array();
                let c = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(a.as_ptr()), zero), one);
                _mm_and_si128(_mm_castps_si128(_mm_add_ps(_mm_mul_ps(c, k), b)), low)
            };
            let bits = _mm_set_epi32(8, 4, 2, 1);
            let p = px.as_mut_ptr().cast::<__m128i>();
            for h in 0..2 {
                let q = &c[4 * h..4 * h + 4];
                // Every value is in 0..=255: the signed packs keep it.
                let w01 = _mm_packs_epi32(conv(&q[0]), conv(&q[1]));
                let w23 = _mm_packs_epi32(conv(&q[2]), conv(&q[3]));
                let v = _mm_packus_epi16(w01, w23);
                let lv = _mm_set1_epi32(i32::from(m >> (4 * h)));
                let on = _mm_cmpeq_epi32(_mm_and_si128(lv, bits), bits);
                let old = _mm_loadu_si128(p.add(h));
                let out = _mm_or_si128(_mm_and_si128(on, v), _mm_andnot_si128(on, old));
                _mm_storeu_si128(p.add(h), out);
            }
        }
        return;
    }
    let ch = |k: usize| -> [f32; LANES] { std::array::from_fn(|l| c[l].to_array()[k]) };
    put(
        dst,
        m,
        &[
            unorm8_lanes(ch(0)),
            unorm8_lanes(ch(1)),
            unorm8_lanes(ch(2)),
            unorm8_lanes(ch(3)),
        ],
    );
}

/// Stores lane l of the channel-major bytes `c` into `dst[l]` for the lanes of `m` (all four
/// channels): `oplanes::store` with ColorMask all true (a whole group selected and stored at
/// once, fewer pixels one by one).
#[inline(always)]
fn put(dst: &mut [[u8; 4]], m: u8, c: &[[u8; LANES]; 4]) {
    super::oplanes::store(dst, c, m, [true; 4]);
}

/// The window values of `N` vertices on arrays, as `SetupCtx::win_lanes` computes them, before
/// they are written out as records (`Win`): window x, y, z and 1/w in f64, the snapped x and y,
/// the pixel centres each bounds and the clip codes.
#[derive(Clone, Copy, Debug)]
pub struct WinLanes<const N: usize> {
    /// Window x before snapping (f64).
    pub(crate) xw: [f64; N],
    /// Window y before snapping (f64).
    pub(crate) yw: [f64; N],
    /// Window z.
    pub(crate) zw: [f64; N],
    /// 1 / w_clip (f64).
    pub(crate) iw: [f64; N],
    /// Snapped window x in 1/256 pixel.
    pub(crate) fx: [i32; N],
    /// Snapped window y in 1/256 pixel.
    pub(crate) fy: [i32; N],
    /// `Win::cen`.
    pub(crate) cen: [[i32; 4]; N],
    /// `Win::code`.
    pub(crate) code: [u16; N],
}

impl<const N: usize> WinLanes<N> {
    /// The records of the first `N` vertices into `out` (as many as it holds), one at a time.
    #[inline(always)]
    pub fn put(&self, out: &mut [Win]) {
        for (i, w) in out.iter_mut().take(N).enumerate() {
            *w = Win {
                x: self.xw[i] as f32,
                y: self.yw[i] as f32,
                fx: i64::from(self.fx[i]),
                fy: i64::from(self.fy[i]),
                z: self.zw[i],
                iw: self.iw[i] as f32,
                code: self.code[i],
                cen: self.cen[i],
            };
        }
    }
}

/// Whether `Win`'s fields lie where `put_wins_avx2` writes them: seven 8-byte words, `cen`
/// (two), `fx`, `fy`, `z`, then `x` and `y`, then `iw` and `code`. That is the order the
/// compiler gives the struct today; it is checked here, not assumed (where it differs, the
/// kernel declines and the records are written one field at a time).
#[cfg(target_arch = "x86_64")]
const WIN_WORDS: bool = {
    use std::mem::{offset_of, size_of};
    size_of::<Win>() == 56
        && offset_of!(Win, cen) == 0
        && offset_of!(Win, fx) == 16
        && offset_of!(Win, fy) == 24
        && offset_of!(Win, z) == 32
        && offset_of!(Win, x) == 40
        && offset_of!(Win, y) == 44
        && offset_of!(Win, iw) == 48
        && offset_of!(Win, code) == 52
};

/// `WinLanes::put` of a whole block of the vertex stage into the first `VERTEX_LANES` records
/// of `out`, four vertices at a time in registers: their f32 conversions (`vcvtpd2ps`, what
/// `as f32` compiles to, so the same bits), the widened snapped coordinates and codes, and
/// three stores a record (the word past the code is the record's padding, written as 0).
/// False, nothing written, where `out` holds fewer than `VERTEX_LANES` records or `Win`'s
/// layout is not `WIN_WORDS`'.
///
/// Design decision: the field-by-field loop was ≈22 instructions a vertex on gauss-smooth-400
/// (eight loads, two conversions, eight stores and the loop), about a sixth of the whole
/// vertex stage's work per vertex there.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn put_wins_avx2(w: &WinLanes<VERTEX_LANES>, out: &mut [Win]) -> bool {
    use std::arch::x86_64::{
        _mm256_castpd256_pd128, _mm256_castps_pd, _mm256_cvtepi32_epi64, _mm256_cvtpd_ps,
        _mm256_extractf128_pd, _mm256_loadu_pd, _mm256_loadu_si256, _mm256_permute2f128_pd,
        _mm256_permute2x128_si256, _mm256_set_m128, _mm256_storeu_si256, _mm256_unpackhi_pd,
        _mm256_unpacklo_pd, _mm_castsi128_ps, _mm_cvtepu16_epi32, _mm_loadl_epi64, _mm_loadu_si128,
        _mm_storel_pd, _mm_storeu_pd, _mm_unpackhi_epi32, _mm_unpackhi_ps, _mm_unpacklo_epi32,
        _mm_unpacklo_ps,
    };
    if !WIN_WORDS || out.len() < VERTEX_LANES {
        return false;
    }
    let dst = out.as_mut_ptr().cast::<u8>();
    for h in (0..VERTEX_LANES).step_by(4) {
        // SAFETY: the CPU has AVX2 (this function's contract). Each load reads four elements
        // of a `[_; VERTEX_LANES]` from h (the centres two at h and two at h + 2), h + 4 <=
        // VERTEX_LANES (no alignment needed). Record h + v < VERTEX_LANES <= out.len() spans
        // bytes 56·(h + v) to 56·(h + v) + 56 of `out` (`WIN_WORDS`: a record is 56 bytes), and
        // its three stores write bytes 0..32, 32..48 and 48..56 of it; every field takes any
        // bit pattern.
        unsafe {
            // Snapped x and y widened to i64 in pairs ([fx0 fy0 | fx1 fy1], [fx2 fy2 | fx3
            // fy3]) and each vertex's centres next to them: words 0 to 3 of each record.
            let fx = _mm_loadu_si128(w.fx.as_ptr().add(h).cast());
            let fy = _mm_loadu_si128(w.fy.as_ptr().add(h).cast());
            let f01 = _mm256_cvtepi32_epi64(_mm_unpacklo_epi32(fx, fy));
            let f23 = _mm256_cvtepi32_epi64(_mm_unpackhi_epi32(fx, fy));
            let c01 = _mm256_loadu_si256(w.cen.as_ptr().add(h).cast());
            let c23 = _mm256_loadu_si256(w.cen.as_ptr().add(h + 2).cast());
            let first = [
                _mm256_permute2x128_si256::<0x20>(c01, f01),
                _mm256_permute2x128_si256::<0x31>(c01, f01),
                _mm256_permute2x128_si256::<0x20>(c23, f23),
                _mm256_permute2x128_si256::<0x31>(c23, f23),
            ];
            // Words 4 to 6: z, then x and y as f32 ([x0 y0 x1 y1 | x2 y2 x3 y3]), then 1/w
            // as f32 beside the code widened to 32 bits ([iw0 c0 iw1 c1 | ...]).
            let x = _mm256_cvtpd_ps(_mm256_loadu_pd(w.xw.as_ptr().add(h)));
            let y = _mm256_cvtpd_ps(_mm256_loadu_pd(w.yw.as_ptr().add(h)));
            let xy = _mm256_castps_pd(_mm256_set_m128(
                _mm_unpackhi_ps(x, y),
                _mm_unpacklo_ps(x, y),
            ));
            let iw = _mm256_cvtpd_ps(_mm256_loadu_pd(w.iw.as_ptr().add(h)));
            let code = _mm_castsi128_ps(_mm_cvtepu16_epi32(_mm_loadl_epi64(
                w.code.as_ptr().add(h).cast(),
            )));
            let ic = _mm256_castps_pd(_mm256_set_m128(
                _mm_unpackhi_ps(iw, code),
                _mm_unpacklo_ps(iw, code),
            ));
            let z = _mm256_loadu_pd(w.zw.as_ptr().add(h));
            // [z0 xy0 | z2 xy2], [z1 xy1 | z3 xy3], [ic1 ic1 | ic3 ic3].
            let (zlo, zhi) = (_mm256_unpacklo_pd(z, xy), _mm256_unpackhi_pd(z, xy));
            let ich = _mm256_unpackhi_pd(ic, ic);
            let second = [
                _mm256_permute2f128_pd::<0x20>(zlo, ic),
                _mm256_permute2f128_pd::<0x20>(zhi, ich),
                _mm256_permute2f128_pd::<0x31>(zlo, ic),
                _mm256_permute2f128_pd::<0x31>(zhi, ich),
            ];
            for v in 0..4 {
                let r = dst.add((h + v) * 56);
                _mm256_storeu_si256(r.cast(), first[v]);
                _mm_storeu_pd(r.add(32).cast(), _mm256_castpd256_pd128(second[v]));
                _mm_storel_pd(r.add(48).cast(), _mm256_extractf128_pd::<1>(second[v]));
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::framebuffer::{depth_unorm, unorm8};
    use crate::cpu::testgen::{Gen, COMPARE_FUNCS};

    #[test]
    fn smooth_rgba_is_the_scalar_expression_bit_for_bit() {
        let mut g = Gen(7);
        for _ in 0..2000 {
            let co: [f32; 10] = std::array::from_fn(|k| match k {
                0 => 0.5 + (g.next() % 1000) as f32 * 1e-3,
                1 => (g.next() % 100) as f32 * 1e-4,
                _ => g.float(),
            });
            let n = 1 + (g.next() % 64) as usize;
            let mask = g.next() | g.next() << 40;
            let fx0 = (g.next() % 900) as i32 - 100;
            let mut got = vec![[9u8; 4]; n];
            smooth_rgba(&mut got, mask, fx0, &co);
            for (k, px) in got.iter().enumerate() {
                let want = if mask & (1 << k) != 0 {
                    let fx = (fx0 + k as i32) as f32;
                    let inv = 1.0 / (co[0] + co[1] * fx);
                    let ch = |o: f32, d: f32| unorm8((o + d * fx) * inv);
                    [
                        ch(co[2], co[3]),
                        ch(co[4], co[5]),
                        ch(co[6], co[7]),
                        ch(co[8], co[9]),
                    ]
                } else {
                    [9; 4]
                };
                assert_eq!(*px, want, "k {k} co {co:?} fx0 {fx0}");
            }
        }
    }

    #[test]
    fn flat_rgba_is_the_scalar_expression_bit_for_bit() {
        let mut g = Gen(5);
        for _ in 0..2000 {
            let mut co: [f32; 12] = std::array::from_fn(|_| g.float());
            // Mostly the planes of a FLAT varying (value, ±0, ±0), the constant route;
            // now and then one of the eight steps nonzero (the general route).
            if g.next() % 3 != 0 {
                for c in 0..4 {
                    co[3 * c + 1] = [0.0, -0.0][(g.next() % 2) as usize];
                    co[3 * c + 2] = [0.0, -0.0][(g.next() % 2) as usize];
                    if g.next() % 4 == 0 {
                        co[3 * c] = [0.0, -0.0, f32::NAN, f32::INFINITY, -1.0, 2.0]
                            [(g.next() % 6) as usize];
                    }
                }
                if g.next() % 5 == 0 {
                    co[1 + (g.next() % 11) as usize] = g.float();
                }
            }
            let n = 1 + (g.next() % 64) as usize;
            let mask = g.next() | g.next() << 40;
            let fx0 = (g.next() % 900) as i32 - 100;
            let fy = (g.next() % 900) as f32;
            let mut got = vec![[9u8; 4]; n];
            flat_rgba(&mut got, mask, fx0, fy, &co);
            for (k, px) in got.iter().enumerate() {
                let fx = (fx0 + k as i32) as f32;
                let want = match mask & (1 << k) != 0 {
                    true => std::array::from_fn(|c| {
                        unorm8(co[3 * c] + co[3 * c + 1] * fx + co[3 * c + 2] * fy)
                    }),
                    false => [9; 4],
                };
                assert_eq!(*px, want, "k {k} co {co:?} fx0 {fx0} fy {fy}");
            }
        }
    }

    #[test]
    fn depth_span_is_the_scalar_test_bit_for_bit() {
        let mut g = Gen(11);
        for _ in 0..2000 {
            let n = 1 + (g.next() % 64) as usize;
            let zrow = g.float();
            let dz = g.float() * 1e-3;
            let fx0 = (g.next() % 900) as i32 - 100;
            let write = g.next() % 2 == 0;
            let func = g.pick(&COMPARE_FUNCS);
            // The row runs on past the span now and then (as a tile's row does); only the
            // live fragments of the span may be tested and written.
            let len = n + (g.next() % 3) as usize * (g.next() % 20) as usize;
            let all = u64::MAX >> (64 - n);
            let live = match g.next() % 3 {
                0 => all,
                _ => (g.next() | g.next() << 40) & all,
            };
            // Few distinct depths so that EQUAL passes now and then.
            let stored: Vec<u32> = (0..len)
                .map(|_| match g.next() % 3 {
                    0 => (g.next() % 4) as u32 * (DEPTH_MAX / 3),
                    _ => (g.next() % (1 << 24)) as u32,
                })
                .collect();
            let mut got = stored.clone();
            let mask = depth_span(&mut got, n, zrow, dz, fx0, live, write, func);
            // The AVX2 route (where the CPU has it) on the same row: the same mask and stores.
            #[cfg(target_arch = "x86_64")]
            if has_avx2() {
                let mut got2 = stored.clone();
                // SAFETY: the CPU has AVX2 (`has_avx2`).
                let m2 = unsafe { depth_span_avx2(&mut got2, n, zrow, dz, fx0, live, write, func) };
                assert_eq!((m2, &got2), (mask, &got), "avx2: zrow {zrow} dz {dz}");
            }
            let mut want = stored.clone();
            let mut want_mask = 0u64;
            for (k, s) in want.iter_mut().enumerate().take(n) {
                if live & (1 << k) == 0 {
                    continue;
                }
                let z = zrow + dz * (fx0 + k as i32) as f32;
                let d = depth_unorm(f64::from(z));
                if crate::cpu::fragops::compare(func, d, *s) {
                    if write {
                        *s = d;
                    }
                    want_mask |= 1 << k;
                }
            }
            assert_eq!((mask, &got), (want_mask, &want), "zrow {zrow} dz {dz}");
        }
    }
    #[test]
    fn smooth_planes8_rows_are_the_scalar_terms_bit_for_bit() {
        let mut g = Gen(41);
        for _ in 0..20_000 {
            let z: [f32; 3] = std::array::from_fn(|_| g.float());
            let pl: [f32; 15] = std::array::from_fn(|_| g.float());
            let fy = match g.next() % 4 {
                0 => g.float(),
                _ => (g.next() % 2000) as f32 - 500.0,
            };
            let sp = SmoothPlanes8::new(&z, &pl);
            // `FragCtx::smooth_row`'s scalar terms: depth, then 1/w, r, g, b, a.
            let want: [f32; 6] = std::array::from_fn(|i| match i {
                0 => z[0] + z[2] * fy,
                _ => pl[(i - 1) * 3] + pl[(i - 1) * 3 + 2] * fy,
            });
            let dx: [f32; 6] = std::array::from_fn(|i| match i {
                0 => z[1],
                _ => pl[(i - 1) * 3 + 1],
            });
            let scalar: [f32; 6] = std::array::from_fn(|i| sp.base[i] + sp.ystep[i] * fy);
            let same = |a: f32, b: f32| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            for i in 0..6 {
                assert!(same(scalar[i], want[i]), "lane {i}: {z:?} {pl:?} fy {fy}");
                assert_eq!(sp.dx[i].to_bits(), dx[i].to_bits());
            }
            #[cfg(target_arch = "x86_64")]
            if has_avx2() {
                // SAFETY: the CPU has AVX2.
                let got = unsafe { sp.row(fy) };
                for i in 0..6 {
                    assert!(same(got[i], want[i]), "avx2 lane {i}: {z:?} {pl:?} fy {fy}");
                }
            }
        }
    }

    #[test]
    fn smooth_depth_span_is_the_scalar_sequence_bit_for_bit() {
        let mut g = Gen(37);
        for i in 0..4000 {
            let co: [f32; 10] = std::array::from_fn(|k| match k {
                0 => 0.5 + (g.next() % 1000) as f32 * 1e-3,
                1 => (g.next() % 100) as f32 * 1e-4,
                _ => g.float(),
            });
            let n = 1 + (g.next() % 64) as usize;
            let zrow = g.float();
            let dz = g.float() * 1e-3;
            let fx0 = (g.next() % 900) as i32 - 100;
            let test = match g.next() % 4 {
                0 => None,
                _ => Some((g.pick(&COMPARE_FUNCS), g.next() % 2 == 0)),
            };
            // The rows run on past the span now and then (as a tile's rows do); the depth row
            // may be shorter than the colour row, or empty, as a bad index would give.
            let len = n + (g.next() % 3) as usize * (g.next() % 20) as usize;
            let dlen = match i % 50 {
                0 => 0,
                1 => n / 2,
                _ => len,
            };
            let color0: Vec<[u8; 4]> = (0..len).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let depth0: Vec<u32> = (0..dlen)
                .map(|_| match g.next() % 3 {
                    0 => (g.next() % 4) as u32 * (DEPTH_MAX / 3),
                    _ => (g.next() % (1 << 24)) as u32,
                })
                .collect();
            let (mut color, mut depth) = (color0.clone(), depth0.clone());
            let got = smooth_depth_span(&mut color, &mut depth, n, fx0, zrow, dz, test, &co);
            // The AVX2 route (where the CPU has it) against the SSE2 one, bit for bit.
            #[cfg(target_arch = "x86_64")]
            if has_avx2() {
                let (mut c2, mut d2) = (color0.clone(), depth0.clone());
                let o = [zrow, co[0], co[2], co[4], co[6], co[8], 0.0, 0.0];
                let dx = [dz, co[1], co[3], co[5], co[7], co[9], 0.0, 0.0];
                // SAFETY: the CPU has AVX2.
                let m2 = unsafe {
                    smooth_depth_span_avx2::<0>(&mut c2, &mut d2, 0, n, fx0, &o, &dx, test)
                };
                assert_eq!(m2, got, "avx2: n {n} test {test:?} co {co:?}");
                assert_eq!(c2, color, "avx2: n {n} test {test:?} co {co:?} fx0 {fx0}");
                assert_eq!(d2, depth, "avx2: n {n} test {test:?} zrow {zrow} dz {dz}");
                // The same span from an index past the buffers' start (a tile's row), the
                // pixels before it untouched.
                let pre = (g.next() % 70) as usize;
                let mut c3 = vec![[7u8; 4]; pre];
                c3.extend_from_slice(&color0);
                let mut d3 = vec![7u32; pre];
                d3.extend_from_slice(&depth0);
                // SAFETY: the CPU has AVX2.
                let m3 = unsafe {
                    smooth_depth_span_avx2::<0>(&mut c3, &mut d3, pre, n, fx0, &o, &dx, test)
                };
                assert_eq!(m3, got, "avx2 from {pre}: n {n} test {test:?}");
                assert_eq!(
                    (&c3[..pre], &c3[pre..]),
                    (&vec![[7u8; 4]; pre][..], &color[..])
                );
                assert_eq!((&d3[..pre], &d3[pre..]), (&vec![7u32; pre][..], &depth[..]));
                // The depth tests chosen at compile time (`test` then not read) against the
                // SSE2 route with the same test.
                type Span = unsafe fn(
                    &mut [[u8; 4]],
                    &mut [u32],
                    usize,
                    usize,
                    i32,
                    &[f32; LANES],
                    &[f32; LANES],
                    Option<(u32, bool)>,
                ) -> u64;
                let fixed: [(u32, Span); 2] = [
                    (
                        crate::gl::LESS,
                        smooth_depth_span_avx2::<{ crate::gl::LESS }>,
                    ),
                    (
                        crate::gl::LEQUAL,
                        smooth_depth_span_avx2::<{ crate::gl::LEQUAL }>,
                    ),
                ];
                for (func, span) in fixed {
                    let t = Some((func, true));
                    let (mut c1, mut d1) = (color0.clone(), depth0.clone());
                    let m1 = smooth_depth_span(&mut c1, &mut d1, n, fx0, zrow, dz, t, &co);
                    let (mut c2, mut d2) = (color0.clone(), depth0.clone());
                    // SAFETY: the CPU has AVX2.
                    let m2 = unsafe { span(&mut c2, &mut d2, 0, n, fx0, &o, &dx, test) };
                    assert_eq!(
                        (m2, &c2, &d2),
                        (m1, &c1, &d1),
                        "avx2 {func}: n {n} fx0 {fx0}"
                    );
                }
            }
            // `FragCtx::tri_span`'s fast path: the depth test over the span, then the colour
            // of each survivor, fragment by fragment.
            let (mut wcolor, mut wdepth) = (color0.clone(), depth0.clone());
            let mut want = 0u64;
            for (k, wc) in wcolor.iter_mut().enumerate().take(n) {
                let fx = (fx0 + k as i32) as f32;
                if let Some((func, write)) = test {
                    let Some(s) = wdepth.get_mut(k) else {
                        continue;
                    };
                    let d = depth_unorm(f64::from(zrow + dz * fx));
                    if !crate::cpu::fragops::compare(func, d, *s) {
                        continue;
                    }
                    if write {
                        *s = d;
                    }
                }
                want |= 1 << k;
                let inv = 1.0 / (co[0] + co[1] * fx);
                let ch = |o: f32, d: f32| unorm8((o + d * fx) * inv);
                *wc = [
                    ch(co[2], co[3]),
                    ch(co[4], co[5]),
                    ch(co[6], co[7]),
                    ch(co[8], co[9]),
                ];
            }
            assert_eq!(got, want, "n {n} test {test:?} co {co:?}");
            assert_eq!(color, wcolor, "n {n} test {test:?} co {co:?} fx0 {fx0}");
            assert_eq!(depth, wdepth, "n {n} test {test:?} zrow {zrow} dz {dz}");
        }
    }
    #[test]
    fn varyings_are_the_scalar_expression_bit_for_bit() {
        let mut g = Gen(13);
        for _ in 0..3000 {
            let np = 3 + 3 * (g.next() % 12) as usize + (g.next() % 3) as usize;
            let planes: Vec<f32> = (0..np)
                .map(|k| match k {
                    0 => 0.5 + (g.next() % 1000) as f32 * 1e-3,
                    1 | 2 => (g.next() % 100) as f32 * 1e-4 - 5e-3,
                    _ => g.float(),
                })
                .collect();
            let nv = (g.next() % 14) as usize;
            let nflat = (g.next() % 6) as usize;
            let fx0 = (g.next() % 900) as i32 - 100;
            let fy = (g.next() % 900) as f32;
            let mut got = vec![[7.0f32; LANES]; nv];
            varyings(&planes, nflat, fx0, fy, &mut got);
            // The AVX2 route: the same bytes as the SSE2/portable one (rows it leaves alone,
            // past the planes, as well), a NaN's payload aside (LLVM may commute the operands
            // of either route; nothing reads it).
            #[cfg(target_arch = "x86_64")]
            if has_avx2() {
                let mut got8 = vec![[7.0f32; LANES]; nv];
                // SAFETY: the CPU has AVX2.
                unsafe { varyings_avx2(&planes, nflat, fx0, fy, &mut got8) };
                for (a, b) in got8.iter().flatten().zip(got.iter().flatten()) {
                    let same = a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan();
                    assert!(same, "{a} vs {b}: {planes:?} nflat {nflat} fx0 {fx0}");
                }
            }
            let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
            for l in 0..LANES {
                // `FragCtx::tri_span`'s scalar loop, fragment by fragment.
                let fx = (fx0 + l as i32) as f32;
                let iw = pl(0) + pl(1) * fx + pl(2) * fy;
                let inv = 1.0 / iw;
                for (j, lanes) in got.iter().enumerate() {
                    let o = 3 + 3 * j;
                    let val = pl(o) + pl(o + 1) * fx + pl(o + 2) * fy;
                    let want = if j < nflat { val } else { val * inv };
                    // A NaN's payload may differ (operand order); nothing reads it.
                    let same =
                        lanes[l].to_bits() == want.to_bits() || lanes[l].is_nan() && want.is_nan();
                    assert!(same, "l {l} j {j}: {} vs {want} {planes:?}", lanes[l]);
                }
            }
        }
    }

    /// `RowVaryings::eval_avx2` against `eval` bit for bit, where the CPU has AVX2: random
    /// planes (NaN, ±∞, −0, denormals, any bits), flat and divided rows, selections past `nv`
    /// and pools shorter than the layout, lane offsets on both sides of 0.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn row_varyings_on_avx2_are_the_sse2_rows_bit_for_bit() {
        if !has_avx2() {
            return;
        }
        let mut g = Gen(41);
        for _ in 0..20_000 {
            let len = (g.next() % 40) as usize;
            let planes: Vec<f32> = (0..len)
                .map(|_| match g.next() % 12 {
                    0 => f32::from_bits(g.next() as u32),
                    1 => f32::from_bits((g.next() as u32) & 0x807F_FFFF),
                    _ => g.float(),
                })
                .collect();
            let nv = (g.next() % 12) as usize;
            let nflat = (g.next() % 6) as usize;
            let sel: [usize; 8] = std::array::from_fn(|_| (g.next() % 12) as usize);
            let k = (g.next() % 9) as usize;
            let fy = (g.next() % 200) as f32 - 50.0;
            let row = RowVaryings::new(&planes, nflat, nv, fy, &sel, k);
            let fx0 = (g.next() % 400) as i32 - 100;
            let fill = f32::from_bits(g.next() as u32);
            let (mut want, mut have) = ([[fill; LANES]; 8], [[fill; LANES]; 8]);
            row.eval(fx0, &mut want);
            // SAFETY: the CPU has AVX2 (checked above).
            unsafe { row.eval_avx2(fx0, &mut have) };
            // The per-primitive form (`RowPlanes8`, the same instructions) as `eval_avx2`.
            let mut split = [[fill; LANES]; 8];
            // SAFETY: as above.
            unsafe {
                let p8 = RowPlanes8::new(&planes, nflat, nv, &sel, k);
                p8.eval(&p8.row(fy), fx0, &mut split);
            }
            // Bit for bit, a NaN as any NaN: LLVM may swap the operands of the SSE2 route's
            // additions and products, so of two NaN operands either payload comes out (every
            // NaN colour or fog coordinate gives the same pixel: the clamps take it to 0).
            let key = |v: f32| if v.is_nan() { u32::MAX } else { v.to_bits() };
            assert_eq!(
                have.map(|r| r.map(key)),
                want.map(|r| r.map(key)),
                "{planes:?} nflat {nflat} nv {nv} sel {sel:?} k {k} fy {fy} fx0 {fx0}"
            );
            assert_eq!(
                split.map(|r| r.map(key)),
                want.map(|r| r.map(key)),
                "RowPlanes8: {planes:?} nflat {nflat} nv {nv} sel {sel:?} k {k} fy {fy} fx0 {fx0}"
            );
        }
    }

    #[test]
    fn to_pixels_and_back_keep_every_bit() {
        let mut g = Gen(29);
        for _ in 0..500 {
            let c: [[f32; LANES]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| g.float()));
            let p = to_pixels([&c[0], &c[1], &c[2], &c[3]]);
            for (l, px) in p.iter().enumerate() {
                let want = [c[0][l], c[1][l], c[2][l], c[3][l]].map(f32::to_bits);
                assert_eq!(px.to_array().map(f32::to_bits), want, "lane {l}");
            }
            let back = from_pixels(&p);
            assert_eq!(
                back.map(|ch| ch.map(f32::to_bits)),
                c.map(|ch| ch.map(f32::to_bits))
            );
        }
    }

    #[test]
    fn store_pixels_is_unorm8_of_each_channel() {
        let mut g = Gen(31);
        for _ in 0..3000 {
            let c: [glam::Vec4; LANES] = std::array::from_fn(|_| {
                glam::Vec4::new(g.float(), g.float(), g.float(), g.float())
            });
            let n = 1 + (g.next() % 12) as usize;
            let m = g.next() as u8;
            let row0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let mut got = row0.clone();
            store_pixels(&mut got, m, &c);
            for (l, px) in got.iter().enumerate() {
                let want = match l < LANES && m & (1 << l) != 0 {
                    true => c[l].to_array().map(unorm8),
                    false => row0[l],
                };
                assert_eq!(*px, want, "l {l} {:?}", c[l.min(LANES - 1)]);
            }
        }
    }

    #[test]
    fn store_rgba_is_unorm8_of_each_lane() {
        let mut g = Gen(17);
        for _ in 0..2000 {
            let c: [[f32; LANES]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| g.float()));
            let n = 1 + (g.next() % 12) as usize;
            let m = g.next() & 0xff;
            let mut got = vec![[9u8; 4]; n];
            store_rgba(&mut got, m, &c);
            for (l, px) in got.iter().enumerate() {
                let want = match m & (1 << l) != 0 {
                    true => std::array::from_fn(|k| unorm8(c[k][l])),
                    false => [9; 4],
                };
                assert_eq!(*px, want, "l {l} {c:?}");
            }
        }
    }
    #[test]
    fn unorm8_and_depth_lanes_are_the_scalar_conversions_bit_for_bit() {
        let mut g = Gen(19);
        for _ in 0..20000 {
            let c: [f32; LANES] = std::array::from_fn(|_| match g.next() % 4 {
                0 => g.float(),
                1 => f32::from_bits(g.next() as u32),
                2 => [f32::INFINITY, f32::NEG_INFINITY, 1.0, -1.0, 0.5, 1e-40]
                    [(g.next() % 6) as usize],
                _ => (g.next() % 300_000) as f32 * 1e-5 - 1.0,
            });
            let u = unorm8_lanes(c);
            let d = depth_lanes(c);
            for l in 0..LANES {
                assert_eq!(
                    u[l],
                    unorm8(c[l]),
                    "unorm8 {} ({:#x})",
                    c[l],
                    c[l].to_bits()
                );
                let want = depth_unorm(f64::from(c[l]));
                assert_eq!(d[l], want, "depth {} ({:#x})", c[l], c[l].to_bits());
            }
        }
    }

    /// `put_wins_avx2` writes each record as `WinLanes::put` does, bit for bit (any f64 bits,
    /// NaN payloads and values that round or overflow as f32 included; any snapped value,
    /// centre and code), leaves the records past the block alone, and writes nothing where the
    /// block does not fit. The layout the kernel needs is today's (`WIN_WORDS`).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn window_records_are_put_field_by_field() {
        const {
            assert!(
                WIN_WORDS,
                "Win's layout changed: the kernel always declines"
            )
        };
        if !is_x86_feature_detected!("avx2") {
            return;
        }
        let g = &mut Gen(0x0057_a11e);
        let f64s = |g: &mut Gen| -> [f64; VERTEX_LANES] {
            std::array::from_fn(|_| match g.next() % 4 {
                0 => f64::from_bits(g.next()),
                1 => f64::from(g.float()),
                _ => (g.next() % 2_000_000) as f64 * 1e-3 - 1000.0 + f64::from(g.float()) * 1e-9,
            })
        };
        let bits = |w: &Win| {
            (
                (w.x.to_bits(), w.y.to_bits(), w.fx, w.fy, w.z.to_bits()),
                (w.iw.to_bits(), w.code, w.cen),
            )
        };
        let any = |g: &mut Gen| Win {
            x: g.float(),
            y: g.float(),
            fx: g.next() as i64,
            fy: g.next() as i64,
            z: f64::from_bits(g.next()),
            iw: g.float(),
            code: g.next() as u16,
            cen: std::array::from_fn(|_| g.next() as i32),
        };
        for _ in 0..200 {
            let lanes = WinLanes::<VERTEX_LANES> {
                xw: f64s(g),
                yw: f64s(g),
                zw: f64s(g),
                iw: f64s(g),
                fx: std::array::from_fn(|_| g.next() as i32),
                fy: std::array::from_fn(|_| g.next() as i32),
                cen: std::array::from_fn(|_| std::array::from_fn(|_| g.next() as i32)),
                code: std::array::from_fn(|_| g.next() as u16),
            };
            let len = VERTEX_LANES + (g.next() % 3) as usize;
            let fill: Vec<Win> = (0..len).map(|_| any(g)).collect();
            let mut want = fill.clone();
            lanes.put(&mut want);
            let mut got = fill.clone();
            // SAFETY: the CPU has AVX2 (checked above).
            assert!(unsafe { put_wins_avx2(&lanes, &mut got) });
            for (k, (a, b)) in got.iter().zip(&want).enumerate() {
                assert_eq!(bits(a), bits(b), "record {k} of {len}");
            }
            let mut short = fill[..VERTEX_LANES - 1].to_vec();
            // SAFETY: as above.
            assert!(!unsafe { put_wins_avx2(&lanes, &mut short) });
            assert!(short.iter().zip(&fill).all(|(a, b)| bits(a) == bits(b)));
        }
    }
}
