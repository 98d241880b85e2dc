//! The framebuffer's buffers on the driver: the FBO that stands for the window's framebuffer,
//! `DrawBuffer`/`ReadBuffer` mapped onto its colour attachments, a buffer swap, a resize, and an
//! emulated accumulation buffer (GL 2.1 §4.2.1, §4.2.4, §4.3.2).
//!
//! The backend draws into an FBO, where the driver takes only COLOR_ATTACHMENTi and NONE in
//! DrawBuffer and has no accumulation buffer (llvmpipe's glAccum on an FBO is
//! INVALID_OPERATION: its FBOs have no accumulation attachment, and no EGL config offers one).
//! So the backend stands in for the window system:
//! - colour attachment 0 is the buffer drawing goes to by default (the back buffer of a
//!   double-buffered configuration, the only buffer otherwise) and attachment 1 the front
//!   buffer of a double-buffered one; DrawBuffer and ReadBuffer are validated with the front
//!   end's rules (`crate::buffers`) and sent as DrawBuffers/ReadBuffer of those attachments, so
//!   the driver itself routes drawing, Clear, ReadPixels and CopyTexImage, and PushAttrib and
//!   PopAttrib save and restore them. The enums as given are kept here for the queries;
//! - a swap copies attachment 0 into attachment 1 (glCopyImageSubData: no fragment state
//!   applies), as llvmpipe's software window system presents the back buffer and keeps it;
//! - the accumulation buffer is held here, 16 signed bits a channel: LOAD and ACCUM read the
//!   driver's read buffer with glReadPixels, RETURN writes the driver's draw buffers through a
//!   scratch texture and glCopyImageSubData, and the arithmetic is `crate::cpu::accum`, which
//!   `tests/it/accum.rs` holds to Mesa's own glAccum on llvmpipe (through OSMesa, whose
//!   framebuffer has an accumulation buffer). What the comparison of an accumulating scene
//!   measures is then the driver's rendering of every pass; the accumulation itself is
//!   checked against the driver separately.
//!
//! Display lists: the driver's list cannot hold these calls, so a list that contains one is
//! expanded when it runs (see `lists.rs`).

use glow::HasContext;

use super::{GlBackend, Platform};
use crate::buffers;
use crate::cpu::accum;
use crate::gl;
use crate::state::ContextConfig;
use crate::Error;

/// The FBO standing for a window's framebuffer, and its renderbuffers.
pub(super) struct Fbo {
    pub fbo: glow::Framebuffer,
    /// Colour attachment 0 (the default buffer), attachment 1 (the front buffer, when
    /// double-buffered), and the DEPTH24_STENCIL8 buffer when depth or stencil is configured.
    pub color: Vec<glow::Renderbuffer>,
    pub depth_stencil: Option<glow::Renderbuffer>,
}

