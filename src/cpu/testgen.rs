//! The small deterministic generator the CPU modules' unit tests draw their inputs from (a
//! 64-bit LCG, Knuth's MMIX constants): the same seed gives the same cases on every machine.

/// The eight comparison functions (DepthFunc, AlphaFunc, StencilFunc), in enum order.
pub(crate) const COMPARE_FUNCS: [u32; 8] = [
    crate::gl::NEVER,
    crate::gl::LESS,
    crate::gl::EQUAL,
    crate::gl::LEQUAL,
    crate::gl::GREATER,
    crate::gl::NOTEQUAL,
    crate::gl::GEQUAL,
    crate::gl::ALWAYS,
];

/// The six minification filters (TEXTURE_MIN_FILTER), NEAREST and LINEAR then the mipmap
/// filters in enum order.
pub(crate) const MIN_FILTERS: [u32; 6] = [
    crate::gl::NEAREST,
    crate::gl::LINEAR,
    crate::gl::NEAREST_MIPMAP_NEAREST,
    crate::gl::LINEAR_MIPMAP_NEAREST,
    crate::gl::NEAREST_MIPMAP_LINEAR,
    crate::gl::LINEAR_MIPMAP_LINEAR,
];

/// The varying layout of a flush whose first `units` units carry coordinates: the colour, then
/// each unit's s, t, r and q.
pub(crate) fn tex_layout(units: usize) -> crate::cpu::setup::RLayout {
    let mut rl = crate::cpu::setup::RLayout {
        n: 4,
        ..Default::default()
    };
    for t in rl.tex.iter_mut().take(units) {
        *t = Some(rl.n);
        rl.n += 4;
    }
    rl
}

pub(crate) struct Gen(pub u64);

impl Gen {
    pub fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 11
    }

    /// One of `v`.
    pub fn pick(&mut self, v: &[u32]) -> u32 {
        v[(self.next() % v.len() as u64) as usize]
    }

    /// An awkward float: NaN, -0, any bit pattern (tiny, huge, infinite), or an ordinary value
    /// around [0, 1].
    pub fn float(&mut self) -> f32 {
        match self.next() % 10 {
            0 => f32::NAN,
            1 => -0.0,
            2 => f32::from_bits(self.next() as u32),
            3 => (self.next() % 2000) as f32 * 1e-3 - 0.5,
            _ => (self.next() % 1_000_000) as f32 * 1e-6 * 1.5 - 0.25,
        }
    }

    /// A float mostly in [-0.25, 1.25], now and then NaN or huge.
    pub fn mostly_unit(&mut self) -> f32 {
        match self.next() % 40 {
            0 => f32::NAN,
            1 => 1e30,
            _ => (self.next() % 1_000_000) as f32 * 1.5e-6 - 0.25,
        }
    }

    /// A byte, 0 and 255 more often than the others.
    pub fn byte(&mut self) -> u8 {
        match self.next() % 6 {
            0 => 0,
            1 => 255,
            _ => self.next() as u8,
        }
    }
}

/// A small triangle's rows in the tile at window (`tx`, `ty`) for `FragCtx::tri_rows`: 1 to
/// 12 consecutive rows from a random one, each from an x drifting by up to two pixels and
/// up to `len - 1` pixels long, clipped to the tile.
pub(crate) fn tri_rows_in_tile(
    next: &mut dyn FnMut() -> u64,
    tx: i32,
    ty: i32,
    len: u64,
) -> Vec<[i32; 3]> {
    use crate::cpu::framebuffer::TILE;
    let y0 = ty + (next() % TILE as u64) as i32;
    let nrows = 1 + (next() % 12) as i32;
    let mut x = tx + (next() % TILE as u64) as i32;
    let mut rows = Vec::new();
    for y in y0..(y0 + nrows).min(ty + TILE as i32) {
        x = (x + (next() % 5) as i32 - 2).clamp(tx, tx + TILE as i32 - 1);
        let x1 = (x + (next() % len) as i32).min(tx + TILE as i32 - 1);
        rows.push([y, x, x1]);
    }
    rows
}

/// What `f.tri_rows` of `rows` of `p` leaves in a tile at window (`tx`, `ty`) with colours
/// `color` and depths `depth` (one buffer of each): with AVX2 where `avx2` (else the SSE2
/// routes, `lanes::NO_AVX2`), whether the rows took the packed route and its fused groups
/// (`FragCtx::packs`), the colours, the depths and the occlusion count.
#[allow(clippy::too_many_arguments)]
pub(crate) fn tri_rows_on(
    f: &crate::cpu::fragment::FragCtx,
    p: &crate::cpu::setup::RPrim,
    planes: &[f32],
    rows: &[[i32; 3]],
    color: &[[u8; 4]],
    depth: &[u32],
    (tx, ty): (i32, i32),
    avx2: bool,
) -> ((bool, bool), Vec<[u8; 4]>, Vec<u32>, u64) {
    let (mut c, mut d, mut s) = (color.to_vec(), depth.to_vec(), vec![0u8; depth.len()]);
    let mut bufs = tile_bufs(&mut c, &mut d, &mut s, (tx, ty));
    crate::cpu::lanes::NO_AVX2.with(|x| x.set(!avx2));
    let packs = f.packs(&bufs, p, planes, rows);
    f.tri_rows(&mut bufs, p, planes, rows, &mut None);
    crate::cpu::lanes::NO_AVX2.with(|x| x.set(false));
    let samples = bufs.samples;
    (packs, c, d, samples)
}

