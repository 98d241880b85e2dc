//! Lane routes of [`Sampler`] beyond the 2D texture: 1D and 3D textures and cube maps
//! ([`Sampler::targets_lanes`]), and the COMBINE environment ([`Sampler::env_lanes_with`]).
//! Each lane computes the scalar route's expressions in the same order (`texel`'s division by q,
//! `cube_face`/`cube_project`, `select`, `nearest`/`linear` with `fetch`'s border and depth
//! comparison, `sample_face`'s level blend, `combine`), so each lane's result has the bits
//! [`Sampler::texel`] and [`Sampler::shade_texel`] give for its fragment (checked bit for bit
//! in `tests/texture_targets.rs`). The wrap indices and weights are computed on all eight lanes
//! (`wrap_nearest_lanes`, `wrap_linear_lanes`), the texels gathered lane by lane.

use glam::Vec4;

#[cfg(target_arch = "x86_64")]
use super::{avx2, cube8, lanes8, linear_axis8, span::select8, store8};
use super::{
    cube_face, cube_project, dense_kernel, depth_compare, fast_log2_lane, inv_q_lanes, kernel_kind,
    lambda_point, mask_eq, mask_ne_zero, mul_lanes, wrap_linear_lanes, wrap_nearest_lanes, Axis,
    Route, Sampler, TexelLanes, Texels,
};
use crate::cpu::lanes::LANES;
use crate::gl;
use crate::texture::Level;

/// The images the lanes of a [`Sampler::pass_targets`] read: lane l's texels and its level's
/// width, height and depth.
struct Views3<'a> {
    tx: [&'a [[f32; 4]]; LANES],
    w: [i32; LANES],
    h: [i32; LANES],
    d: [i32; LANES],
}

/// At most this many lanes of a group are filtered one by one by [`Sampler::texel`] instead
/// of by the lane passes: the passes compute their wraps and weights on all eight lanes, which
/// costs more than the scalar route for a sparse group (the small triangles of a sphere).
/// Measured again in the eighth session (texture-targets, callgrind, millions of
/// instructions): 0 929.5, 1 894.0, 2 877.3, 3 872.6, 4 876.0. The eleventh session, with the
/// AVX2 kernels and λ (a lane-pass group ≈896 instructions, a sparse lane ≈354): 1 727.9,
/// 2 721.4, 3 726.5. The thirteenth session, with both levels of a 1D/3D group in one kernel
/// (`lod_dense`): 1 690.08, 2 686.92 (of which the draws 534.02 and 528.81). The fifteenth
/// session, per target (cube map, 1D, 3D; the cube route's faces now computed for the lanes
/// of the group only): 2,2,2 646.32, 1,2,2 645.34, 0,2,2 649.71, 2,3,2 649.50, 2,2,1
/// 645.57, 1,1,1 646.17, 1,2,1 644.59: [`SPARSE`] for 1D textures (and 2D ones, which do not
/// come here), [`SPARSE_CUBE`] and [`SPARSE_3D`] (a 3D lane filters up to sixteen texels).
const SPARSE: u32 = 2;
/// [`SPARSE`] for a cube map.
const SPARSE_CUBE: u32 = 1;
/// [`SPARSE`] for a 3D texture.
const SPARSE_3D: u32 = 1;

/// Can a one-level pass gather `tx`, a level of `n` texels (width, height, depth), through an
/// index mask: at least one texel per axis, exactly w·h·d texels, a power-of-two count that
/// fits an i32 (the 2D passes' `dense_level` with a depth). Then every index ((k·h + j)·w + i)
/// of an in-image texel lies in 0..tx.len(), where `& (tx.len() - 1)` keeps it: the texel
/// `Level::texel3` reads.
#[inline(always)]
fn dense3(tx: &[[f32; 4]], [w, h, d]: [i32; 3]) -> bool {
    let len = tx.len();
    w >= 1
        && h >= 1
        && d >= 1
        && len.is_power_of_two()
        && len <= i32::MAX as usize
        && (w as usize)
            .checked_mul(h as usize)
            .and_then(|n| n.checked_mul(d as usize))
            == Some(len)
}

