//! The GLU 1.3 matrix helpers lecture code leans on: `gluLookAt`, `gluPerspective` and
//! `gluOrtho2D` (GLU 1.3 §4.1, §4.2).
//!
//! Design decision: like GLU itself, these are not GL entry points. Each builds its matrix on
//! the CPU and multiplies it onto the current matrix through the context's own calls
//! (`mult_matrixd`, `translated`, `ortho`), so a recording holds exactly what a real GLU
//! would have sent to the driver, and the GL backend needs no GLU.

use crate::Context;

/// `v / |v|`, or `v` unchanged when it has zero length (as the reference GLU does).
fn normalize(v: [f64; 3]) -> [f64; 3] {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if len == 0.0 {
        v
    } else {
        [v[0] / len, v[1] / len, v[2] / len]
    }
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `gluLookAt`: a viewing transform with the eye at `(ex, ey, ez)` looking at
/// `(cx, cy, cz)`, `(ux, uy, uz)` giving the up direction. With f = normalize(center − eye),
/// s = normalize(f × up) and u = s × f, multiplies the current matrix by the rotation whose
/// rows are s, u, −f, then by a translation by −eye (GLU 1.3 §4.1; the reference GLU
/// normalises s, which the spec's text omits, so a non-perpendicular up still gives a
/// rotation).
#[allow(clippy::too_many_arguments)]
pub fn look_at(
    ctx: &mut Context,
    ex: f64,
    ey: f64,
    ez: f64,
    cx: f64,
    cy: f64,
    cz: f64,
    ux: f64,
    uy: f64,
    uz: f64,
) {
    let f = normalize([cx - ex, cy - ey, cz - ez]);
    let s = normalize(cross(f, [ux, uy, uz]));
    let u = cross(s, f);
    // Column-major: column j holds (s[j], u[j], -f[j], 0).
    #[rustfmt::skip]
    let m = [
        s[0], u[0], -f[0], 0.0,
        s[1], u[1], -f[1], 0.0,
        s[2], u[2], -f[2], 0.0,
        0.0, 0.0, 0.0, 1.0,
    ];
    ctx.mult_matrixd(&m);
    ctx.translated(-ex, -ey, -ez);
}

/// `gluPerspective`: a symmetric perspective projection with vertical field of view `fovy`
/// degrees, `aspect` = width / height, and clip distances `near`, `far` (GLU 1.3 §4.2). With
/// f = cot(fovy / 2) the matrix is
///
/// ```text
/// f/aspect  0  0                          0
/// 0         f  0                          0
/// 0         0  (far+near)/(near−far)      2·far·near/(near−far)
/// 0         0  −1                         0
/// ```
///
/// As the reference GLU does, nothing happens when `near == far`, `aspect == 0` or
/// sin(fovy / 2) == 0 (no matrix exists; GLU defines no error for it).
pub fn perspective(ctx: &mut Context, fovy: f64, aspect: f64, near: f64, far: f64) {
    let half = (fovy / 2.0).to_radians();
    let (sine, cosine) = half.sin_cos();
    let depth = far - near;
    if depth == 0.0 || sine == 0.0 || aspect == 0.0 {
        return;
    }
    let f = cosine / sine;
    #[rustfmt::skip]
    let m = [
        f / aspect, 0.0, 0.0, 0.0,
        0.0, f, 0.0, 0.0,
        0.0, 0.0, -(far + near) / depth, -1.0,
        0.0, 0.0, -2.0 * near * far / depth, 0.0,
    ];
    ctx.mult_matrixd(&m);
}

/// `gluOrtho2D`: `ortho(left, right, bottom, top, -1, 1)` (GLU 1.3 §4.1).
pub fn ortho_2d(ctx: &mut Context, left: f64, right: f64, bottom: f64, top: f64) {
    ctx.ortho(left, right, bottom, top, -1.0, 1.0);
}