/// A tile's buffers' contents drawn from `g`: colours of any bytes, depths on the quarters
/// of the depth range (so that depth planes meet them exactly: the ties), stencil zero.
pub(crate) fn tile_contents(g: &mut Gen) -> (Vec<[u8; 4]>, Vec<u32>, Vec<u8>) {
    use crate::cpu::framebuffer::{DEPTH_MAX, TILE};
    let color = (0..TILE * TILE)
        .map(|_| (g.next() as u32).to_le_bytes())
        .collect();
    let depth = (0..TILE * TILE)
        .map(|_| (g.next() % 5) as u32 * (DEPTH_MAX / 4))
        .collect();
    (color, depth, vec![0u8; TILE * TILE])
}

/// The tile at window (`tx`, `ty`) with colours `color` (one buffer), depths `depth` and
/// stencil values `stencil`, no samples counted yet.
pub(crate) fn tile_bufs<'a>(
    color: &'a mut [[u8; 4]],
    depth: &'a mut [u32],
    stencil: &'a mut [u8],
    (tx, ty): (i32, i32),
) -> crate::cpu::fragment::TileBufs<'a> {
    crate::cpu::fragment::TileBufs {
        color,
        color2: None,
        depth,
        stencil,
        x: tx,
        y: ty,
        samples: 0,
    }
}

/// `f.tri_rows` of `rows` of `p` in the tile at window `tile` with random colours and depths
/// drawn from `next`: with AVX2 against the SSE2 routes (`tri_rows_on`), byte for byte in
/// colour, depth and the occlusion count (a panic naming the rows where they differ).
/// Returns whether the AVX2 run took the packed route and its fused groups
/// (`FragCtx::packs`), and the rows' pixels.
pub(crate) fn tri_rows_agree(
    f: &crate::cpu::fragment::FragCtx,
    p: &crate::cpu::setup::RPrim,
    planes: &[f32],
    rows: &[[i32; 3]],
    tile: (i32, i32),
    next: &mut dyn FnMut() -> u64,
) -> (bool, bool, usize) {
    use crate::cpu::framebuffer::{DEPTH_MAX, TILE};
    let color: Vec<[u8; 4]> = (0..TILE * TILE)
        .map(|_| (next() as u32).to_le_bytes())
        .collect();
    let depth: Vec<u32> = (0..TILE * TILE)
        .map(|_| (next() % 5) as u32 * (DEPTH_MAX / 4))
        .collect();
    let run = |avx2: bool| tri_rows_on(f, p, planes, rows, &color, &depth, tile, avx2);
    let ((packs, fused), c, d, samples) = run(true);
    let ((never, _), c2, d2, samples2) = run(false);
    assert!(!never, "the SSE2 route packs");
    assert!(
        c == c2 && d == d2 && samples == samples2,
        "the packed and row routes differ (packed {packs}, fused {fused}, rows {rows:?})"
    );
    let n = rows.iter().map(|r| (r[2] - r[1] + 1) as usize).sum();
    (packs, fused, n)
}

/// A fragment context of layout `rl` and texturing units `tex` without per-fragment
/// operations or lighting, one colour buffer written whole, its depth test (enabled three
/// times in four), function, mask, occlusion count and polygon stipple (one time in six)
/// drawn from `next`.
pub(crate) fn tex_ctx<'a>(
    rl: crate::cpu::setup::RLayout,
    tex: [Option<(&'a crate::cpu::texture::Sampler, usize)>; crate::state::MAX_TEXTURE_UNITS],
    next: &mut dyn FnMut() -> u64,
) -> crate::cpu::fragment::FragCtx<'a> {
    crate::cpu::fragment::FragCtx {
        depth_test: next() % 4 != 0,
        depth_func: COMPARE_FUNCS[(next() % 8) as usize],
        depth_mask: next() % 2 == 0,
        color_mask: [true; 4],
        color_sum: false,
        rl,
        lighting: None,
        mats: &[],
        count: false,
        samples: next() % 2 == 0,
        stipple: (next() % 6 == 0).then(|| std::array::from_fn(|_| next() as u32)),
        ops: None,
        tex,
        crossbar: crate::cpu::fragment::crossbar(&tex),
    }
}
