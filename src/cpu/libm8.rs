//! glibc's `expf` and `powf` on eight lanes, bit for bit, where libm's functions are glibc's
//! FMA builds (`__expf_fma`, `__powf_fma`: the variants glibc's ifunc picks on CPUs with AVX2 and
//! FMA). Fog's EXP and EXP2 factors (`oplanes::exp_live`) call `expf` a fragment; lighting's
//! specular and spot terms (`vertex::Lighting`) call `powf` a vertex and light. One libm call
//! is ≈40–50 instructions and a call; these kernels do four lanes a register.
//!
//! Design decision: each kernel is the libm function's own algorithm (its tables, constants and
//! operations, and the fused multiply-adds its compiler chose, read off the machine code of the
//! build, in the same order), in double precision four lanes a register, so the bits are the
//! same wherever libm's function is that build. Whether it is, is checked once at run time
//! against libm (`usable`: thousands of arguments over the range); if not, or without AVX2 and
//! FMA, every lane goes to libm. Arguments outside a kernel's main range (libm's special cases)
//! are reported back and go to libm too. These are the only fused multiply-adds of the crate:
//! they reproduce libm, they do not replace a rounded product and sum of ours.

use std::sync::atomic::{AtomicU8, Ordering};

/// Eight float lanes.
pub type F8 = [f32; 8];

/// 2^(i/32) as doubles, their exponent bits taken out (glibc's `__exp2f_data.tab`).
const TAB: [u64; 32] = [
    0x3ff0000000000000,
    0x3fefd9b0d3158574,
    0x3fefb5586cf9890f,
    0x3fef9301d0125b51,
    0x3fef72b83c7d517b,
    0x3fef54873168b9aa,
    0x3fef387a6e756238,
    0x3fef1e9df51fdee1,
    0x3fef06fe0a31b715,
    0x3feef1a7373aa9cb,
    0x3feedea64c123422,
    0x3feece086061892d,
    0x3feebfdad5362a27,
    0x3feeb42b569d4f82,
    0x3feeab07dd485429,
    0x3feea47eb03a5585,
    0x3feea09e667f3bcd,
    0x3fee9f75e8ec5f74,
    0x3feea11473eb0187,
    0x3feea589994cce13,
    0x3feeace5422aa0db,
    0x3feeb737b0cdc5e5,
    0x3feec49182a3f090,
    0x3feed503b23e255d,
    0x3feee89f995ad3ad,
    0x3feeff76f2fb5e47,
    0x3fef199bdd85529c,
    0x3fef3720dcef9069,
    0x3fef5818dcfba487,
    0x3fef7c97337b9b5f,
    0x3fefa4afa2a490da,
    0x3fefd0765b6e4540,
];

/// A kernel's run-time check, made once: 0 not made yet, 1 the kernel is libm's function, 2 it
/// is not (or the CPU lacks AVX2 or FMA).
struct Checked(AtomicU8);

impl Checked {
    const fn new() -> Self {
        Checked(AtomicU8::new(0))
    }

    /// Whether the kernel may stand for libm: the CPU has AVX2 and FMA, and `check` (run once,
    /// only then) finds libm's bits.
    fn get(&self, check: fn() -> bool) -> bool {
        match self.0.load(Ordering::Relaxed) {
            1 => true,
            2 => false,
            _ => {
                let ok = cpu_has_avx2_fma() && check();
                self.0.store(if ok { 1 } else { 2 }, Ordering::Relaxed);
                ok
            }
        }
    }
}

#[cfg(target_arch = "x86_64")]
fn cpu_has_avx2_fma() -> bool {
    is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma")
}

#[cfg(not(target_arch = "x86_64"))]
fn cpu_has_avx2_fma() -> bool {
    false
}

