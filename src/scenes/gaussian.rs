//! The lecture's JOGL `Rendering` example (seed 000, "Métodos para Rendering de Superfície"), ported
//! call for call: a lit gaussian bump, one `TRIANGLE_STRIP` of four vertices per grid cell.
//!
//! The JOGL class has `init` (clear colour, depth test, `gluLookAt` on MODELVIEW, `glOrtho` on
//! PROJECTION, then `lighting`), `lighting` (LIGHT0 positional, black ambient, white diffuse and
//! specular) and `display` (material, the grid, one strip per cell). Each function below is one of
//! those methods; the comment on each call is the JOGL line it ports.
//!
//! One deliberate departure: the seed's `calculateNormal` leaves the normals of the grid's last row
//! and column unset (Java would throw a NullPointerException when the smooth variant reads them). We
//! give those points the normal of their one-sided difference instead, which is what the seed's
//! picture shows (the surface is flat there: exp(-4) ≈ 0.02).

use crate::gl::*;
use crate::{glu, Context};

use super::{Scene, LECTURE};

/// Which of the seed's three pictures to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    /// `glShadeModel(GL_FLAT)` with one normal per cell (the cell's first point's).
    Flat,
    /// `glShadeModel(GL_SMOOTH)` with a normal per vertex.
    Smooth,
    /// `ShadeModel(PHONG_WIN)` with a normal per vertex: the seed's GLSL Phong shader, done the
    /// fixed-function way (GL_WIN_phong_shading).
    Phong,
}

/// A point of the grid with its normal (the seed's `Cell`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cell {
    /// Position (x, y, z).
    pub point: [f32; 3],
    /// Unit normal.
    pub normal: [f32; 3],
}

/// `createMatrix(size)`: (size+2)² points of y = e^(-x²)·e^(-z²) over [-2, 2)², row i along z,
/// column j along x. The first and last rows and columns only help compute normals.
pub fn create_matrix(size: usize) -> Vec<Vec<Cell>> {
    let n = size + 2;
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let x = (4.0 * j as f32) / (size as f32 + 2.0) - 2.0;
                    let z = (4.0 * i as f32) / (size as f32 + 2.0) - 2.0;
                    let y = ((-x * x) as f64).exp() * ((-z * z) as f64).exp();
                    Cell {
                        point: [x, y as f32, z],
                        normal: [0.0; 3],
                    }
                })
                .collect()
        })
        .collect()
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The seed's `crossproduct`.
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - b[0] * a[1],
    ]
}

/// The seed's `normalize` (a zero vector stays zero instead of dividing by zero).
fn normalize(p: [f32; 3]) -> [f32; 3] {
    let norm = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    if norm == 0.0 {
        return p;
    }
    [p[0] / norm, p[1] / norm, p[2] / norm]
}

/// `calculateNormal(matrix)`: at point V1 = `m[i][j]`, with V2 = `m[i][j+1]` (next column) and
/// V3 = `m[i+1][j]` (next row), the normal is normalize((V2 - V1) × (V1 - V3)). On the last row and
/// column the neighbours are taken on the other side, keeping the same orientation. The matrix
/// is square, as [`create_matrix`] makes it; a point whose neighbours a ragged matrix lacks keeps
/// its normal.
pub fn calculate_normal(matrix: &mut [Vec<Cell>]) {
    let n = matrix.len();
    let point =
        |m: &[Vec<Cell>], i: usize, j: usize| m.get(i).and_then(|r| r.get(j)).map(|c| c.point);
    for i in 1..n {
        for j in 1..n {
            let (j2, flip_x) = if j + 1 < n {
                (j + 1, false)
            } else {
                (j - 1, true)
            };
            let (i3, flip_z) = if i + 1 < n {
                (i + 1, false)
            } else {
                (i - 1, true)
            };
            let (Some(v1), Some(v2), Some(v3)) = (
                point(matrix, i, j),
                point(matrix, i, j2),
                point(matrix, i3, j),
            ) else {
                continue;
            };
            let mut vec1 = sub(v2, v1);
            let mut vec2 = sub(v1, v3);
            if flip_x {
                vec1 = [-vec1[0], -vec1[1], -vec1[2]];
            }
            if flip_z {
                vec2 = [-vec2[0], -vec2[1], -vec2[2]];
            }
            if let Some(c) = matrix.get_mut(i).and_then(|r| r.get_mut(j)) {
                c.normal = normalize(cross(vec1, vec2));
            }
        }
    }
}

