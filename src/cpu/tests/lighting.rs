//! The lighting equation (GL 2.1 §2.14.1) term by term, and the normal transform (§2.11.3).

use glam::{Mat4, Vec3, Vec4};

use super::*;
use crate::cpu::vertex::Lighting;
use crate::state::{Material, BACK, FRONT};

fn close(a: Vec4, b: Vec4) {
    assert!((a - b).abs().max_element() < 1e-5, "{a:?} != {b:?}");
}

/// A state with LIGHT0 on and every ambient source and default term zeroed, so each test turns on
/// exactly the terms it checks.
fn dark() -> State {
    let mut st = State::new(4, 4);
    st.enables.lighting = true;
    st.enables.lights[0] = true;
    st.light_model.ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    st.lights[0].specular = Vec4::ZERO;
    st.lights[0].diffuse = Vec4::ZERO;
    st.materials = [Material {
        ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
        diffuse: Vec4::new(0.0, 0.0, 0.0, 1.0),
        ..Material::default()
    }; 2];
    st
}

fn shade(st: &State, v: Vec3, n: Vec3) -> (Vec4, Vec4) {
    Lighting::new(st).shade(&st.materials[FRONT], FRONT, Vec4::ONE, v, n)
}

#[test]
fn emission_and_scene_ambient() {
    let mut st = dark();
    st.enables.lights[0] = false;
    st.materials[FRONT].emission = Vec4::new(0.1, 0.2, 0.3, 1.0);
    st.materials[FRONT].ambient = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.light_model.ambient = Vec4::new(0.2, 0.4, 0.6, 1.0);
    st.materials[FRONT].diffuse.w = 0.25;
    // e + a_cs·a_cm = (0.1 + 0.1, 0.2 + 0.2, 0.3 + 0.3); alpha = diffuse alpha.
    close(
        shade(&st, Vec3::ZERO, Vec3::Z).0,
        Vec4::new(0.2, 0.4, 0.6, 0.25),
    );
}

#[test]
fn diffuse_directional() {
    let mut st = dark();
    st.lights[0].diffuse = Vec4::ONE;
    st.materials[FRONT].diffuse = Vec4::new(0.5, 0.5, 0.8, 1.0);
    // L = (0,0,1), N = (0, 0.6, 0.8): N·L = 0.8 → 0.8·(0.5, 0.5, 0.8).
    let (c, s) = shade(&st, Vec3::new(5.0, 1.0, -3.0), Vec3::new(0.0, 0.6, 0.8));
    close(c, Vec4::new(0.4, 0.4, 0.64, 1.0));
    close(s, Vec4::ZERO);
    // Facing away: N·L < 0 → no diffuse (and no specular).
    st.lights[0].specular = Vec4::ONE;
    st.materials[FRONT].specular = Vec4::ONE;
    close(
        shade(&st, Vec3::ZERO, Vec3::new(0.0, 0.6, -0.8)).0,
        Vec4::new(0.0, 0.0, 0.0, 1.0),
    );
}

#[test]
fn specular_infinite_and_local_viewer() {
    let mut st = dark();
    st.lights[0].specular = Vec4::ONE;
    st.materials[FRONT].specular = Vec4::ONE;
    st.materials[FRONT].shininess = 10.0;
    // Infinite viewer: h = L + (0,0,1) normalised = (0,0,1); N = (0.6,0,0.8): (N·h)^10 = 0.8^10.
    let e = 0.8f32.powi(10);
    close(
        shade(&st, Vec3::new(2.0, 0.0, -2.0), Vec3::new(0.6, 0.0, 0.8)).0,
        Vec4::new(e, e, e, 1.0),
    );
    // Local viewer at V = (2,0,-2): eye direction (-1,0,1)/√2; h = (−0.7071, 0, 1.7071)/1.847759
    // = (−0.382683, 0, 0.923880); N = (0,0,1): 0.923880^10.
    st.light_model.local_viewer = true;
    let e = 0.923_879_5f32.powi(10);
    close(
        shade(&st, Vec3::new(2.0, 0.0, -2.0), Vec3::Z).0,
        Vec4::new(e, e, e, 1.0),
    );
    // Separate specular: primary has no specular, the secondary carries it, alpha 0.
    st.light_model.color_control = gl::SEPARATE_SPECULAR_COLOR;
    let (c, s) = shade(&st, Vec3::new(2.0, 0.0, -2.0), Vec3::Z);
    close(c, Vec4::new(0.0, 0.0, 0.0, 1.0));
    close(s, Vec4::new(e, e, e, 0.0));
}

