//! Scenes for display lists and the GLUT shapes: `display-list` (a ring of lit GLUT solids, each
//! object a display list, the ring itself one list calling the others through CallLists) and
//! `glut-shapes` (the five GLUT solids side by side, lit).
//!
//! Both draw through the front end only, so the recorded stream holds NewList/EndList/CallList
//! and the GL backend builds and runs the driver's own lists (GL 2.1 §5.4).

use crate::gl::*;
use crate::{glu, glut, Context};

use super::{Scene, LECTURE};

/// The scenes of this module, for the registry.
pub const SCENES: [Scene; 2] = [
    Scene {
        name: "display-list",
        summary: "Display lists: nested lists — a ring of eight lit GLUT solids, each a display list, the ring one list \
                  calling them through ListBase + CallLists (NewList/CallList/PushAttrib)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: display_list,
        animate: Some(display_list_at),
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "glut-shapes",
        summary: "Modelling: the GLUT solids — lit side by side: sphere, cube, cone, torus, teapot",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: glut_shapes,
        animate: Some(glut_shapes_at),
        config: super::DEFAULT_CONFIG,
    },
];

/// Camera, depth test, one white directional light and one dim positional light.
fn setup(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, 1.0, 1.0, 30.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 5.0, 12.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &[1.0, 2.0, 3.0, 0.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.enable(LIGHT1);
    gl.lightfv(LIGHT1, POSITION, &[-4.0, 1.0, 2.0, 1.0]);
    gl.lightfv(LIGHT1, DIFFUSE, &[0.3, 0.3, 0.5, 1.0]);
    gl.enable(NORMALIZE);
    gl.shade_model(SMOOTH);
}

/// Sets the front material: `rgb` for ambient and diffuse, white specular, shininess 40.
fn material(gl: &mut Context, rgb: [f32; 3]) {
    let [r, g, b] = rgb;
    gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &[r, g, b, 1.0]);
    gl.materialfv(FRONT, SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.materialf(FRONT, SHININESS, 40.0);
}

/// The colours of the ring's objects.
const COLOURS: [[f32; 3]; 8] = [
    [0.9, 0.2, 0.2],
    [0.9, 0.6, 0.1],
    [0.8, 0.8, 0.2],
    [0.2, 0.8, 0.3],
    [0.2, 0.7, 0.8],
    [0.2, 0.3, 0.9],
    [0.6, 0.3, 0.9],
    [0.9, 0.4, 0.7],
];

/// `display-list`: lists 1..=5 are the shapes (sphere, cube, cone, torus, teapot), lists
/// 11..=18 place and colour object k of the ring (PushAttrib/PushMatrix around a CallList), and
/// list 20 draws the ring with ListBase(11) and CallLists(UNSIGNED_BYTE, 0..8). Calling list 20
/// twice, the second time scaled down and raised, shows that the lists replay whole.
fn display_list(gl: &mut Context) {
    display_list_at(gl, 0.0);
}

/// `display-list` at `t` seconds: the whole picture turns 25 degrees a second about the vertical
/// axis under the fixed lights (`t = 0` is the still scene).
fn display_list_at(gl: &mut Context, t: f32) {
    setup(gl);
    if t != 0.0 {
        gl.rotatef(25.0 * t, 0.0, 1.0, 0.0);
    }
    let shapes = gl.gen_lists(5);
    gl.new_list(shapes, COMPILE);
    glut::solid_sphere(gl, 0.6, 24, 16);
    gl.end_list();
    gl.new_list(shapes + 1, COMPILE);
    glut::solid_cube(gl, 0.9);
    gl.end_list();
    gl.new_list(shapes + 2, COMPILE);
    gl.rotatef(-90.0, 1.0, 0.0, 0.0);
    glut::solid_cone(gl, 0.5, 1.0, 20, 6);
    gl.end_list();
    gl.new_list(shapes + 3, COMPILE);
    glut::solid_torus(gl, 0.18, 0.45, 16, 28);
    gl.end_list();
    gl.new_list(shapes + 4, COMPILE);
    glut::solid_teapot(gl, 0.5);
    gl.end_list();
    for (k, rgb) in COLOURS.iter().enumerate() {
        gl.new_list(11 + k as u32, COMPILE);
        gl.push_attrib(LIGHTING_BIT);
        gl.push_matrix();
        gl.rotatef(45.0 * k as f32, 0.0, 1.0, 0.0);
        gl.translatef(3.0, 0.0, 0.0);
        gl.rotatef(30.0 * k as f32, 1.0, 1.0, 0.0);
        material(gl, *rgb);
        gl.call_list(shapes + (k as u32 % 5));
        gl.pop_matrix();
        gl.pop_attrib();
        gl.end_list();
    }
    gl.new_list(20, COMPILE);
    gl.list_base(11);
    gl.call_lists(8, UNSIGNED_BYTE, &[0, 1, 2, 3, 4, 5, 6, 7]);
    gl.end_list();
    gl.call_list(20);
    gl.push_matrix();
    gl.translatef(0.0, 2.4, 0.0);
    gl.scalef(0.4, 0.4, 0.4);
    gl.call_list(20);
    gl.pop_matrix();
    // The centre piece, compiled and executed at once.
    gl.new_list(21, COMPILE_AND_EXECUTE);
    material(gl, [0.85, 0.85, 0.85]);
    glut::solid_teapot(gl, 0.9);
    gl.end_list();
}

/// `glut-shapes`: the five solids in a row of three and a row of two, each turned to show its
/// sides.
fn glut_shapes(gl: &mut Context) {
    glut_shapes_at(gl, 0.0);
}

/// `glut-shapes` at `t` seconds: each solid spins 45 degrees a second about its own vertical axis
/// (`t = 0` is the still scene).
fn glut_shapes_at(gl: &mut Context, t: f32) {
    setup(gl);
    let place = |gl: &mut Context, x: f32, y: f32| {
        gl.load_identity();
        glu::look_at(gl, 0.0, 0.0, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
        gl.translatef(x, y, 0.0);
        gl.rotatef(25.0, 1.0, 0.0, 0.0);
        gl.rotatef(-30.0 - 45.0 * t, 0.0, 1.0, 0.0);
    };
    place(gl, -2.3, 1.2);
    material(gl, COLOURS[0]);
    glut::solid_sphere(gl, 0.9, 32, 20);
    place(gl, 0.0, 1.2);
    material(gl, COLOURS[3]);
    glut::solid_cube(gl, 1.3);
    place(gl, 2.3, 1.2);
    gl.rotatef(-90.0, 1.0, 0.0, 0.0);
    material(gl, COLOURS[1]);
    glut::solid_cone(gl, 0.8, 1.5, 24, 8);
    place(gl, -1.2, -1.3);
    material(gl, COLOURS[5]);
    glut::solid_torus(gl, 0.3, 0.75, 20, 36);
    place(gl, 1.3, -1.3);
    material(gl, COLOURS[6]);
    glut::solid_teapot(gl, 0.8);
}
