//! Selection and feedback (GL 2.1 §5.2, §5.3): in SELECT and FEEDBACK render modes a flush turns
//! the batched primitives into hit records or feedback tokens instead of fragments.
//!
//! Design decision: the primitives take the path Mesa's draw module gives them on llvmpipe
//! (`st_cb_feedback.c` over `draw_pipe_*.c`), because what is compared with the driver is the
//! buffer word for word: the Begin modes are decomposed into points, lines and triangles in
//! draw's order (quads and polygons as triangles with the provoking vertex last, each with its
//! boundary-edge flags), triangles are clipped against the planes in draw's order (right, left,
//! top, bottom, near, far, then the user planes), the clipped polygon is emitted as a fan around
//! its first vertex, then culled (a zero-area triangle counts as back-facing), coloured with the
//! back colours when two-sided lighting finds it back-facing, and drawn as lines or points per
//! PolygonMode. A triangle is one POLYGON_TOKEN 3; LINE_RESET_TOKEN marks the first edge drawn
//! of a polygon in LINE mode (draw resets the line stipple there), never a line of a Begin line
//! mode, and the reset stays pending until a line is emitted, across RenderMode calls, as in
//! the driver. Window coordinates are computed in single precision as draw computes them:
//! x · (1/w) · scale + translate, with Mesa's viewport scale and translate, and a vertex made
//! by clipping is interpolated from whichever end is nearer the plane, as draw does: with
//! exactly representable inputs the values are the driver's bit for bit (on an FBO, as the GL
//! backend draws; llvmpipe's window framebuffers flip y and back, which can change its last
//! bit). Where the vertex stage rounds differently (fixedgl transforms by the modelview, then
//! the projection; Mesa by their product, fused multiply-adds included), the last bits can
//! differ.
//!
//! Where llvmpipe departs from GL 2.1 in ways that are evidently not choices (texture
//! coordinates left untransformed unless unit 0 has a complete enabled texture, every edge
//! dropped once EdgeFlag has been called in the primitive), fixedgl does what the spec says;
//! docs/conformance.md lists them. Polygon offset is not applied to feedback or hit depths.

use glam::Vec4;

use super::batch::Batch;
use super::vertex::Layout;
use crate::gl;
use crate::state::{State, MAX_CLIP_PLANES};

/// `MAX_NAME_STACK_DEPTH` (Mesa's value; the spec's minimum is 64).
pub const MAX_NAME_STACK_DEPTH: usize = 64;
/// The largest SelectBuffer or FeedbackBuffer size (in values) fixedgl takes; past it the call
/// is OUT_OF_MEMORY (GL 2.1 §2.5 allows it anywhere). The context only grows its buffer as
/// values are written; the GL backend has to give the driver the whole buffer.
pub const MAX_BUFFER: i32 = 1 << 24;

/// The selection and feedback state of a context: the buffers, the name stack, the pending hit.
#[derive(Clone, Debug)]
pub struct Sink {
    /// SelectBuffer's size, `None` before the first SelectBuffer.
    pub select_size: Option<usize>,
    /// The values written since the buffer was given or selection last began (at most the size).
    pub select: Vec<u32>,
    /// Values the current selection run produced (beyond the size: overflow).
    select_count: usize,
    /// Hit records written in the current selection run.
    hits: i32,
    /// The name stack.
    pub names: Vec<u32>,
    /// The pending hit's minimum and maximum window z (HitFlag set when `Some`).
    hit: Option<(f32, f32)>,
    /// FeedbackBuffer's size and type, `None` before the first FeedbackBuffer.
    pub feedback_size: Option<usize>,
    /// FEEDBACK_BUFFER_TYPE (2D until set).
    pub feedback_type: u32,
    /// The values written since the buffer was given or feedback last began.
    pub feedback: Vec<f32>,
    /// Values the current feedback run produced.
    feedback_count: usize,
    /// The next line is a LINE_RESET_TOKEN (see the module docs).
    line_reset: bool,
}

impl Default for Sink {
    fn default() -> Self {
        Sink {
            select_size: None,
            select: Vec::new(),
            select_count: 0,
            hits: 0,
            names: Vec::new(),
            hit: None,
            feedback_size: None,
            feedback_type: gl::GL_2D,
            feedback: Vec::new(),
            feedback_count: 0,
            line_reset: false,
        }
    }
}