#[test]
fn attenuation_scales_ambient_and_diffuse() {
    let mut st = dark();
    st.lights[0].position = Vec4::new(0.0, 0.0, 3.0, 1.0);
    st.lights[0].diffuse = Vec4::ONE;
    st.lights[0].ambient = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.materials[FRONT].diffuse = Vec4::ONE;
    st.materials[FRONT].ambient = Vec4::ONE;
    st.lights[0].constant_attenuation = 1.0;
    st.lights[0].linear_attenuation = 0.5;
    st.lights[0].quadratic_attenuation = 0.25;
    // d = 3: 1/(1 + 1.5 + 2.25) = 1/4.75; (0.5 ambient + 1·N·L) / 4.75 = 1.5/4.75.
    let k = 1.5 / 4.75;
    close(shade(&st, Vec3::ZERO, Vec3::Z).0, Vec4::new(k, k, k, 1.0));
    // A directional light is never attenuated.
    st.lights[0].position = Vec4::new(0.0, 0.0, 3.0, 0.0);
    close(
        shade(&st, Vec3::ZERO, Vec3::Z).0,
        Vec4::new(1.0, 1.0, 1.0, 1.0),
    );
}

#[test]
fn spot_inside_and_outside_the_cone() {
    let mut st = dark();
    let l = &mut st.lights[0];
    l.position = Vec4::new(0.0, 0.0, 2.0, 1.0);
    l.spot_direction = Vec3::new(0.0, 0.0, -1.0);
    l.spot_cutoff = 30.0;
    l.spot_exponent = 2.0;
    l.ambient = Vec4::new(0.25, 0.25, 0.25, 1.0);
    l.diffuse = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.materials[FRONT].diffuse = Vec4::ONE;
    st.materials[FRONT].ambient = Vec4::ONE;
    // V = (0.5,0,0): VP = (−0.5,0,2)/√4.25; cos = 2/√4.25 = 0.970143 (14°, inside 30°);
    // spot = cos² = 4/4.25; N·L = 0.970143; colour = spot·(0.25 + 0.5·0.970143).
    let cos = 2.0 / 4.25f32.sqrt();
    let k = (4.0 / 4.25) * (0.25 + 0.5 * cos);
    close(
        shade(&st, Vec3::new(0.5, 0.0, 0.0), Vec3::Z).0,
        Vec4::new(k, k, k, 1.0),
    );
    // V = (2,0,0): 45° off the axis, outside: nothing at all, ambient included.
    close(
        shade(&st, Vec3::new(2.0, 0.0, 0.0), Vec3::Z).0,
        Vec4::new(0.0, 0.0, 0.0, 1.0),
    );
    // Cutoff 180: no spot factor even with an exponent.
    st.lights[0].spot_cutoff = 180.0;
    let k = 0.25 + 0.5 * 2.0 / 8.0f32.sqrt();
    close(
        shade(&st, Vec3::new(2.0, 0.0, 0.0), Vec3::Z).0,
        Vec4::new(k, k, k, 1.0),
    );
}

