//! Selection and feedback against the driver, value for value: feedback buffers of every type
//! for every Begin mode, PolygonMode, clipping (frustum and user planes), culling, two-sided
//! lighting and PassThrough; hit records with their depths, the name stack, overflow; the
//! errors of RenderMode, SelectBuffer, FeedbackBuffer and the name stack; display lists.
//!
//! The geometry is chosen so that every coordinate is exact in single precision (a 64x64 window
//! under Ortho(0, 64, 0, 64, -1, 1), coordinates on a 1/4 grid, clipping at halfway points):
//! where rounding cannot differ, the driver's buffer and fixedgl's must be equal bit for bit.
#![cfg(feature = "gl")]

use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context};

const W: u32 = 64;

fn setup() -> Vec<Call> {
    vec![
        Call::MatrixMode(gl::PROJECTION),
        Call::Ortho(Box::new([0.0, 64.0, 0.0, 64.0, -1.0, 1.0])),
        Call::MatrixMode(gl::MODELVIEW),
    ]
}

fn backend() -> Option<GlBackend> {
    crate::common::test_backend(W, W)
}

fn run(cpu: &mut Context, drv: &mut GlBackend, calls: &[Call]) {
    for c in calls {
        cpu.execute(c);
        drv.execute(c);
        if !cpu.inside_begin_end() {
            assert_eq!(cpu.get_error(), drv.get_error(), "after {c:?}");
        }
    }
}

fn prim(mode: u32, v: &[[f32; 3]]) -> Vec<Call> {
    let mut out = vec![Call::Begin(mode)];
    out.extend(v.iter().map(|p| Call::Vertex3f(p[0], p[1], p[2])));
    out.push(Call::End);
    out
}

/// A name for what the tokens are, for failure messages.
fn tokens(v: &[f32]) -> String {
    v.iter().map(|x| format!("{x} ")).collect()
}

/// One feedback case: its calls between RenderMode(FEEDBACK) and RenderMode(RENDER).
fn feedback_case(name: &str, ty: u32, body: Vec<Call>) {
    let mut cpu = Context::new(W, W).expect("context");
    let Some(mut drv) = backend() else { return };
    let mut calls = setup();
    calls.push(Call::FeedbackBuffer(4096, ty));
    calls.push(Call::RenderMode(gl::FEEDBACK));
    calls.extend(body);
    run(&mut cpu, &mut drv, &calls);
    let n = cpu.render_mode(gl::RENDER);
    drv.execute(&Call::RenderMode(gl::RENDER));
    assert_eq!(cpu.get_error(), drv.get_error(), "{name}");
    let (a, b) = (cpu.feedback_values(), drv.feedback_values());
    assert!(
        n > 0 || name.starts_with("nothing"),
        "{name}: some feedback"
    );
    assert_eq!(
        (n, tokens(a)),
        (drv.render_mode_result(), tokens(b)),
        "{name}: fixedgl, then the driver"
    );
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(a), bits(b), "{name}: bit for bit");
}

#[test]
fn feedback_buffers_match_the_driver_value_for_value() {
    let quad = [
        [1.0, 2.0, 0.0],
        [5.0, 2.0, 0.0],
        [5.0, 8.0, 0.0],
        [1.0, 8.0, 0.0],
    ];
    let poly = [
        [1.0, 2.0, 0.5],
        [5.0, 2.0, 0.25],
        [7.0, 5.0, 0.0],
        [5.0, 8.0, -0.25],
        [1.0, 8.0, -0.5],
    ];
    let strip = [
        [1.0, 2.0, 0.0],
        [5.0, 2.0, 0.0],
        [1.0, 8.0, 0.5],
        [5.0, 8.0, 0.5],
        [1.0, 12.0, 0.0],
        [5.0, 12.0, 0.25],
    ];
    for ty in [
        gl::GL_2D,
        gl::GL_3D,
        gl::GL_3D_COLOR,
        gl::GL_3D_COLOR_TEXTURE,
        gl::GL_4D_COLOR_TEXTURE,
    ] {
        for (mode, verts) in [
            (gl::POINTS, &strip[..]),
            (gl::LINES, &strip[..]),
            (gl::LINE_STRIP, &strip[..]),
            (gl::LINE_LOOP, &strip[..]),
            (gl::TRIANGLES, &strip[..]),
            (gl::TRIANGLE_STRIP, &strip[..]),
            (gl::TRIANGLE_FAN, &poly[..]),
            (gl::QUADS, &quad[..]),
            (gl::QUAD_STRIP, &strip[..]),
            (gl::POLYGON, &poly[..]),
        ] {
            let mut body = vec![
                Call::Color4f(0.25, 0.5, 0.75, 1.0),
                Call::TexCoord4f(0.5, 0.25, 2.0, 1.0),
            ];
            body.extend(prim(mode, verts));
            feedback_case(&format!("type {ty:#x} mode {mode}"), ty, body.clone());
            for pm in [gl::LINE, gl::POINT] {
                if mode >= gl::TRIANGLES {
                    let mut b = vec![Call::PolygonMode(gl::FRONT_AND_BACK, pm)];
                    b.extend(body.clone());
                    feedback_case(
                        &format!("type {ty:#x} mode {mode} polygon mode {pm:#x}"),
                        ty,
                        b,
                    );
                }
            }
        }
    }
}

