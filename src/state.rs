//! The GL state vector as plain data (GL 2.1 §6.2, tables 6.4 onwards).
//!
//! `State::new` is the spec's initial-state tables and nothing else: every field's starting value
//! cites the table it comes from, so a state test can check one against the other. The front end
//! (`crate::context`) is the only writer and validates before writing; the CPU pipeline
//! (`crate::cpu`) reads it when it flushes a batch of vertices.
//!
//! Design decision: positions and directions that GL transforms "by the modelview matrix current
//! at the call" (light POSITION and SPOT_DIRECTION, clip planes, later TexGen eye planes) are stored
//! already transformed, in eye coordinates, exactly as `glGet*` reports them.

// Fields are named after the GL state they hold (`light.spot_cutoff` is SPOT_CUTOFF): the table
// row is their documentation.
#![allow(missing_docs)]

use glam::{DVec4, Mat4, Vec3, Vec4};

use crate::gl;

/// Number of lights (`MAX_LIGHTS`; the spec's minimum, and Mesa's value).
pub const MAX_LIGHTS: usize = 8;
/// Number of user clip planes (`MAX_CLIP_PLANES`).
pub const MAX_CLIP_PLANES: usize = 6;
/// Number of texture units (`MAX_TEXTURE_UNITS`).
pub const MAX_TEXTURE_UNITS: usize = 4;
/// `MAX_MODELVIEW_STACK_DEPTH` (the spec's minimum and Mesa's value).
pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
/// `MAX_PROJECTION_STACK_DEPTH` (Mesa's value; the spec's minimum is 2).
pub const MAX_PROJECTION_STACK_DEPTH: usize = 32;
/// `MAX_TEXTURE_STACK_DEPTH` (Mesa's value; the spec's minimum is 2).
pub const MAX_TEXTURE_STACK_DEPTH: usize = 10;
/// Largest framebuffer side `Context::new` accepts (`MAX_VIEWPORT_DIMS`, Mesa's value).
pub const MAX_VIEWPORT_DIM: u32 = 16384;

/// What a context's framebuffer holds, fixed when the context is made (the window system's
/// pixel format: GLUT's GLUT_DOUBLE, GLUT_DEPTH, GLUT_STENCIL, GLUT_ACCUM). Colour is always
/// RGBA8, front-left only (no stereo, no AUX buffers); `Default` is what `Context::new` gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ContextConfig {
    /// A back buffer besides the front one: DOUBLEBUFFER is TRUE, DRAW_BUFFER and READ_BUFFER
    /// start at BACK (GL 2.1 §4.2.1, §4.3.2) and `Context::swap_buffers` presents the back
    /// buffer. Default: false (one colour buffer, FRONT).
    pub double_buffered: bool,
    /// A 24-bit depth buffer (DEPTH_BITS 24). Without one the depth test always passes and
    /// nothing is written (GL 2.1 §4.1.6). Default: true.
    pub depth: bool,
    /// An 8-bit stencil buffer (STENCIL_BITS 8). Without one the stencil test always passes
    /// and nothing is written (§4.1.5). Default: true.
    pub stencil: bool,
    /// An accumulation buffer of 16 signed bits per channel, as llvmpipe's (ACCUM_*_BITS 16;
    /// GL 2.1 §4.2.4). Without one `Accum` is INVALID_OPERATION. Default: false.
    pub accum: bool,
    /// Alpha bits in the colour buffers (ALPHA_BITS 8). Without them (ALPHA_BITS 0, an RGB
    /// visual or EGL config) alpha writes are dropped and the destination alpha reads as 1, in
    /// blending, ReadPixels, CopyPixels, CopyTexImage and Accum (GL 2.1 §4.1.8, §4.3.2).
    /// Default: true.
    pub alpha: bool,
}

impl Default for ContextConfig {
    fn default() -> Self {
        Self {
            double_buffered: false,
            depth: true,
            stencil: true,
            accum: false,
            alpha: true,
        }
    }
}

/// A matrix stack (GL 2.1 §2.11.2). Never empty: the last element is the current matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStack {
    /// The stack, bottom first; `stack.last()` is the current matrix.
    pub stack: Vec<Mat4>,
    /// The most matrices the stack may hold.
    pub max_depth: usize,
}

impl MatrixStack {
    /// A stack holding one identity matrix.
    pub fn new(max_depth: usize) -> Self {
        let mut stack = Vec::with_capacity(max_depth);
        stack.push(Mat4::IDENTITY);
        Self { stack, max_depth }
    }

    /// The current (top) matrix.
    pub fn top(&self) -> &Mat4 {
        // The stack is never empty: `new` pushes one and `pop` refuses the last.
        &self.stack[self.stack.len() - 1]
    }

    /// The current (top) matrix, to modify in place.
    pub fn top_mut(&mut self) -> &mut Mat4 {
        let last = self.stack.len() - 1;
        &mut self.stack[last]
    }

    /// The number of matrices on the stack (`*_STACK_DEPTH`).
    pub fn depth(&self) -> usize {
        self.stack.len()
    }
}

