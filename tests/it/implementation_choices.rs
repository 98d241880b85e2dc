//! Where GL leaves a rasterisation choice to the implementation, fixedgl makes llvmpipe's; these
//! tests hold the CPU backend to the driver pixel for pixel on such cases. (Every registered
//! scene is held to its tolerance by `tests/scenes.rs`.)
//!
//! Where no EGL device exists the test prints `SKIPPED: ...` and returns; `FIXEDGL_REQUIRE_GL=1`
//! makes that a failure.
#![cfg(feature = "gl")]

use fixedgl::compare::compare;

/// GL 2.1 §2.6.1 leaves a quad's diagonal to the implementation; fixedgl splits as llvmpipe
/// does: along 0–2 under SMOOTH, along 1–3 under FLAT. A dart (corner 2 reflex) covers
/// different pixels with the two diagonals, and non-planar colours shade differently, so
/// under both shade models the CPU must match the driver pixel for pixel.
#[test]
fn quad_diagonal_matches_the_driver_under_both_shade_models() {
    use fixedgl::gl::{FLAT, QUADS, SMOOTH};
    use fixedgl::Context;
    // A second quad far outside the view, in the same Begin/End, makes the draw need clipping:
    // llvmpipe then splits every quad of the draw along 1–3, even under SMOOTH.
    for (shade, clipped) in [(SMOOTH, false), (FLAT, false), (SMOOTH, true), (FLAT, true)] {
        let mut ctx = match Context::new(64, 64) {
            Ok(c) => c,
            Err(e) => panic!("{e}"),
        };
        ctx.start_recording();
        ctx.shade_model(shade);
        ctx.begin(QUADS);
        let corners = [[-0.8, -0.8], [0.8, -0.8], [0.0, -0.3], [-0.2, 0.8]];
        let colours = [
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
        ];
        for (v, c) in corners.iter().zip(colours) {
            ctx.color3fv(&c);
            ctx.vertex2f(v[0], v[1]);
        }
        if clipped {
            for [x, y] in [[5.0, 5.0], [6.0, 5.0], [6.0, 6.0], [5.0, 6.0]] {
                ctx.vertex2f(x, y);
            }
        }
        ctx.end();
        let calls = ctx.stop_recording();
        let cpu = ctx.to_image();
        let Some(mut gl) = crate::common::test_backend(64, 64) else {
            return;
        };
        gl.replay(&calls);
        gl.finish();
        let c = compare(&cpu, &gl.read_image(), 2);
        assert_eq!(
            c.differing_pixels, 0,
            "shade {shade:#x}, clipped {clipped}: {c}"
        );
        // The dart is drawn at all (the test would pass trivially on two empty images).
        assert!(cpu.pixels().filter(|p| p.0[3] != 0).count() > 500);
    }
}
