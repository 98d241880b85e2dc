//! The accumulation buffer scenes (GL 2.1 §4.2.4), the two Red Book techniques lecture
//! programs use it for:
//!
//! - `accum-depth-of-field`: the scene drawn [`J8`]`.len()` times through jittered frusta
//!   ([`acc_perspective`]): each pass moves the eye within a small aperture while keeping the
//!   plane at the focus distance fixed on the screen, and shifts the image by a fraction of a
//!   pixel (antialiasing); `Accum(ACCUM, 1/n)` after each pass, `Accum(RETURN, 1)` at the end.
//!   Objects at the focus distance stay sharp, nearer and farther ones blur.
//! - `accum-motion-blur`: successive positions of moving objects, each pass folded into the
//!   accumulation buffer with `Accum(MULT, decay)` then `Accum(ACCUM, 1 - decay)` (the first
//!   with `Accum(LOAD, 1)`), so older positions fade; `Accum(RETURN, 1)` shows the trail.
//!
//! Both need a framebuffer with an accumulation buffer: their [`Scene::config`] asks for one,
//! and the runner makes both backends' framebuffers with it (the GL backend's FBO stands in for
//! it, see `glbackend/buffers.rs`).

use crate::gl::*;
use crate::state::ContextConfig;
use crate::{glu, glut, Context};

use super::{Scene, LECTURE};

/// The framebuffer these scenes draw on: the default one with an accumulation buffer.
pub const ACCUM_CONFIG: ContextConfig = ContextConfig {
    double_buffered: false,
    depth: true,
    stencil: true,
    accum: true,
    alpha: true,
};

/// The scenes of this module, for the registry.
pub const SCENES: [Scene; 2] = [
    Scene {
        name: "accum-motion-blur",
        summary: "Accumulation buffer: motion blur — twelve positions of a bouncing ball and a spinning bar over a \
                  lit floor, each folded in with Accum(MULT, 0.75) and Accum(ACCUM, 0.25) after Accum(LOAD) of the \
                  first, then Accum(RETURN): a fading trail under the sharp last position",
        tolerance: LECTURE,
        default_size: (512, 384),
        draw: motion_blur,
        animate: None,
        config: ACCUM_CONFIG,
    },
    Scene {
        name: "accum-depth-of-field",
        summary: "Accumulation buffer: depth of field — five lit teapots at increasing depths over a checkered \
                  floor, drawn eight times through jittered frusta (accPerspective with the j8 jitter table: eye \
                  offsets around the focus plane and sub-pixel shifts), Accum(ACCUM, 1/8) each, Accum(RETURN)",
        tolerance: LECTURE,
        default_size: (512, 384),
        draw: depth_of_field,
        animate: None,
        config: ACCUM_CONFIG,
    },
];

/// The Red Book's jitter tables (`jitter.h`): sample offsets within a pixel, in pixels, centred
/// on 0, for 2, 3, 4 and 8 passes.
pub const J2: [[f64; 2]; 2] = [[0.246490, 0.249999], [-0.246490, -0.249999]];
/// Three-pass jitter.
pub const J3: [[f64; 2]; 3] = [
    [-0.373411, -0.250550],
    [0.256263, 0.368119],
    [0.117148, -0.117570],
];
/// Four-pass jitter.
pub const J4: [[f64; 2]; 4] = [
    [-0.208147, 0.353730],
    [0.203849, -0.353780],
    [-0.292626, -0.149945],
    [0.296924, 0.149994],
];
/// Eight-pass jitter.
pub const J8: [[f64; 2]; 8] = [
    [-0.334818, 0.435331],
    [0.286438, -0.393495],
    [0.459462, 0.141540],
    [-0.414498, -0.192829],
    [-0.183790, 0.082102],
    [-0.079263, -0.317383],
    [0.102254, 0.299133],
    [0.164216, -0.054399],
];

