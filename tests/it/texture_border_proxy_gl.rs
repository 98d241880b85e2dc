//! Texture borders and proxy textures (GL 2.1 §3.8.1) against the real driver (Mesa llvmpipe
//! through EGL), issue #14. Mesa strips a border of 1 off every real image (its gallium drivers
//! set `StripTextureBorder`): the level is the image inside the border, TEXTURE_BORDER 0, and
//! sub-image offsets count from its first inner texel; proxies keep the border in their state.
//! Each test runs the same calls on the CPU front end and on the driver and compares the
//! errors, the level parameters, GetTexImage's bytes and the drawn pixels. Skipped, with a note
//! on stderr, when no GL backend can start.
#![cfg(feature = "gl")]

use crate::common::{cpu_vs_gl, test_backend};
use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context};

/// `n` bytes of a varied RGBA image.
fn bytes(n: usize) -> Vec<u8> {
    (0..n).map(|k| (k * 37 % 251) as u8).collect()
}

/// The level parameters compared.
const PNAMES: [u32; 10] = [
    gl::TEXTURE_WIDTH,
    gl::TEXTURE_HEIGHT,
    gl::TEXTURE_DEPTH,
    gl::TEXTURE_BORDER,
    gl::TEXTURE_RED_SIZE,
    gl::TEXTURE_ALPHA_SIZE,
    gl::TEXTURE_LUMINANCE_SIZE,
    gl::TEXTURE_INTENSITY_SIZE,
    gl::TEXTURE_DEPTH_SIZE,
    gl::TEXTURE_INTERNAL_FORMAT,
];

/// The level parameters of `target`'s level `level` on both; the internal format is compared
/// only where the level has an image (an empty level reads 1 in GL 1.5, RGBA in the driver's
/// newer context).
fn same_level(cpu: &mut Context, gl: &GlBackend, target: u32, level: i32, what: &str) {
    let mut got = Vec::new();
    let mut want = Vec::new();
    for p in PNAMES {
        let mut a = [-7];
        cpu.get_tex_level_parameteriv(target, level, p, &mut a);
        let mut b = -7;
        // SAFETY: the backend's context is current for its own calls; one value written.
        unsafe { gl.raw().GetTexLevelParameteriv(target, level, p, &mut b) };
        got.push(a[0]);
        want.push(b);
    }
    if got[0] == 0 {
        got.pop();
        want.pop();
    }
    assert_eq!(got, want, "{what}: level parameters (cpu, driver)");
    assert_eq!(cpu.get_error(), gl::NO_ERROR, "{what}");
}

/// Runs `rows` on both, each call's error checked against the expected one on both.
fn run_rows(cpu: &mut Context, gl: &mut GlBackend, rows: &[(Call, u32)]) {
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), *expected, "GL after row {i}: {call:?}");
    }
}

fn t1(target: u32, w: i32, border: i32, p: Option<Vec<u8>>) -> Call {
    Call::TexImage1D(Box::new((
        target,
        0,
        gl::RGBA as i32,
        w,
        border,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        p,
    )))
}

#[allow(clippy::too_many_arguments)]
fn t2(target: u32, level: i32, ifmt: u32, w: i32, h: i32, border: i32, p: Option<Vec<u8>>) -> Call {
    Call::TexImage2D(Box::new((
        target,
        level,
        ifmt as i32,
        w,
        h,
        border,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        p,
    )))
}

fn t3(target: u32, w: i32, h: i32, d: i32, border: i32, p: Option<Vec<u8>>) -> Call {
    Call::TexImage3D(Box::new((
        target,
        0,
        gl::RGBA as i32,
        w,
        h,
        d,
        border,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        p,
    )))
}

