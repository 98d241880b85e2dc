//! The random-call soak (issue #11): millions of random calls over every `Call` variant, each
//! checked by an oracle.
//!
//! **Generator.** `Call`'s serde `Deserialize` derive is driven by [`Gen`], a `serde::Deserializer`
//! that makes values up: `deserialize_enum` picks one of the variants serde passes it, so every
//! variant of `Call` (and of `Pointer`) — including one added tomorrow — is generated with no hand
//! list; integers, floats and sequence lengths come from distributions heavy in the extremes (0,
//! ±1, MIN, MAX, 1<<30, NaN, ±inf, subnormals, -0.0) and in GL enum values (`gl::NAMES`, so calls
//! get past enum validation). A [`Driver`] mixes these free calls with short plans that reach the
//! interesting states: Begin/End pairs around vertex attributes, display lists compiled with
//! COMPILE and COMPILE_AND_EXECUTE, called, nested and calling themselves, texture set-up, client
//! arrays and buffer objects feeding DrawArrays/DrawElements, small viewports.
//!
//! **Oracle**, per call: no panic (each batch runs under `catch_unwind`; a failure is reported
//! with the batch seed, the call, and the shortest tail of the batch that still fails, as a
//! recording); the error flag only ever holds a GL error code; a call that raised an error from a
//! clear flag left `State` unchanged; between Begin and End a command GL 2.1 §2.6.3 does not
//! list is INVALID_OPERATION and changes nothing; a call compiled by NewList(COMPILE) neither changes `State`
//! nor raises an error; no call takes longer than [`CALL_LIMIT`] (a watchdog ends the process if
//! one never returns). Per batch: the recording, written by `write_recording` and read back by
//! `read_recording`, replayed on a fresh context, gives the same image and the same `State`.
//!
//! **Runs.** `soak_ci` (in `cargo test`) runs [`CI_CALLS`] calls; `cargo test --profile ci --
//! --ignored soak` also runs `soak_10m`, 10 million. Environment: `FIXEDGL_SOAK_SEED` (base seed),
//! `FIXEDGL_SOAK_CALLS` (total calls), `FIXEDGL_SOAK_BATCH=<seed>` (run that one batch only),
//! `FIXEDGL_SOAK_TRACE=1` (print every call before it runs: for a hang).

use std::collections::VecDeque;
use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use fixedgl::recording::{read_recording, write_recording};
use fixedgl::state::State;
use fixedgl::texture::{TexObject, Textures};
use fixedgl::{gl, Call, Context, Pointer};
use serde::de::{
    self, DeserializeSeed, EnumAccess, IntoDeserializer, SeqAccess, VariantAccess, Visitor,
};
use serde::Deserialize;

use crate::common;

/// Calls `soak_ci` runs.
const CI_CALLS: u64 = 1_000_000;
/// Calls per batch: one context, one recording, one replay.
const BATCH_CALLS: usize = 4000;
/// Framebuffer side: small, so that draws are cheap and big primitives are clipped.
const SIDE: u32 = 32;
/// The longest one call may take: a bound for a hang, not a speed test.
const CALL_LIMIT: Duration = Duration::from_secs(2);
/// How long the watchdog waits for any progress before it ends the process.
const HANG_LIMIT: Duration = Duration::from_secs(60);
/// Calls compiled into one list before the driver ends it (bounds what a CallList runs).
const MAX_BODY: usize = 40;
/// Texture and buffer names past which a batch ends early (the oracle clones the state per call).
const MAX_NAMES: usize = 1000;

/// The codes `glGetError` may return (GL 2.1 table 2.3).
const CODES: [u32; 7] = [
    gl::NO_ERROR,
    gl::INVALID_ENUM,
    gl::INVALID_VALUE,
    gl::INVALID_OPERATION,
    gl::STACK_OVERFLOW,
    gl::STACK_UNDERFLOW,
    gl::OUT_OF_MEMORY,
];

// ---------------------------------------------------------------------------------------------
// The random source

/// SplitMix64: small, fast, and the same stream for the same seed everywhere.
#[derive(Clone, Debug)]
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (n > 0).
    fn below(&mut self, n: u64) -> u64 {
        ((u128::from(self.next()) * u128::from(n)) >> 64) as u64
    }

    /// Uniform in `lo..=hi`.
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }

    /// True with probability `percent`/100.
    fn percent(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }

    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len() as u64) as usize]
    }

    /// Uniform in `[lo, hi)`.
    fn float(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The batch seed of batch `i` of a run with base seed `base`.
fn batch_seed(base: u64, i: u64) -> u64 {
    Rng(base ^ i.wrapping_mul(0xD1B5_4A32_D192_ED03)).next()
}

// ---------------------------------------------------------------------------------------------
// The generator: a serde Deserializer that makes values up

/// The generator's error (it never fails on `Call`; serde needs the type).
#[derive(Debug)]
pub(crate) struct GenError(String);

impl fmt::Display for GenError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for GenError {}

impl de::Error for GenError {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        GenError(msg.to_string())
    }
}

/// Random values for any `Deserialize` type made of integers, floats, bools, tuples, sequences,
/// options and enums: `Call::deserialize(&mut gen)` is a random call.
pub(crate) struct Gen {
    rng: Rng,
    /// `Call`'s variant names, in declaration order, as serde's derive passes them.
    call_variants: &'static [&'static str],
    /// The variant the next `Call` must be (an index into `call_variants`), if chosen.
    forced: Option<u32>,
    /// Values the next integer arguments take, whatever their type (cast), before random ones.
    forced_ints: VecDeque<i64>,
}

/// Integers worth drawing often (clamped to the type's range).
const EXTREME_INTS: &[i64] = &[
    0,
    1,
    -1,
    2,
    i64::MIN,
    i64::MAX,
    i32::MIN as i64,
    i32::MAX as i64,
    u32::MAX as i64,
    1 << 30,
    -(1 << 30),
    1 << 31,
    1 << 16,
    -(1 << 16),
    255,
    256,
    -128,
    127,
    32767,
    32768,
    -32768,
    65535,
    4096,
    4097,
    16384,
    16385,
    1 << 40,
];

/// Texture enums, to add to `common::ENUMS` (which has few).
const TEXTURE_ENUMS: &[u32] = &[
    gl::TEXTURE_2D,
    gl::TEXTURE_ENV,
    gl::TEXTURE_FILTER_CONTROL,
    gl::TEXTURE_ENV_MODE,
    gl::TEXTURE_ENV_COLOR,
    gl::TEXTURE_LOD_BIAS,
    gl::TEXTURE_MIN_FILTER,
    gl::TEXTURE_MAG_FILTER,
    gl::TEXTURE_WRAP_S,
    gl::TEXTURE_WRAP_T,
    gl::TEXTURE_WRAP_R,
    gl::TEXTURE_BORDER_COLOR,
    gl::TEXTURE_PRIORITY,
    gl::TEXTURE_MIN_LOD,
    gl::TEXTURE_MAX_LOD,
    gl::TEXTURE_BASE_LEVEL,
    gl::TEXTURE_MAX_LEVEL,
    gl::GENERATE_MIPMAP,
    gl::TEXTURE_COMPARE_MODE,
    gl::TEXTURE_COMPARE_FUNC,
    gl::DEPTH_TEXTURE_MODE,
    gl::NEAREST,
    gl::LINEAR,
    gl::NEAREST_MIPMAP_NEAREST,
    gl::LINEAR_MIPMAP_NEAREST,
    gl::NEAREST_MIPMAP_LINEAR,
    gl::LINEAR_MIPMAP_LINEAR,
    gl::REPEAT,
    gl::CLAMP,
    gl::CLAMP_TO_EDGE,
    gl::CLAMP_TO_BORDER,
    gl::MIRRORED_REPEAT,
    gl::MODULATE,
    gl::DECAL,
    gl::BLEND,
    gl::REPLACE,
    gl::ADD,
    gl::COMBINE,
    gl::S,
    gl::T,
    gl::R,
    gl::Q,
    gl::TEXTURE_GEN_MODE,
    gl::OBJECT_PLANE,
    gl::EYE_PLANE,
    gl::OBJECT_LINEAR,
    gl::EYE_LINEAR,
    gl::SPHERE_MAP,
    gl::TEXTURE0,
    gl::TEXTURE1,
    gl::RGBA,
    gl::RGB,
    gl::LUMINANCE,
    gl::LUMINANCE_ALPHA,
    gl::INTENSITY,
    gl::DEPTH_COMPONENT,
    gl::UNPACK_ROW_LENGTH,
    gl::UNPACK_SKIP_ROWS,
    gl::UNPACK_SKIP_PIXELS,
    gl::UNPACK_ALIGNMENT,
];

