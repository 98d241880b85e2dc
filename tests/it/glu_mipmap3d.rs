//! `glu::build_3d_mipmaps` and `glu::build_3d_mipmap_levels` against the real libGLU (Mesa's
//! libGLU 9.0, `dlopen`ed, its GL calls going to llvmpipe through the GL backend's context):
//! libGLU builds a 3D texture on the driver, fixedgl's builder records its calls on a CPU
//! context and they are replayed on the same driver; every level read back with
//! glGetTexImage is byte for byte the same, and the CPU context's own levels
//! (`get_tex_image`) are within 1/255 of libGLU's. The argument errors are libGLU's.
//!
//! Without libGLU.so.1 or an EGL device the driver comparisons print `SKIPPED` and return.

use fixedgl::glu;
use fixedgl::{gl, Context};

/// Data shorter than the unpack modes need (IMAGE_HEIGHT and SKIP_IMAGES included) is
/// GLU_INVALID_VALUE with no GL call; BITMAP is GLU_INVALID_ENUM after the size check; level
/// numbers near i32::MAX end (GL's INVALID_VALUE for the levels past its range).
#[test]
fn build_3d_argument_checks_and_level_limits() {
    let mut ctx = Context::new(4, 4).unwrap();
    let src = [7u8; 256];
    let b3 = |ctx: &mut Context, w, h, d, f, t, data: &[u8]| {
        glu::build_3d_mipmaps(ctx, gl::TEXTURE_3D, gl::RGBA as i32, w, h, d, f, t, data)
    };
    assert_eq!(
        b3(&mut ctx, 4, 4, 5, gl::RGBA, gl::UNSIGNED_BYTE, &src),
        glu::GLU_INVALID_VALUE
    );
    assert_eq!(
        b3(
            &mut ctx,
            4,
            4,
            4,
            gl::LUMINANCE,
            gl::UNSIGNED_BYTE,
            &src[..63]
        ),
        glu::GLU_INVALID_VALUE
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.pixel_storei(gl::UNPACK_SKIP_IMAGES, 1);
    assert_eq!(
        b3(
            &mut ctx,
            4,
            4,
            4,
            gl::LUMINANCE,
            gl::UNSIGNED_BYTE,
            &src[..79]
        ),
        glu::GLU_INVALID_VALUE
    );
    ctx.pixel_storei(gl::UNPACK_SKIP_IMAGES, 0);
    ctx.pixel_storei(gl::UNPACK_IMAGE_HEIGHT, 8);
    assert_eq!(
        b3(
            &mut ctx,
            4,
            4,
            4,
            gl::LUMINANCE,
            gl::UNSIGNED_BYTE,
            &src[..111]
        ),
        glu::GLU_INVALID_VALUE
    );
    ctx.pixel_storei(gl::UNPACK_IMAGE_HEIGHT, 0);
    assert_eq!(
        b3(&mut ctx, 4, 4, 4, gl::COLOR_INDEX, gl::BITMAP, &src),
        glu::GLU_INVALID_ENUM
    );
    assert_eq!(
        b3(&mut ctx, 0, 4, 4, gl::COLOR_INDEX, gl::BITMAP, &src),
        glu::GLU_INVALID_VALUE
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // Nothing was uploaded by the failures.
    let mut w = [0];
    ctx.get_tex_level_parameteriv(gl::TEXTURE_3D, 0, gl::TEXTURE_WIDTH, &mut w);
    assert_eq!(w[0], 0);
    assert_eq!(
        b3(
            &mut ctx,
            4,
            4,
            4,
            gl::LUMINANCE,
            gl::UNSIGNED_BYTE,
            &src[..64]
        ),
        0
    );
    for (level, size) in [(0, 4), (1, 2), (2, 1), (3, 0)] {
        ctx.get_tex_level_parameteriv(gl::TEXTURE_3D, level, gl::TEXTURE_DEPTH, &mut w);
        assert_eq!(w[0], size, "level {level}");
    }
    let top = i32::MAX;
    let r = glu::build_3d_mipmap_levels(
        &mut ctx,
        gl::TEXTURE_3D,
        gl::RGBA as i32,
        2,
        2,
        2,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        top - 1,
        top - 1,
        top,
        &src,
    );
    assert_eq!(r, 0);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    // The unpack modes are what they were.
    let mut v = [0];
    ctx.get_integerv(gl::UNPACK_ALIGNMENT, &mut v);
    assert_eq!(v[0], 4);
}

#[cfg(feature = "gl")]
mod with_libglu {
    use super::*;
    use crate::glu_mipmap::{sweep_pairs, typed_image};
    use std::ffi::{c_char, c_int, c_void};

    extern "C" {
        fn dlopen(file: *const c_char, mode: c_int) -> *mut c_void;
        fn dlsym(handle: *mut c_void, name: *const c_char) -> *mut c_void;
    }
    const RTLD_NOW: c_int = 2;
    type Build3 = unsafe extern "C" fn(u32, i32, i32, i32, i32, u32, u32, *const c_void) -> i32;
    type Build3L = unsafe extern "C" fn(
        u32,
        i32,
        i32,
        i32,
        i32,
        u32,
        u32,
        i32,
        i32,
        i32,
        *const c_void,
    ) -> i32;

    struct LibGlu {
        build3: Build3,
        build3l: Build3L,
    }

    fn libglu() -> Option<LibGlu> {
        // SAFETY: dlopen/dlsym with NUL-terminated names, cast to GL/glu.h's signatures.
        unsafe {
            let h = dlopen(c"libGLU.so.1".as_ptr(), RTLD_NOW);
            if h.is_null() {
                eprintln!("SKIPPED: libGLU.so.1 not found");
                return None;
            }
            let b = dlsym(h, c"gluBuild3DMipmaps".as_ptr());
            let bl = dlsym(h, c"gluBuild3DMipmapLevels".as_ptr());
            if b.is_null() || bl.is_null() {
                eprintln!("SKIPPED: libGLU lacks gluBuild3DMipmaps");
                return None;
            }
            Some(LibGlu {
                build3: std::mem::transmute::<*mut c_void, Build3>(b),
                build3l: std::mem::transmute::<*mut c_void, Build3L>(bl),
            })
        }
    }

    type Modes = &'static [(u32, i32)];

    /// Sets `modes` on the driver's context, or returns them to their initial values.
    unsafe fn set_modes(raw: &fixedgl::glbackend::raw::Gl, modes: Modes, reset: bool) {
        for &(p, v) in modes {
            let v = if !reset {
                v
            } else if p == gl::UNPACK_ALIGNMENT || p == gl::PACK_ALIGNMENT {
                4
            } else {
                0
            };
            raw.PixelStorei(p, v);
        }
    }

    #[derive(Clone, Copy, Debug)]
    enum Builder {
        Mip3,
        /// (level, base, max)
        Levels3(i32, i32, i32),
    }

    /// Every level of the 3D texture `name` on the driver as RGBA UNSIGNED_BYTE; deletes it.
    unsafe fn driver_levels(raw: &fixedgl::glbackend::raw::Gl, name: u32) -> Vec<Vec<u8>> {
        raw.BindTexture(gl::TEXTURE_3D, name);
        raw.PixelStorei(gl::PACK_ALIGNMENT, 1);
        let mut out = Vec::new();
        for level in 0..14 {
            let (mut w, mut h, mut d) = (0, 0, 0);
            raw.GetTexLevelParameteriv(gl::TEXTURE_3D, level, gl::TEXTURE_WIDTH, &mut w);
            raw.GetTexLevelParameteriv(gl::TEXTURE_3D, level, gl::TEXTURE_HEIGHT, &mut h);
            raw.GetTexLevelParameteriv(gl::TEXTURE_3D, level, gl::TEXTURE_DEPTH, &mut d);
            if w == 0 {
                out.push(Vec::new());
                continue;
            }
            let mut buf = vec![0u8; (w * h * d) as usize * 4];
            raw.GetTexImage(
                gl::TEXTURE_3D,
                level,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                buf.as_mut_ptr().cast(),
            );
            out.push(buf);
        }
        raw.PixelStorei(gl::PACK_ALIGNMENT, 4);
        raw.BindTexture(gl::TEXTURE_3D, 0);
        raw.DeleteTextures(1, &name);
        out
    }

    /// One case both ways: libGLU on the driver (texture 901); fixedgl recorded on a CPU
    /// context (texture 900) and replayed on the driver. Returns both return codes, libGLU's
    /// levels, the replayed levels and the CPU context's own levels.
    #[allow(clippy::type_complexity)]
    fn run(
        lib: &LibGlu,
        backend: &mut fixedgl::glbackend::GlBackend,
        b: Builder,
        (format, t): (u32, u32),
        (w, h, d): (i32, i32, i32),
        modes: Modes,
        src: &[u8],
    ) -> (i32, i32, Vec<Vec<u8>>, Vec<Vec<u8>>, Vec<Vec<u8>>) {
        let target = gl::TEXTURE_3D;
        let ifmt = gl::RGBA as i32;
        let p = src.as_ptr().cast();
        // SAFETY: the backend's context is current; libGLU reads `src` (larger than any
        // layout of these cases, and than any pointer walk of libGLU's over it) under the
        // modes set here, reset afterwards; the texture is the test's and deleted after.
        let (want_rc, want) = unsafe {
            let raw = backend.raw();
            raw.BindTexture(target, 901);
            set_modes(raw, modes, false);
            let rc = match b {
                Builder::Mip3 => (lib.build3)(target, ifmt, w, h, d, format, t, p),
                Builder::Levels3(l, lo, hi) => {
                    (lib.build3l)(target, ifmt, w, h, d, format, t, l, lo, hi, p)
                }
            };
            set_modes(raw, modes, true);
            (rc, driver_levels(raw, 901))
        };
        while backend.get_error() != gl::NO_ERROR {}
        let mut ctx = Context::new(4, 4).unwrap();
        ctx.start_recording();
        ctx.bind_texture(target, 900);
        for &(p, v) in modes {
            ctx.pixel_storei(p, v);
        }
        let rc = match b {
            Builder::Mip3 => glu::build_3d_mipmaps(&mut ctx, target, ifmt, w, h, d, format, t, src),
            Builder::Levels3(l, lo, hi) => glu::build_3d_mipmap_levels(
                &mut ctx, target, ifmt, w, h, d, format, t, l, lo, hi, src,
            ),
        };
        let calls = ctx.stop_recording();
        backend.replay(&calls);
        while backend.get_error() != gl::NO_ERROR {}
        // SAFETY: as above; texture 900 is the replay's.
        let replayed = unsafe {
            let raw = backend.raw();
            set_modes(raw, modes, true);
            driver_levels(raw, 900)
        };
        ctx.pixel_storei(gl::PACK_ALIGNMENT, 1);
        let mut cpu = Vec::new();
        for level in 0..14 {
            let (mut lw, mut lh, mut ld) = ([0], [0], [0]);
            ctx.get_tex_level_parameteriv(target, level, gl::TEXTURE_WIDTH, &mut lw);
            ctx.get_tex_level_parameteriv(target, level, gl::TEXTURE_HEIGHT, &mut lh);
            ctx.get_tex_level_parameteriv(target, level, gl::TEXTURE_DEPTH, &mut ld);
            if lw[0] == 0 {
                cpu.push(Vec::new());
                continue;
            }
            let mut buf = vec![0u8; (lw[0] * lh[0] * ld[0]) as usize * 4];
            ctx.get_tex_image(target, level, gl::RGBA, gl::UNSIGNED_BYTE, &mut buf);
            cpu.push(buf);
        }
        (want_rc, rc, want, replayed, cpu)
    }

    /// libGLU's `nearestPower`.
    fn nearest_power(mut v: i32) -> i32 {
        let mut i = 1;
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

    /// Whether libGLU's level `l` of a case is not defined by its own data, so not compared:
    /// (a) a level it made (scaled or halved) whose tight rows are not a multiple of
    /// UNPACK_ALIGNMENT `align`: libGLU uploads it unpadded and GL reads past its rows, where
    /// fixedgl pads them; (b) for a packed type, every level after a 1-high (1-wide) slice
    /// at least 4 wide (high) and more than 1 deep was halved: libGLU's
    /// `halveImagePackedPixelSlice` steps two images a pixel pair and reads past its buffer.
    fn libglu_undefined(
        b: Builder,
        size: (i32, i32, i32),
        (format, t): (u32, u32),
        align: i32,
        l: usize,
    ) -> bool {
        let (first, mut dims) = match b {
            Builder::Mip3 => (
                0,
                (
                    nearest_power(size.0),
                    nearest_power(size.1),
                    nearest_power(size.2),
                ),
            ),
            Builder::Levels3(level, ..) => (level as usize, size),
        };
        let from_user = dims == size;
        let packed = !matches!(
            t,
            gl::UNSIGNED_BYTE
                | gl::BYTE
                | gl::UNSIGNED_SHORT
                | gl::SHORT
                | gl::UNSIGNED_INT
                | gl::INT
                | gl::FLOAT
        );
        let gs = match t {
            gl::UNSIGNED_BYTE | gl::BYTE => 1,
            gl::UNSIGNED_SHORT | gl::SHORT => 2,
            gl::UNSIGNED_INT | gl::INT | gl::FLOAT => 4,
            gl::UNSIGNED_BYTE_3_3_2 | gl::UNSIGNED_BYTE_2_3_3_REV => 1,
            gl::UNSIGNED_INT_8_8_8_8
            | gl::UNSIGNED_INT_8_8_8_8_REV
            | gl::UNSIGNED_INT_10_10_10_2
            | gl::UNSIGNED_INT_2_10_10_10_REV => 4,
            _ => 2,
        } * if packed {
            1
        } else {
            match format {
                gl::RGB => 3,
                gl::RGBA | gl::BGRA => 4,
                gl::LUMINANCE_ALPHA => 2,
                _ => 1,
            }
        };
        let mut tainted = false;
        for k in first..=l {
            if k == l {
                let unaligned = !(k == first && from_user) && (dims.0 * gs) % align != 0;
                return tainted || unaligned;
            }
            let (w, h, d) = dims;
            if packed && d > 1 && ((h == 1 && w >= 4) || (w == 1 && h >= 4)) {
                tainted = true;
            }
            dims = ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
        }
        false
    }

    const MODES_A: Modes = &[(gl::UNPACK_ALIGNMENT, 1)];
    const MODES_B: Modes = &[
        (gl::UNPACK_ALIGNMENT, 2),
        (gl::UNPACK_ROW_LENGTH, 20),
        (gl::UNPACK_SKIP_ROWS, 1),
        (gl::UNPACK_SKIP_PIXELS, 2),
        (gl::UNPACK_IMAGE_HEIGHT, 19),
        (gl::UNPACK_SKIP_IMAGES, 1),
        (gl::UNPACK_SWAP_BYTES, 1),
    ];

    /// Sizes left out of the sweep because libGLU's own result is not defined there: a size
    /// scaled to a width whose rows PACK_ALIGNMENT pads (libGLU's `emptyImage3D` writes past
    /// its tight buffer and corrupts its heap: 1x9x3 aborts the process in realloc), and a
    /// scaled 1-high image halved at depth > 1 twice (7x1x5: the stale image stride reads past
    /// libGLU's smaller level buffer, heap contents).
    ///
    /// gluBuild3DMipmaps and gluBuild3DMipmapLevels over every format/type pair libGLU's 3D
    /// builders take, sizes that are powers of two and not (scaled), 1 deep, deeper than wide,
    /// 1-wide/1-high slices and columns, two sets of unpack modes (the second with row length,
    /// image height, skips of rows, pixels and images, alignment 2 and SWAP_BYTES): return
    /// codes equal, every level replayed on llvmpipe byte for byte libGLU's, fixedgl's own
    /// textures within 1/255 of them.
    #[test]
    fn build_3d_every_type_matches_libglu() {
        let Some(lib) = libglu() else { return };
        let Some(mut backend) = crate::common::test_backend(8, 8) else {
            return;
        };
        let cases: &[(Builder, (i32, i32, i32))] = &[
            (Builder::Mip3, (8, 8, 8)),
            (Builder::Mip3, (6, 5, 3)),
            (Builder::Mip3, (4, 4, 1)),
            (Builder::Mip3, (5, 3, 1)),
            (Builder::Mip3, (4, 4, 16)),
            (Builder::Mip3, (2, 2, 8)),
            (Builder::Mip3, (3, 7, 2)),
            (Builder::Mip3, (16, 2, 4)),
            (Builder::Mip3, (1, 1, 4)),
            (Builder::Mip3, (7, 2, 5)),
            (Builder::Mip3, (1, 8, 4)),
            (Builder::Levels3(1, 2, 4), (8, 4, 8)),
            (Builder::Levels3(0, 0, 2), (5, 4, 4)),
            (Builder::Levels3(0, 0, 3), (8, 8, 2)),
        ];
        let (mut runs, mut levels, mut cpu_off, mut skipped) = (0, 0, 0, 0);
        let mut cpu_max = 0u8;
        let mut bad = Vec::new();
        let pairs: Vec<(u32, u32)> = sweep_pairs()
            .into_iter()
            .filter(|&(_, t)| t != gl::BITMAP)
            .collect();
        for (pi, &pair) in pairs.iter().enumerate() {
            for (ci, &(b, size)) in cases.iter().enumerate() {
                for (mi, modes) in [MODES_A, MODES_B].into_iter().enumerate() {
                    let seed = (pi * 131 + ci * 11 + mi) as u32;
                    let src = typed_image(1 << 18, seed, pair.0, pair.1);
                    let (wrc, grc, want, replayed, cpu) =
                        run(&lib, &mut backend, b, pair, size, modes, &src);
                    runs += 1;
                    let tag = format!(
                        "{b:?} {size:?} format {:#x} type {:#x} modes {mi}",
                        pair.0, pair.1
                    );
                    if wrc != grc {
                        bad.push(format!("{tag}: rc {wrc} / {grc}"));
                        continue;
                    }
                    let align = if mi == 0 { 1 } else { 2 };
                    let skip = |l: usize| libglu_undefined(b, size, pair, align, l);
                    for (l, (a, r)) in want.iter().zip(&replayed).enumerate() {
                        if skip(l) {
                            skipped += usize::from(!a.is_empty());
                            continue;
                        }
                        if a != r {
                            let at = a.iter().zip(r).position(|(x, y)| x != y);
                            bad.push(format!(
                                "{tag}: level {l} differs (sizes {} / {}, first {at:?})",
                                a.len(),
                                r.len()
                            ));
                        }
                        levels += usize::from(!a.is_empty());
                    }
                    if want != cpu {
                        cpu_off += 1;
                        let mut case_max = 0u8;
                        for (l, (a, c)) in want.iter().zip(&cpu).enumerate() {
                            if skip(l) {
                                continue;
                            }
                            if a.len() != c.len() {
                                case_max = 255;
                            }
                            for (x, y) in a.iter().zip(c) {
                                case_max = case_max.max(x.abs_diff(*y));
                            }
                        }
                        if case_max > 1 {
                            bad.push(format!("{tag}: fixedgl's texture {case_max} off libGLU's"));
                        }
                        cpu_max = cpu_max.max(case_max);
                    }
                }
            }
        }
        eprintln!(
            "3D builders: {runs} cases, {levels} levels compared, {skipped} where libGLU's result is undefined left out; CPU textures differing from libGLU's: {cpu_off} (at most {cpu_max} of 255)"
        );
        assert!(bad.is_empty(), "{} differ:\n{}", bad.len(), bad.join("\n"));
        assert!(levels > runs, "levels were built");
    }

    /// The 3D builders' argument errors as libGLU returns them.
    #[test]
    fn build_3d_errors_match_libglu() {
        let Some(lib) = libglu() else { return };
        let Some(mut backend) = crate::common::test_backend(8, 8) else {
            return;
        };
        type ErrCase = (Builder, u32, u32, (i32, i32, i32));
        let cases: &[ErrCase] = &[
            (Builder::Mip3, 0x1234, gl::UNSIGNED_BYTE, (4, 4, 4)),
            (Builder::Mip3, gl::RGBA, 0x1234, (4, 4, 4)),
            (
                Builder::Mip3,
                gl::STENCIL_INDEX,
                gl::UNSIGNED_BYTE,
                (4, 4, 4),
            ),
            (Builder::Mip3, gl::RGBA, gl::UNSIGNED_SHORT_5_6_5, (4, 4, 4)),
            (Builder::Mip3, gl::RGB, gl::UNSIGNED_INT_8_8_8_8, (4, 4, 4)),
            (Builder::Mip3, gl::COLOR_INDEX, gl::BITMAP, (4, 4, 4)),
            (Builder::Mip3, gl::COLOR_INDEX, gl::BITMAP, (4, 0, 4)),
            (Builder::Mip3, gl::RGBA, gl::UNSIGNED_BYTE, (4, 4, 0)),
            (Builder::Mip3, gl::RGBA, gl::UNSIGNED_BYTE, (-1, 4, 4)),
            (
                Builder::Levels3(0, 1, 0),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (4, 4, 4),
            ),
            (
                Builder::Levels3(2, 1, 3),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (4, 4, 4),
            ),
            (
                Builder::Levels3(0, 0, 3),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (4, 4, 4),
            ),
            (
                Builder::Levels3(0, 0, 4),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (4, 2, 8),
            ),
            (
                Builder::Levels3(0, 0, 1),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (5, 3, 7),
            ),
            (
                Builder::Levels3(0, -1, 2),
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                (4, 4, 4),
            ),
            (
                Builder::Levels3(0, 0, 0),
                gl::COLOR_INDEX,
                gl::BITMAP,
                (4, 4, 4),
            ),
        ];
        let src = vec![0u8; 4096];
        for &(b, f, t, size) in cases {
            let (want, got, ..) = run(&lib, &mut backend, b, (f, t), size, &[], &src);
            assert_eq!(want, got, "{b:?} format {f:#x} type {t:#x} {size:?}");
            assert_ne!(
                got, 0,
                "{b:?} format {f:#x} type {t:#x} {size:?} is an error"
            );
        }
    }
}
