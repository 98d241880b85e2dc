//! The raster position and rectangles: `RasterPos*`, `WindowPos*` (GL 2.1 §2.13) and `Rect*`
//! (§2.10).
//!
//! RasterPos treats its coordinates as a vertex: the modelview and projection transforms, the
//! frustum and the enabled user clip planes (outside any of them the raster position becomes
//! invalid and nothing else changes), the viewport and DepthRange, lighting with the front
//! material (or the current colours), and TexGen and the texture matrix on every unit. WindowPos
//! (GL 1.4) sets window coordinates directly: z clamped to [0, 1] and put through DepthRange, the
//! current colours clamped, the current texture coordinates unchanged, always valid. Both set the
//! raster distance: the eye distance (WindowPos: 0), or the current fog coordinate when
//! FOG_COORD_SRC is FOG_COORD. The result is `State::raster_pos`.
//!
//! Design decision: the arithmetic is Mesa's software RasterPos (`_mesa_RasterPos`), which is
//! what llvmpipe runs for fixed-function state: single precision, window coordinates from NDC by
//! the viewport's scale and translation, a clip w of 0 taken as 1. Lighting is the one lighting
//! equation of the CPU pipeline (`cpu::vertex::Lighting`), so a raster position is lit exactly as
//! a vertex at the same place would be.
//!
//! Rect is Begin(QUADS), four vertices, End, as Mesa issues it (GL 2.1 says POLYGON; they cover
//! the same pixels, and under FLAT shading the provoking vertex is the fourth, as the driver's).

use glam::{Mat3, Vec4, Vec4Swizzles};

use super::vertex::Component;
use super::Context;
use crate::call::Call;
use crate::cpu::texgen::TexGenEval;
use crate::cpu::vertex::Lighting;
use crate::gl;
use crate::state::{RasterPos, FRONT, MAX_TEXTURE_UNITS};

/// The mode Rect draws its quadrilateral with (Mesa's `_mesa_Rectf`).
const RECT_MODE: u32 = gl::QUADS;

/// Generates the scalar and vector forms of one RasterPos/WindowPos arity and type.
macro_rules! pos_forms {
    ($set:ident, $t:ty, $n:literal, $f:ident / $V:ident, $fv:ident / $Vv:ident, ($($a:ident),+)) => {
        #[doc = concat!("`gl", stringify!($V), "`.")]
        pub fn $f(&mut self, $($a: $t),+) {
            record!(self, Call::$V($($a),+));
            self.$set([$($a.to_f32()),+]);
        }

        #[doc = concat!("`gl", stringify!($Vv), "`.")]
        pub fn $fv(&mut self, v: &[$t; $n]) {
            record!(self, Call::$Vv(*v));
            self.$set(v.map(Component::to_f32));
        }
    };
}

/// Generates the four forms of Rect for one type.
macro_rules! rect_forms {
    ($t:ty, $f:ident / $V:ident, $fv:ident / $Vv:ident) => {
        #[doc = concat!("`gl", stringify!($V), "`: the rectangle with corners (x1, y1) and (x2, y2) at z = 0.")]
        pub fn $f(&mut self, x1: $t, y1: $t, x2: $t, y2: $t) {
            record!(self, Call::$V(x1, y1, x2, y2));
            self.rect([x1.to_f32(), y1.to_f32()], [x2.to_f32(), y2.to_f32()]);
        }

        #[doc = concat!("`gl", stringify!($Vv), "`: corners `v1` and `v2`.")]
        pub fn $fv(&mut self, v1: &[$t; 2], v2: &[$t; 2]) {
            record!(self, Call::$Vv(*v1, *v2));
            self.rect(v1.map(Component::to_f32), v2.map(Component::to_f32));
        }
    };
}

/// Object coordinates of RasterPos{2,3,4}: z 0 and w 1 where left out (§2.13).
fn object<const N: usize>(v: [f32; N]) -> Vec4 {
    let mut o = Vec4::new(0.0, 0.0, 0.0, 1.0);
    for (k, c) in v.into_iter().enumerate().take(4) {
        o[k] = c;
    }
    o
}

impl Context {
    fn raster_pos_n<const N: usize>(&mut self, v: [f32; N]) {
        self.raster_pos(object(v));
    }

    fn window_pos_n<const N: usize>(&mut self, v: [f32; N]) {
        let g = |k: usize| v.get(k).copied().unwrap_or(0.0);
        self.window_pos(g(0), g(1), g(2));
    }

