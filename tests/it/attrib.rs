//! Attribute stacks (GL 2.1 §6.1.14): each group PushAttrib saves is restored by PopAttrib, groups
//! not pushed are left alone, the matrix stacks are in no group, and the stacks are 16 deep.

#[cfg(feature = "gl")]
use fixedgl::Call;
use fixedgl::{gl, Context};

fn ctx() -> Context {
    Context::new(16, 16).expect("context")
}

/// Every value of `pname`, as floats (unused slots NaN).
fn get(c: &mut Context, pname: u32) -> Vec<f32> {
    let mut v = [f32::NAN; 16];
    c.get_floatv(pname, &mut v);
    assert_eq!(c.get_error(), gl::NO_ERROR, "query {pname:#x}");
    v.iter()
        .map(|x| if x.is_nan() { -12345.0 } else { *x })
        .collect()
}

type Setter = fn(&mut Context);

/// (group, a call that changes state of that group, the query that shows it). The values
/// set are all different from GL's initial ones (tables 6.5 to 6.36).
const ROWS: &[(u32, Setter, u32)] = &[
    (
        gl::CURRENT_BIT,
        |c| c.color4f(0.25, 0.5, 0.75, 1.0),
        gl::CURRENT_COLOR,
    ),
    (
        gl::CURRENT_BIT,
        |c| c.normal3f(1.0, 0.0, 0.0),
        gl::CURRENT_NORMAL,
    ),
    (
        gl::CURRENT_BIT,
        |c| c.tex_coord2f(0.5, 0.25),
        gl::CURRENT_TEXTURE_COORDS,
    ),
    (
        gl::CURRENT_BIT,
        |c| c.window_pos2f(3.0, 4.0),
        gl::CURRENT_RASTER_POSITION,
    ),
    (
        gl::CURRENT_BIT,
        |c| {
            c.color4f(0.5, 0.25, 1.0, 1.0);
            c.raster_pos2f(0.5, 0.5);
        },
        gl::CURRENT_RASTER_COLOR,
    ),
    (
        gl::CURRENT_BIT,
        |c| c.raster_pos2f(5.0, 0.5),
        gl::CURRENT_RASTER_POSITION_VALID,
    ),
    (gl::PIXEL_MODE_BIT, |c| c.pixel_zoom(2.0, -1.0), gl::ZOOM_Y),
    (
        gl::PIXEL_MODE_BIT,
        |c| c.pixel_transferf(gl::GREEN_BIAS, 0.25),
        gl::GREEN_BIAS,
    ),
    (
        gl::PIXEL_MODE_BIT,
        |c| c.pixel_transferi(gl::MAP_STENCIL, 1),
        gl::MAP_STENCIL,
    ),
    (
        gl::PIXEL_MODE_BIT,
        |c| c.pixel_transferi(gl::INDEX_OFFSET, -3),
        gl::INDEX_OFFSET,
    ),
    (gl::ENABLE_BIT, |c| c.disable(gl::DITHER), gl::DITHER),
    (gl::ENABLE_BIT, |c| c.enable(gl::LIGHT3), gl::LIGHT3),
    (
        gl::TRANSFORM_BIT,
        |c| c.matrix_mode(gl::PROJECTION),
        gl::MATRIX_MODE,
    ),
    (
        gl::TRANSFORM_BIT,
        |c| c.enable(gl::NORMALIZE),
        gl::NORMALIZE,
    ),
    (
        gl::TRANSFORM_BIT,
        |c| c.enable(gl::RESCALE_NORMAL),
        gl::RESCALE_NORMAL,
    ),
    (
        gl::TRANSFORM_BIT,
        |c| c.enable(gl::CLIP_PLANE2),
        gl::CLIP_PLANE2,
    ),
    (gl::VIEWPORT_BIT, |c| c.viewport(1, 2, 3, 4), gl::VIEWPORT),
    (
        gl::VIEWPORT_BIT,
        |c| c.depth_range(0.25, 0.5),
        gl::DEPTH_RANGE,
    ),
    (
        gl::LIGHTING_BIT,
        |c| c.shade_model(gl::FLAT),
        gl::SHADE_MODEL,
    ),
    (gl::LIGHTING_BIT, |c| c.enable(gl::LIGHTING), gl::LIGHTING),
    (gl::LIGHTING_BIT, |c| c.enable(gl::LIGHT1), gl::LIGHT1),
    (
        gl::LIGHTING_BIT,
        |c| c.enable(gl::COLOR_MATERIAL),
        gl::COLOR_MATERIAL,
    ),
    (
        gl::LIGHTING_BIT,
        |c| c.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1),
        gl::LIGHT_MODEL_TWO_SIDE,
    ),
    (
        gl::LIGHTING_BIT,
        |c| c.color_material(gl::FRONT, gl::EMISSION),
        gl::COLOR_MATERIAL_PARAMETER,
    ),
    (gl::POINT_BIT, |c| c.point_size(4.0), gl::POINT_SIZE),
    (gl::LINE_BIT, |c| c.line_width(3.0), gl::LINE_WIDTH),
    (
        gl::LINE_BIT,
        |c| c.enable(gl::LINE_STIPPLE),
        gl::LINE_STIPPLE,
    ),
    (
        gl::LINE_BIT,
        |c| c.line_stipple(3, 0x00FF),
        gl::LINE_STIPPLE_PATTERN,
    ),
    (
        gl::LINE_BIT,
        |c| c.line_stipple(3, 0x00FF),
        gl::LINE_STIPPLE_REPEAT,
    ),
    (
        gl::POLYGON_BIT,
        |c| c.enable(gl::POLYGON_STIPPLE),
        gl::POLYGON_STIPPLE,
    ),
    (
        gl::POLYGON_BIT,
        |c| c.cull_face(gl::FRONT),
        gl::CULL_FACE_MODE,
    ),
    (gl::POLYGON_BIT, |c| c.front_face(gl::CW), gl::FRONT_FACE),
    (
        gl::POLYGON_BIT,
        |c| c.polygon_mode(gl::FRONT_AND_BACK, gl::LINE),
        gl::POLYGON_MODE,
    ),
    (
        gl::POLYGON_BIT,
        |c| c.polygon_offset(1.0, 2.0),
        gl::POLYGON_OFFSET_UNITS,
    ),
    (gl::POLYGON_BIT, |c| c.enable(gl::CULL_FACE), gl::CULL_FACE),
    (
        gl::POLYGON_BIT,
        |c| c.enable(gl::POLYGON_OFFSET_FILL),
        gl::POLYGON_OFFSET_FILL,
    ),
    (
        gl::DEPTH_BUFFER_BIT,
        |c| c.depth_func(gl::ALWAYS),
        gl::DEPTH_FUNC,
    ),
    (
        gl::DEPTH_BUFFER_BIT,
        |c| c.depth_mask(false),
        gl::DEPTH_WRITEMASK,
    ),
    (
        gl::DEPTH_BUFFER_BIT,
        |c| c.clear_depth(0.5),
        gl::DEPTH_CLEAR_VALUE,
    ),
    (
        gl::DEPTH_BUFFER_BIT,
        |c| c.enable(gl::DEPTH_TEST),
        gl::DEPTH_TEST,
    ),
    (
        gl::COLOR_BUFFER_BIT,
        |c| c.clear_color(0.5, 0.25, 0.0, 1.0),
        gl::COLOR_CLEAR_VALUE,
    ),
    (
        gl::COLOR_BUFFER_BIT,
        |c| c.color_mask(false, true, false, true),
        gl::COLOR_WRITEMASK,
    ),
    (gl::COLOR_BUFFER_BIT, |c| c.enable(gl::BLEND), gl::BLEND),
    (
        gl::COLOR_BUFFER_BIT,
        |c| c.clear_index(3.75),
        gl::INDEX_CLEAR_VALUE,
    ),
    (
        gl::COLOR_BUFFER_BIT,
        |c| c.index_mask(5),
        gl::INDEX_WRITEMASK,
    ),
    (
        gl::COLOR_BUFFER_BIT,
        |c| c.enable(gl::ALPHA_TEST),
        gl::ALPHA_TEST,
    ),
    (gl::SCISSOR_BIT, |c| c.scissor(1, 1, 2, 2), gl::SCISSOR_BOX),
    (
        gl::SCISSOR_BIT,
        |c| c.enable(gl::SCISSOR_TEST),
        gl::SCISSOR_TEST,
    ),
    (
        gl::STENCIL_BUFFER_BIT,
        |c| c.clear_stencil(3),
        gl::STENCIL_CLEAR_VALUE,
    ),
    (
        gl::STENCIL_BUFFER_BIT,
        |c| c.enable(gl::STENCIL_TEST),
        gl::STENCIL_TEST,
    ),
    (gl::FOG_BIT, |c| c.enable(gl::FOG), gl::FOG),
    (
        gl::HINT_BIT,
        |c| c.hint(gl::FOG_HINT, gl::NICEST),
        gl::FOG_HINT,
    ),
    (
        gl::TEXTURE_BIT,
        |c| c.active_texture(gl::TEXTURE1),
        gl::ACTIVE_TEXTURE,
    ),
    (
        gl::TEXTURE_BIT,
        |c| c.enable(gl::TEXTURE_2D),
        gl::TEXTURE_2D,
    ),
    (gl::EVAL_BIT, |c| c.enable(gl::AUTO_NORMAL), gl::AUTO_NORMAL),
    (
        gl::MULTISAMPLE_BIT,
        |c| c.disable(gl::MULTISAMPLE),
        gl::MULTISAMPLE,
    ),
    (gl::LIST_BIT, |c| c.list_base(7), gl::LIST_BASE),
];

