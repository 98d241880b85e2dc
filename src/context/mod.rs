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

mod buffers;
mod control;
mod dispatch;
mod eval;
mod fbo;
#[cfg(feature = "gl")]
pub(crate) use fbo::renderbuffer_base;
mod framebuffer;
mod lighting;
mod raster;
mod select;
mod share;
pub use crate::cpu::DrawStats;
pub use share::ShareGroup;
#[cfg(test)]
mod tests;
mod vertex;

use crate::call::Call;
use crate::cpu::Renderer;
use crate::gl;
use crate::state::{ContextConfig, State, MAX_VIEWPORT_DIM};
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
    /// For each buffer mapped while recording: its store at MapBuffer, so that UnmapBuffer can
    /// record the bytes written through the mapping (context/arrays.rs).
    pub(crate) map_snapshots: std::collections::BTreeMap<u32, Vec<u8>>,
    /// Query objects and the active query (context/query.rs).
    pub(crate) queries: query::Queries,
    /// The share group this context's lists, textures and buffers live in, if any
    /// (context/share.rs).
    pub(crate) share: Option<Box<share::Link>>,
    /// Framebuffer and renderbuffer objects, and the window's framebuffer while one is bound
    /// (context/fbo.rs).
    pub(crate) fbos: fbo::Fbos,
}

impl Context {
    /// A context with a `width` x `height` framebuffer (RGBA8 colour, 24-bit depth, 8-bit stencil)
    /// in GL's initial state. Each side must be between 1 and 16384 (else
    /// [`Error::InvalidSize`]); [`Error::OutOfMemory`] when the framebuffer cannot be allocated.
    pub fn new(width: u32, height: u32) -> Result<Context, Error> {
        Self::with_config(width, height, ContextConfig::default())
    }

    /// A context with a `width` x `height` framebuffer holding the buffers `config` names
    /// (front and back colour buffers, depth, stencil, accumulation), in GL's initial state:
    /// DRAW_BUFFER and READ_BUFFER are BACK when double-buffered, FRONT otherwise.
    /// [`Context::new`] is `with_config(width, height, ContextConfig::default())`: one RGBA8
    /// colour buffer, 24-bit depth, 8-bit stencil, no accumulation buffer. Errors as
    /// [`Context::new`].
    pub fn with_config(width: u32, height: u32, config: ContextConfig) -> Result<Context, Error> {
        if width == 0 || height == 0 || width > MAX_VIEWPORT_DIM || height > MAX_VIEWPORT_DIM {
            return Err(Error::InvalidSize { width, height });
        }
        // The pool the CPU backend draws on starts here, where failing to start threads can be
        // an `Err`; started lazily at the first draw it could only be a panic.
        crate::cpu::start_threads().map_err(Error::Threads)?;
        // The framebuffer is the one allocation sized by the caller here: tried, so that a size
        // the machine cannot hold is an `Err`, not an abort.
        let renderer =
            Renderer::try_new(width, height, config).ok_or(Error::OutOfMemory { width, height })?;
        Ok(Context {
            state: State::with_config(width, height, config),
            error: gl::NO_ERROR,
            begin_mode: None,
            recording: None,
            capturing: false,
            renderer,
            lists: Default::default(),
            attrib: Default::default(),
            map_snapshots: Default::default(),
            queries: Default::default(),
            share: None,
            fbos: Default::default(),
        })
    }

    /// Returns the context to GL's initial state — as `Context::new` would make it — but keeps
    /// the framebuffer (its contents and memory) and the renderer's buffers, so a program that
    /// draws many independent frames (a benchmark, an animation re-running its `init`) does not
    /// pay for allocating them again. Vertices batched but not yet drawn are discarded, as is any
    /// recording, display list and attribute stack (in a share group: this context's copies;
    /// the group's objects stay, and the context sees them again). Not a GL entry point: never
    /// recorded.
    pub fn reset(&mut self) {
        self.renderer.discard_batch();
        self.fbo_reset();
        let (w, h) = self.size();
        self.renderer.sink = Default::default();
        self.state = State::with_config(w, h, self.state.config);
        self.error = gl::NO_ERROR;
        self.begin_mode = None;
        self.recording = None;
        self.lists = std::mem::take(&mut self.lists).emptied();
        self.sync_capturing();
        self.attrib = Default::default();
        self.map_snapshots = Default::default();
        self.drop_queries();
        // A context of a share group sees the group's objects again, as a new one would.
        self.resync_share();
    }