#[test]
fn feedback_after_clipping_culling_and_lighting_matches_the_driver() {
    let tri = |a: [f32; 2], b: [f32; 2], c: [f32; 2]| {
        prim(
            gl::TRIANGLES,
            &[[a[0], a[1], 0.0], [b[0], b[1], 0.0], [c[0], c[1], 0.0]],
        )
    };
    let mut cases: Vec<(&str, u32, Vec<Call>)> = Vec::new();
    // Clipped at x = 0 halfway along two edges; then at the right and top edges too.
    cases.push(("clip left", gl::GL_3D_COLOR, {
        let mut b = vec![Call::Color3f(1.0, 0.0, 0.0)];
        b.extend(tri([-16.0, 2.0], [16.0, 2.0], [16.0, 34.0]));
        b
    }));
    cases.push((
        "clip three planes",
        gl::GL_2D,
        tri([-16.0, 32.0], [96.0, 32.0], [32.0, 96.0]),
    ));
    cases.push(("clip near and far", gl::GL_3D, {
        prim(
            gl::TRIANGLES,
            &[[8.0, 8.0, -3.0], [24.0, 8.0, 3.0], [8.0, 24.0, 0.0]],
        )
    }));
    // Intersections that are not exact: the new vertices are interpolated from the end nearer
    // each plane, planes taken right, left, top, bottom, near, far, as the driver does.
    cases.push(("clip, inexact intersections", gl::GL_3D, {
        let tris: [[[f32; 3]; 3]; 7] = [
            [[-16.0, 32.0, 0.0], [96.0, 32.0, 0.0], [32.0, 96.0, 0.0]],
            [[-16.0, 32.0, 0.0], [80.0, -10.0, 0.0], [32.0, 96.0, 0.0]],
            [[-20.0, -7.0, 0.0], [70.0, 10.0, 0.0], [10.0, 90.0, 0.0]],
            [[50.0, -9.0, 0.0], [90.0, 50.0, 0.0], [-11.0, 77.0, 0.0]],
            [[5.0, 5.0, -3.0], [60.0, 7.0, 1.7], [30.0, 62.0, 0.3]],
            [[-7.0, 5.0, -3.0], [60.0, -7.0, 1.7], [70.0, 75.0, 2.3]],
            [[-30.0, -30.0, -3.0], [97.0, -13.0, 1.7], [13.0, 99.0, 2.3]],
        ];
        let mut b = vec![Call::Color3f(0.0, 1.0, 0.0)];
        for t in tris {
            b.extend(prim(gl::TRIANGLES, &t));
        }
        b
    }));
    cases.push(("clipped lines", gl::GL_2D, {
        prim(
            gl::LINE_STRIP,
            &[
                [-8.0, 2.0, 0.0],
                [8.0, 2.0, 0.0],
                [8.0, 10.0, 0.0],
                [-8.0, 10.0, 0.0],
                [72.0, 10.0, 0.0],
            ],
        )
    }));
    cases.push(("clipped points", gl::GL_2D, {
        prim(
            gl::POINTS,
            &[
                [-1.0, 2.0, 0.0],
                [3.0, 2.0, 0.0],
                [3.0, 65.0, 0.0],
                [3.0, 4.0, 2.0],
            ],
        )
    }));
    cases.push(("clipped polygon in LINE mode", gl::GL_2D, {
        let mut b = vec![Call::PolygonMode(gl::FRONT_AND_BACK, gl::LINE)];
        b.extend(tri([-16.0, 2.0], [16.0, 2.0], [16.0, 34.0]));
        b
    }));
    cases.push(("user clip plane", gl::GL_2D, {
        let mut b = vec![
            Call::ClipPlane(gl::CLIP_PLANE0, [1.0, 0.0, 0.0, -8.0]),
            Call::Enable(gl::CLIP_PLANE0),
            Call::PolygonMode(gl::FRONT_AND_BACK, gl::LINE),
        ];
        b.extend(tri([0.0, 0.0], [16.0, 0.0], [16.0, 16.0]));
        b.push(Call::PolygonMode(gl::FRONT_AND_BACK, gl::FILL));
        b.extend(tri([0.0, 0.0], [16.0, 0.0], [16.0, 16.0]));
        b.extend(prim(gl::POINTS, &[[4.0, 4.0, 0.0], [12.0, 4.0, 0.0]]));
        b
    }));
    cases.push(("culling", gl::GL_2D, {
        let mut b = vec![Call::Enable(gl::CULL_FACE)];
        b.extend(tri([1.0, 2.0], [1.0, 8.0], [5.0, 6.0]));
        b.extend(tri([1.0, 2.0], [5.0, 6.0], [1.0, 8.0]));
        // Zero area counts as back-facing.
        b.extend(tri([1.0, 2.0], [5.0, 2.0], [9.0, 2.0]));
        b.push(Call::CullFace(gl::FRONT));
        b.push(Call::FrontFace(gl::CW));
        b.extend(tri([1.0, 2.0], [1.0, 8.0], [5.0, 6.0]));
        b.extend(tri([1.0, 2.0], [5.0, 2.0], [9.0, 2.0]));
        b
    }));
    cases.push(("front LINE, back FILL", gl::GL_2D, {
        let mut b = vec![Call::PolygonMode(gl::FRONT, gl::LINE)];
        b.extend(tri([1.0, 2.0], [5.0, 2.0], [5.0, 8.0]));
        b.extend(tri([1.0, 2.0], [5.0, 8.0], [5.0, 2.0]));
        b
    }));
    cases.push(("two-sided lighting", gl::GL_3D_COLOR, {
        let mut b = vec![
            Call::Enable(gl::LIGHTING),
            Call::Enable(gl::LIGHT0),
            Call::LightModeli(gl::LIGHT_MODEL_TWO_SIDE, 1),
            Call::Materialfv(gl::BACK, gl::AMBIENT, vec![0.5, 0.25, 0.0, 1.0]),
            Call::Normal3f(0.0, 0.0, 1.0),
        ];
        b.extend(tri([1.0, 2.0], [5.0, 2.0], [5.0, 8.0]));
        b.extend(tri([1.0, 2.0], [5.0, 8.0], [5.0, 2.0]));
        b
    }));
    cases.push((
        "colours clamped, flat lines keep theirs",
        gl::GL_3D_COLOR,
        {
            let mut b = vec![
                Call::ShadeModel(gl::FLAT),
                Call::Color4f(2.0, -1.0, 0.5, 0.75),
            ];
            b.extend(prim(gl::POINTS, &[[1.0, 2.0, 0.0]]));
            b.extend([
                Call::Begin(gl::LINES),
                Call::Color3f(1.0, 0.0, 0.0),
                Call::Vertex2f(1.0, 2.0),
                Call::Color3f(0.0, 1.0, 0.0),
                Call::Vertex2f(5.0, 6.0),
                Call::End,
            ]);
            b
        },
    ));
    cases.push(("perspective, w", gl::GL_4D_COLOR_TEXTURE, {
        vec![
            Call::MatrixMode(gl::PROJECTION),
            Call::LoadIdentity,
            Call::Frustum(Box::new([-1.0, 1.0, -1.0, 1.0, 1.0, 3.0])),
            Call::MatrixMode(gl::MODELVIEW),
            Call::TexCoord2f(0.5, 0.25),
            Call::Begin(gl::POINTS),
            Call::Vertex3f(0.5, 0.25, -2.0),
            Call::Vertex4f(0.5, 0.5, -4.0, 2.0),
            Call::End,
        ]
    }));
    cases.push(("viewport and depth range", gl::GL_3D, {
        let mut b = vec![Call::Viewport(16, 8, 32, 16), Call::DepthRange(0.25, 0.75)];
        b.extend(prim(gl::POINTS, &[[8.0, 8.0, 0.5], [32.0, 48.0, -1.0]]));
        b
    }));
    cases.push(("pass-through", gl::GL_2D, {
        let mut b = vec![Call::PassThrough(3.5)];
        b.extend(prim(gl::POINTS, &[[1.0, 2.0, 0.0]]));
        b.push(Call::PassThrough(-1.0));
        b
    }));
    cases.push(("display list", gl::GL_2D, {
        let mut b = vec![Call::NewList(1, gl::COMPILE), Call::PassThrough(7.0)];
        b.extend(prim(gl::LINES, &[[1.0, 2.0, 0.0], [3.0, 4.0, 0.0]]));
        b.extend([Call::EndList, Call::CallList(1), Call::CallList(1)]);
        b
    }));
    cases.push(("nothing: everything clipped", gl::GL_2D, {
        prim(
            gl::TRIANGLES,
            &[[-9.0, 2.0, 0.0], [-5.0, 2.0, 0.0], [-5.0, 8.0, 0.0]],
        )
    }));
    for (name, ty, body) in cases {
        feedback_case(name, ty, body);
    }
}

