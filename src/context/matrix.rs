//! Coordinate transformations (GL 2.1 §2.11, §2.12, §2.14.1 for ActiveTexture): the matrix mode
//! and stacks, Load/Mult (plain and transposed), the Translate/Rotate/Scale/Frustum/Ortho
//! builders, Viewport and DepthRange, user ClipPlanes, and the active texture unit that selects
//! the texture matrix stack.
//!
//! Design decision: every product is formed in f64 (`DMat4`) from the f32 matrix that `State`
//! keeps and rounded back to f32 once per call, so a call adds at most one f32 rounding to the
//! current matrix whatever its argument type; `*d` entry points keep their double arguments
//! until that final rounding.

use glam::{DMat4, DVec3, DVec4};

use super::{record, Context};
use crate::call::Call;
use crate::gl;
use crate::state::{MAX_TEXTURE_UNITS, MAX_VIEWPORT_DIM};

/// A matrix written as GL's spec writes it (rows), turned into glam's column-major `DMat4`.
fn from_rows(r: [[f64; 4]; 4]) -> DMat4 {
    DMat4::from_cols_array_2d(&r).transpose()
}

/// `m⁻¹`, or the identity when `m` is singular (as Mesa does, so a ClipPlane given under a
/// singular modelview is stored untransformed rather than as NaNs).
pub(crate) fn inverse_or_identity(m: DMat4) -> DMat4 {
    let det = m.determinant();
    if det == 0.0 || !det.is_finite() {
        DMat4::IDENTITY
    } else {
        m.inverse()
    }
}