/// `init`: white background, depth test, the camera, the projection, then `lighting`.
pub fn init(gl: &mut Context, shading: Shading) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0); // gl.glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    gl.enable(DEPTH_TEST); // gl.glEnable(GL.GL_DEPTH_TEST);
    gl.matrix_mode(MODELVIEW); // gl.glMatrixMode(GL.GL_MODELVIEW);
    gl.load_identity(); // gl.glLoadIdentity();
    glu::look_at(gl, 1.5, 0.75, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0); // glu.gluLookAt(...);
    gl.matrix_mode(PROJECTION); // gl.glMatrixMode(GL.GL_PROJECTION);
    gl.load_identity(); // gl.glLoadIdentity();
    gl.ortho(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5); // gl.glOrtho(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5);
    lighting(gl, shading); // lighting(drawable);
}

/// `lighting`: LIGHT0 at (1, 1.5, -0.5) (positional, transformed by the lookAt modelview current
/// now), black ambient, white diffuse and specular; lighting on; the shade model.
pub fn lighting(gl: &mut Context, shading: Shading) {
    let position = [1.0f32, 1.5, -0.5, 1.0];
    let white = [1.0f32, 1.0, 1.0, 1.0];
    let black = [0.0f32, 0.0, 0.0, 1.0];
    gl.lightfv(LIGHT0, POSITION, &position); // gl.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, position, 0);
    gl.lightfv(LIGHT0, AMBIENT, &black); // gl.glLightfv(GL.GL_LIGHT0, GL.GL_AMBIENT, black, 0);
    gl.lightfv(LIGHT0, DIFFUSE, &white); // gl.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, white, 0);
    gl.lightfv(LIGHT0, SPECULAR, &white); // gl.glLightfv(GL.GL_LIGHT0, GL.GL_SPECULAR, white, 0);
    gl.enable(LIGHTING); // gl.glEnable(GL.GL_LIGHTING);
    gl.enable(LIGHT0); // gl.glEnable(GL.GL_LIGHT0);
    gl.shade_model(match shading {
        Shading::Flat => FLAT,
        Shading::Smooth => SMOOTH,
        Shading::Phong => PHONG_WIN,
    }); // gl.glShadeModel(GL.GL_SMOOTH); // ou GL.GL_FLAT
}

/// `display`: clear, the material, then one 4-vertex strip per cell of a `size` x `size` grid.
pub fn display(gl: &mut Context, size: usize, shading: Shading) {
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT); // gl.glClear(...);
    let diffuse = [0.5f32, 0.5, 0.8, 1.0];
    let specular = [1.0f32, 1.0, 1.0, 1.0];
    let shininess = 100.0f32;
    gl.materialfv(FRONT, DIFFUSE, &diffuse); // gl.glMaterialfv(GL.GL_FRONT, GL.GL_DIFFUSE, diffuse, 0);
    gl.materialfv(FRONT, SPECULAR, &specular); // gl.glMaterialfv(GL.GL_FRONT, GL.GL_SPECULAR, specular, 0);
    gl.materialf(FRONT, SHININESS, shininess); // gl.glMaterialf(GL.GL_FRONT, GL.GL_SHININESS, shininess);

    let mut m = create_matrix(size); // Cell[][] m = createMatrix(40);
    calculate_normal(&mut m); // calculateNormal(m);

    let v = |gl: &mut Context, c: &Cell| gl.vertex3f(c.point[0], c.point[1], c.point[2]);
    let n = |gl: &mut Context, c: &Cell| gl.normal3f(c.normal[0], c.normal[1], c.normal[2]);
    for i in 1..m.len() - 1 {
        for j in 1..m.len() - 1 {
            let corners = [&m[i + 1][j], &m[i + 1][j + 1], &m[i][j], &m[i][j + 1]];
            if shading == Shading::Flat {
                n(gl, &m[i][j]); // One normal per face, before glBegin: the cell's own point's.
            }
            gl.begin(TRIANGLE_STRIP);
            for c in corners {
                if shading != Shading::Flat {
                    n(gl, c); // One normal per vertex.
                }
                v(gl, c);
            }
            gl.end();
        }
    }
    gl.flush(); // gl.glFlush();
}

