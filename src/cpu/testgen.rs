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
