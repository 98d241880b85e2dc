//! Reading the framebuffer back: `glReadPixels` (GL 2.1 §4.3.2) and a PNG-ready image.
//!
//! Design decision: every supported format/type pair goes through one path: each pixel becomes
//! its components as GL defines them (colour and depth normalised to [0, 1], stencil an integer
//! index), then each component is converted to the requested type (§4.3.2, table 2.9 reversed)
//! and packed with PACK_ALIGNMENT row padding. Pixels outside the window are left untouched.

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
    /// `glReadPixels` into `out`, rows bottom-up from (x, y), each row padded to the pack
    /// alignment. Formats RGBA, RGB, RED, GREEN, BLUE, ALPHA, LUMINANCE, LUMINANCE_ALPHA,
    /// DEPTH_COMPONENT and STENCIL_INDEX; types UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT and
    /// FLOAT, multi-byte values little-endian. Errors: INVALID_ENUM for another format or type,
    /// INVALID_VALUE for a negative size or an `out` shorter than the request,
    /// INVALID_OPERATION between Begin and End. Flushes batched drawing first.
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
        let (w, h) = (width as usize, height as usize);
        let row = w * comps * size;
        let align = self.state.pack_alignment.clamp(1, 8) as usize;
        let stride = if size >= align {
            row
        } else {
            row.div_ceil(align) * align
        };
        // §4.3.2: the last row needs no padding.
        let needed = if h == 0 || w == 0 {
            0
        } else {
            stride * (h - 1) + row
        };
        if out.len() < needed {
            return self.error(gl::INVALID_VALUE);
        }
        self.renderer.flush(&self.state);
        let fb = self.renderer.framebuffer();
        for j in 0..h {
            for i in 0..w {
                let (px, py) = (i64::from(x) + i as i64, i64::from(y) + j as i64);
                let Some((c, d, s)) = fb.pixel(px, py) else {
                    continue;
                };
                let at = j * stride + i * comps * size;
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
                }
            }
        }
    }

    /// The colour buffer as an image, top row first (flushes batched drawing first; between
    /// Begin and End it returns what is drawn so far).
    pub fn to_image(&mut self) -> image::RgbaImage {
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        let (w, h) = self.renderer.size();
        let fb = self.renderer.framebuffer();
        image::RgbaImage::from_fn(w, h, |x, y| {
            let c = fb
                .pixel(i64::from(x), i64::from(h) - 1 - i64::from(y))
                .map_or([0; 4], |p| p.0);
            image::Rgba(c)
        })
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