impl Fbo {
    /// Creates and binds (to FRAMEBUFFER) a `width` x `height` FBO with the buffers `config`
    /// names.
    ///
    /// # Safety
    ///
    /// The context of `glow` is current on this thread.
    pub unsafe fn new(
        glow: &glow::Context,
        width: u32,
        height: u32,
        config: &ContextConfig,
    ) -> Result<Fbo, Error> {
        let (w, h) = (width as i32, height as i32);
        let fbo = glow.create_framebuffer().map_err(Error::Backend)?;
        glow.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let mut color = Vec::new();
        for k in 0..if config.double_buffered { 2 } else { 1 } {
            let rb = glow.create_renderbuffer().map_err(Error::Backend)?;
            glow.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            // RGB8 for a framebuffer without alpha bits: the driver then drops alpha writes
            // and reads the destination alpha as 1 itself (ALPHA_BITS 0).
            let format = if config.alpha {
                glow::RGBA8
            } else {
                glow::RGB8
            };
            glow.renderbuffer_storage(glow::RENDERBUFFER, format, w, h);
            glow.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k,
                glow::RENDERBUFFER,
                Some(rb),
            );
            color.push(rb);
        }
        let depth_stencil = if config.depth || config.stencil {
            let rb = glow.create_renderbuffer().map_err(Error::Backend)?;
            glow.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            glow.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH24_STENCIL8, w, h);
            // Attached where the configuration has a buffer: DEPTH_BITS or STENCIL_BITS is 0
            // for the other, and its test passes, as with a window without it.
            let points = [
                (config.depth, glow::DEPTH_ATTACHMENT),
                (config.stencil, glow::STENCIL_ATTACHMENT),
            ];
            for (on, point) in points {
                if on {
                    glow.framebuffer_renderbuffer(
                        glow::FRAMEBUFFER,
                        point,
                        glow::RENDERBUFFER,
                        Some(rb),
                    );
                }
            }
            Some(rb)
        } else {
            None
        };
        glow.bind_renderbuffer(glow::RENDERBUFFER, None);
        let status = glow.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(Error::Backend(format!(
                "the framebuffer for {config:?} is incomplete (status {status:#x})"
            )));
        }
        Ok(Fbo {
            fbo,
            color,
            depth_stencil,
        })
    }

    /// Deletes the FBO and its renderbuffers.
    ///
    /// # Safety
    ///
    /// The context of `glow` is current on this thread and the FBO is its.
    pub unsafe fn delete(&self, glow: &glow::Context) {
        glow.delete_framebuffer(self.fbo);
        for rb in self.color.iter().chain(&self.depth_stencil) {
            glow.delete_renderbuffer(*rb);
        }
    }
}

/// A renderbuffer's name where glow's glCopyImageSubData takes object names as textures (the
/// call takes either kind, told apart by the target argument).
fn as_name(rb: glow::Renderbuffer) -> glow::Texture {
    glow::NativeTexture(rb.0)
}

/// The colour attachments standing for the buffers DrawBuffer(`buf`) names (validated) on a
/// framebuffer of `config`: attachment 0 the default buffer, 1 the front of a double-buffered
/// one.
fn draw_attachments(buf: u32, config: &ContextConfig) -> Vec<u32> {
    let m = buffers::mask(buf).unwrap_or(0);
    let (front, back) = (m & buffers::FRONT_LEFT != 0, m & buffers::BACK_LEFT != 0);
    let (main, second) = match config.double_buffered {
        true => (back, front),
        false => (front, false),
    };
    let mut out = Vec::new();
    if main {
        out.push(glow::COLOR_ATTACHMENT0);
    }
    if second {
        out.push(glow::COLOR_ATTACHMENT1);
    }
    if out.is_empty() {
        out.push(glow::NONE);
    }
    out
}

/// The colour attachment standing for ReadBuffer(`buf`) (validated).
fn read_attachment(buf: u32, config: &ContextConfig) -> u32 {
    let m = buffers::read_mask(buf).unwrap_or(0);
    if config.double_buffered && m & buffers::BACK_LEFT == 0 {
        glow::COLOR_ATTACHMENT1
    } else {
        glow::COLOR_ATTACHMENT0
    }
}

/// Pack or unpack modes and the values that read or write a tight RGBA8 block from its first
/// byte.
const PACK_RESET: [(u32, i32); 5] = [
    (glow::PACK_ALIGNMENT, 1),
    (glow::PACK_ROW_LENGTH, 0),
    (glow::PACK_SKIP_ROWS, 0),
    (glow::PACK_SKIP_PIXELS, 0),
    (glow::PACK_SWAP_BYTES, 0),
];
const UNPACK_RESET: [(u32, i32); 5] = [
    (glow::UNPACK_ALIGNMENT, 1),
    (glow::UNPACK_ROW_LENGTH, 0),
    (glow::UNPACK_SKIP_ROWS, 0),
    (glow::UNPACK_SKIP_PIXELS, 0),
    (glow::UNPACK_SWAP_BYTES, 0),
];

impl GlBackend {
    /// The driver's DrawBuffers for the current DRAW_BUFFER.
    fn apply_draw_buffer(&self) {
        // SAFETY: context current (the caller's `execute` made it so); no pointers kept.
        unsafe {
            match self.fb {
                Some(_) => {
                    let atts = draw_attachments(self.draw_buffer, &self.config);
                    self.glow.draw_buffers(&atts);
                }
                // OSMesa: the window's own buffers.
                None => self.raw.DrawBuffer(self.draw_buffer),
            }
        }
    }

