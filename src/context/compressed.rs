//! GL 1.3's compressed-texture commands (GL 2.1 §3.8.3, §6.1.4): `CompressedTexImage1D/2D/3D`,
//! `CompressedTexSubImage1D/2D/3D` and `GetCompressedTexImage`, for a context that offers no
//! compressed format (NUM_COMPRESSED_TEXTURE_FORMATS 0, COMPRESSED_TEXTURE_FORMATS empty), which
//! GL 1.3 allows.
//!
//! The generic formats of table 3.17 (COMPRESSED_ALPHA, ..., COMPRESSED_RGBA) are taken by
//! TexImage and stored uncompressed (`texture::base_internal_format`), as §3.8.1 says when no
//! specific compressed format is available; so no image is ever compressed, and the commands
//! here can only fail. Which error they give follows Mesa's `teximage.c` and `getteximage.c`
//! (a compatibility context, for a format Mesa does not support), check for check:
//!
//! - CompressedTexImage: outside Begin/End (INVALID_OPERATION), `target` legal for the command
//!   (INVALID_ENUM; Mesa's `legal_teximage_target`, then `_mesa_target_can_be_compressed`, which
//!   no format passes for TEXTURE_1D nor for TEXTURE_3D), then `internalformat` a supported
//!   specific compressed format: none is, and the generic ones never are (§3.8.3), so
//!   INVALID_ENUM. Level, sizes, border and imageSize come later in Mesa's order and are never
//!   reached.
//! - CompressedTexSubImage: Mesa's `compressed_subtexture_target_check` (a 1D target and
//!   anything but TEXTURE_2D / a cube face / TEXTURE_3D is INVALID_ENUM; TEXTURE_3D with a
//!   format that is not BPTC, S3TC or ASTC, that is every format here, is INVALID_OPERATION),
//!   then `compressed_subtexture_error_check`'s first test: a format that is not a supported
//!   compressed format is INVALID_ENUM if it is one of the generic compressed formats, else
//!   INVALID_OPERATION.
//! - GetCompressedTexImage: target (INVALID_ENUM: no proxy, no TEXTURE_CUBE_MAP), level
//!   (INVALID_VALUE), a level without an image INVALID_VALUE for TEXTURE_1D and _2D and
//!   nothing for the others (Mesa's size check, measured), and an uncompressed image
//!   INVALID_OPERATION ("texture is not compressed").
//!
//! Design decision: the checks are pure functions of the arguments ([`compressed_image_error`],
//! [`compressed_sub_image_error`]) shared with the GL backend, which raises fixedgl's error
//! itself for any call the driver, offering S3TC, RGTC and more, could take (`glbackend/
//! compressed.rs`). A display list compiles these calls with their data (Mesa's `dlist.c`
//! copies `imageSize` bytes), except CompressedTexImage with the command's own proxy target
//! (PROXY_TEXTURE_1D, _2D, _3D), which Mesa executes immediately, as GL 2.1 §5.4 says of
//! TexImage with a proxy target (context/lists.rs).

use super::Context;
use crate::call::Call;
use crate::gl;
use crate::texture::{image_binding, MAX_LEVELS};

/// The generic compressed internal formats of GL 2.1 table 3.17 (GL 1.3's six and GL 2.1's
/// four sRGB ones): CompressedTexImage never takes them (§3.8.3), CompressedTexSubImage
/// answers them INVALID_ENUM (Mesa's `_mesa_generic_compressed_format_to_uncompressed_format`,
/// whose GL 3.0 COMPRESSED_RED and COMPRESSED_RG are no enums of GL 2.1).
pub fn is_generic_compressed(format: u32) -> bool {
    matches!(
        format,
        gl::COMPRESSED_ALPHA
            | gl::COMPRESSED_LUMINANCE
            | gl::COMPRESSED_LUMINANCE_ALPHA
            | gl::COMPRESSED_INTENSITY
            | gl::COMPRESSED_RGB
            | gl::COMPRESSED_RGBA
            | gl::COMPRESSED_SRGB
            | gl::COMPRESSED_SRGB_ALPHA
            | gl::COMPRESSED_SLUMINANCE
            | gl::COMPRESSED_SLUMINANCE_ALPHA
    )
}

