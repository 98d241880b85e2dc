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
//! depend on it). A batch is drawn at End once it holds 64k vertices, so memory stays bounded.

pub mod assembly;
pub mod batch;
pub mod clip;
pub mod fragment;
pub mod fragops;
pub mod framebuffer;
mod line;
pub mod raster;
pub mod setup;
// --- texture
pub mod texgen;
pub mod texture;
// --- end texture
pub mod vertex;

#[cfg(test)]
mod tests;

use glam::Vec4;
use rayon::prelude::*;

use crate::state::{Current, Material, State};
use assembly::Asm;
use batch::Batch;
use fragment::{FragCtx, TileBufs};
use framebuffer::{Framebuffer, TILE, TILE_PIXELS};
use setup::{SetupCtx, Worker};
use vertex::{Layout, Lighting};

/// Primitives below which setup stays on one thread.
const PARALLEL_SETUP: usize = 4096;

/// The CPU renderer: the vertex batch not yet drawn, scratch space reused across flushes, and the
/// framebuffer.
#[derive(Debug)]
pub struct Renderer {
    fb: Framebuffer,
    batch: Batch,
    vout: Vec<f32>,
    wins: Vec<setup::Win>,
    asm: Vec<Asm>,
    workers: Vec<Worker>,
    /// Diagnostic: fragments add 1 to the red byte instead of writing colour.
    pub(crate) count_coverage: bool,
}

impl Renderer {
    /// A renderer with a cleared `width` x `height` framebuffer (sizes validated by the caller).
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            fb: Framebuffer::new(width, height),
            batch: Batch::default(),
            vout: Vec::new(),
            wins: Vec::new(),
            asm: Vec::new(),
            workers: Vec::new(),
            count_coverage: false,
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

    /// `End`.
    pub fn end(&mut self) {
        self.batch.end();
    }

