//! Shared by the integration tests: a proptest strategy for arbitrary `Call`s of the front end's
//! set-side entry points, with argument values biased towards the interesting ones (every enum
//! the entry points accept, range limits, NaN, infinities, extremes).
//!
//! `call_from` was generated from `src/call.rs` (one arm per variant, in declaration order); a
//! variant added to `Call` needs an arm here to be fuzzed.
#![allow(dead_code)]

use fixedgl::{gl, Call};
use proptest::prelude::*;

/// Number of `Call` variants `call_from` can build.
pub const VARIANTS: usize = TEXTURE_BASE + TEXTURE_VARIANTS;

// --- arrays
/// The first of the arrays area's variant numbers (tests that fuzz only array calls use it).
pub const ARRAY_BASE: usize = 168;
/// The arrays area's variants, numbered from `ARRAY_BASE`.
pub const ARRAY_VARIANTS: usize = 19;
// --- end arrays
// --- fragment ops
/// The first of the fragment-ops area's variant numbers.
pub const FRAGMENT_BASE: usize = ARRAY_BASE + ARRAY_VARIANTS;
/// The fragment-ops area's variants, numbered from `FRAGMENT_BASE`.
pub const FRAGMENT_VARIANTS: usize = 17;
// --- end fragment ops
// --- texture
/// The first of the texture area's variant numbers (see `texture_call`).
pub const TEXTURE_BASE: usize = FRAGMENT_BASE + FRAGMENT_VARIANTS;
/// Number of texture variants `texture_call` builds.
pub const TEXTURE_VARIANTS: usize = 53;
// --- end texture

/// Argument values for one call; each variant takes what it needs in order.
#[derive(Clone, Debug)]
pub struct Pool {
    pub e: [u32; 4],
    pub f: [f32; 4],
    pub d: [f64; 4],
    pub i: [i32; 4],
    pub b: [bool; 4],
    pub vf: Vec<f32>,
    pub vi: Vec<i32>,
}

/// Enums worth drawing often: every value the set-side entry points accept, and near misses.
pub const ENUMS: &[u32] = &[
    gl::POINTS,
    gl::LINES,
    gl::TRIANGLES,
    gl::TRIANGLE_STRIP,
    gl::QUADS,
    gl::POLYGON,
    10,
    gl::LIGHT0,
    gl::LIGHT1,
    gl::LIGHT7,
    gl::LIGHT7 + 1,
    gl::LIGHT0 - 1,
    gl::FRONT,
    gl::BACK,
    gl::FRONT_AND_BACK,
    gl::LEFT,
    gl::AMBIENT,
    gl::DIFFUSE,
    gl::SPECULAR,
    gl::POSITION,
    gl::SPOT_DIRECTION,
    gl::SPOT_EXPONENT,
    gl::SPOT_CUTOFF,
    gl::CONSTANT_ATTENUATION,
    gl::LINEAR_ATTENUATION,
    gl::QUADRATIC_ATTENUATION,
    gl::EMISSION,
    gl::SHININESS,
    gl::AMBIENT_AND_DIFFUSE,
    gl::COLOR_INDEXES,
    gl::LIGHT_MODEL_AMBIENT,
    gl::LIGHT_MODEL_LOCAL_VIEWER,
    gl::LIGHT_MODEL_TWO_SIDE,
    gl::LIGHT_MODEL_COLOR_CONTROL,
    gl::SINGLE_COLOR,
    gl::SEPARATE_SPECULAR_COLOR,
    gl::FLAT,
    gl::SMOOTH,
    gl::PHONG_WIN,
    gl::CW,
    gl::CCW,
    gl::POINT,
    gl::LINE,
    gl::FILL,
    gl::NEVER,
    gl::LESS,
    gl::ALWAYS,
    gl::ALWAYS + 1,
    gl::PERSPECTIVE_CORRECTION_HINT,
    gl::FOG_HINT,
    gl::GENERATE_MIPMAP_HINT,
    gl::PHONG_HINT_WIN,
    gl::FASTEST,
    gl::NICEST,
    gl::DONT_CARE,
    gl::PACK_ALIGNMENT,
    gl::UNPACK_ALIGNMENT,
    gl::PACK_ROW_LENGTH,
    gl::COLOR_BUFFER_BIT,
    gl::DEPTH_BUFFER_BIT,
    gl::STENCIL_BUFFER_BIT,
    gl::ACCUM_BUFFER_BIT,
    gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT,
    gl::COLOR_MATERIAL,
    gl::LIGHTING,
    gl::DEPTH_TEST,
    gl::CULL_FACE,
    gl::NORMALIZE,
    gl::SCISSOR_TEST,
    // --- lists: NewList modes, CallLists types, attribute masks
    gl::COMPILE,
    gl::COMPILE_AND_EXECUTE,
    gl::UNSIGNED_BYTE,
    gl::GL_2_BYTES,
    gl::FLOAT,
    gl::LIGHTING_BIT | gl::ENABLE_BIT,
    gl::ALL_ATTRIB_BITS,
    // --- end lists
    // --- fragment ops
    gl::FOG_MODE,
    gl::FOG_DENSITY,
    gl::FOG_COLOR,
    gl::FOG_COORD_SRC,
    gl::FOG_COORD,
    gl::FRAGMENT_DEPTH,
    gl::LINEAR,
    gl::EXP,
    gl::EXP2,
    gl::KEEP,
    gl::INCR_WRAP,
    gl::DECR_WRAP,
    gl::INVERT,
    gl::SRC_ALPHA,
    gl::ONE_MINUS_SRC_ALPHA,
    gl::SRC_ALPHA_SATURATE,
    gl::CONSTANT_COLOR,
    gl::FUNC_ADD,
    gl::FUNC_REVERSE_SUBTRACT,
    gl::MIN,
    gl::MAX,
    gl::CLEAR,
    gl::SET,
    gl::SET + 1,
    // --- end fragment ops
    0,
    1,
    u32::MAX,
    // --- arrays
    gl::VERTEX_ARRAY,
    gl::COLOR_ARRAY,
    gl::NORMAL_ARRAY,
    gl::TEXTURE_COORD_ARRAY,
    gl::EDGE_FLAG_ARRAY,
    gl::BYTE,
    gl::UNSIGNED_BYTE,
    gl::SHORT,
    gl::UNSIGNED_SHORT,
    gl::UNSIGNED_INT,
    gl::FLOAT,
    gl::DOUBLE,
    gl::V3F,
    gl::C4UB_V3F,
    gl::T4F_C4F_N3F_V4F,
    gl::ARRAY_BUFFER,
    gl::ELEMENT_ARRAY_BUFFER,
    gl::STATIC_DRAW,
    gl::STREAM_COPY,
    // --- end arrays
];

