//! The fused textured group (AVX2): for a span whose state is the common one — one 2D unit
//! with [`Sampler::lanes_ok`], REPEAT or CLAMP_TO_EDGE on s and t (or LINEAR without mipmaps
//! with CLAMP_TO_BORDER or LINEAR's CLAMP on s or t: `dense_border8`'s border texel, as
//! [`border_bilinear`]), the MODULATE or REPLACE
//! environment on an RGBA or RGB texture without depth comparison, or a depth texture's
//! comparison (NEAREST on the base level, DEPTH_TEXTURE_MODE LUMINANCE) under the BLEND
//! environment (shadow-map's state: r/q compared with the stored depth as `dense_depth8`
//! does, then Cf·(1 - L) + Cc·L as `env_of`), no colour sum, one colour buffer
//! written whole — eight fragments go from the planes to the RGBA8 store in registers: 1/w and
//! the varyings, s/q and t/q, the level choice ([`Sampler::select_lanes`]), the one or two
//! levels' filter on a [`dense_level`] with plain 16-byte texel loads (no gathers), the level
//! blend, the environment and the unorm8 pack. Each lane computes the expressions of the
//! general path (`lanes::varyings`, [`Sampler::texels_lanes`], `env_of`, `store_pixels`) in
//! the same order, so each pixel has the same bytes; a group whose lanes fall on different
//! levels or filters, or whose level is not dense, takes [`Sampler::texels_lanes`] for its
//! texels and goes on in registers.

#[cfg(target_arch = "x86_64")]
use super::{border_linear8, AX_BORDER, AX_CLAMP, AX_EDGE, AX_REPEAT};
#[cfg(target_arch = "x86_64")]
use super::{compare8, dense_level, ifloor8, linear_axis8_of, wrap8, Route};
use super::{Sampler, LANES};
use crate::gl;

/// A span's fused route: the unit's sampler, its coordinates' varying and the state chosen
/// once ([`FusedSpan::new`]).
#[derive(Clone, Copy, Debug)]
pub struct FusedSpan<'a> {
    s: &'a Sampler,
    /// REPEAT on s (else CLAMP_TO_EDGE), on t.
    rep: [bool; 2],
    /// LINEAR on the base level with a border texel ([`border_linear`]): `border_kind`'s
    /// code of the wrap classes (`rep` unused then), else None.
    border: Option<u8>,
    /// The environment: REPLACE, MODULATE, or BLEND of a depth comparison's LUMINANCE.
    env: Env,
    /// TEXTURE_COMPARE_FUNC of a depth texture's comparison (NEAREST on the base level,
    /// DEPTH_TEXTURE_MODE LUMINANCE, env BLEND), else None.
    depth: Option<u32>,
    /// TEXTURE_ENV_COLOR's RGB and 0, twice (BLEND's Cc as `env_of` reads it).
    cc: [f32; 8],
    /// r's row plane (constant, x step, y term), and whether r is smooth (only read with
    /// `depth`).
    rpl: [f32; 3],
    rdiv: bool,
    /// An RGB texture (the fragment's alpha passes).
    rgb: bool,
    /// The row's y terms `dy·fy` of the planes of 1/w, the colour's four varyings and s, t,
    /// q, and those planes' `dy` (a row moves only the y terms: [`FusedSpan::row`] takes
    /// eight products instead of the eight planes again, ≈45 instructions a row).
    yt: [f32; 8],
    dy: [f32; 8],
    /// Those planes' constants and x steps (the primitive's: the same for every row) on eight
    /// lanes each, so that a group reads them as memory operands instead of broadcasting them.
    pad: [[[f32; LANES]; 2]; 8],
    /// The primitive's planes (`rpl` and `lp` of another row are taken from them again,
    /// [`FusedSpan::row`]) and the coordinates' first varying.
    planes: &'a [f32],
    to: usize,
    /// Which of the colour, s, t, q varyings are smooth (multiplied by 1/w).
    div: [bool; 7],
    /// `div`'s pattern where the colour route skips its seven tests (`DIV`): `DIV_COORDS`
    /// (s, t, q smooth, the colour not), `DIV_ALL` (every one), else `DIV_ANY`.
    divs: u8,
    /// The colour loops' level state (`LIN_CLAMP`, `LIN_REPEAT`: LINEAR without mipmaps, no
    /// depth comparison, no border texel, the same repeat flag on both axes; the base level
    /// then looked up once a span, [`FusedSpan::lin_groups`]), else `LIN_NONE`.
    lin: u8,
    /// The levels looked up last: their numbers and views.
    cache: [(i32, View<'a>); 2],
    /// Window x of the planes' origin.
    ox: i32,
    /// λ's planes of s, t and q: constant, x step, y term at the quad row's y and at one
    /// more (`quad_lambda_lanes`' `qy` and `qy + 1`).
    lp: [[f32; 4]; 3],
    /// The LOD route's level choice per quad of the row ([`Sampler::select_lanes`] of each
    /// quad's λ, [`FusedSpan::lambda_quads`]): quad k at window x `qbase + 2k`, its level
    /// `qlv[k]`, weight `qf[k]`, filter bit k of `qlin`. Computed eight quads (sixteen
    /// pixels) at a time as the groups reach them: block b (quads 8b..8b + 8) when bit b of
    /// `qdone` is set; `qbase` is the first group's quad after `new`, after `row` moved the
    /// route to another quad row, or when a group's quads fall outside those kept.
    qlv: [i32; QUADS],
    qf: [f32; QUADS],
    qlin: u64,
    qbase: i32,
    qdone: u8,
    /// The quad row's y of `lp` and the quads (`new`'s or `row`'s `qy`): the two rows of a
    /// quad row share them.
    qy: f32,
}

/// The quads [`FusedSpan`] keeps the level choice of: a row of 64 pixels from any x touches
/// 33 quads, five blocks of eight.
const QUADS: usize = 40;

/// [`FusedSpan`]'s `divs`: the varyings' division by w tested one by one (`div`); s, t and q
/// divided and the colour not; every one divided. (Each a copy of the colour route, the
/// `DIV` of [`FusedSpan::colors`], [`FusedSpan::texels`] and [`FusedSpan::quads_select`]:
/// each copy's one caller inlines it.)
const DIV_ANY: u8 = 0;
const DIV_COORDS: u8 = 1;
const DIV_ALL: u8 = 2;

/// The colour route's `LIN` (its loops' level state, [`FusedSpan`]'s `lin`): the level
/// looked up in each group (`texels`, `level_linear`); LINEAR without mipmaps on a dense base
/// level looked up once for the span, CLAMP_TO_EDGE on both axes, or REPEAT on both (`bilinear!`
/// inline: no call, no cache test and no dispatch on the repeat flags a group, ≈34
/// instructions of a point-sprites group's ≈227 in `level_linear`).
const LIN_NONE: u8 = 0;
const LIN_CLAMP: u8 = 1;
const LIN_REPEAT: u8 = 2;

/// Bit i of the index set in bits 2i and 2i + 1: a group's filter bits from its quads' (lane
/// pairs share a quad).
const DOUBLE: [u16; 32] = {
    let mut t = [0u16; 32];
    let mut v = 0;
    while v < 32 {
        let mut i = 0;
        while i < 5 {
            if v & (1 << i) != 0 {
                t[v] |= 3 << (2 * i);
            }
            i += 1;
        }
        v += 1;
    }
    t
};

/// The environments the route computes (`env_of`'s arms).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Env {
    /// MODULATE on RGBA or RGB.
    Modulate,
    /// REPLACE on RGBA or RGB.
    Replace,
    /// BLEND on a depth texture read as LUMINANCE: Cf·(1 - L) + Cc·L, the fragment's alpha.
    BlendLum,
}

/// A level as the route reads it.
#[derive(Clone, Copy, Debug)]
enum View<'a> {
    /// Not looked up yet (the cache's initial state).
    Unknown,
    /// No such level: (0, 0, 0, 0).
    Missing,
    /// Not [`dense_level`]: the group takes `texels_lanes`.
    Sparse,
    /// A dense level with a texel.
    Dense(DenseLevel<'a>),
}

/// A [`dense_level`] with a texel as the route's kernels read it: its texels, width and
/// height (each at least 1, w·h texels, powers of two), and the constants the kernels derive
/// from the sizes, taken once when the level is looked up ([`FusedSpan::view`]) instead of in
/// each group: the sizes as f32 (the axes' `n as f32`), less one (the wraps' masks) and the
/// row shift (j·w as j << log2 w). (Converted and broadcast in each group they were ≈15
/// instructions of a LINEAR group's ≈220 on textured-cube.)
#[derive(Clone, Copy, Debug)]
struct DenseLevel<'a> {
    dt: &'a [[f32; 4]],
    w: i32,
    h: i32,
    wf: f32,
    hf: f32,
    wm1: i32,
    hm1: i32,
    sh: i32,
}

impl<'a> DenseLevel<'a> {
    /// The level of texels `dt`, `w` x `h`, which [`dense_level`] accepts (w, h ≥ 1).
    fn new(dt: &'a [[f32; 4]], w: i32, h: i32) -> DenseLevel<'a> {
        let (w, h) = (w.max(1), h.max(1));
        DenseLevel {
            dt,
            w,
            h,
            wf: w as f32,
            hf: h as f32,
            wm1: w - 1,
            hm1: h - 1,
            sh: w.trailing_zeros() as i32,
        }
    }
}

/// Where a group's eight lanes lie, as [`FusedSpan`]'s kernels read them (their `PACK`):
/// false, a row's pixels from window x `x` (lane l at x + l; the row's y terms in `pl`,
/// `rpl` and `lp`); true, a packed group's ([`FusedSpan::packed_group`]: lane l at its own
/// pixel, the route set up at y 1 so that those y terms are the planes' ∂y).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Lanes {
    /// The row group's first window x (unused when packed).
    x: i32,
    /// Each lane's x relative to the planes' origin.
    xs: std::arch::x86_64::__m256,
    /// Packed only: each lane's y relative to the origin, its quad's lower-left window x
    /// (even) and that quad's y relative to the origin.
    ys: std::arch::x86_64::__m256,
    qi: std::arch::x86_64::__m256i,
    qy: std::arch::x86_64::__m256,
}

/// The four corners of `bilinear!` (indices `$k00`, `$k10`, `$k01`, `$k11` of level texels
/// `$dt`, each taken modulo `$dt.len()` as [`load_pairs`] takes them) as pixel-major pairs.
/// Where every lane's `k10` is its `k00` + 1 and its `k11` its `k01` + 1 (no lane's row wraps,
/// the common case), each row's two texels come from one address a lane; where moreover every
/// lane's `k01` is its `k00` + `$w` (the level's width: no lane's column wraps either), the
/// four from one address a lane (eight extractions instead of sixteen); the same texels
/// either way. The value is `$sum` (a closure) of the corners, called in each branch: with
/// the sixteen registers merged after the branches, six of them went through the stack in
/// each call. (A macro: as a function it stayed out of line, called from `level`'s four
/// bilinear kernels.)
#[cfg(target_arch = "x86_64")]
macro_rules! load_corners {
    ($dt:expr, $w:expr, $k00:expr, $k10:expr, $k01:expr, $k11:expr, $sum:expr) => {{
        let sum = $sum;
        let dt: &[[f32; 4]] = $dt;
        let w: i32 = $w;
        let (k00, k10, k01, k11) = ($k00, $k10, $k01, $k11);
        let km = dt.len().wrapping_sub(1);
        if dt.is_empty() || km >= 1 << 28 {
            sum([
                load_pairs(dt, k00),
                load_pairs(dt, k10),
                load_pairs(dt, k01),
                load_pairs(dt, k11),
            ])
        } else {
            let kmv = _mm256_set1_epi32(km as i32);
            let (k00, k10) = (_mm256_and_si256(k00, kmv), _mm256_and_si256(k10, kmv));
            let (k01, k11) = (_mm256_and_si256(k01, kmv), _mm256_and_si256(k11, kmv));
            let one = _mm256_set1_epi32(1);
            let next = _mm256_and_si256(
                _mm256_cmpeq_epi32(k10, _mm256_add_epi32(k00, one)),
                _mm256_cmpeq_epi32(k11, _mm256_add_epi32(k01, one)),
            );
            let down = _mm256_cmpeq_epi32(k01, _mm256_add_epi32(k00, _mm256_set1_epi32(w)));
            let (o0, o1) = (_mm256_slli_epi32::<4>(k00), _mm256_slli_epi32::<4>(k01));
            if _mm256_movemask_epi8(_mm256_and_si256(next, down)) == -1 {
                // SAFETY: every lane has k00 + 1 = k10, k00 + w = k01 and k01 + 1 = k11, each
                // at most km < 2^28 (w > 0: k01 > k00 as integers below 2^28): the texels
                // k00, k00 + 1, k00 + w and k00 + w + 1 lie inside `dt` and 16·k fits a u32.
                unsafe {
                    let r = w as usize;
                    sum([
                        load_at::<0>(dt, o0, 0),
                        load_at::<1>(dt, o0, 0),
                        load_at::<0>(dt, o0, r),
                        load_at::<1>(dt, o0, r),
                    ])
                }
            } else if _mm256_movemask_epi8(next) == -1 {
                // SAFETY: every lane has k00 + 1 = k10 <= km and k01 + 1 = k11 <= km,
                // km < 2^28: the texels k00, k00 + 1, k01 and k01 + 1 lie inside `dt` and 16·k
                // fits a u32.
                unsafe {
                    sum([
                        load_at::<0>(dt, o0, 0),
                        load_at::<1>(dt, o0, 0),
                        load_at::<0>(dt, o1, 0),
                        load_at::<1>(dt, o1, 0),
                    ])
                }
            } else {
                // SAFETY: every lane of each index is at most km < 2^28: inside `dt`, and 16·k
                // fits a u32.
                unsafe {
                    sum([
                        load_at::<0>(dt, o0, 0),
                        load_at::<0>(dt, _mm256_slli_epi32::<4>(k10), 0),
                        load_at::<0>(dt, o1, 0),
                        load_at::<0>(dt, _mm256_slli_epi32::<4>(k11), 0),
                    ])
                }
            }
        }
    }};
}

