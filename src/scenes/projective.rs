//! Seed 001's effects done the fixed-function way: `projective-texture` (an image projected
//! onto spheres on a table by EYE_LINEAR TexGen and the texture matrix) and `shadow-map` (the
//! light's depth copied into a DEPTH_COMPONENT texture with CopyTexSubImage2D, then compared
//! per fragment with COMPARE_R_TO_TEXTURE) (GL 2.1 §2.11.4, §3.8.2, §3.8.14).
//!
//! Both use the same recipe for the texture coordinates: the four eye planes are the identity
//! rows (set under an identity modelview, so (s, t, r, q) = the eye position), and the texture
//! matrix takes eye coordinates to the projector's: bias · projector projection · projector
//! view · inverse camera view. The matrices are built with glam and loaded with
//! `load_matrixf`, exactly as a lecture program would compute them with glm.

use glam::{Mat4, Vec3};

use crate::gl::*;
use crate::texture::checkerboard;
use crate::{glu, Context};

use super::{Scene, Tolerance};

/// The scenes of this module.
pub const SCENES: [Scene; 2] = [
    Scene {
        name: "projective-texture",
        summary:
            "Texturing: projective texture mapping — checkerboard projected onto spheres on a table: EYE_LINEAR TexGen on S, T, R, Q, \
                  texture matrix = bias · projection · view · inverse camera view, \
                  CLAMP_TO_BORDER, MODULATE over lighting",
        tolerance: Tolerance {
            channel: 2,
            max_percent: 0.05,
        },
        default_size: (800, 800),
        draw: projective_texture,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "shadow-map",
        summary:
            "Shadows: shadow mapping — spheres on a table lit by a spot of light, shadows by a depth texture: depth from \
                  the light copied with CopyTexSubImage2D, COMPARE_R_TO_TEXTURE, TexEnv BLEND \
                  dimming what the light does not see",
        tolerance: Tolerance {
            channel: 2,
            max_percent: 0.05,
        },
        default_size: (800, 800),
        draw: shadow_map,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];

const CAMERA_EYE: Vec3 = Vec3::new(0.0, 4.0, 7.0);
const CAMERA_AT: Vec3 = Vec3::new(0.0, 0.0, 0.0);

/// `camera view`: what `glu::look_at` multiplies on, as a matrix.
fn camera_view() -> Mat4 {
    Mat4::look_at_rh(CAMERA_EYE, CAMERA_AT, Vec3::Y)
}

/// The bias taking [-1, 1] to [0, 1] on every axis.
fn bias() -> Mat4 {
    Mat4::from_translation(Vec3::splat(0.5)) * Mat4::from_scale(Vec3::splat(0.5))
}

/// A sphere of radius `r` at `c`: `stacks` bands of `slices` quads, outward unit normals.
fn sphere(gl: &mut Context, c: [f32; 3], r: f32, slices: u32, stacks: u32) {
    use std::f32::consts::PI;
    for i in 0..stacks {
        let (p0, p1) = (
            PI * i as f32 / stacks as f32 - PI / 2.0,
            PI * (i + 1) as f32 / stacks as f32 - PI / 2.0,
        );
        gl.begin(QUAD_STRIP);
        for j in 0..=slices {
            let th = 2.0 * PI * j as f32 / slices as f32;
            for p in [p1, p0] {
                let n = [p.cos() * th.cos(), p.sin(), -p.cos() * th.sin()];
                gl.normal3fv(&n);
                gl.vertex3f(c[0] + r * n[0], c[1] + r * n[1], c[2] + r * n[2]);
            }
        }
        gl.end();
    }
}

/// The table top: a 6 x 4 slab at y = 0, cut into a grid so lighting varies across it.
fn table(gl: &mut Context) {
    gl.normal3f(0.0, 1.0, 0.0);
    let n = 12;
    for i in 0..n {
        gl.begin(QUAD_STRIP);
        for j in 0..=n {
            let x = -3.0 + 6.0 * j as f32 / n as f32;
            for k in [i + 1, i] {
                let z = -2.0 + 4.0 * k as f32 / n as f32;
                gl.vertex3f(x, 0.0, z);
            }
        }
        gl.end();
    }
}

/// Table and three spheres, with their materials.
fn world(gl: &mut Context) {
    gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &[0.7, 0.6, 0.45, 1.0]);
    table(gl);
    for (c, r, col) in [
        ([-1.3, 0.6, 0.2], 0.6, [0.8, 0.2, 0.2, 1.0]),
        ([0.4, 0.8, -0.5], 0.8, [0.2, 0.7, 0.3, 1.0]),
        ([1.6, 0.45, 0.9], 0.45, [0.25, 0.35, 0.9, 1.0]),
    ] {
        gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &col);
        sphere(gl, c, r, 32, 16);
    }
}

