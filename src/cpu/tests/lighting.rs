//! The lighting equation (GL 2.1 §2.14.1) term by term, and the normal transform (§2.11.3).

use glam::{Mat4, Vec3, Vec4, Vec4Swizzles};

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

/// A small deterministic generator for the property tests below and `routes`'s (xorshift32),
/// in [0, 1).
pub(super) struct Rng(pub(super) u32);

impl Rng {
    pub(super) fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        (self.0 >> 8) as f32 / (1u32 << 24) as f32
    }

    pub(super) fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }

    fn vec3(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }
}

/// `negligible` may only say yes when adding the specular term really leaves every bit of the
/// sum: checked by doing the addition, over N·H, shininess and sums of many magnitudes; and it
/// does say yes where the power is far below the sum's precision.
#[test]
fn a_negligible_specular_term_changes_no_bit() {
    use crate::cpu::vertex::negligible;
    let mut rng = Rng(0x1234_5678);
    let mut yes = 0;
    for _ in 0..200_000 {
        let x = match rng.next() {
            r if r < 0.1 => 0.0,
            r if r < 0.2 => 1.0,
            _ => rng.next(),
        };
        let srm =
            [0.0, 1.0, 5.0, 23.0, 24.0, 50.0, 100.0, 127.5, 128.0][(rng.next() * 9.0) as usize];
        // Sums from 2^-100 to 2^10, either sign.
        let mut y = [0.0f32; 3];
        for c in &mut y {
            let mag = 2f32.powf(rng.range(-100.0, 10.0));
            *c = if rng.next() < 0.5 { -mag } else { mag };
        }
        let (scl, scm) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        if negligible(x, srm, y) {
            yes += 1;
            for (scl, scm) in [(1.0, 1.0), (scl, scm)] {
                let sp = x.powf(srm) * scl * scm;
                for c in y {
                    assert_eq!((c + sp).to_bits(), c.to_bits(), "x {x} srm {srm} y {c}");
                }
            }
        }
    }
    assert!(yes > 10_000, "only {yes} cases were negligible");
    // 0.5^100 ≈ 7.9e-31 is far below half an ulp of 0.3 (≈ 1.5e-8): negligible.
    assert!(negligible(0.5, 100.0, [0.3, 0.3, 0.3]));
    // 0.95^100 ≈ 0.0059 is not; neither is anything added to a zero sum.
    assert!(!negligible(0.95, 100.0, [0.3, 0.3, 0.3]));
    assert!(!negligible(0.5, 100.0, [0.3, 0.0, 0.3]));
}

/// The §2.14.1 sum written plainly, one point at a time, `powf` evaluated wherever N·L > 0,
/// in the operation order the pipeline documents (dot products (x·x' + y·y') + z·z', products
/// left to right); no COLOR_MATERIAL.
fn reference(st: &State, m: &Material, v: Vec3, n: Vec3) -> (Vec4, Vec4) {
    let mut c = m.emission.xyz() + st.light_model.ambient.xyz() * m.ambient.xyz();
    let mut s = Vec3::ZERO;
    let eye = if st.light_model.local_viewer {
        (-v).normalize_or_zero()
    } else {
        Vec3::Z
    };
    for (l, _) in st
        .lights
        .iter()
        .zip(st.enables.lights)
        .filter(|(_, on)| *on)
    {
        let (vp, mut kf) = if l.position.w != 0.0 {
            let d = l.position.xyz() / l.position.w - v;
            let d2 = d.length_squared();
            let inv = if d2 > 0.0 { 1.0 / d2.sqrt() } else { 0.0 };
            let dist = d2 * inv;
            let att =
                l.constant_attenuation + l.linear_attenuation * dist + l.quadratic_attenuation * d2;
            (d * inv, 1.0 / att)
        } else {
            (l.position.xyz().normalize_or_zero(), 1.0)
        };
        if l.spot_cutoff != 180.0 {
            let cosang = (-vp).dot(l.spot_direction.normalize_or_zero());
            if cosang < l.spot_cutoff.to_radians().cos() {
                continue;
            }
            kf *= cosang.max(0.0).powf(l.spot_exponent);
        }
        let ndl = n.dot(vp);
        let ndh = n.dot((vp + eye).normalize_or_zero()).max(0.0);
        let mut term = l.ambient.xyz() * m.ambient.xyz();
        if ndl > 0.0 {
            term += ndl * l.diffuse.xyz() * m.diffuse.xyz();
            let sp = ndh.powf(m.shininess) * l.specular.xyz() * m.specular.xyz();
            if st.light_model.color_control == gl::SEPARATE_SPECULAR_COLOR {
                s += kf * sp;
            } else {
                term += sp;
            }
        }
        c += kf * term;
    }
    (
        c.extend(m.diffuse.w).clamp(Vec4::ZERO, Vec4::ONE),
        s.extend(0.0).clamp(Vec4::ZERO, Vec4::ONE),
    )
}

