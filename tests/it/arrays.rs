//! Vertex arrays and buffer objects (GL 2.1 §2.8, §2.9): every way of drawing from arrays gives
//! exactly the pixels of the same vertices drawn with Begin/Vertex/End (§2.8 defines the draws
//! by ArrayElement, which is defined by the immediate-mode commands), the error table leaves the
//! State unchanged, queries report the state tables' values, and a recording replays to the same
//! image.

use fixedgl::{gl, Call, Context, Pointer};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;

/// Four triangles in normalised device coordinates (identity matrices): x, y, z, then r, g, b, a.
#[rustfmt::skip]
const TRIS: [[f32; 7]; 12] = [
    [-0.9, -0.9, 0.0,  1.0, 0.0, 0.0, 1.0],
    [-0.1, -0.8, 0.0,  0.0, 1.0, 0.0, 1.0],
    [-0.5, -0.1, 0.0,  0.0, 0.0, 1.0, 1.0],
    [ 0.1, -0.9, 0.5,  1.0, 1.0, 0.0, 1.0],
    [ 0.9, -0.7, 0.5,  0.0, 1.0, 1.0, 1.0],
    [ 0.6,  0.0, 0.5,  1.0, 0.0, 1.0, 1.0],
    [-0.8,  0.1, 0.0,  0.5, 0.5, 0.5, 1.0],
    [-0.2,  0.2, 0.0,  1.0, 0.5, 0.0, 1.0],
    [-0.6,  0.9, 0.0,  0.0, 0.5, 1.0, 1.0],
    [ 0.2,  0.2, 0.0,  0.3, 0.9, 0.1, 1.0],
    [ 0.8,  0.3, 0.0,  0.9, 0.1, 0.3, 1.0],
    [ 0.4,  0.9, 0.0,  0.1, 0.3, 0.9, 1.0],
];

const SIZE: u32 = 64;

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// The reference: the vertices `order` picks from TRIS, drawn with Begin/Color4f/Vertex3f/End.
fn reference(mode: u32, order: &[usize]) -> Vec<u8> {
    let mut c = ctx();
    c.begin(mode);
    for &i in order {
        let v = TRIS[i];
        c.color4f(v[3], v[4], v[5], v[6]);
        c.vertex3f(v[0], v[1], v[2]);
    }
    c.end();
    let img = c.to_image().into_raw();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    // A reference that draws next to nothing would make every comparison pass.
    let lit = img.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 300, "reference draws only {lit} pixels");
    img
}

fn image(c: &mut Context) -> Vec<u8> {
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.to_image().into_raw()
}

fn flat() -> Vec<f32> {
    TRIS.iter().flatten().copied().collect()
}

/// Interleaved client arrays: position at byte 0, colour at byte 12, stride 28.
fn client_interleaved(c: &mut Context) {
    let data = flat();
    c.vertex_pointer(3, gl::FLOAT, 28, &data);
    c.color_pointer(4, gl::FLOAT, 28, &data[3..]);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.enable_client_state(gl::COLOR_ARRAY);
}

#[test]
fn draw_arrays_matches_begin_end() {
    let all: Vec<usize> = (0..12).collect();
    let mut c = ctx();
    client_interleaved(&mut c);
    c.draw_arrays(gl::TRIANGLES, 0, 12);
    assert_eq!(image(&mut c), reference(gl::TRIANGLES, &all));
    // A sub-range, and separate tightly packed arrays.
    let pos: Vec<f32> = TRIS.iter().flat_map(|v| v[..3].to_vec()).collect();
    let col: Vec<f32> = TRIS.iter().flat_map(|v| v[3..].to_vec()).collect();
    let mut c = ctx();
    c.vertex_pointer(3, gl::FLOAT, 0, &pos);
    c.color_pointer(4, gl::FLOAT, 0, &col);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.enable_client_state(gl::COLOR_ARRAY);
    c.draw_arrays(gl::TRIANGLE_STRIP, 3, 6);
    assert_eq!(
        image(&mut c),
        reference(gl::TRIANGLE_STRIP, &[3, 4, 5, 6, 7, 8])
    );
}

#[test]
fn draw_elements_matches_begin_end_for_each_index_type() {
    let order = [11usize, 10, 9, 0, 1, 2, 8, 7, 6, 5, 4, 3, 0, 2, 4];
    let expected = reference(gl::TRIANGLES, &order);
    let bytes: Vec<u8> = order.iter().map(|&i| i as u8).collect();
    let shorts: Vec<u16> = order.iter().map(|&i| i as u16).collect();
    let ints: Vec<u32> = order.iter().map(|&i| i as u32).collect();
    let draws: [(u32, Pointer); 3] = [
        (gl::UNSIGNED_BYTE, (&bytes).into()),
        (gl::UNSIGNED_SHORT, (&shorts).into()),
        (gl::UNSIGNED_INT, (&ints).into()),
    ];
    for (ty, p) in draws {
        let mut c = ctx();
        client_interleaved(&mut c);
        c.draw_elements(gl::TRIANGLES, 15, ty, p);
        assert_eq!(image(&mut c), expected, "type {ty:#x}");
    }
    let mut c = ctx();
    client_interleaved(&mut c);
    c.draw_range_elements(gl::TRIANGLES, 0, 11, 15, gl::UNSIGNED_INT, &ints);
    assert_eq!(image(&mut c), expected, "DrawRangeElements");
}

#[test]
fn array_element_inside_begin_end_matches() {
    let order = [0usize, 1, 2, 6, 7, 8];
    let mut c = ctx();
    client_interleaved(&mut c);
    c.begin(gl::TRIANGLES);
    for &i in &order {
        c.array_element(i as i32);
    }
    c.end();
    assert_eq!(image(&mut c), reference(gl::TRIANGLES, &order));
    // Outside Begin/End it sets the current attributes only: colour of element 4.
    c.array_element(4);
    let mut col = [0.0f32; 4];
    c.get_floatv(gl::CURRENT_COLOR, &mut col);
    assert_eq!(col, [0.0, 1.0, 1.0, 1.0]);
}

