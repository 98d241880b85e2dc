//! The compressed-texture commands on the driver (GL 2.1 §3.8.3): fixedgl offers no compressed
//! format (context/compressed.rs), while the driver offers several (llvmpipe: S3TC, RGTC,
//! LATC, BPTC, ...) and takes GL 3.0+ targets (TEXTURE_2D_ARRAY, ...). A call the driver could
//! therefore answer differently gets fixedgl's error, raised here, and never reaches the driver,
//! in the way `replay::gl21_error` raises the GL 2.1 errors a newer driver relaxes.
//!
//! Design decision: a call goes to the driver only when its format is one fixedgl knows as an
//! uncompressed internal format (the formats TexImage takes, the generic COMPRESSED_* among
//! them: `texture::base_internal_format`), its target is not a GL 3.0+ one, and its data holds
//! `imageSize` bytes. Then the driver, by Mesa's checks, refuses it exactly as fixedgl does, and
//! the tests hold the two errors equal (tests/it/compressed_gl.rs); every other call would
//! differ only where the driver knows more than GL 2.1 with no compressed format.

use super::GlBackend;
use crate::context::compressed::{compressed_image_error, compressed_sub_image_error};
use crate::texture::base_internal_format;
use crate::Call;

/// The targets of GL 3.0 and later extensions a compatibility driver takes for texture images
/// (rectangle, 1D and 2D arrays, cube-map arrays, with their proxies).
fn newer_target(target: u32) -> bool {
    matches!(
        target,
        0x84F5 | 0x84F7 | 0x8C18 | 0x8C19 | 0x8C1A | 0x8C1B | 0x9009 | 0x900B
    )
}

/// Whether `format` is one fixedgl stores uncompressed (so no driver takes it as compressed).
fn uncompressed(format: u32) -> bool {
    i32::try_from(format).is_ok_and(|f| base_internal_format(f).is_some())
}

/// Whether `data` holds the `image_size` bytes the driver may read (NULL reads none).
fn holds(data: &Option<Vec<u8>>, image_size: i32) -> bool {
    data.as_ref().map_or(true, |d| {
        d.len() >= usize::try_from(image_size).unwrap_or(0)
    })
}

/// The data pointer for the driver: NULL or the recorded bytes.
fn ptr(data: &Option<Vec<u8>>) -> *const std::ffi::c_void {
    data.as_ref()
        .map_or(std::ptr::null(), |d| d.as_ptr().cast())
}

impl GlBackend {
    /// `CompressedTexImage1D/2D/3D` and `CompressedTexSubImage1D/2D/3D` (see the module docs).
    pub(super) fn compressed_image(&mut self, call: &Call) {
        // (dims, target, format, imageSize, data, sub-image?)
        let (dims, target, format, size, data, sub): (usize, u32, u32, i32, _, bool) = match call {
            Call::CompressedTexImage1D(a) => (1, a.0, a.2, a.5, &a.6, false),
            Call::CompressedTexImage2D(a) => (2, a.0, a.2, a.6, &a.7, false),
            Call::CompressedTexImage3D(a) => (3, a.0, a.2, a.7, &a.8, false),
            Call::CompressedTexSubImage1D(a) => (1, a.0, a.4, a.5, &a.6, true),
            Call::CompressedTexSubImage2D(a) => (2, a.0, a.6, a.7, &a.8, true),
            Call::CompressedTexSubImage3D(a) => (3, a.0, a.8, a.9, &a.10, true),
            _ => return,
        };
        let to_driver = uncompressed(format) && !newer_target(target) && holds(data, size);
        if !to_driver {
            // Outside Begin/End (`execute` raised INVALID_OPERATION there already).
            // lists: the driver's list would hold the call without fixedgl's error.
            self.list_needs_expansion();
            if self.compile_only() && !crate::context::proxy_image(call) {
                return;
            }
            let code = if sub {
                compressed_sub_image_error(dims, target, format)
            } else {
                compressed_image_error(dims, target, format)
            };
            return self.raise(code);
        }
        let (raw, p) = (&self.raw, ptr(data));
        // SAFETY: the context is current (`execute`); `p` is NULL or the recorded bytes, at
        // least `imageSize` of them (`holds`), all the driver reads.
        unsafe {
            match call {
                Call::CompressedTexImage1D(a) => {
                    raw.CompressedTexImage1D(a.0, a.1, a.2, a.3, a.4, a.5, p)
                }
                Call::CompressedTexImage2D(a) => {
                    raw.CompressedTexImage2D(a.0, a.1, a.2, a.3, a.4, a.5, a.6, p)
                }
                Call::CompressedTexImage3D(a) => {
                    raw.CompressedTexImage3D(a.0, a.1, a.2, a.3, a.4, a.5, a.6, a.7, p)
                }
                Call::CompressedTexSubImage1D(a) => {
                    raw.CompressedTexSubImage1D(a.0, a.1, a.2, a.3, a.4, a.5, p)
                }
                Call::CompressedTexSubImage2D(a) => {
                    raw.CompressedTexSubImage2D(a.0, a.1, a.2, a.3, a.4, a.5, a.6, a.7, p)
                }
                Call::CompressedTexSubImage3D(a) => {
                    raw.CompressedTexSubImage3D(a.0, a.1, a.2, a.3, a.4, a.5, a.6, a.7, a.8, a.9, p)
                }
                _ => {}
            }
        }
    }
}
