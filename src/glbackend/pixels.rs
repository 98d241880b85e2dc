//! Replay of the pixel commands whose client memory the driver reads through a pointer: PixelMap
//! (GL 2.1 §3.6.3), Bitmap (§3.7) and DrawPixels (§3.6.4).
//!
//! Design decision: the driver never reads past the recorded values or bytes. PixelMap's values
//! must hold `mapsize` entries; DrawPixels' and Bitmap's bytes must span the image under the
//! driver's own unpack state (queried at the call, the same `PixelModes` layout the front end
//! uses). A short recording gets the front end's error without the driver seeing the pointer.
//! DrawPixels' format and type are checked here with the front end's GL 2.1 table
//! (`pixels::check`): the driver also takes GL 3.0's HALF_FLOAT and RG, which GL
//! 2.1 does not have. I_TO_I's size must be a power of two in GL 2.1 (§3.6.3), which Mesa does
//! not check, so that INVALID_VALUE is raised here too.

use super::GlBackend;
use crate::gl;
use crate::pixel_store::PixelModes;
use crate::pixels::{check, ImageLayout, MAX_PIXEL_MAP_TABLE};

impl GlBackend {
    /// The driver's unpack modes (those that move where an image's bytes lie).
    pub(super) fn driver_unpack(&self) -> PixelModes {
        let mut v = [0i32; 6];
        for (slot, pname) in v.iter_mut().zip([
            gl::UNPACK_ALIGNMENT,
            gl::UNPACK_ROW_LENGTH,
            gl::UNPACK_SKIP_ROWS,
            gl::UNPACK_SKIP_PIXELS,
            gl::UNPACK_LSB_FIRST,
            gl::UNPACK_SWAP_BYTES,
        ]) {
            // SAFETY: context current (execute made it so); GetIntegerv writes one value.
            unsafe { self.raw.GetIntegerv(pname, slot) };
        }
        PixelModes {
            alignment: v[0],
            row_length: v[1],
            skip_rows: v[2],
            skip_pixels: v[3],
            lsb_first: v[4] != 0,
            swap_bytes: v[5] != 0,
            ..PixelModes::default()
        }
    }

    /// Runs `f` with the driver's unpack modes set to `pixels::TIGHT` (the layout of a list's
    /// unpacked images), then restores them.
    pub(super) fn with_tight_unpack(&mut self, f: impl FnOnce(&mut Self)) {
        let saved = self.driver_unpack();
        let set = |b: &Self, m: &PixelModes| {
            for (pname, v) in [
                (gl::UNPACK_ALIGNMENT, m.alignment),
                (gl::UNPACK_ROW_LENGTH, m.row_length),
                (gl::UNPACK_SKIP_ROWS, m.skip_rows),
                (gl::UNPACK_SKIP_PIXELS, m.skip_pixels),
                (gl::UNPACK_LSB_FIRST, i32::from(m.lsb_first)),
                (gl::UNPACK_SWAP_BYTES, i32::from(m.swap_bytes)),
            ] {
                // SAFETY: context current; no pointers. PixelStore executes immediately, even
                // while a list is being compiled (§5.4).
                unsafe { b.raw.PixelStorei(pname, v) };
            }
        };
        set(self, &crate::pixels::TIGHT);
        f(self);
        set(self, &saved);
    }

    /// An error the backend raises itself for a call the driver does not see: when a list is
    /// being compiled the driver's copy lacks the call, so the list is expanded when it runs
    /// (and the error raised then); otherwise now.
    fn own_error(&mut self, code: u32) {
        self.list_needs_expansion();
        if !self.compile_only() {
            self.raise(code);
        }
    }

    /// Whether PixelMap with these arguments reads `mapsize` values (the driver reads only
    /// when the size is valid), and the GL 2.1 error the backend raises itself, if any.
    fn pixel_map_check(&mut self, map: u32, mapsize: i32, len: usize) -> bool {
        let Ok(n @ 1..=MAX_PIXEL_MAP_TABLE) = usize::try_from(mapsize) else {
            // The driver raises INVALID_VALUE and reads nothing.
            return true;
        };
        if len < n {
            self.own_error(gl::INVALID_VALUE);
            return false;
        }
        if map == gl::PIXEL_MAP_I_TO_I && !n.is_power_of_two() {
            self.own_error(gl::INVALID_VALUE);
            return false;
        }
        true
    }

