//! The CPU backend: turns batches of vertices into pixels in the context's framebuffer.
//!
//! The front end hands vertices to `Renderer` as they arrive (`begin`/`vertex`/`end`) and calls
//! `flush` with the state whenever it is about to change state that affects rendering, or before
//! anything reads the framebuffer. Batching across many Begin/End pairs is what lets the vertex
//! stage and the tile rasteriser run in parallel over large batches (Mesa's FLUSH_VERTICES idea).
//!
//! A flush runs GL 2.1's pipeline in stages, each in its own module:
//! [`batch`] → [`vertex`] (§2.11, §2.14) → [`assembly`] (§2.6) → [`clip`] (§2.12) →
//! [`setup`] (§2.11.1, §3.5–3.6) → [`raster`] (§3.4–3.6) → [`fragment`] (§3.9, §4.1) →
//! [`framebuffer`] (§4.2).
//!
//! Design decision: parallelism without locks and without reordering. The vertex stage runs in
//! parallel chunks; the primitives are then taken in pieces of about 32k vertices, each piece
//! split in order across setup workers that bin their primitives per 64x64 tile; tiles are
//! rasterised in parallel, each owning its pixels, visiting worker 0's bin, then worker 1's, ...,
//! so every tile sees the primitives in submission order (depth ties and, later, blending
//! depend on it).
//!
//! Rasterisation waits for the framebuffer to be needed. Each flush is set up and binned into
//! a scene ([`Scene`]) with its own fragment-stage state, and the scene is rasterised in one
//! pass over the tiles (each visiting the flushes in call order) when something reads or
//! changes the framebuffer, or when the scene is full, as llvmpipe's scene bins a frame's
//! draws with a pointer to each one's state. A frame that changes a matrix between objects
//! then makes one pass and one hand-off to the pool instead of one per object, and the pool's
//! threads share the whole frame's tiles.
//!
//! The front end and the drawing overlap. A batch is drawn at End once it holds 32k vertices
//! (`flush_if_large`), so memory stays bounded. The calling thread runs that batch's vertex
//! stage itself when the pool is still drawing the previous batch, or leaves it to the pool
//! when the pool has finished (so that neither idles while the other is the bottleneck), then
//! hands the batch (setup and rasterisation, and the vertex stage if left) to the pool with a
//! copy of the state (texture images are shared through
//! `Arc`, not copied: a change to one still in use copies it) and goes on filling the next
//! batch. At most one draw is in flight: the next `flush_if_large`, any other flush (a state
//! change, Clear, a read) and every framebuffer access wait for it first, so the draws happen
//! one after the other in call order and the pixels are exactly those of drawing in place
//! (tested in `tests/overlap.rs` under this module). A caller running on the pool itself draws
//! in place. A flush at a state change is set up in place (into the scene): handing it to the
//! pool too was measured slower on the fragment-heavy scenes (docs/conformance.md, Speed).
//!
//! Naming: the state (`crate::state`, `crate::texture`) is named after GL's state blocks
//! (`Fog`, `Blend`, `TexGen`, `Combine`); what this module derives from it when a batch is
//! drawn never reuses those names. The per-flush form of one state block, ready for the
//! per-vertex or per-fragment code, ends in `Eval` (`fragops::FogEval`, `fragops::BlendEval`,
//! `texgen::TexGenEval`); constants gathered for a whole stage end in `Ctx` (`SetupCtx`,
//! `FragCtx`); other derived values are named for what they do (`fragops::ColorWrite`, what the
//! colour write does; `setup::PrimKind`, what a rasterised primitive is).

pub mod aa;
pub mod accum;
pub mod assembly;
pub mod batch;
pub mod clip;
pub mod feedback;
pub mod fragment;
pub mod fragops;
pub mod framebuffer;
pub mod lanes;
pub mod libm8;
mod line;
pub mod oplanes;
pub mod pixels;
mod polygon;
mod pool;
pub mod raster;
pub mod setup;
#[cfg(test)]
pub(crate) mod testgen;
pub mod texgen;
pub mod texture;
pub mod vertex;

#[cfg(test)]
mod tests;

pub use pool::start_pool;
pub(crate) use pool::start_threads;

use glam::Vec4;
use rayon::prelude::*;
use std::sync::mpsc::{self, Receiver};
use std::sync::Mutex;

use crate::state::{ContextConfig, Current, Material, State, MAX_TEXTURE_UNITS};
use assembly::Asm;
use batch::Batch;
use fragment::{FragCtx, TileBufs};
use framebuffer::{Framebuffer, Targets, TILE, TILE_PIXELS};
use setup::{SetupCtx, Worker};
use vertex::{Layout, Lighting};

/// Vertex indices below which setup stays on one thread.
const PARALLEL_SETUP: usize = 4096;
/// The same for a batch with texture coordinates, whose set-up costs more a triangle.
const PARALLEL_SETUP_TEXTURED: usize = 1024;

/// The CPU renderer: the vertex batch being filled, the framebuffer with the scratch space the
/// drawing reuses, and the draw running in the background, if any.
#[derive(Debug)]
pub struct Renderer {
    /// The framebuffer and scratch buffers; `None` while a background draw owns them.
    core: Option<Box<Core>>,
    /// Framebuffer size (kept here so `size` never waits for a background draw).
    size: (u32, u32),
    /// Tiles across and down the framebuffer.
    tiles: (usize, usize),
    batch: Batch,
    /// The vertex stage's output for `batch`, filled when it is drawn.
    verts: Processed,
    /// A drawn batch and its vertex output kept for their memory: the next background draw
    /// swaps them in.
    spare: Option<(Batch, Processed)>,
    /// The background draw of the previous batch: hands back the core, the batch and its
    /// vertex output.
    pending: Option<Mutex<Receiver<Drawn>>>,
    /// Selection and feedback (GL 2.1 §5.2, §5.3): where batches go in SELECT and FEEDBACK
    /// render modes.
    pub(crate) sink: feedback::Sink,
    /// Diagnostic: fragments add 1 to the red byte instead of writing colour.
    pub(crate) count_coverage: bool,
    /// The count of the active occlusion query, if any: draws count the fragments that pass
    /// the depth test (and every test before it) into its `Core::counts` entry. None, no draw
    /// counts anything.
    counting: Option<u64>,
    /// The number the next occlusion query's count gets (`start_counting_samples`).
    next_count: u64,
    /// Diagnostic: batches drawn in the background so far.
    pub(crate) background_draws: u64,
    /// Diagnostic: draws and the calling thread's time in them (`Context::draw_stats`).
    pub(crate) stats: DrawStats,
    /// Test hook: the next background draw panics (to test that the panic reaches the caller).
    #[cfg(test)]
    pub(crate) panic_in_background: bool,
    /// Test hook: where the vertex stage of a batch handed to the pool runs (`Some(true)`: in
    /// the pool's job, `Some(false)`: on the calling thread), instead of the balancing rule.
    #[cfg(test)]
    pub(crate) vertex_stage_on_pool: Option<bool>,
    /// Test hook: every bitmap is drawn in place (`draw_pixel_rect`), none binned into the
    /// scene.
    #[cfg(test)]
    pub(crate) bitmaps_in_place: bool,
}