/// Parameter setters and the leading enums that get them past validation: the `params` plan
/// makes these calls with the other arguments random (NaN, infinities, extremes).
const PARAMS: &[(&[&str], &[u32], &[u32])] = &[
    (
        &[
            "TexParameteri",
            "TexParameterf",
            "TexParameteriv",
            "TexParameterfv",
        ],
        &[gl::TEXTURE_2D],
        &[
            gl::TEXTURE_MIN_FILTER,
            gl::TEXTURE_MAG_FILTER,
            gl::TEXTURE_WRAP_S,
            gl::TEXTURE_WRAP_T,
            gl::TEXTURE_WRAP_R,
            gl::TEXTURE_BORDER_COLOR,
            gl::TEXTURE_PRIORITY,
            gl::TEXTURE_MIN_LOD,
            gl::TEXTURE_MAX_LOD,
            gl::TEXTURE_BASE_LEVEL,
            gl::TEXTURE_MAX_LEVEL,
            gl::GENERATE_MIPMAP,
            gl::TEXTURE_COMPARE_MODE,
            gl::TEXTURE_COMPARE_FUNC,
            gl::DEPTH_TEXTURE_MODE,
        ],
    ),
    (
        &["TexEnvi", "TexEnvf", "TexEnviv", "TexEnvfv"],
        &[gl::TEXTURE_ENV, gl::TEXTURE_FILTER_CONTROL],
        &[
            gl::TEXTURE_ENV_MODE,
            gl::TEXTURE_ENV_COLOR,
            gl::TEXTURE_LOD_BIAS,
        ],
    ),
    (
        &[
            "TexGeni", "TexGenf", "TexGend", "TexGeniv", "TexGenfv", "TexGendv",
        ],
        &[gl::S, gl::T, gl::R, gl::Q],
        &[gl::TEXTURE_GEN_MODE, gl::OBJECT_PLANE, gl::EYE_PLANE],
    ),
    (
        &["Lightf", "Lighti", "Lightfv", "Lightiv"],
        &[gl::LIGHT0, gl::LIGHT1, gl::LIGHT7],
        &[
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
        ],
    ),
    (
        &["Materialf", "Materiali", "Materialfv", "Materialiv"],
        &[gl::FRONT, gl::BACK, gl::FRONT_AND_BACK],
        &[
            gl::AMBIENT,
            gl::DIFFUSE,
            gl::SPECULAR,
            gl::EMISSION,
            gl::SHININESS,
            gl::AMBIENT_AND_DIFFUSE,
            gl::COLOR_INDEXES,
        ],
    ),
    (
        &["LightModelf", "LightModeli", "LightModelfv", "LightModeliv"],
        &[
            gl::LIGHT_MODEL_AMBIENT,
            gl::LIGHT_MODEL_LOCAL_VIEWER,
            gl::LIGHT_MODEL_TWO_SIDE,
            gl::LIGHT_MODEL_COLOR_CONTROL,
        ],
        &[],
    ),
    (
        &[
            "PointParameterf",
            "PointParameteri",
            "PointParameterfv",
            "PointParameteriv",
        ],
        &[
            gl::POINT_SIZE_MIN,
            gl::POINT_SIZE_MAX,
            gl::POINT_FADE_THRESHOLD_SIZE,
            gl::POINT_DISTANCE_ATTENUATION,
            gl::POINT_SPRITE_COORD_ORIGIN,
        ],
        &[],
    ),
    (
        &["Fogf", "Fogi", "Fogfv", "Fogiv"],
        &[
            gl::FOG_MODE,
            gl::FOG_DENSITY,
            gl::FOG_START,
            gl::FOG_END,
            gl::FOG_COLOR,
            gl::FOG_INDEX,
            gl::FOG_COORD_SRC,
        ],
        &[],
    ),
    (
        &["PixelStorei", "PixelStoref"],
        &[
            gl::UNPACK_ALIGNMENT,
            gl::UNPACK_ROW_LENGTH,
            gl::UNPACK_SKIP_ROWS,
            gl::UNPACK_SKIP_PIXELS,
            gl::PACK_ALIGNMENT,
            gl::PACK_ROW_LENGTH,
        ],
        &[],
    ),
];

const SPECIAL_F32: &[f32] = &[
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    0.0,
    -0.0,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    1e-45,
    -1e-40,
    f32::EPSILON,
    1e30,
    -1e30,
    16_777_217.0,
    0.5,
    1.0,
    -1.0,
];

const SPECIAL_F64: &[f64] = &[
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    f64::MAX,
    f64::MIN,
    f64::MIN_POSITIVE,
    5e-324,
    -1e-310,
    1e300,
    -1e300,
    1e39,
    3.5e38,
    0.5,
    1.0,
    -1.0,
];

impl Gen {
    pub(crate) fn new(seed: u64) -> Gen {
        let mut gen = Gen {
            rng: Rng(seed),
            call_variants: &[],
            forced: None,
            forced_ints: VecDeque::new(),
        };
        // One call to learn the variant names from the derive.
        let _ = gen.any_call();
        gen
    }

    /// A random call, every variant equally likely.
    pub(crate) fn any_call(&mut self) -> Call {
        Call::deserialize(&mut *self).expect("the generator builds every Call")
    }

    /// A random call of the variant named `name` (arguments random).
    pub(crate) fn call_named(&mut self, name: &str) -> Call {
        let i = self.call_variants.iter().position(|v| *v == name);
        self.forced = Some(i.unwrap_or_else(|| panic!("no Call variant {name}")) as u32);
        self.any_call()
    }

    /// A random call of the variant named `name` whose leading integer arguments are `ints`.
    fn call_with(&mut self, name: &str, ints: &[i64]) -> Call {
        self.forced_ints.extend(ints);
        let call = self.call_named(name);
        self.forced_ints.clear();
        call
    }

    /// An integer in `min..=max`: small values, the extremes, GL enum values, anything.
    fn signed(&mut self, min: i64, max: i64) -> i64 {
        if let Some(v) = self.forced_ints.pop_front() {
            return v;
        }
        let v = match self.rng.below(100) {
            0..=39 => self.rng.range(-2, 16),
            40..=59 => self.rng.pick(EXTREME_INTS),
            60..=69 => i64::from(self.enum_value()),
            70..=84 => self.rng.range(-300, 300),
            _ => {
                let bits = self.rng.next() as i64;
                return if min == i64::MIN {
                    bits
                } else {
                    bits.rem_euclid(max - min + 1) + min
                };
            }
        };
        if v < min || v > max {
            // Out of range: either the type's extreme or the value wrapped.
            if self.rng.percent(50) {
                return v.clamp(min, max);
            }
            return v.rem_euclid(max - min + 1) + min;
        }
        v
    }

    /// An unsigned integer up to `max` (`u64::MAX` for u64).
    fn unsigned(&mut self, max: u64) -> u64 {
        if let Some(v) = self.forced_ints.pop_front() {
            return v as u64;
        }
        let v = match self.rng.below(100) {
            0..=49 => self.rng.below(17),
            50..=69 => self.rng.pick(EXTREME_INTS) as u64,
            70..=79 => u64::from(self.enum_value()),
            80..=89 => self.rng.below(512),
            _ => self.rng.next(),
        };
        if v > max {
            if self.rng.percent(50) {
                return max;
            }
            return if max == u64::MAX { v } else { v % (max + 1) };
        }
        v
    }

    /// A GL enum value: one the entry points accept often (`common::ENUMS`, `TEXTURE_ENUMS`), else
    /// any of `gl::NAMES`; now and then one next to it.
    fn enum_value(&mut self) -> u32 {
        let v = match self.rng.below(4) {
            0 => self.rng.pick(common::ENUMS),
            1 => self.rng.pick(TEXTURE_ENUMS),
            _ => self.rng.pick(fixedgl::gl::NAMES).1,
        };
        match self.rng.below(20) {
            0 => v.wrapping_add(1),
            1 => v.wrapping_sub(1),
            _ => v,
        }
    }

