//! Primitive setup (GL 2.1 §2.11.1, §3.4–3.6): perspective divide, viewport and DepthRange
//! transform, facing by signed window area, culling, polygon mode, polygon offset, and the
//! per-primitive data the tile rasteriser needs (edge functions, attribute planes, tile bins).
//!
//! Design decision: window x and y are snapped to 1/256 pixel (8 sub-pixel bits, as llvmpipe) and
//! triangle edge functions are exact 64-bit integers evaluated at pixel centres, with a tie-break
//! (left and bottom edges own their centres, as llvmpipe in a y-up window), so two triangles sharing an edge never both cover a pixel on it. Attributes become
//! planes of (attribute / w) and 1 / w over the pixel grid, relative to the primitive's bounding
//! box corner, which is what perspective-correct interpolation needs (§3.5.1, eq. 3.9).
//!
//! The common triangle (no clipping, FILL for both faces, no PHONG_WIN) takes
//! `Worker::fast_tri`: facing, culling and the coverage test use only the vertex stage's
//! compact window records, and varyings are read only for triangles that cover a pixel centre
//! (about half in a dense mesh); it computes exactly what the general path does. Everything
//! else (clipping, PolygonMode LINE/POINT, PHONG_WIN, points and lines) takes the general path
//! in `polygon.rs` (lines themselves in `line.rs`).

use std::mem::MaybeUninit;

use glam::Vec4;

use super::assembly::{Asm, ALL_EDGES, QUAD_STRIP_EDGES};
use super::batch::{Batch, Prim};
use super::clip::Clipper;
use super::framebuffer::TILE;
use super::lanes::WinLanes;
use super::vertex::{Lanes4, Layout, Route};
use crate::gl;
use crate::state::{State, MAX_TEXTURE_UNITS};

/// Largest snapped window coordinate magnitude (1/256 pixel units), for triangles and lines
/// alike: ±2^29 (±2M pixels) leaves room for a line's half width (< 2^27) and the +128 of the
/// pixel centre under [`COORD_LIMIT`].
pub(super) const SNAP_LIMIT: f64 = (1u64 << 29) as f64;

/// Bound on every snapped coordinate `geom` and the rasteriser see: with |v| < 2^30, an edge
/// delta is < 2^31, each edge-function product < 2^62 and their difference fits i64; the
/// bounding box and the vertices fit i32. Clipping (§2.12) keeps real vertices within the
/// viewport, at most MAX_VIEWPORT_DIM wide, so only the snap clamps ever come near it.
pub(super) const COORD_LIMIT: i64 = 1 << 30;

/// Most interpolated floats per fragment: colour 4, secondary 4, four texture units 4 each
/// (`MAX_TEXTURE_UNITS`), PHONG_WIN 10, fog 1, the antialiasing coordinates 4.
pub const MAXV: usize = 4 + 4 + 4 * MAX_TEXTURE_UNITS + 10 + 1 + 4;

/// Where each interpolated value sits in a fragment's varyings.
#[derive(Clone, Copy, Debug, Default)]
pub struct RLayout {
    /// Number of varyings.
    pub n: usize,
    /// Secondary colour (primary is always at 0).
    pub spec: Option<usize>,
    /// Texture coordinates of each unit (see `Layout::tex`).
    pub tex: [Option<usize>; MAX_TEXTURE_UNITS],
    /// PHONG_WIN: eye xyz at `phong`, normal xyz at `phong + 3`, unlit colour at `phong + 6`.
    pub phong: Option<usize>,
    /// Fog coordinate (one float; fragment ops).
    pub fog: Option<usize>,
    /// POINT_SMOOTH or LINE_SMOOTH: the four coordinates Mesa's draw module gives the quad of
    /// a smooth point or line (`F_AAPOINT`, `F_AALINE`), from which the fragment's coverage
    /// comes (see `aa.rs`).
    pub aa: Option<usize>,
}

impl RLayout {
    fn new(l: &Layout) -> Self {
        let mut r = RLayout {
            n: 4,
            ..Default::default()
        };
        if l.spec.is_some() {
            r.spec = Some(r.n);
            r.n += 4;
        }
        for (d, s) in r.tex.iter_mut().zip(&l.tex) {
            if s.is_some() {
                *d = Some(r.n);
                r.n += 4;
            }
        }
        if l.nrm.is_some() {
            r.phong = Some(r.n);
            r.n += 10;
        }
        if l.fog.is_some() {
            r.fog = Some(r.n);
            r.n += 1;
        }
        r
    }
}

/// What kind of rasterised primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrimKind {
    /// A filled triangle (also half of a line's parallelogram).
    Tri,
    /// A point.
    Point,
}

/// Flag: colour varyings are constant (FLAT), not divided by w.
pub const F_FLAT: u8 = 1;
/// Flag: the primitive comes from a back-facing polygon.
pub const F_BACK: u8 = 2;
/// Flag: evaluate lighting per fragment (PHONG_WIN triangle).
pub const F_PHONG: u8 = 4;
/// Flag: half of a line's parallelogram (never polygon-stippled, §3.5.6).
pub const F_LINE: u8 = 8;
/// Flag: half of a smooth point's quad (coverage from the `aa` varyings, `aa.rs`).
pub const F_AAPOINT: u8 = 16;
/// Flag: half of a smooth line's quad (coverage from the `aa` varyings, `aa.rs`).
pub const F_AALINE: u8 = 32;

/// `RPrim::cover`: the low four bits are the covered pixel centres.
pub const COVER_KNOWN: u8 = 0x10;

/// One primitive ready for the tile rasteriser.
#[derive(Clone, Copy, Debug)]
pub struct RPrim {
    /// Triangle, line or point.
    pub kind: PrimKind,
    /// `F_*` bits.
    pub flags: u8,
    /// Pixel bounding box `[x0, y0, x1, y1]`, inclusive, inside the framebuffer and scissor.
    pub bbox: [i32; 4],
    /// Material snapshot index (PHONG_WIN).
    pub mat: u32,
    /// Offset of this primitive's floats in the worker's pool.
    pub voff: u32,
    /// Triangle: the vertices' snapped window x, y (1/256 pixel), counter-clockwise.
    pub xy: [i32; 6],
    /// Triangle: bit k set when edge k (vertex k to k+1) owns the pixel centres exactly on it
    /// (the tie rule: left and bottom edges).
    pub owns: u8,
    /// Triangle with a bounding box of at most 2x2 pixels: `COVER_KNOWN` plus bit
    /// `2 * (y - bbox[1]) + (x - bbox[0])` for each pixel (x, y) whose centre it covers, as
    /// setup found them; 0 when the rasteriser must walk the edges.
    pub cover: u8,
    /// Window z: triangle plane `[z at bbox corner, dz/dx, dz/dy]`; point `[z, _, _]`. Single
    /// precision, as llvmpipe interpolates depth.
    pub z: [f32; 3],
}

impl RPrim {
    /// Triangle edge functions at pixel centres: `[E at pixel (0,0), dE/dx, dE/dy]` with the
    /// tie-break bias applied, so a centre is covered when all three are >= 0.
    #[inline(always)]
    pub fn edges(&self) -> [[i64; 3]; 3] {
        let v = [
            i64::from(self.xy[0]),
            i64::from(self.xy[1]),
            i64::from(self.xy[2]),
            i64::from(self.xy[3]),
            i64::from(self.xy[4]),
            i64::from(self.xy[5]),
        ];
        let edge = |k: usize, j: usize| {
            let (px, py) = (v[2 * k], v[2 * k + 1]);
            let (dx, dy) = (v[2 * j] - px, v[2 * j + 1] - py);
            let e00 = dx * (128 - py) - dy * (128 - px);
            let bias = i64::from(self.owns & (1 << k) == 0);
            [e00 - bias, -dy * 256, dx * 256]
        };
        [edge(0, 1), edge(1, 2), edge(2, 0)]
    }

    /// Whether triangle `self` may cover a pixel centre of `rect` (`[x0, y0, x1, y1]`,
    /// inclusive, inside its bounding box): false when one edge function (`edges`) is negative
    /// at every pixel of `rect`, its largest value being at a corner (exact, in i128). Then
    /// the rasteriser's walk of the rectangle's rows finds no span.
    #[inline(always)]
    pub fn may_reach(&self, rect: [i32; 4]) -> bool {
        let [x0, y0, x1, y1] = rect.map(i128::from);
        self.edges().iter().all(|e| {
            let [c, dx, dy] = e.map(i128::from);
            c + (dx * x0).max(dx * x1) + (dy * y0).max(dy * y1) >= 0
        })
    }
}

/// The per-flush constants of setup.
#[derive(Clone, Debug)]
pub struct SetupCtx {
    /// Processed vertex layout.
    pub layout: Layout,
    /// Varying layout.
    pub rl: RLayout,
    pub(super) clipper: Clipper,
    scale: [f64; 3],
    offset: [f64; 3],
    pub(super) ccw_front: bool,
    pub(super) cull: Option<u32>,
    pub(super) poly_mode: [u32; 2],
    pub(super) offset_on: [bool; 3],
    factor: f64,
    units: f64,
    pub(super) flat: bool,
    /// Quads split along their 1–3 diagonal rather than 0–2 (see `assembly::assemble`); set by
    /// the flush once the vertex stage has the clip codes.
    pub(super) quads_split_last: bool,
    pub(super) phong: bool,
    line_width: f32,
    /// The framebuffer height when lines are set up as llvmpipe sets them up in a window-system
    /// framebuffer (`State::y0_top`; see `line::parallelogram`).
    pub(super) line_flip: Option<f32>,
    /// LINE_STIPPLE enabled: (LINE_STIPPLE_PATTERN, LINE_STIPPLE_REPEAT).
    pub line_stipple: Option<(u16, i32)>,
    pub(super) point_size: f32,
    /// POINT_SMOOTH without POINT_SPRITE (Mesa turns smoothing off for sprites).
    pub(super) point_smooth: bool,
    /// LINE_SMOOTH.
    pub(super) line_smooth: bool,
    /// POINT_SPRITE: points are quads with the coordinates of `sprite_units` replaced.
    pub(super) sprite: bool,
    /// Varying offsets of the texture coordinates that COORD_REPLACE replaces.
    pub(super) sprite_units: [Option<usize>; MAX_TEXTURE_UNITS],
    /// POINT_SPRITE_COORD_ORIGIN is LOWER_LEFT.
    pub(super) sprite_lower_left: bool,
    /// Framebuffer ∩ scissor, inclusive.
    pub rect: [i32; 4],
    /// `rect` as `Win::cen` orders its bounds: `[x0, y0, -x1, -y1]` (negated saturating), so
    /// that cutting a bounding box to `rect` is one `max` per bound (`geom_wins`).
    rect_cen: [i32; 4],
    /// Tiles across.
    pub tiles_x: usize,
    /// Total tiles.
    pub tiles: usize,
    /// Unclipped triangles take `Worker::fast_tri`: FILL for both faces and no PHONG_WIN.
    fast: bool,
    /// Where each group of four varyings comes from, front face then back face (for
    /// `fast_tri`).
    gather: [[Gather4; TABLE]; 2],
}

/// Where one varying of a face comes from in a processed vertex.
#[derive(Clone, Copy, Debug)]
struct Gather {
    /// Offset in the processed vertex; out of range (`u32::MAX`) for a varying that stays 0.
    off: u32,
    /// A colour: taken from the provoking vertex under FLAT.
    colour: bool,
}

/// Groups of four varyings (k..k + 4, k a multiple of 4) that `emit_tri` builds planes for.
const GROUPS: usize = MAXV.div_ceil(4);

/// Entries of a `gather_table`: `GROUPS` rounded up to a power of two, the groups past
/// `GROUPS` varyings that stay 0, so that `fast_tri` finds group k / 4 at `(k / 4) % TABLE`
/// without a range check (an `and`; a check and its zero fallback were five instructions a
/// group).
const TABLE: usize = GROUPS.next_power_of_two();

/// Where the four varyings k..k + 4 of a face come from in a processed vertex.
#[derive(Clone, Copy, Debug)]
struct Gather4 {
    /// Offset of each in the processed vertex; out of range (`u32::MAX`) for one that stays 0.
    off: [u32; 4],
    /// The group's varyings (those below `RLayout::n`) sit one after another from `off[0]`,
    /// four floats inside the vertex: one load of four.
    run: bool,
    /// Colours (all four or none: the colours are groups of their own): taken from the
    /// provoking vertex under FLAT.
    colour: bool,
}

/// The varyings of a face as `Worker::varyings` fills them, for layouts without PHONG_WIN, in
/// groups of four.
fn gather_table(l: &Layout, rl: &RLayout, back: bool) -> [Gather4; TABLE] {
    let mut t = [Gather {
        off: u32::MAX,
        colour: false,
    }; MAXV];
    let mut set = |d: usize, s: usize, n: usize, colour: bool| {
        for i in 0..n {
            if let Some(g) = t.get_mut(d + i) {
                *g = Gather {
                    off: (s + i) as u32,
                    colour,
                };
            }
        }
    };
    let (col, spec) = match (back, l.col_b) {
        (true, Some(cb)) => (cb, l.spec_b),
        _ => (l.col, l.spec),
    };
    set(0, col, 4, true);
    if let (Some(d), Some(s)) = (rl.spec, spec) {
        set(d, s, 4, true);
    }
    for (&d, &s) in rl.tex.iter().zip(&l.tex) {
        if let (Some(d), Some(s)) = (d, s) {
            set(d, s, 4, false);
        }
    }
    if let (Some(d), Some(s)) = (rl.fog, l.fog) {
        set(d, s, 1, false);
    }
    std::array::from_fn(|g| {
        let k = 4 * g;
        let live = rl.n.min(MAXV).saturating_sub(k).min(4);
        let lane = |i: usize| t.get(k + i).copied();
        let off = std::array::from_fn(|i| lane(i).map_or(u32::MAX, |v| v.off));
        let o = off[0] as usize;
        let run = live > 0 && o + 4 <= l.stride && (0..live).all(|i| off[i] as usize == o + i);
        let colour = lane(0).is_some_and(|v| v.colour);
        debug_assert!(
            (0..live).all(|i| lane(i).is_some_and(|v| v.colour == colour)),
            "group {g} mixes colours and other varyings"
        );
        Gather4 { off, run, colour }
    })
}

/// The plane (value at the bounding box's corner, x slope, y slope) of a varying whose values
/// over w at the three vertices are `f`, `l` the vertices' barycentric planes: for one varying
/// (`f32`) or four, one per lane (`Vec4`: per lane the same multiplications and additions in
/// the same order, so the same bits; `plane_lanes_match_scalar`).
#[inline(always)]
fn plane<T: Copy + std::ops::Mul<Output = T> + std::ops::Add<Output = T>>(
    l: [[T; 3]; 3],
    f: [T; 3],
) -> [T; 3] {
    [
        f[0] * l[0][0] + f[1] * l[1][0] + f[2] * l[2][0],
        f[0] * l[0][1] + f[1] * l[1][1] + f[2] * l[2][1],
        f[0] * l[0][2] + f[1] * l[1][2] + f[2] * l[2][2],
    ]
}

/// Floats k..k + 4 of `s` (0 past its end).
#[inline(always)]
pub(super) fn load4(s: &[f32], k: usize) -> Vec4 {
    match s.get(k..k + 4).and_then(|a| <[f32; 4]>::try_from(a).ok()) {
        Some(a) => Vec4::from_array(a),
        None => Vec4::from_array(std::array::from_fn(|i| {
            s.get(k + i).copied().unwrap_or(0.0)
        })),
    }
}

