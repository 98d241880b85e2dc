//! The recorded call stream: one `Call` variant per GL entry point, arguments owned.
//!
//! A `Vec<Call>` is what a context records, what a display list holds, what the real-GL backend
//! replays and what a recording file stores. Every consumer matches `Call` exhaustively (no `_ =>`
//! arm), so an entry point added here cannot be forgotten by a backend.
//!
//! Variants are named as the GL function without `gl` (`glNormal3f` → `Normal3f`) and take the
//! GL types one to one; vector forms whose length GL fixes keep their own variant with an array
//! (`Normal3fv([f32; 3])`), so a replay calls exactly the entry point the user called.

use serde::{Deserialize, Serialize};

/// One GL call with its arguments.
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Call {
    Begin(u32),
    End,
    Vertex3f(f32, f32, f32),
    Normal3f(f32, f32, f32),
    Color4f(f32, f32, f32, f32),
    Enable(u32),
    Disable(u32),
    // --- transforms (context/matrix.rs)
    MatrixMode(u32),
    LoadIdentity,
    LoadMatrixf([f32; 16]),
    LoadMatrixd([f64; 16]),
    MultMatrixf([f32; 16]),
    MultMatrixd([f64; 16]),
    LoadTransposeMatrixf([f32; 16]),
    LoadTransposeMatrixd([f64; 16]),
    MultTransposeMatrixf([f32; 16]),
    MultTransposeMatrixd([f64; 16]),
    Translatef(f32, f32, f32),
    Translated(f64, f64, f64),
    Rotatef(f32, f32, f32, f32),
    Rotated(f64, f64, f64, f64),
    Scalef(f32, f32, f32),
    Scaled(f64, f64, f64),
    Frustum(f64, f64, f64, f64, f64, f64),
    Ortho(f64, f64, f64, f64, f64, f64),
    PushMatrix,
    PopMatrix,
    Viewport(i32, i32, i32, i32),
    DepthRange(f64, f64),
    ClipPlane(u32, [f64; 4]),
    ActiveTexture(u32),
    ClientActiveTexture(u32),
    // --- end transforms
}
