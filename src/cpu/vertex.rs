//! The vertex stage: modelview and projection transforms, the normal transform with
//! RESCALE_NORMAL / NORMALIZE, and the GL 1.x lighting equation (GL 2.1 §2.11, §2.14.1).
//!
//! Design decision: `Lighting::eval` is the one implementation of the lighting equation,
//! generic over its number of lanes and written on a structure of arrays so that the compiler
//! vectorises it; the vertex stage calls it for blocks of `LANES` vertices (`shade_lanes`) and the
//! PHONG_WIN fragment path (through `Lighting::shade`) for single fragments, so the two shading modes can
//! never disagree about the equation, down to the bits. The vertex stage makes one pass per block:
//! it transforms the block's positions and normals on arrays, computes the window coordinates
//! and clip codes (`SetupCtx::win_lanes`, the records written a block at a time on AVX2) while
//! the clip positions are in hand, then lights the block. Results are written to one flat `f32`
//! array with a per-flush `Layout`, carrying only the attributes the flush needs, plus each
//! vertex's clip code and window coordinates. The
//! structures of arrays (`Lanes3`, `Lanes4`, `Block`, `Shaded`) live in the `lanes` submodule.

use glam::{Mat3, Mat4, Vec3, Vec3A, Vec4, Vec4Swizzles};
use rayon::prelude::*;

mod lanes;

use lanes::{clamp01, normalize_or_zero, put_arr};
pub use lanes::{Block, Lanes3, Lanes4, Shaded, LANES};

use super::batch::Batch;
use super::libm8::powf_lanes;
use super::setup::{SetupCtx, Win};
use crate::gl;
use crate::state::{Material, State, BACK, FRONT, MAX_LIGHTS, MAX_TEXTURE_UNITS};

/// Where each attribute lives inside one processed vertex (offsets in `f32`s; clip position at 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Layout {
    /// Floats per vertex.
    pub stride: usize,
    /// Front primary colour (always present; the vertex colour when lighting is off).
    pub col: usize,
    /// Front secondary colour, when the colour sum can use it.
    pub spec: Option<usize>,
    /// Back primary colour, under two-sided lighting.
    pub col_b: Option<usize>,
    /// Back secondary colour, under two-sided lighting with a secondary colour.
    pub spec_b: Option<usize>,
    /// Texture coordinates of each unit (unit 0 always in feedback; otherwise when a texture
    /// target is enabled on the unit), in unit order.
    pub tex: [Option<usize>; MAX_TEXTURE_UNITS],
    /// Eye-space position (x, y, z, w), for user clip planes and per-fragment lighting.
    pub eye: Option<usize>,
    /// Eye-space normal (after rescale/normalize), for per-fragment lighting.
    pub nrm: Option<usize>,
    /// Unlit vertex colour, for COLOR_MATERIAL under per-fragment lighting.
    pub raw: Option<usize>,
    /// Fog coordinate c (one float), when FOG is enabled (§3.10).
    pub fog: Option<usize>,
    /// The point's size (one float) under distance attenuation (§3.3 eq. 3.1), as Mesa's
    /// fixed-function vertex program computes it.
    pub psize: Option<usize>,
}

impl Layout {
    /// The layout `state` needs.
    pub fn for_state(state: &State) -> Self {
        let lit = state.enables.lighting;
        let phong = lit && state.shade_model == gl::PHONG_WIN;
        let spec = (lit && state.light_model.color_control == gl::SEPARATE_SPECULAR_COLOR)
            || state.enables.color_sum;
        let two = lit && state.light_model.two_side;
        // A unit carries coordinates when any texture target is enabled on it.
        let e = &state.enables;
        let unit_on = |u: usize| {
            e.texture_1d[u] || e.texture_2d[u] || e.texture_3d[u] || e.texture_cube_map[u]
        };
        let user = state.enables.clip_planes.iter().any(|&b| b);
        let mut l = Layout {
            col: 4,
            ..Layout::default()
        };
        let mut n = 8;
        let mut take = |k: usize| {
            let o = n;
            n += k;
            Some(o)
        };
        if spec {
            l.spec = take(4);
        }
        if two {
            l.col_b = take(4);
            if spec {
                l.spec_b = take(4);
            }
        }
        for (u, t) in l.tex.iter_mut().enumerate() {
            if unit_on(u) {
                *t = take(4);
            }
        }
        if phong || user {
            l.eye = take(4);
        }
        if phong {
            l.nrm = take(3);
            l.raw = take(4);
        }
        if state.enables.fog {
            l.fog = take(1);
        }
        if state.point.attenuated() {
            l.psize = take(1);
        }
        l.stride = n;
        l
    }

    /// The layout selection and feedback need (GL 2.1 §5.2, §5.3): `for_state`'s, with unit 0's
    /// texture coordinates always (feedback reports them, through TexGen and the texture
    /// matrix, whether or not texturing is on).
    pub fn for_feedback(state: &State) -> Self {
        let mut l = Self::for_state(state);
        if l.tex[0].is_none() {
            l.tex[0] = Some(l.stride);
            l.stride += 4;
        }
        l
    }

    /// The layout selection needs: the clip position, and the eye position under user clip
    /// planes. A hit records window depths only, so no colour (the `col` slot is left as it
    /// was), texture coordinate or lighting is computed.
    pub fn for_select(state: &State) -> Self {
        let user = state.enables.clip_planes.iter().any(|&b| b);
        Layout {
            col: 4,
            eye: user.then_some(8),
            stride: if user { 12 } else { 8 },
            ..Layout::default()
        }
    }
}

