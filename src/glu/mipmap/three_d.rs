//! GLU 1.3's `gluBuild3DMipmaps` and `gluBuild3DMipmapLevels`, byte for byte as Mesa's libGLU
//! 9.0 builds them (`tests/it/glu_mipmap3d.rs` holds them against the real libGLU on
//! llvmpipe). The 3D core works in the caller's type like the 2D one, with its own filters:
//!
//! - a level of depth 1 is halved by the 2D filters (`halve_typed`);
//! - a deeper level by libGLU's `halveImage3D`: a 2x2x2 (or, for a 1-wide or 1-high level, a
//!   2x1x2 / 1x2x2 / 1x1x2) mean of the elements in double, truncated to the type
//!   (`shoveUbyte` .. `shoveFloat`), or for a packed type `halveImagePackedPixel3D`'s float
//!   mean of the components;
//! - sizes that are not already those of `closestFit3D` are scaled by libGLU's
//!   `gluScaleImage3D`: 16-bit components (`fillImage3D` = `fill_image`), the 3D box filter
//!   `scaleInternal3D`, back to the type under the PACK_ modes (`emptyImage3D`).
//!
//! libGLU's pointer walks are kept as they are, with their slips: the 1x1xN column walk steps a
//! row where it means an image, a packed 1-wide or 1-high slice steps two images a pixel pair,
//! the image stride is not updated when the width halves at height 1, and a user image with
//! padded rows (alignment, ROW_LENGTH) or IMAGE_HEIGHT is walked with row padding counted
//! twice. Each walk reads where libGLU reads: the user's data, or the two level buffers libGLU
//! ping-pongs between (each as large as libGLU allocates it, with what earlier levels left in
//! it); a read past the data or a buffer gives 0 where libGLU reads memory it does not own.

use super::*;

/// libGLU's 3D addressing of a client image under (row length, image height, alignment, skip
/// rows, skip pixels, skip images): row stride, image stride, first byte and the bytes
/// touched, with checked arithmetic (None: no slice is that long).
#[derive(Clone, Copy)]
struct Place3 {
    row: usize,
    image: usize,
    start: usize,
    need: usize,
}

#[allow(clippy::too_many_arguments)]
fn place3(
    m: &crate::pixel_store::PixelModes,
    width: i32,
    height: i32,
    depth: i32,
    format: u32,
    t: u32,
) -> Option<Place3> {
    let gs = (bytes_per_element(t) * elements_per_group(format, t)) as u64;
    let w = u64::try_from(width).ok()?;
    let h = u64::try_from(height).ok()?;
    let d = u64::try_from(depth).ok()?;
    let gpl = if m.row_length > 0 {
        u64::try_from(m.row_length).ok()?
    } else {
        w
    };
    let rows = if m.image_height > 0 {
        u64::try_from(m.image_height).ok()?
    } else {
        h
    };
    let align = u64::try_from(m.alignment.max(1)).ok()?;
    let mut row = gpl.checked_mul(gs)?;
    if row % align != 0 {
        row = row.checked_add(align - row % align)?;
    }
    let image = rows.checked_mul(row)?;
    let start = u64::try_from(m.skip_rows)
        .ok()?
        .checked_mul(row)?
        .checked_add(u64::try_from(m.skip_pixels).ok()?.checked_mul(gs)?)?
        .checked_add(u64::try_from(m.skip_images).ok()?.checked_mul(image)?)?;
    let need = if w == 0 || h == 0 || d == 0 {
        start
    } else {
        start
            .checked_add((d - 1).checked_mul(image)?)?
            .checked_add((h - 1).checked_mul(row)?)?
            .checked_add(w.checked_mul(gs)?)?
    };
    Some(Place3 {
        row: usize::try_from(row).ok()?,
        image: usize::try_from(image).ok()?,
        start: usize::try_from(start).ok()?,
        need: usize::try_from(need).ok()?,
    })
}

