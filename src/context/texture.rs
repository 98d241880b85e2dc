//! Texture objects and images: `GenTextures`, `DeleteTextures`, `IsTexture`, `BindTexture`,
//! `TexImage2D`, `TexSubImage2D`, `CopyTexImage2D`, `CopyTexSubImage2D`, `GetTexImage`
//! (GL 2.1 §3.8.1, §3.8.2, §3.8.12, §6.1.4).
//!
//! Objects of every GL 1.3 target exist (TEXTURE_1D, _2D, _3D, _CUBE_MAP: BindTexture, the
//! bindings, parameters, deletion), but images only for TEXTURE_2D: the image commands take
//! TEXTURE_2D alone and any other target (and the proxies) is INVALID_ENUM (TexImage1D/3D and
//! cube-map faces: issue #14). Client pixels are `Option<&[u8]>` (`None` is GL's NULL: the image
//! is allocated with undefined, here zero, contents); FLOAT data is native-endian bytes
//! (`texture::f32_bytes`).
//!
//! Design decision: a slice shorter than the unpack parameters say the image needs is
//! INVALID_OPERATION with nothing changed, the error GL gives for a read past the end of a
//! pixel unpack buffer (§2.9.2) and ARB_robustness for a short client buffer; the recorded call
//! carries exactly the bytes passed, and the GL backend raises the same error without calling
//! the driver. GenTextures hands out the smallest names above every name in use, as Mesa does, so
//! a replay on the driver gets the same names.

use std::sync::Arc;

use super::Context;
use crate::call::Call;
use crate::convert;
use crate::gl;
use crate::texture::{
    as_rgba, base_internal_format, format_components, keep, quantize, target_index, type_size,
    unpack, unpack_into, Level, TexObject, MAX_LEVELS, MAX_TEXTURE_SIZE,
};

/// Most names one GenTextures call hands out; more is OUT_OF_MEMORY (a bound on memory).
pub const MAX_GEN_TEXTURES: i32 = 1 << 16;