/// One enabled light with what the equation needs, in eye coordinates.
#[derive(Clone, Copy, Debug, Default)]
struct Src {
    ambient: Vec3A,
    diffuse: Vec3A,
    specular: Vec3A,
    /// xyz: position (w != 0, already divided) or direction (w == 0).
    pos: Vec3A,
    positional: bool,
    /// Unit spot direction.
    spot_dir: Vec3A,
    spot_exp: f32,
    /// cos(SPOT_CUTOFF), or None for cutoff 180.
    spot_cos: Option<f32>,
    att: [f32; 3],
    /// Attenuation is exactly 1 (constant 1, linear and quadratic 0): skip computing it.
    no_att: bool,
    /// Directional light: unit VP, the same at every point.
    vp_dir: Vec3A,
    /// The specular colour is exactly zero.
    spec_zero: bool,
    /// The specular colour is finite.
    spec_finite: bool,
    /// Every specular component is at most 1 in magnitude.
    spec_small: bool,
}

/// The lighting parameters of one flush (GL 2.1 §2.14.1), ready to evaluate at any point.
#[derive(Clone, Debug)]
pub struct Lighting {
    srcs: [Src; MAX_LIGHTS],
    n: usize,
    scene_ambient: Vec3A,
    local_viewer: bool,
    separate: bool,
    /// COLOR_MATERIAL: which faces track the colour, and the mode.
    color_material: Option<([bool; 2], u32)>,
}

impl Lighting {
    /// The lighting state of `state`, whether or not LIGHTING is enabled.
    pub fn new(state: &State) -> Self {
        let mut srcs = [Src::default(); MAX_LIGHTS];
        let mut n = 0;
        for (l, _) in state
            .lights
            .iter()
            .zip(state.enables.lights)
            .filter(|(_, on)| *on)
        {
            let positional = l.position.w != 0.0;
            srcs[n] = Src {
                ambient: l.ambient.xyz().into(),
                diffuse: l.diffuse.xyz().into(),
                specular: l.specular.xyz().into(),
                pos: if positional {
                    (l.position.xyz() / l.position.w).into()
                } else {
                    l.position.xyz().into()
                },
                positional,
                spot_dir: l.spot_direction.normalize_or_zero().into(),
                spot_exp: l.spot_exponent,
                spot_cos: (l.spot_cutoff != 180.0).then(|| l.spot_cutoff.to_radians().cos()),
                att: [
                    l.constant_attenuation,
                    l.linear_attenuation,
                    l.quadratic_attenuation,
                ],
                no_att: l.constant_attenuation == 1.0
                    && l.linear_attenuation == 0.0
                    && l.quadratic_attenuation == 0.0,
                vp_dir: l.position.xyz().normalize_or_zero().into(),
                spec_zero: l.specular.xyz() == Vec3::ZERO,
                spec_finite: l.specular.xyz().is_finite(),
                spec_small: l.specular.xyz().abs().max_element() <= 1.0,
            };
            n += 1;
        }
        let faces = match state.color_material_face {
            gl::FRONT => [true, false],
            gl::BACK => [false, true],
            _ => [true, true],
        };
        Lighting {
            srcs,
            n,
            scene_ambient: state.light_model.ambient.xyz().into(),
            local_viewer: state.light_model.local_viewer,
            separate: state.light_model.color_control == gl::SEPARATE_SPECULAR_COLOR,
            color_material: state
                .enables
                .color_material
                .then_some((faces, state.color_material_mode)),
        }
    }

    /// The lit (primary, secondary) colours, clamped to [0, 1], of a point at eye position `v`
    /// with unit normal `n` (already negated for a back face), material `m` of face `face`
    /// (FRONT or BACK), and vertex colour `color` for COLOR_MATERIAL (GL 2.1 §2.14.1, §2.14.3).
    /// The secondary colour is the specular sum under SEPARATE_SPECULAR_COLOR, else zero.
    ///
    /// Not inlined: PHONG_WIN's fragment loop (`FragCtx::tri_rows_avx2`) calls it for each
    /// fragment and never inlined it (it was `#[inline]`, so every codegen unit that called it
    /// compiled its own copy). One copy, here, keeps the fragment stage's code independent of
    /// how the vertex stage's code is split among the codegen units: with `#[inline]`, adding
    /// `lanes::put_wins_avx2` to the vertex stage cost `tri_rows_avx2` ≈11 instructions a
    /// lit fragment on gauss-phong-40 (+1.0%) and set-up's `assemble_avx2` +4.7M on
    /// gauss-smooth-400, for no change in either function's source.
    #[inline(never)]
    pub fn shade(&self, m: &Material, face: usize, color: Vec4, v: Vec3, n: Vec3) -> (Vec4, Vec4) {
        let mut out = Shaded::default();
        let p = Block {
            v: Lanes3::splat(v),
            n: Lanes3::splat(n),
            color: [color],
        };
        self.eval(m, face, &p, &mut out);
        out.get(0)
    }

    /// [`Lighting::shade`] for `N` points at once ([`LANES`] for vertices, 1 for a fragment):
    /// the same equation, evaluated step by step across the points on a structure of arrays, so
    /// that the compiler vectorises the square roots, divisions and dot products and the `powf`s
    /// of different points overlap in the CPU.
    ///
    /// Every value is computed with the operations, in the order, of the scalar formula
    /// (`(x·x' + y·y') + z·z'` dot products, `(s·light)·material` products), so results do not
    /// depend on `N`. Work whose result is known is skipped only where the skip is exact: `powf`
    /// when N·L <= 0 (its result is unused), when N·H is 0 (0^srm = 0 for srm > 0), and when
    /// the light's or the material's specular colour is zero (the term is a zero whatever the
    /// finite power, which N·H <= 1 guarantees), and when the power is provably too small to
    /// change any bit of the colour it is added to (see `negligible`); the specular term is then
    /// computed from a power of 0, as where N·L <= 0.
    ///
    /// The stage itself calls the same body through [`Lighting::shade_lanes`] (results left on
    /// arrays) and [`Lighting::shade`] (one point); this form is what the tests compare them with.
    #[cfg(test)]
    pub fn shade_block<const N: usize>(
        &self,
        m: &Material,
        face: usize,
        pts: &Block<N>,
        out: &mut [(Vec4, Vec4); N],
    ) {
        let mut sh = Shaded::default();
        self.eval(m, face, pts, &mut sh);
        for (k, o) in out.iter_mut().enumerate() {
            *o = sh.get(k);
        }
    }

