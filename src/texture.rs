//! Texture state as plain data (GL 2.1 §3.8, tables 6.15 to 6.19): texture objects with their
//! images and parameters, the per-unit environment and coordinate generation, the unpacking of
//! TexImage's client data into texels (§3.8.1: groups read by `crate::pixels`, as DrawPixels
//! reads them), and helpers that make textures without data files.
//!
//! Design decision: a texture object lives behind an `Arc`, so `State` stays cheap to clone (a
//! PushAttrib or a test's "state unchanged" snapshot shares the images) and a flush hands the
//! bound object to the CPU sampler without copying; a change goes through `Arc::make_mut`, which
//! copies only while someone else still holds the old version. Images are stored as RGBA `f32`
//! texels, bottom row first, already reduced to the internal format's precision (8 bits per
//! colour component, as llvmpipe stores them; 24 bits of depth), with the components the base
//! format keeps (table 3.15: L in R, I in R, depth in R).

use std::collections::BTreeMap;
use std::sync::Arc;

use glam::Vec4;

use crate::cpu::pixels::{RowRun, Src};
use crate::gl;
use crate::pixel_store::PixelModes;
use crate::pixels::{Format, Group, Image, ImageLayout, PixelMaps, PixelTransfer};
use crate::state::MAX_TEXTURE_UNITS;

/// `MAX_TEXTURE_SIZE` (as `glGet` reports it).
pub const MAX_TEXTURE_SIZE: i32 = 2048;
/// Mipmap levels a 2D texture can hold: log2(MAX_TEXTURE_SIZE) + 1.
pub const MAX_LEVELS: usize = 12;
/// `MAX_TEXTURE_LOD_BIAS` (Mesa's value).
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;

/// One mipmap level's image (GL 2.1 table 6.17).
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// TEXTURE_WIDTH.
    pub width: i32,
    /// TEXTURE_HEIGHT (1 for a 1D image).
    pub height: i32,
    /// TEXTURE_DEPTH (1 for a 1D or 2D image).
    pub depth: i32,
    /// The internal format as the application gave it (`TEXTURE_INTERNAL_FORMAT`).
    pub internal_format: i32,
    /// The base internal format (table 3.15): ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY, RGB,
    /// RGBA, DEPTH_COMPONENT or GL_EXT_packed_depth_stencil's DEPTH_STENCIL (the depth in R,
    /// the stencil index in G as an integer in [0, 255]).
    pub base: u32,
    /// `width * height * depth` texels, bottom row first (t = 0 first, §3.8.1), the images of
    /// a 3D texture one after the other (r = 0 first). Shared (`Arc`), so that copying the
    /// object to change a parameter while a draw still holds it (`Arc::make_mut` of the
    /// object) does not copy the images; a change to the texels copies only a shared level.
    pub texels: Arc<Vec<[f32; 4]>>,
}

impl Level {
    /// The texel at (i, j), which must be inside the image.
    #[inline(always)]
    pub fn texel(&self, i: i32, j: i32) -> [f32; 4] {
        let k = (j * self.width + i) as usize;
        self.texels.get(k).copied().unwrap_or([0.0; 4])
    }

    /// The texel at (i, j, k) of a 3D image, which must be inside it.
    #[inline(always)]
    pub fn texel3(&self, i: i32, j: i32, k: i32) -> [f32; 4] {
        let n = ((k * self.height + j) * self.width + i) as usize;
        self.texels.get(n).copied().unwrap_or([0.0; 4])
    }
}

/// The faces of a target's objects: 6 for TEXTURE_CUBE_MAP, else 1.
pub fn faces(target: u32) -> usize {
    if target == gl::TEXTURE_CUBE_MAP {
        6
    } else {
        1
    }
}

/// For an image target (TexImage's `target`): the binding target of the object it names and
/// the face (TEXTURE_CUBE_MAP_POSITIVE_X .. NEGATIVE_Z are faces 0 to 5 of TEXTURE_CUBE_MAP).
pub fn image_binding(target: u32) -> (u32, usize) {
    match target {
        gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z => (
            gl::TEXTURE_CUBE_MAP,
            (target - gl::TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
        ),
        t => (t, 0),
    }
}

/// The number of texture coordinates a target's images have: 1, 2 or 3 (a cube map's faces
/// are 2D images).
pub fn target_dims(target: u32) -> usize {
    match target {
        gl::TEXTURE_1D | gl::PROXY_TEXTURE_1D => 1,
        gl::TEXTURE_3D | gl::PROXY_TEXTURE_3D => 3,
        _ => 2,
    }
}

/// For a proxy target, the index in [`TARGETS`] of the target it stands for.
pub fn proxy_index(target: u32) -> Option<usize> {
    match target {
        gl::PROXY_TEXTURE_1D => Some(0),
        gl::PROXY_TEXTURE_2D => Some(1),
        gl::PROXY_TEXTURE_3D => Some(2),
        gl::PROXY_TEXTURE_CUBE_MAP => Some(3),
        _ => None,
    }
}

/// The texture targets of GL 1.2/1.3 (§3.8.12), in the order of their bindings
/// (TEXTURE_BINDING_1D, _2D, _3D, _CUBE_MAP) and of §3.8.15's precedence, lowest first.
pub const TARGETS: [u32; 4] = [
    gl::TEXTURE_1D,
    gl::TEXTURE_2D,
    gl::TEXTURE_3D,
    gl::TEXTURE_CUBE_MAP,
];

/// The index of `target` in [`TARGETS`], or None for anything else (a proxy target or a cube-map
/// face is not a binding target: INVALID_ENUM, §3.8.12).
pub fn target_index(target: u32) -> Option<usize> {
    TARGETS.iter().position(|&t| t == target)
}

/// A texture object (GL 2.1 §3.8.12, table 6.16): images and sampling parameters.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct TexObject {
    /// The target the object was first bound to (§3.8.12: fixed from then on; binding it to
    /// another target is INVALID_OPERATION). Only TEXTURE_2D objects can hold images yet (no
    /// TexImage1D/3D or cube-map faces: issue #14).
    pub target: u32,
    /// Levels 0 to MAX_LEVELS - 1; `None` where no image was specified.
    pub levels: Vec<Option<Level>>,
    pub min_filter: u32,
    pub mag_filter: u32,
    pub wrap_s: u32,
    pub wrap_t: u32,
    pub wrap_r: u32,
    pub border_color: Vec4,
    pub priority: f32,
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    /// TEXTURE_LOD_BIAS (GL 1.4, table 6.16): any float, added to the unit's bias in λ
    /// (§3.8.8 eq. 3.18, where the sum is clamped).
    pub lod_bias: f32,
    pub generate_mipmap: bool,
    pub compare_mode: u32,
    pub compare_func: u32,
    pub depth_texture_mode: u32,
}

impl TexObject {
    /// A new object of `target` with table 6.16's initial values (a cube map has six faces of
    /// MAX_LEVELS levels each).
    pub fn new(target: u32) -> Self {
        Self {
            target,
            levels: vec![None; MAX_LEVELS * faces(target)],
            ..Self::default()
        }
    }

    /// Level `l` of face `face` (0 to 5 in TEXTURE_CUBE_MAP_POSITIVE_X .. NEGATIVE_Z order;
    /// 0 for the other targets), if specified.
    pub fn face_level(&self, face: usize, l: i32) -> Option<&Level> {
        let l = usize::try_from(l).ok().filter(|&l| l < MAX_LEVELS)?;
        self.levels
            .get(face * MAX_LEVELS + l)
            .and_then(Option::as_ref)
    }

    /// The slot of level `l` of face `face`, to store into.
    pub fn slot_mut(&mut self, face: usize, l: i32) -> Option<&mut Option<Level>> {
        let l = usize::try_from(l).ok().filter(|&l| l < MAX_LEVELS)?;
        self.levels.get_mut(face * MAX_LEVELS + l)
    }
}