#[test]
fn interleaved_arrays_match_begin_end() {
    // C4F_N3F_V3F: colour 4 floats, normal 3, vertex 3 (table 2.5), stride 0 = 40 bytes.
    let mut data = Vec::new();
    for v in &TRIS {
        data.extend_from_slice(&v[3..7]);
        data.extend_from_slice(&[0.0, 0.0, 1.0]);
        data.extend_from_slice(&v[..3]);
    }
    let mut c = ctx();
    c.interleaved_arrays(gl::C4F_N3F_V3F, 0, &data);
    c.draw_arrays(gl::TRIANGLES, 0, 12);
    let all: Vec<usize> = (0..12).collect();
    assert_eq!(image(&mut c), reference(gl::TRIANGLES, &all));
    // C4UB_V3F: four colour bytes (one float's room), then the vertex; 16 bytes a vertex.
    let mut bytes = Vec::new();
    for v in &TRIS {
        bytes.extend(v[3..7].iter().map(|&x| (x * 255.0).round() as u8));
        for x in &v[..3] {
            bytes.extend_from_slice(&x.to_ne_bytes());
        }
    }
    let mut c = ctx();
    c.interleaved_arrays(gl::C4UB_V3F, 0, &bytes);
    c.draw_arrays(gl::TRIANGLES, 0, 12);
    let mut r = ctx();
    r.begin(gl::TRIANGLES);
    for v in &TRIS {
        let ub = v[3..7]
            .iter()
            .map(|&x| (x * 255.0).round() as u8)
            .collect::<Vec<_>>();
        r.color4ub(ub[0], ub[1], ub[2], ub[3]);
        r.vertex3f(v[0], v[1], v[2]);
    }
    r.end();
    assert_eq!(image(&mut c), image(&mut r));
}

/// GL 2.1 table 2.5 by hand: (format, texture size, colour size and type, normal, vertex size,
/// stride in bytes; c = 4 bytes for 4 ubytes, f = 4 bytes).
#[test]
fn interleaved_formats_set_table_2_5() {
    const UB: u32 = gl::UNSIGNED_BYTE;
    const F: u32 = gl::FLOAT;
    type Row = (u32, i32, Option<(i32, u32)>, bool, i32, i32);
    let rows: [Row; 14] = [
        (gl::V2F, 0, None, false, 2, 8),
        (gl::V3F, 0, None, false, 3, 12),
        (gl::C4UB_V2F, 0, Some((4, UB)), false, 2, 12),
        (gl::C4UB_V3F, 0, Some((4, UB)), false, 3, 16),
        (gl::C3F_V3F, 0, Some((3, F)), false, 3, 24),
        (gl::N3F_V3F, 0, None, true, 3, 24),
        (gl::C4F_N3F_V3F, 0, Some((4, F)), true, 3, 40),
        (gl::T2F_V3F, 2, None, false, 3, 20),
        (gl::T4F_V4F, 4, None, false, 4, 32),
        (gl::T2F_C4UB_V3F, 2, Some((4, UB)), false, 3, 24),
        (gl::T2F_C3F_V3F, 2, Some((3, F)), false, 3, 32),
        (gl::T2F_N3F_V3F, 2, None, true, 3, 32),
        (gl::T2F_C4F_N3F_V3F, 2, Some((4, F)), true, 3, 48),
        (gl::T4F_C4F_N3F_V4F, 4, Some((4, F)), true, 4, 60),
    ];
    for (format, t, col, n, v, stride) in rows {
        let mut c = ctx();
        c.enable_client_state(gl::EDGE_FLAG_ARRAY);
        c.enable_client_state(gl::FOG_COORD_ARRAY);
        c.interleaved_arrays(format, 0, &[0u8; 256]);
        assert_eq!(c.get_error(), gl::NO_ERROR);
        let geti = |c: &mut Context, p: u32| {
            let mut v = [-7];
            c.get_integerv(p, &mut v);
            v[0]
        };
        assert!(c.is_enabled(gl::VERTEX_ARRAY));
        assert_eq!(geti(&mut c, gl::VERTEX_ARRAY_SIZE), v, "{format:#x}");
        assert_eq!(geti(&mut c, gl::VERTEX_ARRAY_STRIDE), stride, "{format:#x}");
        assert_eq!(c.is_enabled(gl::TEXTURE_COORD_ARRAY), t > 0, "{format:#x}");
        if t > 0 {
            assert_eq!(geti(&mut c, gl::TEXTURE_COORD_ARRAY_SIZE), t);
        }
        assert_eq!(c.is_enabled(gl::COLOR_ARRAY), col.is_some(), "{format:#x}");
        if let Some((size, ty)) = col {
            assert_eq!(geti(&mut c, gl::COLOR_ARRAY_SIZE), size);
            assert_eq!(geti(&mut c, gl::COLOR_ARRAY_TYPE), ty as i32);
            assert_eq!(geti(&mut c, gl::COLOR_ARRAY_STRIDE), stride);
        }
        assert_eq!(c.is_enabled(gl::NORMAL_ARRAY), n, "{format:#x}");
        assert!(!c.is_enabled(gl::EDGE_FLAG_ARRAY));
        assert!(!c.is_enabled(gl::FOG_COORD_ARRAY));
    }
}

