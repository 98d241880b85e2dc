//! GLU 1.3 §3's image helpers, byte for byte as Mesa's libGLU 9.0 computes them
//! (`tests/it/glu_mipmap.rs` holds every one against the real libGLU on llvmpipe):
//!
//! - `scale_image` (`gluScaleImage`) takes any format and any GL 1.2 type libGLU takes (BITMAP,
//!   BYTE .. FLOAT and the twelve packed types) in and out: the image is unpacked under the
//!   UNPACK_ modes to 16-bit components (libGLU's `fill_image`: UNSIGNED_BYTE × 257, BYTE × 516,
//!   SHORT × 2, UNSIGNED_INT >> 16, INT >> 15, FLOAT × 65535, packed fields scaled to 65535,
//!   bits to 0 or 65535; colour indices kept), box-filtered with single-precision coverage
//!   weights (`scale_internal`; an exact halving is a 2x2 average rounded `(a + b + c + d +
//!   2) / 4`) and packed back under the PACK_ modes (`empty_image`);
//! - `build_1d_mipmaps` / `build_1d_mipmap_levels` go through the same 16-bit image and upload
//!   every level as UNSIGNED_SHORT with UNPACK_ALIGNMENT 2, as libGLU does;
//! - `build_2d_mipmaps` / `build_2d_mipmap_levels` work in the caller's own type: libGLU's
//!   per-type filters (`scale_internal_<type>` with its drifting edge weights,
//!   `halveImage_<type>` with integer rounding for the 8- and 16-bit types, double or float
//!   sums for the 32-bit ones, the packed types through float components), BITMAP through the
//!   16-bit path; sizes from libGLU's `closestFit`, which asks the driver through
//!   PROXY_TEXTURE_1D/2D/CUBE_MAP whether level 1 fits and halves until it does;
//! - `build_3d_mipmaps` / `build_3d_mipmap_levels` (`three_d.rs`) likewise in the caller's
//!   type, with libGLU's 3D filters and `gluScaleImage3D`, sized through PROXY_TEXTURE_3D.

use crate::{gl, Context};

use super::{GLU_INVALID_ENUM, GLU_INVALID_OPERATION, GLU_INVALID_VALUE};

// gluBuild3DMipmaps[Levels] (glu/mipmap/three_d.rs), on this file's machinery.
mod three_d;
pub use three_d::{build_3d_mipmap_levels, build_3d_mipmaps};

fn is_index(format: u32) -> bool {
    format == gl::COLOR_INDEX || format == gl::STENCIL_INDEX
}

/// libGLU's `legalFormat`.
fn legal_format(format: u32) -> bool {
    matches!(
        format,
        gl::COLOR_INDEX
            | gl::STENCIL_INDEX
            | gl::DEPTH_COMPONENT
            | gl::RED
            | gl::GREEN
            | gl::BLUE
            | gl::ALPHA
            | gl::RGB
            | gl::RGBA
            | gl::LUMINANCE
            | gl::LUMINANCE_ALPHA
            | gl::BGR
            | gl::BGRA
    )
}

/// libGLU's `legalType`: BITMAP, the six integer types, FLOAT and the packed types.
fn legal_type(t: u32) -> bool {
    t == gl::BITMAP || elem_of(t).is_some() || packed_of(t).is_some()
}

/// libGLU's `isLegalFormatForPackedPixelType`: 3_3_2 and 5_6_5 (and REVs) want RGB, the
/// four-component packed types RGBA or BGRA.
fn legal_format_for_type(format: u32, t: u32) -> bool {
    match packed_of(t) {
        None => true,
        Some(p) if p.comps == 3 => format == gl::RGB,
        Some(_) => format == gl::RGBA || format == gl::BGRA,
    }
}

/// libGLU's `checkMipmapArgs`.
fn check_mipmap_args(format: u32, t: u32) -> i32 {
    if !legal_format(format) || !legal_type(t) || format == gl::STENCIL_INDEX {
        return GLU_INVALID_ENUM;
    }
    if !legal_format_for_type(format, t) {
        return GLU_INVALID_OPERATION;
    }
    0
}

/// Components of `format` ignoring the type (`elements_per_group(format, 0)`).
fn format_comps(format: u32) -> usize {
    match format {
        gl::RGB | gl::BGR => 3,
        gl::LUMINANCE_ALPHA => 2,
        gl::RGBA | gl::BGRA => 4,
        _ => 1,
    }
}

/// libGLU's `elements_per_group`: 1 for a packed type.
fn elements_per_group(format: u32, t: u32) -> usize {
    if packed_of(t).is_some() {
        1
    } else {
        format_comps(format)
    }
}

/// libGLU's `nearestPower`: the power of two nearest `value` (a value 3·2ⁿ goes up).
fn nearest_power(value: u32) -> i32 {
    let mut i = 1i32;
    let mut v = value;
    if v == 0 {
        return -1;
    }
    loop {
        if v == 1 {
            return i;
        } else if v == 3 {
            return i.saturating_mul(4);
        }
        v >>= 1;
        i = i.saturating_mul(2);
    }
}

/// libGLU's `computeLog`: log2 of a power of two, -1 for anything else.
fn compute_log(value: i32) -> i32 {
    if value <= 0 || value & (value - 1) != 0 {
        return -1;
    }
    value.trailing_zeros() as i32
}

/// C's float-to-int conversion as x86-64 performs it: truncation, and INT_MIN (the
/// "indefinite" result) for NaN or a value out of range.
fn c_i32(x: f64) -> i32 {
    if x.is_nan() || x >= 2_147_483_648.0 || x <= -2_147_483_649.0 {
        i32::MIN
    } else {
        x as i32
    }
}

/// The six integer types and FLOAT, as libGLU's per-type filters take them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Elem {
    UByte,
    Byte,
    UShort,
    Short,
    UInt,
    Int,
    Float,
}

fn elem_of(t: u32) -> Option<Elem> {
    Some(match t {
        gl::UNSIGNED_BYTE => Elem::UByte,
        gl::BYTE => Elem::Byte,
        gl::UNSIGNED_SHORT => Elem::UShort,
        gl::SHORT => Elem::Short,
        gl::UNSIGNED_INT => Elem::UInt,
        gl::INT => Elem::Int,
        gl::FLOAT => Elem::Float,
        _ => return None,
    })
}

impl Elem {
    fn size(self) -> usize {
        match self {
            Elem::UByte | Elem::Byte => 1,
            Elem::UShort | Elem::Short => 2,
            _ => 4,
        }
    }
}

/// One field of a packed type: mask, shift, maximum; `dbl`: libGLU's shove multiplies in
/// double (`* 7.0`) rather than float (`* 7`).
#[derive(Clone, Copy)]
struct Field(u32, u32, u32);

/// A GL 1.2 packed type as libGLU's extract/shove routines read and write it.
#[derive(Clone, Copy)]
struct Packed {
    size: usize,
    comps: usize,
    fields: [Field; 4],
    dbl: bool,
}