#[test]
fn color_material_replaces_the_tracked_property() {
    let mut st = dark();
    st.lights[0].diffuse = Vec4::ONE;
    st.materials[FRONT].diffuse = Vec4::new(0.0, 0.0, 1.0, 1.0);
    st.enables.color_material = true;
    st.color_material_mode = gl::DIFFUSE;
    let lt = Lighting::new(&st);
    // Diffuse := vertex colour (1,0,0,0.5): N·L = 0.8 → (0.8, 0, 0), alpha 0.5.
    let (c, _) = lt.shade(
        &st.materials[FRONT],
        FRONT,
        Vec4::new(1.0, 0.0, 0.0, 0.5),
        Vec3::ZERO,
        Vec3::new(0.0, 0.6, 0.8),
    );
    close(c, Vec4::new(0.8, 0.0, 0.0, 0.5));
    // EMISSION mode on the back face only: the front keeps its material.
    st.color_material_face = gl::BACK;
    st.color_material_mode = gl::EMISSION;
    let lt = Lighting::new(&st);
    let col = Vec4::new(0.0, 0.5, 0.0, 1.0);
    close(
        lt.shade(&st.materials[FRONT], FRONT, col, Vec3::ZERO, Vec3::Z)
            .0,
        Vec4::new(0.0, 0.0, 1.0, 1.0),
    );
    close(
        lt.shade(&st.materials[BACK], BACK, col, Vec3::ZERO, Vec3::Z)
            .0,
        Vec4::new(0.0, 0.5, 0.0, 1.0),
    );
}

#[test]
fn several_lights_sum_and_clamp() {
    let mut st = dark();
    st.enables.lights[1] = true;
    st.lights[0].diffuse = Vec4::new(0.75, 0.0, 0.0, 1.0);
    st.lights[1].diffuse = Vec4::new(0.75, 0.5, 0.0, 1.0);
    st.lights[1].position = Vec4::new(0.0, 0.0, 1.0, 0.0);
    st.materials[FRONT].diffuse = Vec4::ONE;
    // 0.75 + 0.75 = 1.5 → clamped to 1 after lighting; green 0.5.
    close(
        shade(&st, Vec3::ZERO, Vec3::Z).0,
        Vec4::new(1.0, 0.5, 0.0, 1.0),
    );
}

/// Draws one lit point at the origin of a 4x4 window (pixel (2,2)) and returns its colour.
fn lit_point(st: &State, n: Vec3) -> [u8; 4] {
    let mut r = Renderer::new(4, 4);
    r.begin(gl::POINTS);
    r.begin_materials(&st.materials);
    r.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0), &cur(WHITE, n));
    r.end();
    r.flush(st);
    px(&mut r, 2, 2)
}

#[test]
fn normal_transform_non_uniform_scale() {
    let mut st = dark();
    st.lights[0].position = Vec4::new(1.0, 0.0, 0.0, 0.0);
    st.lights[0].diffuse = Vec4::ONE;
    st.materials[FRONT].diffuse = Vec4::ONE;
    // MV = scale(2,1,1): the normal matrix (M⁻¹)ᵀ = scale(0.5,1,1): n = (1,1,0) → (0.5,1,0).
    *st.modelview.top_mut() = Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    // Without NORMALIZE: N·L = 0.5 → 0.5·255 + 0.5 = 128.
    assert_eq!(lit_point(&st, Vec3::new(1.0, 1.0, 0.0))[0], 128);
    // NORMALIZE: 0.5/√1.25 = 0.447214 → 114.04 → 114.
    st.enables.normalize = true;
    assert_eq!(lit_point(&st, Vec3::new(1.0, 1.0, 0.0))[0], 114);
    // RESCALE_NORMAL alone: f = 1/|row 3 of M⁻¹| = 1/|(0,0,1)| = 1, unchanged → 128.
    st.enables.normalize = false;
    st.enables.rescale_normal = true;
    assert_eq!(lit_point(&st, Vec3::new(1.0, 1.0, 0.0))[0], 128);
}

#[test]
fn rescale_normal_undoes_uniform_scale() {
    let mut st = dark();
    st.lights[0].position = Vec4::new(1.0, 0.0, 0.0, 0.0);
    st.lights[0].diffuse = Vec4::ONE;
    st.materials[FRONT].diffuse = Vec4::ONE;
    *st.modelview.top_mut() = Mat4::from_scale(Vec3::splat(2.0));
    let n = Vec3::new(0.6, 0.8, 0.0);
    // (M⁻¹)ᵀ = 0.5·I: N·L = 0.3 → 0.3·255 + 0.5 = 77.0 → 77 (the f32 sum lands a hair either
    // side of 77.0 exactly, so check the unambiguous rescaled case precisely and this one within 1).
    let plain = lit_point(&st, n)[0];
    assert!((76..=77).contains(&plain), "{plain}");
    // RESCALE: f = 1/|(0,0,0.5)| = 2 → N·L = 0.6 → 153.5 → 153 or 154; NORMALIZE alike.
    st.enables.rescale_normal = true;
    let rescaled = lit_point(&st, n)[0];
    assert!((153..=154).contains(&rescaled), "{rescaled}");
}

