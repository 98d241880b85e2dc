//! GLU quadrics (GLU 1.3 §6): `gluNewQuadric` and its draw style, normals, orientation and
//! texture-coordinate settings; `gluSphere`, `gluCylinder`, `gluDisk`, `gluPartialDisk`.
//!
//! Each shape issues exactly the GL calls Mesa's libGLU 9.0 (`quad.c`) issues, in the same
//! order — the same primitives, and the same vertices, normals and texture coordinates bit for
//! bit: the sine and cosine tables are built in the same mix of single and double precision
//! (angles rounded to `float`, `sin`/`cos` in double, products rounded where C rounds them), so
//! a recording replays on the driver as the real libGLU would have drawn
//! (`tests/it/glu_quadric.rs` holds both streams to the driver's feedback buffer).
//!
//! Design decision: where libGLU reads a table it did not fill — FLAT normals with the POINT
//! style, FLAT normals with SILHOUETTE (its last loops), and the south pole's normal of a smooth
//! untextured sphere with more stacks than slices — it sends stack garbage (the pole normal is
//! garbage times sin π, next to zero). fixedgl fills every table, so those normals are the
//! smooth ones; every other call is libGLU's.

use std::f64::consts::PI;

use crate::{gl, Context};

/// `GLU_SMOOTH`: one normal per vertex (the default).
pub const GLU_SMOOTH: u32 = 100_000;
/// `GLU_FLAT`: one normal per facet.
pub const GLU_FLAT: u32 = 100_001;
/// `GLU_NONE`: no normals.
pub const GLU_NONE: u32 = 100_002;
/// `GLU_POINT`: the vertices as points.
pub const GLU_POINT: u32 = 100_010;
/// `GLU_LINE`: the edges as lines.
pub const GLU_LINE: u32 = 100_011;
/// `GLU_FILL`: filled polygons (the default).
pub const GLU_FILL: u32 = 100_012;
/// `GLU_SILHOUETTE`: the edges that separate non-coplanar faces (outline only).
pub const GLU_SILHOUETTE: u32 = 100_013;
/// `GLU_OUTSIDE`: normals point outwards (the default).
pub const GLU_OUTSIDE: u32 = 100_020;
/// `GLU_INSIDE`: normals point inwards.
pub const GLU_INSIDE: u32 = 100_021;
/// `GLU_ERROR`: the callback `quadric_callback` sets.
pub const GLU_ERROR: u32 = 100_103;

/// The cache size of libGLU's tables: more slices (and sphere stacks) than `CACHE_SIZE - 1`
/// are drawn as `CACHE_SIZE - 1`.
const CACHE_SIZE: i32 = 240;

/// A quadric object (`GLUquadric`): how its shapes are drawn. Dropping it is `gluDeleteQuadric`.
pub struct Quadric {
    normals: u32,
    texture_coords: bool,
    orientation: u32,
    draw_style: u32,
    error_callback: Option<Box<dyn FnMut(u32)>>,
    last_error: u32,
}

impl std::fmt::Debug for Quadric {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Quadric")
            .field("normals", &self.normals)
            .field("texture_coords", &self.texture_coords)
            .field("orientation", &self.orientation)
            .field("draw_style", &self.draw_style)
            .field("error_callback", &self.error_callback.is_some())
            .field("last_error", &self.last_error)
            .finish()
    }
}

impl Default for Quadric {
    fn default() -> Self {
        new_quadric()
    }
}

impl Quadric {
    /// The last error a call on this quadric reported (GLU_INVALID_ENUM or GLU_INVALID_VALUE),
    /// 0 if none yet; reading it clears it. Not in GLU, which reports errors only through the
    /// GLU_ERROR callback (which is called too).
    pub fn take_error(&mut self) -> u32 {
        std::mem::take(&mut self.last_error)
    }

    /// GLU_SMOOTH, GLU_FLAT or GLU_NONE.
    pub fn normals(&self) -> u32 {
        self.normals
    }

    /// Whether texture coordinates are generated.
    pub fn texture_coords(&self) -> bool {
        self.texture_coords
    }

    /// GLU_OUTSIDE or GLU_INSIDE.
    pub fn orientation(&self) -> u32 {
        self.orientation
    }

    /// GLU_FILL, GLU_LINE, GLU_SILHOUETTE or GLU_POINT.
    pub fn draw_style(&self) -> u32 {
        self.draw_style
    }

