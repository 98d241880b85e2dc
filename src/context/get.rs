//! State queries (GL 2.1 §6.1): `glGet{Boolean,Integer,Float,Double}v`, `glGetLight*`,
//! `glGetMaterial*`, `glGetClipPlane` and `glGetString`.
//!
//! Design decision: one table, [`Context::query`], maps each pname to its value count, its
//! conversion kind and its values (as f64, which holds every f32, i32 and enum exactly); the
//! four getters differ only in the §6.1.2 conversion applied on the way out, so a pname added
//! to the table is answered by all four at once. Queries change no state and are not recorded.

use super::Context;
use crate::gl;
use crate::state::{
    Light, Material, MatrixStack, BACK, FRONT, MAX_CLIP_PLANES, MAX_LIGHTS,
    MAX_MODELVIEW_STACK_DEPTH, MAX_PROJECTION_STACK_DEPTH, MAX_TEXTURE_STACK_DEPTH,
    MAX_TEXTURE_UNITS, MAX_VIEWPORT_DIM,
};

/// `SUBPIXEL_BITS`: window coordinates snap to 1/256 pixel, as llvmpipe's do.
pub const SUBPIXEL_BITS: i32 = 8;
/// `ALIASED_POINT_SIZE_RANGE` and `SMOOTH_POINT_SIZE_RANGE` (= `POINT_SIZE_RANGE`).
pub const POINT_SIZE_RANGE: [f32; 2] = [1.0, 255.0];
/// `SMOOTH_POINT_SIZE_GRANULARITY` (= `POINT_SIZE_GRANULARITY`).
pub const POINT_SIZE_GRANULARITY: f32 = 0.1;
/// `ALIASED_LINE_WIDTH_RANGE` and `SMOOTH_LINE_WIDTH_RANGE` (= `LINE_WIDTH_RANGE`).
pub const LINE_WIDTH_RANGE: [f32; 2] = [1.0, 255.0];
/// `SMOOTH_LINE_WIDTH_GRANULARITY` (= `LINE_WIDTH_GRANULARITY`).
pub const LINE_WIDTH_GRANULARITY: f32 = 0.1;

/// `VENDOR`.
pub const VENDOR: &str = "fixedgl";
/// `RENDERER`.
pub const RENDERER: &str = "fixedgl CPU rasterizer";
/// `VERSION`: GL 1.5, then the crate's own version (GL 2.1 §6.1.11 format).
pub const VERSION: &str = concat!("1.5 fixedgl ", env!("CARGO_PKG_VERSION"));
/// `EXTENSIONS`: the extensions whose every command and enum works, each word followed by a
/// space, as Mesa writes the string (programs that split it, and piglit's glinfo, rely on the
/// last space). Only what works is named: a program that checks an extension before using it
/// must not take a path fixedgl lacks.
pub const EXTENSIONS: &str = concat!(
    "GL_ARB_depth_texture ",        // DEPTH_COMPONENT textures (GL 1.4)
    "GL_ARB_multitexture ",         // ActiveTexture, MultiTexCoord (GL 1.3)
    "GL_ARB_shadow ",               // TEXTURE_COMPARE_MODE (GL 1.4)
    "GL_ARB_texture_env_combine ",  // TexEnv COMBINE (GL 1.3)
    "GL_ARB_texture_env_crossbar ", // COMBINE sources TEXTUREn (GL 1.4)
    "GL_ARB_vertex_buffer_object ", // buffer objects, MapBuffer (GL 1.5)
    "GL_ARB_window_pos ",           // WindowPos (GL 1.4)
    "GL_EXT_abgr ",                 // the ABGR_EXT pixel format (every pixel command)
    "GL_EXT_blend_minmax ",         // MIN and MAX blend equations (GL 1.4)
    "GL_EXT_framebuffer_object ",   // framebuffer objects (context/fbo.rs; GL 3.0 names too)
    "GL_EXT_packed_depth_stencil ", // DEPTH_STENCIL pixels, textures, renderbuffers
    "GL_EXT_shadow_funcs ",         // every TEXTURE_COMPARE_FUNC (GL 1.5)
    "GL_EXT_texture3D ",            // TexImage3D, TexSubImage3D (GL 1.2)
    "GL_EXT_vertex_array ",         // the *PointerEXT commands with a count (capi; GL 1.1 core)
    "GL_WIN_phong_shading ",        // ShadeModel(PHONG_WIN): fixedgl's per-fragment lighting
);

/// How a state value converts to the type a getter asks for (GL 2.1 §6.1.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Conversion {
    /// Boolean state, held as 0 or 1.
    Bool,
    /// Integer or enumerated state, held exactly.
    Int,
    /// Floating-point state: an integer getter rounds it to the nearest integer.
    Float,
    /// A colour component, normal coordinate or depth value: an integer getter maps [-1, 1]
    /// linearly onto the whole integer range (GL 2.1 table 4.9).
    Normalized,
}

