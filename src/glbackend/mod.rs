//! The real-GL backend: replays a recorded [`Call`] stream on a driver's own fixed-function
//! pipeline (a GL 2.1+ compatibility-profile context on an EGL device, no window), renders into
//! an FBO (RGBA8 colour, DEPTH24_STENCIL8) and reads the pixels back for [`crate::compare`].
//!
//! Every `Call` variant is the GL function of the same name with the same arguments (GL 2.1
//! §2.5's command set), so the replay in `replay.rs` is one exhaustive match, one driver call per
//! arm. Entry points come from bindings generated at build time (gl_generator, `build.rs`) and
//! loaded through EGL's `get_proc_address`; glow serves the modern parts (FBO, GLSL, read-back).
//!
//! Design decision: the backend never lets a caller's bad slice reach the driver. Where the CPU
//! front end records INVALID_VALUE for a slice shorter than its pname needs, the backend records
//! the same error in its own sticky flag instead of calling the driver, and merges that flag with
//! the driver's so that [`GlBackend::get_error`] answers exactly as one GL error flag would
//! (GL 2.1 §2.5: the first error sticks until read). `PHONG_WIN`, which no driver implements, is
//! emulated by a GLSL program (`phong.rs`).

mod buffers;
mod egl;
mod eval;
mod fbo;
mod generated;
mod lists;
mod osmesa;
mod phong;
pub mod raw;
mod replay;
mod select;
// Vertex arrays and buffer objects on the driver
mod arrays;
mod query;
mod stipple;
mod texture;
// CompressedTexImage*, CompressedTexSubImage*: fixedgl's errors where the driver could differ
mod compressed;
// DrawPixels, Bitmap, PixelMap on the driver
mod pixels;

use std::cell::Cell;
use std::ffi::CString;
use std::marker::PhantomData;
use std::sync::atomic::{AtomicU64, Ordering};

use glow::HasContext;
use image::RgbaImage;

use crate::gl;
use crate::{Call, Error};

pub use egl::{list_devices, DeviceChoice, DeviceInfo, INSTALL_HINT};

thread_local! {
    /// The id of the backend whose context is current on this thread (0: none of ours).
    static CURRENT: Cell<u64> = const { Cell::new(0) };
    /// An OSMesa context was made current on this thread since the last EGL one. EGL (through
    /// libglvnd) does not see OSMesa's switches and skips eglMakeCurrent of the context it
    /// believes current, so that context must be released first.
    static OSMESA_SINCE_EGL: Cell<bool> = const { Cell::new(false) };
}
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// A real GL context replaying recorded calls into an offscreen framebuffer.
///
/// Not `Send`: an EGL context is current on the thread that created it, so each thread (each
/// test) creates its own backend. Several backends on one thread are fine: every method makes
/// its own context current first (a thread-local check, an EGL call only on a switch).
pub struct GlBackend {
    /// Unique per backend, for the `CURRENT` check.
    id: u64,
    raw: raw::Gl,
    glow: glow::Context,
    /// The FBO standing for the window's framebuffer (buffers.rs); `None` on OSMesa, whose
    /// own framebuffer is the window's.
    fb: Option<buffers::Fbo>,
    width: u32,
    height: u32,
    /// The buffers of the framebuffer the backend stands in for.
    config: crate::ContextConfig,
    /// DRAW_BUFFER and READ_BUFFER as given (the driver holds the attachments standing for
    /// them).
    draw_buffer: u32,
    read_buffer: u32,
    /// The emulated accumulation buffer, bottom-up rows of `accum_size` (buffers.rs).
    accum: Option<Vec<[i16; 4]>>,
    accum_size: (u32, u32),
    /// The selection and feedback buffers the driver writes (select.rs).
    select: select::Buffers,
    /// The backend's own sticky error (a slice too short), merged with the driver's flag.
    error: u32,
    /// A Begin is open (mirrors the front end's Begin/End phase, GL 2.1 §2.6.3).
    inside_begin_end: bool,
    /// `ShadeModel(PHONG_WIN)` is in effect (the driver itself is in SMOOTH).
    phong: bool,
    /// A call since the last Begin may have changed what the Phong program depends on.
    phong_dirty: bool,
    phong_program: Option<phong::PhongProgram>,
    // The mirror of the driver's display lists (lists.rs)
    lists: lists::ListMirror,
    /// Values a `get_*` may write at most (GL 2.1 §6.1.2; COMPRESSED_TEXTURE_FORMATS is the long one).
    max_get_values: usize,
    renderer: String,
    version: String,
    platform: Platform,
    _not_send: PhantomData<*const ()>,
    // The shadow array state; the driver's client pointers point into it.
    arrays: crate::arrays::ArrayState,
    /// The program's framebuffer and renderbuffer objects (fbo.rs).
    user_fbos: fbo::UserFbos,
}