impl Default for TexObject {
    /// Table 6.16's initial values, for a TEXTURE_2D object.
    fn default() -> Self {
        Self {
            target: gl::TEXTURE_2D,
            levels: vec![None; MAX_LEVELS],
            min_filter: gl::NEAREST_MIPMAP_LINEAR,
            mag_filter: gl::LINEAR,
            wrap_s: gl::REPEAT,
            wrap_t: gl::REPEAT,
            wrap_r: gl::REPEAT,
            border_color: Vec4::ZERO,
            priority: 1.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            generate_mipmap: false,
            compare_mode: gl::NONE,
            compare_func: gl::LEQUAL,
            depth_texture_mode: gl::LUMINANCE,
        }
    }
}

/// Does `filter` use mipmaps (§3.8.8)?
pub fn is_mipmap_filter(filter: u32) -> bool {
    matches!(
        filter,
        gl::NEAREST_MIPMAP_NEAREST
            | gl::LINEAR_MIPMAP_NEAREST
            | gl::NEAREST_MIPMAP_LINEAR
            | gl::LINEAR_MIPMAP_LINEAR
    )
}

/// A texture object's parameters without its images: what PushAttrib(TEXTURE_BIT) saves for
/// each unit's bound object of every target (GL 2.1 §6.1.14, table 6.16 rows whose attribute is "texture").
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct TexParams {
    pub min_filter: u32,
    pub mag_filter: u32,
    pub wrap_s: u32,
    pub wrap_t: u32,
    pub wrap_r: u32,
    pub border_color: Vec4,
    pub priority: f32,
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    pub generate_mipmap: bool,
    pub compare_mode: u32,
    pub compare_func: u32,
    pub depth_texture_mode: u32,
}

impl TexObject {
    /// The parameters of table 6.16 (everything but the images).
    pub fn params(&self) -> TexParams {
        TexParams {
            min_filter: self.min_filter,
            mag_filter: self.mag_filter,
            wrap_s: self.wrap_s,
            wrap_t: self.wrap_t,
            wrap_r: self.wrap_r,
            border_color: self.border_color,
            priority: self.priority,
            min_lod: self.min_lod,
            max_lod: self.max_lod,
            base_level: self.base_level,
            max_level: self.max_level,
            lod_bias: self.lod_bias,
            generate_mipmap: self.generate_mipmap,
            compare_mode: self.compare_mode,
            compare_func: self.compare_func,
            depth_texture_mode: self.depth_texture_mode,
        }
    }

    /// Sets the parameters of table 6.16 from `p`, keeping the images.
    pub fn set_params(&mut self, p: &TexParams) {
        self.min_filter = p.min_filter;
        self.mag_filter = p.mag_filter;
        self.wrap_s = p.wrap_s;
        self.wrap_t = p.wrap_t;
        self.wrap_r = p.wrap_r;
        self.border_color = p.border_color;
        self.priority = p.priority;
        self.min_lod = p.min_lod;
        self.max_lod = p.max_lod;
        self.base_level = p.base_level;
        self.max_level = p.max_level;
        self.lod_bias = p.lod_bias;
        self.generate_mipmap = p.generate_mipmap;
        self.compare_mode = p.compare_mode;
        self.compare_func = p.compare_func;
        self.depth_texture_mode = p.depth_texture_mode;
    }
}

impl TexObject {
    /// The level `l` (of face 0 for a cube map), if specified.
    pub fn level(&self, l: i32) -> Option<&Level> {
        self.face_level(0, l)
    }

    /// The last level a complete mipmap array uses: q = min(p, max_level) with
    /// p = floor(log2(max(w, h))) + base_level (§3.8.8), or None without a base image.
    pub fn last_level(&self) -> Option<i32> {
        let b = self.level(self.base_level)?;
        let size = b.width.max(b.height).max(b.depth).max(1);
        let p = 31 - size.leading_zeros() as i32 + self.base_level;
        Some(p.min(self.max_level))
    }

    /// Texture completeness (§3.8.10): the base image exists with positive sizes and, when the
    /// minification filter needs mipmaps, every level from the base to q exists with halved
    /// sizes and the base's internal format, and base_level <= max_level.
    pub fn is_complete(&self) -> bool {
        let n = faces(self.target);
        // Cube completeness (§3.8.10): six square base images of one size and internal format.
        if n == 6 {
            let Some(b) = self.level(self.base_level) else {
                return false;
            };
            let same = (0..6).all(|f| {
                self.face_level(f, self.base_level).is_some_and(|l| {
                    l.width == b.width
                        && l.height == b.height
                        && l.width == l.height
                        && l.internal_format == b.internal_format
                })
            });
            if !same {
                return false;
            }
        }
        (0..n).all(|f| self.face_complete(f))
    }

    /// [`TexObject::is_complete`] for the images of one face.
    fn face_complete(&self, face: usize) -> bool {
        let Some(base) = self.face_level(face, self.base_level) else {
            return false;
        };
        if base.width <= 0 || base.height <= 0 || base.depth <= 0 {
            return false;
        }
        if !is_mipmap_filter(self.min_filter) {
            return true;
        }
        if self.base_level > self.max_level {
            return false;
        }
        let Some(q) = self.last_level() else {
            return false;
        };
        let (mut w, mut h, mut d) = (base.width, base.height, base.depth);
        for l in self.base_level + 1..=q {
            w = (w / 2).max(1);
            h = (h / 2).max(1);
            d = (d / 2).max(1);
            match self.face_level(face, l) {
                Some(lv)
                    if lv.width == w
                        && lv.height == h
                        && lv.depth == d
                        && lv.internal_format == base.internal_format => {}
                _ => return false,
            }
        }
        true
    }

    /// GENERATE_MIPMAP (§3.8.8): levels base+1 ..= q recomputed from the base level with a 2x2
    /// box filter (Mesa's choice; the spec leaves the filter open), each reduced to the format's
    /// precision.
    pub fn generate_mipmaps(&mut self) {
        let Some(q) = self.last_level() else {
            return;
        };
        for face in 0..faces(self.target) {
            let mut l = self.base_level;
            while l < q {
                let Some(src) = self.face_level(face, l) else {
                    break;
                };
                let next = halve(src);
                let Some(slot) = self.slot_mut(face, l + 1) else {
                    break;
                };
                *slot = Some(next);
                l += 1;
            }
        }
    }
}

/// The next-smaller mipmap image of `src`: each texel the mean of the (up to) 2x2x2 texels
/// above it.
pub fn halve(src: &Level) -> Level {
    let w = (src.width / 2).max(1);
    let h = (src.height / 2).max(1);
    let d = (src.depth / 2).max(1);
    let mut texels = Vec::with_capacity((w * h * d) as usize);
    let fx = if src.width > 1 { 2 } else { 1 };
    let fy = if src.height > 1 { 2 } else { 1 };
    let fz = if src.depth > 1 { 2 } else { 1 };
    let n = Vec4::splat((fx * fy * fz) as f32);
    for k in 0..d {
        for j in 0..h {
            for i in 0..w {
                // Each component's sum from zero in the order (dk, dj, di), then over n: the
                // same f32 additions and division as component by component.
                let mut sum = Vec4::ZERO;
                for dk in 0..fz {
                    for dj in 0..fy {
                        for di in 0..fx {
                            sum += Vec4::from(src.texel3(i * fx + di, j * fy + dj, k * fz + dk));
                        }
                    }
                }
                texels.push(quantize(src.base, (sum / n).to_array()));
            }
        }
    }
    Level {
        width: w,
        height: h,
        depth: d,
        internal_format: src.internal_format,
        base: src.base,
        texels: texels.into(),
    }
}

/// Whether base format `base` is a depth format (DEPTH_COMPONENT, or DEPTH_STENCIL, whose
/// depth is sampled and whose stencil is not: GL_EXT_packed_depth_stencil).
pub fn is_depth(base: u32) -> bool {
    matches!(base, gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL)
}

