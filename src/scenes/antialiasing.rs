//! `antialiasing`: smooth points, smooth lines and POLYGON_SMOOTH blended over a background
//! (GL 2.1 §3.3–3.5), as a particle or CAD exercise draws them (`gluOrtho2D`, 640x480).
//!
//! A two-colour background of bands; a row of smooth points of sizes 1 to 16 at whole,
//! half and fractional pixel positions (alpha 1 and 0.6); a fan of smooth lines of widths 1 to
//! 8 at many angles, smooth-shaded along them; a smooth LINE_LOOP; two POLYGON_SMOOTH
//! triangles. Blending SRC_ALPHA / ONE_MINUS_SRC_ALPHA, the hints NICEST. The coverage rule is
//! llvmpipe's (see `cpu::aa`).

use super::{Scene, LECTURE};
use crate::{gl, glu, Context};

fn background(gl: &mut Context) {
    gl.begin(gl::QUADS);
    for i in 0..8 {
        let (y0, y1) = (i as f32 * 60.0, (i + 1) as f32 * 60.0);
        if i % 2 == 0 {
            gl.color3f(0.15, 0.2, 0.3);
        } else {
            gl.color3f(0.3, 0.25, 0.15);
        }
        gl.vertex2f(0.0, y0);
        gl.vertex2f(640.0, y0);
        gl.color3f(0.1, 0.1, 0.12);
        gl.vertex2f(640.0, y1);
        gl.vertex2f(0.0, y1);
    }
    gl.end();
}

fn points(gl: &mut Context) {
    gl.enable(gl::POINT_SMOOTH);
    let sizes = [1.0f32, 1.5, 2.0, 3.0, 4.0, 5.5, 8.0, 11.0, 16.0];
    for (row, (alpha, dy)) in [(1.0f32, 0.0f32), (0.6, 0.5), (1.0, 0.3)]
        .iter()
        .enumerate()
    {
        let y = 420.0 + row as f32 * 22.0 + dy;
        for (i, &s) in sizes.iter().enumerate() {
            gl.point_size(s);
            gl.begin(gl::POINTS);
            gl.color4f(1.0, 0.9 - 0.08 * i as f32, 0.3 + 0.07 * i as f32, *alpha);
            gl.vertex2f(30.0 + i as f32 * 36.0 + 0.25 * row as f32, y);
            gl.end();
        }
    }
    // A scatter of size-6 particles at fractional positions.
    gl.point_size(6.0);
    gl.begin(gl::POINTS);
    for i in 0..40 {
        let t = i as f32 * 0.37;
        gl.color4f(0.4 + 0.5 * (t.sin() * 0.5 + 0.5), 0.8, 1.0, 0.8);
        gl.vertex2f(
            360.0 + 130.0 * (t * 1.3).cos() * (0.3 + 0.02 * i as f32),
            440.0 + 30.0 * t.sin(),
        );
    }
    gl.end();
    gl.disable(gl::POINT_SMOOTH);
}

fn lines(gl: &mut Context) {
    gl.enable(gl::LINE_SMOOTH);
    let widths = [1.0f32, 1.5, 2.0, 3.0, 5.0, 8.0];
    for (k, &w) in widths.iter().enumerate() {
        gl.line_width(w);
        let (cx, cy) = (60.0 + k as f32 * 100.0, 300.0);
        gl.begin(gl::LINES);
        for j in 0..7 {
            let a = (j as f32 * 26.0 + 3.0).to_radians();
            gl.color4f(1.0, 1.0, 1.0, 1.0);
            gl.vertex2f(cx + 0.3, cy + 0.2);
            gl.color4f(0.2 + 0.1 * j as f32, 0.9, 0.4, 0.7);
            gl.vertex2f(cx + 45.0 * a.cos(), cy + 80.0 * a.sin());
        }
        gl.end();
    }
    gl.line_width(2.5);
    gl.color4f(1.0, 0.5, 0.2, 0.9);
    gl.begin(gl::LINE_LOOP);
    for j in 0..9 {
        let a = (j as f32 * 40.0).to_radians();
        gl.vertex2f(520.0 + 60.0 * a.cos(), 110.0 + 60.0 * a.sin());
    }
    gl.end();
    gl.line_width(1.0);
    gl.disable(gl::LINE_SMOOTH);
}

fn polygons(gl: &mut Context) {
    gl.enable(gl::POLYGON_SMOOTH);
    gl.begin(gl::TRIANGLES);
    gl.color4f(0.9, 0.3, 0.3, 0.8);
    gl.vertex2f(40.3, 40.7);
    gl.color4f(0.3, 0.9, 0.3, 0.8);
    gl.vertex2f(220.6, 70.2);
    gl.color4f(0.3, 0.3, 0.9, 0.8);
    gl.vertex2f(110.1, 190.9);
    gl.color4f(1.0, 1.0, 0.4, 0.5);
    gl.vertex2f(180.2, 30.5);
    gl.vertex2f(400.8, 120.3);
    gl.vertex2f(250.4, 200.6);
    gl.end();
    gl.disable(gl::POLYGON_SMOOTH);
}

/// Draws the scene.
pub fn antialiasing(gl: &mut Context) {
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::ortho_2d(gl, 0.0, 640.0, 0.0, 480.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    gl.shade_model(gl::SMOOTH);
    background(gl);
    gl.hint(gl::POINT_SMOOTH_HINT, gl::NICEST);
    gl.hint(gl::LINE_SMOOTH_HINT, gl::NICEST);
    gl.hint(gl::POLYGON_SMOOTH_HINT, gl::NICEST);
    gl.enable(gl::BLEND);
    gl.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
    polygons(gl);
    lines(gl);
    points(gl);
    gl.disable(gl::BLEND);
}

/// The antialiasing scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "antialiasing",
    summary: "Antialiasing: smooth points of sizes 1 to 16, smooth lines of widths 1 to 8 and a smooth line loop, POLYGON_SMOOTH triangles, blended over a banded background with the hints NICEST (llvmpipe's coverage rule)",
    tolerance: LECTURE,
    default_size: (640, 480),
    draw: antialiasing,
    animate: None,
}];