/// The unpack modes with libGLU's resets applied (ROW_LENGTH, IMAGE_HEIGHT and the skips 0):
/// how GL reads level 0 from the user's image, and how `gluScaleImage3D`, called after those
/// resets, reads it.
fn tight(m: &crate::pixel_store::PixelModes) -> crate::pixel_store::PixelModes {
    crate::pixel_store::PixelModes {
        row_length: 0,
        image_height: 0,
        skip_rows: 0,
        skip_pixels: 0,
        skip_images: 0,
        ..*m
    }
}

/// libGLU's `extract<Type>` of the 3D filters: the element at `at` as a double. Under
/// SWAP_BYTES (`__GLU_SWAP_*_BYTES`, a little-endian assembly: the native value here) a FLOAT
/// element's bits are taken as an unsigned integer and converted to float, as libGLU does.
fn extract(ty: &Typed, d: &[u8], at: isize) -> f64 {
    let r = rd(d, at, ty.es, false);
    match ty.elem.unwrap_or(Elem::UByte) {
        Elem::UByte | Elem::UShort | Elem::UInt => f64::from(r),
        Elem::Byte => f64::from(r as u8 as i8),
        Elem::Short => f64::from(r as u16 as i16),
        Elem::Int => f64::from(r as i32),
        Elem::Float if ty.swap => f64::from(r as f32),
        Elem::Float => f64::from(f32::from_bits(r)),
    }
}

/// libGLU's `shove<Type>`: the double converted to the type (C's truncating conversions).
fn shove(ty: &Typed, v: f64, out: &mut Vec<u8>) {
    match ty.elem.unwrap_or(Elem::UByte) {
        Elem::UByte => out.push(v as u8),
        Elem::Byte => out.push(v as i8 as u8),
        Elem::UShort => out.extend_from_slice(&(v as u16).to_le_bytes()),
        Elem::Short => out.extend_from_slice(&(v as i16).to_le_bytes()),
        Elem::UInt => out.extend_from_slice(&(v as u32).to_le_bytes()),
        Elem::Int => out.extend_from_slice(&(v as i32).to_le_bytes()),
        Elem::Float => out.extend_from_slice(&(v as f32).to_le_bytes()),
    }
}

/// The double mean of the elements at `src + o` for each offset, as libGLU sums them (from
/// 0.0, in order), shoved to the type.
fn mean_elems(ty: &Typed, d: &[u8], src: isize, o: &[isize], out: &mut Vec<u8>) {
    let mut total = 0.0f64;
    for &x in o {
        total += extract(ty, d, src + x);
    }
    shove(ty, total / o.len() as f64, out);
}

/// libGLU's `halveImage3D` / `halveImageSlice` for a level of depth > 1 (not a packed type):
/// `img` has rows `row` and images `image` bytes apart.
fn halve_elems_3d(
    ty: &Typed,
    (w, h, d): (usize, usize, usize),
    img: &[u8],
    row: isize,
    image: isize,
) -> Vec<u8> {
    let (es, gs) = (ty.es as isize, ty.gs as isize);
    let row_pad = row - w as isize * gs;
    let image_pad = image - (w * h) as isize * gs;
    let mut out = Vec::new();
    let mut src = 0isize;
    if w == 1 && h == 1 {
        for _ in 0..d / 2 {
            for _ in 0..ty.comps {
                mean_elems(ty, img, src, &[0, image], &mut out);
                src += es;
            }
            src += row;
        }
    } else if h == 1 {
        for _ in 0..d / 2 {
            for _ in 0..w / 2 {
                for _ in 0..ty.comps {
                    mean_elems(ty, img, src, &[0, gs, image, image + gs], &mut out);
                    src += es;
                }
                src += gs;
            }
            src += row_pad + row;
        }
    } else if w == 1 {
        for _ in 0..d / 2 {
            for _ in 0..h / 2 {
                for _ in 0..ty.comps {
                    mean_elems(ty, img, src, &[0, row, image, image + row], &mut out);
                    src += es;
                }
                src += row_pad + row;
            }
            src += image_pad + image;
        }
    } else {
        let o = [
            0,
            gs,
            row,
            row + gs,
            image,
            gs + image,
            row + image,
            row + gs + image,
        ];
        for _ in 0..d / 2 {
            for _ in 0..h / 2 {
                for _ in 0..w / 2 {
                    for _ in 0..ty.comps {
                        mean_elems(ty, img, src, &o, &mut out);
                        src += es;
                    }
                    src += gs;
                }
                src += row_pad + row;
            }
            src += image_pad + image;
        }
    }
    out
}

