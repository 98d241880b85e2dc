//! The texture front end: objects and names, TexImage2D/TexSubImage2D unpacking, parameters and
//! environment, their queries and errors (each erroneous call changes nothing), GENERATE_MIPMAP,
//! CopyTexImage from colour and depth, and textured drawing read back from the framebuffer.
//! Expected values are worked out by hand from GL 2.1 §3.6, §3.8 and tables 6.15 to 6.17.

use fixedgl::gl::*;
use fixedgl::texture::f32_bytes;
use fixedgl::Context;

fn ctx() -> Context {
    Context::new(4, 4).expect("context")
}

/// A quad covering the whole 4x4 window (identity matrices) with texture coordinates 0..1.
fn full_quad(gl: &mut Context) {
    gl.begin(QUADS);
    for (s, t) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord2f(s, t);
        gl.vertex2f(2.0 * s - 1.0, 2.0 * t - 1.0);
    }
    gl.end();
}

fn pixel(gl: &mut Context, x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    gl.read_pixels(x, y, 1, 1, RGBA, UNSIGNED_BYTE, &mut p);
    p
}

#[test]
fn names_bind_delete_and_is_texture() {
    let mut gl = ctx();
    let mut names = [0u32; 3];
    gl.gen_textures(3, &mut names);
    assert_eq!(names, [1, 2, 3]);
    // Generated but never bound: not yet a texture (§3.8.12).
    assert!(!gl.is_texture(2));
    gl.bind_texture(TEXTURE_2D, 2);
    assert!(gl.is_texture(2));
    let mut b = [0i32];
    gl.get_integerv(TEXTURE_BINDING_2D, &mut b);
    assert_eq!(b, [2]);
    // Deleting the bound texture reverts the binding to 0.
    gl.delete_textures(1, &[2]);
    assert!(!gl.is_texture(2));
    gl.get_integerv(TEXTURE_BINDING_2D, &mut b);
    assert_eq!(b, [0]);
    // New names start above every name in use (1 and 3 still are).
    let mut more = [0u32; 1];
    gl.gen_textures(1, &mut more);
    assert_eq!(more, [4]);
    // A name bound without GenTextures is a texture too.
    gl.bind_texture(TEXTURE_2D, 10);
    assert!(gl.is_texture(10));
    assert!(!gl.is_texture(0));
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn parameter_defaults_and_round_trips() {
    let mut gl = ctx();
    // Table 6.16 initial values.
    let rows: &[(u32, i32)] = &[
        (TEXTURE_MIN_FILTER, NEAREST_MIPMAP_LINEAR as i32),
        (TEXTURE_MAG_FILTER, LINEAR as i32),
        (TEXTURE_WRAP_S, REPEAT as i32),
        (TEXTURE_WRAP_T, REPEAT as i32),
        (TEXTURE_BASE_LEVEL, 0),
        (TEXTURE_MAX_LEVEL, 1000),
        (TEXTURE_MIN_LOD, -1000),
        (TEXTURE_MAX_LOD, 1000),
        (GENERATE_MIPMAP, 0),
        (TEXTURE_COMPARE_MODE, NONE as i32),
        (TEXTURE_COMPARE_FUNC, LEQUAL as i32),
        (DEPTH_TEXTURE_MODE, LUMINANCE as i32),
    ];
    for &(pname, want) in rows {
        let mut v = [-7];
        gl.get_tex_parameteriv(TEXTURE_2D, pname, &mut v);
        assert_eq!(v, [want], "{pname:#x}");
    }
    gl.tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &[0.25, 2.0, -1.0, 0.5]);
    let mut c = [0.0f32; 4];
    gl.get_tex_parameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, &mut c);
    // Clamped to [0, 1] (§3.8.4).
    assert_eq!(c, [0.25, 1.0, 0.0, 0.5]);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, MIRRORED_REPEAT as i32);
    let mut w = [0i32];
    gl.get_tex_parameteriv(TEXTURE_2D, TEXTURE_WRAP_T, &mut w);
    assert_eq!(w, [MIRRORED_REPEAT as i32]);
    // TexEnv defaults (table 6.19) and a colour set through integers: i → (2i + 1)/(2^32 - 1).
    let mut m = [0i32];
    gl.get_tex_enviv(TEXTURE_ENV, TEXTURE_ENV_MODE, &mut m);
    assert_eq!(m, [MODULATE as i32]);
    gl.tex_enviv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[i32::MAX, 0, i32::MAX, -1]);
    let mut ec = [9.0f32; 4];
    gl.get_tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &mut ec);
    // MAX → 1; 0 → 1/(2^32 - 1) ≈ 0; -1 → -1/(2^32-1) clamped to 0.
    assert!((ec[0] - 1.0).abs() < 1e-6 && ec[1].abs() < 1e-6 && ec[3] == 0.0);
    // TexGen defaults (table 6.15): EYE_LINEAR, S plane (1,0,0,0), T plane (0,1,0,0).
    let mut g = [0i32];
    gl.get_tex_geniv(T, TEXTURE_GEN_MODE, &mut g);
    assert_eq!(g, [EYE_LINEAR as i32]);
    let mut p = [9.0f64; 4];
    gl.get_tex_gendv(T, OBJECT_PLANE, &mut p);
    assert_eq!(p, [0.0, 1.0, 0.0, 0.0]);
    // EYE_PLANE is multiplied by the inverse modelview at the call: with a translation by
    // (0, 0, -5), p' = p · M^-1 where M^-1 translates by +5: (0, 0, 1, 0) → (0, 0, 1, 5).
    gl.translatef(0.0, 0.0, -5.0);
    gl.tex_genfv(R, EYE_PLANE, &[0.0, 0.0, 1.0, 0.0]);
    gl.get_tex_gendv(R, EYE_PLANE, &mut p);
    assert_eq!(p, [0.0, 0.0, 1.0, 5.0]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn unpack_alignment_row_length_and_get_tex_image() {
    let mut gl = ctx();
    // 2x2 RGB with UNPACK_ALIGNMENT 4 and UNPACK_ROW_LENGTH 3: rows start 12 bytes apart
    // (3 pixels · 3 bytes = 9, padded to 12); the third pixel of each row is skipped.
    gl.pixel_storei(UNPACK_ROW_LENGTH, 3);
    #[rustfmt::skip]
    let data = [
        10, 20, 30,  40, 50, 60,  99, 99, 99,  0, 0, 0,
        70, 80, 90,  100, 110, 120,
    ];
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGB as i32,
        2,
        2,
        0,
        RGB,
        UNSIGNED_BYTE,
        Some(&data),
    );
    assert_eq!(gl.get_error(), NO_ERROR);
    let mut out = [0u8; 16];
    gl.get_tex_image(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, &mut out);
    #[rustfmt::skip]
    assert_eq!(out, [10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255, 100, 110, 120, 255]);
    // Level parameters (table 6.17).
    let q = |gl: &mut Context, pname| {
        let mut v = [-1];
        gl.get_tex_level_parameteriv(TEXTURE_2D, 0, pname, &mut v);
        v[0]
    };
    assert_eq!(q(&mut gl, TEXTURE_WIDTH), 2);
    assert_eq!(q(&mut gl, TEXTURE_HEIGHT), 2);
    assert_eq!(q(&mut gl, TEXTURE_INTERNAL_FORMAT), RGB as i32);
    assert_eq!(q(&mut gl, TEXTURE_RED_SIZE), 8);
    assert_eq!(q(&mut gl, TEXTURE_ALPHA_SIZE), 0);
    // FLOAT luminance data: clamped to [0, 1], returned as L in R with G = B = 0... read back
    // as LUMINANCE: 0.5 → 128 after 8-bit storage (0.5·255 = 127.5 rounds to 128).
    gl.tex_image_2d(
        TEXTURE_2D,
        1,
        LUMINANCE as i32,
        1,
        1,
        0,
        LUMINANCE,
        FLOAT,
        Some(&f32_bytes(&[0.5])),
    );
    let mut l = [0u8; 1];
    gl.get_tex_image(TEXTURE_2D, 1, LUMINANCE, UNSIGNED_BYTE, &mut l);
    assert_eq!(l, [128]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn generate_mipmap_averages_the_base_level() {
    let mut gl = ctx();
    gl.tex_parameteri(TEXTURE_2D, GENERATE_MIPMAP, 1);
    // Rows of 2 bytes: without alignment 1 they would be padded to 4 (and 4 bytes too short).
    gl.pixel_storei(UNPACK_ALIGNMENT, 1);
    // 2x2 luminance 0, 100, 200, 255 → level 1 = round((0 + 100 + 200 + 255) / 4) = 139
    // (138.75 stored as 8 bits).
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        LUMINANCE as i32,
        2,
        2,
        0,
        LUMINANCE,
        UNSIGNED_BYTE,
        Some(&[0, 100, 200, 255]),
    );
    let mut l = [0u8; 1];
    gl.get_tex_image(TEXTURE_2D, 1, LUMINANCE, UNSIGNED_BYTE, &mut l);
    assert_eq!(l, [139]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn copy_tex_image_from_colour_and_depth() {
    let mut gl = ctx();
    gl.clear_color(1.0, 0.5, 0.0, 1.0);
    gl.clear_depth(0.25);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.copy_tex_image_2d(TEXTURE_2D, 0, RGBA, 1, 1, 2, 2, 0);
    let mut out = [0u8; 16];
    gl.get_tex_image(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, &mut out);
    // The clear colour: 0.5 → 128 in the framebuffer.
    assert_eq!(out[..4], [255, 128, 0, 255]);
    assert_eq!(out[12..], [255, 128, 0, 255]);
    // Depth: 0.25 in a 24-bit buffer is round(0.25 · (2^24 - 1)) / (2^24 - 1) ≈ 0.25.
    gl.copy_tex_image_2d(TEXTURE_2D, 1, DEPTH_COMPONENT, 0, 0, 1, 1, 0);
    let mut d = [0u8; 4];
    gl.get_tex_image(TEXTURE_2D, 1, DEPTH_COMPONENT, FLOAT, &mut d);
    assert!((f32::from_ne_bytes(d) - 0.25).abs() < 1e-6);
    // CopyTexSubImage2D of a region drawn red into the colour texture.
    gl.clear_color(1.0, 0.0, 0.0, 1.0);
    gl.clear(COLOR_BUFFER_BIT);
    gl.copy_tex_sub_image_2d(TEXTURE_2D, 0, 1, 0, 0, 0, 1, 1);
    gl.get_tex_image(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, &mut out);
    assert_eq!(out[..8], [255, 128, 0, 255, 255, 0, 0, 255]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn a_textured_quad_reads_back_the_texels() {
    let mut gl = ctx();
    // 2x2 NEAREST texture over the 4x4 window: each texel covers a 2x2 pixel block.
    #[rustfmt::skip]
    let img = [
        255, 0, 0, 255,   0, 255, 0, 255,
        0, 0, 255, 255,   255, 255, 255, 255,
    ];
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA as i32,
        2,
        2,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&img),
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    gl.enable(TEXTURE_2D);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    full_quad(&mut gl);
    assert_eq!(pixel(&mut gl, 0, 0), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut gl, 3, 0), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut gl, 0, 3), [0, 0, 255, 255]);
    assert_eq!(pixel(&mut gl, 2, 2), [255, 255, 255, 255]);
    // MODULATE with colour (0.5, 1, 1, 1): red texel → (128, 0, 0).
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.color3f(0.5, 1.0, 1.0);
    full_quad(&mut gl);
    assert_eq!(pixel(&mut gl, 1, 1), [128, 0, 0, 255]);
    // The texture matrix scales s by 2 with REPEAT: pixel x = 1 (s = 0.375 → 0.75) reads
    // texel column 1 (green) in row 0.
    gl.matrix_mode(TEXTURE);
    gl.scalef(2.0, 1.0, 1.0);
    gl.matrix_mode(MODELVIEW);
    gl.color3f(1.0, 1.0, 1.0);
    full_quad(&mut gl);
    assert_eq!(pixel(&mut gl, 1, 0), [0, 255, 0, 255]);
    // Incomplete texture (default MIN filter wants mipmaps): texturing is off, colour passes.
    gl.matrix_mode(TEXTURE);
    gl.load_identity();
    gl.matrix_mode(MODELVIEW);
    gl.tex_parameteri(
        TEXTURE_2D,
        TEXTURE_MIN_FILTER,
        NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.color3f(0.0, 0.0, 1.0);
    full_quad(&mut gl);
    assert_eq!(pixel(&mut gl, 0, 0), [0, 0, 255, 255]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

#[test]
fn object_linear_texgen_textures_a_quad_like_explicit_coordinates() {
    // s = x/2 + 1/2, t = y/2 + 1/2 over the quad [-1, 1]²: the same texels as full_quad's.
    let mut gl = ctx();
    let img = [
        255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
    ];
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA as i32,
        2,
        2,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&img),
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    gl.enable(TEXTURE_2D);
    gl.enable(TEXTURE_GEN_S);
    gl.enable(TEXTURE_GEN_T);
    gl.tex_geni(S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
    gl.tex_geni(T, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
    gl.tex_genfv(S, OBJECT_PLANE, &[0.5, 0.0, 0.0, 0.5]);
    gl.tex_genfv(T, OBJECT_PLANE, &[0.0, 0.5, 0.0, 0.5]);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    gl.begin(QUADS);
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.vertex2f(x, y);
    }
    gl.end();
    assert_eq!(pixel(&mut gl, 0, 0), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut gl, 3, 1), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut gl, 1, 3), [0, 0, 255, 255]);
    assert_eq!(pixel(&mut gl, 3, 3), [255, 255, 255, 255]);
}

#[test]
fn two_units_combine_in_order() {
    // Unit 0: 1x1 RGB (1, 0.5, 0) with MODULATE over white; unit 1: 1x1 LUMINANCE 0.5 with ADD
    // (table 3.21: Cv = Cf + Lt): (1, 0.5, 0) + 0.5 = (1, 1, 0.5) → (255, 255, 128).
    let mut gl = ctx();
    gl.pixel_storei(UNPACK_ALIGNMENT, 1);
    let mut names = [0u32; 2];
    gl.gen_textures(2, &mut names);
    for (unit, name, fmt, data, env) in [
        (TEXTURE0, names[0], RGB, &[255u8, 128, 0][..], MODULATE),
        (TEXTURE1, names[1], LUMINANCE, &[128u8][..], ADD),
    ] {
        gl.active_texture(unit);
        gl.bind_texture(TEXTURE_2D, name);
        gl.tex_image_2d(
            TEXTURE_2D,
            0,
            fmt as i32,
            1,
            1,
            0,
            fmt,
            UNSIGNED_BYTE,
            Some(data),
        );
        gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
        gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, env as i32);
        gl.enable(TEXTURE_2D);
    }
    gl.begin(QUADS);
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.multi_tex_coord2f(TEXTURE0, 0.5, 0.5);
        gl.multi_tex_coord2f(TEXTURE1, 0.5, 0.5);
        gl.vertex2f(x, y);
    }
    gl.end();
    // 128/255 + 128/255 = 1.0039 → clamped to 1 for green; blue 0 + 0.50196 → 128.
    assert_eq!(pixel(&mut gl, 2, 2), [255, 255, 128, 255]);
    // MultiTexCoord on a unit that does not exist is INVALID_ENUM, allowed inside Begin/End.
    gl.multi_tex_coord1f(TEXTURE0 + 4, 1.0);
    assert_eq!(gl.get_error(), INVALID_ENUM);
    gl.begin(POINTS);
    gl.multi_tex_coord4fv(TEXTURE1, &[1.0, 2.0, 3.0, 4.0]);
    gl.end();
    assert_eq!(gl.get_error(), NO_ERROR);
    let mut tc = [0.0f32; 4];
    gl.active_texture(TEXTURE1);
    gl.get_floatv(CURRENT_TEXTURE_COORDS, &mut tc);
    assert_eq!(tc, [1.0, 2.0, 3.0, 4.0]);
}

#[test]
fn image_helpers_give_gl_row_order() {
    // A 1x2 image: top pixel red, bottom pixel blue. GL's first row is the bottom one.
    let mut img = image::RgbaImage::new(1, 2);
    img.put_pixel(0, 0, image::Rgba([255, 0, 0, 255]));
    img.put_pixel(0, 1, image::Rgba([0, 0, 255, 255]));
    let (w, h, data) = fixedgl::texture_from_image(&image::DynamicImage::ImageRgba8(img));
    assert_eq!((w, h), (1, 2));
    assert_eq!(data, [0, 0, 255, 255, 255, 0, 0, 255]);
    // 4x4 board of 2x2 cells: a at (0,0), b at (2,0) and (0,2), a again at (2,2).
    let (a, b) = ([1, 1, 1, 1], [2, 2, 2, 2]);
    let board = fixedgl::checkerboard(4, 2, a, b);
    let at = |x: usize, y: usize| &board[(y * 4 + x) * 4..(y * 4 + x) * 4 + 4];
    assert_eq!(
        (at(0, 0), at(1, 1), at(2, 0), at(0, 2), at(3, 3)),
        (&a[..], &a[..], &b[..], &b[..], &a[..])
    );
}

#[test]
fn hostile_texture_coordinates_do_not_panic() {
    // NaN, infinities and huge values through every wrap mode and a mipmapped filter.
    let mut gl = ctx();
    gl.tex_parameteri(TEXTURE_2D, GENERATE_MIPMAP, 1);
    let board = fixedgl::checkerboard(4, 2, [255; 4], [0, 0, 0, 255]);
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA as i32,
        4,
        4,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&board),
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.enable(TEXTURE_2D);
    let bad = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        3e9,
        -3e9,
        1e30,
        0.0,
    ];
    for wrap in [
        REPEAT,
        CLAMP,
        CLAMP_TO_EDGE,
        CLAMP_TO_BORDER,
        MIRRORED_REPEAT,
    ] {
        gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_S, wrap as i32);
        gl.tex_parameteri(TEXTURE_2D, TEXTURE_WRAP_T, wrap as i32);
        for (k, &a) in bad.iter().enumerate() {
            let b = bad[(k + 3) % bad.len()];
            gl.begin(TRIANGLES);
            gl.tex_coord4f(a, b, 0.0, 1.0);
            gl.vertex2f(-1.0, -1.0);
            gl.tex_coord4f(b, a, a, b);
            gl.vertex2f(1.0, -1.0);
            gl.tex_coord2f(0.5, a);
            gl.vertex2f(0.0, 1.0);
            gl.end();
        }
    }
    let _ = pixel(&mut gl, 1, 1);
    assert_eq!(gl.get_error(), NO_ERROR);
}