#[test]
fn border_images_are_stripped_as_the_driver_strips_them() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(16, 16) else {
        return;
    };
    let mut cpu = Context::new(16, 16).unwrap();
    let sub = |x, y, w, h| {
        Call::TexSubImage2D(Box::new((
            TEXTURE_2D,
            0,
            x,
            y,
            w,
            h,
            RGBA,
            UNSIGNED_BYTE,
            bytes((w * h * 4).max(0) as usize),
        )))
    };
    run_rows(
        &mut cpu,
        &mut gl,
        &[
            (Call::ClearColor(0.2, 0.4, 0.6, 0.8), NO_ERROR),
            (Call::Clear(COLOR_BUFFER_BIT), NO_ERROR),
            (Call::BindTexture(TEXTURE_2D, 1), NO_ERROR),
            (Call::BindTexture(TEXTURE_1D, 2), NO_ERROR),
            (Call::BindTexture(TEXTURE_3D, 3), NO_ERROR),
            (t2(TEXTURE_2D, 0, RGBA, 6, 6, 2, None), INVALID_VALUE),
            (t2(TEXTURE_2D, 0, RGBA, 6, 6, -1, None), INVALID_VALUE),
            (t2(TEXTURE_2D, 0, RGBA, 1, 1, 1, None), INVALID_VALUE),
            (t2(TEXTURE_2D, 0, RGBA, 6, 1, 1, None), INVALID_VALUE),
            (t2(TEXTURE_2D, 0, RGBA, 2050, 4, 1, None), NO_ERROR),
            (
                t2(TEXTURE_2D, 0, RGBA, 6, 6, 1, Some(bytes(143))),
                INVALID_OPERATION,
            ),
            (t2(TEXTURE_2D, 0, RGBA, 6, 6, 1, Some(bytes(144))), NO_ERROR),
            (sub(-1, -1, 1, 1), INVALID_VALUE),
            (sub(3, 3, 1, 1), NO_ERROR),
            (sub(4, 0, 1, 1), INVALID_VALUE),
            (t1(TEXTURE_1D, 6, 1, Some(bytes(24))), NO_ERROR),
            (
                t3(TEXTURE_3D, 6, 6, 6, 1, Some(bytes(6 * 6 * 6 * 4))),
                NO_ERROR,
            ),
        ],
    );
    same_level(&mut cpu, &gl, TEXTURE_2D, 0, "2D 6x6 border 1");
    same_level(&mut cpu, &gl, TEXTURE_1D, 0, "1D 6 border 1");
    same_level(&mut cpu, &gl, TEXTURE_3D, 0, "3D 6x6x6 border 1");
    let image = |cpu: &mut Context, gl: &GlBackend, target: u32, n: usize, what: &str| {
        let mut a = vec![0u8; n];
        cpu.get_tex_image(target, 0, RGBA, UNSIGNED_BYTE, &mut a);
        let mut b = vec![0u8; n];
        // SAFETY: `b` holds the level's n bytes (compared sizes above), PACK_ALIGNMENT 4 with
        // RGBA rows.
        unsafe {
            gl.raw()
                .GetTexImage(target, 0, RGBA, UNSIGNED_BYTE, b.as_mut_ptr().cast())
        };
        assert!(a == b, "{what}: GetTexImage differs");
    };
    image(&mut cpu, &gl, TEXTURE_2D, 64, "2D");
    image(&mut cpu, &gl, TEXTURE_1D, 16, "1D");
    image(&mut cpu, &gl, TEXTURE_3D, 256, "3D");
    // Sizes where Mesa keeps a dimension under 3 and strips the others; copies.
    let shapes: &[(Call, u32, &str)] = &[
        (
            t2(TEXTURE_2D, 0, RGBA, 7, 3, 1, Some(bytes(7 * 3 * 4))),
            TEXTURE_2D,
            "7x3",
        ),
        (
            t2(TEXTURE_2D, 0, RGBA, 6, 2, 1, Some(bytes(6 * 2 * 4))),
            TEXTURE_2D,
            "6x2",
        ),
        (t2(TEXTURE_2D, 0, RGBA, 2, 2, 1, None), TEXTURE_2D, "2x2"),
        (
            t3(TEXTURE_3D, 6, 4, 2, 1, Some(bytes(6 * 4 * 2 * 4))),
            TEXTURE_3D,
            "6x4x2",
        ),
        (
            Call::CopyTexImage2D(TEXTURE_2D, 0, RGBA, 1, 2, 6, 6, 1),
            TEXTURE_2D,
            "copy 6x6",
        ),
        (
            Call::CopyTexImage2D(TEXTURE_2D, 0, RGBA, 1, 2, 6, 2, 1),
            TEXTURE_2D,
            "copy 6x2",
        ),
        (
            Call::CopyTexImage1D(TEXTURE_1D, 0, RGBA, 1, 2, 6, 1),
            TEXTURE_1D,
            "copy 1D 6",
        ),
    ];
    for (call, target, what) in shapes {
        run_rows(&mut cpu, &mut gl, &[(call.clone(), NO_ERROR)]);
        same_level(&mut cpu, &gl, *target, 0, what);
    }
    run_rows(
        &mut cpu,
        &mut gl,
        &[
            (
                Call::CopyTexImage2D(TEXTURE_2D, 0, RGBA, 0, 0, 6, 1, 1),
                INVALID_VALUE,
            ),
            (
                Call::CopyTexImage2D(TEXTURE_2D, 0, RGBA, 0, 0, 6, 6, 2),
                INVALID_VALUE,
            ),
            (
                Call::CopyTexImage1D(TEXTURE_1D, 0, RGBA, 0, 0, 1, 1),
                INVALID_VALUE,
            ),
        ],
    );
}

