//! The lecture scenes' shared geometry, drawn with Begin/End as the seeds draw it: the sphere by
//! recursive subdivision of a tetrahedron (seed 003 §6.6), the parametric sphere (seed 004), a
//! tessellated floor, the seeds' materials (seed 003 §6.8) and a panel helper that splits the
//! window into viewports.
//!
//! Design decision: geometry is computed by pure functions (`subdivide`, `sphere_point`) that the
//! tests check against the formulas, and drawn by thin functions that only issue GL calls, so a
//! scene's recording is exactly what the lecture code would send. Every size a caller passes is
//! clamped (`MAX_DEPTH`, `MAX_SEGMENTS`), so no input makes an unbounded allocation or loop.

use crate::gl::*;
use crate::Context;

/// Deepest subdivision drawn: 4 · 4^8 = 262,144 triangles.
pub const MAX_DEPTH: u32 = 8;

/// Most segments along one parameter of a tessellated surface.
pub const MAX_SEGMENTS: usize = 1024;

/// A triangle of the subdivided sphere; its vertices are unit vectors, so each is also its normal.
pub type Triangle = [[f32; 3]; 3];

/// How a triangle of the tetrahedron is split at each level (seed 003, slides 46–48).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Split {
    /// Slide 47: the edge midpoints AB, BC, AC pushed out to the sphere, four triangles per
    /// triangle (Angel's `divide_triangle`). Converges to the sphere.
    Midpoint,
    /// Slides 46 and 48: the face's centre D pushed out to the sphere, three triangles joining
    /// the corners to D. The tetrahedron's edges are never split, so this one keeps them.
    Centroid,
}

/// The tetrahedron's corners on the unit sphere (Angel's `v[4]`: (0,0,1) and three points at
/// z = -1/3, the first in the y-z plane).
pub fn tetrahedron() -> [[f32; 3]; 4] {
    let s = (2.0f32).sqrt();
    let t = (6.0f32).sqrt();
    [
        [0.0, 0.0, 1.0],
        [0.0, 2.0 * s / 3.0, -1.0 / 3.0],
        [-t / 3.0, -s / 3.0, -1.0 / 3.0],
        [t / 3.0, -s / 3.0, -1.0 / 3.0],
    ]
}

fn unit(v: [f32; 3]) -> [f32; 3] {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if n == 0.0 {
        v
    } else {
        [v[0] / n, v[1] / n, v[2] / n]
    }
}

fn mid(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    unit([a[0] + b[0], a[1] + b[1], a[2] + b[2]])
}

fn divide(t: Triangle, depth: u32, split: Split, out: &mut Vec<Triangle>) {
    let [a, b, c] = t;
    if depth == 0 {
        out.push(t);
        return;
    }
    match split {
        Split::Midpoint => {
            let (ab, ac, bc) = (mid(a, b), mid(a, c), mid(b, c));
            // Each child keeps its parent's winding.
            divide([a, ab, ac], depth - 1, split, out);
            divide([ab, b, bc], depth - 1, split, out);
            divide([ac, bc, c], depth - 1, split, out);
            divide([ab, bc, ac], depth - 1, split, out);
        }
        Split::Centroid => {
            let d = unit([a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]]);
            divide([a, b, d], depth - 1, split, out);
            divide([b, c, d], depth - 1, split, out);
            divide([c, a, d], depth - 1, split, out);
        }
    }
}

/// The seed's recursive sphere: the tetrahedron's four faces, each split `depth` times
/// (clamped to [`MAX_DEPTH`]), counter-clockwise seen from outside.
pub fn subdivide(depth: u32, split: Split) -> Vec<Triangle> {
    let depth = depth.min(MAX_DEPTH);
    let per_face = match split {
        Split::Midpoint => 4usize.pow(depth),
        Split::Centroid => 3usize.pow(depth),
    };
    let v = tetrahedron();
    let mut out = Vec::with_capacity(4 * per_face);
    // Angel's tetrahedron(): faces (0,1,2), (3,2,1), (0,3,1), (0,2,3), each counter-clockwise
    // seen from outside.
    for [i, j, k] in [[0, 1, 2], [3, 2, 1], [0, 3, 1], [0, 2, 3]] {
        divide([v[i], v[j], v[k]], depth, split, &mut out);
    }
    out
}

/// Draws `triangles` as one `TRIANGLES` primitive, each vertex with itself as normal (the unit
/// sphere's normal is its position), scaled by `radius` about the current origin.
pub fn draw_sphere_triangles(gl: &mut Context, triangles: &[Triangle], radius: f32) {
    gl.begin(TRIANGLES);
    for t in triangles {
        for p in t {
            gl.normal3fv(p);
            gl.vertex3f(radius * p[0], radius * p[1], radius * p[2]);
        }
    }
    gl.end();
}