/// Where a context's calling thread spends its drawing time, for `fixedgl bench --stages`
/// (`Context::draw_stats`): counts and nanoseconds since the context was made. Two clock reads
/// a draw; nothing here changes what is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawStats {
    /// Batches set up in place: every flush at a state change, and at 32k vertices by a
    /// caller running on the pool itself.
    pub draws: u64,
    /// Their time: vertex stage and setup, and rasterisation when the flush fills the scene
    /// (including the pool's part); the scene is otherwise rasterised when the framebuffer is
    /// read.
    pub draw_ns: u64,
    /// Batches handed to the pool to be set up (and rasterised, with the scene) in the
    /// background: a caller off the pool's flush at 32k vertices (`flush_if_large`).
    pub handoffs: u64,
    /// Their time on the calling thread: the hand-off, and the vertex stage when it ran there
    /// (the pool runs it when it has already finished the previous batch).
    pub handoff_ns: u64,
    /// Time the calling thread waited for a background draw to end.
    pub wait_ns: u64,
    /// Rasterisation passes over the scene's tiles (see `Scene`): at reads and changes of the
    /// framebuffer, changes of the colour buffers drawn, changes of a texture the scene
    /// samples, and full scenes.
    pub passes: u64,
}

/// Nanoseconds since `t`, saturated.
fn ns_since(t: std::time::Instant) -> u64 {
    u64::try_from(t.elapsed().as_nanos()).unwrap_or(u64::MAX)
}

/// What a background draw hands back: the core, the drawn batch and its vertex output, always
/// (the job catches a panic of the draw so that nothing it owned is lost), and the panic's
/// payload if the draw panicked, to be resumed on the caller's thread by `wait`.
type Drawn = (
    Box<Core>,
    Batch,
    Processed,
    Option<Box<dyn std::any::Any + Send>>,
);

/// What drawing a batch mutates: the framebuffer, the flushes set up and not yet rasterised,
/// and the setup scratch space reused across draws.
#[derive(Debug)]
struct Core {
    fb: Framebuffer,
    asm: Vec<Asm>,
    scene: Scene,
    /// Occlusion queries' counts (GL 2.1 §4.1.7's SAMPLES_PASSED) by number, from
    /// `start_counting_samples` until `take_samples` or `forget_samples`: a count is complete
    /// once the flushes it counts are rasterised, which waits, like any other draw, for the
    /// scene to be needed (`Renderer::take_samples` rasterises it).
    counts: Vec<(u64, u64)>,
    /// Rasterisation passes so far (`DrawStats::passes`).
    passes: u64,
}

/// Flushes set up and binned but not yet rasterised, as llvmpipe's scene holds a frame's
/// binned commands with a pointer to each one's state: a state change between two draws
/// (a matrix, a fog mode, a bound texture) no longer makes its own pass over the tiles with
/// its own hand-off to the pool. Plain bitmaps (`Renderer::bitmap`) join it too, so that the
/// glyphs of a text overlay neither rasterise the geometry before them nor draw one by one
/// on the calling thread. The scene is rasterised in one pass, every tile visiting the
/// parts in call order (so the pixels are those of drawing each flush in place), when anything
/// reads or changes the framebuffer (`Renderer::core`), when a flush writes other colour
/// buffers, or when it holds `SCENE_VERTICES` vertices or `SCENE_PARTS` parts (so its memory
/// stays bounded).
#[derive(Debug, Default)]
struct Scene {
    /// Each flush's fragment-stage state, in call order.
    frags: Vec<Frag>,
    /// The set-up pieces and binned bitmaps in call order.
    parts: Vec<Part>,
    /// Setup workers: the first `used` hold the parts' primitives; the others are memory kept
    /// for the next parts.
    workers: Vec<Worker>,
    used: usize,
    /// Vertices set up into the parts.
    vertices: usize,
    /// Bytes the binned bitmaps hold.
    bytes: usize,
    /// The colour buffers every part writes.
    targets: Targets,
}

/// One entry of the scene, in call order.
#[derive(Debug)]
enum Part {
    /// A piece of a flush: its `Scene::frags` entry and `Scene::workers` range.
    Prims {
        frag: usize,
        workers: std::ops::Range<usize>,
    },
    /// A plain bitmap (`Renderer::bitmap`).
    Bits(pixels::BinnedBits),
}

/// Vertices in the scene's parts at which it is rasterised.
const SCENE_VERTICES: usize = 1 << 15;

/// Parts at which the scene is rasterised.
const SCENE_PARTS: usize = 1024;

/// Bytes of binned bitmaps at which the scene is rasterised.
const SCENE_BYTES: usize = 1 << 20;

/// Workers kept past this many keep only a small part of their memory after the scene is
/// rasterised (a draw of several pieces late in a scene uses workers beyond it).
const KEPT_WORKERS: usize = 32;

/// A flush's fragment-stage state, owned (what [`FragCtx`] borrows).
#[derive(Debug)]
struct Frag {
    depth_test: bool,
    depth_func: u32,
    depth_mask: bool,
    color_mask: [bool; 4],
    color_sum: bool,
    rl: setup::RLayout,
    lighting: Option<Lighting>,
    mats: Vec<[Material; 2]>,
    count: bool,
    /// The occlusion query counting this flush's fragments (`Core::counts`).
    samples: Option<u64>,
    stipple: Option<[u32; 32]>,
    ops: Option<fragops::Ops>,
    samplers: [Option<texture::Sampler>; MAX_TEXTURE_UNITS],
}

impl Frag {
    /// Some unit samples a texture.
    fn samples_textures(&self) -> bool {
        self.samplers.iter().any(Option::is_some)
    }

