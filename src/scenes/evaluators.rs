//! The `evaluators` scene (GL 2.1 §5.1): the Red Book's Bézier examples in four panels.
//!
//! - top left, *bezcurve*: the cubic of four control points drawn as a LINE_STRIP of
//!   `EvalCoord1f(i / 30)`, its control polygon and points; under it a second cubic by
//!   `MapGrid1f` + `EvalMesh1(LINE)` coloured along its length by a MAP1_COLOR_4 map;
//! - top right, *bezmesh*: the 4x4 patch lit, normals from AUTO_NORMAL, `EvalMesh2(FILL)` on a
//!   20x20 grid, compiled into a display list (the list keeps the points of compile time);
//! - bottom left, *bezsurf*: the same patch as `EvalMesh2(LINE)` with the grid points by
//!   `EvalMesh2(POINT)`, inside PushAttrib(EVAL_BIT)/PopAttrib;
//! - bottom right: a rational patch (MAP2_VERTEX_4, a half cylinder from conic arcs) lit with
//!   AUTO_NORMAL, textured by a MAP2_TEXTURE_COORD_2 map, drawn by `EvalPoint2` strips.

use crate::gl::*;
use crate::{glu, Context};

use super::{Scene, LECTURE};

/// The scenes of this module, for the registry.
pub const SCENES: [Scene; 1] = [Scene {
    name: "evaluators",
    summary: "Evaluators: Bézier curves and patches — the Red Book's bezcurve with its control polygon, a coloured \
              EvalMesh1 curve, the bezmesh patch lit with AUTO_NORMAL (EvalMesh2 FILL, in a display list), bezsurf's \
              wireframe (EvalMesh2 LINE/POINT) and a textured rational patch (Map1f/Map2f/MapGrid/EvalCoord/EvalPoint)",
    tolerance: LECTURE,
    default_size: (600, 600),
    draw: evaluators,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

/// bezcurve.c's control points.
const CURVE: [f32; 12] = [
    -4.0, -4.0, 0.0, -2.0, 4.0, 0.0, 2.0, -4.0, 0.0, 4.0, 4.0, 0.0,
];

/// bezsurf.c's and bezmesh.c's 4x4 control net, u along the inner index (stride 3, 12).
const PATCH: [f32; 48] = [
    -1.5, -1.5, 4.0, -0.5, -1.5, 2.0, 0.5, -1.5, -1.0, 1.5, -1.5, 2.0, //
    -1.5, -0.5, 1.0, -0.5, -0.5, 3.0, 0.5, -0.5, 0.0, 1.5, -0.5, -1.0, //
    -1.5, 0.5, 4.0, -0.5, 0.5, 0.0, 0.5, 0.5, 3.0, 1.5, 0.5, 4.0, //
    -1.5, 1.5, -2.0, -0.5, 1.5, -2.0, 0.5, 1.5, 0.0, 1.5, 1.5, -1.0,
];

fn evaluators(gl: &mut Context) {
    let (w, h) = gl.size();
    let (hw, hh) = ((w / 2) as i32, (h / 2) as i32);
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.shade_model(SMOOTH);

    gl.viewport(0, hh, hw, hh);
    curves(gl);
    gl.viewport(hw, hh, hw, hh);
    lit_patch(gl);
    gl.viewport(0, 0, hw, hh);
    wire_patch(gl);
    gl.viewport(hw, 0, hw, hh);
    rational_patch(gl);
}

/// An orthographic view of `-s..s` square.
fn ortho(gl: &mut Context, s: f64) {
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    gl.ortho(-s, s, -s, s, -10.0, 10.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
}

/// bezcurve, and an EvalMesh1 curve coloured by a MAP1_COLOR_4 map.
fn curves(gl: &mut Context) {
    ortho(gl, 5.5);
    gl.translatef(0.0, 1.0, 0.0);
    gl.scalef(1.0, 0.7, 1.0);
    gl.map1f(MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &CURVE);
    gl.enable(MAP1_VERTEX_3);
    gl.color3f(1.0, 1.0, 1.0);
    gl.begin(LINE_STRIP);
    for i in 0..=30 {
        gl.eval_coord1f(i as f32 / 30.0);
    }
    gl.end();
    // The control polygon and points.
    gl.color3f(0.4, 0.4, 0.5);
    gl.begin(LINE_STRIP);
    for p in CURVE.chunks(3) {
        gl.vertex3f(p[0], p[1], p[2]);
    }
    gl.end();
    gl.point_size(5.0);
    gl.color3f(1.0, 1.0, 0.0);
    gl.begin(POINTS);
    for p in CURVE.chunks(3) {
        gl.vertex3fv(&[p[0], p[1], p[2]]);
    }
    gl.end();

    // A second cubic on the domain 2..4 (doubles, a wider stride), red to blue along it.
    let pts: [f64; 16] = [
        -4.5, -5.5, 0.0, 9.0, -1.5, -3.0, 0.0, 9.0, 1.5, -8.0, 0.0, 9.0, 4.5, -6.0, 0.0, 9.0,
    ];
    gl.map1d(MAP1_VERTEX_3, 2.0, 4.0, 4, 4, &pts);
    let colors: [f32; 8] = [1.0, 0.2, 0.1, 1.0, 0.1, 0.4, 1.0, 1.0];
    gl.map1f(MAP1_COLOR_4, 2.0, 4.0, 4, 2, &colors);
    gl.enable(MAP1_COLOR_4);
    gl.line_width(3.0);
    gl.map_grid1f(24, 2.0, 4.0);
    gl.eval_mesh1(LINE, 0, 24);
    gl.point_size(3.0);
    gl.eval_mesh1(POINT, 0, 24);
    gl.disable(MAP1_COLOR_4);
    gl.disable(MAP1_VERTEX_3);
    gl.line_width(1.0);
    gl.point_size(1.0);
}

/// Perspective on the patch, rotated as bezmesh.c does.
fn patch_view(gl: &mut Context) {
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, 1.0, 1.0, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -12.0);
    gl.rotatef(85.0, 1.0, 1.0, 1.0);
}

/// bezmesh: lit, AUTO_NORMAL, EvalMesh2 FILL, compiled into a list.
fn lit_patch(gl: &mut Context) {
    patch_view(gl);
    gl.enable(DEPTH_TEST);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, AMBIENT, &[0.2, 0.2, 0.2, 1.0]);
    // Positional, in eye coordinates (set under the identity), as bezmesh.c's.
    gl.push_matrix();
    gl.load_identity();
    gl.lightfv(LIGHT0, POSITION, &[1.0, 2.0, 2.0, 1.0]);
    gl.pop_matrix();
    gl.materialfv(FRONT, DIFFUSE, &[0.3, 0.6, 0.9, 1.0]);
    gl.materialfv(BACK, DIFFUSE, &[0.9, 0.5, 0.2, 1.0]);
    gl.materialfv(FRONT_AND_BACK, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.materialf(FRONT_AND_BACK, SHININESS, 50.0);
    gl.light_modeli(LIGHT_MODEL_TWO_SIDE, 1);
    // EvalMesh2 FILL's strips wind clockwise in (u, v) while du x dv points along u x v: the
    // side the normals point out of is the clockwise one.
    gl.front_face(CW);
    gl.enable(AUTO_NORMAL);
    gl.enable(MAP2_VERTEX_3);
    gl.map_grid2f(20, 0.0, 1.0, 20, 0.0, 1.0);
    // The list copies the points now: the map changed after EndList does not reach it.
    gl.new_list(1, COMPILE);
    gl.map2f(MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &PATCH);
    gl.eval_mesh2(FILL, 0, 20, 0, 20);
    gl.end_list();
    gl.map2f(MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 12, 2, &PATCH);
    gl.call_list(1);
    gl.front_face(CCW);
    gl.disable(LIGHTING);
    gl.disable(AUTO_NORMAL);
    gl.light_modeli(LIGHT_MODEL_TWO_SIDE, 0);
}

/// bezsurf: the wireframe of the patch, and its grid points, under PushAttrib(EVAL_BIT).
fn wire_patch(gl: &mut Context) {
    patch_view(gl);
    gl.push_attrib(EVAL_BIT);
    gl.map2f(MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &PATCH);
    gl.enable(MAP2_VERTEX_3);
    gl.map_grid2d(8, 0.0, 1.0, 8, 0.0, 1.0);
    gl.color3f(0.9, 0.9, 0.9);
    gl.eval_mesh2(LINE, 0, 8, 0, 8);
    gl.map_grid2f(4, 0.0, 1.0, 4, 0.0, 1.0);
    gl.point_size(4.0);
    gl.color3f(1.0, 0.5, 0.1);
    gl.eval_mesh2(POINT, 0, 4, 0, 4);
    gl.point_size(1.0);
    gl.pop_attrib();
    // EVAL_BIT restored the enables and the grid: this draws nothing.
    gl.eval_mesh2(LINE, 0, 4, 0, 4);
}

/// A rational patch (MAP2_VERTEX_4): half a cylinder of radius 1 and height 2, two quarter
/// circles as conic arcs of weight 1/√2 along u, a straight line along v; lit with
/// AUTO_NORMAL, its texture coordinates from a MAP2_TEXTURE_COORD_2 map.
fn rational_patch(gl: &mut Context) {
    patch_view(gl);
    gl.load_identity();
    // Directional: a positional light meets Mesa's undivided eye position of a w != 1 vertex
    // (see docs/conformance.md).
    gl.lightfv(LIGHT0, POSITION, &[0.3, 0.5, 1.0, 0.0]);
    gl.translatef(0.0, -0.3, -6.0);
    gl.rotatef(-60.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    let r = std::f32::consts::FRAC_1_SQRT_2;
    let mut net = Vec::new();
    checker(gl);
    // u: (1,0) -> (1,1)w -> (0,1) -> (-1,1)w -> (-1,0), as two quadratics joined: one quartic
    // would not be a circle, so the u order is 3 and the patch spans one quarter; a second
    // map draws the other.
    for (arc, z0) in [
        ([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], -1.0),
        ([[0.0, 1.0], [-1.0, 1.0], [-1.0, 0.0]], -1.0),
    ] {
        net.clear();
        for (i, [x, y]) in arc.into_iter().enumerate() {
            let wgt = if i == 1 { r } else { 1.0 };
            for z in [z0, z0 + 2.0] {
                net.extend([x * wgt, y * wgt, z * wgt, wgt]);
            }
        }
        gl.map2f(MAP2_VERTEX_4, 0.0, 1.0, 8, 3, 0.0, 1.0, 4, 2, &net);
        gl.enable(MAP2_VERTEX_4);
        gl.enable(AUTO_NORMAL);
        gl.enable(NORMALIZE);
        let tex: [f32; 8] = [0.0, 0.0, 0.0, 2.0, 2.0, 0.0, 2.0, 2.0];
        gl.map2f(MAP2_TEXTURE_COORD_2, 0.0, 1.0, 4, 2, 0.0, 1.0, 2, 2, &tex);
        gl.enable(MAP2_TEXTURE_COORD_2);
        gl.enable(LIGHTING);
        gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.9, 0.8, 0.5, 1.0]);
        gl.materialfv(FRONT_AND_BACK, SPECULAR, &[0.3, 0.3, 0.3, 1.0]);
        gl.light_modeli(LIGHT_MODEL_TWO_SIDE, 1);
        gl.map_grid2f(12, 0.0, 1.0, 6, 0.0, 1.0);
        for j in 0..6 {
            gl.begin(QUAD_STRIP);
            for i in 0..=12 {
                gl.eval_point2(i, j);
                gl.eval_point2(i, j + 1);
            }
            gl.end();
        }
    }
    gl.disable(TEXTURE_2D);
    gl.disable(LIGHTING);
    gl.disable(MAP2_TEXTURE_COORD_2);
    gl.disable(MAP2_VERTEX_4);
}

/// An 8x8 black-and-white checker texture on TEXTURE_2D, MODULATE, NEAREST.
fn checker(gl: &mut Context) {
    let mut pixels = Vec::with_capacity(8 * 8 * 4);
    for y in 0..8 {
        for x in 0..8 {
            let v = if (x + y) % 2 == 0 { 255 } else { 90 };
            pixels.extend([v, v, v, 255u8]);
        }
    }
    let mut name = [0];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(TEXTURE_2D, name[0]);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST as i32);
    gl.tex_image_2d(
        TEXTURE_2D,
        0,
        RGBA as i32,
        8,
        8,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&pixels),
    );
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_2D);
}
