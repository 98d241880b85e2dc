//! The pixel-rectangle scene (GL 2.1 §3.6, §3.7, §4.3): `draw-pixels`, the image-processing lab
//! of a graphics course done with the fixed-function pixel path. One procedural photograph is
//! drawn with DrawPixels as it is, mirrored and flipped by negative zooms, enlarged and resampled
//! by positive ones, through scale and bias, and through colour maps; an indexed image takes
//! its colours from the I_TO_R/G/B/A maps; a depth image meets a tilted plane under the depth
//! test; CopyPixels copies a region of the finished picture, mirrored and enlarged; Bitmap
//! writes the labels in a small 5x7 font.
//!
//! Design decision: everything is placed so that the CPU pipeline and llvmpipe agree pixel for
//! pixel where GL 2.1 and the driver agree: raster positions are whole pixels, vertical zooms
//! span whole pixels, the horizontal ones never put a pixel centre on a group boundary (4/3 has
//! an odd denominator), the scale and bias never land on a rounding tie of the 8-bit conversion
//! (checked by a test below), and the colour maps are written to red and green only (llvmpipe
//! gets blue and alpha wrong under MAP_COLOR; docs/conformance.md).

use crate::gl::*;
use crate::Context;

use super::{Scene, LECTURE};

/// The scene's entry.
pub const SCENES: [Scene; 1] = [Scene {
    name: "draw-pixels",
    summary: "Pixel rectangles: image processing — a procedural photo drawn with DrawPixels as it is, zoomed (2x, 4/3 x 2/3, mirrored and flipped by negative zooms), through scale and bias and colour maps, an indexed image through I_TO_RGBA maps, a depth image against a tilted plane, CopyPixels of a region, Bitmap labels",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: draw_pixels,
    animate: None,
}];

/// The photograph's size.
const W: i32 = 160;
const H: i32 = 120;

/// Red scale, green scale, blue scale and the biases of the "warm" panel.
pub const SCALE: [f32; 4] = [0.857, 0.7, 0.45, 1.0];
/// See [`SCALE`].
pub const BIAS: [f32; 4] = [0.153, 0.09, 0.005, 0.0];

/// A procedural photograph, `W` x `H` RGBA8 bytes, rows bottom-up: a sky gradient, a sun, hills
/// and a striped field.
pub fn photo() -> Vec<u8> {
    let mut v = Vec::with_capacity((W * H * 4) as usize);
    for j in 0..H {
        for i in 0..W {
            let (x, y) = (i as f32 / W as f32, j as f32 / H as f32);
            let hill = 0.35 + 0.08 * (x * 9.0).sin() + 0.05 * (x * 23.0 + 1.0).cos();
            let sun = ((x - 0.72).powi(2) + (y - 0.75).powi(2)).sqrt();
            let c = if y < hill {
                let stripe = ((x * 40.0 + y * 25.0).sin() * 0.5 + 0.5) * 0.3;
                [
                    0.15 + stripe,
                    0.45 + 0.4 * y + stripe * 0.5,
                    0.1 + 0.2 * x,
                    1.0,
                ]
            } else if sun < 0.09 {
                [1.0, 0.85, 0.3 + sun * 2.0, 1.0]
            } else {
                [0.35 + 0.3 * y, 0.55 + 0.35 * y, 0.95, 0.6 + 0.4 * x]
            };
            v.extend(c.map(|k: f32| (k.clamp(0.0, 1.0) * 255.0).round() as u8));
        }
    }
    v
}

/// A 96x72 indexed image: escape counts of the quadratic map z² + c over a window of the plane,
/// one byte per group.
fn fractal() -> Vec<u8> {
    let (w, h) = (96, 72);
    let mut v = Vec::with_capacity(w * h);
    for j in 0..h {
        for i in 0..w {
            let (cr, ci) = (
                -2.1 + 2.8 * i as f64 / w as f64,
                -1.05 + 2.1 * j as f64 / h as f64,
            );
            let (mut zr, mut zi, mut n) = (0.0f64, 0.0f64, 0u8);
            while n < 63 && zr * zr + zi * zi < 4.0 {
                let t = zr * zr - zi * zi + cr;
                zi = 2.0 * zr * zi + ci;
                zr = t;
                n += 1;
            }
            v.push(n);
        }
    }
    v
}

