//! The GLUT solids and wires lecture code draws with: sphere, cube, cone, torus and the Utah
//! teapot, with the vertices, winding and normals freeglut 3.x gives them (fg_geometry.c,
//! fg_teapot.c), and its bitmap and stroke fonts (`bitmap_character`, `stroke_character` and friends, in
//! `text`).
//!
//! Each shape is first built as a [`Mesh`] (vertex and normal arrays plus index lists, one per
//! Begin/End part, exactly as freeglut builds them), then drawn through the context's own
//! `begin`/`normal3fv`/`vertex3fv`/`end` (freeglut's GL 1.0 path, which draws the same
//! primitives its vertex-array path does), so a shape is recorded and compiled into display
//! lists like any other drawing.
//!
//! Design decision: freeglut indexes with 16-bit integers and warns (then draws garbage) past
//! 65535 vertices; here a shape that would need more draws nothing, which also bounds the memory
//! a caller's `slices`/`stacks` can make us allocate.

mod bitmap_fonts;
mod stroke_fonts;
mod teapot;
mod text;

pub use text::{
    bitmap_character, bitmap_height, bitmap_length, bitmap_string, bitmap_width, BitmapFont,
    BitmapFontData, BITMAP_8_BY_13, BITMAP_9_BY_15, BITMAP_HELVETICA_10, BITMAP_HELVETICA_12,
    BITMAP_HELVETICA_18, BITMAP_TIMES_ROMAN_10, BITMAP_TIMES_ROMAN_24,
};
pub use text::{
    stroke_character, stroke_height, stroke_length, stroke_lengthf, stroke_string, stroke_width,
    stroke_widthf, StrokeFont, StrokeFontData, StrokeGlyph, STROKE_MONO_ROMAN, STROKE_ROMAN,
};

use crate::{gl, Context};

/// The most vertices one shape may have (freeglut's GLushort index limit).
pub const MAX_VERTICES: usize = 65535;

/// A shape as freeglut builds it: unique vertex/normal pairs, and the parts that draw them.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Object-space positions.
    pub vertices: Vec<[f32; 3]>,
    /// One normal per vertex (unit length, pointing out of the solid).
    pub normals: Vec<[f32; 3]>,
    /// Texture coordinates per vertex (the solid teapot only).
    pub tex_coords: Option<Vec<[f32; 2]>>,
    /// Each part is one Begin(mode) .. End with these vertex indices.
    pub parts: Vec<(u32, Vec<u32>)>,
}

impl Mesh {
    /// Draws the mesh: per part `begin(mode)`, then per index `tex_coord2fv` (if any),
    /// `normal3fv`, `vertex3fv`, then `end`.
    pub fn draw(&self, ctx: &mut Context) {
        for (mode, indices) in &self.parts {
            ctx.begin(*mode);
            for &i in indices {
                let i = i as usize;
                if let Some(t) = self.tex_coords.as_ref().and_then(|t| t.get(i)) {
                    ctx.tex_coord2fv(t);
                }
                if let (Some(n), Some(v)) = (self.normals.get(i), self.vertices.get(i)) {
                    ctx.normal3fv(n);
                    ctx.vertex3fv(v);
                }
            }
            ctx.end();
        }
    }

    /// How many vertices the parts send (indices over all parts).
    pub fn emitted_vertices(&self) -> usize {
        self.parts.iter().map(|(_, p)| p.len()).sum()
    }
}

/// freeglut's `fghCircleTable`: `|n| + 1` (sin, cos) samples around a circle (a half circle
/// when `half`), the last equal to the first (or to angle π); a negative `n` runs clockwise.
/// The angle step is computed in f32 and each sample's sine in f64, as freeglut does.
fn circle_table(n: i32, half: bool) -> Vec<(f32, f32)> {
    let size = n.unsigned_abs() as usize;
    let step =
        if half { 1.0 } else { 2.0 } * std::f32::consts::PI / if n == 0 { 1 } else { n } as f32;
    let mut t = Vec::with_capacity(size + 1);
    t.push((0.0, 1.0));
    for i in 1..size {
        let a = f64::from(step * i as f32);
        t.push((a.sin() as f32, a.cos() as f32));
    }
    t.push(if half { (0.0, -1.0) } else { (0.0, 1.0) });
    t
}

/// Index `i` of a table that has at least `i + 1` entries by construction.
fn at(t: &[(f32, f32)], i: usize) -> (f32, f32) {
    t.get(i).copied().unwrap_or((0.0, 1.0))
}