/// The base internal format a generic compressed format stands for (table 3.17, and what
/// TEXTURE_INTERNAL_FORMAT answers for an image specified with it when no compressed format
/// is chosen: GL 1.3 §3.8.1, Mesa's `_mesa_gl_compressed_format_base_format`), or None.
pub fn generic_compressed_base(format: u32) -> Option<u32> {
    Some(match format {
        gl::COMPRESSED_ALPHA => gl::ALPHA,
        gl::COMPRESSED_LUMINANCE | gl::COMPRESSED_SLUMINANCE => gl::LUMINANCE,
        gl::COMPRESSED_LUMINANCE_ALPHA | gl::COMPRESSED_SLUMINANCE_ALPHA => gl::LUMINANCE_ALPHA,
        gl::COMPRESSED_INTENSITY => gl::INTENSITY,
        gl::COMPRESSED_RGB | gl::COMPRESSED_SRGB => gl::RGB,
        gl::COMPRESSED_RGBA | gl::COMPRESSED_SRGB_ALPHA => gl::RGBA,
        _ => return None,
    })
}

/// Whether `target` is one CompressedTexImage{dims}D takes in GL 2.1 (§3.8.3 refers to
/// TexImage's targets, §3.8.1, proxies included).
pub fn compressed_image_target_ok(dims: usize, target: u32) -> bool {
    match dims {
        1 => matches!(target, gl::TEXTURE_1D | gl::PROXY_TEXTURE_1D),
        2 => {
            matches!(
                target,
                gl::TEXTURE_2D | gl::PROXY_TEXTURE_2D | gl::PROXY_TEXTURE_CUBE_MAP
            ) || (gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                .contains(&target)
        }
        _ => matches!(target, gl::TEXTURE_3D | gl::PROXY_TEXTURE_3D),
    }
}

/// Whether `target` is one CompressedTexSubImage{dims}D takes in GL 2.1 (§3.8.3: TexSubImage's
/// targets, no proxy).
pub fn compressed_sub_image_target_ok(dims: usize, target: u32) -> bool {
    match dims {
        1 => target == gl::TEXTURE_1D,
        2 => {
            target == gl::TEXTURE_2D
                || (gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                    .contains(&target)
        }
        _ => target == gl::TEXTURE_3D,
    }
}

/// The error CompressedTexImage{dims}D raises outside Begin/End (see the module docs): an
/// illegal target, then an `internal_format` that is no supported specific compressed format,
/// which with no format supported is every one. Always INVALID_ENUM; written as Mesa's two
/// checks so that the reason is the spec's.
pub fn compressed_image_error(dims: usize, target: u32, internal_format: u32) -> u32 {
    if !compressed_image_target_ok(dims, target) {
        return gl::INVALID_ENUM;
    }
    // §3.8.3: "internalformat must be a supported specific compressed internal format"; the
    // generic ones (table 3.17) are INVALID_ENUM by name, and no other is supported.
    let _ = internal_format;
    gl::INVALID_ENUM
}

/// The error CompressedTexSubImage{dims}D raises outside Begin/End (see the module docs).
pub fn compressed_sub_image_error(dims: usize, target: u32, format: u32) -> u32 {
    // Mesa's `compressed_subtexture_target_check`: no 1D compressed image exists; a 3D one only
    // in BPTC, S3TC or ASTC formats, none of which is offered.
    if dims == 1 || !compressed_sub_image_target_ok(dims, target) {
        return gl::INVALID_ENUM;
    }
    if dims == 3 {
        return gl::INVALID_OPERATION;
    }
    // §3.8.3: the format must match the image's, which is never compressed here; a generic
    // format is INVALID_ENUM by name.
    if is_generic_compressed(format) {
        gl::INVALID_ENUM
    } else {
        gl::INVALID_OPERATION
    }
}

impl Context {
    /// `glCompressedTexImage1D` (§3.8.3). No compressed format is supported, so every call is
    /// an error: INVALID_OPERATION between Begin and End, else INVALID_ENUM
    /// ([`compressed_image_error`]); nothing changes, proxies included.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: u32,
        width: i32,
        border: i32,
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexImage1D(Box::new((
                target,
                level,
                internal_format,
                width,
                border,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_image(1, target, internal_format);
    }

    /// `glCompressedTexImage2D` (§3.8.3): as [`Context::compressed_tex_image_1d`] (targets
    /// TEXTURE_2D, PROXY_TEXTURE_2D, the cube-map faces and PROXY_TEXTURE_CUBE_MAP).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: u32,
        width: i32,
        height: i32,
        border: i32,
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexImage2D(Box::new((
                target,
                level,
                internal_format,
                width,
                height,
                border,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_image(2, target, internal_format);
    }

    /// `glCompressedTexImage3D` (§3.8.3): as [`Context::compressed_tex_image_1d`] (targets
    /// TEXTURE_3D, PROXY_TEXTURE_3D).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: u32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexImage3D(Box::new((
                target,
                level,
                internal_format,
                width,
                height,
                depth,
                border,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_image(3, target, internal_format);
    }

    /// `glCompressedTexSubImage1D` (§3.8.3). No image is ever compressed, so every call is an
    /// error: INVALID_OPERATION between Begin and End, else [`compressed_sub_image_error`]
    /// (INVALID_ENUM for every 1D call, as Mesa: no 1D compressed format exists).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_1d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        width: i32,
        format: u32,
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexSubImage1D(Box::new((
                target,
                level,
                xoffset,
                width,
                format,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_sub_image(1, target, format);
    }

    /// `glCompressedTexSubImage2D` (§3.8.3): as [`Context::compressed_tex_sub_image_1d`]; on
    /// TEXTURE_2D or a cube-map face a generic compressed `format` is INVALID_ENUM, any other
    /// INVALID_OPERATION (it cannot match the image's uncompressed format).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexSubImage2D(Box::new((
                target,
                level,
                xoffset,
                yoffset,
                width,
                height,
                format,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_sub_image(2, target, format);
    }

    /// `glCompressedTexSubImage3D` (§3.8.3): as [`Context::compressed_tex_sub_image_1d`]; on
    /// TEXTURE_3D every format is INVALID_OPERATION (Mesa: no offered format has 3D images).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_3d(
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
        image_size: i32,
        data: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::CompressedTexSubImage3D(Box::new((
                target,
                level,
                xoffset,
                yoffset,
                zoffset,
                width,
                height,
                depth,
                format,
                image_size,
                data.map(<[u8]>::to_vec),
            )))
        );
        self.compressed_sub_image(3, target, format);
    }

    /// CompressedTexImage after recording: the error, and nothing else.
    fn compressed_image(&mut self, dims: usize, target: u32, internal_format: u32) {
        if self.outside_begin_end() {
            self.error(compressed_image_error(dims, target, internal_format));
        }
    }

    /// CompressedTexSubImage after recording: the error, and nothing else.
    fn compressed_sub_image(&mut self, dims: usize, target: u32, format: u32) {
        if self.outside_begin_end() {
            self.error(compressed_sub_image_error(dims, target, format));
        }
    }

    /// `glGetCompressedTexImage` (§6.1.4): would write level `level` of the bound texture of
    /// `target` as stored, compressed. INVALID_OPERATION between Begin and End; a target other
    /// than TEXTURE_1D, _2D, _3D or a cube-map face is INVALID_ENUM; a level outside
    /// [0, MAX_LEVELS) is INVALID_VALUE; a level without an image is INVALID_VALUE for
    /// TEXTURE_1D and _2D and nothing for TEXTURE_3D and the faces (Mesa's answers); any image
    /// is uncompressed here, which is INVALID_OPERATION (as Mesa). `img` is never written.
    pub fn get_compressed_tex_image(&mut self, target: u32, level: i32, img: &mut [u8]) {
        let _ = img;
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.pull_objects();
        if !matches!(target, gl::TEXTURE_1D | gl::TEXTURE_2D | gl::TEXTURE_3D)
            && !(gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                .contains(&target)
        {
            return self.error(gl::INVALID_ENUM);
        }
        if level < 0 || level >= MAX_LEVELS as i32 {
            return self.error(gl::INVALID_VALUE);
        }
        let unit = self.state.active_texture;
        let (bind, face) = image_binding(target);
        let has_image = self
            .state
            .textures
            .bound(unit, bind)
            .and_then(|o| o.face_level(face, level))
            .is_some();
        // A level without an image: Mesa checks the whole image's size as a sub-image of 0 x 0
        // x 0 (`dimensions_error_check`), in which a 1D image must be 1 high and a 2D one 1
        // deep: INVALID_VALUE for TEXTURE_1D and _2D, nothing for a cube face or TEXTURE_3D
        // (measured on llvmpipe: tests/it/compressed_gl.rs). An image is never compressed.
        if has_image {
            self.error(gl::INVALID_OPERATION);
        } else if matches!(target, gl::TEXTURE_1D | gl::TEXTURE_2D) {
            self.error(gl::INVALID_VALUE);
        }
    }
}
