//! Evaluators (GL 2.1 §5.1) against the real driver: the state Map*, MapGrid* and Enable leave
//! (GetMap COEFF/ORDER/DOMAIN in three types, the grid and enable queries), the errors of every
//! command with bad targets, orders, strides, domains, modes and between Begin and End, display
//! lists (Map copies its points at compile time, the Eval commands are compiled), PushAttrib
//! (EVAL_BIT), and the evaluated vertices themselves through feedback mode. Skips (printing why)
//! without an EGL device.
#![cfg(feature = "gl")]

use fixedgl::compare::compare;
use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context};

const W: u32 = 64;

fn backend() -> Option<GlBackend> {
    crate::common::test_backend(W, W)
}

const MAP1: [u32; 9] = [
    gl::MAP1_COLOR_4,
    gl::MAP1_INDEX,
    gl::MAP1_NORMAL,
    gl::MAP1_TEXTURE_COORD_1,
    gl::MAP1_TEXTURE_COORD_2,
    gl::MAP1_TEXTURE_COORD_3,
    gl::MAP1_TEXTURE_COORD_4,
    gl::MAP1_VERTEX_3,
    gl::MAP1_VERTEX_4,
];

fn map2_targets() -> impl Iterator<Item = u32> {
    MAP1.iter().map(|t| t - gl::MAP1_COLOR_4 + gl::MAP2_COLOR_4)
}

fn all_targets() -> Vec<u32> {
    MAP1.iter().copied().chain(map2_targets()).collect()
}

/// Values `0.25 * i - 3` (not all integers, some halves: GetMapiv's rounding shows).
fn values(n: usize) -> Vec<f32> {
    (0..n).map(|i| 0.25 * i as f32 - 3.0).collect()
}

/// Runs `calls` on both sides.
fn run(cpu: &mut Context, drv: &mut GlBackend, calls: &[Call]) {
    cpu.replay(calls);
    drv.replay(calls);
}

/// Every GetMap answer and every evaluator state query agrees.
fn assert_state_agrees(cpu: &mut Context, drv: &mut GlBackend, what: &str) {
    for target in all_targets() {
        for query in [gl::COEFF, gl::ORDER, gl::DOMAIN] {
            let want = drv.get_mapfv(target, query);
            let mut got = vec![f32::NAN; want.len()];
            cpu.get_mapfv(target, query, &mut got);
            assert_eq!(got, want, "{what}: GetMapfv({target:#x}, {query:#x})");
            let want = drv.get_mapiv(target, query);
            let mut got = vec![i32::MIN; want.len()];
            cpu.get_mapiv(target, query, &mut got);
            assert_eq!(got, want, "{what}: GetMapiv({target:#x}, {query:#x})");
            let want = drv.get_mapdv(target, query);
            let mut got = vec![f64::NAN; want.len()];
            cpu.get_mapdv(target, query, &mut got);
            assert_eq!(got, want, "{what}: GetMapdv({target:#x}, {query:#x})");
        }
        assert_eq!(
            cpu.is_enabled(target),
            drv.is_enabled(target),
            "{what}: IsEnabled({target:#x})"
        );
    }
    assert_eq!(
        cpu.is_enabled(gl::AUTO_NORMAL),
        drv.is_enabled(gl::AUTO_NORMAL),
        "{what}: AUTO_NORMAL"
    );
    for (pname, n) in [
        (gl::MAP1_GRID_DOMAIN, 2),
        (gl::MAP1_GRID_SEGMENTS, 1),
        (gl::MAP2_GRID_DOMAIN, 4),
        (gl::MAP2_GRID_SEGMENTS, 2),
        (gl::MAX_EVAL_ORDER, 1),
    ] {
        let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
        cpu.get_floatv(pname, &mut a);
        drv.get_floatv(pname, &mut b);
        assert_eq!(a, b, "{what}: GetFloatv({pname:#x})");
        let (mut a, mut b) = (vec![0; n], vec![0; n]);
        cpu.get_integerv(pname, &mut a);
        drv.get_integerv(pname, &mut b);
        assert_eq!(a, b, "{what}: GetIntegerv({pname:#x})");
    }
    assert_eq!(cpu.get_error(), drv.get_error(), "{what}: error");
}

