//! Assembly, clipping, setup, rasterisation and per-fragment tests (GL 2.1 §2.6, §2.12, §3.4–3.6,
//! §4.1), checked at known pixels.

use glam::{Vec3, Vec4};

use super::*;

const PALETTE: [Vec4; 6] = [
    RED,
    GREEN,
    BLUE,
    Vec4::new(1.0, 1.0, 0.0, 1.0),
    Vec4::new(0.0, 1.0, 1.0, 1.0),
    Vec4::new(1.0, 0.0, 1.0, 1.0),
];

fn rgb(c: Vec4) -> [u8; 4] {
    [c.x, c.y, c.z, c.w].map(|v| (v * 255.0) as u8)
}

/// Draws `mode` with positions `ps` coloured by the palette in order.
fn draw_pal(r: &mut Renderer, st: &State, mode: u32, ps: &[[f32; 2]]) {
    let vs: Vec<_> = ps
        .iter()
        .zip(PALETTE.iter().cycle())
        .map(|(p, &c)| ([p[0], p[1], 0.0], c))
        .collect();
    draw(r, st, mode, &vs);
}

/// The red byte of every pixel (coverage counts when `count_coverage` is on).
fn counts(r: &mut Renderer) -> Vec<u8> {
    r.color().iter().map(|c| c[0]).collect()
}

#[test]
fn shared_edges_are_drawn_once() {
    let (mut r, st) = setup(16, 16);
    r.count_coverage = true;
    // A full-window quad split along y = x: the diagonal passes exactly through pixel centres.
    let q = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    draw_pal(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[q[0], q[1], q[2], q[0], q[2], q[3]],
    );
    assert!(counts(&mut r).iter().all(|&c| c == 1));
    // An irregular quad: no pixel twice, and the covered set matches the quad drawn as a polygon.
    let (mut r2, _) = setup(16, 16);
    r2.count_coverage = true;
    let q = [[-0.9, -0.8], [0.7, -0.95], [0.85, 0.9], [-0.6, 0.75]];
    draw_pal(
        &mut r2,
        &st,
        gl::TRIANGLES,
        &[q[0], q[1], q[2], q[0], q[2], q[3]],
    );
    let c = counts(&mut r2);
    assert!(c.iter().all(|&c| c <= 1));
    assert!(c.iter().filter(|&&c| c == 1).count() > 150);
}

#[test]
fn vertical_and_horizontal_edges_through_centres() {
    let (mut r, st) = setup(16, 16);
    r.count_coverage = true;
    // x = 0.0625 ndc is window x = 8.5, the centre of column 8; y likewise for row 8.
    let m = 0.0625;
    let quads = [
        [[-1.0, -1.0], [m, -1.0], [m, m], [-1.0, m]],
        [[m, -1.0], [1.0, -1.0], [1.0, m], [m, m]],
        [[m, m], [1.0, m], [1.0, 1.0], [m, 1.0]],
        [[-1.0, m], [m, m], [m, 1.0], [-1.0, 1.0]],
    ];
    for q in quads {
        draw_pal(&mut r, &st, gl::QUADS, &q);
    }
    assert!(counts(&mut r).iter().all(|&c| c == 1));
}

#[test]
fn fan_covering_the_viewport_covers_every_pixel_once() {
    let (mut r, st) = setup(37, 23);
    r.count_coverage = true;
    let fan = [
        [0.1, -0.2],
        [-1.0, -1.0],
        [0.3, -1.0],
        [1.0, -1.0],
        [1.0, 0.45],
        [1.0, 1.0],
        [-0.2, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.1],
        [-1.0, -1.0],
    ];
    draw_pal(&mut r, &st, gl::TRIANGLE_FAN, &fan);
    assert!(counts(&mut r).iter().all(|&c| c == 1));
}

