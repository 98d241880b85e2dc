//! Display lists (GL 2.1 §5.4): a list replays exactly as the same immediate calls, errors are
//! raised when the list runs (NewList/EndList's own at once), the immediate-execution commands
//! are not stored, nesting stops at MAX_LIST_NESTING, and CallLists reads every type.

use fixedgl::{gl, Call, Context};

fn ctx() -> Context {
    Context::new(32, 32).expect("context")
}

fn get_i(c: &mut Context, pname: u32) -> i32 {
    let mut v = [i32::MIN; 16];
    c.get_integerv(pname, &mut v);
    v[0]
}

/// The x translation of the modelview matrix.
fn tx(c: &mut Context) -> f32 {
    let mut m = [0.0; 16];
    c.get_floatv(gl::MODELVIEW_MATRIX, &mut m);
    m[12]
}

/// A lit, coloured quad strip and a fan: state changes and vertices in one drawing.
fn draw(c: &mut Context) {
    c.shade_model(gl::SMOOTH);
    c.enable(gl::LIGHTING);
    c.enable(gl::LIGHT0);
    c.enable(gl::COLOR_MATERIAL);
    c.rotatef(20.0, 0.0, 0.0, 1.0);
    c.begin(gl::QUAD_STRIP);
    for i in 0..6 {
        let x = -0.8 + 0.3 * i as f32;
        c.color3f(0.2 * i as f32, 0.5, 1.0 - 0.15 * i as f32);
        c.normal3f(0.3 * (i as f32 - 2.5), 0.0, 1.0);
        c.vertex2f(x, -0.5);
        c.vertex2f(x, 0.1);
    }
    c.end();
    c.disable(gl::LIGHTING);
    c.begin(gl::TRIANGLE_FAN);
    c.color3f(1.0, 1.0, 0.0);
    c.vertex2f(0.0, 0.5);
    c.color3f(0.0, 1.0, 1.0);
    c.vertex2f(-0.4, 0.9);
    c.vertex2f(0.4, 0.9);
    c.end();
}

#[test]
fn a_list_replays_as_the_same_immediate_calls() {
    let mut immediate = ctx();
    immediate.clear(gl::COLOR_BUFFER_BIT);
    draw(&mut immediate);

    let mut listed = ctx();
    listed.new_list(5, gl::COMPILE);
    draw(&mut listed);
    listed.end_list();
    // COMPILE executed nothing: the state is still the initial one.
    assert_eq!(listed.state(), ctx().state());
    assert_eq!(listed.get_error(), gl::NO_ERROR);
    listed.clear(gl::COLOR_BUFFER_BIT);
    listed.call_list(5);
    assert_eq!(listed.get_error(), gl::NO_ERROR);
    assert_eq!(listed.state(), immediate.state());
    assert_eq!(listed.to_image(), immediate.to_image());

    // COMPILE_AND_EXECUTE draws at once, and the list draws the same again.
    let mut both = ctx();
    both.clear(gl::COLOR_BUFFER_BIT);
    both.new_list(1, gl::COMPILE_AND_EXECUTE);
    draw(&mut both);
    both.end_list();
    assert_eq!(both.state(), immediate.state());
    assert_eq!(both.to_image(), immediate.to_image());
    assert_eq!(both.list_calls(1), listed.list_calls(5));
}

#[test]
fn errors_are_raised_when_the_list_runs() {
    let mut c = ctx();
    c.new_list(1, gl::COMPILE);
    c.lightfv(gl::LIGHT0, gl::POSITION, &[1.0]); // too short: INVALID_VALUE when run
    c.enable(0xdead); // INVALID_ENUM when run
    c.end(); // End without Begin: INVALID_OPERATION when run
    c.end_list();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(c.list_calls(1).map(<[Call]>::len), Some(3));
    c.call_list(1);
    // The first error sticks (GL 2.1 §2.5).
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(c.get_error(), gl::NO_ERROR);

    // NewList and EndList check their own arguments at once.
    c.new_list(0, gl::COMPILE);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.new_list(2, gl::COMPILE + 2);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.end_list();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.new_list(2, gl::COMPILE);
    c.new_list(3, gl::COMPILE);
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    c.color3f(1.0, 0.0, 0.0);
    c.end_list();
    // List 2 was still being defined, and got the colour; 3 was never made.
    assert_eq!(c.list_calls(2), Some(&[Call::Color3f(1.0, 0.0, 0.0)][..]));
    assert!(!c.is_list(3));
    // Inside Begin/End, NewList and EndList are INVALID_OPERATION; CallList is allowed.
    c.begin(gl::POINTS);
    c.new_list(4, gl::COMPILE);
    c.call_list(2);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(get_i(&mut c, gl::LIST_INDEX), 0);
}

