//! Reading the framebuffer back: `glReadPixels` (GL 2.1 §4.3.2) and a PNG-ready image.
//!
//! Design decision: every supported format/type pair goes through one path: each pixel becomes
//! its components as GL defines them (colour and depth normalised to [0, 1], stencil an integer
//! index), through the pixel transfer when it is not at its defaults (§4.3.2: colour scale and
//! bias and MAP_COLOR, DEPTH_SCALE and DEPTH_BIAS, index shift and offset and MAP_STENCIL, as in
//! `crate::pixels`), then each component is converted to the requested type (§4.3.2, table 4.9;
//! packed types field by field, table 3.8) and placed in client memory under the PACK_ modes
//! (§4.3.2 "Placement in Client Memory": ROW_LENGTH, SKIP_ROWS, SKIP_PIXELS, ALIGNMENT,
//! SWAP_BYTES, and LSB_FIRST for bitmaps; `crate::pixel_store`). With the transfer at its
//! defaults a component is exactly what it always was (c/255 in double precision). Pixels outside
//! the window are left untouched, and so are the bytes the skips and row padding pass over.

use crate::gl;
use crate::pixels::{check, Group, ImageLayout, Scalar, Slot, Ty};
use crate::Context;

impl Context {
    /// `glReadPixels` into `out`, rows bottom-up from (x, y), placed under the PACK_ modes
    /// (row length, skipped rows and pixels, alignment, byte swapping, bit order). Formats RGBA,
    /// RGB, BGRA, BGR, RED, GREEN, BLUE, ALPHA, LUMINANCE (R + G + B, §4.3.2), LUMINANCE_ALPHA,
    /// DEPTH_COMPONENT and STENCIL_INDEX; every GL 2.1 type (BITMAP for STENCIL_INDEX, the packed
    /// types for RGB, RGBA and BGRA); multi-byte values in the host's order (reversed with
    /// PACK_SWAP_BYTES). The pixel transfer applies. Errors: INVALID_OPERATION between Begin and
    /// End, INVALID_VALUE for a negative size, INVALID_ENUM or INVALID_OPERATION for the format and
    /// type as DrawPixels (`pixels::check`), INVALID_OPERATION for COLOR_INDEX (no colour-index
    /// buffer), INVALID_VALUE for an `out` shorter than the skips and the request need,
    /// INVALID_OPERATION for DEPTH_COMPONENT (STENCIL_INDEX) without a depth (stencil) buffer.
    /// Colour comes from the buffer READ_BUFFER names. Flushes batched drawing first.
    #[allow(clippy::too_many_arguments)]
    pub fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        out: &mut [u8],
    ) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        let f = match check(format, ty) {
            Ok(f) => f,
            Err(code) => return self.error(code),
        };
        if f.group == Group::Index {
            return self.error(gl::INVALID_OPERATION);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        // §4.3.2: DEPTH_COMPONENT without a depth buffer, STENCIL_INDEX without a stencil
        // buffer.
        let missing = match f.group {
            Group::Depth => !self.state.config.depth,
            Group::Stencil => !self.state.config.stencil,
            // GL_EXT_packed_depth_stencil: both buffers.
            Group::DepthStencil => !(self.state.config.depth && self.state.config.stencil),
            _ => false,
        };
        if missing {
            return self.error(gl::INVALID_OPERATION);
        }
        // Every product of the caller's sizes is checked (`PixelModes::layout`): width, height,
        // PACK_ROW_LENGTH and the skips up to 2^31 times 16 bytes a pixel wrap a usize, and a
        // wrapped `need` passed the length check below while the loops then ran over the whole
        // requested rectangle. No slice can be that long, so an overflow is the same
        // INVALID_VALUE as a short `out`.
        let Some(layout) = self.state.pack.image_layout(f, width, height) else {
            return self.error(gl::INVALID_VALUE);
        };
        if out.len() < layout.need() {
            return self.error(gl::INVALID_VALUE);
        }
        self.renderer.flush(&self.state);
        let t = self.state.pixel;
        let maps = std::sync::Arc::clone(&self.state.pixel_maps);
        let buf = crate::cpu::framebuffer::read_buf(&self.state);
        let fb = self.renderer.framebuffer();
        // Only the part of the rectangle inside the window is visited (§4.3.2: pixels outside it
        // are undefined; fixedgl leaves them untouched), so the work is bounded by the window,
        // not by the requested size. The window is at most MAX_VIEWPORT_DIM square, so the
        // offsets below fit in i64.
        let (fw, fh) = fb.size();
        let (w, h) = (width as usize, height as usize);
        let span = |o: i32, n: usize, limit: u32| {
            let lo = (-i64::from(o)).clamp(0, n as i64);
            let hi = (i64::from(limit) - i64::from(o)).clamp(lo, n as i64);
            (lo as usize)..(hi as usize)
        };
        let (cols, rows) = (span(x, w, fw), span(y, h, fh));
        let color_identity = t.color_is_identity();
        for j in rows {
            for i in cols.clone() {
                let (px, py) = (i64::from(x) + i as i64, i64::from(y) + j as i64);
                let Some((c, d, s)) = fb.pixel_in(buf, px, py) else {
                    continue;
                };
                // The pixel's components, in the format's order, normalised (or an index).
                let mut comps = [Value::Norm(0.0); 4];
                let n = match f.group {
                    Group::Color(slots) => {
                        let rgba: [f64; 4] = if color_identity {
                            c.map(|v| f64::from(v) / 255.0)
                        } else {
                            t.color(&maps, c.map(|v| f32::from(v) / 255.0))
                                .map(f64::from)
                        };
                        for (k, slot) in slots.iter().enumerate() {
                            comps[k] = Value::Norm(match slot {
                                // §4.3.2 "Conversion to L": L = R + G + B (clamped at
                                // conversion).
                                Slot::L => (rgba[0] + rgba[1] + rgba[2]).min(1.0),
                                Slot::R => rgba[0],
                                Slot::G => rgba[1],
                                Slot::B => rgba[2],
                                Slot::A => rgba[3],
                            });
                        }
                        slots.len()
                    }
                    Group::Depth => {
                        let z = f64::from(d) / f64::from((1u32 << 24) - 1);
                        comps[0] = Value::Norm(t.depth(z));
                        1
                    }
                    // The depth as DEPTH_COMPONENT's, the index as STENCIL_INDEX's.
                    Group::DepthStencil => {
                        let z = f64::from(d) / f64::from((1u32 << 24) - 1);
                        comps[0] = Value::Norm(t.depth(z));
                        comps[1] = Value::Int(u32::from(t.stencil(&maps, i64::from(s))));
                        2
                    }
                    _ => {
                        let v = if t.stencil_is_identity() {
                            u32::from(s)
                        } else {
                            u32::from(t.stencil(&maps, i64::from(s)))
                        };
                        comps[0] = Value::Int(v);
                        1
                    }
                };
                store(out, &layout, f.ty, i, j, &comps[..n]);
            }
        }
    }

    /// The colour buffer as an image, top row first (flushes batched drawing first; between
    /// Begin and End it returns what is drawn so far): the back buffer of a double-buffered
    /// context (where drawing goes unless DrawBuffer says otherwise), the only colour buffer of
    /// a single-buffered one; [`Context::front_rgba`] reads the front buffer. The window's
    /// buffer, also while a framebuffer object is bound.
    pub fn to_image(&mut self) -> image::RgbaImage {
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        // The window's, also while a framebuffer object is bound (context/fbo.rs).
        let (bytes, (w, h)) = match self.fbos.window_main_rgba() {
            Some(found) => found,
            None => (
                self.renderer
                    .color_bytes_top_down(crate::cpu::framebuffer::ColorBuf::Main),
                self.renderer.size(),
            ),
        };
        // The buffer holds exactly w·h pixels, so `from_raw` cannot fail (asserted in debug
        // builds); a blank image if it did.
        debug_assert_eq!(bytes.len(), w as usize * h as usize * 4);
        image::RgbaImage::from_raw(w, h, bytes).unwrap_or_else(|| image::RgbaImage::new(w, h))
    }
}