/// One pname's answer: `len` values of one kind.
#[derive(Clone, Copy, Debug)]
struct Value {
    kind: Conversion,
    len: usize,
    v: [f64; 16],
}

impl Value {
    /// The first (at most 16) of `values`, converted to f64 (exact from f32, i32 and u32).
    fn new<T: Into<f64>>(kind: Conversion, values: impl IntoIterator<Item = T>) -> Value {
        let mut v = [0.0; 16];
        let mut len = 0;
        for (slot, x) in v.iter_mut().zip(values) {
            *slot = x.into();
            len += 1;
        }
        Value { kind, len, v }
    }

    fn values(&self) -> impl Iterator<Item = f64> + '_ {
        self.v.iter().copied().take(self.len)
    }
}

fn b(x: bool) -> Value {
    bools([x])
}
fn bools<const N: usize>(x: [bool; N]) -> Value {
    Value::new(Conversion::Bool, x.map(u8::from))
}
fn i(x: i32) -> Value {
    Value::new(Conversion::Int, [x])
}
fn ints<const N: usize>(x: [i32; N]) -> Value {
    Value::new(Conversion::Int, x)
}
fn e(x: u32) -> Value {
    Value::new(Conversion::Int, [x])
}
fn f(x: f32) -> Value {
    Value::new(Conversion::Float, [x])
}
fn floats<const N: usize>(x: [f32; N]) -> Value {
    Value::new(Conversion::Float, x)
}
fn norm<const N: usize>(x: [f32; N]) -> Value {
    Value::new(Conversion::Normalized, x)
}
fn matrix(s: &MatrixStack, transpose: bool) -> Value {
    let m = if transpose {
        s.top().transpose()
    } else {
        *s.top()
    };
    floats(m.to_cols_array())
}

/// GL 2.1 table 4.9, GLint row: c = ((2³² − 1)·f − 1) / 2, so 1.0 → 2³¹ − 1 and
/// −1.0 → −2³¹; outside [−1, 1] the spec leaves the result undefined (here: saturated).
fn normalized_to_int(x: f64) -> i32 {
    crate::convert::unit_to_signed(x, f64::from(u32::MAX)) as i32
}

fn to_int(kind: Conversion, x: f64) -> i32 {
    match kind {
        // Held exactly, from an i32 or a u32 enum below 2^31.
        Conversion::Bool | Conversion::Int => x as i32,
        // Saturating: a value too large for GLint returns the nearest one (GL 2.1 §6.1.2).
        Conversion::Float => x.round() as i32,
        Conversion::Normalized => normalized_to_int(x),
    }
}

