//! Selection and feedback on the driver (GL 2.1 §5.2, §5.3): the buffers the driver writes
//! belong to the backend, and RenderMode is validated here first.
//!
//! The driver gets a buffer of the size given (at least one value: Mesa takes a size of 0 as
//! "no buffer" and refuses RenderMode(SELECT) then, where GL 2.1 counts it as given; with one
//! value of room, every hit still overflows a size-0 buffer). RenderMode with a bad mode, or
//! SELECT/FEEDBACK before any buffer, is raised here and never reaches the driver, which would
//! end the current mode (losing its hits) or switch anyway. What the driver wrote is read with
//! [`GlBackend::selection_buffer`] and [`GlBackend::feedback_values`] once RenderMode has left
//! the mode, the part it filled (from RenderMode's result).

use super::GlBackend;
use crate::cpu::feedback::MAX_BUFFER;
use crate::gl;

/// The backend's selection and feedback buffers and what it knows of the driver's mode.
#[derive(Debug)]
pub(super) struct Buffers {
    mode: u32,
    /// The selection buffer (allocated for the driver) and the size given, once SelectBuffer
    /// was taken.
    select: Option<(Box<[u32]>, usize)>,
    select_filled: usize,
    feedback: Option<(Box<[f32]>, usize)>,
    feedback_filled: usize,
    /// What the last RenderMode returned.
    last: i32,
}

impl Default for Buffers {
    fn default() -> Self {
        Buffers {
            mode: gl::RENDER,
            select: None,
            select_filled: 0,
            feedback: None,
            feedback_filled: 0,
            last: 0,
        }
    }
}

impl GlBackend {
    /// `RenderMode` (executed immediately, never compiled): validated as GL 2.1 says, sent,
    /// and its result kept for [`GlBackend::render_mode_result`].
    pub(super) fn render_mode(&mut self, mode: u32) {
        let b = &self.select;
        let missing = match mode {
            gl::RENDER => false,
            gl::SELECT => b.select.is_none(),
            gl::FEEDBACK => b.feedback.is_none(),
            _ => return self.raise(gl::INVALID_ENUM),
        };
        if missing {
            return self.raise(gl::INVALID_OPERATION);
        }
        // SAFETY: the context is current (see `execute`); the buffers the driver writes in the
        // new mode were handed over by SelectBuffer/FeedbackBuffer and live in `self.select`
        // until replaced by a later successful call.
        let r = unsafe { self.raw.RenderMode(mode) };
        let b = &mut self.select;
        match b.mode {
            gl::SELECT => {
                let (buf, size) = b
                    .select
                    .as_ref()
                    .map_or((&[][..], 0), |(v, s)| (&v[..], *s));
                b.select_filled = if r < 0 {
                    size
                } else {
                    // Each of the r records: its name count, two depths, the names.
                    let mut at = 0usize;
                    for _ in 0..r {
                        let n = buf.get(at).copied().unwrap_or(0) as usize;
                        at = at.saturating_add(3).saturating_add(n).min(size);
                    }
                    at
                };
            }
            gl::FEEDBACK => {
                let size = b.feedback.as_ref().map_or(0, |(_, s)| *s);
                b.feedback_filled = if r < 0 { size } else { (r as usize).min(size) };
            }
            _ => {}
        }
        match mode {
            gl::SELECT => b.select_filled = 0,
            gl::FEEDBACK => b.feedback_filled = 0,
            _ => {}
        }
        b.mode = mode;
        b.last = r;
    }

    /// The render mode the driver is in (RenderMode is never compiled, so this follows it).
    pub(super) fn current_render_mode(&self) -> u32 {
        self.select.mode
    }

    /// SELECTION_BUFFER_SIZE or FEEDBACK_BUFFER_SIZE as given (`None` before any buffer: the
    /// driver's 0 stands).
    pub(super) fn given_buffer_size(&self, pname: u32) -> Option<usize> {
        match pname {
            gl::SELECTION_BUFFER_SIZE => self.select.select.as_ref().map(|(_, s)| *s),
            _ => self.select.feedback.as_ref().map(|(_, s)| *s),
        }
    }

    /// What the last RenderMode replayed returned (0 before any).
    pub fn render_mode_result(&self) -> i32 {
        self.select.last
    }

    /// `SelectBuffer(size)`: validated here (the driver must never hold a buffer that is
    /// freed), then a buffer of `size` values goes to the driver.
    pub(super) fn select_buffer(&mut self, size: i32) {
        if size < 0 {
            return self.raise(gl::INVALID_VALUE);
        }
        if self.select.mode == gl::SELECT {
            return self.raise(gl::INVALID_OPERATION);
        }
        if size > MAX_BUFFER {
            return self.raise(gl::OUT_OF_MEMORY);
        }
        let mut buf = vec![0u32; (size as usize).max(1)].into_boxed_slice();
        // SAFETY: context current; `buf` holds max(size, 1) values, and the size passed is that
        // length, so the driver writes inside it; it is kept in `self.select` until a later
        // successful SelectBuffer hands the driver another one.
        unsafe { self.raw.SelectBuffer(buf.len() as i32, buf.as_mut_ptr()) };
        self.select.select = Some((buf, size as usize));
        self.select.select_filled = 0;
    }

    /// `FeedbackBuffer(size, type)`: as [`GlBackend::select_buffer`], with Mesa's order of
    /// checks (mode, size, type).
    pub(super) fn feedback_buffer(&mut self, size: i32, ty: u32) {
        if self.select.mode == gl::FEEDBACK {
            return self.raise(gl::INVALID_OPERATION);
        }
        if size < 0 {
            return self.raise(gl::INVALID_VALUE);
        }
        if !matches!(
            ty,
            gl::GL_2D
                | gl::GL_3D
                | gl::GL_3D_COLOR
                | gl::GL_3D_COLOR_TEXTURE
                | gl::GL_4D_COLOR_TEXTURE
        ) {
            return self.raise(gl::INVALID_ENUM);
        }
        if size > MAX_BUFFER {
            return self.raise(gl::OUT_OF_MEMORY);
        }
        let mut buf = vec![0f32; (size as usize).max(1)].into_boxed_slice();
        // SAFETY: as in `select_buffer`.
        unsafe {
            self.raw
                .FeedbackBuffer(buf.len() as i32, ty, buf.as_mut_ptr())
        };
        self.select.feedback = Some((buf, size as usize));
        self.select.feedback_filled = 0;
    }

    /// The hit records the driver wrote in the last selection, once RenderMode has left SELECT
    /// mode (on overflow: the whole buffer, as GL fills it).
    pub fn selection_buffer(&self) -> &[u32] {
        match &self.select.select {
            Some((b, _)) => b.get(..self.select.select_filled).unwrap_or(&[]),
            None => &[],
        }
    }

    /// The values the driver wrote in the last feedback, once RenderMode has left FEEDBACK mode.
    pub fn feedback_values(&self) -> &[f32] {
        match &self.select.feedback {
            Some((b, _)) => b.get(..self.select.feedback_filled).unwrap_or(&[]),
            None => &[],
        }
    }
}