    /// [`Lighting::shade_block`] with its results left on arrays (for the vertex stage).
    #[inline(always)]
    pub(super) fn shade_lanes<const N: usize>(
        &self,
        m: &Material,
        face: usize,
        pts: &Block<N>,
        out: &mut Shaded<N>,
    ) {
        self.eval(m, face, pts, out);
    }

    /// The body of [`Lighting::shade_block`], inlined into [`Lighting::shade`] so that a
    /// fragment's point stays in registers.
    // Lane loops index several arrays in lockstep (structure of arrays): indices read best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn eval<const N: usize>(&self, m: &Material, face: usize, pts: &Block<N>, out: &mut Shaded<N>) {
        // Lane masks (`need`) are u32: checked when the function is instantiated, not at run time.
        const { assert!(N <= 32) };
        // §2.14.3: COLOR_MATERIAL replaces the tracked property with the vertex colour.
        let tracked = self
            .color_material
            .and_then(|(faces, mode)| faces.get(face).copied().unwrap_or(false).then_some(mode));
        let mut acm = Lanes3::<N>::splat(m.ambient.xyz());
        let mut dcm = Lanes3::<N>::splat(m.diffuse.xyz());
        let mut scm = Lanes3::<N>::splat(m.specular.xyz());
        let mut ecm = Lanes3::<N>::splat(m.emission.xyz());
        let mut alpha = [m.diffuse.w; N];
        if let Some(mode) = tracked {
            for (i, color) in pts.color.iter().enumerate() {
                let col = color.xyz();
                match mode {
                    gl::AMBIENT => acm.set(i, col),
                    gl::DIFFUSE => {
                        dcm.set(i, col);
                        alpha[i] = color.w;
                    }
                    gl::SPECULAR => scm.set(i, col),
                    gl::EMISSION => ecm.set(i, col),
                    _ => {
                        acm.set(i, col);
                        dcm.set(i, col);
                        alpha[i] = color.w;
                    }
                }
            }
        }
        let (v, nrm) = (&pts.v, &pts.n);
        let sa = self.scene_ambient;
        let mut c = Lanes3::<N>::splat(Vec3::ZERO);
        for i in 0..N {
            c.x[i] = ecm.x[i] + sa.x * acm.x[i];
            c.y[i] = ecm.y[i] + sa.y * acm.y[i];
            c.z[i] = ecm.z[i] + sa.z * acm.z[i];
        }
        let mut s = Lanes3::<N>::splat(Vec3::ZERO);
        let mut eye = Lanes3::<N>::splat(Vec3::Z);
        if self.local_viewer {
            // Local viewer: the half vector uses the direction to the eye.
            for i in 0..N {
                let (x, y, z) = normalize_or_zero(-v.x[i], -v.y[i], -v.z[i]);
                eye.x[i] = x;
                eye.y[i] = y;
                eye.z[i] = z;
            }
        }
        let shininess = m.shininess;
        // Whether every lane's specular material colour is zero, or at most 1 in magnitude: the
        // material's own unless COLOR_MATERIAL tracks the specular colour.
        let (scm_zero, scm_small) = if matches!(tracked, Some(gl::SPECULAR)) {
            (
                (0..N).all(|i| scm.x[i] == 0.0 && scm.y[i] == 0.0 && scm.z[i] == 0.0),
                (0..N).all(|i| {
                    scm.x[i].abs() <= 1.0 && scm.y[i].abs() <= 1.0 && scm.z[i].abs() <= 1.0
                }),
            )
        } else {
            let sm = m.specular.xyz();
            (sm == Vec3::ZERO, sm.abs().max_element() <= 1.0)
        };
        for l in &self.srcs[..self.n] {
            let mut vp = Lanes3::<N>::splat(l.vp_dir.into());
            let mut kf = [1.0f32; N];
            let mut on = [true; N];
            if l.positional {
                let mut d2 = [0.0f32; N];
                let mut inv = [0.0f32; N];
                for i in 0..N {
                    let dx = l.pos.x - v.x[i];
                    let dy = l.pos.y - v.y[i];
                    let dz = l.pos.z - v.z[i];
                    d2[i] = dx * dx + dy * dy + dz * dz;
                    inv[i] = if d2[i] > 0.0 { 1.0 / d2[i].sqrt() } else { 0.0 };
                    vp.x[i] = dx * inv[i];
                    vp.y[i] = dy * inv[i];
                    vp.z[i] = dz * inv[i];
                }
                if !l.no_att {
                    // Attenuation, positional lights only.
                    for i in 0..N {
                        let dist = d2[i] * inv[i];
                        kf[i] = 1.0 / (l.att[0] + l.att[1] * dist + l.att[2] * d2[i]);
                    }
                }
            }
            if let Some(cos_cut) = l.spot_cos {
                // The spot factor's powers, lanes inside the cone (`need`) at once.
                let mut base = [0.0f32; N];
                let mut need = 0u32;
                for i in 0..N {
                    let sd = l.spot_dir;
                    let cosang = -vp.x[i] * sd.x + -vp.y[i] * sd.y + -vp.z[i] * sd.z;
                    if cosang >= cos_cut {
                        base[i] = cosang.max(0.0);
                        need |= 1 << i;
                    } else {
                        // Outside the cone the light contributes nothing at all.
                        on[i] = false;
                    }
                }
                let mut pw = [0.0f32; N];
                powf_lanes(&base, l.spot_exp, need, &mut pw);
                for i in 0..N {
                    if need & (1 << i) != 0 {
                        kf[i] *= pw[i];
                    }
                }
            }
            let mut ndl = [0.0f32; N];
            let mut ndh = [0.0f32; N];
            for i in 0..N {
                ndl[i] = nrm.x[i] * vp.x[i] + nrm.y[i] * vp.y[i] + nrm.z[i] * vp.z[i];
                let (hx, hy, hz) =
                    normalize_or_zero(vp.x[i] + eye.x[i], vp.y[i] + eye.y[i], vp.z[i] + eye.z[i]);
                let d = nrm.x[i] * hx + nrm.y[i] * hy + nrm.z[i] * hz;
                ndh[i] = if d > 0.0 { d } else { 0.0 };
            }
            let (la, ld, ls) = (l.ambient, l.diffuse, l.specular);
            // The ambient and diffuse parts of the term: a + (N·L)·d.
            let mut ad = Lanes3::<N>::splat(Vec3::ZERO);
            for i in 0..N {
                ad.x[i] = la.x * acm.x[i] + ndl[i] * ld.x * dcm.x[i];
                ad.y[i] = la.y * acm.y[i] + ndl[i] * ld.y * dcm.y[i];
                ad.z[i] = la.z * acm.z[i] + ndl[i] * ld.z * dcm.z[i];
            }
            // Where `powf` need not run (its lane keeps pw = 0, giving the same colour bits):
            // - a zero specular colour times a finite power (N·H <= 1) is a zero term;
            // - 0^srm = 0 for srm > 0;
            // - the power is negligible next to a + (N·L)·d, which the addition of the specular
            //   term then returns unchanged (not under SEPARATE_SPECULAR_COLOR, where that term
            //   is summed on its own): see `negligible`.
            let spec_zero = l.spec_zero || (scm_zero && l.spec_finite);
            let may_neglect = !self.separate && l.spec_small && scm_small;
            let mut pw = [0.0f32; N];
            let mut need = 0u32;
            for i in 0..N {
                let x = ndh[i];
                let zero = (x == 0.0 && shininess > 0.0) || (spec_zero && x <= 1.0);
                let small = may_neglect && negligible(x, shininess, [ad.x[i], ad.y[i], ad.z[i]]);
                // Specular only where N·L > 0.
                if ndl[i] > 0.0 && !zero && !small {
                    need |= 1 << i;
                }
            }
            powf_lanes(&ndh, shininess, need, &mut pw);
            // Branch-free so that it vectorises: every term is computed, then selected; the
            // loop compiled for the light's case (`accumulate`).
            let plain = l.spot_cos.is_none() && (!l.positional || l.no_att);
            let t = Terms {
                ndl: &ndl,
                pw: &pw,
                ad: &ad,
                acm: &acm,
                scm: &scm,
                la,
                ls,
                kf: &kf,
                on: &on,
            };
            match (self.separate, plain) {
                (false, true) => t.accumulate::<false, true>(&mut c, &mut s),
                (false, false) => t.accumulate::<false, false>(&mut c, &mut s),
                (true, true) => t.accumulate::<true, true>(&mut c, &mut s),
                (true, false) => t.accumulate::<true, false>(&mut c, &mut s),
            }
        }
        // Colours are clamped after lighting (§2.14.6); alpha is the diffuse alpha.
        for i in 0..N {
            out.c.x[i] = clamp01(c.x[i]);
            out.c.y[i] = clamp01(c.y[i]);
            out.c.z[i] = clamp01(c.z[i]);
            out.a[i] = clamp01(alpha[i]);
        }
        if self.separate {
            for i in 0..N {
                out.s.x[i] = clamp01(s.x[i]);
                out.s.y[i] = clamp01(s.y[i]);
                out.s.z[i] = clamp01(s.z[i]);
            }
        } else {
            // Without SEPARATE_SPECULAR_COLOR the secondary sum stays +0, which the clamp keeps.
            out.s = s;
        }
    }
}

