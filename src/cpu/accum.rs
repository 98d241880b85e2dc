//! The accumulation buffer's arithmetic (GL 2.1 §4.2.4), exactly as Mesa's `main/accum.c`
//! computes it for llvmpipe's accumulation buffer (RGBA, 16 signed bits a channel, value v
//! standing for v / 32767).
//!
//! Design decision: every step is Mesa's C expression, float for float: the colour read as
//! c · (1/255) in single precision, products in single precision, each result converted to a
//! `GLshort` the way x86 compilers convert (truncation to a 32-bit integer, whose out-of-range
//! and NaN value is i32::MIN, then its low 16 bits), and sums wrapping in 16 bits. GL leaves
//! overflow undefined; Mesa neither clamps nor saturates, and neither does fixedgl. RETURN
//! converts with `unorm8` (Mesa's `float_to_ubyte`). Measured against Mesa's own glAccum on
//! llvmpipe through OSMesa, value for value (`tests/it/buffers.rs`). The GL backend's emulation
//! of the accumulation buffer uses these same functions.

use crate::gl;

use super::framebuffer::unorm8;

/// C's `(GLshort) f` on x86: truncation to i32 (i32::MIN when out of range or NaN, as
/// `cvttss2si` gives), then the low 16 bits.
#[inline]
pub fn to_short(f: f32) -> i16 {
    let i = if f.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&f) {
        i32::MIN
    } else {
        f as i32
    };
    i as i16
}

/// A colour byte as Mesa's unpack reads it: c · (1/255) in single precision.
#[inline]
fn unpack(c: u8) -> f32 {
    f32::from(c) * (1.0f32 / 255.0)
}

/// `ClearAccum`'s value for one channel (already clamped to [-1, 1]): Mesa's FLOAT_TO_SHORT,
/// ((GLint)(65535 · c) − 1) / 2 with C's truncating division.
pub fn clear_value(c: f32) -> i16 {
    let i = (65535.0f32 * c) as i32;
    ((i - 1) / 2) as i16
}

/// One accumulation operation on one pixel: `acc` the accumulation buffer's value, `color` the
/// read buffer's (LOAD, ACCUM); returns nothing: RETURN is `ret`. The per-pixel statement of
/// Mesa's arithmetic, which the tests hold [`apply_run`] to.
#[cfg(test)]
pub fn apply(op: u32, value: f32, acc: &mut [i16; 4], color: [u8; 4]) {
    match op {
        gl::LOAD => {
            let scale = value * 32767.0;
            for k in 0..4 {
                acc[k] = to_short(unpack(color[k]) * scale);
            }
        }
        gl::ACCUM => {
            let scale = value * 32767.0;
            for k in 0..4 {
                acc[k] = acc[k].wrapping_add(to_short(unpack(color[k]) * scale));
            }
        }
        gl::ADD => {
            let incr = to_short(value * 32767.0);
            for a in acc.iter_mut() {
                *a = a.wrapping_add(incr);
            }
        }
        gl::MULT => {
            for a in acc.iter_mut() {
                *a = to_short(f32::from(*a) * value);
            }
        }
        _ => {}
    }
}

/// RETURN's colour for accumulation value `acc`: acc · (value / 32767) to unorm8. The
/// per-pixel statement, which the tests hold [`return_run`] to.
#[cfg(test)]
pub fn ret(value: f32, acc: [i16; 4]) -> [u8; 4] {
    let scale = value / 32767.0;
    acc.map(|a| unorm8(f32::from(a) * scale))
}

