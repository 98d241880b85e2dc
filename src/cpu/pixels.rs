//! Rasterisation of pixel rectangles and bitmaps (GL 2.1 §3.6.5 "Conversion to Fragments",
//! §3.7, §4.3.3): DrawPixels, CopyPixels and Bitmap turn groups into fragments here, which then
//! take texturing (at the raster position's texture coordinates), the colour sum, fog (at the
//! raster distance) and the per-fragment operations of §4.1, exactly as the fragments of
//! primitives do (`FragCtx::pixel`). Stencil groups are written to the stencil buffer through the
//! scissor test and the stencil write mask only (§4.3.1).
//!
//! Design decision: which window pixels a zoomed rectangle covers, and which group each takes,
//! is GL 2.1 §3.6.5's rule taken literally: group (i, j) covers the rectangle from (x + i·zx,
//! y + j·zy) to (x + (i + 1)·zx, y + (j + 1)·zy), (x, y) the raster position rounded as Mesa rounds
//! it, and a pixel whose centre lies inside, or on the rectangle's left or bottom boundary, takes
//! that group. The far edges are computed in single precision and snapped to 1/256 pixel, as
//! llvmpipe's rasteriser takes the quad it draws a pixel rectangle with; wherever no pixel centre
//! lies exactly on an edge or a group boundary (integer zooms, fractions with odd denominators)
//! the pixels are the driver's. Each window row and column is mapped to its group once per call
//! (two small tables), and the tiles are filled in parallel, each by one thread, as the
//! rasteriser does.

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use super::fragment::{FragCtx, TileBufs};
use super::framebuffer::{
    depth_unorm, scissor_rect, unorm8, ColorBuf, Framebuffer, Targets, TILE, TILE_PIXELS,
};
use super::texture::{Sampler, UnitTexels};
use super::Renderer;
use crate::state::{State, MAX_TEXTURE_UNITS};