/// One light source's parameters (GL 2.1 table 6.10), in eye coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    /// Eye coordinates: transformed by the modelview matrix current at `lightfv(POSITION)`.
    pub position: Vec4,
    /// Eye coordinates: transformed by the upper 3x3 of the modelview at `lightfv(SPOT_DIRECTION)`.
    pub spot_direction: Vec3,
    pub spot_exponent: f32,
    pub spot_cutoff: f32,
    pub constant_attenuation: f32,
    pub linear_attenuation: f32,
    pub quadratic_attenuation: f32,
}

impl Light {
    /// The initial values of light `i` (LIGHT0 differs: white diffuse and specular).
    pub fn initial(i: usize) -> Self {
        let one = if i == 0 {
            Vec4::ONE
        } else {
            Vec4::new(0.0, 0.0, 0.0, 1.0)
        };
        Self {
            ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
            diffuse: one,
            specular: one,
            position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
        }
    }
}

/// `LightModel` parameters (GL 2.1 table 6.9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightModel {
    pub ambient: Vec4,
    pub local_viewer: bool,
    pub two_side: bool,
    /// `SINGLE_COLOR` or `SEPARATE_SPECULAR_COLOR`.
    pub color_control: u32,
}

/// One face's material (GL 2.1 table 6.9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    pub emission: Vec4,
    pub shininess: f32,
    /// `COLOR_INDEXES` (ambient, diffuse, specular indices; colour-index mode only, kept for queries).
    pub color_indexes: [f32; 3],
}

impl Default for Material {
    fn default() -> Self {
        Self {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
            color_indexes: [0.0, 1.0, 1.0],
        }
    }
}

/// Index of the front material in `State::materials`.
pub const FRONT: usize = 0;
/// Index of the back material in `State::materials`.
pub const BACK: usize = 1;

/// Every capability `Enable`/`Disable`/`IsEnabled` accept (GL 2.1 tables 6.x, "Enable" rows).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Enables {
    pub lighting: bool,
    pub lights: [bool; MAX_LIGHTS],
    pub normalize: bool,
    pub rescale_normal: bool,
    pub color_material: bool,
    pub depth_test: bool,
    pub cull_face: bool,
    pub clip_planes: [bool; MAX_CLIP_PLANES],
    pub polygon_offset_fill: bool,
    pub polygon_offset_line: bool,
    pub polygon_offset_point: bool,
    pub scissor_test: bool,
    pub alpha_test: bool,
    pub blend: bool,
    pub stencil_test: bool,
    pub fog: bool,
    pub color_sum: bool,
    pub color_logic_op: bool,
    pub index_logic_op: bool,
    /// Initially true (GL 2.1 table 6.21).
    pub dither: bool,
    pub line_smooth: bool,
    pub line_stipple: bool,
    pub point_smooth: bool,
    pub point_sprite: bool,
    pub polygon_smooth: bool,
    pub polygon_stipple: bool,
    pub auto_normal: bool,
    pub multisample: bool,
    pub sample_alpha_to_coverage: bool,
    pub sample_alpha_to_one: bool,
    pub sample_coverage: bool,
    pub vertex_program_point_size: bool,
    pub vertex_program_two_side: bool,
    /// Per texture unit: TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP.
    pub texture_1d: [bool; MAX_TEXTURE_UNITS],
    pub texture_2d: [bool; MAX_TEXTURE_UNITS],
    pub texture_3d: [bool; MAX_TEXTURE_UNITS],
    pub texture_cube_map: [bool; MAX_TEXTURE_UNITS],
    /// Per texture unit, TEXTURE_GEN_S, _T, _R, _Q.
    pub texture_gen: [[bool; 4]; MAX_TEXTURE_UNITS],
    /// Evaluator maps, indexed as [`EvalMaps`]: `MAP1_COLOR_4 + i`, `MAP2_COLOR_4 + i`.
    pub map1: [bool; 9],
    pub map2: [bool; 9],
}

impl Default for Enables {
    fn default() -> Self {
        Self {
            lighting: false,
            lights: [false; MAX_LIGHTS],
            normalize: false,
            rescale_normal: false,
            color_material: false,
            depth_test: false,
            cull_face: false,
            clip_planes: [false; MAX_CLIP_PLANES],
            polygon_offset_fill: false,
            polygon_offset_line: false,
            polygon_offset_point: false,
            scissor_test: false,
            alpha_test: false,
            blend: false,
            stencil_test: false,
            fog: false,
            color_sum: false,
            color_logic_op: false,
            index_logic_op: false,
            dither: true,
            line_smooth: false,
            line_stipple: false,
            point_smooth: false,
            point_sprite: false,
            polygon_smooth: false,
            polygon_stipple: false,
            auto_normal: false,
            multisample: true,
            sample_alpha_to_coverage: false,
            sample_alpha_to_one: false,
            sample_coverage: false,
            vertex_program_point_size: false,
            vertex_program_two_side: false,
            texture_1d: [false; MAX_TEXTURE_UNITS],
            texture_2d: [false; MAX_TEXTURE_UNITS],
            texture_3d: [false; MAX_TEXTURE_UNITS],
            texture_cube_map: [false; MAX_TEXTURE_UNITS],
            texture_gen: [[false; 4]; MAX_TEXTURE_UNITS],
            map1: [false; 9],
            map2: [false; 9],
        }
    }
}

