//! The integration tests: one test binary with a module per feature (as tiny-skia keeps its
//! `tests/integration`), so that the suite compiles and links the crate's tests once.
//!
//! GL-backend modules compare with the real driver (Mesa llvmpipe through EGL): where no EGL device
//! exists each such test prints `SKIPPED: ...` and returns, and `FIXEDGL_REQUIRE_GL=1` (set by
//! `.ci/run`) turns that into a failure.

mod common;

mod arrays;
mod attrib;
mod buffer_map;
mod buffers;
mod compressed_gl;
mod crossbar_gl;
mod depth_stencil_gl;
mod error_agreement;
mod errors;
mod eval;
mod fbo;
mod fragment_gl;
mod fragment_state;
mod gl_backend;
mod gl_lists;
mod glu_mipmap;
mod glu_mipmap3d;
mod glu_quadric;
mod glu_tess;
mod glut;
mod implementation_choices;
mod line_ties;
mod lists;
mod matrices;
mod multi_draw;
mod pixel_store;
mod pixel_store_gl;
mod pixels;
mod pixels_gl;
mod points;
mod query;
mod query_errors;
mod raster_gl;
mod recording;
mod report;
mod report_browser;
mod rgb_framebuffer;
mod robustness;
mod scalar_vector_pnames;
mod scenes;
mod select;
mod share;
mod soak;
mod state_initial;
mod stipple;
mod texture;
mod texture_border_proxy_gl;
mod texture_errors;
mod texture_gl;
mod texture_pixels_gl;
mod texture_targets_gl;
mod texture_units_gl;
mod window;
