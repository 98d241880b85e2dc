//! Line stipple (GL 2.1 §3.4.2) and polygon stipple (§3.5.6): `LineStipple`, `PolygonStipple`,
//! `GetPolygonStipple`.
//!
//! The polygon stipple is a 32x32 bitmap, unpacked (and, for GetPolygonStipple, packed) as a
//! COLOR_INDEX / BITMAP image by the pixel store modes of §3.6.1: ROW_LENGTH, SKIP_ROWS,
//! SKIP_PIXELS, ALIGNMENT and LSB_FIRST (SWAP_BYTES does not apply to bitmaps). It is kept in
//! `State::stipple` as 32 rows of 32 bits, bit x of row r for the window pixels with
//! x mod 32 = x and y mod 32 = r (window-aligned, §3.5.6).
//!
//! Design decision: a display list keeps the pattern unpacked at compile time (§5.4, as Mesa's
//! `save_PolygonStipple`): the list holds the pattern re-packed tightly, and a PolygonStipple run
//! from a list reads it with the default unpack modes, whatever the modes are when the list runs.

use super::Context;
use crate::call::Call;
use crate::gl;
use crate::pixel_store::PixelModes;
use crate::state::Stipple;

/// The bytes of a 32x32 bitmap under `modes` (GL 2.1 §3.6.4 for type BITMAP, as Mesa's
/// `_mesa_image_address`): (bytes per row, first byte of row 0, first bit of each row, bytes
/// read or written in all). `None` for sizes past `usize`.
fn bitmap_layout(modes: &PixelModes) -> Option<(usize, usize, usize, usize)> {
    let len = if modes.row_length > 0 {
        usize::try_from(modes.row_length).ok()?
    } else {
        32
    };
    let align = usize::try_from(modes.alignment.clamp(1, 8)).ok()?;
    let stride = len.div_ceil(8 * align).checked_mul(align)?;
    let skip_rows = usize::try_from(modes.skip_rows.max(0)).ok()?;
    let skip_pixels = usize::try_from(modes.skip_pixels.max(0)).ok()?;
    let first = skip_rows
        .checked_mul(stride)?
        .checked_add(skip_pixels / 8)?;
    let last_row = skip_rows.checked_add(31)?.checked_mul(stride)?;
    let need = last_row.checked_add(skip_pixels.checked_add(32)?.div_ceil(8))?;
    Some((stride, first, skip_pixels % 8, need))
}

/// The byte and bit mask of pixel `x` of a bitmap row whose first pixel is bit `bit0` of byte
/// `row` (MSB first unless LSB_FIRST).
fn bit_at(row: usize, bit0: usize, x: usize, lsb_first: bool) -> (usize, u8) {
    let b = bit0 + x;
    let mask = if lsb_first {
        1u8 << (b % 8)
    } else {
        0x80u8 >> (b % 8)
    };
    (row + b / 8, mask)
}

/// Unpacks a polygon stipple from `data` (GL 2.1 §3.5.6); `None` when `data` is too short.
pub(crate) fn unpack_polygon_stipple(modes: &PixelModes, data: &[u8]) -> Option<[u32; 32]> {
    let (stride, first, bit0, need) = bitmap_layout(modes)?;
    if data.len() < need {
        return None;
    }
    let mut rows = [0u32; 32];
    for (r, word) in rows.iter_mut().enumerate() {
        let row = first + r * stride;
        for x in 0..32 {
            let (byte, mask) = bit_at(row, bit0, x, modes.lsb_first);
            if data.get(byte).is_some_and(|&v| v & mask != 0) {
                *word |= 1 << x;
            }
        }
    }
    Some(rows)
}

/// The bytes a stipple unpacks from or packs into under `modes` (`None`: more than `usize`);
/// the GL backend checks a recorded mask with it.
#[cfg(any(test, feature = "gl"))]
pub(crate) fn polygon_stipple_bytes(modes: &PixelModes) -> Option<usize> {
    bitmap_layout(modes).map(|l| l.3)
}

/// Packs `rows` into `out` (GL 2.1 §4.3.2 as for a BITMAP image, as Mesa's `_mesa_pack_bitmap`:
/// whole bytes when SKIP_PIXELS is a multiple of 8, otherwise the bytes a row touches are
/// cleared first); false, nothing written, when `out` is too short.
fn pack_polygon_stipple(modes: &PixelModes, rows: &[u32; 32], out: &mut [u8]) -> bool {
    let Some((stride, first, bit0, need)) = bitmap_layout(modes) else {
        return false;
    };
    if out.len() < need {
        return false;
    }
    for (r, &word) in rows.iter().enumerate() {
        let row = first + r * stride;
        let bytes = (bit0 + 32).div_ceil(8);
        if let Some(span) = out.get_mut(row..row + bytes) {
            span.fill(0);
        }
        for x in 0..32 {
            if word & (1 << x) != 0 {
                let (byte, mask) = bit_at(row, bit0, x, modes.lsb_first);
                if let Some(b) = out.get_mut(byte) {
                    *b |= mask;
                }
            }
        }
    }
    true
}