/// Floats k..k + 4 of `s`, without a range check.
///
/// # Safety
/// `k + 4 <= s.len()`.
#[inline(always)]
unsafe fn load4_unchecked(s: &[f32], k: usize) -> Vec4 {
    debug_assert!(k + 4 <= s.len(), "load4_unchecked at {k} of {}", s.len());
    // SAFETY: floats k..k + 4 are inside `s` (the contract); an unaligned read of four f32.
    Vec4::from_array(unsafe { s.as_ptr().add(k).cast::<[f32; 4]>().read_unaligned() })
}

/// Four varyings' planes (`[value, x slope, y slope]`, one varying a lane) stored as the pool
/// holds them, varying by varying: `a.x, b.x, c.x, a.y, b.y, ...`. On x86-64 by nine SSE
/// shuffles and three stores of four (the array of twelve lanes was fourteen shuffles, a
/// blend and five stores).
#[inline(always)]
fn store_group(d: &mut [MaybeUninit<f32>; 12], [a, b, c]: [Vec4; 3]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{
            __m128, _mm_shuffle_ps, _mm_storeu_ps, _mm_unpackhi_ps, _mm_unpacklo_ps,
        };
        // SAFETY: SSE is part of the x86-64 baseline; the three stores write floats 0..4,
        // 4..8 and 8..12 of the twelve of `d` (no alignment needed).
        unsafe {
            let (a, b, c) = (__m128::from(a), __m128::from(b), __m128::from(c));
            let ab_lo = _mm_unpacklo_ps(a, b); // a0 b0 a1 b1
            let ab_hi = _mm_unpackhi_ps(a, b); // a2 b2 a3 b3
            let c0a1 = _mm_shuffle_ps::<0x50>(c, a); // c0 c0 a1 a1
            let b1c1 = _mm_shuffle_ps::<0x55>(b, c); // b1 b1 c1 c1
            let c2a3 = _mm_shuffle_ps::<0xAA>(c, ab_hi); // c2 c2 a3 a3
            let b3c3 = _mm_shuffle_ps::<0xFF>(ab_hi, c); // b3 b3 c3 c3
            let p = d.as_mut_ptr().cast::<f32>();
            _mm_storeu_ps(p, _mm_shuffle_ps::<0x84>(ab_lo, c0a1)); // a0 b0 c0 a1
            _mm_storeu_ps(p.add(4), _mm_shuffle_ps::<0x48>(b1c1, ab_hi)); // b1 c1 a2 b2
            _mm_storeu_ps(p.add(8), _mm_shuffle_ps::<0x88>(c2a3, b3c3)); // c2 a3 b3 c3
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let v = [a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z, a.w, b.w, c.w];
        for (d, s) in d.iter_mut().zip(v) {
            d.write(s);
        }
    }
}

impl SetupCtx {
    /// LineWidth.
    pub(super) fn line_width(&self) -> f32 {
        self.line_width
    }

    /// FLAT shading.
    pub(super) fn flat(&self) -> bool {
        self.flat
    }

    /// The setup constants of `state`.
    pub fn new(state: &State, layout: Layout, rect: [i32; 4], tiles: (usize, usize)) -> Self {
        let [vx, vy, vw, vh] = state.viewport.map(f64::from);
        let [n, f] = state.depth_range;
        let mut rl = RLayout::new(&layout);
        let point_smooth = state.enables.point_smooth && !state.enables.point_sprite;
        let line_smooth = state.enables.line_smooth;
        if point_smooth || line_smooth {
            rl.aa = Some(rl.n);
            rl.n += 4;
        }
        // The rasteriser's size, clamped to POINT_SIZE_MIN/MAX as Mesa's state tracker does.
        let p = &state.point;
        let point_size = if state.point_size < p.size_min {
            p.size_min
        } else if state.point_size > p.size_max {
            p.size_max
        } else {
            state.point_size
        };
        SetupCtx {
            layout,
            rl,
            clipper: Clipper::new(state, &layout),
            scale: [vw / 2.0, vh / 2.0, (f - n) / 2.0],
            offset: [vx + vw / 2.0, vy + vh / 2.0, (n + f) / 2.0],
            ccw_front: state.front_face != gl::CW,
            cull: state.enables.cull_face.then_some(state.cull_face_mode),
            poly_mode: state.polygon_mode,
            offset_on: [
                state.enables.polygon_offset_fill,
                state.enables.polygon_offset_line,
                state.enables.polygon_offset_point,
            ],
            factor: f64::from(state.polygon_offset_factor),
            units: f64::from(state.polygon_offset_units),
            flat: state.shade_model == gl::FLAT,
            quads_split_last: state.shade_model == gl::FLAT,
            phong: layout.nrm.is_some(),
            line_width: state.line_width,
            line_flip: state.y0_top.then_some(state.height as f32),
            line_stipple: state
                .enables
                .line_stipple
                .then_some((state.stipple.line_pattern, state.stipple.line_repeat)),
            point_size,
            point_smooth,
            line_smooth,
            sprite: state.enables.point_sprite,
            sprite_units: std::array::from_fn(|u| rl.tex[u].filter(|_| p.coord_replace[u])),
            sprite_lower_left: p.sprite_coord_origin == gl::LOWER_LEFT,
            rect,
            rect_cen: rect_cen(rect),
            tiles_x: tiles.0,
            tiles: tiles.0 * tiles.1,
            fast: state.polygon_mode == [gl::FILL; 2] && layout.nrm.is_none(),
            gather: [
                gather_table(&layout, &rl, false),
                gather_table(&layout, &rl, true),
            ],
        }
    }
}

/// A processed vertex's clip code and window coordinates (computed once per vertex by the
/// vertex stage; the window values are meaningful only when `code` is 0).
#[derive(Clone, Copy, Debug)]
pub struct Win {
    /// Window x before snapping.
    pub x: f32,
    /// Window y before snapping.
    pub y: f32,
    /// Snapped window x, y in 1/256 pixel.
    pub fx: i64,
    /// See `fx`.
    pub fy: i64,
    /// Window z.
    pub z: f64,
    /// 1 / w_clip.
    pub iw: f32,
    /// Outside-plane bits (`Clipper::code`).
    pub code: u16,
    /// The pixel centres this vertex bounds, from the snapped `fx`, `fy`: `[centre_lo(fx),
    /// centre_lo(fy), -centre_hi(fx), -centre_hi(fy)]`. Both functions are monotone, so a
    /// triangle's bounding box of centres is the minimum of its vertices' (`geom_wins`), without
    /// the per-triangle divisions of `geom`.
    pub cen: [i32; 4],
}

impl Default for Win {
    /// Zeros, with the `cen` of (0, 0) so that the record stays consistent.
    fn default() -> Self {
        Win {
            x: 0.0,
            y: 0.0,
            fx: 0,
            fy: 0,
            z: 0.0,
            iw: 0.0,
            code: 0,
            cen: cen(0, 0),
        }
    }
}

/// The first pixel whose centre (i + 0.5) is at or right of snapped coordinate `m` (1/256
/// pixel): `geom`'s `lo` in i32 (|m| <= 2^29 + 1 after `snap`, so nothing overflows; the shift
/// is the floor division `div_euclid(256)` is).
#[inline(always)]
fn centre_lo(m: i32) -> i32 {
    -((128 - m) >> 8)
}

/// The last pixel whose centre is at or left of `m`: `geom`'s `hi` in i32.
#[inline(always)]
fn centre_hi(m: i32) -> i32 {
    (m - 128) >> 8
}

/// `SetupCtx::rect_cen` of `rect`.
fn rect_cen(rect: [i32; 4]) -> [i32; 4] {
    [
        rect[0],
        rect[1],
        rect[2].saturating_neg(),
        rect[3].saturating_neg(),
    ]
}

/// `Win::cen` of snapped coordinates `fx`, `fy`.
#[inline(always)]
fn cen(fx: i32, fy: i32) -> [i32; 4] {
    [centre_lo(fx), centre_lo(fy), -centre_hi(fx), -centre_hi(fy)]
}

impl SetupCtx {
    /// Whether a run's strips take `Worker::directs_avx2` (with AVX2): a smooth layout whose
    /// only varyings are the colour, one run of four floats for either face (a lit dense
    /// mesh, whose small triangles `emit_colour_avx2` emits). Other layouts keep the strips'
    /// set-up inlined into `assemble_avx2`, as before.
    #[inline(always)]
    fn colour_strips(&self) -> bool {
        self.rl.n == 4 && !self.flat && self.gather[0][0].run && self.gather[1][0].run
    }

    /// Clip code, perspective divide and viewport/DepthRange transform (§2.11.1) of the
    /// processed vertex `v`, x and y snapped to 1/256 pixel.
    #[inline]
    pub fn win(&self, v: &[f32]) -> Win {
        let g = |i: usize| f64::from(v.get(i).copied().unwrap_or(0.0));
        let iw = 1.0 / g(3);
        let xw = g(0) * iw * self.scale[0] + self.offset[0];
        let yw = g(1) * iw * self.scale[1] + self.offset[1];
        let zw = g(2) * iw * self.scale[2] + self.offset[2];
        let (fx, fy) = (snap(xw), snap(yw));
        Win {
            x: xw as f32,
            y: yw as f32,
            fx: i64::from(fx),
            fy: i64::from(fy),
            z: zw,
            iw: iw as f32,
            code: self.clipper.code(v),
            cen: cen(fx, fy),
        }
    }

    /// [`SetupCtx::win`] of `N` vertices at once into `out` (its first `N` elements at most):
    /// `win_lanes`, then `WinLanes::put`. The vertex stage calls `win_lanes` and writes the
    /// records itself (a whole block at a time on AVX2); the tests compare this form with `win`.
    #[cfg(test)]
    #[inline(always)]
    pub fn win_block<const N: usize>(&self, c: &Lanes4<N>, e: &Lanes4<N>, out: &mut [Win]) {
        self.win_lanes(c, e).put(out);
    }

    /// [`SetupCtx::win`]'s values for `N` vertices at once, on arrays (`WinLanes`), from their
    /// clip positions `c` and eye positions `e` (read only under user clip planes): the same
    /// operations in the same order, so the same bits, on arrays that the compiler vectorises
    /// (the vertex stage calls this while the positions are in hand).
    // Lane loops index several arrays in lockstep (structure of arrays): indices read best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub(super) fn win_lanes<const N: usize>(&self, c: &Lanes4<N>, e: &Lanes4<N>) -> WinLanes<N> {
        let (mut xw, mut yw, mut zw, mut iw) = ([0.0f64; N], [0.0f64; N], [0.0f64; N], [0.0; N]);
        for i in 0..N {
            iw[i] = 1.0 / f64::from(c.w[i]);
            xw[i] = f64::from(c.x[i]) * iw[i] * self.scale[0] + self.offset[0];
            yw[i] = f64::from(c.y[i]) * iw[i] * self.scale[1] + self.offset[1];
            zw[i] = f64::from(c.z[i]) * iw[i] * self.scale[2] + self.offset[2];
        }
        let (mut fx, mut fy) = ([0i32; N], [0i32; N]);
        for i in 0..N {
            fx[i] = snap(xw[i]);
            fy[i] = snap(yw[i]);
        }
        let mut cn = [[0i32; 4]; N];
        for i in 0..N {
            cn[i] = cen(fx[i], fy[i]);
        }
        let mut code = [0u16; N];
        self.clipper.code_block(c, e, &mut code);
        WinLanes {
            xw,
            yw,
            zw,
            iw,
            fx,
            fy,
            cen: cn,
            code,
        }
    }
}

/// Window coordinate `x` snapped to 1/256 pixel. Rounds half away from zero with a cast
/// (f64::round is a libm call on baseline x86-64). The clamp to ±2^29 (±2M pixels) keeps every
/// edge-function product inside i64; only a viewport placed millions of pixels away could reach it.
/// The clamped value plus one half is below 2^31 in magnitude, so the cast is to i32, which
/// vectorises where a cast to i64 does not. A NaN gives 0 (what `as i32` gives it): it is
/// replaced by 0.0 before the cast, so that the cast is a plain truncation (`cvttpd2dq` in
/// lanes) rather than `as`'s saturating one, whose NaN and range fix-ups were ≈7 instructions a
/// coordinate in the vertex stage's `win_block` (`snap_is_the_saturating_cast` checks it).
#[inline(always)]
pub(super) fn snap(x: f64) -> i32 {
    let t = (x * 256.0).clamp(-SNAP_LIMIT, SNAP_LIMIT);
    let t = if t.is_nan() { 0.0 } else { t };
    // SAFETY: `t` is finite and |t| <= 2^29, so `t ± 0.5` truncates to a value inside i32.
    unsafe { (t + 0.5f64.copysign(t)).to_int_unchecked::<i32>() }
}

/// The processed vertices a run of set-up reads (`vout`, their window records `wins`, their
/// material indices `mats`), and whether `vout` holds every vertex that `wins` has a record
/// of, whole (`layout.stride` floats each): decided once a run (`Src::new`), so that
/// `Worker::fast_tri` reads a triangle's vertices, whose records `Worker::one_tri` has found,
/// without a range check. Always so: the vertex stage processes every vertex it writes a
/// record for.
#[derive(Clone, Copy)]
struct Src<'a> {
    vout: &'a [f32],
    wins: &'a [Win],
    mats: &'a [u32],
    /// `vout` holds every vertex of `wins` whole.
    whole: bool,
    /// Set up inside `Worker::assemble_avx2` or `Worker::run_avx2` (so on a CPU with AVX2):
    /// `fast_tri` may use AVX2 kernels. A constant in each build once inlined.
    wide: bool,
    /// Inside `Worker::directs_avx2` (so `wide` too): a strip's triangles take
    /// `Worker::strip_tri_avx2`. A constant in each build once inlined.
    lanes: bool,
}

impl<'a> Src<'a> {
    /// The run's vertices under `ctx` (its `layout.stride`), set up with AVX2 when `wide`.
    #[inline(always)]
    fn new(ctx: &SetupCtx, vout: &'a [f32], wins: &'a [Win], mats: &'a [u32], wide: bool) -> Self {
        let whole = wins
            .len()
            .checked_mul(ctx.layout.stride)
            .is_some_and(|n| n <= vout.len());
        Src {
            vout,
            wins,
            mats,
            whole,
            wide,
            lanes: false,
        }
    }
}

/// Strips, quad strips and fans: set up as they are assembled (`Worker::direct`).
#[inline(always)]
fn is_direct(p: &Prim) -> bool {
    matches!(
        p.mode,
        gl::TRIANGLE_STRIP | gl::QUAD_STRIP | gl::TRIANGLE_FAN
    )
}

/// The span `[lo, hi)` of `idx` from the first of `prims` to the end of the last (a run of
/// set-up's primitives, which come in order), when each of its indices is below `n` (the
/// vertices with a record), else an empty span: found by one maximum over the span (a few
/// vector instructions for eight indices) where each strip checked its own (four
/// instructions a vertex).
fn checked_span(idx: &[u32], prims: &[Prim], n: usize) -> [usize; 2] {
    let (Some(a), Some(z)) = (prims.first(), prims.last()) else {
        return [0, 0];
    };
    let (lo, hi) = (a.first as usize, z.first as usize + z.count as usize);
    match idx.get(lo..hi) {
        Some(ix) if (ix.iter().fold(0, |m, &u| m.max(u)) as usize) < n => [lo, hi],
        _ => [0, 0],
    }
}

/// A vertex in window coordinates with its varyings.
#[derive(Clone, Copy, Debug)]
pub(super) struct WVert {
    /// Window x, y before snapping (line setup works from these, as llvmpipe does).
    pub(super) x: f32,
    pub(super) y: f32,
    /// Snapped x, y in 1/256 pixel.
    pub(super) fx: i64,
    pub(super) fy: i64,
    pub(super) z: f64,
    pub(super) iw: f32,
    pub(super) v: [f32; MAXV],
    /// The point size of this vertex under distance attenuation (0: the context's).
    pub(super) ps: f32,
}

