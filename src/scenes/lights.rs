//! Seed 003's lighting slides (§6.7 light sources, §6.8 materials) as scenes: `materials`,
//! `spotlight`, `light-model`, `two-side`, `emission` and `eight-lights`. Each exercises one part of
//! the GL 2.1 lighting equation (§2.14.1): material reflectances and shininess, the spot factor
//! and 1/(k_c + k_l·d + k_q·d²) attenuation, the global ambient and LOCAL_VIEWER's half vector,
//! two-sided lighting with a BACK material, emission, and all eight lights at once.
//!
//! Design decision: the seed's numbers are used verbatim (slide 51's LIGHT1, slide 54's global
//! ambient, slide 58's emission, slide 61's brass and gold); what the slides leave open (where the
//! objects stand, the camera, the colours of the extra lights) is chosen so the effect fills the
//! picture, and each choice is said where it is made. Surfaces that must show a per-vertex effect
//! (the spot's cone, a local viewer's highlight) are tessellated finely, since Gouraud shading
//! only samples the lighting at vertices.

use crate::gl::*;
use crate::Context;

use super::shapes::{
    draw_floor, draw_sphere, materials, panels, Material, BRASS, GL_DEFAULT, GOLD, YELLOW_PLASTIC,
};
use super::sphere::{camera, seed_light};
use super::{Scene, LECTURE};

/// A grey, slightly shiny material for floors and neutral objects.
const GREY: Material = Material {
    ambient: [0.3, 0.3, 0.3, 1.0],
    diffuse: [0.5, 0.5, 0.5, 1.0],
    specular: [0.3, 0.3, 0.3, 1.0],
    shininess: 20.0,
};