/// One vertex on its way through the primitive pipeline.
#[derive(Clone, Copy, Debug, Default)]
struct FVert {
    clip: Vec4,
    /// Front colour (the primary colour, lit or not, clamped).
    col: Vec4,
    /// Back colour under two-sided lighting.
    col_b: Vec4,
    tex: Vec4,
    eye: Vec4,
    /// The vertex's edge flag (for a clip-made vertex: draw's rule).
    edge: bool,
    /// The outside-plane bits of `clip` and `eye` ([`Sink::clipmask`]; read only for the
    /// batch's vertices, not for clip-made ones).
    mask: u16,
    /// The window coordinates of `clip` ([`Sink::win`]), set once a vertex is complete.
    win: [f32; 4],
}

impl FVert {
    /// The vertex with its clip mask and window coordinates computed (once a vertex, not once
    /// a primitive that uses it).
    fn prepared(mut self, ctx: &Ctx) -> Self {
        self.mask = Sink::clipmask(ctx, &self);
        self.win = Sink::win(ctx, &self);
        self
    }

    /// The vertex with its window coordinates computed (a clip-made vertex).
    fn windowed(mut self, ctx: &Ctx) -> Self {
        self.win = Sink::win(ctx, &self);
        self
    }
}

/// Draw's triangle flags: the boundary edges (edge i runs from v[i] to v[i+1]) and the line
/// stipple reset.
const E0: u8 = 1;
const E1: u8 = 2;
const E2: u8 = 4;
const EALL: u8 = 7;
const RESET: u8 = 8;

/// The constants of one flush.
struct Ctx {
    scale: [f32; 3],
    trans: [f32; 3],
    user: [(bool, Vec4); MAX_CLIP_PLANES],
    cull: Option<u32>,
    /// Facing is needed (cull stage active): culling, two-sided lighting or an unfilled mode.
    det: bool,
    ccw_front: bool,
    two_side: bool,
    modes: [u32; 2],
    flat: bool,
    select: bool,
    /// The enabled user clip planes' indices (6 + plane), in order, `nuser` of them.
    users: [u8; MAX_CLIP_PLANES],
    nuser: usize,
}

impl Sink {
    /// `SelectBuffer(size)` taken (validated): selection starts over in a new buffer.
    pub fn set_select_buffer(&mut self, size: usize) {
        self.select_size = Some(size);
        self.select.clear();
        self.select_count = 0;
        self.hit = None;
    }

    /// `FeedbackBuffer(size, type)` taken (validated).
    pub fn set_feedback_buffer(&mut self, size: usize, ty: u32) {
        self.feedback_size = Some(size);
        self.feedback_type = ty;
        self.feedback.clear();
        self.feedback_count = 0;
    }

    /// NAME_STACK_DEPTH.
    pub fn name_stack_depth(&self) -> usize {
        self.names.len()
    }

    /// Records window depth `z` in the pending hit (Mesa's `_mesa_update_hitflag`).
    pub fn update_hit(&mut self, z: f32) {
        self.hit = Some(match self.hit {
            Some((lo, hi)) => (if z < lo { z } else { lo }, if z > hi { z } else { hi }),
            None => (z, z),
        });
    }

    fn write_select(&mut self, v: u32) {
        if self.select_count < self.select_size.unwrap_or(0) {
            self.select.push(v);
        }
        self.select_count += 1;
    }

    /// Writes the pending hit record, if any (GL 2.1 §5.2): the name stack depth, the minimum and
    /// maximum window z as Mesa scales them (z · 2^32 in single precision, truncated to 32
    /// bits, so z = 1 gives 0, as llvmpipe writes it), and the names.
    pub fn flush_hit(&mut self) {
        let Some((lo, hi)) = self.hit.take() else {
            return;
        };
        // (GLfloat) 0xffffffff is 2^32; the product is exact; x86's conversion keeps the low 32
        // bits of the 64-bit integer.
        let scale = |z: f32| ((z * 4_294_967_296.0f32) as u64) as u32;
        self.write_select(self.names.len() as u32);
        self.write_select(scale(lo));
        self.write_select(scale(hi));
        for i in 0..self.names.len() {
            let n = self.names.get(i).copied().unwrap_or(0);
            self.write_select(n);
        }
        self.hits += 1;
    }

    /// Leaves SELECT mode (RenderMode): writes the pending hit, and returns the number of hit
    /// records, or -1 when they did not fit; the name stack is emptied.
    pub fn end_select(&mut self) -> i32 {
        self.flush_hit();
        let overflow = self.select_count > self.select_size.unwrap_or(0);
        let result = if overflow { -1 } else { self.hits };
        self.select_count = 0;
        self.hits = 0;
        self.names.clear();
        result
    }

    /// Enters SELECT mode: a new run writes from the buffer's start.
    pub fn begin_select(&mut self) {
        self.select.clear();
        self.select_count = 0;
        self.hits = 0;
    }

