//! The replay proper: each [`Call`] becomes the driver call of the same name with the same
//! arguments (GL 2.1 §2.5 onwards; the variant name is the GL function minus `gl`).
//!
//! `execute` does what every call needs (make the context current, the PHONG_WIN and display-list
//! mirrors, the Begin/End phase), then `dispatch`, generated from the command table
//! (`glbackend/generated.rs`), sends the call on: through a safe wrapper of the driver's entry
//! point for most commands, through [`GlBackend::with_params`] for pname-dependent vectors (sized
//! by [`counts`]), or through the backend's own method where the table's `replay=` names one (the
//! GL 2.1 rules a newer driver relaxes, PHONG_WIN emulation, lists, arrays, textures).
//!
//! Design decision: `dispatch` is exhaustive (no `_ =>`), so a command added to the table cannot
//! compile until it is replayed.

use super::generated::Safe;
use super::GlBackend;
use crate::counts;
use crate::gl;
use crate::pixel_store;
use crate::Call;

impl GlBackend {
    /// Sends one recorded call to the driver, exactly as the user's program would have made it.
    pub fn execute(&mut self, call: &Call) {
        self.make_current();
        if !phong_neutral(call) {
            self.phong_dirty = true;
        }
        // lists: the mirror of the display list being defined (lists.rs).
        self.mirror_call(call);
        // GL 2.1 §2.6.3, raised here rather than by the driver: inside Begin/End the driver's
        // error flag cannot be read, so an error it held could not be ordered against one this
        // backend raises itself (a short slice, an array element it refuses to read).
        if self.inside_begin_end && !call.allowed_between_begin_end() {
            self.list_needs_expansion();
            return self.raise(gl::INVALID_OPERATION);
        }
        if let Some(code) = gl21_error(call) {
            // The driver's list would hold the call without the error: run it from the mirror.
            self.list_needs_expansion();
            if self.compile_only() {
                return;
            }
            return self.raise(code);
        }
        if let Some(vector) = scalar_as_vector(call) {
            return self.dispatch(&vector);
        }
        match *call {
            Call::PixelStorei(pname, param) => self.pixel_store(pname, param),
            Call::PixelStoref(pname, param) => {
                self.pixel_store(pname, pixel_store::from_float(pname, param))
            }
            _ => self.dispatch(call),
        }
    }

    /// `PixelStore{i,f}` (executed immediately, never compiled: GL 2.1 §5.4), with `param`
    /// already converted as §3.6.1 says (`pixel_store::from_float` for the f form, the one
    /// conversion the front end uses too). A pname outside GL 2.1 table 3.1 is INVALID_ENUM
    /// raised here (Mesa also takes PACK_INVERT_MESA and GL 4.2's compressed-block pnames); a
    /// boolean goes to the driver as 0 or 1, so that it stores the spec's TRUE for any nonzero
    /// value whatever it makes of other integers. The driver then holds exactly the modes the
    /// CPU `State` does, and raises INVALID_VALUE itself.
    fn pixel_store(&mut self, pname: u32, param: i32) {
        let Some((_, mode)) = pixel_store::pname(pname) else {
            return self.raise(gl::INVALID_ENUM);
        };
        let param = if mode.is_boolean() {
            i32::from(param != 0)
        } else {
            param
        };
        Safe(&self.raw).pixel_storei(pname, param);
    }

    /// `Begin`: under NewList(COMPILE) the driver only stores it. Otherwise GL 2.1 §2.6.1 has
    /// ten modes, while a 3.2+ compatibility driver also accepts the adjacency modes and PATCHES
    /// (0xA..=0xE), so the GL 2.1 INVALID_ENUM is raised here; inside Begin/End the driver's
    /// INVALID_OPERATION comes first, as in GL.
    pub(super) fn replay_begin(&mut self, mode: u32) {
        if !self.compile_only() {
            if mode > gl::POLYGON && !self.inside_begin_end {
                return self.raise(gl::INVALID_ENUM);
            }
            self.before_begin();
        }
        Safe(&self.raw).begin(mode);
        // The driver opened a primitive iff none was open (the mode is valid here).
        if !self.compile_only() {
            self.inside_begin_end = true;
        }
    }