#[test]
fn line_reset_tokens_follow_the_driver_across_feedback_runs() {
    // llvmpipe marks only the first edge of an unfilled polygon with LINE_RESET_TOKEN, and the
    // mark waits for the next line even into a later feedback run.
    let mut cpu = Context::new(W, W).expect("context");
    let Some(mut drv) = backend() else { return };
    run(&mut cpu, &mut drv, &setup());
    let runs: Vec<Vec<Call>> = vec![
        {
            let mut b = vec![Call::PolygonMode(gl::FRONT_AND_BACK, gl::LINE)];
            // A polygon whose edges are all interior to a quad: no line drawn.
            b.extend(prim(
                gl::TRIANGLES,
                &[[1.0, 2.0, 0.0], [5.0, 2.0, 0.0], [5.0, 8.0, 0.0]],
            ));
            b.push(Call::Enable(gl::CULL_FACE));
            b.push(Call::CullFace(gl::FRONT));
            b.extend(prim(
                gl::QUADS,
                &[
                    [1.0, 2.0, 0.0],
                    [5.0, 2.0, 0.0],
                    [5.0, 8.0, 0.0],
                    [1.0, 8.0, 0.0],
                ],
            ));
            b
        },
        prim(
            gl::LINES,
            &[
                [1.0, 2.0, 0.0],
                [3.0, 4.0, 0.0],
                [5.0, 6.0, 0.0],
                [7.0, 8.0, 0.0],
            ],
        ),
    ];
    for body in runs {
        let mut calls = vec![
            Call::FeedbackBuffer(256, gl::GL_2D),
            Call::RenderMode(gl::FEEDBACK),
        ];
        calls.extend(body);
        run(&mut cpu, &mut drv, &calls);
        let n = cpu.render_mode(gl::RENDER);
        drv.execute(&Call::RenderMode(gl::RENDER));
        assert_eq!(n, drv.render_mode_result());
        assert_eq!(tokens(cpu.feedback_values()), tokens(drv.feedback_values()));
    }
}