#[test]
fn initial_state_and_maps_of_every_target_match_the_driver() {
    let Some(mut drv) = backend() else { return };
    let mut cpu = Context::new(W, W).expect("context");
    assert_state_agrees(&mut cpu, &mut drv, "initial");
    let mut calls = Vec::new();
    for (i, &t) in MAP1.iter().enumerate() {
        let k = fixedgl::counts::map_components(t).unwrap();
        let (stride, order) = (k as i32 + i as i32 % 3, 2 + i as i32);
        let n = fixedgl::counts::map1_points(t, stride, order).unwrap();
        if i % 2 == 0 {
            calls.push(Call::Map1f(Box::new((
                t,
                -1.5,
                2.5 + i as f32,
                stride,
                order,
                values(n),
            ))));
        } else {
            let v = values(n).into_iter().map(f64::from).collect();
            calls.push(Call::Map1d(Box::new((t, 0.1, -0.7, stride, order, v))));
        }
        calls.push(Call::Enable(t));
    }
    for (i, t) in map2_targets().enumerate() {
        let k = fixedgl::counts::map_components(t).unwrap() as i32;
        let (uo, vo) = (1 + i as i32 % 4, 2 + i as i32 % 3);
        // Points laid out both ways: u outer (ustride vo*k) or v outer (vstride uo*k).
        let (us, vs) = if i % 2 == 0 {
            (vo * k, k)
        } else {
            (k, uo * k + 1)
        };
        let n = fixedgl::counts::map2_points(t, us, uo, vs, vo).unwrap();
        if i % 3 == 0 {
            let v = values(n).into_iter().map(f64::from).collect();
            calls.push(Call::Map2d(Box::new((
                t, 0.0, 1.0, us, uo, 2.0, -3.0, vs, vo, v,
            ))));
        } else {
            calls.push(Call::Map2f(Box::new((
                t,
                0.5,
                1.0,
                us,
                uo,
                0.0,
                0.3,
                vs,
                vo,
                values(n),
            ))));
        }
        if i % 2 == 1 {
            calls.push(Call::Enable(t));
        }
    }
    calls.push(Call::Enable(gl::AUTO_NORMAL));
    calls.push(Call::MapGrid1d(7, 0.25, -1.5));
    calls.push(Call::MapGrid2f(3, 1.0, 2.0, 9, -0.5, 0.5));
    run(&mut cpu, &mut drv, &calls);
    assert_state_agrees(&mut cpu, &mut drv, "after Map*");
    run(
        &mut cpu,
        &mut drv,
        &[
            Call::Disable(gl::MAP1_VERTEX_3),
            Call::Disable(gl::AUTO_NORMAL),
            Call::MapGrid2d(Box::new((4, 0.1, 0.2, 5, 0.3, 0.4))),
        ],
    );
    assert_state_agrees(&mut cpu, &mut drv, "after Disable");
}

/// A 2x2 MAP2_VERTEX_3 and a cubic MAP1_VERTEX_3, valid, for the error cases to disturb.
fn valid_maps() -> Vec<Call> {
    vec![
        Call::Map1f(Box::new((
            gl::MAP1_VERTEX_3,
            0.0,
            1.0,
            3,
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0],
        ))),
        Call::Map2f(Box::new((
            gl::MAP2_VERTEX_3,
            0.0,
            1.0,
            3,
            2,
            0.0,
            1.0,
            6,
            2,
            values(12),
        ))),
        Call::Enable(gl::MAP1_VERTEX_3),
        Call::Enable(gl::MAP2_VERTEX_3),
    ]
}

