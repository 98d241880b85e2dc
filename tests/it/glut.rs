//! The GLUT shapes against freeglut 3.x's construction (fg_geometry.c, fg_teapot.c), with the
//! expected values computed here independently in f64 from the shapes' defining formulas:
//! vertex counts, positions and normals at sampled vertices, unit outward normals, and
//! counter-clockwise (front-facing, GL 2.1 §3.5.1) winding seen from outside.

use fixedgl::glut::{self, Mesh};
use fixedgl::{gl, Call, Context};
use std::f64::consts::PI;

fn close(a: [f32; 3], b: [f64; 3], tol: f64) -> bool {
    a.iter()
        .zip(b)
        .all(|(&x, y)| (f64::from(x) - y).abs() <= tol)
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| f64::from(a[k]) - f64::from(b[k]))
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Every normal has unit length.
fn unit_normals(m: &Mesh) {
    for n in &m.normals {
        let len = dot(n.map(f64::from), n.map(f64::from)).sqrt();
        assert!((len - 1.0).abs() < 1e-5, "normal {n:?} has length {len}");
    }
}

/// Counts the non-degenerate triangles that are counter-clockwise and clockwise seen from the
/// side their vertex normals point to (counter-clockwise: the outside is the front face).
fn windings(m: &Mesh) -> (usize, usize) {
    let (mut ccw, mut cw) = (0, 0);
    for (mode, idx) in &m.parts {
        let tris: Vec<[u32; 3]> = match *mode {
            gl::TRIANGLES => idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
            gl::TRIANGLE_STRIP => (0..idx.len().saturating_sub(2))
                .map(|k| {
                    if k % 2 == 0 {
                        [idx[k], idx[k + 1], idx[k + 2]]
                    } else {
                        [idx[k + 1], idx[k], idx[k + 2]]
                    }
                })
                .collect(),
            _ => continue,
        };
        for [a, b, c] in tris {
            let v = |i: u32| m.vertices[i as usize];
            let geo = cross(sub(v(b), v(a)), sub(v(c), v(a)));
            // Slivers (twice the area below 1e-4) have no reliable winding: the teapot's knob
            // tip, where the lid patch's first row collapses to within 0.002 of a point, has
            // twelve of them, turned either way.
            if dot(geo, geo).sqrt() < 1e-4 {
                continue;
            }
            let ns: [f64; 3] = [0, 1, 2].map(|k| {
                [a, b, c]
                    .iter()
                    .map(|&i| f64::from(m.normals[i as usize][k]))
                    .sum()
            });
            if dot(geo, ns) > 0.0 {
                ccw += 1;
            } else {
                cw += 1;
            }
        }
    }
    (ccw, cw)
}

/// Every non-degenerate triangle is front-facing from outside; returns how many there are.
fn outward_ccw(m: &Mesh) -> usize {
    let (ccw, cw) = windings(m);
    assert_eq!(cw, 0, "{cw} triangles wind inward");
    ccw
}

#[test]
fn sphere_follows_freeglut() {
    let (r, slices, stacks) = (2.0, 12, 7);
    let m = glut::sphere_mesh(r, slices, stacks, false).expect("sphere");
    assert_eq!(m.vertices.len(), 12 * 6 + 2);
    assert_eq!(m.parts.len(), 7);
    assert!(m
        .parts
        .iter()
        .all(|(mode, p)| *mode == gl::TRIANGLE_STRIP && p.len() == 26));
    assert!(close(m.vertices[0], [0.0, 0.0, 2.0], 0.0));
    assert!(close(m.vertices[73], [0.0, 0.0, -2.0], 0.0));
    // Ring i (1..stacks), slice j: polar angle πi/stacks, azimuth −2πj/slices (clockwise).
    for (i, j) in [(1, 0), (3, 5), (6, 11)] {
        let (th, ph) = (PI * i as f64 / 7.0, -2.0 * PI * j as f64 / 12.0);
        let n = [ph.cos() * th.sin(), ph.sin() * th.sin(), th.cos()];
        let k = 1 + (i - 1) * 12 + j;
        assert!(close(m.normals[k], n, 1e-6), "normal {k}");
        assert!(close(m.vertices[k], n.map(|x| x * r), 2e-6), "vertex {k}");
    }
    unit_normals(&m);
    assert!(outward_ccw(&m) > 100);
    let w = glut::sphere_mesh(r, slices, stacks, true).expect("wire");
    assert_eq!(w.parts.len(), 12 + 6);
    assert_eq!(w.emitted_vertices(), 12 * 8 + 6 * 12);
    assert!(glut::sphere_mesh(1.0, 0, 5, false).is_none());
    assert!(glut::sphere_mesh(1.0, 5, 1, false).is_none());
    assert!(glut::sphere_mesh(1.0, i32::MAX, i32::MAX, false).is_none());
}