/// One setup worker's output: its primitives in order, their floats, and per-tile bins. Several
/// workers split a batch's primitives in order; the rasteriser visits worker 0's bin of a tile,
/// then worker 1's, ..., which preserves primitive order inside every tile.
#[derive(Debug, Default)]
pub struct Worker {
    /// Rasterisable primitives.
    pub prims: Vec<RPrim>,
    /// Their attribute floats.
    pub pool: Vec<f32>,
    /// Per tile, indices into `prims`.
    pub bins: Vec<Vec<u32>>,
    /// The tiles whose bins are not empty, in the order they were first reached: what the
    /// rasteriser visits and the next run empties, so that neither walks every tile of the
    /// framebuffer for a flush that reaches a few.
    pub touched: Vec<u32>,
    /// The pixels of its primitives' bounding boxes, summed: the rasteriser's estimate of the
    /// work, to decide whether handing the tiles to the pool pays.
    pub area: u64,
    pub(super) a: Vec<f32>,
    pub(super) b: Vec<f32>,
    bins_x: usize,
    asm: Vec<Asm>,
    /// The line stipple counter (`line.rs`), carried from segment to segment of a primitive.
    pub(super) stipple_counter: i64,
}

impl Worker {
    /// Assembles `prims` of batch `b` (§2.6) and sets them up ([`Worker::assemble_body`]),
    /// compiled for the baseline or with AVX2 by `Route::best` (the same code, so the same
    /// primitives; `both_routes_set_up_the_same_primitives` compares them).
    pub fn assemble_and_run(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        b: &Batch,
        prims: &[Prim],
    ) {
        self.assemble_by(ctx, vout, wins, b, prims, Route::best());
    }

    /// [`Worker::assemble_and_run`] by `route`.
    pub(super) fn assemble_by(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        b: &Batch,
        prims: &[Prim],
        route: Route,
    ) {
        #[cfg(target_arch = "x86_64")]
        if route == Route::Avx2 {
            // SAFETY: `Route::Avx2` is chosen only where the CPU has AVX2.
            unsafe { self.assemble_avx2(ctx, vout, wins, b, prims) };
            return;
        }
        let _ = route;
        self.assemble_body(ctx, vout, wins, b, prims, false);
    }

