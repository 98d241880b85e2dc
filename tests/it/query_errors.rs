//! Error rows for the transformation entry points and the queries: `(setup, call, expected
//! error)`, each checking that the erroneous call changed nothing but the error flag
//! (GL 2.1 §2.5) and, for queries, wrote nothing into the caller's buffer.
//!
//! Expected errors come from GL 2.1: §2.6.3 (INVALID_OPERATION between Begin and End),
//! §2.11.1 (Viewport), §2.11.2 (MatrixMode, Frustum, Ortho, stacks), §2.12 (ClipPlane),
//! §2.14.1 (ActiveTexture), §6.1 (queries: unknown pname INVALID_ENUM) and the pinned API rule
//! that a slice shorter than the pname needs is INVALID_VALUE.

use fixedgl::{gl, Context};

fn ctx() -> Context {
    match Context::new(32, 32) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// Where the erroneous call is made.
#[derive(Clone, Copy, PartialEq, Eq)]
enum At {
    /// After `setup`, outside any Begin/End.
    Outside,
    /// After `setup`, between `begin(TRIANGLES)` and `end()`.
    InsideBegin,
}
use At::{InsideBegin, Outside};

struct Row {
    name: &'static str,
    at: At,
    setup: fn(&mut Context),
    call: fn(&mut Context),
    error: u32,
}

/// A context whose every matrix and transform state differs from the initial one, so that a
/// call that wrongly resets something shows.
fn busy(c: &mut Context) {
    c.translatef(1.0, 2.0, 3.0);
    c.matrix_mode(gl::PROJECTION);
    c.scalef(2.0, 2.0, 2.0);
    c.matrix_mode(gl::TEXTURE);
    c.rotatef(30.0, 0.0, 0.0, 1.0);
    c.matrix_mode(gl::MODELVIEW);
    c.viewport(1, 2, 3, 4);
    c.depth_range(0.25, 0.75);
    c.clip_plane(gl::CLIP_PLANE1, &[1.0, 0.0, 0.0, 0.5]);
    c.active_texture(gl::TEXTURE2);
    c.client_active_texture(gl::TEXTURE1);
}

fn push_n(c: &mut Context, n: usize) {
    for _ in 0..n {
        c.push_matrix();
    }
}

const M16F: [f32; 16] = [2.0; 16];
const M16D: [f64; 16] = [2.0; 16];
const BAD_PNAME: u32 = 0xFFFF;

#[rustfmt::skip]
fn rows() -> Vec<Row> {
    macro_rules! row {
        ($name:expr, $at:expr, $setup:expr, $call:expr, $err:ident) => {
            Row {
                name: $name,
                at: $at,
                setup: $setup,
                call: $call,
                error: gl::$err,
            }
        };
    }
    vec![
        // MatrixMode (§2.11.2).
        row!("matrix_mode(0)", Outside, busy, |c| c.matrix_mode(0), INVALID_ENUM),
        row!("matrix_mode(COLOR)", Outside, busy, |c| c.matrix_mode(gl::COLOR), INVALID_ENUM),
        row!("matrix_mode(TEXTURE0)", Outside, busy, |c| c.matrix_mode(gl::TEXTURE0), INVALID_ENUM),
        row!("matrix_mode in Begin", InsideBegin, busy, |c| c.matrix_mode(gl::PROJECTION), INVALID_OPERATION),
        // Load / Mult in Begin/End.
        row!("load_identity in Begin", InsideBegin, busy, |c| c.load_identity(), INVALID_OPERATION),
        row!("load_matrixf in Begin", InsideBegin, busy, |c| c.load_matrixf(&M16F), INVALID_OPERATION),
        row!("load_matrixd in Begin", InsideBegin, busy, |c| c.load_matrixd(&M16D), INVALID_OPERATION),
        row!("mult_matrixf in Begin", InsideBegin, busy, |c| c.mult_matrixf(&M16F), INVALID_OPERATION),
        row!("mult_matrixd in Begin", InsideBegin, busy, |c| c.mult_matrixd(&M16D), INVALID_OPERATION),
        row!("load_transpose_matrixf in Begin", InsideBegin, busy, |c| c.load_transpose_matrixf(&M16F), INVALID_OPERATION),
        row!("load_transpose_matrixd in Begin", InsideBegin, busy, |c| c.load_transpose_matrixd(&M16D), INVALID_OPERATION),
        row!("mult_transpose_matrixf in Begin", InsideBegin, busy, |c| c.mult_transpose_matrixf(&M16F), INVALID_OPERATION),
        row!("mult_transpose_matrixd in Begin", InsideBegin, busy, |c| c.mult_transpose_matrixd(&M16D), INVALID_OPERATION),
        row!("translatef in Begin", InsideBegin, busy, |c| c.translatef(1.0, 1.0, 1.0), INVALID_OPERATION),
        row!("translated in Begin", InsideBegin, busy, |c| c.translated(1.0, 1.0, 1.0), INVALID_OPERATION),
        row!("rotatef in Begin", InsideBegin, busy, |c| c.rotatef(10.0, 1.0, 0.0, 0.0), INVALID_OPERATION),
        row!("rotated in Begin", InsideBegin, busy, |c| c.rotated(10.0, 1.0, 0.0, 0.0), INVALID_OPERATION),
        row!("scalef in Begin", InsideBegin, busy, |c| c.scalef(2.0, 2.0, 2.0), INVALID_OPERATION),
        row!("scaled in Begin", InsideBegin, busy, |c| c.scaled(2.0, 2.0, 2.0), INVALID_OPERATION),
        // Frustum (§2.11.2).
        row!("frustum near = 0", Outside, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0), INVALID_VALUE),
        row!("frustum near < 0", Outside, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, -1.0, 10.0), INVALID_VALUE),
        row!("frustum far = 0", Outside, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 0.0), INVALID_VALUE),
        row!("frustum far < 0", Outside, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, -5.0), INVALID_VALUE),
        row!("frustum left = right", Outside, busy, |c| c.frustum(2.0, 2.0, -1.0, 1.0, 1.0, 10.0), INVALID_VALUE),
        row!("frustum bottom = top", Outside, busy, |c| c.frustum(-1.0, 1.0, 3.0, 3.0, 1.0, 10.0), INVALID_VALUE),
        row!("frustum near = far", Outside, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 4.0, 4.0), INVALID_VALUE),
        row!("frustum in Begin", InsideBegin, busy, |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0), INVALID_OPERATION),
        row!("bad frustum in Begin: Begin/End first", InsideBegin, busy, |c| c.frustum(1.0, 1.0, -1.0, 1.0, 0.0, 10.0), INVALID_OPERATION),
        // Ortho (§2.11.2); negative near/far are legal there.
        row!("ortho left = right", Outside, busy, |c| c.ortho(1.0, 1.0, -1.0, 1.0, -1.0, 1.0), INVALID_VALUE),
        row!("ortho bottom = top", Outside, busy, |c| c.ortho(-1.0, 1.0, 0.0, 0.0, -1.0, 1.0), INVALID_VALUE),
        row!("ortho near = far", Outside, busy, |c| c.ortho(-1.0, 1.0, -1.0, 1.0, -2.0, -2.0), INVALID_VALUE),
        row!("ortho in Begin", InsideBegin, busy, |c| c.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0), INVALID_OPERATION),
        // Matrix stacks (§2.11.2).
        row!("push modelview at 32", Outside, |c| { busy(c); push_n(c, 31) }, |c| c.push_matrix(), STACK_OVERFLOW),
        row!("push projection at 32", Outside, |c| { busy(c); c.matrix_mode(gl::PROJECTION); push_n(c, 31) }, |c| c.push_matrix(), STACK_OVERFLOW),
        row!("push texture unit 2 at 10", Outside, |c| { busy(c); c.matrix_mode(gl::TEXTURE); push_n(c, 9) }, |c| c.push_matrix(), STACK_OVERFLOW),
        row!("pop modelview at 1", Outside, busy, |c| c.pop_matrix(), STACK_UNDERFLOW),
        row!("pop projection at 1", Outside, |c| { busy(c); c.matrix_mode(gl::PROJECTION) }, |c| c.pop_matrix(), STACK_UNDERFLOW),
        row!("pop texture at 1", Outside, |c| { busy(c); c.matrix_mode(gl::TEXTURE) }, |c| c.pop_matrix(), STACK_UNDERFLOW),
        row!("pop texture unit 0 at 1 while unit 2 is pushed", Outside, |c| { busy(c); c.matrix_mode(gl::TEXTURE); c.push_matrix(); c.active_texture(gl::TEXTURE0) }, |c| c.pop_matrix(), STACK_UNDERFLOW),
        row!("push in Begin", InsideBegin, busy, |c| c.push_matrix(), INVALID_OPERATION),
        row!("pop in Begin", InsideBegin, |c| { busy(c); c.push_matrix() }, |c| c.pop_matrix(), INVALID_OPERATION),
        // Viewport, DepthRange (§2.11.1).
        row!("viewport width < 0", Outside, busy, |c| c.viewport(0, 0, -1, 10), INVALID_VALUE),
        row!("viewport height < 0", Outside, busy, |c| c.viewport(0, 0, 10, -1), INVALID_VALUE),
        row!("viewport in Begin", InsideBegin, busy, |c| c.viewport(0, 0, 10, 10), INVALID_OPERATION),
        row!("depth_range in Begin", InsideBegin, busy, |c| c.depth_range(0.0, 0.5), INVALID_OPERATION),
        // ClipPlane (§2.12).
        row!("clip_plane(CLIP_PLANE0 + 6)", Outside, busy, |c| c.clip_plane(gl::CLIP_PLANE0 + 6, &[1.0; 4]), INVALID_ENUM),
        row!("clip_plane(CLIP_PLANE0 - 1)", Outside, busy, |c| c.clip_plane(gl::CLIP_PLANE0 - 1, &[1.0; 4]), INVALID_ENUM),
        row!("clip_plane(0)", Outside, busy, |c| c.clip_plane(0, &[1.0; 4]), INVALID_ENUM),
        row!("clip_plane in Begin", InsideBegin, busy, |c| c.clip_plane(gl::CLIP_PLANE0, &[1.0; 4]), INVALID_OPERATION),
        // ActiveTexture, ClientActiveTexture (§2.14.1, §2.8).
        row!("active_texture(TEXTURE0 + 4)", Outside, busy, |c| c.active_texture(gl::TEXTURE0 + 4), INVALID_ENUM),
        row!("active_texture(TEXTURE0 - 1)", Outside, busy, |c| c.active_texture(gl::TEXTURE0 - 1), INVALID_ENUM),
        row!("active_texture(0)", Outside, busy, |c| c.active_texture(0), INVALID_ENUM),
        row!("active_texture in Begin", InsideBegin, busy, |c| c.active_texture(gl::TEXTURE0), INVALID_OPERATION),
        row!("client_active_texture(TEXTURE0 + 4)", Outside, busy, |c| c.client_active_texture(gl::TEXTURE0 + 4), INVALID_ENUM),
        row!("client_active_texture(1)", Outside, busy, |c| c.client_active_texture(1), INVALID_ENUM),
        // glGet*v (§6.1): unknown pname, short slice, Begin/End. Each call checks its buffer.
        row!("get_booleanv(bad pname)", Outside, busy, |c| { let mut o = [true; 16]; c.get_booleanv(BAD_PNAME, &mut o); assert_eq!(o, [true; 16]) }, INVALID_ENUM),
        row!("get_integerv(light pname)", Outside, busy, |c| { let mut o = [-7; 4]; c.get_integerv(gl::SPOT_EXPONENT, &mut o); assert_eq!(o, [-7; 4]) }, INVALID_ENUM),
        row!("get_floatv(material pname)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_floatv(gl::AMBIENT, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_doublev(TEXTURE0)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_doublev(gl::TEXTURE0, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("bad pname and empty slice: enum first", Outside, busy, |c| c.get_floatv(BAD_PNAME, &mut []), INVALID_ENUM),
        row!("get_floatv(MODELVIEW_MATRIX) into 15", Outside, busy, |c| { let mut o = [-7.0; 15]; c.get_floatv(gl::MODELVIEW_MATRIX, &mut o); assert_eq!(o, [-7.0; 15]) }, INVALID_VALUE),
        row!("get_integerv(VIEWPORT) into 3", Outside, busy, |c| { let mut o = [-7; 3]; c.get_integerv(gl::VIEWPORT, &mut o); assert_eq!(o, [-7; 3]) }, INVALID_VALUE),
        row!("get_booleanv(COLOR_WRITEMASK) into 0", Outside, busy, |c| c.get_booleanv(gl::COLOR_WRITEMASK, &mut []), INVALID_VALUE),
        row!("get_doublev(DEPTH_RANGE) into 1", Outside, busy, |c| { let mut o = [-7.0]; c.get_doublev(gl::DEPTH_RANGE, &mut o); assert_eq!(o, [-7.0]) }, INVALID_VALUE),
        row!("get_floatv(CURRENT_NORMAL) into 2", Outside, busy, |c| { let mut o = [-7.0; 2]; c.get_floatv(gl::CURRENT_NORMAL, &mut o); assert_eq!(o, [-7.0; 2]) }, INVALID_VALUE),
        row!("get_booleanv in Begin", InsideBegin, busy, |c| { let mut o = [true]; c.get_booleanv(gl::DITHER, &mut o); assert_eq!(o, [true]) }, INVALID_OPERATION),
        row!("get_integerv in Begin", InsideBegin, busy, |c| { let mut o = [-7]; c.get_integerv(gl::MATRIX_MODE, &mut o); assert_eq!(o, [-7]) }, INVALID_OPERATION),
        row!("get_floatv in Begin", InsideBegin, busy, |c| { let mut o = [-7.0]; c.get_floatv(gl::POINT_SIZE, &mut o); assert_eq!(o, [-7.0]) }, INVALID_OPERATION),
        row!("get_doublev in Begin", InsideBegin, busy, |c| { let mut o = [-7.0; 2]; c.get_doublev(gl::DEPTH_RANGE, &mut o); assert_eq!(o, [-7.0; 2]) }, INVALID_OPERATION),
        // GetLight, GetMaterial (§6.1.3).
        row!("get_lightfv(LIGHT0 + 8)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_lightfv(gl::LIGHT0 + 8, gl::AMBIENT, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_lightfv(LIGHT0, SHININESS)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_lightfv(gl::LIGHT0, gl::SHININESS, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_lightiv(LIGHT0, POSITION) into 3", Outside, busy, |c| { let mut o = [-7; 3]; c.get_lightiv(gl::LIGHT0, gl::POSITION, &mut o); assert_eq!(o, [-7; 3]) }, INVALID_VALUE),
        row!("get_lightfv(LIGHT1, SPOT_DIRECTION) into 2", Outside, busy, |c| { let mut o = [-7.0; 2]; c.get_lightfv(gl::LIGHT1, gl::SPOT_DIRECTION, &mut o); assert_eq!(o, [-7.0; 2]) }, INVALID_VALUE),
        row!("get_lightfv in Begin", InsideBegin, busy, |c| { let mut o = [-7.0; 4]; c.get_lightfv(gl::LIGHT0, gl::DIFFUSE, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_OPERATION),
        row!("get_materialfv(FRONT_AND_BACK)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_materialfv(gl::FRONT_AND_BACK, gl::AMBIENT, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_materialfv(FRONT, POSITION)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_materialfv(gl::FRONT, gl::POSITION, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_materialiv(BACK, AMBIENT_AND_DIFFUSE)", Outside, busy, |c| { let mut o = [-7; 4]; c.get_materialiv(gl::BACK, gl::AMBIENT_AND_DIFFUSE, &mut o); assert_eq!(o, [-7; 4]) }, INVALID_ENUM),
        row!("get_materialfv(FRONT, DIFFUSE) into 2", Outside, busy, |c| { let mut o = [-7.0; 2]; c.get_materialfv(gl::FRONT, gl::DIFFUSE, &mut o); assert_eq!(o, [-7.0; 2]) }, INVALID_VALUE),
        row!("get_materialiv in Begin", InsideBegin, busy, |c| { let mut o = [-7]; c.get_materialiv(gl::FRONT, gl::SHININESS, &mut o); assert_eq!(o, [-7]) }, INVALID_OPERATION),
        // GetClipPlane, GetString.
        row!("get_clip_plane(CLIP_PLANE0 + 6)", Outside, busy, |c| { let mut o = [-7.0; 4]; c.get_clip_plane(gl::CLIP_PLANE0 + 6, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_ENUM),
        row!("get_clip_plane in Begin", InsideBegin, busy, |c| { let mut o = [-7.0; 4]; c.get_clip_plane(gl::CLIP_PLANE1, &mut o); assert_eq!(o, [-7.0; 4]) }, INVALID_OPERATION),
        row!("get_string(0)", Outside, busy, |c| assert_eq!(c.get_string(0), None), INVALID_ENUM),
        row!("get_string(SHADING_LANGUAGE_VERSION)", Outside, busy, |c| assert_eq!(c.get_string(gl::SHADING_LANGUAGE_VERSION), None), INVALID_ENUM),
        row!("get_string in Begin", InsideBegin, busy, |c| assert_eq!(c.get_string(gl::VENDOR), None), INVALID_OPERATION),
    ]
}

#[test]
fn every_error_row() {
    let rows = rows();
    assert!(rows.len() >= 40, "{}", rows.len());
    for row in &rows {
        let mut c = ctx();
        (row.setup)(&mut c);
        assert_eq!(
            c.get_error(),
            gl::NO_ERROR,
            "{}: setup raised an error",
            row.name
        );
        if row.at == InsideBegin {
            c.begin(gl::TRIANGLES);
        }
        let before = c.state().clone();
        (row.call)(&mut c);
        assert!(c.state() == &before, "{}: the state changed", row.name);
        if row.at == InsideBegin {
            c.end();
        }
        assert_eq!(c.get_error(), row.error, "{}", row.name);
        assert_eq!(
            c.get_error(),
            gl::NO_ERROR,
            "{}: error not cleared",
            row.name
        );
    }
}

#[test]
fn the_first_error_sticks() {
    let mut c = ctx();
    c.frustum(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    c.matrix_mode(0);
    c.pop_matrix();
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn a_zero_axis_rotation_is_no_error() {
    // GL defines no error for it; the matrix is left unchanged (see tests/matrices.rs).
    let mut c = ctx();
    c.rotated(90.0, 0.0, 0.0, 0.0);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn client_active_texture_is_not_allowed_between_begin_and_end() {
    // GL 2.1 §2.6.3 does not list it, and Mesa's llvmpipe raises INVALID_OPERATION there.
    let mut c = ctx();
    c.begin(gl::POINTS);
    c.client_active_texture(gl::TEXTURE3);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    let mut unit = [0];
    c.get_integerv(gl::CLIENT_ACTIVE_TEXTURE, &mut unit);
    assert_eq!(unit, [gl::TEXTURE0 as i32], "unchanged");
    c.client_active_texture(gl::TEXTURE3);
    c.get_integerv(gl::CLIENT_ACTIVE_TEXTURE, &mut unit);
    assert_eq!(unit, [(gl::TEXTURE0 + 3) as i32]);
}

/// `Context::reset` gives back exactly the initial state and a clear error flag, drops
/// vertices batched inside an open Begin/End, and keeps what the framebuffer holds.
#[test]
fn reset_restores_the_initial_state_and_keeps_the_framebuffer() {
    let fresh = Context::new(16, 16).expect("context");
    let mut c = Context::new(16, 16).expect("context");
    c.clear_color(0.0, 1.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.enable(gl::LIGHTING);
    c.translatef(1.0, 2.0, 3.0);
    c.push_matrix();
    c.enable(0xFFFF); // INVALID_ENUM, left unread
    c.begin(gl::TRIANGLES); // open, with a vertex that must never be drawn
    c.vertex2f(-1.0, -1.0);
    c.reset();
    assert_eq!(c.state(), fresh.state());
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.begin(gl::TRIANGLES); // no longer inside Begin/End: this Begin is legal
    c.vertex2f(1.0, -1.0);
    c.vertex2f(1.0, 1.0);
    c.end();
    assert_eq!(
        c.get_error(),
        gl::NO_ERROR,
        "a stale vertex would have completed a triangle"
    );
    let img = c.to_image();
    assert!(
        img.pixels().all(|p| p.0 == [0, 255, 0, 255]),
        "the cleared framebuffer is kept"
    );
}
