//! Scenes for the per-fragment operations (GL 2.1 §3.10 fog, §4.1 alpha, stencil, blending):
//! `fog` (LINEAR, EXP and EXP2 side by side), `blending` (translucent layers sorted back to
//! front), and the two effects of seed 001 ("Renderização de cena com reflexão e/ou sombra"),
//! done the fixed-function way: `planar-shadow` (objects flattened onto the floor by a
//! projection matrix, the stencil buffer keeping each floor pixel from being darkened twice)
//! and `planar-reflection` (the objects mirrored in the floor, confined to it by the stencil
//! buffer, the floor blended over the mirror image).
//!
//! Design decision: every object is built here from immediate-mode quads (a cube, a latitude-
//! longitude sphere, a checkerboard floor) so the scenes depend on nothing but the GL entry
//! points they exercise.

use crate::gl::*;
use crate::{glu, Context};

use super::{Scene, LECTURE};

/// A unit cube centred on the origin, one normal per face (GL_QUADS, counter-clockwise).
fn cube(gl: &mut Context, half: f32) {
    const FACES: [([f32; 3], [[f32; 3]; 4]); 6] = [
        (
            [0.0, 0.0, 1.0],
            [[-1., -1., 1.], [1., -1., 1.], [1., 1., 1.], [-1., 1., 1.]],
        ),
        (
            [0.0, 0.0, -1.0],
            [
                [1., -1., -1.],
                [-1., -1., -1.],
                [-1., 1., -1.],
                [1., 1., -1.],
            ],
        ),
        (
            [1.0, 0.0, 0.0],
            [[1., -1., 1.], [1., -1., -1.], [1., 1., -1.], [1., 1., 1.]],
        ),
        (
            [-1.0, 0.0, 0.0],
            [
                [-1., -1., -1.],
                [-1., -1., 1.],
                [-1., 1., 1.],
                [-1., 1., -1.],
            ],
        ),
        (
            [0.0, 1.0, 0.0],
            [[-1., 1., 1.], [1., 1., 1.], [1., 1., -1.], [-1., 1., -1.]],
        ),
        (
            [0.0, -1.0, 0.0],
            [
                [-1., -1., -1.],
                [1., -1., -1.],
                [1., -1., 1.],
                [-1., -1., 1.],
            ],
        ),
    ];
    gl.begin(QUADS);
    for (n, vs) in FACES {
        gl.normal3fv(&n);
        for v in vs {
            gl.vertex3f(v[0] * half, v[1] * half, v[2] * half);
        }
    }
    gl.end();
}

/// A sphere of radius `r` centred on the origin: `stacks` quad strips of `slices` quads, with
/// the unit normal at each vertex.
fn sphere(gl: &mut Context, r: f32, slices: u32, stacks: u32) {
    let pi = std::f32::consts::PI;
    let point = |i: u32, j: u32| {
        let phi = pi * i as f32 / stacks as f32 - pi / 2.0;
        let theta = 2.0 * pi * j as f32 / slices as f32;
        [phi.cos() * theta.cos(), phi.sin(), -phi.cos() * theta.sin()]
    };
    for i in 0..stacks {
        gl.begin(QUAD_STRIP);
        for j in 0..=slices {
            for k in [i + 1, i] {
                let p = point(k, j);
                gl.normal3fv(&p);
                gl.vertex3f(p[0] * r, p[1] * r, p[2] * r);
            }
        }
        gl.end();
    }
}

/// A checkerboard floor in the plane y = 0 over [-size, size]², `n` x `n` squares, normal +y,
/// the two colours' alpha `alpha`.
fn floor(gl: &mut Context, size: f32, n: u32, alpha: f32) {
    let step = 2.0 * size / n as f32;
    gl.normal3f(0.0, 1.0, 0.0);
    gl.begin(QUADS);
    for i in 0..n {
        for j in 0..n {
            if (i + j) % 2 == 0 {
                gl.color4f(0.85, 0.85, 0.8, alpha);
            } else {
                gl.color4f(0.35, 0.4, 0.5, alpha);
            }
            let (x, z) = (-size + j as f32 * step, -size + i as f32 * step);
            gl.vertex3f(x, 0.0, z + step);
            gl.vertex3f(x + step, 0.0, z + step);
            gl.vertex3f(x + step, 0.0, z);
            gl.vertex3f(x, 0.0, z);
        }
    }
    gl.end();
}