/// The common end of `expf` and `powf` (glibc's `exp2_inline`): from x = k/32 + r (`ki` holding
/// k in its low bits, as the shift's addition left it), 2^(k/32) from `TAB` with k's exponent
/// bits added, times the polynomial `c` in r, `(c0·r + c1)·r² + (c2·r + 1)` fused as glibc's
/// build fuses it; rounded to float.
///
/// # Safety
/// Only inlined into functions compiled with AVX2 and FMA (`#[target_feature]`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn exp2_tail(
    r: std::arch::x86_64::__m256d,
    ki: std::arch::x86_64::__m256i,
    c: &[u64; 3],
) -> std::arch::x86_64::__m128 {
    use std::arch::x86_64::*;
    // SAFETY: AVX2 and FMA are present (the caller's promise); the gather's indices are
    // masked to 0..32, inside `TAB`.
    unsafe {
        let idx = _mm256_and_si256(ki, _mm256_set1_epi64x(31));
        let t = _mm256_i64gather_epi64::<8>(TAB.as_ptr().cast::<i64>(), idx);
        let s = _mm256_castsi256_pd(_mm256_add_epi64(t, _mm256_slli_epi64::<47>(ki)));
        let z = _mm256_fmadd_pd(
            r,
            _mm256_set1_pd(f64::from_bits(c[0])),
            _mm256_set1_pd(f64::from_bits(c[1])),
        );
        let r2 = _mm256_mul_pd(r, r);
        let y = _mm256_fmadd_pd(r, _mm256_set1_pd(f64::from_bits(c[2])), _mm256_set1_pd(1.0));
        let y = _mm256_fmadd_pd(z, r2, y);
        let y = _mm256_mul_pd(y, s);
        _mm256_cvtpd_ps(y)
    }
}

/// glibc's `expf` (`sysdeps/ieee754/flt-32/e_expf.c`, build `__expf_fma`): the compiler's
/// contractions in that build: `z = InvLn2N·x + SHIFT` fused, `r = InvLn2N·x − kd` fused,
/// both polynomial steps fused. Lanes outside the main range (|x| ≥ 85.33, infinities, NaN)
/// are left to libm.
pub mod expf {
    use super::{Checked, F8};

    /// 32/ln 2.
    #[cfg(target_arch = "x86_64")]
    const INV_LN2_N: u64 = 0x40471547652b82fe;
    /// 1.5·2^52: adding it rounds to an integer in the low bits.
    #[cfg(target_arch = "x86_64")]
    const SHIFT: u64 = 0x4338000000000000;
    /// The polynomial's coefficients (`__exp2f_data.poly_scaled`).
    #[cfg(target_arch = "x86_64")]
    const C: [u64; 3] = [0x3ebc6af84b912394, 0x3f2ebfce50fac4f3, 0x3f962e42ff0c52d6];

    static CHECKED: Checked = Checked::new();

    /// Whether `expf8` may stand for libm's `expf`: the CPU has AVX2 and FMA, and the kernel
    /// gives `f32::exp`'s bits on 4096 arguments spread over its range (checked once).
    pub fn usable() -> bool {
        CHECKED.get(self_check)
    }

    #[cfg(target_arch = "x86_64")]
    fn self_check() -> bool {
        let mut x = 0x9E37_79B9u32;
        (0..512).all(|i| {
            let a: F8 = std::array::from_fn(|l| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                // Every eighth lane evenly over the range, the others any main-range bits.
                if l == 0 {
                    -87.0 + 174.0 * i as f32 / 512.0
                } else {
                    f32::from_bits(x & 0xC2AF_FFFF)
                }
            });
            let mut out = [0.0; 8];
            // SAFETY: called only after AVX2 and FMA were detected (`Checked::get`).
            let left = unsafe { expf8(&a, &mut out) };
            (0..8).all(|l| left & (1 << l) != 0 || out[l].to_bits() == a[l].exp().to_bits())
        })
    }

    #[cfg(not(target_arch = "x86_64"))]
    fn self_check() -> bool {
        false
    }

    /// `expf` of every lane in the main range into `out`; returns the mask of the lanes left
    /// to libm (|x| ≥ 85.33, ±∞, NaN), whose `out` is unspecified.
    ///
    /// # Safety
    /// The CPU must have AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    pub unsafe fn expf8(x: &F8, out: &mut F8) -> u8 {
        use std::arch::x86_64::*;
        let mut special = 0u8;
        for (h, (xs, os)) in x.chunks_exact(4).zip(out.chunks_exact_mut(4)).enumerate() {
            // SAFETY: AVX2 and FMA are present (the caller's promise); the loads and stores
            // touch four f32 of a four-element chunk.
            unsafe {
                let xf = _mm_loadu_ps(xs.as_ptr());
                // abstop12(x) > abstop12(85.33…): glibc's test for its special cases.
                let top = _mm_and_si128(
                    _mm_srli_epi32(_mm_castps_si128(xf), 20),
                    _mm_set1_epi32(0x7ff),
                );
                let big = _mm_cmpgt_epi32(top, _mm_set1_epi32(0x42a));
                special |= (_mm_movemask_ps(_mm_castsi128_ps(big)) as u8) << (4 * h);
                let xd = _mm256_cvtps_pd(xf);
                let inv = _mm256_set1_pd(f64::from_bits(INV_LN2_N));
                let shift = _mm256_set1_pd(f64::from_bits(SHIFT));
                let kz = _mm256_fmadd_pd(inv, xd, shift);
                let ki = _mm256_castpd_si256(kz);
                let kd = _mm256_sub_pd(kz, shift);
                let r = _mm256_fmsub_pd(inv, xd, kd);
                _mm_storeu_ps(os.as_mut_ptr(), super::exp2_tail(r, ki, &C));
            }
        }
        special
    }
}

