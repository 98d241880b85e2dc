//! What several test modules share: the GL backend or a printed skip, and the GL enum values
//! worth drawing often in random calls.

use fixedgl::gl;

/// A GL backend for a test, or `None` after printing `SKIPPED: GL backend unavailable: <reason>`
/// to standard error (written to the handle, not through `eprintln!`, which libtest captures for
/// passing tests: a skip must stay visible). With `FIXEDGL_REQUIRE_GL` set (CI), an unavailable
/// backend fails the test instead.
#[cfg(feature = "gl")]
pub fn test_backend(width: u32, height: u32) -> Option<fixedgl::glbackend::GlBackend> {
    use fixedgl::glbackend::{DeviceChoice, GlBackend};
    use std::io::Write as _;
    match GlBackend::new(width, height, &DeviceChoice::Auto) {
        Ok(b) => Some(b),
        Err(e) if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() => {
            panic!("FIXEDGL_REQUIRE_GL is set but the GL backend cannot start: {e}")
        }
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED: GL backend unavailable: {e}");
            None
        }
    }
}

/// [`test_backend`] standing in for a framebuffer with the buffers `config` names.
#[cfg(feature = "gl")]
pub fn test_backend_with(
    width: u32,
    height: u32,
    config: fixedgl::ContextConfig,
) -> Option<fixedgl::glbackend::GlBackend> {
    use fixedgl::glbackend::{DeviceChoice, GlBackend};
    use std::io::Write as _;
    match GlBackend::with_config(width, height, &DeviceChoice::Auto, config) {
        Ok(b) => Some(b),
        Err(e) if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() => {
            panic!("FIXEDGL_REQUIRE_GL is set but the GL backend cannot start: {e}")
        }
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED: GL backend unavailable: {e}");
            None
        }
    }
}

/// A backend on OSMesa (llvmpipe with a window framebuffer of its own, accumulation buffer
/// included), or `None` after printing `SKIPPED: ...` where libOSMesa is missing.
#[cfg(feature = "gl")]
pub fn osmesa_backend(
    width: u32,
    height: u32,
    config: fixedgl::ContextConfig,
) -> Option<fixedgl::glbackend::GlBackend> {
    use std::io::Write as _;
    match fixedgl::glbackend::GlBackend::osmesa(width, height, config) {
        Ok(b) => Some(b),
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED: OSMesa unavailable: {e}");
            None
        }
    }
}

