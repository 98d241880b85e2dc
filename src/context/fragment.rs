//! Per-fragment state: `Fog` (GL 2.1 §3.10), `AlphaFunc` (§4.1.4), `StencilFunc`/`StencilOp`/
//! `StencilMask` and their `Separate` forms (§4.1.5, §4.2.2), `BlendFunc`, `BlendFuncSeparate`,
//! `BlendEquation`, `BlendEquationSeparate`, `BlendColor` (§4.1.8), `LogicOp` (§4.1.10) and
//! `SampleCoverage` (§4.1.3).
//!
//! Each command is outside-Begin/End only (§2.6.3): it raises INVALID_OPERATION there, and
//! otherwise flushes the vertex batch before validating, so an erroneous call changes nothing
//! but the error flag.
//!
//! Design decision: values GL 2.1 clamps "when specified" (FOG_COLOR, ALPHA_TEST_REF,
//! BLEND_COLOR) are stored clamped, so state, queries and the CPU fragment stage agree; the
//! stencil reference is stored as given and clamped to [0, 255] where it is used and queried,
//! as the spec words it (§4.1.5) and Mesa does.

use glam::Vec4;

use super::vertex::Component;
use super::Context;
use crate::call::Call;
use crate::counts;
use crate::gl;
use crate::state::{StencilFace, BACK, FRONT};

/// The eight comparison functions (§4.1.4): NEVER..=ALWAYS.
fn is_func(func: u32) -> bool {
    (gl::NEVER..=gl::ALWAYS).contains(&func)
}

/// The eight stencil operations (§4.1.5).
fn is_stencil_op(op: u32) -> bool {
    matches!(
        op,
        gl::KEEP
            | gl::ZERO
            | gl::REPLACE
            | gl::INCR
            | gl::DECR
            | gl::INVERT
            | gl::INCR_WRAP
            | gl::DECR_WRAP
    )
}

/// The stencil faces `face` names, or `None` (§4.1.5: FRONT, BACK, FRONT_AND_BACK).
fn stencil_faces(face: u32) -> Option<&'static [usize]> {
    match face {
        gl::FRONT => Some(&[FRONT]),
        gl::BACK => Some(&[BACK]),
        gl::FRONT_AND_BACK => Some(&[FRONT, BACK]),
        _ => None,
    }
}

/// A blend source factor GL 2.1 accepts (§4.1.8, table 4.2): every factor, SRC_ALPHA_SATURATE
/// included.
fn is_src_factor(f: u32) -> bool {
    is_dst_factor(f) || f == gl::SRC_ALPHA_SATURATE
}

/// A blend destination factor GL 2.1 accepts: every factor but SRC_ALPHA_SATURATE.
fn is_dst_factor(f: u32) -> bool {
    matches!(
        f,
        gl::ZERO
            | gl::ONE
            | gl::SRC_COLOR
            | gl::ONE_MINUS_SRC_COLOR
            | gl::DST_COLOR
            | gl::ONE_MINUS_DST_COLOR
            | gl::SRC_ALPHA
            | gl::ONE_MINUS_SRC_ALPHA
            | gl::DST_ALPHA
            | gl::ONE_MINUS_DST_ALPHA
            | gl::CONSTANT_COLOR
            | gl::ONE_MINUS_CONSTANT_COLOR
            | gl::CONSTANT_ALPHA
            | gl::ONE_MINUS_CONSTANT_ALPHA
    )
}

/// The five blend equations (§4.1.8).
fn is_equation(mode: u32) -> bool {
    matches!(
        mode,
        gl::FUNC_ADD | gl::FUNC_SUBTRACT | gl::FUNC_REVERSE_SUBTRACT | gl::MIN | gl::MAX
    )
}

impl Context {
    /// `glFogf`: a single-valued pname (FOG_COLOR is INVALID_ENUM here, GL 2.1 §3.10).
    pub fn fogf(&mut self, pname: u32, param: f32) {
        record!(self, Call::Fogf(pname, param));
        self.fog(pname, [param, 0.0, 0.0, 0.0], 1, true);
    }

    /// `glFogi`: as [`Context::fogf`], the value converted to float.
    pub fn fogi(&mut self, pname: u32, param: i32) {
        record!(self, Call::Fogi(pname, param));
        self.fog(pname, [param as f32, 0.0, 0.0, 0.0], 1, true);
    }

    /// `glFogfv`: FOG_COLOR takes 4 values, the other pnames 1; a shorter slice is
    /// INVALID_VALUE.
    pub fn fogfv(&mut self, pname: u32, params: &[f32]) {
        record!(self, Call::Fogfv(pname, params.to_vec()));
        let mut p = [0.0; 4];
        for (o, v) in p.iter_mut().zip(params) {
            *o = *v;
        }
        self.fog(pname, p, params.len(), false);
    }

    /// `glFogiv`: FOG_COLOR components map linearly from the integer range to [-1, 1] (table
    /// 2.9) before clamping; other values convert directly.
    pub fn fogiv(&mut self, pname: u32, params: &[i32]) {
        record!(self, Call::Fogiv(pname, params.to_vec()));
        let mut p = [0.0; 4];
        for (o, v) in p.iter_mut().zip(params) {
            *o = if pname == gl::FOG_COLOR {
                v.normalized()
            } else {
                *v as f32
            };
        }
        self.fog(pname, p, params.len(), false);
    }