#[test]
fn provoking_vertex_for_every_mode() {
    let mut st = State::new(16, 16);
    st.shade_model = gl::FLAT;
    let check = |mode: u32, ps: &[[f32; 2]], probes: &[(i64, i64, usize)]| {
        let mut r = Renderer::new(16, 16);
        draw_pal(&mut r, &st, mode, ps);
        for &(x, y, k) in probes {
            assert_eq!(
                px(&mut r, x, y),
                rgb(PALETTE[k]),
                "mode {mode:#x} at ({x},{y})"
            );
        }
    };
    let sq = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    // Points: each its own colour.  Window x = 8·(x + 1).
    check(
        gl::POINTS,
        &[[-0.5, 0.0], [0.5, 0.0]],
        &[(4, 8, 0), (12, 8, 1)],
    );
    // Lines: the second vertex; the strip's segments their end vertex; the loop's closing
    // segment its first vertex (table 2.2). Row 8 for y = 0.0625 (window 8.5).
    check(
        gl::LINES,
        &[[-1.0, 0.0625], [1.0, 0.0625]],
        &[(3, 8, 1), (12, 8, 1)],
    );
    check(
        gl::LINE_STRIP,
        &[[-1.0, 0.0625], [0.0, 0.0625], [1.0, 0.0625]],
        &[(3, 8, 1), (12, 8, 2)],
    );
    check(
        gl::LINE_LOOP,
        // Closing segment (15.2,15.2)→(0.8,0.5): column 10.5 is at t = 0.326, y = 10.41 → row 10.
        &[[-0.9, -0.9375], [0.9, -0.9375], [0.9, 0.9]],
        &[(4, 0, 1), (10, 10, 0)],
    );
    // Triangles: the third vertex.
    check(gl::TRIANGLES, &[sq[0], sq[1], sq[2]], &[(12, 3, 2)]);
    // Strip: triangle i its vertex i + 2.
    check(
        gl::TRIANGLE_STRIP,
        &[[-1.0, -1.0], [-1.0, 1.0], [1.0, -1.0], [1.0, 1.0]],
        &[(1, 1, 2), (14, 14, 3)],
    );
    check(gl::TRIANGLE_FAN, &sq, &[(14, 1, 2), (1, 14, 3)]);
    // A quad: its fourth vertex; a quad strip: quad i its vertex 2i + 3 (0-based).
    check(gl::QUADS, &sq, &[(1, 1, 3), (14, 14, 3)]);
    check(
        gl::QUAD_STRIP,
        &[
            [-1.0, -1.0],
            [-1.0, 1.0],
            [0.0, -1.0],
            [0.0, 1.0],
            [1.0, -1.0],
            [1.0, 1.0],
        ],
        &[(2, 2, 3), (5, 13, 3), (10, 2, 5), (14, 14, 5)],
    );
    // A polygon: its first vertex.
    check(
        gl::POLYGON,
        &[
            [-1.0, -1.0],
            [1.0, -1.0],
            [1.0, 0.5],
            [0.0, 1.0],
            [-1.0, 0.5],
        ],
        &[(1, 1, 0), (8, 12, 0), (14, 2, 0)],
    );
}

#[test]
fn smooth_colour_is_perspective_correct() {
    let (mut r, st) = setup(64, 64);
    r.begin(gl::TRIANGLES);
    let black = Vec4::new(0.0, 0.0, 0.0, 1.0);
    // A at ndc (−1,−1) w 1, B at ndc (1,−1) with w 3, C at ndc (−1,1) w 1; only B is red.
    r.vertex(Vec4::new(-1.0, -1.0, 0.0, 1.0), &cur(black, Vec3::Z));
    r.vertex(Vec4::new(3.0, -3.0, 0.0, 3.0), &cur(RED, Vec3::Z));
    r.vertex(Vec4::new(-1.0, 1.0, 0.0, 1.0), &cur(black, Vec3::Z));
    r.end();
    r.flush(&st);
    // Pixel (31,0), centre (31.5, 0.5): screen barycentrics λB = 31.5/64, λC = 0.5/64, λA = 0.5.
    // red = (λB/3) / (λA/1 + λB/3 + λC/1) = 10.5/43 = 0.244186 → 62.27 + 0.5 → 62
    // (linear interpolation would give 125).
    assert_eq!(px(&mut r, 31, 0)[0], 62);
    // Pixel (0,0): λB = 0.5/64, λC = 0.5/64, λA = 63/64: (0.5/3)/(63 + 0.5/3 + 0.5) = 0.002618 → 1.
    assert_eq!(px(&mut r, 0, 0)[0], 1);
}

