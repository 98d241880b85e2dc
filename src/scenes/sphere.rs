//! The lectures' two spheres, lit: `sphere-subdivision` (seed 003 §6.6, a tetrahedron whose faces
//! are split recursively and pushed out to the unit sphere, gold material, §6.9's set-up) and
//! `sphere-param` (seed 004's parametric sphere p(r, θ, φ) = (r cos θ sin φ, r sin θ sin φ,
//! r cos φ)).
//!
//! Both use the fixed-function lighting of GL 2.1 §2.14.1 with one positional light, and the
//! normal of a point on a sphere about the origin is the point itself (divided by r): seed 003's
//! "normal of an implicit surface", so SMOOTH shading makes the facets disappear as the
//! tessellation gets finer.
//!
//! Design decision: each picture is a grid of viewports (one `glViewport` per panel in a single
//! frame) so the levels of detail or shading modes sit side by side at 800x800, and each panel
//! sets its own projection, camera and lights, as a lecture's `display` would for a window of
//! that size.

use crate::gl::*;
use crate::{glu, Context};

use super::shapes::{
    draw_sphere, draw_sphere_triangles, materials, panels, subdivide, Split, GOLD,
};
use super::{Scene, LECTURE};

/// Slide 51's light (ambient 0.3, white diffuse and specular, at (-2, 2, 1)), as LIGHT0 with no
/// spot and no attenuation, placed under the current modelview.
pub fn seed_light(gl: &mut Context, light: u32) {
    gl.lightfv(light, AMBIENT, &[0.3, 0.3, 0.3, 1.0]);
    gl.lightfv(light, DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(light, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(light, POSITION, &[-2.0, 2.0, 1.0, 1.0]);
    gl.enable(light);
}

/// A square viewport at `(x, y, w, h)` looking at the origin from `eye` (up +y) through a
/// `gluPerspective(fovy, w/h, 0.5, 20)` projection; leaves MODELVIEW current.
pub fn camera(gl: &mut Context, vp: (i32, i32, i32, i32), eye: [f64; 3], fovy: f64) {
    let (x, y, w, h) = vp;
    gl.viewport(x, y, w, h);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, fovy, f64::from(w) / f64::from(h.max(1)), 0.5, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, eye[0], eye[1], eye[2], 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

/// `sphere-subdivision`: the seed's set-up (§6.9: LIGHTING, LIGHT0, DEPTH_TEST,
/// `glPolygonMode(GL_FRONT, GL_FILL)`, gold material) and one sphere per entry of `depths`,
/// in a grid of panels, split the `split` way.
pub fn sphere_subdivision(gl: &mut Context, depths: &[u32], split: Split) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(LIGHTING); // glEnable(GL_LIGHTING);
    gl.enable(LIGHT0); // glEnable(GL_LIGHT0);
    gl.enable(DEPTH_TEST); // glEnable(GL_DEPTH_TEST);
    gl.polygon_mode(FRONT, FILL); // glPolygonMode(GL_FRONT, GL_FILL);
    gl.shade_model(SMOOTH);
    materials(gl, FRONT, &GOLD); // materials(&goldMaterial);
    let depths = &depths[..depths.len().min(16)];
    let cols = (depths.len() as f64).sqrt().ceil().max(1.0) as u32;
    let rows = (depths.len() as u32).div_ceil(cols).max(1);
    for (vp, &depth) in panels(gl, cols, rows).into_iter().zip(depths) {
        camera(gl, vp, [0.0, 0.0, 3.2], 45.0);
        seed_light(gl, LIGHT0);
        // Tip the tetrahedron's top vertex (0, 0, 1) up and towards the viewer.
        gl.rotatef(-70.0, 1.0, 0.0, 0.0);
        gl.rotatef(20.0, 0.0, 0.0, 1.0);
        draw_sphere_triangles(gl, &subdivide(depth, split), 1.0);
    }
    gl.flush();
}

/// `sphere-param`: the seed 004 sphere with `slices` x `stacks` quads in four panels: SMOOTH,
/// FLAT, wireframe (`glPolygonMode(GL_FRONT_AND_BACK, GL_LINE)`, seed 004's wireframe call) and
/// SMOOTH at four times the resolution.
pub fn sphere_param(gl: &mut Context, slices: usize, stacks: usize) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(LIGHTING);
    gl.enable(DEPTH_TEST);
    materials(gl, FRONT_AND_BACK, &GOLD);
    let modes = [
        (SMOOTH, FILL, 1),
        (FLAT, FILL, 1),
        (SMOOTH, LINE, 1),
        (SMOOTH, FILL, 4),
    ];
    for (vp, (shade, mode, k)) in panels(gl, 2, 2).into_iter().zip(modes) {
        camera(gl, vp, [0.0, 0.0, 3.2], 45.0);
        seed_light(gl, LIGHT0);
        gl.shade_model(shade);
        gl.polygon_mode(FRONT_AND_BACK, mode);
        // The parametrisation's pole is +z: tilt it up and towards the viewer.
        gl.rotatef(-60.0, 1.0, 0.0, 0.0);
        draw_sphere(gl, 1.0, slices * k, stacks * k);
    }
    gl.polygon_mode(FRONT_AND_BACK, FILL);
    gl.flush();
}

/// The scenes of this module, as registry entries.
pub(super) const SCENES: [Scene; 2] = [
    Scene {
        name: "sphere-subdivision",
        summary:
            "Modelling: a sphere by recursive subdivision — tetrahedron subdivided 1, 2, 3 and 5 times (midpoints), gold, SMOOTH",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| sphere_subdivision(gl, &[1, 2, 3, 5], Split::Midpoint),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "sphere-param",
        summary:
            "Modelling: a parametric sphere — 24x12, lit: SMOOTH, FLAT, PolygonMode LINE, and 96x48",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| sphere_param(gl, 24, 12),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Call;

    fn calls(scene: &Scene) -> Vec<Call> {
        match scene.record(32, 32) {
            Ok((_, calls)) => calls,
            Err(e) => panic!("{e}"),
        }
    }

    /// Depths 1, 2, 3, 5 draw 4·(4 + 16 + 64 + 1024) = 4432 triangles, one normal per vertex,
    /// with the seed's gold material.
    #[test]
    fn subdivision_scene_draws_every_level() {
        let c = calls(&SCENES[0]);
        let count = |f: fn(&Call) -> bool| c.iter().filter(|x| f(x)).count();
        assert_eq!(count(|x| matches!(x, Call::Vertex3f(..))), 3 * 4432);
        assert_eq!(count(|x| matches!(x, Call::Normal3fv(..))), 3 * 4432);
        assert!(c.contains(&Call::Materialf(FRONT, SHININESS, 51.2)));
        assert!(c.contains(&Call::PolygonMode(FRONT, FILL)));
    }

    /// 24 slices x 12 stacks: 12 strips of 2·25 vertices; the fourth panel has 96 x 48. In all
    /// 12·50·3 + 48·194 = 11112 vertices.
    #[test]
    fn parametric_scene_vertex_count() {
        let c = calls(&SCENES[1]);
        let n = c.iter().filter(|x| matches!(x, Call::Vertex3f(..))).count();
        assert_eq!(n, 12 * 50 * 3 + 48 * 194);
    }
}
