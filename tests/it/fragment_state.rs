//! Fog, alpha test, stencil, blending and logic op state (GL 2.1 §3.10, §4.1, tables 6.8, 6.20,
//! 6.21): initial values through the queries, what valid calls store (clamps included), and an
//! error table whose every row must set its error and leave the State exactly as it was.

use fixedgl::{gl, Context};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;

fn ctx() -> Context {
    match Context::new(4, 4) {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    }
}

fn getf(c: &mut Context, pname: u32, n: usize) -> Vec<f32> {
    let mut v = vec![f32::NAN; n];
    c.get_floatv(pname, &mut v);
    v
}

fn geti(c: &mut Context, pname: u32) -> i32 {
    let mut v = [i32::MIN];
    c.get_integerv(pname, &mut v);
    v[0]
}

#[test]
fn initial_values_match_the_state_tables() {
    let mut c = ctx();
    // (pname, initial value as GetIntegerv reports it); tables 6.8, 6.20, 6.21.
    let rows: &[(u32, i32)] = &[
        (gl::FOG_MODE, gl::EXP as i32),
        (gl::FOG_COORD_SRC, gl::FRAGMENT_DEPTH as i32),
        (gl::FOG_DENSITY, 1),
        (gl::FOG_START, 0),
        (gl::FOG_END, 1),
        (gl::FOG_INDEX, 0),
        (gl::ALPHA_TEST_FUNC, gl::ALWAYS as i32),
        (gl::STENCIL_FUNC, gl::ALWAYS as i32),
        (gl::STENCIL_REF, 0),
        (gl::STENCIL_VALUE_MASK, 255),
        (gl::STENCIL_FAIL, gl::KEEP as i32),
        (gl::STENCIL_PASS_DEPTH_FAIL, gl::KEEP as i32),
        (gl::STENCIL_PASS_DEPTH_PASS, gl::KEEP as i32),
        (gl::STENCIL_BACK_FUNC, gl::ALWAYS as i32),
        (gl::STENCIL_BACK_REF, 0),
        (gl::STENCIL_BACK_VALUE_MASK, 255),
        (gl::STENCIL_BACK_FAIL, gl::KEEP as i32),
        (gl::STENCIL_BACK_PASS_DEPTH_FAIL, gl::KEEP as i32),
        (gl::STENCIL_BACK_PASS_DEPTH_PASS, gl::KEEP as i32),
        (gl::STENCIL_WRITEMASK, 255),
        (gl::STENCIL_BACK_WRITEMASK, 255),
        (gl::BLEND_SRC, gl::ONE as i32),
        (gl::BLEND_DST, gl::ZERO as i32),
        (gl::BLEND_SRC_RGB, gl::ONE as i32),
        (gl::BLEND_DST_RGB, gl::ZERO as i32),
        (gl::BLEND_SRC_ALPHA, gl::ONE as i32),
        (gl::BLEND_DST_ALPHA, gl::ZERO as i32),
        (gl::BLEND_EQUATION_RGB, gl::FUNC_ADD as i32),
        (gl::BLEND_EQUATION_ALPHA, gl::FUNC_ADD as i32),
        (gl::LOGIC_OP_MODE, gl::COPY as i32),
        (gl::FOG, 0),
        (gl::ALPHA_TEST, 0),
        (gl::STENCIL_TEST, 0),
        (gl::BLEND, 0),
        (gl::COLOR_LOGIC_OP, 0),
        (gl::COLOR_SUM, 0),
        (gl::DITHER, 1),
    ];
    for &(pname, want) in rows {
        assert_eq!(geti(&mut c, pname), want, "{pname:#x}");
    }
    assert_eq!(getf(&mut c, gl::FOG_COLOR, 4), [0.0; 4]);
    assert_eq!(getf(&mut c, gl::BLEND_COLOR, 4), [0.0; 4]);
    assert_eq!(getf(&mut c, gl::ALPHA_TEST_REF, 1), [0.0]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn valid_calls_store_and_clamp() {
    let mut c = ctx();
    c.fogi(gl::FOG_MODE, gl::LINEAR as i32);
    c.fogf(gl::FOG_START, -3.5);
    c.fogf(gl::FOG_END, 40.0);
    c.fogf(gl::FOG_DENSITY, 0.0);
    c.fogfv(gl::FOG_COLOR, &[1.5, 0.25, -1.0, 0.5]);
    c.fogi(gl::FOG_COORD_SRC, gl::FOG_COORD as i32);
    assert_eq!(geti(&mut c, gl::FOG_MODE), gl::LINEAR as i32);
    assert_eq!(getf(&mut c, gl::FOG_START, 1), [-3.5]);
    assert_eq!(getf(&mut c, gl::FOG_END, 1), [40.0]);
    assert_eq!(getf(&mut c, gl::FOG_DENSITY, 1), [0.0]);
    // §3.10: FOG_COLOR clamped to [0, 1] when specified.
    assert_eq!(getf(&mut c, gl::FOG_COLOR, 4), [1.0, 0.25, 0.0, 0.5]);
    assert_eq!(geti(&mut c, gl::FOG_COORD_SRC), gl::FOG_COORD as i32);
    // Fogiv colour: the most positive integer maps to 1.0, 0 to 1/(2^32 − 1) ≈ 0 (table 2.9).
    c.fogiv(gl::FOG_COLOR, &[i32::MAX, 0, i32::MAX, i32::MAX]);
    let fc = getf(&mut c, gl::FOG_COLOR, 4);
    assert_eq!([fc[0], fc[2], fc[3]], [1.0; 3]);
    assert!(fc[1].abs() < 1e-9);
    // §4.1.4: the reference clamped to [0, 1].
    c.alpha_func(gl::GEQUAL, 1.5);
    assert_eq!(getf(&mut c, gl::ALPHA_TEST_REF, 1), [1.0]);
    c.alpha_func(gl::LESS, -0.5);
    assert_eq!(getf(&mut c, gl::ALPHA_TEST_REF, 1), [0.0]);
    assert_eq!(geti(&mut c, gl::ALPHA_TEST_FUNC), gl::LESS as i32);
    // §4.1.5: STENCIL_REF is reported clamped to [0, 2^8 − 1]; each face separately.
    c.stencil_func(gl::GEQUAL, 300, 0x0F);
    assert_eq!(geti(&mut c, gl::STENCIL_REF), 255);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_REF), 255);
    c.stencil_func_separate(gl::BACK, gl::NOTEQUAL, -4, 0xF0);
    assert_eq!(geti(&mut c, gl::STENCIL_FUNC), gl::GEQUAL as i32);
    assert_eq!(geti(&mut c, gl::STENCIL_VALUE_MASK), 0x0F);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_FUNC), gl::NOTEQUAL as i32);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_REF), 0);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_VALUE_MASK), 0xF0);
    c.stencil_op_separate(gl::FRONT, gl::INCR_WRAP, gl::DECR_WRAP, gl::INVERT);
    assert_eq!(geti(&mut c, gl::STENCIL_FAIL), gl::INCR_WRAP as i32);
    assert_eq!(
        geti(&mut c, gl::STENCIL_PASS_DEPTH_FAIL),
        gl::DECR_WRAP as i32
    );
    assert_eq!(geti(&mut c, gl::STENCIL_PASS_DEPTH_PASS), gl::INVERT as i32);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_FAIL), gl::KEEP as i32);
    c.stencil_mask(0x3C);
    c.stencil_mask_separate(gl::BACK, 0x81);
    assert_eq!(geti(&mut c, gl::STENCIL_WRITEMASK), 0x3C);
    assert_eq!(geti(&mut c, gl::STENCIL_BACK_WRITEMASK), 0x81);
    // An unsigned mask past i32::MAX saturates in GetIntegerv (§6.1.2), as the driver does.
    c.stencil_mask(0xFFFF_FF0F);
    assert_eq!(geti(&mut c, gl::STENCIL_WRITEMASK), i32::MAX);
    // §4.1.8.
    c.blend_func_separate(
        gl::SRC_ALPHA_SATURATE,
        gl::CONSTANT_COLOR,
        gl::DST_ALPHA,
        gl::ONE_MINUS_CONSTANT_ALPHA,
    );
    assert_eq!(geti(&mut c, gl::BLEND_SRC), gl::SRC_ALPHA_SATURATE as i32);
    assert_eq!(geti(&mut c, gl::BLEND_DST_RGB), gl::CONSTANT_COLOR as i32);
    assert_eq!(geti(&mut c, gl::BLEND_SRC_ALPHA), gl::DST_ALPHA as i32);
    assert_eq!(
        geti(&mut c, gl::BLEND_DST_ALPHA),
        gl::ONE_MINUS_CONSTANT_ALPHA as i32
    );
    c.blend_equation_separate(gl::MIN, gl::FUNC_REVERSE_SUBTRACT);
    assert_eq!(geti(&mut c, gl::BLEND_EQUATION), gl::MIN as i32);
    assert_eq!(
        geti(&mut c, gl::BLEND_EQUATION_ALPHA),
        gl::FUNC_REVERSE_SUBTRACT as i32
    );
    c.blend_color(-1.0, 0.5, 2.0, 0.25);
    assert_eq!(getf(&mut c, gl::BLEND_COLOR, 4), [0.0, 0.5, 1.0, 0.25]);
    c.logic_op(gl::NAND);
    assert_eq!(geti(&mut c, gl::LOGIC_OP_MODE), gl::NAND as i32);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

