//! The general setup path (GL 2.1 §2.12, §3.4, §3.5.1, §3.5.4–3.5.5): every primitive that is not
//! an unclipped FILL triangle — clipped polygons, PolygonMode LINE and POINT, PHONG_WIN triangles,
//! points, and the line and point primitives themselves.
//!
//! Design decision: a vertex here is a whole `WVert` (window coordinates plus every varying the
//! flush interpolates), built once per polygon vertex after clipping, so clipping, facing and the
//! polygon modes share one representation; the common triangle skips all of it
//! (`Worker::fast_tri` in `setup`), and both produce the same planes.

use super::assembly::{Asm, RESET_STIPPLE};
use super::clip::MAX_POLY;
use super::setup::{
    geom, load4, offset, PrimKind, RPrim, SetupCtx, WVert, Win, Worker, COVER_KNOWN, F_BACK,
    F_FLAT, F_PHONG, MAXV,
};
use crate::gl;
use std::mem::MaybeUninit;

impl Worker {
    /// Sets up `p` when it is not an unclipped triangle for `fast_tri`: clipping, lines, points,
    /// polygon modes, PHONG_WIN.
    #[inline(never)]
    pub(super) fn general(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        mats: &[u32],
        p: &Asm,
    ) {
        let s = ctx.layout.stride;
        let vert = |i: u32| {
            debug_assert!(
                (i as usize + 1) * s <= vout.len(),
                "vertex {i} not processed"
            );
            vout.get(i as usize * s..(i as usize + 1) * s)
                .unwrap_or(&[])
        };
        let mat = mats.get(p.provoking as usize).copied().unwrap_or(0);
        let prov = vert(p.provoking);
        match p.n {
            3 => {
                let w = |i: u32| wins.get(i as usize).copied().unwrap_or_default();
                let ws = [w(p.v[0]), w(p.v[1]), w(p.v[2])];
                let codes = [ws[0].code, ws[1].code, ws[2].code];
                if codes[0] & codes[1] & codes[2] != 0 {
                    return;
                }
                let vs = [vert(p.v[0]), vert(p.v[1]), vert(p.v[2])];
                let mut edges = [false; MAX_POLY];
                for (k, e) in edges.iter_mut().take(3).enumerate() {
                    *e = p.edges & (1 << k) != 0;
                }
                let planes = codes[0] | codes[1] | codes[2];
                let reset = p.edges & RESET_STIPPLE != 0;
                if planes == 0 {
                    self.polygon::<3>(ctx, &vs, &ws, &edges, prov, mat, reset);
                } else {
                    let mut a = std::mem::take(&mut self.a);
                    let mut b = std::mem::take(&mut self.b);
                    a.clear();
                    for v in vs {
                        a.extend_from_slice(v);
                    }
                    let n = ctx
                        .clipper
                        .polygon(s, planes, &mut a, &mut b, &mut edges, 3);
                    let mut srcs: [&[f32]; MAX_POLY] = [&[]; MAX_POLY];
                    let mut cw = [Win::default(); MAX_POLY];
                    for (i, (src, w)) in srcs.iter_mut().zip(&mut cw).take(n).enumerate() {
                        *src = a.get(i * s..(i + 1) * s).unwrap_or(&[]);
                        *w = ctx.win(src);
                    }
                    self.polygon::<MAX_POLY>(ctx, &srcs[..n], &cw[..n], &edges, prov, mat, reset);
                    self.a = a;
                    self.b = b;
                }
            }
            2 => {
                let vs = [vert(p.v[0]), vert(p.v[1])];
                let codes = vs.map(|v| ctx.clipper.code(v));
                if codes[0] & codes[1] != 0 {
                    return;
                }
                let planes = codes[0] | codes[1];
                let mut a = std::mem::take(&mut self.a);
                a.clear();
                a.extend_from_slice(vs[0]);
                a.extend_from_slice(vs[1]);
                if planes == 0 || ctx.clipper.line(s, planes, &mut a) {
                    let mut w0 = self.window(ctx, a.get(..s).unwrap_or(&[]));
                    let mut w1 = self.window(ctx, a.get(s..2 * s).unwrap_or(&[]));
                    self.varyings(ctx, &mut w0, a.get(..s).unwrap_or(&[]), false, prov);
                    self.varyings(ctx, &mut w1, a.get(s..2 * s).unwrap_or(&[]), false, prov);
                    let reset = p.edges & RESET_STIPPLE != 0;
                    self.stippled_line(ctx, &w0, &w1, 0.0, 0, mat, reset);
                }
                self.a = a;
            }
            _ => {
                let v = vert(p.v[0]);
                if wins.get(p.v[0] as usize).is_some_and(|w| w.code == 0) {
                    let mut w = self.window(ctx, v);
                    self.varyings(ctx, &mut w, v, false, prov);
                    self.point(ctx, &w, 0.0, 0, mat);
                }
            }
        }
    }