#[test]
fn buffer_objects_with_offsets_match_begin_end() {
    // Four padding bytes first, so that the offsets are not 0.
    let mut data: Vec<u8> = vec![0xAB; 4];
    for v in &TRIS {
        for x in v {
            data.extend_from_slice(&x.to_ne_bytes());
        }
    }
    let order = [0u16, 1, 2, 9, 10, 11, 3, 4, 5];
    let mut c = ctx();
    let mut names = [0; 2];
    c.gen_buffers(2, &mut names);
    assert_eq!(names, [1, 2]);
    c.bind_buffer(gl::ARRAY_BUFFER, names[0]);
    c.buffer_data(
        gl::ARRAY_BUFFER,
        data.len() as isize,
        &data,
        gl::STATIC_DRAW,
    );
    c.vertex_pointer(3, gl::FLOAT, 28, 4usize);
    c.color_pointer(4, gl::FLOAT, 28, 16usize);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.enable_client_state(gl::COLOR_ARRAY);
    c.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, names[1]);
    // Two junk indices, then the real ones at byte offset 4.
    let mut idx = vec![0xFFFFu16, 0xFFFF];
    idx.extend_from_slice(&order);
    c.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        (idx.len() * 2) as isize,
        &idx,
        gl::STATIC_DRAW,
    );
    c.draw_elements(gl::TRIANGLES, 9, gl::UNSIGNED_SHORT, 4usize);
    let expected = reference(gl::TRIANGLES, &order.map(usize::from));
    assert_eq!(image(&mut c), expected);
    // BufferSubData replaces a vertex: the first triangle's third corner moves.
    let moved = [0.9f32, 0.9, 0.0];
    c.buffer_sub_data(gl::ARRAY_BUFFER, 4 + 2 * 28, 12, &moved);
    let mut back = [0u8; 12];
    c.get_buffer_sub_data(gl::ARRAY_BUFFER, 4 + 2 * 28, 12, &mut back);
    let want: Vec<u8> = moved.iter().flat_map(|x| x.to_ne_bytes()).collect();
    assert_eq!(back.to_vec(), want);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn integer_arrays_convert_as_immediate_mode() {
    // SHORT positions in a 64x64 ortho space, UNSIGNED_BYTE colours (normalised), BYTE normals.
    let pos: [i16; 8] = [4, 4, 60, 8, 8, 60, 58, 56];
    let col: [u8; 16] = [
        255, 0, 0, 255, 0, 200, 0, 255, 10, 20, 250, 255, 128, 128, 0, 255,
    ];
    let setup = |c: &mut Context| {
        c.matrix_mode(gl::PROJECTION);
        c.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
        c.matrix_mode(gl::MODELVIEW);
    };
    let mut c = ctx();
    setup(&mut c);
    c.vertex_pointer(2, gl::SHORT, 0, &pos);
    c.color_pointer(4, gl::UNSIGNED_BYTE, 0, &col);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.enable_client_state(gl::COLOR_ARRAY);
    c.draw_arrays(gl::TRIANGLE_STRIP, 0, 4);
    let mut r = ctx();
    setup(&mut r);
    r.begin(gl::TRIANGLE_STRIP);
    for i in 0..4 {
        r.color4ubv(&[col[4 * i], col[4 * i + 1], col[4 * i + 2], col[4 * i + 3]]);
        r.vertex2s(pos[2 * i], pos[2 * i + 1]);
    }
    r.end();
    let a = image(&mut c);
    assert_eq!(a, image(&mut r));
    assert!(a.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count() > 1000);
}