#[test]
fn every_depth_func() {
    // For a new fragment [closer, equal, farther] than the stored depth.
    let table = [
        (gl::NEVER, [false, false, false]),
        (gl::LESS, [true, false, false]),
        (gl::EQUAL, [false, true, false]),
        (gl::LEQUAL, [true, true, false]),
        (gl::GREATER, [false, false, true]),
        (gl::NOTEQUAL, [true, false, true]),
        (gl::GEQUAL, [false, true, true]),
        (gl::ALWAYS, [true, true, true]),
    ];
    let sq = |z: f32, c: Vec4| {
        [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|p| ([p[0], p[1], z], c))
    };
    for (func, expect) in table {
        for (k, z) in [-0.5f32, 0.0, 0.5].into_iter().enumerate() {
            let (mut r, mut st) = setup(4, 4);
            st.enables.depth_test = true;
            draw(&mut r, &st, gl::QUADS, &sq(0.0, RED));
            st.depth_func = func;
            draw(&mut r, &st, gl::QUADS, &sq(z, GREEN));
            let got = px(&mut r, 1, 2) == [0, 255, 0, 255];
            assert_eq!(got, expect[k], "func {func:#x}, z {z}");
            // Depth written only when the test passed: z = −0.5 → window 0.25.
            let d = r.framebuffer().pixel(1, 2).map(|p| p.1);
            let want = if got {
                (z as f64 * 0.5 + 0.5) * 16777215.0 + 0.5
            } else {
                8388608.0
            };
            assert_eq!(d, Some(want as u32), "func {func:#x}, z {z}");
        }
    }
}

#[test]
fn depth_mask_and_disabled_test_do_not_write_depth() {
    let (mut r, mut st) = setup(4, 4);
    let sq = |z: f32, c: Vec4| {
        [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|p| ([p[0], p[1], z], c))
    };
    draw(&mut r, &st, gl::QUADS, &sq(0.0, RED));
    assert_eq!(
        r.framebuffer().pixel(2, 2).map(|p| p.1),
        Some((1 << 24) - 1)
    );
    st.enables.depth_test = true;
    st.depth_mask = false;
    draw(&mut r, &st, gl::QUADS, &sq(0.0, GREEN));
    assert_eq!(px(&mut r, 2, 2), [0, 255, 0, 255]);
    assert_eq!(
        r.framebuffer().pixel(2, 2).map(|p| p.1),
        Some((1 << 24) - 1)
    );
}

#[test]
fn polygon_offset_units() {
    let (mut r, mut st) = setup(4, 4);
    st.enables.depth_test = true;
    st.enables.polygon_offset_fill = true;
    st.polygon_offset_units = 2.0;
    let sq = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|p| ([p[0], p[1], 0.0], RED));
    draw(&mut r, &st, gl::QUADS, &sq);
    // One unit is 2·2⁻²⁴ (llvmpipe's), so z = 0.5 + 4·2⁻²⁴:
    // 0.5·(2²⁴−1) + 4(2²⁴−1)/2²⁴ = 8388611.4999998 → 8388611.
    assert_eq!(r.framebuffer().pixel(1, 1).map(|p| p.1), Some(8_388_611));
}

#[test]
fn culling_and_front_face() {
    let ccw = [[-1.0, -1.0], [1.0, -1.0], [-1.0, 1.0]];
    let cw = [[-1.0, -1.0], [-1.0, 1.0], [1.0, -1.0]];
    let drawn = |st: &State, tri: &[[f32; 2]]| {
        let mut r = Renderer::new(8, 8);
        draw_pal(&mut r, st, gl::TRIANGLES, tri);
        px(&mut r, 1, 1) != [0; 4]
    };
    let mut st = State::new(8, 8);
    assert!(drawn(&st, &ccw) && drawn(&st, &cw));
    st.enables.cull_face = true;
    assert!(drawn(&st, &ccw) && !drawn(&st, &cw));
    st.cull_face_mode = gl::FRONT;
    assert!(!drawn(&st, &ccw) && drawn(&st, &cw));
    st.front_face = gl::CW;
    assert!(drawn(&st, &ccw) && !drawn(&st, &cw));
    st.cull_face_mode = gl::FRONT_AND_BACK;
    assert!(!drawn(&st, &ccw) && !drawn(&st, &cw));
}