    /// Window coordinates of processed vertex `v`; varyings are filled in later.
    fn window(&self, ctx: &SetupCtx, v: &[f32]) -> WVert {
        from_win(&ctx.win(v))
    }

    /// Fills `w.v` from processed vertex `v`: the face's colours (the provoking vertex's under
    /// FLAT), then texture coordinates and the PHONG_WIN values.
    #[inline(always)]
    fn varyings(&self, ctx: &SetupCtx, w: &mut WVert, v: &[f32], back: bool, prov: &[f32]) {
        let l = &ctx.layout;
        let rl = &ctx.rl;
        let csrc = if ctx.flat { prov } else { v };
        let (col, spec) = match (back, l.col_b) {
            (true, Some(cb)) => (cb, l.spec_b),
            _ => (l.col, l.spec),
        };
        copy(&mut w.v, 0, csrc, col, 4);
        if let (Some(d), Some(s)) = (rl.spec, spec) {
            copy(&mut w.v, d, csrc, s, 4);
        }
        for (&d, &s) in rl.tex.iter().zip(&l.tex) {
            if let (Some(d), Some(s)) = (d, s) {
                copy(&mut w.v, d, v, s, 4);
            }
        }
        if let (Some(d), Some(e), Some(n), Some(r)) = (rl.phong, l.eye, l.nrm, l.raw) {
            let ew = v.get(e + 3).copied().unwrap_or(1.0);
            let ew = if ew != 0.0 { ew } else { 1.0 };
            for k in 0..3 {
                if let (Some(o), Some(&x)) = (w.v.get_mut(d + k), v.get(e + k)) {
                    *o = x / ew;
                }
            }
            copy(&mut w.v, d + 3, v, n, 3);
            copy(&mut w.v, d + 6, csrc, r, 4);
        }
        // The fog coordinate is never flat (§3.10 interpolates it).
        if let (Some(d), Some(s)) = (rl.fog, l.fog) {
            copy(&mut w.v, d, v, s, 1);
        }
        if let Some(s) = l.psize {
            w.ps = v.get(s).copied().unwrap_or(0.0);
        }
    }

    /// Facing, culling and polygon mode for a clipped polygon (§3.5.1, §3.5.4): `srcs` are its
    /// processed vertices in order, `edges[i]` the flag of the edge leaving vertex i.
    /// `N` bounds the vertex count (3 on the unclipped path, so no large array is initialised).
    /// `reset`: the line stipple counter restarts at its first edge drawn as a line.
    #[allow(clippy::too_many_arguments)]
    fn polygon<const N: usize>(
        &mut self,
        ctx: &SetupCtx,
        srcs: &[&[f32]],
        wins: &[Win],
        edges: &[bool],
        prov: &[f32],
        mat: u32,
        reset: bool,
    ) {
        let n = srcs.len().min(wins.len()).min(N);
        if n < 3 {
            return;
        }
        // Only the `n` vertices used are written: zeroing all `N` (`MAX_POLY` of about 200
        // bytes each on the clipped path) cost a 3.2 KB memset a polygon.
        let mut buf = [const { MaybeUninit::<WVert>::uninit() }; N];
        for (slot, win) in buf.iter_mut().zip(wins).take(n) {
            slot.write(from_win(win));
        }
        // SAFETY: the loop above initialised `buf[..n]` (n ≤ wins.len() and n ≤ N), and
        // `MaybeUninit<WVert>` has `WVert`'s layout; `WVert` is `Copy`, so nothing is dropped.
        let w: &mut [WVert] =
            unsafe { std::slice::from_raw_parts_mut(buf.as_mut_ptr().cast::<WVert>(), n) };
        // §3.5.1 eq. 3.6: the signed area in window coordinates decides the facing.
        let mut area: i128 = 0;
        for i in 0..n {
            let (a, b) = (&w[i], &w[(i + 1) % n]);
            area += i128::from(a.fx) * i128::from(b.fy) - i128::from(b.fx) * i128::from(a.fy);
        }
        let front = area == 0 || ((area > 0) == ctx.ccw_front);
        match ctx.cull {
            Some(gl::FRONT) if front => return,
            Some(gl::BACK) if !front => return,
            Some(gl::FRONT_AND_BACK) => return,
            _ => {}
        }
        let back = !front;
        for (wv, src) in w.iter_mut().zip(srcs) {
            self.varyings(ctx, wv, src, back, prov);
        }
        let mut flags = if back { F_BACK } else { 0 };
        if ctx.flat {
            flags |= F_FLAT;
        }
        let mode = ctx.poly_mode[usize::from(back)];
        match mode {
            gl::POINT | gl::LINE => {
                let which = if mode == gl::POINT { 2 } else { 1 };
                let off = if ctx.offset_on[which] {
                    let [_, dx, dy] = z_slopes(&w[0], &w[1], &w[2]);
                    offset(ctx, dx, dy)
                } else {
                    0.0
                };
                if reset {
                    self.stipple_counter = 0;
                }
                for i in 0..n {
                    if !edges.get(i).copied().unwrap_or(false) {
                        continue;
                    }
                    if mode == gl::POINT {
                        self.point(ctx, &w[i], off, flags & F_BACK, mat);
                    } else {
                        let (a, b) = (w[i], w[(i + 1) % n]);
                        self.stippled_line(ctx, &a, &b, off, flags & F_BACK, mat, false);
                    }
                }
            }
            _ => {
                if area == 0 {
                    return;
                }
                if ctx.phong {
                    flags |= F_PHONG;
                }
                for i in 1..n - 1 {
                    self.tri(ctx, &w[0], &w[i], &w[i + 1], flags, mat);
                }
            }
        }
    }