/// The packed type `t` as libGLU reads it: the field layout of GL 1.2 table 3.8, which
/// `src/pixels.rs` holds for every pixel command (`Ty::of`), each field as mask, shift and
/// maximum; libGLU's shove multiplies in double for 2_3_3_REV and 5_6_5_REV only.
/// UNSIGNED_INT_24_8 (GL_EXT_packed_depth_stencil) is no type of libGLU's.
fn packed_of(t: u32) -> Option<Packed> {
    let Some(crate::pixels::Ty::Packed { size, fields }) = crate::pixels::Ty::of(t) else {
        return None;
    };
    if t == gl::UNSIGNED_INT_24_8 {
        return None;
    }
    let mut f = [Field(0, 0, 1); 4];
    for (o, &(shift, bits)) in f.iter_mut().zip(fields) {
        let max = (1u32 << bits) - 1;
        *o = Field(max << shift, shift, max);
    }
    Some(Packed {
        size,
        comps: fields.len(),
        fields: f,
        dbl: matches!(
            t,
            gl::UNSIGNED_BYTE_2_3_3_REV | gl::UNSIGNED_SHORT_5_6_5_REV
        ),
    })
}

/// `n` bytes of `d` at `at` as a little-endian integer (reversed with `swap`); bytes outside
/// `d` read as 0 (where libGLU's filters read past their image with a zero weight).
fn rd(d: &[u8], at: isize, n: usize, swap: bool) -> u32 {
    let mut v = 0u32;
    for i in 0..n {
        let b = if at < 0 {
            0
        } else {
            d.get(at as usize + i).copied().unwrap_or(0)
        };
        let sh = if swap { n - 1 - i } else { i };
        v |= u32::from(b) << (8 * sh);
    }
    v
}

impl Packed {
    /// libGLU's `extract*`: each field over its maximum, divided in double, kept as float.
    /// Their SWAP_BYTES reading (`__GLU_SWAP_2_BYTES`/`_4_BYTES`, which assemble the bytes
    /// little-endian) is the native order on the little-endian machines libGLU runs on here,
    /// so it swaps nothing, and neither does this.
    fn extract(&self, d: &[u8], at: isize) -> [f32; 4] {
        let v = rd(d, at, self.size, false);
        let mut out = [0f32; 4];
        for (o, f) in out.iter_mut().zip(&self.fields).take(self.comps) {
            *o = (f64::from((v & f.0) >> f.1) / f64::from(f.2)) as f32;
        }
        out
    }

    /// libGLU's `shove*`: each component times its maximum (float or double) plus 0.5,
    /// truncated, shifted and masked.
    fn shove(&self, c: &[f32; 4]) -> u32 {
        let mut v = 0u32;
        for (x, f) in c.iter().zip(&self.fields).take(self.comps) {
            let m = if self.dbl {
                f64::from(*x) * f64::from(f.2)
            } else {
                f64::from(*x * f.2 as f32)
            };
            v |= ((m + 0.5) as u32) << f.1 & f.0;
        }
        v
    }

    fn put(&self, out: &mut Vec<u8>, v: u32) {
        out.extend_from_slice(&v.to_le_bytes()[..self.size]);
    }
}

/// libGLU's addressing of a client image (`fill_image`/`empty_image`, the 2D core): row
/// stride, first byte, and the bytes it touches, with checked arithmetic (None: no slice is
/// that long).
struct Place {
    rowsize: usize,
    start: usize,
    need: usize,
    /// BITMAP: the first bit's offset within its byte.
    bit0: usize,
}

#[allow(clippy::too_many_arguments)]
fn place(
    row_length: i32,
    alignment: i32,
    skip_rows: i32,
    skip_pixels: i32,
    width: i32,
    height: i32,
    format: u32,
    t: u32,
) -> Option<Place> {
    let comps = elements_per_group(format, t) as u64;
    let gpl = u64::try_from(if row_length > 0 { row_length } else { width }).ok()?;
    let (w, h) = (u64::try_from(width).ok()?, u64::try_from(height).ok()?);
    let (sr, sp) = (
        u64::try_from(skip_rows).ok()?,
        u64::try_from(skip_pixels).ok()?,
    );
    let align = u64::try_from(alignment.max(1)).ok()?;
    let pad = |r: u64| -> Option<u64> {
        let p = r % align;
        if p == 0 {
            Some(r)
        } else {
            r.checked_add(align - p)
        }
    };
    let (rowsize, start, last, bit0) = if t == gl::BITMAP {
        let rowsize = pad(gpl.checked_mul(comps)?.checked_add(7)? / 8)?;
        let bits0 = sp.checked_mul(comps)?;
        let start = sr.checked_mul(rowsize)?.checked_add(bits0 / 8)?;
        let last = ((bits0 % 8) + w * comps).div_ceil(8);
        (rowsize, start, last, (bits0 % 8) as usize)
    } else {
        let es = bytes_per_element(t) as u64;
        let gs = es * comps;
        let rowsize = pad(gpl.checked_mul(gs)?)?;
        let start = sr.checked_mul(rowsize)?.checked_add(sp.checked_mul(gs)?)?;
        (rowsize, start, w.checked_mul(gs)?, 0)
    };
    let need = if h == 0 || w == 0 {
        0
    } else {
        start
            .checked_add((h - 1).checked_mul(rowsize)?)?
            .checked_add(last)?
    };
    Some(Place {
        rowsize: usize::try_from(rowsize).ok()?,
        start: usize::try_from(start).ok()?,
        need: usize::try_from(need).ok()?,
        bit0,
    })
}

/// Bytes per element (BITMAP handled apart).
fn bytes_per_element(t: u32) -> usize {
    match (elem_of(t), packed_of(t)) {
        (Some(e), _) => e.size(),
        (_, Some(p)) => p.size,
        _ => 4,
    }
}

