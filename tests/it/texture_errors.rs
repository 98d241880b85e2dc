//! Texture entry points' error rows (GL 2.1 §3.8.1 to §3.8.4, §3.8.13, §2.11.4, §3.8.12): each
//! raises the error the spec gives and changes nothing (the State compares equal).

use fixedgl::gl::*;
use fixedgl::Context;

fn ctx() -> Context {
    Context::new(4, 4).expect("context")
}

#[test]
fn error_rows_change_nothing() {
    type Row = (&'static str, fn(&mut Context), u32);
    let rows: &[Row] = &[
        (
            "TexImage2D 1D target",
            |g| {
                g.tex_image_2d(
                    TEXTURE_1D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_ENUM,
        ),
        (
            "TexImage2D level -1",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    -1,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D level 12",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    12,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D internal 0",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    0,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D internal 5",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    5,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D width -1",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    -1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    None,
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D width 4096",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    4096,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    None,
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D level 1 width 2048",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    1,
                    RGBA as i32,
                    2048,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    None,
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D border 2",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    2,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_VALUE,
        ),
        (
            "TexImage2D bad format",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    0x1234,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                )
            },
            INVALID_ENUM,
        ),
        (
            "TexImage2D bad type",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    0x1234,
                    Some(&[0; 4]),
                )
            },
            INVALID_ENUM,
        ),
        (
            "TexImage2D depth data, colour format",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    DEPTH_COMPONENT,
                    FLOAT,
                    Some(&[0; 4]),
                )
            },
            INVALID_OPERATION,
        ),
        (
            "TexImage2D colour data, depth format",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    DEPTH_COMPONENT as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    FLOAT,
                    Some(&[0; 16]),
                )
            },
            INVALID_OPERATION,
        ),
        // 2x2 RGB bytes with UNPACK_ALIGNMENT 4: rows of 8 bytes, 8 + 6 = 14 needed.
        (
            "TexImage2D short data",
            |g| {
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGB as i32,
                    2,
                    2,
                    0,
                    RGB,
                    UNSIGNED_BYTE,
                    Some(&[0; 13]),
                )
            },
            INVALID_OPERATION,
        ),
        (
            "TexImage2D inside Begin/End",
            |g| {
                g.begin(POINTS);
                g.tex_image_2d(
                    TEXTURE_2D,
                    0,
                    RGBA as i32,
                    1,
                    1,
                    0,
                    RGBA,
                    UNSIGNED_BYTE,
                    Some(&[0; 4]),
                );
                g.end();
            },
            INVALID_OPERATION,
        ),
        (
            "TexSubImage2D undefined level",
            |g| g.tex_sub_image_2d(TEXTURE_2D, 3, 0, 0, 1, 1, RGBA, UNSIGNED_BYTE, &[0; 4]),
            INVALID_OPERATION,
        ),
        (
            "TexSubImage2D outside",
            |g| g.tex_sub_image_2d(TEXTURE_2D, 0, 1, 1, 2, 1, RGBA, UNSIGNED_BYTE, &[0; 8]),
            INVALID_VALUE,
        ),
        (
            "TexSubImage2D negative offset",
            |g| g.tex_sub_image_2d(TEXTURE_2D, 0, -1, 0, 1, 1, RGBA, UNSIGNED_BYTE, &[0; 4]),
            INVALID_VALUE,
        ),
        (
            "TexSubImage2D short",
            |g| g.tex_sub_image_2d(TEXTURE_2D, 0, 0, 0, 2, 2, RGBA, UNSIGNED_BYTE, &[0; 15]),
            INVALID_OPERATION,
        ),
        (
            "TexParameteri bad target (a cube-map face is no binding target)",
            |g| {
                g.tex_parameteri(
                    TEXTURE_CUBE_MAP_POSITIVE_X,
                    TEXTURE_MIN_FILTER,
                    LINEAR as i32,
                )
            },
            INVALID_ENUM,
        ),
        (
            "TexParameteri bad pname",
            |g| g.tex_parameteri(TEXTURE_2D, 0x1234, 0),
            INVALID_ENUM,
        ),
        (
            "TexParameteri MAG mipmap",
            |g| g.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR_MIPMAP_LINEAR as i32),
            INVALID_ENUM,
        ),
        (
            "TexParameteri wrap bad",
            |g| g.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, LINEAR as i32),
            INVALID_ENUM,
        ),
        (
            "TexParameteri border colour scalar, bad target",
            |g| g.tex_parameteri(TEXTURE_ENV, TEXTURE_BORDER_COLOR, 0),
            INVALID_ENUM,
        ),
        (
            "TexParameteri BASE_LEVEL -1",
            |g| g.tex_parameteri(TEXTURE_2D, TEXTURE_BASE_LEVEL, -1),
            INVALID_VALUE,
        ),
        (
            "TexParameterfv short border",
            |g| g.tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &[1.0; 3]),
            INVALID_VALUE,
        ),
        (
            "TexParameteri compare func bad",
            |g| g.tex_parameteri(TEXTURE_2D, TEXTURE_COMPARE_FUNC, LINEAR as i32),
            INVALID_ENUM,
        ),
        (
            "TexEnvi bad mode",
            |g| g.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, LINEAR as i32),
            INVALID_ENUM,
        ),
        (
            "TexEnvi bad target",
            |g| g.tex_envi(TEXTURE_2D, TEXTURE_ENV_MODE, MODULATE as i32),
            INVALID_ENUM,
        ),
        (
            "TexEnvfv short colour",
            |g| g.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[1.0; 3]),
            INVALID_VALUE,
        ),
        (
            "TexGeni SPHERE_MAP on R",
            |g| g.tex_geni(R, TEXTURE_GEN_MODE, SPHERE_MAP as i32),
            INVALID_ENUM,
        ),
        (
            "TexGeni REFLECTION_MAP on Q",
            |g| g.tex_geni(Q, TEXTURE_GEN_MODE, REFLECTION_MAP as i32),
            INVALID_ENUM,
        ),
        (
            "TexGenf plane scalar, bad coord",
            |g| g.tex_genf(TEXTURE_2D, EYE_PLANE, 1.0),
            INVALID_ENUM,
        ),
        (
            "TexGenfv short plane",
            |g| g.tex_genfv(S, OBJECT_PLANE, &[1.0; 3]),
            INVALID_VALUE,
        ),
        (
            "GenTextures -1",
            |g| g.gen_textures(-1, &mut []),
            INVALID_VALUE,
        ),
        (
            "GenTextures short slice",
            |g| g.gen_textures(2, &mut [0]),
            INVALID_VALUE,
        ),
        (
            "DeleteTextures short slice",
            |g| g.delete_textures(2, &[1]),
            INVALID_VALUE,
        ),
        (
            "BindTexture proxy target",
            |g| g.bind_texture(PROXY_TEXTURE_2D, 1),
            INVALID_ENUM,
        ),
        (
            "PixelStorei UNPACK_ROW_LENGTH -1",
            |g| g.pixel_storei(UNPACK_ROW_LENGTH, -1),
            INVALID_VALUE,
        ),
        (
            "CopyTexImage2D bad internal",
            // INVALID_ENUM as Mesa (texture_gl.rs checks it against the driver).
            |g| g.copy_tex_image_2d(TEXTURE_2D, 0, 3, 0, 0, 1, 1, 0),
            INVALID_ENUM,
        ),
        (
            "CopyTexSubImage2D undefined level",
            |g| g.copy_tex_sub_image_2d(TEXTURE_2D, 2, 0, 0, 0, 0, 1, 1),
            INVALID_OPERATION,
        ),
    ];
    for (name, call, code) in rows {
        let mut gl = ctx();
        // A 2x2 RGBA level 0 to update.
        gl.tex_image_2d(
            TEXTURE_2D,
            0,
            RGBA as i32,
            2,
            2,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&[7; 16]),
        );
        assert_eq!(gl.get_error(), NO_ERROR);
        let before = gl.state().clone();
        call(&mut gl);
        assert_eq!(gl.get_error(), *code, "{name}");
        assert!(gl.state() == &before, "{name} changed state");
    }
}