    /// The fragment stage's view of it.
    fn ctx(&self) -> FragCtx<'_> {
        let tex = fragment::tex_units(&self.samplers, &self.rl);
        FragCtx {
            depth_test: self.depth_test,
            depth_func: self.depth_func,
            depth_mask: self.depth_mask,
            color_mask: self.color_mask,
            color_sum: self.color_sum,
            rl: self.rl,
            lighting: self.lighting.as_ref(),
            mats: &self.mats,
            count: self.count,
            samples: self.samples.is_some(),
            stipple: self.stipple,
            ops: self.ops,
            crossbar: fragment::crossbar(&tex),
            tex,
        }
    }
}

/// The vertex stage's output for a batch: `layout.stride` floats per vertex, and each vertex's
/// clip code and window coordinates.
#[derive(Debug, Default)]
struct Processed {
    vout: Vec<f32>,
    wins: Vec<setup::Win>,
}

/// The per-draw constants of a batch's state, and its processed vertices' layout.
struct Plan {
    layout: Layout,
    ctx: SetupCtx,
}

impl Plan {
    /// Runs the vertex stage (§2.11, §2.14) of `batch` under `state` into `out`; `parallel`
    /// splits it across the pool.
    fn process(
        state: &State,
        tiles: (usize, usize),
        batch: &Batch,
        out: &mut Processed,
        parallel: bool,
    ) -> Self {
        let layout = Layout::for_state(state);
        let rect = framebuffer::scissor_rect(state);
        let mut ctx = SetupCtx::new(state, layout, rect, tiles);
        vertex::process(
            state,
            batch,
            &layout,
            &ctx,
            &mut out.vout,
            &mut out.wins,
            parallel,
        );
        // llvmpipe splits quads along 1–3 when it shades FLAT or when any vertex of the draw
        // needs clipping (its draw module then takes the clipping path, which decomposes quads
        // provoking-vertex-last), and along 0–2 otherwise; measured in
        // tests/implementation_choices.rs. A flush is our counterpart of its draw.
        ctx.quads_split_last |= out.wins.iter().any(|w| w.code != 0);
        Plan { layout, ctx }
    }
}

impl Renderer {
    /// A renderer with a cleared `width` x `height` framebuffer (sizes validated by the caller).
    /// Aborts if the framebuffer cannot be allocated, as `vec!` does; see [`Renderer::try_new`].
    /// For tests: the library builds renderers with `try_new`.
    #[cfg(test)]
    pub fn new(width: u32, height: u32) -> Self {
        Self::with_core(Box::new(Core::new(width, height)), width, height)
    }

    /// [`Renderer::new`], or `None` when the framebuffer cannot be allocated (what
    /// `Context::new` reports as [`crate::Error::OutOfMemory`]).
    /// The framebuffer has the buffers `config` names.
    pub fn try_new(width: u32, height: u32, config: ContextConfig) -> Option<Self> {
        let core = Box::new(Core::try_new(width, height, config)?);
        Some(Self::with_core(core, width, height))
    }

    /// Resizes the framebuffer to `width` x `height` (drawing what is batched first unless
    /// `open`: a primitive is open, its vertices are then drawn into the new framebuffer),
    /// keeping what fits (`Framebuffer::resized`); false, with nothing changed, when the new
    /// buffers cannot be allocated.
    pub fn resize(&mut self, state: &State, width: u32, height: u32, open: bool) -> bool {
        if !open {
            self.flush(state);
        }
        let Some(fb) = self.core().fb.resized(width, height) else {
            return false;
        };
        self.tiles = fb.tiles();
        self.size = (width, height);
        self.core().fb = fb;
        true
    }

    /// Draws what is batched (under `state`), then makes `fb` the framebuffer drawing and
    /// reading use and returns the one it replaces (a framebuffer object bound or unbound,
    /// context/fbo.rs).
    pub fn swap_framebuffer(&mut self, state: &State, fb: Framebuffer) -> Framebuffer {
        self.flush(state);
        self.tiles = fb.tiles();
        self.size = fb.size();
        std::mem::replace(&mut self.core().fb, fb)
    }

    /// The framebuffer, to modify (Accum, SwapBuffers), once everything drawn so far is in it.
    pub fn framebuffer_mut(&mut self) -> &mut Framebuffer {
        let fb = &mut self.core().fb;
        fb.materialize_all();
        fb
    }

    fn with_core(core: Box<Core>, width: u32, height: u32) -> Self {
        Self {
            tiles: core.fb.tiles(),
            core: Some(core),
            size: (width, height),
            batch: Batch::default(),
            verts: Processed::default(),
            spare: None,
            pending: None,
            sink: feedback::Sink::default(),
            count_coverage: false,
            counting: None,
            next_count: 0,
            background_draws: 0,
            stats: DrawStats::default(),
            #[cfg(test)]
            panic_in_background: false,
            #[cfg(test)]
            vertex_stage_on_pool: None,
            #[cfg(test)]
            bitmaps_in_place: false,
        }
    }

    /// `Begin(mode)`: opens a primitive in the batch (mode already validated).
    pub fn begin(&mut self, mode: u32) {
        self.batch.begin(mode);
    }

    /// The materials in effect at `Begin`: what the primitive's vertices use until a `Material`
    /// call inside the pair ([`Renderer::materials_changed`]) changes them.
    pub fn begin_materials(&mut self, materials: &[Material; 2]) {
        self.batch.note_materials(materials);
    }

    /// A vertex with the current attributes.
    #[inline]
    pub fn vertex(&mut self, position: Vec4, current: &Current) {
        self.batch.vertex(position, current);
    }

    /// A vertex with attributes the caller computed ([`Batch::vertex_computed`]).
    #[inline]
    pub fn vertex_computed(&mut self, position: Vec4, current: &Current) {
        self.batch.vertex_computed(position, current);
    }

    /// `End`.
    pub fn end(&mut self) {
        self.batch.end();
    }

    /// Starts drawing the batch if it holds many vertices: called after `End`, when the state
    /// the batch was specified under is still current. The draw runs in the background on the
    /// thread pool while the front end fills the next batch (see the module docs); it keeps
    /// the batch (and its memory) bounded and cache-warm without changing the result.
    #[inline(always)]
    pub fn flush_if_large(&mut self, state: &State) {
        // The test alone inline (it runs at every End); the draw out of line.
        if self.batch.idx.len() >= FLUSH_AT {
            self.flush_large(state);
        }
    }

