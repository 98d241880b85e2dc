//! Reading the framebuffer back: `glReadPixels` (GL 2.1 §4.3.2) and a PNG-ready image.
//!
//! Design decision: every supported format/type pair goes through one path: each pixel becomes
//! its components as GL defines them (colour and depth normalised to [0, 1], stencil an integer
//! index), then each component is converted to the requested type (§4.3.2, table 2.9 reversed)
//! and placed in client memory under the PACK_ modes (§4.3.2 "Placement in Client Memory":
//! ROW_LENGTH, SKIP_ROWS, SKIP_PIXELS, ALIGNMENT, SWAP_BYTES; `crate::pixel_store`). Pixels
//! outside the window are left untouched, and so are the bytes the skips and row padding pass
//! over.

use crate::gl;
use crate::Context;

/// What a pixel is read as.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Source {
    /// Colour components by index into RGBA (R=0 .. A=3); LUMINANCE is R (§4.3.2).
    Color(&'static [usize]),
    Depth,
    Stencil,
}

impl Context {
    /// `glReadPixels` into `out`, rows bottom-up from (x, y), placed under the PACK_ modes
    /// (row length, skipped rows and pixels, alignment, byte swapping). Formats RGBA, RGB, RED, GREEN, BLUE, ALPHA, LUMINANCE, LUMINANCE_ALPHA,
    /// DEPTH_COMPONENT and STENCIL_INDEX; types UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT and
    /// FLOAT, multi-byte values little-endian (big-endian with PACK_SWAP_BYTES). Errors:
    /// INVALID_ENUM for another format or type, INVALID_VALUE for a negative size or an `out`
    /// shorter than the skips and the request need,
    /// INVALID_OPERATION between Begin and End, or for DEPTH_COMPONENT (STENCIL_INDEX) without a
    /// depth (stencil) buffer. Colour comes from the buffer READ_BUFFER names. Flushes batched
    /// drawing first.
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
        let source = match format {
            gl::RGBA => Source::Color(&[0, 1, 2, 3]),
            gl::RGB => Source::Color(&[0, 1, 2]),
            gl::RED => Source::Color(&[0]),
            gl::GREEN => Source::Color(&[1]),
            gl::BLUE => Source::Color(&[2]),
            gl::ALPHA => Source::Color(&[3]),
            gl::LUMINANCE => Source::Color(&[0]),
            gl::LUMINANCE_ALPHA => Source::Color(&[0, 3]),
            gl::DEPTH_COMPONENT => Source::Depth,
            gl::STENCIL_INDEX => Source::Stencil,
            _ => return self.error(gl::INVALID_ENUM),
        };
        let size: usize = match ty {
            gl::UNSIGNED_BYTE => 1,
            gl::UNSIGNED_SHORT => 2,
            gl::UNSIGNED_INT | gl::FLOAT => 4,
            _ => return self.error(gl::INVALID_ENUM),
        };
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        let comps = match source {
            Source::Color(c) => c.len(),
            _ => 1,
        };
        // §4.3.2: DEPTH_COMPONENT without a depth buffer, STENCIL_INDEX without a stencil
        // buffer.
        let missing = match source {
            Source::Depth => !self.state.config.depth,
            Source::Stencil => !self.state.config.stencil,
            Source::Color(_) => false,
        };
        if missing {
            return self.error(gl::INVALID_OPERATION);
        }
        let (w, h) = (width as usize, height as usize);
        // Every product of the caller's sizes is checked (`PixelModes::layout`): width, height,
        // PACK_ROW_LENGTH and the skips up to 2^31 times 16 bytes a pixel wrap a usize, and a
        // wrapped `need` passed the length check below while the loops then ran over the whole
        // requested rectangle. No slice can be that long, so an overflow is the same
        // INVALID_VALUE as a short `out`.
        let Some(layout) = self.state.pack.layout(width, height, comps, size) else {
            return self.error(gl::INVALID_VALUE);
        };
        if out.len() < layout.need {
            return self.error(gl::INVALID_VALUE);
        }
        self.renderer.flush(&self.state);
        let buf = crate::cpu::framebuffer::read_buf(&self.state);
        let fb = self.renderer.framebuffer();
        // Only the part of the rectangle inside the window is visited (§4.3.2: pixels outside it
        // are undefined; fixedgl leaves them untouched), so the work is bounded by the window,
        // not by the requested size. The window is at most MAX_VIEWPORT_DIM square, so the
        // offsets below fit in i64.
        let (fw, fh) = fb.size();
        let span = |o: i32, n: usize, limit: u32| {
            let lo = (-i64::from(o)).clamp(0, n as i64);
            let hi = (i64::from(limit) - i64::from(o)).clamp(lo, n as i64);
            (lo as usize)..(hi as usize)
        };
        let (cols, rows) = (span(x, w, fw), span(y, h, fh));
        for j in rows {
            for i in cols.clone() {
                let (px, py) = (i64::from(x) + i as i64, i64::from(y) + j as i64);
                let Some((c, d, s)) = fb.pixel_in(buf, px, py) else {
                    continue;
                };
                // j < h and i < w, so this is at most `layout.need`, which did not overflow.
                let at = layout.at(i, j);
                for k in 0..comps {
                    let (norm, int) = match source {
                        Source::Color(idx) => {
                            let v = idx.get(k).and_then(|&n| c.get(n)).copied().unwrap_or(0);
                            (f64::from(v) / 255.0, None)
                        }
                        Source::Depth => (f64::from(d) / f64::from((1u32 << 24) - 1), None),
                        Source::Stencil => (0.0, Some(u32::from(s))),
                    };
                    let o = at + k * size;
                    let Some(dst) = out.get_mut(o..o + size) else {
                        continue;
                    };
                    pack(dst, ty, norm, int);
                    layout.order(dst);
                }
            }
        }
    }

    /// The colour buffer as an image, top row first (flushes batched drawing first; between
    /// Begin and End it returns what is drawn so far): the back buffer of a double-buffered
    /// context (where drawing goes unless DrawBuffer says otherwise), the only colour buffer of
    /// a single-buffered one; [`Context::front_rgba`] reads the front buffer.
    pub fn to_image(&mut self) -> image::RgbaImage {
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        let (w, h) = self.renderer.size();
        let bytes = self.renderer.framebuffer().color_bytes_top_down();
        // The buffer holds exactly w·h pixels, so `from_raw` cannot fail (asserted in debug
        // builds); a blank image if it did.
        debug_assert_eq!(bytes.len(), w as usize * h as usize * 4);
        image::RgbaImage::from_raw(w, h, bytes).unwrap_or_else(|| image::RgbaImage::new(w, h))
    }
}

/// Converts one component to type `ty` into `dst`: a normalised value by c·(2^b − 1) rounded
/// (§4.3.2 / table 2.9), or an integer index as is (stencil, masked to the type).
fn pack(dst: &mut [u8], ty: u32, norm: f64, int: Option<u32>) {
    let unorm = |bits: u32| -> u32 {
        match int {
            Some(i) => i & ((1u64 << bits) - 1) as u32,
            None => (norm.clamp(0.0, 1.0) * ((1u64 << bits) - 1) as f64).round() as u32,
        }
    };
    match ty {
        gl::UNSIGNED_BYTE => dst.copy_from_slice(&[unorm(8) as u8]),
        gl::UNSIGNED_SHORT => dst.copy_from_slice(&(unorm(16) as u16).to_le_bytes()),
        gl::UNSIGNED_INT => dst.copy_from_slice(&unorm(32).to_le_bytes()),
        _ => {
            let f = int.map_or(norm as f32, |i| i as f32);
            dst.copy_from_slice(&f.to_le_bytes());
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
        c.read_pixels(0, 0, 2, 1, gl::LUMINANCE, gl::UNSIGNED_BYTE, &mut a);
        assert_eq!(a, [255, 51]);
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