/// One light's terms across `N` points, for [`Terms::accumulate`]: N·L, the specular powers
/// (0 where `powf` was skipped), the ambient and diffuse parts a + (N·L)·d, the ambient and
/// specular material colours, the light's ambient and specular colours, the attenuation and
/// spot factor, and whether the light reaches each point (inside its spot cone).
struct Terms<'a, const N: usize> {
    ndl: &'a [f32; N],
    pw: &'a [f32; N],
    ad: &'a Lanes3<N>,
    acm: &'a Lanes3<N>,
    scm: &'a Lanes3<N>,
    la: Vec3A,
    ls: Vec3A,
    kf: &'a [f32; N],
    on: &'a [bool; N],
}

impl<const N: usize> Terms<'_, N> {
    /// Adds the light's term to the primary sums `c` (and its specular part to the secondary
    /// sums `s` under SEPARATE_SPECULAR_COLOR, `SEP`). `PLAIN`: a light without attenuation or
    /// spot, whose factor is 1 and which reaches every point, adds its term as it is: 1·t is t
    /// bit for bit (t is the result of arithmetic, so a NaN there is quiet and kept), and the
    /// selection by `on` keeps the sum. Without `SEP` the secondary sums are left alone (they
    /// stay zero), where they took a product, a sum and a selection a component.
    // Lane loops index several arrays in lockstep (structure of arrays): indices read best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn accumulate<const SEP: bool, const PLAIN: bool>(&self, c: &mut Lanes3<N>, s: &mut Lanes3<N>) {
        let (la, ls, acm, scm, ad) = (self.la, self.ls, self.acm, self.scm, self.ad);
        for i in 0..N {
            let lit = self.ndl[i] > 0.0;
            let d = self.pw[i];
            let sx = d * ls.x * scm.x[i];
            let sy = d * ls.y * scm.y[i];
            let sz = d * ls.z * scm.z[i];
            // term = a (+ (N·L)·d (+ s unless separate)) where N·L > 0.
            let ax = la.x * acm.x[i];
            let ay = la.y * acm.y[i];
            let az = la.z * acm.z[i];
            let (lx, ly, lz) = if SEP {
                (ad.x[i], ad.y[i], ad.z[i])
            } else {
                (ad.x[i] + sx, ad.y[i] + sy, ad.z[i] + sz)
            };
            let (tx, ty, tz) = if lit { (lx, ly, lz) } else { (ax, ay, az) };
            let k = self.kf[i];
            let on = self.on[i];
            if PLAIN {
                c.x[i] += tx;
                c.y[i] += ty;
                c.z[i] += tz;
            } else {
                c.x[i] = if on { c.x[i] + k * tx } else { c.x[i] };
                c.y[i] = if on { c.y[i] + k * ty } else { c.y[i] };
                c.z[i] = if on { c.z[i] + k * tz } else { c.z[i] };
            }
            if SEP {
                let add = on && lit;
                s.x[i] = if add { s.x[i] + k * sx } else { s.x[i] };
                s.y[i] = if add { s.y[i] + k * sy } else { s.y[i] };
                s.z[i] = if add { s.z[i] + k * sz } else { s.z[i] };
            }
        }
    }
}