/// The groups of a pixel rectangle after the pixel transfer, rows bottom-up, `width` per row.
#[derive(Clone, Copy, Debug)]
pub enum Groups<'a> {
    /// RGBA colours, clamped to [0, 1] (DrawPixels of a colour or colour-index format,
    /// CopyPixels COLOR).
    Color(&'a [[f32; 4]]),
    /// Colours already in the colour buffer's 8 bits: only where [`Renderer::pixels_plain`]
    /// says the fragments reach the buffer unchanged.
    Bytes(&'a [[u8; 4]]),
    /// Depths in [0, 1] (DEPTH_COMPONENT, CopyPixels DEPTH); the colour is the raster colour.
    Depth(&'a [f64]),
    /// Stencil indices (STENCIL_INDEX, CopyPixels STENCIL): written to the stencil buffer only.
    Stencil(&'a [u8]),
    /// Depths in [0, 1] and stencil indices of the same groups (GL_EXT_packed_depth_stencil's
    /// DEPTH_STENCIL, CopyPixels DEPTH_STENCIL): written to the depth and stencil buffers only,
    /// each through its write mask (GL 3.0 §4.3.1).
    DepthStencil(&'a [f64], &'a [u8]),
    /// A bitmap's bits (nonzero: a fragment of the raster colour at the raster depth).
    Bits(&'a [u8]),
}

/// Which window columns (or rows) a rectangle covers, and the group each takes.
#[derive(Clone, Debug, Default)]
pub struct Span {
    /// The first covered window coordinate.
    pub lo: i32,
    /// For each covered coordinate from `lo`, its group (column or row index).
    pub groups: Vec<u32>,
}

impl Span {
    /// The span of `n` groups of size `zoom` starting at window coordinate `start`, whose far
    /// edge is `end` (both snapped to 1/256 pixel here, as the rasteriser snaps vertices), cut
    /// to the inclusive window range `[min, max]`. A pixel is covered when its centre c satisfies
    /// low <= c < high (the low edge owns centres exactly on it); it takes the group
    /// floor((c − start) / zoom), clamped to the groups there are.
    pub fn new(start: f64, end: f64, n: usize, zoom: f32, min: i32, max: i32) -> Span {
        let snap = |v: f64| (v * 256.0).round() / 256.0;
        let (a, b) = (snap(start), snap(end));
        let (low, high) = if a <= b { (a, b) } else { (b, a) };
        if n == 0 || zoom == 0.0 || !zoom.is_finite() || low >= high || low.is_nan() || min > max {
            return Span::default();
        }
        // First pixel whose centre is >= low, last whose centre is < high, inside [min, max].
        let first = ((low - 0.5).ceil()).max(f64::from(min));
        let last = ((high - 0.5).ceil() - 1.0).min(f64::from(max));
        if first > last {
            return Span::default();
        }
        let (first, last) = (first as i32, last as i32);
        let z = f64::from(zoom);
        // Zoom 1 from a whole start (every bitmap, DrawPixels at its rounded raster position):
        // (p + 0.5 − start) / 1 is exact in f64 for i32 coordinates, and its floor is p − start.
        if z == 1.0 && start.fract() == 0.0 && start.abs() <= f64::from(i32::MAX) {
            let (start, top) = (start as i64, (n - 1) as i64);
            let groups = (first..=last)
                .map(|p| (i64::from(p) - start).clamp(0, top) as u32)
                .collect();
            return Span { lo: first, groups };
        }
        let groups = (first..=last)
            .map(|p| {
                // §3.6.5: a centre on the boundary between two groups belongs to the group
                // whose left (bottom) boundary it is: the higher one for a positive zoom, the
                // lower for a negative one.
                let t = (f64::from(p) + 0.5 - start) / z;
                let g = if z > 0.0 { t.floor() } else { t.ceil() - 1.0 };
                g.clamp(0.0, (n - 1) as f64) as u32
            })
            .collect();
        Span { lo: first, groups }
    }

    /// Covered coordinates from `lo`.
    pub fn len(&self) -> usize {
        self.groups.len()
    }

    /// Whether nothing is covered.
    pub fn is_empty(&self) -> bool {
        self.groups.is_empty()
    }
}

/// Where a [`RowRun`] reads one buffer's pixels: the buffer's memory, or the value of its
/// tile's pending clear (every pixel of the run has it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Src<'a, T> {
    /// The run's pixels in the buffer.
    Mem(&'a [T]),
    /// The tile's pending clear value.
    Fill(T),
}

impl<T: Copy> Src<'_, T> {
    /// Pixel `k` of the run (`None` past a memory run's end).
    pub fn get(&self, k: usize) -> Option<T> {
        match self {
            Src::Mem(s) => s.get(k).copied(),
            Src::Fill(v) => Some(*v),
        }
    }
}

/// Pixels of one framebuffer row as [`row_runs`] gives them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowRun<'a> {
    /// This many pixels outside the framebuffer (`Framebuffer::pixel_in` gives `None`).
    Outside(usize),
    /// `len` pixels inside one tile: their colour (of the buffer asked for), depth and stencil.
    Inside {
        len: usize,
        color: Src<'a, [u8; 4]>,
        depth: Src<'a, u32>,
        stencil: Src<'a, u8>,
    },
}

impl RowRun<'_> {
    /// The pixels of the run.
    pub fn len(&self) -> usize {
        match *self {
            RowRun::Outside(n) | RowRun::Inside { len: n, .. } => n,
        }
    }

    /// Whether the run has no pixel (`row_runs` gives none such).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// `Framebuffer::pixels_in` a run at a time: the `n` pixels (x + k, y), k = 0 .. n, given to
/// `f` in order as runs of pixels outside the framebuffer and runs inside one tile, each buffer
/// of a run as a slice of its memory or its tile's pending clear. Pixel for pixel the values
/// `pixel_in` gives (checked in `row_runs_are_pixel_in`); for the copies of the framebuffer
/// into textures (CopyTexImage, a framebuffer object's images), which then convert a run with
/// one loop and no per-pixel lookups.
pub fn row_runs(
    fb: &Framebuffer,
    buf: ColorBuf,
    x: i64,
    y: i64,
    n: usize,
    mut f: impl FnMut(RowRun<'_>),
) {
    let (w, h) = fb.size();
    let (w, h) = (i64::from(w), i64::from(h));
    let (src, front): (&[[u8; 4]], bool) = match (buf, &fb.front) {
        (ColorBuf::Front, Some(b)) => (b, true),
        _ => (&fb.color, false),
    };
    let mut k = 0usize;
    while k < n {
        let left = n - k;
        let px = x.saturating_add(k as i64);
        if y < 0 || y >= h || px >= w {
            return f(RowRun::Outside(left));
        }
        if px < 0 {
            let m = (px.unsigned_abs().min(left as u64)) as usize;
            f(RowRun::Outside(m));
            k += m;
            continue;
        }
        // The pixels from px to the end of its tile, of the row or of the request.
        let run = (TILE - px as usize % TILE).min(left).min((w - px) as usize);
        let i0 = fb.index(px as usize, y as usize);
        let fill = fb
            .pending
            .get(i0 / TILE_PIXELS)
            .copied()
            .unwrap_or_default();
        let pending_color = if front { fill.front } else { fill.main };
        let range = i0..i0 + run;
        let color = pending_color
            .map(Src::Fill)
            .or_else(|| src.get(range.clone()).map(Src::Mem));
        let depth = fill
            .depth
            .map(Src::Fill)
            .or_else(|| fb.depth.get(range.clone()).map(Src::Mem));
        let stencil = fill
            .stencil
            .map(Src::Fill)
            .or_else(|| fb.stencil.get(range).map(Src::Mem));
        f(match (color, depth, stencil) {
            (Some(color), Some(depth), Some(stencil)) => RowRun::Inside {
                len: run,
                color,
                depth,
                stencil,
            },
            // Buffers shorter than their tiles (never: each holds whole tiles).
            _ => RowRun::Outside(run),
        });
        k += run;
    }
}

impl Framebuffer {
    /// `set_pixel` (or `set_stencil`) of the pixels (k, y), k = 0 .. src.len(), in the buffer
    /// `buf` picks, from `src[k]`: a tile's run of the row with one slice copy. Nothing
    /// outside the framebuffer; for a framebuffer with no pending clear (a framebuffer object's
    /// images being loaded). Checked against `set_pixel` in `set_row_is_set_pixel`.
    pub(crate) fn set_row<T: Copy>(&mut self, y: u32, src: &[T], buf: fn(&mut Self) -> &mut [T]) {
        let (w, h) = self.size();
        if y >= h {
            return;
        }
        let n = src.len().min(w as usize);
        let mut x = 0usize;
        while x < n {
            let run = (TILE - x % TILE).min(n - x);
            let i0 = self.index(x, y as usize);
            if let (Some(d), Some(s)) = (buf(self).get_mut(i0..i0 + run), src.get(x..x + run)) {
                d.copy_from_slice(s);
            }
            x += run;
        }
    }
}

/// A pixel rectangle or bitmap ready to rasterise.
#[derive(Clone, Debug)]
pub struct PixelDraw<'a> {
    /// Covered columns and their group columns.
    pub cols: Span,
    /// Covered rows and their group rows.
    pub rows: Span,
    /// Groups per row.
    pub width: usize,
    /// The groups.
    pub groups: Groups<'a>,
}

/// What every fragment of one draw shares: the raster position's associated data.
struct Shared<'a> {
    /// Window z of the raster position.
    z: f64,
    /// Raster colour.
    color: Vec4,
    /// Secondary colour added by the colour sum, when it applies.
    secondary: Option<Vec3>,
    /// Raster texture coordinates of each unit, and their samplers.
    tex: [Option<(&'a Sampler, [f32; 4])>; MAX_TEXTURE_UNITS],
    /// Fog coordinate: the raster distance.
    fogc: f32,
    /// `shade(color)`: the colour of every fragment of a bitmap or a depth rectangle (the
    /// raster colour, textured at the raster position's coordinates), shaded once a draw.
    shaded: Vec4,
}

impl Shared<'_> {
    /// The fragment colour after texturing (§3.8.13) and the colour sum (§3.9).
    #[inline]
    fn shade(&self, c: Vec4) -> Vec4 {
        let prim = c;
        let mut c = c;
        // The coordinates are the same for every fragment: no derivatives, λ = 0. Every unit
        // samples first: a COMBINE source TEXTUREn reads unit n's texel (GL 1.4 §3.8.13).
        let raw: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] =
            std::array::from_fn(|u| self.tex[u].map(|(tx, coords)| tx.texel(coords, 0.0)));
        let units: UnitTexels = std::array::from_fn(|u| {
            self.tex[u]
                .zip(raw[u])
                .map(|((tx, _), r)| tx.combine_texel(r))
        });
        for ((tx, _), r) in self.tex.iter().zip(raw).filter_map(|(t, r)| t.zip(r)) {
            c = tx.shade_texel(c, prim, r, &units);
        }
        if let Some(s) = self.secondary {
            c += s.extend(0.0);
        }
        c
    }
}

impl Renderer {
    /// Whether the fragments of a pixel rectangle drawn under `state` reach the colour buffer as
    /// they are, through ColorMask only: no texturing, depth test, fog, alpha or stencil test,
    /// blending or logic op. The front end then converts the groups to the buffer's 8 bits
    /// itself ([`Groups::Bytes`]).
    pub fn pixels_plain(&self, state: &State) -> bool {
        let e = &state.enables;
        let textured = (0..MAX_TEXTURE_UNITS).any(|u| {
            e.texture_1d[u] || e.texture_2d[u] || e.texture_3d[u] || e.texture_cube_map[u]
        });
        !self.count_coverage
            && !e.depth_test
            && !textured
            && super::fragops::Ops::new(state).is_none()
    }

    /// The colour mask and the bytes every fragment of a bitmap drawn under `state` writes,
    /// when nothing but the colour write applies to them: [`Renderer::pixels_plain`], no
    /// colour sum and no occlusion query. Then no texture unit is enabled, so the fragments'
    /// colour is the raster colour ([`Shared::shade`] changes nothing), and
    /// `draw_pixel_rect` would take its plain rows with this mask and these bytes.
    fn plain_bits(&self, state: &State) -> Option<([bool; 4], [u8; 4])> {
        let lit_sum = state.enables.lighting
            && state.light_model.color_control == crate::gl::SEPARATE_SPECULAR_COLOR;
        if !self.pixels_plain(state)
            || lit_sum
            || state.enables.color_sum
            || self.counting.is_some()
        {
            return None;
        }
        let mask = match Targets::of(state).none() {
            true => [false; 4],
            false => state.color_write_mask(),
        };
        let c = state.raster_pos.color;
        Some((mask, [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)]))
    }

    /// Draws the bitmap of `bits` (one byte a group, nonzero: a fragment) whose covered window
    /// columns and rows are `cols` and `rows` (`width` groups a row), with `state`, after
    /// everything batched before it. A plain one ([`Renderer::plain_bits`]) is binned into the
    /// scene and rasterised with it (a frame of text and geometry is then one pass, its glyphs
    /// drawn on the pool's threads); any other is drawn in place by `draw_pixel_rect`.
    pub fn bitmap(&mut self, state: &State, cols: Span, rows: Span, width: usize, bits: Vec<u8>) {
        #[cfg(test)]
        let in_place = self.bitmaps_in_place;
        #[cfg(not(test))]
        let in_place = false;
        match self.plain_bits(state) {
            Some((mask, px)) if !in_place && !cols.is_empty() && !rows.is_empty() => {
                self.flush(state);
                let part = BinnedBits {
                    cols,
                    rows,
                    width,
                    bits,
                    mask,
                    px,
                };
                let core = self.unresolved_core();
                core.bin_bits(Targets::of(state), part);
                self.stats.passes = core.passes;
            }
            _ => {
                let d = PixelDraw {
                    cols,
                    rows,
                    width,
                    groups: Groups::Bits(&bits),
                };
                self.draw_pixel_rect(state, &d, true);
            }
        }
    }

    /// Draws the pixel rectangle or bitmap `d` with `state` (the raster position, texturing,
    /// fog and the per-fragment operations it enables), after everything batched before it.
    /// `secondary`: whether the raster secondary colour is the fragments' secondary colour
    /// (bitmaps; pixel rectangles have none).
    pub fn draw_pixel_rect(&mut self, state: &State, d: &PixelDraw, secondary: bool) {
        self.flush(state);
        if d.cols.is_empty() || d.rows.is_empty() {
            return;
        }
        let samplers: [Option<Sampler>; MAX_TEXTURE_UNITS] =
            std::array::from_fn(|u| Sampler::new(state, u));
        let rp = &state.raster_pos;
        let lit_sum = state.enables.lighting
            && state.light_model.color_control == crate::gl::SEPARATE_SPECULAR_COLOR;
        let sum = (secondary && (lit_sum || state.enables.color_sum))
            .then(|| rp.secondary_color.truncate());
        let mut shared = Shared {
            z: f64::from(rp.window.z),
            color: rp.color,
            secondary: sum,
            tex: std::array::from_fn(|u| {
                samplers[u]
                    .as_ref()
                    .map(|s| (s, rp.tex_coords[u].to_array()))
            }),
            fogc: rp.distance,
            shaded: rp.color,
        };
        shared.shaded = shared.shade(shared.color);
        let targets = Targets::of(state);
        let has_depth = self.core().fb.config().depth;
        let fctx = FragCtx {
            // Without a depth buffer the depth test always passes and writes nothing (§4.1.6).
            depth_test: state.enables.depth_test && has_depth,
            depth_func: state.depth_func,
            depth_mask: state.depth_mask,
            // DrawBuffer(NONE): fragments go through every test and write no colour.
            color_mask: if targets.none() {
                [false; 4]
            } else {
                state.color_write_mask()
            },
            color_sum: false,
            rl: Default::default(),
            lighting: None,
            mats: &[],
            count: self.count_coverage,
            samples: self.counting.is_some(),
            // Polygon stipple applies to polygons only (§3.5.6).
            stipple: None,
            ops: super::fragops::Ops::new(state),
            tex: [None; MAX_TEXTURE_UNITS],
            crossbar: false,
        };
        // The colour of a fragment never changes on its way when nothing but the colour write
        // applies: the groups go straight to the buffer.
        let plain = fctx.ops.is_none()
            && !fctx.depth_test
            && shared.tex.iter().all(Option::is_none)
            && shared.secondary.is_none()
            && !fctx.count
            && !fctx.samples;
        // A bitmap fragment's colour in the buffer's bytes (`FragCtx::pixel`'s write of it).
        let c = shared.shaded;
        let bit_px = [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)];
        let stencil_mask = (state.stencil_writemask & 0xFF) as u8;
        let counting = self.counting;
        let core = self.core();
        let fb = &mut core.fb;
        let (tiles_x, tiles_y) = fb.tiles();
        // Only the tiles the rectangle reaches are visited, in ascending order, and only
        // their pending clears are written first (the others' stay pending).
        fb.materialize_rect(rect(&d.cols, &d.rows));
        let tiles = rect_tiles(&d.cols, &d.rows, (tiles_x, tiles_y));
        let Framebuffer {
            color,
            front,
            depth,
            stencil,
            ..
        } = fb;
        // The first colour target is each tile's colour slice, a second one its `color2`
        // (DrawBuffer(FRONT_AND_BACK)), as for primitives.
        let (primary, secondary) = match (targets.front, front.as_mut()) {
            (true, Some(f)) if !targets.main => (f, None),
            (true, Some(f)) => (color, Some(f)),
            _ => (color, None),
        };
        let work = |t: usize, color, color2, depth, stencil| -> u64 {
            let mut bufs = TileBufs {
                color,
                color2,
                depth,
                stencil,
                x: ((t % tiles_x) * TILE) as i32,
                y: ((t / tiles_x) * TILE) as i32,
                samples: 0,
            };
            let rows = plain.then_some((fctx.color_mask, bit_px));
            draw_tile(
                &d.cols,
                &d.rows,
                d.width,
                d.groups,
                &mut bufs,
                rows,
                |bufs, g, i| fragment(&fctx, &shared, bufs, d.groups, g, i, plain, stencil_mask),
            );
            bufs.samples
        };
        let colors = super::tile_parts(primary, &tiles, TILE_PIXELS);
        let mut seconds = secondary.map(|s| super::tile_parts(s, &tiles, TILE_PIXELS).into_iter());
        let depths = super::tile_parts(depth, &tiles, TILE_PIXELS);
        let stencils = super::tile_parts(stencil, &tiles, TILE_PIXELS);
        let mut jobs = Vec::with_capacity(tiles.len());
        for (((&t, c), z), s) in tiles.iter().zip(colors).zip(depths).zip(stencils) {
            let c2 = seconds.as_mut().and_then(|it| it.next().flatten());
            if let (Some(c), Some(z), Some(s)) = (c, z, s) {
                jobs.push((t, c, c2, z, s));
            }
        }
        // A rectangle within one or two tiles, or of fewer pixels than two tiles hold (a glyph
        // across a tile corner, a small image), is drawn on this thread: handing it to the pool
        // costs more than drawing it (`bench bitmap-text`). Tiles are independent, so the
        // pixels are the same either way.
        let pixels = (d.cols.len() as u64).saturating_mul(d.rows.len() as u64);
        let counted: u64 = if jobs.len() <= 2 || pixels < super::SERIAL_AREA {
            jobs.into_iter()
                .map(|(t, c, c2, z, s)| work(t, c, c2, z, s))
                .sum()
        } else {
            jobs.into_par_iter()
                .map(|(t, c, c2, z, s)| work(t, c, c2, z, s))
                .sum()
        };
        if let Some(query) = counting {
            core.add_samples(query, counted);
        }
    }
}