    /// RasterPos of object coordinates `obj` (§2.13).
    fn raster_pos(&mut self, obj: Vec4) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        let s = &self.state;
        let eye = *s.modelview.top() * obj;
        let clip = *s.projection.top() * eye;
        // The clip volume (§2.12), as a point: -w <= x, y, z <= w, then the user planes in eye
        // coordinates.
        let (x, y, z, w) = (clip.x, clip.y, clip.z, clip.w);
        let frustum = !(x > w || x < -w || y > w || y < -w || z > w || z < -w);
        let user = s
            .enables
            .clip_planes
            .iter()
            .zip(&s.clip_planes)
            .filter(|(on, _)| **on)
            .all(|(_, p)| p.as_vec4().dot(eye) >= 0.0);
        if !(frustum && user) {
            self.state.raster_pos.valid = false;
            return;
        }
        let d = if w == 0.0 { 1.0 } else { 1.0 / w };
        let ndc = clip.xyz() * d;
        let [vx, vy, vw, vh] = s.viewport.map(|c| c as f32);
        let [n, f] = s.depth_range.map(|c| c as f32);
        let (hw, hh) = (0.5 * vw, 0.5 * vh);
        let window = Vec4::new(
            ndc.x * hw + (hw + vx),
            ndc.y * hh + (hh + vy),
            ndc.z * (0.5 * (f - n)) + 0.5 * (n + f),
            w,
        );
        let distance = if s.fog.coord_src == gl::FOG_COORD {
            s.current.fog_coord
        } else {
            (eye.x * eye.x + eye.y * eye.y + eye.z * eye.z).sqrt()
        };
        // The eye-space normal (§2.11.3): the inverse transpose of the modelview's upper 3x3,
        // RESCALE_NORMAL, NORMALIZE.
        let mv3 = Mat3::from_mat4(*s.modelview.top());
        let inv = mv3.inverse();
        let mut nm = inv.transpose();
        if s.enables.rescale_normal {
            nm *= 1.0 / inv.row(2).length();
        }
        let mut normal = nm * s.current.normal;
        if s.enables.normalize {
            normal = normal.normalize_or_zero();
        }
        let (color, secondary) = if s.enables.lighting {
            let l = Lighting::new(s);
            let v = if eye.w != 0.0 && eye.w != 1.0 {
                eye.xyz() / eye.w
            } else {
                eye.xyz()
            };
            let (c, sec) = l.shade(&s.materials[FRONT], FRONT, s.current.color, v, normal);
            (c, sec.truncate().extend(1.0))
        } else {
            (s.current.color, s.current.secondary_color)
        };
        let mut tex_coords = s.current.tex_coords;
        for (u, tc) in tex_coords.iter_mut().enumerate().take(MAX_TEXTURE_UNITS) {
            if let Some(g) = TexGenEval::new(s, u) {
                *tc = g.apply(*tc, obj, eye, normal);
            }
            *tc = *s.texture_matrix[u].top() * *tc;
        }
        let index = s.raster_pos.index;
        self.state.raster_pos = RasterPos {
            valid: true,
            window,
            color,
            secondary_color: secondary,
            index,
            tex_coords,
            distance,
        };
    }

    /// WindowPos3 of window coordinates (x, y, z) (§2.13).
    fn window_pos(&mut self, x: f32, y: f32, z: f32) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        let s = &self.state;
        let [n, f] = s.depth_range;
        let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
        let zw = (f64::from(z) * (f - n) + n) as f32;
        let clamp = |c: Vec4| c.clamp(Vec4::ZERO, Vec4::ONE);
        self.state.raster_pos = RasterPos {
            valid: true,
            window: Vec4::new(x, y, zw, 1.0),
            color: clamp(s.current.color),
            secondary_color: clamp(s.current.secondary_color),
            index: s.raster_pos.index,
            tex_coords: s.current.tex_coords,
            distance: if s.fog.coord_src == gl::FOG_COORD {
                s.current.fog_coord
            } else {
                0.0
            },
        };
    }

    /// Rect with corners `a` and `b` (§2.10): a quadrilateral through (a.x, a.y), (b.x, a.y),
    /// (b.x, b.y), (a.x, b.y) at z = 0 with the current attributes. INVALID_OPERATION between
    /// Begin and End.
    fn rect(&mut self, a: [f32; 2], b: [f32; 2]) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.begin_mode = Some(RECT_MODE);
        self.renderer.begin(RECT_MODE);
        self.renderer.begin_materials(&self.state.materials);
        for (x, y) in [(a[0], a[1]), (b[0], a[1]), (b[0], b[1]), (a[0], b[1])] {
            self.vertex(Vec4::new(x, y, 0.0, 1.0));
        }
        self.begin_mode = None;
        self.renderer.end();
        self.renderer.flush_if_large(&self.state);
    }

    pos_forms! { raster_pos_n, i16, 2, raster_pos2s / RasterPos2s, raster_pos2sv / RasterPos2sv, (x, y) }
    pos_forms! { raster_pos_n, i32, 2, raster_pos2i / RasterPos2i, raster_pos2iv / RasterPos2iv, (x, y) }
    pos_forms! { raster_pos_n, f32, 2, raster_pos2f / RasterPos2f, raster_pos2fv / RasterPos2fv, (x, y) }
    pos_forms! { raster_pos_n, f64, 2, raster_pos2d / RasterPos2d, raster_pos2dv / RasterPos2dv, (x, y) }
    pos_forms! { raster_pos_n, i16, 3, raster_pos3s / RasterPos3s, raster_pos3sv / RasterPos3sv, (x, y, z) }
    pos_forms! { raster_pos_n, i32, 3, raster_pos3i / RasterPos3i, raster_pos3iv / RasterPos3iv, (x, y, z) }
    pos_forms! { raster_pos_n, f32, 3, raster_pos3f / RasterPos3f, raster_pos3fv / RasterPos3fv, (x, y, z) }
    pos_forms! { raster_pos_n, f64, 3, raster_pos3d / RasterPos3d, raster_pos3dv / RasterPos3dv, (x, y, z) }
    pos_forms! { raster_pos_n, i16, 4, raster_pos4s / RasterPos4s, raster_pos4sv / RasterPos4sv, (x, y, z, w) }
    pos_forms! { raster_pos_n, i32, 4, raster_pos4i / RasterPos4i, raster_pos4iv / RasterPos4iv, (x, y, z, w) }
    pos_forms! { raster_pos_n, f32, 4, raster_pos4f / RasterPos4f, raster_pos4fv / RasterPos4fv, (x, y, z, w) }
    pos_forms! { raster_pos_n, f64, 4, raster_pos4d / RasterPos4d, raster_pos4dv / RasterPos4dv, (x, y, z, w) }

    pos_forms! { window_pos_n, i16, 2, window_pos2s / WindowPos2s, window_pos2sv / WindowPos2sv, (x, y) }
    pos_forms! { window_pos_n, i32, 2, window_pos2i / WindowPos2i, window_pos2iv / WindowPos2iv, (x, y) }
    pos_forms! { window_pos_n, f32, 2, window_pos2f / WindowPos2f, window_pos2fv / WindowPos2fv, (x, y) }
    pos_forms! { window_pos_n, f64, 2, window_pos2d / WindowPos2d, window_pos2dv / WindowPos2dv, (x, y) }
    pos_forms! { window_pos_n, i16, 3, window_pos3s / WindowPos3s, window_pos3sv / WindowPos3sv, (x, y, z) }
    pos_forms! { window_pos_n, i32, 3, window_pos3i / WindowPos3i, window_pos3iv / WindowPos3iv, (x, y, z) }
    pos_forms! { window_pos_n, f32, 3, window_pos3f / WindowPos3f, window_pos3fv / WindowPos3fv, (x, y, z) }
    pos_forms! { window_pos_n, f64, 3, window_pos3d / WindowPos3d, window_pos3dv / WindowPos3dv, (x, y, z) }

    rect_forms! { i16, rects / Rects, rectsv / Rectsv }
    rect_forms! { i32, recti / Recti, rectiv / Rectiv }
    rect_forms! { f32, rectf / Rectf, rectfv / Rectfv }
    rect_forms! { f64, rectd / Rectd, rectdv / Rectdv }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn raster_pos_transforms_clips_and_keeps_its_data() {
        let mut c = Context::new(100, 50).unwrap();
        // Identity matrices: NDC (0.5, -0.5, 0.5) → window (75, 12.5, 0.75).
        c.color4f(0.25, 0.5, 0.75, 1.0);
        c.tex_coord2f(3.0, 4.0);
        c.raster_pos3f(0.5, -0.5, 0.5);
        let r = c.state.raster_pos;
        assert!(r.valid);
        assert_eq!(r.window, Vec4::new(75.0, 12.5, 0.75, 1.0));
        assert_eq!(r.color, Vec4::new(0.25, 0.5, 0.75, 1.0));
        assert_eq!(r.tex_coords[0], Vec4::new(3.0, 4.0, 0.0, 1.0));
        assert!((r.distance - (0.75f32).sqrt()).abs() < 1e-6);
        // Outside the frustum: invalid, the rest kept.
        c.raster_pos2f(1.5, 0.0);
        assert!(!c.state.raster_pos.valid);
        assert_eq!(c.state.raster_pos.window, r.window);
        // A user clip plane x <= 0 (eye) rejects x = 0.5.
        c.clip_plane(gl::CLIP_PLANE0, &[-1.0, 0.0, 0.0, 0.0]);
        c.enable(gl::CLIP_PLANE0);
        c.raster_pos2f(0.5, 0.0);
        assert!(!c.state.raster_pos.valid);
        c.raster_pos2f(-0.5, 0.0);
        assert!(c.state.raster_pos.valid);
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    #[test]
    fn window_pos_clamps_and_is_always_valid() {
        let mut c = Context::new(10, 10).unwrap();
        c.depth_range(0.5, 1.0);
        c.color4f(2.0, -1.0, 0.5, 1.0);
        c.window_pos3f(-20.0, 30.5, 2.0);
        let r = c.state.raster_pos;
        assert!(r.valid);
        assert_eq!(r.window, Vec4::new(-20.0, 30.5, 1.0, 1.0));
        assert_eq!(r.color, Vec4::new(1.0, 0.0, 0.5, 1.0));
        assert_eq!(r.distance, 0.0);
        c.window_pos2i(1, 2);
        assert_eq!(c.state.raster_pos.window, Vec4::new(1.0, 2.0, 0.5, 1.0));
        c.begin(gl::POINTS);
        c.window_pos2i(3, 3);
        c.end();
        assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    }
}