/// A 128x128 depth image (FLOAT): a dome, window depth 0.95 at its rim rising towards the
/// viewer (0.15) at its centre, with 1.0 (nothing) outside it.
fn dome() -> Vec<u8> {
    let n = 128;
    let mut v = Vec::with_capacity(n * n * 4);
    for j in 0..n {
        for i in 0..n {
            let (x, y) = (
                (i as f32 + 0.5) / n as f32 * 2.0 - 1.0,
                (j as f32 + 0.5) / n as f32 * 2.0 - 1.0,
            );
            let r2 = x * x + y * y;
            let d = if r2 < 1.0 {
                0.95 - 0.8 * (1.0 - r2).sqrt()
            } else {
                1.0
            };
            v.extend_from_slice(&d.to_ne_bytes());
        }
    }
    v
}

/// A 5x7 font for the labels: each glyph seven rows of five bits, top row first.
fn glyph(c: char) -> [u8; 7] {
    match c {
        'A' => [0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11],
        'B' => [0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E],
        'C' => [0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E],
        'D' => [0x1E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1E],
        'E' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F],
        'F' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10],
        'H' => [0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11],
        'I' => [0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E],
        'L' => [0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F],
        'M' => [0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11],
        'N' => [0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x11],
        'O' => [0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E],
        'P' => [0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10],
        'R' => [0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11],
        'S' => [0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E],
        'T' => [0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04],
        'W' => [0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A],
        'X' => [0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11],
        'Y' => [0x11, 0x11, 0x0A, 0x04, 0x04, 0x04, 0x04],
        'Z' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F],
        '1' => [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
        '2' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
        '3' => [0x1E, 0x01, 0x01, 0x0E, 0x01, 0x01, 0x1E],
        '4' => [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
        '/' => [0x01, 0x01, 0x02, 0x04, 0x08, 0x10, 0x10],
        '-' => [0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00],
        _ => [0; 7],
    }
}

/// Writes `text` with Bitmap from window position (x, y), each glyph 5x7 bits in a byte per row
/// (most significant bits), advancing 6 pixels (GLUT's way: the bitmaps move the raster
/// position). The font is drawn doubled: each glyph twice, one pixel apart, for weight.
fn label(gl: &mut Context, x: i32, y: i32, text: &str) {
    gl.window_pos2i(x, y);
    for c in text.chars() {
        // Rows bottom-up, each glyph row shifted to the byte's top bits.
        let rows: Vec<u8> = glyph(c).iter().rev().map(|r| r << 3).collect();
        gl.bitmap(5, 7, 0.0, 0.0, 1.0, 0.0, Some(&rows));
        gl.bitmap(5, 7, 0.0, 0.0, 5.0, 0.0, Some(&rows));
    }
}