/// The whole frame: `init` then `display`, as JOGL calls them for the first frame.
pub fn draw(gl: &mut Context, size: usize, shading: Shading) {
    init(gl, shading);
    display(gl, size, shading);
}

/// How fast the animated scenes turn the surface: degrees a second about the y axis.
pub const DEGREES_PER_SECOND: f32 = 30.0;

/// The frame at `t` seconds for `fixedgl view`: the surface turned `DEGREES_PER_SECOND · t` about
/// its vertical axis under the fixed light and camera (the rotation goes after `init`'s lookAt and
/// light position, so only the model turns). At `t = 0` this is [`draw`], call for call.
pub fn draw_at(gl: &mut Context, size: usize, shading: Shading, t: f32) {
    init(gl, shading);
    if t != 0.0 {
        gl.matrix_mode(MODELVIEW);
        gl.rotatef(DEGREES_PER_SECOND * t, 0.0, 1.0, 0.0);
    }
    display(gl, size, shading);
}

/// The seed's pictures as registry entries.
pub(super) const SCENES: [Scene; 4] = [
    Scene {
        name: "gauss-flat-40",
        summary: "Surface rendering: flat shading — the JOGL Rendering gaussian bump, 40x40 cells, FLAT, one normal per cell",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| draw(gl, 40, Shading::Flat),
        animate: Some(|gl, t| draw_at(gl, 40, Shading::Flat, t)),
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "gauss-smooth-40",
        summary: "Surface rendering: Gouraud shading — the JOGL Rendering gaussian bump, 40x40 cells, SMOOTH, normal per vertex",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| draw(gl, 40, Shading::Smooth),
        animate: Some(|gl, t| draw_at(gl, 40, Shading::Smooth, t)),
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "gauss-smooth-400",
        summary: "Surface rendering: Gouraud shading on a fine mesh — the gaussian bump, 400x400 cells (320k triangles, 1.6M calls), SMOOTH",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| draw(gl, 400, Shading::Smooth),
        animate: Some(|gl, t| draw_at(gl, 400, Shading::Smooth, t)),
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "gauss-phong-40",
        summary: "Surface rendering: Phong shading — the 40x40 bump with ShadeModel(PHONG_WIN), per-fragment lighting (the lecture's GLSL Phong)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| draw(gl, 40, Shading::Phong),
        animate: Some(|gl, t| draw_at(gl, 40, Shading::Phong, t)),
        config: super::DEFAULT_CONFIG,
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid is the seed's: (size+2)^2 points over [-2, 2), y = e^(-x^2 - z^2), and every
    /// normal is a unit vector pointing up (the bump is a height field seen from above).
    #[test]
    fn grid_points_and_normals() {
        let mut m = create_matrix(40);
        calculate_normal(&mut m);
        assert_eq!(m.len(), 42);
        assert!(m.iter().all(|row| row.len() == 42));
        let p = m[21][21].point; // x = z = 4*21/42 - 2 = 0: the top of the bump.
        assert_eq!(p, [0.0, 1.0, 0.0]);
        assert_eq!(m[0][0].point, [-2.0, ((-8.0f64).exp()) as f32, -2.0]);
        for row in &m[1..] {
            for c in &row[1..] {
                let [x, y, z] = c.normal;
                assert!(((x * x + y * y + z * z).sqrt() - 1.0).abs() < 1e-5, "{c:?}");
                assert!(y > 0.0, "{c:?}");
            }
        }
        // At the top the surface is flat: the normal is (almost) straight up.
        assert!(m[21][21].normal[1] > 0.99);
    }

    /// One 4-vertex strip per cell: the smooth 40 frame has 1600 Begin/End pairs, 4 normals and
    /// 4 vertices each.
    #[test]
    fn smooth_frame_makes_the_seed_calls() {
        let (_, calls) = match SCENES[1].record(16, 16) {
            Ok(r) => r,
            Err(e) => panic!("{e}"),
        };
        let count = |f: fn(&crate::Call) -> bool| calls.iter().filter(|c| f(c)).count();
        assert_eq!(
            count(|c| matches!(c, crate::Call::Begin(TRIANGLE_STRIP))),
            1600
        );
        assert_eq!(count(|c| matches!(c, crate::Call::Vertex3f(..))), 6400);
        assert_eq!(count(|c| matches!(c, crate::Call::Normal3f(..))), 6400);
    }
}