/// One selection: its calls after RenderMode(SELECT); returns the hit count and records of
/// both.
fn select_case(name: &str, size: i32, body: Vec<Call>) -> Vec<u32> {
    let mut cpu = Context::new(W, W).expect("context");
    let Some(mut drv) = backend() else {
        return Vec::new();
    };
    let mut calls = setup();
    calls.push(Call::SelectBuffer(size));
    calls.push(Call::RenderMode(gl::SELECT));
    calls.extend(body);
    run(&mut cpu, &mut drv, &calls);
    let n = cpu.render_mode(gl::RENDER);
    drv.execute(&Call::RenderMode(gl::RENDER));
    assert_eq!(cpu.get_error(), drv.get_error(), "{name}");
    assert_eq!(
        (n, cpu.selection_buffer()),
        (drv.render_mode_result(), drv.selection_buffer()),
        "{name}: fixedgl, then the driver"
    );
    cpu.selection_buffer().to_vec()
}

#[test]
fn hit_records_match_the_driver_value_for_value() {
    let tri = |z: f32| {
        prim(
            gl::TRIANGLES,
            &[[16.0, 16.0, z], [48.0, 16.0, z], [32.0, 48.0, z]],
        )
    };
    let mut b = vec![Call::InitNames, Call::PushName(7)];
    b.extend(tri(0.0));
    b.push(Call::LoadName(8));
    // Window z 0.5 and 0.75 (Ortho: z_window = (1 - z) / 2).
    b.extend(tri(0.0));
    b.extend(tri(-0.5));
    // The near plane, window z 1 after Ortho flips it: Mesa's scaling wraps it to 0.
    b.push(Call::LoadName(9));
    b.extend(tri(-1.0));
    // Entirely clipped: no hit.
    b.push(Call::LoadName(10));
    b.extend(tri(2.0));
    b.push(Call::LoadName(11));
    b.extend(prim(gl::POINTS, &[[3.0, 4.0, 0.25]]));
    b.push(Call::LoadName(12));
    b.extend(prim(gl::LINES, &[[1.0, 2.0, -0.5], [63.0, 2.0, 0.5]]));
    // Clipped by near and far: depths 0 and 1.
    b.push(Call::LoadName(13));
    b.extend(prim(
        gl::TRIANGLES,
        &[[8.0, 8.0, -3.0], [24.0, 8.0, 3.0], [8.0, 24.0, 0.0]],
    ));
    // Culled: no hit.
    b.extend([
        Call::LoadName(14),
        Call::Enable(gl::CULL_FACE),
        Call::CullFace(gl::FRONT),
    ]);
    b.extend(tri(0.0));
    b.push(Call::Disable(gl::CULL_FACE));
    b.extend([
        Call::LoadName(15),
        Call::PolygonMode(gl::FRONT_AND_BACK, gl::LINE),
    ]);
    b.extend(tri(0.25));
    b.push(Call::PolygonMode(gl::FRONT_AND_BACK, gl::FILL));
    b.extend([Call::LoadName(16), Call::DepthRange(0.25, 0.75)]);
    b.extend(tri(0.0));
    b.extend(tri(-1.0));
    b.push(Call::DepthRange(0.0, 1.0));
    b.extend([Call::PushName(17), Call::PushName(18)]);
    b.extend(tri(0.5));
    b.extend([Call::PopName, Call::PopName, Call::PopName]);
    // An empty name stack still records hits.
    b.extend(tri(0.5));
    // Names from a display list.
    b.extend([
        Call::NewList(1, gl::COMPILE),
        Call::PushName(30),
        Call::LoadName(31),
    ]);
    b.extend(tri(0.0));
    b.extend([Call::PopName, Call::EndList, Call::CallList(1)]);
    let records = select_case("every kind of hit", 512, b.clone());
    if records.is_empty() {
        return;
    }
    // Spot checks against GL's layout (and Mesa's depth scaling), independent of the driver.
    assert_eq!(records[..4], [1, 1 << 31, 1 << 31, 7]);
    assert_eq!(records[4..8], [1, 1 << 31, 3 << 30, 8]);
    assert_eq!(records[8..12], [1, 0, 0, 9]);
    // Overflow: the records that fit and the start of the next, -1.
    for size in [0, 1, 5, 9, 13] {
        select_case(&format!("overflow at {size}"), size, b.clone());
    }
}

