//! `quadrics`: the GLU quadrics of a scene-graph assignment, nine panels in three rows.
//!
//! Top: a smooth lit sphere, a cylinder and a cone with FLAT normals. Middle: a checkerboard
//! textured sphere and disk (gluQuadricTexture, MODULATE over lighting), a lit partial disk seen
//! from both sides (INSIDE orientation, two-sided lighting). Bottom: a wireframe sphere
//! (GLU_LINE), a cylinder's silhouette and a partial disk of points.

use super::{Scene, LECTURE};
use crate::glu::{self, Quadric};
use crate::texture::checkerboard;
use crate::{gl, Context};

/// Sets up panel `k` of the 3x3 grid: viewport, perspective, camera, the light.
fn panel(gl: &mut Context, k: i32) {
    let (w, h) = gl.size();
    let (pw, ph) = (w as i32 / 3, h as i32 / 3);
    gl.viewport((k % 3) * pw, (2 - k / 3) * ph, pw, ph);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, f64::from(pw) / f64::from(ph.max(1)), 1.0, 20.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, -4.0, 2.6, 0.0, 0.0, 0.2, 0.0, 0.0, 1.0);
    gl.lightfv(gl::LIGHT0, gl::POSITION, &[2.0, -3.0, 4.0, 1.0]);
}

fn material(gl: &mut Context, rgb: [f32; 3]) {
    gl.materialfv(gl::FRONT_AND_BACK, gl::AMBIENT, &[0.2, 0.2, 0.2, 1.0]);
    gl.materialfv(
        gl::FRONT_AND_BACK,
        gl::DIFFUSE,
        &[rgb[0], rgb[1], rgb[2], 1.0],
    );
    gl.materialfv(gl::FRONT_AND_BACK, gl::SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(gl::FRONT_AND_BACK, gl::SHININESS, 40.0);
}

fn style(q: &mut Quadric, draw: u32, normals: u32, orientation: u32, texture: bool) {
    glu::quadric_draw_style(q, draw);
    glu::quadric_normals(q, normals);
    glu::quadric_orientation(q, orientation);
    glu::quadric_texture(q, texture);
}

/// The `quadrics` scene.
pub fn quadrics(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.14, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.enable(gl::DEPTH_TEST);
    gl.enable(gl::LIGHTING);
    gl.enable(gl::LIGHT0);
    gl.shade_model(gl::SMOOTH);
    let img = checkerboard(64, 8, [240, 240, 240, 255], [200, 60, 40, 255]);
    gl.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        64,
        64,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&img),
    );
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    gl.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::MODULATE as i32);
    let mut q = glu::new_quadric();

    // Top row: sphere, cylinder (closed by two disks), cone with FLAT normals.
    panel(gl, 0);
    material(gl, [0.9, 0.7, 0.2]);
    glu::sphere(gl, &mut q, 1.0, 32, 24);
    panel(gl, 1);
    material(gl, [0.3, 0.6, 0.9]);
    gl.translatef(0.0, 0.0, -0.6);
    glu::cylinder(gl, &mut q, 0.7, 0.7, 1.4, 24, 4);
    style(
        &mut q,
        glu::GLU_FILL,
        glu::GLU_SMOOTH,
        glu::GLU_INSIDE,
        false,
    );
    glu::disk(gl, &mut q, 0.0, 0.7, 24, 2);
    gl.translatef(0.0, 0.0, 1.4);
    style(
        &mut q,
        glu::GLU_FILL,
        glu::GLU_SMOOTH,
        glu::GLU_OUTSIDE,
        false,
    );
    glu::disk(gl, &mut q, 0.0, 0.7, 24, 2);
    panel(gl, 2);
    material(gl, [0.5, 0.85, 0.4]);
    gl.translatef(0.0, 0.0, -0.6);
    style(
        &mut q,
        glu::GLU_FILL,
        glu::GLU_FLAT,
        glu::GLU_OUTSIDE,
        false,
    );
    glu::cylinder(gl, &mut q, 0.9, 0.0, 1.6, 16, 3);

    // Middle row: textured sphere and disk, a partial disk seen from both sides.
    gl.enable(gl::TEXTURE_2D);
    style(
        &mut q,
        glu::GLU_FILL,
        glu::GLU_SMOOTH,
        glu::GLU_OUTSIDE,
        true,
    );
    panel(gl, 3);
    material(gl, [1.0, 1.0, 1.0]);
    gl.rotatef(30.0, 0.0, 0.0, 1.0);
    glu::sphere(gl, &mut q, 1.0, 24, 16);
    panel(gl, 4);
    gl.rotatef(55.0, 1.0, 0.0, 0.0);
    glu::disk(gl, &mut q, 0.3, 1.1, 20, 4);
    gl.disable(gl::TEXTURE_2D);
    panel(gl, 5);
    gl.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1);
    gl.materialfv(gl::FRONT, gl::DIFFUSE, &[0.9, 0.4, 0.6, 1.0]);
    gl.materialfv(gl::BACK, gl::DIFFUSE, &[0.4, 0.5, 0.95, 1.0]);
    gl.rotatef(70.0, 1.0, 0.0, 0.0);
    gl.rotatef(25.0, 0.0, 1.0, 0.0);
    style(
        &mut q,
        glu::GLU_FILL,
        glu::GLU_SMOOTH,
        glu::GLU_INSIDE,
        false,
    );
    glu::partial_disk(gl, &mut q, 0.25, 1.1, 24, 3, 30.0, 250.0);
    gl.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 0);

    // Bottom row: wireframe sphere, cylinder silhouette, points.
    gl.disable(gl::LIGHTING);
    panel(gl, 6);
    gl.color3f(0.6, 0.9, 1.0);
    style(
        &mut q,
        glu::GLU_LINE,
        glu::GLU_NONE,
        glu::GLU_OUTSIDE,
        false,
    );
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    glu::sphere(gl, &mut q, 1.0, 18, 12);
    panel(gl, 7);
    gl.color3f(1.0, 0.8, 0.4);
    gl.line_width(2.0);
    style(
        &mut q,
        glu::GLU_SILHOUETTE,
        glu::GLU_NONE,
        glu::GLU_OUTSIDE,
        false,
    );
    gl.translatef(0.0, 0.0, -0.6);
    glu::cylinder(gl, &mut q, 0.8, 0.5, 1.3, 20, 5);
    gl.line_width(1.0);
    panel(gl, 8);
    gl.enable(gl::LIGHTING);
    material(gl, [0.95, 0.5, 0.3]);
    gl.point_size(3.0);
    style(
        &mut q,
        glu::GLU_POINT,
        glu::GLU_SMOOTH,
        glu::GLU_OUTSIDE,
        false,
    );
    gl.rotatef(50.0, 1.0, 0.0, 0.0);
    glu::partial_disk(gl, &mut q, 0.3, 1.2, 20, 5, -60.0, 300.0);
    gl.point_size(1.0);
}

/// The quadrics scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "quadrics",
    summary: "GLU quadrics: spheres, cylinders, cones, disks and a partial disk — lit SMOOTH and FLAT, textured, two-sided, wireframe, silhouette and points (gluSphere, gluCylinder, gluDisk, gluPartialDisk)",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: quadrics,
    animate: None,
}];