#[test]
fn polygon_mode_line_and_point() {
    let (_, mut st) = setup(16, 16);
    // Window vertices (1.5, 1.5), (14.5, 1.5), (1.5, 14.5).
    let tri = [[-0.8125, -0.8125], [0.8125, -0.8125], [-0.8125, 0.8125]];
    let cw = [tri[0], tri[2], tri[1]];
    st.polygon_mode = [gl::LINE, gl::FILL];
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::TRIANGLES, &tri);
    assert_ne!(px(&mut r, 8, 1), [0; 4]); // on the bottom edge
    assert_ne!(px(&mut r, 1, 8), [0; 4]); // on the left edge
    assert_eq!(px(&mut r, 5, 5), [0; 4]); // interior
                                          // The back face fills.
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::TRIANGLES, &cw);
    assert_ne!(px(&mut r, 5, 5), [0; 4]);
    // POINT: the three vertices only.
    st.polygon_mode = [gl::POINT, gl::POINT];
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::TRIANGLES, &tri);
    assert_eq!(count_not(&mut r, [0; 4]), 3);
    assert_ne!(px(&mut r, 14, 1), [0; 4]);
    // LINE with the second vertex's edge flag off: the hypotenuse is not drawn.
    st.polygon_mode = [gl::LINE, gl::LINE];
    let mut r = Renderer::new(16, 16);
    r.begin(gl::TRIANGLES);
    for (i, p) in tri.iter().enumerate() {
        let mut c = cur(WHITE, Vec3::Z);
        c.inputs_mut().edge_flag = i != 1;
        r.vertex(Vec4::new(p[0], p[1], 0.0, 1.0), &c);
    }
    r.end();
    r.flush(&st);
    assert_eq!(px(&mut r, 8, 7), [0; 4]);
    assert_ne!(px(&mut r, 8, 1), [0; 4]);
    // A quad in LINE mode: no diagonal.
    let mut r = Renderer::new(16, 16);
    draw_pal(
        &mut r,
        &st,
        gl::QUADS,
        &[tri[0], tri[1], [0.8125, 0.8125], tri[2]],
    );
    assert_eq!(px(&mut r, 8, 8), [0; 4]);
    assert_ne!(px(&mut r, 14, 8), [0; 4]);
}

#[test]
fn near_plane_cut() {
    let (mut r, st) = setup(16, 16);
    // z = 2x: the part left of x = −0.5 is beyond the near plane, right of 0.5 beyond the far
    // one. Kept: window x in [4, 12] → columns 4..=11.
    let vs = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]
        .map(|p| ([p[0], p[1], 2.0 * p[0]], RED));
    draw(&mut r, &st, gl::QUADS, &vs);
    for y in 0..16 {
        for x in 0..16 {
            assert_eq!(
                px(&mut r, x, y) != [0; 4],
                (4..12).contains(&x),
                "({x},{y})"
            );
        }
    }
}

#[test]
fn inside_triangle_is_not_clipped_and_boundary_vertices_are_inside() {
    let (mut r, st) = setup(16, 16);
    r.count_coverage = true;
    // Vertices exactly on x = ±w (the frustum's edge): nothing is clipped away.
    draw_pal(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]],
    );
    // Row y has centres with x > y strictly inside, x == y on the diagonal: the edge from
    // (16,16) to (0,0) goes down (dy < 0), a left edge, so centres on it count:
    // 16 + 15 + ... + 1 = 136.
    assert_eq!(counts(&mut r).iter().filter(|&&c| c == 1).count(), 136);
}

#[test]
fn user_clip_plane() {
    let (mut r, mut st) = setup(16, 16);
    st.enables.clip_planes[0] = true;
    st.clip_planes[0] = glam::DVec4::new(1.0, 0.0, 0.0, 0.0); // keep x >= 0 (eye space)
    draw_pal(
        &mut r,
        &st,
        gl::QUADS,
        &[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]],
    );
    for y in 0..16 {
        for x in 0..16 {
            assert_eq!(px(&mut r, x, y) != [0; 4], x >= 8, "({x},{y})");
        }
    }
}