    /// [`Worker::assemble_body`] compiled with AVX2.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn assemble_avx2(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        b: &Batch,
        prims: &[Prim],
    ) {
        self.assemble_body(ctx, vout, wins, b, prims, true);
    }

    /// Assembles `prims` of batch `b` (§2.6) and sets them up (`wide`: see `Src::wide`).
    #[inline(always)]
    fn assemble_body(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        b: &Batch,
        prims: &[Prim],
        wide: bool,
    ) {
        self.start(ctx);
        let src = Src::new(ctx, vout, wins, &b.mat, wide);
        let known = checked_span(&b.idx, prims, wins.len());
        let mut asm = std::mem::take(&mut self.asm);
        let mut rest = prims;
        // Strips, quad strips and fans (a mesh's and a quadric's usual primitives) are set up
        // as they are assembled (`directs`), without the round trip through `asm`. Runs of
        // other primitives go through `assemble`.
        // (One pass: each primitive is looked at once, a run of others measured where it
        // starts; a scan for the run of direct ones first was 13 instructions a strip.)
        while let Some(p) = rest.first() {
            if is_direct(p) {
                #[cfg(target_arch = "x86_64")]
                if wide && p.mode == gl::TRIANGLE_STRIP && ctx.colour_strips() {
                    // SAFETY: `wide`: this runs inside `assemble_avx2`, which `Route::Avx2`
                    // chooses only where the CPU has AVX2.
                    rest = unsafe { self.directs_avx2(ctx, src, rest, (&b.idx, known)) };
                    continue;
                }
                rest = self.directs(ctx, src, &b.idx, known, rest, is_direct);
                continue;
            }
            let others = rest.iter().position(is_direct).unwrap_or(rest.len());
            let (now, after) = rest.split_at(others);
            super::assembly::assemble(now, &b.idx, b.edge(), ctx.quads_split_last, &mut asm);
            for p in &asm {
                self.one(ctx, src, p);
            }
            rest = after;
        }
        self.asm = asm;
    }

    /// Sets up the run of direct primitives (`is_direct`) of kinds `kind` that `prims` starts
    /// with, one by one (`direct`); returns the primitives after it.
    #[inline(always)]
    fn directs<'p>(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        idx: &[u32],
        known: [usize; 2],
        prims: &'p [Prim],
        kind: impl Fn(&Prim) -> bool,
    ) -> &'p [Prim] {
        let mut rest = prims;
        while let Some((p, after)) = rest.split_first() {
            if !kind(p) {
                break;
            }
            self.direct(ctx, src, idx, known, p);
            rest = after;
        }
        rest
    }

    /// [`Worker::directs`] of a run of triangle strips (`idx` and `known` as for `direct`) of
    /// a colour-only layout (`SetupCtx::colour_strips`) compiled with AVX2, a function of its
    /// own (`inline(never)`), whose strips take `strip_tri_avx2`: a dense mesh's set-up,
    /// compiled apart from `assemble_avx2`'s
    /// other routes and from `run_avx2` (with `fast_tri`, inlined into both, a change to one
    /// route moved the other's code by ±0.2–1.5M instructions on display-list and
    /// sphere-subdivision), and its loop keeps its registers. A call a run of direct
    /// primitives, not a strip (a gauss-smooth-400 frame has 160k strips of two triangles).
    ///
    /// # Safety
    /// The CPU must have AVX2; `src.wide`.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn directs_avx2<'p>(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        prims: &'p [Prim],
        (idx, known): (&[u32], [usize; 2]),
    ) -> &'p [Prim] {
        let src = Src { lanes: true, ..src };
        self.directs(ctx, src, idx, known, prims, |p| {
            p.mode == gl::TRIANGLE_STRIP
        })
    }

    /// Assembles and sets up the triangle strip, quad strip or fan `p` (§2.6.1) as
    /// `assembly::assemble` makes their triangles, in its order, with its vertices, provoking
    /// vertex and edge flags: strip triangle i (i + 2 its provoking vertex) is given vertices
    /// (i, i + 1, i + 2), its first two swapped when i is odd; quad i of a quad strip is
    /// (2i + 2, 2i, 2i + 3) and (2i, 2i + 1, 2i + 3), provoking vertex 2i + 3; fan triangle i
    /// is (0, i + 1, i + 2), provoking vertex i + 2. `idx` maps given vertices to unique ones;
    /// each is mapped and its record found once, as it enters (a triangle at a time through
    /// `assemble`, three lookups each). `known`: a span of `idx` whose indices all have
    /// records (`checked_span`).
    #[inline(always)]
    fn direct(&mut self, ctx: &SetupCtx, src: Src, idx: &[u32], known: [usize; 2], p: &Prim) {
        let vert = |i: u32| {
            let u = idx.get(i as usize).copied().unwrap_or(u32::MAX);
            (u, src.wins.get(u as usize))
        };
        let (f, n) = (p.first, p.count);
        // (Each `one_tri` below: every vertex is `vert`'s, its record `src.wins.get` of its
        // index.)
        match p.mode {
            gl::TRIANGLE_STRIP if n >= 3 => {
                // Every record in range (so always: the vertex stage writes one for every
                // vertex of the batch), by `strip`: known for the run, else checked here.
                let (lo, hi) = (f as usize, f as usize + n as usize);
                if let Some(ix) = idx.get(lo..hi) {
                    let inside = known[0] <= lo && hi <= known[1];
                    if inside || ix.iter().all(|&u| (u as usize) < src.wins.len()) {
                        // SAFETY: each of `ix` is below `src.wins.len()`: inside `known`
                        // (`checked_span`), or just checked.
                        unsafe { self.strip(ctx, src, ix) };
                        return;
                    }
                }
                let (mut a, mut b) = (vert(f), vert(f + 1));
                for i in 0..n - 2 {
                    let c = vert(f + i + 2);
                    let v = if i % 2 == 0 { [a, b, c] } else { [b, a, c] };
                    // SAFETY: `vert`'s vertices (see above).
                    unsafe { self.one_tri(ctx, src, v, c.0, ALL_EDGES) };
                    (a, b) = (b, c);
                }
            }
            gl::QUAD_STRIP if n >= 4 => {
                let [e0, e1] = QUAD_STRIP_EDGES;
                let (mut a, mut b) = (vert(f), vert(f + 1));
                for i in 0..n / 2 - 1 {
                    let q = f + 2 * i;
                    let (c, d) = (vert(q + 2), vert(q + 3));
                    // SAFETY: `vert`'s vertices (see above).
                    unsafe { self.one_tri(ctx, src, [c, a, d], d.0, e0) };
                    // SAFETY: `vert`'s vertices (see above).
                    unsafe { self.one_tri(ctx, src, [a, b, d], d.0, e1) };
                    (a, b) = (c, d);
                }
            }
            gl::TRIANGLE_FAN if n >= 3 => {
                let (a, mut b) = (vert(f), vert(f + 1));
                for i in 0..n - 2 {
                    let c = vert(f + i + 2);
                    // SAFETY: `vert`'s vertices (see above).
                    unsafe { self.one_tri(ctx, src, [a, b, c], c.0, ALL_EDGES) };
                    b = c;
                }
            }
            _ => {}
        }
    }

    /// Sets up the triangle strip of vertices `ix` as `direct` does, its records read without
    /// a range check: triangle i is window i of three, its first two swapped when i is odd, so
    /// that the loop keeps only its place in `ix` (the per-triangle `Option`s and the two
    /// vertices carried from step to step, through the stack, were ≈40 instructions a
    /// triangle on a dense mesh). One call site: two (a step of two triangles) doubled the
    /// inlined set-up and pushed its helpers out of line.
    ///
    /// # Safety
    /// Each of `ix` is below `src.wins.len()`.
    #[inline(always)]
    unsafe fn strip(&mut self, ctx: &SetupCtx, src: Src, ix: &[u32]) {
        let w = |u: u32| {
            debug_assert!((u as usize) < src.wins.len(), "vertex {u} has no record");
            // SAFETY: `u` is one of `ix`, each below `src.wins.len()` (the contract).
            (u, unsafe { src.wins.get_unchecked(u as usize) })
        };
        for (i, t) in ix.windows(3).enumerate() {
            let &[x, y, z] = t else {
                continue;
            };
            let (a, b) = if i % 2 == 0 { (x, y) } else { (y, x) };
            // SAFETY: `w`'s records are `src.wins`'s of their indices.
            unsafe { self.found_tri::<true>(ctx, src, [w(a), w(b), w(z)], z, ALL_EDGES) };
        }
    }

    /// Sets up `asm` (indices into `vout`; `wins` the vertices' clip codes and window
    /// coordinates, `mats` their material indices), compiled for the baseline or with AVX2 by
    /// `Route::best` as [`Worker::assemble_and_run`] is (the same code, so the same
    /// primitives; `both_routes_set_up_the_same_primitives` compares them).
    pub fn run(&mut self, ctx: &SetupCtx, vout: &[f32], wins: &[Win], mats: &[u32], asm: &[Asm]) {
        self.run_by(ctx, vout, wins, mats, asm, Route::best());
    }

    /// [`Worker::run`] by `route`.
    pub(super) fn run_by(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        mats: &[u32],
        asm: &[Asm],
        route: Route,
    ) {
        #[cfg(target_arch = "x86_64")]
        if route == Route::Avx2 {
            // SAFETY: `Route::Avx2` is chosen only where the CPU has AVX2.
            unsafe { self.run_avx2(ctx, vout, wins, mats, asm) };
            return;
        }
        let _ = route;
        self.run_body(ctx, Src::new(ctx, vout, wins, mats, false), asm);
    }

    /// [`Worker::run_body`] compiled with AVX2.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_avx2(
        &mut self,
        ctx: &SetupCtx,
        vout: &[f32],
        wins: &[Win],
        mats: &[u32],
        asm: &[Asm],
    ) {
        self.run_body(ctx, Src::new(ctx, vout, wins, mats, true), asm);
    }

    /// Sets up `asm` of the vertices `src`.
    #[inline(always)]
    fn run_body(&mut self, ctx: &SetupCtx, src: Src, asm: &[Asm]) {
        self.start(ctx);
        for p in asm {
            self.one(ctx, src, p);
        }
    }

    /// Lets go of the memory of its outputs beyond what a small flush needs (after the
    /// rasteriser has visited them; the next run starts them again).
    pub fn trim(&mut self) {
        const KEEP: usize = 1 << 12;
        self.empty();
        self.prims.shrink_to(KEEP);
        self.pool.shrink_to(8 * KEEP);
        self.a.shrink_to(KEEP);
        self.b.shrink_to(KEEP);
        self.asm.shrink_to(KEEP);
    }

    /// Empties the outputs for a new run.
    fn start(&mut self, ctx: &SetupCtx) {
        self.empty();
        // Every bin is empty now: those not touched were emptied by the run that filled them.
        debug_assert!(self.bins.iter().all(Vec::is_empty), "a bin not emptied");
        self.bins.resize_with(ctx.tiles, Vec::new);
        self.bins_x = ctx.tiles_x;
    }

    /// Empties the primitives and the bins they reached.
    fn empty(&mut self) {
        self.prims.clear();
        self.pool.clear();
        for &t in &self.touched {
            if let Some(b) = self.bins.get_mut(t as usize) {
                b.clear();
            }
        }
        self.touched.clear();
        self.area = 0;
    }

    /// Sets up one assembled primitive `p` of the run's vertices `src`: the triangle by
    /// `one_tri`, everything else out of line in `general`.
    #[inline(always)]
    fn one(&mut self, ctx: &SetupCtx, src: Src, p: &Asm) {
        if p.n == 3 {
            let v = p.v.map(|i| (i, src.wins.get(i as usize)));
            // SAFETY: each record is `src.wins.get` of its index.
            unsafe { self.one_tri(ctx, src, v, p.provoking, p.edges) };
            return;
        }
        self.general(ctx, src.vout, src.wins, src.mats, p);
    }

    /// Sets up the assembled triangle of vertices `v` of `src` (each its index and its record,
    /// `None` past the end of `src.wins`), provoking vertex `provoking` and edge flags `edges`:
    /// dropped when a record is missing or all three vertices are outside one clip plane, set
    /// up by `fast_tri` when it can be, else by `general`.
    ///
    /// # Safety
    /// Each record of `v` is `src.wins.get` of its index.
    #[inline(always)]
    unsafe fn one_tri(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        v: [(u32, Option<&Win>); 3],
        provoking: u32,
        edges: u8,
    ) {
        let [(a, Some(wa)), (b, Some(wb)), (c, Some(wc))] = v else {
            return;
        };
        // SAFETY: each record is `src.wins.get` of its index (the contract).
        unsafe { self.found_tri::<false>(ctx, src, [(a, wa), (b, wb), (c, wc)], provoking, edges) };
    }

    /// [`Worker::one_tri`] of a triangle whose three records `v` were found; a strip's
    /// (`STRIP`) with AVX2 (`src.wide`) by `strip_tri_avx2`, every other by `fast_tri`.
    ///
    /// # Safety
    /// Each record of `v` is `src.wins[i]` of its index i.
    #[inline(always)]
    unsafe fn found_tri<const STRIP: bool>(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        v: [(u32, &Win); 3],
        provoking: u32,
        edges: u8,
    ) {
        let [(a, wa), (b, wb), (c, wc)] = v;
        if wa.code & wb.code & wc.code != 0 {
            return;
        }
        let ids = [a, b, c];
        if ctx.fast && src.whole && wa.code | wb.code | wc.code == 0 {
            #[cfg(target_arch = "x86_64")]
            if STRIP && src.lanes {
                // SAFETY: as for `fast_tri` below; `src.wide`: compiled for AVX2 and run
                // only where the CPU has it.
                unsafe { self.strip_tri_avx2(ctx, src, v, provoking) };
                return;
            }
            // SAFETY: `src.whole`: `src.vout` holds every vertex of `src.wins` whole, and `ids`
            // are indices of `src.wins` (the contract; their records were found).
            unsafe { self.fast_tri(ctx, src, [wa, wb, wc], ids, provoking) };
            return;
        }
        let p = Asm {
            n: 3,
            edges,
            v: ids,
            provoking,
        };
        self.general(ctx, src.vout, src.wins, src.mats, &p);
    }

    /// The common triangle (no clipping, FILL for both faces, no PHONG_WIN) straight from the
    /// vertex stage's output: facing, culling and the coverage reject use only the window
    /// records `w` of vertices `ids`; varyings are read from `vout` only for a triangle that may
    /// cover a pixel centre. Produces exactly what `polygon::<3>` and `tri` produce.
    ///
    /// With AVX2 (`src.wide`) a box of at most 2x2 pixels is placed and its coverage found
    /// in vector lanes (`geom_small_avx2`).
    ///
    /// # Safety
    /// `src.vout` holds `(ids[j] + 1) * ctx.layout.stride` floats at least, for each j.
    #[inline(always)]
    unsafe fn fast_tri(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        w: [&Win; 3],
        ids: [u32; 3],
        provoking: u32,
    ) {
        let Some(bbox) = wins_bbox(&ctx.rect_cen, w) else {
            return;
        };
        let p = [[w[0].fx, w[0].fy], [w[1].fx, w[1].fy], [w[2].fx, w[2].fy]];
        let area = doubled_area(p);
        let Some(front) = facing(ctx, area) else {
            return;
        };
        #[cfg(target_arch = "x86_64")]
        let small = if src.wide {
            // SAFETY: `src.wide`: this runs inside `assemble_avx2` or `run_avx2`, which
            // `Route::Avx2` chooses only where the CPU has AVX2.
            unsafe { geom_small_lanes_avx2(bbox, p, area) }
        } else {
            None
        };
        #[cfg(not(target_arch = "x86_64"))]
        let small = None;
        // SAFETY: the caller's contract (`fast_tri`'s).
        unsafe { self.fast_tri_placed(ctx, src, p, area, front, bbox, w, ids, provoking, small) };
    }

    /// A strip's `fast_tri` with AVX2 (inside `directs_avx2` only) of the vertices `v` (each
    /// its index and its record): the box and its size class from the records in lanes
    /// (`strip_lanes_avx2`), the area as `fast_tri`'s; a box of at most 2x2 placed by
    /// `small_p_avx2`, the rest as `fast_tri` (`fast_tri_placed`). The same primitives
    /// (`strip_route_is_fast_tri`).
    ///
    /// # Safety
    /// As for `fast_tri` (`ids` the indices of `v`), and the CPU must have AVX2, the caller be
    /// compiled for it.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn strip_tri_avx2(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        v: [(u32, &Win); 3],
        provoking: u32,
    ) {
        let [(a, wa), (b, wb), (c, wc)] = v;
        let (w, ids) = ([wa, wb, wc], [a, b, c]);
        // SAFETY: the CPU has AVX2 (the contract).
        let Some(sl) = (unsafe { strip_lanes_avx2(&ctx.rect_cen, w) }) else {
            return;
        };
        let p = [[w[0].fx, w[0].fy], [w[1].fx, w[1].fy], [w[2].fx, w[2].fy]];
        let area = doubled_area(p);
        let Some(front) = facing(ctx, area) else {
            return;
        };
        if !sl.small {
            // (Its own call, with `small` a constant `None`: the larger triangle's route
            // without the small one's arm. Joined with it, ≈6M more on gauss-smooth-400;
            // `fast_tri` from the records again, ≈+0.3% on gauss-smooth-40, +0.6% on
            // materials.)
            // SAFETY: the caller's contract (`fast_tri`'s).
            unsafe {
                self.fast_tri_placed(ctx, src, p, area, front, sl.bbox, w, ids, provoking, None)
            };
            return;
        }
        // SAFETY: the CPU has AVX2 (the contract); `sl`'s box is at most 2x2.
        let small = Some(unsafe { small_p_avx2(sl.bbox, p, area) });
        // SAFETY: the caller's contract (`fast_tri`'s).
        unsafe {
            self.fast_tri_placed(ctx, src, p, area, front, sl.bbox, w, ids, provoking, small)
        };
    }

    /// The rest of `fast_tri` once the triangle `p` (records `w`, vertices `ids`) is found
    /// inside box `bbox` with doubled signed area `area` (not 0) and facing `front`, and
    /// placed by `small` when its box is at most 2x2 (with AVX2).
    ///
    /// # Safety
    /// As for `fast_tri`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    unsafe fn fast_tri_placed(
        &mut self,
        ctx: &SetupCtx,
        src: Src,
        p: [[i64; 2]; 3],
        area: i64,
        front: bool,
        bbox: [i32; 4],
        w: [&Win; 3],
        ids: [u32; 3],
        provoking: u32,
        small: Option<(Geom, u8, EdgeLanes)>,
    ) {
        let (vout, mats) = (src.vout, src.mats);
        let back = !front;
        let s = ctx.layout.stride;
        let (g, cover) = match small {
            Some((mut g, cover, l)) => {
                // (The cover tested and a colour-only triangle emitted here, before the join
                // with the other route, so that its edges leave their lanes only for the other
                // layouts; and nothing it needs computed before the test, where it cost every
                // triangle with a box ≈14 instructions.)
                if cover == COVER_KNOWN {
                    return;
                }
                #[cfg(target_arch = "x86_64")]
                if ctx.rl.n == 4 && !ctx.flat && ctx.gather[usize::from(back)][0].run {
                    let o = ctx.gather[usize::from(back)][0].off[0] as usize;
                    // SAFETY: the caller's contract (`fast_tri`'s).
                    let (z, iw, vs) = unsafe { ccw_verts(g.swapped, w, ids, vout, s) };
                    // SAFETY: `run`: `o + 4 <= stride` (see `colour4`).
                    let q = unsafe { colour4(vs, o) };
                    let flags = if back { F_BACK } else { 0 };
                    let mat = mats.get(provoking as usize).copied().unwrap_or(0);
                    // SAFETY: `l` comes from `geom_small_avx2`, called under `src.wide`
                    // only (see above): the CPU has AVX2 and this code is compiled for it.
                    unsafe { self.emit_colour_avx2(ctx, &g, &l, z, iw, flags, mat, q, cover) };
                    return;
                }
                #[cfg(not(target_arch = "x86_64"))]
                let _ = l;
                // `Geom::v` counter-clockwise for the other layouts only (see
                // `geom_small_lanes_avx2`).
                g.v = ccw(p, area).1;
                (g, cover)
            }
            None => {
                let g = geom_placed(bbox, p, area);
                let cover = g.coverage();
                (g, cover)
            }
        };
        if cover == COVER_KNOWN {
            return;
        }
        let mut flags = if back { F_BACK } else { 0 };
        if ctx.flat {
            flags |= F_FLAT;
        }
        let mat = mats.get(provoking as usize).copied().unwrap_or(0);
        let table = &ctx.gather[usize::from(back)];
        let flat = ctx.flat;
        // SAFETY: the caller's contract (`fast_tri`'s).
        let (z, iw, vs) = unsafe { ccw_verts(g.swapped, w, ids, vout, s) };
        if ctx.rl.n == 4 && !flat && table[0].run {
            // The colour alone, smooth (the common dense mesh).
            // SAFETY: `run`: `o + 4 <= stride` (see `colour4`).
            let q = unsafe { colour4(vs, table[0].off[0] as usize) };
            let a = q[0];
            self.emit_tri(ctx, &g, z, iw, flags, mat, |_| a, |j, _| q[j], cover);
            return;
        }
        // The provoking vertex only under FLAT (the only case `flat4` reads it), with a range
        // check (not one of `ids` to the type system).
        let prov = if flat {
            let i = provoking as usize;
            vout.get(i * s..(i + 1) * s).unwrap_or(&[])
        } else {
            &[][..]
        };
        // Varyings k..k + 4 of vertex j: colours from the provoking vertex under FLAT; a run
        // of four floats in one load, otherwise one float each.
        let get4 = |src: &[f32], t: &Gather4| {
            if t.run {
                return load4(src, t.off[0] as usize);
            }
            Vec4::from_array(t.off.map(|o| src.get(o as usize).copied().unwrap_or(0.0)))
        };
        // Group k / 4 (`emit_tri` asks for k below `rl.n`, at most `MAXV`, so the modulo is
        // k / 4 itself).
        let group = |k: usize| {
            debug_assert!(k < MAXV, "varying {k} past MAXV");
            &table[(k / 4) % TABLE]
        };
        let flat4 = |k: usize| {
            let t = group(k);
            get4(if t.colour && flat { prov } else { vs[0] }, t)
        };
        // `emit_tri` asks `var4` for the groups it divides by w only (k >= its `nflat`), never
        // the colours under FLAT (those are its flat groups): always vertex j's own floats.
        let var4 = |j: usize, k: usize| {
            let t = group(k);
            debug_assert!(!(t.colour && flat), "a FLAT colour group divided");
            let src = vs[j];
            if t.run {
                // SAFETY: `src` holds the vertex's `s` = `layout.stride` floats (`vert`);
                // `run`: `off[0] + 4 <= stride` (`gather_table`, of this layout).
                return unsafe { load4_unchecked(src, t.off[0] as usize) };
            }
            get4(src, t)
        };
        self.emit_tri(ctx, &g, z, iw, flags, mat, flat4, var4, cover);
    }

    /// Emits the triangle placed by `g` (vertices in `g.v`'s counter-clockwise order, `z` and
    /// `iw` their window z and 1/w, `var4(j, k)` varyings k..k + 4 of vertex j, k a multiple
    /// of 4, lanes past the last varying anything, asked for the varyings divided by w only;
    /// `flat4(k)` the same of the flat varyings under `F_FLAT` (the colours, k below 4 or 8),
    /// the value the whole triangle takes; `cover` from `Geom::coverage`): barycentric
    /// planes, depth plane, one plane per varying, and the primitive.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn emit_tri(
        &mut self,
        ctx: &SetupCtx,
        g: &Geom,
        z: [f64; 3],
        iw: [f32; 3],
        flags: u8,
        mat: u32,
        flat4: impl Fn(usize) -> Vec4,
        var4: impl Fn(usize, usize) -> Vec4,
        cover: u8,
    ) {
        // Room for the planes first, before any float is computed: the call that may grow the
        // pool clobbers every vector register, and the barycentric planes, live across it,
        // went through the stack (≈25 instructions a triangle).
        let n = ctx.rl.n.min(MAXV);
        let voff = self.pool.len();
        let len = 3 * (n + 1);
        self.pool.reserve(len);
        let area = g.area;
        let mut lam = [[0f64; 3]; 3];
        let inv = 1.0 / area as f64;
        for k in 0..3 {
            let [dx, dy] = g.d[k];
            // Barycentric of the vertex opposite edge k, relative to the bbox corner.
            lam[(k + 2) % 3] = [
                g.e[k] as f64 * inv,
                (-dy * 256) as f64 * inv,
                (dx * 256) as f64 * inv,
            ];
        }
        let mut zp = [0.0f64; 3];
        for (j, zj) in zp.iter_mut().enumerate() {
            *zj = z[0] * lam[0][j] + z[1] * lam[1][j] + z[2] * lam[2][j];
        }
        if ctx.offset_on[0] {
            zp[0] += offset(ctx, zp[1], zp[2]);
        }
        let zp = [zp[0] as f32, zp[1] as f32, zp[2] as f32];
        // Varying planes in f32: relative to the bbox corner the values stay small. (Kept as
        // nine scalars: built as an array, its rows went through the stack and were reloaded
        // as vectors, a store-forwarding stall.)
        let l32 = [
            [lam[0][0] as f32, lam[0][1] as f32, lam[0][2] as f32],
            [lam[1][0] as f32, lam[1][1] as f32, lam[1][2] as f32],
            [lam[2][0] as f32, lam[2][1] as f32, lam[2][2] as f32],
        ];
        let nflat = if flags & F_FLAT != 0 {
            ctx.rl.spec.map_or(4, |s| s + 4)
        } else {
            0
        };
        let spare = self.pool.spare_capacity_mut();
        debug_assert!(spare.len() >= len, "pool not reserved");
        // SAFETY: `reserve(len)` above left room for `len` more floats (a second range check
        // here reloaded the pool's length and capacity, ≈5 instructions a triangle).
        let out = unsafe { spare.get_unchecked_mut(..len) };
        let (head, planes) = out.split_at_mut(3);
        for (d, s) in head.iter_mut().zip(plane(l32, iw)) {
            d.write(s);
        }
        // Four varyings at a time, one per SIMD lane: per lane the same multiplications and
        // additions in the same order as `plane`, so the same bits. FLAT's (k < nflat, a
        // multiple of 4, whole groups) keep vertex 0's value and slopes of 0; then the whole
        // groups divided, each stored as three vectors (`store_group`); then the last
        // varyings (fewer than four, never flat) one by one.
        let l4 = l32.map(|r| r.map(Vec4::splat));
        let iw4 = iw.map(Vec4::splat);
        // (Walked by `split_first_chunk_mut`: `chunks_mut(12)` and the counts of the groups
        // cost divisions by 12 and 3 a triangle, ≈8 instructions a colour-only triangle.)
        let mut rest = planes;
        let mut k = 0;
        // (The `else` arms below never run, so no float is left unwritten: `nflat`, a multiple
        // of 4, is at most `n` (4 with the colour, 8 with the secondary colour after it), and
        // the divided loop checks the length first.)
        while k < nflat {
            let Some((c, r)) = std::mem::take(&mut rest).split_first_chunk_mut::<12>() else {
                break;
            };
            store_group(c, [flat4(k), Vec4::ZERO, Vec4::ZERO]);
            (rest, k) = (r, k + 4);
        }
        while !rest.is_empty() {
            let f = [
                var4(0, k) * iw4[0],
                var4(1, k) * iw4[1],
                var4(2, k) * iw4[2],
            ];
            let pl = plane(l4, f);
            if rest.len() < 12 {
                let [p0, px, py] = pl;
                let a = [
                    p0.x, px.x, py.x, p0.y, px.y, py.y, p0.z, px.z, py.z, p0.w, px.w, py.w,
                ];
                for (d, s) in rest.iter_mut().zip(a) {
                    d.write(s);
                }
                break;
            }
            let Some((c, r)) = std::mem::take(&mut rest).split_first_chunk_mut::<12>() else {
                break;
            };
            store_group(c, pl);
            (rest, k) = (r, k + 4);
        }
        // SAFETY: `reserve` made room for `len` more floats, and every one of them was written
        // above (`head`, and each chunk of `planes` whole).
        unsafe { self.pool.set_len(voff + len) };
        let v = g.v;
        let xy = [
            v[0][0] as i32,
            v[0][1] as i32,
            v[1][0] as i32,
            v[1][1] as i32,
            v[2][0] as i32,
            v[2][1] as i32,
        ];
        self.push_tri(g, xy, flags, mat, voff, cover, zp);
    }

    /// Pushes the triangle placed by `g` (`xy` its vertices as `RPrim::xy`) whose floats start
    /// at `voff` in the pool (see `emit_tri`), `zp` its depth plane.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn push_tri(
        &mut self,
        g: &Geom,
        xy: [i32; 6],
        flags: u8,
        mat: u32,
        voff: usize,
        cover: u8,
        zp: [f32; 3],
    ) {
        self.push(RPrim {
            kind: PrimKind::Tri,
            flags,
            bbox: g.bbox,
            mat,
            voff: voff as u32,
            xy,
            owns: g.owns,
            cover,
            z: zp,
        });
    }

    /// `emit_tri` of a smooth triangle whose only varyings are the colour (`q[j]` vertex j's
    /// four floats, `g.v`'s order), placed by `geom_small_avx2` (`l` its edges, lane k edge
    /// k): the same floats, computed in lanes. The barycentric planes are built with lane j
    /// the plane's term j (value, x slope, y slope) from the edges' lanes converted at once
    /// (`i64_lanes_f64`, `small_lanes_f64`) and transposed, so the depth and 1/w planes take
    /// three multiplications and two additions of vectors; `emit_tri` stored the edges out
    /// of their lanes and converted and multiplied nine scalars (≈60 instructions). Each
    /// value takes `emit_tri`'s operations in its order: `(dx·256) as f64 · inv` is `dx as
    /// f64 · (256·inv)` (both products exact before one rounding; `256·inv` exact), and
    /// `-dy·256` is negated as an integer, so a zero stays +0.0
    /// (`colour_lanes_are_emit_tri`).
    ///
    /// # Safety
    /// The CPU must have AVX2, and the caller be compiled for it (`Src::wide`).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    unsafe fn emit_colour_avx2(
        &mut self,
        ctx: &SetupCtx,
        g: &Geom,
        l: &EdgeLanes,
        z: [f64; 3],
        iw: [f32; 3],
        flags: u8,
        mat: u32,
        q: [Vec4; 3],
        cover: u8,
    ) {
        use std::arch::x86_64::{
            _mm256_add_pd, _mm256_castps128_ps256, _mm256_castps256_ps128, _mm256_cvtpd_ps,
            _mm256_extractf128_ps, _mm256_loadu_pd, _mm256_mul_pd, _mm256_permute2f128_pd,
            _mm256_set1_pd, _mm256_set_m128, _mm256_setr_epi32, _mm256_setzero_si256,
            _mm256_storeu_pd, _mm256_storeu_si256, _mm256_sub_epi64, _mm256_unpackhi_pd,
            _mm256_unpacklo_pd, _mm_cvtss_f32, _mm_extract_ps, _mm_storeu_ps,
        };
        const LEN: usize = 15;
        debug_assert!(ctx.rl.n == 4 && flags & F_FLAT == 0, "not a smooth colour");
        // Room first, as in `emit_tri` (one float more: see the stores below).
        let voff = self.pool.len();
        self.pool.reserve(LEN + 1);
        let l_xy = l.xy;
        let inv = 1.0 / g.area as f64;
        // SAFETY: the CPU has AVX2 (the contract); register arithmetic and one store of four
        // f64 to `zd`.
        let (zp, lam) = unsafe {
            let zero = _mm256_setzero_si256();
            let scaled = _mm256_set1_pd(inv * 256.0);
            // Lane k: edge k's terms of the barycentric plane of the vertex opposite it.
            let v0 = _mm256_mul_pd(i64_lanes_f64(l.e), _mm256_set1_pd(inv));
            let v1 = _mm256_mul_pd(small_lanes_f64(_mm256_sub_epi64(zero, l.dy)), scaled);
            let v2 = _mm256_mul_pd(small_lanes_f64(l.dx), scaled);
            // Transposed: `k[k]` lane j is term j of edge k (lane 3 a copy of lane 2).
            let (t0, t1) = (_mm256_unpacklo_pd(v0, v1), _mm256_unpackhi_pd(v0, v1));
            let (t2, t3) = (_mm256_unpacklo_pd(v2, v2), _mm256_unpackhi_pd(v2, v2));
            let k0 = _mm256_permute2f128_pd::<0x20>(t0, t2);
            let k1 = _mm256_permute2f128_pd::<0x20>(t1, t3);
            let k2 = _mm256_permute2f128_pd::<0x31>(t0, t2);
            // `emit_tri`'s lam[(k + 2) % 3] is edge k's.
            let lam = [k1, k2, k0];
            let zp = _mm256_add_pd(
                _mm256_add_pd(
                    _mm256_mul_pd(_mm256_set1_pd(z[0]), lam[0]),
                    _mm256_mul_pd(_mm256_set1_pd(z[1]), lam[1]),
                ),
                _mm256_mul_pd(_mm256_set1_pd(z[2]), lam[2]),
            );
            let zp = if ctx.offset_on[0] {
                let mut zd = [0.0f64; 4];
                _mm256_storeu_pd(zd.as_mut_ptr(), zp);
                zd[0] += offset(ctx, zd[1], zd[2]);
                _mm256_loadu_pd(zd.as_ptr())
            } else {
                zp
            };
            let z32 = _mm256_cvtpd_ps(zp);
            let zp = [
                _mm_cvtss_f32(z32),
                f32::from_bits(_mm_extract_ps::<1>(z32) as u32),
                f32::from_bits(_mm_extract_ps::<2>(z32) as u32),
            ];
            (
                zp,
                [
                    Vec4::from(_mm256_cvtpd_ps(lam[0])),
                    Vec4::from(_mm256_cvtpd_ps(lam[1])),
                    Vec4::from(_mm256_cvtpd_ps(lam[2])),
                ],
            )
        };
        // 1/w's plane, as `emit_tri`'s `plane`: lane j term j.
        let iw4 = [Vec4::splat(iw[0]), Vec4::splat(iw[1]), Vec4::splat(iw[2])];
        let head = iw4[0] * lam[0] + iw4[1] * lam[1] + iw4[2] * lam[2];
        let f = [q[0] * iw4[0], q[1] * iw4[1], q[2] * iw4[2]];
        let spare = self.pool.spare_capacity_mut();
        debug_assert!(spare.len() > LEN, "pool not reserved");
        // SAFETY: the CPU has AVX2 (the contract). `reserve(LEN + 1)` above left room for
        // `LEN + 1` floats after the pool's: the stores of four floats write floats 0..4,
        // 3..7, 6..10, 9..13 and 12..16 of that room, in that order, each overwriting the
        // previous one's fourth (float 15 is left past the end). The rest is register
        // arithmetic.
        let xy = unsafe {
            // The colour's planes, varying by varying as the pool holds them (`store_group`'s
            // order): lane j of half h is term j of colour 2·i + h, from varying 2·i + h of
            // each vertex's `f` against the three terms of its barycentric plane, with
            // `plane`'s operations in its order.
            // (No closures: they are compiled without AVX2, so its intrinsics are not
            // inlined into them, and they went out of line, ≈180 instructions a triangle.)
            let l = [
                _mm256_set_m128(lam[0].into(), lam[0].into()),
                _mm256_set_m128(lam[1].into(), lam[1].into()),
                _mm256_set_m128(lam[2].into(), lam[2].into()),
            ];
            let f = [
                _mm256_castps128_ps256(f[0].into()),
                _mm256_castps128_ps256(f[1].into()),
                _mm256_castps128_ps256(f[2].into()),
            ];
            let c01 = colour_pair(f, l, _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1));
            let c23 = colour_pair(f, l, _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3));
            let p = spare.as_mut_ptr().cast::<f32>();
            _mm_storeu_ps(p, head.into());
            _mm_storeu_ps(p.add(3), _mm256_castps256_ps128(c01));
            _mm_storeu_ps(p.add(6), _mm256_extractf128_ps::<1>(c01));
            _mm_storeu_ps(p.add(9), _mm256_castps256_ps128(c23));
            _mm_storeu_ps(p.add(12), _mm256_extractf128_ps::<1>(c23));
            let mut xy = [0i32; 8];
            _mm256_storeu_si256(xy.as_mut_ptr().cast(), l_xy);
            [xy[0], xy[1], xy[2], xy[3], xy[4], xy[5]]
        };
        // SAFETY: `reserve` made room, and the first `LEN` floats were written above.
        unsafe { self.pool.set_len(voff + LEN) };
        self.push_tri(g, xy, flags, mat, voff, cover, zp);
    }

    /// Appends `p` and bins it into every tile its bounding box overlaps.
    #[inline(always)]
    pub(super) fn push(&mut self, p: RPrim) {
        let idx = self.prims.len() as u32;
        let [tx0, ty0, tx1, ty1] = tile_range(&p.bbox);
        let tiles_x = self.bins_x;
        let [x0, y0, x1, y1] = p.bbox.map(i64::from);
        let pixels = ((x1 - x0 + 1).max(0) * (y1 - y0 + 1).max(0)) as u64;
        self.area = self.area.saturating_add(pixels);
        if tx0 == tx1 && ty0 == ty1 {
            let t = ty0 * tiles_x + tx0;
            if let Some(b) = self.bins.get_mut(t) {
                if b.is_empty() {
                    self.touched.push(t as u32);
                }
                b.push(idx);
            }
            self.prims.push(p);
            return;
        }
        // A long thin triangle (a line's half, a fan's sliver) crosses few of the tiles of its
        // box: the others are not binned, so the rasteriser neither walks their rows nor
        // clears them for it. Every tile whose pixels it covers is binned (`may_reach`).
        let test =
            p.kind == PrimKind::Tri && p.cover & COVER_KNOWN == 0 && (ty1 - ty0) + (tx1 - tx0) > 1;
        let side = TILE as i32;
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                if test {
                    let (x, y) = (tx as i32 * side, ty as i32 * side);
                    let rect = [
                        x.max(x0 as i32),
                        y.max(y0 as i32),
                        (x + side - 1).min(x1 as i32),
                        (y + side - 1).min(y1 as i32),
                    ];
                    if !p.may_reach(rect) {
                        continue;
                    }
                }
                let t = ty * tiles_x + tx;
                if let Some(b) = self.bins.get_mut(t) {
                    if b.is_empty() {
                        self.touched.push(t as u32);
                    }
                    b.push(idx);
                }
            }
        }
        self.prims.push(p);
    }
}

