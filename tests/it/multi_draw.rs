//! MultiDrawArrays and MultiDrawElements (GL 1.4, GL 2.1 §2.8): the same pixels as the draws
//! they stand for, made one by one; the errors, in Mesa's order; display lists that keep the
//! array data of compile time; and the same pictures and errors on the driver.

use fixedgl::{gl, Call, Context, Pointer};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;
const OK: u32 = gl::NO_ERROR;
const SIZE: u32 = 64;

/// Twelve vertices, x y z r g b: four triangles, or strips of them.
#[rustfmt::skip]
const VERTS: [f32; 72] = [
    -0.9, -0.9, 0.0, 1.0, 0.0, 0.0,   -0.1, -0.8, 0.0, 0.0, 1.0, 0.0,   -0.5, -0.1, 0.0, 0.0, 0.0, 1.0,
     0.1, -0.9, 0.5, 1.0, 1.0, 0.0,    0.9, -0.7, 0.5, 0.0, 1.0, 1.0,    0.6,  0.0, 0.5, 1.0, 0.0, 1.0,
    -0.8,  0.1, 0.0, 0.5, 0.5, 0.5,   -0.2,  0.2, 0.0, 1.0, 0.5, 0.0,   -0.6,  0.9, 0.0, 0.0, 0.5, 1.0,
     0.2,  0.2, 0.0, 0.3, 0.9, 0.1,    0.8,  0.3, 0.0, 0.9, 0.1, 0.3,    0.4,  0.9, 0.0, 0.1, 0.3, 0.9,
];

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

fn arrays(c: &mut Context) {
    c.interleaved_arrays(gl::C3F_V3F, 0, &reordered());
}

/// VERTS as C3F_V3F wants them: colour first.
fn reordered() -> Vec<f32> {
    VERTS
        .chunks_exact(6)
        .flat_map(|v| [v[3], v[4], v[5], v[0], v[1], v[2]])
        .collect()
}

fn image(c: &mut Context) -> Vec<u8> {
    assert_eq!(c.get_error(), OK);
    let img = c.to_image().into_raw();
    let lit = img.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 200, "only {lit} pixels drawn");
    img
}

#[test]
fn multi_draw_arrays_draws_each_range_in_order() {
    let first = [0, 9, 4, 6];
    let count = [3, 3, 0, 4];
    let mut one_by_one = ctx();
    arrays(&mut one_by_one);
    for (&f, &n) in first.iter().zip(&count) {
        one_by_one.draw_arrays(gl::TRIANGLE_STRIP, f, n);
    }
    let mut multi = ctx();
    arrays(&mut multi);
    // Entries past drawcount are not read.
    multi.multi_draw_arrays(gl::TRIANGLE_STRIP, &[0, 9, 4, 6, -5], &[3, 3, 0, 4, -1], 4);
    assert_eq!(image(&mut multi), image(&mut one_by_one));
}

#[test]
fn multi_draw_elements_draws_each_index_list() {
    let lists: [&[u8]; 3] = [&[0, 1, 2, 9, 10, 11], &[], &[3, 4, 5, 8, 7, 6]];
    let mut one_by_one = ctx();
    arrays(&mut one_by_one);
    for l in lists {
        one_by_one.draw_elements(gl::TRIANGLES, l.len() as i32, gl::UNSIGNED_BYTE, l);
    }
    let expected = image(&mut one_by_one);
    let mut multi = ctx();
    arrays(&mut multi);
    let pointers: Vec<Pointer> = lists.iter().map(|l| Pointer::from(*l)).collect();
    multi.multi_draw_elements(gl::TRIANGLES, &[6, 0, 6], gl::UNSIGNED_BYTE, &pointers, 3);
    assert_eq!(image(&mut multi), expected);
    // The same indices from an element buffer, by offset.
    let mut buffered = ctx();
    arrays(&mut buffered);
    buffered.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, 1);
    let all: Vec<u16> = lists
        .iter()
        .flat_map(|l| l.iter().map(|&i| u16::from(i)))
        .collect();
    buffered.buffer_data(gl::ELEMENT_ARRAY_BUFFER, 24, &all, gl::STATIC_DRAW);
    buffered.multi_draw_elements(
        gl::TRIANGLES,
        &[6, 0, 6],
        gl::UNSIGNED_SHORT,
        &[Pointer::Offset(0), Pointer::Offset(12), Pointer::Offset(12)],
        3,
    );
    assert_eq!(image(&mut buffered), expected);
}