    /// A `u32`: most of the time a GL enum (so that calls get past enum validation), else a small
    /// number (list, texture and buffer names, counts) or an extreme.
    fn u32_value(&mut self) -> u32 {
        if let Some(v) = self.forced_ints.pop_front() {
            return v as u32;
        }
        match self.rng.below(100) {
            0..=59 => self.enum_value(),
            60..=79 => self.rng.below(10) as u32,
            80..=89 => self.rng.pick(EXTREME_INTS) as u32,
            _ => self.rng.next() as u32,
        }
    }

    fn f64_value(&mut self) -> f64 {
        match self.rng.below(100) {
            0..=9 => f64::from(self.rng.pick(SPECIAL_F32)),
            10..=17 => self.rng.pick(SPECIAL_F64),
            18..=54 => self.rng.float(-2.0, 2.0),
            55..=69 => self.rng.range(-10, 300) as f64,
            70..=76 => f64::from(self.enum_value()),
            77..=89 => self.rng.float(-1e4, 1e4),
            _ => f64::from_bits(self.rng.next()),
        }
    }

    fn f32_value(&mut self) -> f32 {
        match self.rng.below(100) {
            0..=14 => self.rng.pick(SPECIAL_F32),
            90..=99 => f32::from_bits(self.rng.next() as u32),
            _ => self.f64_value() as f32,
        }
    }

    /// A sequence length: short (0..=20) mostly, which also tests the short-slice paths; now and
    /// then a few hundred (pixel and pointer data).
    fn seq_len(&mut self) -> usize {
        if self.rng.percent(7) {
            self.rng.below(400) as usize
        } else {
            self.rng.below(21) as usize
        }
    }
}

/// `len` elements of a tuple or sequence.
struct Seq<'a> {
    gen: &'a mut Gen,
    left: usize,
}

impl<'de> SeqAccess<'de> for Seq<'_> {
    type Error = GenError;

    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, GenError> {
        if self.left == 0 {
            return Ok(None);
        }
        self.left -= 1;
        seed.deserialize(&mut *self.gen).map(Some)
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.left)
    }
}

/// One enum value: the chosen variant, then its fields.
struct Enum<'a> {
    gen: &'a mut Gen,
    index: u32,
}

impl<'de, 'a> EnumAccess<'de> for Enum<'a> {
    type Error = GenError;
    type Variant = Self;

    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self), GenError> {
        let index: de::value::U32Deserializer<GenError> = self.index.into_deserializer();
        Ok((seed.deserialize(index)?, self))
    }
}

impl<'de, 'a> VariantAccess<'de> for Enum<'a> {
    type Error = GenError;

    fn unit_variant(self) -> Result<(), GenError> {
        Ok(())
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, GenError> {
        seed.deserialize(self.gen)
    }

    fn tuple_variant<V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value, GenError> {
        visitor.visit_seq(Seq {
            gen: self.gen,
            left: len,
        })
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, GenError> {
        visitor.visit_seq(Seq {
            gen: self.gen,
            left: fields.len(),
        })
    }
}

macro_rules! signed {
    ($method:ident, $visit:ident, $t:ty) => {
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
            let v = self.signed(<$t>::MIN as i64, <$t>::MAX as i64);
            visitor.$visit(v as $t)
        }
    };
}

macro_rules! unsigned {
    ($method:ident, $visit:ident, $t:ty) => {
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
            let v = self.unsigned(<$t>::MAX as u64);
            visitor.$visit(v as $t)
        }
    };
}

impl<'de> de::Deserializer<'de> for &mut Gen {
    type Error = GenError;

