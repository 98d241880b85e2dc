//! What valid set-side calls store. Expected values are worked by hand from the GL 2.1 formulas
//! cited on each test (errors are tested in `tests/errors.rs`).

use glam::{Mat4, Vec3, Vec4};

use super::Context;
use crate::gl;
use crate::state::{BACK, FRONT};

fn ctx() -> Context {
    match Context::new(8, 8) {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    }
}

/// 90° about z, column-major: x → y, y → -x.
const ROT_Z90: [f32; 16] = [
    0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// §2.14.2: POSITION is multiplied by the modelview matrix current at the call.
#[test]
fn light_position_is_stored_in_eye_coordinates() {
    let mut c = ctx();
    *c.state.modelview.top_mut() = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
    c.lightfv(gl::LIGHT2, gl::POSITION, &[1.0, 1.5, -0.5, 1.0]);
    assert_eq!(c.state.lights[2].position, Vec4::new(2.0, 3.5, 2.5, 1.0));
    // A direction (w = 0) ignores the translation.
    c.lightfv(gl::LIGHT3, gl::POSITION, &[0.0, 0.0, 1.0, 0.0]);
    assert_eq!(c.state.lights[3].position, Vec4::new(0.0, 0.0, 1.0, 0.0));
    // Changing the matrix afterwards does not move the light.
    *c.state.modelview.top_mut() = Mat4::IDENTITY;
    assert_eq!(c.state.lights[2].position, Vec4::new(2.0, 3.5, 2.5, 1.0));
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// §2.14.2: SPOT_DIRECTION is multiplied by the upper 3x3 of the modelview matrix.
#[test]
fn spot_direction_uses_the_upper_3x3() {
    let mut c = ctx();
    *c.state.modelview.top_mut() =
        Mat4::from_translation(Vec3::new(5.0, 6.0, 7.0)) * Mat4::from_cols_array(&ROT_Z90);
    c.lightfv(gl::LIGHT0, gl::SPOT_DIRECTION, &[1.0, 0.0, 0.0]);
    assert_eq!(c.state.lights[0].spot_direction, Vec3::new(0.0, 1.0, 0.0));
    c.lightiv(gl::LIGHT0, gl::POSITION, &[1, 0, 0, 1]);
    assert_eq!(c.state.lights[0].position, Vec4::new(5.0, 7.0, 7.0, 1.0));
}

/// §2.14.2: integer colours map linearly, (2c+1)/(2^32-1); other integers convert directly.
#[test]
fn integer_light_parameters() {
    let mut c = ctx();
    c.lightiv(gl::LIGHT1, gl::AMBIENT, &[i32::MAX, i32::MIN, 0, -1]);
    let expected = [
        1.0,
        -1.0,
        (1.0 / 4294967295.0f64) as f32,
        (-1.0 / 4294967295.0f64) as f32,
    ];
    assert_eq!(c.state.lights[1].ambient.to_array(), expected);
    c.lighti(gl::LIGHT1, gl::SPOT_CUTOFF, 45);
    c.lighti(gl::LIGHT1, gl::SPOT_EXPONENT, 128);
    c.lightf(gl::LIGHT1, gl::QUADRATIC_ATTENUATION, 0.25);
    c.lightf(gl::LIGHT1, gl::SPOT_CUTOFF, 180.0);
    let l = &c.state.lights[1];
    assert_eq!((l.spot_cutoff, l.spot_exponent), (180.0, 128.0));
    assert_eq!(l.quadratic_attenuation, 0.25);
    c.light_modeliv(gl::LIGHT_MODEL_AMBIENT, &[i32::MAX, 0, i32::MAX, i32::MIN]);
    assert_eq!(c.state.light_model.ambient.x, 1.0);
    assert_eq!(c.state.light_model.ambient.w, -1.0);
    c.light_modeli(gl::LIGHT_MODEL_LOCAL_VIEWER, 5);
    c.light_modelf(gl::LIGHT_MODEL_TWO_SIDE, 1.0);
    c.light_modelf(
        gl::LIGHT_MODEL_COLOR_CONTROL,
        gl::SEPARATE_SPECULAR_COLOR as f32,
    );
    let lm = c.state.light_model;
    assert!(lm.local_viewer && lm.two_side);
    assert_eq!(lm.color_control, gl::SEPARATE_SPECULAR_COLOR);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn materials_by_face() {
    let mut c = ctx();
    c.materialfv(
        gl::FRONT_AND_BACK,
        gl::AMBIENT_AND_DIFFUSE,
        &[0.1, 0.2, 0.3, 0.4],
    );
    c.materialiv(
        gl::BACK,
        gl::SPECULAR,
        &[i32::MAX, i32::MAX, i32::MIN, i32::MAX],
    );
    c.materiali(gl::FRONT, gl::SHININESS, 100);
    c.materialfv(gl::FRONT, gl::COLOR_INDEXES, &[1.0, 2.0, 3.0]);
    let [f, b] = c.state.materials;
    let v = Vec4::new(0.1, 0.2, 0.3, 0.4);
    assert_eq!((f.ambient, f.diffuse, b.ambient, b.diffuse), (v, v, v, v));
    assert_eq!(b.specular, Vec4::new(1.0, 1.0, -1.0, 1.0));
    assert_eq!(f.specular, Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert_eq!((f.shininess, b.shininess), (100.0, 0.0));
    assert_eq!(f.color_indexes, [1.0, 2.0, 3.0]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// The scalar forms take a vector pname as Mesa does (piglit gl-1.0-beginend-coverage): the
/// value first, zeros after it, inside Begin/End too; the face and pname are still checked.
#[test]
fn scalar_material_forms_take_vector_pnames() {
    let mut c = ctx();
    c.materialfv(gl::FRONT_AND_BACK, gl::SPECULAR, &[0.5; 4]);
    c.materialf(gl::FRONT, gl::AMBIENT, 0.25);
    c.materiali(gl::BACK, gl::DIFFUSE, 2);
    c.materialf(gl::FRONT_AND_BACK, gl::EMISSION, 0.75);
    c.materialf(gl::FRONT, gl::COLOR_INDEXES, 4.0);
    c.begin(gl::POINTS);
    c.materialf(gl::FRONT_AND_BACK, gl::SPECULAR, 0.5);
    c.materiali(gl::FRONT, gl::AMBIENT_AND_DIFFUSE, 0);
    c.end();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let [f, b] = c.state.materials;
    assert_eq!(f.ambient, Vec4::ZERO);
    assert_eq!(f.diffuse, Vec4::ZERO);
    assert_eq!(b.ambient, Vec4::new(0.2, 0.2, 0.2, 1.0));
    // Materiali converts as a float, not as a normalised colour.
    assert_eq!(b.diffuse, Vec4::new(2.0, 0.0, 0.0, 0.0));
    assert_eq!(f.emission, Vec4::new(0.75, 0.0, 0.0, 0.0));
    assert_eq!(b.emission, f.emission);
    assert_eq!(f.specular, Vec4::new(0.5, 0.0, 0.0, 0.0));
    assert_eq!(b.specular, f.specular);
    assert_eq!(f.color_indexes, [4.0, 0.0, 0.0]);
    // Still errors: a bad face, a non-material pname, and shininess out of range.
    let before = c.state.materials;
    c.materialf(gl::LEFT, gl::AMBIENT, 1.0);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.materiali(gl::FRONT, gl::POSITION, 1);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.materialf(gl::FRONT, gl::SHININESS, 129.0);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(c.state.materials, before);
}

/// ClearIndex and IndexMask store their values (Mesa's `(GLuint) c` truncation; a negative or
/// NaN index is 0) and change nothing an RGBA framebuffer uses; INVALID_OPERATION inside.
#[test]
fn clear_index_and_index_mask() {
    let mut c = ctx();
    assert_eq!(
        (c.state.clear_index, c.state.index_writemask),
        (0, u32::MAX)
    );
    let before = c.state.clone();
    c.clear_index(7.9);
    c.index_mask(0x0f);
    assert_eq!((c.state.clear_index, c.state.index_writemask), (7, 0x0f));
    let mut s = c.state.clone();
    (s.clear_index, s.index_writemask) = (before.clear_index, before.index_writemask);
    assert_eq!(s, before);
    let mut v = [0.0f32];
    c.get_floatv(gl::INDEX_CLEAR_VALUE, &mut v);
    assert_eq!(v, [7.0]);
    let mut m = [0i32];
    c.get_integerv(gl::INDEX_WRITEMASK, &mut m);
    assert_eq!(m, [0x0f]);
    for bad in [-3.0, f32::NAN] {
        c.clear_index(bad);
        assert_eq!(c.state.clear_index, 0);
    }
    c.begin(gl::POINTS);
    c.clear_index(2.0);
    c.index_mask(1);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!((c.state.clear_index, c.state.index_writemask), (0, 0x0f));
}

/// §2.14.3: with COLOR_MATERIAL on, the selected material values track the current colour
/// from the Enable, on every Color call and on ColorMaterial; Material cannot override them.
#[test]
fn color_material_tracks_the_current_colour() {
    let mut c = ctx();
    c.color4f(0.1, 0.2, 0.3, 0.4);
    let before = c.state.materials;
    assert_eq!(
        before[FRONT].ambient,
        Vec4::new(0.2, 0.2, 0.2, 1.0),
        "off: no tracking"
    );
    c.enable(gl::COLOR_MATERIAL);
    let v = Vec4::new(0.1, 0.2, 0.3, 0.4);
    for face in [FRONT, BACK] {
        assert_eq!(c.state.materials[face].ambient, v);
        assert_eq!(c.state.materials[face].diffuse, v);
    }
    c.color3ub(255, 0, 51);
    let red = Vec4::new(1.0, 0.0, 0.2, 1.0);
    assert_eq!(c.state.materials[BACK].diffuse, red);
    c.color_material(gl::FRONT, gl::EMISSION);
    assert_eq!(c.state.materials[FRONT].emission, red);
    assert_eq!(
        c.state.materials[BACK].emission,
        Vec4::new(0.0, 0.0, 0.0, 1.0)
    );
    // Tracked (front emission) ignored; untracked (back emission, front specular) applied.
    c.materialfv(gl::FRONT_AND_BACK, gl::EMISSION, &[0.5, 0.5, 0.5, 1.0]);
    c.materialfv(gl::FRONT, gl::SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    assert_eq!(c.state.materials[FRONT].emission, red);
    assert_eq!(
        c.state.materials[BACK].emission,
        Vec4::new(0.5, 0.5, 0.5, 1.0)
    );
    assert_eq!(
        c.state.materials[FRONT].specular,
        Vec4::new(0.5, 0.5, 0.5, 1.0)
    );
    c.disable(gl::COLOR_MATERIAL);
    c.color3f(0.0, 0.0, 0.0);
    assert_eq!(
        c.state.materials[FRONT].emission, red,
        "off again: no tracking"
    );
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// Table 2.9, and §2.7's defaults for components a command leaves out.
#[test]
fn attribute_conversions() {
    let mut c = ctx();
    c.normal3s(32767, -32768, 0);
    assert_eq!(
        c.state.current.normal,
        Vec3::new(1.0, -1.0, (1.0 / 65535.0f64) as f32)
    );
    c.normal3bv(&[127, -128, -1]);
    assert_eq!(
        c.state.current.normal,
        Vec3::new(1.0, -1.0, (-1.0 / 255.0f64) as f32)
    );
    c.normal3d(0.5, 0.25, 2.0);
    assert_eq!(c.state.current.normal, Vec3::new(0.5, 0.25, 2.0));
    c.color3ub(255, 0, 51);
    assert_eq!(c.state.current.color, Vec4::new(1.0, 0.0, 0.2, 1.0));
    c.color4usv(&[65535, 0, 0, 0]);
    assert_eq!(c.state.current.color, Vec4::new(1.0, 0.0, 0.0, 0.0));
    c.color4i(i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    assert_eq!(c.state.current.color, Vec4::new(1.0, -1.0, 1.0, -1.0));
    c.tex_coord1i(5);
    assert_eq!(c.state.current.tex_coords[0], Vec4::new(5.0, 0.0, 0.0, 1.0));
    c.tex_coord3sv(&[1, 2, 3]);
    assert_eq!(c.state.current.tex_coords[0], Vec4::new(1.0, 2.0, 3.0, 1.0));
    c.tex_coord4d(1.0, 2.0, 3.0, 4.0);
    assert_eq!(c.state.current.tex_coords[0], Vec4::new(1.0, 2.0, 3.0, 4.0));
    assert_eq!(c.state.current.tex_coords[1], Vec4::new(0.0, 0.0, 0.0, 1.0));
    c.secondary_color3ub(255, 0, 51);
    assert_eq!(
        c.state.current.secondary_color,
        Vec4::new(1.0, 0.0, 0.2, 1.0)
    );
    c.fog_coordd(2.5);
    assert_eq!(c.state.current.fog_coord, 2.5);
    c.edge_flagv(&[false]);
    assert!(!c.state.current.edge_flag);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn raster_framebuffer_and_control_state() {
    let mut c = ctx();
    c.polygon_mode(gl::FRONT, gl::LINE);
    assert_eq!(c.state.polygon_mode, [gl::LINE, gl::FILL]);
    c.polygon_mode(gl::FRONT_AND_BACK, gl::POINT);
    assert_eq!(c.state.polygon_mode, [gl::POINT, gl::POINT]);
    c.front_face(gl::CW);
    c.cull_face(gl::FRONT_AND_BACK);
    c.polygon_offset(1.5, -2.0);
    c.point_size(4.0);
    c.line_width(0.5);
    let s = &c.state;
    assert_eq!(
        (s.front_face, s.cull_face_mode),
        (gl::CW, gl::FRONT_AND_BACK)
    );
    assert_eq!(
        (s.polygon_offset_factor, s.polygon_offset_units),
        (1.5, -2.0)
    );
    assert_eq!((s.point_size, s.line_width), (4.0, 0.5));
    // §4.2.3: clear values are clamped to [0, 1].
    c.clear_color(-1.0, 2.0, 0.5, 1.0);
    c.clear_depth(7.0);
    assert_eq!(c.state.clear_color, Vec4::new(0.0, 1.0, 0.5, 1.0));
    assert_eq!(c.state.clear_depth, 1.0);
    c.clear_depth(-7.0);
    assert_eq!(c.state.clear_depth, 0.0);
    c.clear_stencil(-3);
    c.depth_func(gl::GEQUAL);
    c.depth_mask(false);
    c.color_mask(true, false, true, false);
    c.scissor(-5, -6, 0, 7);
    c.clear(gl::COLOR_BUFFER_BIT | gl::ACCUM_BUFFER_BIT);
    let s = &c.state;
    assert_eq!(
        (s.clear_stencil, s.depth_func, s.depth_mask),
        (-3, gl::GEQUAL, false)
    );
    assert_eq!(s.color_mask, [true, false, true, false]);
    assert_eq!(s.scissor, [-5, -6, 0, 7]);
    c.hint(gl::PHONG_HINT_WIN, gl::NICEST);
    c.hint(gl::GENERATE_MIPMAP_HINT, gl::FASTEST);
    c.pixel_storef(gl::UNPACK_ALIGNMENT, 2.4);
    c.pixel_storei(gl::PACK_ALIGNMENT, 8);
    c.shade_model(gl::PHONG_WIN);
    c.flush();
    c.finish();
    let s = &c.state;
    assert_eq!(
        (s.hints.phong, s.hints.generate_mipmap),
        (gl::NICEST, gl::FASTEST)
    );
    assert_eq!((s.unpack.alignment, s.pack.alignment), (2, 8));
    assert_eq!(s.shade_model, gl::PHONG_WIN);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn finish_rasterises_the_scene_and_flush_does_not() {
    let mut c = Context::new(16, 16).expect("context");
    let passes = |c: &Context| c.draw_stats().passes;
    c.begin(gl::TRIANGLES);
    c.vertex2f(-1.0, -1.0);
    c.vertex2f(1.0, -1.0);
    c.vertex2f(0.0, 1.0);
    c.end();
    c.flush();
    // The triangle waits in the scene after a flush...
    assert_eq!(passes(&c), 0);
    // ...and is in the framebuffer when Finish returns: one pass, none for nothing new.
    c.finish();
    assert_eq!(passes(&c), 1);
    c.finish();
    assert_eq!(passes(&c), 1);
    // Between Begin and End, Finish is INVALID_OPERATION and draws nothing.
    c.begin(gl::POINTS);
    c.vertex2f(0.0, 0.0);
    c.finish();
    assert_eq!(passes(&c), 1);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let img = c.to_image();
    assert_eq!(img.get_pixel(8, 8).0, [255, 255, 255, 255]);
}

/// The replay loop's two builds (`Route::Baseline`, and `Route::Avx2` where the CPU has AVX2:
/// the immediate-mode vertex path and its batching compiled with AVX2) draw the same image, byte
/// for byte, for scenes of many kinds: lit strips and a vertex cache that shares vertices
/// (gauss-smooth-400, light-model), display lists, evaluators, bitmaps, textures, fog, two-sided
/// lighting, materials inside Begin/End.
#[test]
fn both_replay_routes_draw_the_same_image() {
    use crate::cpu::vertex::Route;
    let wide = Route::best();
    if wide != Route::Avx2 {
        eprintln!("no AVX2 on this CPU: the baseline route is compared with itself");
    }
    let names = [
        "gauss-smooth-400",
        "light-model",
        "display-list",
        "evaluators",
        "bitmap-text",
        "textured-cube",
        "fog",
        "two-side",
        "materials",
        "eight-lights",
    ];
    for name in names {
        let Some(scene) = crate::scenes::find(name) else {
            panic!("no scene {name}");
        };
        let (w, h) = (97, 71);
        let calls = match scene.record(w, h) {
            Ok((_, calls)) => calls,
            Err(e) => panic!("{name}: {e}"),
        };
        let image = |route| {
            let mut c = match Context::with_config(w, h, scene.config) {
                Ok(c) => c,
                Err(e) => panic!("{e}"),
            };
            c.replay_by(&calls, route);
            c.to_image().into_raw()
        };
        let base = image(Route::Baseline);
        assert!(base.iter().any(|&b| b != base[0]), "{name}: a blank image");
        assert!(base == image(wide), "{name}: the routes' images differ");
    }
}

/// `execute` runs Vertex3fv, Normal3fv and TexCoord2fv as their scalar forms when nothing
/// records: the image and the current attributes are those of the calls run one by one
/// through `execute_any` (every variant's own method), and a recording context still records
/// the vector forms. render-to-texture's GLUT teapot and torus send all three, and a script of
/// awkward values (NaN, -0, huge) checks the conversions bit for bit.
#[test]
fn vector_forms_run_as_their_calls() {
    use crate::call::Call;
    use crate::cpu::testgen::Gen;
    let Some(scene) = crate::scenes::find("render-to-texture") else {
        panic!("no scene render-to-texture");
    };
    let (w, h) = (97, 71);
    let mut calls = match scene.record(w, h) {
        Ok((_, calls)) => calls,
        Err(e) => panic!("{e}"),
    };
    let is_vector = |c: &Call| {
        matches!(
            c,
            Call::Vertex3fv(..) | Call::Normal3fv(..) | Call::TexCoord2fv(..)
        )
    };
    assert!(calls.iter().filter(|c| is_vector(c)).count() > 1000);
    // A few points with awkward attributes, drawn after the scene.
    let mut g = Gen(16);
    calls.push(Call::Begin(gl::POINTS));
    for _ in 0..200 {
        let v = [g.float(), g.float(), g.float()];
        calls.push(match g.next() % 3 {
            0 => Call::TexCoord2fv([v[0], v[1]]),
            1 => Call::Normal3fv(v),
            _ => Call::Vertex3fv([v[0] * 0.1, v[1] * 0.1, v[2] * 0.1]),
        });
    }
    calls.push(Call::End);
    let run = |one_by_one: bool| {
        let mut c = match Context::with_config(w, h, scene.config) {
            Ok(c) => c,
            Err(e) => panic!("{e}"),
        };
        if one_by_one {
            for call in &calls {
                c.execute_any(call);
            }
        } else {
            c.replay(&calls);
        }
        let cur = c.state.current;
        let bits = |v: Vec4| v.to_array().map(f32::to_bits);
        let attrs = (
            bits(cur.tex_coords[0]),
            cur.normal.to_array().map(f32::to_bits),
        );
        (c.to_image().into_raw(), attrs)
    };
    let (fast, slow) = (run(false), run(true));
    assert!(fast.0.iter().any(|&b| b != fast.0[0]), "a blank image");
    assert!(fast == slow, "execute and execute_any differ");
    // Replayed into a recording context, the vector forms are recorded as themselves.
    let mut c = match Context::with_config(w, h, scene.config) {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    };
    c.start_recording();
    c.replay(&calls);
    let again = c.stop_recording();
    // (Compared as text: a NaN is not equal to itself.)
    let vectors = |cs: &[Call]| {
        format!(
            "{:?}",
            cs.iter().filter(|c| is_vector(c)).collect::<Vec<_>>()
        )
    };
    assert!(
        vectors(&again) == vectors(&calls),
        "the recording lost the vector forms"
    );
}

/// Begin's inlined path (the window's framebuffer, no share group) and its checked path
/// (`begin_checked`) open the same primitives and raise the same errors.
#[test]
fn begin_checks_every_case_its_inlined_path_leaves_out() {
    let mut c = ctx();
    // The usual Begin: one primitive, no error.
    c.begin(gl::TRIANGLES);
    assert!(c.inside_begin_end());
    // Begin inside Begin/End.
    c.begin(gl::POINTS);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    // A mode past POLYGON.
    c.begin(gl::POLYGON + 1);
    assert!(!c.inside_begin_end());
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    // An incomplete framebuffer object bound (no attachment): refused, no primitive.
    let mut fb = [0];
    c.gen_framebuffers(1, &mut fb);
    c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
    c.begin(gl::TRIANGLES);
    assert!(!c.inside_begin_end());
    assert_eq!(c.get_error(), gl::INVALID_FRAMEBUFFER_OPERATION);
    // The window's again: the inlined path.
    c.bind_framebuffer(gl::FRAMEBUFFER, 0);
    c.begin(gl::TRIANGLES);
    assert!(c.inside_begin_end());
    c.end();
    assert_eq!(c.get_error(), gl::NO_ERROR);
}
