//! Texturing of fragments (GL 2.1 §3.8.8 minification and magnification, §3.8.9, §3.8.13
//! texture environments, §3.8.14 depth comparison): level of detail from the derivatives of
//! the texture coordinates, wrap modes, NEAREST / LINEAR and the four mipmap filters, the
//! depth compare, then TexEnv REPLACE / MODULATE / DECAL / BLEND / ADD per table 3.21.
//!
//! Design decision: λ comes from one scale factor per 2x2 pixel quad, as llvmpipe computes it:
//! the perspective-correct coordinates are evaluated at the quad's lower-left pixel and its right
//! and upper neighbours (the planes give any pixel, covered or not), and
//! ρ = max(|∂(u,v)/∂x|, |∂(u,v)/∂y|) from those differences (eq. 3.21 with the exact lengths),
//! and λ = ½·log2(ρ²) with llvmpipe's piecewise-linear log2 (exponent + mantissa − 1, exact at
//! powers of two): with the exact log2, mip-blended checker edges differed from the driver in
//! 16 times as many pixels. One measured difference is kept on purpose: the switch point c of
//! §3.8.9 is 0.5 for MAG LINEAR with a NEAREST_MIPMAP_* filter, as the spec says; llvmpipe
//! switches at 0 (3.8% of pixels of a minified floor differ in that configuration).
//! Everything that does not change per fragment (the object, its complete levels, the filters,
//! the environment) is resolved once per flush in [`Sampler::new`], and an untextured flush
//! carries no sampler at all, so untextured fragments never reach this module.

use std::sync::Arc;

use glam::Vec4;

use super::lanes::{recip_lanes, LANES};

mod span;
mod targets;
use crate::gl;
use crate::state::{State, MAX_TEXTURE_UNITS};
use crate::texture::{as_rgba, is_mipmap_filter, Combine, Level, TexObject, MAX_TEXTURE_LOD_BIAS};
pub use span::FusedSpan;

/// Eight fragments' texels, lane-major (each lane's RGBA as `shade`'s filters return it).
pub type TexelLanes = [[f32; 4]; LANES];

/// Which sampling routine a flush uses (chosen once in [`Sampler::new`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Route {
    /// NEAREST on the base level whatever λ (no mipmaps, both filters NEAREST).
    Nearest,
    /// LINEAR on the base level whatever λ (no mipmaps, both filters LINEAR).
    Linear,
    /// λ decides: magnification, or minification with or without mipmaps.
    Lod,
}

/// Each unit's filtered texel as a COMBINE source TEXTUREn reads it (ARB_texture_env_crossbar,
/// GL 1.4 §3.8.13), by unit number: `None` for a unit that is disabled (no target enabled, or
/// none complete), which reads as (0, 0, 0, 0) as in llvmpipe (see [`Sampler::shade_texel`]).
pub type UnitTexels = [Option<Vec4>; MAX_TEXTURE_UNITS];

/// One texture unit's sampling and environment state for a flush.
#[derive(Clone, Debug)]
pub struct Sampler {
    obj: Arc<TexObject>,
    /// The texture unit (0 for TEXTURE0).
    unit: usize,
    /// The environment is COMBINE with a TEXTUREn source (the crossbar): the fragment stage
    /// must sample every unit before this unit's environment runs.
    crossbar: bool,
    /// Base internal format of the base level (DEPTH_COMPONENT read through `depth_mode`).
    base: u32,
    base_level: i32,
    /// The last mipmap level used (q of §3.8.8).
    last: i32,
    /// The image dimensions of the target: 1 (TEXTURE_1D), 2 or 3 (TEXTURE_3D).
    dims: usize,
    /// A cube map: (s, t, r) pick a face and a point on it (§3.8.6).
    cube: bool,
    /// Base level width, height and depth, for ρ (0 for the dimensions the target lacks).
    size: [f32; 3],
    min: u32,
    mag: u32,
    /// WRAP_S, _T, _R.
    wrap: [u32; 3],
    border: [f32; 4],
    min_lod: f32,
    max_lod: f32,
    bias: f32,
    /// The minification / magnification switch point c of §3.8.9.
    c: f32,
    env: u32,
    env_color: Vec4,
    /// The COMBINE parameters.
    combine: Combine,
    /// COMBINE's choices that depend only on the flush's state, for `combine8`.
    comb_pick: targets::CombinePick,
    /// The sampling routine of this flush.
    route: Route,
    /// TEXTURE_COMPARE_FUNC when TEXTURE_COMPARE_MODE is COMPARE_R_TO_TEXTURE on a depth texture.
    compare: Option<u32>,
    depth_mode: u32,
    /// Per face, the levels (bit k: level k) whose texels an index mask can address; the
    /// levels the 1D/3D trilinear kernel may read; whether the wrap modes keep NEAREST's and
    /// LINEAR's indices inside the image: `targets::target_levels`.
    dense: [u16; 6],
    lod_kernel: u16,
    in_image: [bool; 2],
}