/// The Red Book's `accFrustum`: `Frustum(left, right, bottom, top, near, far)` on a fresh
/// projection matrix, shifted by (`pixdx`, `pixdy`) pixels of the current viewport (for
/// antialiasing) and sheared so that an eye moved by (`eyedx`, `eyedy`) still sees the plane at
/// distance `focus` in the same place (depth of field); the modelview matrix is reset to the
/// eye translation, in MODELVIEW mode. Draw the scene after it, relative to that.
#[allow(clippy::too_many_arguments)]
pub fn acc_frustum(
    gl: &mut Context,
    [left, right, bottom, top]: [f64; 4],
    near: f64,
    far: f64,
    pixd: [f64; 2],
    eyed: [f64; 2],
    focus: f64,
) {
    let mut vp = [0i32; 4];
    gl.get_integerv(VIEWPORT, &mut vp);
    let (xw, yw) = (right - left, top - bottom);
    let vw = f64::from(vp[2].max(1));
    let vh = f64::from(vp[3].max(1));
    let dx = -(pixd[0] * xw / vw + eyed[0] * near / focus);
    let dy = -(pixd[1] * yw / vh + eyed[1] * near / focus);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    gl.frustum(left + dx, right + dx, bottom + dy, top + dy, near, far);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    gl.translatef(-eyed[0] as f32, -eyed[1] as f32, 0.0);
}

/// The Red Book's `accPerspective`: [`acc_frustum`] of the frustum `gluPerspective(fovy,
/// aspect, near, far)` describes.
pub fn acc_perspective(
    gl: &mut Context,
    [fovy, aspect, near, far]: [f64; 4],
    pixd: [f64; 2],
    eyed: [f64; 2],
    focus: f64,
) {
    let half = fovy.to_radians() / 2.0;
    let top = near * half.tan();
    let right = top * aspect;
    acc_frustum(gl, [-right, right, -top, top], near, far, pixd, eyed, focus);
}

/// The viewport's aspect ratio.
fn aspect(gl: &mut Context) -> f64 {
    let mut vp = [0i32; 4];
    gl.get_integerv(VIEWPORT, &mut vp);
    f64::from(vp[2].max(1)) / f64::from(vp[3].max(1))
}

/// One directional white light, colour material for ambient and diffuse, a little specular.
fn lights(gl: &mut Context) {
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.lightfv(LIGHT0, DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.25, 0.25, 0.25, 1.0]);
    gl.enable(NORMALIZE);
    gl.enable(DEPTH_TEST);
}

/// A checkered floor of `n` x `n` unit squares centred on the origin at height `y`, its squares
/// alternating between two colours (COLOR_MATERIAL must be on for them to show).
fn floor(gl: &mut Context, n: i32, y: f32, a: [f32; 3], b: [f32; 3]) {
    gl.normal3f(0.0, 1.0, 0.0);
    gl.begin(QUADS);
    let h = n as f32 / 2.0;
    for i in 0..n {
        for j in 0..n {
            let c = if (i + j) % 2 == 0 { a } else { b };
            gl.color3f(c[0], c[1], c[2]);
            let (x, z) = (i as f32 - h, j as f32 - h);
            gl.vertex3f(x, y, z);
            gl.vertex3f(x, y, z + 1.0);
            gl.vertex3f(x + 1.0, y, z + 1.0);
            gl.vertex3f(x + 1.0, y, z);
        }
    }
    gl.end();
}

/// The motion blur's positions.
const BLUR_FRAMES: usize = 12;
/// How much of the accumulated image each new position keeps.
const DECAY: f32 = 0.75;

/// The moving objects at step `k` of [`BLUR_FRAMES`]: a ball bouncing from left to right and a
/// bar turning like a propeller.
fn movers(gl: &mut Context, k: usize) {
    let s = k as f32 / (BLUR_FRAMES - 1) as f32;
    // The ball: across the floor, two bounces.
    let x = -4.5 + 8.0 * s;
    let y = 0.6 + 2.0 * (std::f32::consts::PI * 2.0 * s).sin().abs();
    gl.push_matrix();
    gl.translatef(x, y, 1.0);
    gl.color3f(0.9, 0.25, 0.15);
    glut::solid_sphere(gl, 0.6, 24, 16);
    gl.pop_matrix();
    // The bar: a quarter turn over the frames, in the picture's plane.
    gl.push_matrix();
    gl.translatef(-2.2, 2.2, -3.0);
    gl.rotatef(10.0 + 90.0 * s, 0.0, 0.0, 1.0);
    gl.scalef(3.0, 0.35, 0.35);
    gl.color3f(0.2, 0.45, 0.9);
    glut::solid_cube(gl, 1.0);
    gl.pop_matrix();
}

