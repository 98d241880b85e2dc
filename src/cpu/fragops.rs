//! The per-fragment operations past the colour: fog (GL 2.1 §3.10), the alpha test (§4.1.4), the
//! stencil test (§4.1.5), blending (§4.1.8) and the logical operation (§4.1.10), as pure
//! functions over one fragment, plus [`Ops`], their state for one flush.
//!
//! Naming: the per-flush forms of GL state blocks end in `Eval` ([`FogEval`] is `state::Fog`
//! ready for fragments, [`BlendEval`] is `state::Blend` in unorm8), so they never share a name
//! with the state they come from; see the `cpu` module docs.
//!
//! Design decision: where GL leaves the arithmetic open, it is llvmpipe's, because the project's
//! promise is agreement with that driver: the alpha test compares alpha and reference quantised
//! to unorm8 (the colour buffer's precision), and blending runs on unorm8 values, every
//! product `a·b/255` rounded to nearest, sums and differences saturating. [`Ops::new`] returns
//! `None` when none of these operations is enabled, so the fragment stage keeps its fast path
//! for the common case and chooses between the two once per span, never per pixel.

use glam::{Vec3, Vec4};

use super::framebuffer::unorm8;
use crate::gl;
use crate::state::{State, StencilFace, BACK, FRONT};

/// Fog (§3.10): the mode's parameters and colour.
#[derive(Clone, Copy, Debug)]
pub struct FogEval {
    /// LINEAR, EXP or EXP2.
    pub mode: u32,
    /// FOG_DENSITY.
    pub density: f32,
    /// FOG_START.
    pub start: f32,
    /// FOG_END.
    pub end: f32,
    /// FOG_COLOR (RGB; fog leaves alpha alone).
    pub color: Vec3,
}

impl FogEval {
    /// The fog factor f for fog coordinate `c`, clamped to [0, 1] (§3.10 eqs. 3.22–3.24).
    #[inline]
    pub fn factor(&self, c: f32) -> f32 {
        let f = match self.mode {
            // As Mesa's fog parameters: c·(−1/(e − s)) + e·(1/(e − s)).
            gl::LINEAR => {
                let scale = -1.0 / (self.end - self.start);
                c * scale + self.end * -scale
            }
            gl::EXP => (-self.density * c).exp(),
            _ => {
                let dc = self.density * c;
                (-dc * dc).exp()
            }
        };
        // NaN (END == START with c == END) counts as 0, as a saturating GPU min/max gives.
        if f.is_nan() {
            0.0
        } else {
            f.clamp(0.0, 1.0)
        }
    }

    /// The fogged colour: `f·C + (1 − f)·C_f` on RGB, alpha unchanged (§3.10 eq. 3.25).
    #[inline]
    pub fn apply(&self, c: Vec4, coord: f32) -> Vec4 {
        let f = self.factor(coord);
        // As llvmpipe's lerp: C_f + f·(C − C_f).
        let rgb = self.color + (c.truncate() - self.color) * f;
        rgb.extend(c.w)
    }
}

/// The stencil state of one face, with the reference already clamped (§4.1.5).
#[derive(Clone, Copy, Debug)]
pub struct StencilSide {
    /// STENCIL_FUNC.
    pub func: u32,
    /// Reference clamped to [0, 255].
    pub reference: u8,
    /// Value mask, low 8 bits.
    pub mask: u8,
    /// Operations on stencil fail, depth fail, depth pass.
    pub ops: [u32; 3],
    /// Write mask, low 8 bits.
    pub write: u8,
}

impl StencilSide {
    fn new(f: &StencilFace, write: u32) -> Self {
        Self {
            func: f.func,
            reference: f.reference.clamp(0, 255) as u8,
            mask: (f.value_mask & 0xFF) as u8,
            ops: [f.fail, f.zfail, f.zpass],
            write: (write & 0xFF) as u8,
        }
    }

    /// Does the stencil test pass against stored value `s`? (§4.1.5: `(ref & mask) op (s & mask)`.)
    #[inline]
    pub fn test(&self, s: u8) -> bool {
        compare(self.func, self.reference & self.mask, s & self.mask)
    }

    /// The stored value after operation `ops[which]` (0 stencil fail, 1 depth fail, 2 depth
    /// pass) on `s`, through the write mask (§4.1.5, §4.2.2).
    #[inline]
    pub fn update(&self, which: usize, s: u8) -> u8 {
        let op = self.ops.get(which).copied().unwrap_or(gl::KEEP);
        let v = stencil_op(op, s, self.reference);
        (s & !self.write) | (v & self.write)
    }
}

