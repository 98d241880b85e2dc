//! Structures of arrays for the vertex stage (GL 2.1 §2.11, §2.14.1): `N` vectors as one array
//! per component (`Lanes3`, `Lanes4`), the points a block lights (`Block`) and their clamped lit
//! colours (`Shaded`), with the few element-wise helpers the stage shares.
//!
//! Design decision: every operation here is written one lane at a time with the operations, in
//! the order, of the scalar (glam) code it stands for, so that the compiler vectorises it across
//! lanes and its results are the same bits as the scalar code's, whatever the number of lanes.

use glam::{Mat4, Vec3, Vec4};

/// `x` clamped to [0, 1] exactly as glam's `Vec4::clamp(ZERO, ONE)` does it on SSE2 (`maxps`
/// then `minps`: NaN gives 0, -0 gives +0), one lane at a time so that it vectorises on arrays.
#[inline(always)]
pub(super) fn clamp01(x: f32) -> f32 {
    let t = if x > 0.0 { x } else { 0.0 };
    if t < 1.0 {
        t
    } else {
        1.0
    }
}

/// The lit colours of `N` points on arrays, clamped to [0, 1]: primary rgb and alpha, and the
/// secondary rgb (its alpha is 0).
#[derive(Clone, Copy, Debug)]
pub struct Shaded<const N: usize> {
    /// Primary colour.
    pub c: Lanes3<N>,
    /// Primary alpha.
    pub a: [f32; N],
    /// Secondary colour.
    pub s: Lanes3<N>,
}

impl<const N: usize> Default for Shaded<N> {
    fn default() -> Self {
        Shaded {
            c: Lanes3::splat(Vec3::ZERO),
            a: [0.0; N],
            s: Lanes3::splat(Vec3::ZERO),
        }
    }
}

impl<const N: usize> Shaded<N> {
    /// Point `k`'s (primary, secondary) colours (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, k: usize) -> (Vec4, Vec4) {
        let a = self.a.get(k).copied().unwrap_or(0.0);
        (self.c.get(k).extend(a), self.s.get(k).extend(0.0))
    }

    /// Sets point `k` from `one`'s only point (nothing past the last lane).
    #[inline(always)]
    pub(super) fn set_from(&mut self, k: usize, one: &Shaded<1>) {
        self.c.set(k, one.c.get(0));
        self.s.set(k, one.s.get(0));
        if let Some(a) = self.a.get_mut(k) {
            *a = one.a[0];
        }
    }

    /// Writes point `k`'s primary colour at `col` of `o` (none when `col` is None: written
    /// already), and its secondary colour at `spec`.
    #[inline(always)]
    pub(super) fn put(&self, k: usize, o: &mut [f32], col: Option<usize>, spec: Option<usize>) {
        if let (Some(col), Some(&x), Some(&y), Some(&z), Some(&a)) = (
            col,
            self.c.x.get(k),
            self.c.y.get(k),
            self.c.z.get(k),
            self.a.get(k),
        ) {
            put_arr(o, col, [x, y, z, a]);
        }
        if let (Some(at), Some(&x), Some(&y), Some(&z)) =
            (spec, self.s.x.get(k), self.s.y.get(k), self.s.z.get(k))
        {
            put_arr(o, at, [x, y, z, 0.0]);
        }
    }
}

/// `N` three-component vectors as a structure of arrays (one array per component).
#[derive(Clone, Copy, Debug)]
pub struct Lanes3<const N: usize> {
    /// The x components.
    pub x: [f32; N],
    /// The y components.
    pub y: [f32; N],
    /// The z components.
    pub z: [f32; N],
}

impl<const N: usize> Lanes3<N> {
    /// `v` in every lane.
    #[inline(always)]
    pub fn splat(v: Vec3) -> Self {
        Lanes3 {
            x: [v.x; N],
            y: [v.y; N],
            z: [v.z; N],
        }
    }

