//! Buffer mapping (GL 1.5, GL 2.1 §2.9): MapBuffer / UnmapBuffer / GetBufferPointerv, the
//! BUFFER_MAPPED and BUFFER_ACCESS queries, the errors, the stable address of a mapped store, and
//! recordings that carry the bytes written through a mapping so that a replay — on another
//! context or on the driver — draws the same picture.

use fixedgl::{gl, Call, Context, Pointer};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;
const OK: u32 = gl::NO_ERROR;

const SIZE: u32 = 64;

fn ctx() -> Context {
    match Context::new(SIZE, SIZE) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

fn param(c: &mut Context, target: u32, pname: u32) -> i32 {
    let mut v = [-7];
    c.get_buffer_parameteriv(target, pname, &mut v);
    v[0]
}

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

#[test]
fn a_mapping_reads_and_writes_the_store() {
    let mut c = ctx();
    c.bind_buffer(gl::ARRAY_BUFFER, 3);
    c.buffer_data(
        gl::ARRAY_BUFFER,
        8,
        &[1u8, 2, 3, 4, 5, 6, 7, 8],
        gl::DYNAMIC_DRAW,
    );
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    assert_eq!(
        param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_ACCESS),
        gl::READ_WRITE as i32
    );
    assert!(c
        .get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_MAP_POINTER)
        .is_null());
    let addr = match c.map_buffer(gl::ARRAY_BUFFER, gl::WRITE_ONLY) {
        Some(m) => {
            assert_eq!(m, &[1, 2, 3, 4, 5, 6, 7, 8]);
            m[2] = 30;
            m[7] = 80;
            m.as_ptr()
        }
        None => panic!("map failed: {:#x}", c.get_error()),
    };
    assert_eq!(c.get_error(), OK);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 1);
    assert_eq!(
        param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_ACCESS),
        gl::WRITE_ONLY as i32
    );
    // The store stays where it is while mapped, whatever else happens to buffers and bindings.
    let mut names = [0; 40];
    c.gen_buffers(40, &mut names);
    for &n in &names {
        c.bind_buffer(gl::ARRAY_BUFFER, n);
        c.buffer_data(gl::ARRAY_BUFFER, 1000, Pointer::NULL, gl::STATIC_DRAW);
    }
    c.push_client_attrib(gl::CLIENT_ALL_ATTRIB_BITS);
    c.bind_buffer(gl::ARRAY_BUFFER, 0);
    c.pop_client_attrib();
    c.delete_buffers(20, &names);
    c.bind_buffer(gl::ARRAY_BUFFER, 3);
    assert_eq!(c.get_error(), OK);
    let p = c.get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_MAP_POINTER);
    assert_eq!(p.cast::<u8>().cast_const(), addr);
    assert_eq!(
        c.mapped_buffer_mut(gl::ARRAY_BUFFER).map(|m| m.as_ptr()),
        Some(addr)
    );
    assert!(c.unmap_buffer(gl::ARRAY_BUFFER));
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    // After UnmapBuffer, BUFFER_ACCESS reads READ_WRITE again, as llvmpipe reports it.
    assert_eq!(
        param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_ACCESS),
        gl::READ_WRITE as i32
    );
    assert!(c.mapped_buffer_mut(gl::ARRAY_BUFFER).is_none());
    let mut out = [0u8; 8];
    c.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 8, &mut out);
    assert_eq!(out, [1, 2, 30, 4, 5, 6, 7, 80]);
    assert_eq!(c.get_error(), OK);
}

/// Where the erroneous call is made.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum At {
    Outside,
    InsideBegin,
}

