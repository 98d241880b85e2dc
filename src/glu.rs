//! The GLU 1.3 matrix helpers lecture code leans on: `gluLookAt`, `gluPerspective` and
//! `gluOrtho2D` (GLU 1.3 §4.1, §4.2); `gluBuild2DMipmaps`; the quadrics (§6, `quadric.rs`:
//! `new_quadric`, `sphere`, `cylinder`, `disk`, `partial_disk`); `gluErrorString`.
//!
//! Design decision: like GLU itself, these are not GL entry points. Each builds its matrix on
//! the CPU and multiplies it onto the current matrix through the context's own calls
//! (`mult_matrixd`, `translated`, `ortho`), so a recording holds exactly what a real GLU
//! would have sent to the driver, and the GL backend needs no GLU.

use crate::Context;

// Quadrics (glu/quadric.rs)
mod quadric;
pub use quadric::{
    cylinder, delete_quadric, disk, new_quadric, partial_disk, quadric_callback,
    quadric_draw_style, quadric_normals, quadric_orientation, quadric_texture, sphere, Quadric,
    GLU_ERROR, GLU_FILL, GLU_FLAT, GLU_INSIDE, GLU_LINE, GLU_NONE, GLU_OUTSIDE, GLU_POINT,
    GLU_SILHOUETTE, GLU_SMOOTH,
};

// Tessellator (glu/tess.rs, the sweep in glu/tess_sweep.rs over the mesh of glu/tess_mesh.rs)
mod tess;
mod tess_mesh;
mod tess_sweep;
pub use tess::*;

// gluScaleImage, gluBuild2DMipmaps (glu/mipmap.rs)
mod mipmap;
pub use mipmap::{build_2d_mipmaps, scale_image};

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

/// `GLU_INVALID_VALUE`.
pub const GLU_INVALID_VALUE: i32 = 100_901;
/// `GLU_INVALID_ENUM`.
pub const GLU_INVALID_ENUM: i32 = 100_900;

/// `GLU_OUT_OF_MEMORY`.
pub const GLU_OUT_OF_MEMORY: i32 = 100_902;
/// `GLU_INCOMPATIBLE_GL_VERSION`.
pub const GLU_INCOMPATIBLE_GL_VERSION: i32 = 100_903;
/// `GLU_INVALID_OPERATION`.
pub const GLU_INVALID_OPERATION: i32 = 100_904;

/// `gluErrorString` (GLU 1.3 §2.5): the text Mesa's libGLU 9.0 gives each GL error, GLU error,
/// tessellator error (GLU_TESS_ERROR1 to 6) and NURBS error (GLU_NURBS_ERROR1 to 37), byte for
/// byte (typos included: a program may compare them); `None` (libGLU's NULL) for any other
/// value.
pub fn error_string(code: u32) -> Option<&'static str> {
    use crate::gl;
    Some(match code {
        gl::NO_ERROR => "no error",
        gl::INVALID_ENUM => "invalid enumerant",
        gl::INVALID_VALUE => "invalid value",
        gl::INVALID_OPERATION => "invalid operation",
        gl::STACK_OVERFLOW => "stack overflow",
        gl::STACK_UNDERFLOW => "stack underflow",
        gl::OUT_OF_MEMORY => "out of memory",
        // GL_INVALID_FRAMEBUFFER_OPERATION, GL_TABLE_TOO_LARGE.
        0x0506 => "invalid framebuffer operation",
        0x8031 => "table too large",
        100_900 => "invalid enumerant",
        100_901 => "invalid value",
        100_902 => "out of memory",
        100_903 => "incompatible gl version",
        100_904 => "invalid operation",
        100_151..=100_156 => TESS_ERRORS[(code - 100_151) as usize],
        100_251..=100_287 => NURBS_ERRORS[(code - 100_251) as usize],
        _ => return None,
    })
}

/// GLU_TESS_ERROR1 to GLU_TESS_ERROR6 (100151 to 100156).
const TESS_ERRORS: [&str; 6] = [
    "gluTessBeginPolygon() must precede a gluTessEndPolygon()",
    "gluTessBeginContour() must precede a gluTessEndContour()",
    "gluTessEndPolygon() must follow a gluTessBeginPolygon()",
    "gluTessEndContour() must follow a gluTessBeginContour()",
    "a coordinate is too large",
    "need combine callback",
];

/// GLU_NURBS_ERROR1 to GLU_NURBS_ERROR37 (100251 to 100287).
const NURBS_ERRORS: [&str; 37] = [
    "spline order un-supported",
    "too few knots",
    "valid knot range is empty",
    "decreasing knot sequence knot",
    "knot multiplicity greater than order of spline",
    "gluEndCurve() must follow gluBeginCurve()",
    "gluBeginCurve() must precede gluEndCurve()",
    "missing or extra geometric data",
    "can't draw piecewise linear trimming curves",
    "missing or extra domain data",
    "missing or extra domain data",
    "gluEndTrim() must precede gluEndSurface()",
    "gluBeginSurface() must precede gluEndSurface()",
    "curve of improper type passed as trim curve",
    "gluBeginSurface() must precede gluBeginTrim()",
    "gluEndTrim() must follow gluBeginTrim()",
    "gluBeginTrim() must precede gluEndTrim()",
    "invalid or missing trim curve",
    "gluBeginTrim() must precede gluPwlCurve()",
    "piecewise linear trimming curve referenced twice",
    "piecewise linear trimming curve and nurbs curve mixed",
    "improper usage of trim data type",
    "nurbs curve referenced twice",
    "nurbs curve and piecewise linear trimming curve mixed",
    "nurbs surface referenced twice",
    "invalid property",
    "gluEndSurface() must follow gluBeginSurface()",
    "intersecting or misoriented trim curves",
    "intersecting trim curves",
    "UNUSED",
    "unconnected trim curves",
    "unknown knot error",
    "negative vertex count encountered",
    "negative byte-stride encounteed",
    "unknown type descriptor",
    "null control point reference",
    "duplicate point on piecewise linear trimming curve",
];
