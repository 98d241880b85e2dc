//! The vertex-array and buffer-object examples of seed 004 ("CCI-36 OpenGL", ITA), ported call
//! for call from their Python (PyOpenGL + pyrr) to fixedgl's fixed-function equivalents.
//!
//! The seed uploads vertices and indices into a VBO and an EBO with `glGenBuffers` /
//! `glBindBuffer` / `glBufferData`, points at them with byte offsets and draws with
//! `glDrawElements`; here the generic `glVertexAttribPointer(0, ...)` of its shaders becomes
//! `glVertexPointer` (and location 1, the colour, `glColorPointer`), and the shader's
//! `projection * view * model` becomes the projection and modelview matrices, built with
//! `gluPerspective`, `gluLookAt`, `glScalef` and `glRotatef` in the order pyrr composes them.
//!
//! Design decision: the cube's vertex table is garbled in the OCR; it is rebuilt as the slides
//! describe it (24 vertices, four per face, one colour per face, position then colour
//! interleaved, indices `4k, 4k+1, 4k+2, 4k+2, 4k+3, 4k` as UNSIGNED_INT). The face colours
//! other than the front's red (the only one legible) are this port's choice.

use super::{Scene, LECTURE};
use crate::{gl, glu, Context, Pointer};

/// The two scenes, in listing order.
pub const SCENES: [Scene; 2] = [
    Scene {
        name: "rect-wire",
        summary: "Vertex arrays: buffer objects — a rectangle of two triangles from a VBO and UNSIGNED_BYTE EBO [0,1,3, 1,2,3], \
                  PolygonMode(FRONT_AND_BACK, LINE)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: rect_wire,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "cube-colors",
        summary: "Vertex arrays: interleaved arrays — a cube of 24 position+colour vertices in a VBO, UNSIGNED_INT \
                  EBO, scale 1.1, rotate -45 about x and y, gluLookAt + gluPerspective 45, depth test",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: cube_colors,
        animate: Some(cube_colors_at),
        config: super::DEFAULT_CONFIG,
    },
];

/// `rect-wire`: the rectangle of "Exemplo: Retângulo" as a wireframe.
pub fn rect_wire(gl: &mut Context) {
    // Passo 1: vertices and indices.
    #[rustfmt::skip]
    let vertices: [f32; 8] = [
         0.5,  0.5, // top right
         0.5, -0.5, // bottom right
        -0.5, -0.5, // bottom left
        -0.5,  0.5, // top left
    ];
    let indices: [u8; 6] = [0, 1, 3, 1, 2, 3];
    gl.clear_color(0.2, 0.3, 0.3, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT);
    // Passo 2: buffers.
    let mut vbo = [0];
    gl.gen_buffers(1, &mut vbo);
    gl.bind_buffer(gl::ARRAY_BUFFER, vbo[0]);
    gl.buffer_data(
        gl::ARRAY_BUFFER,
        size_of_val(&vertices) as isize,
        &vertices,
        gl::STATIC_DRAW,
    );
    let mut ebo = [0];
    gl.gen_buffers(1, &mut ebo);
    gl.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, ebo[0]);
    gl.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        size_of_val(&indices) as isize,
        &indices,
        gl::STATIC_DRAW,
    );
    // Passo 3: the position attribute: 2 floats, stride 2 * itemsize, offset None.
    gl.vertex_pointer(2, gl::FLOAT, 2 * 4, Pointer::NULL);
    gl.enable_client_state(gl::VERTEX_ARRAY);
    // Wireframe, then Passo 4: draw.
    gl.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    gl.color3f(1.0, 1.0, 1.0);
    gl.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_BYTE, Pointer::NULL);
}

