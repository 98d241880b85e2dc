//! Occlusion queries (GL 1.5, GL 2.1 §4.1.7, §6.1.12): the count of fragments that pass the
//! depth test (and the tests before it) equals llvmpipe's for every kind of primitive and test;
//! counting changes no pixel; the errors, names, IsQuery, display-list behaviour and the queries
//! of query state agree with GL 2.1 and the driver.

use fixedgl::{gl, Context};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;
const OK: u32 = gl::NO_ERROR;
const SIZE: u32 = 96;
/// GL 3.3's targets, which GL 2.1 does not have (a 4.5 driver takes them).
const ANY_SAMPLES_PASSED: u32 = 0x8C2F;
const TIME_ELAPSED: u32 = 0x88BF;

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

fn result(c: &mut Context, id: u32) -> u32 {
    let mut v = [u32::MAX - 1];
    c.get_query_objectuiv(id, gl::QUERY_RESULT, &mut v);
    assert_eq!(c.get_error(), OK, "result of {id}");
    v[0]
}

fn quad(c: &mut Context, x0: f32, y0: f32, x1: f32, y1: f32, z: f32) {
    c.begin(gl::QUADS);
    c.vertex3f(x0, y0, z);
    c.vertex3f(x1, y0, z);
    c.vertex3f(x1, y1, z);
    c.vertex3f(x0, y1, z);
    c.end();
}