    /// [`Renderer::flush_if_large`]'s draw of a large batch.
    #[inline(never)]
    fn flush_large(&mut self, state: &State) {
        if state.render_mode != crate::gl::RENDER {
            return self.flush(state);
        }
        // A caller running on the pool itself draws in place: blocking one of the pool's
        // threads on a job queued behind it could wait forever.
        if rayon::current_thread_index().is_some() {
            return self.flush(state);
        }
        // The two cores balanced: while the previous batch is still being drawn on the pool,
        // the vertex stage runs here, on the calling thread, and the pool then only sets up and
        // rasterises; when the pool has already finished (it idles while the front end fills
        // the batch), the vertex stage goes to the pool with the rest. The vertex stage's
        // output is the same bits on either thread (and in chunks or not).
        let t0 = std::time::Instant::now();
        let on_pool = self.background_done();
        #[cfg(test)]
        let on_pool = self.vertex_stage_on_pool.unwrap_or(on_pool);
        let plan = if on_pool {
            None
        } else {
            Some(Plan::process(
                state,
                self.tiles,
                &self.batch,
                &mut self.verts,
                false,
            ))
        };
        self.draw_in_background(state, plan);
        self.stats.handoffs += 1;
        self.stats.handoff_ns = self.stats.handoff_ns.saturating_add(ns_since(t0));
    }

