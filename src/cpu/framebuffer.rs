//! The framebuffer: RGBA8 colour, 24-bit depth and 8-bit stencil (GL 2.1 §4), and `Clear` (§4.2.3).
//!
//! Design decision: every buffer is stored tile-major: the framebuffer is cut into `TILE` x `TILE`
//! squares (edge tiles padded to full size) and each square's pixels are contiguous, rows bottom-up
//! inside it. A tile is then one `chunks_mut` slice, so the rasteriser hands each tile to its own
//! thread with no locks and no unsafe code.

use rayon::prelude::*;

use crate::state::{ContextConfig, State};

/// Side of a square screen tile, in pixels.
pub const TILE: usize = 64;
/// Pixels per tile.
pub const TILE_PIXELS: usize = TILE * TILE;
/// Largest 24-bit depth value (window z = 1).
pub const DEPTH_MAX: u32 = (1 << 24) - 1;

/// The colour, depth, stencil and accumulation buffers, tile-major.
#[derive(Debug, Clone)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    tiles_x: usize,
    tiles_y: usize,
    /// RGBA8 per pixel: the context's default colour buffer, the back buffer of a
    /// double-buffered framebuffer and the only (front) one otherwise. Whatever draws or reads
    /// "the colour buffer" without naming one uses this.
    pub(crate) color: Vec<[u8; 4]>,
    /// The front buffer of a double-buffered framebuffer (`None` when single-buffered).
    pub(crate) front: Option<Vec<[u8; 4]>>,
    /// 24-bit depth in the low bits (allocated even without a depth buffer; then never read
    /// or written: `has_depth`).
    pub(crate) depth: Vec<u32>,
    pub(crate) stencil: Vec<u8>,
    /// The accumulation buffer, 16 signed bits per channel (GL 2.1 §4.2.4; `None`: none).
    pub(crate) accum: Option<Vec<[i16; 4]>>,
    /// Which buffers exist (the context's configuration).
    config: ContextConfig,
    /// Lazy clears, one entry per tile: the values a `Clear` covering the whole tile left to
    /// be written (see [`Fill`]). What reads or writes the buffers directly materialises them
    /// first ([`Framebuffer::materialize_all`]); the rasteriser materialises a tile when a
    /// primitive reaches it, and readback reads a pending colour without writing it.
    pub(crate) pending: Vec<Fill>,
    /// Some tile has a pending fill.
    any_pending: bool,
}

/// A tile's pending clear: the value each buffer is to be filled with (`None`: that buffer's
/// memory is current). Only whole-tile clears with full write masks are deferred; since a
/// fill replaces the whole tile's contents, a later whole-tile clear simply replaces the value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Fill {
    /// `Framebuffer::color`.
    pub(crate) main: Option<[u8; 4]>,
    /// `Framebuffer::front`.
    pub(crate) front: Option<[u8; 4]>,
    pub(crate) depth: Option<u32>,
    pub(crate) stencil: Option<u8>,
}

impl Fill {
    /// Nothing pending.
    #[inline]
    pub(crate) fn is_empty(&self) -> bool {
        *self == Fill::default()
    }

    /// Writes the pending depth and stencil values into the tile's slices, and the colour ones
    /// whose slices are given (`main`, `front`), clearing what it wrote from `self`.
    #[inline]
    pub(crate) fn materialize(
        &mut self,
        main: Option<&mut [[u8; 4]]>,
        front: Option<&mut [[u8; 4]]>,
        depth: &mut [u32],
        stencil: &mut [u8],
    ) {
        if let (Some(v), Some(buf)) = (self.main, main) {
            buf.fill(v);
            self.main = None;
        }
        if let (Some(v), Some(buf)) = (self.front, front) {
            buf.fill(v);
            self.front = None;
        }
        if let Some(v) = self.depth.take() {
            depth.fill(v);
        }
        if let Some(v) = self.stencil.take() {
            stencil.fill(v);
        }
    }
}

/// One of the framebuffer's colour buffers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorBuf {
    /// `Framebuffer::color`: the back buffer when double-buffered, the only buffer otherwise.
    Main,
    /// The front buffer of a double-buffered framebuffer.
    Front,
}

/// The colour buffers fragments, Clear and Accum(RETURN) write: none, one or both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Targets {
    /// `Framebuffer::color`.
    pub main: bool,
    /// The front buffer of a double-buffered framebuffer.
    pub front: bool,
}

impl Targets {
    /// The buffers DRAW_BUFFER names in `state` (validated when it was set): FRONT, LEFT,
    /// FRONT_LEFT and FRONT_AND_BACK name the front buffer, BACK, LEFT, BACK_LEFT and
    /// FRONT_AND_BACK the back buffer (GL 2.1 table 4.4); a single-buffered framebuffer's only
    /// buffer is its front.
    pub fn of(state: &State) -> Self {
        // A framebuffer object's one colour buffer (context/fbo.rs).
        if state.draw_buffer == crate::gl::COLOR_ATTACHMENT0 {
            return Targets {
                main: true,
                front: false,
            };
        }
        let mask = crate::buffers::mask(state.draw_buffer).unwrap_or(0);
        let (front, back) = (
            mask & crate::buffers::FRONT_LEFT != 0,
            mask & crate::buffers::BACK_LEFT != 0,
        );
        if state.config.double_buffered {
            Targets { main: back, front }
        } else {
            Targets {
                main: front,
                front: false,
            }
        }
    }

    /// Whether no colour buffer is written (DrawBuffer(NONE)).
    pub fn none(&self) -> bool {
        !self.main && !self.front
    }
}

/// The colour buffer READ_BUFFER names in `state` (validated when it was set).
pub fn read_buf(state: &State) -> ColorBuf {
    let mask = crate::buffers::read_mask(state.read_buffer).unwrap_or(0);
    if state.config.double_buffered && mask & crate::buffers::BACK_LEFT == 0 {
        ColorBuf::Front
    } else {
        ColorBuf::Main
    }
}