/// Lighting with LIGHT0 at `pos` and COLOR_MATERIAL tracking ambient and diffuse.
fn lights(gl: &mut Context, pos: [f32; 4]) {
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &pos);
    gl.lightfv(LIGHT0, DIFFUSE, &[0.9, 0.9, 0.9, 1.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.25, 0.25, 0.25, 1.0]);
    gl.enable(COLOR_MATERIAL);
    gl.color_material(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE);
    gl.materialfv(FRONT_AND_BACK, SPECULAR, &[0.4, 0.4, 0.4, 1.0]);
    gl.materialf(FRONT_AND_BACK, SHININESS, 24.0);
}

/// `fog`: three panels of the same avenue of cubes on a floor, fogged LINEAR (start 2, end 22),
/// EXP (density 0.09) and EXP2 (density 0.07), the clear colour the fog colour.
fn fog(gl: &mut Context) {
    let fog_color = [0.62, 0.68, 0.75, 1.0];
    gl.clear_color(fog_color[0], fog_color[1], fog_color[2], 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.shade_model(SMOOTH);
    gl.enable(FOG);
    gl.fogfv(FOG_COLOR, &fog_color);
    gl.hint(FOG_HINT, NICEST);
    let (w, h) = gl.size();
    let (w, h) = (w as i32, h as i32);
    let modes = [(LINEAR, 0.0), (EXP, 0.09), (EXP2, 0.07)];
    for (k, (mode, density)) in modes.into_iter().enumerate() {
        let (x0, x1) = (k as i32 * w / 3, (k as i32 + 1) * w / 3);
        gl.viewport(x0, 0, x1 - x0, h);
        gl.fogi(FOG_MODE, mode as i32);
        gl.fogf(FOG_DENSITY, density);
        gl.fogf(FOG_START, 2.0);
        gl.fogf(FOG_END, 22.0);
        gl.matrix_mode(PROJECTION);
        gl.load_identity();
        glu::perspective(gl, 50.0, f64::from(x1 - x0) / f64::from(h), 0.5, 60.0);
        gl.matrix_mode(MODELVIEW);
        gl.load_identity();
        glu::look_at(gl, 0.0, 1.6, 4.0, 0.0, 0.6, -10.0, 0.0, 1.0, 0.0);
        lights(gl, [0.4, 1.0, 0.6, 0.0]);
        gl.push_matrix();
        gl.translatef(0.0, 0.0, -12.0);
        floor(gl, 16.0, 16, 1.0);
        gl.pop_matrix();
        for i in 0..9 {
            let z = 1.0 - 3.2 * i as f32;
            for side in [-1.0f32, 1.0] {
                gl.push_matrix();
                gl.translatef(1.6 * side, 0.5, z);
                gl.rotatef(20.0 * i as f32, 0.0, 1.0, 0.0);
                if side < 0.0 {
                    gl.color3f(0.85, 0.3, 0.2);
                } else {
                    gl.color3f(0.25, 0.55, 0.85);
                }
                cube(gl, 0.5);
                gl.pop_matrix();
            }
        }
        gl.disable(LIGHTING);
    }
}

/// `blending`: an opaque sphere and floor, then five translucent coloured panels drawn back to
/// front (sorted by eye depth, as the lecture teaches) with SRC_ALPHA / ONE_MINUS_SRC_ALPHA,
/// depth test on and depth writes off; a last additive panel (ONE, ONE) and one weighted by
/// the constant colour (CONSTANT_ALPHA).
fn blending(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, 1.0, 1.0, 30.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 2.5, 3.0, 7.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
    lights(gl, [2.0, 5.0, 4.0, 1.0]);
    floor(gl, 4.0, 8, 1.0);
    gl.push_matrix();
    gl.translatef(0.0, 1.0, -1.5);
    gl.color3f(0.9, 0.75, 0.2);
    sphere(gl, 1.0, 32, 16);
    gl.pop_matrix();
    // Translucent panels: (centre z, colour with alpha). Eye depth grows with -z here, so
    // back to front is increasing z.
    let mut panels = [
        (0.6f32, [0.2f32, 0.8, 0.3, 0.5]),
        (-2.6, [0.9, 0.2, 0.2, 0.6]),
        (1.8, [0.2, 0.4, 0.95, 0.4]),
        (-0.8, [0.9, 0.9, 0.2, 0.35]),
        (2.8, [0.8, 0.3, 0.9, 0.55]),
    ];
    panels.sort_by(|a, b| a.0.total_cmp(&b.0));
    gl.disable(LIGHTING);
    gl.enable(BLEND);
    gl.blend_func(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
    gl.depth_mask(false);
    for (k, (z, c)) in panels.iter().enumerate() {
        let x = -1.6 + 0.8 * k as f32;
        gl.color4fv(c);
        gl.begin(QUADS);
        gl.vertex3f(x - 1.0, 0.1, *z);
        gl.vertex3f(x + 1.0, 0.1, *z);
        gl.vertex3f(x + 1.0, 2.3, *z);
        gl.vertex3f(x - 1.0, 2.3, *z);
        gl.end();
    }
    // Additive glow in front, then a panel weighted by the constant alpha.
    gl.blend_func(ONE, ONE);
    gl.color4f(0.25, 0.1, 0.05, 1.0);
    gl.begin(TRIANGLES);
    gl.vertex3f(-2.5, 2.0, 3.2);
    gl.vertex3f(-0.5, 2.0, 3.2);
    gl.vertex3f(-1.5, 3.2, 3.2);
    gl.end();
    gl.blend_color(0.0, 0.0, 0.0, 0.3);
    gl.blend_func(CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA);
    gl.color4f(1.0, 1.0, 1.0, 1.0);
    gl.begin(TRIANGLES);
    gl.vertex3f(0.5, 2.0, 3.3);
    gl.vertex3f(2.5, 2.0, 3.3);
    gl.vertex3f(1.5, 3.2, 3.3);
    gl.end();
    gl.depth_mask(true);
    gl.disable(BLEND);
}

/// The light of the shadow and reflection scenes (positional, above and to the side).
const LIGHT: [f32; 4] = [2.5, 6.0, 2.0, 1.0];

/// The objects standing on the floor of the shadow and reflection scenes.
fn objects(gl: &mut Context, shadow: bool) {
    let col = |gl: &mut Context, c: [f32; 3]| {
        if !shadow {
            gl.color3fv(&c);
        }
    };
    gl.push_matrix();
    gl.translatef(-1.2, 1.1, 0.3);
    gl.rotatef(30.0, 0.0, 1.0, 0.0);
    gl.rotatef(20.0, 1.0, 0.0, 0.0);
    col(gl, [0.85, 0.3, 0.25]);
    cube(gl, 0.6);
    gl.pop_matrix();
    gl.push_matrix();
    gl.translatef(1.0, 1.3, -0.6);
    col(gl, [0.3, 0.6, 0.9]);
    sphere(gl, 0.75, 32, 16);
    gl.pop_matrix();
    gl.push_matrix();
    gl.translatef(0.4, 0.45, 1.5);
    gl.rotatef(-25.0, 0.0, 1.0, 0.0);
    col(gl, [0.4, 0.8, 0.35]);
    cube(gl, 0.35);
    gl.pop_matrix();
}

/// The matrix that projects points onto the plane `p` (a·x + b·y + c·z + d = 0) away from the
/// light `l` (homogeneous): `(p·l)·I − l·pᵀ`, column-major.
fn shadow_matrix(p: [f32; 4], l: [f32; 4]) -> [f32; 16] {
    let dot = p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3] * l[3];
    let mut m = [0.0f32; 16];
    for col in 0..4 {
        for row in 0..4 {
            let id = if row == col { dot } else { 0.0 };
            m[col * 4 + row] = id - l[row] * p[col];
        }
    }
    m
}

/// Camera of the shadow and reflection scenes.
fn camera(gl: &mut Context) {
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, 1.0, 1.0, 40.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 4.5, 8.0, 0.0, 0.4, 0.0, 0.0, 1.0, 0.0);
}

