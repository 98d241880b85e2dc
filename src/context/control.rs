//! Implementation hints, pixel storage modes, and flushing: `Hint`, `PixelStore{i,f}`, `Flush`,
//! `Finish` (GL 2.1 §5.6, §3.6.1, §5.5).
//!
//! Each command is outside-Begin/End only (§2.6.3).
//!
//! Pixel storage: all sixteen modes are kept (`State::pack`, `State::unpack`, see
//! `crate::pixel_store`); those fixedgl has no command for (IMAGE_HEIGHT, SKIP_IMAGES) are stored
//! and queried only.

use super::{record, Context};
use crate::call::Call;
use crate::gl;
use crate::pixel_store;

impl Context {
    /// `glHint`: every GL 2.1 target and PHONG_HINT_WIN; mode FASTEST, NICEST or DONT_CARE.
    pub fn hint(&mut self, target: u32, mode: u32) {
        record!(self, Call::Hint(target, mode));
        if !self.outside_begin_end() {
            return;
        }
        if !matches!(mode, gl::FASTEST | gl::NICEST | gl::DONT_CARE) {
            return self.error(gl::INVALID_ENUM);
        }
        let h = &mut self.state.hints;
        let slot = match target {
            gl::PERSPECTIVE_CORRECTION_HINT => &mut h.perspective_correction,
            gl::POINT_SMOOTH_HINT => &mut h.point_smooth,
            gl::LINE_SMOOTH_HINT => &mut h.line_smooth,
            gl::POLYGON_SMOOTH_HINT => &mut h.polygon_smooth,
            gl::FOG_HINT => &mut h.fog,
            gl::GENERATE_MIPMAP_HINT => &mut h.generate_mipmap,
            gl::TEXTURE_COMPRESSION_HINT => &mut h.texture_compression,
            gl::FRAGMENT_SHADER_DERIVATIVE_HINT => &mut h.fragment_shader_derivative,
            gl::PHONG_HINT_WIN => &mut h.phong,
            _ => return self.error(gl::INVALID_ENUM),
        };
        *slot = mode;
    }

    /// `glPixelStorei`: any of the sixteen modes of GL 2.1 table 3.1 (else INVALID_ENUM); a
    /// boolean is TRUE for any nonzero value, an integer must be >= 0 and an alignment 1, 2, 4
    /// or 8 (else INVALID_VALUE, nothing changed). Executed immediately in a display list
    /// (§5.4).
    pub fn pixel_storei(&mut self, pname: u32, param: i32) {
        record!(self, Call::PixelStorei(pname, param));
        self.pixel_store(pname, param);
    }

    /// `glPixelStoref`: a boolean mode is FALSE for 0.0 and TRUE otherwise, an integer mode takes
    /// the value rounded to the nearest integer (§3.6.1); see [`pixel_store::from_float`].
    pub fn pixel_storef(&mut self, pname: u32, param: f32) {
        record!(self, Call::PixelStoref(pname, param));
        self.pixel_store(pname, pixel_store::from_float(pname, param));
    }

    fn pixel_store(&mut self, pname: u32, param: i32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some((pack, mode)) = pixel_store::pname(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        let modes = if pack {
            &mut self.state.pack
        } else {
            &mut self.state.unpack
        };
        if let Err(code) = modes.set(mode, param) {
            self.error(code);
        }
    }

    /// `glFlush`: draws everything batched so far.
    pub fn flush(&mut self) {
        record!(self, Call::Flush);
        self.outside_begin_end();
    }

    /// `glFinish`: as `flush`, and the CPU renderer has rasterised everything drawn so far into
    /// the framebuffer when it returns (GL 2.1 §5.5: the effects of every earlier command are
    /// complete). Pending clears stay pending: they are the framebuffer's contents already.
    pub fn finish(&mut self) {
        record!(self, Call::Finish);
        if self.outside_begin_end() {
            self.renderer.finish();
        }
    }
}