impl Framebuffer {
    /// A framebuffer cleared to colour 0, depth 1 and stencil 0 (GL's initial contents are
    /// undefined; this is what llvmpipe starts with too), single-buffered with depth and
    /// stencil. Aborts when the buffers cannot be allocated, as `vec!` does; see
    /// [`Framebuffer::try_new`]. For tests: the library builds framebuffers with `try_new`.
    #[cfg(test)]
    pub fn new(width: u32, height: u32) -> Self {
        Self::try_new(width, height, ContextConfig::default()).expect("a test framebuffer")
    }

    /// A cleared framebuffer with the buffers `config` names (colour 0, depth 1, stencil 0,
    /// accumulation 0), or `None` when they (9 bytes a pixel, 13 with a back buffer, 8 more
    /// with an accumulation buffer; padded to whole tiles) cannot be allocated: the
    /// allocation is tried, never assumed.
    pub fn try_new(width: u32, height: u32, config: ContextConfig) -> Option<Self> {
        let (tiles_x, tiles_y, n) = Self::layout(width, height);
        // Without alpha bits the stored alpha is 1 everywhere, and stays so (`color_write_mask`).
        let empty = [0, 0, 0, if config.alpha { 0 } else { 255 }];
        Some(Self {
            width,
            height,
            tiles_x,
            tiles_y,
            color: filled(n, empty)?,
            front: match config.double_buffered {
                true => Some(filled(n, empty)?),
                false => None,
            },
            depth: filled(n, DEPTH_MAX)?,
            stencil: filled(n, 0)?,
            accum: match config.accum {
                true => Some(filled(n, [0; 4])?),
                false => None,
            },
            config,
            pending: filled(n / TILE_PIXELS, Fill::default())?,
            any_pending: false,
        })
    }

    /// The same framebuffer at `width` x `height` (`Context::resize`): what lies inside both
    /// sizes is kept, pixel for pixel from the lower-left corner, the rest is as a new
    /// framebuffer's (GL leaves it undefined). `None` when the new buffers cannot be allocated.
    pub fn resized(&self, width: u32, height: u32) -> Option<Self> {
        if self.any_pending {
            let mut src = self.clone();
            src.materialize_all();
            return src.resized(width, height);
        }
        let mut out = Self::try_new(width, height, self.config)?;
        let (w, h) = (
            width.min(self.width) as usize,
            height.min(self.height) as usize,
        );
        for y in 0..h {
            for x in 0..w {
                let (from, to) = (self.index(x, y), out.index(x, y));
                let copy = |d: &mut [[u8; 4]], s: &[[u8; 4]]| {
                    if let (Some(d), Some(s)) = (d.get_mut(to), s.get(from)) {
                        *d = *s;
                    }
                };
                copy(&mut out.color, &self.color);
                if let (Some(d), Some(s)) = (out.front.as_deref_mut(), self.front.as_deref()) {
                    copy(d, s);
                }
                if let (Some(d), Some(s)) = (out.depth.get_mut(to), self.depth.get(from)) {
                    *d = *s;
                }
                if let (Some(d), Some(s)) = (out.stencil.get_mut(to), self.stencil.get(from)) {
                    *d = *s;
                }
                if let (Some(d), Some(s)) = (
                    out.accum.as_deref_mut().and_then(|a| a.get_mut(to)),
                    self.accum.as_deref().and_then(|a| a.get(from)),
                ) {
                    *d = *s;
                }
            }
        }
        Some(out)
    }

    /// The buffers this framebuffer has.
    pub fn config(&self) -> ContextConfig {
        self.config
    }

    /// The colour buffer `buf` (the main one when there is no separate front buffer).
    fn buffer(&self, buf: ColorBuf) -> &[[u8; 4]] {
        match (buf, &self.front) {
            (ColorBuf::Front, Some(f)) => f,
            _ => &self.color,
        }
    }

    /// What a buffer swap does to the colour buffers (`Context::swap_buffers`): the back buffer
    /// becomes the front buffer, and the back buffer keeps its contents, as llvmpipe's
    /// software winsys leaves it (GL leaves them undefined). Nothing when single-buffered.
    pub fn swap(&mut self) {
        self.materialize_all();
        if let Some(front) = self.front.as_mut() {
            front.copy_from_slice(&self.color);
        }
    }