type Step = fn(&mut Context);

fn none(_: &mut Context) {}

fn inside(c: &mut Context) {
    c.begin(gl::TRIANGLES);
}

/// Non-initial fragment state, so "unchanged" is not just "still initial".
fn set(c: &mut Context) {
    c.fogi(gl::FOG_MODE, gl::EXP2 as i32);
    c.fogf(gl::FOG_DENSITY, 0.5);
    c.alpha_func(gl::GREATER, 0.25);
    c.stencil_func(gl::LESS, 3, 0x7F);
    c.stencil_op(gl::ZERO, gl::INCR, gl::DECR);
    c.blend_func(gl::SRC_ALPHA, gl::ONE);
    c.blend_equation(gl::FUNC_SUBTRACT);
    c.logic_op(gl::XOR);
}

#[rustfmt::skip]
const ROWS: &[(&str, Step, Step, u32)] = &[
    // Fog (GL 2.1 §3.10, glFog reference page).
    ("Fogi bad pname", set, |c| c.fogi(gl::FOG_HINT, 0), IE),
    ("Fogi bad mode", set, |c| c.fogi(gl::FOG_MODE, gl::LINEAR as i32 + 7), IE),
    ("Fogf mode not exact", set, |c| c.fogf(gl::FOG_MODE, gl::EXP as f32 + 0.5), IE),
    ("Fogf negative density", set, |c| c.fogf(gl::FOG_DENSITY, -0.01), IV),
    ("Fogfv negative density", set, |c| c.fogfv(gl::FOG_DENSITY, &[-1.0]), IV),
    ("Fogi bad coord src", set, |c| c.fogi(gl::FOG_COORD_SRC, gl::FOG_HINT as i32), IE),
    ("Fogfv short FOG_COLOR", set, |c| c.fogfv(gl::FOG_COLOR, &[1.0, 1.0, 1.0]), IV),
    ("Fogiv short FOG_COLOR", set, |c| c.fogiv(gl::FOG_COLOR, &[1, 1]), IV),
    ("Fogfv empty", set, |c| c.fogfv(gl::FOG_START, &[]), IV),
    ("Fogfv bad pname", set, |c| c.fogfv(0x1234, &[1.0; 4]), IE),
    ("Fogf inside", inside, |c| c.fogf(gl::FOG_START, 1.0), IO),
    // AlphaFunc (§4.1.4).
    ("AlphaFunc bad func", set, |c| c.alpha_func(gl::ALWAYS + 1, 0.5), IE),
    ("AlphaFunc NEVER - 1", set, |c| c.alpha_func(gl::NEVER - 1, 0.5), IE),
    ("AlphaFunc inside", inside, |c| c.alpha_func(gl::LESS, 0.5), IO),
    // Stencil (§4.1.5, §4.2.2).
    ("StencilFunc bad func", set, |c| c.stencil_func(gl::KEEP, 0, 0xFF), IE),
    ("StencilFuncSeparate bad face", set, |c| c.stencil_func_separate(gl::LEFT, gl::LESS, 0, 0xFF), IE),
    ("StencilFuncSeparate bad func", set, |c| c.stencil_func_separate(gl::FRONT, 0, 0, 0xFF), IE),
    ("StencilOp bad sfail", set, |c| c.stencil_op(gl::NEVER, gl::KEEP, gl::KEEP), IE),
    ("StencilOp bad dpfail", set, |c| c.stencil_op(gl::KEEP, gl::INCR_WRAP + 2, gl::KEEP), IE),
    ("StencilOp bad dppass", set, |c| c.stencil_op(gl::KEEP, gl::KEEP, gl::ALWAYS), IE),
    ("StencilOpSeparate bad face", set, |c| c.stencil_op_separate(gl::FRONT_LEFT, gl::KEEP, gl::KEEP, gl::KEEP), IE),
    ("StencilMaskSeparate bad face", set, |c| c.stencil_mask_separate(gl::LEFT, 0), IE),
    ("StencilFunc inside", inside, |c| c.stencil_func(gl::LESS, 0, 0), IO),
    ("StencilOp inside", inside, |c| c.stencil_op(gl::KEEP, gl::KEEP, gl::KEEP), IO),
    ("StencilMask inside", inside, |c| c.stencil_mask(0), IO),
    // Blending (§4.1.8).
    ("BlendFunc bad src", set, |c| c.blend_func(gl::SRC_ALPHA + 0x100, gl::ONE), IE),
    ("BlendFunc SRC_ALPHA_SATURATE as dst", set, |c| c.blend_func(gl::ONE, gl::SRC_ALPHA_SATURATE), IE),
    ("BlendFuncSeparate bad dst alpha", set, |c| c.blend_func_separate(gl::ONE, gl::ONE, gl::ONE, gl::SRC_ALPHA_SATURATE), IE),
    ("BlendFuncSeparate bad src alpha", set, |c| c.blend_func_separate(gl::ONE, gl::ONE, gl::LESS, gl::ONE), IE),
    ("BlendEquation bad", set, |c| c.blend_equation(gl::FUNC_ADD + 0x20), IE),
    ("BlendEquation LOGIC_OP", set, |c| c.blend_equation(gl::LOGIC_OP), IE),
    ("BlendEquationSeparate bad alpha", set, |c| c.blend_equation_separate(gl::MIN, gl::ONE), IE),
    ("BlendFunc inside", inside, |c| c.blend_func(gl::ONE, gl::ONE), IO),
    ("BlendColor inside", inside, |c| c.blend_color(1.0, 1.0, 1.0, 1.0), IO),
    ("BlendEquation inside", inside, |c| c.blend_equation(gl::MAX), IO),
    // LogicOp (§4.1.10).
    ("LogicOp below CLEAR", set, |c| c.logic_op(gl::CLEAR - 1), IE),
    ("LogicOp above SET", set, |c| c.logic_op(gl::SET + 1), IE),
    ("LogicOp inside", inside, |c| c.logic_op(gl::COPY), IO),
    ("LogicOp none", none, |c| c.logic_op(0), IE),
];

#[test]
fn every_row_sets_its_error_and_changes_nothing() {
    let mut failures = Vec::new();
    for &(name, setup, call, expected) in ROWS {
        let mut c = ctx();
        setup(&mut c);
        assert_eq!(c.pending_error(), gl::NO_ERROR, "{name}: setup");
        let before = c.state().clone();
        call(&mut c);
        let got = c.pending_error();
        if got != expected {
            failures.push(format!("{name}: expected {expected:#x}, got {got:#x}"));
        }
        if *c.state() != before {
            failures.push(format!("{name}: state changed"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
