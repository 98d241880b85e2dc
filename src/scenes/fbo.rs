//! `render-to-texture`: a lit teapot and torus drawn into a 128x128 texture through a
//! framebuffer object (GL_EXT_framebuffer_object under the GL 3.0 names, GL 3.0 §4.4) with a
//! depth renderbuffer, then that texture on the faces of a cube in the window — the lecture
//! recipe for render-to-texture (and, with a depth texture, for shadow maps).

use crate::gl::*;
use crate::{glu, glut, Context};

use super::{Scene, Tolerance};

/// The scenes of this module.
pub const SCENES: [Scene; 1] = [Scene {
    name: "render-to-texture",
    summary: "Framebuffer objects: render to texture — a lit teapot and torus drawn into a 128x128 RGBA8 texture \
              through GenFramebuffers/FramebufferTexture2D with a DEPTH_COMPONENT24 renderbuffer, \
              then the texture on a cube in the window (LINEAR, MODULATE)",
    tolerance: Tolerance {
        channel: 2,
        max_percent: 0.05,
    },
    default_size: (400, 400),
    draw: render_to_texture,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

/// Side of the texture drawn into.
const SIZE: i32 = 128;

/// The scene: the offscreen pass, then the window pass.
pub fn render_to_texture(gl: &mut Context) {
    let (w, h) = gl.size();
    let mut tex = [0];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(TEXTURE_2D, tex[0]);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, CLAMP_TO_EDGE as i32);
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA8 as i32,
        SIZE,
        SIZE,
        0,
        RGBA,
        UNSIGNED_BYTE,
        None,
    );
    let (mut fbo, mut depth) = ([0], [0]);
    gl.gen_renderbuffers(1, &mut depth);
    gl.bind_renderbuffer(RENDERBUFFER, depth[0]);
    gl.renderbuffer_storage(RENDERBUFFER, DEPTH_COMPONENT24, SIZE, SIZE);
    gl.gen_framebuffers(1, &mut fbo);
    gl.bind_framebuffer(FRAMEBUFFER, fbo[0]);
    gl.framebuffer_texture_2d(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex[0], 0);
    gl.framebuffer_renderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, depth[0]);

    // The offscreen pass: what a camera sees, into the texture.
    gl.viewport(0, 0, SIZE, SIZE);
    gl.clear_color(0.95, 0.85, 0.55, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, 1.0, 1.0, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 1.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(DEPTH_TEST);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.enable(NORMALIZE);
    gl.lightfv(LIGHT0, POSITION, &[2.0, 3.0, 4.0, 0.0]);
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.8, 0.2, 0.2, 1.0]);
    gl.materialfv(FRONT_AND_BACK, SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(FRONT_AND_BACK, SHININESS, 40.0);
    gl.push_matrix();
    gl.translatef(-0.3, 0.2, 0.0);
    glut::solid_teapot(gl, 0.8);
    gl.pop_matrix();
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.2, 0.4, 0.9, 1.0]);
    gl.push_matrix();
    gl.translatef(0.6, -0.4, 0.8);
    gl.rotatef(60.0, 1.0, 0.0, 0.0);
    glut::solid_torus(gl, 0.15, 0.45, 16, 32);
    gl.pop_matrix();
    gl.disable(LIGHTING);

    // The window pass: the texture on a cube.
    gl.bind_framebuffer(FRAMEBUFFER, 0);
    gl.viewport(0, 0, w as i32, h as i32);
    gl.clear_color(0.15, 0.15, 0.2, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 35.0, f64::from(w) / f64::from(h.max(1)), 1.0, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 3.0, 2.6, 4.2, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(TEXTURE_2D);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.begin(QUADS);
    // Each face: a shade (MODULATE) and four corners with their texture coordinates.
    let faces: [(f32, [[f32; 3]; 4]); 3] = [
        (
            1.0,
            [
                [-1.0, -1.0, 1.0],
                [1.0, -1.0, 1.0],
                [1.0, 1.0, 1.0],
                [-1.0, 1.0, 1.0],
            ],
        ),
        (
            0.8,
            [
                [1.0, -1.0, 1.0],
                [1.0, -1.0, -1.0],
                [1.0, 1.0, -1.0],
                [1.0, 1.0, 1.0],
            ],
        ),
        (
            0.9,
            [
                [-1.0, 1.0, 1.0],
                [1.0, 1.0, 1.0],
                [1.0, 1.0, -1.0],
                [-1.0, 1.0, -1.0],
            ],
        ),
    ];
    for (shade, corners) in faces {
        gl.color3f(shade, shade, shade);
        for (k, [x, y, z]) in corners.into_iter().enumerate() {
            let (s, t) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][k];
            gl.tex_coord2f(s, t);
            gl.vertex3f(x, y, z);
        }
    }
    gl.end();
    gl.disable(TEXTURE_2D);
    gl.delete_framebuffers(1, &fbo);
    gl.delete_renderbuffers(1, &depth);
}
