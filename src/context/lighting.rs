//! Lighting parameters: `Material`, `Light`, `LightModel`, `ColorMaterial`, `ShadeModel`
//! (GL 2.1 §2.14.2, §2.14.3, §2.14.7).
//!
//! Every form (`f`, `i`, `fv`, `iv`) converts its parameters to floats and goes through one
//! validating setter per command, so the error rules live in one place: a bad face or light is
//! INVALID_ENUM, a pname the form cannot take is INVALID_ENUM, a slice shorter than the pname needs
//! is INVALID_VALUE, an out-of-range value is INVALID_VALUE; on any error nothing changes.
//! Integer colour parameters map linearly so that the most positive integer is 1.0 and the most
//! negative -1.0 (§2.14.2, table 2.9's signed rule); other integer parameters convert directly.
//!
//! Design decision: light POSITION and SPOT_DIRECTION are transformed by the modelview matrix
//! current at the call and stored in eye coordinates (§2.14.2), as `glGetLightfv` reports them.

use glam::{Vec3, Vec4};

use super::vertex::Component;
use super::{record, Context};
use crate::call::Call;
use crate::counts;
use crate::gl;
use crate::state::{Material, BACK, FRONT, MAX_LIGHTS};

/// Parameters converted to float, at most four (every lighting pname takes one to four values).
type Params = [f32; 4];

/// Converts `src` to at most four floats; colour pnames of integer forms are normalised.
fn convert<T: Component>(src: &[T], color: bool) -> (Params, usize) {
    let mut out = [0.0; 4];
    for (o, v) in out.iter_mut().zip(src) {
        *o = if color { v.normalized() } else { v.to_f32() };
    }
    (out, src.len().min(4))
}

/// Whether `pname` is one of the colour-valued lighting pnames.
fn is_color(pname: u32) -> bool {
    matches!(
        pname,
        gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::EMISSION | gl::AMBIENT_AND_DIFFUSE
    )
}

/// The faces `face` names as indices into `State::materials`, or `None` if it names none.
pub(crate) fn faces(face: u32) -> Option<&'static [usize]> {
    match face {
        gl::FRONT => Some(&[FRONT]),
        gl::BACK => Some(&[BACK]),
        gl::FRONT_AND_BACK => Some(&[FRONT, BACK]),
        _ => None,
    }
}

/// The material parameters `ColorMaterial(mode)` tracks, as `Material` pnames.
fn tracked(mode: u32) -> &'static [u32] {
    match mode {
        gl::AMBIENT_AND_DIFFUSE => &[gl::AMBIENT, gl::DIFFUSE],
        gl::AMBIENT => &[gl::AMBIENT],
        gl::DIFFUSE => &[gl::DIFFUSE],
        gl::SPECULAR => &[gl::SPECULAR],
        gl::EMISSION => &[gl::EMISSION],
        _ => &[],
    }
}

/// Writes one validated material parameter.
fn set_material(m: &mut Material, pname: u32, p: &Params) {
    let v = Vec4::from_array(*p);
    match pname {
        gl::AMBIENT => m.ambient = v,
        gl::DIFFUSE => m.diffuse = v,
        gl::SPECULAR => m.specular = v,
        gl::EMISSION => m.emission = v,
        gl::AMBIENT_AND_DIFFUSE => {
            m.ambient = v;
            m.diffuse = v;
        }
        gl::SHININESS => m.shininess = p[0],
        gl::COLOR_INDEXES => m.color_indexes = [p[0], p[1], p[2]],
        _ => {}
    }
}

impl Context {
    /// With COLOR_MATERIAL enabled, copies the current colour into the material parameters
    /// `ColorMaterial` selected (GL 2.1 §2.14.3: they track the current colour at all times).
    pub(crate) fn track_color_material(&mut self) {
        let c = self.state.current.color.to_array();
        // ColorMaterial validated both before storing them (and the initial values are valid).
        debug_assert!(faces(self.state.color_material_face).is_some());
        debug_assert!(!tracked(self.state.color_material_mode).is_empty());
        let faces = faces(self.state.color_material_face).unwrap_or(&[]);
        for &pname in tracked(self.state.color_material_mode) {
            for &f in faces {
                if let Some(m) = self.state.materials.get_mut(f) {
                    set_material(m, pname, &c);
                }
            }
        }
    }

