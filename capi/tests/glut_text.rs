//! The independent check of `fixedgl::glut`'s fonts against the system's real freeglut:
//! `glut_text/freeglut_glyphs.c` draws every code 1..=255 of the seven GLUT bitmap fonts and the
//! two stroke fonts (each glyph alone; stroke glyphs scaled by 1/4), one multi-line
//! `glutBitmapString` per bitmap font and one scaled `glutStrokeString` per stroke font, with
//! freeglut on Mesa (llvmpipe) under a private Xvfb, and writes the pixels and metrics it got;
//! fixedgl draws the same with `glut::bitmap_*`/`glut::stroke_*` on its CPU pipeline, and the
//! two must agree pixel for pixel, with the same `glutBitmapHeight`, `glutBitmapWidth`, raster
//! advance, `glutStrokeHeight`, `glutStrokeWidth[f]`, `glutStrokeLength[f]` and modelview
//! advance (float for float).
//!
//! fixedgl's glyph data is generated from the calls this same freeglut issues
//! (tools/gen_glut_fonts.py), so the glyph data is not independent of the check; what the check
//! holds independently is everything between the data and the pixels: the cell layout, unpack
//! modes, raster advance, strip order, translation and line rasterisation, against the driver.
//!
//! Skips (a `SKIPPED:` line) without Xvfb, a C compiler or freeglut's header, unless
//! FIXEDGL_REQUIRE_GL is set.

mod xsupport;

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::sync::OnceLock;
use std::time::Duration;

use fixedgl::{gl, glut, Context};
use xsupport::{available, has_header, has_program, on, run, Gl, Xvfb};

const LIMIT: Duration = Duration::from_secs(120);
const W: usize = 48;
const H: usize = 40;
const SW: usize = 256;
const SH: usize = 64;
const STRING: &str = "Hello GLUT\nline two 0123";
const STX: f32 = 4.25;
const STY: f32 = 10.25;
const SCALE: f32 = 0.25;
const SSCALE: f32 = 0.125;

/// Draws with fixedgl what the C program draws: `draw` at a cleared 256 x 64 window under a
/// pixel ortho projection, then the lower-left `w` x `h` as '0'/'1' (red > 127), the raster
/// position's x and the modelview matrix's x translation.
fn fixedgl_pixels(w: usize, h: usize, draw: impl FnOnce(&mut Context)) -> (String, f32, f32) {
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
    let mut m = [0f32; 16];
    c.get_floatv(gl::MODELVIEW_MATRIX, &mut m);
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
    (bits, pos[0], m[12])
}

/// The C program's output (built and run once for both tests), or `None` for a skip.
fn freeglut_output() -> Option<&'static str> {
    static OUT: OnceLock<Option<String>> = OnceLock::new();
    OUT.get_or_init(|| {
        if !available(has_program("cc"), "a C compiler (cc)")
            || !available(
                has_header("GL/freeglut.h"),
                "the header GL/freeglut.h (freeglut3-dev)",
            )
        {
            return None;
        }
        let x = Xvfb::start()?;
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
        Some(std::fs::read_to_string(&out).expect("the C program's output"))
    })
    .as_deref()
}

/// A float the C program wrote as its bits in hex.
fn float_bits(s: &str) -> f32 {
    f32::from_bits(u32::from_str_radix(s, 16).expect("float bits"))
}

#[test]
fn bitmap_fonts_draw_as_freeglut_does() {
    let Some(text) = freeglut_output() else {
        return;
    };
    let mut heights = HashMap::new();
    let (mut glyphs, mut strings) = (0, 0);
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
                let width: i32 = f[3].parse().expect("width");
                let advance: f32 = f[4].parse().expect("advance");
                assert_eq!(
                    glut::bitmap_width(font, i32::from(code)),
                    width,
                    "{font:?} glutBitmapWidth({code})"
                );
                let (bits, x, _) = fixedgl_pixels(W, H, |c| {
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
                let (bits, _, _) = fixedgl_pixels(SW, SH, |c| {
                    c.raster_pos2f(4.5, 40.5);
                    glut::bitmap_string(c, font, STRING);
                });
                assert!(bits == f[2], "{font:?} glutBitmapString differs");
                strings += 1;
            }
            _ => {}
        }
    }
    assert_eq!(heights.len(), 7);
    assert_eq!(strings, 7);
    assert_eq!(glyphs, 7 * 255);
    eprintln!("{glyphs} glyphs and {strings} strings as freeglut draws them");
}

#[test]
fn stroke_fonts_draw_as_freeglut_does() {
    let Some(text) = freeglut_output() else {
        return;
    };
    let (mut heights, mut glyphs, mut drawn, mut lengths, mut strings) = (0, 0, 0, 0, 0);
    for line in text.lines() {
        let f: Vec<&str> = line.split(' ').collect();
        let font = || glut::StrokeFont::ALL[f[1].parse::<usize>().expect("font")];
        match f[0] {
            "SH" => {
                assert_eq!(glut::stroke_height(font()), float_bits(f[2]));
                heights += 1;
            }
            "SC" => {
                let (font, code) = (font(), f[2].parse::<i32>().expect("code"));
                let width: i32 = f[3].parse().expect("width");
                assert_eq!(
                    glut::stroke_width(font, code),
                    width,
                    "{font:?} width of {code}"
                );
                assert_eq!(glut::stroke_widthf(font, code), float_bits(f[4]));
                let (bits, _, mx) = fixedgl_pixels(W, H, |c| {
                    c.translatef(STX, STY, 0.0);
                    c.scalef(SCALE, SCALE, 1.0);
                    glut::stroke_character(c, font, code);
                });
                assert_eq!(mx, float_bits(f[5]), "{font:?} advance of {code}");
                if bits != f[6] {
                    panic!(
                        "{font:?} stroke glyph {code} differs from freeglut's:\nfreeglut:\n{}\nfixedgl:\n{}",
                        picture(f[6], W),
                        picture(&bits, W)
                    );
                }
                glyphs += 1;
                drawn += usize::from(bits.contains('1'));
            }
            "SL" => {
                let font = font();
                let length: i32 = f[2].parse().expect("length");
                assert_eq!(glut::stroke_length(font, STRING), length);
                assert_eq!(glut::stroke_lengthf(font, STRING), float_bits(f[3]));
                lengths += 1;
            }
            "SS" => {
                let font = font();
                let (bits, _, _) = fixedgl_pixels(SW, SH, |c| {
                    c.translatef(4.5, 40.5, 0.0);
                    c.scalef(SSCALE, SSCALE, 1.0);
                    glut::stroke_string(c, font, STRING);
                });
                if bits != f[2] {
                    panic!(
                        "{font:?} glutStrokeString differs:\nfreeglut:\n{}\nfixedgl:\n{}",
                        picture(f[2], SW),
                        picture(&bits, SW)
                    );
                }
                strings += 1;
            }
            _ => {}
        }
    }
    assert_eq!((heights, lengths, strings), (2, 2, 2));
    assert_eq!(glyphs, 2 * 255);
    eprintln!(
        "{glyphs} stroke codes ({drawn} with pixels) and {strings} strings as freeglut draws them"
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