#[test]
fn errors_match_the_driver_and_change_nothing() {
    let m1 = |t: u32, u1: f32, u2: f32, stride: i32, order: i32, n: usize| {
        Call::Map1f(Box::new((t, u1, u2, stride, order, values(n))))
    };
    let m2 = |t: u32, d: [f32; 4], so: [i32; 4], n: usize| {
        Call::Map2f(Box::new((
            t,
            d[0],
            d[1],
            so[0],
            so[1],
            d[2],
            d[3],
            so[2],
            so[3],
            values(n),
        )))
    };
    let cases: Vec<(&str, Vec<Call>)> = vec![
        (
            "map1 bad target",
            vec![m1(gl::TEXTURE_2D, 0.0, 1.0, 3, 2, 6)],
        ),
        (
            "map1 map2 target",
            vec![m1(gl::MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 6)],
        ),
        (
            "map1 u1 == u2",
            vec![m1(gl::MAP1_VERTEX_3, 1.0, 1.0, 3, 2, 6)],
        ),
        (
            "map1 u1 == u2, bad target",
            vec![m1(0x1234, 1.0, 1.0, 3, 2, 6)],
        ),
        (
            "map1 order 0",
            vec![m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 0, 6)],
        ),
        (
            "map1 order 31",
            vec![m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 31, 93)],
        ),
        (
            "map1 order 30",
            vec![m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 30, 90)],
        ),
        (
            "map1 stride 2",
            vec![m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 2, 2, 6)],
        ),
        (
            "map1 stride -1",
            vec![m1(gl::MAP1_COLOR_4, 0.0, 1.0, -1, 2, 8)],
        ),
        (
            "map1 short",
            vec![m1(gl::MAP1_VERTEX_4, 0.0, 1.0, 4, 3, 11)],
        ),
        (
            "map2 bad target",
            vec![m2(
                gl::MAP1_VERTEX_3,
                [0.0, 1.0, 0.0, 1.0],
                [3, 2, 6, 2],
                12,
            )],
        ),
        (
            "map2 v1 == v2",
            vec![m2(
                gl::MAP2_VERTEX_3,
                [0.0, 1.0, 2.0, 2.0],
                [3, 2, 6, 2],
                12,
            )],
        ),
        (
            "map2 vorder 0",
            vec![m2(
                gl::MAP2_VERTEX_3,
                [0.0, 1.0, 0.0, 1.0],
                [3, 2, 6, 0],
                12,
            )],
        ),
        (
            "map2 uorder 31",
            vec![m2(
                gl::MAP2_NORMAL,
                [0.0, 1.0, 0.0, 1.0],
                [3, 31, 93, 1],
                93,
            )],
        ),
        (
            "map2 vstride 1",
            vec![m2(gl::MAP2_NORMAL, [0.0, 1.0, 0.0, 1.0], [3, 2, 1, 2], 12)],
        ),
        (
            "map2 bad target, stride 0",
            vec![m2(0x0DA0, [0.0, 1.0, 0.0, 1.0], [0, 2, 0, 2], 12)],
        ),
        (
            "map2 short",
            vec![m2(gl::MAP2_COLOR_4, [0.0, 1.0, 0.0, 1.0], [8, 2, 4, 2], 15)],
        ),
        (
            "map1 on texture unit 1",
            vec![
                Call::ActiveTexture(gl::TEXTURE1),
                m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 2, 6),
                Call::ActiveTexture(gl::TEXTURE0),
            ],
        ),
        (
            "map2 on texture unit 1",
            vec![
                Call::ActiveTexture(gl::TEXTURE1),
                m2(gl::MAP2_VERTEX_3, [0.0, 1.0, 0.0, 1.0], [3, 2, 6, 2], 12),
                Call::ActiveTexture(gl::TEXTURE0),
            ],
        ),
        ("grid1 un 0", vec![Call::MapGrid1f(0, 0.0, 1.0)]),
        ("grid1d un -1", vec![Call::MapGrid1d(-1, 0.0, 1.0)]),
        (
            "grid2 vn 0",
            vec![Call::MapGrid2f(2, 0.0, 1.0, 0, 0.0, 1.0)],
        ),
        (
            "grid2d un 0",
            vec![Call::MapGrid2d(Box::new((0, 0.0, 1.0, 3, 0.0, 1.0)))],
        ),
        ("grid equal ends", vec![Call::MapGrid1f(3, 1.0, 1.0)]),
        ("mesh1 FILL", vec![Call::EvalMesh1(gl::FILL, 0, 1)]),
        ("mesh1 bad mode", vec![Call::EvalMesh1(gl::POINTS, 0, 1)]),
        (
            "mesh2 bad mode",
            vec![Call::EvalMesh2(gl::LINES, 0, 1, 0, 1)],
        ),
        (
            "mesh2 reversed",
            vec![Call::EvalMesh2(gl::FILL, 3, 0, 2, 0)],
        ),
    ];
    let inside: Vec<(&str, Vec<Call>)> = [
        m1(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 2, 6),
        m1(gl::TEXTURE_2D, 1.0, 1.0, 3, 2, 6),
        m2(gl::MAP2_VERTEX_3, [0.0, 1.0, 0.0, 1.0], [3, 2, 6, 2], 12),
        Call::MapGrid1f(2, 0.0, 1.0),
        Call::MapGrid2f(2, 0.0, 1.0, 2, 0.0, 1.0),
        Call::EvalMesh1(gl::LINE, 0, 2),
        Call::EvalMesh2(gl::FILL, 0, 1, 0, 1),
        Call::EvalCoord1f(0.5),
        Call::EvalCoord2dv([0.5, 0.25]),
        Call::EvalPoint1(1),
        Call::EvalPoint2(1, 1),
    ]
    .into_iter()
    .map(|c| {
        (
            "between Begin and End",
            vec![Call::Begin(gl::POINTS), c, Call::End],
        )
    })
    .collect();
    for (name, body) in cases.into_iter().chain(inside) {
        let Some(mut drv) = backend() else { return };
        let mut cpu = Context::new(W, W).expect("context");
        run(&mut cpu, &mut drv, &valid_maps());
        run(&mut cpu, &mut drv, &body);
        let (a, b) = (cpu.get_error(), drv.get_error());
        assert_eq!(a, b, "{name} ({body:?}): fixedgl, then the driver");
        assert_state_agrees(&mut cpu, &mut drv, name);
    }
    // GetMap's own errors.
    let Some(mut drv) = backend() else { return };
    let mut cpu = Context::new(W, W).expect("context");
    for (target, query) in [
        (gl::TEXTURE_2D, gl::COEFF),
        (gl::MAP1_VERTEX_3, gl::TEXTURE_2D),
        (gl::MAP2_INDEX, 0),
    ] {
        let mut v = [0.0f32; 16];
        cpu.get_mapfv(target, query, &mut v);
        assert!(drv.get_mapfv(target, query).is_empty());
        assert_eq!(
            cpu.get_error(),
            drv.get_error(),
            "GetMapfv({target:#x}, {query:#x})"
        );
    }
}

