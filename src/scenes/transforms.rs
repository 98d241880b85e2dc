//! `transforms`: seed 004's geometric transformations (translation, scale, rotation; GL 2.1
//! §2.11.2 `glTranslate`, `glScale`, `glRotate`) applied to one object, a cube with a colour per
//! face, seen through the seed's camera: `lookAt(eye (0,0,3), centre 0, up +y)` and
//! `perspective(45°, width/height, 0.1, 100)`.
//!
//! The seed's cube example builds its model matrix as `from_scale(1.1) · from_x_rotation(-45°) ·
//! from_y_rotation(-45°)` in pyrr's row-vector convention, i.e. the vertex is scaled, then turned
//! about x, then about y. In GL's column-vector convention the calls come in the reverse order:
//! `glRotatef(-45, 0,1,0); glRotatef(-45, 1,0,0); glScalef(1.1, 1.1, 1.1)`.
//!
//! Design decision: four panels, each the slide's model with one more transformation multiplied
//! on the left (applied last, in world space): none, a translation, a non-uniform scale, a
//! rotation about z. The cube is drawn with `GL_QUADS` and `glColor3f` per face, so the scene
//! needs only Begin/End (the vertex-array cube is `cube-colors`).

use crate::gl::*;
use crate::{glu, Context};

use super::shapes::panels;
use super::{Scene, LECTURE};

/// The cube's faces: (colour, four corners counter-clockwise seen from outside), half size 0.5.
pub const FACES: [([f32; 3], [[f32; 3]; 4]); 6] = [
    // Front (z = +0.5), red.
    (
        [1.0, 0.0, 0.0],
        [
            [-0.5, -0.5, 0.5],
            [0.5, -0.5, 0.5],
            [0.5, 0.5, 0.5],
            [-0.5, 0.5, 0.5],
        ],
    ),
    // Back (z = -0.5), green.
    (
        [0.0, 1.0, 0.0],
        [
            [0.5, -0.5, -0.5],
            [-0.5, -0.5, -0.5],
            [-0.5, 0.5, -0.5],
            [0.5, 0.5, -0.5],
        ],
    ),
    // Left (x = -0.5), blue.
    (
        [0.0, 0.0, 1.0],
        [
            [-0.5, -0.5, -0.5],
            [-0.5, -0.5, 0.5],
            [-0.5, 0.5, 0.5],
            [-0.5, 0.5, -0.5],
        ],
    ),
    // Right (x = +0.5), yellow.
    (
        [1.0, 1.0, 0.0],
        [
            [0.5, -0.5, 0.5],
            [0.5, -0.5, -0.5],
            [0.5, 0.5, -0.5],
            [0.5, 0.5, 0.5],
        ],
    ),
    // Top (y = +0.5), magenta.
    (
        [1.0, 0.0, 1.0],
        [
            [-0.5, 0.5, 0.5],
            [0.5, 0.5, 0.5],
            [0.5, 0.5, -0.5],
            [-0.5, 0.5, -0.5],
        ],
    ),
    // Bottom (y = -0.5), cyan.
    (
        [0.0, 1.0, 1.0],
        [
            [-0.5, -0.5, -0.5],
            [0.5, -0.5, -0.5],
            [0.5, -0.5, 0.5],
            [-0.5, -0.5, 0.5],
        ],
    ),
];

/// The cube, one `GL_QUADS` primitive, a colour per face.
pub fn draw_cube(gl: &mut Context) {
    gl.begin(QUADS);
    for (colour, corners) in FACES {
        gl.color3fv(&colour);
        for p in corners {
            gl.vertex3fv(&p);
        }
    }
    gl.end();
}

/// The extra transformation of each panel, in reading order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Extra {
    /// The slide's model matrix alone.
    None,
    /// `glTranslatef(x, y, z)`.
    Translate([f32; 3]),
    /// `glScalef(x, y, z)`.
    Scale([f32; 3]),
    /// `glRotatef(angle, x, y, z)`.
    Rotate(f32, [f32; 3]),
}