impl Sampler {
    /// The sampler of texture unit `unit`, or None when the unit is disabled: no texture target
    /// enabled there, or none with a complete texture (see [`unit_texture`]).
    pub fn new(state: &State, unit: usize) -> Option<Sampler> {
        let (target, obj) = unit_texture(state, unit)?;
        let dims = crate::texture::target_dims(target);
        let u = state.textures.units.get(unit)?;
        let b = obj.level(obj.base_level)?;
        let mipmapped = is_mipmap_filter(obj.min_filter);
        let c = if obj.mag_filter == gl::LINEAR
            && matches!(
                obj.min_filter,
                gl::NEAREST_MIPMAP_NEAREST | gl::NEAREST_MIPMAP_LINEAR
            ) {
            0.5
        } else {
            0.0
        };
        let crossbar = u.env_mode == gl::COMBINE
            && u.combine
                .src_rgb
                .iter()
                .chain(&u.combine.src_alpha)
                .any(|&s| unit_of_source(s).is_some());
        let compare = (obj.compare_mode == gl::COMPARE_R_TO_TEXTURE
            && crate::texture::is_depth(b.base))
        .then_some(obj.compare_func);
        let (cube, wrap) = (
            target == gl::TEXTURE_CUBE_MAP,
            [obj.wrap_s, obj.wrap_t, obj.wrap_r],
        );
        let (dense, lod_kernel, in_image) =
            targets::target_levels(obj, dims, cube, compare.is_some(), wrap);
        let mut s = Sampler {
            unit,
            crossbar,
            dense,
            lod_kernel,
            in_image,
            base: b.base,
            base_level: obj.base_level,
            last: if mipmapped {
                obj.last_level().unwrap_or(obj.base_level)
            } else {
                obj.base_level
            },
            dims,
            cube,
            size: [
                b.width as f32,
                if dims >= 2 { b.height as f32 } else { 0.0 },
                if dims == 3 { b.depth as f32 } else { 0.0 },
            ],
            min: obj.min_filter,
            mag: obj.mag_filter,
            wrap,
            border: obj.border_color.to_array(),
            min_lod: obj.min_lod,
            max_lod: obj.max_lod,
            // §3.8.8 eq. 3.18: the object's and the unit's biases, their sum clamped to
            // ±MAX_TEXTURE_LOD_BIAS. The object's bias is clamped on its own first, as the driver
            // does (measured in tests/texture_gl.rs: object 20 with unit -15 draws as bias 1, not
            // the spec's 5); the unit's was clamped at TexEnv already. The two orders differ only
            // for an object bias beyond ±16. A NaN stays NaN and makes λ 0 in `sample`.
            bias: (obj
                .lod_bias
                .clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS)
                + u.lod_bias)
                .clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS),
            c,
            env: u.env_mode,
            env_color: u.env_color,
            combine: u.combine,
            route: match (mipmapped, obj.min_filter == obj.mag_filter, obj.min_filter) {
                (false, true, gl::NEAREST) => Route::Nearest,
                (false, true, _) => Route::Linear,
                _ => Route::Lod,
            },
            compare,
            depth_mode: obj.depth_texture_mode,
            obj: Arc::clone(obj),
            comb_pick: targets::CombinePick::default(),
        };
        s.comb_pick = targets::CombinePick::of(&s);
        Some(s)
    }

    /// Does the result depend on λ? Not when no mipmaps are used and the minification and
    /// magnification filters agree (then λ only chooses between two identical filters).
    #[inline]
    pub fn needs_lambda(&self) -> bool {
        self.route == Route::Lod
    }

    /// λ of §3.8.8 for the 2x2 quad whose lower-left pixel is at (fx, fy) relative to the
    /// primitive's plane origin: `planes` are the primitive's (1/w plane, then one plane per
    /// varying) and `to` the index of the varying s (t, r, q follow). The scalar reference of
    /// the lane routes (`quad_lambda_lanes`, `SpanLambda`), for the tests.
    #[cfg(test)]
    pub fn quad_lambda(&self, planes: &[f32], to: usize, fx: f32, fy: f32) -> f32 {
        let at = |x: f32, y: f32| {
            let pl = |j: usize| {
                let o = 3 * j;
                planes.get(o).copied().unwrap_or(0.0)
                    + planes.get(o + 1).copied().unwrap_or(0.0) * x
                    + planes.get(o + 2).copied().unwrap_or(0.0) * y
            };
            // The 1/w factors cancel in s/q, t/q and r/q.
            let q = pl(1 + to + 3);
            let inv = if q != 0.0 { 1.0 / q } else { 0.0 };
            if self.cube {
                return [pl(1 + to) * inv, pl(2 + to) * inv, pl(3 + to) * inv];
            }
            let u = pl(1 + to) * inv * self.size[0];
            let v = if self.dims >= 2 {
                pl(2 + to) * inv * self.size[1]
            } else {
                0.0
            };
            let w = if self.dims == 3 {
                pl(3 + to) * inv * self.size[2]
            } else {
                0.0
            };
            [u, v, w]
        };
        let (mut p0, mut px, mut py) = (at(fx, fy), at(fx + 1.0, fy), at(fx, fy + 1.0));
        if self.cube {
            // The three points projected on the face the quad's first pixel selects.
            let (face, ..) = cube_face(p0);
            let on = |p: [f32; 3]| {
                let (s, t) = cube_project(face, p);
                [s * self.size[0], t * self.size[1], 0.0]
            };
            (p0, px, py) = (on(p0), on(px), on(py));
        }
        let len2 = |a: [f32; 3]| {
            let d = [a[0] - p0[0], a[1] - p0[1], a[2] - p0[2]];
            d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
        };
        let rho2 = len2(px).max(len2(py));
        0.5 * fast_log2(rho2)
    }

    /// [`Sampler::quad_lambda`] for eight quads at once, lane l's quad at (`qx[l]`, `qy`): the
    /// same operations in the same order on lanes (the division by q as `divps`), written as
    /// plain loops over lane arrays so that the compiler keeps them in vector registers; each
    /// lane holds exactly the scalar result's bits. A cube map takes `cube_lambda_lanes` (its
    /// face choice differs between lanes).
    #[inline]
    pub fn quad_lambda_lanes(
        &self,
        planes: &[f32],
        to: usize,
        qx: [f32; LANES],
        qy: f32,
    ) -> [f32; LANES] {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: `avx2()` holds only on a CPU with AVX2.
            return unsafe { self.quad_lambda_avx2(planes, to, qx, qy) };
        }
        self.quad_lambda_on(planes, to, qx, qy)
    }

    /// λ of the 2x2 quads `q0..q0 + 8·out.len()` of a row (window quad numbers: quad q's
    /// lower-left pixel at window x 2q), eight a call of [`Sampler::quad_lambda_lanes`] (quad
    /// q0 + 8k + j in `out[k][j]`); the planes' origin is at window x `ox` and the quads'
    /// y is `qy` relative to it. Each value is `quad_lambda_lanes`'s for its quad (its lanes
    /// are independent of each other), so the same bits as [`SpanLambda`]'s windows. With
    /// `AVX2` (true only in functions compiled for AVX2 that run where the CPU has it) the
    /// AVX2 kernel is called directly, without `quad_lambda_lanes`' check (≈28 instructions a
    /// call on texture-targets).
    #[inline(always)]
    pub fn quad_lambda_row<const AVX2: bool>(
        &self,
        planes: &[f32],
        to: usize,
        ox: i32,
        qy: f32,
        q0: i32,
        out: &mut [[f32; LANES]],
    ) {
        // Without a cube map on AVX2: the planes looked up once for the row and
        // `quad_lambda_avx2`'s kernel called directly.
        #[cfg(target_arch = "x86_64")]
        let pl = (AVX2 && !self.cube).then(|| lambda_planes_at(planes, to));
        for (k, o) in out.iter_mut().enumerate() {
            // Window x 2·q of quad q, relative to the origin (2·(q0 + 8k + j) - ox).
            let xa = q0
                .wrapping_add((k * LANES) as i32)
                .wrapping_mul(2)
                .wrapping_sub(ox);
            #[cfg(target_arch = "x86_64")]
            if let Some(pl) = &pl {
                // SAFETY: `AVX2` is true only where the CPU has AVX2 (above).
                *o = unsafe { quad_lambda8(pl, &quad_xs8(xa), &[qy; LANES], self.size, self.dims) };
                continue;
            }
            let qx = std::array::from_fn(|j| xa.wrapping_add(2 * j as i32) as f32);
            #[cfg(target_arch = "x86_64")]
            if AVX2 {
                // SAFETY: as above.
                *o = unsafe { self.quad_lambda_avx2(planes, to, qx, qy) };
                continue;
            }
            *o = self.quad_lambda_lanes(planes, to, qx, qy);
        }
    }

    /// [`Sampler::quad_lambda_lanes`] on AVX2: a cube map by `cube_lambda_lanes` compiled
    /// for AVX2, the other targets by [`quad_lambda8`] (eight lanes a register, the same
    /// operations in the same order, no FMA). texture-targets (callgrind, 3 frames):
    /// `quad_lambda_lanes` 404 → ≈247 instructions a call inclusive.
    ///
    /// # Safety
    /// Only on a CPU with AVX2 ([`avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn quad_lambda_avx2(
        &self,
        planes: &[f32],
        to: usize,
        qx: [f32; LANES],
        qy: f32,
    ) -> [f32; LANES] {
        if self.cube {
            return self.cube_lambda_lanes(planes, to, qx, qy);
        }
        let pl = lambda_planes_at(planes, to);
        quad_lambda8(&pl, &qx, &[qy; LANES], self.size, self.dims)
    }

    /// The s, t, r and q planes [`Sampler::quad_lambda_xy8`] reads for the coordinates at
    /// varying `to` of `planes`, looked up once for a primitive; None for a cube map, whose λ
    /// projects on the face of each quad (`cube_lambda_lanes`).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub fn lambda_planes_of(&self, planes: &[f32], to: usize) -> Option<[[f32; 3]; 4]> {
        (!self.cube).then(|| lambda_planes_at(planes, to))
    }

    /// λ of eight 2x2 quads of one primitive, lane l's lower-left pixel at (`qx[l]`, `qy[l]`)
    /// relative to the planes' origin, from its planes `pl` ([`Sampler::lambda_planes_of`]):
    /// the kernel of [`Sampler::quad_lambda_row`], each lane with its own row, so each lane
    /// the bits `quad_lambda_row` gives its quad.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub unsafe fn quad_lambda_xy8(
        &self,
        pl: &[[f32; 3]; 4],
        qx: &[f32; LANES],
        qy: &[f32; LANES],
    ) -> [f32; LANES] {
        quad_lambda8(pl, qx, qy, self.size, self.dims)
    }

    /// [`Sampler::quad_lambda_lanes`] without AVX2: plain lane loops (SSE2 on x86-64).
    #[inline(always)]
    fn quad_lambda_on(&self, planes: &[f32], to: usize, qx: [f32; LANES], qy: f32) -> [f32; LANES] {
        if self.cube {
            return self.cube_lambda_lanes(planes, to, qx, qy);
        }
        let [ps, pt, pr, pq] = lambda_planes(planes, to);
        let (size, dims) = (self.size, self.dims);
        let mut qx1 = qx;
        for x in &mut qx1 {
            *x += 1.0;
        }
        let p0 = lambda_point(&ps, &pt, &pr, &pq, &qx, qy, size, dims);
        let px = lambda_point(&ps, &pt, &pr, &pq, &qx1, qy, size, dims);
        let py = lambda_point(&ps, &pt, &pr, &pq, &qx, qy + 1.0, size, dims);
        // `len2` of `quad_lambda` for both neighbours, then the larger, lane by lane.
        let mut rho2 = [0.0f32; LANES];
        for l in 0..LANES {
            let (ax, ay, az) = (
                px[0][l] - p0[0][l],
                px[1][l] - p0[1][l],
                px[2][l] - p0[2][l],
            );
            let (bx, by, bz) = (
                py[0][l] - p0[0][l],
                py[1][l] - p0[1][l],
                py[2][l] - p0[2][l],
            );
            let lx = ax * ax + ay * ay + az * az;
            let ly = bx * bx + by * by + bz * bz;
            rho2[l] = lx.max(ly);
        }
        let lg = fast_log2_lanes(&rho2);
        let mut out = [0.0f32; LANES];
        for l in 0..LANES {
            out[l] = 0.5 * lg[l];
        }
        out
    }

    /// The texture unit this sampler belongs to.
    #[inline]
    pub fn unit(&self) -> usize {
        self.unit
    }

    /// Is the environment COMBINE with a TEXTUREn source? Then every unit's texel must be
    /// known before it runs ([`Sampler::shade_texel`]).
    #[inline]
    pub fn crossbar(&self) -> bool {
        self.crossbar
    }

    /// The texture-environment result for fragment colour `cf` (the previous unit's result),
    /// primary colour `prim` (COMBINE's PRIMARY_COLOR), texture coordinates `(s, t, r, q)`
    /// (already perspective-correct) and level of detail `lambda` before bias. For an
    /// environment without TEXTUREn sources (`!self.crossbar()`).
    #[inline]
    pub fn shade(&self, cf: Vec4, prim: Vec4, coords: [f32; 4], lambda: f32) -> Vec4 {
        let texel = self.texel(coords, lambda);
        self.shade_texel(cf, prim, texel, &[])
    }

    /// This unit's filtered texel (internal components) at texture coordinates `(s, t, r, q)`
    /// (already perspective-correct) and level of detail `lambda` before bias.
    #[inline]
    pub fn texel(&self, coords: [f32; 4], lambda: f32) -> [f32; 4] {
        let [s, t, r, q] = coords;
        let inv = if q != 0.0 { 1.0 / q } else { 0.0 };
        let (s, t, r) = (s * inv, t * inv, r * inv);
        let (face, s, t) = if self.cube {
            let (face, ..) = cube_face([s, t, r]);
            let (s, t) = cube_project(face, [s, t, r]);
            (face, s, t)
        } else {
            (0, s, t)
        };
        // The route was chosen once for the flush: without mipmaps and with equal filters, λ
        // cannot matter and the base level's filter is called directly.
        match self.route {
            Route::Nearest => self.nearest(face, self.base_level, s, t, r),
            Route::Linear => self.linear(face, self.base_level, s, t, r),
            Route::Lod => self.sample_face(face, s, t, r, lambda),
        }
    }

    /// Can [`Sampler::texels_lanes`] and [`Sampler::env_lanes_with`] stand for
    /// [`Sampler::shade`]: every target (1D, 3D and cube maps by `targets_lanes`; depth
    /// textures and the depth comparison included) and every environment but a COMBINE with
    /// TEXTUREn sources (the crossbar needs the other units' texels). Chosen once per span.
    #[inline]
    pub fn lanes_ok(&self) -> bool {
        !self.crossbar
    }

    /// The filtered texels of eight fragments (the texel `shade` filters for each, lane-major)
    /// from their coordinates `coords` (s, t, r, q lanes, perspective-correct) and λ before
    /// bias; lanes outside `m` are left zero. Only for a sampler with [`Sampler::lanes_ok`].
    /// Each lane's level(s), filter and weight come from [`Sampler::select`] (as in
    /// `sample_face`), then one pass per filter (NEAREST, LINEAR) covers every lane whatever its
    /// level; each lane computes `shade`'s expressions in the same order (the division by q as
    /// `divps`), so its texel has the scalar texel's bits.
    #[inline]
    pub fn texels_lanes(
        &self,
        coords: [&[f32; LANES]; 4],
        lambda: &[f32; LANES],
        m: u8,
    ) -> TexelLanes {
        if self.dims != 2 || self.cube {
            return self.targets_texels(coords, lambda, m);
        }
        let [s, t, r, q] = coords;
        let inv = inv_q_lanes(q);
        let (ss, tt) = (mul_lanes(s, &inv), mul_lanes(t, &inv));
        // r/q is read by the depth comparison only.
        let rr = if self.compare.is_some() {
            mul_lanes(r, &inv)
        } else {
            [0.0f32; LANES]
        };
        let mut out = [[0.0f32; 4]; LANES];
        match self.route {
            Route::Nearest => self.pass_level(false, self.base_level, &ss, &tt, &rr, m, &mut out),
            Route::Linear => self.pass_level(true, self.base_level, &ss, &tt, &rr, m, &mut out),
            Route::Lod => self.lod_lanes(&ss, &tt, &rr, lambda, m, &mut out),
        }
        out
    }

    /// The level, filter (LINEAR: true) and second-level weight f (0: one level only; else
    /// the result is (1 - f)·level + f·(level + 1)) that λ before bias selects (§3.8.8,
    /// §3.8.9): the choice [`Sampler::sample_face`] and [`Sampler::lod_lanes`] share. The
    /// ceil and floor are computed by truncation (exact on the small positive values involved:
    /// λ is bounded below by c ≥ 0 here and at most `span` + 2 after the cap), since
    /// `f32::ceil`/`floor` are library calls on the x86-64 baseline.
    #[inline(always)]
    fn select(&self, lambda: f32) -> (i32, bool, f32) {
        // §3.8.8 clamps λ to [TEXTURE_MIN_LOD, TEXTURE_MAX_LOD], but TexParameter accepts any
        // float (§3.8.4), so min > max and NaN reach here; `f32::clamp` would panic. The order is
        // llvmpipe's (`lp_build_lod_selector`: min with MAX_LOD, then max with MIN_LOD): when
        // min > max, MIN_LOD wins. A NaN bound does not bound (f32::min/max ignore NaN); a NaN
        // λ (NaN coordinates or bias) is taken as 0, before the bounds, as it always was.
        let lambda = lambda + self.bias;
        let lambda = if lambda.is_nan() { 0.0 } else { lambda };
        let lambda = lambda.min(self.max_lod).max(self.min_lod);
        if lambda <= self.c {
            return (self.base_level, self.mag != gl::NEAREST, 0.0);
        }
        let span = (self.last - self.base_level) as f32;
        let lin = lin(self.min) == gl::LINEAR;
        match self.min {
            gl::NEAREST_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_NEAREST => {
                // d = base + ceil(λ + 1/2) - 1 for λ > 1/2, else base; at most q. λ + 1/2 > 1
                // here (not NaN, possibly infinite); capping it at span + 2 first changes no
                // result (ceil is monotonic and ceil(span + 2) - 1 > span), and below 2^24 the
                // truncation is exact, so ceil is the truncation plus one where it fell short.
                let d = if lambda <= 0.5 {
                    0.0
                } else {
                    let x = (lambda + 0.5).min(span + 2.0);
                    let tr = x as i32 as f32;
                    let c = if tr < x { tr + 1.0 } else { tr };
                    (c - 1.0).min(span)
                };
                (self.base_level + d as i32, lin, 0.0)
            }
            gl::NEAREST_MIPMAP_LINEAR | gl::LINEAR_MIPMAP_LINEAR => {
                if lambda >= span {
                    return (self.last, lin, 0.0);
                }
                // 0 <= c < λ < span: floor is the truncation, exact.
                let d1 = lambda as i32;
                let f = lambda - d1 as f32;
                (self.base_level + d1, lin, f)
            }
            f => (self.base_level, f != gl::NEAREST, 0.0),
        }
    }

    /// [`Sampler::select`] for eight λ at once: the same steps as lane loops with selects
    /// (the minification filter's arm chosen once for the group, the floors by
    /// [`ifloor_lanes`]), each lane exactly the scalar choice. Returns the lanes' levels, the
    /// lanes that filter LINEAR (bit l) and the second-level weights.
    #[inline(always)]
    fn select_lanes(&self, lambda: &[f32; LANES]) -> ([i32; LANES], u8, [f32; LANES]) {
        // `select`'s bias, NaN and bounds, then the magnification lanes (λ <= c).
        let mut lam = [0.0f32; LANES];
        for l in 0..LANES {
            let x = lambda[l] + self.bias;
            let x = if x.is_nan() { 0.0 } else { x };
            lam[l] = x.min(self.max_lod).max(self.min_lod);
        }
        let (base, last) = (self.base_level, self.last);
        let span = (self.last - self.base_level) as f32;
        let span_i = last.wrapping_sub(base);
        let mut lv = [base; LANES];
        let mut f = [0.0f32; LANES];
        let min_lin = match self.min {
            gl::NEAREST_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_NEAREST => {
                // d = ceil(x) - 1 capped at span for λ > 1/2 (x = λ + 1/2 capped at span + 2,
                // at least 1 there), else 0; x taken as at least 0 on the other lanes so that
                // the floor is the truncation everywhere, and the ceil the truncation plus one
                // where it fell short, in integers (the values are exact small integers).
                let mut x = [0.0f32; LANES];
                for l in 0..LANES {
                    x[l] = (lam[l] + 0.5).min(span + 2.0).max(0.0);
                }
                let tr = ifloor_lanes(&x);
                for l in 0..LANES {
                    let c = tr[l] + i32::from((tr[l] as f32) < x[l]);
                    let d = (c - 1).min(span_i);
                    lv[l] = base.wrapping_add(if lam[l] <= 0.5 { 0 } else { d });
                }
                lin(self.min) == gl::LINEAR
            }
            gl::NEAREST_MIPMAP_LINEAR | gl::LINEAR_MIPMAP_LINEAR => {
                // The last level from λ >= span, else d1 = floor(λ) with 0 <= c < λ < span
                // (the truncation of λ clamped to [0, span], exact) and f = λ - d1.
                let mut x = [0.0f32; LANES];
                for l in 0..LANES {
                    x[l] = lam[l].max(0.0).min(span);
                }
                let d1 = ifloor_lanes(&x);
                for l in 0..LANES {
                    let top = lam[l] >= span;
                    lv[l] = if top { last } else { base.wrapping_add(d1[l]) };
                    f[l] = if top { 0.0 } else { lam[l] - d1[l] as f32 };
                }
                lin(self.min) == gl::LINEAR
            }
            m => m != gl::NEAREST,
        };
        // The magnification lanes (λ <= c): the base level, one level, the MAG filter; the
        // selects on the float compare (a `[bool; 8]` mask kept this loop scalar).
        let c = self.c;
        for l in 0..LANES {
            let mag = lam[l] <= c;
            lv[l] = if mag { base } else { lv[l] };
            f[l] = if mag { 0.0 } else { f[l] };
        }
        let mag = mask_le(&lam, c);
        let all = |b: bool| if b { 0xffu8 } else { 0 };
        let linear = (mag & all(self.mag != gl::NEAREST)) | (!mag & all(min_lin));
        (lv, linear, f)
    }

    /// `sample_face` for the lanes of `m` (face 0, 2D): each lane's level(s), filter and
    /// weight from [`Sampler::select_lanes`]. When every lane of `m` is on one level with one
    /// filter (the common case: λ is per quad and neighbouring quads nearly always pick the
    /// same level), one pass on that level with its size and texels as scalars
    /// ([`Sampler::pass_level`]), then the trilinear lanes' next level and the blend;
    /// otherwise a pass per filter over the lanes using it (each lane on its own level), then
    /// the second level of the trilinear lanes and the blend.
    #[inline]
    fn lod_lanes(
        &self,
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        lambda: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        let (la, linear, f) = self.select_lanes(lambda);
        let first = la[(m.trailing_zeros() as usize).min(LANES - 1)];
        let (second, same) = (mask_ne_zero(&f), mask_eq(&la, first));
        let (linear, second) = (linear & m, second & m);
        if same & m == m && (linear == 0 || linear == m) {
            let linear = linear != 0;
            self.pass_level(linear, first, s, t, r, m, out);
            if second != 0 {
                // f ≠ 0 only below `span`: first + 1 is at most `last`.
                let mut b = [[0.0f32; 4]; LANES];
                self.pass_level(linear, first.saturating_add(1), s, t, r, second, &mut b);
                blend_levels(out, &b, &f, second);
            }
            return;
        }
        self.pass(false, &la, s, t, r, m & !linear, out);
        self.pass(true, &la, s, t, r, linear, out);
        if second == 0 {
            return;
        }
        let mut lb = [self.base_level; LANES];
        for l in 0..LANES {
            if second & (1 << l) != 0 {
                // f ≠ 0 only below `span`: level + 1 is at most `last`.
                lb[l] = la[l].saturating_add(1);
            }
        }
        let mut b = [[0.0f32; 4]; LANES];
        self.pass(false, &lb, s, t, r, second & !linear, &mut b);
        self.pass(true, &lb, s, t, r, second & linear, &mut b);
        blend_levels(out, &b, &f, second);
    }

    /// NEAREST (`linear` false) or LINEAR on a 2D texture for the lanes of `m`, every lane on
    /// level `level`: its texels and size looked up once and passed on as scalars. A missing
    /// level gives (0, 0, 0, 0), as `nearest` and `linear` give.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn pass_level(
        &self,
        linear: bool,
        level: i32,
        s: &[f32; LANES],
        t: &[f32; LANES],
        r: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
    ) {
        if m == 0 {
            return;
        }
        let Some(v) = self.obj.face_level(0, level) else {
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = [0.0; 4];
                }
            }
            return;
        };
        let tx: &[[f32; 4]] = &v.texels;
        let (w, h) = (v.width, v.height);
        let dense = dense_level(tx, w, h).then_some(tx);
        if let (Some(dt), Some(kind)) = (dense, kernel_kind(linear, self.wrap)) {
            match self.compare {
                None => return dense_kernel(kind, dt, w, h, s, t, m, out),
                // A depth texture's NEAREST: the kernel's gather (the texels `pass_on` reads),
                // then the comparison of each lane's one texel, as below.
                Some(func) if !linear => {
                    if dense_depth(kind, func, dt, w, h, s, t, r, m, out) {
                        return;
                    }
                    dense_kernel(kind, dt, w, h, s, t, m, out);
                    return depth_compare_lanes(func, r, m, out);
                }
                Some(_) => {}
            }
        }
        // A border texel (CLAMP_TO_BORDER, LINEAR's CLAMP): the AVX2 border kernel, the same way.
        if let (Some(dt), Some(kind)) = (dense, border_kind(linear, self.wrap)) {
            let border = crate::texture::keep(self.base, self.border);
            match self.compare {
                None => return dense_border(kind, dt, w, h, border, s, t, m, out),
                Some(func) if !linear => {
                    dense_border(kind, dt, w, h, border, s, t, m, out);
                    return depth_compare_lanes(func, r, m, out);
                }
                Some(_) => {}
            }
        }
        match self.compare {
            None => self.pass_on(linear, tx, dense, w, h, s, t, m, out, |_, t| t),
            // NEAREST compares each lane's one texel: after the gather, the function chosen once.
            Some(func) if !linear => {
                self.pass_on(false, tx, dense, w, h, s, t, m, out, |_, t| t);
                depth_compare_lanes(func, r, m, out);
            }
            Some(func) => self.pass_on(linear, tx, dense, w, h, s, t, m, out, |l, t| {
                depth_compare(func, r[l], t)
            }),
        }
    }

    /// NEAREST (`linear` false) or LINEAR on a 2D texture for the lanes of `m`, lane l on
    /// level `lv[l]`: `nearest` and `linear` (dims 2) with the wrap mode chosen once; each
    /// texel through `fetch`'s depth comparison against the lane's `r` when comparison is on.
    /// A lane whose level is missing gets (0, 0, 0, 0), as `nearest` and `linear` give.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn pass(
        &self,
        linear: bool,
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
        // Each lane's level: its texels and size (looked up once per run of equal levels).
        let empty: &[[f32; 4]] = &[];
        let mut tx = [empty; LANES];
        let (mut w, mut h) = ([1i32; LANES], [1i32; LANES]);
        let mut have = 0u8;
        let mut cur: Option<(i32, Option<&Level>)> = None;
        for l in 0..LANES {
            if m & (1 << l) == 0 {
                continue;
            }
            let level = match cur {
                Some((k, v)) if k == lv[l] => v,
                _ => {
                    let v = self.obj.face_level(0, lv[l]);
                    cur = Some((lv[l], v));
                    v
                }
            };
            if let Some(v) = level {
                (tx[l], w[l], h[l]) = (&v.texels[..], v.width, v.height);
                have |= 1 << l;
            } else {
                out[l] = [0.0; 4];
            }
        }
        let m = m & have;
        match self.compare {
            None => self.pass_on(linear, &tx, None, &w, &h, s, t, m, out, |_, t| t),
            Some(func) if !linear => {
                self.pass_on(false, &tx, None, &w, &h, s, t, m, out, |_, t| t);
                depth_compare_lanes(func, r, m, out);
            }
            Some(func) => self.pass_on(linear, &tx, None, &w, &h, s, t, m, out, |l, t| {
                depth_compare(func, r[l], t)
            }),
        }
    }

    /// `pass` on the lanes' levels (texels `tx`, widths `w`, heights `h`: per lane, or one
    /// level for all), `cmp(l, texel)` giving what `fetch` makes of lane l's texel (itself, or
    /// the comparison result). The wrap indices and weights are computed on all eight lanes
    /// (integer indices and inside flags, no `Option`), the texels fetched lane by lane (a
    /// gather) and blended with the weights computed on lanes. `dense`: the one level's texels
    /// when [`dense_level`] holds for them (then every in-image index is below their power-of-two
    /// length, and the gathers read them through an index mask instead of a bounds check).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pass_on<X: Texels, A: Axis>(
        &self,
        linear: bool,
        tx: X,
        dense: Option<&[[f32; 4]]>,
        w: A,
        h: A,
        s: &[f32; LANES],
        t: &[f32; LANES],
        m: u8,
        out: &mut TexelLanes,
        cmp: impl Fn(usize, [f32; 4]) -> [f32; 4],
    ) {
        // `fetch`'s texel: the image's (`texel3` at k = 0 is `texel`) or the border colour.
        let border = crate::texture::keep(self.base, self.border);
        let texel = |l: usize, i: i32, j: i32, inside: bool| {
            cmp(
                l,
                if inside {
                    // `Level::texel`'s expression.
                    tx.get(l, (j * w.at(l) + i) as usize)
                } else {
                    border
                },
            )
        };
        // Wrap modes whose indices are always inside the image (no border texel).
        let edge = |mode: u32| matches!(mode, gl::CLAMP | gl::CLAMP_TO_BORDER);
        if !linear {
            let (i, ii) = wrap_nearest_lanes(self.wrap[0], s, w);
            let (j, ji) = wrap_nearest_lanes(self.wrap[1], t, h);
            // NEAREST's CLAMP clamps the index like CLAMP_TO_EDGE: only CLAMP_TO_BORDER can
            // leave the image.
            let in_image =
                self.wrap[0] != gl::CLAMP_TO_BORDER && self.wrap[1] != gl::CLAMP_TO_BORDER;
            if let (true, Some(dt)) = (in_image, dense) {
                // Every index inside a level of w·h texels: k = j·w + i < w·h = dt.len().
                let Some(km) = dt.len().checked_sub(1) else {
                    return;
                };
                let wl = w.at(0);
                let mut k = [0i32; LANES];
                for l in 0..LANES {
                    k[l] = j[l].wrapping_mul(wl).wrapping_add(i[l]);
                }
                for (l, o) in out.iter_mut().enumerate() {
                    if m & (1 << l) != 0 {
                        *o = cmp(l, dt[k[l] as usize & km]);
                    }
                }
                return;
            }
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) != 0 {
                    *o = texel(l, i[l], j[l], ii[l] && ji[l]);
                }
            }
            return;
        }
        let x = wrap_linear_lanes(self.wrap[0], s, w);
        let y = wrap_linear_lanes(self.wrap[1], t, h);
        // The four weights of eq. 3.24 as the scalar expression groups them:
        // (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11.
        let mut wt = [[0.0f32; LANES]; 4];
        for (l, (&a, &b)) in x.w.iter().zip(&y.w).enumerate() {
            wt[0][l] = (1.0 - a) * (1.0 - b);
            wt[1][l] = a * (1.0 - b);
            wt[2][l] = (1.0 - a) * b;
            wt[3][l] = a * b;
        }
        if let (false, false, Some(dt)) = (edge(self.wrap[0]), edge(self.wrap[1]), dense) {
            // As below, the four indices of each lane on lanes and the gathers through the
            // index mask (each index j·w + i < w·h = dt.len(), so the mask keeps it).
            let Some(km) = dt.len().checked_sub(1) else {
                return;
            };
            let wl = w.at(0);
            let mut k = [[0i32; LANES]; 4];
            // A plain lane loop over the four index arrays (clippy would have it iterate one).
            #[allow(clippy::needless_range_loop)]
            for l in 0..LANES {
                let (r0, r1) = (y.i0[l].wrapping_mul(wl), y.i1[l].wrapping_mul(wl));
                k[0][l] = r0.wrapping_add(x.i0[l]);
                k[1][l] = r0.wrapping_add(x.i1[l]);
                k[2][l] = r1.wrapping_add(x.i0[l]);
                k[3][l] = r1.wrapping_add(x.i1[l]);
            }
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) == 0 {
                    continue;
                }
                let at = |c: usize| cmp(l, dt[k[c][l] as usize & km]);
                *o = bilinear(
                    [wt[0][l], wt[1][l], wt[2][l], wt[3][l]],
                    [at(0), at(1), at(2), at(3)],
                );
            }
            return;
        }
        if !edge(self.wrap[0]) && !edge(self.wrap[1]) {
            // No index can fall outside the image (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT on
            // both axes): the four texels of each lane without the border choice, the row
            // offsets j·w once per row (`Level::texel`'s (j·w + i) as usize).
            for (l, o) in out.iter_mut().enumerate() {
                if m & (1 << l) == 0 {
                    continue;
                }
                let wl = w.at(l);
                let (r0, r1) = (y.i0[l] * wl, y.i1[l] * wl);
                let at = |k: i32| cmp(l, tx.get(l, k as usize));
                let (t00, t10) = (at(r0 + x.i0[l]), at(r0 + x.i1[l]));
                let (t01, t11) = (at(r1 + x.i0[l]), at(r1 + x.i1[l]));
                *o = bilinear(
                    [wt[0][l], wt[1][l], wt[2][l], wt[3][l]],
                    [t00, t10, t01, t11],
                );
            }
            return;
        }
        for (l, o) in out.iter_mut().enumerate() {
            if m & (1 << l) == 0 {
                continue;
            }
            let t00 = texel(l, x.i0[l], y.i0[l], x.in0[l] && y.in0[l]);
            let t10 = texel(l, x.i1[l], y.i0[l], x.in1[l] && y.in0[l]);
            let t01 = texel(l, x.i0[l], y.i1[l], x.in0[l] && y.in1[l]);
            let t11 = texel(l, x.i1[l], y.i1[l], x.in1[l] && y.in1[l]);
            *o = bilinear(
                [wt[0][l], wt[1][l], wt[2][l], wt[3][l]],
                [t00, t10, t01, t11],
            );
        }
    }

    /// Table 3.21 for the lanes of `m`: `env` of each lane's colour `cf[l]` and texel `t[l]`,
    /// the (environment, base format) pair chosen once for the group. Only for a sampler with
    /// [`Sampler::lanes_ok`] (not COMBINE). A depth texture reads as DEPTH_TEXTURE_MODE, as in
    /// `env`.
    #[inline]
    pub fn env_lanes(&self, cf: &mut [Vec4; LANES], t: &TexelLanes, m: u8) {
        if crate::texture::is_depth(self.base) {
            // A depth texture through DEPTH_TEXTURE_MODE; the common pairs with the
            // environment and the mode constant, so that `env_of`'s choice folds away.
            macro_rules! depth_each {
                ($e:expr, $b:expr) => {{
                    let (env, base) = ($e, $b);
                    for l in 0..LANES {
                        if m & (1 << l) != 0 {
                            let t = if base == gl::ALPHA {
                                [0.0, 0.0, 0.0, t[l][0]]
                            } else {
                                t[l]
                            };
                            cf[l] = env_of(env, base, self.env_color, cf[l], t);
                        }
                    }
                }};
            }
            match (self.env, self.depth_mode) {
                (gl::BLEND, gl::LUMINANCE) => depth_each!(gl::BLEND, gl::LUMINANCE),
                (gl::MODULATE, gl::LUMINANCE) => depth_each!(gl::MODULATE, gl::LUMINANCE),
                (gl::REPLACE, gl::LUMINANCE) => depth_each!(gl::REPLACE, gl::LUMINANCE),
                (gl::MODULATE, gl::INTENSITY) => depth_each!(gl::MODULATE, gl::INTENSITY),
                (e, gl::ALPHA) => depth_each!(e, gl::ALPHA),
                (e, b) => depth_each!(e, b),
            }
            return;
        }
        macro_rules! each {
            ($e:expr, $b:expr) => {
                for l in 0..LANES {
                    if m & (1 << l) != 0 {
                        cf[l] = env_of($e, $b, self.env_color, cf[l], t[l]);
                    }
                }
            };
        }
        match (self.env, self.base) {
            (gl::MODULATE, gl::RGBA) => each!(gl::MODULATE, gl::RGBA),
            (gl::MODULATE, gl::RGB) => each!(gl::MODULATE, gl::RGB),
            (gl::REPLACE, gl::RGBA) => each!(gl::REPLACE, gl::RGBA),
            (gl::REPLACE, gl::RGB) => each!(gl::REPLACE, gl::RGB),
            (gl::DECAL, gl::RGBA) => each!(gl::DECAL, gl::RGBA),
            (gl::ADD, gl::RGBA) => each!(gl::ADD, gl::RGBA),
            (e, b) => each!(e, b),
        }
    }

    /// `texel` (from [`Sampler::texel`]) as COMBINE reads it (table 3.23's Cs and As): the
    /// base internal format expanded to RGBA, a depth texture through DEPTH_TEXTURE_MODE. What
    /// another unit's TEXTUREn source reads of this unit ([`UnitTexels`]).
    #[inline]
    pub fn combine_texel(&self, texel: [f32; 4]) -> Vec4 {
        let (base, t) = if crate::texture::is_depth(self.base) {
            match self.depth_mode {
                gl::ALPHA => (gl::ALPHA, [0.0, 0.0, 0.0, texel[0]]),
                m => (m, texel),
            }
        } else {
            (self.base, texel)
        };
        Vec4::from_array(as_rgba(base, t))
    }

    /// The texture-environment result for fragment colour `cf`, primary colour `prim` and this
    /// unit's filtered texel `texel` (from [`Sampler::texel`]); `units` holds every unit's
    /// texel for COMBINE's TEXTUREn sources (only read when [`Sampler::crossbar`]).
    #[inline]
    pub fn shade_texel(
        &self,
        cf: Vec4,
        prim: Vec4,
        texel: [f32; 4],
        units: &[Option<Vec4>],
    ) -> Vec4 {
        if self.env == gl::COMBINE {
            return self.combine(cf, prim, self.combine_texel(texel), units);
        }
        self.env(cf, texel)
    }

    /// The COMBINE function (§3.8.13, tables 3.23 and 3.24) of the previous result `cf`, the
    /// primary colour `prim`, this unit's texel `tex` (as [`Sampler::combine_texel`] gives it)
    /// and, for a source TEXTUREn (ARB_texture_env_crossbar, core in GL 1.4), unit n's texel in
    /// `units`. A disabled unit n, which the spec leaves undefined, reads (0, 0, 0, 0): Mesa's
    /// fixed-function fragment program loads zero for it (measured on llvmpipe in
    /// tests/it/crossbar_gl.rs).
    fn combine(&self, cf: Vec4, prim: Vec4, tex: Vec4, units: &[Option<Vec4>]) -> Vec4 {
        let c = &self.combine;
        let src = |s: u32| match s {
            gl::CONSTANT => self.env_color,
            gl::PRIMARY_COLOR => prim,
            gl::PREVIOUS => cf,
            gl::TEXTURE => tex,
            s => unit_of_source(s)
                .and_then(|n| units.get(n).copied().flatten())
                .unwrap_or(Vec4::ZERO),
        };
        let arg_rgb = |k: usize| {
            let v = src(c.src_rgb[k]);
            match c.operand_rgb[k] {
                gl::ONE_MINUS_SRC_COLOR => Vec4::ONE - v,
                gl::SRC_ALPHA => Vec4::splat(v.w),
                gl::ONE_MINUS_SRC_ALPHA => Vec4::splat(1.0 - v.w),
                _ => v,
            }
        };
        let arg_a = |k: usize| {
            let a = src(c.src_alpha[k]).w;
            if c.operand_alpha[k] == gl::ONE_MINUS_SRC_ALPHA {
                1.0 - a
            } else {
                a
            }
        };
        let rgb = match c.rgb {
            gl::REPLACE => arg_rgb(0),
            gl::MODULATE => arg_rgb(0) * arg_rgb(1),
            gl::ADD => arg_rgb(0) + arg_rgb(1),
            gl::ADD_SIGNED => arg_rgb(0) + arg_rgb(1) - Vec4::splat(0.5),
            gl::INTERPOLATE => {
                let a2 = arg_rgb(2);
                arg_rgb(0) * a2 + arg_rgb(1) * (Vec4::ONE - a2)
            }
            gl::SUBTRACT => arg_rgb(0) - arg_rgb(1),
            _ => {
                // DOT3_RGB(A): 4·Σ (a0 - 1/2)(a1 - 1/2) over r, g, b into every channel.
                let d = (arg_rgb(0) - Vec4::splat(0.5)).truncate();
                let e = (arg_rgb(1) - Vec4::splat(0.5)).truncate();
                Vec4::splat(4.0 * d.dot(e))
            }
        };
        let a = if c.rgb == gl::DOT3_RGBA {
            rgb.x
        } else {
            match c.alpha {
                gl::REPLACE => arg_a(0),
                gl::MODULATE => arg_a(0) * arg_a(1),
                gl::ADD => arg_a(0) + arg_a(1),
                gl::ADD_SIGNED => arg_a(0) + arg_a(1) - 0.5,
                gl::INTERPOLATE => arg_a(0) * arg_a(2) + arg_a(1) * (1.0 - arg_a(2)),
                _ => arg_a(0) - arg_a(1),
            }
        };
        // RGB_SCALE and ALPHA_SCALE, then the clamp (§3.8.13); DOT3_RGBA's alpha is scaled by
        // ALPHA_SCALE like any alpha (as llvmpipe does; measured in the GL-backend test).
        (rgb * c.rgb_scale)
            .truncate()
            .extend(a * c.alpha_scale)
            .clamp(Vec4::ZERO, Vec4::ONE)
    }

    /// The filtered texel (internal components: L and I in R) at (s, t), depth compared
    /// against `r` when comparison is on (§3.8.8, §3.8.14).
    #[cfg(test)]
    pub fn sample(&self, s: f32, t: f32, r: f32, lambda: f32) -> [f32; 4] {
        self.sample_face(0, s, t, r, lambda)
    }

    /// [`Sampler::sample`] on face `face` of a cube map (0 for the other targets).
    fn sample_face(&self, face: usize, s: f32, t: f32, r: f32, lambda: f32) -> [f32; 4] {
        let (level, linear, f) = self.select(lambda);
        let filter = if linear { gl::LINEAR } else { gl::NEAREST };
        let a = self.filter(face, level, filter, s, t, r);
        if f == 0.0 {
            return a;
        }
        let b = self.filter(face, level + 1, filter, s, t, r);
        std::array::from_fn(|k| a[k] * (1.0 - f) + b[k] * f)
    }

    /// NEAREST or LINEAR on one level (§3.8.8, the wrap modes of §3.8.7).
    #[inline]
    fn filter(&self, face: usize, level: i32, filter: u32, s: f32, t: f32, r: f32) -> [f32; 4] {
        if filter == gl::NEAREST {
            self.nearest(face, level, s, t, r)
        } else {
            self.linear(face, level, s, t, r)
        }
    }

    /// NEAREST on level `level`: the texel containing (u, v, w) (eq. 3.22).
    #[inline]
    fn nearest(&self, face: usize, level: i32, s: f32, t: f32, r: f32) -> [f32; 4] {
        let Some(lv) = self.obj.face_level(face, level) else {
            return [0.0; 4];
        };
        let i = wrap_nearest(self.wrap[0], s, lv.width);
        match self.dims {
            1 => self.fetch(lv, i, Some(0), Some(0), r),
            2 => {
                let j = wrap_nearest(self.wrap[1], t, lv.height);
                match (self.compare, i, j) {
                    // Inside the image, no comparison: `fetch`'s texel without its choices.
                    (None, Some(i), Some(j)) => lv.texel(i, j),
                    _ => self.fetch(lv, i, j, Some(0), r),
                }
            }
            _ => {
                let j = wrap_nearest(self.wrap[1], t, lv.height);
                let k = wrap_nearest(self.wrap[2], r, lv.depth);
                self.fetch(lv, i, j, k, r)
            }
        }
    }

    /// LINEAR on level `level`: the 2 (1D), 2x2 or 2x2x2 (3D) texels around (u, v, w)
    /// weighted by eq. 3.24 (and its 1D and 3D forms).
    #[inline]
    fn linear(&self, face: usize, level: i32, s: f32, t: f32, r: f32) -> [f32; 4] {
        self.linear_on::<true>(face, level, s, t, r)
    }

    /// [`Sampler::linear`], with (`FAST3`) or without the 3D in-image route (the tests compare
    /// the two bit for bit).
    #[inline(always)]
    fn linear_on<const FAST3: bool>(
        &self,
        face: usize,
        level: i32,
        s: f32,
        t: f32,
        r: f32,
    ) -> [f32; 4] {
        let Some(lv) = self.obj.face_level(face, level) else {
            return [0.0; 4];
        };
        let (i0, i1, a) = wrap_linear(self.wrap[0], s, lv.width);
        if self.dims == 1 {
            let t0 = self.fetch(lv, i0, Some(0), Some(0), r);
            let t1 = self.fetch(lv, i1, Some(0), Some(0), r);
            return std::array::from_fn(|c| (1.0 - a) * t0[c] + a * t1[c]);
        }
        let (j0, j1, b) = wrap_linear(self.wrap[1], t, lv.height);
        // A 2D image with four texels inside it and no depth comparison (the common case):
        // the same texels (`texel` is `texel3` at k = 0) and weights, without the border and
        // comparison choices made per texel.
        if let (2, None, Some(i0), Some(i1), Some(j0), Some(j1)) =
            (self.dims, self.compare, i0, i1, j0, j1)
        {
            let (t00, t10) = (lv.texel(i0, j0), lv.texel(i1, j0));
            let (t01, t11) = (lv.texel(i0, j1), lv.texel(i1, j1));
            return std::array::from_fn(|c| {
                (1.0 - a) * (1.0 - b) * t00[c]
                    + a * (1.0 - b) * t10[c]
                    + (1.0 - a) * b * t01[c]
                    + a * b * t11[c]
            });
        }
        // A 3D image with its eight texels inside it and no depth comparison (the 1D and 3D
        // levels of texture-targets' sparse lanes): `plane`'s texels (`fetch` is `texel3`
        // there) and sums in the same order, without the per-texel choices and the closure
        // call (not inlined: ≈128 instructions a plane).
        if FAST3 && self.dims == 3 && self.compare.is_none() {
            let (k0, k1, g) = wrap_linear(self.wrap[2], r, lv.depth);
            if let (Some(i0), Some(i1), Some(j0), Some(j1), Some(k0), Some(k1)) =
                (i0, i1, j0, j1, k0, k1)
            {
                // `plane`'s (1 - α)(1 - β)·t00 + α(1 - β)·t10 + (1 - α)β·t01 + αβ·t11.
                let w = [(1.0 - a) * (1.0 - b), a * (1.0 - b), (1.0 - a) * b, a * b];
                let p0 = bilinear(
                    w,
                    [
                        lv.texel3(i0, j0, k0),
                        lv.texel3(i1, j0, k0),
                        lv.texel3(i0, j1, k0),
                        lv.texel3(i1, j1, k0),
                    ],
                );
                let p1 = bilinear(
                    w,
                    [
                        lv.texel3(i0, j0, k1),
                        lv.texel3(i1, j0, k1),
                        lv.texel3(i0, j1, k1),
                        lv.texel3(i1, j1, k1),
                    ],
                );
                return std::array::from_fn(|c| (1.0 - g) * p0[c] + g * p1[c]);
            }
        }
        let plane = |k: Option<i32>| {
            let t00 = self.fetch(lv, i0, j0, k, r);
            let t10 = self.fetch(lv, i1, j0, k, r);
            let t01 = self.fetch(lv, i0, j1, k, r);
            let t11 = self.fetch(lv, i1, j1, k, r);
            std::array::from_fn(|c| {
                (1.0 - a) * (1.0 - b) * t00[c]
                    + a * (1.0 - b) * t10[c]
                    + (1.0 - a) * b * t01[c]
                    + a * b * t11[c]
            })
        };
        if self.dims == 2 {
            return plane(Some(0));
        }
        let (k0, k1, g) = wrap_linear(self.wrap[2], r, lv.depth);
        let p0: [f32; 4] = plane(k0);
        let p1: [f32; 4] = plane(k1);
        std::array::from_fn(|c| (1.0 - g) * p0[c] + g * p1[c])
    }

    /// The texel at (i, j), the border colour where a wrap mode says so (None), and the depth
    /// comparison result in place of a depth when comparison is on.
    #[inline(always)]
    fn fetch(
        &self,
        lv: &Level,
        i: Option<i32>,
        j: Option<i32>,
        k: Option<i32>,
        r: f32,
    ) -> [f32; 4] {
        let t = match (i, j, k) {
            (Some(i), Some(j), Some(k)) => lv.texel3(i, j, k),
            // The border colour in the base format's components (table 3.15).
            _ => crate::texture::keep(self.base, self.border),
        };
        match self.compare {
            Some(func) => depth_compare(func, r, t),
            None => t,
        }
    }

    /// Table 3.21: the texture function `env` of fragment colour `cf` and filtered texel `t`.
    pub fn env(&self, cf: Vec4, t: [f32; 4]) -> Vec4 {
        // A depth texture reads as DEPTH_TEXTURE_MODE (§3.8.14).
        let (base, t) = if crate::texture::is_depth(self.base) {
            match self.depth_mode {
                gl::ALPHA => (gl::ALPHA, [0.0, 0.0, 0.0, t[0]]),
                m => (m, t),
            }
        } else {
            (self.base, t)
        };
        env_of(self.env, base, self.env_color, cf, t)
    }
}