    /// Leaves FEEDBACK mode: the number of values written, or -1 when they did not fit.
    pub fn end_feedback(&mut self) -> i32 {
        let overflow = self.feedback_count > self.feedback_size.unwrap_or(0);
        let result = if overflow {
            -1
        } else {
            self.feedback_count as i32
        };
        self.feedback_count = 0;
        result
    }

    /// Enters FEEDBACK mode.
    pub fn begin_feedback(&mut self) {
        self.feedback.clear();
        self.feedback_count = 0;
    }

    /// Appends one feedback value (counted even past the buffer's end).
    pub fn token(&mut self, v: f32) {
        if self.feedback_count < self.feedback_size.unwrap_or(0) {
            self.feedback.push(v);
        }
        self.feedback_count += 1;
    }

    /// Appends one vertex in the buffer's type (GL 2.1 table 5.2): window x, y (z for 3D types,
    /// w for 4D), the colour (RGBA), the texture coordinates (s, t, r, q).
    pub fn vertex(&mut self, win: [f32; 4], color: Vec4, tex: Vec4) {
        let ty = self.feedback_type;
        self.token(win[0]);
        self.token(win[1]);
        if ty != gl::GL_2D {
            self.token(win[2]);
        }
        if ty == gl::GL_4D_COLOR_TEXTURE {
            self.token(win[3]);
        }
        if matches!(
            ty,
            gl::GL_3D_COLOR | gl::GL_3D_COLOR_TEXTURE | gl::GL_4D_COLOR_TEXTURE
        ) {
            for c in color.to_array() {
                self.token(c);
            }
        }
        if matches!(ty, gl::GL_3D_COLOR_TEXTURE | gl::GL_4D_COLOR_TEXTURE) {
            for t in tex.to_array() {
                self.token(t);
            }
        }
    }

    /// A pixel-rectangle token at a raster position (GL 2.1 §5.3): BITMAP_TOKEN,
    /// DRAW_PIXEL_TOKEN or COPY_PIXEL_TOKEN, then the current raster position as a vertex
    /// (window coordinates and clip w, the raster colour, unit 0's raster texture coordinates).
    /// What Bitmap, DrawPixels and CopyPixels write in FEEDBACK mode with a valid raster
    /// position; in SELECT mode they write nothing, as in Mesa (RasterPos makes the hit).
    pub fn raster_token(&mut self, token: u32, win: [f32; 4], color: Vec4, tex: Vec4) {
        self.token(token as f32);
        self.vertex(win, color, tex);
    }

