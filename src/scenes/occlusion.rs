//! `occlusion-query`: occlusion culling with GL 1.5 queries (GL 2.1 §4.1.7, §6.1.12), the way
//! lecture code does it: a wall is drawn, then for each of five objects behind or beside it a
//! proxy box is drawn with colour and depth writes off inside BeginQuery/EndQuery(SAMPLES_PASSED);
//! the object itself is drawn only if `GetQueryObjectuiv(QUERY_RESULT)` says samples passed.
//! Each result is shown: a label per object (its sample count, drawn or culled) and a bar as
//! long as the count.
//!
//! Design decision (the recording and the driver): the scene's control flow depends on a value
//! the CPU backend computes at record time. The recorded stream holds what the program did with
//! that value — the BeginQuery/EndQuery pairs, the draws it then chose, the labels and bars it
//! drew from the counts — not the branch itself (GetQueryObject is a query, not recorded). The
//! GL replay therefore cannot diverge: it makes the same queries on the driver and the same
//! draws. What it cannot do by itself is notice that the driver would have answered differently;
//! so the labels and bars draw each count into the picture (a different count on the driver
//! would have drawn a different picture only if the driver chose, so the comparison alone is not
//! enough), and the scene test asks the driver for each query's result after the replay and
//! asserts it equals the CPU's (`tests/it/scenes.rs`).

use super::{Scene, LECTURE};
use crate::{gl, glu, glut, Context};

/// Objects: x position, colour, and which solid.
const OBJECTS: [(f32, [f32; 4], u8); 5] = [
    (-3.4, [0.9, 0.3, 0.2, 1.0], 0),
    (-2.2, [0.2, 0.8, 0.3, 1.0], 1),
    (0.0, [0.3, 0.4, 0.9, 1.0], 2),
    (1.7, [0.9, 0.8, 0.2, 1.0], 0),
    (3.4, [0.8, 0.3, 0.9, 1.0], 1),
];

/// Half the side of each object's proxy box (the objects fit inside it).
const HALF: f32 = 0.75;

fn object(gl: &mut Context, kind: u8) {
    match kind {
        0 => glut::solid_sphere(gl, 0.7, 24, 16),
        1 => glut::solid_torus(gl, 0.22, 0.5, 16, 24),
        _ => glut::solid_teapot(gl, 0.55),
    }
}

/// The proxy: the object's bounding box, six quads.
fn proxy_box(gl: &mut Context) {
    let h = HALF;
    let faces: [[[f32; 3]; 4]; 6] = [
        [[-h, -h, h], [h, -h, h], [h, h, h], [-h, h, h]],
        [[h, -h, -h], [-h, -h, -h], [-h, h, -h], [h, h, -h]],
        [[-h, -h, -h], [-h, -h, h], [-h, h, h], [-h, h, -h]],
        [[h, -h, h], [h, -h, -h], [h, h, -h], [h, h, h]],
        [[-h, h, h], [h, h, h], [h, h, -h], [-h, h, -h]],
        [[-h, -h, -h], [h, -h, -h], [h, -h, h], [-h, -h, h]],
    ];
    gl.begin(gl::QUADS);
    for f in faces {
        for [x, y, z] in f {
            gl.vertex3f(x, y, z);
        }
    }
    gl.end();
}

/// The wall in front of the middle objects, and a floor.
fn wall_and_floor(gl: &mut Context) {
    gl.materialfv(
        gl::FRONT_AND_BACK,
        gl::AMBIENT_AND_DIFFUSE,
        &[0.6, 0.6, 0.55, 1.0],
    );
    gl.normal3f(0.0, 0.0, 1.0);
    gl.begin(gl::QUADS);
    gl.vertex3f(-2.3, -1.2, 1.0);
    gl.vertex3f(2.5, -1.2, 1.0);
    gl.vertex3f(2.5, 1.6, 1.0);
    gl.vertex3f(-2.3, 1.6, 1.0);
    gl.end();
    gl.materialfv(
        gl::FRONT_AND_BACK,
        gl::AMBIENT_AND_DIFFUSE,
        &[0.35, 0.3, 0.25, 1.0],
    );
    gl.normal3f(0.0, 1.0, 0.0);
    gl.begin(gl::QUADS);
    gl.vertex3f(-6.0, -1.2, 4.0);
    gl.vertex3f(6.0, -1.2, 4.0);
    gl.vertex3f(6.0, -1.2, -6.0);
    gl.vertex3f(-6.0, -1.2, -6.0);
    gl.end();
}