#[test]
fn border_textures_draw_as_the_driver_draws_them() {
    use fixedgl::gl::*;
    let Some((n, first)) = cpu_vs_gl(48, 1, |c| {
        c.clear_color(0.5, 0.1, 0.9, 1.0);
        c.clear(COLOR_BUFFER_BIT);
        c.color3f(1.0, 1.0, 1.0);
        let quad = |c: &mut Context, x0: f32, y0: f32, dims: usize| {
            c.begin(QUADS);
            for (x, y) in [(0.0f32, 0.0f32), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                // Coordinates beyond [0, 1], so the wrap modes show.
                let (s, t) = (x * 1.6 - 0.3, y * 1.6 - 0.3);
                match dims {
                    1 => c.tex_coord1f(s),
                    3 => c.tex_coord3f(s, t, 0.5),
                    _ => c.tex_coord2f(s, t),
                }
                c.vertex2f(x0 + x * 0.45, y0 + y * 0.45);
            }
            c.end();
        };
        c.tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &[0.0, 1.0, 0.0, 1.0]);
        let img = bytes(8 * 8 * 4);
        c.tex_image_2d(
            TEXTURE_2D,
            0,
            RGBA as i32,
            8,
            8,
            1,
            RGBA,
            UNSIGNED_BYTE,
            Some(&img),
        );
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR as i32);
        c.enable(TEXTURE_2D);
        for (k, wrap) in [CLAMP, CLAMP_TO_BORDER, CLAMP_TO_EDGE, REPEAT]
            .iter()
            .enumerate()
        {
            c.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, *wrap as i32);
            c.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, *wrap as i32);
            quad(c, -1.0 + 0.5 * k as f32, 0.5, 2);
        }
        // A copy with a border, drawn NEAREST.
        c.copy_tex_image_2d(TEXTURE_2D, 0, RGB, 5, 20, 10, 10, 1);
        c.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
        quad(c, -1.0, 0.0, 2);
        c.disable(TEXTURE_2D);
        c.tex_image_1d(
            TEXTURE_1D,
            0,
            RGBA as i32,
            6,
            1,
            RGBA,
            UNSIGNED_BYTE,
            Some(&img[..24]),
        );
        c.tex_parameteri(TEXTURE_1D, TEXTURE_MIN_FILTER, LINEAR as i32);
        c.tex_parameteri(TEXTURE_1D, TEXTURE_WRAP_S, CLAMP as i32);
        c.enable(TEXTURE_1D);
        quad(c, -0.5, 0.0, 1);
        c.disable(TEXTURE_1D);
        let vol = bytes(6 * 6 * 6 * 4);
        c.tex_image_3d(
            TEXTURE_3D,
            0,
            RGBA as i32,
            6,
            6,
            6,
            1,
            RGBA,
            UNSIGNED_BYTE,
            Some(&vol),
        );
        c.tex_parameteri(TEXTURE_3D, TEXTURE_MIN_FILTER, LINEAR as i32);
        c.tex_parameteri(TEXTURE_3D, TEXTURE_WRAP_S, CLAMP_TO_BORDER as i32);
        c.enable(TEXTURE_3D);
        quad(c, 0.0, 0.0, 3);
        c.disable(TEXTURE_3D);
    }) else {
        return;
    };
    assert_eq!(n, 0, "first {first}");
}

