//! Smooth points and lines (GL 2.1 §3.3.2 POINT_SMOOTH, §3.4.2 LINE_SMOOTH) as Mesa llvmpipe
//! draws them, the reference fixedgl is compared with.
//!
//! Design decision: llvmpipe has no coverage rasteriser of its own; Mesa's draw module turns a
//! smooth point into a quad of two triangles (`draw_pipe_aapoint.c`) and a smooth line into a
//! longer, wider quad (`draw_pipe_aaline.c`), each vertex carrying four extra coordinates, and
//! a fragment-shader epilogue (`nir_lower_aapoint_fs`, `nir_lower_aaline_fs`) turns the
//! interpolated coordinates into a coverage that multiplies the fragment's alpha. fixedgl
//! builds the same quads (same float arithmetic, same triangle order) and interpolates the
//! same coordinates with its triangle rasteriser (`RLayout::aa`, perspective-correct like
//! every varying), then applies the same epilogue (`coverage`):
//!
//! - point: radius r = 1 for a size up to 2, else size / 2; the quad spans ±r with (s, t)
//!   going from -1 to 1; d = s² + t²; the fragment is discarded when d > 1; with
//!   k = (1 - 1/r)², the alpha is multiplied by (1 - d) / (1 - k) when d <= k and left alone
//!   otherwise. That select is the Mesa 22.3 epilogue's, the reverse of what its comment
//!   intends (the TGSI original faded the rim): inside the inner disc alpha grows (clamped
//!   later), the rim keeps it — measured on llvmpipe, where a point of alpha 0.5 and size 8
//!   reads 255 at its centre and 128 on its rim.
//! - line: half width w = 1 for a width up to 1, else width / 2 + 1/2; the quad is the segment
//!   lengthened by 1/2 at each end and ±w across; with x in [-w, w] across, z in [-h, h]
//!   along (h = length / 2 + 1/2), the coverage is sat(w - |x|) · min(sat(h - |z|), 2h - 1).
//!
//! POLYGON_SMOOTH changes nothing on llvmpipe (measured: a smooth triangle's pixels are those
//! of the plain one, alpha untouched), so it changes nothing here.

use super::lanes::LANES;
use super::setup::{snap, SetupCtx, WVert, Worker, F_AALINE, F_AAPOINT, F_LINE};

/// The coverage factors of eight smooth point or line fragments (`F_AAPOINT` or `F_AALINE` in
/// `flags`) from their interpolated `aa` coordinates `a` (lane l's at `a[j][l]`), and the mask
/// of the lanes kept (bit l clear: lane l is discarded, its factor unspecified). Every lane
/// computes the epilogue of the module docs with the same operations in the same order as a
/// scalar fragment would (plain loops over the lanes, no `Option`, so that the compiler can
/// keep them in SIMD registers): a point's fragment is discarded when 1 (its `a[3]`) < d (not for a NaN
/// d), its factor is (1 / (1 − k))·(1 − d) when k >= d, else that 1; a line's is
/// sat(w − |x|)·min(sat(h − |z|), 2h − 1), `f32::clamp` and `f32::min` (a NaN stays in the
/// first, is passed over by the second).
#[inline(always)]
pub fn coverage_lanes(flags: u8, a: [&[f32; LANES]; 4]) -> ([f32; LANES], u8) {
    let [a0, a1, a2, a3] = a;
    let mut cov = [0.0f32; LANES];
    if flags & F_AAPOINT != 0 {
        let mut keep = 0u8;
        for l in 0..LANES {
            let d = a0[l] * a0[l] + a1[l] * a1[l];
            let (k, one) = (a2[l], a3[l]);
            // Kept unless 1 < d: a NaN d (or 1) keeps the fragment.
            let discard = one < d;
            keep |= u8::from(!discard) << l;
            let c = (1.0 / (one - k)) * (one - d);
            cov[l] = if k >= d { c } else { one };
        }
        return (cov, keep);
    }
    let sat = |v: f32| v.clamp(0.0, 1.0);
    for l in 0..LANES {
        let len = a3[l] * 2.0 - 1.0;
        let across = sat(a1[l] - a0[l].abs());
        let along = sat(a3[l] - a2[l].abs());
        cov[l] = across * along.min(len);
    }
    (cov, 0xFF)
}

impl Worker {
    /// A copy of `v` moved to window (x, y) with antialiasing coordinates `aa`.
    fn aa_vert(ctx: &SetupCtx, v: &WVert, x: f32, y: f32, off: f64, aa: [f32; 4]) -> WVert {
        let mut w = *v;
        w.x = x;
        w.y = y;
        w.fx = i64::from(snap(f64::from(x)));
        w.fy = i64::from(snap(f64::from(y)));
        w.z = v.z + off;
        if let Some(o) = ctx.rl.aa {
            if let Some(dst) = w.v.get_mut(o..o + 4) {
                dst.copy_from_slice(&aa);
            }
        }
        w
    }