    /// The validating body of every `Fog` form (GL 2.1 §3.10).
    fn fog(&mut self, pname: u32, p: [f32; 4], n: usize, scalar: bool) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(len) = counts::fog(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        // A scalar form takes a vector pname (FOG_COLOR) as `[param, 0, 0, 0]`, as Mesa does.
        let n = if scalar { len } else { n };
        if n < len {
            return self.error(gl::INVALID_VALUE);
        }
        let [x, ..] = p;
        let fog = &mut self.state.fog;
        match pname {
            gl::FOG_MODE => {
                // Converted from float: only an exact enum value names a mode.
                match [gl::LINEAR, gl::EXP, gl::EXP2]
                    .into_iter()
                    .find(|&m| x == m as f32)
                {
                    Some(m) => fog.mode = m,
                    None => self.error(gl::INVALID_ENUM),
                }
            }
            gl::FOG_DENSITY => {
                if x < 0.0 {
                    return self.error(gl::INVALID_VALUE);
                }
                fog.density = x;
            }
            gl::FOG_START => fog.start = x,
            gl::FOG_END => fog.end = x,
            gl::FOG_INDEX => fog.index = x,
            gl::FOG_COORD_SRC => {
                match [gl::FOG_COORD, gl::FRAGMENT_DEPTH]
                    .into_iter()
                    .find(|&m| x == m as f32)
                {
                    Some(m) => fog.coord_src = m,
                    None => self.error(gl::INVALID_ENUM),
                }
            }
            _ => fog.color = Vec4::from_array(p).clamp(Vec4::ZERO, Vec4::ONE),
        }
    }

    /// `glAlphaFunc`: one of the eight functions; `reference` clamped to [0, 1] (GL 2.1 §4.1.4).
    pub fn alpha_func(&mut self, func: u32, reference: f32) {
        record!(self, Call::AlphaFunc(func, reference));
        if !self.outside_begin_end() {
            return;
        }
        if !is_func(func) {
            return self.error(gl::INVALID_ENUM);
        }
        self.state.alpha.func = func;
        // NaN stays NaN through `clamp`; store 0 as Mesa's CLAMP does.
        self.state.alpha.reference = if reference.is_nan() {
            0.0
        } else {
            reference.clamp(0.0, 1.0)
        };
    }

    /// `glSampleCoverage` (GL 2.1 §4.1.3): SAMPLE_COVERAGE_VALUE, clamped to [0, 1] (NaN
    /// stored as 0, as Mesa's SATURATE does), and SAMPLE_COVERAGE_INVERT. fixedgl's
    /// framebuffers are single-sampled (SAMPLE_BUFFERS 0), so, as §4.1.3 says, the values have
    /// no effect on rendering; they are state (multisample group, table 6.15) all the same.
    pub fn sample_coverage(&mut self, value: f32, invert: bool) {
        record!(self, Call::SampleCoverage(value, invert));
        if !self.outside_begin_end() {
            return;
        }
        self.state.sample_coverage_value = if value.is_nan() {
            0.0
        } else {
            value.clamp(0.0, 1.0)
        };
        self.state.sample_coverage_invert = invert;
    }