/// The window rectangle `[x0, y0, x1, y1]` (inclusive) that `cols` and `rows` cover (not
/// empty).
fn rect(cols: &Span, rows: &Span) -> [i32; 4] {
    let (x0, y0) = (cols.lo, rows.lo);
    [
        x0,
        y0,
        x0 + cols.len() as i32 - 1,
        y0 + rows.len() as i32 - 1,
    ]
}

/// The tiles of a framebuffer of `tiles` (across, down) that the rectangle of `cols` and `rows`
/// (not empty) reaches, in ascending order.
fn rect_tiles(cols: &Span, rows: &Span, (tiles_x, tiles_y): (usize, usize)) -> Vec<usize> {
    let [x0, y0, x1, y1] = rect(cols, rows);
    let span = |lo: i32, hi: i32, n: usize| match hi < 0 {
        true => 0..0,
        false => (lo.max(0) as usize / TILE).min(n)..(hi as usize / TILE + 1).min(n),
    };
    let (across, up) = (span(x0, x1, tiles_x), span(y0, y1, tiles_y));
    up.flat_map(|ty| across.clone().map(move |tx| ty * tiles_x + tx))
        .collect()
}

/// The fragments of the pixel rectangle `cols` x `rows` (groups `width` a row) inside the tile
/// `bufs` holds: with `plain` (the colour mask and a bitmap's bytes) a row at a time through
/// [`put_row`] where it applies, otherwise `each(bufs, g, i)` for group `g` at tile index `i`,
/// rows bottom-up and left to right.
fn draw_tile(
    cols: &Span,
    rows: &Span,
    width: usize,
    groups: Groups,
    bufs: &mut TileBufs,
    plain: Option<([bool; 4], [u8; 4])>,
    mut each: impl FnMut(&mut TileBufs, usize, usize),
) {
    let [x0, y0, x1, y1] = rect(cols, rows);
    let (ox, oy) = (bufs.x, bufs.y);
    let (tx0, ty0) = (x0.max(ox), y0.max(oy));
    let (tx1, ty1) = (x1.min(ox + TILE as i32 - 1), y1.min(oy + TILE as i32 - 1));
    if tx0 > tx1 || ty0 > ty1 {
        return;
    }
    // The tile's columns, as indices into `cols`.
    let tile_cols = (tx0 - x0) as usize..=(tx1 - x0) as usize;
    for y in ty0..=ty1 {
        let Some(&gj) = rows.groups.get((y - y0) as usize) else {
            continue;
        };
        let row = gj as usize * width;
        let base = (y - oy) as usize * TILE;
        if let Some((mask, bit_px)) = plain {
            // Only the colour write applies: a whole row at a time.
            if let Some(c) = cols.groups.get(tile_cols.clone()) {
                let first = base + (tx0 - ox) as usize;
                if put_row(bufs, first, c, row, groups, mask, bit_px) {
                    continue;
                }
            }
        }
        for x in tx0..=tx1 {
            let Some(&gi) = cols.groups.get((x - x0) as usize) else {
                continue;
            };
            each(bufs, row + gi as usize, base + (x - ox) as usize);
        }
    }
}

