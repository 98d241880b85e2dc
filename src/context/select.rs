//! Selection and feedback (GL 2.1 §5.2, §5.3): `RenderMode`, `SelectBuffer`, `FeedbackBuffer`,
//! the name stack (`InitNames`, `LoadName`, `PushName`, `PopName`) and `PassThrough`. The
//! primitives themselves go through `cpu::feedback` when a batch is flushed.
//!
//! Design decision: the buffers belong to the context. `select_buffer(size)` and
//! `feedback_buffer(size, type)` say how many values GL may write; what has been written is read
//! with [`Context::selection_buffer`] and [`Context::feedback_values`] (the C ABI copies it into
//! the caller's memory when RenderMode leaves the mode). Errors are GL 2.1's where Mesa differs:
//! RenderMode with a bad mode, or SELECT (FEEDBACK) before any SelectBuffer (FeedbackBuffer),
//! changes nothing (Mesa first ends the current mode, losing its hits, or switches anyway), and a
//! buffer of size 0 counts as given. The name stack commands are ignored outside SELECT mode, and
//! PushName and PopName write the pending hit record before checking the stack, as Mesa does.

use super::{record, Context};
use crate::call::Call;
use crate::cpu::feedback::{MAX_BUFFER, MAX_NAME_STACK_DEPTH};
use crate::gl;

impl Context {
    /// `glRenderMode`: switches between RENDER, SELECT and FEEDBACK and returns what the mode
    /// being left produced: the number of hit records (SELECT) or of values written (FEEDBACK),
    /// -1 when the buffer overflowed, 0 when leaving RENDER. INVALID_OPERATION (and 0) between
    /// Begin and End, or entering SELECT (FEEDBACK) before any SelectBuffer (FeedbackBuffer);
    /// INVALID_ENUM for another mode. Batched vertices go to the mode being left.
    pub fn render_mode(&mut self, mode: u32) -> i32 {
        if self.capturing && self.lists.depth == 0 && self.capture(Call::RenderMode(mode)) {
            return 0;
        }
        if !self.outside_begin_end() {
            return 0;
        }
        let sink = &self.renderer.sink;
        let missing = match mode {
            gl::RENDER => false,
            gl::SELECT => sink.select_size.is_none(),
            gl::FEEDBACK => sink.feedback_size.is_none(),
            _ => {
                self.error(gl::INVALID_ENUM);
                return 0;
            }
        };
        if missing {
            self.error(gl::INVALID_OPERATION);
            return 0;
        }
        let sink = &mut self.renderer.sink;
        let result = match self.state.render_mode {
            gl::SELECT => sink.end_select(),
            gl::FEEDBACK => sink.end_feedback(),
            _ => 0,
        };
        match mode {
            gl::SELECT => sink.begin_select(),
            gl::FEEDBACK => sink.begin_feedback(),
            _ => {}
        }
        self.state.render_mode = mode;
        result
    }

    /// `glSelectBuffer`: the hit records of the next selection go to a buffer of `size` values
    /// that the context keeps ([`Context::selection_buffer`] reads it). INVALID_VALUE for a
    /// negative size, then INVALID_OPERATION in SELECT mode or between Begin and End;
    /// OUT_OF_MEMORY past 2^24 values. Executed immediately, never compiled (GL 2.1 §5.4).
    pub fn select_buffer(&mut self, size: i32) {
        record!(self, Call::SelectBuffer(size));
        if !self.outside_begin_end() {
            return;
        }
        if size < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if self.state.render_mode == gl::SELECT {
            return self.error(gl::INVALID_OPERATION);
        }
        if size > MAX_BUFFER {
            return self.error(gl::OUT_OF_MEMORY);
        }
        self.renderer.sink.set_select_buffer(size as usize);
    }

    /// `glFeedbackBuffer`: feedback goes to a buffer of `size` values of `type_` (2D, 3D,
    /// 3D_COLOR, 3D_COLOR_TEXTURE, 4D_COLOR_TEXTURE; GL 2.1 table 5.2) that the context keeps
    /// ([`Context::feedback_values`] reads it). Errors in Mesa's order: INVALID_OPERATION between
    /// Begin and End or in FEEDBACK mode, INVALID_VALUE for a negative size, INVALID_ENUM for
    /// another type; OUT_OF_MEMORY past 2^24 values. Executed immediately, never compiled.
    pub fn feedback_buffer(&mut self, size: i32, type_: u32) {
        record!(self, Call::FeedbackBuffer(size, type_));
        if !self.outside_begin_end() {
            return;
        }
        if self.state.render_mode == gl::FEEDBACK {
            return self.error(gl::INVALID_OPERATION);
        }
        if size < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if !matches!(
            type_,
            gl::GL_2D
                | gl::GL_3D
                | gl::GL_3D_COLOR
                | gl::GL_3D_COLOR_TEXTURE
                | gl::GL_4D_COLOR_TEXTURE
        ) {
            return self.error(gl::INVALID_ENUM);
        }
        if size > MAX_BUFFER {
            return self.error(gl::OUT_OF_MEMORY);
        }
        self.renderer.sink.set_feedback_buffer(size as usize, type_);
    }