/// libGLU's `fill_image`: the user's `width` x `height` image of `format`/`t`, read under the
/// UNPACK_ modes `m` at `pl`, as 16-bit components (tight, `format_comps` a pixel).
fn fill_image(
    m: &crate::pixel_store::PixelModes,
    pl: &Place,
    width: usize,
    height: usize,
    format: u32,
    t: u32,
    data: &[u8],
) -> Vec<u16> {
    let index = is_index(format);
    let comps = elements_per_group(format, t);
    let mut out = Vec::with_capacity(width * height * format_comps(format));
    if t == gl::BITMAP {
        for i in 0..height {
            let mut at = pl.start + i * pl.rowsize;
            let mut bit = pl.bit0;
            for _ in 0..width * comps {
                let byte = data[at];
                let set = if m.lsb_first {
                    byte & (1 << bit)
                } else {
                    byte & (1 << (7 - bit))
                };
                out.push(match (set != 0, index) {
                    (false, _) => 0,
                    (true, true) => 1,
                    (true, false) => 65535,
                });
                bit += 1;
                if bit == 8 {
                    bit = 0;
                    at += 1;
                }
            }
        }
        return out;
    }
    let es = bytes_per_element(t);
    let swap = m.swap_bytes && es > 1;
    for i in 0..height {
        let row = pl.start + i * pl.rowsize;
        for j in 0..width * comps {
            let at = (row + j * es) as isize;
            if let Some(p) = packed_of(t) {
                let c = p.extract(data, at);
                for v in c.iter().take(p.comps) {
                    out.push((v * 65535.0) as u16);
                }
                continue;
            }
            let raw = rd(data, at, es, swap);
            out.push(match t {
                gl::UNSIGNED_BYTE if index => raw as u16,
                gl::UNSIGNED_BYTE => (raw * 257) as u16,
                gl::BYTE if index => i16::from(raw as u8 as i8) as u16,
                gl::BYTE => (i32::from(raw as u8 as i8) * 516) as u16,
                gl::UNSIGNED_SHORT => raw as u16,
                gl::SHORT if index => raw as u16,
                gl::SHORT => (i32::from(raw as u16 as i16) * 2) as u16,
                gl::UNSIGNED_INT if index => raw as u16,
                gl::UNSIGNED_INT => (raw >> 16) as u16,
                gl::INT if index => raw as u16,
                gl::INT => ((raw as i32) >> 15) as u16,
                // FLOAT: float to GLushort as x86-64 converts it (through a 32-bit int).
                _ if index => c_i32(f64::from(f32::from_bits(raw))) as u16,
                _ => c_i32(f64::from(65535.0 * f32::from_bits(raw))) as u16,
            });
        }
    }
    out
}

/// libGLU's `empty_image`: 16-bit components written into the user's image of
/// `format`/`t` under the PACK_ modes `m` at `pl` (bytes between the groups untouched).
#[allow(clippy::too_many_arguments)]
fn empty_image(
    m: &crate::pixel_store::PixelModes,
    pl: &Place,
    width: usize,
    height: usize,
    format: u32,
    t: u32,
    img: &[u16],
    data: &mut [u8],
) {
    let index = is_index(format);
    let comps = elements_per_group(format, t);
    let mut src = img.iter().copied();
    if t == gl::BITMAP {
        for i in 0..height {
            let mut at = pl.start + i * pl.rowsize;
            let mut bit = pl.bit0;
            for _ in 0..width * comps {
                let v = src.next().unwrap_or(0);
                let set = if index { v & 1 != 0 } else { v > 32767 };
                let mask = if m.lsb_first {
                    1u8 << bit
                } else {
                    1u8 << (7 - bit)
                };
                if set {
                    data[at] |= mask;
                } else {
                    data[at] &= !mask;
                }
                bit += 1;
                if bit == 8 {
                    bit = 0;
                    at += 1;
                }
            }
        }
        return;
    }
    let es = bytes_per_element(t);
    let swap = m.swap_bytes && es > 1;
    let mut put = |at: usize, v: u32| {
        let b = v.to_le_bytes();
        for i in 0..es {
            data[at + i] = if swap { b[es - 1 - i] } else { b[i] };
        }
    };
    for i in 0..height {
        let row = pl.start + i * pl.rowsize;
        for j in 0..width * comps {
            let at = row + j * es;
            if let Some(p) = packed_of(t) {
                let mut c = [0f32; 4];
                for x in c.iter_mut().take(p.comps) {
                    *x = (f64::from(src.next().unwrap_or(0)) / 65535.0) as f32;
                }
                put(at, p.shove(&c));
                continue;
            }
            let v = src.next().unwrap_or(0);
            let v32 = u32::from(v);
            put(
                at,
                match t {
                    gl::UNSIGNED_BYTE if index => v32 & 0xff,
                    gl::UNSIGNED_BYTE => v32 >> 8,
                    gl::BYTE if index => v32 & 0xff,
                    gl::BYTE => v32 >> 9,
                    gl::UNSIGNED_SHORT => v32,
                    gl::SHORT if index => v32,
                    gl::SHORT => v32 >> 1,
                    gl::UNSIGNED_INT if index => v32,
                    gl::UNSIGNED_INT => v32.wrapping_mul(65537),
                    gl::INT if index => v32,
                    gl::INT => v32.wrapping_mul(65537) / 2,
                    _ if index => f32::from(v).to_bits(),
                    _ => (f32::from(v) / 65535.0).to_bits(),
                },
            );
        }
    }
}

/// `gluScaleImage`: scales `data_in` (`width_in` x `height_in` of `format` / `type_in`, read
/// under the context's UNPACK_ modes) to `width_out` x `height_out` of `type_out`, written
/// into `data_out` under the PACK_ modes (ALIGNMENT, ROW_LENGTH, SKIP_ROWS, SKIP_PIXELS,
/// SWAP_BYTES, LSB_FIRST). Types: BITMAP, BYTE .. FLOAT and the twelve packed types of GL 1.2;
/// formats: COLOR_INDEX, STENCIL_INDEX, DEPTH_COMPONENT, RED .. ALPHA, RGB, RGBA, BGR, BGRA,
/// LUMINANCE, LUMINANCE_ALPHA (colour indices are scaled unnormalised). Returns 0 (also for a
/// zero size, nothing written), GLU_INVALID_VALUE for a negative size or a buffer too short
/// for the modes (libGLU reads or writes past it), GLU_INVALID_ENUM for another format or
/// type, GLU_INVALID_OPERATION for a packed type of the wrong format. Bytes of `data_out`
/// outside the image (skips, row padding) are left as they were.
#[allow(clippy::too_many_arguments)]
pub fn scale_image(
    ctx: &Context,
    format: u32,
    width_in: i32,
    height_in: i32,
    type_in: u32,
    data_in: &[u8],
    width_out: i32,
    height_out: i32,
    type_out: u32,
    data_out: &mut [u8],
) -> i32 {
    if width_in == 0 || height_in == 0 || width_out == 0 || height_out == 0 {
        return 0;
    }
    if width_in < 0 || height_in < 0 || width_out < 0 || height_out < 0 {
        return GLU_INVALID_VALUE;
    }
    if !legal_format(format) || !legal_type(type_in) || !legal_type(type_out) {
        return GLU_INVALID_ENUM;
    }
    if !legal_format_for_type(format, type_in) || !legal_format_for_type(format, type_out) {
        return GLU_INVALID_OPERATION;
    }
    let st = ctx.state();
    let (u, p) = (st.unpack, st.pack);
    let Some(lin) = place(
        u.row_length,
        u.alignment,
        u.skip_rows,
        u.skip_pixels,
        width_in,
        height_in,
        format,
        type_in,
    )
    .filter(|l| data_in.len() >= l.need) else {
        return GLU_INVALID_VALUE;
    };
    let Some(lout) = place(
        p.row_length,
        p.alignment,
        p.skip_rows,
        p.skip_pixels,
        width_out,
        height_out,
        format,
        type_out,
    )
    .filter(|l| data_out.len() >= l.need) else {
        return GLU_INVALID_VALUE;
    };
    let before = fill_image(
        &u,
        &lin,
        width_in as usize,
        height_in as usize,
        format,
        type_in,
        data_in,
    );
    let c = format_comps(format);
    let after = scale_internal(c, width_in, height_in, &before, width_out, height_out);
    empty_image(
        &p,
        &lout,
        width_out as usize,
        height_out as usize,
        format,
        type_out,
        &after,
        data_out,
    );
    0
}

