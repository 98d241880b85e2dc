//! `ShadeModel(PHONG_WIN)` on a driver that has no such shade model (GL_WIN_phong_shading): the
//! GL 1.x lighting equation (GL 2.1 §2.14.1) evaluated per fragment by a GLSL 1.10 program that
//! reads the fixed-function state through the compatibility built-ins (`gl_LightSource[]`,
//! `gl_FrontMaterial`/`gl_BackMaterial`, `gl_LightModel`, `gl_FrontLightModelProduct`,
//! `gl_NormalMatrix`).
//!
//! Design decision: the built-ins carry every light and material parameter, so the program needs
//! uniforms only for what GLSL cannot see — which lights are enabled, LIGHT_MODEL_LOCAL_VIEWER,
//! LIGHT_MODEL_TWO_SIDE, LIGHT_MODEL_COLOR_CONTROL and COLOR_MATERIAL. Those are read back from
//! the driver just before a Begin when a state change may have touched them, so the emulation
//! follows the driver's state exactly, whatever call (Enable, LightModel, PopAttrib...) set it.
//! With LIGHTING disabled the program is unbound: PHONG_WIN without lighting is plain SMOOTH.
//!
//! While it is bound, a fragment shader replaces texturing, the colour sum and fog (GL 2.1 §3.11).
//! Fog is done again in the program as the CPU pipeline does it (§3.10, `cpu::fragops::FogEval`): the
//! fog coordinate |z_eye| or |FOG_COORD| per vertex, interpolated, then f per fragment from the
//! `gl_Fog` built-ins (FOG_MODE, FOG_COORD_SRC and the FOG enable are read back as uniforms).
//! What the program does not do: texturing and the colour sum with a texture. The interpolated normal is
//! always renormalised per fragment, i.e. NORMALIZE/RESCALE_NORMAL make no difference. User clip
//! planes work (`gl_ClipVertex`), as do all per-fragment operations after the shader (alpha, stencil
//! and depth tests, blending).

use glow::HasContext;

use super::raw;
use crate::gl;
use crate::Error;

const VERTEX: &str = r#"#version 110
varying vec3 v_normal;
varying vec4 v_eye;
varying float v_fog;
// FOG_COORD_SRC is FOG_COORD.
uniform bool u_fog_coord;
void main() {
    v_eye = gl_ModelViewMatrix * gl_Vertex;
    // §3.10: the fog coordinate, |z_eye| for FRAGMENT_DEPTH (as Mesa), |FOG_COORD| otherwise.
    v_fog = abs(u_fog_coord ? gl_FogCoord : v_eye.z);
    v_normal = gl_NormalMatrix * gl_Normal;
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
    gl_ClipVertex = v_eye;
    gl_Position = ftransform();
}
"#;

/// GL 2.1 §2.14.1, equation for c (primary) and, with SEPARATE_SPECULAR_COLOR, c_spec.
const FRAGMENT: &str = r#"#version 110
uniform int u_light_on[8];
uniform bool u_local_viewer;
uniform bool u_two_side;
uniform bool u_separate_specular;
uniform bool u_cm_front;
uniform bool u_cm_back;
// COLOR_MATERIAL_PARAMETER: 1 AMBIENT, 2 DIFFUSE, 3 SPECULAR, 4 EMISSION, 5 AMBIENT_AND_DIFFUSE.
uniform int u_cm_param;
// FOG_MODE when FOG is enabled: 0 off, 1 LINEAR, 2 EXP, 3 EXP2.
uniform int u_fog_mode;
varying vec3 v_normal;
varying vec4 v_eye;
varying float v_fog;

// x^e with 0^0 = 1 (the spec's convention; GLSL leaves pow(0, 0) undefined).
float powz(float x, float e) {
    return e == 0.0 ? 1.0 : pow(max(x, 0.0), e);
}