/// `planar-shadow`: the floor marks its pixels 1 in the stencil buffer; the objects, flattened
/// onto y = 0 by the shadow matrix, are drawn black at alpha 0.5 where the stencil is 1 and
/// reset it to 0 (StencilOp ZERO), so overlapping shadow polygons darken each pixel once; then
/// the lit objects.
fn planar_shadow(gl: &mut Context) {
    gl.clear_color(0.55, 0.65, 0.8, 1.0);
    gl.clear_stencil(0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.enable(CULL_FACE);
    camera(gl);
    lights(gl, LIGHT);
    // Floor, writing 1 into the stencil buffer.
    gl.enable(STENCIL_TEST);
    gl.stencil_func(ALWAYS, 1, 0xFF);
    gl.stencil_op(KEEP, KEEP, REPLACE);
    floor(gl, 4.0, 8, 1.0);
    // Shadows: on the floor only, each pixel once, no depth test (coplanar with the floor).
    gl.stencil_func(EQUAL, 1, 0xFF);
    gl.stencil_op(KEEP, KEEP, ZERO);
    gl.disable(LIGHTING);
    gl.disable(DEPTH_TEST);
    gl.enable(BLEND);
    gl.blend_func(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
    gl.color4f(0.0, 0.0, 0.0, 0.5);
    gl.push_matrix();
    gl.mult_matrixf(&shadow_matrix([0.0, 1.0, 0.0, 0.0], LIGHT));
    // The flattened objects' winding is not meaningful: draw both faces.
    gl.disable(CULL_FACE);
    objects(gl, true);
    gl.pop_matrix();
    gl.disable(BLEND);
    gl.disable(STENCIL_TEST);
    // The objects themselves.
    gl.enable(CULL_FACE);
    gl.enable(DEPTH_TEST);
    gl.enable(LIGHTING);
    objects(gl, false);
}

/// `planar-reflection`: the floor marks its pixels in the stencil buffer without drawing; the
/// objects mirrored by Scale(1, −1, 1) (light re-specified under the mirror, FrontFace CW) are
/// drawn where the stencil is 1; the floor is blended over them at alpha 0.55; then the objects.
fn planar_reflection(gl: &mut Context) {
    gl.clear_color(0.2, 0.22, 0.28, 1.0);
    gl.clear_stencil(0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.enable(CULL_FACE);
    camera(gl);
    // The mirror's pixels: stencil 1, no colour or depth.
    gl.enable(STENCIL_TEST);
    gl.stencil_func(ALWAYS, 1, 0xFF);
    gl.stencil_op(KEEP, KEEP, REPLACE);
    gl.color_mask(false, false, false, false);
    gl.depth_mask(false);
    floor(gl, 3.0, 6, 1.0);
    gl.color_mask(true, true, true, true);
    gl.depth_mask(true);
    // The reflection, confined to the mirror.
    gl.stencil_func(EQUAL, 1, 0xFF);
    gl.stencil_op(KEEP, KEEP, KEEP);
    gl.push_matrix();
    gl.scalef(1.0, -1.0, 1.0);
    gl.front_face(CW);
    lights(gl, LIGHT);
    objects(gl, false);
    gl.front_face(CCW);
    gl.pop_matrix();
    gl.disable(STENCIL_TEST);
    // The floor over the reflection, lit from the real light.
    lights(gl, LIGHT);
    gl.enable(BLEND);
    gl.blend_func(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
    floor(gl, 3.0, 6, 0.55);
    gl.disable(BLEND);
    objects(gl, false);
}

/// The fragment-operation scenes, in registry order.
pub(super) const SCENES: [Scene; 4] = [
    Scene {
        name: "fog",
        summary: "Fog: linear and exponential fog — an avenue of cubes fogged LINEAR, EXP and EXP2 side by side (Fog, per-fragment |z_eye|)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: fog,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "blending",
        summary: "Blending: transparency — translucent panels sorted back to front over a lit sphere (BlendFunc SRC_ALPHA, ONE, CONSTANT_ALPHA; DepthMask)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: blending,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "planar-shadow",
        summary: "Shadows: planar projection — shadows projected onto the floor, stencil against double blending, blended darkening",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: planar_shadow,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "planar-reflection",
        summary: "Reflections: a planar mirror — objects mirrored in the floor, confined by the stencil buffer, floor blended over them",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: planar_reflection,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shadow_matrix_flattens_onto_the_floor_away_from_the_light() {
        // Light at (0, 4, 0, 1), floor y = 0: the point (1, 2, 0) lies halfway between the
        // light and the floor, so its shadow is at (2, 0, 0) (similar triangles: 1 · 4/2).
        let m = shadow_matrix([0.0, 1.0, 0.0, 0.0], [0.0, 4.0, 0.0, 1.0]);
        let p = [1.0f32, 2.0, 0.0, 1.0];
        let mut q = [0.0f32; 4];
        for (row, out) in q.iter_mut().enumerate() {
            *out = (0..4).map(|col| m[col * 4 + row] * p[col]).sum();
        }
        let w = q[3];
        assert_eq!([q[0] / w, q[1] / w, q[2] / w], [2.0, 0.0, 0.0]);
    }
}