/// How the backend reaches the driver.
#[derive(Debug)]
enum Platform {
    /// An EGL device (surfaceless; the backend draws into its FBO).
    Egl(egl::EglContext),
    /// OSMesa, with its own single-buffered framebuffer (and accumulation buffer).
    OsMesa(osmesa::OsMesaContext, DeviceInfo),
}

impl std::fmt::Debug for GlBackend {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GlBackend")
            .field("size", &(self.width, self.height))
            .field("renderer", &self.renderer)
            .field("version", &self.version)
            .field("device", self.device())
            .finish_non_exhaustive()
    }
}

/// Largest framebuffer side accepted (as [`crate::Context::new`]).
const MAX_SIDE: u32 = crate::state::MAX_VIEWPORT_DIM;

impl GlBackend {
    /// A `width` x `height` offscreen framebuffer on the device `choice` selects, in GL's initial
    /// state, with the viewport and scissor box covering it (as a window of that size would).
    ///
    /// Errors: no libEGL, no EGL device, no compatibility context, an incomplete FBO — each
    /// message says which, and what to install.
    pub fn new(width: u32, height: u32, choice: &DeviceChoice) -> Result<GlBackend, Error> {
        Self::with_config(width, height, choice, crate::ContextConfig::default())
    }

    /// [`GlBackend::new`] standing in for a framebuffer with the buffers `config` names, as
    /// `Context::with_config` makes it: a back buffer (colour attachment 0, with the front one
    /// attachment 1), depth and stencil attachments as configured, and an emulated
    /// accumulation buffer (see `buffers.rs`).
    pub fn with_config(
        width: u32,
        height: u32,
        choice: &DeviceChoice,
        config: crate::ContextConfig,
    ) -> Result<GlBackend, Error> {
        if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
            return Err(Error::InvalidSize { width, height });
        }
        if config.accum && !config.alpha {
            // The emulated accumulation buffer moves RGBA8 images in and out of the colour
            // attachments (glCopyImageSubData), which an RGB8 attachment cannot take.
            return Err(Error::Backend(
                "an accumulation buffer with a colour buffer without alpha is not emulated on EGL"
                    .into(),
            ));
        }
        let egl = egl::create(choice)?;
        // The new context is current now, whatever backend was before (and should this
        // constructor fail below, none of ours is).
        CURRENT.with(|c| c.set(0));
        use glutin::display::GlDisplay;
        let display = egl.display.clone();
        let load = |name: &str| match CString::new(name) {
            Ok(c) => display.get_proc_address(&c),
            Err(_) => std::ptr::null(),
        };
        Self::start(Platform::Egl(egl), &load, width, height, config)
    }

    /// A backend on Mesa's OSMesa (llvmpipe drawing into memory) instead of an EGL device:
    /// the context's own framebuffer is the window's, with the depth, stencil and accumulation
    /// buffers `config` names, so Accum runs Mesa's own accumulation code (an EGL backend
    /// emulates it). OSMesa has no back buffer: a double-buffered `config` is an
    /// `Error::Backend`, as is a machine without libOSMesa (the message says what to install).
    pub fn osmesa(
        width: u32,
        height: u32,
        config: crate::ContextConfig,
    ) -> Result<GlBackend, Error> {
        if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
            return Err(Error::InvalidSize { width, height });
        }
        if config.double_buffered {
            return Err(Error::Backend(
                "OSMesa's framebuffer has no back buffer (a double-buffered config needs EGL)"
                    .into(),
            ));
        }
        if !config.alpha {
            return Err(Error::Backend(
                "the OSMesa backend draws into RGBA (a config without alpha needs EGL)".into(),
            ));
        }
        let bits = |on: bool, n: i32| if on { n } else { 0 };
        let ctx = osmesa::OsMesaContext::new(
            width,
            height,
            bits(config.depth, 24),
            bits(config.stencil, 8),
            bits(config.accum, 16),
        )?;
        CURRENT.with(|c| c.set(0));
        OSMESA_SINCE_EGL.with(|f| f.set(true));
        let info = DeviceInfo {
            index: usize::MAX,
            name: "OSMesa".into(),
            vendor: "Mesa".into(),
            extensions: Vec::new(),
            software: true,
        };
        // A copy of OSMesa's lookup function: the library stays loaded inside the platform.
        let load = ctx.loader();
        let platform = Platform::OsMesa(ctx, info);
        Self::start(platform, &load, width, height, config)
    }

    /// The common part of the constructors: entry points through `load`, the FBO on EGL, the
    /// window's initial state.
    fn start(
        platform: Platform,
        load: &dyn Fn(&str) -> *const std::ffi::c_void,
        width: u32,
        height: u32,
        config: crate::ContextConfig,
    ) -> Result<GlBackend, Error> {
        let device = match &platform {
            Platform::Egl(e) => e.device.to_string(),
            Platform::OsMesa(..) => "OSMesa".to_string(),
        };
        let raw = raw::Gl::load_with(load);
        if !raw.Begin.is_loaded() || !raw.Lightfv.is_loaded() {
            return Err(Error::Backend(format!(
                "the driver on {device} exports no fixed-function entry points (glBegin, glLightfv)"
            )));
        }
        // SAFETY: the context is current on this thread and the loader resolves its entry points.
        let glow = unsafe { glow::Context::from_loader_function(|name| load(name)) };
        let on_fbo = matches!(platform, Platform::Egl(_));
        // SAFETY: context current; sizes validated by the callers; every object is created here.
        let (fb, renderer, version, max_get_values) = unsafe {
            let renderer = glow.get_parameter_string(glow::RENDERER);
            let version = glow.get_parameter_string(glow::VERSION);
            let (w, h) = (width as i32, height as i32);
            let fb = if on_fbo {
                let fb = buffers::Fbo::new(&glow, width, height, &config)
                    .map_err(|e| Error::Backend(format!("{e} on {renderer}")))?;
                // Drawing and reading start on the default buffer (attachment 0), as
                // DRAW_BUFFER and READ_BUFFER start at BACK or FRONT.
                glow.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
                glow.read_buffer(glow::COLOR_ATTACHMENT0);
                Some(fb)
            } else {
                None
            };
            // A window's initial viewport and scissor box are its size (GL 2.1 §2.11.1, §4.1.2);
            // a surfaceless context starts at 0x0.
            glow.viewport(0, 0, w, h);
            glow.scissor(0, 0, w, h);
            glow.clear_color(0.0, 0.0, 0.0, 0.0);
            if on_fbo && config.double_buffered {
                glow.draw_buffers(&[glow::COLOR_ATTACHMENT0, glow::COLOR_ATTACHMENT1]);
            }
            glow.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT);
            if on_fbo {
                glow.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
            }
            let formats = glow.get_parameter_i32(glow::NUM_COMPRESSED_TEXTURE_FORMATS);
            let max_get = (formats.max(0) as usize).clamp(16, 4096);
            // Setup leaves no error behind: the stream starts with a clear flag.
            while glow.get_error() != glow::NO_ERROR {}
            (fb, renderer, version, max_get)
        };
        let buffer = if config.double_buffered {
            gl::BACK
        } else {
            gl::FRONT
        };
        let id = NEXT_ID.fetch_add(1, Ordering::Relaxed);
        CURRENT.with(|c| c.set(id));
        Ok(GlBackend {
            id,
            raw,
            glow,
            fb,
            width,
            height,
            config,
            draw_buffer: buffer,
            read_buffer: buffer,
            // Emulated on an FBO only: OSMesa's framebuffer has the driver's own.
            accum: (config.accum && on_fbo).then(|| vec![[0; 4]; width as usize * height as usize]),
            accum_size: (width, height),
            select: select::Buffers::default(),
            error: gl::NO_ERROR,
            inside_begin_end: false,
            phong: false,
            phong_dirty: true,
            phong_program: None,
            lists: Default::default(),
            max_get_values,
            renderer,
            version,
            platform,
            _not_send: PhantomData,
            arrays: crate::arrays::ArrayState::default(),
            user_fbos: fbo::UserFbos::default(),
        })
    }

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Makes this backend's context current on the calling thread if another one is.
    pub(crate) fn make_current(&self) {
        if CURRENT.with(Cell::get) != self.id {
            match &self.platform {
                Platform::Egl(egl) => {
                    if OSMESA_SINCE_EGL.with(|f| f.replace(false)) {
                        use glutin::context::PossiblyCurrentGlContext as _;
                        let _ = egl.context.make_not_current_in_place();
                    }
                    match egl.context.make_current_surfaceless() {
                        Ok(()) => CURRENT.with(|c| c.set(self.id)),
                        Err(e) => eprintln!("fixedgl: eglMakeCurrent failed: {e}"),
                    }
                }
                Platform::OsMesa(ctx, _) => {
                    OSMESA_SINCE_EGL.with(|f| f.set(true));
                    match ctx.make_current() {
                        true => CURRENT.with(|c| c.set(self.id)),
                        false => eprintln!("fixedgl: OSMesaMakeCurrent failed"),
                    }
                }
            }
        }
    }

    /// The driver's `GL_RENDERER` string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    pub fn renderer(&self) -> &str {
        &self.renderer
    }

    /// The driver's `GL_VERSION` string (e.g. "4.5 (Compatibility Profile) Mesa 22.3.6").
    pub fn version(&self) -> &str {
        &self.version
    }

    /// The EGL device the backend runs on.
    pub fn device(&self) -> &DeviceInfo {
        match &self.platform {
            Platform::Egl(egl) => &egl.device,
            Platform::OsMesa(_, info) => info,
        }
    }

    /// The generated driver entry points, for calling the driver directly (each is itself
    /// `unsafe`: the caller vouches for its pointer arguments). Makes this backend's context
    /// current on the calling thread. The backend's Begin/End, error and `PHONG_WIN` tracking do
    /// not see such calls.
    ///
    /// # Safety
    ///
    /// The backend's own methods call the driver with pointers they size from the state they
    /// expect it to be in; direct calls can change that state under them. For as long as this
    /// backend is used after calls made through the returned value, the caller guarantees that
    /// those calls:
    ///
    /// - are made on this thread while this backend's context is current: no method of another
    ///   [`GlBackend`] (which makes its own context current) runs between `raw()` and them;
    /// - leave no client-array pointer set (`VertexPointer`, `TexCoordPointer`, ...; enabled or
    ///   not) to memory that may be freed before the backend's next draw, no pack state that
    ///   [`GlBackend::read_image`] does not set and restore (it does ALIGNMENT, ROW_LENGTH,
    ///   SKIP_ROWS, SKIP_PIXELS and SWAP_BYTES; LSB_FIRST, IMAGE_HEIGHT and SKIP_IMAGES do not
    ///   affect its read) away from its initial value, nor a buffer bound to `PIXEL_PACK_BUFFER`;
    /// - do not delete or unbind the backend's framebuffer object or its renderbuffers, and do
    ///   not leave a `Begin` open or a GLSL program bound.
    pub unsafe fn raw(&self) -> &raw::Gl {
        self.make_current();
        &self.raw
    }

    /// Executes `calls` in order (see [`GlBackend::execute`]).
    pub fn replay(&mut self, calls: &[Call]) {
        for call in calls {
            self.execute(call);
        }
    }

    /// `glGetError` with the backend's own errors merged in: the first error since the last read,
    /// then clear (GL 2.1 §2.5). Between Begin and End it is itself an INVALID_OPERATION and
    /// returns NO_ERROR, as the driver and the CPU front end do.
    pub fn get_error(&mut self) -> u32 {
        self.make_current();
        // SAFETY: context current; no pointers.
        let driver = unsafe { self.raw.GetError() };
        if self.inside_begin_end {
            return driver;
        }
        if self.error != gl::NO_ERROR {
            // Ours came first; one GL flag would have dropped whatever the driver holds.
            return std::mem::replace(&mut self.error, gl::NO_ERROR);
        }
        driver
    }

    /// Records `code` as the backend's own error unless an earlier one is pending, in the
    /// driver's flag or ours (the first error sticks).
    pub(crate) fn raise(&mut self, code: u32) {
        self.make_current();
        if self.error != gl::NO_ERROR {
            return;
        }
        if !self.inside_begin_end {
            // SAFETY: context current; outside Begin/End glGetError is a plain read.
            let pending = unsafe { self.raw.GetError() };
            if pending != gl::NO_ERROR {
                self.error = pending;
                return;
            }
        }
        self.error = code;
    }

    /// `glIsEnabled` on the driver.
    pub fn is_enabled(&mut self, cap: u32) -> bool {
        self.make_current();
        // SAFETY: context current; no pointers.
        unsafe { self.raw.IsEnabled(cap) != 0 }
    }

    /// `glGetFloatv`: writes the pname's values to the front of `out`. An `out` shorter than the
    /// pname's value count is INVALID_VALUE with nothing written (as the CPU front end).
    /// SHADE_MODEL reports PHONG_WIN while it is emulated; DRAW_BUFFER, READ_BUFFER,
    /// DOUBLEBUFFER and ACCUM_*_BITS report the framebuffer the backend stands in for
    /// (`buffers.rs`), not its FBO.
    pub fn get_floatv(&mut self, pname: u32, out: &mut [f32]) {
        let sentinels = [f32::from_bits(0x7fc1_2345), f32::from_bits(0x7fd5_4321)];
        let written = self.get_into(pname, out, sentinels, f32::to_bits, |gl, p, v| {
            // SAFETY: `get_into` passes a buffer of `max_get_values` slots, the most any pname
            // writes.
            unsafe { gl.GetFloatv(p, v) }
        });
        if let (true, Some(first)) = (
            written && pname == gl::SHADE_MODEL && self.phong,
            out.first_mut(),
        ) {
            *first = gl::PHONG_WIN as f32;
        }
        if let (true, Some(v), Some(first)) = (written, self.winsys_value(pname), out.first_mut()) {
            *first = v as f32;
        }
    }

    /// `glGetIntegerv` (slice rule and SHADE_MODEL as [`GlBackend::get_floatv`]).
    pub fn get_integerv(&mut self, pname: u32, out: &mut [i32]) {
        let sentinels = [0x5a5a_1234, -0x2345_6789];
        let written = self.get_into(
            pname,
            out,
            sentinels,
            |v| v as u32,
            // SAFETY: as in `get_floatv`.
            |gl, p, v| unsafe { gl.GetIntegerv(p, v) },
        );
        if let (true, Some(first)) = (
            written && pname == gl::SHADE_MODEL && self.phong,
            out.first_mut(),
        ) {
            *first = gl::PHONG_WIN as i32;
        }
        if let (true, Some(v), Some(first)) = (written, self.winsys_value(pname), out.first_mut()) {
            *first = v as i32;
        }
    }

    /// `glGetBooleanv` (slice rule as [`GlBackend::get_floatv`]).
    pub fn get_booleanv(&mut self, pname: u32, out: &mut [bool]) {
        let mut bytes = vec![0u8; out.len()];
        let written = self.get_into(
            pname,
            &mut bytes,
            [0xa5, 0x5a],
            u32::from,
            // SAFETY: as in `get_floatv`.
            |gl, p, v| unsafe { gl.GetBooleanv(p, v) },
        );
        if written {
            for (o, b) in out.iter_mut().zip(&bytes) {
                *o = *b != 0;
            }
        }
        if let (true, Some(v), Some(first)) = (written, self.winsys_value(pname), out.first_mut()) {
            *first = v != 0.0;
        }
    }

    /// `glGetTexParameterfv` of the object bound to `target` on the active unit (slice rule as
    /// [`GlBackend::get_floatv`]): what the front end's `get_tex_parameterfv` is compared with.
    pub fn get_tex_parameterfv(&mut self, target: u32, pname: u32, out: &mut [f32]) {
        let sentinels = [f32::from_bits(0x7fc1_2345), f32::from_bits(0x7fd5_4321)];
        self.get_into(pname, out, sentinels, f32::to_bits, |gl, p, v| {
            // SAFETY: `get_into` passes a buffer of `max_get_values` slots; a texture parameter
            // is at most 4 values (TEXTURE_BORDER_COLOR).
            unsafe { gl.GetTexParameterfv(target, p, v) }
        });
    }

    /// `glGetTexParameteriv` (as [`GlBackend::get_tex_parameterfv`]).
    pub fn get_tex_parameteriv(&mut self, target: u32, pname: u32, out: &mut [i32]) {
        let sentinels = [0x5a5a_1234, -0x2345_6789];
        self.get_into(
            pname,
            out,
            sentinels,
            |v| v as u32,
            // SAFETY: as in `get_tex_parameterfv`.
            |gl, p, v| unsafe { gl.GetTexParameteriv(target, p, v) },
        );
    }

    /// The common path of the `get_*` queries. The driver writes into a scratch buffer twice
    /// prefilled with two different sentinels; the written count is where both passes stop
    /// differing from their sentinel. This needs no table of pnames and never lets the driver
    /// write past a caller's slice. Returns whether `out` was written.
    fn get_into<T: Copy + Default>(
        &mut self,
        pname: u32,
        out: &mut [T],
        sentinels: [T; 2],
        bits: impl Fn(T) -> u32,
        query: impl Fn(&raw::Gl, u32, *mut T),
    ) -> bool {
        self.make_current();
        let mut scratch = [
            vec![T::default(); self.max_get_values],
            vec![T::default(); self.max_get_values],
        ];
        for (buf, s) in scratch.iter_mut().zip(sentinels) {
            buf.fill(s);
            query(&self.raw, pname, buf.as_mut_ptr());
        }
        let count = (0..self.max_get_values)
            .rev()
            .find(|&i| {
                bits(scratch[0][i]) != bits(sentinels[0])
                    || bits(scratch[1][i]) != bits(sentinels[1])
            })
            .map_or(0, |i| i + 1);
        if count == 0 {
            // Nothing written: the driver raised an error (bad pname, inside Begin/End).
            return false;
        }
        if out.len() < count {
            self.raise(gl::INVALID_VALUE);
            return false;
        }
        out[..count].copy_from_slice(&scratch[0][..count]);
        true
    }

    /// `glFinish`: waits until the driver has drawn everything issued.
    pub fn finish(&mut self) {
        self.make_current();
        // SAFETY: context current; no pointers.
        unsafe { self.raw.Finish() }
    }

    /// The colour buffer as an image with the top row first (glReadPixels returns rows bottom-up,
    /// GL 2.1 §4.3.2): the default one (the back buffer when double-buffered), as
    /// `Context::to_image`. Reads from the FBO with the pack modes at their initial values except
    /// PACK_ALIGNMENT 1 (whatever PACK_ROW_LENGTH, SKIP_ROWS, SKIP_PIXELS or SWAP_BYTES the
    /// recorded calls set, which would shift the image or write past `pixels`) and the colour
    /// transfer at its identity (scales 1, biases 0, MAP_COLOR off), then restores them.
    pub fn read_image(&mut self) -> RgbaImage {
        self.make_current();
        let (w, h) = (self.width as usize, self.height as usize);
        let mut pixels = vec![0u8; w * h * 4];
        // Every pack mode that moves where ReadPixels writes (GL 2.1 §4.3.2), and the value it
        // must have for `pixels` to be read tightly packed from its first byte.
        const RESET: [(u32, i32); 5] = [
            (glow::PACK_ALIGNMENT, 1),
            (glow::PACK_ROW_LENGTH, 0),
            (glow::PACK_SKIP_ROWS, 0),
            (glow::PACK_SKIP_PIXELS, 0),
            (glow::PACK_SWAP_BYTES, 0),
        ];
        // The colour transfer (GL 2.1 §4.3.2: scale, bias and MAP_COLOR apply to ReadPixels)
        // and its identity values: the image is the framebuffer as it is.
        const TRANSFER: [(u32, f32); 9] = [
            (gl::MAP_COLOR, 0.0),
            (gl::RED_SCALE, 1.0),
            (gl::GREEN_SCALE, 1.0),
            (gl::BLUE_SCALE, 1.0),
            (gl::ALPHA_SCALE, 1.0),
            (gl::RED_BIAS, 0.0),
            (gl::GREEN_BIAS, 0.0),
            (gl::BLUE_BIAS, 0.0),
            (gl::ALPHA_BIAS, 0.0),
        ];
        // SAFETY: context current; `pixels` holds exactly w*h RGBA8 texels with alignment 1,
        // no row length and no skips; GetFloatv of each transfer pname writes one value.
        unsafe {
            let saved = RESET.map(|(pname, _)| self.glow.get_parameter_i32(pname));
            for (pname, v) in RESET {
                self.glow.pixel_store_i32(pname, v);
            }
            let mut transfer = [0.0f32; 9];
            for ((pname, v), slot) in TRANSFER.iter().zip(&mut transfer) {
                self.raw.GetFloatv(*pname, slot);
                self.raw.PixelTransferf(*pname, *v);
            }
            self.glow
                .bind_framebuffer(glow::READ_FRAMEBUFFER, self.fb.as_ref().map(|f| f.fbo));
            // The default buffer, whatever READ_BUFFER the calls chose (restored below).
            let read = self.glow.get_parameter_i32(glow::READ_BUFFER);
            self.glow.read_buffer(match self.fb {
                Some(_) => glow::COLOR_ATTACHMENT0,
                None => glow::FRONT,
            });
            self.glow.read_pixels(
                0,
                0,
                self.width as i32,
                self.height as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut pixels)),
            );
            self.glow.read_buffer(read as u32);
            for ((pname, _), v) in RESET.iter().zip(saved) {
                self.glow.pixel_store_i32(*pname, v);
            }
            for ((pname, _), v) in TRANSFER.iter().zip(transfer) {
                self.raw.PixelTransferf(*pname, v);
            }
        }
        let row = w * 4;
        let mut top_down = Vec::with_capacity(pixels.len());
        for r in pixels.chunks_exact(row.max(1)).rev() {
            top_down.extend_from_slice(r);
        }
        // Whole rows of the w x h read-back, reversed: exactly one image's bytes.
        debug_assert_eq!(top_down.len(), w * h * 4);
        RgbaImage::from_raw(self.width, self.height, top_down)
            .unwrap_or_else(|| RgbaImage::new(self.width, self.height))
    }

    /// `ShadeModel` as the backend replays it: FLAT and SMOOTH go to the driver; `PHONG_WIN` sets
    /// SMOOTH on the driver and shades lit primitives per fragment with the emulation program.
    /// Anything else goes to the driver unchanged, so the driver raises the error.
    pub fn shade_model(&mut self, mode: u32) {
        self.make_current();
        // lists: under NewList(COMPILE) the driver stores the mode (SMOOTH for PHONG_WIN, whose
        // list is then expanded when it runs, see lists.rs) and nothing of ours changes.
        if self.compile_only() {
            let stored = if mode == gl::PHONG_WIN {
                gl::SMOOTH
            } else {
                mode
            };
            // SAFETY: context current; no pointers.
            return unsafe { self.raw.ShadeModel(stored) };
        }
        if mode != gl::PHONG_WIN || self.inside_begin_end {
            // SAFETY: context current; no pointers.
            unsafe { self.raw.ShadeModel(mode) };
            if !self.inside_begin_end && (mode == gl::FLAT || mode == gl::SMOOTH) && self.phong {
                self.phong = false;
                // SAFETY: context current.
                unsafe { self.glow.use_program(None) };
            }
            return;
        }
        if self.phong_program.is_none() {
            match phong::PhongProgram::new(&self.glow) {
                Ok(p) => self.phong_program = Some(p),
                Err(e) => {
                    // A driver without GLSL cannot emulate PHONG_WIN: report it as the GL error
                    // a driver lacking the extension gives, and say why on stderr.
                    eprintln!("fixedgl: {e}");
                    return self.raise(gl::INVALID_ENUM);
                }
            }
        }
        // SAFETY: context current; no pointers.
        unsafe { self.raw.ShadeModel(gl::SMOOTH) };
        self.phong = true;
        self.phong_dirty = true;
    }

    /// Called before a Begin is sent to the driver: under PHONG_WIN, brings the program in line
    /// with the driver's lighting state if anything may have changed it.
    fn before_begin(&mut self) {
        if self.phong && self.phong_dirty && !self.inside_begin_end {
            if let Some(p) = &self.phong_program {
                p.sync(&self.raw, &self.glow);
            }
            self.phong_dirty = false;
        }
    }
}