    fn deserialize_any<V: Visitor<'de>>(self, _visitor: V) -> Result<V::Value, GenError> {
        Err(de::Error::custom("the generator needs a typed request"))
    }

    signed!(deserialize_i8, visit_i8, i8);
    signed!(deserialize_i16, visit_i16, i16);
    signed!(deserialize_i32, visit_i32, i32);
    signed!(deserialize_i64, visit_i64, i64);
    unsigned!(deserialize_u8, visit_u8, u8);
    unsigned!(deserialize_u16, visit_u16, u16);
    unsigned!(deserialize_u64, visit_u64, u64);

    fn deserialize_u32<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        let v = self.u32_value();
        visitor.visit_u32(v)
    }

    fn deserialize_f32<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        let v = self.f32_value();
        visitor.visit_f32(v)
    }

    fn deserialize_f64<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        let v = self.f64_value();
        visitor.visit_f64(v)
    }

    fn deserialize_bool<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        let v = self.rng.percent(50);
        visitor.visit_bool(v)
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        if self.rng.percent(15) {
            visitor.visit_none()
        } else {
            visitor.visit_some(self)
        }
    }

    fn deserialize_seq<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, GenError> {
        let left = self.seq_len();
        visitor.visit_seq(Seq { gen: self, left })
    }

    fn deserialize_tuple<V: Visitor<'de>>(
        self,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, GenError> {
        visitor.visit_seq(Seq {
            gen: self,
            left: len,
        })
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, GenError> {
        visitor.visit_seq(Seq {
            gen: self,
            left: len,
        })
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, GenError> {
        visitor.visit_newtype_struct(self)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, GenError> {
        visitor.visit_seq(Seq {
            gen: self,
            left: fields.len(),
        })
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        name: &'static str,
        variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, GenError> {
        let index = match self.forced.take() {
            Some(i) if name == "Call" => i,
            forced => {
                self.forced = forced;
                self.rng.below(variants.len() as u64) as u32
            }
        };
        if name == "Call" {
            self.call_variants = variants;
        }
        visitor.visit_enum(Enum { gen: self, index })
    }

    serde::forward_to_deserialize_any! {
        char str string bytes byte_buf unit unit_struct map identifier ignored_any
    }
}

// ---------------------------------------------------------------------------------------------
// The driver: free random calls mixed with plans that reach the interesting states

/// Bytes of `xs` in native order (client memory handed to a pointer call).
fn bytes_of_f32(xs: impl IntoIterator<Item = f32>) -> Vec<u8> {
    xs.into_iter().flat_map(f32::to_ne_bytes).collect()
}

/// Builds the call stream of one batch, a plan at a time.
struct Driver {
    gen: Gen,
    queue: VecDeque<Call>,
}

impl Driver {
    fn new(seed: u64) -> Driver {
        Driver {
            gen: Gen::new(seed),
            queue: VecDeque::new(),
        }
    }

    /// The next call to run.
    fn next_call(&mut self) -> Call {
        while self.queue.is_empty() {
            self.plan();
        }
        self.queue.pop_front().expect("a plan adds calls")
    }

    fn push(&mut self, call: Call) {
        self.queue.push_back(call);
    }

    fn rng(&mut self) -> &mut Rng {
        &mut self.gen.rng
    }

    /// Queues one plan.
    fn plan(&mut self) {
        match self.rng().below(100) {
            0..=49 => {
                let call = self.gen.any_call();
                self.push(call);
            }
            50..=61 => self.begin_end(),
            62..=65 => self.define_list(),
            66..=71 => self.call_lists(),
            72..=77 => self.textures(),
            78..=83 => self.arrays(),
            84..=89 => self.params(),
            90..=95 => self.view(),
            _ => self.misuse(),
        }
    }

    /// A primitive mode: valid mostly.
    fn prim(&mut self) -> u32 {
        if self.rng().percent(90) {
            self.rng().below(10) as u32
        } else {
            self.gen.u32_value()
        }
    }

    fn coord(&mut self) -> f32 {
        self.rng().float(-1.3, 1.3) as f32
    }

    /// A vertex attribute with ordinary values, so that primitives reach the pixels.
    fn attribute(&mut self) -> Call {
        let (x, y, z) = (self.coord(), self.coord(), self.coord());
        match self.rng().below(10) {
            0..=4 => Call::Vertex3f(x, y, z),
            5 => Call::Color4f(x.abs(), y.abs(), z.abs(), 1.0),
            6 => Call::Normal3f(x, y, z),
            7 => Call::TexCoord2f(x * 2.0, y * 2.0),
            8 => Call::Vertex2f(x, y),
            _ => Call::ArrayElement(self.rng().range(-1, 8) as i32),
        }
    }

    /// Begin, attributes (some random, some not allowed there), End (mostly).
    fn begin_end(&mut self) {
        let mode = self.prim();
        self.push(Call::Begin(mode));
        for _ in 0..self.rng().below(13) {
            let call = match self.rng().below(100) {
                0..=74 => self.attribute(),
                75..=94 => loop {
                    let call = self.gen.any_call();
                    if call.allowed_between_begin_end() {
                        break call;
                    }
                },
                _ => self.gen.any_call(),
            };
            self.push(call);
        }
        if self.rng().percent(92) {
            self.push(Call::End);
        }
    }

    /// NewList, a few plans, EndList (mostly).
    fn define_list(&mut self) {
        let name = self.rng().range(1, 8) as u32;
        let mode = match self.rng().below(10) {
            0..=4 => gl::COMPILE,
            5..=8 => gl::COMPILE_AND_EXECUTE,
            _ => self.gen.u32_value(),
        };
        self.push(Call::NewList(name, mode));
        for _ in 0..self.rng().range(1, 6) {
            match self.rng().below(10) {
                0..=3 => {
                    let call = self.gen.any_call();
                    self.push(call);
                }
                4..=5 => self.begin_end(),
                6 => self.push(Call::CallList(name)), // itself
                7 => self.call_lists(),
                8 => self.textures(),
                _ => {
                    if self.rng().percent(50) {
                        self.arrays()
                    } else {
                        self.view()
                    }
                }
            }
        }
        if self.rng().percent(90) {
            self.push(Call::EndList);
        }
    }

    /// CallList, CallLists and ListBase with names of lists that are likely defined.
    fn call_lists(&mut self) {
        match self.rng().below(10) {
            0..=4 => {
                let name = self.rng().below(10) as u32;
                self.push(Call::CallList(name));
            }
            5..=8 => {
                let n = if self.rng().percent(85) {
                    self.rng().range(0, 4) as i32
                } else {
                    self.gen.signed(i32::MIN.into(), i32::MAX.into()) as i32
                };
                let ty = if self.rng().percent(70) {
                    gl::UNSIGNED_BYTE
                } else {
                    self.gen.u32_value()
                };
                let len = (n.clamp(0, 8) as u64 * 4).saturating_sub(self.rng().below(3));
                let names = (0..len).map(|_| self.rng().below(9) as u8).collect();
                self.push(Call::CallLists(n, ty, names));
            }
            _ => {
                let base = self.rng().below(3) as u32;
                self.push(Call::ListBase(base));
            }
        }
    }

    /// Texture objects: GenTextures, BindTexture, TexImage2D of small sizes, parameters, Enable.
    fn textures(&mut self) {
        let name = self.rng().below(5) as u32;
        if self.rng().percent(30) {
            let n = self.rng().range(1, 3) as i32;
            self.push(Call::GenTextures(n));
        }
        if self.rng().percent(25) {
            return self.textures_1d_3d(name);
        }
        self.push(Call::BindTexture(gl::TEXTURE_2D, name));
        let sizes = [0, 1, 2, 4, 8, 3, 16];
        let (w, h) = (self.rng().pick(&sizes), self.rng().pick(&sizes));
        let formats = [
            gl::RGBA,
            gl::RGB,
            gl::LUMINANCE,
            gl::ALPHA,
            gl::LUMINANCE_ALPHA,
        ];
        let format = self.rng().pick(&formats);
        let internal = if self.rng().percent(80) {
            format as i32
        } else {
            self.gen.enum_value() as i32
        };
        let ty = if self.rng().percent(80) {
            gl::UNSIGNED_BYTE
        } else {
            gl::FLOAT
        };
        let level = self.rng().range(0, 3) as i32;
        let size = (w * h * 4 * if ty == gl::FLOAT { 4 } else { 1 }) as usize;
        let pixels = match self.rng().below(10) {
            0 => None,
            1 => Some(vec![0x7f; size / 2]),
            _ => Some((0..size).map(|_| self.rng().next() as u8).collect()),
        };
        self.push(Call::TexImage2D(Box::new((
            gl::TEXTURE_2D,
            level,
            internal,
            w,
            h,
            0,
            format,
            ty,
            pixels,
        ))));
        let filters = [
            gl::NEAREST,
            gl::LINEAR,
            gl::NEAREST_MIPMAP_NEAREST,
            gl::LINEAR_MIPMAP_LINEAR,
        ];
        let pname = self
            .rng()
            .pick(&[gl::TEXTURE_MIN_FILTER, gl::TEXTURE_MAG_FILTER]);
        let filter = self.rng().pick(&filters) as i32;
        self.push(Call::TexParameteri(gl::TEXTURE_2D, pname, filter));
        if self.rng().percent(50) {
            let mode = self
                .rng()
                .pick(&[gl::MODULATE, gl::DECAL, gl::BLEND, gl::REPLACE, gl::ADD]);
            self.push(Call::TexEnvi(
                gl::TEXTURE_ENV,
                gl::TEXTURE_ENV_MODE,
                mode as i32,
            ));
        }
        if self.rng().percent(60) {
            self.push(Call::Enable(gl::TEXTURE_2D));
        }
    }

    /// 1D and 3D textures (issue #14): TexImage1D/3D of small sizes under random image
    /// unpack modes, sub-images, copies, WRAP_R, Enable.
    fn textures_1d_3d(&mut self, name: u32) {
        let three = self.rng().percent(50);
        let target = if three {
            gl::TEXTURE_3D
        } else {
            gl::TEXTURE_1D
        };
        // Names of the other target's objects are INVALID_OPERATION here: part of the soak.
        self.push(Call::BindTexture(target, name + 10 * u32::from(three)));
        let sizes = [0, 1, 2, 4, 3, 8];
        let (w, h, d) = (
            self.rng().pick(&sizes),
            self.rng().pick(&sizes),
            self.rng().pick(&sizes),
        );
        if self.rng().percent(30) {
            let pname = self
                .rng()
                .pick(&[gl::UNPACK_IMAGE_HEIGHT, gl::UNPACK_SKIP_IMAGES]);
            let v = self.rng().range(0, 6) as i32;
            self.push(Call::PixelStorei(pname, v));
        }
        let level = self.rng().range(0, 3) as i32;
        let size = (w * h.max(1) * d.max(1) * 4 + 64) as usize;
        let pixels = match self.rng().below(10) {
            0 => None,
            1 => Some(vec![0x7f; size / 3]),
            _ => Some((0..size).map(|_| self.rng().next() as u8).collect()),
        };
        let internal = if self.rng().percent(85) {
            gl::RGBA as i32
        } else {
            self.gen.enum_value() as i32
        };
        let (ox, oz) = (
            self.rng().range(-1, 3) as i32,
            self.rng().range(-1, 3) as i32,
        );
        if three {
            self.push(Call::TexImage3D(Box::new((
                target,
                level,
                internal,
                w,
                h,
                d,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                pixels.clone(),
            ))));
            self.push(Call::TexSubImage3D(Box::new((
                target,
                level,
                ox,
                0,
                oz,
                1,
                1,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                pixels.clone().unwrap_or_default(),
            ))));
            if self.rng().percent(30) {
                self.push(Call::CopyTexSubImage3D(target, level, 0, 0, 0, 0, 0, w, h));
            }
        } else {
            self.push(Call::TexImage1D(Box::new((
                target,
                level,
                internal,
                w,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                pixels.clone(),
            ))));
            self.push(Call::TexSubImage1D(Box::new((
                target,
                level,
                ox,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                pixels.clone().unwrap_or_default(),
            ))));
            if self.rng().percent(30) {
                self.push(Call::CopyTexImage1D(target, level, gl::RGB, 1, 1, w, 0));
                self.push(Call::CopyTexSubImage1D(target, level, 1, 0, 0, 2));
            }
        }
        let wrap = self
            .rng()
            .pick(&[gl::REPEAT, gl::CLAMP, gl::MIRRORED_REPEAT]);
        self.push(Call::TexParameteri(target, gl::TEXTURE_WRAP_R, wrap as i32));
        let filter = self
            .rng()
            .pick(&[gl::NEAREST, gl::LINEAR, gl::LINEAR_MIPMAP_LINEAR]);
        self.push(Call::TexParameteri(
            target,
            gl::TEXTURE_MIN_FILTER,
            filter as i32,
        ));
        if self.rng().percent(60) {
            self.push(Call::Enable(target));
        }
    }

    /// Client arrays (and now and then a buffer object) feeding DrawArrays/DrawElements.
    fn arrays(&mut self) {
        let n = self.rng().below(12) as usize;
        if self.rng().percent(25) {
            // A buffer object holding the vertices.
            let buffer = self.rng().range(1, 3) as u32;
            let data = bytes_of_f32((0..n * 3).map(|_| self.coord()));
            let size = if self.rng().percent(90) {
                data.len() as isize
            } else {
                self.gen.signed(isize::MIN as i64, isize::MAX as i64) as isize
            };
            self.push(Call::BindBuffer(gl::ARRAY_BUFFER, buffer));
            self.push(Call::BufferData(
                gl::ARRAY_BUFFER,
                size,
                Box::new(Pointer::Data(data)),
                gl::STATIC_DRAW,
            ));
            self.push(Call::VertexPointer(3, gl::FLOAT, 0, Pointer::Offset(0)));
            self.push(Call::BindBuffer(gl::ARRAY_BUFFER, 0));
        } else {
            let size = self.rng().range(2, 4) as i32;
            let data = bytes_of_f32((0..n * size as usize).map(|_| self.coord()));
            self.push(Call::VertexPointer(size, gl::FLOAT, 0, Pointer::Data(data)));
        }
        self.push(Call::EnableClientState(gl::VERTEX_ARRAY));
        if self.rng().percent(40) {
            let data = (0..n * 4).map(|_| self.rng().next() as u8).collect();
            self.push(Call::ColorPointer(
                4,
                gl::UNSIGNED_BYTE,
                0,
                Pointer::Data(data),
            ));
            self.push(Call::EnableClientState(gl::COLOR_ARRAY));
        }
        if self.rng().percent(30) {
            let data = bytes_of_f32((0..n * 2).map(|_| self.coord()));
            self.push(Call::TexCoordPointer(2, gl::FLOAT, 0, Pointer::Data(data)));
            self.push(Call::EnableClientState(gl::TEXTURE_COORD_ARRAY));
        }
        let mode = self.prim();
        let count = if self.rng().percent(90) {
            self.rng().range(0, 14) as i32
        } else {
            self.gen.signed(i32::MIN.into(), i32::MAX.into()) as i32
        };
        if self.rng().percent(50) {
            let first = self.rng().range(0, 3) as i32;
            self.push(Call::DrawArrays(mode, first, count));
        } else {
            let ty = self
                .rng()
                .pick(&[gl::UNSIGNED_BYTE, gl::UNSIGNED_SHORT, gl::UNSIGNED_INT]);
            let width = match ty {
                gl::UNSIGNED_BYTE => 1,
                gl::UNSIGNED_SHORT => 2,
                _ => 4,
            };
            let k = count.clamp(0, 20) as usize;
            let indices: Vec<u8> = (0..k)
                .flat_map(|_| {
                    let i = self.rng().below(n as u64 + 2);
                    i.to_ne_bytes()[..width].to_vec()
                })
                .collect();
            self.push(Call::DrawElements(mode, count, ty, Pointer::Data(indices)));
        }
        if self.rng().percent(30) {
            self.push(Call::DisableClientState(gl::VERTEX_ARRAY));
        }
    }

    /// Viewport, scissor, projection and modelview set-ups, clears.
    fn view(&mut self) {
        match self.rng().below(8) {
            0 | 1 => {
                let x = self.rng().range(-8, 40) as i32;
                let y = self.rng().range(-8, 40) as i32;
                let w = self.rng().range(0, 48) as i32;
                let h = self.rng().range(0, 48) as i32;
                if self.rng().percent(70) {
                    self.push(Call::Viewport(x, y, w, h));
                } else {
                    self.push(Call::Scissor(x, y, w, h));
                    self.push(Call::Enable(gl::SCISSOR_TEST));
                }
            }
            2 => {
                self.push(Call::MatrixMode(gl::PROJECTION));
                self.push(Call::LoadIdentity);
                let ortho = self.rng().percent(50);
                let near = if ortho { -2.0 } else { 0.5 };
                let p = Box::new([-1.0, 1.0, -1.0, 1.0, near, 4.0]);
                self.push(if ortho {
                    Call::Ortho(p)
                } else {
                    Call::Frustum(p)
                });
                self.push(Call::MatrixMode(gl::MODELVIEW));
                self.push(Call::LoadIdentity);
                if !ortho {
                    self.push(Call::Translatef(0.0, 0.0, -2.0));
                }
            }
            3 => {
                let angle = self.rng().float(0.0, 360.0) as f32;
                self.push(Call::Rotatef(angle, 0.3, 1.0, 0.2));
            }
            4 => {
                let bits = gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT;
                let mask = self.rng().next() as u32 & bits;
                self.push(Call::Clear(mask));
            }
            5 => {
                let caps = [
                    gl::LIGHTING,
                    gl::LIGHT0,
                    gl::DEPTH_TEST,
                    gl::CULL_FACE,
                    gl::BLEND,
                    gl::FOG,
                    gl::STENCIL_TEST,
                    gl::ALPHA_TEST,
                    gl::COLOR_MATERIAL,
                    gl::NORMALIZE,
                    gl::TEXTURE_2D,
                    gl::POLYGON_OFFSET_FILL,
                    gl::COLOR_LOGIC_OP,
                    gl::TEXTURE_GEN_S,
                    gl::CLIP_PLANE0,
                ];
                let cap = self.rng().pick(&caps);
                let call = if self.rng().percent(70) {
                    Call::Enable(cap)
                } else {
                    Call::Disable(cap)
                };
                self.push(call);
            }
            6 => {
                let name = self
                    .rng()
                    .pick(&["PushMatrix", "PushAttrib", "PushClientAttrib"]);
                let call = self.gen.call_named(name);
                self.push(call);
            }
            _ => {
                let name = self
                    .rng()
                    .pick(&["PopMatrix", "PopAttrib", "PopClientAttrib"]);
                let call = self.gen.call_named(name);
                self.push(call);
            }
        }
    }

    /// A parameter setter past its enum checks with random values; the value itself a valid
    /// enum half of the time. Then, often, a textured and lit triangle to use it.
    fn params(&mut self) {
        let (names, firsts, seconds) = self.rng().pick(PARAMS);
        let name = self.rng().pick(names);
        let mut ints = vec![i64::from(self.rng().pick(firsts))];
        if !seconds.is_empty() {
            ints.push(i64::from(self.rng().pick(seconds)));
        }
        if self.rng().percent(50) {
            ints.push(i64::from(self.rng().pick(TEXTURE_ENUMS)));
        }
        let call = self.gen.call_with(name, &ints);
        self.push(call);
        if self.rng().percent(40) {
            self.push(Call::Enable(gl::TEXTURE_2D));
            self.push(Call::Enable(gl::LIGHTING));
            self.push(Call::Enable(gl::LIGHT0));
            self.push(Call::Begin(gl::TRIANGLES));
            for _ in 0..3 {
                let (s, t) = (self.coord() * 3.0, self.coord() * 3.0);
                self.push(Call::TexCoord2f(s, t));
                self.push(Call::Normal3f(0.0, 0.0, 1.0));
                let (x, y) = (self.coord(), self.coord());
                self.push(Call::Vertex2f(x, y));
            }
            self.push(Call::End);
        }
    }

    /// Commands where they do not belong: End without Begin, EndList without NewList, a nested
    /// Begin or NewList, a random call of a variant picked again (the free calls already reach
    /// the rest).
    fn misuse(&mut self) {
        let name = self
            .rng()
            .pick(&["End", "EndList", "Begin", "NewList", "GenLists"]);
        let call = self.gen.call_named(name);
        self.push(call);
    }
}

// ---------------------------------------------------------------------------------------------
// The oracle

/// State equality where NaN equals NaN (a NaN a valid call stored must not fail the check).
fn same(a: &State, b: &State) -> bool {
    a == b || state_diff(a, b).is_none()
}

/// The field in which `after` differs from `before`, NaN equal to NaN; `None` when they are the
/// same.
fn changed(before: &State, after: &State) -> Option<&'static str> {
    if before == after {
        return None;
    }
    state_diff(before, after)
}

/// Equality where NaN equals NaN: `==`, else the Debug forms.
fn loose_eq<T: PartialEq + fmt::Debug>(x: &T, y: &T) -> bool {
    x == y || format!("{x:?}") == format!("{y:?}")
}

/// Compares the named fields of two values of a struct with `loose_eq`, returning the name of the
/// first that differs; the pattern names every field, so a field added to the struct is a compile
/// error here until it is compared.
macro_rules! first_diff {
    ($a:expr, $b:expr, $ty:ident { $($field:ident),* $(,)? } $(, special { $($sp:ident),* })?) => {{
        let $ty { $($field: _,)* $($($sp: _,)*)? } = $a;
        None$(.or_else(|| (!loose_eq(&$a.$field, &$b.$field)).then_some(stringify!($field))))*
    }};
}

/// The first field of `State` in which `a` and `b` differ, NaN equal to NaN; field by field, so
/// that a NaN somewhere (a matrix, a texel) costs the Debug form of that field only.
fn state_diff(a: &State, b: &State) -> Option<&'static str> {
    first_diff!(
        a,
        b,
        State {
            width,
            height,
            config,
            y0_top,
            current,
            matrix_mode,
            modelview,
            projection,
            texture_matrix,
            active_texture,
            client_active_texture,
            viewport,
            depth_range,
            clip_planes,
            enables,
            shade_model,
            lights,
            light_model,
            materials,
            color_material_face,
            color_material_mode,
            point_size,
            point,
            line_width,
            front_face,
            cull_face_mode,
            polygon_mode,
            polygon_offset_factor,
            polygon_offset_units,
            scissor,
            depth_func,
            color_mask,
            depth_mask,
            stencil_writemask,
            clear_color,
            clear_index,
            index_writemask,
            clear_depth,
            clear_stencil,
            draw_buffer,
            read_buffer,
            accum_clear,
            render_mode,
            unpack,
            pack,
            hints,
            list_base,
            arrays,
            fog,
            alpha,
            sample_coverage_value,
            sample_coverage_invert,
            stencil,
            blend,
            logic_op,
            eval_maps,
            eval_grid,
            raster_pos,
            pixel,
            pixel_maps,
            stipple
        },
        special { textures }
    )
    .or_else(|| textures_diff(&a.textures, &b.textures))
}

fn textures_diff(a: &Textures, b: &Textures) -> Option<&'static str> {
    if a == b {
        return None;
    }
    let same_objects = a.objects.len() == b.objects.len()
        && a.objects
            .iter()
            .zip(&b.objects)
            .all(|((ka, oa), (kb, ob))| ka == kb && tex_object_diff(oa, ob).is_none());
    if !same_objects {
        return Some("textures.objects");
    }
    for (da, db) in a.defaults.iter().zip(&b.defaults) {
        if let Some(field) = tex_object_diff(da, db) {
            return Some(field);
        }
    }
    first_diff!(
        a,
        b,
        Textures {
            names,
            units,
            proxies
        },
        special { objects, defaults }
    )
    .map(|_| "textures")
}

