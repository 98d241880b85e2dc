//! The replay proper: each [`Call`] variant becomes the driver call of the same name with the
//! same arguments (GL 2.1 §2.5 onwards; the variant name is the GL function minus `gl`).
//!
//! Adding a variant is mechanical, by the argument shape:
//! - scalars: `Call::Normal3f(x, y, z) => unsafe { gl.Normal3f(x, y, z) }`;
//! - fixed-length arrays: `Call::Normal3fv(v) => unsafe { gl.Normal3fv(v.as_ptr()) }` (the array
//!   has exactly the length GL reads);
//! - pname-dependent slices: through [`GlBackend::with_params`] with the pname's count from
//!   [`params`], which raises INVALID_VALUE instead of letting a short slice reach the driver:
//!   `Call::Lightfv(l, p, ref v) => self.with_params(v, params::light(p), false, |gl, v| unsafe
//!   { gl.Lightfv(l, p, v) })` (`true` for Materialfv/iv, the only ones allowed in Begin/End);
//! - `ShadeModel(mode) => self.shade_model(mode)` (PHONG_WIN is emulated).
//!
//! Design decision: the match is exhaustive (no `_ =>`), so a variant the front end gains cannot
//! compile until it is replayed here.

use super::{raw, GlBackend};
use crate::gl;
use crate::Call;

impl GlBackend {
    /// Sends one recorded call to the driver, exactly as the user's program would have made it.
    pub fn execute(&mut self, call: &Call) {
        self.make_current();
        if !phong_neutral(call) {
            self.phong_dirty = true;
        }
        let gl = &self.raw;
        // SAFETY: the context is current on this thread (GlBackend is not Send) and every pointer
        // passed below points to at least as many elements as the driver reads for the call.
        match *call {
            Call::Begin(mode) => {
                // GL 2.1 §2.6.1 has ten modes; a 3.2+ compatibility driver also accepts the
                // adjacency modes and PATCHES (0xA..=0xE), so the GL 2.1 INVALID_ENUM is raised
                // here. Inside Begin/End the driver's INVALID_OPERATION comes first, as in GL.
                if mode > gl::POLYGON && !self.inside_begin_end {
                    return self.raise(gl::INVALID_ENUM);
                }
                self.before_begin();
                unsafe { self.raw.Begin(mode) };
                // The driver opened a primitive iff none was open (the mode is valid here).
                self.inside_begin_end = true;
            }
            Call::End => {
                unsafe { gl.End() };
                self.inside_begin_end = false;
            }
            Call::Vertex3f(x, y, z) => unsafe { gl.Vertex3f(x, y, z) },
            Call::Normal3f(x, y, z) => unsafe { gl.Normal3f(x, y, z) },
            Call::Color4f(r, g, b, a) => unsafe { gl.Color4f(r, g, b, a) },
            Call::Enable(cap) => unsafe { gl.Enable(cap) },
            Call::Disable(cap) => unsafe { gl.Disable(cap) },
        }
    }

    /// Calls the driver with a pname-dependent parameter slice `v` of which GL reads `needed`
    /// values, or — when `v` is shorter — records INVALID_VALUE as the CPU front end does and
    /// calls nothing. Between Begin and End a command not `allowed_in_begin_end` is an
    /// INVALID_OPERATION first (GL 2.1 §2.6.3), short slice or not. The driver always gets a
    /// buffer of at least 16 values (the slice, zero-padded), so an unknown pname (count 0, the
    /// driver raises INVALID_ENUM) can never make it read past the caller's data.
    #[allow(dead_code)] // Used by the pname-dependent variants as they are added.
    pub(crate) fn with_params<T: Copy + Default>(
        &mut self,
        v: &[T],
        needed: usize,
        allowed_in_begin_end: bool,
        call: impl FnOnce(&raw::Gl, *const T),
    ) {
        if v.len() < needed {
            let code = if self.inside_begin_end && !allowed_in_begin_end {
                gl::INVALID_OPERATION
            } else {
                gl::INVALID_VALUE
            };
            return self.raise(code);
        }
        let mut padded = [T::default(); 16];
        if v.len() >= padded.len() {
            call(&self.raw, v.as_ptr());
        } else {
            padded[..v.len()].copy_from_slice(v);
            call(&self.raw, padded.as_ptr());
        }
    }
}

