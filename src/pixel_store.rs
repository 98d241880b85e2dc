//! Pixel storage modes (GL 2.1 §3.6.1 table 3.1; state tables 6.17 and 6.18) and the byte
//! layout they give an image in client memory (§3.6.4 "Unpacking", §4.3.2 "Placement in Client
//! Memory").
//!
//! One [`PixelModes`] holds one direction's eight modes: `State::unpack` governs every command
//! that reads client pixels (TexImage2D, TexSubImage2D, DrawPixels, Bitmap, gluBuild2DMipmaps'
//! input), `State::pack` every command that writes them (ReadPixels, GetTexImage). [`PixelModes::layout`] turns the
//! modes and an image's size into byte offsets, with checked arithmetic throughout: every size
//! here is the caller's, and `None` (a layout no slice can hold) is the caller's short-slice
//! error. The CPU front end, gluBuild2DMipmaps and the GL backend's guard against the driver
//! reading past recorded pixels all use this one computation.
//!
//! Design decision: IMAGE_HEIGHT and SKIP_IMAGES (3D images, §3.8.1) are stored and queried but
//! affect nothing yet: fixedgl has no command that takes a 3D image. LSB_FIRST orders the bits of
//! bitmaps (`crate::pixels::BitLayout`).

use crate::gl;

/// One direction's pixel storage modes (GL 2.1 table 3.1), initially as table 6.17/6.18 gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelModes {
    /// *_SWAP_BYTES: each multi-byte element's bytes reversed (§3.6.4, table 3.7).
    pub swap_bytes: bool,
    /// *_LSB_FIRST: bit order within a bitmap byte (Bitmap, DrawPixels and ReadPixels of type
    /// BITMAP).
    pub lsb_first: bool,
    /// *_ROW_LENGTH: pixels between row starts, 0 for the image's width.
    pub row_length: i32,
    /// *_IMAGE_HEIGHT: rows between 3D image slices, 0 for the image's height (3D only).
    pub image_height: i32,
    /// *_SKIP_ROWS: rows skipped before the first.
    pub skip_rows: i32,
    /// *_SKIP_PIXELS: pixels skipped at the start of each row.
    pub skip_pixels: i32,
    /// *_SKIP_IMAGES: 3D slices skipped before the first (3D only).
    pub skip_images: i32,
    /// *_ALIGNMENT: 1, 2, 4 or 8; rows start at multiples of it (§3.6.4).
    pub alignment: i32,
}

impl Default for PixelModes {
    fn default() -> Self {
        Self {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            image_height: 0,
            skip_rows: 0,
            skip_pixels: 0,
            skip_images: 0,
            alignment: 4,
        }
    }
}

/// Which of the eight modes a pname names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// *_SWAP_BYTES (boolean).
    SwapBytes,
    /// *_LSB_FIRST (boolean).
    LsbFirst,
    /// *_ROW_LENGTH.
    RowLength,
    /// *_IMAGE_HEIGHT.
    ImageHeight,
    /// *_SKIP_ROWS.
    SkipRows,
    /// *_SKIP_PIXELS.
    SkipPixels,
    /// *_SKIP_IMAGES.
    SkipImages,
    /// *_ALIGNMENT.
    Alignment,
}

impl Mode {
    /// SWAP_BYTES and LSB_FIRST are boolean, the others integer (table 3.1).
    pub fn is_boolean(self) -> bool {
        matches!(self, Mode::SwapBytes | Mode::LsbFirst)
    }
}