impl Context {
    /// The pname table: count, kind and values of every state variable `glGet` answers
    /// (GL 2.1 tables 6.5 onward, and the implementation limits of tables 6.34 onward).
    /// Enables not listed fall through to the `IsEnabled` capabilities.
    fn query(&mut self, pname: u32) -> Option<Value> {
        let s = &self.state;
        let unit = s.active_texture;
        let tex_stack = s.texture_matrix.get(unit)?;
        let v = match pname {
            // Current values (table 6.5).
            gl::CURRENT_COLOR => norm(s.current.color.to_array()),
            gl::CURRENT_SECONDARY_COLOR => norm(s.current.secondary_color.to_array()),
            gl::CURRENT_TEXTURE_COORDS => floats(s.current.tex_coords.get(unit)?.to_array()),
            gl::CURRENT_NORMAL => norm(s.current.normal.to_array()),
            gl::CURRENT_FOG_COORD => f(s.current.fog_coord),
            gl::EDGE_FLAG => b(s.current.edge_flag),
            gl::CURRENT_INDEX => f(s.current.index),
            // The raster position (table 6.5).
            gl::CURRENT_RASTER_POSITION => floats(s.raster_pos.window.to_array()),
            gl::CURRENT_RASTER_POSITION_VALID => b(s.raster_pos.valid),
            gl::CURRENT_RASTER_COLOR => norm(s.raster_pos.color.to_array()),
            gl::CURRENT_RASTER_SECONDARY_COLOR => norm(s.raster_pos.secondary_color.to_array()),
            gl::CURRENT_RASTER_INDEX => f(s.raster_pos.index),
            gl::CURRENT_RASTER_TEXTURE_COORDS => {
                floats(s.raster_pos.tex_coords.get(unit)?.to_array())
            }
            gl::CURRENT_RASTER_DISTANCE => f(s.raster_pos.distance),
            // Pixel transfer and zoom (table 6.23), pixel map sizes (table 6.24).
            gl::MAP_COLOR => b(s.pixel.map_color),
            gl::MAP_STENCIL => b(s.pixel.map_stencil),
            gl::INDEX_SHIFT => i(s.pixel.index_shift),
            gl::INDEX_OFFSET => i(s.pixel.index_offset),
            gl::RED_SCALE => f(s.pixel.scale[0]),
            gl::GREEN_SCALE => f(s.pixel.scale[1]),
            gl::BLUE_SCALE => f(s.pixel.scale[2]),
            gl::ALPHA_SCALE => f(s.pixel.scale[3]),
            gl::RED_BIAS => f(s.pixel.bias[0]),
            gl::GREEN_BIAS => f(s.pixel.bias[1]),
            gl::BLUE_BIAS => f(s.pixel.bias[2]),
            gl::ALPHA_BIAS => f(s.pixel.bias[3]),
            gl::DEPTH_SCALE => f(s.pixel.depth_scale),
            gl::DEPTH_BIAS => f(s.pixel.depth_bias),
            gl::ZOOM_X => f(s.pixel.zoom[0]),
            gl::ZOOM_Y => f(s.pixel.zoom[1]),
            gl::PIXEL_MAP_I_TO_I_SIZE..=gl::PIXEL_MAP_A_TO_A_SIZE => {
                let k = (pname - gl::PIXEL_MAP_I_TO_I_SIZE) as usize;
                i(s.pixel_maps.tables.get(k)?.len() as i32)
            }
            gl::MAX_PIXEL_MAP_TABLE => i(crate::pixels::MAX_PIXEL_MAP_TABLE as i32),
            // Transformation (tables 6.7, 6.8).
            gl::MODELVIEW_MATRIX => matrix(&s.modelview, false),
            gl::PROJECTION_MATRIX => matrix(&s.projection, false),
            gl::TEXTURE_MATRIX => matrix(tex_stack, false),
            gl::TRANSPOSE_MODELVIEW_MATRIX => matrix(&s.modelview, true),
            gl::TRANSPOSE_PROJECTION_MATRIX => matrix(&s.projection, true),
            gl::TRANSPOSE_TEXTURE_MATRIX => matrix(tex_stack, true),
            gl::MODELVIEW_STACK_DEPTH => i(s.modelview.depth() as i32),
            gl::PROJECTION_STACK_DEPTH => i(s.projection.depth() as i32),
            gl::TEXTURE_STACK_DEPTH => i(tex_stack.depth() as i32),
            gl::MATRIX_MODE => e(s.matrix_mode),
            gl::VIEWPORT => ints(s.viewport),
            gl::DEPTH_RANGE => Value::new(Conversion::Normalized, s.depth_range),
            gl::ACTIVE_TEXTURE => e(gl::TEXTURE0 + unit as u32),
            gl::CLIENT_ACTIVE_TEXTURE => e(gl::TEXTURE0 + s.client_active_texture as u32),
            // Colouring and lighting (tables 6.8, 6.9).
            gl::SHADE_MODEL => e(s.shade_model),
            gl::COLOR_MATERIAL_FACE => e(s.color_material_face),
            gl::COLOR_MATERIAL_PARAMETER => e(s.color_material_mode),
            gl::LIGHT_MODEL_AMBIENT => norm(s.light_model.ambient.to_array()),
            gl::LIGHT_MODEL_LOCAL_VIEWER => b(s.light_model.local_viewer),
            gl::LIGHT_MODEL_TWO_SIDE => b(s.light_model.two_side),
            gl::LIGHT_MODEL_COLOR_CONTROL => e(s.light_model.color_control),
            // Rasterisation (tables 6.11 to 6.13).
            gl::POINT_SIZE => f(s.point_size),
            gl::POINT_SIZE_MIN => f(s.point.size_min),
            gl::POINT_SIZE_MAX => f(s.point.size_max),
            gl::POINT_FADE_THRESHOLD_SIZE => f(s.point.fade_threshold),
            gl::POINT_DISTANCE_ATTENUATION => floats(s.point.distance_attenuation),
            gl::POINT_SPRITE_COORD_ORIGIN => e(s.point.sprite_coord_origin),
            gl::LINE_WIDTH => f(s.line_width),
            gl::LINE_STIPPLE_PATTERN => i(i32::from(s.stipple.line_pattern)),
            gl::LINE_STIPPLE_REPEAT => i(s.stipple.line_repeat),
            gl::FRONT_FACE => e(s.front_face),
            gl::CULL_FACE_MODE => e(s.cull_face_mode),
            gl::POLYGON_MODE => ints(s.polygon_mode.map(|m| m as i32)),
            gl::POLYGON_OFFSET_FACTOR => f(s.polygon_offset_factor),
            gl::POLYGON_OFFSET_UNITS => f(s.polygon_offset_units),
            // Pixel operations and framebuffer control (tables 6.20 to 6.22).
            gl::SCISSOR_BOX => ints(s.scissor),
            gl::DEPTH_FUNC => e(s.depth_func),
            gl::COLOR_WRITEMASK => bools(s.color_mask),
            gl::DEPTH_WRITEMASK => b(s.depth_mask),
            // fragment ops: masks are unsigned; past i32::MAX GetIntegerv saturates (§6.1.2).
            gl::STENCIL_WRITEMASK => e(s.stencil_writemask),
            gl::INDEX_WRITEMASK => e(s.index_writemask),
            gl::INDEX_CLEAR_VALUE => e(s.clear_index),
            gl::COLOR_CLEAR_VALUE => norm(s.clear_color.to_array()),
            gl::DEPTH_CLEAR_VALUE => Value::new(Conversion::Normalized, [s.clear_depth]),
            gl::STENCIL_CLEAR_VALUE => i(s.clear_stencil),
            // Pixel store (tables 6.17, 6.18): SWAP_BYTES and LSB_FIRST are booleans.
            p if crate::pixel_store::pname(p).is_some() => {
                let (pack, mode) = crate::pixel_store::pname(p)?;
                let v = if pack { s.pack } else { s.unpack }.get(mode);
                if mode.is_boolean() {
                    b(v != 0)
                } else {
                    i(v)
                }
            }
            // Hints (table 6.37).
            gl::PERSPECTIVE_CORRECTION_HINT => e(s.hints.perspective_correction),
            gl::POINT_SMOOTH_HINT => e(s.hints.point_smooth),
            gl::LINE_SMOOTH_HINT => e(s.hints.line_smooth),
            gl::POLYGON_SMOOTH_HINT => e(s.hints.polygon_smooth),
            gl::FOG_HINT => e(s.hints.fog),
            gl::GENERATE_MIPMAP_HINT => e(s.hints.generate_mipmap),
            gl::TEXTURE_COMPRESSION_HINT => e(s.hints.texture_compression),
            gl::FRAGMENT_SHADER_DERIVATIVE_HINT => e(s.hints.fragment_shader_derivative),
            gl::PHONG_HINT_WIN => e(s.hints.phong),
            // Implementation-dependent values (tables 6.34 to 6.40).
            gl::MAX_LIGHTS => i(MAX_LIGHTS as i32),
            gl::MAX_CLIP_PLANES => i(MAX_CLIP_PLANES as i32),
            gl::MAX_MODELVIEW_STACK_DEPTH => i(MAX_MODELVIEW_STACK_DEPTH as i32),
            gl::MAX_PROJECTION_STACK_DEPTH => i(MAX_PROJECTION_STACK_DEPTH as i32),
            gl::MAX_TEXTURE_STACK_DEPTH => i(MAX_TEXTURE_STACK_DEPTH as i32),
            gl::MAX_TEXTURE_UNITS => i(MAX_TEXTURE_UNITS as i32),
            // GL 1.3 with no compressed format (no compression extension is offered): none to
            // list; the generic COMPRESSED_* internal formats are stored uncompressed.
            gl::NUM_COMPRESSED_TEXTURE_FORMATS => i(0),
            gl::COMPRESSED_TEXTURE_FORMATS => Value::new(Conversion::Int, [0i32; 0]),
            gl::MAX_VIEWPORT_DIMS => ints([MAX_VIEWPORT_DIM as i32; 2]),
            gl::MAX_TEXTURE_SIZE | gl::MAX_3D_TEXTURE_SIZE => i(crate::texture::MAX_TEXTURE_SIZE),
            gl::SUBPIXEL_BITS => i(SUBPIXEL_BITS),
            gl::ALIASED_POINT_SIZE_RANGE | gl::SMOOTH_POINT_SIZE_RANGE => floats(POINT_SIZE_RANGE),
            gl::SMOOTH_POINT_SIZE_GRANULARITY => f(POINT_SIZE_GRANULARITY),
            gl::ALIASED_LINE_WIDTH_RANGE | gl::SMOOTH_LINE_WIDTH_RANGE => floats(LINE_WIDTH_RANGE),
            gl::SMOOTH_LINE_WIDTH_GRANULARITY => f(LINE_WIDTH_GRANULARITY),
            gl::RED_BITS | gl::GREEN_BITS | gl::BLUE_BITS => i(8),
            gl::ALPHA_BITS => i(if s.config.alpha { 8 } else { 0 }),
            // The framebuffer's buffers (table 6.33), as the context was made.
            gl::DEPTH_BITS => i(if s.config.depth { 24 } else { 0 }),
            gl::STENCIL_BITS => i(if s.config.stencil { 8 } else { 0 }),
            gl::ACCUM_RED_BITS
            | gl::ACCUM_GREEN_BITS
            | gl::ACCUM_BLUE_BITS
            | gl::ACCUM_ALPHA_BITS => i(if s.config.accum { 16 } else { 0 }),
            gl::DOUBLEBUFFER => b(s.config.double_buffered),
            gl::INDEX_BITS | gl::AUX_BUFFERS | gl::SAMPLE_BUFFERS | gl::SAMPLES => i(0),
            gl::RGBA_MODE => b(true),
            gl::INDEX_MODE | gl::STEREO => b(false),
            // Tables 6.22, 6.26, 6.31.
            gl::DRAW_BUFFER => e(s.draw_buffer),
            gl::READ_BUFFER => e(s.read_buffer),
            gl::ACCUM_CLEAR_VALUE => norm(s.accum_clear.to_array()),
            gl::RENDER_MODE => e(s.render_mode),
            // Selection and feedback (GL 2.1 table 6.31 and GL 1.1's sizes).
            gl::NAME_STACK_DEPTH => i(self.renderer.sink.name_stack_depth() as i32),
            gl::MAX_NAME_STACK_DEPTH => i(crate::cpu::feedback::MAX_NAME_STACK_DEPTH as i32),
            gl::SELECTION_BUFFER_SIZE => i(self.renderer.sink.select_size.unwrap_or(0) as i32),
            // GL_EXT_framebuffer_object (context/fbo.rs).
            gl::FRAMEBUFFER_BINDING => i(self.fbos.bound_fb as i32),
            gl::RENDERBUFFER_BINDING => i(self.fbos.bound_rb as i32),
            gl::MAX_RENDERBUFFER_SIZE => i(super::fbo::MAX_RENDERBUFFER_SIZE),
            gl::MAX_COLOR_ATTACHMENTS => i(super::fbo::MAX_COLOR_ATTACHMENTS),
            gl::FEEDBACK_BUFFER_SIZE => i(self.renderer.sink.feedback_size.unwrap_or(0) as i32),
            gl::FEEDBACK_BUFFER_TYPE => e(self.renderer.sink.feedback_type),
            // Display lists, attribute stacks (table 6.36, 6.35)
            gl::LIST_BASE => e(s.list_base),
            gl::LIST_INDEX => e(self.list_index_and_mode().0),
            gl::LIST_MODE => e(self.list_index_and_mode().1),
            gl::MAX_LIST_NESTING => e(super::MAX_LIST_NESTING),
            gl::ATTRIB_STACK_DEPTH => i(self.attrib_stack_depths().0 as i32),
            gl::CLIENT_ATTRIB_STACK_DEPTH => i(self.attrib_stack_depths().1 as i32),
            gl::MAX_ATTRIB_STACK_DEPTH | gl::MAX_CLIENT_ATTRIB_STACK_DEPTH => {
                i(super::MAX_ATTRIB_STACK_DEPTH as i32)
            }
            // Client arrays (tables 6.6 to 6.8) and buffer bindings (GL 2.1 §2.9).
            gl::VERTEX_ARRAY
            | gl::NORMAL_ARRAY
            | gl::COLOR_ARRAY
            | gl::SECONDARY_COLOR_ARRAY
            | gl::FOG_COORD_ARRAY
            | gl::EDGE_FLAG_ARRAY
            | gl::INDEX_ARRAY
            | gl::TEXTURE_COORD_ARRAY => b(s.arrays.enabled(pname, s.client_active_texture)?),
            gl::VERTEX_ARRAY_SIZE => i(s.arrays.vertex.size),
            gl::VERTEX_ARRAY_TYPE => e(s.arrays.vertex.ty),
            gl::VERTEX_ARRAY_STRIDE => i(s.arrays.vertex.stride),
            gl::VERTEX_ARRAY_BUFFER_BINDING => e(s.arrays.vertex.buffer),
            gl::NORMAL_ARRAY_TYPE => e(s.arrays.normal.ty),
            gl::NORMAL_ARRAY_STRIDE => i(s.arrays.normal.stride),
            gl::NORMAL_ARRAY_BUFFER_BINDING => e(s.arrays.normal.buffer),
            gl::COLOR_ARRAY_SIZE => i(s.arrays.color.size),
            gl::COLOR_ARRAY_TYPE => e(s.arrays.color.ty),
            gl::COLOR_ARRAY_STRIDE => i(s.arrays.color.stride),
            gl::COLOR_ARRAY_BUFFER_BINDING => e(s.arrays.color.buffer),
            gl::SECONDARY_COLOR_ARRAY_SIZE => i(s.arrays.secondary_color.size),
            gl::SECONDARY_COLOR_ARRAY_TYPE => e(s.arrays.secondary_color.ty),
            gl::SECONDARY_COLOR_ARRAY_STRIDE => i(s.arrays.secondary_color.stride),
            gl::SECONDARY_COLOR_ARRAY_BUFFER_BINDING => e(s.arrays.secondary_color.buffer),
            gl::FOG_COORD_ARRAY_TYPE => e(s.arrays.fog_coord.ty),
            gl::FOG_COORD_ARRAY_STRIDE => i(s.arrays.fog_coord.stride),
            gl::FOG_COORD_ARRAY_BUFFER_BINDING => e(s.arrays.fog_coord.buffer),
            gl::EDGE_FLAG_ARRAY_STRIDE => i(s.arrays.edge_flag.stride),
            gl::EDGE_FLAG_ARRAY_BUFFER_BINDING => e(s.arrays.edge_flag.buffer),
            gl::INDEX_ARRAY_TYPE => e(s.arrays.index.ty),
            gl::INDEX_ARRAY_STRIDE => i(s.arrays.index.stride),
            gl::INDEX_ARRAY_BUFFER_BINDING => e(s.arrays.index.buffer),
            gl::TEXTURE_COORD_ARRAY_SIZE => {
                i(s.arrays.tex_coords.get(s.client_active_texture)?.size)
            }
            gl::TEXTURE_COORD_ARRAY_TYPE => e(s.arrays.tex_coords.get(s.client_active_texture)?.ty),
            gl::TEXTURE_COORD_ARRAY_STRIDE => {
                i(s.arrays.tex_coords.get(s.client_active_texture)?.stride)
            }
            gl::TEXTURE_COORD_ARRAY_BUFFER_BINDING => {
                e(s.arrays.tex_coords.get(s.client_active_texture)?.buffer)
            }
            gl::ARRAY_BUFFER_BINDING => e(s.arrays.array_buffer),
            gl::ELEMENT_ARRAY_BUFFER_BINDING => e(s.arrays.element_array_buffer),
            gl::MAX_ELEMENTS_VERTICES | gl::MAX_ELEMENTS_INDICES => i(crate::arrays::MAX_ELEMENTS),
            gl::FOG_MODE => e(s.fog.mode),
            gl::FOG_DENSITY => f(s.fog.density),
            gl::FOG_START => f(s.fog.start),
            gl::FOG_END => f(s.fog.end),
            gl::FOG_INDEX => f(s.fog.index),
            gl::FOG_COLOR => norm(s.fog.color.to_array()),
            gl::FOG_COORD_SRC => e(s.fog.coord_src),
            // Table 6.15 (§4.1.3): as Mesa, a float (GetIntegerv rounds) and a boolean.
            gl::SAMPLE_COVERAGE_VALUE => f(s.sample_coverage_value),
            gl::SAMPLE_COVERAGE_INVERT => b(s.sample_coverage_invert),
            gl::ALPHA_TEST_FUNC => e(s.alpha.func),
            gl::ALPHA_TEST_REF => norm([s.alpha.reference]),
            gl::STENCIL_FUNC => e(s.stencil.faces[FRONT].func),
            gl::STENCIL_REF => i(stencil_ref(s.stencil.faces[FRONT].reference)),
            gl::STENCIL_VALUE_MASK => e(s.stencil.faces[FRONT].value_mask),
            gl::STENCIL_FAIL => e(s.stencil.faces[FRONT].fail),
            gl::STENCIL_PASS_DEPTH_FAIL => e(s.stencil.faces[FRONT].zfail),
            gl::STENCIL_PASS_DEPTH_PASS => e(s.stencil.faces[FRONT].zpass),
            gl::STENCIL_BACK_FUNC => e(s.stencil.faces[BACK].func),
            gl::STENCIL_BACK_REF => i(stencil_ref(s.stencil.faces[BACK].reference)),
            gl::STENCIL_BACK_VALUE_MASK => e(s.stencil.faces[BACK].value_mask),
            gl::STENCIL_BACK_FAIL => e(s.stencil.faces[BACK].fail),
            gl::STENCIL_BACK_PASS_DEPTH_FAIL => e(s.stencil.faces[BACK].zfail),
            gl::STENCIL_BACK_PASS_DEPTH_PASS => e(s.stencil.faces[BACK].zpass),
            gl::STENCIL_BACK_WRITEMASK => e(s.stencil.back_writemask),
            gl::BLEND_SRC | gl::BLEND_SRC_RGB => e(s.blend.src_rgb),
            gl::BLEND_DST | gl::BLEND_DST_RGB => e(s.blend.dst_rgb),
            gl::BLEND_SRC_ALPHA => e(s.blend.src_alpha),
            gl::BLEND_DST_ALPHA => e(s.blend.dst_alpha),
            gl::BLEND_EQUATION_RGB => e(s.blend.equation_rgb),
            gl::BLEND_EQUATION_ALPHA => e(s.blend.equation_alpha),
            gl::BLEND_COLOR => norm(s.blend.color.to_array()),
            gl::LOGIC_OP_MODE => e(s.logic_op),
            // Table 6.15: one binding per target on the active unit, in TARGETS order.
            gl::TEXTURE_BINDING_1D => i(s.textures.units.get(unit)?.bindings[0] as i32),
            gl::TEXTURE_BINDING_2D => i(s.textures.units.get(unit)?.bindings[1] as i32),
            gl::TEXTURE_BINDING_3D => i(s.textures.units.get(unit)?.bindings[2] as i32),
            gl::TEXTURE_BINDING_CUBE_MAP => i(s.textures.units.get(unit)?.bindings[3] as i32),
            gl::MAX_TEXTURE_LOD_BIAS => f(crate::texture::MAX_TEXTURE_LOD_BIAS),
            // Evaluators (table 6.33, and MAX_EVAL_ORDER of table 6.35).
            gl::MAX_EVAL_ORDER => i(crate::state::MAX_EVAL_ORDER),
            gl::MAP1_GRID_DOMAIN => floats(s.eval_grid.u1),
            gl::MAP1_GRID_SEGMENTS => i(s.eval_grid.un1),
            gl::MAP2_GRID_DOMAIN => floats(s.eval_grid.d2),
            gl::MAP2_GRID_SEGMENTS => ints(s.eval_grid.n2),
            _ => b(*self.state.cap_mut(pname)?),
        };
        Some(v)
    }