/// `dense_linear8`'s wraps, weights and indices on level `$lv` (a `&DenseLevel`) at `$s`,
/// `$t`, REPEAT on s `$rx`, on t `$ry` (else CLAMP_TO_EDGE), the four corners loaded per lane
/// and summed pixel-major: (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11 in that order
/// per channel. A row's two corners come from one address a lane where no lane's pair wraps
/// (`load_corners`): the same texels. (A macro: as a function LLVM left it out of line, or
/// inlined it, depending on how many callers it had: `FusedSpan::level_linear`'s four
/// instances and the colour route's `LIN` loops, which took it out of line for all of them.)
#[cfg(target_arch = "x86_64")]
macro_rules! bilinear {
    ($rx:literal, $ry:literal, $lv:expr, $s:expr, $t:expr) => {{
        let lv: &DenseLevel = $lv;
        let (x0, x1, a) = linear_axis8_of::<$rx>($s, lv.wf, lv.wm1);
        let (y0, y1, b) = linear_axis8_of::<$ry>($t, lv.hf, lv.hm1);
        let sh = _mm_cvtsi32_si128(lv.sh);
        let (r0, r1) = (_mm256_sll_epi32(y0, sh), _mm256_sll_epi32(y1, sh));
        load_corners!(
            lv.dt,
            lv.w,
            _mm256_add_epi32(r0, x0),
            _mm256_add_epi32(r0, x1),
            _mm256_add_epi32(r1, x0),
            _mm256_add_epi32(r1, x1),
            |c: [[__m256; 4]; 4]| corner_sum(a, b, &c)
        )
    }};
}

impl<'a> FusedSpan<'a> {
    /// Does the route cover sampler `s`'s state (the checks of [`FusedSpan::new`] on the
    /// sampler alone, cheap enough for the caller to make before the call)?
    #[inline(always)]
    pub fn covers(s: &Sampler) -> bool {
        let edge = |m: u32| m == gl::REPEAT || m == gl::CLAMP_TO_EDGE;
        let color = s.compare.is_none()
            && (s.env == gl::MODULATE || s.env == gl::REPLACE)
            && (s.base == gl::RGBA || s.base == gl::RGB);
        cfg!(target_arch = "x86_64")
            && s.dims == 2
            && !s.cube
            && !s.crossbar
            && (color || depth_blend(s))
            && (edge(s.wrap[0]) && edge(s.wrap[1]) || border_linear(s).is_some())
    }