/// The UNPACK_ modes libGLU reads at entry and restores at exit.
fn restore_unpack(ctx: &mut Context, m: &crate::pixel_store::PixelModes) {
    ctx.pixel_storei(gl::UNPACK_ALIGNMENT, m.alignment);
    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, m.skip_rows);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, m.skip_pixels);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, m.row_length);
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, i32::from(m.swap_bytes));
}

/// libGLU's `closestFit`: the nearest powers of two, both halved while the driver's proxy
/// (PROXY_TEXTURE_2D, PROXY_TEXTURE_CUBE_MAP for a cube face, else PROXY_TEXTURE_1D) answers
/// width 0 for level 1 at half those sizes; if even 1x1 does not fit, the nearest powers
/// clamped to MAX_TEXTURE_SIZE.
#[allow(clippy::too_many_arguments)]
fn closest_fit(
    ctx: &mut Context,
    target: u32,
    width: i32,
    height: i32,
    internal_format: i32,
    format: u32,
    t: u32,
) -> (i32, i32) {
    let mut w2 = nearest_power(width as u32);
    let mut h2 = nearest_power(height as u32);
    loop {
        let w1 = if w2 > 1 { w2 >> 1 } else { w2 };
        let h1 = if h2 > 1 { h2 >> 1 } else { h2 };
        let proxy = if target == gl::TEXTURE_2D || target == gl::PROXY_TEXTURE_2D {
            ctx.tex_image_2d(
                gl::PROXY_TEXTURE_2D,
                1,
                internal_format,
                w1,
                h1,
                0,
                format,
                t,
                None,
            );
            gl::PROXY_TEXTURE_2D
        } else if (gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z)
            .contains(&target)
        {
            ctx.tex_image_2d(
                gl::PROXY_TEXTURE_CUBE_MAP,
                1,
                internal_format,
                w1,
                h1,
                0,
                format,
                t,
                None,
            );
            gl::PROXY_TEXTURE_CUBE_MAP
        } else {
            ctx.tex_image_1d(
                gl::PROXY_TEXTURE_1D,
                1,
                internal_format,
                w1,
                0,
                format,
                t,
                None,
            );
            gl::PROXY_TEXTURE_1D
        };
        let mut pw = [0i32];
        ctx.get_tex_level_parameteriv(proxy, 1, gl::TEXTURE_WIDTH, &mut pw);
        if pw[0] != 0 {
            return (w2, h2);
        }
        if w2 == 1 && h2 == 1 {
            break;
        }
        w2 = w1;
        h2 = h1;
    }
    let mut max = [0i32];
    ctx.get_integerv(gl::MAX_TEXTURE_SIZE, &mut max);
    (
        nearest_power(width as u32).min(max[0]),
        nearest_power(height as u32).min(max[0]),
    )
}

/// libGLU's `isLegalLevels`.
fn legal_levels(user: i32, base: i32, max: i32, total: i32) -> bool {
    !(base < 0 || base < user || max < base || total < max)
}

/// Checks `data` holds a `width` x `height` image of `format`/`t` under the UNPACK_ modes.
fn unpack_place(
    ctx: &Context,
    width: i32,
    height: i32,
    format: u32,
    t: u32,
    data: &[u8],
) -> Option<Place> {
    let u = ctx.state().unpack;
    place(
        u.row_length,
        u.alignment,
        u.skip_rows,
        u.skip_pixels,
        width,
        height,
        format,
        t,
    )
    .filter(|l| data.len() >= l.need)
}