/// `draw-pixels` (800x800).
pub fn draw_pixels(gl: &mut Context) {
    let img = photo();
    gl.clear_color(0.12, 0.12, 0.14, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 800.0, 0.0, 800.0, -1.0, 1.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    gl.pixel_storei(UNPACK_ALIGNMENT, 1);

    // Top row: as it is; mirrored (zoom −1, 1); flipped (zoom 1, −1); resampled by 4/3 x 2/3.
    gl.raster_pos2i(20, 650);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pixel_zoom(-1.0, 1.0);
    gl.raster_pos2i(360, 650);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pixel_zoom(1.0, -1.0);
    gl.window_pos2i(380, 770);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pixel_zoom(4.0 / 3.0, 2.0 / 3.0);
    gl.window_pos2i(562, 670);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);

    // Middle row: 2x; warm tones by scale and bias; colour maps on red and green.
    gl.pixel_zoom(2.0, 2.0);
    gl.window_pos2i(20, 370);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pixel_zoom(1.0, 1.0);
    gl.push_attrib(PIXEL_MODE_BIT);
    for k in 0..4 {
        gl.pixel_transferf(
            [RED_SCALE, GREEN_SCALE, BLUE_SCALE, ALPHA_SCALE][k],
            SCALE[k],
        );
        gl.pixel_transferf([RED_BIAS, GREEN_BIAS, BLUE_BIAS, ALPHA_BIAS][k], BIAS[k]);
    }
    gl.window_pos2i(370, 490);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pop_attrib();
    // Posterised red (4 levels), inverted green: drawn over the image itself, red and green
    // only, so blue and alpha stay the photo's.
    let posterise: Vec<f32> = (0..256).map(|k| ((k / 64) as f32) / 3.0).collect();
    let invert: Vec<u16> = (0..256).map(|k| 65535 - k * 257).collect();
    gl.pixel_mapfv(PIXEL_MAP_R_TO_R, 256, &posterise);
    gl.pixel_mapusv(PIXEL_MAP_G_TO_G, 256, &invert);
    gl.window_pos2i(370, 370);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.pixel_transferi(MAP_COLOR, 1);
    gl.color_mask(true, true, false, false);
    gl.draw_pixels(W, H, RGBA, UNSIGNED_BYTE, &img);
    gl.color_mask(true, true, true, true);
    gl.pixel_transferi(MAP_COLOR, 0);

    // The indexed image: 64 escape counts through a palette of I_TO_R/G/B/A maps, 2x.
    let n = 64usize;
    let pal = |f: &dyn Fn(f32) -> f32| -> Vec<f32> {
        (0..n).map(|i| f(i as f32 / (n - 1) as f32)).collect()
    };
    gl.pixel_mapfv(PIXEL_MAP_I_TO_R, n as i32, &pal(&|t| (3.0 * t).min(1.0)));
    gl.pixel_mapfv(
        PIXEL_MAP_I_TO_G,
        n as i32,
        &pal(&|t| (3.0 * t - 1.0).clamp(0.0, 1.0)),
    );
    gl.pixel_mapfv(PIXEL_MAP_I_TO_B, n as i32, &pal(&|t| (0.3 + t).min(1.0)));
    gl.pixel_mapfv(PIXEL_MAP_I_TO_A, 1, &[1.0]);
    gl.pixel_zoom(2.0, 2.0);
    gl.window_pos2i(560, 380);
    gl.draw_pixels(96, 72, COLOR_INDEX, UNSIGNED_BYTE, &fractal());
    gl.pixel_zoom(1.0, 1.0);

    // Bottom left: a tilted, shaded plane, then a depth image drawn in orange against it under
    // the depth test: the dome shows where it is nearer than the plane.
    gl.enable(DEPTH_TEST);
    gl.begin(QUADS);
    gl.color3f(0.2, 0.3, 0.6);
    gl.vertex3f(20.0, 40.0, 0.9);
    gl.color3f(0.3, 0.6, 0.8);
    gl.vertex3f(300.0, 40.0, 0.9);
    gl.color3f(0.5, 0.8, 0.9);
    gl.vertex3f(300.0, 320.0, -0.9);
    gl.color3f(0.3, 0.4, 0.7);
    gl.vertex3f(20.0, 320.0, -0.9);
    gl.end();
    gl.color3f(1.0, 0.55, 0.1);
    gl.window_pos2i(96, 116);
    gl.draw_pixels(128, 128, DEPTH_COMPONENT, FLOAT, &dome());
    gl.disable(DEPTH_TEST);

    // CopyPixels: the lower left quarter of the depth panel, mirrored both ways and enlarged.
    gl.pixel_zoom(-2.0, -2.0);
    gl.window_pos2i(700, 340);
    gl.copy_pixels(100, 120, 150, 130, COLOR);
    gl.pixel_zoom(1.0, 1.0);

    // Labels.
    gl.color3f(1.0, 1.0, 0.6);
    label(gl, 20, 780, "DRAWPIXELS");
    label(gl, 200, 780, "ZOOM -1 1");
    label(gl, 380, 780, "ZOOM 1 -1");
    label(gl, 562, 760, "ZOOM 4/3 2/3");
    label(gl, 20, 615, "ZOOM 2 2");
    label(gl, 370, 615, "SCALE BIAS");
    label(gl, 370, 350, "MAP COLOR");
    label(gl, 560, 530, "COLOR INDEX");
    label(gl, 20, 20, "DEPTH");
    label(gl, 400, 20, "COPYPIXELS -2 -2");
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scale and bias panel matches the driver only where c·scale + bias never falls on a
    /// half of the 8-bit scale (the driver's arithmetic there differs in the last bit).
    #[test]
    fn scale_and_bias_stay_clear_of_rounding_ties() {
        for k in 0..4 {
            if SCALE[k] == 1.0 && BIAS[k] == 0.0 {
                continue;
            }
            for v in 0..=255u8 {
                let c = f64::from(f32::from(v) / 255.0 * SCALE[k] + BIAS[k]) * 255.0;
                let frac = c - c.floor();
                assert!(
                    (frac - 0.5).abs() > 0.02,
                    "component {k}, byte {v}: {c} is within 0.02 of a tie"
                );
            }
        }
    }

    #[test]
    fn the_images_have_their_sizes() {
        assert_eq!(photo().len(), (W * H * 4) as usize);
        assert_eq!(fractal().len(), 96 * 72);
        assert_eq!(dome().len(), 128 * 128 * 4);
    }
}