/// glibc's `powf` (`sysdeps/ieee754/flt-32/e_powf.c`, build `__powf_fma`) for a positive
/// normal base: log2 of x from a 16-entry table and a degree-5 polynomial, times y, then
/// `exp2_tail` with the unscaled polynomial. The build's contractions, read off its code:
/// `r = z·invc − 1`, the polynomial's `A0·r + A1`, `A2·r + A3`, `A4·r + y0`, `p·r² + q` and
/// `y·r⁴ + q` fused; `k + logc`, `r²`, `r⁴` and `y·log2 x` rounded alone; in the tail
/// `ylogx + SHIFT` and `ylogx − kd` rounded alone.
pub mod powf {
    use super::{Checked, F8};

    /// `__powf_log2_data.tab`'s `invc`, entry by entry.
    #[cfg(target_arch = "x86_64")]
    const INVC: [u64; 16] = [
        0x3ff661ec79f8f3be,
        0x3ff571ed4aaf883d,
        0x3ff49539f0f010b0,
        0x3ff3c995b0b80385,
        0x3ff30d190c8864a5,
        0x3ff25e227b0b8ea0,
        0x3ff1bb4a4a1a343f,
        0x3ff12358f08ae5ba,
        0x3ff0953f419900a7,
        0x3ff0000000000000,
        0x3fee608cfd9a47ac,
        0x3feca4b31f026aa0,
        0x3feb2036576afce6,
        0x3fe9c2d163a1aa2d,
        0x3fe886e6037841ed,
        0x3fe767dcf5534862,
    ];
    /// `__powf_log2_data.tab`'s `logc` (log2 of 1/invc).
    #[cfg(target_arch = "x86_64")]
    const LOGC: [u64; 16] = [
        0xbfdefec65b963019,
        0xbfdb0b6832d4fca4,
        0xbfd7418b0a1fb77b,
        0xbfd39de91a6dcf7b,
        0xbfd01d9bf3f2b631,
        0xbfc97c1d1b3b7af0,
        0xbfc2f9e393af3c9f,
        0xbfb960cbbf788d5c,
        0xbfaa6f9db6475fce,
        0x0000000000000000,
        0x3fb338ca9f24f53d,
        0x3fc476a9543891ba,
        0x3fce840b4ac4e4d2,
        0x3fd40645f0c6651c,
        0x3fd88e9c2c1b9ff8,
        0x3fdce0a44eb17bcc,
    ];
    /// `__powf_log2_data.poly`: log1p(r)/ln 2 ≈ A0·r⁵ + A1·r⁴ + A2·r³ + A3·r² + A4·r.
    #[cfg(target_arch = "x86_64")]
    const A: [u64; 5] = [
        0x3fd27616c9496e0b,
        0xbfd71969a075c67a,
        0x3fdec70a6ca7badd,
        0xbfe7154748bef6c8,
        0x3ff71547652ab82b,
    ];
    /// `__exp2f_data.shift_scaled`: 1.5·2^52/32.
    #[cfg(target_arch = "x86_64")]
    const SHIFT: u64 = 0x42e8000000000000;
    /// `__exp2f_data.poly` (unscaled).
    #[cfg(target_arch = "x86_64")]
    const C: [u64; 3] = [0x3fac6af84b912394, 0x3fcebfce50fac4f3, 0x3fe62e42ff0c52d6];

