//! Points and antialiasing (GL 2.1 §3.3–3.5): PointParameter state, COORD_REPLACE, their
//! errors, display lists and attribute groups, each sequence run on the front end and on the
//! driver and compared (errors call by call, then every queried value); smooth points, smooth
//! lines and POLYGON_SMOOTH pictures against the driver's.

use fixedgl::{gl, Call, Context};

const SIZE: u32 = 64;

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// The values compared after each sequence: (pname, count).
const QUERIES: &[(u32, usize)] = &[
    (gl::POINT_SIZE, 1),
    (gl::POINT_SIZE_MIN, 1),
    (gl::POINT_SIZE_MAX, 1),
    (gl::POINT_FADE_THRESHOLD_SIZE, 1),
    (gl::POINT_DISTANCE_ATTENUATION, 3),
    (gl::POINT_SPRITE_COORD_ORIGIN, 1),
    (gl::POINT_SMOOTH, 1),
    (gl::POINT_SPRITE, 1),
    (gl::LINE_SMOOTH, 1),
    (gl::POLYGON_SMOOTH, 1),
    (gl::POINT_SMOOTH_HINT, 1),
    (gl::LINE_SMOOTH_HINT, 1),
    (gl::POLYGON_SMOOTH_HINT, 1),
    (gl::SMOOTH_POINT_SIZE_RANGE, 2),
    (gl::SMOOTH_POINT_SIZE_GRANULARITY, 1),
    (gl::ALIASED_POINT_SIZE_RANGE, 2),
    (gl::SMOOTH_LINE_WIDTH_RANGE, 2),
    (gl::SMOOTH_LINE_WIDTH_GRANULARITY, 1),
    (gl::ALIASED_LINE_WIDTH_RANGE, 2),
];

fn cpu_values(c: &mut Context) -> Vec<f32> {
    let mut out = Vec::new();
    for &(pname, n) in QUERIES {
        let mut v = vec![f32::NAN; n];
        c.get_floatv(pname, &mut v);
        out.extend(v);
    }
    for unit in 0..4 {
        c.active_texture(gl::TEXTURE0 + unit);
        let mut v = [-1];
        c.get_tex_enviv(gl::POINT_SPRITE, gl::COORD_REPLACE, &mut v);
        out.push(v[0] as f32);
    }
    c.active_texture(gl::TEXTURE0);
    out
}

/// Sequences of calls: each ends where its state is compared.
fn sequences() -> Vec<(&'static str, Vec<Call>)> {
    use Call as C;
    vec![
        ("initial", vec![]),
        (
            "parameters",
            vec![
                C::PointParameterf(gl::POINT_SIZE_MIN, 2.5),
                C::PointParameteri(gl::POINT_SIZE_MAX, 40),
                C::PointParameterfv(gl::POINT_FADE_THRESHOLD_SIZE, vec![3.0]),
                C::PointParameterfv(gl::POINT_DISTANCE_ATTENUATION, vec![1.0, 0.5, 0.25]),
                C::PointParameteri(gl::POINT_SPRITE_COORD_ORIGIN, gl::LOWER_LEFT as i32),
                C::PointParameteriv(gl::POINT_DISTANCE_ATTENUATION, vec![2, 0, 1]),
                C::ActiveTexture(gl::TEXTURE2),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1),
                C::ActiveTexture(gl::TEXTURE0),
                C::TexEnvf(gl::POINT_SPRITE, gl::COORD_REPLACE, 1.0),
                C::Enable(gl::POINT_SPRITE),
                C::Enable(gl::POINT_SMOOTH),
                C::Enable(gl::LINE_SMOOTH),
                C::Enable(gl::POLYGON_SMOOTH),
                C::Hint(gl::POINT_SMOOTH_HINT, gl::NICEST),
                C::Hint(gl::LINE_SMOOTH_HINT, gl::FASTEST),
                C::Hint(gl::POLYGON_SMOOTH_HINT, gl::NICEST),
            ],
        ),
        (
            "errors",
            vec![
                C::PointParameterf(gl::POINT_SIZE_MIN, -1.0),
                C::PointParameterf(gl::POINT_SIZE_MAX, -0.5),
                C::PointParameteri(gl::POINT_FADE_THRESHOLD_SIZE, -2),
                C::PointParameterfv(gl::POINT_DISTANCE_ATTENUATION, vec![2.0]),
                C::PointParameteri(gl::POINT_SPRITE_COORD_ORIGIN, gl::LEFT as i32),
                C::PointParameterf(gl::POINT_SIZE, 3.0),
                C::PointParameterfv(gl::LINE_WIDTH, vec![3.0]),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 2),
                C::TexEnvi(gl::POINT_SPRITE, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32),
                C::Hint(gl::POINT_SMOOTH_HINT, gl::LINE),
                C::Begin(gl::POINTS),
                C::PointParameterf(gl::POINT_SIZE_MIN, 4.0),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1),
                C::End,
            ],
        ),
        (
            "display list",
            vec![
                C::NewList(1, gl::COMPILE),
                C::PointParameterf(gl::POINT_SIZE_MAX, 9.0),
                C::PointParameterfv(gl::POINT_DISTANCE_ATTENUATION, vec![0.0, 1.0, 0.0]),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1),
                C::PointParameterf(gl::POINT_SIZE_MIN, -3.0),
                C::EndList,
                C::PointParameterf(gl::POINT_SIZE_MAX, 20.0),
                C::CallList(1),
            ],
        ),
        (
            "attribute groups",
            vec![
                C::PushAttrib(gl::POINT_BIT),
                C::PointParameterf(gl::POINT_SIZE_MIN, 2.0),
                C::PointParameteri(gl::POINT_SPRITE_COORD_ORIGIN, gl::LOWER_LEFT as i32),
                C::PointParameterfv(gl::POINT_DISTANCE_ATTENUATION, vec![0.0, 0.0, 1.0]),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1),
                C::Enable(gl::POINT_SPRITE),
                C::PopAttrib,
                C::PushAttrib(gl::TEXTURE_BIT | gl::ENABLE_BIT),
                C::ActiveTexture(gl::TEXTURE1),
                C::TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1),
                C::ActiveTexture(gl::TEXTURE0),
                C::Enable(gl::POINT_SMOOTH),
                C::Enable(gl::POINT_SPRITE),
                C::PopAttrib,
                C::PushAttrib(gl::HINT_BIT),
                C::Hint(gl::LINE_SMOOTH_HINT, gl::NICEST),
                C::PopAttrib,
            ],
        ),
    ]
}

