//! Framebuffer objects (GL_EXT_framebuffer_object, under the GL 3.0 entry-point names; GL 3.0
//! §4.4, §6.1.3): Gen/Bind/Delete/IsFramebuffer and IsRenderbuffer, RenderbufferStorage,
//! FramebufferTexture1D/2D/3D, FramebufferRenderbuffer, CheckFramebufferStatus, the attachment
//! and renderbuffer queries, and GenerateMipmap.
//!
//! Design decision: the CPU renderer draws into a [`Framebuffer`] whatever is bound. Binding a
//! complete framebuffer object *loads* a framebuffer of the attachments' size from the attached
//! images (texture levels are `f32` texels, renderbuffers keep their own pixels here) and swaps
//! it into the renderer, the window's framebuffer set aside with its size, configuration and
//! DRAW_BUFFER/READ_BUFFER; `State::width`, `height` and `config` then describe the object's
//! buffers (an object without a depth attachment has no depth buffer: the depth test passes,
//! as §4.1.6 says of a window without one). Whatever leaves the object — another binding, a
//! change of its attachments, a change of an attached texture image, a deletion — first
//! *stores* the framebuffer back into the images it was loaded from (as CopyTexSubImage would:
//! quantised to the texture's format), so each image has one authoritative copy at any time:
//! the texture level outside, the loaded framebuffer while bound. Sampling a texture attached
//! to the bound framebuffer is a feedback loop GL leaves undefined (GL 3.0 §4.4.3), so a draw
//! does not store first.
//!
//! Object names are handed out after the largest name used so far (Mesa); BindFramebuffer and
//! BindRenderbuffer take any name, creating the object, as EXT_framebuffer_object allows (and
//! Mesa in its compatibility context). One colour attachment (MAX_COLOR_ATTACHMENTS 1, the
//! extension's minimum), a depth and a stencil attachment; colour-renderable are RGB and RGBA
//! textures and the RGB/RGBA renderbuffer formats, depth-renderable DEPTH_COMPONENT and
//! DEPTH_STENCIL ones, stencil-renderable STENCIL_INDEX renderbuffers and DEPTH_STENCIL
//! textures and renderbuffers (GL_EXT_packed_depth_stencil). A framebuffer with both a depth
//! and a stencil attachment that are not the same image is FRAMEBUFFER_UNSUPPORTED (Mesa's
//! state tracker wants depth and stencil in one image). Completeness is decided as Mesa
//! decides it (see `status_of`).
//! Objects are the context's own, not shared with a share group.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::{record, Context};
use crate::call::Call;
use crate::cpu::framebuffer::{depth_unorm, ColorBuf, Framebuffer, DEPTH_MAX};
use crate::cpu::pixels::{row_runs, RowRun, Src};
use crate::gl;
use crate::state::ContextConfig;
use crate::texture::{
    base_internal_format, fb_texels, image_binding, quantize, TexObject, MAX_LEVELS,
};

/// `MAX_RENDERBUFFER_SIZE`: the largest side of a renderbuffer (llvmpipe's 16384; as large as
/// the window framebuffer fixedgl allows).
pub const MAX_RENDERBUFFER_SIZE: i32 = 16384;
/// `MAX_COLOR_ATTACHMENTS`: one (the extension's minimum; no DrawBuffers in GL 1.5).
pub const MAX_COLOR_ATTACHMENTS: i32 = 1;

/// What an attachment point holds (GL 3.0 table 6.39's OBJECT_TYPE and the rest).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Attachment {
    /// Nothing (OBJECT_TYPE NONE).
    #[default]
    None,
    /// A level of a texture: its name, the image target (TEXTURE_1D, TEXTURE_2D, a cube-map
    /// face or TEXTURE_3D), the level and, for a 3D texture, the image (zoffset).
    Texture {
        name: u32,
        target: u32,
        level: i32,
        zoffset: i32,
    },
    /// A renderbuffer, by name.
    Renderbuffer(u32),
}

/// One framebuffer object: its three attachment points and its own DRAW_BUFFER and
/// READ_BUFFER (per-framebuffer state, initially COLOR_ATTACHMENT0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct FboObject {
    color: Attachment,
    depth: Attachment,
    stencil: Attachment,
    pub(crate) draw_buffer: u32,
    pub(crate) read_buffer: u32,
}

impl Default for FboObject {
    fn default() -> Self {
        FboObject {
            color: Attachment::None,
            depth: Attachment::None,
            stencil: Attachment::None,
            draw_buffer: gl::COLOR_ATTACHMENT0,
            read_buffer: gl::COLOR_ATTACHMENT0,
        }
    }
}

/// One renderbuffer: its format and size (0 x 0 and RGBA until RenderbufferStorage) and its
/// pixels, bottom-up rows: colour for a colour format, depth (24 bits) or stencil otherwise.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Renderbuffer {
    internal_format: u32,
    width: i32,
    height: i32,
    color: Vec<[u8; 4]>,
    depth: Vec<u32>,
    stencil: Vec<u8>,
}

/// The window's framebuffer while a framebuffer object is loaded in the renderer.
#[derive(Debug)]
struct Window {
    fb: Framebuffer,
    width: u32,
    height: u32,
    config: ContextConfig,
    y0_top: bool,
    draw_buffer: u32,
    read_buffer: u32,
}

/// What the renderer draws into while a framebuffer object is bound: the attachments the
/// framebuffer was loaded from, to store it back into.
#[derive(Clone, Copy, Debug)]
struct Loaded {
    color: Attachment,
    depth: Attachment,
    stencil: Attachment,
}

/// The context's framebuffer and renderbuffer objects and bindings.
#[derive(Debug, Default)]
pub(crate) struct Fbos {
    framebuffers: BTreeMap<u32, FboObject>,
    renderbuffers: BTreeMap<u32, Renderbuffer>,
    /// Names GenFramebuffers / GenRenderbuffers returned that are not objects yet (Is* answers
    /// false until first bound, GL 3.0 §4.4.1).
    fb_names: std::collections::BTreeSet<u32>,
    rb_names: std::collections::BTreeSet<u32>,
    /// The largest names ever used (Mesa hands out the names after them).
    fb_max: u32,
    rb_max: u32,
    /// FRAMEBUFFER_BINDING and RENDERBUFFER_BINDING.
    pub(crate) bound_fb: u32,
    pub(crate) bound_rb: u32,
    /// The window set aside while an object is bound (Some exactly when `bound_fb != 0`).
    window: Option<Window>,
    /// The attachments the renderer's framebuffer was loaded from (`None`: the bound object is
    /// incomplete, or none is bound).
    loaded: Option<Loaded>,
}

impl Fbos {
    /// Resizes the window's framebuffer set aside while an object is bound (`Context::resize`):
    /// false when none is set aside, or (the old one kept, the binding not 0) when the new
    /// buffers cannot be allocated.
    /// Sets the window's `State::y0_top` while a framebuffer object is bound; false when the
    /// window is bound (its value is then in the state).
    pub(crate) fn set_window_y0_top(&mut self, on: bool) -> bool {
        let Some(w) = self.window.as_mut() else {
            return false;
        };
        w.y0_top = on;
        true
    }

    pub(crate) fn resize_window(&mut self, width: u32, height: u32) -> bool {
        let Some(w) = self.window.as_mut() else {
            return false;
        };
        let Some(fb) = w.fb.resized(width, height) else {
            return false;
        };
        w.fb = fb;
        w.width = width;
        w.height = height;
        true
    }

    /// The window's main colour buffer (top row first) and size while an object is bound
    /// (`Context::to_image`; `None` when none is).
    pub(crate) fn window_main_rgba(&self) -> Option<(Vec<u8>, (u32, u32))> {
        let w = self.window.as_ref()?;
        let bytes = w.fb.bytes_top_down(crate::cpu::framebuffer::ColorBuf::Main);
        Some((bytes, (w.width, w.height)))
    }