    /// The driver's ReadBuffer for the current READ_BUFFER.
    fn apply_read_buffer(&self) {
        let b = match self.fb {
            Some(_) => read_attachment(self.read_buffer, &self.config),
            None => self.read_buffer,
        };
        // SAFETY: context current; no pointers.
        unsafe { self.glow.read_buffer(b) };
    }

    /// `DrawBuffer`: validated as the front end validates it, then sent as the attachments
    /// standing for the buffers it names.
    pub(super) fn draw_buffer(&mut self, buf: u32) {
        // lists: the driver's list cannot hold it; its effect and errors come when it runs.
        self.list_needs_expansion();
        if self.compile_only() {
            return;
        }
        // A framebuffer object of the program's bound: its own buffer, sent as given.
        if self.user_fbos.bound_fb != 0 {
            if let Some(e) = buffers::fbo_draw_error(buf) {
                return self.raise(e);
            }
            // SAFETY: context current; no pointers.
            return unsafe { self.raw.DrawBuffer(buf) };
        }
        if let Some(e) = buffers::draw_error(buf, &self.config) {
            return self.raise(e);
        }
        self.draw_buffer = buf;
        self.apply_draw_buffer();
    }

    /// `ReadBuffer`: as [`GlBackend::draw_buffer`].
    pub(super) fn read_buffer(&mut self, buf: u32) {
        self.list_needs_expansion();
        if self.compile_only() {
            return;
        }
        if self.user_fbos.bound_fb != 0 {
            if let Some(e) = buffers::fbo_read_error(buf) {
                return self.raise(e);
            }
            // SAFETY: context current; no pointers.
            return unsafe { self.raw.ReadBuffer(buf) };
        }
        if let Some(e) = buffers::read_error(buf, &self.config) {
            return self.raise(e);
        }
        self.read_buffer = buf;
        self.apply_read_buffer();
    }

    /// What a value of DRAW_BUFFER, READ_BUFFER, DOUBLEBUFFER or ACCUM_*_BITS is for the
    /// framebuffer this backend stands in for (the driver answers for its FBO), and
    /// SELECTION_BUFFER_SIZE and FEEDBACK_BUFFER_SIZE as given.
    pub(super) fn winsys_value(&self, pname: u32) -> Option<f64> {
        let c = &self.config;
        if let Some(v) = self.fbo_binding_value(pname) {
            return Some(v);
        }
        if self.user_fbos.bound_fb != 0 && matches!(pname, gl::DRAW_BUFFER | gl::READ_BUFFER) {
            return None; // the program's framebuffer object: the driver's own answer
        }
        Some(match pname {
            gl::DRAW_BUFFER => f64::from(self.draw_buffer),
            gl::READ_BUFFER => f64::from(self.read_buffer),
            gl::DOUBLEBUFFER => f64::from(u8::from(c.double_buffered)),
            // The sizes given, where the driver got room for at least one value (select.rs).
            gl::SELECTION_BUFFER_SIZE | gl::FEEDBACK_BUFFER_SIZE => {
                self.given_buffer_size(pname)? as f64
            }
            gl::ACCUM_RED_BITS
            | gl::ACCUM_GREEN_BITS
            | gl::ACCUM_BLUE_BITS
            | gl::ACCUM_ALPHA_BITS => {
                if c.accum {
                    16.0
                } else {
                    0.0
                }
            }
            _ => return None,
        })
    }

    /// The buffers this backend's framebuffer has.
    pub fn config(&self) -> ContextConfig {
        self.config
    }