    /// Sets lane `i` (nothing past the last lane).
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Vec3) {
        if let (Some(x), Some(y), Some(z)) =
            (self.x.get_mut(i), self.y.get_mut(i), self.z.get_mut(i))
        {
            (*x, *y, *z) = (v.x, v.y, v.z);
        }
    }

    /// Lane `i` (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vec3 {
        match (self.x.get(i), self.y.get(i), self.z.get(i)) {
            (Some(&x), Some(&y), Some(&z)) => Vec3::new(x, y, z),
            _ => Vec3::ZERO,
        }
    }

    /// Every lane negated (exact).
    #[inline(always)]
    pub fn neg(&self) -> Self {
        Lanes3 {
            x: self.x.map(|a| -a),
            y: self.y.map(|a| -a),
            z: self.z.map(|a| -a),
        }
    }
}

/// `N` four-component vectors as a structure of arrays (one array per component).
#[derive(Clone, Copy, Debug)]
pub struct Lanes4<const N: usize> {
    /// The x components.
    pub x: [f32; N],
    /// The y components.
    pub y: [f32; N],
    /// The z components.
    pub z: [f32; N],
    /// The w components.
    pub w: [f32; N],
}

impl<const N: usize> Default for Lanes4<N> {
    fn default() -> Self {
        Lanes4 {
            x: [0.0; N],
            y: [0.0; N],
            z: [0.0; N],
            w: [0.0; N],
        }
    }
}

impl<const N: usize> Lanes4<N> {
    /// `v` in every lane.
    #[inline(always)]
    pub fn splat(v: Vec4) -> Self {
        Lanes4 {
            x: [v.x; N],
            y: [v.y; N],
            z: [v.z; N],
            w: [v.w; N],
        }
    }

    /// Lane `i` (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vec4 {
        match (self.x.get(i), self.y.get(i), self.z.get(i), self.w.get(i)) {
            (Some(&x), Some(&y), Some(&z), Some(&w)) => Vec4::new(x, y, z, w),
            _ => Vec4::ZERO,
        }
    }

    /// The x, y and z components.
    #[inline(always)]
    pub fn xyz(&self) -> Lanes3<N> {
        Lanes3 {
            x: self.x,
            y: self.y,
            z: self.z,
        }
    }

    /// `m` times every lane, with glam's `Mat4 * Vec4` operations in its order
    /// (`((c0·x + c1·y) + c2·z) + c3·w`, no fused multiply-add), so the same bits.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub fn transform(&self, m: &Mat4) -> Self {
        let c = m.to_cols_array();
        let mut r = Self::default();
        for i in 0..N {
            let (x, y, z, w) = (self.x[i], self.y[i], self.z[i], self.w[i]);
            r.x[i] = c[0] * x + c[4] * y + c[8] * z + c[12] * w;
            r.y[i] = c[1] * x + c[5] * y + c[9] * z + c[13] * w;
            r.z[i] = c[2] * x + c[6] * y + c[10] * z + c[14] * w;
            r.w[i] = c[3] * x + c[7] * y + c[11] * z + c[15] * w;
        }
        r
    }
}

/// glam's `normalize_or_zero` on one vector of a [`Lanes3`]: times the reciprocal length when
/// that is finite and positive, else zero.
#[inline(always)]
pub(super) fn normalize_or_zero(x: f32, y: f32, z: f32) -> (f32, f32, f32) {
    let rcp = 1.0 / (x * x + y * y + z * z).sqrt();
    if rcp.is_finite() && rcp > 0.0 {
        (x * rcp, y * rcp, z * rcp)
    } else {
        (0.0, 0.0, 0.0)
    }
}

/// Points transformed and lit together by the vertex stage. 16 executes fewer instructions than
/// 8 (per-block and per-light set-up amortised over more vertices) and far fewer than 4 (measured
/// with callgrind on gauss-smooth-400); results do not depend on it.
pub const LANES: usize = 16;