    /// A filled triangle: edge functions, bounding box and attribute planes (§3.5.1).
    #[inline]
    pub(super) fn tri(
        &mut self,
        ctx: &SetupCtx,
        a: &WVert,
        b: &WVert,
        c: &WVert,
        flags: u8,
        mat: u32,
    ) {
        let Some(g) = geom(&ctx.rect, [[a.fx, a.fy], [b.fx, b.fy], [c.fx, c.fy]]) else {
            return;
        };
        let cover = g.coverage();
        if cover == COVER_KNOWN {
            // A sliver between pixel centres (common in dense meshes): nothing to draw.
            return;
        }
        let (b, c) = if g.swapped { (c, b) } else { (b, c) };
        let v = [a, b, c];
        self.emit_tri(
            ctx,
            &g,
            [a.z, b.z, c.z],
            [a.iw, b.iw, c.iw],
            flags,
            mat,
            |k| load4(&v[0].v, k),
            |j, k| load4(&v[j].v, k),
            cover,
        );
    }

    /// A point (§3.4): a square of side round(size) centred on the vertex.
    fn point(&mut self, ctx: &SetupCtx, a: &WVert, off: f64, flags: u8, mat: u32) {
        if ctx.point_smooth {
            return self.aa_point(ctx, a, off, flags, mat);
        }
        if ctx.sprite {
            return self.sprite(ctx, a, off, flags, mat);
        }
        let (x, y) = (a.fx as f32 / 256.0, a.fy as f32 / 256.0);
        // llvmpipe's legacy point width: the size in 1/256 pixel rounded to a whole pixel,
        // halves down (2.5 draws 2x2, measured), at least 1.
        let size = if a.ps > 0.0 { a.ps } else { ctx.point_size };
        let size =
            ((((f64::from(size) * 256.0).round() as i64).saturating_add(127) >> 8).max(1)) as f32;
        let x0 = clamp_f((x - size / 2.0 + 0.5).floor());
        let y0 = clamp_f((y - size / 2.0 + 0.5).floor());
        let s = size.min(1e6) as i32;
        let bbox = [
            x0.max(ctx.rect[0]),
            y0.max(ctx.rect[1]),
            x0.saturating_add(s - 1).min(ctx.rect[2]),
            y0.saturating_add(s - 1).min(ctx.rect[3]),
        ];
        if bbox[0] > bbox[2] || bbox[1] > bbox[3] {
            return;
        }
        let voff = self.pool.len() as u32;
        self.pool.extend([x, y, size]);
        self.pool.extend_from_slice(&a.v[..ctx.rl.n]);
        self.push(RPrim {
            kind: PrimKind::Point,
            flags,
            bbox,
            mat,
            voff,
            xy: [0; 6],
            owns: 0,
            cover: 0,
            z: [(a.z + off) as f32, 0.0, 0.0],
        });
    }
}

fn from_win(w: &Win) -> WVert {
    WVert {
        x: w.x,
        y: w.y,
        fx: w.fx,
        fy: w.fy,
        z: w.z,
        iw: w.iw,
        v: [0.0; MAXV],
        ps: 0.0,
    }
}

/// The z plane of three window vertices: `[_, dz/dx, dz/dy]` per pixel (for polygon offset).
fn z_slopes(a: &WVert, b: &WVert, c: &WVert) -> [f64; 3] {
    let (x1, y1) = ((b.fx - a.fx) as f64 / 256.0, (b.fy - a.fy) as f64 / 256.0);
    let (x2, y2) = ((c.fx - a.fx) as f64 / 256.0, (c.fy - a.fy) as f64 / 256.0);
    let (z1, z2) = (b.z - a.z, c.z - a.z);
    let det = x1 * y2 - x2 * y1;
    if det == 0.0 {
        return [0.0; 3];
    }
    [0.0, (z1 * y2 - z2 * y1) / det, (x1 * z2 - x2 * z1) / det]
}

fn clamp_f(v: f32) -> i32 {
    v.floor().clamp(-1e9, 1e9) as i32
}

#[inline(always)]
fn copy(dst: &mut [f32; MAXV], d: usize, src: &[f32], s: usize, n: usize) {
    if let (Some(o), Some(i)) = (dst.get_mut(d..d + n), src.get(s..s + n)) {
        o.copy_from_slice(i);
    }
}