/// The seed 004 parametric sphere at azimuth `theta` and polar angle `phi`:
/// p(r, θ, φ) = (r cos θ sin φ, r sin θ sin φ, r cos φ).
pub fn sphere_point(r: f32, theta: f32, phi: f32) -> [f32; 3] {
    [
        r * theta.cos() * phi.sin(),
        r * theta.sin() * phi.sin(),
        r * phi.cos(),
    ]
}

/// Draws the parametric sphere's band between polar angles `phi0` < `phi1` (radians) with
/// `slices` steps of θ over [0, 2π] and `stacks` steps of φ: one `TRIANGLE_STRIP` per stack,
/// normal p/r at each vertex, counter-clockwise seen from outside. The z axis is the pole.
pub fn draw_sphere_band(
    gl: &mut Context,
    r: f32,
    slices: usize,
    stacks: usize,
    phi0: f32,
    phi1: f32,
) {
    let slices = slices.clamp(3, MAX_SEGMENTS);
    let stacks = stacks.clamp(1, MAX_SEGMENTS);
    let tau = std::f32::consts::TAU;
    for i in 0..stacks {
        let pa = phi0 + (phi1 - phi0) * i as f32 / stacks as f32;
        let pb = phi0 + (phi1 - phi0) * (i + 1) as f32 / stacks as f32;
        gl.begin(TRIANGLE_STRIP);
        for j in 0..=slices {
            // The last column repeats the first exactly, so the seam has no crack.
            let theta = if j == slices {
                0.0
            } else {
                tau * j as f32 / slices as f32
            };
            for phi in [pa, pb] {
                let n = sphere_point(1.0, theta, phi);
                gl.normal3fv(&n);
                gl.vertex3f(r * n[0], r * n[1], r * n[2]);
            }
        }
        gl.end();
    }
}

/// The whole parametric sphere (φ over [0, π]).
pub fn draw_sphere(gl: &mut Context, r: f32, slices: usize, stacks: usize) {
    draw_sphere_band(gl, r, slices, stacks, 0.0, std::f32::consts::PI);
}

/// A floor in the y = 0 plane over [-half, half]², `cells` x `cells` quads as one
/// `TRIANGLE_STRIP` per row, normal +y, counter-clockwise seen from above. Fine cells let
/// Gouraud shading show a spotlight's cone or a local viewer's highlight.
pub fn draw_floor(gl: &mut Context, half: f32, cells: usize) {
    let cells = cells.clamp(1, MAX_SEGMENTS);
    let at = |k: usize| -half + 2.0 * half * k as f32 / cells as f32;
    gl.normal3f(0.0, 1.0, 0.0);
    for row in 0..cells {
        gl.begin(TRIANGLE_STRIP);
        for col in 0..=cells {
            gl.vertex3f(at(col), 0.0, at(row));
            gl.vertex3f(at(col), 0.0, at(row + 1));
        }
        gl.end();
    }
}

/// The seed's `materialStruct` (seed 003 §6.8, slide 60).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// GL_AMBIENT reflectance.
    pub ambient: [f32; 4],
    /// GL_DIFFUSE reflectance.
    pub diffuse: [f32; 4],
    /// GL_SPECULAR reflectance.
    pub specular: [f32; 4],
    /// GL_SHININESS exponent.
    pub shininess: f32,
}

/// `brassMaterial` (slide 61).
pub const BRASS: Material = Material {
    ambient: [0.33, 0.22, 0.03, 1.0],
    diffuse: [0.78, 0.57, 0.11, 1.0],
    specular: [0.99, 0.94, 0.81, 1.0],
    shininess: 27.89,
};

/// `goldMaterial` (slide 61).
pub const GOLD: Material = Material {
    ambient: [0.25, 0.20, 0.07, 1.0],
    diffuse: [0.75, 0.61, 0.23, 1.0],
    specular: [0.63, 0.56, 0.37, 1.0],
    shininess: 51.2,
};

/// The slide 57 example material "i": grey ambient, yellow diffuse, white specular, shininess 100.
pub const YELLOW_PLASTIC: Material = Material {
    ambient: [0.2, 0.2, 0.2, 1.0],
    diffuse: [1.0, 0.8, 0.0, 1.0],
    specular: [1.0, 1.0, 1.0, 1.0],
    shininess: 100.0,
};

/// GL's initial material (slide 56; GL 2.1 table 6.11): no specular highlight at all.
pub const GL_DEFAULT: Material = Material {
    ambient: [0.2, 0.2, 0.2, 1.0],
    diffuse: [0.8, 0.8, 0.8, 1.0],
    specular: [0.0, 0.0, 0.0, 1.0],
    shininess: 0.0,
};

/// The seed's `materials(materialStruct*)`, for any face (the seed uses GL_FRONT).
pub fn materials(gl: &mut Context, face: u32, m: &Material) {
    gl.materialfv(face, AMBIENT, &m.ambient); // glMaterialfv(GL_FRONT, GL_AMBIENT, materials->ambient);
    gl.materialfv(face, DIFFUSE, &m.diffuse); // glMaterialfv(GL_FRONT, GL_DIFFUSE, materials->diffuse);
    gl.materialfv(face, SPECULAR, &m.specular); // glMaterialfv(GL_FRONT, GL_SPECULAR, materials->specular);
    gl.materialf(face, SHININESS, m.shininess); // glMaterialf(GL_FRONT, GL_SHININESS, materials->shininess);
}