/// Queries 1 to 9, each around one kind of drawing; the counts are compared with llvmpipe's.
fn counted_program(c: &mut Context) {
    c.clear_color(0.1, 0.1, 0.1, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    c.enable(gl::DEPTH_TEST);
    // 1: a quad on an empty depth buffer.
    c.begin_query(gl::SAMPLES_PASSED, 1);
    c.color3f(1.0, 0.0, 0.0);
    quad(c, -0.6, -0.6, 0.3, 0.4, 0.0);
    c.end_query(gl::SAMPLES_PASSED);
    // 2: a quad half behind it.
    c.begin_query(gl::SAMPLES_PASSED, 2);
    c.color3f(0.0, 1.0, 0.0);
    quad(c, -0.1, -0.9, 0.9, 0.2, 0.5);
    c.end_query(gl::SAMPLES_PASSED);
    // 3: entirely behind: nothing passes.
    c.begin_query(gl::SAMPLES_PASSED, 3);
    quad(c, -0.5, -0.5, 0.2, 0.3, 0.9);
    c.end_query(gl::SAMPLES_PASSED);
    // 4: wide lines and big points, colour and depth writes off (they still count).
    c.color_mask(false, false, false, false);
    c.depth_mask(false);
    c.begin_query(gl::SAMPLES_PASSED, 4);
    c.line_width(3.0);
    c.begin(gl::LINE_STRIP);
    c.vertex3f(-0.95, 0.9, -0.5);
    c.vertex3f(0.8, 0.5, -0.5);
    c.vertex3f(-0.2, -0.95, 0.8);
    c.end();
    c.point_size(5.0);
    c.begin(gl::POINTS);
    for k in 0..7 {
        c.vertex3f(-0.9 + 0.27 * k as f32, 0.7 - 0.2 * k as f32, -0.2);
    }
    c.end();
    c.end_query(gl::SAMPLES_PASSED);
    c.color_mask(true, true, true, true);
    c.depth_mask(true);
    // 5: alpha test and scissor remove fragments before the count.
    c.enable(gl::ALPHA_TEST);
    c.alpha_func(gl::GREATER, 0.5);
    c.enable(gl::SCISSOR_TEST);
    c.scissor(10, 5, 60, 70);
    c.begin_query(gl::SAMPLES_PASSED, 5);
    c.begin(gl::TRIANGLES);
    c.color4f(1.0, 1.0, 0.0, 0.0);
    c.vertex3f(-1.0, -1.0, -0.9);
    c.color4f(1.0, 1.0, 0.0, 1.0);
    c.vertex3f(1.0, -1.0, -0.9);
    c.vertex3f(0.0, 1.0, -0.9);
    c.end();
    c.end_query(gl::SAMPLES_PASSED);
    c.disable(gl::ALPHA_TEST);
    c.disable(gl::SCISSOR_TEST);
    // 6: the stencil test: only where a first pass wrote 1.
    c.enable(gl::STENCIL_TEST);
    c.stencil_func(gl::ALWAYS, 1, 0xff);
    c.stencil_op(gl::KEEP, gl::KEEP, gl::REPLACE);
    c.disable(gl::DEPTH_TEST);
    c.color3f(0.0, 0.0, 1.0);
    quad(c, -0.3, -0.3, 0.5, 0.5, 0.0);
    c.stencil_func(gl::EQUAL, 1, 0xff);
    c.begin_query(gl::SAMPLES_PASSED, 6);
    c.color3f(1.0, 0.0, 1.0);
    quad(c, 0.0, -0.8, 0.9, 0.9, 0.0);
    c.end_query(gl::SAMPLES_PASSED);
    c.disable(gl::STENCIL_TEST);
    // 7: blending and no depth test: every covered pixel, a large batch of triangles.
    c.enable(gl::BLEND);
    c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
    c.begin_query(gl::SAMPLES_PASSED, 7);
    c.color4f(1.0, 1.0, 1.0, 0.3);
    c.begin(gl::TRIANGLES);
    for k in 0..12000 {
        let x = -1.0 + (k % 100) as f32 * 0.02;
        let y = -1.0 + (k / 100) as f32 * 0.016;
        c.vertex2f(x, y);
        c.vertex2f(x + 0.03, y);
        c.vertex2f(x, y + 0.03);
    }
    c.end();
    c.end_query(gl::SAMPLES_PASSED);
    c.disable(gl::BLEND);
    // 8: nothing drawn.
    c.begin_query(gl::SAMPLES_PASSED, 8);
    c.end_query(gl::SAMPLES_PASSED);
    // 9: GREATER depth test, with polygon mode LINE.
    c.enable(gl::DEPTH_TEST);
    c.depth_func(gl::GREATER);
    c.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    c.begin_query(gl::SAMPLES_PASSED, 9);
    quad(c, -0.9, -0.9, 0.9, 0.9, 0.95);
    c.end_query(gl::SAMPLES_PASSED);
}

#[test]
fn counts_are_the_fragments_that_pass() {
    let mut c = ctx();
    counted_program(&mut c);
    assert_eq!(c.get_error(), OK);
    let counts: Vec<u32> = (1..=9).map(|id| result(&mut c, id)).collect();
    // Exact values by construction where they are easy to see: nothing behind the first quad
    // passes, an empty query counts nothing, and the first quad is its pixel count.
    assert_eq!(counts[2], 0);
    assert_eq!(counts[7], 0);
    assert!(counts[0] > 1500 && counts[1] > 500, "{counts:?}");
    // The blended triangles overlap: more fragments than pixels.
    assert!(counts[6] > SIZE * SIZE, "{counts:?}");
    // The first quad: the pixels whose centres it covers, 0.9 x 1.0 of a 96-pixel NDC square.
    let mut alone = ctx();
    alone.begin_query(gl::SAMPLES_PASSED, 1);
    quad(&mut alone, -0.6, -0.6, 0.3, 0.4, 0.0);
    alone.end_query(gl::SAMPLES_PASSED);
    assert_eq!(result(&mut alone, 1), 43 * 48);
}

#[test]
fn counting_changes_no_pixel() {
    let mut with = ctx();
    counted_program(&mut with);
    let mut without = ctx();
    without.start_recording();
    counted_program(&mut without);
    let calls = without.stop_recording();
    let plain: Vec<_> = calls
        .into_iter()
        .filter(|c| {
            !matches!(
                c,
                fixedgl::Call::BeginQuery(..) | fixedgl::Call::EndQuery(_)
            )
        })
        .collect();
    let mut replayed = ctx();
    replayed.replay(&plain);
    assert_eq!(with.to_image(), replayed.to_image());
}

#[test]
fn names_objects_and_state() {
    let mut c = ctx();
    let mut ids = [0; 3];
    c.gen_queries(3, &mut ids);
    assert_eq!(ids, [1, 2, 3]);
    // Generated names are not query objects until BeginQuery uses them.
    assert!(!c.is_query(1));
    let mut v = [-1];
    c.get_queryiv(gl::SAMPLES_PASSED, gl::QUERY_COUNTER_BITS, &mut v);
    assert_eq!(v, [64]);
    c.get_queryiv(gl::SAMPLES_PASSED, gl::CURRENT_QUERY, &mut v);
    assert_eq!(v, [0]);
    // Any name becomes a query at BeginQuery (compatibility profile, as Mesa).
    c.begin_query(gl::SAMPLES_PASSED, 1000);
    c.get_queryiv(gl::SAMPLES_PASSED, gl::CURRENT_QUERY, &mut v);
    assert_eq!(v, [1000]);
    assert!(c.is_query(1000));
    c.end_query(gl::SAMPLES_PASSED);
    let mut avail = [7];
    c.get_query_objectiv(1000, gl::QUERY_RESULT_AVAILABLE, &mut avail);
    assert_eq!(avail, [1]);
    // Names continue after the largest used, as Mesa's.
    c.gen_queries(2, &mut ids);
    assert_eq!(ids[..2], [1001, 1002]);
    // Deleting the active query ends it.
    c.begin_query(gl::SAMPLES_PASSED, 5);
    c.delete_queries(1, &[5]);
    c.get_queryiv(gl::SAMPLES_PASSED, gl::CURRENT_QUERY, &mut v);
    assert_eq!(v, [0]);
    assert!(!c.is_query(5));
    c.end_query(gl::SAMPLES_PASSED);
    assert_eq!(c.get_error(), IO);
    // Begin and End compile into lists; GenQueries and DeleteQueries run at once.
    let list = c.gen_lists(1);
    c.new_list(list, gl::COMPILE);
    c.begin_query(gl::SAMPLES_PASSED, 9);
    c.gen_queries(1, &mut ids);
    c.end_query(gl::SAMPLES_PASSED);
    c.end_list();
    assert_eq!(ids[0], 1003);
    assert!(!c.is_query(9));
    c.call_list(list);
    assert!(c.is_query(9));
    assert_eq!(c.get_error(), OK);
}

type Row = (&'static str, fn(&mut Context), u32);

fn active(c: &mut Context) {
    c.begin_query(gl::SAMPLES_PASSED, 4);
}

#[rustfmt::skip]
const ROWS: &[Row] = &[
    ("gen: n < 0", |c| c.gen_queries(-1, &mut [0; 2]), IV),
    ("gen: in Begin/End", |c| { c.begin(gl::POINTS); c.gen_queries(1, &mut [0]); c.end() }, IO),
    ("delete: n < 0", |c| c.delete_queries(-1, &[1]), IV),
    ("delete: in Begin/End", |c| { c.begin(gl::POINTS); c.delete_queries(1, &[1]); c.end() }, IO),
    ("delete: unused and 0", |c| c.delete_queries(2, &[0, 77]), OK),
    ("begin: target", |c| c.begin_query(ANY_SAMPLES_PASSED, 1), IE),
    ("begin: target before id 0", |c| c.begin_query(0x1234, 0), IE),
    ("begin: id 0", |c| c.begin_query(gl::SAMPLES_PASSED, 0), IO),
    ("begin: twice", |c| { active(c); c.begin_query(gl::SAMPLES_PASSED, 5) }, IO),
    ("begin: the active one again", |c| { active(c); c.begin_query(gl::SAMPLES_PASSED, 4) }, IO),
    ("begin: in Begin/End", |c| { c.begin(gl::POINTS); c.begin_query(gl::SAMPLES_PASSED, 1); c.end() }, IO),
    ("end: target", |c| { active(c); c.end_query(TIME_ELAPSED) }, IE),
    ("end: none active", |c| c.end_query(gl::SAMPLES_PASSED), IO),
    ("end: in Begin/End", |c| { active(c); c.begin(gl::POINTS); c.end_query(gl::SAMPLES_PASSED); c.end() }, IO),
    ("get: target", |c| c.get_queryiv(ANY_SAMPLES_PASSED, gl::CURRENT_QUERY, &mut [0]), IE),
    ("get: pname", |c| c.get_queryiv(gl::SAMPLES_PASSED, gl::QUERY_RESULT, &mut [0]), IE),
    ("get: in Begin/End", |c| { c.begin(gl::POINTS); c.get_queryiv(gl::SAMPLES_PASSED, gl::CURRENT_QUERY, &mut [0]); c.end() }, IO),
    ("object: 0", |c| c.get_query_objectiv(0, gl::QUERY_RESULT, &mut [0]), IO),
    ("object: unknown", |c| c.get_query_objectiv(55, gl::QUERY_RESULT, &mut [0]), IO),
    ("object: generated, never begun", |c| { c.gen_queries(1, &mut [0]); c.get_query_objectiv(1, gl::QUERY_RESULT, &mut [0]) }, IO),
    ("object: active", |c| { active(c); c.get_query_objectuiv(4, gl::QUERY_RESULT_AVAILABLE, &mut [0]) }, IO),
    ("object: active before pname", |c| { active(c); c.get_query_objectiv(4, 0x1234, &mut [0]) }, IO),
    ("object: pname", |c| { active(c); c.end_query(gl::SAMPLES_PASSED); c.get_query_objectiv(4, 0x1234, &mut [0]) }, IE),
    ("object: in Begin/End", |c| { active(c); c.end_query(gl::SAMPLES_PASSED); c.begin(gl::POINTS); c.get_query_objectiv(4, gl::QUERY_RESULT, &mut [0]); c.end() }, IO),
];

#[test]
fn every_error_row() {
    for &(name, call, error) in ROWS {
        let mut c = ctx();
        call(&mut c);
        assert_eq!(c.get_error(), error, "{name}");
    }
}

#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;
    use fixedgl::glbackend::GlBackend;

    fn driver_result(gl: &GlBackend, id: u32) -> u32 {
        let mut v = u32::MAX - 1;
        // SAFETY: QUERY_RESULT writes one GLuint; this thread's backend is current.
        unsafe { gl.raw().GetQueryObjectuiv(id, gl::QUERY_RESULT, &mut v) };
        v
    }

    #[test]
    fn counts_match_llvmpipe() {
        let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
            return;
        };
        let mut c = ctx();
        c.start_recording();
        counted_program(&mut c);
        let calls = c.stop_recording();
        gl.replay(&calls);
        assert_eq!(gl.get_error(), OK);
        let cpu: Vec<u32> = (1..=9).map(|id| result(&mut c, id)).collect();
        let driver: Vec<u32> = (1..=9).map(|id| driver_result(&gl, id)).collect();
        assert_eq!(cpu, driver);
        // (Query 7's thirty-odd layers of blending differ by up to 2/255 in places: the
        // blending arithmetic's own residue, not the counting's.)
        let cmp = compare(&c.to_image(), &gl.read_image(), 2);
        assert_eq!(cmp.differing_pixels, 0, "max {:?}", cmp.max_diff);
    }

    /// The recorded rows on the driver; the query-only calls (GetQuery*, not recorded) are made
    /// on it directly after the recorded setup.
    #[test]
    fn rows_agree_with_the_driver() {
        for &(name, call, error) in ROWS {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            c.start_recording();
            call(&mut c);
            let calls = c.stop_recording();
            gl.replay(&calls);
            if name.starts_with("get") || name.starts_with("object") {
                let mut v = 0i32;
                let mut u = 0u32;
                // SAFETY: each query writes one integer into `v` or `u`.
                unsafe {
                    let raw = gl.raw();
                    let inside = name.ends_with("in Begin/End");
                    if inside {
                        raw.Begin(gl::POINTS);
                    }
                    match name {
                        "get: target" => {
                            raw.GetQueryiv(ANY_SAMPLES_PASSED, gl::CURRENT_QUERY, &mut v)
                        }
                        "get: pname" => {
                            raw.GetQueryiv(gl::SAMPLES_PASSED, gl::QUERY_RESULT, &mut v)
                        }
                        "get: in Begin/End" => {
                            raw.GetQueryiv(gl::SAMPLES_PASSED, gl::CURRENT_QUERY, &mut v)
                        }
                        "object: 0" => raw.GetQueryObjectiv(0, gl::QUERY_RESULT, &mut v),
                        "object: unknown" => raw.GetQueryObjectiv(55, gl::QUERY_RESULT, &mut v),
                        "object: generated, never begun" => {
                            raw.GetQueryObjectiv(1, gl::QUERY_RESULT, &mut v)
                        }
                        "object: active" => {
                            raw.GetQueryObjectuiv(4, gl::QUERY_RESULT_AVAILABLE, &mut u)
                        }
                        "object: active before pname" | "object: pname" => {
                            raw.GetQueryObjectiv(4, 0x1234, &mut v)
                        }
                        _ => raw.GetQueryObjectiv(4, gl::QUERY_RESULT, &mut v),
                    }
                    if inside {
                        raw.End();
                    }
                }
            }
            // GL 2.1 has only SAMPLES_PASSED: GetQueryiv(ANY_SAMPLES_PASSED) is the driver's
            // own business (a 4.5 context answers it); the recorded calls agree.
            let expected = if name == "get: target" { OK } else { error };
            assert_eq!(gl.get_error(), expected, "{name} on the driver");
        }
    }
}