    /// Hands the batch to the pool to be set up and rasterised with a copy of `state`, once
    /// the draw before it has handed back the core; `plan` describes its vertex stage, already
    /// run into `self.verts`, or is `None` when the job is to run the vertex stage first (split
    /// across the pool). The caller goes on with an empty batch.
    fn draw_in_background(&mut self, state: &State, plan: Option<Plan>) {
        self.wait_for_pool();
        // The calling thread goes on beside the pool: it keeps its CPU, the pool the others.
        pool::workers_beside_caller();
        let (mut next, next_verts) = self.spare.take().unwrap_or_default();
        next.clear();
        let batch = std::mem::replace(&mut self.batch, next);
        let mut verts = std::mem::replace(&mut self.verts, next_verts);
        let mut core = self.take_core();
        // The state is copied (texture images are shared, not copied): the front end goes on
        // changing its own.
        let state = Box::new(state.clone());
        let count = self.count_coverage;
        let samples = self.counting;
        let tiles = self.tiles;
        let (tx, rx) = mpsc::channel();
        self.pending = Some(Mutex::new(rx));
        self.background_draws += 1;
        #[cfg(test)]
        let fail = std::mem::take(&mut self.panic_in_background);
        rayon::spawn(move || {
            // A panic must not abort the process from the pool, nor be lost: it is caught
            // here and handed back with everything the job owned, and `wait` resumes it on
            // the caller's thread, as if the draw had run there.
            let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                #[cfg(test)]
                assert!(!fail, "test hook: background draw panics");
                let plan = match plan {
                    Some(plan) => plan,
                    None => Plan::process(&state, tiles, &batch, &mut verts, true),
                };
                core.draw(&state, &batch, &verts, plan, count, samples);
            }))
            .err();
            // The copy of the state goes first: the caller may change a texture as soon as it
            // has the core back, and a texture still shared would be copied (`Arc::make_mut`).
            drop(state);
            // The receiver lives until `wait` takes this; a send cannot fail before that.
            let _ = tx.send((core, batch, verts, panicked));
        });
    }

    /// Whether no background draw is running: a finished one is taken back (as `wait` does),
    /// without blocking on one still running.
    fn background_done(&mut self) -> bool {
        let Some(rx) = self.pending.as_mut() else {
            return true;
        };
        // See `wait` on the mutex.
        let rx = rx.get_mut().unwrap_or_else(|e| e.into_inner());
        match rx.try_recv() {
            Err(mpsc::TryRecvError::Empty) => false,
            received => {
                self.pending = None;
                self.take_back(received.map_err(|_| mpsc::RecvError));
                true
            }
        }
    }

    /// Waits for the background draw, if any, and takes back what it owned. A panic of that
    /// draw is resumed here, on the caller's thread (`std::panic::resume_unwind`): the frame is
    /// then wrong, and the caller must learn it, exactly as when a draw in place panics. The
    /// framebuffer (drawn up to the panic) is kept, never replaced by a cleared one.
    ///
    /// The caller is about to wait for the pool or use it for a job of its own: the pool's
    /// threads are pinned (see `pool`).
    fn wait(&mut self) {
        self.wait_for_pool();
        pool::pin_workers();
    }

    /// `wait`, leaving the pool's threads as they are: for a background draw.
    fn wait_for_pool(&mut self) {
        let Some(rx) = self.pending.take() else {
            return;
        };
        // The mutex only makes the receiver Sync; nothing ever locks it, so it is never
        // poisoned, and its receiver is usable either way.
        let rx = rx.into_inner().unwrap_or_else(|e| e.into_inner());
        let t0 = std::time::Instant::now();
        let received = rx.recv();
        self.stats.wait_ns = self.stats.wait_ns.saturating_add(ns_since(t0));
        self.take_back(received);
    }

    /// What a background draw handed back, taken back (see `wait`).
    fn take_back(&mut self, received: Result<Drawn, mpsc::RecvError>) {
        match received {
            Ok((core, batch, verts, panicked)) => {
                self.core = Some(core);
                self.spare = Some((batch, verts));
                if let Some(payload) = panicked {
                    std::panic::resume_unwind(payload);
                }
            }
            // The job sends whatever happens in the draw; only a job that never ran (the pool
            // torn down, which rayon's global pool never is) could end here. The framebuffer
            // is gone with it: say so rather than draw on a blank one.
            Err(_) => {
                panic!("fixedgl: a background draw ended without handing back the framebuffer")
            }
        }
    }

    /// The core, taken out (for a background draw). Only one draw holds it at a time: every
    /// path that takes it waits first.
    fn take_core(&mut self) -> Box<Core> {
        self.wait_for_pool();
        match self.core.take() {
            Some(core) => core,
            None => Self::lost(),
        }
    }

    /// After `wait` the core is back: it is `None` only if a background draw's job vanished,
    /// which `wait` has already reported by panicking.
    #[cold]
    fn lost() -> ! {
        panic!("fixedgl: the framebuffer was lost with a background draw that vanished")
    }

    /// Rasterises the scene if one of its flushes samples a texture: called before texels
    /// change in place (TexSubImage), so that the change does not copy a level the scene
    /// still holds (`Arc::make_mut` copies a shared one; the pixels are the same either way).
    /// A parameter change or a new image needs no pass: the object is copied with its levels
    /// shared, and a level replaced is not copied.
    pub fn release_textures(&mut self) {
        self.wait();
        if let Some(core) = self.core.as_deref_mut() {
            if core.scene.frags.iter().any(Frag::samples_textures) {
                core.resolve();
                self.stats.passes = core.passes;
            }
        }
    }

    /// The framebuffer and scratch space, once no background draw holds them and the scene
    /// (every flush so far) is rasterised into the framebuffer.
    fn core(&mut self) -> &mut Core {
        self.wait();
        match self.core.as_deref_mut() {
            Some(core) => {
                core.resolve();
                self.stats.passes = core.passes;
                core
            }
            None => Self::lost(),
        }
    }

    /// `Material` called between Begin and End: `materials` are the new front and back materials,
    /// which apply from the next vertex on (GL 2.1 §2.14.3). Outside Begin/End the front end
    /// flushes instead, so this is only called with a primitive open.
    pub fn materials_changed(&mut self, materials: &[Material; 2]) {
        self.batch.materials_changed(materials);
    }

    /// `glClear` with a validated `mask` (any of COLOR/DEPTH/STENCIL_BUFFER_BIT), honouring the
    /// scissor test and the colour, depth and stencil write masks in `state` (GL 2.1 §4.2.3).
    pub fn clear(&mut self, state: &State, mask: u32) {
        self.flush(state);
        self.core().fb.clear(state, mask);
    }

    /// `glFinish` after a flush: the scene is rasterised into the framebuffer and no background
    /// draw holds it when this returns.
    pub fn finish(&mut self) {
        self.core();
    }

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// The framebuffer (read access for readback), once everything drawn so far is in it.
    pub fn framebuffer(&mut self) -> &Framebuffer {
        let fb = &mut self.core().fb;
        fb.materialize_all();
        fb
    }

    /// Colour buffer `buf` as RGBA8 bytes, top row first, once everything drawn so far is in
    /// it: pending clears are read as their colour, not written (see `Framebuffer::pending`).
    pub fn color_bytes_top_down(&mut self, buf: framebuffer::ColorBuf) -> Vec<u8> {
        self.core().fb.bytes_top_down(buf)
    }

    /// The colour buffer as bottom-up rows, `width * height` pixels.
    #[cfg(test)]
    pub fn color(&mut self) -> Vec<[u8; 4]> {
        self.core().fb.color_rows()
    }

    /// Starts an occlusion query's count (GL 2.1 §4.1.7): everything batched so far is drawn
    /// uncounted, then every fragment that passes the depth test (after scissor, alpha and
    /// stencil tests) counts, until `stop_counting_samples`. Returns the count's number, for
    /// [`Renderer::take_samples`]. Nothing is rasterised: the flushes join the scene, each
    /// tagged with the count it adds to, as any other draw (llvmpipe's queries are resolved
    /// when their result is read, too).
    pub fn start_counting_samples(&mut self, state: &State) -> u64 {
        self.flush(state);
        let n = self.next_count;
        self.next_count = self.next_count.wrapping_add(1);
        self.counting = Some(n);
        self.unresolved_core().counts.push((n, 0));
        n
    }

    /// Ends the count: draws what is batched (counted, into the scene).
    pub fn stop_counting_samples(&mut self, state: &State) {
        self.flush(state);
        self.counting = None;
    }

    /// The fragments count `n` counted (0 for a count forgotten or already taken), once every
    /// flush it counts is rasterised; the count is then forgotten.
    pub fn take_samples(&mut self, n: u64) -> u64 {
        let counts = &mut self.core().counts;
        match counts.iter().position(|&(k, _)| k == n) {
            Some(at) => counts.swap_remove(at).1,
            None => 0,
        }
    }

    /// Forgets count `n` (a query object deleted or begun again before its result was
    /// read): what is still to be rasterised of it counts nowhere.
    pub fn forget_samples(&mut self, n: u64) {
        self.unresolved_core().counts.retain(|&(k, _)| k != n);
    }

    /// The core once no background draw holds it, its scene left as it is.
    fn unresolved_core(&mut self) -> &mut Core {
        self.wait();
        match self.core.as_deref_mut() {
            Some(core) => core,
            None => Self::lost(),
        }
    }

    /// Drops the vertices batched so far without drawing them (`Context::reset`).
    pub fn discard_batch(&mut self) {
        self.batch.clear();
    }

    /// Draws everything batched so far with `state`, leaving the batch empty: its vertex stage
    /// and setup happen in place, into the scene, which is rasterised when the framebuffer is
    /// needed (see [`Scene`]). Handing a state change's flush to the pool as `flush_if_large`
    /// does was measured slower (see docs/conformance.md, Speed, fourth session).
    pub fn flush(&mut self, state: &State) {
        self.wait();
        if self.batch.is_empty() {
            self.batch.clear();
            return;
        }
        if state.render_mode != crate::gl::RENDER {
            // Hit records or feedback tokens instead of fragments.
            let Renderer {
                batch,
                verts,
                sink,
                tiles,
                ..
            } = self;
            sink.process(state, batch, &mut verts.vout, &mut verts.wins, *tiles);
            batch.clear();
            return;
        }
        let count = self.count_coverage;
        let samples = self.counting;
        let t0 = std::time::Instant::now();
        let plan = Plan::process(state, self.tiles, &self.batch, &mut self.verts, true);
        let Renderer {
            core, batch, verts, ..
        } = self;
        match core.as_deref_mut() {
            Some(core) => {
                core.draw(state, batch, verts, plan, count, samples);
                self.stats.passes = core.passes;
            }
            None => Self::lost(),
        }
        batch.clear();
        self.stats.draws += 1;
        self.stats.draw_ns = self.stats.draw_ns.saturating_add(ns_since(t0));
    }
}

impl Core {
    #[cfg(test)]
    fn new(width: u32, height: u32) -> Self {
        Core {
            fb: Framebuffer::new(width, height),
            asm: Vec::new(),
            scene: Scene::default(),
            counts: Vec::new(),
            passes: 0,
        }
    }

    fn try_new(width: u32, height: u32, config: ContextConfig) -> Option<Self> {
        Some(Core {
            fb: Framebuffer::try_new(width, height, config)?,
            asm: Vec::new(),
            scene: Scene::default(),
            counts: Vec::new(),
            passes: 0,
        })
    }