    fn error(&mut self, which: u32) {
        self.last_error = which;
        if let Some(cb) = self.error_callback.as_mut() {
            cb(which);
        }
    }
}

/// `gluNewQuadric`: GLU_SMOOTH normals, no texture coordinates, GLU_OUTSIDE, GLU_FILL, no
/// callback.
pub fn new_quadric() -> Quadric {
    Quadric {
        normals: GLU_SMOOTH,
        texture_coords: false,
        orientation: GLU_OUTSIDE,
        draw_style: GLU_FILL,
        error_callback: None,
        last_error: 0,
    }
}

/// `gluDeleteQuadric`: drops the quadric.
pub fn delete_quadric(q: Quadric) {
    drop(q);
}

/// `gluQuadricCallback(q, GLU_ERROR, f)`: `f` is called with the error code of each erroneous
/// call on `q` (`None` removes it). Another `which` is GLU_INVALID_ENUM.
pub fn quadric_callback(q: &mut Quadric, which: u32, f: Option<Box<dyn FnMut(u32)>>) {
    if which == GLU_ERROR {
        q.error_callback = f;
    } else {
        q.error(super::GLU_INVALID_ENUM as u32);
    }
}

/// `gluQuadricNormals`: GLU_SMOOTH, GLU_FLAT or GLU_NONE (else GLU_INVALID_ENUM, unchanged).
pub fn quadric_normals(q: &mut Quadric, normals: u32) {
    match normals {
        GLU_SMOOTH | GLU_FLAT | GLU_NONE => q.normals = normals,
        _ => q.error(super::GLU_INVALID_ENUM as u32),
    }
}

/// `gluQuadricTexture`: whether texture coordinates are generated.
pub fn quadric_texture(q: &mut Quadric, texture_coords: bool) {
    q.texture_coords = texture_coords;
}

/// `gluQuadricOrientation`: GLU_OUTSIDE or GLU_INSIDE (else GLU_INVALID_ENUM, unchanged).
pub fn quadric_orientation(q: &mut Quadric, orientation: u32) {
    match orientation {
        GLU_OUTSIDE | GLU_INSIDE => q.orientation = orientation,
        _ => q.error(super::GLU_INVALID_ENUM as u32),
    }
}

/// `gluQuadricDrawStyle`: GLU_POINT, GLU_LINE, GLU_FILL or GLU_SILHOUETTE (else
/// GLU_INVALID_ENUM, unchanged).
pub fn quadric_draw_style(q: &mut Quadric, draw_style: u32) {
    match draw_style {
        GLU_POINT | GLU_LINE | GLU_FILL | GLU_SILHOUETTE => q.draw_style = draw_style,
        _ => q.error(super::GLU_INVALID_ENUM as u32),
    }
}

/// An angle as libGLU keeps it: computed in double, stored in a `GLfloat`.
fn angle(a: f64) -> f32 {
    a as f32
}

/// libGLU's `SIN` and `COS` of a float angle: in double, stored back in a float.
fn sin(a: f32) -> f64 {
    f64::from(a).sin()
}
fn cos(a: f32) -> f64 {
    f64::from(a).cos()
}

/// `(float) n / d`, as C evaluates it (a float divided by an int promoted to float).
fn frac(n: i32, d: i32) -> f32 {
    n as f32 / d as f32
}

/// `1 - (float) n / d`, a float.
fn one_minus(n: i32, d: i32) -> f32 {
    1.0 - frac(n, d)
}

