//! Per-fragment operations in the spec's order (GL 2.1 §3.9 colour sum, §3.10 fog, §4.1
//! per-fragment operations): the scissor test (already applied as the rasteriser's rectangle),
//! the alpha test, the stencil test, the depth test with DepthFunc and DepthMask, blending or
//! the logical operation, then the colour write through ColorMask (the operations themselves
//! are in `fragops`). Dithering is never done (GL 2.1 §4.1.9 allows it; llvmpipe does not).
//!
//! Design decision: two routines, chosen once per span (never per pixel). With no fog, alpha,
//! stencil, blend or logic op enabled (`FragCtx::ops` is `None`, as in the lecture's surface
//! scenes), the depth test runs over the whole span first and produces a coverage mask, and
//! colours are computed only for the surviving pixels, returning at once when the mask is empty
//! (Mesa `swrast/s_span.h`). Otherwise the span takes the full sequence in spec order, eight
//! fragments at a time (`oplanes`), because the alpha test needs the colour before the stencil
//! and depth tests may write.

use glam::{Vec3, Vec4};

use super::fragops::{compare, ColorWrite, Ops};
use super::framebuffer::{depth_unorm, unorm8, TILE};
use super::lanes::LANES;
use super::setup::{RLayout, RPrim, F_AALINE, F_AAPOINT, F_BACK, F_FLAT, F_LINE, F_PHONG, MAXV};
use super::texture::{Sampler, SpanLambda, UnitTexels};
use super::vertex::Lighting;
use crate::gl;
use crate::state::{Material, BACK, FRONT, MAX_TEXTURE_UNITS};

/// The depth functions the AVX2 row routes compile in (`FragCtx::depth_fast`).
const LESS: u32 = gl::LESS;
const LEQUAL: u32 = gl::LEQUAL;

/// The primitive flags that keep a primitive off `FragCtx::smooth_rows` (`smooth_planes`).
const NOT_SMOOTH: u8 = F_AAPOINT | F_AALINE | F_FLAT | F_PHONG;

/// The fragment-stage state of one flush.
#[derive(Clone, Debug)]
pub struct FragCtx<'a> {
    /// DEPTH_TEST enabled.
    pub depth_test: bool,
    /// DepthFunc.
    pub depth_func: u32,
    /// DepthMask.
    pub depth_mask: bool,
    /// ColorMask.
    pub color_mask: [bool; 4],
    /// Add the secondary colour (§3.9: lighting with SEPARATE_SPECULAR_COLOR, or COLOR_SUM).
    pub color_sum: bool,
    /// Varying layout.
    pub rl: RLayout,
    /// Lighting for PHONG_WIN triangles.
    pub lighting: Option<&'a Lighting>,
    /// Materials by snapshot index.
    pub mats: &'a [[Material; 2]],
    /// Diagnostic: instead of writing colour, add 1 to the red byte of every fragment that
    /// reaches the colour write (tests count coverage with it).
    pub count: bool,
    /// An occlusion query is active: count each fragment that passes the depth test (and the
    /// tests before it) in `TileBufs::samples`, as llvmpipe counts after its depth/stencil
    /// stage, whatever the masks then write.
    pub samples: bool,
    /// POLYGON_STIPPLE enabled: each window row's stipple bits (`stipple_rows`), applied to
    /// filled polygons only (not to a line's parallelogram, `F_LINE`, nor to points).
    pub stipple: Option<[u32; 32]>,
    /// Fog, alpha, stencil, blend, logic op: `None` when none is enabled (the fast path).
    pub ops: Option<Ops>,
    /// The texturing units of this flush in unit order, then `None`s: each one's sampler (the
    /// unit carries coordinates, a target is enabled and its texture complete, §3.8) and the
    /// offset of its coordinates among the varyings. Each takes the previous one's result
    /// (§3.8.15); a fragment stops at the first `None`, so a flush pays for the units it uses.
    pub tex: [Option<(&'a Sampler, usize)>; MAX_TEXTURE_UNITS],
    /// Some unit's environment reads another unit's texel (a COMBINE source TEXTUREn,
    /// [`crossbar`]): every unit samples before the first environment runs.
    pub crossbar: bool,
}

/// A span's row state for [`fused_span`]: its first window x and pixel count, its tile index,
/// its coverage mask, the flat varyings, its y and the quad row's y relative to the planes'
/// origin, whose window x is `ox`.
#[cfg(target_arch = "x86_64")]
struct FusedArgs {
    x0: i32,
    n: usize,
    base: usize,
    mask: u64,
    nflat: usize,
    fy: f32,
    ox: i32,
    qy: f32,
}

/// The 2x2 quads' λ of a span row that the general path keeps, eight quads a block: a span's
/// covered groups (at most 64 pixels) lie in at most 33 quads.
const ROW_QUAD_BLOCKS: usize = 5;

/// Each unit's λ of a span row's quads (`Sampler::quad_lambda_row`), for `FragCtx::tri_span_in`.
type RowQuads = [[[f32; LANES]; ROW_QUAD_BLOCKS]; MAX_TEXTURE_UNITS];

/// Which of its routes `FragCtx::tri_span_in` takes for a primitive's spans (`RowPlan`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum SpanRoute {
    /// The smooth primary colour alone (no FLAT, secondary colour or PHONG_WIN).
    Smooth,
    /// The FLAT colour alone into one colour buffer written whole.
    Flat,
    /// Anything else (textured spans among them).
    General,
}

/// `FragCtx::tri_span_in`'s choices for the spans of one primitive in one tile
/// (`FragCtx::row_plan`).
struct RowPlan<'s> {
    /// ColorMask all false and no coverage count: the depth test writes all a span writes.
    depth_only: bool,
    /// The flat varyings that lead the layout (0 unless the primitive is FLAT).
    nflat: usize,
    route: SpanRoute,
    /// One colour buffer written whole (no second buffer, ColorMask all true, no count).
    whole: bool,
    /// `FragCtx::tex_lanes_ok`.
    on_lanes: bool,
    /// The units whose sampler needs λ, bit u for unit u.
    lod: u8,
    /// The fused route's sampler and its coordinates' first varying, where the spans take it.
    fused: Option<(&'s Sampler, usize)>,
    /// The spans' colours go through `FragCtx::packed_rows` (AVX2 only).
    packed: bool,
}

/// A textured group's place for `FragCtx::tex_group_rest`: its stencil side, the depth row
/// (`zrow`, `dz`), its first lane's x offset `fx0` and tile index `i0`, its lanes `m`, and
/// whether the span writes colour.
struct TexGroup<'a> {
    side: Option<&'a super::fragops::StencilSide>,
    zrow: f32,
    dz: f32,
    fx0: i32,
    i0: usize,
    m: u8,
    writes_color: bool,
}

/// `lanes::varyings` of a group, on eight lanes a register where `AVX2` (the same bits:
/// `lanes::varyings_avx2`). `AVX2` is true only in functions compiled for AVX2 that run where
/// the CPU has it (`tri_rows_avx2`, `tex_span_avx2`).
#[inline(always)]
fn varyings_on<const AVX2: bool>(
    planes: &[f32],
    nflat: usize,
    fx0: i32,
    fy: f32,
    out: &mut [[f32; LANES]],
) {
    #[cfg(target_arch = "x86_64")]
    if AVX2 {
        // SAFETY: `AVX2` is true only where the CPU has AVX2 (above).
        unsafe { super::lanes::varyings_avx2(planes, nflat, fx0, fy, out) };
        return;
    }
    super::lanes::varyings(planes, nflat, fx0, fy, out);
}

/// `texture::spread_quads` of a unit's row of quads `q` (`RowQuads`), on eight lanes a
/// register where `AVX2` (`spread_quads_avx2`: the same floats, moved).
#[inline(always)]
fn spread_on<const AVX2: bool>(
    q: &[[f32; LANES]; ROW_QUAD_BLOCKS],
    d: usize,
    x: i32,
) -> [f32; LANES] {
    #[cfg(target_arch = "x86_64")]
    if AVX2 {
        // SAFETY: `AVX2` is true only where the CPU has AVX2 (`varyings_on`).
        return unsafe { spread_quads_avx2(q, d, x) };
    }
    super::texture::spread_quads(q.as_flattened(), d, x)
}

/// `texture::spread_quads` on AVX2: lane l takes quad `d + (x % 2 + l) / 2` of `q`, one
/// unaligned load of the eight quads from `d` and one `vpermps` of it (a lane-at-a-time
/// gather of five floats and their selection cost ≈40 instructions a unit and group on
/// texture-targets). Quads past `q`'s end read as 0 as there: for `d` past the load's reach
/// (never in `tri_span_in`, where d <= 28), `spread_quads` itself.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn spread_quads_avx2(q: &[[f32; LANES]; ROW_QUAD_BLOCKS], d: usize, x: i32) -> [f32; LANES] {
    use std::arch::x86_64::{_mm256_loadu_ps, _mm256_permutevar8x32_ps, _mm256_setr_epi32};
    let flat = q.as_flattened();
    let Some(w) = flat.get(d..d + LANES) else {
        return super::texture::spread_quads(flat, d, x);
    };
    // SAFETY: the CPU has AVX2 (this function's contract); the load reads the eight floats of
    // `w` (in bounds, no alignment needed); `__m256` has the layout of `[f32; 8]`.
    unsafe {
        let idx = if x & 1 == 0 {
            _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3)
        } else {
            _mm256_setr_epi32(0, 1, 1, 2, 2, 3, 3, 4)
        };
        let v = _mm256_permutevar8x32_ps(_mm256_loadu_ps(w.as_ptr()), idx);
        std::mem::transmute::<std::arch::x86_64::__m256, [f32; LANES]>(v)
    }
}

/// `lanes::to_pixels` of four whole rows on AVX2: the 4x8 transposition two pixels a
/// register (in-lane unpacks and shuffles, then the halves put in order), where
/// `to_pixels` takes four 4x4 transpositions of 128-bit halves and `tex_pixels` loaded each
/// row through its own bounds check (≈24 instructions a group fewer on texture-targets).
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn to_pixels_avx2(rows: &[[f32; LANES]; 4]) -> [Vec4; LANES] {
    use std::arch::x86_64::{
        __m256, _mm256_loadu_ps, _mm256_permute2f128_ps, _mm256_shuffle_ps, _mm256_unpackhi_ps,
        _mm256_unpacklo_ps,
    };
    let [r, g, b, a] = rows;
    // SAFETY: the CPU has AVX2 (this function's contract); each load reads the eight floats
    // of one row (in bounds, no alignment needed); `[__m256; 4]` and `[Vec4; 8]` are both 32
    // floats in a row (`Vec4` has the layout of `[f32; 4]`), every bit pattern valid.
    unsafe {
        let (r, g) = (_mm256_loadu_ps(r.as_ptr()), _mm256_loadu_ps(g.as_ptr()));
        let (b, a) = (_mm256_loadu_ps(b.as_ptr()), _mm256_loadu_ps(a.as_ptr()));
        // r0 g0 r1 g1 | r4 g4 r5 g5, b0 a0 b1 a1 | b4 a4 b5 a5, and the same of lanes 2, 3, 6, 7.
        let (lo_rg, lo_ba) = (_mm256_unpacklo_ps(r, g), _mm256_unpacklo_ps(b, a));
        let (hi_rg, hi_ba) = (_mm256_unpackhi_ps(r, g), _mm256_unpackhi_ps(b, a));
        // Pixels 0 | 4, 1 | 5, 2 | 6 and 3 | 7.
        let p04 = _mm256_shuffle_ps::<0x44>(lo_rg, lo_ba);
        let p15 = _mm256_shuffle_ps::<0xEE>(lo_rg, lo_ba);
        let p26 = _mm256_shuffle_ps::<0x44>(hi_rg, hi_ba);
        let p37 = _mm256_shuffle_ps::<0xEE>(hi_rg, hi_ba);
        let out: [__m256; 4] = [
            _mm256_permute2f128_ps::<0x20>(p04, p15),
            _mm256_permute2f128_ps::<0x20>(p26, p37),
            _mm256_permute2f128_ps::<0x31>(p04, p15),
            _mm256_permute2f128_ps::<0x31>(p26, p37),
        ];
        std::mem::transmute::<[__m256; 4], [Vec4; LANES]>(out)
    }
}

/// `lanes::store_pixels`, on eight lanes a register where `AVX2` (`store_pixels_avx2`: the
/// same bytes).
#[inline(always)]
fn store_pixels_on<const AVX2: bool>(dst: &mut [[u8; 4]], m: u8, c: &[Vec4; LANES]) {
    #[cfg(target_arch = "x86_64")]
    if AVX2 {
        // SAFETY: `AVX2` is true only where the CPU has AVX2 (`varyings_on`).
        return unsafe { store_pixels_avx2(dst, m, c) };
    }
    super::lanes::store_pixels(dst, m, c);
}

/// `lanes::store_pixels` on AVX2: the same clamp, scale and bias of each channel (the same
/// operations in the same order, two pixels a register where `store_pixels` takes one), the
/// same saturating packs (within each 128-bit half, the pixels then put back in order by one
/// `vpermd`) and one masked store of the lanes of `m` (≈66 instructions a group on
/// texture-targets before). A row shorter than a group goes to `store_pixels` itself.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn store_pixels_avx2(dst: &mut [[u8; 4]], m: u8, c: &[Vec4; LANES]) {
    use super::lanes::lane_mask8;
    use std::arch::x86_64::_mm256_maskstore_epi32;
    let Some(px) = dst.get_mut(..LANES) else {
        return super::lanes::store_pixels(dst, m, c);
    };
    let ch = c.as_ptr().cast::<f32>();
    // SAFETY: the CPU has AVX2 (this function's contract); `Vec4` has the layout of
    // `[f32; 4]`, so `ch` points at the 32 contiguous floats of `c`, read eight at offsets 0,
    // 8, 16 and 24 (in bounds, no alignment needed); `px` holds eight
    // `[u8; 4]`, 32 contiguous bytes, written by the masked store (in bounds); `__m256i` is
    // plain bits.
    unsafe {
        let v = pixels8_reg(ch);
        _mm256_maskstore_epi32(px.as_mut_ptr().cast::<i32>(), lane_mask8(m), v);
    }
}

/// The RGBA8 pixels of eight colours `c` as `store_pixels_avx2` converts them (the same
/// bytes), pixel l in `out[l]`: for a packed group (`FragCtx::packed_group`), whose pixels
/// are stored one by one.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn pixels8_avx2(c: &[Vec4; LANES]) -> [[u8; 4]; LANES] {
    // SAFETY: the CPU has AVX2 (this function's contract); `c` is 32 contiguous floats
    // (`Vec4` has the layout of `[f32; 4]`); `__m256i` and `[[u8; 4]; 8]` are both 32 bytes,
    // every bit pattern valid.
    unsafe {
        let v = pixels8_reg(c.as_ptr().cast::<f32>());
        std::mem::transmute::<std::arch::x86_64::__m256i, [[u8; 4]; LANES]>(v)
    }
}

/// The conversion of `store_pixels_avx2` and `pixels8_avx2`: the 32 floats at `ch` (eight
/// pixels' r, g, b, a) to eight RGBA8 pixels in lane order.
///
/// # Safety
/// The CPU must have AVX2, and `ch` must point at 32 readable floats.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn pixels8_reg(ch: *const f32) -> std::arch::x86_64::__m256i {
    use super::lanes::unorm8_bits8;
    use std::arch::x86_64::{
        __m256i, _mm256_loadu_ps, _mm256_packs_epi32, _mm256_packus_epi16,
        _mm256_permutevar8x32_epi32, _mm256_setr_epi32,
    };
    // SAFETY: the CPU has AVX2 (this function's contract); the loads read eight floats at
    // offsets 0, 8, 16 and 24 of the 32 at `ch` (the caller's promise, no alignment needed).
    unsafe {
        // Pixels 2j and 2j + 1, each channel's byte in the low bits of its lane.
        let conv = |j: usize| -> __m256i { unorm8_bits8(_mm256_loadu_ps(ch.add(8 * j))) };
        // Halves [px0 px2 | px1 px3] and [px4 px6 | px5 px7], then bytes whose dwords are
        // pixels 0 2 4 6 1 3 5 7 (every value is in 0..=255: the signed packs keep it).
        let w01 = _mm256_packs_epi32(conv(0), conv(1));
        let w23 = _mm256_packs_epi32(conv(2), conv(3));
        _mm256_permutevar8x32_epi32(
            _mm256_packus_epi16(w01, w23),
            _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7),
        )
    }
}

/// Do spans `rows` fill less than three quarters of their row groups (`tri_span_in`'s groups
/// of eight pixels from each span's first), so that a primitive in the fused route's state
/// packs them (`FragCtx::packed_rows`)? Its row groups cost about as much as packed ones
/// (callgrind, 3 frames, the fused route's scenes packed at fills below 55%, 65%, 75%, 85%
/// and 101%: 75% the least on each, textured-cube's mipmapped spans, 7.55 fragments a row
/// group, 28% more when all packed: the packed group chooses its lanes' levels on its own).
#[cfg(target_arch = "x86_64")]
#[inline]
fn short_spans(rows: &[[i32; 3]]) -> bool {
    let (mut n, mut g) = (0i64, 0i64);
    for &[_, x0, x1] in rows {
        let k = i64::from(x1) - i64::from(x0) + 1;
        n += k;
        g += (k + 7) >> 3;
    }
    // n / 8g < 3/4.
    n < 6 * g
}

/// A packed group's fragments (`FragCtx::packed_rows`): window x and y and tile index of
/// lanes `0..n`.
#[derive(Default)]
struct Packed {
    x: [i32; LANES],
    y: [i32; LANES],
    at: [usize; LANES],
    n: usize,
}

impl Packed {
    /// Stores pixel l of `v` at lane l's tile index, for the group's `n` lanes.
    #[inline(always)]
    fn scatter(&self, bufs: &mut TileBufs, v: &[[u8; 4]; LANES]) {
        for (l, &at) in self.at.iter().enumerate().take(self.n.min(LANES)) {
            if let (Some(dst), Some(&c)) = (bufs.color.get_mut(at), v.get(l)) {
                *dst = c;
            }
        }
    }
}

/// `tri_span`'s general path for a span in the fused route's state ([`FusedSpan`], sampler
/// `tx` with coordinates at varying `to`): each covered group from the planes to the store.
/// False, with nothing written, when the sampler's state is not the route's. Out of line, so
/// that the general path's code stays as it was.
///
/// # Safety
/// The CPU must have AVX2 (`lanes::has_avx2`).
///
/// [`FusedSpan`]: super::texture::FusedSpan
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,popcnt")]
#[inline(never)]
unsafe fn fused_span<'s>(
    bufs: &mut TileBufs,
    tx: &'s Sampler,
    to: usize,
    planes: &'s [f32],
    a: &FusedArgs,
    slot: &mut FusedSlot<'s>,
) -> bool {
    let Some(fs) = fused_at(slot, tx, to, planes, a.nflat, a.fy, a.ox, a.qy) else {
        return false;
    };
    if let Some(dst) = bufs.color.get_mut(a.base..) {
        // SAFETY: the CPU has AVX2 (the caller's promise).
        unsafe { fs.span(a.x0, a.n, a.mask, dst) };
    }
    true
}

/// The primitive's fused route in `slot` at row `fy` and quad row `qy` (relative to the
/// planes' origin, whose window x is `ox`): the route of an earlier span moved to this row
/// (the levels looked up stay, as `fused_tex_rows`), else set up here and kept for the
/// primitive's next spans; None when the sampler's state is not the route's.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn fused_at<'s, 'a>(
    slot: &'a mut FusedSlot<'s>,
    tx: &'s Sampler,
    to: usize,
    planes: &'s [f32],
    nflat: usize,
    fy: f32,
    ox: i32,
    qy: f32,
) -> Option<&'a mut super::texture::FusedSpan<'s>> {
    if let Some(fs) = slot.as_mut() {
        fs.row(fy, qy);
    } else {
        *slot = super::texture::FusedSpan::new(tx, to, planes, nflat, fy, ox, qy);
    }
    slot.as_mut()
}

/// The fused route ([`FusedSpan`]) of one primitive's spans in one tile, set up by its first
/// fused span and moved to each next span's row (`FragCtx::tri_rows`); None before.
///
/// [`FusedSpan`]: super::texture::FusedSpan
pub type FusedSlot<'a> = Option<super::texture::FusedSpan<'a>>;

/// What each fragment of a primitive's spans writes besides its depth when that is the same
/// for all (`FragCtx::const_fill`): one colour, its bytes as stored, or none.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConstFill {
    /// A FLAT primitive's one colour.
    Flat([u8; 4]),
    /// A depth-only pass (ColorMask all false): nothing but the depth test.
    Depth,
}

/// `FragCtx::crossbar` of the units `tex`.
pub fn crossbar(tex: &[Option<(&Sampler, usize)>]) -> bool {
    tex.iter().flatten().any(|(s, _)| s.crossbar())
}

