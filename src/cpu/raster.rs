//! Rasterisation of one screen tile (GL 2.1 §3.4 points, §3.5 lines, §3.6 polygons): which
//! pixels each primitive covers, and the values interpolated there.
//!
//! Design decision: triangles are walked row by row; on each row the covered pixels form one run
//! whose ends come straight from the three integer edge functions (a division per edge, no
//! per-pixel edge test), and the run goes to the fragment stage as a span. Lines use the spec's
//! diamond-exit rule along the major axis (one fragment per column of an x-major line, the start
//! pixel drawn and the end pixel not when they hold the end points), `round(width)` fragments
//! across; points are `round(size)` squares.

use super::fragment::{FragCtx, TileBufs};
use super::framebuffer::TILE;
use super::setup::{Kind, RPrim, MAXV};

/// Rasterises `p` into the tile `bufs` (whose rectangle is `TILE` x `TILE` at bufs.x, bufs.y).
pub fn prim(ctx: &FragCtx, bufs: &mut TileBufs, p: &RPrim, pool: &[f32]) {
    let t = TILE as i32;
    let x0 = p.bbox[0].max(bufs.x);
    let y0 = p.bbox[1].max(bufs.y);
    let x1 = p.bbox[2].min(bufs.x + t - 1);
    let y1 = p.bbox[3].min(bufs.y + t - 1);
    if x0 > x1 || y0 > y1 {
        return;
    }
    let data = pool.get(p.voff as usize..).unwrap_or(&[]);
    match p.kind {
        Kind::Tri => tri(ctx, bufs, p, data, [x0, y0, x1, y1]),
        Kind::Line => line(ctx, bufs, p, data, [x0, y0, x1, y1]),
        Kind::Point => {
            let v = data.get(3..3 + ctx.rl.n).unwrap_or(&[]);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    ctx.fragment(bufs, p, x, y, f64::from(p.z[0]), v);
                }
            }
        }
    }
}

fn tri(ctx: &FragCtx, bufs: &mut TileBufs, p: &RPrim, planes: &[f32], r: [i32; 4]) {
    let [x0, y0, x1, y1] = r;
    let edges = p.edges();
    if x1 - x0 < SMALL {
        // Narrow: test each pixel centre (additions only) instead of dividing per edge.
        for y in y0..=y1 {
            let at = |e: &[i64; 3]| e[0] + e[2] * i64::from(y) + e[1] * i64::from(x0);
            let mut e = [at(&edges[0]), at(&edges[1]), at(&edges[2])];
            let (mut l, mut h) = (i32::MAX, i32::MIN);
            for x in x0..=x1 {
                if (e[0] | e[1] | e[2]) >= 0 {
                    l = l.min(x);
                    h = x;
                }
                for (ek, edge) in e.iter_mut().zip(&edges) {
                    *ek += edge[1];
                }
            }
            if l <= h {
                ctx.tri_span(bufs, p, planes, y, l, h);
            }
        }
        return;
    }
    for y in y0..=y1 {
        let (mut l, mut h) = (i64::from(x0), i64::from(x1));
        for e in &edges {
            // E(x) = erow + e[1]·x must be >= 0 (the tie-break bias is already in e[0]).
            let erow = e[0] + e[2] * i64::from(y);
            let dx = e[1];
            if dx > 0 {
                l = l.max(-erow.div_euclid(dx));
            } else if dx < 0 {
                h = h.min(erow.div_euclid(-dx));
            } else if erow < 0 {
                h = l - 1;
            }
        }
        if l <= h {
            ctx.tri_span(bufs, p, planes, y, l as i32, h as i32);
        }
    }
}

/// Bounding boxes narrower than this are scanned pixel by pixel.
const SMALL: i32 = 12;

fn line(ctx: &FragCtx, bufs: &mut TileBufs, p: &RPrim, data: &[f32], r: [i32; 4]) {
    let n = ctx.rl.n;
    let g = |k: usize| data.get(k).copied().unwrap_or(0.0);
    let [ax, ay, bx, by, width] = [0, 1, 2, 3, 4].map(g);
    let (iwa, iwb) = (g(5), g(6));
    let va = data.get(7..7 + n).unwrap_or(&[]);
    let vb = data.get(7 + n..7 + 2 * n).unwrap_or(&[]);
    let wi = width.round().max(1.0);
    let x_major = (bx - ax).abs() >= (by - ay).abs();
    // Along the major axis u from a to b; the minor coordinate m.
    let (ua, ub, ma, mb) = if x_major {
        (ax, bx, ay, by)
    } else {
        (ay, by, ax, bx)
    };
    if ua == ub {
        return;
    }
    let (u_lo, u_hi, m_lo, m_hi) = if x_major {
        (r[0], r[2], r[1], r[3])
    } else {
        (r[1], r[3], r[0], r[2])
    };
    let mut v = [0.0f32; MAXV];
    let dir = if ub > ua { 1.0 } else { -1.0 };
    // §3.5.1 diamond-exit: pixel f gets a fragment when the segment, from a to b, leaves f's
    // diamond |x − xc| + |y − yc| < 1/2; a diamond holding b is never left.
    let in_diamond = |u: i32, row: i32, pu: f32, pm: f32| {
        (pu - (u as f32 + 0.5)).abs() + (pm - (row as f32 + 0.5)).abs() < 0.5
    };
    for u in u_lo..=u_hi {
        let c = u as f32 + 0.5;
        let (da, db) = ((c - ua) * dir, (ub - c) * dir);
        if db <= 0.0 {
            // At or past the end: the segment stops before crossing this column's centre.
            continue;
        }
        let (t, row) = if da >= 0.0 {
            // The segment crosses the column centre: the pixel there is the one it passes.
            let t = (c - ua) / (ub - ua);
            (t, (ma + t * (mb - ma)).floor() as i32)
        } else {
            // The start lies past this column's centre: only a diamond holding it is left.
            let row = ma.floor() as i32;
            if !in_diamond(u, row, ua, ma) {
                continue;
            }
            (0.0, row)
        };
        if in_diamond(u, row, ub, mb) {
            continue;
        }
        let m = ma + t * (mb - ma);
        let m0 = if wi > 1.0 {
            (m - wi / 2.0 + 0.5).floor() as i32
        } else {
            row
        };
        let m1 = (i64::from(m0) + wi as i64 - 1).min(i64::from(m_hi)) as i32;
        for mm in m0.max(m_lo)..=m1 {
            // Eq. 3.10 with t along the major axis (constant across a wide line, as llvmpipe):: perspective-correct parameter for the varyings; z is linear.
            let tp = t * iwb / ((1.0 - t) * iwa + t * iwb);
            for (k, vk) in v.iter_mut().enumerate().take(n) {
                let (a, b) = (
                    va.get(k).copied().unwrap_or(0.0),
                    vb.get(k).copied().unwrap_or(0.0),
                );
                *vk = a + tp * (b - a);
            }
            let z = f64::from(p.z[0] + t * (p.z[1] - p.z[0]));
            let (x, y) = if x_major { (u, mm) } else { (mm, u) };
            ctx.fragment(bufs, p, x, y, z, &v[..n]);
        }
    }
}
