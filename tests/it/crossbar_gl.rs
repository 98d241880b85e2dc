//! ARB_texture_env_crossbar (core in GL 1.4, GL 2.1 §3.8.13): a COMBINE source TEXTUREn reads
//! texture unit n's filtered texel, whichever unit's environment names it. Four units with
//! different textures (a LINEAR 2D, a 1D, a 3D and a cube map, `texture_units_gl.rs`), COMBINE on
//! unit 2 reading TEXTURE0 and TEXTURE3 (and TEXTURE1, and itself as TEXTURE2) in RGB and ALPHA
//! with every operand, through MODULATE, INTERPOLATE, ADD_SIGNED, SUBTRACT, DOT3_RGB and
//! DOT3_RGBA, unit 3 reading TEXTURE0 back; a source naming a disabled or incomplete unit (the
//! spec: undefined; llvmpipe: (0, 0, 0, 0)); pixel rectangles and bitmaps. Drawn by the CPU and
//! by the driver (Mesa llvmpipe) from the same recorded calls. Skipped, with a note on stderr,
//! when no GL backend can start.
#![cfg(feature = "gl")]

use crate::common::cpu_vs_gl;
use crate::texture_units_gl::{check, perspective_quad, texel, unit_texture};
use fixedgl::gl::*;
use fixedgl::Context;

/// One unit's COMBINE environment.
struct Combine {
    rgb: u32,
    alpha: u32,
    src_rgb: [u32; 3],
    op_rgb: [u32; 3],
    src_alpha: [u32; 3],
    op_alpha: [u32; 3],
    rgb_scale: f32,
}

/// Sets the active unit's environment to `e`.
fn combine(c: &mut Context, e: &Combine) {
    c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32);
    c.tex_envi(TEXTURE_ENV, COMBINE_RGB, e.rgb as i32);
    c.tex_envi(TEXTURE_ENV, COMBINE_ALPHA, e.alpha as i32);
    for k in 0..3 {
        c.tex_envi(TEXTURE_ENV, SOURCE0_RGB + k, e.src_rgb[k as usize] as i32);
        c.tex_envi(TEXTURE_ENV, OPERAND0_RGB + k, e.op_rgb[k as usize] as i32);
        c.tex_envi(
            TEXTURE_ENV,
            SOURCE0_ALPHA + k,
            e.src_alpha[k as usize] as i32,
        );
        c.tex_envi(
            TEXTURE_ENV,
            OPERAND0_ALPHA + k,
            e.op_alpha[k as usize] as i32,
        );
    }
    c.tex_envf(TEXTURE_ENV, RGB_SCALE, e.rgb_scale);
    c.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[0.2, 0.5, 0.8, 0.35]);
}

/// Unit 2's environments: each function, with sources from other units in RGB and ALPHA.
fn unit2_cases() -> Vec<(&'static str, Combine)> {
    const C: u32 = SRC_COLOR;
    const NC: u32 = ONE_MINUS_SRC_COLOR;
    const A: u32 = SRC_ALPHA;
    const NA: u32 = ONE_MINUS_SRC_ALPHA;
    vec![
        (
            "modulate",
            Combine {
                rgb: MODULATE,
                alpha: MODULATE,
                src_rgb: [TEXTURE0, TEXTURE3, PREVIOUS],
                op_rgb: [C, NC, C],
                src_alpha: [TEXTURE3, TEXTURE0, PREVIOUS],
                op_alpha: [A, NA, A],
                rgb_scale: 1.0,
            },
        ),
        (
            "interpolate",
            Combine {
                rgb: INTERPOLATE,
                alpha: INTERPOLATE,
                src_rgb: [TEXTURE0, TEXTURE3, TEXTURE1],
                op_rgb: [C, A, NA],
                src_alpha: [TEXTURE3, PREVIOUS, TEXTURE0],
                op_alpha: [NA, A, A],
                rgb_scale: 1.0,
            },
        ),
        (
            "add signed",
            Combine {
                rgb: ADD_SIGNED,
                alpha: ADD_SIGNED,
                src_rgb: [TEXTURE3, TEXTURE0, CONSTANT],
                op_rgb: [A, NC, C],
                src_alpha: [TEXTURE0, TEXTURE3, CONSTANT],
                op_alpha: [A, NA, A],
                rgb_scale: 2.0,
            },
        ),
        (
            "subtract, own unit as TEXTURE2",
            Combine {
                rgb: SUBTRACT,
                alpha: SUBTRACT,
                src_rgb: [TEXTURE2, TEXTURE0, CONSTANT],
                op_rgb: [C, C, C],
                src_alpha: [TEXTURE3, TEXTURE2, CONSTANT],
                op_alpha: [A, NA, A],
                rgb_scale: 4.0,
            },
        ),
        (
            "dot3 rgb",
            Combine {
                rgb: DOT3_RGB,
                alpha: REPLACE,
                src_rgb: [TEXTURE0, TEXTURE3, CONSTANT],
                op_rgb: [C, NC, C],
                src_alpha: [TEXTURE3, PREVIOUS, CONSTANT],
                op_alpha: [A, A, A],
                rgb_scale: 1.0,
            },
        ),
        (
            "dot3 rgba",
            Combine {
                rgb: DOT3_RGBA,
                alpha: REPLACE,
                src_rgb: [TEXTURE3, TEXTURE1, CONSTANT],
                op_rgb: [C, C, C],
                src_alpha: [TEXTURE0, PREVIOUS, CONSTANT],
                op_alpha: [A, A, A],
                rgb_scale: 1.0,
            },
        ),
    ]
}