/// (name, setup, call, error): each call made after `setup`, the error it must raise and, for
/// an error, the State it must leave unchanged.
type Row = (&'static str, At, fn(&mut Context), fn(&mut Context), u32);

fn data(c: &mut Context) {
    c.bind_buffer(gl::ARRAY_BUFFER, 5);
    c.buffer_data(gl::ARRAY_BUFFER, 36, &[0.5f32; 9], gl::STATIC_DRAW);
}
fn mapped(c: &mut Context) {
    data(c);
    c.map_buffer(gl::ARRAY_BUFFER, gl::READ_WRITE);
}
fn mapped_array(c: &mut Context) {
    mapped(c);
    c.vertex_pointer(3, gl::FLOAT, 0, 0usize);
    c.enable_client_state(gl::VERTEX_ARRAY);
}
fn mapped_elements(c: &mut Context) {
    c.vertex_pointer(3, gl::FLOAT, 0, &[0.0f32; 9]);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, 6);
    c.buffer_data(gl::ELEMENT_ARRAY_BUFFER, 3, &[0u8, 1, 2], gl::STATIC_DRAW);
    c.map_buffer(gl::ELEMENT_ARRAY_BUFFER, gl::READ_ONLY);
}
fn empty(c: &mut Context) {
    c.bind_buffer(gl::ARRAY_BUFFER, 5);
}
fn none(_: &mut Context) {}

#[rustfmt::skip]
const ROWS: &[Row] = &[
    ("map: bad access", At::Outside, data, |c| { c.map_buffer(gl::ARRAY_BUFFER, gl::STATIC_DRAW); }, IE),
    ("map: bad access before bad target", At::Outside, data, |c| { c.map_buffer(gl::TEXTURE_2D, 0); }, IE),
    ("map: bad target", At::Outside, data, |c| { c.map_buffer(gl::TEXTURE_2D, gl::READ_ONLY); }, IE),
    ("map: bad access, none bound", At::Outside, none, |c| { c.map_buffer(gl::ARRAY_BUFFER, 0); }, IE),
    ("map: none bound", At::Outside, none, |c| { c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY); }, IO),
    ("map: empty store", At::Outside, empty, |c| { c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY); }, IO),
    ("map: twice", At::Outside, mapped, |c| { c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY); }, IO),
    ("map: in Begin/End", At::InsideBegin, data, |c| { c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY); }, IO),
    ("unmap: bad target", At::Outside, mapped, |c| { c.unmap_buffer(gl::TEXTURE_2D); }, IE),
    ("unmap: none bound", At::Outside, none, |c| { c.unmap_buffer(gl::ARRAY_BUFFER); }, IO),
    ("unmap: not mapped", At::Outside, data, |c| { c.unmap_buffer(gl::ARRAY_BUFFER); }, IO),
    ("unmap: other target", At::Outside, mapped, |c| { c.unmap_buffer(gl::ELEMENT_ARRAY_BUFFER); }, IO),
    ("unmap: in Begin/End", At::InsideBegin, mapped, |c| { c.unmap_buffer(gl::ARRAY_BUFFER); }, IO),
    ("sub data: mapped", At::Outside, mapped, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, 0, 4, &[1u8; 4]), IO),
    ("sub data: mapped, range first", At::Outside, mapped, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, 0, 400, &[1u8; 400]), IV),
    ("sub data: mapped, negative offset", At::Outside, mapped, |c| c.buffer_sub_data(gl::ARRAY_BUFFER, -1, 4, &[1u8; 4]), IV),
    ("get sub data: mapped", At::Outside, mapped, |c| c.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 4, &mut [0u8; 4]), IO),
    ("pointer: bad pname", At::Outside, mapped, |c| { c.get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_SIZE); }, IE),
    ("pointer: bad pname, none bound", At::Outside, none, |c| { c.get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_SIZE); }, IE),
    ("pointer: bad target", At::Outside, mapped, |c| { c.get_buffer_pointerv(gl::TEXTURE_2D, gl::BUFFER_MAP_POINTER); }, IE),
    ("pointer: none bound", At::Outside, none, |c| { c.get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_MAP_POINTER); }, IO),
    ("pointer: in Begin/End", At::InsideBegin, mapped, |c| { c.get_buffer_pointerv(gl::ARRAY_BUFFER, gl::BUFFER_MAP_POINTER); }, IO),
    // GL 2.1 §2.9: a mapped store must be unmapped before a command dereferences it.
    ("draw arrays: mapped array", At::Outside, mapped_array, |c| c.draw_arrays(gl::TRIANGLES, 0, 3), IO),
    ("draw elements: mapped array", At::Outside, mapped_array, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IO),
    ("draw range elements: mapped array", At::Outside, mapped_array, |c| c.draw_range_elements(gl::TRIANGLES, 0, 2, 3, gl::UNSIGNED_BYTE, &[0u8, 1, 2]), IO),
    ("array element: mapped array", At::InsideBegin, mapped_array, |c| c.array_element(0), IO),
    ("draw elements: mapped indices", At::Outside, mapped_elements, |c| c.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_BYTE, 0usize), IO),
    ("draw arrays: mapped array, bad mode first", At::Outside, mapped_array, |c| c.draw_arrays(gl::POLYGON + 1, 0, 3), IE),
    ("draw arrays: mapped array, count 0", At::Outside, mapped_array, |c| c.draw_arrays(gl::TRIANGLES, 0, 0), OK),
    ("draw arrays: mapped buffer, array disabled", At::Outside, mapped, |c| { c.vertex_pointer(3, gl::FLOAT, 0, 0usize); c.draw_arrays(gl::TRIANGLES, 0, 3) }, OK),
    ("draw arrays: element buffer mapped", At::Outside, mapped_elements, |c| c.draw_arrays(gl::TRIANGLES, 0, 3), OK),
    ("buffer data: unmaps", At::Outside, mapped, |c| c.buffer_data(gl::ARRAY_BUFFER, 4, &[0u8; 4], gl::STATIC_DRAW), OK),
    ("delete: unmaps", At::Outside, mapped, |c| c.delete_buffers(1, &[5]), OK),
];