/// Reduces a texel to the stored precision: 8-bit unsigned normalised colour, 24-bit depth,
/// an 8-bit stencil index (DEPTH_STENCIL's G, an integer).
pub fn quantize(base: u32, t: [f32; 4]) -> [f32; 4] {
    let s = 16_777_215.0;
    let mut out = [0.0f32; 4];
    if base == gl::DEPTH_COMPONENT {
        for (o, c) in out.iter_mut().zip(t) {
            *o = round_small(c.clamp(0.0, 1.0) * s) / s;
        }
        out
    } else if base == gl::DEPTH_STENCIL {
        let d = round_small(t[0].clamp(0.0, 1.0) * s) / s;
        let st = if t[1].is_nan() {
            0.0
        } else {
            round_small(t[1].clamp(0.0, 255.0))
        };
        [d, st, 0.0, 0.0]
    } else {
        quantize_colour(t).unwrap_or_else(|| {
            for (o, c) in out.iter_mut().zip(t) {
                *o = round_small(c.clamp(0.0, 1.0) * 255.0) / 255.0;
            }
            out
        })
    }
}

/// `quantize`'s colour components, `round_small(c.clamp(0, 1)·255) / 255` each, on four SSE2
/// lanes when none of `t` is NaN (else None: the scalar expression then): `f32::clamp` as
/// `maxps(0, c)` then `minps(1, ·)` (those operand orders keep −0 as −0), the truncation by
/// `cvttps2dq` (exact on [−0, 255]), one more where the fraction is at least 1/2, `x`'s sign,
/// then `divps`. The same bits as the scalar expression (test `quantize_colour_is_the_scalar`).
#[inline(always)]
fn quantize_colour(t: [f32; 4]) -> Option<[f32; 4]> {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE2 is part of the x86-64 baseline; the only memory read is `t` and written
    // `out`, four f32 each.
    unsafe {
        use std::arch::x86_64::*;
        let v = _mm_loadu_ps(t.as_ptr());
        if _mm_movemask_ps(_mm_cmpunord_ps(v, v)) != 0 {
            return None;
        }
        let c = _mm_min_ps(_mm_set1_ps(1.0), _mm_max_ps(_mm_setzero_ps(), v));
        let x = _mm_mul_ps(c, _mm_set1_ps(255.0));
        let tr = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
        let up = _mm_cmpge_ps(_mm_sub_ps(x, tr), _mm_set1_ps(0.5));
        let r = _mm_add_ps(tr, _mm_and_ps(up, _mm_set1_ps(1.0)));
        let sign = _mm_set1_ps(-0.0);
        let r = _mm_or_ps(_mm_andnot_ps(sign, r), _mm_and_ps(sign, x));
        let mut out = [0.0f32; 4];
        _mm_storeu_ps(out.as_mut_ptr(), _mm_div_ps(r, _mm_set1_ps(255.0)));
        Some(out)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = t;
        None
    }
}

/// `x.round()` (half away from zero) for `x` in [-0, 2^24] or NaN, the values [`quantize`]
/// rounds, without libm's `roundf` (what `f32::round` is on the x86-64 baseline: a call per
/// component of every texel stored): the truncation by `as i32` (exact below 2^31), plus one
/// where the fraction x - t (exact) is at least 1/2, with x's sign (so -0 stays -0). A NaN takes
/// `f32::round` itself. Checked against `f32::round` in the test `round_small_is_round`.
#[inline(always)]
fn round_small(x: f32) -> f32 {
    if x.is_nan() {
        return x.round();
    }
    let t = x as i32 as f32;
    let r = if x - t >= 0.5 { t + 1.0 } else { t };
    r.copysign(x)
}

/// The texel CopyTexImage / CopyTexSubImage store (§3.8.2) for a framebuffer pixel `px`
/// (colour, 24-bit depth, stencil as `Framebuffer::pixel_in` gives them; `None` outside the
/// framebuffer, read as zero) in a texture of base format `base`: depth d as d / (2^24 - 1),
/// DEPTH_STENCIL's stencil as an integer, colour v as v / 255 through [`keep`].
///
/// It is `quantize(base, ..)` of that value without the call: every such value is already at the
/// stored precision, so [`quantize`] returns it bit for bit (for all 2^24 depths, checked by the
/// unit test `fb_texels_are_quantized`, and all 256 colour values). That spares the per-texel
/// `roundf` library call (f32::round on the x86-64 baseline) that dominated a shadow map's
/// per-frame depth copy.
#[inline]
pub fn fb_texel(base: u32, px: Option<([u8; 4], u32, u8)>) -> [f32; 4] {
    const DEPTH_MAX: f32 = crate::cpu::framebuffer::DEPTH_MAX as f32;
    match (px, base) {
        (Some((_, d, _)), gl::DEPTH_COMPONENT) => [d as f32 / DEPTH_MAX, 0.0, 0.0, 0.0],
        (Some((_, d, s)), gl::DEPTH_STENCIL) => [d as f32 / DEPTH_MAX, f32::from(s), 0.0, 0.0],
        (Some((c, _, _)), _) => keep(base, c.map(|v| f32::from(v) / 255.0)),
        (None, _) => [0.0; 4],
    }
}

/// [`fb_texel`] of each pixel of a framebuffer run (`cpu::pixels::row_runs`) into the first
/// `run.len()` texels of `dst` (fewer when `dst` is shorter): the same values, the base format
/// chosen once per run and a tile's pending clear converted once (checked against `fb_texel`
/// in `fb_texels_are_fb_texel`).
pub fn fb_texels(base: u32, run: RowRun<'_>, dst: &mut [[f32; 4]]) {
    const DEPTH_MAX: f32 = crate::cpu::framebuffer::DEPTH_MAX as f32;
    let n = run.len().min(dst.len());
    let dst = &mut dst[..n];
    let RowRun::Inside {
        color,
        depth,
        stencil,
        ..
    } = run
    else {
        return dst.fill([0.0; 4]);
    };
    /// `f` of each pixel of `src` into `dst`.
    #[inline(always)]
    fn each<T: Copy>(dst: &mut [[f32; 4]], src: Src<'_, T>, f: impl Fn(T) -> [f32; 4]) {
        match src {
            Src::Mem(s) => {
                for (d, &v) in dst.iter_mut().zip(s) {
                    *d = f(v);
                }
            }
            Src::Fill(v) => dst.fill(f(v)),
        }
    }
    let unit = unit4;
    match base {
        gl::DEPTH_COMPONENT => match depth {
            Src::Mem(s) => depth_texels(dst, s),
            Src::Fill(d) => dst.fill([d as f32 / DEPTH_MAX, 0.0, 0.0, 0.0]),
        },
        gl::DEPTH_STENCIL => {
            for (k, t) in dst.iter_mut().enumerate() {
                if let (Some(d), Some(s)) = (depth.get(k), stencil.get(k)) {
                    *t = [d as f32 / DEPTH_MAX, f32::from(s), 0.0, 0.0];
                }
            }
        }
        gl::ALPHA => each(dst, color, |c| keep(gl::ALPHA, unit(c))),
        gl::LUMINANCE => each(dst, color, |c| keep(gl::LUMINANCE, unit(c))),
        gl::INTENSITY => each(dst, color, |c| keep(gl::INTENSITY, unit(c))),
        gl::LUMINANCE_ALPHA => each(dst, color, |c| keep(gl::LUMINANCE_ALPHA, unit(c))),
        gl::RGB => each(dst, color, |c| keep(gl::RGB, unit(c))),
        // `keep` of RGBA is the texel itself: the arm with the constant lets the four
        // components go to memory as one store.
        gl::RGBA => each(dst, color, |c| keep(gl::RGBA, unit(c))),
        _ => each(dst, color, |c| keep(base, unit(c))),
    }
}

/// `c.map(|v| f32::from(v) / 255.0)`: a colour pixel's four components in [0, 1] (SSE2: the
/// bytes widened to i32, converted exactly, then one `divps`, the same correctly rounded
/// division per component as the scalar `/`).
#[inline(always)]
fn unit4(c: [u8; 4]) -> [f32; 4] {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE2 is part of the x86-64 baseline; the only memory written is `out`.
    unsafe {
        use std::arch::x86_64::*;
        let z = _mm_setzero_si128();
        let b = _mm_cvtsi32_si128(i32::from_le_bytes(c));
        let v = _mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(b, z), z));
        let mut out = [0.0f32; 4];
        _mm_storeu_ps(out.as_mut_ptr(), _mm_div_ps(v, _mm_set1_ps(255.0)));
        out
    }
    #[cfg(not(target_arch = "x86_64"))]
    c.map(|v| f32::from(v) / 255.0)
}