#[test]
fn selection_and_feedback_errors_match_the_driver() {
    let mut cpu = Context::new(W, W).expect("context");
    let Some(mut drv) = backend() else { return };
    let mut calls = setup();
    calls.extend([
        // Before any buffer: INVALID_OPERATION, the mode unchanged (GL 2.1; Mesa switches).
        Call::RenderMode(gl::SELECT),
        Call::RenderMode(gl::FEEDBACK),
        Call::RenderMode(0x1234),
        Call::SelectBuffer(-1),
        Call::FeedbackBuffer(-1, gl::GL_2D),
        Call::FeedbackBuffer(8, 0x1234),
        // Ignored outside SELECT mode, even on an empty stack.
        Call::LoadName(1),
        Call::PopName,
        Call::PushName(1),
        Call::PassThrough(1.0),
        // A size of 0 is a buffer (GL 2.1; Mesa refuses RenderMode then).
        Call::SelectBuffer(0),
        Call::RenderMode(gl::SELECT),
        Call::SelectBuffer(8),
        Call::RenderMode(0x1234),
        Call::LoadName(1),
        Call::PopName,
        Call::InitNames,
        Call::PushName(2),
        Call::Begin(gl::POINTS),
        Call::PushName(3),
        Call::End,
        Call::RenderMode(gl::RENDER),
        Call::FeedbackBuffer(16, gl::GL_3D),
        Call::RenderMode(gl::FEEDBACK),
        Call::FeedbackBuffer(16, gl::GL_3D),
        Call::SelectBuffer(4),
        Call::RenderMode(gl::FEEDBACK),
        Call::RenderMode(gl::RENDER),
        Call::RenderMode(gl::SELECT),
    ]);
    // The 65th push overflows the stack (MAX_NAME_STACK_DEPTH 64).
    for _ in 0..65 {
        calls.push(Call::PushName(1));
    }
    calls.push(Call::RenderMode(gl::RENDER));
    let expected_errors = [
        gl::INVALID_OPERATION,
        gl::INVALID_OPERATION,
        gl::INVALID_ENUM,
        gl::INVALID_VALUE,
        gl::INVALID_VALUE,
        gl::INVALID_ENUM,
    ];
    for (i, c) in calls.iter().enumerate() {
        cpu.execute(c);
        drv.execute(c);
        if cpu.inside_begin_end() {
            continue;
        }
        let (a, b) = (cpu.get_error(), drv.get_error());
        assert_eq!(a, b, "call {i}: {c:?}");
        if let Some(&e) = i.checked_sub(3).and_then(|k| expected_errors.get(k)) {
            assert_eq!(a, e, "call {i}: {c:?}");
        }
        let (mut m, mut d) = ([0; 1], [0; 1]);
        cpu.get_integerv(gl::RENDER_MODE, &mut m);
        drv.get_integerv(gl::RENDER_MODE, &mut d);
        assert_eq!(m, d, "RENDER_MODE after {c:?}");
        for p in [
            gl::NAME_STACK_DEPTH,
            gl::SELECTION_BUFFER_SIZE,
            gl::FEEDBACK_BUFFER_SIZE,
            gl::FEEDBACK_BUFFER_TYPE,
            gl::MAX_NAME_STACK_DEPTH,
        ] {
            let (mut x, mut y) = ([0; 1], [0; 1]);
            cpu.get_integerv(p, &mut x);
            drv.get_integerv(p, &mut y);
            assert_eq!(x, y, "{p:#x} after {c:?}");
        }
    }
}