/// `FragCtx::tex` from one optional sampler per unit and the varying layout (see there).
pub fn tex_units<'a>(
    s: &'a [Option<Sampler>; MAX_TEXTURE_UNITS],
    rl: &RLayout,
) -> [Option<(&'a Sampler, usize)>; MAX_TEXTURE_UNITS] {
    let mut tex = [None; MAX_TEXTURE_UNITS];
    let mut n = 0;
    for (s, o) in s.iter().zip(&rl.tex) {
        if let (Some(s), Some(o), Some(dst)) = (s, o, tex.get_mut(n)) {
            *dst = Some((s, *o));
            n += 1;
        }
    }
    tex
}

/// What the per-fragment operations see of a pixel rectangle's or bitmap's fragments: a
/// front-facing primitive (the front stencil state applies, §4.1.5).
const PIXEL_PRIM: RPrim = RPrim {
    kind: super::setup::PrimKind::Point,
    flags: 0,
    bbox: [0; 4],
    mat: 0,
    voff: 0,
    xy: [0; 6],
    owns: 0,
    cover: 0,
    z: [0.0; 3],
};

/// The polygon stipple of `state` (GL 2.1 §3.5.6) as `FragCtx::stipple` wants it: row r for
/// window rows y ≡ r (mod 32), bit x set when window columns x' ≡ x (mod 32) are drawn.
pub fn stipple_rows(state: &crate::state::State) -> [u32; 32] {
    state.stipple.polygon
}

/// The stipple bits of window row `y` for the 64 pixels from column `x0` on: bit k for pixel
/// x0 + k.
#[inline(always)]
fn stipple_mask(rows: &[u32; 32], x0: i32, y: i32) -> u64 {
    let row = rows[(y & 31) as usize].rotate_right((x0 & 31) as u32);
    u64::from(row) | u64::from(row) << 32
}

/// One tile's slices of the colour and depth buffers, and the tile's lower-left pixel.
pub struct TileBufs<'a> {
    /// RGBA8, `TILE * TILE`.
    pub color: &'a mut [[u8; 4]],
    /// A second colour buffer written with the same fragments (DrawBuffer FRONT_AND_BACK or
    /// LEFT on a double-buffered framebuffer), blended against its own contents.
    pub color2: Option<&'a mut [[u8; 4]]>,
    /// Depth, `TILE * TILE`.
    pub depth: &'a mut [u32],
    /// Stencil, `TILE * TILE`.
    pub stencil: &'a mut [u8],
    /// Tile origin x.
    pub x: i32,
    /// Tile origin y.
    pub y: i32,
    /// Fragments counted for an occlusion query (`FragCtx::samples`).
    pub samples: u64,
}

/// A tile's buffers as `FragCtx::tiny` writes them, borrowed from its `TileBufs` for a run of
/// triangles (`raster::prims`): colour and depth, the tile's corner, the occlusion count, and
/// whether the tile has a second colour buffer.
#[cfg(target_arch = "x86_64")]
pub struct TinyOut<'b> {
    /// RGBA8, `TILE * TILE`.
    pub color: &'b mut [[u8; 4]],
    /// Depth, `TILE * TILE`.
    pub depth: &'b mut [u32],
    /// The tile's corner (`TileBufs::x`, `TileBufs::y`).
    pub tile: (i32, i32),
    /// `TileBufs::samples`.
    pub samples: &'b mut u64,
    /// `TileBufs::color2` is present.
    pub color2: bool,
}