    /// The shared body of the four getters: Begin/End check, table lookup, length check, and
    /// the conversion `conv` into `out`.
    fn get_into<T>(&mut self, pname: u32, out: &mut [T], conv: impl Fn(Conversion, f64) -> T) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        let Some(value) = self.query(pname) else {
            return self.error(gl::INVALID_ENUM);
        };
        write(self, value, out, conv);
    }

    /// How many values `get_*v(pname)` writes; `None` for a pname it does not know (which it
    /// answers with INVALID_ENUM). Not a GL entry point: what a C caller's buffer must hold,
    /// for the C ABI, which gets a bare pointer. Raises no error.
    pub fn get_count(&mut self, pname: u32) -> Option<usize> {
        self.query(pname).map(|v| v.len)
    }

    /// `glGetBooleanv`: a number converts to `false` exactly when it is zero (GL 2.1 §6.1.2).
    /// INVALID_ENUM for an unknown `pname`; INVALID_VALUE, nothing written, if `params` is
    /// shorter than the pname's value count.
    pub fn get_booleanv(&mut self, pname: u32, params: &mut [bool]) {
        self.get_into(pname, params, |_, x| x != 0.0);
    }

    /// `glGetIntegerv`: booleans as 1/0; colours, normals and depth values mapped linearly
    /// from [-1, 1] onto the integer range; other floats rounded to nearest (GL 2.1 §6.1.2).
    /// Errors as [`Context::get_booleanv`].
    pub fn get_integerv(&mut self, pname: u32, params: &mut [i32]) {
        self.get_into(pname, params, to_int);
    }

    /// `glGetFloatv`: booleans as 1.0/0.0, integers converted (GL 2.1 §6.1.2). Errors as
    /// [`Context::get_booleanv`].
    pub fn get_floatv(&mut self, pname: u32, params: &mut [f32]) {
        self.get_into(pname, params, |_, x| x as f32);
    }

    /// `glGetDoublev`: as [`Context::get_floatv`], in double precision (DEPTH_RANGE and
    /// DEPTH_CLEAR_VALUE are held as doubles).
    pub fn get_doublev(&mut self, pname: u32, params: &mut [f64]) {
        self.get_into(pname, params, |_, x| x);
    }

    /// The common validation of GetLight/GetMaterial: Begin/End first, then the enums.
    fn light_value(&mut self, light: u32, pname: u32) -> Option<Value> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let index = light.wrapping_sub(gl::LIGHT0) as usize;
        let value = self
            .state
            .lights
            .get(index)
            .and_then(|l| light_param(l, pname));
        if value.is_none() {
            self.error(gl::INVALID_ENUM);
        }
        value
    }

    fn material_value(&mut self, face: u32, pname: u32) -> Option<Value> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let side = match face {
            gl::FRONT => Some(FRONT),
            gl::BACK => Some(BACK),
            _ => None,
        };
        let value = side
            .and_then(|side| self.state.materials.get(side))
            .and_then(|m| material_param(m, pname));
        if value.is_none() {
            self.error(gl::INVALID_ENUM);
        }
        value
    }

    /// `glGetLightfv`: the parameters of `light` (`LIGHT0 + i`), POSITION and SPOT_DIRECTION
    /// in eye coordinates (GL 2.1 §6.1.3). INVALID_ENUM for a bad light or pname;
    /// INVALID_VALUE, nothing written, if `params` is too short.
    pub fn get_lightfv(&mut self, light: u32, pname: u32, params: &mut [f32]) {
        if let Some(value) = self.light_value(light, pname) {
            write(self, value, params, |_, x| x as f32);
        }
    }

    /// `glGetLightiv`: as [`Context::get_lightfv`]; colours map linearly onto the integer
    /// range, the other parameters round to nearest.
    pub fn get_lightiv(&mut self, light: u32, pname: u32, params: &mut [i32]) {
        if let Some(value) = self.light_value(light, pname) {
            write(self, value, params, to_int);
        }
    }

    /// `glGetMaterialfv`: `face` is FRONT or BACK (FRONT_AND_BACK is INVALID_ENUM), `pname`
    /// AMBIENT, DIFFUSE, SPECULAR, EMISSION, SHININESS or COLOR_INDEXES. INVALID_VALUE,
    /// nothing written, if `params` is too short.
    pub fn get_materialfv(&mut self, face: u32, pname: u32, params: &mut [f32]) {
        if let Some(value) = self.material_value(face, pname) {
            write(self, value, params, |_, x| x as f32);
        }
    }

    /// `glGetMaterialiv`: as [`Context::get_materialfv`]; colours map linearly onto the
    /// integer range, SHININESS and COLOR_INDEXES round to nearest.
    pub fn get_materialiv(&mut self, face: u32, pname: u32, params: &mut [i32]) {
        if let Some(value) = self.material_value(face, pname) {
            write(self, value, params, to_int);
        }
    }

    /// `glGetClipPlane`: the plane's equation in eye coordinates, as `clip_plane` stored it.
    /// INVALID_ENUM unless `plane` is `CLIP_PLANE0 + i`, i < MAX_CLIP_PLANES.
    pub fn get_clip_plane(&mut self, plane: u32, equation: &mut [f64; 4]) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        let index = plane.wrapping_sub(gl::CLIP_PLANE0) as usize;
        match self.state.clip_planes.get(index) {
            Some(p) => *equation = p.to_array(),
            None => self.error(gl::INVALID_ENUM),
        }
    }

    /// `glGetString`: VENDOR, RENDERER, VERSION ("1.5 fixedgl" and the crate version) or
    /// EXTENSIONS; `None` with INVALID_ENUM for any other name, and with INVALID_OPERATION
    /// between Begin and End.
    pub fn get_string(&mut self, name: u32) -> Option<&'static str> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let s = match name {
            gl::VENDOR => VENDOR,
            gl::RENDERER => RENDERER,
            gl::VERSION => VERSION,
            gl::EXTENSIONS => EXTENSIONS,
            _ => {
                self.error(gl::INVALID_ENUM);
                return None;
            }
        };
        Some(s)
    }
}