/// Whether adding a specular term `sp = (x^srm · scl) · scm` (rounded as `f32`s), with
/// |scl|, |scm| <= 1 and 0 <= x, to each component of `y` leaves every component's bits unchanged,
/// so that `x.powf(srm)` need not be evaluated. Sound, not tight (x <= 1 throughout):
/// - with 2^e <= |y| (e >= -90, from the exponent bits; NaN and infinite components stay what
///   they are), a term with |sp| <= 2^(e-26) is below half the float spacing around y, even just
///   under a power of two, so y + sp rounds to y;
/// - |sp| <= x^srm·(1 + 2^-23) (products of factors at most 1 only round down in magnitude, and
///   `powf` is within an ulp), so x^srm <= 2^(e-27) suffices;
/// - ln x <= 2(x - 1)/(x + 1) for 0 < x <= 1 (equal at 1, and the difference grows with x), so
///   x^srm <= 2^(e-27) when srm·(1 - x) >= (27 - e)·(ln 2 / 2)·(1 + x); the test uses 0.36 for
///   ln 2 / 2 = 0.3466, a 3.9% margin far above the rounding of the test itself.
#[inline(always)]
pub(super) fn negligible(x: f32, srm: f32, y: [f32; 3]) -> bool {
    // Biased exponents: 2^(b - 127) <= |y| for normal y; 255 (NaN, infinity) is never the minimum
    // that matters, as NaN + sp and inf + sp return the NaN or infinity.
    let b = y.map(|v| (v.to_bits() >> 23) & 0xff);
    let b = b[0].min(b[1]).min(b[2]);
    // e = b - 127 >= -90, and 27 - e = 154 - b.
    x <= 1.0 && b >= 37 && srm * (1.0 - x) >= (154 - b as i32) as f32 * 0.36 * (1.0 + x)
}

/// The per-flush transform state.
#[derive(Clone, Debug)]
pub struct Transform {
    mv: Mat4,
    proj: Mat4,
    normal: Mat3,
    normalize: bool,
}

impl Transform {
    /// Matrices of `state`: the normal matrix is the inverse transpose of the modelview's upper
    /// 3x3 (GL 2.1 §2.11.3), times the RESCALE_NORMAL factor when that is enabled.
    pub fn new(state: &State) -> Self {
        let mv = *state.modelview.top();
        let inv = Mat3::from_mat4(mv).inverse();
        let mut normal = inv.transpose();
        if state.enables.rescale_normal {
            // §2.11.3: f = 1 / sqrt(m31² + m32² + m33²), m the entries of the inverse.
            let row3 = inv.row(2);
            normal *= 1.0 / row3.length();
        }
        Transform {
            mv,
            proj: *state.projection.top(),
            normal,
            normalize: state.enables.normalize,
        }
    }
}

/// Runs the vertex stage over the whole batch into `out` (`layout.stride` floats per vertex),
/// and each vertex's clip code and window coordinates into `wins`; `parallel` splits a large
/// batch across the thread pool.
pub fn process(
    state: &State,
    batch: &Batch,
    layout: &Layout,
    setup: &SetupCtx,
    out: &mut Vec<f32>,
    wins: &mut Vec<Win>,
    parallel: bool,
) {
    run(
        state,
        batch,
        layout,
        setup,
        out,
        wins,
        parallel,
        true,
        Route::best(),
    );
}

/// The clip positions (and eye positions where `layout` has them) and window coordinates of
/// `batch`'s vertices, as [`process`] computes them, without colours, lighting or any other
/// attribute: for selection ([`Layout::for_select`]).
pub fn positions(
    state: &State,
    batch: &Batch,
    layout: &Layout,
    setup: &SetupCtx,
    out: &mut Vec<f32>,
    wins: &mut Vec<Win>,
) {
    run(
        state,
        batch,
        layout,
        setup,
        out,
        wins,
        false,
        false,
        Route::best(),
    );
}

