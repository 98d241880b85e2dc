//! The real-GL backend against the CPU front end and against the driver used directly.
//!
//! Every test needs an EGL device. Where none exists (or the backend cannot start) the test
//! prints `SKIPPED: ...` with the reason and returns; set `FIXEDGL_REQUIRE_GL=1` (CI with Mesa)
//! to make that a failure instead. Each test creates its own backend: EGL contexts are per thread.
#![cfg(feature = "gl")]

use fixedgl::compare::compare;
use fixedgl::gl;
use fixedgl::glbackend::GlBackend;
use fixedgl::scenes;
use fixedgl::{Call, Context};
use image::Rgba;
use std::io::Write as _;

/// A backend, or `None` after printing why the test is skipped.
fn backend(width: u32, height: u32) -> Option<GlBackend> {
    crate::common::test_backend(width, height)
}

#[test]
fn starts_clears_and_reads_back_top_down() {
    let Some(mut gl) = backend(8, 6) else { return };
    let _ = writeln!(
        std::io::stderr(),
        "GL backend: {} | {}",
        gl.renderer(),
        gl.version()
    );
    assert!(!gl.renderer().is_empty());
    // SAFETY: plain driver calls on the backend's current context.
    unsafe {
        let raw = gl.raw();
        // 0.2*255 = 51, 0.6*255 = 153 exactly: no rounding ambiguity.
        raw.ClearColor(0.2, 0.6, 1.0, 1.0);
        raw.Clear(gl::COLOR_BUFFER_BIT);
        // The bottom two window rows (y = 0, 1) red.
        raw.Enable(gl::SCISSOR_TEST);
        raw.Scissor(0, 0, 8, 2);
        raw.ClearColor(1.0, 0.0, 0.0, 1.0);
        raw.Clear(gl::COLOR_BUFFER_BIT);
    }
    let img = gl.read_image();
    assert_eq!(img.dimensions(), (8, 6));
    // Top-down image: window rows 0-1 are image rows 5-4.
    for y in 0..6 {
        let expected = if y >= 4 {
            Rgba([255, 0, 0, 255])
        } else {
            Rgba([51, 153, 255, 255])
        };
        for x in 0..8 {
            assert_eq!(*img.get_pixel(x, y), expected, "pixel ({x},{y})");
        }
    }
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

#[test]
fn error_sequence_matches_the_cpu_front_end() {
    let Some(mut gl) = backend(16, 16) else {
        return;
    };
    let Ok(mut cpu) = Context::new(16, 16) else {
        panic!("CPU context")
    };
    // (call, the error GL 2.1 requires right after it), read back after every call.
    let rows: &[(Call, u32)] = &[
        (Call::Enable(0x1234), gl::INVALID_ENUM), // not a capability (§2.5)
        (Call::Disable(gl::LIGHTING), gl::NO_ERROR),
        (Call::End, gl::INVALID_OPERATION), // End without Begin (§2.6.1)
        // GL 2.1 has 10 modes; a 3.2+ driver also takes LINES_ADJACENCY (POLYGON + 1) etc.
        (Call::Begin(gl::POLYGON + 1), gl::INVALID_ENUM),
        (Call::Begin(0x20), gl::INVALID_ENUM),
        (Call::Enable(gl::LIGHT7), gl::NO_ERROR),
        (Call::Enable(gl::LIGHT0 + 8), gl::INVALID_ENUM), // MAX_LIGHTS is 8
        (Call::Color4f(1.0, 0.5, 0.25, 1.0), gl::NO_ERROR),
    ];
    for (i, (call, expected)) in rows.iter().enumerate() {
        cpu.execute(call);
        gl.execute(call);
        assert_eq!(cpu.get_error(), *expected, "CPU after row {i}: {call:?}");
        assert_eq!(gl.get_error(), *expected, "GL after row {i}: {call:?}");
    }
    // Inside Begin/End: the first error sticks and is read after End (§2.5, §2.6.3); glGetError
    // there is itself an error that returns NO_ERROR.
    let pair = [
        Call::Begin(gl::TRIANGLES),
        Call::Enable(gl::LIGHTING), // INVALID_OPERATION: not allowed in Begin/End
        Call::Begin(gl::TRIANGLES), // INVALID_OPERATION too, but the first sticks
        Call::Vertex3f(0.0, 0.0, 0.0), // allowed
        Call::Disable(0x1234),      // would be INVALID_ENUM outside; here INVALID_OPERATION
    ];
    cpu.replay(&pair);
    gl.replay(&pair);
    assert_eq!(
        cpu.get_error(),
        gl::NO_ERROR,
        "CPU get_error inside Begin/End"
    );
    assert_eq!(
        gl.get_error(),
        gl::NO_ERROR,
        "GL get_error inside Begin/End"
    );
    cpu.execute(&Call::End);
    gl.execute(&Call::End);
    assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
    assert_eq!(gl.get_error(), gl::INVALID_OPERATION);
    assert_eq!(cpu.get_error(), gl::NO_ERROR, "the flag is clear once read");
    assert_eq!(gl.get_error(), gl::NO_ERROR, "the flag is clear once read");
    // LIGHTING was refused inside Begin/End: still disabled on both.
    assert!(!cpu.is_enabled(gl::LIGHTING));
    assert!(!gl.is_enabled(gl::LIGHTING));
}

#[test]
fn enables_and_queries_agree_with_the_cpu_state() {
    let Some(mut gl) = backend(40, 30) else {
        return;
    };
    let Ok(mut cpu) = Context::new(40, 30) else {
        panic!("CPU context")
    };
    let calls = [
        Call::Enable(gl::LIGHTING),
        Call::Enable(gl::LIGHT3),
        Call::Enable(gl::NORMALIZE),
        Call::Enable(gl::DEPTH_TEST),
        Call::Disable(gl::DITHER),
        Call::Color4f(0.5, 0.25, 1.0, 0.75),
        Call::Normal3f(0.0, 1.0, 0.0),
    ];
    cpu.replay(&calls);
    gl.replay(&calls);
    for cap in [
        gl::LIGHTING,
        gl::LIGHT0,
        gl::LIGHT3,
        gl::NORMALIZE,
        gl::DEPTH_TEST,
        gl::DITHER,
        gl::CULL_FACE,
        gl::BLEND,
        gl::COLOR_MATERIAL,
        gl::SCISSOR_TEST,
    ] {
        assert_eq!(gl.is_enabled(cap), cpu.is_enabled(cap), "cap {cap:#x}");
    }
    let mut c = [0.0f32; 4];
    gl.get_floatv(gl::CURRENT_COLOR, &mut c);
    assert_eq!(c, [0.5, 0.25, 1.0, 0.75]);
    assert_eq!(c, cpu.state().current.color.to_array());
    let mut n = [0.0f32; 3];
    gl.get_floatv(gl::CURRENT_NORMAL, &mut n);
    assert_eq!(n, [0.0, 1.0, 0.0]);
    assert_eq!(n, cpu.state().current.normal.to_array());
    // The initial viewport is the framebuffer (§2.11.1), as for the CPU context.
    let mut vp = [0i32; 4];
    gl.get_integerv(gl::VIEWPORT, &mut vp);
    assert_eq!(vp, [0, 0, 40, 30]);
    let mut m = [f32::NAN; 16];
    gl.get_floatv(gl::MODELVIEW_MATRIX, &mut m);
    assert_eq!(m, glam::Mat4::IDENTITY.to_cols_array());
    let mut b = [false; 1];
    gl.get_booleanv(gl::LIGHTING, &mut b);
    assert_eq!(b, [true]);
    let mut shade = [0i32];
    gl.get_integerv(gl::SHADE_MODEL, &mut shade);
    assert_eq!(shade, [gl::SMOOTH as i32]);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

#[test]
fn a_short_query_slice_is_invalid_value_and_writes_nothing() {
    let Some(mut gl) = backend(8, 8) else { return };
    let mut m = [7.0f32; 15]; // MODELVIEW_MATRIX has 16 values
    gl.get_floatv(gl::MODELVIEW_MATRIX, &mut m);
    assert_eq!(m, [7.0; 15]);
    assert_eq!(gl.get_error(), gl::INVALID_VALUE);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    let mut vp = [9i32; 3];
    gl.get_integerv(gl::VIEWPORT, &mut vp);
    assert_eq!(vp, [9; 3]);
    assert_eq!(gl.get_error(), gl::INVALID_VALUE);
    // The first error sticks: a driver error before ours wins, ours is then dropped.
    gl.execute(&Call::Enable(0x1234)); // INVALID_ENUM in the driver
    gl.get_integerv(gl::VIEWPORT, &mut vp); // ours would be INVALID_VALUE
    assert_eq!(gl.get_error(), gl::INVALID_ENUM);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    // And ours first: the driver's later error is dropped as one GL flag would drop it.
    gl.get_integerv(gl::VIEWPORT, &mut vp);
    gl.execute(&Call::Enable(0x1234));
    assert_eq!(gl.get_error(), gl::INVALID_VALUE);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    // An unknown pname writes nothing and is the driver's INVALID_ENUM.
    let mut x = [3i32; 4];
    gl.get_integerv(0x1234, &mut x);
    assert_eq!(x, [3; 4]);
    assert_eq!(gl.get_error(), gl::INVALID_ENUM);
}

/// Draws the `triangle` scene's calls straight into the driver, without the replay.
fn triangle_direct(gl: &GlBackend) {
    // SAFETY: plain driver calls on the backend's current context.
    unsafe {
        let raw = gl.raw();
        raw.Begin(gl::TRIANGLES);
        raw.Color4f(1.0, 0.0, 0.0, 1.0);
        raw.Vertex3f(-0.8, -0.8, 0.0);
        raw.Color4f(0.0, 1.0, 0.0, 1.0);
        raw.Vertex3f(0.8, -0.8, 0.0);
        raw.Color4f(0.0, 0.0, 1.0, 1.0);
        raw.Vertex3f(0.0, 0.8, 0.0);
        raw.End();
        raw.Finish();
    }
}

#[test]
fn replay_adds_nothing() {
    let Some(scene) = scenes::find("triangle") else {
        panic!("triangle scene")
    };
    let Ok((_, calls)) = scene.record(64, 48) else {
        panic!("recording")
    };
    let Some(mut replayed) = backend(64, 48) else {
        return;
    };
    replayed.replay(&calls);
    replayed.finish();
    let a = replayed.read_image();
    let Some(mut direct) = backend(64, 48) else {
        return;
    };
    triangle_direct(&direct);
    let b = direct.read_image();
    assert_eq!(a.as_raw(), b.as_raw(), "replayed and direct pixels differ");
    // And the picture is not empty: the centroid is lit, a corner is the clear colour.
    assert_ne!(*a.get_pixel(32, 30), Rgba([0, 0, 0, 0]));
    assert_eq!(*a.get_pixel(0, 0), Rgba([0, 0, 0, 0]));
    assert_eq!(replayed.get_error(), gl::NO_ERROR);
}

/// LIGHTING and LIGHT0 on, then the quad (-1,-1)..(1,1) at z = 0, counter-clockwise (front
/// facing), with whatever normal and colour are current (initially (0,0,1) and white).
fn lit_viewport_quad() -> Vec<Call> {
    vec![
        Call::Enable(gl::LIGHTING),
        Call::Enable(gl::LIGHT0),
        Call::Begin(gl::QUADS),
        Call::Vertex3f(-1.0, -1.0, 0.0),
        Call::Vertex3f(1.0, -1.0, 0.0),
        Call::Vertex3f(1.0, 1.0, 0.0),
        Call::Vertex3f(-1.0, 1.0, 0.0),
        Call::End,
    ]
}

/// A 64x64 quad filling the viewport at z = 0 (identity matrices), normal +z, lit by LIGHT0 at
/// eye position (0, 0, 1, 1) with white diffuse and no ambient or specular; default material
/// (ambient 0.2, diffuse 0.8) and light-model ambient 0.2.
fn lit_quad(gl: &mut GlBackend, shade: u32) {
    // SAFETY: each pointer points to 4 floats, what Lightfv reads for these pnames.
    unsafe {
        let raw = gl.raw();
        raw.Lightfv(gl::LIGHT0, gl::POSITION, [0.0f32, 0.0, 1.0, 1.0].as_ptr());
        raw.Lightfv(gl::LIGHT0, gl::SPECULAR, [0.0f32, 0.0, 0.0, 1.0].as_ptr());
    }
    gl.shade_model(shade);
    gl.replay(&lit_viewport_quad());
    gl.finish();
}

#[test]
fn phong_win_lights_per_fragment() {
    // Per fragment (GL 2.1 §2.14.1 at each pixel): c = 0.2*0.2 + 0.8 * (n . l), l towards
    // (0,0,1) from the pixel's eye position (x, y, 0), so n . l = 1 / sqrt(x² + y² + 1).
    //  - image pixel (32, 31) is window (32, 32), centre NDC (0.015625, 0.015625):
    //    n.l = 1/sqrt(1.00048828) = 0.99975598, c = 0.83980478 -> 214.15 -> 214;
    //  - image pixel (0, 63) is window (0, 0), centre NDC (-0.984375, -0.984375):
    //    n.l = 1/sqrt(2.93798828) = 0.58341030, c = 0.50672824 -> 129.22 -> 129.
    // Gouraud (SMOOTH) lights the corners only: n.l = 1/sqrt(3), c = 0.50188021 -> 127.98 -> 128
    // everywhere.
    let Some(mut phong) = backend(64, 64) else {
        return;
    };
    lit_quad(&mut phong, gl::PHONG_WIN);
    assert_eq!(phong.get_error(), gl::NO_ERROR);
    let mut shade = [0i32];
    phong.get_integerv(gl::SHADE_MODEL, &mut shade);
    assert_eq!(shade, [gl::PHONG_WIN as i32]);
    let p = phong.read_image();
    let near = |a: u8, b: u8| a.abs_diff(b) <= 1;
    let centre = p.get_pixel(32, 31).0;
    let corner = p.get_pixel(0, 63).0;
    assert!(centre[..3].iter().all(|&c| near(c, 214)), "{centre:?}");
    assert!(corner[..3].iter().all(|&c| near(c, 129)), "{corner:?}");
    assert_eq!(centre[3], 255);

    let Some(mut smooth) = backend(64, 64) else {
        return;
    };
    lit_quad(&mut smooth, gl::SMOOTH);
    let s = smooth.read_image();
    let centre = s.get_pixel(32, 31).0;
    assert!(centre[..3].iter().all(|&c| near(c, 128)), "{centre:?}");

    // Back to SMOOTH on the Phong backend: fixed function again, same pixels as `smooth`.
    phong.shade_model(gl::SMOOTH);
    lit_quad(&mut phong, gl::SMOOTH);
    let again = phong.read_image();
    assert_eq!(compare(&again, &s, 0).differing_pixels, 0);
}

#[test]
fn phong_win_without_lighting_is_plain_smooth() {
    let calls = [
        Call::Begin(gl::TRIANGLES),
        Call::Color4f(1.0, 0.0, 0.0, 1.0),
        Call::Vertex3f(-0.9, -0.9, 0.0),
        Call::Color4f(0.0, 1.0, 0.0, 1.0),
        Call::Vertex3f(0.9, -0.9, 0.0),
        Call::Color4f(0.0, 0.0, 1.0, 1.0),
        Call::Vertex3f(0.0, 0.9, 0.0),
        Call::End,
    ];
    let Some(mut phong) = backend(32, 32) else {
        return;
    };
    phong.shade_model(gl::PHONG_WIN);
    phong.replay(&calls);
    let Some(mut smooth) = backend(32, 32) else {
        return;
    };
    smooth.replay(&calls);
    assert_eq!(phong.read_image().as_raw(), smooth.read_image().as_raw());
    // PHONG_WIN inside Begin/End is refused like any ShadeModel there.
    phong.execute(&Call::Begin(gl::POINTS));
    phong.shade_model(gl::FLAT);
    phong.execute(&Call::End);
    assert_eq!(phong.get_error(), gl::INVALID_OPERATION);
    // An invalid mode is the driver's INVALID_ENUM.
    phong.shade_model(0x1234);
    assert_eq!(phong.get_error(), gl::INVALID_ENUM);
}

#[test]
fn two_backends_on_one_thread_stay_apart() {
    let Some(mut a) = backend(4, 4) else { return };
    let Some(mut b) = backend(4, 4) else { return };
    // `b` was created last, so its context is current; `a`'s calls must still reach `a`.
    // SAFETY: plain driver calls on each backend's own context (raw() makes it current).
    unsafe {
        let raw = a.raw();
        raw.ClearColor(1.0, 0.0, 0.0, 1.0);
        raw.Clear(gl::COLOR_BUFFER_BIT);
    }
    unsafe {
        let raw = b.raw();
        raw.ClearColor(0.0, 1.0, 0.0, 1.0);
        raw.Clear(gl::COLOR_BUFFER_BIT);
    }
    a.execute(&Call::Enable(gl::LIGHTING));
    b.execute(&Call::Enable(0x1234));
    assert_eq!(*a.read_image().get_pixel(1, 1), Rgba([255, 0, 0, 255]));
    assert_eq!(*b.read_image().get_pixel(1, 1), Rgba([0, 255, 0, 255]));
    assert!(a.is_enabled(gl::LIGHTING));
    assert!(!b.is_enabled(gl::LIGHTING));
    assert_eq!(a.get_error(), gl::NO_ERROR);
    assert_eq!(b.get_error(), gl::INVALID_ENUM);
    drop(a);
    // Dropping `a` (which made itself current to clean up) leaves `b` working.
    b.execute(&Call::Enable(gl::BLEND));
    assert!(b.is_enabled(gl::BLEND));
}

/// The 64x64 quad of `lit_quad` wound clockwise (a back face), LIGHT0 directional from behind
/// (0, 0, -1, 0), BACK diffuse green; `two_side` sets LIGHT_MODEL_TWO_SIDE.
fn back_quad(gl: &mut GlBackend, shade: u32, two_side: bool) -> Rgba<u8> {
    // SAFETY: each pointer points to 4 floats, what Lightfv/Materialfv read for these pnames.
    unsafe {
        let raw = gl.raw();
        raw.Lightfv(gl::LIGHT0, gl::POSITION, [0.0f32, 0.0, -1.0, 0.0].as_ptr());
        raw.Materialfv(gl::BACK, gl::DIFFUSE, [0.0f32, 1.0, 0.0, 1.0].as_ptr());
        raw.LightModeli(gl::LIGHT_MODEL_TWO_SIDE, i32::from(two_side));
    }
    gl.shade_model(shade);
    gl.replay(&[
        Call::Enable(gl::LIGHTING),
        Call::Enable(gl::LIGHT0),
        Call::Normal3f(0.0, 0.0, 1.0),
        Call::Begin(gl::QUADS),
        Call::Vertex3f(-1.0, -1.0, 0.0),
        Call::Vertex3f(-1.0, 1.0, 0.0),
        Call::Vertex3f(1.0, 1.0, 0.0),
        Call::Vertex3f(1.0, -1.0, 0.0),
        Call::End,
    ]);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    *gl.read_image().get_pixel(20, 40)
}

#[test]
fn phong_win_two_sided_lighting_uses_the_back_material_and_negated_normal() {
    // Two-sided (§2.14.1): back material, normal (0,0,-1), n.l = 1 with l = (0,0,-1):
    // c = 0.2*0.2 (back ambient x model ambient) + (0,1,0) = (0.04, 1.04, 0.04) -> (10, 255, 10).
    // One-sided: front material, normal (0,0,1), n.l = -1: c = 0.04 -> (10, 10, 10).
    for (two_side, expected) in [(true, [10, 255, 10, 255]), (false, [10, 10, 10, 255])] {
        for shade in [gl::PHONG_WIN, gl::SMOOTH] {
            let Some(mut gl) = backend(64, 64) else {
                return;
            };
            let got = back_quad(&mut gl, shade, two_side);
            assert_eq!(got, Rgba(expected), "two_side {two_side}, shade {shade:#x}");
        }
    }
}

#[test]
fn phong_win_follows_color_material() {
    // COLOR_MATERIAL (initially AMBIENT_AND_DIFFUSE on both faces, §2.14.3) with colour
    // (0.5, 0.2, 0.6), LIGHT0 directional along +z, normal +z: n.l = 1, so
    // c = 0.2 * colour (model ambient x ambient) + colour = 1.2 * colour
    //   = (0.6, 0.24, 0.72) -> (153, 61.2, 183.6) -> (153, 61, 184).
    for shade in [gl::PHONG_WIN, gl::SMOOTH] {
        let Some(mut gl) = backend(16, 16) else {
            return;
        };
        // SAFETY: 4 floats, what Lightfv reads for POSITION.
        unsafe {
            gl.raw()
                .Lightfv(gl::LIGHT0, gl::POSITION, [0.0f32, 0.0, 1.0, 0.0].as_ptr());
        }
        gl.shade_model(shade);
        gl.replay(&[
            Call::Enable(gl::COLOR_MATERIAL),
            Call::Color4f(0.5, 0.2, 0.6, 1.0),
        ]);
        gl.replay(&lit_viewport_quad());
        let px = *gl.read_image().get_pixel(8, 8);
        assert_eq!(px, Rgba([153, 61, 184, 255]), "shade {shade:#x}");
    }
}

#[test]
fn phong_win_spot_cone_applies_to_directional_lights_as_the_driver_does() {
    // LIGHT0 directional along +z with a 10-degree cone aimed along +x: the direction from the
    // light, (0,0,-1), makes 90 degrees with the spot axis, outside the cone, so the light adds
    // nothing (§2.14.1 spot_i = 0) and c = 0.2 * 0.2 = 0.04 -> 10.2 -> 10. llvmpipe's fixed
    // function agrees (it does not exempt directional lights from the cone).
    for shade in [gl::SMOOTH, gl::PHONG_WIN] {
        let Some(mut gl) = backend(16, 16) else {
            return;
        };
        // SAFETY: 4 / 3 floats for POSITION / SPOT_DIRECTION, 1 for Lightf.
        unsafe {
            let raw = gl.raw();
            raw.Lightfv(gl::LIGHT0, gl::POSITION, [0.0f32, 0.0, 1.0, 0.0].as_ptr());
            raw.Lightf(gl::LIGHT0, gl::SPOT_CUTOFF, 10.0);
            raw.Lightfv(gl::LIGHT0, gl::SPOT_DIRECTION, [1.0f32, 0.0, 0.0].as_ptr());
        }
        gl.shade_model(shade);
        gl.replay(&lit_viewport_quad());
        let px = *gl.read_image().get_pixel(8, 8);
        assert_eq!(px, Rgba([10, 10, 10, 255]), "shade {shade:#x}");
    }
}

#[test]
fn phong_win_local_viewer_and_separate_specular() {
    // Material: ambient 0.2 (default), diffuse 0, specular 0.5, shininess 1; LIGHT0 directional
    // along +z (specular 1). On the z = 0 plane facing +z, n.l = 1 and:
    //  - infinite viewer: h = (0,0,1), n.h = 1: c = 0.04 + 0.5 = 0.54 -> 137.7 -> 138;
    //  - local viewer: v = -p/|p| lies in the plane, h ~ (v + l), n.h = 1/sqrt(2) at every point:
    //    c = 0.04 + 0.5 * 0.70711 = 0.39355 -> 100.4 -> 100.
    // Without texturing SEPARATE_SPECULAR_COLOR sums the same values.
    for (local, separate, expected) in [
        (false, false, 138),
        (true, false, 100),
        (false, true, 138),
        (true, true, 100),
    ] {
        for shade in [gl::SMOOTH, gl::PHONG_WIN] {
            let Some(mut gl) = backend(16, 16) else {
                return;
            };
            // SAFETY: 4 floats for POSITION / DIFFUSE / SPECULAR, scalars otherwise.
            unsafe {
                let raw = gl.raw();
                raw.Lightfv(gl::LIGHT0, gl::POSITION, [0.0f32, 0.0, 1.0, 0.0].as_ptr());
                raw.Materialfv(gl::FRONT, gl::DIFFUSE, [0.0f32, 0.0, 0.0, 1.0].as_ptr());
                raw.Materialfv(gl::FRONT, gl::SPECULAR, [0.5f32, 0.5, 0.5, 1.0].as_ptr());
                raw.Materialf(gl::FRONT, gl::SHININESS, 1.0);
                raw.LightModeli(gl::LIGHT_MODEL_LOCAL_VIEWER, i32::from(local));
                let control = if separate {
                    gl::SEPARATE_SPECULAR_COLOR
                } else {
                    gl::SINGLE_COLOR
                };
                raw.LightModeli(gl::LIGHT_MODEL_COLOR_CONTROL, control as i32);
            }
            gl.shade_model(shade);
            gl.replay(&lit_viewport_quad());
            let px = *gl.read_image().get_pixel(8, 8);
            let what = format!("local {local}, separate {separate}, shade {shade:#x}");
            assert_eq!(px, Rgba([expected, expected, expected, 255]), "{what}");
        }
    }
}

#[test]
fn implementation_limits_agree_with_the_cpu_state() {
    // Known divergences, left to the state's owner: llvmpipe reports MAX_CLIP_PLANES 8 (state: 6)
    // and MAX_TEXTURE_UNITS 8 (state: 4). DRAW_BUFFER, READ_BUFFER and DOUBLEBUFFER are those
    // of the framebuffer the backend's FBO stands for (glbackend/buffers.rs).
    use fixedgl::state;
    let Some(mut gl) = backend(8, 8) else { return };
    for (pname, expected) in [
        (gl::MAX_LIGHTS, state::MAX_LIGHTS as i32),
        (
            gl::MAX_MODELVIEW_STACK_DEPTH,
            state::MAX_MODELVIEW_STACK_DEPTH as i32,
        ),
        (
            gl::MAX_PROJECTION_STACK_DEPTH,
            state::MAX_PROJECTION_STACK_DEPTH as i32,
        ),
        (
            gl::MAX_TEXTURE_STACK_DEPTH,
            state::MAX_TEXTURE_STACK_DEPTH as i32,
        ),
        (gl::MAX_VIEWPORT_DIMS, state::MAX_VIEWPORT_DIM as i32),
        (gl::SUBPIXEL_BITS, 8), // DESIGN.md: window coordinates snap to 1/256 pixel
        (gl::RED_BITS, 8),
        (gl::ALPHA_BITS, 8),
        (gl::DEPTH_BITS, 24),
        (gl::STENCIL_BITS, 8),
        (gl::DRAW_BUFFER, gl::FRONT as i32),
        (gl::READ_BUFFER, gl::FRONT as i32),
        (gl::DOUBLEBUFFER, 0),
        (gl::ACCUM_RED_BITS, 0),
        (gl::MAX_NAME_STACK_DEPTH, 64),
    ] {
        let mut v = [0i32; 2];
        gl.get_integerv(pname, &mut v);
        assert_eq!(v[0], expected, "pname {pname:#x}");
    }
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

/// A lit floor receding from z = -1 to z = -40 under perspective, with PHONG_WIN and the given
/// fog (`None`: FOG off): FOG_MODE, then whether FOG_COORD_SRC is FOG_COORD (then each vertex
/// carries its own fog coordinate, unlike its depth).
fn fogged_phong_floor(fog: Option<(u32, bool)>) -> Vec<Call> {
    let Ok(mut c) = Context::new(96, 96) else {
        panic!("CPU context")
    };
    c.start_recording();
    c.clear_color(0.1, 0.2, 0.3, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.matrix_mode(gl::PROJECTION);
    c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 50.0);
    c.matrix_mode(gl::MODELVIEW);
    c.enable(gl::LIGHTING);
    c.enable(gl::LIGHT0);
    c.lightfv(gl::LIGHT0, gl::POSITION, &[0.0, 2.0, -6.0, 1.0]);
    c.lightfv(gl::LIGHT0, gl::SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    c.materialfv(gl::FRONT, gl::SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    c.materialf(gl::FRONT, gl::SHININESS, 20.0);
    c.shade_model(gl::PHONG_WIN);
    if let Some((mode, coord)) = fog {
        c.enable(gl::FOG);
        c.fogi(gl::FOG_MODE, mode as i32);
        c.fogfv(gl::FOG_COLOR, &[0.8, 0.7, 0.6, 1.0]);
        c.fogf(gl::FOG_START, 1.0);
        c.fogf(gl::FOG_END, 12.0);
        c.fogf(gl::FOG_DENSITY, 0.2);
        if coord {
            c.fogi(gl::FOG_COORD_SRC, gl::FOG_COORD as i32);
        }
    }
    c.begin(gl::QUADS);
    c.normal3f(0.0, 1.0, 0.0);
    for (x, z, f) in [
        (-8.0, -1.0, 25.0),
        (8.0, -1.0, 2.0),
        (8.0, -40.0, 10.0),
        (-8.0, -40.0, 0.0),
    ] {
        c.fog_coordf(f);
        c.vertex3f(x, -1.0, z);
    }
    c.end();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.stop_recording()
}

#[test]
fn phong_win_fog_matches_the_cpu_pipeline() {
    // GL 2.1 §3.11: with the emulation program bound the driver does no fog of its own, so the
    // program must (§3.10); the CPU pipeline is the reference, within 2/255 everywhere.
    let Some(mut plain) = backend(96, 96) else {
        return;
    };
    plain.replay(&fogged_phong_floor(None));
    let unfogged = plain.read_image();
    for fog in [
        (gl::LINEAR, false),
        (gl::EXP, false),
        (gl::EXP2, false),
        (gl::LINEAR, true),
        (gl::EXP2, true),
    ] {
        let calls = fogged_phong_floor(Some(fog));
        let Ok(mut cpu) = Context::new(96, 96) else {
            panic!("CPU context")
        };
        for call in &calls {
            cpu.execute(call);
        }
        let Some(mut drv) = backend(96, 96) else {
            return;
        };
        drv.replay(&calls);
        assert_eq!(drv.get_error(), gl::NO_ERROR);
        let got = drv.read_image();
        let cmp = compare(&cpu.to_image(), &got, 2);
        assert_eq!(cmp.differing_pixels, 0, "{fog:?}: max {:?}", cmp.max_diff);
        // And the fog shows: the floor (about a third of the image) is not what it is unfogged.
        let fogged = compare(&got, &unfogged, 2).differing_pixels;
        let _ = writeln!(
            std::io::stderr(),
            "{fog:?}: {fogged} pixels fogged, max diff {:?}",
            cmp.max_diff
        );
        assert!(fogged > 96 * 96 / 5, "{fog:?}: only {fogged} pixels fogged");
    }
}