    /// The fused route of sampler `s` whose coordinates are varyings `to..to + 4`, or None
    /// when its state is not the one the route covers (see the module documentation; the
    /// caller checks the rest of the span's state).
    /// `planes` must hold the 1/w plane and the planes of the `nv` varyings (the first
    /// `nflat` flat), with `to + 4 <= nv`; `fy` is the row's y relative to the planes' origin.
    #[inline(always)]
    pub fn new(
        s: &'a Sampler,
        to: usize,
        planes: &'a [f32],
        nflat: usize,
        fy: f32,
        ox: i32,
        qy: f32,
    ) -> Option<FusedSpan<'a>> {
        let rep = |mode: u32| match mode {
            gl::REPEAT => Some(true),
            gl::CLAMP_TO_EDGE => Some(false),
            _ => None,
        };
        if cfg!(not(target_arch = "x86_64")) || s.dims != 2 || s.cube || s.crossbar {
            return None;
        }
        let (env, depth) = match (s.compare, s.env, s.base) {
            (None, gl::MODULATE, gl::RGBA | gl::RGB) => (Env::Modulate, None),
            (None, gl::REPLACE, gl::RGBA | gl::RGB) => (Env::Replace, None),
            (Some(func), _, _) if depth_blend(s) => (Env::BlendLum, Some(func)),
            _ => return None,
        };
        let (rep, border) = match (rep(s.wrap[0]), rep(s.wrap[1])) {
            (Some(x), Some(y)) => ([x, y], None),
            _ => ([false; 2], Some(border_linear(s)?)),
        };
        let div = [0, 1, 2, 3, to, to + 1, to + 3].map(|j| j >= nflat);
        let c = s.env_color;
        let rj = to.checked_add(2)?;
        let pl = row_planes(planes, to)?;
        let dy = pl.map(|[_, _, dy]| dy);
        Some(FusedSpan {
            s,
            rep,
            border,
            env,
            depth,
            cc: [c.x, c.y, c.z, 0.0, c.x, c.y, c.z, 0.0],
            rpl: r_plane(planes, rj, fy)?,
            rdiv: rj >= nflat,
            rgb: s.base == gl::RGB,
            yt: dy.map(|dy| dy * fy),
            dy,
            pad: pl.map(|[a, dx, _]| [[a; LANES], [dx; LANES]]),
            planes,
            to,
            div,
            // (`div`'s patterns: 0 >= nflat; 3 < nflat <= to.)
            divs: if nflat == 0 {
                DIV_ALL
            } else if (4..=to).contains(&nflat) {
                DIV_COORDS
            } else {
                DIV_ANY
            },
            lin: match (s.route, depth, border, rep) {
                (Route::Linear, None, None, [false, false]) => LIN_CLAMP,
                (Route::Linear, None, None, [true, true]) => LIN_REPEAT,
                _ => LIN_NONE,
            },
            cache: [(0, View::Unknown); 2],
            ox,
            // (λ's planes are read on the LOD route only.)
            lp: if s.route == Route::Lod {
                lambda_planes(planes, to, qy)
            } else {
                [[0.0; 4]; 3]
            },
            qlv: [0; QUADS],
            qf: [0.0; QUADS],
            qlin: 0,
            qbase: 0,
            qdone: 0,
            qy,
        })
    }

    /// Moves the route to another row of the same primitive: `fy` the row's y relative to
    /// the planes' origin, `qy` its quad row's (the levels looked up stay, and on the same
    /// quad row λ's planes and the quads' level choice too: a quad's λ depends on its window
    /// x and `qy` alone).
    #[inline]
    pub fn row(&mut self, fy: f32, qy: f32) {
        // (The planes' constants and x steps are the primitive's: `pad`, kept.)
        self.yt = self.dy.map(|dy| dy * fy);
        if self.depth.is_some() {
            if let Some(rp) = r_plane(self.planes, self.to + 2, fy) {
                self.rpl = rp;
            }
        }
        if self.s.route == Route::Lod && qy.to_bits() != self.qy.to_bits() {
            self.lp = lambda_planes(self.planes, self.to, qy);
            self.qy = qy;
            self.qdone = 0;
        }
    }

    /// The group of eight fragments from window x `x` (lane l at x + l), lanes `m`: their
    /// colours stored into `dst` (a lane l into `dst[l]`), what `tri_span`'s general path
    /// stores for them (`tex_pixels`, then `store_pixels`).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub unsafe fn group(&mut self, x: i32, m: u8, dst: &mut [[u8; 4]]) {
        if let Some(func) = self.depth {
            // SAFETY: the CPU has AVX2 (the caller's promise).
            let done = unsafe {
                match u8::from(self.rep[0]) | u8::from(self.rep[1]) << 1 {
                    0 => self.depth_group::<false, false>(func, x, m, dst),
                    1 => self.depth_group::<true, false>(func, x, m, dst),
                    2 => self.depth_group::<false, true>(func, x, m, dst),
                    _ => self.depth_group::<true, true>(func, x, m, dst),
                }
            };
            if done {
                return;
            }
        }
        // SAFETY: the CPU has AVX2 (the caller's promise).
        unsafe { store_group(self.colors::<DIV_ANY>(x, m), m, dst) }
    }

    /// [`FusedSpan::group`] for each group of the span of `n` pixels (at most 64) from
    /// window x `x0`, lanes `mask` (bit i for pixel x0 + i), pixel i stored into `dst[i]`:
    /// the groups with a lane in `mask`, in order, as that many `group` calls do. The depth
    /// comparison's state is tested once here instead of once a group.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    pub unsafe fn span(&mut self, x0: i32, n: usize, mask: u64, dst: &mut [[u8; 4]]) {
        // SAFETY: the CPU has AVX2 and POPCNT (the caller's promise).
        unsafe {
            if self.depth.is_some() {
                return self.depth_groups(x0, n, mask, dst);
            }
            let store = |g: usize, m: u8, c| {
                if let Some(d) = dst.get_mut(g..) {
                    store_group(c, m, d);
                }
            };
            if self.lin != LIN_NONE && self.lin_groups(x0, n, mask, store) {
                return;
            }
            // (Each group's level looked up in it: the loop inline here, as before the `LIN`
            // loops; through `colors_loop` projective-texture took 0.6% more.)
            match self.divs {
                DIV_COORDS => self.store_groups::<DIV_COORDS>(x0, n, mask, dst),
                DIV_ALL => self.store_groups::<DIV_ALL>(x0, n, mask, dst),
                _ => self.store_groups::<DIV_ANY>(x0, n, mask, dst),
            }
        }
    }

    /// [`FusedSpan::span`]'s colour groups, `divs` `DIV`, each group's level looked up in it.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn store_groups<const DIV: u8>(
        &mut self,
        x0: i32,
        n: usize,
        mask: u64,
        dst: &mut [[u8; 4]],
    ) {
        each_group(n, mask, |g, m| {
            if let Some(d) = dst.get_mut(g..) {
                let x = x0.wrapping_add(g as i32);
                // SAFETY: the CPU has AVX2 (the caller's promise).
                unsafe { store_group(self.colors::<DIV>(x, m), m, d) };
            }
        });
    }

    /// The groups of the span of `n` pixels (at most 64) from window x `x0` with a lane in
    /// `mask` (bit i for pixel x0 + i), in order, where the route's `lin` is LINEAR without
    /// mipmaps on a dense base level and its `divs` not `DIV_ANY`: `f(g, m, colours)` for the
    /// group of pixels g..g + 8 (lanes `m`), its colours as [`FusedSpan::colors`] gives them,
    /// the level looked up once for the span and its filter inline in the loop (a copy for each
    /// `divs` and repeat flag). False, with nothing done, otherwise.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline]
    unsafe fn lin_groups(
        &mut self,
        x0: i32,
        n: usize,
        mask: u64,
        f: impl FnMut(usize, u8, [std::arch::x86_64::__m256; 4]),
    ) -> bool {
        if self.lin == LIN_NONE {
            return false;
        }
        let Ok(&lv) = self.dense(self.s.base_level) else {
            return false;
        };
        let lin = Some(&lv);
        // SAFETY: the CPU has AVX2 and POPCNT (the caller's promise).
        unsafe {
            match (self.lin, self.divs) {
                (LIN_CLAMP, DIV_COORDS) => {
                    self.colors_loop::<DIV_COORDS, LIN_CLAMP, _>(lin, x0, n, mask, f)
                }
                (LIN_REPEAT, DIV_COORDS) => {
                    self.colors_loop::<DIV_COORDS, LIN_REPEAT, _>(lin, x0, n, mask, f)
                }
                (LIN_CLAMP, DIV_ALL) => {
                    self.colors_loop::<DIV_ALL, LIN_CLAMP, _>(lin, x0, n, mask, f)
                }
                (LIN_REPEAT, DIV_ALL) => {
                    self.colors_loop::<DIV_ALL, LIN_REPEAT, _>(lin, x0, n, mask, f)
                }
                _ => return false,
            }
        }
        true
    }

    /// The groups' colours of [`FusedSpan::span`] channel-major (`out[g][c][l]`: channel c of
    /// lane l), as `tex_span` takes them: group g's (pixels 8g..8g + 8, from window x
    /// `x0 + 8g`) into `out[g]` where it has a lane in `mask` (the other groups' left as they
    /// are), `oplanes::clamp01` of each channel of `color_lanes`, bit for bit. Lanes outside
    /// `mask` hold unspecified values.
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    pub unsafe fn channel_groups(
        &mut self,
        x0: i32,
        n: usize,
        mask: u64,
        out: &mut [[[f32; LANES]; 4]; 64 / LANES],
    ) {
        let mut put = |g: usize, _: u8, p| {
            if let Some(o) = out.get_mut(g / LANES) {
                *o = channel_major(p);
            }
        };
        // SAFETY: the CPU has AVX2 and POPCNT (the caller's promise).
        unsafe {
            if self.lin != LIN_NONE && self.lin_groups(x0, n, mask, &mut put) {
                return;
            }
            match self.divs {
                DIV_COORDS => self.colors_loop::<DIV_COORDS, LIN_NONE, _>(None, x0, n, mask, put),
                DIV_ALL => self.colors_loop::<DIV_ALL, LIN_NONE, _>(None, x0, n, mask, put),
                _ => self.colors_loop::<DIV_ANY, LIN_NONE, _>(None, x0, n, mask, put),
            }
        }
    }

    /// The colour groups' loop ([`FusedSpan::lin_groups`], [`FusedSpan::channel_groups`]):
    /// `f(g, m, colours)` for each group with a lane in `mask`, `divs` `DIV` and the level
    /// state `LIN` (`lin` the level of `LIN_CLAMP` and `LIN_REPEAT`, the group's route inline
    /// here; `LIN_NONE`, [`FusedSpan::colors`] out of line, as each group called it before).
    /// `f` is meant to be small (a store): a large `f` (`fused_tex_rows`' tests and writes)
    /// stayed out of line, called for each group, +6.8% on point-sprites. (The `LIN` copies
    /// end up inlined into `lin_groups` all the same.)
    ///
    /// # Safety
    /// The CPU must have AVX2 and POPCNT (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt")]
    #[inline(never)]
    unsafe fn colors_loop<const DIV: u8, const LIN: u8, F>(
        &mut self,
        lin: Option<&DenseLevel<'a>>,
        x0: i32,
        n: usize,
        mask: u64,
        mut f: F,
    ) where
        F: FnMut(usize, u8, [std::arch::x86_64::__m256; 4]),
    {
        each_group(n, mask, |g, m| {
            let x = x0.wrapping_add(g as i32);
            // SAFETY: the CPU has AVX2 (the caller's promise).
            let c = unsafe {
                if LIN == LIN_NONE {
                    self.colors::<DIV>(x, m)
                } else {
                    self.colors_at::<DIV, false, LIN, F>(self.at_row(x), m, lin)
                }
            };
            f(g, m, c);
        });
    }

    /// A packed group (`FragCtx::packed_rows`): lane l the fragment at window x `x[l]` and y
    /// `y[l]` of the primitive whose planes' origin is at window (`ox`, `oy`), lanes `m`;
    /// their RGBA8 pixels in lane order (lanes outside `m` unspecified), each the bytes
    /// [`FusedSpan::group`] stores for it in its row: each lane the row route's operations
    /// with ∂y·y a product per lane instead of one a row (`varyings_xy_avx2`'s planes),
    /// λ at its own quad (`quad_lambda_xy8`'s) and its level chosen by [`select8`]. The route
    /// must have been set up (`new`, or moved by `row`) at y 1 and quad row 1, so that the
    /// planes' y terms it keeps are their ∂y.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub unsafe fn packed_group(
        &mut self,
        x: &[i32; LANES],
        y: &[i32; LANES],
        oy: i32,
        m: u8,
    ) -> [[u8; 4]; LANES] {
        use std::arch::x86_64::*;
        // SAFETY: each load reads the eight values of `x` or `y` (no alignment needed).
        let (xi, yi) = unsafe {
            (
                _mm256_loadu_si256(x.as_ptr().cast::<__m256i>()),
                _mm256_loadu_si256(y.as_ptr().cast::<__m256i>()),
            )
        };
        // `as f32` of each lane's x - ox, y - oy, and its quad's (x & !1) - ox, (y & !1) - oy.
        let (ox, oy) = (_mm256_set1_epi32(self.ox), _mm256_set1_epi32(oy));
        let even = _mm256_set1_epi32(!1);
        let yq = _mm256_and_si256(yi, even);
        let at = Lanes {
            x: 0,
            xs: _mm256_cvtepi32_ps(_mm256_sub_epi32(xi, ox)),
            ys: _mm256_cvtepi32_ps(_mm256_sub_epi32(yi, oy)),
            qi: _mm256_and_si256(xi, even),
            qy: _mm256_cvtepi32_ps(_mm256_sub_epi32(yq, oy)),
        };
        let v = 'v: {
            if let Some(func) = self.depth {
                let d = match u8::from(self.rep[0]) | u8::from(self.rep[1]) << 1 {
                    0 => self.depth_packed::<false, false>(func, &at),
                    1 => self.depth_packed::<true, false>(func, &at),
                    2 => self.depth_packed::<false, true>(func, &at),
                    _ => self.depth_packed::<true, true>(func, &at),
                };
                if let Some(v) = d {
                    break 'v v;
                }
            }
            // SAFETY: the CPU has AVX2 (the caller's promise).
            pack_group(unsafe {
                match (self.depth.is_some(), self.divs) {
                    (false, DIV_COORDS) => {
                        self.colors_at::<DIV_COORDS, true, LIN_NONE, ()>(at, m, None)
                    }
                    (false, DIV_ALL) => self.colors_at::<DIV_ALL, true, LIN_NONE, ()>(at, m, None),
                    _ => self.colors_at::<DIV_ANY, true, LIN_NONE, ()>(at, m, None),
                }
            })
        };
        // SAFETY: `__m256i` and `[[u8; 4]; 8]` are both 32 bytes, every bit pattern valid.
        unsafe { std::mem::transmute::<__m256i, [[u8; 4]; LANES]>(v) }
    }

    /// [`FusedSpan::span`]'s loop in the depth comparison's state: [`FusedSpan::group`] for
    /// each group (its depth state tested once here instead of once a group).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn depth_groups(&mut self, x0: i32, n: usize, mask: u64, dst: &mut [[u8; 4]]) {
        each_group(n, mask, |g, m| {
            if let Some(d) = dst.get_mut(g..) {
                // SAFETY: the CPU has AVX2 (the caller's promise).
                unsafe { self.group(x0.wrapping_add(g as i32), m, d) };
            }
        });
    }

    /// [`FusedSpan::group`] in the depth comparison's state (`func` its TEXTURE_COMPARE_FUNC,
    /// REPEAT on s `RX`, on t `RY`, as `rep`)
    /// on a dense base level, channel-major: each lane the expressions of
    /// [`FusedSpan::colors`] (its varyings, `nearest`'s texel, `dense_depth8`'s comparison,
    /// BLEND of LUMINANCE, the clamp) in the same order, so the same bytes; the comparison
    /// and the environment on eight lanes at once instead of four pixel-major pairs. False,
    /// with nothing written, where the base level is missing or not dense (the caller then
    /// takes [`FusedSpan::colors`]).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn depth_group<const RX: bool, const RY: bool>(
        &mut self,
        func: u32,
        x: i32,
        m: u8,
        dst: &mut [[u8; 4]],
    ) -> bool {
        let Some(c) = self.depth_colors::<RX, RY, false>(func, &self.at_row(x)) else {
            return false;
        };
        // SAFETY: the CPU has AVX2 (the caller's promise).
        unsafe { store_group(c, m, dst) };
        true
    }

    /// [`FusedSpan::depth_group`] of a packed group (lanes `at`): its eight pixels, None
    /// where the base level is missing or not dense.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    fn depth_packed<const RX: bool, const RY: bool>(
        &mut self,
        func: u32,
        at: &Lanes,
    ) -> Option<std::arch::x86_64::__m256i> {
        Some(pack_group(self.depth_colors::<RX, RY, true>(func, at)?))
    }

    /// The colours (pixel-major pairs, clamped) of [`FusedSpan::depth_group`] at lanes `at`
    /// (`PACK` as [`Lanes`]); None where the base level is missing or not dense.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn depth_colors<const RX: bool, const RY: bool, const PACK: bool>(
        &mut self,
        func: u32,
        at: &Lanes,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        let Ok(&lv) = self.dense(self.s.base_level) else {
            return None;
        };
        let inv = self.inv::<PACK>(at);
        let [ss, tt, rr] = self.coords::<PACK>(at, inv);
        let l = compare8(func, nearest_depth::<RX, RY>(&lv, ss, tt), rr);
        // `env_of`'s BLEND of LUMINANCE: cf·(1 - L) + cc·L on r, g, b, the fragment's alpha;
        // then `Vec4::clamp` (`maxps` with 0, then `minps` with 1).
        let (one, zero) = (_mm256_set1_ps(1.0), _mm256_setzero_ps());
        let nl = _mm256_sub_ps(one, l);
        let [cr, cg, cb, _, ..] = self.cc;
        let env = |cf: __m256, cc: f32| {
            _mm256_add_ps(_mm256_mul_ps(cf, nl), _mm256_mul_ps(_mm256_set1_ps(cc), l))
        };
        let c = [
            env(self.vary::<0, DIV_ANY, PACK>(at, inv), cr),
            env(self.vary::<1, DIV_ANY, PACK>(at, inv), cg),
            env(self.vary::<2, DIV_ANY, PACK>(at, inv), cb),
            self.vary::<3, DIV_ANY, PACK>(at, inv),
        ]
        .map(|c| _mm256_min_ps(_mm256_max_ps(c, zero), one));
        Some(pairs(&c))
    }

    /// Plane `k` of `pl` at lanes `at` (`PACK` as [`Lanes`]): [`plane8l`] of the row, or
    /// [`plane8xy`] of each lane's x and y; its constant and x step from `pad`.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn plane<const PACK: bool>(&self, k: usize, at: &Lanes) -> std::arch::x86_64::__m256 {
        // (k < 8 at every call: the indices are constants in range.)
        if PACK {
            plane8xy(&self.pad[k], self.yt[k], at)
        } else {
            plane8l(&self.pad[k], self.yt[k], at.xs)
        }
    }

    /// The row group from window x `x`: lane l at x + l (`lanes::varyings`' x, fx0 as f32 + l).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn at_row(&self, x: i32) -> Lanes {
        use std::arch::x86_64::*;
        const IOTA: [f32; LANES] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
        // SAFETY: the load reads the eight floats of `IOTA`.
        let xs = _mm256_add_ps(_mm256_set1_ps((x - self.ox) as f32), unsafe {
            _mm256_loadu_ps(IOTA.as_ptr())
        });
        let zero = _mm256_setzero_ps();
        Lanes {
            x,
            xs,
            ys: zero,
            qi: _mm256_setzero_si256(),
            qy: zero,
        }
    }

    /// 1/w at lanes `at` (`lanes::varyings`' `divps`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn inv<const PACK: bool>(&self, at: &Lanes) -> std::arch::x86_64::__m256 {
        use std::arch::x86_64::*;
        _mm256_div_ps(_mm256_set1_ps(1.0), self.plane::<PACK>(0, at))
    }

    /// Varying k of the colour (0..4) and s, t, q (4, 5, 6) at lanes `at` (1/w `inv`): its
    /// plane, times 1/w where smooth (`lanes::varyings`): `div[K]`, or `DIV`'s pattern (the
    /// caller passes `divs`, or `DIV_ANY`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn vary<const K: usize, const DIV: u8, const PACK: bool>(
        &self,
        at: &Lanes,
        inv: std::arch::x86_64::__m256,
    ) -> std::arch::x86_64::__m256 {
        use std::arch::x86_64::*;
        // (K < 7: the indices are constants in range.)
        let v = self.plane::<PACK>(K + 1, at);
        let div = match DIV {
            DIV_ALL => true,
            DIV_COORDS => K >= 4,
            _ => self.div[K],
        };
        if div {
            _mm256_mul_ps(v, inv)
        } else {
            v
        }
    }

    /// s/q, t/q and r/q of the lanes `xs` (1/w `inv`) as `texels_lanes` divides them: 1/q
    /// where q ≠ 0 (a NaN q included), else 0; r (varying `to + 2`) read with a depth
    /// comparison only (else 0). (`FusedSpan::colors` computes the same values and keeps s,
    /// t, q for its fallback.)
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn coords<const PACK: bool>(
        &self,
        at: &Lanes,
        inv: std::arch::x86_64::__m256,
    ) -> [std::arch::x86_64::__m256; 3] {
        use std::arch::x86_64::*;
        let (s, t, q) = (
            self.vary::<4, DIV_ANY, PACK>(at, inv),
            self.vary::<5, DIV_ANY, PACK>(at, inv),
            self.vary::<6, DIV_ANY, PACK>(at, inv),
        );
        let rq = _mm256_div_ps(_mm256_set1_ps(1.0), q);
        let qi = _mm256_and_ps(rq, _mm256_cmp_ps::<_CMP_NEQ_UQ>(q, _mm256_setzero_ps()));
        let r = self.r::<PACK>(at, inv);
        [
            _mm256_mul_ps(s, qi),
            _mm256_mul_ps(t, qi),
            _mm256_mul_ps(r, qi),
        ]
    }

    /// r (varying `to + 2`) at lanes `xs` (1/w `inv`), read by the depth comparison only (as
    /// in `texels_lanes`; 0 otherwise).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn r<const PACK: bool>(
        &self,
        at: &Lanes,
        inv: std::arch::x86_64::__m256,
    ) -> std::arch::x86_64::__m256 {
        use std::arch::x86_64::*;
        if self.depth.is_none() {
            return _mm256_setzero_ps();
        }
        let [a, dx, yt] = self.rpl;
        let adx = [[a; LANES], [dx; LANES]];
        let v = if PACK {
            plane8xy(&adx, yt, at)
        } else {
            plane8l(&adx, yt, at.xs)
        };
        if self.rdiv {
            _mm256_mul_ps(v, inv)
        } else {
            v
        }
    }
}