    /// The counterpart of `Context::swap_buffers`: the back buffer (attachment 0) is copied to
    /// the front buffer (attachment 1) and kept. Nothing when single-buffered, inside
    /// Begin/End, or while a list is compiled (the call is never compiled).
    pub(super) fn swap_buffers(&mut self) {
        if self.inside_begin_end || !self.config.double_buffered {
            return;
        }
        let Some(fb) = &self.fb else {
            return;
        };
        if let [back, front] = fb.color[..] {
            let (w, h) = (self.width as i32, self.height as i32);
            // SAFETY: context current; both renderbuffers are this backend's, of w x h.
            unsafe {
                self.glow.copy_image_sub_data(
                    as_name(back),
                    glow::RENDERBUFFER,
                    0,
                    0,
                    0,
                    0,
                    as_name(front),
                    glow::RENDERBUFFER,
                    0,
                    0,
                    0,
                    0,
                    w,
                    h,
                    1,
                )
            };
        }
    }

    /// The counterpart of `Context::resize`: every buffer becomes `width` x `height`, keeping
    /// what fits from the lower-left corner (the rest: colour 0, depth 1, stencil 0); the
    /// viewport and scissor box are not changed. Errors as `Context::resize`.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), Error> {
        let max = crate::state::MAX_VIEWPORT_DIM;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::InvalidSize { width, height });
        }
        self.make_current();
        if let Platform::OsMesa(ctx, _) = &mut self.platform {
            if !ctx.resize(width, height) {
                return Err(Error::OutOfMemory { width, height });
            }
            self.width = width;
            self.height = height;
            return Ok(());
        }
        let Some(old) = self.fb.take() else {
            return Ok(());
        };
        // SAFETY: context current; every object used is this backend's.
        unsafe {
            let fresh = match Fbo::new(&self.glow, width, height, &self.config) {
                Ok(f) => f,
                Err(e) => {
                    self.glow.bind_framebuffer(glow::FRAMEBUFFER, Some(old.fbo));
                    self.fb = Some(old);
                    return Err(e);
                }
            };
            let (w, h) = (width.min(self.width) as i32, height.min(self.height) as i32);
            // The new buffers start as a new framebuffer's (colour 0, depth 1, stencil 0): a
            // driver Clear with the state it depends on (scissor, masks, clear values, draw
            // buffers) set for it and restored after.
            let scissor = self.raw.IsEnabled(gl::SCISSOR_TEST);
            let mut cmask = [0u8; 4];
            self.raw
                .GetBooleanv(gl::COLOR_WRITEMASK, cmask.as_mut_ptr());
            let mut dmask = 0u8;
            self.raw.GetBooleanv(gl::DEPTH_WRITEMASK, &mut dmask);
            let (mut sfront, mut sback) = (0i32, 0i32);
            self.raw.GetIntegerv(gl::STENCIL_WRITEMASK, &mut sfront);
            self.raw.GetIntegerv(gl::STENCIL_BACK_WRITEMASK, &mut sback);
            let mut ccol = [0f32; 4];
            self.raw.GetFloatv(gl::COLOR_CLEAR_VALUE, ccol.as_mut_ptr());
            let mut cdepth = 0f64;
            self.raw.GetDoublev(gl::DEPTH_CLEAR_VALUE, &mut cdepth);
            let mut cstencil = 0i32;
            self.raw.GetIntegerv(gl::STENCIL_CLEAR_VALUE, &mut cstencil);
            self.raw.Disable(gl::SCISSOR_TEST);
            self.raw.ColorMask(1, 1, 1, 1);
            self.raw.DepthMask(1);
            self.raw.StencilMask(0xFF);
            self.raw.ClearColor(0.0, 0.0, 0.0, 0.0);
            self.raw.ClearDepth(1.0);
            self.raw.ClearStencil(0);
            let all: Vec<u32> = (0..fresh.color.len() as u32)
                .map(|k| glow::COLOR_ATTACHMENT0 + k)
                .collect();
            self.glow.draw_buffers(&all);
            self.raw
                .Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
            if scissor != 0 {
                self.raw.Enable(gl::SCISSOR_TEST);
            }
            self.raw.ColorMask(cmask[0], cmask[1], cmask[2], cmask[3]);
            self.raw.DepthMask(dmask);
            self.raw.StencilMaskSeparate(gl::FRONT, sfront as u32);
            self.raw.StencilMaskSeparate(gl::BACK, sback as u32);
            self.raw.ClearColor(ccol[0], ccol[1], ccol[2], ccol[3]);
            self.raw.ClearDepth(cdepth);
            self.raw.ClearStencil(cstencil);
            let pairs = old
                .color
                .iter()
                .zip(&fresh.color)
                .chain(old.depth_stencil.iter().zip(&fresh.depth_stencil));
            for (old, new) in pairs {
                self.glow.copy_image_sub_data(
                    as_name(*old),
                    glow::RENDERBUFFER,
                    0,
                    0,
                    0,
                    0,
                    as_name(*new),
                    glow::RENDERBUFFER,
                    0,
                    0,
                    0,
                    0,
                    w,
                    h,
                    1,
                );
            }
            old.delete(&self.glow);
            self.fb = Some(fresh);
            self.width = width;
            self.height = height;
            // The new FBO is bound; its draw and read buffers are the ones in effect.
            self.apply_draw_buffer();
            self.apply_read_buffer();
            while self.glow.get_error() != glow::NO_ERROR {}
        }
        if let Some(acc) = self.accum.as_mut() {
            let mut fresh = vec![[0i16; 4]; width as usize * height as usize];
            let (ow, oh) = (self.accum_size.0 as usize, self.accum_size.1 as usize);
            for y in 0..oh.min(height as usize) {
                for x in 0..ow.min(width as usize) {
                    if let (Some(d), Some(s)) =
                        (fresh.get_mut(y * width as usize + x), acc.get(y * ow + x))
                    {
                        *d = *s;
                    }
                }
            }
            *acc = fresh;
            self.accum_size = (width, height);
        }
        Ok(())
    }

    /// `Clear`: the driver clears colour, depth and stencil; ACCUM_BUFFER_BIT clears the
    /// emulated accumulation buffer inside the scissor box, in RENDER mode, after the driver
    /// accepted the mask.
    pub(super) fn clear(&mut self, mask: u32) {
        if self.compile_only() {
            if mask & gl::ACCUM_BUFFER_BIT != 0 {
                self.list_needs_expansion();
            }
            // SAFETY: context current; no pointers.
            return unsafe { self.raw.Clear(mask) };
        }
        if mask & gl::ACCUM_BUFFER_BIT != 0 {
            self.list_needs_expansion();
        }
        // SAFETY: as above.
        unsafe { self.raw.Clear(mask) };
        let valid = mask
            & !(gl::COLOR_BUFFER_BIT
                | gl::DEPTH_BUFFER_BIT
                | gl::STENCIL_BUFFER_BIT
                | gl::ACCUM_BUFFER_BIT)
            == 0;
        if mask & gl::ACCUM_BUFFER_BIT == 0
            || !valid
            || self.accum.is_none()
            || self.inside_begin_end
            || self.current_render_mode() != gl::RENDER
        {
            return;
        }
        let mut c = [0.0f32; 4];
        // SAFETY: ACCUM_CLEAR_VALUE is 4 floats.
        unsafe { self.raw.GetFloatv(gl::ACCUM_CLEAR_VALUE, c.as_mut_ptr()) };
        let value = c.map(accum::clear_value);
        let [x0, y0, x1, y1] = self.scissor_rect();
        let w = self.accum_size.0 as usize;
        if let Some(acc) = self.accum.as_mut() {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    if let Some(a) = acc.get_mut(y as usize * w + x as usize) {
                        *a = value;
                    }
                }
            }
        }
    }

    /// The window cut by the scissor box as the driver holds it, inclusive `[x0, y0, x1, y1]`
    /// (empty when x0 > x1 or y0 > y1).
    fn scissor_rect(&self) -> [i32; 4] {
        let (w, h) = (self.width as i32, self.height as i32);
        let mut r = [0, 0, w - 1, h - 1];
        // SAFETY: SCISSOR_BOX is 4 integers; no other pointers.
        unsafe {
            if self.raw.IsEnabled(gl::SCISSOR_TEST) != 0 {
                let mut b = [0i32; 4];
                self.raw.GetIntegerv(gl::SCISSOR_BOX, b.as_mut_ptr());
                r[0] = r[0].max(b[0]);
                r[1] = r[1].max(b[1]);
                r[2] = r[2].min(b[0].saturating_add(b[2]).saturating_sub(1));
                r[3] = r[3].min(b[1].saturating_add(b[3]).saturating_sub(1));
            }
        }
        r
    }

    /// Reads the RGBA8 pixels of the rectangle `r` (inclusive, inside the window) of colour
    /// attachment `att`, bottom-up rows.
    fn read_rect(&self, att: u32, r: [i32; 4]) -> Vec<u8> {
        let (w, h) = ((r[2] - r[0] + 1) as usize, (r[3] - r[1] + 1) as usize);
        let mut px = vec![0u8; w * h * 4];
        // SAFETY: context current; `px` holds w x h RGBA8 pixels read with the pack modes
        // reset (alignment 1, no row length, no skips, no swap) and no pack buffer bound by
        // fixedgl; the modes and the read buffer are restored.
        unsafe {
            let saved = PACK_RESET.map(|(p, _)| self.glow.get_parameter_i32(p));
            for (p, v) in PACK_RESET {
                self.glow.pixel_store_i32(p, v);
            }
            self.glow.read_buffer(att);
            self.glow.read_pixels(
                r[0],
                r[1],
                w as i32,
                h as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut px)),
            );
            self.apply_read_buffer();
            for ((p, _), v) in PACK_RESET.iter().zip(saved) {
                self.glow.pixel_store_i32(*p, v);
            }
        }
        px
    }

    /// `glReadPixels(x, y, width, height, RGBA, UNSIGNED_BYTE)` from the buffer READ_BUFFER
    /// names (through the driver, as the recorded calls left it), with the pack modes at their
    /// initial values but alignment 1 (restored after): `width * height * 4` bytes, rows
    /// bottom-up. Pixels outside the window are zero. Negative sizes read nothing.
    pub fn read_rgba(&mut self, x: i32, y: i32, width: i32, height: i32) -> Vec<u8> {
        self.make_current();
        let (w, h) = (width.max(0) as usize, height.max(0) as usize);
        let mut px = vec![0u8; w * h * 4];
        if px.is_empty() {
            return px;
        }
        // SAFETY: context current; `px` holds w x h RGBA8 pixels read with the pack modes reset
        // (restored after) and no pack buffer bound by fixedgl.
        unsafe {
            let saved = PACK_RESET.map(|(p, _)| self.glow.get_parameter_i32(p));
            for (p, v) in PACK_RESET {
                self.glow.pixel_store_i32(p, v);
            }
            self.glow.read_pixels(
                x,
                y,
                w as i32,
                h as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut px)),
            );
            for ((p, _), v) in PACK_RESET.iter().zip(saved) {
                self.glow.pixel_store_i32(*p, v);
            }
        }
        px
    }

    /// The counterpart of `Context::front_rgba`: the front buffer (the only one when
    /// single-buffered) as RGBA8 bytes, top row first.
    pub fn front_rgba(&mut self) -> Vec<u8> {
        self.make_current();
        let r = [0, 0, self.width as i32 - 1, self.height as i32 - 1];
        let att = match (&self.fb, self.config.double_buffered) {
            (Some(_), true) => glow::COLOR_ATTACHMENT1,
            (Some(_), false) => glow::COLOR_ATTACHMENT0,
            (None, _) => glow::FRONT,
        };
        let up = self.read_rect(att, r);
        let row = self.width as usize * 4;
        up.chunks_exact(row.max(1))
            .rev()
            .flatten()
            .copied()
            .collect()
    }

    /// Writes RGBA8 pixels (bottom-up rows) into the rectangle `r` (inclusive) of colour
    /// attachment `k`, bypassing every fragment operation (glCopyImageSubData from a scratch
    /// texture created and deleted here, without binding it).
    fn write_rect(&self, k: usize, r: [i32; 4], px: &[u8]) {
        let Some(rb) = self.fb.as_ref().and_then(|f| f.color.get(k)) else {
            return;
        };
        let (w, h) = (r[2] - r[0] + 1, r[3] - r[1] + 1);
        // SAFETY: context current; `px` holds w x h RGBA8 pixels, uploaded with the unpack
        // modes reset (restored after) and no unpack buffer bound by fixedgl; the texture is
        // created by DSA, never bound, and deleted.
        unsafe {
            let Ok(tex) = self.glow.create_named_texture(glow::TEXTURE_2D) else {
                return;
            };
            self.glow.texture_storage_2d(tex, 1, glow::RGBA8, w, h);
            let saved = UNPACK_RESET.map(|(p, _)| self.glow.get_parameter_i32(p));
            for (p, v) in UNPACK_RESET {
                self.glow.pixel_store_i32(p, v);
            }
            self.glow.texture_sub_image_2d(
                tex,
                0,
                0,
                0,
                w,
                h,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelUnpackData::Slice(Some(px)),
            );
            for ((p, _), v) in UNPACK_RESET.iter().zip(saved) {
                self.glow.pixel_store_i32(*p, v);
            }
            self.glow.copy_image_sub_data(
                tex,
                glow::TEXTURE_2D,
                0,
                0,
                0,
                0,
                as_name(*rb),
                glow::RENDERBUFFER,
                0,
                r[0],
                r[1],
                0,
                w,
                h,
                1,
            );
            self.glow.delete_texture(tex);
        }
    }

    /// `Accum`: the driver validates (INVALID_ENUM for a bad op, then INVALID_OPERATION since
    /// its FBO has no accumulation buffer); the backend raises the same errors itself and, with
    /// an accumulation buffer configured, does the operation on its own buffer.
    pub(super) fn accum(&mut self, op: u32, value: f32) {
        self.list_needs_expansion();
        if self.compile_only() {
            return;
        }
        if self.fb.is_none() {
            // OSMesa: the driver's own accumulation buffer.
            // SAFETY: context current; no pointers.
            return unsafe { self.raw.Accum(op, value) };
        }
        if !matches!(op, gl::ACCUM | gl::LOAD | gl::RETURN | gl::MULT | gl::ADD) {
            return self.raise(gl::INVALID_ENUM);
        }
        if self.accum.is_none() {
            return self.raise(gl::INVALID_OPERATION);
        }
        if self.current_render_mode() != gl::RENDER {
            return;
        }
        let r = self.scissor_rect();
        if r[0] > r[2] || r[1] > r[3] {
            return;
        }
        let (rw, rh) = ((r[2] - r[0] + 1) as usize, (r[3] - r[1] + 1) as usize);
        let w = self.accum_size.0 as usize;
        let at = |i: usize, j: usize| (r[1] as usize + j) * w + r[0] as usize + i;
        if op == gl::RETURN {
            let mut mask = [0u8; 4];
            // SAFETY: COLOR_WRITEMASK is 4 booleans.
            unsafe { self.raw.GetBooleanv(gl::COLOR_WRITEMASK, mask.as_mut_ptr()) };
            let atts = draw_attachments(self.draw_buffer, &self.config);
            for att in atts.into_iter().filter(|&a| a != glow::NONE) {
                let k = (att - glow::COLOR_ATTACHMENT0) as usize;
                // Masked channels keep the buffer's own values.
                let mut px = if mask.contains(&0) {
                    self.read_rect(att, r)
                } else {
                    vec![0u8; rw * rh * 4]
                };
                if let Some(acc) = self.accum.as_ref() {
                    let mask = mask.map(|m| m != 0);
                    for (j, row) in px.chunks_exact_mut(rw * 4).enumerate() {
                        if let Some(a) = acc.get(at(0, j)..at(rw, j)) {
                            accum::return_run(value, a, row, mask);
                        }
                    }
                }
                self.write_rect(k, r, &px);
            }
            return;
        }
        let px = if accum::reads_color(op) {
            self.read_rect(read_attachment(self.read_buffer, &self.config), r)
        } else {
            Vec::new()
        };
        if let Some(acc) = self.accum.as_mut() {
            for j in 0..rh {
                // The row's colour bytes (none for ADD and MULT, which read no colour).
                let row = px.get(j * rw * 4..(j + 1) * rw * 4).unwrap_or(&[]);
                if let Some(a) = acc.get_mut(at(0, j)..at(rw, j)) {
                    accum::apply_run(op, value, a, row);
                }
            }
        }
    }
}