/// The DEPTH_COMPONENT texels of a run of depths: `[d as f32 / (2^24 - 1), 0, 0, 0]` for each
/// d of `src` into `dst` (as far as the shorter goes). SSE2: four depths at a time converted
/// (`cvtdq2ps`, exact and equal to `as f32` for values below 2^31; a group with a larger one
/// takes the scalar expression) and divided by one `divps`, each quotient stored with three
/// zeros.
#[inline]
fn depth_texels(dst: &mut [[f32; 4]], src: &[u32]) {
    const DEPTH_MAX: f32 = crate::cpu::framebuffer::DEPTH_MAX as f32;
    let scalar = |d: &mut [f32; 4], v: u32| *d = [v as f32 / DEPTH_MAX, 0.0, 0.0, 0.0];
    let n = dst.len().min(src.len());
    let (dst, src) = (&mut dst[..n], &src[..n]);
    #[cfg(target_arch = "x86_64")]
    {
        let mut dc = dst.chunks_exact_mut(4);
        let mut sc = src.chunks_exact(4);
        for (d, s) in (&mut dc).zip(&mut sc) {
            let (Ok(d), Ok(s)) = (<&mut [[f32; 4]; 4]>::try_from(d), <&[u32; 4]>::try_from(s))
            else {
                continue;
            };
            // SAFETY: SSE2 is part of the x86-64 baseline; the loads and stores are of `s`
            // (16 bytes) and of the four texels of `d` (16 bytes each).
            unsafe {
                use std::arch::x86_64::*;
                let vi = _mm_loadu_si128(s.as_ptr().cast());
                if _mm_movemask_ps(_mm_castsi128_ps(vi)) != 0 {
                    for (t, &v) in d.iter_mut().zip(s) {
                        scalar(t, v);
                    }
                    continue;
                }
                let q = _mm_div_ps(_mm_cvtepi32_ps(vi), _mm_set1_ps(DEPTH_MAX));
                // (q0, 0, q1, 0) and (q2, 0, q3, 0), then each 64-bit half with 64 zero bits.
                let z = _mm_setzero_ps();
                let (lo, hi) = (
                    _mm_castps_pd(_mm_unpacklo_ps(q, z)),
                    _mm_castps_pd(_mm_unpackhi_ps(q, z)),
                );
                let zd = _mm_setzero_pd();
                let p = |v: __m128d| _mm_castpd_ps(v);
                _mm_storeu_ps(d[0].as_mut_ptr(), p(_mm_unpacklo_pd(lo, zd)));
                _mm_storeu_ps(d[1].as_mut_ptr(), p(_mm_unpackhi_pd(lo, zd)));
                _mm_storeu_ps(d[2].as_mut_ptr(), p(_mm_unpacklo_pd(hi, zd)));
                _mm_storeu_ps(d[3].as_mut_ptr(), p(_mm_unpackhi_pd(hi, zd)));
            }
        }
        for (d, &v) in dc.into_remainder().iter_mut().zip(sc.remainder()) {
            scalar(d, v);
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    for (d, &v) in dst.iter_mut().zip(src) {
        scalar(d, v);
    }
}

/// Texture coordinate generation for one coordinate (GL 2.1 §2.11.4, table 6.15).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGen {
    /// TEXTURE_GEN_MODE.
    pub mode: u32,
    /// OBJECT_PLANE.
    pub object_plane: Vec4,
    /// EYE_PLANE, already multiplied by the inverse modelview current at the call.
    pub eye_plane: Vec4,
}

/// One texture unit's state other than its enables and matrix (tables 6.15, 6.18, 6.19).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexUnit {
    /// TEXTURE_BINDING_1D, _2D, _3D, _CUBE_MAP, in [`TARGETS`] order (0: that target's
    /// default texture).
    pub bindings: [u32; 4],
    /// TEXTURE_ENV_MODE.
    pub env_mode: u32,
    /// TEXTURE_ENV_COLOR.
    pub env_color: Vec4,
    /// TEXTURE_LOD_BIAS of TEXTURE_FILTER_CONTROL.
    pub lod_bias: f32,
    /// S, T, R, Q.
    pub gen: [TexGen; 4],
    /// The COMBINE environment's parameters (table 6.19).
    pub combine: Combine,
}

/// TexEnv COMBINE parameters (GL 2.1 §3.8.13, tables 3.22 to 3.24, initial values table 6.19).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combine {
    /// COMBINE_RGB.
    pub rgb: u32,
    /// COMBINE_ALPHA.
    pub alpha: u32,
    /// SRC0_RGB, SRC1_RGB, SRC2_RGB.
    pub src_rgb: [u32; 3],
    /// SRC0_ALPHA, SRC1_ALPHA, SRC2_ALPHA.
    pub src_alpha: [u32; 3],
    /// OPERAND0_RGB ..= OPERAND2_RGB.
    pub operand_rgb: [u32; 3],
    /// OPERAND0_ALPHA ..= OPERAND2_ALPHA.
    pub operand_alpha: [u32; 3],
    /// RGB_SCALE (1, 2 or 4).
    pub rgb_scale: f32,
    /// ALPHA_SCALE (1, 2 or 4).
    pub alpha_scale: f32,
}

impl Default for Combine {
    fn default() -> Self {
        Self {
            rgb: gl::MODULATE,
            alpha: gl::MODULATE,
            src_rgb: [gl::TEXTURE, gl::PREVIOUS, gl::CONSTANT],
            src_alpha: [gl::TEXTURE, gl::PREVIOUS, gl::CONSTANT],
            operand_rgb: [gl::SRC_COLOR, gl::SRC_COLOR, gl::SRC_ALPHA],
            operand_alpha: [gl::SRC_ALPHA; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
        }
    }
}

impl Default for TexUnit {
    fn default() -> Self {
        let plane = |k: usize| {
            let mut p = [0.0; 4];
            if k < 2 {
                p[k] = 1.0;
            }
            Vec4::from_array(p)
        };
        Self {
            bindings: [0; 4],
            env_mode: gl::MODULATE,
            env_color: Vec4::ZERO,
            lod_bias: 0.0,
            combine: Combine::default(),
            gen: std::array::from_fn(|k| TexGen {
                mode: gl::EYE_LINEAR,
                object_plane: plane(k),
                eye_plane: plane(k),
            }),
        }
    }
}

/// A set of names kept as runs of consecutive names: GenTextures hands out consecutive names,
/// so a name generated and never bound costs nothing of its own (a run is two u32 in a
/// B-tree, whatever its length), and 2^32 names cost no more than one. Runs are disjoint and
/// never adjacent, so equal sets are equal values (`State: PartialEq` compares them).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct NameSet {
    /// First name of each run to its last (inclusive).
    runs: BTreeMap<u32, u32>,
}

impl NameSet {
    /// The run holding `name`, as (first, last).
    fn run_of(&self, name: u32) -> Option<(u32, u32)> {
        let (&first, &last) = self.runs.range(..=name).next_back()?;
        (name <= last).then_some((first, last))
    }

    /// The last name of the run holding `name`, if `name` is in the set: a search for an
    /// unused name skips a whole run in one step.
    pub fn run_end(&self, name: u32) -> Option<u32> {
        self.run_of(name).map(|(_, last)| last)
    }

    /// The first name of the first run starting at or after `from`.
    pub fn next_run_start(&self, from: u32) -> Option<u32> {
        self.runs.range(from..).next().map(|(&first, _)| first)
    }

    /// Whether `name` is in the set.
    pub fn contains(&self, name: u32) -> bool {
        self.run_of(name).is_some()
    }

    /// Adds `first..=last` (first <= last), merging with the runs it touches.
    pub fn insert_range(&mut self, first: u32, last: u32) {
        debug_assert!(first <= last);
        let (mut lo, mut hi) = (first, last);
        // A run ending at or after first - 1 and starting at or before last + 1 touches it.
        let from = self
            .runs
            .range(..=first)
            .next_back()
            .filter(|&(_, &l)| l >= first.saturating_sub(1))
            .map_or(first, |(&f, _)| f);
        let touching: Vec<(u32, u32)> = self
            .runs
            .range(from..=last.saturating_add(1))
            .map(|(&f, &l)| (f, l))
            .collect();
        for (f, l) in touching {
            self.runs.remove(&f);
            lo = lo.min(f);
            hi = hi.max(l);
        }
        self.runs.insert(lo, hi);
    }