#[test]
fn immediate_commands_are_executed_not_stored() {
    let mut c = ctx();
    c.start_recording();
    c.new_list(7, gl::COMPILE);
    c.pixel_storei(gl::PACK_ALIGNMENT, 2);
    c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
    c.pop_client_attrib();
    c.client_active_texture(gl::TEXTURE1);
    let base = c.gen_lists(3);
    c.flush();
    c.finish();
    c.delete_lists(base, 1);
    assert!(c.is_list(base + 1));
    assert_eq!(get_i(&mut c, gl::LIST_INDEX), 7);
    assert_eq!(get_i(&mut c, gl::LIST_MODE), gl::COMPILE as i32);
    c.point_size(3.0); // compiled
    c.end_list();
    assert_eq!(get_i(&mut c, gl::PACK_ALIGNMENT), 2);
    assert_eq!(
        get_i(&mut c, gl::CLIENT_ACTIVE_TEXTURE),
        gl::TEXTURE1 as i32
    );
    assert_eq!(c.list_calls(7), Some(&[Call::PointSize(3.0)][..]));
    assert_eq!(get_i(&mut c, gl::LIST_INDEX), 0);
    assert_eq!(get_i(&mut c, gl::LIST_MODE), 0);
    // The recording holds everything the caller made, the list's content once.
    let rec = c.stop_recording();
    assert_eq!(rec.len(), 11);
    assert_eq!(rec[0], Call::NewList(7, gl::COMPILE));
    assert_eq!(rec[9], Call::PointSize(3.0));
    assert_eq!(rec[10], Call::EndList);
}