/// How the vertex stage's lane loops are compiled: for the x86-64 baseline (SSE2, four `f32`
/// lanes a vector), or with AVX2 (eight), chosen once at run time. Both are the same Rust code,
/// operation for operation (AVX2 alone enables no fused multiply-add), so the same bits; the
/// test `both_routes_process_the_same_bits` compares them on random batches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// The baseline build.
    Baseline,
    /// The AVX2 build of the same code (only where the CPU has AVX2).
    Avx2,
}

impl Route {
    /// AVX2 where the CPU has it, else the baseline (std caches the detection: a load and a
    /// bit test).
    #[inline]
    pub fn best() -> Self {
        #[cfg(target_arch = "x86_64")]
        if is_x86_feature_detected!("avx2") {
            return Route::Avx2;
        }
        Route::Baseline
    }
}

/// [`process`] (`attributes`) or [`positions`] by `route` (for the test comparing the routes).
#[cfg(test)]
#[allow(clippy::too_many_arguments)]
pub fn process_by(
    state: &State,
    batch: &Batch,
    layout: &Layout,
    setup: &SetupCtx,
    out: &mut Vec<f32>,
    wins: &mut Vec<Win>,
    attributes: bool,
    route: Route,
) {
    run(
        state, batch, layout, setup, out, wins, false, attributes, route,
    );
}

#[allow(clippy::too_many_arguments)]
fn run(
    state: &State,
    batch: &Batch,
    layout: &Layout,
    setup: &SetupCtx,
    out: &mut Vec<f32>,
    wins: &mut Vec<Win>,
    parallel: bool,
    attributes: bool,
    route: Route,
) {
    let n = batch.len();
    // Every float of `out` (`Lit::run` writes each attribute of the layout for every vertex) and
    // every element of `wins` (one per vertex) is overwritten below, so the previous flush's
    // elements are kept rather than cleared: only new ones are initialised.
    out.resize(n * layout.stride, 0.0);
    wins.resize(n, Win::default());
    let tf = Transform::new(state);
    let lighting = (attributes && state.enables.lighting).then(|| Lighting::new(state));
    let lit = Lit {
        state,
        batch,
        layout,
        tf: &tf,
        lighting: lighting.as_ref(),
        setup,
        attributes,
        route,
    };
    // Split from two chunks on. A lit vertex costs ≈400–550 instructions (texture-targets'
    // height field and spheres, 3136–4704 vertices a flush; render-to-texture's teapot), so a
    // lit flush of a few thousand vertices is worth the pool's wake-up (tens of µs) while
    // the pool would otherwise idle; an unlit vertex costs a fraction of that and keeps the
    // larger chunks. The output is the same bits on either side of a split.
    let chunk = if lighting.is_some() { 1024 } else { 4096 };
    if parallel && n >= 2 * chunk {
        out.par_chunks_mut(chunk * layout.stride)
            .zip(wins.par_chunks_mut(chunk))
            .enumerate()
            .for_each(|(c, (part, w))| lit.run(c * chunk, part, w));
    } else {
        lit.run(0, out, wins);
    }
}

/// One carried texture unit of a flush: where its coordinates go in a processed vertex, its
/// TexGen (§2.11.4) and its texture matrix (§2.11.2).
#[derive(Clone, Copy, Debug, Default)]
struct TexOut {
    at: usize,
    unit: usize,
    gen: Option<super::texgen::TexGenEval>,
    matrix: Mat4,
}

struct Lit<'a> {
    state: &'a State,
    batch: &'a Batch,
    layout: &'a Layout,
    tf: &'a Transform,
    lighting: Option<&'a Lighting>,
    setup: &'a SetupCtx,
    /// Colours and the layout's other attributes are computed (not for [`positions`]).
    attributes: bool,
    /// The build of the lane loops to run.
    route: Route,
}