#[test]
fn every_error_row_sets_its_error_and_changes_nothing() {
    for &(name, at, setup, call, error) in ROWS {
        let mut c = ctx();
        setup(&mut c);
        assert_eq!(c.get_error(), OK, "{name}: setup");
        if at == At::InsideBegin {
            c.begin(gl::POINTS);
        }
        let before = c.state().clone();
        call(&mut c);
        if at == At::InsideBegin {
            c.end();
        }
        assert_eq!(c.get_error(), error, "{name}");
        if error != OK {
            assert!(c.state() == &before, "{name}: the state changed");
        }
    }
}

#[test]
fn buffer_data_and_delete_end_the_mapping() {
    let mut c = ctx();
    mapped(&mut c);
    c.buffer_data(gl::ARRAY_BUFFER, 4, &[9u8; 4], gl::STREAM_DRAW);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    assert!(c.mapped_buffer_mut(gl::ARRAY_BUFFER).is_none());
    assert!(c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY).is_some());
    c.delete_buffers(1, &[5]);
    c.bind_buffer(gl::ARRAY_BUFFER, 5);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_SIZE), 0);
    // Binding another buffer does not unmap: the mapping belongs to the object.
    mapped(&mut c);
    c.bind_buffer(gl::ARRAY_BUFFER, 0);
    c.bind_buffer(gl::ARRAY_BUFFER, 5);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 1);
    assert_eq!(c.get_error(), OK);
}

#[test]
fn map_and_unmap_execute_immediately_in_display_lists() {
    let mut c = ctx();
    data(&mut c);
    let list = c.gen_lists(1);
    c.new_list(list, gl::COMPILE);
    assert!(c.map_buffer(gl::ARRAY_BUFFER, gl::READ_ONLY).is_some());
    c.end_list();
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 1);
    c.new_list(list, gl::COMPILE);
    assert!(c.unmap_buffer(gl::ARRAY_BUFFER));
    c.end_list();
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    // The list holds neither.
    c.call_list(list);
    assert_eq!(param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED), 0);
    assert_eq!(c.get_error(), OK);
}