/// Table 3.21: texture function `env` of fragment colour `cf` and filtered texel `t` read as
/// base format `base`, with TEXTURE_ENV_COLOR `env_color` (what [`Sampler::env`] and
/// [`Sampler::env_lanes`] compute; inlined so that constant `env` and `base` fold the match).
#[inline(always)]
fn env_of(env: u32, base: u32, env_color: Vec4, cf: Vec4, t: [f32; 4]) -> Vec4 {
    let ct = Vec4::new(t[0], t[1], t[2], 0.0);
    let l = t[0];
    let at = t[3];
    let (cfr, af) = (cf.truncate().extend(0.0), cf.w);
    let cc = env_color.truncate().extend(0.0);
    let lum = Vec4::new(l, l, l, 0.0);
    let (c, a) = match (env, base) {
        (gl::REPLACE, gl::ALPHA) => (cfr, at),
        (gl::REPLACE, gl::LUMINANCE) => (lum, af),
        (gl::REPLACE, gl::LUMINANCE_ALPHA) => (lum, at),
        (gl::REPLACE, gl::INTENSITY) => (lum, l),
        (gl::REPLACE, gl::RGB) => (ct, af),
        (gl::REPLACE, _) => (ct, at),
        (gl::MODULATE, gl::ALPHA) => (cfr, af * at),
        (gl::MODULATE, gl::LUMINANCE) => (cfr * l, af),
        (gl::MODULATE, gl::LUMINANCE_ALPHA) => (cfr * l, af * at),
        (gl::MODULATE, gl::INTENSITY) => (cfr * l, af * l),
        (gl::MODULATE, gl::RGB) => (cfr * ct, af),
        (gl::MODULATE, _) => (cfr * ct, af * at),
        // DECAL is undefined for the one- and two-component formats: the fragment passes.
        (gl::DECAL, gl::RGB) => (ct, af),
        (gl::DECAL, gl::RGBA) => (cfr * (1.0 - at) + ct * at, af),
        (gl::DECAL, _) => (cfr, af),
        (gl::BLEND, gl::ALPHA) => (cfr, af * at),
        (gl::BLEND, gl::LUMINANCE) => (cfr * (1.0 - l) + cc * l, af),
        (gl::BLEND, gl::LUMINANCE_ALPHA) => (cfr * (1.0 - l) + cc * l, af * at),
        (gl::BLEND, gl::INTENSITY) => (cfr * (1.0 - l) + cc * l, af * (1.0 - l) + env_color.w * l),
        (gl::BLEND, gl::RGB) => (cfr * (Vec4::ONE - ct) + cc * ct, af),
        (gl::BLEND, _) => (cfr * (Vec4::ONE - ct) + cc * ct, af * at),
        (gl::ADD, gl::ALPHA) => (cfr, af * at),
        (gl::ADD, gl::LUMINANCE) => (cfr + lum, af),
        (gl::ADD, gl::LUMINANCE_ALPHA) => (cfr + lum, af * at),
        (gl::ADD, gl::INTENSITY) => (cfr + lum, af + l),
        (gl::ADD, gl::RGB) => (cfr + ct, af),
        (gl::ADD, _) => (cfr + ct, af * at),
        _ => (cfr, af),
    };
    Vec4::new(c.x, c.y, c.z, a).clamp(Vec4::ZERO, Vec4::ONE)
}