impl Drop for GlBackend {
    fn drop(&mut self) {
        self.make_current();
        // SAFETY: the objects were created on this context, which is still current here.
        unsafe {
            // llvmpipe's rasteriser threads may still be drawing a scene that counts into an
            // occlusion query; destroying the context frees the query under them (a
            // use-after-free valgrind shows in Mesa 22.3). Finish first: nothing is in flight.
            self.raw.Finish();
            if let Some(p) = &self.phong_program {
                p.delete(&self.glow);
            }
            self.glow.bind_framebuffer(glow::FRAMEBUFFER, None);
            if let Some(fb) = &self.fb {
                fb.delete(&self.glow);
            }
        }
        // Released from this thread, so that dropping the context destroys it now: EGL defers
        // destroying a context that is still current, and a thread that ends without releasing
        // it (every test thread) would leak it with its driver resources.
        use glutin::context::PossiblyCurrentGlContext as _;
        if let Platform::Egl(egl) = &self.platform {
            let _ = egl.context.make_not_current_in_place();
        }
        CURRENT.with(|c| c.set(0));
    }
}

impl GlBackend {
    /// Replays `calls` as one benchmark frame starting from the state the frame began in: all
    /// server and client attribute groups and the three matrix stacks' tops are saved before
    /// and restored after (PushAttrib/PushClientAttrib, GL 2.1 §6.1.14), an unterminated Begin
    /// is closed, and the PHONG_WIN emulation is reset to its state at the start.
    pub fn replay_frame(&mut self, calls: &[Call]) {
        self.make_current();
        let phong = self.phong;
        // The client array state PopClientAttrib restores, for the shadow, and the draw and
        // read buffers PopAttrib restores on the driver.
        let saved_arrays = self.arrays.clone();
        let saved_buffers = (self.draw_buffer, self.read_buffer);
        // SAFETY: context current; no pointers.
        unsafe {
            self.raw.PushAttrib(gl::ALL_ATTRIB_BITS);
            self.raw.PushClientAttrib(gl::CLIENT_ALL_ATTRIB_BITS);
            for mode in [gl::TEXTURE, gl::PROJECTION, gl::MODELVIEW] {
                self.raw.MatrixMode(mode);
                self.raw.PushMatrix();
            }
        }
        self.replay(calls);
        if self.inside_begin_end {
            self.execute(&Call::End);
        }
        // SAFETY: as above.
        unsafe {
            for mode in [gl::TEXTURE, gl::PROJECTION, gl::MODELVIEW] {
                self.raw.MatrixMode(mode);
                self.raw.PopMatrix();
            }
            self.raw.PopClientAttrib();
            self.raw.PopAttrib();
        }
        self.restore_client_arrays(saved_arrays);
        (self.draw_buffer, self.read_buffer) = saved_buffers;
        if !phong && self.phong {
            self.phong = false;
            // SAFETY: context current.
            unsafe { self.glow.use_program(None) };
        }
        self.phong_dirty = true;
    }
}