/// `shade_block` over [`LANES`] lanes, `shade` on one point and the plain sum agree bit for bit over
/// random lights (positional with attenuation, spot, directional), materials (shininess up to
/// 128, where most specular powers are skipped as negligible), viewer and colour-control modes.
#[test]
fn block_and_single_point_shading_equal_the_plain_sum_bit_for_bit() {
    use crate::cpu::vertex::{Block, LANES};
    let mut rng = Rng(0x9e37_79b9);
    for case in 0..400 {
        let mut st = State::new(4, 4);
        st.enables.lighting = true;
        st.light_model.local_viewer = case % 2 == 1;
        st.light_model.color_control = if case % 3 == 0 {
            gl::SEPARATE_SPECULAR_COLOR
        } else {
            gl::SINGLE_COLOR
        };
        st.light_model.ambient = rng.vec3(0.0, 0.3).extend(1.0);
        for (i, l) in st.lights.iter_mut().enumerate().take(3) {
            st.enables.lights[i] = true;
            l.ambient = rng.vec3(0.0, 0.2).extend(1.0);
            l.diffuse = rng.vec3(0.0, 1.0).extend(1.0);
            l.specular = if case % 5 == 0 {
                Vec4::ZERO
            } else {
                rng.vec3(0.0, 1.0).extend(1.0)
            };
            let w = if i == 2 { 0.0 } else { 1.0 };
            l.position = rng.vec3(-3.0, 3.0).extend(w);
        }
        st.lights[1].linear_attenuation = rng.range(0.0, 0.5);
        st.lights[1].quadratic_attenuation = rng.range(0.0, 0.2);
        if case % 4 == 0 {
            st.lights[0].spot_cutoff = rng.range(10.0, 90.0);
            st.lights[0].spot_exponent = rng.range(0.0, 20.0);
            st.lights[0].spot_direction = rng.vec3(-1.0, 1.0);
        }
        let m = Material {
            ambient: rng.vec3(0.0, 1.0).extend(1.0),
            diffuse: rng.vec3(0.0, 1.0).extend(rng.next()),
            specular: rng.vec3(0.0, 1.0).extend(1.0),
            emission: rng.vec3(0.0, 0.1).extend(1.0),
            shininess: [0.0, 1.0, 10.0, 100.0, 128.0][case % 5],
            ..Material::default()
        };
        let lt = Lighting::new(&st);
        let mut blk = Block::<LANES>::default();
        for k in 0..LANES {
            blk.v.set(k, rng.vec3(-2.0, 2.0));
            blk.n.set(k, rng.vec3(-1.0, 1.0).normalize_or_zero());
        }
        let mut out = [(Vec4::ZERO, Vec4::ZERO); LANES];
        lt.shade_block(&m, FRONT, &blk, &mut out);
        for (k, &(c, s)) in out.iter().enumerate() {
            let (v, n) = (blk.v.get(k), blk.n.get(k));
            let (rc, rs) = reference(&st, &m, v, n);
            let (pc, ps) = lt.shade(&m, FRONT, Vec4::ONE, v, n);
            let bits = |a: Vec4| a.to_array().map(f32::to_bits);
            assert_eq!(bits(c), bits(rc), "case {case} lane {k}: {c} vs {rc}");
            assert_eq!(bits(s), bits(rs), "case {case} lane {k}: {s} vs {rs}");
            assert_eq!(
                (bits(pc), bits(ps)),
                (bits(c), bits(s)),
                "case {case} lane {k}"
            );
        }
    }
}