/// The scene: 640x480.
pub fn occlusion(gl: &mut Context) {
    let (w, h) = (640.0f32, 480.0f32);
    gl.clear_color(0.08, 0.1, 0.14, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.enable(gl::DEPTH_TEST);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, f64::from(w / h), 1.0, 30.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 1.5, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(gl::LIGHTING);
    gl.enable(gl::LIGHT0);
    gl.enable(gl::NORMALIZE);
    gl.lightfv(gl::LIGHT0, gl::POSITION, &[3.0, 5.0, 8.0, 1.0]);
    gl.materialfv(gl::FRONT_AND_BACK, gl::SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(gl::FRONT_AND_BACK, gl::SHININESS, 30.0);
    wall_and_floor(gl);

    let mut ids = [0u32; 5];
    gl.gen_queries(5, &mut ids);
    let mut counts = [0u32; 5];
    for (i, &(x, colour, kind)) in OBJECTS.iter().enumerate() {
        gl.push_matrix();
        gl.translatef(x, 0.0, -1.0);
        // The proxy: counted, not drawn.
        gl.color_mask(false, false, false, false);
        gl.depth_mask(false);
        gl.disable(gl::LIGHTING);
        gl.begin_query(gl::SAMPLES_PASSED, ids[i]);
        proxy_box(gl);
        gl.end_query(gl::SAMPLES_PASSED);
        gl.color_mask(true, true, true, true);
        gl.depth_mask(true);
        gl.enable(gl::LIGHTING);
        let mut n = [0u32];
        gl.get_query_objectuiv(ids[i], gl::QUERY_RESULT, &mut n);
        counts[i] = n[0];
        if n[0] > 0 {
            gl.materialfv(gl::FRONT_AND_BACK, gl::AMBIENT_AND_DIFFUSE, &colour);
            gl.rotatef(20.0 + 25.0 * i as f32, 0.3, 1.0, 0.1);
            object(gl, kind);
        }
        gl.pop_matrix();
    }
    gl.delete_queries(5, &ids);

    // The results: one label and one bar per object, in window coordinates.
    gl.disable(gl::LIGHTING);
    gl.disable(gl::DEPTH_TEST);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    for (i, (&(_, colour, kind), &n)) in OBJECTS.iter().zip(&counts).enumerate() {
        let y = h - 20.0 - 18.0 * i as f32;
        let name = ["sphere", "torus", "teapot"][usize::from(kind.min(2))];
        let text = if n > 0 {
            format!("{name} {}: {n} samples, drawn", i + 1)
        } else {
            format!("{name} {}: 0 samples, culled", i + 1)
        };
        gl.color3f(colour[0], colour[1], colour[2]);
        gl.raster_pos2f(10.5, y + 0.5);
        glut::bitmap_string(gl, glut::BITMAP_8_BY_13, &text);
        // A bar of one pixel per 64 samples.
        let len = (n as f32 / 64.0).floor().min(300.0);
        if len > 0.0 {
            gl.rectf(300.0, y, 300.0 + len, y + 10.0);
        }
    }
}

/// The occlusion-query scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "occlusion-query",
    summary: "Occlusion culling: five objects drawn only if their proxy box's SAMPLES_PASSED query says samples passed a wall's depth; counts shown as labels and bars (GenQueries, BeginQuery, EndQuery, GetQueryObjectuiv)",
    tolerance: LECTURE,
    default_size: (640, 480),
    draw: occlusion,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];
