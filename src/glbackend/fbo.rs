//! Framebuffer objects on the driver (GL_EXT_framebuffer_object under the GL 3.0 names;
//! context/fbo.rs is the front end).
//!
//! The backend itself draws into an FBO that stands for the window (buffers.rs), so the
//! program's framebuffer 0 is that FBO, and the program's object and renderbuffer names are
//! mapped to driver objects made at their first binding (the front end's names would collide
//! with the backend's own). A name the program never bound goes to the driver as a name no
//! object has, so the driver raises the error a missing object gets. Where fixedgl's GL 1.5
//! rules are narrower than Mesa's (one colour attachment; the FRAMEBUFFER target only; the
//! renderbuffer formats of EXT_framebuffer_object; nothing attached to the window), the front
//! end's error is raised here before the driver sees the call.

use glow::HasContext;
use std::collections::HashMap;

use super::GlBackend;
use crate::gl;

/// A driver name no object has: what a program's name that was never bound maps to.
const NO_OBJECT: u32 = 0xFFFF_FF00;

/// The program's framebuffer and renderbuffer objects on the driver.
#[derive(Debug, Default)]
pub(super) struct UserFbos {
    framebuffers: HashMap<u32, glow::Framebuffer>,
    renderbuffers: HashMap<u32, glow::Renderbuffer>,
    /// The program's FRAMEBUFFER_BINDING and RENDERBUFFER_BINDING.
    pub(super) bound_fb: u32,
    pub(super) bound_rb: u32,
}

impl GlBackend {
    /// The driver framebuffer standing for the program's framebuffer 0 (`None`: OSMesa's own).
    fn window_framebuffer(&self) -> Option<glow::Framebuffer> {
        self.fb.as_ref().map(|f| f.fbo)
    }

    /// A recorded `GenFramebuffers` / `GenRenderbuffers`: the front end's INVALID_VALUE;
    /// nothing is sent (the objects are made at their first binding).
    pub(super) fn gen_framebuffers(&mut self, n: i32, names: &[u32]) {
        match usize::try_from(n) {
            Ok(n) if n <= names.len() => {}
            _ => self.raise(gl::INVALID_VALUE),
        }
    }

    /// See [`GlBackend::gen_framebuffers`].
    pub(super) fn gen_renderbuffers(&mut self, n: i32, names: &[u32]) {
        self.gen_framebuffers(n, names);
    }