impl Sampler {
    /// `texels_lanes` for a 1D or 3D texture or a cube map: the coordinates (s, t, r, q) of
    /// the lanes, λ before bias, the lanes of `m` (the others are left zero). A group of at
    /// most [`SPARSE`] lanes takes [`Sampler::texel`] per lane; the others `texel`'s division
    /// by q on lanes (as `texels_lanes`), then [`Sampler::targets_lanes`].
    #[inline]
    pub(super) fn targets_texels(
        &self,
        coords: [&[f32; LANES]; 4],
        lambda: &[f32; LANES],
        m: u8,
    ) -> TexelLanes {
        let [s, t, r, q] = coords;
        let mut out = [[0.0f32; 4]; LANES];
        let sparse = match (self.cube, self.dims) {
            (true, _) => SPARSE_CUBE,
            (false, 3) => SPARSE_3D,
            _ => SPARSE,
        };
        if m.count_ones() <= sparse {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = self.texel([s[l], t[l], r[l], q[l]], lambda[l]);
                }
            }
            return out;
        }
        // On SSE2 registers (as a lane loop of all three, LLVM did not always vectorise it:
        // ≈28 instructions a group more in one build).
        let inv = inv_q_lanes(q);
        let (ss, tt, rr) = (mul_lanes(s, &inv), mul_lanes(t, &inv), mul_lanes(r, &inv));
        // The AVX2 route called from here (through `targets_lanes`' check, its call and
        // arguments cost ≈25 instructions a group more).
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: AVX2 is present (checked just above).
            unsafe { self.targets_lanes8(&ss, &tt, &rr, lambda, m, &mut out) };
            return out;
        }
        self.targets_lanes(&ss, &tt, &rr, lambda, m, &mut out);
        out
    }

    /// `texels_lanes` for a 1D or 3D texture or a cube map, from the lanes' coordinates
    /// already divided by q (`s`, `t`, `r`) and λ before bias, into `out` (zeroed: the AVX2
    /// trilinear kernel stores all eight lanes, those outside `m` zero) for the lanes of `m`
    /// (the others are left zero). A cube map picks each lane's face and face
    /// coordinates as `texel` does; then the flush's route (NEAREST, LINEAR, or λ's choice per
    /// lane) on each lane's face. Without AVX2 (with it, [`Sampler::targets_lanes8`]).
    #[inline]
    pub(super) fn targets_lanes(
        &self,
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        lambda: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        let mut face = [0i32; LANES];
        let (mut fs, mut ft) = ([0.0f32; LANES], [0.0f32; LANES]);
        let (s, t) = match self.cube {
            false => (s, t),
            true => {
                // The lanes of `m` only: the others' face and coordinates are read by nobody.
                let mut b = m;
                while b != 0 {
                    let l = b.trailing_zeros() as usize & (LANES - 1);
                    b &= b - 1;
                    let p = [s[l], t[l], r[l]];
                    let (f, _) = cube_face(p);
                    (fs[l], ft[l]) = cube_project(f, p);
                    face[l] = f as i32;
                }
                (&fs, &ft)
            }
        };
        let sel = match self.route {
            Route::Lod => Some(self.select_lanes(lambda)),
            _ => None,
        };
        self.targets_route(&face, s, t, r, sel, m, out);
    }

    /// [`Sampler::targets_lanes`] on AVX2 registers: a cube map's faces and face coordinates
    /// for the eight lanes at once ([`cube8`]: `cube_face` and `cube_project` bit for bit;
    /// per lane they cost ≈30 instructions a lane on texture-targets), λ's level choice by
    /// [`select8`] (`select_lanes` bit for bit, without its lane loops through memory).
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn targets_lanes8(
        &self,
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        lambda: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        use std::arch::x86_64::{__m256, __m256i};
        let ints = |v: __m256i| {
            // SAFETY: `__m256i` has the layout of `[i32; 8]`, every bit pattern valid for both.
            unsafe { std::mem::transmute::<__m256i, [i32; LANES]>(v) }
        };
        let floats = |v: __m256| {
            // SAFETY: `__m256` has the layout of `[f32; 8]`.
            unsafe { std::mem::transmute::<__m256, [f32; LANES]>(v) }
        };
        let mut face = [0i32; LANES];
        let (fs, ft);
        let (s, t) = match self.cube {
            false => (s, t),
            true => {
                let (f, a, b) = cube8(lanes8(s), lanes8(t), lanes8(r));
                (face, fs, ft) = (ints(f), floats(a), floats(b));
                (&fs, &ft)
            }
        };
        let sel = match self.route {
            Route::Lod => {
                let (lv, linear, f) = select8(self, lanes8(lambda));
                Some((ints(lv), linear, floats(f)))
            }
            _ => None,
        };
        self.targets_route(&face, s, t, r, sel, m, out);
    }

    /// The flush's route for the lanes of `m` on faces `face` with face coordinates `s`, `t`
    /// (and `r`): NEAREST or LINEAR on the base level, or (`sel`, `select_lanes`' levels,
    /// LINEAR lanes and weights) λ's choice per lane ([`Sampler::lod_targets`]).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn targets_route(
        &self,
        face: &[i32; LANES],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        sel: Option<([i32; LANES], u8, [f32; LANES])>,
        m: u8,
        out: &mut TexelLanes,
    ) {
        let base = [self.base_level; LANES];
        match sel {
            Some((la, linear, f)) => self.lod_targets(face, &la, linear, &f, s, t, r, m, out),
            None => self.pass_targets(self.route == Route::Linear, face, &base, s, t, r, m, out),
        }
    }

    /// `sample_face` for the lanes of `m`, lane l on face `face[l]`: each lane's level(s),
    /// filter and weight from `select` (`la`, `linear`, `f`: `select_lanes`), a pass per
    /// filter over the lanes using it, then the second level of the lanes that blend two and
    /// the blend (`sample_face`'s expression).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn lod_targets(
        &self,
        face: &[i32; LANES],
        la: &[i32; LANES],
        linear: u8,
        f: &[f32; LANES],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        let mut lb = [self.base_level; LANES];
        let (linear, second) = (linear & m, mask_ne_zero(f) & m);
        if linear == m && self.lod_dense(la, s, t, r, f, second, m, out) {
            return;
        }
        self.pass_targets(false, face, la, s, t, r, m & !linear, out);
        self.pass_targets(true, face, la, s, t, r, linear, out);
        if second == 0 {
            return;
        }
        for l in 0..LANES {
            if second & (1 << l) != 0 {
                // f ≠ 0 only below the last level: level + 1 exists.
                lb[l] = la[l].saturating_add(1);
            }
        }
        let mut b = [[0.0f32; 4]; LANES];
        self.pass_targets(false, face, &lb, s, t, r, second & !linear, &mut b);
        self.pass_targets(true, face, &lb, s, t, r, second & linear, &mut b);
        for l in 0..LANES {
            if second & (1 << l) != 0 {
                // `sample_face`'s a·(1 - f) + b·f on the four channels at once.
                let (a, b, f) = (Vec4::from_array(out[l]), Vec4::from_array(b[l]), f[l]);
                out[l] = (a * Vec4::splat(1.0 - f) + b * Vec4::splat(f)).to_array();
            }
        }
    }

    /// `lod_targets` in one AVX2 kernel ([`dense_targets_lod`]) when it can take the group:
    /// a 1D or 3D texture without depth comparison, every lane of `m` LINEAR on one level
    /// `lv` (the common case: λ is per quad), that level and, when some lane blends two
    /// (`second`, its weight in `f`), the next one dense ([`dense3`]) with wrap modes the
    /// kernel takes ([`targets_kernel_ok`], [`in_image`]). Both levels as
    /// `pass_targets` computes them, and `sample_face`'s blend, without the texels of the
    /// levels going through memory between the passes. Returns false (nothing written) for
    /// any other group.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn lod_dense(
        &self,
        lv: &[i32; LANES],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        f: &[f32; LANES],
        second: u8,
        m: u8,
        out: &mut TexelLanes,
    ) -> bool {
        if m == 0 || self.lod_kernel == 0 {
            return false;
        }
        let k0 = lv[m.trailing_zeros() as usize & (LANES - 1)];
        if !mask_eq(lv, k0) & m != 0 {
            return false;
        }
        // The level's bit in `lod_kernel` (decided once a flush by `target_levels`; a
        // negative level shifts by more than 15 and has none).
        let dense = |k: i32| {
            if self.lod_kernel.checked_shr(k as u32).unwrap_or(0) & 1 == 0 {
                return None;
            }
            let x = self.obj.face_level(0, k)?;
            Some((&x.texels[..], [x.width, x.height, x.depth]))
        };
        let Some(a) = dense(k0) else {
            return false;
        };
        // f ≠ 0 only below the last level: level + 1 exists (`lod_targets`).
        let b = match second {
            0 => None,
            _ => match dense(k0.saturating_add(1)) {
                Some(b) => Some(b),
                None => return false,
            },
        };
        let rep = self.wrap.map(|mode| mode == gl::REPEAT);
        dense_targets_lod(self.dims, rep, a, b, [s, t, r], f, second, m, out)
    }

    /// NEAREST (`linear` false) or LINEAR for the lanes of `m`, lane l on level `lv[l]` of
    /// face `face[l]`: `nearest` and `linear` for this sampler's dimensions. A lane whose level
    /// is missing gets (0, 0, 0, 0), as the scalar filters give.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pass_targets(
        &self,
        linear: bool,
        face: &[i32; LANES],
        lv: &[i32; LANES],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        if m == 0 {
            return;
        }
        // Whether every lane of `m` is on one (face, level), compared on all eight lanes at
        // once (the common case): then one lookup, and the pass reads that one image with its
        // sizes in registers (as the 2D passes' one-level route). Looking the level up per lane
        // and filling the per-lane views cost ≈270 instructions a group on texture-targets.
        let first = m.trailing_zeros() as usize & (LANES - 1);
        let (f0, k0) = (face[first], lv[first]);
        // The levels by one SSE2 compare (the per-lane loop of both was ≈64 instructions a
        // call on texture-targets); the faces only for a cube map (else all 0), the same way
        // (a loop over the lanes was ≈35 instructions a call).
        let mut other = !mask_eq(lv, k0);
        if self.cube {
            other |= !mask_eq(face, f0);
        }
        if other & m == 0 {
            let Some(x) = self.obj.face_level(f0 as usize, k0) else {
                for (l, o) in out.iter_mut().enumerate() {
                    if m & (1 << l) != 0 {
                        *o = [0.0; 4];
                    }
                }
                return;
            };
            let tx: &[[f32; 4]] = &x.texels[..];
            let n = [x.width, x.height, x.depth];
            // `dense3` and `in_image` as decided once a flush (`target_levels`).
            if self.dense_level(f0, k0) && self.in_image[usize::from(linear)] {
                // Without comparison, the kernels: a cube face (2D) by the 2D sampler's
                // `dense_kernel`, a 1D or 3D LINEAR level by `dense_targets` (AVX2).
                if self.compare.is_none() {
                    if self.dims == 2 {
                        if let Some(kind) = kernel_kind(linear, self.wrap) {
                            return dense_kernel(kind, tx, n[0], n[1], s, t, m, out);
                        }
                    } else if linear && targets_kernel_ok(self.dims, self.wrap, tx.len()) {
                        let rep = self.wrap.map(|mode| mode == gl::REPEAT);
                        return dense_targets(self.dims, rep, tx, n, s, t, r, m, out);
                    }
                }
                match self.compare {
                    None => self.pass_dense(linear, tx, n, s, t, r, m, out, |_, x| x),
                    Some(func) => self.pass_dense(linear, tx, n, s, t, r, m, out, |l, x| {
                        depth_compare(func, r[l], x)
                    }),
                }
            } else {
                self.pass_targets_cmp(linear, tx, n, s, t, r, m, out)
            }
            return;
        }
        // The lanes on two or more (face, level) pairs: each lane's level, looked up once per
        // run of equal pairs.
        let empty: &[[f32; 4]] = &[];
        let mut v = Views3 {
            tx: [empty; LANES],
            w: [1; LANES],
            h: [1; LANES],
            d: [1; LANES],
        };
        let mut have = 0u8;
        let mut cur: Option<(i32, i32, Option<&Level>)> = None;
        for l in 0..LANES {
            if m & (1 << l) == 0 {
                continue;
            }
            let level = match cur {
                Some((f, k, x)) if f == face[l] && k == lv[l] => x,
                _ => {
                    let x = self.obj.face_level(face[l] as usize, lv[l]);
                    cur = Some((face[l], lv[l], x));
                    x
                }
            };
            if let Some(x) = level {
                (v.tx[l], v.w[l], v.h[l], v.d[l]) = (&x.texels[..], x.width, x.height, x.depth);
                have |= 1 << l;
            } else {
                out[l] = [0.0; 4];
            }
        }
        let m = m & have;
        if m == 0 {
            return;
        }
        self.pass_targets_cmp(linear, &v.tx, [&v.w, &v.h, &v.d], s, t, r, m, out)
    }

    /// Is level `k` of face `f` one that [`dense3`] holds for (`Sampler::dense`, decided
    /// once a flush by [`target_levels`])?
    #[inline(always)]
    fn dense_level(&self, f: i32, k: i32) -> bool {
        let bits = self.dense.get(f as usize).copied().unwrap_or(0);
        bits.checked_shr(k as u32).unwrap_or(0) & 1 != 0
    }

    /// Each axis's NEAREST index and inside flag (`wrap_nearest_lanes`) for coordinates `s`,
    /// `t`, `r` on sizes `w`, `h`, `d`; the axes a texture of fewer dimensions lacks are index
    /// 0, inside.
    #[inline(always)]
    fn nearest_axes<A: Axis + Copy>(
        &self,
        [s, t, r]: [&[f32; LANES]; 3],
        [w, h, d]: [A; 3],
    ) -> [([i32; LANES], [bool; LANES]); 3] {
        let zero = ([0i32; LANES], [true; LANES]);
        [
            wrap_nearest_lanes(self.wrap[0], s, w),
            match self.dims >= 2 {
                true => wrap_nearest_lanes(self.wrap[1], t, h),
                false => zero,
            },
            match self.dims == 3 {
                true => wrap_nearest_lanes(self.wrap[2], r, d),
                false => zero,
            },
        ]
    }

    /// `pass_targets_on` for every lane on one level `dt` of `n` texels (width, height,
    /// depth) that [`dense3`] holds for, with wrap modes that keep every index inside the
    /// image ([`in_image`]): each index ((k·h + j)·w + i) of an in-image texel is
    /// below dt.len(), a power of two, so `& (dt.len() - 1)` keeps it, and the gathers need no
    /// bounds check and no border choice. The weights and blends are `pass_targets_on`'s.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pass_dense(
        &self,
        linear: bool,
        dt: &[[f32; 4]],
        [w, h, d]: [i32; 3],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
        cmp: impl Fn(usize, [f32; 4]) -> [f32; 4],
    ) {
        let Some(km) = dt.len().checked_sub(1) else {
            return;
        };
        let dims = self.dims;
        // ((k·h + j)·w + i) = k·(h·w) + j·w + i: the same value (below 2^31) in wrapping i32.
        let slab = h.wrapping_mul(w);
        // The gathers (macros: as closures they were not always inlined, a call of ≈13
        // instructions per texel).
        macro_rules! at {
            ($l:expr, $k:expr) => {{
                let (l, k): (usize, i32) = ($l, $k);
                cmp(l, dt[k as usize & km])
            }};
        }
        macro_rules! tv {
            ($l:expr, $k:expr) => {
                Vec4::from_array(at!($l, $k))
            };
        }
        if !linear {
            let [(i, _), (j, _), (k, _)] = self.nearest_axes([s, t, r], [w, h, d]);
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    let n = k[l]
                        .wrapping_mul(slab)
                        .wrapping_add(j[l].wrapping_mul(w))
                        .wrapping_add(i[l]);
                    *o = at!(l, n);
                }
            }
            return;
        }
        let x = wrap_linear_lanes(self.wrap[0], s, w);
        if dims == 1 {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) == 0 {
                    continue;
                }
                let (t0, t1) = (tv!(l, x.i0[l]), tv!(l, x.i1[l]));
                let a = x.w[l];
                // (1 - α)·t0 + α·t1.
                *o = (Vec4::splat(1.0 - a) * t0 + Vec4::splat(a) * t1).to_array();
            }
            return;
        }
        let y = wrap_linear_lanes(self.wrap[1], t, h);
        let mut wt = [[0.0f32; LANES]; 4];
        for (l, (&a, &b)) in x.w.iter().zip(&y.w).enumerate() {
            wt[0][l] = (1.0 - a) * (1.0 - b);
            wt[1][l] = a * (1.0 - b);
            wt[2][l] = (1.0 - a) * b;
            wt[3][l] = a * b;
        }
        // `linear`'s `plane` at the slab offset `k0` for lane l (a macro: as a closure it was
        // not inlined, a call of ≈77 instructions per plane).
        macro_rules! plane {
            ($l:expr, $k0:expr) => {{
                let (l, k0): (usize, i32) = ($l, $k0);
                let (r0, r1) = (
                    k0.wrapping_add(y.i0[l].wrapping_mul(w)),
                    k0.wrapping_add(y.i1[l].wrapping_mul(w)),
                );
                let t00 = tv!(l, r0.wrapping_add(x.i0[l]));
                let t10 = tv!(l, r0.wrapping_add(x.i1[l]));
                let t01 = tv!(l, r1.wrapping_add(x.i0[l]));
                let t11 = tv!(l, r1.wrapping_add(x.i1[l]));
                weigh(&wt, l, [t00, t10, t01, t11])
            }};
        }
        if dims == 2 {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = plane!(l, 0).to_array();
                }
            }
            return;
        }
        let z = wrap_linear_lanes(self.wrap[2], r, d);
        for (l, o) in out.iter_mut().enumerate() {
            if m & (1 << l) == 0 {
                continue;
            }
            let p0 = plane!(l, z.i0[l].wrapping_mul(slab));
            let p1 = plane!(l, z.i1[l].wrapping_mul(slab));
            let g = z.w[l];
            // (1 - γ)·p0 + γ·p1.
            *o = (Vec4::splat(1.0 - g) * p0 + Vec4::splat(g) * p1).to_array();
        }
    }

    /// `pass_targets` on the images `tx` of sizes `n` (width, height, depth; per lane or one
    /// for all), with `fetch`'s depth comparison when the sampler has one.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pass_targets_cmp<A: Axis, T: Texels>(
        &self,
        linear: bool,
        tx: T,
        n: [A; 3],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        match self.compare {
            None => self.pass_targets_on(linear, tx, n, s, t, r, m, out, |_, x| x),
            Some(func) => self.pass_targets_on(linear, tx, n, s, t, r, m, out, |l, x| {
                depth_compare(func, r[l], x)
            }),
        }
    }

    /// `pass_targets` on the images `tx` of sizes `n`, `cmp(l, texel)` giving what `fetch`
    /// makes of lane l's texel (itself, or the comparison result against the lane's r).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pass_targets_on<A: Axis, T: Texels>(
        &self,
        linear: bool,
        tx: T,
        [nw, nh, nd]: [A; 3],
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
        cmp: impl Fn(usize, [f32; 4]) -> [f32; 4],
    ) {
        let dims = self.dims;
        // `fetch`: the image's texel (`Level::texel3`'s expression; `texel` is it at k = 0,
        // and a 1D image's at j = k = 0) or the border colour, through `cmp`.
        let border = crate::texture::keep(self.base, self.border);
        let texel = |l: usize, i: i32, j: i32, k: i32, inside: bool| {
            cmp(
                l,
                if inside {
                    let n = ((k * nh.at(l) + j) * nw.at(l) + i) as usize;
                    tx.get(l, n)
                } else {
                    border
                },
            )
        };
        if !linear {
            let [(i, ii), (j, ji), (k, ki)] = self.nearest_axes([s, t, r], [nw, nh, nd]);
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = texel(l, i[l], j[l], k[l], ii[l] && ji[l] && ki[l]);
                }
            }
            return;
        }
        // The blends below are `linear`'s per-channel expressions on the four channels at
        // once (`Vec4`: the same IEEE operations, in the same order, on each channel).
        let tv = |l: usize, i: i32, j: i32, k: i32, inside: bool| {
            Vec4::from_array(texel(l, i, j, k, inside))
        };
        let x = wrap_linear_lanes(self.wrap[0], s, nw);
        if dims == 1 {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) == 0 {
                    continue;
                }
                let t0 = tv(l, x.i0[l], 0, 0, x.in0[l]);
                let t1 = tv(l, x.i1[l], 0, 0, x.in1[l]);
                let a = x.w[l];
                // (1 - α)·t0 + α·t1.
                *o = (Vec4::splat(1.0 - a) * t0 + Vec4::splat(a) * t1).to_array();
            }
            return;
        }
        let y = wrap_linear_lanes(self.wrap[1], t, nh);
        // The four weights of eq. 3.24 as `linear` groups them:
        // (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11.
        let mut wt = [[0.0f32; LANES]; 4];
        for (l, (&a, &b)) in x.w.iter().zip(&y.w).enumerate() {
            wt[0][l] = (1.0 - a) * (1.0 - b);
            wt[1][l] = a * (1.0 - b);
            wt[2][l] = (1.0 - a) * b;
            wt[3][l] = a * b;
        }
        // `linear`'s `plane` at depth index k (inside the image or not) for lane l.
        macro_rules! plane {
            ($l:expr, $k:expr, $kin:expr) => {{
                let (l, k, kin) = ($l, $k, $kin);
                let t00 = tv(l, x.i0[l], y.i0[l], k, x.in0[l] && y.in0[l] && kin);
                let t10 = tv(l, x.i1[l], y.i0[l], k, x.in1[l] && y.in0[l] && kin);
                let t01 = tv(l, x.i0[l], y.i1[l], k, x.in0[l] && y.in1[l] && kin);
                let t11 = tv(l, x.i1[l], y.i1[l], k, x.in1[l] && y.in1[l] && kin);
                weigh(&wt, l, [t00, t10, t01, t11])
            }};
        }
        if dims == 2 {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = plane!(l, 0, true).to_array();
                }
            }
            return;
        }
        let z = wrap_linear_lanes(self.wrap[2], r, nd);
        for (l, o) in out.iter_mut().enumerate() {
            if m & (1 << l) == 0 {
                continue;
            }
            let p0 = plane!(l, z.i0[l], z.in0[l]);
            let p1 = plane!(l, z.i1[l], z.in1[l]);
            let g = z.w[l];
            // (1 - γ)·p0 + γ·p1.
            *o = (Vec4::splat(1.0 - g) * p0 + Vec4::splat(g) * p1).to_array();
        }
    }

    /// [`Sampler::quad_lambda`] of a cube map for eight quads, lane l's at (`qx[l]`, `qy`):
    /// the three points of each quad on lanes (`lambda_point` with unit sizes: the plane
    /// values divided by q, times 1, which changes no bit of a number), then per lane the face
    /// of the quad's first point, the three points projected on it and scaled, and
    /// `quad_lambda`'s ρ² and λ: each lane the scalar λ (a NaN where it is NaN).
    #[inline(always)]
    pub(super) fn cube_lambda_lanes(
        &self,
        planes: &[f32],
        to: usize,
        qx: [f32; LANES],
        qy: f32,
    ) -> [f32; LANES] {
        let g = |o: usize| planes.get(o).copied().unwrap_or(0.0);
        let plane = |j: usize| [g(3 * j), g(3 * j + 1), g(3 * j + 2)];
        let (ps, pt, pr, pq) = (plane(1 + to), plane(2 + to), plane(3 + to), plane(4 + to));
        let mut qx1 = qx;
        for x in &mut qx1 {
            *x += 1.0;
        }
        let one = [1.0f32; 3];
        let p0 = lambda_point(&ps, &pt, &pr, &pq, &qx, qy, one, 3);
        let px = lambda_point(&ps, &pt, &pr, &pq, &qx1, qy, one, 3);
        let py = lambda_point(&ps, &pt, &pr, &pq, &qx, qy + 1.0, one, 3);
        let size = self.size;
        let mut out = [0.0f32; LANES];
        for (l, o) in out.iter_mut().enumerate() {
            let at = |p: &[[f32; LANES]; 3]| [p[0][l], p[1][l], p[2][l]];
            let a = at(&p0);
            let (face, _) = cube_face(a);
            let on = |p: [f32; 3]| {
                let (s, t) = cube_project(face, p);
                [s * size[0], t * size[1], 0.0]
            };
            let (a, b, c) = (on(a), on(at(&px)), on(at(&py)));
            let len2 = |q: [f32; 3]| {
                let d = [q[0] - a[0], q[1] - a[1], q[2] - a[2]];
                d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
            };
            let rho2 = len2(b).max(len2(c));
            *o = 0.5 * fast_log2_lane(rho2);
        }
        out
    }

    /// The texture environment of the lanes of `m` (what [`Sampler::shade_texel`] gives each
    /// lane's fragment colour `cf[l]`, primary colour `prim[l]` and texel `t[l]`): COMBINE here,
    /// the other environments by [`Sampler::env_lanes`]. Not for a COMBINE with TEXTUREn
    /// sources (`crossbar`), which [`Sampler::lanes_ok`] keeps off the lanes.
    #[inline]
    pub fn env_lanes_with(
        &self,
        cf: &mut [Vec4; LANES],
        prim: &[Vec4; LANES],
        t: &TexelLanes,
        m: u8,
    ) {
        if self.env != gl::COMBINE {
            return self.env_lanes(cf, t, m);
        }
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: AVX2 is present (checked just above).
            return unsafe { self.combine8(cf, prim, t, m) };
        }
        let out = self.combine_lanes(cf, prim, t);
        for l in 0..LANES {
            if m & (1 << l) != 0 {
                cf[l] = out[l];
            }
        }
    }

    /// `combine` (§3.8.13, tables 3.23 and 3.24; no TEXTUREn source) for eight lanes: each
    /// source, operand and function chosen once for the group, then the same `Vec4` / `f32`
    /// operations in the same order as `combine` on every lane.
    #[inline]
    fn combine_lanes(
        &self,
        cf: &[Vec4; LANES],
        prim: &[Vec4; LANES],
        t: &TexelLanes,
    ) -> [Vec4; LANES] {
        type V = [Vec4; LANES];
        let c = &self.combine;
        let mut tex = [Vec4::ZERO; LANES];
        for (x, t) in tex.iter_mut().zip(t) {
            *x = self.combine_texel(*t);
        }
        let src = |s: u32| -> V {
            match s {
                gl::CONSTANT => [self.env_color; LANES],
                gl::PRIMARY_COLOR => *prim,
                gl::PREVIOUS => *cf,
                gl::TEXTURE => tex,
                // A TEXTUREn source (the crossbar) never reaches the lanes; an unknown source
                // reads zero, as in `combine`.
                _ => [Vec4::ZERO; LANES],
            }
        };
        let arg_rgb = |k: usize| -> V {
            let mut v = src(c.src_rgb[k]);
            match c.operand_rgb[k] {
                gl::ONE_MINUS_SRC_COLOR => {
                    for x in &mut v {
                        *x = Vec4::ONE - *x;
                    }
                }
                gl::SRC_ALPHA => {
                    for x in &mut v {
                        *x = Vec4::splat(x.w);
                    }
                }
                gl::ONE_MINUS_SRC_ALPHA => {
                    for x in &mut v {
                        *x = Vec4::splat(1.0 - x.w);
                    }
                }
                _ => {}
            }
            v
        };
        let arg_a = |k: usize| -> [f32; LANES] {
            let v = src(c.src_alpha[k]);
            let mut a = [0.0f32; LANES];
            let minus = c.operand_alpha[k] == gl::ONE_MINUS_SRC_ALPHA;
            for (a, v) in a.iter_mut().zip(&v) {
                *a = if minus { 1.0 - v.w } else { v.w };
            }
            a
        };
        // Functions of two arguments, one loop each (a macro, so that each body inlines).
        macro_rules! two {
            ($arg:ident, $out:ident, |$a:ident, $b:ident| $e:expr) => {{
                let (x, y) = ($arg(0), $arg(1));
                for l in 0..LANES {
                    let ($a, $b) = (x[l], y[l]);
                    $out[l] = $e;
                }
            }};
        }
        let mut rgb = [Vec4::ZERO; LANES];
        match c.rgb {
            gl::REPLACE => rgb = arg_rgb(0),
            gl::MODULATE => two!(arg_rgb, rgb, |a, b| a * b),
            gl::ADD => two!(arg_rgb, rgb, |a, b| a + b),
            gl::ADD_SIGNED => two!(arg_rgb, rgb, |a, b| a + b - Vec4::splat(0.5)),
            gl::INTERPOLATE => {
                let (a0, a1, a2) = (arg_rgb(0), arg_rgb(1), arg_rgb(2));
                for l in 0..LANES {
                    rgb[l] = a0[l] * a2[l] + a1[l] * (Vec4::ONE - a2[l]);
                }
            }
            gl::SUBTRACT => two!(arg_rgb, rgb, |a, b| a - b),
            // DOT3_RGB(A): 4·Σ (a0 - 1/2)(a1 - 1/2) over r, g, b into every channel.
            _ => two!(arg_rgb, rgb, |a, b| {
                let d = (a - Vec4::splat(0.5)).truncate();
                let e = (b - Vec4::splat(0.5)).truncate();
                Vec4::splat(4.0 * d.dot(e))
            }),
        }
        let mut alpha = [0.0f32; LANES];
        if c.rgb == gl::DOT3_RGBA {
            for l in 0..LANES {
                alpha[l] = rgb[l].x;
            }
        } else {
            match c.alpha {
                gl::REPLACE => alpha = arg_a(0),
                gl::MODULATE => two!(arg_a, alpha, |a, b| a * b),
                gl::ADD => two!(arg_a, alpha, |a, b| a + b),
                gl::ADD_SIGNED => two!(arg_a, alpha, |a, b| a + b - 0.5),
                gl::INTERPOLATE => {
                    let (a0, a1, a2) = (arg_a(0), arg_a(1), arg_a(2));
                    for l in 0..LANES {
                        alpha[l] = a0[l] * a2[l] + a1[l] * (1.0 - a2[l]);
                    }
                }
                _ => two!(arg_a, alpha, |a, b| a - b),
            }
        }
        let mut out = [Vec4::ZERO; LANES];
        for l in 0..LANES {
            out[l] = (rgb[l] * c.rgb_scale)
                .truncate()
                .extend(alpha[l] * c.alpha_scale)
                .clamp(Vec4::ZERO, Vec4::ONE);
        }
        out
    }
}