/// Rows of 16-bit components as the little-endian bytes GL reads for UNSIGNED_SHORT.
fn u16_bytes(img: &[u16]) -> Vec<u8> {
    img.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// `gluBuild1DMipmaps`: a 1D mipmap pyramid of `data` (`width` of `format`/`type_`, read
/// under the UNPACK_ modes) for `target`: the width rounded to the nearest power of two that
/// the driver's PROXY_TEXTURE_1D takes (libGLU's `closestFit`), the image scaled to it and
/// each next level scaled from the last, all in 16-bit components and uploaded with
/// `tex_image_1d` as UNSIGNED_SHORT under UNPACK_ALIGNMENT 2, the skips and ROW_LENGTH 0 and
/// SWAP_BYTES false, which are restored at the end, as libGLU does. Returns 0,
/// GLU_INVALID_VALUE for a width below 1 or data too short, GLU_INVALID_ENUM for a format or
/// type libGLU does not take (STENCIL_INDEX included), GLU_INVALID_OPERATION for a packed
/// type of the wrong format.
#[allow(clippy::too_many_arguments)]
pub fn build_1d_mipmaps(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    format: u32,
    type_: u32,
    data: &[u8],
) -> i32 {
    let rc = check_mipmap_args(format, type_);
    if rc != 0 {
        return rc;
    }
    if width < 1 {
        return GLU_INVALID_VALUE;
    }
    if unpack_place(ctx, width, 1, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    let (w2, _) = closest_fit(ctx, target, width, 1, internal_format, format, type_);
    let levels = compute_log(w2);
    build_1d_core(
        ctx,
        target,
        internal_format,
        width,
        w2,
        format,
        type_,
        [0, 0, levels],
        data,
    )
}

/// `gluBuild1DMipmapLevels`: as [`build_1d_mipmaps`] without the size fit: `width` must be a
/// power of two; levels `level` .. `level` + log2(width) are made and those within
/// `base` ..= `max` uploaded. GLU_INVALID_VALUE also where libGLU's `isLegalLevels` fails
/// (base below 0 or `level`, `max` below `base` or past the last level).
#[allow(clippy::too_many_arguments)]
pub fn build_1d_mipmap_levels(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    format: u32,
    type_: u32,
    level: i32,
    base: i32,
    max: i32,
    data: &[u8],
) -> i32 {
    let rc = check_mipmap_args(format, type_);
    if rc != 0 {
        return rc;
    }
    if width < 1 {
        return GLU_INVALID_VALUE;
    }
    let levels = compute_log(width).saturating_add(level);
    if !legal_levels(level, base, max, levels) {
        return GLU_INVALID_VALUE;
    }
    if unpack_place(ctx, width, 1, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    build_1d_core(
        ctx,
        target,
        internal_format,
        width,
        width,
        format,
        type_,
        [level, base, max],
        data,
    )
}

/// libGLU's `gluBuild1DMipmapLevelsCore`. Deviation: for a packed type libGLU filters the
/// levels it scales with one component a pixel (`elements_per_group` of a packed type) and
/// uploads memory it never wrote; fixedgl filters all the format's components.
#[allow(clippy::too_many_arguments)]
fn build_1d_core(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    width2: i32,
    format: u32,
    t: u32,
    [user, base, max]: [i32; 3],
    data: &[u8],
) -> i32 {
    let psm = ctx.state().unpack;
    let Some(pl) = unpack_place(ctx, width, 1, format, t, data) else {
        return GLU_INVALID_VALUE;
    };
    let mut newwidth = width2;
    let levels = i64::from(compute_log(newwidth)) + i64::from(user);
    let mut img = fill_image(&psm, &pl, width as usize, 1, format, t, data);
    let mut img_w = width;
    let cmpts = format_comps(format);
    ctx.pixel_storei(gl::UNPACK_ALIGNMENT, 2);
    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, 0);
    let mut level = i64::from(user);
    while level <= levels {
        if img_w != newwidth {
            img = scale_internal(cmpts, img_w, 1, &img, newwidth, 1);
            img_w = newwidth;
        }
        if i64::from(base) <= level && level <= i64::from(max) {
            ctx.tex_image_1d(
                target,
                level as i32,
                internal_format,
                img_w,
                0,
                format,
                gl::UNSIGNED_SHORT,
                Some(&u16_bytes(&img)),
            );
        }
        if newwidth > 1 {
            newwidth /= 2;
        }
        level += 1;
    }
    restore_unpack(ctx, &psm);
    0
}

/// libGLU's `bitmapBuild2DMipmaps` (BITMAP data): the 16-bit path of 1D for two dimensions,
/// every level uploaded as UNSIGNED_SHORT under UNPACK_ALIGNMENT 2. libGLU takes this path for
/// `gluBuild2DMipmapLevels` too, ignoring its levels.
#[allow(clippy::too_many_arguments)]
fn bitmap_build_2d(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    height: i32,
    format: u32,
    t: u32,
    data: &[u8],
) -> i32 {
    let psm = ctx.state().unpack;
    let Some(pl) = unpack_place(ctx, width, height, format, t, data) else {
        return GLU_INVALID_VALUE;
    };
    let (mut nw, mut nh) = closest_fit(ctx, target, width, height, internal_format, format, t);
    let levels = compute_log(nw).max(compute_log(nh));
    let mut img = fill_image(&psm, &pl, width as usize, height as usize, format, t, data);
    let (mut iw, mut ih) = (width, height);
    let cmpts = format_comps(format);
    ctx.pixel_storei(gl::UNPACK_ALIGNMENT, 2);
    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, 0);
    for level in 0..=levels {
        if iw != nw || ih != nh {
            img = scale_internal(cmpts, iw, ih, &img, nw, nh);
            iw = nw;
            ih = nh;
        }
        ctx.tex_image_2d(
            target,
            level,
            internal_format,
            iw,
            ih,
            0,
            format,
            gl::UNSIGNED_SHORT,
            Some(&u16_bytes(&img)),
        );
        if nw > 1 {
            nw /= 2;
        }
        if nh > 1 {
            nh /= 2;
        }
    }
    restore_unpack(ctx, &psm);
    0
}
/// `halveImage` on 16-bit components.
fn halve_u16(c: usize, w: usize, h: usize, input: &[u16]) -> Vec<u16> {
    let (nw, nh) = (w / 2, h / 2);
    let delta = w * c;
    let mut out = Vec::with_capacity(nw * nh * c);
    for i in 0..nh {
        for j in 0..nw {
            let t = i * 2 * delta + j * 2 * c;
            for k in 0..c {
                let s = u32::from(input[t + k])
                    + u32::from(input[t + k + c])
                    + u32::from(input[t + k + delta])
                    + u32::from(input[t + k + delta + c])
                    + 2;
                out.push((s / 4) as u16);
            }
        }
    }
    out
}

#[allow(clippy::needless_range_loop)]
/// `scale_internal`: box filter with float coverage weights on 16-bit components.
fn scale_internal(c: usize, win: i32, hin: i32, input: &[u16], wout: i32, hout: i32) -> Vec<u16> {
    if win == wout * 2 && hin == hout * 2 {
        return halve_u16(c, win as usize, hin as usize, input);
    }
    let mut out = vec![0u16; (wout * hout) as usize * c];
    let convy = hin as f32 / hout as f32;
    let convx = win as f32 / wout as f32;
    let halfconvx = convx / 2.0;
    let halfconvy = convy / 2.0;
    for i in 0..hout {
        let y = (f64::from(convy) * (f64::from(i) + 0.5)) as f32;
        let (lowy, highy) = if hin > hout {
            (y - halfconvy, y + halfconvy)
        } else {
            ((f64::from(y) - 0.5) as f32, (f64::from(y) + 0.5) as f32)
        };
        for j in 0..wout {
            let x = (f64::from(convx) * (f64::from(j) + 0.5)) as f32;
            let (lowx, highx) = if win > wout {
                (x - halfconvx, x + halfconvx)
            } else {
                ((f64::from(x) - 0.5) as f32, (f64::from(x) + 0.5) as f32)
            };
            let mut totals = [0f32; 4];
            let mut area = 0f32;
            let mut y = lowy;
            let mut yint = f64::from(y).floor() as i32;
            while y < highy {
                let yindex = (yint + hin).rem_euclid(hin);
                let ypercent = if highy < (yint + 1) as f32 {
                    highy - y
                } else {
                    (yint + 1) as f32 - y
                };
                let mut x = lowx;
                let mut xint = f64::from(x).floor() as i32;
                while x < highx {
                    let xindex = (xint + win).rem_euclid(win);
                    let xpercent = if highx < (xint + 1) as f32 {
                        highx - x
                    } else {
                        (xint + 1) as f32 - x
                    };
                    let percent = xpercent * ypercent;
                    area += percent;
                    let temp = (xindex + yindex * win) as usize * c;
                    for k in 0..c {
                        totals[k] += f32::from(input[temp + k]) * percent;
                    }
                    xint += 1;
                    x = xint as f32;
                }
                yint += 1;
                y = yint as f32;
            }
            let temp = (j + i * wout) as usize * c;
            for k in 0..c {
                out[temp + k] = ((f64::from(totals[k]) + 0.5) / f64::from(area)) as u16;
            }
        }
    }
    out
}

/// An image in the caller's type as libGLU's 2D core filters it: element kind or packed type,
/// components a group, bytes an element and a group, and libGLU's `myswap_bytes`. That flag
/// reorders no bytes (libGLU's swap macros read little-endian, the native order here), but it
/// selects code paths that round differently: separate left/right sums for SHORT, INT and
/// FLOAT, and FLOAT 2x1 means of the elements' bits taken as integers.
#[derive(Clone, Copy)]
struct Typed {
    elem: Option<Elem>,
    packed: Option<Packed>,
    comps: usize,
    es: usize,
    gs: usize,
    swap: bool,
}

impl Typed {
    fn new(format: u32, t: u32, swap: bool) -> Self {
        let es = bytes_per_element(t);
        let cmpts = elements_per_group(format, t);
        Typed {
            elem: elem_of(t),
            packed: packed_of(t),
            comps: packed_of(t).map_or(cmpts, |p| p.comps),
            es,
            gs: es * cmpts,
            swap: swap && es > 1,
        }
    }

    /// The components of the pixel at byte `at` as the float libGLU multiplies.
    fn px(&self, d: &[u8], at: isize) -> [f32; 4] {
        if let Some(p) = self.packed {
            return p.extract(d, at);
        }
        let mut out = [0f32; 4];
        let e = self.elem.unwrap_or(Elem::UByte);
        for (k, o) in out.iter_mut().enumerate().take(self.comps) {
            let r = rd(d, at + (k * self.es) as isize, self.es, false);
            *o = match e {
                Elem::UByte => r as f32,
                Elem::Byte => f32::from(r as u8 as i8),
                Elem::UShort => r as f32,
                Elem::Short => f32::from(r as u16 as i16),
                Elem::UInt => r as f32,
                Elem::Int => r as i32 as f32,
                Elem::Float => f32::from_bits(r),
            };
        }
        out
    }

    /// libGLU's left/right column sums for SHORT, INT and FLOAT under SWAP_BYTES add the two
    /// products one at a time (elsewhere their sum at once).
    fn split_lr(&self) -> bool {
        self.swap && matches!(self.elem, Some(Elem::Short | Elem::Int | Elem::Float))
    }

    /// Writes one filtered pixel (`totals / area` per component) in the type.
    fn put(&self, out: &mut Vec<u8>, v: [f32; 4]) {
        if let Some(p) = self.packed {
            p.put(out, p.shove(&v));
            return;
        }
        for x in v.iter().take(self.comps) {
            let x = *x;
            match self.elem.unwrap_or(Elem::UByte) {
                Elem::UByte => out.push(c_i32(f64::from(x)) as u8),
                Elem::Byte => out.push(c_i32(f64::from(x)) as u8),
                Elem::UShort => out.extend_from_slice(&(c_i32(f64::from(x)) as u16).to_le_bytes()),
                Elem::Short => out.extend_from_slice(&(c_i32(f64::from(x)) as u16).to_le_bytes()),
                Elem::UInt => {
                    let u = if x >= 4_294_967_296.0 {
                        u32::MAX
                    } else {
                        f64::from(x) as u32
                    };
                    out.extend_from_slice(&u.to_le_bytes());
                }
                Elem::Int => out.extend_from_slice(&c_i32(f64::from(x)).to_le_bytes()),
                Elem::Float => out.extend_from_slice(&x.to_le_bytes()),
            }
        }
    }

    /// The 2x2 average of `halveImage_<type>` of the elements at `o` (k-th component).
    fn avg4(&self, d: &[u8], o: [isize; 4], out: &mut Vec<u8>) {
        let e = self.elem.unwrap_or(Elem::UByte);
        let r = |a: isize| rd(d, a, self.es, false);
        match e {
            Elem::UByte | Elem::Byte | Elem::UShort | Elem::Short => {
                let v = |a| -> i32 {
                    let x = r(a);
                    match e {
                        Elem::Byte => i32::from(x as u8 as i8),
                        Elem::Short => i32::from(x as u16 as i16),
                        _ => x as i32,
                    }
                };
                let s = (v(o[0]) + v(o[1]) + v(o[2]) + v(o[3]) + 2) / 4;
                out.extend_from_slice(&s.to_le_bytes()[..self.es]);
            }
            Elem::UInt => {
                let s = f64::from(r(o[0]))
                    + f64::from(r(o[1]))
                    + f64::from(r(o[2]))
                    + f64::from(r(o[3]));
                out.extend_from_slice(&((s / 4.0 + 0.5) as u32).to_le_bytes());
            }
            Elem::Int => {
                let f = |a| r(a) as i32 as f32;
                let s = f(o[0]) + f(o[1]) + f(o[2]) + f(o[3]);
                out.extend_from_slice(&c_i32(f64::from(s / 4.0) + 0.5).to_le_bytes());
            }
            Elem::Float => {
                let f = |a| f32::from_bits(r(a));
                let s = (f(o[0]) + f(o[1]) + f(o[2]) + f(o[3])) / 4.0;
                out.extend_from_slice(&s.to_le_bytes());
            }
        }
    }

    /// The 2x1 average of `halve1Dimage_<type>`: truncating integer means; INT through
    /// the elements' unsigned values in float and FLOAT under SWAP_BYTES through the swapped
    /// bits' integer value, as libGLU computes them.
    fn avg2(&self, d: &[u8], a: isize, b: isize, out: &mut Vec<u8>) {
        let e = self.elem.unwrap_or(Elem::UByte);
        let r = |x: isize| rd(d, x, self.es, false);
        match e {
            Elem::UByte | Elem::Byte | Elem::UShort | Elem::Short => {
                let v = |x| -> i32 {
                    let y = r(x);
                    match e {
                        Elem::Byte => i32::from(y as u8 as i8),
                        Elem::Short => i32::from(y as u16 as i16),
                        _ => y as i32,
                    }
                };
                let s = (v(a) + v(b)) / 2;
                out.extend_from_slice(&s.to_le_bytes()[..self.es]);
            }
            Elem::UInt => {
                let s = (f64::from(r(a)) + f64::from(r(b))) / 2.0;
                out.extend_from_slice(&(s as u32).to_le_bytes());
            }
            Elem::Int => {
                let s = f64::from(r(a) as f32 + r(b) as f32) / 2.0;
                out.extend_from_slice(&c_i32(s).to_le_bytes());
            }
            Elem::Float => {
                let f = |x| {
                    if self.swap {
                        r(x) as f32
                    } else {
                        f32::from_bits(r(x))
                    }
                };
                let s = (f64::from(f(a) + f(b)) / 2.0) as f32;
                out.extend_from_slice(&s.to_le_bytes());
            }
        }
    }
}

/// libGLU's `halveImage_<type>` / `halveImagePackedPixel` (and their 1D forms for a single
/// row or column): `img` rows `ysize` bytes apart; the result is tightly packed.
fn halve_typed(ty: &Typed, w: usize, h: usize, img: &[u8], ysize: usize) -> Vec<u8> {
    let mut out = Vec::new();
    let (gs, es) = (ty.gs as isize, ty.es as isize);
    let ys = ysize as isize;
    if let Some(p) = ty.packed {
        let mean = |pix: &[isize], out: &mut Vec<u8>| {
            let mut t = [0f32; 4];
            let ex: Vec<[f32; 4]> = pix.iter().map(|&a| p.extract(img, a)).collect();
            for (c, tc) in t.iter_mut().enumerate().take(p.comps) {
                let mut s = 0f32;
                for e in &ex {
                    s += e[c];
                }
                *tc = s / pix.len() as f32;
            }
            p.put(out, p.shove(&t));
        };
        if h == 1 {
            for jj in 0..(w / 2) as isize {
                mean(&[jj * 2 * gs, jj * 2 * gs + gs], &mut out);
            }
        } else if w == 1 {
            for jj in 0..(h / 2) as isize {
                mean(&[jj * 2 * ys, jj * 2 * ys + ys], &mut out);
            }
        } else {
            for i in 0..(h / 2) as isize {
                for j in 0..(w / 2) as isize {
                    let s = i * 2 * ys + j * 2 * gs;
                    mean(&[s, s + gs, s + ys, s + ys + gs], &mut out);
                }
            }
        }
        return out;
    }
    if h == 1 {
        for jj in 0..(w / 2) as isize {
            for k in 0..ty.comps as isize {
                let s = jj * 2 * gs + k * es;
                ty.avg2(img, s, s + gs, &mut out);
            }
        }
    } else if w == 1 {
        for jj in 0..(h / 2) as isize {
            for k in 0..ty.comps as isize {
                let s = jj * 2 * ys + k * es;
                ty.avg2(img, s, s + ys, &mut out);
            }
        }
    } else {
        for i in 0..(h / 2) as isize {
            for j in 0..(w / 2) as isize {
                for k in 0..ty.comps as isize {
                    let t = i * 2 * ys + j * 2 * gs + k * es;
                    ty.avg4(img, [t, t + gs, t + ys, t + ys + gs], &mut out);
                }
            }
        }
    }
    out
}

/// libGLU's `scale_internal_<type>` / `scaleInternalPackedPixel`: the box filter for sizes
/// that are not an exact halving (edge weights accumulate in float; the left and right edge
/// pointers of a block's middle rows drift by an element a component, as in libGLU; the
/// packed form does not clamp the last row).
#[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
fn scale_typed(
    ty: &Typed,
    win: i32,
    hin: i32,
    data: &[u8],
    wout: i32,
    hout: i32,
    ysize: usize,
) -> Vec<u8> {
    if win == wout * 2 && hin == hout * 2 {
        return halve_typed(ty, win as usize, hin as usize, data, ysize);
    }
    let c = ty.comps;
    let gs = ty.gs as isize;
    let ys = ysize as isize;
    let split = ty.split_lr();
    let px = |at: isize| ty.px(data, at);
    let mut out = Vec::with_capacity((wout * hout) as usize * ty.gs);
    let convy = hin as f32 / hout as f32;
    let convx = win as f32 / wout as f32;
    let convy_int = f64::from(convy).floor() as i32;
    let convy_float = convy - convy_int as f32;
    let convx_int = f64::from(convx).floor() as i32;
    let convx_float = convx - convx_int as f32;
    let area = convx * convy;
    let mut lowy_int = 0i32;
    let mut lowy_float = 0f32;
    let mut highy_int = convy_int;
    let mut highy_float = convy_float;
    let add = |totals: &mut [f32; 4], v: [f32; 4], w: f32| {
        for k in 0..c {
            totals[k] += v[k] * w;
        }
    };
    for _ in 0..hout {
        if ty.packed.is_none() && highy_int >= hin {
            highy_int = hin - 1;
        }
        let mut lowx_int = 0i32;
        let mut lowx_float = 0f32;
        let mut highx_int = convx_int;
        let mut highx_float = convx_float;
        for _ in 0..wout {
            let mut totals = [0f32; 4];
            let xindex = lowx_int as isize * gs;
            if highy_int > lowy_int && highx_int > lowx_int {
                let mut y_percent = 1.0 - lowy_float;
                let mut temp = xindex + lowy_int as isize * ys;
                add(&mut totals, px(temp), y_percent * (1.0 - lowx_float));
                let mut left = temp;
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    add(&mut totals, px(temp), y_percent);
                }
                temp += gs;
                let mut right = temp;
                add(&mut totals, px(temp), y_percent * highx_float);
                y_percent = highy_float;
                temp = xindex + highy_int as isize * ys;
                add(&mut totals, px(temp), y_percent * (1.0 - lowx_float));
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    add(&mut totals, px(temp), y_percent);
                }
                temp += gs;
                add(&mut totals, px(temp), y_percent * highx_float);
                for _ in lowy_int + 1..highy_int {
                    left += ys;
                    right += ys;
                    if ty.packed.is_some() {
                        let (l, r) = (px(left), px(right));
                        for k in 0..c {
                            totals[k] += l[k] * (1.0 - lowx_float) + r[k] * highx_float;
                        }
                    } else {
                        // libGLU advances `left`/`right` by an element per component, so
                        // component k of row m reads element k of the pixel m·(gs/es)... as
                        // a pointer walk: the pixel at left + k·es, then left moves on.
                        for k in 0..c {
                            let l = ty.px(data, left)[0];
                            let r = ty.px(data, right)[0];
                            if split {
                                totals[k] += l * (1.0 - lowx_float);
                                totals[k] += r * highx_float;
                            } else {
                                totals[k] += l * (1.0 - lowx_float) + r * highx_float;
                            }
                            left += ty.es as isize;
                            right += ty.es as isize;
                        }
                    }
                }
            } else if highy_int > lowy_int {
                let x_percent = highx_float - lowx_float;
                let mut temp = xindex + lowy_int as isize * ys;
                add(&mut totals, px(temp), (1.0 - lowy_float) * x_percent);
                for _ in lowy_int + 1..highy_int {
                    temp += ys;
                    add(&mut totals, px(temp), x_percent);
                }
                temp += ys;
                add(&mut totals, px(temp), x_percent * highy_float);
            } else if highx_int > lowx_int {
                let y_percent = highy_float - lowy_float;
                let mut temp = xindex + lowy_int as isize * ys;
                add(&mut totals, px(temp), (1.0 - lowx_float) * y_percent);
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    add(&mut totals, px(temp), y_percent);
                }
                temp += gs;
                add(&mut totals, px(temp), y_percent * highx_float);
            } else {
                let percent = (highy_float - lowy_float) * (highx_float - lowx_float);
                let temp = xindex + lowy_int as isize * ys;
                add(&mut totals, px(temp), percent);
            }
            let mut temp0 = xindex + gs + (lowy_int + 1) as isize * ys;
            for _ in lowy_int + 1..highy_int {
                let mut temp = temp0;
                for _ in lowx_int + 1..highx_int {
                    let v = px(temp);
                    for k in 0..c {
                        totals[k] += v[k];
                    }
                    temp += gs;
                }
                temp0 += ys;
            }
            let mut v = [0f32; 4];
            for k in 0..c {
                v[k] = totals[k] / area;
            }
            ty.put(&mut out, v);
            lowx_int = highx_int;
            lowx_float = highx_float;
            highx_int += convx_int;
            highx_float += convx_float;
            if highx_float > 1.0 {
                highx_float -= 1.0;
                highx_int += 1;
            }
        }
        lowy_int = highy_int;
        lowy_float = highy_float;
        highy_int += convy_int;
        highy_float += convy_float;
        if highy_float > 1.0 {
            highy_float -= 1.0;
            highy_int += 1;
        }
    }
    out
}
/// Rows of `row` bytes copied to a stride padded to `alignment` (what GL will read).
fn pad_rows(img: &[u8], row: usize, rows: usize, alignment: usize) -> Vec<u8> {
    let pad = row % alignment;
    if pad == 0 {
        return img.to_vec();
    }
    let stride = row + alignment - pad;
    let mut out = vec![0u8; stride * rows];
    for r in 0..rows {
        out[r * stride..r * stride + row].copy_from_slice(&img[r * row..(r + 1) * row]);
    }
    out
}