/// `gluCylinder` (GLU 1.3 §6.7): a cylinder (or cone) around +z from z = 0 (radius `base`) to
/// z = `height` (radius `top`), in `slices` around and `stacks` along. GLU_INVALID_VALUE (and
/// nothing drawn) for fewer than 2 slices or 1 stack, a negative radius or height, or a zero
/// slant length; more than 239 slices draw 239.
pub fn cylinder(
    ctx: &mut Context,
    q: &mut Quadric,
    base: f64,
    top: f64,
    height: f64,
    slices: i32,
    stacks: i32,
) {
    let slices = slices.min(CACHE_SIZE - 1);
    if slices < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0 {
        return q.error(super::GLU_INVALID_VALUE as u32);
    }
    let delta = (base - top) as f32;
    let length = (f64::from(delta * delta) + height * height).sqrt() as f32;
    if length == 0.0 {
        return q.error(super::GLU_INVALID_VALUE as u32);
    }
    let z_normal = delta / length;
    let ratio = (height / f64::from(length)) as f32;
    let outside = q.orientation == GLU_OUTSIDE;
    let signed = if outside { ratio } else { -ratio };
    let n = slices as usize;
    let mut sin1 = vec![0.0f32; n + 1];
    let mut cos1 = vec![0.0f32; n + 1];
    let mut sin2 = vec![0.0f32; n + 1];
    let mut cos2 = vec![0.0f32; n + 1];
    let mut sin3 = vec![0.0f32; n + 1];
    let mut cos3 = vec![0.0f32; n + 1];
    for i in 0..n {
        let a = angle(2.0 * PI * i as f64 / f64::from(slices));
        sin2[i] = (f64::from(signed) * sin(a)) as f32;
        cos2[i] = (f64::from(signed) * cos(a)) as f32;
        sin1[i] = sin(a) as f32;
        cos1[i] = cos(a) as f32;
        let a3 = angle(2.0 * PI * (i as f64 - 0.5) / f64::from(slices));
        sin3[i] = (f64::from(signed) * sin(a3)) as f32;
        cos3[i] = (f64::from(signed) * cos(a3)) as f32;
    }
    for t in [
        &mut sin1, &mut cos1, &mut sin2, &mut cos2, &mut sin3, &mut cos3,
    ] {
        t[n] = t[0];
    }
    let z_at = |j: i32| (f64::from(j) * height / f64::from(stacks)) as f32;
    let radius_at = |j: i32| (base - f64::from(delta * frac(j, stacks))) as f32;
    let tex = q.texture_coords;
    // The normal of vertex column i in the FILL, LINE and SILHOUETTE rings.
    let ring_normal = |ctx: &mut Context, i: usize| match q.normals {
        GLU_FLAT => ctx.normal3f(sin3[i], cos3[i], z_normal),
        GLU_SMOOTH => ctx.normal3f(sin2[i], cos2[i], z_normal),
        _ => {}
    };
    match q.draw_style {
        GLU_FILL => {
            for j in 0..stacks {
                let (z_low, z_high) = (z_at(j), z_at(j + 1));
                let (r_low, r_high) = (radius_at(j), radius_at(j + 1));
                ctx.begin(gl::QUAD_STRIP);
                for i in 0..=n {
                    ring_normal(ctx, i);
                    let s = one_minus(i as i32, slices);
                    let low = (frac(j, stacks), r_low * sin1[i], r_low * cos1[i], z_low);
                    let high = (
                        frac(j + 1, stacks),
                        r_high * sin1[i],
                        r_high * cos1[i],
                        z_high,
                    );
                    let order = if outside { [low, high] } else { [high, low] };
                    for (t, x, y, z) in order {
                        if tex {
                            ctx.tex_coord2f(s, t);
                        }
                        ctx.vertex3f(x, y, z);
                    }
                }
                ctx.end();
            }
        }
        GLU_POINT => {
            ctx.begin(gl::POINTS);
            for i in 0..n {
                if q.normals != GLU_NONE {
                    ctx.normal3f(sin2[i], cos2[i], z_normal);
                }
                for j in 0..=stacks {
                    let r = radius_at(j);
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), frac(j, stacks));
                    }
                    ctx.vertex3f(r * sin1[i], r * cos1[i], z_at(j));
                }
            }
            ctx.end();
        }
        GLU_LINE | GLU_SILHOUETTE => {
            // LINE: every inner ring, then (as SILHOUETTE) the two end rings and the lines
            // along z.
            let rings: Vec<i32> = if q.draw_style == GLU_LINE {
                (1..stacks).chain([0, stacks]).collect()
            } else {
                vec![0, stacks]
            };
            for j in rings {
                let r = radius_at(j);
                ctx.begin(gl::LINE_STRIP);
                for i in 0..=n {
                    ring_normal(ctx, i);
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), frac(j, stacks));
                    }
                    ctx.vertex3f(r * sin1[i], r * cos1[i], z_at(j));
                }
                ctx.end();
            }
            for i in 0..n {
                if q.normals != GLU_NONE {
                    ctx.normal3f(sin2[i], cos2[i], 0.0);
                }
                ctx.begin(gl::LINE_STRIP);
                for j in 0..=stacks {
                    let r = radius_at(j);
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), frac(j, stacks));
                    }
                    ctx.vertex3f(r * sin1[i], r * cos1[i], z_at(j));
                }
                ctx.end();
            }
        }
        _ => {}
    }
}