impl Sampler {
    /// [`Sampler::combine_lanes`] (and the write of the lanes of `m` into `cf`) on eight lanes
    /// a register, one register per channel (AVX2): the previous and primary colours and the
    /// texels transposed to channel registers ([`load8`], moves only), the texture's channels
    /// picked as [`Sampler::combine_texel`] picks them, each source, operand and function
    /// chosen once for the group, then `combine`'s per-channel operations in its order (`vmulps`,
    /// `vaddps`, `vsubps`: the same IEEE operations on each lane; RGB only on r, g and b, all
    /// of it `combine` keeps; DOT3's sum as `Vec3::dot` adds, (x·x' + y·y') + z·z'), the
    /// scales, the clamp as glam's (`vmaxps` with 0, then `vminps` with 1, in that operand
    /// order), the lanes outside `m` blended back and the registers transposed back
    /// ([`store8`]). Pixel-major, with the sources copied per lane, `combine_lanes` cost
    /// ≈450 instructions a call on texture-targets.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn combine8(&self, cf: &mut [Vec4; LANES], prim: &[Vec4; LANES], t: &TexelLanes, m: u8) {
        use std::arch::x86_64::*;
        type C = [__m256; 4];
        type Rgb = [__m256; 3];
        let c = &self.combine;
        let zero = _mm256_setzero_ps();
        let (one, half) = (_mm256_set1_ps(1.0), _mm256_set1_ps(0.5));
        // The sources by reference (copied by value, each read moved four registers through
        // the stack), an unused one as zeros.
        let zeros: C = [zero; 4];
        let tex_ch: C;
        let tex = match self.comb_pick.tex {
            Some(pick) => {
                let ch = load8(|l| t[l]);
                // By `pick`'s numbers: 0, 1, then the texel's channels.
                let regs = [zero, one, ch[0], ch[1], ch[2], ch[3]];
                tex_ch = pick.map(|k| regs.get(usize::from(k)).copied().unwrap_or(zero));
                &tex_ch
            }
            None => &zeros,
        };
        let prev = load8(|l| cf[l].to_array());
        let prim_ch: C;
        let prim = match self.comb_pick.prim {
            true => {
                prim_ch = load8(|l| prim[l].to_array());
                &prim_ch
            }
            false => &zeros,
        };
        let konst: C = self.env_color.to_array().map(|x| _mm256_set1_ps(x));
        // By `CombinePick::src`'s numbers.
        let srcs: [&C; 5] = [&zeros, &konst, prim, &prev, tex];
        let src = |s: u8| -> &C { srcs.get(usize::from(s)).copied().unwrap_or(&zeros) };
        let minus = |x: __m256| _mm256_sub_ps(one, x);
        let arg_rgb = |k: usize| -> Rgb {
            let v = src(self.comb_pick.src_rgb[k]);
            match c.operand_rgb[k] {
                gl::ONE_MINUS_SRC_COLOR => [minus(v[0]), minus(v[1]), minus(v[2])],
                gl::SRC_ALPHA => [v[3]; 3],
                gl::ONE_MINUS_SRC_ALPHA => [minus(v[3]); 3],
                _ => [v[0], v[1], v[2]],
            }
        };
        let arg_a = |k: usize| -> __m256 {
            let a = src(self.comb_pick.src_alpha[k])[3];
            match c.operand_alpha[k] == gl::ONE_MINUS_SRC_ALPHA {
                true => minus(a),
                false => a,
            }
        };
        // a0·a2 + a1·(1 - a2).
        let lerp = |a0: __m256, a1: __m256, a2: __m256| {
            _mm256_add_ps(_mm256_mul_ps(a0, a2), _mm256_mul_ps(a1, minus(a2)))
        };
        // Functions of two arguments, channel by channel (macros, so that each body inlines).
        macro_rules! two {
            (|$a:ident, $b:ident| $e:expr) => {{
                let (x, y) = (arg_rgb(0), arg_rgb(1));
                let f = |$a: __m256, $b: __m256| $e;
                [f(x[0], y[0]), f(x[1], y[1]), f(x[2], y[2])]
            }};
        }
        macro_rules! two_a {
            (|$a:ident, $b:ident| $e:expr) => {{
                let ($a, $b) = (arg_a(0), arg_a(1));
                $e
            }};
        }
        let rgb: Rgb = match c.rgb {
            gl::REPLACE => arg_rgb(0),
            gl::MODULATE => two!(|a, b| _mm256_mul_ps(a, b)),
            gl::ADD => two!(|a, b| _mm256_add_ps(a, b)),
            gl::ADD_SIGNED => two!(|a, b| _mm256_sub_ps(_mm256_add_ps(a, b), half)),
            gl::INTERPOLATE => {
                let (a0, a1, a2) = (arg_rgb(0), arg_rgb(1), arg_rgb(2));
                [
                    lerp(a0[0], a1[0], a2[0]),
                    lerp(a0[1], a1[1], a2[1]),
                    lerp(a0[2], a1[2], a2[2]),
                ]
            }
            gl::SUBTRACT => two!(|a, b| _mm256_sub_ps(a, b)),
            // DOT3_RGB(A): 4·Σ (a0 - 1/2)(a1 - 1/2) over r, g, b into every channel.
            _ => {
                let d = two!(|a, b| _mm256_mul_ps(_mm256_sub_ps(a, half), _mm256_sub_ps(b, half)));
                let dot = _mm256_add_ps(_mm256_add_ps(d[0], d[1]), d[2]);
                [_mm256_mul_ps(_mm256_set1_ps(4.0), dot); 3]
            }
        };
        let alpha = if c.rgb == gl::DOT3_RGBA {
            rgb[0]
        } else {
            match c.alpha {
                gl::REPLACE => arg_a(0),
                gl::MODULATE => two_a!(|a, b| _mm256_mul_ps(a, b)),
                gl::ADD => two_a!(|a, b| _mm256_add_ps(a, b)),
                gl::ADD_SIGNED => two_a!(|a, b| _mm256_sub_ps(_mm256_add_ps(a, b), half)),
                gl::INTERPOLATE => lerp(arg_a(0), arg_a(1), arg_a(2)),
                _ => two_a!(|a, b| _mm256_sub_ps(a, b)),
            }
        };
        let (rs, as_) = (_mm256_set1_ps(c.rgb_scale), _mm256_set1_ps(c.alpha_scale));
        let out = [
            _mm256_mul_ps(rgb[0], rs),
            _mm256_mul_ps(rgb[1], rs),
            _mm256_mul_ps(rgb[2], rs),
            _mm256_mul_ps(alpha, as_),
        ];
        // The lanes of `m` (an all-ones lane) take the clamped result, the others keep `cf`.
        let sel = mask8(m);
        let ch = [0, 1, 2, 3].map(|k| {
            let x = _mm256_min_ps(_mm256_max_ps(out[k], zero), one);
            _mm256_blendv_ps(prev[k], x, sel)
        });
        // SAFETY: `Vec4` is four f32 in memory order (16 bytes, aligned to 16), so
        // `[Vec4; 8]` has the size of `[[f32; 4]; 8]` and at least its alignment, and every
        // bit pattern is valid for both: the registers go straight into `cf` (through an array
        // and a copy per lane, ≈16 instructions a call more).
        let cf = unsafe { &mut *std::ptr::from_mut(cf).cast::<TexelLanes>() };
        store8(&ch, 0xff, cf);
    }
}