#[test]
fn cube_follows_freeglut() {
    let m = glut::cube_mesh(3.0, false);
    assert_eq!(m.vertices.len(), 24);
    assert_eq!(m.parts, vec![(gl::TRIANGLES, m.parts[0].1.clone())]);
    assert_eq!(m.emitted_vertices(), 36);
    // Face 0 is +z through corners (+,+), (−,+), (−,−), (+,−) of half-size 1.5.
    assert!(close(m.vertices[0], [1.5, 1.5, 1.5], 0.0));
    assert!(close(m.vertices[2], [-1.5, -1.5, 1.5], 0.0));
    assert!(close(m.normals[0], [0.0, 0.0, 1.0], 0.0));
    // Every vertex lies on the plane of its face's normal, at distance 1.5.
    for (v, n) in m.vertices.iter().zip(&m.normals) {
        assert_eq!(dot(v.map(f64::from), n.map(f64::from)), 1.5);
    }
    unit_normals(&m);
    assert_eq!(outward_ccw(&m), 12);
    let w = glut::cube_mesh(1.0, true);
    assert_eq!(w.parts.len(), 6);
    assert!(w
        .parts
        .iter()
        .all(|(mode, p)| *mode == gl::LINE_LOOP && p.len() == 4));
}

#[test]
fn cone_follows_freeglut() {
    let (b, h, slices, stacks) = (1.0, 2.0, 10, 4);
    let m = glut::cone_mesh(b, h, slices, stacks, false).expect("cone");
    assert_eq!(m.vertices.len(), 10 * 6 + 1);
    assert_eq!(m.parts.len(), 5);
    // The side normal is (h cos φ, h sin φ, b) / √(h² + b²) on every side ring.
    let hyp = (h * h + b * b).sqrt();
    for (ring, j) in [(0usize, 0usize), (2, 3), (4, 9)] {
        let ph = -2.0 * PI * j as f64 / 10.0;
        let k = 1 + 10 + ring * 10 + j;
        let r = b * (1.0 - ring as f64 / 4.0);
        let z = h * ring as f64 / 4.0;
        assert!(
            close(m.vertices[k], [r * ph.cos(), r * ph.sin(), z], 1e-6),
            "vertex {k}"
        );
        let n = [h * ph.cos() / hyp, h * ph.sin() / hyp, b / hyp];
        assert!(close(m.normals[k], n, 1e-6), "normal {k}");
    }
    // The base ring faces down.
    assert!(m.normals[..11].iter().all(|n| *n == [0.0, 0.0, -1.0]));
    unit_normals(&m);
    assert!(outward_ccw(&m) > 50);
    let w = glut::cone_mesh(b, h, slices, stacks, true).expect("wire");
    assert_eq!(w.parts[0].0, gl::LINES);
    assert_eq!(w.parts.len(), 1 + 4);
}

