//! The vertex stage: modelview and projection transforms, the normal transform with
//! RESCALE_NORMAL / NORMALIZE, and the GL 1.x lighting equation (GL 2.1 §2.11, §2.14.1).
//!
//! Design decision: `Lighting::shade_block` is the one implementation of the lighting equation;
//! the vertex stage calls it for blocks of 8 vertices and the PHONG_WIN fragment path (through
//! `Lighting::shade`) for single fragments, so the two shading modes can never disagree about the
//! equation. Results are written to one flat `f32` array with a per-flush `Layout`, carrying only
//! the attributes the flush needs, plus each vertex's clip code and window coordinates.

use glam::{Mat3, Mat4, Vec3, Vec3A, Vec4, Vec4Swizzles};
use rayon::prelude::*;

use super::batch::Batch;
use super::setup::{SetupCtx, Win};
use crate::gl;
use crate::state::{Material, State, BACK, FRONT, MAX_LIGHTS};

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
    /// Texture coordinates of unit 0.
    pub tex: Option<usize>,
    // --- texture
    /// Texture coordinates of unit 1 (when TEXTURE_2D is enabled there).
    pub tex1: Option<usize>,
    // --- end texture
    /// Eye-space position (x, y, z, w), for user clip planes and per-fragment lighting.
    pub eye: Option<usize>,
    /// Eye-space normal (after rescale/normalize), for per-fragment lighting.
    pub nrm: Option<usize>,
    /// Unlit vertex colour, for COLOR_MATERIAL under per-fragment lighting.
    pub raw: Option<usize>,
    // --- fragment ops
    /// Fog coordinate c (one float), when FOG is enabled (§3.10).
    pub fog: Option<usize>,
    // --- end fragment ops
}