/// COMBINE's choices for [`Sampler::combine8`] that depend only on the flush's state, made
/// once when the sampler is built (texture-targets: ≈40 instructions a call when `combine8`
/// made them for every eight fragments).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CombinePick {
    /// Where a source reads TEXTURE: each channel of `combine_texel` of the texel as 0, 1 or
    /// 2 + the texel channel it reads (`combine_texel` of the channel numbers 2..=5).
    tex: Option<[u8; 4]>,
    /// Whether a source reads PRIMARY_COLOR.
    prim: bool,
    /// The sources of the RGB and alpha arguments as `combine8` numbers them: 0 zero, 1
    /// CONSTANT, 2 PRIMARY_COLOR, 3 PREVIOUS, 4 TEXTURE.
    src_rgb: [u8; 3],
    src_alpha: [u8; 3],
}

impl CombinePick {
    /// The choices of `s`'s COMBINE state.
    pub fn of(s: &Sampler) -> Self {
        let c = &s.combine;
        let used = |src: u32| c.src_rgb.contains(&src) || c.src_alpha.contains(&src);
        CombinePick {
            tex: used(gl::TEXTURE).then(|| {
                s.combine_texel([2.0, 3.0, 4.0, 5.0]).to_array().map(|k| {
                    if (1.0..=5.0).contains(&k) {
                        k as u8
                    } else {
                        0
                    }
                })
            }),
            prim: used(gl::PRIMARY_COLOR),
            src_rgb: c.src_rgb.map(Self::source),
            src_alpha: c.src_alpha.map(Self::source),
        }
    }