#[test]
fn flat_colour_survives_clipping() {
    let (mut r, mut st) = setup(16, 16);
    st.shade_model = gl::FLAT;
    // The provoking (third) vertex lies above the window and is clipped away.
    draw_pal(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[[-0.5, -0.5], [0.5, -0.5], [0.0, 3.0]],
    );
    assert_eq!(px(&mut r, 8, 6), rgb(BLUE));
    assert_eq!(px(&mut r, 8, 15), rgb(BLUE));
}

#[test]
fn nothing_behind_the_eye_is_drawn() {
    let (mut r, st) = setup(8, 8);
    r.begin(gl::TRIANGLES);
    for p in [[-1.0, -1.0], [1.0, -1.0], [0.0, 1.0]] {
        r.vertex(Vec4::new(p[0], p[1], 0.0, -1.0), &cur(WHITE, Vec3::Z));
    }
    r.end();
    r.flush(&st);
    assert_eq!(count_not(&mut r, [0; 4]), 0);
}

#[test]
fn lines_and_points() {
    let (mut r, mut st) = setup(16, 16);
    r.count_coverage = true;
    // A strip across the window at window y 8.5: 16 columns once each, the shared vertex once.
    draw_pal(
        &mut r,
        &st,
        gl::LINE_STRIP,
        &[[-1.0, 0.0625], [0.1, 0.0625], [1.0, 0.0625]],
    );
    let c = counts(&mut r);
    assert!((0..16).all(|x| c[8 * 16 + x] == 1));
    assert_eq!(c.iter().map(|&v| usize::from(v)).sum::<usize>(), 16);
    // Width 3: three rows, 7..=9.
    st.line_width = 3.0;
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::LINES, &[[-1.0, 0.0625], [1.0, 0.0625]]);
    assert_eq!(count_not(&mut r, [0; 4]), 48);
    assert!(
        px(&mut r, 5, 7) != [0; 4] && px(&mut r, 5, 9) != [0; 4] && px(&mut r, 5, 10) == [0; 4]
    );
    // Points: size 2 at window (8.3, 8.3) covers centres in [7.3, 9.3): columns/rows 7 and 8.
    st.point_size = 2.0;
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::POINTS, &[[0.3 / 8.0, 0.3 / 8.0]]);
    assert_eq!(count_not(&mut r, [0; 4]), 4);
    assert!(px(&mut r, 7, 7) != [0; 4] && px(&mut r, 8, 8) != [0; 4]);
    st.point_size = 3.0;
    let mut r = Renderer::new(16, 16);
    draw_pal(&mut r, &st, gl::POINTS, &[[0.3 / 8.0, 0.3 / 8.0]]);
    assert_eq!(count_not(&mut r, [0; 4]), 9);
    assert!(px(&mut r, 7, 7) != [0; 4] && px(&mut r, 9, 9) != [0; 4]);
}

#[test]
fn scissor_limits_drawing() {
    let (mut r, mut st) = setup(16, 16);
    st.enables.scissor_test = true;
    st.scissor = [2, 3, 4, 5];
    draw_pal(
        &mut r,
        &st,
        gl::QUADS,
        &[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]],
    );
    assert_eq!(count_not(&mut r, [0; 4]), 20);
    assert!(px(&mut r, 2, 3) != [0; 4] && px(&mut r, 5, 7) != [0; 4] && px(&mut r, 6, 7) == [0; 4]);
}

#[test]
fn color_mask_on_draw() {
    let (mut r, mut st) = setup(4, 4);
    st.color_mask = [true, false, true, false];
    draw(
        &mut r,
        &st,
        gl::QUADS,
        &[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|p| ([p[0], p[1], 0.0], WHITE)),
    );
    assert_eq!(px(&mut r, 1, 1), [255, 0, 255, 0]);
}