    /// Swaps the window's buffers while an object is bound (`Context::swap_buffers`): false
    /// when none is.
    pub(crate) fn swap_window(&mut self) -> bool {
        let Some(w) = self.window.as_mut() else {
            return false;
        };
        w.fb.materialize_all();
        w.fb.swap();
        true
    }

    /// The window's front colour buffer as `Context::front_rgba` returns it, while an object
    /// is bound (`None` when none is).
    pub(crate) fn window_front_rgba(&self) -> Option<Vec<u8>> {
        let w = self.window.as_ref()?;
        let buf = match w.config.double_buffered {
            true => crate::cpu::framebuffer::ColorBuf::Front,
            false => crate::cpu::framebuffer::ColorBuf::Main,
        };
        Some(w.fb.bytes_top_down(buf))
    }
}

/// The colour-renderable base formats (GL 3.0 §4.4.4, as EXT_framebuffer_object: RGB, RGBA).
fn color_renderable(base: u32) -> bool {
    matches!(base, gl::RGB | gl::RGBA)
}

/// The base format of a renderbuffer internal format RenderbufferStorage takes in GL 1.5
/// (EXT_framebuffer_object: the colour formats of table 3.16 with base RGB or RGBA,
/// DEPTH_COMPONENT[16|24|32], STENCIL_INDEX[1|4|8|16]; EXT_packed_depth_stencil's
/// DEPTH_STENCIL and DEPTH24_STENCIL8), or `None`.
pub(crate) fn renderbuffer_base(internal: u32) -> Option<u32> {
    match internal {
        gl::STENCIL_INDEX
        | gl::STENCIL_INDEX1
        | gl::STENCIL_INDEX4
        | gl::STENCIL_INDEX8
        | gl::STENCIL_INDEX16 => Some(gl::STENCIL_INDEX),
        _ => {
            let base = base_internal_format(internal as i32)?;
            // The GL 1.0 component counts 1..=4 are not internal formats of renderbuffers.
            if (1..=4).contains(&internal) {
                return None;
            }
            matches!(
                base,
                gl::RGB | gl::RGBA | gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL
            )
            .then_some(base)
        }
    }
}

/// The texture image an attachment names, if the texture and the level exist.
fn attached_level<'a>(
    textures: &'a BTreeMap<u32, Arc<TexObject>>,
    att: &Attachment,
) -> Option<&'a crate::texture::Level> {
    let Attachment::Texture {
        name,
        target,
        level,
        ..
    } = *att
    else {
        return None;
    };
    let (_, face) = image_binding(target);
    textures.get(&name)?.face_level(face, level)
}

impl Context {
    /// Whether drawing and reading are refused: the bound framebuffer object is not complete
    /// (INVALID_FRAMEBUFFER_OPERATION, raised here; GL 3.0 §4.4.4).
    pub(crate) fn framebuffer_incomplete(&mut self) -> bool {
        if self.fbos.bound_fb != 0 && self.fbos.loaded.is_none() {
            self.error(gl::INVALID_FRAMEBUFFER_OPERATION);
            return true;
        }
        false
    }

