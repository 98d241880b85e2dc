//! The scalar forms (f, i, d) of Light, LightModel, Fog, PointParameter, TexParameter, TexEnv and
//! TexGen given a multi-valued pname: GL 2.1 says INVALID_ENUM, Mesa takes the value as the first
//! of the vector form's values, zeros after it, and piglit's gl-1.0-beginend-coverage relies on
//! it. The CPU front end stores `[param, 0, 0, 0]`; the GL backend sends the driver that vector.
//! The stored values, and pictures drawn with them, are held against the driver.

use crate::common::{cpu_vs_gl, test_backend};
use fixedgl::{gl, Context};

/// The scalar calls under test, none an error.
fn scalar_calls(c: &mut Context) {
    c.light_modelf(gl::LIGHT_MODEL_AMBIENT, 0.25);
    c.light_modeli(gl::LIGHT_MODEL_AMBIENT, 0);
    c.light_modelf(gl::LIGHT_MODEL_AMBIENT, 0.3);
    c.lightf(gl::LIGHT0, gl::DIFFUSE, 0.75);
    c.lighti(gl::LIGHT0, gl::SPECULAR, 0);
    c.lightf(gl::LIGHT0, gl::POSITION, 1.0);
    c.fogf(gl::FOG_COLOR, 0.5);
    c.point_parameteri(gl::POINT_DISTANCE_ATTENUATION, 2);
    c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, 0.5);
    c.tex_envf(gl::TEXTURE_ENV, gl::TEXTURE_ENV_COLOR, 0.75);
    c.tex_gend(gl::S, gl::OBJECT_PLANE, 0.5);
    c.tex_geni(gl::T, gl::OBJECT_PLANE, 0);
    c.tex_genf(gl::T, gl::EYE_PLANE, 2.0);
}