    /// Adds `name`.
    pub fn insert(&mut self, name: u32) {
        self.insert_range(name, name);
    }

    /// Removes `name`, splitting its run.
    pub fn remove(&mut self, name: u32) {
        let Some((first, last)) = self.run_of(name) else {
            return;
        };
        self.runs.remove(&first);
        if first < name {
            self.runs.insert(first, name - 1);
        }
        if name < last {
            self.runs.insert(name + 1, last);
        }
    }

    /// The largest name, if any.
    pub fn last(&self) -> Option<u32> {
        self.runs.values().next_back().copied()
    }

    /// How many names the set holds.
    pub fn len(&self) -> u64 {
        self.runs.iter().map(|(&f, &l)| u64::from(l - f) + 1).sum()
    }

    /// Whether the set is empty.
    pub fn is_empty(&self) -> bool {
        self.runs.is_empty()
    }
}

/// The state of one level of a proxy texture (GL 2.1 §3.8.1, table 6.17): what a TexImage of a
/// proxy target would have made of the image, without texels. A level that would not fit is
/// `None` in [`Textures::proxies`] and reads as zero sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ProxyLevel {
    /// TEXTURE_WIDTH, border included.
    pub width: i32,
    /// TEXTURE_HEIGHT, border included (1 for 1D).
    pub height: i32,
    /// TEXTURE_DEPTH, border included (1 for 1D and 2D).
    pub depth: i32,
    /// TEXTURE_BORDER (0 or 1: a proxy keeps the border Mesa strips from real images).
    pub border: i32,
    /// TEXTURE_INTERNAL_FORMAT as the application gave it.
    pub internal_format: i32,
    /// The base internal format (table 3.15), for the component sizes.
    pub base: u32,
}

/// Every piece of texture state: objects, names, units (the unpack modes are `State::unpack`).
#[derive(Clone, Debug, PartialEq)]
pub struct Textures {
    /// Names returned by GenTextures and not yet deleted (bound or not).
    pub names: NameSet,
    /// The objects that exist (a name becomes an object of a target when first bound), by name.
    pub objects: BTreeMap<u32, Arc<TexObject>>,
    /// Texture object 0 of each target, in [`TARGETS`] order: the default textures (§3.8.12:
    /// each target has its own, with its own parameters).
    pub defaults: [Arc<TexObject>; 4],
    /// Per-unit state.
    pub units: [TexUnit; MAX_TEXTURE_UNITS],
    /// The proxy textures' levels (§3.8.1), PROXY_TEXTURE_1D, _2D, _3D, _CUBE_MAP in
    /// [`TARGETS`] order, MAX_LEVELS each: the context's own (not shared, not bound, no
    /// parameters; PushAttrib does not save them, as Mesa).
    pub proxies: [Vec<Option<ProxyLevel>>; 4],
}

impl Default for Textures {
    fn default() -> Self {
        Self {
            names: NameSet::default(),
            objects: BTreeMap::new(),
            defaults: TARGETS.map(|t| Arc::new(TexObject::new(t))),
            units: Default::default(),
            proxies: std::array::from_fn(|_| vec![None; MAX_LEVELS]),
        }
    }
}

impl Textures {
    /// The object bound to `target` (one of [`TARGETS`]) on `unit`.
    pub fn bound(&self, unit: usize, target: u32) -> Option<&Arc<TexObject>> {
        let k = target_index(target)?;
        let name = *self.units.get(unit)?.bindings.get(k)?;
        if name == 0 {
            self.defaults.get(k)
        } else {
            self.objects.get(&name)
        }
    }

    /// The object bound to `target` on `unit`, to modify (copied first if shared).
    pub fn bound_mut(&mut self, unit: usize, target: u32) -> Option<&mut TexObject> {
        let k = target_index(target)?;
        let name = *self.units.get(unit)?.bindings.get(k)?;
        let arc = if name == 0 {
            self.defaults.get_mut(k)?
        } else {
            self.objects.get_mut(&name)?
        };
        Some(Arc::make_mut(arc))
    }

    /// The object bound to TEXTURE_2D on `unit`.
    pub fn bound_2d(&self, unit: usize) -> Option<&Arc<TexObject>> {
        self.bound(unit, gl::TEXTURE_2D)
    }

    /// The object bound to TEXTURE_2D on `unit`, to modify (copied first if shared).
    pub fn bound_2d_mut(&mut self, unit: usize) -> Option<&mut TexObject> {
        self.bound_mut(unit, gl::TEXTURE_2D)
    }
}

/// The base internal format (table 3.15) of an accepted `internalformat` (tables 3.16, 3.17,
/// 1..=4 for the component counts GL 1.0 took, and the generic compressed formats of table
/// 3.18, which GL 1.3 lets an implementation with no compressed format store uncompressed, as
/// Mesa does when no compression extension is exposed), or None.
pub fn base_internal_format(internal: i32) -> Option<u32> {
    let Ok(f) = u32::try_from(internal) else {
        return None;
    };
    Some(match f {
        1 => gl::LUMINANCE,
        2 => gl::LUMINANCE_ALPHA,
        3 => gl::RGB,
        4 => gl::RGBA,
        gl::COMPRESSED_ALPHA => gl::ALPHA,
        gl::COMPRESSED_LUMINANCE => gl::LUMINANCE,
        gl::COMPRESSED_LUMINANCE_ALPHA => gl::LUMINANCE_ALPHA,
        gl::COMPRESSED_INTENSITY => gl::INTENSITY,
        gl::COMPRESSED_RGB => gl::RGB,
        gl::COMPRESSED_RGBA => gl::RGBA,
        gl::ALPHA | gl::ALPHA4 | gl::ALPHA8 | gl::ALPHA12 | gl::ALPHA16 => gl::ALPHA,
        gl::LUMINANCE | gl::LUMINANCE4 | gl::LUMINANCE8 | gl::LUMINANCE12 | gl::LUMINANCE16 => {
            gl::LUMINANCE
        }
        gl::LUMINANCE_ALPHA
        | gl::LUMINANCE4_ALPHA4
        | gl::LUMINANCE6_ALPHA2
        | gl::LUMINANCE8_ALPHA8
        | gl::LUMINANCE12_ALPHA4
        | gl::LUMINANCE12_ALPHA12
        | gl::LUMINANCE16_ALPHA16 => gl::LUMINANCE_ALPHA,
        gl::INTENSITY | gl::INTENSITY4 | gl::INTENSITY8 | gl::INTENSITY12 | gl::INTENSITY16 => {
            gl::INTENSITY
        }
        gl::RGB
        | gl::R3_G3_B2
        | gl::RGB4
        | gl::RGB5
        | gl::RGB8
        | gl::RGB10
        | gl::RGB12
        | gl::RGB16 => gl::RGB,
        gl::RGBA
        | gl::RGBA2
        | gl::RGBA4
        | gl::RGB5_A1
        | gl::RGBA8
        | gl::RGB10_A2
        | gl::RGBA12
        | gl::RGBA16 => gl::RGBA,
        gl::DEPTH_COMPONENT
        | gl::DEPTH_COMPONENT16
        | gl::DEPTH_COMPONENT24
        | gl::DEPTH_COMPONENT32 => gl::DEPTH_COMPONENT,
        // GL_EXT_packed_depth_stencil (as Mesa takes it in a compatibility context).
        gl::DEPTH_STENCIL | gl::DEPTH24_STENCIL8 => gl::DEPTH_STENCIL,
        _ => return None,
    })
}

/// Components per pixel of a client pixel `format` this crate unpacks (table 3.6), or None.
pub fn format_components(format: u32) -> Option<usize> {
    Some(match format {
        gl::RED | gl::GREEN | gl::BLUE | gl::ALPHA | gl::LUMINANCE | gl::DEPTH_COMPONENT => 1,
        gl::LUMINANCE_ALPHA => 2,
        gl::RGB | gl::BGR => 3,
        gl::RGBA | gl::BGRA => 4,
        _ => return None,
    })
}