/// The feedback of `body` (4D_COLOR_TEXTURE: window position, colour, texture coordinates) on
/// both sides, after `setup`.
fn feedback(name: &str, setup: &[Call], body: &[Call]) -> Option<(Vec<f32>, Vec<f32>)> {
    let mut drv = backend()?;
    let mut cpu = Context::new(W, W).expect("context");
    run(&mut cpu, &mut drv, setup);
    let mut calls = vec![
        Call::FeedbackBuffer(1 << 16, gl::GL_4D_COLOR_TEXTURE),
        Call::RenderMode(gl::FEEDBACK),
    ];
    calls.extend_from_slice(body);
    run(&mut cpu, &mut drv, &calls);
    cpu.render_mode(gl::RENDER);
    drv.execute(&Call::RenderMode(gl::RENDER));
    assert_eq!(cpu.get_error(), drv.get_error());
    // EvalCoord leaves the current values as they were (GL 2.1 §5.1). llvmpipe's CURRENT_*
    // queries after an evaluation read values of other attributes when materials were set
    // (docs/conformance.md): compared in the unlit cases only.
    if !setup.contains(&Call::Enable(gl::LIGHTING)) {
        for pname in [
            gl::CURRENT_COLOR,
            gl::CURRENT_TEXTURE_COORDS,
            gl::CURRENT_NORMAL,
        ] {
            let (mut a, mut b) = ([0.0f32; 4], [0.0f32; 4]);
            cpu.get_floatv(pname, &mut a);
            drv.get_floatv(pname, &mut b);
            assert_eq!(a, b, "{name}: GetFloatv({pname:#x})");
        }
    }
    Some((
        cpu.feedback_values().to_vec(),
        drv.feedback_values().to_vec(),
    ))
}

