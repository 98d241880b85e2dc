//! `gluScaleImage` and `gluBuild2DMipmaps` (GLU 1.3 §3.1, §3.2) for UNSIGNED_BYTE images,
//! with libGLU 9.0's filters, so the images come out byte for byte as libGLU's
//! (`tests/it/glu_mipmap.rs` holds both against the real libGLU on llvmpipe):
//!
//! - `scale_image` widens each component to 16 bits (× 257), box-filters with single-precision
//!   coverage weights (libGLU's `scale_internal`; an exact halving is a 2x2 average rounded
//!   `(a + b + c + d + 2) / 4`), and narrows back (`>> 8`);
//! - `build_2d_mipmaps` rounds each size to the nearest power of two (3·2ⁿ up), scales to it
//!   in 8 bits (libGLU's `scale_internal_ubyte`, including its drifting edge weights), and
//!   halves level by level: 2x2 blocks rounded as above, 2x1 and 1x2 blocks truncated
//!   (`(a + b) / 2`), as libGLU's `halveImage_ubyte` does.

use crate::texture::format_components;
use crate::{gl, Context};

use super::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};

fn is_index(format: u32) -> bool {
    format == gl::COLOR_INDEX || format == gl::STENCIL_INDEX
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
            return i * 4;
        }
        v >>= 1;
        i *= 2;
    }
}

fn compute_log(value: i32) -> i32 {
    if value <= 0 {
        return -1;
    }
    value.trailing_zeros() as i32
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

/// `gluScaleImage` for UNSIGNED_BYTE data: scales `data_in` (`width_in` x `height_in`, read
/// under the context's UNPACK_ modes) to `width_out` x `height_out` written into `data_out`
/// under the PACK_ modes (ALIGNMENT, ROW_LENGTH, SKIP_ROWS, SKIP_PIXELS). Returns 0 (also for
/// a zero size, nothing written), GLU_INVALID_VALUE for a negative size or a buffer too short
/// (libGLU reads or writes past it), GLU_INVALID_ENUM for a format GL has no components for
/// or a type other than UNSIGNED_BYTE (deviation: libGLU scales every GL 1.2 type; fixedgl
/// UNSIGNED_BYTE only).
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
    let Some(n) = format_components(format) else {
        return GLU_INVALID_ENUM;
    };
    if type_in != gl::UNSIGNED_BYTE || type_out != gl::UNSIGNED_BYTE {
        return GLU_INVALID_ENUM;
    }
    let st = ctx.state();
    let Some(lin) = st
        .unpack
        .layout(width_in, height_in, n, 1)
        .filter(|l| data_in.len() >= l.need)
    else {
        return GLU_INVALID_VALUE;
    };
    let Some(lout) = st
        .pack
        .layout(width_out, height_out, n, 1)
        .filter(|l| data_out.len() >= l.need)
    else {
        return GLU_INVALID_VALUE;
    };
    let index = is_index(format);
    let mut before = Vec::with_capacity((width_in * height_in) as usize * n);
    for j in 0..height_in as usize {
        for i in 0..width_in as usize {
            let at = lin.at(i, j);
            for k in 0..n {
                let b = u16::from(data_in[at + k]);
                before.push(if index { b } else { b * 257 });
            }
        }
    }
    let after = scale_internal(n, width_in, height_in, &before, width_out, height_out);
    for j in 0..height_out as usize {
        for i in 0..width_out as usize {
            let at = lout.at(i, j);
            for k in 0..n {
                let v = after[(j * width_out as usize + i) * n + k];
                data_out[at + k] = if index { v as u8 } else { (v >> 8) as u8 };
            }
        }
    }
    0
}

/// Reads byte `at` of `img`, 0 past its end (where libGLU's filters read past their image).
#[inline]
fn px(img: &[u8], at: usize) -> u8 {
    img.get(at).copied().unwrap_or(0)
}

/// `halveImage_ubyte`: `img` rows are `ysize` bytes apart; the result is tightly packed.
fn halve_u8(c: usize, w: usize, h: usize, img: &[u8], ysize: usize) -> Vec<u8> {
    let g = c;
    let mut out = Vec::new();
    if w == 1 || h == 1 {
        if h == 1 {
            for jj in 0..w / 2 {
                for k in 0..c {
                    let s = jj * 2 * g + k;
                    out.push(((u32::from(px(img, s)) + u32::from(px(img, s + g))) / 2) as u8);
                }
            }
        } else {
            for jj in 0..h / 2 {
                for k in 0..c {
                    let s = jj * 2 * ysize + k;
                    out.push(((u32::from(px(img, s)) + u32::from(px(img, s + ysize))) / 2) as u8);
                }
            }
        }
        return out;
    }
    for i in 0..h / 2 {
        for j in 0..w / 2 {
            for k in 0..c {
                let t = i * 2 * ysize + j * 2 * g + k;
                let s = u32::from(px(img, t))
                    + u32::from(px(img, t + g))
                    + u32::from(px(img, t + ysize))
                    + u32::from(px(img, t + ysize + g))
                    + 2;
                out.push((s / 4) as u8);
            }
        }
    }
    out
}

