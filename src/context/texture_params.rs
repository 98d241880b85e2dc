//! Texture parameters, environment and coordinate generation, and their queries:
//! `TexParameter{i,f}[v]`, `TexEnv{i,f}[v]`, `TexGen{i,f,d}[v]`, `GetTexParameter*`,
//! `GetTexLevelParameter*`, `GetTexEnv*`, `GetTexGen*` (GL 2.1 §3.8.4, §3.8.13, §2.11.4,
//! §6.1.3, §6.1.4).
//!
//! Design decision: every setter form funnels into one validator taking `f64` values plus
//! whether they came as integers (an integer BORDER_COLOR or TEXTURE_ENV_COLOR maps the whole
//! integer range onto [-1, 1], §2.1.2), so the eight forms of a command cannot disagree; a vector
//! shorter than the pname needs is INVALID_VALUE with nothing changed (the crate's slice rule).

use glam::{DVec4, Vec4};

/// What a scalar form (TexParameter{f,i}, TexEnv{f,i}, TexGen{d,f,i}) hands the validator: Mesa
/// passes `param` on to the vector form as `[param, 0, 0, 0]`, so a vector pname (BORDER_COLOR,
/// TEXTURE_ENV_COLOR, OBJECT_PLANE, EYE_PLANE) is taken, not INVALID_ENUM as GL 2.1 says.
fn scalar(param: f64) -> [f64; 4] {
    [param, 0.0, 0.0, 0.0]
}

/// `GL_TEXTURE_STENCIL_SIZE` (GL 3.0, EXT_packed_depth_stencil; not in the GL 2.1 constants).
pub(crate) const TEXTURE_STENCIL_SIZE: u32 = 0x88F1;

use super::Context;
use crate::call::Call;
use crate::convert;
use crate::counts;
use crate::gl;
use crate::state::MAX_TEXTURE_UNITS;
use crate::texture::{target_index, TexObject, MAX_TEXTURE_LOD_BIAS};

/// An integer colour component as a float: the full range onto [-1, 1] (table 2.9).
fn int_to_norm(i: f64) -> f64 {
    convert::signed_to_unit(i, f64::from(u32::MAX))
}

/// The enum a parameter value names (a float converts by truncation, as Mesa does for TexEnv and
/// TexGen).
fn as_enum(v: f64) -> u32 {
    if v >= 0.0 && v <= f64::from(u32::MAX) {
        v as u32
    } else {
        u32::MAX
    }
}