/// Writes `value` into `out` through `conv`, or raises INVALID_VALUE and writes nothing when
/// `out` is too short.
fn write<T>(ctx: &mut Context, value: Value, out: &mut [T], conv: impl Fn(Conversion, f64) -> T) {
    if out.len() < value.len {
        return ctx.error(gl::INVALID_VALUE);
    }
    for (o, x) in out.iter_mut().zip(value.values()) {
        *o = conv(value.kind, x);
    }
}

/// GetLight's table (GL 2.1 table 6.10).
fn light_param(l: &Light, pname: u32) -> Option<Value> {
    Some(match pname {
        gl::AMBIENT => norm(l.ambient.to_array()),
        gl::DIFFUSE => norm(l.diffuse.to_array()),
        gl::SPECULAR => norm(l.specular.to_array()),
        gl::POSITION => floats(l.position.to_array()),
        gl::SPOT_DIRECTION => floats(l.spot_direction.to_array()),
        gl::SPOT_EXPONENT => f(l.spot_exponent),
        gl::SPOT_CUTOFF => f(l.spot_cutoff),
        gl::CONSTANT_ATTENUATION => f(l.constant_attenuation),
        gl::LINEAR_ATTENUATION => f(l.linear_attenuation),
        gl::QUADRATIC_ATTENUATION => f(l.quadratic_attenuation),
        _ => return None,
    })
}

/// GetMaterial's table (GL 2.1 table 6.9).
fn material_param(m: &Material, pname: u32) -> Option<Value> {
    Some(match pname {
        gl::AMBIENT => norm(m.ambient.to_array()),
        gl::DIFFUSE => norm(m.diffuse.to_array()),
        gl::SPECULAR => norm(m.specular.to_array()),
        gl::EMISSION => norm(m.emission.to_array()),
        gl::SHININESS => f(m.shininess),
        gl::COLOR_INDEXES => floats(m.color_indexes),
        _ => return None,
    })
}

/// STENCIL_REF as queried: the reference clamped to [0, 2^8 - 1] (GL 2.1 §4.1.5).
fn stencil_ref(r: i32) -> i32 {
    r.clamp(0, 255)
}