/// The vertex stage's window coordinates and clip codes (`SetupCtx::win_block`, 16 lanes at
/// once) equal `SetupCtx::win` on the processed vertex, bit for bit, over random positions with
/// infinities, NaNs, signed zeros and w of both signs, under a user clip plane; and one vertex
/// worked by hand (§2.11.1: x_w = (p_x/w)·(w_v/2) + o_x): viewport 800 x 800 at the origin, clip
/// position (0.5, -0.5, 0.25, 1) lands at (600, 200) = (153600, 51200)/256, z = 0.25·0.5 + 0.5.
#[test]
fn window_coordinates_of_a_block_equal_those_of_each_vertex() {
    use crate::cpu::framebuffer::scissor_rect;
    use crate::cpu::setup::{SetupCtx, Win};
    use crate::cpu::vertex::{Lanes4, Layout};
    use glam::DVec4;
    let mut st = State::new(800, 800);
    st.viewport = [0, 0, 800, 800];
    st.enables.clip_planes[1] = true;
    st.clip_planes[1] = DVec4::new(0.5, -1.0, 0.25, 0.125);
    let layout = Layout::for_state(&st);
    let eye_at = layout
        .eye
        .expect("a user clip plane needs the eye position");
    let ctx = SetupCtx::new(&st, layout, scissor_rect(&st), (1, 1));
    let special = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        1e-30,
    ];
    let mut rng = Rng(0x2468_ace1);
    let pick = |rng: &mut Rng| {
        if rng.next() < 0.15 {
            special[(rng.next() * special.len() as f32) as usize % special.len()]
        } else {
            rng.range(-3.0, 3.0)
        }
    };
    for _ in 0..200 {
        let mut c = Lanes4::<16>::splat(Vec4::ZERO);
        let mut e = c;
        for k in 0..16 {
            (c.x[k], c.y[k], c.z[k], c.w[k]) = (
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
            );
            (e.x[k], e.y[k], e.z[k], e.w[k]) = (
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
                pick(&mut rng),
            );
        }
        let mut ws = [Win::default(); 16];
        ctx.win_block(&c, &e, &mut ws);
        for (k, w) in ws.iter().enumerate() {
            let mut v = vec![0.0f32; layout.stride];
            v[..4].copy_from_slice(&c.get(k).to_array());
            v[eye_at..eye_at + 4].copy_from_slice(&e.get(k).to_array());
            let r = ctx.win(&v);
            let bits = |w: &Win| {
                (
                    w.x.to_bits(),
                    w.y.to_bits(),
                    w.fx,
                    w.fy,
                    w.z.to_bits(),
                    w.iw.to_bits(),
                    w.code,
                    w.cen,
                )
            };
            assert_eq!(bits(w), bits(&r), "lane {k}: {w:?} vs {r:?}");
        }
    }
    let mut c = Lanes4::<1>::splat(Vec4::new(0.5, -0.5, 0.25, 1.0));
    let e = Lanes4::<1>::splat(Vec4::new(0.0, 0.0, 0.0, 1.0)); // plane: 0.125 >= 0, inside
    let mut w = [Win::default()];
    ctx.win_block(&c, &e, &mut w);
    assert_eq!(
        (w[0].x, w[0].y, w[0].fx, w[0].fy),
        (600.0, 200.0, 153_600, 51_200)
    );
    assert_eq!((w[0].z, w[0].iw, w[0].code), (0.625, 1.0, 0));
    // x > w is outside the plane w - x >= 0 (bit 1); the eye point below the user plane sets
    // bit 7 + 1.
    c.x[0] = 2.0;
    let e = Lanes4::<1>::splat(Vec4::new(0.0, 1.0, 0.0, 1.0)); // -1 + 0.125 < 0
    ctx.win_block(&c, &e, &mut w);
    assert_eq!(w[0].code, 1 << 1 | 1 << 8);
}