    /// `End`: closes the pair the driver opened (under NewList(COMPILE), only stored).
    pub(super) fn replay_end(&mut self) {
        Safe(&self.raw).end();
        if !self.compile_only() {
            self.inside_begin_end = false;
        }
    }

    /// `Materialf`: a vector pname is sent as `Materialfv([param, 0, 0, 0])`, the values the
    /// front end stores (`Context::material`); the driver's own `Materialf` would read three
    /// uninitialised floats after `param`. SHININESS and bad pnames go to the driver as they are.
    pub(super) fn materialf(&mut self, face: u32, pname: u32, param: f32) {
        if counts::material(pname).is_some_and(|n| n > 1) {
            let mut v = [0.0; counts::MAX_VALUES];
            v[0] = param;
            return Safe(&self.raw).materialfv(face, pname, &v);
        }
        Safe(&self.raw).materialf(face, pname, param);
    }

    /// `Materiali`: as `materialf`, `param` converted as a float (not normalised), as Mesa's
    /// `_mesa_Materiali` does.
    pub(super) fn materiali(&mut self, face: u32, pname: u32, param: i32) {
        if counts::material(pname).is_some_and(|n| n > 1) {
            let mut v = [0.0; counts::MAX_VALUES];
            #[allow(clippy::cast_precision_loss)]
            {
                v[0] = param as f32;
            }
            return Safe(&self.raw).materialfv(face, pname, &v);
        }
        Safe(&self.raw).materiali(face, pname, param);
    }

    /// `Hint`: PHONG_HINT_WIN (GL_WIN_phong_shading) is not a target the driver knows, so it is
    /// validated here with the rules of GL 2.1 §5.6 (INVALID_OPERATION inside Begin/End, then
    /// INVALID_ENUM for a bad mode) and, having no effect on the emulation, not sent on.
    pub(super) fn hint(&mut self, target: u32, mode: u32) {
        if target != gl::PHONG_HINT_WIN {
            return Safe(&self.raw).hint(target, mode);
        }
        // lists: the driver's list cannot hold this hint; its errors come when the list runs.
        self.list_needs_expansion();
        if self.compile_only() {
            return;
        }
        if self.inside_begin_end {
            self.raise(gl::INVALID_OPERATION);
        } else if !matches!(mode, gl::FASTEST | gl::NICEST | gl::DONT_CARE) {
            self.raise(gl::INVALID_ENUM);
        }
    }