/// The unpack (or pack) modes that place image `k` of a 3D image of `height` rows (GL 2.1
/// §3.8.1) as a 2D image: SKIP_ROWS advanced by SKIP_IMAGES + `k` images of IMAGE_HEIGHT (or
/// `height`) rows. With `three_d` false (a 1D or 2D image) IMAGE_HEIGHT and SKIP_IMAGES do not
/// apply. None when the row count does not fit an i32 (no client buffer is that long).
pub fn slice_modes(modes: &PixelModes, height: i32, k: usize, three_d: bool) -> Option<PixelModes> {
    let flat = PixelModes {
        image_height: 0,
        skip_images: 0,
        ..*modes
    };
    if !three_d {
        return Some(flat);
    }
    let img = i64::from(if modes.image_height > 0 {
        modes.image_height
    } else {
        height.max(0)
    });
    let images = i64::from(modes.skip_images.max(0)).checked_add(i64::try_from(k).ok()?)?;
    let rows = i64::from(modes.skip_rows.max(0)).checked_add(images.checked_mul(img)?)?;
    Some(PixelModes {
        skip_rows: i32::try_from(rows).ok()?,
        ..flat
    })
}

/// Where image `k` of a `width` x `height` x `depth` client image of `f` lies under `modes`
/// ([`slice_modes`]); every pixel transfer command's layout (`PixelModes::image_layout`), so
/// BITMAP and the packed types are placed as DrawPixels places them.
pub fn slice_layout(
    modes: &PixelModes,
    f: Format,
    width: i32,
    height: i32,
    k: usize,
    three_d: bool,
) -> Option<ImageLayout> {
    slice_modes(modes, height, k, three_d)?.image_layout(f, width, height)
}

/// The bytes a `width` x `height` x `depth` image of `f` spans under `modes` (the last image's
/// end; 0 for an empty image, whatever the skips), or None when that does not fit a usize.
pub fn image_need3(
    modes: &PixelModes,
    f: Format,
    width: i32,
    height: i32,
    depth: i32,
    three_d: bool,
) -> Option<usize> {
    if width <= 0 || height <= 0 || depth <= 0 {
        return Some(0);
    }
    let last = usize::try_from(depth - 1).ok()?;
    slice_layout(modes, f, width, height, last, three_d).map(|l| l.need())
}

/// Appends the `width` x `height` groups of `img` (validated: its data spans its layout) to
/// `out` (which the caller may have reserved fallibly) as texels of base format `base`: each
/// group made RGBA as DrawPixels makes it (§3.8.1 refers to §3.6.4 and §3.6.5: colours with
/// the colour transfer, colour indices through the I_TO_R/G/B/A maps after the index shift and
/// offset, depths scaled and biased), then the components `base` keeps (table 3.15), clamped
/// and reduced to the stored precision.
pub fn unpack_into(
    out: &mut Vec<[f32; 4]>,
    img: &Image,
    width: i32,
    height: i32,
    base: u32,
    t: &PixelTransfer,
    maps: &PixelMaps,
) {
    unpack_with(out, img, width, height, base, t, maps, true);
}

/// [`unpack_into`]; `bytes` false keeps UNSIGNED_BYTE colour data off its byte route (for
/// the test that compares the two routes).
#[allow(clippy::too_many_arguments)]
fn unpack_with(
    out: &mut Vec<[f32; 4]>,
    img: &Image,
    width: i32,
    height: i32,
    base: u32,
    t: &PixelTransfer,
    maps: &PixelMaps,
    bytes: bool,
) {
    let (w, h) = (width.max(0) as usize, height.max(0) as usize);
    let first = out.len();
    // UNSIGNED_BYTE colour data with no colour transfer into a colour format: each component
    // unpacks to v / 255, which `quantize` returns as it is (`fb_texels_are_quantized`), so the
    // texel is `keep` of the bytes' values — no per-component rounding.
    let colour_base = matches!(
        base,
        gl::ALPHA | gl::LUMINANCE | gl::LUMINANCE_ALPHA | gl::INTENSITY | gl::RGB | gl::RGBA
    );
    if bytes && colour_base && matches!(img.format.group, Group::Color(_)) && t.color_is_identity()
    {
        let cols: Vec<usize> = (0..w).collect();
        let rows: Vec<usize> = (0..h).collect();
        let mut b = Vec::new();
        if b.try_reserve_exact(w * h).is_ok() && img.bytes(&cols, &rows, &mut b).is_some() {
            /// `f` of each colour's components as c / 255, appended to `out`.
            #[inline(always)]
            fn conv(out: &mut Vec<[f32; 4]>, b: &[[u8; 4]], f: impl Fn([f32; 4]) -> [f32; 4]) {
                // `unit4` is `unit_u8` of each component (c / 255 correctly rounded, which the
                // table's double-precision quotient rounded to f32 is for every byte: the
                // test `unpack_byte_route_is_the_general_route` goes through all 256).
                out.extend(b.iter().map(|&c| f(unit4(c))));
            }
            match base {
                gl::ALPHA => conv(out, &b, |c| keep(gl::ALPHA, c)),
                gl::LUMINANCE => conv(out, &b, |c| keep(gl::LUMINANCE, c)),
                gl::LUMINANCE_ALPHA => conv(out, &b, |c| keep(gl::LUMINANCE_ALPHA, c)),
                gl::INTENSITY => conv(out, &b, |c| keep(gl::INTENSITY, c)),
                gl::RGB => conv(out, &b, |c| keep(gl::RGB, c)),
                _ => conv(out, &b, |c| keep(gl::RGBA, c)),
            }
            return;
        }
    }
    match img.format.group {
        Group::Color(_) => {
            let cols: Vec<usize> = (0..w).collect();
            let rows: Vec<usize> = (0..h).collect();
            img.colors(&cols, &rows, out);
            if !t.color_is_identity() {
                for c in &mut out[first..] {
                    *c = t.color(maps, *c);
                }
            }
        }
        group => {
            for j in 0..h {
                for i in 0..w {
                    out.push(match group {
                        Group::Index => t.index_to_rgba(maps, img.index(i, j)),
                        // DEPTH_COMPONENT data into a DEPTH_STENCIL image: stencil 0.
                        Group::Depth if base == gl::DEPTH_STENCIL => {
                            [t.depth(img.depth(i, j)) as f32, 0.0, 0.0, 1.0]
                        }
                        Group::Depth => {
                            let d = t.depth(img.depth(i, j)) as f32;
                            [d, d, d, 1.0]
                        }
                        // DEPTH_STENCIL data: the depth, and for a DEPTH_STENCIL image the
                        // index through the index transfer (shift, offset, MAP_STENCIL), as
                        // Mesa's `_mesa_texstore_z24_s8`; a DEPTH_COMPONENT image drops it.
                        Group::DepthStencil if base == gl::DEPTH_STENCIL => {
                            let d = t.depth(img.depth(i, j)) as f32;
                            [d, f32::from(t.stencil(maps, img.index(i, j))), 0.0, 1.0]
                        }
                        Group::DepthStencil => {
                            let d = t.depth(img.depth(i, j)) as f32;
                            [d, d, d, 1.0]
                        }
                        // Rejected by the commands (INVALID_OPERATION, as Mesa).
                        _ => [0.0, 0.0, 0.0, 1.0],
                    });
                }
            }
        }
    }
    for c in &mut out[first..] {
        *c = quantize(base, keep(base, *c));
    }
}

/// The components base format `base` keeps of an RGBA colour (table 3.15), others zero, the
/// luminance and intensity in R.
pub fn keep(base: u32, [r, g, b, a]: [f32; 4]) -> [f32; 4] {
    match base {
        gl::ALPHA => [0.0, 0.0, 0.0, a],
        gl::LUMINANCE | gl::INTENSITY | gl::DEPTH_COMPONENT => [r, 0.0, 0.0, 0.0],
        gl::DEPTH_STENCIL => [r, g, 0.0, 0.0],
        gl::LUMINANCE_ALPHA => [r, 0.0, 0.0, a],
        gl::RGB => [r, g, b, 0.0],
        _ => [r, g, b, a],
    }
}

