//! Line setup (GL 2.1 §3.5): each segment becomes a parallelogram that the triangle rasteriser
//! fills, with varyings planes along the major axis.
//!
//! Design decision: GL's diamond-exit rule leaves the treatment of end points on diamond edges to
//! the implementation; fixedgl reproduces Mesa llvmpipe's reading of it (the reference it is
//! compared with): an x-major segment becomes the parallelogram of height round(width) centred on
//! it, whose ends are moved half a pixel when the diamond tests say the end pixel must (or must
//! not) be drawn, and whose edges follow the same tie rule as triangles. Varyings vary
//! along the major axis only (so a wide line is constant across), perspective-correct (eq. 3.10);
//! window z linearly.

use super::setup::{
    geom, PrimKind, RPrim, SetupCtx, WVert, Worker, F_FLAT, F_LINE, MAXV, SNAP_LIMIT,
};

/// Nearest 1/256 pixel, ties to even (llvmpipe's `lrintf` in the default rounding mode),
/// clamped to ±`SNAP_LIMIT` as triangle vertices are: the parallelogram's corners then stay
/// under `COORD_LIMIT`, where every edge-function product of `geom` and the rasteriser fits
/// i64 (a clamp of ±1e12 let a long diagonal overflow them). Clipped vertices lie within the
/// viewport, so the clamp only bites on coordinates no clipped line can have; NaN gives 0.
fn snap(v: f32) -> i64 {
    (f64::from(v) * 256.0)
        .round_ties_even()
        .clamp(-SNAP_LIMIT, SNAP_LIMIT) as i64
}

/// Offset of `v` from the centre of the pixel it lies in, in [-0.5, 0.5).
fn centre_offset(v: f32) -> f32 {
    v - v.floor() - 0.5
}

/// `v >= 0`, the sign test of the diamond rule.
fn nonneg(v: f32) -> bool {
    v >= 0.0
}