/// TEXTURE_BINDING_1D/2D/3D/CUBE_MAP of the active unit, in that order.
fn bindings(gl: &mut Context) -> [i32; 4] {
    let mut out = [0; 4];
    for (o, pname) in out.iter_mut().zip([
        TEXTURE_BINDING_1D,
        TEXTURE_BINDING_2D,
        TEXTURE_BINDING_3D,
        TEXTURE_BINDING_CUBE_MAP,
    ]) {
        let mut v = [-1];
        gl.get_integerv(pname, &mut v);
        *o = v[0];
    }
    out
}

fn tex_param(gl: &mut Context, target: u32, pname: u32) -> f32 {
    let mut v = [f32::NAN];
    gl.get_tex_parameterfv(target, pname, &mut v);
    v[0]
}

/// GL 1.2/1.3 texture targets (§3.8.12): one binding per target and unit, each with its own
/// default object; an object's target is fixed at its first bind; parameters act on the object
/// bound to the given target; DeleteTextures unbinds every target; TEXTURE_BIT saves them all.
#[test]
fn every_target_has_its_binding_and_objects() {
    let mut gl = ctx();
    gl.bind_texture(TEXTURE_2D, 1);
    gl.bind_texture(TEXTURE_3D, 2);
    gl.bind_texture(TEXTURE_CUBE_MAP, 3);
    assert_eq!(bindings(&mut gl), [0, 1, 2, 3]);
    assert_eq!(gl.get_error(), NO_ERROR);
    // Name 1 is a 2D texture now: binding it to 1D changes nothing.
    let before = gl.state().clone();
    gl.bind_texture(TEXTURE_1D, 1);
    assert_eq!(gl.get_error(), INVALID_OPERATION);
    assert!(gl.state() == &before);
    gl.bind_texture(TEXTURE_CUBE_MAP_POSITIVE_X, 3);
    assert_eq!(gl.get_error(), INVALID_ENUM);
    // Parameters go to the object bound to the target named.
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_WRAP_R, CLAMP_TO_EDGE as i32);
    gl.tex_parameterf(TEXTURE_CUBE_MAP, TEXTURE_LOD_BIAS, 1.25);
    gl.tex_parameterf(TEXTURE_1D, TEXTURE_LOD_BIAS, -3.0);
    assert_eq!(
        tex_param(&mut gl, TEXTURE_3D, TEXTURE_WRAP_R),
        CLAMP_TO_EDGE as f32
    );
    assert_eq!(
        tex_param(&mut gl, TEXTURE_2D, TEXTURE_WRAP_R),
        REPEAT as f32
    );
    assert_eq!(tex_param(&mut gl, TEXTURE_CUBE_MAP, TEXTURE_LOD_BIAS), 1.25);
    assert_eq!(tex_param(&mut gl, TEXTURE_1D, TEXTURE_LOD_BIAS), -3.0);
    assert_eq!(tex_param(&mut gl, TEXTURE_2D, TEXTURE_LOD_BIAS), 0.0);
    // Another unit has its own bindings.
    gl.active_texture(TEXTURE1);
    assert_eq!(bindings(&mut gl), [0; 4]);
    assert_eq!(
        tex_param(&mut gl, TEXTURE_1D, TEXTURE_LOD_BIAS),
        -3.0,
        "default 1D object"
    );
    gl.bind_texture(TEXTURE_3D, 2);
    gl.active_texture(TEXTURE0);
    // TEXTURE_BIT saves every target's binding and the bound objects' parameters.
    gl.push_attrib(TEXTURE_BIT);
    gl.bind_texture(TEXTURE_1D, 4);
    gl.bind_texture(TEXTURE_3D, 0);
    gl.bind_texture(TEXTURE_CUBE_MAP, 5);
    gl.bind_texture(TEXTURE_CUBE_MAP, 3);
    gl.tex_parameterf(TEXTURE_CUBE_MAP, TEXTURE_LOD_BIAS, 7.0);
    assert_eq!(bindings(&mut gl), [4, 1, 0, 3]);
    gl.pop_attrib();
    assert_eq!(bindings(&mut gl), [0, 1, 2, 3]);
    assert_eq!(tex_param(&mut gl, TEXTURE_CUBE_MAP, TEXTURE_LOD_BIAS), 1.25);
    // Deleting a texture unbinds it from its target on every unit.
    gl.delete_textures(2, &[2, 3]);
    assert_eq!(bindings(&mut gl), [0, 1, 0, 0]);
    gl.active_texture(TEXTURE1);
    assert_eq!(bindings(&mut gl), [0; 4]);
    assert!(!gl.is_texture(2));
    // A deleted name may come back as another target.
    gl.bind_texture(TEXTURE_1D, 2);
    assert_eq!(bindings(&mut gl), [2, 0, 0, 0]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

/// TEXTURE_LOD_BIAS of the object (table 6.16): any float, stored as given; in λ it adds to the
/// unit's TEXTURE_FILTER_CONTROL bias and the sum is clamped to ±MAX_TEXTURE_LOD_BIAS (§3.8.8
/// eq. 3.18), the object's bias clamped on its own first as the driver does. A 16x16 texture on
/// the 4x4 window has λ = 2; each level is one colour, so the level NEAREST_MIPMAP_NEAREST picks
/// reads back directly.
#[test]
fn the_object_lod_bias_adds_to_the_unit_bias() {
    let colours: [[u8; 4]; 5] = [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 0, 255],
        [0, 255, 255, 255],
    ];
    let level_of = |p: [u8; 4]| colours.iter().position(|&c| c == p);
    let mut gl = ctx();
    for (level, c) in colours.iter().enumerate() {
        let size = 16 >> level;
        let data: Vec<u8> = c.repeat(size * size);
        gl.tex_image_2d(
            TEXTURE_2D,
            level as i32,
            RGBA as i32,
            size as i32,
            size as i32,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&data),
        );
    }
    gl.tex_parameteri(
        TEXTURE_2D,
        TEXTURE_MIN_FILTER,
        NEAREST_MIPMAP_NEAREST as i32,
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    gl.enable(TEXTURE_2D);
    assert_eq!(tex_param(&mut gl, TEXTURE_2D, TEXTURE_LOD_BIAS), 0.0);
    // (object bias, unit bias, level): λ = 2 + clamp(clamp(object) + unit), d = ⌈λ + ½⌉ - 1.
    for (object, unit, level) in [
        (0.0, 0.0, 2),
        (-1.0, 0.0, 1),
        (1.0, 0.0, 3),
        (-1.0, 2.0, 3),
        (1.5, -1.5, 2),
        (40.0, 0.0, 4),
        (-40.0, 0.0, 0),
        // The object's bias is clamped before the sum (the driver's order): 16 - 15 is 1, where
        // the spec's clamp of the sum alone would give 20 - 15 = 5 and level 4.
        (20.0, -15.0, 3),
        (-40.0, 16.0, 2),
    ] {
        gl.tex_parameterf(TEXTURE_2D, TEXTURE_LOD_BIAS, object);
        gl.tex_envf(TEXTURE_FILTER_CONTROL, TEXTURE_LOD_BIAS, unit);
        assert_eq!(tex_param(&mut gl, TEXTURE_2D, TEXTURE_LOD_BIAS), object);
        full_quad(&mut gl);
        let p = pixel(&mut gl, 1, 1);
        assert_eq!(
            level_of(p),
            Some(level),
            "object {object}, unit {unit}: {p:?}"
        );
    }
    // The integer forms convert as numbers; the getters round.
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_LOD_BIAS, 3);
    assert_eq!(tex_param(&mut gl, TEXTURE_2D, TEXTURE_LOD_BIAS), 3.0);
    gl.tex_parameterfv(TEXTURE_2D, TEXTURE_LOD_BIAS, &[-2.6]);
    let mut i = [0];
    gl.get_tex_parameteriv(TEXTURE_2D, TEXTURE_LOD_BIAS, &mut i);
    assert_eq!(i, [-3]);
    assert_eq!(gl.get_error(), NO_ERROR);
}

