//! Rasterisation of one screen tile (GL 2.1 §3.4 points, §3.5 lines, §3.6 polygons): which
//! pixels each primitive covers, and the values interpolated there.
//!
//! Design decision: triangles are walked row by row; on each row the covered pixels form one run
//! whose ends come straight from the three integer edge functions (a division per edge, no
//! per-pixel edge test), and the run goes to the fragment stage as a span. A triangle whose
//! bounding box is at most 2x2 pixels (most of a dense mesh) arrives with its covered centres
//! already found by setup (`RPrim::cover`, the same integer tests) and is not walked at all.
//! Lines arrive as parallelograms made of two triangles (see `line`); points are `round(size)`
//! squares.

#[cfg(target_arch = "x86_64")]
use super::fragment::TinyOut;
use super::fragment::{FragCtx, TileBufs};
use super::framebuffer::TILE;
use super::setup::{PrimKind, RPrim, COVER_KNOWN, F_AALINE, F_AAPOINT};

/// Rasterises the primitives `bin` (indices into `prims`, in submission order; their floats
/// in `pool`) into the tile `bufs`, each as `prim` does. From the first triangle whose
/// covered pixels setup found (`COVER_KNOWN`, at most 2x2 pixels) on, the rest of the bin goes
/// to `rest`, where such triangles skip `prim` when the state allows it; bins without one (the
/// larger triangles of most scenes) stay in this loop, which is the plain one but for that
/// test (a loop compiled for AVX2 around every primitive cost 15–20 instructions a primitive
/// and tile: +0.3% on sphere-subdivision, +0.2% on materials).
pub fn prims(ctx: &FragCtx, bufs: &mut TileBufs, prims: &[RPrim], bin: &[u32], pool: &[f32]) {
    for (i, &pi) in bin.iter().enumerate() {
        let Some(p) = prims.get(pi as usize) else {
            continue;
        };
        if p.cover & COVER_KNOWN != 0 {
            return rest(ctx, bufs, prims, bin.get(i..).unwrap_or_default(), pool);
        }
        prim(ctx, bufs, p, pool);
    }
}

/// The rest of a bin of `prims`, from its first `COVER_KNOWN` triangle. Where the flush's
/// state lets every smooth triangle take `FragCtx::smooth_rows` with the depth test LESS or
/// LEQUAL (decided here once for the rest of the bin, `FragCtx::tiny_depth`), a smooth or FLAT
/// `COVER_KNOWN` triangle inside the tile takes `FragCtx::tiny` (`tiny_avx2`): a dense mesh's
/// triangle of about one pixel went through `prim`, `tri`, the per-primitive checks, the
/// spans' batch and an eight-lane group for its one or two fragments (≈450 instructions on
/// gauss-smooth-400). Otherwise each through `prim`.
#[inline(never)]
fn rest(ctx: &FragCtx, bufs: &mut TileBufs, prims: &[RPrim], bin: &[u32], pool: &[f32]) {
    #[cfg(target_arch = "x86_64")]
    {
        use crate::gl::{LEQUAL, LESS};
        match ctx.tiny_depth(bufs) {
            // SAFETY: `tiny_depth` is not 0 only where the CPU has AVX2 and POPCNT.
            LESS => return unsafe { tiny_avx2::<LESS>(ctx, bufs, prims, bin, pool) },
            // SAFETY: as above.
            LEQUAL => return unsafe { tiny_avx2::<LEQUAL>(ctx, bufs, prims, bin, pool) },
            _ => {}
        }
    }
    for &pi in bin {
        if let Some(p) = prims.get(pi as usize) {
            prim(ctx, bufs, p, pool);
        }
    }
}