/// libGLU's `halveImagePackedPixel3D` / `halveImagePackedPixelSlice` for a level of depth > 1.
fn halve_packed_3d(
    p: &Packed,
    (w, h, d): (usize, usize, usize),
    img: &[u8],
    row: isize,
    image: isize,
) -> Vec<u8> {
    let ps = p.size as isize;
    let mut out = Vec::new();
    let mean = |src: isize, o: &[isize], out: &mut Vec<u8>| {
        let ex: Vec<[f32; 4]> = o.iter().map(|&x| p.extract(img, src + x)).collect();
        let mut t = [0f32; 4];
        for (c, tc) in t.iter_mut().enumerate().take(p.comps) {
            let mut s = 0f32;
            for e in &ex {
                s += e[c];
            }
            *tc = s / o.len() as f32;
        }
        p.put(out, p.shove(&t));
    };
    let mut src = 0isize;
    if w == 1 && h == 1 {
        for _ in 0..d / 2 {
            mean(src, &[0, image], &mut out);
            src += 2 * image;
        }
    } else if h == 1 {
        for _ in 0..d / 2 {
            for _ in 0..w / 2 {
                mean(src, &[0, ps, image, image + ps], &mut out);
                src += 2 * image;
            }
        }
    } else if w == 1 {
        for _ in 0..d / 2 {
            for _ in 0..h / 2 {
                mean(src, &[0, row, image, image + row], &mut out);
                src += 2 * image;
            }
        }
    } else {
        let pad = row - w as isize * ps;
        let o = [
            0,
            ps,
            row,
            row + ps,
            image,
            ps + image,
            row + image,
            row + ps + image,
        ];
        for _ in 0..d / 2 {
            for _ in 0..h / 2 {
                for _ in 0..w / 2 {
                    mean(src, &o, &mut out);
                    src += 2 * ps;
                }
                src += pad + row;
            }
            src += image;
        }
    }
    out
}

/// One halving as libGLU's 3D core chooses it: the 2D filters at depth 1, else the 3D ones.
fn halve_3d(
    ty: &Typed,
    (w, h, d): (usize, usize, usize),
    img: &[u8],
    row: usize,
    image: usize,
) -> Vec<u8> {
    if d == 1 {
        return halve_typed(ty, w, h, img, row);
    }
    let (row, image) = (row as isize, image as isize);
    match &ty.packed {
        Some(p) => halve_packed_3d(p, (w, h, d), img, row, image),
        None => halve_elems_3d(ty, (w, h, d), img, row, image),
    }
}