/// Texels compared by bits (a NaN texel stays the same NaN), the rest with `loose_eq`.
fn tex_object_diff(a: &TexObject, b: &TexObject) -> Option<&'static str> {
    if a == b {
        return None;
    }
    let same_levels =
        a.levels.len() == b.levels.len()
            && a.levels
                .iter()
                .zip(&b.levels)
                .all(|(la, lb)| match (la, lb) {
                    (None, None) => true,
                    (Some(la), Some(lb)) => {
                        (la.width, la.height, la.internal_format, la.base)
                            == (lb.width, lb.height, lb.internal_format, lb.base)
                            && la.texels.len() == lb.texels.len()
                            && la.texels.iter().zip(lb.texels.iter()).all(|(x, y)| {
                                x.iter().zip(y).all(|(x, y)| x.to_bits() == y.to_bits())
                            })
                    }
                    _ => false,
                });
    if !same_levels {
        return Some("texture object levels");
    }
    first_diff!(
        a,
        b,
        TexObject {
            target,
            min_filter,
            mag_filter,
            wrap_s,
            wrap_t,
            wrap_r,
            border_color,
            priority,
            min_lod,
            max_lod,
            base_level,
            max_level,
            lod_bias,
            generate_mipmap,
            compare_mode,
            compare_func,
            depth_texture_mode
        },
        special { levels }
    )
    .map(|_| "texture object parameters")
}