/// The target and texture object unit `unit` samples, or None when texturing is off for the
/// unit.
///
/// Of the targets enabled on the unit, taken in §3.8.15's precedence (CUBE_MAP, 3D, 2D, 1D), the
/// first whose bound texture is complete (§3.8.10) is used. That is the driver's rule (Mesa's
/// `update_ff_texture_state` walks the enabled targets in this order and takes the first
/// complete one), and it is what `tests/texture_gl.rs` measures. GL 2.1 instead picks the
/// highest enabled target and disables the unit when its texture is incomplete; the two rules
/// differ only when a higher target's texture is incomplete: following the spec would leave a
/// unit with TEXTURE_2D and TEXTURE_3D enabled and an incomplete 3D texture untextured where the
/// driver textures it with the 2D texture.
fn unit_texture(state: &State, unit: usize) -> Option<(u32, &Arc<TexObject>)> {
    let e = &state.enables;
    let enabled = |flags: &[bool]| flags.get(unit).copied().unwrap_or(false);
    let order = [
        (gl::TEXTURE_CUBE_MAP, enabled(&e.texture_cube_map)),
        (gl::TEXTURE_3D, enabled(&e.texture_3d)),
        (gl::TEXTURE_2D, enabled(&e.texture_2d)),
        (gl::TEXTURE_1D, enabled(&e.texture_1d)),
    ];
    order
        .into_iter()
        .filter(|&(_, on)| on)
        .find_map(|(target, _)| {
            let obj = state.textures.bound(unit, target)?;
            obj.is_complete().then_some((target, obj))
        })
}

/// The unit a COMBINE source TEXTUREn names (the front end accepts n < MAX_TEXTURE_UNITS only).
#[inline]
fn unit_of_source(source: u32) -> Option<usize> {
    let n = source.wrapping_sub(gl::TEXTURE0) as usize;
    (n < MAX_TEXTURE_UNITS).then_some(n)
}

/// The cube-map face (0 to 5: +X, -X, +Y, -Y, +Z, -Z) of direction `p` by its major axis
/// (GL 2.1 §3.8.6, table 3.19), with llvmpipe's tie order (`lp_build_cube_lookup`: X over Y and
/// Z when |x| is at least as large, then Y over Z), and the axis magnitude.
#[inline]
fn cube_face([x, y, z]: [f32; 3]) -> (usize, f32) {
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    if ax >= ay && ax >= az {
        (if x >= 0.0 { 0 } else { 1 }, ax)
    } else if ay >= az {
        (if y >= 0.0 { 2 } else { 3 }, ay)
    } else {
        (if z >= 0.0 { 4 } else { 5 }, az)
    }
}

/// The face coordinates (s, t) of direction `p` on `face` (table 3.19, eq. 3.19):
/// s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
#[inline]
fn cube_project(face: usize, [x, y, z]: [f32; 3]) -> (f32, f32) {
    let (sc, tc, ma) = match face {
        0 => (-z, -y, x),
        1 => (z, -y, x),
        2 => (x, z, y),
        3 => (x, -z, y),
        4 => (x, -y, z),
        _ => (-x, -y, z),
    };
    let m = ma.abs();
    let inv = if m > 0.0 { 0.5 / m } else { 0.0 };
    (sc * inv + 0.5, tc * inv + 0.5)
}

/// [`cube_face`] then [`cube_project`] of eight directions (the lanes of `x`, `y`, `z`) at
/// once (AVX2): the faces, s and t of each lane, the scalar values bit for bit. The same
/// compares (`>=` and `>` ordered: false with a NaN, as in Rust), so the same face; the
/// negations and magnitudes as sign-bit flips and clears (what `-x` and `abs` do); the same
/// division, product and sum (`vdivps`, `vmulps`, `vaddps`, no fused multiply-add), the lanes
/// where |ma| is not above 0 taking 0 for 1/(2|ma|) as the scalar `inv`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::type_complexity)]
fn cube8(
    x: std::arch::x86_64::__m256,
    y: std::arch::x86_64::__m256,
    z: std::arch::x86_64::__m256,
) -> (
    std::arch::x86_64::__m256i,
    std::arch::x86_64::__m256,
    std::arch::x86_64::__m256,
) {
    use std::arch::x86_64::*;
    let sign = _mm256_set1_ps(-0.0);
    let abs = |v: __m256| _mm256_andnot_ps(sign, v);
    let neg = |v: __m256| _mm256_xor_ps(sign, v);
    let ge = |a: __m256, b: __m256| _mm256_cmp_ps::<_CMP_GE_OQ>(a, b);
    let zero = _mm256_setzero_ps();
    let (ax, ay, az) = (abs(x), abs(y), abs(z));
    // `cube_face`'s major axis: X where ax >= ay and ax >= az, else Y where ay >= az, else Z.
    let ox = _mm256_and_ps(ge(ax, ay), ge(ax, az));
    let oy = _mm256_andnot_ps(ox, ge(ay, az));
    let (px, py, pz) = (ge(x, zero), ge(y, zero), ge(z, zero));
    // The face: 4 (Z), 2 (Y) or 0 (X), plus 1 on the negative side (the masks are -1).
    let pos = _mm256_blendv_ps(_mm256_blendv_ps(pz, py, oy), px, ox);
    let icast = |v: __m256| _mm256_castps_si256(v);
    let face = _mm256_add_epi32(
        _mm256_add_epi32(_mm256_set1_epi32(5), icast(pos)),
        _mm256_add_epi32(
            _mm256_slli_epi32::<2>(icast(ox)),
            _mm256_slli_epi32::<1>(icast(oy)),
        ),
    );
    // `cube_project`'s sc, tc and |ma| per face: X ∓z, -y, ax; Y x, ±z, ay; Z ±x, -y, az.
    let sx = _mm256_blendv_ps(z, neg(z), px);
    let sz = _mm256_blendv_ps(neg(x), x, pz);
    let sc = _mm256_blendv_ps(_mm256_blendv_ps(sz, x, oy), sx, ox);
    let ty = _mm256_blendv_ps(neg(z), z, py);
    let tc = _mm256_blendv_ps(neg(y), ty, oy);
    let m = _mm256_blendv_ps(_mm256_blendv_ps(az, ay, oy), ax, ox);
    let inv = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_GT_OQ>(m, zero),
        _mm256_div_ps(_mm256_set1_ps(0.5), m),
    );
    let half = _mm256_set1_ps(0.5);
    (
        face,
        _mm256_add_ps(_mm256_mul_ps(sc, inv), half),
        _mm256_add_ps(_mm256_mul_ps(tc, inv), half),
    )
}

/// The depth comparison of §3.8.14 (TEXTURE_COMPARE_MODE COMPARE_R_TO_TEXTURE): `r` clamped
/// to [0, 1] against the texel's depth `t[0]` under `func`; 1 where it passes, else 0.
#[inline(always)]
fn depth_compare(func: u32, r: f32, t: [f32; 4]) -> [f32; 4] {
    let d = t[0];
    let r = r.clamp(0.0, 1.0);
    let pass = match func {
        gl::LEQUAL => r <= d,
        gl::GEQUAL => r >= d,
        gl::LESS => r < d,
        gl::GREATER => r > d,
        gl::EQUAL => r == d,
        gl::NOTEQUAL => r != d,
        gl::ALWAYS => true,
        _ => false,
    };
    [f32::from(u8::from(pass)), 0.0, 0.0, 0.0]
}

/// [`depth_compare`] of each lane of `m`, lane l's `r[l]` against the texel `out[l]`, into
/// `out[l]`: the function chosen once for the eight lanes (NEAREST's comparison after its
/// gather: the same texel, the same clamp and comparison as `fetch`'s).
#[inline(always)]
fn depth_compare_lanes(func: u32, r: &[f32; LANES], m: u8, out: &mut TexelLanes) {
    #[inline(always)]
    fn each(r: &[f32; LANES], m: u8, out: &mut TexelLanes, pass: impl Fn(f32, f32) -> bool) {
        for (l, o) in out.iter_mut().enumerate() {
            if m & (1 << l) != 0 {
                let p = pass(r[l].clamp(0.0, 1.0), o[0]);
                *o = [f32::from(u8::from(p)), 0.0, 0.0, 0.0];
            }
        }
    }
    match func {
        gl::LEQUAL => each(r, m, out, |r, d| r <= d),
        gl::GEQUAL => each(r, m, out, |r, d| r >= d),
        gl::LESS => each(r, m, out, |r, d| r < d),
        gl::GREATER => each(r, m, out, |r, d| r > d),
        gl::EQUAL => each(r, m, out, |r, d| r == d),
        gl::NOTEQUAL => each(r, m, out, |r, d| r != d),
        gl::ALWAYS => each(r, m, out, |_, _| true),
        _ => each(r, m, out, |_, _| false),
    }
}

/// log2 as exponent plus (mantissa - 1): exact at powers of two, linear between them.
#[cfg(test)]
#[inline(always)]
fn fast_log2(x: f32) -> f32 {
    if x.is_nan() || x <= 0.0 || x.is_infinite() {
        return x.log2();
    }
    let bits = x.to_bits();
    let e = ((bits >> 23) & 0xff) as i32 - 127;
    let m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    e as f32 + (m - 1.0)
}

/// `floor` as an index, saturating (NaN → 0), without a libm call: truncate, then step down
/// where truncation rounded up (negative non-integers).
#[inline(always)]
fn ifloor(x: f32) -> i32 {
    let t = x as i32;
    if (t as f32) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// MIRRORED_REPEAT's coordinate (§3.8.7): frac(s) where floor(s) is even, else 1 - frac(s).
#[inline(always)]
fn mirror(s: f32) -> f32 {
    let f = s - s.floor();
    if (s.floor() as i64).rem_euclid(2) == 0 {
        f
    } else {
        1.0 - f
    }
}

/// REPEAT's texel index `i.rem_euclid(n)` for `n` >= 1 (§3.8.7): a mask when `n` is a power
/// of two (the usual texture, and the same value for every i32 in two's complement), sparing
/// the integer division that dominated a bilinear REPEAT sample (four per 2D sample). What
/// [`wrap_nearest`] and [`wrap_linear`] compute through [`repeat_p`].
#[cfg(test)]
fn repeat(i: i32, n: i32) -> i32 {
    repeat_p(i, n, n & (n - 1) == 0)
}

/// The NEAREST texel index along an axis of `n` texels; None: the border colour.
#[inline(always)]
fn wrap_nearest(mode: u32, s: f32, n: i32) -> Option<i32> {
    let m = n.max(1);
    let (i, inside) = wrap_nearest_i(mode, s, n, m & (m - 1) == 0);
    inside.then_some(i)
}

/// The two LINEAR texel indices along an axis and the weight of the second (§3.8.8 eq. 3.24):
/// u = s·n - 1/2, i0 = floor(u), i1 = i0 + 1, α = frac(u); None: the border colour.
#[inline(always)]
fn wrap_linear(mode: u32, s: f32, n: i32) -> (Option<i32>, Option<i32>, f32) {
    let m = n.max(1);
    let (i0, i1, a, in0, in1) = wrap_linear_i(mode, s, n, m & (m - 1) == 0);
    (in0.then_some(i0), in1.then_some(i1), a)
}

/// One perspective-correct point of [`Sampler::quad_lambda_lanes`] on lanes: planes s, t, r
/// and q (each (a, ∂x, ∂y)) at (`x[l]`, `y`), divided by q (0 where q is 0) and scaled by
/// `size`; the components a target of `dims` dimensions lacks are 0, as in `quad_lambda`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn lambda_point(
    ps: &[f32; 3],
    pt: &[f32; 3],
    pr: &[f32; 3],
    pq: &[f32; 3],
    x: &[f32; LANES],
    y: f32,
    size: [f32; 3],
    dims: usize,
) -> [[f32; LANES]; 3] {
    // (a + dx·x) + dy·y, as `pl` in `quad_lambda` evaluates a plane.
    let ev = |p: &[f32; 3]| {
        let yt = p[2] * y;
        let mut v = [0.0f32; LANES];
        for l in 0..LANES {
            v[l] = (p[0] + p[1] * x[l]) + yt;
        }
        v
    };
    let q = ev(pq);
    let rq = recip_lanes(q);
    let mut inv = [0.0f32; LANES];
    for l in 0..LANES {
        inv[l] = if q[l] != 0.0 { rq[l] } else { 0.0 };
    }
    let scaled = |p: &[f32; 3], size: f32| {
        let c = ev(p);
        let mut v = [0.0f32; LANES];
        for l in 0..LANES {
            v[l] = c[l] * inv[l] * size;
        }
        v
    };
    let u = scaled(ps, size[0]);
    let v = if dims >= 2 {
        scaled(pt, size[1])
    } else {
        [0.0; LANES]
    };
    let w = if dims == 3 {
        scaled(pr, size[2])
    } else {
        [0.0; LANES]
    };
    [u, v, w]
}

/// The x of eight quads' lower-left pixels from `xa` on (`Sampler::quad_lambda_row`), lane j
/// `xa + 2j` (the add wrapping) as f32, on one register: `vpaddd` and `vcvtdq2ps` (rounding
/// as `as f32`'s `cvtsi2ss`) in place of eight scalar conversions put together lane by lane
/// (≈20 instructions).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn quad_xs8(xa: i32) -> [f32; LANES] {
    use std::arch::x86_64::*;
    let steps = _mm256_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14);
    let v = _mm256_cvtepi32_ps(_mm256_add_epi32(_mm256_set1_epi32(xa), steps));
    let mut out = [0.0f32; LANES];
    // SAFETY: the store writes the eight f32 of `out` (no alignment needed).
    unsafe { _mm256_storeu_ps(out.as_mut_ptr(), v) };
    out
}