    static CHECKED: Checked = Checked::new();

    /// Whether `powf8` may stand for libm's `powf`: the CPU has AVX2 and FMA, and the kernel
    /// gives `f32::powf`'s bits on 4096 pairs (bases over (0, 1] and beyond, the exponents
    /// lighting uses and others; checked once).
    pub fn usable() -> bool {
        CHECKED.get(self_check)
    }

    #[cfg(target_arch = "x86_64")]
    fn self_check() -> bool {
        let mut g = 0x9E37_79B9u32;
        let mut next = move || {
            g ^= g << 13;
            g ^= g >> 17;
            g ^= g << 5;
            g
        };
        (0..512).all(|i| {
            let y = match i % 4 {
                0 => 1.0 + (i / 4) as f32,
                1 => (next() % 12_800) as f32 * 0.01,
                _ => f32::from_bits(next() & 0x437F_FFFF),
            };
            let a: F8 = std::array::from_fn(|l| {
                let b = next();
                if l == 0 {
                    (i as f32 + 0.5) / 512.0
                } else {
                    f32::from_bits(b & 0x3FFF_FFFF)
                }
            });
            let mut out = [0.0; 8];
            // SAFETY: called only after AVX2 and FMA were detected (`Checked::get`).
            let left = unsafe { powf8(&a, y, &mut out) };
            (0..8).all(|l| left & (1 << l) != 0 || out[l].to_bits() == a[l].powf(y).to_bits())
        })
    }

    #[cfg(not(target_arch = "x86_64"))]
    fn self_check() -> bool {
        false
    }