/// Floats worth drawing often: range limits of the lighting parameters, and the non-finite.
pub const FLOATS: &[f32] = &[
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    4.0,
    8.0,
    90.0,
    90.5,
    128.0,
    128.5,
    180.0,
    -0.001,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    1e-45,
    6913.0,
    16385.0,
];

/// Integers worth drawing often.
pub const INTS: &[i32] = &[
    0,
    1,
    2,
    3,
    4,
    8,
    -1,
    90,
    128,
    129,
    180,
    255,
    -128,
    32767,
    i32::MAX,
    i32::MIN,
];

pub fn any_u32() -> impl Strategy<Value = u32> {
    prop_oneof![4 => prop::sample::select(ENUMS), 1 => any::<u32>()]
}

pub fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![2 => prop::sample::select(FLOATS), 2 => -200.0f32..200.0, 1 => any::<f32>()]
}

pub fn any_f64() -> impl Strategy<Value = f64> {
    any_f32().prop_map(f64::from)
}

pub fn any_i32() -> impl Strategy<Value = i32> {
    prop_oneof![2 => prop::sample::select(INTS), 1 => any::<i32>()]
}

pub fn pool() -> impl Strategy<Value = Pool> {
    (
        prop::array::uniform4(any_u32()),
        prop::array::uniform4(any_f32()),
        prop::array::uniform4(any_f64()),
        prop::array::uniform4(any_i32()),
        prop::array::uniform4(any::<bool>()),
        prop::collection::vec(any_f32(), 0..6),
        prop::collection::vec(any_i32(), 0..6),
    )
        .prop_map(|(e, f, d, i, b, vf, vi)| Pool {
            e,
            f,
            d,
            i,
            b,
            vf,
            vi,
        })
}

/// Any call, Begin/End drawn more often so that sequences often sit inside a primitive.
pub fn any_call() -> impl Strategy<Value = Call> {
    prop_oneof![
        1 => Just(Call::Begin(gl::TRIANGLES)),
        1 => Just(Call::End),
        12 => (0..VARIANTS, pool()).prop_map(|(k, p)| call_from(k, &p)),
    ]
}

