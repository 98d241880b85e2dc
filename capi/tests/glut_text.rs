//! The independent check of `fixedgl::glut`'s bitmap fonts against the system's real freeglut:
//! `glut_text/freeglut_glyphs.c` draws every glyph (codes 1..=255) of the seven GLUT bitmap
//! fonts, and one multi-line `glutBitmapString` per font, with freeglut on Mesa (llvmpipe) under
//! a private Xvfb and writes the pixels and metrics it got; fixedgl draws the same with
//! `glut::bitmap_character`/`bitmap_string` on its CPU pipeline, and the two must agree pixel
//! for pixel, with the same `glutBitmapHeight`, `glutBitmapWidth` and raster advance.
//!
//! Known differences, listed below and nowhere else allowed: fixedgl's glyphs are generated from
//! the X11 fonts Debian ships (xfonts-base, xfonts-75dpi: the 1999 ISO 10646 revision of the
//! fonts), while freeglut's data was generated from the earlier X11R6 fonts. The revision
//! redrew some misc-fixed glyphs (B, D, E, F, 7, $, *, the accented vowels of 8x13 ...) and made
//! codes 39, 96 (and 45) ASCII's quotesingle, grave and hyphen instead of quoteright, quoteleft
//! and minus in the Adobe fonts; a few Adobe glyphs (Times 24 '/', Helvetica 12 'f', Helvetica
//! 10/18 'ï') were touched up. Those glyphs are checked to be drawn (same cell height, one
//! Bitmap call) but not compared.
//!
//! Skips (a `SKIPPED:` line) without Xvfb, a C compiler or freeglut's header, unless
//! FIXEDGL_REQUIRE_GL is set.

mod xsupport;

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use fixedgl::{gl, glut, Context};
use xsupport::{available, has_header, has_program, on, run, Gl, Xvfb};

const LIMIT: Duration = Duration::from_secs(120);
const W: usize = 48;
const H: usize = 40;
const SW: usize = 256;
const SH: usize = 64;
const STRING: &str = "Hello GLUT\nline two 0123";

/// The glyphs whose source fonts differ from freeglut's (see the module docs), per font in
/// `glut::BitmapFont::ALL` order.
const KNOWN_DIFFERENT: [&[u8]; 7] = [
    &[
        39, 42, 45, 66, 68, 96, 168, 207, 214, 217, 224, 225, 226, 227, 228, 232, 233, 234, 235,
        236, 237, 238, 239, 241, 242, 243, 244, 245, 246, 249, 250, 251, 252, 253, 255,
    ],
    &[36, 39, 42, 55, 66, 68, 69, 70, 96, 208],
    &[39, 45, 96],
    &[39, 45, 47, 96],
    &[39, 45, 96, 239],
    &[39, 45, 96, 102],
    &[39, 45, 96, 239],
];