/// Feedback values agree to a few float steps (the evaluation is Mesa's operation for
/// operation; the transform and lighting around it are the crate's own).
fn assert_close(name: &str, a: &[f32], b: &[f32]) {
    assert_eq!(a.len(), b.len(), "{name}: {a:?}\n{b:?}");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let tol = 1e-4 * x.abs().max(1.0);
        assert!(
            (x - y).abs() <= tol,
            "{name}: value {i}: {x} vs {y}\n{a:?}\n{b:?}"
        );
    }
    assert!(!a.is_empty(), "{name}: some feedback");
}

/// A lit, textured setup: the colour in feedback shows the evaluated normal.
fn lit_setup() -> Vec<Call> {
    vec![
        Call::MatrixMode(gl::PROJECTION),
        Call::Ortho(Box::new([-2.0, 2.0, -2.0, 2.0, -10.0, 10.0])),
        Call::MatrixMode(gl::MODELVIEW),
        Call::Rotatef(30.0, 1.0, 0.5, 0.0),
        Call::Enable(gl::LIGHTING),
        Call::Enable(gl::LIGHT0),
        Call::Lightfv(gl::LIGHT0, gl::POSITION, vec![0.5, 1.0, 2.0, 0.0]),
        Call::Lightfv(gl::LIGHT0, gl::SPECULAR, vec![1.0, 1.0, 1.0, 1.0]),
        Call::Materialfv(gl::FRONT_AND_BACK, gl::SPECULAR, vec![0.5, 0.5, 0.5, 1.0]),
        Call::Materialf(gl::FRONT_AND_BACK, gl::SHININESS, 20.0),
        Call::Normal3f(0.0, 0.6, 0.8),
    ]
}

/// bezmesh's patch, u along the inner index.
const PATCH: [f32; 48] = [
    -1.5, -1.5, 4.0, -0.5, -1.5, 2.0, 0.5, -1.5, -1.0, 1.5, -1.5, 2.0, //
    -1.5, -0.5, 1.0, -0.5, -0.5, 3.0, 0.5, -0.5, 0.0, 1.5, -0.5, -1.0, //
    -1.5, 0.5, 4.0, -0.5, 0.5, 0.0, 0.5, 0.5, 3.0, 1.5, 0.5, 4.0, //
    -1.5, 1.5, -2.0, -0.5, 1.5, -2.0, 0.5, 1.5, 0.0, 1.5, 1.5, -1.0,
];

