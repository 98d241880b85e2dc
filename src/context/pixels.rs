//! Pixel rectangles and bitmaps: `PixelZoom`, `PixelTransfer`, `PixelMap`, `GetPixelMap`
//! (GL 2.1 §3.6.3, §3.6.5, §6.1.3), `DrawPixels` (§3.6.4), `Bitmap` (§3.7) and `CopyPixels`
//! (§4.3.3).
//!
//! DrawPixels unpacks the client's groups under the unpack modes (`crate::pixels`), puts them
//! through the pixel transfer and hands them to the CPU pipeline as fragments at the rounded
//! raster position (`cpu::pixels`). Bitmap draws its set bits in the raster colour at
//! floor(raster position − origin) and then moves the raster position by (xmove, ymove).
//! CopyPixels reads a rectangle of the framebuffer as ReadPixels would (through the transfer)
//! and draws it as DrawPixels would. Nothing is drawn while the raster position is invalid (and
//! Bitmap then does not move it either).
//!
//! Design decisions: where GL leaves the placement open, it is Mesa's. The raster position is
//! rounded half away from zero for DrawPixels and CopyPixels (`lroundf`), and Bitmap's corner is
//! floor(x + 0.0001 − xorig) (`_mesa_Bitmap`'s epsilon). Errors come in Mesa's order: INVALID_OPERATION
//! between Begin and End, INVALID_VALUE for a negative size, then the format and type
//! (`pixels::check`), then a client slice shorter than the unpack modes say the image spans,
//! INVALID_OPERATION as for TexImage2D. A display list holds DrawPixels and Bitmap with their
//! groups unpacked at compile time (§5.4): the list stores them tightly packed (alignment 1, no
//! skips, host byte order, most significant bit first), and a call executed from a list reads
//! them so.

use super::Context;
use crate::call::Call;
use crate::cpu::framebuffer::unorm8;
use crate::cpu::pixels::{spans, Groups, PixelDraw, Span};
use crate::gl;
use crate::pixel_store::PixelModes;
use crate::pixels::{
    self, check, is_index_map, map_index, Group, Image, TransferParam, MAX_PIXEL_MAP_TABLE, TIGHT,
};

/// Rounds half away from zero, as C's `lroundf` (saturating).
fn lround(v: f32) -> i32 {
    v.round() as i32
}

/// How a value of a PixelMapuiv/usv colour table converts (table 2.9, as Mesa: `UINT_TO_FLOAT`
/// and `USHORT_TO_FLOAT`).
trait MapValue: Copy {
    fn index(self) -> f32;
    fn color(self) -> f32;
}

impl MapValue for f32 {
    fn index(self) -> f32 {
        self
    }
    fn color(self) -> f32 {
        self
    }
}

impl MapValue for u32 {
    fn index(self) -> f32 {
        self as f32
    }
    fn color(self) -> f32 {
        (f64::from(self) * (1.0 / f64::from(u32::MAX))) as f32
    }
}

impl MapValue for u16 {
    fn index(self) -> f32 {
        f32::from(self)
    }
    fn color(self) -> f32 {
        f32::from(self) * (1.0 / 65535.0)
    }
}

impl Context {
    /// The unpack modes a DrawPixels or Bitmap reads its data under: the state's, or, for a call
    /// executed from a display list, those of the list's tightly packed copy.
    fn unpack_modes(&self) -> PixelModes {
        if self.lists.depth > 0 {
            TIGHT
        } else {
            self.state.unpack
        }
    }

    /// `glPixelZoom`: the zoom factors of DrawPixels and CopyPixels (§3.6.5); any floats.
    pub fn pixel_zoom(&mut self, xfactor: f32, yfactor: f32) {
        record!(self, Call::PixelZoom(xfactor, yfactor));
        if !self.outside_begin_end() {
            return;
        }
        self.state.pixel.zoom = [xfactor, yfactor];
    }

    /// `glPixelTransferf`: one parameter of table 3.2 (INVALID_ENUM for another pname, the
    /// imaging subset's included). MAP_COLOR and MAP_STENCIL are TRUE for any nonzero value;
    /// INDEX_SHIFT and INDEX_OFFSET take the value truncated, as Mesa does.
    pub fn pixel_transferf(&mut self, pname: u32, param: f32) {
        record!(self, Call::PixelTransferf(pname, param));
        self.pixel_transfer(pname, param);
    }