    /// The state, read-only: what the `get_*` queries report, as plain data.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.state.width, self.state.height)
    }

    /// Raises `code` as a command would: it becomes the sticky error unless an earlier one is
    /// still unread. Not a GL entry point: for layers that embed a context and meet an error
    /// of their own (the C ABI raises OUT_OF_MEMORY when a command could not complete).
    pub fn raise_error(&mut self, code: u32) {
        self.error(code);
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

    /// Diagnostic: the draws made so far and the calling thread's time in them (for
    /// `fixedgl bench --stages`). Not a GL entry point.
    pub fn draw_stats(&self) -> DrawStats {
        self.renderer.stats
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
        // In a share group: the objects other contexts changed since (context/share.rs).
        self.pull_objects();
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

    /// `glBegin`. Inlined (into replay loops): the usual Begin, valid, drawing into the window's
    /// framebuffer (never incomplete) and in no share group (nothing to pull), tests four fields
    /// and opens the primitive; any other goes through `begin_checked`'s checks. A lit mesh
    /// of one strip per cell gives a Begin every four vertices, and its call cost about 15
    /// instructions of the ~40 (gauss-smooth-400).
    #[inline(always)]
    pub fn begin(&mut self, mode: u32) {
        record!(self, Call::Begin(mode));
        if self.begin_is_usual(mode) {
            self.open_primitive(mode);
        } else {
            self.begin_checked(mode);
        }
    }

    /// Whether Begin(`mode`) takes the usual path: valid, drawing into the window's
    /// framebuffer, in no share group.
    #[inline(always)]
    fn begin_is_usual(&self, mode: u32) -> bool {
        self.begin_mode.is_none()
            && mode <= gl::POLYGON
            && self.fbos.bound_fb == 0
            && self.share.is_none()
    }

    /// [`Context::begin`]'s errors, framebuffer test and share group's objects.
    #[inline(never)]
    fn begin_checked(&mut self, mode: u32) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if mode > gl::POLYGON {
            return self.error(gl::INVALID_ENUM);
        }
        if self.framebuffer_incomplete() {
            return;
        }
        self.pull_objects();
        self.open_primitive(mode);
    }

    /// Begin's effect, once it passed its checks.
    #[inline(always)]
    fn open_primitive(&mut self, mode: u32) {
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
        // The client arrays (VERTEX_ARRAY, ...) are no Enable caps in GL 2.1 (INVALID_ENUM), but
        // Mesa's compatibility context, the reference, takes them as Enable/DisableClientState
        // of the client active texture unit, and programs written against it rely on that
        // (piglit's vertex-buffer-offsets).
        if self.state.arrays.enabled(cap, 0).is_some() {
            let unit = self.state.client_active_texture;
            if let Err(code) = self.state.arrays.enable_client_state(cap, on, unit) {
                self.error(code);
            }
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
    /// The calls an immediate-mode mesh is made of (Begin, End, Normal3f, Vertex3f and their
    /// vector forms, TexCoord2f/2fv: all but a handful of a recorded surface or of a GLUT
    /// mesh) are dispatched first, by a short match inlined into replay loops (compiled with
    /// AVX2 there); every other call goes through `execute_any`, which matches every variant
    /// (so a new entry point cannot be forgotten there). A vector form runs as its scalar form
    /// when nothing records (the same conversion and the same state change; only what a
    /// recording stores differs), so the vertex path is inlined once.
    #[inline(always)]
    pub fn execute(&mut self, call: &Call) {
        match *call {
            Call::Vertex3f(a, b, c) => self.vertex3f(a, b, c),
            Call::Vertex3fv([a, b, c]) if !self.capturing => self.vertex3f(a, b, c),
            Call::Normal3f(a, b, c) => self.normal3f(a, b, c),
            Call::Normal3fv([a, b, c]) if !self.capturing => self.normal3f(a, b, c),
            Call::TexCoord2f(s, t) => self.tex_coord2f(s, t),
            Call::TexCoord2fv([s, t]) if !self.capturing => self.tex_coord2f(s, t),
            Call::Begin(a) => self.begin(a),
            Call::End => self.end(),
            _ => self.execute_any(call),
        }
    }

    /// Executes every call of `calls` in order. The loop, with the hot calls `execute` inlines
    /// (the immediate-mode vertex path and its batching), is compiled for the baseline or with
    /// AVX2 by `Route::best`: the same code, so the same calls and pixels
    /// (`both_replay_routes_draw_the_same_image` compares them).
    pub fn replay(&mut self, calls: &[Call]) {
        self.replay_by(calls, crate::cpu::vertex::Route::best());
    }

    /// [`Context::replay`] by `route`.
    pub(crate) fn replay_by(&mut self, calls: &[Call], route: crate::cpu::vertex::Route) {
        #[cfg(target_arch = "x86_64")]
        if route == crate::cpu::vertex::Route::Avx2 {
            // SAFETY: `Route::Avx2` is chosen only where the CPU has AVX2.
            unsafe { self.replay_avx2(calls) };
            return;
        }
        let _ = route;
        // Lists called from `calls` follow the route too (for the routes test).
        self.lists.baseline = true;
        self.replay_body(calls);
        self.lists.baseline = false;
    }

    /// [`Context::replay_body`] compiled with AVX2.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn replay_avx2(&mut self, calls: &[Call]) {
        self.replay_body(calls);
    }

    #[inline(always)]
    fn replay_body(&mut self, calls: &[Call]) {
        for call in calls {
            self.execute(call);
        }
    }

    /// A recorded `GenTextures(n)`: the names land in a buffer of room for `n` (at most
    /// [`texture::MAX_GEN_TEXTURES`]: more is INVALID_VALUE, raised by `gen_textures`).
    fn replay_gen_textures(&mut self, n: i32) {
        let mut names = vec![0; n.clamp(0, texture::MAX_GEN_TEXTURES) as usize];
        self.gen_textures(n, &mut names);
    }

    /// A recorded `GenBuffers(n, names)`: room for as many names as the recorded call got.
    fn replay_gen_buffers(&mut self, n: i32, names: &[u32]) {
        let mut out = vec![0; names.len()];
        self.gen_buffers(n, &mut out);
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

// Vertex arrays and buffer objects (context/arrays.rs); the GL backend writes a recorded
// UnmapBuffer's bytes as the front end does.
mod arrays;
#[cfg(feature = "gl")]
pub(crate) use arrays::write_into;

// glReadPixels and to_image (context/readback.rs)
mod readback;

// Raster position, rectangles, pixel rectangles, bitmaps (context/rasterpos.rs, context/pixels.rs)
mod pixels;
mod rasterpos;
// Line and polygon stipple (context/stipple.rs)
pub(crate) mod stipple;

// Occlusion queries (context/query.rs)
mod query;
pub use eval::MAX_EVAL_MESH_VERTICES;
pub use query::QUERY_COUNTER_BITS;

// Display lists and attribute stacks (context/lists.rs, context/attrib.rs)
mod attrib;
mod lists;
pub use attrib::MAX_ATTRIB_STACK_DEPTH;
pub use lists::MAX_LIST_NESTING;
// The GL backend reads CallLists arrays as the front end does.
#[cfg(feature = "gl")]
pub(crate) use lists::{name_offset, name_size, proxy_image};
// Fog, AlphaFunc, Stencil*, Blend*, LogicOp (context/fragment.rs)
mod fragment;
// Objects, images, parameters (context/texture.rs, context/texture_params.rs); the GL backend
// shares TexImage2D's argument checks.
pub(crate) mod texture;
// CompressedTexImage*, CompressedTexSubImage*, GetCompressedTexImage (context/compressed.rs).
pub(crate) mod compressed;
mod texture_coords;
mod texture_params;
mod texture_residency;
