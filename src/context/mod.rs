//! The GL front end: validates every call exactly as GL does, then changes `State`, records the
//! call, and hands vertices to the CPU backend.
//!
//! Every entry point follows the same three steps (Mesa `main/*.c`):
//! 1. **record**: when recording, the call is appended to the stream as a [`Call`], erroneous or
//!    not, so a replay elsewhere reproduces the same errors;
//! 2. **validate**: on error, `Context::error` sets the sticky flag and the call returns having
//!    changed nothing else (GL 2.1 §2.5);
//! 3. **set**: flush the vertex batch if the change affects rendering, then write `State`.
//!
//! Commands not allowed between Begin and End (GL 2.1 §2.6.3) start with
//! `Context::outside_begin_end`, which both raises INVALID_OPERATION inside a Begin/End pair
//! and flushes batched vertices before the state they were specified under changes.
//!
//! One submodule per area, each an `impl Context` block: `vertex` (current attributes and
//! `Vertex`, the hot path), `lighting` (Material, Light, LightModel, ColorMaterial, ShadeModel),
//! `raster` (FrontFace, CullFace, PolygonMode, PolygonOffset, PointSize, LineWidth),
//! `framebuffer` (Clear*, DepthFunc, masks, Scissor) and `control` (Hint, PixelStore, Flush,
//! Finish). Begin/End, Enable/Disable, the error flag and [`Context::execute`] live here.

mod control;
mod framebuffer;
mod lighting;
mod raster;
#[cfg(test)]
mod tests;
mod vertex;

use crate::call::Call;
use crate::cpu::Renderer;
use crate::gl;
use crate::state::{State, MAX_VIEWPORT_DIM};
use crate::Error;

mod get;
mod matrix;

/// Appends `$call` to the recording, if one is running, and to the display list being
/// compiled, if any (GL 2.1 §5.4); builds the `Call` only then. Under NewList(COMPILE) it then
/// returns from the calling method: the command is stored, not validated or executed. A call
/// [`Call::executes_immediately`] names is recorded but never compiled. Calls made by a list
/// being executed (CallList) are neither recorded nor compiled: the stream holds the CallList.
macro_rules! record {
    ($ctx:expr, $call:expr) => {
        debug_assert_eq!(
            $ctx.capturing,
            $ctx.recording.is_some() || $ctx.lists.compiling.is_some()
        );
        if $ctx.capturing && $ctx.lists.depth == 0 && $ctx.capture($call) {
            return;
        }
    };
}
pub(crate) use record;

/// A GL context: state, sticky error flag, optional recording, and the CPU framebuffer.
///
/// Nothing is global: contexts are independent values and may live on different threads.
#[derive(Debug)]
pub struct Context {
    pub(crate) state: State,
    /// The sticky error flag (`NO_ERROR` when clear).
    pub(crate) error: u32,
    /// The mode of the open Begin/End pair, if any.
    pub(crate) begin_mode: Option<u32>,
    pub(crate) recording: Option<Vec<Call>>,
    /// Whether a recording runs or a display list is being compiled: `record!`'s one test on
    /// every call. Every change of `recording` or `lists.compiling` calls `sync_capturing`.
    pub(crate) capturing: bool,
    pub(crate) renderer: Renderer,
    pub(crate) lists: lists::DisplayLists,
    pub(crate) attrib: attrib::AttribStacks,
}

impl Context {
    /// A context with a `width` x `height` framebuffer (RGBA8 colour, 24-bit depth, 8-bit stencil)
    /// in GL's initial state. Each side must be between 1 and 16384.
    pub fn new(width: u32, height: u32) -> Result<Context, Error> {
        if width == 0 || height == 0 || width > MAX_VIEWPORT_DIM || height > MAX_VIEWPORT_DIM {
            return Err(Error::InvalidSize { width, height });
        }
        Ok(Context {
            state: State::new(width, height),
            error: gl::NO_ERROR,
            begin_mode: None,
            recording: None,
            capturing: false,
            renderer: Renderer::new(width, height),
            lists: Default::default(),
            attrib: Default::default(),
        })
    }

    /// Returns the context to GL's initial state — as `Context::new` would make it — but keeps
    /// the framebuffer (its contents and memory) and the renderer's buffers, so a program that
    /// draws many independent frames (a benchmark, an animation re-running its `init`) does not
    /// pay for allocating them again. Vertices batched but not yet drawn are discarded, as is any
    /// recording, display list and attribute stack. Not a GL entry point: never recorded.
    pub fn reset(&mut self) {
        let (w, h) = self.size();
        self.renderer.discard_batch();
        self.state = State::new(w, h);
        self.error = gl::NO_ERROR;
        self.begin_mode = None;
        self.recording = None;
        self.lists = Default::default();
        self.sync_capturing();
        self.attrib = Default::default();
    }