#[test]
fn normal_and_edge_flag_arrays_match_immediate_mode() {
    // A lit quad fan with BYTE normals (normalised by table 2.9) and an edge flag per vertex,
    // drawn filled and in LINE mode (where a false edge flag hides the edge it starts).
    let pos: [f32; 12] = [
        -0.8, -0.8, 0.0, 0.8, -0.7, 0.0, 0.7, 0.8, 0.0, -0.6, 0.6, 0.0,
    ];
    let nrm: [i8; 12] = [0, 0, 127, 60, 0, 100, -40, 40, 100, 0, -127, 20];
    let edge = [true, false, true, true];
    for mode in [gl::FILL, gl::LINE] {
        let setup = |c: &mut Context| {
            c.enable(gl::LIGHTING);
            c.enable(gl::LIGHT0);
            c.lightfv(gl::LIGHT0, gl::POSITION, &[0.3, 0.2, 1.0, 0.0]);
            c.polygon_mode(gl::FRONT_AND_BACK, mode);
        };
        let mut c = ctx();
        setup(&mut c);
        c.vertex_pointer(3, gl::FLOAT, 0, &pos);
        c.normal_pointer(gl::BYTE, 0, &nrm);
        c.edge_flag_pointer(0, &edge);
        for cap in [gl::VERTEX_ARRAY, gl::NORMAL_ARRAY, gl::EDGE_FLAG_ARRAY] {
            c.enable_client_state(cap);
        }
        c.draw_arrays(gl::POLYGON, 0, 4);
        let mut r = ctx();
        setup(&mut r);
        r.begin(gl::POLYGON);
        for i in 0..4 {
            r.edge_flag(edge[i]);
            r.normal3b(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
            r.vertex3f(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
        }
        r.end();
        let a = image(&mut c);
        assert_eq!(a, image(&mut r), "mode {mode:#x}");
        assert!(a.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count() > 100);
    }
}

#[test]
fn queries_report_the_state_tables() {
    let mut c = ctx();
    let geti = |c: &mut Context, p: u32| {
        let mut v = [-7];
        c.get_integerv(p, &mut v);
        assert_eq!(c.get_error(), gl::NO_ERROR, "{p:#x}");
        v[0]
    };
    // Initial values: GL 2.1 tables 6.6 to 6.8 and §2.9.
    let initial: [(u32, i32); 23] = [
        (gl::VERTEX_ARRAY_SIZE, 4),
        (gl::VERTEX_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::VERTEX_ARRAY_STRIDE, 0),
        (gl::NORMAL_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::NORMAL_ARRAY_STRIDE, 0),
        (gl::COLOR_ARRAY_SIZE, 4),
        (gl::COLOR_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::SECONDARY_COLOR_ARRAY_SIZE, 3),
        (gl::SECONDARY_COLOR_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::TEXTURE_COORD_ARRAY_SIZE, 4),
        (gl::TEXTURE_COORD_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::FOG_COORD_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::EDGE_FLAG_ARRAY_STRIDE, 0),
        (gl::INDEX_ARRAY_TYPE, gl::FLOAT as i32),
        (gl::INDEX_ARRAY_STRIDE, 0),
        (gl::INDEX_ARRAY, 0),
        (gl::ARRAY_BUFFER_BINDING, 0),
        (gl::ELEMENT_ARRAY_BUFFER_BINDING, 0),
        (gl::VERTEX_ARRAY_BUFFER_BINDING, 0),
        (gl::VERTEX_ARRAY, 0),
        (gl::COLOR_ARRAY, 0),
        (gl::TEXTURE_COORD_ARRAY, 0),
        (gl::CLIENT_ACTIVE_TEXTURE, gl::TEXTURE0 as i32),
    ];
    for (p, v) in initial {
        assert_eq!(geti(&mut c, p), v, "{p:#x}");
    }
    // Client states are IsEnabled caps, not Enable caps in GL 2.1; Mesa's compatibility
    // context (the reference) takes Enable/Disable of them as Enable/DisableClientState.
    c.enable(gl::VERTEX_ARRAY);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert!(c.is_enabled(gl::VERTEX_ARRAY));
    c.disable(gl::VERTEX_ARRAY);
    assert!(!c.is_enabled(gl::VERTEX_ARRAY));
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.vertex_pointer(2, gl::SHORT, 6, &[0i16; 9]);
    c.normal_pointer(gl::BYTE, 5, &[0i8; 8]);
    c.color_pointer(3, gl::UNSIGNED_BYTE, 7, &[0u8; 10]);
    c.client_active_texture(gl::TEXTURE1);
    c.tex_coord_pointer(1, gl::DOUBLE, 16, &[0f64; 2]);
    c.enable_client_state(gl::TEXTURE_COORD_ARRAY);
    c.enable_client_state(gl::NORMAL_ARRAY);
    assert_eq!(geti(&mut c, gl::VERTEX_ARRAY_SIZE), 2);
    assert_eq!(geti(&mut c, gl::VERTEX_ARRAY_TYPE), gl::SHORT as i32);
    assert_eq!(geti(&mut c, gl::VERTEX_ARRAY_STRIDE), 6);
    assert_eq!(geti(&mut c, gl::NORMAL_ARRAY_TYPE), gl::BYTE as i32);
    assert_eq!(geti(&mut c, gl::NORMAL_ARRAY_STRIDE), 5);
    assert_eq!(geti(&mut c, gl::COLOR_ARRAY_SIZE), 3);
    assert_eq!(geti(&mut c, gl::TEXTURE_COORD_ARRAY_SIZE), 1);
    assert_eq!(
        geti(&mut c, gl::TEXTURE_COORD_ARRAY_TYPE),
        gl::DOUBLE as i32
    );
    assert!(c.is_enabled(gl::TEXTURE_COORD_ARRAY));
    assert!(c.is_enabled(gl::NORMAL_ARRAY));
    assert!(!c.is_enabled(gl::VERTEX_ARRAY));
    // The colour-index array: held, enabled and queried; no RGBA draw reads it.
    c.index_pointer(gl::SHORT, 10, &[0i16; 6]);
    c.enable_client_state(gl::INDEX_ARRAY);
    assert_eq!(geti(&mut c, gl::INDEX_ARRAY_TYPE), gl::SHORT as i32);
    assert_eq!(geti(&mut c, gl::INDEX_ARRAY_STRIDE), 10);
    assert!(c.is_enabled(gl::INDEX_ARRAY));
    assert_eq!(
        c.get_pointerv(gl::INDEX_ARRAY_POINTER),
        Pointer::Data(vec![0; 12])
    );
    c.interleaved_arrays(gl::V2F, 0, &[0f32; 4]);
    assert!(
        !c.is_enabled(gl::INDEX_ARRAY),
        "InterleavedArrays disables INDEX_ARRAY"
    );
    assert_eq!(
        c.get_pointerv(gl::TEXTURE_COORD_ARRAY_POINTER),
        Pointer::Data(vec![0; 16])
    );
    assert_eq!(c.get_pointerv(gl::VERTEX_ARRAY_SIZE), Pointer::NULL);
    assert_eq!(c.get_error(), IE);
    // Unit 0's texture coordinate array is untouched.
    c.client_active_texture(gl::TEXTURE0);
    assert_eq!(geti(&mut c, gl::TEXTURE_COORD_ARRAY_SIZE), 4);
    assert!(!c.is_enabled(gl::TEXTURE_COORD_ARRAY));
}

#[test]
fn buffer_names_bindings_and_parameters() {
    let mut c = ctx();
    let mut n = [0; 3];
    c.gen_buffers(3, &mut n);
    assert_eq!(n, [1, 2, 3]);
    // Generated but never bound: not yet a buffer object (GL 2.1 §2.9).
    assert!(!c.is_buffer(1));
    c.bind_buffer(gl::ARRAY_BUFFER, 2);
    assert!(c.is_buffer(2));
    let mut p = [-1];
    c.get_buffer_parameteriv(gl::ARRAY_BUFFER, gl::BUFFER_SIZE, &mut p);
    assert_eq!(p, [0]);
    c.buffer_data(gl::ARRAY_BUFFER, 10, Pointer::NULL, gl::DYNAMIC_DRAW);
    for (pname, v) in [
        (gl::BUFFER_SIZE, 10),
        (gl::BUFFER_USAGE, gl::DYNAMIC_DRAW as i32),
        (gl::BUFFER_ACCESS, gl::READ_WRITE as i32),
        (gl::BUFFER_MAPPED, 0),
    ] {
        c.get_buffer_parameteriv(gl::ARRAY_BUFFER, pname, &mut p);
        assert_eq!(p, [v], "{pname:#x}");
    }
    c.vertex_pointer(3, gl::FLOAT, 0, 0usize);
    let mut v = [0];
    c.get_integerv(gl::VERTEX_ARRAY_BUFFER_BINDING, &mut v);
    assert_eq!(v, [2]);
    // Deleting a bound buffer reverts its bindings to 0; the name is free again.
    c.delete_buffers(1, &[2]);
    c.get_integerv(gl::ARRAY_BUFFER_BINDING, &mut v);
    assert_eq!(v, [0]);
    c.get_integerv(gl::VERTEX_ARRAY_BUFFER_BINDING, &mut v);
    assert_eq!(v, [0]);
    assert!(!c.is_buffer(2));
    let mut m = [0; 2];
    c.gen_buffers(2, &mut m);
    assert_eq!(m, [2, 4]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

type Step = fn(&mut Context);

fn none(_: &mut Context) {}
fn inside(c: &mut Context) {
    c.begin(gl::TRIANGLES);
}
/// A 3-vertex client vertex array, enabled.
fn three(c: &mut Context) {
    c.vertex_pointer(2, gl::FLOAT, 0, &[0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0]);
    c.enable_client_state(gl::VERTEX_ARRAY);
}
fn three_inside(c: &mut Context) {
    three(c);
    c.begin(gl::POINTS);
}
fn bound(c: &mut Context) {
    c.bind_buffer(gl::ARRAY_BUFFER, 5);
    c.buffer_data(gl::ARRAY_BUFFER, 8, &[1u8; 8], gl::STATIC_DRAW);
}
fn element_bound(c: &mut Context) {
    three(c);
    c.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, 6);
    c.buffer_data(gl::ELEMENT_ARRAY_BUFFER, 3, &[0u8, 1, 2], gl::STATIC_DRAW);
}
fn offset_without_buffer(c: &mut Context) {
    c.vertex_pointer(2, gl::FLOAT, 0, 16usize);
    c.enable_client_state(gl::VERTEX_ARRAY);
}

#[rustfmt::skip]
const ERRORS: &[(&str, Step, Step, u32)] = &[
    ("EnableClientState(LIGHTING)", none, |c| c.enable_client_state(gl::LIGHTING), IE),
    ("DisableClientState(0)", none, |c| c.disable_client_state(0), IE),
    ("EnableClientState in Begin/End", inside, |c| c.enable_client_state(gl::VERTEX_ARRAY), IO),
    ("VertexPointer size 1", none, |c| c.vertex_pointer(1, gl::FLOAT, 0, &[0f32; 4]), IV),
    ("VertexPointer size 5", none, |c| c.vertex_pointer(5, gl::FLOAT, 0, &[0f32; 5]), IV),
    ("VertexPointer UNSIGNED_BYTE", none, |c| c.vertex_pointer(3, gl::UNSIGNED_BYTE, 0, &[0u8; 3]), IE),
    ("VertexPointer stride -1", none, |c| c.vertex_pointer(3, gl::FLOAT, -1, &[0f32; 3]), IV),
    ("VertexPointer stride 2049", none, |c| c.vertex_pointer(3, gl::FLOAT, 2049, &[0f32; 3]), IV),
    ("InterleavedArrays stride 2049", none, |c| c.interleaved_arrays(gl::V3F, 2049, &[0f32; 8]), IV),
    ("VertexPointer in Begin/End", inside, |c| c.vertex_pointer(3, gl::FLOAT, 0, &[0f32; 3]), IO),
    ("VertexPointer client data, buffer bound", bound, |c| c.vertex_pointer(2, gl::FLOAT, 0, &[0f32; 2]), IO),
    ("NormalPointer UNSIGNED_BYTE", none, |c| c.normal_pointer(gl::UNSIGNED_BYTE, 0, &[0u8; 3]), IE),
    ("NormalPointer stride -4", none, |c| c.normal_pointer(gl::FLOAT, -4, &[0f32; 3]), IV),
    ("ColorPointer size 2", none, |c| c.color_pointer(2, gl::FLOAT, 0, &[0f32; 2]), IV),
    ("ColorPointer type 0x1234", none, |c| c.color_pointer(4, 0x1234, 0, &[0f32; 4]), IE),
    ("SecondaryColorPointer size 4", none, |c| c.secondary_color_pointer(4, gl::FLOAT, 0, &[0f32; 4]), IV),
    ("TexCoordPointer size 0", none, |c| c.tex_coord_pointer(0, gl::FLOAT, 0, &[0f32; 4]), IV),
    ("TexCoordPointer UNSIGNED_INT", none, |c| c.tex_coord_pointer(2, gl::UNSIGNED_INT, 0, &[0u32; 2]), IE),
    ("FogCoordPointer INT", none, |c| c.fog_coord_pointer(gl::INT, 0, &[0i32; 1]), IE),
    ("EdgeFlagPointer stride -1", none, |c| c.edge_flag_pointer(-1, &[true]), IV),
    ("IndexPointer UNSIGNED_SHORT", none, |c| c.index_pointer(gl::UNSIGNED_SHORT, 0, &[0u16; 1]), IE),
    ("IndexPointer stride -1", none, |c| c.index_pointer(gl::INT, -1, &[0i32; 1]), IV),
    ("IndexPointer in Begin/End", inside, |c| c.index_pointer(gl::FLOAT, 0, &[0f32; 1]), IO),
    ("InterleavedArrays(FLOAT)", none, |c| c.interleaved_arrays(gl::FLOAT, 0, &[0f32; 8]), IE),
    ("InterleavedArrays stride -1", none, |c| c.interleaved_arrays(gl::V3F, -1, &[0f32; 8]), IV),
    ("DrawArrays mode 10", three, |c| c.draw_arrays(10, 0, 3), IE),
    ("DrawArrays count -1", three, |c| c.draw_arrays(gl::TRIANGLES, 0, -1), IV),
    ("DrawArrays first -1", three, |c| c.draw_arrays(gl::TRIANGLES, -1, 3), IV),
    ("DrawArrays in Begin/End", three_inside, |c| c.draw_arrays(gl::TRIANGLES, 0, 3), IO),
    ("DrawArrays past the data", three, |c| c.draw_arrays(gl::TRIANGLES, 1, 3), IO),
    ("DrawArrays offset, no buffer", offset_without_buffer, |c| c.draw_arrays(gl::POINTS, 0, 1), IO),
    ("DrawElements type FLOAT", three, |c| c.draw_elements(gl::TRIANGLES, 3, gl::FLOAT, &[0f32; 3]), IE),
    ("DrawElements mode 11", three, |c| c.draw_elements(11, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IE),
    ("DrawElements count -1", three, |c| c.draw_elements(gl::TRIANGLES, -1, gl::UNSIGNED_BYTE, &[0u8]), IV),
    ("DrawElements in Begin/End", three_inside, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IO),
    ("DrawElements index 3 of 3", three, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_SHORT, &[0u16, 1, 3]), IO),
    ("DrawElements short index data", three, |c| c.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_INT, &[0u32, 1, 2]), IO),
    ("DrawElements client indices, EBO bound", element_bound, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IO),
    ("DrawElements EBO offset past end", element_bound, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, 1usize), IO),
    ("DrawRangeElements end < start", three, |c| c.draw_range_elements(gl::TRIANGLES, 2, 1, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IV),
    ("ArrayElement(-1)", three, |c| c.array_element(-1), IV),
    ("ArrayElement past the data, in Begin/End", three_inside, |c| c.array_element(3), IO),
    ("GenBuffers(-1)", none, |c| c.gen_buffers(-1, &mut []), IV),
    ("GenBuffers(2) into 1", none, |c| c.gen_buffers(2, &mut [0]), IV),
    ("GenBuffers in Begin/End", inside, |c| c.gen_buffers(1, &mut [0]), IO),
    ("DeleteBuffers(-1)", bound, |c| c.delete_buffers(-1, &[5]), IV),
    ("DeleteBuffers(2) of 1", bound, |c| c.delete_buffers(2, &[5]), IV),
    ("BindBuffer(TEXTURE_2D)", none, |c| c.bind_buffer(gl::TEXTURE_2D, 1), IE),
    ("BindBuffer in Begin/End", inside, |c| c.bind_buffer(gl::ARRAY_BUFFER, 1), IO),
    ("BufferData, none bound", none, |c| c.buffer_data(gl::ARRAY_BUFFER, 4, &[0u8; 4], gl::STATIC_DRAW), IO),
    ("BufferData size -1", bound, |c| c.buffer_data(gl::ARRAY_BUFFER, -1, Pointer::NULL, gl::STATIC_DRAW), IV),
    ("BufferData usage 0", bound, |c| c.buffer_data(gl::ARRAY_BUFFER, 4, Pointer::NULL, 0), IE),
    ("BufferData target PIXEL_PACK", bound, |c| c.buffer_data(gl::TEXTURE_2D, 4, Pointer::NULL, gl::STATIC_DRAW), IE),
    ("BufferData data shorter than size", bound, |c| c.buffer_data(gl::ARRAY_BUFFER, 9, &[0u8; 8], gl::STATIC_DRAW), IV),
    ("BufferData 1 GiB without data", bound, |c| c.buffer_data(gl::ARRAY_BUFFER, 1 << 30, Pointer::NULL, gl::STATIC_DRAW), gl::OUT_OF_MEMORY),
    ("BufferSubData past the end", bound, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, 4, 5, &[0u8; 5]), IV),
    ("BufferSubData offset -1", bound, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, -1, 1, &[0u8; 1]), IV),
    ("BufferSubData, none bound", none, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, 0, 1, &[0u8; 1]), IO),
    ("BufferSubData in Begin/End", inside, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, 0, 1, &[0u8; 1]), IO),
    ("GetBufferParameteriv(ARRAY_BUFFER_BINDING)", bound, |c| c.get_buffer_parameteriv(gl::ARRAY_BUFFER, gl::ARRAY_BUFFER_BINDING, &mut [0]), IE),
    ("GetBufferParameteriv, none bound", none, |c| c.get_buffer_parameteriv(gl::ARRAY_BUFFER, gl::BUFFER_SIZE, &mut [0]), IO),
    ("GetBufferSubData into a short slice", bound, |c| c.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 8, &mut [0u8; 7]), IV),
];