/// Four triangles whose vertices (x, y, z) and colours (r, g, b) are written through mappings:
/// positions into one buffer at map time, colours into a second buffer in two separate
/// mappings that each change part of it.
fn mapped_program(c: &mut Context) {
    #[rustfmt::skip]
    let positions: [f32; 36] = [
        -0.9, -0.9, 0.0,  -0.1, -0.8, 0.0,  -0.5, -0.1, 0.0,
         0.1, -0.9, 0.0,   0.9, -0.7, 0.0,   0.6,  0.0, 0.0,
        -0.8,  0.1, 0.0,  -0.2,  0.2, 0.0,  -0.6,  0.9, 0.0,
         0.2,  0.2, 0.0,   0.8,  0.3, 0.0,   0.4,  0.9, 0.0,
    ];
    let mut names = [0; 2];
    c.gen_buffers(2, &mut names);
    c.bind_buffer(gl::ARRAY_BUFFER, names[0]);
    c.buffer_data(gl::ARRAY_BUFFER, 144, Pointer::NULL, gl::STATIC_DRAW);
    if let Some(m) = c.map_buffer(gl::ARRAY_BUFFER, gl::WRITE_ONLY) {
        m.copy_from_slice(&f32_bytes(&positions));
    }
    c.unmap_buffer(gl::ARRAY_BUFFER);
    c.vertex_pointer(3, gl::FLOAT, 0, 0usize);
    c.bind_buffer(gl::ARRAY_BUFFER, names[1]);
    c.buffer_data(gl::ARRAY_BUFFER, 144, &[0.25f32; 36], gl::DYNAMIC_DRAW);
    if let Some(m) = c.map_buffer(gl::ARRAY_BUFFER, gl::READ_WRITE) {
        // Red for the first two triangles, read back and written as it was elsewhere.
        for v in 0..6 {
            m[v * 12..v * 12 + 4].copy_from_slice(&1.0f32.to_ne_bytes());
        }
    }
    c.unmap_buffer(gl::ARRAY_BUFFER);
    if let Some(m) = c.map_buffer(gl::ARRAY_BUFFER, gl::READ_WRITE) {
        // Blue for vertices 7 and 10.
        for v in [7, 10] {
            m[v * 12 + 8..v * 12 + 12].copy_from_slice(&0.9f32.to_ne_bytes());
        }
    }
    c.unmap_buffer(gl::ARRAY_BUFFER);
    c.color_pointer(3, gl::FLOAT, 0, 0usize);
    c.bind_buffer(gl::ARRAY_BUFFER, 0);
    c.enable_client_state(gl::VERTEX_ARRAY);
    c.enable_client_state(gl::COLOR_ARRAY);
    c.draw_arrays(gl::TRIANGLES, 0, 12);
    // Mapped again and left mapped: a draw from it is refused.
    c.bind_buffer(gl::ARRAY_BUFFER, names[0]);
    if let Some(m) = c.map_buffer(gl::ARRAY_BUFFER, gl::READ_WRITE) {
        m[0] = 0xff;
    }
    c.draw_arrays(gl::TRIANGLES, 0, 3);
}

#[test]
fn recordings_carry_the_bytes_written_through_mappings() {
    let mut c = ctx();
    c.start_recording();
    mapped_program(&mut c);
    let calls = c.stop_recording();
    assert_eq!(c.get_error(), IO);
    // Each record holds the bytes from the first to the last that changed, no more: the
    // positions end in a zero z that was zero already (140 of 144 bytes); 0.25 → 1.0 first
    // changes the high byte of the first red (offset 3, up to the sixth red's last byte: 61
    // bytes); the third mapping changed vertices 7 and 10's blue only (92 ..= 131).
    let unmaps: Vec<_> = calls
        .iter()
        .filter_map(|call| match call {
            Call::UnmapBuffer(_, w) => Some((w.0, w.1.len())),
            _ => None,
        })
        .collect();
    assert_eq!(unmaps, vec![(0, 140), (3, 61), (92, 40)]);
    let image = c.to_image();
    let lit = image.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count();
    assert!(lit > 500, "the program draws only {lit} pixels");
    // Replayed on a fresh context, and through the text format: the same pixels and errors.
    let mut again = ctx();
    again.replay(&calls);
    assert_eq!(again.get_error(), IO);
    assert_eq!(again.to_image(), image);
    let mut text = Vec::new();
    if let Err(e) = fixedgl::recording::write_recording(&calls, &mut text) {
        panic!("write: {e}");
    }
    let read = match fixedgl::recording::read_recording(&text[..]) {
        Ok(r) => r,
        Err(e) => panic!("read: {e}"),
    };
    assert_eq!(read, calls);
}

#[cfg(feature = "gl")]
mod on_gl {
    use super::*;
    use fixedgl::compare::compare;
    use fixedgl::glbackend::GlBackend;