/// `f(g, m)` for each group of eight pixels g..g + 8 of a span of `n` pixels (at most 64)
/// with a lane in `mask` (bit i for pixel i), `m` its lanes, in order: the loop of
/// [`FusedSpan::span`]'s and [`FusedSpan::channel_groups`]' routes.
#[inline(always)]
fn each_group(n: usize, mask: u64, mut f: impl FnMut(usize, u8)) {
    let mut g = 0;
    while g < n.min(64) {
        let m = ((mask >> g) & ((1 << LANES) - 1)) as u8;
        if m != 0 {
            f(g, m);
        }
        g += LANES;
    }
}

/// The RGBA8 store of [`FusedSpan::group`]: colours `c` (pixel-major pairs, clamped) packed as
/// `store_pixels` converts them and stored into `dst`'s lanes of `m` (lane l into `dst[l]`).
///
/// # Safety
/// The CPU must have AVX2 (`lanes::has_avx2`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn store_group(c: [std::arch::x86_64::__m256; 4], m: u8, dst: &mut [[u8; 4]]) {
    use std::arch::x86_64::*;
    let v = pack_group(c);
    if let Some(d) = dst.get_mut(..LANES) {
        let p = d.as_mut_ptr().cast::<__m256i>();
        // A whole group (most of a large triangle's) is stored as it is: no mask, no load
        // and blend of the pixels it replaces (≈6 instructions a group on textured-cube).
        if m == u8::MAX {
            // SAFETY: `d` is eight `[u8; 4]`, 32 contiguous bytes (no alignment needed).
            unsafe { _mm256_storeu_si256(p, v) };
            return;
        }
        let on = crate::cpu::lanes::lane_mask8(m);
        // SAFETY: `d` is eight `[u8; 4]`, 32 contiguous bytes (no alignment needed); the
        // tile belongs to this thread, so the unwritten pixels stored back are unchanged.
        unsafe {
            let old = _mm256_loadu_si256(p);
            _mm256_storeu_si256(p, _mm256_blendv_epi8(old, v, on));
        }
        return;
    }
    // SAFETY: `__m256i` and `[[u8; 4]; 8]` are both 32 bytes, every bit pattern valid.
    let px = unsafe { std::mem::transmute::<__m256i, [[u8; 4]; LANES]>(v) };
    for (l, (d, c)) in dst.iter_mut().zip(px).enumerate() {
        if m & (1 << l) != 0 {
            *d = c;
        }
    }
}

/// The conversion of [`store_group`]: colours `c` (pixel-major pairs, clamped) as
/// `store_pixels` converts them, the eight RGBA8 pixels in lane order.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn pack_group(c: [std::arch::x86_64::__m256; 4]) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let (k255, bias) = (_mm256_set1_ps(255.0 / 256.0), _mm256_set1_ps(32768.0));
    let low = _mm256_set1_epi32(0xFF);
    let px: [__m256i; 4] = std::array::from_fn(|k| {
        // `store_pixels`' conversion (its clamp leaves a clamped value as it is).
        _mm256_and_si256(
            _mm256_castps_si256(_mm256_add_ps(_mm256_mul_ps(c[k], k255), bias)),
            low,
        )
    });
    // Pairs (q, q + 4): the packs give pixels 0..3 in the low half and 4..7 in the high.
    _mm256_packus_epi16(
        _mm256_packs_epi32(px[0], px[1]),
        _mm256_packs_epi32(px[2], px[3]),
    )
}