/// [`Sampler::quad_lambda_on`] without a cube map on eight AVX registers: `lambda_point`'s
/// three points (planes `pl` = s, t, r, q, each (a, ∂x, ∂y), at (`qx[l]`, `qy[l]`),
/// (`qx[l]` + 1, `qy[l]`) and (`qx[l]`, `qy[l]` + 1)), the two squared lengths, their larger
/// and `0.5·fast_log2`: each lane the same operations in the same order as the SSE2 lane
/// loops (no FMA; ∂y·y a product per lane, the one `quad_lambda_on` takes once for its row),
/// so the same bits but a NaN's payload (every NaN becomes `fast_log2`'s NaN).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn quad_lambda8(
    pl: &[[f32; 3]; 4],
    qx: &[f32; LANES],
    qy: &[f32; LANES],
    size: [f32; 3],
    dims: usize,
) -> [f32; LANES] {
    use std::arch::x86_64::*;
    let [ps, pt, pr, pq] = pl;
    let x0 = lanes8(qx);
    let x1 = _mm256_add_ps(x0, _mm256_set1_ps(1.0));
    let y0 = lanes8(qy);
    let zero = _mm256_setzero_ps();
    // `lambda_point`: (a + dx·x) + dy·y per plane, the division by q (0 where q is 0;
    // `!=` is true for a NaN), then each component times its size.
    let point = |x: __m256, y: __m256| -> [__m256; 3] {
        let ev = |p: &[f32; 3]| {
            let yt = _mm256_mul_ps(_mm256_set1_ps(p[2]), y);
            _mm256_add_ps(
                _mm256_add_ps(_mm256_set1_ps(p[0]), _mm256_mul_ps(_mm256_set1_ps(p[1]), x)),
                yt,
            )
        };
        let q = ev(pq);
        let inv = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_NEQ_UQ>(q, zero),
            _mm256_div_ps(_mm256_set1_ps(1.0), q),
        );
        let scaled = |p: &[f32; 3], size: f32| {
            _mm256_mul_ps(_mm256_mul_ps(ev(p), inv), _mm256_set1_ps(size))
        };
        let u = scaled(ps, size[0]);
        let v = if dims >= 2 { scaled(pt, size[1]) } else { zero };
        let w = if dims == 3 { scaled(pr, size[2]) } else { zero };
        [u, v, w]
    };
    let p0 = point(x0, y0);
    let px = point(x1, y0);
    let py = point(x0, _mm256_add_ps(y0, _mm256_set1_ps(1.0)));
    let len2 = |p: &[__m256; 3]| {
        let (a, b, c) = (
            _mm256_sub_ps(p[0], p0[0]),
            _mm256_sub_ps(p[1], p0[1]),
            _mm256_sub_ps(p[2], p0[2]),
        );
        _mm256_add_ps(
            _mm256_add_ps(_mm256_mul_ps(a, a), _mm256_mul_ps(b, b)),
            _mm256_mul_ps(c, c),
        )
    };
    let (lx, ly) = (len2(&px), len2(&py));
    // `lx.max(ly)`: the larger, the other where one is NaN (`vmaxps` gives its second operand
    // where either is NaN: lx where ly is NaN; then ly where lx is NaN).
    let m = _mm256_max_ps(ly, lx);
    let rho2 = _mm256_blendv_ps(m, ly, _mm256_cmp_ps::<_CMP_UNORD_Q>(lx, lx));
    // `fast_log2_lanes` on eight lanes.
    let bits = _mm256_castps_si256(rho2);
    let e = _mm256_sub_epi32(
        _mm256_and_si256(_mm256_srli_epi32::<23>(bits), _mm256_set1_epi32(0xff)),
        _mm256_set1_epi32(127),
    );
    let mant = _mm256_castsi256_ps(_mm256_or_si256(
        _mm256_and_si256(bits, _mm256_set1_epi32(0x007f_ffff)),
        _mm256_set1_epi32(0x3f80_0000),
    ));
    let val = _mm256_add_ps(
        _mm256_cvtepi32_ps(e),
        _mm256_sub_ps(mant, _mm256_set1_ps(1.0)),
    );
    let inf = _mm256_set1_ps(f32::INFINITY);
    let is_zero = _mm256_cmp_ps::<_CMP_EQ_OQ>(rho2, zero);
    let is_inf = _mm256_cmp_ps::<_CMP_EQ_OQ>(rho2, inf);
    let special = _mm256_blendv_ps(
        _mm256_blendv_ps(_mm256_set1_ps(f32::NAN), inf, is_inf),
        _mm256_set1_ps(f32::NEG_INFINITY),
        is_zero,
    );
    let ok = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_GT_OQ>(rho2, zero),
        _mm256_cmp_ps::<_CMP_LT_OQ>(rho2, inf),
    );
    let lg = _mm256_blendv_ps(special, val, ok);
    let out = _mm256_mul_ps(_mm256_set1_ps(0.5), lg);
    // SAFETY: `__m256` is eight f32 lanes in memory order, the layout of `[f32; 8]`.
    unsafe { std::mem::transmute::<__m256, [f32; LANES]>(out) }
}

/// [`fast_log2`] without the library call on the paths a lane takes: the same value for
/// every input (a NaN for a NaN or a negative input, whatever its payload; -∞ for ±0, +∞ for
/// +∞), written as selects so that a loop of it stays in vector registers.
#[inline(always)]
fn fast_log2_lane(x: f32) -> f32 {
    let bits = x.to_bits();
    let e = ((bits >> 23) & 0xff) as i32 - 127;
    let m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    let v = e as f32 + (m - 1.0);
    let special = if x == 0.0 {
        f32::NEG_INFINITY
    } else if x == f32::INFINITY {
        x
    } else {
        f32::NAN
    };
    // `&`, not `&&`: no branch.
    if (x > 0.0) & (x < f32::INFINITY) {
        v
    } else {
        special
    }
}

/// [`fast_log2_lane`] on eight lanes, as SSE2 code on x86-64 (LLVM leaves the scalar lane
/// loop scalar, with branches): the same operations per lane (the exponent as an integer
/// converted exactly, plus the mantissa minus one) and the same special values, selected by
/// compare masks.
#[inline(always)]
fn fast_log2_lanes(x: &[f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        let half = |h: [f32; 4]| -> [f32; 4] {
            // SAFETY: SSE2 is part of the x86-64 baseline (see `ifloor_lanes`); `__m128` is
            // four f32 lanes in memory order, the layout of `[f32; 4]`, every bit pattern valid.
            unsafe {
                let v = std::mem::transmute::<[f32; 4], __m128>(h);
                let bits = _mm_castps_si128(v);
                let e = _mm_sub_epi32(
                    _mm_and_si128(_mm_srli_epi32(bits, 23), _mm_set1_epi32(0xff)),
                    _mm_set1_epi32(127),
                );
                let m = _mm_castsi128_ps(_mm_or_si128(
                    _mm_and_si128(bits, _mm_set1_epi32(0x007f_ffff)),
                    _mm_set1_epi32(0x3f80_0000),
                ));
                let val = _mm_add_ps(_mm_cvtepi32_ps(e), _mm_sub_ps(m, _mm_set1_ps(1.0)));
                // -∞ for ±0, +∞ for +∞, NaN otherwise; `val` where 0 < x < +∞.
                let inf = _mm_set1_ps(f32::INFINITY);
                let zero = _mm_cmpeq_ps(v, _mm_setzero_ps());
                let is_inf = _mm_cmpeq_ps(v, inf);
                let not_zero = _mm_or_ps(
                    _mm_and_ps(is_inf, inf),
                    _mm_andnot_ps(is_inf, _mm_set1_ps(f32::NAN)),
                );
                let special = _mm_or_ps(
                    _mm_and_ps(zero, _mm_set1_ps(f32::NEG_INFINITY)),
                    _mm_andnot_ps(zero, not_zero),
                );
                let ok = _mm_and_ps(_mm_cmpgt_ps(v, _mm_setzero_ps()), _mm_cmplt_ps(v, inf));
                std::mem::transmute::<__m128, [f32; 4]>(_mm_or_ps(
                    _mm_and_ps(ok, val),
                    _mm_andnot_ps(ok, special),
                ))
            }
        };
        let lo = half([x[0], x[1], x[2], x[3]]);
        let hi = half([x[4], x[5], x[6], x[7]]);
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        x.map(fast_log2_lane)
    }
}

/// The lanes of `x` as a mask, bit l for lane l, from four-lane compare masks (`movmskps`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lane_bits(
    x: [f32; LANES],
    f: impl Fn(std::arch::x86_64::__m128) -> std::arch::x86_64::__m128,
) -> u8 {
    use std::arch::x86_64::*;
    let half = |h: [f32; 4]| -> u8 {
        // SAFETY: SSE2 is part of the x86-64 baseline (see `ifloor_lanes`); `__m128` has the
        // layout of `[f32; 4]` and every bit pattern is valid for both.
        unsafe { _mm_movemask_ps(f(std::mem::transmute::<[f32; 4], __m128>(h))) as u8 }
    };
    half([x[0], x[1], x[2], x[3]]) | half([x[4], x[5], x[6], x[7]]) << 4
}

/// Bit l set where `x[l] != 0.0` (true for a NaN, as in Rust).
#[inline(always)]
fn mask_ne_zero(x: &[f32; LANES]) -> u8 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86-64 baseline; `cmpneqps` is true for unordered lanes.
        lane_bits(*x, |v| unsafe { _mm_cmpneq_ps(v, _mm_setzero_ps()) })
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        (0..LANES).fold(0, |b, l| b | u8::from(x[l] != 0.0) << l)
    }
}

/// Bit l set where `x[l] <= c` (false for a NaN, as in Rust).
#[inline(always)]
fn mask_le(x: &[f32; LANES], c: f32) -> u8 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86-64 baseline; `cmpleps` is false for unordered lanes.
        lane_bits(*x, |v| unsafe { _mm_cmple_ps(v, _mm_set1_ps(c)) })
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        (0..LANES).fold(0, |b, l| b | u8::from(x[l] <= c) << l)
    }
}

/// Bit l set where `x[l] == v`.
#[inline(always)]
fn mask_eq(x: &[i32; LANES], v: i32) -> u8 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        let half = |h: [i32; 4]| -> u8 {
            // SAFETY: SSE2 is part of the x86-64 baseline; `__m128i` has the layout of
            // `[i32; 4]` and every bit pattern is valid for both.
            unsafe {
                let a = std::mem::transmute::<[i32; 4], __m128i>(h);
                _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a, _mm_set1_epi32(v)))) as u8
            }
        };
        half([x[0], x[1], x[2], x[3]]) | half([x[4], x[5], x[6], x[7]]) << 4
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        (0..LANES).fold(0, |b, l| b | u8::from(x[l] == v) << l)
    }
}

/// The sizes of one axis for the lanes of a pass: one per lane (`&[i32; LANES]`, lanes on
/// different levels) or one for all (`i32`, every lane on one level: the compiler then keeps
/// the size in a register and the wrap loops work on a broadcast value).
trait Axis: Copy {
    /// Lane l's number of texels along the axis.
    fn at(self, l: usize) -> i32;
    /// Are all of the lanes' sizes (each taken as at least 1) powers of two?
    fn pow2(self) -> bool;
}

impl Axis for &[i32; LANES] {
    #[inline(always)]
    fn at(self, l: usize) -> i32 {
        self[l]
    }
    #[inline(always)]
    fn pow2(self) -> bool {
        all_pow2(self)
    }
}

impl Axis for i32 {
    #[inline(always)]
    fn at(self, _: usize) -> i32 {
        self
    }
    #[inline(always)]
    fn pow2(self) -> bool {
        let n = self.max(1);
        n & (n - 1) == 0
    }
}

/// The texels a pass reads: one level per lane, or one level for all lanes (as [`Axis`]).
trait Texels: Copy {
    /// Texel number `k` of lane l's level (`Level::texel`'s fallback (0, 0, 0, 0) beyond it).
    fn get(self, l: usize, k: usize) -> [f32; 4];
}

impl Texels for &[&[[f32; 4]]; LANES] {
    #[inline(always)]
    fn get(self, l: usize, k: usize) -> [f32; 4] {
        self[l].get(k).copied().unwrap_or([0.0; 4])
    }
}

impl Texels for &[[f32; 4]] {
    #[inline(always)]
    fn get(self, _: usize, k: usize) -> [f32; 4] {
        <[[f32; 4]]>::get(self, k).copied().unwrap_or([0.0; 4])
    }
}

/// REPEAT's index `i.rem_euclid(n)` for `n` >= 1, as a mask when the caller knows `n` is a
/// power of two (`p2`; the same value for every i32 in two's complement).
#[inline(always)]
fn repeat_p(i: i32, n: i32, p2: bool) -> i32 {
    if p2 {
        i & (n - 1)
    } else {
        i.rem_euclid(n)
    }
}

/// The value [`wrap_nearest`] floors for coordinate `s` on an axis of `n` texels (n taken as
/// at least 1): u = s·n, of MIRRORED_REPEAT's mirrored s.
#[inline(always)]
fn nearest_u(mode: u32, s: f32, n: i32) -> f32 {
    let n = n.max(1);
    match mode {
        gl::MIRRORED_REPEAT => mirror(s) * n as f32,
        _ => s * n as f32,
    }
}

/// [`wrap_nearest`]'s index from i = floor(u) (`ifloor` of [`nearest_u`]) and whether it is
/// inside the image (false: the border colour), `p2` telling whether `n.max(1)` is a power of
/// two. The clamps are written as max/min (the same values, n - 1 >= 0) so that no panic path
/// stays in a lane loop.
#[inline(always)]
fn nearest_finish(mode: u32, i: i32, n: i32, p2: bool) -> (i32, bool) {
    let n = n.max(1);
    match mode {
        gl::REPEAT => (repeat_p(i, n, p2), true),
        gl::CLAMP_TO_BORDER => (i, i >= 0 && i < n),
        // CLAMP and CLAMP_TO_EDGE agree for NEAREST: s in [0, 1], i = n taken as n - 1;
        // MIRRORED_REPEAT's mirrored s is in [0, 1] too.
        _ => (i.max(0).min(n - 1), true),
    }
}

/// [`wrap_nearest`] as an index and whether it is inside the image.
#[inline(always)]
fn wrap_nearest_i(mode: u32, s: f32, n: i32, p2: bool) -> (i32, bool) {
    nearest_finish(mode, ifloor(nearest_u(mode, s, n)), n, p2)
}

/// The value u = s·n - 1/2 [`wrap_linear`] floors (after MIRRORED_REPEAT's mirror or CLAMP's
/// clamp of s; a NaN u taken as 0), on an axis of `n` texels (n taken as at least 1).
#[inline(always)]
fn linear_u(mode: u32, s: f32, n: i32) -> f32 {
    let nf = n.max(1) as f32;
    let s = match mode {
        gl::MIRRORED_REPEAT => mirror(s),
        gl::CLAMP => s.clamp(0.0, 1.0),
        _ => s,
    };
    let u = s * nf - 0.5;
    if u.is_nan() {
        0.0
    } else {
        u
    }
}

/// [`wrap_linear`]'s indices, the weight of the second, and whether each index is inside the
/// image (false: the border colour), from u ([`linear_u`]) and i0 = floor(u) (`ifloor`);
/// `p2` as for [`nearest_finish`].
#[inline(always)]
fn linear_finish(mode: u32, u: f32, i0: i32, n: i32, p2: bool) -> (i32, i32, f32, bool, bool) {
    let n = n.max(1);
    // |u| beyond 2^24 has no fraction; a saturated i0 must not produce a weight outside [0, 1].
    let a = (u - i0 as f32).clamp(0.0, 1.0);
    let i1 = i0.saturating_add(1);
    match mode {
        gl::REPEAT => (repeat_p(i0, n, p2), repeat_p(i1, n, p2), a, true, true),
        gl::CLAMP_TO_BORDER | gl::CLAMP => (i0, i1, a, i0 >= 0 && i0 < n, i1 >= 0 && i1 < n),
        // CLAMP_TO_EDGE and MIRRORED_REPEAT: indices clamped to the edge texels.
        _ => (i0.max(0).min(n - 1), i1.max(0).min(n - 1), a, true, true),
    }
}

/// [`wrap_linear`]'s indices, weight and inside flags.
#[inline(always)]
fn wrap_linear_i(mode: u32, s: f32, n: i32, p2: bool) -> (i32, i32, f32, bool, bool) {
    let u = linear_u(mode, s, n);
    linear_finish(mode, u, ifloor(u), n, p2)
}

/// [`ifloor`] on eight lanes: SSE2's `cvttps2dq` truncation with `as i32`'s saturation
/// (2^31 and above to i32::MAX, NaN to 0; below -2^31 it already gives i32::MIN), then one
/// step down where the truncation exceeds x, except from i32::MIN (`saturating_sub`): each
/// lane is `ifloor`'s value. The compiler leaves the saturating cast scalar.
#[inline(always)]
fn ifloor_lanes(x: &[f32; LANES]) -> [i32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        let half = |h: [f32; 4]| -> [i32; 4] {
            // SAFETY: SSE2 is part of the x86-64 baseline, so these intrinsics exist on every
            // x86-64 CPU; `__m128`/`__m128i` are four f32/i32 lanes in memory order, the
            // layouts of `[f32; 4]`/`[i32; 4]`, and every bit pattern is valid for all four.
            unsafe {
                let v = std::mem::transmute::<[f32; 4], __m128>(h);
                std::mem::transmute::<__m128i, [i32; 4]>(ifloor4(v))
            }
        };
        let lo = half([x[0], x[1], x[2], x[3]]);
        let hi = half([x[4], x[5], x[6], x[7]]);
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        x.map(ifloor)
    }
}

/// `texel`'s 1/q for eight lanes: `recip_lanes` (`divps`), 0 where q is 0.
#[inline(always)]
fn inv_q_lanes(q: &[f32; LANES]) -> [f32; LANES] {
    let rq = recip_lanes(*q);
    let mut inv = [0.0f32; LANES];
    for l in 0..LANES {
        inv[l] = if q[l] != 0.0 { rq[l] } else { 0.0 };
    }
    inv
}