/// Step `k` of the motion: the floor, a still cone (for comparison) and [`movers`].
fn blur_frame(gl: &mut Context, k: usize) {
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    floor(gl, 12, 0.0, [0.75, 0.75, 0.7], [0.25, 0.3, 0.35]);
    gl.push_matrix();
    gl.translatef(2.8, 0.0, -3.0);
    gl.rotatef(-90.0, 1.0, 0.0, 0.0);
    gl.color3f(0.3, 0.75, 0.35);
    glut::solid_cone(gl, 0.5, 2.5, 20, 4);
    gl.pop_matrix();
    movers(gl, k);
}

/// `accum-motion-blur`: the positions of [`blur_frame`] folded into the accumulation buffer,
/// newest strongest; then the newest position drawn over the trail, sharp (its depths are
/// those of the last pass, still in the depth buffer: LEQUAL lets it through).
pub fn motion_blur(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.14, 1.0);
    gl.clear_accum(0.0, 0.0, 0.0, 0.0);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    let a = aspect(gl);
    glu::perspective(gl, 40.0, a, 1.0, 40.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 4.0, 11.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0);
    lights(gl);
    gl.lightfv(LIGHT0, POSITION, &[-2.0, 5.0, 4.0, 0.0]);
    gl.enable(COLOR_MATERIAL);
    gl.color_material(FRONT, AMBIENT_AND_DIFFUSE);
    gl.materialfv(FRONT, SPECULAR, &[0.4, 0.4, 0.4, 1.0]);
    gl.materialf(FRONT, SHININESS, 40.0);
    for k in 0..BLUR_FRAMES {
        blur_frame(gl, k);
        if k == 0 {
            gl.accum(LOAD, 1.0);
        } else {
            gl.accum(MULT, DECAY);
            gl.accum(ACCUM, 1.0 - DECAY);
        }
    }
    gl.accum(RETURN, 1.0);
    gl.depth_func(LEQUAL);
    movers(gl, BLUR_FRAMES - 1);
}

/// The teapots: position and the material's ambient, diffuse, specular and shininess (the Red
/// Book's ruby, gold, silver, emerald and cyan plastic, as `dof.c` names them).
#[allow(clippy::type_complexity)]
const TEAPOTS: [([f32; 3], [f32; 3], [f32; 3], [f32; 3], f32); 5] = [
    (
        [-1.1, -0.5, -4.5],
        [0.1745, 0.01175, 0.01175],
        [0.61424, 0.04136, 0.04136],
        [0.727811, 0.626959, 0.626959],
        0.6,
    ),
    (
        [-0.5, -0.5, -5.0],
        [0.24725, 0.1995, 0.0745],
        [0.75164, 0.60648, 0.22648],
        [0.628281, 0.555802, 0.366065],
        0.4,
    ),
    (
        [0.2, -0.5, -5.5],
        [0.19225, 0.19225, 0.19225],
        [0.50754, 0.50754, 0.50754],
        [0.508273, 0.508273, 0.508273],
        0.4,
    ),
    (
        [1.0, -0.5, -6.0],
        [0.0215, 0.1745, 0.0215],
        [0.07568, 0.61424, 0.07568],
        [0.633, 0.727811, 0.633],
        0.6,
    ),
    (
        [1.8, -0.5, -6.5],
        [0.0, 0.1, 0.06],
        [0.0, 0.509_803_9, 0.509_803_9],
        [0.501_960_8, 0.501_960_8, 0.501_960_8],
        0.25,
    ),
];

/// The jittered passes of the depth of field, and the eye's aperture (in eye units per unit of
/// jitter).
const APERTURE: f64 = 0.33;
/// The distance that stays in focus: the middle (silver) teapot's.
const FOCUS: f64 = 5.5;