#[test]
fn evaluated_vertices_match_the_driver_in_feedback() {
    let patch = |t: u32, uo: i32, vo: i32| {
        Call::Map2f(Box::new((
            t,
            0.0,
            1.0,
            3,
            uo,
            0.0,
            1.0,
            12,
            vo,
            PATCH.to_vec(),
        )))
    };
    let scaled: Vec<f32> = PATCH.iter().map(|x| x * 0.3).collect();
    let cases: Vec<(&str, Vec<Call>, Vec<Call>)> = vec![
        (
            "curve with colour and texture maps",
            vec![
                // Set, so that the plain vertex at the end shows them: llvmpipe gives a vertex
                // (0,0,0,0) for a colour never set once an evaluated one was (docs/conformance.md).
                Call::Color4f(0.2, 0.4, 0.6, 0.8),
                Call::TexCoord2f(0.5, 0.25),
                Call::Map1f(Box::new((
                    gl::MAP1_VERTEX_3,
                    2.0,
                    -1.0,
                    3,
                    4,
                    scaled[..12].to_vec(),
                ))),
                Call::Map1f(Box::new((
                    gl::MAP1_COLOR_4,
                    2.0,
                    -1.0,
                    4,
                    3,
                    values(12).iter().map(|v| v / 3.0 + 0.5).collect(),
                ))),
                Call::Map1f(Box::new((
                    gl::MAP1_TEXTURE_COORD_2,
                    0.0,
                    1.0,
                    2,
                    5,
                    values(10),
                ))),
                Call::Map1f(Box::new((
                    gl::MAP1_TEXTURE_COORD_3,
                    0.0,
                    1.0,
                    3,
                    2,
                    values(6),
                ))),
                Call::Enable(gl::MAP1_VERTEX_3),
                Call::Enable(gl::MAP1_COLOR_4),
                Call::Enable(gl::MAP1_TEXTURE_COORD_2),
                Call::MapGrid1f(9, 2.0, -1.0),
            ],
            vec![
                Call::EvalMesh1(gl::LINE, 0, 9),
                Call::EvalMesh1(gl::POINT, 2, 5),
                Call::Begin(gl::POINTS),
                Call::EvalCoord1f(0.3),
                Call::EvalCoord1d(1.7),
                Call::EvalPoint1(4),
                Call::Enable(gl::MAP1_TEXTURE_COORD_3),
                Call::EvalCoord1fv([0.9]),
                Call::End,
                // The current values did not change: a plain vertex shows them.
                Call::Begin(gl::POINTS),
                Call::Vertex2f(0.1, 0.2),
                Call::End,
            ],
        ),
        (
            "lit patch, AUTO_NORMAL, every mesh mode",
            {
                let mut s = lit_setup();
                s.extend([
                    patch(gl::MAP2_VERTEX_3, 4, 4),
                    Call::Enable(gl::MAP2_VERTEX_3),
                    Call::Enable(gl::AUTO_NORMAL),
                    Call::MapGrid2f(5, 0.0, 1.0, 4, 0.0, 1.0),
                ]);
                s
            },
            vec![
                Call::EvalMesh2(gl::FILL, 0, 5, 0, 4),
                Call::EvalMesh2(gl::LINE, 1, 3, 0, 2),
                Call::EvalMesh2(gl::POINT, 0, 2, 1, 3),
                Call::Begin(gl::TRIANGLES),
                Call::EvalCoord2f(0.1, 0.2),
                Call::EvalCoord2d(0.7, 0.4),
                Call::EvalPoint2(3, 1),
                Call::End,
            ],
        ),
        (
            "uneven orders, normal map without AUTO_NORMAL",
            {
                let mut s = lit_setup();
                s.extend([
                    patch(gl::MAP2_VERTEX_3, 4, 2),
                    patch(gl::MAP2_NORMAL, 2, 3),
                    Call::Enable(gl::MAP2_VERTEX_3),
                    Call::Enable(gl::MAP2_NORMAL),
                    Call::MapGrid2d(Box::new((3, 0.0, 1.0, 3, 0.0, 1.0))),
                ]);
                s
            },
            vec![Call::EvalMesh2(gl::FILL, 0, 3, 0, 3)],
        ),
        (
            "AUTO_NORMAL with orders 3x5, 5x3, 2x4",
            {
                let mut s = lit_setup();
                s.extend([
                    Call::Map2f(Box::new((
                        gl::MAP2_VERTEX_3,
                        0.0,
                        1.0,
                        3,
                        3,
                        0.0,
                        1.0,
                        9,
                        5,
                        values(45).iter().map(|v| (v * 1.7).sin()).collect(),
                    ))),
                    Call::Enable(gl::MAP2_VERTEX_3),
                    Call::Enable(gl::AUTO_NORMAL),
                    Call::MapGrid2f(4, 0.0, 1.0, 4, 0.0, 1.0),
                ]);
                s
            },
            vec![
                Call::EvalMesh2(gl::FILL, 0, 4, 0, 4),
                Call::Map2f(Box::new((
                    gl::MAP2_VERTEX_3,
                    0.0,
                    1.0,
                    3,
                    5,
                    0.0,
                    1.0,
                    15,
                    3,
                    values(45).iter().map(|v| (v * 0.9).cos()).collect(),
                ))),
                Call::EvalMesh2(gl::FILL, 0, 4, 0, 4),
                Call::Map2f(Box::new((
                    gl::MAP2_VERTEX_3,
                    -1.0,
                    1.0,
                    3,
                    2,
                    1.0,
                    0.0,
                    6,
                    4,
                    values(24).iter().map(|v| (v * 0.5).sin()).collect(),
                ))),
                Call::EvalMesh2(gl::FILL, 0, 4, 0, 4),
            ],
        ),
        (
            "rational patch with colour and texture",
            {
                let mut s = lit_setup();
                s.extend([
                    Call::Map2f(Box::new((
                        gl::MAP2_VERTEX_4,
                        0.0,
                        1.0,
                        4,
                        3,
                        0.0,
                        1.0,
                        12,
                        2,
                        vec![
                            1.0, 0.0, 0.0, 1.0, 0.7, 0.7, 0.0, 0.7, 0.0, 1.0, 0.0, 1.0, //
                            1.0, 0.0, 1.0, 1.0, 0.7, 0.7, 0.7, 0.7, 0.0, 1.0, 1.0, 1.0,
                        ],
                    ))),
                    Call::Map2f(Box::new((
                        gl::MAP2_COLOR_4,
                        0.0,
                        1.0,
                        4,
                        2,
                        0.0,
                        1.0,
                        8,
                        2,
                        values(16).iter().map(|v| v / 4.0 + 0.6).collect(),
                    ))),
                    Call::Map2f(Box::new((
                        gl::MAP2_TEXTURE_COORD_4,
                        0.0,
                        1.0,
                        4,
                        2,
                        0.0,
                        1.0,
                        8,
                        2,
                        values(16),
                    ))),
                    Call::Enable(gl::MAP2_VERTEX_4),
                    Call::Enable(gl::MAP2_VERTEX_3),
                    Call::Enable(gl::MAP2_COLOR_4),
                    Call::Enable(gl::MAP2_TEXTURE_COORD_4),
                    Call::Enable(gl::MAP2_TEXTURE_COORD_1),
                    Call::Enable(gl::AUTO_NORMAL),
                    // The evaluated colour feeds the material, per vertex.
                    Call::Enable(gl::COLOR_MATERIAL),
                    Call::MapGrid2f(3, 0.0, 1.0, 2, 0.0, 1.0),
                ]);
                s
            },
            vec![
                Call::EvalMesh2(gl::FILL, 0, 3, 0, 2),
                Call::EvalMesh2(gl::LINE, 0, 3, 0, 2),
            ],
        ),
        (
            "no vertex map: nothing",
            vec![
                Call::Color4f(0.3, 0.6, 0.9, 1.0),
                Call::Map2f(Box::new((
                    gl::MAP2_COLOR_4,
                    0.0,
                    1.0,
                    4,
                    2,
                    0.0,
                    1.0,
                    8,
                    2,
                    values(16),
                ))),
                Call::Enable(gl::MAP2_COLOR_4),
                Call::Enable(gl::MAP1_VERTEX_3),
            ],
            vec![
                Call::EvalMesh2(gl::FILL, 0, 3, 0, 2),
                Call::Begin(gl::POINTS),
                Call::EvalCoord2f(0.5, 0.5),
                Call::Vertex2f(0.0, 0.0),
                Call::End,
            ],
        ),
    ];
    for (name, setup, body) in cases {
        let Some((a, b)) = feedback(name, &setup, &body) else {
            return;
        };
        assert_close(name, &a, &b);
    }
}