#[test]
fn every_error_row_sets_its_error_and_changes_nothing() {
    assert!(ERRORS.len() >= 30);
    for &(name, setup, call, expected) in ERRORS {
        let mut c = ctx();
        setup(&mut c);
        assert_eq!(c.pending_error(), gl::NO_ERROR, "{name}: setup");
        let before = c.state().clone();
        call(&mut c);
        assert!(c.state() == &before, "{name}: state changed");
        assert_eq!(c.pending_error(), expected, "{name}");
        // Nothing was drawn either: the framebuffer is still the initial clear (0, 0, 0, 0).
        let img = c.to_image().into_raw();
        assert!(img.iter().all(|&b| b == 0), "{name}: drew something");
    }
}

/// A scene using client arrays, buffer objects, InterleavedArrays and ArrayElement.
pub fn mixed(c: &mut Context) {
    client_interleaved(c);
    c.draw_arrays(gl::TRIANGLES, 0, 3);
    c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, &[6u8, 7, 8]);
    let mut b = [0];
    c.gen_buffers(1, &mut b);
    c.bind_buffer(gl::ARRAY_BUFFER, b[0]);
    let data = flat();
    c.buffer_data(
        gl::ARRAY_BUFFER,
        (data.len() * 4) as isize,
        &data,
        gl::STREAM_DRAW,
    );
    c.vertex_pointer(3, gl::FLOAT, 28, 0usize);
    c.color_pointer(4, gl::FLOAT, 28, 12usize);
    c.draw_range_elements(gl::TRIANGLES, 3, 5, 3, gl::UNSIGNED_INT, &[3u32, 4, 5]);
    c.bind_buffer(gl::ARRAY_BUFFER, 0);
    c.interleaved_arrays(
        gl::C3F_V3F,
        0,
        &[
            1.0f32, 1.0, 1.0, 0.2, 0.2, 0.0, 1.0, 1.0, 1.0, 0.8, 0.3, 0.0, 1.0, 1.0, 1.0, 0.5, 0.8,
            0.0,
        ],
    );
    c.begin(gl::TRIANGLES);
    for i in 0..3 {
        c.array_element(i);
    }
    c.end();
    // An erroneous draw is recorded and must stay erroneous on replay.
    c.draw_arrays(gl::TRIANGLES, 0, 4);
}