/// `rest` where `tiny_depth` gave the depth test `F`: each primitive `FragCtx::tiny` takes
/// (a `COVER_KNOWN` triangle inside the tile), the others through `prim`.
///
/// # Safety
/// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,popcnt")]
unsafe fn tiny_avx2<const F: u32>(
    ctx: &FragCtx,
    bufs: &mut TileBufs,
    prims: &[RPrim],
    bin: &[u32],
    pool: &[f32],
) {
    let (tx, ty) = (bufs.x, bufs.y);
    let mut rest = bin;
    while !rest.is_empty() {
        // A run of the primitives `FragCtx::tiny` takes, the tile's buffers borrowed once for
        // the run: a `prim` call (after the run) may change what `bufs` holds, so while it sat
        // in the same loop every triangle reloaded the buffers' addresses and lengths.
        let TileBufs {
            color,
            color2,
            depth,
            samples,
            ..
        } = &mut *bufs;
        let mut out = TinyOut {
            color,
            depth,
            tile: (tx, ty),
            samples,
            color2: color2.is_some(),
        };
        let mut taken = 0;
        for &pi in rest {
            let Some(p) = prims.get(pi as usize) else {
                taken += 1;
                continue;
            };
            // The box inside the tile: each of its offsets from the tile's corner in 0..TILE
            // (a negative one is a large u32).
            let [x0, y0, x1, y1] = p.bbox;
            let inside = (((x0 - tx) | (x1 - tx) | (y0 - ty) | (y1 - ty)) as u32) < TILE as u32;
            let tiny = p.cover & COVER_KNOWN != 0 && inside && p.kind == PrimKind::Tri;
            // The fifteen floats of a smooth or FLAT triangle without texturing
            // (`FragCtx::tiny` reads no more).
            let off = p.voff as usize;
            let Some(pl) = pool.get(off..off.wrapping_add(15)).filter(|_| tiny) else {
                break;
            };
            // SAFETY: the CPU has AVX2 and POPCNT (this function's contract).
            if !unsafe { ctx.tiny::<F>(&mut out, p, pl) } {
                break;
            }
            taken += 1;
        }
        // The primitive that ended the run, if any, through `prim`.
        rest = rest.get(taken..).unwrap_or_default();
        if let Some((&pi, tail)) = rest.split_first() {
            if let Some(p) = prims.get(pi as usize) {
                prim(ctx, bufs, p, pool);
            }
            rest = tail;
        }
    }
}

/// Rasterises `p` into the tile `bufs` (whose rectangle is `TILE` x `TILE` at bufs.x, bufs.y).
#[inline(never)]
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
        PrimKind::Tri => tri(ctx, bufs, p, data, [x0, y0, x1, y1]),
        PrimKind::Point => {
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
    if p.flags & (F_AAPOINT | F_AALINE) != 0 {
        // A smooth point's or line's quad: its rows (at most a tile's) are gathered and shaded
        // in one call, which decides what depends on the primitive once (`aa_rows`).
        let mut rows = [[0i32; 3]; TILE];
        let mut k = 0;
        spans(p, r, |y, l, h| {
            if let Some(row) = rows.get_mut(k) {
                *row = [y, l, h];
                k += 1;
            }
        });
        return ctx.aa_rows(bufs, p, planes, rows.get(..k).unwrap_or_default());
    }
    if let Some(pl) = ctx.smooth_planes(bufs, p, planes) {
        // Smooth colour and the depth test alone: decided here once, the rows shaded a batch
        // at a time (`batched`).
        return batched(p, r, |rows| ctx.smooth_rows(bufs, p, pl, rows));
    }
    if let Some(fill) = ctx.const_fill(bufs, p, planes) {
        // One colour (FLAT) or none (depth only) and the depth test: the same, the rows'
        // groups tested and stored in one pass (`const_rows`).
        return batched(p, r, |rows| ctx.const_rows(bufs, p, planes, fill, rows));
    }
    if let Some(ops) = &ctx.ops {
        // Per-fragment operations: the rows (at most a tile's) are gathered and shaded in one
        // call, which sets up what depends on the primitive once (`ops_rows`).
        let mut rows = [[0i32; 3]; TILE];
        let mut k = 0;
        spans(p, r, |y, l, h| {
            if let Some(row) = rows.get_mut(k) {
                *row = [y, l, h];
                k += 1;
            }
        });
        return ctx.ops_rows(ops, bufs, p, planes, rows.get(..k).unwrap_or_default());
    }
    // One fused route for the primitive's spans (`FusedSlot`), the rows a batch at a time
    // (the general path's set-up once a batch, `tri_rows`).
    let mut fused = None;
    batched(p, r, |rows| ctx.tri_rows(bufs, p, planes, rows, &mut fused));
}

