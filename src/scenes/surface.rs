//! Seed 000's other two pictures of the gaussian surface: `gauss-normalize` (normals three times
//! too long, repaired by `glEnable(GL_NORMALIZE)`, GL 2.1 §2.11.3) and `vertex-color` (the seed's
//! GLSL shader that colours each fragment by its vertex's object position, done the
//! fixed-function way with `glColor3f(x, y, z)` per vertex and lighting off, §2.14).
//!
//! Both reuse the port of the JOGL `Rendering` class in [`super::gaussian`]: same grid, same
//! camera (`gluLookAt(1.5, 0.75, 1, ...)`, `glOrtho(-2.5, 2.5, ...)`), same strips.
//!
//! Design decision, `vertex-color`: the shader passes the *unclamped* position as a varying and the
//! framebuffer clamps each fragment; `glColor3f` colours are clamped to [0, 1] per vertex before
//! interpolation (§2.14.8), so where x or z changes sign inside a cell the fixed-function picture
//! ramps to black over that cell instead of exactly at x = 0. Everywhere else the two agree.

use crate::gl::*;
use crate::{glu, Context};

use super::gaussian::{calculate_normal, create_matrix, init, Cell, Shading};
use super::{Scene, LECTURE};

/// `gauss-normalize`: the SMOOTH 40x40 frame with every normal multiplied by `scale` and
/// `glEnable(GL_NORMALIZE)`, so lighting sees unit normals again (§2.11.3). With `scale` = 3 the
/// picture must equal `gauss-smooth-40`.
pub fn gauss_normalize(gl: &mut Context, scale: f32) {
    gauss_scaled(gl, scale, true);
}

/// The SMOOTH frame with normals scaled by `scale`, NORMALIZE on or off.
fn gauss_scaled(gl: &mut Context, scale: f32, normalize: bool) {
    init(gl, Shading::Smooth);
    if normalize {
        gl.enable(NORMALIZE); // gl.glEnable(GL.GL_NORMALIZE);
    }
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.materialfv(FRONT, DIFFUSE, &[0.5, 0.5, 0.8, 1.0]);
    gl.materialfv(FRONT, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.materialf(FRONT, SHININESS, 100.0);
    let mut m = create_matrix(40);
    calculate_normal(&mut m);
    strips(gl, &m, |gl, c| {
        let [x, y, z] = c.normal;
        gl.normal3f(scale * x, scale * y, scale * z);
    });
    gl.flush();
}

/// `vertex-color`: the seed's camera and grid, lighting off, SMOOTH, and before each vertex
/// `glColor3f(x, y, z)` of its object position: the vertex shader's `vertex_color = gl_Vertex.xyz`.
pub fn vertex_color(gl: &mut Context) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 1.5, 0.75, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    gl.ortho(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5);
    gl.shade_model(SMOOTH);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    let m = create_matrix(40);
    strips(gl, &m, |gl, c| {
        let [x, y, z] = c.point;
        gl.color3f(x, y, z);
    });
    gl.flush();
}

/// One 4-vertex `TRIANGLE_STRIP` per cell, in the seed's vertex order, calling `attr` before
/// each vertex.
fn strips(gl: &mut Context, m: &[Vec<Cell>], attr: impl Fn(&mut Context, &Cell)) {
    let n = m.len();
    for i in 1..n.saturating_sub(1) {
        for j in 1..n.saturating_sub(1) {
            gl.begin(TRIANGLE_STRIP);
            for c in [&m[i + 1][j], &m[i + 1][j + 1], &m[i][j], &m[i][j + 1]] {
                attr(gl, c);
                gl.vertex3f(c.point[0], c.point[1], c.point[2]);
            }
            gl.end();
        }
    }
}

/// The seed 000 scenes of this module, as registry entries.
pub(super) const SCENES: [Scene; 2] = [
    Scene {
        name: "gauss-normalize",
        summary:
            "Surface rendering: normals of the wrong length — the SMOOTH 40x40 bump with normals scaled by 3 and glEnable(GL_NORMALIZE)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| gauss_normalize(gl, 3.0),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "vertex-color",
        summary:
            "Surface rendering: colour per vertex — the bump coloured by object position, glColor3f(x, y, z) per vertex, unlit",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: vertex_color,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenes::find;

    fn render(draw: fn(&mut Context), size: u32) -> image::RgbaImage {
        match Context::new(size, size) {
            Ok(mut gl) => {
                draw(&mut gl);
                gl.to_image()
            }
            Err(e) => panic!("{e}"),
        }
    }

    /// NORMALIZE undoes the factor 3: the picture is the unscaled smooth one, within rounding of
    /// the renormalised normal (1/255 on a channel).
    #[test]
    fn normalize_undoes_the_scale() {
        let smooth = find("gauss-smooth-40").map(|s| s.draw);
        let Some(smooth) = smooth else {
            panic!("gauss-smooth-40 is registered")
        };
        let a = render(smooth, 96);
        let b = render(|gl| gauss_normalize(gl, 3.0), 96);
        let worst = a
            .pixels()
            .zip(b.pixels())
            .flat_map(|(p, q)| (0..4).map(move |k| p.0[k].abs_diff(q.0[k])))
            .max();
        assert!(worst.is_some_and(|d| d <= 1), "{worst:?}");
        // Without NORMALIZE the factor 3 over-lights the bump (N·L triples): some pixel must
        // come out brighter.
        let c = render(|gl| gauss_scaled(gl, 3.0, false), 96);
        assert!(b
            .pixels()
            .zip(c.pixels())
            .any(|(p, q)| q.0[2] > p.0[2].saturating_add(8)));
    }

    /// The top of the bump is x = z = 0, y = 1: colour (0, 1, 0) before clamping, so the pixel at
    /// the bump's top is pure green; the white background stays white in the corner.
    #[test]
    fn vertex_color_top_is_green() {
        let img = render(vertex_color, 200);
        // gluLookAt(1.5, 0.75, 1 → origin): the point (0, 1, 0) is at eye x = 0 and eye
        // y = up·(0,1,0) with up = u = s × f; |y| = 1·(cos of the angle between world up and
        // the view plane) = sqrt(1.5² + 1²)/|eye| = 1.8028/1.9526 = 0.9233; with ortho ±2.5 on 200
        // pixels, window y = 100 + 0.9233·40 = 136.9, image row 200 - 137 = 63.
        let p = img.get_pixel(100, 63).0;
        assert!(p[0] < 16 && p[1] > 230 && p[2] < 16, "{p:?}");
        assert_eq!(img.get_pixel(0, 0).0, [255, 255, 255, 255]);
    }
}