/// Blending (§4.1.8) with the constant colour already in unorm8.
#[derive(Clone, Copy, Debug)]
pub struct BlendEval {
    /// Source and destination factors for RGB and for alpha.
    pub src_rgb: u32,
    /// See `src_rgb`.
    pub dst_rgb: u32,
    /// See `src_rgb`.
    pub src_alpha: u32,
    /// See `src_rgb`.
    pub dst_alpha: u32,
    /// Equations for RGB and for alpha.
    pub eq_rgb: u32,
    /// See `eq_rgb`.
    pub eq_alpha: u32,
    /// BLEND_COLOR in unorm8.
    pub constant: [u8; 4],
}

/// What the colour write does with the fragment and the stored colour.
#[derive(Clone, Copy, Debug)]
pub enum ColorWrite {
    /// Replace (no blending, no logic op).
    Replace,
    /// Blend (§4.1.8).
    Blend(BlendEval),
    /// Logical operation (§4.1.10): takes precedence over blending.
    Logic(u32),
}

/// The per-fragment operations of one flush, when any is enabled.
#[derive(Clone, Copy, Debug)]
pub struct Ops {
    /// Fog, when FOG is enabled.
    pub fog: Option<FogEval>,
    /// Alpha test `(func, reference in unorm8)`, when ALPHA_TEST is enabled.
    pub alpha: Option<(u32, u8)>,
    /// Stencil `[front, back]`, when STENCIL_TEST is enabled.
    pub stencil: Option<[StencilSide; 2]>,
    /// The colour write.
    pub write: ColorWrite,
}

impl Ops {
    /// The operations `state` enables, or `None` when there are none (the fast path).
    pub fn new(state: &State) -> Option<Ops> {
        let e = &state.enables;
        // Without a stencil buffer the stencil test always passes and writes nothing (§4.1.5).
        let stencil_test = e.stencil_test && state.config.stencil;
        if !(e.fog || e.alpha_test || stencil_test || e.blend || e.color_logic_op) {
            return None;
        }
        let f = &state.fog;
        let fog = e.fog.then_some(FogEval {
            mode: f.mode,
            density: f.density,
            start: f.start,
            end: f.end,
            color: f.color.truncate(),
        });
        let alpha = e
            .alpha_test
            .then_some((state.alpha.func, unorm8(state.alpha.reference)));
        let s = &state.stencil;
        let stencil = stencil_test.then(|| {
            [
                StencilSide::new(&s.faces[FRONT], state.stencil_writemask),
                StencilSide::new(&s.faces[BACK], s.back_writemask),
            ]
        });
        let b = &state.blend;
        let write = if e.color_logic_op {
            ColorWrite::Logic(state.logic_op)
        } else if e.blend {
            let c = b.color;
            ColorWrite::Blend(BlendEval {
                src_rgb: b.src_rgb,
                dst_rgb: b.dst_rgb,
                src_alpha: b.src_alpha,
                dst_alpha: b.dst_alpha,
                eq_rgb: b.equation_rgb,
                eq_alpha: b.equation_alpha,
                constant: [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)],
            })
        } else {
            ColorWrite::Replace
        };
        Some(Ops {
            fog,
            alpha,
            stencil,
            write,
        })
    }
}

/// One of the eight comparison functions (§4.1.4–4.1.6): `a func b`.
#[inline]
pub fn compare<T: PartialOrd>(func: u32, a: T, b: T) -> bool {
    match func {
        gl::NEVER => false,
        gl::LESS => a < b,
        gl::EQUAL => a == b,
        gl::LEQUAL => a <= b,
        gl::GREATER => a > b,
        gl::NOTEQUAL => a != b,
        gl::GEQUAL => a >= b,
        _ => true,
    }
}

/// A stencil operation on the 8-bit value `s` (§4.1.5, table 4.1): INCR and DECR saturate at 0
/// and 255, the _WRAP forms wrap around.
#[inline]
pub fn stencil_op(op: u32, s: u8, reference: u8) -> u8 {
    match op {
        gl::ZERO => 0,
        gl::REPLACE => reference,
        gl::INCR => s.saturating_add(1),
        gl::DECR => s.saturating_sub(1),
        gl::INVERT => !s,
        gl::INCR_WRAP => s.wrapping_add(1),
        gl::DECR_WRAP => s.wrapping_sub(1),
        _ => s,
    }
}