#[test]
fn display_lists_copy_the_points_and_compile_the_eval_commands() {
    let Some(mut drv) = backend() else { return };
    let mut cpu = Context::new(W, W).expect("context");
    let patch = |uo: i32, scale: f32| {
        let p: Vec<f32> = PATCH.iter().map(|x| x * scale).collect();
        Call::Map2f(Box::new((
            gl::MAP2_VERTEX_3,
            0.0,
            1.0,
            3,
            uo,
            0.0,
            1.0,
            12,
            4,
            p,
        )))
    };
    let mut calls = lit_setup();
    calls.extend([
        Call::Enable(gl::MAP2_VERTEX_3),
        Call::Enable(gl::AUTO_NORMAL),
        Call::Enable(gl::DEPTH_TEST),
        Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT),
        Call::NewList(1, gl::COMPILE),
        patch(4, 0.5),
        Call::MapGrid2f(12, 0.0, 1.0, 12, 0.0, 1.0),
        Call::EvalMesh2(gl::FILL, 0, 12, 0, 12),
        Call::Begin(gl::POINTS),
        Call::EvalPoint2(6, 6),
        Call::EvalCoord2f(0.25, 0.75),
        Call::End,
        Call::EndList,
    ]);
    run(&mut cpu, &mut drv, &calls);
    // Compiled, not executed: the maps and grid are as they were.
    assert_state_agrees(&mut cpu, &mut drv, "after COMPILE");
    let mut before = vec![0.0f32; 2];
    cpu.get_mapfv(gl::MAP2_VERTEX_3, gl::ORDER, &mut before);
    assert_eq!(before, [1.0, 1.0]);
    // Another map now; the list runs its own copy.
    run(&mut cpu, &mut drv, &[patch(2, 1.0), Call::CallList(1)]);
    assert_state_agrees(&mut cpu, &mut drv, "after CallList");
    let cmp = compare(&cpu.to_image(), &drv.read_image(), 2);
    assert!(cmp.differing_percent <= 0.05, "{cmp:?}");
    assert!(cmp.differing_percent < 100.0);
    // COMPILE_AND_EXECUTE of a Map changes the map now as well.
    run(
        &mut cpu,
        &mut drv,
        &[
            Call::NewList(2, gl::COMPILE_AND_EXECUTE),
            patch(3, 2.0),
            Call::EndList,
        ],
    );
    assert_state_agrees(&mut cpu, &mut drv, "after COMPILE_AND_EXECUTE");
}

