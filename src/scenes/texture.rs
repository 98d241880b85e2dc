//! Texturing scenes: `textured-cube`, a lit cube and a receding floor under a mipmapped
//! checkerboard with TexEnv MODULATE (GL 2.1 §3.8).
//!
//! The floor runs from the camera to the horizon, so every mipmap level is used and the
//! comparison exercises λ selection and LINEAR_MIPMAP_LINEAR blending; the cube's faces
//! exercise magnification, REPEAT wrapping and MODULATE over lit colours.
//!
//! Measured against llvmpipe: 2 of 640 000 pixels differ by more than 2/255 at 800x800, 5 of
//! 160 000 at 400x400 (with the exact log2 for λ instead of llvmpipe's piecewise-linear one it
//! was 84 and 353: LINEAR_MIPMAP_LINEAR on checker edges blends levels of very different values,
//! so λ must match to a few thousandths).

use crate::gl::*;
use crate::texture::checkerboard;
use crate::{glu, Context};

use super::{Scene, Tolerance};

/// The scenes of this module.
pub const SCENES: [Scene; 1] = [Scene {
    name: "textured-cube",
    summary: "lit cube and floor, mipmapped checkerboard (gluBuild2DMipmaps, \
              LINEAR_MIPMAP_LINEAR, REPEAT), TexEnv MODULATE",
    tolerance: Tolerance {
        channel: 2,
        max_percent: 0.05,
    },
    default_size: (800, 800),
    draw: textured_cube,
}];

/// The cube's faces: normal, then four corners counter-clockwise seen from outside.
const FACES: [([f32; 3], [[f32; 3]; 4]); 6] = [
    (
        [0.0, 0.0, 1.0],
        [
            [-1.0, -1.0, 1.0],
            [1.0, -1.0, 1.0],
            [1.0, 1.0, 1.0],
            [-1.0, 1.0, 1.0],
        ],
    ),
    (
        [0.0, 0.0, -1.0],
        [
            [1.0, -1.0, -1.0],
            [-1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [1.0, 1.0, -1.0],
        ],
    ),
    (
        [1.0, 0.0, 0.0],
        [
            [1.0, -1.0, 1.0],
            [1.0, -1.0, -1.0],
            [1.0, 1.0, -1.0],
            [1.0, 1.0, 1.0],
        ],
    ),
    (
        [-1.0, 0.0, 0.0],
        [
            [-1.0, -1.0, -1.0],
            [-1.0, -1.0, 1.0],
            [-1.0, 1.0, 1.0],
            [-1.0, 1.0, -1.0],
        ],
    ),
    (
        [0.0, 1.0, 0.0],
        [
            [-1.0, 1.0, 1.0],
            [1.0, 1.0, 1.0],
            [1.0, 1.0, -1.0],
            [-1.0, 1.0, -1.0],
        ],
    ),
    (
        [0.0, -1.0, 0.0],
        [
            [-1.0, -1.0, -1.0],
            [1.0, -1.0, -1.0],
            [1.0, -1.0, 1.0],
            [-1.0, -1.0, 1.0],
        ],
    ),
];

/// `textured-cube`.
fn textured_cube(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 50.0, 1.0, 0.5, 100.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 2.2, 5.5, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0);

    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &[3.0, 5.0, 4.0, 1.0]);
    gl.lightfv(LIGHT0, DIFFUSE, &[0.9, 0.9, 0.85, 1.0]);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.3, 0.3, 0.3, 1.0]);
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.9, 0.8, 0.6, 1.0]);

    let mut tex = [0u32; 1];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(TEXTURE_2D, tex[0]);
    let img = checkerboard(64, 8, [240, 240, 240, 255], [40, 60, 160, 255]);
    glu::build_2d_mipmaps(
        gl,
        TEXTURE_2D,
        RGBA as i32,
        64,
        64,
        RGBA,
        UNSIGNED_BYTE,
        &img,
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, REPEAT as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, REPEAT as i32);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_2D);

    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);

    // The floor: y = -1, texture repeated 20 times over 40 x 40 units.
    gl.begin(QUADS);
    gl.normal3f(0.0, 1.0, 0.0);
    for (s, t, x, z) in [
        (0.0, 0.0, -20.0, 10.0),
        (20.0, 0.0, 20.0, 10.0),
        (20.0, 20.0, 20.0, -30.0),
        (0.0, 20.0, -20.0, -30.0),
    ] {
        gl.tex_coord2f(s, t);
        gl.vertex3f(x, -1.0, z);
    }
    gl.end();

    // The cube, turned to show three faces, the texture twice across each face.
    gl.push_matrix();
    gl.translatef(0.0, 0.2, 0.0);
    gl.rotatef(30.0, 0.0, 1.0, 0.0);
    gl.rotatef(20.0, 1.0, 0.0, 0.0);
    gl.scalef(0.9, 0.9, 0.9);
    gl.begin(QUADS);
    for (n, corners) in FACES {
        gl.normal3fv(&n);
        for (k, c) in corners.iter().enumerate() {
            let st = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]][k];
            gl.tex_coord2f(st[0], st[1]);
            gl.vertex3fv(c);
        }
    }
    gl.end();
    gl.pop_matrix();
}