/// `a·b/255` for unorm8 `a` and `b` as llvmpipe computes it (`lp_build_mul_norm`):
/// `(ab + (ab >> 8) + 128) >> 8`. It is the rounded quotient except for a few products just
/// above a half, which come out one lower (191·253/255 = 189.502 gives 189), measured against
/// the driver pixel for pixel.
#[inline(always)]
pub fn mul8(a: u8, b: u8) -> u8 {
    let x = u32::from(a) * u32::from(b);
    ((x + (x >> 8) + 128) >> 8) as u8
}

/// The blend factor `factor` for component `k` (0..3 RGB, 3 alpha) (§4.1.8, table 4.2), in
/// unorm8; `s`, `d` source and destination colours, `c` the constant colour.
#[inline]
pub fn factor(factor: u32, k: usize, s: [u8; 4], d: [u8; 4], c: [u8; 4]) -> u8 {
    let at = |v: [u8; 4], i: usize| v.get(i).copied().unwrap_or(0);
    match factor {
        gl::ZERO => 0,
        gl::ONE => 255,
        gl::SRC_COLOR => at(s, k),
        gl::ONE_MINUS_SRC_COLOR => 255 - at(s, k),
        gl::DST_COLOR => at(d, k),
        gl::ONE_MINUS_DST_COLOR => 255 - at(d, k),
        gl::SRC_ALPHA => s[3],
        gl::ONE_MINUS_SRC_ALPHA => 255 - s[3],
        gl::DST_ALPHA => d[3],
        gl::ONE_MINUS_DST_ALPHA => 255 - d[3],
        gl::CONSTANT_COLOR => at(c, k),
        gl::ONE_MINUS_CONSTANT_COLOR => 255 - at(c, k),
        gl::CONSTANT_ALPHA => c[3],
        gl::ONE_MINUS_CONSTANT_ALPHA => 255 - c[3],
        // SRC_ALPHA_SATURATE: min(As, 1 − Ad) for RGB, 1 for alpha.
        gl::SRC_ALPHA_SATURATE if k < 3 => s[3].min(255 - d[3]),
        _ => 255,
    }
}

/// One blend equation (§4.1.8, table 4.1) on unorm8 terms: `s`, `d` the colours, `sf`, `df` the
/// weighted terms (`s·S`, `d·D`). MIN and MAX ignore the factors.
#[inline]
pub fn equation(eq: u32, s: u8, d: u8, sf: u8, df: u8) -> u8 {
    match eq {
        gl::FUNC_SUBTRACT => sf.saturating_sub(df),
        gl::FUNC_REVERSE_SUBTRACT => df.saturating_sub(sf),
        gl::MIN => s.min(d),
        gl::MAX => s.max(d),
        _ => sf.saturating_add(df),
    }
}

impl BlendEval {
    /// The blended colour of source `s` over destination `d` (§4.1.8).
    #[inline]
    pub fn apply(&self, s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
        let mut out = [0u8; 4];
        for (k, o) in out.iter_mut().enumerate() {
            let (sfac, dfac, eq) = if k < 3 {
                (self.src_rgb, self.dst_rgb, self.eq_rgb)
            } else {
                (self.src_alpha, self.dst_alpha, self.eq_alpha)
            };
            let (sk, dk) = (s[k], d[k]);
            let sf = mul8(sk, factor(sfac, k, s, d, self.constant));
            let df = mul8(dk, factor(dfac, k, s, d, self.constant));
            *o = equation(eq, sk, dk, sf, df);
        }
        out
    }
}

/// A logical operation on source `s` and destination `d` (§4.1.10, table 4.3).
#[inline]
pub fn logic_op(op: u32, s: u8, d: u8) -> u8 {
    match op {
        gl::CLEAR => 0,
        gl::AND => s & d,
        gl::AND_REVERSE => s & !d,
        gl::COPY => s,
        gl::AND_INVERTED => !s & d,
        gl::NOOP => d,
        gl::XOR => s ^ d,
        gl::OR => s | d,
        gl::NOR => !(s | d),
        gl::EQUIV => !(s ^ d),
        gl::INVERT => !d,
        gl::OR_REVERSE => s | !d,
        gl::COPY_INVERTED => !s,
        gl::OR_INVERTED => !s | d,
        gl::NAND => !(s & d),
        _ => 255, // SET
    }
}
