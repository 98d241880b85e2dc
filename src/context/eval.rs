//! Evaluators (GL 2.1 §5.1): `Map1`, `Map2`, `MapGrid1`, `MapGrid2`, `EvalCoord1`,
//! `EvalCoord2`, `EvalMesh1`, `EvalMesh2`, `EvalPoint1`, `EvalPoint2` and `GetMap`.
//!
//! Evaluation happens here, in the front end, and feeds the ordinary vertex path: an
//! `EvalCoord` inside Begin/End is a `Vertex` with the evaluated attributes, an `EvalMesh` a
//! Begin/End of `EvalCoord`s. The arithmetic is Mesa's (`main/eval.c`, `math/m_eval.c`,
//! `vbo/vbo_exec_eval.c`, `vbo_exec_api.c`), so that the vertices agree with llvmpipe's to the
//! bit:
//! - maps are kept as floats (Map*d converts its domain and points), the parameter mapped to
//!   `(u - u1) * (1 / (u2 - u1))`;
//! - points are computed by Horner's scheme with running binomial coefficients; with
//!   AUTO_NORMAL, a MAP2_VERTEX map is evaluated by de Casteljau's algorithm, which also gives
//!   the partial derivatives, in the mapped parameters (so a domain with `u2 < u1` flips the
//!   normal, as in Mesa), of the dehomogenised point for VERTEX_4; the normal is their cross
//!   product, normalised unless zero;
//! - the attributes come from the enabled maps of the highest texture coordinate size and
//!   VERTEX_4 over VERTEX_3; INDEX maps are accepted and kept but colour-index mode does not
//!   exist, so they evaluate to nothing; an evaluated texture coordinate sets unit 0's;
//! - `EvalCoord` leaves the current values as they were (GL 2.1 §5.1);
//! - `EvalMesh` steps the grid as Mesa does: `u = u1 + i1 * du`, then `u += du` per step (not
//!   `u1 + i * du`), with `du = (u2 - u1) / n` computed at MapGrid; `EvalPoint` computes
//!   `i * du + u1` with `du` computed at the call.
//!
//! Bound: one `EvalMesh` evaluates at most [`MAX_EVAL_MESH_VERTICES`] points; a larger grid is
//! OUT_OF_MEMORY and draws nothing (GL lets any command raise it; a driver would spend hours).

use glam::{Vec3, Vec4};

use super::{record, Context};
use crate::call::Call;
use crate::counts;
use crate::gl;
use crate::state::{EvalMap, EVAL_COMPONENTS, MAX_EVAL_ORDER};

/// The most points one `EvalMesh1` or `EvalMesh2` evaluates (FILL counts two per grid point of
/// each strip); beyond it the call is OUT_OF_MEMORY.
pub const MAX_EVAL_MESH_VERTICES: u64 = 1 << 22;

/// Map indices (`target - MAP1_COLOR_4`, `target - MAP2_COLOR_4`), in [`EvalMaps`] order.
///
/// [`EvalMaps`]: crate::state::EvalMaps
const COLOR_4: usize = 0;
const NORMAL: usize = 2;
const TEXTURE_COORD_1: usize = 3;
const VERTEX_3: usize = 7;
const VERTEX_4: usize = 8;

/// A control point component type: Map*f's floats, Map*d's doubles (kept as floats).
pub(crate) trait Ctl: Copy {
    fn to_f32(self) -> f32;
}
impl Ctl for f32 {
    fn to_f32(self) -> f32 {
        self
    }
}
impl Ctl for f64 {
    fn to_f32(self) -> f32 {
        self as f32
    }
}

impl Context {
    /// `glMap1f`: defines the one-dimensional map `target` (MAP1_*) on the domain `u1` to `u2`
    /// from `order` points, `stride` values apart in `points` (GL 2.1 §5.1). Errors in Mesa's
    /// order: INVALID_VALUE for `u1 == u2`, an order outside 1 to MAX_EVAL_ORDER or an empty
    /// `points` (C's NULL); INVALID_ENUM for a target that is no MAP1_*; INVALID_VALUE for a
    /// stride below the target's components or `points` shorter than `(order - 1) * stride +
    /// k`; INVALID_OPERATION with ACTIVE_TEXTURE other than TEXTURE0 (GL 1.2.1 §F.2.13) and
    /// between Begin and End. A display list keeps a copy of the points.
    pub fn map1f(
        &mut self,
        target: u32,
        u1: f32,
        u2: f32,
        stride: i32,
        order: i32,
        points: &[f32],
    ) {
        record!(
            self,
            Call::Map1f(Box::new((target, u1, u2, stride, order, points.to_vec())))
        );
        self.map1(target, u1, u2, stride, order, points);
    }

    /// `glMap1d`: [`Context::map1f`] with double arguments, kept as floats.
    pub fn map1d(
        &mut self,
        target: u32,
        u1: f64,
        u2: f64,
        stride: i32,
        order: i32,
        points: &[f64],
    ) {
        record!(
            self,
            Call::Map1d(Box::new((target, u1, u2, stride, order, points.to_vec())))
        );
        self.map1(target, u1 as f32, u2 as f32, stride, order, points);
    }

    /// `glMap2f`: defines the two-dimensional map `target` (MAP2_*) on `u1..u2` x `v1..v2` from
    /// `uorder` x `vorder` points, point `(i, j)` at `points[i * ustride + j * vstride..]`.
    /// Errors in Mesa's order: INVALID_VALUE for `u1 == u2`, `v1 == v2`, an order outside 1 to
    /// MAX_EVAL_ORDER; INVALID_ENUM for a target that is no MAP2_*; INVALID_VALUE for a stride
    /// below the target's components or `points` too short; INVALID_OPERATION with
    /// ACTIVE_TEXTURE other than TEXTURE0 and between Begin and End.
    #[allow(clippy::too_many_arguments)]
    pub fn map2f(
        &mut self,
        target: u32,
        u1: f32,
        u2: f32,
        ustride: i32,
        uorder: i32,
        v1: f32,
        v2: f32,
        vstride: i32,
        vorder: i32,
        points: &[f32],
    ) {
        record!(
            self,
            Call::Map2f(Box::new((
                target,
                u1,
                u2,
                ustride,
                uorder,
                v1,
                v2,
                vstride,
                vorder,
                points.to_vec()
            )))
        );
        self.map2(
            target,
            [u1, u2, v1, v2],
            [ustride, uorder, vstride, vorder],
            points,
        );
    }