/// Whether a triangle of doubled signed area `area` is front-facing (§3.5.1 eq. 3.6: a
/// negative area, clockwise, is `Geom::swapped`); `None` when it has no area or is culled.
#[inline(always)]
fn facing(ctx: &SetupCtx, area: i64) -> Option<bool> {
    if area == 0 {
        return None;
    }
    let front = (area < 0) != ctx.ccw_front;
    match ctx.cull {
        Some(gl::FRONT) if front => None,
        Some(gl::BACK) if !front => None,
        Some(gl::FRONT_AND_BACK) => None,
        _ => Some(front),
    }
}

/// Without AVX2 nothing is placed in lanes (`fast_tri`'s `small` is always `None`).
#[cfg(not(target_arch = "x86_64"))]
type EdgeLanes = ();

/// `Worker::fast_tri`'s vertices `ids` (records `w`) in `Geom::v`'s counter-clockwise order
/// (the second and third exchanged when `swapped`): their window z, 1/w and floats in `vout`
/// (`s` each), without a range check.
///
/// # Safety
/// `vout` holds `(ids[j] + 1) * s` floats at least, for each j.
#[inline(always)]
unsafe fn ccw_verts<'a>(
    swapped: bool,
    w: [&Win; 3],
    ids: [u32; 3],
    vout: &'a [f32],
    s: usize,
) -> ([f64; 3], [f32; 3], [&'a [f32]; 3]) {
    let (ids, ws) = if swapped {
        ([ids[0], ids[2], ids[1]], [w[0], w[2], w[1]])
    } else {
        (ids, w)
    };
    let vert = |i: u32| {
        let i = i as usize;
        debug_assert!((i + 1) * s <= vout.len(), "vertex {i} not processed");
        // SAFETY: floats i·s..(i + 1)·s are inside `vout` (the contract).
        unsafe { vout.get_unchecked(i * s..(i + 1) * s) }
    };
    (
        [ws[0].z, ws[1].z, ws[2].z],
        [ws[0].iw, ws[1].iw, ws[2].iw],
        [vert(ids[0]), vert(ids[1]), vert(ids[2])],
    )
}

/// The four floats from `o` of each of `vs` (a colour-only layout's colour: what `load4(v, o)`
/// is), without a range check.
///
/// # Safety
/// Each of `vs` holds `o + 4` floats at least (the layout's `stride`, when its gather table's
/// group 0 is a `run`: `gather_table`).
#[inline(always)]
unsafe fn colour4(vs: [&[f32]; 3], o: usize) -> [Vec4; 3] {
    // SAFETY: floats o..o + 4 are inside each of `vs` (the contract).
    unsafe {
        [
            load4_unchecked(vs[0], o),
            load4_unchecked(vs[1], o),
            load4_unchecked(vs[2], o),
        ]
    }
}

/// A triangle's place on the pixel grid: counter-clockwise order, doubled area, the pixels whose
/// centres can be inside (cut to `rect`), and which edges own centres exactly on them.
pub(super) struct Geom {
    /// The vertices counter-clockwise (snapped, 1/256 pixel).
    pub v: [[i64; 2]; 3],
    /// The second and third input vertices were swapped to make the order counter-clockwise.
    pub swapped: bool,
    /// Twice the area, in (1/256 pixel)², positive.
    pub area: i64,
    /// Pixel bounding box, inclusive.
    pub bbox: [i32; 4],
    /// Bit k: edge k (vertex k to k + 1) owns the centres on it.
    pub owns: u8,
    /// Edge k's (dx, dy): vertex k + 1 minus vertex k.
    pub d: [[i64; 2]; 3],
    /// Edge k's function `dx·(py − y_k) − dy·(px − x_k)` at the centre of the bounding box's
    /// corner pixel (without the tie-break bias): exact, shared by the coverage test and the
    /// barycentric planes.
    pub e: [i64; 3],
}

impl Geom {
    /// For a bounding box of at most 2x2 pixels, `COVER_KNOWN` plus the covered centres (see
    /// `RPrim::cover`), with the same edge functions and tie rule as the rasteriser; 0 for a
    /// larger box. Exactly `COVER_KNOWN` means the triangle covers no pixel centre.
    #[inline(always)]
    pub(super) fn coverage(&self) -> u8 {
        let [x0, y0, x1, y1] = self.bbox;
        if x1 - x0 > 1 || y1 - y0 > 1 {
            return 0;
        }
        #[cfg(target_arch = "x86_64")]
        let inside = self.inside_sse2();
        #[cfg(not(target_arch = "x86_64"))]
        let inside = self.inside_scalar();
        let cols = if x1 > x0 { 0b1111 } else { 0b0101 };
        let rows = if y1 > y0 { 0b1111 } else { 0b0011 };
        COVER_KNOWN | (inside & cols & rows)
    }

    /// Bit c (2·row + column) set when centre c of the 2x2 block at the box's corner is inside
    /// all three edges (with the tie rule's bias): each edge function at the four centres,
    /// stepping by its exact integer increments, the three edges' values OR-ed per centre, whose
    /// sign bit is then clear exactly when all three are >= 0.
    #[cfg(any(test, not(target_arch = "x86_64")))]
    #[inline(always)]
    pub(super) fn inside_scalar(&self) -> u8 {
        let mut or = [0i64; 4];
        for k in 0..3 {
            let [dx, dy] = self.d[k];
            let bias = i64::from(self.owns & (1 << k) == 0);
            let e = self.e[k] - bias;
            let (ex, ey) = (-dy * 256, dx * 256);
            or[0] |= e;
            or[1] |= e + ex;
            or[2] |= e + ey;
            or[3] |= e + ex + ey;
        }
        u8::from(or[0] >= 0)
            | u8::from(or[1] >= 0) << 1
            | u8::from(or[2] >= 0) << 2
            | u8::from(or[3] >= 0) << 3
    }

    /// [`Geom::inside_scalar`] on two SSE2 registers of two i64 lanes (centres 0, 1 and 2, 3):
    /// the same integer sums (exact: |e| < 2^62 and the steps below 2^40, see `COORD_LIMIT`),
    /// the sign bits taken with `movmskpd` instead of four comparisons.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub(super) fn inside_sse2(&self) -> u8 {
        use std::arch::x86_64::{
            _mm_add_epi64, _mm_castsi128_pd, _mm_movemask_pd, _mm_or_si128, _mm_set1_epi64x,
            _mm_set_epi64x, _mm_setzero_si128,
        };
        // SAFETY: SSE2 is part of the x86-64 baseline; register arithmetic only.
        unsafe {
            let (mut lo, mut hi) = (_mm_setzero_si128(), _mm_setzero_si128());
            for k in 0..3 {
                let [dx, dy] = self.d[k];
                let bias = i64::from(self.owns & (1 << k) == 0);
                let e = self.e[k].wrapping_sub(bias);
                let (ex, ey) = (dy.wrapping_mul(-256), dx.wrapping_mul(256));
                // Centres 0 and 1 (row 0), then 2 and 3: the same plus ey.
                let a = _mm_set_epi64x(e.wrapping_add(ex), e);
                let b = _mm_add_epi64(a, _mm_set1_epi64x(ey));
                lo = _mm_or_si128(lo, a);
                hi = _mm_or_si128(hi, b);
            }
            let neg =
                _mm_movemask_pd(_mm_castsi128_pd(lo)) | _mm_movemask_pd(_mm_castsi128_pd(hi)) << 2;
            (!neg & 0b1111) as u8
        }
    }
}