void main() {
    // Two-sided lighting: back faces use the BACK material and the negated normal (§2.14.1).
    bool back = u_two_side && !gl_FrontFacing;
    vec3 n = normalize(v_normal);
    vec4 emission = gl_FrontMaterial.emission;
    vec4 ambient = gl_FrontMaterial.ambient;
    vec4 diffuse = gl_FrontMaterial.diffuse;
    vec4 specular = gl_FrontMaterial.specular;
    float shininess = gl_FrontMaterial.shininess;
    vec4 scene = gl_FrontLightModelProduct.sceneColor;
    if (back) {
        n = -n;
        emission = gl_BackMaterial.emission;
        ambient = gl_BackMaterial.ambient;
        diffuse = gl_BackMaterial.diffuse;
        specular = gl_BackMaterial.specular;
        shininess = gl_BackMaterial.shininess;
        scene = gl_BackLightModelProduct.sceneColor;
    }
    // COLOR_MATERIAL (§2.14.3): the current colour replaces the tracked material colour(s).
    if (back ? u_cm_back : u_cm_front) {
        if (u_cm_param == 1 || u_cm_param == 5) ambient = gl_Color;
        if (u_cm_param == 2 || u_cm_param == 5) diffuse = gl_Color;
        if (u_cm_param == 3) specular = gl_Color;
        if (u_cm_param == 4) emission = gl_Color;
        scene = emission + ambient * gl_LightModel.ambient;
    }
    vec3 eye = v_eye.xyz / v_eye.w;
    vec3 view = u_local_viewer ? normalize(-eye) : vec3(0.0, 0.0, 1.0);
    vec3 prim = scene.rgb;
    vec3 spec = vec3(0.0);
    for (int i = 0; i < 8; i++) {
        if (u_light_on[i] == 0) continue;
        vec4 p = gl_LightSource[i].position;
        vec3 l;
        float att = 1.0;
        if (p.w != 0.0) {
            // Positional: attenuation 1 / (k0 + k1 d + k2 d^2).
            vec3 d = p.xyz / p.w - eye;
            float dist = length(d);
            l = d / dist;
            att = 1.0 / (gl_LightSource[i].constantAttenuation
                + gl_LightSource[i].linearAttenuation * dist
                + gl_LightSource[i].quadraticAttenuation * dist * dist);
        } else {
            l = normalize(p.xyz);
        }
        if (gl_LightSource[i].spotCutoff != 180.0) {
            // Outside the cone the whole contribution, ambient included, is zero.
            float c = dot(-l, normalize(gl_LightSource[i].spotDirection));
            att *= c >= gl_LightSource[i].spotCosCutoff
                ? powz(c, gl_LightSource[i].spotExponent) : 0.0;
        }
        vec3 term = ambient.rgb * gl_LightSource[i].ambient.rgb;
        float ndotl = dot(n, l);
        if (ndotl > 0.0) {
            term += ndotl * diffuse.rgb * gl_LightSource[i].diffuse.rgb;
            // Specular is zero where n.l <= 0; h = l + (0,0,1) or l + the direction to the eye.
            vec3 h = normalize(l + view);
            spec += att * powz(dot(n, h), shininess)
                * specular.rgb * gl_LightSource[i].specular.rgb;
        }
        prim += att * term;
    }
    // Colours are clamped after lighting (§2.14.1); alpha is the diffuse material's.
    vec3 rgb = u_separate_specular ? clamp(prim, 0.0, 1.0) + clamp(spec, 0.0, 1.0) : prim + spec;
    rgb = clamp(rgb, 0.0, 1.0);
    // Fog (§3.10 eqs. 3.22 to 3.25) on the clamped colour, alpha unchanged: f clamped to [0, 1],
    // LINEAR in Mesa's form c * -scale + end * scale, the blend as C_f + f (C - C_f).
    if (u_fog_mode != 0) {
        float c = v_fog;
        float f;
        if (u_fog_mode == 1) {
            f = c * -gl_Fog.scale + gl_Fog.end * gl_Fog.scale;
        } else if (u_fog_mode == 2) {
            f = exp(-gl_Fog.density * c);
        } else {
            float dc = gl_Fog.density * c;
            f = exp(-dc * dc);
        }
        f = clamp(f, 0.0, 1.0);
        rgb = gl_Fog.color.rgb + (rgb - gl_Fog.color.rgb) * f;
    }
    gl_FragColor = vec4(rgb, clamp(diffuse.a, 0.0, 1.0));
}
"#;

/// The compiled program and its uniform locations.
#[derive(Debug)]
pub(super) struct PhongProgram {
    program: glow::Program,
    light_on: Option<glow::UniformLocation>,
    local_viewer: Option<glow::UniformLocation>,
    two_side: Option<glow::UniformLocation>,
    separate_specular: Option<glow::UniformLocation>,
    cm_front: Option<glow::UniformLocation>,
    cm_back: Option<glow::UniformLocation>,
    cm_param: Option<glow::UniformLocation>,
    fog_mode: Option<glow::UniformLocation>,
    fog_coord: Option<glow::UniformLocation>,
}