/// The current vertex attributes (GL 2.1 table 6.5).
///
/// Design decision: the inputs a batched vertex shares with its span (`Inputs`: colours,
/// texture coordinates, fog coordinate, edge flag; cpu/batch.rs) are read through `Deref` and
/// written only through [`Current::inputs_mut`], which gives the value a fresh stamp, never
/// given before in the process. A copy keeps both the inputs and the stamp, so two `Current`s
/// with the same stamp have the same inputs, whatever copied or restored them (PopAttrib, a
/// display list's or an array draw's restore, an evaluator's own copy): the batch then knows a
/// vertex's inputs are its span's with one compare instead of 25 floats. The compiler enforces
/// the rule: the fields are private, so a writer that forgets the stamp does not build.
#[derive(Clone, Copy)]
pub struct Current {
    inputs: Inputs,
    /// See the type's docs; 0 for the initial values (`Default`), which are all the same.
    stamp: u64,
    pub normal: Vec3,
    /// CURRENT_INDEX: the current colour index (§2.7, initially 1), held and pushed in
    /// colour-index mode's place; an RGBA context draws nothing with it.
    pub index: f32,
}

/// The current values a vertex's span shares (see [`Current`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inputs {
    pub color: Vec4,
    pub secondary_color: Vec4,
    pub tex_coords: [Vec4; MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    pub edge_flag: bool,
}

impl Default for Current {
    fn default() -> Self {
        Self {
            inputs: Inputs {
                color: Vec4::ONE,
                secondary_color: Vec4::new(0.0, 0.0, 0.0, 1.0),
                tex_coords: [Vec4::new(0.0, 0.0, 0.0, 1.0); MAX_TEXTURE_UNITS],
                fog_coord: 0.0,
                edge_flag: true,
            },
            stamp: 0,
            normal: Vec3::new(0.0, 0.0, 1.0),
            index: 1.0,
        }
    }
}

impl std::ops::Deref for Current {
    type Target = Inputs;

    #[inline(always)]
    fn deref(&self) -> &Inputs {
        &self.inputs
    }
}

/// The values, without the stamp (as `PartialEq` compares them): two equal values print alike
/// whatever wrote them, NaNs included, which is how state comparisons (the soak test's) tell
/// equal states from different ones.
impl std::fmt::Debug for Current {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Inputs {
            color,
            secondary_color,
            tex_coords,
            fog_coord,
            edge_flag,
        } = &self.inputs;
        f.debug_struct("Current")
            .field("color", color)
            .field("secondary_color", secondary_color)
            .field("normal", &self.normal)
            .field("tex_coords", tex_coords)
            .field("fog_coord", fog_coord)
            .field("edge_flag", edge_flag)
            .field("index", &self.index)
            .finish()
    }
}

/// Equal values, whatever their stamps.
impl PartialEq for Current {
    fn eq(&self, other: &Self) -> bool {
        self.inputs == other.inputs && self.normal == other.normal && self.index == other.index
    }
}

impl Current {
    /// Values with `inputs`, `normal` and `index` (a fresh stamp).
    pub fn new(inputs: Inputs, normal: Vec3, index: f32) -> Self {
        Current {
            inputs,
            stamp: fresh_stamp(),
            normal,
            index,
        }
    }

    /// The inputs, to write: the value takes a fresh stamp (see the type's docs).
    #[inline(always)]
    pub fn inputs_mut(&mut self) -> &mut Inputs {
        self.stamp = fresh_stamp();
        &mut self.inputs
    }

    /// Whether `other` has `self`'s stamp, so the same inputs (see the type's docs); false
    /// after [`Current::forget_stamp`], whatever the inputs.
    #[inline(always)]
    pub fn same_stamp_as(&self, other: &Current) -> bool {
        self.stamp == other.stamp
    }

    /// Gives `self` a stamp no value has (`NO_STAMP`): the inputs are the same, but the next
    /// compare ([`Current::same_inputs_as`]) compares them. The vertex batch's way to look at
    /// its span again at the next vertex when something outside the inputs changed (a
    /// `Material` call inside Begin/End, cpu/batch.rs).
    #[inline]
    pub fn forget_stamp(&mut self) {
        self.stamp = NO_STAMP;
    }

    /// Whether `other`'s inputs have the bits of `self`'s ([`Inputs::same_bits`]): at once
    /// when the stamps are the same (see the type's docs); otherwise compared, and when the
    /// bits are the same, `self` takes `other`'s stamp, so that the next compare with it (or
    /// its copies) is at once.
    #[inline(always)]
    pub fn same_inputs_as(&mut self, other: &Current) -> bool {
        if self.stamp == other.stamp {
            return true;
        }
        let same = self.inputs.same_bits(&other.inputs);
        if same {
            self.stamp = other.stamp;
        }
        same
    }
}