/// `a[l] * b[l]` on every lane (`mulps` on x86-64: LLVM's vectoriser left the plain loop
/// scalar in `texels_lanes` once the dense kernels joined it).
#[inline(always)]
fn mul_lanes(a: &[f32; LANES], b: &[f32; LANES]) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        let h = |x: [f32; 4], y: [f32; 4]| {
            // SAFETY: SSE2 is part of the x86-64 baseline; `__m128` is four f32 lanes in
            // memory order, the layout of `[f32; 4]`, every bit pattern valid for both.
            unsafe {
                std::mem::transmute::<__m128, [f32; 4]>(_mm_mul_ps(
                    std::mem::transmute::<[f32; 4], __m128>(x),
                    std::mem::transmute::<[f32; 4], __m128>(y),
                ))
            }
        };
        let lo = h([a[0], a[1], a[2], a[3]], [b[0], b[1], b[2], b[3]]);
        let hi = h([a[4], a[5], a[6], a[7]], [b[4], b[5], b[6], b[7]]);
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        std::array::from_fn(|l| a[l] * b[l])
    }
}

/// [`ifloor`] on four lanes (SSE2): `cvttps2dq` truncation with `as i32`'s saturation (2^31
/// and above to i32::MAX, NaN to 0; below -2^31 it already gives i32::MIN), then one step
/// down where the truncation exceeds x, except from i32::MIN. [`ifloor_lanes`] and the dense
/// kernels ([`dense_kernel`]) share it.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn ifloor4(v: std::arch::x86_64::__m128) -> std::arch::x86_64::__m128i {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86-64 baseline, so these intrinsics exist on every x86-64
    // CPU; they read and write registers only.
    unsafe {
        let t = _mm_cvttps_epi32(v);
        let big = _mm_castps_si128(_mm_cmpge_ps(v, _mm_set1_ps(2_147_483_648.0)));
        let t = _mm_or_si128(
            _mm_andnot_si128(big, t),
            _mm_and_si128(big, _mm_set1_epi32(i32::MAX)),
        );
        let nan = _mm_castps_si128(_mm_cmpunord_ps(v, v));
        let t = _mm_andnot_si128(nan, t);
        // -1 where (t as f32) > x and t is not i32::MIN.
        let gt = _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(t), v));
        let at_min = _mm_cmpeq_epi32(t, _mm_set1_epi32(i32::MIN));
        _mm_add_epi32(t, _mm_andnot_si128(at_min, gt))
    }
}

/// Which dense kernel ([`dense_kernel`]) covers a one-level pass with filter `linear` and
/// wrap modes `wrap` (s, t): bit 2 LINEAR, bit 1 REPEAT on s (else an edge clamp), bit 0
/// REPEAT on t. NEAREST takes REPEAT, CLAMP or CLAMP_TO_EDGE, LINEAR REPEAT or CLAMP_TO_EDGE
/// (no border texel either way); None otherwise, and always off x86-64.
#[inline(always)]
fn kernel_kind(linear: bool, wrap: [u32; 3]) -> Option<u8> {
    if cfg!(not(target_arch = "x86_64")) {
        return None;
    }
    let rep = |mode: u32| match mode {
        gl::REPEAT => Some(1u8),
        gl::CLAMP_TO_EDGE => Some(0),
        gl::CLAMP if !linear => Some(0),
        _ => None,
    };
    Some(u8::from(linear) << 2 | rep(wrap[0])? << 1 | rep(wrap[1])?)
}

/// The one-level pass (`pass_on`) of a level without depth comparison whose texels `dt` are
/// [`dense_level`] (`w` x `h`, both powers of two) as one SSE2 kernel per half group, for the
/// filter and wrap modes [`kernel_kind`] encodes in `kind` (no border texel). Each lane
/// computes `pass_on`'s expressions in the same order (the wraps' u, floor, weight and
/// indices, eq. 3.24's weights and sum), so every texel has the same bits; the coordinates,
/// weights and indices stay in registers from the wrap to the gather, which `pass_on`'s lane
/// loops spill between steps. Out of line: inlined, it made `pass_level`'s other routes
/// spill more.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn dense_kernel(
    kind: u8,
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    #[cfg(target_arch = "x86_64")]
    dense_kernel_on(avx2(), kind, dt, w, h, s, t, m, out);
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (kind, dt, w, h, s, t, m, out);
    }
}

/// May the eight-lane dense kernels run? The fragment stage's one answer
/// ([`super::lanes::has_avx2`]: AVX2 on this CPU, and in tests not switched off on this
/// thread), so that every AVX2 route of a span is on or off together.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn avx2() -> bool {
    super::lanes::has_avx2()
}

/// [`dense_kernel`] on the AVX2 kernels (`wide`: only where [`avx2`] holds) or the SSE2 ones.
/// The AVX2 kernels ([`dense_nearest8`], [`dense_linear8`]) compute the SSE2 kernels'
/// expressions on eight lanes at once, the LINEAR one gathering each channel of each corner
/// for the eight lanes (`vgatherdps`, the indices j·w + i times four f32 a texel, so a level
/// of at most 2^28 texels; larger ones take the SSE2 kernel).
#[cfg(target_arch = "x86_64")]
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn dense_kernel_on(
    wide: bool,
    kind: u8,
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    if wide && dt.len() <= 1 << 28 {
        // SAFETY: the caller passes `wide` only when the CPU has AVX2 (`avx2`).
        unsafe {
            match kind {
                0 => dense_nearest8::<false, false>(dt, w, h, s, t, m, out),
                1 => dense_nearest8::<false, true>(dt, w, h, s, t, m, out),
                2 => dense_nearest8::<true, false>(dt, w, h, s, t, m, out),
                3 => dense_nearest8::<true, true>(dt, w, h, s, t, m, out),
                4 => dense_linear8::<false, false>(dt, w, h, s, t, m, out),
                5 => dense_linear8::<false, true>(dt, w, h, s, t, m, out),
                6 => dense_linear8::<true, false>(dt, w, h, s, t, m, out),
                _ => dense_linear8::<true, true>(dt, w, h, s, t, m, out),
            }
        }
        return;
    }
    match kind {
        0 => dense_nearest::<false, false>(dt, w, h, s, t, m, out),
        1 => dense_nearest::<false, true>(dt, w, h, s, t, m, out),
        2 => dense_nearest::<true, false>(dt, w, h, s, t, m, out),
        3 => dense_nearest::<true, true>(dt, w, h, s, t, m, out),
        4 => dense_linear::<false, false>(dt, w, h, s, t, m, out),
        5 => dense_linear::<false, true>(dt, w, h, s, t, m, out),
        6 => dense_linear::<true, false>(dt, w, h, s, t, m, out),
        _ => dense_linear::<true, true>(dt, w, h, s, t, m, out),
    }
}

/// Lanes `LO..LO + 4` of `x` as one SSE2 register.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn half4<const LO: usize>(x: &[f32; LANES]) -> std::arch::x86_64::__m128 {
    let h = [x[LO], x[LO + 1], x[LO + 2], x[LO + 3]];
    // SAFETY: `__m128` is four f32 lanes in memory order, the layout of `[f32; 4]`.
    unsafe { std::mem::transmute::<[f32; 4], std::arch::x86_64::__m128>(h) }
}

/// An axis' finish for the dense kernels: REPEAT's mask (`REP`; n a power of two) or the
/// edge clamp `i.max(0).min(n - 1)` ([`nearest_finish`], [`linear_finish`]), on four lanes.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn wrap4<const REP: bool>(
    i: std::arch::x86_64::__m128i,
    nm1: std::arch::x86_64::__m128i,
) -> std::arch::x86_64::__m128i {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only.
    unsafe {
        if REP {
            _mm_and_si128(i, nm1)
        } else {
            let i = _mm_and_si128(i, _mm_cmpgt_epi32(i, _mm_setzero_si128()));
            let gt = _mm_cmpgt_epi32(i, nm1);
            _mm_or_si128(_mm_and_si128(gt, nm1), _mm_andnot_si128(gt, i))
        }
    }
}

/// `log2(n)` of a power of two `n` >= 1 as SSE2's shift count: j·n as j << log2(n) (the same
/// bits as `wrapping_mul`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn shift_of(n: i32) -> std::arch::x86_64::__m128i {
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only.
    unsafe { std::arch::x86_64::_mm_cvtsi32_si128(n.trailing_zeros() as i32) }
}

/// NEAREST on a dense level ([`dense_kernel`]), REPEAT (`RX`, `RY` true) or an edge clamp
/// per axis: i = floor(s·w), j = floor(t·h), wrapped, texel j·w + i (`wrap_nearest_lanes`
/// and `pass_on`'s dense gather).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn dense_nearest<const RX: bool, const RY: bool>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let (w, h) = (w.max(1), h.max(1));
    if m & 0xf != 0 {
        nearest_half::<RX, RY, 0>(dt, km, w, h, s, t, m, out);
    }
    if m & 0xf0 != 0 {
        nearest_half::<RX, RY, 4>(dt, km, w, h, s, t, m, out);
    }
}

/// [`dense_nearest`] for lanes `LO..LO + 4`.
#[cfg(target_arch = "x86_64")]
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn nearest_half<const RX: bool, const RY: bool, const LO: usize>(
    dt: &[[f32; 4]],
    km: usize,
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only, and `__m128i` is four
    // i32 lanes in memory order, the layout of `[i32; 4]`.
    let k = unsafe {
        let i = ifloor4(_mm_mul_ps(half4::<LO>(s), _mm_set1_ps(w as f32)));
        let j = ifloor4(_mm_mul_ps(half4::<LO>(t), _mm_set1_ps(h as f32)));
        let i = wrap4::<RX>(i, _mm_set1_epi32(w - 1));
        let j = wrap4::<RY>(j, _mm_set1_epi32(h - 1));
        std::mem::transmute::<__m128i, [u32; 4]>(_mm_add_epi32(_mm_sll_epi32(j, shift_of(w)), i))
    };
    macro_rules! lane {
        ($l:literal) => {
            if m & (1 << (LO + $l)) != 0 {
                out[LO + $l] = dt[k[$l] as usize & km];
            }
        };
    }
    lane!(0);
    lane!(1);
    lane!(2);
    lane!(3);
}

/// LINEAR on a dense level ([`dense_kernel`]), REPEAT (`RX`, `RY` true) or CLAMP_TO_EDGE per
/// axis: `linear_u`, the floor, `linear_finish` (weight from the unwrapped floor, the second
/// index by `saturating_add`), eq. 3.24's weights as `pass_on` groups them and the sum
/// (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11 in that order, per channel.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn dense_linear<const RX: bool, const RY: bool>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let (w, h) = (w.max(1), h.max(1));
    if m & 0xf != 0 {
        linear_half::<RX, RY, 0>(dt, km, w, h, s, t, m, out);
    }
    if m & 0xf0 != 0 {
        linear_half::<RX, RY, 4>(dt, km, w, h, s, t, m, out);
    }
}

/// One axis of [`dense_linear`] on four lanes: the wrapped indices i0, i1 and the weight α of
/// i1 ([`linear_u`], [`ifloor`], [`linear_finish`]) for coordinates `c` on `n` texels.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn linear_axis4<const REP: bool>(
    c: std::arch::x86_64::__m128,
    n: i32,
) -> (
    std::arch::x86_64::__m128i,
    std::arch::x86_64::__m128i,
    std::arch::x86_64::__m128,
) {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only.
    unsafe {
        // u = s·n - 1/2, a NaN u taken as 0.
        let u = _mm_sub_ps(_mm_mul_ps(c, _mm_set1_ps(n as f32)), _mm_set1_ps(0.5));
        let u = _mm_and_ps(u, _mm_cmpord_ps(u, u));
        let i0 = ifloor4(u);
        // (u - i0).clamp(0, 1) in `f32::clamp`'s order (a -0 stays -0).
        let a = _mm_sub_ps(u, _mm_cvtepi32_ps(i0));
        let a = _mm_min_ps(_mm_set1_ps(1.0), _mm_max_ps(_mm_setzero_ps(), a));
        // i0.saturating_add(1): i0 + 1, less 1 where i0 was i32::MAX.
        let at_max = _mm_cmpeq_epi32(i0, _mm_set1_epi32(i32::MAX));
        let i1 = _mm_add_epi32(_mm_add_epi32(i0, _mm_set1_epi32(1)), at_max);
        let nm1 = _mm_set1_epi32(n - 1);
        (wrap4::<REP>(i0, nm1), wrap4::<REP>(i1, nm1), a)
    }
}

/// [`dense_linear`] for lanes `LO..LO + 4`.
#[cfg(target_arch = "x86_64")]
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn linear_half<const RX: bool, const RY: bool, const LO: usize>(
    dt: &[[f32; 4]],
    km: usize,
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    let (x0, x1, a) = linear_axis4::<RX>(half4::<LO>(s), w);
    let (y0, y1, b) = linear_axis4::<RY>(half4::<LO>(t), h);
    // SAFETY: SSE2 is part of the x86-64 baseline; registers only, and `__m128i` is four
    // i32 lanes in memory order, the layout of `[u32; 4]`.
    let (k, wt) = unsafe {
        let one = _mm_set1_ps(1.0);
        let (na, nb) = (_mm_sub_ps(one, a), _mm_sub_ps(one, b));
        let wt = [
            _mm_mul_ps(na, nb),
            _mm_mul_ps(a, nb),
            _mm_mul_ps(na, b),
            _mm_mul_ps(a, b),
        ];
        let sh = shift_of(w);
        let (r0, r1) = (_mm_sll_epi32(y0, sh), _mm_sll_epi32(y1, sh));
        let k = [
            _mm_add_epi32(r0, x0),
            _mm_add_epi32(r0, x1),
            _mm_add_epi32(r1, x0),
            _mm_add_epi32(r1, x1),
        ]
        .map(|v| std::mem::transmute::<__m128i, [u32; 4]>(v));
        (k, wt)
    };
    macro_rules! lane {
        ($l:literal) => {
            if m & (1 << (LO + $l)) != 0 {
                // SAFETY: SSE2 is part of the x86-64 baseline; `__m128` is four f32 lanes in
                // memory order, the layout of `[f32; 4]`.
                out[LO + $l] = unsafe {
                    let at = |c: usize| {
                        std::mem::transmute::<[f32; 4], __m128>(dt[k[c][$l] as usize & km])
                    };
                    // Lane $l of a weight in every channel (`pshufd`: one instruction).
                    let b = |x: __m128| {
                        _mm_castsi128_ps(_mm_shuffle_epi32::<{ $l * 0x55 }>(_mm_castps_si128(x)))
                    };
                    let v = _mm_add_ps(_mm_mul_ps(b(wt[0]), at(0)), _mm_mul_ps(b(wt[1]), at(1)));
                    let v = _mm_add_ps(v, _mm_mul_ps(b(wt[2]), at(2)));
                    let v = _mm_add_ps(v, _mm_mul_ps(b(wt[3]), at(3)));
                    std::mem::transmute::<__m128, [f32; 4]>(v)
                };
            }
        };
    }
    lane!(0);
    lane!(1);
    lane!(2);
    lane!(3);
}

/// [`ifloor4`] on eight lanes (AVX2): `vroundps`' floor, then `cvttps2dq` (exact on the
/// floor; 2^31 and beyond and below -2^31 give i32::MIN), flipped to i32::MAX where x ≥ 2^31,
/// 0 for NaN — `ifloor`'s value in 6 instructions instead of `ifloor4`'s 12.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn ifloor8(v: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let nan = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_UNORD_Q>(v, v));
    _mm256_andnot_si256(nan, ifloor8_num(v))
}

/// [`ifloor8`] without its NaN test, for lanes that hold no NaN (a NaN lane gives i32::MIN):
/// the LINEAR axes, which take a NaN u as 0 before the floor.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn ifloor8_num(v: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let t = _mm256_cvttps_epi32(_mm256_floor_ps(v));
    // i32::MIN ^ -1 = i32::MAX where x ≥ 2^31.
    let big = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_GE_OQ>(
        v,
        _mm256_set1_ps(2_147_483_648.0),
    ));
    _mm256_xor_si256(t, big)
}

/// [`wrap4`] on eight lanes (AVX2).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn wrap8<const REP: bool>(
    i: std::arch::x86_64::__m256i,
    nm1: std::arch::x86_64::__m256i,
) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    if REP {
        _mm256_and_si256(i, nm1)
    } else {
        let i = _mm256_and_si256(i, _mm256_cmpgt_epi32(i, _mm256_setzero_si256()));
        let gt = _mm256_cmpgt_epi32(i, nm1);
        _mm256_or_si256(_mm256_and_si256(gt, nm1), _mm256_andnot_si256(gt, i))
    }
}

/// [`linear_axis4`] on eight lanes (AVX2).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn linear_axis8<const REP: bool>(c: std::arch::x86_64::__m256, n: i32) -> Axis8 {
    linear_axis8_of::<REP>(c, n as f32, n - 1)
}

/// A LINEAR axis on eight lanes ([`linear_axis8`]): the lower and upper texel indices,
/// wrapped, and the weight α of the upper one.
#[cfg(target_arch = "x86_64")]
type Axis8 = (
    std::arch::x86_64::__m256i,
    std::arch::x86_64::__m256i,
    std::arch::x86_64::__m256,
);

/// [`linear_axis8`] of an axis of `n` texels given as `n as f32` `nf` and `n - 1` `nm1` (a
/// kernel that keeps them for its level: `span::DenseLevel`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn linear_axis8_of<const REP: bool>(c: std::arch::x86_64::__m256, nf: f32, nm1: i32) -> Axis8 {
    use std::arch::x86_64::*;
    // u = s·n - 1/2, a NaN u taken as 0.
    let u = _mm256_sub_ps(_mm256_mul_ps(c, _mm256_set1_ps(nf)), _mm256_set1_ps(0.5));
    let u = _mm256_and_ps(u, _mm256_cmp_ps::<_CMP_ORD_Q>(u, u));
    let i0 = ifloor8_num(u);
    // (u - i0).clamp(0, 1) in `f32::clamp`'s order (a -0 stays -0).
    let a = _mm256_sub_ps(u, _mm256_cvtepi32_ps(i0));
    let a = _mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_setzero_ps(), a));
    // i0.saturating_add(1): i0 + 1, less 1 where i0 was i32::MAX.
    let at_max = _mm256_cmpeq_epi32(i0, _mm256_set1_epi32(i32::MAX));
    let i1 = _mm256_add_epi32(_mm256_add_epi32(i0, _mm256_set1_epi32(1)), at_max);
    let nm1 = _mm256_set1_epi32(nm1);
    (wrap8::<REP>(i0, nm1), wrap8::<REP>(i1, nm1), a)
}