impl<'a> FusedSpan<'a> {
    /// The colours of the group of eight fragments from window x `x` (lane l at x + l), lanes
    /// `m`, as pixel-major pairs (register k: lane k's RGBA, then lane k + 4's), clamped to
    /// [0, 1]: what `tex_pixels` gives for them, each channel through `Vec4::clamp`
    /// (`oplanes::clamp01`: `maxps` with 0, then `minps` with 1). Lanes outside `m` hold
    /// unspecified values.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn colors<const DIV: u8>(&mut self, x: i32, m: u8) -> [std::arch::x86_64::__m256; 4] {
        // SAFETY: the CPU has AVX2 (the caller's promise).
        unsafe { self.colors_at::<DIV, false, LIN_NONE, ()>(self.at_row(x), m, None) }
    }

    /// [`FusedSpan::colors`] of lanes `at` (`PACK` as [`Lanes`]); with `LIN` `LIN_CLAMP` or
    /// `LIN_REPEAT` the caller's [`FusedSpan::lin_groups`] (its level `lin`) and
    /// `bilinear!` inline. `K` is the caller's (`FusedSpan::colors_loop`'s closure on the
    /// `LIN` routes, else `()`), unused but for making such an instance's caller its only
    /// one, so that the caller inlines it: with two callers (the span's store and the rows'
    /// channels) each instance stayed out of line, its call, prologue and return through
    /// memory in every group. (The level looked up in each group, `LIN_NONE`, stays out of
    /// line: inlined into the loop, textured-cube took 3% more.)
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    #[allow(clippy::extra_unused_type_parameters)]
    unsafe fn colors_at<const DIV: u8, const PACK: bool, const LIN: u8, K>(
        &mut self,
        at: Lanes,
        m: u8,
        lin: Option<&DenseLevel<'a>>,
    ) -> [std::arch::x86_64::__m256; 4] {
        use std::arch::x86_64::*;
        // `lanes::varyings`: x = fx0 as f32 + l, each plane (a + dx·x) + dy·fy, 1/w by
        // `divps`, the smooth varyings times it (packed: `varyings_xy_avx2`'s, the same).
        let at = &at;
        let inv = self.inv::<PACK>(at);
        let one = _mm256_set1_ps(1.0);
        let (s, t, q) = (
            self.vary::<4, DIV, PACK>(at, inv),
            self.vary::<5, DIV, PACK>(at, inv),
            self.vary::<6, DIV, PACK>(at, inv),
        );
        // `texels_lanes`: inv = 1/q where q ≠ 0 (a NaN q included), else 0; s·inv, t·inv.
        let rq = _mm256_div_ps(one, q);
        let qi = _mm256_and_ps(rq, _mm256_cmp_ps::<_CMP_NEQ_UQ>(q, _mm256_setzero_ps()));
        let (ss, tt) = (_mm256_mul_ps(s, qi), _mm256_mul_ps(t, qi));
        // r (varying `to + 2`) and r/q, read by the depth comparison only (as in
        // `texels_lanes`).
        let r = self.r::<PACK>(at, inv);
        let rr = _mm256_mul_ps(r, qi);
        let tex = if let (LIN_CLAMP | LIN_REPEAT, Some(lv)) = (LIN, lin) {
            // `level_linear`'s kernel on the span's level (`lin`: no depth
            // comparison, no border texel, the level dense).
            Some(if LIN == LIN_REPEAT {
                bilinear!(true, true, lv, ss, tt)
            } else {
                bilinear!(false, false, lv, ss, tt)
            })
        } else if self.depth.is_some() || self.border.is_some() {
            // SAFETY: the CPU has AVX2 (the caller's promise).
            unsafe { self.other_texels(ss, tt, rr) }
        } else {
            self.texels::<DIV, PACK>(at, ss, tt, m)
        };
        let tex = match tex {
            Some(p) => p,
            None => {
                // Any other case: `texels_lanes` on the same coordinates.
                // (s, t, q computed again, the same values: kept from above, they were
                // stored to the stack in every group for this rare case.)
                let a = |v: __m256| std::mem::transmute::<__m256, [f32; LANES]>(v);
                let (sa, ta, qa) = (
                    a(self.vary::<4, DIV, PACK>(at, inv)),
                    a(self.vary::<5, DIV, PACK>(at, inv)),
                    a(self.vary::<6, DIV, PACK>(at, inv)),
                );
                let ra = a(r);
                let lam = if self.s.route == Route::Lod {
                    a(self.lambda_at::<PACK>(at))
                } else {
                    [0.0; LANES]
                };
                let tl = self.s.texels_lanes([&sa, &ta, &ra, &qa], &lam, m);
                std::array::from_fn(|k| _mm256_loadu2_m128(tl[k + 4].as_ptr(), tl[k].as_ptr()))
            }
        };
        // `env_of` (MODULATE: cf·t, REPLACE: t; an RGB texture keeps the fragment's alpha;
        // BLEND of LUMINANCE L = t[0]: cfr·(1 - L) + cc·L, the fragment's alpha), clamped to
        // [0, 1] as `Vec4::clamp` does (`maxps` with 0, then `minps` with 1).
        // The colour's varyings after the texels (the same values: nothing they read changes),
        // so that they are not kept across the `level` calls.
        let col = [
            self.vary::<0, DIV, PACK>(at, inv),
            self.vary::<1, DIV, PACK>(at, inv),
            self.vary::<2, DIV, PACK>(at, inv),
            self.vary::<3, DIV, PACK>(at, inv),
        ];
        let cf = pairs(&col);
        let zero = _mm256_setzero_ps();
        // SAFETY: the load reads the eight floats of `cc`.
        let cc = unsafe { _mm256_loadu_ps(self.cc.as_ptr()) };
        std::array::from_fn(|k| {
            let c = match self.env {
                Env::Replace => tex[k],
                Env::Modulate => _mm256_mul_ps(cf[k], tex[k]),
                Env::BlendLum => {
                    let l = _mm256_permute_ps::<0x00>(tex[k]);
                    _mm256_add_ps(
                        _mm256_mul_ps(cf[k], _mm256_sub_ps(one, l)),
                        _mm256_mul_ps(cc, l),
                    )
                }
            };
            let c = if self.rgb || self.env == Env::BlendLum {
                _mm256_blend_ps::<0x88>(c, cf[k])
            } else {
                c
            };
            _mm256_min_ps(_mm256_max_ps(c, zero), one)
        })
    }

    /// λ before bias of the eight pixels from window x `x` (lane l at x + l): each lane its
    /// quad's, what `quad_lambda_lanes` gives for the quad at
    /// ((x + l) & !1) - ox (each lane computes its quad's value; two lanes share a quad).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    pub(super) fn lambda(&self, x: i32) -> std::arch::x86_64::__m256 {
        use std::arch::x86_64::*;
        let iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        let qi = _mm256_and_si256(
            _mm256_add_epi32(_mm256_set1_epi32(x), iota),
            _mm256_set1_epi32(!1),
        );
        self.lambda_quads::<false>(qi, _mm256_setzero_ps())
    }

    /// λ before bias of lanes `at` (`PACK` as [`Lanes`]): [`FusedSpan::lambda`] of the row
    /// group, or each packed lane's quad's (`quad_lambda_xy8`'s value).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn lambda_at<const PACK: bool>(&self, at: &Lanes) -> std::arch::x86_64::__m256 {
        if PACK {
            self.lambda_quads::<true>(at.qi, at.qy)
        } else {
            self.lambda(at.x)
        }
    }

    /// λ before bias of the quads at window x `qi` (lane l's quad's lower-left pixel, even):
    /// what `quad_lambda_lanes` gives for the quad at `qi[l] - ox`; `PACK`, each lane's quad
    /// at its own y `qy[l]` relative to the origin (`lp`'s y terms then the planes' ∂y), what
    /// `quad_lambda_xy8` gives (∂y·y a product per lane, the one `lp` holds for its row).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn lambda_quads<const PACK: bool>(
        &self,
        qi: std::arch::x86_64::__m256i,
        qy: std::arch::x86_64::__m256,
    ) -> std::arch::x86_64::__m256 {
        use std::arch::x86_64::*;
        let qx = _mm256_cvtepi32_ps(_mm256_sub_epi32(qi, _mm256_set1_epi32(self.ox)));
        let one = _mm256_set1_ps(1.0);
        let qx1 = _mm256_add_ps(qx, one);
        let [ps, pt, pq] = self.lp;
        let size = [self.s.size[0], self.s.size[1]];
        // `lambda_point` (dims 2): each plane (a + dx·x) + yt, 1/q where q ≠ 0 else 0,
        // then (c·inv)·size for s and t; r's component is 0.
        let qy1 = _mm256_add_ps(qy, one);
        let point = |xv: __m256, row: usize| {
            let ev = |p: [f32; 4]| {
                let yt = if PACK {
                    _mm256_mul_ps(_mm256_set1_ps(p[2]), if row == 0 { qy } else { qy1 })
                } else {
                    _mm256_set1_ps(p[2 + row])
                };
                _mm256_add_ps(
                    _mm256_add_ps(
                        _mm256_set1_ps(p[0]),
                        _mm256_mul_ps(_mm256_set1_ps(p[1]), xv),
                    ),
                    yt,
                )
            };
            let q = ev(pq);
            let rq = _mm256_div_ps(one, q);
            let inv = _mm256_and_ps(rq, _mm256_cmp_ps::<_CMP_NEQ_UQ>(q, _mm256_setzero_ps()));
            let sc =
                |p: [f32; 4], n: f32| _mm256_mul_ps(_mm256_mul_ps(ev(p), inv), _mm256_set1_ps(n));
            (sc(ps, size[0]), sc(pt, size[1]))
        };
        let (p0, px, py) = (point(qx, 0), point(qx1, 0), point(qx, 1));
        // `len2`: ax·ax + ay·ay + az·az, az = 0 - 0.
        let zero = _mm256_setzero_ps();
        let zz = _mm256_mul_ps(zero, zero);
        let len2 = |p: (__m256, __m256)| {
            let (a, b) = (_mm256_sub_ps(p.0, p0.0), _mm256_sub_ps(p.1, p0.1));
            _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a, a), _mm256_mul_ps(b, b)), zz)
        };
        let (lx, ly) = (len2(px), len2(py));
        // `f32::max`: the other argument where one is NaN.
        let rho2 = _mm256_blendv_ps(
            _mm256_max_ps(lx, ly),
            lx,
            _mm256_cmp_ps::<_CMP_UNORD_Q>(ly, ly),
        );
        _mm256_mul_ps(_mm256_set1_ps(0.5), fast_log2_8(rho2))
    }

    /// The texels of the group (pixel-major pairs: register k holds lane k's texel in its low
    /// half and lane k + 4's in its high half) from window x `x` at s/q `ss`, t/q `tt` and
    /// each lane's quad's λ, when every lane of `m` is on one level with one filter and the
    /// levels read are dense: what `texels_lanes` gives (`lod_lanes`' one-level case, `pass_level`'s dense kernels,
    /// `blend_levels`). None otherwise.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn texels<const DIV: u8, const PACK: bool>(
        &mut self,
        at: &Lanes,
        ss: std::arch::x86_64::__m256,
        tt: std::arch::x86_64::__m256,
        m: u8,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        let s = self.s;
        let zero = _mm256_setzero_ps();
        let (level, linear, second, f) = match s.route {
            Route::Nearest => (s.base_level, false, 0, zero),
            Route::Linear => (s.base_level, true, 0, zero),
            // A packed group's quads lie on several rows: `select8` of its lanes' λ.
            Route::Lod if PACK => {
                let (lv, linear, f) = select8(s, self.lambda_at::<true>(at));
                one_level(lv, linear, f, m)?
            }
            Route::Lod => {
                let x = at.x;
                let (lv, linear, f) = match self.quads_select::<DIV>(x) {
                    Some(q) => q,
                    None => {
                        let lam = std::mem::transmute::<__m256, [f32; LANES]>(self.lambda(x));
                        let (la, lin, f) = s.select_lanes(&lam);
                        (
                            std::mem::transmute::<[i32; LANES], __m256i>(la),
                            lin,
                            std::mem::transmute::<[f32; LANES], __m256>(f),
                        )
                    }
                };
                one_level(lv, linear, f, m)?
            }
        };
        // One level's NEAREST or LINEAR as `pass_level` computes it: (0, 0, 0, 0) for a
        // missing level, None for one that is not `dense_level`. NEAREST inline (a short
        // kernel: the call, the prologue and the return through memory were a third of its
        // cost), LINEAR out of line (`level_linear`). (A macro: a function stays out of line.)
        macro_rules! level {
            ($level:expr) => {
                if linear {
                    // SAFETY: the CPU has AVX2 (the caller's promise).
                    unsafe { self.level_linear($level, ss, tt)? }
                } else {
                    let rep = self.rep;
                    match self.dense($level) {
                        Ok(lv) => match rep {
                            [false, false] => nearest::<false, false>(lv, ss, tt),
                            [false, true] => nearest::<false, true>(lv, ss, tt),
                            [true, false] => nearest::<true, false>(lv, ss, tt),
                            [true, true] => nearest::<true, true>(lv, ss, tt),
                        },
                        Err(true) => [_mm256_setzero_ps(); 4],
                        Err(false) => return None,
                    }
                }
            };
        }
        let a = level!(level);
        if second == 0 {
            return Some(a);
        }
        // f ≠ 0 only below `span`: level + 1 is at most `last`.
        let b = level!(level.saturating_add(1));
        // `blend_levels`: a·(1 - f) + b·f on the lanes of `second`, a on the others (every
        // lane of `m` blended: no select, the lanes outside `m` are unspecified).
        let one = _mm256_set1_ps(1.0);
        let mix = |k: usize, fk: __m256| {
            _mm256_add_ps(
                _mm256_mul_ps(a[k], _mm256_sub_ps(one, fk)),
                _mm256_mul_ps(b[k], fk),
            )
        };
        if second == m {
            return Some(std::array::from_fn(|k| {
                mix(k, _mm256_permutevar8x32_ps(f, pair_index(k)))
            }));
        }
        let on = _mm256_castsi256_ps(crate::cpu::lanes::lane_mask8(second));
        Some(std::array::from_fn(|k| {
            let idx = pair_index(k);
            let (fk, onk) = (
                _mm256_permutevar8x32_ps(f, idx),
                _mm256_permutevar8x32_ps(on, idx),
            );
            _mm256_blendv_ps(a[k], mix(k, fk), onk)
        }))
    }

    /// [`Sampler::select_lanes`] of the λ of the group from window x `x` (lane l at x + l,
    /// each lane its quad's λ) from the row's quads (`qlv`, `qf`, `qlin`), the blocks it
    /// reaches computed first; when its quads are not among the `QUADS` kept from `qbase`,
    /// the quads start again from the group's (None where they could not be computed: the
    /// caller then computes them for the group alone). Each lane is
    /// `select_lanes`' value of its quad's λ either way: `select_lanes` works lane by lane,
    /// and a quad's λ depends on its window x alone.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn quads_select<const DIV: u8>(
        &mut self,
        x: i32,
    ) -> Option<(std::arch::x86_64::__m256i, u8, std::arch::x86_64::__m256)> {
        use std::arch::x86_64::*;
        // The group's first quad from `qbase` (window x wrap as the lanes' integers do: lane
        // l's quad (x + l) & !1 is qbase + 2·(off + ((x & 1) + l) / 2) modulo 2^32).
        let mut d = (x & !1).wrapping_sub(self.qbase) as u32;
        if self.qdone == 0 || d > 64 {
            self.qbase = x & !1;
            self.qdone = 0;
            d = 0;
        }
        let odd = (x & 1) as usize;
        let off = (d / 2) as usize;
        // off + 7 < QUADS; the last quad, off + 3 + odd, in block 4 at most.
        let (b0, b1) = (off / 8, (off + 3 + odd) / 8);
        // (Two tests, not a loop: the block's constants stay in its branch.)
        if self.qdone & (1 << b0) == 0 {
            // SAFETY: the CPU has AVX2 (the caller's promise).
            unsafe { self.quads_block(b0) };
        }
        if self.qdone & (1 << b1) == 0 {
            // SAFETY: the CPU has AVX2 (the caller's promise).
            unsafe { self.quads_block(b1) };
        }
        let need = (1u8 << b0) | (1 << b1);
        if self.qdone & need != need {
            return None;
        }
        // Lane l's quad: off + ((x & 1) + l) / 2.
        const IDX: [[i32; LANES]; 2] = [[0, 0, 1, 1, 2, 2, 3, 3], [0, 1, 1, 2, 2, 3, 3, 4]];
        let lv = <&[i32; LANES]>::try_from(self.qlv.get(off..off + LANES)?).ok()?;
        let fv = <&[f32; LANES]>::try_from(self.qf.get(off..off + LANES)?).ok()?;
        let idx = IDX.get(odd)?;
        // SAFETY: each load reads the eight values of `lv`, `fv` or `idx`.
        let (lv, fv, idx) = unsafe {
            (
                _mm256_loadu_si256(lv.as_ptr().cast::<__m256i>()),
                _mm256_loadu_ps(fv.as_ptr()),
                _mm256_loadu_si256(idx.as_ptr().cast::<__m256i>()),
            )
        };
        let la = _mm256_permutevar8x32_epi32(lv, idx);
        let f = _mm256_permutevar8x32_ps(fv, idx);
        let bits = DOUBLE.get(((self.qlin >> off) & 31) as usize).copied()?;
        Some((la, (bits >> odd) as u8, f))
    }

    /// Block `b` of the row's quads (quads 8b..8b + 8 from `qbase`): their λ
    /// ([`FusedSpan::lambda_quads`]) and [`Sampler::select_lanes`] into `qlv`, `qf`, `qlin`.
    /// Out of line: most groups find their blocks done.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn quads_block(&mut self, b: usize) {
        use std::arch::x86_64::*;
        if b >= QUADS / 8 {
            return;
        }
        let k = 8 * b;
        let start = self.qbase.wrapping_add(16 * b as i32);
        let qi = _mm256_add_epi32(
            _mm256_set1_epi32(start),
            _mm256_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14),
        );
        let (la, lin, f) = select8(self.s, self.lambda_quads::<false>(qi, _mm256_setzero_ps()));
        if let (Some(lv), Some(fv)) = (self.qlv.get_mut(k..k + 8), self.qf.get_mut(k..k + 8)) {
            // SAFETY: each store writes the eight values of `lv` or `fv`.
            unsafe {
                _mm256_storeu_si256(lv.as_mut_ptr().cast::<__m256i>(), la);
                _mm256_storeu_ps(fv.as_mut_ptr(), f);
            }
            self.qlin = (self.qlin & !(0xFF << k)) | u64::from(lin) << k;
            self.qdone |= 1 << b;
        }
    }

    /// The depth comparison's texels (pixel-major pairs, L in every channel) of the group at
    /// s/q `ss`, t/q `tt`, r/q `rr`, on the base level (the route's depth state is NEAREST
    /// without mipmaps): `pass_level`'s NEAREST then the comparison of each lane's texel
    /// (`dense_depth8`), (0, 0, 0, 0) for a missing level, None for a level that is not
    /// [`dense_level`]. Out of line (in [`FusedSpan::other_texels`]), so that
    /// [`FusedSpan::level`]'s colour kernels stay inlined as they were.
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn depth_texels(
        &mut self,
        func: u32,
        ss: std::arch::x86_64::__m256,
        tt: std::arch::x86_64::__m256,
        rr: std::arch::x86_64::__m256,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        let rep = self.rep;
        let lv = match self.dense(self.s.base_level) {
            Ok(d) => d,
            Err(missing) => return missing.then(|| [_mm256_setzero_ps(); 4]),
        };
        let d = match rep {
            [false, false] => nearest_depth::<false, false>(lv, ss, tt),
            [false, true] => nearest_depth::<false, true>(lv, ss, tt),
            [true, false] => nearest_depth::<true, false>(lv, ss, tt),
            [true, true] => nearest_depth::<true, true>(lv, ss, tt),
        };
        // L in every channel of each lane's pair.
        let l = compare8(func, d, rr);
        Some(std::array::from_fn(|k| {
            _mm256_permutevar8x32_ps(l, pair_index(k))
        }))
    }

    /// The texels (pixel-major pairs) of a group whose state is not the colour kernels'
    /// ([`FusedSpan::texels`]): the depth comparison's ([`FusedSpan::depth_texels`]) or the
    /// border kernel's ([`FusedSpan::border_texels`]); None (`texels_lanes`) otherwise. One
    /// call out of line, so that the common route's code in [`FusedSpan::colors`] stays as it
    /// was (a second call there cost textured-cube 25 instructions a group).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn other_texels(
        &mut self,
        ss: std::arch::x86_64::__m256,
        tt: std::arch::x86_64::__m256,
        rr: std::arch::x86_64::__m256,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        // SAFETY: the CPU has AVX2 (the caller's promise).
        unsafe {
            match (self.depth, self.border) {
                (Some(func), _) => self.depth_texels(func, ss, tt, rr),
                (None, Some(kind)) => self.border_texels(kind, ss, tt),
                (None, None) => None,
            }
        }
    }

    /// The texels (pixel-major pairs) of the group at s/q `ss`, t/q `tt` on the base level
    /// with a border texel (LINEAR without mipmaps, the wrap classes `kind` of
    /// `border_kind`): what `pass_level` gives through `dense_border` ([`border_bilinear`]),
    /// (0, 0, 0, 0) for a missing level, None for a level that is not [`dense_level`] (or
    /// beyond `dense_border`'s 2^28 texels). Out of line (in [`FusedSpan::other_texels`]).
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn border_texels(
        &mut self,
        kind: u8,
        ss: std::arch::x86_64::__m256,
        tt: std::arch::x86_64::__m256,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        let (dt, w, h) = match self.dense(self.s.base_level) {
            Ok(lv) if lv.dt.len() <= 1 << 28 => (lv.dt, lv.w, lv.h),
            Err(true) => return Some([_mm256_setzero_ps(); 4]),
            _ => return None,
        };
        if dt.is_empty() {
            return None;
        }
        // The border colour in the base format's components, as `pass_level` gives it to
        // `dense_border` (in both halves: lanes k and k + 4 of a pixel-major pair).
        let bc = crate::texture::keep(self.s.base, self.s.border);
        // SAFETY: the load reads the four floats of `bc` (no alignment needed).
        let b4 = unsafe { _mm_loadu_ps(bc.as_ptr()) };
        let b = _mm256_set_m128(b4, b4);
        macro_rules! pick {
            ($($k:literal => $x:ident, $y:ident;)*) => {
                match kind {
                    $($k => border_bilinear::<$x, $y>(dt, w, h, b, ss, tt),)*
                    _ => return None,
                }
            };
        }
        Some(pick! {
            0b1_0010 => AX_EDGE, AX_BORDER;
            0b1_0011 => AX_EDGE, AX_CLAMP;
            0b1_0110 => AX_REPEAT, AX_BORDER;
            0b1_0111 => AX_REPEAT, AX_CLAMP;
            0b1_1000 => AX_BORDER, AX_EDGE;
            0b1_1001 => AX_BORDER, AX_REPEAT;
            0b1_1010 => AX_BORDER, AX_BORDER;
            0b1_1011 => AX_BORDER, AX_CLAMP;
            0b1_1100 => AX_CLAMP, AX_EDGE;
            0b1_1101 => AX_CLAMP, AX_REPEAT;
            0b1_1110 => AX_CLAMP, AX_BORDER;
            0b1_1111 => AX_CLAMP, AX_CLAMP;
        })
    }

    /// Level `level` as the route reads it, from the cache or looked up (and cached). Two
    /// cache slots by parity: a trilinear group's two levels keep one each.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn view(&mut self, level: i32) -> View<'a> {
        let slot = &mut self.cache[(level & 1) as usize];
        match *slot {
            (n, v) if n == level && !matches!(v, View::Unknown) => v,
            _ => {
                let sampler: &'a Sampler = self.s;
                // (An empty level is taken as Sparse: the route's kernels need a texel.)
                let v = match sampler.obj.face_level(0, level) {
                    None => View::Missing,
                    Some(v)
                        if !v.texels.is_empty() && dense_level(&v.texels, v.width, v.height) =>
                    {
                        View::Dense(DenseLevel::new(&v.texels, v.width, v.height))
                    }
                    Some(_) => View::Sparse,
                };
                *slot = (level, v);
                v
            }
        }
    }

    /// Level `level`'s texels and size where it is [`dense_level`] and not empty; else
    /// whether it is missing (its texels (0, 0, 0, 0); otherwise the group takes
    /// `texels_lanes`).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn dense(&mut self, level: i32) -> Result<&DenseLevel<'a>, bool> {
        // The cached level first: one compare of the number, one of the kind. (The level
        // lent from its slot, not copied: the kernels read its constants where they lie.)
        let slot = (level & 1) as usize;
        if !matches!(self.cache[slot], (n, View::Dense(_)) if n == level) {
            match self.view(level) {
                View::Dense(_) => {}
                View::Missing => return Err(true),
                View::Sparse | View::Unknown => return Err(false),
            }
        }
        // (`view` cached the level in its slot.)
        match &self.cache[slot] {
            (_, View::Dense(lv)) => Ok(lv),
            _ => Err(false),
        }
    }

    /// One level's LINEAR for the eight lanes (pixel-major pairs), as `pass_level` computes
    /// it (`bilinear!`): a missing level gives (0, 0, 0, 0); a level that is not
    /// [`dense_level`] gives None. Out of line: inlined into [`FusedSpan::colors`] its
    /// registers spill (twelfth session). (NEAREST is inline in [`FusedSpan::texels`].)
    ///
    /// # Safety
    /// The CPU must have AVX2 (`lanes::has_avx2`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn level_linear(
        &mut self,
        level: i32,
        ss: std::arch::x86_64::__m256,
        tt: std::arch::x86_64::__m256,
    ) -> Option<[std::arch::x86_64::__m256; 4]> {
        use std::arch::x86_64::*;
        let rep = self.rep;
        let lv = match self.dense(level) {
            Ok(d) => d,
            Err(missing) => return missing.then(|| [_mm256_setzero_ps(); 4]),
        };
        Some(match rep {
            [false, false] => bilinear!(false, false, lv, ss, tt),
            [false, true] => bilinear!(false, true, lv, ss, tt),
            [true, false] => bilinear!(true, false, lv, ss, tt),
            [true, true] => bilinear!(true, true, lv, ss, tt),
        })
    }
}