impl Inputs {
    /// Whether every input of `self` has the bits of `other`'s: equal bits, identical inputs
    /// (NaNs with equal bits are equal, -0 and 0 differ), what a batched vertex may share
    /// (cpu/batch.rs), and what two values of one stamp have. Every field is named here (a
    /// new one does not build until it is compared), and both sides lie in the same order:
    /// a few vector loads and compares, without branches and without copying either.
    #[inline(always)]
    pub fn same_bits(&self, other: &Inputs) -> bool {
        let Inputs {
            color,
            secondary_color,
            tex_coords: [t0, t1, t2, t3],
            fog_coord,
            edge_flag,
        } = self;
        let [u0, u1, u2, u3] = &other.tex_coords;
        let bits = |v: &Vec4| v.to_array().map(f32::to_bits);
        let pairs = [
            (color, &other.color),
            (secondary_color, &other.secondary_color),
            (t0, u0),
            (t1, u1),
            (t2, u2),
            (t3, u3),
        ];
        let mut d = fog_coord.to_bits() ^ other.fog_coord.to_bits();
        d |= u32::from(*edge_flag ^ other.edge_flag);
        for (x, y) in pairs {
            let (x, y) = (bits(x), bits(y));
            for k in 0..4 {
                d |= x[k] ^ y[k];
            }
        }
        d == 0
    }
}

/// A stamp no value has: `fresh_stamp` hands out none of block 0, whose only stamp in use is
/// 0, the initial values' (`Current::forget_stamp`).
const NO_STAMP: u64 = 1;

/// Stamps a thread hands out before it takes another block of them.
const STAMP_BLOCK: u64 = 1 << 32;

/// A stamp never given before (see [`Current`]): the next of the calling thread's block of
/// `STAMP_BLOCK`, blocks being taken from one process-wide counter (so threads never hand out
/// the same stamp, and a context may move between threads). A plain thread-local increment
/// almost always: an atomic operation per stamp would cost tens of cycles on every `Color` or
/// `TexCoord` call.
#[inline(always)]
fn fresh_stamp() -> u64 {
    use std::cell::Cell;
    use std::sync::atomic::{AtomicU64, Ordering};
    // Block 0 holds stamp 0, the initial values', so it is never handed out.
    static BLOCKS: AtomicU64 = AtomicU64::new(1);
    thread_local! {
        static NEXT: Cell<u64> = const { Cell::new(0) };
    }
    NEXT.with(|next| {
        let mut s = next.get();
        if s % STAMP_BLOCK == 0 {
            // The thread's first stamp, or its block used up.
            s = BLOCKS.fetch_add(1, Ordering::Relaxed) * STAMP_BLOCK;
        }
        next.set(s + 1);
        s
    })
}

/// `Hint` targets (GL 2.1 table 6.37); each `DONT_CARE`, `FASTEST` or `NICEST`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hints {
    pub perspective_correction: u32,
    pub point_smooth: u32,
    pub line_smooth: u32,
    pub polygon_smooth: u32,
    pub fog: u32,
    pub generate_mipmap: u32,
    pub texture_compression: u32,
    pub fragment_shader_derivative: u32,
    /// `PHONG_HINT_WIN` (GL_WIN_phong_shading).
    pub phong: u32,
}

impl Default for Hints {
    fn default() -> Self {
        let d = gl::DONT_CARE;
        Self {
            perspective_correction: d,
            point_smooth: d,
            line_smooth: d,
            polygon_smooth: d,
            fog: d,
            generate_mipmap: d,
            texture_compression: d,
            fragment_shader_derivative: d,
            phong: d,
        }
    }
}

/// Point parameters (GL 2.1 §3.4, table 6.11; `PointParameter`) and each unit's COORD_REPLACE
/// (§3.4.1, attribute group "point").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointParams {
    /// POINT_SIZE_MIN (initially 0).
    pub size_min: f32,
    /// POINT_SIZE_MAX (initially the largest point size, as llvmpipe reports it: 255).
    pub size_max: f32,
    /// POINT_FADE_THRESHOLD_SIZE (initially 1).
    pub fade_threshold: f32,
    /// POINT_DISTANCE_ATTENUATION: a, b, c of §3.4 eq. 3.1 (initially 1, 0, 0).
    pub distance_attenuation: [f32; 3],
    /// POINT_SPRITE_COORD_ORIGIN: UPPER_LEFT (initial) or LOWER_LEFT.
    pub sprite_coord_origin: u32,
    /// COORD_REPLACE of each texture unit (TexEnv target POINT_SPRITE).
    pub coord_replace: [bool; MAX_TEXTURE_UNITS],
}

impl Default for PointParams {
    fn default() -> Self {
        PointParams {
            size_min: 0.0,
            size_max: 255.0,
            fade_threshold: 1.0,
            distance_attenuation: [1.0, 0.0, 0.0],
            sprite_coord_origin: gl::UPPER_LEFT,
            coord_replace: [false; MAX_TEXTURE_UNITS],
        }
    }
}

impl PointParams {
    /// Distance attenuation is in effect (not the initial 1, 0, 0).
    pub fn attenuated(&self) -> bool {
        self.distance_attenuation != [1.0, 0.0, 0.0]
    }
}