/// A vertex count if it is positive and within [`MAX_VERTICES`].
fn count(n: i64) -> Option<usize> {
    usize::try_from(n)
        .ok()
        .filter(|&n| n > 0 && n <= MAX_VERTICES)
}

/// `glutSolidSphere`/`glutWireSphere`'s mesh (fghGenerateSphere, fghSphere): a pole at +z and
/// at -z, `stacks - 1` rings of `slices` vertices; normals are the unit positions. Solid:
/// `stacks` triangle strips; wire: `slices` line strips pole to pole, `stacks - 1` loops.
/// None for `slices < 1`, `stacks < 2` or more than [`MAX_VERTICES`] vertices.
pub fn sphere_mesh(radius: f64, slices: i32, stacks: i32, wire: bool) -> Option<Mesh> {
    if slices < 1 || stacks < 2 {
        return None;
    }
    let n_vert = count(i64::from(slices) * i64::from(stacks - 1) + 2)?;
    let r = radius as f32;
    let (sl, st) = (slices as usize, stacks as usize);
    let t1 = circle_table(-slices, false);
    let t2 = circle_table(stacks, true);
    let mut vertices = Vec::with_capacity(n_vert);
    let mut normals = Vec::with_capacity(n_vert);
    vertices.push([0.0, 0.0, r]);
    normals.push([0.0, 0.0, 1.0]);
    for i in 1..st {
        for j in 0..sl {
            let (s1, c1) = at(&t1, j);
            let (s2, c2) = at(&t2, i);
            let (x, y, z) = (c1 * s2, s1 * s2, c2);
            vertices.push([x * r, y * r, z * r]);
            normals.push([x, y, z]);
        }
    }
    vertices.push([0.0, 0.0, -r]);
    normals.push([0.0, 0.0, -1.0]);
    let (s, last) = (sl as u32, n_vert as u32 - 1);
    let mut parts = Vec::new();
    if wire {
        for i in 0..s {
            let mut p = vec![0];
            p.extend((0..st as u32 - 1).map(|j| 1 + i + j * s));
            p.push(last);
            parts.push((gl::LINE_STRIP, p));
        }
        for i in 0..st as u32 - 1 {
            parts.push((gl::LINE_LOOP, (0..s).map(|j| 1 + i * s + j).collect()));
        }
    } else {
        let strip = |pairs: &mut dyn Iterator<Item = (u32, u32)>| -> Vec<u32> {
            pairs.flat_map(|(a, b)| [a, b]).collect()
        };
        // Top cap, middle stacks, bottom cap; each strip repeats its first pair to close.
        let top = (0..s).map(|j| (j + 1, 0)).chain([(1, 0)]);
        parts.push((gl::TRIANGLE_STRIP, strip(&mut top.into_iter())));
        for i in 0..st as u32 - 2 {
            let o = 1 + i * s;
            let mid = (0..s).map(move |j| (o + j + s, o + j)).chain([(o + s, o)]);
            parts.push((gl::TRIANGLE_STRIP, strip(&mut mid.into_iter())));
        }
        let o = 1 + (st as u32 - 2) * s;
        let bottom = (0..s).map(move |j| (last, o + j)).chain([(last, o)]);
        parts.push((gl::TRIANGLE_STRIP, strip(&mut bottom.into_iter())));
    }
    Some(Mesh {
        vertices,
        normals,
        tex_coords: None,
        parts,
    })
}

