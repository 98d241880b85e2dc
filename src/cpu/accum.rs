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
/// read buffer's (LOAD, ACCUM); returns nothing: RETURN is [`ret`].
#[inline]
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

/// RETURN's colour for accumulation value `acc`: acc · (value / 32767) to unorm8.
#[inline]
pub fn ret(value: f32, acc: [i16; 4]) -> [u8; 4] {
    let scale = value / 32767.0;
    acc.map(|a| unorm8(f32::from(a) * scale))
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