/// What went wrong, and at which call of the calls run.
#[derive(Debug)]
struct Failure {
    /// Index of the failing call in the calls run (the end of the batch for the replay check).
    index: usize,
    /// A panic (true) or an oracle check (false).
    panic: bool,
}

/// The oracle's model of the context: what it cannot read from `Context` directly.
struct Oracle {
    /// LIST_MODE: the mode of the list being defined, 0 when none.
    compiling: u32,
    /// Calls compiled into the list being defined, and how many of them call lists.
    body_len: usize,
    body_list_calls: usize,
}

impl Oracle {
    fn new() -> Oracle {
        Oracle {
            compiling: 0,
            body_len: 0,
            body_list_calls: 0,
        }
    }

    /// Whether `call` may run: a list that calls lists more than once per run can run 2^64
    /// times through MAX_LIST_NESTING levels (as on any driver), so a list body holds at most one
    /// CallList or one-name CallLists.
    fn allowed(&self, call: &Call) -> bool {
        if self.compiling == 0 {
            return true;
        }
        match call {
            Call::CallList(_) => self.body_list_calls == 0,
            Call::CallLists(n, ..) => self.body_list_calls == 0 && *n <= 1,
            _ => true,
        }
    }

    /// Runs `call` on `ctx` and checks it.
    fn step(&mut self, ctx: &mut Context, call: &Call) -> Result<(), String> {
        let runs_list = matches!(call, Call::CallList(_) | Call::CallLists(..));
        let compiled = self.compiling != 0 && !call.executes_immediately();
        let compile_only = compiled && self.compiling == gl::COMPILE;
        // GL 2.1 §2.6.3: between Begin and End every command it does not list is
        // INVALID_OPERATION and changes nothing.
        let misplaced = ctx.inside_begin_end() && !call.allowed_between_begin_end();
        let e0 = ctx.pending_error();
        let before = (compile_only || misplaced || (e0 == gl::NO_ERROR && !runs_list))
            .then(|| ctx.state().clone());
        let t0 = Instant::now();
        ctx.execute(call);
        let took = t0.elapsed();
        if took > CALL_LIMIT {
            return Err(format!("took {took:?} (limit {CALL_LIMIT:?})"));
        }
        let e1 = ctx.pending_error();
        if !CODES.contains(&e1) {
            return Err(format!("left error flag {e1:#x}, not a GL error code"));
        }
        self.follow(ctx, call, compiled);
        if compile_only {
            if let Some(field) = changed(before.as_ref().unwrap(), ctx.state()) {
                return Err(format!(
                    "compiled (COMPILE) and changed the state ({field})"
                ));
            }
            if e1 != e0 {
                return Err(format!("compiled (COMPILE) and raised {e1:#x}"));
            }
        } else if misplaced {
            if e1 == gl::NO_ERROR || (e0 == gl::NO_ERROR && e1 != gl::INVALID_OPERATION) {
                return Err(format!(
                    "between Begin and End raised {e1:#x}, not INVALID_OPERATION"
                ));
            }
            if let Some(field) = changed(before.as_ref().unwrap(), ctx.state()) {
                return Err(format!("between Begin and End changed the state ({field})"));
            }
        } else if let Some(before) = before {
            if e1 != gl::NO_ERROR {
                if let Some(field) = changed(&before, ctx.state()) {
                    return Err(format!("raised {e1:#x} and changed the state ({field})"));
                }
            }
        }
        if !ctx.inside_begin_end() {
            ctx.get_error();
        }
        Ok(())
    }

    /// Follows the list being compiled after `call` ran on `ctx` (`compiled`: whether it went
    /// into that list): the body's length, its list calls, and LIST_MODE after NewList and
    /// EndList.
    fn follow(&mut self, ctx: &mut Context, call: &Call, compiled: bool) {
        if compiled {
            self.body_len += 1;
            self.body_list_calls +=
                usize::from(matches!(call, Call::CallList(_) | Call::CallLists(..)));
        }
        if matches!(call, Call::NewList(..) | Call::EndList) && !ctx.inside_begin_end() {
            // LIST_MODE is a query: it leaves the error flag as it was.
            let mut mode = [0];
            ctx.get_integerv(gl::LIST_MODE, &mut mode);
            let mode = mode[0] as u32;
            if mode != self.compiling {
                self.body_len = 0;
                self.body_list_calls = 0;
            }
            self.compiling = mode;
        }
    }
}

