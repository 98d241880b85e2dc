//! `stipple`: the Red Book's `lines.c` and `polys.c` (chapter 2) on one 800x800 page, with more
//! patterns, factors, widths and directions, drawn in window coordinates (`gluOrtho2D`).
//!
//! Top half: dashed lines — patterns 0x0101 (dotted), 0x00FF (dashed), 0x1C47 (dash/dot/dash) at
//! widths 1 and 5; factors 1 to 6; a line strip whose pattern runs on across its vertices; the
//! same points as separate LINES, where it restarts at every segment; diagonal and steep lines
//! with colour along them; a LINE_LOOP. Bottom half: a rectangle filled plain beside the Red
//! Book's fly and halftone polygon stipples, and a smooth-shaded triangle and a lit disk under a
//! third pattern: the pattern is aligned to the window, not to the polygon.

use super::{Scene, LECTURE};
use crate::{gl, glu, Context};

/// The Red Book's fly (polys.c), 32 rows of 4 bytes, bottom row first.
#[rustfmt::skip]
pub const FLY: [u8; 128] = [
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x03, 0x80, 0x01, 0xC0, 0x06, 0xC0, 0x03, 0x60,
    0x04, 0x60, 0x06, 0x20, 0x04, 0x30, 0x0C, 0x20,
    0x04, 0x18, 0x18, 0x20, 0x04, 0x0C, 0x30, 0x20,
    0x04, 0x06, 0x60, 0x20, 0x44, 0x03, 0xC0, 0x22,
    0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22,
    0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22,
    0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22,
    0x66, 0x01, 0x80, 0x66, 0x33, 0x01, 0x80, 0xCC,
    0x19, 0x81, 0x81, 0x98, 0x0C, 0xC1, 0x83, 0x30,
    0x07, 0xe1, 0x87, 0xe0, 0x03, 0x3f, 0xfc, 0xc0,
    0x03, 0x31, 0x8c, 0xc0, 0x03, 0x33, 0xcc, 0xc0,
    0x06, 0x64, 0x26, 0x60, 0x0c, 0xcc, 0x33, 0x30,
    0x18, 0xcc, 0x33, 0x18, 0x10, 0xc4, 0x23, 0x08,
    0x10, 0x63, 0xC6, 0x08, 0x10, 0x30, 0x0c, 0x08,
    0x10, 0x18, 0x18, 0x08, 0x10, 0x00, 0x00, 0x08,
];

/// The Red Book's halftone (polys.c): alternate pixels in alternate pairs of rows.
pub fn halftone() -> [u8; 128] {
    let mut h = [0u8; 128];
    for (i, b) in h.iter_mut().enumerate() {
        *b = if (i / 4) % 2 == 0 { 0xAA } else { 0x55 };
    }
    h
}

/// A diagonal weave: bit (x + 2y) mod 7 < 3, for the triangle and the disk.
fn weave() -> [u8; 128] {
    let mut w = [0u8; 128];
    for y in 0..32 {
        for x in 0..32 {
            if (x + 2 * y) % 7 < 3 {
                w[y * 4 + x / 8] |= 0x80 >> (x % 8);
            }
        }
    }
    w
}

fn rect(gl: &mut Context, x1: f32, y1: f32, x2: f32, y2: f32) {
    gl.begin(gl::QUADS);
    gl.vertex2f(x1, y1);
    gl.vertex2f(x2, y1);
    gl.vertex2f(x2, y2);
    gl.vertex2f(x1, y2);
    gl.end();
}

fn line(gl: &mut Context, x1: f32, y1: f32, x2: f32, y2: f32) {
    gl.begin(gl::LINES);
    gl.vertex2f(x1, y1);
    gl.vertex2f(x2, y2);
    gl.end();
}