/// Camera projection and view, the light, and the eye-plane TexGen on S, T, R, Q.
fn camera_and_light(gl: &mut Context, light: [f32; 4]) {
    gl.viewport(0, 0, 800, 800);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, 1.0, 1.0, 30.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    // Eye planes under the identity: (s, t, r, q) = eye coordinates.
    for (k, c) in [S, T, R, Q].into_iter().enumerate() {
        let mut p = [0.0f32; 4];
        p[k] = 1.0;
        gl.tex_geni(c, TEXTURE_GEN_MODE, EYE_LINEAR as i32);
        gl.tex_genfv(c, EYE_PLANE, &p);
    }
    for c in [TEXTURE_GEN_S, TEXTURE_GEN_T, TEXTURE_GEN_R, TEXTURE_GEN_Q] {
        gl.enable(c);
    }
    let (e, a) = (CAMERA_EYE, CAMERA_AT);
    glu::look_at(
        gl,
        e.x.into(),
        e.y.into(),
        e.z.into(),
        a.x.into(),
        a.y.into(),
        a.z.into(),
        0.0,
        1.0,
        0.0,
    );
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &light);
    gl.lightfv(LIGHT0, DIFFUSE, &[0.9, 0.9, 0.9, 1.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[0.0, 0.0, 0.0, 1.0]);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.25, 0.25, 0.25, 1.0]);
}

/// Loads `m` on the texture matrix stack (unit 0) and returns to MODELVIEW.
fn texture_matrix(gl: &mut Context, m: Mat4) {
    gl.matrix_mode(TEXTURE);
    gl.load_matrixf(&m.to_cols_array());
    gl.matrix_mode(MODELVIEW);
}

/// `projective-texture`.
fn projective_texture(gl: &mut Context) {
    gl.clear_color(0.05, 0.05, 0.08, 1.0);
    gl.enable(DEPTH_TEST);
    let mut tex = [0u32];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(TEXTURE_2D, tex[0]);
    let img = checkerboard(64, 4, [255, 230, 60, 255], [200, 40, 160, 255]);
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA as i32,
        64,
        64,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&img),
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_BORDER as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, CLAMP_TO_BORDER as i32);
    gl.tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &[1.0, 1.0, 1.0, 1.0]);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_2D);
    // The projector: above and to the left, a 28° frustum onto the middle of the table.
    let proj = Mat4::perspective_rh_gl(28f32.to_radians(), 1.0, 1.0, 20.0);
    let view = Mat4::look_at_rh(Vec3::new(-2.5, 6.0, 3.0), Vec3::new(0.0, 0.3, 0.0), Vec3::Y);
    texture_matrix(gl, bias() * proj * view * camera_view().inverse());
    camera_and_light(gl, [3.0, 6.0, 4.0, 1.0]);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    world(gl);
}

/// Side of the shadow map, drawn in the framebuffer's lower-left corner.
const SHADOW: i32 = 512;

/// `shadow-map`.
fn shadow_map(gl: &mut Context) {
    let light_pos = Vec3::new(2.5, 6.0, 3.0);
    let light_proj = Mat4::perspective_rh_gl(45f32.to_radians(), 1.0, 4.0, 12.0);
    let light_view = Mat4::look_at_rh(light_pos, Vec3::ZERO, Vec3::Y);
    gl.clear_color(0.05, 0.05, 0.08, 1.0);
    gl.enable(DEPTH_TEST);

    // Pass 1: depth from the light, colour writes off, pushed back by polygon offset.
    gl.viewport(0, 0, SHADOW, SHADOW);
    gl.matrix_mode(PROJECTION);
    gl.load_matrixf(&light_proj.to_cols_array());
    gl.matrix_mode(MODELVIEW);
    gl.load_matrixf(&light_view.to_cols_array());
    gl.color_mask(false, false, false, false);
    gl.enable(POLYGON_OFFSET_FILL);
    gl.polygon_offset(2.0, 4.0);
    gl.clear(DEPTH_BUFFER_BIT);
    world(gl);
    gl.disable(POLYGON_OFFSET_FILL);
    gl.color_mask(true, true, true, true);

    let mut tex = [0u32];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(TEXTURE_2D, tex[0]);
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        DEPTH_COMPONENT as i32,
        SHADOW,
        SHADOW,
        0,
        DEPTH_COMPONENT,
        UNSIGNED_BYTE,
        None,
    );
    gl.copy_tex_sub_image_2d(TEXTURE_2D, 0, 0, 0, 0, 0, SHADOW, SHADOW);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(
        TEXTURE_2D,
        TEXTURE_COMPARE_MODE,
        COMPARE_R_TO_TEXTURE as i32,
    );
    // 1 where the fragment is farther from the light than the stored depth: in shadow.
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_COMPARE_FUNC, GREATER as i32);
    gl.tex_parameteri(TEXTURE_2D, DEPTH_TEXTURE_MODE, LUMINANCE as i32);
    // BLEND: Cf·(1 - L) + Cc·L, so shadowed fragments (L = 1) take the dim environment colour.
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, BLEND as i32);
    gl.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[0.12, 0.11, 0.14, 1.0]);
    gl.enable(TEXTURE_2D);

    // Pass 2: the lit scene from the camera.
    texture_matrix(
        gl,
        bias() * light_proj * light_view * camera_view().inverse(),
    );
    camera_and_light(gl, [light_pos.x, light_pos.y, light_pos.z, 1.0]);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    world(gl);
}
