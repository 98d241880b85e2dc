//! Every registered scene, rendered by the CPU backend and by the real driver from the same
//! recorded calls, must agree within the scene's tolerance; and replaying adds nothing of its own.
//!
//! Needs an EGL device (Mesa's llvmpipe on CI). Where none exists each test prints
//! `SKIPPED: ...` and returns; `FIXEDGL_REQUIRE_GL=1` turns that into a failure. A failing
//! comparison writes its CPU | GL | diff strip to `target/scene-failures/<scene>.png`.
#![cfg(feature = "gl")]

use std::io::Write as _;
use std::path::PathBuf;

use fixedgl::compare::compare;
use fixedgl::gl;
use fixedgl::glbackend::GlBackend;
use fixedgl::scenes;

/// A backend, or `None` after printing why the test is skipped.
fn backend(width: u32, height: u32) -> Option<GlBackend> {
    crate::common::test_backend(width, height)
}

fn failure_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/scene-failures")
}

#[test]
fn every_scene_matches_the_driver_within_its_tolerance() {
    let mut failures = Vec::new();
    for scene in scenes::scenes() {
        let (w, h) = scene.default_size;
        let (mut ctx, calls) = match scene.record(w, h) {
            Ok(r) => r,
            Err(e) => panic!("{}: {e}", scene.name),
        };
        assert_eq!(
            ctx.get_error(),
            gl::NO_ERROR,
            "{}: the scene makes a GL error",
            scene.name
        );
        let cpu = ctx.to_image();
        // A scene that draws nothing would pass vacuously: insist on a picture.
        let first = cpu.get_pixel(0, 0);
        assert!(
            cpu.pixels().any(|p| p != first),
            "{}: the CPU image is one flat colour",
            scene.name
        );

        let Some(mut driver) = crate::common::test_backend_with(w, h, scene.config) else {
            return;
        };
        driver.replay(&calls);
        driver.finish();
        assert_eq!(
            driver.get_error(),
            gl::NO_ERROR,
            "{}: the driver saw a GL error",
            scene.name
        );
        let gl_image = driver.read_image();

        let cmp = compare(&cpu, &gl_image, scene.tolerance.channel);
        let line = format!(
            "{}: {} px ({:.4}%) off by more than {}, max {:?}, PSNR {:.2} dB (allowed {}%)",
            scene.name,
            cmp.differing_pixels,
            cmp.differing_percent,
            scene.tolerance.channel,
            cmp.max_diff,
            cmp.psnr,
            scene.tolerance.max_percent
        );
        let _ = writeln!(std::io::stderr(), "{line}");
        if !cmp.passes(scene.tolerance.max_percent) {
            let dir = failure_dir();
            let _ = std::fs::create_dir_all(&dir);
            let _ = cmp
                .side_by_side(&cpu, &gl_image)
                .save(dir.join(format!("{}.png", scene.name)));
            failures.push(line);
        }
    }
    assert!(
        failures.is_empty(),
        "scenes over tolerance:\n{}",
        failures.join("\n")
    );
}

