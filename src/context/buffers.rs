//! The framebuffer's buffers as a whole (GL 2.1 §4.2.1, §4.2.4, §4.3.2): `DrawBuffer`,
//! `ReadBuffer`, `Accum`, `ClearAccum`, and what the window system does to them (not GL
//! commands): a buffer swap, a resize, the front buffer read for presenting.
//!
//! Design decision: the framebuffer's buffers are fixed when the context is made
//! ([`ContextConfig`]); DRAW_BUFFER and READ_BUFFER hold the enum as given (as Mesa reports
//! it), validated by `crate::buffers`, which the GL backend validates with too. Where GL 2.1 and
//! Mesa disagree (Mesa takes BACK on a single-buffered framebuffer, and NONE and FRONT_AND_BACK
//! in ReadBuffer), fixedgl raises GL 2.1's error.

use glam::Vec4;

use super::{record, Context};
use crate::buffers;
use crate::call::Call;
use crate::cpu::framebuffer::{read_buf, scissor_rect, ColorBuf, Targets};
use crate::gl;
use crate::state::{ContextConfig, MAX_VIEWPORT_DIM};
use crate::Error;

impl Context {
    /// `glDrawBuffer` (GL 2.1 §4.2.1): the colour buffers drawing, Clear and Accum(RETURN)
    /// write. INVALID_ENUM for a value not in table 4.4; INVALID_OPERATION when `buf` names no
    /// buffer this framebuffer has (BACK on a single-buffered one, any RIGHT or AUXi).
    pub fn draw_buffer(&mut self, buf: u32) {
        record!(self, Call::DrawBuffer(buf));
        if !self.outside_begin_end() {
            return;
        }
        let error = match self.fbos.bound_fb {
            0 => buffers::draw_error(buf, &self.state.config),
            _ => buffers::fbo_draw_error(buf),
        };
        if let Some(e) = error {
            return self.error(e);
        }
        self.state.draw_buffer = buf;
        self.fbo_buffers_changed();
    }

    /// `glReadBuffer` (GL 2.1 §4.3.2): the colour buffer ReadPixels, CopyTexImage and
    /// Accum(LOAD, ACCUM) read. INVALID_ENUM for a value GL 2.1's ReadBuffer does not take
    /// (NONE and FRONT_AND_BACK among them); INVALID_OPERATION for a buffer this framebuffer
    /// lacks.
    pub fn read_buffer(&mut self, buf: u32) {
        record!(self, Call::ReadBuffer(buf));
        if !self.outside_begin_end() {
            return;
        }
        let error = match self.fbos.bound_fb {
            0 => buffers::read_error(buf, &self.state.config),
            _ => buffers::fbo_read_error(buf),
        };
        if let Some(e) = error {
            return self.error(e);
        }
        self.state.read_buffer = buf;
        self.fbo_buffers_changed();
    }

    /// `glClearAccum`: the accumulation buffer's clear value, each component clamped to
    /// [-1, 1] (GL 2.1 §4.2.3).
    pub fn clear_accum(&mut self, red: f32, green: f32, blue: f32, alpha: f32) {
        record!(self, Call::ClearAccum(red, green, blue, alpha));
        if !self.outside_begin_end() {
            return;
        }
        self.state.accum_clear = Vec4::new(red, green, blue, alpha).clamp(-Vec4::ONE, Vec4::ONE);
    }

    /// `glAccum` (GL 2.1 §4.2.4): LOAD, ACCUM, MULT, ADD or RETURN over the window (cut by the
    /// scissor box). INVALID_ENUM for another `op`, then INVALID_OPERATION without an
    /// accumulation buffer (`ContextConfig::accum`). In SELECT and FEEDBACK render modes it
    /// does nothing (as Mesa). The arithmetic is Mesa's, bit for bit (`cpu::accum`).
    pub fn accum(&mut self, op: u32, value: f32) {
        record!(self, Call::Accum(op, value));
        if !self.outside_begin_end() {
            return;
        }
        if !matches!(op, gl::ACCUM | gl::LOAD | gl::RETURN | gl::MULT | gl::ADD) {
            return self.error(gl::INVALID_ENUM);
        }
        if !self.state.config.accum {
            return self.error(gl::INVALID_OPERATION);
        }
        if self.state.render_mode != gl::RENDER {
            return;
        }
        let rect = scissor_rect(&self.state);
        let (read, targets) = (read_buf(&self.state), Targets::of(&self.state));
        let mask = self.state.color_write_mask();
        self.renderer
            .framebuffer_mut()
            .accum(op, value, rect, read, targets, mask);
    }

