//! Replay of the texture entry points whose client memory the driver reads through a pointer
//! (GL 2.1 §3.8.1, §3.8.2, §3.8.12): GenTextures, DeleteTextures, TexImage1D/2D/3D,
//! TexSubImage1D/2D/3D.
//!
//! Design decision: the driver must never read past the recorded bytes. The bytes an image needs
//! are computed from the driver's own unpack state (alignment, row length, skipped rows and
//! pixels, queried at the call); a recording whose data is shorter gets the front end's
//! INVALID_OPERATION (see `context::texture`) without the driver seeing the pointer, unless the
//! arguments are in error anyway, in which case the driver is called with NULL so that it raises
//! its own error and reads nothing.

use super::GlBackend;
use crate::context::texture::{
    is_proxy, tex_image_args_error, tex_image_nd_args_error, MAX_GEN_TEXTURES,
};
use crate::gl;
use crate::pixel_store::PixelModes;
use crate::pixels::check;
use crate::texture::image_need3;

impl GlBackend {
    /// The bytes the driver reads for a `width` x `height` image of `format` / `type_` under
    /// its current unpack state (the same `texture::image_need3` the CPU front end uses, from
    /// the driver's own values), or None for a format or type this crate does not unpack or a
    /// layout whose size overflows (no recording holds that many bytes). SWAP_BYTES, LSB_FIRST,
    /// IMAGE_HEIGHT and SKIP_IMAGES change nothing a 2D image reads.
    fn driver_unpack_need(
        &self,
        width: i32,
        height: i32,
        format: u32,
        type_: u32,
    ) -> Option<usize> {
        self.driver_unpack_need3(width, height, 1, false, format, type_)
    }

    /// [`Self::driver_unpack_need`] for `depth` images of `width` x `height` (TexImage3D,
    /// `three_d`: IMAGE_HEIGHT and SKIP_IMAGES place the images) or a 1D/2D image (depth 1).
    fn driver_unpack_need3(
        &self,
        width: i32,
        height: i32,
        depth: i32,
        three_d: bool,
        format: u32,
        type_: u32,
    ) -> Option<usize> {
        let f = check(format, type_).ok()?;
        let mut v = [0i32; 6];
        for (slot, pname) in v.iter_mut().zip([
            gl::UNPACK_ALIGNMENT,
            gl::UNPACK_ROW_LENGTH,
            gl::UNPACK_SKIP_ROWS,
            gl::UNPACK_SKIP_PIXELS,
            gl::UNPACK_IMAGE_HEIGHT,
            gl::UNPACK_SKIP_IMAGES,
        ]) {
            // SAFETY: context current (execute made it so); GetIntegerv writes one value.
            unsafe { self.raw.GetIntegerv(pname, slot) };
        }
        let modes = PixelModes {
            alignment: v[0],
            row_length: v[1],
            skip_rows: v[2],
            skip_pixels: v[3],
            image_height: if three_d { v[4] } else { 0 },
            skip_images: if three_d { v[5] } else { 0 },
            ..PixelModes::default()
        };
        image_need3(&modes, f, width, height, depth, three_d)
    }

    /// `glGenTextures(n)` with a scratch buffer for the names (the front end's bound on n).
    pub(super) fn gen_textures(&mut self, n: i32) {
        if n > MAX_GEN_TEXTURES {
            return self.raise(gl::OUT_OF_MEMORY);
        }
        let mut names = vec![0u32; n.max(1) as usize];
        // SAFETY: `names` holds at least max(n, 1) values; with n < 0 the driver writes nothing.
        unsafe { self.raw.GenTextures(n, names.as_mut_ptr()) };
    }

    /// `glDeleteTextures(n, names)`: a slice shorter than n is INVALID_VALUE, as in the front end.
    pub(super) fn delete_textures(&mut self, n: i32, names: &[u32]) {
        if n > 0 && names.len() < n as usize && !self.inside_begin_end {
            return self.raise(gl::INVALID_VALUE);
        }
        let one = [0u32];
        let p = if names.is_empty() {
            one.as_ptr()
        } else {
            names.as_ptr()
        };
        let n = if names.len() < n.max(0) as usize {
            0
        } else {
            n
        };
        // SAFETY: the driver reads at most n <= names.len() names (0 inside Begin/End when short).
        unsafe { self.raw.DeleteTextures(n, p) };
    }