    /// A source's number (`src_rgb`).
    fn source(s: u32) -> u8 {
        match s {
            gl::CONSTANT => 1,
            gl::PRIMARY_COLOR => 2,
            gl::PREVIOUS => 3,
            gl::TEXTURE => 4,
            // A TEXTUREn source (the crossbar) never reaches the lanes; an unknown source
            // reads zero, as in `combine`.
            _ => 0,
        }
    }
}

/// Eight four-channel values (`at(l)` lane l's) as four channel registers (AVX2): lanes q and
/// q + 4 in one register, then the two 4x4 transpositions (unpacks and shuffles; moves only,
/// every bit kept). The inverse of [`store8`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn load8(at: impl Fn(usize) -> [f32; 4]) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    let pair = |q: usize| {
        let (lo, hi) = (at(q), at(q + 4));
        // SAFETY: `__m128` is four f32 lanes in memory order, the layout of `[f32; 4]`;
        // AVX is present (this function's target feature).
        unsafe {
            let lo = std::mem::transmute::<[f32; 4], __m128>(lo);
            let hi = std::mem::transmute::<[f32; 4], __m128>(hi);
            _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(lo), hi)
        }
    };
    let v = [pair(0), pair(1), pair(2), pair(3)];
    // Each half: r and g of lanes q, q + 1 (t0) and q + 2, q + 3 (t1); b and a in t2, t3.
    let (t0, t1) = (
        _mm256_unpacklo_ps(v[0], v[1]),
        _mm256_unpacklo_ps(v[2], v[3]),
    );
    let (t2, t3) = (
        _mm256_unpackhi_ps(v[0], v[1]),
        _mm256_unpackhi_ps(v[2], v[3]),
    );
    [
        _mm256_shuffle_ps::<0x44>(t0, t1),
        _mm256_shuffle_ps::<0xEE>(t0, t1),
        _mm256_shuffle_ps::<0x44>(t2, t3),
        _mm256_shuffle_ps::<0xEE>(t2, t3),
    ]
}