    /// `powf(x[l], y)` of every lane whose base is a positive normal float and whose result is
    /// in the main range (|y·log2 x| < 126) into `out`; returns the mask of the lanes left to
    /// libm (every lane when y is 0, infinite or NaN), whose `out` is unspecified.
    ///
    /// # Safety
    /// The CPU must have AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    pub unsafe fn powf8(x: &F8, y: f32, out: &mut F8) -> u8 {
        use std::arch::x86_64::*;
        // zeroinfnan(y): 2·iy − 1 ≥ 2·0x7f800000 − 1 (unsigned).
        if y.to_bits().wrapping_mul(2).wrapping_sub(1) >= 0xfeff_ffff {
            return 0xff;
        }
        let mut special = 0u8;
        for (h, (xs, os)) in x.chunks_exact(4).zip(out.chunks_exact_mut(4)).enumerate() {
            // SAFETY: AVX2 and FMA are present (the caller's promise); the loads and stores
            // touch four f32 of a four-element chunk; the gathers' indices are masked to 0..16,
            // inside `INVC` and `LOGC`.
            unsafe {
                let ix = _mm_loadu_si128(xs.as_ptr().cast());
                // ix − 0x00800000 ≥ 0x7f800000 − 0x00800000 (unsigned): not a positive normal
                // float; compared signed with the sign bits flipped.
                let flip = _mm_set1_epi32(i32::MIN);
                let off = _mm_xor_si128(_mm_sub_epi32(ix, _mm_set1_epi32(0x0080_0000)), flip);
                let bad =
                    _mm_cmpgt_epi32(off, _mm_set1_epi32((0x7eff_ffff_u32 ^ 0x8000_0000) as i32));
                special |= (_mm_movemask_ps(_mm_castsi128_ps(bad)) as u8) << (4 * h);
                // x = 2^k·z with z in [OFF, 2·OFF), the table entry i from z's top bits.
                let tmp = _mm_sub_epi32(ix, _mm_set1_epi32(0x3f33_0000));
                let i = _mm_and_si128(_mm_srli_epi32::<19>(tmp), _mm_set1_epi32(15));
                let top = _mm_and_si128(tmp, _mm_set1_epi32(0xff80_0000_u32 as i32));
                let iz = _mm_sub_epi32(ix, top);
                let k = _mm_srai_epi32::<23>(top);
                let z = _mm256_cvtps_pd(_mm_castsi128_ps(iz));
                let invc = _mm256_i32gather_pd::<8>(INVC.as_ptr().cast::<f64>(), i);
                let logc = _mm256_i32gather_pd::<8>(LOGC.as_ptr().cast::<f64>(), i);
                let a = |j: usize| _mm256_set1_pd(f64::from_bits(A[j]));
                let r = _mm256_fmadd_pd(z, invc, _mm256_set1_pd(-1.0));
                let y0 = _mm256_add_pd(_mm256_cvtepi32_pd(k), logc);
                let r2 = _mm256_mul_pd(r, r);
                let p0 = _mm256_fmadd_pd(r, a(0), a(1));
                let p = _mm256_fmadd_pd(r, a(2), a(3));
                let r4 = _mm256_mul_pd(r2, r2);
                let q = _mm256_fmadd_pd(r, a(4), y0);
                let q = _mm256_fmadd_pd(r2, p, q);
                let logx = _mm256_fmadd_pd(p0, r4, q);
                let ylogx = _mm256_mul_pd(_mm256_set1_pd(f64::from(y)), logx);
                // |y·log2 x| ≥ 126 (glibc's test on bits 47..62): under- or overflow handling.
                let e = _mm256_and_si256(
                    _mm256_srli_epi64::<47>(_mm256_castpd_si256(ylogx)),
                    _mm256_set1_epi64x(0xffff),
                );
                let big = _mm256_cmpgt_epi64(e, _mm256_set1_epi64x(0x80be));
                special |= (_mm256_movemask_pd(_mm256_castsi256_pd(big)) as u8) << (4 * h);
                let shift = _mm256_set1_pd(f64::from_bits(SHIFT));
                let kz = _mm256_add_pd(ylogx, shift);
                let ki = _mm256_castpd_si256(kz);
                let kd = _mm256_sub_pd(kz, shift);
                let r = _mm256_sub_pd(ylogx, kd);
                _mm_storeu_ps(os.as_mut_ptr(), super::exp2_tail(r, ki, &C));
            }
        }
        special
    }
}

