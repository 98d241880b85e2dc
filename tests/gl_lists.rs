//! Display lists and attribute stacks on the real driver: the GL backend replays NewList,
//! EndList and CallList so the driver builds its own lists (GL 2.1 §5.4), and its own
//! bookkeeping (Begin/End phase, PHONG_WIN emulation, errors it raises itself) must survive
//! calls that are compiled rather than executed. Skips (printing why) without an EGL device.
#![cfg(feature = "gl")]

use fixedgl::compare::compare;
use fixedgl::glbackend::{DeviceChoice, GlBackend};
use fixedgl::{gl, scenes, Call, Context};
use std::io::Write as _;

fn backend(width: u32, height: u32) -> Option<GlBackend> {
    match GlBackend::new(width, height, &DeviceChoice::Auto) {
        Ok(b) => Some(b),
        Err(e) if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() => {
            panic!("FIXEDGL_REQUIRE_GL is set but the GL backend cannot start: {e}")
        }
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED: GL backend unavailable: {e}");
            None
        }
    }
}

#[test]
fn list_scenes_match_the_driver() {
    for name in ["display-list", "glut-shapes"] {
        let Some(scene) = scenes::find(name) else {
            panic!("{name} is not registered");
        };
        let Ok((mut ctx, calls)) = scene.record(160, 160) else {
            panic!("{name} did not record");
        };
        assert!(calls.iter().any(|c| matches!(c, Call::CallList(_))) || name != "display-list");
        let Some(mut gl) = backend(160, 160) else {
            return;
        };
        gl.replay(&calls);
        assert_eq!(gl.get_error(), gl::NO_ERROR, "{name}");
        let cmp = compare(&scenes::cpu_image(&mut ctx), &gl.read_image(), 2);
        assert!(cmp.differing_percent <= 0.05, "{name}: {cmp:?}");
    }
}

#[test]
fn compiled_begin_end_and_errors_come_when_the_list_runs() {
    let Some(mut gl) = backend(16, 16) else {
        return;
    };
    let mut cpu = Context::new(16, 16).expect("context");
    let calls = [
        Call::NewList(1, gl::COMPILE),
        Call::Begin(gl::TRIANGLES),
        Call::Vertex2f(-1.0, -1.0),
        Call::Vertex2f(1.0, -1.0),
        Call::Vertex2f(0.0, 1.0),
        Call::End,
        Call::Lightfv(gl::LIGHT0, gl::POSITION, vec![1.0]),
        Call::EndList,
    ];
    gl.replay(&calls);
    cpu.replay(&calls);
    // Nothing ran: no error, and no Begin/End pair is open (a query is allowed).
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    assert_eq!(cpu.get_error(), gl::NO_ERROR);
    let mut depth = [-1];
    gl.get_integerv(gl::LIST_INDEX, &mut depth);
    assert_eq!(depth, [0]);
    // Running it draws, and raises the short slice's INVALID_VALUE now.
    gl.execute(&Call::CallList(1));
    cpu.execute(&Call::CallList(1));
    assert_eq!(gl.get_error(), gl::INVALID_VALUE);
    assert_eq!(cpu.get_error(), gl::INVALID_VALUE);
    let (g, c) = (gl.read_image(), scenes::cpu_image(&mut cpu));
    assert_eq!(compare(&c, &g, 0).differing_pixels, 0);
    assert_eq!(g.get_pixel(8, 8).0, [255, 255, 255, 255]);
}

#[test]
fn phong_win_inside_a_list_is_shaded_per_fragment() {
    // As tests/gl_backend.rs `phong_win_lights_per_fragment`: a 64x64 lit quad, LIGHT0 at eye
    // (0, 0, 1, 1), no specular; per fragment the centre pixel is 0.2*0.2 + 0.8*0.99975598
    // = 0.8398 -> 214, where Gouraud shading gives 128.
    let Some(mut gl) = backend(64, 64) else {
        return;
    };
    let calls = vec![
        Call::Lightfv(gl::LIGHT0, gl::POSITION, vec![0.0, 0.0, 1.0, 1.0]),
        Call::Lightfv(gl::LIGHT0, gl::SPECULAR, vec![0.0, 0.0, 0.0, 1.0]),
        Call::NewList(7, gl::COMPILE),
        Call::ShadeModel(gl::PHONG_WIN),
        Call::Enable(gl::LIGHTING),
        Call::Enable(gl::LIGHT0),
        Call::Begin(gl::QUADS),
        Call::Vertex3f(-1.0, -1.0, 0.0),
        Call::Vertex3f(1.0, -1.0, 0.0),
        Call::Vertex3f(1.0, 1.0, 0.0),
        Call::Vertex3f(-1.0, 1.0, 0.0),
        Call::End,
        Call::EndList,
    ];
    gl.replay(&calls);
    let mut shade = [0];
    gl.get_integerv(gl::SHADE_MODEL, &mut shade);
    assert_eq!(
        shade,
        [gl::SMOOTH as i32],
        "COMPILE changed the shade model"
    );
    gl.execute(&Call::CallList(7));
    gl.finish();
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    gl.get_integerv(gl::SHADE_MODEL, &mut shade);
    assert_eq!(shade, [gl::PHONG_WIN as i32]);
    let centre = gl.read_image().get_pixel(32, 31).0;
    assert!(
        centre[..3].iter().all(|&c| c.abs_diff(214) <= 1),
        "{centre:?}"
    );
}

#[test]
fn attribute_stacks_restore_on_the_driver_as_on_the_cpu() {
    let Some(mut gl) = backend(8, 8) else { return };
    let mut cpu = Context::new(8, 8).expect("context");
    let calls = [
        Call::PushAttrib(gl::POINT_BIT | gl::LIGHTING_BIT),
        Call::PointSize(4.0),
        Call::ShadeModel(gl::FLAT),
        Call::PushAttrib(gl::LINE_BIT),
        Call::LineWidth(3.0),
        Call::PopAttrib,
        Call::PopAttrib,
        Call::PopAttrib,
    ];
    gl.replay(&calls);
    cpu.replay(&calls);
    for pname in [
        gl::POINT_SIZE,
        gl::LINE_WIDTH,
        gl::SHADE_MODEL,
        gl::ATTRIB_STACK_DEPTH,
    ] {
        let (mut a, mut b) = ([0.0f32], [0.0f32]);
        gl.get_floatv(pname, &mut a);
        cpu.get_floatv(pname, &mut b);
        assert_eq!(a, b, "{pname:#x}");
    }
    assert_eq!(gl.get_error(), gl::STACK_UNDERFLOW);
    assert_eq!(cpu.get_error(), gl::STACK_UNDERFLOW);
}

#[test]
fn gen_lists_hands_out_the_names_the_driver_does() {
    let Some(gl) = backend(4, 4) else { return };
    let mut cpu = Context::new(4, 4).expect("context");
    let raw = gl.raw();
    // SAFETY: plain driver calls, no pointers.
    let driver = unsafe {
        let a = raw.GenLists(3);
        raw.DeleteLists(a, 3);
        let b = raw.GenLists(2);
        raw.NewList(50, gl::COMPILE);
        raw.EndList();
        let c = raw.GenLists(1);
        [a, b, c]
    };
    let a = cpu.gen_lists(3);
    cpu.delete_lists(a, 3);
    let b = cpu.gen_lists(2);
    cpu.new_list(50, gl::COMPILE);
    cpu.end_list();
    let c = cpu.gen_lists(1);
    assert_eq!([a, b, c], driver);
}