    /// `glStencilFunc`: both faces (GL 2.1 §4.1.5).
    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        record!(self, Call::StencilFunc(func, reference, mask));
        self.stencil_func_faces(gl::FRONT_AND_BACK, func, reference, mask);
    }

    /// `glStencilFuncSeparate`: `face` FRONT, BACK or FRONT_AND_BACK.
    pub fn stencil_func_separate(&mut self, face: u32, func: u32, reference: i32, mask: u32) {
        record!(self, Call::StencilFuncSeparate(face, func, reference, mask));
        self.stencil_func_faces(face, func, reference, mask);
    }

    fn stencil_func_faces(&mut self, face: u32, func: u32, reference: i32, mask: u32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(faces) = stencil_faces(face) else {
            return self.error(gl::INVALID_ENUM);
        };
        if !is_func(func) {
            return self.error(gl::INVALID_ENUM);
        }
        for &f in faces {
            let s: &mut StencilFace = &mut self.state.stencil.faces[f];
            s.func = func;
            s.reference = reference;
            s.value_mask = mask;
        }
    }

    /// `glStencilOp`: both faces; each of KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP,
    /// DECR_WRAP (GL 2.1 §4.1.5).
    pub fn stencil_op(&mut self, sfail: u32, dpfail: u32, dppass: u32) {
        record!(self, Call::StencilOp(sfail, dpfail, dppass));
        self.stencil_op_faces(gl::FRONT_AND_BACK, sfail, dpfail, dppass);
    }

    /// `glStencilOpSeparate`: `face` FRONT, BACK or FRONT_AND_BACK.
    pub fn stencil_op_separate(&mut self, face: u32, sfail: u32, dpfail: u32, dppass: u32) {
        record!(self, Call::StencilOpSeparate(face, sfail, dpfail, dppass));
        self.stencil_op_faces(face, sfail, dpfail, dppass);
    }

    fn stencil_op_faces(&mut self, face: u32, sfail: u32, dpfail: u32, dppass: u32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(faces) = stencil_faces(face) else {
            return self.error(gl::INVALID_ENUM);
        };
        if ![sfail, dpfail, dppass].into_iter().all(is_stencil_op) {
            return self.error(gl::INVALID_ENUM);
        }
        for &f in faces {
            let s = &mut self.state.stencil.faces[f];
            s.fail = sfail;
            s.zfail = dpfail;
            s.zpass = dppass;
        }
    }

    /// `glStencilMask`: the write mask of both faces (GL 2.1 §4.2.2).
    pub fn stencil_mask(&mut self, mask: u32) {
        record!(self, Call::StencilMask(mask));
        self.stencil_mask_faces(gl::FRONT_AND_BACK, mask);
    }

    /// `glStencilMaskSeparate`: `face` FRONT, BACK or FRONT_AND_BACK.
    pub fn stencil_mask_separate(&mut self, face: u32, mask: u32) {
        record!(self, Call::StencilMaskSeparate(face, mask));
        self.stencil_mask_faces(face, mask);
    }

    fn stencil_mask_faces(&mut self, face: u32, mask: u32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(faces) = stencil_faces(face) else {
            return self.error(gl::INVALID_ENUM);
        };
        for &f in faces {
            if f == FRONT {
                self.state.stencil_writemask = mask;
            } else {
                self.state.stencil.back_writemask = mask;
            }
        }
    }

    /// `glBlendFunc`: source and destination factors for RGB and alpha alike (GL 2.1 §4.1.8).
    pub fn blend_func(&mut self, sfactor: u32, dfactor: u32) {
        record!(self, Call::BlendFunc(sfactor, dfactor));
        self.blend_funcs(sfactor, dfactor, sfactor, dfactor);
    }

    /// `glBlendFuncSeparate`.
    pub fn blend_func_separate(
        &mut self,
        src_rgb: u32,
        dst_rgb: u32,
        src_alpha: u32,
        dst_alpha: u32,
    ) {
        record!(
            self,
            Call::BlendFuncSeparate(src_rgb, dst_rgb, src_alpha, dst_alpha)
        );
        self.blend_funcs(src_rgb, dst_rgb, src_alpha, dst_alpha);
    }

    fn blend_funcs(&mut self, src_rgb: u32, dst_rgb: u32, src_alpha: u32, dst_alpha: u32) {
        if !self.outside_begin_end() {
            return;
        }
        if !(is_src_factor(src_rgb)
            && is_dst_factor(dst_rgb)
            && is_src_factor(src_alpha)
            && is_dst_factor(dst_alpha))
        {
            return self.error(gl::INVALID_ENUM);
        }
        let b = &mut self.state.blend;
        b.src_rgb = src_rgb;
        b.dst_rgb = dst_rgb;
        b.src_alpha = src_alpha;
        b.dst_alpha = dst_alpha;
    }

    /// `glBlendEquation`: FUNC_ADD, FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN or MAX, for RGB and
    /// alpha alike (GL 2.1 §4.1.8).
    pub fn blend_equation(&mut self, mode: u32) {
        record!(self, Call::BlendEquation(mode));
        self.blend_equations(mode, mode);
    }

    /// `glBlendEquationSeparate`.
    pub fn blend_equation_separate(&mut self, mode_rgb: u32, mode_alpha: u32) {
        record!(self, Call::BlendEquationSeparate(mode_rgb, mode_alpha));
        self.blend_equations(mode_rgb, mode_alpha);
    }

    fn blend_equations(&mut self, rgb: u32, alpha: u32) {
        if !self.outside_begin_end() {
            return;
        }
        if !(is_equation(rgb) && is_equation(alpha)) {
            return self.error(gl::INVALID_ENUM);
        }
        self.state.blend.equation_rgb = rgb;
        self.state.blend.equation_alpha = alpha;
    }

    /// `glBlendColor`: components clamped to [0, 1] (GL 2.1 §4.1.8).
    pub fn blend_color(&mut self, red: f32, green: f32, blue: f32, alpha: f32) {
        record!(self, Call::BlendColor(red, green, blue, alpha));
        if !self.outside_begin_end() {
            return;
        }
        let c = Vec4::new(red, green, blue, alpha);
        // NaN components become 0 (`clamp` would keep them).
        let c = Vec4::select(c.cmpeq(c), c, Vec4::ZERO);
        self.state.blend.color = c.clamp(Vec4::ZERO, Vec4::ONE);
    }

    /// `glLogicOp`: one of the sixteen operations CLEAR..=SET (GL 2.1 §4.1.10, table 4.3).
    pub fn logic_op(&mut self, opcode: u32) {
        record!(self, Call::LogicOp(opcode));
        if !self.outside_begin_end() {
            return;
        }
        if !(gl::CLEAR..=gl::SET).contains(&opcode) {
            return self.error(gl::INVALID_ENUM);
        }
        self.state.logic_op = opcode;
    }
}