    /// Tiles across, tiles up and pixels stored (whole tiles) for a `width` x `height` buffer:
    /// at most 256 x 256 tiles of 4096 pixels for the 16384 x 16384 maximum, far below usize.
    fn layout(width: u32, height: u32) -> (usize, usize, usize) {
        let tiles_x = (width as usize).div_ceil(TILE);
        let tiles_y = (height as usize).div_ceil(TILE);
        (tiles_x, tiles_y, tiles_x * tiles_y * TILE_PIXELS)
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Number of tiles across and up.
    pub fn tiles(&self) -> (usize, usize) {
        (self.tiles_x, self.tiles_y)
    }

    /// Index of pixel (x, y) in the tile-major buffers; the caller keeps x < width, y < height.
    #[inline]
    pub fn index(&self, x: usize, y: usize) -> usize {
        let tile = (y / TILE) * self.tiles_x + x / TILE;
        tile * TILE_PIXELS + (y % TILE) * TILE + x % TILE
    }

    /// Writes the main colour and depth of pixel (x, y) (those given), inside the framebuffer,
    /// which has no pending clear (a new one): how a framebuffer object's images are loaded.
    #[cfg(test)]
    pub(crate) fn set_pixel(&mut self, x: u32, y: u32, color: Option<[u8; 4]>, depth: Option<u32>) {
        if x >= self.width || y >= self.height {
            return;
        }
        let i = self.index(x as usize, y as usize);
        if let (Some(c), Some(px)) = (color, self.color.get_mut(i)) {
            *px = c;
        }
        if let (Some(d), Some(px)) = (depth, self.depth.get_mut(i)) {
            *px = d;
        }
    }

    /// Sets the stencil index of pixel (x, y) (nothing outside the framebuffer): a framebuffer
    /// object's stencil attachment loaded (context/fbo.rs).
    #[cfg(test)]
    pub(crate) fn set_stencil(&mut self, x: u32, y: u32, s: u8) {
        if x >= self.width || y >= self.height {
            return;
        }
        let i = self.index(x as usize, y as usize);
        if let Some(px) = self.stencil.get_mut(i) {
            *px = s;
        }
    }

    /// Colour (of the main colour buffer), depth and stencil of pixel (x, y), or `None`
    /// outside the framebuffer. The library reads with [`Framebuffer::pixel_in`] and the read
    /// buffer (`read_buf`).
    #[cfg(test)]
    pub fn pixel(&self, x: i64, y: i64) -> Option<([u8; 4], u32, u8)> {
        self.pixel_in(ColorBuf::Main, x, y)
    }

    /// Colour of colour buffer `buf`, depth and stencil of pixel (x, y), or `None` outside the
    /// framebuffer.
    #[inline]
    pub fn pixel_in(&self, buf: ColorBuf, x: i64, y: i64) -> Option<([u8; 4], u32, u8)> {
        if x < 0 || y < 0 || x >= i64::from(self.width) || y >= i64::from(self.height) {
            return None;
        }
        let i = self.index(x as usize, y as usize);
        let fill = self
            .pending
            .get(i / TILE_PIXELS)
            .copied()
            .unwrap_or_default();
        let pending_color = match (buf, &self.front) {
            (ColorBuf::Front, Some(_)) => fill.front,
            _ => fill.main,
        };
        Some((
            pending_color.map_or_else(|| self.buffer(buf).get(i).copied(), Some)?,
            fill.depth
                .map_or_else(|| self.depth.get(i).copied(), Some)?,
            fill.stencil
                .map_or_else(|| self.stencil.get(i).copied(), Some)?,
        ))
    }

    /// [`Framebuffer::pixel_in`] of the `n` pixels (x + k, y), k = 0 .. n, given to `f` in
    /// that order: the same values, with each tile's pending clear looked up once per run of
    /// pixels in it rather than per pixel (CopyTexImage's read of a rectangle, row by row).
    #[cfg(test)]
    pub fn pixels_in(
        &self,
        buf: ColorBuf,
        x: i64,
        y: i64,
        n: usize,
        mut f: impl FnMut(Option<([u8; 4], u32, u8)>),
    ) {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let src = self.buffer(buf);
        let front = matches!((buf, &self.front), (ColorBuf::Front, Some(_)));
        let mut k = 0usize;
        while k < n {
            let px = x.saturating_add(k as i64);
            if px < 0 || y < 0 || px >= w || y >= h {
                f(None);
                k += 1;
                continue;
            }
            // The pixels from px to the end of its tile, of the row or of the request.
            let run = (TILE - px as usize % TILE)
                .min(n - k)
                .min((w - px) as usize);
            let i0 = self.index(px as usize, y as usize);
            let fill = self
                .pending
                .get(i0 / TILE_PIXELS)
                .copied()
                .unwrap_or_default();
            let pending_color = if front { fill.front } else { fill.main };
            for i in i0..i0 + run {
                let c = pending_color.map_or_else(|| src.get(i).copied(), Some);
                let d = fill.depth.map_or_else(|| self.depth.get(i).copied(), Some);
                let s = fill
                    .stencil
                    .map_or_else(|| self.stencil.get(i).copied(), Some);
                f(match (c, d, s) {
                    (Some(c), Some(d), Some(s)) => Some((c, d, s)),
                    _ => None,
                });
            }
            k += run;
        }
    }

    /// The colour buffer as bottom-up rows (GL window order), `width * height` pixels.
    #[cfg(test)]
    pub fn color_rows(&self) -> Vec<[u8; 4]> {
        let (w, h) = (self.width as usize, self.height as usize);
        let mut out = Vec::with_capacity(w * h);
        for y in 0..h {
            self.extend_with_row(ColorBuf::Main, y, &mut out);
        }
        out
    }

    /// The main colour buffer as RGBA8 bytes, top row first (image order).
    #[cfg(test)]
    pub fn color_bytes_top_down(&self) -> Vec<u8> {
        self.bytes_top_down(ColorBuf::Main)
    }

    /// Colour buffer `buf` as RGBA8 bytes, top row first (image order): the bytes of
    /// [`Framebuffer::extend_with_row`] for each row, top-down, built by whole copies. Each band
    /// of rows one tile high is read with its tiles' pending clears looked up once; a tile's row
    /// in memory is one slice copy, and a run of tiles whose clear is pending is, in the band's
    /// first row, its colour repeated and, in the band's other rows, one copy of the same bytes
    /// of the row above (a band of pending tiles only: each row one copy of the row above).
    pub fn bytes_top_down(&self, buf: ColorBuf) -> Vec<u8> {
        let (w, h) = (self.width as usize, self.height as usize);
        let mut out: Vec<u8> = Vec::with_capacity(w * h * 4);
        let src = self.buffer(buf);
        let front = matches!((buf, &self.front), (ColorBuf::Front, Some(_)));
        // Per tile of the band: its pending colour, or `None` (read from memory).
        let mut fills: Vec<Option<[u8; 4]>> = Vec::with_capacity(self.tiles_x);
        for ty in (0..self.tiles_y).rev() {
            fills.clear();
            fills.extend((0..self.tiles_x).map(|tx| {
                let fill = self
                    .pending
                    .get(ty * self.tiles_x + tx)
                    .copied()
                    .unwrap_or_default();
                if front {
                    fill.front
                } else {
                    fill.main
                }
            }));
            let rows = (ty * TILE..h.min((ty + 1) * TILE)).rev();
            let first = out.len();
            for y in rows {
                let row = ty * self.tiles_x * TILE_PIXELS + (y % TILE) * TILE;
                // Where the row above in this band starts in `out` (none in its first row).
                let above = (out.len() > first).then(|| out.len() - w * 4);
                let mut tx = 0;
                while tx < self.tiles_x {
                    let x0 = tx * TILE;
                    match (fills.get(tx).copied().flatten(), above) {
                        (None, _) => {
                            let at = row + tx * TILE_PIXELS;
                            let n = (w - x0).min(TILE);
                            if let Some(px) = src.get(at..at + n) {
                                out.extend_from_slice(px.as_flattened());
                            }
                            tx += 1;
                        }
                        (Some(c), None) => {
                            let n = (w - x0).min(TILE);
                            out.extend_from_slice([c; TILE][..n].as_flattened());
                            tx += 1;
                        }
                        (Some(_), Some(a)) => {
                            // The run of pending tiles from tx: the same bytes as the row above.
                            let mut end = tx + 1;
                            while fills.get(end).copied().flatten().is_some() {
                                end += 1;
                            }
                            let x1 = w.min(end * TILE);
                            let r = a + x0 * 4..a + x1 * 4;
                            if r.end <= out.len() {
                                out.extend_from_within(r);
                            }
                            tx = end;
                        }
                    }
                }
            }
        }
        debug_assert_eq!(out.len(), w * h * 4, "readback of the wrong size");
        out
    }

    /// Appends row `y` (< height) of colour buffer `buf` to `out`: one slice copy per tile, or
    /// the tile's pending clear colour (which stays pending). The statement of what
    /// [`Framebuffer::bytes_top_down`] reads, row by row.
    #[cfg(test)]
    fn extend_with_row(&self, buf: ColorBuf, y: usize, out: &mut Vec<[u8; 4]>) {
        let src = self.buffer(buf);
        let front = matches!((buf, &self.front), (ColorBuf::Front, Some(_)));
        let w = self.width as usize;
        let trow = (y / TILE) * self.tiles_x;
        let row = trow * TILE_PIXELS + (y % TILE) * TILE;
        for tx in 0..self.tiles_x {
            let at = row + tx * TILE_PIXELS;
            let n = (w - tx * TILE).min(TILE);
            let fill = self.pending.get(trow + tx).copied().unwrap_or_default();
            match if front { fill.front } else { fill.main } {
                Some(c) => out.resize(out.len() + n, c),
                None => {
                    if let Some(px) = src.get(at..at + n) {
                        out.extend_from_slice(px);
                    }
                }
            }
        }
    }

    /// Writes every pending clear into the buffers: what any code that reads or writes the
    /// buffers' memory directly (not through the rasteriser or readback) calls first.
    pub fn materialize_all(&mut self) {
        if !self.any_pending {
            return;
        }
        let n = self.pending.len();
        let mains = tile_slices(Some(&mut self.color), n);
        let fronts = tile_slices(self.front.as_mut(), n);
        for ((((fill, main), front), depth), stencil) in self
            .pending
            .iter_mut()
            .zip(mains)
            .zip(fronts)
            .zip(self.depth.chunks_mut(TILE_PIXELS))
            .zip(self.stencil.chunks_mut(TILE_PIXELS))
        {
            if !fill.is_empty() {
                fill.materialize(main, front, depth, stencil);
            }
        }
        self.any_pending = false;
    }

    /// Writes the pending clears of the tiles the inclusive pixel rectangle `[x0, y0, x1, y1]`
    /// reaches (cut to the framebuffer) into the buffers, leaving the other tiles' pending:
    /// what a write of that rectangle straight into the buffers' memory (DrawPixels, Bitmap)
    /// calls first.
    pub fn materialize_rect(&mut self, [x0, y0, x1, y1]: [i32; 4]) {
        if !self.any_pending {
            return;
        }
        let (w, h) = (self.width as i32, self.height as i32);
        let (x0, y0, x1, y1) = (x0.max(0), y0.max(0), x1.min(w - 1), y1.min(h - 1));
        if x0 > x1 || y0 > y1 {
            return;
        }
        let (cols, rows) = (
            x0 as usize / TILE..=x1 as usize / TILE,
            y0 as usize / TILE..=y1 as usize / TILE,
        );
        for ty in rows {
            for tx in cols.clone() {
                let t = ty * self.tiles_x + tx;
                let Some(fill) = self.pending.get_mut(t).filter(|f| !f.is_empty()) else {
                    continue;
                };
                let r = t * TILE_PIXELS..(t + 1) * TILE_PIXELS;
                let main = self.color.get_mut(r.clone());
                let front = self.front.as_mut().and_then(|f| f.get_mut(r.clone()));
                if let (Some(d), Some(s)) = (self.depth.get_mut(r.clone()), self.stencil.get_mut(r))
                {
                    fill.materialize(main, front, d, s);
                }
            }
        }
    }

    /// `glClear` (GL 2.1 §4.2.3): the buffers named in `mask` (colour: those DRAW_BUFFER
    /// names), inside the scissor box when the scissor test is enabled, through ColorMask /
    /// DepthMask / StencilMask. A depth or stencil bit without that buffer clears nothing.
    pub fn clear(&mut self, state: &State, mask: u32) {
        let [x0, y0, x1, y1] = scissor_rect(state);
        if x0 > x1 || y0 > y1 {
            return;
        }
        let targets = Targets::of(state);
        let color = (mask & crate::gl::COLOR_BUFFER_BIT != 0 && !targets.none()).then(|| {
            let c = state.clear_color.clamp(glam::Vec4::ZERO, glam::Vec4::ONE);
            [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)]
        });
        let mut cmask = state.color_mask;
        // Without alpha bits the stored alpha is 255 and stays so: writing 255 leaves a
        // colour-only clear whole-tile lazy.
        let color = match self.config.alpha {
            true => color,
            false => {
                cmask[3] = true;
                color.map(|[r, g, b, _]| [r, g, b, 255])
            }
        };
        let depth =
            (mask & crate::gl::DEPTH_BUFFER_BIT != 0 && state.depth_mask && self.config.depth)
                .then(|| depth_unorm(state.clear_depth.clamp(0.0, 1.0)));
        let smask = (state.stencil_writemask & 0xFF) as u8;
        let stencil =
            (mask & crate::gl::STENCIL_BUFFER_BIT != 0 && smask != 0 && self.config.stencil)
                .then_some((state.clear_stencil & 0xFF) as u8);
        if color.is_none() && depth.is_none() && stencil.is_none() {
            return;
        }
        let tiles_x = self.tiles_x;
        let n = self.tiles_x * self.tiles_y;
        let (w, h) = (self.width as i32, self.height as i32);
        let front_exists = self.front.is_some();
        // Tiles whose part inside the window the clear covers whole, with full write masks,
        // are only marked (lazy clear); the others are written now, below.
        let lazy_ok =
            (color.is_none() || cmask == [true; 4]) && (stencil.is_none() || smask == 0xFF);
        let mut eager = Vec::new();
        for (t, fill) in self.pending.iter_mut().enumerate() {
            let (ox, oy) = (((t % tiles_x) * TILE) as i32, ((t / tiles_x) * TILE) as i32);
            let (tx0, ty0) = (x0.max(ox), y0.max(oy));
            let (tx1, ty1) = (x1.min(ox + TILE as i32 - 1), y1.min(oy + TILE as i32 - 1));
            if tx0 > tx1 || ty0 > ty1 {
                continue;
            }
            let whole = tx0 == ox
                && ty0 == oy
                && tx1 >= (ox + TILE as i32 - 1).min(w - 1)
                && ty1 >= (oy + TILE as i32 - 1).min(h - 1);
            if !(whole && lazy_ok) {
                eager.resize(n, false);
                if let Some(e) = eager.get_mut(t) {
                    *e = true;
                }
                continue;
            }
            if let Some(c) = color {
                if targets.main {
                    fill.main = Some(c);
                }
                if targets.front && front_exists {
                    fill.front = Some(c);
                }
            }
            if depth.is_some() {
                fill.depth = depth;
            }
            if stencil.is_some() {
                fill.stencil = stencil;
            }
            self.any_pending = true;
        }
        if eager.is_empty() {
            return;
        }
        let mains = tile_slices(Some(&mut self.color), n);
        let fronts = tile_slices(self.front.as_mut(), n);
        // Tiles in parallel, each clearing its part of the rectangle (after writing what was
        // pending there).
        mains
            .into_par_iter()
            .zip(fronts)
            .zip(self.depth.par_chunks_mut(TILE_PIXELS))
            .zip(self.stencil.par_chunks_mut(TILE_PIXELS))
            .zip(self.pending.par_iter_mut())
            .enumerate()
            .for_each(|(t, ((((mut cbuf, mut fbuf), dbuf), sbuf), fill))| {
                if !eager.get(t).copied().unwrap_or(false) {
                    return;
                }
                if !fill.is_empty() {
                    fill.materialize(cbuf.as_deref_mut(), fbuf.as_deref_mut(), dbuf, sbuf);
                }
                let (ox, oy) = (((t % tiles_x) * TILE) as i32, ((t / tiles_x) * TILE) as i32);
                let (tx0, ty0) = (x0.max(ox), y0.max(oy));
                let (tx1, ty1) = (x1.min(ox + TILE as i32 - 1), y1.min(oy + TILE as i32 - 1));
                if tx0 > tx1 || ty0 > ty1 {
                    return;
                }
                let cbuf = cbuf.filter(|_| targets.main);
                let fbuf = fbuf.filter(|_| targets.front);
                // Rows inside a tile are contiguous: a span as wide as the tile covers all the
                // rows at once.
                let full = tx0 == ox && tx1 == ox + TILE as i32 - 1;
                let rows = if full { ty0..=ty0 } else { ty0..=ty1 };
                let (mut cbuf, mut fbuf) = (cbuf, fbuf);
                for y in rows {
                    let row = (y - oy) as usize * TILE;
                    let (a, b) = if full {
                        (row, (ty1 - oy) as usize * TILE + TILE - 1)
                    } else {
                        (row + (tx0 - ox) as usize, row + (tx1 - ox) as usize)
                    };
                    if let Some(c) = color {
                        for buf in [cbuf.as_deref_mut(), fbuf.as_deref_mut()]
                            .into_iter()
                            .flatten()
                        {
                            let Some(px) = buf.get_mut(a..=b) else {
                                continue;
                            };
                            if cmask == [true; 4] {
                                px.fill(c);
                            } else {
                                for p in px {
                                    for k in 0..4 {
                                        if cmask[k] {
                                            p[k] = c[k];
                                        }
                                    }
                                }
                            }
                        }
                    }
                    if let (Some(d), Some(px)) = (depth, dbuf.get_mut(a..=b)) {
                        px.fill(d);
                    }
                    if let (Some(sv), Some(px)) = (stencil, sbuf.get_mut(a..=b)) {
                        if smask == 0xFF {
                            px.fill(sv);
                        } else {
                            for p in px {
                                *p = (*p & !smask) | (sv & smask);
                            }
                        }
                    }
                }
            });
    }
}