/// A stored texel as RGBA with the base format's reading (table 3.21's Rt, Gt, Bt, At, before
/// the environment): L → (L, L, L, 1), I → (I, I, I, I), A → (0, 0, 0, A), RGB → (R, G, B, 1).
/// What GetTexImage returns, and what DECAL and the colour-only environments read.
pub fn as_rgba(base: u32, [r, g, b, a]: [f32; 4]) -> [f32; 4] {
    match base {
        gl::ALPHA => [0.0, 0.0, 0.0, a],
        gl::LUMINANCE | gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL => [r, r, r, 1.0],
        gl::LUMINANCE_ALPHA => [r, r, r, a],
        gl::INTENSITY => [r, r, r, r],
        gl::RGB => [r, g, b, 1.0],
        _ => [r, g, b, a],
    }
}

/// A `size` x `size` RGBA8 checkerboard of `cells` x `cells` squares, `a` at the lower-left
/// corner and `b` beside it, as tightly packed bytes ready for `tex_image_2d(.., RGBA,
/// UNSIGNED_BYTE, ..)` with any UNPACK_ALIGNMENT.
pub fn checkerboard(size: u32, cells: u32, a: [u8; 4], b: [u8; 4]) -> Vec<u8> {
    let size = size.min(MAX_TEXTURE_SIZE as u32);
    let cell = (size / cells.max(1)).max(1);
    let mut out = Vec::with_capacity((size * size * 4) as usize);
    for y in 0..size {
        for x in 0..size {
            let odd = ((x / cell) + (y / cell)) % 2 == 1;
            out.extend_from_slice(if odd { &b } else { &a });
        }
    }
    out
}

/// An image's pixels as RGBA8 bytes in GL's row order (bottom row first), with its width and
/// height, ready for `tex_image_2d(.., RGBA, UNSIGNED_BYTE, ..)`.
pub fn texture_from_image(img: &image::DynamicImage) -> (i32, i32, Vec<u8>) {
    let rgba = image::imageops::flip_vertical(&img.to_rgba8());
    let (w, h) = rgba.dimensions();
    (w as i32, h as i32, rgba.into_raw())
}