/// The whole GL state that fixedgl keeps, as plain data. `State::new` is the initial state.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Framebuffer size: set at context creation, changed only by `Context::resize` (the
    /// window system's size, not GL state).
    pub width: u32,
    pub height: u32,
    /// The framebuffer's buffers, fixed at context creation.
    pub config: ContextConfig,
    /// The framebuffer drawn into is one Mesa's llvmpipe draws upside down (a window-system
    /// framebuffer: GLX, EGL or OSMesa, Mesa's `Y_0_TOP`), so lines decide their pixel-centre
    /// ties as the driver does there; false for a framebuffer object (`Y_0_BOTTOM`, what
    /// `GlBackend::new` draws into). Not GL state: `Context::set_window_system_framebuffer`
    /// sets it for the window, and binding a framebuffer object clears it while bound.
    pub y0_top: bool,

    // Current values (table 6.5).
    pub current: Current,

    // Transformation (tables 6.7, 6.8).
    pub matrix_mode: u32,
    pub modelview: MatrixStack,
    pub projection: MatrixStack,
    pub texture_matrix: [MatrixStack; MAX_TEXTURE_UNITS],
    /// `ACTIVE_TEXTURE - TEXTURE0`: selects which texture matrix stack MatrixMode(TEXTURE) edits.
    pub active_texture: usize,
    pub client_active_texture: usize,
    /// x, y, width, height.
    pub viewport: [i32; 4],
    /// near, far, clamped to [0, 1].
    pub depth_range: [f64; 2],
    /// Eye-coordinate plane equations.
    pub clip_planes: [DVec4; MAX_CLIP_PLANES],

    pub enables: Enables,

    // Coloring and lighting (tables 6.9, 6.10).
    pub shade_model: u32,
    pub lights: [Light; MAX_LIGHTS],
    pub light_model: LightModel,
    /// `[FRONT]`, `[BACK]`.
    pub materials: [Material; 2],
    pub color_material_face: u32,
    pub color_material_mode: u32,

    // Rasterisation (tables 6.11, 6.12, 6.13).
    pub point_size: f32,
    /// Point parameters and COORD_REPLACE (table 6.11).
    pub point: PointParams,
    pub line_width: f32,
    pub front_face: u32,
    pub cull_face_mode: u32,
    /// `[FRONT]`, `[BACK]`: FILL, LINE or POINT.
    pub polygon_mode: [u32; 2],
    pub polygon_offset_factor: f32,
    pub polygon_offset_units: f32,

    // Pixel operations (tables 6.20, 6.21).
    /// x, y, width, height.
    pub scissor: [i32; 4],
    pub depth_func: u32,

    // Framebuffer control (table 6.22).
    pub color_mask: [bool; 4],
    pub depth_mask: bool,
    pub stencil_writemask: u32,
    pub clear_color: Vec4,
    /// `INDEX_CLEAR_VALUE`: what `ClearIndex` stored, truncated to an unsigned integer as Mesa
    /// does (`(GLuint) c`); an RGBA framebuffer never uses it.
    pub clear_index: u32,
    /// `INDEX_WRITEMASK`: all ones at first; an RGBA framebuffer never uses it.
    pub index_writemask: u32,
    pub clear_depth: f64,
    pub clear_stencil: i32,
    /// `DRAW_BUFFER` (table 6.22) as given to DrawBuffer: FRONT when single-buffered, BACK when
    /// double-buffered at first.
    pub draw_buffer: u32,
    /// `READ_BUFFER` (table 6.26), in PIXEL_MODE_BIT: initially as DRAW_BUFFER.
    pub read_buffer: u32,
    /// `ACCUM_CLEAR_VALUE` (table 6.22), clamped to [-1, 1] when specified.
    pub accum_clear: Vec4,
    /// `RENDER_MODE` (table 6.31): RENDER, SELECT or FEEDBACK (GL 2.1 §5.2, §5.3).
    pub render_mode: u32,

    // Pixel store (tables 6.17, 6.18; GL 2.1 §3.6.1): every client pixel read (TexImage2D,
    // TexSubImage2D) goes through `unpack`, every write (ReadPixels, GetTexImage) through `pack`.
    pub unpack: crate::pixel_store::PixelModes,
    pub pack: crate::pixel_store::PixelModes,

    pub hints: Hints,

    // Display lists (table 6.36)
    /// LIST_BASE.
    pub list_base: u32,
    pub arrays: crate::arrays::ArrayState,
    // Their own structs, one line each for PushAttrib
    pub fog: Fog,
    pub alpha: AlphaTest,
    /// `SAMPLE_COVERAGE_VALUE` (table 6.15, multisample group), clamped to [0, 1] when
    /// specified.
    pub sample_coverage_value: f32,
    /// `SAMPLE_COVERAGE_INVERT` (table 6.15, multisample group).
    pub sample_coverage_invert: bool,
    pub stencil: Stencil,
    pub blend: Blend,
    /// `LOGIC_OP_MODE` (table 6.21).
    pub logic_op: u32,
    // Objects and units (tables 6.15, 6.16, 6.19)
    pub textures: crate::texture::Textures,

    // Evaluators (table 6.33): the maps (no attribute group) and the grids (EVAL_BIT).
    pub eval_maps: EvalMaps,
    pub eval_grid: EvalGrid,
    // Raster position (§2.13, table 6.5), pixel transfer and zoom (§3.6.3, §3.6.5, table 6.23),
    // pixel maps (table 6.24)
    /// The current raster position and its associated data.
    pub raster_pos: RasterPos,
    /// PixelTransfer's parameters and PixelZoom's factors (attribute "pixel").
    pub pixel: crate::pixels::PixelTransfer,
    /// The ten pixel maps (in no attribute group), shared copy-on-write.
    pub pixel_maps: crate::pixels::SharedMaps,
    /// Line and polygon stipple (tables 6.12, 6.13; context/stipple.rs).
    pub stipple: Stipple,
}