#[test]
fn recording_replays_to_the_same_image() {
    let mut c = ctx();
    c.start_recording();
    mixed(&mut c);
    let calls = c.stop_recording();
    assert_eq!(c.get_error(), IO);
    let img = c.to_image().into_raw();
    assert!(img.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count() > 500);
    assert!(
        matches!(calls.first(), Some(Call::VertexPointer(3, gl::FLOAT, 28, Pointer::Data(d))) if d.len() == 12 * 28)
    );
    let mut r = ctx();
    r.replay(&calls);
    assert_eq!(r.get_error(), IO);
    assert_eq!(r.to_image().into_raw(), img);
    // Through the text format.
    let mut text = Vec::new();
    assert!(fixedgl::recording::write_recording(&calls, &mut text).is_ok());
    let read = fixedgl::recording::read_recording(&text[..]);
    match &read {
        Ok(back) => assert!(back == &calls, "text round trip"),
        Err(e) => panic!("{e}"),
    }
    let text = String::from_utf8_lossy(&text);
    assert!(
        text.contains("DrawRangeElements(TRIANGLES, 3, 5, 3, UNSIGNED_INT"),
        "{text}"
    );
    assert!(
        text.contains("InterleavedArrays(C3F_V3F, 0, Data(["),
        "{text}"
    );
}

