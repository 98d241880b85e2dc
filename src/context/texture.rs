//! Texture objects and images: `GenTextures`, `DeleteTextures`, `IsTexture`, `BindTexture`,
//! `TexImage1D/2D/3D`, `TexSubImage1D/2D/3D`, `CopyTexImage1D/2D`, `CopyTexSubImage1D/2D/3D`,
//! `GetTexImage`
//! (GL 2.1 §3.8.1, §3.8.2, §3.8.12, §6.1.4).
//!
//! Objects of every GL 1.3 target exist (TEXTURE_1D, _2D, _3D, _CUBE_MAP: BindTexture, the
//! bindings, parameters, deletion); images for TEXTURE_1D, _2D, _3D and the six faces of
//! TEXTURE_CUBE_MAP (TexImage1D/2D/3D, TexSubImage1D/2D/3D, CopyTexImage1D/2D,
//! CopyTexSubImage1D/2D/3D; the faces through the 2D commands, square). The proxy targets
//! (§3.8.1) take TexImage1D/2D/3D and keep only level state (`Textures::proxies`); a border of
//! 1 is stripped off real images as Mesa does for llvmpipe ([`strip_border`]). Client pixels are `Option<&[u8]>` (`None` is GL's NULL: the image
//! is allocated with undefined, here zero, contents); FLOAT data is native-endian bytes
//! (`texture::f32_bytes`). Every format and type DrawPixels takes is read exactly as DrawPixels
//! reads it (`crate::pixels`: the packed types, COLOR_INDEX and BITMAP through the I_TO_* maps,
//! the pixel transfer), and GetTexImage packs as ReadPixels packs.
//!
//! Design decision: a slice shorter than the unpack parameters say the image needs is
//! INVALID_OPERATION with nothing changed, the error GL gives for a read past the end of a
//! pixel unpack buffer (§2.9.2) and ARB_robustness for a short client buffer; the recorded call
//! carries exactly the bytes passed, and the GL backend raises the same error without calling
//! the driver. GenTextures hands out the smallest names above every name in use, as Mesa does, so
//! a replay on the driver gets the same names.

use std::sync::Arc;

use super::readback::{store, Value};
use super::Context;
use crate::call::Call;
use crate::cpu::pixels::row_runs;
use crate::gl;
use crate::pixels::{check, Group, Image, Slot};
use crate::texture::{
    as_rgba, base_internal_format, image_binding, image_need3, is_depth, proxy_index, quantize,
    slice_layout, target_index, unpack_into, Level, ProxyLevel, TexObject, MAX_LEVELS,
    MAX_TEXTURE_SIZE,
};

/// What `write_box` writes into a texture image.
#[derive(Clone, Copy)]
enum BoxSrc<'a> {
    /// Texels, rows of the box's width.
    Texels(&'a [[f32; 4]]),
    /// The window's framebuffer rectangle at (x, y) the size of the box, as `read_fb` reads it
    /// for base format `base` (CopyTexSubImage).
    Window { x: i32, y: i32, base: u32 },
}

/// Most names one GenTextures call hands out; more is OUT_OF_MEMORY (a bound on memory).
pub const MAX_GEN_TEXTURES: i32 = 1 << 16;

/// The error `TexImage2D` raises for these arguments before looking at state or data, if any
/// (GL 2.1 §3.8.1): shared by the front end and the GL backend's replay.
#[allow(clippy::too_many_arguments)]
#[cfg_attr(not(feature = "gl"), allow(dead_code))]
pub fn tex_image_args_error(
    target: u32,
    level: i32,
    internal_format: i32,
    width: i32,
    height: i32,
    border: i32,
    format: u32,
    type_: u32,
) -> Option<u32> {
    tex_image_nd_args_error(
        2,
        target,
        level,
        internal_format,
        [width, height, 1],
        border,
        format,
        type_,
    )
}

