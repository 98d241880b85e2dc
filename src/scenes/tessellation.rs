//! `tessellation`: the GLU tessellator on the polygons a lecture uses it for, four panels.
//!
//! Top left: a five-pointed star with a star-shaped hole (two contours, ODD rule), one colour
//! per vertex, smooth shading. Top right: the same star filled flat with its triangles drawn
//! over it in wireframe, and its boundary (BOUNDARY_ONLY line loops). Bottom left: a
//! self-intersecting pentagram under NONZERO (all of it) and bottom right under ODD (the
//! points only) beside two overlapping squares under ABS_GEQ_TWO (their overlap); the
//! crossings are new vertices made by the COMBINE callback, which interpolates the colours.

use super::{Scene, LECTURE};
use crate::glu::{self, Tess, TessCallback};
use crate::{gl, Context};

/// A vertex: position and colour.
type V = [f64; 6];

/// Tessellates `contours` with `rule` straight into `gl` (BEGIN/VERTEX/END _DATA callbacks on
/// the context, COMBINE interpolating position and colour).
fn tessellate(gl: &mut Context, rule: u32, boundary_only: bool, contours: &[Vec<V>]) {
    let mut t: Tess<V, &mut Context> = glu::new_tess();
    t.callback(TessCallback::BeginData(Box::new(|ty, gl| {
        if let Some(gl) = gl {
            gl.begin(ty);
        }
    })));
    t.callback(TessCallback::VertexData(Box::new(|v, gl| {
        if let Some(gl) = gl {
            gl.color3d(v[3], v[4], v[5]);
            gl.vertex3d(v[0], v[1], v[2]);
        }
    })));
    t.callback(TessCallback::EndData(Box::new(|gl| {
        if let Some(gl) = gl {
            gl.end();
        }
    })));
    t.callback(TessCallback::Combine(Box::new(|c, data, w| {
        let mut out = [c[0], c[1], c[2], 0.0, 0.0, 0.0];
        for (d, w) in data.iter().zip(w) {
            if let Some(d) = d {
                for k in 3..6 {
                    out[k] += f64::from(w) * d[k];
                }
            }
        }
        Some(out)
    })));
    t.property(glu::GLU_TESS_WINDING_RULE, f64::from(rule));
    t.property(
        glu::GLU_TESS_BOUNDARY_ONLY,
        if boundary_only { 1.0 } else { 0.0 },
    );
    t.normal(0.0, 0.0, 1.0);
    t.begin_polygon(gl);
    for c in contours {
        t.begin_contour();
        for v in c {
            t.vertex([v[0], v[1], v[2]], *v);
        }
        t.end_contour();
    }
    t.end_polygon();
}

/// A star of `points` points around (cx, cy), colours running around the hue circle.
fn star(cx: f64, cy: f64, r_out: f64, r_in: f64, points: usize, reverse: bool) -> Vec<V> {
    let n = 2 * points;
    let mut v: Vec<V> = (0..n)
        .map(|k| {
            let r = if k % 2 == 0 { r_out } else { r_in };
            let a = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::TAU / n as f64;
            let h = k as f64 / n as f64 * std::f64::consts::TAU;
            [
                cx + r * a.cos(),
                cy + r * a.sin(),
                0.0,
                0.55 + 0.45 * h.cos(),
                0.55 + 0.45 * (h + 2.1).cos(),
                0.55 + 0.45 * (h + 4.2).cos(),
            ]
        })
        .collect();
    if reverse {
        v.reverse();
    }
    v
}

fn pentagram(cx: f64, cy: f64, r: f64) -> Vec<V> {
    (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + k as f64 * 2.0 * std::f64::consts::TAU / 5.0;
            let h = k as f64 / 5.0;
            [
                cx + r * a.cos(),
                cy + r * a.sin(),
                0.0,
                0.95,
                0.3 + 0.6 * h,
                0.2 + 0.3 * (1.0 - h),
            ]
        })
        .collect()
}