/// The grid placement of triangle `p` (snapped window coordinates), `None` when it has no area
/// or no pixel of `rect`.
#[inline(always)]
pub(super) fn geom(rect: &[i32; 4], p: [[i64; 2]; 3]) -> Option<Geom> {
    debug_assert!(
        p.iter().flatten().all(|v| v.abs() < COORD_LIMIT),
        "snapped coordinates past COORD_LIMIT: {p:?}"
    );
    let [a, b, c] = p;
    let (minx, maxx) = (a[0].min(b[0]).min(c[0]), a[0].max(b[0]).max(c[0]));
    let (miny, maxy) = (a[1].min(b[1]).min(c[1]), a[1].max(b[1]).max(c[1]));
    // Pixels whose centre (i + 0.5) can lie inside.
    let lo = |m: i64| -((128 - m).div_euclid(256));
    let hi = |m: i64| (m - 128).div_euclid(256);
    // Cut to `rect` in i64; a non-empty result lies inside `rect`, so it fits i32.
    let r = rect.map(i64::from);
    let b64 = [
        lo(minx).max(r[0]),
        lo(miny).max(r[1]),
        hi(maxx).min(r[2]),
        hi(maxy).min(r[3]),
    ];
    if b64[0] > b64[2] || b64[1] > b64[3] {
        return None;
    }
    geom_in(b64.map(|v| v as i32), p)
}

/// `geom(rect, p)` for the window records `w` of a triangle's vertices, `rect_cen` being
/// `SetupCtx::rect_cen` of `rect`: the bounding box from the vertices' `Win::cen` (the
/// minimum of a monotone function's values is its value at the minimum, so these are `geom`'s
/// bounds exactly), cut to `rect` by one `max` per bound; the same `Geom`
/// (`geom_wins_is_geom` compares them).
#[cfg(test)]
pub(super) fn geom_wins(rect_cen: &[i32; 4], w: [&Win; 3]) -> Option<Geom> {
    let bbox = wins_bbox(rect_cen, w)?;
    geom_in(
        bbox,
        [[w[0].fx, w[0].fy], [w[1].fx, w[1].fy], [w[2].fx, w[2].fy]],
    )
}

/// The bounding box of `geom_wins`, `None` when empty.
#[inline(always)]
fn wins_bbox(rect_cen: &[i32; 4], w: [&Win; 3]) -> Option<[i32; 4]> {
    let c: [i32; 4] = std::array::from_fn(|i| {
        w[0].cen[i]
            .min(w[1].cen[i])
            .min(w[2].cen[i])
            .max(rect_cen[i])
    });
    // Empty: x0 > x1 or y0 > y1 with x1 = -c[2], y1 = -c[3] (in i64: `rect_cen`'s saturated
    // bounds stay comparable).
    let neg = |v: i32| -i64::from(v);
    if i64::from(c[0]) > neg(c[2]) || i64::from(c[1]) > neg(c[3]) {
        return None;
    }
    // Not empty, so x1 >= x0 and y1 >= y0 > i32::MIN: the negations fit.
    Some([c[0], c[1], c[2].wrapping_neg(), c[3].wrapping_neg()])
}

/// Twice the signed area of triangle `p` (snapped), positive counter-clockwise: `geom_in`'s.
#[inline(always)]
fn doubled_area(p: [[i64; 2]; 3]) -> i64 {
    let [a, b, c] = p;
    (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
}

/// `geom_placed(bbox, p, area)` and its `coverage()` for a triangle whose box `bbox` (from
/// `wins_bbox`, not empty) is at most 2x2 pixels, `None` for a larger box: the three edges'
/// deltas, edge functions, tie rule and the four centres' sums of `inside_scalar` in the
/// lanes of AVX2 registers of i64 (lane k edge k; lane 3 an edge of nothing, left out of the
/// masks). Each product's factors fit i32 (vertices below `COORD_LIMIT`, and the box corner's
/// centre lies between them), so `_mm256_mul_epi32` makes it exactly: the same integers, so
/// the same `Geom` and cover (`geom_small_is_geom` compares). The scalar edges, the tie rule's
/// branches and the coverage's own sums were ≈140 instructions a triangle. (`fast_tri` calls
/// `geom_small_lanes_avx2`, and completes `Geom::v` itself.)
///
/// # Safety
/// The CPU must have AVX2, and the caller be compiled for it (`Src::wide`).
#[cfg(all(test, target_arch = "x86_64"))]
unsafe fn geom_small_avx2(
    bbox: [i32; 4],
    p: [[i64; 2]; 3],
    area: i64,
) -> Option<(Geom, u8, EdgeLanes)> {
    // SAFETY: this function's contract.
    let small = unsafe { geom_small_lanes_avx2(bbox, p, area) };
    small.map(|(mut g, cover, l)| {
        g.v = ccw(p, area).1;
        (g, cover, l)
    })
}

/// [`geom_small_avx2`] but for `Geom::v`, left as given (`p`): `fast_tri` puts it in
/// counter-clockwise order (`ccw`) only on the route that reads it, after the colour-only
/// triangle (which reads `EdgeLanes::xy` instead) has been emitted. Built here, `ccw`'s
/// selects were ≈10 instructions on every triangle with a box of at most 2x2.
///
/// Inlined (always: as a function of its own it returned the `Geom` through memory, ≈160
/// instructions a call) into `fast_tri` only where that is compiled for AVX2.
///
/// # Safety
/// As for `geom_small_avx2`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn geom_small_lanes_avx2(
    bbox: [i32; 4],
    p: [[i64; 2]; 3],
    area: i64,
) -> Option<(Geom, u8, EdgeLanes)> {
    let [x0, y0, x1, y1] = bbox;
    if x1 - x0 > 1 || y1 - y0 > 1 {
        return None;
    }
    // SAFETY: the CPU has AVX2 (the contract); the box is at most 2x2 (just tested).
    Some(unsafe { small_p_avx2(bbox, p, area) })
}

/// `small_lanes_avx2` of the vertices `p`.
///
/// # Safety
/// As for `small_lanes_avx2`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn small_p_avx2(bbox: [i32; 4], p: [[i64; 2]; 3], area: i64) -> (Geom, u8, EdgeLanes) {
    use std::arch::x86_64::_mm256_set_epi64x;
    // SAFETY: the CPU has AVX2 (the contract); register arithmetic.
    let (x, y) = unsafe {
        (
            _mm256_set_epi64x(0, p[2][0], p[1][0], p[0][0]),
            _mm256_set_epi64x(0, p[2][1], p[1][1], p[0][1]),
        )
    };
    // SAFETY: the CPU has AVX2 (the contract); the box is at most 2x2 (the caller's).
    unsafe { small_lanes_avx2(bbox, x, y, p, area) }
}

/// `geom_small_lanes_avx2` of a triangle whose box `bbox` is at most 2x2 pixels, its
/// vertices `p` also given as lanes `x`, `y` (lane k vertex k, lane 3 zero).
///
/// # Safety
/// As for `geom_small_avx2`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn small_lanes_avx2(
    bbox: [i32; 4],
    x: std::arch::x86_64::__m256i,
    y: std::arch::x86_64::__m256i,
    p: [[i64; 2]; 3],
    area: i64,
) -> (Geom, u8, EdgeLanes) {
    use std::arch::x86_64::{
        _mm256_add_epi64, _mm256_and_si256, _mm256_blend_epi32, _mm256_castsi256_pd,
        _mm256_cmpeq_epi64, _mm256_cmpgt_epi64, _mm256_movemask_pd, _mm256_mul_epi32,
        _mm256_or_si256, _mm256_permute2x128_si256, _mm256_permute4x64_epi64, _mm256_set1_epi64x,
        _mm256_set_epi64x, _mm256_setzero_si256, _mm256_slli_epi64, _mm256_storeu_si256,
        _mm256_sub_epi64, _mm256_unpackhi_epi64, _mm256_unpacklo_epi64,
    };
    let [x0, y0, x1, y1] = bbox;
    let swapped = area < 0;
    let (mut dx, mut dy, mut e) = ([0i64; 4], [0i64; 4], [0i64; 4]);
    // SAFETY: the CPU has AVX2, and the caller is compiled for it (this function's contract);
    // the stores write the four i64 of
    // `dx`, `dy` and `e` (no alignment needed); the rest is register arithmetic.
    let (inside, owns, lanes) = unsafe {
        // Lane k: vertex k (counter-clockwise), and vertex k + 1 by a permutation (lane 3
        // zeros): the lanes are `p`'s, a clockwise triangle's second and third vertices
        // then exchanged in them (`ccw` in lanes).
        let (x, y) = if swapped {
            (
                _mm256_permute4x64_epi64::<0b11_01_10_00>(x),
                _mm256_permute4x64_epi64::<0b11_01_10_00>(y),
            )
        } else {
            (x, y)
        };
        let ex = _mm256_sub_epi64(_mm256_permute4x64_epi64::<0b11_00_10_01>(x), x);
        let ey = _mm256_sub_epi64(_mm256_permute4x64_epi64::<0b11_00_10_01>(y), y);
        let px = _mm256_set1_epi64x(i64::from(x0) * 256 + 128);
        let py = _mm256_set1_epi64x(i64::from(y0) * 256 + 128);
        // dx·(py − y) − dy·(px − x), each factor within ±2^31.
        let ee = _mm256_sub_epi64(
            _mm256_mul_epi32(ex, _mm256_sub_epi64(py, y)),
            _mm256_mul_epi32(ey, _mm256_sub_epi64(px, x)),
        );
        _mm256_storeu_si256(dx.as_mut_ptr().cast(), ex);
        _mm256_storeu_si256(dy.as_mut_ptr().cast(), ey);
        _mm256_storeu_si256(e.as_mut_ptr().cast(), ee);
        // The tie rule, all ones where the edge owns the centres on it; the bias is 1 where
        // it does not: e − 1 − owns.
        let zero = _mm256_setzero_si256();
        let owns = _mm256_or_si256(
            _mm256_cmpgt_epi64(zero, ey),
            _mm256_and_si256(_mm256_cmpeq_epi64(ey, zero), _mm256_cmpgt_epi64(ex, zero)),
        );
        // (Lane 3, an edge of nothing, gets 0 − 0 − 0: never negative, so it takes no mask.)
        let c0 = _mm256_sub_epi64(_mm256_sub_epi64(ee, owns), _mm256_set_epi64x(0, 1, 1, 1));
        // Centres 1, 2, 3 as `inside_scalar` steps to them: + (−dy·256), + dx·256, both.
        let (sx, sy) = (_mm256_slli_epi64::<8>(ey), _mm256_slli_epi64::<8>(ex));
        let c1 = _mm256_sub_epi64(c0, sx);
        let c2 = _mm256_add_epi64(c0, sy);
        let c3 = _mm256_add_epi64(c1, sy);
        // A centre is inside when none of the edges is negative there: the four centres'
        // lanes OR-ed together by two unpacks and a swap of halves, lane c then centre c's
        // (one `movmskpd` where four, with their tests and shifts, were ≈18 instructions).
        let p01 = _mm256_or_si256(_mm256_unpacklo_epi64(c0, c1), _mm256_unpackhi_epi64(c0, c1));
        let p23 = _mm256_or_si256(_mm256_unpacklo_epi64(c2, c3), _mm256_unpackhi_epi64(c2, c3));
        let all = _mm256_or_si256(
            _mm256_permute2x128_si256::<0x20>(p01, p23),
            _mm256_permute2x128_si256::<0x31>(p01, p23),
        );
        let inside = !_mm256_movemask_pd(_mm256_castsi256_pd(all)) as u8 & 0b1111;
        (
            inside,
            _mm256_movemask_pd(_mm256_castsi256_pd(owns)) as u8 & 0b111,
            EdgeLanes {
                dx: ex,
                dy: ey,
                e: ee,
                // x in the low dwords, y in the high ones: `RPrim::xy` (each `as i32`).
                xy: _mm256_blend_epi32::<0b1010_1010>(x, _mm256_slli_epi64::<32>(y)),
            },
        )
    };
    let cols = if x1 > x0 { 0b1111 } else { 0b0101 };
    let rows = if y1 > y0 { 0b1111 } else { 0b0011 };
    let g = Geom {
        v: p,
        swapped,
        area: area.abs(),
        bbox,
        owns,
        d: [[dx[0], dy[0]], [dx[1], dy[1]], [dx[2], dy[2]]],
        e: [e[0], e[1], e[2]],
    };
    (g, COVER_KNOWN | (inside & cols & rows), lanes)
}

/// A strip triangle's place from its window records, found in lanes by `strip_lanes_avx2`.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct StripLanes {
    /// `wins_bbox`'s box (not empty).
    bbox: [i32; 4],
    /// The box is at most 2x2 pixels.
    small: bool,
}

/// `wins_bbox(rect_cen, w)` (`None` when empty), whether that box is at most 2x2, and
/// `doubled_area` of the vertices, in lanes: the three `Win::cen` one register each, their
/// minimum and the maximum with `rect_cen` by `pminsd`, `pmaxsd`, the emptiness and size
/// tests on the bounds widened to i64 (`x0 + (−x1)`, exact where `wins_bbox` compares in
/// i64), the box's `x1`, `y1` negated back by `psignd` (`wrapping_neg`'s bits); the area
/// `ex2·ey0 − ex0·ey2` from the edges' lanes by one `pmuldq` (each delta within ±2^31: the
/// records' snapped coordinates are below `COORD_LIMIT`). The scalar box (bounds as 64-bit
/// halves, the box through the stack) and area were ≈50 instructions a triangle.
///
/// # Safety
/// The CPU must have AVX2, and the caller be compiled for it.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn strip_lanes_avx2(rect_cen: &[i32; 4], w: [&Win; 3]) -> Option<StripLanes> {
    use std::arch::x86_64::{
        __m128i, _mm256_add_epi64, _mm256_castsi256_pd, _mm256_cmpgt_epi64, _mm256_cvtepi32_epi64,
        _mm256_movemask_pd, _mm256_permute4x64_epi64, _mm256_set1_epi64x, _mm256_setzero_si256,
        _mm_loadu_si128, _mm_max_epi32, _mm_min_epi32, _mm_setr_epi32, _mm_sign_epi32,
        _mm_storeu_si128,
    };
    let load = |c: &[i32; 4]| {
        // SAFETY: `c` is four i32, read unaligned (the CPU has AVX2: the contract).
        unsafe { _mm_loadu_si128(c.as_ptr().cast::<__m128i>()) }
    };
    let mut bbox = [0i32; 4];
    // SAFETY: the CPU has AVX2 (the contract); register arithmetic and one store of four
    // i32 to `bbox`.
    unsafe {
        let c = _mm_min_epi32(
            _mm_min_epi32(load(&w[0].cen), load(&w[1].cen)),
            load(&w[2].cen),
        );
        let c = _mm_max_epi32(c, load(rect_cen));
        // Lanes 0, 1: x0 − x1, y0 − y1 (in i64).
        let c64 = _mm256_cvtepi32_epi64(c);
        let size = _mm256_add_epi64(c64, _mm256_permute4x64_epi64::<0b01_00_11_10>(c64));
        let empty = _mm256_cmpgt_epi64(size, _mm256_setzero_si256());
        if _mm256_movemask_pd(_mm256_castsi256_pd(empty)) & 0b11 != 0 {
            return None;
        }
        let big = _mm256_cmpgt_epi64(_mm256_set1_epi64x(-1), size);
        let small = _mm256_movemask_pd(_mm256_castsi256_pd(big)) & 0b11 == 0;
        _mm_storeu_si128(
            bbox.as_mut_ptr().cast(),
            _mm_sign_epi32(c, _mm_setr_epi32(1, 1, -1, -1)),
        );
        Some(StripLanes { bbox, small })
    }
}