/// The same recordings on the real driver (skipped, with the reason printed, without EGL).
#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;
    use fixedgl::glbackend::{DeviceChoice, GlBackend};

    fn backend() -> Option<GlBackend> {
        crate::common::test_backend(SIZE, SIZE)
    }

    #[test]
    fn recorded_array_draws_replay_on_the_driver() {
        let Some(mut gl) = backend() else { return };
        let mut c = ctx();
        c.start_recording();
        mixed(&mut c);
        let calls = c.stop_recording();
        let cpu = c.to_image();
        gl.replay(&calls);
        // The out-of-bounds DrawArrays at the end: refused on the driver too.
        assert_eq!(gl.get_error(), IO);
        let img = gl.read_image();
        let cmp = compare(&cpu, &img, 2);
        assert!(
            cmp.passes(0.5),
            "{} pixels differ, max {:?}",
            cmp.differing_pixels,
            cmp.max_diff
        );
        // Replaying again as a frame (Push/PopClientAttrib) keeps the shadow in step: the same
        // image and the same error.
        gl.replay_frame(&calls);
        assert_eq!(gl.get_error(), IO);
        gl.replay(&[Call::DrawArrays(gl::TRIANGLES, 0, 3)]);
        assert_eq!(gl.get_error(), gl::NO_ERROR);
    }

    #[test]
    fn refused_draws_never_reach_the_driver() {
        let Some(mut gl) = backend() else { return };
        for &(name, setup, call, expected) in ERRORS {
            let mut c = ctx();
            c.start_recording();
            setup(&mut c);
            call(&mut c);
            let calls = c.stop_recording();
            // Queries are not recorded: nothing of theirs to replay.
            if name.starts_with("Get") {
                continue;
            }
            gl.replay(&calls);
            if matches!(calls.first(), Some(Call::Begin(_)))
                || name.contains("in Begin/End")
                || matches!(calls.get(2), Some(Call::Begin(_)))
            {
                gl.replay(&[Call::End]);
            }
            assert_eq!(gl.get_error(), expected, "{name}");
            // Leave the driver's client state as a fresh context's for the next row.
            gl.replay(&[
                Call::DisableClientState(gl::VERTEX_ARRAY),
                Call::BindBuffer(gl::ARRAY_BUFFER, 0),
                Call::BindBuffer(gl::ELEMENT_ARRAY_BUFFER, 0),
            ]);
            assert_eq!(gl.get_error(), gl::NO_ERROR, "{name}: reset");
        }
    }

    #[test]
    fn seed_scenes_match_the_driver() {
        let Some(_) = backend() else { return };
        for name in ["rect-wire", "cube-colors"] {
            let Some(scene) = fixedgl::scenes::find(name) else {
                panic!("{name} not registered")
            };
            let Ok((mut c, calls)) = scene.record(200, 200) else {
                panic!("{name}: record")
            };
            let Ok(mut gl) = GlBackend::new(200, 200, &DeviceChoice::Auto) else {
                return;
            };
            gl.replay(&calls);
            assert_eq!(gl.get_error(), gl::NO_ERROR, "{name}");
            assert_eq!(c.get_error(), gl::NO_ERROR, "{name}");
            let cmp = compare(&c.to_image(), &gl.read_image(), scene.tolerance.channel);
            assert!(
                cmp.passes(scene.tolerance.max_percent),
                "{name}: {} pixels differ",
                cmp.differing_pixels
            );
        }
    }
}

/// Random sequences of array and buffer calls give the same errors on the driver as on the CPU
/// front end, and never make the driver read past the data (which would crash the test).
#[cfg(feature = "gl")]
mod random_on_gl {
    use super::*;
    use fixedgl::glbackend::{DeviceChoice, GlBackend};
    use proptest::prelude::*;

    /// The array and buffer commands, whose errors the test compares.
    const ARRAY_CALLS: [&str; 23] = [
        "EnableClientState",
        "DisableClientState",
        "VertexPointer",
        "NormalPointer",
        "ColorPointer",
        "SecondaryColorPointer",
        "TexCoordPointer",
        "FogCoordPointer",
        "EdgeFlagPointer",
        "InterleavedArrays",
        "ArrayElement",
        "DrawArrays",
        "DrawElements",
        "DrawRangeElements",
        "GenBuffers",
        "DeleteBuffers",
        "BindBuffer",
        "BufferData",
        "BufferSubData",
        "MapBuffer",
        "UnmapBuffer",
        "MultiDrawArrays",
        "MultiDrawElements",
    ];