impl Context {
    /// `glLineStipple` (GL 2.1 §3.4.2): `factor` clamped to [1, 256] (LINE_STIPPLE_REPEAT),
    /// `pattern` the 16-bit pattern (LINE_STIPPLE_PATTERN), its least significant bit first.
    /// Used while LINE_STIPPLE is enabled; the pattern restarts at each Begin and, for LINES, at
    /// each segment (as llvmpipe's draw module, which counts along the clipped segments).
    /// INVALID_OPERATION between Begin and End.
    pub fn line_stipple(&mut self, factor: i32, pattern: u16) {
        record!(self, Call::LineStipple(factor, pattern));
        if !self.outside_begin_end() {
            return;
        }
        self.state.stipple.line_pattern = pattern;
        self.state.stipple.line_repeat = factor.clamp(1, 256);
    }

    /// `glPolygonStipple` (GL 2.1 §3.5.6): the 32x32 pattern unpacked from `mask` by the
    /// current unpack modes, used for filled polygons while POLYGON_STIPPLE is enabled (not for
    /// lines, points or polygons drawn in LINE or POINT mode, as GL and llvmpipe). INVALID_OPERATION
    /// between Begin and End, and (Rust API, as the image commands) for a `mask` shorter than the
    /// bytes the modes read; nothing changes then.
    pub fn polygon_stipple(&mut self, mask: &[u8]) {
        record!(self, Call::PolygonStipple(mask.to_vec()));
        if !self.outside_begin_end() {
            return;
        }
        // Run from a display list: the pattern was unpacked at compile time and stored tightly.
        let modes = if self.lists.depth > 0 {
            PixelModes::default()
        } else {
            self.state.unpack
        };
        match unpack_polygon_stipple(&modes, mask) {
            Some(rows) => self.state.stipple.polygon = rows,
            None => self.error(gl::INVALID_OPERATION),
        }
    }

    /// What a PolygonStipple compiles into (GL 2.1 §5.4): the pattern unpacked now by the
    /// current modes, re-packed tightly (run from the list with the default modes, see the module
    /// docs); `None` (compiled as it is, to raise its error when run) for data too short.
    pub(crate) fn compile_polygon_stipple(&self, mask: &[u8]) -> Option<Vec<Call>> {
        let rows = unpack_polygon_stipple(&self.state.unpack, mask)?;
        let mut tight = vec![0u8; 128];
        pack_polygon_stipple(&PixelModes::default(), &rows, &mut tight);
        Some(vec![Call::PolygonStipple(tight)])
    }

    /// `glGetPolygonStipple`: the pattern packed into `mask` by the current pack modes.
    /// INVALID_OPERATION between Begin and End, and (Rust API, as ReadPixels' short buffer) for
    /// a `mask` shorter than the bytes the modes write; nothing is written then.
    pub fn get_polygon_stipple(&mut self, mask: &mut [u8]) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        let Stipple { polygon, .. } = self.state.stipple;
        if !pack_polygon_stipple(&self.state.pack, &polygon, mask) {
            self.error(gl::INVALID_OPERATION);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tight_msb_first_rows_and_skips() {
        let mut data = vec![0u8; 128];
        // Row 0: pixel 0 (MSB of byte 0) and pixel 31 (LSB of byte 3); row 31: pixel 8.
        data[0] = 0x80;
        data[3] = 0x01;
        data[124 + 1] = 0x80;
        let rows = unpack_polygon_stipple(&PixelModes::default(), &data);
        let Some(rows) = rows else { panic!("short") };
        assert_eq!(rows[0], 1 | 1 << 31);
        assert_eq!(rows[31], 1 << 8);
        assert!(rows[1..31].iter().all(|&r| r == 0));
        // LSB first: byte 0's bit 0 is pixel 0.
        let lsb = PixelModes {
            lsb_first: true,
            ..PixelModes::default()
        };
        let Some(r2) = unpack_polygon_stipple(&lsb, &data) else {
            panic!("short")
        };
        assert_eq!(r2[0], 1 << 7 | 1 << 24);
        // SKIP_PIXELS 3, ROW_LENGTH 40, ALIGNMENT 2, SKIP_ROWS 1: rows of 6 bytes from byte 6;
        // pixel 0 is bit 3 (MSB first) of the row's first byte.
        let m = PixelModes {
            skip_pixels: 3,
            row_length: 40,
            alignment: 2,
            skip_rows: 1,
            ..PixelModes::default()
        };
        assert_eq!(polygon_stipple_bytes(&m), Some(32 * 6 + 5));
        let mut d = vec![0u8; 32 * 6 + 5];
        d[6] = 0x10;
        let Some(r3) = unpack_polygon_stipple(&m, &d) else {
            panic!("short")
        };
        assert_eq!(r3[0], 1);
        assert!(unpack_polygon_stipple(&m, &d[..d.len() - 1]).is_none());
        // Packing is the inverse under the same modes.
        let mut back = vec![0xAAu8; d.len()];
        assert!(pack_polygon_stipple(&m, &r3, &mut back));
        assert_eq!(unpack_polygon_stipple(&m, &back), Some(r3));
    }
}