    /// The state, read-only: what the `get_*` queries report, as plain data.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.state.width, self.state.height)
    }

    /// Records `code` unless an earlier error is still unread: the first error sticks until
    /// `get_error` reads it (GL 2.1 §2.5).
    pub(crate) fn error(&mut self, code: u32) {
        if self.error == gl::NO_ERROR {
            self.error = code;
        }
    }

    /// `glGetError`: returns and clears the sticky error flag. Between Begin and End it is, like
    /// every command GL 2.1 §2.6.3 does not list, an INVALID_OPERATION: it returns NO_ERROR there
    /// (as Mesa does) and the flag is read by the first `get_error` after End.
    pub fn get_error(&mut self) -> u32 {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return gl::NO_ERROR;
        }
        std::mem::replace(&mut self.error, gl::NO_ERROR)
    }

    /// The sticky error flag, without reading (clearing) it: what the next `get_error` outside
    /// Begin/End will return. Not a GL entry point: for tests and tools that must not disturb
    /// the context.
    pub fn pending_error(&self) -> u32 {
        self.error
    }

    /// Whether a Begin/End pair is open. Not a GL entry point (GL has no query for it): for
    /// tests and tools.
    pub fn inside_begin_end(&self) -> bool {
        self.begin_mode.is_some()
    }

    /// For a command not allowed between Begin and End: raises INVALID_OPERATION there and
    /// returns false; otherwise draws the batched vertices (their state is about to change) and
    /// returns true.
    pub(crate) fn outside_begin_end(&mut self) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.renderer.flush(&self.state);
        true
    }

    /// Starts recording every call made on this context (replacing any recording in progress).
    pub fn start_recording(&mut self) {
        self.recording = Some(Vec::new());
        self.sync_capturing();
    }

    /// Stops recording and returns the calls recorded since `start_recording` (empty if none).
    pub fn stop_recording(&mut self) -> Vec<Call> {
        let calls = self.recording.take().unwrap_or_default();
        self.sync_capturing();
        calls
    }

    /// Brings `capturing` in step with `recording` and `lists.compiling`.
    pub(crate) fn sync_capturing(&mut self) {
        self.capturing = self.recording.is_some() || self.lists.compiling.is_some();
    }

    /// `glBegin`.
    pub fn begin(&mut self, mode: u32) {
        record!(self, Call::Begin(mode));
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if mode > gl::POLYGON {
            return self.error(gl::INVALID_ENUM);
        }
        self.begin_mode = Some(mode);
        self.renderer.begin(mode);
        // cpu-pipeline: the materials at Begin, for Material changes inside the pair (§2.14.3).
        self.renderer.begin_materials(&self.state.materials);
    }

    /// `glEnd`.
    pub fn end(&mut self) {
        record!(self, Call::End);
        if self.begin_mode.take().is_none() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.renderer.end();
        // cpu-pipeline: draw a large batch now (its state is unchanged since it was batched).
        self.renderer.flush_if_large(&self.state);
    }

    /// `glEnable`.
    pub fn enable(&mut self, cap: u32) {
        record!(self, Call::Enable(cap));
        self.set_enabled(cap, true);
    }

    /// `glDisable`.
    pub fn disable(&mut self, cap: u32) {
        record!(self, Call::Disable(cap));
        self.set_enabled(cap, false);
    }

    fn set_enabled(&mut self, cap: u32, on: bool) {
        if !self.outside_begin_end() {
            return;
        }
        match self.state.cap_mut(cap) {
            Some(flag) => *flag = on,
            None => return self.error(gl::INVALID_ENUM),
        }
        // GL 2.1 §2.14.3: once enabled, the selected material values track the current colour.
        if on && cap == gl::COLOR_MATERIAL {
            self.track_color_material();
        }
    }

    /// `glIsEnabled`: INVALID_ENUM (and false) for a cap that is not one.
    pub fn is_enabled(&mut self, cap: u32) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        // The client states (GL 2.1 §2.8) are IsEnabled caps, not Enable caps.
        let unit = self.state.client_active_texture;
        if let Some(on) = self.state.arrays.enabled(cap, unit) {
            return on;
        }
        match self.state.cap_mut(cap) {
            Some(flag) => *flag,
            None => {
                self.error(gl::INVALID_ENUM);
                false
            }
        }
    }

    /// Executes one recorded call on this context, exactly as if its method had been called.
    ///
    /// The calls an immediate-mode mesh is made of (Begin, End, Normal3f, Vertex3f: all but a
    /// handful of a recorded surface) are dispatched first, by a four-arm match inlined into
    /// replay loops; every other call goes through `execute_any`, which matches every variant
    /// (so a new entry point cannot be forgotten there).
    #[inline(always)]
    pub fn execute(&mut self, call: &Call) {
        match *call {
            Call::Vertex3f(a, b, c) => self.vertex3f(a, b, c),
            Call::Normal3f(a, b, c) => self.normal3f(a, b, c),
            Call::Begin(a) => self.begin(a),
            Call::End => self.end(),
            _ => self.execute_any(call),
        }
    }

    /// `execute` for every call: one arm per variant.
    #[inline(never)]
    fn execute_any(&mut self, call: &Call) {
        match *call {
            // Begin/End and capabilities (GL 2.1 §2.6, §2.12)
            Call::Begin(a) => self.begin(a),
            Call::End => self.end(),
            Call::MatrixMode(mode) => self.matrix_mode(mode),
            Call::LoadIdentity => self.load_identity(),
            Call::LoadMatrixf(ref m) => self.load_matrixf(m),
            Call::LoadMatrixd(ref m) => self.load_matrixd(m),
            Call::MultMatrixf(ref m) => self.mult_matrixf(m),
            Call::MultMatrixd(ref m) => self.mult_matrixd(m),
            Call::LoadTransposeMatrixf(ref m) => self.load_transpose_matrixf(m),
            Call::LoadTransposeMatrixd(ref m) => self.load_transpose_matrixd(m),
            Call::MultTransposeMatrixf(ref m) => self.mult_transpose_matrixf(m),
            Call::MultTransposeMatrixd(ref m) => self.mult_transpose_matrixd(m),
            Call::Translatef(x, y, z) => self.translatef(x, y, z),
            Call::Translated(x, y, z) => self.translated(x, y, z),
            Call::Rotatef(a, x, y, z) => self.rotatef(a, x, y, z),
            Call::Rotated(a, x, y, z) => self.rotated(a, x, y, z),
            Call::Scalef(x, y, z) => self.scalef(x, y, z),
            Call::Scaled(x, y, z) => self.scaled(x, y, z),
            Call::Frustum(ref p) => self.frustum(p[0], p[1], p[2], p[3], p[4], p[5]),
            Call::Ortho(ref p) => self.ortho(p[0], p[1], p[2], p[3], p[4], p[5]),
            Call::PushMatrix => self.push_matrix(),
            Call::PopMatrix => self.pop_matrix(),
            Call::Viewport(x, y, w, h) => self.viewport(x, y, w, h),
            Call::DepthRange(n, f) => self.depth_range(n, f),
            Call::ClipPlane(plane, ref eq) => self.clip_plane(plane, eq),
            Call::ActiveTexture(t) => self.active_texture(t),
            Call::ClientActiveTexture(t) => self.client_active_texture(t),
            Call::Enable(a) => self.enable(a),
            Call::Disable(a) => self.disable(a),
            // Vertex attributes (GL 2.1 §2.7): context/vertex.rs
            Call::Vertex2s(a, b) => self.vertex2s(a, b),
            Call::Vertex2i(a, b) => self.vertex2i(a, b),
            Call::Vertex2f(a, b) => self.vertex2f(a, b),
            Call::Vertex2d(a, b) => self.vertex2d(a, b),
            Call::Vertex3s(a, b, c) => self.vertex3s(a, b, c),
            Call::Vertex3i(a, b, c) => self.vertex3i(a, b, c),
            Call::Vertex3f(a, b, c) => self.vertex3f(a, b, c),
            Call::Vertex3d(a, b, c) => self.vertex3d(a, b, c),
            Call::Vertex4s(a, b, c, d) => self.vertex4s(a, b, c, d),
            Call::Vertex4i(a, b, c, d) => self.vertex4i(a, b, c, d),
            Call::Vertex4f(a, b, c, d) => self.vertex4f(a, b, c, d),
            Call::Vertex4d(a, b, c, d) => self.vertex4d(a, b, c, d),
            Call::Vertex2sv(ref a) => self.vertex2sv(a),
            Call::Vertex2iv(ref a) => self.vertex2iv(a),
            Call::Vertex2fv(ref a) => self.vertex2fv(a),
            Call::Vertex2dv(ref a) => self.vertex2dv(a),
            Call::Vertex3sv(ref a) => self.vertex3sv(a),
            Call::Vertex3iv(ref a) => self.vertex3iv(a),
            Call::Vertex3fv(ref a) => self.vertex3fv(a),
            Call::Vertex3dv(ref a) => self.vertex3dv(a),
            Call::Vertex4sv(ref a) => self.vertex4sv(a),
            Call::Vertex4iv(ref a) => self.vertex4iv(a),
            Call::Vertex4fv(ref a) => self.vertex4fv(a),
            Call::Vertex4dv(ref a) => self.vertex4dv(a),
            Call::Normal3b(a, b, c) => self.normal3b(a, b, c),
            Call::Normal3s(a, b, c) => self.normal3s(a, b, c),
            Call::Normal3i(a, b, c) => self.normal3i(a, b, c),
            Call::Normal3f(a, b, c) => self.normal3f(a, b, c),
            Call::Normal3d(a, b, c) => self.normal3d(a, b, c),
            Call::Normal3bv(ref a) => self.normal3bv(a),
            Call::Normal3sv(ref a) => self.normal3sv(a),
            Call::Normal3iv(ref a) => self.normal3iv(a),
            Call::Normal3fv(ref a) => self.normal3fv(a),
            Call::Normal3dv(ref a) => self.normal3dv(a),
            Call::Color3b(a, b, c) => self.color3b(a, b, c),
            Call::Color3s(a, b, c) => self.color3s(a, b, c),
            Call::Color3i(a, b, c) => self.color3i(a, b, c),
            Call::Color3f(a, b, c) => self.color3f(a, b, c),
            Call::Color3d(a, b, c) => self.color3d(a, b, c),
            Call::Color3ub(a, b, c) => self.color3ub(a, b, c),
            Call::Color3us(a, b, c) => self.color3us(a, b, c),
            Call::Color3ui(a, b, c) => self.color3ui(a, b, c),
            Call::Color3bv(ref a) => self.color3bv(a),
            Call::Color3sv(ref a) => self.color3sv(a),
            Call::Color3iv(ref a) => self.color3iv(a),
            Call::Color3fv(ref a) => self.color3fv(a),
            Call::Color3dv(ref a) => self.color3dv(a),
            Call::Color3ubv(ref a) => self.color3ubv(a),
            Call::Color3usv(ref a) => self.color3usv(a),
            Call::Color3uiv(ref a) => self.color3uiv(a),
            Call::Color4b(a, b, c, d) => self.color4b(a, b, c, d),
            Call::Color4s(a, b, c, d) => self.color4s(a, b, c, d),
            Call::Color4i(a, b, c, d) => self.color4i(a, b, c, d),
            Call::Color4f(a, b, c, d) => self.color4f(a, b, c, d),
            Call::Color4d(a, b, c, d) => self.color4d(a, b, c, d),
            Call::Color4ub(a, b, c, d) => self.color4ub(a, b, c, d),
            Call::Color4us(a, b, c, d) => self.color4us(a, b, c, d),
            Call::Color4ui(a, b, c, d) => self.color4ui(a, b, c, d),
            Call::Color4bv(ref a) => self.color4bv(a),
            Call::Color4sv(ref a) => self.color4sv(a),
            Call::Color4iv(ref a) => self.color4iv(a),
            Call::Color4fv(ref a) => self.color4fv(a),
            Call::Color4dv(ref a) => self.color4dv(a),
            Call::Color4ubv(ref a) => self.color4ubv(a),
            Call::Color4usv(ref a) => self.color4usv(a),
            Call::Color4uiv(ref a) => self.color4uiv(a),
            Call::SecondaryColor3b(a, b, c) => self.secondary_color3b(a, b, c),
            Call::SecondaryColor3s(a, b, c) => self.secondary_color3s(a, b, c),
            Call::SecondaryColor3i(a, b, c) => self.secondary_color3i(a, b, c),
            Call::SecondaryColor3f(a, b, c) => self.secondary_color3f(a, b, c),
            Call::SecondaryColor3d(a, b, c) => self.secondary_color3d(a, b, c),
            Call::SecondaryColor3ub(a, b, c) => self.secondary_color3ub(a, b, c),
            Call::SecondaryColor3us(a, b, c) => self.secondary_color3us(a, b, c),
            Call::SecondaryColor3ui(a, b, c) => self.secondary_color3ui(a, b, c),
            Call::SecondaryColor3bv(ref a) => self.secondary_color3bv(a),
            Call::SecondaryColor3sv(ref a) => self.secondary_color3sv(a),
            Call::SecondaryColor3iv(ref a) => self.secondary_color3iv(a),
            Call::SecondaryColor3fv(ref a) => self.secondary_color3fv(a),
            Call::SecondaryColor3dv(ref a) => self.secondary_color3dv(a),
            Call::SecondaryColor3ubv(ref a) => self.secondary_color3ubv(a),
            Call::SecondaryColor3usv(ref a) => self.secondary_color3usv(a),
            Call::SecondaryColor3uiv(ref a) => self.secondary_color3uiv(a),
            Call::TexCoord1s(a) => self.tex_coord1s(a),
            Call::TexCoord1i(a) => self.tex_coord1i(a),
            Call::TexCoord1f(a) => self.tex_coord1f(a),
            Call::TexCoord1d(a) => self.tex_coord1d(a),
            Call::TexCoord2s(a, b) => self.tex_coord2s(a, b),
            Call::TexCoord2i(a, b) => self.tex_coord2i(a, b),
            Call::TexCoord2f(a, b) => self.tex_coord2f(a, b),
            Call::TexCoord2d(a, b) => self.tex_coord2d(a, b),
            Call::TexCoord3s(a, b, c) => self.tex_coord3s(a, b, c),
            Call::TexCoord3i(a, b, c) => self.tex_coord3i(a, b, c),
            Call::TexCoord3f(a, b, c) => self.tex_coord3f(a, b, c),
            Call::TexCoord3d(a, b, c) => self.tex_coord3d(a, b, c),
            Call::TexCoord4s(a, b, c, d) => self.tex_coord4s(a, b, c, d),
            Call::TexCoord4i(a, b, c, d) => self.tex_coord4i(a, b, c, d),
            Call::TexCoord4f(a, b, c, d) => self.tex_coord4f(a, b, c, d),
            Call::TexCoord4d(a, b, c, d) => self.tex_coord4d(a, b, c, d),
            Call::TexCoord1sv(ref a) => self.tex_coord1sv(a),
            Call::TexCoord1iv(ref a) => self.tex_coord1iv(a),
            Call::TexCoord1fv(ref a) => self.tex_coord1fv(a),
            Call::TexCoord1dv(ref a) => self.tex_coord1dv(a),
            Call::TexCoord2sv(ref a) => self.tex_coord2sv(a),
            Call::TexCoord2iv(ref a) => self.tex_coord2iv(a),
            Call::TexCoord2fv(ref a) => self.tex_coord2fv(a),
            Call::TexCoord2dv(ref a) => self.tex_coord2dv(a),
            Call::TexCoord3sv(ref a) => self.tex_coord3sv(a),
            Call::TexCoord3iv(ref a) => self.tex_coord3iv(a),
            Call::TexCoord3fv(ref a) => self.tex_coord3fv(a),
            Call::TexCoord3dv(ref a) => self.tex_coord3dv(a),
            Call::TexCoord4sv(ref a) => self.tex_coord4sv(a),
            Call::TexCoord4iv(ref a) => self.tex_coord4iv(a),
            Call::TexCoord4fv(ref a) => self.tex_coord4fv(a),
            Call::TexCoord4dv(ref a) => self.tex_coord4dv(a),
            Call::FogCoordf(a) => self.fog_coordf(a),
            Call::FogCoordd(a) => self.fog_coordd(a),
            Call::FogCoordfv(ref a) => self.fog_coordfv(a),
            Call::FogCoorddv(ref a) => self.fog_coorddv(a),
            Call::EdgeFlag(a) => self.edge_flag(a),
            Call::EdgeFlagv(ref a) => self.edge_flagv(a),
            // Lighting and shading (GL 2.1 §2.14): context/lighting.rs
            Call::Materialf(a, b, c) => self.materialf(a, b, c),
            Call::Materiali(a, b, c) => self.materiali(a, b, c),
            Call::Materialfv(a, b, ref c) => self.materialfv(a, b, c),
            Call::Materialiv(a, b, ref c) => self.materialiv(a, b, c),
            Call::Lightf(a, b, c) => self.lightf(a, b, c),
            Call::Lighti(a, b, c) => self.lighti(a, b, c),
            Call::Lightfv(a, b, ref c) => self.lightfv(a, b, c),
            Call::Lightiv(a, b, ref c) => self.lightiv(a, b, c),
            Call::LightModelf(a, b) => self.light_modelf(a, b),
            Call::LightModeli(a, b) => self.light_modeli(a, b),
            Call::LightModelfv(a, ref b) => self.light_modelfv(a, b),
            Call::LightModeliv(a, ref b) => self.light_modeliv(a, b),
            Call::ColorMaterial(a, b) => self.color_material(a, b),
            Call::ShadeModel(a) => self.shade_model(a),
            // Rasterisation (GL 2.1 §3.3 to §3.5): context/raster.rs
            Call::FrontFace(a) => self.front_face(a),
            Call::CullFace(a) => self.cull_face(a),
            Call::PolygonMode(a, b) => self.polygon_mode(a, b),
            Call::PolygonOffset(a, b) => self.polygon_offset(a, b),
            Call::PointSize(a) => self.point_size(a),
            Call::LineWidth(a) => self.line_width(a),
            // Framebuffer and per-fragment control (GL 2.1 §4.1, §4.2): context/framebuffer.rs
            Call::ClearColor(a, b, c, d) => self.clear_color(a, b, c, d),
            Call::ClearDepth(a) => self.clear_depth(a),
            Call::ClearStencil(a) => self.clear_stencil(a),
            Call::Clear(a) => self.clear(a),
            Call::DepthFunc(a) => self.depth_func(a),
            Call::DepthMask(a) => self.depth_mask(a),
            Call::ColorMask(a, b, c, d) => self.color_mask(a, b, c, d),
            Call::Scissor(a, b, c, d) => self.scissor(a, b, c, d),
            // Hints, pixel store, flush (GL 2.1 §5.6, §3.6.1, §5.5): context/control.rs
            Call::Hint(a, b) => self.hint(a, b),
            Call::PixelStorei(a, b) => self.pixel_storei(a, b),
            Call::PixelStoref(a, b) => self.pixel_storef(a, b),
            Call::Flush => self.flush(),
            Call::Finish => self.finish(),
            // Display lists, attribute stacks (context/lists.rs, context/attrib.rs)
            Call::GenLists(a) => {
                self.gen_lists(a);
            }
            Call::NewList(a, b) => self.new_list(a, b),
            Call::EndList => self.end_list(),
            Call::CallList(a) => self.call_list(a),
            Call::CallLists(a, b, ref c) => self.call_lists(a, b, c),
            Call::ListBase(a) => self.list_base(a),
            Call::DeleteLists(a, b) => self.delete_lists(a, b),
            Call::PushAttrib(a) => self.push_attrib(a),
            Call::PopAttrib => self.pop_attrib(),
            Call::PushClientAttrib(a) => self.push_client_attrib(a),
            Call::PopClientAttrib => self.pop_client_attrib(),
            Call::EnableClientState(a) => self.enable_client_state(a),
            Call::DisableClientState(a) => self.disable_client_state(a),
            Call::VertexPointer(a, b, c, ref p) => self.vertex_pointer(a, b, c, p.clone()),
            Call::NormalPointer(a, b, ref p) => self.normal_pointer(a, b, p.clone()),
            Call::ColorPointer(a, b, c, ref p) => self.color_pointer(a, b, c, p.clone()),
            Call::SecondaryColorPointer(a, b, c, ref p) => {
                self.secondary_color_pointer(a, b, c, p.clone())
            }
            Call::TexCoordPointer(a, b, c, ref p) => self.tex_coord_pointer(a, b, c, p.clone()),
            Call::FogCoordPointer(a, b, ref p) => self.fog_coord_pointer(a, b, p.clone()),
            Call::EdgeFlagPointer(a, ref p) => self.edge_flag_pointer(a, p.clone()),
            Call::InterleavedArrays(a, b, ref p) => self.interleaved_arrays(a, b, p.clone()),
            Call::ArrayElement(i) => self.array_element(i),
            Call::DrawArrays(a, b, c) => self.draw_arrays(a, b, c),
            Call::DrawElements(a, b, c, ref p) => self.draw_elements(a, b, c, p.clone()),
            Call::DrawRangeElements(a, b, c, d, e, ref p) => {
                self.draw_range_elements(a, b, c, d, e, (**p).clone())
            }
            Call::GenBuffers(n, ref names) => {
                // The names the recorded call got, if it succeeded; room for as many.
                let mut out = vec![0; names.len()];
                self.gen_buffers(n, &mut out);
            }
            Call::DeleteBuffers(n, ref names) => self.delete_buffers(n, names),
            Call::BindBuffer(a, b) => self.bind_buffer(a, b),
            Call::BufferData(a, b, ref p, d) => self.buffer_data(a, b, (**p).clone(), d),
            Call::BufferSubData(a, b, c, ref p) => self.buffer_sub_data(a, b, c, (**p).clone()),
            Call::Fogf(p, v) => self.fogf(p, v),
            Call::Fogi(p, v) => self.fogi(p, v),
            Call::Fogfv(p, ref v) => self.fogfv(p, v),
            Call::Fogiv(p, ref v) => self.fogiv(p, v),
            Call::AlphaFunc(f, r) => self.alpha_func(f, r),
            Call::StencilFunc(f, r, m) => self.stencil_func(f, r, m),
            Call::StencilFuncSeparate(face, f, r, m) => self.stencil_func_separate(face, f, r, m),
            Call::StencilOp(a, b, c) => self.stencil_op(a, b, c),
            Call::StencilOpSeparate(face, a, b, c) => self.stencil_op_separate(face, a, b, c),
            Call::StencilMask(m) => self.stencil_mask(m),
            Call::StencilMaskSeparate(face, m) => self.stencil_mask_separate(face, m),
            Call::BlendFunc(s, d) => self.blend_func(s, d),
            Call::BlendFuncSeparate(a, b, c, d) => self.blend_func_separate(a, b, c, d),
            Call::BlendEquation(m) => self.blend_equation(m),
            Call::BlendEquationSeparate(a, b) => self.blend_equation_separate(a, b),
            Call::BlendColor(r, g, b, a) => self.blend_color(r, g, b, a),
            Call::LogicOp(op) => self.logic_op(op),
            Call::GenTextures(n) => {
                let mut names = vec![0; n.clamp(0, texture::MAX_GEN_TEXTURES) as usize];
                self.gen_textures(n, &mut names);
            }
            Call::DeleteTextures(n, ref t) => self.delete_textures(n, t),
            Call::BindTexture(a, b) => self.bind_texture(a, b),
            Call::TexImage2D(ref args) => {
                let (t, l, i, w, h, b, f, ty, ref p) = **args;
                self.tex_image_2d(t, l, i, w, h, b, f, ty, p.as_deref())
            }
            Call::TexSubImage2D(ref args) => {
                let (t, l, x, y, w, h, f, ty, ref p) = **args;
                self.tex_sub_image_2d(t, l, x, y, w, h, f, ty, p)
            }
            Call::CopyTexImage2D(t, l, i, x, y, w, h, b) => {
                self.copy_tex_image_2d(t, l, i, x, y, w, h, b)
            }
            Call::CopyTexSubImage2D(t, l, xo, yo, x, y, w, h) => {
                self.copy_tex_sub_image_2d(t, l, xo, yo, x, y, w, h)
            }
            Call::TexParameteri(a, b, c) => self.tex_parameteri(a, b, c),
            Call::TexParameterf(a, b, c) => self.tex_parameterf(a, b, c),
            Call::TexParameteriv(a, b, ref c) => self.tex_parameteriv(a, b, c),
            Call::TexParameterfv(a, b, ref c) => self.tex_parameterfv(a, b, c),
            Call::TexEnvi(a, b, c) => self.tex_envi(a, b, c),
            Call::TexEnvf(a, b, c) => self.tex_envf(a, b, c),
            Call::TexEnviv(a, b, ref c) => self.tex_enviv(a, b, c),
            Call::TexEnvfv(a, b, ref c) => self.tex_envfv(a, b, c),
            Call::TexGeni(a, b, c) => self.tex_geni(a, b, c),
            Call::TexGenf(a, b, c) => self.tex_genf(a, b, c),
            Call::TexGend(a, b, c) => self.tex_gend(a, b, c),
            Call::TexGeniv(a, b, ref c) => self.tex_geniv(a, b, c),
            Call::TexGenfv(a, b, ref c) => self.tex_genfv(a, b, c),
            Call::TexGendv(a, b, ref c) => self.tex_gendv(a, b, c),
            Call::MultiTexCoord1s(t, a0) => self.multi_tex_coord1s(t, a0),
            Call::MultiTexCoord1sv(t, ref v) => self.multi_tex_coord1sv(t, v),
            Call::MultiTexCoord1i(t, a0) => self.multi_tex_coord1i(t, a0),
            Call::MultiTexCoord1iv(t, ref v) => self.multi_tex_coord1iv(t, v),
            Call::MultiTexCoord1f(t, a0) => self.multi_tex_coord1f(t, a0),
            Call::MultiTexCoord1fv(t, ref v) => self.multi_tex_coord1fv(t, v),
            Call::MultiTexCoord1d(t, a0) => self.multi_tex_coord1d(t, a0),
            Call::MultiTexCoord1dv(t, ref v) => self.multi_tex_coord1dv(t, v),
            Call::MultiTexCoord2s(t, a0, a1) => self.multi_tex_coord2s(t, a0, a1),
            Call::MultiTexCoord2sv(t, ref v) => self.multi_tex_coord2sv(t, v),
            Call::MultiTexCoord2i(t, a0, a1) => self.multi_tex_coord2i(t, a0, a1),
            Call::MultiTexCoord2iv(t, ref v) => self.multi_tex_coord2iv(t, v),
            Call::MultiTexCoord2f(t, a0, a1) => self.multi_tex_coord2f(t, a0, a1),
            Call::MultiTexCoord2fv(t, ref v) => self.multi_tex_coord2fv(t, v),
            Call::MultiTexCoord2d(t, a0, a1) => self.multi_tex_coord2d(t, a0, a1),
            Call::MultiTexCoord2dv(t, ref v) => self.multi_tex_coord2dv(t, v),
            Call::MultiTexCoord3s(t, a0, a1, a2) => self.multi_tex_coord3s(t, a0, a1, a2),
            Call::MultiTexCoord3sv(t, ref v) => self.multi_tex_coord3sv(t, v),
            Call::MultiTexCoord3i(t, a0, a1, a2) => self.multi_tex_coord3i(t, a0, a1, a2),
            Call::MultiTexCoord3iv(t, ref v) => self.multi_tex_coord3iv(t, v),
            Call::MultiTexCoord3f(t, a0, a1, a2) => self.multi_tex_coord3f(t, a0, a1, a2),
            Call::MultiTexCoord3fv(t, ref v) => self.multi_tex_coord3fv(t, v),
            Call::MultiTexCoord3d(t, a0, a1, a2) => self.multi_tex_coord3d(t, a0, a1, a2),
            Call::MultiTexCoord3dv(t, ref v) => self.multi_tex_coord3dv(t, v),
            Call::MultiTexCoord4s(t, a0, a1, a2, a3) => self.multi_tex_coord4s(t, a0, a1, a2, a3),
            Call::MultiTexCoord4sv(t, ref v) => self.multi_tex_coord4sv(t, v),
            Call::MultiTexCoord4i(t, a0, a1, a2, a3) => self.multi_tex_coord4i(t, a0, a1, a2, a3),
            Call::MultiTexCoord4iv(t, ref v) => self.multi_tex_coord4iv(t, v),
            Call::MultiTexCoord4f(t, a0, a1, a2, a3) => self.multi_tex_coord4f(t, a0, a1, a2, a3),
            Call::MultiTexCoord4fv(t, ref v) => self.multi_tex_coord4fv(t, v),
            Call::MultiTexCoord4d(t, a0, a1, a2, a3) => self.multi_tex_coord4d(t, a0, a1, a2, a3),
            Call::MultiTexCoord4dv(t, ref v) => self.multi_tex_coord4dv(t, v),
        }
    }

    /// Executes every call of `calls` in order.
    pub fn replay(&mut self, calls: &[Call]) {
        for call in calls {
            self.execute(call);
        }
    }
}

