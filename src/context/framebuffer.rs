//! Framebuffer control and per-fragment state: `ClearColor`, `ClearDepth`, `ClearStencil`,
//! `Clear`, `DepthFunc`, `DepthMask`, `ColorMask`, `Scissor` (GL 2.1 §4.1.2, §4.1.5, §4.2.2,
//! §4.2.3).
//!
//! Each command is outside-Begin/End only (§2.6.3). `Clear` validates its mask, then hands the
//! clear to the renderer with the current state (scissor and write masks apply, §4.2.3).
//!
//! Design decision: clear values are clamped to [0, 1] when set, as GL 2.1 §4.2.3 specifies, so
//! state and queries hold the clamped values.

use glam::Vec4;

use super::{record, Context};
use crate::call::Call;
use crate::gl;

/// The buffer bits `Clear` accepts (GL 2.1 §4.2.3); a bit for a buffer the framebuffer lacks
/// clears nothing.
const CLEAR_BITS: u32 =
    gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT | gl::ACCUM_BUFFER_BIT;

impl Context {
    /// `glClearColor`: components clamped to [0, 1].
    pub fn clear_color(&mut self, red: f32, green: f32, blue: f32, alpha: f32) {
        record!(self, Call::ClearColor(red, green, blue, alpha));
        if !self.outside_begin_end() {
            return;
        }
        self.state.clear_color = Vec4::new(red, green, blue, alpha).clamp(Vec4::ZERO, Vec4::ONE);
    }

    /// `glClearIndex` (GL 2.1 §4.2.3): stored as Mesa does, the integer part as an unsigned
    /// integer (`(GLuint) c`; a negative or NaN index is 0 here, where C leaves it undefined).
    /// Only a colour-index framebuffer uses it, and fixedgl's are RGBA: nothing else changes.
    pub fn clear_index(&mut self, c: f32) {
        record!(self, Call::ClearIndex(c));
        if !self.outside_begin_end() {
            return;
        }
        // `as` saturates: negative and NaN give 0, past u32::MAX gives u32::MAX.
        self.state.clear_index = c as u32;
    }

    /// `glClearDepth`: clamped to [0, 1].
    pub fn clear_depth(&mut self, depth: f64) {
        record!(self, Call::ClearDepth(depth));
        if !self.outside_begin_end() {
            return;
        }
        self.state.clear_depth = depth.clamp(0.0, 1.0);
    }

    /// `glClearStencil`.
    pub fn clear_stencil(&mut self, s: i32) {
        record!(self, Call::ClearStencil(s));
        if !self.outside_begin_end() {
            return;
        }
        self.state.clear_stencil = s;
    }

    /// `glClear`: INVALID_VALUE for any bit other than COLOR, DEPTH, STENCIL, ACCUM_BUFFER_BIT.
    /// Colour goes to the buffers DRAW_BUFFER names. In SELECT and FEEDBACK render modes it
    /// clears nothing, as Mesa does.
    pub fn clear(&mut self, mask: u32) {
        record!(self, Call::Clear(mask));
        if !self.outside_begin_end() {
            return;
        }
        if mask & !CLEAR_BITS != 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        if self.state.render_mode != gl::RENDER {
            return;
        }
        if mask & gl::ACCUM_BUFFER_BIT != 0 {
            self.clear_accum_buffer();
        }
        let mask = mask & !gl::ACCUM_BUFFER_BIT;
        if mask != 0 {
            self.renderer.clear(&self.state, mask);
        }
    }

    /// `glDepthFunc`: one of the eight comparison functions (GL 2.1 §4.1.6).
    pub fn depth_func(&mut self, func: u32) {
        record!(self, Call::DepthFunc(func));
        if !self.outside_begin_end() {
            return;
        }
        match func {
            gl::NEVER..=gl::ALWAYS => self.state.depth_func = func,
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glDepthMask` (GL 2.1 §4.2.2).
    pub fn depth_mask(&mut self, flag: bool) {
        record!(self, Call::DepthMask(flag));
        if !self.outside_begin_end() {
            return;
        }
        self.state.depth_mask = flag;
    }

    /// `glColorMask` (GL 2.1 §4.2.2).
    pub fn color_mask(&mut self, red: bool, green: bool, blue: bool, alpha: bool) {
        record!(self, Call::ColorMask(red, green, blue, alpha));
        if !self.outside_begin_end() {
            return;
        }
        self.state.color_mask = [red, green, blue, alpha];
    }

    /// `glIndexMask` (GL 2.1 §4.2.2): the colour-index write mask, all ones at first. Only a
    /// colour-index framebuffer uses it, and fixedgl's are RGBA: nothing else changes.
    pub fn index_mask(&mut self, mask: u32) {
        record!(self, Call::IndexMask(mask));
        if !self.outside_begin_end() {
            return;
        }
        self.state.index_writemask = mask;
    }

    /// `glScissor`: INVALID_VALUE if `width` or `height` is negative (GL 2.1 §4.1.2).
    pub fn scissor(&mut self, x: i32, y: i32, width: i32, height: i32) {
        record!(self, Call::Scissor(x, y, width, height));
        if !self.outside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        self.state.scissor = [x, y, width, height];
    }
}