/// The f32 offsets of the NEAREST texels of eight lanes on a dense `w` x `h` level of
/// `km + 1` texels (AVX2): [`nearest_u`]'s floors, [`wrap8`]'s wraps, then (j·w + i & km)·4
/// ([`dense_linear8`]), so that no lane's offset leaves the level.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn nearest_offsets8<const RX: bool, const RY: bool>(
    w: i32,
    h: i32,
    km: usize,
    s: &[f32; LANES],
    t: &[f32; LANES],
) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let (w, h) = (w.max(1), h.max(1));
    let i = ifloor8(_mm256_mul_ps(lanes8(s), _mm256_set1_ps(w as f32)));
    let j = ifloor8(_mm256_mul_ps(lanes8(t), _mm256_set1_ps(h as f32)));
    let i = wrap8::<RX>(i, _mm256_set1_epi32(w - 1));
    let j = wrap8::<RY>(j, _mm256_set1_epi32(h - 1));
    let sh = _mm_cvtsi32_si128(w.trailing_zeros() as i32);
    let k = _mm256_add_epi32(_mm256_sll_epi32(j, sh), i);
    _mm256_slli_epi32::<2>(_mm256_and_si256(k, _mm256_set1_epi32(km as i32)))
}

/// Eight lanes of `x` as one AVX register.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn lanes8(x: &[f32; LANES]) -> std::arch::x86_64::__m256 {
    // SAFETY: `__m256` is eight f32 lanes in memory order, the layout of `[f32; 8]`.
    unsafe { std::mem::transmute::<[f32; LANES], std::arch::x86_64::__m256>(*x) }
}

/// [`dense_nearest`] on eight lanes at once (AVX2): the same index per lane, each channel
/// gathered for the eight lanes, the four channel registers transposed back to a texel per
/// lane.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn dense_nearest8<const RX: bool, const RY: bool>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let k = nearest_offsets8::<RX, RY>(w, h, km, s, t);
    let base = dt.as_ptr().cast::<f32>();
    // SAFETY: AVX2 is present (the caller's promise); each offset is at most
    // 4·(dt.len() - 1) and c < 4, so every f32 read lies inside `dt`.
    let ch: [__m256; 4] =
        std::array::from_fn(|c| unsafe { _mm256_i32gather_ps::<4>(base.add(c), k) });
    store8(&ch, m, out);
}

/// [`dense_linear`] on eight lanes at once (AVX2): the wraps and eq. 3.24's weights as
/// [`linear_half`] computes them, then per channel the four corners' values gathered for the
/// eight lanes and summed (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11 in that order, the
/// four channel registers transposed back to a texel per lane.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn dense_linear8<const RX: bool, const RY: bool>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let (w, h) = (w.max(1), h.max(1));
    let (x0, x1, a) = linear_axis8::<RX>(lanes8(s), w);
    let (y0, y1, b) = linear_axis8::<RY>(lanes8(t), h);
    let one = _mm256_set1_ps(1.0);
    let (na, nb) = (_mm256_sub_ps(one, a), _mm256_sub_ps(one, b));
    let wt = [
        _mm256_mul_ps(na, nb),
        _mm256_mul_ps(a, nb),
        _mm256_mul_ps(na, b),
        _mm256_mul_ps(a, b),
    ];
    let sh = _mm_cvtsi32_si128(w.trailing_zeros() as i32);
    let (r0, r1) = (_mm256_sll_epi32(y0, sh), _mm256_sll_epi32(y1, sh));
    // The f32 offset of each corner's texel: (k & km)·4, k & km being k (in-image indices
    // are below the power-of-two count) and at most 2^28 - 1 (the caller's bound).
    let kmv = _mm256_set1_epi32(km as i32);
    let f = |k: __m256i| _mm256_slli_epi32::<2>(_mm256_and_si256(k, kmv));
    let k = [
        f(_mm256_add_epi32(r0, x0)),
        f(_mm256_add_epi32(r0, x1)),
        f(_mm256_add_epi32(r1, x0)),
        f(_mm256_add_epi32(r1, x1)),
    ];
    let base = dt.as_ptr().cast::<f32>();
    let mut ch = [_mm256_setzero_ps(); 4];
    for (c, v) in ch.iter_mut().enumerate() {
        // SAFETY: AVX2 is present (the caller's promise); each offset is at most
        // 4·(dt.len() - 1) and c < 4, so every f32 read lies inside `dt`.
        let at = |q: usize| unsafe { _mm256_i32gather_ps::<4>(base.add(c), k[q]) };
        let x = _mm256_add_ps(_mm256_mul_ps(wt[0], at(0)), _mm256_mul_ps(wt[1], at(1)));
        let x = _mm256_add_ps(x, _mm256_mul_ps(wt[2], at(2)));
        *v = _mm256_add_ps(x, _mm256_mul_ps(wt[3], at(3)));
    }
    store8(&ch, m, out);
}

/// Eight texels whose channels are `ch` (channel-major, a lane each) into `out`, lane-major:
/// the lanes of `m` written, the others left as they were.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn store8(ch: &[std::arch::x86_64::__m256; 4], m: u8, out: &mut TexelLanes) {
    use std::arch::x86_64::*;
    // Transposed: p[q] holds lane q's texel in its low half, lane q + 4's in its high half.
    let (t0, t1) = (
        _mm256_unpacklo_ps(ch[0], ch[1]),
        _mm256_unpackhi_ps(ch[0], ch[1]),
    );
    let (t2, t3) = (
        _mm256_unpacklo_ps(ch[2], ch[3]),
        _mm256_unpackhi_ps(ch[2], ch[3]),
    );
    let p = [
        _mm256_shuffle_ps::<0x44>(t0, t2),
        _mm256_shuffle_ps::<0xEE>(t0, t2),
        _mm256_shuffle_ps::<0x44>(t1, t3),
        _mm256_shuffle_ps::<0xEE>(t1, t3),
    ];
    // SAFETY: `__m128` is four f32 lanes in memory order, the layout of `[f32; 4]`, and
    // `__m256` eight, the layout of `[[f32; 4]; 2]`.
    unsafe {
        let pair = |v: __m256| std::mem::transmute::<__m256, [[f32; 4]; 2]>(v);
        if m == 0xff {
            [out[0], out[1]] = pair(_mm256_permute2f128_ps::<0x20>(p[0], p[1]));
            [out[2], out[3]] = pair(_mm256_permute2f128_ps::<0x20>(p[2], p[3]));
            [out[4], out[5]] = pair(_mm256_permute2f128_ps::<0x31>(p[0], p[1]));
            [out[6], out[7]] = pair(_mm256_permute2f128_ps::<0x31>(p[2], p[3]));
            return;
        }
        for (q, v) in p.iter().enumerate() {
            let [lo, hi] = pair(*v);
            if m & (1 << q) != 0 {
                out[q] = lo;
            }
            if m & (1 << (q + 4)) != 0 {
                out[q + 4] = hi;
            }
        }
    }
}

/// NEAREST on a dense depth level followed by the depth comparison (`pass_level`'s
/// `dense_kernel` then [`depth_compare_lanes`]) as one AVX2 kernel ([`dense_depth8`]) for a
/// NEAREST `kind` of [`kernel_kind`]: only the depth channel gathered, the eight comparisons at
/// once. Returns false, having done nothing, where the CPU lacks AVX2 or the level has more
/// than 2^28 texels (the caller then takes the two steps).
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn dense_depth(
    kind: u8,
    func: u32,
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    r: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if avx2() && dt.len() <= 1 << 28 && kind < 4 {
        // SAFETY: AVX2 is present (checked above) and `dt` at most 2^28 texels.
        unsafe {
            match kind {
                0 => dense_depth8::<false, false>(func, dt, w, h, s, t, r, m, out),
                1 => dense_depth8::<false, true>(func, dt, w, h, s, t, r, m, out),
                2 => dense_depth8::<true, false>(func, dt, w, h, s, t, r, m, out),
                _ => dense_depth8::<true, true>(func, dt, w, h, s, t, r, m, out),
            }
        }
        return true;
    }
    let _ = (kind, func, dt, w, h, s, t, r, m, out);
    false
}

/// [`dense_nearest8`]'s index per lane, the depth (channel 0) gathered for the eight lanes,
/// then [`depth_compare_lanes`]: r clamped to [0, 1] in `f32::clamp`'s order (maxps/minps
/// return their second operand when the compare fails, so a NaN and -0 are kept), compared with
/// `func`'s predicate (the ordered forms for the comparisons Rust's operators make false on a
/// NaN, the unordered one for `!=`), the result (1 or +0, 0, 0, 0) into the lanes of `m`.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn dense_depth8<const RX: bool, const RY: bool>(
    func: u32,
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    s: &[f32; LANES],
    t: &[f32; LANES],
    r: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let k = nearest_offsets8::<RX, RY>(w, h, km, s, t);
    // SAFETY: AVX2 is present (the caller's promise); each offset is at most
    // 4·(dt.len() - 1), so every f32 read lies inside `dt`.
    let d = unsafe { _mm256_i32gather_ps::<4>(dt.as_ptr().cast::<f32>(), k) };
    let z = _mm256_setzero_ps();
    store8(&[compare8(func, d, lanes8(r)), z, z, z], m, out);
}

/// The depth comparison of [`dense_depth8`] and the fused route's depth groups on eight lanes: the depths `d` against r/q `rr` clamped to
/// [0, 1] (`minps(1, maxps(0, r))`), under `func`'s predicate; each lane 1 or +0 (the
/// LUMINANCE L the environment reads).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn compare8(
    func: u32,
    d: std::arch::x86_64::__m256,
    rr: std::arch::x86_64::__m256,
) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    let one = _mm256_set1_ps(1.0);
    let r = _mm256_min_ps(one, _mm256_max_ps(_mm256_setzero_ps(), rr));
    let c = match func {
        gl::LEQUAL => _mm256_cmp_ps::<_CMP_LE_OQ>(r, d),
        gl::GEQUAL => _mm256_cmp_ps::<_CMP_GE_OQ>(r, d),
        gl::LESS => _mm256_cmp_ps::<_CMP_LT_OQ>(r, d),
        gl::GREATER => _mm256_cmp_ps::<_CMP_GT_OQ>(r, d),
        gl::EQUAL => _mm256_cmp_ps::<_CMP_EQ_OQ>(r, d),
        gl::NOTEQUAL => _mm256_cmp_ps::<_CMP_NEQ_UQ>(r, d),
        gl::ALWAYS => return one,
        _ => return _mm256_setzero_ps(),
    };
    _mm256_and_ps(c, one)
}

/// The wrap class of one axis for the border kernels ([`border_kind`]): the edge clamp
/// (CLAMP_TO_EDGE, and NEAREST's CLAMP), REPEAT, CLAMP_TO_BORDER (an index outside the level
/// reads the border colour), and LINEAR's CLAMP (s clamped to [0, 1] first, then as
/// CLAMP_TO_BORDER).
const AX_EDGE: u8 = 0;
const AX_REPEAT: u8 = 1;
const AX_BORDER: u8 = 2;
const AX_CLAMP: u8 = 3;

/// Which border kernel ([`dense_border`]) covers a one-level pass with filter `linear` and
/// wrap modes `wrap` (s, t) where [`kernel_kind`] has none: at least one axis CLAMP_TO_BORDER
/// (or LINEAR's CLAMP), the other REPEAT, CLAMP, CLAMP_TO_EDGE or CLAMP_TO_BORDER (not
/// MIRRORED_REPEAT). Bit 4 LINEAR, bits 2–3 the class of s, bits 0–1 that of t. Only on a
/// CPU with AVX2 ([`avx2`]; other CPUs keep `pass_on`), None elsewhere.
#[inline(always)]
fn border_kind(linear: bool, wrap: [u32; 3]) -> Option<u8> {
    #[cfg(target_arch = "x86_64")]
    {
        let class = |mode: u32| match mode {
            gl::CLAMP_TO_EDGE => Some(AX_EDGE),
            gl::REPEAT => Some(AX_REPEAT),
            gl::CLAMP_TO_BORDER => Some(AX_BORDER),
            gl::CLAMP if linear => Some(AX_CLAMP),
            gl::CLAMP => Some(AX_EDGE),
            _ => None,
        };
        let (x, y) = (class(wrap[0])?, class(wrap[1])?);
        if x < AX_BORDER && y < AX_BORDER || !avx2() {
            return None;
        }
        Some(u8::from(linear) << 4 | x << 2 | y)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (linear, wrap);
        None
    }
}

/// The one-level pass (`pass_on`) of a [`dense_level`] level `dt` (`w` x `h`, powers of two)
/// with a border texel, for the filter and wrap classes [`border_kind`] encodes in `kind`, as
/// one AVX2 kernel ([`dense_border8`]) for the eight lanes: the lanes of `m` get `pass_on`'s
/// bits, the others are left as they were. `border` is the border colour in the base format's
/// components (`pass_on`'s). Does nothing where the CPU lacks AVX2 or the level has more than
/// 2^28 texels (`border_kind` is None there, so no caller reaches it). Out of line, as
/// [`dense_kernel`].
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn dense_border(
    kind: u8,
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    border: [f32; 4],
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    #[cfg(target_arch = "x86_64")]
    if avx2() && dt.len() <= 1 << 28 {
        macro_rules! pick {
            ($($k:literal => $lin:literal, $x:ident, $y:ident;)*) => {
                match kind {
                    // SAFETY: AVX2 is present (checked above) and `dt` at most 2^28 texels.
                    $($k => unsafe {
                        dense_border8::<$lin, $x, $y>(dt, w, h, border, s, t, m, out)
                    },)*
                    _ => {}
                }
            };
        }
        pick! {
            0b0_0010 => false, AX_EDGE, AX_BORDER;
            0b0_0110 => false, AX_REPEAT, AX_BORDER;
            0b0_1000 => false, AX_BORDER, AX_EDGE;
            0b0_1001 => false, AX_BORDER, AX_REPEAT;
            0b0_1010 => false, AX_BORDER, AX_BORDER;
            0b1_0010 => true, AX_EDGE, AX_BORDER;
            0b1_0011 => true, AX_EDGE, AX_CLAMP;
            0b1_0110 => true, AX_REPEAT, AX_BORDER;
            0b1_0111 => true, AX_REPEAT, AX_CLAMP;
            0b1_1000 => true, AX_BORDER, AX_EDGE;
            0b1_1001 => true, AX_BORDER, AX_REPEAT;
            0b1_1010 => true, AX_BORDER, AX_BORDER;
            0b1_1011 => true, AX_BORDER, AX_CLAMP;
            0b1_1100 => true, AX_CLAMP, AX_EDGE;
            0b1_1101 => true, AX_CLAMP, AX_REPEAT;
            0b1_1110 => true, AX_CLAMP, AX_BORDER;
            0b1_1111 => true, AX_CLAMP, AX_CLAMP;
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (kind, dt, w, h, border, s, t, m, out);
    }
}

/// An axis of [`dense_border8`] for wrap class `MODE` (AVX2): the wrapped index and an
/// all-ones lane where it is inside the level (always for the edge clamp and REPEAT), from
/// the floor `i` on `n` texels ([`nearest_finish`], [`linear_finish`]).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn border_finish8<const MODE: u8>(
    i: std::arch::x86_64::__m256i,
    n: i32,
) -> (std::arch::x86_64::__m256i, std::arch::x86_64::__m256i) {
    use std::arch::x86_64::*;
    match MODE {
        AX_EDGE => (
            wrap8::<false>(i, _mm256_set1_epi32(n - 1)),
            _mm256_set1_epi32(-1),
        ),
        AX_REPEAT => (
            wrap8::<true>(i, _mm256_set1_epi32(n - 1)),
            _mm256_set1_epi32(-1),
        ),
        // i >= 0 && i < n.
        _ => (
            i,
            _mm256_and_si256(
                _mm256_cmpgt_epi32(i, _mm256_set1_epi32(-1)),
                _mm256_cmpgt_epi32(_mm256_set1_epi32(n), i),
            ),
        ),
    }
}

/// A LINEAR axis of [`dense_border8`] for wrap class `MODE` (AVX2): [`linear_u`] (CLAMP's
/// clamp of s to [0, 1] in `f32::clamp`'s order, u = s·n − ½, a NaN u taken as 0), the floor,
/// the weight from the unwrapped floor and the second index by `saturating_add`
/// ([`linear_finish`], as [`linear_axis8`]), then each index's finish and inside lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
#[allow(clippy::type_complexity)]
fn border_linear8<const MODE: u8>(
    c: std::arch::x86_64::__m256,
    n: i32,
) -> (
    [std::arch::x86_64::__m256i; 2],
    [std::arch::x86_64::__m256i; 2],
    std::arch::x86_64::__m256,
) {
    use std::arch::x86_64::*;
    let c = if MODE == AX_CLAMP {
        // `f32::clamp(0, 1)`: below 0 taken as 0, above 1 as 1, a NaN and -0 kept (maxps and
        // minps return their second operand when the compare fails).
        _mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_setzero_ps(), c))
    } else {
        c
    };
    let u = _mm256_sub_ps(
        _mm256_mul_ps(c, _mm256_set1_ps(n as f32)),
        _mm256_set1_ps(0.5),
    );
    let u = _mm256_and_ps(u, _mm256_cmp_ps::<_CMP_ORD_Q>(u, u));
    let i0 = ifloor8_num(u);
    let a = _mm256_sub_ps(u, _mm256_cvtepi32_ps(i0));
    let a = _mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_setzero_ps(), a));
    let at_max = _mm256_cmpeq_epi32(i0, _mm256_set1_epi32(i32::MAX));
    let i1 = _mm256_add_epi32(_mm256_add_epi32(i0, _mm256_set1_epi32(1)), at_max);
    let (i0, in0) = border_finish8::<MODE>(i0, n);
    let (i1, in1) = border_finish8::<MODE>(i1, n);
    ([i0, i1], [in0, in1], a)
}

