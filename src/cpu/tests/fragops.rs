//! Fog, alpha test, stencil, blending and logic op: the operations one by one with values worked
//! out by hand from GL 2.1 §3.10 and §4.1, then through the whole pipeline on a small context.

use glam::{Vec3, Vec4};

use crate::cpu::fragops::{
    compare, equation, factor, logic_op, mul8, stencil_op, BlendEval, FogEval, StencilSide,
};
use crate::cpu::framebuffer::unorm8;
use crate::gl;
use crate::Context;

#[test]
fn unorm8_is_255c_rounded_ties_to_even() {
    // 255·0.3 = 76.5 and 255·0.7 = 178.5 are ties (after the f32 product): even wins, as in
    // llvmpipe. 255·0.5 = 127.5 → 128 (even); 255·0.2 = 51; out of range clamps; NaN is 0.
    let rows = [
        (0.3, 76),
        (0.7, 178),
        (0.5, 128),
        (0.2, 51),
        (1.0, 255),
        (0.0, 0),
        (-1.0, 0),
        (2.0, 255),
        (f32::NAN, 0),
    ];
    for (c, want) in rows {
        assert_eq!(unorm8(c), want, "{c}");
    }
}

#[test]
fn every_stencil_op_including_the_wraps() {
    // §4.1.5 table: INCR/DECR clamp to [0, 255], the _WRAP forms wrap; REPLACE takes the ref.
    let rows = [
        (gl::KEEP, 5, 5),
        (gl::ZERO, 5, 0),
        (gl::REPLACE, 5, 9),
        (gl::INCR, 5, 6),
        (gl::INCR, 255, 255),
        (gl::DECR, 5, 4),
        (gl::DECR, 0, 0),
        (gl::INVERT, 0x0F, 0xF0),
        (gl::INCR_WRAP, 255, 0),
        (gl::INCR_WRAP, 7, 8),
        (gl::DECR_WRAP, 0, 255),
        (gl::DECR_WRAP, 7, 6),
    ];
    for (op, s, want) in rows {
        assert_eq!(stencil_op(op, s, 9), want, "op {op:#x} on {s}");
    }
}

#[test]
fn stencil_write_mask_and_value_mask() {
    let side = StencilSide {
        func: gl::EQUAL,
        reference: 0x55,
        mask: 0x0F,
        ops: [gl::KEEP, gl::KEEP, gl::REPLACE],
        write: 0x0F,
    };
    // §4.2.2: only the write mask's bits change: (0xAA & 0xF0) | (0x55 & 0x0F) = 0xA5.
    assert_eq!(side.update(2, 0xAA), 0xA5);
    assert_eq!(side.update(0, 0xAA), 0xAA);
    // §4.1.5: (ref & mask) = 0x05 against (s & mask): 0x35 → 0x05 passes, 0x36 → 0x06 fails.
    assert!(side.test(0x35));
    assert!(!side.test(0x36));
}

#[test]
fn the_eight_comparison_functions() {
    // (func, a < b, a == b, a > b)
    let rows = [
        (gl::NEVER, false, false, false),
        (gl::LESS, true, false, false),
        (gl::EQUAL, false, true, false),
        (gl::LEQUAL, true, true, false),
        (gl::GREATER, false, false, true),
        (gl::NOTEQUAL, true, false, true),
        (gl::GEQUAL, false, true, true),
        (gl::ALWAYS, true, true, true),
    ];
    for (f, lt, eq, gt) in rows {
        assert_eq!(
            [compare(f, 1u8, 2), compare(f, 2u8, 2), compare(f, 3u8, 2)],
            [lt, eq, gt],
            "{f:#x}"
        );
    }
}

#[test]
fn unorm8_products() {
    // 1·x = x and 0·x = 0 for every byte.
    for x in 0..=255u8 {
        assert_eq!(mul8(255, x), x);
        assert_eq!(mul8(0, x), 0);
    }
    // 128·128/255 = 64.25 → 64; 128·255... covered above; 100·200/255 = 78.43 → 78.
    assert_eq!(mul8(128, 128), 64);
    assert_eq!(mul8(100, 200), 78);
    // llvmpipe's approximation: 191·253/255 = 189.502 comes out 189 (measured on the driver).
    assert_eq!(mul8(191, 253), 189);
}

