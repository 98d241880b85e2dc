//! `MultiTexCoord{1,2,3,4}{s,i,f,d}[v]` (GL 2.1 §2.7): the current texture coordinates of
//! any texture unit, allowed between Begin and End like every current attribute.
//!
//! Design decision: integer coordinates are taken as values (no normalisation, as TexCoord), and
//! a `target` outside TEXTURE0 .. TEXTURE0 + MAX_TEXTURE_UNITS - 1 is INVALID_ENUM with nothing
//! changed (Mesa accepts up to its 8 coordinate sets; fixedgl has 4 units).

use glam::Vec4;

use super::Context;
use crate::call::Call;
use crate::gl;
use crate::state::MAX_TEXTURE_UNITS;

// Every form converts with `as f32`, the f32 forms included, so all read alike.
#[allow(clippy::unnecessary_cast)]
impl Context {
    /// Sets unit `target - TEXTURE0`'s current texture coordinates.
    fn set_multi_tex_coord(&mut self, target: u32, t: Vec4) {
        let unit = target.wrapping_sub(gl::TEXTURE0) as usize;
        if unit >= MAX_TEXTURE_UNITS {
            return self.error(gl::INVALID_ENUM);
        }
        if let Some(slot) = self.state.current.inputs_mut().tex_coords.get_mut(unit) {
            *slot = t;
        }
    }