    /// A smooth point (`draw_pipe_aapoint.c`'s quad; see the module docs).
    pub(super) fn aa_point(&mut self, ctx: &SetupCtx, a: &WVert, off: f64, flags: u8, mat: u32) {
        let size = ctx.point_size;
        // A size per vertex (distance attenuation) is taken as it is.
        let r = if a.ps > 0.0 {
            0.5 * a.ps
        } else if size <= 2.0 {
            1.0f32
        } else {
            0.5 * size
        };
        let k = 1.0 / r;
        let k = 1.0 - 2.0 * k + k * k;
        let (x, y) = (a.x, a.y);
        let v0 = Self::aa_vert(ctx, a, x - r, y - r, off, [-1.0, -1.0, k, 1.0]);
        let v1 = Self::aa_vert(ctx, a, x + r, y - r, off, [1.0, -1.0, k, 1.0]);
        let v2 = Self::aa_vert(ctx, a, x + r, y + r, off, [1.0, 1.0, k, 1.0]);
        let v3 = Self::aa_vert(ctx, a, x - r, y + r, off, [-1.0, 1.0, k, 1.0]);
        let f = flags | F_AAPOINT;
        self.tri(ctx, &v0, &v1, &v2, f, mat);
        self.tri(ctx, &v0, &v2, &v3, f, mat);
    }

    /// A smooth line segment (`draw_pipe_aaline.c`'s quad; see the module docs).
    pub(super) fn aa_line(
        &mut self,
        ctx: &SetupCtx,
        a: &WVert,
        b: &WVert,
        off: f64,
        flags: u8,
        mat: u32,
    ) {
        let width = ctx.line_width();
        let hw = if width <= 1.0 {
            1.0f32
        } else {
            0.5 * width + 0.5
        };
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        let ang = dy.atan2(dx);
        let (c, s) = (ang.cos(), ang.sin());
        let hl = 0.5 * (dx * dx + dy * dy).sqrt() + 0.5;
        let (tw, tl) = (hw, 0.5f32);
        let v0 = Self::aa_vert(
            ctx,
            a,
            a.x + (-tl * c - tw * s),
            a.y + (-tl * s + tw * c),
            off,
            [-hw, hw, -hl, hl],
        );
        let v1 = Self::aa_vert(
            ctx,
            a,
            a.x + (-tl * c - -tw * s),
            a.y + (-tl * s + -tw * c),
            off,
            [hw, hw, -hl, hl],
        );
        let v2 = Self::aa_vert(
            ctx,
            b,
            b.x + (tl * c - tw * s),
            b.y + (tl * s + tw * c),
            off,
            [-hw, hw, hl, hl],
        );
        let v3 = Self::aa_vert(
            ctx,
            b,
            b.x + (tl * c - -tw * s),
            b.y + (tl * s + -tw * c),
            off,
            [hw, hw, hl, hl],
        );
        let f = flags | F_AALINE;
        self.tri(ctx, &v2, &v1, &v0, f, mat);
        self.tri(ctx, &v3, &v1, &v2, f, mat);
    }

    /// A point sprite (GL 2.0 §3.3.1, ARB_point_sprite) as llvmpipe rasterises it
    /// (`lp_setup_point.c`, quad rasterisation): a square of the size in 1/256 pixel (at least
    /// one pixel) centred on the snapped vertex, filled with the triangle rule, never
    /// polygon-stippled; the units with COORD_REPLACE get s = 1/2 + (x - x_w) / size and
    /// t = 1/2 ± (y - y_w) / size (+ for LOWER_LEFT, - for UPPER_LEFT), r = 0, q = 1, at each
    /// pixel centre (x, y); the other varyings are the vertex's.
    pub(super) fn sprite(&mut self, ctx: &SetupCtx, a: &WVert, off: f64, flags: u8, mat: u32) {
        let size = if a.ps > 0.0 { a.ps } else { ctx.point_size }.min(255.0);
        let fw = ((f64::from(size) * 256.0).round() as i64).max(256);
        let cx = i64::from(snap(f64::from(a.x - 0.5))) + 128;
        let cy = i64::from(snap(f64::from(a.y - 0.5))) + 128;
        let (x0, y0) = (cx - fw / 2, cy - fw / 2);
        let w = fw as f32 / 256.0;
        let corner = |fx: i64, fy: i64| {
            let mut v = *a;
            v.fx = fx;
            v.fy = fy;
            v.x = fx as f32 / 256.0;
            v.y = fy as f32 / 256.0;
            v.z = a.z + off;
            let s = 0.5 + (v.x - a.x) / w;
            let dt = (v.y - a.y) / w;
            let t = if ctx.sprite_lower_left {
                0.5 + dt
            } else {
                0.5 - dt
            };
            for o in ctx.sprite_units.into_iter().flatten() {
                if let Some(dst) = v.v.get_mut(o..o + 4) {
                    dst.copy_from_slice(&[s, t, 0.0, 1.0]);
                }
            }
            v
        };
        let v0 = corner(x0, y0);
        let v1 = corner(x0 + fw, y0);
        let v2 = corner(x0 + fw, y0 + fw);
        let v3 = corner(x0, y0 + fw);
        let f = flags | F_LINE;
        self.tri(ctx, &v0, &v1, &v2, f, mat);
        self.tri(ctx, &v0, &v2, &v3, f, mat);
    }
}