type Row = (&'static str, fn(&mut Context), u32);

#[rustfmt::skip]
const ROWS: &[Row] = &[
    ("arrays: drawcount < 0 before mode", |c| c.multi_draw_arrays(0x55, &[0], &[3], -1), IV),
    ("arrays: mode", |c| c.multi_draw_arrays(0x55, &[0], &[3], 1), IE),
    ("arrays: count < 0", |c| c.multi_draw_arrays(gl::TRIANGLES, &[0, 1], &[3, -1], 2), IV),
    ("arrays: short slices", |c| c.multi_draw_arrays(gl::TRIANGLES, &[0], &[3, 3], 2), IV),
    ("arrays: drawcount 0", |c| c.multi_draw_arrays(gl::TRIANGLES, &[], &[], 0), OK),
    ("arrays: past the data", |c| c.multi_draw_arrays(gl::TRIANGLES, &[0, 10], &[3, 3], 2), IO),
    ("arrays: negative first, count 0", |c| c.multi_draw_arrays(gl::TRIANGLES, &[-1], &[0], 1), OK),
    ("arrays: negative first", |c| c.multi_draw_arrays(gl::TRIANGLES, &[-1], &[3], 1), IO),
    ("arrays: in Begin/End", |c| { c.begin(gl::POINTS); c.multi_draw_arrays(gl::TRIANGLES, &[0], &[3], 1); c.end() }, IO),
    ("elements: drawcount < 0 before mode", |c| c.multi_draw_elements(0x55, &[3], gl::FLOAT, &[Pointer::NULL], -1), IV),
    ("elements: mode before type", |c| c.multi_draw_elements(0x55, &[3], gl::FLOAT, &[Pointer::NULL], 1), IE),
    ("elements: type before count", |c| c.multi_draw_elements(gl::TRIANGLES, &[-3], gl::FLOAT, &[Pointer::NULL], 1), IE),
    ("elements: count < 0", |c| c.multi_draw_elements(gl::TRIANGLES, &[3, -3], gl::UNSIGNED_BYTE, &[(&[0u8, 1, 2]).into(), Pointer::NULL], 2), IV),
    ("elements: short indices", |c| c.multi_draw_elements(gl::TRIANGLES, &[3, 3], gl::UNSIGNED_BYTE, &[(&[0u8, 1, 2]).into()], 2), IV),
    ("elements: index past the data", |c| c.multi_draw_elements(gl::TRIANGLES, &[3, 3], gl::UNSIGNED_BYTE, &[(&[0u8, 1, 2]).into(), (&[0u8, 1, 12]).into()], 2), IO),
    ("elements: index data too short", |c| c.multi_draw_elements(gl::TRIANGLES, &[3], gl::UNSIGNED_SHORT, &[(&[0u8, 1, 2]).into()], 1), IO),
    ("elements: in Begin/End", |c| { c.begin(gl::POINTS); c.multi_draw_elements(gl::TRIANGLES, &[3], gl::UNSIGNED_BYTE, &[(&[0u8, 1, 2]).into()], 1); c.end() }, IO),
    ("elements: two good draws", |c| c.multi_draw_elements(gl::TRIANGLES, &[3, 3], gl::UNSIGNED_BYTE, &[(&[0u8, 1, 2]).into(), (&[3u8, 4, 5]).into()], 2), OK),
];

#[test]
fn every_error_row_sets_its_error_and_draws_nothing() {
    for &(name, call, error) in ROWS {
        let mut c = ctx();
        arrays(&mut c);
        let before = c.state().clone();
        call(&mut c);
        assert_eq!(c.get_error(), error, "{name}");
        if error != OK {
            assert!(c.state() == &before, "{name}: state changed");
            assert!(
                c.to_image().pixels().all(|p| p.0 == [0, 0, 0, 0]),
                "{name}: drew"
            );
        }
    }
}

/// A list compiled with MultiDrawArrays keeps the vertices of compile time (GL 2.1 §5.4), as
/// piglit's gl-1.4-dlist-multidrawarrays checks; an erroneous one raises its error when run.
fn list_program(c: &mut Context) {
    arrays(c);
    let list = c.gen_lists(2);
    c.new_list(list, gl::COMPILE);
    c.multi_draw_arrays(gl::TRIANGLES, &[0, 6], &[3, 6], 2);
    c.end_list();
    c.new_list(list + 1, gl::COMPILE);
    c.multi_draw_arrays(gl::TRIANGLES, &[0], &[-3], 1);
    c.end_list();
    assert_eq!(c.get_error(), OK);
    // Other vertices now: the list still draws the old ones.
    c.vertex_pointer(3, gl::FLOAT, 0, &[0.0f32; 36]);
    c.call_list(list);
    assert_eq!(c.get_error(), OK);
    c.call_list(list + 1);
}

#[test]
fn lists_keep_the_data_of_compile_time() {
    let mut c = ctx();
    list_program(&mut c);
    assert_eq!(c.get_error(), IV);
    let mut direct = ctx();
    arrays(&mut direct);
    direct.draw_arrays(gl::TRIANGLES, 0, 3);
    direct.draw_arrays(gl::TRIANGLES, 6, 6);
    assert_eq!(image(&mut c), image(&mut direct));
}

#[test]
fn recorded_calls_round_trip_the_text_format() {
    let call = Call::MultiDrawElements(Box::new((
        gl::TRIANGLES,
        vec![3, 0],
        gl::UNSIGNED_SHORT,
        vec![Pointer::Data(vec![0, 0, 1, 0, 2, 0]), Pointer::Offset(8)],
        2,
    )));
    let mut text = Vec::new();
    if let Err(e) = fixedgl::recording::write_recording(std::slice::from_ref(&call), &mut text) {
        panic!("{e}");
    }
    match fixedgl::recording::read_recording(&text[..]) {
        Ok(calls) => assert_eq!(calls, vec![call]),
        Err(e) => panic!("{e}"),
    }
}

#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;

    fn same_on_the_driver(program: fn(&mut Context)) -> (u32, u32) {
        let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
            return (OK, OK);
        };
        let mut c = ctx();
        c.start_recording();
        program(&mut c);
        let calls = c.stop_recording();
        gl.replay(&calls);
        let errors = (c.get_error(), gl.get_error());
        let cmp = compare(&c.to_image(), &gl.read_image(), 1);
        assert_eq!(cmp.differing_pixels, 0, "max {:?}", cmp.max_diff);
        errors
    }

    #[test]
    fn multi_draws_match_the_driver() {
        let (cpu, gl) = same_on_the_driver(|c| {
            arrays(c);
            c.multi_draw_arrays(gl::TRIANGLE_STRIP, &[0, 9, 4, 6], &[3, 3, 0, 4], 4);
            c.translatef(0.05, 0.05, 0.0);
            c.multi_draw_elements(
                gl::LINE_LOOP,
                &[6, 0, 6],
                gl::UNSIGNED_BYTE,
                &[
                    (&[0u8, 1, 2, 9, 10, 11]).into(),
                    Pointer::NULL,
                    (&[3u8, 4, 5, 8, 7, 6]).into(),
                ],
                3,
            );
        });
        assert_eq!((cpu, gl), (OK, OK));
        let (cpu, gl) = same_on_the_driver(list_program);
        assert_eq!((cpu, gl), (IV, IV));
    }

    #[test]
    fn rows_agree_with_the_driver() {
        for &(name, call, error) in ROWS {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            c.start_recording();
            arrays(&mut c);
            call(&mut c);
            let calls = c.stop_recording();
            gl.replay(&calls);
            assert_eq!(gl.get_error(), error, "{name}");
        }
    }
}