impl FragCtx<'_> {
    /// The depth test (§4.1.6): does `d` pass against the stored `stored`?
    #[inline(always)]
    fn depth_pass(&self, d: u32, stored: u32) -> bool {
        match self.depth_func {
            gl::NEVER => false,
            gl::LESS => d < stored,
            gl::EQUAL => d == stored,
            gl::LEQUAL => d <= stored,
            gl::GREATER => d > stored,
            gl::NOTEQUAL => d != stored,
            gl::GEQUAL => d >= stored,
            _ => true,
        }
    }

    /// Depth test and depth write for the fragment at tile index `i`; true when it survives.
    #[inline(always)]
    fn depth(&self, bufs: &mut TileBufs, i: usize, z: f64) -> bool {
        if !self.depth_test {
            return true;
        }
        let d = depth_unorm(z);
        let Some(stored) = bufs.depth.get_mut(i) else {
            return false;
        };
        if !self.depth_pass(d, *stored) {
            return false;
        }
        if self.depth_mask {
            *stored = d;
        }
        true
    }

    /// The final colour of a fragment with varyings `v` and texture level of detail `lambda`
    /// (§3.8 texturing, §3.9 colour sum; PHONG_WIN lighting).
    #[inline(always)]
    fn color(&self, p: &RPrim, v: &[f32], lambda: [f32; MAX_TEXTURE_UNITS]) -> Vec4 {
        let g = |k: usize| v.get(k).copied().unwrap_or(0.0);
        let mut c = Vec4::new(g(0), g(1), g(2), g(3));
        let mut s = self.rl.spec.map(|o| Vec3::new(g(o), g(o + 1), g(o + 2)));
        if p.flags & F_PHONG != 0 {
            if let (Some(l), Some(o)) = (self.lighting, self.rl.phong) {
                let eye = Vec3::new(g(o), g(o + 1), g(o + 2));
                let mut n = Vec3::new(g(o + 3), g(o + 4), g(o + 5)).normalize_or_zero();
                let raw = Vec4::new(g(o + 6), g(o + 7), g(o + 8), g(o + 9));
                let face = if p.flags & F_BACK != 0 { BACK } else { FRONT };
                if face == BACK {
                    n = -n;
                }
                let mats = self.mats.get(p.mat as usize).or(self.mats.first());
                if let Some(m) = mats {
                    let (pc, ps) = l.shade(&m[face], face, raw, eye, n);
                    c = pc;
                    s = s.map(|_| ps.truncate());
                }
            }
        }
        // §3.8.13, texturing comes before the colour sum (§3.9) and fog (§3.10,
        // in `full`)
        // §3.8.15: each enabled unit takes the previous unit's result as Cf.
        let prim = c;
        if self.crossbar {
            // A COMBINE source TEXTUREn (GL 1.4 §3.8.13) reads unit n's texel: every unit
            // samples first, then the environments run in unit order.
            let mut raw = [[0.0f32; 4]; MAX_TEXTURE_UNITS];
            let mut units: UnitTexels = [None; MAX_TEXTURE_UNITS];
            for ((t, l), r) in self.tex.iter().zip(lambda).zip(&mut raw) {
                let Some((tx, o)) = *t else { break };
                *r = tx.texel([g(o), g(o + 1), g(o + 2), g(o + 3)], l);
                if let Some(slot) = units.get_mut(tx.unit()) {
                    *slot = Some(tx.combine_texel(*r));
                }
            }
            for (t, r) in self.tex.iter().zip(raw) {
                let Some((tx, _)) = *t else { break };
                c = tx.shade_texel(c, prim, r, &units);
            }
        } else {
            for (t, l) in self.tex.iter().zip(lambda) {
                let Some((tx, o)) = *t else { break };
                c = tx.shade(c, prim, [g(o), g(o + 1), g(o + 2), g(o + 3)], l);
            }
        }
        if let (true, Some(s)) = (self.color_sum, s) {
            c += s.extend(0.0);
        }
        c
    }

    /// Can `color_lanes` texture on lanes: no PHONG_WIN and every unit's sampler
    /// [`Sampler::lanes_ok`]. Chosen once per span.
    #[inline]
    fn tex_lanes_ok(&self, p: &RPrim) -> bool {
        p.flags & F_PHONG == 0 && self.tex.iter().flatten().all(|(t, _)| t.lanes_ok())
    }

    /// The colours (channel-major) of the lanes of `m` whose varyings are `vs` (lane-major
    /// per varying, `vs.len()` varyings) and λ `lam` (per unit, per lane): what `color` gives
    /// for each lane's fragment, bit for bit. With `on_lanes` (`tex_lanes_ok`) every unit's
    /// texels are filtered for the eight lanes (`Sampler::texels_lanes`) and its environment
    /// applied, in unit order (§3.8.15), then the colour sum (§3.9) follows (`tex_pixels`);
    /// otherwise each lane takes `color`. Lanes outside `m` hold unspecified values.
    #[inline(always)]
    fn color_lanes(
        &self,
        p: &RPrim,
        vs: &[[f32; LANES]],
        m: u8,
        lam: &[[f32; LANES]; MAX_TEXTURE_UNITS],
        on_lanes: bool,
    ) -> [[f32; LANES]; 4] {
        if !on_lanes {
            let mut col = [[0.0f32; LANES]; 4];
            let mut v = [0.0f32; MAXV];
            let nv = vs.len().min(MAXV);
            for l in 0..LANES {
                if m & (1 << l) == 0 {
                    continue;
                }
                for (vj, lj) in v.iter_mut().zip(vs) {
                    *vj = lj[l];
                }
                let c = self.color(p, &v[..nv], lam.map(|u| u[l]));
                for (ch, x) in col.iter_mut().zip(c.to_array()) {
                    ch[l] = x;
                }
            }
            return col;
        }
        super::lanes::from_pixels(&self.tex_pixels(vs, m, lam))
    }

    /// `color_lanes` on lanes (`tex_lanes_ok`), pixel-major: the colour of lane l's fragment
    /// in `out[l]`. Lanes outside `m` hold unspecified values.
    #[inline(always)]
    fn tex_pixels(
        &self,
        vs: &[[f32; LANES]],
        m: u8,
        lam: &[[f32; LANES]; MAX_TEXTURE_UNITS],
    ) -> [Vec4; LANES] {
        self.tex_pixels_on::<false>(vs, m, lam)
    }

    /// `tex_pixels`, its colour rows transposed on eight lanes a register where `AVX2`
    /// (`to_pixels_avx2`: the same floats, moved), true only where the CPU has AVX2
    /// (`tri_span_in`).
    #[inline(always)]
    fn tex_pixels_on<const AVX2: bool>(
        &self,
        vs: &[[f32; LANES]],
        m: u8,
        lam: &[[f32; LANES]; MAX_TEXTURE_UNITS],
    ) -> [Vec4; LANES] {
        const ZERO: [f32; LANES] = [0.0; LANES];
        let g = |k: usize| vs.get(k).unwrap_or(&ZERO);
        let mut c: [Vec4; LANES] = match vs.first_chunk::<4>() {
            // SAFETY: `AVX2` is true only where the CPU has AVX2 (above).
            #[cfg(target_arch = "x86_64")]
            Some(rows) if AVX2 => unsafe { to_pixels_avx2(rows) },
            _ => super::lanes::to_pixels([g(0), g(1), g(2), g(3)]),
        };
        // Each unit's texels, then its environment, in unit order (§3.8.15). A sampler with
        // `lanes_ok` is never a COMBINE with a TEXTUREn source, so no environment reads another
        // unit's texel and sampling unit k + 1 after unit k's environment gives the same texels.
        // COMBINE's PRIMARY_COLOR is the colour before the first unit.
        let prim = c;
        for (t, lu) in self.tex.iter().zip(lam) {
            let Some((tx, o)) = *t else { break };
            // The unit's four coordinate rows with one bounds check (where the layout holds
            // them, always in `tri_span_in`), not four with their fallbacks (texture-targets:
            // ≈16 instructions a unit and group).
            let coords = match vs.get(o..).and_then(|v| v.first_chunk::<4>()) {
                Some([s, t, r, q]) => [s, t, r, q],
                None => [g(o), g(o + 1), g(o + 2), g(o + 3)],
            };
            let tl = tx.texels_lanes(coords, lu, m);
            tx.env_lanes_with(&mut c, &prim, &tl, m);
        }
        if let (true, Some(o)) = (self.color_sum, self.rl.spec) {
            let (sr, sg, sb) = (g(o), g(o + 1), g(o + 2));
            for (l, c) in c.iter_mut().enumerate() {
                *c += Vec3::new(sr[l], sg[l], sb[l]).extend(0.0);
            }
        }
        c
    }

    /// Writes colour `c` at tile index `i` through ColorMask (§4.2.2).
    #[inline(always)]
    fn write(&self, bufs: &mut TileBufs, i: usize, c: Vec4) {
        let px = [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)];
        self.store(bufs, i, px);
    }

    /// Writes unorm8 colour `px` at tile index `i` through ColorMask (§4.2.2), to each colour
    /// buffer being drawn.
    #[inline(always)]
    fn store(&self, bufs: &mut TileBufs, i: usize, px: [u8; 4]) {
        if let Some(dst) = bufs.color.get_mut(i) {
            self.store_one(dst, px);
        }
        if let Some(dst) = bufs.color2.as_deref_mut().and_then(|c| c.get_mut(i)) {
            self.store_one(dst, px);
        }
    }

    /// Writes `px` over `dst` through ColorMask.
    #[inline(always)]
    fn store_one(&self, dst: &mut [u8; 4], px: [u8; 4]) {
        if self.count {
            dst[0] = dst[0].wrapping_add(1);
        } else if self.color_mask == [true; 4] {
            *dst = px;
        } else {
            for k in 0..4 {
                if self.color_mask[k] {
                    dst[k] = px[k];
                }
            }
        }
    }

    /// The full sequence for one fragment with colour `c` (before clamping) and fog coordinate
    /// `fogc` at tile index `i`: clamp (§3.9), fog (§3.10), alpha test (§4.1.4), stencil and
    /// depth tests (§4.1.5, §4.1.6), blending or logic op (§4.1.8, §4.1.10), masked write.
    /// A fragment that passes the depth test counts for an occlusion query.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn full(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        i: usize,
        z: f64,
        c: Vec4,
        fogc: f32,
    ) {
        let mut c = c.clamp(Vec4::ZERO, Vec4::ONE);
        // (Texturing, §3.8, is applied by `color` before the colour sum.)
        if let Some(fog) = &ops.fog {
            c = fog.apply(c, fogc);
        }
        if let Some((func, reference)) = ops.alpha {
            if !compare(func, unorm8(c.w), reference) {
                return;
            }
        }
        if let Some(sides) = &ops.stencil {
            let side = &sides[usize::from(p.flags & F_BACK != 0)];
            let Some(&s) = bufs.stencil.get(i) else {
                return;
            };
            let (pass, which) = if !side.test(s) {
                (false, 0)
            } else if !self.depth(bufs, i, z) {
                (false, 1)
            } else {
                (true, 2)
            };
            if let Some(st) = bufs.stencil.get_mut(i) {
                *st = side.update(which, s);
            }
            if !pass {
                return;
            }
        } else if !self.depth(bufs, i, z) {
            return;
        }
        if self.samples {
            bufs.samples += 1;
        }
        let src = [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)];
        // Blending and the logic op read each colour buffer's own contents (§4.1.8, §4.1.10).
        let combine = |d: [u8; 4]| match ops.write {
            ColorWrite::Replace => src,
            ColorWrite::Blend(b) => b.apply(src, d),
            ColorWrite::Logic(op) => {
                std::array::from_fn(|k| super::fragops::logic_op(op, src[k], d[k]))
            }
        };
        if let Some(dst) = bufs.color.get_mut(i) {
            self.store_one(dst, combine(*dst));
        }
        if let Some(dst) = bufs.color2.as_deref_mut().and_then(|c| c.get_mut(i)) {
            self.store_one(dst, combine(*dst));
        }
    }

    /// The fog coordinate among varyings `v` (0 when fog is off).
    #[inline(always)]
    fn fog_coord(&self, v: &[f32]) -> f32 {
        self.rl.fog.and_then(|o| v.get(o).copied()).unwrap_or(0.0)
    }

    /// One fragment of a pixel rectangle or a bitmap at tile index `i` (GL 2.1 §3.6.5, §3.7):
    /// colour `c` (textured and summed by the caller), window depth `z`, fog coordinate `fogc`;
    /// then fog and the per-fragment operations of §4.1, as a front-facing fragment takes them.
    #[inline]
    pub fn pixel(&self, bufs: &mut TileBufs, i: usize, z: f64, c: Vec4, fogc: f32) {
        match &self.ops {
            Some(ops) => self.full(ops, bufs, &PIXEL_PRIM, i, z, c, fogc),
            None => {
                if self.depth(bufs, i, z) {
                    self.write(bufs, i, c);
                }
            }
        }
    }

    /// One fragment of a line or point at window pixel (x, y).
    pub fn fragment(&self, bufs: &mut TileBufs, p: &RPrim, x: i32, y: i32, z: f64, v: &[f32]) {
        let i = ((y - bufs.y) as usize) * TILE + (x - bufs.x) as usize;
        if let Some(ops) = &self.ops {
            // A line or point fragment has no quad derivatives: λ = 0, as below.
            let c = self.color(p, v, [0.0; MAX_TEXTURE_UNITS]);
            self.full(ops, bufs, p, i, z, c, self.fog_coord(v));
            return;
        }
        if self.depth(bufs, i, z) {
            if self.samples {
                bufs.samples += 1;
            }
            // A point has no derivatives: λ = 0 (the base level, magnification).
            let c = self.color(p, v, [0.0; MAX_TEXTURE_UNITS]);
            self.write(bufs, i, c);
        }
    }

    /// A triangle span: pixels `x0..=x1` of row `y` (all inside the tile), `planes` the
    /// primitive's pool floats (1/w plane then one plane per varying, relative to its bbox corner).
    /// Its fused route set up for this span alone (the tests' reference for `tri_rows`).
    #[cfg(test)]
    pub fn tri_span(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        y: i32,
        x0: i32,
        x1: i32,
    ) {
        self.tri_rows(bufs, p, planes, &[[y, x0, x1]], &mut None);
    }

    /// `tri_span` of rows `[y, x0, x1]` of one primitive (in the tile), whose spans in this
    /// tile share `slot` (None before the first): the fused route is set up once for them, the
    /// same bits. A thin dispatch, inlined into its callers: with the portable body inlined
    /// here, every call paid that body's prologue and epilogue (six registers saved, a 3 KiB
    /// frame) on its way to `tri_rows_avx2`, ≈28 instructions a call. Rows come a batch at a
    /// time (`raster::tri`): the general path's set-up (its scratch zeroed, the units' varying
    /// rows looked up) is paid once a batch, not once a span.
    #[inline(always)]
    pub fn tri_rows<'s>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        rows: &[[i32; 3]],
        slot: &mut FusedSlot<'s>,
    ) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.tri_rows_avx2(bufs, p, planes, rows, slot) };
            return;
        }
        self.tri_rows_portable(bufs, p, planes, rows, slot);
    }

    /// `tri_rows` without AVX2 (out of line, as `tri_rows_avx2`).
    #[inline(never)]
    fn tri_rows_portable<'s>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        rows: &[[i32; 3]],
        slot: &mut FusedSlot<'s>,
    ) {
        self.tri_rows_in::<false>(bufs, p, planes, rows, slot);
    }

    /// `tri_rows` compiled for AVX2 and POPCNT (as `plain_rows_avx2`: the same bits).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn tri_rows_avx2<'s>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        rows: &[[i32; 3]],
        slot: &mut FusedSlot<'s>,
    ) {
        self.tri_rows_in::<true>(bufs, p, planes, rows, slot);
    }

    /// The body of `tri_rows`: the rows of a smooth point or line (`aa_rows`) or with
    /// per-fragment operations (`ops_rows`) together, any other row by `tri_span_in` with the
    /// general path's scratch set up here once for all the rows (texture-targets, callgrind:
    /// ≈370 instructions of set-up a span before).
    #[inline(always)]
    fn tri_rows_in<'s, const AVX2: bool>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        rows: &[[i32; 3]],
        slot: &mut FusedSlot<'s>,
    ) {
        if p.flags & (F_AAPOINT | F_AALINE) != 0 {
            return self.aa_rows(bufs, p, planes, rows);
        }
        if let Some(ops) = &self.ops {
            return self.ops_rows(ops, bufs, p, planes, rows);
        }
        // The varyings' rows: only the `nv` in use are zeroed (`lanes::varyings` writes them
        // all for each group); zeroing all MAXV rows (1248 bytes) was a memset of ≈85
        // instructions a span on texture-targets.
        let nv = self.rl.n.min(MAXV);
        let mut vl_rows = [std::mem::MaybeUninit::<[f32; LANES]>::uninit(); MAXV];
        let vl_used = vl_rows.get_mut(..nv).unwrap_or_default();
        for row in vl_used.iter_mut() {
            row.write([0.0; LANES]);
        }
        // SAFETY: every element of `vl_used` was initialised just above, and
        // `MaybeUninit<[f32; LANES]>` has the layout of `[f32; LANES]`.
        let vl: &mut [[f32; LANES]] =
            unsafe { &mut *(std::ptr::from_mut(vl_used) as *mut [[f32; LANES]]) };
        let plan = self.row_plan(bufs, p, planes, rows);
        #[cfg(target_arch = "x86_64")]
        if AVX2 && plan.packed {
            // SAFETY: `AVX2` is true only where the CPU has AVX2 and POPCNT (`tri_rows_avx2`).
            unsafe { self.packed_rows(bufs, p, planes, rows, vl, &plan, slot) };
            return;
        }
        // λ per unit and lane: a unit's entry is written for each group before it is read
        // where the unit needs λ, and stays 0 where it does not, whatever the row. (Zeroed
        // after the packed route's return, which reads neither: 768 bytes a call set and
        // copied for nothing on texture-targets' small triangles, ≈45 instructions.)
        let mut lam = [[0.0f32; LANES]; MAX_TEXTURE_UNITS];
        let mut lq = [[[0.0f32; LANES]; ROW_QUAD_BLOCKS]; MAX_TEXTURE_UNITS];
        for &row in rows {
            self.tri_span_in::<AVX2>(bufs, p, planes, row, slot, vl, &mut lam, &mut lq, &plan);
        }
    }

    /// The spans `rows` of `p` by the packed route (`RowPlan::packed`): each span's depth test
    /// as `tri_span_in`'s, then the fragments that pass, from all the spans, eight to a group
    /// in the order the spans give them (a primitive's pixels are distinct, so the order of
    /// their colour writes does not matter), each group's varyings and λ per lane at its own
    /// pixel, its colours by `tex_pixels_on` and each lane's pixel stored at its place. On
    /// texture-targets' small triangles a span row fills about half a group (callgrind: 4.2
    /// fragments a group on the four-unit sphere, 2.6 on the height field), and a group's
    /// texturing costs the same whatever its fragments. Each fragment's colour is the general
    /// path's, bit for bit: the same operations on each lane (`varyings_xy_avx2`,
    /// `quad_lambda_xy8`, the same `tex_pixels_on` and conversion).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline]
    #[allow(clippy::too_many_arguments)]
    unsafe fn packed_rows<'s>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        rows: &[[i32; 3]],
        vl: &mut [[f32; LANES]],
        plan: &RowPlan<'s>,
        slot: &mut FusedSlot<'s>,
    ) {
        // The λ planes of each unit that needs λ, looked up once.
        let mut lpl = [None; MAX_TEXTURE_UNITS];
        for (u, (l, t)) in lpl.iter_mut().zip(&self.tex).enumerate() {
            let Some((tx, to)) = *t else { break };
            if plan.lod & (1 << u) != 0 {
                *l = tx.lambda_planes_of(planes, to);
            }
        }
        // The fused route's state: its route at y 1 (`FusedSpan::packed_group`).
        let mut fused = match plan.fused {
            Some((tx, to)) => fused_at(slot, tx, to, planes, plan.nflat, 1.0, p.bbox[0], 1.0),
            None => None,
        };
        let mut g = Packed::default();
        for &row in rows {
            let Some((mut mask, base)) = self.span_coverage::<true>(bufs, p, row) else {
                continue;
            };
            let [y, x0, _] = row;
            while mask != 0 {
                let k = mask.trailing_zeros();
                mask &= mask - 1;
                let l = g.n;
                if let (Some(x), Some(yy), Some(at)) =
                    (g.x.get_mut(l), g.y.get_mut(l), g.at.get_mut(l))
                {
                    *x = x0 + k as i32;
                    *yy = y;
                    *at = base + k as usize;
                }
                g.n += 1;
                if g.n == LANES {
                    // SAFETY: the CPU has AVX2 (this function's contract).
                    unsafe { self.packed_group(bufs, p, planes, &g, vl, &lpl, plan, &mut fused) };
                    g.n = 0;
                }
            }
        }
        if g.n > 0 {
            // SAFETY: as above.
            unsafe { self.packed_group(bufs, p, planes, &g, vl, &lpl, plan, &mut fused) };
        }
    }

    /// Whether the spans `rows` of `p` (as `tri_rows` takes them) take the packed route
    /// (`packed_rows`), and whether by the fused route's groups (`FusedSpan::packed_group`),
    /// for the tests.
    #[cfg(test)]
    pub(crate) fn packs(
        &self,
        bufs: &TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) -> (bool, bool) {
        let plan = self.row_plan(bufs, p, planes, rows);
        (plan.packed, plan.packed && plan.fused.is_some())
    }

    /// One group of `packed_rows`: the first `g.n` lanes of `g`, by the fused route `fused`
    /// where the primitive takes it (`FusedSpan::packed_group`).
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline]
    #[allow(clippy::too_many_arguments)]
    unsafe fn packed_group(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        g: &Packed,
        vl: &mut [[f32; LANES]],
        lpl: &[Option<[[f32; 3]; 4]>; MAX_TEXTURE_UNITS],
        plan: &RowPlan<'_>,
        fused: &mut Option<&mut super::texture::FusedSpan<'_>>,
    ) {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let n = g.n.min(LANES);
        let m = (u16::MAX >> (16 - n)) as u8;
        if let Some(fs) = fused {
            // SAFETY: the CPU has AVX2 (this function's contract).
            let v = unsafe { fs.packed_group(&g.x, &g.y, oy, m) };
            return g.scatter(bufs, &v);
        }
        // Lanes past `n` repeat lane 0's pixel (a fragment of the primitive), never stored.
        let lane = |l: usize| if l < n { l } else { 0 };
        let fx: [f32; LANES] = std::array::from_fn(|l| (g.x[lane(l)] - ox) as f32);
        let fy: [f32; LANES] = std::array::from_fn(|l| (g.y[lane(l)] - oy) as f32);
        // SAFETY: the CPU has AVX2 (this function's contract).
        unsafe { super::lanes::varyings_xy_avx2(planes, plan.nflat, &fx, &fy, vl) };
        let mut lam = [[0.0f32; LANES]; MAX_TEXTURE_UNITS];
        if plan.lod != 0 {
            // Each lane's quad: its lower-left pixel relative to the planes' origin.
            let qx: [f32; LANES] = std::array::from_fn(|l| ((g.x[lane(l)] & !1) - ox) as f32);
            let qy: [f32; LANES] = std::array::from_fn(|l| ((g.y[lane(l)] & !1) - oy) as f32);
            for ((lu, pl), t) in lam.iter_mut().zip(lpl).zip(&self.tex) {
                let (Some(pl), Some((tx, _))) = (pl, t) else {
                    continue;
                };
                // SAFETY: as above.
                *lu = unsafe { tx.quad_lambda_xy8(pl, &qx, &qy) };
            }
        }
        let px = self.tex_pixels_on::<true>(vl, m, &lam);
        // SAFETY: as above.
        let v = unsafe { pixels8_avx2(&px) };
        g.scatter(bufs, &v);
    }

    /// What `tri_span_in` decides for each span of `p` in this tile, decided once for them
    /// all: none of it depends on the row (texture-targets, callgrind: ≈40 instructions a
    /// span that reaches the colour stage, the units' samplers asked again for each).
    #[inline(always)]
    fn row_plan<'s>(
        &'s self,
        bufs: &TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) -> RowPlan<'s> {
        let nv = self.rl.n;
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let phong = p.flags & F_PHONG != 0;
        let whole = !self.count && self.color_mask == [true; 4] && bufs.color2.is_none();
        let route = if nv == 4 && nflat == 0 && !phong {
            SpanRoute::Smooth
        } else if nv == 4 && nflat == 4 && !phong && whole {
            SpanRoute::Flat
        } else {
            SpanRoute::General
        };
        let on_lanes = self.tex_lanes_ok(p);
        // The units that need λ, in unit order up to the first absent one (as the loops over
        // `self.tex` that break there).
        let mut lod = 0u8;
        for (u, t) in self.tex.iter().enumerate() {
            let Some((tx, _)) = *t else { break };
            if tx.needs_lambda() {
                lod |= 1 << u;
            }
        }
        let mut fused = None;
        #[cfg(target_arch = "x86_64")]
        if let [Some((tx, to)), None, ..] = self.tex {
            let nv = nv.min(MAXV);
            if whole
                && on_lanes
                && super::texture::FusedSpan::covers(tx)
                && !(self.color_sum && self.rl.spec.is_some())
                && to.checked_add(4).is_some_and(|e| e <= nv)
                && planes.len() >= 3 + 3 * nv
                && super::lanes::has_avx2()
            {
                fused = Some((tx, to));
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = planes;
        let depth_only = self.color_mask == [false; 4] && !self.count;
        // The general path's textured spans of one colour buffer written whole, where every
        // unit that needs λ has planes for `quad_lambda_xy8` (no cube map) and the pool holds
        // every varying; the fused route's spans where they are short (`short_spans`: its
        // row groups cost less than a packed group where full).
        #[cfg(target_arch = "x86_64")]
        let packed = if fused.is_some() {
            !depth_only && short_spans(rows)
        } else {
            route == SpanRoute::General
                && whole
                && on_lanes
                && !depth_only
                && self.tex.first().is_some_and(Option::is_some)
                && planes.len() >= 3 + 3 * nv
                && nv <= MAXV
                && self.tex.iter().enumerate().all(|(u, t)| {
                    lod & (1 << u) == 0
                        || t.is_some_and(|(tx, to)| tx.lambda_planes_of(planes, to).is_some())
                })
                && super::lanes::has_avx2()
        };
        #[cfg(not(target_arch = "x86_64"))]
        let packed = {
            let _ = rows;
            false
        };
        RowPlan {
            depth_only,
            nflat,
            route,
            whole,
            on_lanes,
            lod,
            fused,
            packed,
        }
    }

    /// Pass 1 of a span `[y, x0, x1]` of `p`: the depth test over it into a coverage mask
    /// (n <= TILE = 64 bits), the comparison chosen once per span, a polygon stipple (§3.5.6)
    /// removing fragments first; the fragments that pass counted for an occlusion query. None
    /// when none passes, else the mask (bit k for x0 + k) and the span's first tile index.
    #[inline(always)]
    fn span_coverage<const AVX2: bool>(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        [y, x0, x1]: [i32; 3],
    ) -> Option<(u64, usize)> {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let fy = (y - oy) as f32;
        let zrow = p.z[0] + p.z[2] * fy;
        let row = ((y - bufs.y) as usize) * TILE;
        let base = row + (x0 - bufs.x) as usize;
        let n = (x1 - x0 + 1) as usize;
        let (fx0, dz) = (x0 - ox, p.z[1]);
        let all = u64::MAX >> (64 - n.clamp(1, 64));
        let mask = match self.stipple {
            Some(rows) if p.flags & F_LINE == 0 => {
                let live = all & stipple_mask(&rows, x0, y);
                if live == 0 {
                    return None;
                }
                self.depth_mask_span::<AVX2>(bufs, base, n, zrow, dz, fx0, live)
            }
            _ => self.depth_mask_span::<AVX2>(bufs, base, n, zrow, dz, fx0, all),
        };
        if mask == 0 {
            return None;
        }
        if self.samples {
            bufs.samples += u64::from(mask.count_ones());
        }
        Some((mask, base))
    }

    /// One row of `tri_rows_in` (`AVX2`: true only in `tri_rows_avx2`, where the CPU has
    /// AVX2; the general path's varyings then on eight lanes a register), the general path's
    /// scratch `vl` (the `rl.n` varying rows, at most MAXV), `lam` and `lq` (each unit's λ of
    /// the span's quads) set up by the caller.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn tri_span_in<'s, const AVX2: bool>(
        &'s self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &'s [f32],
        [y, x0, x1]: [i32; 3],
        slot: &mut FusedSlot<'s>,
        vl: &mut [[f32; LANES]],
        lam: &mut [[f32; LANES]; MAX_TEXTURE_UNITS],
        lq: &mut RowQuads,
        plan: &RowPlan<'s>,
    ) {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let fy = (y - oy) as f32;
        let n = (x1 - x0 + 1) as usize;
        let Some((mut mask, base)) = self.span_coverage::<AVX2>(bufs, p, [y, x0, x1]) else {
            return;
        };
        // ColorMask all false (a depth-only pass, as a shadow map's first pass): the depth test
        // above wrote what this span writes; its colours would be computed to be thrown away.
        if plan.depth_only {
            return;
        }
        // Pass 2: perspective-correct varyings (§3.5.1 eq. 3.9) and colour for survivors.
        let nflat = plan.nflat;
        // Fast path: smooth primary colour only (no FLAT, secondary colour or PHONG_WIN).
        if plan.route == SpanRoute::Smooth {
            if let Some(&[w0, wx, wy, r0, rx, ry, g0, gx, gy, b0, bx, by, a0, ax, ay]) =
                planes.get(..15)
            {
                let (w0, r0, g0, b0, a0) = (
                    w0 + wy * fy,
                    r0 + ry * fy,
                    g0 + gy * fy,
                    b0 + by * fy,
                    a0 + ay * fy,
                );
                // One colour buffer written whole: eight fragments at a time (`lanes`).
                if !self.count && self.color_mask == [true; 4] && bufs.color2.is_none() {
                    let co = [w0, wx, r0, rx, g0, gx, b0, bx, a0, ax];
                    if let Some(dst) = bufs.color.get_mut(base..base + n) {
                        super::lanes::smooth_rgba(dst, mask, x0 - ox, &co);
                    }
                    return;
                }
                while mask != 0 {
                    let k = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    let fx = (x0 - ox + k as i32) as f32;
                    let inv = 1.0 / (w0 + wx * fx);
                    let c = Vec4::new(
                        (r0 + rx * fx) * inv,
                        (g0 + gx * fx) * inv,
                        (b0 + bx * fx) * inv,
                        (a0 + ax * fx) * inv,
                    );
                    self.write(bufs, base + k, c);
                }
            }
            return;
        }
        // FLAT colour alone, one colour buffer written whole: eight fragments at a time.
        if plan.route == SpanRoute::Flat {
            if let (Some(pl), Some(dst)) = (
                planes
                    .get(3..15)
                    .and_then(|p| <&[f32; 12]>::try_from(p).ok()),
                bufs.color.get_mut(base..base + n),
            ) {
                super::lanes::flat_rgba(dst, mask, x0 - ox, fy, pl);
                return;
            }
        }
        // The general path (textured spans among them), eight fragments at a time: their
        // perspective-correct varyings (§3.5.1 eq. 3.9) on lanes, then each covered one's
        // colour, stored on lanes when one colour buffer is written whole.
        let (on_lanes, whole) = (plan.on_lanes, plan.whole);
        // λ per 2x2 quad (§3.8.8), on lanes: lane l's is its pixel's quad's, at the quad's
        // lower-left pixel relative to the bounding-box corner (as `quad_lambda`), for the
        // units of `plan.lod`.
        let lod = plan.lod != 0;
        let qy = ((y & !1) - oy) as f32;
        // The common textured state (one 2D unit, MODULATE or REPLACE, no colour sum, one
        // colour buffer written whole) on AVX2: each group from the planes to the store in
        // registers, its λ included (`FusedSpan`).
        #[cfg(target_arch = "x86_64")]
        if let Some((tx, to)) = plan.fused {
            let span = FusedArgs {
                x0,
                n,
                base,
                mask,
                nflat,
                fy,
                ox,
                qy,
            };
            // SAFETY: the CPU has AVX2 (`has_avx2`, in `row_plan`).
            if unsafe { fused_span(bufs, tx, to, planes, &span, slot) } {
                return;
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = slot;
        // Each quad's λ once (not once per lane), those of the span's covered groups all at
        // once, eight quads a call (`Sampler::quad_lambda_row`): the groups from the first
        // covered one's (ga) to the last's (gb) lie in window quads qa..=qb (at most 33), quad
        // qa + j's λ in `lq[unit][j / 8][j % 8]`. Texture-targets (small triangles, spans of a
        // group or two): a `SpanLambda` window per group cost ≈55 instructions a group besides
        // its λ calls.
        let qa = (x0 + (mask.trailing_zeros() as i32 & !7)) >> 1;
        if lod {
            let gb = (63 - mask.leading_zeros()) as i32 & !7;
            let nq = (((x0 + gb + 7) >> 1) - qa + 1) as usize;
            let blocks = nq.div_ceil(LANES).min(ROW_QUAD_BLOCKS);
            for (u, (lu, t)) in lq.iter_mut().zip(&self.tex).enumerate() {
                let Some((tx, to)) = *t else { break };
                if plan.lod & (1 << u) != 0 {
                    let out = lu.get_mut(..blocks).unwrap_or_default();
                    tx.quad_lambda_row::<AVX2>(planes, to, ox, qy, qa, out);
                }
            }
        }
        let mut g = 0;
        while g < n.min(64) {
            let m = (mask >> g) & ((1 << LANES) - 1);
            if m == 0 {
                g += LANES;
                continue;
            }
            let vs = &mut *vl;
            varyings_on::<AVX2>(planes, nflat, x0 - ox + g as i32, fy, vs);
            if lod {
                // The group's first pixel's quad, 0..=28 quads from qa.
                let d = (((x0 + g as i32) >> 1) - qa) as usize;
                for (u, (lu, q)) in lam.iter_mut().zip(&*lq).enumerate() {
                    if plan.lod & (1 << u) != 0 {
                        *lu = spread_on::<AVX2>(q, d, x0 + g as i32);
                    }
                }
            }
            if whole && on_lanes {
                // Pixel-major colours straight to RGBA8 (no transposition back).
                let px = self.tex_pixels_on::<AVX2>(vs, m as u8, lam);
                if let Some(dst) = bufs.color.get_mut(base + g..) {
                    store_pixels_on::<AVX2>(dst, m as u8, &px);
                }
                g += LANES;
                continue;
            }
            let col = self.color_lanes(p, vs, m as u8, lam, on_lanes);
            if whole {
                if let Some(dst) = bufs.color.get_mut(base + g..) {
                    super::lanes::store_rgba(dst, m, &col);
                }
            } else {
                for l in (0..LANES).filter(|l| m & (1 << l) != 0) {
                    let c = Vec4::new(col[0][l], col[1][l], col[2][l], col[3][l]);
                    self.write(bufs, base + g + l, c);
                }
            }
            g += LANES;
        }
    }

    /// The planes of `p` when every span of it takes `smooth_row`, else None (then each span
    /// goes through `tri_span`): no per-fragment operation beyond the depth test, no polygon
    /// stipple, the smooth primary colour alone (no FLAT, secondary colour or PHONG_WIN), one
    /// colour buffer written whole (no second buffer, ColorMask all true, no coverage count),
    /// the 1/w and four colour planes present — the spans `tri_span` sends through
    /// `depth_mask_span` and `lanes::smooth_rgba`. Decided once per primitive and tile.
    #[inline(always)]
    pub fn smooth_planes<'p>(
        &self,
        bufs: &TileBufs,
        p: &RPrim,
        planes: &'p [f32],
    ) -> Option<&'p [f32; 15]> {
        let stippled = self.stipple.is_some() && p.flags & F_LINE == 0;
        if self.ops.is_some()
            || self.rl.n != 4
            || p.flags & NOT_SMOOTH != 0
            || stippled
            || self.count
            || self.color_mask != [true; 4]
            || bufs.color2.is_some()
        {
            return None;
        }
        planes.get(..15).and_then(|p| p.try_into().ok())
    }

    /// What `smooth_planes` asks of the flush's state and the tile (the same for all its
    /// primitives; `smooth_planes` tests it in its own order, the primitive's flags early):
    /// no per-fragment operation beyond the depth test, no texturing or secondary colour, no
    /// coverage count, one colour buffer written whole.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn smooth_state(&self, bufs: &TileBufs) -> bool {
        self.ops.is_none()
            && self.rl.n == 4
            && !self.count
            && self.color_mask == [true; 4]
            && bufs.color2.is_none()
    }

    /// The depth test of `tiny_smooth`, decided once for a bin of primitives
    /// (`raster::prims`): LESS or LEQUAL where the CPU has AVX2, the state lets every smooth
    /// triangle take `smooth_rows` (`smooth_state`, and no polygon stipple, so that only each
    /// primitive's flags are left to check) and the depth test is one `depth_fast` compiles
    /// in; else 0 (every primitive through `raster::prim`).
    #[inline(always)]
    pub fn tiny_depth(&self, bufs: &TileBufs) -> u32 {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() && self.stipple.is_none() && self.smooth_state(bufs) {
            return self.depth_fast();
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = bufs;
        0
    }

    /// A triangle whose covered pixels setup found (`RPrim::cover`), its bounding box inside
    /// the tile, its floats `planes`, the depth test `F` (LESS or LEQUAL, `tiny_depth`): when
    /// `smooth_planes` accepts it, what `smooth_rows` draws for its spans, and when it is a
    /// FLAT one `const_fill` gives one colour, what `const_rows` draws; each covered pixel
    /// computed alone (`lanes::tiny_avx2`) instead of in an
    /// eight-lane group; the occlusion count. False, nothing drawn, for any other primitive.
    /// The tile's buffers come borrowed for a run of such triangles (`TinyOut`).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline]
    pub unsafe fn tiny<const F: u32>(&self, out: &mut TinyOut, p: &RPrim, planes: &[f32]) -> bool {
        use super::lanes::{tiny_avx2, TinyFill};
        // Setup sets no covered bit outside the box (`RPrim::cover`).
        let (cover, [x0, y0, ..]) = (p.cover, p.bbox);
        let at = ((y0 - out.tile.1) as usize) * TILE + (x0 - out.tile.0) as usize;
        let fill = if p.flags & NOT_SMOOTH == 0 {
            // `smooth_planes`' test of the primitive (its state is `tiny_depth`'s).
            let Some(pl) = planes.get(..15).and_then(|p| p.try_into().ok()) else {
                return false;
            };
            TinyFill::Smooth(pl)
        } else if let Some(ConstFill::Flat(px)) = self.const_fill_of(out.color2, p, planes) {
            TinyFill::Flat(px)
        } else {
            return false;
        };
        // SAFETY: the CPU has AVX2 (this function's contract).
        let pass = unsafe { tiny_avx2::<F>(out.color, out.depth, at, cover, &p.z, fill) };
        if self.samples {
            *out.samples += u64::from(pass.count_ones());
        }
        true
    }

    /// Spans of a primitive `smooth_planes` accepted (its planes `pl`), `rows` holding each
    /// span's window row and first and last pixel (all inside the tile): `smooth_row` of each.
    #[inline(never)]
    pub fn smooth_rows(&self, bufs: &mut TileBufs, p: &RPrim, pl: &[f32; 15], rows: &[[i32; 3]]) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.smooth_rows_avx2(bufs, p, pl, rows) };
            return;
        }
        self.smooth_rows_on::<false, 0>(bufs, p, pl, rows);
    }

    /// `smooth_rows` compiled for AVX2, each row's groups through
    /// `lanes::smooth_depth_span_avx2` (the same bits as the SSE2 route).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn smooth_rows_avx2(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        pl: &[f32; 15],
        rows: &[[i32; 3]],
    ) {
        // The common depth tests chosen once for the call (each group's compare then known
        // when `smooth_row` is compiled), any other through `test` per group.
        match self.depth_fast() {
            LESS => self.smooth_rows_on::<true, LESS>(bufs, p, pl, rows),
            LEQUAL => self.smooth_rows_on::<true, LEQUAL>(bufs, p, pl, rows),
            _ => self.smooth_rows_on::<true, 0>(bufs, p, pl, rows),
        }
    }

    /// The depth test when it is one of the common ones, chosen once per call by the AVX2
    /// routes (`smooth_rows_avx2`, `plain_rows_avx2`, `tests_rows_avx2`) so that each group's
    /// compare is known when their loops are compiled: on with the depth mask true and
    /// DepthFunc LESS or LEQUAL gives that function, anything else 0 (then each group reads
    /// the context's state).
    #[inline(always)]
    fn depth_fast(&self) -> u32 {
        match (self.depth_test, self.depth_func, self.depth_mask) {
            (true, LESS, true) => LESS,
            (true, LEQUAL, true) => LEQUAL,
            _ => 0,
        }
    }

    /// `smooth_row` of each of `rows` (`AVX2` and `F` as there).
    #[inline(always)]
    fn smooth_rows_on<const AVX2: bool, const F: u32>(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        pl: &[f32; 15],
        rows: &[[i32; 3]],
    ) {
        let sp = super::lanes::SmoothPlanes8::new(&p.z, pl);
        for &[y, x0, x1] in rows {
            self.smooth_row::<AVX2, F>(bufs, p, &sp, y, x0, x1);
        }
    }

    /// A span of a primitive `smooth_planes` accepted (its planes in `sp`): pixels `x0..=x1` of
    /// row `y`, all inside the tile. What `tri_span` computes for it (the row's terms of each
    /// plane, `zrow`, the depth test and the smooth colour, the occlusion count), without the
    /// per-span decisions, in one pass over its groups (`lanes::smooth_depth_span`).
    /// On AVX2 the row's terms come from `sp` (`lanes::SmoothPlanes8`, the same scalar
    /// expressions on eight lanes) and `F` is 0 or the depth test known for all rows
    /// (`lanes::smooth_depth_span_avx2`).
    #[inline(always)]
    fn smooth_row<const AVX2: bool, const F: u32>(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        sp: &super::lanes::SmoothPlanes8,
        y: i32,
        x0: i32,
        x1: i32,
    ) {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let fy = (y - oy) as f32;
        let base = ((y - bufs.y) as usize) * TILE + (x0 - bufs.x) as usize;
        let n = (x1 - x0 + 1) as usize;
        let test = self
            .depth_test
            .then_some((self.depth_func, self.depth_mask));
        let mask = match () {
            // SAFETY: `AVX2` is true only in `smooth_rows_avx2`, which runs where the CPU has
            // AVX2.
            #[cfg(target_arch = "x86_64")]
            () if AVX2 => unsafe {
                let o = sp.row(fy);
                super::lanes::smooth_depth_span_avx2::<F>(
                    bufs.color,
                    bufs.depth,
                    base,
                    n,
                    x0 - ox,
                    &o,
                    &sp.dx,
                    test,
                )
            },
            () => {
                // The row's terms as `SmoothPlanes8::row`'s lanes, one by one.
                let t = |i: usize| sp.base[i] + sp.ystep[i] * fy;
                let d = &sp.dx;
                let color = bufs.color.get_mut(base..).unwrap_or_default();
                let depth = bufs.depth.get_mut(base..).unwrap_or_default();
                let co = [t(1), d[1], t(2), d[2], t(3), d[3], t(4), d[4], t(5), d[5]];
                super::lanes::smooth_depth_span(color, depth, n, x0 - ox, t(0), d[0], test, &co)
            }
        };
        if self.samples {
            bufs.samples += u64::from(mask.count_ones());
        }
    }

    /// What every span of `p` writes when it is one colour or none — a FLAT primitive whose
    /// planes give one colour for all its fragments (`lanes::flat_px`) into one colour buffer
    /// written whole, or a depth-only pass (ColorMask all false) — with no per-fragment
    /// operation beyond the depth test, no polygon stipple and no coverage count: the spans
    /// `tri_span` sends through `depth_mask_span` and then `lanes::flat_rgba` or nothing.
    /// None for any other primitive. Decided once per primitive and tile (`raster::tri`).
    #[inline(always)]
    pub fn const_fill(&self, bufs: &TileBufs, p: &RPrim, planes: &[f32]) -> Option<ConstFill> {
        self.const_fill_of(bufs.color2.is_some(), p, planes)
    }

    /// `const_fill` where the tile has a second colour buffer when `color2`.
    #[inline(always)]
    fn const_fill_of(&self, color2: bool, p: &RPrim, planes: &[f32]) -> Option<ConstFill> {
        let stippled = self.stipple.is_some() && p.flags & F_LINE == 0;
        if self.ops.is_some() || p.flags & (F_AAPOINT | F_AALINE) != 0 || stippled || self.count {
            return None;
        }
        if self.color_mask == [false; 4] {
            return Some(ConstFill::Depth);
        }
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        if self.rl.n != 4
            || nflat != 4
            || p.flags & F_PHONG != 0
            || self.color_mask != [true; 4]
            || color2
        {
            return None;
        }
        let pl = planes.get(3..15)?.try_into().ok()?;
        super::lanes::flat_px(pl, 0, 0.0).map(ConstFill::Flat)
    }

    /// Spans of a primitive `const_fill` accepted (`fill`), `rows` holding each span's window
    /// row and first and last pixel (all inside the tile): what `tri_span` does with each,
    /// on AVX2 the depth test and the store of each group in one pass
    /// (`lanes::depth_color_span_avx2`) with the depth test chosen once per call.
    #[inline(never)]
    pub fn const_rows(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        fill: ConstFill,
        rows: &[[i32; 3]],
    ) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.const_rows_avx2(bufs, p, fill, rows) };
            return;
        }
        let _ = fill;
        self.tri_rows_portable(bufs, p, planes, rows, &mut None);
    }

    /// `const_rows` compiled for AVX2 and POPCNT, the common depth tests chosen once for the
    /// call (`depth_fast`, as `smooth_rows_avx2`).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn const_rows_avx2(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        fill: ConstFill,
        rows: &[[i32; 3]],
    ) {
        // SAFETY: the CPU has AVX2 and POPCNT (this function's contract).
        unsafe {
            match (fill, self.depth_fast()) {
                (ConstFill::Flat(px), LESS) => self.const_rows_on::<LESS, true>(bufs, p, px, rows),
                (ConstFill::Flat(px), LEQUAL) => {
                    self.const_rows_on::<LEQUAL, true>(bufs, p, px, rows)
                }
                (ConstFill::Flat(px), _) => self.const_rows_on::<0, true>(bufs, p, px, rows),
                (ConstFill::Depth, LESS) => {
                    self.const_rows_on::<LESS, false>(bufs, p, [0; 4], rows)
                }
                (ConstFill::Depth, LEQUAL) => {
                    self.const_rows_on::<LEQUAL, false>(bufs, p, [0; 4], rows)
                }
                (ConstFill::Depth, _) => self.const_rows_on::<0, false>(bufs, p, [0; 4], rows),
            }
        }
    }

    /// Each of `rows` as `tri_span` computes it for `const_fill`'s primitives: its `zrow`, the
    /// depth test over the span (`depth_mask_span`: every pixel of it live, the depth row's
    /// length bounding it) and, when `FLAT`, the colour `px` stored into its survivors group
    /// by group as the groups are tested (`lanes::flat_group_avx2`, what `flat_rgba` stores);
    /// the occlusion count. `F` as in `lanes::depth_groups_avx2`.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn const_rows_on<const F: u32, const FLAT: bool>(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        px: [u8; 4],
        rows: &[[i32; 3]],
    ) {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let (func, write) = (self.depth_func, self.depth_mask);
        for &[y, x0, x1] in rows {
            let fy = (y - oy) as f32;
            let zrow = p.z[0] + p.z[2] * fy;
            let base = ((y - bufs.y) as usize) * TILE + (x0 - bufs.x) as usize;
            let n = (x1 - x0 + 1) as usize;
            let mask = if self.depth_test {
                let Some(row) = bufs.depth.get_mut(base..) else {
                    continue;
                };
                let n = n.min(64).min(row.len());
                if n == 0 {
                    continue;
                }
                let live = u64::MAX >> (64 - n);
                let color = bufs.color.get_mut(base..).unwrap_or_default();
                let a = (row, n, zrow, p.z[1], x0 - ox, live);
                // SAFETY: the CPU has AVX2 (this function's contract).
                unsafe {
                    super::lanes::depth_groups_avx2::<F>(a, func, write, |c, m| {
                        if FLAT {
                            super::lanes::flat_group_avx2(color, c, m, px);
                        }
                    })
                }
            } else {
                let n = n.clamp(1, 64);
                if FLAT {
                    if let Some(dst) = bufs.color.get_mut(base..base + n) {
                        dst.fill(px);
                    }
                }
                u64::MAX >> (64 - n)
            };
            if self.samples {
                bufs.samples += u64::from(mask.count_ones());
            }
        }
    }

    /// Spans of a smooth point's or line's quad triangle (`aa.rs`), `rows` holding each span's
    /// window row and first and last pixel (all inside the tile): each fragment's coverage
    /// from its interpolated antialiasing coordinates multiplies its alpha (after texturing
    /// and the colour sum, before the fragment operations), or discards it; never
    /// polygon-stippled. What depends on the primitive alone is decided once for all its rows
    /// in the tile (a span is a group or two: per-span set-up was a third of the work). Eight
    /// fragments at a time: the varyings (`lanes::varyings`), the coverage
    /// (`aa::coverage_lanes`; a group whose lanes are all discarded stops there), the colour
    /// (on lanes without texturing, else `color_lanes`), then `ops_group` or the depth test
    /// and the masked store; each lane computes what one fragment's `color`, alpha times
    /// coverage, then `full` (or `depth` and `write`) computes.
    pub fn aa_rows(&self, bufs: &mut TileBufs, p: &RPrim, planes: &[f32], rows: &[[i32; 3]]) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.aa_rows_avx2(bufs, p, planes, rows) };
            return;
        }
        self.aa_rows_in(bufs, p, planes, rows);
    }

    /// `aa_rows` compiled for AVX2 and POPCNT (as `plain_rows_avx2`: the same bits).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn aa_rows_avx2(
        &self,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) {
        self.aa_rows_in(bufs, p, planes, rows);
    }

    /// The body of `aa_rows`.
    #[inline(always)]
    fn aa_rows_in(&self, bufs: &mut TileBufs, p: &RPrim, planes: &[f32], rows: &[[i32; 3]]) {
        use super::lanes::{depth_lanes, lane_x, lin_lanes, unorm8_lanes};
        use super::oplanes as ol;
        const ZERO: [f32; LANES] = [0.0; LANES];
        let Some(o) = self.rl.aa else {
            return;
        };
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let nv = self.rl.n.min(MAXV);
        // The colour is the interpolated primary (plus the secondary) unless a unit textures
        // or PHONG_WIN lights it.
        let plain = self.tex[0].is_none() && p.flags & F_PHONG == 0;
        let on_lanes = !plain && self.tex_lanes_ok(p);
        let spec = self.rl.spec.filter(|_| self.color_sum);
        let lod = self.tex.iter().flatten().any(|(t, _)| t.needs_lambda());
        let mut lam = [[0.0f32; LANES]; MAX_TEXTURE_UNITS];
        // Varyings past `nv` stay 0, as a fragment's missing ones read.
        let mut v = [[0.0f32; LANES]; MAXV];
        for &[y, x0, x1] in rows {
            let fy = (y - oy) as f32;
            let zrow = p.z[0] + p.z[2] * fy;
            let base = ((y - bufs.y) as usize) * TILE + (x0 - bufs.x) as usize;
            let n = usize::try_from(x1 - x0 + 1).unwrap_or(0).min(TILE);
            let qy = ((y & !1) - oy) as f32;
            let mut quads = lod.then(|| [SpanLambda::new(x0, ox, qy); MAX_TEXTURE_UNITS]);
            let mut c = 0;
            while c < n {
                let live = if n - c >= LANES {
                    0xFF
                } else {
                    (1u8 << (n - c)) - 1
                };
                let fx0 = x0 - ox + c as i32;
                super::lanes::varyings(planes, nflat, fx0, fy, &mut v[..nv]);
                let g = |j: usize| v.get(o + j).unwrap_or(&ZERO);
                let (cov, keep) = super::aa::coverage_lanes(p.flags, [g(0), g(1), g(2), g(3)]);
                let m = live & keep;
                if m == 0 {
                    c += LANES;
                    continue;
                }
                let mut col = if plain {
                    let g = |k: usize| *v[..nv].get(k).unwrap_or(&ZERO);
                    let mut col = [g(0), g(1), g(2), g(3)];
                    if let Some(s) = spec {
                        // `color`'s colour sum: (R, G, B, A) + (R2, G2, B2, 0).
                        let add = [g(s), g(s + 1), g(s + 2), ZERO];
                        for (ch, add) in col.iter_mut().zip(add) {
                            for l in 0..LANES {
                                ch[l] += add[l];
                            }
                        }
                    }
                    col
                } else {
                    if let Some(quads) = &mut quads {
                        for ((lu, t), sq) in lam.iter_mut().zip(&self.tex).zip(quads) {
                            let Some((tx, to)) = *t else { break };
                            if tx.needs_lambda() {
                                *lu = sq.lanes(tx, planes, to, x0 + c as i32);
                            }
                        }
                    }
                    self.color_lanes(p, &v[..nv], m, &lam, on_lanes)
                };
                for l in 0..LANES {
                    col[3][l] *= cov[l];
                }
                let z = lin_lanes(zrow, p.z[1], &lane_x(fx0));
                let i0 = base + c;
                if let Some(ops) = &self.ops {
                    let fogc = self.rl.fog.filter(|&f| f < nv).map_or(ZERO, |f| v[f]);
                    self.ops_group(ops, bufs, p, i0, z, &col, fogc, m);
                    c += LANES;
                    continue;
                }
                let mut m = m;
                if self.depth_test {
                    let dp = bufs.depth.get_mut(i0..).unwrap_or_default();
                    m = ol::depth_test(self.depth_func, self.depth_mask, dp, depth_lanes(z), m);
                }
                if m != 0 {
                    if self.samples {
                        bufs.samples += u64::from(m.count_ones());
                    }
                    let src = col.map(unorm8_lanes);
                    self.store_group(bufs.color.get_mut(i0..).unwrap_or_default(), &src, m);
                    if let Some(c2) = bufs.color2.as_deref_mut() {
                        self.store_group(c2.get_mut(i0..).unwrap_or_default(), &src, m);
                    }
                }
                c += LANES;
            }
        }
    }

    /// The per-fragment operations of a group of eight fragments (`aa_rows`) at tile indices
    /// `i0..` (lanes `m`), with window depths `z` (single precision), colours `col` (before
    /// clamping) and fog coordinates `fogc`: what `full` does to each, on lanes (`oplanes`):
    /// clamp (§3.9), alpha test (§4.1.4), stencil and depth tests (§4.1.5, §4.1.6), the
    /// occlusion count, fog (§3.10: it changes neither alpha nor anything the tests read, so it
    /// runs on the survivors only), blending or logic op (§4.1.8, §4.1.10), masked write.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn ops_group(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        i0: usize,
        z: [f32; LANES],
        col: &[[f32; LANES]; 4],
        fogc: [f32; LANES],
        m: u8,
    ) {
        use super::lanes::{depth_lanes, unorm8_lanes};
        use super::oplanes as ol;
        let mut rgb = [
            ol::clamp01(col[0]),
            ol::clamp01(col[1]),
            ol::clamp01(col[2]),
        ];
        let a = ol::clamp01(col[3]);
        let mut m = m;
        if let Some((func, reference)) = ops.alpha {
            m &= ol::alpha_test(func, reference, a);
        }
        if m == 0 {
            return;
        }
        let d = if self.depth_test {
            depth_lanes(z)
        } else {
            [0; LANES]
        };
        let depth = self
            .depth_test
            .then_some((self.depth_func, self.depth_mask));
        let dp = bufs.depth.get_mut(i0..).unwrap_or_default();
        m = match &ops.stencil {
            Some(sides) => {
                let side = &sides[usize::from(p.flags & F_BACK != 0)];
                let st = bufs.stencil.get_mut(i0..).unwrap_or_default();
                ol::stencil_depth(side, depth, st, dp, d, m)
            }
            None if self.depth_test => ol::depth_test(self.depth_func, self.depth_mask, dp, d, m),
            None => m,
        };
        if m == 0 {
            return;
        }
        if self.samples {
            bufs.samples += u64::from(m.count_ones());
        }
        if !self.count && self.color_mask == [false; 4] {
            return;
        }
        if let Some(f) = &ops.fog {
            ol::fog(f, &mut rgb, fogc, m);
        }
        let src = [
            unorm8_lanes(rgb[0]),
            unorm8_lanes(rgb[1]),
            unorm8_lanes(rgb[2]),
            unorm8_lanes(a),
        ];
        self.write_group(ops, bufs.color.get_mut(i0..).unwrap_or_default(), &src, m);
        if let Some(c2) = bufs.color2.as_deref_mut() {
            self.write_group(ops, c2.get_mut(i0..).unwrap_or_default(), &src, m);
        }
    }

    /// The masked store (§4.2.2) of lanes `m` of `src` over one colour buffer's row from the
    /// group's first pixel, or the coverage count: `store` for each lane's fragment.
    #[inline(always)]
    fn store_group(&self, row: &mut [[u8; 4]], src: &[[u8; LANES]; 4], m: u8) {
        if self.count {
            for (l, dst) in row.iter_mut().take(LANES).enumerate() {
                if m & (1 << l) != 0 {
                    self.store_one(dst, src.map(|ch| ch[l]));
                }
            }
        } else {
            super::oplanes::store(row, src, m, self.color_mask);
        }
    }

    /// The coverage mask of a span after the depth test: `live` (the fragments the span has;
    /// with a polygon stipple it lacks some inside the span) when the test is off, else what
    /// the depth test and write (§4.1.6) of the `n` fragments from tile index `b` leave of it:
    /// z = `zrow + dz * (fx0 + k)` for the k-th, DepthFunc and DepthMask applied eight
    /// fragments at a time (`lanes::depth_span`; `lanes::depth_span_avx2` where `AVX2`, true
    /// only in functions compiled for AVX2 that run where the CPU has it, or where the CPU is
    /// found to have it).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn depth_mask_span<const AVX2: bool>(
        &self,
        bufs: &mut TileBufs,
        b: usize,
        n: usize,
        zrow: f32,
        dz: f32,
        fx0: i32,
        live: u64,
    ) -> u64 {
        if !self.depth_test {
            return live;
        }
        // The row runs on to the tile's end, so that the span's last group is a whole one
        // too (its lanes past the span are not live: neither tested nor written).
        let Some(row) = bufs.depth.get_mut(b..) else {
            return 0;
        };
        let n = n.min(64).min(row.len());
        if n == 0 {
            return 0;
        }
        let live = live & (u64::MAX >> (64 - n));
        #[cfg(target_arch = "x86_64")]
        if AVX2 || super::lanes::has_avx2() {
            let (f, w) = (self.depth_func, self.depth_mask);
            // SAFETY: the CPU has AVX2 (`AVX2`'s promise, else `has_avx2`).
            return unsafe { super::lanes::depth_span_avx2(row, n, zrow, dz, fx0, live, w, f) };
        }
        super::lanes::depth_span(
            row,
            n,
            zrow,
            dz,
            fx0,
            live,
            self.depth_mask,
            self.depth_func,
        )
    }

    /// Texture level of detail of each unit for the 2x2 quad holding window pixel (x, y), from
    /// the quad's lower-left pixel as llvmpipe does (§3.8.8), relative to the primitive's
    /// bounding-box corner (ox, oy); 0 for a unit whose result does not depend on it. (The
    /// scalar reference the lane routes' tests compare with.)
    #[cfg(test)]
    fn quad_lambda(
        &self,
        planes: &[f32],
        x: i32,
        y: i32,
        ox: i32,
        oy: i32,
    ) -> [f32; MAX_TEXTURE_UNITS] {
        let (qx, qy) = ((x & !1) - ox, (y & !1) - oy);
        let mut lambda = [0.0; MAX_TEXTURE_UNITS];
        for (l, t) in lambda.iter_mut().zip(&self.tex) {
            let Some((tx, to)) = *t else { break };
            if tx.needs_lambda() {
                *l = tx.quad_lambda(planes, to, qx as f32, qy as f32);
            }
        }
        lambda
    }

    /// Spans through the full sequence (`ops` enabled), eight fragments at a time
    /// (`oplanes`): varyings, colour, clamp (§3.9), alpha test (§4.1.4), stencil and depth
    /// tests (§4.1.5, §4.1.6), fog (§3.10: it changes neither alpha nor anything the tests
    /// read, so it runs on the survivors only), blending or logic op (§4.1.8, §4.1.10), masked
    /// write; each lane computes what `full` computes for its fragment.
    ///
    /// The route is chosen here, once per primitive and tile, and each route is a function of
    /// its own, so that a span sets up only what its route reads (one function holding every
    /// route paid ≈570 instructions a span hoisting the texture units' and all varyings'
    /// addresses, and a 1.2 KB `memset`, for spans of three groups on average): `tests_rows`
    /// when no colour is needed (ColorMask all false, no coverage count, no alpha test),
    /// `plain_rows` for an untextured colour, `tex_span` (each row) for a textured or
    /// PHONG_WIN one. `rows` holds each span's window row and first and last pixel (all
    /// inside the tile), drawn in order: the untextured routes set up what depends on the
    /// primitive alone once for all its rows in the tile (≈480 instructions a span when each
    /// span was a call of its own).
    pub fn ops_rows(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) {
        // With ColorMask all false (and no coverage count) nothing reaches a colour buffer,
        // so fog, blending and the stores are skipped, and without an alpha test the colour
        // itself (the varyings, texturing) is never computed: only the stencil and depth
        // tests and their writes remain.
        let writes_color = self.count || self.color_mask != [false; 4];
        if !writes_color && ops.alpha.is_none() {
            self.tests_rows(ops, bufs, p, rows);
        } else if self.tex[0].is_none() && p.flags & F_PHONG == 0 {
            self.plain_rows(ops, bufs, p, planes, rows);
        } else {
            // The fused route's state (one 2D unit, `FusedSpan::covers`, no colour sum) on
            // AVX2: each group's colours from the planes in registers (`fused_tex_rows`).
            #[cfg(target_arch = "x86_64")]
            if let (true, Some((tx, to))) = (super::lanes::has_avx2(), self.fused_unit(p, planes)) {
                // SAFETY: the CPU has AVX2 and POPCNT (`has_avx2`).
                if unsafe { self.fused_tex_rows(ops, bufs, p, planes, tx, to, rows) } {
                    return;
                }
            }
            for &[y, x0, x1] in rows {
                if let Some((fy, zrow, base, n, live)) = self.row_at(bufs, p, y, x0, x1) {
                    self.tex_span(ops, bufs, p, planes, fy, zrow, base, x0, n, live);
                }
            }
        }
    }

    /// The span `x0..=x1` of row `y` of `p` (inside the tile): its row offset `fy` from the
    /// bounding box, depth `zrow` at the box's left edge, tile index `base` of its first
    /// pixel, length `n` (at most a tile row) and the fragments `live` after a polygon stipple
    /// (§3.5.6 removes fragments before any test); None when the stipple leaves none.
    #[inline(always)]
    fn row_at(
        &self,
        bufs: &TileBufs,
        p: &RPrim,
        y: i32,
        x0: i32,
        x1: i32,
    ) -> Option<(f32, f32, usize, usize, u64)> {
        let fy = (y - p.bbox[1]) as f32;
        let zrow = p.z[0] + p.z[2] * fy;
        let base = ((y - bufs.y) as usize) * TILE + (x0 - bufs.x) as usize;
        let n = ((x1 - x0 + 1) as usize).min(TILE);
        let all = u64::MAX >> (64 - n.clamp(1, 64));
        let live = match self.stipple {
            Some(rows) if p.flags & F_LINE == 0 => all & stipple_mask(&rows, x0, y),
            _ => all,
        };
        (live != 0).then_some((fy, zrow, base, n, live))
    }

    /// The stencil and depth tests of a group (§4.1.5, §4.1.6) and their writes, for
    /// `ops_rows`'s routes: fragment k of the group, whose first lane is at x offset `fx0`,
    /// has z = `zrow + dz·(fx0 + k)`; returns the survivors of `m`, counted for an occlusion
    /// query. The eight-lane AVX2 kernels (`oplanes::avx2`) where `AVX2`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn tests_group_on<const AVX2: bool>(
        &self,
        side: Option<&super::fragops::StencilSide>,
        bufs: &mut TileBufs,
        zrow: f32,
        dz: f32,
        fx0: i32,
        i0: usize,
        m: u8,
    ) -> u8 {
        self.tests_group_f::<AVX2, 0>(side, bufs, zrow, dz, fx0, i0, m)
    }

    /// `tests_group_on` with `F` other than 0 the depth test known for the whole call (on,
    /// DepthFunc `F`, the depth mask true: `depth_fast`), so that each group's compare is
    /// chosen when the caller is compiled rather than by a jump per group; `F` = 0 reads the
    /// context's depth state.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn tests_group_f<const AVX2: bool, const F: u32>(
        &self,
        side: Option<&super::fragops::StencilSide>,
        bufs: &mut TileBufs,
        zrow: f32,
        dz: f32,
        fx0: i32,
        i0: usize,
        m: u8,
    ) -> u8 {
        use super::lanes::{depth_lanes, lane_x, lin_lanes};
        use super::oplanes as ol;
        let (depth_test, depth_func, depth_mask) = if F != 0 {
            (true, F, true)
        } else {
            (self.depth_test, self.depth_func, self.depth_mask)
        };
        let d = || {
            if depth_test {
                depth_lanes(lin_lanes(zrow, dz, &lane_x(fx0)))
            } else {
                [0; LANES]
            }
        };
        let dp = bufs.depth.get_mut(i0..).unwrap_or_default();
        let m = match side {
            #[cfg(target_arch = "x86_64")]
            Some(side) if AVX2 => {
                let st = bufs.stencil.get_mut(i0..).unwrap_or_default();
                let depth = depth_test.then_some((depth_func, depth_mask));
                // SAFETY: `AVX2` is true only in `plain_rows_avx2`, `tests_rows_avx2` and
                // `fused_tex_rows`, which run where the CPU has AVX2.
                unsafe { ol::avx2::stencil_depth(side, depth, st, dp, zrow, dz, fx0, m) }
            }
            Some(side) => {
                let st = bufs.stencil.get_mut(i0..).unwrap_or_default();
                let depth = depth_test.then_some((depth_func, depth_mask));
                ol::stencil_depth(side, depth, st, dp, d(), m)
            }
            #[cfg(target_arch = "x86_64")]
            None if AVX2 && depth_test => {
                // SAFETY: `AVX2` is true only in `plain_rows_avx2`, `tests_rows_avx2` and
                // `fused_tex_rows`, which run where the CPU has AVX2.
                unsafe { ol::avx2::depth_test(depth_func, depth_mask, dp, zrow, dz, fx0, m) }
            }
            None if depth_test => ol::depth_test(depth_func, depth_mask, dp, d(), m),
            None => m,
        };
        if self.samples {
            bufs.samples += u64::from(m.count_ones());
        }
        m
    }

    /// The fog (§3.10), conversion to unorm8 and colour write (`write_group`) of a group's
    /// survivors `m`, clamped colour `rgb`, `a`, fog coordinates `coord`, at tile index `i0`;
    /// the eight-lane AVX2 kernels (`oplanes::avx2`) where `AVX2`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn finish_group_on<const AVX2: bool>(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        rgb: &mut [[f32; LANES]; 3],
        a: [f32; LANES],
        coord: [f32; LANES],
        i0: usize,
        m: u8,
    ) {
        use super::lanes::unorm8_lanes;
        use super::oplanes as ol;
        // The eight-lane kernels where `AVX2` (true only in `plain_rows_avx2` and
        // `fused_tex_rows`, which run where the CPU has AVX2: the SAFETY of each call), else
        // the SSE2 ones.
        macro_rules! k {
            ($f:ident($($arg:expr),* $(,)?)) => {{
                #[cfg(target_arch = "x86_64")]
                let r = if AVX2 {
                    // SAFETY: see above.
                    unsafe { ol::avx2::$f($($arg),*) }
                } else {
                    ol::$f($($arg),*)
                };
                #[cfg(not(target_arch = "x86_64"))]
                let r = ol::$f($($arg),*);
                r
            }};
        }
        // Fog (§3.10) changes only R, G and B, which nothing before the colour write
        // reads (the alpha test reads alpha): it runs on the survivors alone, so EXP and
        // EXP2 call `expf` only for fragments that are written.
        if let Some(f) = &ops.fog {
            k!(fog(f, rgb, coord, m));
        }
        if !self.count {
            if let ColorWrite::Replace = ops.write {
                // Straight to the pixels: each lane's four bytes assembled in its 32-bit lane
                // (the copy of the channel-major bytes was taken apart byte by byte, ≈130
                // instructions a group).
                k!(store_unorm8(
                    bufs.color.get_mut(i0..).unwrap_or_default(),
                    rgb,
                    &a,
                    m,
                    self.color_mask,
                ));
                if let Some(c2) = bufs.color2.as_deref_mut() {
                    let row = c2.get_mut(i0..).unwrap_or_default();
                    k!(store_unorm8(row, rgb, &a, m, self.color_mask));
                }
                return;
            }
            if let ColorWrite::Blend(b) = &ops.write {
                // SRC_ALPHA, ONE_MINUS_SRC_ALPHA and ONE, ONE stay pixel-major too.
                let row = bufs.color.get_mut(i0..).unwrap_or_default();
                if k!(blend_unorm8(b, row, rgb, &a, m, self.color_mask)) {
                    match bufs.color2.as_deref_mut() {
                        None => return,
                        Some(c2) => {
                            let row = c2.get_mut(i0..).unwrap_or_default();
                            if k!(blend_unorm8(b, row, rgb, &a, m, self.color_mask)) {
                                return;
                            }
                            // (A short second row: it takes the general route alone.)
                            let src = [rgb[0], rgb[1], rgb[2], a].map(unorm8_lanes);
                            self.write_group(ops, row, &src, m);
                            return;
                        }
                    }
                }
            }
        }
        let src = [
            unorm8_lanes(rgb[0]),
            unorm8_lanes(rgb[1]),
            unorm8_lanes(rgb[2]),
            unorm8_lanes(a),
        ];
        // Blending and the logic op read each colour buffer's own contents (§4.1.8,
        // §4.1.10).
        self.write_group(ops, bufs.color.get_mut(i0..).unwrap_or_default(), &src, m);
        if let Some(c2) = bufs.color2.as_deref_mut() {
            self.write_group(ops, c2.get_mut(i0..).unwrap_or_default(), &src, m);
        }
    }

    /// `ops_rows` when no colour is needed (no colour buffer written, no coverage count, no
    /// alpha test): the stencil and depth tests and their writes alone, row by row.
    #[inline(never)]
    fn tests_rows(&self, ops: &Ops, bufs: &mut TileBufs, p: &RPrim, rows: &[[i32; 3]]) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.tests_rows_avx2(ops, bufs, p, rows) };
            return;
        }
        self.tests_rows_in::<false, 0>(ops, bufs, p, rows);
    }

    /// `tests_rows` compiled for AVX2 and POPCNT (as `plain_rows_avx2`: the same bits).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn tests_rows_avx2(&self, ops: &Ops, bufs: &mut TileBufs, p: &RPrim, rows: &[[i32; 3]]) {
        // The common depth tests chosen once for the call (`depth_fast`).
        match self.depth_fast() {
            LESS => self.tests_rows_in::<true, LESS>(ops, bufs, p, rows),
            LEQUAL => self.tests_rows_in::<true, LEQUAL>(ops, bufs, p, rows),
            _ => self.tests_rows_in::<true, 0>(ops, bufs, p, rows),
        }
    }

    /// The body of `tests_rows` (`F` as `tests_group_f`'s).
    #[inline(always)]
    fn tests_rows_in<const AVX2: bool, const F: u32>(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        rows: &[[i32; 3]],
    ) {
        let ox = p.bbox[0];
        let side = ops
            .stencil
            .as_ref()
            .map(|s| &s[usize::from(p.flags & F_BACK != 0)]);
        let dz = p.z[1];
        for &[y, x0, x1] in rows {
            let Some((_, zrow, base, n, live)) = self.row_at(bufs, p, y, x0, x1) else {
                continue;
            };
            let mut c = 0;
            while c < n {
                let m = ((live >> c) & 0xFF) as u8;
                if m != 0 {
                    self.tests_group_f::<AVX2, F>(
                        side,
                        bufs,
                        zrow,
                        dz,
                        x0 - ox + c as i32,
                        base + c,
                        m,
                    );
                }
                c += LANES;
            }
        }
    }

    /// `ops_rows` for an untextured colour (no texturing unit, not PHONG_WIN), row by row: the
    /// colour is the interpolated primary (plus the secondary's RGB with the colour sum,
    /// §3.9), so the primary, the secondary's RGB and the fog coordinate are the only varyings
    /// read and the only ones interpolated (`lanes::RowVaryings`, the bits `lanes::varyings`
    /// gives them; their planes looked up once per row), into eight rows.
    #[inline(never)]
    fn plain_rows(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.plain_rows_avx2(ops, bufs, p, planes, rows) };
            return;
        }
        self.plain_rows_in::<false, 0>(ops, bufs, p, planes, rows);
    }

    /// `plain_rows` compiled for AVX2 and POPCNT: the same operations (the lane code's SSE2
    /// intrinsics VEX-encoded, no FMA), so the same bits.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    unsafe fn plain_rows_avx2(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) {
        // The common depth tests chosen once for the call (`depth_fast`).
        match self.depth_fast() {
            LESS => self.plain_rows_in::<true, LESS>(ops, bufs, p, planes, rows),
            LEQUAL => self.plain_rows_in::<true, LEQUAL>(ops, bufs, p, planes, rows),
            _ => self.plain_rows_in::<true, 0>(ops, bufs, p, planes, rows),
        }
    }

    /// The body of `plain_rows` (`F` as `tests_group_f`'s).
    #[inline(always)]
    fn plain_rows_in<const AVX2: bool, const F: u32>(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        rows: &[[i32; 3]],
    ) {
        use super::lanes::RowVaryings;
        use super::oplanes as ol;
        let ox = p.bbox[0];
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let nv = self.rl.n.min(MAXV);
        let spec = self.rl.spec.filter(|&s| self.color_sum && s + 3 <= nv);
        // The varyings read: R, G, B, A, then the secondary R, G, B, then the fog coordinate.
        let mut sel = [0, 1, 2, 3, 0, 0, 0, 0];
        let mut k = 4;
        if let Some(s) = spec {
            sel[4..7].copy_from_slice(&[s, s + 1, s + 2]);
            k = 7;
        }
        let fog_row = match (&ops.fog, self.rl.fog.filter(|&o| o < nv)) {
            (Some(_), Some(o)) => {
                sel[k] = o;
                k += 1;
                Some(k - 1)
            }
            _ => None,
        };
        let writes_color = self.count || self.color_mask != [false; 4];
        let side = ops
            .stencil
            .as_ref()
            .map(|s| &s[usize::from(p.flags & F_BACK != 0)]);
        let dz = p.z[1];
        // Without an alpha test no test reads the colour, and computing it has no effect of
        // its own: the stencil and depth tests run first, and a group none of whose
        // fragments survives them interpolates nothing (`full`'s order of effects is kept:
        // the tests' writes, then the colour write of the survivors).
        let tests_first = ops.alpha.is_none();
        let mut v = [[0.0f32; LANES]; 8];
        // On AVX2 the chosen planes are broadcast once per call (`RowPlanes8`), a row only its
        // y terms; the SSE2 route builds its `RowVaryings` a row.
        // (Held by value, not in an Option: a reference kept beside the group loop's values
        // cost ≈35 instructions a group in blending.)
        #[cfg(target_arch = "x86_64")]
        let planes8 = if AVX2 {
            // SAFETY: `AVX2` is true only in `plain_rows_avx2`, which runs where the CPU has
            // AVX2.
            unsafe { super::lanes::RowPlanes8::new(planes, nflat, nv, &sel, k) }
        } else {
            super::lanes::RowPlanes8::zeroed()
        };
        for &[y, x0, x1] in rows {
            let Some((fy, zrow, base, n, live)) = self.row_at(bufs, p, y, x0, x1) else {
                continue;
            };
            #[cfg(target_arch = "x86_64")]
            let row8 = if AVX2 {
                // SAFETY: as above.
                unsafe { planes8.row(fy) }
            } else {
                super::lanes::RowY8::zeroed()
            };
            let row = (!AVX2).then(|| RowVaryings::new(planes, nflat, nv, fy, &sel, k));
            let mut c = 0;
            while c < n {
                let mut m = ((live >> c) & 0xFF) as u8;
                let i0 = base + c;
                let fx0 = x0 - ox + c as i32;
                c += LANES;
                if m == 0 {
                    continue;
                }
                if tests_first {
                    m = self.tests_group_f::<AVX2, F>(side, bufs, zrow, dz, fx0, i0, m);
                    if m == 0 || !writes_color {
                        continue;
                    }
                }
                // Varyings (§3.5.1 eq. 3.9), as `full`'s caller computes them.
                #[cfg(target_arch = "x86_64")]
                if AVX2 {
                    // SAFETY: `AVX2` is true only in `plain_rows_avx2`, which runs where the
                    // CPU has AVX2.
                    unsafe { planes8.eval(&row8, fx0, &mut v) };
                } else if let Some(row) = &row {
                    row.eval(fx0, &mut v);
                }
                #[cfg(not(target_arch = "x86_64"))]
                if let Some(row) = &row {
                    row.eval(fx0, &mut v);
                }
                let [r, g, b, a] = [v[0], v[1], v[2], v[3]];
                let mut rgb = [r, g, b];
                if spec.is_some() {
                    for (ch, add) in rgb.iter_mut().zip(&v[4..7]) {
                        for l in 0..LANES {
                            ch[l] += add[l];
                        }
                    }
                    // (Alpha gains 0.0, which leaves every value's bits as they are but −0,
                    // whose clamp below gives +0 either way.)
                }
                let clamp = |c| {
                    #[cfg(target_arch = "x86_64")]
                    if AVX2 {
                        // SAFETY: as above.
                        return unsafe { ol::avx2::clamp01(c) };
                    }
                    ol::clamp01(c)
                };
                let mut rgb = [clamp(rgb[0]), clamp(rgb[1]), clamp(rgb[2])];
                let a = clamp(a);
                if let Some((func, reference)) = ops.alpha {
                    m &= ol::alpha_test(func, reference, a);
                    if m == 0 {
                        continue;
                    }
                }
                if !tests_first {
                    m = self.tests_group_f::<AVX2, F>(side, bufs, zrow, dz, fx0, i0, m);
                    if m == 0 || !writes_color {
                        continue;
                    }
                }
                let coord = fog_row.map_or([0.0; LANES], |i| v[i]);
                self.finish_group_on::<AVX2>(ops, bufs, &mut rgb, a, coord, i0, m);
            }
        }
    }

    /// `ops_rows` for a textured or PHONG_WIN colour (`color_lanes`; a PHONG_WIN one from
    /// `color`, one fragment at a time), lanes `live` of the `n` fragments from tile index
    /// `base`.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn tex_span(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        fy: f32,
        zrow: f32,
        base: usize,
        x0: i32,
        n: usize,
        live: u64,
    ) {
        #[cfg(target_arch = "x86_64")]
        if super::lanes::has_avx2() {
            // SAFETY: the CPU has AVX2 and POPCNT.
            unsafe { self.tex_span_avx2(ops, bufs, p, planes, fy, zrow, base, x0, n, live) };
            return;
        }
        self.tex_span_in::<false>(ops, bufs, p, planes, fy, zrow, base, x0, n, live);
    }

    /// The one texture unit of `p`'s fragments when `tex_span` would take it on lanes in the
    /// fused route's state (`FusedSpan::covers`, no PHONG_WIN, no colour sum), its
    /// coordinates' varyings and `planes` present.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn fused_unit(&self, p: &RPrim, planes: &[f32]) -> Option<(&Sampler, usize)> {
        let [Some((tx, to)), None, ..] = self.tex else {
            return None;
        };
        let nv = self.rl.n.min(MAXV);
        (p.flags & F_PHONG == 0
            && tx.lanes_ok()
            && super::texture::FusedSpan::covers(tx)
            && !(self.color_sum && self.rl.spec.is_some())
            && to.checked_add(4).is_some_and(|e| e <= nv)
            && planes.len() >= 3 + 3 * nv)
            .then_some((tx, to))
    }

    /// `ops_rows`'s textured rows (`tex_span` each) for a primitive in the fused route's state
    /// ([`FusedSpan`], sampler `tx` with coordinates at varying `to`): each group's clamped
    /// colours from [`FusedSpan::channel_groups`] (a row's at once; the bits of `oplanes::clamp01` of
    /// `color_lanes`), then the alpha test, the stencil and depth tests and `finish_group_on` as
    /// `tex_span_in`, on the eight-lane AVX2 kernels. The route is set up once for the rows
    /// (its levels looked up once). False, with nothing done, when the sampler's state is not
    /// the route's. Out of line, so that `tex_span`'s code stays as it was.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    ///
    /// [`FusedSpan`]: super::texture::FusedSpan
    /// [`FusedSpan::channel_groups`]: super::texture::FusedSpan::channel_groups
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    unsafe fn fused_tex_rows(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        tx: &Sampler,
        to: usize,
        rows: &[[i32; 3]],
    ) -> bool {
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let nv = self.rl.n.min(MAXV);
        let Some(mut fs) = super::texture::FusedSpan::new(tx, to, planes, nflat, 0.0, ox, 0.0)
        else {
            return false;
        };
        let fog_at = self.rl.fog.filter(|&o| o < nv);
        let side = ops
            .stencil
            .as_ref()
            .map(|s| &s[usize::from(p.flags & F_BACK != 0)]);
        let writes_color = self.count || self.color_mask != [false; 4];
        let dz = p.z[1];
        // A row's groups' colours ([`FusedSpan::channel_groups`]: the route's loop a row).
        let mut ch = [[[0.0f32; LANES]; 4]; TILE / LANES];
        for &[y, x0, x1] in rows {
            let Some((fy, zrow, base, n, live)) = self.row_at(bufs, p, y, x0, x1) else {
                continue;
            };
            // `tex_span_in`'s row: y = oy + fy, its quad row (y & !1) - oy.
            let y = oy + fy as i32;
            fs.row(fy, ((y & !1) - oy) as f32);
            // SAFETY: the CPU has AVX2 and POPCNT (the caller's promise).
            unsafe { fs.channel_groups(x0, n, live, &mut ch) };
            let mut c = 0;
            while c < n {
                let m = ((live >> c) & 0xFF) as u8;
                let i0 = base + c;
                let fx0 = x0 - ox + c as i32;
                let [r, g, b, al] = ch[(c / LANES) % ch.len()];
                c += LANES;
                if m == 0 {
                    continue;
                }
                let grp = TexGroup {
                    side,
                    zrow,
                    dz,
                    fx0,
                    i0,
                    m,
                    writes_color,
                };
                // The fog coordinate alone of the varyings (each is computed on its own).
                let coord = || match fog_at {
                    Some(o) => {
                        let mut v = [[0.0f32; LANES]; MAXV];
                        let vs = v.get_mut(..=o).unwrap_or_default();
                        super::lanes::varyings(planes, nflat, fx0, fy, vs);
                        vs.last().copied().unwrap_or([0.0; LANES])
                    }
                    None => [0.0; LANES],
                };
                self.tex_group_rest::<true>(ops, bufs, &grp, [r, g, b], al, coord);
            }
        }
        true
    }

    /// `tex_span` compiled for AVX2 and POPCNT (as `plain_rows_avx2`: the same bits).
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[allow(clippy::too_many_arguments)]
    unsafe fn tex_span_avx2(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        fy: f32,
        zrow: f32,
        base: usize,
        x0: i32,
        n: usize,
        live: u64,
    ) {
        self.tex_span_in::<true>(ops, bufs, p, planes, fy, zrow, base, x0, n, live);
    }

    /// The body of `tex_span` (`AVX2` as `tri_span_in`'s: true only in `tex_span_avx2`).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn tex_span_in<const AVX2: bool>(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        fy: f32,
        zrow: f32,
        base: usize,
        x0: i32,
        n: usize,
        live: u64,
    ) {
        use super::oplanes as ol;
        let ox = p.bbox[0];
        let nflat = if p.flags & F_FLAT != 0 {
            self.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let nv = self.rl.n.min(MAXV);
        let y = p.bbox[1] + fy as i32;
        let fog_at = self.rl.fog.filter(|&o| o < nv);
        let side = ops
            .stencil
            .as_ref()
            .map(|s| &s[usize::from(p.flags & F_BACK != 0)]);
        let on_lanes = self.tex_lanes_ok(p);
        let lod = self.tex.iter().flatten().any(|(t, _)| t.needs_lambda());
        let qy = ((y & !1) - p.bbox[1]) as f32;
        let writes_color = self.count || self.color_mask != [false; 4];
        let dz = p.z[1];
        let mut lam = [[0.0f32; LANES]; MAX_TEXTURE_UNITS];
        let mut quads = [SpanLambda::new(x0, ox, qy); MAX_TEXTURE_UNITS];
        let mut v = [[0.0f32; LANES]; MAXV];
        let mut c = 0;
        while c < n {
            let m = ((live >> c) & 0xFF) as u8;
            let i0 = base + c;
            let fx0 = x0 - ox + c as i32;
            let gx = x0 + c as i32;
            c += LANES;
            if m == 0 {
                continue;
            }
            // Varyings (§3.5.1 eq. 3.9), as `full`'s caller computes them.
            // (`lanes::varyings` computes `full`'s caller's expressions bit for bit.)
            varyings_on::<AVX2>(planes, nflat, fx0, fy, &mut v[..nv]);
            // λ per 2x2 quad on lanes (as `tri_span`), then the colours.
            if lod {
                for ((lu, t), sq) in lam.iter_mut().zip(&self.tex).zip(&mut quads) {
                    let Some((tx, to)) = *t else { break };
                    if tx.needs_lambda() {
                        *lu = sq.lanes(tx, planes, to, gx);
                    }
                }
            }
            let col = self.color_lanes(p, &v[..nv], m, &lam, on_lanes);
            let rgb = [
                ol::clamp01(col[0]),
                ol::clamp01(col[1]),
                ol::clamp01(col[2]),
            ];
            let a = ol::clamp01(col[3]);
            let grp = TexGroup {
                side,
                zrow,
                dz,
                fx0,
                i0,
                m,
                writes_color,
            };
            let coord = || fog_at.map_or([0.0; LANES], |o| v[o]);
            self.tex_group_rest::<false>(ops, bufs, &grp, rgb, a, coord);
        }
    }

    /// A textured group after its clamped colours `rgb`, `a` (`tex_span_in`,
    /// `fused_tex_rows`): the alpha test (§4.1.4), the stencil and depth tests
    /// (`tests_group_on`), then fog and the colour write (`finish_group_on`) with the fog
    /// coordinates `coord` gives, asked only for a group that reaches the write.
    #[inline(always)]
    fn tex_group_rest<const AVX2: bool>(
        &self,
        ops: &Ops,
        bufs: &mut TileBufs,
        g: &TexGroup,
        mut rgb: [[f32; LANES]; 3],
        a: [f32; LANES],
        coord: impl FnOnce() -> [f32; LANES],
    ) {
        use super::oplanes as ol;
        let mut m = g.m;
        if let Some((func, reference)) = ops.alpha {
            m &= ol::alpha_test(func, reference, a);
            if m == 0 {
                return;
            }
        }
        m = self.tests_group_on::<AVX2>(g.side, bufs, g.zrow, g.dz, g.fx0, g.i0, m);
        if m == 0 || !g.writes_color {
            return;
        }
        self.finish_group_on::<AVX2>(ops, bufs, &mut rgb, a, coord(), g.i0, m);
    }

    /// The colour write of a group (`ops_rows`) to one colour buffer's row from the group's
    /// first pixel: blending or the logic op with the row's own contents (§4.1.8, §4.1.10),
    /// then the masked store of lanes `m` (§4.2.2), or the coverage count.
    #[inline(always)]
    fn write_group(&self, ops: &Ops, row: &mut [[u8; 4]], src: &[[u8; LANES]; 4], m: u8) {
        use super::oplanes as ol;
        let out = match ops.write {
            ColorWrite::Replace => *src,
            ColorWrite::Blend(b) => ol::blend(&b, src, &ol::load(row)),
            ColorWrite::Logic(op) => ol::logic(op, src, &ol::load(row)),
        };
        if self.count {
            for (l, dst) in row.iter_mut().take(LANES).enumerate() {
                if m & (1 << l) != 0 {
                    self.store_one(dst, out.map(|ch| ch[l]));
                }
            }
        } else {
            ol::store(row, &out, m, self.color_mask);
        }
    }
}