impl Framebuffer {
    /// `glAccum(op, value)` (GL 2.1 §4.2.4) over the inclusive pixel rectangle `rect` (the
    /// window cut by the scissor box): LOAD and ACCUM read colour buffer `read`; RETURN writes
    /// the colour buffers `targets` names through `color_mask`. Nothing without an
    /// accumulation buffer. The arithmetic is [`super::accum`]'s.
    pub fn accum(
        &mut self,
        op: u32,
        value: f32,
        rect: [i32; 4],
        read: ColorBuf,
        targets: Targets,
        color_mask: [bool; 4],
    ) {
        let (w, h) = (self.width as i32, self.height as i32);
        let rect = [
            rect[0].max(0),
            rect[1].max(0),
            rect[2].min(w - 1),
            rect[3].min(h - 1),
        ];
        if rect[0] > rect[2] || rect[1] > rect[3] {
            return;
        }
        self.materialize_all();
        let Some(mut accum) = self.accum.take() else {
            return;
        };
        let tiles_x = self.tiles_x;
        let n = accum.len() / TILE_PIXELS;
        // Tiles are independent: a rectangle of more than two tiles' pixels is done on the
        // pool, tile by tile, each tile's rows as runs of contiguous pixels.
        let area = i64::from(rect[2] - rect[0] + 1) * i64::from(rect[3] - rect[1] + 1);
        let parallel = area > 2 * TILE_PIXELS as i64;
        let reached = |t: usize| tile_runs(t, tiles_x, rect).next().is_some();
        if op == crate::gl::RETURN {
            let mains = tile_slices(targets.main.then_some(&mut self.color), n);
            let fronts = match targets.front {
                true => tile_slices(self.front.as_mut(), n),
                false => tile_slices(None, n),
            };
            let jobs: Vec<_> = accum
                .chunks(TILE_PIXELS)
                .zip(mains)
                .zip(fronts)
                .enumerate()
                .filter(|(t, _)| reached(*t))
                .collect();
            type Job<'a> = (
                usize,
                (
                    (&'a [[i16; 4]], Option<&'a mut [[u8; 4]]>),
                    Option<&'a mut [[u8; 4]]>,
                ),
            );
            let work = |(t, ((acc, mut main), mut front)): Job| {
                for r in tile_runs(t, tiles_x, rect) {
                    let Some(a) = acc.get(r.clone()) else {
                        continue;
                    };
                    for dst in [main.as_deref_mut(), front.as_deref_mut()]
                        .into_iter()
                        .flatten()
                    {
                        if let Some(d) = dst.get_mut(r.clone()) {
                            super::accum::return_run(value, a, d.as_flattened_mut(), color_mask);
                        }
                    }
                }
            };
            match parallel {
                true => jobs.into_par_iter().for_each(work),
                false => jobs.into_iter().for_each(work),
            }
        } else {
            let reads = super::accum::reads_color(op);
            let src = self.buffer(read);
            let jobs: Vec<_> = accum
                .chunks_mut(TILE_PIXELS)
                .zip(src.chunks(TILE_PIXELS))
                .enumerate()
                .filter(|(t, _)| reached(*t))
                .collect();
            type Job<'a> = (usize, (&'a mut [[i16; 4]], &'a [[u8; 4]]));
            let work = |(t, (acc, color)): Job| {
                for r in tile_runs(t, tiles_x, rect) {
                    let c = match reads {
                        true => color.get(r.clone()).unwrap_or(&[]),
                        false => &[],
                    };
                    if let Some(a) = acc.get_mut(r) {
                        super::accum::apply_run(op, value, a, c.as_flattened());
                    }
                }
            };
            match parallel {
                true => jobs.into_par_iter().for_each(work),
                false => jobs.into_iter().for_each(work),
            }
        }
        self.accum = Some(accum);
    }

    /// Clear of the accumulation buffer to `value` (already converted) over the inclusive
    /// rectangle `rect` (§4.2.3: the scissor box applies; no mask does).
    pub fn clear_accum(&mut self, value: [i16; 4], rect: [i32; 4]) {
        let [x0, y0, x1, y1] = rect;
        let (w, h) = (self.width as i32, self.height as i32);
        let Some(mut accum) = self.accum.take() else {
            return;
        };
        for y in y0.max(0)..=y1.min(h - 1) {
            for x in x0.max(0)..=x1.min(w - 1) {
                let i = self.index(x as usize, y as usize);
                if let Some(a) = accum.get_mut(i) {
                    *a = value;
                }
            }
        }
        self.accum = Some(accum);
    }
}

