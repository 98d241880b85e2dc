//! Structures of arrays for the vertex stage (GL 2.1 §2.11, §2.14.1): `N` vectors as one array
//! per component (`Lanes3`, `Lanes4`), the points a block lights (`Block`) and their clamped lit
//! colours (`Shaded`), with the few element-wise helpers the stage shares.
//!
//! Design decision: every operation here is written one lane at a time with the operations, in
//! the order, of the scalar (glam) code it stands for, so that the compiler vectorises it across
//! lanes and its results are the same bits as the scalar code's, whatever the number of lanes.

use glam::{Mat4, Vec3, Vec4};

/// `x` clamped to [0, 1] exactly as glam's `Vec4::clamp(ZERO, ONE)` does it on SSE2 (`maxps`
/// then `minps`: NaN gives 0, -0 gives +0), one lane at a time so that it vectorises on arrays.
#[inline(always)]
pub(super) fn clamp01(x: f32) -> f32 {
    let t = if x > 0.0 { x } else { 0.0 };
    if t < 1.0 {
        t
    } else {
        1.0
    }
}

/// The lit colours of `N` points on arrays, clamped to [0, 1]: primary rgb and alpha, and the
/// secondary rgb (its alpha is 0).
#[derive(Clone, Copy, Debug)]
pub struct Shaded<const N: usize> {
    /// Primary colour.
    pub c: Lanes3<N>,
    /// Primary alpha.
    pub a: [f32; N],
    /// Secondary colour.
    pub s: Lanes3<N>,
}

impl<const N: usize> Default for Shaded<N> {
    fn default() -> Self {
        Shaded {
            c: Lanes3::splat(Vec3::ZERO),
            a: [0.0; N],
            s: Lanes3::splat(Vec3::ZERO),
        }
    }
}

impl<const N: usize> Shaded<N> {
    /// Point `k`'s (primary, secondary) colours (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, k: usize) -> (Vec4, Vec4) {
        let a = self.a.get(k).copied().unwrap_or(0.0);
        (self.c.get(k).extend(a), self.s.get(k).extend(0.0))
    }

    /// Sets point `k` from `one`'s only point (nothing past the last lane).
    #[inline(always)]
    pub(super) fn set_from(&mut self, k: usize, one: &Shaded<1>) {
        self.c.set(k, one.c.get(0));
        self.s.set(k, one.s.get(0));
        if let Some(a) = self.a.get_mut(k) {
            *a = one.a[0];
        }
    }

    /// Writes point `k`'s primary colour at `col` of `o`, and its secondary colour at `spec`.
    #[inline(always)]
    pub(super) fn put(&self, k: usize, o: &mut [f32], col: usize, spec: Option<usize>) {
        if let (Some(&x), Some(&y), Some(&z), Some(&a)) = (
            self.c.x.get(k),
            self.c.y.get(k),
            self.c.z.get(k),
            self.a.get(k),
        ) {
            put_arr(o, col, [x, y, z, a]);
        }
        if let (Some(at), Some(&x), Some(&y), Some(&z)) =
            (spec, self.s.x.get(k), self.s.y.get(k), self.s.z.get(k))
        {
            put_arr(o, at, [x, y, z, 0.0]);
        }
    }
}

/// `N` three-component vectors as a structure of arrays (one array per component).
#[derive(Clone, Copy, Debug)]
pub struct Lanes3<const N: usize> {
    /// The x components.
    pub x: [f32; N],
    /// The y components.
    pub y: [f32; N],
    /// The z components.
    pub z: [f32; N],
}

impl<const N: usize> Lanes3<N> {
    /// `v` in every lane.
    #[inline(always)]
    pub fn splat(v: Vec3) -> Self {
        Lanes3 {
            x: [v.x; N],
            y: [v.y; N],
            z: [v.z; N],
        }
    }

    /// Sets lane `i` (nothing past the last lane).
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Vec3) {
        if let (Some(x), Some(y), Some(z)) =
            (self.x.get_mut(i), self.y.get_mut(i), self.z.get_mut(i))
        {
            (*x, *y, *z) = (v.x, v.y, v.z);
        }
    }

    /// Lane `i` (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vec3 {
        match (self.x.get(i), self.y.get(i), self.z.get(i)) {
            (Some(&x), Some(&y), Some(&z)) => Vec3::new(x, y, z),
            _ => Vec3::ZERO,
        }
    }

    /// Every lane negated (exact).
    #[inline(always)]
    pub fn neg(&self) -> Self {
        Lanes3 {
            x: self.x.map(|a| -a),
            y: self.y.map(|a| -a),
            z: self.z.map(|a| -a),
        }
    }
}