/// Calls that can never change what the PHONG_WIN program depends on (LIGHTING, the light
/// enables, the light model, COLOR_MATERIAL), so they need not trigger a re-read before the next
/// Begin. Anything not listed here does: a new variant is correct by default, merely slower.
fn phong_neutral(call: &Call) -> bool {
    matches!(
        call,
        Call::Begin(_) | Call::End | Call::Vertex3f(..) | Call::Normal3f(..) | Call::Color4f(..)
    )
}

/// How many values each pname-dependent vector command reads (GL 2.1 §2.14.2, §2.14.3, §3.10,
/// §3.8.4, §3.8.13, §2.11.4, §3.4); 0 for a pname the command does not know, which the driver
/// rejects with INVALID_ENUM before reading anything.
#[allow(dead_code)] // Used by the pname-dependent variants as they are added.
pub(crate) mod params {
    use crate::gl;

    /// `Light{fv,iv}` (table 6.10).
    pub fn light(pname: u32) -> usize {
        match pname {
            gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::POSITION => 4,
            gl::SPOT_DIRECTION => 3,
            gl::SPOT_EXPONENT
            | gl::SPOT_CUTOFF
            | gl::CONSTANT_ATTENUATION
            | gl::LINEAR_ATTENUATION
            | gl::QUADRATIC_ATTENUATION => 1,
            _ => 0,
        }
    }

    /// `Material{fv,iv}` (table 6.9).
    pub fn material(pname: u32) -> usize {
        match pname {
            gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::EMISSION | gl::AMBIENT_AND_DIFFUSE => 4,
            gl::COLOR_INDEXES => 3,
            gl::SHININESS => 1,
            _ => 0,
        }
    }

    /// `LightModel{fv,iv}` (table 6.9).
    pub fn light_model(pname: u32) -> usize {
        match pname {
            gl::LIGHT_MODEL_AMBIENT => 4,
            gl::LIGHT_MODEL_LOCAL_VIEWER
            | gl::LIGHT_MODEL_TWO_SIDE
            | gl::LIGHT_MODEL_COLOR_CONTROL => 1,
            _ => 0,
        }
    }

    /// `Fog{fv,iv}` (table 6.8).
    pub fn fog(pname: u32) -> usize {
        match pname {
            gl::FOG_COLOR => 4,
            gl::FOG_MODE
            | gl::FOG_DENSITY
            | gl::FOG_START
            | gl::FOG_END
            | gl::FOG_INDEX
            | gl::FOG_COORD_SRC => 1,
            _ => 0,
        }
    }

    /// `TexEnv{fv,iv}` (table 6.20).
    pub fn tex_env(pname: u32) -> usize {
        match pname {
            gl::TEXTURE_ENV_COLOR => 4,
            gl::TEXTURE_ENV_MODE
            | gl::COMBINE_RGB
            | gl::COMBINE_ALPHA
            | gl::SRC0_RGB
            | gl::SRC1_RGB
            | gl::SRC2_RGB
            | gl::SRC0_ALPHA
            | gl::SRC1_ALPHA
            | gl::SRC2_ALPHA
            | gl::OPERAND0_RGB
            | gl::OPERAND1_RGB
            | gl::OPERAND2_RGB
            | gl::OPERAND0_ALPHA
            | gl::OPERAND1_ALPHA
            | gl::OPERAND2_ALPHA
            | gl::RGB_SCALE
            | gl::ALPHA_SCALE
            | gl::TEXTURE_LOD_BIAS
            | gl::COORD_REPLACE => 1,
            _ => 0,
        }
    }

    /// `TexGen{fv,iv,dv}` (table 6.15).
    pub fn tex_gen(pname: u32) -> usize {
        match pname {
            gl::OBJECT_PLANE | gl::EYE_PLANE => 4,
            gl::TEXTURE_GEN_MODE => 1,
            _ => 0,
        }
    }