/// The runs of tile `t`'s pixels (indices within the tile, one per row) inside the inclusive
/// rectangle `rect` (already inside the framebuffer); none when the tile is outside it.
fn tile_runs(
    t: usize,
    tiles_x: usize,
    [x0, y0, x1, y1]: [i32; 4],
) -> impl Iterator<Item = std::ops::Range<usize>> {
    let (tx, ty) = ((t % tiles_x * TILE) as i32, (t / tiles_x * TILE) as i32);
    let (lo, hi) = (x0.max(tx), x1.min(tx + TILE as i32 - 1));
    let rows = y0.max(ty)..=y1.min(ty + TILE as i32 - 1);
    // No rows when the rectangle misses the tile's columns.
    let rows = (lo <= hi).then_some(rows).into_iter().flatten();
    rows.map(move |y| {
        let row = (y - ty) as usize * TILE;
        row + (lo - tx) as usize..row + (hi - tx) as usize + 1
    })
}

/// `buf` cut into its `n` tiles, or `n` times `None` (a buffer not written): what the tile loops
/// zip with the other buffers' tiles.
pub(crate) fn tile_slices<T>(buf: Option<&mut Vec<T>>, n: usize) -> Vec<Option<&mut [T]>> {
    match buf {
        Some(b) => b.chunks_mut(TILE_PIXELS).map(Some).collect(),
        None => (0..n).map(|_| None).collect(),
    }
}