#[test]
fn nesting_stops_at_max_list_nesting() {
    let mut c = ctx();
    assert_eq!(get_i(&mut c, gl::MAX_LIST_NESTING), 64);
    // List k translates by 1 and calls list k + 1: only 64 levels run.
    for k in 1..=100 {
        c.new_list(k, gl::COMPILE);
        c.translatef(1.0, 0.0, 0.0);
        c.call_list(k + 1);
        c.end_list();
    }
    c.call_list(1);
    assert_eq!(tx(&mut c), 64.0);
    // A list calling itself stops at the same depth.
    c.load_identity();
    c.new_list(200, gl::COMPILE);
    c.translatef(1.0, 0.0, 0.0);
    c.call_list(200);
    c.end_list();
    c.call_list(200);
    assert_eq!(tx(&mut c), 64.0);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn call_lists_reads_every_type_offset_by_list_base() {
    let mut c = ctx();
    // List n translates by n.
    for n in 1..=300u32 {
        c.new_list(n, gl::COMPILE);
        c.translatef(n as f32, 0.0, 0.0);
        c.end_list();
    }
    c.list_base(10);
    assert_eq!(get_i(&mut c, gl::LIST_BASE), 10);
    let cases: Vec<(u32, Vec<u8>, f32)> = vec![
        (gl::UNSIGNED_BYTE, vec![1, 2], 11.0 + 12.0),
        (gl::BYTE, vec![0xff, 5], 9.0 + 15.0),
        (
            gl::SHORT,
            [-3i16, 4].iter().flat_map(|v| v.to_ne_bytes()).collect(),
            7.0 + 14.0,
        ),
        (
            gl::UNSIGNED_SHORT,
            [200u16].iter().flat_map(|v| v.to_ne_bytes()).collect(),
            210.0,
        ),
        (
            gl::INT,
            [-9i32].iter().flat_map(|v| v.to_ne_bytes()).collect(),
            1.0,
        ),
        (
            gl::UNSIGNED_INT,
            [290u32].iter().flat_map(|v| v.to_ne_bytes()).collect(),
            300.0,
        ),
        (
            gl::FLOAT,
            [5.9f32].iter().flat_map(|v| v.to_ne_bytes()).collect(),
            15.0,
        ),
        (gl::GL_2_BYTES, vec![1, 0], 266.0),
        (gl::GL_3_BYTES, vec![0, 0, 20], 30.0),
        (gl::GL_4_BYTES, vec![0, 0, 0, 40], 50.0),
    ];
    for (ty, bytes, expected) in cases {
        c.load_identity();
        let n = bytes.len() / fixed_size(ty);
        c.call_lists(n as i32, ty, &bytes);
        assert_eq!(c.get_error(), gl::NO_ERROR, "type {ty:#x}");
        assert_eq!(tx(&mut c), expected, "type {ty:#x}");
    }
    // Errors: negative n, unknown type, an array shorter than n names.
    c.load_identity();
    c.call_lists(-1, gl::UNSIGNED_BYTE, &[1]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    c.call_lists(1, gl::DOUBLE, &[1; 8]);
    assert_eq!(c.get_error(), gl::INVALID_ENUM);
    c.call_lists(2, gl::UNSIGNED_SHORT, &[1, 0, 0]);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(tx(&mut c), 0.0);
}

fn fixed_size(ty: u32) -> usize {
    match ty {
        gl::UNSIGNED_BYTE | gl::BYTE => 1,
        gl::SHORT | gl::UNSIGNED_SHORT | gl::GL_2_BYTES => 2,
        gl::GL_3_BYTES => 3,
        _ => 4,
    }
}

#[test]
fn names_are_generated_tested_and_deleted() {
    let mut c = ctx();
    assert_eq!(c.gen_lists(0), 0);
    assert_eq!(c.gen_lists(-1), 0);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    let a = c.gen_lists(3);
    assert_eq!(a, 1);
    assert!(c.is_list(1) && c.is_list(3) && !c.is_list(4) && !c.is_list(0));
    // A huge range costs nothing: names are kept as runs.
    let b = c.gen_lists(i32::MAX);
    assert_eq!(b, 4);
    c.delete_lists(4, i32::MAX);
    assert!(!c.is_list(4));
    c.delete_lists(2, 1);
    assert!(c.is_list(1) && !c.is_list(2) && c.is_list(3));
    c.delete_lists(1, -1);
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    // A redefinition replaces the list.
    c.new_list(3, gl::COMPILE);
    c.point_size(2.0);
    c.end_list();
    c.new_list(3, gl::COMPILE);
    c.line_width(2.0);
    c.end_list();
    assert_eq!(c.list_calls(3), Some(&[Call::LineWidth(2.0)][..]));
    // Calling an undefined list does nothing.
    c.call_list(999);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn a_recording_holds_call_list_and_replays_the_same() {
    let mut c = ctx();
    c.start_recording();
    c.new_list(1, gl::COMPILE);
    draw(&mut c);
    c.end_list();
    c.clear(gl::COLOR_BUFFER_BIT);
    c.call_list(1);
    c.translatef(0.1, 0.0, 0.0);
    c.call_list(1);
    let rec = c.stop_recording();
    assert_eq!(rec.iter().filter(|x| **x == Call::CallList(1)).count(), 2);
    let mut r = ctx();
    r.replay(&rec);
    assert_eq!(r.state(), c.state());
    assert_eq!(r.to_image(), c.to_image());
}

/// GL 2.1 §5.4: a vertex-array draw compiled into a display list captures the array data at
/// compile time. A triangle in the left half is compiled; then the vertex array is repointed at a
/// triangle in the right half before the list runs. The list must still draw the left one —
/// exactly what drawing it immediately draws — and the driver must agree.
#[test]
fn compiled_draw_arrays_keeps_the_arrays_of_compile_time() {
    let left: [f32; 6] = [-0.9, -0.9, -0.1, -0.9, -0.5, 0.9];
    let right: [f32; 6] = [0.1, -0.9, 0.9, -0.9, 0.5, 0.9];
    let colours: [u8; 12] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255];
    let setup = |c: &mut Context, verts: &[f32; 6]| {
        c.enable_client_state(gl::VERTEX_ARRAY);
        c.enable_client_state(gl::COLOR_ARRAY);
        c.vertex_pointer(2, gl::FLOAT, 0, verts);
        c.color_pointer(4, gl::UNSIGNED_BYTE, 0, &colours);
    };

    let mut listed = Context::new(64, 64).expect("context");
    listed.start_recording();
    setup(&mut listed, &left);
    listed.new_list(1, gl::COMPILE);
    listed.draw_arrays(gl::TRIANGLES, 0, 3);
    listed.end_list();
    listed.vertex_pointer(2, gl::FLOAT, 0, &right);
    listed.call_list(1);
    assert_eq!(listed.get_error(), gl::NO_ERROR);
    // The recording is replayed on the driver below (with the `gl` feature).
    #[cfg_attr(not(feature = "gl"), allow(unused_variables))]
    let calls = listed.stop_recording();
    let got = listed.to_image();

    let mut direct = Context::new(64, 64).expect("context");
    setup(&mut direct, &left);
    direct.draw_arrays(gl::TRIANGLES, 0, 3);
    let want = direct.to_image();
    assert!(
        want.pixels().filter(|p| p.0[3] != 0).count() > 300,
        "the triangle is drawn"
    );
    assert_eq!(
        got.as_raw(),
        want.as_raw(),
        "the list drew the arrays of call time"
    );

    #[cfg(feature = "gl")]
    if let Some(mut driver) = crate::common::test_backend(64, 64) {
        driver.replay(&calls);
        driver.finish();
        assert_eq!(driver.get_error(), gl::NO_ERROR);
        let c = fixedgl::compare::compare(&got, &driver.read_image(), 2);
        assert_eq!(c.differing_pixels, 0, "{c}");
    }
}