/// A plain bitmap (only the colour write applies) binned into the scene instead of drawn in
/// place: rasterised with the scene, each tile drawing it after the primitives and bitmaps
/// before it and before those after it, as [`Renderer::draw_pixel_rect`] would have drawn it
/// at its call (the same rows through [`put_row`]).
#[derive(Debug)]
pub(crate) struct BinnedBits {
    cols: Span,
    rows: Span,
    width: usize,
    bits: Vec<u8>,
    mask: [bool; 4],
    px: [u8; 4],
}

impl BinnedBits {
    /// The tiles it reaches, in ascending order.
    pub(crate) fn tiles(&self, tiles: (usize, usize)) -> Vec<usize> {
        rect_tiles(&self.cols, &self.rows, tiles)
    }

    /// Covered pixels.
    pub(crate) fn pixels(&self) -> u64 {
        (self.cols.len() as u64).saturating_mul(self.rows.len() as u64)
    }

    /// Bytes held (for the scene's bound on memory).
    pub(crate) fn bytes(&self) -> usize {
        self.bits.len() + 4 * (self.cols.len() + self.rows.len())
    }

    /// Draws its part in the tile `bufs` holds.
    pub(crate) fn draw(&self, bufs: &mut TileBufs) {
        let groups = Groups::Bits(&self.bits);
        let plain = Some((self.mask, self.px));
        // `put_row` takes every row of bits: nothing is left to a fragment.
        draw_tile(
            &self.cols,
            &self.rows,
            self.width,
            groups,
            bufs,
            plain,
            |_, _, _| {},
        );
    }
}