/// `gluDisk` (GLU 1.3 §6.8): `gluPartialDisk` from 0 through 360 degrees.
pub fn disk(ctx: &mut Context, q: &mut Quadric, inner: f64, outer: f64, slices: i32, loops: i32) {
    partial_disk(ctx, q, inner, outer, slices, loops, 0.0, 360.0);
}

/// `gluPartialDisk` (GLU 1.3 §6.9): the part of the annulus between radii `inner` and `outer`
/// in the z = 0 plane from `start` degrees (clockwise from +y) through `sweep` degrees, in
/// `slices` around and `loops` across. GLU_INVALID_VALUE (and nothing drawn) for fewer than 2
/// slices or 1 loop, a non-positive outer or negative inner radius, or inner > outer; a sweep
/// beyond ±360 draws 360 (as libGLU: below -360 too), a negative one is turned around.
#[allow(clippy::too_many_arguments)]
pub fn partial_disk(
    ctx: &mut Context,
    q: &mut Quadric,
    inner: f64,
    outer: f64,
    slices: i32,
    loops: i32,
    start: f64,
    sweep: f64,
) {
    let slices = slices.min(CACHE_SIZE - 1);
    if slices < 2 || loops < 1 || outer <= 0.0 || inner < 0.0 || inner > outer {
        return q.error(super::GLU_INVALID_VALUE as u32);
    }
    let (mut start, mut sweep) = (start, sweep);
    if !(-360.0..=360.0).contains(&sweep) {
        sweep = 360.0;
    }
    if sweep < 0.0 {
        start += sweep;
        sweep = -sweep;
    }
    let full = sweep == 360.0;
    let n = slices as usize;
    let slices2 = if full { n } else { n + 1 };
    let delta = (outer - inner) as f32;
    let offset = angle(start / 180.0 * PI);
    let mut sins = vec![0.0f32; n + 1];
    let mut coss = vec![0.0f32; n + 1];
    for i in 0..=n {
        let a = angle(f64::from(offset) + ((PI * sweep) / 180.0) * i as f64 / f64::from(slices));
        sins[i] = sin(a) as f32;
        coss[i] = cos(a) as f32;
    }
    if full {
        sins[n] = sins[0];
        coss[n] = coss[0];
    }
    let outside = q.orientation == GLU_OUTSIDE;
    if q.normals != GLU_NONE {
        ctx.normal3f(0.0, 0.0, if outside { 1.0 } else { -1.0 });
    }
    let tex = q.texture_coords;
    let radius_at = |j: i32| (outer - f64::from(delta * frac(j, loops))) as f32;
    let tex_scale = |r: f32| (f64::from(r) / outer / 2.0) as f32;
    // A vertex at radius `r` (texture scale `t`) on spoke i.
    let vertex = |ctx: &mut Context, r: f32, t: f32, i: usize| {
        if tex {
            ctx.tex_coord2f(
                (f64::from(t * sins[i]) + 0.5) as f32,
                (f64::from(t * coss[i]) + 0.5) as f32,
            );
        }
        ctx.vertex3f(r * sins[i], r * coss[i], 0.0);
    };
    match q.draw_style {
        GLU_FILL => {
            let finish = if inner == 0.0 {
                // The innermost loop as a fan around the centre.
                ctx.begin(gl::TRIANGLE_FAN);
                if tex {
                    ctx.tex_coord2f(0.5, 0.5);
                }
                ctx.vertex3f(0.0, 0.0, 0.0);
                let r = (outer - f64::from(delta * frac(loops - 1, loops))) as f32;
                let t = tex_scale(r);
                if outside {
                    for i in (0..=n).rev() {
                        vertex(ctx, r, t, i);
                    }
                } else {
                    for i in 0..=n {
                        vertex(ctx, r, t, i);
                    }
                }
                ctx.end();
                loops - 1
            } else {
                loops
            };
            for j in 0..finish {
                let (r_low, r_high) = (radius_at(j), radius_at(j + 1));
                let (t_low, t_high) = (tex_scale(r_low), tex_scale(r_high));
                ctx.begin(gl::QUAD_STRIP);
                for i in 0..=n {
                    if outside {
                        vertex(ctx, r_low, t_low, i);
                        vertex(ctx, r_high, t_high, i);
                    } else {
                        vertex(ctx, r_high, t_high, i);
                        vertex(ctx, r_low, t_low, i);
                    }
                }
                ctx.end();
            }
        }
        GLU_POINT => {
            ctx.begin(gl::POINTS);
            for i in 0..slices2 {
                for j in 0..=loops {
                    let r = radius_at(j);
                    vertex(ctx, r, tex_scale(r), i);
                }
            }
            ctx.end();
        }
        GLU_LINE => {
            if inner == outer {
                ctx.begin(gl::LINE_STRIP);
                for i in 0..=n {
                    if tex {
                        ctx.tex_coord2f(
                            (f64::from(sins[i] / 2.0) + 0.5) as f32,
                            (f64::from(coss[i] / 2.0) + 0.5) as f32,
                        );
                    }
                    ctx.vertex3f(
                        (inner * f64::from(sins[i])) as f32,
                        (inner * f64::from(coss[i])) as f32,
                        0.0,
                    );
                }
                ctx.end();
                return;
            }
            for j in 0..=loops {
                let r = radius_at(j);
                let t = tex_scale(r);
                ctx.begin(gl::LINE_STRIP);
                for i in 0..=n {
                    vertex(ctx, r, t, i);
                }
                ctx.end();
            }
            for i in 0..slices2 {
                ctx.begin(gl::LINE_STRIP);
                for j in 0..=loops {
                    let r = radius_at(j);
                    vertex(ctx, r, tex_scale(r), i);
                }
                ctx.end();
            }
        }
        GLU_SILHOUETTE => {
            if sweep < 360.0 {
                for i in [0, n] {
                    ctx.begin(gl::LINE_STRIP);
                    for j in 0..=loops {
                        let r = radius_at(j);
                        vertex(ctx, r, tex_scale(r), i);
                    }
                    ctx.end();
                }
            }
            for j in [0, loops] {
                let r = radius_at(j);
                let t = tex_scale(r);
                ctx.begin(gl::LINE_STRIP);
                for i in 0..=n {
                    vertex(ctx, r, t, i);
                }
                ctx.end();
                if inner == outer {
                    break;
                }
            }
        }
        _ => {}
    }
}

