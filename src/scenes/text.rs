//! The GLUT text scene: `bitmap-text`, labels in every GLUT bitmap font over a lit teapot, as
//! lecture code annotates a 3D view with `glutBitmapString` at `glRasterPos` positions, and a
//! title and two lines in the GLUT stroke fonts (`glutStrokeCharacter`, `glutStrokeString`).
//!
//! What it exercises: Bitmap under freeglut's pushed/tight unpack modes, the raster position
//! through perspective (a label attached to the teapot) and through a pixel-aligned ortho
//! projection, glyphs partly outside the window (the raster position valid, the cells clipped
//! at the right and bottom edges), one label whose raster position falls outside the view volume
//! (invalid: nothing of it draws, and its glyphs do not move the raster position), multi-line
//! strings, and the raster colour taken from the current colour when the raster position is set;
//! stroke glyphs as line strips under a scaled (and, for Mono Roman, rotated) modelview matrix,
//! with glutStrokeString's newline translation.
//!
//! Design decision: the ortho labels sit at half-pixel raster positions, so the floor in
//! Bitmap's placement (§3.7) never lands on a tie where the CPU pipeline and llvmpipe could round
//! apart; the perspective label's position is a plain float whichever way it lands, since both
//! floor the same transformed value. The stroke text is translated to a quarter-pixel offset for
//! the same reason: line endpoints off the half-pixel grid keep the diamond-exit rule away from
//! ties.

use crate::gl::*;
use crate::{glu, glut, Context};

use super::{Scene, LECTURE};