/// `glutSolidCone`/`glutWireCone`'s mesh (fghGenerateCone, fghCone): the base disk at z = 0
/// (normal -z), `stacks + 1` rings up to the apex at z = `height` with the side normal
/// (cos·h, sin·h, base)/√(h² + base²). Solid: a fan-like strip for the base, then `stacks`
/// strips; wire: the slice lines as LINES, one loop per stack. None for `slices < 1`,
/// `stacks < 1` or more than [`MAX_VERTICES`] vertices.
pub fn cone_mesh(base: f64, height: f64, slices: i32, stacks: i32, wire: bool) -> Option<Mesh> {
    if slices < 1 || stacks < 1 {
        return None;
    }
    let n_vert = count(i64::from(slices) * (i64::from(stacks) + 2) + 1)?;
    let (b, h) = (base as f32, height as f32);
    let (sl, st) = (slices as usize, stacks as usize);
    let z_step = h / stacks as f32;
    let r_step = b / stacks as f32;
    let hyp = f64::from(h * h + b * b).sqrt();
    let cosn = (f64::from(h) / hyp) as f32;
    let sinn = (f64::from(b) / hyp) as f32;
    let t = circle_table(-slices, false);
    let mut vertices = Vec::with_capacity(n_vert);
    let mut normals = Vec::with_capacity(n_vert);
    vertices.push([0.0, 0.0, 0.0]);
    normals.push([0.0, 0.0, -1.0]);
    for j in 0..sl {
        let (s, c) = at(&t, j);
        vertices.push([c * b, s * b, 0.0]);
        normals.push([0.0, 0.0, -1.0]);
    }
    let (mut z, mut r) = (0.0f32, b);
    for _ in 0..=st {
        for j in 0..sl {
            let (s, c) = at(&t, j);
            vertices.push([c * r, s * r, z]);
            normals.push([c * cosn, s * cosn, sinn]);
        }
        z += z_step;
        r -= r_step;
    }
    let s = sl as u32;
    let stacks = st as u32;
    let mut parts = Vec::new();
    if wire {
        let lines = (0..s)
            .flat_map(|i| [1 + i + s, 1 + i + (stacks + 1) * s])
            .collect();
        parts.push((gl::LINES, lines));
        for i in 0..stacks {
            let o = 1 + (i + 1) * s;
            parts.push((gl::LINE_LOOP, (0..s).map(|j| o + j).collect()));
        }
    } else {
        let mut base_strip: Vec<u32> = (0..s).flat_map(|j| [0, j + 1]).collect();
        base_strip.extend([0, 1]);
        parts.push((gl::TRIANGLE_STRIP, base_strip));
        for i in 0..stacks {
            let o = 1 + (i + 1) * s;
            let mut p: Vec<u32> = (0..s).flat_map(|j| [o + j, o + j + s]).collect();
            p.extend([o, o + s]);
            parts.push((gl::TRIANGLE_STRIP, p));
        }
    }
    Some(Mesh {
        vertices,
        normals,
        tex_coords: None,
        parts,
    })
}

/// `glutSolidTorus`/`glutWireTorus`'s mesh (fghGenerateTorus, fghTorus): `rings` rings around
/// the z axis of `sides` vertices around the tube; the normal is the unit direction from the
/// tube's centre circle. Solid: one strip per side; wire: a loop per ring and per side. None for
/// `sides < 2`, `rings < 2` or more than [`MAX_VERTICES`] vertices.
pub fn torus_mesh(inner: f64, outer: f64, sides: i32, rings: i32, wire: bool) -> Option<Mesh> {
    if sides < 2 || rings < 2 {
        return None;
    }
    let n_vert = count(i64::from(sides) * i64::from(rings))?;
    let (ir, or) = (inner as f32, outer as f32);
    let psi = circle_table(rings, false);
    let phi = circle_table(-sides, false);
    let mut vertices = Vec::with_capacity(n_vert);
    let mut normals = Vec::with_capacity(n_vert);
    for j in 0..rings as usize {
        let (sp, cp) = at(&psi, j);
        for i in 0..sides as usize {
            let (sf, cf) = at(&phi, i);
            vertices.push([cp * (or + cf * ir), sp * (or + cf * ir), sf * ir]);
            normals.push([cp * cf, sp * cf, sf]);
        }
    }
    let (ns, nr) = (sides as u32, rings as u32);
    let mut parts = Vec::new();
    if wire {
        for j in 0..nr {
            parts.push((gl::LINE_LOOP, (0..ns).map(|i| j * ns + i).collect()));
        }
        for i in 0..ns {
            parts.push((gl::LINE_LOOP, (0..nr).map(|j| j * ns + i).collect()));
        }
    } else {
        for i in 0..ns {
            // The strip between side i and side i + 1 (the last side wraps to side 0).
            let next = if i == ns - 1 { 0 } else { i + 1 };
            let mut p: Vec<u32> = (0..nr).flat_map(|j| [j * ns + i, j * ns + next]).collect();
            p.extend([i, next]);
            parts.push((gl::TRIANGLE_STRIP, p));
        }
    }
    Some(Mesh {
        vertices,
        normals,
        tex_coords: None,
        parts,
    })
}

