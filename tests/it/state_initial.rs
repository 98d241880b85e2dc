//! A fresh context reports the GL 2.1 initial state (§6.2, tables 6.5 onward) through every
//! query: `get_{boolean,integer,float,double}v`, `get_light*`, `get_material*`,
//! `get_clip_plane`, `get_string` and `is_enabled`.
//!
//! Each row is `(pname, expected value in the type of the getter that asks)`, transcribed from
//! the spec's tables; integer forms of colours, normals and depth values follow table 4.9,
//! c = ((2³² − 1)·f − 1) / 2 (1.0 → 2147483647, 0.0 → 0, f32 0.2 → 429496735,
//! f32 0.8 → 1717986943, worked by hand in the comments of `get_integer_conversions`).
//! Implementation-dependent rows hold fixedgl's documented values.

use fixedgl::{gl, Context};

/// The framebuffer size every test uses; VIEWPORT and SCISSOR_BOX start as (0, 0, W, H).
const W: i32 = 64;
const H: i32 = 48;

fn ctx() -> Context {
    match Context::new(W as u32, H as u32) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// An expected value, typed as the getter that is to be asked for it.
#[derive(Debug)]
enum Want {
    B(&'static [bool]),
    I(&'static [i32]),
    F(&'static [f32]),
    D(&'static [f64]),
}
use Want::{B, D, F, I};

macro_rules! row {
    ($name:ident, $want:expr) => {
        (stringify!($name), gl::$name, $want)
    };
}

const ID: [f32; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];
const ID_D: [f64; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];
const ONE_I: i32 = 2147483647;
const DC: i32 = gl::DONT_CARE as i32;

/// GL 2.1 tables 6.5 to 6.40 (the state fixedgl keeps) and the implementation limits.
const GET_ROWS: &[(&str, u32, Want)] = &[
    // Table 6.5: current values.
    row!(CURRENT_COLOR, F(&[1.0, 1.0, 1.0, 1.0])),
    row!(CURRENT_COLOR, I(&[ONE_I, ONE_I, ONE_I, ONE_I])),
    row!(CURRENT_SECONDARY_COLOR, F(&[0.0, 0.0, 0.0, 1.0])),
    row!(CURRENT_SECONDARY_COLOR, I(&[0, 0, 0, ONE_I])),
    row!(CURRENT_TEXTURE_COORDS, D(&[0.0, 0.0, 0.0, 1.0])),
    row!(CURRENT_TEXTURE_COORDS, I(&[0, 0, 0, 1])),
    row!(CURRENT_NORMAL, F(&[0.0, 0.0, 1.0])),
    row!(CURRENT_NORMAL, I(&[0, 0, ONE_I])),
    row!(CURRENT_NORMAL, B(&[false, false, true])),
    row!(CURRENT_FOG_COORD, F(&[0.0])),
    row!(EDGE_FLAG, B(&[true])),
    row!(EDGE_FLAG, I(&[1])),
    // Table 6.5: the raster position and its associated data.
    row!(CURRENT_RASTER_POSITION, F(&[0.0, 0.0, 0.0, 1.0])),
    row!(CURRENT_RASTER_POSITION_VALID, B(&[true])),
    row!(CURRENT_RASTER_COLOR, F(&[1.0, 1.0, 1.0, 1.0])),
    row!(CURRENT_RASTER_COLOR, I(&[ONE_I, ONE_I, ONE_I, ONE_I])),
    row!(CURRENT_RASTER_SECONDARY_COLOR, F(&[0.0, 0.0, 0.0, 1.0])),
    row!(CURRENT_RASTER_INDEX, F(&[1.0])),
    row!(CURRENT_RASTER_TEXTURE_COORDS, F(&[0.0, 0.0, 0.0, 1.0])),
    row!(CURRENT_RASTER_DISTANCE, F(&[0.0])),
    // Tables 6.23, 6.24: pixel transfer, zoom, pixel maps.
    row!(MAP_COLOR, B(&[false])),
    row!(MAP_STENCIL, B(&[false])),
    row!(INDEX_SHIFT, I(&[0])),
    row!(INDEX_OFFSET, I(&[0])),
    row!(RED_SCALE, F(&[1.0])),
    row!(GREEN_SCALE, F(&[1.0])),
    row!(BLUE_SCALE, F(&[1.0])),
    row!(ALPHA_SCALE, F(&[1.0])),
    row!(DEPTH_SCALE, F(&[1.0])),
    row!(RED_BIAS, F(&[0.0])),
    row!(GREEN_BIAS, F(&[0.0])),
    row!(BLUE_BIAS, F(&[0.0])),
    row!(ALPHA_BIAS, F(&[0.0])),
    row!(DEPTH_BIAS, F(&[0.0])),
    row!(ZOOM_X, F(&[1.0])),
    row!(ZOOM_Y, F(&[1.0])),
    row!(PIXEL_MAP_I_TO_I_SIZE, I(&[1])),
    row!(PIXEL_MAP_S_TO_S_SIZE, I(&[1])),
    row!(PIXEL_MAP_I_TO_R_SIZE, I(&[1])),
    row!(PIXEL_MAP_A_TO_A_SIZE, I(&[1])),
    row!(MAX_PIXEL_MAP_TABLE, I(&[256])),
    // Tables 6.7, 6.8: transformation.
    row!(MODELVIEW_MATRIX, F(&ID)),
    row!(MODELVIEW_MATRIX, D(&ID_D)),
    row!(PROJECTION_MATRIX, F(&ID)),
    row!(TEXTURE_MATRIX, F(&ID)),
    row!(TRANSPOSE_MODELVIEW_MATRIX, D(&ID_D)),
    row!(TRANSPOSE_PROJECTION_MATRIX, F(&ID)),
    row!(TRANSPOSE_TEXTURE_MATRIX, F(&ID)),
    row!(
        MODELVIEW_MATRIX,
        I(&[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    ),
    row!(MODELVIEW_STACK_DEPTH, I(&[1])),
    row!(PROJECTION_STACK_DEPTH, I(&[1])),
    row!(TEXTURE_STACK_DEPTH, I(&[1])),
    row!(MODELVIEW_STACK_DEPTH, F(&[1.0])),
    row!(MATRIX_MODE, I(&[gl::MODELVIEW as i32])),
    row!(VIEWPORT, I(&[0, 0, W, H])),
    row!(VIEWPORT, F(&[0.0, 0.0, W as f32, H as f32])),
    row!(DEPTH_RANGE, D(&[0.0, 1.0])),
    row!(DEPTH_RANGE, I(&[0, ONE_I])),
    row!(DEPTH_RANGE, B(&[false, true])),
    row!(NORMALIZE, B(&[false])),
    row!(RESCALE_NORMAL, B(&[false])),
    row!(CLIP_PLANE0, B(&[false])),
    row!(CLIP_PLANE5, I(&[0])),
    row!(ACTIVE_TEXTURE, I(&[gl::TEXTURE0 as i32])),
    row!(CLIENT_ACTIVE_TEXTURE, I(&[gl::TEXTURE0 as i32])),
    // Tables 6.8, 6.9: colouring and lighting.
    row!(SHADE_MODEL, I(&[gl::SMOOTH as i32])),
    row!(LIGHTING, B(&[false])),
    row!(COLOR_MATERIAL, B(&[false])),
    row!(
        COLOR_MATERIAL_PARAMETER,
        I(&[gl::AMBIENT_AND_DIFFUSE as i32])
    ),
    row!(COLOR_MATERIAL_FACE, I(&[gl::FRONT_AND_BACK as i32])),
    row!(LIGHT_MODEL_AMBIENT, F(&[0.2, 0.2, 0.2, 1.0])),
    row!(
        LIGHT_MODEL_AMBIENT,
        I(&[429496735, 429496735, 429496735, ONE_I])
    ),
    row!(LIGHT_MODEL_AMBIENT, B(&[true, true, true, true])),
    row!(LIGHT_MODEL_LOCAL_VIEWER, B(&[false])),
    row!(LIGHT_MODEL_TWO_SIDE, B(&[false])),
    row!(LIGHT_MODEL_TWO_SIDE, D(&[0.0])),
    row!(LIGHT_MODEL_COLOR_CONTROL, I(&[gl::SINGLE_COLOR as i32])),
    row!(LIGHT0, B(&[false])),
    row!(LIGHT7, B(&[false])),
    row!(FOG, B(&[false])),
    row!(COLOR_SUM, B(&[false])),
    // Tables 6.11 to 6.13: rasterisation.
    row!(POINT_SIZE, F(&[1.0])),
    row!(POINT_SIZE, I(&[1])),
    row!(POINT_SMOOTH, B(&[false])),
    row!(POINT_SPRITE, B(&[false])),
    row!(LINE_WIDTH, F(&[1.0])),
    row!(LINE_WIDTH, D(&[1.0])),
    row!(LINE_SMOOTH, B(&[false])),
    row!(LINE_STIPPLE, B(&[false])),
    row!(LINE_STIPPLE_PATTERN, I(&[0xFFFF])),
    row!(LINE_STIPPLE_REPEAT, I(&[1])),
    row!(CULL_FACE, B(&[false])),
    row!(CULL_FACE_MODE, I(&[gl::BACK as i32])),
    row!(FRONT_FACE, I(&[gl::CCW as i32])),
    row!(POLYGON_SMOOTH, B(&[false])),
    row!(POLYGON_MODE, I(&[gl::FILL as i32, gl::FILL as i32])),
    row!(POLYGON_MODE, F(&[gl::FILL as f32, gl::FILL as f32])),
    row!(POLYGON_OFFSET_FACTOR, F(&[0.0])),
    row!(POLYGON_OFFSET_UNITS, F(&[0.0])),
    row!(POLYGON_OFFSET_POINT, B(&[false])),
    row!(POLYGON_OFFSET_LINE, B(&[false])),
    row!(POLYGON_OFFSET_FILL, B(&[false])),
    row!(POLYGON_STIPPLE, B(&[false])),
    // Table 6.15: multisampling.
    row!(MULTISAMPLE, B(&[true])),
    row!(SAMPLE_ALPHA_TO_COVERAGE, B(&[false])),
    row!(SAMPLE_ALPHA_TO_ONE, B(&[false])),
    row!(SAMPLE_COVERAGE, B(&[false])),
    row!(SAMPLE_COVERAGE_VALUE, F(&[1.0])),
    row!(SAMPLE_COVERAGE_INVERT, B(&[false])),
    // Tables 6.16, 6.19: texture enables and generation (unit 0).
    row!(TEXTURE_1D, B(&[false])),
    row!(TEXTURE_2D, B(&[false])),
    row!(TEXTURE_3D, B(&[false])),
    row!(TEXTURE_CUBE_MAP, B(&[false])),
    row!(TEXTURE_GEN_S, B(&[false])),
    row!(TEXTURE_GEN_Q, I(&[0])),
    // Tables 6.20, 6.21: pixel operations.
    row!(SCISSOR_TEST, B(&[false])),
    row!(SCISSOR_BOX, I(&[0, 0, W, H])),
    row!(ALPHA_TEST, B(&[false])),
    row!(STENCIL_TEST, B(&[false])),
    row!(DEPTH_TEST, B(&[false])),
    row!(DEPTH_FUNC, I(&[gl::LESS as i32])),
    row!(BLEND, B(&[false])),
    row!(DITHER, B(&[true])),
    row!(INDEX_LOGIC_OP, B(&[false])),
    row!(COLOR_LOGIC_OP, B(&[false])),
    // Table 6.22: framebuffer control (STENCIL_WRITEMASK: "1's", the stencil buffer's 8 bits, as
    // the driver reports it).
    row!(COLOR_WRITEMASK, B(&[true, true, true, true])),
    row!(COLOR_WRITEMASK, I(&[1, 1, 1, 1])),
    row!(DEPTH_WRITEMASK, B(&[true])),
    row!(STENCIL_WRITEMASK, I(&[255])),
    row!(COLOR_CLEAR_VALUE, F(&[0.0, 0.0, 0.0, 0.0])),
    row!(COLOR_CLEAR_VALUE, I(&[0, 0, 0, 0])),
    row!(DEPTH_CLEAR_VALUE, D(&[1.0])),
    row!(DEPTH_CLEAR_VALUE, I(&[ONE_I])),
    row!(STENCIL_CLEAR_VALUE, I(&[0])),
    // INDEX_WRITEMASK: "1's", 32 of them; GetIntegerv saturates an unsigned value past i32::MAX
    // as it does STENCIL_WRITEMASK's (Mesa's int field gives -1).
    row!(INDEX_WRITEMASK, I(&[i32::MAX])),
    row!(INDEX_WRITEMASK, D(&[4_294_967_295.0])),
    row!(INDEX_CLEAR_VALUE, F(&[0.0])),
    // Table 6.24: pixel store.
    row!(UNPACK_ALIGNMENT, I(&[4])),
    row!(PACK_ALIGNMENT, I(&[4])),
    row!(PACK_ALIGNMENT, F(&[4.0])),
    // Tables 6.32, 6.37: evaluators, hints.
    row!(MAP1_VERTEX_3, B(&[false])),
    row!(MAP2_TEXTURE_COORD_2, B(&[false])),
    row!(AUTO_NORMAL, B(&[false])),
    row!(PERSPECTIVE_CORRECTION_HINT, I(&[DC])),
    row!(POINT_SMOOTH_HINT, I(&[DC])),
    row!(LINE_SMOOTH_HINT, I(&[DC])),
    row!(POLYGON_SMOOTH_HINT, I(&[DC])),
    row!(FOG_HINT, I(&[DC])),
    row!(GENERATE_MIPMAP_HINT, I(&[DC])),
    row!(TEXTURE_COMPRESSION_HINT, I(&[DC])),
    row!(FRAGMENT_SHADER_DERIVATIVE_HINT, I(&[DC])),
    row!(PHONG_HINT_WIN, I(&[DC])),
    row!(VERTEX_PROGRAM_POINT_SIZE, B(&[false])),
    row!(VERTEX_PROGRAM_TWO_SIDE, B(&[false])),
    // Tables 6.34 onward: implementation-dependent values.
    row!(MAX_LIGHTS, I(&[8])),
    row!(MAX_CLIP_PLANES, I(&[6])),
    row!(MAX_MODELVIEW_STACK_DEPTH, I(&[32])),
    row!(MAX_PROJECTION_STACK_DEPTH, I(&[32])),
    row!(MAX_TEXTURE_STACK_DEPTH, I(&[10])),
    row!(MAX_VIEWPORT_DIMS, I(&[16384, 16384])),
    row!(MAX_TEXTURE_UNITS, I(&[4])),
    row!(MAX_TEXTURE_SIZE, I(&[2048])),
    row!(MAX_TEXTURE_SIZE, F(&[2048.0])),
    row!(SUBPIXEL_BITS, I(&[8])),
    row!(RED_BITS, I(&[8])),
    row!(GREEN_BITS, I(&[8])),
    row!(BLUE_BITS, I(&[8])),
    row!(ALPHA_BITS, I(&[8])),
    row!(DEPTH_BITS, I(&[24])),
    row!(STENCIL_BITS, I(&[8])),
    row!(INDEX_BITS, I(&[0])),
    row!(ACCUM_RED_BITS, I(&[0])),
    row!(ACCUM_ALPHA_BITS, I(&[0])),
    row!(AUX_BUFFERS, I(&[0])),
    row!(SAMPLE_BUFFERS, I(&[0])),
    row!(SAMPLES, I(&[0])),
    row!(RGBA_MODE, B(&[true])),
    row!(INDEX_MODE, B(&[false])),
    row!(DOUBLEBUFFER, B(&[false])),
    row!(STEREO, B(&[false])),
    // Tables 6.22, 6.26, 6.31: buffers, render mode, selection and feedback.
    row!(DRAW_BUFFER, I(&[gl::FRONT as i32])),
    row!(READ_BUFFER, I(&[gl::FRONT as i32])),
    row!(ACCUM_CLEAR_VALUE, F(&[0.0, 0.0, 0.0, 0.0])),
    row!(ACCUM_CLEAR_VALUE, I(&[0, 0, 0, 0])),
    row!(RENDER_MODE, I(&[gl::RENDER as i32])),
    row!(NAME_STACK_DEPTH, I(&[0])),
    row!(MAX_NAME_STACK_DEPTH, I(&[64])),
    row!(SELECTION_BUFFER_SIZE, I(&[0])),
    row!(FEEDBACK_BUFFER_SIZE, I(&[0])),
    row!(FEEDBACK_BUFFER_TYPE, I(&[gl::GL_2D as i32])),
    row!(ALIASED_POINT_SIZE_RANGE, F(&[1.0, 255.0])),
    row!(SMOOTH_POINT_SIZE_RANGE, F(&[1.0, 255.0])),
    row!(POINT_SIZE_RANGE, I(&[1, 255])),
    row!(SMOOTH_POINT_SIZE_GRANULARITY, F(&[0.1])),
    row!(ALIASED_LINE_WIDTH_RANGE, F(&[1.0, 255.0])),
    row!(SMOOTH_LINE_WIDTH_RANGE, D(&[1.0, 255.0])),
    row!(LINE_WIDTH_GRANULARITY, F(&[0.1])),
];

/// Runs one row: the getter its type names, a buffer one longer than the value with a
/// sentinel at the end (exactly `len` values are written), and no error.
fn check_row(c: &mut Context, name: &str, pname: u32, want: &Want) {
    match want {
        B(w) => {
            let mut out = vec![false; w.len() + 1];
            out[w.len()] = true;
            c.get_booleanv(pname, &mut out);
            assert_eq!(&out[..w.len()], *w, "{name}");
            assert!(out[w.len()], "{name}: wrote past its count");
        }
        I(w) => {
            let mut out = vec![-7; w.len() + 1];
            c.get_integerv(pname, &mut out);
            assert_eq!(&out[..w.len()], *w, "{name}");
            assert_eq!(out[w.len()], -7, "{name}: wrote past its count");
        }
        F(w) => {
            let mut out = vec![-7.0; w.len() + 1];
            c.get_floatv(pname, &mut out);
            assert_eq!(&out[..w.len()], *w, "{name}");
            assert_eq!(out[w.len()], -7.0, "{name}: wrote past its count");
        }
        D(w) => {
            let mut out = vec![-7.0; w.len() + 1];
            c.get_doublev(pname, &mut out);
            assert_eq!(&out[..w.len()], *w, "{name}");
            assert_eq!(out[w.len()], -7.0, "{name}: wrote past its count");
        }
    }
    assert_eq!(c.get_error(), gl::NO_ERROR, "{name}");
}

#[test]
fn get_rows_report_the_initial_state() {
    let mut c = ctx();
    for (name, pname, want) in GET_ROWS {
        check_row(&mut c, name, *pname, want);
    }
}

#[test]
fn every_getter_type_is_exercised() {
    let (mut b, mut i, mut f, mut d) = (0, 0, 0, 0);
    for (_, _, want) in GET_ROWS {
        match want {
            B(_) => b += 1,
            I(_) => i += 1,
            F(_) => f += 1,
            D(_) => d += 1,
        }
    }
    assert!(b > 10 && i > 10 && f > 10 && d > 5, "{b} {i} {f} {d}");
}

#[test]
fn get_integer_conversions() {
    let mut c = ctx();
    // f32 0.2 is 13421773/2^26: (2^32 − 1)·f = 858993471.8, minus 1, halved: 429496735.4.
    // f32 0.8 is 13421773/2^24: 3435973887.2 − 1 = 3435973886.2, halved: 1717986943.1.
    c.color4f(0.8, -1.0, 0.5, 0.2);
    let mut out = [0i32; 4];
    c.get_integerv(gl::CURRENT_COLOR, &mut out);
    // −1.0 → (−(2^32 − 1) − 1)/2 = −2^31; 0.5 → (2147483647.5 − 1)/2 = 1073741823.25.
    assert_eq!(out, [1717986943, -2147483648, 1073741823, 429496735]);
    // A non-colour float rounds to nearest.
    c.translatef(2.5, -2.5, 0.4);
    let mut m = [0i32; 16];
    c.get_integerv(gl::MODELVIEW_MATRIX, &mut m);
    assert_eq!(&m[12..], &[3, -3, 0, 1]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// GL 2.1 table 6.10, per light: (pname, LIGHT0's value, the other lights' value).
const LIGHT_ROWS: &[(&str, u32, &[f32], &[f32])] = &[
    (
        "AMBIENT",
        gl::AMBIENT,
        &[0.0, 0.0, 0.0, 1.0],
        &[0.0, 0.0, 0.0, 1.0],
    ),
    (
        "DIFFUSE",
        gl::DIFFUSE,
        &[1.0, 1.0, 1.0, 1.0],
        &[0.0, 0.0, 0.0, 1.0],
    ),
    (
        "SPECULAR",
        gl::SPECULAR,
        &[1.0, 1.0, 1.0, 1.0],
        &[0.0, 0.0, 0.0, 1.0],
    ),
    (
        "POSITION",
        gl::POSITION,
        &[0.0, 0.0, 1.0, 0.0],
        &[0.0, 0.0, 1.0, 0.0],
    ),
    (
        "SPOT_DIRECTION",
        gl::SPOT_DIRECTION,
        &[0.0, 0.0, -1.0],
        &[0.0, 0.0, -1.0],
    ),
    ("SPOT_EXPONENT", gl::SPOT_EXPONENT, &[0.0], &[0.0]),
    ("SPOT_CUTOFF", gl::SPOT_CUTOFF, &[180.0], &[180.0]),
    (
        "CONSTANT_ATTENUATION",
        gl::CONSTANT_ATTENUATION,
        &[1.0],
        &[1.0],
    ),
    ("LINEAR_ATTENUATION", gl::LINEAR_ATTENUATION, &[0.0], &[0.0]),
    (
        "QUADRATIC_ATTENUATION",
        gl::QUADRATIC_ATTENUATION,
        &[0.0],
        &[0.0],
    ),
];

#[test]
fn lights_report_table_6_10() {
    let mut c = ctx();
    for light in 0..8u32 {
        for (name, pname, first, others) in LIGHT_ROWS {
            let want = if light == 0 { first } else { others };
            let mut out = vec![-7.0f32; want.len() + 1];
            c.get_lightfv(gl::LIGHT0 + light, *pname, &mut out);
            assert_eq!(&out[..want.len()], *want, "LIGHT{light} {name}");
            assert_eq!(
                out[want.len()],
                -7.0,
                "LIGHT{light} {name}: wrote past its count"
            );
            assert_eq!(c.get_error(), gl::NO_ERROR, "LIGHT{light} {name}");
        }
    }
}

#[test]
fn light_integer_forms() {
    let mut c = ctx();
    let mut out = [0i32; 4];
    // Colours map linearly: 1.0 → 2^31 − 1.
    c.get_lightiv(gl::LIGHT0, gl::DIFFUSE, &mut out);
    assert_eq!(out, [ONE_I, ONE_I, ONE_I, ONE_I]);
    c.get_lightiv(gl::LIGHT3, gl::SPECULAR, &mut out);
    assert_eq!(out, [0, 0, 0, ONE_I]);
    // Everything else rounds to nearest.
    c.get_lightiv(gl::LIGHT5, gl::POSITION, &mut out);
    assert_eq!(out, [0, 0, 1, 0]);
    let mut dir = [0i32; 3];
    c.get_lightiv(gl::LIGHT1, gl::SPOT_DIRECTION, &mut dir);
    assert_eq!(dir, [0, 0, -1]);
    let mut one = [0i32];
    c.get_lightiv(gl::LIGHT7, gl::SPOT_CUTOFF, &mut one);
    assert_eq!(one, [180]);
    c.get_lightiv(gl::LIGHT2, gl::CONSTANT_ATTENUATION, &mut one);
    assert_eq!(one, [1]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// GL 2.1 table 6.9, material rows (the same for FRONT and BACK).
const MATERIAL_ROWS: &[(&str, u32, &[f32], &[i32])] = &[
    (
        "AMBIENT",
        gl::AMBIENT,
        &[0.2, 0.2, 0.2, 1.0],
        &[429496735, 429496735, 429496735, ONE_I],
    ),
    (
        "DIFFUSE",
        gl::DIFFUSE,
        &[0.8, 0.8, 0.8, 1.0],
        &[1717986943, 1717986943, 1717986943, ONE_I],
    ),
    (
        "SPECULAR",
        gl::SPECULAR,
        &[0.0, 0.0, 0.0, 1.0],
        &[0, 0, 0, ONE_I],
    ),
    (
        "EMISSION",
        gl::EMISSION,
        &[0.0, 0.0, 0.0, 1.0],
        &[0, 0, 0, ONE_I],
    ),
    ("SHININESS", gl::SHININESS, &[0.0], &[0]),
    (
        "COLOR_INDEXES",
        gl::COLOR_INDEXES,
        &[0.0, 1.0, 1.0],
        &[0, 1, 1],
    ),
];

#[test]
fn materials_report_table_6_9() {
    let mut c = ctx();
    for face in [gl::FRONT, gl::BACK] {
        for (name, pname, fv, iv) in MATERIAL_ROWS {
            let mut out = vec![-7.0f32; fv.len() + 1];
            c.get_materialfv(face, *pname, &mut out);
            assert_eq!(&out[..fv.len()], *fv, "{face:#x} {name}");
            assert_eq!(
                out[fv.len()],
                -7.0,
                "{face:#x} {name}: wrote past its count"
            );
            let mut out = vec![-7i32; iv.len() + 1];
            c.get_materialiv(face, *pname, &mut out);
            assert_eq!(&out[..iv.len()], *iv, "{face:#x} {name}");
            assert_eq!(out[iv.len()], -7, "{face:#x} {name}: wrote past its count");
            assert_eq!(c.get_error(), gl::NO_ERROR, "{face:#x} {name}");
        }
    }
}

#[test]
fn clip_planes_start_at_zero() {
    let mut c = ctx();
    for p in 0..6 {
        let mut eq = [f64::NAN; 4];
        c.get_clip_plane(gl::CLIP_PLANE0 + p, &mut eq);
        assert_eq!(eq, [0.0; 4], "CLIP_PLANE{p}");
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn strings() {
    let mut c = ctx();
    assert_eq!(c.get_string(gl::VENDOR), Some("fixedgl"));
    assert_eq!(c.get_string(gl::RENDERER), Some("fixedgl CPU rasterizer"));
    let version = c.get_string(gl::VERSION);
    assert!(
        version.is_some_and(|v| v.starts_with("1.5 ")),
        "{version:?}"
    );
    let ext = c.get_string(gl::EXTENSIONS).unwrap_or_default();
    assert!(
        ext.ends_with(' '),
        "each name ends with a space, as Mesa's: {ext:?}"
    );
    let names: Vec<&str> = ext.split_whitespace().collect();
    for want in [
        "GL_ARB_texture_env_crossbar",
        "GL_ARB_vertex_buffer_object",
        "GL_ARB_window_pos",
        "GL_EXT_packed_depth_stencil",
        "GL_WIN_phong_shading",
    ] {
        assert!(names.contains(&want), "{want} in {ext:?}");
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// Every capability `is_enabled` accepts, with its initial value (GL 2.1 tables 6.x, the
/// "IsEnabled" rows): all false except DITHER and MULTISAMPLE.
const ENABLE_ROWS: &[(&str, u32, bool)] = &[
    row!(LIGHTING, false),
    row!(LIGHT0, false),
    row!(LIGHT1, false),
    row!(LIGHT2, false),
    row!(LIGHT3, false),
    row!(LIGHT4, false),
    row!(LIGHT5, false),
    row!(LIGHT6, false),
    row!(LIGHT7, false),
    row!(NORMALIZE, false),
    row!(RESCALE_NORMAL, false),
    row!(COLOR_MATERIAL, false),
    row!(DEPTH_TEST, false),
    row!(CULL_FACE, false),
    row!(CLIP_PLANE0, false),
    row!(CLIP_PLANE1, false),
    row!(CLIP_PLANE2, false),
    row!(CLIP_PLANE3, false),
    row!(CLIP_PLANE4, false),
    row!(CLIP_PLANE5, false),
    row!(POLYGON_OFFSET_FILL, false),
    row!(POLYGON_OFFSET_LINE, false),
    row!(POLYGON_OFFSET_POINT, false),
    row!(SCISSOR_TEST, false),
    row!(ALPHA_TEST, false),
    row!(BLEND, false),
    row!(STENCIL_TEST, false),
    row!(FOG, false),
    row!(COLOR_SUM, false),
    row!(COLOR_LOGIC_OP, false),
    row!(INDEX_LOGIC_OP, false),
    row!(DITHER, true),
    row!(LINE_SMOOTH, false),
    row!(LINE_STIPPLE, false),
    row!(POINT_SMOOTH, false),
    row!(POINT_SPRITE, false),
    row!(POLYGON_SMOOTH, false),
    row!(POLYGON_STIPPLE, false),
    row!(AUTO_NORMAL, false),
    row!(MULTISAMPLE, true),
    row!(SAMPLE_ALPHA_TO_COVERAGE, false),
    row!(SAMPLE_ALPHA_TO_ONE, false),
    row!(SAMPLE_COVERAGE, false),
    row!(VERTEX_PROGRAM_POINT_SIZE, false),
    row!(VERTEX_PROGRAM_TWO_SIDE, false),
    row!(MAP1_COLOR_4, false),
    row!(MAP1_INDEX, false),
    row!(MAP1_NORMAL, false),
    row!(MAP1_TEXTURE_COORD_1, false),
    row!(MAP1_TEXTURE_COORD_2, false),
    row!(MAP1_TEXTURE_COORD_3, false),
    row!(MAP1_TEXTURE_COORD_4, false),
    row!(MAP1_VERTEX_3, false),
    row!(MAP1_VERTEX_4, false),
    row!(MAP2_COLOR_4, false),
    row!(MAP2_INDEX, false),
    row!(MAP2_NORMAL, false),
    row!(MAP2_TEXTURE_COORD_1, false),
    row!(MAP2_TEXTURE_COORD_2, false),
    row!(MAP2_TEXTURE_COORD_3, false),
    row!(MAP2_TEXTURE_COORD_4, false),
    row!(MAP2_VERTEX_3, false),
    row!(MAP2_VERTEX_4, false),
];

/// Per texture unit (selected by ACTIVE_TEXTURE), all initially false (tables 6.16, 6.19).
const UNIT_ENABLE_ROWS: &[(&str, u32, bool)] = &[
    row!(TEXTURE_1D, false),
    row!(TEXTURE_2D, false),
    row!(TEXTURE_3D, false),
    row!(TEXTURE_CUBE_MAP, false),
    row!(TEXTURE_GEN_S, false),
    row!(TEXTURE_GEN_T, false),
    row!(TEXTURE_GEN_R, false),
    row!(TEXTURE_GEN_Q, false),
];

#[test]
fn is_enabled_for_every_capability() {
    let mut c = ctx();
    for (name, cap, want) in ENABLE_ROWS {
        assert_eq!(c.is_enabled(*cap), *want, "{name}");
        // The same state through glGet (GL 2.1 §6.1.1: enables are also Get pnames).
        let mut b = [!want];
        c.get_booleanv(*cap, &mut b);
        assert_eq!(b, [*want], "get_booleanv({name})");
        assert_eq!(c.get_error(), gl::NO_ERROR, "{name}");
    }
    for unit in 0..4 {
        c.active_texture(gl::TEXTURE0 + unit);
        for (name, cap, want) in UNIT_ENABLE_ROWS {
            assert_eq!(c.is_enabled(*cap), *want, "unit {unit} {name}");
            assert_eq!(c.get_error(), gl::NO_ERROR, "unit {unit} {name}");
        }
    }
}

#[test]
fn there_are_at_least_150_rows() {
    let rows = GET_ROWS.len()
        + LIGHT_ROWS.len() * 8
        + MATERIAL_ROWS.len() * 2
        + ENABLE_ROWS.len()
        + UNIT_ENABLE_ROWS.len() * 4;
    assert!(rows >= 150, "{rows}");
}

#[test]
fn configured_framebuffers_report_their_buffers() {
    let config = fixedgl::ContextConfig {
        double_buffered: true,
        depth: false,
        stencil: true,
        accum: true,
        alpha: true,
    };
    let mut c = Context::with_config(16, 16, config).expect("context");
    for (name, pname, want) in [
        row!(DOUBLEBUFFER, B(&[true])),
        row!(DRAW_BUFFER, I(&[gl::BACK as i32])),
        row!(READ_BUFFER, I(&[gl::BACK as i32])),
        row!(DEPTH_BITS, I(&[0])),
        row!(STENCIL_BITS, I(&[8])),
        row!(ACCUM_RED_BITS, I(&[16])),
        row!(ACCUM_GREEN_BITS, I(&[16])),
        row!(ACCUM_BLUE_BITS, I(&[16])),
        row!(ACCUM_ALPHA_BITS, I(&[16])),
    ] {
        check_row(&mut c, name, pname, &want);
    }
    assert_eq!(c.config(), config);
    // reset keeps the configuration.
    c.draw_buffer(gl::FRONT);
    c.reset();
    check_row(
        &mut c,
        "DRAW_BUFFER",
        gl::DRAW_BUFFER,
        &I(&[gl::BACK as i32]),
    );
}