#[test]
fn every_blend_factor() {
    let (s, d, c) = ([10, 20, 30, 40], [50, 60, 70, 80], [90, 100, 110, 120]);
    // Table 4.2, for the green component (k = 1) and for alpha (k = 3).
    let rows = [
        (gl::ZERO, 0, 0),
        (gl::ONE, 255, 255),
        (gl::SRC_COLOR, 20, 40),
        (gl::ONE_MINUS_SRC_COLOR, 235, 215),
        (gl::DST_COLOR, 60, 80),
        (gl::ONE_MINUS_DST_COLOR, 195, 175),
        (gl::SRC_ALPHA, 40, 40),
        (gl::ONE_MINUS_SRC_ALPHA, 215, 215),
        (gl::DST_ALPHA, 80, 80),
        (gl::ONE_MINUS_DST_ALPHA, 175, 175),
        (gl::CONSTANT_COLOR, 100, 120),
        (gl::ONE_MINUS_CONSTANT_COLOR, 155, 135),
        (gl::CONSTANT_ALPHA, 120, 120),
        (gl::ONE_MINUS_CONSTANT_ALPHA, 135, 135),
        // min(As, 1 − Ad) = min(40, 175) for RGB; 1 for alpha.
        (gl::SRC_ALPHA_SATURATE, 40, 255),
    ];
    for (f, g, a) in rows {
        assert_eq!(factor(f, 1, s, d, c), g, "{f:#x} green");
        assert_eq!(factor(f, 3, s, d, c), a, "{f:#x} alpha");
    }
}

#[test]
fn every_blend_equation() {
    // (eq, s, d, s·S, d·D) → table 4.1, saturating in unorm8.
    assert_eq!(equation(gl::FUNC_ADD, 0, 0, 200, 100), 255);
    assert_eq!(equation(gl::FUNC_ADD, 0, 0, 20, 100), 120);
    assert_eq!(equation(gl::FUNC_SUBTRACT, 0, 0, 200, 100), 100);
    assert_eq!(equation(gl::FUNC_SUBTRACT, 0, 0, 100, 200), 0);
    assert_eq!(equation(gl::FUNC_REVERSE_SUBTRACT, 0, 0, 100, 200), 100);
    assert_eq!(equation(gl::FUNC_REVERSE_SUBTRACT, 0, 0, 200, 100), 0);
    // MIN and MAX take the colours, not the weighted terms.
    assert_eq!(equation(gl::MIN, 30, 70, 255, 255), 30);
    assert_eq!(equation(gl::MAX, 30, 70, 0, 0), 70);
}

#[test]
fn alpha_blending_over() {
    let b = BlendEval {
        src_rgb: gl::SRC_ALPHA,
        dst_rgb: gl::ONE_MINUS_SRC_ALPHA,
        src_alpha: gl::SRC_ALPHA,
        dst_alpha: gl::ONE_MINUS_SRC_ALPHA,
        eq_rgb: gl::FUNC_ADD,
        eq_alpha: gl::FUNC_ADD,
        constant: [0; 4],
    };
    // Red at alpha 128 over opaque blue: R = 255·128/255 = 128; B = 255·127/255 = 127;
    // A = 128·128/255 (64.25 → 64) + 255·127/255 (127) = 191.
    assert_eq!(
        b.apply([255, 0, 0, 128], [0, 0, 255, 255]),
        [128, 0, 127, 191]
    );
}

#[test]
fn all_sixteen_logic_ops() {
    let (s, d) = (0xCC, 0xAA);
    let rows = [
        (gl::CLEAR, 0x00),
        (gl::AND, 0x88),
        (gl::AND_REVERSE, 0x44),
        (gl::COPY, 0xCC),
        (gl::AND_INVERTED, 0x22),
        (gl::NOOP, 0xAA),
        (gl::XOR, 0x66),
        (gl::OR, 0xEE),
        (gl::NOR, 0x11),
        (gl::EQUIV, 0x99),
        (gl::INVERT, 0x55),
        (gl::OR_REVERSE, 0xDD),
        (gl::COPY_INVERTED, 0x33),
        (gl::OR_INVERTED, 0xBB),
        (gl::NAND, 0x77),
        (gl::SET, 0xFF),
    ];
    for (op, want) in rows {
        assert_eq!(logic_op(op, s, d), want, "{op:#x}");
    }
}