    /// `glPixelTransferi`: as [`Context::pixel_transferf`] with the integer as a float.
    pub fn pixel_transferi(&mut self, pname: u32, param: i32) {
        record!(self, Call::PixelTransferi(pname, param));
        self.pixel_transfer(pname, param as f32);
    }

    fn pixel_transfer(&mut self, pname: u32, param: f32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(p) = TransferParam::of(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        self.state.pixel.set(p, param);
    }

    /// `glPixelMapfv`: loads the first `mapsize` of `values` into pixel map `map` (§3.6.3).
    /// INVALID_VALUE when `mapsize` is outside 1..=MAX_PIXEL_MAP_TABLE, when `values` holds fewer
    /// than `mapsize` values (a Rust-API rule: C cannot tell), or when an index map (I_TO_I,
    /// S_TO_S, I_TO_R, I_TO_G, I_TO_B, I_TO_A) gets a size that is not a power of two; then
    /// INVALID_ENUM for a `map` that is none of the ten. Colour tables keep their values clamped
    /// to [0, 1]; S_TO_S rounds to integers (as Mesa).
    pub fn pixel_mapfv(&mut self, map: u32, mapsize: i32, values: &[f32]) {
        let kept = values.get(..mapsize.max(0) as usize).unwrap_or(values);
        record!(self, Call::PixelMapfv(map, mapsize, kept.to_vec()));
        self.pixel_map(map, mapsize, values);
    }

    /// `glPixelMapuiv`: as [`Context::pixel_mapfv`]; colour tables take c / (2³² − 1), index
    /// tables the integers.
    pub fn pixel_mapuiv(&mut self, map: u32, mapsize: i32, values: &[u32]) {
        let kept = values.get(..mapsize.max(0) as usize).unwrap_or(values);
        record!(self, Call::PixelMapuiv(map, mapsize, kept.to_vec()));
        self.pixel_map(map, mapsize, values);
    }

    /// `glPixelMapusv`: as [`Context::pixel_mapfv`]; colour tables take c / (2¹⁶ − 1).
    pub fn pixel_mapusv(&mut self, map: u32, mapsize: i32, values: &[u16]) {
        let kept = values.get(..mapsize.max(0) as usize).unwrap_or(values);
        record!(self, Call::PixelMapusv(map, mapsize, kept.to_vec()));
        self.pixel_map(map, mapsize, values);
    }

    fn pixel_map<T: MapValue>(&mut self, map: u32, mapsize: i32, values: &[T]) {
        if !self.outside_begin_end() {
            return;
        }
        let size = match usize::try_from(mapsize) {
            Ok(n @ 1..=MAX_PIXEL_MAP_TABLE) if values.len() >= n => n,
            _ => return self.error(gl::INVALID_VALUE),
        };
        let index = map_index(map);
        if let Some(k) = index {
            // GL 2.1 §3.6.3: the index maps' sizes are powers of two.
            if k < 6 && !size.is_power_of_two() {
                return self.error(gl::INVALID_VALUE);
            }
        }
        let Some(k) = index else {
            return self.error(gl::INVALID_ENUM);
        };
        let table: Vec<f32> = values
            .iter()
            .take(size)
            .map(|&v| {
                if !is_index_map(k) {
                    let c = v.color();
                    if c.is_nan() {
                        0.0
                    } else {
                        c.clamp(0.0, 1.0)
                    }
                } else if map == gl::PIXEL_MAP_S_TO_S {
                    v.index().round()
                } else {
                    v.index()
                }
            })
            .collect();
        let maps = std::sync::Arc::make_mut(&mut self.state.pixel_maps);
        maps.tables[k] = table;
    }

    /// The table of `map` for GetPixelMap: INVALID_OPERATION between Begin and End,
    /// INVALID_ENUM for a bad map, INVALID_VALUE when `len` (the caller's slice) is shorter than
    /// the table.
    fn pixel_map_table(&mut self, map: u32, len: usize) -> Option<(usize, Vec<f32>)> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let Some(k) = map_index(map) else {
            self.error(gl::INVALID_ENUM);
            return None;
        };
        let t = self.state.pixel_maps.tables[k].clone();
        if len < t.len() {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some((k, t))
    }

    /// `glGetPixelMapfv`: the table of `map` into the front of `values` (PIXEL_MAP_*_SIZE of
    /// them; a shorter slice is INVALID_VALUE with nothing written).
    pub fn get_pixel_mapfv(&mut self, map: u32, values: &mut [f32]) {
        if let Some((_, t)) = self.pixel_map_table(map, values.len()) {
            values[..t.len()].copy_from_slice(&t);
        }
    }

    /// `glGetPixelMapuiv`: colour tables as c · (2³² − 1) truncated (as the driver's
    /// `FLOAT_TO_UINT`), index tables as integers (truncated, saturating).
    pub fn get_pixel_mapuiv(&mut self, map: u32, values: &mut [u32]) {
        if let Some((k, t)) = self.pixel_map_table(map, values.len()) {
            for (o, v) in values.iter_mut().zip(t) {
                *o = if is_index_map(k) {
                    v as u32
                } else {
                    (f64::from(v) * f64::from(u32::MAX)) as u32
                };
            }
        }
    }

    /// `glGetPixelMapusv`: colour tables as c · (2¹⁶ − 1) rounded, index tables as integers
    /// (truncated, saturating).
    pub fn get_pixel_mapusv(&mut self, map: u32, values: &mut [u16]) {
        if let Some((k, t)) = self.pixel_map_table(map, values.len()) {
            for (o, v) in values.iter_mut().zip(t) {
                *o = if is_index_map(k) {
                    v as u16
                } else {
                    (f64::from(v) * 65535.0).round() as u16
                };
            }
        }
    }

    /// `glBitmap`: draws the bits of `bitmap` set to 1 as fragments of the raster colour at the
    /// raster depth, with its lower-left corner at floor(raster position − (xorig, yorig)), then
    /// moves the raster position by (xmove, ymove) (§3.7). `None` (C's NULL) draws nothing and
    /// still moves it. Nothing at all while the raster position is invalid. Errors:
    /// INVALID_OPERATION between Begin and End, INVALID_VALUE for a negative size,
    /// INVALID_OPERATION when `bitmap` is shorter than the unpack modes say it spans.
    #[allow(clippy::too_many_arguments)]
    pub fn bitmap(
        &mut self,
        width: i32,
        height: i32,
        xorig: f32,
        yorig: f32,
        xmove: f32,
        ymove: f32,
        bitmap: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::Bitmap(
                width,
                height,
                xorig,
                yorig,
                xmove,
                ymove,
                Box::new(bitmap.map(<[u8]>::to_vec))
            )
        );
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        // The bits: a slice shorter than the unpack modes say the bitmap spans is an error
        // (checked whatever the raster position, as DrawPixels' data).
        let bits = match bitmap {
            Some(data) if width > 0 && height > 0 => {
                match self
                    .unpack_modes()
                    .bitmap_layout(width, height)
                    .filter(|l| data.len() >= l.need)
                {
                    Some(layout) => Some((data, layout)),
                    None => return self.error(gl::INVALID_OPERATION),
                }
            }
            _ => None,
        };
        if self.framebuffer_incomplete() {
            return;
        }
        if !self.state.raster_pos.valid {
            return;
        }
        // FEEDBACK and SELECT modes draw nothing (a token in FEEDBACK); the position moves.
        let render = self.raster_rect_token(gl::BITMAP_TOKEN);
        if let Some((data, layout)) = bits.filter(|_| render) {
            let (w, h) = (width as usize, height as usize);
            const EPSILON: f32 = 0.0001;
            let r = self.state.raster_pos.window;
            let x = (r.x + EPSILON - xorig).floor() as i32;
            let y = (r.y + EPSILON - yorig).floor() as i32;
            let (cols, rows) = spans(&self.state, x, y, w, h, [1.0, 1.0]);
            let (gi, gj, cols, rows) = compact(cols, rows);
            // The columns are one run (zoom 1: always), taken a byte at a time, or any others.
            let run = gi
                .first()
                .filter(|_| gi.windows(2).all(|p| p[0].checked_add(1) == Some(p[1])));
            let Some(bits) = gather_bits(&gi, &gj, |j, out| match run {
                Some(&i0) => layout.push_run(data, i0, gi.len(), j, out),
                None => layout.push_row(data, &gi, j, out),
            }) else {
                return self.error(gl::OUT_OF_MEMORY);
            };
            self.renderer
                .bitmap(&self.state, cols, rows, gi.len(), bits);
        }
        let r = &mut self.state.raster_pos.window;
        r.x += xmove;
        r.y += ymove;
    }