    /// `BindFramebuffer`: 0 binds the FBO standing for the window; another name its driver
    /// object (made now the first time).
    pub(super) fn bind_framebuffer(&mut self, target: u32, id: u32) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        if target != gl::FRAMEBUFFER {
            return self.raise(gl::INVALID_ENUM);
        }
        let fb = if id == 0 {
            self.window_framebuffer()
        } else if let Some(&fb) = self.user_fbos.framebuffers.get(&id) {
            Some(fb)
        } else {
            // SAFETY: the context is current (see `execute`).
            match unsafe { self.glow.create_framebuffer() } {
                Ok(fb) => {
                    self.user_fbos.framebuffers.insert(id, fb);
                    Some(fb)
                }
                Err(_) => return self.raise(gl::OUT_OF_MEMORY),
            }
        };
        self.user_fbos.bound_fb = id;
        // SAFETY: context current; a framebuffer this backend made.
        unsafe { self.glow.bind_framebuffer(glow::FRAMEBUFFER, fb) };
    }

    /// `BindRenderbuffer`: as [`GlBackend::bind_framebuffer`], 0 unbinding.
    pub(super) fn bind_renderbuffer(&mut self, target: u32, id: u32) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        if target != gl::RENDERBUFFER {
            return self.raise(gl::INVALID_ENUM);
        }
        let rb = if id == 0 {
            None
        } else if let Some(&rb) = self.user_fbos.renderbuffers.get(&id) {
            Some(rb)
        } else {
            // SAFETY: the context is current.
            match unsafe { self.glow.create_renderbuffer() } {
                Ok(rb) => {
                    self.user_fbos.renderbuffers.insert(id, rb);
                    Some(rb)
                }
                Err(_) => return self.raise(gl::OUT_OF_MEMORY),
            }
        };
        self.user_fbos.bound_rb = id;
        // SAFETY: context current; a renderbuffer this backend made.
        unsafe { self.glow.bind_renderbuffer(glow::RENDERBUFFER, rb) };
    }

    /// `DeleteFramebuffers`: the driver objects of the names; deleting the bound one binds the
    /// window's FBO (the driver would bind its own framebuffer 0).
    pub(super) fn delete_framebuffers(&mut self, n: i32, names: &[u32]) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| names.get(..n)) else {
            return self.raise(gl::INVALID_VALUE);
        };
        for &id in names {
            if let Some(fb) = self.user_fbos.framebuffers.remove(&id) {
                // SAFETY: context current; an object this backend made, deleted once.
                unsafe { self.glow.delete_framebuffer(fb) };
                if self.user_fbos.bound_fb == id {
                    self.user_fbos.bound_fb = 0;
                    let window = self.window_framebuffer();
                    // SAFETY: context current.
                    unsafe { self.glow.bind_framebuffer(glow::FRAMEBUFFER, window) };
                }
            }
        }
    }

    /// `DeleteRenderbuffers`: the driver objects of the names (the driver detaches them from
    /// its bound framebuffer).
    pub(super) fn delete_renderbuffers(&mut self, n: i32, names: &[u32]) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| names.get(..n)) else {
            return self.raise(gl::INVALID_VALUE);
        };
        for &id in names {
            if let Some(rb) = self.user_fbos.renderbuffers.remove(&id) {
                if self.user_fbos.bound_rb == id {
                    self.user_fbos.bound_rb = 0;
                }
                // SAFETY: context current; an object this backend made, deleted once.
                unsafe { self.glow.delete_renderbuffer(rb) };
            }
        }
    }

    /// `RenderbufferStorage`: an internal format EXT_framebuffer_object does not name is the
    /// front end's INVALID_ENUM (Mesa takes more); the rest is the driver's.
    pub(super) fn renderbuffer_storage(&mut self, target: u32, format: u32, w: i32, h: i32) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        if target == gl::RENDERBUFFER && crate::context::renderbuffer_base(format).is_none() {
            return self.raise(gl::INVALID_ENUM);
        }
        // SAFETY: context current; no pointers.
        unsafe { self.glow.renderbuffer_storage(target, format, w, h) };
    }

    /// The checks of an attachment command fixedgl makes before the driver (see the module
    /// docs): false when it raised one.
    fn attachment_checks(&mut self, target: u32, attachment: u32) -> bool {
        if self.inside_begin_end {
            self.raise(gl::INVALID_OPERATION);
            return false;
        }
        if target != gl::FRAMEBUFFER {
            self.raise(gl::INVALID_ENUM);
            return false;
        }
        if crate::buffers::is_color_attachment(attachment) && attachment != gl::COLOR_ATTACHMENT0 {
            self.raise(gl::INVALID_OPERATION);
            return false;
        }
        if !matches!(
            attachment,
            gl::COLOR_ATTACHMENT0 | gl::DEPTH_ATTACHMENT | gl::STENCIL_ATTACHMENT
        ) {
            self.raise(gl::INVALID_ENUM);
            return false;
        }
        if self.user_fbos.bound_fb == 0 {
            self.raise(gl::INVALID_OPERATION);
            return false;
        }
        true
    }

    /// `FramebufferTexture1D`.
    pub(super) fn framebuffer_texture_1d(&mut self, t: u32, a: u32, tt: u32, tex: u32, l: i32) {
        if self.attachment_checks(t, a) {
            // SAFETY: context current; no pointers.
            unsafe { self.raw.FramebufferTexture1D(t, a, tt, tex, l) };
        }
    }

    /// `FramebufferTexture2D`.
    pub(super) fn framebuffer_texture_2d(&mut self, t: u32, a: u32, tt: u32, tex: u32, l: i32) {
        if self.attachment_checks(t, a) {
            // SAFETY: context current; no pointers.
            unsafe { self.raw.FramebufferTexture2D(t, a, tt, tex, l) };
        }
    }

    /// `FramebufferTexture3D`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn framebuffer_texture_3d(
        &mut self,
        t: u32,
        a: u32,
        tt: u32,
        tex: u32,
        l: i32,
        z: i32,
    ) {
        if self.attachment_checks(t, a) {
            // SAFETY: context current; no pointers.
            unsafe { self.raw.FramebufferTexture3D(t, a, tt, tex, l, z) };
        }
    }

    /// `FramebufferRenderbuffer`: the program's renderbuffer name mapped to the driver's.
    pub(super) fn framebuffer_renderbuffer(&mut self, t: u32, a: u32, rt: u32, id: u32) {
        if !self.attachment_checks(t, a) {
            return;
        }
        let rb = match id {
            0 => 0,
            _ => self
                .user_fbos
                .renderbuffers
                .get(&id)
                .map_or(NO_OBJECT, |rb| rb.0.get()),
        };
        // SAFETY: context current; no pointers.
        unsafe { self.raw.FramebufferRenderbuffer(t, a, rt, rb) };
    }

    /// `GenerateMipmap`: a target GL 1.5 lacks (the array targets Mesa takes) is the front
    /// end's INVALID_ENUM.
    pub(super) fn generate_mipmap(&mut self, target: u32) {
        if self.inside_begin_end {
            return self.raise(gl::INVALID_OPERATION);
        }
        if !matches!(
            target,
            gl::TEXTURE_1D | gl::TEXTURE_2D | gl::TEXTURE_3D | gl::TEXTURE_CUBE_MAP
        ) {
            return self.raise(gl::INVALID_ENUM);
        }
        // SAFETY: context current; no pointers.
        unsafe { self.glow.generate_mipmap(target) };
    }

    /// The program's FRAMEBUFFER_BINDING and RENDERBUFFER_BINDING (the driver's are the
    /// backend's own objects).
    pub(super) fn fbo_binding_value(&self, pname: u32) -> Option<f64> {
        match pname {
            gl::FRAMEBUFFER_BINDING => Some(f64::from(self.user_fbos.bound_fb)),
            gl::RENDERBUFFER_BINDING => Some(f64::from(self.user_fbos.bound_rb)),
            _ => None,
        }
    }

    /// `CheckFramebufferStatus` on the driver (FRAMEBUFFER_COMPLETE for the window). Not a
    /// recorded call: for tests.
    pub fn check_framebuffer_status(&mut self, target: u32) -> u32 {
        self.make_current();
        if target != gl::FRAMEBUFFER {
            self.raise(gl::INVALID_ENUM);
            return 0;
        }
        if self.user_fbos.bound_fb == 0 {
            return gl::FRAMEBUFFER_COMPLETE;
        }
        // SAFETY: context current.
        unsafe { self.glow.check_framebuffer_status(target) }
    }

    /// `GetFramebufferAttachmentParameteriv` on the driver, the object name mapped back to the
    /// program's. Not a recorded call: for tests.
    pub fn get_framebuffer_attachment_parameteriv(
        &mut self,
        target: u32,
        attachment: u32,
        pname: u32,
        out: &mut [i32],
    ) {
        self.make_current();
        if !self.attachment_checks(target, attachment) {
            return;
        }
        let Some(first) = out.first_mut() else {
            return self.raise(gl::INVALID_VALUE);
        };
        // SAFETY: context current; one value written.
        let v = unsafe {
            self.glow
                .get_framebuffer_attachment_parameter_i32(target, attachment, pname)
        };
        *first = v;
        if pname == gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME {
            // SAFETY: context current.
            let ty = unsafe {
                self.glow.get_framebuffer_attachment_parameter_i32(
                    target,
                    attachment,
                    gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                )
            } as u32;
            if ty == gl::RENDERBUFFER {
                let found = self
                    .user_fbos
                    .renderbuffers
                    .iter()
                    .find(|(_, rb)| rb.0.get() == v as u32);
                *first = found.map_or(v, |(&id, _)| id as i32);
            }
        }
    }
}