/// `accum-depth-of-field`: eight passes through [`acc_perspective`] with [`J8`] as both eye and
/// sub-pixel jitter, accumulated at 1/8 each.
pub fn depth_of_field(gl: &mut Context) {
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_accum(0.0, 0.0, 0.0, 0.0);
    gl.clear(ACCUM_BUFFER_BIT);
    lights(gl);
    gl.front_face(CW);
    let a = aspect(gl);
    let n = J8.len();
    for j in J8 {
        gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
        acc_perspective(
            gl,
            [45.0, a, 1.0, 15.0],
            j,
            [APERTURE * j[0], APERTURE * j[1]],
            FOCUS,
        );
        // The light in eye coordinates, after the eye's own translation.
        gl.lightfv(LIGHT0, POSITION, &[0.0, 3.0, 3.0, 0.0]);
        // The floor, in colour material (the teapots' materials are set explicitly).
        gl.front_face(CCW);
        gl.enable(COLOR_MATERIAL);
        gl.color_material(FRONT, AMBIENT_AND_DIFFUSE);
        gl.materialfv(FRONT, SPECULAR, &[0.0, 0.0, 0.0, 1.0]);
        gl.push_matrix();
        gl.translatef(0.0, 0.0, -5.5);
        floor(gl, 10, -0.8, [0.55, 0.55, 0.6], [0.15, 0.15, 0.2]);
        gl.pop_matrix();
        gl.disable(COLOR_MATERIAL);
        // glutSolidTeapot's faces wind clockwise.
        gl.front_face(CW);
        for (pos, amb, dif, spec, shine) in TEAPOTS {
            gl.push_matrix();
            gl.translatef(pos[0], pos[1], pos[2]);
            gl.materialfv(FRONT, AMBIENT, &[amb[0], amb[1], amb[2], 1.0]);
            gl.materialfv(FRONT, DIFFUSE, &[dif[0], dif[1], dif[2], 1.0]);
            gl.materialfv(FRONT, SPECULAR, &[spec[0], spec[1], spec[2], 1.0]);
            gl.materialf(FRONT, SHININESS, shine * 128.0);
            glut::solid_teapot(gl, 0.5);
            gl.pop_matrix();
        }
        gl.accum(ACCUM, 1.0 / n as f32);
    }
    gl.accum(RETURN, 1.0);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The jitter tables are centred within a pixel, as the Red Book's are: every offset in
    /// (-0.5, 0.5), their mean near 0.
    #[test]
    fn jitter_tables_lie_within_a_pixel() {
        let tables: [&[[f64; 2]]; 4] = [&J2, &J3, &J4, &J8];
        for t in tables {
            assert!(t.iter().flatten().all(|v| v.abs() < 0.5));
            for k in 0..2 {
                let mean = t.iter().map(|p| p[k]).sum::<f64>() / t.len() as f64;
                assert!(mean.abs() < 0.05, "{mean}");
            }
        }
    }

    /// acc_perspective with no jitter is gluPerspective's matrix, and an eye offset keeps the
    /// focus plane's centre where it was.
    #[test]
    fn acc_perspective_without_jitter_is_glu_perspective() {
        let mut a = Context::new(64, 48).unwrap();
        acc_perspective(
            &mut a,
            [45.0, 4.0 / 3.0, 1.0, 15.0],
            [0.0; 2],
            [0.0; 2],
            5.0,
        );
        let mut b = Context::new(64, 48).unwrap();
        b.matrix_mode(PROJECTION);
        glu::perspective(&mut b, 45.0, 4.0 / 3.0, 1.0, 15.0);
        let (mut pa, mut pb) = ([0.0f32; 16], [0.0f32; 16]);
        a.get_floatv(PROJECTION_MATRIX, &mut pa);
        b.get_floatv(PROJECTION_MATRIX, &mut pb);
        for (x, y) in pa.iter().zip(&pb) {
            assert!((x - y).abs() < 1e-6, "{pa:?} vs {pb:?}");
        }
        // Eye moved by 0.2 to the right: the point at (0, 0, -5) stays at the viewport's centre.
        acc_perspective(
            &mut a,
            [45.0, 4.0 / 3.0, 1.0, 15.0],
            [0.0; 2],
            [0.2, 0.0],
            5.0,
        );
        let mut mv = [0.0f64; 16];
        let mut pr = [0.0f64; 16];
        a.get_doublev(MODELVIEW_MATRIX, &mut mv);
        a.get_doublev(PROJECTION_MATRIX, &mut pr);
        let win = glu::project([0.0, 0.0, -5.0], &mv, &pr, [0, 0, 64, 48]);
        let [x, y, _] = win.expect("projects");
        assert!(
            (x - 32.0).abs() < 1e-5 && (y - 24.0).abs() < 1e-5,
            "{x} {y}"
        );
    }
}