#[test]
fn the_picking_scene_s_hits_match_the_driver() {
    use fixedgl::scenes::picking;
    let Some(scene) = fixedgl::scenes::find("picking") else {
        panic!("the picking scene is registered")
    };
    let (w, h) = scene.default_size;
    let (cpu, calls) = scene.record(w, h).expect("recorded");
    let Some(mut drv) = crate::common::test_backend(w, h) else {
        return;
    };
    drv.replay(&calls);
    assert_eq!(drv.get_error(), gl::NO_ERROR);
    let ours = cpu.selection_buffer().to_vec();
    let theirs = drv.selection_buffer().to_vec();
    let count = drv.render_mode_result();
    let (a, b) = (picking::hits(&ours, count), picking::hits(&theirs, count));
    assert!(a.len() >= 2, "the pick box covers two objects: {b:?}");
    assert_eq!(ours.len(), theirs.len(), "{a:?} vs {b:?}");
    // The same objects, in the same order, and the same one nearest.
    let names = |h: &[picking::Hit]| h.iter().map(|x| x.names.clone()).collect::<Vec<_>>();
    assert_eq!(names(&a), names(&b));
    assert_eq!(picking::nearest(&a), picking::nearest(&b));
    // Depths: the window z of perspective-transformed vertices, scaled to 2^32. fixedgl
    // transforms by the modelview, then the projection, Mesa by their product (with fused
    // multiply-adds), so the single-precision z can differ in its last bits, each of which is
    // 2^32 · 2^-24 = 256 here (z in [0.5, 1)).
    for (x, y) in a.iter().zip(&b) {
        for (p, q) in [(x.z_min, y.z_min), (x.z_max, y.z_max)] {
            let d = p.abs_diff(q);
            assert!(d <= 4 * 256, "{a:?} vs {b:?}");
        }
    }
}

