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
use crate::counts;
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

    /// `glPointParameterf`: a single-valued pname (POINT_DISTANCE_ATTENUATION, three values,
    /// is INVALID_ENUM here, GL 2.1 §3.4).
    pub fn point_parameterf(&mut self, pname: u32, param: f32) {
        record!(self, Call::PointParameterf(pname, param));
        self.point_parameter(pname, &[param], true);
    }

    /// `glPointParameteri`: as [`Context::point_parameterf`], the value converted to float.
    pub fn point_parameteri(&mut self, pname: u32, param: i32) {
        record!(self, Call::PointParameteri(pname, param));
        self.point_parameter(pname, &[param as f32], true);
    }

    /// `glPointParameterfv`: POINT_DISTANCE_ATTENUATION takes 3 values, the other pnames 1; a
    /// shorter slice is INVALID_VALUE.
    pub fn point_parameterfv(&mut self, pname: u32, params: &[f32]) {
        record!(self, Call::PointParameterfv(pname, params.to_vec()));
        self.point_parameter(pname, params, false);
    }

    /// `glPointParameteriv`: as [`Context::point_parameterfv`], the values converted to float.
    pub fn point_parameteriv(&mut self, pname: u32, params: &[i32]) {
        record!(self, Call::PointParameteriv(pname, params.to_vec()));
        let v: Vec<f32> = params.iter().take(3).map(|&x| x as f32).collect();
        self.point_parameter(pname, &v, false);
    }

    /// The body of every `PointParameter` form (GL 2.1 §3.4): POINT_SIZE_MIN, POINT_SIZE_MAX and
    /// POINT_FADE_THRESHOLD_SIZE take a value >= 0 (else INVALID_VALUE),
    /// POINT_DISTANCE_ATTENUATION any three, POINT_SPRITE_COORD_ORIGIN LOWER_LEFT or UPPER_LEFT
    /// (else INVALID_VALUE, as Mesa).
    fn point_parameter(&mut self, pname: u32, v: &[f32], scalar: bool) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(len) = counts::point_parameter(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        // A scalar form takes POINT_DISTANCE_ATTENUATION as `[param, 0, 0]`, as Mesa does.
        let padded = [v.first().copied().unwrap_or(0.0), 0.0, 0.0];
        let v = if scalar { &padded[..] } else { v };
        if v.len() < len {
            return self.error(gl::INVALID_VALUE);
        }
        let x = v.first().copied().unwrap_or(0.0);
        let p = &mut self.state.point;
        match pname {
            gl::POINT_DISTANCE_ATTENUATION => {
                if let [a, b, c, ..] = *v {
                    p.distance_attenuation = [a, b, c];
                }
            }
            gl::POINT_SPRITE_COORD_ORIGIN => {
                match [gl::LOWER_LEFT, gl::UPPER_LEFT]
                    .into_iter()
                    .find(|&m| x == m as f32)
                {
                    Some(m) => p.sprite_coord_origin = m,
                    None => self.error(gl::INVALID_VALUE),
                }
            }
            _ if x < 0.0 || x.is_nan() => self.error(gl::INVALID_VALUE),
            gl::POINT_SIZE_MIN => p.size_min = x,
            gl::POINT_SIZE_MAX => p.size_max = x,
            _ => p.fade_threshold = x,
        }
    }
}