#[test]
fn pop_attrib_restores_every_group() {
    for &(bit, set, pname) in ROWS {
        for mask in [bit, gl::ALL_ATTRIB_BITS] {
            let mut c = ctx();
            let before = get(&mut c, pname);
            c.push_attrib(mask);
            set(&mut c);
            let changed = get(&mut c, pname);
            assert_ne!(before, changed, "{pname:#x}: the setter changes nothing");
            c.pop_attrib();
            assert_eq!(c.get_error(), gl::NO_ERROR);
            assert_eq!(
                get(&mut c, pname),
                before,
                "{bit:#x} did not restore {pname:#x}"
            );
        }
        // A group the state is not in leaves it as set (LIST_BIT holds only LIST_BASE).
        let other = if bit == gl::LIST_BIT {
            gl::CURRENT_BIT
        } else {
            gl::LIST_BIT
        };
        let mut c = ctx();
        c.push_attrib(other);
        set(&mut c);
        let changed = get(&mut c, pname);
        c.pop_attrib();
        assert_eq!(
            get(&mut c, pname),
            changed,
            "{other:#x} restored {pname:#x}"
        );
    }
}

#[test]
fn lights_materials_and_clip_planes_come_back_whole() {
    let mut c = ctx();
    let initial = c.state().clone();
    c.push_attrib(gl::LIGHTING_BIT | gl::TRANSFORM_BIT);
    c.lightfv(gl::LIGHT2, gl::POSITION, &[1.0, 2.0, 3.0, 1.0]);
    c.materialfv(gl::BACK, gl::SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    c.light_modelfv(gl::LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    c.clip_plane(gl::CLIP_PLANE1, &[1.0, 0.0, 0.0, 0.5]);
    assert_ne!(c.state(), &initial);
    c.pop_attrib();
    assert_eq!(c.state(), &initial);
}

#[test]
fn matrix_stacks_are_in_no_group() {
    let mut c = ctx();
    c.push_attrib(gl::ALL_ATTRIB_BITS);
    c.translatef(1.0, 2.0, 3.0);
    c.push_matrix();
    c.pop_attrib();
    let m = get(&mut c, gl::MODELVIEW_MATRIX);
    assert_eq!(&m[12..15], &[1.0, 2.0, 3.0]);
    assert_eq!(get(&mut c, gl::MODELVIEW_STACK_DEPTH)[0], 2.0);
}

#[test]
fn client_groups_are_restored() {
    let mut c = ctx();
    c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
    c.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
    c.pixel_storei(gl::PACK_ALIGNMENT, 8);
    c.pop_client_attrib();
    assert_eq!(get(&mut c, gl::UNPACK_ALIGNMENT)[0], 4.0);
    assert_eq!(get(&mut c, gl::PACK_ALIGNMENT)[0], 4.0);
    c.push_client_attrib(gl::CLIENT_VERTEX_ARRAY_BIT);
    c.client_active_texture(gl::TEXTURE2);
    c.pixel_storei(gl::PACK_ALIGNMENT, 8);
    c.pop_client_attrib();
    assert_eq!(
        get(&mut c, gl::CLIENT_ACTIVE_TEXTURE)[0],
        gl::TEXTURE0 as f32
    );
    assert_eq!(get(&mut c, gl::PACK_ALIGNMENT)[0], 8.0);
    // The server stack does not hold client state.
    c.push_attrib(gl::ALL_ATTRIB_BITS);
    c.pixel_storei(gl::PACK_ALIGNMENT, 2);
    c.pop_attrib();
    assert_eq!(get(&mut c, gl::PACK_ALIGNMENT)[0], 2.0);
}

#[test]
fn stacks_are_sixteen_deep() {
    let mut c = ctx();
    assert_eq!(get(&mut c, gl::MAX_ATTRIB_STACK_DEPTH)[0], 16.0);
    assert_eq!(get(&mut c, gl::MAX_CLIENT_ATTRIB_STACK_DEPTH)[0], 16.0);
    for depth in 1..=16 {
        c.push_attrib(gl::CURRENT_BIT);
        c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
        assert_eq!(get(&mut c, gl::ATTRIB_STACK_DEPTH)[0], depth as f32);
        assert_eq!(get(&mut c, gl::CLIENT_ATTRIB_STACK_DEPTH)[0], depth as f32);
    }
    c.push_attrib(gl::CURRENT_BIT);
    assert_eq!(c.get_error(), gl::STACK_OVERFLOW);
    c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
    assert_eq!(c.get_error(), gl::STACK_OVERFLOW);
    assert_eq!(get(&mut c, gl::ATTRIB_STACK_DEPTH)[0], 16.0);
    for _ in 0..16 {
        c.pop_attrib();
        c.pop_client_attrib();
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.pop_attrib();
    assert_eq!(c.get_error(), gl::STACK_UNDERFLOW);
    c.pop_client_attrib();
    assert_eq!(c.get_error(), gl::STACK_UNDERFLOW);
    // Between Begin and End: INVALID_OPERATION, nothing pushed.
    c.begin(gl::POINTS);
    c.push_attrib(gl::CURRENT_BIT);
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(get(&mut c, gl::ATTRIB_STACK_DEPTH)[0], 0.0);
}

#[test]
fn push_attrib_is_compiled_push_client_attrib_is_not() {
    let mut c = ctx();
    c.new_list(1, gl::COMPILE);
    c.push_attrib(gl::POINT_BIT);
    c.point_size(5.0);
    c.push_client_attrib(gl::CLIENT_PIXEL_STORE_BIT);
    c.pop_attrib();
    c.end_list();
    assert_eq!(get(&mut c, gl::ATTRIB_STACK_DEPTH)[0], 0.0);
    assert_eq!(get(&mut c, gl::CLIENT_ATTRIB_STACK_DEPTH)[0], 1.0);
    assert_eq!(c.list_calls(1).map(<[_]>::len), Some(3));
    c.call_list(1);
    assert_eq!(get(&mut c, gl::POINT_SIZE)[0], 1.0);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// The groups whose state arrived with the fragment operations, texturing and vertex arrays:
/// each row sets a value inside a push of its group and checks the pop restores the initial one,
/// and that popping an unrelated group does not.
#[test]
fn fragment_texture_and_array_state_is_saved_by_its_group() {
    type Set = fn(&mut Context);
    let rows: [(u32, bool, Set, u32, i32); 8] = [
        (
            gl::COLOR_BUFFER_BIT,
            false,
            |c| c.blend_func(gl::SRC_ALPHA, gl::ONE),
            gl::BLEND_SRC,
            gl::ONE as i32,
        ),
        (
            gl::COLOR_BUFFER_BIT,
            false,
            |c| c.alpha_func(gl::GREATER, 0.5),
            gl::ALPHA_TEST_FUNC,
            gl::ALWAYS as i32,
        ),
        (
            gl::COLOR_BUFFER_BIT,
            false,
            |c| c.logic_op(gl::XOR),
            gl::LOGIC_OP_MODE,
            gl::COPY as i32,
        ),
        (
            gl::STENCIL_BUFFER_BIT,
            false,
            |c| c.stencil_func(gl::EQUAL, 3, 0xF),
            gl::STENCIL_FUNC,
            gl::ALWAYS as i32,
        ),
        (
            gl::FOG_BIT,
            false,
            |c| c.fogi(gl::FOG_MODE, gl::LINEAR as i32),
            gl::FOG_MODE,
            gl::EXP as i32,
        ),
        (
            gl::TEXTURE_BIT,
            false,
            |c| c.bind_texture(gl::TEXTURE_2D, 7),
            gl::TEXTURE_BINDING_2D,
            0,
        ),
        (
            gl::CLIENT_VERTEX_ARRAY_BIT,
            true,
            |c| c.vertex_pointer(2, gl::FLOAT, 0, &[0.0f32; 8]),
            gl::VERTEX_ARRAY_SIZE,
            4,
        ),
        (
            gl::CLIENT_PIXEL_STORE_BIT,
            true,
            |c| c.pixel_storei(gl::UNPACK_ROW_LENGTH, 5),
            gl::UNPACK_ROW_LENGTH,
            0,
        ),
    ];
    for (bit, client, set, pname, initial) in rows {
        for (mask, restored) in [(bit, true), (gl::HINT_BIT, false)] {
            let mut c = Context::new(8, 8).expect("context");
            let client_group = client && restored;
            if client_group {
                c.push_client_attrib(mask);
            } else {
                c.push_attrib(mask);
            }
            set(&mut c);
            let mut v = [0];
            c.get_integerv(pname, &mut v);
            assert_ne!(v[0], initial, "{pname:#x}: the setter changed nothing");
            if client_group {
                c.pop_client_attrib();
            } else {
                c.pop_attrib();
            }
            c.get_integerv(pname, &mut v);
            assert_eq!(
                v[0] == initial,
                restored,
                "{pname:#x} after popping {mask:#x}"
            );
            assert_eq!(c.get_error(), gl::NO_ERROR, "{pname:#x}");
        }
    }
}

/// (pname, table 6.16's initial value, a different value set inside the push) for every
/// texture-object parameter whose attribute column says "texture" (GL 2.1 §6.1.14).
const TEX_PARAM_ROWS: &[(u32, &[f32], &[f32])] = &[
    (
        gl::TEXTURE_MIN_FILTER,
        &[gl::NEAREST_MIPMAP_LINEAR as f32],
        &[gl::LINEAR as f32],
    ),
    (
        gl::TEXTURE_MAG_FILTER,
        &[gl::LINEAR as f32],
        &[gl::NEAREST as f32],
    ),
    (
        gl::TEXTURE_WRAP_S,
        &[gl::REPEAT as f32],
        &[gl::CLAMP_TO_EDGE as f32],
    ),
    (
        gl::TEXTURE_WRAP_T,
        &[gl::REPEAT as f32],
        &[gl::MIRRORED_REPEAT as f32],
    ),
    (
        gl::TEXTURE_WRAP_R,
        &[gl::REPEAT as f32],
        &[gl::CLAMP as f32],
    ),
    (
        gl::TEXTURE_BORDER_COLOR,
        &[0.0, 0.0, 0.0, 0.0],
        &[0.25, 0.5, 0.75, 1.0],
    ),
    (gl::TEXTURE_PRIORITY, &[1.0], &[0.5]),
    (gl::TEXTURE_MIN_LOD, &[-1000.0], &[-2.0]),
    (gl::TEXTURE_MAX_LOD, &[1000.0], &[3.0]),
    (gl::TEXTURE_BASE_LEVEL, &[0.0], &[1.0]),
    (gl::TEXTURE_MAX_LEVEL, &[1000.0], &[4.0]),
    (gl::GENERATE_MIPMAP, &[0.0], &[1.0]),
    (
        gl::TEXTURE_COMPARE_MODE,
        &[gl::NONE as f32],
        &[gl::COMPARE_R_TO_TEXTURE as f32],
    ),
    (
        gl::TEXTURE_COMPARE_FUNC,
        &[gl::LEQUAL as f32],
        &[gl::GREATER as f32],
    ),
    (
        gl::DEPTH_TEXTURE_MODE,
        &[gl::LUMINANCE as f32],
        &[gl::ALPHA as f32],
    ),
];

/// The first `n` values of the bound 2D texture's `pname`.
fn tex_param(c: &mut Context, pname: u32, n: usize) -> Vec<f32> {
    let mut v = [f32::NAN; 4];
    c.get_tex_parameterfv(gl::TEXTURE_2D, pname, &mut v);
    assert_eq!(c.get_error(), gl::NO_ERROR, "query {pname:#x}");
    v[..n].to_vec()
}

/// The calls of one row: texture 3 on unit 1, texture 0 (the default) on unit 0; the parameter
/// changed on both inside a push of `mask`, then popped; back on unit 1 at the end.
fn tex_param_row(c: &mut Context, mask: u32, pname: u32, set: &[f32]) {
    c.active_texture(gl::TEXTURE1);
    c.bind_texture(gl::TEXTURE_2D, 3);
    c.push_attrib(mask);
    c.tex_parameterfv(gl::TEXTURE_2D, pname, set);
    c.active_texture(gl::TEXTURE0);
    c.tex_parameterfv(gl::TEXTURE_2D, pname, set);
    c.pop_attrib();
    c.active_texture(gl::TEXTURE1);
}

#[test]
fn texture_bit_restores_the_bound_objects_parameters() {
    for &(pname, initial, set) in TEX_PARAM_ROWS {
        let mut c = ctx();
        tex_param_row(&mut c, gl::TEXTURE_BIT, pname, set);
        assert_eq!(c.get_error(), gl::NO_ERROR, "{pname:#x}");
        assert_eq!(
            tex_param(&mut c, pname, set.len()),
            initial,
            "{pname:#x} unit 1"
        );
        c.active_texture(gl::TEXTURE0);
        assert_eq!(
            tex_param(&mut c, pname, set.len()),
            initial,
            "{pname:#x} unit 0"
        );

        // Another group leaves the parameter as set.
        let mut c = ctx();
        tex_param_row(&mut c, gl::ENABLE_BIT, pname, set);
        assert_eq!(
            tex_param(&mut c, pname, set.len()),
            set,
            "{pname:#x} not pushed"
        );
    }
}

#[test]
fn texture_bit_keeps_the_images_and_other_objects() {
    let mut c = ctx();
    c.bind_texture(gl::TEXTURE_2D, 5);
    c.push_attrib(gl::TEXTURE_BIT);
    c.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        1,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&[10, 20, 30, 40]),
    );
    c.bind_texture(gl::TEXTURE_2D, 6);
    c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    c.pop_attrib();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    // Texture images are in no attribute group: the image specified inside the push stays.
    let mut px = [0u8; 4];
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [10, 20, 30, 40]);
    // Texture 6 was not bound at the push: its parameter stays.
    c.bind_texture(gl::TEXTURE_2D, 6);
    assert_eq!(
        tex_param(&mut c, gl::TEXTURE_MAG_FILTER, 1),
        [gl::NEAREST as f32]
    );
}

#[cfg(feature = "gl")]
#[test]
fn texture_bit_parameters_match_the_driver() {
    let Some(mut drv) = crate::common::test_backend(8, 8) else {
        return;
    };
    for &(pname, initial, set) in TEX_PARAM_ROWS {
        let mut c = ctx();
        c.start_recording();
        tex_param_row(&mut c, gl::TEXTURE_BIT, pname, set);
        drv.replay(&c.stop_recording());
        assert_eq!(drv.get_error(), gl::NO_ERROR, "{pname:#x}");
        let mut v = [f32::NAN; 4];
        // SAFETY: `v` has 4 slots, the most any of these pnames writes.
        unsafe {
            drv.raw()
                .GetTexParameterfv(gl::TEXTURE_2D, pname, v.as_mut_ptr())
        };
        assert_eq!(&v[..initial.len()], initial, "driver {pname:#x}");
        assert_eq!(
            tex_param(&mut c, pname, initial.len()),
            initial,
            "{pname:#x}"
        );
        // Leave the driver as a fresh context would be for the next row.
        drv.replay(&[
            Call::ActiveTexture(gl::TEXTURE0),
            Call::DeleteTextures(1, vec![3]),
        ]);
    }
}