/// The LOD route's one level for a group of lanes `m` from [`Sampler::select_lanes`]' choice
/// (levels `lv`, LINEAR lanes `linear`, second-level weights `f`): the first lane of `m`'s
/// level, whether it filters LINEAR, the lanes of `m` with a second level (`mask_ne_zero`:
/// f != 0, a NaN included) and `f`; None when the lanes of `m` fall on different levels or
/// filters (`mask_eq`'s compare).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn one_level(
    lv: std::arch::x86_64::__m256i,
    linear: u8,
    f: std::arch::x86_64::__m256,
    m: u8,
) -> Option<(i32, bool, u8, std::arch::x86_64::__m256)> {
    use std::arch::x86_64::*;
    let t = (m.trailing_zeros() as i32).min(LANES as i32 - 1);
    let fl = _mm256_permutevar8x32_epi32(lv, _mm256_set1_epi32(t));
    let same = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(lv, fl)));
    let second = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_NEQ_UQ>(f, _mm256_setzero_ps())) as u8 & m;
    let linear = linear & m;
    if same as u8 & m != m || (linear != 0 && linear != m) {
        return None;
    }
    Some((_mm256_cvtsi256_si32(fl), linear != 0, second, f))
}

/// [`Sampler::select_lanes`] of sampler `s` for the eight λ `lambda` in AVX2 registers: the
/// same steps lane by lane (bias, NaN as 0, the LOD bounds, the minification filter's arm,
/// the magnification lanes), each lane exactly the scalar choice. `f32::min`/`max` as LLVM
/// lowers them (`minps`/`maxps` with the bound first: the value itself on a tie, the value
/// where the bound is NaN; the value is never NaN), the floors by `ifloor8_num` (its
/// arguments are never NaN). Returns the lanes' levels, the lanes that filter LINEAR (bit l)
/// and the second-level weights.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) fn select8(
    s: &Sampler,
    lambda: std::arch::x86_64::__m256,
) -> (std::arch::x86_64::__m256i, u8, std::arch::x86_64::__m256) {
    use std::arch::x86_64::*;
    let zero = _mm256_setzero_ps();
    let x = _mm256_add_ps(lambda, _mm256_set1_ps(s.bias));
    let x = _mm256_andnot_ps(_mm256_cmp_ps::<_CMP_UNORD_Q>(x, x), x);
    let lam = _mm256_max_ps(
        _mm256_set1_ps(s.min_lod),
        _mm256_min_ps(_mm256_set1_ps(s.max_lod), x),
    );
    let (base, last) = (s.base_level, s.last);
    let span = (last - base) as f32;
    let span_i = last.wrapping_sub(base);
    let basev = _mm256_set1_epi32(base);
    let (lv, f, min_lin) = match s.min {
        gl::NEAREST_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_NEAREST => {
            let x = _mm256_max_ps(
                zero,
                _mm256_min_ps(
                    _mm256_set1_ps(span + 2.0),
                    _mm256_add_ps(lam, _mm256_set1_ps(0.5)),
                ),
            );
            let tr = super::ifloor8_num(x);
            // c = tr + 1 where tr < x (the mask is -1 there).
            let short = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_LT_OQ>(_mm256_cvtepi32_ps(tr), x));
            let c = _mm256_sub_epi32(tr, short);
            let d = _mm256_min_epi32(
                _mm256_sub_epi32(c, _mm256_set1_epi32(1)),
                _mm256_set1_epi32(span_i),
            );
            let low = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_LE_OQ>(lam, _mm256_set1_ps(0.5)));
            let lv = _mm256_add_epi32(basev, _mm256_andnot_si256(low, d));
            (lv, zero, super::lin(s.min) == gl::LINEAR)
        }
        gl::NEAREST_MIPMAP_LINEAR | gl::LINEAR_MIPMAP_LINEAR => {
            let spanv = _mm256_set1_ps(span);
            let x = _mm256_min_ps(spanv, _mm256_max_ps(zero, lam));
            let d1 = super::ifloor8_num(x);
            let top = _mm256_cmp_ps::<_CMP_GE_OQ>(lam, spanv);
            let lv = _mm256_blendv_epi8(
                _mm256_add_epi32(basev, d1),
                _mm256_set1_epi32(last),
                _mm256_castps_si256(top),
            );
            let f = _mm256_andnot_ps(top, _mm256_sub_ps(lam, _mm256_cvtepi32_ps(d1)));
            (lv, f, super::lin(s.min) == gl::LINEAR)
        }
        m => (basev, zero, m != gl::NEAREST),
    };
    // The magnification lanes (λ <= c, false for NaN): the base level, no second level.
    let mag = _mm256_cmp_ps::<_CMP_LE_OQ>(lam, _mm256_set1_ps(s.c));
    let lv = _mm256_blendv_epi8(lv, basev, _mm256_castps_si256(mag));
    let f = _mm256_andnot_ps(mag, f);
    let magb = _mm256_movemask_ps(mag) as u8;
    let all = |b: bool| if b { 0xffu8 } else { 0 };
    let linear = (magb & all(s.mag != gl::NEAREST)) | (!magb & all(min_lin));
    (lv, linear, f)
}

/// Is sampler `s` a depth texture's comparison the route covers: NEAREST on the base level
/// (no mipmaps), DEPTH_TEXTURE_MODE LUMINANCE, the BLEND environment?
#[inline(always)]
fn depth_blend(s: &Sampler) -> bool {
    s.compare.is_some()
        && s.route == super::Route::Nearest
        && s.depth_mode == gl::LUMINANCE
        && s.env == gl::BLEND
        && crate::texture::is_depth(s.base)
}

/// The border kernel's code ([`super::border_kind`]) of sampler `s` when the route reads it
/// with a border texel: LINEAR on the base level without mipmaps, no depth comparison,
/// CLAMP_TO_BORDER or LINEAR's CLAMP on s or t (the other any wrap the border kernels take);
/// None otherwise (and on a CPU without AVX2).
#[inline(always)]
fn border_linear(s: &Sampler) -> Option<u8> {
    if s.route == super::Route::Linear && s.compare.is_none() {
        super::border_kind(true, s.wrap)
    } else {
        None
    }
}

/// `lanes::varyings`' plane of varying `j` at row `fy` (constant, x step, y term `dy·fy`);
/// None when `planes` does not hold it.
#[inline(always)]
fn r_plane(planes: &[f32], j: usize, fy: f32) -> Option<[f32; 3]> {
    let k = j.checked_mul(3)?.checked_add(3)?;
    let p = planes.get(k..k.checked_add(3)?)?;
    Some([p[0], p[1], p[2] * fy])
}

/// A plane at a packed group's lanes `at` (each lane's x and y): (a + dx·x) + dy·y, the
/// constant and x step `adx` on eight lanes each, ∂y `dy` (`lanes::varyings_xy_avx2`'s
/// operations in its order, so each lane the bits [`plane8l`] gives in its own row).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn plane8xy(adx: &[[f32; LANES]; 2], dy: f32, at: &Lanes) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    // SAFETY: each load reads the eight floats of one term.
    let [a, dx] = adx.map(|v| unsafe { _mm256_loadu_ps(v.as_ptr()) });
    _mm256_add_ps(
        _mm256_add_ps(a, _mm256_mul_ps(dx, at.xs)),
        _mm256_mul_ps(_mm256_set1_ps(dy), at.ys),
    )
}