    /// `glPixelMapfv` with the recorded values.
    pub(super) fn pixel_mapfv(&mut self, map: u32, mapsize: i32, values: &[f32]) {
        if self.pixel_map_check(map, mapsize, values.len()) {
            let one = [0.0f32];
            let p = if values.is_empty() {
                one.as_ptr()
            } else {
                values.as_ptr()
            };
            // SAFETY: context current; the driver reads `mapsize` values only when it is in
            // 1..=MAX_PIXEL_MAP_TABLE, and then `values` holds at least that many (checked).
            unsafe { self.raw.PixelMapfv(map, mapsize, p) };
        }
    }

    /// `glPixelMapuiv` with the recorded values.
    pub(super) fn pixel_mapuiv(&mut self, map: u32, mapsize: i32, values: &[u32]) {
        if self.pixel_map_check(map, mapsize, values.len()) {
            let one = [0u32];
            let p = if values.is_empty() {
                one.as_ptr()
            } else {
                values.as_ptr()
            };
            // SAFETY: as in `pixel_mapfv`.
            unsafe { self.raw.PixelMapuiv(map, mapsize, p) };
        }
    }

    /// `glPixelMapusv` with the recorded values.
    pub(super) fn pixel_mapusv(&mut self, map: u32, mapsize: i32, values: &[u16]) {
        if self.pixel_map_check(map, mapsize, values.len()) {
            let one = [0u16];
            let p = if values.is_empty() {
                one.as_ptr()
            } else {
                values.as_ptr()
            };
            // SAFETY: as in `pixel_mapfv`.
            unsafe { self.raw.PixelMapusv(map, mapsize, p) };
        }
    }

    /// `glBitmap` with the recorded bytes (or NULL).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn bitmap(
        &mut self,
        width: i32,
        height: i32,
        xorig: f32,
        yorig: f32,
        xmove: f32,
        ymove: f32,
        bitmap: Option<&[u8]>,
    ) {
        let p = match bitmap {
            Some(data) if width > 0 && height > 0 => {
                let need = self
                    .driver_unpack()
                    .bitmap_layout(width, height)
                    .map(|l| l.need);
                if need.map_or(true, |n| data.len() < n) {
                    return self.own_error(gl::INVALID_OPERATION);
                }
                data.as_ptr()
            }
            // A negative or empty size reads nothing.
            Some(data) => data.as_ptr(),
            None => std::ptr::null(),
        };
        // SAFETY: context current; `p` is NULL, or the driver reads nothing (a size of 0 or an
        // INVALID_VALUE), or it reads the bitmap's `need` bytes under its own unpack state,
        // which `data` holds (checked above).
        unsafe {
            self.raw
                .Bitmap(width, height, xorig, yorig, xmove, ymove, p)
        };
    }

    /// `glDrawPixels` with the recorded bytes.
    pub(super) fn draw_pixels(
        &mut self,
        width: i32,
        height: i32,
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        if width >= 0 && height >= 0 {
            let f = match check(format, type_) {
                Ok(f) => f,
                Err(code) => return self.own_error(code),
            };
            let need = self
                .driver_unpack()
                .image_layout(f, width, height)
                .map(|l: ImageLayout| l.need());
            if need.map_or(true, |n| pixels.len() < n) {
                return self.own_error(gl::INVALID_OPERATION);
            }
        }
        // SAFETY: context current; with a negative size the driver raises INVALID_VALUE and
        // reads nothing; otherwise it reads the image's `need` bytes under its own unpack state
        // (format and type valid in GL 2.1), which `pixels` holds (checked above).
        unsafe {
            self.raw
                .DrawPixels(width, height, format, type_, pixels.as_ptr().cast())
        };
    }
}