/// The lanes of `m` as an AVX2 mask: lane l all ones where bit l of `m` is set, else zero.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn mask8(m: u8) -> std::arch::x86_64::__m256 {
    // SAFETY: see `lane_mask8`: only inlined into this module's AVX2 kernels.
    unsafe { std::arch::x86_64::_mm256_castsi256_ps(crate::cpu::lanes::lane_mask8(m)) }
}

/// Can the AVX2 kernel [`dense_targets8`] take a one-image LINEAR pass of a 1D or 3D
/// texture without depth comparison: every axis the texture has REPEAT or CLAMP_TO_EDGE (the
/// indices `linear_axis8` wraps; no border texel, no mirror), a CPU with AVX2 ([`avx2`]) and
/// a level of at most 2^28 texels (the gathers' byte offsets fit an i32).
#[inline(always)]
fn targets_kernel_ok(dims: usize, wrap: [u32; 3], len: usize) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        targets_wraps_ok(dims, wrap, len) && avx2()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (dims, wrap, len);
        false
    }
}

/// [`targets_kernel_ok`] but for the CPU: a 1D or 3D texture whose axes REPEAT or
/// CLAMP_TO_EDGE, a level of at most 2^28 texels.
#[inline]
fn targets_wraps_ok(dims: usize, wrap: [u32; 3], len: usize) -> bool {
    (dims == 1 || dims == 3)
        && wrap
            .iter()
            .take(dims)
            .all(|&mode| mode == gl::REPEAT || mode == gl::CLAMP_TO_EDGE)
        && len <= 1 << 28
}