/// The scene's entry.
pub const SCENES: [Scene; 1] = [Scene {
    name: "bitmap-text",
    summary: "GLUT text: labels in the seven GLUT bitmap fonts over a lit teapot (glutBitmapString at RasterPos), glyphs clipped at the window edges, a label at an invalid raster position that draws nothing, a stroke-font title (Roman) and two rotated lines of Mono Roman",
    tolerance: LECTURE,
    default_size: (640, 480),
    draw: bitmap_text,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

/// Draws the scene (the framebuffer is assumed 640 x 480, as the default size; other sizes
/// draw the same calls).
fn bitmap_text(gl: &mut Context) {
    let (w, h) = (640.0f32, 480.0f32);
    gl.clear_color(0.08, 0.09, 0.14, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, f64::from(w / h), 1.0, 30.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 1.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &[1.0, 2.0, 3.0, 0.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.enable(NORMALIZE);
    gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &[0.85, 0.55, 0.2, 1.0]);
    gl.materialfv(FRONT, SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(FRONT, SHININESS, 40.0);
    gl.push_matrix();
    gl.rotatef(-30.0, 0.0, 1.0, 0.0);
    glut::solid_teapot(gl, 1.2);
    gl.pop_matrix();

    // A label pinned to the teapot's spout through the perspective projection, depth-tested
    // off so the text reads over the surface.
    gl.disable(LIGHTING);
    gl.disable(DEPTH_TEST);
    gl.color3f(1.0, 1.0, 0.4);
    gl.raster_pos3f(1.9, 0.55, 0.3);
    glut::bitmap_string(gl, glut::BITMAP_HELVETICA_12, "<- spout");

    // A label whose raster position is behind the eye: invalid, so none of it draws.
    gl.color3f(1.0, 0.0, 0.0);
    gl.raster_pos3f(0.0, 0.0, 9.0);
    glut::bitmap_string(gl, glut::BITMAP_TIMES_ROMAN_24, "INVISIBLE");

    // Pixel-aligned labels: an ortho projection one unit a pixel.
    gl.matrix_mode(PROJECTION);
    gl.push_matrix();
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(MODELVIEW);
    gl.push_matrix();
    gl.load_identity();

    let labels: [(glut::BitmapFont, &str, [f32; 3]); 7] = [
        (
            glut::BITMAP_TIMES_ROMAN_24,
            "Times Roman 24: GLUT text",
            [1.0, 1.0, 1.0],
        ),
        (
            glut::BITMAP_HELVETICA_18,
            "Helvetica 18: glutBitmapString",
            [0.6, 0.9, 1.0],
        ),
        (
            glut::BITMAP_HELVETICA_12,
            "Helvetica 12: the quick brown fox jumps",
            [0.7, 1.0, 0.7],
        ),
        (
            glut::BITMAP_HELVETICA_10,
            "Helvetica 10: over the lazy dog (0123456789)",
            [1.0, 0.8, 0.8],
        ),
        (
            glut::BITMAP_TIMES_ROMAN_10,
            "Times Roman 10: ÀÉÎÕÜ àéîõü ß ©®±µ",
            [0.9, 0.9, 0.6],
        ),
        (
            glut::BITMAP_9_BY_15,
            "9x15: fixed {}[]<>|~",
            [0.8, 0.7, 1.0],
        ),
        (
            glut::BITMAP_8_BY_13,
            "8x13: fixed !@#$%^&*()_+",
            [1.0, 0.7, 0.4],
        ),
    ];
    let mut y = h - 30.5;
    for (font, text, [r, g, b]) in labels {
        gl.color3f(r, g, b);
        gl.raster_pos2f(10.5, y);
        glut::bitmap_string(gl, font, text);
        y -= glut::bitmap_height(font) as f32 + 4.0;
    }

    // A two-line string: the newline returns to the line's start one cell lower.
    gl.color3f(0.5, 1.0, 1.0);
    gl.raster_pos2f(10.5, 150.5);
    glut::bitmap_string(
        gl,
        glut::BITMAP_9_BY_15,
        "two lines:\n  via glutBitmapString",
    );

    // Clipped at the right edge: the position is inside, the glyphs run out of the window.
    gl.color3f(1.0, 0.5, 1.0);
    let text = "clipped at the right edge";
    let len = glut::bitmap_length(glut::BITMAP_HELVETICA_18, text) as f32;
    gl.raster_pos2f(w - len * 0.5 + 0.5, 60.5);
    glut::bitmap_string(gl, glut::BITMAP_HELVETICA_18, text);

    // Clipped at the bottom edge: descenders and the cell's lower rows fall below row 0.
    gl.color3f(0.4, 1.0, 0.4);
    gl.raster_pos2f(10.5, 1.5);
    glut::bitmap_string(gl, glut::BITMAP_TIMES_ROMAN_24, "jpqgy below the bottom");

    // Characters one at a time, as glutBitmapCharacter loops do, ending past the top edge.
    gl.color3f(1.0, 1.0, 1.0);
    gl.raster_pos2f(w - 150.5, h - 8.5);
    for c in "Top edge: Ag".chars() {
        glut::bitmap_character(gl, glut::BITMAP_HELVETICA_18, c as i32);
    }

    // The stroke-font title, centred with glutStrokeLength, as lecture code scales and
    // translates glutStrokeCharacter's 152-unit glyphs into place.
    let title = "GLUT stroke title";
    let scale = 0.25f32;
    let len = glut::stroke_length(glut::STROKE_ROMAN, title) as f32 * scale;
    gl.color3f(1.0, 0.85, 0.3);
    gl.push_matrix();
    gl.translatef(((w - len) * 0.5).floor() + 0.25, 95.25, 0.0);
    gl.scalef(scale, scale, 1.0);
    for c in title.chars() {
        glut::stroke_character(gl, glut::STROKE_ROMAN, c as i32);
    }
    gl.pop_matrix();

    // Two lines of Mono Roman through glutStrokeString (the newline steps back and down by
    // the font's height), turned a little so the strokes meet the pixel grid at odd angles.
    gl.color3f(0.6, 1.0, 0.8);
    gl.push_matrix();
    gl.translatef(478.25, 152.25, 0.0);
    gl.rotatef(8.0, 0.0, 0.0, 1.0);
    gl.scalef(0.12, 0.12, 1.0);
    glut::stroke_string(gl, glut::STROKE_MONO_ROMAN, "Mono Roman\n0123 !?{}");
    gl.pop_matrix();

    gl.pop_matrix();
    gl.matrix_mode(PROJECTION);
    gl.pop_matrix();
    gl.matrix_mode(MODELVIEW);
}