    /// `glDrawPixels`: draws `width` x `height` groups of `format`/`type_` from `pixels`
    /// (unpacked under the unpack modes, §3.6.4), through the pixel transfer (§3.6.5), zoomed, at
    /// the rounded raster position. Every GL 2.1 format: the colour formats (RED .. BGRA,
    /// LUMINANCE, LUMINANCE_ALPHA), COLOR_INDEX (made RGBA by the I_TO_* maps), DEPTH_COMPONENT
    /// (the raster colour at the groups' depths) and STENCIL_INDEX (written to the stencil buffer
    /// only); every type, BITMAP for the index formats and the packed types of GL 1.2. Errors in
    /// the module docs' order.
    pub fn draw_pixels(&mut self, width: i32, height: i32, format: u32, type_: u32, pixels: &[u8]) {
        record!(
            self,
            Call::DrawPixels(width, height, format, type_, Box::new(pixels.to_vec()))
        );
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        let f = match check(format, type_) {
            Ok(f) => f,
            Err(code) => return self.error(code),
        };
        if self.framebuffer_incomplete() {
            return;
        }
        // GL_EXT_packed_depth_stencil: DEPTH_STENCIL needs both buffers (Mesa's
        // `_mesa_dest_buffer_exists`).
        if f.group == Group::DepthStencil && !(self.state.config.depth && self.state.config.stencil)
        {
            return self.error(gl::INVALID_OPERATION);
        }
        let Some(layout) = self
            .unpack_modes()
            .image_layout(f, width, height)
            .filter(|l| pixels.len() >= l.need())
        else {
            return self.error(gl::INVALID_OPERATION);
        };
        // FEEDBACK mode writes its token even for an empty rectangle (Mesa's `_mesa_DrawPixels`).
        if !self.state.raster_pos.valid
            || !self.raster_rect_token(gl::DRAW_PIXEL_TOKEN)
            || width == 0
            || height == 0
        {
            return;
        }
        let img = Image {
            data: pixels,
            format: f,
            layout,
        };
        let (w, h) = (width as usize, height as usize);
        let t = self.state.pixel;
        let maps = std::sync::Arc::clone(&self.state.pixel_maps);
        let r = self.state.raster_pos.window;
        let (x, y) = (lround(r.x), lround(r.y));
        let (cols, rows) = spans(&self.state, x, y, w, h, t.zoom);
        if cols.is_empty() || rows.is_empty() {
            return;
        }
        // Only the groups some covered pixel takes are converted (once each, however many pixels
        // take them): the work and memory are bounded by the window, not by the image.
        let (gi, gj, cols, rows) = compact(cols, rows);
        let n = gi.len();
        let drawn = match f.group {
            // Straight to the buffer's 8 bits when nothing but the colour write follows: the
            // bytes themselves for UNSIGNED_BYTE with no transfer, the 8-bit conversion of the
            // transferred colour otherwise (one less float image to hold).
            Group::Color(_) if self.renderer.pixels_plain(&self.state) => {
                let mut out = Vec::new();
                gi.len()
                    .checked_mul(gj.len())
                    .and_then(|len| out.try_reserve_exact(len).ok())
                    .map(|()| {
                        let direct = img.bytes(&gi, &gj, &mut out).is_some();
                        if direct && !t.color_is_identity() {
                            // The transfer works on each component alone: one table per
                            // channel of the 256 bytes' results.
                            let mut lut = [[0u8; 256]; 4];
                            for v in 0..=255u8 {
                                let x = crate::pixels::unit_u8(v);
                                let c = t.color(&maps, [x; 4]).map(unorm8);
                                for (ch, table) in lut.iter_mut().enumerate() {
                                    table[usize::from(v)] = c[ch];
                                }
                            }
                            for px in &mut out {
                                *px = std::array::from_fn(|ch| lut[ch][usize::from(px[ch])]);
                            }
                        }
                        if !direct {
                            out.clear();
                            for &j in &gj {
                                for &i in &gi {
                                    let c = img.color(i, j);
                                    let c = if t.color_is_identity() {
                                        c.map(clamp01)
                                    } else {
                                        t.color(&maps, c)
                                    };
                                    out.push(c.map(unorm8));
                                }
                            }
                        }
                        self.draw_groups(cols, rows, n, Groups::Bytes(&out))
                    })
            }
            Group::Color(_) => {
                let mut out = Vec::new();
                gi.len()
                    .checked_mul(gj.len())
                    .and_then(|len| out.try_reserve_exact(len).ok())
                    .map(|()| {
                        img.colors(&gi, &gj, &mut out);
                        // The final conversion clamps (§3.6.5); the transfer clamps itself.
                        if t.color_is_identity() {
                            for c in &mut out {
                                *c = c.map(clamp01);
                            }
                        } else {
                            for c in &mut out {
                                *c = t.color(&maps, *c);
                            }
                        }
                        self.draw_groups(cols, rows, n, Groups::Color(&out))
                    })
            }
            Group::Index => gather(&gi, &gj, |i, j| t.index_to_rgba(&maps, img.index(i, j)))
                .map(|out| self.draw_groups(cols, rows, n, Groups::Color(&out))),
            Group::Depth => gather(&gi, &gj, |i, j| t.depth(img.depth(i, j)))
                .map(|out| self.draw_groups(cols, rows, n, Groups::Depth(&out))),
            Group::Stencil => gather(&gi, &gj, |i, j| t.stencil(&maps, img.index(i, j)))
                .map(|out| self.draw_groups(cols, rows, n, Groups::Stencil(&out))),
            // GL 3.0 §4.3.1: written to both buffers, as CopyPixels(DEPTH_STENCIL) writes.
            Group::DepthStencil => {
                let depths = gather(&gi, &gj, |i, j| t.depth(img.depth(i, j)));
                let indices = gather(&gi, &gj, |i, j| t.stencil(&maps, img.index(i, j)));
                depths
                    .zip(indices)
                    .map(|(d, s)| self.draw_groups(cols, rows, n, Groups::DepthStencil(&d, &s)))
            }
        };
        if drawn.is_none() {
            self.error(gl::OUT_OF_MEMORY);
        }
    }