impl Context {
    /// `glTexParameteri`.
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, param: i32) {
        record!(self, Call::TexParameteri(target, pname, param));
        self.tex_parameter(target, pname, &scalar(f64::from(param)), true, false);
    }

    /// `glTexParameterf`.
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, param: f32) {
        record!(self, Call::TexParameterf(target, pname, param));
        self.tex_parameter(target, pname, &scalar(f64::from(param)), false, false);
    }

    /// `glTexParameteriv`.
    pub fn tex_parameteriv(&mut self, target: u32, pname: u32, params: &[i32]) {
        record!(self, Call::TexParameteriv(target, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_parameter(target, pname, &v, true, true);
    }

    /// `glTexParameterfv`.
    pub fn tex_parameterfv(&mut self, target: u32, pname: u32, params: &[f32]) {
        record!(self, Call::TexParameterfv(target, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_parameter(target, pname, &v, false, true);
    }

    /// The body of the TexParameter forms (§3.8.4, table 3.19): validate, then set on the
    /// object bound to `target` (TEXTURE_1D, _2D, _3D or _CUBE_MAP) on the active unit.
    fn tex_parameter(&mut self, target: u32, pname: u32, v: &[f64], int: bool, vector: bool) {
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            ctx.tex_parameter_now(target, pname, v, int, vector)
        });
    }

    fn tex_parameter_now(&mut self, target: u32, pname: u32, v: &[f64], int: bool, vector: bool) {
        if !self.outside_begin_end() {
            return;
        }
        // A short vector is INVALID_VALUE as soon as its pname names a length, whatever the
        // target (the GL backend checks it there, before the driver sees the call).
        if vector && counts::tex_parameter(pname).is_some_and(|n| v.len() < n) {
            return self.error(gl::INVALID_VALUE);
        }
        if target_index(target).is_none() {
            return self.error(gl::INVALID_ENUM);
        }
        let Some(count) = counts::tex_parameter(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        if v.len() < count {
            return self.error(gl::INVALID_VALUE);
        }
        let x = v.first().copied().unwrap_or(0.0);
        // TexParameterf names an enum by rounding (Mesa's IROUND: COMPARE_MODE 0.5 is ONE, not
        // NONE); TexParameterfv, TexEnv and TexGen truncate.
        let e = as_enum(if int || vector { x } else { x.round() });
        let ok_enum = match pname {
            gl::TEXTURE_MIN_FILTER => matches!(
                e,
                gl::NEAREST
                    | gl::LINEAR
                    | gl::NEAREST_MIPMAP_NEAREST
                    | gl::LINEAR_MIPMAP_NEAREST
                    | gl::NEAREST_MIPMAP_LINEAR
                    | gl::LINEAR_MIPMAP_LINEAR
            ),
            gl::TEXTURE_MAG_FILTER => matches!(e, gl::NEAREST | gl::LINEAR),
            gl::TEXTURE_WRAP_S | gl::TEXTURE_WRAP_T | gl::TEXTURE_WRAP_R => matches!(
                e,
                gl::CLAMP
                    | gl::REPEAT
                    | gl::CLAMP_TO_EDGE
                    | gl::CLAMP_TO_BORDER
                    | gl::MIRRORED_REPEAT
            ),
            gl::TEXTURE_COMPARE_MODE => matches!(e, gl::NONE | gl::COMPARE_R_TO_TEXTURE),
            gl::TEXTURE_COMPARE_FUNC => (gl::NEVER..=gl::ALWAYS).contains(&e),
            gl::DEPTH_TEXTURE_MODE => matches!(e, gl::LUMINANCE | gl::INTENSITY | gl::ALPHA),
            _ => true,
        };
        if !ok_enum {
            return self.error(gl::INVALID_ENUM);
        }
        if matches!(pname, gl::TEXTURE_BASE_LEVEL | gl::TEXTURE_MAX_LEVEL) && x < 0.0 {
            return self.error(gl::INVALID_VALUE);
        }
        let unit = self.state.active_texture;
        let Some(o) = self.state.textures.bound_mut(unit, target) else {
            return;
        };
        let f = x as f32;
        match pname {
            gl::TEXTURE_MIN_FILTER => o.min_filter = e,
            gl::TEXTURE_MAG_FILTER => o.mag_filter = e,
            gl::TEXTURE_WRAP_S => o.wrap_s = e,
            gl::TEXTURE_WRAP_T => o.wrap_t = e,
            gl::TEXTURE_WRAP_R => o.wrap_r = e,
            gl::TEXTURE_COMPARE_MODE => o.compare_mode = e,
            gl::TEXTURE_COMPARE_FUNC => o.compare_func = e,
            gl::DEPTH_TEXTURE_MODE => o.depth_texture_mode = e,
            gl::TEXTURE_PRIORITY => {
                o.priority = if int { int_to_norm(x) as f32 } else { f }.clamp(0.0, 1.0)
            }
            gl::TEXTURE_MIN_LOD => o.min_lod = f,
            gl::TEXTURE_MAX_LOD => o.max_lod = f,
            // Any float, kept as given (an integer form converts as a number, not normalised);
            // the clamp of §3.8.8 eq. 3.18 applies to the sum with the unit's bias, at sampling.
            gl::TEXTURE_LOD_BIAS => o.lod_bias = f,
            gl::TEXTURE_BASE_LEVEL => o.base_level = x.min(f64::from(i32::MAX)) as i32,
            gl::TEXTURE_MAX_LEVEL => o.max_level = x.min(f64::from(i32::MAX)) as i32,
            gl::GENERATE_MIPMAP => {
                o.generate_mipmap = x != 0.0;
            }
            gl::TEXTURE_BORDER_COLOR => {
                let c: Vec<f32> = v
                    .iter()
                    .take(4)
                    .map(|&c| if int { int_to_norm(c) } else { c } as f32)
                    .collect();
                if let [r, g, b, a] = c[..] {
                    o.border_color = Vec4::new(r, g, b, a).clamp(Vec4::ZERO, Vec4::ONE);
                }
            }
            _ => {}
        }
    }

    /// `glTexEnvi`.
    pub fn tex_envi(&mut self, target: u32, pname: u32, param: i32) {
        record!(self, Call::TexEnvi(target, pname, param));
        self.tex_env(target, pname, &scalar(f64::from(param)), true, false);
    }

    /// `glTexEnvf`.
    pub fn tex_envf(&mut self, target: u32, pname: u32, param: f32) {
        record!(self, Call::TexEnvf(target, pname, param));
        self.tex_env(target, pname, &scalar(f64::from(param)), false, false);
    }

    /// `glTexEnviv`.
    pub fn tex_enviv(&mut self, target: u32, pname: u32, params: &[i32]) {
        record!(self, Call::TexEnviv(target, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_env(target, pname, &v, true, true);
    }

    /// `glTexEnvfv`.
    pub fn tex_envfv(&mut self, target: u32, pname: u32, params: &[f32]) {
        record!(self, Call::TexEnvfv(target, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_env(target, pname, &v, false, true);
    }

    /// The body of the TexEnv forms (§3.8.13): TEXTURE_ENV with TEXTURE_ENV_MODE (MODULATE,
    /// DECAL, BLEND, REPLACE, ADD, COMBINE), TEXTURE_ENV_COLOR (vector forms, clamped to
    /// [0, 1]) and the COMBINE parameters (tables 3.22 to 3.24: the functions, the sources
    /// TEXTURE, TEXTUREn, CONSTANT, PRIMARY_COLOR, PREVIOUS, the operands, RGB_SCALE and
    /// ALPHA_SCALE 1, 2 or 4, else INVALID_VALUE), and TEXTURE_FILTER_CONTROL with
    /// TEXTURE_LOD_BIAS (clamped to ±MAX_TEXTURE_LOD_BIAS), and POINT_SPRITE with COORD_REPLACE.
    fn tex_env(&mut self, target: u32, pname: u32, v: &[f64], int: bool, vector: bool) {
        if !self.outside_begin_end() {
            return;
        }
        // A short vector is INVALID_VALUE as soon as its pname names a length, whatever the
        // target (the GL backend checks it there, before the driver sees the call).
        if vector && counts::tex_env(pname).is_some_and(|n| v.len() < n) {
            return self.error(gl::INVALID_VALUE);
        }
        let env_pname = matches!(
            pname,
            gl::TEXTURE_ENV_MODE
                | gl::TEXTURE_ENV_COLOR
                | gl::COMBINE_RGB
                | gl::COMBINE_ALPHA
                | gl::RGB_SCALE
                | gl::ALPHA_SCALE
        ) || (gl::SRC0_RGB..=gl::SRC2_ALPHA).contains(&pname)
            && !matches!(pname, 0x8583..=0x8587)
            || (gl::OPERAND0_RGB..=gl::OPERAND2_ALPHA).contains(&pname)
                && !matches!(pname, 0x8593..=0x8597);
        if target == gl::POINT_SPRITE {
            // §3.4.1: COORD_REPLACE of the active unit, TRUE or FALSE (the value truncated to an
            // integer first, as Mesa); any other pname is INVALID_ENUM.
            if pname != gl::COORD_REPLACE {
                return self.error(gl::INVALID_ENUM);
            }
            let i = v.first().copied().unwrap_or(0.0) as i64;
            if i != i64::from(gl::TRUE) && i != i64::from(gl::FALSE) {
                return self.error(gl::INVALID_VALUE);
            }
            let unit = self.state.active_texture;
            if let Some(c) = self.state.point.coord_replace.get_mut(unit) {
                *c = i == i64::from(gl::TRUE);
            }
            return;
        }
        let pair_ok = (target == gl::TEXTURE_ENV && env_pname)
            || (target, pname) == (gl::TEXTURE_FILTER_CONTROL, gl::TEXTURE_LOD_BIAS);
        if !pair_ok {
            return self.error(gl::INVALID_ENUM);
        }
        let need = if pname == gl::TEXTURE_ENV_COLOR { 4 } else { 1 };
        if v.len() < need {
            return self.error(gl::INVALID_VALUE);
        }
        let x = v.first().copied().unwrap_or(0.0);
        let unit = self.state.active_texture;
        let e = as_enum(x);
        let source = |e: u32| {
            matches!(
                e,
                gl::TEXTURE | gl::CONSTANT | gl::PRIMARY_COLOR | gl::PREVIOUS
            ) || (gl::TEXTURE0..gl::TEXTURE0 + MAX_TEXTURE_UNITS as u32).contains(&e)
        };
        let rgb_fns = |e: u32| {
            matches!(
                e,
                gl::REPLACE
                    | gl::MODULATE
                    | gl::ADD
                    | gl::ADD_SIGNED
                    | gl::INTERPOLATE
                    | gl::SUBTRACT
            )
        };
        let ok = match pname {
            gl::TEXTURE_ENV_MODE => matches!(
                e,
                gl::MODULATE | gl::DECAL | gl::BLEND | gl::REPLACE | gl::ADD | gl::COMBINE
            ),
            gl::COMBINE_RGB => rgb_fns(e) || matches!(e, gl::DOT3_RGB | gl::DOT3_RGBA),
            gl::COMBINE_ALPHA => rgb_fns(e),
            gl::SRC0_RGB..=gl::SRC2_ALPHA => source(e),
            gl::OPERAND0_RGB..=gl::OPERAND2_RGB => matches!(
                e,
                gl::SRC_COLOR | gl::ONE_MINUS_SRC_COLOR | gl::SRC_ALPHA | gl::ONE_MINUS_SRC_ALPHA
            ),
            gl::OPERAND0_ALPHA..=gl::OPERAND2_ALPHA => {
                matches!(e, gl::SRC_ALPHA | gl::ONE_MINUS_SRC_ALPHA)
            }
            _ => true,
        };
        if !ok {
            return self.error(gl::INVALID_ENUM);
        }
        if matches!(pname, gl::RGB_SCALE | gl::ALPHA_SCALE) && ![1.0, 2.0, 4.0].contains(&x) {
            return self.error(gl::INVALID_VALUE);
        }
        let Some(u) = self.state.textures.units.get_mut(unit) else {
            return;
        };
        let c = &mut u.combine;
        let k = |first: u32| (pname - first) as usize;
        match pname {
            gl::TEXTURE_ENV_MODE => u.env_mode = e,
            gl::TEXTURE_LOD_BIAS => {
                u.lod_bias = (x as f32).clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS)
            }
            gl::COMBINE_RGB => c.rgb = e,
            gl::COMBINE_ALPHA => c.alpha = e,
            gl::RGB_SCALE => c.rgb_scale = x as f32,
            gl::ALPHA_SCALE => c.alpha_scale = x as f32,
            gl::SRC0_RGB..=gl::SRC2_RGB => c.src_rgb[k(gl::SRC0_RGB).min(2)] = e,
            gl::SRC0_ALPHA..=gl::SRC2_ALPHA => c.src_alpha[k(gl::SRC0_ALPHA).min(2)] = e,
            gl::OPERAND0_RGB..=gl::OPERAND2_RGB => c.operand_rgb[k(gl::OPERAND0_RGB).min(2)] = e,
            gl::OPERAND0_ALPHA..=gl::OPERAND2_ALPHA => {
                c.operand_alpha[k(gl::OPERAND0_ALPHA).min(2)] = e
            }
            _ => {
                let c: Vec<f32> = v
                    .iter()
                    .take(4)
                    .map(|&c| if int { int_to_norm(c) } else { c } as f32)
                    .collect();
                if let [r, g, b, a] = c[..] {
                    u.env_color = Vec4::new(r, g, b, a).clamp(Vec4::ZERO, Vec4::ONE);
                }
            }
        }
    }

    /// `glTexGeni`.
    pub fn tex_geni(&mut self, coord: u32, pname: u32, param: i32) {
        record!(self, Call::TexGeni(coord, pname, param));
        self.tex_gen(coord, pname, &scalar(f64::from(param)), false);
    }

    /// `glTexGenf`.
    pub fn tex_genf(&mut self, coord: u32, pname: u32, param: f32) {
        record!(self, Call::TexGenf(coord, pname, param));
        self.tex_gen(coord, pname, &scalar(f64::from(param)), false);
    }

    /// `glTexGend`.
    pub fn tex_gend(&mut self, coord: u32, pname: u32, param: f64) {
        record!(self, Call::TexGend(coord, pname, param));
        self.tex_gen(coord, pname, &scalar(param), false);
    }

    /// `glTexGeniv`.
    pub fn tex_geniv(&mut self, coord: u32, pname: u32, params: &[i32]) {
        record!(self, Call::TexGeniv(coord, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_gen(coord, pname, &v, true);
    }

    /// `glTexGenfv`.
    pub fn tex_genfv(&mut self, coord: u32, pname: u32, params: &[f32]) {
        record!(self, Call::TexGenfv(coord, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).map(|&x| f64::from(x)).collect();
        self.tex_gen(coord, pname, &v, true);
    }

    /// `glTexGendv`.
    pub fn tex_gendv(&mut self, coord: u32, pname: u32, params: &[f64]) {
        record!(self, Call::TexGendv(coord, pname, params.to_vec()));
        let v: Vec<f64> = params.iter().take(4).copied().collect();
        self.tex_gen(coord, pname, &v, true);
    }

    /// The body of the TexGen forms (§2.11.4): TEXTURE_GEN_MODE (SPHERE_MAP only for S and T,
    /// REFLECTION_MAP and NORMAL_MAP not for Q), OBJECT_PLANE, and EYE_PLANE, which is stored
    /// multiplied by the inverse of the modelview matrix current now: (p1 p2 p3 p4) M^-1.
    fn tex_gen(&mut self, coord: u32, pname: u32, v: &[f64], vector: bool) {
        if !self.outside_begin_end() {
            return;
        }
        // A short vector is INVALID_VALUE as soon as its pname names a length, whatever the
        // target (the GL backend checks it there, before the driver sees the call).
        if vector && counts::tex_gen(pname).is_some_and(|n| v.len() < n) {
            return self.error(gl::INVALID_VALUE);
        }
        let k = match coord {
            gl::S => 0,
            gl::T => 1,
            gl::R => 2,
            gl::Q => 3,
            _ => return self.error(gl::INVALID_ENUM),
        };
        let plane = matches!(pname, gl::OBJECT_PLANE | gl::EYE_PLANE);
        if !(pname == gl::TEXTURE_GEN_MODE || plane) {
            return self.error(gl::INVALID_ENUM);
        }
        let need = if plane { 4 } else { 1 };
        if v.len() < need {
            return self.error(gl::INVALID_VALUE);
        }
        let unit = self.state.active_texture;
        let mv = self.state.modelview.top().as_dmat4();
        let Some(u) = self.state.textures.units.get_mut(unit) else {
            return;
        };
        let g = &mut u.gen[k];
        match pname {
            gl::TEXTURE_GEN_MODE => {
                let m = as_enum(v.first().copied().unwrap_or(0.0));
                let ok = match m {
                    gl::OBJECT_LINEAR | gl::EYE_LINEAR => true,
                    gl::SPHERE_MAP => k < 2,
                    gl::REFLECTION_MAP | gl::NORMAL_MAP => k < 3,
                    _ => false,
                };
                if !ok {
                    return self.error(gl::INVALID_ENUM);
                }
                g.mode = m;
            }
            _ => {
                let p = DVec4::new(
                    v.first().copied().unwrap_or(0.0),
                    v.get(1).copied().unwrap_or(0.0),
                    v.get(2).copied().unwrap_or(0.0),
                    v.get(3).copied().unwrap_or(0.0),
                );
                if pname == gl::OBJECT_PLANE {
                    g.object_plane = p.as_vec4();
                } else {
                    // Row vector times M^-1 = (M^-T) p.
                    g.eye_plane = (mv.inverse().transpose() * p).as_vec4();
                }
            }
        }
    }

    /// `glGetTexParameteriv`.
    pub fn get_tex_parameteriv(&mut self, target: u32, pname: u32, params: &mut [i32]) {
        if let Some((v, norm)) = self.tex_parameter_value(target, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = if norm {
                    norm_to_int(x)
                } else {
                    x.round() as i32
                };
            }
        }
    }

    /// `glGetTexParameterfv`.
    pub fn get_tex_parameterfv(&mut self, target: u32, pname: u32, params: &mut [f32]) {
        if let Some((v, _)) = self.tex_parameter_value(target, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x as f32;
            }
        }
    }

    /// A texture parameter's values (and whether they are a normalised colour) of the object
    /// bound to `target` on the active unit, after the Begin/End, target, pname and length
    /// checks (§6.1.3).
    fn tex_parameter_value(
        &mut self,
        target: u32,
        pname: u32,
        len: usize,
    ) -> Option<(Vec<f64>, bool)> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        self.pull_objects();
        if target_index(target).is_none() {
            self.error(gl::INVALID_ENUM);
            return None;
        }
        let unit = self.state.active_texture;
        let default = TexObject::new(target);
        let o: &TexObject = self
            .state
            .textures
            .bound(unit, target)
            .map_or(&default, |a| a);
        let e = |x: u32| vec![f64::from(x)];
        let v = match pname {
            gl::TEXTURE_MIN_FILTER => e(o.min_filter),
            gl::TEXTURE_MAG_FILTER => e(o.mag_filter),
            gl::TEXTURE_WRAP_S => e(o.wrap_s),
            gl::TEXTURE_WRAP_T => e(o.wrap_t),
            gl::TEXTURE_WRAP_R => e(o.wrap_r),
            gl::TEXTURE_COMPARE_MODE => e(o.compare_mode),
            gl::TEXTURE_COMPARE_FUNC => e(o.compare_func),
            gl::DEPTH_TEXTURE_MODE => e(o.depth_texture_mode),
            gl::TEXTURE_PRIORITY => vec![f64::from(o.priority)],
            gl::TEXTURE_MIN_LOD => vec![f64::from(o.min_lod)],
            gl::TEXTURE_MAX_LOD => vec![f64::from(o.max_lod)],
            gl::TEXTURE_LOD_BIAS => vec![f64::from(o.lod_bias)],
            gl::TEXTURE_BASE_LEVEL => vec![f64::from(o.base_level)],
            gl::TEXTURE_MAX_LEVEL => vec![f64::from(o.max_level)],
            gl::GENERATE_MIPMAP => vec![f64::from(u8::from(o.generate_mipmap))],
            gl::TEXTURE_RESIDENT => vec![1.0],
            gl::TEXTURE_BORDER_COLOR => o.border_color.to_array().map(f64::from).to_vec(),
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        if len < v.len() {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some((v, pname == gl::TEXTURE_BORDER_COLOR))
    }

    /// `glGetTexLevelParameteriv`.
    pub fn get_tex_level_parameteriv(
        &mut self,
        target: u32,
        level: i32,
        pname: u32,
        params: &mut [i32],
    ) {
        if let Some(v) = self.tex_level_value(target, level, pname, params.len()) {
            if let Some(o) = params.first_mut() {
                *o = v;
            }
        }
    }

    /// `glGetTexLevelParameterfv`.
    pub fn get_tex_level_parameterfv(
        &mut self,
        target: u32,
        level: i32,
        pname: u32,
        params: &mut [f32],
    ) {
        if let Some(v) = self.tex_level_value(target, level, pname, params.len()) {
            if let Some(o) = params.first_mut() {
                *o = v as f32;
            }
        }
    }

    /// One level parameter (table 6.17) of the active unit's 1D, 2D or 3D texture, a cube-map
    /// face, or a proxy target's level (§3.8.1); a level without an image (or a proxy level
    /// zeroed because its image did not fit) reports zero sizes and internal format 1, as the
    /// spec's initial values.
    fn tex_level_value(&mut self, target: u32, level: i32, pname: u32, len: usize) -> Option<i32> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        self.pull_objects();
        let proxy = crate::texture::proxy_index(target);
        if !matches!(target, gl::TEXTURE_1D | gl::TEXTURE_2D | gl::TEXTURE_3D)
            && !(gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                .contains(&target)
            && proxy.is_none()
        {
            self.error(gl::INVALID_ENUM);
            return None;
        }
        if level < 0 || level >= crate::texture::MAX_LEVELS as i32 {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        // (width, height, depth, border, internal format, base) of the level, if any: a real
        // image (its border stripped, `context::texture::strip_border`) or a proxy's.
        let lv = match proxy {
            Some(k) => self
                .state
                .textures
                .proxies
                .get(k)
                .and_then(|v| v.get(level as usize).copied().flatten())
                .map(|p| {
                    (
                        p.width,
                        p.height,
                        p.depth,
                        p.border,
                        p.internal_format,
                        p.base,
                    )
                }),
            None => {
                let unit = self.state.active_texture;
                let (bind, face) = crate::texture::image_binding(target);
                self.state
                    .textures
                    .bound(unit, bind)
                    .and_then(|o| o.face_level(face, level))
                    .map(|l| (l.width, l.height, l.depth, 0, l.internal_format, l.base))
            }
        };
        let base = lv.map_or(0, |l| l.5);
        let bits = |has: bool, n: i32| if has { n } else { 0 };
        let v = match pname {
            gl::TEXTURE_WIDTH => lv.map_or(0, |l| l.0),
            gl::TEXTURE_HEIGHT => lv.map_or(0, |l| l.1),
            gl::TEXTURE_DEPTH => lv.map_or(0, |l| l.2),
            gl::TEXTURE_BORDER => lv.map_or(0, |l| l.3),
            // No image is compressed (context/compressed.rs): TEXTURE_COMPRESSED_IMAGE_SIZE of
            // an uncompressed level, with an image or without, is INVALID_OPERATION (§6.1.3;
            // Mesa, measured).
            gl::TEXTURE_COMPRESSED => 0,
            gl::TEXTURE_COMPRESSED_IMAGE_SIZE => {
                self.error(gl::INVALID_OPERATION);
                return None;
            }
            // A generic compressed format (table 3.17) stored uncompressed answers its base
            // format, as GL 1.3 §3.8.1 says ("internalformat is instead replaced by the
            // corresponding base internal format") and Mesa answers.
            gl::TEXTURE_INTERNAL_FORMAT => lv.map_or(1, |l| {
                u32::try_from(l.4)
                    .ok()
                    .and_then(super::compressed::generic_compressed_base)
                    .map_or(l.4, |b| b as i32)
            }),
            gl::TEXTURE_RED_SIZE | gl::TEXTURE_GREEN_SIZE | gl::TEXTURE_BLUE_SIZE => {
                bits(matches!(base, gl::RGB | gl::RGBA), 8)
            }
            gl::TEXTURE_ALPHA_SIZE => bits(
                matches!(base, gl::ALPHA | gl::LUMINANCE_ALPHA | gl::RGBA),
                8,
            ),
            gl::TEXTURE_LUMINANCE_SIZE => {
                bits(matches!(base, gl::LUMINANCE | gl::LUMINANCE_ALPHA), 8)
            }
            gl::TEXTURE_INTENSITY_SIZE => bits(base == gl::INTENSITY, 8),
            gl::TEXTURE_DEPTH_SIZE => bits(crate::texture::is_depth(base), 24),
            // EXT_packed_depth_stencil's TEXTURE_STENCIL_SIZE_EXT: 8 for DEPTH_STENCIL.
            TEXTURE_STENCIL_SIZE => bits(base == gl::DEPTH_STENCIL, 8),
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        if len < 1 {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some(v)
    }

    /// `glGetTexEnviv` (colours map [0, 1] onto the integer range, §6.1.2).
    pub fn get_tex_enviv(&mut self, target: u32, pname: u32, params: &mut [i32]) {
        if let Some((v, norm)) = self.tex_env_value(target, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = if norm {
                    norm_to_int(x)
                } else {
                    x.round() as i32
                };
            }
        }
    }

    /// `glGetTexEnvfv`.
    pub fn get_tex_envfv(&mut self, target: u32, pname: u32, params: &mut [f32]) {
        if let Some((v, _)) = self.tex_env_value(target, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x as f32;
            }
        }
    }

    fn tex_env_value(&mut self, target: u32, pname: u32, len: usize) -> Option<(Vec<f64>, bool)> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let u = self
            .state
            .textures
            .units
            .get(self.state.active_texture)
            .copied()
            .unwrap_or_default();
        let v = match (target, pname) {
            (gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE) => vec![f64::from(u.env_mode)],
            (gl::TEXTURE_ENV, gl::TEXTURE_ENV_COLOR) => {
                u.env_color.to_array().map(f64::from).to_vec()
            }
            (gl::TEXTURE_FILTER_CONTROL, gl::TEXTURE_LOD_BIAS) => vec![f64::from(u.lod_bias)],
            (gl::POINT_SPRITE, gl::COORD_REPLACE) => {
                let unit = self.state.active_texture;
                let on = self.state.point.coord_replace.get(unit).copied();
                vec![if on.unwrap_or(false) { 1.0 } else { 0.0 }]
            }
            (gl::TEXTURE_ENV, gl::COMBINE_RGB) => vec![f64::from(u.combine.rgb)],
            (gl::TEXTURE_ENV, gl::COMBINE_ALPHA) => vec![f64::from(u.combine.alpha)],
            (gl::TEXTURE_ENV, gl::RGB_SCALE) => vec![f64::from(u.combine.rgb_scale)],
            (gl::TEXTURE_ENV, gl::ALPHA_SCALE) => vec![f64::from(u.combine.alpha_scale)],
            (gl::TEXTURE_ENV, p @ gl::SRC0_RGB..=gl::SRC2_RGB) => {
                vec![f64::from(
                    u.combine.src_rgb[((p - gl::SRC0_RGB) as usize).min(2)],
                )]
            }
            (gl::TEXTURE_ENV, p @ gl::SRC0_ALPHA..=gl::SRC2_ALPHA) => {
                vec![f64::from(
                    u.combine.src_alpha[((p - gl::SRC0_ALPHA) as usize).min(2)],
                )]
            }
            (gl::TEXTURE_ENV, p @ gl::OPERAND0_RGB..=gl::OPERAND2_RGB) => {
                vec![f64::from(
                    u.combine.operand_rgb[((p - gl::OPERAND0_RGB) as usize).min(2)],
                )]
            }
            (gl::TEXTURE_ENV, p @ gl::OPERAND0_ALPHA..=gl::OPERAND2_ALPHA) => vec![f64::from(
                u.combine.operand_alpha[((p - gl::OPERAND0_ALPHA) as usize).min(2)],
            )],
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        if len < v.len() {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some((v, pname == gl::TEXTURE_ENV_COLOR))
    }

    /// `glGetTexGeniv`.
    pub fn get_tex_geniv(&mut self, coord: u32, pname: u32, params: &mut [i32]) {
        if let Some(v) = self.tex_gen_value(coord, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x.round() as i32;
            }
        }
    }

    /// `glGetTexGenfv`.
    pub fn get_tex_genfv(&mut self, coord: u32, pname: u32, params: &mut [f32]) {
        if let Some(v) = self.tex_gen_value(coord, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x as f32;
            }
        }
    }

    /// `glGetTexGendv`.
    pub fn get_tex_gendv(&mut self, coord: u32, pname: u32, params: &mut [f64]) {
        if let Some(v) = self.tex_gen_value(coord, pname, params.len()) {
            for (o, x) in params.iter_mut().zip(v) {
                *o = x;
            }
        }
    }

    fn tex_gen_value(&mut self, coord: u32, pname: u32, len: usize) -> Option<Vec<f64>> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let k = match coord {
            gl::S => 0,
            gl::T => 1,
            gl::R => 2,
            gl::Q => 3,
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        let u = self
            .state
            .textures
            .units
            .get(self.state.active_texture)
            .copied()
            .unwrap_or_default();
        let g = u.gen.get(k).copied().unwrap_or(u.gen[0]);
        let v = match pname {
            gl::TEXTURE_GEN_MODE => vec![f64::from(g.mode)],
            gl::OBJECT_PLANE => g.object_plane.to_array().map(f64::from).to_vec(),
            gl::EYE_PLANE => g.eye_plane.to_array().map(f64::from).to_vec(),
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        if len < v.len() {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some(v)
    }
}

/// A [0, 1] colour component as an integer: the whole positive range (table 4.9 inverted).
fn norm_to_int(x: f64) -> i32 {
    convert::unit_to_signed(x, f64::from(u32::MAX))
        .round()
        .clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
}