impl State {
    /// The flag behind an `Enable` capability, or `None` if `cap` is not one.
    pub(crate) fn cap_mut(&mut self, cap: u32) -> Option<&mut bool> {
        let e = &mut self.enables;
        let unit = self.active_texture;
        Some(match cap {
            gl::LIGHTING => &mut e.lighting,
            gl::LIGHT0..=gl::LIGHT7 => &mut e.lights[(cap - gl::LIGHT0) as usize],
            gl::NORMALIZE => &mut e.normalize,
            gl::RESCALE_NORMAL => &mut e.rescale_normal,
            gl::COLOR_MATERIAL => &mut e.color_material,
            gl::DEPTH_TEST => &mut e.depth_test,
            gl::CULL_FACE => &mut e.cull_face,
            gl::CLIP_PLANE0..=gl::CLIP_PLANE5 => {
                &mut e.clip_planes[(cap - gl::CLIP_PLANE0) as usize]
            }
            gl::POLYGON_OFFSET_FILL => &mut e.polygon_offset_fill,
            gl::POLYGON_OFFSET_LINE => &mut e.polygon_offset_line,
            gl::POLYGON_OFFSET_POINT => &mut e.polygon_offset_point,
            gl::SCISSOR_TEST => &mut e.scissor_test,
            gl::ALPHA_TEST => &mut e.alpha_test,
            gl::BLEND => &mut e.blend,
            gl::STENCIL_TEST => &mut e.stencil_test,
            gl::FOG => &mut e.fog,
            gl::COLOR_SUM => &mut e.color_sum,
            gl::COLOR_LOGIC_OP => &mut e.color_logic_op,
            gl::INDEX_LOGIC_OP => &mut e.index_logic_op,
            gl::DITHER => &mut e.dither,
            gl::LINE_SMOOTH => &mut e.line_smooth,
            gl::LINE_STIPPLE => &mut e.line_stipple,
            gl::POINT_SMOOTH => &mut e.point_smooth,
            gl::POINT_SPRITE => &mut e.point_sprite,
            gl::POLYGON_SMOOTH => &mut e.polygon_smooth,
            gl::POLYGON_STIPPLE => &mut e.polygon_stipple,
            gl::AUTO_NORMAL => &mut e.auto_normal,
            gl::MULTISAMPLE => &mut e.multisample,
            gl::SAMPLE_ALPHA_TO_COVERAGE => &mut e.sample_alpha_to_coverage,
            gl::SAMPLE_ALPHA_TO_ONE => &mut e.sample_alpha_to_one,
            gl::SAMPLE_COVERAGE => &mut e.sample_coverage,
            gl::VERTEX_PROGRAM_POINT_SIZE => &mut e.vertex_program_point_size,
            gl::VERTEX_PROGRAM_TWO_SIDE => &mut e.vertex_program_two_side,
            gl::TEXTURE_1D => &mut e.texture_1d[unit],
            gl::TEXTURE_2D => &mut e.texture_2d[unit],
            gl::TEXTURE_3D => &mut e.texture_3d[unit],
            gl::TEXTURE_CUBE_MAP => &mut e.texture_cube_map[unit],
            gl::TEXTURE_GEN_S => &mut e.texture_gen[unit][0],
            gl::TEXTURE_GEN_T => &mut e.texture_gen[unit][1],
            gl::TEXTURE_GEN_R => &mut e.texture_gen[unit][2],
            gl::TEXTURE_GEN_Q => &mut e.texture_gen[unit][3],
            gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4 => &mut e.map1[(cap - gl::MAP1_COLOR_4) as usize],
            gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4 => &mut e.map2[(cap - gl::MAP2_COLOR_4) as usize],
            _ => return None,
        })
    }
}

// Vertex arrays and buffer objects (context/arrays.rs)
mod arrays;

// glReadPixels and to_image (context/readback.rs)
mod readback;

// Display lists and attribute stacks (context/lists.rs, context/attrib.rs)
mod attrib;
mod lists;
pub use attrib::MAX_ATTRIB_STACK_DEPTH;
pub use lists::MAX_LIST_NESTING;
// The GL backend reads CallLists arrays as the front end does.
#[cfg(feature = "gl")]
pub(crate) use lists::{name_offset, name_size};
// Fog, AlphaFunc, Stencil*, Blend*, LogicOp (context/fragment.rs)
mod fragment;
// Objects, images, parameters (context/texture.rs, context/texture_params.rs); the GL backend
// shares TexImage2D's argument checks.
pub(crate) mod texture;
mod texture_coords;
mod texture_params;