/// `v`'s bits, every NaN as one value: the sign and payload of a NaN made from NaN or infinite
/// inputs are not defined by the compiler (x86 returns the first operand's NaN, and either build
/// may order a commutative operation's operands either way), and nothing downstream reads them
/// (comparisons, clamps and conversions treat every NaN alike).
pub(super) fn nan_bits(v: f32) -> u32 {
    if v.is_nan() {
        u32::MAX
    } else {
        v.to_bits()
    }
}

/// The vertex stage's two builds ([`Route::Baseline`], and [`Route::Avx2`] where the CPU has
/// AVX2) write the same bits (every NaN counted as one value, see `nan_bits`): every float of every processed vertex and every window record, over
/// random batches (1 to 70 vertices: whole and partial blocks) under random states — lighting on
/// and off, up to four positional, directional and spot lights, local viewer, separate specular,
/// two-sided, COLOR_MATERIAL, NORMALIZE and RESCALE_NORMAL, a projective modelview, TexGen and
/// the texture matrix, fog, point attenuation, a user clip plane, a Material change inside
/// Begin/End — with positions and normals holding zeros, infinities and NaNs; and positions only
/// (selection). Without AVX2 it checks the baseline against itself and says so.
#[test]
fn both_routes_process_the_same_bits() {
    use crate::cpu::batch::Batch;
    use crate::cpu::framebuffer::scissor_rect;
    use crate::cpu::setup::{SetupCtx, Win};
    use crate::cpu::vertex::{process_by, Layout, Route};
    use glam::DVec4;
    let wide = Route::best();
    if wide != Route::Avx2 {
        eprintln!("no AVX2 on this CPU: the baseline route is compared with itself");
    }
    let mut rng = Rng(0x0bad_cafe);
    let special = [0.0, -0.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 1e-30];
    let mut lanes_lit = 0;
    for case in 0..300 {
        let mut st = State::new(200, 150);
        st.viewport = [0, 0, 200, 150];
        let e = &mut st.enables;
        e.lighting = case % 5 != 0;
        e.normalize = case % 3 == 0;
        e.rescale_normal = case % 7 == 1;
        e.color_material = case % 4 == 1;
        e.fog = case % 3 == 1;
        e.texture_2d[0] = case % 2 == 0;
        e.texture_gen[0] = [case % 6 == 0, case % 6 == 0, false, false];
        e.clip_planes[2] = case % 5 == 2;
        st.clip_planes[2] = DVec4::new(0.3, -1.0, 0.5, 0.2);
        st.textures.units[0].gen[0].mode = [gl::SPHERE_MAP, gl::EYE_LINEAR][case % 2];
        st.textures.units[0].gen[1].mode = gl::OBJECT_LINEAR;
        st.textures.units[0].gen[1].object_plane = rng.vec3(-1.0, 1.0).extend(0.5);
        *st.texture_matrix[0].top_mut() =
            Mat4::from_scale(rng.vec3(0.5, 2.0)) * Mat4::from_rotation_z(rng.range(0.0, 3.0));
        if case % 4 == 3 {
            st.point.distance_attenuation = [1.0, rng.range(0.0, 0.5), rng.range(0.0, 0.2)];
        }
        st.light_model.local_viewer = case % 2 == 1;
        st.light_model.two_side = case % 3 == 2;
        st.light_model.color_control = if case % 4 == 0 {
            gl::SEPARATE_SPECULAR_COLOR
        } else {
            gl::SINGLE_COLOR
        };
        st.color_material_mode = [gl::AMBIENT_AND_DIFFUSE, gl::SPECULAR, gl::DIFFUSE][case % 3];
        st.light_model.ambient = rng.vec3(0.0, 0.3).extend(1.0);
        for (i, l) in st.lights.iter_mut().enumerate().take(1 + case % 4) {
            st.enables.lights[i] = true;
            l.ambient = rng.vec3(0.0, 0.2).extend(1.0);
            l.diffuse = rng.vec3(0.0, 1.0).extend(1.0);
            l.specular = rng.vec3(0.0, 1.0).extend(1.0);
            let w = if i % 2 == 1 { 0.0 } else { 1.0 };
            l.position = rng.vec3(-3.0, 3.0).extend(w);
            l.linear_attenuation = rng.range(0.0, 0.5);
            if i == 2 {
                l.spot_cutoff = rng.range(10.0, 90.0);
                l.spot_exponent = rng.range(0.0, 20.0);
                l.spot_direction = rng.vec3(-1.0, 1.0);
            }
        }
        for m in &mut st.materials {
            m.ambient = rng.vec3(0.0, 1.0).extend(1.0);
            m.diffuse = rng.vec3(0.0, 1.0).extend(rng.next());
            m.specular = rng.vec3(0.0, 1.0).extend(1.0);
            m.emission = rng.vec3(0.0, 0.1).extend(1.0);
            m.shininess = [0.0, 1.0, 10.0, 100.0, 128.0][case % 5];
        }
        let mut mv = Mat4::from_translation(rng.vec3(-1.0, 1.0) - Vec3::Z * 4.0)
            * Mat4::from_rotation_y(rng.range(0.0, 6.0))
            * Mat4::from_scale(rng.vec3(0.3, 2.0));
        if case % 8 == 5 {
            // A projective modelview: eye w other than 1.
            mv.w_axis.w = rng.range(0.5, 2.0);
            mv.x_axis.w = rng.range(-0.2, 0.2);
        }
        *st.modelview.top_mut() = mv;
        *st.projection.top_mut() = Mat4::perspective_rh_gl(1.0, 4.0 / 3.0, 0.5, 20.0);
        let mut b = Batch::default();
        let n = 1 + (rng.next() * 70.0) as usize;
        b.begin(gl::TRIANGLES);
        b.note_materials(&st.materials);
        let pick = |rng: &mut Rng, lo: f32, hi: f32| {
            if rng.next() < 0.04 {
                special[(rng.next() * special.len() as f32) as usize % special.len()]
            } else {
                rng.range(lo, hi)
            }
        };
        for k in 0..n {
            if case % 9 == 4 && k == n / 2 {
                let mut m = st.materials;
                m[0].diffuse = rng.vec3(0.0, 1.0).extend(1.0);
                m[1].shininess = 5.0;
                b.materials_changed(&m);
            }
            let p = Vec4::new(
                pick(&mut rng, -2.0, 2.0),
                pick(&mut rng, -2.0, 2.0),
                pick(&mut rng, -2.0, 2.0),
                if rng.next() < 0.1 {
                    rng.range(0.5, 2.0)
                } else {
                    1.0
                },
            );
            let nrm = Vec3::new(
                pick(&mut rng, -1.0, 1.0),
                pick(&mut rng, -1.0, 1.0),
                pick(&mut rng, -1.0, 1.0),
            );
            let mut c = cur(rng.vec3(0.0, 1.0).extend(rng.next()), nrm);
            c.inputs_mut().tex_coords[0] = rng.vec3(-1.0, 1.0).extend(1.0);
            c.inputs_mut().fog_coord = rng.range(0.0, 5.0);
            b.vertex(p, &c);
        }
        b.end();
        for attributes in [true, false] {
            let layout = if attributes {
                Layout::for_state(&st)
            } else {
                Layout::for_select(&st)
            };
            let ctx = SetupCtx::new(&st, layout, scissor_rect(&st), (4, 3));
            let run = |route| {
                let (mut out, mut wins) = (Vec::new(), Vec::new());
                process_by(
                    &st, &b, &layout, &ctx, &mut out, &mut wins, attributes, route,
                );
                (out, wins)
            };
            let (o1, w1) = run(Route::Baseline);
            let (o2, w2) = run(wide);
            assert_eq!(o1.len(), b.len() * layout.stride);
            let bits = |o: &[f32]| o.iter().map(|&v| nan_bits(v)).collect::<Vec<_>>();
            assert_eq!(
                bits(&o1),
                bits(&o2),
                "case {case}: processed vertices differ"
            );
            let wb = |w: &Win| {
                (
                    nan_bits(w.x),
                    nan_bits(w.y),
                    w.fx,
                    w.fy,
                    if w.z.is_nan() {
                        u64::MAX
                    } else {
                        w.z.to_bits()
                    },
                    nan_bits(w.iw),
                    w.code,
                )
            };
            assert_eq!(
                w1.iter().map(wb).collect::<Vec<_>>(),
                w2.iter().map(wb).collect::<Vec<_>>(),
                "case {case}: window records differ"
            );
            if attributes && st.enables.lighting {
                lanes_lit += b.len();
            }
        }
    }
    assert!(lanes_lit > 5000, "only {lanes_lit} lit vertices compared");
}