    /// `glMap2d`: [`Context::map2f`] with double arguments, kept as floats.
    #[allow(clippy::too_many_arguments)]
    pub fn map2d(
        &mut self,
        target: u32,
        u1: f64,
        u2: f64,
        ustride: i32,
        uorder: i32,
        v1: f64,
        v2: f64,
        vstride: i32,
        vorder: i32,
        points: &[f64],
    ) {
        record!(
            self,
            Call::Map2d(Box::new((
                target,
                u1,
                u2,
                ustride,
                uorder,
                v1,
                v2,
                vstride,
                vorder,
                points.to_vec()
            )))
        );
        let d = [u1 as f32, u2 as f32, v1 as f32, v2 as f32];
        self.map2(target, d, [ustride, uorder, vstride, vorder], points);
    }

    fn map1<T: Ctl>(&mut self, target: u32, u1: f32, u2: f32, stride: i32, order: i32, p: &[T]) {
        if !self.outside_begin_end() {
            return;
        }
        if u1 == u2 || !(1..=MAX_EVAL_ORDER).contains(&order) || p.is_empty() {
            return self.error(gl::INVALID_VALUE);
        }
        let Some(k) = counts::map_components(target) else {
            return self.error(gl::INVALID_ENUM);
        };
        if stride < k as i32 {
            return self.error(gl::INVALID_VALUE);
        }
        if self.state.active_texture != 0 {
            return self.error(gl::INVALID_OPERATION);
        }
        if !(gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4).contains(&target) {
            return self.error(gl::INVALID_ENUM);
        }
        // The points the driver reads: a shorter slice (C cannot have one) is INVALID_VALUE.
        match counts::map1_points(target, stride, order) {
            Some(n) if p.len() >= n => {}
            _ => return self.error(gl::INVALID_VALUE),
        }
        let (stride, order) = (stride as usize, order as usize);
        let mut points = Vec::with_capacity(order * k);
        for i in 0..order {
            points.extend(p[i * stride..i * stride + k].iter().map(|c| c.to_f32()));
        }
        self.state.eval_maps.map1[(target - gl::MAP1_COLOR_4) as usize] = EvalMap {
            uorder: order as i32,
            vorder: 1,
            domain: [u1, u2, 0.0, 1.0],
            points,
        };
    }

    fn map2<T: Ctl>(&mut self, target: u32, d: [f32; 4], so: [i32; 4], p: &[T]) {
        if !self.outside_begin_end() {
            return;
        }
        let [ustride, uorder, vstride, vorder] = so;
        let orders = 1..=MAX_EVAL_ORDER;
        if d[0] == d[1] || d[2] == d[3] || !orders.contains(&uorder) || !orders.contains(&vorder) {
            return self.error(gl::INVALID_VALUE);
        }
        // Mesa raises INVALID_ENUM for a target of no components and carries on to the stride
        // checks, whose error cannot replace it: the same as returning here.
        let Some(k) = counts::map_components(target) else {
            return self.error(gl::INVALID_ENUM);
        };
        if ustride < k as i32 || vstride < k as i32 {
            return self.error(gl::INVALID_VALUE);
        }
        if self.state.active_texture != 0 {
            return self.error(gl::INVALID_OPERATION);
        }
        if !(gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4).contains(&target) {
            return self.error(gl::INVALID_ENUM);
        }
        match counts::map2_points(target, ustride, uorder, vstride, vorder) {
            Some(n) if p.len() >= n => {}
            _ => return self.error(gl::INVALID_VALUE),
        }
        let (us, uo, vs, vo) = (
            ustride as usize,
            uorder as usize,
            vstride as usize,
            vorder as usize,
        );
        let mut points = Vec::with_capacity(uo * vo * k);
        for i in 0..uo {
            for j in 0..vo {
                let at = i * us + j * vs;
                points.extend(p[at..at + k].iter().map(|c| c.to_f32()));
            }
        }
        self.state.eval_maps.map2[(target - gl::MAP2_COLOR_4) as usize] = EvalMap {
            uorder,
            vorder,
            domain: d,
            points,
        };
    }

    /// `glMapGrid1f`: the grid `EvalMesh1` and `EvalPoint1` step: `un` segments from `u1` to
    /// `u2`. INVALID_VALUE for `un < 1`; INVALID_OPERATION between Begin and End.
    pub fn map_grid1f(&mut self, un: i32, u1: f32, u2: f32) {
        record!(self, Call::MapGrid1f(un, u1, u2));
        self.map_grid1(un, u1, u2);
    }

    /// `glMapGrid1d`: [`Context::map_grid1f`], kept as floats.
    pub fn map_grid1d(&mut self, un: i32, u1: f64, u2: f64) {
        record!(self, Call::MapGrid1d(un, u1, u2));
        self.map_grid1(un, u1 as f32, u2 as f32);
    }

    fn map_grid1(&mut self, un: i32, u1: f32, u2: f32) {
        if !self.outside_begin_end() {
            return;
        }
        if un < 1 {
            return self.error(gl::INVALID_VALUE);
        }
        self.state.eval_grid.un1 = un;
        self.state.eval_grid.u1 = [u1, u2];
    }

    /// `glMapGrid2f`: `un` x `vn` segments over `u1..u2` x `v1..v2`. INVALID_VALUE for `un < 1`
    /// or `vn < 1`; INVALID_OPERATION between Begin and End.
    pub fn map_grid2f(&mut self, un: i32, u1: f32, u2: f32, vn: i32, v1: f32, v2: f32) {
        record!(self, Call::MapGrid2f(un, u1, u2, vn, v1, v2));
        self.map_grid2(un, u1, u2, vn, v1, v2);
    }