#[test]
fn two_sided_lighting_uses_back_material_and_negated_normal() {
    let (mut r, mut st) = setup(8, 8);
    st.enables.lighting = true;
    st.enables.lights[0] = true;
    st.light_model.ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    st.light_model.two_side = true;
    st.materials[FRONT].ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    st.materials[BACK].ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    st.materials[FRONT].diffuse = Vec4::new(1.0, 0.0, 0.0, 1.0);
    st.materials[BACK].diffuse = Vec4::new(0.0, 1.0, 0.0, 1.0);
    // Normal (0,0,−1) faces away from the light (0,0,1): the front is black, the back (normal
    // negated to (0,0,1), N·L = 1) is the BACK diffuse, green.
    let tri = |r: &mut Renderer, st: &State, cw: bool| {
        r.begin(gl::TRIANGLES);
        r.begin_materials(&st.materials);
        let vs = if cw {
            [[-1.0, -1.0], [-1.0, 1.0], [1.0, -1.0]]
        } else {
            [[-1.0, -1.0], [1.0, -1.0], [-1.0, 1.0]]
        };
        for v in vs {
            r.vertex(Vec4::new(v[0], v[1], 0.0, 1.0), &cur(WHITE, Vec3::NEG_Z));
        }
        r.end();
        r.flush(st);
    };
    tri(&mut r, &st, true);
    assert_eq!(px(&mut r, 1, 1), [0, 255, 0, 255]);
    tri(&mut r, &st, false);
    assert_eq!(px(&mut r, 1, 1), [0, 0, 0, 255]);
    // Without TWO_SIDE the back face is lit as the front: black.
    st.light_model.two_side = false;
    r.clear(&st, gl::COLOR_BUFFER_BIT);
    tri(&mut r, &st, true);
    assert_eq!(px(&mut r, 1, 1), [0, 0, 0, 255]);
}

#[test]
fn separate_specular_is_added_after_as_colour_sum() {
    let mut st = dark();
    st.lights[0].diffuse = Vec4::new(0.25, 0.25, 0.25, 1.0);
    st.lights[0].specular = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.materials[FRONT].diffuse = Vec4::ONE;
    st.materials[FRONT].specular = Vec4::ONE;
    st.light_model.color_control = gl::SEPARATE_SPECULAR_COLOR;
    // N = L = h = (0,0,1): primary 0.25, secondary 0.5; colour sum 0.75 → 191.75 → 191.
    assert_eq!(lit_point(&st, Vec3::Z), [191, 191, 191, 255]);
}

#[test]
fn material_change_inside_begin_end_applies_from_the_next_vertex() {
    let (mut r, mut st) = setup(8, 8);
    st.enables.lighting = true;
    st.light_model.ambient = Vec4::ONE;
    st.materials[FRONT].ambient = Vec4::new(1.0, 0.0, 0.0, 1.0);
    r.begin(gl::POINTS);
    r.begin_materials(&st.materials);
    r.vertex(Vec4::new(-0.5, -0.5, 0.0, 1.0), &cur(WHITE, Vec3::Z));
    st.materials[FRONT].ambient = Vec4::new(0.0, 0.0, 1.0, 1.0);
    r.materials_changed(&st.materials);
    r.vertex(Vec4::new(0.5, 0.5, 0.0, 1.0), &cur(WHITE, Vec3::Z));
    r.end();
    r.flush(&st);
    // Scene ambient 1 × material ambient: the first point red, the second blue.
    assert_eq!(px(&mut r, 2, 2)[..3], [255, 0, 0]);
    assert_eq!(px(&mut r, 6, 6)[..3], [0, 0, 255]);
}