    /// `glGenFramebuffers`: `n` unused names in `ids` (after the largest used). INVALID_VALUE
    /// for a negative `n` or (Rust API) an `ids` shorter than `n`; OUT_OF_MEMORY when the names
    /// run out. Executed immediately under NewList.
    pub fn gen_framebuffers(&mut self, n: i32, ids: &mut [u32]) {
        let made = self.gen_fbo_names(n, ids, true);
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::GenFramebuffers(n, made));
        }
    }

    /// `glGenRenderbuffers`: as [`Context::gen_framebuffers`], for renderbuffers.
    pub fn gen_renderbuffers(&mut self, n: i32, ids: &mut [u32]) {
        let made = self.gen_fbo_names(n, ids, false);
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::GenRenderbuffers(n, made));
        }
    }

    /// A recorded GenFramebuffers replayed: takes as many names.
    pub(super) fn replay_gen_framebuffers(&mut self, n: i32, names: &[u32]) {
        let mut out = vec![0; names.len()];
        self.gen_framebuffers(n, &mut out);
    }

    /// A recorded GenRenderbuffers replayed: takes as many names.
    pub(super) fn replay_gen_renderbuffers(&mut self, n: i32, names: &[u32]) {
        let mut out = vec![0; names.len()];
        self.gen_renderbuffers(n, &mut out);
    }

    fn gen_fbo_names(&mut self, n: i32, ids: &mut [u32], framebuffers: bool) -> Vec<u32> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return Vec::new();
        }
        let Ok(n) = usize::try_from(n) else {
            self.error(gl::INVALID_VALUE);
            return Vec::new();
        };
        let Some(out) = ids.get_mut(..n) else {
            self.error(gl::INVALID_VALUE);
            return Vec::new();
        };
        let max_used = match framebuffers {
            true => self.fbos.fb_max,
            false => self.fbos.rb_max,
        };
        let first = u64::from(max_used) + 1;
        if first + n as u64 > u64::from(u32::MAX) + 1 {
            self.error(gl::OUT_OF_MEMORY);
            return Vec::new();
        }
        let f = &mut self.fbos;
        let (max, names) = match framebuffers {
            true => (&mut f.fb_max, &mut f.fb_names),
            false => (&mut f.rb_max, &mut f.rb_names),
        };
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = (first + k as u64) as u32;
            names.insert(*slot);
        }
        if n > 0 {
            *max = (first + n as u64 - 1) as u32;
        }
        out.to_vec()
    }

    /// `glIsFramebuffer`: whether `id` names a framebuffer object (bound at least once and
    /// not deleted). FALSE between Begin and End (with INVALID_OPERATION). Not recorded.
    pub fn is_framebuffer(&mut self, id: u32) -> bool {
        if !self.outside_begin_end() {
            return false;
        }
        self.fbos.framebuffers.contains_key(&id)
    }

    /// `glIsRenderbuffer`: as [`Context::is_framebuffer`], for renderbuffers.
    pub fn is_renderbuffer(&mut self, id: u32) -> bool {
        if !self.outside_begin_end() {
            return false;
        }
        self.fbos.renderbuffers.contains_key(&id)
    }

    /// `glBindRenderbuffer`: RENDERBUFFER_BINDING; any name, the object made at its first
    /// binding. INVALID_ENUM for a `target` other than RENDERBUFFER.
    pub fn bind_renderbuffer(&mut self, target: u32, id: u32) {
        record!(self, Call::BindRenderbuffer(target, id));
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM);
        }
        if id != 0 {
            let f = &mut self.fbos;
            f.rb_names.remove(&id);
            f.rb_max = f.rb_max.max(id);
            f.renderbuffers.entry(id).or_insert_with(|| Renderbuffer {
                internal_format: gl::RGBA,
                ..Default::default()
            });
        }
        self.fbos.bound_rb = id;
    }

    /// `glBindFramebuffer`: FRAMEBUFFER_BINDING; any name, the object made at its first
    /// binding; 0 is the window. The renderer then draws into the object's attachments (when
    /// it is complete). INVALID_ENUM for a `target` other than FRAMEBUFFER.
    pub fn bind_framebuffer(&mut self, target: u32, id: u32) {
        record!(self, Call::BindFramebuffer(target, id));
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::FRAMEBUFFER {
            return self.error(gl::INVALID_ENUM);
        }
        if id != 0 {
            let f = &mut self.fbos;
            f.fb_names.remove(&id);
            f.fb_max = f.fb_max.max(id);
            f.framebuffers.entry(id).or_default();
        }
        self.fbo_store();
        self.fbo_switch(id);
        self.fbo_load();
    }

    /// `glDeleteRenderbuffers`: deletes the named renderbuffers (0 and unknown names ignored);
    /// one bound is unbound, and one attached to the bound framebuffer detached (GL 3.0
    /// §4.4.2). INVALID_VALUE for a negative `n` or (Rust API) fewer than `n` names.
    pub fn delete_renderbuffers(&mut self, n: i32, ids: &[u32]) {
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::DeleteRenderbuffers(n, ids.to_vec()));
        }
        if !self.outside_begin_end() {
            return;
        }
        let Some(ids) = usize::try_from(n).ok().and_then(|n| ids.get(..n)) else {
            return self.error(gl::INVALID_VALUE);
        };
        self.fbo_store();
        for &id in ids.iter().filter(|&&id| id != 0) {
            let f = &mut self.fbos;
            f.rb_names.remove(&id);
            if f.renderbuffers.remove(&id).is_none() {
                continue;
            }
            if f.bound_rb == id {
                f.bound_rb = 0;
            }
            if let Some(obj) = f.framebuffers.get_mut(&f.bound_fb) {
                for att in [&mut obj.color, &mut obj.depth, &mut obj.stencil] {
                    if *att == Attachment::Renderbuffer(id) {
                        *att = Attachment::None;
                    }
                }
            }
        }
        self.fbo_load();
    }

    /// `glDeleteFramebuffers`: deletes the named framebuffer objects (0 and unknown names
    /// ignored); deleting the bound one binds the window (GL 3.0 §4.4.1). INVALID_VALUE for a
    /// negative `n` or (Rust API) fewer than `n` names.
    pub fn delete_framebuffers(&mut self, n: i32, ids: &[u32]) {
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::DeleteFramebuffers(n, ids.to_vec()));
        }
        if !self.outside_begin_end() {
            return;
        }
        let Some(ids) = usize::try_from(n).ok().and_then(|n| ids.get(..n)) else {
            return self.error(gl::INVALID_VALUE);
        };
        for &id in ids.iter().filter(|&&id| id != 0) {
            self.fbos.fb_names.remove(&id);
            if !self.fbos.framebuffers.contains_key(&id) {
                continue;
            }
            if self.fbos.bound_fb == id {
                self.fbo_store();
                self.fbo_switch(0);
            }
            self.fbos.framebuffers.remove(&id);
        }
    }

    /// DRAW_BUFFER or READ_BUFFER changed: while an object is bound they are its own, and its
    /// completeness depends on them.
    pub(super) fn fbo_buffers_changed(&mut self) {
        let f = &mut self.fbos;
        let Some(obj) = f.framebuffers.get_mut(&f.bound_fb) else {
            return;
        };
        if (obj.draw_buffer, obj.read_buffer) == (self.state.draw_buffer, self.state.read_buffer) {
            return;
        }
        self.fbo_store();
        let f = &mut self.fbos;
        if let Some(obj) = f.framebuffers.get_mut(&f.bound_fb) {
            obj.draw_buffer = self.state.draw_buffer;
            obj.read_buffer = self.state.read_buffer;
        }
        self.fbo_load();
    }

    /// Detaches texture `name` from the bound framebuffer (DeleteTextures, GL 3.0 §4.4.2),
    /// after storing what was drawn; the caller deletes the texture and calls `fbo_load`.
    pub(super) fn fbo_detach_texture(&mut self, name: u32) {
        let f = &mut self.fbos;
        let Some(obj) = f.framebuffers.get_mut(&f.bound_fb) else {
            return;
        };
        for att in [&mut obj.color, &mut obj.depth, &mut obj.stencil] {
            if matches!(*att, Attachment::Texture { name: n, .. } if n == name) {
                *att = Attachment::None;
            }
        }
    }

    /// `glRenderbufferStorage`: the bound renderbuffer's format and size; its contents become
    /// undefined (here: colour 0, depth 1, stencil 0). INVALID_ENUM for a `target` other than
    /// RENDERBUFFER or an internal format renderbuffers do not take; INVALID_VALUE for a side
    /// below 0 or above MAX_RENDERBUFFER_SIZE; INVALID_OPERATION with renderbuffer 0 bound;
    /// OUT_OF_MEMORY when the pixels cannot be allocated.
    pub fn renderbuffer_storage(
        &mut self,
        target: u32,
        internalformat: u32,
        width: i32,
        height: i32,
    ) {
        record!(
            self,
            Call::RenderbufferStorage(target, internalformat, width, height)
        );
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM);
        }
        let Some(base) = renderbuffer_base(internalformat) else {
            return self.error(gl::INVALID_ENUM);
        };
        if !(0..=MAX_RENDERBUFFER_SIZE).contains(&width)
            || !(0..=MAX_RENDERBUFFER_SIZE).contains(&height)
        {
            return self.error(gl::INVALID_VALUE);
        }
        if self.fbos.bound_rb == 0 {
            return self.error(gl::INVALID_OPERATION);
        }
        let n = width as usize * height as usize;
        let mut rb = Renderbuffer {
            internal_format: internalformat,
            width,
            height,
            ..Default::default()
        };
        let ok = match base {
            gl::DEPTH_COMPONENT => filled(&mut rb.depth, n, DEPTH_MAX),
            gl::STENCIL_INDEX => filled(&mut rb.stencil, n, 0),
            gl::DEPTH_STENCIL => {
                filled(&mut rb.depth, n, DEPTH_MAX) && filled(&mut rb.stencil, n, 0)
            }
            _ => filled(
                &mut rb.color,
                n,
                [0, 0, 0, if base == gl::RGB { 255 } else { 0 }],
            ),
        };
        if !ok {
            return self.error(gl::OUT_OF_MEMORY);
        }
        self.fbo_store();
        let id = self.fbos.bound_rb;
        self.fbos.renderbuffers.insert(id, rb);
        self.fbo_load();
    }

    /// `glFramebufferTexture1D` (GL 3.0 §4.4.2): attaches level `level` of 1D texture
    /// `texture` (0 detaches). Errors as [`Context::framebuffer_texture_2d`], `textarget`
    /// TEXTURE_1D.
    pub fn framebuffer_texture_1d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        record!(
            self,
            Call::FramebufferTexture1D(target, attachment, textarget, texture, level)
        );
        self.framebuffer_texture(1, target, attachment, textarget, texture, level, 0);
    }

    /// `glFramebufferTexture2D` (GL 3.0 §4.4.2): attaches level `level` of the 2D texture (or
    /// cube-map face `textarget`) `texture` to `attachment` of the bound framebuffer; texture 0
    /// detaches. INVALID_ENUM for a `target` other than FRAMEBUFFER or an `attachment` that is
    /// not COLOR_ATTACHMENTi, DEPTH_ATTACHMENT or STENCIL_ATTACHMENT; INVALID_OPERATION with
    /// framebuffer 0 bound, for COLOR_ATTACHMENTi past MAX_COLOR_ATTACHMENTS, for a texture
    /// that does not exist or whose target does not match `textarget`; INVALID_VALUE for a
    /// level outside the texture target's levels.
    pub fn framebuffer_texture_2d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        record!(
            self,
            Call::FramebufferTexture2D(target, attachment, textarget, texture, level)
        );
        self.framebuffer_texture(2, target, attachment, textarget, texture, level, 0);
    }

    /// `glFramebufferTexture3D` (GL 3.0 §4.4.2): attaches image `zoffset` of level `level` of
    /// 3D texture `texture`. Errors as [`Context::framebuffer_texture_2d`], and INVALID_VALUE
    /// for a `zoffset` outside 0..MAX_3D_TEXTURE_SIZE.
    #[allow(clippy::too_many_arguments)]
    pub fn framebuffer_texture_3d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
        zoffset: i32,
    ) {
        record!(
            self,
            Call::FramebufferTexture3D(target, attachment, textarget, texture, level, zoffset)
        );
        self.framebuffer_texture(3, target, attachment, textarget, texture, level, zoffset);
    }

    /// The attachment point `attachment` names in the bound framebuffer, after the target and
    /// attachment errors (raised here).
    fn attachment_point(&mut self, target: u32, attachment: u32) -> Option<()> {
        if target != gl::FRAMEBUFFER {
            self.error(gl::INVALID_ENUM);
            return None;
        }
        match attachment {
            gl::COLOR_ATTACHMENT0 | gl::DEPTH_ATTACHMENT | gl::STENCIL_ATTACHMENT => {}
            gl::COLOR_ATTACHMENT1..=gl::COLOR_ATTACHMENT15 => {
                self.error(gl::INVALID_OPERATION);
                return None;
            }
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        }
        if self.fbos.bound_fb == 0 {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        Some(())
    }

    /// FramebufferTexture1D/2D/3D after recording.
    #[allow(clippy::too_many_arguments)]
    fn framebuffer_texture(
        &mut self,
        dims: usize,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
        zoffset: i32,
    ) {
        if !self.outside_begin_end() {
            return;
        }
        if self.attachment_point(target, attachment).is_none() {
            return;
        }
        let new = if texture == 0 {
            Attachment::None
        } else {
            let targets_ok = match dims {
                1 => textarget == gl::TEXTURE_1D,
                3 => textarget == gl::TEXTURE_3D,
                _ => {
                    textarget == gl::TEXTURE_2D
                        || (gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
                            .contains(&textarget)
                }
            };
            if !targets_ok {
                return self.error(gl::INVALID_OPERATION);
            }
            let (bind, _) = image_binding(textarget);
            match self.state.textures.objects.get(&texture) {
                Some(obj) if obj.target == bind => {}
                _ => return self.error(gl::INVALID_OPERATION),
            }
            let max_level = match bind {
                gl::TEXTURE_3D => 8,
                gl::TEXTURE_CUBE_MAP => 11,
                _ => MAX_LEVELS as i32 - 1,
            };
            if !(0..=max_level).contains(&level) {
                return self.error(gl::INVALID_VALUE);
            }
            if dims == 3 && !(0..256).contains(&zoffset) {
                return self.error(gl::INVALID_VALUE);
            }
            Attachment::Texture {
                name: texture,
                target: textarget,
                level,
                zoffset: if dims == 3 { zoffset } else { 0 },
            }
        };
        self.set_attachment(attachment, new);
    }

    /// `glFramebufferRenderbuffer` (GL 3.0 §4.4.2): attaches renderbuffer `renderbuffer` (0
    /// detaches). Errors as FramebufferTexture2D for `target` and `attachment`; INVALID_ENUM
    /// for a `renderbuffertarget` other than RENDERBUFFER; INVALID_OPERATION for a name that
    /// is not a renderbuffer object.
    pub fn framebuffer_renderbuffer(
        &mut self,
        target: u32,
        attachment: u32,
        renderbuffertarget: u32,
        renderbuffer: u32,
    ) {
        record!(
            self,
            Call::FramebufferRenderbuffer(target, attachment, renderbuffertarget, renderbuffer)
        );
        if !self.outside_begin_end() {
            return;
        }
        if self.attachment_point(target, attachment).is_none() {
            return;
        }
        if renderbuffertarget != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM);
        }
        if renderbuffer != 0 && !self.fbos.renderbuffers.contains_key(&renderbuffer) {
            return self.error(gl::INVALID_OPERATION);
        }
        let new = match renderbuffer {
            0 => Attachment::None,
            id => Attachment::Renderbuffer(id),
        };
        self.set_attachment(attachment, new);
    }

    /// Stores what was drawn, changes `attachment` of the bound framebuffer (validated), and
    /// loads the result.
    fn set_attachment(&mut self, attachment: u32, new: Attachment) {
        self.fbo_store();
        let f = &mut self.fbos;
        if let Some(obj) = f.framebuffers.get_mut(&f.bound_fb) {
            match attachment {
                gl::DEPTH_ATTACHMENT => obj.depth = new,
                gl::STENCIL_ATTACHMENT => obj.stencil = new,
                _ => obj.color = new,
            }
        }
        self.fbo_load();
    }

    /// `glCheckFramebufferStatus` (GL 3.0 §4.4.4): FRAMEBUFFER_COMPLETE for the window or a
    /// complete object, else the first reason it is not. INVALID_ENUM (returning 0) for a
    /// `target` other than FRAMEBUFFER; INVALID_OPERATION (0) between Begin and End. Not
    /// recorded (a query).
    pub fn check_framebuffer_status(&mut self, target: u32) -> u32 {
        if !self.outside_begin_end() {
            return 0;
        }
        if target != gl::FRAMEBUFFER {
            self.error(gl::INVALID_ENUM);
            return 0;
        }
        match self.fbos.framebuffers.get(&self.fbos.bound_fb) {
            None => gl::FRAMEBUFFER_COMPLETE,
            Some(obj) => self
                .status_of(obj)
                .err()
                .unwrap_or(gl::FRAMEBUFFER_COMPLETE),
        }
    }

    /// The size of the image an attachment names and its base format, `Err` with the status
    /// of an attachment that is not attachment-complete (GL 3.0 §4.4.4) for `point`.
    fn attachment_image(&self, att: &Attachment, point: u32) -> Result<Option<(i32, i32)>, u32> {
        let incomplete = gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
        let (w, h, base) = match *att {
            Attachment::None => return Ok(None),
            Attachment::Texture { zoffset, .. } => {
                let lv = attached_level(&self.state.textures.objects, att).ok_or(incomplete)?;
                if zoffset >= lv.depth.max(1) {
                    return Err(incomplete);
                }
                (lv.width, lv.height, lv.base)
            }
            Attachment::Renderbuffer(id) => {
                let rb = self.fbos.renderbuffers.get(&id).ok_or(incomplete)?;
                let base = renderbuffer_base(rb.internal_format).ok_or(incomplete)?;
                (rb.width, rb.height, base)
            }
        };
        let fits = match point {
            gl::DEPTH_ATTACHMENT => crate::texture::is_depth(base),
            gl::STENCIL_ATTACHMENT => matches!(base, gl::STENCIL_INDEX | gl::DEPTH_STENCIL),
            _ => color_renderable(base),
        };
        if w <= 0 || h <= 0 || !fits {
            return Err(incomplete);
        }
        Ok(Some((w, h)))
    }

    /// The size of a complete framebuffer object, or the status saying why it is not. As
    /// Mesa decides it in its compatibility context (with ARB_framebuffer_object and
    /// ARB_ES2_compatibility), not as EXT_framebuffer_object alone: attachments of different
    /// sizes are complete, drawing covering the smallest (no INCOMPLETE_DIMENSIONS), and
    /// DRAW_BUFFER or READ_BUFFER naming an empty attachment is no INCOMPLETE_DRAW_BUFFER or
    /// INCOMPLETE_READ_BUFFER (a depth-only object is complete); attachments are checked
    /// depth, stencil, colour, as Mesa's loop. Depth and stencil attachments that are not the
    /// same image (one DEPTH_STENCIL renderbuffer or texture level on both points) are
    /// FRAMEBUFFER_UNSUPPORTED, as llvmpipe answers (measured); either alone is complete.
    fn status_of(&self, obj: &FboObject) -> Result<(u32, u32), u32> {
        let d = self.attachment_image(&obj.depth, gl::DEPTH_ATTACHMENT)?;
        let s = self.attachment_image(&obj.stencil, gl::STENCIL_ATTACHMENT)?;
        let c = self.attachment_image(&obj.color, gl::COLOR_ATTACHMENT0)?;
        let sizes: Vec<(i32, i32)> = [d, s, c].into_iter().flatten().collect();
        if sizes.is_empty() {
            return Err(gl::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT);
        }
        if d.is_some() && s.is_some() && obj.depth != obj.stencil {
            return Err(gl::FRAMEBUFFER_UNSUPPORTED);
        }
        let w = sizes.iter().map(|s| s.0).min().unwrap_or(0);
        let h = sizes.iter().map(|s| s.1).min().unwrap_or(0);
        Ok((w as u32, h as u32))
    }

    /// `glGetFramebufferAttachmentParameteriv` (GL 3.0 §6.1.13): OBJECT_TYPE (NONE, TEXTURE
    /// or RENDERBUFFER), OBJECT_NAME, and for a texture TEXTURE_LEVEL, TEXTURE_CUBE_MAP_FACE
    /// and TEXTURE_3D_ZOFFSET (FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER). INVALID_ENUM for a
    /// `target` other than FRAMEBUFFER, another `attachment`, or a pname the attachment's
    /// type does not have; INVALID_OPERATION with framebuffer 0 bound. Not recorded.
    pub fn get_framebuffer_attachment_parameteriv(
        &mut self,
        target: u32,
        attachment: u32,
        pname: u32,
        params: &mut [i32],
    ) {
        if !self.outside_begin_end() || self.attachment_point(target, attachment).is_none() {
            return;
        }
        let Some(obj) = self.fbos.framebuffers.get(&self.fbos.bound_fb) else {
            return;
        };
        let att = match attachment {
            gl::DEPTH_ATTACHMENT => obj.depth,
            gl::STENCIL_ATTACHMENT => obj.stencil,
            _ => obj.color,
        };
        let value = match (att, pname) {
            (Attachment::None, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) => gl::NONE as i32,
            (Attachment::Texture { .. }, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) => {
                gl::TEXTURE as i32
            }
            (Attachment::Renderbuffer(_), gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) => {
                gl::RENDERBUFFER as i32
            }
            (Attachment::Texture { name, .. }, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME)
            | (Attachment::Renderbuffer(name), gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME) => {
                name as i32
            }
            (Attachment::Texture { level, .. }, gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL) => level,
            (
                Attachment::Texture { target, .. },
                gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
            ) => match target {
                gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z => target as i32,
                _ => 0,
            },
            (Attachment::Texture { zoffset, .. }, gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER) => {
                zoffset
            }
            _ => return self.error(gl::INVALID_ENUM),
        };
        match params.first_mut() {
            Some(p) => *p = value,
            None => self.error(gl::INVALID_VALUE),
        }
    }

    /// `glGetRenderbufferParameteriv` (GL 3.0 §6.1.14): the bound renderbuffer's WIDTH,
    /// HEIGHT, INTERNAL_FORMAT and component sizes (8 bits a colour component, 24 depth bits,
    /// 8 stencil bits, as stored). INVALID_ENUM for a `target` other than RENDERBUFFER or
    /// another pname; INVALID_OPERATION with renderbuffer 0 bound. Not recorded.
    pub fn get_renderbuffer_parameteriv(&mut self, target: u32, pname: u32, params: &mut [i32]) {
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM);
        }
        let Some(rb) = self.fbos.renderbuffers.get(&self.fbos.bound_rb) else {
            return self.error(gl::INVALID_OPERATION);
        };
        let base = renderbuffer_base(rb.internal_format);
        let sized = rb.width > 0 && rb.height > 0;
        let bits = |b: bool, n: i32| if b && sized { n } else { 0 };
        let value = match pname {
            gl::RENDERBUFFER_WIDTH => rb.width,
            gl::RENDERBUFFER_HEIGHT => rb.height,
            gl::RENDERBUFFER_INTERNAL_FORMAT => rb.internal_format as i32,
            gl::RENDERBUFFER_RED_SIZE
            | gl::RENDERBUFFER_GREEN_SIZE
            | gl::RENDERBUFFER_BLUE_SIZE => bits(matches!(base, Some(gl::RGB | gl::RGBA)), 8),
            gl::RENDERBUFFER_ALPHA_SIZE => bits(base == Some(gl::RGBA), 8),
            gl::RENDERBUFFER_DEPTH_SIZE => bits(
                matches!(base, Some(gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL)),
                24,
            ),
            gl::RENDERBUFFER_STENCIL_SIZE => bits(
                matches!(base, Some(gl::STENCIL_INDEX | gl::DEPTH_STENCIL)),
                8,
            ),
            _ => return self.error(gl::INVALID_ENUM),
        };
        match params.first_mut() {
            Some(p) => *p = value,
            None => self.error(gl::INVALID_VALUE),
        }
    }

    /// `glGenerateMipmap` (GL 3.0 §3.8.8): the levels after the base level of the texture bound
    /// to `target` on the active unit, from the base level, as GENERATE_MIPMAP makes them.
    /// INVALID_ENUM for a `target` other than TEXTURE_1D, TEXTURE_2D, TEXTURE_3D or
    /// TEXTURE_CUBE_MAP; INVALID_OPERATION for a cube map whose faces are not all the same
    /// square size and format (cube complete).
    pub fn generate_mipmap(&mut self, target: u32) {
        record!(self, Call::GenerateMipmap(target));
        if !self.outside_begin_end() {
            return;
        }
        if !matches!(
            target,
            gl::TEXTURE_1D | gl::TEXTURE_2D | gl::TEXTURE_3D | gl::TEXTURE_CUBE_MAP
        ) {
            return self.error(gl::INVALID_ENUM);
        }
        let unit = self.state.active_texture;
        if target == gl::TEXTURE_CUBE_MAP {
            let Some(obj) = self.state.textures.bound(unit, target) else {
                return;
            };
            let base = obj.base_level;
            let faces: Vec<_> = (0..6).map(|f| obj.face_level(f, base)).collect();
            let first = faces[0].map(|l| (l.width, l.height, l.internal_format));
            let complete = first.is_some_and(|(w, h, _)| w == h)
                && faces
                    .iter()
                    .all(|l| l.map(|l| (l.width, l.height, l.internal_format)) == first);
            if !complete {
                return self.error(gl::INVALID_OPERATION);
            }
        }
        self.fbo_store();
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            if let Some(obj) = ctx.state.textures.bound_mut(unit, target) {
                obj.generate_mipmaps();
            }
        });
        self.fbo_load();
    }

    /// Switches the renderer from whatever it draws into to the window (`id` 0) or leaves it
    /// on the window's set-aside framebuffer's place for an object (loaded by `fbo_load`);
    /// the per-framebuffer DRAW_BUFFER and READ_BUFFER follow the binding. Call `fbo_store`
    /// first.
    fn fbo_switch(&mut self, id: u32) {
        let old = self.fbos.bound_fb;
        if old == id {
            return;
        }
        // The outgoing object's own DRAW_BUFFER and READ_BUFFER.
        if let Some(obj) = self.fbos.framebuffers.get_mut(&old) {
            obj.draw_buffer = self.state.draw_buffer;
            obj.read_buffer = self.state.read_buffer;
        }
        self.fbos.bound_fb = id;
        if id == 0 {
            if let Some(w) = self.fbos.window.take() {
                self.renderer.swap_framebuffer(&self.state, w.fb);
                self.state.width = w.width;
                self.state.height = w.height;
                self.state.config = w.config;
                self.state.y0_top = w.y0_top;
                self.state.draw_buffer = w.draw_buffer;
                self.state.read_buffer = w.read_buffer;
            }
            return;
        }
        if old == 0 {
            // Set the window aside: a 1 x 1 placeholder (allocation-free in practice) stands in
            // until `fbo_load` puts the object's buffers in.
            let config = ContextConfig {
                double_buffered: false,
                depth: false,
                stencil: false,
                accum: false,
                alpha: true,
            };
            let Some(placeholder) = Framebuffer::try_new(1, 1, config) else {
                self.fbos.bound_fb = old;
                return self.error(gl::OUT_OF_MEMORY);
            };
            let fb = self.renderer.swap_framebuffer(&self.state, placeholder);
            self.fbos.window = Some(Window {
                fb,
                width: self.state.width,
                height: self.state.height,
                config: self.state.config,
                y0_top: self.state.y0_top,
                draw_buffer: self.state.draw_buffer,
                read_buffer: self.state.read_buffer,
            });
            self.placeholder_state();
        }
        if let Some(obj) = self.fbos.framebuffers.get(&id) {
            self.state.draw_buffer = obj.draw_buffer;
            self.state.read_buffer = obj.read_buffer;
        }
    }

    /// The state's framebuffer size and buffers while the renderer holds the 1 x 1 placeholder
    /// of an incomplete object (nothing draws into it: INVALID_FRAMEBUFFER_OPERATION).
    fn placeholder_state(&mut self) {
        self.state.width = 1;
        self.state.height = 1;
        // A framebuffer object: llvmpipe draws it the GL way up.
        self.state.y0_top = false;
        self.state.config = ContextConfig {
            double_buffered: false,
            depth: false,
            stencil: false,
            accum: false,
            alpha: true,
        };
    }

    /// Writes the renderer's framebuffer back into the images it was loaded from (nothing
    /// when no object is loaded), then leaves nothing loaded: the renderer holds a placeholder
    /// until `fbo_load`.
    pub(super) fn fbo_store(&mut self) {
        let Some(loaded) = self.fbos.loaded.take() else {
            return;
        };
        let config = ContextConfig {
            double_buffered: false,
            depth: false,
            stencil: false,
            accum: false,
            alpha: true,
        };
        let Some(placeholder) = Framebuffer::try_new(1, 1, config) else {
            // Keep drawing into the loaded framebuffer rather than lose it.
            self.fbos.loaded = Some(loaded);
            return self.error(gl::OUT_OF_MEMORY);
        };
        let mut fb = self.renderer.swap_framebuffer(&self.state, placeholder);
        self.placeholder_state();
        fb.materialize_all();
        let (w, h) = fb.size();
        let pixel = |x: u32, y: u32| {
            fb.pixel_in(crate::cpu::framebuffer::ColorBuf::Main, x as i64, y as i64)
        };
        // Colour.
        match loaded.color {
            Attachment::Renderbuffer(id) => {
                if let Some(rb) = self.fbos.renderbuffers.get_mut(&id) {
                    rb_store(&fb, rb.width, &mut rb.color, |r| match r {
                        RowRun::Inside { color, .. } => Some(color),
                        RowRun::Outside(_) => None,
                    });
                }
            }
            att @ Attachment::Texture { .. } => {
                let objects = &mut self.state.textures.objects;
                if !store_texture_fb(objects, &att, &fb, false) {
                    store_texture(objects, &att, w, h, None, |x, y| {
                        pixel(x, y).map(|(c, _, _)| c.map(|v| f32::from(v) / 255.0))
                    });
                }
            }
            Attachment::None => {}
        }
        // Depth.
        match loaded.depth {
            Attachment::Renderbuffer(id) => {
                if let Some(rb) = self.fbos.renderbuffers.get_mut(&id) {
                    rb_store(&fb, rb.width, &mut rb.depth, |r| match r {
                        RowRun::Inside { depth, .. } => Some(depth),
                        RowRun::Outside(_) => None,
                    });
                }
            }
            att @ Attachment::Texture { .. } => {
                let objects = &mut self.state.textures.objects;
                if !store_texture_fb(objects, &att, &fb, true) {
                    store_texture(objects, &att, w, h, Some(0), |x, y| {
                        pixel(x, y).map(|(_, d, _)| [d as f32 / DEPTH_MAX as f32, 0.0, 0.0, 0.0])
                    });
                }
            }
            Attachment::None => {}
        }
        // Stencil (a STENCIL_INDEX or DEPTH_STENCIL renderbuffer, a DEPTH_STENCIL texture's G).
        match loaded.stencil {
            Attachment::Renderbuffer(id) => {
                if let Some(rb) = self.fbos.renderbuffers.get_mut(&id) {
                    rb_store(&fb, rb.width, &mut rb.stencil, |r| match r {
                        RowRun::Inside { stencil, .. } => Some(stencil),
                        RowRun::Outside(_) => None,
                    });
                }
            }
            att @ Attachment::Texture { .. } => {
                store_texture(
                    &mut self.state.textures.objects,
                    &att,
                    w,
                    h,
                    Some(1),
                    |x, y| pixel(x, y).map(|(_, _, s)| [0.0, f32::from(s), 0.0, 0.0]),
                );
            }
            Attachment::None => {}
        }
    }

    /// Loads the bound object's attachments into a framebuffer for the renderer when the
    /// object is complete (nothing loaded, drawing refused, when it is not; nothing for the
    /// window). Call after `fbo_store`.
    pub(super) fn fbo_load(&mut self) {
        debug_assert!(self.fbos.loaded.is_none());
        let id = self.fbos.bound_fb;
        let Some(obj) = self.fbos.framebuffers.get(&id).cloned() else {
            return;
        };
        let Ok((w, h)) = self.status_of(&obj) else {
            return;
        };
        let config = ContextConfig {
            double_buffered: false,
            depth: obj.depth != Attachment::None,
            stencil: obj.stencil != Attachment::None,
            accum: false,
            alpha: true,
        };
        let Some(mut fb) = Framebuffer::try_new(w, h, config) else {
            return self.error(gl::OUT_OF_MEMORY);
        };
        let objects = &self.state.textures.objects;
        // Each image a row at a time (`set_row`: what `set_pixel` writes pixel by pixel).
        match obj.color {
            Attachment::Renderbuffer(rid) => {
                if let Some(rb) = self.fbos.renderbuffers.get(&rid) {
                    let rw = rb.width.max(1) as usize;
                    for (y, row) in rb.color.chunks(rw).enumerate() {
                        fb.set_row(y as u32, row, |f| &mut f.color);
                    }
                }
            }
            att @ Attachment::Texture { zoffset, .. } => {
                if let Some(lv) = attached_level(objects, &att) {
                    let mut row = vec![[0u8; 4]; w as usize];
                    let rgb = lv.base == gl::RGB;
                    let px =
                        |t: [f32; 4]| unorm8x4([t[0], t[1], t[2], if rgb { 1.0 } else { t[3] }]);
                    for y in 0..h as i32 {
                        match level_row(lv, y, zoffset, row.len()) {
                            Some(src) => unorm8_row(src, &mut row, rgb),
                            None => {
                                for (x, c) in row.iter_mut().enumerate() {
                                    *c = px(lv.texel3(x as i32, y, zoffset));
                                }
                            }
                        }
                        fb.set_row(y as u32, &row, |f| &mut f.color);
                    }
                }
            }
            Attachment::None => {}
        }
        match obj.depth {
            Attachment::Renderbuffer(rid) => {
                if let Some(rb) = self.fbos.renderbuffers.get(&rid) {
                    let rw = rb.width.max(1) as usize;
                    for (y, row) in rb.depth.chunks(rw).enumerate() {
                        fb.set_row(y as u32, row, |f| &mut f.depth);
                    }
                }
            }
            att @ Attachment::Texture { zoffset, .. } => {
                if let Some(lv) = attached_level(objects, &att) {
                    let mut row = vec![0u32; w as usize];
                    for y in 0..h as i32 {
                        match level_row(lv, y, zoffset, row.len()) {
                            Some(src) => {
                                for (d, t) in row.iter_mut().zip(src) {
                                    *d = depth_unorm(f64::from(t[0]));
                                }
                            }
                            None => {
                                for (x, d) in row.iter_mut().enumerate() {
                                    let z = lv.texel3(x as i32, y, zoffset)[0];
                                    *d = depth_unorm(f64::from(z));
                                }
                            }
                        }
                        fb.set_row(y as u32, &row, |f| &mut f.depth);
                    }
                }
            }
            Attachment::None => {}
        }
        match obj.stencil {
            Attachment::Renderbuffer(rid) => {
                if let Some(rb) = self.fbos.renderbuffers.get(&rid) {
                    let rw = rb.width.max(1) as usize;
                    for (y, row) in rb.stencil.chunks(rw).enumerate() {
                        fb.set_row(y as u32, row, |f| &mut f.stencil);
                    }
                }
            }
            att @ Attachment::Texture { zoffset, .. } => {
                if let Some(lv) = attached_level(objects, &att) {
                    let mut row = vec![0u8; w as usize];
                    for y in 0..h as i32 {
                        for (x, s) in row.iter_mut().enumerate() {
                            *s = lv.texel3(x as i32, y, zoffset)[1].clamp(0.0, 255.0) as u8;
                        }
                        fb.set_row(y as u32, &row, |f| &mut f.stencil);
                    }
                }
            }
            Attachment::None => {}
        }
        self.renderer.swap_framebuffer(&self.state, fb);
        self.state.width = w;
        self.state.height = h;
        self.state.config = config;
        self.fbos.loaded = Some(Loaded {
            color: obj.color,
            depth: obj.depth,
            stencil: obj.stencil,
        });
    }

    /// Forgets every framebuffer and renderbuffer object, the window's framebuffer back in the
    /// renderer (`Context::reset`).
    pub(super) fn fbo_reset(&mut self) {
        self.fbo_store();
        self.fbo_switch(0);
        self.fbos = Fbos::default();
    }
}