fn square(x: f64, y: f64, s: f64, rgb: [f64; 3]) -> Vec<V> {
    [(0.0, 0.0), (s, 0.0), (s, s), (0.0, s)]
        .iter()
        .map(|&(dx, dy)| [x + dx, y + dy, 0.0, rgb[0], rgb[1], rgb[2]])
        .collect()
}

fn recolor(c: &[V], rgb: [f64; 3]) -> Vec<V> {
    c.iter()
        .map(|v| [v[0], v[1], v[2], rgb[0], rgb[1], rgb[2]])
        .collect()
}

fn panel(gl: &mut Context, k: i32) {
    let (w, h) = gl.size();
    let (pw, ph) = (w as i32 / 2, h as i32 / 2);
    gl.viewport((k % 2) * pw, (1 - k / 2) * ph, pw, ph);
    gl.matrix_mode(gl::PROJECTION);
    gl.load_identity();
    glu::ortho_2d(gl, -1.2, 1.2, -1.2, 1.2);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
}

/// The `tessellation` scene.
pub fn tessellation(gl: &mut Context) {
    gl.clear_color(0.1, 0.1, 0.14, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT);
    gl.shade_model(gl::SMOOTH);
    let outer = star(0.0, 0.0, 1.05, 0.45, 5, false);
    let hole = star(0.0, 0.0, 0.38, 0.18, 5, true);
    let odd = glu::GLU_TESS_WINDING_ODD;

    // Top left: the star with a hole, smooth colours.
    panel(gl, 0);
    tessellate(gl, odd, false, &[outer.clone(), hole.clone()]);

    // Top right: flat fill, the triangles in wireframe, the boundary thick.
    panel(gl, 1);
    let fill = [0.25, 0.45, 0.8];
    tessellate(
        gl,
        odd,
        false,
        &[recolor(&outer, fill), recolor(&hole, fill)],
    );
    gl.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    let wire = [0.75, 0.85, 1.0];
    tessellate(
        gl,
        odd,
        false,
        &[recolor(&outer, wire), recolor(&hole, wire)],
    );
    gl.polygon_mode(gl::FRONT_AND_BACK, gl::FILL);
    gl.line_width(3.0);
    let edge = [1.0, 0.8, 0.3];
    tessellate(
        gl,
        odd,
        true,
        &[recolor(&outer, edge), recolor(&hole, edge)],
    );
    gl.line_width(1.0);

    // Bottom left: the pentagram under NONZERO.
    panel(gl, 2);
    tessellate(
        gl,
        glu::GLU_TESS_WINDING_NONZERO,
        false,
        &[pentagram(0.0, 0.0, 1.1)],
    );

    // Bottom right: the pentagram under ODD, overlapping squares under ABS_GEQ_TWO.
    panel(gl, 3);
    tessellate(gl, odd, false, &[pentagram(-0.45, 0.4, 0.7)]);
    tessellate(
        gl,
        glu::GLU_TESS_WINDING_ABS_GEQ_TWO,
        false,
        &[
            square(-0.05, -1.1, 0.9, [0.3, 0.9, 0.5]),
            square(0.25, -0.8, 0.9, [0.9, 0.3, 0.8]),
        ],
    );
    gl.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    for s in [
        square(-0.05, -1.1, 0.9, [0.6, 0.6, 0.6]),
        square(0.25, -0.8, 0.9, [0.6, 0.6, 0.6]),
    ] {
        gl.begin(gl::QUADS);
        for v in &s {
            gl.color3d(v[3], v[4], v[5]);
            gl.vertex3d(v[0], v[1], v[2]);
        }
        gl.end();
    }
    gl.polygon_mode(gl::FRONT_AND_BACK, gl::FILL);
}

/// The tessellation scene, for the registry.
pub(super) const SCENES: [Scene; 1] = [Scene {
    name: "tessellation",
    summary: "GLU tessellator: a star with a star-shaped hole (ODD), its triangles and BOUNDARY_ONLY outline, a pentagram under NONZERO and ODD, overlapping squares under ABS_GEQ_TWO, COMBINE interpolating colours (gluNewTess, gluTessCallback, gluTessVertex)",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: tessellation,
    animate: None,
}];