fn fog(mode: u32, density: f32) -> FogEval {
    FogEval {
        mode,
        density,
        start: 2.0,
        end: 10.0,
        color: Vec3::new(0.0, 0.0, 1.0),
    }
}

#[test]
fn fog_factors_at_known_distances() {
    let close = |a: f32, b: f32| (a - b).abs() < 1e-6;
    // LINEAR (e − c)/(e − s), e = 10, s = 2: c = 4 → 0.75; c = 0 → 1.25 clamped to 1;
    // c = 12 → −0.25 clamped to 0.
    let lin = fog(gl::LINEAR, 1.0);
    assert!(close(lin.factor(4.0), 0.75));
    assert_eq!(lin.factor(0.0), 1.0);
    assert_eq!(lin.factor(12.0), 0.0);
    // EXP e^(−d·c): d = 0.5, c = 2 → e^−1.
    assert!(close(fog(gl::EXP, 0.5).factor(2.0), (-1.0f32).exp()));
    // EXP2 e^(−(d·c)²): d = 0.5, c = 4 → e^−4.
    assert!(close(fog(gl::EXP2, 0.5).factor(4.0), (-4.0f32).exp()));
    // eq. 3.25 on RGB only: red with f = 0.75 into blue fog → (0.75, 0, 0.25), alpha kept.
    let c = lin.apply(Vec4::new(1.0, 0.0, 0.0, 0.5), 4.0);
    assert!((c - Vec4::new(0.75, 0.0, 0.25, 0.5)).abs().max_element() < 1e-6);
}

/// A 4x4 context with identity modelview and `ortho(-1, 1, -1, 1, 0, 10)`, so a vertex at
/// z = -k has eye distance k.
fn ctx() -> Context {
    let Ok(mut c) = Context::new(4, 4) else {
        panic!("context")
    };
    c.matrix_mode(gl::PROJECTION);
    c.ortho(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0);
    c.matrix_mode(gl::MODELVIEW);
    c
}

/// A quad over the whole viewport at eye z = `z`, counter-clockwise unless `cw`.
fn quad(c: &mut Context, z: f32, cw: bool) {
    c.begin(gl::QUADS);
    let mut vs = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    if cw {
        vs.reverse();
    }
    for [x, y] in vs {
        c.vertex3f(x, y, z);
    }
    c.end();
    c.finish();
}

fn pixel(c: &mut Context) -> ([u8; 4], u8) {
    c.renderer
        .framebuffer()
        .pixel(1, 2)
        .map_or(([0; 4], 0), |p| (p.0, p.2))
}

#[test]
fn stencil_through_the_pipeline() {
    let mut c = ctx();
    c.enable(gl::STENCIL_TEST);
    c.stencil_func(gl::ALWAYS, 7, 0xFF);
    c.stencil_op(gl::KEEP, gl::KEEP, gl::REPLACE);
    c.color3f(1.0, 0.0, 0.0);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c), ([255, 0, 0, 255], 7));
    // 5 < 7 passes: INCR_WRAP on depth pass → 8, colour written.
    c.stencil_func(gl::LESS, 5, 0xFF);
    c.stencil_op(gl::KEEP, gl::KEEP, gl::INCR_WRAP);
    c.color3f(0.0, 1.0, 0.0);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c), ([0, 255, 0, 255], 8));
    // 5 > 8 fails: the stencil-fail op DECR → 7, no colour.
    c.stencil_func(gl::GREATER, 5, 0xFF);
    c.stencil_op(gl::DECR, gl::KEEP, gl::KEEP);
    c.color3f(0.0, 0.0, 1.0);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c), ([0, 255, 0, 255], 7));
    // Depth test fails (NEVER): the depth-fail op ZERO, no colour.
    c.enable(gl::DEPTH_TEST);
    c.depth_func(gl::NEVER);
    c.stencil_func(gl::ALWAYS, 0, 0xFF);
    c.stencil_op(gl::KEEP, gl::ZERO, gl::KEEP);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c), ([0, 255, 0, 255], 0));
    // A back-facing polygon uses the BACK state (§4.1.5): INVERT on stencil fail → 255.
    c.disable(gl::DEPTH_TEST);
    c.stencil_func_separate(gl::BACK, gl::NEVER, 0, 0xFF);
    c.stencil_op_separate(gl::BACK, gl::INVERT, gl::KEEP, gl::KEEP);
    quad(&mut c, -1.0, true);
    assert_eq!(pixel(&mut c), ([0, 255, 0, 255], 255));
    // The front state was left alone: ALWAYS passes, KEEP.
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c), ([0, 0, 255, 255], 255));
}