/// NEAREST or LINEAR (`LIN`) on a dense level with a border texel (AVX2), wrap classes `MX`
/// on s and `MY` on t ([`AX_EDGE`], [`AX_REPEAT`], [`AX_BORDER`], [`AX_CLAMP`]): `pass_on`'s
/// wraps, indices j·w + i and eq. 3.24's weights and sum in its order, on eight lanes. NEAREST
/// gathers each channel of the eight lanes' texels through their inside mask (`vgatherdps`
/// with the border colour's channel where a texel is outside the level: the texel `pass_on`
/// takes, without reading it), then transposes back to a texel per lane; LINEAR loads each
/// covered lane's four texels whole (16 bytes each) and sums the four channels at once.
///
/// # Safety
/// The CPU must have AVX2, and `dt` at most 2^28 texels.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn dense_border8<const LIN: bool, const MX: u8, const MY: u8>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    border: [f32; 4],
    s: &[f32; LANES],
    t: &[f32; LANES],
    m: u8,
    out: &mut TexelLanes,
) {
    use std::arch::x86_64::*;
    let Some(km) = dt.len().checked_sub(1) else {
        return;
    };
    let (w, h) = (w.max(1), h.max(1));
    let sh = _mm_cvtsi32_si128(w.trailing_zeros() as i32);
    // The f32 offset of a texel: (k & km)·4, k & km being k for every in-image index (below
    // the power-of-two count) and at most 2^28 - 1 (the caller's bound), so that a lane
    // outside the mask reads nothing outside `dt` either.
    let kmv = _mm256_set1_epi32(km as i32);
    let off = |j: __m256i, i: __m256i| {
        _mm256_slli_epi32::<2>(_mm256_and_si256(
            _mm256_add_epi32(_mm256_sll_epi32(j, sh), i),
            kmv,
        ))
    };
    let base = dt.as_ptr().cast::<f32>();
    let mut ch = [_mm256_setzero_ps(); 4];
    if !LIN {
        // [`nearest_u`], [`nearest_finish`].
        let i = ifloor8(_mm256_mul_ps(lanes8(s), _mm256_set1_ps(w as f32)));
        let j = ifloor8(_mm256_mul_ps(lanes8(t), _mm256_set1_ps(h as f32)));
        let (i, ii) = border_finish8::<MX>(i, w);
        let (j, ji) = border_finish8::<MY>(j, h);
        let (k, inside) = (off(j, i), _mm256_castsi256_ps(_mm256_and_si256(ii, ji)));
        for (c, v) in ch.iter_mut().enumerate() {
            // SAFETY: AVX2 is present (the caller's promise); each offset is at most
            // 4·(dt.len() - 1) and c < 4, so every f32 the mask lets it read lies inside `dt`.
            *v = unsafe {
                _mm256_mask_i32gather_ps::<4>(_mm256_set1_ps(border[c]), base.add(c), k, inside)
            };
        }
    } else {
        let (x, xi, a) = border_linear8::<MX>(lanes8(s), w);
        let (y, yi, b) = border_linear8::<MY>(lanes8(t), h);
        let one = _mm256_set1_ps(1.0);
        let (na, nb) = (_mm256_sub_ps(one, a), _mm256_sub_ps(one, b));
        let wt = [
            _mm256_mul_ps(na, nb),
            _mm256_mul_ps(a, nb),
            _mm256_mul_ps(na, b),
            _mm256_mul_ps(a, b),
        ];
        // Each lane's four texels as plain 16-byte loads (the border colour where a texel is
        // outside the level), summed four channels at a time: a channel-by-channel gather of
        // the eight lanes cost more time than these loads, for fewer instructions.
        let idx = |j: __m256i, i: __m256i| {
            _mm256_and_si256(_mm256_add_epi32(_mm256_sll_epi32(j, sh), i), kmv)
        };
        let mut kt = [[0u32; LANES]; 4];
        let mut wts = [[0.0f32; LANES]; 4];
        let corners = [
            idx(y[0], x[0]),
            idx(y[0], x[1]),
            idx(y[1], x[0]),
            idx(y[1], x[1]),
        ];
        for q in 0..4 {
            // SAFETY: AVX is present (the caller's promise); each store writes exactly the
            // eight 4-byte lanes of its `[_; 8]` array (no alignment needed).
            unsafe {
                _mm256_storeu_si256(kt[q].as_mut_ptr().cast(), corners[q]);
                _mm256_storeu_ps(wts[q].as_mut_ptr(), wt[q]);
            }
        }
        let ins = [
            _mm256_and_si256(xi[0], yi[0]),
            _mm256_and_si256(xi[1], yi[0]),
            _mm256_and_si256(xi[0], yi[1]),
            _mm256_and_si256(xi[1], yi[1]),
        ]
        .map(|v| _mm256_movemask_ps(_mm256_castsi256_ps(v)) as u32);
        for (l, o) in out.iter_mut().enumerate() {
            if m & (1 << l) == 0 {
                continue;
            }
            let at = |q: usize| {
                let texel = if ins[q] & (1 << l) != 0 {
                    dt.get(kt[q][l] as usize & km).unwrap_or(&border)
                } else {
                    &border
                };
                // SAFETY: SSE is part of the x86-64 baseline; the load reads the four f32 of
                // one `[f32; 4]` (no alignment needed).
                unsafe { _mm_loadu_ps(texel.as_ptr()) }
            };
            // eq. 3.24's sum in `pass_on`'s order, all four channels at once.
            let v = _mm_add_ps(
                _mm_mul_ps(_mm_set1_ps(wts[0][l]), at(0)),
                _mm_mul_ps(_mm_set1_ps(wts[1][l]), at(1)),
            );
            let v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(wts[2][l]), at(2)));
            let v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(wts[3][l]), at(3)));
            // SAFETY: as above; the store writes the four f32 of `o`.
            unsafe { _mm_storeu_ps(o.as_mut_ptr(), v) };
        }
        return;
    }
    store8(&ch, m, out);
}

/// Are all of `n` (each taken as at least 1) powers of two?
#[inline(always)]
fn all_pow2(n: &[i32; LANES]) -> bool {
    n.iter().all(|&n| {
        let n = n.max(1);
        n & (n - 1) == 0
    })
}

/// Can a one-level pass gather `tx`, a level of `w` x `h` texels, through an index mask: at
/// least one texel per axis, exactly w·h texels, a power-of-two count that fits an i32. Then
/// every index j·w + i of an in-image texel (0 <= i < w, 0 <= j < h, what every wrap mode but
/// the border's gives) lies in 0..tx.len(), where `k & (tx.len() - 1)` is k itself: the same
/// texel `Level::texel` reads, without a bounds check that cannot fail.
#[inline(always)]
fn dense_level(tx: &[[f32; 4]], w: i32, h: i32) -> bool {
    let n = tx.len();
    w >= 1
        && h >= 1
        && n.is_power_of_two()
        && n <= i32::MAX as usize
        && (w as usize).checked_mul(h as usize) == Some(n)
}

/// [`wrap_nearest_i`] on eight lanes (the floors by [`ifloor_lanes`]), lane l along an axis
/// of `n.at(l)` texels: the mode (and whether every n is a power of two) chosen once, each arm
/// a plain loop over the lanes with a constant mode, so every lane is the scalar index.
#[inline(always)]
fn wrap_nearest_lanes<A: Axis>(mode: u32, s: &[f32; LANES], n: A) -> ([i32; LANES], [bool; LANES]) {
    let mut i = [0i32; LANES];
    let mut inside = [true; LANES];
    macro_rules! each {
        ($mode:expr, $p2:expr) => {{
            let mut u = [0.0f32; LANES];
            for l in 0..LANES {
                u[l] = nearest_u($mode, s[l], n.at(l));
            }
            let fl = ifloor_lanes(&u);
            for l in 0..LANES {
                (i[l], inside[l]) = nearest_finish($mode, fl[l], n.at(l), $p2);
            }
        }};
    }
    match (mode, n.pow2()) {
        (gl::REPEAT, true) => each!(gl::REPEAT, true),
        (gl::REPEAT, false) => each!(gl::REPEAT, false),
        (gl::MIRRORED_REPEAT, _) => each!(gl::MIRRORED_REPEAT, false),
        (gl::CLAMP_TO_BORDER, _) => each!(gl::CLAMP_TO_BORDER, false),
        (gl::CLAMP_TO_EDGE, _) => each!(gl::CLAMP_TO_EDGE, false),
        _ => each!(mode, false),
    }
    (i, inside)
}

/// The LINEAR indices, weights and inside flags of eight lanes ([`wrap_linear_i`] per lane).
struct LinearLanes {
    i0: [i32; LANES],
    i1: [i32; LANES],
    w: [f32; LANES],
    in0: [bool; LANES],
    in1: [bool; LANES],
}

/// [`wrap_linear_i`] on eight lanes (the floors by [`ifloor_lanes`]), lane l along an axis of
/// `n.at(l)` texels, the mode chosen once (as [`wrap_nearest_lanes`]).
#[inline(always)]
fn wrap_linear_lanes<A: Axis>(mode: u32, s: &[f32; LANES], n: A) -> LinearLanes {
    let mut o = LinearLanes {
        i0: [0; LANES],
        i1: [0; LANES],
        w: [0.0; LANES],
        in0: [true; LANES],
        in1: [true; LANES],
    };
    macro_rules! each {
        ($mode:expr, $p2:expr) => {{
            let mut u = [0.0f32; LANES];
            for l in 0..LANES {
                u[l] = linear_u($mode, s[l], n.at(l));
            }
            let fl = ifloor_lanes(&u);
            for l in 0..LANES {
                (o.i0[l], o.i1[l], o.w[l], o.in0[l], o.in1[l]) =
                    linear_finish($mode, u[l], fl[l], n.at(l), $p2);
            }
        }};
    }
    match (mode, n.pow2()) {
        (gl::REPEAT, true) => each!(gl::REPEAT, true),
        (gl::REPEAT, false) => each!(gl::REPEAT, false),
        (gl::MIRRORED_REPEAT, _) => each!(gl::MIRRORED_REPEAT, false),
        (gl::CLAMP, _) => each!(gl::CLAMP, false),
        (gl::CLAMP_TO_BORDER, _) => each!(gl::CLAMP_TO_BORDER, false),
        (gl::CLAMP_TO_EDGE, _) => each!(gl::CLAMP_TO_EDGE, false),
        _ => each!(mode, false),
    }
    o
}

/// The trilinear blend of `sample_face`, (1 - f)·a + f·b per channel, for the lanes of
/// `second`: `a` in `out`, `b` the next level's texels, f the lanes' weights.
#[inline(always)]
fn blend_levels(out: &mut TexelLanes, b: &TexelLanes, f: &[f32; LANES], second: u8) {
    for l in 0..LANES {
        if second & (1 << l) != 0 {
            let (a, b, f) = (out[l], b[l], f[l]);
            for k in 0..4 {
                out[l][k] = a[k] * (1.0 - f) + b[k] * f;
            }
        }
    }
}

/// Eq. 3.24's sum of four texels `t` (t00, t10, t01, t11) with their weights `w`, in the
/// scalar expression's order, per channel.
#[inline(always)]
fn bilinear(w: [f32; 4], t: [[f32; 4]; 4]) -> [f32; 4] {
    let mut o = [0.0f32; 4];
    for c in 0..4 {
        o[c] = w[0] * t[0][c] + w[1] * t[1][c] + w[2] * t[2][c] + w[3] * t[3][c];
    }
    o
}

/// λ of one unit for the 2x2 quads of a span row, computed eight quads at a time as the
/// span's lane groups ask for them ([`SpanLambda::lanes`]): a group of eight pixels needs four
/// or five quads, so one call of [`Sampler::quad_lambda_lanes`] for eight quads from the
/// group's first usually serves the next group too. Each value is `quad_lambda_lanes`'s for the
/// same quad position (its lanes are independent of each other), so the same bits.
///
/// The eleventh session dropped the per-thread row of quads that the span of the second pixel
/// row of a quad row reused (keyed by the planes, 80 bytes): on texture-targets (small
/// triangles) its bookkeeping cost ≈162 instructions a group and saved too few λ calls (140 634
/// for 192 444 groups), more than the AVX2 λ (≈215 a call) it saved.
#[derive(Clone, Copy, Debug)]
pub struct SpanLambda {
    /// Window x of the planes' origin (the primitive's bounding-box corner).
    ox: i32,
    /// The quads' lower-left y relative to the planes' origin.
    qy: f32,
    /// The window quad number (window x / 2, floor) of `lam[0]`; `lam` holds nothing yet when
    /// `have` is false.
    q0: i32,
    have: bool,
    /// λ of quads `q0..q0 + 8`, and a spare entry (the window `lanes` reads is five quads).
    lam: [f32; LANES + 1],
}

impl SpanLambda {
    /// For a span row whose first pixel is at window x `x0` (not needed: the quads are kept by
    /// window x), with the planes' origin at window x `ox` and the row's quads at `qy`
    /// (relative to the origin, as `quad_lambda` takes it).
    #[inline]
    pub fn new(x0: i32, ox: i32, qy: f32) -> SpanLambda {
        let _ = x0;
        SpanLambda {
            ox,
            qy,
            q0: 0,
            have: false,
            lam: [0.0; LANES + 1],
        }
    }

    /// λ for the eight pixels from window x `x` (lane l at x + l): each its quad's, as
    /// `s.quad_lambda_lanes(planes, to, ..)` gives it. `s`, `planes` and `to` must be the same
    /// on every call for one `SpanLambda`.
    #[inline]
    pub fn lanes(&mut self, s: &Sampler, planes: &[f32], to: usize, x: i32) -> [f32; LANES] {
        let last = x.saturating_add(LANES as i32 - 1);
        if last == i32::MAX || x < i32::MIN / 2 {
            let qx = std::array::from_fn(|l| {
                (x.wrapping_add(l as i32) & !1).wrapping_sub(self.ox) as f32
            });
            return s.quad_lambda_lanes(planes, to, qx, self.qy);
        }
        // The group's first and last quads (lane l's is (x + l) / 2, floor).
        let (qa, qb) = (x >> 1, last >> 1);
        if !self.have || qa < self.q0 || qb - self.q0 >= LANES as i32 {
            // Quads qa..qa + 8, at window x 2·q (what `(x + l) & !1` is for lane l's quad).
            let ox = self.ox;
            let qx = std::array::from_fn(|j| {
                qa.wrapping_add(j as i32).wrapping_mul(2).wrapping_sub(ox) as f32
            });
            let v = s.quad_lambda_lanes(planes, to, qx, self.qy);
            self.lam[..LANES].copy_from_slice(&v);
            (self.q0, self.have) = (qa, true);
        }
        // qa - q0 is 0..=4 here (qb - qa is 3 or 4, qb - q0 < 8); the five entries from it are
        // inside `lam` (its spare one is read only for an even x, whose lanes use four).
        let d = usize::try_from(qa - self.q0).unwrap_or(0).min(4);
        spread_quads(&self.lam, d, x)
    }
}

/// The s, t, r and q planes of the coordinates at varying `to` (`Sampler::quad_lambda_avx2`,
/// `Sampler::quad_lambda_row`); past the end of `planes`, 0 (as `quad_lambda_on`), out of
/// line: merged with the twelve loads, the bounded lookups cost ≈40 instructions a call
/// (texture-targets, callgrind).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lambda_planes_at(planes: &[f32], to: usize) -> [[f32; 3]; 4] {
    let o = to.saturating_add(1).saturating_mul(3);
    let whole = planes
        .get(o..o.saturating_add(12))
        .and_then(|p| <&[f32; 12]>::try_from(p).ok());
    match whole {
        Some(p) => std::array::from_fn(|j| [p[3 * j], p[3 * j + 1], p[3 * j + 2]]),
        None => lambda_planes_short(planes, to),
    }
}

/// The s, t, r and q planes of the coordinates at varying `to` (`lambda_planes_at`)
/// when `planes` ends before their last: each value past the end 0 (as `quad_lambda_on`).
#[cfg(target_arch = "x86_64")]
#[cold]
#[inline(never)]
fn lambda_planes_short(planes: &[f32], to: usize) -> [[f32; 3]; 4] {
    lambda_planes(planes, to)
}

/// The s, t, r and q planes of the coordinates at varying `to`, each value past the end of
/// `planes` 0 (`Sampler::quad_lambda_on`).
#[inline(always)]
fn lambda_planes(planes: &[f32], to: usize) -> [[f32; 3]; 4] {
    let g = |o: usize| planes.get(o).copied().unwrap_or(0.0);
    let plane = |j: usize| [g(3 * j), g(3 * j + 1), g(3 * j + 2)];
    [plane(1 + to), plane(2 + to), plane(3 + to), plane(4 + to)]
}

/// λ for the eight pixels from window x `x` (lane l at x + l) from a row of quads' λ, `lam[d]`
/// the quad of pixel x (window x / 2, floor) and the next four after it: lane l takes its
/// quad's, `lam[d + (x % 2 + l) / 2]`. Entries past `lam`'s end read as 0 (lane 7 of an even
/// x never reads entry d + 4).
#[inline(always)]
pub fn spread_quads(lam: &[f32], d: usize, x: i32) -> [f32; LANES] {
    let mut w = [0.0f32; 5];
    if let Some(src) = lam.get(d..d + 5) {
        w.copy_from_slice(src);
    }
    if x & 1 == 0 {
        [w[0], w[0], w[1], w[1], w[2], w[2], w[3], w[3]]
    } else {
        [w[0], w[1], w[1], w[2], w[2], w[3], w[3], w[4]]
    }
}

/// The filter a minification filter applies within one level: LINEAR for LINEAR and the
/// LINEAR_MIPMAP_* filters, NEAREST for the others (GL 2.1 §3.8.8).
fn lin(filter: u32) -> u32 {
    if matches!(
        filter,
        gl::LINEAR | gl::LINEAR_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_LINEAR
    ) {
        gl::LINEAR
    } else {
        gl::NEAREST
    }
}

#[cfg(test)]
#[path = "tests/texture.rs"]
mod tests;