#[test]
fn scalar_forms_store_the_vector_with_zeros() {
    let Ok(mut c) = Context::new(8, 8) else {
        panic!("context")
    };
    scalar_calls(&mut c);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let mut v = [9.0f32; 4];
    c.get_floatv(gl::LIGHT_MODEL_AMBIENT, &mut v);
    assert_eq!(v, [0.3, 0.0, 0.0, 0.0]);
    c.get_lightfv(gl::LIGHT0, gl::DIFFUSE, &mut v);
    assert_eq!(v, [0.75, 0.0, 0.0, 0.0]);
    c.get_lightfv(gl::LIGHT0, gl::POSITION, &mut v);
    assert_eq!(v, [1.0, 0.0, 0.0, 0.0]);
    c.get_floatv(gl::FOG_COLOR, &mut v);
    assert_eq!(v, [0.5, 0.0, 0.0, 0.0]);
    let mut a = [9.0f32; 3];
    c.get_floatv(gl::POINT_DISTANCE_ATTENUATION, &mut a);
    assert_eq!(a, [2.0, 0.0, 0.0]);
    c.get_tex_parameterfv(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, &mut v);
    assert_eq!(v, [0.5, 0.0, 0.0, 0.0]);
    c.get_tex_envfv(gl::TEXTURE_ENV, gl::TEXTURE_ENV_COLOR, &mut v);
    assert_eq!(v, [0.75, 0.0, 0.0, 0.0]);
    c.get_tex_genfv(gl::S, gl::OBJECT_PLANE, &mut v);
    assert_eq!(v, [0.5, 0.0, 0.0, 0.0]);
    c.get_tex_genfv(gl::T, gl::EYE_PLANE, &mut v);
    assert_eq!(v, [2.0, 0.0, 0.0, 0.0]);
    // The first argument is still checked, and an error changes nothing.
    c.lightf(gl::LIGHT0 + 8, gl::AMBIENT, 1.0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.tex_genf(gl::TEXTURE_2D, gl::OBJECT_PLANE, 1.0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.tex_parameterf(gl::LIGHT0, gl::TEXTURE_BORDER_COLOR, 1.0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.get_lightfv(gl::LIGHT0, gl::AMBIENT, &mut v);
    assert_eq!(v, [0.0, 0.0, 0.0, 1.0]);
    c.get_tex_genfv(gl::S, gl::OBJECT_PLANE, &mut v);
    assert_eq!(v, [0.5, 0.0, 0.0, 0.0]);
    c.get_tex_parameterfv(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, &mut v);
    assert_eq!(v, [0.5, 0.0, 0.0, 0.0]);
}

#[cfg(feature = "gl")]
#[test]
fn the_driver_holds_the_same_values() {
    let Some(mut gl_) = test_backend(8, 8) else {
        return;
    };
    let Ok(mut c) = Context::new(8, 8) else {
        panic!("context")
    };
    c.start_recording();
    scalar_calls(&mut c);
    gl_.replay(&c.stop_recording());
    assert_eq!(gl_.get_error(), gl::NO_ERROR);
    for pname in [gl::LIGHT_MODEL_AMBIENT, gl::FOG_COLOR] {
        let (mut a, mut b) = ([9.0f32; 4], [8.0f32; 4]);
        c.get_floatv(pname, &mut a);
        gl_.get_floatv(pname, &mut b);
        assert_eq!(a, b, "pname {pname:#x}");
    }
    let (mut a, mut b) = ([9.0f32; 3], [8.0f32; 3]);
    c.get_floatv(gl::POINT_DISTANCE_ATTENUATION, &mut a);
    gl_.get_floatv(gl::POINT_DISTANCE_ATTENUATION, &mut b);
    assert_eq!(a, b);
    let (mut a, mut b) = ([9.0f32; 4], [8.0f32; 4]);
    c.get_tex_parameterfv(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, &mut a);
    gl_.get_tex_parameterfv(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, &mut b);
    assert_eq!(a, b);
}

/// A lit quad (LIGHT0 and the light model ambient set through the scalar forms), then a
/// texture-generated, BLEND-textured, fogged quad whose coordinates reach the border colour.
#[cfg(feature = "gl")]
#[test]
fn pictures_drawn_with_scalar_vector_pnames_match_the_driver() {
    let r = cpu_vs_gl(32, 1, |c| {
        c.clear_color(0.1, 0.2, 0.3, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.enable(gl::LIGHTING);
        c.enable(gl::LIGHT0);
        c.light_modelf(gl::LIGHT_MODEL_AMBIENT, 0.3);
        c.lightf(gl::LIGHT0, gl::DIFFUSE, 0.75);
        c.lightf(gl::LIGHT0, gl::POSITION, 1.0);
        c.materialf(gl::FRONT, gl::AMBIENT, 1.0);
        c.normal3f(0.6, 0.0, 0.8);
        c.rectf(-1.0, -1.0, 0.0, 1.0);
        c.disable(gl::LIGHTING);
        let texels: Vec<u8> = (0..16).map(|i| if i % 3 == 0 { 255 } else { 40 }).collect();
        c.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::LUMINANCE as i32,
            4,
            4,
            0,
            gl::LUMINANCE,
            gl::UNSIGNED_BYTE,
            Some(&texels),
        );
        for (p, v) in [
            (gl::TEXTURE_MIN_FILTER, gl::NEAREST),
            (gl::TEXTURE_MAG_FILTER, gl::NEAREST),
            (gl::TEXTURE_WRAP_S, gl::CLAMP_TO_BORDER),
            (gl::TEXTURE_WRAP_T, gl::CLAMP_TO_BORDER),
        ] {
            c.tex_parameteri(gl::TEXTURE_2D, p, v as i32);
        }
        c.tex_parameterf(gl::TEXTURE_2D, gl::TEXTURE_BORDER_COLOR, 0.5);
        c.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::BLEND as i32);
        c.tex_envf(gl::TEXTURE_ENV, gl::TEXTURE_ENV_COLOR, 0.75);
        c.tex_geni(gl::S, gl::TEXTURE_GEN_MODE, gl::OBJECT_LINEAR as i32);
        c.tex_genf(gl::S, gl::OBJECT_PLANE, 1.5);
        c.enable(gl::TEXTURE_GEN_S);
        c.enable(gl::TEXTURE_2D);
        c.enable(gl::FOG);
        c.fogi(gl::FOG_MODE, gl::LINEAR as i32);
        c.fogf(gl::FOG_START, 0.0);
        c.fogf(gl::FOG_END, 2.0);
        c.fogf(gl::FOG_COLOR, 0.5);
        c.color3f(0.2, 0.9, 0.4);
        c.tex_coord2f(0.0, 0.4);
        c.rectf(0.0, -1.0, 1.0, 1.0);
    });
    if let Some((n, first)) = r {
        assert_eq!(n, 0, "{first}");
    }
}