/// Unit 3 after unit 2: MODULATE of the previous result and unit 0's texel (a later unit
/// reading an earlier one) with ALPHA from TEXTURE1.
fn unit3_reads_back(c: &mut Context) {
    c.active_texture(TEXTURE3);
    combine(
        c,
        &Combine {
            rgb: MODULATE,
            alpha: ADD,
            src_rgb: [PREVIOUS, TEXTURE0, CONSTANT],
            op_rgb: [SRC_COLOR, SRC_COLOR, SRC_COLOR],
            src_alpha: [PREVIOUS, TEXTURE1, CONSTANT],
            op_alpha: [SRC_ALPHA, ONE_MINUS_SRC_ALPHA, SRC_ALPHA],
            rgb_scale: 2.0,
        },
    );
}

#[test]
fn unit_2_combines_the_texels_of_other_units_as_the_driver_does() {
    for (name, env) in unit2_cases() {
        for read_back in [false, true] {
            // Measured: the differences are those of a filtered texel (the driver's 8-bit LINEAR
            // weights), multiplied by unit 2's RGB_SCALE, DOT3's factor 4 and unit 3's RGB_SCALE
            // 2; within 1 + that factor in 255ths, every case has at most 1 pixel of 4096 off, a
            // NEAREST texel boundary of the 1D/3D/cube units that the driver rounds the other
            // way (as in `texture_units_gl.rs`). A source read from the wrong unit is off by far
            // more, everywhere.
            let dot3 = if matches!(env.rgb, DOT3_RGB | DOT3_RGBA) {
                4.0
            } else {
                1.0
            };
            let factor = env.rgb_scale * dot3 * if read_back { 2.0 } else { 1.0 };
            let got = cpu_vs_gl(64, 1 + factor as u8, |c| {
                for u in 0..4 {
                    unit_texture(c, u);
                }
                c.active_texture(TEXTURE0);
                c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
                c.active_texture(TEXTURE1);
                c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, ADD as i32);
                c.active_texture(TEXTURE2);
                combine(c, &env);
                if read_back {
                    unit3_reads_back(c);
                } else {
                    c.active_texture(TEXTURE3);
                    c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
                }
                perspective_quad(c);
            });
            check(&format!("{name}, unit 3 reads back: {read_back}"), got, 1);
        }
    }
}

/// Unit 2 REPLACEs with TEXTURE1 in RGB and TEXTURE3 in ALPHA while units 1 and 3 do not
/// texture: unit 1 incomplete (a mipmap filter without mipmaps, §3.8.10) or no target enabled,
/// unit 3 no target enabled. The spec leaves the result undefined; llvmpipe reads (0, 0, 0, 0)
/// for such a unit, and so does fixedgl.
#[test]
fn a_disabled_or_incomplete_unit_reads_zero_as_in_the_driver() {
    for incomplete in [false, true] {
        let got = cpu_vs_gl(64, 0, |c| {
            unit_texture(c, 0);
            unit_texture(c, 2);
            if incomplete {
                unit_texture(c, 1);
                c.tex_parameteri(
                    TEXTURE_1D,
                    TEXTURE_MIN_FILTER,
                    NEAREST_MIPMAP_NEAREST as i32,
                );
            }
            c.active_texture(TEXTURE2);
            combine(
                c,
                &Combine {
                    rgb: ADD,
                    alpha: ADD,
                    src_rgb: [TEXTURE1, CONSTANT, PREVIOUS],
                    op_rgb: [SRC_COLOR, SRC_COLOR, SRC_COLOR],
                    src_alpha: [TEXTURE3, CONSTANT, PREVIOUS],
                    op_alpha: [SRC_ALPHA, SRC_ALPHA, SRC_ALPHA],
                    rgb_scale: 1.0,
                },
            );
            perspective_quad(c);
        });
        check(&format!("disabled unit, incomplete {incomplete}"), got, 0);
    }
    // What the driver was measured to draw, on the CPU alone: the constant plus zero.
    let Ok(mut c) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    unit_texture(&mut c, 2);
    combine(
        &mut c,
        &Combine {
            rgb: ADD,
            alpha: ADD,
            src_rgb: [TEXTURE1, CONSTANT, PREVIOUS],
            op_rgb: [SRC_COLOR, SRC_COLOR, SRC_COLOR],
            src_alpha: [TEXTURE3, CONSTANT, PREVIOUS],
            op_alpha: [SRC_ALPHA, SRC_ALPHA, SRC_ALPHA],
            rgb_scale: 1.0,
        },
    );
    c.multi_tex_coord3f(TEXTURE2, 0.5, 0.5, 0.5);
    c.rectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(c.get_error(), NO_ERROR);
    let p = c.to_image().get_pixel(4, 4).0;
    assert_eq!(p, [51, 128, 204, 89], "CONSTANT + (0, 0, 0, 0)");
}