    /// Sets up `batch` (not empty), whose vertices `verts` went through the vertex stage as
    /// `plan` says, with `state`, and bins it into the scene; the scene is rasterised first if
    /// it writes other colour buffers, and after any piece that fills it (see [`Scene`]).
    fn draw(
        &mut self,
        state: &State,
        batch: &Batch,
        verts: &Processed,
        plan: Plan,
        count_coverage: bool,
        count_samples: Option<u64>,
    ) {
        let Plan { layout, ctx } = plan;
        let targets = Targets::of(state);
        if targets != self.scene.targets {
            self.resolve();
            self.scene.targets = targets;
        }
        // Fragment-stage state, owned by the scene until it is rasterised.
        let frag = Frag {
            // Without a depth buffer the depth test always passes and writes nothing (§4.1.6).
            depth_test: state.enables.depth_test && self.fb.config().depth,
            depth_func: state.depth_func,
            depth_mask: state.depth_mask,
            // DrawBuffer(NONE): fragments go through every test and write no colour.
            color_mask: if targets.none() {
                [false; 4]
            } else {
                state.color_write_mask()
            },
            color_sum: layout.spec.is_some(),
            rl: ctx.rl,
            lighting: layout.nrm.is_some().then(|| Lighting::new(state)),
            mats: if batch.snapshots.is_empty() {
                vec![state.materials]
            } else {
                batch.snapshots.clone()
            },
            count: count_coverage,
            samples: count_samples,
            stipple: state
                .enables
                .polygon_stipple
                .then(|| fragment::stipple_rows(state)),
            ops: fragops::Ops::new(state),
            // Each unit that carries coordinates, when enabled and complete (§3.8.10).
            samplers: std::array::from_fn(|u| {
                layout.tex[u].and_then(|_| texture::Sampler::new(state, u))
            }),
        };
        let mut fi = self.scene.frags.len();
        self.scene.frags.push(frag);
        // The line stipple counter runs from segment to segment in submission order: one
        // worker sets up everything while LINE_STIPPLE is on.
        let parallel = if layout.tex.iter().any(Option::is_some) {
            PARALLEL_SETUP_TEXTURED
        } else {
            PARALLEL_SETUP
        };
        let nw = if batch.idx.len() >= parallel && ctx.line_stipple.is_none() {
            // More workers than threads balances the load when other processes share the cores.
            (4 * rayon::current_num_threads()).clamp(1, 32)
        } else {
            1
        };
        let v = Verts {
            vout: &verts.vout,
            wins: &verts.wins,
            batch,
        };
        // Pieces of whole primitives, about PIECE vertices each, go through assembly, clipping
        // and setup one after the other, and a piece that fills the scene is rasterised at
        // once: the setup output stays small and warm in the cache, and memory does not grow
        // with the batch.
        let prims = &batch.prims;
        let mut start = 0;
        while let Some((first, more)) = prims.get(start..).and_then(|r| r.split_first()) {
            // The piece: its first primitive whatever its size, then those that keep it within
            // PIECE vertices, its largest primitive found on the way (one walk over a dense
            // mesh's 160k strips, without a range check or a second pass for the largest).
            let mut count = first.count as usize;
            let mut largest = count;
            let mut end = start + 1;
            for p in more {
                let n = p.count as usize;
                if count + n > PIECE {
                    break;
                }
                count += n;
                largest = largest.max(n);
                end += 1;
            }
            debug_assert!(end <= prims.len(), "piece past the primitive list");
            let piece = prims.get(start..end).unwrap_or(&[]);
            if nw == 1 || largest <= count / nw {
                let workers = self.scene.take(fi, nw);
                setup_by_primitives(workers, &ctx, &v, piece, count);
                self.scene.vertices += count;
                fi = self.settle(fi);
            } else {
                // One primitive dominates: assemble it, then cut its triangles into runs.
                let mut asm = std::mem::take(&mut self.asm);
                assembly::assemble(
                    piece,
                    &batch.idx,
                    batch.edge(),
                    ctx.quads_split_last,
                    &mut asm,
                );
                for run in asm.chunks(PIECE) {
                    let workers = self.scene.take(fi, nw);
                    setup_by_triangles(workers, &ctx, &v, run);
                    self.scene.vertices += 3 * run.len();
                    fi = self.settle(fi);
                }
                self.asm = asm;
            }
            start = end;
        }
    }

    /// Rasterises the scene if it is full, keeping the fragment state of flush `fi`, the one
    /// being set up (the last): returns its index afterwards.
    fn settle(&mut self, fi: usize) -> usize {
        if !self.scene.full() {
            return fi;
        }
        self.rasterise_parts();
        self.scene.frags.drain(..fi.min(self.scene.frags.len()));
        0
    }

    /// Bins the plain bitmap `bits`, drawn into `targets`, into the scene (rasterised first if
    /// it writes other colour buffers, and after it if it fills the scene).
    fn bin_bits(&mut self, targets: Targets, bits: pixels::BinnedBits) {
        if targets != self.scene.targets {
            self.resolve();
            self.scene.targets = targets;
        }
        self.scene.bytes = self.scene.bytes.saturating_add(bits.bytes());
        self.scene.parts.push(Part::Bits(bits));
        if self.scene.full() {
            self.resolve();
        }
    }

    /// Rasterises every part of the scene into the framebuffer and empties it.
    fn resolve(&mut self) {
        self.rasterise_parts();
        self.scene.frags.clear();
    }

    /// Rasterises the scene's parts and empties them (not `Scene::frags`).
    fn rasterise_parts(&mut self) {
        let Core {
            fb,
            scene,
            counts,
            passes,
            ..
        } = self;
        if scene.parts.is_empty() {
            return;
        }
        *passes += 1;
        let ctxs: Vec<FragCtx> = scene.frags.iter().map(Frag::ctx).collect();
        // The occlusion queries the parts count for, each given a slot of `rasterise`'s sums.
        let mut queries: Vec<u64> = Vec::new();
        let slots: Vec<Option<usize>> = scene
            .frags
            .iter()
            .map(|f| {
                let n = f.samples?;
                Some(match queries.iter().position(|&k| k == n) {
                    Some(slot) => slot,
                    None => {
                        queries.push(n);
                        queries.len() - 1
                    }
                })
            })
            .collect();
        let parts: Vec<Piece> = scene
            .parts
            .iter()
            .filter_map(|p| match p {
                Part::Prims { frag, workers } => Some(Piece::Prims(
                    ctxs.get(*frag)?,
                    slots.get(*frag).copied().flatten(),
                    scene.workers.get(workers.clone())?,
                )),
                Part::Bits(b) => Some(Piece::Bits(b)),
            })
            .collect();
        let sums = rasterise(fb, &parts, queries.len(), scene.targets);
        for (n, sum) in queries.iter().zip(sums) {
            if let Some((_, c)) = counts.iter_mut().find(|(k, _)| k == n) {
                *c = c.wrapping_add(sum);
            }
        }
        drop(parts);
        drop(ctxs);
        scene.clear();
    }

