//! Clipping in homogeneous clip space (GL 2.1 §2.12): the six frustum planes -w <= x, y, z <= w,
//! the enabled user clip planes (tested in eye space, eye · plane >= 0), and w > 0.
//!
//! Design decision: a clipped vertex is a whole processed vertex (`Layout::stride` floats) and
//! every float of it is interpolated linearly in clip space, so new vertices carry colours, eye
//! position, normal and texture coordinates alike; the provoking vertex is an index into the
//! unclipped vertices, so a FLAT primitive keeps its colour through clipping (Mesa
//! `tnl/t_vb_cliptmp.h` does the same). For polygon mode LINE, an edge created along a user clip
//! plane is a boundary edge and one along a frustum plane is not (Mesa's draw module does this;
//! GL leaves it open).

use glam::{DVec4, Vec4};

use super::vertex::{Lanes4, Layout};
use crate::state::{State, MAX_CLIP_PLANES};

/// Most vertices a clipped triangle can have: 3 plus one per plane.
pub const MAX_POLY: usize = 3 + 7 + MAX_CLIP_PLANES;

/// The planes of one flush.
#[derive(Clone, Debug)]
pub struct Clipper {
    user: [Vec4; MAX_CLIP_PLANES],
    user_on: [bool; MAX_CLIP_PLANES],
    any_user: bool,
    eye: usize,
}

/// Smallest w a vertex may reach the rasteriser with.
const W_MIN: f32 = 1e-20;

impl Clipper {
    /// The planes enabled in `state`.
    pub fn new(state: &State, layout: &Layout) -> Self {
        let user = state.clip_planes.map(|p: DVec4| p.as_vec4());
        Clipper {
            user,
            user_on: state.enables.clip_planes,
            any_user: state.enables.clip_planes.iter().any(|&b| b),
            eye: layout.eye.unwrap_or(0),
        }
    }

    /// Signed distance of vertex `v` (a processed vertex) to plane `k` (inside when >= 0).
    #[inline(always)]
    fn dist(&self, v: &[f32], k: usize) -> f32 {
        let g = |i: usize| v.get(i).copied().unwrap_or(0.0);
        let (x, y, z, w) = (g(0), g(1), g(2), g(3));
        match k {
            0 => w + x,
            1 => w - x,
            2 => w + y,
            3 => w - y,
            4 => w + z,
            5 => w - z,
            6 => w - W_MIN,
            _ => {
                let p = self.user.get(k - 7).copied().unwrap_or(Vec4::ZERO);
                let e = self.eye;
                p.x * g(e) + p.y * g(e + 1) + p.z * g(e + 2) + p.w * g(e + 3)
            }
        }
    }

    /// Bit k set when `v` is outside plane k: bits 0..=5 the frustum planes, bit 6 w > 0, bits
    /// 7.. the user planes.
    #[inline]
    pub fn code(&self, v: &[f32]) -> u16 {
        let mut c = 0;
        for k in 0..7 {
            if outside(self.dist(v, k)) {
                c |= 1 << k;
            }
        }
        if self.any_user {
            for k in 0..MAX_CLIP_PLANES {
                if self.user_on[k] && outside(self.dist(v, 7 + k)) {
                    c |= 1 << (7 + k);
                }
            }
        }
        c
    }