/// `apply` over a run of pixels: `acc` the accumulation values, `color` their colour bytes
/// (four a pixel, as many as `acc` holds; read by LOAD and ACCUM only, so empty for ADD and
/// MULT). Each channel gets `apply`'s expression, but the operation is chosen once per run
/// ([`apply_groups`] is compiled once per operation) and the channels go eight at a time
/// through [`to_short_lanes`] (two pixels), the rest one by one.
pub fn apply_run(op: u32, value: f32, acc: &mut [[i16; 4]], color: &[u8]) {
    let acc = acc.as_flattened_mut();
    match op {
        gl::LOAD => apply_groups::<{ gl::LOAD }>(value, acc, color),
        gl::ACCUM => apply_groups::<{ gl::ACCUM }>(value, acc, color),
        gl::MULT => apply_groups::<{ gl::MULT }>(value, acc, &[]),
        gl::ADD => {
            let incr = to_short(value * 32767.0);
            for a in acc.iter_mut() {
                *a = a.wrapping_add(incr);
            }
        }
        _ => {}
    }
}

/// [`apply_run`] for LOAD, ACCUM or MULT (`OP`): a loop of its own for each, so that no
/// choice is left in the loop (with one loop for the three, the compiler's choice of what to
/// hoist moved with unrelated code: accum-motion-blur +4% instructions in one build).
#[inline(never)]
fn apply_groups<const OP: u32>(value: f32, acc: &mut [i16], color: &[u8]) {
    let scale = value * 32767.0;
    // Channel k's product: its value's (MULT) or its colour's (LOAD, ACCUM).
    let product = |a: i16, c: u8| -> f32 {
        match OP {
            gl::MULT => f32::from(a) * value,
            _ => unpack(c) * scale,
        }
    };
    let n = match OP {
        gl::MULT => acc.len(),
        _ => acc.len().min(color.len()),
    };
    let acc = &mut acc[..n];
    let mut groups = acc.chunks_exact_mut(8);
    let mut colors = color.get(..n).unwrap_or(&[]).chunks_exact(8);
    for a in groups.by_ref() {
        let c: [u8; 8] = match OP {
            gl::MULT => [0; 8],
            _ => match colors.next().and_then(|c| c.try_into().ok()) {
                Some(c) => c,
                None => return,
            },
        };
        let mut f = [0.0f32; 8];
        for ((f, &a), &c) in f.iter_mut().zip(a.iter()).zip(&c) {
            *f = product(a, c);
        }
        let s = to_short_lanes(f);
        for (a, s) in a.iter_mut().zip(s) {
            *a = match OP {
                gl::ACCUM => a.wrapping_add(s),
                _ => s,
            };
        }
    }
    let tail = colors.remainder();
    for (k, a) in groups.into_remainder().iter_mut().enumerate() {
        let s = to_short(product(*a, tail.get(k).copied().unwrap_or(0)));
        *a = match OP {
            gl::ACCUM => a.wrapping_add(s),
            _ => s,
        };
    }
}

/// [`to_short`] of eight values: on x86-64 SSE2's `cvttps2dq`, which is the conversion
/// `to_short` describes (i32::MIN when out of range or NaN), then the low 16 bits of each.
#[inline(always)]
fn to_short_lanes(f: [f32; 8]) -> [i16; 8] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128i, _mm_cvttps_epi32, _mm_loadu_ps, _mm_packs_epi32, _mm_slli_epi32,
            _mm_srai_epi32,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; `_mm_loadu_ps` reads four f32 from an
        // `[f32; 8]` at offsets 0 and 4 (in bounds, no alignment needed); `__m128i` has the
        // layout of `[i16; 8]` and every bit pattern is valid for both.
        unsafe {
            // Each i32's low 16 bits, sign-extended: the signed pack then keeps them exactly.
            let low = |v: __m128i| _mm_srai_epi32::<16>(_mm_slli_epi32::<16>(v));
            let lo = low(_mm_cvttps_epi32(_mm_loadu_ps(f.as_ptr())));
            let hi = low(_mm_cvttps_epi32(_mm_loadu_ps(f.as_ptr().add(4))));
            std::mem::transmute::<__m128i, [i16; 8]>(_mm_packs_epi32(lo, hi))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        f.map(to_short)
    }
}