/// Builds variant number `k` (declaration order) from `p`.
#[rustfmt::skip]
pub fn call_from(k: usize, p: &Pool) -> Call {
    match k {
        0 => Call::Begin(p.e[0]),
        1 => Call::End,
        2 => Call::Enable(p.e[0]),
        3 => Call::Disable(p.e[0]),
        4 => Call::Vertex2s(p.i[0] as i16, p.i[1] as i16),
        5 => Call::Vertex2i(p.i[0], p.i[1]),
        6 => Call::Vertex2f(p.f[0], p.f[1]),
        7 => Call::Vertex2d(p.d[0], p.d[1]),
        8 => Call::Vertex3s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        9 => Call::Vertex3i(p.i[0], p.i[1], p.i[2]),
        10 => Call::Vertex3f(p.f[0], p.f[1], p.f[2]),
        11 => Call::Vertex3d(p.d[0], p.d[1], p.d[2]),
        12 => Call::Vertex4s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16),
        13 => Call::Vertex4i(p.i[0], p.i[1], p.i[2], p.i[3]),
        14 => Call::Vertex4f(p.f[0], p.f[1], p.f[2], p.f[3]),
        15 => Call::Vertex4d(p.d[0], p.d[1], p.d[2], p.d[3]),
        16 => Call::Vertex2sv([p.i[0] as i16, p.i[1] as i16]),
        17 => Call::Vertex2iv([p.i[0], p.i[1]]),
        18 => Call::Vertex2fv([p.f[0], p.f[1]]),
        19 => Call::Vertex2dv([p.d[0], p.d[1]]),
        20 => Call::Vertex3sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        21 => Call::Vertex3iv([p.i[0], p.i[1], p.i[2]]),
        22 => Call::Vertex3fv([p.f[0], p.f[1], p.f[2]]),
        23 => Call::Vertex3dv([p.d[0], p.d[1], p.d[2]]),
        24 => Call::Vertex4sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16]),
        25 => Call::Vertex4iv([p.i[0], p.i[1], p.i[2], p.i[3]]),
        26 => Call::Vertex4fv([p.f[0], p.f[1], p.f[2], p.f[3]]),
        27 => Call::Vertex4dv([p.d[0], p.d[1], p.d[2], p.d[3]]),
        28 => Call::Normal3b(p.i[0] as i8, p.i[1] as i8, p.i[2] as i8),
        29 => Call::Normal3s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        30 => Call::Normal3i(p.i[0], p.i[1], p.i[2]),
        31 => Call::Normal3f(p.f[0], p.f[1], p.f[2]),
        32 => Call::Normal3d(p.d[0], p.d[1], p.d[2]),
        33 => Call::Normal3bv([p.i[0] as i8, p.i[1] as i8, p.i[2] as i8]),
        34 => Call::Normal3sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        35 => Call::Normal3iv([p.i[0], p.i[1], p.i[2]]),
        36 => Call::Normal3fv([p.f[0], p.f[1], p.f[2]]),
        37 => Call::Normal3dv([p.d[0], p.d[1], p.d[2]]),
        38 => Call::Color3b(p.i[0] as i8, p.i[1] as i8, p.i[2] as i8),
        39 => Call::Color3s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        40 => Call::Color3i(p.i[0], p.i[1], p.i[2]),
        41 => Call::Color3f(p.f[0], p.f[1], p.f[2]),
        42 => Call::Color3d(p.d[0], p.d[1], p.d[2]),
        43 => Call::Color3ub(p.i[0] as u8, p.i[1] as u8, p.i[2] as u8),
        44 => Call::Color3us(p.i[0] as u16, p.i[1] as u16, p.i[2] as u16),
        45 => Call::Color3ui(p.e[0], p.e[1], p.e[2]),
        46 => Call::Color3bv([p.i[0] as i8, p.i[1] as i8, p.i[2] as i8]),
        47 => Call::Color3sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        48 => Call::Color3iv([p.i[0], p.i[1], p.i[2]]),
        49 => Call::Color3fv([p.f[0], p.f[1], p.f[2]]),
        50 => Call::Color3dv([p.d[0], p.d[1], p.d[2]]),
        51 => Call::Color3ubv([p.i[0] as u8, p.i[1] as u8, p.i[2] as u8]),
        52 => Call::Color3usv([p.i[0] as u16, p.i[1] as u16, p.i[2] as u16]),
        53 => Call::Color3uiv([p.e[0], p.e[1], p.e[2]]),
        54 => Call::Color4b(p.i[0] as i8, p.i[1] as i8, p.i[2] as i8, p.i[3] as i8),
        55 => Call::Color4s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16),
        56 => Call::Color4i(p.i[0], p.i[1], p.i[2], p.i[3]),
        57 => Call::Color4f(p.f[0], p.f[1], p.f[2], p.f[3]),
        58 => Call::Color4d(p.d[0], p.d[1], p.d[2], p.d[3]),
        59 => Call::Color4ub(p.i[0] as u8, p.i[1] as u8, p.i[2] as u8, p.i[3] as u8),
        60 => Call::Color4us(p.i[0] as u16, p.i[1] as u16, p.i[2] as u16, p.i[3] as u16),
        61 => Call::Color4ui(p.e[0], p.e[1], p.e[2], p.e[3]),
        62 => Call::Color4bv([p.i[0] as i8, p.i[1] as i8, p.i[2] as i8, p.i[3] as i8]),
        63 => Call::Color4sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16]),
        64 => Call::Color4iv([p.i[0], p.i[1], p.i[2], p.i[3]]),
        65 => Call::Color4fv([p.f[0], p.f[1], p.f[2], p.f[3]]),
        66 => Call::Color4dv([p.d[0], p.d[1], p.d[2], p.d[3]]),
        67 => Call::Color4ubv([p.i[0] as u8, p.i[1] as u8, p.i[2] as u8, p.i[3] as u8]),
        68 => Call::Color4usv([p.i[0] as u16, p.i[1] as u16, p.i[2] as u16, p.i[3] as u16]),
        69 => Call::Color4uiv([p.e[0], p.e[1], p.e[2], p.e[3]]),
        70 => Call::SecondaryColor3b(p.i[0] as i8, p.i[1] as i8, p.i[2] as i8),
        71 => Call::SecondaryColor3s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        72 => Call::SecondaryColor3i(p.i[0], p.i[1], p.i[2]),
        73 => Call::SecondaryColor3f(p.f[0], p.f[1], p.f[2]),
        74 => Call::SecondaryColor3d(p.d[0], p.d[1], p.d[2]),
        75 => Call::SecondaryColor3ub(p.i[0] as u8, p.i[1] as u8, p.i[2] as u8),
        76 => Call::SecondaryColor3us(p.i[0] as u16, p.i[1] as u16, p.i[2] as u16),
        77 => Call::SecondaryColor3ui(p.e[0], p.e[1], p.e[2]),
        78 => Call::SecondaryColor3bv([p.i[0] as i8, p.i[1] as i8, p.i[2] as i8]),
        79 => Call::SecondaryColor3sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        80 => Call::SecondaryColor3iv([p.i[0], p.i[1], p.i[2]]),
        81 => Call::SecondaryColor3fv([p.f[0], p.f[1], p.f[2]]),
        82 => Call::SecondaryColor3dv([p.d[0], p.d[1], p.d[2]]),
        83 => Call::SecondaryColor3ubv([p.i[0] as u8, p.i[1] as u8, p.i[2] as u8]),
        84 => Call::SecondaryColor3usv([p.i[0] as u16, p.i[1] as u16, p.i[2] as u16]),
        85 => Call::SecondaryColor3uiv([p.e[0], p.e[1], p.e[2]]),
        86 => Call::TexCoord1s(p.i[0] as i16),
        87 => Call::TexCoord1i(p.i[0]),
        88 => Call::TexCoord1f(p.f[0]),
        89 => Call::TexCoord1d(p.d[0]),
        90 => Call::TexCoord2s(p.i[0] as i16, p.i[1] as i16),
        91 => Call::TexCoord2i(p.i[0], p.i[1]),
        92 => Call::TexCoord2f(p.f[0], p.f[1]),
        93 => Call::TexCoord2d(p.d[0], p.d[1]),
        94 => Call::TexCoord3s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        95 => Call::TexCoord3i(p.i[0], p.i[1], p.i[2]),
        96 => Call::TexCoord3f(p.f[0], p.f[1], p.f[2]),
        97 => Call::TexCoord3d(p.d[0], p.d[1], p.d[2]),
        98 => Call::TexCoord4s(p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16),
        99 => Call::TexCoord4i(p.i[0], p.i[1], p.i[2], p.i[3]),
        100 => Call::TexCoord4f(p.f[0], p.f[1], p.f[2], p.f[3]),
        101 => Call::TexCoord4d(p.d[0], p.d[1], p.d[2], p.d[3]),
        102 => Call::TexCoord1sv([p.i[0] as i16]),
        103 => Call::TexCoord1iv([p.i[0]]),
        104 => Call::TexCoord1fv([p.f[0]]),
        105 => Call::TexCoord1dv([p.d[0]]),
        106 => Call::TexCoord2sv([p.i[0] as i16, p.i[1] as i16]),
        107 => Call::TexCoord2iv([p.i[0], p.i[1]]),
        108 => Call::TexCoord2fv([p.f[0], p.f[1]]),
        109 => Call::TexCoord2dv([p.d[0], p.d[1]]),
        110 => Call::TexCoord3sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        111 => Call::TexCoord3iv([p.i[0], p.i[1], p.i[2]]),
        112 => Call::TexCoord3fv([p.f[0], p.f[1], p.f[2]]),
        113 => Call::TexCoord3dv([p.d[0], p.d[1], p.d[2]]),
        114 => Call::TexCoord4sv([p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16]),
        115 => Call::TexCoord4iv([p.i[0], p.i[1], p.i[2], p.i[3]]),
        116 => Call::TexCoord4fv([p.f[0], p.f[1], p.f[2], p.f[3]]),
        117 => Call::TexCoord4dv([p.d[0], p.d[1], p.d[2], p.d[3]]),
        118 => Call::FogCoordf(p.f[0]),
        119 => Call::FogCoordd(p.d[0]),
        120 => Call::FogCoordfv([p.f[0]]),
        121 => Call::FogCoorddv([p.d[0]]),
        122 => Call::EdgeFlag(p.b[0]),
        123 => Call::EdgeFlagv([p.b[0]]),
        124 => Call::Materialf(p.e[0], p.e[1], p.f[2]),
        125 => Call::Materiali(p.e[0], p.e[1], p.i[2]),
        126 => Call::Materialfv(p.e[0], p.e[1], p.vf.clone()),
        127 => Call::Materialiv(p.e[0], p.e[1], p.vi.clone()),
        128 => Call::Lightf(p.e[0], p.e[1], p.f[2]),
        129 => Call::Lighti(p.e[0], p.e[1], p.i[2]),
        130 => Call::Lightfv(p.e[0], p.e[1], p.vf.clone()),
        131 => Call::Lightiv(p.e[0], p.e[1], p.vi.clone()),
        132 => Call::LightModelf(p.e[0], p.f[1]),
        133 => Call::LightModeli(p.e[0], p.i[1]),
        134 => Call::LightModelfv(p.e[0], p.vf.clone()),
        135 => Call::LightModeliv(p.e[0], p.vi.clone()),
        136 => Call::ColorMaterial(p.e[0], p.e[1]),
        137 => Call::ShadeModel(p.e[0]),
        138 => Call::FrontFace(p.e[0]),
        139 => Call::CullFace(p.e[0]),
        140 => Call::PolygonMode(p.e[0], p.e[1]),
        141 => Call::PolygonOffset(p.f[0], p.f[1]),
        142 => Call::PointSize(p.f[0]),
        143 => Call::LineWidth(p.f[0]),
        144 => Call::ClearColor(p.f[0], p.f[1], p.f[2], p.f[3]),
        145 => Call::ClearDepth(p.d[0]),
        146 => Call::ClearStencil(p.i[0]),
        147 => Call::Clear(p.e[0]),
        148 => Call::DepthFunc(p.e[0]),
        149 => Call::DepthMask(p.b[0]),
        150 => Call::ColorMask(p.b[0], p.b[1], p.b[2], p.b[3]),
        151 => Call::Scissor(p.i[0], p.i[1], p.i[2], p.i[3]),
        152 => Call::Hint(p.e[0], p.e[1]),
        153 => Call::PixelStorei(p.e[0], p.i[1]),
        154 => Call::PixelStoref(p.e[0], p.f[1]),
        155 => Call::Flush,
        156 => Call::Finish,
        // --- lists: list names 1..=4, so that lists are defined and called often
        157 => Call::GenLists(p.i[0]),
        158 => Call::NewList(1 + (p.e[0] & 3), p.e[1]),
        159 => Call::EndList,
        160 => Call::CallList(1 + (p.e[0] & 3)),
        161 => Call::CallLists(p.i[0] % 6, p.e[1], p.vi.iter().map(|&v| (v & 3) as u8).collect()),
        162 => Call::ListBase(p.e[0] & 1),
        163 => Call::DeleteLists(p.e[0] & 3, p.i[1]),
        164 => Call::PushAttrib(p.e[0]),
        165 => Call::PopAttrib,
        166 => Call::PushClientAttrib(p.e[0]),
        167 => Call::PopClientAttrib,
        // --- end lists
        // --- arrays
        k @ ARRAY_BASE.. if k < ARRAY_BASE + ARRAY_VARIANTS => array_call(k - ARRAY_BASE, p),
        // --- end arrays
        // --- fragment ops
        k @ FRAGMENT_BASE.. if k < FRAGMENT_BASE + FRAGMENT_VARIANTS => {
            fragment_call(k - FRAGMENT_BASE, p)
        }
        // --- end fragment ops
        // --- texture
        k @ TEXTURE_BASE.. if k < TEXTURE_BASE + TEXTURE_VARIANTS => {
            texture_call(k - TEXTURE_BASE, p)
        }
        // --- end texture
        _ => Call::End,
    }
}

