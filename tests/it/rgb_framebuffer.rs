//! A framebuffer without alpha bits (`ContextConfig { alpha: false, .. }`, an RGB visual or
//! EGL config): ALPHA_BITS 0, alpha writes dropped, the destination alpha read as 1 by blending,
//! ReadPixels and CopyTexImage (GL 2.1 §4.1.8, §4.3.2). Held against the driver drawing into an
//! RGB8 framebuffer.

use crate::common::test_backend_with;
use fixedgl::{gl, Context, ContextConfig};

const RGB: ContextConfig = ContextConfig {
    double_buffered: false,
    depth: true,
    stencil: true,
    accum: false,
    alpha: false,
};

fn rgb_context(w: u32) -> Context {
    let Ok(c) = Context::with_config(w, w, RGB) else {
        panic!("context")
    };
    c
}

fn quad(c: &mut Context, x0: f32, x1: f32, rgba: [f32; 4]) {
    c.color4f(rgba[0], rgba[1], rgba[2], rgba[3]);
    c.rectf(x0, -1.0, x1, 1.0);
}

/// Clears, plain and blended quads (DST_ALPHA both ways), a DrawPixels with alpha 0, a
/// CopyTexImage of the framebuffer drawn back through an alpha test, and a colour mask.
fn scene(c: &mut Context) {
    c.clear_color(0.2, 0.4, 0.6, 0.3);
    c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    quad(c, -1.0, -0.75, [0.8, 0.2, 0.4, 0.25]);
    c.enable(gl::BLEND);
    c.blend_func(gl::DST_ALPHA, gl::ONE_MINUS_DST_ALPHA);
    quad(c, -0.75, -0.5, [0.9, 0.1, 0.5, 0.0]);
    c.blend_func(gl::ONE_MINUS_DST_ALPHA, gl::DST_ALPHA);
    quad(c, -0.5, -0.25, [0.9, 0.1, 0.5, 0.5]);
    c.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
    quad(c, -0.25, 0.0, [0.1, 0.9, 0.3, 0.5]);
    c.disable(gl::BLEND);
    c.color_mask(true, false, true, true);
    quad(c, 0.0, 0.25, [0.6, 0.6, 0.6, 0.0]);
    c.color_mask(true, true, true, true);
    c.raster_pos2f(0.25, -1.0);
    let px: Vec<u8> = (0..4 * 8 * 8)
        .map(|i| if i % 4 == 3 { 0 } else { 200 })
        .collect();
    c.draw_pixels(8, 8, gl::RGBA, gl::UNSIGNED_BYTE, &px);
    // The framebuffer's alpha as a texture: 1 everywhere, so GREATER 0.9 passes.
    c.copy_tex_image_2d(gl::TEXTURE_2D, 0, gl::RGBA, 0, 0, 8, 8, 0);
    c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    c.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
    c.enable(gl::TEXTURE_2D);
    c.enable(gl::ALPHA_TEST);
    c.alpha_func(gl::GREATER, 0.9);
    c.begin(gl::QUADS);
    for (s, t, x, y) in [
        (0.0, 0.0, 0.5, -1.0),
        (1.0, 0.0, 1.0, -1.0),
        (1.0, 1.0, 1.0, 1.0),
        (0.0, 1.0, 0.5, 1.0),
    ] {
        c.tex_coord2f(s, t);
        c.vertex2f(x, y);
    }
    c.end();
}

#[test]
fn alpha_reads_one_and_is_never_written() {
    let mut c = rgb_context(32);
    let mut bits = [9i32; 1];
    c.get_integerv(gl::ALPHA_BITS, &mut bits);
    assert_eq!(bits, [0]);
    c.get_integerv(gl::RED_BITS, &mut bits);
    assert_eq!(bits, [8]);
    let mut px = [0u8; 4];
    c.read_pixels(3, 3, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [0, 0, 0, 255], "a new framebuffer's alpha is 1");
    scene(&mut c);
    assert_eq!(c.get_error(), gl::NO_ERROR);
    let mut all = vec![0u8; 32 * 32 * 4];
    c.read_pixels(0, 0, 32, 32, gl::RGBA, gl::UNSIGNED_BYTE, &mut all);
    assert!(all.chunks(4).all(|p| p[3] == 255), "alpha is 1 everywhere");
    // DST_ALPHA is 1: the second quad is its source colour, the third the clear colour.
    c.read_pixels(6, 16, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [230, 25, 128, 255]);
    c.read_pixels(10, 16, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [51, 102, 153, 255]);
    // The default framebuffer of an RGBA context keeps alpha.
    let Ok(mut rgba) = Context::new(4, 4) else {
        panic!("context")
    };
    rgba.clear_color(0.0, 0.0, 0.0, 0.3);
    rgba.clear(gl::COLOR_BUFFER_BIT);
    rgba.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px[3], 76);
    rgba.get_integerv(gl::ALPHA_BITS, &mut bits);
    assert_eq!(bits, [8]);
}

#[cfg(feature = "gl")]
#[test]
fn an_rgb_framebuffer_matches_the_driver() {
    let Some(mut backend) = test_backend_with(32, 32, RGB) else {
        return;
    };
    let mut c = rgb_context(32);
    c.start_recording();
    scene(&mut c);
    let calls = c.stop_recording();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    backend.replay(&calls);
    assert_eq!(backend.get_error(), gl::NO_ERROR);
    let mut bits = [9i32; 1];
    backend.get_integerv(gl::ALPHA_BITS, &mut bits);
    assert_eq!(bits, [0], "the driver's ALPHA_BITS");
    let (ci, gi) = (c.to_image(), backend.read_image());
    let cmp = fixedgl::compare::compare(&ci, &gi, 1);
    let first = ci
        .enumerate_pixels()
        .find(|(x, y, p)| {
            p.0.iter()
                .zip(gi.get_pixel(*x, *y).0)
                .any(|(a, b)| a.abs_diff(b) > 1)
        })
        .map(|(x, y, p)| format!("({x},{y}) cpu {:?} gl {:?}", p.0, gi.get_pixel(x, y).0));
    assert_eq!(cmp.differing_pixels, 0, "{first:?}");
    assert!(
        gi.pixels().all(|p| p.0[3] == 255),
        "the driver's alpha is 1 too"
    );
}