    /// Clears the accumulation buffer (Clear's ACCUM_BUFFER_BIT) inside the scissor box.
    pub(super) fn clear_accum_buffer(&mut self) {
        let c = self.state.accum_clear;
        let value = [c.x, c.y, c.z, c.w].map(crate::cpu::accum::clear_value);
        let rect = scissor_rect(&self.state);
        self.renderer.framebuffer_mut().clear_accum(value, rect);
    }

    /// What a window system's buffer swap does (glXSwapBuffers, glutSwapBuffers; not a GL
    /// command, recorded as `Call::SwapBuffers` so that replays see the same frames): draws what
    /// is batched, then the back buffer becomes the front buffer. GL leaves the back buffer's
    /// contents afterwards undefined; fixedgl keeps them, as llvmpipe's software window system
    /// does (measured under GLX: the back buffer reads the same after a swap). Nothing on a
    /// single-buffered context, and nothing between Begin and End (GLX leaves that undefined;
    /// Mesa's swap raises no GL error there, so the command table lists it as allowed inside).
    pub fn swap_buffers(&mut self) {
        record!(self, Call::SwapBuffers);
        if self.begin_mode.is_some() {
            return;
        }
        self.renderer.flush(&self.state);
        // A framebuffer object bound: the window's framebuffer is set aside (context/fbo.rs).
        if !self.fbos.swap_window() {
            self.renderer.framebuffer_mut().swap();
        }
    }

    /// The front colour buffer (the only one of a single-buffered context: what a window
    /// shows) as RGBA8 bytes, top row first (image order, as [`Context::to_image`]), `width *
    /// height * 4` bytes. Draws what is batched first (between Begin and End: what is drawn so
    /// far). Not a GL command.
    pub fn front_rgba(&mut self) -> Vec<u8> {
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        // A framebuffer object bound: the window's framebuffer is set aside (context/fbo.rs).
        if let Some(bytes) = self.fbos.window_front_rgba() {
            return bytes;
        }
        let buf = match self.state.config.double_buffered {
            true => ColorBuf::Front,
            false => ColorBuf::Main,
        };
        self.renderer.color_bytes_top_down(buf)
    }

    /// Resizes every buffer of the framebuffer to `width` x `height` (a window resized; not a
    /// GL command, never recorded). What fits in both sizes is kept, pixel for pixel from the
    /// lower-left corner, the rest starts as a new framebuffer's (colour 0, depth 1, stencil 0,
    /// accumulation 0); GL leaves all of it undefined. The viewport and scissor box are not
    /// changed: GL sets them to the window's size only when a context is first made current
    /// (GL 2.1 §2.11.1, §4.1.2), so a program's reshape callback sets the viewport itself.
    /// Batched vertices are drawn first (between Begin and End, those of the open primitive
    /// are drawn into the resized framebuffer when it ends). Errors: [`Error::InvalidSize`] for a side of 0 or
    /// above 16384, [`Error::OutOfMemory`] when the buffers cannot be allocated (the old ones
    /// are then kept).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), Error> {
        if width == 0 || height == 0 || width > MAX_VIEWPORT_DIM || height > MAX_VIEWPORT_DIM {
            return Err(Error::InvalidSize { width, height });
        }
        let open = self.begin_mode.is_some();
        // A framebuffer object bound: the window's framebuffer is set aside (context/fbo.rs).
        if self.fbos.resize_window(width, height) {
            return Ok(());
        }
        if self.fbos.bound_fb != 0 {
            return Err(Error::OutOfMemory { width, height });
        }
        if !self.renderer.resize(&self.state, width, height, open) {
            return Err(Error::OutOfMemory { width, height });
        }
        self.state.width = width;
        self.state.height = height;
        Ok(())
    }

    /// Draws the window's framebuffer as Mesa's llvmpipe draws a window-system framebuffer (a
    /// GLX window, an EGL surface, an OSMesa buffer: `true`) or a framebuffer object (`false`,
    /// the default, what [`crate::glbackend::GlBackend::new`] compares with). The two differ only
    /// in which pixel a line draws when an end lies exactly on a pixel centre's row or column
    /// (docs/conformance.md, "line ends on pixel centres"): the driver sets lines up in its own
    /// y-down coordinates, and a window's are the other way up. The C ABI sets it for every
    /// window-system framebuffer. Not a GL command, never recorded; vertices batched before it
    /// are drawn first (outside Begin/End; inside, the open primitive's lines follow the new
    /// setting). Framebuffer objects are always drawn as objects.
    pub fn set_window_system_framebuffer(&mut self, on: bool) {
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        if !self.fbos.set_window_y0_top(on) {
            self.state.y0_top = on;
        }
    }

    /// The buffers this context's framebuffer has.
    pub fn config(&self) -> ContextConfig {
        self.state.config
    }
}