/// `gluBuild2DMipmaps`: a mipmap pyramid of `data` (`width` x `height` of `format`/`type_`,
/// read under the UNPACK_ modes) for `target` (TEXTURE_2D or a cube-map face), as libGLU
/// 9.0 builds it: sizes rounded to the nearest powers of two (3·2ⁿ up) and halved together
/// while the driver's proxy (PROXY_TEXTURE_2D or PROXY_TEXTURE_CUBE_MAP, level 1) answers
/// width 0; level 0 is `data` itself when the sizes are already those (read by GL under the
/// user's ROW_LENGTH, ALIGNMENT and SWAP_BYTES, GLU having applied the skips), else `data`
/// scaled to them in its own type; each next level halves the last; UNPACK_SKIP_ROWS,
/// SKIP_PIXELS, ROW_LENGTH 0 and SWAP_BYTES false while the levels go up, those modes restored
/// at the end. BITMAP images (COLOR_INDEX) go through 16-bit components as libGLU's
/// `bitmapBuild2DMipmaps`. Returns 0, GLU_INVALID_VALUE for a size below 1 or data too short
/// for the unpack modes, GLU_INVALID_ENUM for a format or type libGLU does not take
/// (STENCIL_INDEX included), GLU_INVALID_OPERATION for a packed type of the wrong format.
/// Deviation: where libGLU uploads the first scaled or halved level with rows not a multiple
/// of UNPACK_ALIGNMENT unpadded (GL then reads past its buffer), fixedgl pads the rows.
#[allow(clippy::too_many_arguments)]
pub fn build_2d_mipmaps(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    height: i32,
    format: u32,
    type_: u32,
    data: &[u8],
) -> i32 {
    let rc = check_mipmap_args(format, type_);
    if rc != 0 {
        return rc;
    }
    if width < 1 || height < 1 {
        return GLU_INVALID_VALUE;
    }
    if unpack_place(ctx, width, height, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    if type_ == gl::BITMAP {
        return bitmap_build_2d(
            ctx,
            target,
            internal_format,
            width,
            height,
            format,
            type_,
            data,
        );
    }
    let (w2, h2) = closest_fit(ctx, target, width, height, internal_format, format, type_);
    let levels = compute_log(w2).max(compute_log(h2));
    build_2d_core(
        ctx,
        target,
        internal_format,
        [width, height, w2, h2],
        format,
        type_,
        [0, 0, levels],
        data,
    )
}

/// `gluBuild2DMipmapLevels`: as [`build_2d_mipmaps`] without the size fit (both sizes must be
/// powers of two): levels `level` .. `level` + log2(max(width, height)) are made and those
/// within `base` ..= `max` uploaded. GLU_INVALID_VALUE also where libGLU's `isLegalLevels`
/// fails. BITMAP data takes libGLU's bitmap path, which ignores the three levels.
#[allow(clippy::too_many_arguments)]
pub fn build_2d_mipmap_levels(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    height: i32,
    format: u32,
    type_: u32,
    level: i32,
    base: i32,
    max: i32,
    data: &[u8],
) -> i32 {
    let rc = check_mipmap_args(format, type_);
    if rc != 0 {
        return rc;
    }
    if width < 1 || height < 1 {
        return GLU_INVALID_VALUE;
    }
    let levels = compute_log(width)
        .max(compute_log(height))
        .saturating_add(level);
    if !legal_levels(level, base, max, levels) {
        return GLU_INVALID_VALUE;
    }
    if unpack_place(ctx, width, height, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    if type_ == gl::BITMAP {
        return bitmap_build_2d(
            ctx,
            target,
            internal_format,
            width,
            height,
            format,
            type_,
            data,
        );
    }
    build_2d_core(
        ctx,
        target,
        internal_format,
        [width, height, width, height],
        format,
        type_,
        [level, base, max],
        data,
    )
}

/// libGLU's `gluBuild2DMipmapLevelsCore` for every type but BITMAP.
#[allow(clippy::too_many_arguments)]
fn build_2d_core(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    [width, height, w2, h2]: [i32; 4],
    format: u32,
    t: u32,
    [user, base, max]: [i32; 3],
    data: &[u8],
) -> i32 {
    let psm = ctx.state().unpack;
    let Some(pl) = unpack_place(ctx, width, height, format, t, data) else {
        return GLU_INVALID_VALUE;
    };
    let (mut nw, mut nh) = (w2, h2);
    let levels = i64::from(compute_log(nw).max(compute_log(nh))) + i64::from(user);
    let user_ty = Typed::new(format, t, psm.swap_bytes);
    let ty = Typed::new(format, t, false);
    let alignment = psm.alignment.max(1) as usize;
    let users = &data[pl.start.min(data.len())..];

    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
    let mut level = i64::from(user);
    let mut img;
    if width == nw && height == nh {
        if i64::from(base) <= level && level <= i64::from(max) {
            ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, psm.row_length);
            let need = pl.need - pl.start;
            ctx.tex_image_2d(
                target,
                level as i32,
                internal_format,
                width,
                height,
                0,
                format,
                t,
                Some(&users[..need.min(users.len())]),
            );
        }
        ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
        if levels == 0 {
            restore_unpack(ctx, &psm);
            return 0;
        }
        img = halve_typed(&user_ty, width as usize, height as usize, users, pl.rowsize);
        nw = (width / 2).max(1);
        nh = (height / 2).max(1);
        level = i64::from(user) + 1;
    } else {
        img = scale_typed(&user_ty, width, height, users, nw, nh, pl.rowsize);
    }
    let mut rowsize = nw as usize * ty.gs;
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, 0);
    if i64::from(base) <= level && level <= i64::from(max) {
        let up = pad_rows(&img, rowsize, nh as usize, alignment);
        ctx.tex_image_2d(
            target,
            level as i32,
            internal_format,
            nw,
            nh,
            0,
            format,
            t,
            Some(&up),
        );
    }
    level += 1;
    while level <= levels {
        img = halve_typed(&ty, nw as usize, nh as usize, &img, rowsize);
        if nw > 1 {
            nw /= 2;
            rowsize /= 2;
        }
        if nh > 1 {
            nh /= 2;
        }
        if i64::from(base) <= level && level <= i64::from(max) {
            let up = pad_rows(&img, rowsize, nh as usize, alignment);
            ctx.tex_image_2d(
                target,
                level as i32,
                internal_format,
                nw,
                nh,
                0,
                format,
                t,
                Some(&up),
            );
        }
        level += 1;
    }
    restore_unpack(ctx, &psm);
    0
}