/// The error `TexImage2D` raises for these arguments before looking at state or data, if any
/// (GL 2.1 §3.8.1): shared by the front end and the GL backend's replay.
#[allow(clippy::too_many_arguments)]
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
    if target != gl::TEXTURE_2D {
        return Some(gl::INVALID_ENUM);
    }
    if format_components(format).is_none() || type_size(type_).is_none() {
        return Some(gl::INVALID_ENUM);
    }
    if level < 0 || level >= MAX_LEVELS as i32 {
        return Some(gl::INVALID_VALUE);
    }
    let Some(base) = base_internal_format(internal_format) else {
        return Some(gl::INVALID_VALUE);
    };
    // Border 1 is legal GL 2.1 but not supported here (documented deviation).
    let max = MAX_TEXTURE_SIZE >> level;
    if border != 0 || width < 0 || height < 0 || width > max || height > max {
        return Some(gl::INVALID_VALUE);
    }
    // §3.8.1: depth data only into a depth format, and a depth format only from depth data.
    if (format == gl::DEPTH_COMPONENT) != (base == gl::DEPTH_COMPONENT) {
        return Some(gl::INVALID_OPERATION);
    }
    None
}

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
        if !self.outside_begin_end() {
            return;
        }
        if n < 0 || textures.len() < n as usize {
            return self.error(gl::INVALID_VALUE);
        }
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
        self.state.textures.objects.contains_key(&texture)
    }

    /// `glBindTexture(target, name)` on the active unit, for TEXTURE_1D, _2D, _3D or _CUBE_MAP
    /// (any other target is INVALID_ENUM). A new name becomes a texture object of `target` with
    /// the initial state; a name whose object was first bound to another target is
    /// INVALID_OPERATION (GL 2.1 §3.8.12). Name 0 binds the target's default texture.
    pub fn bind_texture(&mut self, target: u32, texture: u32) {
        record!(self, Call::BindTexture(target, texture));
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
        if !self.outside_begin_end() {
            return;
        }
        if let Some(code) = tex_image_args_error(
            target,
            level,
            internal_format,
            width,
            height,
            border,
            format,
            type_,
        ) {
            return self.error(code);
        }
        let base = base_internal_format(internal_format).unwrap_or(gl::RGBA);
        let (n, s) = (
            format_components(format).unwrap_or(4),
            type_size(type_).unwrap_or(1),
        );
        // With no data (NULL) nothing is read, whatever the skips.
        let data = match pixels {
            Some(p) => match self.unpack_layout(width, height, n, s, p.len()) {
                Some(layout) => Some((p, layout)),
                None => return self.error(gl::INVALID_OPERATION),
            },
            None => None,
        };
        // Up to MAX_TEXTURE_SIZE² texels of 16 bytes (64 MiB) per call: reserved first, so an
        // allocation the machine cannot make is OUT_OF_MEMORY with nothing changed (GL 2.1
        // §2.5), not an abort.
        let texels_n = width as usize * height as usize;
        let mut texels = Vec::new();
        if texels.try_reserve_exact(texels_n).is_err() {
            return self.error(gl::OUT_OF_MEMORY);
        }
        match data {
            Some((p, l)) => unpack_into(&mut texels, p, width, height, format, type_, &l, base),
            None => texels.resize(texels_n, quantize(base, [0.0; 4])),
        }
        let lv = Level {
            width,
            height,
            internal_format,
            base,
            texels,
        };
        self.store_level(level, lv);
    }

    /// Stores `lv` as level `level` of the active unit's 2D texture, then GENERATE_MIPMAP.
    fn store_level(&mut self, level: i32, lv: Level) {
        let unit = self.state.active_texture;
        if let Some(obj) = self.state.textures.bound_2d_mut(unit) {
            if let Some(slot) = obj.levels.get_mut(level as usize) {
                *slot = Some(lv);
            }
            if obj.generate_mipmap && level == obj.base_level {
                obj.generate_mipmaps();
            }
        }
    }

    /// Where a `w` x `h` image of `n` components of `s` bytes lies in client data of `len`
    /// bytes under the UNPACK_ modes (§3.6.4), or None when `len` is shorter than the skips and
    /// the image need (or the need overflows a usize).
    fn unpack_layout(
        &self,
        w: i32,
        h: i32,
        n: usize,
        s: usize,
        len: usize,
    ) -> Option<crate::pixel_store::Layout> {
        self.state
            .unpack
            .layout(w, h, n, s)
            .filter(|l| len >= l.need)
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
        if !self.outside_begin_end() {
            return;
        }
        let Some(base) = self.check_sub_image(target, level, xoffset, yoffset, width, height)
        else {
            return;
        };
        let (Some(n), Some(s)) = (format_components(format), type_size(type_)) else {
            return self.error(gl::INVALID_ENUM);
        };
        if (format == gl::DEPTH_COMPONENT) != (base == gl::DEPTH_COMPONENT) {
            return self.error(gl::INVALID_OPERATION);
        }
        let Some(layout) = self.unpack_layout(width, height, n, s, pixels.len()) else {
            return self.error(gl::INVALID_OPERATION);
        };
        let texels = unpack(pixels, width, height, format, type_, &layout, base);
        self.write_rect(level, xoffset, yoffset, width, &texels);
    }

    /// The TexSubImage/CopyTexSubImage checks shared by both (§3.8.2): the target, a specified
    /// level, the rectangle inside it. Returns the level's base format, or None after raising.
    fn check_sub_image(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
    ) -> Option<u32> {
        if target != gl::TEXTURE_2D {
            self.error(gl::INVALID_ENUM);
            return None;
        }
        if level < 0 || level >= MAX_LEVELS as i32 {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        let unit = self.state.active_texture;
        let Some(lv) = self
            .state
            .textures
            .bound_2d(unit)
            .and_then(|o| o.level(level))
        else {
            self.error(gl::INVALID_OPERATION);
            return None;
        };
        let (lw, lh, base) = (lv.width, lv.height, lv.base);
        let inside = xoffset >= 0
            && yoffset >= 0
            && width >= 0
            && height >= 0
            && i64::from(xoffset) + i64::from(width) <= i64::from(lw)
            && i64::from(yoffset) + i64::from(height) <= i64::from(lh);
        if !inside {
            self.error(gl::INVALID_VALUE);
            return None;
        }
        Some(base)
    }

    /// Writes `texels` (rows of `width`) into level `level` at (x, y), then GENERATE_MIPMAP.
    fn write_rect(&mut self, level: i32, x: i32, y: i32, width: i32, texels: &[[f32; 4]]) {
        let unit = self.state.active_texture;
        let Some(obj) = self.state.textures.bound_2d_mut(unit) else {
            return;
        };
        if let Some(Some(lv)) = obj.levels.get_mut(level as usize) {
            let lw = lv.width as usize;
            for (j, row) in texels.chunks(width.max(1) as usize).enumerate() {
                let at = (y as usize + j) * lw + x as usize;
                if let Some(dst) = lv.texels.get_mut(at..at + row.len()) {
                    dst.copy_from_slice(row);
                }
            }
        }
        if obj.generate_mipmap && level == obj.base_level {
            obj.generate_mipmaps();
        }
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
        if !self.outside_begin_end() {
            return;
        }
        let ifmt = internal_format as i32;
        let Some(base) = base_internal_format(ifmt) else {
            // Target and level errors first, as TexImage2D orders them.
            let code = tex_image_args_error(
                target,
                level,
                gl::RGBA as i32,
                width,
                height,
                border,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
            );
            return self.error(code.unwrap_or(gl::INVALID_VALUE));
        };
        // 1..=4 are not accepted by CopyTexImage (§3.8.2 lists base and sized formats only).
        let fmt = if base == gl::DEPTH_COMPONENT {
            gl::DEPTH_COMPONENT
        } else {
            gl::RGBA
        };
        if (1..=4).contains(&ifmt) {
            return self.error(gl::INVALID_VALUE);
        }
        if let Some(code) =
            tex_image_args_error(target, level, ifmt, width, height, border, fmt, gl::FLOAT)
        {
            return self.error(code);
        }
        // §3.8.2: a depth format without a depth buffer to copy from.
        if base == gl::DEPTH_COMPONENT && !self.state.config.depth {
            return self.error(gl::INVALID_OPERATION);
        }
        let Some(texels) = self.read_fb(x, y, width, height, base) else {
            return self.error(gl::OUT_OF_MEMORY);
        };
        self.store_level(
            level,
            Level {
                width,
                height,
                internal_format: ifmt,
                base,
                texels,
            },
        );
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
        if !self.outside_begin_end() {
            return;
        }
        let Some(base) = self.check_sub_image(target, level, xoffset, yoffset, width, height)
        else {
            return;
        };
        if base == gl::DEPTH_COMPONENT && !self.state.config.depth {
            return self.error(gl::INVALID_OPERATION);
        }
        let Some(texels) = self.read_fb(x, y, width, height, base) else {
            return self.error(gl::OUT_OF_MEMORY);
        };
        self.write_rect(level, xoffset, yoffset, width, &texels);
    }

    /// Framebuffer pixels as texels of `base`: depth (as [0, 1]) for DEPTH_COMPONENT, else the
    /// colour converted as TexImage converts RGBA data.
    /// `None` when the texels cannot be allocated (w and h are validated, at most
    /// MAX_TEXTURE_SIZE).
    fn read_fb(&mut self, x: i32, y: i32, w: i32, h: i32, base: u32) -> Option<Vec<[f32; 4]>> {
        // Colour from the buffer READ_BUFFER names (§3.8.2 reads as ReadPixels does).
        let buf = crate::cpu::framebuffer::read_buf(&self.state);
        let fb = self.renderer.framebuffer();
        let mut out = Vec::new();
        out.try_reserve_exact(w.max(0) as usize * h.max(0) as usize)
            .ok()?;
        for j in 0..h.max(0) {
            for i in 0..w.max(0) {
                let px = fb.pixel_in(
                    buf,
                    i64::from(x) + i64::from(i),
                    i64::from(y) + i64::from(j),
                );
                let t = match (px, base) {
                    (Some((_, d, _)), gl::DEPTH_COMPONENT) => {
                        let z = d as f32 / crate::cpu::framebuffer::DEPTH_MAX as f32;
                        [z, 0.0, 0.0, 0.0]
                    }
                    (Some((c, _, _)), _) => keep(base, c.map(|v| f32::from(v) / 255.0)),
                    (None, _) => [0.0; 4],
                };
                out.push(quantize(base, t));
            }
        }
        Some(out)
    }

    /// `glGetTexImage` (§6.1.4): level `level` of the bound 2D texture as `format` / `type_`,
    /// placed under the PACK_ modes (§4.3.2) into `pixels`. A level not specified writes
    /// nothing; a `pixels` too short for the skips and the image is INVALID_OPERATION (as
    /// TexImage2D's unpack); depth data from a colour texture (or the reverse) is
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
        if target != gl::TEXTURE_2D {
            return self.error(gl::INVALID_ENUM);
        }
        let (Some(n), Some(s)) = (format_components(format), type_size(type_)) else {
            return self.error(gl::INVALID_ENUM);
        };
        if level < 0 || level >= MAX_LEVELS as i32 {
            return self.error(gl::INVALID_VALUE);
        }
        let unit = self.state.active_texture;
        let Some(lv) = self
            .state
            .textures
            .bound_2d(unit)
            .and_then(|o| o.level(level))
            .cloned()
        else {
            return;
        };
        if (format == gl::DEPTH_COMPONENT) != (lv.base == gl::DEPTH_COMPONENT) {
            return self.error(gl::INVALID_OPERATION);
        }
        // Placed under the PACK_ modes like ReadPixels (§6.1.4 refers to §4.3.2).
        let Some(layout) = self
            .state
            .pack
            .layout(lv.width, lv.height, n, s)
            .filter(|l| pixels.len() >= l.need)
        else {
            return self.error(gl::INVALID_OPERATION);
        };
        for j in 0..lv.height {
            for i in 0..lv.width {
                let [r, g, b, a] = as_rgba(lv.base, lv.texel(i, j));
                // §6.1.4: luminance is returned as R (no sum), as Mesa does.
                let comps: &[f32] = &match format {
                    gl::RED | gl::LUMINANCE | gl::DEPTH_COMPONENT => [r, 0.0, 0.0, 0.0],
                    gl::GREEN => [g, 0.0, 0.0, 0.0],
                    gl::BLUE => [b, 0.0, 0.0, 0.0],
                    gl::ALPHA => [a, 0.0, 0.0, 0.0],
                    gl::LUMINANCE_ALPHA => [r, a, 0.0, 0.0],
                    gl::BGR | gl::BGRA => [b, g, r, a],
                    _ => [r, g, b, a],
                };
                let at = layout.at(i as usize, j as usize);
                for (k, &c) in comps.iter().take(n).enumerate() {
                    pack(pixels, at + k * s, type_, c);
                    // PACK_SWAP_BYTES: each element's bytes reversed (§4.3.2).
                    if let Some(e) = pixels.get_mut(at + k * s..at + (k + 1) * s) {
                        layout.order(e);
                    }
                }
            }
        }
    }
}

/// Writes one component `c` in [0, 1] as `type_` at byte `at` (table 4.7's conversions).
fn pack(dst: &mut [u8], at: usize, type_: u32, c: f32) {
    let c = f64::from(c);
    let bytes: Vec<u8> = match type_ {
        gl::UNSIGNED_BYTE => vec![(c * 255.0).round() as u8],
        gl::BYTE => vec![convert::unit_to_signed(c, 255.0).round() as i8 as u8],
        gl::UNSIGNED_SHORT => ((c * 65535.0).round() as u16).to_ne_bytes().to_vec(),
        gl::SHORT => (convert::unit_to_signed(c, 65535.0).round() as i16)
            .to_ne_bytes()
            .to_vec(),
        gl::UNSIGNED_INT => ((c * f64::from(u32::MAX)).round() as u32)
            .to_ne_bytes()
            .to_vec(),
        gl::INT => (convert::unit_to_signed(c, f64::from(u32::MAX)).round() as i32)
            .to_ne_bytes()
            .to_vec(),
        _ => (c as f32).to_ne_bytes().to_vec(),
    };
    if let Some(d) = dst.get_mut(at..at + bytes.len()) {
        d.copy_from_slice(&bytes);
    }
}