    fn any_array_call() -> impl Strategy<Value = Call> {
        prop_oneof![
            1 => Just(Call::Begin(gl::POINTS)),
            1 => Just(Call::End),
            1 => Just(Call::ClientActiveTexture(gl::TEXTURE1)),
            12 => (any::<u64>(), 0..ARRAY_CALLS.len())
                .prop_map(|(seed, k)| crate::soak::Gen::new(seed).call_named(ARRAY_CALLS[k])),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

        #[test]
        fn same_errors_as_the_cpu(calls in prop::collection::vec(any_array_call(), 1..40)) {
            let Ok(mut gl) = GlBackend::new(8, 8, &DeviceChoice::Auto) else {
                prop_assert!(std::env::var_os("FIXEDGL_REQUIRE_GL").is_none(), "no GL backend");
                return Ok(());
            };
            let mut c = ctx();
            let mut inside = false;
            for call in &calls {
                c.execute(call);
                gl.execute(call);
                match call {
                    Call::Begin(_) if !inside => inside = true,
                    Call::End if inside => inside = false,
                    _ => {}
                }
                if !inside {
                    prop_assert_eq!(gl.get_error(), c.get_error(), "{:?}", call);
                }
            }
        }
    }
}

/// What a draw from arrays leaves in the current attributes, on the driver and on the CPU: Mesa
/// draws from the arrays without touching the current values (GL 2.1 §2.8 leaves them
/// indeterminate), while a draw compiled into a display list becomes immediate-mode calls
/// (§5.4), which set them when the list runs.
#[cfg(feature = "gl")]
mod current_after_draws {
    use super::*;

    fn setup(c: &mut Context) {
        c.color4f(0.1, 0.2, 0.3, 0.4);
        c.normal3f(0.0, 0.6, 0.8);
        c.tex_coord4f(0.5, 0.25, 0.125, 1.0);
        c.secondary_color3f(0.7, 0.1, 0.2);
        c.fog_coordf(3.0);
        c.edge_flag(false);
        let v: [f32; 8] = [-0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, 0.5];
        let col: [f32; 16] = [1.0, 0.5, 0.25, 1.0]
            .repeat(4)
            .try_into()
            .unwrap_or([0.0; 16]);
        let n: [f32; 12] = [1.0, 0.0, 0.0].repeat(4).try_into().unwrap_or([0.0; 12]);
        let t: [f32; 8] = [0.75, 0.5].repeat(4).try_into().unwrap_or([0.0; 8]);
        let s: [f32; 12] = [0.0, 0.0, 1.0].repeat(4).try_into().unwrap_or([0.0; 12]);
        let f: [f32; 4] = [9.0; 4];
        let e: [u8; 4] = [1; 4];
        c.vertex_pointer(2, gl::FLOAT, 0, &v[..]);
        c.color_pointer(4, gl::FLOAT, 0, &col[..]);
        c.normal_pointer(gl::FLOAT, 0, &n[..]);
        c.tex_coord_pointer(2, gl::FLOAT, 0, &t[..]);
        c.secondary_color_pointer(3, gl::FLOAT, 0, &s[..]);
        c.fog_coord_pointer(gl::FLOAT, 0, &f[..]);
        c.edge_flag_pointer(0, &e[..]);
        for a in [
            gl::VERTEX_ARRAY,
            gl::COLOR_ARRAY,
            gl::NORMAL_ARRAY,
            gl::TEXTURE_COORD_ARRAY,
            gl::SECONDARY_COLOR_ARRAY,
            gl::FOG_COORD_ARRAY,
            gl::EDGE_FLAG_ARRAY,
        ] {
            c.enable_client_state(a);
        }
    }

    /// CURRENT_COLOR, NORMAL, TEXTURE_COORDS, SECONDARY_COLOR, FOG_COORD and EDGE_FLAG.
    fn current(get: &mut dyn FnMut(u32, &mut [f32])) -> Vec<Vec<f32>> {
        [
            (gl::CURRENT_COLOR, 4),
            (gl::CURRENT_NORMAL, 3),
            (gl::CURRENT_TEXTURE_COORDS, 4),
            (gl::CURRENT_SECONDARY_COLOR, 4),
            (gl::CURRENT_FOG_COORD, 1),
            (gl::EDGE_FLAG, 1),
        ]
        .iter()
        .map(|&(p, n)| {
            let mut v = vec![f32::NAN; n];
            get(p, &mut v);
            v
        })
        .collect()
    }

    #[test]
    fn draws_leave_the_current_attributes_as_the_driver_does() {
        for list in [false, true] {
            for elements in [false, true] {
                let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                    return;
                };
                let mut c = ctx();
                c.start_recording();
                setup(&mut c);
                if list {
                    c.new_list(1, gl::COMPILE);
                }
                if elements {
                    c.draw_elements(gl::QUADS, 4, gl::UNSIGNED_BYTE, &[0u8, 1, 2, 3][..]);
                } else {
                    c.draw_arrays(gl::QUADS, 0, 4);
                }
                if list {
                    c.end_list();
                    c.call_list(1);
                }
                let calls = c.stop_recording();
                gl.replay(&calls);
                assert_eq!(gl.get_error(), gl::NO_ERROR);
                assert_eq!(c.get_error(), gl::NO_ERROR);
                let on_gl = current(&mut |p, v| gl.get_floatv(p, v));
                let on_cpu = current(&mut |p, v| c.get_floatv(p, v));
                assert_eq!(on_cpu, on_gl, "list {list}, elements {elements}");
                // The recording replayed on a fresh CPU context agrees too.
                let mut again = ctx();
                again.replay(&calls);
                let replayed = current(&mut |p, v| again.get_floatv(p, v));
                assert_eq!(
                    replayed, on_gl,
                    "replayed: list {list}, elements {elements}"
                );
            }
        }
    }
}