impl PhongProgram {
    /// Compiles and links the program; a driver without GLSL 1.10 is a backend error.
    pub fn new(glow: &glow::Context) -> Result<Self, Error> {
        // SAFETY: the backend's context is current on this thread.
        unsafe {
            let program = glow.create_program().map_err(Error::Backend)?;
            let mut shaders = Vec::new();
            for (kind, src) in [
                (glow::VERTEX_SHADER, VERTEX),
                (glow::FRAGMENT_SHADER, FRAGMENT),
            ] {
                let shader = glow.create_shader(kind).map_err(Error::Backend)?;
                glow.shader_source(shader, src);
                glow.compile_shader(shader);
                if !glow.get_shader_compile_status(shader) {
                    let log = glow.get_shader_info_log(shader);
                    return Err(Error::Backend(format!(
                        "the PHONG_WIN emulation shader does not compile: {log}"
                    )));
                }
                glow.attach_shader(program, shader);
                shaders.push(shader);
            }
            glow.link_program(program);
            for s in shaders {
                glow.detach_shader(program, s);
                glow.delete_shader(s);
            }
            if !glow.get_program_link_status(program) {
                let log = glow.get_program_info_log(program);
                return Err(Error::Backend(format!(
                    "the PHONG_WIN emulation program does not link: {log}"
                )));
            }
            let loc = |name: &str| glow.get_uniform_location(program, name);
            Ok(Self {
                light_on: loc("u_light_on"),
                local_viewer: loc("u_local_viewer"),
                two_side: loc("u_two_side"),
                separate_specular: loc("u_separate_specular"),
                cm_front: loc("u_cm_front"),
                cm_back: loc("u_cm_back"),
                cm_param: loc("u_cm_param"),
                fog_mode: loc("u_fog_mode"),
                fog_coord: loc("u_fog_coord"),
                program,
            })
        }
    }

    /// Reads LIGHTING, the light enables, the light model flags, COLOR_MATERIAL and the fog
    /// enable, mode and coordinate source from the driver, then binds the program with matching uniforms, or unbinds it when lighting is
    /// off. Must be called outside Begin/End (it queries state).
    pub fn sync(&self, raw: &raw::Gl, glow: &glow::Context) {
        // SAFETY: the backend's context is current; every query writes one value into a local.
        unsafe {
            if raw.IsEnabled(gl::LIGHTING) == 0 {
                glow.use_program(None);
                return;
            }
            let int = |pname: u32| {
                let mut v = 0i32;
                raw.GetIntegerv(pname, &mut v);
                v
            };
            let lights: [i32; 8] =
                std::array::from_fn(|i| i32::from(raw.IsEnabled(gl::LIGHT0 + i as u32) != 0));
            let cm_on = raw.IsEnabled(gl::COLOR_MATERIAL) != 0;
            let face = int(gl::COLOR_MATERIAL_FACE) as u32;
            let param = match int(gl::COLOR_MATERIAL_PARAMETER) as u32 {
                gl::AMBIENT => 1,
                gl::DIFFUSE => 2,
                gl::SPECULAR => 3,
                gl::EMISSION => 4,
                _ => 5, // AMBIENT_AND_DIFFUSE, the initial value
            };
            glow.use_program(Some(self.program));
            glow.uniform_1_i32_slice(self.light_on.as_ref(), &lights);
            let set = |l: &Option<glow::UniformLocation>, v: bool| {
                glow.uniform_1_i32(l.as_ref(), i32::from(v));
            };
            set(&self.local_viewer, int(gl::LIGHT_MODEL_LOCAL_VIEWER) != 0);
            set(&self.two_side, int(gl::LIGHT_MODEL_TWO_SIDE) != 0);
            set(
                &self.separate_specular,
                int(gl::LIGHT_MODEL_COLOR_CONTROL) as u32 == gl::SEPARATE_SPECULAR_COLOR,
            );
            set(&self.cm_front, cm_on && face != gl::BACK);
            set(&self.cm_back, cm_on && face != gl::FRONT);
            glow.uniform_1_i32(self.cm_param.as_ref(), param);
            let fog_mode = if raw.IsEnabled(gl::FOG) == 0 {
                0
            } else {
                match int(gl::FOG_MODE) as u32 {
                    gl::LINEAR => 1,
                    gl::EXP => 2,
                    _ => 3, // EXP2
                }
            };
            glow.uniform_1_i32(self.fog_mode.as_ref(), fog_mode);
            set(
                &self.fog_coord,
                int(gl::FOG_COORD_SRC) as u32 == gl::FOG_COORD,
            );
        }
    }

    /// Frees the program (context current).
    pub fn delete(&self, glow: &glow::Context) {
        // SAFETY: the program was created on this context.
        unsafe { glow.delete_program(self.program) };
    }
}