/// The parallelogram of the segment (x1, y1)–(x2, y2) of width `width`, as four corners in
/// 1/256 pixel with pixel centres at +128 (the triangle rasteriser's convention).
///
/// `flip` is the framebuffer height when the framebuffer is one llvmpipe draws upside down (a
/// window-system framebuffer, Mesa's `Y_0_TOP`: its state tracker negates the viewport's y
/// scale, so the driver sees y' = height − y): the diamond tests and end offsets are then
/// decided on y', as the driver decides them, and the corners mapped back. Without it the
/// driver's view is GL's (a framebuffer object, `Y_0_BOTTOM`). The two differ only for ends on
/// pixel-centre rows or columns (ties), which each orientation resolves its own way.
fn parallelogram(
    x1: f32,
    y1: f32,
    x2: f32,
    y2: f32,
    width: f32,
    flip: Option<f32>,
) -> Option<[[i64; 2]; 4]> {
    let (y1, y2) = match flip {
        Some(h) => (h - y1, h - y2),
        None => (y1, y2),
    };
    let (dx, dy) = (x1 - x2, y1 - y2);
    if dx * dx + dy * dy == 0.0 || !(dx.is_finite() && dy.is_finite()) {
        return None;
    }
    let (x1d, y1d) = (centre_offset(x1), centre_offset(y1));
    let (mut x2d, mut y2d) = (centre_offset(x2), centre_offset(y2));
    let half = (f64::from(width.max(1.0)).round_ties_even().min(1e6) as i64) * 256 / 2;
    let frac = |v: f32| v - v.floor();
    let (mut xo, mut yo, mut xoe, mut yoe) = (0.0f32, 0.0f32, 0.0f32, 0.0f32);
    let q = if dx.abs() >= dy.abs() {
        let dydx = dy / dx;
        if y2d == -0.5 && dy < 0.0 {
            y2d = 0.5;
        }
        // Diamond exit for the start: inside its diamond, the segment leaves it; otherwise it
        // depends on which way the segment heads from the diamond's corner regions.
        let start = if x1d.abs() + y1d.abs() < 0.5 {
            true
        } else if nonneg(x1d) == nonneg(-dx) {
            false
        } else if nonneg(-y1d) != nonneg(dy) {
            true
        } else {
            let yi = frac(y1) + x1d * dydx;
            yi > 0.0 && yi < 1.0
        };
        // The end: a diamond holding it is never left.
        let end = if x2d.abs() + y2d.abs() < 0.5 || nonneg(x2d) != nonneg(-dx) {
            false
        } else if nonneg(-y2d) == nonneg(dy) {
            true
        } else {
            let yi = frac(y2) + x2d * dydx;
            yi > 0.0 && yi < 1.0
        };
        // Move an end by up to half a pixel where the plain parallelogram would decide
        // differently from the diamond test. Mesa 22.3's `will_draw_start/end` (sign tests
        // that do not depend on the framebuffer's orientation; later Mesa made them depend on
        // `bottom_edge_rule`): with `sign(v) = v >= 0`, sign(-x1d) != sign(dx) and
        // sign(x2d) == sign(-dx) || x2d == 0.
        let will_start = nonneg(-x1d) != nonneg(dx);
        let will_end = nonneg(x2d) == nonneg(-dx) || x2d == 0.0;
        let ((ax, ay), (bx, by)) = if dx < 0.0 {
            if will_start != start {
                xoe = -x1d - 0.5;
                yoe = xoe * dydx;
            }
            if will_end != end {
                xo = -x2d - 0.5;
                yo = xo * dydx;
            }
            ((x2, y2), (x1, y1))
        } else {
            if will_start != start {
                xo = -x1d + 0.5;
                yo = xo * dydx;
            }
            if will_end != end {
                xoe = -x2d + 0.5;
                yoe = xoe * dydx;
            }
            ((x1, y1), (x2, y2))
        };
        let (xa, xb) = (snap(ax + xo - 0.5), snap(bx + xoe - 0.5));
        let (ya, yb) = (snap(ay + yo - 0.5), snap(by + yoe - 0.5));
        [
            [xa, ya - half],
            [xb, yb - half],
            [xb, yb + half],
            [xa, ya + half],
        ]
    } else {
        let dxdy = dx / dy;
        if x2d == -0.5 && dx < 0.0 {
            x2d = 0.5;
        }
        let start = if x1d.abs() + y1d.abs() < 0.5 {
            true
        } else if nonneg(-y1d) == nonneg(dy) {
            false
        } else if nonneg(x1d) != nonneg(-dx) {
            true
        } else {
            let xi = frac(x1) + y1d * dxdy;
            xi > 0.0 && xi < 1.0
        };
        let end = if x2d.abs() + y2d.abs() < 0.5 || nonneg(-y2d) != nonneg(dy) {
            false
        } else if nonneg(x2d) == nonneg(-dx) {
            true
        } else {
            let xi = frac(x2) + y2d * dxdy;
            (0.0..1.0).contains(&xi)
        };
        // Mesa 22.3's sign tests, as for x-major lines: sign(y1d) == sign(dy) and
        // sign(-y2d) == sign(dy) || y2d == 0.
        let will_start = nonneg(y1d) == nonneg(dy);
        let will_end = nonneg(-y2d) == nonneg(dy) || y2d == 0.0;
        let ((ax, ay), (bx, by)) = if dy > 0.0 {
            if will_start != start {
                yoe = -y1d + 0.5;
                xoe = yoe * dxdy;
            }
            if will_end != end {
                yo = -y2d + 0.5;
                xo = yo * dxdy;
            }
            ((x2, y2), (x1, y1))
        } else {
            if will_start != start {
                yo = -y1d - 0.5;
                xo = yo * dxdy;
            }
            if will_end != end {
                yoe = -y2d - 0.5;
                xoe = yoe * dxdy;
            }
            ((x1, y1), (x2, y2))
        };
        let (xa, xb) = (snap(ax + xo - 0.5), snap(bx + xoe - 0.5));
        let (ya, yb) = (snap(ay + yo - 0.5), snap(by + yoe - 0.5));
        [
            [xa - half, ya],
            [xb - half, yb],
            [xb + half, yb],
            [xa + half, ya],
        ]
    };
    // Back to centres at +0.5 pixel; from y' = height − y, row r' is row height − 1 − r'.
    Some(match flip {
        Some(h) => q.map(|[x, y]| [x + 128, snap(h) - 128 - y]),
        None => q.map(|[x, y]| [x + 128, y + 128]),
    })
}