    /// Draws the batch now if it holds many vertices: called after `End`, when the state the
    /// batch was specified under is still current. Keeps the batch (and its memory) bounded and
    /// cache-warm without changing the result.
    pub fn flush_if_large(&mut self, state: &State) {
        if self.batch.idx.len() >= FLUSH_AT {
            self.flush(state);
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
        self.fb.clear(state, mask);
    }

    /// Framebuffer width and height.
    pub fn size(&self) -> (u32, u32) {
        self.fb.size()
    }

    /// The framebuffer (read access for readback).
    pub fn framebuffer(&self) -> &Framebuffer {
        &self.fb
    }

    /// The colour buffer as bottom-up rows, `width * height` pixels.
    pub fn color(&self) -> Vec<[u8; 4]> {
        self.fb.color_rows()
    }

    /// Drops the vertices batched so far without drawing them (`Context::reset`).
    pub fn discard_batch(&mut self) {
        self.batch.clear();
    }

    /// Draws everything batched so far with `state`, leaving the batch empty.
    pub fn flush(&mut self, state: &State) {
        if self.batch.is_empty() {
            self.batch.clear();
            return;
        }
        let layout = Layout::for_state(state);
        let rect = framebuffer::scissor_rect(state);
        let mut ctx = SetupCtx::new(state, layout, rect, self.fb.tiles());
        // Vertex stage (§2.11, §2.14), parallel over large batches.
        vertex::process(
            state,
            &self.batch,
            &layout,
            &ctx,
            &mut self.vout,
            &mut self.wins,
        );
        // llvmpipe splits quads along 1–3 when it shades FLAT or when any vertex of the draw
        // needs clipping (its draw module then takes the clipping path, which decomposes quads
        // provoking-vertex-last), and along 0–2 otherwise; measured in
        // tests/implementation_choices.rs. A flush is our counterpart of its draw.
        ctx.quads_split_last |= self.wins.iter().any(|w| w.code != 0);
        // Fragment-stage constants.
        let lighting = (layout.nrm.is_some()).then(|| Lighting::new(state));
        // --- texture: unit 0, when enabled and complete (§3.8.10)
        let sampler = layout.tex.and_then(|_| texture::Sampler::new(state, 0));
        let sampler1 = layout.tex1.and_then(|_| texture::Sampler::new(state, 1));
        // --- end texture
        let Renderer {
            fb,
            batch,
            vout,
            wins,
            asm,
            workers,
            count_coverage,
        } = self;
        let mats: &[[Material; 2]] = if batch.snapshots.is_empty() {
            std::slice::from_ref(&state.materials)
        } else {
            &batch.snapshots
        };
        let fctx = FragCtx {
            depth_test: state.enables.depth_test,
            depth_func: state.depth_func,
            depth_mask: state.depth_mask,
            color_mask: state.color_mask,
            color_sum: layout.spec.is_some(),
            rl: ctx.rl,
            lighting: lighting.as_ref(),
            mats,
            count: *count_coverage,
            ops: fragops::Ops::new(state),
            // --- texture
            tex: sampler.as_ref(),
            tex1: sampler1.as_ref(),
            // --- end texture
        };
        let nw = if batch.idx.len() >= PARALLEL_SETUP {
            // More workers than threads balances the load when other processes share the cores.
            (4 * rayon::current_num_threads()).clamp(1, 32)
        } else {
            1
        };
        if workers.len() < nw {
            workers.resize_with(nw, Worker::default);
        }
        let workers = &mut workers[..nw];
        let v = Verts { vout, wins, batch };
        // Pieces of whole primitives, about PIECE vertices each, go through assembly, clipping,
        // setup and rasterisation one after the other: the setup output stays small and warm
        // in the cache, and memory does not grow with the batch.
        let prims = &batch.prims;
        let mut start = 0;
        while start < prims.len() {
            let mut end = start;
            let mut count = 0usize;
            while let Some(p) = prims.get(end) {
                if end > start && count + p.count as usize > PIECE {
                    break;
                }
                count += p.count as usize;
                end += 1;
            }
            let piece = prims.get(start..end).unwrap_or(&[]);
            let largest = piece.iter().map(|p| p.count as usize).max().unwrap_or(0);
            if workers.len() == 1 || largest <= count / workers.len() {
                setup_by_primitives(workers, &ctx, &v, piece, count);
                rasterise(fb, workers, &fctx, ctx.tiles_x);
            } else {
                // One primitive dominates: assemble it, then cut its triangles into runs.
                assembly::assemble(piece, &batch.idx, &batch.edge, ctx.quads_split_last, asm);
                for run in asm.chunks(PIECE) {
                    setup_by_triangles(workers, &ctx, &v, run);
                    rasterise(fb, workers, &fctx, ctx.tiles_x);
                }
            }
            start = end;
        }
        batch.clear();
    }
}

/// Given vertices after which `flush_if_large` draws the batch.
const FLUSH_AT: usize = 1 << 16;

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
    // Cut points: the first primitive starting at or after each k·count/nw vertices.
    let first = prims.first().map_or(0, |p| p.first as usize);
    let mut cuts = [0usize; 33];
    let mut k = 1;
    for (i, p) in prims.iter().enumerate() {
        while k < nw && p.first as usize - first >= k * count / nw {
            cuts[k] = i;
            k += 1;
        }
    }
    for c in cuts.iter_mut().take(nw + 1).skip(k) {
        *c = prims.len();
    }
    workers.par_iter_mut().enumerate().for_each(|(i, w)| {
        let lo = cuts.get(i).copied().unwrap_or(0);
        let hi = cuts.get(i + 1).copied().unwrap_or(lo);
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

/// Rasterisation and fragment operations, tiles in parallel; inside a tile, worker 0's
/// primitives first, then worker 1's, ..., which is submission order.
fn rasterise(fb: &mut Framebuffer, workers: &[Worker], fctx: &FragCtx, tiles_x: usize) {
    fb.color
        .par_chunks_mut(TILE_PIXELS)
        .zip(fb.depth.par_chunks_mut(TILE_PIXELS))
        .zip(fb.stencil.par_chunks_mut(TILE_PIXELS))
        .enumerate()
        .for_each(|(t, ((color, depth), stencil))| {
            if workers
                .iter()
                .all(|w| w.bins.get(t).map_or(true, |b| b.is_empty()))
            {
                return;
            }
            let mut bufs = TileBufs {
                color,
                depth,
                stencil,
                x: ((t % tiles_x) * TILE) as i32,
                y: ((t / tiles_x) * TILE) as i32,
            };
            for w in workers {
                for &pi in w.bins.get(t).map_or(&[][..], |b| &b[..]) {
                    if let Some(p) = w.prims.get(pi as usize) {
                        raster::prim(fctx, &mut bufs, p, &w.pool);
                    }
                }
            }
        });
}