/// Bitmap, DrawPixels and CopyPixels of `w` x `h` at the current raster position.
fn raster_rects(w: i32, h: i32) -> Vec<Call> {
    let n = (w.max(0) * h.max(0)) as usize;
    vec![
        Call::Bitmap(
            w,
            h,
            0.5,
            0.25,
            3.0,
            -2.5,
            Box::new(Some(vec![0xa5; n * 4])),
        ),
        Call::DrawPixels(
            w,
            h,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Box::new(vec![200; n * 4]),
        ),
        Call::CopyPixels(1, 2, w, h, gl::COLOR),
    ]
}

/// GL 2.1 §5.3 for the raster operations, against the driver word for word: RasterPos and
/// WindowPos write nothing; Bitmap, DrawPixels and CopyPixels write their token and the raster
/// position as a vertex of the buffer's type (window x, y, z, clip w, the raster colour, unit
/// 0's raster texture coordinates) in order with the primitives, only while it is valid; an
/// empty Bitmap or DrawPixels still writes its token, an empty CopyPixels does not (Mesa's
/// `drawpix.c`); Bitmap moves the raster position as in RENDER mode; display lists; and
/// nothing is drawn.
#[test]
fn raster_tokens_match_the_driver_value_for_value() {
    for ty in [
        gl::GL_2D,
        gl::GL_3D,
        gl::GL_3D_COLOR,
        gl::GL_3D_COLOR_TEXTURE,
        gl::GL_4D_COLOR_TEXTURE,
    ] {
        let mut b = vec![
            Call::Color4f(0.25, 0.5, 0.75, 1.0),
            Call::TexCoord4f(0.5, 0.25, 2.0, 1.0),
            Call::MultiTexCoord4f(gl::TEXTURE1, 8.0, 9.0, 10.0, 11.0),
            Call::RasterPos3f(10.0, 20.0, 0.5),
        ];
        b.extend(raster_rects(2, 3));
        // Empty rectangles, a NULL bitmap.
        b.extend(raster_rects(0, 3));
        b.extend(raster_rects(4, 0));
        b.push(Call::Bitmap(8, 8, 0.0, 0.0, 1.0, 1.0, Box::new(None)));
        // In order with batched primitives and PassThrough.
        b.extend(prim(gl::POINTS, &[[3.0, 4.0, 0.25]]));
        b.push(Call::PassThrough(7.0));
        b.extend(raster_rects(1, 1));
        // Clip w and the texture matrix (unit 0's coordinates only).
        b.extend([
            Call::MatrixMode(gl::TEXTURE),
            Call::Scalef(2.0, 4.0, 0.5),
            Call::MatrixMode(gl::MODELVIEW),
            Call::RasterPos4f(8.0, 12.0, -0.5, 2.0),
        ]);
        b.extend(raster_rects(2, 2));
        // WindowPos: clamped colour, clamped z through DepthRange, w 1.
        b.extend([
            Call::Color4f(2.0, -1.0, 0.5, 0.25),
            Call::DepthRange(0.25, 0.75),
            Call::WindowPos3f(5.5, 6.25, 2.0),
        ]);
        b.extend(raster_rects(2, 2));
        b.push(Call::WindowPos2f(-3.5, 70.0));
        b.extend(raster_rects(2, 2));
        // An invalid raster position: nothing at all.
        b.extend([Call::DepthRange(0.0, 1.0), Call::RasterPos2f(80.0, 2.0)]);
        b.extend(raster_rects(2, 2));
        // From a display list.
        b.push(Call::NewList(1, gl::COMPILE));
        b.push(Call::RasterPos2f(30.0, 40.0));
        b.extend(raster_rects(2, 1));
        b.extend([Call::EndList, Call::CallList(1)]);
        feedback_case(&format!("raster tokens, type {ty:#x}"), ty, b);
    }
    feedback_case(
        "nothing from an invalid raster position",
        gl::GL_3D,
        [
            vec![Call::RasterPos2f(-80.0, 2.0)],
            raster_rects(2, 2),
            vec![Call::RasterPos2f(1.0, 1.0)],
        ]
        .concat(),
    );
}