/// The spans of `p` in `r` handed to `shade` in batches, so that what depends on the
/// primitive alone is set up once a batch and kept in registers (a call per span paid its
/// set-up every time): a triangle of at most 2x2 pixels (a dense mesh's usual triangle) in
/// one batch of at most two rows, without the sixteen-row array; any other sixteen rows at a
/// time.
#[inline(always)]
fn batched(p: &RPrim, r: [i32; 4], mut shade: impl FnMut(&[[i32; 3]])) {
    if p.cover & COVER_KNOWN != 0 {
        let mut rows = [[0i32; 3]; 2];
        let mut k = 0;
        spans(p, r, |y, l, h| {
            if let Some(row) = rows.get_mut(k) {
                *row = [y, l, h];
                k += 1;
            }
        });
        return shade(rows.get(..k).unwrap_or_default());
    }
    let mut rows = [[0i32; 3]; 16];
    let mut k = 0;
    spans(p, r, |y, l, h| {
        if k == rows.len() {
            shade(&rows);
            k = 0;
        }
        if let Some(row) = rows.get_mut(k) {
            *row = [y, l, h];
            k += 1;
        }
    });
    shade(rows.get(..k).unwrap_or_default())
}

/// The covered run of each row of `r` (the triangle's bounding box clipped to the tile) in
/// bottom-to-top order: `span(y, first, last)` for every row with one.
#[inline(always)]
fn spans(p: &RPrim, r: [i32; 4], mut span: impl FnMut(i32, i32, i32)) {
    let [x0, y0, x1, y1] = r;
    if p.cover & COVER_KNOWN != 0 {
        // At most 2x2 pixels whose covered centres setup already found: no edge walk.
        let (bx, by) = (p.bbox[0], p.bbox[1]);
        for y in rows(y0, y1) {
            let row = (p.cover >> (2 * (y - by))) & 3;
            // Columns x0..=x1 of the tile, relative to the bounding box (0 or 1).
            let cols = row & (((2u8 << (x1 - bx)) - 1) & !((1u8 << (x0 - bx)) - 1));
            if cols != 0 {
                let l = bx + cols.trailing_zeros() as i32;
                let h = bx + 7 - cols.leading_zeros() as i32;
                span(y, l, h);
            }
        }
        return;
    }
    let edges = p.edges();
    if x1 - x0 < SMALL {
        // Narrow: test each pixel centre (additions only) instead of dividing per edge, on
        // 32-bit lanes when every edge value of the rectangle fits.
        #[cfg(target_arch = "x86_64")]
        if narrow_sse(&edges, r, &mut span) {
            return;
        }
        return narrow(&edges, r, span);
    }
    for y in rows(y0, y1) {
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
            span(y, l as i32, h as i32);
        }
    }
}

/// The narrow walk: on each row of `r` the first and last pixel whose centre all three edge
/// functions (`RPrim::edges`) leave >= 0, each pixel tested in i64.
#[inline(always)]
fn narrow(edges: &[[i64; 3]; 3], r: [i32; 4], mut span: impl FnMut(i32, i32, i32)) {
    let [x0, y0, x1, y1] = r;
    for y in y0..=y1 {
        let at = |e: &[i64; 3]| e[0] + e[2] * i64::from(y) + e[1] * i64::from(x0);
        let mut e = [at(&edges[0]), at(&edges[1]), at(&edges[2])];
        let (mut l, mut h) = (i32::MAX, i32::MIN);
        for x in x0..=x1 {
            if (e[0] | e[1] | e[2]) >= 0 {
                l = l.min(x);
                h = x;
            }
            for (ek, edge) in e.iter_mut().zip(edges) {
                *ek += edge[1];
            }
        }
        if l <= h {
            span(y, l, h);
        }
    }
}