/// `read_pixels` with random arguments (sizes with the extremes, any format and type, a buffer
/// of any length up to what the request needs): a GL error code, no change of state, in time.
fn read_pixels_probe(ctx: &mut Context, gen: &mut Gen) -> Result<(), String> {
    let int = |gen: &mut Gen| gen.signed(i32::MIN.into(), i32::MAX.into()) as i32;
    let (x, y, w, h) = (int(gen), int(gen), int(gen), int(gen));
    let (format, ty) = (gen.u32_value(), gen.u32_value());
    let need = w.clamp(0, 64) as usize * h.clamp(0, 64) as usize * 16;
    let mut out = vec![0u8; gen.rng.below(need as u64 + 2) as usize];
    let before = ctx.state().clone();
    let e0 = ctx.pending_error();
    let t0 = Instant::now();
    ctx.read_pixels(x, y, w, h, format, ty, &mut out);
    let took = t0.elapsed();
    let what = format!(
        "read_pixels({x}, {y}, {w}, {h}, {format:#x}, {ty:#x}, [{} bytes])",
        out.len()
    );
    if took > CALL_LIMIT {
        return Err(format!("{what} took {took:?}"));
    }
    let e1 = ctx.pending_error();
    if !CODES.contains(&e1) || (e0 != gl::NO_ERROR && e1 != e0) {
        return Err(format!("{what} left error flag {e1:#x}"));
    }
    if let Some(field) = changed(&before, ctx.state()) {
        return Err(format!("{what} changed the state ({field})"));
    }
    if !ctx.inside_begin_end() {
        ctx.get_error();
    }
    Ok(())
}

/// Runs `calls` on a fresh context under the oracle (no replay check): for shrinking a failure.
fn check_calls(calls: &[Call]) -> Result<(), Failure> {
    let mut ctx = Context::new(SIDE, SIDE).expect("context");
    let mut oracle = Oracle::new();
    for (index, call) in calls.iter().enumerate() {
        match catch_unwind(AssertUnwindSafe(|| oracle.step(&mut ctx, call))) {
            Ok(Ok(())) => {}
            Ok(Err(_)) => {
                return Err(Failure {
                    index,
                    panic: false,
                })
            }
            Err(_) => return Err(Failure { index, panic: true }),
        }
    }
    Ok(())
}

fn panic_message(payload: &Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        format!("panicked: {s}")
    } else if let Some(s) = payload.downcast_ref::<String>() {
        format!("panicked: {s}")
    } else {
        "panicked".into()
    }
}

/// A short list of calls ending with the last of `calls` (which fail at their last call) that
/// still fails the same way on a fresh context: the shortest failing tail, then with chunks
/// dropped while it still fails. Panics in the attempts are kept quiet.
fn shortest_failing_tail(calls: &[Call], panic: bool) -> Vec<Call> {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let fails = |k: usize| {
        let tail = &calls[calls.len() - k..];
        matches!(check_calls(tail), Err(f) if f.panic == panic && f.index == k - 1)
    };
    // Doubling, then bisection between the last length that passed and the first that failed.
    let (mut lo, mut hi) = (0, calls.len());
    let mut k = 1;
    while k < calls.len() {
        if fails(k) {
            hi = k;
            break;
        }
        lo = k;
        k *= 2;
    }
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if fails(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    // Then drop chunks of the tail (never its last, failing call) while it still fails: halves,
    // quarters, ... down to single calls, within a budget of runs.
    let mut tail = calls[calls.len() - hi..].to_vec();
    let still_fails =
        |t: &[Call]| matches!(check_calls(t), Err(f) if f.panic == panic && f.index == t.len() - 1);
    let mut chunk = tail.len() / 2;
    let mut runs = 0;
    while chunk >= 1 && runs < 400 {
        let mut start = 0;
        while start + chunk < tail.len() && runs < 400 {
            let mut shorter = tail[..start].to_vec();
            shorter.extend_from_slice(&tail[start + chunk..]);
            runs += 1;
            if still_fails(&shorter) {
                tail = shorter;
            } else {
                start += chunk;
            }
        }
        chunk /= 2;
    }
    std::panic::set_hook(hook);
    tail
}

/// What one batch did.
#[derive(Default)]
struct BatchStats {
    calls: u64,
    slowest: Duration,
    /// Whether the batch ended before its count (over `MAX_NAMES` object names).
    ended_early: bool,
}

/// Texture and buffer names the state holds.
fn object_names(ctx: &Context) -> usize {
    let s = ctx.state();
    let names = s
        .textures
        .names
        .len()
        .saturating_add(s.arrays.reserved.len());
    usize::try_from(names)
        .unwrap_or(usize::MAX)
        .saturating_add(s.textures.objects.len() + s.arrays.buffers.len())
}

/// Progress the watchdog reads: the running batch's seed and its calls run so far.
#[derive(Default)]
struct Progress {
    seed: AtomicU64,
    calls: AtomicU64,
}

/// Runs one batch of `n` calls from `seed` under the oracle, then checks the replay of its
/// recording. On failure: the message to report, with the seed, the call and the shortest
/// failing tail.
fn run_batch(seed: u64, n: usize, progress: &Progress, trace: bool) -> Result<BatchStats, String> {
    progress.seed.store(seed, Ordering::Relaxed);
    let mut driver = Driver::new(seed);
    let mut ctx = Context::new(SIDE, SIDE).expect("context");
    ctx.start_recording();
    let mut oracle = Oracle::new();
    let mut stats = BatchStats::default();
    // Every call run, in order: the failing tail comes from here.
    let mut run: Vec<Call> = Vec::with_capacity(n);
    let result = catch_unwind(AssertUnwindSafe(|| -> Result<(), String> {
        while run.len() < n {
            let mut call = driver.next_call();
            if oracle.compiling != 0 && oracle.body_len >= MAX_BODY {
                driver.queue.push_front(call);
                call = if ctx.inside_begin_end() {
                    Call::End
                } else {
                    Call::EndList
                };
            }
            if !oracle.allowed(&call) {
                continue;
            }
            if trace {
                eprintln!("soak trace: batch {seed:#x} call #{}: {call:?}", run.len());
            }
            run.push(call);
            let call = run.last().unwrap();
            let t0 = Instant::now();
            oracle.step(&mut ctx, call)?;
            stats.slowest = stats.slowest.max(t0.elapsed());
            progress.calls.fetch_add(1, Ordering::Relaxed);
            if driver.rng().percent(1) {
                // glReadPixels is a query, not a `Call`: probed here, not recorded.
                if let Err(message) = read_pixels_probe(&mut ctx, &mut driver.gen) {
                    return Err(format!("after call #{}: {message}", run.len() - 1));
                }
            }
            if object_names(&ctx) > MAX_NAMES {
                // Every call clones the state: a GenTextures(65536) would make the rest of the
                // batch slow, not more thorough.
                stats.ended_early = true;
                break;
            }
        }
        // Close what is open, so that the image is of finished primitives and lists.
        if ctx.inside_begin_end() {
            run.push(Call::End);
            oracle.step(&mut ctx, run.last().unwrap())?;
        }
        if oracle.compiling != 0 {
            run.push(Call::EndList);
            oracle.step(&mut ctx, run.last().unwrap())?;
        }
        Ok(())
    }));
    stats.calls = run.len() as u64;
    let failure = match result {
        Ok(Ok(())) => None,
        Ok(Err(message)) => Some((false, message)),
        Err(payload) => Some((true, panic_message(&payload))),
    };
    if let Some((panic, message)) = failure {
        let index = run.len() - 1;
        let tail = shortest_failing_tail(&run, panic);
        let mut text = Vec::new();
        write_recording(&tail, &mut text).ok();
        let path =
            std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("soak-{seed:016x}.txt"));
        std::fs::write(&path, &text).ok();
        let text = String::from_utf8_lossy(&text);
        let lines: Vec<&str> = text.lines().collect();
        let shown: Vec<String> = lines[lines.len().saturating_sub(40)..]
            .iter()
            .map(|l| l.chars().take(300).collect())
            .collect();
        return Err(format!(
            "soak: batch seed {seed:#x} (rerun: FIXEDGL_SOAK_BATCH={seed:#x}), call #{index}: \
             {call:?}\n  {message}\n  {k} calls reproduce it on a fresh {SIDE}x{SIDE} context, \
             saved as a recording in {path} (`fixedgl replay` reads it); the last of them:\n{shown}",
            call = run[index],
            k = tail.len(),
            path = path.display(),
            shown = shown.join("\n"),
        ));
    }
    check_replay(&mut ctx, seed)?;
    Ok(stats)
}