/// libGLU's `scaleInternal3D`: the 3D box filter on 16-bit components (single-precision
/// coverage, wrapping indices), every output component `(total + 0.5) / volume` truncated.
#[allow(clippy::needless_range_loop)]
fn scale_internal_3d(
    c: usize,
    (win, hin, din): (i32, i32, i32),
    input: &[u16],
    (wout, hout, dout): (i32, i32, i32),
) -> Vec<u16> {
    let (wo, ho, wi, hi) = (wout as usize, hout as usize, win as usize, hin as usize);
    let mut out = vec![0u16; wo * ho * dout as usize * c];
    let convz = din as f32 / dout as f32;
    let convy = hin as f32 / hout as f32;
    let convx = win as f32 / wout as f32;
    let (halfconvx, halfconvy, halfconvz) = (convx / 2.0, convy / 2.0, convz / 2.0);
    // (low, high) of output index `i` along one axis, as libGLU computes them.
    let span = |conv: f32, half: f32, i: i32, shrink: bool| {
        let m = (f64::from(conv) * (f64::from(i) + 0.5)) as f32;
        if shrink {
            (m - half, m + half)
        } else {
            ((f64::from(m) - 0.5) as f32, (f64::from(m) + 0.5) as f32)
        }
    };
    // The covered cells along one axis: (wrapped index, fraction).
    let cells = |low: f32, high: f32, n: i32| {
        let mut v = Vec::new();
        let mut x = low;
        let mut xint = f64::from(x).floor() as i32;
        while x < high {
            let idx = (xint + n).rem_euclid(n);
            let pct = if high < (xint + 1) as f32 {
                high - x
            } else {
                (xint + 1) as f32 - x
            };
            v.push((idx, pct));
            xint += 1;
            x = xint as f32;
        }
        v
    };
    for d in 0..dout {
        let (lowz, highz) = span(convz, halfconvz, d, din > dout);
        let zs = cells(lowz, highz, din);
        for i in 0..hout {
            let (lowy, highy) = span(convy, halfconvy, i, hin > hout);
            let ys = cells(lowy, highy, hin);
            for j in 0..wout {
                let (lowx, highx) = span(convx, halfconvx, j, win > wout);
                let xs = cells(lowx, highx, win);
                let mut totals = [0f32; 4];
                let mut volume = 0f32;
                for &(zi, zp) in &zs {
                    for &(yi, yp) in &ys {
                        for &(xi, xp) in &xs {
                            let percent = xp * yp * zp;
                            volume += percent;
                            let temp = (xi as usize + yi as usize * wi + zi as usize * wi * hi) * c;
                            for k in 0..c {
                                totals[k] += f32::from(input[temp + k]) * percent;
                            }
                        }
                    }
                }
                let temp = (j as usize + i as usize * wo + d as usize * wo * ho) * c;
                for k in 0..c {
                    out[temp + k] = ((f64::from(totals[k]) + 0.5) / f64::from(volume)) as u16;
                }
            }
        }
    }
    out
}

/// libGLU's `gluScaleImage3D` as the 3D core calls it: `users` (the user's image past the
/// skips) read under the unpack modes `um` (after the core's resets), scaled to `to`, written
/// under the PACK_ modes `pm` into a buffer of libGLU's tight size `len` (bytes the pack
/// layout puts past it are dropped, where libGLU writes past its allocation).
#[allow(clippy::too_many_arguments)]
fn scale_image_3d(
    um: &crate::pixel_store::PixelModes,
    pm: &crate::pixel_store::PixelModes,
    format: u32,
    t: u32,
    from: (i32, i32, i32),
    users: &[u8],
    to: (i32, i32, i32),
    len: usize,
) -> Option<Vec<u8>> {
    let lin = place3(um, from.0, from.1, from.2, format, t)?;
    let mut before = Vec::new();
    for dd in 0..from.2 as usize {
        let pl = Place {
            rowsize: lin.row,
            start: lin.start + dd * lin.image,
            need: 0,
            bit0: 0,
        };
        before.extend(fill_image(
            um,
            &pl,
            from.0 as usize,
            from.1 as usize,
            format,
            t,
            users,
        ));
    }
    let after = scale_internal_3d(format_comps(format), from, &before, to);
    let lout = place3(pm, to.0, to.1, to.2, format, t)?;
    let rowbytes = to.0 as usize * bytes_per_element(t) * elements_per_group(format, t);
    let comps_row = to.0 as usize * format_comps(format);
    let mut out = vec![0u8; len];
    let mut scratch = vec![0u8; rowbytes];
    let one = Place {
        rowsize: rowbytes,
        start: 0,
        need: rowbytes,
        bit0: 0,
    };
    for (n, src) in after.chunks(comps_row).enumerate() {
        let (dd, ii) = (n / to.1 as usize, n % to.1 as usize);
        empty_image(pm, &one, to.0 as usize, 1, format, t, src, &mut scratch);
        let at = dd
            .checked_mul(lout.image)
            .and_then(|x| x.checked_add(ii.checked_mul(lout.row)?))
            .and_then(|x| x.checked_add(lout.start));
        let Some(at) = at.filter(|&a| a < len) else {
            continue;
        };
        let n = rowbytes.min(len - at);
        out[at..at + n].copy_from_slice(&scratch[..n]);
    }
    Some(out)
}