    fn driver_param(gl: &GlBackend, target: u32, pname: u32) -> i32 {
        let mut v = [-7];
        // SAFETY: GetBufferParameteriv writes one integer; this thread's backend is current.
        unsafe { gl.raw().GetBufferParameteriv(target, pname, v.as_mut_ptr()) };
        v[0]
    }

    #[test]
    fn recorded_mappings_replay_on_the_driver() {
        let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
            return;
        };
        let mut c = ctx();
        c.start_recording();
        mapped_program(&mut c);
        let calls = c.stop_recording();
        gl.replay(&calls);
        // The draw from the buffer left mapped: the spec's error, raised by the backend (Mesa
        // would let llvmpipe read the store).
        assert_eq!(gl.get_error(), IO);
        assert_eq!(c.get_error(), IO);
        let cmp = compare(&c.to_image(), &gl.read_image(), 1);
        assert_eq!(cmp.differing_pixels, 0, "max {:?}", cmp.max_diff);
        assert_eq!(
            driver_param(&gl, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED),
            param(&mut c, gl::ARRAY_BUFFER, gl::BUFFER_MAPPED)
        );
    }

    /// Every row's recorded calls on the driver: the same error, and the same BUFFER_MAPPED and
    /// BUFFER_ACCESS after it.
    #[test]
    fn rows_agree_with_the_driver() {
        for &(name, at, setup, call, error) in ROWS {
            let Some(mut gl) = crate::common::test_backend(SIZE, SIZE) else {
                return;
            };
            let mut c = ctx();
            c.start_recording();
            setup(&mut c);
            if at == At::InsideBegin {
                c.begin(gl::POINTS);
            }
            call(&mut c);
            if at == At::InsideBegin {
                c.end();
            }
            let calls = c.stop_recording();
            assert_eq!(c.get_error(), error, "{name}");
            // Queries are not recorded: those rows are the driver's own calls.
            let query = name.starts_with("pointer") || name.starts_with("get sub data");
            gl.replay(&calls);
            if query {
                let mut out = [0u8; 4];
                let mut p: *mut std::ffi::c_void = std::ptr::null_mut();
                // The binding takes `*const *mut`; the driver writes `p`.
                let pp = std::ptr::addr_of_mut!(p).cast_const();
                // SAFETY: each call writes what its buffer holds (4 bytes; one pointer).
                unsafe {
                    let raw = gl.raw();
                    if at == At::InsideBegin {
                        raw.Begin(gl::POINTS);
                    }
                    match name {
                        "get sub data: mapped" => {
                            raw.GetBufferSubData(gl::ARRAY_BUFFER, 0, 4, out.as_mut_ptr().cast())
                        }
                        "pointer: bad pname" | "pointer: bad pname, none bound" => {
                            raw.GetBufferPointerv(gl::ARRAY_BUFFER, gl::BUFFER_SIZE, pp)
                        }
                        "pointer: bad target" => {
                            raw.GetBufferPointerv(gl::TEXTURE_2D, gl::BUFFER_MAP_POINTER, pp)
                        }
                        _ => raw.GetBufferPointerv(gl::ARRAY_BUFFER, gl::BUFFER_MAP_POINTER, pp),
                    }
                    if at == At::InsideBegin {
                        raw.End();
                    }
                }
            }
            assert_eq!(gl.get_error(), error, "{name} on the driver");
            for target in [gl::ARRAY_BUFFER, gl::ELEMENT_ARRAY_BUFFER] {
                let mut bound = [0];
                c.get_integerv(
                    if target == gl::ARRAY_BUFFER {
                        gl::ARRAY_BUFFER_BINDING
                    } else {
                        gl::ELEMENT_ARRAY_BUFFER_BINDING
                    },
                    &mut bound,
                );
                if bound[0] == 0 {
                    continue;
                }
                for pname in [gl::BUFFER_MAPPED, gl::BUFFER_ACCESS, gl::BUFFER_SIZE] {
                    assert_eq!(
                        driver_param(&gl, target, pname),
                        param(&mut c, target, pname),
                        "{name}: {pname:#x} of {target:#x}"
                    );
                }
            }
        }
    }
}
