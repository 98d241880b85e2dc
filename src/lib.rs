//! fixedgl: the OpenGL 1.x fixed-function pipeline on the CPU, and the same recorded calls replayed
//! on a real GL driver, so that both can be compared side by side.
//!
//! ```text
//! user code ─► Context (validates exactly as GL; sticky error flag; State; Call recording)
//!                 ├─► cpu:  vertex stage → assembly → clipping → setup → tile rasteriser → framebuffer
//!                 └─► Vec<Call> ─► GL backend (EGL, compatibility profile) ─► compare
//! ```
//!
//! Start with [`Context::new`], then call GL entry points as methods: `glNormal3f` is
//! [`Context::normal3f`], constants live in [`gl`]. See `docs/architecture.md`.
#![warn(missing_docs)]

pub mod call;
pub mod context;
pub mod cpu;
mod error;
pub mod gl;
// --- GLU (glu.rs)
pub mod glu;
// --- end GLU
// --- lists: GLUT shapes (glut.rs)
pub mod glut;
// --- end lists
pub mod state;

// ---- frontend-set: the recording file format ----
pub mod recording;

pub use call::Call;
pub use context::Context;
pub use error::Error;

// ---- gl-backend branch: compare, report, scenes, real-GL backend ----
pub mod compare;
#[cfg(feature = "gl")]
pub mod glbackend;
pub mod report;
pub mod scenes;

// --- arrays: vertex arrays and buffer objects (arrays.rs)
pub mod arrays;
pub use arrays::Pointer;
// --- end arrays
// --- texture: texture state, unpacking and image helpers (texture.rs)
pub mod texture;
pub use texture::{checkerboard, texture_from_image};
// --- end texture
