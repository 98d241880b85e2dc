//! Texture coordinate generation (GL 2.1 §2.11.4) for each texture unit, in the vertex stage
//! before the texture matrix: OBJECT_LINEAR, EYE_LINEAR, SPHERE_MAP, REFLECTION_MAP and
//! NORMAL_MAP, each enabled per coordinate with TEXTURE_GEN_S/T/R/Q.
//!
//! Design decision: the per-flush [`TexGenEval`] exists only when some coordinate is generated, so
//! a flush without TexGen pays one `Option` test per vertex. EYE_LINEAR planes were multiplied
//! by the inverse modelview when they were specified (see `context::texture_params`), so here
//! each coordinate is a plain dot product with the eye position.

use glam::{Vec3, Vec4, Vec4Swizzles};

use crate::gl;
use crate::state::State;

/// The generation state of one unit for a flush.
#[derive(Clone, Copy, Debug)]
pub struct TexGenEval {
    /// Per coordinate S, T, R, Q: the mode when TEXTURE_GEN_* is enabled.
    modes: [Option<u32>; 4],
    object: [Vec4; 4],
    eye: [Vec4; 4],
    /// Some coordinate needs the eye-space normal (SPHERE_MAP, REFLECTION_MAP, NORMAL_MAP).
    pub needs_normal: bool,
}

impl TexGenEval {
    /// Unit `unit`'s generation state, or None when no coordinate is generated.
    pub fn new(state: &State, unit: usize) -> Option<TexGenEval> {
        let on = state.enables.texture_gen.get(unit)?;
        let u = state.textures.units.get(unit)?;
        if !on.iter().any(|&b| b) {
            return None;
        }
        let modes: [Option<u32>; 4] = std::array::from_fn(|k| on[k].then_some(u.gen[k].mode));
        Some(TexGenEval {
            modes,
            object: u.gen.map(|g| g.object_plane),
            eye: u.gen.map(|g| g.eye_plane),
            needs_normal: modes.iter().any(|m| {
                matches!(
                    m,
                    Some(gl::SPHERE_MAP | gl::REFLECTION_MAP | gl::NORMAL_MAP)
                )
            }),
        })
    }

    /// The texture coordinates of a vertex with current coordinates `tc`, object position
    /// `obj`, eye position `eye` and eye-space normal `n` (used only when `needs_normal`).
    #[inline]
    pub fn apply(&self, tc: Vec4, obj: Vec4, eye: Vec4, n: Vec3) -> Vec4 {
        // §2.11.4: u is the unit vector from the origin to the vertex, r = u - 2 n' (n'·u).
        let (r, m) = if self.needs_normal {
            let u = eye.xyz().normalize_or_zero();
            let r = u - 2.0 * n * n.dot(u);
            let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
            (r, m)
        } else {
            (Vec3::ZERO, 0.0)
        };
        let mut out = tc.to_array();
        for (k, o) in out.iter_mut().enumerate() {
            let Some(mode) = self.modes[k] else {
                continue;
            };
            *o = match mode {
                gl::OBJECT_LINEAR => self.object[k].dot(obj),
                gl::EYE_LINEAR => self.eye[k].dot(eye),
                gl::SPHERE_MAP => {
                    let c = if k == 0 { r.x } else { r.y };
                    if m != 0.0 {
                        c / m + 0.5
                    } else {
                        0.5
                    }
                }
                gl::REFLECTION_MAP => r.to_array().get(k).copied().unwrap_or(0.0),
                gl::NORMAL_MAP => n.to_array().get(k).copied().unwrap_or(0.0),
                _ => *o,
            };
        }
        Vec4::from_array(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::*;
    use crate::Context;

    #[test]
    fn texgen_modes_follow_section_2_11_4() {
        let mut gl = Context::new(4, 4).expect("context");
        gl.enable(TEXTURE_GEN_S);
        gl.enable(TEXTURE_GEN_T);
        gl.tex_geni(S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
        gl.tex_genfv(S, OBJECT_PLANE, &[1.0, 2.0, 3.0, 4.0]);
        // EYE_LINEAR for T, the plane (0, 0, 1, 0) given under a translation by (0, 0, -5):
        // stored as (0, 0, 1, 5), so the eye point (0, 0, -5, 1) gives t = -5 + 5 = 0.
        gl.translatef(0.0, 0.0, -5.0);
        gl.tex_genfv(T, EYE_PLANE, &[0.0, 0.0, 1.0, 0.0]);
        let g = TexGenEval::new(gl.state(), 0).expect("texgen on");
        let tc = Vec4::new(7.0, 7.0, 7.0, 1.0);
        let out = g.apply(tc, Vec4::ONE, Vec4::new(0.0, 0.0, -5.0, 1.0), Vec3::Z);
        // s = 1 + 2 + 3 + 4; t = 0; r and q not generated keep the current values.
        assert_eq!(out, Vec4::new(10.0, 0.0, 7.0, 1.0));

        // SPHERE_MAP: u = (0, 0, -1), n = (1, 0, 1)/√2: r = u - 2n(n·u) = (1, 0, 0),
        // m = 2·sqrt(1 + 0 + 1) = 2√2, s = 1/(2√2) + 1/2, t = 0 + 1/2.
        gl.tex_geni(S, TEXTURE_GEN_MODE, SPHERE_MAP as i32);
        gl.tex_geni(T, TEXTURE_GEN_MODE, SPHERE_MAP as i32);
        let g = TexGenEval::new(gl.state(), 0).expect("texgen on");
        let n = Vec3::new(1.0, 0.0, 1.0).normalize();
        let eye = Vec4::new(0.0, 0.0, -1.0, 1.0);
        let out = g.apply(tc, Vec4::ONE, eye, n);
        let s_want = 1.0 / (2.0 * 2f32.sqrt()) + 0.5;
        assert!((out.x - s_want).abs() < 1e-6 && (out.y - 0.5).abs() < 1e-6);
        // REFLECTION_MAP gives r itself, NORMAL_MAP the normal.
        gl.enable(TEXTURE_GEN_R);
        for c in [S, T, R] {
            gl.tex_geni(c, TEXTURE_GEN_MODE, REFLECTION_MAP as i32);
        }
        let out = TexGenEval::new(gl.state(), 0)
            .expect("on")
            .apply(tc, Vec4::ONE, eye, n);
        assert!((out - Vec4::new(1.0, 0.0, 0.0, 1.0)).abs().max_element() < 1e-6);
        for c in [S, T, R] {
            gl.tex_geni(c, TEXTURE_GEN_MODE, NORMAL_MAP as i32);
        }
        let out = TexGenEval::new(gl.state(), 0)
            .expect("on")
            .apply(tc, Vec4::ONE, eye, n);
        assert!((out - n.extend(1.0)).abs().max_element() < 1e-6);
        assert_eq!(gl.get_error(), NO_ERROR);
    }
}