    /// Runs the batch's primitives through the selection or feedback pipeline (see the module
    /// docs). `vout` and `wins` are the vertex stage's scratch space.
    pub fn process(
        &mut self,
        state: &State,
        batch: &Batch,
        vout: &mut Vec<f32>,
        wins: &mut Vec<super::setup::Win>,
        tiles: (usize, usize),
    ) {
        let select = state.render_mode == gl::SELECT;
        let layout = match select {
            true => Layout::for_select(state),
            false => Layout::for_feedback(state),
        };
        let rect = super::framebuffer::scissor_rect(state);
        let setup = super::setup::SetupCtx::new(state, layout, rect, tiles);
        match select {
            true => super::vertex::positions(state, batch, &layout, &setup, vout, wins),
            false => super::vertex::process(state, batch, &layout, &setup, vout, wins, false),
        }
        let get = |v: &[f32], o: Option<usize>| -> Vec4 {
            match o.and_then(|o| v.get(o..o + 4)) {
                Some(s) => Vec4::new(s[0], s[1], s[2], s[3]),
                None => Vec4::ZERO,
            }
        };
        let mut verts: Vec<FVert> = vout
            .chunks_exact(layout.stride.max(1))
            .zip(batch.edge())
            .map(|(v, &edge)| FVert {
                clip: get(v, Some(0)),
                col: get(v, Some(layout.col)),
                col_b: get(v, layout.col_b.or(Some(layout.col))),
                tex: get(v, layout.tex[0]),
                eye: get(v, layout.eye),
                edge,
                ..FVert::default()
            })
            .collect();
        let [vx, vy, vw, vh] = state.viewport;
        let (hw, hh) = (0.5f32 * vw as f32, 0.5f32 * vh as f32);
        let [n, f] = state.depth_range;
        let mut user = [(false, Vec4::ZERO); MAX_CLIP_PLANES];
        for (k, u) in user.iter_mut().enumerate() {
            *u = (state.enables.clip_planes[k], state.clip_planes[k].as_vec4());
        }
        let unfilled = state.polygon_mode != [gl::FILL; 2];
        let two_side = state.enables.lighting && state.light_model.two_side;
        let mut users = [0u8; MAX_CLIP_PLANES];
        let mut nuser = 0;
        for (k, u) in user.iter().enumerate() {
            if u.0 {
                if let Some(slot) = users.get_mut(nuser) {
                    *slot = (6 + k) as u8;
                    nuser += 1;
                }
            }
        }
        let ctx = Ctx {
            scale: [hw, hh, (0.5 * (f - n)) as f32],
            trans: [hw + vx as f32, hh + vy as f32, (0.5 * (n + f)) as f32],
            user,
            cull: state.enables.cull_face.then_some(state.cull_face_mode),
            det: unfilled || two_side || state.enables.cull_face,
            ccw_front: state.front_face != gl::CW,
            two_side,
            modes: state.polygon_mode,
            flat: state.shade_model == gl::FLAT,
            select,
            users,
            nuser,
        };
        for v in &mut verts {
            *v = v.prepared(&ctx);
        }
        let zero = FVert::default().prepared(&ctx);
        let vert = |i: u32| {
            let u = batch.idx.get(i as usize).copied().unwrap_or(u32::MAX);
            verts.get(u as usize).copied().unwrap_or(zero)
        };
        for p in &batch.prims {
            let (f0, n) = (p.first, p.count);
            let v = |k: u32| vert(f0 + k);
            match p.mode {
                gl::POINTS => (0..n).for_each(|k| self.point(&ctx, v(k))),
                gl::LINES => {
                    for k in (0..n.saturating_sub(1)).step_by(2) {
                        self.line(&ctx, v(k), v(k + 1));
                    }
                }
                gl::LINE_STRIP | gl::LINE_LOOP if n >= 2 => {
                    for k in 1..n {
                        self.line(&ctx, v(k - 1), v(k));
                    }
                    if p.mode == gl::LINE_LOOP {
                        self.line(&ctx, v(n - 1), v(0));
                    }
                }
                gl::TRIANGLES => {
                    for k in (0..n.saturating_sub(2)).step_by(3) {
                        self.tri(&ctx, [v(k), v(k + 1), v(k + 2)], RESET | EALL);
                    }
                }
                gl::TRIANGLE_STRIP => {
                    for k in 0..n.saturating_sub(2) {
                        let odd = k & 1;
                        self.tri(&ctx, [v(k + odd), v(k + 1 - odd), v(k + 2)], RESET | EALL);
                    }
                }
                gl::TRIANGLE_FAN => {
                    for k in 0..n.saturating_sub(2) {
                        self.tri(&ctx, [v(0), v(k + 1), v(k + 2)], RESET | EALL);
                    }
                }
                gl::QUADS => {
                    for k in (0..n.saturating_sub(3)).step_by(4) {
                        self.quad(&ctx, [v(k), v(k + 1), v(k + 2), v(k + 3)]);
                    }
                }
                gl::QUAD_STRIP => {
                    for k in (0..n.saturating_sub(3)).step_by(2) {
                        self.quad(&ctx, [v(k + 2), v(k), v(k + 1), v(k + 3)]);
                    }
                }
                gl::POLYGON => {
                    let mut flags = RESET | E2 | E0;
                    for k in 0..n.saturating_sub(2) {
                        if k + 3 == n {
                            flags |= E1;
                        }
                        self.tri(&ctx, [v(k + 1), v(k + 2), v(0)], flags);
                        flags = E0;
                    }
                }
                _ => {}
            }
        }
    }

    /// A quad (i0, i1, i2, i3) as draw's QUAD_LAST_PV: (i0, i1, i3) and (i1, i2, i3).
    fn quad(&mut self, ctx: &Ctx, q: [FVert; 4]) {
        let [a, b, c, d] = q;
        self.tri(ctx, [a, b, d], RESET | E0 | E2);
        self.tri(ctx, [b, c, d], E0 | E1);
    }

    /// The vertex's outside-plane bits in draw's order: 0 right, 1 left, 2 top, 3 bottom,
    /// 4 near, 5 far, 6.. the enabled user planes.
    fn clipmask(ctx: &Ctx, v: &FVert) -> u16 {
        let mut m = 0;
        let users = ctx.users.get(..ctx.nuser).unwrap_or(&[]);
        for k in (0..6).chain(users.iter().map(|&k| k as usize)) {
            if let Some(d) = Self::dist(ctx, v, k) {
                if d < 0.0 {
                    m |= 1 << k;
                }
            }
        }
        m
    }