    /// The validating body of every `Material` form. `scalar`: the `f`/`i` forms. GL 2.1
    /// §2.14.2 gives them SHININESS, but Mesa (GL 1.5 through 4.x compatibility) takes every
    /// material pname there: `_mesa_Materialf` puts `param` first in a four-float array and calls
    /// `Materialfv`, whose other elements are uninitialised stack. fixedgl takes the pname too
    /// and makes those elements 0 (`[param, 0, 0, 0]`, `[param, 0, 0]` for COLOR_INDEXES); the GL
    /// backend replays the call as that vector so the driver holds the same values.
    fn material(&mut self, face: u32, pname: u32, p: (Params, usize), scalar: bool) {
        // A short vector is INVALID_VALUE as soon as its pname names a length, whatever the face
        // (the GL backend checks it there, before the driver sees the call).
        if !scalar && counts::material(pname).is_some_and(|n| p.1 < n) {
            return self.error(gl::INVALID_VALUE);
        }
        let Some(targets) = faces(face) else {
            return self.error(gl::INVALID_ENUM);
        };
        let Some(len) = counts::material(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        let (p, n) = p;
        // The scalar's missing elements are the zeros `convert` left there.
        let n = if scalar { len } else { n };
        if n < len {
            return self.error(gl::INVALID_VALUE);
        }
        if pname == gl::SHININESS && !(0.0..=128.0).contains(&p[0]) {
            return self.error(gl::INVALID_VALUE);
        }
        // Material is allowed between Begin and End (§2.6.3): there it applies from the next
        // vertex on; outside, batched vertices are drawn with the old material first.
        let inside = self.begin_mode.is_some();
        if !inside {
            self.renderer.flush(&self.state);
        }
        // While COLOR_MATERIAL is on, the tracked parameters follow the current colour "at all
        // times" (§2.14.3), so a Material call does not change them (as Mesa does).
        let color_material = self.state.enables.color_material;
        debug_assert!(faces(self.state.color_material_face).is_some());
        let tracked_faces = faces(self.state.color_material_face).unwrap_or(&[]);
        let tracked_pnames = tracked(self.state.color_material_mode);
        let pnames: &[u32] = if pname == gl::AMBIENT_AND_DIFFUSE {
            &[gl::AMBIENT, gl::DIFFUSE]
        } else {
            std::slice::from_ref(&pname)
        };
        for &f in targets {
            for &pn in pnames {
                let is_tracked =
                    color_material && tracked_faces.contains(&f) && tracked_pnames.contains(&pn);
                if let (false, Some(m)) = (is_tracked, self.state.materials.get_mut(f)) {
                    set_material(m, pn, &p);
                }
            }
        }
        if inside {
            self.renderer.materials_changed(&self.state.materials);
        }
    }

    /// `glMaterialf`: a vector pname takes `[param, 0, 0, 0]` (see `material`).
    pub fn materialf(&mut self, face: u32, pname: u32, param: f32) {
        record!(self, Call::Materialf(face, pname, param));
        self.material(face, pname, convert(&[param], false), true);
    }

    /// `glMateriali`: `param` converted as a float, not normalised, as Mesa does; a vector pname
    /// takes `[param, 0, 0, 0]` (see `material`).
    pub fn materiali(&mut self, face: u32, pname: u32, param: i32) {
        record!(self, Call::Materiali(face, pname, param));
        self.material(face, pname, convert(&[param], false), true);
    }

    /// `glMaterialfv`.
    pub fn materialfv(&mut self, face: u32, pname: u32, params: &[f32]) {
        record!(self, Call::Materialfv(face, pname, params.to_vec()));
        self.material(face, pname, convert(params, false), false);
    }

    /// `glMaterialiv`: colours map linearly, the most positive integer to 1.0.
    pub fn materialiv(&mut self, face: u32, pname: u32, params: &[i32]) {
        record!(self, Call::Materialiv(face, pname, params.to_vec()));
        self.material(face, pname, convert(params, is_color(pname)), false);
    }

    /// The validating body of every `Light` form (GL 2.1 §2.14.2).
    fn light(&mut self, light: u32, pname: u32, p: (Params, usize), scalar: bool) {
        if !self.outside_begin_end() {
            return;
        }
        // A short vector is INVALID_VALUE as soon as its pname names a length, whatever the light.
        if !scalar && counts::light(pname).is_some_and(|n| p.1 < n) {
            return self.error(gl::INVALID_VALUE);
        }
        let index = light.wrapping_sub(gl::LIGHT0) as usize;
        if index >= MAX_LIGHTS {
            return self.error(gl::INVALID_ENUM);
        }
        let Some(len) = counts::light(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        let (p, n) = p;
        // A scalar form takes a vector pname as `[param, 0, 0, 0]`, as Mesa does (`Context::material`).
        let n = if scalar { len } else { n };
        if n < len {
            return self.error(gl::INVALID_VALUE);
        }
        let x = p[0];
        let in_range = match pname {
            gl::SPOT_EXPONENT => (0.0..=128.0).contains(&x),
            gl::SPOT_CUTOFF => (0.0..=90.0).contains(&x) || x == 180.0,
            gl::CONSTANT_ATTENUATION | gl::LINEAR_ATTENUATION | gl::QUADRATIC_ATTENUATION => {
                x >= 0.0
            }
            _ => true,
        };
        if !in_range {
            return self.error(gl::INVALID_VALUE);
        }
        let modelview = *self.state.modelview.top();
        let Some(l) = self.state.lights.get_mut(index) else {
            return self.error(gl::INVALID_ENUM);
        };
        let v = Vec4::from_array(p);
        match pname {
            gl::AMBIENT => l.ambient = v,
            gl::DIFFUSE => l.diffuse = v,
            gl::SPECULAR => l.specular = v,
            gl::POSITION => l.position = modelview * v,
            gl::SPOT_DIRECTION => {
                l.spot_direction = glam::Mat3::from_mat4(modelview) * Vec3::new(x, p[1], p[2]);
            }
            gl::SPOT_EXPONENT => l.spot_exponent = x,
            gl::SPOT_CUTOFF => l.spot_cutoff = x,
            gl::CONSTANT_ATTENUATION => l.constant_attenuation = x,
            gl::LINEAR_ATTENUATION => l.linear_attenuation = x,
            gl::QUADRATIC_ATTENUATION => l.quadratic_attenuation = x,
            _ => {}
        }
    }

    /// `glLightf`: a vector pname takes `[param, 0, 0, 0]`, as Mesa does.
    pub fn lightf(&mut self, light: u32, pname: u32, param: f32) {
        record!(self, Call::Lightf(light, pname, param));
        self.light(light, pname, convert(&[param], false), true);
    }

    /// `glLighti`: as [`Context::lightf`].
    pub fn lighti(&mut self, light: u32, pname: u32, param: i32) {
        record!(self, Call::Lighti(light, pname, param));
        self.light(light, pname, convert(&[param], false), true);
    }

    /// `glLightfv`. POSITION and SPOT_DIRECTION are transformed by the current modelview matrix.
    pub fn lightfv(&mut self, light: u32, pname: u32, params: &[f32]) {
        record!(self, Call::Lightfv(light, pname, params.to_vec()));
        self.light(light, pname, convert(params, false), false);
    }

    /// `glLightiv`: colours map linearly, the most positive integer to 1.0.
    pub fn lightiv(&mut self, light: u32, pname: u32, params: &[i32]) {
        record!(self, Call::Lightiv(light, pname, params.to_vec()));
        self.light(light, pname, convert(params, is_color(pname)), false);
    }

    /// The validating body of every `LightModel` form (GL 2.1 §2.14.2, table 2.10).
    fn light_model(&mut self, pname: u32, p: (Params, usize), scalar: bool) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(len) = counts::light_model(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        let (p, n) = p;
        // A scalar form takes a vector pname as `[param, 0, 0, 0]`, as Mesa does (`Context::material`).
        let n = if scalar { len } else { n };
        if n < len {
            return self.error(gl::INVALID_VALUE);
        }
        let lm = &mut self.state.light_model;
        match pname {
            gl::LIGHT_MODEL_AMBIENT => lm.ambient = Vec4::from_array(p),
            gl::LIGHT_MODEL_LOCAL_VIEWER => lm.local_viewer = p[0] != 0.0,
            gl::LIGHT_MODEL_TWO_SIDE => lm.two_side = p[0] != 0.0,
            gl::LIGHT_MODEL_COLOR_CONTROL => {
                // Converted from float: only an exact enum value names a mode.
                if p[0] == gl::SINGLE_COLOR as f32 {
                    lm.color_control = gl::SINGLE_COLOR;
                } else if p[0] == gl::SEPARATE_SPECULAR_COLOR as f32 {
                    lm.color_control = gl::SEPARATE_SPECULAR_COLOR;
                } else {
                    self.error(gl::INVALID_ENUM);
                }
            }
            _ => {}
        }
    }

    /// `glLightModelf`: LOCAL_VIEWER, TWO_SIDE or COLOR_CONTROL.
    pub fn light_modelf(&mut self, pname: u32, param: f32) {
        record!(self, Call::LightModelf(pname, param));
        self.light_model(pname, convert(&[param], false), true);
    }

    /// `glLightModeli`: LOCAL_VIEWER, TWO_SIDE or COLOR_CONTROL.
    pub fn light_modeli(&mut self, pname: u32, param: i32) {
        record!(self, Call::LightModeli(pname, param));
        self.light_model(pname, convert(&[param], false), true);
    }

    /// `glLightModelfv`.
    pub fn light_modelfv(&mut self, pname: u32, params: &[f32]) {
        record!(self, Call::LightModelfv(pname, params.to_vec()));
        self.light_model(pname, convert(params, false), false);
    }

    /// `glLightModeliv`: AMBIENT maps linearly, the most positive integer to 1.0.
    pub fn light_modeliv(&mut self, pname: u32, params: &[i32]) {
        record!(self, Call::LightModeliv(pname, params.to_vec()));
        let color = pname == gl::LIGHT_MODEL_AMBIENT;
        self.light_model(pname, convert(params, color), false);
    }

    /// `glColorMaterial` (GL 2.1 §2.14.3). With COLOR_MATERIAL enabled, the newly selected
    /// parameters take the current colour at once.
    pub fn color_material(&mut self, face: u32, mode: u32) {
        record!(self, Call::ColorMaterial(face, mode));
        if !self.outside_begin_end() {
            return;
        }
        if faces(face).is_none() || tracked(mode).is_empty() {
            return self.error(gl::INVALID_ENUM);
        }
        self.state.color_material_face = face;
        self.state.color_material_mode = mode;
        if self.state.enables.color_material {
            self.track_color_material();
        }
    }

    /// `glShadeModel`: FLAT, SMOOTH, or PHONG_WIN (GL_WIN_phong_shading) (GL 2.1 §2.14.7).
    pub fn shade_model(&mut self, mode: u32) {
        record!(self, Call::ShadeModel(mode));
        if !self.outside_begin_end() {
            return;
        }
        match mode {
            gl::FLAT | gl::SMOOTH | gl::PHONG_WIN => self.state.shade_model = mode,
            _ => self.error(gl::INVALID_ENUM),
        }
    }
}