/// `N` points to light, one array per coordinate: eye positions, unit normals (negated for a
/// back face), vertex colours.
#[derive(Clone, Copy, Debug)]
pub struct Block<const N: usize> {
    /// Eye-space positions.
    pub v: Lanes3<N>,
    /// Normals.
    pub n: Lanes3<N>,
    /// Vertex colours (COLOR_MATERIAL).
    pub color: [Vec4; N],
}

impl<const N: usize> Default for Block<N> {
    fn default() -> Self {
        Block {
            v: Lanes3::splat(Vec3::ZERO),
            n: Lanes3::splat(Vec3::ZERO),
            color: [Vec4::ZERO; N],
        }
    }
}

impl<const N: usize> Block<N> {
    /// Point `k` alone (zero past the last lane).
    pub(super) fn one(&self, k: usize) -> Block<1> {
        Block {
            v: Lanes3::splat(self.v.get(k)),
            n: Lanes3::splat(self.n.get(k)),
            color: [self.color.get(k).copied().unwrap_or(Vec4::ZERO)],
        }
    }

    /// The same points with their normals negated (back faces).
    pub(super) fn back(&self) -> Self {
        Block {
            n: self.n.neg(),
            ..*self
        }
    }
}

/// Writes `v` at `at` of the processed vertex `o` (nothing when it does not fit).
#[inline(always)]
pub(super) fn put_arr(o: &mut [f32], at: usize, v: [f32; 4]) {
    if let Some(d) = o.get_mut(at..at + 4) {
        d.copy_from_slice(&v);
    }
}