/// One component before conversion to the client's type (ReadPixels and GetTexImage).
#[derive(Clone, Copy, Debug)]
pub(super) enum Value {
    /// A colour or depth in [0, 1].
    Norm(f64),
    /// A stencil index.
    Int(u32),
}

/// Places the components `comps` of pixel (`i`, `j`) of the request in `out` as type `ty` under
/// `layout` (which `out` is long enough for). GetTexImage packs its texels with it too.
pub(super) fn store(
    out: &mut [u8],
    layout: &ImageLayout,
    ty: Ty,
    i: usize,
    j: usize,
    comps: &[Value],
) {
    match (layout, ty) {
        (ImageLayout::Bits(b), _) => {
            // BITMAP (stencil only): the index's low bit (§4.3.2).
            let bit = matches!(comps.first(), Some(Value::Int(v)) if v & 1 != 0);
            let k = b.skip + i;
            let at = b.offset + j * b.stride + k / 8;
            let mask = if b.lsb_first {
                1u8 << (k % 8)
            } else {
                0x80u8 >> (k % 8)
            };
            if let Some(byte) = out.get_mut(at) {
                if bit {
                    *byte |= mask;
                } else {
                    *byte &= !mask;
                }
            }
        }
        (ImageLayout::Bytes(l), Ty::Packed { size, fields }) => {
            let mut e = 0u32;
            for (c, &(shift, bits)) in comps.iter().zip(fields) {
                let max = (1u64 << bits) - 1;
                let v = match *c {
                    Value::Norm(n) => (n.clamp(0.0, 1.0) * max as f64).round() as u64,
                    Value::Int(v) => u64::from(v) & max,
                };
                e |= (v as u32) << shift;
            }
            let at = l.at(i, j);
            let bytes = e.to_ne_bytes();
            let src = match size {
                1 => &bytes[..1],
                2 => &(e as u16).to_ne_bytes()[..],
                _ => &bytes[..],
            };
            if let Some(dst) = out.get_mut(at..at + size) {
                dst.copy_from_slice(src);
                l.order(dst);
            }
        }
        (ImageLayout::Bytes(l), Ty::Scalar(s)) => {
            let at = l.at(i, j);
            let size = s.size();
            for (k, c) in comps.iter().enumerate() {
                let o = at + k * size;
                if let Some(dst) = out.get_mut(o..o + size) {
                    pack(dst, s, *c);
                    l.order(dst);
                }
            }
        }
        _ => {}
    }
}

