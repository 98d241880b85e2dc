//! Evaluators on the driver (GL 2.1 §5.1): Map1 and Map2 hand the driver their recorded points,
//! exactly the values it reads (`counts::map1_points`, `map2_points`); a recorded slice shorter
//! than that (the front end's INVALID_VALUE) never reaches it, as with `with_params`. The
//! GetMap queries are here for tests comparing the two sides.

use super::GlBackend;
use crate::counts;
use crate::gl;

/// The most values GetMap writes: MAX_EVAL_ORDER² points of 4 components.
const MAX_MAP_VALUES: usize =
    (crate::state::MAX_EVAL_ORDER * crate::state::MAX_EVAL_ORDER) as usize * 4;

impl GlBackend {
    /// Checks a recorded Map's points against what the driver reads (`needed`: `None` when the
    /// driver fails the call before reading). `false`: the front end's INVALID_VALUE instead.
    fn map_points_ok<T>(&mut self, points: &[T], needed: Option<usize>) -> bool {
        if points.len() >= needed.unwrap_or(0) {
            return true;
        }
        // lists: the driver's list cannot hold this call; its error comes when the list runs.
        self.list_needs_expansion();
        if self.compile_only() {
            return false;
        }
        let code = if self.inside_begin_end {
            gl::INVALID_OPERATION
        } else {
            gl::INVALID_VALUE
        };
        self.raise(code);
        false
    }

    pub(super) fn map1f(
        &mut self,
        target: u32,
        u1: f32,
        u2: f32,
        stride: i32,
        order: i32,
        p: &[f32],
    ) {
        if self.map_points_ok(p, counts::map1_points(target, stride, order)) {
            // SAFETY: the context is current; `p` holds every value the driver reads (or it
            // reads none, failing first: NULL is its INVALID_VALUE, as an empty slice is the
            // front end's).
            unsafe { self.raw.Map1f(target, u1, u2, stride, order, or_null(p)) }
        }
    }

    pub(super) fn map1d(
        &mut self,
        target: u32,
        u1: f64,
        u2: f64,
        stride: i32,
        order: i32,
        p: &[f64],
    ) {
        if self.map_points_ok(p, counts::map1_points(target, stride, order)) {
            // SAFETY: as in `map1f`.
            unsafe { self.raw.Map1d(target, u1, u2, stride, order, or_null(p)) }
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn map2f(
        &mut self,
        target: u32,
        u1: f32,
        u2: f32,
        ustride: i32,
        uorder: i32,
        v1: f32,
        v2: f32,
        vstride: i32,
        vorder: i32,
        p: &[f32],
    ) {
        let needed = counts::map2_points(target, ustride, uorder, vstride, vorder);
        if self.map_points_ok(p, needed) {
            // SAFETY: as in `map1f`.
            unsafe {
                self.raw.Map2f(
                    target,
                    u1,
                    u2,
                    ustride,
                    uorder,
                    v1,
                    v2,
                    vstride,
                    vorder,
                    p.as_ptr(),
                )
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn map2d(
        &mut self,
        target: u32,
        u1: f64,
        u2: f64,
        ustride: i32,
        uorder: i32,
        v1: f64,
        v2: f64,
        vstride: i32,
        vorder: i32,
        p: &[f64],
    ) {
        let needed = counts::map2_points(target, ustride, uorder, vstride, vorder);
        if self.map_points_ok(p, needed) {
            // SAFETY: as in `map1f`.
            unsafe {
                self.raw.Map2d(
                    target,
                    u1,
                    u2,
                    ustride,
                    uorder,
                    v1,
                    v2,
                    vstride,
                    vorder,
                    p.as_ptr(),
                )
            }
        }
    }

    /// `glGetMapfv` on the driver: the values it writes (at most MAX_EVAL_ORDER² points), or
    /// an empty vector when it wrote none (an error).
    pub fn get_mapfv(&mut self, target: u32, query: u32) -> Vec<f32> {
        self.make_current();
        let mut a = vec![f32::from_bits(0x7fc1_2345); MAX_MAP_VALUES];
        let mut b = vec![f32::from_bits(0x7fd5_4321); MAX_MAP_VALUES];
        // SAFETY: the context is current; each buffer holds the most GetMap writes.
        unsafe {
            self.raw.GetMapfv(target, query, a.as_mut_ptr());
            self.raw.GetMapfv(target, query, b.as_mut_ptr());
        }
        let n = (0..MAX_MAP_VALUES)
            .rev()
            .find(|&i| a[i].to_bits() != 0x7fc1_2345 || b[i].to_bits() != 0x7fd5_4321)
            .map_or(0, |i| i + 1);
        a.truncate(n);
        a
    }

    /// `glGetMapiv` on the driver (as [`GlBackend::get_mapfv`]).
    pub fn get_mapiv(&mut self, target: u32, query: u32) -> Vec<i32> {
        self.make_current();
        let (sa, sb) = (0x5a5a_1234, -0x2345_6789);
        let mut a = vec![sa; MAX_MAP_VALUES];
        let mut b = vec![sb; MAX_MAP_VALUES];
        // SAFETY: as in `get_mapfv`.
        unsafe {
            self.raw.GetMapiv(target, query, a.as_mut_ptr());
            self.raw.GetMapiv(target, query, b.as_mut_ptr());
        }
        let n = (0..MAX_MAP_VALUES)
            .rev()
            .find(|&i| a[i] != sa || b[i] != sb)
            .map_or(0, |i| i + 1);
        a.truncate(n);
        a
    }

    /// `glGetMapdv` on the driver (as [`GlBackend::get_mapfv`]).
    pub fn get_mapdv(&mut self, target: u32, query: u32) -> Vec<f64> {
        self.make_current();
        let (sa, sb) = (
            f64::from_bits(0x7ff8_1234_5678_9abc),
            f64::from_bits(0x7ff8_4321_8765_cba9),
        );
        let mut a = vec![sa; MAX_MAP_VALUES];
        let mut b = vec![sb; MAX_MAP_VALUES];
        // SAFETY: as in `get_mapfv`.
        unsafe {
            self.raw.GetMapdv(target, query, a.as_mut_ptr());
            self.raw.GetMapdv(target, query, b.as_mut_ptr());
        }
        let n = (0..MAX_MAP_VALUES)
            .rev()
            .find(|&i| a[i].to_bits() != sa.to_bits() || b[i].to_bits() != sb.to_bits())
            .map_or(0, |i| i + 1);
        a.truncate(n);
        a
    }
}

/// The slice's pointer, NULL when it is empty (Map1 checks for NULL before its target).
fn or_null<T>(p: &[T]) -> *const T {
    if p.is_empty() {
        std::ptr::null()
    } else {
        p.as_ptr()
    }
}