/// The `n` texels `Level::texel3` reads at (x, y, k), x = 0 .. n, as one slice of the level
/// (`texel3`'s index of (0, y, k), in the same i32 arithmetic, and the n texels after it);
/// `None` when they are not all inside the level's texels (then `texel3` per texel, which reads
/// zero outside).
fn level_row(lv: &crate::texture::Level, y: i32, k: i32, n: usize) -> Option<&[[f32; 4]]> {
    let at = k
        .checked_mul(lv.height)?
        .checked_add(y)?
        .checked_mul(lv.width)?;
    let at = usize::try_from(at).ok()?;
    lv.texels.get(at..at.checked_add(n)?)
}

/// `c.map(unorm8)`: the four components at once (SSE2: NaN to 0 by `maxps` against 0, which
/// returns its second operand for a NaN, then `minps` against 1, the product and sum in
/// single precision as `unorm8` computes them, the low byte of each sum's bits). A -0 becomes
/// +0 where `clamp` keeps -0, which no byte tells apart (-0·k + 2^15 = +0·k + 2^15). Checked
/// against `unorm8` in `unorm8x4_is_unorm8`.
#[inline(always)]
fn unorm8x4(c: [f32; 4]) -> [u8; 4] {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE2 is part of the x86-64 baseline; the only memory read is `c` itself.
    unsafe {
        use std::arch::x86_64::*;
        let v = _mm_loadu_ps(c.as_ptr());
        let v = _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(1.0));
        let t = _mm_add_ps(
            _mm_mul_ps(v, _mm_set1_ps(255.0 / 256.0)),
            _mm_set1_ps(32768.0),
        );
        let b = _mm_and_si128(_mm_castps_si128(t), _mm_set1_epi32(0xFF));
        let p = _mm_packus_epi16(_mm_packs_epi32(b, b), _mm_setzero_si128());
        (_mm_cvtsi128_si32(p) as u32).to_le_bytes()
    }
    #[cfg(not(target_arch = "x86_64"))]
    c.map(crate::cpu::framebuffer::unorm8)
}

