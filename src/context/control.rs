//! Implementation hints, pixel storage modes, and flushing: `Hint`, `PixelStore{i,f}`, `Flush`,
//! `Finish` (GL 2.1 §5.6, §3.6.1, §5.5).
//!
//! Each command is outside-Begin/End only (§2.6.3).
//!
//! Design decision: of the pixel storage modes only PACK_ALIGNMENT and UNPACK_ALIGNMENT are kept
//! (the only ones `State` holds); any other pname is INVALID_ENUM, which GL would accept.

use super::{record, Context};
use crate::call::Call;
use crate::gl;

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

    /// `glPixelStorei`: PACK_ALIGNMENT or UNPACK_ALIGNMENT, each 1, 2, 4 or 8 (GL 2.1 §3.6.1).
    pub fn pixel_storei(&mut self, pname: u32, param: i32) {
        record!(self, Call::PixelStorei(pname, param));
        self.pixel_store(pname, param);
    }

    /// `glPixelStoref`: the value is rounded to the nearest integer (GL 2.1 §3.6.1).
    pub fn pixel_storef(&mut self, pname: u32, param: f32) {
        record!(self, Call::PixelStoref(pname, param));
        // `as` saturates and maps NaN to 0, which no alignment accepts.
        self.pixel_store(pname, param.round() as i32);
    }

    fn pixel_store(&mut self, pname: u32, param: i32) {
        if !self.outside_begin_end() {
            return;
        }
        // UNPACK_ROW_LENGTH, any value >= 0 (§3.6.1, table 3.1)
        if pname == gl::UNPACK_ROW_LENGTH {
            if param < 0 {
                return self.error(gl::INVALID_VALUE);
            }
            self.state.textures.unpack_row_length = param;
            return;
        }
        if !matches!(pname, gl::PACK_ALIGNMENT | gl::UNPACK_ALIGNMENT) {
            return self.error(gl::INVALID_ENUM);
        }
        if !matches!(param, 1 | 2 | 4 | 8) {
            return self.error(gl::INVALID_VALUE);
        }
        if pname == gl::PACK_ALIGNMENT {
            self.state.pack_alignment = param;
        } else {
            self.state.unpack_alignment = param;
        }
    }

    /// `glFlush`: draws everything batched so far.
    pub fn flush(&mut self) {
        record!(self, Call::Flush);
        self.outside_begin_end();
    }

    /// `glFinish`: as `flush`; the CPU renderer has finished when it returns.
    pub fn finish(&mut self) {
        record!(self, Call::Finish);
        self.outside_begin_end();
    }
}