/// `x[i].powf(y)` into `out[i]` for each lane i whose bit is set in `need`; the other lanes of
/// `out` keep their values. Groups of eight lanes with a lane to compute go through
/// `powf::powf8` where it stands for libm, the lanes it leaves (and every lane elsewhere)
/// through libm. A function of its own so that the caller's vector registers are not spilled
/// around each libm call.
#[inline(never)]
pub fn powf_lanes<const N: usize>(x: &[f32; N], y: f32, need: u32, out: &mut [f32; N]) {
    let mut rest = need;
    #[cfg(target_arch = "x86_64")]
    if N % 8 == 0 && need != 0 && powf::usable() {
        for (c, (xs, os)) in x.chunks_exact(8).zip(out.chunks_exact_mut(8)).enumerate() {
            let m = need.checked_shr(8 * c as u32).unwrap_or(0) as u8;
            let (Ok(xs), false) = (<&F8>::try_from(xs), m == 0) else {
                continue;
            };
            let mut o = [0.0; 8];
            // SAFETY: `usable` is true only where the CPU has AVX2 and FMA.
            let left = unsafe { powf::powf8(xs, y, &mut o) };
            let done = m & !left;
            for (l, (d, v)) in os.iter_mut().zip(o).enumerate() {
                if done & (1 << l) != 0 {
                    *d = v;
                }
            }
            rest &= !u32::from(done).checked_shl(8 * c as u32).unwrap_or(0);
        }
    }
    while rest != 0 {
        let l = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        if let (Some(o), Some(a)) = (out.get_mut(l), x.get(l)) {
            *o = a.powf(y);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift
    struct Gen(u32);
    impl Gen {
        fn next(&mut self) -> u32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 17;
            self.0 ^= self.0 << 5;
            self.0
        }
    }

    /// `powf_lanes` against `f32::powf` bit for bit: bases of any bits (NaN, ±∞, zeros,
    /// denormals, negative, above 1) and the (0, 1] cosines lighting gives, exponents lighting
    /// uses (0..128, integers and not) and any bits; random lane masks. Untouched lanes keep
    /// their values. Where `powf8` is usable it is also checked on its own: the lanes it keeps
    /// are libm's bits and it leaves exactly the lanes outside its main range.
    #[test]
    fn powf_lanes_is_libm_powf_bit_for_bit() {
        let mut g = Gen(23);
        let usable = powf::usable();
        for round in 0..40_000 {
            let y = match g.next() % 5 {
                0 => (g.next() % 129) as f32,
                1 => (g.next() % 12_800) as f32 * 0.01,
                2 => f32::from_bits(g.next()),
                3 => [0.0, -0.0, 1.0, 0.5, f32::INFINITY, f32::NAN, -3.0][(g.next() % 7) as usize],
                _ => f32::from_bits(g.next() & 0x437F_FFFF),
            };
            let x: [f32; 16] = std::array::from_fn(|_| match g.next() % 4 {
                0 => f32::from_bits(g.next()),
                1 => f32::from_bits(g.next() & 0x3F7F_FFFF),
                2 => (g.next() % 1_000_001) as f32 / 1_000_000.0,
                _ => [0.0, 1.0, -0.0, 1e-40, f32::MIN_POSITIVE][(g.next() % 5) as usize],
            });
            let need = if round % 3 == 0 {
                0xFFFF
            } else {
                g.next() & 0xFFFF
            };
            let mut out = [7.0f32; 16];
            powf_lanes(&x, y, need, &mut out);
            for l in 0..16 {
                let want = if need & (1 << l) != 0 {
                    x[l].powf(y)
                } else {
                    7.0
                };
                assert_eq!(out[l].to_bits(), want.to_bits(), "{}^{} lane {l}", x[l], y);
            }
            #[cfg(target_arch = "x86_64")]
            if usable {
                let x8: F8 = std::array::from_fn(|l| x[l]);
                let mut o = [0.0; 8];
                // SAFETY: `usable` says AVX2 and FMA are present.
                let left = unsafe { powf::powf8(&x8, y, &mut o) };
                for l in 0..8 {
                    if left & (1 << l) == 0 {
                        assert_eq!(o[l].to_bits(), x8[l].powf(y).to_bits(), "{}^{}", x8[l], y);
                        assert!(x8[l] > 0.0 && x8[l].is_normal(), "{} kept", x8[l]);
                    }
                }
            }
        }
    }

    /// Normal bases over (0, 1] (runs of eight consecutive floats, one run every 776 bit
    /// patterns: 10.9 million bases an exponent) with the exponents shininess and spot
    /// exponents take (the integers 1..128 and a few fractions) against libm; about 20 s in
    /// release: `cargo test --release -p fixedgl --lib powf8_cosines -- --ignored`.
    #[cfg(target_arch = "x86_64")]
    #[test]
    #[ignore]
    fn powf8_cosines_are_libm_powf() {
        if !powf::usable() {
            return;
        }
        let mut bad = 0u64;
        for y in (1..=128)
            .map(|n| n as f32)
            .chain([0.5, 2.5, 7.3, 12.8, 50.25, 100.0])
        {
            let mut b = 0x0080_0000u32;
            while b <= 0x3F80_0000 {
                let a: F8 = std::array::from_fn(|l| f32::from_bits(b + l as u32));
                let mut out = [0.0; 8];
                // SAFETY: `usable` says AVX2 and FMA are present.
                let left = unsafe { powf::powf8(&a, y, &mut out) };
                for l in 0..8 {
                    if left & (1 << l) == 0 && out[l].to_bits() != a[l].powf(y).to_bits() {
                        bad += 1;
                    }
                }
                b += 8 * 97;
            }
        }
        assert_eq!(bad, 0);
    }
}