/// `unorm8x4` of each texel of `src` into `dst` (as many as the shorter holds), alpha 1 for
/// an RGB level (`rgb`): a colour attachment's row as `fbo_load` loads it. Eight texels an
/// iteration with AVX2 where the CPU has it (the same operations on eight lanes of four
/// components: `row_avx2`), else `unorm8x4` per texel; `unorm8_rows_are_unorm8x4` compares
/// the two.
fn unorm8_row(src: &[[f32; 4]], dst: &mut [[u8; 4]], rgb: bool) {
    #[cfg(target_arch = "x86_64")]
    if is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2.
        unsafe { unorm8_row_avx2(src, dst, rgb) };
        return;
    }
    unorm8_row_scalar(src, dst, rgb);
}

/// [`unorm8_row`] a texel at a time.
fn unorm8_row_scalar(src: &[[f32; 4]], dst: &mut [[u8; 4]], rgb: bool) {
    for (c, &t) in dst.iter_mut().zip(src) {
        *c = unorm8x4([t[0], t[1], t[2], if rgb { 1.0 } else { t[3] }]);
    }
}

/// [`unorm8_row`] with AVX2: two texels a register, four registers an iteration (`unorm8x4`'s
/// `maxps`/`minps`/`mulps`/`addps` and low byte on each, no fused multiply-add), the 32 bytes
/// packed and put back in texel order by one `vpermd`; the last texels (fewer than eight) by
/// `unorm8x4`.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn unorm8_row_avx2(src: &[[f32; 4]], dst: &mut [[u8; 4]], rgb: bool) {
    use std::arch::x86_64::*;
    let n = src.len().min(dst.len());
    let whole = n - n % 8;
    let one = _mm256_set1_ps(1.0);
    // After the packs, 32-bit element j holds texel [0, 2, 4, 6, 1, 3, 5, 7][j].
    let order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
    // One register of two texels: alpha 1 for an RGB level (lanes 3 and 7 from `one`), then
    // `unorm8x4`'s operations.
    macro_rules! bytes {
        ($v:expr) => {{
            let v = $v;
            let v = if rgb {
                _mm256_blend_ps::<0x88>(v, one)
            } else {
                v
            };
            crate::cpu::lanes::unorm8_bits8(v)
        }};
    }
    let (sp, dp) = (src.as_ptr().cast::<f32>(), dst.as_mut_ptr().cast::<u8>());
    for i in (0..whole).step_by(8) {
        // SAFETY: texels i .. i + 8 lie in both slices (i + 8 <= whole <= n), 16 bytes of
        // floats and 4 bytes a texel; the loads and the store are unaligned.
        unsafe {
            let a = bytes!(_mm256_loadu_ps(sp.add(4 * i)));
            let b = bytes!(_mm256_loadu_ps(sp.add(4 * i + 8)));
            let c = bytes!(_mm256_loadu_ps(sp.add(4 * i + 16)));
            let d = bytes!(_mm256_loadu_ps(sp.add(4 * i + 24)));
            let p = _mm256_packus_epi16(_mm256_packs_epi32(a, b), _mm256_packs_epi32(c, d));
            let p = _mm256_permutevar8x32_epi32(p, order);
            _mm256_storeu_si256(dp.add(4 * i).cast::<__m256i>(), p);
        }
    }
    if let (Some(s), Some(d)) = (src.get(whole..n), dst.get_mut(whole..n)) {
        unorm8_row_scalar(s, d, rgb);
    }
}

