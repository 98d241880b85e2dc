//! Pipeline-level tests: a `State` built by hand feeds a `Renderer` directly. Every expected value
//! is worked out by hand from the spec's equations in the comment next to it.

mod fragops;
mod gauss;
mod lighting;
mod overlap;
mod raster;
mod reference;
mod routes;
mod scene;

use glam::{Vec3, Vec4};

use super::Renderer;
use crate::gl;
use crate::state::{Current, State};

/// A renderer and its initial state, `w` x `h`.
pub(super) fn setup(w: u32, h: u32) -> (Renderer, State) {
    (Renderer::new(w, h), State::new(w, h))
}

/// Current attributes with colour `c` and normal `n`.
pub(super) fn cur(c: Vec4, n: Vec3) -> Current {
    let mut k = Current::default();
    k.inputs_mut().color = c;
    k.normal = n;
    k
}

/// Draws one Begin/End of `mode` with vertices `(x, y, z, colour)`, normal (0, 0, 1), and flushes.
pub(super) fn draw(r: &mut Renderer, st: &State, mode: u32, vs: &[([f32; 3], Vec4)]) {
    r.begin(mode);
    r.begin_materials(&st.materials);
    for (p, c) in vs {
        r.vertex(Vec4::new(p[0], p[1], p[2], 1.0), &cur(*c, Vec3::Z));
    }
    r.end();
    r.flush(st);
}

/// Colour of pixel (x, y).
pub(super) fn px(r: &mut Renderer, x: i64, y: i64) -> [u8; 4] {
    r.framebuffer().pixel(x, y).map_or([0; 4], |p| p.0)
}

/// Number of pixels whose colour is not `bg`.
pub(super) fn count_not(r: &mut Renderer, bg: [u8; 4]) -> usize {
    r.color().iter().filter(|&&c| c != bg).count()
}

pub(super) const RED: Vec4 = Vec4::new(1.0, 0.0, 0.0, 1.0);
pub(super) const GREEN: Vec4 = Vec4::new(0.0, 1.0, 0.0, 1.0);
pub(super) const BLUE: Vec4 = Vec4::new(0.0, 0.0, 1.0, 1.0);
pub(super) const WHITE: Vec4 = Vec4::ONE;

#[test]
fn clear_honours_scissor_and_masks() {
    let (mut r, mut st) = setup(8, 8);
    st.clear_color = Vec4::new(1.0, 0.5, 0.25, 1.0);
    r.clear(&st, gl::COLOR_BUFFER_BIT);
    // 0.5·255 + 0.5 = 128.0 → 128; 0.25·255 + 0.5 = 64.25 → 64.
    assert_eq!(px(&mut r, 7, 7), [255, 128, 64, 255]);
    st.enables.scissor_test = true;
    st.scissor = [2, 2, 3, 3];
    st.color_mask = [false, true, false, true];
    st.clear_color = Vec4::ZERO;
    st.clear_depth = 0.5;
    r.clear(&st, gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    assert_eq!(px(&mut r, 2, 2), [255, 0, 64, 0]);
    assert_eq!(px(&mut r, 4, 4), [255, 0, 64, 0]);
    assert_eq!(px(&mut r, 5, 5), [255, 128, 64, 255]);
    assert_eq!(px(&mut r, 1, 3), [255, 128, 64, 255]);
    // Depth 0.5 → 0.5·(2^24 − 1) + 0.5 = 8388608.
    assert_eq!(r.framebuffer().pixel(3, 3).map(|p| p.1), Some(8_388_608));
    assert_eq!(
        r.framebuffer().pixel(6, 6).map(|p| p.1),
        Some((1 << 24) - 1)
    );
    st.depth_mask = false;
    st.clear_depth = 0.0;
    r.clear(&st, gl::DEPTH_BUFFER_BIT);
    assert_eq!(r.framebuffer().pixel(3, 3).map(|p| p.1), Some(8_388_608));
    st.stencil_writemask = 0x0F;
    st.clear_stencil = 0xFF;
    r.clear(&st, gl::STENCIL_BUFFER_BIT);
    assert_eq!(r.framebuffer().pixel(3, 3).map(|p| p.2), Some(0x0F));
    assert_eq!(r.framebuffer().pixel(0, 0).map(|p| p.2), Some(0));
}