    /// The distance of `v` to plane `k` (draw's dot product, plane · position), or `None` for a
    /// user plane that is off.
    fn dist(ctx: &Ctx, v: &FVert, k: usize) -> Option<f32> {
        let c = v.clip;
        let plane: Vec4 = match k {
            0 => Vec4::new(-1.0, 0.0, 0.0, 1.0),
            1 => Vec4::new(1.0, 0.0, 0.0, 1.0),
            2 => Vec4::new(0.0, -1.0, 0.0, 1.0),
            3 => Vec4::new(0.0, 1.0, 0.0, 1.0),
            4 => Vec4::new(0.0, 0.0, 1.0, 1.0),
            5 => Vec4::new(0.0, 0.0, -1.0, 1.0),
            _ => {
                let (on, p) = ctx.user.get(k - 6).copied()?;
                if !on {
                    return None;
                }
                let e = v.eye;
                return Some(p.x * e.x + p.y * e.y + p.z * e.z + p.w * e.w);
            }
        };
        Some(plane.x * c.x + plane.y * c.y + plane.z * c.z + plane.w * c.w)
    }

    /// Window coordinates of `v`: x · (1/w) · scale + translate, and 1/w.
    fn win(ctx: &Ctx, v: &FVert) -> [f32; 4] {
        let oow = 1.0 / v.clip.w;
        let c = v.clip.to_array();
        let w = |i: usize| c[i] * oow * ctx.scale[i] + ctx.trans[i];
        [w(0), w(1), w(2), oow]
    }

    /// `out` moved toward `inside` by `t` (draw's interp: LINTERP of every attribute, in
    /// single precision; `out` is the end it starts from, inside or not).
    fn interp(t: f32, out: &FVert, inside: &FVert) -> FVert {
        let l = |o: Vec4, i: Vec4| {
            let (o, i) = (o.to_array(), i.to_array());
            Vec4::from_array(std::array::from_fn(|k| o[k] + t * (i[k] - o[k])))
        };
        FVert {
            clip: l(out.clip, inside.clip),
            col: l(out.col, inside.col),
            col_b: l(out.col_b, inside.col_b),
            tex: l(out.tex, inside.tex),
            eye: l(out.eye, inside.eye),
            edge: out.edge,
            mask: 0,
            win: [0.0; 4],
        }
    }

    fn point(&mut self, ctx: &Ctx, v: FVert) {
        if v.mask != 0 {
            return;
        }
        self.emit_point(ctx, &v);
    }

    fn emit_point(&mut self, ctx: &Ctx, v: &FVert) {
        let w = v.win;
        if ctx.select {
            self.update_hit(w[2]);
        } else {
            self.token(gl::POINT_TOKEN as f32);
            self.vertex_out(w, v);
        }
    }

    /// A feedback vertex: window coordinates, w as 1 / (1/w) (draw keeps 1/w), colour, texture
    /// coordinates.
    fn vertex_out(&mut self, w: [f32; 4], v: &FVert) {
        self.vertex([w[0], w[1], w[2], 1.0 / w[3]], v.col, v.tex);
    }

    /// A line of a Begin line mode: clipped (draw's do_clip_line), then emitted.
    fn line(&mut self, ctx: &Ctx, v0: FVert, v1: FVert) {
        let (m0, m1) = (v0.mask, v1.mask);
        if m0 & m1 != 0 {
            return;
        }
        if m0 | m1 == 0 {
            return self.emit_line(ctx, &v0, &v1);
        }
        let (mut t0, mut t1) = (0.0f32, 0.0f32);
        let mut mask = m0 | m1;
        while mask != 0 {
            let k = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let (Some(d0), Some(d1)) = (Self::dist(ctx, &v0, k), Self::dist(ctx, &v1, k)) else {
                continue;
            };
            if !d0.is_finite() || !d1.is_finite() {
                return;
            }
            if d1 < 0.0 {
                t1 = t1.max(d1 / (d1 - d0));
            }
            if d0 < 0.0 {
                t0 = t0.max(d0 / (d0 - d1));
            }
            if t0 + t1 >= 1.0 {
                return;
            }
        }
        // A clip-made end takes the provoking (last) vertex's colours under FLAT.
        let mut a = v0;
        if m0 != 0 {
            a = Self::interp(t0, &v0, &v1).windowed(ctx);
            if ctx.flat {
                (a.col, a.col_b) = (v1.col, v1.col_b);
            }
        }
        let mut b = v1;
        if m1 != 0 {
            b = Self::interp(t1, &v1, &v0).windowed(ctx);
            if ctx.flat {
                (b.col, b.col_b) = (v1.col, v1.col_b);
            }
        }
        self.emit_line(ctx, &a, &b);
    }

    fn emit_line(&mut self, ctx: &Ctx, v0: &FVert, v1: &FVert) {
        let (w0, w1) = (v0.win, v1.win);
        if ctx.select {
            self.update_hit(w0[2]);
            self.update_hit(w1[2]);
            return;
        }
        let token = if std::mem::take(&mut self.line_reset) {
            gl::LINE_RESET_TOKEN
        } else {
            gl::LINE_TOKEN
        };
        self.token(token as f32);
        self.vertex_out(w0, v0);
        self.vertex_out(w1, v1);
    }