/// The recording of the batch just run on `ctx`, written and read back as text, replayed on a
/// fresh context: the same image and the same state.
fn check_replay(ctx: &mut Context, seed: u64) -> Result<(), String> {
    let calls = ctx.stop_recording();
    let fail = |what: String| {
        format!("soak: batch seed {seed:#x} (rerun: FIXEDGL_SOAK_BATCH={seed:#x}): {what}")
    };
    let mut text = Vec::new();
    write_recording(&calls, &mut text).map_err(|e| fail(format!("write_recording: {e}")))?;
    let read = read_recording(&text[..]).map_err(|e| fail(format!("read_recording: {e}")))?;
    if read.len() != calls.len() {
        return Err(fail(format!(
            "read back {} calls of {}",
            read.len(),
            calls.len()
        )));
    }
    for (i, (a, b)) in calls.iter().zip(&read).enumerate() {
        if a != b && format!("{a:?}") != format!("{b:?}") {
            return Err(fail(format!(
                "call #{i} read back as {b:?}, written as {a:?}"
            )));
        }
    }
    let mut replay = Context::new(SIDE, SIDE).expect("context");
    let replayed = catch_unwind(AssertUnwindSafe(|| {
        for call in &read {
            replay.execute(call);
        }
    }));
    if let Err(payload) = replayed {
        return Err(fail(format!("the replay {}", panic_message(&payload))));
    }
    if !same(ctx.state(), replay.state()) {
        return Err(fail("the replay's state differs".into()));
    }
    if ctx.to_image() != replay.to_image() {
        return Err(fail("the replay's image differs".into()));
    }
    Ok(())
}

/// Peak resident memory (VmHWM) in KiB, from /proc/self/status (0 where there is none).
fn peak_rss_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}

fn env_u64(name: &str) -> Option<u64> {
    let v = std::env::var(name).ok()?;
    let v = v.trim();
    let parsed = match v.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => v.parse(),
    };
    Some(parsed.unwrap_or_else(|_| panic!("{name}={v}: not a number")))
}

/// Runs `total` calls in batches from the base seed, failing with the first failure's report.
fn soak(total: u64, default_seed: u64) {
    let base = env_u64("FIXEDGL_SOAK_SEED").unwrap_or(default_seed);
    let total = env_u64("FIXEDGL_SOAK_CALLS").unwrap_or(total);
    let trace = std::env::var_os("FIXEDGL_SOAK_TRACE").is_some();
    let only = env_u64("FIXEDGL_SOAK_BATCH");
    let progress = Arc::new(Progress::default());
    let watched = Arc::clone(&progress);
    // The watchdog: a call that never returns fails the run instead of hanging CI.
    std::thread::spawn(move || {
        let mut last = u64::MAX;
        loop {
            std::thread::sleep(HANG_LIMIT);
            let now = watched.calls.load(Ordering::Relaxed);
            if now == last {
                eprintln!(
                    "soak: no progress for {HANG_LIMIT:?} in batch seed {seed:#x} after {now} calls; \
                     rerun with FIXEDGL_SOAK_BATCH={seed:#x} FIXEDGL_SOAK_TRACE=1 to see the call",
                    seed = watched.seed.load(Ordering::Relaxed)
                );
                std::process::exit(101);
            }
            last = now;
        }
    });
    let rss0 = peak_rss_kib();
    let t0 = Instant::now();
    let mut done = 0u64;
    let mut slowest = Duration::ZERO;
    let mut batch = 0u64;
    let mut ended_early = 0u64;
    while done < total {
        let seed = only.unwrap_or_else(|| batch_seed(base, batch));
        let n = (total - done).min(BATCH_CALLS as u64) as usize;
        let stats =
            run_batch(seed, n, &progress, trace).unwrap_or_else(|report| panic!("{report}"));
        done += stats.calls;
        slowest = slowest.max(stats.slowest);
        ended_early += u64::from(stats.ended_early);
        batch += 1;
        if only.is_some() {
            break;
        }
    }
    let secs = t0.elapsed().as_secs_f64();
    eprintln!(
        "soak: {done} calls in {batch} batches ({ended_early} ended early on object names; \
         base seed {base:#x}) in {secs:.1} s \
         ({:.0} calls/s), slowest call {slowest:?}, 0 panics; VmHWM {rss0} KiB at start, {} KiB at end",
        done as f64 / secs,
        peak_rss_kib()
    );
}

/// Every variant of `Call` is generated: the enumeration comes from serde, not from a list.
#[test]
fn generator_reaches_every_variant() {
    let mut gen = Gen::new(1);
    let names = gen.call_variants;
    assert!(names.len() > 250, "{} variants", names.len());
    let mut seen = vec![false; names.len()];
    for _ in 0..200_000 {
        let call = gen.any_call();
        let debug = format!("{call:?}");
        let name = debug.split(['(', ' ']).next().unwrap();
        seen[names.iter().position(|n| *n == name).unwrap()] = true;
    }
    let missing: Vec<_> = names.iter().zip(&seen).filter(|(_, s)| !**s).collect();
    assert!(missing.is_empty(), "never generated: {missing:?}");
}

/// CI: a million random calls (seconds in a release build with overflow checks).
#[test]
fn soak_ci() {
    soak(CI_CALLS, 0x5EED_0011);
}

/// Before a release: `cargo test --profile ci -- --ignored soak` (10 million calls).
#[test]
#[ignore = "10 million calls: run before a release"]
fn soak_10m() {
    soak(10_000_000, 0x5EED_1000);
}

/// Two contexts of one share group (GL appendix D), each on its own thread, run random calls
/// at once: display lists, textures and buffers made, changed, called and deleted by both.
/// Neither panics, hangs, or holds anything but a GL error code; names stay unique (the
/// transactions of context/share.rs), and lists calling each other's lists stop at the nesting
/// limit.
#[test]
fn shared_contexts_on_two_threads_survive_random_calls() {
    let calls: usize = std::env::var("FIXEDGL_SOAK_SHARED_CALLS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(200_000);
    let mut a = Context::new(SIDE, SIDE).expect("context");
    let group = a.share_group();
    let b = Context::with_config_shared(SIDE, SIDE, Default::default(), &group).expect("B");
    let run = move |mut ctx: Context, seed: u64| {
        let mut driver = Driver::new(seed);
        // The single-context soak's rule for list bodies (at most one list call each, see
        // `Oracle::allowed`): without it two lists that each call the other twice run 2^64
        // times through the nesting limit, on any driver.
        let mut bodies = Oracle::new();
        let mut i = 0;
        while i < calls {
            let call = driver.next_call();
            if !bodies.allowed(&call) {
                continue;
            }
            let compiled = bodies.compiling != 0 && !call.executes_immediately();
            let started = Instant::now();
            let r = catch_unwind(AssertUnwindSafe(|| ctx.execute(&call)));
            assert!(r.is_ok(), "seed {seed}, call {i}: {call:?} panicked");
            assert!(
                started.elapsed() < CALL_LIMIT * 5,
                "seed {seed}, call {i}: {call:?} took {:?}",
                started.elapsed()
            );
            bodies.follow(&mut ctx, &call, compiled);
            i += 1;
            let e = ctx.pending_error();
            assert!(CODES.contains(&e), "seed {seed}: error flag {e:#x}");
            if i % 64 == 0 {
                ctx.get_error();
            }
        }
        ctx.to_image();
    };
    // A hang shows as the test running past the harness's limit: each call is also timed.
    std::thread::scope(|s| {
        let ha = s.spawn(|| run(a, 0x5A5A_0001));
        let hb = s.spawn(|| run(b, 0x5A5A_0002));
        ha.join().expect("context A's thread");
        hb.join().expect("context B's thread");
    });
}