#[test]
fn proxy_textures_answer_as_the_driver_does() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    let checks: &[Check] = &[
        (
            &[(t2(PROXY_TEXTURE_2D, 0, RGBA, 64, 32, 0, None), NO_ERROR)],
            PROXY_TEXTURE_2D,
            0,
            "64x32",
        ),
        (&[], PROXY_TEXTURE_2D, 1, "level 1 never specified"),
        (
            &[(
                t2(PROXY_TEXTURE_2D, 0, RGBA, 66, 34, 1, Some(bytes(3))),
                NO_ERROR,
            )],
            PROXY_TEXTURE_2D,
            0,
            "66x34 border 1 (data never read)",
        ),
        (
            &[(t2(PROXY_TEXTURE_2D, 0, LUMINANCE8, 8, 8, 0, None), NO_ERROR)],
            PROXY_TEXTURE_2D,
            0,
            "L8",
        ),
        (
            &[(t2(PROXY_TEXTURE_2D, 0, ALPHA, 8, 8, 0, None), NO_ERROR)],
            PROXY_TEXTURE_2D,
            0,
            "A",
        ),
        (
            &[(t2(PROXY_TEXTURE_2D, 0, INTENSITY, 8, 8, 0, None), NO_ERROR)],
            PROXY_TEXTURE_2D,
            0,
            "I",
        ),
        (
            &[
                (t2(PROXY_TEXTURE_2D, 0, RGBA, 8, 8, 0, None), NO_ERROR),
                (
                    t2(PROXY_TEXTURE_2D, 5555, RGBA, 8, 8, 0, None),
                    INVALID_VALUE,
                ),
                (t2(PROXY_TEXTURE_2D, 0, RGBA, -8, 8, 0, None), INVALID_VALUE),
                (t2(PROXY_TEXTURE_2D, 0, RGBA, 8, 8, 2, None), INVALID_VALUE),
                (
                    t2(PROXY_TEXTURE_2D, 0, 0x1234, 8, 8, 0, None),
                    INVALID_VALUE,
                ),
                (
                    Call::TexImage2D(Box::new((
                        PROXY_TEXTURE_2D,
                        0,
                        RGBA as i32,
                        8,
                        8,
                        0,
                        DEPTH_COMPONENT,
                        UNSIGNED_INT_8_8_8_8,
                        None,
                    ))),
                    INVALID_OPERATION,
                ),
                (
                    Call::TexImage2D(Box::new((
                        PROXY_TEXTURE_2D,
                        0,
                        RGBA as i32,
                        8,
                        8,
                        0,
                        DEPTH_COMPONENT,
                        FLOAT,
                        None,
                    ))),
                    INVALID_OPERATION,
                ),
                (
                    Call::CopyTexImage2D(PROXY_TEXTURE_2D, 0, RGBA, 0, 0, 4, 4, 0),
                    INVALID_ENUM,
                ),
                (Call::BindTexture(PROXY_TEXTURE_2D, 0), INVALID_ENUM),
                (
                    Call::TexParameteri(PROXY_TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32),
                    INVALID_ENUM,
                ),
                (t3(PROXY_TEXTURE_2D, 4, 4, 4, 0, None), INVALID_ENUM),
                (t1(PROXY_TEXTURE_2D, 4, 0, None), INVALID_ENUM),
            ],
            PROXY_TEXTURE_2D,
            0,
            "errors leave the proxy unchanged",
        ),
        (
            // Larger than either implementation's MAX_TEXTURE_SIZE: zeroed, no error.
            &[(
                t2(PROXY_TEXTURE_2D, 0, RGBA, 32768, 32768, 0, None),
                NO_ERROR,
            )],
            PROXY_TEXTURE_2D,
            0,
            "too big",
        ),
        (
            &[(t2(PROXY_TEXTURE_2D, 0, RGBA, 1, 1, 1, None), NO_ERROR)],
            PROXY_TEXTURE_2D,
            0,
            "1x1 border 1",
        ),
        (
            &[(t1(PROXY_TEXTURE_1D, 16, 0, None), NO_ERROR)],
            PROXY_TEXTURE_1D,
            0,
            "1D 16",
        ),
        (
            &[(t1(PROXY_TEXTURE_1D, 18, 1, None), NO_ERROR)],
            PROXY_TEXTURE_1D,
            0,
            "1D 18 border 1",
        ),
        (
            &[(t3(PROXY_TEXTURE_3D, 16, 8, 4, 0, None), NO_ERROR)],
            PROXY_TEXTURE_3D,
            0,
            "3D 16x8x4",
        ),
        (
            &[(t3(PROXY_TEXTURE_3D, 4096, 4096, 4096, 0, None), NO_ERROR)],
            PROXY_TEXTURE_3D,
            0,
            "3D too big",
        ),
        (
            &[(
                t2(PROXY_TEXTURE_CUBE_MAP, 0, RGBA, 16, 16, 0, None),
                NO_ERROR,
            )],
            PROXY_TEXTURE_CUBE_MAP,
            0,
            "cube 16",
        ),
        (
            &[(
                t2(PROXY_TEXTURE_CUBE_MAP, 0, RGBA, 16, 8, 0, None),
                NO_ERROR,
            )],
            PROXY_TEXTURE_CUBE_MAP,
            0,
            "cube not square",
        ),
        (
            // §5.4: a proxy TexImage is executed, not compiled, inside NewList(COMPILE).
            &[
                (Call::NewList(1, COMPILE), NO_ERROR),
                (t2(PROXY_TEXTURE_2D, 0, RGB, 4, 2, 0, None), NO_ERROR),
                (Call::EndList, NO_ERROR),
            ],
            PROXY_TEXTURE_2D,
            0,
            "in a display list",
        ),
        (
            &[
                (t2(PROXY_TEXTURE_2D, 0, RGBA, 8, 8, 0, None), NO_ERROR),
                (Call::CallList(1), NO_ERROR),
            ],
            PROXY_TEXTURE_2D,
            0,
            "the list holds nothing",
        ),
    ];
    for (rows, target, level, what) in checks {
        run_rows(&mut cpu, &mut gl, rows);
        same_level(&mut cpu, &gl, *target, *level, what);
    }
    // A proxy has no parameters (§6.1.3: INVALID_ENUM), and the real level is untouched.
    let mut v = [-7];
    cpu.get_tex_parameteriv(PROXY_TEXTURE_2D, TEXTURE_MIN_FILTER, &mut v);
    assert_eq!((cpu.get_error(), v[0]), (INVALID_ENUM, -7));
    same_level(&mut cpu, &gl, TEXTURE_2D, 0, "the real 2D level");
}