    /// `glMultiTexCoord1s`.
    pub fn multi_tex_coord1s(&mut self, target: u32, s: i16) {
        record!(self, Call::MultiTexCoord1s(target, s));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1sv`.
    pub fn multi_tex_coord1sv(&mut self, target: u32, v: &[i16; 1]) {
        record!(self, Call::MultiTexCoord1sv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1i`.
    pub fn multi_tex_coord1i(&mut self, target: u32, s: i32) {
        record!(self, Call::MultiTexCoord1i(target, s));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1iv`.
    pub fn multi_tex_coord1iv(&mut self, target: u32, v: &[i32; 1]) {
        record!(self, Call::MultiTexCoord1iv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1f`.
    pub fn multi_tex_coord1f(&mut self, target: u32, s: f32) {
        record!(self, Call::MultiTexCoord1f(target, s));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1fv`.
    pub fn multi_tex_coord1fv(&mut self, target: u32, v: &[f32; 1]) {
        record!(self, Call::MultiTexCoord1fv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1d`.
    pub fn multi_tex_coord1d(&mut self, target: u32, s: f64) {
        record!(self, Call::MultiTexCoord1d(target, s));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord1dv`.
    pub fn multi_tex_coord1dv(&mut self, target: u32, v: &[f64; 1]) {
        record!(self, Call::MultiTexCoord1dv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, 0.0, 0.0, 1.0));
    }

    /// `glMultiTexCoord2s`.
    pub fn multi_tex_coord2s(&mut self, target: u32, s: i16, t: i16) {
        record!(self, Call::MultiTexCoord2s(target, s, t));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2sv`.
    pub fn multi_tex_coord2sv(&mut self, target: u32, v: &[i16; 2]) {
        record!(self, Call::MultiTexCoord2sv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2i`.
    pub fn multi_tex_coord2i(&mut self, target: u32, s: i32, t: i32) {
        record!(self, Call::MultiTexCoord2i(target, s, t));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2iv`.
    pub fn multi_tex_coord2iv(&mut self, target: u32, v: &[i32; 2]) {
        record!(self, Call::MultiTexCoord2iv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2f`.
    pub fn multi_tex_coord2f(&mut self, target: u32, s: f32, t: f32) {
        record!(self, Call::MultiTexCoord2f(target, s, t));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2fv`.
    pub fn multi_tex_coord2fv(&mut self, target: u32, v: &[f32; 2]) {
        record!(self, Call::MultiTexCoord2fv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2d`.
    pub fn multi_tex_coord2d(&mut self, target: u32, s: f64, t: f64) {
        record!(self, Call::MultiTexCoord2d(target, s, t));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord2dv`.
    pub fn multi_tex_coord2dv(&mut self, target: u32, v: &[f64; 2]) {
        record!(self, Call::MultiTexCoord2dv(target, *v));
        self.set_multi_tex_coord(target, Vec4::new(v[0] as f32, v[1] as f32, 0.0, 1.0));
    }

    /// `glMultiTexCoord3s`.
    pub fn multi_tex_coord3s(&mut self, target: u32, s: i16, t: i16, r: i16) {
        record!(self, Call::MultiTexCoord3s(target, s, t, r));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }

    /// `glMultiTexCoord3sv`.
    pub fn multi_tex_coord3sv(&mut self, target: u32, v: &[i16; 3]) {
        record!(self, Call::MultiTexCoord3sv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }

    /// `glMultiTexCoord3i`.
    pub fn multi_tex_coord3i(&mut self, target: u32, s: i32, t: i32, r: i32) {
        record!(self, Call::MultiTexCoord3i(target, s, t, r));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }

    /// `glMultiTexCoord3iv`.
    pub fn multi_tex_coord3iv(&mut self, target: u32, v: &[i32; 3]) {
        record!(self, Call::MultiTexCoord3iv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }

    /// `glMultiTexCoord3f`.
    pub fn multi_tex_coord3f(&mut self, target: u32, s: f32, t: f32, r: f32) {
        record!(self, Call::MultiTexCoord3f(target, s, t, r));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }

    /// `glMultiTexCoord3fv`.
    pub fn multi_tex_coord3fv(&mut self, target: u32, v: &[f32; 3]) {
        record!(self, Call::MultiTexCoord3fv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }

    /// `glMultiTexCoord3d`.
    pub fn multi_tex_coord3d(&mut self, target: u32, s: f64, t: f64, r: f64) {
        record!(self, Call::MultiTexCoord3d(target, s, t, r));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, 1.0));
    }

    /// `glMultiTexCoord3dv`.
    pub fn multi_tex_coord3dv(&mut self, target: u32, v: &[f64; 3]) {
        record!(self, Call::MultiTexCoord3dv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, 1.0),
        );
    }

    /// `glMultiTexCoord4s`.
    pub fn multi_tex_coord4s(&mut self, target: u32, s: i16, t: i16, r: i16, q: i16) {
        record!(self, Call::MultiTexCoord4s(target, s, t, r, q));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }

    /// `glMultiTexCoord4sv`.
    pub fn multi_tex_coord4sv(&mut self, target: u32, v: &[i16; 4]) {
        record!(self, Call::MultiTexCoord4sv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }

    /// `glMultiTexCoord4i`.
    pub fn multi_tex_coord4i(&mut self, target: u32, s: i32, t: i32, r: i32, q: i32) {
        record!(self, Call::MultiTexCoord4i(target, s, t, r, q));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }

    /// `glMultiTexCoord4iv`.
    pub fn multi_tex_coord4iv(&mut self, target: u32, v: &[i32; 4]) {
        record!(self, Call::MultiTexCoord4iv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }

    /// `glMultiTexCoord4f`.
    pub fn multi_tex_coord4f(&mut self, target: u32, s: f32, t: f32, r: f32, q: f32) {
        record!(self, Call::MultiTexCoord4f(target, s, t, r, q));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }

    /// `glMultiTexCoord4fv`.
    pub fn multi_tex_coord4fv(&mut self, target: u32, v: &[f32; 4]) {
        record!(self, Call::MultiTexCoord4fv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }

    /// `glMultiTexCoord4d`.
    pub fn multi_tex_coord4d(&mut self, target: u32, s: f64, t: f64, r: f64, q: f64) {
        record!(self, Call::MultiTexCoord4d(target, s, t, r, q));
        self.set_multi_tex_coord(target, Vec4::new(s as f32, t as f32, r as f32, q as f32));
    }

    /// `glMultiTexCoord4dv`.
    pub fn multi_tex_coord4dv(&mut self, target: u32, v: &[f64; 4]) {
        record!(self, Call::MultiTexCoord4dv(target, *v));
        self.set_multi_tex_coord(
            target,
            Vec4::new(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32),
        );
    }
}