impl Layout {
    /// The layout `state` needs.
    pub fn for_state(state: &State) -> Self {
        let lit = state.enables.lighting;
        let phong = lit && state.shade_model == gl::PHONG_WIN;
        let spec = (lit && state.light_model.color_control == gl::SEPARATE_SPECULAR_COLOR)
            || state.enables.color_sum;
        let two = lit && state.light_model.two_side;
        let tex = state.enables.texture_2d[0] || state.enables.texture_1d[0];
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
        if tex {
            l.tex = take(4);
        }
        // --- texture
        if state.enables.texture_2d[1] {
            l.tex1 = take(4);
        }
        // --- end texture
        if phong || user {
            l.eye = take(4);
        }
        if phong {
            l.nrm = take(3);
            l.raw = take(4);
        }
        // --- fragment ops
        if state.enables.fog {
            l.fog = take(1);
        }
        // --- end fragment ops
        l.stride = n;
        l
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
    pub fn shade(&self, m: &Material, face: usize, color: Vec4, v: Vec3, n: Vec3) -> (Vec4, Vec4) {
        let mut out = [(Vec4::ZERO, Vec4::ZERO)];
        let p = Point {
            v: v.into(),
            n: n.into(),
            color,
        };
        self.shade_block(m, face, &[p], &mut out);
        out[0]
    }

    /// [`Lighting::shade`] for up to [`LANES`] points at once (the rest of `pts` is ignored):
    /// the same equation, evaluated step by step across the points so that the square roots,
    /// divisions and `powf`s of different points overlap in the CPU.
    pub fn shade_block(&self, m: &Material, face: usize, pts: &[Point], out: &mut [(Vec4, Vec4)]) {
        let k = pts.len().min(out.len()).min(LANES);
        let pts = &pts[..k];
        // §2.14.3: COLOR_MATERIAL replaces the tracked property with the vertex colour.
        let tracked = self
            .color_material
            .and_then(|(faces, mode)| faces.get(face).copied().unwrap_or(false).then_some(mode));
        let mut acm = [Vec3A::ZERO; LANES];
        let mut dcm = [Vec3A::ZERO; LANES];
        let mut scm = [Vec3A::ZERO; LANES];
        let mut alpha = [0.0f32; LANES];
        let mut c = [Vec3A::ZERO; LANES];
        let mut s = [Vec3A::ZERO; LANES];
        let mut eye = [Vec3A::Z; LANES];
        for (i, p) in pts.iter().enumerate() {
            let (mut a, mut d, mut sp, mut e) = (m.ambient, m.diffuse, m.specular, m.emission);
            match tracked {
                None => {}
                Some(gl::AMBIENT) => a = p.color,
                Some(gl::DIFFUSE) => d = p.color,
                Some(gl::SPECULAR) => sp = p.color,
                Some(gl::EMISSION) => e = p.color,
                Some(_) => {
                    a = p.color;
                    d = p.color;
                }
            }
            acm[i] = a.xyz().into();
            dcm[i] = d.xyz().into();
            scm[i] = sp.xyz().into();
            alpha[i] = d.w;
            c[i] = Vec3A::from(e.xyz()) + self.scene_ambient * acm[i];
            if self.local_viewer {
                // Local viewer: the half vector uses the direction to the eye.
                eye[i] = (-p.v).normalize_or_zero();
            }
        }
        for l in &self.srcs[..self.n] {
            let mut vp = [l.vp_dir; LANES];
            let mut kf = [1.0f32; LANES];
            let mut on = [true; LANES];
            if l.positional {
                for (i, p) in pts.iter().enumerate() {
                    let d = l.pos - p.v;
                    let d2 = d.length_squared();
                    let inv = if d2 > 0.0 { 1.0 / d2.sqrt() } else { 0.0 };
                    vp[i] = d * inv;
                    if !l.no_att {
                        // Attenuation, positional lights only.
                        let dist = d2 * inv;
                        kf[i] = 1.0 / (l.att[0] + l.att[1] * dist + l.att[2] * d2);
                    }
                }
            }
            if let Some(cos_cut) = l.spot_cos {
                for i in 0..k {
                    let cosang = (-vp[i]).dot(l.spot_dir);
                    if cosang >= cos_cut {
                        kf[i] *= cosang.max(0.0).powf(l.spot_exp);
                    } else {
                        // Outside the cone the light contributes nothing at all.
                        on[i] = false;
                    }
                }
            }
            let mut ndl = [0.0f32; LANES];
            let mut ndh = [0.0f32; LANES];
            for (i, p) in pts.iter().enumerate() {
                ndl[i] = p.n.dot(vp[i]);
                let h = (vp[i] + eye[i]).normalize_or_zero();
                ndh[i] = p.n.dot(h).max(0.0);
            }
            let mut pw = [0.0f32; LANES];
            for i in 0..k {
                // Specular only where N·L > 0.
                if ndl[i] > 0.0 {
                    pw[i] = ndh[i].powf(m.shininess);
                }
            }
            for i in 0..k {
                if !on[i] {
                    continue;
                }
                let mut term = l.ambient * acm[i];
                if ndl[i] > 0.0 {
                    term += ndl[i] * l.diffuse * dcm[i];
                    let sp = pw[i] * l.specular * scm[i];
                    if self.separate {
                        s[i] += kf[i] * sp;
                    } else {
                        term += sp;
                    }
                }
                c[i] += kf[i] * term;
            }
        }
        // Colours are clamped after lighting (§2.14.6); alpha is the diffuse alpha.
        for (i, o) in out.iter_mut().take(k).enumerate() {
            *o = (
                Vec3::from(c[i])
                    .extend(alpha[i])
                    .clamp(Vec4::ZERO, Vec4::ONE),
                Vec3::from(s[i]).extend(0.0).clamp(Vec4::ZERO, Vec4::ONE),
            );
        }
    }
}

/// Points lit together by [`Lighting::shade_block`].
pub const LANES: usize = 8;

/// One point to light: eye position, unit normal (negated for a back face), vertex colour.
#[derive(Clone, Copy, Debug, Default)]
pub struct Point {
    /// Eye-space position.
    pub v: Vec3A,
    /// Normal.
    pub n: Vec3A,
    /// Vertex colour (COLOR_MATERIAL).
    pub color: Vec4,
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
/// and each vertex's clip code and window coordinates into `wins`.
pub fn process(
    state: &State,
    batch: &Batch,
    layout: &Layout,
    setup: &SetupCtx,
    out: &mut Vec<f32>,
    wins: &mut Vec<Win>,
) {
    let n = batch.len();
    out.clear();
    out.resize(n * layout.stride, 0.0);
    wins.clear();
    wins.resize(n, Win::default());
    let tf = Transform::new(state);
    let lighting = state.enables.lighting.then(|| Lighting::new(state));
    let lit = Lit {
        state,
        batch,
        layout,
        tf: &tf,
        lighting: lighting.as_ref(),
        setup,
    };
    const CHUNK: usize = 4096;
    if n > 2 * CHUNK {
        out.par_chunks_mut(CHUNK * layout.stride)
            .zip(wins.par_chunks_mut(CHUNK))
            .enumerate()
            .for_each(|(c, (chunk, w))| lit.run(c * CHUNK, chunk, w));
    } else {
        lit.run(0, out, wins);
    }
}

struct Lit<'a> {
    state: &'a State,
    batch: &'a Batch,
    layout: &'a Layout,
    tf: &'a Transform,
    lighting: Option<&'a Lighting>,
    setup: &'a SetupCtx,
}

impl Lit<'_> {
    fn run(&self, first: usize, out: &mut [f32], wins: &mut [Win]) {
        self.shade_all(first, out);
        for (o, w) in out.chunks_exact(self.layout.stride).zip(wins) {
            *w = self.setup.win(o);
        }
    }