/// Calls with their expected errors, then the proxy target and level to compare, and a label.
type Check<'a> = (&'a [(Call, u32)], u32, i32, &'a str);

/// `PrioritizeTextures(n, textures, priorities)` as a recorded call.
fn prioritize(n: i32, names: &[u32], p: &[f32]) -> Call {
    Call::PrioritizeTextures(Box::new((n, names.to_vec(), p.to_vec())))
}

#[test]
fn priorities_and_residency_match_the_driver() {
    use fixedgl::gl::*;
    let Some(mut gl) = test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).unwrap();
    // TEXTURE_PRIORITY of the object bound to TEXTURE_2D on both.
    let priority = |cpu: &mut Context, gl: &mut GlBackend, name: u32, what: &str| {
        run_rows(cpu, gl, &[(Call::BindTexture(TEXTURE_2D, name), NO_ERROR)]);
        let (mut a, mut b) = ([-1.0f32], [-1.0f32]);
        cpu.get_tex_parameterfv(TEXTURE_2D, TEXTURE_PRIORITY, &mut a);
        gl.get_tex_parameterfv(TEXTURE_2D, TEXTURE_PRIORITY, &mut b);
        assert_eq!(a, b, "{what}: priority of {name} (cpu, driver)");
        a[0]
    };
    run_rows(
        &mut cpu,
        &mut gl,
        &[
            (Call::BindTexture(TEXTURE_2D, 1), NO_ERROR),
            (Call::BindTexture(TEXTURE_2D, 2), NO_ERROR),
            (Call::BindTexture(TEXTURE_1D, 3), NO_ERROR),
            (prioritize(3, &[1, 2, 3], &[2.0, -1.0, 0.25]), NO_ERROR),
            // 0 and names that are no texture are skipped without an error.
            (prioritize(2, &[0, 77], &[0.5, 0.5]), NO_ERROR),
            (prioritize(-1, &[1], &[0.5]), INVALID_VALUE),
            // Between Begin and End GetError answers NO_ERROR; the flag shows after End.
            (Call::Begin(TRIANGLES), NO_ERROR),
            (prioritize(1, &[1], &[0.5]), NO_ERROR),
            (Call::End, INVALID_OPERATION),
        ],
    );
    assert_eq!(priority(&mut cpu, &mut gl, 1, "clamped to 1"), 1.0);
    assert_eq!(priority(&mut cpu, &mut gl, 2, "clamped to 0"), 0.0);
    // A display list holds PrioritizeTextures (GL 2.1 §5.4), which runs at CallList.
    run_rows(
        &mut cpu,
        &mut gl,
        &[
            (Call::NewList(5, COMPILE), NO_ERROR),
            (prioritize(1, &[1], &[0.75]), NO_ERROR),
            (Call::EndList, NO_ERROR),
        ],
    );
    assert_eq!(priority(&mut cpu, &mut gl, 1, "compiled only"), 1.0);
    run_rows(&mut cpu, &mut gl, &[(Call::CallList(5), NO_ERROR)]);
    assert_eq!(priority(&mut cpu, &mut gl, 1, "after CallList"), 0.75);
    // PushAttrib(TEXTURE_BIT) saves the bound object's priority.
    run_rows(
        &mut cpu,
        &mut gl,
        &[
            (Call::PushAttrib(TEXTURE_BIT), NO_ERROR),
            (prioritize(1, &[1], &[0.125]), NO_ERROR),
            (Call::PopAttrib, NO_ERROR),
        ],
    );
    assert_eq!(priority(&mut cpu, &mut gl, 1, "after PopAttrib"), 0.75);
    // AreTexturesResident: every texture is; 0 or a name that is none is INVALID_VALUE.
    let mut generated = [0u32];
    cpu.gen_textures(1, &mut generated);
    let mut gen_gl = 0u32;
    // SAFETY: the backend's context is current for its own calls; one name written.
    unsafe { gl.raw().GenTextures(1, &mut gen_gl) };
    assert_eq!(generated[0], gen_gl, "both hand out the same name");
    let cases: &[(&[u32], bool, u32)] = &[
        (&[1, 2, 3], true, NO_ERROR),
        (&[1, gen_gl], true, NO_ERROR),
        (&[], true, NO_ERROR),
        (&[1, 0], false, INVALID_VALUE),
        (&[99, 1], false, INVALID_VALUE),
    ];
    for &(names, want, err) in cases {
        let got = cpu.are_textures_resident(names.len() as i32, names, &mut []);
        assert_eq!((got, cpu.get_error()), (want, err), "cpu {names:?}");
        let mut res = [7u8; 4];
        // SAFETY: `names.len()` names and as many residences (at most 4) are passed.
        let r = unsafe {
            gl.raw()
                .AreTexturesResident(names.len() as i32, names.as_ptr(), res.as_mut_ptr())
        };
        assert_eq!((r != 0, gl.get_error()), (want, err), "driver {names:?}");
    }
    assert!(!cpu.are_textures_resident(-1, &[], &mut []));
    assert_eq!(cpu.get_error(), INVALID_VALUE);
    cpu.begin(TRIANGLES);
    assert!(!cpu.are_textures_resident(1, &[1], &mut []));
    cpu.end();
    assert_eq!(cpu.get_error(), INVALID_OPERATION);
    // A query is not compiled: inside NewList it answers at once.
    cpu.new_list(6, COMPILE);
    assert!(cpu.are_textures_resident(1, &[1], &mut []));
    cpu.end_list();
    assert_eq!(cpu.get_error(), NO_ERROR);
}