    /// A triangle with draw's flags: clipped (draw's do_clip_tri and emit_poly) when a vertex
    /// is outside a plane, then the later stages.
    fn tri(&mut self, ctx: &Ctx, v: [FVert; 3], flags: u8) {
        let m = v.map(|x| x.mask);
        if m[0] & m[1] & m[2] != 0 {
            return;
        }
        if m[0] | m[1] | m[2] == 0 {
            return self.after_clip(ctx, v, flags);
        }
        let mut list: Vec<FVert> = v.to_vec();
        let mut edges: Vec<bool> = vec![flags & E0 != 0, flags & E1 != 0, flags & E2 != 0];
        let mut mask = m[0] | m[1] | m[2];
        while mask != 0 && list.len() >= 3 {
            let k = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let n = list.len();
            let (mut out, mut out_edges) = (Vec::with_capacity(n + 1), Vec::with_capacity(n + 1));
            let Some(mut prev) = list.first().copied() else {
                return;
            };
            let mut edge_prev = edges.first().copied().unwrap_or(false);
            let Some(mut dp_prev) = Self::dist(ctx, &prev, k) else {
                continue;
            };
            if !dp_prev.is_finite() {
                return;
            }
            for i in 1..=n {
                let cur = list.get(i % n).copied().unwrap_or(prev);
                let edge = edges.get(i % n).copied().unwrap_or(false);
                let Some(dp) = Self::dist(ctx, &cur, k) else {
                    return;
                };
                if !dp.is_finite() {
                    return;
                }
                if dp_prev >= 0.0 {
                    out.push(prev);
                    out_edges.push(edge_prev);
                }
                if (dp < 0.0) != (dp_prev < 0.0) {
                    // The new vertex is interpolated from whichever end is nearer the plane
                    // (draw's do_clip_tri), which decides its last bits.
                    let denom = dp - dp_prev;
                    if dp < 0.0 {
                        // Going out.
                        let mut nv = if -dp < dp_prev {
                            Self::interp(dp / denom, &cur, &prev)
                        } else {
                            Self::interp(-dp_prev / denom, &prev, &cur)
                        };
                        let user = k >= 6;
                        nv.edge = user;
                        out.push(nv.windowed(ctx));
                        out_edges.push(if user { true } else { edge_prev });
                    } else {
                        // Coming back in.
                        let mut nv = if -dp_prev < dp {
                            Self::interp(-dp_prev / denom, &prev, &cur)
                        } else {
                            Self::interp(dp / denom, &cur, &prev)
                        };
                        nv.edge = prev.edge;
                        out.push(nv.windowed(ctx));
                        out_edges.push(edge_prev);
                    }
                }
                prev = cur;
                edge_prev = edge;
                dp_prev = dp;
            }
            list = out;
            edges = out_edges;
        }
        let n = list.len();
        if n < 3 {
            return;
        }
        if ctx.flat {
            // The provoking vertex's colours on the polygon's first vertex.
            if let Some(first) = list.first_mut() {
                first.col = v[2].col;
                first.col_b = v[2].col_b;
            }
        }
        // emit_poly, provoking vertex last: (in[i-1], in[i], in[0]).
        let (edge_middle, edge_last) = (E0, E1);
        let edge_first = if edges.first().copied().unwrap_or(false) {
            E2
        } else {
            0
        };
        let mut f = RESET | edge_first | edge_middle;
        for i in 2..n {
            if !edges.get(i - 1).copied().unwrap_or(false) {
                f &= !edge_middle;
            }
            if i == n - 1 && edges.get(i).copied().unwrap_or(false) {
                f |= edge_last;
            }
            let (Some(&a), Some(&b), Some(&c)) = (list.get(i - 1), list.get(i), list.first())
            else {
                return;
            };
            self.after_clip(ctx, [a, b, c], f);
            f = edge_middle;
        }
    }

