//! The raster position (GL 2.1 §2.13) and rectangles (§2.10) against the real driver: after each
//! step of a sequence of RasterPos / WindowPos / Bitmap calls under different transforms,
//! clip planes, lighting, TexGen and fog settings, every CURRENT_RASTER_* query must answer as
//! the driver's does (positions and colours to float rounding; validity exactly), with the same
//! errors. Rect must draw the driver's pixels. The CPU-only checks (display lists, attribute
//! stacks, every vector and integer form) are at the end.
//!
//! Skipped (with `SKIPPED:` on stderr) where no EGL device exists.

use fixedgl::{gl, Context};

/// A labelled sequence of calls.
type Named = (&'static str, fn(&mut Context));

/// The raster queries compared, with their value counts.
#[cfg(feature = "gl")]
const QUERIES: &[(&str, u32, usize)] = &[
    ("POSITION", gl::CURRENT_RASTER_POSITION, 4),
    ("VALID", gl::CURRENT_RASTER_POSITION_VALID, 1),
    ("COLOR", gl::CURRENT_RASTER_COLOR, 4),
    ("SECONDARY", gl::CURRENT_RASTER_SECONDARY_COLOR, 4),
    ("TEXTURE", gl::CURRENT_RASTER_TEXTURE_COORDS, 4),
    ("DISTANCE", gl::CURRENT_RASTER_DISTANCE, 1),
    ("INDEX", gl::CURRENT_RASTER_INDEX, 1),
];

/// Every raster query of `c`, as floats.
#[cfg(feature = "gl")]
fn raster(c: &mut Context) -> Vec<f32> {
    let mut out = Vec::new();
    for &(_, pname, n) in QUERIES {
        let mut v = [f32::NAN; 4];
        c.get_floatv(pname, &mut v);
        out.extend_from_slice(&v[..n]);
    }
    out
}

/// The steps of the sequence: each a label and the calls it makes.
#[cfg(feature = "gl")]
const STEPS: &[Named] = &[
    ("initial state", |_| {}),
    ("perspective, rotated", |c| {
        c.matrix_mode(gl::PROJECTION);
        c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
        c.matrix_mode(gl::MODELVIEW);
        c.translatef(0.1, 0.2, -3.0);
        c.rotatef(30.0, 0.0, 1.0, 0.0);
        c.color4f(0.2, 0.4, 0.6, 0.8);
        c.secondary_color3f(0.1, 0.2, 0.3);
        c.tex_coord4f(1.0, 2.0, 3.0, 4.0);
        c.raster_pos3f(0.3, -0.2, 0.5);
    }),
    ("outside the frustum: invalid, the rest kept", |c| {
        c.raster_pos3f(50.0, 0.0, 0.0);
    }),
    ("beyond the far plane", |c| c.raster_pos3f(0.0, 0.0, 20.0)),
    ("homogeneous, back inside", |c| {
        c.raster_pos4f(0.2, 0.1, -1.0, 2.0)
    }),
    (
        "unlit colour out of [0, 1] (kept unclamped, as the driver)",
        |c| {
            c.color4f(2.0, -1.0, 0.5, 1.5);
            c.raster_pos2f(0.0, 0.0);
        },
    ),
    ("lit, separate specular", |c| {
        c.load_identity();
        c.enable(gl::LIGHTING);
        c.enable(gl::LIGHT0);
        c.light_modeli(
            gl::LIGHT_MODEL_COLOR_CONTROL,
            gl::SEPARATE_SPECULAR_COLOR as i32,
        );
        c.materialfv(gl::FRONT, gl::SPECULAR, &[0.5, 0.6, 0.7, 0.3]);
        c.materialf(gl::FRONT, gl::SHININESS, 10.0);
        c.normal3f(0.2, 0.3, 1.0);
        c.raster_pos3f(0.1, 0.1, -2.0);
    }),
    // The normal is of unit length: Mesa's RasterPos ignores NORMALIZE (GL 2.1 applies it;
    // `normalize_applies_to_the_raster_position` below).
    ("lit, positional light, COLOR_MATERIAL", |c| {
        c.lightfv(gl::LIGHT0, gl::POSITION, &[1.0, 2.0, 1.0, 1.0]);
        c.enable(gl::COLOR_MATERIAL);
        c.enable(gl::NORMALIZE);
        c.color4f(0.9, 0.3, 0.2, 1.0);
        c.normal3f(0.0, 0.6, 0.8);
        c.raster_pos3f(-0.2, 0.3, -2.5);
    }),
    ("TexGen OBJECT_LINEAR and the texture matrix", |c| {
        c.disable(gl::LIGHTING);
        c.enable(gl::TEXTURE_GEN_S);
        c.tex_geni(gl::S, gl::TEXTURE_GEN_MODE, gl::OBJECT_LINEAR as i32);
        c.tex_genfv(gl::S, gl::OBJECT_PLANE, &[1.0, 2.0, 3.0, 4.0]);
        c.matrix_mode(gl::TEXTURE);
        c.scalef(2.0, 3.0, 1.0);
        c.matrix_mode(gl::MODELVIEW);
        c.raster_pos3f(0.1, 0.1, -2.0);
    }),
    ("TexGen SPHERE_MAP", |c| {
        c.tex_geni(gl::S, gl::TEXTURE_GEN_MODE, gl::SPHERE_MAP as i32);
        c.enable(gl::TEXTURE_GEN_T);
        c.tex_geni(gl::T, gl::TEXTURE_GEN_MODE, gl::SPHERE_MAP as i32);
        // A unit normal (NORMALIZE is on: see the previous step).
        c.normal3f(0.48, 0.64, 0.6);
        c.raster_pos3f(0.2, -0.1, -2.0);
    }),
    ("unit 1's coordinates through ActiveTexture", |c| {
        c.active_texture(gl::TEXTURE1);
        c.multi_tex_coord2f(gl::TEXTURE1, 5.0, 6.0);
        c.raster_pos3f(0.1, 0.1, -2.0);
    }),
    ("WindowPos3f with DepthRange and FOG_COORD", |c| {
        c.active_texture(gl::TEXTURE0);
        c.depth_range(0.25, 0.75);
        c.fogi(gl::FOG_COORD_SRC, gl::FOG_COORD as i32);
        c.fog_coordf(7.5);
        c.color4f(2.0, 0.5, -1.0, 1.0);
        c.window_pos3f(10.5, -3.25, 0.5);
    }),
    (
        "RasterPos with FOG_COORD: the fog coordinate as distance",
        |c| c.raster_pos3f(0.1, 0.1, -2.0),
    ),
    ("WindowPos z clamped", |c| c.window_pos3d(1.0, 2.0, 5.0)),
    ("WindowPos2i: z 0", |c| c.window_pos2i(-4, 9)),
    ("WindowPos2sv, WindowPos3iv", |c| {
        c.window_pos2sv(&[7, 8]);
        c.window_pos3iv(&[1, 2, 0]);
    }),
    ("Bitmap moves the raster position", |c| {
        c.bitmap(0, 0, 0.0, 0.0, 2.5, -1.5, None)
    }),
    ("PushAttrib(CURRENT_BIT) brings it back", |c| {
        c.push_attrib(gl::CURRENT_BIT);
        c.window_pos2i(3, 4);
        c.pop_attrib();
    }),
    ("a user clip plane makes it invalid", |c| {
        c.clip_plane(gl::CLIP_PLANE0, &[1.0, 0.0, 0.0, 0.0]);
        c.enable(gl::CLIP_PLANE0);
        c.matrix_mode(gl::PROJECTION);
        c.load_identity();
        c.matrix_mode(gl::MODELVIEW);
        c.load_identity();
        c.raster_pos2f(-0.5, 0.0);
    }),
    ("an invalid raster position does not move", |c| {
        c.bitmap(0, 0, 0.0, 0.0, 2.5, -1.5, None)
    }),
    ("WindowPos makes it valid again", |c| {
        c.window_pos2f(1.0, 1.0)
    }),
    ("RasterPos inside Begin/End: INVALID_OPERATION", |c| {
        c.begin(gl::POINTS);
        c.raster_pos2f(0.5, 0.5);
        c.window_pos2f(0.5, 0.5);
        c.end();
    }),
    // An empty slice, not None: Mesa raises OUT_OF_MEMORY compiling Bitmap(0, 0, .., NULL)
    // (docs/conformance.md); `raster_position_in_lists_and_recordings` compiles the NULL form.
    ("a display list holding RasterPos and Bitmap", |c| {
        c.new_list(1, gl::COMPILE);
        c.raster_pos2f(0.25, -0.25);
        c.bitmap(0, 0, 0.0, 0.0, 1.0, 1.0, Some(&[]));
        c.end_list();
        c.window_pos2i(0, 0);
        c.call_list(1);
    }),
];

#[cfg(feature = "gl")]
#[test]
fn raster_position_state_matches_the_driver_step_by_step() {
    let Some(mut drv) = crate::common::test_backend(64, 48) else {
        return;
    };
    let mut cpu = Context::new(64, 48).expect("context");
    for &(label, step) in STEPS {
        cpu.start_recording();
        step(&mut cpu);
        drv.replay(&cpu.stop_recording());
        let (a, b) = (cpu.get_error(), drv.get_error());
        assert_eq!(a, b, "{label}: errors");
        let mine = raster(&mut cpu);
        let mut theirs = Vec::new();
        for &(_, pname, n) in QUERIES {
            let mut v = [f32::NAN; 4];
            drv.get_floatv(pname, &mut v);
            theirs.extend_from_slice(&v[..n]);
        }
        let close = mine
            .iter()
            .zip(&theirs)
            .all(|(x, y)| (x - y).abs() <= 2e-6 * (1.0 + y.abs()));
        assert!(close, "{label}:\n  cpu    {mine:?}\n  driver {theirs:?}");
    }
}

#[cfg(feature = "gl")]
#[test]
fn rect_draws_the_drivers_pixels() {
    let Some(mut drv) = crate::common::test_backend(64, 48) else {
        return;
    };
    let mut cpu = Context::new(64, 48).expect("context");
    cpu.start_recording();
    cpu.matrix_mode(gl::PROJECTION);
    cpu.ortho(0.0, 64.0, 0.0, 48.0, -1.0, 1.0);
    cpu.matrix_mode(gl::MODELVIEW);
    // Every form, corners in either order; FLAT lit by a positional light, whose colour varies
    // per vertex: the provoking vertex must be the driver's.
    cpu.shade_model(gl::FLAT);
    cpu.enable(gl::LIGHTING);
    cpu.enable(gl::LIGHT0);
    cpu.lightfv(gl::LIGHT0, gl::POSITION, &[10.0, 30.0, 1.0, 1.0]);
    cpu.normal3f(0.0, 0.0, 1.0);
    cpu.rectf(2.0, 2.0, 30.0, 20.0);
    cpu.shade_model(gl::SMOOTH);
    cpu.recti(60, 46, 34, 24);
    cpu.rectsv(&[2, 46], &[30, 24]);
    cpu.disable(gl::LIGHTING);
    cpu.color3f(0.2, 0.9, 0.4);
    cpu.rectdv(&[33.5, 2.5], &[62.25, 20.75]);
    cpu.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    cpu.color3f(1.0, 1.0, 0.0);
    cpu.rectd(36.0, 4.0, 58.0, 18.0);
    // Inside Begin/End: INVALID_OPERATION, nothing drawn.
    cpu.begin(gl::TRIANGLES);
    cpu.rectf(0.0, 0.0, 64.0, 48.0);
    cpu.end();
    drv.replay(&cpu.stop_recording());
    assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
    assert_eq!(drv.get_error(), gl::INVALID_OPERATION);
    assert_eq!(cpu.to_image(), drv.read_image());
}

#[test]
fn every_form_converts_its_coordinates() {
    let mut c = Context::new(100, 100).expect("context");
    c.matrix_mode(gl::PROJECTION);
    c.ortho(0.0, 100.0, 0.0, 100.0, -100.0, 100.0);
    c.matrix_mode(gl::MODELVIEW);
    let pos = |c: &mut Context| {
        let mut v = [0.0f32; 4];
        c.get_floatv(gl::CURRENT_RASTER_POSITION, &mut v);
        v
    };
    // z = 0 → window z 0.5 with this ortho; w is the clip w (1).
    let forms: [Named; 12] = [
        ("2s", |c| c.raster_pos2s(10, 20)),
        ("2i", |c| c.raster_pos2i(10, 20)),
        ("2f", |c| c.raster_pos2f(10.0, 20.0)),
        ("2d", |c| c.raster_pos2d(10.0, 20.0)),
        ("3sv", |c| c.raster_pos3sv(&[10, 20, 0])),
        ("3iv", |c| c.raster_pos3iv(&[10, 20, 0])),
        ("3fv", |c| c.raster_pos3fv(&[10.0, 20.0, 0.0])),
        ("3dv", |c| c.raster_pos3dv(&[10.0, 20.0, 0.0])),
        ("4s", |c| c.raster_pos4s(20, 40, 0, 2)),
        ("4i", |c| c.raster_pos4i(20, 40, 0, 2)),
        ("4fv", |c| c.raster_pos4fv(&[20.0, 40.0, 0.0, 2.0])),
        ("4dv", |c| c.raster_pos4dv(&[20.0, 40.0, 0.0, 2.0])),
    ];
    for (name, f) in forms {
        c.window_pos2i(0, 0);
        f(&mut c);
        let p = pos(&mut c);
        let w = if name.starts_with('4') { 2.0 } else { 1.0 };
        let want = [10.0, 20.0, 0.5, w];
        let close = p.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-4);
        assert!(close, "RasterPos{name}: {p:?}");
    }
    let forms: [Named; 8] = [
        ("2s", |c| c.window_pos2s(3, 4)),
        ("2fv", |c| c.window_pos2fv(&[3.0, 4.0])),
        ("2dv", |c| c.window_pos2dv(&[3.0, 4.0])),
        ("2iv", |c| c.window_pos2iv(&[3, 4])),
        ("3s", |c| c.window_pos3s(3, 4, 0)),
        ("3f", |c| c.window_pos3f(3.0, 4.0, 0.0)),
        ("3sv", |c| c.window_pos3sv(&[3, 4, 0])),
        ("3dv", |c| c.window_pos3dv(&[3.0, 4.0, 0.0])),
    ];
    for (name, f) in forms {
        c.raster_pos2i(50, 50);
        f(&mut c);
        assert_eq!(pos(&mut c), [3.0, 4.0, 0.0, 1.0], "WindowPos{name}");
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn raster_position_in_lists_and_recordings() {
    let mut c = Context::new(32, 32).expect("context");
    // COMPILE stores the calls: nothing changes until the list runs.
    c.new_list(5, gl::COMPILE);
    c.window_pos2i(7, 9);
    c.bitmap(0, 0, 0.0, 0.0, 3.0, -2.0, None);
    c.end_list();
    assert_eq!(c.state().raster_pos.window.x, 0.0);
    c.call_list(5);
    let r = c.state().raster_pos.window;
    assert_eq!((r.x, r.y), (10.0, 7.0));
    // A recording replays to the same raster state.
    c.start_recording();
    c.color4f(0.5, 0.25, 0.75, 1.0);
    c.raster_pos3f(0.25, 0.5, 0.0);
    c.call_list(5);
    let calls = c.stop_recording();
    let mut d = Context::new(32, 32).expect("context");
    d.new_list(5, gl::COMPILE);
    d.window_pos2i(7, 9);
    d.bitmap(0, 0, 0.0, 0.0, 3.0, -2.0, None);
    d.end_list();
    d.replay(&calls);
    assert_eq!(d.state().raster_pos, c.state().raster_pos);
}

#[test]
fn normalize_applies_to_the_raster_position() {
    // GL 2.1 §2.13: the raster position is lit as a vertex, so NORMALIZE scales the normal
    // (0, 0, 3) to unit length: diffuse N·L = 1 for a light straight above, not 3 (saturated).
    let mut c = Context::new(8, 8).expect("context");
    c.enable(gl::LIGHTING);
    c.enable(gl::LIGHT0);
    c.enable(gl::NORMALIZE);
    c.light_modelfv(gl::LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    c.materialfv(gl::FRONT, gl::DIFFUSE, &[0.25, 0.5, 0.125, 1.0]);
    c.normal3f(0.0, 0.0, 3.0);
    c.raster_pos2f(0.0, 0.0);
    let mut col = [0.0f32; 4];
    c.get_floatv(gl::CURRENT_RASTER_COLOR, &mut col);
    assert_eq!(col, [0.25, 0.5, 0.125, 1.0]);
}