/// `geom_small_avx2`'s edges as it leaves them in AVX2 registers: lane k holds edge k's
/// `Geom::d` (dx, dy) and `Geom::e` (lane 3: 0), for `Worker::emit_colour_avx2`, which
/// builds the barycentric planes from them in lanes without storing them first.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct EdgeLanes {
    dx: std::arch::x86_64::__m256i,
    dy: std::arch::x86_64::__m256i,
    e: std::arch::x86_64::__m256i,
    /// The vertices counter-clockwise as i32 (`Geom::v` as `RPrim::xy` holds it), then 0, 0.
    xy: std::arch::x86_64::__m256i,
}

/// Two colour varyings' planes, one a half (lane j term j, as the pool holds them): `idx`
/// picks the varying of each half from `f[m]` (vertex m's four, over w, in the low half),
/// multiplied by `l[m]` (vertex m's barycentric plane in both halves), the three products
/// added in `plane`'s order.
///
/// # Safety
/// The CPU must have AVX2, and the caller be compiled for it.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn colour_pair(
    f: [std::arch::x86_64::__m256; 3],
    l: [std::arch::x86_64::__m256; 3],
    idx: std::arch::x86_64::__m256i,
) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::{_mm256_add_ps, _mm256_mul_ps, _mm256_permutevar8x32_ps};
    // SAFETY: register arithmetic (the CPU has AVX2: the contract).
    unsafe {
        let t0 = _mm256_mul_ps(_mm256_permutevar8x32_ps(f[0], idx), l[0]);
        let t1 = _mm256_mul_ps(_mm256_permutevar8x32_ps(f[1], idx), l[1]);
        let t2 = _mm256_mul_ps(_mm256_permutevar8x32_ps(f[2], idx), l[2]);
        _mm256_add_ps(_mm256_add_ps(t0, t1), t2)
    }
}

/// The i64 lanes of `v` as f64, each rounded once to nearest as `as f64` rounds it (so the
/// same bits): the top 16 bits' multiple of 2^48 and the low 48 bits are each exact in a
/// double (added to and subtracted from constants whose spacing is 2^48 and 1), and their sum
/// is rounded once. AVX2 has no conversion of i64 (`vcvtqq2pd` is AVX-512).
///
/// # Safety
/// The CPU must have AVX2, and the caller be compiled for it.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn i64_lanes_f64(v: std::arch::x86_64::__m256i) -> std::arch::x86_64::__m256d {
    use std::arch::x86_64::{
        _mm256_add_epi64, _mm256_add_pd, _mm256_blend_epi16, _mm256_castpd_si256,
        _mm256_castsi256_pd, _mm256_set1_pd, _mm256_setzero_si256, _mm256_srai_epi32,
        _mm256_sub_pd,
    };
    // 3·2^67, whose spacing is 2^16: adding n·2^32 to its bits adds n·2^48; and 2^52, whose
    // spacing is 1.
    let (big, unit) = ((3u128 << 67) as f64, (1u64 << 52) as f64);
    // SAFETY: register arithmetic (the CPU has AVX2: the contract).
    unsafe {
        // The top 16 bits, sign-extended, in the high dword (the low dword zeroed).
        let hi = _mm256_blend_epi16::<0x33>(_mm256_srai_epi32::<16>(v), _mm256_setzero_si256());
        let hi = _mm256_castsi256_pd(_mm256_add_epi64(
            hi,
            _mm256_castpd_si256(_mm256_set1_pd(big)),
        ));
        // The low 48 bits under 2^52's exponent.
        let lo = _mm256_castsi256_pd(_mm256_blend_epi16::<0x88>(
            v,
            _mm256_castpd_si256(_mm256_set1_pd(unit)),
        ));
        _mm256_add_pd(_mm256_sub_pd(hi, _mm256_set1_pd(big + unit)), lo)
    }
}

/// The i64 lanes of `v`, each within ±2^51, as f64 (exactly): added to the bits of 1.5·2^52,
/// whose spacing is 1, then that subtracted.
///
/// # Safety
/// The CPU must have AVX2, and the caller be compiled for it.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn small_lanes_f64(v: std::arch::x86_64::__m256i) -> std::arch::x86_64::__m256d {
    use std::arch::x86_64::{
        _mm256_add_epi64, _mm256_castpd_si256, _mm256_castsi256_pd, _mm256_set1_pd, _mm256_sub_pd,
    };
    let magic = (3u64 << 51) as f64;
    // SAFETY: register arithmetic (the CPU has AVX2: the contract).
    unsafe {
        let m = _mm256_set1_pd(magic);
        _mm256_sub_pd(
            _mm256_castsi256_pd(_mm256_add_epi64(v, _mm256_castpd_si256(m))),
            m,
        )
    }
}

/// The rest of `geom` once the bounding box `bbox` (not empty, inside the rectangle) is known.
#[inline(always)]
fn geom_in(bbox: [i32; 4], p: [[i64; 2]; 3]) -> Option<Geom> {
    let area = doubled_area(p);
    if area == 0 {
        return None;
    }
    Some(geom_placed(bbox, p, area))
}