    fn draw_groups(&mut self, cols: Span, rows: Span, width: usize, groups: Groups) {
        let d = PixelDraw {
            cols,
            rows,
            width,
            groups,
        };
        self.renderer.draw_pixel_rect(&self.state, &d, false);
    }

    /// `glCopyPixels`: copies the `width` x `height` rectangle of the framebuffer at (x, y) to
    /// the rounded raster position, as ReadPixels followed by DrawPixels would (§4.3.3): COLOR
    /// (RGBA through the colour transfer), DEPTH (the raster colour at the copied depths, through
    /// DEPTH_SCALE and DEPTH_BIAS) or STENCIL (shift, offset, MAP_STENCIL; written to the
    /// stencil buffer only), zoomed. The source is read whole before anything is written, so
    /// overlapping rectangles copy as if from a copy; pixels outside the window read as 0.
    /// DEPTH_STENCIL (GL_EXT_packed_depth_stencil) reads both buffers (depths through DEPTH_SCALE
    /// and DEPTH_BIAS, indices through the index transfer) and writes both as a DrawPixels of
    /// DEPTH_STENCIL does (GL 3.0 §4.3.1): no fragments, only the scissor test, each index
    /// through the stencil write mask and each depth when DepthMask is TRUE, the depth and
    /// stencil tests ignored; no colour.
    /// Errors: INVALID_OPERATION between Begin and End, INVALID_VALUE for a negative size,
    /// INVALID_ENUM for another type, INVALID_OPERATION for DEPTH_STENCIL without both a depth
    /// and a stencil buffer (the extension's §4.3.3 rule, Mesa's `_mesa_source_buffer_exists`).
    pub fn copy_pixels(&mut self, x: i32, y: i32, width: i32, height: i32, type_: u32) {
        record!(self, Call::CopyPixels(x, y, width, height, type_));
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if !matches!(
            type_,
            gl::COLOR | gl::DEPTH | gl::STENCIL | gl::DEPTH_STENCIL
        ) {
            return self.error(gl::INVALID_ENUM);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        if type_ == gl::DEPTH_STENCIL && !(self.state.config.depth && self.state.config.stencil) {
            return self.error(gl::INVALID_OPERATION);
        }
        // An empty rectangle writes no feedback token either (Mesa's `_mesa_CopyPixels`).
        if !self.state.raster_pos.valid
            || width == 0
            || height == 0
            || !self.raster_rect_token(gl::COPY_PIXEL_TOKEN)
        {
            return;
        }
        self.copy_rect(x, y, width, height, type_);
    }

    /// The copy of [`Context::copy_pixels`], once its errors are checked and its feedback token
    /// written (`width`, `height` > 0, raster position valid).
    fn copy_rect(&mut self, x: i32, y: i32, width: i32, height: i32, type_: u32) {
        let t = self.state.pixel;
        let maps = std::sync::Arc::clone(&self.state.pixel_maps);
        let r = self.state.raster_pos.window;
        let (dx, dy) = (lround(r.x), lround(r.y));
        // Only the part of the source inside the window matters for the work: a larger
        // rectangle reads zeros. Its size is bounded by what the zoomed destination covers.
        let (w, h) = (width as usize, height as usize);
        let (cols, rows) = spans(&self.state, dx, dy, w, h, t.zoom);
        if cols.is_empty() || rows.is_empty() {
            return;
        }
        // The groups the covered pixels take, read from the framebuffer once each.
        let (gi, gj, cols, rows) = compact(cols, rows);
        let n = gi.len();
        let fb = self.renderer.framebuffer();
        // Colour comes from the buffer READ_BUFFER names (§4.3.3).
        let buf = crate::cpu::framebuffer::read_buf(&self.state);
        let at =
            |i: usize, j: usize| fb.pixel_in(buf, i64::from(x) + i as i64, i64::from(y) + j as i64);
        let drawn = match type_ {
            gl::COLOR => {
                let identity = t.color_is_identity();
                gather(&gi, &gj, |i, j| {
                    let c = at(i, j).map_or([0.0; 4], |(c, _, _)| c.map(|v| f32::from(v) / 255.0));
                    if identity {
                        c
                    } else {
                        t.color(&maps, c)
                    }
                })
                .map(|out| self.draw_groups(cols, rows, n, Groups::Color(&out)))
            }
            gl::DEPTH => {
                let max = f64::from(crate::cpu::framebuffer::DEPTH_MAX);
                gather(&gi, &gj, |i, j| {
                    t.depth(at(i, j).map_or(0.0, |(_, d, _)| f64::from(d) / max))
                })
                .map(|out| self.draw_groups(cols, rows, n, Groups::Depth(&out)))
            }
            gl::STENCIL => gather(&gi, &gj, |i, j| {
                t.stencil(&maps, at(i, j).map_or(0, |(_, _, s)| i64::from(s)))
            })
            .map(|out| self.draw_groups(cols, rows, n, Groups::Stencil(&out))),
            // DEPTH_STENCIL: both read first, then written together.
            _ => {
                let max = f64::from(crate::cpu::framebuffer::DEPTH_MAX);
                let depths = gather(&gi, &gj, |i, j| {
                    t.depth(at(i, j).map_or(0.0, |(_, d, _)| f64::from(d) / max))
                });
                let indices = gather(&gi, &gj, |i, j| {
                    t.stencil(&maps, at(i, j).map_or(0, |(_, _, s)| i64::from(s)))
                });
                depths
                    .zip(indices)
                    .map(|(d, s)| self.draw_groups(cols, rows, n, Groups::DepthStencil(&d, &s)))
            }
        };
        if drawn.is_none() {
            self.error(gl::OUT_OF_MEMORY);
        }
    }

    /// The call a display list stores for `call` (GL 2.1 §5.4): see
    /// [`pixels::compile_unpacked`], under the current unpack modes.
    pub(crate) fn compile_pixels(&self, call: &Call) -> Option<Call> {
        pixels::compile_unpacked(&self.state.unpack, call)
    }
}

/// `v` clamped to [0, 1] (NaN gives 0): the final conversion of a colour (§3.6.5).
fn clamp01(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

/// The sorted distinct groups of `span` (the group columns or rows some covered pixel takes),
/// and the span with each pixel's group replaced by its position among them.
fn compact_span(span: Span) -> (Vec<usize>, Span) {
    // Groups that rise one by one (zoom 1) are their own keys, at positions 0, 1, ...
    if span
        .groups
        .windows(2)
        .all(|w| w[0].checked_add(1) == Some(w[1]))
    {
        let keys = span.groups.iter().map(|&g| g as usize).collect();
        // The positions overwrite the groups in place (one allocation less a call).
        let mut groups = span.groups;
        for (k, g) in groups.iter_mut().enumerate() {
            *g = k as u32;
        }
        return (
            keys,
            Span {
                lo: span.lo,
                groups,
            },
        );
    }
    let mut keys = span.groups.clone();
    keys.sort_unstable();
    keys.dedup();
    let groups = span
        .groups
        .iter()
        .map(|g| keys.binary_search(g).unwrap_or(0) as u32)
        .collect();
    let keys = keys.into_iter().map(|k| k as usize).collect();
    (
        keys,
        Span {
            lo: span.lo,
            groups,
        },
    )
}

/// [`compact_span`] of the columns and of the rows.
fn compact(cols: Span, rows: Span) -> (Vec<usize>, Vec<usize>, Span, Span) {
    let (gi, cols) = compact_span(cols);
    let (gj, rows) = compact_span(rows);
    (gi, gj, cols, rows)
}

/// `f(i, j)` for every group row `j` of `gj` and column `i` of `gi`, rows first, or None when
/// the values cannot be allocated (at most one per covered window pixel).
fn gather<T>(gi: &[usize], gj: &[usize], mut f: impl FnMut(usize, usize) -> T) -> Option<Vec<T>> {
    let mut out = Vec::new();
    out.try_reserve_exact(gi.len().checked_mul(gj.len())?)
        .ok()?;
    for &j in gj {
        for &i in gi {
            out.push(f(i, j));
        }
    }
    Some(out)
}

/// What [`gather`] gives for `f(i, j) = bit (i, j)`, a row at a time: `row(j, out)` appends
/// row `j`'s values for every column of `gi` to `out`.
fn gather_bits(
    gi: &[usize],
    gj: &[usize],
    mut row: impl FnMut(usize, &mut Vec<u8>),
) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    out.try_reserve_exact(gi.len().checked_mul(gj.len())?)
        .ok()?;
    for &j in gj {
        row(j, &mut out);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Plain bitmaps (only the colour write applies: `put_row`'s bits, a row at a time) give the
    /// pixels of the same bitmaps through the per-fragment route (`FragCtx::pixel`, taken when a
    /// depth test ALWAYS without depth writes makes the draw not plain): random glyphs under
    /// random unpack modes, positions across tile edges and off the window, colours and colour
    /// masks.
    #[test]
    fn plain_bitmap_rows_are_the_fragment_route() {
        let mut seed = 23u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        let (w, h) = (90usize, 75usize);
        let mut drew = 0;
        for case in 0..150 {
            let mut ctxs: Vec<Context> = (0..2)
                .map(|_| match Context::new(w as u32, h as u32) {
                    Ok(c) => c,
                    Err(e) => panic!("{e}"),
                })
                .collect();
            let (lsb, skip_px, skip_rows) = (next() % 2 == 1, next() % 11, next() % 3);
            let align = [1, 2, 4, 8][(next() % 4) as usize];
            let row_length = if next() % 3 == 0 { 45 } else { 0 };
            let clear =
                [next() % 256, next() % 256, next() % 256, next() % 256].map(|v| v as f32 / 255.0);
            let mask = [0, 1, 2, 3].map(|_| next() % 5 != 0);
            let draws: Vec<_> = (0..4)
                .map(|_| {
                    let (bw, bh) = (1 + next() as i32 % 40, 1 + next() as i32 % 40);
                    let pos = [
                        next() as f32 % 130.0 - 30.0 + 0.5 * (next() % 2) as f32,
                        next() as f32 % 110.0 - 30.0,
                    ];
                    let orig = [(next() % 5) as f32 - 2.0, (next() % 5) as f32 - 2.0];
                    let color = [0, 1, 2, 3].map(|_| (next() % 1001) as f32 / 1000.0);
                    let data: Vec<u8> = (0..4000).map(|_| next() as u8).collect();
                    (bw, bh, pos, orig, color, data)
                })
                .collect();
            let mut images = Vec::new();
            for (k, c) in ctxs.iter_mut().enumerate() {
                c.clear_color(clear[0], clear[1], clear[2], clear[3]);
                c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
                c.pixel_storei(gl::UNPACK_LSB_FIRST, i32::from(lsb));
                c.pixel_storei(gl::UNPACK_SKIP_PIXELS, skip_px as i32);
                c.pixel_storei(gl::UNPACK_SKIP_ROWS, skip_rows as i32);
                c.pixel_storei(gl::UNPACK_ALIGNMENT, align);
                c.pixel_storei(gl::UNPACK_ROW_LENGTH, row_length);
                c.color_mask(mask[0], mask[1], mask[2], mask[3]);
                if k == 1 {
                    c.enable(gl::DEPTH_TEST);
                    c.depth_func(gl::ALWAYS);
                    c.depth_mask(false);
                }
                for (bw, bh, pos, orig, color, data) in &draws {
                    c.color4f(color[0], color[1], color[2], color[3]);
                    c.window_pos2f(pos[0], pos[1]);
                    c.bitmap(*bw, *bh, orig[0], orig[1], 3.0, 1.0, Some(data));
                }
                let mut out = vec![0u8; w * h * 4];
                c.read_pixels(
                    0,
                    0,
                    w as i32,
                    h as i32,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    &mut out,
                );
                assert_eq!(c.get_error(), gl::NO_ERROR, "case {case}");
                images.push(out);
            }
            assert_eq!(images[0], images[1], "case {case}");
            let cleared = images[0].chunks(4).filter(|p| {
                p.iter()
                    .zip(clear)
                    .all(|(&b, c)| b == crate::cpu::framebuffer::unorm8(c))
            });
            drew += usize::from(cleared.count() < w * h);
        }
        assert!(drew > 100, "{drew} cases drew something");
    }

    /// `compact_span` gives each covered pixel the position of its group among the sorted
    /// distinct groups, for runs that rise one by one (its shortcut) and any others.
    #[test]
    fn compact_span_ranks_the_groups() {
        let mut seed = 11u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        for case in 0..2000 {
            let len = (next() % 70) as usize;
            let start = next() as u32 % 1000;
            let groups: Vec<u32> = match case % 3 {
                0 => (start..start + len as u32).collect(),
                1 => (0..len).map(|_| next() as u32 % 40).collect(),
                _ => (0..len)
                    .map(|k| start + k as u32 + u32::from(next() % 9 == 0))
                    .collect(),
            };
            let span = Span {
                lo: (next() % 50) as i32,
                groups: groups.clone(),
            };
            let (keys, out) = compact_span(span);
            let sorted: Vec<usize> = groups
                .iter()
                .map(|&g| g as usize)
                .collect::<std::collections::BTreeSet<_>>()
                .into_iter()
                .collect();
            assert_eq!(keys, sorted, "case {case}: {groups:?}");
            let ranks: Vec<u32> = groups
                .iter()
                .map(|&g| sorted.iter().position(|&k| k == g as usize).unwrap_or(0) as u32)
                .collect();
            assert_eq!(out.groups, ranks, "case {case}: {groups:?}");
        }
    }
}
