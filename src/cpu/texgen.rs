//! Texture coordinate generation (GL 2.1 §2.11.4) for texture unit 0, in the vertex stage
//! before the texture matrix: OBJECT_LINEAR, EYE_LINEAR, SPHERE_MAP, REFLECTION_MAP and
//! NORMAL_MAP, each enabled per coordinate with TEXTURE_GEN_S/T/R/Q.
//!
//! Design decision: the per-flush [`TexGen`] exists only when some coordinate is generated, so
//! a flush without TexGen pays one `Option` test per vertex. EYE_LINEAR planes were multiplied
//! by the inverse modelview when they were specified (see `context::texture_params`), so here
//! each coordinate is a plain dot product with the eye position.

use glam::{Vec3, Vec4, Vec4Swizzles};

use crate::gl;
use crate::state::State;

/// The generation state of one unit for a flush.
#[derive(Clone, Copy, Debug)]
pub struct TexGen {
    /// Per coordinate S, T, R, Q: the mode when TEXTURE_GEN_* is enabled.
    modes: [Option<u32>; 4],
    object: [Vec4; 4],
    eye: [Vec4; 4],
    /// Some coordinate needs the eye-space normal (SPHERE_MAP, REFLECTION_MAP, NORMAL_MAP).
    pub needs_normal: bool,
}

impl TexGen {
    /// Unit `unit`'s generation state, or None when no coordinate is generated.
    pub fn new(state: &State, unit: usize) -> Option<TexGen> {
        let on = state.enables.texture_gen.get(unit)?;
        let u = state.textures.units.get(unit)?;
        if !on.iter().any(|&b| b) {
            return None;
        }
        let modes: [Option<u32>; 4] = std::array::from_fn(|k| on[k].then_some(u.gen[k].mode));
        Some(TexGen {
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