#[test]
fn alpha_test_compares_in_unorm8() {
    let mut c = ctx();
    c.enable(gl::ALPHA_TEST);
    c.alpha_func(gl::GREATER, 0.5);
    c.color4f(1.0, 1.0, 1.0, 0.4);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c).0, [0, 0, 0, 0], "0.4 > 0.5 fails");
    // 0.4 → 102 and the reference 0.4 → 102: GEQUAL passes, EQUAL passes, LESS fails.
    c.alpha_func(gl::LESS, 0.4);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c).0, [0, 0, 0, 0]);
    c.alpha_func(gl::EQUAL, 0.4);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c).0, [255, 255, 255, 102]);
}

#[test]
fn fog_through_the_pipeline_at_eye_distance_4() {
    let mut c = ctx();
    c.enable(gl::FOG);
    c.fogfv(gl::FOG_COLOR, &[0.0, 0.0, 1.0, 1.0]);
    c.fogi(gl::FOG_MODE, gl::LINEAR as i32);
    c.fogf(gl::FOG_START, 2.0);
    c.fogf(gl::FOG_END, 10.0);
    c.color3f(1.0, 0.0, 0.0);
    quad(&mut c, -4.0, false);
    // f = 0.75: R = 0.75·255 = 191.25 → 191, B = 0.25·255 = 63.75 → 64.
    assert_eq!(pixel(&mut c).0, [191, 0, 64, 255]);
    // EXP, density 0.25: f = e^−1 = 0.3679: R = 93.8 → 94, B = 161.2 → 161.
    c.fogi(gl::FOG_MODE, gl::EXP as i32);
    c.fogf(gl::FOG_DENSITY, 0.25);
    quad(&mut c, -4.0, false);
    assert_eq!(pixel(&mut c).0, [94, 0, 161, 255]);
    // EXP2, density 0.125: f = e^−(0.5²) = 0.7788: R = 198.6 → 199, B = 56.4 → 56.
    c.fogi(gl::FOG_MODE, gl::EXP2 as i32);
    c.fogf(gl::FOG_DENSITY, 0.125);
    quad(&mut c, -4.0, false);
    assert_eq!(pixel(&mut c).0, [199, 0, 56, 255]);
    c.fogi(gl::FOG_MODE, gl::EXP as i32);
    c.fogf(gl::FOG_DENSITY, 0.25);
    // FOG_COORD source: c = |−2| = 2 → EXP f = e^−0.5 = 0.6065: R = 154.7 → 155, B = 100.3 → 100.
    c.fogi(gl::FOG_COORD_SRC, gl::FOG_COORD as i32);
    c.fog_coordf(-2.0);
    quad(&mut c, -4.0, false);
    assert_eq!(pixel(&mut c).0, [155, 0, 100, 255]);
}

#[test]
fn blending_and_logic_op_through_the_pipeline() {
    let mut c = ctx();
    c.clear_color(0.0, 0.0, 1.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.enable(gl::BLEND);
    c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
    c.color4ub(255, 0, 0, 128);
    quad(&mut c, -1.0, false);
    // As `alpha_blending_over`.
    assert_eq!(pixel(&mut c).0, [128, 0, 127, 191]);
    // COLOR_LOGIC_OP takes precedence over blending (§4.1.10): source XOR destination.
    c.enable(gl::COLOR_LOGIC_OP);
    c.logic_op(gl::XOR);
    quad(&mut c, -1.0, false);
    assert_eq!(pixel(&mut c).0, [128 ^ 255, 0, 127, 191 ^ 128]);
}

#[test]
fn color_sum_adds_the_secondary_colour() {
    let mut c = ctx();
    c.enable(gl::COLOR_SUM);
    c.color3f(0.5, 0.0, 0.0);
    c.secondary_color3f(0.25, 0.25, 0.0);
    quad(&mut c, -1.0, false);
    // (0.75, 0.25, 0): 191.25 → 191, 63.75 → 64.
    assert_eq!(pixel(&mut c).0, [191, 64, 0, 255]);
}