#[test]
fn phong_win_gives_a_sharper_highlight() {
    // A single coarse quad facing the viewer, normals all (0,0,1), a positional light just
    // above its centre: at the corners the highlight is faint, at the centre N·H = 1.
    let render = |model: u32| {
        let (mut r, mut st) = setup(32, 32);
        st.shade_model = model;
        st.enables.lighting = true;
        st.enables.lights[0] = true;
        st.light_model.ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
        st.lights[0].position = Vec4::new(0.0, 0.0, 1.0, 1.0);
        st.lights[0].diffuse = Vec4::ZERO;
        st.materials[0].ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
        st.materials[0].specular = Vec4::ONE;
        st.materials[0].shininess = 50.0;
        r.begin(gl::QUADS);
        for p in [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]] {
            r.vertex(Vec4::new(p[0], p[1], 0.0, 1.0), &cur(WHITE, Vec3::Z));
        }
        r.end();
        r.flush(&st);
        (0..32).map(|x| px(&mut r, x, 16)[0]).collect::<Vec<_>>()
    };
    let (smooth, phong) = (render(gl::SMOOTH), render(gl::PHONG_WIN));
    // At a corner L = (1,1,1)/√3 and h ∝ (1,1,1+√3): N·h = 0.8881; 0.8881^50 ≈ 0.0027 → 1 or 0.
    // Gouraud spreads that everywhere; per-fragment at the centre (pixel 16, centre (0.03, 0.03)
    // in eye space) N·h ≈ 1 → ≈ 255.
    assert!(smooth.iter().all(|&v| v <= 1), "{smooth:?}");
    assert!(phong[16] >= 250, "{phong:?}");
    // Narrow: cos^50 φ = 0.5 at φ = 9.52° between N and h; h is half-way to L, so L is 19.04°
    // off the normal: |x| < tan 19.04° = 0.345 ndc, i.e. centres (i + 0.5)/16 − 1 in that range:
    // i = 10..=21, 12 pixels, but i = 10 and 21 sit right at the threshold (x = 0.34375), so
    // 10..=12 pixels.
    let wide = phong.iter().filter(|&&v| v >= 128).count();
    assert!((10..=12).contains(&wide), "{phong:?}");
}

/// A watertight 32x32-cell mesh over the whole window with jittered interior points, as
/// triangles (two per cell, `per_cell` Begin/End pairs or one big one).
fn jittered_mesh(r: &mut Renderer, st: &State, one_primitive: bool) {
    let n = 32;
    let pt = |i: usize, j: usize| {
        let f = |k: usize| -1.0 + 2.0 * k as f32 / n as f32;
        let interior = |k: usize| k > 0 && k < n;
        // A fixed pseudo-random jitter of up to ±0.3 cell.
        let h = ((i * 7919 + j * 104_729) % 997) as f32 / 997.0 - 0.5;
        let g = ((i * 15_485_863 + j * 32_452_843) % 991) as f32 / 991.0 - 0.5;
        let dx = if interior(i) && interior(j) {
            0.6 * h / n as f32
        } else {
            0.0
        };
        let dy = if interior(i) && interior(j) {
            0.6 * g / n as f32
        } else {
            0.0
        };
        Vec4::new(f(i) + dx, f(j) + dy, 0.0, 1.0)
    };
    let c = cur(WHITE, Vec3::Z);
    if one_primitive {
        r.begin(gl::TRIANGLES);
    }
    for j in 0..n {
        for i in 0..n {
            if !one_primitive {
                r.begin(gl::TRIANGLES);
            }
            for (a, b) in [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)] {
                r.vertex(pt(i + a, j + b), &c);
            }
            if !one_primitive {
                r.end();
            }
        }
    }
    if one_primitive {
        r.end();
    }
    r.flush(st);
}

#[test]
fn large_meshes_cover_every_pixel_once_on_every_setup_path() {
    for one in [false, true] {
        let (mut r, st) = setup(70, 50);
        r.count_coverage = true;
        // 32·32·6 = 6144 vertices: enough for the parallel setup paths (by primitives when
        // they are many, by triangles when one primitive holds them all).
        jittered_mesh(&mut r, &st, one);
        assert!(
            counts(&mut r).iter().all(|&c| c == 1),
            "one primitive: {one}"
        );
    }
}