impl Worker {
    /// A line segment from `a` to `b` under LINE_STIPPLE (GL 2.1 §3.4.2), cut as llvmpipe's
    /// draw module cuts it (its stipple stage, after clipping): the counter restarts when
    /// `reset` (see `assembly::RESET_STIPPLE`); the segment's length is its larger window
    /// extent, and it has ceil(length) stipple pixels; pixel i is on when bit
    /// ((counter + i) / factor) mod 16 of the pattern is set; each run of on-pixels is drawn as
    /// a line of its own from i0/length to i1/length of the way, every varying interpolated
    /// linearly in window space; then the counter grows by ceil(length) (measured on llvmpipe:
    /// a strip's second segment starts where whole stipple pixels left off, not at the
    /// fractional length). Without stipple, the segment.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn stippled_line(
        &mut self,
        ctx: &SetupCtx,
        a: &WVert,
        b: &WVert,
        off: f64,
        flags: u8,
        mat: u32,
        reset: bool,
    ) {
        let Some((pattern, factor)) = ctx.line_stipple else {
            return self.line(ctx, a, b, off, flags, mat);
        };
        if reset {
            self.stipple_counter = 0;
        }
        let length = (a.x - b.x).abs().max((a.y - b.y).abs());
        // Clipped segments lie inside the viewport (at most 16384 pixels a side): the loop is
        // bounded by that; an infinite or NaN length draws nothing, as in Mesa.
        let steps = if length.is_finite() {
            length.ceil().min(1e6) as i64
        } else {
            0
        };
        let counter = self.stipple_counter;
        let factor = i64::from(factor.max(1));
        let on = |i: i64| (pattern >> (((counter + i) / factor) & 0xf)) & 1 != 0;
        let (mut state, mut start) = (false, 0.0f32);
        for i in 0..steps {
            let bit = on(i);
            if bit != state {
                if state {
                    self.segment(
                        ctx,
                        a,
                        b,
                        start / length,
                        i as f32 / length,
                        off,
                        flags,
                        mat,
                    );
                } else {
                    start = i as f32;
                }
                state = bit;
            }
        }
        if state && start < length {
            self.segment(ctx, a, b, start / length, 1.0, off, flags, mat);
        }
        self.stipple_counter = self.stipple_counter.saturating_add(steps);
    }

    /// The part of segment `a`–`b` from `t0` to `t1` of the way (draw's `emit_segment`).
    #[allow(clippy::too_many_arguments)]
    fn segment(
        &mut self,
        ctx: &SetupCtx,
        a: &WVert,
        b: &WVert,
        t0: f32,
        t1: f32,
        off: f64,
        flags: u8,
        mat: u32,
    ) {
        let at = |t: f32| {
            let mut w = *a;
            w.x = a.x + t * (b.x - a.x);
            w.y = a.y + t * (b.y - a.y);
            w.z = f64::from(a.z as f32 + t * (b.z as f32 - a.z as f32));
            w.iw = a.iw + t * (b.iw - a.iw);
            for (o, (&va, &vb)) in w.v.iter_mut().zip(a.v.iter().zip(&b.v)) {
                *o = va + t * (vb - va);
            }
            w
        };
        let p = if t0 > 0.0 { at(t0) } else { *a };
        let q = if t1 < 1.0 { at(t1) } else { *b };
        self.line(ctx, &p, &q, off, flags, mat);
    }

    /// A line segment from `a` to `b` (window vertices with their varyings), its depth moved by
    /// `off` (polygon offset of a polygon drawn as lines).
    pub(super) fn line(
        &mut self,
        ctx: &SetupCtx,
        a: &WVert,
        b: &WVert,
        off: f64,
        flags: u8,
        mat: u32,
    ) {
        if ctx.line_smooth {
            return self.aa_line(ctx, a, b, off, flags, mat);
        }
        let Some(q) = parallelogram(a.x, a.y, b.x, b.y, ctx.line_width(), ctx.line_flip) else {
            return;
        };
        let x_major = (a.x - b.x).abs() >= (a.y - b.y).abs();
        let (p1, p2) = if x_major { (a.x, b.x) } else { (a.y, b.y) };
        let d = p2 - p1;
        let flat = ctx.flat();
        let nflat = if flat {
            ctx.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        for tri in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            let Some(g) = geom(&ctx.rect, tri) else {
                continue;
            };
            // Planes over the pixel grid relative to the bbox corner, varying along the major
            // axis: value at a pixel = value at its centre's major coordinate.
            let o = if x_major { g.bbox[0] } else { g.bbox[1] } as f32 + 0.5;
            let lin = |v1: f32, v2: f32| -> [f32; 3] {
                let s = (v2 - v1) / d;
                let c = v1 + s * (o - p1);
                if x_major {
                    [c, s, 0.0]
                } else {
                    [c, 0.0, s]
                }
            };
            let voff = self.pool.len() as u32;
            self.pool.extend(lin(a.iw, b.iw));
            for k in 0..ctx.rl.n.min(MAXV) {
                if k < nflat {
                    self.pool.extend([a.v[k], 0.0, 0.0]);
                } else {
                    self.pool.extend(lin(a.v[k] * a.iw, b.v[k] * b.iw));
                }
            }
            let (za, zb) = ((a.z + off) as f32, (b.z + off) as f32);
            self.push(RPrim {
                kind: PrimKind::Tri,
                flags: flags | F_LINE | if flat { F_FLAT } else { 0 },
                bbox: g.bbox,
                mat,
                voff,
                xy: [
                    g.v[0][0] as i32,
                    g.v[0][1] as i32,
                    g.v[1][0] as i32,
                    g.v[1][1] as i32,
                    g.v[2][0] as i32,
                    g.v[2][1] as i32,
                ],
                owns: g.owns,
                cover: 0,
                z: lin(za, zb),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::setup::{geom, COORD_LIMIT};
    use super::parallelogram;

    /// A long diagonal from -1e38 to 1e38 (finite window coordinates; only clipping keeps them
    /// out): each parallelogram triangle's area and edge functions are exactly what 128-bit
    /// arithmetic gives, never a wrapped i64 (a panic under overflow checks before the fix).
    #[test]
    fn huge_diagonal_edge_functions_are_exact() {
        for (x1, y1, x2, y2) in [
            (-1e38, -1e38, 1e38, 1e38),
            (1e38, -1e38, -1e38, 1e38),
            (-1e9, 5.0, 1e9, 7.0),
            (5.0, -1e9, 7.0, 1e9),
        ] {
            let Some(q) = parallelogram(x1, y1, x2, y2, 1e9, None) else {
                panic!("no parallelogram for ({x1}, {y1}) to ({x2}, {y2})");
            };
            assert!(q.iter().flatten().all(|v| v.abs() < COORD_LIMIT), "{q:?}");
            for tri in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
                let Some(g) = geom(&[0, 0, 63, 63], tri) else {
                    continue;
                };
                let w = |v: i64| i128::from(v);
                let [a, b, c] = g.v;
                let area = (w(b[0]) - w(a[0])) * (w(c[1]) - w(a[1]))
                    - (w(c[0]) - w(a[0])) * (w(b[1]) - w(a[1]));
                assert_eq!(i128::from(g.area), area.abs());
                let (px, py) = (
                    w(i64::from(g.bbox[0])) * 256 + 128,
                    w(i64::from(g.bbox[1])) * 256 + 128,
                );
                for k in 0..3 {
                    let (p, n) = (g.v[k], g.v[(k + 1) % 3]);
                    let (dx, dy) = (w(n[0]) - w(p[0]), w(n[1]) - w(p[1]));
                    assert_eq!(
                        i128::from(g.e[k]),
                        dx * (py - w(p[1])) - dy * (px - w(p[0]))
                    );
                }
            }
        }
    }
}