    /// Calls the driver with a pname-dependent parameter slice `v` of which GL reads `needed`
    /// values, or — when `v` is shorter — records INVALID_VALUE as the CPU front end does and
    /// calls nothing. Between Begin and End a command not `allowed_in_begin_end` is an
    /// INVALID_OPERATION first (GL 2.1 §2.6.3), short slice or not. The driver always gets a
    /// buffer of at least [`counts::MAX_VALUES`] values (the slice, zero-padded), so a pname
    /// `counts` does not know (`None`: the driver raises INVALID_ENUM, or takes it if it knows
    /// better, which the error-agreement tests catch) can never make it read past the data.
    pub(super) fn with_params<T: Copy + Default>(
        &mut self,
        v: &[T],
        needed: Option<usize>,
        allowed_in_begin_end: bool,
        call: impl FnOnce(Safe<'_>, &[T]),
    ) {
        if v.len() < needed.unwrap_or(0) {
            // lists: the driver's list cannot hold this call; its error comes when the list runs.
            self.list_needs_expansion();
            if self.compile_only() {
                return;
            }
            let code = if self.inside_begin_end && !allowed_in_begin_end {
                gl::INVALID_OPERATION
            } else {
                gl::INVALID_VALUE
            };
            return self.raise(code);
        }
        let mut padded = [T::default(); counts::MAX_VALUES];
        if v.len() >= padded.len() {
            call(Safe(&self.raw), v);
        } else {
            padded[..v.len()].copy_from_slice(v);
            call(Safe(&self.raw), &padded);
        }
    }
}

/// A scalar form (f, i, d) given a multi-valued pname, as the vector form the front end stores:
/// `[param, 0, 0, 0]` (three values for POINT_DISTANCE_ATTENUATION), converted as the front end
/// converts the scalar. GL 2.1 makes these calls INVALID_ENUM (§2.11.4, §2.14.2, §3.4, §3.8.4,
/// §3.8.13, §3.10), but Mesa in every version takes them, passing `param` on to the vector form,
/// and programs (piglit's gl-1.0-beginend-coverage among them) rely on it, so fixedgl takes them
/// too; sending the vector leaves nothing for the driver to fill in its own way.
fn scalar_as_vector(call: &Call) -> Option<Call> {
    let vector = |count: Option<usize>| count.is_some_and(|n| n > 1);
    let f4 = |x: f32| vec![x, 0.0, 0.0, 0.0];
    #[allow(clippy::cast_precision_loss)]
    let i2f = |x: i32| x as f32;
    Some(match *call {
        Call::Lightf(l, p, x) if vector(counts::light(p)) => Call::Lightfv(l, p, f4(x)),
        Call::Lighti(l, p, x) if vector(counts::light(p)) => Call::Lightfv(l, p, f4(i2f(x))),
        Call::LightModelf(p, x) if vector(counts::light_model(p)) => Call::LightModelfv(p, f4(x)),
        Call::LightModeli(p, x) if vector(counts::light_model(p)) => {
            Call::LightModelfv(p, f4(i2f(x)))
        }
        Call::Fogf(p, x) if vector(counts::fog(p)) => Call::Fogfv(p, f4(x)),
        Call::Fogi(p, x) if vector(counts::fog(p)) => Call::Fogfv(p, f4(i2f(x))),
        Call::PointParameterf(p, x) if vector(counts::point_parameter(p)) => {
            Call::PointParameterfv(p, vec![x, 0.0, 0.0])
        }
        Call::PointParameteri(p, x) if vector(counts::point_parameter(p)) => {
            Call::PointParameterfv(p, vec![i2f(x), 0.0, 0.0])
        }
        // TexParameter and TexEnv: an integer colour is normalised, as the iv form's.
        Call::TexParameterf(t, p, x) if vector(counts::tex_parameter(p)) => {
            Call::TexParameterfv(t, p, f4(x))
        }
        Call::TexParameteri(t, p, x) if vector(counts::tex_parameter(p)) => {
            Call::TexParameteriv(t, p, vec![x, 0, 0, 0])
        }
        Call::TexEnvf(t, p, x) if vector(counts::tex_env(p)) => Call::TexEnvfv(t, p, f4(x)),
        Call::TexEnvi(t, p, x) if vector(counts::tex_env(p)) => {
            Call::TexEnviv(t, p, vec![x, 0, 0, 0])
        }
        Call::TexGenf(c, p, x) if vector(counts::tex_gen(p)) => Call::TexGenfv(c, p, f4(x)),
        Call::TexGend(c, p, x) if vector(counts::tex_gen(p)) => {
            Call::TexGendv(c, p, vec![x, 0.0, 0.0, 0.0])
        }
        Call::TexGeni(c, p, x) if vector(counts::tex_gen(p)) => {
            Call::TexGeniv(c, p, vec![x, 0, 0, 0])
        }
        _ => return None,
    })
}

/// The GL 2.1 errors a newer driver does not raise, because a later version or an extension it
/// implements relaxes the rule; the backend raises them itself, so that both backends give the
/// spec's error (the error-agreement test walks every pname-taking command for this).
fn gl21_error(call: &Call) -> Option<u32> {
    // GL 2.1 table 3.21's sources; ZERO and ONE come with ATI_texture_env_combine3, and the
    // driver has more units than fixedgl's MAX_TEXTURE_UNITS, whose TEXTUREn (n past the last
    // unit, up to TEXTURE31) the spec makes INVALID_ENUM (§3.8.13).
    let zero_one_source = |pname: u32, v: f64| {
        let past_units = f64::from(gl::TEXTURE0 + crate::state::MAX_TEXTURE_UNITS as u32)
            ..=f64::from(gl::TEXTURE0 + 31);
        (gl::SRC0_RGB..=gl::SRC2_ALPHA).contains(&pname)
            && ((0.0..2.0).contains(&v) || past_units.contains(&v))
    };
    let wrong = match *call {
        Call::TexEnvf(_, p, v) => zero_one_source(p, f64::from(v)),
        Call::TexEnvi(_, p, v) => zero_one_source(p, f64::from(v)),
        Call::TexEnvfv(_, p, ref v) => v.first().is_some_and(|&x| zero_one_source(p, f64::from(x))),
        Call::TexEnviv(_, p, ref v) => v.first().is_some_and(|&x| zero_one_source(p, f64::from(x))),
        // SRC_ALPHA_SATURATE is a source factor only (§4.1.8); ARB_blend_func_extended takes it
        // as a destination too.
        Call::BlendFunc(_, d) => d == gl::SRC_ALPHA_SATURATE,
        Call::BlendFuncSeparate(_, d, _, da) => {
            d == gl::SRC_ALPHA_SATURATE || da == gl::SRC_ALPHA_SATURATE
        }
        // GL 2.1 §4.3.3: COLOR, DEPTH or STENCIL, and GL_EXT_packed_depth_stencil's
        // DEPTH_STENCIL, as the driver (after its INVALID_VALUE for a negative size, which stays
        // the driver's). A newer driver takes its own further types (NV_copy_depth_to_color).
        Call::CopyPixels(_, _, w, h, t) => {
            w >= 0
                && h >= 0
                && !matches!(t, gl::COLOR | gl::DEPTH | gl::STENCIL | gl::DEPTH_STENCIL)
        }
        // SAMPLES_PASSED is GL 2.1's only query target (§4.1.7); a 4.5 driver takes more.
        Call::BeginQuery(t, _) | Call::EndQuery(t) => t != gl::SAMPLES_PASSED,
        _ => false,
    };
    wrong.then_some(gl::INVALID_ENUM)
}

/// Calls that can never change what the PHONG_WIN program depends on (LIGHTING, the light
/// enables, the light model, COLOR_MATERIAL), so they need not trigger a re-read before the next
/// Begin. Anything not listed here does: a new variant is correct by default, merely slower.
pub(super) fn phong_neutral(call: &Call) -> bool {
    // The vertex attributes, Material and ArrayElement: what GL allows between Begin and End,
    // except a display list, which may hold anything.
    matches!(call, Call::Begin(_))
        || (call.allowed_between_begin_end()
            && !matches!(call, Call::CallList(_) | Call::CallLists(..)))
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
        let lightfv = |pname: u32| move |gl: Safe<'_>, v: &[f32]| gl.lightfv(gl::LIGHT0, pname, v);
        // POSITION needs 4 values: 3 is INVALID_VALUE and the initial (0,0,1,0) stays.
        b.with_params(
            &[5.0, 5.0, 5.0],
            counts::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), [0.0, 0.0, 1.0, 0.0]);
        // Enough values: applied (identity modelview, so stored as given).
        let v = [1.0, 2.0, 3.0, 1.0];
        b.with_params(
            &v,
            counts::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::NO_ERROR);
        assert_eq!(light0_position(&b), v);
        // An unknown pname needs nothing of ours: the driver's INVALID_ENUM.
        b.with_params(&[], counts::light(0x1234), false, lightfv(0x1234));
        assert_eq!(b.get_error(), gl::INVALID_ENUM);
        // Between Begin and End a command not allowed there is INVALID_OPERATION first...
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(
            &[1.0],
            counts::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_OPERATION);
        // ...while Material, allowed there, reports the short slice.
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(&[1.0], counts::material(gl::DIFFUSE), true, |gl, v| {
            gl.materialfv(gl::FRONT, gl::DIFFUSE, v)
        });
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), v);
    }
}