/// Writes `px` through `mask` to the pixel at tile index `i` of each colour buffer drawn.
#[inline(always)]
fn put(bufs: &mut TileBufs, i: usize, px: [u8; 4], mask: [bool; 4]) {
    let second = bufs.color2.as_deref_mut().and_then(|c| c.get_mut(i));
    for dst in bufs.color.get_mut(i).into_iter().chain(second) {
        for k in 0..4 {
            if mask[k] {
                dst[k] = px[k];
            }
        }
    }
}

/// The colour groups of row `row` (the index of its first group) that `cols` names, as the
/// fragments at tile indices `first..first + cols.len()`, when nothing but the colour write
/// applies to them (`plain`): what [`fragment`] does to each, a row at a time; a bitmap's set
/// bits as `bit_px` (the shaded raster colour's bytes). False, with nothing written, for groups
/// that are neither colours nor bits.
fn put_row(
    bufs: &mut TileBufs,
    first: usize,
    cols: &[u32],
    row: usize,
    groups: Groups,
    mask: [bool; 4],
    bit_px: [u8; 4],
) -> bool {
    let end = first + cols.len();
    let second = bufs
        .color2
        .as_deref_mut()
        .and_then(|c| c.get_mut(first..end));
    let targets = bufs.color.get_mut(first..end).into_iter().chain(second);
    let full = mask == [true; 4];
    let store = |dst: &mut [u8; 4], px: [u8; 4]| {
        if full {
            *dst = px;
            return;
        }
        for k in 0..4 {
            if mask[k] {
                dst[k] = px[k];
            }
        }
    };
    match groups {
        // Every channel written: whole pixels.
        Groups::Bytes(b) if mask == [true; 4] => {
            let Some(b) = b.get(row..) else { return true };
            for dst in targets {
                for (d, &gi) in dst.iter_mut().zip(cols) {
                    if let Some(&px) = b.get(gi as usize) {
                        *d = px;
                    }
                }
            }
        }
        Groups::Color(c) => {
            let Some(c) = c.get(row..) else { return true };
            for dst in targets {
                for (d, &gi) in dst.iter_mut().zip(cols) {
                    if let Some(c) = c.get(gi as usize) {
                        store(d, [unorm8(c[0]), unorm8(c[1]), unorm8(c[2]), unorm8(c[3])]);
                    }
                }
            }
        }
        Groups::Bytes(b) => {
            let Some(b) = b.get(row..) else { return true };
            for dst in targets {
                for (d, &gi) in dst.iter_mut().zip(cols) {
                    if let Some(&px) = b.get(gi as usize) {
                        store(d, px);
                    }
                }
            }
        }
        // Plain: `FragCtx::pixel` is the masked write of the shaded colour (no depth test,
        // no count), for each set bit.
        Groups::Bits(b) => {
            let Some(b) = b.get(row..) else { return true };
            for dst in targets {
                for (d, &gi) in dst.iter_mut().zip(cols) {
                    if b.get(gi as usize).is_some_and(|&v| v != 0) {
                        store(d, bit_px);
                    }
                }
            }
        }
        _ => return false,
    }
    true
}