/// `narrow` on SSE2 lanes: when |E| at (`x0`, `y0`) plus |dE/dx|·(x1 − x0) plus
/// |dE/dy|·(y1 − y0) is below 2^31 for every edge, every edge value at a pixel of `r` is exact
/// in i32 (E is linear, so none exceeds that bound), and each row's values at up to twelve
/// pixels are three `paddd` from the row's first pixel; the sign bits of the three edges' OR
/// (`movmskps`) give the uncovered pixels, the span's ends their first and last clear bit.
/// Each row's values are the previous row's plus dE/dy (exact, within the bound). The same
/// spans as `narrow`; false (nothing emitted) when the bound does not hold, the width is not
/// below `SMALL`, or `r` is empty.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn narrow_sse(edges: &[[i64; 3]; 3], r: [i32; 4], span: &mut impl FnMut(i32, i32, i32)) -> bool {
    let [x0, y0, x1, y1] = r;
    let (w, h) = (x1.wrapping_sub(x0), y1.wrapping_sub(y0));
    if !(0..SMALL).contains(&w) || h < 0 {
        return false;
    }
    let mut base = [0i32; 3];
    for (b, e) in base.iter_mut().zip(edges) {
        // `narrow`'s first value of row y0 (wrapping: the same bits as its i64 sums).
        let e00 = e[0]
            .wrapping_add(e[2].wrapping_mul(i64::from(y0)))
            .wrapping_add(e[1].wrapping_mul(i64::from(x0)));
        let bound = e00
            .unsigned_abs()
            .saturating_add(e[1].unsigned_abs().saturating_mul(w as u64))
            .saturating_add(e[2].unsigned_abs().saturating_mul(h as u64));
        if bound > i32::MAX as u64 {
            return false;
        }
        *b = e00 as i32;
    }
    // dE/dx and dE/dy fit too when they are used: (x1 − x0) ≥ 1 for a lane past the first,
    // (y1 − y0) ≥ 1 for a second row. Past those, the lanes' wrapped values are masked off.
    let dx = edges.map(|e| e[1] as i32);
    let dy = edges.map(|e| e[2] as i32);
    let cols = (2u32 << w) - 1;
    // Pixels 0-3 of the row, or 0-3, 4-7 and 8-11 (a third copy of the row loop for two
    // groups pushed `tri` out of line: planar-shadow +1.7% instructions).
    let a = (base, dx, dy, x0, [y0, y1], cols);
    match w {
        0..4 => narrow_rows::<1>(a, span),
        _ => narrow_rows::<3>(a, span),
    }
    true
}

/// The rows of `narrow_sse` on `K` groups of four lanes (pixels 0 to 4K − 1 of the row: one
/// group for a width up to four, else three; the lanes past it masked off by `cols`): each
/// edge's values E, E + d, E + 2d, E + 3d, then + 4d a group, stepped by dE/dy a row, in
/// straight-line code.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
// The group index runs over the three edges' arrays at once.
#[allow(clippy::type_complexity, clippy::needless_range_loop)]
fn narrow_rows<const K: usize>(
    (base, dx, dy, x0, [y0, y1], cols): ([i32; 3], [i32; 3], [i32; 3], i32, [i32; 2], u32),
    span: &mut impl FnMut(i32, i32, i32),
) {
    use std::arch::x86_64::{
        __m128i, _mm_add_epi32, _mm_castsi128_ps, _mm_movemask_ps, _mm_or_si128, _mm_set1_epi32,
        _mm_set_epi32,
    };
    // SAFETY: SSE2 is part of the x86-64 baseline; register arithmetic only.
    unsafe {
        let lanes = |k: usize| -> [__m128i; K] {
            let (b, d) = (base[k], dx[k]);
            let at = |l: i32| b.wrapping_add(d.wrapping_mul(l));
            let v0 = _mm_set_epi32(at(3), at(2), at(1), at(0));
            let d4 = _mm_set1_epi32(d.wrapping_mul(4));
            let mut v = [v0; K];
            for c in 1..K {
                v[c] = _mm_add_epi32(v[c - 1], d4);
            }
            v
        };
        let mut v: [[__m128i; K]; 3] = [lanes(0), lanes(1), lanes(2)];
        let step = dy.map(|d| _mm_set1_epi32(d));
        for y in rows(y0, y1) {
            let mut neg = 0u32;
            for c in 0..K {
                let o = _mm_or_si128(_mm_or_si128(v[0][c], v[1][c]), v[2][c]);
                neg |= (_mm_movemask_ps(_mm_castsi128_ps(o)) as u32) << (4 * c);
            }
            let cov = !neg & cols;
            if cov != 0 {
                let l = x0 + cov.trailing_zeros() as i32;
                let h = x0 + 31 - cov.leading_zeros() as i32;
                span(y, l, h);
            }
            for (vk, s) in v.iter_mut().zip(&step) {
                *vk = vk.map(|vc| _mm_add_epi32(vc, *s));
            }
        }
    }
}