impl State {
    /// COLOR_WRITEMASK as the colour buffers take it: without alpha bits the alpha channel is
    /// never written, so the stored alpha stays 1 (255), which is what the destination alpha
    /// reads as in a framebuffer without alpha (GL 2.1 §4.1.8, §4.3.2).
    pub(crate) fn color_write_mask(&self) -> [bool; 4] {
        let [r, g, b, a] = self.color_mask;
        [r, g, b, a && self.config.alpha]
    }

    /// The initial state of a context whose framebuffer is `width` x `height`, of the default
    /// [`ContextConfig`] (single-buffered, depth and stencil, no accumulation buffer).
    pub fn new(width: u32, height: u32) -> Self {
        Self::with_config(width, height, ContextConfig::default())
    }

    /// The initial state of a context whose framebuffer is `width` x `height` with the buffers
    /// `config` names.
    pub fn with_config(width: u32, height: u32, config: ContextConfig) -> Self {
        let (w, h) = (width as i32, height as i32);
        // Tables 6.22 and 6.26: BACK if there is a back buffer, FRONT otherwise.
        let buffer = if config.double_buffered {
            gl::BACK
        } else {
            gl::FRONT
        };
        Self {
            width,
            height,
            config,
            y0_top: false,
            current: Current::default(),
            matrix_mode: gl::MODELVIEW,
            modelview: MatrixStack::new(MAX_MODELVIEW_STACK_DEPTH),
            projection: MatrixStack::new(MAX_PROJECTION_STACK_DEPTH),
            texture_matrix: std::array::from_fn(|_| MatrixStack::new(MAX_TEXTURE_STACK_DEPTH)),
            active_texture: 0,
            client_active_texture: 0,
            viewport: [0, 0, w, h],
            depth_range: [0.0, 1.0],
            clip_planes: [DVec4::ZERO; MAX_CLIP_PLANES],
            enables: Enables::default(),
            shade_model: gl::SMOOTH,
            lights: std::array::from_fn(Light::initial),
            light_model: LightModel {
                ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
                local_viewer: false,
                two_side: false,
                color_control: gl::SINGLE_COLOR,
            },
            materials: [Material::default(); 2],
            color_material_face: gl::FRONT_AND_BACK,
            color_material_mode: gl::AMBIENT_AND_DIFFUSE,
            point_size: 1.0,
            point: PointParams::default(),
            line_width: 1.0,
            front_face: gl::CCW,
            cull_face_mode: gl::BACK,
            polygon_mode: [gl::FILL, gl::FILL],
            polygon_offset_factor: 0.0,
            polygon_offset_units: 0.0,
            scissor: [0, 0, w, h],
            depth_func: gl::LESS,
            color_mask: [true; 4],
            depth_mask: true,
            // fragment ops: "1's" for the 8-bit stencil buffer, 0xFF as the driver reports it.
            stencil_writemask: 0xFF,
            clear_color: Vec4::ZERO,
            clear_index: 0,
            index_writemask: u32::MAX,
            clear_depth: 1.0,
            clear_stencil: 0,
            draw_buffer: buffer,
            read_buffer: buffer,
            accum_clear: Vec4::ZERO,
            render_mode: gl::RENDER,
            unpack: crate::pixel_store::PixelModes::default(),
            pack: crate::pixel_store::PixelModes::default(),
            hints: Hints::default(),
            list_base: 0,
            arrays: crate::arrays::ArrayState::default(),
            fog: Fog::default(),
            alpha: AlphaTest::default(),
            sample_coverage_value: 1.0,
            sample_coverage_invert: false,
            stencil: Stencil::default(),
            blend: Blend::default(),
            logic_op: gl::COPY,
            textures: crate::texture::Textures::default(),
            eval_maps: EvalMaps::default(),
            eval_grid: EvalGrid::default(),
            raster_pos: RasterPos::default(),
            pixel: crate::pixels::PixelTransfer::default(),
            pixel_maps: Default::default(),
            stipple: Stipple::default(),
        }
    }

    /// The matrix stack `MatrixMode` currently selects.
    pub fn current_stack(&self) -> &MatrixStack {
        match self.matrix_mode {
            gl::PROJECTION => &self.projection,
            gl::TEXTURE => &self.texture_matrix[self.active_texture],
            _ => &self.modelview,
        }
    }

    /// The matrix stack `MatrixMode` currently selects, to modify.
    pub fn current_stack_mut(&mut self) -> &mut MatrixStack {
        match self.matrix_mode {
            gl::PROJECTION => &mut self.projection,
            gl::TEXTURE => &mut self.texture_matrix[self.active_texture],
            _ => &mut self.modelview,
        }
    }
}