/// `geom_in` of a triangle whose doubled signed area `area` (`doubled_area`) is not 0.
#[inline(always)]
fn geom_placed(bbox: [i32; 4], p: [[i64; 2]; 3], area: i64) -> Geom {
    let (swapped, v) = ccw(p, area);
    let (px, py) = (
        i64::from(bbox[0]) * 256 + 128,
        i64::from(bbox[1]) * 256 + 128,
    );
    let mut owns = 0u8;
    let mut d = [[0i64; 2]; 3];
    let mut e = [0i64; 3];
    for k in 0..3 {
        let (p, q) = (v[k], v[(k + 1) % 3]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        // Tie rule, as llvmpipe applies it to a y-up window: a left edge (going down) or a
        // bottom edge (going right) owns the pixel centres exactly on it; other edges do not.
        owns |= u8::from(dy < 0 || (dy == 0 && dx > 0)) << k;
        d[k] = [dx, dy];
        e[k] = dx * (py - p[1]) - dy * (px - p[0]);
    }
    Geom {
        v,
        swapped,
        area: area.abs(),
        bbox,
        owns,
        d,
        e,
    }
}

/// Whether triangle `p` of doubled signed area `area` is clockwise, and its vertices
/// counter-clockwise (the second and third swapped when it is).
#[inline(always)]
fn ccw(p: [[i64; 2]; 3], area: i64) -> (bool, [[i64; 2]; 3]) {
    let [a, b, c] = p;
    let swapped = area < 0;
    (swapped, if swapped { [a, c, b] } else { [a, b, c] })
}

/// Polygon offset (§3.5.5): factor · max slope + units · r. GL leaves r to the implementation
/// ("the smallest value guaranteed to produce a resolvable difference"); llvmpipe's is twice
/// one step of the 24-bit depth buffer (Mesa's state tracker passes units · 2 to gallium, which
/// scales by 2^-24), and with half that one unit does not lift a filled polygon off its own
/// outline (piglit's polygon-mode-offset and gl-1.4-polygon-offset).
pub(super) fn offset(ctx: &SetupCtx, dzdx: f64, dzdy: f64) -> f64 {
    let m = dzdx.abs().max(dzdy.abs());
    ctx.factor * m + ctx.units * 2.0 / f64::from(1u32 << 24)
}

/// Which tiles `bbox` overlaps: `(tx0, ty0, tx1, ty1)` inclusive.
pub fn tile_range(bbox: &[i32; 4]) -> [usize; 4] {
    let t = |v: i32| (v.max(0) as usize) / TILE;
    [t(bbox[0]), t(bbox[1]), t(bbox[2]), t(bbox[3])]
}

#[cfg(test)]
mod tests {
    use super::{
        cen, geom, geom_wins, load4, load4_unchecked, plane, rect_cen, store_group, Geom, Win,
        SNAP_LIMIT,
    };
    #[cfg(target_arch = "x86_64")]
    use super::{
        doubled_area, geom_placed, geom_small_avx2, strip_lanes_avx2, wins_bbox, COVER_KNOWN,
    };
    use crate::cpu::testgen::Gen;
    use glam::Vec4;

    /// `snap` (a plain truncating cast after NaN is replaced by 0.0) against the saturating
    /// `as i32` it stands in for, bit for bit: NaNs of both signs and several payloads, ±0,
    /// infinities, subnormals, values at and around the clamp, every tie of ±(k + 1/2)/256,
    /// random bit patterns of every magnitude and random window coordinates; each value both
    /// alone and in the lanes of a 16-wide loop compiled with AVX2 (`win_block`'s shape, which
    /// is where the compiler turns the cast into `cvttpd2dq`).
    #[test]
    fn snap_is_the_saturating_cast() {
        use super::snap;
        fn reference(x: f64) -> i32 {
            let t = (x * 256.0).clamp(-SNAP_LIMIT, SNAP_LIMIT);
            (t + 0.5f64.copysign(t)) as i32
        }
        let lim = SNAP_LIMIT / 256.0;
        let mut xs = vec![
            0.0,
            -0.0,
            f64::NAN,
            -f64::NAN,
            f64::from_bits(0x7ff0_0000_0000_0001),
            f64::from_bits(0xfff8_dead_beef_0001),
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::from_bits(1),
            -f64::from_bits(1),
            lim,
            -lim,
            1e300,
            -1e300,
            2f64.powi(31),
            -(2f64.powi(31)),
        ];
        for d in [-2.0, -1.0, -0.5, 0.5, 1.0, 2.0] {
            xs.push(lim + d / 256.0);
            xs.push(-lim + d / 256.0);
            xs.push(f64::from_bits((lim + d).to_bits() - 1));
        }
        for k in -600i32..600 {
            let tie = (f64::from(k) + 0.5) / 256.0;
            xs.extend([
                tie,
                f64::from_bits(tie.to_bits() + 1),
                f64::from_bits(tie.to_bits() - 1),
            ]);
            xs.push(f64::from(k) * 1024.0 + 0.5 / 256.0);
        }
        let mut g = Gen(0x5a4b_2026);
        for _ in 0..200_000 {
            xs.push(f64::from_bits(g.next()));
            xs.push((g.next() as i64 as f64) / 2f64.powi(g.next() as i32 & 63));
            xs.push(f64::from(g.float()) * 2000.0);
        }
        for &x in &xs {
            assert_eq!(snap(x), reference(x), "{x:e} ({:#x})", x.to_bits());
        }
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            #[target_feature(enable = "avx2")]
            fn lanes(x: &[f64; 16]) -> [i32; 16] {
                let mut r = [0; 16];
                for i in 0..16 {
                    r[i] = snap(x[i]);
                }
                r
            }
            for ch in xs.chunks_exact(16) {
                let x: [f64; 16] = ch.try_into().expect("16 values");
                // SAFETY: the CPU has AVX2 (tested above).
                let got = unsafe { lanes(&x) };
                assert_eq!(got, x.map(reference), "{x:?}");
            }
        }
    }

    /// `store_group` against the twelve floats written lane by lane (`emit_tri`'s last group),
    /// bit for bit (NaN payloads included: no arithmetic), and `load4_unchecked` against
    /// `load4` inside a slice.
    #[test]
    fn store_group_interleaves_the_planes() {
        let mut g = Gen(0x5eed_0716);
        for _ in 0..2000 {
            let v: [Vec4; 3] = std::array::from_fn(|_| {
                Vec4::from_array(std::array::from_fn(|_| f32::from_bits(g.next() as u32)))
            });
            let mut got = [std::mem::MaybeUninit::new(0.0f32); 12];
            store_group(&mut got, v);
            let [a, b, c] = v;
            let want = [a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z, a.w, b.w, c.w];
            for (i, (d, w)) in got.iter().zip(want).enumerate() {
                // SAFETY: every float was initialised (`new(0.0)`) before `store_group`.
                let d = unsafe { d.assume_init() };
                assert_eq!(d.to_bits(), w.to_bits(), "float {i} of {v:?}");
            }
            let s: Vec<f32> = (0..12).map(|_| g.float()).collect();
            let k = g.next() as usize % 9;
            // SAFETY: k + 4 <= 12 = s.len().
            let u = unsafe { load4_unchecked(&s, k) };
            assert_eq!(
                u.to_array().map(f32::to_bits),
                load4(&s, k).to_array().map(f32::to_bits)
            );
        }
    }

    /// `plane` of four varyings at once (as `emit_tri` builds them) against `plane` of each
    /// alone, bit for bit, on random planes and values (NaN and infinities among them).
    #[test]
    fn plane_lanes_match_scalar() {
        let mut g = Gen(0x91a4_e5c3);
        let val = |g: &mut Gen| match g.next() % 8 {
            0 => [f32::INFINITY, -1e-40, 3e38][g.next() as usize % 3],
            _ => g.float(),
        };
        // Every NaN one value (which NaN's payload an operation passes on is not compared).
        let bits = |v: f32| if v.is_nan() { u32::MAX } else { v.to_bits() };
        for _ in 0..20_000 {
            let l: [[f32; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| val(&mut g)));
            let f: [[f32; 4]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| val(&mut g)));
            let wide = plane(l.map(|r| r.map(Vec4::splat)), f.map(Vec4::from_array));
            for i in 0..4 {
                let one = plane(l, [f[0][i], f[1][i], f[2][i]]);
                for c in 0..3 {
                    assert_eq!(
                        bits(wide[c].to_array()[i]),
                        bits(one[c]),
                        "lane {i}, coefficient {c}: l {l:?}, f {f:?}"
                    );
                }
            }
        }
    }

    /// Every field of `g`.
    type Fields = (
        [[i64; 2]; 3],
        bool,
        i64,
        [i32; 4],
        u8,
        [[i64; 2]; 3],
        [i64; 3],
    );

    fn fields(g: Option<Geom>) -> Option<Fields> {
        g.map(|g| (g.v, g.swapped, g.area, g.bbox, g.owns, g.d, g.e))
    }

    /// `RPrim::may_reach` on random triangles (thin, large, near the 1/256 grid, every tie
    /// rule) and random rectangles inside their boxes: true whenever a pixel centre of the
    /// rectangle has all three edge functions >= 0 (each pixel tested), and false for some.
    #[test]
    fn may_reach_keeps_every_covered_rect() {
        use super::{PrimKind, RPrim};
        let mut g = Gen(0x5eed_0d16);
        let (mut reached, mut missed) = (0, 0);
        for case in 0..20_000 {
            let span = [24u64, 200, 3000, 40_000][case % 4];
            let mut xy = [0i32; 6];
            for v in xy.iter_mut() {
                *v = (g.next() % span) as i32 - (span / 4) as i32;
            }
            let p = RPrim {
                kind: PrimKind::Tri,
                flags: 0,
                bbox: [0; 4],
                mat: 0,
                voff: 0,
                xy,
                owns: g.byte() & 7,
                cover: 0,
                z: [0.0; 3],
            };
            let edges = p.edges();
            let lo = |k: usize| xy.iter().skip(k).step_by(2).min().copied().unwrap_or(0) / 256 - 1;
            let hi = |k: usize| xy.iter().skip(k).step_by(2).max().copied().unwrap_or(0) / 256 + 1;
            let (bx0, by0, bx1, by1) = (lo(0), lo(1), hi(0), hi(1));
            let pick = |g: &mut Gen, a: i32, b: i32| a + (g.next() % (b - a + 1) as u64) as i32;
            let (xa, xb) = (pick(&mut g, bx0, bx1), pick(&mut g, bx0, bx1));
            let (ya, yb) = (pick(&mut g, by0, by1), pick(&mut g, by0, by1));
            let rect = [xa.min(xb), ya.min(yb), xa.max(xb), ya.max(yb)];
            let covered = (rect[1]..=rect[3]).any(|y| {
                (rect[0]..=rect[2]).any(|x| {
                    edges
                        .iter()
                        .all(|e| e[0] + e[1] * i64::from(x) + e[2] * i64::from(y) >= 0)
                })
            });
            let may = p.may_reach(rect);
            assert!(may || !covered, "case {case}: {xy:?} {rect:?}");
            match may {
                true => reached += 1,
                false => missed += 1,
            }
        }
        assert!(reached > 1000 && missed > 1000, "{reached} {missed}");
    }

    /// `geom_wins` (the bounding box from the vertices' `Win::cen`) against `geom` on random
    /// triangles: a few pixels wide near the grid's centres (ties at centres and at 1/256
    /// steps), large, at the snap limits, under rectangles small, ordinary, empty and extreme
    /// (`i32::MIN`/`MAX` bounds): the same `Geom`, field for field, or both `None`.
    #[test]
    fn geom_wins_is_geom() {
        let mut g = Gen(0x5eed_0011);
        let lim = SNAP_LIMIT as i64;
        let mut some = 0;
        for case in 0..200_000 {
            let rect = match case % 7 {
                0 => [0, 0, 799, 799],
                1 => [i32::MIN, i32::MIN, i32::MAX, i32::MAX],
                2 => [3, 5, 2, 9],
                3 => [i32::MAX, 0, i32::MIN, 10],
                _ => {
                    let mut r = || (g.next() % 40) as i32 - 8;
                    [r(), r(), r(), r()]
                }
            };
            let coord = |g: &mut Gen| -> i64 {
                match g.next() % 8 {
                    0 => (g.next() % (2 * lim as u64 + 1)) as i64 - lim,
                    1 => [lim, -lim, 0, 128, -128][(g.next() % 5) as usize],
                    2 => (g.next() % 64) as i64 * 128,
                    _ => (g.next() % 8000) as i64 - 1000,
                }
            };
            let p: [[i64; 2]; 3] = std::array::from_fn(|_| [coord(&mut g), coord(&mut g)]);
            let w = p.map(|[x, y]| Win {
                fx: x,
                fy: y,
                cen: cen(x as i32, y as i32),
                ..Win::default()
            });
            let a = fields(geom(&rect, p));
            let b = fields(geom_wins(&rect_cen(rect), [&w[0], &w[1], &w[2]]));
            assert_eq!(a, b, "case {case}: rect {rect:?}, {p:?}");
            some += usize::from(a.is_some());
        }
        assert!(some > 50_000, "too few triangles with a box: {some}");
    }

    /// The 2x2 coverage on SSE2 lanes against the scalar sums, on the `Geom`s of random small
    /// and large triangles (ties at centres, every owned-edge pattern, the snap limits).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn inside_sse2_is_inside_scalar() {
        let mut g = Gen(0x0c0f_fee5);
        let lim = SNAP_LIMIT as i64;
        let mut n = 0;
        for case in 0..200_000 {
            let coord = |g: &mut Gen| -> i64 {
                match g.next() % 6 {
                    0 => (g.next() % (2 * lim as u64 + 1)) as i64 - lim,
                    1 => (g.next() % 16) as i64 * 128,
                    _ => (g.next() % 1200) as i64 - 100,
                }
            };
            let p: [[i64; 2]; 3] = std::array::from_fn(|_| [coord(&mut g), coord(&mut g)]);
            let Some(t) = geom(&[i32::MIN, i32::MIN, i32::MAX, i32::MAX], p) else {
                continue;
            };
            assert_eq!(t.inside_sse2(), t.inside_scalar(), "case {case}: {p:?}");
            n += 1;
        }
        assert!(n > 100_000, "too few triangles: {n}");
    }

    /// Whether the CPU has AVX2, which the test of kernel `what` needs (said on stderr when
    /// not).
    #[cfg(target_arch = "x86_64")]
    fn has_avx2(what: &str) -> bool {
        let has = is_x86_feature_detected!("avx2");
        if !has {
            eprintln!("no AVX2 on this CPU: {what} not compared");
        }
        has
    }

    /// `small_case`'s rectangle and triangle before its box: a rectangle (the framebuffer's,
    /// unbounded, or tiny and random) and three vertices (anywhere in the snapped range, at
    /// its clamps, on and around pixel centres, or near one another) with their records.
    #[cfg(target_arch = "x86_64")]
    fn case_records(g: &mut Gen, case: usize) -> ([i32; 4], [[i64; 2]; 3], [Win; 3]) {
        let lim = SNAP_LIMIT as i64;
        let rect = match case % 4 {
            0 => [0, 0, 799, 799],
            1 => [i32::MIN, i32::MIN, i32::MAX, i32::MAX],
            _ => {
                let mut r = || (g.next() % 40) as i32 - 8;
                [r(), r(), r(), r()]
            }
        };
        let (cx, cy) = (
            (g.next() % 3000) as i64 - 800,
            (g.next() % 3000) as i64 - 800,
        );
        let coord = |g: &mut Gen, c: i64| -> i64 {
            match g.next() % 16 {
                0 => (g.next() % (2 * lim as u64 + 1)) as i64 - lim,
                1 => [lim, -lim][(g.next() % 2) as usize],
                2..=5 => (c & !127) + (g.next() % 5) as i64 * 128 - 256,
                _ => c + (g.next() % 800) as i64 - 400,
            }
        };
        let p: [[i64; 2]; 3] = std::array::from_fn(|_| [coord(g, cx), coord(g, cy)]);
        let w = p.map(|[x, y]| Win {
            fx: x,
            fy: y,
            cen: cen(x as i32, y as i32),
            ..Win::default()
        });
        (rect, p, w)
    }

    /// A random triangle for `geom_small_is_geom` and `colour_lanes_are_emit_tri`, a few
    /// pixels across near the grid's centres (ties at centres and on 1/128 steps, every
    /// owned-edge pattern, either winding), some with a vertex far away or at the snap limits
    /// and the box cut by the rectangle: `(rect, p, bbox, area)`, `None` when its box is empty
    /// or its area 0.
    #[cfg(target_arch = "x86_64")]
    #[allow(clippy::type_complexity)]
    fn small_case(g: &mut Gen, case: usize) -> Option<([i32; 4], [[i64; 2]; 3], [i32; 4], i64)> {
        let (rect, p, w) = case_records(g, case);
        let bbox = wins_bbox(&rect_cen(rect), [&w[0], &w[1], &w[2]])?;
        let area = doubled_area(p);
        (area != 0).then_some((rect, p, bbox, area))
    }

    /// `strip_lanes_avx2` against `wins_bbox` and the 2x2 test of `geom_small_lanes_avx2`
    /// (in i64) on 400k random triangles of window records (`case_records`: coordinates
    /// anywhere in the snapped range, at its clamps, on and around pixel centres, near one
    /// another) in the framebuffer's, unbounded, and tiny or empty random rectangles: the same
    /// box, or none, and the same size class.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn strip_lanes_are_wins_bbox() {
        let (mut g, mut boxes, mut small) = (Gen(0x5157_a9e1), 0, 0);
        if !has_avx2("strip_lanes_avx2") {
            return;
        }
        for case in 0..400_000usize {
            let (rect, _, w) = case_records(&mut g, case);
            let w = [&w[0], &w[1], &w[2]];
            let rc = rect_cen(rect);
            let want = wins_bbox(&rc, w).map(|b| {
                let size = |lo: i32, hi: i32| i64::from(hi) - i64::from(lo);
                (b, size(b[0], b[2]) <= 1 && size(b[1], b[3]) <= 1)
            });
            // SAFETY: the CPU has AVX2 (checked above), and this test is compiled for it
            // only inside the function (`strip_lanes_avx2` is inlined where it is called).
            let got = unsafe { lanes(&rc, w) }.map(|l| (l.bbox, l.small));
            assert_eq!(
                got,
                want,
                "case {case}: rect {rect:?}, {:?}",
                w.map(|v| (v.fx, v.fy))
            );
            boxes += usize::from(want.is_some());
            small += usize::from(want.is_some_and(|(_, s)| s));
        }
        assert!(
            boxes > 100_000 && small > 20_000,
            "{boxes} boxes, {small} small"
        );

        #[target_feature(enable = "avx2")]
        unsafe fn lanes(rc: &[i32; 4], w: [&Win; 3]) -> Option<super::StripLanes> {
            // SAFETY: compiled for AVX2; the caller checked the CPU.
            unsafe { strip_lanes_avx2(rc, w) }
        }
    }

    /// `i64_lanes_f64` against `as f64` on random i64 of every magnitude (and the extremes),
    /// bit for bit.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn i64_lanes_are_as_f64() {
        use std::arch::x86_64::{_mm256_loadu_si256, _mm256_storeu_pd};
        if !has_avx2("i64_lanes_f64") {
            return;
        }
        let mut g = Gen(0x5eed_1164);
        for case in 0..100_000 {
            let v: [i64; 4] = std::array::from_fn(|i| match (case + i) % 5 {
                0 => [i64::MIN, i64::MAX, 0, -1, 1 << 53, (1 << 53) + 1][(g.next() % 6) as usize],
                1 => (g.next() as i64) - (1 << 52),
                _ => ((g.next() << 11) ^ g.next()) as i64 >> (g.next() % 64),
            });
            let mut got = [0.0f64; 4];
            // SAFETY: the CPU has AVX2 (detected above); the load reads the four i64 of `v`
            // and the store writes the four f64 of `got`.
            unsafe {
                let f = super::i64_lanes_f64(_mm256_loadu_si256(v.as_ptr().cast()));
                _mm256_storeu_pd(got.as_mut_ptr(), f);
            }
            for i in 0..4 {
                assert_eq!(got[i].to_bits(), (v[i] as f64).to_bits(), "{}", v[i]);
            }
        }
    }

    /// `Worker::emit_colour_avx2` against `Worker::emit_tri` on the triangles of
    /// `small_case` that `geom_small_avx2` places (edges far past 2^51 among them), with
    /// random z, 1/w and colours (NaN, ±0, huge), facing, polygon offset on and off: the same
    /// primitive and the same fifteen floats, bit for bit.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn colour_lanes_are_emit_tri() {
        use super::{SetupCtx, Worker, F_BACK};
        use crate::cpu::vertex::Layout;
        use crate::state::State;
        if !has_avx2("emit_colour_avx2") {
            return;
        }
        let mut g = Gen(0x5eed_c010);
        let ctxs = [false, true].map(|on| {
            let mut st = State::new(800, 800);
            st.enables.polygon_offset_fill = on;
            st.polygon_offset_factor = 1.5;
            st.polygon_offset_units = -2.0;
            SetupCtx::new(&st, Layout::for_state(&st), [0, 0, 799, 799], (13, 13))
        });
        assert!(ctxs.iter().all(|c| c.rl.n == 4 && !c.flat()));
        let (mut a, mut b) = (Worker::default(), Worker::default());
        for w in [&mut a, &mut b] {
            w.start(&ctxs[0]);
        }
        // Every NaN counted as one value: which operand's NaN a product keeps is the
        // compiler's choice (`lighting::nan_bits`).
        let nan_bits = |v: f32| if v.is_nan() { u32::MAX } else { v.to_bits() };
        let mut n = 0;
        for case in 0..100_000 {
            let Some((_, p, bbox, area)) = small_case(&mut g, case) else {
                continue;
            };
            // SAFETY: the CPU has AVX2 (detected above).
            let Some((geo, cover, l)) = (unsafe { geom_small_avx2(bbox, p, area) }) else {
                continue;
            };
            let ctx = &ctxs[case % 2];
            let z = std::array::from_fn(|_| match g.next() % 8 {
                0 => f64::from(g.float()),
                _ => (g.next() % 1_000_000) as f64 * 1e-6,
            });
            let iw = std::array::from_fn(|_| g.float());
            let q = std::array::from_fn(|_| Vec4::new(g.float(), g.float(), g.float(), g.float()));
            let flags = if g.next() % 2 == 0 { F_BACK } else { 0 };
            let mat = (g.next() % 7) as u32;
            a.emit_tri(ctx, &geo, z, iw, flags, mat, |_| q[0], |j, _| q[j], cover);
            // SAFETY: the CPU has AVX2 (detected above); `l` is `geom_small_avx2`'s.
            unsafe { b.emit_colour_avx2(ctx, &geo, &l, z, iw, flags, mat, q, cover) };
            n += 1;
        }
        assert!(n > 10_000, "only {n} triangles compared");
        assert_eq!(a.prims.len(), b.prims.len());
        // (`Debug` writes every field, each float as the shortest decimal that reads back as
        // it, and every NaN as `NaN`.)
        for (i, (x, y)) in a.prims.iter().zip(&b.prims).enumerate() {
            assert_eq!(format!("{x:?}"), format!("{y:?}"), "primitive {i}");
        }
        assert_eq!(a.pool.len(), b.pool.len());
        for (i, (&x, &y)) in a.pool.iter().zip(&b.pool).enumerate() {
            assert_eq!(nan_bits(x), nan_bits(y), "pool float {i}: {x} against {y}");
        }
        assert_eq!(a.area, b.area);
        assert_eq!(a.touched, b.touched);
    }

    /// `geom_small_avx2` against `geom_placed` and `Geom::coverage` on random triangles a few
    /// pixels across near the grid's centres (ties at centres and on 1/128 steps, every
    /// owned-edge pattern, either winding), some with a vertex far away or at the snap limits
    /// and the box cut by the rectangle: the same `Geom`, field for field, and the same cover
    /// for every box of at most 2x2 pixels, and `None` exactly for the larger ones.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn geom_small_is_geom() {
        if !has_avx2("geom_small_avx2") {
            return;
        }
        let mut g = Gen(0x5eed_2c2c);
        let (mut small, mut covered, mut large) = (0, 0, 0);
        for case in 0..200_000 {
            let Some((rect, p, bbox, area)) = small_case(&mut g, case) else {
                continue;
            };
            let want = geom_placed(bbox, p, area);
            let want_cover = want.coverage();
            // SAFETY: the CPU has AVX2 (detected above).
            match unsafe { geom_small_avx2(bbox, p, area) } {
                None => {
                    assert_eq!(want_cover, 0, "case {case}: {p:?} in {rect:?}");
                    large += 1;
                }
                Some((got, cover, _)) => {
                    assert_eq!(
                        fields(Some(got)),
                        fields(Some(want)),
                        "case {case}: {p:?} in {rect:?}"
                    );
                    assert_eq!(cover, want_cover, "case {case}: {p:?} in {rect:?}");
                    small += 1;
                    covered += usize::from(cover != COVER_KNOWN);
                }
            }
        }
        assert!(
            small > 20_000 && covered > 5_000 && large > 5_000,
            "too few of a kind: {small} small, {covered} covering, {large} large"
        );
    }

    #[test]
    fn default_win_is_consistent() {
        let w = Win::default();
        assert_eq!(w.cen, cen(0, 0));
        assert_eq!(w.cen, [0, 0, 1, 1]);
    }
}