// --- arrays
/// A pointer argument: the pool's floats as bytes, or an offset (possibly huge).
fn pointer(p: &Pool) -> fixedgl::Pointer {
    if p.b[3] {
        fixedgl::Pointer::Data(p.vf.iter().flat_map(|x| x.to_ne_bytes()).collect())
    } else {
        fixedgl::Pointer::Offset(p.i[3] as u32 as usize)
    }
}

/// The arrays area's variant number `k` (declaration order) from `p`; small counts and sizes
/// drawn often so that draws succeed as well as fail.
#[rustfmt::skip]
fn array_call(k: usize, p: &Pool) -> Call {
    let small = |x: i32| if p.b[2] { x.rem_euclid(5) } else { x };
    match k {
        0 => Call::EnableClientState(p.e[0]),
        1 => Call::DisableClientState(p.e[0]),
        2 => Call::VertexPointer(small(p.i[0]), p.e[1], small(p.i[2]), pointer(p)),
        3 => Call::NormalPointer(p.e[0], small(p.i[1]), pointer(p)),
        4 => Call::ColorPointer(small(p.i[0]), p.e[1], small(p.i[2]), pointer(p)),
        5 => Call::SecondaryColorPointer(small(p.i[0]), p.e[1], small(p.i[2]), pointer(p)),
        6 => Call::TexCoordPointer(small(p.i[0]), p.e[1], small(p.i[2]), pointer(p)),
        7 => Call::FogCoordPointer(p.e[0], small(p.i[1]), pointer(p)),
        8 => Call::EdgeFlagPointer(small(p.i[0]), pointer(p)),
        9 => Call::InterleavedArrays(p.e[0], small(p.i[1]), pointer(p)),
        10 => Call::ArrayElement(small(p.i[0])),
        11 => Call::DrawArrays(p.e[0], small(p.i[1]), small(p.i[2])),
        12 => Call::DrawElements(p.e[0], small(p.i[1]), p.e[2], pointer(p)),
        13 => Call::DrawRangeElements(p.e[0], p.e[1], p.e[2], small(p.i[0]), p.e[3], Box::new(pointer(p))),
        14 => Call::GenBuffers(small(p.i[0]), p.vi.iter().map(|&x| x as u32).collect()),
        15 => Call::DeleteBuffers(small(p.i[0]), p.vi.iter().map(|&x| x.rem_euclid(4) as u32).collect()),
        16 => Call::BindBuffer(p.e[0], small(p.i[1]) as u32),
        17 => Call::BufferData(p.e[0], small(p.i[1]) as isize, Box::new(pointer(p)), p.e[2]),
        _ => Call::BufferSubData(p.e[0], small(p.i[1]) as isize, small(p.i[2]) as isize, Box::new(pointer(p))),
    }
}
// --- end arrays