impl Lit<'_> {
    /// Processes the vertices from `first` into `out` and `wins` ([`Lit::body`]) by `route`.
    fn run(&self, first: usize, out: &mut [f32], wins: &mut [Win]) {
        #[cfg(target_arch = "x86_64")]
        if self.route == Route::Avx2 {
            // SAFETY: `Route::Avx2` is chosen only where the CPU has AVX2 (`Route::best`; the
            // test asks for it only after detecting it).
            unsafe { self.run_avx2(first, out, wins) };
            return;
        }
        self.body::<false>(first, out, wins);
    }

    /// [`Lit::body`] compiled with AVX2: its lane loops on eight `f32` lanes a vector.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_avx2(&self, first: usize, out: &mut [f32], wins: &mut [Win]) {
        self.body::<true>(first, out, wins);
    }

    /// Processes the vertices from `first` into `out` and `wins`, one block of [`LANES`] at a
    /// time in a single pass: transforms on a structure of arrays, window coordinates and clip
    /// codes from the clip positions in hand, the other attributes, then lighting. `AVX2`: the
    /// body is compiled inside `run_avx2` (so on a CPU with AVX2), where a whole lit block's
    /// outputs are written through `lanes::put_clip_col_avx2`.
    // Lane loops index several arrays in lockstep (structure of arrays): indices read best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn body<const AVX2: bool>(&self, first: usize, out: &mut [f32], wins: &mut [Win]) {
        let l = self.layout;
        let b = self.batch;
        let state = self.state;
        let tf = self.tf;
        let uniform = b.snapshots.is_empty();
        // The vertex colour is read only where an output or COLOR_MATERIAL needs it.
        let need_attribs = self.attributes
            && (self.lighting.map_or(true, |g| g.color_material.is_some())
                || l.tex.iter().any(Option::is_some)
                || l.fog.is_some()
                || l.psize.is_some()
                || l.raw.is_some());
        // The carried units only, in unit order: a vertex pays for the units in use.
        let mut units = [TexOut::default(); MAX_TEXTURE_UNITS];
        let mut n_units = 0;
        for (u, at) in l.tex.iter().enumerate() {
            if let (Some(at), Some(dst)) = (at, units.get_mut(n_units)) {
                *dst = TexOut {
                    at: *at,
                    unit: u,
                    gen: super::texgen::TexGenEval::new(state, u),
                    matrix: *state.texture_matrix[u].top(),
                };
                n_units += 1;
            }
        }
        let units = &units[..n_units];
        // The lit colours of a block: every lane is rewritten for each block (in a non-uniform
        // block, every lane that is read), so they are initialised once.
        let mut lit = Shaded::<LANES>::default();
        let mut lit_b = Shaded::<LANES>::default();
        // The points to light; each block rewrites their positions and normals, and their
        // colours where `extras` reads them (the lanes past a block's last vertex are not used).
        let mut pts = Block::<LANES>::default();
        // A block's positions and normals, every lane rewritten for each block.
        let mut p = Lanes4::<LANES>::splat(Vec4::ZERO);
        let mut nr = Lanes3::<LANES>::splat(Vec3::ZERO);
        let blocks = out.chunks_mut(l.stride * LANES).zip(wins.chunks_mut(LANES));
        for (blk, (os, ws)) in blocks.enumerate() {
            let base = first + blk * LANES;
            // `os` holds as many vertices as `ws`.
            let cnt = ws.len();
            let (Some(pos), Some(nin)) = (
                b.pos().get(base..base + cnt),
                b.normal().get(base..base + cnt),
            ) else {
                return;
            };
            // Lanes past `cnt` (in a batch's last block) repeat its first vertex; their results
            // are not used.
            let (Some(q0), Some(m0)) = (pos.first(), nin.first()) else {
                return;
            };
            // A whole block on AVX2: transposed in registers (`lanes::load_block_avx2`).
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `AVX2` is true only in `run_avx2`, which runs where the CPU has AVX2.
            let loaded = AVX2 && unsafe { lanes::load_block_avx2(pos, nin, &mut p, &mut nr) };
            #[cfg(not(target_arch = "x86_64"))]
            let loaded = false;
            if !loaded {
                if cnt < LANES {
                    p = Lanes4::splat(*q0);
                    nr = Lanes3::splat(*m0);
                }
                for (k, (q, m)) in pos.iter().zip(nin).enumerate().take(LANES) {
                    (p.x[k], p.y[k], p.z[k], p.w[k]) = (q.x, q.y, q.z, q.w);
                    (nr.x[k], nr.y[k], nr.z[k]) = (m.x, m.y, m.z);
                }
            }
            let eye = p.transform(&tf.mv);
            let clip = eye.transform(&tf.proj);
            // The window records: on AVX2 a whole block's through `super::lanes::put_wins_avx2`.
            let win = self.setup.win_lanes(&clip, &eye);
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `AVX2` is true only in `run_avx2`, which runs where the CPU has AVX2.
            let put = AVX2 && unsafe { super::lanes::put_wins_avx2(&win, ws) };
            #[cfg(not(target_arch = "x86_64"))]
            let put = false;
            if !put {
                win.put(ws);
            }
            if need_attribs {
                for (k, o) in os.chunks_exact_mut(l.stride).enumerate() {
                    let Some(a) = b.attribs(base + k) else {
                        return;
                    };
                    if let Some(c) = pts.color.get_mut(k) {
                        *c = a.color;
                    }
                    self.extras(o, a, pos[k], nin[k], eye.get(k), units);
                }
            }
            if let Some(lighting) = self.lighting {
                pts.v = eye.xyz();
                // The normal transform (glam's Mat3 * Vec3, operation for operation), then
                // NORMALIZE (§2.11.3), written in place.
                let m = tf.normal.to_cols_array();
                let n = &mut pts.n;
                for i in 0..LANES {
                    n.x[i] = m[0] * nr.x[i] + m[3] * nr.y[i] + m[6] * nr.z[i];
                    n.y[i] = m[1] * nr.x[i] + m[4] * nr.y[i] + m[7] * nr.z[i];
                    n.z[i] = m[2] * nr.x[i] + m[5] * nr.y[i] + m[8] * nr.z[i];
                }
                if tf.normalize {
                    for i in 0..LANES {
                        (n.x[i], n.y[i], n.z[i]) = normalize_or_zero(n.x[i], n.y[i], n.z[i]);
                    }
                }
                // The eye position divided by w; dividing by w = 1 is exact (the common affine
                // modelview skips it), and w = 0 is kept.
                if !eye.w.iter().fold(true, |a, &w| a & (w == 1.0)) {
                    let v = &mut pts.v;
                    for i in 0..LANES {
                        let w = eye.w[i];
                        if w != 0.0 && w != 1.0 {
                            v.x[i] = eye.x[i] / w;
                            v.y[i] = eye.y[i] / w;
                            v.z[i] = eye.z[i] / w;
                        }
                    }
                }
                if let Some(no) = l.nrm {
                    for (k, o) in os.chunks_exact_mut(l.stride).enumerate() {
                        put3(o, no, pts.n.get(k));
                    }
                }
                // Materials: the state's for the whole block, or each vertex's own snapshot.
                let mat_of = |i: usize| {
                    b.mat
                        .get(i)
                        .and_then(|&m| b.snapshots.get(m as usize))
                        .unwrap_or(&state.materials)
                };
                let two = l.col_b.is_some();
                if uniform {
                    let m = &state.materials;
                    lighting.shade_lanes(&m[FRONT], FRONT, &pts, &mut lit);
                    if two {
                        lighting.shade_lanes(&m[BACK], BACK, &pts.back(), &mut lit_b);
                    }
                } else {
                    for k in 0..cnt {
                        let m = mat_of(base + k);
                        let p = pts.one(k);
                        let mut one = Shaded::<1>::default();
                        lighting.shade_lanes(&m[FRONT], FRONT, &p, &mut one);
                        lit.set_from(k, &one);
                        if two {
                            lighting.shade_lanes(&m[BACK], BACK, &p.back(), &mut one);
                            lit_b.set_from(k, &one);
                        }
                    }
                }
            }
            // The clip (and eye) position, and the lit colours (`extras` wrote the unlit ones).
            let lit_on = self.lighting.is_some();
            // A whole lit block on AVX2: the clip positions and primary colours (the first
            // eight floats of each vertex) transposed in registers, the rest below.
            #[cfg(target_arch = "x86_64")]
            let wrote = AVX2
                && lit_on
                && cnt == LANES
                && l.col == 4
                // SAFETY: `AVX2` is true only in `run_avx2`, which runs where the CPU has AVX2.
                && unsafe { lanes::put_clip_col_avx2(os, l.stride, &clip, &lit.c, &lit.a) };
            #[cfg(not(target_arch = "x86_64"))]
            let wrote = false;
            let rest = l.eye.is_some() || l.spec.is_some() || l.col_b.is_some();
            if !wrote || rest {
                for (k, o) in os.chunks_exact_mut(l.stride).enumerate().take(LANES) {
                    if !wrote {
                        put_arr(o, 0, [clip.x[k], clip.y[k], clip.z[k], clip.w[k]]);
                    }
                    if let Some(o_eye) = l.eye {
                        put_arr(o, o_eye, [eye.x[k], eye.y[k], eye.z[k], eye.w[k]]);
                    }
                    if lit_on {
                        lit.put(k, o, (!wrote).then_some(l.col), l.spec);
                        if let Some(cb) = l.col_b {
                            lit_b.put(k, o, Some(cb), l.spec_b);
                        }
                    }
                }
            }
        }
    }

    /// The outputs of one vertex other than position and lit colours: texture coordinates, fog
    /// coordinate, the unlit colours (lighting off) or the raw colour (PHONG_WIN).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn extras(
        &self,
        o: &mut [f32],
        a: &super::batch::Attribs,
        p: Vec4,
        nrm: Vec3,
        eye: Vec4,
        units: &[TexOut],
    ) {
        let l = self.layout;
        let tf = self.tf;
        let (color, color2) = (a.color, a.color2);
        // TexGen (§2.11.4), then the texture matrix (§2.11.2)
        for t in units {
            let tc = a.tex.get(t.unit).copied().unwrap_or(Vec4::ZERO);
            let tc = match &t.gen {
                Some(g) => {
                    let mut n = tf.normal * nrm;
                    if g.needs_normal && tf.normalize {
                        n = n.normalize_or_zero();
                    }
                    g.apply(tc, p, eye, n)
                }
                None => tc,
            };
            put(o, t.at, t.matrix * tc);
        }
        // The fog coordinate (§3.10), |z_eye| for FRAGMENT_DEPTH as
        // Mesa's EYE_PLANE_ABSOLUTE default; |fog coordinate| otherwise, as Mesa.
        if let Some(f) = l.fog {
            let c = if self.state.fog.coord_src == gl::FOG_COORD {
                a.fog
            } else {
                eye.z
            };
            if let Some(d) = o.get_mut(f) {
                *d = c.abs();
            }
        }
        // The attenuated point size (§3.3 eq. 3.1) as Mesa's fixed-function vertex program
        // computes it: size / sqrt(a + b·|z_eye| + c·z_eye²), clamped to POINT_SIZE_MIN and
        // POINT_SIZE_MAX bounded by the implementation's 1 and 255 (llvmpipe ignores
        // POINT_FADE_THRESHOLD_SIZE, measured).
        if let Some(ps) = l.psize {
            let pp = &self.state.point;
            let [pa, pb, pc] = pp.distance_attenuation;
            let d = eye.z.abs();
            let f = d * pc + pb;
            let f = d * f + pa;
            let s = (1.0 / f.sqrt()) * self.state.point_size;
            let lo = if pp.size_min >= 1.0 { pp.size_min } else { 1.0 };
            let hi = if pp.size_max <= 255.0 {
                pp.size_max
            } else {
                255.0
            };
            if let Some(dst) = o.get_mut(ps) {
                *dst = s.max(lo).min(hi);
            }
        }
        if self.lighting.is_none() {
            put(o, l.col, color.clamp(Vec4::ZERO, Vec4::ONE));
            if let Some(s) = l.spec {
                put(o, s, color2.clamp(Vec4::ZERO, Vec4::ONE));
            }
        }
        if let Some(r) = l.raw {
            put(o, r, color);
        }
    }
}

#[inline(always)]
fn put(o: &mut [f32], at: usize, v: Vec4) {
    if let Some(d) = o.get_mut(at..at + 4) {
        d.copy_from_slice(&v.to_array());
    }
}

#[inline(always)]
fn put3(o: &mut [f32], at: usize, v: Vec3) {
    if let Some(d) = o.get_mut(at..at + 3) {
        d.copy_from_slice(&v.to_array());
    }
}