#[test]
fn push_attrib_eval_bit_saves_the_enables_and_grids_not_the_maps() {
    let Some(mut drv) = backend() else { return };
    let mut cpu = Context::new(W, W).expect("context");
    let calls = [
        Call::Enable(gl::AUTO_NORMAL),
        Call::Enable(gl::MAP1_COLOR_4),
        Call::Enable(gl::MAP2_TEXTURE_COORD_3),
        Call::MapGrid1f(5, 0.5, 1.5),
        Call::MapGrid2f(3, -1.0, 1.0, 4, 2.0, 3.0),
        Call::PushAttrib(gl::EVAL_BIT),
        Call::Disable(gl::AUTO_NORMAL),
        Call::Disable(gl::MAP1_COLOR_4),
        Call::Enable(gl::MAP2_VERTEX_4),
        Call::MapGrid1f(9, 0.0, 0.25),
        Call::MapGrid2d(Box::new((1, 0.0, 1.0, 1, 0.0, 1.0))),
        Call::Map1f(Box::new((gl::MAP1_NORMAL, 0.0, 2.0, 3, 2, values(6)))),
    ];
    run(&mut cpu, &mut drv, &calls);
    assert_state_agrees(&mut cpu, &mut drv, "pushed and changed");
    run(&mut cpu, &mut drv, &[Call::PopAttrib]);
    assert_state_agrees(&mut cpu, &mut drv, "popped");
    assert!(cpu.is_enabled(gl::AUTO_NORMAL) && !cpu.is_enabled(gl::MAP2_VERTEX_4));
    let mut order = [0.0f32];
    cpu.get_mapfv(gl::MAP1_NORMAL, gl::ORDER, &mut order);
    assert_eq!(order, [2.0], "the map itself is in no attribute group");
    // ENABLE_BIT holds the evaluator enables too.
    run(
        &mut cpu,
        &mut drv,
        &[
            Call::PushAttrib(gl::ENABLE_BIT),
            Call::Disable(gl::AUTO_NORMAL),
            Call::Enable(gl::MAP1_VERTEX_3),
            Call::PopAttrib,
        ],
    );
    assert_state_agrees(&mut cpu, &mut drv, "ENABLE_BIT");
}

#[test]
fn the_evaluators_scene_matches_the_driver() {
    let scene = fixedgl::scenes::find("evaluators").expect("registered");
    let (mut ctx, calls) = scene.record(300, 300).expect("records");
    let Some(mut drv) = crate::common::test_backend(300, 300) else {
        return;
    };
    drv.replay(&calls);
    assert_eq!(drv.get_error(), gl::NO_ERROR);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let cmp = compare(&ctx.to_image(), &drv.read_image(), 2);
    assert!(cmp.differing_percent <= 0.05, "{cmp:?}");
}