/// Fog parameters (GL 2.1 §3.10, table 6.8).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// `FOG_MODE`: LINEAR, EXP or EXP2.
    pub mode: u32,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    /// `FOG_COLOR`, clamped to [0, 1] when specified.
    pub color: Vec4,
    /// `FOG_INDEX` (colour-index mode only; kept for queries).
    pub index: f32,
    /// `FOG_COORD_SRC`: FRAGMENT_DEPTH or FOG_COORD.
    pub coord_src: u32,
}

impl Default for Fog {
    fn default() -> Self {
        Self {
            mode: gl::EXP,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            color: Vec4::ZERO,
            index: 0.0,
            coord_src: gl::FRAGMENT_DEPTH,
        }
    }
}

/// The alpha test (GL 2.1 §4.1.4, table 6.20).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaTest {
    /// `ALPHA_TEST_FUNC`.
    pub func: u32,
    /// `ALPHA_TEST_REF`, clamped to [0, 1] when specified.
    pub reference: f32,
}

impl Default for AlphaTest {
    fn default() -> Self {
        Self {
            func: gl::ALWAYS,
            reference: 0.0,
        }
    }
}

/// One face's stencil function and operations (GL 2.1 §4.1.5, table 6.20).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilFace {
    /// `STENCIL_FUNC`.
    pub func: u32,
    /// `STENCIL_REF` as given (clamped to [0, 2^8 - 1] where it is used and queried).
    pub reference: i32,
    /// `STENCIL_VALUE_MASK`: initially "1's" (table 6.20), the 8 bits of the stencil buffer.
    pub value_mask: u32,
    /// `STENCIL_FAIL`.
    pub fail: u32,
    /// `STENCIL_PASS_DEPTH_FAIL`.
    pub zfail: u32,
    /// `STENCIL_PASS_DEPTH_PASS`.
    pub zpass: u32,
}

impl Default for StencilFace {
    fn default() -> Self {
        Self {
            func: gl::ALWAYS,
            reference: 0,
            value_mask: 0xFF,
            fail: gl::KEEP,
            zfail: gl::KEEP,
            zpass: gl::KEEP,
        }
    }
}

/// Stencil test state (GL 2.1 §4.1.5); the front write mask is `State::stencil_writemask`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stencil {
    /// `[FRONT]`, `[BACK]` (STENCIL_* and STENCIL_BACK_*).
    pub faces: [StencilFace; 2],
    /// `STENCIL_BACK_WRITEMASK`.
    pub back_writemask: u32,
}

impl Default for Stencil {
    fn default() -> Self {
        Self {
            faces: [StencilFace::default(); 2],
            back_writemask: 0xFF,
        }
    }
}

/// Blending (GL 2.1 §4.1.8, table 6.21).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blend {
    pub src_rgb: u32,
    pub dst_rgb: u32,
    pub src_alpha: u32,
    pub dst_alpha: u32,
    /// `BLEND_EQUATION_RGB` (= `BLEND_EQUATION`).
    pub equation_rgb: u32,
    pub equation_alpha: u32,
    /// `BLEND_COLOR`, clamped to [0, 1] when specified.
    pub color: Vec4,
}

impl Default for Blend {
    fn default() -> Self {
        Self {
            src_rgb: gl::ONE,
            dst_rgb: gl::ZERO,
            src_alpha: gl::ONE,
            dst_alpha: gl::ZERO,
            equation_rgb: gl::FUNC_ADD,
            equation_alpha: gl::FUNC_ADD,
            color: Vec4::ZERO,
        }
    }
}

/// `MAX_EVAL_ORDER` (GL 2.1 table 6.35): Mesa's 30.
pub const MAX_EVAL_ORDER: i32 = 30;

/// One evaluator map (GL 2.1 §5.1): its orders, domain and control points, as Mesa keeps them —
/// floats (Map*d converts), packed `k` components per point, point `(i, j)` (i along u) at
/// `(i * vorder + j) * k`. A one-dimensional map has `vorder` 1 and domain `v` 0 to 1.
#[derive(Clone, Debug, PartialEq)]
pub struct EvalMap {
    pub uorder: i32,
    pub vorder: i32,
    /// u1, u2, v1, v2.
    pub domain: [f32; 4],
    pub points: Vec<f32>,
}

/// The 18 maps, MAP1_* then MAP2_*, each in the order of the enums: COLOR_4, INDEX, NORMAL,
/// TEXTURE_COORD_1 to _4, VERTEX_3, VERTEX_4 (`target - MAP1_COLOR_4`, `target - MAP2_COLOR_4`).
#[derive(Clone, Debug, PartialEq)]
pub struct EvalMaps {
    pub map1: [EvalMap; 9],
    pub map2: [EvalMap; 9],
}

/// The components of each map's points, in [`EvalMaps`] order.
pub const EVAL_COMPONENTS: [usize; 9] = [4, 1, 3, 1, 2, 3, 4, 3, 4];

