//! The Utah teapot as freeglut 3.x tessellates it (fg_teapot.c, fg_teapot_data.h): ten bicubic
//! Bezier patches (rim, body ×2, lid ×2, bottom rotated into the four quadrants; handle ×2 and
//! spout ×2 mirrored across the x-y plane), each evaluated on an n × n grid (8 solid, 10 wire)
//! with normals from the cross product of the two partial derivatives.
//!
//! Design decision: the arithmetic is freeglut's, in f32 and in the same order (control points
//! pre-rotated 270° about x, scaled by size/2 and lowered by 1.575), so the vertices and normals
//! are the ones a GLUT program draws, bit for bit where the compiler keeps f32.

use super::Mesh;
use crate::gl;

/// Grid points per patch side.
const SOLID_SUBDIV: usize = 8;
const WIRE_SUBDIV: usize = 10;
/// The teapot's z offset (freeglut: 1.575, which centres it on the z axis).
const Z_OFFSET: f32 = 1.575;

/// Control-point indices of the ten input patches (fg_teapot_data.h).
const PATCHES: [[usize; 16]; 10] = [
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15],
    [
        12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27,
    ],
    [
        24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    ],
    [
        40, 41, 42, 40, 43, 44, 45, 46, 47, 47, 47, 47, 48, 49, 50, 51,
    ],
    [
        48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63,
    ],
    [
        64, 64, 64, 64, 65, 66, 67, 68, 69, 70, 71, 72, 39, 38, 37, 36,
    ],
    [
        73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88,
    ],
    [
        85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100,
    ],
    [
        101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116,
    ],
    [
        113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128,
    ],
];

/// The 129 control points (Newell's teapot, with freeglut's added bottom).
#[rustfmt::skip]
const CP: [[f32; 3]; 129] = [
    [1.4, 0.0, 2.4], [1.4, -0.784, 2.4], [0.784, -1.4, 2.4], [0.0, -1.4, 2.4],
    [1.3375, 0.0, 2.53125], [1.3375, -0.749, 2.53125], [0.749, -1.3375, 2.53125], [0.0, -1.3375, 2.53125],
    [1.4375, 0.0, 2.53125], [1.4375, -0.805, 2.53125], [0.805, -1.4375, 2.53125], [0.0, -1.4375, 2.53125],
    [1.5, 0.0, 2.4], [1.5, -0.84, 2.4], [0.84, -1.5, 2.4], [0.0, -1.5, 2.4],
    [1.75, 0.0, 1.875], [1.75, -0.98, 1.875], [0.98, -1.75, 1.875], [0.0, -1.75, 1.875],
    [2.0, 0.0, 1.35], [2.0, -1.12, 1.35], [1.12, -2.0, 1.35], [0.0, -2.0, 1.35],
    [2.0, 0.0, 0.9], [2.0, -1.12, 0.9], [1.12, -2.0, 0.9], [0.0, -2.0, 0.9],
    [2.0, 0.0, 0.45], [2.0, -1.12, 0.45], [1.12, -2.0, 0.45], [0.0, -2.0, 0.45],
    [1.5, 0.0, 0.225], [1.5, -0.84, 0.225], [0.84, -1.5, 0.225], [0.0, -1.5, 0.225],
    [1.5, 0.0, 0.15], [1.5, -0.84, 0.15], [0.84, -1.5, 0.15], [0.0, -1.5, 0.15],
    [0.0, 0.0, 3.15], [0.0, -0.002, 3.15], [0.002, 0.0, 3.15], [0.8, 0.0, 3.15],
    [0.8, -0.45, 3.15], [0.45, -0.8, 3.15], [0.0, -0.8, 3.15], [0.0, 0.0, 2.85],
    [0.2, 0.0, 2.7], [0.2, -0.112, 2.7], [0.112, -0.2, 2.7], [0.0, -0.2, 2.7],
    [0.4, 0.0, 2.55], [0.4, -0.224, 2.55], [0.224, -0.4, 2.55], [0.0, -0.4, 2.55],
    [1.3, 0.0, 2.55], [1.3, -0.728, 2.55], [0.728, -1.3, 2.55], [0.0, -1.3, 2.55],
    [1.3, 0.0, 2.4], [1.3, -0.728, 2.4], [0.728, -1.3, 2.4], [0.0, -1.3, 2.4],
    [0.0, 0.0, 0.0], [0.0, -1.425, 0.0], [0.798, -1.425, 0.0], [1.425, -0.798, 0.0],
    [1.425, 0.0, 0.0], [0.0, -1.5, 0.075], [0.84, -1.5, 0.075], [1.5, -0.84, 0.075],
    [1.5, 0.0, 0.075], [-1.6, 0.0, 2.025], [-1.6, -0.3, 2.025], [-1.5, -0.3, 2.25],
    [-1.5, 0.0, 2.25], [-2.3, 0.0, 2.025], [-2.3, -0.3, 2.025], [-2.5, -0.3, 2.25],
    [-2.5, 0.0, 2.25], [-2.7, 0.0, 2.025], [-2.7, -0.3, 2.025], [-3.0, -0.3, 2.25],
    [-3.0, 0.0, 2.25], [-2.7, 0.0, 1.8], [-2.7, -0.3, 1.8], [-3.0, -0.3, 1.8],
    [-3.0, 0.0, 1.8], [-2.7, 0.0, 1.575], [-2.7, -0.3, 1.575], [-3.0, -0.3, 1.35],
    [-3.0, 0.0, 1.35], [-2.5, 0.0, 1.125], [-2.5, -0.3, 1.125], [-2.65, -0.3, 0.9375],
    [-2.65, 0.0, 0.9375], [-2.0, 0.0, 0.9], [-2.0, -0.3, 0.9], [-1.9, -0.3, 0.6],
    [-1.9, 0.0, 0.6], [1.7, 0.0, 1.425], [1.7, -0.66, 1.425], [1.7, -0.66, 0.6],
    [1.7, 0.0, 0.6], [2.6, 0.0, 1.425], [2.6, -0.66, 1.425], [3.1, -0.66, 0.825],
    [3.1, 0.0, 0.825], [2.3, 0.0, 2.1], [2.3, -0.25, 2.1], [2.4, -0.25, 2.025],
    [2.4, 0.0, 2.025], [2.7, 0.0, 2.4], [2.7, -0.25, 2.4], [3.3, -0.25, 2.4],
    [3.3, 0.0, 2.4], [2.8, 0.0, 2.475], [2.8, -0.25, 2.475], [3.525, -0.25, 2.49375],
    [3.525, 0.0, 2.49375], [2.9, 0.0, 2.475], [2.9, -0.15, 2.475], [3.45, -0.15, 2.5125],
    [3.45, 0.0, 2.5125], [2.8, 0.0, 2.4], [2.8, -0.15, 2.4], [3.2, -0.15, 2.4],
    [3.2, 0.0, 2.4],
];