/// The rotation of GL 2.1 §2.11.2 by `angle` degrees about the axis (x, y, z), normalised
/// first. `None` for a zero-length or non-finite axis, which leaves the matrix unchanged (the
/// spec defines no matrix for it; Mesa skips the multiplication too). Mesa also skips axes
/// shorter than 1e-4 that are not along x, y or z; fixedgl follows the spec and normalises them.
fn rotation(angle: f64, x: f64, y: f64, z: f64) -> Option<DMat4> {
    let len = (x * x + y * y + z * z).sqrt();
    if len == 0.0 || !len.is_finite() {
        return None;
    }
    let (x, y, z) = (x / len, y / len, z / len);
    let (s, c) = angle.to_radians().sin_cos();
    let k = 1.0 - c;
    Some(from_rows([
        [x * x * k + c, x * y * k - z * s, x * z * k + y * s, 0.0],
        [y * x * k + z * s, y * y * k + c, y * z * k - x * s, 0.0],
        [x * z * k - y * s, y * z * k + x * s, z * z * k + c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}

impl Context {
    /// Replaces the current matrix of the current stack.
    fn set_current_matrix(&mut self, m: DMat4) {
        *self.state.current_stack_mut().top_mut() = m.as_mat4();
    }

    /// Post-multiplies the current matrix by `m` (C = C·M, GL 2.1 §2.11.2), in f64.
    fn mult_current_matrix(&mut self, m: DMat4) {
        let top = self.state.current_stack_mut().top_mut();
        *top = (top.as_dmat4() * m).as_mat4();
    }

    /// The common body of every Load/Mult entry point (validation: Begin/End only).
    fn load_or_mult(&mut self, m: DMat4, mult: bool) {
        if !self.outside_begin_end() {
            return;
        }
        if mult {
            self.mult_current_matrix(m);
        } else {
            self.set_current_matrix(m);
        }
    }

    /// `glMatrixMode`: MODELVIEW, PROJECTION or TEXTURE (the active unit's stack), else
    /// INVALID_ENUM.
    pub fn matrix_mode(&mut self, mode: u32) {
        record!(self, Call::MatrixMode(mode));
        if !self.outside_begin_end() {
            return;
        }
        match mode {
            gl::MODELVIEW | gl::PROJECTION | gl::TEXTURE => self.state.matrix_mode = mode,
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glLoadIdentity`.
    pub fn load_identity(&mut self) {
        record!(self, Call::LoadIdentity);
        self.load_or_mult(DMat4::IDENTITY, false);
    }

    /// `glLoadMatrixf`: `m` is column-major, as GL stores it.
    pub fn load_matrixf(&mut self, m: &[f32; 16]) {
        record!(self, Call::LoadMatrixf(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(&m.map(f64::from)), false);
    }

    /// `glLoadMatrixd`: `m` is column-major.
    pub fn load_matrixd(&mut self, m: &[f64; 16]) {
        record!(self, Call::LoadMatrixd(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(m), false);
    }

    /// `glMultMatrixf`: C = C·M, `m` column-major.
    pub fn mult_matrixf(&mut self, m: &[f32; 16]) {
        record!(self, Call::MultMatrixf(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(&m.map(f64::from)), true);
    }

    /// `glMultMatrixd`: C = C·M, `m` column-major.
    pub fn mult_matrixd(&mut self, m: &[f64; 16]) {
        record!(self, Call::MultMatrixd(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(m), true);
    }

    /// `glLoadTransposeMatrixf`: `m` is row-major (GL 2.1 §2.11.2).
    pub fn load_transpose_matrixf(&mut self, m: &[f32; 16]) {
        record!(self, Call::LoadTransposeMatrixf(Box::new(*m)));
        let m = DMat4::from_cols_array(&m.map(f64::from)).transpose();
        self.load_or_mult(m, false);
    }

    /// `glLoadTransposeMatrixd`: `m` is row-major.
    pub fn load_transpose_matrixd(&mut self, m: &[f64; 16]) {
        record!(self, Call::LoadTransposeMatrixd(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(m).transpose(), false);
    }

    /// `glMultTransposeMatrixf`: C = C·M with `m` read row-major.
    pub fn mult_transpose_matrixf(&mut self, m: &[f32; 16]) {
        record!(self, Call::MultTransposeMatrixf(Box::new(*m)));
        let m = DMat4::from_cols_array(&m.map(f64::from)).transpose();
        self.load_or_mult(m, true);
    }

    /// `glMultTransposeMatrixd`: `m` row-major.
    pub fn mult_transpose_matrixd(&mut self, m: &[f64; 16]) {
        record!(self, Call::MultTransposeMatrixd(Box::new(*m)));
        self.load_or_mult(DMat4::from_cols_array(m).transpose(), true);
    }

    /// `glTranslatef`.
    pub fn translatef(&mut self, x: f32, y: f32, z: f32) {
        record!(self, Call::Translatef(x, y, z));
        let t = DVec3::new(x.into(), y.into(), z.into());
        self.load_or_mult(DMat4::from_translation(t), true);
    }

    /// `glTranslated`.
    pub fn translated(&mut self, x: f64, y: f64, z: f64) {
        record!(self, Call::Translated(x, y, z));
        self.load_or_mult(DMat4::from_translation(DVec3::new(x, y, z)), true);
    }

    /// `glScalef`.
    pub fn scalef(&mut self, x: f32, y: f32, z: f32) {
        record!(self, Call::Scalef(x, y, z));
        let s = DVec3::new(x.into(), y.into(), z.into());
        self.load_or_mult(DMat4::from_scale(s), true);
    }

    /// `glScaled`.
    pub fn scaled(&mut self, x: f64, y: f64, z: f64) {
        record!(self, Call::Scaled(x, y, z));
        self.load_or_mult(DMat4::from_scale(DVec3::new(x, y, z)), true);
    }

    /// `glRotatef`: `angle` degrees counter-clockwise about the axis (x, y, z), which is
    /// normalised; a zero axis leaves the matrix unchanged.
    pub fn rotatef(&mut self, angle: f32, x: f32, y: f32, z: f32) {
        record!(self, Call::Rotatef(angle, x, y, z));
        self.rotate(angle.into(), x.into(), y.into(), z.into());
    }

    /// `glRotated`: as [`Context::rotatef`].
    pub fn rotated(&mut self, angle: f64, x: f64, y: f64, z: f64) {
        record!(self, Call::Rotated(angle, x, y, z));
        self.rotate(angle, x, y, z);
    }

    fn rotate(&mut self, angle: f64, x: f64, y: f64, z: f64) {
        if !self.outside_begin_end() {
            return;
        }
        if let Some(r) = rotation(angle, x, y, z) {
            self.mult_current_matrix(r);
        }
    }

    /// `glFrustum`: multiplies by the perspective matrix of GL 2.1 §2.11.2. INVALID_VALUE if
    /// `near` or `far` is not positive, `left == right`, `bottom == top` or `near == far`.
    pub fn frustum(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64) {
        record!(
            self,
            Call::Frustum(Box::new([left, right, bottom, top, near, far]))
        );
        if !self.outside_begin_end() {
            return;
        }
        if near <= 0.0 || far <= 0.0 || left == right || bottom == top || near == far {
            return self.error(gl::INVALID_VALUE);
        }
        let (l, r, b, t, n, f) = (left, right, bottom, top, near, far);
        self.mult_current_matrix(from_rows([
            [2.0 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
            [0.0, 2.0 * n / (t - b), (t + b) / (t - b), 0.0],
            [0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n)],
            [0.0, 0.0, -1.0, 0.0],
        ]));
    }

    /// `glOrtho`: multiplies by the parallel projection of GL 2.1 §2.11.2. INVALID_VALUE if
    /// `left == right`, `bottom == top` or `near == far`.
    pub fn ortho(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64) {
        record!(
            self,
            Call::Ortho(Box::new([left, right, bottom, top, near, far]))
        );
        if !self.outside_begin_end() {
            return;
        }
        if left == right || bottom == top || near == far {
            return self.error(gl::INVALID_VALUE);
        }
        let (l, r, b, t, n, f) = (left, right, bottom, top, near, far);
        self.mult_current_matrix(from_rows([
            [2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
            [0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b)],
            [0.0, 0.0, -2.0 / (f - n), -(f + n) / (f - n)],
            [0.0, 0.0, 0.0, 1.0],
        ]));
    }

    /// `glPushMatrix`: duplicates the current matrix; STACK_OVERFLOW when the current stack
    /// already holds its maximum depth (GL 2.1 §2.11.2).
    pub fn push_matrix(&mut self) {
        record!(self, Call::PushMatrix);
        if !self.outside_begin_end() {
            return;
        }
        let stack = self.state.current_stack_mut();
        if stack.depth() >= stack.max_depth {
            return self.error(gl::STACK_OVERFLOW);
        }
        let top = *stack.top();
        stack.stack.push(top);
    }

    /// `glPopMatrix`: STACK_UNDERFLOW when the current stack holds a single matrix.
    pub fn pop_matrix(&mut self) {
        record!(self, Call::PopMatrix);
        if !self.outside_begin_end() {
            return;
        }
        let stack = self.state.current_stack_mut();
        if stack.depth() <= 1 {
            return self.error(gl::STACK_UNDERFLOW);
        }
        stack.stack.pop();
    }

    /// `glViewport`: INVALID_VALUE for a negative width or height; width and height are
    /// clamped to `MAX_VIEWPORT_DIMS` (GL 2.1 §2.11.1).
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) {
        record!(self, Call::Viewport(x, y, width, height));
        if !self.outside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        let max = MAX_VIEWPORT_DIM as i32;
        self.state.viewport = [x, y, width.min(max), height.min(max)];
    }

    /// `glDepthRange`: both values clamped to [0, 1] (GL 2.1 §2.11.1); `near > far` is allowed.
    pub fn depth_range(&mut self, near: f64, far: f64) {
        record!(self, Call::DepthRange(near, far));
        if !self.outside_begin_end() {
            return;
        }
        self.state.depth_range = [near.clamp(0.0, 1.0), far.clamp(0.0, 1.0)];
    }

    /// `glClipPlane`: stores the plane in eye coordinates, `p_eye = p · M⁻¹` with M the
    /// modelview matrix current now (GL 2.1 §2.12). INVALID_ENUM unless `plane` is
    /// `CLIP_PLANE0 + i`, i < MAX_CLIP_PLANES.
    pub fn clip_plane(&mut self, plane: u32, equation: &[f64; 4]) {
        record!(self, Call::ClipPlane(plane, *equation));
        if !self.outside_begin_end() {
            return;
        }
        // `get_mut` is None past MAX_CLIP_PLANES, for any `plane` below CLIP_PLANE0 too.
        let index = plane.wrapping_sub(gl::CLIP_PLANE0) as usize;
        let inverse = inverse_or_identity(self.state.modelview.top().as_dmat4());
        match self.state.clip_planes.get_mut(index) {
            // A row vector times M⁻¹ is (M⁻¹)ᵀ times the column vector.
            Some(stored) => {
                *stored = inverse.transpose() * DVec4::from_array(*equation);
            }
            _ => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glActiveTexture`: selects the unit whose texture matrix stack, current texture
    /// coordinates and texture enables later calls address. INVALID_ENUM unless `texture` is
    /// `TEXTURE0 + i`, i < MAX_TEXTURE_UNITS.
    pub fn active_texture(&mut self, texture: u32) {
        record!(self, Call::ActiveTexture(texture));
        if !self.outside_begin_end() {
            return;
        }
        match texture_unit(texture) {
            Some(unit) => self.state.active_texture = unit,
            None => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glClientActiveTexture`: selects the unit client-side texture-coordinate array calls
    /// address. INVALID_ENUM unless `texture` is `TEXTURE0 + i`, i < MAX_TEXTURE_UNITS.
    ///
    /// Client state: like Mesa, no INVALID_OPERATION between Begin and End (the reference page
    /// lists none) and nothing is flushed, since no batched vertex depends on it.
    pub fn client_active_texture(&mut self, texture: u32) {
        record!(self, Call::ClientActiveTexture(texture));
        // Not in GL 2.1 §2.6.3's list of commands allowed between Begin and End (Mesa agrees).
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        match texture_unit(texture) {
            Some(unit) => self.state.client_active_texture = unit,
            None => self.error(gl::INVALID_ENUM),
        }
    }
}

/// `TEXTURE0 + i` → `i` for a unit that exists.
fn texture_unit(texture: u32) -> Option<usize> {
    let unit = texture.wrapping_sub(gl::TEXTURE0) as usize;
    (unit < MAX_TEXTURE_UNITS).then_some(unit)
}