/// The four panels of the scene.
pub const PANELS: [Extra; 4] = [
    Extra::None,
    Extra::Translate([0.45, 0.35, -0.5]),
    Extra::Scale([1.5, 0.6, 1.0]),
    Extra::Rotate(30.0, [0.0, 0.0, 1.0]),
];

/// `transforms`: the cube under the seed's camera in a 2x2 grid, one [`Extra`] per panel.
pub fn transforms(gl: &mut Context, extras: &[Extra; 4]) {
    gl.clear_color(0.95, 0.95, 0.95, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.shade_model(FLAT);
    for ((x, y, w, h), extra) in panels(gl, 2, 2).into_iter().zip(extras) {
        gl.viewport(x, y, w, h);
        gl.matrix_mode(PROJECTION);
        gl.load_identity();
        glu::perspective(gl, 45.0, f64::from(w) / f64::from(h.max(1)), 0.1, 100.0);
        gl.matrix_mode(MODELVIEW);
        gl.load_identity();
        glu::look_at(gl, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0); // view
        match *extra {
            Extra::None => {}
            Extra::Translate([a, b, c]) => gl.translatef(a, b, c),
            Extra::Scale([a, b, c]) => gl.scalef(a, b, c),
            Extra::Rotate(angle, [a, b, c]) => gl.rotatef(angle, a, b, c),
        }
        // The slide's model: scale 1.1, then -45° about x, then -45° about y.
        gl.rotatef(-45.0, 0.0, 1.0, 0.0);
        gl.rotatef(-45.0, 1.0, 0.0, 0.0);
        gl.scalef(1.1, 1.1, 1.1);
        draw_cube(gl);
    }
    gl.flush();
}

/// The scene, as a registry entry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "transforms",
    summary: "Geometric transformations: translate, scale, rotate — a face-coloured cube, the slide's model (scale, rotate x, rotate y), then translate / scale / rotate",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: |gl| transforms(gl, &PANELS),
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

#[cfg(test)]
mod tests {
    use super::*;

    /// Every face is wound counter-clockwise seen from outside: (b - a) × (c - a) points the way
    /// of the face's centre, and all corners are on the face's plane (|coordinate| = 0.5).
    #[test]
    fn faces_wind_outwards() {
        for (_, [a, b, c, d]) in FACES {
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let g = [a[0] + c[0], a[1] + c[1], a[2] + c[2]];
            assert!(n[0] * g[0] + n[1] * g[1] + n[2] * g[2] > 0.0);
            assert!([a, b, c, d].iter().flatten().all(|x| x.abs() == 0.5));
        }
    }

    /// Under the seed's camera with no model transform, the front face (z = 0.5, red) faces the
    /// eye: the panel centre is red. With perspective(45°), the face's half-width 0.5 at eye
    /// distance 2.5 spans 0.5/2.5/tan(22.5°) = 0.483 of the half-panel, so 8 pixels right of the
    /// centre of a 400-pixel panel is still red.
    #[test]
    fn identity_cube_shows_its_red_front() {
        let mut gl = match Context::new(800, 800) {
            Ok(gl) => gl,
            Err(e) => panic!("{e}"),
        };
        gl.enable(DEPTH_TEST);
        gl.viewport(0, 0, 400, 400);
        gl.matrix_mode(PROJECTION);
        glu::perspective(&mut gl, 45.0, 1.0, 0.1, 100.0);
        gl.matrix_mode(MODELVIEW);
        glu::look_at(&mut gl, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
        draw_cube(&mut gl);
        let img = gl.to_image();
        assert_eq!(img.get_pixel(208, 599).0, [255, 0, 0, 255]);
        // 0.483 · 200 = 96.6 pixels: 110 pixels right of the centre is background (black).
        assert_eq!(img.get_pixel(310, 599).0, [0, 0, 0, 0]);
    }
}
