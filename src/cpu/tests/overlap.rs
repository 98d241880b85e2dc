//! Background drawing (`Renderer::flush_if_large` hands a full batch to the thread pool while the
//! front end fills the next): the pixels must be exactly those of drawing every batch in place,
//! whatever state changes, Material calls inside Begin/End and reads happen between batches.

use crate::gl;
use crate::Context;

/// Rows of the strip mesh per band, and vertices per row: each band holds well over two
/// batches' worth of vertices (a batch is drawn once it holds 32k).
const ROWS: usize = 120;
const COLS: usize = 600;

/// A lit mesh in three bands with a state change between bands, Material changes inside some
/// Begin/End pairs, and a read of the framebuffer in the middle. Returns the mid-frame read,
/// the final image, and how many batches were drawn in the background.
fn frame(gl: &mut Context) -> (Vec<u8>, Vec<u8>, u64) {
    gl.clear_color(0.1, 0.1, 0.1, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.enable(gl::DEPTH_TEST);
    gl.enable(gl::LIGHTING);
    gl.enable(gl::LIGHT0);
    gl.matrix_mode(gl::PROJECTION);
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
    gl.matrix_mode(gl::MODELVIEW);
    let mut mid = vec![0u8; 64 * 64 * 4];
    for band in 0..3 {
        let b = band as f32;
        gl.lightfv(gl::LIGHT0, gl::POSITION, &[b - 1.0, 1.0, 1.0, 0.0]);
        for row in 0..ROWS {
            let y0 = -1.0 + 2.0 * (band * ROWS + row) as f32 / (3 * ROWS) as f32;
            let y1 = y0 + 2.0 / (3 * ROWS) as f32;
            gl.begin(gl::TRIANGLE_STRIP);
            for col in 0..COLS {
                if col == COLS / 2 && row % 7 == 0 {
                    let g = (row % 5) as f32 / 5.0;
                    gl.materialfv(gl::FRONT, gl::DIFFUSE, &[0.9, g, 0.3, 1.0]);
                }
                let x = -1.0 + 2.0 * (col / 2) as f32 / (COLS / 2) as f32;
                let y = if col % 2 == 0 { y0 } else { y1 };
                let z = (x * 3.0).sin() * (y * 5.0).cos() * 0.5;
                gl.normal3f(-(x * 3.0).cos(), (y * 5.0).sin(), 1.0);
                gl.vertex3f(x, y, z);
            }
            gl.end();
        }
        if band == 1 {
            gl.read_pixels(100, 100, 64, 64, gl::RGBA, gl::UNSIGNED_BYTE, &mut mid);
        }
    }
    let img = gl.to_image().into_raw();
    (mid, img, gl.renderer.background_draws)
}

#[test]
fn background_draws_give_the_pixels_of_drawing_in_place() {
    // On this (non-pool) thread, full batches are drawn in the background.
    let mut a = Context::new(256, 256).expect("context");
    let (mid_a, img_a, n_a) = frame(&mut a);
    assert!(n_a >= 4, "expected background draws, got {n_a}");
    // Called from a pool thread, the renderer draws every batch in place.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("pool");
    let (mid_b, img_b, n_b) = pool.install(|| {
        let mut b = Context::new(256, 256).expect("context");
        frame(&mut b)
    });
    assert_eq!(n_b, 0);
    assert_eq!(a.get_error(), gl::NO_ERROR);
    assert!(mid_a == mid_b, "the mid-frame reads differ");
    assert!(img_a == img_b, "the final images differ");
    // The frame is not trivially uniform: the lit mesh covers most pixels with varied colours.
    let distinct: std::collections::BTreeSet<&[u8]> = img_a.chunks(4).collect();
    assert!(distinct.len() > 1000, "only {} colours", distinct.len());
    // The vertex stage of every batch handed to the pool run in the pool's job, then on the
    // calling thread (the two sides of the balancing rule): the same pixels.
    for on_pool in [true, false] {
        let mut c = Context::new(256, 256).expect("context");
        c.renderer.vertex_stage_on_pool = Some(on_pool);
        let (mid_c, img_c, n_c) = frame(&mut c);
        assert_eq!(n_c, n_a);
        assert!(
            mid_c == mid_b,
            "the mid-frame reads differ (on_pool {on_pool})"
        );
        assert!(
            img_c == img_b,
            "the final images differ (on_pool {on_pool})"
        );
    }
}

/// A background draw that panics must not be swallowed (issue #11): before, the frame went on
/// with a cleared framebuffer. The panic reaches the caller at the next wait, and the
/// framebuffer is the one drawn so far, not a new cleared one.
#[test]
fn a_panicking_background_draw_reaches_the_caller() {
    let mut gl = Context::new(64, 64).expect("context");
    gl.clear_color(0.0, 0.0, 1.0, 1.0);
    gl.clear(gl::COLOR_BUFFER_BIT);
    gl.renderer.panic_in_background = true;
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        // Two batches' worth of vertices: the first full batch goes to the pool and panics
        // there; the next full batch, or the read below, waits for it.
        for row in 0..120 {
            let y = -1.0 + row as f32 / 60.0;
            gl.begin(gl::TRIANGLE_STRIP);
            for col in 0..600 {
                let x = -1.0 + (col / 2) as f32 / 150.0;
                gl.vertex2f(x, if col % 2 == 0 { y } else { y + 1.0 / 60.0 });
            }
            gl.end();
        }
        gl.to_image()
    }));
    assert!(caught.is_err(), "the background draw's panic was swallowed");
    assert!(gl.renderer.background_draws >= 1);
    // The framebuffer kept what was drawn before: the blue clear, not a new zeroed buffer.
    gl.renderer.discard_batch();
    let px = gl.renderer.color();
    assert_eq!(px[0], [0, 0, 255, 255]);
}