/// `N` four-component vectors as a structure of arrays (one array per component).
#[derive(Clone, Copy, Debug)]
pub struct Lanes4<const N: usize> {
    /// The x components.
    pub x: [f32; N],
    /// The y components.
    pub y: [f32; N],
    /// The z components.
    pub z: [f32; N],
    /// The w components.
    pub w: [f32; N],
}

impl<const N: usize> Default for Lanes4<N> {
    fn default() -> Self {
        Lanes4 {
            x: [0.0; N],
            y: [0.0; N],
            z: [0.0; N],
            w: [0.0; N],
        }
    }
}

impl<const N: usize> Lanes4<N> {
    /// `v` in every lane.
    #[inline(always)]
    pub fn splat(v: Vec4) -> Self {
        Lanes4 {
            x: [v.x; N],
            y: [v.y; N],
            z: [v.z; N],
            w: [v.w; N],
        }
    }

    /// Lane `i` (zero past the last lane).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vec4 {
        match (self.x.get(i), self.y.get(i), self.z.get(i), self.w.get(i)) {
            (Some(&x), Some(&y), Some(&z), Some(&w)) => Vec4::new(x, y, z, w),
            _ => Vec4::ZERO,
        }
    }

    /// The x, y and z components.
    #[inline(always)]
    pub fn xyz(&self) -> Lanes3<N> {
        Lanes3 {
            x: self.x,
            y: self.y,
            z: self.z,
        }
    }

    /// `m` times every lane, with glam's `Mat4 * Vec4` operations in its order
    /// (`((c0·x + c1·y) + c2·z) + c3·w`, no fused multiply-add), so the same bits.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub fn transform(&self, m: &Mat4) -> Self {
        let c = m.to_cols_array();
        let mut r = Self::default();
        for i in 0..N {
            let (x, y, z, w) = (self.x[i], self.y[i], self.z[i], self.w[i]);
            r.x[i] = c[0] * x + c[4] * y + c[8] * z + c[12] * w;
            r.y[i] = c[1] * x + c[5] * y + c[9] * z + c[13] * w;
            r.z[i] = c[2] * x + c[6] * y + c[10] * z + c[14] * w;
            r.w[i] = c[3] * x + c[7] * y + c[11] * z + c[15] * w;
        }
        r
    }
}

/// glam's `normalize_or_zero` on one vector of a [`Lanes3`]: times the reciprocal length when
/// that is finite and positive, else zero.
#[inline(always)]
pub(super) fn normalize_or_zero(x: f32, y: f32, z: f32) -> (f32, f32, f32) {
    let rcp = 1.0 / (x * x + y * y + z * z).sqrt();
    if rcp.is_finite() && rcp > 0.0 {
        (x * rcp, y * rcp, z * rcp)
    } else {
        (0.0, 0.0, 0.0)
    }
}

/// Points transformed and lit together by the vertex stage. 16 executes fewer instructions than
/// 8 (per-block and per-light set-up amortised over more vertices) and far fewer than 4 (measured
/// with callgrind on gauss-smooth-400); results do not depend on it.
pub const LANES: usize = 16;

/// `N` points to light, one array per coordinate: eye positions, unit normals (negated for a
/// back face), vertex colours.
#[derive(Clone, Copy, Debug)]
pub struct Block<const N: usize> {
    /// Eye-space positions.
    pub v: Lanes3<N>,
    /// Normals.
    pub n: Lanes3<N>,
    /// Vertex colours (COLOR_MATERIAL).
    pub color: [Vec4; N],
}

impl<const N: usize> Default for Block<N> {
    fn default() -> Self {
        Block {
            v: Lanes3::splat(Vec3::ZERO),
            n: Lanes3::splat(Vec3::ZERO),
            color: [Vec4::ZERO; N],
        }
    }
}

impl<const N: usize> Block<N> {
    /// Point `k` alone (zero past the last lane).
    pub(super) fn one(&self, k: usize) -> Block<1> {
        Block {
            v: Lanes3::splat(self.v.get(k)),
            n: Lanes3::splat(self.n.get(k)),
            color: [self.color.get(k).copied().unwrap_or(Vec4::ZERO)],
        }
    }

    /// The same points with their normals negated (back faces).
    pub(super) fn back(&self) -> Self {
        Block {
            n: self.n.neg(),
            ..*self
        }
    }
}

/// Writes `v` at `at` of the processed vertex `o` (nothing when it does not fit).
#[inline(always)]
pub(super) fn put_arr(o: &mut [f32], at: usize, v: [f32; 4]) {
    if let Some(d) = o.get_mut(at..at + 4) {
        d.copy_from_slice(&v);
    }
}