/// `scale_internal_ubyte`: libGLU's 8-bit box filter for sizes that are not an exact halving
/// (edge weights accumulate in float; the left and right edge pointers of a block's middle rows
/// drift by a pixel a row, as in libGLU).
#[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
fn scale_u8(
    c: usize,
    win: i32,
    hin: i32,
    data: &[u8],
    wout: i32,
    hout: i32,
    ysize: usize,
) -> Vec<u8> {
    let g = c;
    if win == wout * 2 && hin == hout * 2 {
        return halve_u8(c, win as usize, hin as usize, data, ysize);
    }
    let mut out = vec![0u8; (wout * hout) as usize * c];
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
    let d = |at: isize| -> f32 {
        if at < 0 {
            0.0
        } else {
            f32::from(px(data, at as usize))
        }
    };
    let ys = ysize as isize;
    let gs = g as isize;
    for i in 0..hout {
        if highy_int >= hin {
            highy_int = hin - 1;
        }
        let mut lowx_int = 0i32;
        let mut lowx_float = 0f32;
        let mut highx_int = convx_int;
        let mut highx_float = convx_float;
        for j in 0..wout {
            let mut totals = [0f32; 4];
            let xindex = lowx_int as isize * gs;
            if highy_int > lowy_int && highx_int > lowx_int {
                let mut y_percent = 1.0 - lowy_float;
                let mut temp = xindex + lowy_int as isize * ys;
                let mut percent = y_percent * (1.0 - lowx_float);
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                let mut left = temp;
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    for k in 0..c {
                        totals[k] += d(temp + k as isize) * y_percent;
                    }
                }
                temp += gs;
                let mut right = temp;
                percent = y_percent * highx_float;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                y_percent = highy_float;
                percent = y_percent * (1.0 - lowx_float);
                temp = xindex + highy_int as isize * ys;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    for k in 0..c {
                        totals[k] += d(temp + k as isize) * y_percent;
                    }
                }
                temp += gs;
                percent = y_percent * highx_float;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                for _ in lowy_int + 1..highy_int {
                    left += ys;
                    right += ys;
                    for t in totals.iter_mut().take(c) {
                        *t += d(left) * (1.0 - lowx_float) + d(right) * highx_float;
                        left += 1;
                        right += 1;
                    }
                }
            } else if highy_int > lowy_int {
                let x_percent = highx_float - lowx_float;
                let mut percent = (1.0 - lowy_float) * x_percent;
                let mut temp = xindex + lowy_int as isize * ys;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                for _ in lowy_int + 1..highy_int {
                    temp += ys;
                    for k in 0..c {
                        totals[k] += d(temp + k as isize) * x_percent;
                    }
                }
                percent = x_percent * highy_float;
                temp += ys;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
            } else if highx_int > lowx_int {
                let y_percent = highy_float - lowy_float;
                let mut percent = (1.0 - lowx_float) * y_percent;
                let mut temp = xindex + lowy_int as isize * ys;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
                for _ in lowx_int + 1..highx_int {
                    temp += gs;
                    for k in 0..c {
                        totals[k] += d(temp + k as isize) * y_percent;
                    }
                }
                temp += gs;
                percent = y_percent * highx_float;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
            } else {
                let percent = (highy_float - lowy_float) * (highx_float - lowx_float);
                let temp = xindex + lowy_int as isize * ys;
                for k in 0..c {
                    totals[k] += d(temp + k as isize) * percent;
                }
            }
            let mut temp0 = xindex + gs + (lowy_int + 1) as isize * ys;
            for _ in lowy_int + 1..highy_int {
                let mut temp = temp0;
                for _ in lowx_int + 1..highx_int {
                    for k in 0..c {
                        totals[k] += d(temp + k as isize);
                    }
                    temp += gs;
                }
                temp0 += ys;
            }
            let outindex = (j + i * wout) as usize * c;
            for k in 0..c {
                // float to GLubyte: truncation (values stay within 0..=255).
                out[outindex + k] = (totals[k] / area) as u8;
            }
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

/// `gluBuild2DMipmaps` for UNSIGNED_BYTE data: libGLU 9.0's calls and images. Level 0 is
/// `data` itself when both sizes are powers of two (read by GL under the user's ROW_LENGTH and
/// ALIGNMENT, GLU having applied the skips), else `data` scaled to the nearest powers of two;
/// each next level halves the previous; every level goes to `tex_image_2d` with UNPACK_
/// SKIP_ROWS, SKIP_PIXELS, ROW_LENGTH 0 and SWAP_BYTES false, rows padded to the user's
/// ALIGNMENT, and those modes are restored at the end, as libGLU sets them. A size over
/// MAX_TEXTURE_SIZE halves both sizes until it fits (libGLU's proxy-texture fit).
/// Returns 0, GLU_INVALID_VALUE for a size below 1 or data too short for the unpack modes,
/// GLU_INVALID_ENUM for a format GL has no components for or a type other than
/// UNSIGNED_BYTE (deviation: libGLU takes every type). Deviation: where libGLU uploads a
/// level whose rows are not a multiple of ALIGNMENT without padding them (the first scaled or
/// halved level: GL then reads past its buffer), fixedgl pads them.
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
    let Some(n) = format_components(format) else {
        return GLU_INVALID_ENUM;
    };
    if type_ != gl::UNSIGNED_BYTE {
        return GLU_INVALID_ENUM;
    }
    if width < 1 || height < 1 {
        return GLU_INVALID_VALUE;
    }
    let psm = ctx.state().unpack;
    // Checked (the row length and skips are the user's): an overflow is data too short.
    let Some(layout) = psm
        .layout(width, height, n, 1)
        .filter(|l| data.len() >= l.need)
    else {
        return GLU_INVALID_VALUE;
    };
    // closestFit: the nearest powers of two, halved together while level 1 would not fit.
    let max = crate::texture::MAX_TEXTURE_SIZE;
    let (mut nw, mut nh) = (nearest_power(width as u32), nearest_power(height as u32));
    loop {
        let w1 = if nw > 1 { nw >> 1 } else { nw };
        let h1 = if nh > 1 { nh >> 1 } else { nh };
        if w1 <= max >> 1 && h1 <= max >> 1 || (nw == 1 && nh == 1) {
            break;
        }
        nw = w1;
        nh = h1;
    }
    let levels = compute_log(nw).max(compute_log(nh));
    let alignment = psm.alignment.max(1) as usize;
    let group = n;
    let ysize = layout.stride;
    let user = &data[layout.offset.min(data.len())..];

    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
    let restore = |ctx: &mut Context| {
        ctx.pixel_storei(gl::UNPACK_ALIGNMENT, psm.alignment);
        ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, psm.skip_rows);
        ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, psm.skip_pixels);
        ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, psm.row_length);
        ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, i32::from(psm.swap_bytes));
    };
    let mut level;
    let mut img;
    if width == nw && height == nh {
        level = 0;
        ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, psm.row_length);
        let need = layout.need - layout.offset;
        ctx.tex_image_2d(
            target,
            level,
            internal_format,
            width,
            height,
            0,
            format,
            type_,
            Some(&user[..need.min(user.len())]),
        );
        ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
        if levels == 0 {
            restore(ctx);
            return 0;
        }
        img = halve_u8(n, width as usize, height as usize, user, ysize);
        nw = (width / 2).max(1);
        nh = (height / 2).max(1);
        level += 1;
    } else {
        img = scale_u8(n, width, height, user, nw, nh, ysize);
        level = 0;
    }
    let mut rowsize = nw as usize * group;
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, 0);
    let up = pad_rows(&img, rowsize, nh as usize, alignment);
    ctx.tex_image_2d(
        target,
        level,
        internal_format,
        nw,
        nh,
        0,
        format,
        type_,
        Some(&up),
    );
    level += 1;
    while level <= levels {
        img = halve_u8(n, nw as usize, nh as usize, &img, rowsize);
        if nw > 1 {
            nw /= 2;
            rowsize /= 2;
        }
        if nh > 1 {
            nh /= 2;
        }
        let up = pad_rows(&img, rowsize, nh as usize, alignment);
        ctx.tex_image_2d(
            target,
            level,
            internal_format,
            nw,
            nh,
            0,
            format,
            type_,
            Some(&up),
        );
        level += 1;
    }
    restore(ctx);
    0
}