/// The four cubic Bernstein polynomials and their derivatives at x (freeglut's `bernstein3`).
fn bernstein(x: f32) -> ([f32; 4], [f32; 4]) {
    let inv = 1.0 - x;
    let (ii, xx) = (inv * inv, x * x);
    (
        [inv * ii, 3.0 * x * ii, 3.0 * xx * inv, x * xx],
        [
            -3.0 * ii,
            3.0 * ii - 6.0 * x * inv,
            6.0 * x * inv - 3.0 * xx,
            3.0 * xx,
        ],
    )
}

/// One patch's n × n grid of points and unit normals, row u major.
fn eval_patch(cp: &[[[f32; 3]; 4]; 4], bern: &[([f32; 4], [f32; 4])]) -> Vec<([f32; 3], [f32; 3])> {
    let mut out = Vec::with_capacity(bern.len() * bern.len());
    for (b0u, b1u) in bern {
        for (b0v, b1v) in bern {
            let (mut p, mut t1, mut t2) = ([0.0f32; 3], [0.0f32; 3], [0.0f32; 3]);
            for i in 0..4 {
                let (mut v0, mut v1) = ([0.0f32; 3], [0.0f32; 3]);
                for j in 0..4 {
                    for k in 0..3 {
                        v0[k] += b0v[j] * cp[i][j][k];
                        v1[k] += b1v[j] * cp[i][j][k];
                    }
                }
                for k in 0..3 {
                    p[k] += b0u[i] * v0[k];
                    t1[k] += b0u[i] * v1[k];
                    t2[k] += b1u[i] * v0[k];
                }
            }
            let n = [
                t1[1] * t2[2] - t1[2] * t2[1],
                t1[2] * t2[0] - t1[0] * t2[2],
                t1[0] * t2[1] - t1[1] * t2[0],
            ];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            out.push((p, [n[0] / len, n[1] / len, n[2] / len]));
        }
    }
    out
}