// --- fragment ops
/// The fragment-ops area's variant `k` (0-based).
fn fragment_call(k: usize, p: &Pool) -> Call {
    match k {
        0 => Call::Fogf(p.e[0], p.f[1]),
        1 => Call::Fogi(p.e[0], p.i[1]),
        2 => Call::Fogfv(p.e[0], p.vf.clone()),
        3 => Call::Fogiv(p.e[0], p.vi.clone()),
        4 => Call::AlphaFunc(p.e[0], p.f[1]),
        5 => Call::StencilFunc(p.e[0], p.i[1], p.e[2]),
        6 => Call::StencilFuncSeparate(p.e[0], p.e[1], p.i[2], p.e[3]),
        7 => Call::StencilOp(p.e[0], p.e[1], p.e[2]),
        8 => Call::StencilOpSeparate(p.e[0], p.e[1], p.e[2], p.e[3]),
        9 => Call::StencilMask(p.e[0]),
        10 => Call::StencilMaskSeparate(p.e[0], p.e[1]),
        11 => Call::BlendFunc(p.e[0], p.e[1]),
        12 => Call::BlendFuncSeparate(p.e[0], p.e[1], p.e[2], p.e[3]),
        13 => Call::BlendEquation(p.e[0]),
        14 => Call::BlendEquationSeparate(p.e[0], p.e[1]),
        15 => Call::BlendColor(p.f[0], p.f[1], p.f[2], p.f[3]),
        _ => Call::LogicOp(p.e[0]),
    }
}
// --- end fragment ops
// --- texture: texture calls, targets and pnames biased towards the valid ones so that the
// setters get past their first checks often.
fn texture_call(k: usize, p: &Pool) -> Call {
    let target = if p.b[0] { gl::TEXTURE_2D } else { p.e[0] };
    let tp = [
        gl::TEXTURE_MIN_FILTER,
        gl::TEXTURE_MAG_FILTER,
        gl::TEXTURE_WRAP_S,
        gl::TEXTURE_WRAP_T,
        gl::TEXTURE_BORDER_COLOR,
        gl::TEXTURE_BASE_LEVEL,
        gl::TEXTURE_MAX_LEVEL,
        gl::TEXTURE_MIN_LOD,
        gl::GENERATE_MIPMAP,
        gl::TEXTURE_COMPARE_MODE,
        gl::DEPTH_TEXTURE_MODE,
    ];
    let values = [
        gl::NEAREST,
        gl::LINEAR,
        gl::LINEAR_MIPMAP_LINEAR,
        gl::NEAREST_MIPMAP_NEAREST,
        gl::REPEAT,
        gl::CLAMP,
        gl::CLAMP_TO_EDGE,
        gl::MIRRORED_REPEAT,
        gl::COMPARE_R_TO_TEXTURE,
        gl::ALPHA,
        gl::MODULATE,
        gl::DECAL,
        gl::BLEND,
        gl::REPLACE,
        gl::ADD,
        gl::EYE_LINEAR,
        gl::SPHERE_MAP,
    ];
    let pick = |xs: &[u32], i: i32| xs[(i.unsigned_abs() as usize) % xs.len()];
    let pname = if p.b[1] { pick(&tp, p.i[3]) } else { p.e[1] };
    let value = if p.b[2] {
        pick(&values, p.i[2]) as i32
    } else {
        p.i[2]
    };
    let formats = [
        gl::RGBA,
        gl::RGB,
        gl::LUMINANCE,
        gl::ALPHA,
        gl::DEPTH_COMPONENT,
        gl::INTENSITY,
    ];
    let format = if p.b[3] {
        pick(&formats, p.i[0])
    } else {
        p.e[2]
    };
    let size = |i: i32| i.rem_euclid(6) - 1;
    let bytes: Vec<u8> = p.vi.iter().flat_map(|x| x.to_ne_bytes()).collect();
    let env = if p.b[1] { gl::TEXTURE_ENV } else { p.e[0] };
    let envp = if p.b[2] { gl::TEXTURE_ENV_MODE } else { p.e[1] };
    let unit = if p.b[0] {
        gl::TEXTURE0 + p.i[3].rem_euclid(5) as u32
    } else {
        p.e[0]
    };
    let coord = if p.b[1] {
        gl::S + (p.i[0].rem_euclid(4)) as u32
    } else {
        p.e[0]
    };
    match k {
        0 => Call::GenTextures(p.i[0].rem_euclid(5) - 1),
        1 => Call::DeleteTextures(
            p.i[0].rem_euclid(4) - 1,
            p.vi.iter().map(|&x| x.rem_euclid(8) as u32).collect(),
        ),
        2 => Call::BindTexture(target, p.i[1].rem_euclid(8) as u32),
        3 => Call::TexImage2D(Box::new((
            target,
            p.i[1].rem_euclid(3) - 1,
            format as i32,
            size(p.i[2]),
            size(p.i[3]),
            i32::from(!p.b[2]) * p.i[2].rem_euclid(2),
            format,
            if p.b[1] { gl::UNSIGNED_BYTE } else { gl::FLOAT },
            p.b[2].then_some(bytes),
        ))),
        4 => Call::TexSubImage2D(Box::new((
            target,
            0,
            size(p.i[1]),
            size(p.i[2]),
            size(p.i[3]),
            1,
            format,
            gl::UNSIGNED_BYTE,
            bytes,
        ))),
        5 => Call::CopyTexImage2D(
            target,
            p.i[1].rem_euclid(3) - 1,
            format,
            p.i[0],
            p.i[1],
            size(p.i[2]),
            size(p.i[3]),
            0,
        ),
        6 => Call::CopyTexSubImage2D(
            target,
            0,
            size(p.i[1]),
            0,
            p.i[0],
            p.i[1],
            size(p.i[2]),
            size(p.i[3]),
        ),
        7 => Call::TexParameteri(target, pname, value),
        8 => Call::TexParameterf(target, pname, value as f32),
        9 => Call::TexParameteriv(target, pname, p.vi.clone()),
        10 => Call::TexParameterfv(target, pname, p.vf.clone()),
        11 => Call::TexEnvi(env, envp, value),
        12 => Call::TexEnvf(env, envp, p.f[0]),
        13 => Call::TexEnviv(env, gl::TEXTURE_ENV_COLOR, p.vi.clone()),
        14 => Call::TexEnvfv(env, envp, p.vf.clone()),
        15 => Call::TexGeni(coord, gl::TEXTURE_GEN_MODE, value),
        16 => Call::TexGenf(coord, p.e[1], p.f[0]),
        17 => Call::TexGend(coord, gl::TEXTURE_GEN_MODE, p.d[0]),
        18 => Call::TexGeniv(coord, gl::OBJECT_PLANE, p.vi.clone()),
        19 => Call::TexGenfv(coord, gl::EYE_PLANE, p.vf.clone()),
        21 => Call::MultiTexCoord1s(unit, p.i[0] as i16),
        22 => Call::MultiTexCoord1sv(unit, [p.i[0] as i16]),
        23 => Call::MultiTexCoord1i(unit, p.i[0]),
        24 => Call::MultiTexCoord1iv(unit, [p.i[0]]),
        25 => Call::MultiTexCoord1f(unit, p.f[0]),
        26 => Call::MultiTexCoord1fv(unit, [p.f[0]]),
        27 => Call::MultiTexCoord1d(unit, p.d[0]),
        28 => Call::MultiTexCoord1dv(unit, [p.d[0]]),
        29 => Call::MultiTexCoord2s(unit, p.i[0] as i16, p.i[1] as i16),
        30 => Call::MultiTexCoord2sv(unit, [p.i[0] as i16, p.i[1] as i16]),
        31 => Call::MultiTexCoord2i(unit, p.i[0], p.i[1]),
        32 => Call::MultiTexCoord2iv(unit, [p.i[0], p.i[1]]),
        33 => Call::MultiTexCoord2f(unit, p.f[0], p.f[1]),
        34 => Call::MultiTexCoord2fv(unit, [p.f[0], p.f[1]]),
        35 => Call::MultiTexCoord2d(unit, p.d[0], p.d[1]),
        36 => Call::MultiTexCoord2dv(unit, [p.d[0], p.d[1]]),
        37 => Call::MultiTexCoord3s(unit, p.i[0] as i16, p.i[1] as i16, p.i[2] as i16),
        38 => Call::MultiTexCoord3sv(unit, [p.i[0] as i16, p.i[1] as i16, p.i[2] as i16]),
        39 => Call::MultiTexCoord3i(unit, p.i[0], p.i[1], p.i[2]),
        40 => Call::MultiTexCoord3iv(unit, [p.i[0], p.i[1], p.i[2]]),
        41 => Call::MultiTexCoord3f(unit, p.f[0], p.f[1], p.f[2]),
        42 => Call::MultiTexCoord3fv(unit, [p.f[0], p.f[1], p.f[2]]),
        43 => Call::MultiTexCoord3d(unit, p.d[0], p.d[1], p.d[2]),
        44 => Call::MultiTexCoord3dv(unit, [p.d[0], p.d[1], p.d[2]]),
        45 => Call::MultiTexCoord4s(
            unit,
            p.i[0] as i16,
            p.i[1] as i16,
            p.i[2] as i16,
            p.i[3] as i16,
        ),
        46 => Call::MultiTexCoord4sv(
            unit,
            [p.i[0] as i16, p.i[1] as i16, p.i[2] as i16, p.i[3] as i16],
        ),
        47 => Call::MultiTexCoord4i(unit, p.i[0], p.i[1], p.i[2], p.i[3]),
        48 => Call::MultiTexCoord4iv(unit, [p.i[0], p.i[1], p.i[2], p.i[3]]),
        49 => Call::MultiTexCoord4f(unit, p.f[0], p.f[1], p.f[2], p.f[3]),
        50 => Call::MultiTexCoord4fv(unit, [p.f[0], p.f[1], p.f[2], p.f[3]]),
        51 => Call::MultiTexCoord4d(unit, p.d[0], p.d[1], p.d[2], p.d[3]),
        52 => Call::MultiTexCoord4dv(unit, [p.d[0], p.d[1], p.d[2], p.d[3]]),
        _ => Call::TexGendv(coord, p.e[1], p.vf.iter().map(|&x| f64::from(x)).collect()),
    }
}
// --- end texture