/// A PixelStore pname of GL 2.1 table 3.1: `(pack, mode)`, or None (INVALID_ENUM).
pub fn pname(pname: u32) -> Option<(bool, Mode)> {
    Some(match pname {
        gl::UNPACK_SWAP_BYTES => (false, Mode::SwapBytes),
        gl::UNPACK_LSB_FIRST => (false, Mode::LsbFirst),
        gl::UNPACK_ROW_LENGTH => (false, Mode::RowLength),
        gl::UNPACK_IMAGE_HEIGHT => (false, Mode::ImageHeight),
        gl::UNPACK_SKIP_ROWS => (false, Mode::SkipRows),
        gl::UNPACK_SKIP_PIXELS => (false, Mode::SkipPixels),
        gl::UNPACK_SKIP_IMAGES => (false, Mode::SkipImages),
        gl::UNPACK_ALIGNMENT => (false, Mode::Alignment),
        gl::PACK_SWAP_BYTES => (true, Mode::SwapBytes),
        gl::PACK_LSB_FIRST => (true, Mode::LsbFirst),
        gl::PACK_ROW_LENGTH => (true, Mode::RowLength),
        gl::PACK_IMAGE_HEIGHT => (true, Mode::ImageHeight),
        gl::PACK_SKIP_ROWS => (true, Mode::SkipRows),
        gl::PACK_SKIP_PIXELS => (true, Mode::SkipPixels),
        gl::PACK_SKIP_IMAGES => (true, Mode::SkipImages),
        gl::PACK_ALIGNMENT => (true, Mode::Alignment),
        _ => return None,
    })
}

/// PixelStoref's value as the integer PixelStorei would get (§3.6.1): for a boolean mode FALSE
/// (0) if the value is 0.0 and TRUE (1) otherwise, NaN included; for an integer mode the value
/// rounded to the nearest integer. A value with no nearest GLint (NaN, infinite, beyond
/// i32) becomes -1, an INVALID_VALUE, as Mesa's conversion gives. An unknown pname keeps the
/// rounding (its INVALID_ENUM comes first anyway).
pub fn from_float(pname_: u32, param: f32) -> i32 {
    if pname(pname_).is_some_and(|(_, m)| m.is_boolean()) {
        return i32::from(param != 0.0);
    }
    let r = f64::from(param).round();
    if r.is_finite() && r >= f64::from(i32::MIN) && r <= f64::from(i32::MAX) {
        r as i32
    } else {
        -1
    }
}

impl PixelModes {
    /// The value of `mode`, as GetIntegerv returns it (booleans 0 or 1).
    pub fn get(&self, mode: Mode) -> i32 {
        match mode {
            Mode::SwapBytes => i32::from(self.swap_bytes),
            Mode::LsbFirst => i32::from(self.lsb_first),
            Mode::RowLength => self.row_length,
            Mode::ImageHeight => self.image_height,
            Mode::SkipRows => self.skip_rows,
            Mode::SkipPixels => self.skip_pixels,
            Mode::SkipImages => self.skip_images,
            Mode::Alignment => self.alignment,
        }
    }

    /// Sets `mode` from PixelStorei's `param` (§3.6.1): a boolean is TRUE for any nonzero
    /// value; an integer must be >= 0 and an alignment 1, 2, 4 or 8 (table 3.1), else
    /// `Err(INVALID_VALUE)` with nothing changed.
    pub fn set(&mut self, mode: Mode, param: i32) -> Result<(), u32> {
        let valid = match mode {
            Mode::SwapBytes | Mode::LsbFirst => true,
            Mode::Alignment => matches!(param, 1 | 2 | 4 | 8),
            _ => param >= 0,
        };
        if !valid {
            return Err(gl::INVALID_VALUE);
        }
        match mode {
            Mode::SwapBytes => self.swap_bytes = param != 0,
            Mode::LsbFirst => self.lsb_first = param != 0,
            Mode::RowLength => self.row_length = param,
            Mode::ImageHeight => self.image_height = param,
            Mode::SkipRows => self.skip_rows = param,
            Mode::SkipPixels => self.skip_pixels = param,
            Mode::SkipImages => self.skip_images = param,
            Mode::Alignment => self.alignment = param,
        }
        Ok(())
    }

