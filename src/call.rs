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
}