/// Is `target` one TexImage{dims}D takes: TEXTURE_1D / PROXY_TEXTURE_1D, TEXTURE_3D /
/// PROXY_TEXTURE_3D, or TEXTURE_2D, the six cube-map faces, PROXY_TEXTURE_2D and
/// PROXY_TEXTURE_CUBE_MAP (GL 2.1 §3.8.1)?
fn image_target_ok(dims: usize, target: u32) -> bool {
    match dims {
        1 => matches!(target, gl::TEXTURE_1D | gl::PROXY_TEXTURE_1D),
        3 => matches!(target, gl::TEXTURE_3D | gl::PROXY_TEXTURE_3D),
        _ => {
            matches!(
                target,
                gl::TEXTURE_2D | gl::PROXY_TEXTURE_2D | gl::PROXY_TEXTURE_CUBE_MAP
            ) || (gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                .contains(&target)
        }
    }
}

/// Is `target` one of the proxy targets of §3.8.1 (PROXY_TEXTURE_1D, _2D, _3D, _CUBE_MAP)?
pub fn is_proxy(target: u32) -> bool {
    matches!(
        target,
        gl::PROXY_TEXTURE_1D
            | gl::PROXY_TEXTURE_2D
            | gl::PROXY_TEXTURE_3D
            | gl::PROXY_TEXTURE_CUBE_MAP
    )
}

/// Whether a TexImage{dims}D image of `size` (border included) with `border` fits level
/// `level` of `target` (Mesa's `_mesa_legal_texture_dimensions`): each of the command's
/// dimensions between 2·border and 2·border + MAX_TEXTURE_SIZE >> level (any size between:
/// ARB_texture_non_power_of_two, which Mesa offers in every context), cube-map faces square.
/// A real target that fails this is INVALID_VALUE; a proxy gets a zeroed level instead (§3.8.1).
pub fn legal_dimensions(dims: usize, target: u32, level: i32, size: [i32; 3], border: i32) -> bool {
    let max = MAX_TEXTURE_SIZE >> level.clamp(0, 31);
    let fits = size
        .iter()
        .take(dims)
        .all(|&n| n >= 2 * border && n - 2 * border <= max);
    let cube = dims == 2 && !matches!(target, gl::TEXTURE_2D | gl::PROXY_TEXTURE_2D);
    fits && !(cube && size[0] != size[1])
}

/// The error `TexImage1D` (dims 1), `TexImage2D` (2) or `TexImage3D` (3) raises for these
/// arguments before looking at state or data (GL 2.1 §3.8.1); `size` is width, height, depth
/// (1 for the dimensions the command does not have), border included. A proxy target's
/// sizes that do not fit ([`legal_dimensions`]) are no error here.
#[allow(clippy::too_many_arguments)]
pub fn tex_image_nd_args_error(
    dims: usize,
    target: u32,
    level: i32,
    internal_format: i32,
    size: [i32; 3],
    border: i32,
    format: u32,
    type_: u32,
) -> Option<u32> {
    if !image_target_ok(dims, target) {
        return Some(gl::INVALID_ENUM);
    }
    // The format and type as DrawPixels takes them (§3.8.1 refers to §3.6.4; Mesa's order):
    // INVALID_ENUM, or INVALID_OPERATION for a packed type the format does not fit.
    let f = match check(format, type_) {
        Ok(f) => f,
        Err(code) => return Some(code),
    };
    if level < 0 || level >= MAX_LEVELS as i32 {
        return Some(gl::INVALID_VALUE);
    }
    let Some(base) = base_internal_format(internal_format) else {
        return Some(gl::INVALID_VALUE);
    };
    // §3.8.1: border 0 or 1 (Mesa strips a border of 1 off the image: `tex_image`).
    if !(0..=1).contains(&border) || size.iter().any(|&n| n < 0) {
        return Some(gl::INVALID_VALUE);
    }
    // §3.8.1: depth data only into a depth format, and a depth format only from depth data;
    // depth textures only for the 1D and 2D targets.
    if !formats_agree(f.group, base) {
        return Some(gl::INVALID_OPERATION);
    }
    if dims == 3 && is_depth(base) {
        return Some(gl::INVALID_OPERATION);
    }
    if !is_proxy(target) && !legal_dimensions(dims, target, level, size, border) {
        return Some(gl::INVALID_VALUE);
    }
    None
}

/// The image Mesa keeps of an image specified with a border of 1 (`strip_texture_border`,
/// which its gallium drivers, llvmpipe among them, ask for: `StripTextureBorder`): the border
/// texels dropped, width - 2 wide, height - 2 high and depth - 2 deep where that dimension is
/// at least 3 (a 2-high image keeps its two rows, as Mesa does), the level then a border-0
/// image. GL 2.1 §3.8.1/§3.8.8 would keep and sample the border texels; Mesa's comment calls
/// stripping "fast but wrong", and llvmpipe is the reference here (docs/conformance.md §3.8).
pub fn strip_border(lv: Level) -> Level {
    let (w, h, d) = (lv.width, lv.height, lv.depth);
    let nw = (w - 2).max(0);
    let (nh, y0) = if h >= 3 { (h - 2, 1) } else { (h, 0) };
    let (nd, z0) = if d >= 3 { (d - 2, 1) } else { (d, 0) };
    let mut texels = Vec::with_capacity(nw as usize * nh as usize * nd as usize);
    for k in z0..z0 + nd {
        for j in y0..y0 + nh {
            for i in 1..1 + nw {
                texels.push(lv.texel3(i, j, k));
            }
        }
    }
    Level {
        width: nw,
        height: nh,
        depth: nd,
        texels: texels.into(),
        ..lv
    }
}

/// Whether client data of `group` may specify a texture of base format `base` (§3.8.1, as
/// Mesa's `texture_formats_agree`): depth data only for a depth format and the reverse; colour
/// data and colour indices (made RGBA through the I_TO_* maps) for a colour format; never
/// stencil indices (INVALID_OPERATION, Mesa's error for a format no texture takes).
/// GL_EXT_packed_depth_stencil's DEPTH_STENCIL data counts as depth data, as Mesa counts it: a
/// DEPTH_COMPONENT texture takes its depths, the indices dropped; a DEPTH_STENCIL texture takes
/// both, and DEPTH_COMPONENT data too (measured on llvmpipe).
fn formats_agree(group: Group, base: u32) -> bool {
    match group {
        Group::Depth | Group::DepthStencil => is_depth(base),
        Group::Color(_) | Group::Index => !is_depth(base),
        Group::Stencil => false,
    }
}

/// Most texels one image may hold: MAX_TEXTURE_SIZE² (64 MiB of `f32` texels); a larger 3D
/// image is OUT_OF_MEMORY (a bound on memory: 2048³ texels would be 128 GiB).
pub const MAX_IMAGE_TEXELS: usize = (MAX_TEXTURE_SIZE as usize) * (MAX_TEXTURE_SIZE as usize);

impl Context {
    /// `glGenTextures`: writes `n` unused names to the front of `textures`. `n < 0` or
    /// `textures` shorter than `n` is INVALID_VALUE; more than [`MAX_GEN_TEXTURES`] at once is
    /// OUT_OF_MEMORY.
    pub fn gen_textures(&mut self, n: i32, textures: &mut [u32]) {
        record!(self, Call::GenTextures(n));
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if n < 0 || textures.len() < n as usize {
            return self.error(gl::INVALID_VALUE);
        }
        self.gen_names(n, textures);
    }

    /// GenTextures without an output slice (replay): the names are taken all the same.
    pub(crate) fn gen_names(&mut self, n: i32, out: &mut [u32]) {
        self.objects_txn(super::share::TEXTURES, &[], |ctx| ctx.gen_names_now(n, out));
    }

    fn gen_names_now(&mut self, n: i32, out: &mut [u32]) {
        if n < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if n > MAX_GEN_TEXTURES {
            return self.error(gl::OUT_OF_MEMORY);
        }
        let t = &mut self.state.textures;
        let top = t
            .names
            .last()
            .max(t.objects.keys().last().copied())
            .unwrap_or(0);
        if u64::from(top) + n as u64 > u64::from(u32::MAX) {
            return self.error(gl::OUT_OF_MEMORY);
        }
        if n == 0 {
            return;
        }
        // One run for the whole call (issue #11: a set entry per name made 38 KB of
        // GenTextures(65536) lines cost 1.66 GB); only the caller's slice is per name.
        t.names.insert_range(top + 1, top + n as u32);
        for (k, o) in out.iter_mut().take(n as usize).enumerate() {
            *o = top + 1 + k as u32;
        }
    }

    /// `glDeleteTextures`: the first `n` names of `textures`; unused names and 0 are ignored, a
    /// bound texture reverts every unit's binding of every target that holds it to 0 (§3.8.12).
    /// `n < 0` or a short slice is INVALID_VALUE.
    pub fn delete_textures(&mut self, n: i32, textures: &[u32]) {
        record!(self, Call::DeleteTextures(n, textures.to_vec()));
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            ctx.delete_textures_now(n, textures)
        });
    }

    fn delete_textures_now(&mut self, n: i32, textures: &[u32]) {
        if !self.outside_begin_end() {
            return;
        }
        if n < 0 || textures.len() < n as usize {
            return self.error(gl::INVALID_VALUE);
        }
        // A texture attached to the bound framebuffer object is detached first (GL 3.0
        // §4.4.2), what was drawn into it stored.
        self.fbo_store();
        for &name in textures.iter().take(n as usize) {
            self.fbo_detach_texture(name);
        }
        self.fbo_load();
        let t = &mut self.state.textures;
        for &name in textures.iter().take(n as usize) {
            if name == 0 {
                continue;
            }
            t.names.remove(name);
            t.objects.remove(&name);
            for b in t.units.iter_mut().flat_map(|u| u.bindings.iter_mut()) {
                if *b == name {
                    *b = 0;
                }
            }
        }
    }

    /// `glIsTexture`: true for the name of an existing texture object (one bound at least once
    /// and not deleted); false for 0 and for names only generated.
    pub fn is_texture(&mut self, texture: u32) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.pull_objects();
        self.state.textures.objects.contains_key(&texture)
    }

    /// `glBindTexture(target, name)` on the active unit, for TEXTURE_1D, _2D, _3D or _CUBE_MAP
    /// (any other target is INVALID_ENUM). A new name becomes a texture object of `target` with
    /// the initial state; a name whose object was first bound to another target is
    /// INVALID_OPERATION (GL 2.1 §3.8.12). Name 0 binds the target's default texture.
    pub fn bind_texture(&mut self, target: u32, texture: u32) {
        record!(self, Call::BindTexture(target, texture));
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            ctx.bind_texture_now(target, texture)
        });
    }

    fn bind_texture_now(&mut self, target: u32, texture: u32) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(k) = target_index(target) else {
            return self.error(gl::INVALID_ENUM);
        };
        let unit = self.state.active_texture;
        let t = &mut self.state.textures;
        if texture != 0 {
            if t.objects.get(&texture).is_some_and(|o| o.target != target) {
                return self.error(gl::INVALID_OPERATION);
            }
            t.names.insert(texture);
            t.objects
                .entry(texture)
                .or_insert_with(|| Arc::new(TexObject::new(target)));
        }
        if let Some(b) = t.units.get_mut(unit).and_then(|u| u.bindings.get_mut(k)) {
            *b = texture;
        }
    }

    /// `glTexImage1D` (§3.8.1): level `level` of the bound 1D texture, a `width` x 1 image
    /// unpacked as TexImage2D's one row. Errors as TexImage2D (target TEXTURE_1D).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::TexImage1D(Box::new((
                target,
                level,
                internal_format,
                width,
                border,
                format,
                type_,
                pixels.map(<[u8]>::to_vec),
            )))
        );
        self.tex_image(
            1,
            target,
            level,
            internal_format,
            [width, 1, 1],
            border,
            format,
            type_,
            pixels,
        );
    }

    /// `glTexImage2D` (§3.8.1): specifies level `level` of the bound 2D texture from client
    /// pixels of `format` / `type_` (unpacked under the UNPACK_ modes: ROW_LENGTH, SKIP_ROWS,
    /// SKIP_PIXELS, ALIGNMENT, SWAP_BYTES, §3.6.4). Errors: see [`tex_image_args_error`];
    /// `pixels` shorter than the skips and the image need is INVALID_OPERATION.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::TexImage2D(Box::new((
                target,
                level,
                internal_format,
                width,
                height,
                border,
                format,
                type_,
                pixels.map(<[u8]>::to_vec),
            )))
        );
        self.tex_image(
            2,
            target,
            level,
            internal_format,
            [width, height, 1],
            border,
            format,
            type_,
            pixels,
        );
    }

    /// `glTexImage3D` (§3.8.1): level `level` of the bound 3D texture, `depth` images of
    /// `width` x `height` placed by the UNPACK_ modes plus IMAGE_HEIGHT and SKIP_IMAGES.
    /// Errors as TexImage2D (target TEXTURE_3D; a depth format is INVALID_OPERATION); an image
    /// of more than [`MAX_IMAGE_TEXELS`] texels is OUT_OF_MEMORY.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        record!(
            self,
            Call::TexImage3D(Box::new((
                target,
                level,
                internal_format,
                width,
                height,
                depth,
                border,
                format,
                type_,
                pixels.map(<[u8]>::to_vec),
            )))
        );
        self.tex_image(
            3,
            target,
            level,
            internal_format,
            [width, height, depth],
            border,
            format,
            type_,
            pixels,
        );
    }

    /// TexImage1D/2D/3D after recording.
    #[allow(clippy::too_many_arguments)]
    fn tex_image(
        &mut self,
        dims: usize,
        target: u32,
        level: i32,
        internal_format: i32,
        size: [i32; 3],
        border: i32,
        format: u32,
        type_: u32,
        pixels: Option<&[u8]>,
    ) {
        if !self.outside_begin_end() {
            return;
        }
        if let Some(code) = tex_image_nd_args_error(
            dims,
            target,
            level,
            internal_format,
            size,
            border,
            format,
            type_,
        ) {
            return self.error(code);
        }
        let [width, height, depth] = size;
        let base = base_internal_format(internal_format).unwrap_or(gl::RGBA);
        let Ok(f) = check(format, type_) else {
            return;
        };
        let texels_n = width as usize * height as usize * depth as usize;
        if let Some(k) = proxy_index(target) {
            // §3.8.1: a proxy reads no pixels and raises no error for an image that does not
            // fit: its level is zeroed instead (the sizes of `legal_dimensions`; more than
            // MAX_IMAGE_TEXELS texels, the bound on memory a real image has here).
            let fits =
                legal_dimensions(dims, target, level, size, border) && texels_n <= MAX_IMAGE_TEXELS;
            let lv = fits.then_some(ProxyLevel {
                width,
                height,
                depth,
                border,
                internal_format,
                base,
            });
            if let Some(slot) = self
                .state
                .textures
                .proxies
                .get_mut(k)
                .and_then(|v| v.get_mut(level as usize))
            {
                *slot = lv;
            }
            return;
        }
        if texels_n > MAX_IMAGE_TEXELS {
            return self.error(gl::OUT_OF_MEMORY);
        }
        // With no data (NULL) nothing is read, whatever the skips.
        let three_d = dims == 3;
        let modes = self.state.unpack;
        if let Some(p) = pixels {
            let need = image_need3(&modes, f, width, height, depth, three_d);
            if need.map_or(true, |n| p.len() < n) {
                return self.error(gl::INVALID_OPERATION);
            }
        }
        // Up to MAX_IMAGE_TEXELS texels of 16 bytes (64 MiB) per call: reserved first, so an
        // allocation the machine cannot make is OUT_OF_MEMORY with nothing changed (GL 2.1
        // §2.5), not an abort.
        let mut texels = Vec::new();
        if texels.try_reserve_exact(texels_n).is_err() {
            return self.error(gl::OUT_OF_MEMORY);
        }
        match pixels {
            Some(p) => {
                let (t, maps) = (self.state.pixel, Arc::clone(&self.state.pixel_maps));
                for k in 0..depth as usize {
                    let Some(layout) = slice_layout(&modes, f, width, height, k, three_d) else {
                        return self.error(gl::INVALID_OPERATION);
                    };
                    let img = Image {
                        data: p,
                        format: f,
                        layout,
                    };
                    unpack_into(&mut texels, &img, width, height, base, &t, &maps);
                }
            }
            None => texels.resize(texels_n, quantize(base, [0.0; 4])),
        }
        let lv = Level {
            width,
            height,
            depth,
            internal_format,
            base,
            texels: texels.into(),
        };
        let lv = if border == 1 { strip_border(lv) } else { lv };
        self.store_level(target, level, lv);
    }

    /// Stores `lv` as level `level` of the active unit's texture of `target`, then
    /// GENERATE_MIPMAP.
    fn store_level(&mut self, target: u32, level: i32, lv: Level) {
        // The image may be attached to the bound framebuffer object: what was drawn into it
        // is stored first, and the framebuffer loaded again after (context/fbo.rs).
        self.fbo_store();
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            ctx.store_level_now(target, level, lv)
        });
        self.fbo_load();
    }

    fn store_level_now(&mut self, target: u32, level: i32, lv: Level) {
        let unit = self.state.active_texture;
        let (bind, face) = image_binding(target);
        if let Some(obj) = self.state.textures.bound_mut(unit, bind) {
            if let Some(slot) = obj.slot_mut(face, level) {
                *slot = Some(lv);
            }
            if obj.generate_mipmap && level == obj.base_level {
                obj.generate_mipmaps();
            }
        }
    }

    /// `glTexSubImage1D` (§3.8.2): replaces texels `xoffset..xoffset + width` of an existing
    /// level of the bound 1D texture; errors as TexSubImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_1d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        width: i32,
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        record!(
            self,
            Call::TexSubImage1D(Box::new((
                target,
                level,
                xoffset,
                width,
                format,
                type_,
                pixels.to_vec(),
            )))
        );
        self.tex_sub_image(
            1,
            target,
            level,
            [xoffset, 0, 0],
            [width, 1, 1],
            format,
            type_,
            pixels,
        );
    }

    /// `glTexSubImage2D` (§3.8.2): replaces a rectangle of an existing level. A level not
    /// specified, or depth data for a colour texture (or the reverse), is INVALID_OPERATION;
    /// a rectangle outside the level is INVALID_VALUE; a short `pixels` is INVALID_OPERATION.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_2d(
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
        record!(
            self,
            Call::TexSubImage2D(Box::new((
                target,
                level,
                xoffset,
                yoffset,
                width,
                height,
                format,
                type_,
                pixels.to_vec(),
            )))
        );
        self.tex_sub_image(
            2,
            target,
            level,
            [xoffset, yoffset, 0],
            [width, height, 1],
            format,
            type_,
            pixels,
        );
    }

    /// `glTexSubImage3D` (§3.8.2): replaces a box of an existing level of the bound 3D
    /// texture (unpacked as TexImage3D); errors as TexSubImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_3d(
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
        record!(
            self,
            Call::TexSubImage3D(Box::new((
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
                pixels.to_vec(),
            )))
        );
        self.tex_sub_image(
            3,
            target,
            level,
            [xoffset, yoffset, zoffset],
            [width, height, depth],
            format,
            type_,
            pixels,
        );
    }

    /// TexSubImage1D/2D/3D after recording.
    #[allow(clippy::too_many_arguments)]
    fn tex_sub_image(
        &mut self,
        dims: usize,
        target: u32,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        format: u32,
        type_: u32,
        pixels: &[u8],
    ) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(base) = self.check_sub_image(dims, target, level, offset, size) else {
            return;
        };
        let f = match check(format, type_) {
            Ok(f) => f,
            Err(code) => return self.error(code),
        };
        if !formats_agree(f.group, base) {
            return self.error(gl::INVALID_OPERATION);
        }
        let [width, height, depth] = size;
        let (three_d, modes) = (dims == 3, self.state.unpack);
        let need = image_need3(&modes, f, width, height, depth, three_d);
        if need.map_or(true, |n| pixels.len() < n) {
            return self.error(gl::INVALID_OPERATION);
        }
        let (t, maps) = (self.state.pixel, Arc::clone(&self.state.pixel_maps));
        let mut texels = Vec::new();
        for k in 0..depth.max(0) as usize {
            let Some(layout) = slice_layout(&modes, f, width, height, k, three_d) else {
                return self.error(gl::INVALID_OPERATION);
            };
            let img = Image {
                data: pixels,
                format: f,
                layout,
            };
            unpack_into(&mut texels, &img, width, height, base, &t, &maps);
        }
        // DEPTH_COMPONENT data into a DEPTH_STENCIL image replaces the depths only (Mesa's
        // `_mesa_texstore_z24_s8` keeps the stencil; llvmpipe measured: see docs).
        let depth_only = base == gl::DEPTH_STENCIL && f.group == Group::Depth;
        self.write_box(
            target,
            level,
            offset,
            size,
            BoxSrc::Texels(&texels),
            depth_only,
        );
    }

    /// The TexSubImage/CopyTexSubImage checks shared by all (§3.8.2): the target (TexImage's
    /// but the proxies, INVALID_ENUM as Mesa's `legal_texsubimage_target`), a specified level,
    /// the box inside it. Returns the level's base format, or None after raising.
    fn check_sub_image(
        &mut self,
        dims: usize,
        target: u32,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
    ) -> Option<u32> {
        if !image_target_ok(dims, target) || is_proxy(target) {
            self.error(gl::INVALID_ENUM);
            return None;
        }
        if level < 0 || level >= MAX_LEVELS as i32 {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        let unit = self.state.active_texture;
        let (bind, face) = image_binding(target);
        let Some(lv) = self
            .state
            .textures
            .bound(unit, bind)
            .and_then(|o| o.face_level(face, level))
        else {
            self.error(gl::INVALID_OPERATION);
            return None;
        };
        let dims_of = [lv.width, lv.height, lv.depth];
        let base = lv.base;
        let inside = (0..3).all(|k| {
            offset[k] >= 0
                && size[k] >= 0
                && i64::from(offset[k]) + i64::from(size[k]) <= i64::from(dims_of[k])
        });
        if !inside {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some(base)
    }

    /// Writes `texels` (rows of `size[0]`, images of `size[1]` rows) into level `level` of the
    /// texture of `target` at `offset` (with `depth_only`, only their first component: the
    /// depths of a DEPTH_STENCIL image, its stencil kept), then GENERATE_MIPMAP.
    fn write_box(
        &mut self,
        target: u32,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        src: BoxSrc<'_>,
        depth_only: bool,
    ) {
        // As `store_level`: the bound framebuffer object's images stay coherent.
        self.fbo_store();
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            ctx.write_box_now(target, level, offset, size, src, depth_only)
        });
        self.fbo_load();
    }

    fn write_box_now(
        &mut self,
        target: u32,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        src: BoxSrc<'_>,
        depth_only: bool,
    ) {
        let unit = self.state.active_texture;
        let (bind, face) = image_binding(target);
        let read = crate::cpu::framebuffer::read_buf(&self.state);
        self.renderer.release_textures();
        // The window's framebuffer, for a copy from it (the texels are read from it row by row
        // straight into the level).
        let fb = match src {
            BoxSrc::Window { .. } => Some(self.renderer.framebuffer()),
            BoxSrc::Texels(_) => None,
        };
        let Some(obj) = self.state.textures.bound_mut(unit, bind) else {
            return;
        };
        if let Some(Some(lv)) = obj.slot_mut(face, level) {
            let (lw, lh) = (lv.width as usize, lv.height as usize);
            let rows = size[1].max(1) as usize;
            let dst_texels = Arc::make_mut(&mut lv.texels);
            let at = |r: usize| {
                let (k, j) = (r / rows, r % rows);
                ((offset[2] as usize + k) * lh + offset[1] as usize + j) * lw + offset[0] as usize
            };
            match (src, fb) {
                (BoxSrc::Texels(texels), _) => {
                    for (r, row) in texels.chunks(size[0].max(1) as usize).enumerate() {
                        let at = at(r);
                        if let Some(dst) = dst_texels.get_mut(at..at + row.len()) {
                            if depth_only {
                                for (d, s) in dst.iter_mut().zip(row) {
                                    d[0] = s[0];
                                }
                            } else {
                                dst.copy_from_slice(row);
                            }
                        }
                    }
                }
                (BoxSrc::Window { x, y, base }, Some(fb)) => {
                    // `read_fb`'s texels, row r of the rectangle into row r of the box.
                    let w = size[0].max(0) as usize;
                    let h = if w == 0 { 0 } else { size[1].max(0) as usize };
                    for r in 0..h {
                        let at = at(r);
                        let Some(dst) = dst_texels.get_mut(at..at + w) else {
                            continue;
                        };
                        let (row, mut k) = (i64::from(y) + r as i64, 0usize);
                        row_runs(fb, read, i64::from(x), row, w, |run| {
                            if let Some(d) = dst.get_mut(k..) {
                                crate::texture::fb_texels(base, run, d);
                            }
                            k += run.len();
                        });
                    }
                }
                (BoxSrc::Window { .. }, None) => {}
            }
        }
        if obj.generate_mipmap && level == obj.base_level {
            obj.generate_mipmaps();
        }
    }

    /// `glCopyTexImage1D` (§3.8.2): level `level` of the bound 1D texture from the `width`
    /// framebuffer pixels at (x, y); errors as CopyTexImage2D (target TEXTURE_1D).
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: u32,
        x: i32,
        y: i32,
        width: i32,
        border: i32,
    ) {
        record!(
            self,
            Call::CopyTexImage1D(target, level, internal_format, x, y, width, border)
        );
        self.copy_tex_image(1, target, level, internal_format, x, y, [width, 1], border);
    }

    /// `glCopyTexImage2D` (§3.8.2): level `level` from the framebuffer rectangle at (x, y) of
    /// `width` x `height`: colour for a colour `internal_format`, depth for a depth one. Pixels
    /// outside the window are undefined (here zero). Errors as TexImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: u32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        border: i32,
    ) {
        record!(
            self,
            Call::CopyTexImage2D(target, level, internal_format, x, y, width, height, border)
        );
        self.copy_tex_image(
            2,
            target,
            level,
            internal_format,
            x,
            y,
            [width, height],
            border,
        );
    }

    /// CopyTexImage1D/2D after recording.
    #[allow(clippy::too_many_arguments)]
    fn copy_tex_image(
        &mut self,
        dims: usize,
        target: u32,
        level: i32,
        internal_format: u32,
        x: i32,
        y: i32,
        [width, height]: [i32; 2],
        border: i32,
    ) {
        if !self.outside_begin_end() {
            return;
        }
        // §3.8.2: CopyTexImage takes no proxy target.
        if is_proxy(target) {
            return self.error(gl::INVALID_ENUM);
        }
        let ifmt = internal_format as i32;
        let size = [width, height, 1];
        // Target and level errors first (INVALID_ENUM, INVALID_VALUE), then an internal format
        // that is unknown or one of the GL 1.0 counts 1..=4 (§3.8.2 refuses those), which Mesa
        // (copytexture_error_check) raises as INVALID_ENUM before the size and border checks,
        // where TexImage gives INVALID_VALUE (piglit copyteximage.c:638).
        let base = base_internal_format(ifmt).filter(|_| !(1..=4).contains(&ifmt));
        let Some(base) = base else {
            let code = tex_image_nd_args_error(
                dims,
                target,
                level,
                gl::RGBA as i32,
                [0, 0, 0],
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
            );
            return self.error(code.unwrap_or(gl::INVALID_ENUM));
        };
        let (fmt, ty) = match base {
            gl::DEPTH_COMPONENT => (gl::DEPTH_COMPONENT, gl::FLOAT),
            gl::DEPTH_STENCIL => (gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8),
            _ => (gl::RGBA, gl::FLOAT),
        };
        if let Some(code) =
            tex_image_nd_args_error(dims, target, level, ifmt, size, border, fmt, ty)
        {
            return self.error(code);
        }
        // §3.8.2: a depth format without a depth buffer to copy from (DEPTH_STENCIL: without
        // a depth and a stencil buffer, as Mesa's `copytexture_error_check`).
        if self.copy_source_missing(base) {
            return self.error(gl::INVALID_OPERATION);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        // A border is stripped as Mesa does for its gallium drivers (`strip_border`): here by
        // copying the rectangle inside it (for 2D both dimensions, whatever the height).
        let (x, y, width, height) = match (border, dims) {
            (1, 1) => (x + 1, y, width - 2, height),
            (1, _) => (x + 1, y + 1, width - 2, height - 2),
            _ => (x, y, width, height),
        };
        let Some(texels) = self.read_fb(x, y, width, height, base) else {
            return self.error(gl::OUT_OF_MEMORY);
        };
        self.store_level(
            target,
            level,
            Level {
                width,
                height,
                depth: 1,
                internal_format: ifmt,
                base,
                texels: texels.into(),
            },
        );
    }

    /// `glCopyTexSubImage1D` (§3.8.2): replaces texels `xoffset..xoffset + width` of level
    /// `level` of the bound 1D texture with the framebuffer pixels at (x, y).
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_1d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        x: i32,
        y: i32,
        width: i32,
    ) {
        record!(
            self,
            Call::CopyTexSubImage1D(target, level, xoffset, x, y, width)
        );
        self.copy_tex_sub_image(1, target, level, [xoffset, 0, 0], x, y, [width, 1]);
    }

    /// `glCopyTexSubImage2D` (§3.8.2): replaces a rectangle of level `level` with the
    /// framebuffer rectangle at (x, y); errors as TexSubImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) {
        record!(
            self,
            Call::CopyTexSubImage2D(target, level, xoffset, yoffset, x, y, width, height)
        );
        self.copy_tex_sub_image(
            2,
            target,
            level,
            [xoffset, yoffset, 0],
            x,
            y,
            [width, height],
        );
    }

    /// `glCopyTexSubImage3D` (§3.8.2): replaces a rectangle of image `zoffset` of level
    /// `level` of the bound 3D texture with the framebuffer rectangle at (x, y).
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) {
        record!(
            self,
            Call::CopyTexSubImage3D(target, level, xoffset, yoffset, zoffset, x, y, width, height)
        );
        self.copy_tex_sub_image(
            3,
            target,
            level,
            [xoffset, yoffset, zoffset],
            x,
            y,
            [width, height],
        );
    }

    /// CopyTexSubImage1D/2D/3D after recording.
    #[allow(clippy::too_many_arguments)]
    fn copy_tex_sub_image(
        &mut self,
        dims: usize,
        target: u32,
        level: i32,
        offset: [i32; 3],
        x: i32,
        y: i32,
        [width, height]: [i32; 2],
    ) {
        if !self.outside_begin_end() {
            return;
        }
        let size = [width, height, 1];
        let Some(base) = self.check_sub_image(dims, target, level, offset, size) else {
            return;
        };
        if self.copy_source_missing(base) {
            return self.error(gl::INVALID_OPERATION);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        if self.fbos.bound_fb == 0 {
            // From the window (nothing loaded from a framebuffer object that `write_box`
            // would store first): straight from the framebuffer into the level.
            let src = BoxSrc::Window { x, y, base };
            return self.write_box(target, level, offset, size, src, false);
        }
        let Some(texels) = self.read_fb(x, y, width, height, base) else {
            return self.error(gl::OUT_OF_MEMORY);
        };
        self.write_box(target, level, offset, size, BoxSrc::Texels(&texels), false);
    }

    /// Whether the framebuffer lacks a buffer CopyTex(Sub)Image into base format `base` reads:
    /// depth for DEPTH_COMPONENT, depth and stencil for DEPTH_STENCIL (INVALID_OPERATION).
    fn copy_source_missing(&self, base: u32) -> bool {
        let c = &self.state.config;
        match base {
            gl::DEPTH_COMPONENT => !c.depth,
            gl::DEPTH_STENCIL => !(c.depth && c.stencil),
            _ => false,
        }
    }

    /// Framebuffer pixels as texels of `base`: depth (as [0, 1]) for DEPTH_COMPONENT, depth and
    /// stencil index for DEPTH_STENCIL, else the
    /// colour converted as TexImage converts RGBA data.
    /// `None` when the texels cannot be allocated (w and h are validated, at most
    /// MAX_TEXTURE_SIZE).
    fn read_fb(&mut self, x: i32, y: i32, w: i32, h: i32, base: u32) -> Option<Vec<[f32; 4]>> {
        // Colour from the buffer READ_BUFFER names (§3.8.2 reads as ReadPixels does).
        let buf = crate::cpu::framebuffer::read_buf(&self.state);
        let fb = self.renderer.framebuffer();
        let (w, h) = (w.max(0) as usize, h.max(0) as usize);
        let mut out = Vec::new();
        out.try_reserve_exact(w * h).ok()?;
        out.resize(w * h, [0.0; 4]);
        for (j, dst) in out.chunks_mut(w.max(1)).enumerate() {
            // Each texel is already at the stored precision: `quantize` would return it as is.
            let (row, mut k) = (i64::from(y) + j as i64, 0usize);
            row_runs(fb, buf, i64::from(x), row, w, |run| {
                if let Some(d) = dst.get_mut(k..) {
                    crate::texture::fb_texels(base, run, d);
                }
                k += run.len();
            });
        }
        Some(out)
    }

    /// `glGetTexImage` (§6.1.4): level `level` of the bound texture of `target` (TEXTURE_1D,
    /// _2D or _3D) as `format` / `type_`, placed under the PACK_ modes (§4.3.2; a 3D image's
    /// slices by PACK_IMAGE_HEIGHT and PACK_SKIP_IMAGES) into `pixels`. A level not specified
    /// writes nothing; a `pixels` too short for the skips and the image is INVALID_OPERATION
    /// (as TexImage2D's unpack); depth data from a colour texture (or the reverse) is
    /// INVALID_OPERATION.
    pub fn get_tex_image(
        &mut self,
        target: u32,
        level: i32,
        format: u32,
        type_: u32,
        pixels: &mut [u8],
    ) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        // A level attached to the bound framebuffer object holds what was drawn once stored
        // (context/fbo.rs).
        self.fbo_store();
        self.fbo_load();
        self.pull_objects();
        if !matches!(target, gl::TEXTURE_1D | gl::TEXTURE_2D | gl::TEXTURE_3D)
            && !(gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                .contains(&target)
        {
            return self.error(gl::INVALID_ENUM);
        }
        // §6.1.4: the formats and types of ReadPixels (GL 2.1 table 3.6, the packed types of
        // table 3.8 with their INVALID_OPERATION), but no colour or stencil index.
        let f = match check(format, type_) {
            Ok(f) => f,
            Err(code) => return self.error(code),
        };
        if matches!(f.group, Group::Index | Group::Stencil) {
            return self.error(gl::INVALID_ENUM);
        }
        if level < 0 || level >= MAX_LEVELS as i32 {
            return self.error(gl::INVALID_VALUE);
        }
        let unit = self.state.active_texture;
        let (bind, face) = image_binding(target);
        let Some(lv) = self
            .state
            .textures
            .bound(unit, bind)
            .and_then(|o| o.face_level(face, level))
            .cloned()
        else {
            return;
        };
        // DEPTH_STENCIL only from a DEPTH_STENCIL image, DEPTH_COMPONENT only from a depth
        // one, colour only from a colour one (Mesa's INVALID_OPERATION for a format that does
        // not match the image's).
        let agree = match f.group {
            Group::DepthStencil => lv.base == gl::DEPTH_STENCIL,
            Group::Depth => is_depth(lv.base),
            _ => !is_depth(lv.base),
        };
        if !agree {
            return self.error(gl::INVALID_OPERATION);
        }
        // Placed under the PACK_ modes like ReadPixels (§6.1.4 refers to §4.3.2).
        let (modes, three_d) = (self.state.pack, target == gl::TEXTURE_3D);
        let need = image_need3(&modes, f, lv.width, lv.height, lv.depth, three_d);
        if need.map_or(true, |n| pixels.len() < n) {
            return self.error(gl::INVALID_OPERATION);
        }
        // §6.1.4: the colour goes through the pixel transfer as ReadPixels' does (Mesa's
        // `_mesa_GetTexImage` applies scale, bias and MAP_COLOR too).
        let (t, maps) = (self.state.pixel, Arc::clone(&self.state.pixel_maps));
        for k in 0..lv.depth.max(0) as usize {
            let Some(layout) = slice_layout(&modes, f, lv.width, lv.height, k, three_d) else {
                return self.error(gl::INVALID_OPERATION);
            };
            for j in 0..lv.height.max(0) as usize {
                for i in 0..lv.width.max(0) as usize {
                    // Table 6.1: L and I are returned as R alone, (L, 0, 0, 1) as RGBA (Mesa
                    // agrees; piglit `getteximage-luminance`).
                    let tx = lv.texel3(i as i32, j as i32, k as i32);
                    if f.group == Group::DepthStencil {
                        // The stored depth and index as they are, as Mesa's
                        // `get_tex_depth_stencil` (no pixel transfer).
                        let comps = [Value::Norm(f64::from(tx[0])), Value::Int(tx[1] as u32)];
                        store(pixels, &layout, f.ty, i, j, &comps);
                        continue;
                    }
                    let rgba = match lv.base {
                        gl::LUMINANCE | gl::INTENSITY => [tx[0], 0.0, 0.0, 1.0],
                        gl::LUMINANCE_ALPHA => [tx[0], 0.0, 0.0, tx[3]],
                        gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL => {
                            [t.depth(f64::from(tx[0])) as f32, 0.0, 0.0, 1.0]
                        }
                        base => as_rgba(base, tx),
                    };
                    let [r, g, b, a] = if t.color_is_identity() || is_depth(lv.base) {
                        rgba
                    } else {
                        t.color(&maps, rgba)
                    };
                    let mut comps = [Value::Norm(0.0); 4];
                    let n = match f.group {
                        Group::Color(slots) => {
                            for (c, slot) in comps.iter_mut().zip(slots) {
                                // §6.1.4: luminance is returned as R (no sum), as Mesa does.
                                *c = Value::Norm(f64::from(match slot {
                                    Slot::R | Slot::L => r,
                                    Slot::G => g,
                                    Slot::B => b,
                                    Slot::A => a,
                                }));
                            }
                            slots.len()
                        }
                        _ => {
                            comps[0] = Value::Norm(f64::from(r));
                            1
                        }
                    };
                    store(pixels, &layout, f.ty, i, j, &comps[..n]);
                }
            }
        }
    }
}
