//! `primitives` and `primitives-flat`: the ten Begin/End modes of GL 2.1 §2.6.1 (POINTS, LINES,
//! LINE_STRIP, LINE_LOOP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN, QUADS, QUAD_STRIP, POLYGON), one
//! panel each, every vertex its own colour, under SMOOTH and under FLAT shading.
//!
//! Under FLAT every primitive takes the colour of its provoking vertex (§2.14.7, table 2.12): the
//! last vertex of each line, triangle and quad (for a strip or fan, the vertex that completes
//! it), the first vertex of a POLYGON. Points are 7 pixels wide and lines 3, so both show.
//!
//! Design decision: the vertex lists are plain data (`MODES`), so a test can count what each
//! mode must make from the spec's rules without running the pipeline.

use std::f32::consts::TAU;

use crate::gl::*;
use crate::Context;

use super::shapes::panels;
use super::{Scene, LECTURE};

/// The per-vertex colours, used in order (vertex k gets `PALETTE[k % 8]`).
pub const PALETTE: [[f32; 3]; 8] = [
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 0.5, 0.0],
    [1.0, 1.0, 1.0],
];

/// `n` points on a circle of radius `r` about the panel centre, starting at angle `a0` (radians),
/// counter-clockwise.
fn ring(n: usize, r: f32, a0: f32) -> Vec<[f32; 2]> {
    (0..n)
        .map(|k| {
            let a = a0 + TAU * k as f32 / n as f32;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// A zigzag of `n` vertices from left to right, alternating between y = -h and y = h.
fn zigzag(n: usize, h: f32) -> Vec<[f32; 2]> {
    (0..n)
        .map(|k| {
            let x = -0.8 + 1.6 * k as f32 / (n.max(2) - 1) as f32;
            [x, if k % 2 == 0 { -h } else { h }]
        })
        .collect()
}

/// Each mode with its vertices (x, y in [-1, 1], the panel's normalised device coordinates).
pub fn modes() -> [(u32, Vec<[f32; 2]>); 10] {
    [
        (POINTS, ring(8, 0.6, 0.1)),
        (
            LINES,
            vec![
                [-0.8, -0.6],
                [0.7, -0.7],
                [-0.7, 0.05],
                [0.8, -0.1],
                [-0.6, 0.75],
                [0.75, 0.55],
            ],
        ),
        (LINE_STRIP, zigzag(6, 0.55)),
        (LINE_LOOP, ring(6, 0.7, 0.2)),
        (
            TRIANGLES,
            vec![
                [-0.85, -0.7],
                [0.05, -0.75],
                [-0.45, 0.75],
                [0.15, 0.7],
                [0.35, -0.6],
                [0.85, 0.65],
            ],
        ),
        (TRIANGLE_STRIP, zigzag(7, 0.6)),
        (TRIANGLE_FAN, {
            let mut v = vec![[-0.05, -0.1]];
            v.extend((0..6).map(|k| {
                let a = 0.3 + 0.85 * k as f32;
                [0.8 * a.cos(), 0.75 * a.sin()]
            }));
            v
        }),
        (
            QUADS,
            vec![
                [-0.85, -0.7],
                [-0.1, -0.6],
                [-0.15, 0.65],
                [-0.8, 0.75],
                [0.1, -0.3],
                [0.85, -0.75],
                [0.8, 0.7],
                [0.2, 0.35],
            ],
        ),
        (QUAD_STRIP, {
            // Pairs bottom/top from left to right: quad k is 2k, 2k+1, 2k+3, 2k+2.
            (0..8)
                .map(|k| {
                    let x = -0.8 + 1.6 * (k / 2) as f32 / 3.0 + 0.05 * (k % 2) as f32;
                    let y = if k % 2 == 0 { -0.6 } else { 0.6 } + 0.1 * ((k / 2) % 2) as f32;
                    [x, y]
                })
                .collect()
        }),
        (POLYGON, ring(7, 0.75, 0.35)),
    ]
}

/// Draws the ten modes in a 4x3 grid of panels under `shade` (SMOOTH or FLAT).
pub fn primitives(gl: &mut Context, shade: u32) {
    gl.clear_color(0.12, 0.12, 0.12, 1.0);
    gl.clear(COLOR_BUFFER_BIT);
    gl.shade_model(shade);
    gl.point_size(7.0);
    gl.line_width(3.0);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    for ((x, y, w, h), (mode, verts)) in panels(gl, 4, 3).into_iter().zip(modes()) {
        gl.viewport(x, y, w, h);
        gl.begin(mode);
        for (k, v) in verts.iter().enumerate() {
            gl.color3fv(&PALETTE[k % PALETTE.len()]);
            gl.vertex2f(v[0], v[1]);
        }
        gl.end();
    }
    gl.point_size(1.0);
    gl.line_width(1.0);
    gl.flush();
}

/// The two scenes, as registry entries.
pub(super) const SCENES: [Scene; 2] = [
    Scene {
        name: "primitives",
        summary:
            "Primitives: the ten Begin/End modes — a colour per vertex, SMOOTH; 7-pixel points, 3-pixel lines",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| primitives(gl, SMOOTH),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "primitives-flat",
        summary:
            "Primitives: flat shading and the provoking vertex — all ten Begin/End modes, a colour per vertex, FLAT: the provoking vertex's colour",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| primitives(gl, FLAT),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Every mode's vertex count is one the spec draws completely (no vertices left over):
    /// LINES even, TRIANGLES a multiple of 3, QUADS of 4, QUAD_STRIP even.
    #[test]
    fn vertex_counts_are_complete_primitives() {
        for (mode, v) in modes() {
            let n = v.len();
            let ok = match mode {
                LINES | QUAD_STRIP => n % 2 == 0 && n >= 2,
                TRIANGLES => n % 3 == 0,
                QUADS => n % 4 == 0,
                _ => n >= 3,
            };
            assert!(ok, "{mode:#x}: {n}");
            assert!(v.iter().flatten().all(|c| c.abs() < 1.0));
        }
    }

    fn pixel_at(img: &image::RgbaImage, panel: u32, v: [f32; 2]) -> [u8; 4] {
        // 800x800 in 4x3 panels of 200x266 (rows from the top); NDC v maps to the panel.
        let (col, row) = (panel % 4, panel / 4);
        let x = col * 200 + ((v[0] + 1.0) * 100.0) as u32;
        let y_gl = (2 - row) * 266 + 2 + ((v[1] + 1.0) * 133.0) as u32;
        img.get_pixel(x, 799 - y_gl).0
    }

    /// FLAT by hand: the first TRIANGLES triangle (vertices 0, 1, 2) has vertex 2's colour, blue;
    /// the POLYGON takes its first vertex's, red; the QUADS' first quad vertex 3's, yellow.
    /// SMOOTH at a triangle's centroid mixes its three corners (red, green, blue → ~1/3 each).
    #[test]
    fn flat_takes_the_provoking_vertex() {
        let draw = |shade: u32| match Context::new(800, 800) {
            Ok(mut gl) => {
                primitives(&mut gl, shade);
                gl.to_image()
            }
            Err(e) => panic!("{e}"),
        };
        let flat = draw(FLAT);
        let m = modes();
        let centroid = |v: &[[f32; 2]], idx: &[usize]| {
            let k = idx.len() as f32;
            let s = idx
                .iter()
                .fold([0.0, 0.0], |a, &i| [a[0] + v[i][0], a[1] + v[i][1]]);
            [s[0] / k, s[1] / k]
        };
        let tri = centroid(&m[4].1, &[0, 1, 2]);
        assert_eq!(pixel_at(&flat, 4, tri), [0, 0, 255, 255]);
        let quad = centroid(&m[7].1, &[0, 1, 2, 3]);
        assert_eq!(pixel_at(&flat, 7, quad), [255, 255, 0, 255]);
        let poly = centroid(&m[9].1, &[0, 1, 2, 3, 4, 5, 6]);
        assert_eq!(pixel_at(&flat, 9, poly), [255, 0, 0, 255]);
        let smooth = draw(SMOOTH);
        let p = pixel_at(&smooth, 4, tri);
        assert!(p[..3].iter().all(|&c| (70..100).contains(&c)), "{p:?}");
    }

    /// A SMOOTH quad is split along its 0–2 diagonal, as llvmpipe does (a FLAT one along 1–3,
    /// which only coverage of a non-convex quad could show). The window-filling quad with only
    /// corner 2 (top right) white puts the centre pixel (window (32.5, 32.5) of 64, NDC
    /// x = y = 1/64) on the 0–2 diagonal, at t = (1 + 1/64)/2 of the way from 0 to 2: colour
    /// 0.508 · 255 ≈ 130. Split along 1–3 it would be in triangle (1,2,3) with corner 2's weight
    /// (x + y)/2 = 1/64: about 4.
    #[test]
    fn smooth_quad_uses_the_0_2_diagonal() {
        let mut gl = match Context::new(64, 64) {
            Ok(gl) => gl,
            Err(e) => panic!("{e}"),
        };
        gl.begin(QUADS);
        for (i, v) in [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]
            .iter()
            .enumerate()
        {
            let c = if i == 2 { 1.0 } else { 0.0 };
            gl.color3f(c, c, c);
            gl.vertex2f(v[0], v[1]);
        }
        gl.end();
        let img = gl.to_image();
        let p = img.get_pixel(32, 63 - 32).0;
        assert!((125..=135).contains(&p[0]), "{p:?}");
    }
}