#[test]
fn torus_follows_freeglut() {
    let (ir, or, sides, rings) = (0.5, 2.0, 8, 12);
    let m = glut::torus_mesh(ir, or, sides, rings, false).expect("torus");
    assert_eq!(m.vertices.len(), 96);
    assert_eq!(m.parts.len(), 8);
    assert!(m.parts.iter().all(|(_, p)| p.len() == 26));
    for (j, i) in [(0usize, 0usize), (5, 3), (11, 7)] {
        let psi = 2.0 * PI * j as f64 / 12.0;
        let phi = -2.0 * PI * i as f64 / 8.0;
        let k = j * 8 + i;
        let n = [psi.cos() * phi.cos(), psi.sin() * phi.cos(), phi.sin()];
        assert!(close(m.normals[k], n, 1e-6), "normal {k}");
        // The vertex is the tube centre plus inner radius along the normal.
        let v = [
            or * psi.cos() + ir * n[0],
            or * psi.sin() + ir * n[1],
            ir * n[2],
        ];
        assert!(close(m.vertices[k], v, 1e-6), "vertex {k}");
    }
    unit_normals(&m);
    assert!(outward_ccw(&m) > 150);
    let w = glut::torus_mesh(ir, or, sides, rings, true).expect("wire");
    assert_eq!(w.parts.len(), 12 + 8);
}

#[test]
fn teapot_follows_freeglut() {
    let m = glut::teapot_mesh(2.0, false);
    // 6 patches in 4 rotations and 4 in 2 mirror images, 8 × 8 points each.
    assert_eq!(m.vertices.len(), 32 * 64);
    assert_eq!(m.emitted_vertices(), 32 * 7 * 7 * 6);
    assert_eq!(m.tex_coords.as_ref().map(Vec::len), Some(32 * 64));
    // Patch 3 (the lid's top) starts after 3 × 4 patches: its first row is the knob's top,
    // control point (0, 0, 3.15) → (0, (3.15 − 1.575)·size/2, 0), normal fixed to +y.
    assert!(close(m.vertices[12 * 64], [0.0, 1.575, 0.0], 1e-6));
    assert_eq!(m.normals[12 * 64], [0.0, 1.0, 0.0]);
    // The rim's first point, control point (1.4, 0, 2.4) → (1.4, 0.825, 0) at size 2.
    assert!(close(m.vertices[0], [1.4, 0.825, 0.0], 1e-6));
    // Its 90° copy about y: (x, y, z) → (z, y, −x).
    assert!(close(m.vertices[64], [0.0, 0.825, -1.4], 1e-6));
    assert!(m.normals.iter().all(|n| n.iter().all(|c| c.is_finite())));
    unit_normals(&m);
    // freeglut's teapot, like GLUT's, winds clockwise seen from outside: every triangle, the
    // mirrored handle and spout included (their rows are reversed to keep it so).
    let (ccw, cw) = windings(&m);
    assert_eq!(ccw, 0);
    assert!(cw > 2500, "{cw}");
    let w = glut::teapot_mesh(1.0, true);
    assert_eq!(w.vertices.len(), 32 * 100);
    assert_eq!(w.parts.len(), 32 * 20);
    assert!(w.tex_coords.is_none());
}

#[test]
fn shapes_draw_through_the_context() {
    let mut ctx = Context::new(8, 8).expect("context");
    ctx.start_recording();
    glut::solid_cube(&mut ctx, 1.0);
    let calls = ctx.stop_recording();
    assert_eq!(calls.len(), 2 + 36 * 2);
    assert_eq!(calls[0], Call::Begin(gl::TRIANGLES));
    assert_eq!(calls[1], Call::Normal3fv([0.0, 0.0, 1.0]));
    assert_eq!(calls[2], Call::Vertex3fv([0.5, 0.5, 0.5]));
    assert_eq!(calls.last(), Some(&Call::End));
    // Compiled into a list like any drawing.
    ctx.new_list(1, gl::COMPILE);
    glut::wire_torus(&mut ctx, 0.2, 0.5, 4, 6);
    ctx.end_list();
    assert_eq!(
        ctx.list_calls(1).map(<[Call]>::len),
        Some(10 * 2 + (24 + 24) * 2)
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}