    /// The selection buffer's values written so far: the hit records of the current selection,
    /// or of the last one once RenderMode has left SELECT mode (until selection begins again or
    /// SelectBuffer is called). At most the SelectBuffer size: on overflow, the records that
    /// fit and the first words of the one that did not, as GL writes them. Not a GL command.
    pub fn selection_buffer(&self) -> &[u32] {
        &self.renderer.sink.select
    }

    /// The feedback buffer's values written so far, as [`Context::selection_buffer`]. Values
    /// from batched primitives appear once the batch is drawn (RenderMode, any state change,
    /// or [`Context::flush`]). Not a GL command.
    pub fn feedback_values(&self) -> &[f32] {
        &self.renderer.sink.feedback
    }

    /// `glInitNames`: writes the pending hit record (in SELECT mode) and empties the name stack.
    pub fn init_names(&mut self) {
        record!(self, Call::InitNames);
        if !self.outside_begin_end() {
            return;
        }
        if self.state.render_mode == gl::SELECT {
            self.renderer.sink.flush_hit();
        }
        self.renderer.sink.names.clear();
    }

    /// `glLoadName`: replaces the top of the name stack, writing the pending hit record first.
    /// Ignored outside SELECT mode; INVALID_OPERATION on an empty stack.
    pub fn load_name(&mut self, name: u32) {
        record!(self, Call::LoadName(name));
        if !self.outside_begin_end() || self.state.render_mode != gl::SELECT {
            return;
        }
        let sink = &mut self.renderer.sink;
        if sink.names.is_empty() {
            return self.error(gl::INVALID_OPERATION);
        }
        sink.flush_hit();
        if let Some(top) = sink.names.last_mut() {
            *top = name;
        }
    }

    /// `glPushName`: writes the pending hit record, then pushes `name`; STACK_OVERFLOW past
    /// MAX_NAME_STACK_DEPTH (64). Ignored outside SELECT mode.
    pub fn push_name(&mut self, name: u32) {
        record!(self, Call::PushName(name));
        if !self.outside_begin_end() || self.state.render_mode != gl::SELECT {
            return;
        }
        let sink = &mut self.renderer.sink;
        sink.flush_hit();
        if sink.names.len() >= MAX_NAME_STACK_DEPTH {
            return self.error(gl::STACK_OVERFLOW);
        }
        sink.names.push(name);
    }

    /// `glPopName`: writes the pending hit record, then pops; STACK_UNDERFLOW on an empty
    /// stack. Ignored outside SELECT mode.
    pub fn pop_name(&mut self) {
        record!(self, Call::PopName);
        if !self.outside_begin_end() || self.state.render_mode != gl::SELECT {
            return;
        }
        let sink = &mut self.renderer.sink;
        sink.flush_hit();
        if sink.names.pop().is_none() {
            self.error(gl::STACK_UNDERFLOW);
        }
    }

    /// What Bitmap, DrawPixels and CopyPixels do in place of drawing when the render mode is
    /// not RENDER (GL 2.1 §5.3, as Mesa's `drawpix.c`): in FEEDBACK mode `token` (BITMAP_TOKEN,
    /// DRAW_PIXEL_TOKEN or COPY_PIXEL_TOKEN) and the current raster position as a vertex of the
    /// buffer's type (window coordinates and clip w, the raster colour, unit 0's raster texture
    /// coordinates), after what is batched; in SELECT mode nothing (GL 2.1 appendix B,
    /// corollary 6: they do not affect the hits; RasterPos and WindowPos record the hit).
    /// Returns whether the mode is RENDER, that is whether the caller draws. The raster
    /// position is valid here (the callers return first otherwise).
    pub(super) fn raster_rect_token(&mut self, token: u32) -> bool {
        match self.state.render_mode {
            gl::FEEDBACK => {
                self.renderer.flush(&self.state);
                let r = self.state.raster_pos;
                self.renderer.sink.raster_token(
                    token,
                    r.window.to_array(),
                    r.color,
                    r.tex_coords[0],
                );
                false
            }
            gl::SELECT => false,
            _ => true,
        }
    }

    /// RasterPos or WindowPos has made a valid raster position: in SELECT mode its window z
    /// joins the pending hit (Mesa's `_mesa_RasterPos` and `window_pos3f` call
    /// `_mesa_update_hitflag`; GL 2.1 §5.2 names only primitives and RasterPos, with which
    /// WindowPos is one command group).
    pub(super) fn raster_pos_hit(&mut self) {
        if self.state.render_mode == gl::SELECT {
            let z = self.state.raster_pos.window.z;
            self.renderer.sink.update_hit(z);
        }
    }

    /// `glPassThrough`: in FEEDBACK mode, PASS_THROUGH_TOKEN and `token` after what is batched;
    /// ignored in the other modes.
    pub fn pass_through(&mut self, token: f32) {
        record!(self, Call::PassThrough(token));
        if !self.outside_begin_end() || self.state.render_mode != gl::FEEDBACK {
            return;
        }
        let sink = &mut self.renderer.sink;
        sink.token(gl::PASS_THROUGH_TOKEN as f32);
        sink.token(token);
    }
}