#[test]
fn hostile_input_never_panics() {
    let bad = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1e30,
        -1e30,
        0.0,
        1e-30,
    ];
    for mode in gl::POINTS..=gl::POLYGON {
        for &pm in &[gl::FILL, gl::LINE, gl::POINT] {
            let (mut r, mut st) = setup(9, 7);
            st.polygon_mode = [pm, pm];
            st.point_size = 1e30;
            st.line_width = 1e30;
            st.enables.polygon_offset_fill = true;
            st.polygon_offset_factor = 1e30;
            st.enables.depth_test = true;
            st.enables.lighting = true;
            st.enables.lights[0] = true;
            st.lights[0].position = Vec4::new(0.0, 0.0, 0.0, 1.0);
            st.viewport = [i32::MAX - 5, i32::MIN + 5, 16384, 16384];
            r.begin(mode);
            for (i, &x) in bad.iter().enumerate() {
                let y = bad[(i + 3) % bad.len()];
                r.vertex(
                    Vec4::new(x, y, 0.5, 1.0),
                    &cur(WHITE, Vec3::new(x, 0.0, 0.0)),
                );
                r.vertex(Vec4::new(0.5, -0.5, x, y), &cur(WHITE, Vec3::Z));
            }
            r.end();
            r.flush(&st);
            st.viewport = [0, 0, 9, 7];
            r.begin(mode);
            for &x in &bad {
                r.vertex(Vec4::new(x, 0.5, 0.0, 1.0), &cur(Vec4::splat(x), Vec3::Z));
                r.vertex(Vec4::new(-0.5, x, 0.0, 1.0), &cur(WHITE, Vec3::Z));
                r.vertex(Vec4::new(0.5, 0.5, 0.0, x), &cur(WHITE, Vec3::Z));
            }
            r.end();
            r.flush(&st);
        }
    }
}

#[test]
fn lines_follow_the_diamond_exit_rule() {
    let st = State::new(16, 16);
    // Window x → ndc: x/8 − 1; row 5's centre line y = 5.5 → −0.3125.
    let ndc = |x: f32| x / 8.0 - 1.0;
    let drawn = |xa: f32, xb: f32| {
        let mut r = Renderer::new(16, 16);
        draw_pal(
            &mut r,
            &st,
            gl::LINES,
            &[[ndc(xa), -0.3125], [ndc(xb), -0.3125]],
        );
        (0..16)
            .filter(|&x| px(&mut r, x, 5) != [0; 4])
            .collect::<Vec<_>>()
    };
    // From 2.7: the start lies in pixel 2's diamond (|2.7 − 2.5| = 0.2 < 0.5), which the line
    // leaves, so pixel 2 is drawn; pixel 8's centre 8.5 lies past the end 8.3: not drawn.
    assert_eq!(drawn(2.7, 8.3), (2..=7).collect::<Vec<_>>());
    // To 8.6: the end lies in pixel 8's diamond (0.1 < 0.5), never left: not drawn.
    assert_eq!(drawn(2.2, 8.6), (2..=7).collect::<Vec<_>>());
    // Reversed: pixel 8's diamond holds the start (drawn, the line leaves it); pixel 2's holds
    // the end (|2.2 − 2.5| = 0.3 < 0.5): not drawn.
    assert_eq!(drawn(8.6, 2.2), (3..=8).collect::<Vec<_>>());
}

#[test]
fn tie_rule_owns_left_and_bottom_edges() {
    let (mut r, st) = setup(16, 16);
    // Window coordinates through pixel centres: x/8 − 1.
    let ndc = |p: [f32; 2]| [p[0] / 8.0 - 1.0, p[1] / 8.0 - 1.0];
    let a = [[2.5, 2.5], [8.5, 2.5], [2.5, 8.5]].map(ndc);
    let b = [[13.5, 13.5], [9.5, 13.5], [13.5, 9.5]].map(ndc);
    draw_pal(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[a[0], a[1], a[2], b[0], b[1], b[2]],
    );
    // A: its bottom edge (row 2) and left edge (column 2) own their centres; the hypotenuse
    // x + y = 11 does not (it goes up-left), so row 2 is columns 2..=7.
    let row2: Vec<i64> = (0..16).filter(|&x| px(&mut r, x, 2) != [0; 4]).collect();
    assert_eq!(row2, (2..=7).collect::<Vec<_>>());
    assert!((2..=7).all(|y| px(&mut r, 2, y) != [0; 4]));
    // B: its top edge (row 13) and right edge (column 13) own nothing.
    assert!((0..16).all(|x| px(&mut r, x, 13) == [0; 4]));
    assert!((0..16).all(|y| px(&mut r, 13, y) == [0; 4]));
    assert_ne!(px(&mut r, 12, 12), [0; 4]);
}