#[test]
fn point_state_on_the_front_end() {
    let mut c = ctx();
    let v = cpu_values(&mut c);
    // POINT_SIZE 1, MIN 0, MAX 255, FADE 1, attenuation 1 0 0, origin UPPER_LEFT.
    assert_eq!(
        v[..8],
        [1.0, 0.0, 255.0, 1.0, 1.0, 0.0, 0.0, gl::UPPER_LEFT as f32]
    );
    c.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[1.0, 2.0]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.point_parameterf(gl::POINT_SIZE_MIN, -1.0);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(cpu_values(&mut c), v, "errors change nothing");
    // The scalar form takes the three-valued pname as Mesa does: [param, 0, 0].
    c.point_parameterf(gl::POINT_DISTANCE_ATTENUATION, 0.5);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(cpu_values(&mut c)[4..7], [0.5, 0.0, 0.0]);
}

#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;

    fn driver_values(gl: &mut fixedgl::glbackend::GlBackend) -> Vec<f32> {
        let mut out = Vec::new();
        // SAFETY: the backend's context is current; only queries and ActiveTexture follow.
        let raw = unsafe { gl.raw() };
        for &(pname, n) in QUERIES {
            let mut v = vec![f32::NAN; n.max(4)];
            // SAFETY: each pname writes at most `n` <= 4 floats.
            unsafe { raw.GetFloatv(pname, v.as_mut_ptr()) };
            out.extend(&v[..n]);
        }
        for unit in 0..4 {
            let mut v = -1;
            // SAFETY: one integer.
            unsafe {
                raw.ActiveTexture(gl::TEXTURE0 + unit);
                raw.GetTexEnviv(gl::POINT_SPRITE, gl::COORD_REPLACE, &mut v);
            }
            out.push(v as f32);
        }
        // SAFETY: no pointer.
        unsafe { raw.ActiveTexture(gl::TEXTURE0) };
        out
    }

    #[test]
    fn point_state_errors_lists_and_attributes_agree_with_the_driver() {
        for (name, calls) in sequences() {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            for call in &calls {
                c.execute(call);
                gl.execute(call);
                assert_eq!(c.get_error(), gl.get_error(), "{name}: {call:?}");
            }
            assert_eq!(cpu_values(&mut c), driver_values(&mut gl), "{name}");
        }
    }

    type Draw = fn(&mut Context);

    fn ortho(c: &mut Context) {
        c.matrix_mode(gl::PROJECTION);
        c.load_identity();
        c.ortho(0.0, f64::from(SIZE), 0.0, f64::from(SIZE), -1.0, 1.0);
        c.matrix_mode(gl::MODELVIEW);
        c.enable(gl::BLEND);
        c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
        c.clear_color(0.1, 0.2, 0.3, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
    }

    fn perspective(c: &mut Context) {
        c.clear_color(0.1, 0.2, 0.3, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.matrix_mode(gl::PROJECTION);
        c.load_identity();
        c.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
        c.matrix_mode(gl::MODELVIEW);
        c.load_identity();
    }

    fn row_of_points(c: &mut Context) {
        c.begin(gl::POINTS);
        for i in 0..10 {
            let f = i as f32;
            c.color4f(1.0, 0.2 + 0.08 * f, 0.3, 0.8);
            c.vertex3f(-1.0 + 0.23 * f, 0.9 - 0.2 * f, -1.5 - 0.9 * f);
        }
        c.end();
    }

    /// An 8x8 texture of distinct texels, NEAREST, on unit 0 with COORD_REPLACE and sprites on.
    fn sprite_texture(c: &mut Context) {
        let mut t = [0u32];
        c.gen_textures(1, &mut t);
        c.bind_texture(gl::TEXTURE_2D, t[0]);
        let mut px = Vec::new();
        for y in 0..8u8 {
            for x in 0..8u8 {
                px.extend([x * 32, y * 32, 255 - (x ^ y) * 16, 255]);
            }
        }
        c.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            8,
            8,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Some(&px),
        );
        c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
        c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
        c.enable(gl::TEXTURE_2D);
        c.tex_envi(gl::POINT_SPRITE, gl::COORD_REPLACE, 1);
        c.enable(gl::POINT_SPRITE);
    }

    fn pictures() -> Vec<(&'static str, Draw)> {
        vec![
            ("smooth points", |c| {
                ortho(c);
                c.enable(gl::POINT_SMOOTH);
                for (i, s) in [1.0f32, 2.0, 2.5, 3.0, 4.5, 7.0, 10.0, 13.0]
                    .iter()
                    .enumerate()
                {
                    c.point_size(*s);
                    c.begin(gl::POINTS);
                    c.color4f(1.0, 0.8, 0.2, if i % 2 == 0 { 1.0 } else { 0.5 });
                    let f = i as f32;
                    c.vertex2f(
                        6.0 + (f % 4.0) * 15.0 + 0.13 * f,
                        10.0 + (f / 4.0).floor() * 30.0 + 0.31 * f,
                    );
                    c.end();
                }
            }),
            ("smooth points, size clamped and as polygon vertices", |c| {
                ortho(c);
                c.enable(gl::POINT_SMOOTH);
                c.point_parameterf(gl::POINT_SIZE_MAX, 6.0);
                c.point_size(20.0);
                c.polygon_mode(gl::FRONT_AND_BACK, gl::POINT);
                c.begin(gl::TRIANGLES);
                c.color4f(0.2, 1.0, 0.5, 0.7);
                c.vertex2f(10.2, 10.7);
                c.vertex2f(50.5, 12.0);
                c.vertex2f(30.0, 50.25);
                c.end();
            }),
            ("smooth lines", |c| {
                ortho(c);
                c.enable(gl::LINE_SMOOTH);
                c.shade_model(gl::SMOOTH);
                for (i, w) in [0.5f32, 1.0, 2.0, 3.5, 6.0].iter().enumerate() {
                    c.line_width(*w);
                    c.begin(gl::LINE_STRIP);
                    let f = i as f32;
                    c.color4f(1.0, 1.0, 1.0, 1.0);
                    c.vertex2f(3.0 + 0.2 * f, 5.0 + 12.0 * f);
                    c.color4f(1.0, 0.3, 0.3, 0.6);
                    c.vertex2f(40.0, 8.0 + 11.0 * f + 0.3);
                    c.vertex2f(60.0 - f, 60.0 - 3.0 * f);
                    c.end();
                }
            }),
            ("attenuated points", |c| {
                perspective(c);
                c.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[0.0, 0.2, 0.05]);
                c.point_parameterf(gl::POINT_SIZE_MAX, 14.0);
                c.point_size(18.0);
                row_of_points(c);
            }),
            ("attenuated smooth points", |c| {
                perspective(c);
                c.enable(gl::POINT_SMOOTH);
                c.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[0.5, 0.1, 0.02]);
                c.point_size(14.0);
                row_of_points(c);
            }),
            ("sprites, upper left", |c| {
                sprite_texture(c);
                perspective(c);
                c.point_parameterfv(gl::POINT_DISTANCE_ATTENUATION, &[0.0, 0.15, 0.02]);
                c.point_size(24.0);
                row_of_points(c);
            }),
            ("sprites, lower left, plain size", |c| {
                sprite_texture(c);
                perspective(c);
                c.point_parameteri(gl::POINT_SPRITE_COORD_ORIGIN, gl::LOWER_LEFT as i32);
                for (i, s) in [3.0f32, 6.5, 9.0, 12.25].iter().enumerate() {
                    c.point_size(*s);
                    c.begin(gl::POINTS);
                    c.vertex3f(-0.6 + 0.4 * i as f32, 0.1 * i as f32 - 0.2, -2.0);
                    c.end();
                }
            }),
            ("polygon smooth", |c| {
                ortho(c);
                c.enable(gl::POLYGON_SMOOTH);
                c.begin(gl::TRIANGLES);
                c.color4f(0.9, 0.9, 0.2, 0.6);
                c.vertex2f(3.3, 4.1);
                c.vertex2f(60.7, 13.9);
                c.vertex2f(25.1, 58.3);
                c.end();
            }),
        ]
    }

    #[test]
    fn smooth_pictures_match_the_driver() {
        for (name, draw) in pictures() {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            c.start_recording();
            draw(&mut c);
            let calls = c.stop_recording();
            gl.replay(&calls);
            assert_eq!(gl.get_error(), gl::NO_ERROR, "{name}");
            let cmp = compare(&c.to_image(), &gl.read_image(), 2);
            assert_eq!(cmp.differing_pixels, 0, "{name}: max {:?}", cmp.max_diff);
        }
    }
}