/// Of the enabled targets (CUBE_MAP > 3D > 2D > 1D), the first with a complete texture is used,
/// as the driver does (tests/texture_gl.rs compares): 1D, 3D and cube-map textures hold no
/// images yet, so with 2D enabled too the 2D texture is drawn, and alone they draw nothing.
#[test]
fn enabled_targets_without_images_leave_the_2d_texture() {
    for (enables, textured) in [
        (&[TEXTURE_2D][..], true),
        (&[TEXTURE_2D, TEXTURE_3D][..], true),
        (&[TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D][..], true),
        (&[TEXTURE_1D][..], false),
        (&[TEXTURE_3D, TEXTURE_CUBE_MAP][..], false),
    ] {
        let mut gl = ctx();
        gl.tex_image_2d(
            TEXTURE_2D,
            0,
            RGBA as i32,
            1,
            1,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&[0, 255, 0, 255]),
        );
        gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
        gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
        for &e in enables {
            gl.enable(e);
            assert!(gl.is_enabled(e));
        }
        gl.color3f(0.0, 0.0, 1.0);
        full_quad(&mut gl);
        let want = if textured {
            [0, 255, 0, 255]
        } else {
            [0, 0, 255, 255]
        };
        assert_eq!(pixel(&mut gl, 2, 2), want, "{enables:x?}");
        assert_eq!(gl.get_error(), NO_ERROR);
    }
}