/// Converts one component to scalar type `s` into `dst` (host order): a normalised value by
/// c·(2^b − 1) rounded for the unsigned types, ((2^b − 1)·c − 1)/2 rounded for the signed ones
/// (table 4.9), as it is for FLOAT; an index masked to the type (as it is for FLOAT).
fn pack(dst: &mut [u8], s: Scalar, c: Value) {
    let unorm = |bits: u32| -> u32 {
        match c {
            Value::Int(i) => i & ((1u64 << bits) - 1) as u32,
            Value::Norm(n) => (n.clamp(0.0, 1.0) * ((1u64 << bits) - 1) as f64).round() as u32,
        }
    };
    let snorm = |bits: u32| -> i32 {
        let max = ((1u64 << bits) - 1) as f64;
        match c {
            Value::Int(i) => i as i32,
            // Half up: f = 0 gives 0, not −1 (the rounding table 4.9 leaves open; the driver's).
            Value::Norm(n) => {
                (crate::convert::unit_to_signed(n.clamp(-1.0, 1.0), max) + 0.5).floor() as i32
            }
        }
    };
    match s {
        Scalar::U8 => dst.copy_from_slice(&[unorm(8) as u8]),
        Scalar::U16 => dst.copy_from_slice(&(unorm(16) as u16).to_ne_bytes()),
        Scalar::U32 => dst.copy_from_slice(&unorm(32).to_ne_bytes()),
        Scalar::I8 => dst.copy_from_slice(&[snorm(8) as i8 as u8]),
        Scalar::I16 => dst.copy_from_slice(&(snorm(16) as i16).to_ne_bytes()),
        Scalar::I32 => dst.copy_from_slice(&snorm(32).to_ne_bytes()),
        Scalar::F32 => {
            let f = match c {
                Value::Int(i) => i as f32,
                Value::Norm(n) => n as f32,
            };
            dst.copy_from_slice(&f.to_ne_bytes());
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec4;

    use crate::gl;
    use crate::Context;

    /// A 3x2 context: colour (0.2, 0.4, 0.6, 1.0) → bytes (51, 102, 153, 255) since
    /// 0.2·255 + 0.5 = 51.5 → 51, 102.5 → 102, 153.5 → 153; depth 0.25, stencil 5; then the
    /// bottom-left pixel cleared to pure red through the scissor.
    fn ctx() -> Context {
        let mut c = Context::new(3, 2).unwrap();
        c.state.clear_color = Vec4::new(0.2, 0.4, 0.6, 1.0);
        c.state.clear_depth = 0.25;
        c.state.clear_stencil = 5;
        let all = gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT;
        c.renderer.clear(&c.state, all);
        c.state.enables.scissor_test = true;
        c.state.scissor = [0, 0, 1, 1];
        c.state.clear_color = Vec4::new(1.0, 0.0, 0.0, 1.0);
        c.renderer.clear(&c.state, gl::COLOR_BUFFER_BIT);
        c.state.enables.scissor_test = false;
        c
    }

    const BG: [u8; 4] = [51, 102, 153, 255];

    #[test]
    fn rgba_bottom_up() {
        let mut c = ctx();
        let mut out = [0u8; 24];
        c.read_pixels(0, 0, 3, 2, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        assert_eq!(out[..4], [255, 0, 0, 255]);
        assert_eq!(out[4..8], BG);
        assert_eq!(out[12..16], BG);
    }

    #[test]
    fn rgb_rows_padded_to_pack_alignment() {
        let mut c = ctx();
        // Row 3·3 = 9 bytes, padded to 12 with alignment 4; the last row is not padded: 21.
        let mut out = [7u8; 21];
        c.read_pixels(0, 0, 3, 2, gl::RGB, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        assert_eq!(out[..9], [255, 0, 0, 51, 102, 153, 51, 102, 153]);
        assert_eq!(out[9..12], [7, 7, 7]); // padding untouched
        assert_eq!(out[12..15], [51, 102, 153]);
        // One byte short: INVALID_VALUE, nothing written.
        let mut short = [7u8; 20];
        c.read_pixels(0, 0, 3, 2, gl::RGB, gl::UNSIGNED_BYTE, &mut short);
        assert_eq!(c.get_error(), gl::INVALID_VALUE);
        assert!(short.iter().all(|&b| b == 7));
        // Alignment 1: rows packed back to back.
        c.state.pack.alignment = 1;
        let mut out = [0u8; 18];
        c.read_pixels(0, 0, 3, 2, gl::RGB, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(out[9..12], [51, 102, 153]);
    }

    #[test]
    fn alpha_luminance_depth_stencil() {
        let mut c = ctx();
        let mut a = [0u8; 2];
        c.read_pixels(0, 0, 2, 1, gl::ALPHA, gl::UNSIGNED_BYTE, &mut a);
        assert_eq!(a, [255, 255]);
        // L = R + G + B, clamped: 255 + 0 + 0, and 51 + 102 + 153 = 306 → 255.
        c.read_pixels(0, 0, 2, 1, gl::LUMINANCE, gl::UNSIGNED_BYTE, &mut a);
        assert_eq!(a, [255, 255]);
        // Depth 0.25 is stored as 0.25·(2^24 − 1) + 0.5 → 4194304; read back as 4194304/(2^24 − 1).
        let mut d = [0u8; 4];
        c.read_pixels(2, 1, 1, 1, gl::DEPTH_COMPONENT, gl::FLOAT, &mut d);
        assert_eq!(f32::from_le_bytes(d), (4194304.0f64 / 16777215.0) as f32);
        let mut s = [0u8; 1];
        c.read_pixels(1, 1, 1, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut s);
        assert_eq!(s, [5]);
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }

    #[test]
    fn outside_the_window_is_untouched() {
        let mut c = ctx();
        let mut out = [9u8; 12];
        c.read_pixels(-1, 1, 3, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        assert_eq!(out[..4], [9; 4]);
        assert_eq!(out[4..8], BG);
    }

    #[test]
    fn errors() {
        let mut c = ctx();
        let mut out = [0u8; 64];
        c.read_pixels(0, 0, 1, 1, gl::TRIANGLES, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(c.get_error(), gl::INVALID_ENUM);
        c.read_pixels(0, 0, 1, 1, gl::RGBA, gl::RGBA, &mut out);
        assert_eq!(c.get_error(), gl::INVALID_ENUM);
        c.read_pixels(0, 0, -1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(c.get_error(), gl::INVALID_VALUE);
        c.begin(gl::POINTS);
        c.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut out);
        c.end();
        assert_eq!(c.get_error(), gl::INVALID_OPERATION);
        assert!(out.iter().all(|&b| b == 0));
    }

    #[test]
    fn to_image_is_top_down() {
        let mut c = ctx();
        let img = c.to_image();
        assert_eq!(img.dimensions(), (3, 2));
        assert_eq!(img.get_pixel(0, 1).0, [255, 0, 0, 255]);
        assert_eq!(img.get_pixel(0, 0).0, BG);
    }

    #[test]
    fn context_draws_and_reads_back() {
        let mut c = Context::new(4, 4).unwrap();
        c.begin(gl::TRIANGLES);
        c.color4f(0.0, 1.0, 0.0, 1.0);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0)] {
            c.vertex3f(x, y, 0.0);
        }
        c.end();
        let mut out = [0u8; 8];
        // Pixel (0,0) is inside the lower-left half, (3,3) outside (cleared black).
        c.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut out[..4]);
        c.read_pixels(3, 3, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut out[4..]);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        assert_eq!(out, [0, 255, 0, 255, 0, 0, 0, 0]);
    }
}
