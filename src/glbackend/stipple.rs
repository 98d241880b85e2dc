//! Polygon stipple on the driver (GL 2.1 §3.5.6): the recorded mask goes to the driver only
//! when it holds every byte the driver's unpack modes make it read.

use super::GlBackend;
use crate::gl;
use crate::pixel_store::PixelModes;

impl GlBackend {
    /// `PolygonStipple(mask)`: INVALID_OPERATION, raised here as the front end raises it, when
    /// `mask` is shorter than the driver's unpack modes read (between Begin and End `execute`
    /// has raised INVALID_OPERATION already).
    pub(super) fn polygon_stipple(&mut self, mask: &[u8]) {
        let mut v = [0i32; 5];
        for (slot, pname) in v.iter_mut().zip([
            gl::UNPACK_ALIGNMENT,
            gl::UNPACK_ROW_LENGTH,
            gl::UNPACK_SKIP_ROWS,
            gl::UNPACK_SKIP_PIXELS,
            gl::UNPACK_LSB_FIRST,
        ]) {
            // SAFETY: context current (execute made it so); GetIntegerv writes one value.
            unsafe { self.raw.GetIntegerv(pname, slot) };
        }
        let modes = PixelModes {
            alignment: v[0],
            row_length: v[1],
            skip_rows: v[2],
            skip_pixels: v[3],
            lsb_first: v[4] != 0,
            ..PixelModes::default()
        };
        match crate::context::stipple::polygon_stipple_bytes(&modes) {
            Some(need) if mask.len() >= need => {
                // SAFETY: `mask` holds every byte the driver's unpack modes read.
                unsafe { self.raw.PolygonStipple(mask.as_ptr()) }
            }
            _ => {
                // lists: the driver's list would lack the call; its error comes when it runs.
                self.list_needs_expansion();
                if !self.compile_only() {
                    self.raise(gl::INVALID_OPERATION);
                }
            }
        }
    }
}