/// The UNPACK_ modes libGLU's 3D core restores at its end, in its order.
fn restore_unpack_3d(ctx: &mut Context, m: &crate::pixel_store::PixelModes) {
    ctx.pixel_storei(gl::UNPACK_ALIGNMENT, m.alignment);
    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, m.skip_rows);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, m.skip_pixels);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, m.row_length);
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, i32::from(m.swap_bytes));
    ctx.pixel_storei(gl::UNPACK_SKIP_IMAGES, m.skip_images);
    ctx.pixel_storei(gl::UNPACK_IMAGE_HEIGHT, m.image_height);
}

/// libGLU's `closestFit3D`: the nearest powers of two, all three halved while the driver's
/// PROXY_TEXTURE_3D answers width 0 for level 1 at half those sizes; 1x1x1 if even that does
/// not fit.
fn closest_fit_3d(
    ctx: &mut Context,
    (width, height, depth): (i32, i32, i32),
    internal_format: i32,
    format: u32,
    t: u32,
) -> (i32, i32, i32) {
    let mut w2 = nearest_power(width as u32);
    let mut h2 = nearest_power(height as u32);
    let mut d2 = nearest_power(depth as u32);
    loop {
        let half = |v: i32| if v > 1 { v >> 1 } else { v };
        let (w1, h1, d1) = (half(w2), half(h2), half(d2));
        ctx.tex_image_3d(
            gl::PROXY_TEXTURE_3D,
            1,
            internal_format,
            w1,
            h1,
            d1,
            0,
            format,
            t,
            None,
        );
        let mut pw = [0i32];
        ctx.get_tex_level_parameteriv(gl::PROXY_TEXTURE_3D, 1, gl::TEXTURE_WIDTH, &mut pw);
        if pw[0] != 0 {
            return (w2, h2, d2);
        }
        if w2 == 1 && h2 == 1 && d2 == 1 {
            return (1, 1, 1);
        }
        (w2, h2, d2) = (w1, h1, d1);
    }
}

/// The data checks of the 3D builders: `data` holds the image under the user's unpack modes
/// and, from the first byte past the skips, the tight image GL reads for level 0 (or
/// `gluScaleImage3D` reads) once libGLU has reset ROW_LENGTH, IMAGE_HEIGHT and the skips.
fn unpack_place_3d(
    ctx: &Context,
    (w, h, d): (i32, i32, i32),
    format: u32,
    t: u32,
    data: &[u8],
) -> Option<(Place3, Place3)> {
    let m = ctx.state().unpack;
    let user = place3(&m, w, h, d, format, t).filter(|p| p.need <= data.len())?;
    let tight = place3(&tight(&m), w, h, d, format, t)
        .filter(|p| p.need <= data.len().saturating_sub(user.start))?;
    Some((user, tight))
}

/// The argument checks both 3D builders make, in libGLU's order.
fn check_3d(format: u32, t: u32, (w, h, d): (i32, i32, i32)) -> i32 {
    let rc = check_mipmap_args(format, t);
    if rc != 0 {
        return rc;
    }
    if w < 1 || h < 1 || d < 1 {
        return GLU_INVALID_VALUE;
    }
    if t == gl::BITMAP {
        return GLU_INVALID_ENUM;
    }
    0
}