/// Group `g` of `groups` as the fragment at tile index `i`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn fragment(
    fctx: &FragCtx,
    shared: &Shared,
    bufs: &mut TileBufs,
    groups: Groups,
    g: usize,
    i: usize,
    plain: bool,
    stencil_mask: u8,
) {
    let (c, z) = match groups {
        Groups::Color(c) => {
            let Some(&c) = c.get(g) else { return };
            let c = Vec4::from_array(c);
            if plain {
                let px = [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)];
                put(bufs, i, px, fctx.color_mask);
                return;
            }
            (c, shared.z)
        }
        Groups::Bytes(c) => {
            if let Some(&px) = c.get(g) {
                put(bufs, i, px, fctx.color_mask);
            }
            return;
        }
        Groups::Depth(d) => {
            let Some(&z) = d.get(g) else { return };
            return fctx.pixel(bufs, i, z, shared.shaded, shared.fogc);
        }
        Groups::Bits(b) => {
            if b.get(g).copied().unwrap_or(0) == 0 {
                return;
            }
            return fctx.pixel(bufs, i, shared.z, shared.shaded, shared.fogc);
        }
        Groups::Stencil(s) => {
            // §4.3.1: only the scissor test (the span is cut to it) and the write mask apply.
            let (Some(&v), Some(dst)) = (s.get(g), bufs.stencil.get_mut(i)) else {
                return;
            };
            *dst = (*dst & !stencil_mask) | (v & stencil_mask);
            return;
        }
        Groups::DepthStencil(d, s) => {
            // GL 3.0 §4.3.1 (EXT_packed_depth_stencil): as a stencil index, and the depth is
            // written too when DepthMask is TRUE, whatever the depth test; no colour.
            if let (Some(&v), Some(dst)) = (s.get(g), bufs.stencil.get_mut(i)) {
                *dst = (*dst & !stencil_mask) | (v & stencil_mask);
            }
            if fctx.depth_mask {
                if let (Some(&z), Some(dst)) = (d.get(g), bufs.depth.get_mut(i)) {
                    *dst = depth_unorm(z);
                }
            }
            return;
        }
    };
    let c = shared.shade(c);
    fctx.pixel(bufs, i, z, c, shared.fogc);
}