/// The framebuffer's pixels into a renderbuffer's image `dst` (rows of `rw` pixels, pixel
/// (x, y) at y·rw + x), the buffer `pick` takes from each run; what lies outside the
/// framebuffer is kept. Row by row, a run at a time: what `fbo_store` did pixel by pixel.
fn rb_store<T: Copy>(
    fb: &Framebuffer,
    rw: i32,
    dst: &mut [T],
    pick: fn(RowRun<'_>) -> Option<Src<'_, T>>,
) {
    let (w, h) = fb.size();
    let rw = rw.max(1) as usize;
    for (y, row) in dst.chunks_mut(rw).enumerate().take(h as usize) {
        let n = row.len().min(w as usize);
        let mut x = 0usize;
        row_runs(fb, ColorBuf::Main, 0, y as i64, n, |run| {
            let len = run.len();
            if let (Some(src), Some(d)) = (pick(run), row.get_mut(x..x + len)) {
                match src {
                    Src::Mem(s) => d.copy_from_slice(&s[..len.min(s.len())]),
                    Src::Fill(v) => d.fill(v),
                }
            }
            x += len;
        });
    }
}

/// [`store_texture`] of the framebuffer's pixels where what it stores is CopyTexImage's
/// texel of the pixel ([`fb_texels`]): a colour attachment of a colour format (`depth`
/// false; `quantize` of v / 255 is v / 255) or the depth attachment of a DEPTH_COMPONENT
/// texture (`depth` true; d / (2^24 - 1) is quantised, the other components zero). Row by
/// row, a run at a time. False, with nothing written, for other images (then `store_texture`).
fn store_texture_fb(
    objects: &mut BTreeMap<u32, Arc<TexObject>>,
    att: &Attachment,
    fb: &Framebuffer,
    depth: bool,
) -> bool {
    let Attachment::Texture {
        name,
        target,
        level,
        zoffset,
    } = *att
    else {
        return false;
    };
    let (_, face) = image_binding(target);
    let Some(obj) = objects.get_mut(&name) else {
        return false;
    };
    let ok = |base: u32| match depth {
        true => base == gl::DEPTH_COMPONENT,
        false => matches!(
            base,
            gl::ALPHA | gl::LUMINANCE | gl::LUMINANCE_ALPHA | gl::INTENSITY | gl::RGB | gl::RGBA
        ),
    };
    if !obj.face_level(face, level).is_some_and(|lv| ok(lv.base)) {
        return false;
    }
    let obj = Arc::make_mut(obj);
    let Some(Some(lv)) = obj.slot_mut(face, level) else {
        return false;
    };
    if !ok(lv.base) {
        return false;
    }
    let (w, h) = fb.size();
    let (lw, lh) = (lv.width.max(0) as u32, lv.height.max(0) as u32);
    let base = lv.base;
    let texels = Arc::make_mut(&mut lv.texels);
    let n = w.min(lw) as usize;
    for y in 0..h.min(lh) {
        // `store_texture`'s index of texel (0, y).
        let i = (zoffset.max(0) as u32)
            .wrapping_mul(lh)
            .wrapping_add(y)
            .wrapping_mul(lw) as usize;
        let end = i.saturating_add(n).min(texels.len());
        let Some(dst) = texels.get_mut(i..end) else {
            continue;
        };
        let mut x = 0usize;
        row_runs(fb, ColorBuf::Main, 0, i64::from(y), dst.len(), |run| {
            if let (RowRun::Inside { .. }, Some(d)) = (run, dst.get_mut(x..)) {
                fb_texels(base, run, d);
            }
            x += run.len();
        });
    }
    if obj.generate_mipmap && level == obj.base_level {
        obj.generate_mipmaps();
    }
    true
}

/// Writes a `w` x `h` rectangle of texels, `get(x, y)` as [0, 1] RGBA (or depth in the first
/// component, a stencil index in the second), into the texture image `att` names, quantised to
/// its format; with `only` Some(k), component k alone (a DEPTH_STENCIL texture's depth or
/// stencil, the other kept).
fn store_texture(
    objects: &mut BTreeMap<u32, Arc<TexObject>>,
    att: &Attachment,
    w: u32,
    h: u32,
    only: Option<usize>,
    get: impl Fn(u32, u32) -> Option<[f32; 4]>,
) {
    let Attachment::Texture {
        name,
        target,
        level,
        zoffset,
    } = *att
    else {
        return;
    };
    let (_, face) = image_binding(target);
    let Some(obj) = objects.get_mut(&name) else {
        return;
    };
    let obj = Arc::make_mut(obj);
    let Some(Some(lv)) = obj.slot_mut(face, level) else {
        return;
    };
    let (lw, lh) = (lv.width.max(0) as u32, lv.height.max(0) as u32);
    let base = lv.base;
    let texels = Arc::make_mut(&mut lv.texels);
    for y in 0..h.min(lh) {
        for x in 0..w.min(lw) {
            let Some(t) = get(x, y) else { continue };
            let i = ((zoffset.max(0) as u32 * lh + y) * lw + x) as usize;
            if let Some(dst) = texels.get_mut(i) {
                let t = match only {
                    Some(k) => {
                        let mut merged = *dst;
                        merged[k] = t[k];
                        merged
                    }
                    None => t,
                };
                *dst = quantize(base, crate::texture::keep(base, t));
            }
        }
    }
    if obj.generate_mipmap && level == obj.base_level {
        obj.generate_mipmaps();
    }
}

/// Fills `v` with `n` copies of `value`; false when the memory cannot be had.
fn filled<T: Clone>(v: &mut Vec<T>, n: usize, value: T) -> bool {
    if v.try_reserve_exact(n).is_err() {
        return false;
    }
    v.resize(n, value);
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::framebuffer::unorm8;

    /// `level_row` is `Level::texel3` of each texel of the row where it gives a slice: levels
    /// of several sizes (texel vectors as long as the sizes say, shorter and longer), rows and
    /// images inside, past the end and negative, rows of every length up to twice the width.
    #[test]
    fn level_row_is_texel3() {
        use crate::texture::Level;
        let mut seed = 0x51ed_2701u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let mut some = 0;
        for round in 0..3000 {
            let (w, h, d) = (1 + next() % 9, 1 + next() % 7, 1 + next() % 3);
            let len = match round % 3 {
                0 => w * h * d,
                1 => (w * h * d).saturating_sub(next() % 5),
                _ => w * h * d + next() % 5,
            } as usize;
            let texels: Vec<[f32; 4]> = (0..len).map(|k| [k as f32, 0.5, 0.25, 1.0]).collect();
            let lv = Level {
                width: w as i32,
                height: h as i32,
                depth: d as i32,
                internal_format: gl::RGBA as i32,
                base: gl::RGBA,
                texels: Arc::new(texels),
            };
            let y = (next() % (h + 3)) as i32 - 1;
            let k = (next() % (d + 2)) as i32 - 1;
            let n = (next() % (2 * w + 1)) as usize;
            if let Some(row) = level_row(&lv, y, k, n) {
                some += 1;
                assert_eq!(row.len(), n);
                for (x, t) in row.iter().enumerate() {
                    assert_eq!(*t, lv.texel3(x as i32, y, k), "{w}x{h}x{d} ({x}, {y}, {k})");
                }
            }
        }
        assert!(some > 1000, "{some}");
        let huge = Level {
            width: i32::MAX,
            height: i32::MAX,
            depth: 1,
            internal_format: gl::RGBA as i32,
            base: gl::RGBA,
            texels: Arc::new(vec![[0.0; 4]; 4]),
        };
        assert!(level_row(&huge, 5, 3, 2).is_none());
        assert!(level_row(&huge, -1, 0, 2).is_none());
    }

    /// `unorm8x4` is `unorm8` per component: every k / 255 and the values between, NaN, ±0,
    /// ±∞, subnormals, values beyond [0, 1], random bit patterns, in every position.
    #[test]
    fn unorm8x4_is_unorm8() {
        let mut vals: Vec<f32> = vec![
            f32::NAN,
            -f32::NAN,
            0.0,
            -0.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MIN_POSITIVE,
            -f32::MIN_POSITIVE,
            1e-45,
            1.0,
            1.0000001,
            0.99999994,
            2.0,
            -1.0,
            0.3,
            0.7,
        ];
        for k in 0..=2550 {
            let x = k as f32 / 2550.0;
            vals.extend([
                x,
                f32::from_bits(x.to_bits() + 1),
                f32::from_bits(x.to_bits().saturating_sub(1)),
            ]);
        }
        let mut seed = 0x1234_5678u32;
        for _ in 0..100_000 {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            vals.push(f32::from_bits(seed));
        }
        for w in vals.windows(4) {
            let c = [w[0], w[1], w[2], w[3]];
            assert_eq!(unorm8x4(c), c.map(unorm8), "{c:?}");
        }
    }

    /// `unorm8_row` (AVX2 where the CPU has it) is `unorm8x4` per texel, alpha 1 for an RGB
    /// level: awkward floats, every row length from 0 to 40 and misaligned starts.
    #[test]
    fn unorm8_rows_are_unorm8x4() {
        let mut g = crate::cpu::testgen::Gen(99);
        #[cfg(target_arch = "x86_64")]
        if !is_x86_feature_detected!("avx2") {
            eprintln!("no AVX2 on this CPU: the scalar row is compared with itself");
        }
        for round in 0..4000 {
            let n = round % 41;
            let skip = (g.next() % 3) as usize;
            let src: Vec<[f32; 4]> = (0..n + skip)
                .map(|_| {
                    [(); 4].map(|_| match g.next() % 3 {
                        0 => g.float(),
                        _ => g.mostly_unit(),
                    })
                })
                .collect();
            let rgb = g.next() % 2 == 0;
            let src = &src[skip..];
            let mut got = vec![[7u8; 4]; n + 1];
            unorm8_row(src, &mut got[..n], rgb);
            let want: Vec<[u8; 4]> = src
                .iter()
                .map(|t| unorm8x4([t[0], t[1], t[2], if rgb { 1.0 } else { t[3] }]))
                .collect();
            assert_eq!(got[..n], want[..], "n {n}, rgb {rgb}");
            assert_eq!(got[n], [7; 4], "written past the row");
        }
    }
}