/// After the raster operations in FEEDBACK mode the raster position is where Bitmap moved
/// it, and nothing was drawn, on either side.
#[test]
fn raster_operations_draw_nothing_outside_render_mode() {
    for (mode, buffer) in [
        (gl::FEEDBACK, Call::FeedbackBuffer(256, gl::GL_3D)),
        (gl::SELECT, Call::SelectBuffer(256)),
    ] {
        let mut cpu = Context::new(W, W).expect("context");
        let Some(mut drv) = backend() else { return };
        let mut calls = setup();
        calls.extend([
            Call::ClearColor(0.0, 0.0, 0.0, 0.0),
            Call::Clear(gl::COLOR_BUFFER_BIT),
            Call::Begin(gl::TRIANGLES),
            Call::Vertex2f(0.0, 0.0),
            Call::Vertex2f(30.0, 0.0),
            Call::Vertex2f(0.0, 30.0),
            Call::End,
            buffer,
            Call::RenderMode(mode),
            Call::InitNames,
            Call::PushName(1),
            Call::RasterPos2f(40.0, 40.0),
        ]);
        calls.extend(raster_rects(8, 8));
        calls.push(Call::RenderMode(gl::RENDER));
        run(&mut cpu, &mut drv, &calls);
        let mut pos = [0.0f32; 4];
        cpu.get_floatv(gl::CURRENT_RASTER_POSITION, &mut pos);
        assert_eq!(pos, [43.0, 37.5, 0.5, 1.0], "mode {mode:#x}");
        let cpu_img = cpu.to_image().into_raw();
        let drv_img = drv.read_rgba(0, 0, W as i32, W as i32);
        // The triangle alone: as many lit pixels on both sides, none above row 32 or right of
        // column 32 where the rectangles would have been drawn.
        let lit = |v: &[u8]| v.chunks(4).filter(|p| p[0] != 0).count();
        assert_eq!(lit(&cpu_img), lit(&drv_img), "mode {mode:#x}");
        assert!(lit(&drv_img) > 400, "mode {mode:#x}: the triangle is drawn");
        let w = W as usize;
        let far = drv_img
            .chunks(4)
            .enumerate()
            .filter(|(k, p)| p[0] != 0 && (k % w >= 32 || k / w >= 32))
            .count();
        assert_eq!(far, 0, "mode {mode:#x}: the driver drew no rectangle");
    }
}

/// SELECT mode: a valid raster position from RasterPos or WindowPos joins the pending hit at
/// its window z; an invalid one does not; Bitmap, DrawPixels and CopyPixels make no hit (Mesa's
/// `rastpos.c` and `drawpix.c`), against the driver's hit records.
#[test]
fn raster_positions_make_hits_as_the_driver() {
    let mut b = vec![Call::InitNames, Call::PushName(1)];
    b.push(Call::RasterPos3f(10.0, 20.0, 0.5));
    // Outside the frustum: no hit.
    b.extend([Call::LoadName(2), Call::RasterPos3f(10.0, 20.0, 1.5)]);
    // WindowPos, z clamped and through DepthRange.
    b.extend([
        Call::LoadName(3),
        Call::WindowPos3f(1.0, 2.0, 0.75),
        Call::WindowPos3f(100.0, -2.0, 2.0),
        Call::DepthRange(0.25, 0.5),
        Call::WindowPos2f(1.0, 2.0),
        Call::DepthRange(0.0, 1.0),
    ]);
    // The raster operations at a valid position make none.
    b.push(Call::LoadName(4));
    b.extend(raster_rects(4, 4));
    b.extend(raster_rects(0, 0));
    // RasterPos with primitives under one name; a RasterPos4 with w 2.
    b.extend([Call::LoadName(5), Call::RasterPos4f(8.0, 12.0, -0.5, 2.0)]);
    b.extend(prim(
        gl::TRIANGLES,
        &[[16.0, 16.0, 0.0], [48.0, 16.0, 0.0], [32.0, 48.0, 0.0]],
    ));
    // From a display list.
    b.extend([
        Call::NewList(1, gl::COMPILE),
        Call::LoadName(6),
        Call::RasterPos3f(1.0, 1.0, -0.75),
        Call::EndList,
        Call::CallList(1),
    ]);
    let records = select_case("raster position hits", 256, b.clone());
    if records.is_empty() {
        return;
    }
    // Window z 0.25 (Ortho: (1 - z) / 2) for name 1; name 2 makes no record.
    assert_eq!(records[..4], [1, 1 << 30, 1 << 30, 1]);
    assert_eq!(records[4], 1);
    assert_eq!(records[7], 3);
    for size in [0, 3, 6] {
        select_case(&format!("raster hits, overflow at {size}"), size, b.clone());
    }
}