/// The columns and rows a pixel rectangle of `width` x `height` groups covers with its lower-left
/// corner at window (`x`, `y`) (the rounded raster position) and zoom factors `zoom`, cut to the
/// framebuffer and the scissor box (see the module docs).
pub fn spans(
    state: &State,
    x: i32,
    y: i32,
    width: usize,
    height: usize,
    zoom: [f32; 2],
) -> (Span, Span) {
    let [sx0, sy0, sx1, sy1] = scissor_rect(state);
    let (zx, zy) = (zoom[0], zoom[1]);
    // The far edges in single precision, x + width · ZOOM_X, as Mesa computes them.
    let x_end = f64::from(x as f32 + width as f32 * zx);
    let y_end = f64::from(y as f32 + height as f32 * zy);
    let cols = Span::new(f64::from(x), x_end, width, zx, sx0, sx1);
    let rows = Span::new(f64::from(y), y_end, height, zy, sy0, sy1);
    (cols, rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Zoom 1 from a whole start (the shortcut) gives each covered pixel the group of the
    /// general rule, floor((p + 0.5 − start) / zoom) clamped to the groups there are.
    #[test]
    fn zoom_one_spans_are_the_general_rule() {
        let mut seed = 5u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        for case in 0..5000 {
            let n = 1 + (next() % 120) as usize;
            let start = (next() % 700) as i32 - 300;
            let (min, max) = ((next() % 300) as i32 - 100, (next() % 400) as i32);
            // The far edge: the exact one, or a little past it (a clipped or inexact end).
            let end = f64::from(start) + n as f64 + [0.0, 0.3, -0.6][case % 3];
            let s = Span::new(f64::from(start), end, n, 1.0, min, max);
            // The same edges by the general rule (zoom 1 taken as any other zoom).
            let (a, b) = (
                (f64::from(start) * 256.0).round() / 256.0,
                (end * 256.0).round() / 256.0,
            );
            let first = ((a - 0.5).ceil()).max(f64::from(min));
            let last = ((b - 0.5).ceil() - 1.0).min(f64::from(max));
            let want: Vec<u32> = match first > last {
                true => Vec::new(),
                false => (first as i32..=last as i32)
                    .map(|p| {
                        let t = (f64::from(p) + 0.5 - f64::from(start)) / 1.0;
                        t.floor().clamp(0.0, (n - 1) as f64) as u32
                    })
                    .collect(),
            };
            assert_eq!(
                s.groups, want,
                "case {case}: start {start} n {n} [{min}, {max}]"
            );
            if !want.is_empty() {
                assert_eq!(s.lo, first as i32, "case {case}");
            }
        }
    }

    /// `row_runs` gives `pixel_in`'s values pixel for pixel: spans that start and end outside
    /// the framebuffer, cross tiles with and without pending clears (whole and partial), read
    /// either colour buffer; runs never cross a tile or come out empty.
    #[test]
    fn row_runs_are_pixel_in() {
        let mut fb = super::super::framebuffer::tests::pending_clears_fixture();
        // Distinct values in the memory of every pixel, pending clears kept where they are.
        for (i, ((c, d), s)) in fb
            .color
            .iter_mut()
            .zip(fb.depth.iter_mut())
            .zip(fb.stencil.iter_mut())
            .enumerate()
        {
            *c = [i as u8, (i >> 8) as u8, 7, 200];
            *d = (i as u32).wrapping_mul(2_654_435_761) >> 8;
            *s = (i * 31) as u8;
        }
        let mut seed = 5u32;
        let mut next = |m: u32| {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed % m
        };
        let mut cases: Vec<(i64, i64, usize)> = Vec::new();
        for y in [-1i64, 0, 10, 33, 63, 64, 69, 70] {
            for (x, n) in [(-5i64, 20usize), (0, 130), (50, 30), (120, 40), (-3, 200)] {
                cases.push((x, y, n));
            }
            cases.push((131, y, 4));
            cases.push((0, y, 0));
        }
        for _ in 0..400 {
            let (x, y, n) = (next(300) as i64 - 100, next(90) as i64 - 10, next(260));
            cases.push((x, y, n as usize));
        }
        cases.push((i64::MIN + 3, 5, 8));
        cases.push((i64::MAX - 3, 5, 8));
        for buf in [ColorBuf::Main, ColorBuf::Front] {
            for &(x, y, n) in &cases {
                let mut got = Vec::new();
                row_runs(&fb, buf, x, y, n, |r| match r {
                    RowRun::Outside(m) => {
                        assert!(m > 0);
                        got.extend(std::iter::repeat_n(None, m));
                    }
                    RowRun::Inside {
                        len,
                        color,
                        depth,
                        stencil,
                    } => {
                        assert!(len > 0 && len <= TILE);
                        for k in 0..len {
                            got.push(Some((
                                color.get(k).expect("colour"),
                                depth.get(k).expect("depth"),
                                stencil.get(k).expect("stencil"),
                            )));
                        }
                    }
                });
                let want: Vec<_> = (0..n as i64)
                    .map(|k| fb.pixel_in(buf, x.saturating_add(k), y))
                    .collect();
                assert_eq!(got, want, "{buf:?} y {y} x {x} n {n}");
            }
        }
    }

    /// `set_row` writes what `set_pixel` / `set_stencil` write pixel by pixel: rows across
    /// tiles, longer than the framebuffer is wide, above its top.
    #[test]
    fn set_row_is_set_pixel() {
        let config = crate::state::ContextConfig::default();
        let (mut a, mut b) = (
            Framebuffer::try_new(130, 70, config).expect("a test framebuffer"),
            Framebuffer::try_new(130, 70, config).expect("a test framebuffer"),
        );
        for (y, n) in [
            (0u32, 130usize),
            (5, 20),
            (63, 64),
            (64, 65),
            (69, 200),
            (70, 10),
            (900, 3),
        ] {
            let c: Vec<[u8; 4]> = (0..n).map(|k| [k as u8, y as u8, 3, 4]).collect();
            let d: Vec<u32> = (0..n).map(|k| (k as u32) << 8 | y).collect();
            let st: Vec<u8> = (0..n).map(|k| (k as u8) ^ (y as u8)).collect();
            a.set_row(y, &c, |f| &mut f.color);
            a.set_row(y, &d, |f| &mut f.depth);
            a.set_row(y, &st, |f| &mut f.stencil);
            for k in 0..n {
                b.set_pixel(k as u32, y, Some(c[k]), Some(d[k]));
                b.set_stencil(k as u32, y, st[k]);
            }
        }
        assert_eq!((a.color, a.depth, a.stencil), (b.color, b.depth, b.stencil));
    }

    #[test]
    fn spans_follow_the_zoom() {
        // Zoom 1 at 10: pixels 10..=12 take groups 0, 1, 2.
        let s = Span::new(10.0, 13.0, 3, 1.0, 0, 100);
        assert_eq!((s.lo, s.groups.clone()), (10, vec![0, 1, 2]));
        // Zoom 2: 10..=15, two pixels a group.
        let s = Span::new(10.0, 16.0, 3, 2.0, 0, 100);
        assert_eq!((s.lo, s.groups.clone()), (10, vec![0, 0, 1, 1, 2, 2]));
        // Zoom -1: from 10 leftwards, 7..=9 take groups 2, 1, 0.
        let s = Span::new(10.0, 7.0, 3, -1.0, 0, 100);
        assert_eq!((s.lo, s.groups.clone()), (7, vec![2, 1, 0]));
        // Cut to the window: only 0..=1 of -2..=1.
        let s = Span::new(-2.0, 2.0, 4, 1.0, 0, 100);
        assert_eq!((s.lo, s.groups.clone()), (0, vec![2, 3]));
        // Zoom 0 or an empty rectangle covers nothing.
        assert!(Span::new(10.0, 10.0, 3, 0.0, 0, 100).is_empty());
        assert!(Span::new(10.0, 10.0, 0, 1.0, 0, 100).is_empty());
        // Zoom 4/3: 4 groups span 5.33 pixels, centres 10.5 .. 14.5 (15.5 is past the edge).
        let s = Span::new(
            10.0,
            10.0 + 4.0 * (4.0f32 / 3.0) as f64,
            4,
            4.0 / 3.0,
            0,
            100,
        );
        assert_eq!((s.lo, s.groups.clone()), (10, vec![0, 1, 1, 2, 3]));
    }
}
