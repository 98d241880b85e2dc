//! Primitive assembly: the ten Begin modes into points, lines and triangles (GL 2.1 §2.6.1,
//! table 2.2 for the provoking vertex, §2.6.2 for edge flags).
//!
//! Design decision: quads and polygons are split into triangles here, the way Mesa's draw module
//! splits them (so interpolation across a non-planar quad matches llvmpipe), with the interior
//! (diagonal) edges flagged off, so polygon mode LINE and POINT still draw exactly the original
//! boundary and each boundary vertex once; every sub-triangle keeps the original polygon's
//! provoking vertex. Incomplete primitives are dropped.

use super::batch::Prim;
use crate::gl;

/// `Asm::edges` bit: the line stipple counter restarts at this primitive (a line: at its
/// segment; a triangle drawn as lines: at its first edge), where llvmpipe's draw module sets
/// `DRAW_PIPE_RESET_STIPPLE`: every segment of LINES, the first of a strip or loop, every
/// triangle of TRIANGLES, the first of each quad and polygon.
pub const RESET_STIPPLE: u8 = 8;

/// `Asm::edges` of a triangle whose edges from its first, second and third vertex are boundary
/// edges (`a`, `b`, `c`).
const fn edge_bits(a: bool, b: bool, c: bool) -> u8 {
    a as u8 | (b as u8) << 1 | (c as u8) << 2
}

/// `Asm::edges` of a strip's or a fan's triangles: every edge a boundary edge.
pub(super) const ALL_EDGES: u8 = edge_bits(true, true, true);

/// `Asm::edges` of the two triangles of a quad strip's quad (see `assemble`), which
/// `Worker::assemble_and_run` also sets up without `assemble`.
pub(super) const QUAD_STRIP_EDGES: [u8; 2] = [
    edge_bits(true, false, true) | RESET_STIPPLE,
    edge_bits(true, true, false),
];

/// One assembled primitive, indices into the processed vertex array.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Asm {
    /// 1 point, 2 line, 3 triangle.
    pub n: u8,
    /// Bit i set: the edge from `v[i]` to the next vertex is a boundary edge (triangles);
    /// `RESET_STIPPLE` as that constant says (lines and triangles).
    pub edges: u8,
    /// Vertex indices (the first `n`).
    pub v: [u32; 3],
    /// The provoking vertex (FLAT colour source).
    pub provoking: u32,
}