    fn shade_all(&self, first: usize, out: &mut [f32]) {
        let l = self.layout;
        let b = self.batch;
        let state = self.state;
        let uniform = b.snapshots.is_empty();
        // --- texture
        let tex_matrix = *state.texture_matrix[0].top();
        let texgen = l.tex.and_then(|_| super::texgen::TexGen::new(state, 0));
        let tex_matrix1 = *state.texture_matrix[1].top();
        let texgen1 = l.tex1.and_then(|_| super::texgen::TexGen::new(state, 1));
        // --- end texture
        for (blk, os) in out.chunks_mut(l.stride * LANES).enumerate() {
            let base = first + blk * LANES;
            let mut pts = [Point::default(); LANES];
            let mut cnt = 0;
            for (k, o) in os.chunks_exact_mut(l.stride).enumerate() {
                let i = base + k;
                let (Some(&p), Some(&nrm), Some(a)) = (b.pos.get(i), b.normal.get(i), b.attribs(i))
                else {
                    return;
                };
                let (color, color2) = (a.color, a.color2);
                let eye = self.tf.mv * p;
                let clip = self.tf.proj * eye;
                put(o, 0, clip);
                if let Some(o_eye) = l.eye {
                    put(o, o_eye, eye);
                }
                if let (Some(t), tc) = (l.tex, a.tex) {
                    // --- texture: TexGen (§2.11.4), then the texture matrix (§2.11.2)
                    let tc = match &texgen {
                        Some(g) => {
                            let mut n = self.tf.normal * nrm;
                            if g.needs_normal && self.tf.normalize {
                                n = n.normalize_or_zero();
                            }
                            g.apply(tc, p, eye, n)
                        }
                        None => tc,
                    };
                    put(o, t, tex_matrix * tc);
                }
                if let (Some(t), tc) = (l.tex1, a.tex1) {
                    let tc = match &texgen1 {
                        Some(g) => {
                            let mut n = self.tf.normal * nrm;
                            if g.needs_normal && self.tf.normalize {
                                n = n.normalize_or_zero();
                            }
                            g.apply(tc, p, eye, n)
                        }
                        None => tc,
                    };
                    put(o, t, tex_matrix1 * tc);
                    // --- end texture
                }
                // --- fragment ops: the fog coordinate (§3.10), |z_eye| for FRAGMENT_DEPTH as
                // Mesa's EYE_PLANE_ABSOLUTE default; |fog coordinate| otherwise, as Mesa.
                if let Some(f) = l.fog {
                    let c = if state.fog.coord_src == gl::FOG_COORD {
                        a.fog
                    } else {
                        eye.z
                    };
                    if let Some(d) = o.get_mut(f) {
                        *d = c.abs();
                    }
                }
                // --- end fragment ops
                if self.lighting.is_none() {
                    put(o, l.col, color.clamp(Vec4::ZERO, Vec4::ONE));
                    if let Some(s) = l.spec {
                        put(o, s, color2.clamp(Vec4::ZERO, Vec4::ONE));
                    }
                    continue;
                }
                let mut n = self.tf.normal * nrm;
                if self.tf.normalize {
                    n = n.normalize_or_zero();
                }
                let v = if eye.w != 0.0 {
                    eye.xyz() / eye.w
                } else {
                    eye.xyz()
                };
                pts[k] = Point {
                    v: v.into(),
                    n: n.into(),
                    color,
                };
                cnt = k + 1;
                if let Some(no) = l.nrm {
                    put3(o, no, n);
                }
                if let Some(r) = l.raw {
                    put(o, r, color);
                }
            }
            let Some(lighting) = self.lighting else {
                continue;
            };
            // Materials: the state's for the whole block, or each vertex's own snapshot.
            let mat_of = |i: usize| {
                b.mat
                    .get(i)
                    .and_then(|&m| b.snapshots.get(m as usize))
                    .unwrap_or(&state.materials)
            };
            let mut lit = [(Vec4::ZERO, Vec4::ZERO); LANES];
            let mut lit_b = [(Vec4::ZERO, Vec4::ZERO); LANES];
            let two = l.col_b.is_some();
            if uniform {
                let m = &state.materials;
                lighting.shade_block(&m[FRONT], FRONT, &pts[..cnt], &mut lit);
                if two {
                    let back = pts.map(|p| Point { n: -p.n, ..p });
                    lighting.shade_block(&m[BACK], BACK, &back[..cnt], &mut lit_b);
                }
            } else {
                for k in 0..cnt {
                    let m = mat_of(base + k);
                    let p = pts[k];
                    lighting.shade_block(&m[FRONT], FRONT, &[p], &mut lit[k..]);
                    if two {
                        let q = Point { n: -p.n, ..p };
                        lighting.shade_block(&m[BACK], BACK, &[q], &mut lit_b[k..]);
                    }
                }
            }
            for (k, o) in os.chunks_exact_mut(l.stride).take(cnt).enumerate() {
                let (c, s) = lit[k];
                put(o, l.col, c);
                if let Some(so) = l.spec {
                    put(o, so, s);
                }
                if let Some(cb) = l.col_b {
                    let (c, s) = lit_b[k];
                    put(o, cb, c);
                    if let Some(sb) = l.spec_b {
                        put(o, sb, s);
                    }
                }
            }
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