/// A lit batch large enough for `vertex::process` to split across the pool (chunks of 1024
/// vertices), with a material change and TexGen partway: the same bits as the whole batch on
/// one thread, for every vertex of every chunk.
#[test]
fn a_lit_batch_split_across_the_pool_is_the_whole_batch_bit_for_bit() {
    use crate::cpu::batch::Batch;
    use crate::cpu::framebuffer::scissor_rect;
    use crate::cpu::setup::SetupCtx;
    use crate::cpu::vertex::{process, Layout};
    let mut st = dark();
    st.lights[0].diffuse = Vec4::new(0.8, 0.7, 0.6, 1.0);
    st.lights[0].specular = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.lights[0].position = Vec4::new(1.0, 2.0, 3.0, 1.0);
    st.materials[FRONT].diffuse = Vec4::new(0.9, 0.5, 0.2, 1.0);
    st.materials[FRONT].specular = Vec4::new(0.4, 0.4, 0.4, 1.0);
    st.materials[FRONT].shininess = 20.0;
    st.enables.texture_2d[0] = true;
    st.enables.texture_gen[0] = [true, true, false, false];
    st.textures.units[0].gen[0].mode = gl::SPHERE_MAP;
    st.textures.units[0].gen[1].mode = gl::SPHERE_MAP;
    *st.modelview.top_mut() = Mat4::from_translation(Vec3::new(0.1, -0.2, -4.0));
    *st.projection.top_mut() = Mat4::perspective_rh_gl(1.0, 1.0, 0.5, 20.0);
    let mut rng = Rng(91);
    let mut b = Batch::default();
    let n = 3 * 1700;
    b.begin(gl::TRIANGLES);
    b.note_materials(&st.materials);
    for k in 0..n {
        if k == 2900 {
            let mut m = st.materials;
            m[FRONT].diffuse = Vec4::new(0.1, 0.8, 0.3, 1.0);
            b.materials_changed(&m);
        }
        let mut c = Current::default();
        c.normal = rng.vec3(-1.0, 1.0);
        b.vertex(rng.vec3(-2.0, 2.0).extend(1.0), &c);
    }
    b.end();
    let layout = Layout::for_state(&st);
    let ctx = SetupCtx::new(&st, layout, scissor_rect(&st), (1, 1));
    let run = |parallel| {
        let (mut out, mut wins) = (Vec::new(), Vec::new());
        process(&st, &b, &layout, &ctx, &mut out, &mut wins, parallel);
        let w: Vec<_> = wins
            .iter()
            .map(|w| (w.x.to_bits(), w.y.to_bits(), w.z.to_bits(), w.code))
            .collect();
        (out.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), w)
    };
    let (whole, split) = (run(false), run(true));
    assert_eq!(whole.0.len(), n * layout.stride);
    assert!(
        layout.tex[0].is_some(),
        "the layout carries no texture coordinates"
    );
    assert!(whole == split, "the split batch's vertices differ");
}