/// Appends the primitives of `prims` to `out`: `idx` maps each vertex given to its unique
/// vertex, `edge` are the unique vertices' edge flags, `split_last` whether quads split along
/// their 1–3 diagonal (FLAT shading, or a batch that needs clipping) rather than 0–2.
pub fn assemble(prims: &[Prim], idx: &[u32], edge: &[bool], split_last: bool, out: &mut Vec<Asm>) {
    out.clear();
    let start = out.len();
    let ef = |i: u32| {
        let u = idx.get(i as usize).copied().unwrap_or(u32::MAX);
        edge.get(u as usize).copied().unwrap_or(true)
    };
    let point = |a: u32| Asm {
        n: 1,
        edges: 0,
        v: [a, a, a],
        provoking: a,
    };
    let line = |a: u32, b: u32, p: u32, reset: bool| Asm {
        n: 2,
        edges: if reset { RESET_STIPPLE } else { 0 },
        v: [a, b, b],
        provoking: p,
    };
    let tri = |a: u32, b: u32, c: u32, p: u32, edges: u8| Asm {
        n: 3,
        edges,
        v: [a, b, c],
        provoking: p,
    };
    let flags = edge_bits;
    for p in prims {
        let (f, n) = (p.first, p.count);
        match p.mode {
            gl::POINTS => out.extend((f..f + n).map(point)),
            gl::LINES => out.extend((0..n / 2).map(|i| {
                let a = f + 2 * i;
                line(a, a + 1, a + 1, true)
            })),
            gl::LINE_STRIP | gl::LINE_LOOP => {
                if n < 2 {
                    continue;
                }
                out.extend((f..f + n - 1).map(|a| line(a, a + 1, a + 1, a == f)));
                if p.mode == gl::LINE_LOOP {
                    // Table 2.2: the closing segment's provoking vertex is the first.
                    out.push(line(f + n - 1, f, f, false));
                }
            }
            gl::TRIANGLES => out.extend((0..n / 3).map(|i| {
                let a = f + 3 * i;
                let e = flags(ef(a), ef(a + 1), ef(a + 2));
                tri(a, a + 1, a + 2, a + 2, e | RESET_STIPPLE)
            })),
            gl::TRIANGLE_STRIP => out.extend((0..n.saturating_sub(2)).map(|i| {
                let a = f + i;
                // Odd triangles swap their first two vertices to keep the strip's orientation.
                if i % 2 == 0 {
                    tri(a, a + 1, a + 2, a + 2, ALL_EDGES)
                } else {
                    tri(a + 1, a, a + 2, a + 2, ALL_EDGES)
                }
            })),
            gl::TRIANGLE_FAN => out.extend(
                (0..n.saturating_sub(2))
                    .map(|i| tri(f, f + i + 1, f + i + 2, f + i + 2, ALL_EDGES)),
            ),
            gl::QUADS => {
                // GL leaves the diagonal open (§2.6.1); fixedgl takes llvmpipe's. With `flat`
                // (FLAT shading, or a batch that needs clipping: the caller decides), along
                // 1–3, (0,1,3) and (1,2,3), as Mesa's draw pipeline splits with the provoking
                // vertex last; otherwise along 0–2, (0,1,2) and (0,2,3), as llvmpipe's own
                // setup does. Either way each sub-triangle keeps provoking vertex 3.
                for i in 0..n / 4 {
                    let a = f + 4 * i;
                    let [e0, e1, e2, e3] = [ef(a), ef(a + 1), ef(a + 2), ef(a + 3)];
                    if split_last {
                        let e = flags(e0, false, e3) | RESET_STIPPLE;
                        out.push(tri(a, a + 1, a + 3, a + 3, e));
                        out.push(tri(a + 1, a + 2, a + 3, a + 3, flags(e1, e2, false)));
                    } else {
                        let e = flags(e0, e1, false) | RESET_STIPPLE;
                        out.push(tri(a, a + 1, a + 2, a + 3, e));
                        out.push(tri(a, a + 2, a + 3, a + 3, flags(false, e2, e3)));
                    }
                }
            }
            gl::QUAD_STRIP => {
                for i in 0..(n / 2).saturating_sub(1) {
                    // Quad i: vertices 2i, 2i+1, 2i+3, 2i+2 (0-based), provoking 2i+3; split
                    // along 2i–2i+3 like Mesa: (2i+2, 2i, 2i+3) and (2i, 2i+1, 2i+3).
                    let a = f + 2 * i;
                    let [e0, e1] = QUAD_STRIP_EDGES;
                    out.push(tri(a + 2, a, a + 3, a + 3, e0));
                    out.push(tri(a, a + 1, a + 3, a + 3, e1));
                }
            }
            gl::POLYGON => {
                for i in 0..n.saturating_sub(2) {
                    let (b, c) = (f + i + 1, f + i + 2);
                    let first = i == 0;
                    let last = i + 3 == n;
                    let e = flags(first && ef(f), ef(b), last && ef(c));
                    let reset = if first { RESET_STIPPLE } else { 0 };
                    out.push(tri(f, b, c, f, e | reset));
                }
            }
            _ => {}
        }
    }
    // Assembled in given-vertex positions; now point them at the unique vertices.
    let map = |i: u32| idx.get(i as usize).copied().unwrap_or(u32::MAX);
    for a in &mut out[start..] {
        a.v = a.v.map(map);
        a.provoking = map(a.provoking);
    }
}