/// Pixel rectangles and bitmaps (§3.6.5, §3.7): fragments take the raster texture coordinates,
/// and unit 1's COMBINE reads unit 0's texel there. (The driver samples only unit 0 at the raster
/// coordinates, `texture_units_gl.rs`; here unit 1 samples nothing of its own.)
#[test]
fn pixel_rectangles_and_bitmaps_read_other_units() {
    let got = cpu_vs_gl(64, 2, |c| {
        unit_texture(c, 0);
        c.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
        unit_texture(c, 1);
        combine(
            c,
            &Combine {
                rgb: MODULATE,
                alpha: REPLACE,
                src_rgb: [PREVIOUS, TEXTURE0, CONSTANT],
                op_rgb: [SRC_COLOR, ONE_MINUS_SRC_COLOR, SRC_COLOR],
                src_alpha: [TEXTURE0, PREVIOUS, CONSTANT],
                op_alpha: [ONE_MINUS_SRC_ALPHA, SRC_ALPHA, SRC_ALPHA],
                rgb_scale: 4.0,
            },
        );
        c.multi_tex_coord2f(TEXTURE0, 0.3, 0.6);
        c.raster_pos2f(-0.8, -0.8);
        let px: Vec<u8> = (0..20 * 20).flat_map(|k| texel(k, 9)).collect();
        c.draw_pixels(20, 20, RGBA, UNSIGNED_BYTE, &px);
        c.color4f(0.9, 0.6, 0.3, 0.8);
        c.raster_pos2f(0.2, 0.2);
        c.bitmap(
            16,
            2,
            0.0,
            0.0,
            0.0,
            0.0,
            Some(&[0xF0, 0x0F, 0, 0, 0xAA, 0x55, 0, 0]),
        );
    });
    check("pixels and bitmap", got, 0);
}

/// TEXTURE0 + n is a source for n < MAX_TEXTURE_UNITS (4) only: TEXTURE4 is INVALID_ENUM and
/// changes nothing, on the CPU context and through the GL backend (whose driver has 8 units).
#[test]
fn sources_past_the_last_unit_are_invalid_enum_on_both_backends() {
    let Some(mut backend) = crate::common::test_backend(8, 8) else {
        return;
    };
    let Ok(mut c) = Context::new(8, 8) else {
        panic!("CPU context")
    };
    c.active_texture(TEXTURE1);
    c.start_recording();
    c.tex_envi(TEXTURE_ENV, SOURCE1_ALPHA, TEXTURE3 as i32);
    let mut v = [0];
    c.get_tex_enviv(TEXTURE_ENV, SOURCE1_ALPHA, &mut v);
    assert_eq!((c.get_error(), v[0]), (NO_ERROR, TEXTURE3 as i32));
    let ok = c.stop_recording();
    backend.replay(&ok);
    assert_eq!(backend.get_error(), NO_ERROR);
    for (pname, bad) in [(SOURCE1_ALPHA, TEXTURE4), (SOURCE0_RGB, TEXTURE0 + 7)] {
        c.start_recording();
        c.tex_envf(TEXTURE_ENV, pname, bad as f32);
        let calls = c.stop_recording();
        assert_eq!(c.get_error(), INVALID_ENUM, "{pname:#x} {bad:#x}");
        backend.replay(&calls);
        assert_eq!(backend.get_error(), INVALID_ENUM, "GL: {pname:#x} {bad:#x}");
    }
    c.get_tex_enviv(TEXTURE_ENV, SOURCE1_ALPHA, &mut v);
    assert_eq!(v[0], TEXTURE3 as i32, "unchanged");
}