/// The pixel rectangle `[x0, y0, x1, y1]` (inclusive) that fragments may touch: the framebuffer,
/// cut by the scissor box when SCISSOR_TEST is on (GL 2.1 §4.1.2). Empty when x0 > x1 or y0 > y1.
pub fn scissor_rect(state: &State) -> [i32; 4] {
    let (w, h) = (state.width as i32, state.height as i32);
    let mut r = [0, 0, w - 1, h - 1];
    if state.enables.scissor_test {
        let [sx, sy, sw, sh] = state.scissor;
        r[0] = r[0].max(sx);
        r[1] = r[1].max(sy);
        r[2] = r[2].min(sx.saturating_add(sw).saturating_sub(1));
        r[3] = r[3].min(sy.saturating_add(sh).saturating_sub(1));
    }
    r
}

/// `n` copies of `v`, or `None` if they cannot be allocated.
fn filled<T: Clone>(n: usize, v: T) -> Option<Vec<T>> {
    let mut out = Vec::new();
    out.try_reserve_exact(n).ok()?;
    out.resize(n, v);
    Some(out)
}

/// Float colour component to unorm8 (GL 2.1 §2.14.9), clamped to [0, 1] (NaN gives 0).
///
/// fragment ops: exactly llvmpipe's conversion (and Mesa's `float_to_ubyte`, used for clears):
/// `c·(255/256)` in single precision, then rounded to a multiple of 1/256 by adding 2^15 (whose
/// ulp is 2^-8), ties to even. It is `round(255·c)` except at ties after the f32 product, where
/// it goes to even: 0.3 and 0.7 give 76 and 178, not 77 and 179 (measured against the driver).
#[inline(always)]
pub fn unorm8(c: f32) -> u8 {
    // NaN gives 0 (`clamp` would keep it).
    let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
    let t = c * (255.0 / 256.0) + 32768.0;
    (t.to_bits() & 0xFF) as u8
}