    /// Adds `n` fragments to occlusion query count `query` (a pixel rectangle's, drawn in
    /// place).
    fn add_samples(&mut self, query: u64, n: u64) {
        if let Some((_, c)) = self.counts.iter_mut().find(|(k, _)| *k == query) {
            *c = c.wrapping_add(n);
        }
    }
}

impl Scene {
    /// `n` workers for a new part of flush `frag`, set up next.
    fn take(&mut self, frag: usize, n: usize) -> &mut [Worker] {
        let range = self.used..self.used + n;
        if self.workers.len() < range.end {
            self.workers.resize_with(range.end, Worker::default);
        }
        self.used = range.end;
        self.parts.push(Part::Prims {
            frag,
            workers: range.clone(),
        });
        self.workers.get_mut(range).unwrap_or_default()
    }

    /// Empties the parts once rasterised.
    fn clear(&mut self) {
        self.parts.clear();
        for w in self.workers.iter_mut().skip(KEPT_WORKERS) {
            w.trim();
        }
        self.used = 0;
        self.vertices = 0;
        self.bytes = 0;
    }

    /// Whether it holds enough to be rasterised (see [`Scene`]).
    fn full(&self) -> bool {
        self.vertices >= SCENE_VERTICES
            || self.parts.len() >= SCENE_PARTS
            || self.bytes >= SCENE_BYTES
    }
}

/// Bounding-box pixels of a rasterisation below which its tiles are drawn on the calling
/// thread (two tiles' worth, as the two-tile rule).
const SERIAL_AREA: u64 = 2 * TILE_PIXELS as u64;

/// Estimated work of a rasterisation (bounding-box pixels, plus `PRIM_WORK` for each
/// primitive) below which its tiles are drawn on the calling thread: sixteen tiles' pixels.
/// Waking the pool costs 25–40 µs on the bench machine (the workers sleep during the GL frame
/// the bench interleaves); a single smooth triangle over 41616 box pixels takes ~25 µs.
const SERIAL_WORK: u64 = 16 * TILE_PIXELS as u64;

/// A primitive's fixed cost in a rasterisation (per tile reached: its set-up per tile, its edge
/// walk), in bounding-box pixels, for `SERIAL_WORK`.
const PRIM_WORK: u64 = 64;

/// Whether a rasterisation of `jobs` busy tiles, primitives with `area` bounding-box pixels in
/// all and `prims` primitives is drawn on the calling thread: handing it to the pool costs more
/// than it saves. Tiles are independent, so the pixels are the same either way.
fn serial_pass(jobs: usize, area: u64, prims: u64) -> bool {
    jobs <= 2
        || area < SERIAL_AREA
        || area.saturating_add(prims.saturating_mul(PRIM_WORK)) < SERIAL_WORK
}

/// Given vertices after which `flush_if_large` draws the batch.
const FLUSH_AT: usize = 1 << 15;

/// Given vertices per piece of a flush.
const PIECE: usize = 1 << 15;

/// The processed vertices of a flush.
struct Verts<'a> {
    vout: &'a [f32],
    wins: &'a [setup::Win],
    batch: &'a Batch,
}

/// Setup of whole primitives split in order across `workers`, balanced by vertex count
/// (`count` vertices in all).
fn setup_by_primitives(
    workers: &mut [Worker],
    ctx: &SetupCtx,
    v: &Verts,
    prims: &[batch::Prim],
    count: usize,
) {
    let nw = workers.len();
    if nw == 1 {
        if let Some(w) = workers.first_mut() {
            w.assemble_and_run(ctx, v.vout, v.wins, v.batch, prims);
        }
        return;
    }
    // Cut points: the first primitive starting at or after each k·count/nw vertices. The
    // threshold is computed when k moves on, not for each primitive (a multiplication and a
    // division for each of a dense mesh's 160k strips), and the walk stops at the last cut.
    let first = prims.first().map_or(0, |p| p.first as usize);
    let mut cuts = [0usize; 33];
    let mut k = 1;
    // (`nw` is not 0 here: none would return above; `max` keeps the division safe regardless.)
    let mut at = count / nw.max(1);
    for (i, p) in prims.iter().enumerate() {
        if k >= nw {
            break;
        }
        while k < nw && p.first as usize - first >= at {
            cuts[k] = i;
            k += 1;
            at = k * count / nw;
        }
    }
    for c in cuts.iter_mut().take(nw + 1).skip(k) {
        *c = prims.len();
    }
    workers.par_iter_mut().enumerate().for_each(|(i, w)| {
        debug_assert!(i + 1 < cuts.len(), "a worker without its cut");
        let lo = cuts.get(i).copied().unwrap_or(0);
        let hi = cuts.get(i + 1).copied().unwrap_or(lo);
        debug_assert!(
            lo <= hi && hi <= prims.len(),
            "cuts out of order: {lo}..{hi}"
        );
        let part = prims.get(lo..hi).unwrap_or(&[]);
        w.assemble_and_run(ctx, v.vout, v.wins, v.batch, part);
    });
}

/// Setup of assembled triangles cut into equal runs across `workers`.
fn setup_by_triangles(workers: &mut [Worker], ctx: &SetupCtx, v: &Verts, asm: &[Asm]) {
    let chunk = asm.len().div_ceil(workers.len()).max(1);
    workers.par_iter_mut().enumerate().for_each(|(i, w)| {
        let lo = (i * chunk).min(asm.len());
        let hi = ((i + 1) * chunk).min(asm.len());
        w.run(
            ctx,
            v.vout,
            v.wins,
            &v.batch.mat,
            asm.get(lo..hi).unwrap_or(&[]),
        );
    });
}