    /// `glMapGrid2d`: [`Context::map_grid2f`], kept as floats.
    pub fn map_grid2d(&mut self, un: i32, u1: f64, u2: f64, vn: i32, v1: f64, v2: f64) {
        record!(self, Call::MapGrid2d(Box::new((un, u1, u2, vn, v1, v2))));
        self.map_grid2(un, u1 as f32, u2 as f32, vn, v1 as f32, v2 as f32);
    }

    fn map_grid2(&mut self, un: i32, u1: f32, u2: f32, vn: i32, v1: f32, v2: f32) {
        if !self.outside_begin_end() {
            return;
        }
        if un < 1 || vn < 1 {
            return self.error(gl::INVALID_VALUE);
        }
        self.state.eval_grid.n2 = [un, vn];
        self.state.eval_grid.d2 = [u1, u2, v1, v2];
    }

    /// `glEvalCoord1f`: with MAP1_VERTEX_3 or MAP1_VERTEX_4 enabled, a vertex at the map's
    /// point for `u`, with the colour, normal and texture coordinates of the other enabled
    /// MAP1 maps (the current values elsewhere); the current values do not change. Nothing
    /// without a vertex map, or outside Begin/End (as `Vertex`). Allowed between Begin and End.
    pub fn eval_coord1f(&mut self, u: f32) {
        record!(self, Call::EvalCoord1f(u));
        self.eval1(u);
    }

    /// `glEvalCoord1d`.
    pub fn eval_coord1d(&mut self, u: f64) {
        record!(self, Call::EvalCoord1d(u));
        self.eval1(u as f32);
    }

    /// `glEvalCoord1fv`.
    pub fn eval_coord1fv(&mut self, u: &[f32; 1]) {
        record!(self, Call::EvalCoord1fv(*u));
        self.eval1(u[0]);
    }

    /// `glEvalCoord1dv`.
    pub fn eval_coord1dv(&mut self, u: &[f64; 1]) {
        record!(self, Call::EvalCoord1dv(*u));
        self.eval1(u[0] as f32);
    }

    /// `glEvalCoord2f`: as [`Context::eval_coord1f`] with the MAP2 maps; with AUTO_NORMAL the
    /// normal is the surface's (see the module docs), whatever MAP2_NORMAL gives.
    pub fn eval_coord2f(&mut self, u: f32, v: f32) {
        record!(self, Call::EvalCoord2f(u, v));
        self.eval2(u, v);
    }

    /// `glEvalCoord2d`.
    pub fn eval_coord2d(&mut self, u: f64, v: f64) {
        record!(self, Call::EvalCoord2d(u, v));
        self.eval2(u as f32, v as f32);
    }

    /// `glEvalCoord2fv`.
    pub fn eval_coord2fv(&mut self, uv: &[f32; 2]) {
        record!(self, Call::EvalCoord2fv(*uv));
        self.eval2(uv[0], uv[1]);
    }

    /// `glEvalCoord2dv`.
    pub fn eval_coord2dv(&mut self, uv: &[f64; 2]) {
        record!(self, Call::EvalCoord2dv(*uv));
        self.eval2(uv[0] as f32, uv[1] as f32);
    }

    /// `glEvalPoint1`: `EvalCoord1` at grid point `i`: `u = i * ((u2 - u1) / n) + u1`.
    pub fn eval_point1(&mut self, i: i32) {
        record!(self, Call::EvalPoint1(i));
        let g = self.state.eval_grid;
        let du = (g.u1[1] - g.u1[0]) / g.un1 as f32;
        self.eval1(i as f32 * du + g.u1[0]);
    }

    /// `glEvalPoint2`: `EvalCoord2` at grid point `(i, j)`.
    pub fn eval_point2(&mut self, i: i32, j: i32) {
        record!(self, Call::EvalPoint2(i, j));
        let g = self.state.eval_grid;
        let du = (g.d2[1] - g.d2[0]) / g.n2[0] as f32;
        let dv = (g.d2[3] - g.d2[2]) / g.n2[1] as f32;
        self.eval2(i as f32 * du + g.d2[0], j as f32 * dv + g.d2[2]);
    }

    /// `glEvalMesh1`: POINT draws POINTS, LINE a LINE_STRIP, of `EvalCoord1` at grid points
    /// `i1` to `i2` (none if `i2 < i1`). INVALID_ENUM for another mode; INVALID_OPERATION
    /// between Begin and End; nothing without MAP1_VERTEX_3 or _4 enabled; OUT_OF_MEMORY past
    /// [`MAX_EVAL_MESH_VERTICES`].
    pub fn eval_mesh1(&mut self, mode: u32, i1: i32, i2: i32) {
        record!(self, Call::EvalMesh1(mode, i1, i2));
        if !self.outside_begin_end() {
            return;
        }
        let prim = match mode {
            gl::POINT => gl::POINTS,
            gl::LINE => gl::LINE_STRIP,
            _ => return self.error(gl::INVALID_ENUM),
        };
        if self.framebuffer_incomplete() {
            return;
        }
        let e = &self.state.enables;
        if !e.map1[VERTEX_3] && !e.map1[VERTEX_4] {
            return;
        }
        let n = steps(i1, i2);
        if n > MAX_EVAL_MESH_VERTICES {
            return self.error(gl::OUT_OF_MEMORY);
        }
        let g = self.state.eval_grid;
        let du = (g.u1[1] - g.u1[0]) / g.un1 as f32;
        let mut u = g.u1[0] + i1 as f32 * du;
        self.begin_unrecorded(prim);
        for _ in 0..n {
            self.eval1(u);
            u += du;
        }
        self.end_unrecorded();
    }