/// What [`Sampler::pass_targets`] and [`Sampler::lod_dense`] would otherwise decide per group
/// (≈87 instructions a level a group in `lod_dense`), decided once a flush in
/// [`Sampler::new`] from the texture object `obj` of `dims` dimensions (a cube map: six
/// faces), its depth comparison and wrap modes: for each face, the levels (bit k for level
/// k) that [`dense3`] holds for; the levels `lod_dense`'s kernel may read (none for a cube
/// map or with a depth comparison; else each dense level of face 0 with wrap modes the
/// kernel takes, [`targets_wraps_ok`], which also keeps every index inside the image; whether
/// the CPU has AVX2 is still asked per group, [`dense_targets_lod`]); and [`in_image`] for
/// NEAREST and LINEAR.
pub(super) fn target_levels(
    obj: &crate::texture::TexObject,
    dims: usize,
    cube: bool,
    compare: bool,
    wrap: [u32; 3],
) -> ([u16; 6], u16, [bool; 2]) {
    let levels = crate::texture::MAX_LEVELS.min(16);
    let mut dense = [0u16; 6];
    let mut kernel = 0u16;
    for (f, bits) in dense.iter_mut().enumerate().take(if cube { 6 } else { 1 }) {
        for k in 0..levels {
            let Some(x) = obj.face_level(f, k as i32) else {
                continue;
            };
            let tx = &x.texels[..];
            if dense3(tx, [x.width, x.height, x.depth]) {
                *bits |= 1 << k;
                let ok = f == 0 && !cube && !compare && targets_wraps_ok(dims, wrap, tx.len());
                kernel |= u16::from(ok) << k;
            }
        }
    }
    (
        dense,
        kernel,
        [false, true].map(|linear| in_image(dims, wrap, linear)),
    )
}

/// Whether every index the wrap modes `wrap` of a texture of `dims` dimensions give lies
/// inside the image (no border texel): for LINEAR none of CLAMP and CLAMP_TO_BORDER, for
/// NEAREST (whose CLAMP clamps the index as CLAMP_TO_EDGE does) no CLAMP_TO_BORDER.
fn in_image(dims: usize, wrap: [u32; 3], linear: bool) -> bool {
    wrap.iter()
        .take(dims.clamp(1, 3))
        .all(|&mode| match linear {
            true => !matches!(mode, gl::CLAMP | gl::CLAMP_TO_BORDER),
            false => mode != gl::CLAMP_TO_BORDER,
        })
}

/// `pass_dense`'s LINEAR on a 1D (`dims` 1) or 3D texture as one AVX2 kernel
/// ([`dense_targets8`]) for the eight lanes, when [`targets_kernel_ok`] holds; `rep` tells
/// which axes REPEAT (else CLAMP_TO_EDGE). Out of line, as the 2D `dense_kernel`.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn dense_targets(
    dims: usize,
    rep: [bool; 3],
    dt: &[[f32; 4]],
    n: [i32; 3],
    s: &[f32; LANES],
    t: &[f32; LANES],
    r: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    #[cfg(target_arch = "x86_64")]
    if avx2() && dt.len() <= 1 << 28 {
        // SAFETY: AVX2 is present (checked above) and `dt` at most 2^28 texels.
        unsafe { dense_targets8(dims == 3, rep, dt, n, s, t, r, m, out) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (dims, rep, dt, n, s, t, r, m, out);
    }
}

/// [`linear_axis8`] with the wrap (REPEAT or the edge clamp) chosen at run time (AVX2).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::type_complexity)]
fn axis8(
    c: std::arch::x86_64::__m256,
    n: i32,
    rep: bool,
) -> (
    std::arch::x86_64::__m256i,
    std::arch::x86_64::__m256i,
    std::arch::x86_64::__m256,
) {
    if rep {
        linear_axis8::<true>(c, n)
    } else {
        linear_axis8::<false>(c, n)
    }
}

/// LINEAR on one dense 1D or 3D (`three`) level, eight lanes at once (AVX2): each axis's
/// `linear_u`, floor, weight and wrapped indices as `wrap_linear_lanes` computes them
/// ([`linear_axis8`]), the indices k·(h·w) + j·w + i as shifts (w, h, d are powers of two:
/// [`dense3`]), each channel of each corner gathered for the eight lanes (`vgatherdps`, the
/// offsets (k & (len − 1))·4), then `linear`'s sums in its order: 1D (1 − α)·t0 + α·t1; 3D
/// eq. 3.24's plane at k0 and at k1, then (1 − γ)·p0 + γ·p1; the channel registers transposed
/// back to a texel per lane, the lanes of `m` written.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn dense_targets8(
    three: bool,
    rep: [bool; 3],
    dt: &[[f32; 4]],
    n: [i32; 3],
    s: &[f32; LANES],
    t: &[f32; LANES],
    r: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    // SAFETY: the caller's promises are `targets_ch8`'s.
    if let Some(ch) = unsafe { targets_ch8(three, rep, dt, n, [s, t, r]) } {
        store8(&ch, m, out);
    }
}