/// The accumulation scenes against Mesa's own glAccum: replayed on OSMesa, whose window
/// framebuffer has a real accumulation buffer (the EGL backend's FBO has none, so there the
/// backend accumulates the driver's passes itself, with fixedgl's arithmetic). OSMesa's window
/// framebuffer rasterises upside down and flips back, which can move an edge pixel of a pass;
/// the tolerance is the scene's all the same.
#[test]
fn accumulation_scenes_match_mesas_own_accumulation_buffer() {
    let mut failures = Vec::new();
    for scene in scenes::scenes().iter().filter(|s| s.config.accum) {
        let (w, h) = scene.default_size;
        let (mut ctx, calls) = scene.record(w, h).unwrap();
        let Some(mut osmesa) = crate::common::osmesa_backend(w, h, scene.config) else {
            return;
        };
        osmesa.replay(&calls);
        osmesa.finish();
        assert_eq!(osmesa.get_error(), gl::NO_ERROR, "{}", scene.name);
        let cmp = compare(
            &ctx.to_image(),
            &osmesa.read_image(),
            scene.tolerance.channel,
        );
        let line = format!(
            "{} on OSMesa: {} px ({:.4}%) off by more than {}, max {:?} (allowed {}%)",
            scene.name,
            cmp.differing_pixels,
            cmp.differing_percent,
            scene.tolerance.channel,
            cmp.max_diff,
            scene.tolerance.max_percent
        );
        let _ = writeln!(std::io::stderr(), "{line}");
        if !cmp.passes(scene.tolerance.max_percent) {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The frames `fixedgl view` animates are held to the same tolerances: every animated scene, 1.5 s
/// in, against the driver (the 400-cell surface left out: its calls are the 40-cell one's, ten
/// times over, and it alone would take longer than all the others).
#[test]
fn animated_scenes_match_the_driver_mid_animation() {
    let mut failures = Vec::new();
    let animated = scenes::scenes()
        .iter()
        .filter(|s| s.animate.is_some() && s.name != "gauss-smooth-400");
    for scene in animated {
        let (w, h) = scene.default_size;
        let (mut ctx, calls) = scene.record_at(w, h, 1.5).unwrap();
        assert_eq!(ctx.get_error(), gl::NO_ERROR, "{}", scene.name);
        let Some(mut driver) = crate::common::test_backend_with(w, h, scene.config) else {
            return;
        };
        driver.replay(&calls);
        let cmp = compare(
            &ctx.to_image(),
            &driver.read_image(),
            scene.tolerance.channel,
        );
        let line = format!(
            "{} at 1.5 s: {:.4}% off by more than {} (allowed {}%)",
            scene.name, cmp.differing_percent, scene.tolerance.channel, scene.tolerance.max_percent
        );
        let _ = writeln!(std::io::stderr(), "{line}");
        if !cmp.passes(scene.tolerance.max_percent) {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// gluLookAt as the GLU 1.3 specification defines it: f = normalize(center - eye),
/// s = normalize(f × up), u = s × f, M = [s; u; -f] (rows), followed by a translation by -eye.
/// Written here independently of `fixedgl::glu`, returning the column-major matrix.
fn look_at_matrix(eye: [f64; 3], center: [f64; 3], up: [f64; 3]) -> [f64; 16] {
    let norm = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / l, v[1] / l, v[2] / l]
    };
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let f = norm([center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]]);
    let s = norm(cross(f, up));
    let u = cross(s, f);
    [
        s[0], u[0], -f[0], 0.0, //
        s[1], u[1], -f[1], 0.0, //
        s[2], u[2], -f[2], 0.0, //
        0.0, 0.0, 0.0, 1.0,
    ]
}

/// The seed's JOGL `Rendering` frame (SMOOTH, 40x40 cells) written straight against the driver's
/// entry points, with the grid from the scene module (geometry is not what is under test here).
fn gauss_smooth_40_direct(gl: &GlBackend) {
    use fixedgl::scenes::gaussian::{calculate_normal, create_matrix};
    let mut m = create_matrix(40);
    calculate_normal(&mut m);
    let look = look_at_matrix([1.5, 0.75, 1.0], [0.0; 3], [0.0, 1.0, 0.0]);
    // SAFETY: plain driver calls on the backend's current context; every pointer points to as
    // many values as the call reads.
    unsafe {
        let raw = gl.raw();
        raw.ClearColor(1.0, 1.0, 1.0, 1.0);
        raw.Enable(gl::DEPTH_TEST);
        raw.MatrixMode(gl::MODELVIEW);
        raw.LoadIdentity();
        raw.MultMatrixd(look.as_ptr());
        raw.Translated(-1.5, -0.75, -1.0);
        raw.MatrixMode(gl::PROJECTION);
        raw.LoadIdentity();
        raw.Ortho(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5);
        let position = [1.0f32, 1.5, -0.5, 1.0];
        let white = [1.0f32; 4];
        let black = [0.0f32, 0.0, 0.0, 1.0];
        raw.Lightfv(gl::LIGHT0, gl::POSITION, position.as_ptr());
        raw.Lightfv(gl::LIGHT0, gl::AMBIENT, black.as_ptr());
        raw.Lightfv(gl::LIGHT0, gl::DIFFUSE, white.as_ptr());
        raw.Lightfv(gl::LIGHT0, gl::SPECULAR, white.as_ptr());
        raw.Enable(gl::LIGHTING);
        raw.Enable(gl::LIGHT0);
        raw.ShadeModel(gl::SMOOTH);
        raw.Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        let diffuse = [0.5f32, 0.5, 0.8, 1.0];
        raw.Materialfv(gl::FRONT, gl::DIFFUSE, diffuse.as_ptr());
        raw.Materialfv(gl::FRONT, gl::SPECULAR, white.as_ptr());
        raw.Materialf(gl::FRONT, gl::SHININESS, 100.0);
        for i in 1..m.len() - 1 {
            for j in 1..m.len() - 1 {
                raw.Begin(gl::TRIANGLE_STRIP);
                for c in [&m[i + 1][j], &m[i + 1][j + 1], &m[i][j], &m[i][j + 1]] {
                    raw.Normal3f(c.normal[0], c.normal[1], c.normal[2]);
                    raw.Vertex3f(c.point[0], c.point[1], c.point[2]);
                }
                raw.End();
            }
        }
        raw.Flush();
        raw.Finish();
    }
}

/// `fixedgl render --backend gl gauss-smooth-40` (the recorded scene replayed) is pixel-identical
/// to the same frame sent straight to the driver: the replay adds nothing of its own.
#[test]
fn gauss_smooth_40_replay_is_pixel_identical_to_direct_driver_calls() {
    let Some(scene) = scenes::find("gauss-smooth-40") else {
        panic!("the gauss-smooth-40 scene is registered")
    };
    let (w, h) = scene.default_size;
    let Ok((_, calls)) = scene.record(w, h) else {
        panic!("recording gauss-smooth-40")
    };
    let Some(mut replayed) = backend(w, h) else {
        return;
    };
    replayed.replay(&calls);
    replayed.finish();
    let a = replayed.read_image();
    drop(replayed);
    let Some(mut direct) = backend(w, h) else {
        return;
    };
    gauss_smooth_40_direct(&direct);
    let b = direct.read_image();
    let differing = a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count();
    assert_eq!(
        differing, 0,
        "replayed and direct frames differ in {differing} pixels"
    );
    // Not vacuous: the white background and the lit surface are both there.
    assert_eq!(a.get_pixel(0, 0).0, [255, 255, 255, 255]);
    assert!(a.pixels().filter(|p| p.0 != [255, 255, 255, 255]).count() > 100_000);
}

/// `occlusion-query` chooses what to draw from query results the CPU computed at record time;
/// the replay makes the same draws whatever the driver counts. So the counts themselves are
/// checked: the recorded calls run one at a time on a CPU context and on the driver, and after
/// every EndQuery both answer QUERY_RESULT for the query just ended — equal, and some zero
/// (culled) and some not (drawn), so the scene exercises both branches.
#[test]
fn occlusion_query_scene_counts_what_the_driver_counts() {
    let Some(scene) = scenes::find("occlusion-query") else {
        panic!("occlusion-query is registered")
    };
    let (w, h) = scene.default_size;
    let (_, calls) = scene.record(w, h).unwrap();
    let Some(mut driver) = crate::common::test_backend_with(w, h, scene.config) else {
        return;
    };
    let mut cpu = fixedgl::Context::with_config(w, h, scene.config).unwrap();
    let (mut active, mut pairs) = (0u32, Vec::new());
    for call in &calls {
        cpu.replay(std::slice::from_ref(call));
        driver.replay(std::slice::from_ref(call));
        match *call {
            fixedgl::Call::BeginQuery(_, id) => active = id,
            fixedgl::Call::EndQuery(_) => {
                let mut c = [u32::MAX];
                cpu.get_query_objectuiv(active, gl::QUERY_RESULT, &mut c);
                let mut d = u32::MAX - 1;
                // SAFETY: QUERY_RESULT writes one GLuint; this thread's backend is current.
                unsafe {
                    driver
                        .raw()
                        .GetQueryObjectuiv(active, gl::QUERY_RESULT, &mut d)
                };
                pairs.push((c[0], d));
            }
            _ => {}
        }
    }
    assert_eq!(cpu.get_error(), gl::NO_ERROR);
    assert_eq!(driver.get_error(), gl::NO_ERROR);
    assert_eq!(pairs.len(), 5);
    assert!(
        pairs.iter().all(|(c, d)| c == d),
        "cpu vs driver counts: {pairs:?}"
    );
    assert!(
        pairs.iter().any(|p| p.0 == 0) && pairs.iter().any(|p| p.0 > 0),
        "{pairs:?}"
    );
}