#[cfg(test)]
mod tests {
    //! `ops_rows` (eight fragments at a time) against the scalar sequence it replaced, each
    //! fragment through `full`, on random states, spans and buffers: byte for byte.

    use super::*;
    use crate::cpu::fragops::{BlendEval, FogEval, StencilSide};
    use crate::cpu::framebuffer::DEPTH_MAX;
    use crate::cpu::setup::{PrimKind, RLayout};

    /// The scalar span: every fragment in order through `full` (the code before `oplanes`).
    #[allow(clippy::too_many_arguments)]
    fn scalar_span(
        f: &FragCtx,
        ops: &Ops,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        fy: f32,
        zrow: f32,
        base: usize,
        x0: i32,
        n: usize,
    ) {
        let ox = p.bbox[0];
        let nflat = if p.flags & F_FLAT != 0 {
            f.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
        let mut v = [0.0f32; super::super::setup::MAXV];
        let nv = f.rl.n.min(v.len());
        let (mut quad_x, mut lambda) = (i32::MIN, [0.0f32; MAX_TEXTURE_UNITS]);
        let y = p.bbox[1] + fy as i32;
        let live = match f.stipple {
            Some(rows) if p.flags & F_LINE == 0 => stipple_mask(&rows, x0, y),
            _ => u64::MAX,
        };
        for k in 0..n.min(TILE) {
            if live & (1 << k) == 0 {
                continue;
            }
            let fx = (x0 - ox + k as i32) as f32;
            let z = zrow + p.z[1] * fx;
            let inv = 1.0 / (pl(0) + pl(1) * fx + pl(2) * fy);
            for (j, vj) in v.iter_mut().enumerate().take(nv) {
                let o = 3 + 3 * j;
                let val = pl(o) + pl(o + 1) * fx + pl(o + 2) * fy;
                *vj = if j < nflat { val } else { val * inv };
            }
            let qx = (x0 + k as i32) & !1;
            if qx != quad_x {
                quad_x = qx;
                lambda = f.quad_lambda(planes, qx, y, ox, p.bbox[1]);
            }
            let c = f.color(p, &v[..nv], lambda);
            let fogc = f.fog_coord(&v[..nv]);
            f.full(ops, bufs, p, base + k, f64::from(z), c, fogc);
        }
    }

    use crate::cpu::testgen::{Gen, COMPARE_FUNCS as FUNCS};

    /// The coverage of one smooth point or line fragment as the scalar per-fragment code
    /// computed it before `aa::coverage_lanes` (`None`: discarded).
    fn scalar_coverage(flags: u8, a: [f32; 4]) -> Option<f32> {
        let sat = |v: f32| v.clamp(0.0, 1.0);
        if flags & F_AAPOINT != 0 {
            let d = a[0] * a[0] + a[1] * a[1];
            let (k, one) = (a[2], a[3]);
            if one < d {
                return None;
            }
            let cov = (1.0 / (one - k)) * (one - d);
            Some(if k >= d { cov } else { one })
        } else {
            let len = a[3] * 2.0 - 1.0;
            let across = sat(a[1] - a[0].abs());
            let along = sat(a[3] - a[2].abs());
            Some(across * along.min(len))
        }
    }

    /// The scalar smooth point or line span (the code before `aa_rows`): each
    /// fragment's varyings, coverage, `color` with its quad's λ, alpha times the coverage,
    /// then `full`, or the depth test and `write`.
    fn scalar_aa_span(
        f: &FragCtx,
        bufs: &mut TileBufs,
        p: &RPrim,
        planes: &[f32],
        y: i32,
        x0: i32,
        x1: i32,
    ) {
        let Some(o) = f.rl.aa else {
            return;
        };
        let (ox, oy) = (p.bbox[0], p.bbox[1]);
        let fy = (y - oy) as f32;
        let zrow = p.z[0] + p.z[2] * fy;
        let row = ((y - bufs.y) as usize) * TILE;
        let nflat = if p.flags & F_FLAT != 0 {
            f.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
        let mut v = [0.0f32; MAXV];
        let nv = f.rl.n.min(v.len());
        let (mut quad_x, mut lambda) = (i32::MIN, [0.0f32; MAX_TEXTURE_UNITS]);
        for x in x0..=x1 {
            let fx = (x - ox) as f32;
            let inv = 1.0 / (pl(0) + pl(1) * fx + pl(2) * fy);
            for (j, vj) in v.iter_mut().enumerate().take(nv) {
                let k = 3 + 3 * j;
                let val = pl(k) + pl(k + 1) * fx + pl(k + 2) * fy;
                *vj = if j < nflat { val } else { val * inv };
            }
            let g = |j: usize| v.get(o + j).copied().unwrap_or(0.0);
            let Some(cov) = scalar_coverage(p.flags, [g(0), g(1), g(2), g(3)]) else {
                continue;
            };
            let qx = x & !1;
            if qx != quad_x {
                quad_x = qx;
                lambda = f.quad_lambda(planes, qx, y, ox, oy);
            }
            let mut c = f.color(p, &v[..nv], lambda);
            c.w *= cov;
            let z = f64::from(zrow + p.z[1] * fx);
            let i = row + (x - bufs.x) as usize;
            if let Some(ops) = &f.ops {
                let fogc = f.fog_coord(&v[..nv]);
                f.full(ops, bufs, p, i, z, c, fogc);
            } else if f.depth(bufs, i, z) {
                if f.samples {
                    bufs.samples += 1;
                }
                f.write(bufs, i, c);
            }
        }
    }

    /// Smooth point and line spans on lanes (`aa_rows`: coverage, colour and the per-fragment
    /// operations eight fragments at a time) against the scalar sequence, byte for byte:
    /// random quads' antialiasing planes (fragments kept and discarded, coverage inside and
    /// outside [0, 1], NaN now and then), with or without per-fragment operations (alpha
    /// test, stencil, fog, blending, logic op), the colour sum, a texture unit, masks, a
    /// second colour buffer and the coverage count.
    /// A tile's buffers for the span tests: colour, second colour, depth, stencil.
    type Tile = (Vec<[u8; 4]>, Vec<[u8; 4]>, Vec<u32>, Vec<u8>);

    /// One span of a primitive in a tile: row `y`, columns `xs` (inclusive), the tile at
    /// `origin`.
    struct Span<'a> {
        p: &'a RPrim,
        planes: &'a [f32],
        origin: (i32, i32),
        y: i32,
        xs: (i32, i32),
        /// Further rows (window row, first and last pixel) drawn after the first: on lanes
        /// all in one `ops_rows` call, in the scalar sequence one span after the other.
        more: &'a [[i32; 3]],
    }

    impl Span<'_> {
        /// The span drawn into copies of `tile` (its second colour buffer used when `two`)
        /// through `tri_span` (`lanes`) or through `scalar_span` with `ops`: the buffers after,
        /// and the samples counted.
        fn draw(&self, f: &FragCtx, ops: &Ops, tile: &Tile, two: bool, lanes: bool) -> (Tile, u64) {
            let (mut c, mut c2, mut d, mut s) = tile.clone();
            let ((tx, ty), (x0, x1), y, p) = (self.origin, self.xs, self.y, self.p);
            let mut bufs = TileBufs {
                color: &mut c,
                color2: two.then_some(&mut c2[..]),
                depth: &mut d,
                stencil: &mut s,
                x: tx,
                y: ty,
                samples: 0,
            };
            if lanes && self.more.is_empty() {
                f.tri_span(&mut bufs, p, self.planes, y, x0, x1);
            } else if lanes {
                let mut rows = vec![[y, x0, x1]];
                rows.extend_from_slice(self.more);
                f.ops_rows(ops, &mut bufs, p, self.planes, &rows);
            } else {
                for &[y, x0, x1] in std::iter::once(&[y, x0, x1]).chain(self.more) {
                    let fy = (y - p.bbox[1]) as f32;
                    let zrow = p.z[0] + p.z[2] * fy;
                    let base = ((y - ty) as usize) * TILE + (x0 - tx) as usize;
                    let n = (x1 - x0 + 1) as usize;
                    scalar_span(f, ops, &mut bufs, p, self.planes, fy, zrow, base, x0, n);
                }
            }
            let samples = bufs.samples;
            ((c, c2, d, s), samples)
        }

        /// The span on lanes and through the scalar sequence (see `draw`).
        /// On x86-64 with AVX2 the lanes run twice, through the AVX2 routes and with them
        /// turned off (`lanes::NO_AVX2`, the SSE2 routes), which must agree byte for byte.
        fn both(&self, f: &FragCtx, ops: &Ops, tile: &Tile, two: bool) -> [(Tile, u64); 2] {
            #[cfg(target_arch = "x86_64")]
            if crate::cpu::lanes::has_avx2() {
                let avx2 = self.draw(f, ops, tile, two, true);
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(true));
                let sse2 = self.draw(f, ops, tile, two, true);
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
                assert!(avx2 == sse2, "the AVX2 and SSE2 routes differ");
            }
            [true, false].map(|lanes| self.draw(f, ops, tile, two, lanes))
        }
    }

    #[test]
    fn aa_span_on_lanes_is_the_scalar_sequence_byte_for_byte() {
        use crate::cpu::fragops::{BlendEval, FogEval, StencilSide};
        use crate::cpu::texture::Sampler;
        use crate::state::State;
        use crate::texture::{Level, TexObject};
        use std::sync::Arc;
        let mut g = Gen(16);
        let factors = [
            gl::ZERO,
            gl::ONE,
            gl::SRC_ALPHA,
            gl::ONE_MINUS_SRC_ALPHA,
            gl::DST_ALPHA,
            gl::SRC_ALPHA_SATURATE,
        ];
        let sops = [gl::KEEP, gl::ZERO, gl::REPLACE, gl::INCR, gl::INVERT];
        let mut written = 0;
        for round in 0..3000 {
            let textured = round % 4 == 3;
            let mut state = State::new(4, 4);
            if textured {
                let mut obj = TexObject {
                    min_filter: g.pick(&[gl::NEAREST, gl::LINEAR_MIPMAP_LINEAR]),
                    mag_filter: g.pick(&[gl::NEAREST, gl::LINEAR]),
                    ..TexObject::default()
                };
                for (k, w) in [4, 2, 1].into_iter().enumerate() {
                    let texels = (0..w * w)
                        .map(|_| std::array::from_fn(|_| (g.next() % 256) as f32 / 255.0))
                        .collect::<Vec<_>>();
                    obj.levels[k] = Some(Level {
                        depth: 1,
                        width: w,
                        height: w,
                        internal_format: gl::RGBA as i32,
                        base: gl::RGBA,
                        texels: texels.into(),
                    });
                }
                state.textures.defaults[1] = Arc::new(obj);
                state.enables.texture_2d[0] = true;
                state.textures.units[0].env_mode = g.pick(&[gl::MODULATE, gl::DECAL, gl::ADD]);
            }
            let mut samplers: [Option<Sampler>; MAX_TEXTURE_UNITS] = Default::default();
            if textured {
                samplers[0] = Sampler::new(&state, 0);
                assert!(samplers[0].is_some(), "unit 0 complete");
            }
            let spec = g.next() % 2 == 0;
            let fog_on = g.next() % 3 == 0;
            let mut rl = RLayout {
                n: 4,
                ..Default::default()
            };
            if spec {
                rl.spec = Some(rl.n);
                rl.n += 4;
            }
            if fog_on || g.next() % 3 == 0 {
                rl.fog = Some(rl.n);
                rl.n += 1;
            }
            if textured {
                rl.tex[0] = Some(rl.n);
                rl.n += 4;
            }
            rl.aa = Some(rl.n);
            rl.n += 4;
            let tex = tex_units(&samplers, &rl);
            let mut side = || StencilSide {
                func: g.pick(&FUNCS),
                reference: g.next() as u8 % 4,
                mask: 0xFF,
                ops: [g.pick(&sops), g.pick(&sops), g.pick(&sops)],
                write: 0xFF,
            };
            let sides = [side(), side()];
            let ops = (g.next() % 5 != 0).then(|| Ops {
                fog: fog_on.then(|| FogEval {
                    mode: g.pick(&[gl::LINEAR, gl::EXP]),
                    density: (g.next() % 100) as f32 * 0.05,
                    start: 0.1,
                    end: 0.9,
                    color: Vec3::new(g.mostly_unit(), 0.5, g.mostly_unit()),
                }),
                alpha: (g.next() % 3 == 0).then(|| (g.pick(&FUNCS), g.next() as u8)),
                stencil: (g.next() % 3 == 0).then_some(sides),
                write: match g.next() % 4 {
                    0 => ColorWrite::Replace,
                    1 => ColorWrite::Logic(gl::CLEAR + (g.next() % 16) as u32),
                    _ => ColorWrite::Blend(BlendEval {
                        src_rgb: g.pick(&factors),
                        dst_rgb: g.pick(&factors),
                        src_alpha: g.pick(&factors),
                        dst_alpha: g.pick(&factors),
                        eq_rgb: gl::FUNC_ADD,
                        eq_alpha: gl::FUNC_ADD,
                        constant: [0; 4],
                    }),
                },
            });
            let f = FragCtx {
                depth_test: g.next() % 3 == 0,
                depth_func: g.pick(&FUNCS),
                depth_mask: g.next() % 2 == 0,
                color_mask: match g.next() % 6 {
                    0 => std::array::from_fn(|_| g.next() % 2 == 0),
                    1 => [false; 4],
                    _ => [true; 4],
                },
                color_sum: spec && g.next() % 4 != 0,
                rl,
                lighting: None,
                mats: &[],
                count: g.next() % 10 == 0,
                samples: g.next() % 2 == 0,
                // A polygon stipple never applies to points and lines.
                stipple: (g.next() % 4 == 0).then(|| std::array::from_fn(|_| g.next() as u32)),
                ops,
                tex,
                crossbar: false,
            };
            let (tx, ty) = (64 * (g.next() % 4) as i32, 64 * (g.next() % 4) as i32);
            let point = g.next() % 2 == 0;
            let flags = if point { F_AAPOINT } else { F_AALINE }
                | [0, F_FLAT, F_BACK][(g.next() % 3) as usize];
            let bbox = [
                tx + (g.next() % 40) as i32 - 20,
                ty + (g.next() % 40) as i32 - 20,
            ];
            let p = RPrim {
                kind: PrimKind::Tri,
                flags,
                bbox: [bbox[0], bbox[1], bbox[0] + 100, bbox[1] + 100],
                mat: 0,
                voff: 0,
                xy: [0; 6],
                owns: 0,
                cover: 0,
                z: [g.mostly_unit(), (g.next() % 100) as f32 * 1e-3 - 0.05, 1e-3],
            };
            // 1/w: constant (an orthographic quad, as the scenes draw them) or varying.
            let mut planes = if g.next() % 2 == 0 {
                vec![1.0, 0.0, 0.0]
            } else {
                vec![0.5 + (g.next() % 100) as f32 * 0.01, 1e-3, -2e-3]
            };
            let aa = rl.aa.unwrap_or(0);
            for j in 0..rl.n {
                if j < aa {
                    let d = if j < 4 { 1e-2 } else { 0.1 };
                    planes.extend([g.mostly_unit(), g.mostly_unit() * d, g.mostly_unit() * d]);
                    continue;
                }
                // The antialiasing coordinates: across the span from about -1.5 to 1.5
                // (point s, t; line x, z), k in [0, 1), a point's 1 or a line's w and h.
                let slope = ((g.next() % 200) as f32 - 100.0) * 1e-3;
                let c0 = match (point, j - aa) {
                    (_, 0) | (true, 1) | (false, 2) => g.mostly_unit() * 3.0 - 1.5,
                    (true, 2) => g.mostly_unit(),
                    (true, _) => 1.0,
                    (false, _) => 0.5 + (g.next() % 40) as f32 * 0.1,
                };
                let s = if matches!(j - aa, 0 | 1) || !point && j - aa == 2 {
                    [slope, slope * 0.5]
                } else {
                    [0.0, 0.0]
                };
                planes.extend([c0, s[0], s[1]]);
            }
            let color: Vec<[u8; 4]> = (0..TILE * TILE)
                .map(|_| (g.next() as u32).to_le_bytes())
                .collect();
            let two = g.next() % 4 == 0;
            let color2: Vec<[u8; 4]> = color.iter().map(|c| c.map(|x| x ^ 0x5A)).collect();
            let depth: Vec<u32> = (0..TILE * TILE)
                .map(|_| (g.next() % 5) as u32 * (DEPTH_MAX / 4))
                .collect();
            let stencil: Vec<u8> = (0..TILE * TILE).map(|_| g.next() as u8 % 4).collect();
            // One to four rows of the tile (the rows of one primitive share `aa_rows`' set-up).
            let rows: Vec<[i32; 3]> = (0..1 + g.next() % 4)
                .map(|_| {
                    let y = ty + (g.next() % TILE as u64) as i32;
                    let x0 = tx + (g.next() % TILE as u64) as i32;
                    let x1 = (x0 + (g.next() % 64) as i32).min(tx + TILE as i32 - 1);
                    [y, x0, x1]
                })
                .collect();
            let run = |lanes: bool| {
                let (mut c, mut c2, mut d, mut s) = (
                    color.clone(),
                    color2.clone(),
                    depth.clone(),
                    stencil.clone(),
                );
                let mut bufs = TileBufs {
                    color: &mut c,
                    color2: two.then_some(&mut c2[..]),
                    depth: &mut d,
                    stencil: &mut s,
                    x: tx,
                    y: ty,
                    samples: 0,
                };
                if lanes {
                    f.aa_rows(&mut bufs, &p, &planes, &rows);
                } else {
                    for &[y, x0, x1] in &rows {
                        scalar_aa_span(&f, &mut bufs, &p, &planes, y, x0, x1);
                    }
                }
                let samples = bufs.samples;
                (c, c2, d, s, samples)
            };
            let (got, want) = (run(true), run(false));
            assert!(got == want, "round {round}: {f:?} {p:?} rows {rows:?}");
            if got.0 != color {
                written += 1;
            }
        }
        // The cases are not vacuous: many rounds write colours, many are left untouched
        // (fragments discarded by the coverage or failing the tests, or masked).
        assert!(
            (600..2400).contains(&written),
            "{written} of 3000 rounds wrote"
        );
    }

    /// Textured spans without per-fragment operations (`tri_span`'s general path: the
    /// varyings, λ and colours on lanes, the pixel-major store when one colour buffer is
    /// written whole) against the scalar sequence: each fragment's depth test, then `color`
    /// with its quad's `quad_lambda` and `write`, byte for byte. One or two units (the same 2D
    /// texture, each with its own environment), random filters, masks, buffers and stipples.
    #[test]
    fn textured_tri_span_is_the_scalar_sequence_byte_for_byte() {
        use crate::cpu::texture::Sampler;
        use crate::state::State;
        use crate::texture::{Level, TexObject};
        use std::sync::Arc;
        let mut g = Gen(37);
        let mins = [
            gl::NEAREST,
            gl::LINEAR,
            gl::NEAREST_MIPMAP_NEAREST,
            gl::LINEAR_MIPMAP_LINEAR,
        ];
        let envs = [gl::MODULATE, gl::REPLACE, gl::DECAL, gl::ADD, gl::BLEND];
        let wraps = [
            gl::REPEAT,
            gl::CLAMP_TO_EDGE,
            gl::REPEAT,
            gl::CLAMP_TO_EDGE,
            gl::CLAMP,
            gl::MIRRORED_REPEAT,
        ];
        // Rounds the fused AVX2 route (`FusedSpan`) covers, with a border texel among them.
        let (mut fused, mut fused_border) = (0, 0);
        for round in 0..900 {
            let mut obj = TexObject {
                min_filter: g.pick(&mins),
                mag_filter: g.pick(&[gl::NEAREST, gl::LINEAR]),
                wrap_s: g.pick(&wraps),
                wrap_t: g.pick(&wraps),
                ..TexObject::default()
            };
            // One round in four LINEAR without mipmaps with a border texel on s or t
            // (CLAMP_TO_BORDER or LINEAR's CLAMP; projective-texture's state), a border
            // colour of ones, zeros or random values.
            let bordered = round % 4 == 2;
            if bordered {
                border_state(&mut g, &mut obj);
            }
            let (ws, wt) = (obj.wrap_s, obj.wrap_t);
            // Mostly power-of-two levels (the dense ones), sometimes 6x6, 3x3, 1x1; RGBA or
            // RGB (alpha 1).
            let mut w = [8, 8, 4, 6][(g.next() % 4) as usize];
            let rgb = g.next() % 3 == 0;
            let mut k = 0;
            while w >= 1 {
                let texels = (0..w * w)
                    .map(|_| {
                        let mut t: [f32; 4] =
                            std::array::from_fn(|_| (g.next() % 256) as f32 / 255.0);
                        if rgb {
                            t[3] = 1.0;
                        }
                        t
                    })
                    .collect::<Vec<_>>();
                obj.levels[k] = Some(Level {
                    depth: 1,
                    width: w,
                    height: w,
                    internal_format: if rgb { gl::RGB } else { gl::RGBA } as i32,
                    base: if rgb { gl::RGB } else { gl::RGBA },
                    texels: texels.into(),
                });
                k += 1;
                w /= 2;
            }
            let units = 1 + round % 2;
            let mut state = State::new(4, 4);
            state.textures.defaults[1] = Arc::new(obj);
            for u in 0..units {
                state.enables.texture_2d[u] = true;
                state.textures.units[u].env_mode = g.pick(&envs);
                state.textures.units[u].env_color = Vec4::new(1.0, 0.0, 0.5, 0.25);
            }
            let mut samplers: [Option<Sampler>; MAX_TEXTURE_UNITS] = Default::default();
            for (u, s) in samplers.iter_mut().enumerate().take(units) {
                *s = Sampler::new(&state, u);
                assert!(s.is_some(), "unit {u} complete");
            }
            let rl = crate::cpu::testgen::tex_layout(units);
            let tex = tex_units(&samplers, &rl);
            let f = FragCtx {
                depth_test: g.next() % 4 != 0,
                depth_func: g.pick(&FUNCS),
                depth_mask: g.next() % 2 == 0,
                color_mask: match g.next() % 4 {
                    0 => std::array::from_fn(|_| g.next() % 2 == 0),
                    _ => [true; 4],
                },
                color_sum: false,
                rl,
                lighting: None,
                mats: &[],
                count: g.next() % 8 == 0,
                samples: g.next() % 2 == 0,
                stipple: (g.next() % 4 == 0).then(|| std::array::from_fn(|_| g.next() as u32)),
                ops: None,
                tex,
                crossbar: crossbar(&tex),
            };
            let ((tx, ty), p) = tile_tri(&mut g, &[0, F_LINE]);
            let planes = tex_planes(&mut g, rl.n);
            let color: Vec<[u8; 4]> = (0..TILE * TILE)
                .map(|_| (g.next() as u32).to_le_bytes())
                .collect();
            let two = g.next() % 4 == 0;
            if units == 1
                && matches!(state.textures.units[0].env_mode, gl::MODULATE | gl::REPLACE)
                && (bordered
                    || [ws, wt]
                        .iter()
                        .all(|&m| m == gl::REPEAT || m == gl::CLAMP_TO_EDGE))
                && !f.count
                && f.color_mask == [true; 4]
                && !two
            {
                fused += 1;
                fused_border += usize::from(bordered);
            }
            let depth: Vec<u32> = (0..TILE * TILE)
                .map(|_| (g.next() % 5) as u32 * (DEPTH_MAX / 4))
                .collect();
            let y = ty + (g.next() % TILE as u64) as i32;
            let x0 = tx + (g.next() % TILE as u64) as i32;
            let x1 = (x0 + (g.next() % 64) as i32).min(tx + TILE as i32 - 1);
            let run = |lanes: bool, rows: &[[i32; 3]], shared: bool| {
                let (mut c, mut c2, mut d, mut s) = (
                    color.clone(),
                    color.clone(),
                    depth.clone(),
                    vec![0u8; TILE * TILE],
                );
                let mut bufs = TileBufs {
                    color: &mut c,
                    color2: two.then_some(&mut c2[..]),
                    depth: &mut d,
                    stencil: &mut s,
                    x: tx,
                    y: ty,
                    samples: 0,
                };
                if lanes {
                    // One fused route for all the rows in one call (`raster::tri`'s) or one
                    // a row.
                    if shared {
                        f.tri_rows(&mut bufs, &p, &planes, rows, &mut None);
                    } else {
                        for &[y, x0, x1] in rows {
                            f.tri_span(&mut bufs, &p, &planes, y, x0, x1);
                        }
                    }
                } else {
                    let (ox, oy) = (p.bbox[0], p.bbox[1]);
                    let fy = (y - oy) as f32;
                    let zrow = p.z[0] + p.z[2] * fy;
                    let live = match f.stipple {
                        Some(rows) if p.flags & F_LINE == 0 => stipple_mask(&rows, x0, y),
                        _ => u64::MAX,
                    };
                    let pl = |j: usize| planes.get(j).copied().unwrap_or(0.0);
                    let mut v = vec![0.0f32; rl.n];
                    for x in x0..=x1 {
                        if live & (1 << (x - x0)) == 0 {
                            continue;
                        }
                        let i = ((y - ty) as usize) * TILE + (x - tx) as usize;
                        let fx = (x - ox) as f32;
                        if !f.depth(&mut bufs, i, f64::from(zrow + p.z[1] * fx)) {
                            continue;
                        }
                        if f.samples {
                            bufs.samples += 1;
                        }
                        let inv = 1.0 / (pl(0) + pl(1) * fx + pl(2) * fy);
                        for (j, vj) in v.iter_mut().enumerate() {
                            let o = 3 + 3 * j;
                            *vj = (pl(o) + pl(o + 1) * fx + pl(o + 2) * fy) * inv;
                        }
                        let lambda = f.quad_lambda(&planes, x, y, ox, oy);
                        let c = f.color(&p, &v, lambda);
                        f.write(&mut bufs, i, c);
                    }
                }
                let samples = bufs.samples;
                (c, c2, d, samples)
            };
            let one = [[y, x0, x1]];
            let (got, want) = (run(true, &one, false), run(false, &one, false));
            assert!(
                got == want,
                "round {round}: {f:?} {p:?} y {y} x {x0}..={x1}"
            );
            // Several rows of the primitive (repeats and both directions among them) through
            // one shared fused route against a route set up for each span.
            let mut r = Gen(2000 + round as u64);
            let rows: Vec<[i32; 3]> = (0..5)
                .map(|_| {
                    let y = ty + (r.next() % TILE as u64) as i32;
                    let x0 = tx + (r.next() % TILE as u64) as i32;
                    [
                        y,
                        x0,
                        (x0 + (r.next() % 64) as i32).min(tx + TILE as i32 - 1),
                    ]
                })
                .collect();
            let shared = run(true, &rows, true);
            assert!(
                shared == run(true, &rows, false),
                "round {round}: shared fused route differs, rows {rows:?}"
            );
            // The AVX2 routes (the fused one among them) against the SSE2 ones.
            #[cfg(target_arch = "x86_64")]
            if crate::cpu::lanes::has_avx2() {
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(true));
                let sse2 = run(true, &one, false);
                let sse2_rows = run(true, &rows, true);
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
                assert!(got == sse2, "round {round}: AVX2 and SSE2 differ");
                assert!(
                    shared == sse2_rows,
                    "round {round}: rows: AVX2 and SSE2 differ"
                );
            }
            // The same span with per-fragment operations (`ops_rows`'s textured route,
            // `tex_span`) against each fragment through `full`.
            let mut h = Gen(1000 + round as u64);
            let ops = Ops {
                fog: (h.next() % 2 == 0).then(|| FogEval {
                    mode: h.pick(&[gl::LINEAR, gl::EXP, gl::EXP2]),
                    density: (h.next() % 100) as f32 * 0.05,
                    start: -0.5,
                    end: 0.9,
                    color: Vec3::new(h.mostly_unit(), 0.5, h.mostly_unit()),
                }),
                alpha: (h.next() % 2 == 0).then(|| (h.pick(&FUNCS), h.next() as u8)),
                stencil: (h.next() % 2 == 0).then(|| {
                    [0, 1].map(|_| StencilSide {
                        func: h.pick(&FUNCS),
                        reference: h.next() as u8 % 4,
                        mask: 3,
                        ops: [gl::KEEP, gl::INCR, gl::REPLACE],
                        write: 0xFF,
                    })
                }),
                write: match h.next() % 4 {
                    0 => ColorWrite::Replace,
                    // The additive blend of point sprites (`blend_unorm8`'s SRC_ALPHA, ONE).
                    3 => ColorWrite::Blend(BlendEval {
                        src_rgb: gl::SRC_ALPHA,
                        dst_rgb: gl::ONE,
                        src_alpha: gl::SRC_ALPHA,
                        dst_alpha: gl::ONE,
                        eq_rgb: gl::FUNC_ADD,
                        eq_alpha: gl::FUNC_ADD,
                        constant: [0; 4],
                    }),
                    1 => ColorWrite::Blend(BlendEval {
                        src_rgb: gl::SRC_ALPHA,
                        dst_rgb: gl::ONE_MINUS_SRC_ALPHA,
                        src_alpha: gl::SRC_ALPHA,
                        dst_alpha: gl::ONE_MINUS_SRC_ALPHA,
                        eq_rgb: gl::FUNC_ADD,
                        eq_alpha: gl::FUNC_ADD,
                        constant: [0; 4],
                    }),
                    _ => ColorWrite::Logic(gl::XOR),
                },
            };
            let fo = FragCtx {
                ops: Some(ops),
                ..f.clone()
            };
            let stencil: Vec<u8> = (0..TILE * TILE).map(|_| h.next() as u8 % 4).collect();
            let tile = (color.clone(), color.clone(), depth.clone(), stencil);
            let span = Span {
                p: &p,
                planes: &planes,
                origin: (tx, ty),
                y,
                xs: (x0, x1),
                more: &[],
            };
            let [got, want] = span.both(&fo, &ops, &tile, two);
            assert!(
                got == want,
                "round {round} with {ops:?}: {f:?} {p:?} y {y} x {x0}..={x1}"
            );
        }
        assert!(
            fused > 30 && fused_border > 8,
            "{fused} of 900 rounds in the fused route's state, {fused_border} with a border"
        );
    }

    /// A tile at a random place of a 256x256 window and a triangle whose bounding box's
    /// corner lies within 20 pixels of the tile's, with flags one of `flags` and a depth
    /// plane drawn from `g`.
    fn tile_tri(g: &mut Gen, flags: &[u8]) -> ((i32, i32), RPrim) {
        let (tx, ty) = (64 * (g.next() % 4) as i32, 64 * (g.next() % 4) as i32);
        let bbox = [
            tx + (g.next() % 40) as i32 - 20,
            ty + (g.next() % 40) as i32 - 20,
        ];
        let flags = flags[(g.next() % flags.len() as u64) as usize];
        let z = [g.mostly_unit(), (g.next() % 100) as f32 * 1e-3 - 0.05, 1e-3];
        ((tx, ty), box_tri(flags, bbox, z))
    }

    /// A textured primitive's planes of `n` varyings: 1/w, the colour (around [0, 1]) and
    /// the rest (coordinates) spanning a few repeats, with derivatives large and small so
    /// that λ crosses the levels; now and then a coordinate plane term that is NaN, infinite
    /// or zero (q = 0).
    fn tex_planes(g: &mut Gen, n: usize) -> Vec<f32> {
        let mut planes = vec![0.5 + (g.next() % 100) as f32 * 0.01, 1e-3, -2e-3];
        for j in 0..n {
            let d = if j < 4 {
                1e-2
            } else {
                [1e-3, 3e-2, 0.3][(g.next() % 3) as usize]
            };
            planes.extend([g.mostly_unit(), g.mostly_unit() * d, g.mostly_unit() * d]);
        }
        if g.next() % 8 == 0 {
            let k = 3 + 3 * 4 + (g.next() % 12) as usize;
            if let Some(v) = planes.get_mut(k) {
                *v = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0][(g.next() % 4) as usize];
            }
        }
        planes
    }

    /// A texture object's state with a border texel the fused route covers: LINEAR on both
    /// filters (no mipmaps read), CLAMP_TO_BORDER or CLAMP on s or t (both now and then), the
    /// other axis any wrap the border kernels take, a border colour of ones, zeros or random
    /// values (NaN and 1e30 among them).
    fn border_state(g: &mut Gen, obj: &mut crate::texture::TexObject) {
        obj.min_filter = gl::LINEAR;
        obj.mag_filter = gl::LINEAR;
        let (a, b) = (
            g.pick(&[gl::CLAMP_TO_BORDER, gl::CLAMP_TO_BORDER, gl::CLAMP]),
            g.pick(&[
                gl::CLAMP_TO_BORDER,
                gl::CLAMP,
                gl::REPEAT,
                gl::CLAMP_TO_EDGE,
            ]),
        );
        (obj.wrap_s, obj.wrap_t) = if g.next() % 2 == 0 { (a, b) } else { (b, a) };
        obj.border_color = match g.next() % 3 {
            0 => Vec4::ONE,
            1 => Vec4::ZERO,
            _ => Vec4::from_array(std::array::from_fn(|_| g.mostly_unit())),
        };
    }

    /// The fused route's packed groups (`FusedSpan::packed_group` through `packed_rows`)
    /// against the SSE2 row route, byte for byte (colour, depth, the occlusion count): one 2D
    /// unit in the states `FusedSpan` covers — MODULATE or REPLACE on RGBA or RGB under
    /// REPEAT or CLAMP_TO_EDGE with every MIN filter (λ of each lane's own quad, levels
    /// that are not dense among them), LINEAR with a border texel (`border_state`), a depth
    /// texture's comparison under BLEND — the varyings all smooth, the colour flat, or all
    /// flat (`FusedSpan`'s three `DIV` patterns), the rows of small triangles (short spans,
    /// packed) and now and then wide ones (the row route). Each state is asserted to have
    /// packed in many rounds.
    #[test]
    fn fused_packed_groups_are_the_row_route_byte_for_byte() {
        use crate::cpu::testgen::{tri_rows_agree, tri_rows_in_tile};
        use crate::cpu::texture::FusedSpan;
        let mut g = Gen(97);
        if !crate::cpu::lanes::has_avx2() {
            return;
        }
        // Rounds packed by the fused route, per state (colour, border, shadow), and the
        // fragments they drew.
        let (mut packed, mut frags) = ([0usize; 3], 0usize);
        for round in 0..1500 {
            let kind = round % 3;
            let (shadow, bordered) = (kind == 2, kind == 1);
            let samplers = fused_unit(&mut g, shadow, bordered);
            // The coordinates after the colour, or after a secondary colour, or before it
            // (a FLAT primitive's flat varyings then cover them: every varying flat).
            let mut rl = RLayout {
                n: 8,
                ..Default::default()
            };
            match g.next() % 3 {
                0 => rl.tex[0] = Some(4),
                1 => (rl.n, rl.spec, rl.tex[0]) = (12, Some(4), Some(8)),
                _ => (rl.n, rl.spec, rl.tex[0]) = (12, Some(8), Some(4)),
            }
            let tex = tex_units(&samplers, &rl);
            let Some((tx, _)) = tex[0] else {
                panic!("unit 0 complete");
            };
            assert!(FusedSpan::covers(tx) && tx.lanes_ok(), "round {round}");
            let f = crate::cpu::testgen::tex_ctx(rl, tex, &mut || g.next());
            let ((tx, ty), p) = tile_tri(&mut g, &[F_FLAT, 0, 0, 0]);
            let planes = tex_planes(&mut g, rl.n);
            // A small triangle's rows (consecutive, a few pixels each, drifting), one round
            // in eight a wide one's.
            let len = if g.next() % 8 == 0 { 40 } else { 14 };
            let rows = tri_rows_in_tile(&mut || g.next(), tx, ty, len);
            let (_, packs, n) = tri_rows_agree(&f, &p, &planes, &rows, (tx, ty), &mut || g.next());
            if packs {
                packed[kind] += 1;
                frags += n;
            }
        }
        assert!(
            packed.iter().all(|&n| n > 300) && frags > 20_000,
            "{packed:?} rounds packed, {frags} fragments"
        );
    }

    /// The sampler of a unit 0 the fused route covers (`FusedSpan::covers`), drawn from `g`:
    /// a depth texture's comparison (NEAREST, LUMINANCE, env BLEND: shadow-map's state)
    /// where `shadow`, LINEAR with a border texel where `bordered` (`border_state`), else
    /// REPEAT or CLAMP_TO_EDGE under any MIN filter, MODULATE or REPLACE; dense levels
    /// mostly (8x8, 4x4, 32x32 and 6x6 ones), RGBA or RGB.
    fn fused_unit(
        g: &mut Gen,
        shadow: bool,
        bordered: bool,
    ) -> [Option<crate::cpu::texture::Sampler>; MAX_TEXTURE_UNITS] {
        use crate::state::State;
        use crate::texture::{Level, TexObject};
        use std::sync::Arc;
        let mut obj = TexObject {
            min_filter: g.pick(&crate::cpu::testgen::MIN_FILTERS),
            mag_filter: g.pick(&[gl::NEAREST, gl::LINEAR]),
            wrap_s: g.pick(&[gl::REPEAT, gl::CLAMP_TO_EDGE]),
            wrap_t: g.pick(&[gl::REPEAT, gl::CLAMP_TO_EDGE]),
            ..TexObject::default()
        };
        if shadow {
            obj.min_filter = gl::NEAREST;
            obj.mag_filter = gl::NEAREST;
            obj.compare_mode = gl::COMPARE_R_TO_TEXTURE;
            obj.compare_func = g.pick(&FUNCS);
            obj.depth_texture_mode = gl::LUMINANCE;
        }
        if bordered {
            border_state(g, &mut obj);
        }
        let mut w = [8, 8, 4, 6, 32][(g.next() % 5) as usize];
        // Twice as high or half as high now and then: a kernel that takes the level's width
        // for its height (or the reverse) fails.
        let mut h = match g.next() % 3 {
            0 => w,
            1 => 2 * w,
            _ => (w / 2).max(1),
        };
        let rgb = g.next() % 3 == 0;
        let mut k = 0;
        loop {
            let texels = (0..w * h)
                .map(|_| {
                    let mut t: [f32; 4] = std::array::from_fn(|_| (g.next() % 256) as f32 / 255.0);
                    if rgb {
                        t[3] = 1.0;
                    }
                    if shadow {
                        t = [t[0], 0.0, 0.0, 1.0];
                    }
                    t
                })
                .collect::<Vec<_>>();
            let (fmt, base) = match (shadow, rgb) {
                (true, _) => (gl::DEPTH_COMPONENT, gl::DEPTH_COMPONENT),
                (false, true) => (gl::RGB, gl::RGB),
                (false, false) => (gl::RGBA, gl::RGBA),
            };
            obj.levels[k] = Some(Level {
                depth: 1,
                width: w,
                height: h,
                internal_format: fmt as i32,
                base,
                texels: texels.into(),
            });
            k += 1;
            if w == 1 && h == 1 {
                break;
            }
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
        let mut state = State::new(4, 4);
        state.textures.defaults[1] = Arc::new(obj);
        state.enables.texture_2d[0] = true;
        state.textures.units[0].env_mode = g.pick(&[gl::MODULATE, gl::REPLACE]);
        if shadow {
            state.textures.units[0].env_mode = gl::BLEND;
            state.textures.units[0].env_color =
                Vec4::from_array(std::array::from_fn(|_| g.mostly_unit()));
        }
        let mut samplers: [Option<crate::cpu::texture::Sampler>; MAX_TEXTURE_UNITS] =
            Default::default();
        samplers[0] = crate::cpu::texture::Sampler::new(&state, 0);
        samplers
    }

    /// `FusedSpan::channel_groups` (the colours of `tex_span`'s fused route) against
    /// `oplanes::clamp01` of `color_lanes` (what `tex_span_in` computes for them, λ from each
    /// pixel's `quad_lambda`), bit for bit on the lanes of the mask: random states the fused
    /// route covers (filters, REPEAT or CLAMP_TO_EDGE, RGB or RGBA, power-of-two and 6x6
    /// levels, MODULATE or REPLACE; one round in four LINEAR with a border texel, as
    /// `border_state`), flat or smooth colours, planes with NaN, infinite or zero terms,
    /// groups and masks. `FusedSpan::group` (the colours packed and stored; the depth
    /// comparison's own route) on the same groups against `store_pixels`' bytes of them, and
    /// `FusedSpan::span` against `group` (LINEAR without mipmaps there with its level looked
    /// up once a span, the filter inline: the `LIN` loops).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn fused_channels_are_clamped_color_lanes_bit_for_bit() {
        use crate::cpu::oplanes::clamp01;
        use crate::cpu::texture::FusedSpan;
        if !crate::cpu::lanes::has_avx2() {
            return;
        }
        let mut g = Gen(53);
        for round in 0..2000 {
            // One round in three a depth texture's comparison (NEAREST, LUMINANCE, env
            // BLEND), the shadow-map state.
            let shadow = round % 3 == 2;
            let bordered = !shadow && round % 4 == 1;
            let samplers = fused_unit(&mut g, shadow, bordered);
            let mut rl = RLayout {
                n: 8,
                ..Default::default()
            };
            rl.tex[0] = Some(4);
            let tex = tex_units(&samplers, &rl);
            let Some((tx, to)) = tex[0] else {
                panic!("unit 0 complete");
            };
            assert!(FusedSpan::covers(tx) && tx.lanes_ok(), "round {round}");
            // No depth test, occlusion count or stipple (`tex_ctx` with them off).
            let f = FragCtx {
                depth_test: false,
                depth_func: gl::LESS,
                samples: false,
                stipple: None,
                ..crate::cpu::testgen::tex_ctx(rl, tex, &mut || 1)
            };
            let flat = g.next() % 4 == 0;
            let bbox = [(g.next() % 300) as i32 - 50, (g.next() % 300) as i32 - 50];
            let p = RPrim {
                kind: PrimKind::Tri,
                flags: if flat { F_FLAT } else { 0 },
                bbox: [bbox[0], bbox[1], bbox[0] + 100, bbox[1] + 100],
                mat: 0,
                voff: 0,
                xy: [0; 6],
                owns: 0,
                cover: 0,
                z: [0.5, 0.0, 0.0],
            };
            // 1/w, the colour (around [0, 1], beyond it now and then) and coordinates
            // spanning a few repeats, derivatives large and small so that λ crosses levels.
            let mut planes = vec![0.5 + (g.next() % 100) as f32 * 0.01, 1e-3, -2e-3];
            for j in 0..rl.n {
                let d = if j < 4 {
                    [1e-2, 0.2][(g.next() % 2) as usize]
                } else {
                    [1e-3, 3e-2, 0.3][(g.next() % 3) as usize]
                };
                planes.extend([g.mostly_unit(), g.mostly_unit() * d, g.mostly_unit() * d]);
            }
            if g.next() % 6 == 0 {
                let k = (g.next() % planes.len() as u64) as usize;
                planes[k] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0]
                    [(g.next() % 5) as usize];
            }
            if g.next() % 10 == 0 {
                // q = 0 over the whole plane.
                planes[3 + 3 * 7..3 + 3 * 8].copy_from_slice(&[0.0; 3]);
            }
            let nflat = if flat { 4 } else { 0 };
            let y = bbox[1] + (g.next() % 64) as i32;
            let fy = (y - bbox[1]) as f32;
            let qy = ((y & !1) - bbox[1]) as f32;
            let Some(mut fs) = FusedSpan::new(tx, to, &planes, nflat, fy, bbox[0], qy) else {
                panic!("round {round}: the fused route covers this sampler");
            };
            let mut gx = bbox[0] + (g.next() % 64) as i32;
            for k in 0..4 {
                // The next group of the row (the row's quads' λ kept), or any group.
                gx = if k > 0 && g.next() % 2 == 0 {
                    gx + 8
                } else {
                    bbox[0] + (g.next() % 64) as i32
                };
                let m = match g.next() % 3 {
                    0 => 0xFF,
                    _ => (g.next() as u8).max(1),
                };
                let mut v = [[0.0f32; LANES]; 8];
                crate::cpu::lanes::varyings(&planes, nflat, gx - bbox[0], fy, &mut v);
                let mut lam = [[0.0f32; LANES]; MAX_TEXTURE_UNITS];
                for (l, x) in lam[0].iter_mut().enumerate() {
                    *x = f.quad_lambda(&planes, gx + l as i32, y, bbox[0], bbox[1])[0];
                }
                let want = f.color_lanes(&p, &v, m, &lam, true).map(clamp01);
                // `FusedSpan::group` from the same state (the depth comparison's groups
                // through `depth_group`): `store_pixels`' bytes of `want` on the lanes of
                // `m`, the others untouched.
                let mut fg = fs;
                let mut px = [[7u8; 4]; LANES];
                // SAFETY: the CPU has AVX2 (checked above).
                unsafe { fg.group(gx, m, &mut px) };
                for (l, got) in px.iter().enumerate() {
                    let pack = |c: f32| ((c * (255.0 / 256.0) + 32768.0).to_bits() & 0xFF) as u8;
                    let wl = if m & (1 << l) != 0 {
                        want.map(|c| pack(c[l]))
                    } else {
                        [7; 4]
                    };
                    assert_eq!(*got, wl, "round {round} x {gx} lane {l}: group's bytes");
                }
                // `FusedSpan::span` on the same group (its depth state chosen once): the
                // same bytes, the lanes outside `m` untouched.
                let mut fg = fs;
                let mut ps = [[7u8; 4]; LANES];
                // SAFETY: the CPU has AVX2 (checked above).
                unsafe { fg.span(gx, LANES, u64::from(m), &mut ps) };
                assert_eq!(ps, px, "round {round} x {gx}: span's bytes");
                // `FusedSpan::channel_groups` on a span of two groups from gx - 8, the group
                // at gx its second (the first without a lane: left as it was).
                let mut out = [[[7.0f32; LANES]; 4]; TILE / LANES];
                // SAFETY: the CPU has AVX2 and POPCNT (checked above).
                unsafe { fs.channel_groups(gx - 8, 16, u64::from(m) << 8, &mut out) };
                assert_eq!(
                    out[0], [[7.0; LANES]; 4],
                    "round {round} x {gx}: group 0 written"
                );
                let got = out[1];
                for l in (0..LANES).filter(|l| m & (1 << l) != 0) {
                    let (a, b) = (got.map(|c| c[l].to_bits()), want.map(|c| c[l].to_bits()));
                    assert!(
                        a == b,
                        "round {round} x {gx} lane {l}: {:?} {:?}",
                        got.map(|c| c[l]),
                        want.map(|c| c[l])
                    );
                }
            }
        }
    }

    /// A triangle of the random span tests: `flags`, its box 100 pixels square from `bbox`,
    /// the depth plane `z`.
    fn box_tri(flags: u8, bbox: [i32; 2], z: [f32; 3]) -> RPrim {
        RPrim {
            kind: PrimKind::Tri,
            flags,
            bbox: [bbox[0], bbox[1], bbox[0] + 100, bbox[1] + 100],
            mat: 0,
            voff: 0,
            xy: [0; 6],
            owns: 0,
            cover: 0,
            z,
        }
    }
    #[test]
    fn full_span_on_lanes_is_the_scalar_sequence_byte_for_byte() {
        let mut g = Gen(21);
        let sops = [
            gl::KEEP,
            gl::ZERO,
            gl::REPLACE,
            gl::INCR,
            gl::DECR_WRAP,
            gl::INVERT,
        ];
        let factors = [
            gl::ZERO,
            gl::ONE,
            gl::SRC_ALPHA,
            gl::ONE_MINUS_SRC_ALPHA,
            gl::DST_COLOR,
            gl::CONSTANT_COLOR,
            gl::SRC_ALPHA_SATURATE,
        ];
        let eqs = [gl::FUNC_ADD, gl::FUNC_SUBTRACT, gl::MIN];
        for round in 0..3000 {
            let spec = g.next() % 2 == 0;
            let fog_on = g.next() % 2 == 0;
            let mut rl = RLayout {
                n: 4,
                ..Default::default()
            };
            if spec {
                rl.spec = Some(rl.n);
                rl.n += 4;
            }
            // Now and then coordinates of a unit without texturing between the colours and
            // the fog coordinate (`plain_rows` interpolates only the varyings it reads).
            let unused = g.next() % 3 == 0;
            if unused {
                rl.tex[1] = Some(rl.n);
                rl.n += 4;
            }
            if fog_on || g.next() % 3 == 0 {
                rl.fog = Some(rl.n);
                rl.n += 1;
            }
            let mut side = || StencilSide {
                func: g.pick(&FUNCS),
                reference: g.next() as u8 % 4,
                mask: if g.next() % 2 == 0 { 0xFF } else { 3 },
                ops: [g.pick(&sops), g.pick(&sops), g.pick(&sops)],
                write: if g.next() % 2 == 0 {
                    0xFF
                } else {
                    g.next() as u8
                },
            };
            let sides = [side(), side()];
            let stencil = (g.next() % 2 == 0).then_some(sides);
            let write = match g.next() % 3 {
                0 => ColorWrite::Replace,
                1 => ColorWrite::Blend(BlendEval {
                    src_rgb: g.pick(&factors),
                    dst_rgb: g.pick(&factors),
                    src_alpha: g.pick(&factors),
                    dst_alpha: g.pick(&factors),
                    eq_rgb: g.pick(&eqs),
                    eq_alpha: g.pick(&eqs),
                    constant: [g.next() as u8, 7, 200, g.next() as u8],
                }),
                _ => ColorWrite::Logic(gl::CLEAR + (g.next() % 16) as u32),
            };
            let ops = Ops {
                fog: fog_on.then(|| FogEval {
                    mode: g.pick(&[gl::LINEAR, gl::EXP, gl::EXP2]),
                    density: (g.next() % 100) as f32 * 0.05,
                    start: 0.1,
                    end: if g.next() % 5 == 0 { 0.1 } else { 0.9 },
                    color: Vec3::new(g.mostly_unit(), 0.5, g.mostly_unit()),
                }),
                alpha: (g.next() % 2 == 0).then(|| (g.pick(&FUNCS), g.next() as u8)),
                stencil,
                write,
            };
            let stipple = (g.next() % 4 == 0).then(|| std::array::from_fn(|_| g.next() as u32));
            let mut f = FragCtx {
                depth_test: g.next() % 4 != 0,
                depth_func: g.pick(&FUNCS),
                depth_mask: g.next() % 2 == 0,
                // All false now and then: `ops_rows`'s route without a colour write.
                color_mask: match g.next() % 6 {
                    0 | 1 => std::array::from_fn(|_| g.next() % 2 == 0),
                    2 => [false; 4],
                    _ => [true; 4],
                },
                color_sum: spec && g.next() % 4 != 0,
                rl,
                lighting: None,
                mats: &[],
                count: g.next() % 8 == 0,
                samples: g.next() % 2 == 0,
                stipple,
                ops: Some(ops),
                tex: [None; MAX_TEXTURE_UNITS],
                crossbar: false,
            };
            // One round in four the depth tests the AVX2 routes compile in (`depth_fast`:
            // LESS or LEQUAL, the depth mask true), against the SSE2 routes' per-group choice.
            if round % 4 == 3 {
                f.depth_test = true;
                f.depth_func = [gl::LESS, gl::LEQUAL][round / 4 % 2];
                f.depth_mask = true;
            }
            let (tx, ty) = (64 * (g.next() % 4) as i32, 64 * (g.next() % 4) as i32);
            let flags = [0, F_FLAT, F_BACK, F_LINE, F_FLAT | F_BACK][(g.next() % 5) as usize];
            let bbox = [
                tx + (g.next() % 40) as i32 - 20,
                ty + (g.next() % 40) as i32 - 20,
            ];
            // Depths: a plane crossing the stored values, sometimes outside [0, 1].
            let z = [g.mostly_unit(), (g.next() % 100) as f32 * 1e-3 - 0.05, 1e-3];
            let p = box_tri(flags, bbox, z);
            let mut planes = vec![0.5 + (g.next() % 100) as f32 * 0.01, 1e-3, -2e-3];
            for _ in 0..rl.n {
                planes.extend([
                    g.mostly_unit(),
                    g.mostly_unit() * 1e-2,
                    g.mostly_unit() * 1e-2,
                ]);
            }
            if unused && g.next() % 2 == 0 {
                // A pool shorter than the layout: the missing floats read as 0.
                planes.truncate(3 + (g.next() % (3 * rl.n as u64)) as usize);
            }
            let color: Vec<[u8; 4]> = (0..TILE * TILE)
                .map(|_| (g.next() as u32).to_le_bytes())
                .collect();
            let two = g.next() % 4 == 0;
            let color2: Vec<[u8; 4]> = color.iter().map(|c| c.map(|x| x ^ 0x5A)).collect();
            let depth: Vec<u32> = (0..TILE * TILE)
                .map(|_| (g.next() % 5) as u32 * (DEPTH_MAX / 4))
                .collect();
            let stencil: Vec<u8> = (0..TILE * TILE).map(|_| g.next() as u8 % 4).collect();
            let y = ty + (g.next() % TILE as u64) as i32;
            let x0 = tx + (g.next() % TILE as u64) as i32;
            let x1 = (x0 + (g.next() % 64) as i32).min(tx + TILE as i32 - 1);
            let tile = (color, color2, depth, stencil);
            // Half the time up to three further rows of the primitive in the same call
            // (`ops_rows`: what depends on the primitive set up once), rows above and below,
            // each its own columns, the same pixels now and then drawn twice.
            let mut more = Vec::new();
            if g.next() % 2 == 0 {
                for _ in 0..1 + g.next() % 3 {
                    let y = ty + (g.next() % TILE as u64) as i32;
                    let x0 = tx + (g.next() % TILE as u64) as i32;
                    let x1 = (x0 + (g.next() % 64) as i32).min(tx + TILE as i32 - 1);
                    more.push([y, x0, x1]);
                }
            }
            let span = Span {
                p: &p,
                planes: &planes,
                origin: (tx, ty),
                y,
                xs: (x0, x1),
                more: &more,
            };
            let [got, want] = span.both(&f, &ops, &tile, two);
            assert!(
                got == want,
                "round {round}: {f:?} {p:?} y {y} x {x0}..={x1} {more:?}"
            );
        }
    }

    /// `const_rows` (a FLAT primitive of one colour, or a depth-only pass, its rows in one
    /// call) against each row through `tri_span`, on the AVX2 route and with it turned off
    /// (`lanes::NO_AVX2`): the same colours, depths and samples, byte for byte. Random depth
    /// states (the compiled-in LESS and LEQUAL among them), depth planes crossing the stored
    /// values, flat colours with ±0, NaN and ∞, rows anywhere in the tile (its last pixels
    /// among them, where a group runs past the buffers' end).
    #[test]
    fn const_rows_are_tri_span_byte_for_byte() {
        let mut g = Gen(61);
        let (mut taken, mut flat) = (0, 0);
        for round in 0..3000 {
            let mut f = FragCtx {
                depth_test: g.next() % 5 != 0,
                depth_func: g.pick(&FUNCS),
                depth_mask: g.next() % 2 == 0,
                color_mask: match g.next() % 8 {
                    0 => std::array::from_fn(|_| g.next() % 2 == 0),
                    1 | 2 => [false; 4],
                    _ => [true; 4],
                },
                color_sum: false,
                rl: RLayout {
                    n: 4,
                    ..Default::default()
                },
                lighting: None,
                mats: &[],
                count: g.next() % 20 == 0,
                samples: g.next() % 2 == 0,
                stipple: None,
                ops: None,
                tex: [None; MAX_TEXTURE_UNITS],
                crossbar: false,
            };
            if round % 3 == 2 {
                f.depth_test = true;
                f.depth_func = [gl::LESS, gl::LEQUAL][round / 3 % 2];
                f.depth_mask = true;
            }
            let (tx, ty) = (64 * (g.next() % 4) as i32, 64 * (g.next() % 4) as i32);
            let flags = [F_FLAT, F_FLAT, F_FLAT | F_BACK, 0][(g.next() % 4) as usize];
            let bbox = [tx - (g.next() % 20) as i32, ty - (g.next() % 20) as i32];
            let z = [g.mostly_unit(), (g.next() % 100) as f32 * 1e-3 - 0.05, 1e-3];
            let p = box_tri(flags, bbox, z);
            let mut planes = vec![0.5 + (g.next() % 100) as f32 * 0.01, 1e-3, -2e-3];
            for _ in 0..4 {
                let v = match g.next() % 8 {
                    0 => [0.0, -0.0, f32::NAN, f32::INFINITY, -1.0, 2.0][(g.next() % 6) as usize],
                    _ => g.mostly_unit(),
                };
                let z = |g: &mut Gen| [0.0, -0.0][(g.next() % 2) as usize];
                planes.extend([v, z(&mut g), z(&mut g)]);
            }
            if g.next() % 10 == 0 {
                // A step: not one colour (`const_fill` says None).
                planes[4 + 3 * (g.next() % 4) as usize] = 1e-3;
            }
            let (color, depth, stencil) = crate::cpu::testgen::tile_contents(&mut g);
            let rows: Vec<[i32; 3]> = (0..1 + g.next() % 20)
                .map(|_| {
                    let y = ty + (g.next() % TILE as u64) as i32;
                    let x0 = tx + (g.next() % TILE as u64) as i32;
                    let x1 = (x0 + (g.next() % 64) as i32).min(tx + TILE as i32 - 1);
                    [y, x0, x1]
                })
                .collect();
            let draw = |by_rows: bool| {
                let (mut c, mut d, mut s) = (color.clone(), depth.clone(), stencil.clone());
                let mut bufs = crate::cpu::testgen::tile_bufs(&mut c, &mut d, &mut s, (tx, ty));
                let fill = f.const_fill(&bufs, &p, &planes);
                match fill {
                    Some(fill) if by_rows => f.const_rows(&mut bufs, &p, &planes, fill, &rows),
                    _ => {
                        for &[y, x0, x1] in &rows {
                            f.tri_span(&mut bufs, &p, &planes, y, x0, x1);
                        }
                    }
                }
                let samples = bufs.samples;
                (fill, c, d, samples)
            };
            let want = draw(false);
            let got = draw(true);
            assert!(
                got == want,
                "round {round}: {f:?} {p:?} {planes:?} {rows:?}"
            );
            #[cfg(target_arch = "x86_64")]
            if crate::cpu::lanes::has_avx2() {
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(true));
                let sse2 = draw(false);
                crate::cpu::lanes::NO_AVX2.with(|c| c.set(false));
                assert!(got == sse2, "round {round}: the SSE2 route differs");
            }
            taken += usize::from(got.0.is_some());
            flat += usize::from(matches!(got.0, Some(ConstFill::Flat(_))));
        }
        // Both fills were taken, and the other primitives left to `tri_span`.
        assert!(
            taken > 1500 && flat > 800 && taken < 2900,
            "taken {taken} flat {flat}"
        );
    }

    #[test]
    fn spread_on_lanes_is_spread_quads_bit_for_bit() {
        let mut g = Gen(43);
        for _ in 0..5000 {
            let q: [[f32; LANES]; ROW_QUAD_BLOCKS] =
                std::array::from_fn(|_| std::array::from_fn(|_| g.float()));
            let d = (g.next() % 40) as usize;
            let x = (g.next() % 4096) as i32 - 1024;
            let want = crate::cpu::texture::spread_quads(q.as_flattened(), d, x).map(f32::to_bits);
            for avx2 in [false, true] {
                let got = match avx2 {
                    #[cfg(target_arch = "x86_64")]
                    true if crate::cpu::lanes::has_avx2() => spread_on::<true>(&q, d, x),
                    true => continue,
                    false => spread_on::<false>(&q, d, x),
                };
                assert_eq!(got.map(f32::to_bits), want, "d {d} x {x} avx2 {avx2}");
            }
        }
    }

    #[test]
    fn store_pixels_on_lanes_is_store_pixels_byte_for_byte() {
        let mut g = Gen(47);
        for _ in 0..3000 {
            let c: [Vec4; LANES] =
                std::array::from_fn(|_| Vec4::new(g.float(), g.float(), g.float(), g.float()));
            let n = 1 + (g.next() % 12) as usize;
            let m = g.next() as u8;
            let row0: Vec<[u8; 4]> = (0..n).map(|_| (g.next() as u32).to_le_bytes()).collect();
            let mut want = row0.clone();
            crate::cpu::lanes::store_pixels(&mut want, m, &c);
            for avx2 in [false, true] {
                let mut got = row0.clone();
                match avx2 {
                    #[cfg(target_arch = "x86_64")]
                    true if crate::cpu::lanes::has_avx2() => {
                        store_pixels_on::<true>(&mut got, m, &c)
                    }
                    true => continue,
                    false => store_pixels_on::<false>(&mut got, m, &c),
                }
                assert_eq!(got, want, "m {m:#x} n {n} avx2 {avx2} {c:?}");
            }
        }
    }

    #[test]
    fn to_pixels_on_lanes_is_to_pixels_bit_for_bit() {
        #[cfg(target_arch = "x86_64")]
        if crate::cpu::lanes::has_avx2() {
            let mut g = Gen(53);
            for _ in 0..2000 {
                let c: [[f32; LANES]; 4] =
                    std::array::from_fn(|_| std::array::from_fn(|_| g.float()));
                let want = crate::cpu::lanes::to_pixels([&c[0], &c[1], &c[2], &c[3]]);
                // SAFETY: the CPU has AVX2 (`has_avx2`).
                let got = unsafe { to_pixels_avx2(&c) };
                assert_eq!(
                    got.map(|v| v.to_array().map(f32::to_bits)),
                    want.map(|v| v.to_array().map(f32::to_bits))
                );
            }
        }
    }
}