/// The cube's 24 vertices: x, y, z, r, g, b; four per face.
#[rustfmt::skip]
pub const CUBE_VERTICES: [f32; 144] = [
    // front (z = +0.5): red
    -0.5, -0.5,  0.5,  1.0, 0.0, 0.0,
     0.5, -0.5,  0.5,  1.0, 0.0, 0.0,
     0.5,  0.5,  0.5,  1.0, 0.0, 0.0,
    -0.5,  0.5,  0.5,  1.0, 0.0, 0.0,
    // back (z = -0.5): green
    -0.5, -0.5, -0.5,  0.0, 1.0, 0.0,
     0.5, -0.5, -0.5,  0.0, 1.0, 0.0,
     0.5,  0.5, -0.5,  0.0, 1.0, 0.0,
    -0.5,  0.5, -0.5,  0.0, 1.0, 0.0,
    // left (x = -0.5): blue
    -0.5, -0.5, -0.5,  0.0, 0.0, 1.0,
    -0.5, -0.5,  0.5,  0.0, 0.0, 1.0,
    -0.5,  0.5,  0.5,  0.0, 0.0, 1.0,
    -0.5,  0.5, -0.5,  0.0, 0.0, 1.0,
    // right (x = +0.5): yellow
     0.5, -0.5, -0.5,  1.0, 1.0, 0.0,
     0.5, -0.5,  0.5,  1.0, 1.0, 0.0,
     0.5,  0.5,  0.5,  1.0, 1.0, 0.0,
     0.5,  0.5, -0.5,  1.0, 1.0, 0.0,
    // top (y = +0.5): magenta
    -0.5,  0.5, -0.5,  1.0, 0.0, 1.0,
     0.5,  0.5, -0.5,  1.0, 0.0, 1.0,
     0.5,  0.5,  0.5,  1.0, 0.0, 1.0,
    -0.5,  0.5,  0.5,  1.0, 0.0, 1.0,
    // bottom (y = -0.5): cyan
    -0.5, -0.5, -0.5,  0.0, 1.0, 1.0,
     0.5, -0.5, -0.5,  0.0, 1.0, 1.0,
     0.5, -0.5,  0.5,  0.0, 1.0, 1.0,
    -0.5, -0.5,  0.5,  0.0, 1.0, 1.0,
];

/// The cube's indices: two triangles per face.
#[rustfmt::skip]
pub const CUBE_INDICES: [u32; 36] = [
     0,  1,  2,   2,  3,  0,
     4,  5,  6,   6,  7,  4,
     8,  9, 10,  10, 11,  8,
    12, 13, 14,  14, 15, 12,
    16, 17, 18,  18, 19, 16,
    20, 21, 22,  22, 23, 20,
];

/// `cube-colors`: the coloured cube of "Exemplo: Cubo".
pub fn cube_colors(gl: &mut Context) {
    cube_colors_at(gl, 0.0);
}

/// `cube-colors` at `t` seconds: the cube turns 40 degrees a second about its y axis (`t = 0` is
/// the still scene).
pub fn cube_colors_at(gl: &mut Context, t: f32) {
    let (w, h) = gl.size();
    gl.clear_color(0.0, 0.1, 0.1, 1.0);
    gl.enable(gl::DEPTH_TEST);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    let mut vbo = [0];
    gl.gen_buffers(1, &mut vbo);
    gl.bind_buffer(gl::ARRAY_BUFFER, vbo[0]);
    gl.buffer_data(
        gl::ARRAY_BUFFER,
        size_of_val(&CUBE_VERTICES) as isize,
        &CUBE_VERTICES,
        gl::STATIC_DRAW,
    );
    let mut ebo = [0];
    gl.gen_buffers(1, &mut ebo);
    gl.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, ebo[0]);
    gl.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        size_of_val(&CUBE_INDICES) as isize,
        &CUBE_INDICES,
        gl::STATIC_DRAW,
    );
    // Location 0 (position) and 1 (colour): stride 6 floats, colour 12 bytes in.
    gl.vertex_pointer(3, gl::FLOAT, 24, 0usize);
    gl.enable_client_state(gl::VERTEX_ARRAY);
    gl.color_pointer(3, gl::FLOAT, 24, 12usize);
    gl.enable_client_state(gl::COLOR_ARRAY);
    // Passo 6: projection (fovy 45, width/height, 0.1, 100).
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, f64::from(w) / f64::from(h), 0.1, 100.0);
    // Passo 5 and 4: view, then model = scale · rot_x(-45) · rot_y(-45).
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.scalef(1.1, 1.1, 1.1);
    gl.rotatef(-45.0, 1.0, 0.0, 0.0);
    gl.rotatef(-45.0 - 40.0 * t, 0.0, 1.0, 0.0);
    gl.draw_elements(gl::TRIANGLES, 36, gl::UNSIGNED_INT, 0usize);
}