/// The `stipple` scene.
pub fn stipple(gl: &mut Context) {
    let (w, h) = gl.size();
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::ortho_2d(gl, 0.0, f64::from(w), 0.0, f64::from(h));
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    // Everything below is laid out for 800x800.
    gl.scalef(w as f32 / 800.0, h as f32 / 800.0, 1.0);
    gl.shade_model(gl::SMOOTH);

    // lines.c, first row: three patterns, width 1.
    gl.enable(gl::LINE_STIPPLE);
    gl.color3f(1.0, 1.0, 1.0);
    for (i, pattern) in [0x0101u16, 0x00FF, 0x1C47].into_iter().enumerate() {
        gl.line_stipple(1, pattern);
        let x = 40.0 + 250.0 * i as f32;
        line(gl, x, 760.0, x + 220.0, 760.0);
    }
    // Second row: the same, width 5.
    gl.line_width(5.0);
    gl.color3f(1.0, 0.8, 0.3);
    for (i, pattern) in [0x0101u16, 0x00FF, 0x1C47].into_iter().enumerate() {
        gl.line_stipple(1, pattern);
        let x = 40.0 + 250.0 * i as f32;
        line(gl, x, 730.0, x + 220.0, 730.0);
    }
    gl.line_width(1.0);
    // Third row: a strip of seven segments, the pattern running on (lines.c's line strip).
    gl.color3f(0.4, 1.0, 0.5);
    gl.line_stipple(1, 0x1C47);
    gl.begin(gl::LINE_STRIP);
    for i in 0..8 {
        gl.vertex2f(40.0 + i as f32 * 100.0, 700.0);
    }
    gl.end();
    // Fourth row: the same points as separate lines, restarting at each.
    gl.begin(gl::LINES);
    for i in 0..7 {
        gl.vertex2f(40.0 + i as f32 * 100.0, 680.0);
        gl.vertex2f(40.0 + (i + 1) as f32 * 100.0, 680.0);
    }
    gl.end();
    // Factors 1 to 6 of one pattern, colour changing along each line.
    gl.line_width(2.0);
    for f in 1..=6 {
        gl.line_stipple(f, 0x0F3F);
        let y = 650.0 - 14.0 * f as f32;
        gl.begin(gl::LINES);
        gl.color3f(1.0, 0.2, 0.2);
        gl.vertex2f(40.0, y);
        gl.color3f(0.2, 0.4, 1.0);
        gl.vertex2f(760.0, y);
        gl.end();
    }
    gl.line_width(1.0);
    // Diagonal and steep lines, off the pixel grid, thin and wide: a fan of twelve.
    for k in 0..12 {
        let a = k as f32 * std::f32::consts::PI / 12.0 + 0.13;
        let (cx, cy) = (200.3, 400.6);
        gl.line_width(if k % 2 == 0 { 1.0 } else { 3.0 });
        gl.line_stipple(
            1 + k % 3,
            [0xAAAA, 0x33FF, 0x0F0F, 0x5F5F][(k % 4) as usize],
        );
        gl.begin(gl::LINES);
        gl.color3f(1.0, 1.0, 0.2);
        gl.vertex2f(cx + 25.0 * a.cos(), cy + 25.0 * a.sin());
        gl.color3f(0.2, 1.0, 1.0);
        gl.vertex2f(cx + 140.0 * a.cos(), cy + 140.0 * a.sin());
        gl.end();
    }
    gl.line_width(1.0);
    // A loop: a star, the pattern running round it and on through the closing segment.
    gl.line_stipple(2, 0x3F07);
    gl.color3f(0.9, 0.5, 1.0);
    gl.begin(gl::LINE_LOOP);
    for k in 0..5 {
        let a = std::f32::consts::FRAC_PI_2 + k as f32 * 4.0 * std::f32::consts::PI / 5.0;
        gl.vertex2f(560.2 + 130.0 * a.cos(), 470.3 + 130.0 * a.sin());
    }
    gl.end();
    gl.disable(gl::LINE_STIPPLE);

    // polys.c: a plain rectangle, the fly, the halftone.
    gl.color3f(1.0, 1.0, 1.0);
    rect(gl, 25.0, 200.0, 225.0, 320.0);
    gl.enable(gl::POLYGON_STIPPLE);
    gl.polygon_stipple(&FLY);
    rect(gl, 275.0, 200.0, 475.0, 320.0);
    gl.polygon_stipple(&halftone());
    rect(gl, 525.0, 200.0, 725.0, 320.0);
    // A shaded triangle and a lit disk under the weave.
    gl.polygon_stipple(&weave());
    gl.begin(gl::TRIANGLES);
    gl.color3f(1.0, 0.0, 0.0);
    gl.vertex2f(40.0, 20.0);
    gl.color3f(0.0, 1.0, 0.0);
    gl.vertex2f(360.0, 40.0);
    gl.color3f(0.0, 0.0, 1.0);
    gl.vertex2f(180.0, 180.0);
    gl.end();
    gl.enable(gl::LIGHTING);
    gl.enable(gl::LIGHT0);
    gl.lightfv(gl::LIGHT0, gl::POSITION, &[0.3, 0.5, 1.0, 0.0]);
    gl.materialfv(gl::FRONT, gl::DIFFUSE, &[0.3, 0.7, 1.0, 1.0]);
    gl.begin(gl::TRIANGLE_FAN);
    gl.normal3f(0.0, 0.0, 1.0);
    gl.vertex2f(560.0, 100.0);
    for k in 0..=48 {
        let a = k as f32 * std::f32::consts::TAU / 48.0;
        gl.normal3f(0.6 * a.cos(), 0.6 * a.sin(), 0.8);
        gl.vertex2f(560.0 + 90.0 * a.cos(), 100.0 + 90.0 * a.sin());
    }
    gl.end();
    gl.disable(gl::LIGHTING);
    gl.disable(gl::POLYGON_STIPPLE);
}

/// The stipple scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "stipple",
    summary: "Stipple: the Red Book's lines.c and polys.c — dashed lines of several patterns and factors, thin and wide, strips running on and LINES restarting; fly and halftone polygon stipples aligned to the window (LineStipple, PolygonStipple)",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: stipple,
    animate: None,
}];