/// Enums worth drawing often: every value the set-side entry points accept, and near misses.
pub const ENUMS: &[u32] = &[
    gl::POINTS,
    gl::LINES,
    gl::TRIANGLES,
    gl::TRIANGLE_STRIP,
    gl::QUADS,
    gl::POLYGON,
    10,
    gl::LIGHT0,
    gl::LIGHT1,
    gl::LIGHT7,
    gl::LIGHT7 + 1,
    gl::LIGHT0 - 1,
    gl::FRONT,
    gl::BACK,
    gl::FRONT_AND_BACK,
    gl::LEFT,
    gl::AMBIENT,
    gl::DIFFUSE,
    gl::SPECULAR,
    gl::POSITION,
    gl::SPOT_DIRECTION,
    gl::SPOT_EXPONENT,
    gl::SPOT_CUTOFF,
    gl::CONSTANT_ATTENUATION,
    gl::LINEAR_ATTENUATION,
    gl::QUADRATIC_ATTENUATION,
    gl::EMISSION,
    gl::SHININESS,
    gl::AMBIENT_AND_DIFFUSE,
    gl::COLOR_INDEXES,
    gl::LIGHT_MODEL_AMBIENT,
    gl::LIGHT_MODEL_LOCAL_VIEWER,
    gl::LIGHT_MODEL_TWO_SIDE,
    gl::LIGHT_MODEL_COLOR_CONTROL,
    gl::SINGLE_COLOR,
    gl::SEPARATE_SPECULAR_COLOR,
    gl::FLAT,
    gl::SMOOTH,
    gl::PHONG_WIN,
    gl::CW,
    gl::CCW,
    gl::POINT,
    gl::LINE,
    gl::FILL,
    gl::NEVER,
    gl::LESS,
    gl::ALWAYS,
    gl::ALWAYS + 1,
    gl::PERSPECTIVE_CORRECTION_HINT,
    gl::FOG_HINT,
    gl::GENERATE_MIPMAP_HINT,
    gl::PHONG_HINT_WIN,
    gl::FASTEST,
    gl::NICEST,
    gl::DONT_CARE,
    gl::PACK_ALIGNMENT,
    gl::UNPACK_ALIGNMENT,
    gl::PACK_ROW_LENGTH,
    gl::COLOR_BUFFER_BIT,
    gl::DEPTH_BUFFER_BIT,
    gl::STENCIL_BUFFER_BIT,
    gl::ACCUM_BUFFER_BIT,
    gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT,
    gl::COLOR_MATERIAL,
    gl::LIGHTING,
    gl::DEPTH_TEST,
    gl::CULL_FACE,
    gl::NORMALIZE,
    gl::SCISSOR_TEST,
    // --- lists: NewList modes, CallLists types, attribute masks
    gl::COMPILE,
    gl::COMPILE_AND_EXECUTE,
    gl::UNSIGNED_BYTE,
    gl::GL_2_BYTES,
    gl::FLOAT,
    gl::LIGHTING_BIT | gl::ENABLE_BIT,
    gl::ALL_ATTRIB_BITS,
    // --- end lists
    // --- fragment ops
    gl::FOG_MODE,
    gl::FOG_DENSITY,
    gl::FOG_COLOR,
    gl::FOG_COORD_SRC,
    gl::FOG_COORD,
    gl::FRAGMENT_DEPTH,
    gl::LINEAR,
    gl::EXP,
    gl::EXP2,
    gl::KEEP,
    gl::INCR_WRAP,
    gl::DECR_WRAP,
    gl::INVERT,
    gl::SRC_ALPHA,
    gl::ONE_MINUS_SRC_ALPHA,
    gl::SRC_ALPHA_SATURATE,
    gl::CONSTANT_COLOR,
    gl::FUNC_ADD,
    gl::FUNC_REVERSE_SUBTRACT,
    gl::MIN,
    gl::MAX,
    gl::CLEAR,
    gl::SET,
    gl::SET + 1,
    // --- end fragment ops
    0,
    1,
    u32::MAX,
    // --- arrays
    gl::VERTEX_ARRAY,
    gl::COLOR_ARRAY,
    gl::NORMAL_ARRAY,
    gl::TEXTURE_COORD_ARRAY,
    gl::EDGE_FLAG_ARRAY,
    gl::BYTE,
    gl::UNSIGNED_BYTE,
    gl::SHORT,
    gl::UNSIGNED_SHORT,
    gl::UNSIGNED_INT,
    gl::FLOAT,
    gl::DOUBLE,
    gl::V3F,
    gl::C4UB_V3F,
    gl::T4F_C4F_N3F_V4F,
    gl::ARRAY_BUFFER,
    gl::ELEMENT_ARRAY_BUFFER,
    gl::STATIC_DRAW,
    gl::STREAM_COPY,
    // --- end arrays
];

/// Records `draw` on a CPU context of `w` x `w`, replays it on the driver, and returns the number
/// of pixels off by more than `tol`, with the first one for the message; `None` (a skip, said on
/// stderr) without a GL backend.
#[cfg(feature = "gl")]
pub fn cpu_vs_gl(
    w: u32,
    tol: u8,
    draw: impl FnOnce(&mut fixedgl::Context),
) -> Option<(u64, String)> {
    use fixedgl::{gl, Context};
    let mut backend = test_backend(w, w)?;
    let Ok(mut cpu) = Context::new(w, w) else {
        panic!("CPU context")
    };
    cpu.start_recording();
    draw(&mut cpu);
    let calls = cpu.stop_recording();
    assert_eq!(cpu.get_error(), gl::NO_ERROR);
    backend.replay(&calls);
    assert_eq!(backend.get_error(), gl::NO_ERROR);
    let (ci, gi) = (cpu.to_image(), backend.read_image());
    let cmp = fixedgl::compare::compare(&ci, &gi, tol);
    let first = ci
        .enumerate_pixels()
        .find(|(x, y, p)| {
            let q = gi.get_pixel(*x, *y);
            p.0.iter().zip(q.0).any(|(a, b)| a.abs_diff(b) > tol)
        })
        .map(|(x, y, p)| format!("({x},{y}) cpu {:?} gl {:?}", p.0, gi.get_pixel(x, y).0))
        .unwrap_or_default();
    Some((cmp.differing_pixels, first))
}