/// `gluSphere` (GLU 1.3 §6.6): a sphere of `radius` around the origin, `slices` around z and
/// `stacks` from +z to -z. GLU_INVALID_VALUE (and nothing drawn) for fewer than 2 slices or 1
/// stack, or a negative radius; more than 239 slices or stacks draw 239.
pub fn sphere(ctx: &mut Context, q: &mut Quadric, radius: f64, slices: i32, stacks: i32) {
    let slices = slices.min(CACHE_SIZE - 1);
    let stacks = stacks.min(CACHE_SIZE - 1);
    if slices < 2 || stacks < 1 || radius < 0.0 {
        return q.error(super::GLU_INVALID_VALUE as u32);
    }
    let (n, m) = (slices as usize, stacks as usize);
    let outside = q.orientation == GLU_OUTSIDE;
    // Around z (1a: vertices, = 2a: smooth normals; 3a: facet normals) and from +z to -z (1b:
    // vertices times the radius; 2b, 3b: normals, negated inside). The tables around z are
    // long enough for index `stacks` too (see the module docs).
    let len_a = n.max(m) + 1;
    let mut sin1a = vec![0.0f32; len_a];
    let mut cos1a = vec![0.0f32; len_a];
    let mut sin3a = vec![0.0f32; len_a];
    let mut cos3a = vec![0.0f32; len_a];
    for i in 0..len_a {
        let a = angle(2.0 * PI * i as f64 / f64::from(slices));
        sin1a[i] = sin(a) as f32;
        cos1a[i] = cos(a) as f32;
        let a3 = angle(2.0 * PI * (i as f64 - 0.5) / f64::from(slices));
        sin3a[i] = sin(a3) as f32;
        cos3a[i] = cos(a3) as f32;
    }
    for t in [&mut sin1a, &mut cos1a, &mut sin3a, &mut cos3a] {
        t[n] = t[0];
    }
    let (sin2a, cos2a) = (&sin1a, &cos1a);
    let mut sin1b = vec![0.0f32; m + 1];
    let mut cos1b = vec![0.0f32; m + 1];
    let mut sin2b = vec![0.0f32; m + 1];
    let mut cos2b = vec![0.0f32; m + 1];
    let mut sin3b = vec![0.0f32; m + 1];
    let mut cos3b = vec![0.0f32; m + 1];
    let sign = |v: f64| (if outside { v } else { -v }) as f32;
    for j in 0..=m {
        let a = angle(PI * j as f64 / f64::from(stacks));
        sin2b[j] = sign(sin(a));
        cos2b[j] = sign(cos(a));
        sin1b[j] = (radius * sin(a)) as f32;
        cos1b[j] = (radius * cos(a)) as f32;
        let a3 = angle(PI * (j as f64 - 0.5) / f64::from(stacks));
        sin3b[j] = sign(sin(a3));
        cos3b[j] = sign(cos(a3));
    }
    // Make sure it comes to a point.
    sin1b[0] = 0.0;
    sin1b[m] = 0.0;
    let tex = q.texture_coords;
    let normals = q.normals;
    let ring = |ctx: &mut Context, s: f32, z: f32, i: usize| {
        ctx.vertex3f(s * sin1a[i], s * cos1a[i], z);
    };
    match q.draw_style {
        GLU_FILL => {
            let (first, last) = if tex {
                (0, m)
            } else {
                // The poles as fans (not when texturing: the pole's texture coordinate differs
                // for every triangle around it).
                let (s2, z) = (sin1b[1], cos1b[1]);
                let (s3, c3) = match normals {
                    GLU_FLAT => (sin3b[1], cos3b[1]),
                    GLU_SMOOTH => {
                        ctx.normal3f(sin2a[0] * sin2b[0], cos2a[0] * sin2b[0], cos2b[0]);
                        (sin2b[1], cos2b[1])
                    }
                    _ => (0.0, 0.0),
                };
                ctx.begin(gl::TRIANGLE_FAN);
                ctx.vertex3f(0.0, 0.0, radius as f32);
                let fan = |ctx: &mut Context, i: usize, forward: bool| {
                    match normals {
                        GLU_SMOOTH => ctx.normal3f(sin2a[i] * s3, cos2a[i] * s3, c3),
                        GLU_FLAT if forward => ctx.normal3f(sin3a[i] * s3, cos3a[i] * s3, c3),
                        GLU_FLAT if i != n => {
                            ctx.normal3f(sin3a[i + 1] * s3, cos3a[i + 1] * s3, c3)
                        }
                        _ => {}
                    }
                    ring(ctx, s2, z, i);
                };
                if outside {
                    for i in (0..=n).rev() {
                        fan(ctx, i, false);
                    }
                } else {
                    for i in 0..=n {
                        fan(ctx, i, true);
                    }
                }
                ctx.end();
                let (s2, z) = (sin1b[m - 1], cos1b[m - 1]);
                let (s3, c3) = match normals {
                    GLU_FLAT => (sin3b[m], cos3b[m]),
                    GLU_SMOOTH => {
                        ctx.normal3f(sin2a[m] * sin2b[m], cos2a[m] * sin2b[m], cos2b[m]);
                        (sin2b[m - 1], cos2b[m - 1])
                    }
                    _ => (0.0, 0.0),
                };
                let fan = |ctx: &mut Context, i: usize, forward: bool| {
                    match normals {
                        GLU_SMOOTH => ctx.normal3f(sin2a[i] * s3, cos2a[i] * s3, c3),
                        GLU_FLAT if forward => ctx.normal3f(sin3a[i] * s3, cos3a[i] * s3, c3),
                        GLU_FLAT if i != n => {
                            ctx.normal3f(sin3a[i + 1] * s3, cos3a[i + 1] * s3, c3)
                        }
                        _ => {}
                    }
                    ring(ctx, s2, z, i);
                };
                ctx.begin(gl::TRIANGLE_FAN);
                ctx.vertex3f(0.0, 0.0, -radius as f32);
                if outside {
                    for i in 0..=n {
                        fan(ctx, i, true);
                    }
                } else {
                    for i in (0..=n).rev() {
                        fan(ctx, i, false);
                    }
                }
                ctx.end();
                (1, m - 1)
            };
            for j in first..last {
                let (z_low, z_high) = (cos1b[j], cos1b[j + 1]);
                let (s1, s2) = (sin1b[j], sin1b[j + 1]);
                // The normals of the upper (3) and lower (4) vertex of each pair, in the order
                // the pair is sent.
                let ((s3, c3), (s4, c4)) = match normals {
                    GLU_FLAT => ((0.0, 0.0), (sin3b[j + 1], cos3b[j + 1])),
                    GLU_SMOOTH if outside => ((sin2b[j + 1], cos2b[j + 1]), (sin2b[j], cos2b[j])),
                    GLU_SMOOTH => ((sin2b[j], cos2b[j]), (sin2b[j + 1], cos2b[j + 1])),
                    _ => ((0.0, 0.0), (0.0, 0.0)),
                };
                let (t_j, t_j1) = (one_minus(j as i32, stacks), one_minus(j as i32 + 1, stacks));
                ctx.begin(gl::QUAD_STRIP);
                for i in 0..=n {
                    if normals == GLU_SMOOTH {
                        ctx.normal3f(sin2a[i] * s3, cos2a[i] * s3, c3);
                    }
                    let s = one_minus(i as i32, slices);
                    if tex {
                        ctx.tex_coord2f(s, if outside { t_j1 } else { t_j });
                    }
                    if outside {
                        ring(ctx, s2, z_high, i);
                    } else {
                        ring(ctx, s1, z_low, i);
                    }
                    match normals {
                        GLU_SMOOTH => ctx.normal3f(sin2a[i] * s4, cos2a[i] * s4, c4),
                        GLU_FLAT => ctx.normal3f(sin3a[i] * s4, cos3a[i] * s4, c4),
                        _ => {}
                    }
                    if tex {
                        ctx.tex_coord2f(s, if outside { t_j } else { t_j1 });
                    }
                    if outside {
                        ring(ctx, s1, z_low, i);
                    } else {
                        ring(ctx, s2, z_high, i);
                    }
                }
                ctx.end();
            }
        }
        GLU_POINT => {
            ctx.begin(gl::POINTS);
            for j in 0..=m {
                let (s1, c1) = (sin1b[j], cos1b[j]);
                let (s2, c2) = (sin2b[j], cos2b[j]);
                for i in 0..n {
                    if normals != GLU_NONE {
                        ctx.normal3f(sin2a[i] * s2, cos2a[i] * s2, c2);
                    }
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), one_minus(j as i32, stacks));
                    }
                    ring(ctx, s1, c1, i);
                }
            }
            ctx.end();
        }
        GLU_LINE | GLU_SILHOUETTE => {
            // libGLU draws its silhouette as every line, as GLU_LINE.
            for j in 1..m {
                let (s1, c1) = (sin1b[j], cos1b[j]);
                let (s2, c2) = (sin2b[j], cos2b[j]);
                ctx.begin(gl::LINE_STRIP);
                for i in 0..=n {
                    match normals {
                        GLU_FLAT => ctx.normal3f(sin3a[i] * s2, cos3a[i] * s2, c2),
                        GLU_SMOOTH => ctx.normal3f(sin2a[i] * s2, cos2a[i] * s2, c2),
                        _ => {}
                    }
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), one_minus(j as i32, stacks));
                    }
                    ring(ctx, s1, c1, i);
                }
                ctx.end();
            }
            for i in 0..n {
                let (s1, c1) = (sin1a[i], cos1a[i]);
                let (s2, c2) = (sin2a[i], cos2a[i]);
                ctx.begin(gl::LINE_STRIP);
                for j in 0..=m {
                    match normals {
                        GLU_FLAT => ctx.normal3f(s2 * sin3b[j], c2 * sin3b[j], cos3b[j]),
                        GLU_SMOOTH => ctx.normal3f(s2 * sin2b[j], c2 * sin2b[j], cos2b[j]),
                        _ => {}
                    }
                    if tex {
                        ctx.tex_coord2f(one_minus(i as i32, slices), one_minus(j as i32, stacks));
                    }
                    ctx.vertex3f(s1 * sin1b[j], c1 * sin1b[j], cos1b[j]);
                }
                ctx.end();
            }
        }
        _ => {}
    }
}