/// `f32` values as the native-endian bytes `tex_image_2d(.., FLOAT, ..)` takes.
pub fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_ne_bytes()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `quantize` as it was written with `f32::round`.
    fn quantize_ref(base: u32, t: [f32; 4]) -> [f32; 4] {
        let s = 16_777_215.0;
        if base == gl::DEPTH_COMPONENT {
            t.map(|c| (c.clamp(0.0, 1.0) * s).round() / s)
        } else if base == gl::DEPTH_STENCIL {
            let d = (t[0].clamp(0.0, 1.0) * s).round() / s;
            let st = if t[1].is_nan() {
                0.0
            } else {
                t[1].clamp(0.0, 255.0).round()
            };
            [d, st, 0.0, 0.0]
        } else {
            t.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() / 255.0)
        }
    }

    /// `round_small` is `f32::round` bit for bit on [-0, 2^24] and NaN: every value within
    /// 64 ulps of each half-integer and integer up to 2^12, every 61st bit pattern of the
    /// range, the ends; and `quantize` is the `f32::round` version on every 997th f32 bit
    /// pattern (NaN, infinities, negatives, subnormals included) in each base format.
    /// `quantize_colour` is `quantize`'s scalar colour expression bit for bit: every value
    /// near each of the 256 steps and their midpoints (of c·255), signed zeros, subnormals,
    /// values below 0 and above 1, infinities, and random bits (NaN among them: None).
    #[test]
    fn quantize_colour_is_the_scalar() {
        let scalar = |c: f32| round_small(c.clamp(0.0, 1.0) * 255.0) / 255.0;
        let mut vals = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            2.0,
            f32::INFINITY,
            -f32::INFINITY,
            1e-45,
        ];
        for k in 0..=255u32 {
            for c in [k as f32 / 255.0, (k as f32 + 0.5) / 255.0] {
                let b = c.to_bits();
                vals.extend((0..=64u32).map(|d| f32::from_bits((b + d).saturating_sub(32))));
            }
        }
        let mut seed = 0x1234_5678u32;
        for _ in 0..100_000 {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            vals.push(f32::from_bits(seed));
        }
        for q in vals.chunks(4) {
            let mut t = [0.5f32; 4];
            t[..q.len()].copy_from_slice(q);
            match quantize_colour(t) {
                Some(got) => {
                    let want = t.map(scalar);
                    assert_eq!(got.map(f32::to_bits), want.map(f32::to_bits), "{t:?}");
                }
                None => assert!(t.iter().any(|c| c.is_nan()), "{t:?}"),
            }
        }
        #[cfg(target_arch = "x86_64")]
        assert!(quantize_colour([0.1, 0.2, 0.3, 0.4]).is_some());
    }

    #[test]
    fn round_small_is_round() {
        let check = |x: f32| {
            assert_eq!(
                round_small(x).to_bits(),
                x.round().to_bits(),
                "{x:e} ({:#x})",
                x.to_bits()
            );
        };
        for k in 0..=4096u32 {
            for c in [k as f32, k as f32 + 0.5] {
                let b = c.to_bits();
                for d in 0..=128u32 {
                    check(f32::from_bits((b + d).saturating_sub(64)));
                }
            }
        }
        let top = (1u32 << 24) as f32;
        for b in (0..=top.to_bits()).step_by(61) {
            check(f32::from_bits(b));
        }
        for x in [
            0.0,
            -0.0,
            top,
            f32::NAN,
            -f32::NAN,
            0.5,
            0.49999997,
            8_388_607.5,
        ] {
            check(x);
        }
        let bases = [
            gl::ALPHA,
            gl::LUMINANCE,
            gl::RGB,
            gl::RGBA,
            gl::DEPTH_COMPONENT,
            gl::DEPTH_STENCIL,
        ];
        for b in (0..=u32::MAX).step_by(997) {
            let x = f32::from_bits(b);
            let t = [x, f32::from_bits(b.rotate_left(7)), -x, x * 0.25];
            for base in bases {
                let (got, want) = (quantize(base, t), quantize_ref(base, t));
                assert_eq!(
                    got.map(f32::to_bits),
                    want.map(f32::to_bits),
                    "{base:#x} {t:?}"
                );
            }
        }
    }

    /// [`fb_texel`] is `quantize` of the value it computes, bit for bit: every 24-bit depth,
    /// every stencil, every colour value in every base format, and a pixel outside.
    /// `fb_texels` of a run is `fb_texel` of each of its pixels, for every base format,
    /// runs from memory and from a pending clear, outside runs, and `dst` shorter than the run.
    #[test]
    fn fb_texels_are_fb_texel() {
        let bits = |t: &[[f32; 4]]| t.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
        let mut seed = 0x2545_f491u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let bases = [
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
            gl::INTENSITY,
            gl::RGB,
            gl::RGBA,
            gl::DEPTH_COMPONENT,
            gl::DEPTH_STENCIL,
        ];
        for round in 0..200 {
            let len = 1 + (next() % 64) as usize;
            let colors: Vec<[u8; 4]> = (0..len).map(|_| next().to_le_bytes()).collect();
            // Every seventh round full 32-bit values (the SSE2 conversion is exact only
            // below 2^31: such a group takes the scalar expression).
            let depths: Vec<u32> = (0..len)
                .map(|_| if round % 7 == 3 { next() } else { next() >> 8 })
                .collect();
            let stencils: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            let (fc, fd, fs) = (next().to_le_bytes(), next() >> 8, next() as u8);
            let color = if round % 3 == 0 {
                Src::Fill(fc)
            } else {
                Src::Mem(&colors[..])
            };
            let depth = if round % 4 == 1 {
                Src::Fill(fd)
            } else {
                Src::Mem(&depths[..])
            };
            let stencil = if round % 5 == 2 {
                Src::Fill(fs)
            } else {
                Src::Mem(&stencils[..])
            };
            let run = RowRun::Inside {
                len,
                color,
                depth,
                stencil,
            };
            for base in bases {
                for short in [0, 1, len / 2] {
                    let n = len - short;
                    let mut got = vec![[f32::NAN; 4]; n];
                    fb_texels(base, run, &mut got);
                    let want: Vec<[f32; 4]> = (0..n)
                        .map(|k| {
                            let px = (color.get(k), depth.get(k), stencil.get(k));
                            fb_texel(base, Some((px.0.unwrap(), px.1.unwrap(), px.2.unwrap())))
                        })
                        .collect();
                    assert_eq!(bits(&got), bits(&want), "base {base:#x} round {round}");
                }
                let mut got = vec![[f32::NAN; 4]; len + 2];
                fb_texels(base, RowRun::Outside(len), &mut got);
                let want = [fb_texel(base, None)].repeat(len);
                assert_eq!(bits(&got[..len]), bits(&want), "base {base:#x} outside");
                assert!(got[len..].iter().flatten().all(|v| v.is_nan()));
            }
        }
    }

    /// `unpack_into`'s byte route (UNSIGNED_BYTE colour data, no colour transfer, a colour
    /// format: `keep` of c / 255, no rounding) stores the texels of the general route
    /// (`Image::colors`, then `quantize`) bit for bit: every colour format of the data, every
    /// colour base format, unpack alignments and row lengths that pad rows, random bytes
    /// (every value of each component); and with a colour transfer the route is not taken.
    #[test]
    fn unpack_byte_route_is_the_general_route() {
        use crate::pixels::{check, PixelMaps, PixelTransfer};
        let bits = |t: &[[f32; 4]]| t.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
        let mut seed = 0x9e37_79b9u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let formats = [
            gl::RGBA,
            gl::RGB,
            gl::BGRA,
            gl::BGR,
            gl::ABGR_EXT,
            gl::RED,
            gl::GREEN,
            gl::BLUE,
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
        ];
        let bases = [
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
            gl::INTENSITY,
            gl::RGB,
            gl::RGBA,
        ];
        let maps = PixelMaps::default();
        let identity = PixelTransfer::default();
        let scaled = PixelTransfer {
            scale: [0.5, 1.0, 2.0, 1.0],
            ..PixelTransfer::default()
        };
        let mut routes = 0;
        for (n, &format) in formats.iter().enumerate() {
            let Ok(f) = check(format, gl::UNSIGNED_BYTE) else {
                continue;
            };
            for (width, height, align, row_length) in [
                (16, 16, 4, 0),
                (7, 5, 1, 0),
                (5, 3, 8, 0),
                (3, 4, 2, 9),
                (1, 1, 4, 0),
            ] {
                let modes = PixelModes {
                    alignment: align,
                    row_length,
                    ..PixelModes::default()
                };
                let data: Vec<u8> = (0..4096).map(|_| next() as u8).collect();
                let Some(layout) = slice_layout(&modes, f, width, height, 0, false) else {
                    continue;
                };
                let img = Image {
                    data: &data,
                    format: f,
                    layout,
                };
                for base in bases {
                    for t in [&identity, &scaled] {
                        let (mut a, mut b) = (vec![[1.0; 4]], vec![[1.0; 4]]);
                        unpack_with(&mut a, &img, width, height, base, t, &maps, true);
                        unpack_with(&mut b, &img, width, height, base, t, &maps, false);
                        assert_eq!(a.len(), 1 + (width * height) as usize);
                        assert_eq!(
                            bits(&a),
                            bits(&b),
                            "format {n} base {base:#x} {width}x{height}"
                        );
                        routes += 1;
                    }
                }
            }
        }
        assert!(routes > 200, "{routes}");
        // Every byte value in every channel once.
        let data: Vec<u8> = (0..=255u8)
            .flat_map(|v| [v, v ^ 0x5a, 255 - v, v / 3 * 2])
            .collect();
        let f = check(gl::RGBA, gl::UNSIGNED_BYTE).expect("RGBA bytes");
        let layout = slice_layout(&PixelModes::default(), f, 256, 1, 0, false).expect("a layout");
        let img = Image {
            data: &data,
            format: f,
            layout,
        };
        for base in bases {
            let (mut a, mut b) = (Vec::new(), Vec::new());
            unpack_with(&mut a, &img, 256, 1, base, &identity, &maps, true);
            unpack_with(&mut b, &img, 256, 1, base, &identity, &maps, false);
            assert_eq!(bits(&a), bits(&b), "base {base:#x}");
        }
    }

    /// `unit4` is the scalar c / 255 of each component (every byte value in every position)
    /// and `depth_texels` the scalar d / (2^24 - 1) of each depth: every 24-bit depth, values
    /// at and above 2^31 (the scalar route of a group), destinations and sources of every
    /// length up to 21 against each other (the shorter one decides, the rest untouched).
    #[test]
    fn depth_texels_and_unit4_are_the_scalar_expressions() {
        const DEPTH_MAX: f32 = crate::cpu::framebuffer::DEPTH_MAX as f32;
        let want = |v: u32| [v as f32 / DEPTH_MAX, 0.0, 0.0, 0.0].map(f32::to_bits);
        for v in 0..=255u8 {
            for k in 0..4 {
                let mut c = [v.wrapping_mul(7), v ^ 0x5a, 255 - v, v.wrapping_add(99)];
                c[k] = v;
                let got = unit4(c).map(f32::to_bits);
                assert_eq!(got, c.map(|v| (f32::from(v) / 255.0).to_bits()), "{c:?}");
            }
        }
        let all: Vec<u32> = (0..1u32 << 24).collect();
        let mut dst = vec![[f32::NAN; 4]; all.len()];
        depth_texels(&mut dst, &all);
        for (d, &v) in dst.iter().zip(&all) {
            assert_eq!(d.map(f32::to_bits), want(v), "{v}");
        }
        let mut seed = 0x9e37_79b9u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        for round in 0..400 {
            let (nd, ns) = (round % 22, (round / 22) % 22);
            let src: Vec<u32> = (0..ns)
                .map(|k| match (round + k) % 5 {
                    0 => next(),
                    1 => u32::MAX - (next() & 3),
                    2 => (1 << 31) + (next() & 1),
                    _ => next() >> 8,
                })
                .collect();
            let mut dst = vec![[f32::NAN; 4]; nd];
            depth_texels(&mut dst, &src);
            for (k, d) in dst.iter().enumerate() {
                match src.get(k) {
                    Some(&v) => assert_eq!(d.map(f32::to_bits), want(v), "{v} at {k}"),
                    None => assert!(d.iter().all(|x| x.is_nan())),
                }
            }
        }
    }

    #[test]
    fn fb_texels_are_quantized() {
        const DEPTH_MAX: f32 = crate::cpu::framebuffer::DEPTH_MAX as f32;
        let bits = |t: [f32; 4]| t.map(f32::to_bits);
        for d in 0..1u32 << 24 {
            let z = d as f32 / DEPTH_MAX;
            let want = quantize(gl::DEPTH_COMPONENT, [z, 0.0, 0.0, 0.0]);
            let got = fb_texel(gl::DEPTH_COMPONENT, Some(([0; 4], d, 0)));
            assert_eq!(bits(got), bits(want), "depth {d}");
            let s = (d % 256) as u8;
            let want = quantize(gl::DEPTH_STENCIL, [z, f32::from(s), 0.0, 0.0]);
            let got = fb_texel(gl::DEPTH_STENCIL, Some(([0; 4], d, s)));
            assert_eq!(bits(got), bits(want), "depth {d} stencil {s}");
        }
        let bases = [
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
            gl::INTENSITY,
            gl::RGB,
            gl::RGBA,
        ];
        for base in bases {
            for v in 0..=255u8 {
                let c = [v, 255 - v, v / 3, v ^ 0x5a];
                let t = keep(base, c.map(|v| f32::from(v) / 255.0));
                let got = fb_texel(base, Some((c, 0, 0)));
                assert_eq!(bits(got), bits(quantize(base, t)), "base {base:#x} {c:?}");
            }
            assert_eq!(bits(fb_texel(base, None)), bits(quantize(base, [0.0; 4])));
        }
    }
}