    /// [`Clipper::code`] of `N` vertices at once, from their clip positions `c` and eye positions
    /// `e` (read only under user clip planes), into `out` (its first `N` elements at most): the
    /// same planes and tests, in a form the compiler vectorises.
    // Lane loops index several arrays in lockstep (structure of arrays): indices read best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub fn code_block<const N: usize>(&self, c: &Lanes4<N>, e: &Lanes4<N>, out: &mut [u16; N]) {
        let o = |d: f32| u16::from(outside(d));
        for i in 0..N {
            let (x, y, z, w) = (c.x[i], c.y[i], c.z[i], c.w[i]);
            out[i] = o(w + x)
                | o(w - x) << 1
                | o(w + y) << 2
                | o(w - y) << 3
                | o(w + z) << 4
                | o(w - z) << 5
                | o(w - W_MIN) << 6;
        }
        if self.any_user {
            for (k, p) in self.user.iter().enumerate() {
                if !self.user_on[k] {
                    continue;
                }
                for i in 0..N {
                    let d = p.x * e.x[i] + p.y * e.y[i] + p.z * e.z[i] + p.w * e.w[i];
                    out[i] |= o(d) << (7 + k);
                }
            }
        }
    }

    /// Clips the polygon in `a` (`n` vertices of `stride` floats, edge flag of the edge starting
    /// at each in `edges`) against every plane set in `planes`; the result is left in `a`/`edges`
    /// and its vertex count returned (0 when nothing is left). `b` is scratch.
    #[allow(clippy::needless_range_loop)] // i indexes both the vertex array and the flags
    pub fn polygon(
        &self,
        stride: usize,
        planes: u16,
        a: &mut Vec<f32>,
        b: &mut Vec<f32>,
        edges: &mut [bool; MAX_POLY],
        mut n: usize,
    ) -> usize {
        let mut eb = [false; MAX_POLY];
        for k in 0..7 + MAX_CLIP_PLANES {
            if planes & (1 << k) == 0 || n == 0 {
                continue;
            }
            b.clear();
            let mut m = 0;
            for i in 0..n {
                let j = (i + 1) % n;
                let (Some(vi), Some(vj)) = (
                    a.get(i * stride..(i + 1) * stride),
                    a.get(j * stride..(j + 1) * stride),
                ) else {
                    return 0;
                };
                let (di, dj) = (self.dist(vi, k), self.dist(vj, k));
                let (ini, inj) = (di >= 0.0, dj >= 0.0);
                if ini && m < MAX_POLY {
                    b.extend_from_slice(vi);
                    eb[m] = edges[i];
                    m += 1;
                }
                if ini != inj && m < MAX_POLY {
                    let t = di / (di - dj);
                    b.extend(vi.iter().zip(vj).map(|(&p, &q)| p + t * (q - p)));
                    // Entering: the new vertex's edge is part of i→j. Leaving: its edge runs
                    // along the plane: drawn for a user plane, not for a frustum plane (what
                    // Mesa does, after NVIDIA).
                    eb[m] = if ini { k >= 7 } else { edges[i] };
                    m += 1;
                }
            }
            std::mem::swap(a, b);
            edges[..m].copy_from_slice(&eb[..m]);
            n = m;
        }
        if n < 3 {
            0
        } else {
            n
        }
    }

    /// Clips the segment `v` (two vertices of `stride` floats) against the planes in `planes`;
    /// false when nothing is left.
    pub fn line(&self, stride: usize, planes: u16, v: &mut [f32]) -> bool {
        let (mut t0, mut t1) = (0.0f32, 1.0f32);
        let (Some(p), Some(q)) = (v.get(..stride), v.get(stride..2 * stride)) else {
            return false;
        };
        for k in 0..7 + MAX_CLIP_PLANES {
            if planes & (1 << k) == 0 {
                continue;
            }
            let (dp, dq) = (self.dist(p, k), self.dist(q, k));
            if dp < 0.0 && dq < 0.0 {
                return false;
            }
            let t = dp / (dp - dq);
            if dp < 0.0 {
                t0 = t0.max(t);
            } else if dq < 0.0 {
                t1 = t1.min(t);
            }
        }
        if t0.is_nan() || t1.is_nan() || t0 > t1 {
            return false;
        }
        let (head, tail) = v.split_at_mut(stride);
        for (a, b) in head.iter_mut().zip(tail.iter_mut()) {
            let (x, y) = (*a, *b);
            *a = x + t0 * (y - x);
            *b = x + t1 * (y - x);
        }
        true
    }
}

/// Outside a plane: negative distance, or NaN (a NaN vertex never reaches the rasteriser).
#[inline(always)]
fn outside(d: f32) -> bool {
    d.is_nan() || d < 0.0
}
