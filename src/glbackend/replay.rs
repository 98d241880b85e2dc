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
        self.dispatch(call);
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

    /// `Fogf`/`Fogi`: GL 2.1 (glFog reference page) takes FOG_COLOR only through the vector
    /// forms; Mesa also takes it here. Raised here as for Begin, so both backends agree.
    pub(super) fn replay_fogf(&mut self, pname: u32, param: f32) {
        if pname == gl::FOG_COLOR && !self.inside_begin_end {
            return self.raise(gl::INVALID_ENUM);
        }
        Safe(&self.raw).fogf(pname, param);
    }

    /// `Fogi`: as [`Self::replay_fogf`].
    pub(super) fn replay_fogi(&mut self, pname: u32, param: i32) {
        if pname == gl::FOG_COLOR && !self.inside_begin_end {
            return self.raise(gl::INVALID_ENUM);
        }
        Safe(&self.raw).fogi(pname, param);
    }

    /// `BlendFunc`: SRC_ALPHA_SATURATE is a source factor only in GL 2.1 (§4.1.8); a driver
    /// with ARB_blend_func_extended takes it as a destination too.
    pub(super) fn replay_blend_func(&mut self, sfactor: u32, dfactor: u32) {
        if dfactor == gl::SRC_ALPHA_SATURATE && !self.inside_begin_end {
            return self.raise(gl::INVALID_ENUM);
        }
        Safe(&self.raw).blend_func(sfactor, dfactor);
    }

    /// `BlendFuncSeparate`: as [`Self::replay_blend_func`], for both destination factors.
    pub(super) fn replay_blend_func_separate(
        &mut self,
        src_rgb: u32,
        dst_rgb: u32,
        src_a: u32,
        dst_a: u32,
    ) {
        let saturate = gl::SRC_ALPHA_SATURATE;
        if (dst_rgb == saturate || dst_a == saturate) && !self.inside_begin_end {
            return self.raise(gl::INVALID_ENUM);
        }
        Safe(&self.raw).blend_func_separate(src_rgb, dst_rgb, src_a, dst_a);
    }

    /// `Hint`: PHONG_HINT_WIN (GL_WIN_phong_shading) is not a target the driver knows, so it is
    /// validated here with the rules of GL 2.1 §5.6 (INVALID_OPERATION inside Begin/End, then
    /// INVALID_ENUM for a bad mode) and, having no effect on the emulation, not sent on.
    pub(super) fn hint(&mut self, target: u32, mode: u32) {
        if target != gl::PHONG_HINT_WIN {
            // SAFETY: the context is current (see `execute`); no pointers.
            return unsafe { self.raw.Hint(target, mode) };
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