/// Rows `y0..=y1` as a half-open range (`y1` is at most a tile's last row, far below
/// `i32::MAX`): the inclusive range's exhaustion flag cost a test and a branch per row.
#[inline(always)]
fn rows(y0: i32, y1: i32) -> std::ops::Range<i32> {
    y0..y1.saturating_add(1)
}

/// Bounding boxes narrower than this are scanned pixel by pixel.
const SMALL: i32 = 12;

#[cfg(test)]
mod tests {
    use super::super::setup::{geom, COVER_KNOWN};

    const RECT: [i32; 4] = [0, 0, 99, 99];

    /// Coverage of a triangle given in 1/256 pixel, as setup hands it to the rasteriser.
    fn cover(p: [[i64; 2]; 3]) -> Option<u8> {
        geom(&RECT, p).map(|g| g.coverage())
    }

    #[test]
    fn one_pixel_box_covered_or_not() {
        // Legs of 300/256 px: the centre (128, 128) has x + y = 256 < 300, inside.
        assert_eq!(cover([[0, 0], [300, 0], [0, 300]]), Some(COVER_KNOWN | 1));
        // Legs of 200/256 px: the same box (pixel 0), but x + y = 256 > 200, outside.
        assert_eq!(cover([[0, 0], [200, 0], [0, 200]]), Some(COVER_KNOWN));
        // Clockwise input gives the same answer (setup reorders it).
        assert_eq!(cover([[0, 0], [0, 300], [300, 0]]), Some(COVER_KNOWN | 1));
    }

    #[test]
    fn two_by_two_box_mask() {
        // Legs of 600/256 px: centres (128|384, 128|384); x + y < 600 except (384, 384).
        // Bits: 2·row + column.
        assert_eq!(
            cover([[0, 0], [600, 0], [0, 600]]),
            Some(COVER_KNOWN | 0b0111)
        );
        // Shifted one pixel right and up: same mask, relative to the box corner (1, 1).
        let s = |v: [i64; 2]| [v[0] + 256, v[1] + 256];
        let g = geom(&RECT, [s([0, 0]), s([600, 0]), s([0, 600])]);
        assert_eq!(g.as_ref().map(|g| g.bbox), Some([1, 1, 2, 2]));
        assert_eq!(g.map(|g| g.coverage()), Some(COVER_KNOWN | 0b0111));
    }