/// Common frame start: clear to `bg`, depth test, lighting, SMOOTH.
fn start(gl: &mut Context, bg: f32) {
    gl.clear_color(bg, bg, bg, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.enable(LIGHTING);
    gl.shade_model(SMOOTH);
}

/// A sphere of radius `r` centred at `at`, pole up, `slices` x `slices/2` quads.
fn sphere_at(gl: &mut Context, at: [f32; 3], r: f32, slices: usize) {
    gl.push_matrix();
    gl.translatef(at[0], at[1], at[2]);
    gl.rotatef(-90.0, 1.0, 0.0, 0.0);
    draw_sphere(gl, r, slices, slices / 2);
    gl.pop_matrix();
}

/// `materials`: brass, gold (slide 61), slide 57's yellow material and GL's default material
/// (slide 56), one sphere each in a 2x2 grid, under slide 51's light.
pub fn materials_scene(gl: &mut Context) {
    start(gl, 0.1);
    for (vp, m) in panels(gl, 2, 2)
        .into_iter()
        .zip([BRASS, GOLD, YELLOW_PLASTIC, GL_DEFAULT])
    {
        camera(gl, vp, [0.0, 0.0, 3.2], 45.0);
        seed_light(gl, LIGHT0);
        materials(gl, FRONT, &m); // materials(&brassMaterial); ...
        sphere_at(gl, [0.0, 0.0, 0.0], 1.0, 64);
    }
    gl.flush();
}

/// `spotlight`: slide 51–52's LIGHT1 verbatim (ambient 0.3, white diffuse and specular, at
/// (-2, 2, 1), attenuation 1.5 / 0.5 / 0.2, cutoff 45°, exponent 2) over a floor and two
/// spheres. The slide's direction (-1, -1, 0) points away from any object standing around the
/// origin, so the spot is aimed at `target` instead (the brief's "aimed so the cone falls on
/// the objects"); LIGHT0 stays off, so outside the cone only the global ambient lights.
pub fn spotlight(gl: &mut Context, target: [f32; 3]) {
    start(gl, 0.0);
    let (w, h) = gl.size();
    camera(gl, (0, 0, w as i32, h as i32), [2.0, 4.0, 6.0], 45.0);
    let pos = [-2.0f32, 2.0, 1.0];
    let dir = [target[0] - pos[0], target[1] - pos[1], target[2] - pos[2]];
    gl.lightfv(LIGHT1, AMBIENT, &[0.3, 0.3, 0.3, 1.0]); // glLightfv(GL_LIGHT1, GL_AMBIENT, L1_ambiente);
    gl.lightfv(LIGHT1, DIFFUSE, &[1.0, 1.0, 1.0, 1.0]); // glLightfv(GL_LIGHT1, GL_DIFFUSE, L1_difusa);
    gl.lightfv(LIGHT1, SPECULAR, &[1.0, 1.0, 1.0, 1.0]); // glLightfv(GL_LIGHT1, GL_SPECULAR, L1_especular);
    gl.lightfv(LIGHT1, POSITION, &[pos[0], pos[1], pos[2], 1.0]); // glLightfv(GL_LIGHT1, GL_POSITION, L1_posicao);
    gl.lightf(LIGHT1, CONSTANT_ATTENUATION, 1.5); // glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 1.5);
    gl.lightf(LIGHT1, LINEAR_ATTENUATION, 0.5); // glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.5);
    gl.lightf(LIGHT1, QUADRATIC_ATTENUATION, 0.2); // glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.2);
    gl.lightf(LIGHT1, SPOT_CUTOFF, 45.0); // glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45.0);
    gl.lightfv(LIGHT1, SPOT_DIRECTION, &dir); // glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot_dir);
    gl.lightf(LIGHT1, SPOT_EXPONENT, 2.0); // glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.0);
    gl.enable(LIGHT1); // glEnable(GL_LIGHT1);
                       // White surfaces, so the dim attenuated light (1/(1.5 + 0.5d + 0.2d²) ≈ 0.2 at d = 3) shows.
    let white = Material {
        ambient: [1.0, 1.0, 1.0, 1.0],
        diffuse: [1.0, 1.0, 1.0, 1.0],
        specular: [0.5, 0.5, 0.5, 1.0],
        shininess: 10.0,
    };
    materials(gl, FRONT, &white);
    draw_floor(gl, 3.0, 120);
    sphere_at(gl, [0.2, 0.5, -0.6], 0.5, 48);
    sphere_at(gl, [-1.4, 0.35, 0.6], 0.35, 48);
    gl.flush();
}

/// `light-model`: a shiny floor and a sphere under one directional light, four times: top row
/// with no global ambient, bottom row with slide 54's (0.2, 0.2, 0.2, 1); left column the
/// infinite viewer (the half vector uses (0, 0, 1): a flat floor under a directional light is
/// one colour), right column `GL_LIGHT_MODEL_LOCAL_VIEWER` (the direction to the eye: a
/// highlight appears), GL 2.1 §2.14.1.
pub fn light_model(gl: &mut Context) {
    start(gl, 0.0);
    let shiny = Material {
        ambient: [0.6, 0.5, 0.4, 1.0],
        diffuse: [0.2, 0.3, 0.6, 1.0],
        specular: [0.9, 0.9, 0.9, 1.0],
        shininess: 60.0,
    };
    materials(gl, FRONT, &shiny);
    gl.lightfv(LIGHT0, DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.enable(LIGHT0);
    let rows: [[f32; 4]; 2] = [[0.0, 0.0, 0.0, 1.0], [0.2, 0.2, 0.2, 1.0]];
    for (i, vp) in panels(gl, 2, 2).into_iter().enumerate() {
        // GLfloat luz_ambiente_global[] = {0.2, 0.2, 0.2, 1.0}; (bottom row)
        gl.light_modelfv(LIGHT_MODEL_AMBIENT, &rows[i / 2]);
        gl.light_modeli(LIGHT_MODEL_LOCAL_VIEWER, (i % 2) as i32); // GL_FALSE / GL_TRUE
        camera(gl, vp, [0.0, 2.6, 2.6], 50.0);
        // Directional, from above and a little behind. For the infinite viewer N·H is one
        // value over the whole floor (0.963^60 ≈ 0.1); the local viewer's mirror point, where
        // N·H = 1, is the floor point at z ≈ 1.96 seen from the eye.
        gl.lightfv(LIGHT0, POSITION, &[0.0, 1.0, -0.25, 0.0]);
        draw_floor(gl, 2.5, 100);
        sphere_at(gl, [0.0, 0.6, -0.5], 0.6, 48);
    }
    gl.flush();
}

/// `two-side`: an open bowl (the parametric sphere below 63° of latitude) whose inside shows,
/// gold FRONT material and a blue BACK material, under slide 51's light; top panel with
/// `GL_LIGHT_MODEL_TWO_SIDE` off (the inside is lit with the front material and the outward
/// normal), bottom panel on (back faces use the BACK material and the negated normal,
/// GL 2.1 §2.14.1).
pub fn two_side(gl: &mut Context) {
    start(gl, 0.1);
    let blue = Material {
        ambient: [0.1, 0.1, 0.3, 1.0],
        diffuse: [0.2, 0.4, 0.9, 1.0],
        specular: [0.6, 0.6, 0.6, 1.0],
        shininess: 30.0,
    };
    materials(gl, FRONT, &GOLD);
    materials(gl, BACK, &blue);
    for (i, vp) in panels(gl, 1, 2).into_iter().enumerate() {
        gl.light_modeli(LIGHT_MODEL_TWO_SIDE, i as i32); // glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        camera(gl, vp, [0.0, 2.0, 2.6], 40.0);
        seed_light(gl, LIGHT0);
        gl.push_matrix();
        gl.rotatef(-90.0, 1.0, 0.0, 0.0); // the pole +z up
        gl.translatef(0.0, 0.0, 0.2);
        super::shapes::draw_sphere_band(gl, 1.0, 64, 24, 1.1, std::f32::consts::PI);
        gl.pop_matrix();
    }
    gl.flush();
}

/// `emission`: slide 58's emissive material (0, 0.3, 0.3) on the right sphere, the same grey
/// without emission on the left, and a "bulb" between them that is all emission (no ambient,
/// diffuse or specular reflectance) with a warm positional LIGHT0 at its centre, over a floor.
pub fn emission(gl: &mut Context) {
    start(gl, 0.0);
    let (w, h) = gl.size();
    camera(gl, (0, 0, w as i32, h as i32), [0.0, 2.4, 5.0], 45.0);
    let bulb = [0.0f32, 1.5, 0.0];
    gl.lightfv(LIGHT0, AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.lightfv(LIGHT0, DIFFUSE, &[1.0, 0.9, 0.7, 1.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 0.9, 0.7, 1.0]);
    gl.lightfv(LIGHT0, POSITION, &[bulb[0], bulb[1], bulb[2], 1.0]);
    gl.lightf(LIGHT0, LINEAR_ATTENUATION, 0.2);
    gl.enable(LIGHT0);
    let none = [0.0f32, 0.0, 0.0, 1.0];
    materials(gl, FRONT, &GREY);
    gl.materialfv(FRONT, EMISSION, &none);
    draw_floor(gl, 3.0, 64);
    sphere_at(gl, [-1.4, 0.6, 0.3], 0.6, 48);
    gl.materialfv(FRONT, EMISSION, &[0.0, 0.3, 0.3, 1.0]); // glMaterialfv(GL_FRONT, GL_EMISSION, emissao);
    sphere_at(gl, [1.4, 0.6, 0.3], 0.6, 48);
    let dark = Material {
        ambient: none,
        diffuse: none,
        specular: none,
        shininess: 0.0,
    };
    materials(gl, FRONT, &dark);
    gl.materialfv(FRONT, EMISSION, &[1.0, 0.9, 0.6, 1.0]);
    sphere_at(gl, bulb, 0.25, 32);
    gl.flush();
}

/// The eight lights of `eight-lights`: (colour, position) with w = 1 positional (even lights)
/// and w = 0 directional (odd lights).
pub const EIGHT: [([f32; 3], [f32; 4]); 8] = [
    ([0.6, 0.1, 0.1], [2.0, 1.5, 2.0, 1.0]),
    ([0.1, 0.5, 0.1], [-1.0, 1.0, 0.5, 0.0]),
    ([0.1, 0.1, 0.7], [-2.0, 1.5, 2.0, 1.0]),
    ([0.4, 0.4, 0.0], [0.0, 1.0, -1.0, 0.0]),
    ([0.5, 0.0, 0.5], [0.0, 3.0, 0.0, 1.0]),
    ([0.0, 0.4, 0.4], [1.0, 0.3, 1.0, 0.0]),
    ([0.6, 0.3, 0.0], [2.0, 0.3, -2.0, 1.0]),
    ([0.15, 0.15, 0.15], [0.0, 0.5, 1.0, 0.0]),
];

/// `eight-lights`: GL_LIGHT0..GL_LIGHT7 all on (slide 50's limit of eight), each a different
/// colour, even ones positional (with linear attenuation 0.1), odd ones directional, over a
/// sphere on a floor.
pub fn eight_lights(gl: &mut Context) {
    start(gl, 0.0);
    let (w, h) = gl.size();
    camera(gl, (0, 0, w as i32, h as i32), [0.0, 2.5, 5.0], 45.0);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.05, 0.05, 0.05, 1.0]);
    for (i, (c, p)) in (0u32..).zip(EIGHT) {
        let light = LIGHT0 + i;
        gl.lightfv(light, DIFFUSE, &[c[0], c[1], c[2], 1.0]);
        gl.lightfv(light, SPECULAR, &[c[0], c[1], c[2], 1.0]);
        gl.lightfv(light, POSITION, &p);
        if p[3] != 0.0 {
            gl.lightf(light, LINEAR_ATTENUATION, 0.1);
        }
        gl.enable(light);
    }
    let white = Material {
        ambient: [1.0, 1.0, 1.0, 1.0],
        diffuse: [0.9, 0.9, 0.9, 1.0],
        specular: [0.6, 0.6, 0.6, 1.0],
        shininess: 40.0,
    };
    materials(gl, FRONT, &GREY);
    draw_floor(gl, 3.0, 96);
    materials(gl, FRONT, &white);
    sphere_at(gl, [0.0, 1.0, 0.0], 1.0, 96);
    gl.flush();
}

/// The scenes of this module, as registry entries.
pub(super) const SCENES: [Scene; 6] = [
    Scene {
        name: "materials",
        summary: "Lighting: materials — brass, gold, slide 57's yellow and GL's default material, side by side",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: materials_scene,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "spotlight",
        summary: "Lighting: a spotlight with attenuation — LIGHT1 spot at (-2,2,1), attenuation 1.5/0.5/0.2, cutoff 45, exponent 2",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: |gl| spotlight(gl, [0.0, 0.0, 0.0]),
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "light-model",
        summary: "Lighting: the light model — global ambient 0 vs 0.2 (rows), LOCAL_VIEWER off vs on (columns)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: light_model,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "two-side",
        summary: "Lighting: two-sided lighting — open bowl, gold FRONT, blue BACK; LIGHT_MODEL_TWO_SIDE off (top), on",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: two_side,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "emission",
        summary: "Lighting: emissive materials — GL_EMISSION (0,0.3,0.3) vs none, and an all-emissive bulb holding LIGHT0",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: emission,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
    Scene {
        name: "eight-lights",
        summary: "Lighting: eight light sources — LIGHT0..7 coloured, positional (even) and directional (odd)",
        tolerance: LECTURE,
        default_size: (800, 800),
        draw: eight_lights,
        animate: None,
        config: super::DEFAULT_CONFIG,
    },
];
