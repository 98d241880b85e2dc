//! `point-sprites`: a particle exercise (GL 2.0 point sprites, GL 1.4 point parameters):
//! a perspective field of sprites whose size falls off with distance
//! (POINT_DISTANCE_ATTENUATION, POINT_SIZE_MIN/MAX), each textured with COORD_REPLACE by a
//! procedural particle texture (a soft disc with a cross, alpha falling to the rim) and blended
//! additively, over a row of large sprites in both POINT_SPRITE_COORD_ORIGINs and a textured
//! quad showing the texture itself (640x480).

use super::{Scene, LECTURE};
use crate::{gl, glu, Context};

/// A 32x32 RGBA particle: a soft disc, brighter on a cross, an arrow in one corner so the
/// origin shows.
fn particle() -> Vec<u8> {
    let mut px = Vec::with_capacity(32 * 32 * 4);
    for y in 0..32 {
        for x in 0..32 {
            let (dx, dy) = (x as f32 - 15.5, y as f32 - 15.5);
            let r = (dx * dx + dy * dy).sqrt() / 16.0;
            let a = (1.0 - r).clamp(0.0, 1.0);
            let cross = if dx.abs() < 2.0 || dy.abs() < 2.0 {
                1.0
            } else {
                0.6
            };
            let mark = x > 22 && y > 22 && x + y > 50;
            let (cr, cg, cb) = if mark {
                (1.0, 0.2, 0.1)
            } else {
                (0.6 + 0.4 * cross, 0.8 * cross, 1.0)
            };
            let a = if mark { 1.0 } else { a };
            px.extend([cr, cg, cb, a].map(|v: f32| (v * 255.0).round() as u8));
        }
    }
    px
}

/// Draws the scene.
pub fn point_sprites(gl: &mut Context) {
    gl.clear_color(0.02, 0.02, 0.08, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 50.0, 640.0 / 480.0, 0.5, 60.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 2.0, 6.0, 0.0, 0.0, -6.0, 0.0, 1.0, 0.0);

    let mut tex = [0u32];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(gl::TEXTURE_2D, tex[0]);
    let px = particle();
    gl.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        32,
        32,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::LINEAR as i32);
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::LINEAR as i32);
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_WRAP_S, gl::CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_WRAP_T, gl::CLAMP_TO_EDGE as i32);
    gl.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::MODULATE as i32);
    gl.enable(gl::TEXTURE_2D);

    // The texture itself on a quad, for reference (lower left of the view).
    gl.color3f(1.0, 1.0, 1.0);
    gl.begin(gl::QUADS);
    gl.tex_coord2f(0.0, 0.0);
    gl.vertex3f(-5.0, -1.5, -2.0);
    gl.tex_coord2f(1.0, 0.0);
    gl.vertex3f(-3.5, -1.5, -2.0);
    gl.tex_coord2f(1.0, 1.0);
    gl.vertex3f(-3.5, 0.0, -2.0);
    gl.tex_coord2f(0.0, 1.0);
    gl.vertex3f(-5.0, 0.0, -2.0);
    gl.end();

    gl.enable(gl::BLEND);
    gl.blend_func(gl::SRC_ALPHA, gl::ONE);
    gl.enable(gl::POINT_SPRITE);
    gl.tex_envi(gl::POINT_SPRITE, gl::COORD_REPLACE, gl::TRUE as i32);

    // A field of attenuated sprites on a ground grid.
    gl.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[0.0, 0.08, 0.006]);
    gl.point_parameterf(gl::POINT_SIZE_MIN, 2.0);
    gl.point_parameterf(gl::POINT_SIZE_MAX, 48.0);
    gl.point_size(40.0);
    gl.begin(gl::POINTS);
    for i in 0..12 {
        for j in 0..9 {
            let (x, z) = (-5.5 + i as f32, -1.0 - 2.0 * j as f32);
            let h = 0.3 * ((x * 0.7).sin() + (z * 0.5).cos());
            gl.color4f(
                0.5 + 0.5 * (i as f32 / 11.0),
                0.6,
                1.0 - 0.5 * (j as f32 / 8.0),
                0.9,
            );
            gl.vertex3f(x, h - 0.8, z);
        }
    }
    gl.end();

    // Large unattenuated sprites, upper-left then lower-left origin (the red mark moves).
    gl.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[1.0, 0.0, 0.0]);
    gl.point_size(56.0);
    gl.color4f(1.0, 1.0, 1.0, 1.0);
    gl.begin(gl::POINTS);
    gl.vertex3f(1.5, 1.6, -1.0);
    gl.end();
    gl.point_parameteri(gl::POINT_SPRITE_COORD_ORIGIN, gl::LOWER_LEFT as i32);
    gl.point_size(37.5);
    gl.begin(gl::POINTS);
    gl.vertex3f(3.2, 1.6, -1.0);
    gl.end();

    gl.disable(gl::POINT_SPRITE);
    gl.disable(gl::BLEND);
    gl.disable(gl::TEXTURE_2D);
}

/// The point-sprites scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "point-sprites",
    summary: "Point sprites: a perspective field of particles sized by POINT_DISTANCE_ATTENUATION within POINT_SIZE_MIN/MAX, textured through COORD_REPLACE and blended additively, large sprites in both POINT_SPRITE_COORD_ORIGINs, and the particle texture on a quad",
    tolerance: LECTURE,
    default_size: (640, 480),
    draw: point_sprites,
    animate: None,
}];