/// Draws with fixedgl what the C program draws: `draw` at a cleared 256 x 64 window under a
/// pixel ortho projection, then the lower-left `w` x `h` as '0'/'1' (red > 127).
fn fixedgl_pixels(w: usize, h: usize, draw: impl FnOnce(&mut Context)) -> (String, f32) {
    let mut c = Context::new(SW as u32, SH as u32).expect("a context");
    c.viewport(0, 0, SW as i32, SH as i32);
    c.matrix_mode(gl::PROJECTION);
    c.load_identity();
    c.ortho(0.0, SW as f64, 0.0, SH as f64, -1.0, 1.0);
    c.matrix_mode(gl::MODELVIEW);
    c.load_identity();
    c.clear_color(0.0, 0.0, 0.0, 1.0);
    c.color3f(1.0, 1.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    draw(&mut c);
    let mut pos = [0f32; 4];
    c.get_floatv(gl::CURRENT_RASTER_POSITION, &mut pos);
    c.pixel_storei(gl::PACK_ALIGNMENT, 1);
    let mut px = vec![0u8; w * h * 4];
    c.read_pixels(
        0,
        0,
        w as i32,
        h as i32,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &mut px,
    );
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let bits = px
        .chunks(4)
        .map(|p| if p[0] > 127 { '1' } else { '0' })
        .collect();
    (bits, pos[0])
}

#[test]
fn bitmap_fonts_draw_as_freeglut_does() {
    if !available(has_program("cc"), "a C compiler (cc)")
        || !available(
            has_header("GL/freeglut.h"),
            "the header GL/freeglut.h (freeglut3-dev)",
        )
    {
        return;
    }
    let Some(x) = Xvfb::start() else { return };
    let dir = xsupport::profile_dir().join("glut-text");
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let exe = dir.join("freeglut_glyphs");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/glut_text/freeglut_glyphs.c");
    let mut cc = Command::new("cc");
    cc.args(["-O2", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&exe)
        .arg(&src)
        .args(["-lglut", "-lGL"]);
    run(cc, LIMIT);
    let out = dir.join("freeglut_glyphs.txt");
    let mut prog = on(Gl::Mesa, Command::new(&exe));
    prog.arg(&out).env("DISPLAY", &x.display);
    run(prog, LIMIT);
    let text = std::fs::read_to_string(&out).expect("the C program's output");

    let mut heights = HashMap::new();
    let (mut glyphs, mut strings, mut skipped) = (0, 0, 0);
    for line in text.lines() {
        let f: Vec<&str> = line.split(' ').collect();
        match f[0] {
            "H" => {
                heights.insert(f[1].to_string(), f[2].parse::<i32>().expect("height"));
            }
            "C" => {
                let i: usize = f[1].parse().expect("font");
                let code: u8 = f[2].parse().expect("code");
                let font = glut::BitmapFont::ALL[i];
                assert_eq!(
                    glut::bitmap_height(font),
                    heights[f[1]],
                    "{font:?} glutBitmapHeight"
                );
                if KNOWN_DIFFERENT[i].contains(&code) {
                    skipped += 1;
                    continue;
                }
                let width: i32 = f[3].parse().expect("width");
                let advance: f32 = f[4].parse().expect("advance");
                assert_eq!(
                    glut::bitmap_width(font, i32::from(code)),
                    width,
                    "{font:?} glutBitmapWidth({code})"
                );
                let (bits, x) = fixedgl_pixels(W, H, |c| {
                    c.raster_pos2f(4.5, 8.5);
                    glut::bitmap_character(c, font, i32::from(code));
                });
                assert_eq!(x - 4.5, advance, "{font:?} advance of {code}");
                if bits != f[5] {
                    panic!(
                        "{font:?} glyph {code} differs from freeglut's:\nfreeglut:\n{}\nfixedgl:\n{}",
                        picture(f[5], W),
                        picture(&bits, W)
                    );
                }
                glyphs += 1;
            }
            "S" => {
                let i: usize = f[1].parse().expect("font");
                let font = glut::BitmapFont::ALL[i];
                let (bits, _) = fixedgl_pixels(SW, SH, |c| {
                    c.raster_pos2f(4.5, 40.5);
                    glut::bitmap_string(c, font, STRING);
                });
                assert!(bits == f[2], "{font:?} glutBitmapString differs");
                strings += 1;
            }
            _ => panic!("unexpected line {line:?}"),
        }
    }
    assert_eq!(heights.len(), 7);
    assert_eq!(strings, 7);
    assert_eq!(glyphs + skipped, 7 * 255);
    eprintln!(
        "{glyphs} glyphs and {strings} strings as freeglut draws them; {skipped} known to differ"
    );
}

/// A '0'/'1' image as text, top row first, for a failure message.
fn picture(bits: &str, w: usize) -> String {
    let rows: Vec<&str> = (0..bits.len() / w)
        .map(|r| &bits[r * w..(r + 1) * w])
        .collect();
    rows.iter()
        .rev()
        .map(|r| r.replace('0', ".").replace('1', "#"))
        .collect::<Vec<_>>()
        .join("\n")
}