    /// `glTexImage2D` with the recorded pixels (or NULL).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        let raw = &self.raw;
        let call = |p: *const u8| {
            // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
            unsafe {
                raw.TexImage2D(
                    target,
                    level,
                    internal,
                    width,
                    height,
                    border,
                    format,
                    type_,
                    p.cast(),
                )
            }
        };
        let bad = self.inside_begin_end
            || tex_image_args_error(
                target, level, internal, width, height, border, format, type_,
            )
            .is_some();
        match pixels {
            None => call(std::ptr::null()),
            // A proxy reads no pixels (§3.8.1): the driver gets NULL.
            Some(_) if bad || is_proxy(target) => call(std::ptr::null()),
            Some(p) => match self.driver_unpack_need(width, height, format, type_) {
                Some(need) if p.len() >= need => call(p.as_ptr()),
                _ => self.raise(gl::INVALID_OPERATION),
            },
        }
    }

    /// `glTexSubImage2D` with the recorded pixels. Short data: the driver is called with NULL,
    /// which Mesa treats as nothing to copy after its own checks, so its error (if any) comes
    /// first, else the front end's INVALID_OPERATION.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        let enough = !self.inside_begin_end
            && self
                .driver_unpack_need(width, height, format, type_)
                .is_some_and(|need| pixels.len() >= need);
        let p = if enough {
            pixels.as_ptr()
        } else {
            std::ptr::null()
        };
        // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
        unsafe {
            self.raw.TexSubImage2D(
                target,
                level,
                xoffset,
                yoffset,
                width,
                height,
                format,
                type_,
                p.cast(),
            )
        };
        if !enough && !self.inside_begin_end {
            // SAFETY: context current; outside Begin/End a plain read of the flag.
            let e = unsafe { self.raw.GetError() };
            self.raise(if e == gl::NO_ERROR {
                gl::INVALID_OPERATION
            } else {
                e
            });
        }
    }

    /// `glTexImage1D` with the recorded pixels (or NULL), as [`Self::tex_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        width: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        let raw = &self.raw;
        let call = |p: *const u8| {
            // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
            unsafe {
                raw.TexImage1D(
                    target,
                    level,
                    internal,
                    width,
                    border,
                    format,
                    type_,
                    p.cast(),
                )
            }
        };
        let bad = self.inside_begin_end
            || tex_image_nd_args_error(
                1,
                target,
                level,
                internal,
                [width, 1, 1],
                border,
                format,
                type_,
            )
            .is_some();
        match pixels {
            None => call(std::ptr::null()),
            // A proxy reads no pixels (§3.8.1): the driver gets NULL.
            Some(_) if bad || is_proxy(target) => call(std::ptr::null()),
            Some(p) => match self.driver_unpack_need(width, 1, format, type_) {
                Some(need) if p.len() >= need => call(p.as_ptr()),
                _ => self.raise(gl::INVALID_OPERATION),
            },
        }
    }

    /// `glTexImage3D` with the recorded pixels (or NULL), as [`Self::tex_image_2d`]; the
    /// bytes the driver reads include IMAGE_HEIGHT and SKIP_IMAGES.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        let raw = &self.raw;
        let call = |p: *const u8| {
            // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
            unsafe {
                raw.TexImage3D(
                    target,
                    level,
                    internal,
                    width,
                    height,
                    depth,
                    border,
                    format,
                    type_,
                    p.cast(),
                )
            }
        };
        let bad = self.inside_begin_end
            || tex_image_nd_args_error(
                3,
                target,
                level,
                internal,
                [width, height, depth],
                border,
                format,
                type_,
            )
            .is_some();
        match pixels {
            None => call(std::ptr::null()),
            // A proxy reads no pixels (§3.8.1): the driver gets NULL.
            Some(_) if bad || is_proxy(target) => call(std::ptr::null()),
            Some(p) => match self.driver_unpack_need3(width, height, depth, true, format, type_) {
                Some(need) if p.len() >= need => call(p.as_ptr()),
                _ => self.raise(gl::INVALID_OPERATION),
            },
        }
    }

    /// After a sub-image call made with NULL because the recorded data was short: the
    /// driver's own error if it raised one, else the front end's INVALID_OPERATION.
    fn short_sub_image(&mut self, enough: bool) {
        if !enough && !self.inside_begin_end {
            // SAFETY: context current; outside Begin/End a plain read of the flag.
            let e = unsafe { self.raw.GetError() };
            self.raise(if e == gl::NO_ERROR {
                gl::INVALID_OPERATION
            } else {
                e
            });
        }
    }

    /// `glTexSubImage1D` with the recorded pixels, as [`Self::tex_sub_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_sub_image_1d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        width: i32,
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        let enough = !self.inside_begin_end
            && self
                .driver_unpack_need(width, 1, format, type_)
                .is_some_and(|need| pixels.len() >= need);
        let p = if enough {
            pixels.as_ptr()
        } else {
            std::ptr::null()
        };
        // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
        unsafe {
            self.raw
                .TexSubImage1D(target, level, xoffset, width, format, type_, p.cast())
        };
        self.short_sub_image(enough);
    }

    /// `glTexSubImage3D` with the recorded pixels, as [`Self::tex_sub_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        width: i32,
        height: i32,
        depth: i32,
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        let enough = !self.inside_begin_end
            && self
                .driver_unpack_need3(width, height, depth, true, format, type_)
                .is_some_and(|need| pixels.len() >= need);
        let p = if enough {
            pixels.as_ptr()
        } else {
            std::ptr::null()
        };
        // SAFETY: `p` is NULL or points to at least as many bytes as the driver reads.
        unsafe {
            self.raw.TexSubImage3D(
                target,
                level,
                xoffset,
                yoffset,
                zoffset,
                width,
                height,
                depth,
                format,
                type_,
                p.cast(),
            )
        };
        self.short_sub_image(enough);
    }
}

impl GlBackend {
    /// `glPrioritizeTextures(n, textures, priorities)`: slices shorter than n are INVALID_VALUE
    /// without the driver reading them, as in the front end.
    pub(super) fn prioritize_textures(&mut self, n: i32, textures: &[u32], priorities: &[f32]) {
        let count = usize::try_from(n).unwrap_or(0);
        if (textures.len() < count || priorities.len() < count) && !self.inside_begin_end {
            return self.raise(gl::INVALID_VALUE);
        }
        let n = if textures.len() < count || priorities.len() < count {
            0
        } else {
            n
        };
        let (t, p) = ([0u32], [0f32]);
        let tp = if textures.is_empty() {
            t.as_ptr()
        } else {
            textures.as_ptr()
        };
        let pp = if priorities.is_empty() {
            p.as_ptr()
        } else {
            priorities.as_ptr()
        };
        // SAFETY: the driver reads at most n values of each, and n <= both lengths (0 inside
        // Begin/End when short, where the driver only raises INVALID_OPERATION).
        unsafe { self.raw.PrioritizeTextures(n, tp, pp) };
    }
}