impl Default for EvalMaps {
    /// Table 6.33: order 1, domain 0 to 1, the point (1,1,1,1) for colour, 1 for the index,
    /// (0,0,1) for the normal, (0,0,0,1) cut to the size for texture coordinates and vertices.
    fn default() -> Self {
        const INITIAL: [&[f32]; 9] = [
            &[1.0, 1.0, 1.0, 1.0],
            &[1.0],
            &[0.0, 0.0, 1.0],
            &[0.0],
            &[0.0, 0.0],
            &[0.0, 0.0, 0.0],
            &[0.0, 0.0, 0.0, 1.0],
            &[0.0, 0.0, 0.0],
            &[0.0, 0.0, 0.0, 1.0],
        ];
        let map = |i: usize| EvalMap {
            uorder: 1,
            vorder: 1,
            domain: [0.0, 1.0, 0.0, 1.0],
            points: INITIAL[i].to_vec(),
        };
        EvalMaps {
            map1: std::array::from_fn(map),
            map2: std::array::from_fn(map),
        }
    }
}

/// The evaluator grids (MapGrid1, MapGrid2; table 6.33, EVAL_BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EvalGrid {
    /// MAP1_GRID_SEGMENTS.
    pub un1: i32,
    /// MAP1_GRID_DOMAIN.
    pub u1: [f32; 2],
    /// MAP2_GRID_SEGMENTS.
    pub n2: [i32; 2],
    /// MAP2_GRID_DOMAIN: u1, u2, v1, v2.
    pub d2: [f32; 4],
}

impl Default for EvalGrid {
    fn default() -> Self {
        EvalGrid {
            un1: 1,
            u1: [0.0, 1.0],
            n2: [1, 1],
            d2: [0.0, 1.0, 0.0, 1.0],
        }
    }
}

/// The current raster position (GL 2.1 §2.13, table 6.5, attribute "current"): what RasterPos and
/// WindowPos set, and what Bitmap, DrawPixels and CopyPixels read (and feedback reports).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterPos {
    /// CURRENT_RASTER_POSITION_VALID: RasterPos of a point outside the clip volume (frustum and
    /// enabled user clip planes) makes it invalid; WindowPos always valid.
    pub valid: bool,
    /// CURRENT_RASTER_POSITION: window x, y, z (z after DepthRange) and clip w.
    pub window: Vec4,
    /// CURRENT_RASTER_COLOR: the colour lighting gives the point (or the current colour).
    pub color: Vec4,
    /// CURRENT_RASTER_SECONDARY_COLOR.
    pub secondary_color: Vec4,
    /// CURRENT_RASTER_INDEX (colour-index mode only; kept for queries).
    pub index: f32,
    /// CURRENT_RASTER_TEXTURE_COORDS of each unit (after TexGen and the texture matrix).
    pub tex_coords: [Vec4; MAX_TEXTURE_UNITS],
    /// CURRENT_RASTER_DISTANCE: the eye distance, or the fog coordinate under FOG_COORD_SRC
    /// FOG_COORD.
    pub distance: f32,
}

impl Default for RasterPos {
    /// Table 6.5's initial values: (0, 0, 0, 1), valid, white, secondary (0, 0, 0, 1), index
    /// 1, texture coordinates (0, 0, 0, 1), distance 0.
    fn default() -> Self {
        Self {
            valid: true,
            window: Vec4::new(0.0, 0.0, 0.0, 1.0),
            color: Vec4::ONE,
            secondary_color: Vec4::new(0.0, 0.0, 0.0, 1.0),
            index: 1.0,
            tex_coords: [Vec4::new(0.0, 0.0, 0.0, 1.0); MAX_TEXTURE_UNITS],
            distance: 0.0,
        }
    }
}

/// Line stipple (GL 2.1 §3.4.2, table 6.12) and polygon stipple (§3.5.6, table 6.13).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stipple {
    /// `LINE_STIPPLE_PATTERN`: bit i (from the least significant) is the i-th pixel of 16.
    pub line_pattern: u16,
    /// `LINE_STIPPLE_REPEAT`: the factor, clamped to [1, 256] when specified.
    pub line_repeat: i32,
    /// `POLYGON_STIPPLE`: row r is window rows y with y mod 32 = r; bit x (from the least
    /// significant) is window columns with x mod 32 = x.
    pub polygon: [u32; 32],
}

impl Default for Stipple {
    /// Tables 6.12, 6.13: pattern all ones, repeat 1, polygon stipple all ones.
    fn default() -> Self {
        Self {
            line_pattern: 0xFFFF,
            line_repeat: 1,
            polygon: [u32::MAX; 32],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two values of the inputs written apart (so with different stamps) are equal and print
    /// alike, NaNs included: the stamp is not part of the value.
    #[test]
    fn the_stamp_is_not_part_of_the_value() {
        let (mut a, mut b) = (Current::default(), Current::default());
        a.inputs_mut().color = Vec4::new(f32::NAN, 0.5, 0.25, 1.0);
        b.inputs_mut().color = Vec4::new(f32::NAN, 0.5, 0.25, 1.0);
        assert_ne!(a.stamp, b.stamp);
        assert_eq!(format!("{a:?}"), format!("{b:?}"));
        a.inputs_mut().fog_coord = 1.0;
        b.inputs_mut().fog_coord = 1.0;
        a.normal = Vec3::X;
        b.normal = Vec3::X;
        a.inputs_mut().color = Vec4::ONE;
        b.inputs_mut().color = Vec4::ONE;
        assert_eq!(a, b);
        b.inputs_mut().edge_flag = false;
        assert_ne!(a, b);
        assert_ne!(format!("{a:?}"), format!("{b:?}"));
    }
}