    /// Where a `width` x `height` image of `components` elements of `size` bytes per pixel
    /// lies in client memory under these modes (§3.6.4, the same for packing by §4.3.2):
    /// rows ROW_LENGTH pixels apart (or `width`), each row start rounded up to ALIGNMENT
    /// unless an element is at least that large, and the first pixel after SKIP_ROWS rows and
    /// SKIP_PIXELS pixels. None when a byte count does not fit a usize (no slice can hold it);
    /// an empty image needs no bytes, whatever the skips.
    pub fn layout(
        &self,
        width: i32,
        height: i32,
        components: usize,
        size: usize,
    ) -> Option<Layout> {
        let w = usize::try_from(width.max(0)).ok()?;
        let h = usize::try_from(height.max(0)).ok()?;
        let l = if self.row_length > 0 {
            usize::try_from(self.row_length).ok()?
        } else {
            w
        };
        let a = usize::try_from(self.alignment.clamp(1, 8)).ok()?;
        let pixel = components.checked_mul(size)?;
        let row = pixel.checked_mul(l)?;
        // k = a/s · ceil(s·n·l / a) elements when s < a, else n·l (§3.6.4), here in bytes.
        let stride = if size >= a {
            row
        } else {
            row.checked_next_multiple_of(a)?
        };
        let skip_rows = usize::try_from(self.skip_rows.max(0)).ok()?;
        let skip_pixels = usize::try_from(self.skip_pixels.max(0)).ok()?;
        // §3.6.4: "the pointer is advanced by SKIP_PIXELS·n + SKIP_ROWS·k elements".
        let offset = stride
            .checked_mul(skip_rows)?
            .checked_add(pixel.checked_mul(skip_pixels)?)?;
        let need = if w == 0 || h == 0 {
            0
        } else {
            offset
                .checked_add(stride.checked_mul(h - 1)?)?
                .checked_add(pixel.checked_mul(w)?)?
        };
        Some(Layout {
            offset,
            stride,
            pixel,
            size,
            swap: self.swap_bytes && size > 1,
            need,
        })
    }
}

impl PixelModes {
    /// Where a `width` x `height` x `depth` image (TexImage3D, GetTexImage of a 3D texture)
    /// lies in client memory (GL 2.1 §3.8.1): each 2D image as [`PixelModes::layout`] places
    /// it, images IMAGE_HEIGHT rows apart (or `height`), the first after SKIP_IMAGES images.
    /// Returns the layout of the whole as one 2D image of `(depth - 1) * image rows + height`
    /// rows (its `need` is the 3D image's) and the rows between images; image `k`'s row `j` is
    /// row `k * rows + j` of it.
    pub fn layout3(
        &self,
        width: i32,
        height: i32,
        depth: i32,
        components: usize,
        size: usize,
    ) -> Option<(Layout, usize)> {
        let h = usize::try_from(height.max(0)).ok()?;
        let d = usize::try_from(depth.max(0)).ok()?;
        let img = if self.image_height > 0 {
            usize::try_from(self.image_height).ok()?
        } else {
            h
        };
        let skip_images = usize::try_from(self.skip_images.max(0)).ok()?;
        let rows = if d == 0 || h == 0 {
            0
        } else {
            (d - 1).checked_mul(img)?.checked_add(h)?
        };
        let skip_rows = usize::try_from(self.skip_rows.max(0))
            .ok()?
            .checked_add(skip_images.checked_mul(img)?)?;
        let modes = PixelModes {
            skip_rows: i32::try_from(skip_rows).ok()?,
            ..*self
        };
        let l = modes.layout(width, i32::try_from(rows).ok()?, components, size)?;
        Some((l, img))
    }
}

/// The byte layout [`PixelModes::layout`] computes. For `i < width`, `j < height` of a layout
/// with `need > 0`, `at(i, j) + pixel <= need`, so no offset computed from it overflows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Bytes before the first pixel (the skips).
    pub offset: usize,
    /// Bytes between row starts.
    pub stride: usize,
    /// Bytes per pixel.
    pub pixel: usize,
    /// Bytes per element (component).
    pub size: usize,
    /// Whether each element's bytes are reversed (SWAP_BYTES with 2- or 4-byte elements).
    pub swap: bool,
    /// Bytes the whole image spans from the start of the client buffer.
    pub need: usize,
}