/// freeglut's cube: corners (±½, ±½, ±½), faces as quads of these corners, one normal per face.
const CUBE_V: [[f32; 3]; 8] = [
    [0.5, 0.5, 0.5],
    [-0.5, 0.5, 0.5],
    [-0.5, -0.5, 0.5],
    [0.5, -0.5, 0.5],
    [0.5, -0.5, -0.5],
    [0.5, 0.5, -0.5],
    [-0.5, 0.5, -0.5],
    [-0.5, -0.5, -0.5],
];
const CUBE_N: [[f32; 3]; 6] = [
    [0.0, 0.0, 1.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [-1.0, 0.0, 0.0],
    [0.0, -1.0, 0.0],
    [0.0, 0.0, -1.0],
];
const CUBE_FACES: [[usize; 4]; 6] = [
    [0, 1, 2, 3],
    [0, 3, 4, 5],
    [0, 5, 6, 1],
    [1, 6, 7, 2],
    [7, 4, 3, 2],
    [4, 7, 6, 5],
];

/// `glutSolidCube`/`glutWireCube`'s mesh: 24 vertices (4 per face, the face's normal). Solid:
/// one TRIANGLES part, each face split (0,1,2)(0,2,3); wire: a loop per face.
pub fn cube_mesh(size: f64, wire: bool) -> Mesh {
    let s = size as f32;
    let mut vertices = Vec::with_capacity(24);
    let mut normals = Vec::with_capacity(24);
    for (face, n) in CUBE_FACES.iter().zip(CUBE_N) {
        for &c in face {
            let v = CUBE_V[c];
            vertices.push([s * v[0], s * v[1], s * v[2]]);
            normals.push(n);
        }
    }
    let parts = if wire {
        (0..6u32)
            .map(|f| (gl::LINE_LOOP, (0..4).map(|j| 4 * f + j).collect()))
            .collect()
    } else {
        let tris = (0..6u32)
            .flat_map(|f| [0, 1, 2, 0, 2, 3].map(|j| 4 * f + j))
            .collect();
        vec![(gl::TRIANGLES, tris)]
    };
    Mesh {
        vertices,
        normals,
        tex_coords: None,
        parts,
    }
}

pub use teapot::teapot_mesh;

/// `glutSolidSphere(radius, slices, stacks)`.
pub fn solid_sphere(ctx: &mut Context, radius: f64, slices: i32, stacks: i32) {
    if let Some(m) = sphere_mesh(radius, slices, stacks, false) {
        m.draw(ctx);
    }
}

/// `glutWireSphere(radius, slices, stacks)`.
pub fn wire_sphere(ctx: &mut Context, radius: f64, slices: i32, stacks: i32) {
    if let Some(m) = sphere_mesh(radius, slices, stacks, true) {
        m.draw(ctx);
    }
}

/// `glutSolidCube(size)`.
pub fn solid_cube(ctx: &mut Context, size: f64) {
    cube_mesh(size, false).draw(ctx);
}

/// `glutWireCube(size)`.
pub fn wire_cube(ctx: &mut Context, size: f64) {
    cube_mesh(size, true).draw(ctx);
}

/// `glutSolidCone(base, height, slices, stacks)`.
pub fn solid_cone(ctx: &mut Context, base: f64, height: f64, slices: i32, stacks: i32) {
    if let Some(m) = cone_mesh(base, height, slices, stacks, false) {
        m.draw(ctx);
    }
}

/// `glutWireCone(base, height, slices, stacks)`.
pub fn wire_cone(ctx: &mut Context, base: f64, height: f64, slices: i32, stacks: i32) {
    if let Some(m) = cone_mesh(base, height, slices, stacks, true) {
        m.draw(ctx);
    }
}

/// `glutSolidTorus(inner_radius, outer_radius, sides, rings)`.
pub fn solid_torus(ctx: &mut Context, inner: f64, outer: f64, sides: i32, rings: i32) {
    if let Some(m) = torus_mesh(inner, outer, sides, rings, false) {
        m.draw(ctx);
    }
}

/// `glutWireTorus(inner_radius, outer_radius, sides, rings)`.
pub fn wire_torus(ctx: &mut Context, inner: f64, outer: f64, sides: i32, rings: i32) {
    if let Some(m) = torus_mesh(inner, outer, sides, rings, true) {
        m.draw(ctx);
    }
}

/// `glutSolidTeapot(size)`.
pub fn solid_teapot(ctx: &mut Context, size: f64) {
    teapot_mesh(size, false).draw(ctx);
}

/// `glutWireTeapot(size)`.
pub fn wire_teapot(ctx: &mut Context, size: f64) {
    teapot_mesh(size, true).draw(ctx);
}