/// [`plane8`] with the constant and x step `adx` on eight lanes each (`FusedSpan::pad`),
/// the y term `yt`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn plane8l(
    adx: &[[f32; LANES]; 2],
    yt: f32,
    xs: std::arch::x86_64::__m256,
) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    // SAFETY: each load reads the eight floats of one term.
    let [a, dx] = adx.map(|v| unsafe { _mm256_loadu_ps(v.as_ptr()) });
    _mm256_add_ps(_mm256_add_ps(a, _mm256_mul_ps(dx, xs)), _mm256_set1_ps(yt))
}

/// `lanes::varyings`' planes (constant, x step, y step `dy`) of 1/w, the colour's four
/// varyings and s, t, q (varyings `to`, `to + 1`, `to + 3`); None when `planes` does not hold
/// them.
#[inline(always)]
fn row_planes(planes: &[f32], to: usize) -> Option<[[f32; 3]; 8]> {
    // (a, dx, dy) of 1/w and the colour's four varyings (floats 0..15), then of s, t, r, q
    // (varying `to` at float 3 + 3·to): two bounds checks, not one a plane.
    let c = <&[f32; 15]>::try_from(planes.get(..15)?).ok()?;
    let k = to.checked_mul(3)?.checked_add(3)?;
    let t = <&[f32; 12]>::try_from(planes.get(k..k.checked_add(12)?)?).ok()?;
    let p = |a: f32, dx: f32, dy: f32| [a, dx, dy];
    Some([
        p(c[0], c[1], c[2]),
        p(c[3], c[4], c[5]),
        p(c[6], c[7], c[8]),
        p(c[9], c[10], c[11]),
        p(c[12], c[13], c[14]),
        p(t[0], t[1], t[2]),
        p(t[3], t[4], t[5]),
        p(t[9], t[10], t[11]),
    ])
}

/// λ's planes of s, t and q (varyings `to`, `to + 1`, `to + 3`): constant, x step, y term
/// at quad row `qy` and at `qy + 1` (0 for a float `planes` does not hold).
#[inline(always)]
fn lambda_planes(planes: &[f32], to: usize, qy: f32) -> [[f32; 4]; 3] {
    [to, to + 1, to + 3].map(|j| {
        let k = 3 + 3 * j;
        let g = |o: usize| planes.get(o).copied().unwrap_or(0.0);
        let (a, dx, dy) = (g(k), g(k + 1), g(k + 2));
        [a, dx, dy * qy, dy * (qy + 1.0)]
    })
}

/// Pixel-major pairs `p` (register k: lane k's RGBA, then lane k + 4's) channel-major
/// (`[c][l]`: channel c of lane l): the 4x4 transposition in each half, its own inverse
/// ([`pairs`]).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn channel_major(p: [std::arch::x86_64::__m256; 4]) -> [[f32; LANES]; 4] {
    use std::arch::x86_64::*;
    // SAFETY: `__m256` has the layout of `[f32; 8]`; every bit pattern is valid.
    pairs(&p).map(|v| unsafe { std::mem::transmute::<__m256, [f32; LANES]>(v) })
}

/// The `vpermps` index that puts lane k in the low half and lane k + 4 in the high half.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn pair_index(k: usize) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let (a, b) = (k as i32, k as i32 + 4);
    _mm256_setr_epi32(a, a, a, a, b, b, b, b)
}

/// Channel-major lanes `ch` as pixel-major pairs (register k: lane k's RGBA, then lane
/// k + 4's), `store8`'s transposition.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn pairs(ch: &[std::arch::x86_64::__m256; 4]) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    let (t0, t1) = (
        _mm256_unpacklo_ps(ch[0], ch[1]),
        _mm256_unpackhi_ps(ch[0], ch[1]),
    );
    let (t2, t3) = (
        _mm256_unpacklo_ps(ch[2], ch[3]),
        _mm256_unpackhi_ps(ch[2], ch[3]),
    );
    [
        _mm256_shuffle_ps::<0x44>(t0, t2),
        _mm256_shuffle_ps::<0xEE>(t0, t2),
        _mm256_shuffle_ps::<0x44>(t1, t3),
        _mm256_shuffle_ps::<0xEE>(t1, t3),
    ]
}

/// The texels of `dt` at the eight indices `k` (each taken modulo `dt.len()`, a power of
/// two: masked by `dt.len() - 1` here) as pixel-major pairs: lane q's texel in the low half of
/// register q, lane q + 4's in the high half; zeros for an empty `dt`. The byte offsets are
/// shifted on the lanes, one `vpextrd` and the load a lane.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn load_pairs(dt: &[[f32; 4]], k: std::arch::x86_64::__m256i) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    let Some(km) = dt.len().checked_sub(1) else {
        return [_mm256_setzero_ps(); 4];
    };
    let k = _mm256_and_si256(k, _mm256_set1_epi32(km as i32));
    if km >= 1 << 28 {
        // (Byte offsets past 32 bits: the indices a lane, the bounds check folded by the mask.)
        // SAFETY: `__m256i` has the layout of `[u32; 8]`; every bit pattern is valid.
        let k = unsafe { std::mem::transmute::<__m256i, [u32; LANES]>(k) };
        let at = |l: usize| &dt[k[l] as usize & km];
        return std::array::from_fn(|q| {
            let (lo, hi) = (at(q), at(q + 4));
            // SAFETY: each load reads one `[f32; 4]` of `dt`.
            unsafe { _mm256_loadu2_m128(hi.as_ptr(), lo.as_ptr()) }
        });
    }
    // SAFETY: every lane of `k` is at most `km` < 2^28, so 16·k fits a u32 and lies inside
    // `dt` (16 bytes a texel).
    unsafe { load_at::<0>(dt, _mm256_slli_epi32::<4>(k), 0) }
}

/// The texels at byte offsets `off` (and `D` + `row` texels further on) of `dt` as
/// pixel-major pairs.
///
/// # Safety
/// Every lane of `off` is 16·i with i + `D` + `row` < `dt.len()`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn load_at<const D: usize>(
    dt: &[[f32; 4]],
    off: std::arch::x86_64::__m256i,
    row: usize,
) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    // SAFETY: `__m256i` has the layout of `[u32; 8]`; every bit pattern is valid.
    let off = unsafe { std::mem::transmute::<__m256i, [u32; LANES]>(off) };
    let p = dt.as_ptr().wrapping_add(D).wrapping_add(row).cast::<u8>();
    std::array::from_fn(|q| {
        // SAFETY: texel i + D + row of `dt` (the caller's promise), 16 bytes, no alignment
        // needed.
        unsafe {
            _mm256_loadu2_m128(
                p.add(off[q + 4] as usize).cast::<f32>(),
                p.add(off[q] as usize).cast::<f32>(),
            )
        }
    })
}

/// `dense_nearest8`'s indices (the same wraps, floors and masks), the texels loaded per lane.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn nearest<const RX: bool, const RY: bool>(
    lv: &DenseLevel,
    s: std::arch::x86_64::__m256,
    t: std::arch::x86_64::__m256,
) -> [std::arch::x86_64::__m256; 4] {
    load_pairs(lv.dt, nearest_index::<RX, RY>(lv, s, t))
}

/// `dense_nearest8`'s indices j·w + i on level `lv` (the same wraps, floors; not yet
/// masked).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn nearest_index<const RX: bool, const RY: bool>(
    lv: &DenseLevel,
    s: std::arch::x86_64::__m256,
    t: std::arch::x86_64::__m256,
) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let i = ifloor8(_mm256_mul_ps(s, _mm256_set1_ps(lv.wf)));
    let j = ifloor8(_mm256_mul_ps(t, _mm256_set1_ps(lv.hf)));
    let i = wrap8::<RX>(i, _mm256_set1_epi32(lv.wm1));
    let j = wrap8::<RY>(j, _mm256_set1_epi32(lv.hm1));
    _mm256_add_epi32(_mm256_sll_epi32(j, _mm_cvtsi32_si128(lv.sh)), i)
}

/// Channel 0 (the depth) of [`nearest`]'s texels, one lane each: the same indices, each
/// taken modulo `dt.len()` (a power of two); zeros for an empty `dt`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn nearest_depth<const RX: bool, const RY: bool>(
    lv: &DenseLevel,
    s: std::arch::x86_64::__m256,
    t: std::arch::x86_64::__m256,
) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    let dt = lv.dt;
    let Some(km) = dt.len().checked_sub(1) else {
        return _mm256_setzero_ps();
    };
    let k = nearest_index::<RX, RY>(lv, s, t);
    // SAFETY: `__m256i` has the layout of `[u32; 8]`; every bit pattern is valid.
    let k = unsafe { std::mem::transmute::<__m256i, [u32; LANES]>(k) };
    // (The bounds check folds: k & km < dt.len().)
    let d = |l: usize| dt[k[l] as usize & km][0];
    _mm256_setr_ps(d(0), d(1), d(2), d(3), d(4), d(5), d(6), d(7))
}

/// eq. 3.24's sum of the four corners `c` (t00, t10, t01, t11, each pixel-major pairs) with
/// weights from α `a` and β `b` (lanes): (1-α)(1-β)·t00 + α(1-β)·t10 + (1-α)β·t01 + αβ·t11
/// in that order per channel, as `pass_on`, `dense_linear8` and `dense_border8` sum them.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn corner_sum(
    a: std::arch::x86_64::__m256,
    b: std::arch::x86_64::__m256,
    c: &[[std::arch::x86_64::__m256; 4]; 4],
) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    let one = _mm256_set1_ps(1.0);
    let (na, nb) = (_mm256_sub_ps(one, a), _mm256_sub_ps(one, b));
    let wt = [
        _mm256_mul_ps(na, nb),
        _mm256_mul_ps(a, nb),
        _mm256_mul_ps(na, b),
        _mm256_mul_ps(a, b),
    ];
    std::array::from_fn(|q| {
        let idx = pair_index(q);
        let wq = |n: usize| _mm256_permutevar8x32_ps(wt[n], idx);
        let x = _mm256_add_ps(_mm256_mul_ps(wq(0), c[0][q]), _mm256_mul_ps(wq(1), c[1][q]));
        let x = _mm256_add_ps(x, _mm256_mul_ps(wq(2), c[2][q]));
        _mm256_add_ps(x, _mm256_mul_ps(wq(3), c[3][q]))
    })
}

/// `dense_border8`'s LINEAR on eight lanes, wrap classes `MX` on s and `MY` on t: its axes
/// ([`border_linear8`]: the wraps, inside masks and weights), indices (j·w + i) & km and
/// eq. 3.24's sum ([`corner_sum`]), each corner's texels loaded per lane as `bilinear!` loads
/// them and replaced by the border colour `bc` (pixel-major pairs) where the corner is
/// outside the level — the texel `dense_border8` takes there.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn border_bilinear<const MX: u8, const MY: u8>(
    dt: &[[f32; 4]],
    w: i32,
    h: i32,
    bc: std::arch::x86_64::__m256,
    s: std::arch::x86_64::__m256,
    t: std::arch::x86_64::__m256,
) -> [std::arch::x86_64::__m256; 4] {
    use std::arch::x86_64::*;
    let (w, h) = (w.max(1), h.max(1));
    let (x, xi, a) = border_linear8::<MX>(s, w);
    let (y, yi, b) = border_linear8::<MY>(t, h);
    let sh = _mm_cvtsi32_si128(w.trailing_zeros() as i32);
    let index = |i: usize, j: usize| _mm256_add_epi32(_mm256_sll_epi32(y[j], sh), x[i]);
    let inside = |i: usize, j: usize| _mm256_castsi256_ps(_mm256_and_si256(xi[i], yi[j]));
    // Every lane's four corners inside the level (the blends would keep every texel: the
    // corners loaded as `bilinear` loads them), or every lane's four outside (the blends
    // would take the border colour for each: no texel read).
    let all_in = _mm256_and_ps(
        _mm256_and_ps(inside(0, 0), inside(1, 0)),
        _mm256_and_ps(inside(0, 1), inside(1, 1)),
    );
    let any_in = _mm256_or_ps(
        _mm256_or_ps(inside(0, 0), inside(1, 0)),
        _mm256_or_ps(inside(0, 1), inside(1, 1)),
    );
    if _mm256_movemask_ps(all_in) == 0xFF {
        // (The corners merged, then summed: summed in each branch, `border_texels` took
        // 0.6% more of projective-texture.)
        let c = load_corners!(
            dt,
            w,
            index(0, 0),
            index(1, 0),
            index(0, 1),
            index(1, 1),
            |c: [[__m256; 4]; 4]| c
        );
        return corner_sum(a, b, &c);
    }
    if _mm256_movemask_ps(any_in) == 0 {
        return corner_sum(a, b, &[[bc; 4]; 4]);
    }
    let corner = |q: usize| {
        let (i, j) = (q & 1, q >> 1);
        // (`load_pairs` takes the index modulo the level's texels: & km.)
        let k = index(i, j);
        let inside = inside(i, j);
        let c = load_pairs(dt, k);
        std::array::from_fn(|p| {
            _mm256_blendv_ps(bc, c[p], _mm256_permutevar8x32_ps(inside, pair_index(p)))
        })
    };
    corner_sum(a, b, &[corner(0), corner(1), corner(2), corner(3)])
}