/// One entry of the scene to rasterise.
enum Piece<'a> {
    /// A piece of a flush: its fragment-stage state, the slot of the occlusion query it counts
    /// for (`rasterise`'s sums), and the workers holding its binned primitives.
    Prims(&'a FragCtx<'a>, Option<usize>, &'a [Worker]),
    /// A plain bitmap.
    Bits(&'a pixels::BinnedBits),
}

/// Rasterisation and fragment operations of `parts` (each a flush's fragment-stage state and
/// the workers holding a piece of its binned primitives), tiles in parallel; inside a tile,
/// the parts in order, and in each part worker 0's primitives first, then worker 1's, ...,
/// which is submission order. Colour goes to the buffers `targets` names: the main buffer,
/// the front buffer, or both (the front one as each tile's second colour slice). Returns the
/// fragments counted for each of `queries` occlusion query slots (by the parts whose
/// `FragCtx::samples` is set, into their slot).
fn rasterise(fb: &mut Framebuffer, parts: &[Piece], queries: usize, targets: Targets) -> Vec<u64> {
    let (tx, ty) = fb.tiles();
    let Framebuffer {
        color,
        front,
        depth,
        stencil,
        pending,
        ..
    } = fb;
    // The first target is each tile's colour slice, a second one its `color2`.
    let (primary, secondary, front_first) = match (targets.front, front.as_mut()) {
        (true, Some(f)) if !targets.main => (f, None, true),
        (true, Some(f)) => (color, Some(f), false),
        _ => (color, None, false),
    };
    // The tiles some primitive reaches, from the workers' lists, in tile order (the others
    // are not visited: their pending clears stay pending).
    let mut busy: Vec<usize> = Vec::new();
    for piece in parts {
        match piece {
            Piece::Prims(_, _, ws) => busy.extend(
                ws.iter()
                    .flat_map(|w| w.touched.iter().map(|&t| t as usize)),
            ),
            Piece::Bits(b) => busy.extend(b.tiles((tx, ty))),
        }
    }
    busy.retain(|&t| t < tx * ty);
    busy.sort_unstable();
    busy.dedup();
    let colors = tile_parts(primary, &busy, TILE_PIXELS);
    let mut seconds = secondary.map(|s| tile_parts(s, &busy, TILE_PIXELS).into_iter());
    let depths = tile_parts(depth, &busy, TILE_PIXELS);
    let stencils = tile_parts(stencil, &busy, TILE_PIXELS);
    let fills = tile_parts(pending, &busy, 1);
    let mut jobs = Vec::with_capacity(busy.len());
    for ((((&t, c), d), s), f) in busy.iter().zip(colors).zip(depths).zip(stencils).zip(fills) {
        let c2 = seconds.as_mut().and_then(|it| it.next().flatten());
        if let (Some(c), Some(d), Some(s), Some([f])) = (c, d, s, f) {
            jobs.push((t, c, c2, d, s, f));
        }
    }
    let work = |(t, color, mut color2, depth, stencil, fill): Job| -> Vec<u64> {
        // A lazily cleared tile is written before its first primitive (the colour buffer
        // not drawn stays pending).
        if !fill.is_empty() {
            match front_first {
                true => fill.materialize(None, Some(&mut *color), depth, stencil),
                false => fill.materialize(Some(&mut *color), color2.as_deref_mut(), depth, stencil),
            }
        }
        let mut bufs = TileBufs {
            color,
            color2,
            depth,
            stencil,
            x: ((t % tx) * TILE) as i32,
            y: ((t / tx) * TILE) as i32,
            samples: 0,
        };
        let mut sums = vec![0u64; queries];
        for piece in parts {
            let (fctx, slot, workers) = match *piece {
                Piece::Prims(fctx, slot, workers) => (fctx, slot, workers),
                Piece::Bits(b) => {
                    b.draw(&mut bufs);
                    continue;
                }
            };
            let before = bufs.samples;
            for w in workers {
                let bin = w.bins.get(t).map_or(&[][..], |b| &b[..]);
                raster::prims(fctx, &mut bufs, &w.prims, bin, &w.pool);
            }
            if let Some(sum) = slot.and_then(|s| sums.get_mut(s)) {
                *sum = sum.wrapping_add(bufs.samples.wrapping_sub(before));
            }
        }
        sums
    };
    // The tiles' sums, slot by slot.
    let add = |a: Vec<u64>, b: Vec<u64>| {
        let (mut long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
        for (x, y) in long.iter_mut().zip(&short) {
            *x = x.wrapping_add(*y);
        }
        long
    };
    // Primitives within one or two tiles, whose bounding boxes hold fewer pixels than two
    // tiles, or few primitives over fewer than sixteen tiles' pixels are drawn on this thread
    // (`serial_pass`).
    let (area, prims) = parts
        .iter()
        .fold((0u64, 0u64), |(a, n), piece| match piece {
            Piece::Prims(_, _, ws) => ws.iter().fold((a, n), |(a, n), w| {
                (
                    a.saturating_add(w.area),
                    n.saturating_add(w.prims.len() as u64),
                )
            }),
            Piece::Bits(b) => (a.saturating_add(b.pixels()), n.saturating_add(1)),
        });
    if serial_pass(jobs.len(), area, prims) {
        jobs.into_iter().map(work).fold(Vec::new(), add)
    } else {
        jobs.into_par_iter().map(work).reduce(Vec::new, add)
    }
}

/// The parts `tiles` (ascending, distinct) of `buf` cut into parts of `len` elements, each
/// `None` past the end of `buf`.
fn tile_parts<'a, T>(
    mut rest: &'a mut [T],
    tiles: &[usize],
    len: usize,
) -> Vec<Option<&'a mut [T]>> {
    let mut base = 0;
    tiles
        .iter()
        .map(|&t| {
            let skip = (t * len).checked_sub(base)?;
            let (_, tail) = std::mem::take(&mut rest).split_at_mut_checked(skip)?;
            let (part, tail) = tail.split_at_mut_checked(len)?;
            rest = tail;
            base = (t + 1) * len;
            Some(part)
        })
        .collect()
}

/// One tile's share of a rasterisation: its index, colour slice, second colour slice, depth
/// and stencil slices and pending clear.
type Job<'a> = (
    usize,
    &'a mut [[u8; 4]],
    Option<&'a mut [[u8; 4]]>,
    &'a mut [u32],
    &'a mut [u8],
    &'a mut framebuffer::Fill,
);