/// Loads a whole block's object positions `pos` and normals `nrm` (the batch's arrays of
/// structures, at least [`LANES`] of each) into the structures of arrays `p` and `n`, as the
/// stage's lane-by-lane copy does: eight vertices at a time, the positions through a 4x8
/// transposition (two vertices a 256-bit register) and the normals, three floats apart,
/// through blends of three 256-bit loads and one permutation a coordinate. Moves only, so the
/// same bits. False, nothing loaded, where either array holds fewer than `LANES`.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn load_block_avx2(
    pos: &[Vec4],
    nrm: &[Vec3],
    p: &mut Lanes4<LANES>,
    n: &mut Lanes3<LANES>,
) -> bool {
    use std::arch::x86_64::{
        _mm256_blend_ps, _mm256_castps128_ps256, _mm256_insertf128_ps, _mm256_loadu_ps,
        _mm256_permutevar8x32_ps, _mm256_setr_epi32, _mm256_shuffle_ps, _mm256_storeu_ps,
        _mm256_unpackhi_ps, _mm256_unpacklo_ps, _mm_loadu_ps,
    };
    // A Vec4 is four f32 (x, y, z, w), a Vec3 three (x, y, z), without padding.
    const { assert!(size_of::<Vec4>() == 16 && size_of::<Vec3>() == 12) };
    if pos.len() < LANES || nrm.len() < LANES {
        return false;
    }
    let (src_p, src_n) = (pos.as_ptr().cast::<f32>(), nrm.as_ptr().cast::<f32>());
    for h in (0..LANES).step_by(8) {
        // SAFETY: the CPU has AVX2 (this function's contract); vertex h + k (k < 8, so
        // h + k < LANES <= both lengths) is the four f32 at 4(h + k) of `pos` and the three at
        // 3(h + k) of `nrm`: the 128-bit loads read pos[h + k] whole, the three 256-bit loads
        // of the normals the 24 f32 of nrm[h..h + 8] (no alignment needed); the stores write
        // eight f32 of a `[f32; LANES]` at h, h + 8 <= LANES.
        unsafe {
            let v = |k: usize| _mm_loadu_ps(src_p.add(4 * (h + k)));
            // Vertex k in the low half, k + 4 in the high half.
            let pair = |k: usize| _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(v(k)), v(k + 4));
            let (a, b, c, d) = (pair(0), pair(1), pair(2), pair(3));
            // x0 x1 y0 y1 | x4 x5 y4 y5 and the like.
            let (ab0, ab1) = (_mm256_unpacklo_ps(a, b), _mm256_unpackhi_ps(a, b));
            let (cd0, cd1) = (_mm256_unpacklo_ps(c, d), _mm256_unpackhi_ps(c, d));
            _mm256_storeu_ps(p.x.as_mut_ptr().add(h), _mm256_shuffle_ps::<0x44>(ab0, cd0));
            _mm256_storeu_ps(p.y.as_mut_ptr().add(h), _mm256_shuffle_ps::<0xee>(ab0, cd0));
            _mm256_storeu_ps(p.z.as_mut_ptr().add(h), _mm256_shuffle_ps::<0x44>(ab1, cd1));
            _mm256_storeu_ps(p.w.as_mut_ptr().add(h), _mm256_shuffle_ps::<0xee>(ab1, cd1));
            // m0 = x0 y0 z0 x1 y1 z1 x2 y2, m1 = z2 x3 y3 z3 x4 y4 z4 x5,
            // m2 = y5 z5 x6 y6 z6 x7 y7 z7: each coordinate sits in positions 0, 3, 6 of one
            // load, 1, 4, 7 of the next and 2, 5 of the third (cyclically), so two blends
            // gather it and one permutation puts it in order.
            let m = src_n.add(3 * h);
            let (m0, m1, m2) = (
                _mm256_loadu_ps(m),
                _mm256_loadu_ps(m.add(8)),
                _mm256_loadu_ps(m.add(16)),
            );
            // x: m0 at 0, 3, 6; m1 at 1, 4, 7; m2 at 2, 5 -> x0 x3 x6 x1 x4 x7 x2 x5.
            let bx = _mm256_blend_ps::<0b0010_0100>(_mm256_blend_ps::<0b1001_0010>(m0, m1), m2);
            // y: m0 at 1, 4, 7; m1 at 2, 5; m2 at 0, 3, 6 -> y5 y0 y3 y6 y1 y4 y7 y2.
            let by = _mm256_blend_ps::<0b0100_1001>(_mm256_blend_ps::<0b0010_0100>(m0, m1), m2);
            // z: m0 at 2, 5; m1 at 0, 3, 6; m2 at 1, 4, 7 -> z2 z5 z0 z3 z6 z1 z4 z7.
            let bz = _mm256_blend_ps::<0b1001_0010>(_mm256_blend_ps::<0b0100_1001>(m0, m1), m2);
            let ix = _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
            let iy = _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6);
            let iz = _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7);
            _mm256_storeu_ps(n.x.as_mut_ptr().add(h), _mm256_permutevar8x32_ps(bx, ix));
            _mm256_storeu_ps(n.y.as_mut_ptr().add(h), _mm256_permutevar8x32_ps(by, iy));
            _mm256_storeu_ps(n.z.as_mut_ptr().add(h), _mm256_permutevar8x32_ps(bz, iz));
        }
    }
    true
}