/// Window z in [0, 1] to the 24-bit depth buffer value, round-to-nearest (GL 2.1 §2.11.1).
#[inline(always)]
pub fn depth_unorm(z: f64) -> u32 {
    (z.clamp(0.0, 1.0) * f64::from(DEPTH_MAX) + 0.5) as u32
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::gl;
    use glam::Vec4;

    const RED: [u8; 4] = [255, 0, 0, 255];
    const BLUE: [u8; 4] = [0, 0, 255, 255];

    /// 130x70 pixels: 3x2 tiles, the right and top ones partly outside the window.
    fn cleared() -> (Framebuffer, State) {
        let mut fb = Framebuffer::new(130, 70);
        let mut st = State::new(130, 70);
        st.clear_color = Vec4::new(1.0, 0.0, 0.0, 1.0);
        st.clear_depth = 0.5;
        fb.clear(&st, gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        (fb, st)
    }

    #[test]
    fn clear_covers_whole_and_partial_tiles() {
        let (mut fb, mut st) = cleared();
        // Depth 0.5 → 0.5·(2^24 − 1) + 0.5 = 8388608, in every tile.
        for (x, y) in [(0, 0), (63, 63), (64, 0), (129, 69), (0, 69), (128, 64)] {
            assert_eq!(fb.pixel(x, y), Some((RED, 8_388_608, 0)), "({x}, {y})");
        }
        // A scissor box x 60..=69, y 60..=64 across four tiles.
        st.enables.scissor_test = true;
        st.scissor = [60, 60, 10, 5];
        st.clear_color = Vec4::new(0.0, 0.0, 1.0, 1.0);
        st.clear_stencil = 3;
        fb.clear(&st, gl::COLOR_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
        for (x, y) in [(60, 60), (69, 64), (63, 63), (64, 64)] {
            assert_eq!(fb.pixel(x, y), Some((BLUE, 8_388_608, 3)), "({x}, {y})");
        }
        for (x, y) in [(59, 60), (70, 64), (65, 65), (64, 59)] {
            assert_eq!(fb.pixel(x, y), Some((RED, 8_388_608, 0)), "({x}, {y})");
        }
    }

    /// A whole-window clear is only marked; a masked clear over it writes the pending value
    /// first, and every read sees the same pixels as eager clears would give.
    #[test]
    fn lazy_clear_is_materialised_before_a_masked_clear() {
        let (mut fb, mut st) = cleared();
        assert!(fb.any_pending && fb.pending.iter().all(|f| !f.is_empty()));
        st.color_mask = [false, true, true, true];
        st.clear_color = Vec4::new(0.0, 0.0, 1.0, 1.0);
        fb.clear(&st, gl::COLOR_BUFFER_BIT);
        let mixed = [255, 0, 255, 255];
        for (x, y) in [(0, 0), (129, 69), (64, 64)] {
            assert_eq!(fb.pixel(x, y), Some((mixed, 8_388_608, 0)), "({x}, {y})");
        }
        // A tile written eagerly has nothing pending left.
        assert!(fb.pending[0].is_empty());
        fb.materialize_all();
        assert!(fb.pending.iter().all(Fill::is_empty));
        let i = fb.index(129, 69);
        assert_eq!((fb.color[i], fb.depth[i]), (mixed, 8_388_608));
        assert_eq!(fb.color_bytes_top_down()[..4], mixed);
    }

    /// A double-buffered 130x70 framebuffer whose front buffer holds a materialised green clear,
    /// whose back buffer a pending red one (depth 0.25, stencil 9), and a scissored clear
    /// (60, 10, 20x50) written eagerly into part of some tiles: the mix of pending and written
    /// tiles the readers must agree on.
    pub(crate) fn pending_clears_fixture() -> Framebuffer {
        let config = ContextConfig {
            double_buffered: true,
            ..ContextConfig::default()
        };
        let mut fb = Framebuffer::try_new(130, 70, config).expect("a test framebuffer");
        let mut st = State::new(130, 70);
        st.config = config;
        let all = gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT;
        st.clear_color = Vec4::new(0.0, 1.0, 0.0, 1.0);
        fb.clear(&st, all);
        fb.swap();
        st.clear_color = Vec4::new(1.0, 0.0, 0.0, 1.0);
        st.clear_depth = 0.25;
        st.clear_stencil = 9;
        fb.clear(&st, all);
        st.enables.scissor_test = true;
        st.scissor = [60, 10, 20, 50];
        st.clear_color = Vec4::new(0.0, 0.5, 1.0, 1.0);
        st.clear_depth = 0.75;
        st.clear_stencil = 4;
        fb.clear(&st, all);
        fb
    }

    /// `pixels_in` gives `pixel_in`'s values for spans that start and end outside the
    /// framebuffer, cross tiles with and without pending clears, and read either colour buffer.
    #[test]
    fn pixels_in_is_pixel_in_per_pixel() {
        let fb = pending_clears_fixture();
        for buf in [ColorBuf::Main, ColorBuf::Front] {
            for y in [-1i64, 0, 10, 33, 63, 64, 69, 70] {
                for (x, n) in [
                    (-5i64, 20usize),
                    (0, 130),
                    (50, 30),
                    (120, 40),
                    (-3, 200),
                    (131, 4),
                ] {
                    let mut got = Vec::new();
                    fb.pixels_in(buf, x, y, n, |p| got.push(p));
                    let want: Vec<_> = (0..n as i64).map(|k| fb.pixel_in(buf, x + k, y)).collect();
                    assert_eq!(got, want, "{buf:?} y {y} x {x} n {n}");
                }
            }
        }
    }

    /// `bytes_top_down` is `extend_with_row` of every row, top-down, for random sizes (within
    /// one tile, across tiles, partial edge tiles), random memory and random pending clears
    /// per tile and buffer (runs of pending tiles of one colour and of different colours),
    /// reading either colour buffer.
    #[test]
    fn bytes_top_down_is_the_rows_top_down() {
        let mut g = crate::cpu::testgen::Gen(7);
        for case in 0..300 {
            let (w, h) = match case % 4 {
                0 => (1 + (g.next() % 64) as u32, 1 + (g.next() % 64) as u32),
                _ => (1 + (g.next() % 300) as u32, 1 + (g.next() % 200) as u32),
            };
            let config = ContextConfig {
                double_buffered: g.next() % 2 == 0,
                ..ContextConfig::default()
            };
            let mut fb = Framebuffer::try_new(w, h, config).expect("a test framebuffer");
            for p in fb.color.iter_mut() {
                *p = (g.next() as u32).to_le_bytes();
            }
            if let Some(f) = fb.front.as_mut() {
                for p in f.iter_mut() {
                    *p = (g.next() as u32).to_le_bytes();
                }
            }
            // A few colours, so that neighbouring pending tiles often share one.
            let colours = [[1, 2, 3, 4], [9, 8, 7, 6], (g.next() as u32).to_le_bytes()];
            let density = g.next() % 5;
            for fill in fb.pending.iter_mut() {
                for slot in [&mut fill.main, &mut fill.front] {
                    if g.next() % 4 < density {
                        *slot = Some(colours[(g.next() % 3) as usize]);
                    }
                }
            }
            fb.any_pending = true;
            for buf in [ColorBuf::Main, ColorBuf::Front] {
                let mut want = Vec::new();
                for y in (0..h as usize).rev() {
                    fb.extend_with_row(buf, y, &mut want);
                }
                assert_eq!(
                    fb.bytes_top_down(buf),
                    want.as_flattened(),
                    "case {case}: {w}x{h} {buf:?}"
                );
            }
        }
    }

    /// `materialize_rect` writes exactly the pending clears of the tiles the rectangle
    /// reaches (rectangles partly or wholly outside the framebuffer included) and changes no
    /// pixel's value.
    #[test]
    fn materialize_rect_writes_the_tiles_reached() {
        let config = ContextConfig {
            double_buffered: true,
            ..ContextConfig::default()
        };
        let all = gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT;
        for rect in [
            [0, 0, 0, 0],
            [63, 63, 64, 64],
            [70, 10, 129, 20],
            [-40, -5, 5, 200],
            [129, 69, 500, 500],
            [130, 0, 140, 10],
            [-10, -10, -1, 80],
            [5, 5, 4, 9],
        ] {
            let mut fb = Framebuffer::try_new(130, 70, config).expect("a test framebuffer");
            let mut st = State::new(130, 70);
            st.config = config;
            st.clear_color = Vec4::new(0.0, 1.0, 0.0, 1.0);
            st.clear_depth = 0.25;
            st.clear_stencil = 5;
            fb.clear(&st, all);
            let before: Vec<_> = (0..70)
                .flat_map(|y| (0..130).map(move |x| (x, y)))
                .map(|(x, y)| {
                    (
                        fb.pixel_in(ColorBuf::Main, x, y),
                        fb.pixel_in(ColorBuf::Front, x, y),
                    )
                })
                .collect();
            let pending = fb.pending.clone();
            fb.materialize_rect(rect);
            let after: Vec<_> = (0..70)
                .flat_map(|y| (0..130).map(move |x| (x, y)))
                .map(|(x, y)| {
                    (
                        fb.pixel_in(ColorBuf::Main, x, y),
                        fb.pixel_in(ColorBuf::Front, x, y),
                    )
                })
                .collect();
            assert_eq!(before, after, "{rect:?}");
            let [x0, y0, x1, y1] = rect;
            for (t, (now, was)) in fb.pending.iter().zip(&pending).enumerate() {
                let (ox, oy) = ((t % 3) as i32 * 64, (t / 3) as i32 * 64);
                let reached = x0.max(0).max(ox) <= x1.min(129).min(ox + 63)
                    && y0.max(0).max(oy) <= y1.min(69).min(oy + 63);
                match reached {
                    true => assert!(now.is_empty(), "{rect:?} tile {t}"),
                    false => assert_eq!(now, was, "{rect:?} tile {t}"),
                }
            }
        }
    }

    #[test]
    fn colour_rows_in_both_orders() {
        let (mut fb, mut st) = cleared();
        // One blue pixel at (65, 64): tile (1, 1).
        st.enables.scissor_test = true;
        st.scissor = [65, 64, 1, 1];
        st.clear_color = Vec4::new(0.0, 0.0, 1.0, 1.0);
        fb.clear(&st, gl::COLOR_BUFFER_BIT);
        let up = fb.color_rows();
        assert_eq!(up.len(), 130 * 70);
        assert_eq!(up[64 * 130 + 65], BLUE);
        assert_eq!(up.iter().filter(|&&c| c == BLUE).count(), 1);
        let down = fb.color_bytes_top_down();
        assert_eq!(down.len(), 130 * 70 * 4);
        // Row 64 from the bottom is row 70 − 1 − 64 = 5 from the top.
        let at = (5 * 130 + 65) * 4;
        assert_eq!(down[at..at + 4], BLUE);
        assert_eq!(down.chunks(4).filter(|&c| c == BLUE).count(), 1);
    }
}
