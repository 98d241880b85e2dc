//! Rasterisation state: `FrontFace`, `CullFace`, `PolygonMode`, `PolygonOffset`, `PointSize`,
//! `LineWidth` (GL 2.1 §3.3, §3.4, §3.5).
//!
//! Each command is outside-Begin/End only (§2.6.3): it raises INVALID_OPERATION there, and
//! otherwise flushes the vertex batch before validating and writing the state.
//!
//! Design decision: sizes follow the spec's test literally (`size <= 0` is INVALID_VALUE), so a
//! NaN size is stored as given (as Mesa does); the rasteriser must cope with it.

use super::{record, Context};
use crate::call::Call;
use crate::gl;
use crate::state::{BACK, FRONT};

impl Context {
    /// `glFrontFace`: CW or CCW (GL 2.1 §3.5.1).
    pub fn front_face(&mut self, mode: u32) {
        record!(self, Call::FrontFace(mode));
        if !self.outside_begin_end() {
            return;
        }
        match mode {
            gl::CW | gl::CCW => self.state.front_face = mode,
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glCullFace`: FRONT, BACK or FRONT_AND_BACK (GL 2.1 §3.5.1).
    pub fn cull_face(&mut self, mode: u32) {
        record!(self, Call::CullFace(mode));
        if !self.outside_begin_end() {
            return;
        }
        match mode {
            gl::FRONT | gl::BACK | gl::FRONT_AND_BACK => self.state.cull_face_mode = mode,
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glPolygonMode`: `face` FRONT, BACK or FRONT_AND_BACK; `mode` POINT, LINE or FILL
    /// (GL 2.1 §3.5.4).
    pub fn polygon_mode(&mut self, face: u32, mode: u32) {
        record!(self, Call::PolygonMode(face, mode));
        if !self.outside_begin_end() {
            return;
        }
        if !matches!(mode, gl::POINT | gl::LINE | gl::FILL) {
            return self.error(gl::INVALID_ENUM);
        }
        let pm = &mut self.state.polygon_mode;
        match face {
            gl::FRONT => pm[FRONT] = mode,
            gl::BACK => pm[BACK] = mode,
            gl::FRONT_AND_BACK => *pm = [mode, mode],
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glPolygonOffset` (GL 2.1 §3.5.5): any values, no error.
    pub fn polygon_offset(&mut self, factor: f32, units: f32) {
        record!(self, Call::PolygonOffset(factor, units));
        if !self.outside_begin_end() {
            return;
        }
        self.state.polygon_offset_factor = factor;
        self.state.polygon_offset_units = units;
    }

    /// `glPointSize`: INVALID_VALUE if `size <= 0` (GL 2.1 §3.3).
    pub fn point_size(&mut self, size: f32) {
        record!(self, Call::PointSize(size));
        if !self.outside_begin_end() {
            return;
        }
        if size <= 0.0 {
            return self.error(gl::INVALID_VALUE);
        }
        self.state.point_size = size;
    }

    /// `glLineWidth`: INVALID_VALUE if `width <= 0` (GL 2.1 §3.4.2).
    pub fn line_width(&mut self, width: f32) {
        record!(self, Call::LineWidth(width));
        if !self.outside_begin_end() {
            return;
        }
        if width <= 0.0 {
            return self.error(gl::INVALID_VALUE);
        }
        self.state.line_width = width;
    }
}