/// [`dense_targets8`]'s LINEAR of all eight lanes as channel registers (r, g, b, a), None for
/// an empty `dt`.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn targets_ch8(
    three: bool,
    rep: [bool; 3],
    dt: &[[f32; 4]],
    [w, h, d]: [i32; 3],
    [s, t, r]: [&[f32; LANES]; 3],
) -> Option<[std::arch::x86_64::__m256; 4]> {
    use std::arch::x86_64::*;
    let km = dt.len().checked_sub(1)?;
    let (w, h, d) = (w.max(1), h.max(1), d.max(1));
    let kmv = _mm256_set1_epi32(km as i32);
    let off = |k: __m256i| _mm256_slli_epi32::<2>(_mm256_and_si256(k, kmv));
    let base = dt.as_ptr().cast::<f32>();
    let one = _mm256_set1_ps(1.0);
    let (x0, x1, a) = axis8(lanes8(s), w, rep[0]);
    let na = _mm256_sub_ps(one, a);
    let mut ch = [_mm256_setzero_ps(); 4];
    if !three {
        let (k0, k1) = (off(x0), off(x1));
        for (c, v) in ch.iter_mut().enumerate() {
            // SAFETY: AVX2 is present (the caller's promise); each offset is at most
            // 4·(dt.len() - 1) and c < 4, so every f32 read lies inside `dt`.
            let (t0, t1) = unsafe {
                (
                    _mm256_i32gather_ps::<4>(base.add(c), k0),
                    _mm256_i32gather_ps::<4>(base.add(c), k1),
                )
            };
            *v = _mm256_add_ps(_mm256_mul_ps(na, t0), _mm256_mul_ps(a, t1));
        }
        return Some(ch);
    }
    let (y0, y1, b) = axis8(lanes8(t), h, rep[1]);
    let (z0, z1, g) = axis8(lanes8(r), d, rep[2]);
    let nb = _mm256_sub_ps(one, b);
    let wt = [
        _mm256_mul_ps(na, nb),
        _mm256_mul_ps(a, nb),
        _mm256_mul_ps(na, b),
        _mm256_mul_ps(a, b),
    ];
    let ng = _mm256_sub_ps(one, g);
    let shw = _mm_cvtsi32_si128(w.trailing_zeros() as i32);
    // h·w's log2 (both powers of two, their product at most 2^28).
    let shs = _mm_cvtsi32_si128((w.trailing_zeros() + h.trailing_zeros()) as i32);
    let (r0, r1) = (_mm256_sll_epi32(y0, shw), _mm256_sll_epi32(y1, shw));
    // The four corners of the plane at slab offset `z`: t00, t10, t01, t11.
    let corners = |z: __m256i| {
        let z = _mm256_sll_epi32(z, shs);
        let (q0, q1) = (_mm256_add_epi32(z, r0), _mm256_add_epi32(z, r1));
        [
            off(_mm256_add_epi32(q0, x0)),
            off(_mm256_add_epi32(q0, x1)),
            off(_mm256_add_epi32(q1, x0)),
            off(_mm256_add_epi32(q1, x1)),
        ]
    };
    let (k0, k1) = (corners(z0), corners(z1));
    for (c, v) in ch.iter_mut().enumerate() {
        // SAFETY: as above.
        let at = |k: __m256i| unsafe { _mm256_i32gather_ps::<4>(base.add(c), k) };
        let plane = |k: &[__m256i; 4]| {
            let x = _mm256_add_ps(
                _mm256_mul_ps(wt[0], at(k[0])),
                _mm256_mul_ps(wt[1], at(k[1])),
            );
            let x = _mm256_add_ps(x, _mm256_mul_ps(wt[2], at(k[2])));
            _mm256_add_ps(x, _mm256_mul_ps(wt[3], at(k[3])))
        };
        let (p0, p1) = (plane(&k0), plane(&k1));
        *v = _mm256_add_ps(_mm256_mul_ps(ng, p0), _mm256_mul_ps(g, p1));
    }
    Some(ch)
}

/// A dense level's texels and sizes (width, height, depth).
type DenseLevel<'a> = (&'a [[f32; 4]], [i32; 3]);

/// [`Sampler::lod_dense`]'s kernel: level `a` for the lanes of `m` and, when given, level `b`
/// for the lanes of `second` blended in as `sample_face` does, `a·(1 - f) + b·f` per channel
/// (`f` the lane's weight), each by [`targets_ch8`] (AVX2). Out of line, as
/// [`dense_targets`]. Returns false (nothing written) where the kernel cannot run (no AVX2, a
/// level of more than 2^28 texels, an empty one). Inlined into `lod_dense`, which calls the
/// AVX2 kernel directly (out of line, its call and arguments were ≈37 instructions a group;
/// inlined, `targets_lanes` grew by about as much).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn dense_targets_lod(
    dims: usize,
    rep: [bool; 3],
    a: DenseLevel<'_>,
    b: Option<DenseLevel<'_>>,
    coords: [&[f32; LANES]; 3],
    f: &[f32; LANES],
    second: u8,
    m: u8,
    out: &mut TexelLanes,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if avx2() && a.0.len() <= 1 << 28 && b.map_or(0, |b| b.0.len()) <= 1 << 28 {
        // SAFETY: AVX2 is present (checked above) and both levels at most 2^28 texels.
        return unsafe { dense_targets_lod8(dims == 3, rep, a, b, coords, f, second, m, out) };
    }
    let _ = (dims, rep, a, b, coords, f, second, m, out);
    false
}

/// [`dense_targets_lod`] on AVX2.
///
/// # Safety
/// The CPU must have AVX2, and both levels at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn dense_targets_lod8(
    three: bool,
    rep: [bool; 3],
    (at, an): DenseLevel<'_>,
    b: Option<DenseLevel<'_>>,
    coords: [&[f32; LANES]; 3],
    f: &[f32; LANES],
    second: u8,
    m: u8,
    out: &mut TexelLanes,
) -> bool {
    use std::arch::x86_64::*;
    // SAFETY: AVX2 is present and level `a` at most 2^28 texels (the caller's promises).
    let ch = unsafe { targets_ch8(three, rep, at, an, coords) };
    let Some(mut ch) = ch else {
        return false;
    };
    if let Some((bt, bn)) = b {
        // SAFETY: AVX2 is present and level `b` at most 2^28 texels (the caller's promises).
        let cb = unsafe { targets_ch8(three, rep, bt, bn, coords) };
        let Some(cb) = cb else {
            return false;
        };
        let fv = lanes8(f);
        let nf = _mm256_sub_ps(_mm256_set1_ps(1.0), fv);
        // The lanes of `second` (bit l of the mask to all ones in lane l).
        let sel = mask8(second);
        for (c, cb) in ch.iter_mut().zip(cb) {
            // `sample_face`'s a·(1 - f) + b·f.
            let mix = _mm256_add_ps(_mm256_mul_ps(*c, nf), _mm256_mul_ps(cb, fv));
            *c = _mm256_blendv_ps(*c, mix, sel);
        }
    }
    // `out` comes zeroed (`targets_texels`) and nothing else has written it: the lanes
    // outside `m` cleared and all eight stored (`store8`'s lane-by-lane stores of a partial
    // mask cost ≈20 instructions more).
    if m != 0xff {
        let keep = mask8(m);
        for c in &mut ch {
            *c = _mm256_and_ps(*c, keep);
        }
    }
    store8(&ch, 0xff, out);
    true
}

/// Eq. 3.24's sum for lane l of a LINEAR pass, in the scalar code's order:
/// w00·t00 + w10·t10 + w01·t01 + w11·t11 (the weights `wt`, lane-major by texel).
#[inline(always)]
fn weigh(wt: &[[f32; LANES]; 4], l: usize, t: [Vec4; 4]) -> Vec4 {
    Vec4::splat(wt[0][l]) * t[0]
        + Vec4::splat(wt[1][l]) * t[1]
        + Vec4::splat(wt[2][l]) * t[2]
        + Vec4::splat(wt[3][l]) * t[3]
}

#[cfg(test)]
#[path = "../tests/texture_targets.rs"]
mod tests;