/// `fast_log2_lanes` on eight lanes (AVX2): the exponent as an integer converted exactly plus
/// the mantissa minus one where 0 < x < +∞; -∞ for ±0, +∞ for +∞, NaN otherwise.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn fast_log2_8(v: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    let bits = _mm256_castps_si256(v);
    let e = _mm256_sub_epi32(
        _mm256_and_si256(_mm256_srli_epi32::<23>(bits), _mm256_set1_epi32(0xff)),
        _mm256_set1_epi32(127),
    );
    let m = _mm256_castsi256_ps(_mm256_or_si256(
        _mm256_and_si256(bits, _mm256_set1_epi32(0x007f_ffff)),
        _mm256_set1_epi32(0x3f80_0000),
    ));
    let val = _mm256_add_ps(_mm256_cvtepi32_ps(e), _mm256_sub_ps(m, _mm256_set1_ps(1.0)));
    let inf = _mm256_set1_ps(f32::INFINITY);
    let zero = _mm256_cmp_ps::<_CMP_EQ_OQ>(v, _mm256_setzero_ps());
    let is_inf = _mm256_cmp_ps::<_CMP_EQ_OQ>(v, inf);
    let not_zero = _mm256_or_ps(
        _mm256_and_ps(is_inf, inf),
        _mm256_andnot_ps(is_inf, _mm256_set1_ps(f32::NAN)),
    );
    let special = _mm256_or_ps(
        _mm256_and_ps(zero, _mm256_set1_ps(f32::NEG_INFINITY)),
        _mm256_andnot_ps(zero, not_zero),
    );
    let ok = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_GT_OQ>(v, _mm256_setzero_ps()),
        _mm256_cmp_ps::<_CMP_LT_OQ>(v, inf),
    );
    _mm256_or_ps(_mm256_and_ps(ok, val), _mm256_andnot_ps(ok, special))
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use crate::cpu::testgen::Gen;
    use crate::state::State;
    use crate::texture::{Level, TexObject};
    use std::sync::Arc;

    /// [`FusedSpan::lambda`] against [`Sampler::quad_lambda_lanes`] bit for bit: random
    /// planes (some terms NaN, infinite or zero, q = 0 among them), origins, quad rows and
    /// groups, textures of a few sizes.
    #[test]
    fn fused_lambda_is_quad_lambda_lanes_bit_for_bit() {
        if !crate::cpu::lanes::has_avx2() {
            return;
        }
        let mut g = Gen(91);
        for round in 0..4000 {
            let (w, h) = (
                [1, 4, 16, 64][(g.next() % 4) as usize],
                [1, 8, 32][(g.next() % 3) as usize],
            );
            let mut obj = TexObject {
                min_filter: gl::LINEAR_MIPMAP_LINEAR,
                ..TexObject::default()
            };
            obj.levels[0] = Some(Level {
                depth: 1,
                width: w,
                height: h,
                internal_format: gl::RGBA as i32,
                base: gl::RGBA,
                texels: vec![[0.5f32; 4]; (w * h) as usize].into(),
            });
            obj.max_level = 0;
            let mut state = State::new(4, 4);
            state.textures.defaults[1] = Arc::new(obj);
            state.enables.texture_2d[0] = true;
            let Some(s) = Sampler::new(&state, 0) else {
                panic!("complete");
            };
            let to = 4;
            let mut planes: Vec<f32> = (0..3 + 3 * 8)
                .map(|k| {
                    let d = [1e-3, 3e-2, 0.3][(g.next() % 3) as usize];
                    if k % 3 == 0 {
                        g.mostly_unit()
                    } else {
                        g.mostly_unit() * d
                    }
                })
                .collect();
            if g.next() % 4 == 0 {
                let k = 3 + 3 * to + (g.next() % 12) as usize;
                planes[k] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0]
                    [(g.next() % 5) as usize];
            }
            if g.next() % 8 == 0 {
                // q = 0 over the whole plane.
                let k = 3 + 3 * (to + 3);
                planes[k..k + 3].copy_from_slice(&[0.0; 3]);
            }
            let ox = (g.next() % 300) as i32 - 100;
            let qy = ((g.next() % 200) as i32 - 50) as f32;
            let x = (g.next() % 400) as i32 - 100;
            let Some(fs) = FusedSpan::new(&s, to, &planes, 0, 0.0, ox, qy) else {
                panic!("the fused route covers this sampler");
            };
            // SAFETY: the CPU has AVX2 (checked above).
            let got = unsafe {
                std::mem::transmute::<std::arch::x86_64::__m256, [f32; LANES]>(fs.lambda(x))
            };
            let qx = std::array::from_fn(|l| ((x + l as i32) & !1).wrapping_sub(ox) as f32);
            let want = s.quad_lambda_lanes(&planes, to, qx, qy);
            assert!(
                got.map(f32::to_bits) == want.map(f32::to_bits),
                "round {round}: {got:?} {want:?}"
            );
        }
    }

    /// [`FusedSpan::quads_select`] (the row's quads' level choice, computed eight quads at a
    /// time) against [`Sampler::select_lanes`] of [`Sampler::quad_lambda_lanes`], bit for bit
    /// on every lane: mipmapped textures under each MIN filter, random planes (some terms
    /// NaN, infinite or zero), rows from an odd or even x with groups in order (eight pixels
    /// on, now and then sixteen or more), now and then out of order or before the row's
    /// first quad, and a new row.
    #[test]
    fn fused_quads_select_is_select_lanes_bit_for_bit() {
        if !crate::cpu::lanes::has_avx2() {
            return;
        }
        let mins = [
            gl::NEAREST_MIPMAP_NEAREST,
            gl::LINEAR_MIPMAP_NEAREST,
            gl::NEAREST_MIPMAP_LINEAR,
            gl::LINEAR_MIPMAP_LINEAR,
        ];
        let mut g = Gen(57);
        let mut checked = 0;
        for round in 0..1500 {
            let (w, h) = (
                [8, 64][(g.next() % 2) as usize],
                [4, 32][(g.next() % 2) as usize],
            );
            let mut obj = TexObject {
                min_filter: mins[(g.next() % 4) as usize],
                mag_filter: [gl::NEAREST, gl::LINEAR][(g.next() % 2) as usize],
                ..TexObject::default()
            };
            let (mut lw, mut lh, mut n) = (w, h, 0);
            loop {
                if let Some(l) = obj.levels.get_mut(n) {
                    *l = Some(Level {
                        depth: 1,
                        width: lw,
                        height: lh,
                        internal_format: gl::RGBA as i32,
                        base: gl::RGBA,
                        texels: vec![[0.5f32; 4]; (lw * lh) as usize].into(),
                    });
                }
                if lw == 1 && lh == 1 {
                    break;
                }
                (lw, lh, n) = ((lw / 2).max(1), (lh / 2).max(1), n + 1);
            }
            let mut state = State::new(4, 4);
            state.textures.defaults[1] = Arc::new(obj);
            state.enables.texture_2d[0] = true;
            let Some(s) = Sampler::new(&state, 0) else {
                panic!("complete");
            };
            let to = 4;
            let mut planes: Vec<f32> = (0..3 + 3 * 8)
                .map(|k| {
                    let d = [1e-3, 3e-2, 0.3, 2.0][(g.next() % 4) as usize];
                    if k % 3 == 0 {
                        g.mostly_unit()
                    } else {
                        g.mostly_unit() * d
                    }
                })
                .collect();
            if g.next() % 5 == 0 {
                let k = 3 + 3 * to + (g.next() % 12) as usize;
                planes[k] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0]
                    [(g.next() % 5) as usize];
            }
            let ox = (g.next() % 300) as i32 - 100;
            let mut qy = ((g.next() % 200) as i32 - 50) as f32;
            let Some(mut fs) = FusedSpan::new(&s, to, &planes, 0, 0.0, ox, qy) else {
                panic!("the fused route covers this sampler");
            };
            let mut x = (g.next() % 400) as i32 - 100;
            for step in 0..12 {
                if step % 6 == 0 && g.next() % 2 == 0 {
                    // Another row: of another quad row (the quads' choice starts again) or of
                    // the same one (the quads kept), from another x now and then.
                    if g.next() % 2 == 0 {
                        qy = ((g.next() % 200) as i32 - 50) as f32;
                    }
                    fs.row(1.0, qy);
                    if g.next() % 2 == 0 {
                        x = (g.next() % 400) as i32 - 100;
                    }
                }
                // SAFETY: the CPU has AVX2 (checked above).
                let got = unsafe { fs.quads_select::<DIV_ANY>(x) };
                let qx = std::array::from_fn(|l| ((x + l as i32) & !1).wrapping_sub(ox) as f32);
                let want = s.select_lanes(&s.quad_lambda_lanes(&planes, to, qx, qy));
                if let Some((la, lin, f)) = got {
                    use std::arch::x86_64::{__m256, __m256i};
                    // SAFETY: the registers have the layouts of the arrays; every bit pattern
                    // is valid for both.
                    let (la, f) = unsafe {
                        (
                            std::mem::transmute::<__m256i, [i32; LANES]>(la),
                            std::mem::transmute::<__m256, [f32; LANES]>(f),
                        )
                    };
                    checked += 1;
                    assert!(
                        la == want.0
                            && lin == want.1
                            && f.map(f32::to_bits) == want.2.map(f32::to_bits),
                        "round {round} x {x}: {la:?} {lin:#x} {f:?}, {want:?}"
                    );
                }
                x += match g.next() % 8 {
                    0 => 16,
                    1 => 40,
                    2 => -8,
                    3 => -((g.next() % 30) as i32),
                    _ => 8,
                };
            }
        }
        assert!(checked > 10000, "{checked} groups from the quads");
    }
    /// [`select8`] against [`Sampler::select_lanes`] bit for bit on every lane: each MIN and
    /// MAG filter, random λ (NaN, infinities, signed zeros, subnormals, random bits, values
    /// about the levels), biases, LOD bounds (NaN and signed zeros among them), c, base and
    /// last levels.
    #[test]
    fn select8_is_select_lanes_bit_for_bit() {
        if !crate::cpu::lanes::has_avx2() {
            return;
        }
        let mut obj = TexObject {
            min_filter: gl::NEAREST,
            ..TexObject::default()
        };
        obj.levels[0] = Some(Level {
            depth: 1,
            width: 4,
            height: 4,
            internal_format: gl::RGBA as i32,
            base: gl::RGBA,
            texels: vec![[0.5f32; 4]; 16].into(),
        });
        let mut state = State::new(4, 4);
        state.textures.defaults[1] = Arc::new(obj);
        state.enables.texture_2d[0] = true;
        let Some(s0) = Sampler::new(&state, 0) else {
            panic!("complete");
        };
        let mins = crate::cpu::testgen::MIN_FILTERS;
        let special = [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            1e-40,
            -1e-40,
            0.5,
            1.0,
            2.0,
        ];
        let mut g = Gen(23);
        for round in 0..20_000 {
            let mut s = s0.clone();
            s.min = mins[(g.next() % 6) as usize];
            s.mag = [gl::NEAREST, gl::LINEAR][(g.next() % 2) as usize];
            s.bias = [0.0, -0.0, 0.5, -1.25, g.float()][(g.next() % 5) as usize];
            s.min_lod = [-1000.0, 0.0, -0.0, 0.5, f32::NAN, g.float()][(g.next() % 6) as usize];
            s.max_lod = [1000.0, 0.0, -0.0, 2.5, f32::NAN, g.float()][(g.next() % 6) as usize];
            s.c = [0.0, 0.5][(g.next() % 2) as usize];
            s.base_level = (g.next() % 4) as i32;
            s.last = s.base_level + (g.next() % 9) as i32;
            let lam: [f32; LANES] = std::array::from_fn(|_| match g.next() % 4 {
                0 => special[(g.next() % special.len() as u64) as usize],
                1 => f32::from_bits(g.next() as u32),
                2 => (g.next() % 4000) as f32 / 256.0 - 4.0,
                _ => g.float(),
            });
            // SAFETY: the CPU has AVX2 (checked above); the registers have the layouts of the
            // arrays and every bit pattern is valid for both.
            let (la, lin, f) = unsafe {
                let (la, lin, f) = select8(
                    &s,
                    std::mem::transmute::<[f32; LANES], std::arch::x86_64::__m256>(lam),
                );
                (
                    std::mem::transmute::<std::arch::x86_64::__m256i, [i32; LANES]>(la),
                    lin,
                    std::mem::transmute::<std::arch::x86_64::__m256, [f32; LANES]>(f),
                )
            };
            let want = s.select_lanes(&lam);
            assert!(
                la == want.0 && lin == want.1 && f.map(f32::to_bits) == want.2.map(f32::to_bits),
                "round {round} λ {lam:?}: {la:?} {lin:#x} {f:?}, {want:?}"
            );
        }
    }
}