#[test]
fn edges_along_a_user_clip_plane_are_drawn_in_line_mode() {
    let (mut r, mut st) = setup(16, 16);
    st.polygon_mode = [gl::LINE, gl::LINE];
    st.enables.clip_planes[0] = true;
    // Keep x <= 0.0625 (window x <= 8.5, the centres of column 8).
    st.clip_planes[0] = glam::DVec4::new(-1.0, 0.0, 0.0, 0.0625);
    draw_pal(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[[-0.9, -0.9], [0.9, -0.9], [-0.9, 0.9]],
    );
    // The cut runs along column 8 from the bottom edge up to the hypotenuse (window y from 0.8
    // to 8.3): rows 1..=7 of column 8 are drawn; nothing right of it.
    assert!((1..=7).all(|y| px(&mut r, 8, y) != [0; 4]));
    assert!((0..16).all(|y| px(&mut r, 9, y) == [0; 4]));
}

/// Triangle strips are set up as they are assembled (`Worker::strip`), other primitives through
/// `assembly::assemble`: strips of 0 to 9 vertices, with points, triangles and quads between
/// them, give the pixels of the same triangles drawn as TRIANGLES in the strip's order (odd
/// triangles with their first two vertices swapped, the third vertex provoking), smooth and
/// flat, back faces culled, one Begin/End per primitive, with enough vertices for the parallel
/// setup.
#[test]
fn strips_set_up_while_assembled_are_their_triangles() {
    let pt = |k: usize| {
        let h = |m: usize| ((k * m) % 997) as f32 / 997.0;
        Vec4::new(
            2.2 * h(7919) - 1.1,
            2.2 * h(104_729) - 1.1,
            h(31) - 0.5,
            1.0,
        )
    };
    let col = |k: usize| *PALETTE.get(k % PALETTE.len()).unwrap_or(&WHITE);
    for flat in [false, true] {
        let (mut a, mut st) = setup(61, 47);
        let (mut b, _) = setup(61, 47);
        if flat {
            st.shade_model = gl::FLAT;
        }
        st.enables.depth_test = true;
        // Culling makes each triangle's orientation, which the odd triangles' swap keeps,
        // visible in the pixels.
        st.enables.cull_face = true;
        let mut k = 0;
        let mut given = 0;
        for s in 0..1500 {
            let n = s % 10;
            let vs: Vec<usize> = (k..k + n).collect();
            k += n;
            a.begin(gl::TRIANGLE_STRIP);
            a.begin_materials(&st.materials);
            for &v in &vs {
                a.vertex(pt(v), &cur(col(v), Vec3::Z));
            }
            a.end();
            b.begin(gl::TRIANGLES);
            b.begin_materials(&st.materials);
            for i in 0..n.saturating_sub(2) {
                let t = if i % 2 == 0 {
                    [i, i + 1, i + 2]
                } else {
                    [i + 1, i, i + 2]
                };
                for j in t {
                    let v = vs[j];
                    b.vertex(pt(v), &cur(col(v), Vec3::Z));
                }
            }
            b.end();
            given += n;
            // Every seventh strip, a run of other primitives, the same in both.
            if s % 7 == 3 {
                for (mode, m) in [(gl::POINTS, 2), (gl::TRIANGLES, 3), (gl::QUADS, 4)] {
                    for r in [&mut a, &mut b] {
                        r.begin(mode);
                        r.begin_materials(&st.materials);
                        for v in k..k + m {
                            r.vertex(pt(v), &cur(col(v), Vec3::Z));
                        }
                        r.end();
                    }
                    k += m;
                }
            }
        }
        assert!(
            given > 4096,
            "too few vertices for the parallel setup: {given}"
        );
        a.flush(&st);
        b.flush(&st);
        let (ca, cb) = (a.color(), b.color());
        assert!(
            ca.iter().any(|c| *c != ca[0]),
            "nothing drawn (flat: {flat})"
        );
        assert!(
            ca == cb,
            "strips differ from their triangles (flat: {flat})"
        );
    }
}