/// The window split into `cols` x `rows` equal viewports, row 0 at the top, as
/// `(x, y, width, height)` for `glViewport`, in reading order.
pub fn panels(gl: &Context, cols: u32, rows: u32) -> Vec<(i32, i32, i32, i32)> {
    let (w, h) = gl.size();
    let (cols, rows) = (cols.clamp(1, 16), rows.clamp(1, 16));
    let (pw, ph) = (w / cols, h / rows);
    let mut out = Vec::with_capacity((cols * rows) as usize);
    for r in 0..rows {
        for c in 0..cols {
            let y = h - (r + 1) * ph;
            out.push((
                (c * pw) as i32,
                y as i32,
                pw.max(1) as i32,
                ph.max(1) as i32,
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn len(v: [f32; 3]) -> f32 {
        (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
    }

    fn outward(t: &Triangle) -> f32 {
        // (b - a) × (c - a) · centroid: positive when counter-clockwise seen from outside.
        let [a, b, c] = *t;
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let g = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
        n[0] * g[0] + n[1] * g[1] + n[2] * g[2]
    }

    /// The tetrahedron is regular and inscribed in the unit sphere: its edges are all
    /// sqrt(8/3) long (edge = 4/sqrt(6) · circumradius).
    #[test]
    fn tetrahedron_is_regular_and_on_the_unit_sphere() {
        let v = tetrahedron();
        let edge = (8.0f32 / 3.0).sqrt();
        for i in 0..4 {
            assert!((len(v[i]) - 1.0).abs() < 1e-6);
            for j in i + 1..4 {
                let d = [v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]];
                assert!((len(d) - edge).abs() < 1e-6, "{i}{j}");
            }
        }
    }

    /// Midpoint splits make 4·4^d triangles, centroid splits 4·3^d; every vertex is on the unit
    /// sphere and every triangle faces outwards.
    #[test]
    fn subdivision_counts_radius_and_winding() {
        for (split, base) in [(Split::Midpoint, 4usize), (Split::Centroid, 3)] {
            for depth in 0..5u32 {
                let t = subdivide(depth, split);
                assert_eq!(t.len(), 4 * base.pow(depth), "{split:?} {depth}");
                for tri in &t {
                    assert!(tri.iter().all(|p| (len(*p) - 1.0).abs() < 1e-5));
                    assert!(outward(tri) > 0.0, "{split:?} {depth} {tri:?}");
                }
            }
        }
        // Huge depths are clamped rather than allocating without bound.
        assert_eq!(
            subdivide(1000, Split::Midpoint).len(),
            4 * 4usize.pow(MAX_DEPTH)
        );
    }

    /// At depth 1 the midpoint split's new vertices are the normalised edge midpoints: the
    /// midpoint of (0,0,1) and (0, 2√2/3, -1/3) is (0, √2/3, 1/3), of length √(1/3), so the
    /// vertex is (0, √(2/3), √(1/3)).
    #[test]
    fn midpoint_vertex_by_hand() {
        let t = subdivide(1, Split::Midpoint);
        let want = [0.0, (2.0f32 / 3.0).sqrt(), (1.0f32 / 3.0).sqrt()];
        let found = t.iter().flatten().any(|p| {
            (p[0] - want[0]).abs() < 1e-6
                && (p[1] - want[1]).abs() < 1e-6
                && (p[2] - want[2]).abs() < 1e-6
        });
        assert!(found);
    }

    /// The seed 004 formula: θ = 0, φ = π/2 is (r, 0, 0); θ = π/2, φ = π/2 is (0, r, 0); φ = 0 is
    /// the pole (0, 0, r).
    #[test]
    fn parametric_sphere_points() {
        use std::f32::consts::FRAC_PI_2;
        let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
        assert!(close(sphere_point(2.0, 0.0, FRAC_PI_2), [2.0, 0.0, 0.0]));
        assert!(close(
            sphere_point(2.0, FRAC_PI_2, FRAC_PI_2),
            [0.0, 2.0, 0.0]
        ));
        assert!(close(sphere_point(2.0, 1.0, 0.0), [0.0, 0.0, 2.0]));
    }

    /// A 2x2 split of 800x800: 400x400 panels, the first at the top left (GL's y = 400).
    #[test]
    fn panels_read_top_left_first() {
        let gl = match Context::new(800, 800) {
            Ok(gl) => gl,
            Err(e) => panic!("{e}"),
        };
        assert_eq!(
            panels(&gl, 2, 2),
            vec![
                (0, 400, 400, 400),
                (400, 400, 400, 400),
                (0, 0, 400, 400),
                (400, 0, 400, 400)
            ]
        );
    }
}