/// Writes the clip positions `clip` and primary colours (`c`, alpha `a`) of a whole block of
/// [`LANES`] lit vertices into the processed vertices `o` (`stride` floats each), as
/// [`put_arr`] and [`Shaded::put`] write them one vertex at a time: the first eight floats of
/// a processed vertex, the clip position at 0 and the colour at 4 (`Layout::col`), eight
/// vertices at a time through one 8x8 transposition in registers (24 shuffles and eight
/// 256-bit stores for what took ≈36 scalar instructions a vertex). Moves only, so the same
/// bits. False, nothing written, where `o` is too short for the block or `stride` below 8
/// (the caller then writes vertex by vertex).
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) unsafe fn put_clip_col_avx2(
    o: &mut [f32],
    stride: usize,
    clip: &Lanes4<LANES>,
    c: &Lanes3<LANES>,
    a: &[f32; LANES],
) -> bool {
    use std::arch::x86_64::{
        _mm256_loadu_ps, _mm256_permute2f128_ps, _mm256_shuffle_ps, _mm256_storeu_ps,
        _mm256_unpackhi_ps, _mm256_unpacklo_ps,
    };
    // The last vertex's eight floats end at (LANES - 1)·stride + 8.
    let fits = stride >= 8
        && (LANES - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(8))
            .is_some_and(|n| n <= o.len());
    if !fits {
        return false;
    }
    let dst = o.as_mut_ptr();
    for h in (0..LANES).step_by(8) {
        // SAFETY: the CPU has AVX2 (this function's contract); each load reads eight f32 of a
        // `[f32; LANES]` at h, h + 8 <= LANES (no alignment needed); each store writes eight
        // f32 at (h + k)·stride for k < 8, h + k <= LANES - 1, so it ends at or before
        // (LANES - 1)·stride + 8 <= o.len() (`fits`).
        unsafe {
            let ld = |r: &[f32; LANES]| _mm256_loadu_ps(r.as_ptr().add(h));
            let (x, y, z, w) = (ld(&clip.x), ld(&clip.y), ld(&clip.z), ld(&clip.w));
            let (r, g, b, al) = (ld(&c.x), ld(&c.y), ld(&c.z), ld(a));
            // Pairs: x0 y0 x1 y1 | x4 y4 x5 y5, and so on.
            let (xy0, xy1) = (_mm256_unpacklo_ps(x, y), _mm256_unpackhi_ps(x, y));
            let (zw0, zw1) = (_mm256_unpacklo_ps(z, w), _mm256_unpackhi_ps(z, w));
            let (rg0, rg1) = (_mm256_unpacklo_ps(r, g), _mm256_unpackhi_ps(r, g));
            let (ba0, ba1) = (_mm256_unpacklo_ps(b, al), _mm256_unpackhi_ps(b, al));
            // Quads: vertex v's clip position in the low half, v + 4's in the high half.
            let p = [
                _mm256_shuffle_ps::<0x44>(xy0, zw0),
                _mm256_shuffle_ps::<0xee>(xy0, zw0),
                _mm256_shuffle_ps::<0x44>(xy1, zw1),
                _mm256_shuffle_ps::<0xee>(xy1, zw1),
            ];
            let q = [
                _mm256_shuffle_ps::<0x44>(rg0, ba0),
                _mm256_shuffle_ps::<0xee>(rg0, ba0),
                _mm256_shuffle_ps::<0x44>(rg1, ba1),
                _mm256_shuffle_ps::<0xee>(rg1, ba1),
            ];
            for v in 0..4 {
                let lo = _mm256_permute2f128_ps::<0x20>(p[v], q[v]);
                let hi = _mm256_permute2f128_ps::<0x31>(p[v], q[v]);
                _mm256_storeu_ps(dst.add((h + v) * stride), lo);
                _mm256_storeu_ps(dst.add((h + v + 4) * stride), hi);
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::testgen::Gen;

    /// Runs `test` with a generator seeded `seed` where the CPU has AVX2, which the kernels
    /// compared here need (else a note).
    #[cfg(target_arch = "x86_64")]
    fn on_avx2(seed: u64, test: impl FnOnce(&mut Gen)) {
        if is_x86_feature_detected!("avx2") {
            test(&mut Gen(seed));
        } else {
            eprintln!("no AVX2 on this CPU: nothing to compare");
        }
    }

    /// `load_block_avx2` fills the structures of arrays as the stage's lane-by-lane copy does,
    /// bit for bit, from any of a longer batch's blocks, and loads nothing from fewer than
    /// `LANES` vertices.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn block_load_transposition_is_the_copy() {
        on_avx2(0x0b10_c4ed, |g| {
            let bits = |v: &[f32]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
            for _ in 0..50 {
                let len = LANES + (g.next() % 20) as usize;
                let pos: Vec<Vec4> = (0..len)
                    .map(|_| Vec4::new(g.float(), g.float(), g.float(), g.float()))
                    .collect();
                let nrm: Vec<Vec3> = (0..len)
                    .map(|_| Vec3::new(g.float(), g.float(), g.float()))
                    .collect();
                let at = (g.next() as usize) % (len - LANES + 1);
                let (ps, ns) = (&pos[at..], &nrm[at..]);
                let (mut p, mut n) = (Lanes4::<LANES>::default(), Lanes3::splat(Vec3::ZERO));
                // SAFETY: the CPU has AVX2 (`on_avx2` runs this only there).
                assert!(unsafe { load_block_avx2(ps, ns, &mut p, &mut n) });
                for k in 0..LANES {
                    let (q, m) = (ps[k], ns[k]);
                    assert_eq!(
                        bits(&[p.x[k], p.y[k], p.z[k], p.w[k], n.x[k], n.y[k], n.z[k]]),
                        bits(&[q.x, q.y, q.z, q.w, m.x, m.y, m.z]),
                        "vertex {k} of the block at {at}"
                    );
                }
                let (mut p2, mut n2) = (Lanes4::<LANES>::default(), Lanes3::splat(Vec3::ZERO));
                // SAFETY: as above.
                let short = unsafe { load_block_avx2(&ps[..LANES - 1], ns, &mut p2, &mut n2) }
                    // SAFETY: as above.
                    || unsafe { load_block_avx2(ps, &ns[..LANES - 1], &mut p2, &mut n2) };
                assert!(!short && p2.x.iter().chain(&n2.z).all(|&v| v == 0.0));
            }
        });
    }

    /// `put_clip_col_avx2` writes each vertex's first eight floats as `put_arr` and
    /// `Shaded::put` do one vertex at a time, bit for bit (awkward floats, NaN payloads
    /// included), leaves every other float alone, and writes nothing where the block does not
    /// fit.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn clip_col_transposition_is_put_arr() {
        on_avx2(0x5eed_0b10, |g| {
            for stride in [8, 9, 12, 16, 20, 27] {
                for _ in 0..20 {
                    let mut clip = Lanes4::<LANES>::default();
                    let mut sh = Shaded::<LANES>::default();
                    for k in 0..LANES {
                        (clip.x[k], clip.y[k], clip.z[k], clip.w[k]) =
                            (g.float(), g.float(), g.float(), g.float());
                        sh.c.set(k, Vec3::new(g.float(), g.float(), g.float()));
                        sh.a[k] = g.float();
                    }
                    let fill: Vec<f32> = (0..LANES * stride + 5).map(|_| g.float()).collect();
                    let mut want = fill.clone();
                    for (k, o) in want.chunks_exact_mut(stride).enumerate().take(LANES) {
                        put_arr(o, 0, [clip.x[k], clip.y[k], clip.z[k], clip.w[k]]);
                        sh.put(k, o, Some(4), None);
                    }
                    let mut got = fill.clone();
                    // SAFETY: the CPU has AVX2 (`on_avx2` runs this only there).
                    let ok = unsafe { put_clip_col_avx2(&mut got, stride, &clip, &sh.c, &sh.a) };
                    assert!(ok, "stride {stride}: the block fits");
                    let bits = |v: &[f32]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&got), bits(&want), "stride {stride}");
                    // Too short by one float, or a stride below the eight floats written.
                    let n = (LANES - 1) * stride + 7;
                    let mut short = fill.get(..n).unwrap_or_default().to_vec();
                    // SAFETY: as above.
                    let ok = unsafe { put_clip_col_avx2(&mut short, stride, &clip, &sh.c, &sh.a) };
                    assert!(!ok && bits(&short) == bits(&fill[..n]), "stride {stride}");
                    let mut narrow = fill.clone();
                    // SAFETY: as above.
                    let ok = unsafe { put_clip_col_avx2(&mut narrow, 7, &clip, &sh.c, &sh.a) };
                    assert!(!ok && bits(&narrow) == bits(&fill));
                }
            }
        });
    }
}