impl Layout {
    /// The byte where pixel (`i`, `j`) starts (row `j` counted from the first one read).
    pub fn at(&self, i: usize, j: usize) -> usize {
        self.offset + j * self.stride + i * self.pixel
    }

    /// Element bytes in client order to the host's native order, or back (a swap is its own
    /// inverse): reversed when SWAP_BYTES is on (§3.6.4 table 3.7, §4.3.2).
    pub fn order(&self, bytes: &mut [u8]) {
        if self.swap {
            bytes.reverse();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_with_skips_row_length_and_alignment() {
        let m = PixelModes {
            row_length: 5,
            skip_rows: 2,
            skip_pixels: 1,
            ..PixelModes::default()
        };
        // RGB bytes: 15-byte rows padded to 16; skip 2 rows (32) and 1 pixel (3).
        let l = m.layout(3, 2, 3, 1).unwrap();
        assert_eq!((l.offset, l.stride, l.pixel), (35, 16, 3));
        assert_eq!(l.need, 35 + 16 + 9);
        assert_eq!(l.at(2, 1), 35 + 16 + 6);
        // An empty image reads nothing, whatever the skips.
        assert_eq!(m.layout(0, 2, 3, 1).unwrap().need, 0);
        // Elements at least as large as the alignment: no padding.
        let l = m.layout(3, 2, 1, 4).unwrap();
        assert_eq!(l.stride, 20);
    }

    #[test]
    fn layout_overflow_is_none() {
        let m = PixelModes {
            skip_rows: i32::MAX,
            row_length: i32::MAX,
            ..PixelModes::default()
        };
        assert_eq!(m.layout(1, 1, 4, 4).map(|l| l.need), {
            // 2^31·16 per row, times 2^31 rows, overflows 64 bits.
            None
        });
        let big = PixelModes::default();
        assert!(big.layout(i32::MAX, 1, 4, 4).is_some_and(|l| l.need > 0));
        assert_eq!(big.layout(i32::MAX, i32::MAX, 4, 4), None);
    }

    #[test]
    fn pnames_values_and_float_conversion() {
        let mut m = PixelModes::default();
        assert_eq!(m.set(Mode::Alignment, 3), Err(gl::INVALID_VALUE));
        assert_eq!(m.set(Mode::SkipRows, -1), Err(gl::INVALID_VALUE));
        assert_eq!(m.set(Mode::SwapBytes, -7), Ok(()));
        assert_eq!(m.get(Mode::SwapBytes), 1);
        assert_eq!(
            m,
            PixelModes {
                swap_bytes: true,
                ..PixelModes::default()
            }
        );
        assert_eq!(pname(gl::PACK_SKIP_IMAGES), Some((true, Mode::SkipImages)));
        assert_eq!(pname(gl::PIXEL_PACK_BUFFER), None);
        assert_eq!(from_float(gl::UNPACK_SWAP_BYTES, 0.25), 1);
        assert_eq!(from_float(gl::UNPACK_SWAP_BYTES, f32::NAN), 1);
        assert_eq!(from_float(gl::UNPACK_SWAP_BYTES, -0.0), 0);
        assert_eq!(from_float(gl::UNPACK_SKIP_ROWS, 2.5), 3);
        assert_eq!(from_float(gl::UNPACK_SKIP_ROWS, -0.4), 0);
        assert_eq!(from_float(gl::UNPACK_SKIP_ROWS, f32::NAN), -1);
        assert_eq!(from_float(gl::UNPACK_SKIP_ROWS, 3e9), -1);
        assert_eq!(from_float(gl::PACK_ALIGNMENT, 2.4), 2);
    }
}
