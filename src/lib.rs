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
#![warn(clippy::undocumented_unsafe_blocks)]

// The front end: validation, state, queries (GL 2.1 chapters 2 to 6).
pub mod arrays;
pub(crate) mod buffers;
pub mod context;
mod convert;
mod error;
pub mod gl;
pub mod pixel_store;
pub mod pixels;
pub mod state;
pub mod texture;

// The command table, and the recorded call stream made from it, with its file format.
pub mod call;
pub mod commands;
pub mod counts;
pub mod recording;

// Backends: the CPU pipeline and the real driver.
pub(crate) mod cpu;
#[cfg(feature = "gl")]
pub mod glbackend;

// Tools over both: comparison, report, the lecture scenes, GLU and GLUT helpers.
pub mod compare;
pub mod glu;
pub mod glut;
pub mod report;
pub mod scenes;
// Windows and animation: a Context in a window, JOGL-style listeners, `fixedgl view`.
#[cfg(feature = "window")]
pub mod window;

pub use arrays::Pointer;
pub use call::Call;
pub use context::{Context, ShareGroup};
pub use cpu::start_pool;
pub use error::Error;
pub use state::ContextConfig;
pub use texture::{checkerboard, texture_from_image};