    /// `TexParameter{fv,iv}` (table 6.16).
    pub fn tex_parameter(pname: u32) -> usize {
        match pname {
            gl::TEXTURE_BORDER_COLOR => 4,
            gl::TEXTURE_MIN_FILTER
            | gl::TEXTURE_MAG_FILTER
            | gl::TEXTURE_WRAP_S
            | gl::TEXTURE_WRAP_T
            | gl::TEXTURE_WRAP_R
            | gl::TEXTURE_PRIORITY
            | gl::TEXTURE_MIN_LOD
            | gl::TEXTURE_MAX_LOD
            | gl::TEXTURE_BASE_LEVEL
            | gl::TEXTURE_MAX_LEVEL
            | gl::TEXTURE_LOD_BIAS
            | gl::DEPTH_TEXTURE_MODE
            | gl::TEXTURE_COMPARE_MODE
            | gl::TEXTURE_COMPARE_FUNC
            | gl::GENERATE_MIPMAP => 1,
            _ => 0,
        }
    }

    /// `PointParameter{fv,iv}` (§3.4).
    pub fn point_parameter(pname: u32) -> usize {
        match pname {
            gl::POINT_DISTANCE_ATTENUATION => 3,
            gl::POINT_SIZE_MIN
            | gl::POINT_SIZE_MAX
            | gl::POINT_FADE_THRESHOLD_SIZE
            | gl::POINT_SPRITE_COORD_ORIGIN => 1,
            _ => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glbackend::DeviceChoice;
    use std::io::Write as _;

    fn light0_position(b: &GlBackend) -> [f32; 4] {
        let mut p = [f32::NAN; 4];
        // SAFETY: GetLightfv(POSITION) writes 4 floats.
        unsafe { b.raw().GetLightfv(gl::LIGHT0, gl::POSITION, p.as_mut_ptr()) };
        p
    }

    #[test]
    fn short_parameter_slices_never_reach_the_driver() {
        let mut b = match GlBackend::new(4, 4, &DeviceChoice::Auto) {
            Ok(b) => b,
            Err(e) => {
                let _ = writeln!(std::io::stderr(), "SKIPPED: GL backend unavailable: {e}");
                return;
            }
        };
        let lightfv = |pname: u32| {
            move |gl: &raw::Gl, v: *const f32| unsafe { gl.Lightfv(gl::LIGHT0, pname, v) }
        };
        // POSITION needs 4 values: 3 is INVALID_VALUE and the initial (0,0,1,0) stays.
        b.with_params(
            &[5.0, 5.0, 5.0],
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), [0.0, 0.0, 1.0, 0.0]);
        // Enough values: applied (identity modelview, so stored as given).
        let v = [1.0, 2.0, 3.0, 1.0];
        b.with_params(
            &v,
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::NO_ERROR);
        assert_eq!(light0_position(&b), v);
        // An unknown pname needs nothing of ours: the driver's INVALID_ENUM.
        b.with_params(&[], params::light(0x1234), false, lightfv(0x1234));
        assert_eq!(b.get_error(), gl::INVALID_ENUM);
        // Between Begin and End a command not allowed there is INVALID_OPERATION first...
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(
            &[1.0],
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_OPERATION);
        // ...while Material, allowed there, reports the short slice.
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(
            &[1.0],
            params::material(gl::DIFFUSE),
            true,
            |gl, v| unsafe { gl.Materialfv(gl::FRONT, gl::DIFFUSE, v) },
        );
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), v);
    }

    #[test]
    fn parameter_counts_follow_the_state_tables() {
        assert_eq!(params::light(gl::SPOT_DIRECTION), 3);
        assert_eq!(params::light(gl::QUADRATIC_ATTENUATION), 1);
        assert_eq!(params::material(gl::AMBIENT_AND_DIFFUSE), 4);
        assert_eq!(params::material(gl::COLOR_INDEXES), 3);
        assert_eq!(params::material(gl::POSITION), 0);
        assert_eq!(params::light_model(gl::LIGHT_MODEL_AMBIENT), 4);
        assert_eq!(params::fog(gl::FOG_COLOR), 4);
        assert_eq!(params::tex_gen(gl::EYE_PLANE), 4);
        assert_eq!(params::tex_env(gl::TEXTURE_ENV_MODE), 1);
        assert_eq!(params::tex_parameter(gl::TEXTURE_BORDER_COLOR), 4);
        assert_eq!(params::point_parameter(gl::POINT_DISTANCE_ATTENUATION), 3);
    }
}
