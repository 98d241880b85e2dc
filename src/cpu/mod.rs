//! The CPU backend: turns batches of vertices into pixels in the context's framebuffer.
//!
//! The front end hands vertices to `Renderer` as they arrive (`begin`/`vertex`/`end`) and calls
//! `flush` with the state whenever it is about to change state that affects rendering, or before
//! anything reads the framebuffer. Batching across many Begin/End pairs is what lets the vertex
//! stage and the tile rasteriser run in parallel over large batches (Mesa's FLUSH_VERTICES idea).

use glam::Vec4;

use crate::state::{Current, Material, State};

/// The CPU renderer: the vertex batch not yet drawn and the framebuffer.
#[derive(Debug)]
pub struct Renderer {
    width: u32,
    height: u32,
    /// RGBA8, bottom-up rows (GL window coordinates).
    color: Vec<[u8; 4]>,
    /// Vertices of the current batch, object coordinates.
    positions: Vec<Vec4>,
}

impl Renderer {
    /// A renderer with a cleared `width` x `height` framebuffer (sizes validated by the caller).
    pub fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self {
            width,
            height,
            color: vec![[0; 4]; n],
            positions: Vec::new(),
        }
    }

    /// `Begin(mode)`: opens a primitive in the batch (mode already validated).
    pub fn begin(&mut self, _mode: u32) {}

    /// A vertex with the current attributes.
    pub fn vertex(&mut self, position: Vec4, _current: &Current) {
        self.positions.push(position);
    }

    /// `End`.
    pub fn end(&mut self) {}

    /// Draws everything batched so far with `state`, leaving the batch empty.
    pub fn flush(&mut self, _state: &State) {
        self.positions.clear();
    }

    /// `Material` called between Begin and End: `materials` are the new front and back materials,
    /// which apply from the next vertex on (GL 2.1 §2.14.3). Outside Begin/End the front end
    /// flushes instead, so this is only called with a primitive open.
    pub fn materials_changed(&mut self, _materials: &[Material; 2]) {}

    /// `glClear` with a validated `mask` (any of COLOR/DEPTH/STENCIL_BUFFER_BIT), honouring the
    /// scissor test and the colour, depth and stencil write masks in `state` (GL 2.1 §4.2.3).
    pub fn clear(&mut self, _state: &State, _mask: u32) {}

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// The colour buffer, bottom-up rows.
    pub fn color(&self) -> &[[u8; 4]] {
        &self.color
    }
}