/// `ret` over a run of pixels: each accumulation value's colour written into `dst` (four
/// bytes a pixel), the channels `mask` leaves off keeping their bytes.
pub fn return_run(value: f32, acc: &[[i16; 4]], dst: &mut [u8], mask: [bool; 4]) {
    let scale = value / 32767.0;
    let acc = acc.as_flattened();
    if mask == [true; 4] {
        for (d, &a) in dst.iter_mut().zip(acc) {
            *d = unorm8(f32::from(a) * scale);
        }
        return;
    }
    for (k, (d, &a)) in dst.iter_mut().zip(acc).enumerate() {
        if mask[k % 4] {
            *d = unorm8(f32::from(a) * scale);
        }
    }
}

/// Whether `op` reads the colour buffer (LOAD, ACCUM).
pub fn reads_color(op: u32) -> bool {
    op == gl::LOAD || op == gl::ACCUM
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_as_c_does_them() {
        assert_eq!(to_short(655.34), 655);
        assert_eq!(to_short(-655.9), -655);
        // 65534 fits an i32: its low 16 bits are -2 (Mesa wraps, measured on llvmpipe).
        assert_eq!(to_short(65534.0), -2);
        assert_eq!(to_short(3.0e13), 0);
        assert_eq!(to_short(f32::NAN), 0);
        assert_eq!(clear_value(0.25), 8191);
        assert_eq!(clear_value(-0.5), -16384);
        assert_eq!(clear_value(1.0), 32767);
        assert_eq!(clear_value(0.333), 10911);
    }

    /// `apply_run` and `return_run` give, value for value, what `apply` and `ret` give pixel
    /// by pixel: every operation, runs of every length mod 8 (the lanes and the tail), values
    /// that overflow 16 bits, NaN and infinite operands, every colour mask.
    #[test]
    fn runs_are_the_pixel_functions() {
        let mut seed = 0x2545_f491_u32;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let values = [
            0.0,
            0.25,
            1.0,
            -1.0,
            0.75,
            1.0 / 3.0,
            2.5,
            -7.0,
            1e6,
            -1e9,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MIN_POSITIVE,
        ];
        for len in [0usize, 1, 2, 3, 5, 8, 9, 15, 16, 17, 64] {
            let acc0: Vec<[i16; 4]> = (0..len).map(|_| [0; 4].map(|_| next() as i16)).collect();
            let color: Vec<u8> = (0..4 * len).map(|_| next() as u8).collect();
            for op in [gl::LOAD, gl::ACCUM, gl::ADD, gl::MULT] {
                for &v in &values {
                    let mut want = acc0.clone();
                    for (i, a) in want.iter_mut().enumerate() {
                        let c = [0, 1, 2, 3].map(|k| color[4 * i + k]);
                        apply(op, v, a, if reads_color(op) { c } else { [0; 4] });
                    }
                    let mut got = acc0.clone();
                    let c: &[u8] = if reads_color(op) { &color } else { &[] };
                    apply_run(op, v, &mut got, c);
                    assert_eq!(got, want, "op {op:#x} value {v} length {len}");
                }
            }
            for &v in &values {
                for mask in 0..16u8 {
                    let mask = [0, 1, 2, 3].map(|k| mask & (1 << k) != 0);
                    let mut want = color.clone();
                    for (i, a) in acc0.iter().enumerate() {
                        let px = ret(v, *a);
                        for k in 0..4 {
                            if mask[k] {
                                want[4 * i + k] = px[k];
                            }
                        }
                    }
                    let mut got = color.clone();
                    return_run(v, &acc0, &mut got, mask);
                    assert_eq!(got, want, "RETURN value {v} length {len} mask {mask:?}");
                }
            }
        }
    }

    #[test]
    fn load_and_return() {
        let mut acc = [0; 4];
        apply(gl::LOAD, 0.3, &mut acc, [17, 255, 0, 200]);
        assert_eq!(acc, [655, 9830, 0, 7709]);
        // Measured on llvmpipe: 5, 76, 0 and (alpha) 60.
        assert_eq!(ret(1.0, acc), [5, 76, 0, 60]);
        assert_eq!(ret(3.333_333_3, acc), [17, 255, 0, 200]);
    }
}