/// `glutSolidTeapot`/`glutWireTeapot`'s mesh: 32 patches of 8 × 8 (solid) or 10 × 10 (wire)
/// vertices. Solid: one TRIANGLES part, two triangles per grid square, with freeglut's texture
/// coordinates (u, v) = (row, column)/(n − 1); wire: a line strip along each grid line.
pub fn teapot_mesh(size: f64, wire: bool) -> Mesh {
    let n = if wire { WIRE_SUBDIV } else { SOLID_SUBDIV };
    let scale = size as f32;
    let bern: Vec<_> = (0..n)
        .map(|s| bernstein(s as f32 / (n as f32 - 1.0)))
        .collect();
    let mut vertices = Vec::with_capacity(32 * n * n);
    let mut normals = Vec::with_capacity(32 * n * n);
    for (p, patch) in PATCHES.iter().enumerate() {
        // Rotated 270° about x, scaled by size/2, lowered by Z_OFFSET (fghTeaset).
        let mut cp = [[[0.0f32; 3]; 4]; 4];
        for (i, &c) in patch.iter().enumerate() {
            let v = CP[c];
            cp[i / 4][i % 4] = [
                v[0] * scale / 2.0,
                (v[2] - Z_OFFSET) * scale / 2.0,
                -v[1] * scale / 2.0,
            ];
        }
        let mut grid = eval_patch(&cp, &bern);
        // The lid's top (patch 3) and the bottom's centre (patch 5) are degenerate rows.
        let fix = match p {
            3 => Some(1.0),
            5 => Some(-1.0),
            _ => None,
        };
        if let Some(y) = fix {
            for (_, nrm) in grid.iter_mut().take(n) {
                *nrm = [0.0, y, 0.0];
            }
        }
        let copies: Vec<Vec<([f32; 3], [f32; 3])>> = if p < 6 {
            // The patch and its 90°, 180°, 270° rotations about y.
            let rot =
                |f: fn([f32; 3]) -> [f32; 3]| grid.iter().map(|&(v, m)| (f(v), f(m))).collect();
            vec![
                grid.clone(),
                rot(|v| [v[2], v[1], -v[0]]),
                rot(|v| [-v[0], v[1], -v[2]]),
                rot(|v| [-v[2], v[1], v[0]]),
            ]
        } else {
            // The patch and its mirror in z, rows reversed to keep the winding.
            let flip = grid
                .chunks(n)
                .rev()
                .flatten()
                .map(|&(v, m)| ([v[0], v[1], -v[2]], [m[0], m[1], -m[2]]))
                .collect();
            vec![grid, flip]
        };
        for c in copies {
            for (v, m) in c {
                vertices.push(v);
                normals.push(m);
            }
        }
    }
    let patches = vertices.len() / (n * n);
    let n32 = n as u32;
    let mut parts = Vec::new();
    let tex_coords = if wire {
        for p in 0..patches as u32 {
            let idx = n32 * n32 * p;
            for c in 0..n32 {
                parts.push((
                    gl::LINE_STRIP,
                    (0..n32).map(|r| idx + r * n32 + c).collect(),
                ));
            }
        }
        for p in 0..patches as u32 {
            let idx = n32 * n32 * p;
            for r in 0..n32 {
                parts.push((
                    gl::LINE_STRIP,
                    (0..n32).map(|c| idx + r * n32 + c).collect(),
                ));
            }
        }
        None
    } else {
        let mut tris = Vec::with_capacity(patches * (n - 1) * (n - 1) * 6);
        for p in 0..patches as u32 {
            let idx = n32 * n32 * p;
            for r in 0..n32 - 1 {
                for c in 0..n32 - 1 {
                    let row1 = idx + r * n32 + c;
                    let row2 = row1 + n32;
                    tris.extend([row1, row2, row2 + 1, row1, row2 + 1, row1 + 1]);
                }
            }
        }
        parts.push((gl::TRIANGLES, tris));
        let d = n as f32 - 1.0;
        let one: Vec<[f32; 2]> = (0..n)
            .flat_map(|r| (0..n).map(move |c| [r as f32 / d, c as f32 / d]))
            .collect();
        Some(one.iter().copied().cycle().take(vertices.len()).collect())
    };
    Mesh {
        vertices,
        normals,
        tex_coords,
        parts,
    }
}