    /// The stages after clipping: cull, two-sided colour, flat shading of unfilled polygons,
    /// PolygonMode, emission.
    fn after_clip(&mut self, ctx: &Ctx, mut v: [FVert; 3], flags: u8) {
        let w = v.map(|x| x.win);
        // Facing from the window-coordinate area (positive: counter-clockwise in GL's window);
        // a zero-area triangle counts as back-facing, as draw's cull stage takes it.
        let mut front = true;
        if ctx.det {
            let (ex, ey) = (w[0][0] - w[2][0], w[0][1] - w[2][1]);
            let (fx, fy) = (w[1][0] - w[2][0], w[1][1] - w[2][1]);
            let det = ex * fy - ey * fx;
            front = det != 0.0 && ((det > 0.0) == ctx.ccw_front);
            let culled = match ctx.cull {
                Some(gl::FRONT) => front,
                Some(gl::BACK) => !front,
                Some(_) => true,
                None => false,
            };
            if culled {
                return;
            }
        }
        if ctx.two_side && !front {
            for x in &mut v {
                x.col = x.col_b;
            }
        }
        let mode = ctx.modes[usize::from(!front)];
        if mode != gl::FILL && ctx.flat {
            let c = v[2].col;
            for x in &mut v {
                x.col = c;
            }
        }
        match mode {
            gl::LINE => {
                if flags & RESET != 0 {
                    self.line_reset = true;
                }
                for (bit, a, b) in [(E2, 2, 0), (E0, 0, 1), (E1, 1, 2)] {
                    if flags & bit != 0 && v[a].edge {
                        self.emit_line(ctx, &v[a], &v[b]);
                    }
                }
            }
            gl::POINT => {
                for (bit, a) in [(E0, 0), (E1, 1), (E2, 2)] {
                    if flags & bit != 0 && v[a].edge {
                        self.emit_point(ctx, &v[a]);
                    }
                }
            }
            _ => {
                if ctx.select {
                    for x in &w {
                        self.update_hit(x[2]);
                    }
                } else {
                    self.token(gl::POLYGON_TOKEN as f32);
                    self.token(3.0);
                    for (x, vx) in w.iter().zip(&v) {
                        self.vertex_out(*x, vx);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_records_and_tokens_are_laid_out_as_gl_says() {
        let mut s = Sink::default();
        s.set_select_buffer(9);
        s.begin_select();
        s.names = vec![7, 8];
        s.update_hit(0.5);
        s.update_hit(0.25);
        // z = 1 scales to 2^32, whose low 32 bits Mesa keeps: 0.
        s.update_hit(1.0);
        s.flush_hit();
        assert_eq!(s.select, [2, 1 << 30, 0, 7, 8]);
        s.update_hit(0.75);
        s.flush_hit();
        // The second record does not fit: its first four values are written.
        assert_eq!(s.select.len(), 9);
        assert_eq!(s.end_select(), -1);
        s.set_feedback_buffer(64, gl::GL_3D_COLOR);
        s.begin_feedback();
        let c = Vec4::new(0.25, 0.5, 0.75, 1.0);
        s.raster_token(gl::DRAW_PIXEL_TOKEN, [1.0, 2.0, 0.5, 1.0], c, Vec4::ZERO);
        assert_eq!(
            s.feedback,
            [
                gl::DRAW_PIXEL_TOKEN as f32,
                1.0,
                2.0,
                0.5,
                0.25,
                0.5,
                0.75,
                1.0
            ]
        );
        assert_eq!(s.end_feedback(), 8);
    }

    /// Random triangles and strips, lit two-sided, under a perspective projection and a user
    /// clip plane (many of them clipped), once in SELECT mode (positions only, no lighting)
    /// and once in FEEDBACK mode (the whole vertex stage): each name's hit holds exactly the
    /// minimum and maximum window z of the polygons feedback reports for it. Also: the clip
    /// mask computed once a vertex ([`FVert::prepared`]) is the mask over every plane.
    #[test]
    fn selection_depths_are_the_feedback_depths() {
        use crate::Context;
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rnd = move |lo: f32, hi: f32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            lo + (hi - lo) * ((seed >> 40) as f32 / (1u64 << 24) as f32)
        };
        const NAMES: u32 = 60;
        let mut batches = Vec::new();
        for _ in 0..NAMES {
            let n = 3 * (1 + (rnd(0.0, 4.0) as usize));
            let vs: Vec<[f32; 9]> = (0..n)
                .map(|_| {
                    let mut v = [0.0f32; 9];
                    for (k, x) in v.iter_mut().enumerate() {
                        *x = match k {
                            0 | 1 => rnd(-3.0, 3.0),
                            2 => rnd(-9.0, 0.5),
                            _ => rnd(-1.0, 1.0),
                        };
                    }
                    v
                })
                .collect();
            batches.push((rnd(0.0, 1.0) < 0.5, vs));
        }
        let draw = |gl: &mut Context| {
            gl.init_names();
            gl.push_name(0);
            for (name, (strip, vs)) in batches.iter().enumerate() {
                gl.load_name(name as u32 + 1);
                // In FEEDBACK mode a pass-through token marks where each name's polygons start
                // (SELECT mode ignores it, as FEEDBACK mode ignores the name stack).
                gl.pass_through(name as f32);
                gl.begin(if *strip {
                    gl::TRIANGLE_STRIP
                } else {
                    gl::TRIANGLES
                });
                for v in vs {
                    gl.normal3f(v[3], v[4], v[5]);
                    gl.color3f(v[6], v[7], v[8]);
                    gl.vertex3f(v[0], v[1], v[2]);
                }
                gl.end();
            }
        };
        let mut gl = Context::new(64, 48).expect("context");
        gl.matrix_mode(gl::PROJECTION);
        gl.frustum(-1.0, 1.0, -0.75, 0.75, 1.0, 8.0);
        gl.matrix_mode(gl::MODELVIEW);
        gl.translatef(0.1, -0.2, -1.5);
        gl.clip_plane(gl::CLIP_PLANE0 + 2, &[0.3, -1.0, 0.2, 0.4]);
        gl.enable(gl::CLIP_PLANE0 + 2);
        gl.enable(gl::LIGHTING);
        gl.enable(gl::LIGHT0);
        gl.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1);
        gl.select_buffer(4 * NAMES as i32);
        gl.render_mode(gl::SELECT);
        draw(&mut gl);
        let hits = gl.render_mode(gl::RENDER);
        assert!(hits > 5, "too few hits ({hits}) to compare");
        let select = gl.selection_buffer().to_vec();
        gl.feedback_buffer(1 << 20, gl::GL_3D);
        gl.render_mode(gl::FEEDBACK);
        draw(&mut gl);
        let count = gl.render_mode(gl::RENDER);
        assert!(count > 0);
        let fb = gl.feedback_values().to_vec();
        // Each name's depth range from the feedback polygons.
        let mut ranges: Vec<Option<(f32, f32)>> = vec![None; NAMES as usize];
        let (mut at, mut cur) = (0usize, 0usize);
        while let Some(&t) = fb.get(at) {
            if t == gl::PASS_THROUGH_TOKEN as f32 {
                cur = fb[at + 1] as usize;
                at += 2;
            } else {
                assert_eq!(t, gl::POLYGON_TOKEN as f32);
                let n = fb[at + 1] as usize;
                for k in 0..n {
                    let z = fb[at + 2 + 3 * k + 2];
                    let r = &mut ranges[cur];
                    *r = Some(match *r {
                        Some((lo, hi)) => (lo.min(z), hi.max(z)),
                        None => (z, z),
                    });
                }
                at += 2 + 3 * n;
            }
        }
        let scale = |z: f32| ((z * 4_294_967_296.0f32) as u64) as u32;
        let mut want = Vec::new();
        for (name, r) in ranges.iter().enumerate() {
            if let Some((lo, hi)) = r {
                want.extend([1, scale(*lo), scale(*hi), name as u32 + 1]);
            }
        }
        assert_eq!(select, want);
        assert_eq!(hits as usize, want.len() / 4);

        // The clip mask of a prepared vertex against the mask over every plane.
        let mut user = [(false, Vec4::ZERO); MAX_CLIP_PLANES];
        for trial in 0..2000 {
            for u in user.iter_mut() {
                *u = (
                    rnd(0.0, 1.0) < 0.4,
                    Vec4::new(
                        rnd(-1.0, 1.0),
                        rnd(-1.0, 1.0),
                        rnd(-1.0, 1.0),
                        rnd(-1.0, 1.0),
                    ),
                );
            }
            let mut users = [0u8; MAX_CLIP_PLANES];
            let mut nuser = 0;
            for (k, u) in user.iter().enumerate() {
                if u.0 {
                    users[nuser] = (6 + k) as u8;
                    nuser += 1;
                }
            }
            let ctx = Ctx {
                scale: [32.0, 24.0, 0.5],
                trans: [32.0, 24.0, 0.5],
                user,
                cull: None,
                det: false,
                ccw_front: true,
                two_side: false,
                modes: [gl::FILL; 2],
                flat: false,
                select: true,
                users,
                nuser,
            };
            let r4 = |r: &mut dyn FnMut(f32, f32) -> f32| {
                Vec4::new(r(-2.0, 2.0), r(-2.0, 2.0), r(-2.0, 2.0), r(-2.0, 2.0))
            };
            let v = FVert {
                clip: r4(&mut rnd),
                eye: r4(&mut rnd),
                ..FVert::default()
            };
            let mut full = 0u16;
            for k in 0..6 + MAX_CLIP_PLANES {
                if Sink::dist(&ctx, &v, k).is_some_and(|d| d < 0.0) {
                    full |= 1 << k;
                }
            }
            let p = v.prepared(&ctx);
            assert_eq!(p.mask, full, "trial {trial}");
            assert_eq!(
                p.win.map(f32::to_bits),
                Sink::win(&ctx, &v).map(f32::to_bits)
            );
        }
    }
}