    #[test]
    fn one_row_and_one_column_boxes() {
        // 600 wide, 380 high: box 2x1; centres (128, 128) and (384, 128) satisfy
        // x/600 + y/380 < 1 (0.55 and 0.98): bits 0 and 1.
        assert_eq!(
            cover([[0, 0], [600, 0], [0, 380]]),
            Some(COVER_KNOWN | 0b0011)
        );
        // Transposed: box 1x2, pixels (0, 0) and (0, 1): bits 0 and 2.
        assert_eq!(
            cover([[0, 0], [380, 0], [0, 600]]),
            Some(COVER_KNOWN | 0b0101)
        );
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    fn narrow_sse_is_the_i64_walk() {
        use super::{narrow, narrow_sse, SMALL};
        let mut g = crate::cpu::testgen::Gen(41);
        let (mut fast, mut slow) = (0, 0);
        for i in 0..30000 {
            let mut rnd = |s: i64| (g.next() % (2 * s as u64 + 1)) as i64 - s;
            let (x0, y0) = (rnd(3000) as i32, rnd(3000) as i32);
            let (w, h) = (rnd(SMALL as i64).abs() as i32 % SMALL, rnd(70).abs() as i32);
            let r = [x0, y0, x0 + w, y0 + h];
            let scale = [1i64 << 10, 1 << 18, 1 << 24, 1 << 28, 1 << 45][i % 5];
            let edges: [[i64; 3]; 3] = std::array::from_fn(|_| {
                let (mut e1, e2) = (rnd(scale), rnd(scale));
                if rnd(8) == 0 {
                    e1 = 0;
                }
                // The value at a pixel of the rectangle, zero now and then (the ties).
                let (cx, cy) = (
                    x0 + rnd(w as i64).abs() as i32,
                    y0 + rnd(h as i64).abs() as i32,
                );
                let v = if rnd(5) == 0 { 0 } else { rnd(4 * scale) };
                let e0 = v
                    .wrapping_sub(e1.wrapping_mul(i64::from(cx)))
                    .wrapping_sub(e2.wrapping_mul(i64::from(cy)));
                [e0, e1, e2]
            });
            let mut want = Vec::new();
            narrow(&edges, r, |y, l, h| want.push([y, l, h]));
            let mut got = Vec::new();
            if narrow_sse(&edges, r, &mut |y, l, h| got.push([y, l, h])) {
                fast += 1;
                assert_eq!(got, want, "r {r:?} edges {edges:?}");
            } else {
                slow += 1;
                assert!(got.is_empty());
            }
        }
        // Both routes were taken, the lanes' most of the time.
        assert!(fast > 15000 && slow > 3000, "fast {fast} slow {slow}");
    }

    /// `prims` (the `COVER_KNOWN` triangles through `FragCtx::tiny` where the state allows)
    /// against each primitive of the bin through `prim`: the same colours, depths and
    /// occlusion count, byte for byte. Bins of smooth and FLAT triangles of at most 2x2
    /// pixels crowded into a corner of the tile (so that later ones land on earlier ones'
    /// pixels), some across its edges or outside it, some larger or without known coverage;
    /// depth planes meeting the stored values exactly (the ties LESS and LEQUAL differ on),
    /// awkward plane values (NaN, ±0, ∞); random depth states (LESS and LEQUAL with the mask on
    /// most often), colour masks, occlusion counts, stipple.
    #[test]
    fn tiny_triangles_are_prim_byte_for_byte() {
        use super::super::fragment::TileBufs;
        use super::super::framebuffer::TILE;
        use super::super::setup::{PrimKind, RLayout, RPrim, F_FLAT};
        use super::{prim, prims};
        use crate::cpu::testgen::{tex_ctx, tile_bufs, Gen};
        use crate::gl;
        let mut g = Gen(71);
        let mut tiny = 0;
        for round in 0..1500 {
            let rl = RLayout {
                n: 4,
                ..Default::default()
            };
            let mut f = tex_ctx(rl, Default::default(), &mut || g.next());
            if round % 4 != 3 {
                f.depth_test = true;
                f.depth_func = [gl::LESS, gl::LEQUAL][round % 2];
                f.depth_mask = true;
                f.stipple = None;
            }
            if g.next() % 10 == 0 {
                f.color_mask = [g.next() % 2 == 0, true, true, g.next() % 2 == 0];
            }
            f.count = g.next() % 20 == 0;
            let (tx, ty) = (64 * (g.next() % 3) as i32, 64 * (g.next() % 3) as i32);
            // Corners near the tile's first or last pixels.
            let (cx, cy) = match g.next() % 3 {
                0 => (tx - 1, ty - 1),
                1 => (tx + TILE as i32 - 5, ty + TILE as i32 - 5),
                _ => (tx + 20, ty + 30),
            };
            let mut pool = Vec::new();
            let mut list = Vec::new();
            for _ in 0..1 + g.next() % 40 {
                let (w, h) = ((g.next() % 2) as i32, (g.next() % 2) as i32);
                let (x0, y0) = (cx + (g.next() % 6) as i32, cy + (g.next() % 6) as i32);
                let known = g.next() % 8 != 0;
                let big = !known && g.next() % 2 == 0;
                let bbox = match big {
                    true => [x0 - 3, y0 - 2, x0 + 4, y0 + 3],
                    false => [x0, y0, x0 + w, y0 + h],
                };
                // Covered bits inside the box only (as setup sets them), none now and then.
                let inside = (if w == 1 { 0b11 } else { 0b01 }) * (if h == 1 { 0b101 } else { 1 });
                let cover = match known {
                    true => COVER_KNOWN | (g.next() as u8 & inside),
                    false => 0,
                };
                let mut s = |v: i32| v * 256 + (g.next() % 256) as i32;
                let xy = [
                    s(bbox[0]),
                    s(bbox[1]),
                    s(bbox[2]),
                    s(bbox[1]),
                    s(bbox[0]),
                    s(bbox[3]),
                ];
                let flags = [0, 0, 0, F_FLAT][(g.next() % 4) as usize];
                // A depth on the stored quarters now and then (ties), else near them.
                let k = (g.next() % 5) as f32 * 0.25;
                let z = match g.next() % 3 {
                    0 => [k, 0.0, 0.0],
                    1 => [k, (g.next() % 9) as f32 * 1e-3 - 4e-3, -2e-3],
                    _ => [
                        g.mostly_unit(),
                        g.mostly_unit() * 0.1,
                        g.mostly_unit() * 0.1,
                    ],
                };
                let voff = pool.len() as u32;
                let w0 = match g.next() % 10 {
                    0 => g.float(),
                    _ => 0.5 + (g.next() % 100) as f32 * 0.02,
                };
                pool.extend([w0, g.mostly_unit() * 0.1, g.mostly_unit() * 0.1]);
                for _ in 0..4 {
                    let v = match g.next() % 8 {
                        0 => {
                            [0.0, -0.0, f32::NAN, f32::INFINITY, -1.0, 2.0][(g.next() % 6) as usize]
                        }
                        _ => g.mostly_unit(),
                    };
                    let step = |g: &mut Gen| match (flags, g.next() % 12) {
                        (F_FLAT, 0) => 1e-3,
                        (F_FLAT, _) => [0.0, -0.0][(g.next() % 2) as usize],
                        _ => g.mostly_unit() * 0.2,
                    };
                    pool.extend([v, step(&mut g), step(&mut g)]);
                }
                let kind = PrimKind::Tri;
                let (mat, owns) = (0, (g.next() % 8) as u8);
                list.push(RPrim {
                    kind,
                    flags,
                    bbox,
                    mat,
                    voff,
                    xy,
                    owns,
                    cover,
                    z,
                });
            }
            let bin: Vec<u32> = (0..list.len() as u32).collect();
            let (color, depth, stencil) = crate::cpu::testgen::tile_contents(&mut g);
            let draw = |binned: bool| {
                let (mut c, mut d, mut s) = (color.clone(), depth.clone(), stencil.clone());
                let mut bufs: TileBufs = tile_bufs(&mut c, &mut d, &mut s, (tx, ty));
                match binned {
                    true => prims(&f, &mut bufs, &list, &bin, &pool),
                    false => list.iter().for_each(|p| prim(&f, &mut bufs, p, &pool)),
                }
                let samples = bufs.samples;
                (c, d, samples)
            };
            let want = draw(false);
            let got = draw(true);
            assert!(got == want, "round {round}: {f:?} {list:?} {pool:?}");
            let bufs_state = {
                let (mut c, mut d, mut s) = (color.clone(), depth.clone(), stencil.clone());
                f.tiny_depth(&tile_bufs(&mut c, &mut d, &mut s, (tx, ty)))
            };
            if bufs_state != 0 {
                tiny += list.iter().filter(|p| p.cover & COVER_KNOWN != 0).count();
            }
        }
        // The tiny route was open to most of the triangles.
        assert!(tiny > 10000, "tiny {tiny}");
    }

    #[test]
    fn larger_box_is_left_to_the_edge_walk() {
        assert_eq!(cover([[0, 0], [900, 0], [0, 900]]), Some(0));
    }
}