    /// `glEvalMesh2`: POINT draws the grid's points, LINE its lines (a LINE_STRIP per row of
    /// constant v, then one per column), FILL a TRIANGLE_STRIP per row of cells, over grid
    /// points `i1..=i2` x `j1..=j2`. Errors as [`Context::eval_mesh1`]; nothing without
    /// MAP2_VERTEX_3 or _4 enabled.
    pub fn eval_mesh2(&mut self, mode: u32, i1: i32, i2: i32, j1: i32, j2: i32) {
        record!(self, Call::EvalMesh2(mode, i1, i2, j1, j2));
        if !self.outside_begin_end() {
            return;
        }
        if !matches!(mode, gl::POINT | gl::LINE | gl::FILL) {
            return self.error(gl::INVALID_ENUM);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        let e = &self.state.enables;
        if !e.map2[VERTEX_3] && !e.map2[VERTEX_4] {
            return;
        }
        let (ni, nj) = (steps(i1, i2), steps(j1, j2));
        let total = match mode {
            gl::LINE => ni.saturating_mul(nj).saturating_mul(2),
            gl::FILL => ni.saturating_mul(nj.saturating_sub(1)).saturating_mul(2),
            _ => ni.saturating_mul(nj),
        };
        if total > MAX_EVAL_MESH_VERTICES {
            return self.error(gl::OUT_OF_MEMORY);
        }
        let g = self.state.eval_grid;
        let du = (g.d2[1] - g.d2[0]) / g.n2[0] as f32;
        let dv = (g.d2[3] - g.d2[2]) / g.n2[1] as f32;
        let u1 = g.d2[0] + i1 as f32 * du;
        let v1 = g.d2[2] + j1 as f32 * dv;
        match mode {
            gl::POINT => {
                self.begin_unrecorded(gl::POINTS);
                let mut v = v1;
                for _ in 0..nj {
                    let mut u = u1;
                    for _ in 0..ni {
                        self.eval2(u, v);
                        u += du;
                    }
                    v += dv;
                }
                self.end_unrecorded();
            }
            gl::LINE => {
                let mut v = v1;
                for _ in 0..nj {
                    self.begin_unrecorded(gl::LINE_STRIP);
                    let mut u = u1;
                    for _ in 0..ni {
                        self.eval2(u, v);
                        u += du;
                    }
                    self.end_unrecorded();
                    v += dv;
                }
                let mut u = u1;
                for _ in 0..ni {
                    self.begin_unrecorded(gl::LINE_STRIP);
                    let mut v = v1;
                    for _ in 0..nj {
                        self.eval2(u, v);
                        v += dv;
                    }
                    self.end_unrecorded();
                    u += du;
                }
            }
            _ => {
                let mut v = v1;
                for _ in 0..nj.saturating_sub(1) {
                    self.begin_unrecorded(gl::TRIANGLE_STRIP);
                    let mut u = u1;
                    for _ in 0..ni {
                        self.eval2(u, v);
                        self.eval2(u, v + dv);
                        u += du;
                    }
                    self.end_unrecorded();
                    v += dv;
                }
            }
        }
    }

    /// `glGetMapfv`: for `target` (a MAP1_* or MAP2_*), COEFF writes the control points
    /// (`uorder * vorder * k` values, as kept: floats, packed), ORDER the order(s), DOMAIN the
    /// domain (`u1, u2` and for MAP2 `v1, v2`). INVALID_ENUM for another target or query;
    /// INVALID_VALUE, nothing written, if `v` is shorter than [`counts::get_map`];
    /// INVALID_OPERATION between Begin and End.
    pub fn get_mapfv(&mut self, target: u32, query: u32, v: &mut [f32]) {
        if let Some(values) = self.map_values(target, query, v.len()) {
            for (o, x) in v.iter_mut().zip(values) {
                *o = x;
            }
        }
    }

    /// `glGetMapdv`: as [`Context::get_mapfv`], the floats widened.
    pub fn get_mapdv(&mut self, target: u32, query: u32, v: &mut [f64]) {
        if let Some(values) = self.map_values(target, query, v.len()) {
            for (o, x) in v.iter_mut().zip(values) {
                *o = f64::from(x);
            }
        }
    }

    /// `glGetMapiv`: as [`Context::get_mapfv`]; COEFF and DOMAIN values rounded to the
    /// nearest integer (halves away from zero, as Mesa's `lroundf`).
    pub fn get_mapiv(&mut self, target: u32, query: u32, v: &mut [i32]) {
        if let Some(values) = self.map_values(target, query, v.len()) {
            for (o, x) in v.iter_mut().zip(values) {
                *o = x.round() as i32;
            }
        }
    }

    /// The values GetMap writes, after its checks (raising their error and answering `None`).
    fn map_values(&mut self, target: u32, query: u32, room: usize) -> Option<Vec<f32>> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let map = match target {
            gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4 => {
                &self.state.eval_maps.map1[(target - gl::MAP1_COLOR_4) as usize]
            }
            gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4 => {
                &self.state.eval_maps.map2[(target - gl::MAP2_COLOR_4) as usize]
            }
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        let two = target >= gl::MAP2_COLOR_4;
        let values = match query {
            gl::COEFF => map.points.clone(),
            gl::ORDER if two => vec![map.uorder as f32, map.vorder as f32],
            gl::ORDER => vec![map.uorder as f32],
            gl::DOMAIN if two => map.domain.to_vec(),
            gl::DOMAIN => map.domain[..2].to_vec(),
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        if room < values.len() {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some(values)
    }

    /// Begin without recording (EvalMesh is recorded itself); the caller checked the phase.
    fn begin_unrecorded(&mut self, mode: u32) {
        self.begin_mode = Some(mode);
        self.renderer.begin(mode);
        self.renderer.begin_materials(&self.state.materials);
    }

    /// End without recording.
    fn end_unrecorded(&mut self) {
        self.begin_mode = None;
        self.renderer.end();
        self.renderer.flush_if_large(&self.state);
    }

    /// EvalCoord1's body (Mesa's `vbo_exec_do_EvalCoord1f`).
    fn eval1(&mut self, u: f32) {
        let e = &self.state.enables;
        let pos = if e.map1[VERTEX_4] {
            VERTEX_4
        } else if e.map1[VERTEX_3] {
            VERTEX_3
        } else {
            return;
        };
        if self.begin_mode.is_none() {
            // A Vertex outside Begin/End: nothing, and the current values stay.
            return;
        }
        let maps = &self.state.eval_maps.map1;
        let mut cur = self.state.current;
        let at = |i: usize| {
            let m = &maps[i];
            let uu = (u - m.domain[0]) * (1.0 / (m.domain[1] - m.domain[0]));
            let mut out = [0.0, 0.0, 0.0, 1.0];
            horner_curve(
                &m.points,
                &mut out,
                uu,
                EVAL_COMPONENTS[i],
                m.uorder as usize,
            );
            Vec4::from(out)
        };
        if e.map1[COLOR_4] {
            cur.inputs_mut().color = at(COLOR_4);
        }
        if e.map1[NORMAL] {
            cur.normal = at(NORMAL).truncate();
        }
        if let Some(t) = (0..4).rev().find(|&t| e.map1[TEXTURE_COORD_1 + t]) {
            cur.inputs_mut().tex_coords[0] = at(TEXTURE_COORD_1 + t);
        }
        let p = at(pos);
        self.renderer.vertex_computed(p, &cur);
    }

    /// EvalCoord2's body (Mesa's `vbo_exec_do_EvalCoord2f`).
    fn eval2(&mut self, u: f32, v: f32) {
        let e = &self.state.enables;
        let pos = if e.map2[VERTEX_4] {
            VERTEX_4
        } else if e.map2[VERTEX_3] {
            VERTEX_3
        } else {
            return;
        };
        if self.begin_mode.is_none() {
            return;
        }
        let maps = &self.state.eval_maps.map2;
        let params = |m: &EvalMap| {
            let uu = (u - m.domain[0]) * (1.0 / (m.domain[1] - m.domain[0]));
            let vv = (v - m.domain[2]) * (1.0 / (m.domain[3] - m.domain[2]));
            (uu, vv)
        };
        let at = |i: usize| {
            let m = &maps[i];
            let (uu, vv) = params(m);
            let mut out = [0.0, 0.0, 0.0, 1.0];
            let (uo, vo) = (m.uorder as usize, m.vorder as usize);
            horner_surf(&m.points, &mut out, uu, vv, EVAL_COMPONENTS[i], uo, vo);
            Vec4::from(out)
        };
        let mut cur = self.state.current;
        if e.map2[COLOR_4] {
            cur.inputs_mut().color = at(COLOR_4);
        }
        if e.map2[NORMAL] {
            cur.normal = at(NORMAL).truncate();
        }
        if let Some(t) = (0..4).rev().find(|&t| e.map2[TEXTURE_COORD_1 + t]) {
            cur.inputs_mut().tex_coords[0] = at(TEXTURE_COORD_1 + t);
        }
        let p = if e.auto_normal {
            let m = &maps[pos];
            let (uu, vv) = params(m);
            let dim = EVAL_COMPONENTS[pos];
            let (mut p, mut du, mut dv) = ([0.0, 0.0, 0.0, 1.0], [0.0; 4], [0.0; 4]);
            let (uo, vo) = (m.uorder as usize, m.vorder as usize);
            de_casteljau_surf(&m.points, &mut p, &mut du, &mut dv, uu, vv, dim, uo, vo);
            if dim == 4 {
                for k in 0..3 {
                    du[k] = du[k] * p[3] - du[3] * p[k];
                    dv[k] = dv[k] * p[3] - dv[3] * p[k];
                }
            }
            let n = [
                du[1] * dv[2] - du[2] * dv[1],
                du[2] * dv[0] - du[0] * dv[2],
                du[0] * dv[1] - du[1] * dv[0],
            ];
            let len = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
            cur.normal = if len != 0.0 {
                let inv = 1.0 / len.sqrt();
                Vec3::new(n[0] * inv, n[1] * inv, n[2] * inv)
            } else {
                Vec3::from(n)
            };
            Vec4::from(p)
        } else {
            at(pos)
        };
        self.renderer.vertex_computed(p, &cur);
    }
}

/// The number of grid points from `a` to `b` inclusive (0 if `b < a`).
fn steps(a: i32, b: i32) -> u64 {
    (i64::from(b) - i64::from(a) + 1).max(0) as u64
}

/// `1 / i` as Mesa tabulates it (`inv_tab`), in float.
fn inv(i: usize) -> f32 {
    1.0 / i as f32
}

/// A point of the Bézier curve of `order` points of `dim` components at `cp`, at `t` (0 to 1),
/// by Horner's scheme with the binomial coefficients kept as a running product, in Mesa's
/// order of float operations (`_math_horner_bezier_curve`); writes `dim` values of `out`.
fn horner_curve(cp: &[f32], out: &mut [f32], t: f32, dim: usize, order: usize) {
    if order < 2 {
        out[..dim].copy_from_slice(&cp[..dim]);
        return;
    }
    let mut bincoeff = (order - 1) as f32;
    let s = 1.0 - t;
    for k in 0..dim {
        out[k] = s * cp[k] + bincoeff * t * cp[dim + k];
    }
    let mut powert = t * t;
    for i in 2..order {
        bincoeff *= (order - i) as f32;
        bincoeff *= inv(i);
        let p = &cp[i * dim..];
        for k in 0..dim {
            out[k] = s * out[k] + bincoeff * powert * p[k];
        }
        powert *= t;
    }
}

/// A point of the tensor-product Bézier surface of `uorder` x `vorder` points at `cn` (point
/// `(i, j)` at `(i * vorder + j) * dim`): the control polygon of the curve along the larger
/// order first, then its point (`_math_horner_bezier_surf`).
fn horner_surf(cn: &[f32], out: &mut [f32], u: f32, v: f32, dim: usize, uo: usize, vo: usize) {
    let uinc = vo * dim;
    let mut cp = [0.0f32; MAX_EVAL_ORDER as usize * 4];
    if vo > uo {
        if uo < 2 {
            return horner_curve(cn, out, v, dim, vo);
        }
        // The curve along v whose points are the u-curves' points at u.
        let s = 1.0 - u;
        for j in 0..vo {
            let ucp = &cn[j * dim..];
            let mut bincoeff = (uo - 1) as f32;
            for k in 0..dim {
                cp[j * dim + k] = s * ucp[k] + bincoeff * u * ucp[uinc + k];
            }
            let mut poweru = u * u;
            for i in 2..uo {
                bincoeff *= (uo - i) as f32;
                bincoeff *= inv(i);
                for k in 0..dim {
                    cp[j * dim + k] = s * cp[j * dim + k] + bincoeff * poweru * ucp[i * uinc + k];
                }
                poweru *= u;
            }
        }
        horner_curve(&cp, out, v, dim, vo);
    } else {
        if vo < 2 {
            // Points along u are `uinc = dim` apart: the points as one curve.
            return horner_curve(cn, out, u, dim, uo);
        }
        for i in 0..uo {
            horner_curve(&cn[i * uinc..], &mut cp[i * dim..], v, dim, vo);
        }
        horner_curve(&cp, out, u, dim, uo);
    }
}

/// The point and the partial derivative directions (unscaled: the derivatives divided by the
/// degree) of the surface at `(u, v)`, by de Casteljau's algorithm in Mesa's order of
/// operations (`_math_de_casteljau_surf`), one component at a time. A direction of order 1 has
/// no derivative: it is zero (Mesa reads past the points there).
#[allow(clippy::too_many_arguments)]
fn de_casteljau_surf(
    cn: &[f32],
    out: &mut [f32; 4],
    du: &mut [f32; 4],
    dv: &mut [f32; 4],
    u: f32,
    v: f32,
    dim: usize,
    uo: usize,
    vo: usize,
) {
    if uo < 2 || vo < 2 {
        let mut p = [0.0, 0.0, 0.0, 1.0];
        horner_surf(cn, &mut p, u, v, dim, uo, vo);
        out[..dim].copy_from_slice(&p[..dim]);
        du[..dim].fill(0.0);
        dv[..dim].fill(0.0);
        return;
    }
    // The scratch net, zeroed: DCN(i, j) at i * vo + j. Its indices stay below
    // max(uo, 3)·vo + 3 (rows up to max(uo − 1, 2), columns up to max(vo − 1, 2)), so a net
    // that small runs on a small zeroed array: the same values (an entry never written reads
    // 0 either way) without zeroing 3.6 KB for every point (which cost three quarters of the
    // evaluation of a bicubic patch).
    const SMALL: usize = 64;
    if uo.max(3) * vo + 3 <= SMALL {
        let mut d = [0.0f32; SMALL];
        de_casteljau_net(cn, out, du, dv, [u, v], dim, uo, vo, &mut d);
    } else {
        let mut d = [0.0f32; (MAX_EVAL_ORDER * MAX_EVAL_ORDER) as usize];
        de_casteljau_net(cn, out, du, dv, [u, v], dim, uo, vo, &mut d);
    }
}

/// The body of [`de_casteljau_surf`] for orders of at least 2, on the zeroed scratch net `d`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn de_casteljau_net(
    cn: &[f32],
    out: &mut [f32; 4],
    du: &mut [f32; 4],
    dv: &mut [f32; 4],
    [u, v]: [f32; 2],
    dim: usize,
    uo: usize,
    vo: usize,
    d: &mut [f32],
) {
    let (us, vs) = (1.0 - u, 1.0 - v);
    let minorder = uo.min(vo);
    let uinc = vo * dim;
    let c = |i: usize, j: usize, k: usize| cn[i * uinc + j * dim + k];
    let ix = |i: usize, j: usize| i * vo + j;
    for k in 0..dim {
        if minorder < 3 {
            if uo == vo {
                du[k] = vs * (c(1, 0, k) - c(0, 0, k)) + v * (c(1, 1, k) - c(0, 1, k));
                dv[k] = us * (c(0, 1, k) - c(0, 0, k)) + u * (c(1, 1, k) - c(1, 0, k));
                out[k] = us * (vs * c(0, 0, k) + v * c(0, 1, k))
                    + u * (vs * c(1, 0, k) + v * c(1, 1, k));
            } else if minorder == uo {
                d[ix(1, 0)] = c(1, 0, k) - c(0, 0, k);
                d[ix(0, 0)] = us * c(0, 0, k) + u * c(1, 0, k);
                for j in 0..vo - 1 {
                    d[ix(1, j + 1)] = c(1, j + 1, k) - c(0, j + 1, k);
                    d[ix(1, j)] = vs * d[ix(1, j)] + v * d[ix(1, j + 1)];
                    d[ix(0, j + 1)] = us * c(0, j + 1, k) + u * c(1, j + 1, k);
                    d[ix(0, j)] = vs * d[ix(0, j)] + v * d[ix(0, j + 1)];
                }
                for h in minorder..vo - 1 {
                    for j in 0..vo - h {
                        d[ix(1, j)] = vs * d[ix(1, j)] + v * d[ix(1, j + 1)];
                        d[ix(0, j)] = vs * d[ix(0, j)] + v * d[ix(0, j + 1)];
                    }
                }
                dv[k] = d[ix(0, 1)] - d[ix(0, 0)];
                du[k] = vs * d[ix(1, 0)] + v * d[ix(1, 1)];
                out[k] = vs * d[ix(0, 0)] + v * d[ix(0, 1)];
            } else {
                d[ix(0, 1)] = c(0, 1, k) - c(0, 0, k);
                d[ix(0, 0)] = vs * c(0, 0, k) + v * c(0, 1, k);
                for i in 0..uo - 1 {
                    d[ix(i + 1, 1)] = c(i + 1, 1, k) - c(i + 1, 0, k);
                    d[ix(i, 1)] = us * d[ix(i, 1)] + u * d[ix(i + 1, 1)];
                    d[ix(i + 1, 0)] = vs * c(i + 1, 0, k) + v * c(i + 1, 1, k);
                    d[ix(i, 0)] = us * d[ix(i, 0)] + u * d[ix(i + 1, 0)];
                }
                for h in minorder..uo - 1 {
                    for i in 0..uo - h {
                        d[ix(i, 1)] = us * d[ix(i, 1)] + u * d[ix(i + 1, 1)];
                        d[ix(i, 0)] = us * d[ix(i, 0)] + u * d[ix(i + 1, 0)];
                    }
                }
                du[k] = d[ix(1, 0)] - d[ix(0, 0)];
                dv[k] = us * d[ix(0, 1)] + u * d[ix(1, 1)];
                out[k] = us * d[ix(0, 0)] + u * d[ix(1, 0)];
            }
            continue;
        }
        // Both orders at least 3: bilinear steps down to a 2x2 net (or a strip of one).
        for i in 0..uo - 1 {
            d[ix(i, 0)] = us * c(i, 0, k) + u * c(i + 1, 0, k);
            for j in 0..vo - 1 {
                d[ix(i, j + 1)] = us * c(i, j + 1, k) + u * c(i + 1, j + 1, k);
                d[ix(i, j)] = vs * d[ix(i, j)] + v * d[ix(i, j + 1)];
            }
        }
        for h in 2..minorder - 1 {
            for i in 0..uo - h {
                d[ix(i, 0)] = us * d[ix(i, 0)] + u * d[ix(i + 1, 0)];
                for j in 0..vo - h {
                    d[ix(i, j + 1)] = us * d[ix(i, j + 1)] + u * d[ix(i + 1, j + 1)];
                    d[ix(i, j)] = vs * d[ix(i, j)] + v * d[ix(i, j + 1)];
                }
            }
        }
        if uo == vo {
            du[k] = vs * (d[ix(1, 0)] - d[ix(0, 0)]) + v * (d[ix(1, 1)] - d[ix(0, 1)]);
            dv[k] = us * (d[ix(0, 1)] - d[ix(0, 0)]) + u * (d[ix(1, 1)] - d[ix(1, 0)]);
            out[k] = us * (vs * d[ix(0, 0)] + v * d[ix(0, 1)])
                + u * (vs * d[ix(1, 0)] + v * d[ix(1, 1)]);
        } else if minorder == uo {
            d[ix(2, 0)] = d[ix(1, 0)] - d[ix(0, 0)];
            d[ix(0, 0)] = us * d[ix(0, 0)] + u * d[ix(1, 0)];
            for j in 0..vo - 1 {
                d[ix(2, j + 1)] = d[ix(1, j + 1)] - d[ix(0, j + 1)];
                d[ix(2, j)] = vs * d[ix(2, j)] + v * d[ix(2, j + 1)];
                d[ix(0, j + 1)] = us * d[ix(0, j + 1)] + u * d[ix(1, j + 1)];
                d[ix(0, j)] = vs * d[ix(0, j)] + v * d[ix(0, j + 1)];
            }
            for h in minorder..vo - 1 {
                for j in 0..vo - h {
                    d[ix(2, j)] = vs * d[ix(2, j)] + v * d[ix(2, j + 1)];
                    d[ix(0, j)] = vs * d[ix(0, j)] + v * d[ix(0, j + 1)];
                }
            }
            dv[k] = d[ix(0, 1)] - d[ix(0, 0)];
            du[k] = vs * d[ix(2, 0)] + v * d[ix(2, 1)];
            out[k] = vs * d[ix(0, 0)] + v * d[ix(0, 1)];
        } else {
            d[ix(0, 2)] = d[ix(0, 1)] - d[ix(0, 0)];
            d[ix(0, 0)] = vs * d[ix(0, 0)] + v * d[ix(0, 1)];
            for i in 0..uo - 1 {
                d[ix(i + 1, 2)] = d[ix(i + 1, 1)] - d[ix(i + 1, 0)];
                d[ix(i, 2)] = us * d[ix(i, 2)] + u * d[ix(i + 1, 2)];
                d[ix(i + 1, 0)] = vs * d[ix(i + 1, 0)] + v * d[ix(i + 1, 1)];
                d[ix(i, 0)] = us * d[ix(i, 0)] + u * d[ix(i + 1, 0)];
            }
            for h in minorder..uo - 1 {
                for i in 0..uo - h {
                    d[ix(i, 2)] = us * d[ix(i, 2)] + u * d[ix(i + 1, 2)];
                    d[ix(i, 0)] = us * d[ix(i, 0)] + u * d[ix(i + 1, 0)];
                }
            }
            du[k] = d[ix(1, 0)] - d[ix(0, 0)];
            dv[k] = us * d[ix(0, 2)] + u * d[ix(1, 2)];
            out[k] = us * d[ix(0, 0)] + u * d[ix(1, 0)];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic's point by the Bernstein sum, in f64.
    fn bernstein(p: &[f64; 4], t: f64) -> f64 {
        let s = 1.0 - t;
        s * s * s * p[0] + 3.0 * s * s * t * p[1] + 3.0 * s * t * t * p[2] + t * t * t * p[3]
    }

    /// A grid of billions of points is OUT_OF_MEMORY at once; extreme strides and orders with a
    /// short slice are INVALID_VALUE without allocating; nothing panics.
    #[test]
    fn extreme_arguments_are_prompt_errors() {
        let mut gl = Context::new(8, 8).expect("context");
        gl.map2f(
            gl::MAP2_VERTEX_3,
            0.0,
            1.0,
            3,
            2,
            0.0,
            1.0,
            6,
            2,
            &[0.0; 12],
        );
        gl.enable(gl::MAP2_VERTEX_3);
        gl.map1f(gl::MAP1_VERTEX_4, 0.0, 1.0, 4, 2, &[0.0; 8]);
        gl.enable(gl::MAP1_VERTEX_4);
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        let start = std::time::Instant::now();
        gl.eval_mesh2(gl::FILL, i32::MIN, i32::MAX, i32::MIN, i32::MAX);
        assert_eq!(gl.get_error(), gl::OUT_OF_MEMORY);
        gl.eval_mesh1(gl::LINE, -5, i32::MAX);
        assert_eq!(gl.get_error(), gl::OUT_OF_MEMORY);
        gl.eval_mesh2(gl::LINE, 0, 2047, 0, 1023);
        assert_eq!(gl.get_error(), gl::NO_ERROR, "2M points are drawn");
        gl.eval_mesh2(gl::POINT, i32::MAX, i32::MIN, 0, 0);
        assert_eq!(gl.get_error(), gl::NO_ERROR, "an empty range is no error");
        gl.map2f(
            gl::MAP2_VERTEX_3,
            0.0,
            1.0,
            i32::MAX,
            30,
            0.0,
            1.0,
            i32::MAX,
            30,
            &[0.0; 3],
        );
        assert_eq!(gl.get_error(), gl::INVALID_VALUE);
        gl.map1d(
            gl::MAP1_COLOR_4,
            f64::MAX,
            f64::INFINITY,
            i32::MAX,
            30,
            &[0.0; 4],
        );
        assert_eq!(gl.get_error(), gl::INVALID_VALUE);
        gl.map_grid2f(1, f32::NAN, f32::INFINITY, 1, -0.0, f32::MAX);
        gl.eval_mesh2(gl::FILL, 0, 1, 0, 1);
        gl.eval_point2(i32::MIN, i32::MAX);
        assert!(start.elapsed() < std::time::Duration::from_secs(20));
        let mut order = [0.0f32; 2];
        gl.get_mapfv(gl::MAP2_VERTEX_3, gl::ORDER, &mut order);
        assert_eq!(order, [2.0, 2.0]);
        let mut short = [0.0f32; 1];
        gl.get_mapfv(gl::MAP2_VERTEX_3, gl::DOMAIN, &mut short);
        assert_eq!(gl.get_error(), gl::INVALID_VALUE);
    }

    #[test]
    fn horner_is_the_bernstein_sum() {
        let p = [0.0, 3.0, -2.0, 1.0];
        let cp: Vec<f32> = p.iter().map(|&x| x as f32).collect();
        for t in [0.0, 0.25, 0.5, 0.9, 1.0] {
            let mut out = [0.0; 4];
            horner_curve(&cp, &mut out, t as f32, 1, 4);
            assert!((f64::from(out[0]) - bernstein(&p, t)).abs() < 1e-5, "{t}");
        }
    }

    /// `de_casteljau_surf` on its small scratch net gives the bits of the full-size net, for
    /// every pair of orders from 2 to 30 and every dimension, over random nets and parameters
    /// (inside and outside [0, 1]).
    #[test]
    fn the_small_scratch_net_gives_the_full_nets_bits() {
        let mut x = 0x2545_f491u32;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            (x >> 8) as f32 / (1u32 << 24) as f32
        };
        let max = MAX_EVAL_ORDER as usize;
        let mut small = 0;
        for uo in 2..=max {
            for vo in 2..=max {
                let dim = 1 + (uo + vo) % 4;
                small += usize::from(uo.max(3) * vo + 3 <= 64);
                let net: Vec<f32> = (0..uo * vo * dim).map(|_| next() * 4.0 - 2.0).collect();
                for _ in 0..3 {
                    let (u, v) = (next() * 1.4 - 0.2, next() * 1.4 - 0.2);
                    let (mut c, mut du, mut dv) = ([0.0; 4], [0.0; 4], [0.0; 4]);
                    de_casteljau_surf(&net, &mut c, &mut du, &mut dv, u, v, dim, uo, vo);
                    let (mut c2, mut du2, mut dv2) = ([0.0; 4], [0.0; 4], [0.0; 4]);
                    let mut d = [0.0f32; (MAX_EVAL_ORDER * MAX_EVAL_ORDER) as usize];
                    let (o, p) = (&mut c2, &mut du2);
                    de_casteljau_net(&net, o, p, &mut dv2, [u, v], dim, uo, vo, &mut d);
                    let bits = |a: [f32; 4]| a.map(f32::to_bits);
                    assert_eq!(
                        [bits(c), bits(du), bits(dv)],
                        [bits(c2), bits(du2), bits(dv2)],
                        "{uo}x{vo}, dimension {dim}, at {u}, {v}"
                    );
                }
            }
        }
        assert!(small > 20, "only {small} order pairs took the small net");
    }

    #[test]
    fn surfaces_agree_both_ways_and_with_de_casteljau() {
        // A 4x3 net, one component, and its transpose.
        for (uo, vo) in [(4, 3), (3, 4), (2, 2), (2, 5), (5, 2), (4, 4), (3, 3)] {
            let net: Vec<f32> = (0..uo * vo).map(|i| ((i * 7) % 5) as f32 - 1.5).collect();
            for (u, v) in [(0.3f32, 0.6f32), (0.0, 1.0), (0.75, 0.1)] {
                let mut h = [0.0; 4];
                horner_surf(&net, &mut h, u, v, 1, uo, vo);
                let (mut c, mut du, mut dv) = ([0.0; 4], [0.0; 4], [0.0; 4]);
                de_casteljau_surf(&net, &mut c, &mut du, &mut dv, u, v, 1, uo, vo);
                assert!(
                    (h[0] - c[0]).abs() < 1e-5,
                    "{uo}x{vo} at {u},{v}: {h:?} {c:?}"
                );
                // The derivative in u over the degree, by a central difference.
                let e = 1e-3;
                let (mut a, mut b) = ([0.0; 4], [0.0; 4]);
                horner_surf(&net, &mut a, u + e, v, 1, uo, vo);
                horner_surf(&net, &mut b, u - e, v, 1, uo, vo);
                let numeric = (a[0] - b[0]) / (2.0 * e) / (uo - 1) as f32;
                assert!(
                    (numeric - du[0]).abs() < 2e-2,
                    "{uo}x{vo}: {numeric} {du:?}"
                );
                horner_surf(&net, &mut a, u, v + e, 1, uo, vo);
                horner_surf(&net, &mut b, u, v - e, 1, uo, vo);
                let numeric = (a[0] - b[0]) / (2.0 * e) / (vo - 1) as f32;
                assert!(
                    (numeric - dv[0]).abs() < 2e-2,
                    "{uo}x{vo}: {numeric} {dv:?}"
                );
            }
        }
    }
}