/// `gluBuild3DMipmaps`: a 3D mipmap pyramid of `data` (`width` x `height` x `depth` of
/// `format`/`type_`, read under the UNPACK_ modes, IMAGE_HEIGHT and SKIP_IMAGES included) for
/// `target` (TEXTURE_3D), as libGLU 9.0 builds it: sizes rounded to the nearest powers of two
/// (3·2ⁿ up) and halved together while the driver's PROXY_TEXTURE_3D answers width 0 for
/// level 1; level 0 is `data` itself when the sizes are already those (read by GL as a tight
/// image from the first byte past the skips: libGLU has set ROW_LENGTH and IMAGE_HEIGHT to
/// 0), else `data` scaled to them by `gluScaleImage3D` (which reads the image tight too, and
/// writes it under the PACK_ modes); each next level halves the last (the user's image itself
/// under the user's row length, image height and alignment for level 1). UNPACK_SKIP_ROWS,
/// SKIP_PIXELS, ROW_LENGTH, SKIP_IMAGES and IMAGE_HEIGHT are 0 and SWAP_BYTES false (from the
/// second upload) while the levels go up; all seven modes are restored at the end. Returns 0,
/// GLU_INVALID_VALUE for a size below 1 or data too short for the unpack modes,
/// GLU_INVALID_ENUM for a format or type libGLU does not take (STENCIL_INDEX and BITMAP
/// included), GLU_INVALID_OPERATION for a packed type of the wrong format.
/// Deviation: where libGLU uploads a level with rows not a multiple of UNPACK_ALIGNMENT
/// unpadded (GL then reads past its buffer), fixedgl pads the rows.
#[allow(clippy::too_many_arguments)]
pub fn build_3d_mipmaps(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    height: i32,
    depth: i32,
    format: u32,
    type_: u32,
    data: &[u8],
) -> i32 {
    let size = (width, height, depth);
    let rc = check_3d(format, type_, size);
    if rc != 0 {
        return rc;
    }
    if unpack_place_3d(ctx, size, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    let fit = closest_fit_3d(ctx, size, internal_format, format, type_);
    let levels = compute_log(fit.0)
        .max(compute_log(fit.1))
        .max(compute_log(fit.2));
    build_3d_core(
        ctx,
        target,
        internal_format,
        size,
        fit,
        format,
        type_,
        [0, 0, levels],
        data,
    )
}

/// `gluBuild3DMipmapLevels`: as [`build_3d_mipmaps`] without the size fit: levels `level` ..
/// `level` + log2(max(width, height, depth)) are made (a size that is not a power of two
/// counts -1, as libGLU's `computeLog`) and those within `base` ..= `max` uploaded.
/// GLU_INVALID_VALUE also where libGLU's `isLegalLevels` fails.
#[allow(clippy::too_many_arguments)]
pub fn build_3d_mipmap_levels(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    width: i32,
    height: i32,
    depth: i32,
    format: u32,
    type_: u32,
    level: i32,
    base: i32,
    max: i32,
    data: &[u8],
) -> i32 {
    let size = (width, height, depth);
    let rc = check_3d(format, type_, size);
    if rc != 0 {
        return rc;
    }
    let levels = compute_log(width)
        .max(compute_log(height))
        .max(compute_log(depth))
        .saturating_add(level);
    if !legal_levels(level, base, max, levels) {
        return GLU_INVALID_VALUE;
    }
    if unpack_place_3d(ctx, size, format, type_, data).is_none() {
        return GLU_INVALID_VALUE;
    }
    build_3d_core(
        ctx,
        target,
        internal_format,
        size,
        size,
        format,
        type_,
        [level, base, max],
        data,
    )
}

/// libGLU's `gluBuild3DMipmapLevelsCore`.
#[allow(clippy::too_many_arguments)]
fn build_3d_core(
    ctx: &mut Context,
    target: u32,
    internal_format: i32,
    (width, height, depth): (i32, i32, i32),
    (w2, h2, d2): (i32, i32, i32),
    format: u32,
    t: u32,
    [user, base, max]: [i32; 3],
    data: &[u8],
) -> i32 {
    let psm = ctx.state().unpack;
    let pack = ctx.state().pack;
    let Some((pl, tl)) = unpack_place_3d(ctx, (width, height, depth), format, t, data) else {
        return GLU_INVALID_VALUE;
    };
    let levels =
        i64::from(compute_log(w2).max(compute_log(h2)).max(compute_log(d2))) + i64::from(user);
    let user_ty = Typed::new(format, t, psm.swap_bytes);
    let ty = Typed::new(format, t, false);
    let gs = ty.gs;
    let size_of = |w: i32, h: i32, d: i32| (w as usize) * (h as usize) * (d as usize) * gs;
    let alignment = psm.alignment.max(1) as usize;
    let users = &data[pl.start..];
    let in_range = |l: i64| i64::from(base) <= l && l <= i64::from(max);
    let upload = |ctx: &mut Context, level: i64, (w, h, d): (i32, i32, i32), img: &[u8]| {
        if in_range(level) {
            let rowbytes = w as usize * gs;
            let up = pad_rows(
                &img[..size_of(w, h, d)],
                rowbytes,
                (h * d) as usize,
                alignment,
            );
            ctx.tex_image_3d(
                target,
                level as i32,
                internal_format,
                w,
                h,
                d,
                0,
                format,
                t,
                Some(&up),
            );
        }
    };

    ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, 0);
    ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, 0);
    ctx.pixel_storei(gl::UNPACK_SKIP_IMAGES, 0);
    ctx.pixel_storei(gl::UNPACK_IMAGE_HEIGHT, 0);
    let mut level = i64::from(user);
    // libGLU's two level buffers: `src` holds the level just made, `dst` is written next;
    // each keeps what earlier levels left past the current one.
    let (mut src, mut dst);
    let (mut nw, mut nh, mut nd);
    if (width, height, depth) == (w2, h2, d2) {
        if in_range(level) {
            ctx.tex_image_3d(
                target,
                level as i32,
                internal_format,
                width,
                height,
                depth,
                0,
                format,
                t,
                Some(&users[..tl.need]),
            );
        }
        if levels == 0 {
            restore_unpack_3d(ctx, &psm);
            return 0;
        }
        nw = (width / 2).max(1);
        nh = (height / 2).max(1);
        nd = (depth / 2).max(1);
        src = vec![0u8; size_of(nw, nh, nd)];
        let half = halve_3d(
            &user_ty,
            (width as usize, height as usize, depth as usize),
            users,
            pl.row,
            pl.image,
        );
        let n = half.len().min(src.len());
        src[..n].copy_from_slice(&half[..n]);
        dst = vec![0u8; size_of(nw, nh, nd)];
        level += 1;
    } else {
        let len = size_of(w2, h2, d2);
        let Some(scaled) = scale_image_3d(
            &tight(&psm),
            &pack,
            format,
            t,
            (width, height, depth),
            users,
            (w2, h2, d2),
            len,
        ) else {
            restore_unpack_3d(ctx, &psm);
            return GLU_INVALID_VALUE;
        };
        src = scaled;
        (nw, nh, nd) = (w2, h2, d2);
        dst = if levels != 0 {
            vec![0u8; size_of((nw / 2).max(1), (nh / 2).max(1), (nd / 2).max(1))]
        } else {
            Vec::new()
        };
    }
    let mut row = nw as usize * gs;
    let mut image = row * nh as usize;
    ctx.pixel_storei(gl::UNPACK_SWAP_BYTES, 0);
    upload(ctx, level, (nw, nh, nd), &src);
    level += 1;
    while level <= levels {
        let half = halve_3d(
            &ty,
            (nw as usize, nh as usize, nd as usize),
            &src,
            row,
            image,
        );
        let n = half.len().min(dst.len());
        dst[..n].copy_from_slice(&half[..n]);
        std::mem::swap(&mut src, &mut dst);
        if nw > 1 {
            nw /= 2;
            row /= 2;
        }
        if nh > 1 {
            nh /= 2;
            image = row * nh as usize;
        }
        if nd > 1 {
            nd /= 2;
        }
        upload(ctx, level, (nw, nh, nd), &src);
        level += 1;
    }
    restore_unpack_3d(ctx, &psm);
    0
}
