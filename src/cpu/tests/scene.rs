//! The scene (`Scene` in the module above): flushes are set up and binned as they come and
//! rasterised together when the framebuffer is needed. The pixels must be exactly those of
//! rasterising every flush as it is made, whatever state changes between the flushes.

use std::sync::Arc;

use crate::gl;
use crate::state::ContextConfig;
use crate::Context;

/// Objects drawn: more than `SCENE_PARTS`, so the scene also fills up inside the frame.
const OBJECTS: usize = 1100;

/// What a frame leaves: the back buffer, the front buffer and an occlusion query's count.
type Frame = (Vec<u8>, Vec<u8>, u32);

/// A frame of `OBJECTS` small quads, each under its own modelview matrix (a flush each), with
/// state that changes from object to object: fog modes, blending, depth functions, a texture
/// whose filter and texels change between the quads that sample it, the stencil test, the
/// polygon stipple, the colour mask, the draw buffers (back, then both) and an occlusion query
/// around some of them. With `sync`, a pixel is read after every object, which rasterises
/// each flush on its own, as before the scene.
fn frame(sync: bool) -> Frame {
    let config = ContextConfig {
        double_buffered: true,
        ..ContextConfig::default()
    };
    let mut gl = Context::with_config(200, 160, config).expect("context");
    let mut px = [0u8; 4];
    gl.clear_color(0.2, 0.25, 0.3, 1.0);
    gl.draw_buffer(gl::FRONT_AND_BACK);
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    gl.draw_buffer(gl::BACK);
    gl.matrix_mode(gl::PROJECTION);
    gl.ortho(0.0, 200.0, 0.0, 160.0, -10.0, 10.0);
    gl.matrix_mode(gl::MODELVIEW);
    gl.enable(gl::DEPTH_TEST);
    gl.fogfv(gl::FOG_COLOR, &[0.9, 0.8, 0.7, 1.0]);
    gl.fogf(gl::FOG_DENSITY, 0.3);
    gl.fogf(gl::FOG_END, 12.0);
    gl.stencil_op(gl::KEEP, gl::KEEP, gl::INCR);
    gl.polygon_stipple(&[0xA5; 128]);
    let mut tex = [0u32; 1];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(gl::TEXTURE_2D, tex[0]);
    let texels: Vec<u8> = (0..64u8).map(|i| i.wrapping_mul(37)).collect();
    gl.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        4,
        4,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&texels),
    );
    let mut query = [0u32; 1];
    gl.gen_queries(1, &mut query);
    for k in 0..OBJECTS {
        let kind = k % 8;
        if k == 500 {
            gl.begin_query(gl::SAMPLES_PASSED, query[0]);
        }
        if k == 600 {
            gl.end_query(gl::SAMPLES_PASSED);
        }
        if k == 700 {
            gl.draw_buffer(gl::FRONT_AND_BACK);
        }
        let on = |gl: &mut Context, cap: u32, yes: bool| match yes {
            true => gl.enable(cap),
            false => gl.disable(cap),
        };
        on(&mut gl, gl::FOG, kind == 1 || kind == 5);
        gl.fogi(gl::FOG_MODE, [gl::LINEAR, gl::EXP, gl::EXP2][k % 3] as i32);
        on(&mut gl, gl::BLEND, kind == 2 || kind == 5);
        gl.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
        gl.depth_func([gl::LEQUAL, gl::LESS, gl::ALWAYS, gl::GREATER][k % 4]);
        on(&mut gl, gl::TEXTURE_2D, kind == 3 || kind == 6);
        if kind == 3 || kind == 6 {
            let filter = [gl::NEAREST, gl::LINEAR][k % 2] as i32;
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, filter);
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, filter);
        }
        if k % 50 == 3 {
            let texel = [(k % 256) as u8, 40, 200, 255];
            gl.tex_sub_image_2d(
                gl::TEXTURE_2D,
                0,
                1,
                2,
                1,
                1,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                &texel,
            );
        }
        on(&mut gl, gl::STENCIL_TEST, kind == 4);
        gl.stencil_func(gl::LEQUAL, (k % 3) as i32, 0xFF);
        on(&mut gl, gl::POLYGON_STIPPLE, kind == 7);
        gl.color_mask(true, kind != 6, true, true);
        gl.load_identity();
        let (x, y) = ((k * 37 % 190) as f32, (k * 53 % 150) as f32);
        gl.translatef(x, y, (k % 11) as f32 - 5.0);
        gl.rotatef((k * 13 % 360) as f32, 0.0, 0.0, 1.0);
        let s = 6.0 + (k % 5) as f32 * 9.0;
        gl.begin(gl::QUADS);
        for (i, (cx, cy)) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .into_iter()
            .enumerate()
        {
            let c = (k + i) as f32 / OBJECTS as f32;
            gl.color4f(c, 1.0 - c, (i as f32) * 0.3, 0.6);
            gl.tex_coord2f((cx + 1.0) * 0.7, (cy + 1.0) * 0.7);
            gl.vertex3f(cx * s, cy * s, 0.5 * cx);
        }
        gl.end();
        if sync {
            gl.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
        }
    }
    assert_eq!(gl.get_error(), gl::NO_ERROR);
    let mut count = [0u32; 1];
    gl.get_query_objectuiv(query[0], gl::QUERY_RESULT, &mut count);
    let back = gl.to_image().into_raw();
    let front = gl.front_rgba();
    (back, front, count[0])
}

#[test]
fn a_frame_rasterised_as_one_scene_is_the_frame_rasterised_flush_by_flush() {
    let (back, front, count) = frame(false);
    let (back1, front1, count1) = frame(true);
    assert_eq!(count, count1, "occlusion query counts");
    assert!(back == back1, "the back buffers differ");
    assert!(front == front1, "the front buffers differ");
    // The frame is not trivially uniform, and the query counted something.
    let distinct: std::collections::BTreeSet<&[u8]> = back.chunks(4).collect();
    assert!(distinct.len() > 500, "only {} colours", distinct.len());
    assert!(count > 1000, "{count} samples");
}

/// A texture a waiting flush samples: a parameter change neither rasterises the scene nor
/// copies the images (the object is copied, its levels shared); a change to its texels
/// rasterises the scene first, so that the level is not copied either.
#[test]
fn changing_a_texture_the_scene_samples_copies_no_image() {
    let mut gl = Context::new(64, 64).expect("context");
    let mut tex = [0u32; 1];
    gl.gen_textures(1, &mut tex);
    gl.bind_texture(gl::TEXTURE_2D, tex[0]);
    let texels = [255u8; 4 * 16 * 16];
    gl.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        16,
        16,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&texels),
    );
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    gl.enable(gl::TEXTURE_2D);
    let image = |gl: &Context| {
        let obj = gl.state.textures.bound_2d(0).expect("bound");
        obj.face_level(0, 0).map(|l| Arc::as_ptr(&l.texels))
    };
    let before = image(&gl);
    assert!(before.is_some());
    let passes = gl.draw_stats().passes;
    gl.begin(gl::TRIANGLES);
    gl.tex_coord2f(0.0, 0.0);
    gl.vertex2f(-1.0, -1.0);
    gl.tex_coord2f(1.0, 0.0);
    gl.vertex2f(1.0, -1.0);
    gl.tex_coord2f(0.0, 1.0);
    gl.vertex2f(-1.0, 1.0);
    gl.end();
    // A state change: the triangle is set up into the scene, which holds the texture.
    gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    assert_eq!(
        gl.draw_stats().passes,
        passes,
        "a parameter change rasterised"
    );
    assert_eq!(image(&gl), before, "a parameter change copied the image");
    gl.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        1,
        1,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &[0; 4],
    );
    assert_eq!(
        gl.draw_stats().passes,
        passes + 1,
        "no pass before the texels changed"
    );
    assert_eq!(image(&gl), before, "the texels were copied");
    // And the triangle was drawn with the texture as it was (white).
    let img = gl.to_image();
    assert_eq!(img.get_pixel(2, 61).0, [255; 4]);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

/// Occlusion queries whose results are read late: four query objects, each begun and ended
/// around its own objects (one begun twice, its first count never read; one counting a pixel
/// rectangle; one counting nothing), all read after the last object. Each result, and the
/// image, equals the frame that reads each result right after its EndQuery (a pass each);
/// read late, the frame makes one pass.
#[test]
fn queries_read_late_count_what_they_counted() {
    fn frame(read_at_once: bool) -> (Vec<u8>, [u32; 4], u64) {
        let mut gl = Context::new(200, 160).expect("context");
        gl.clear_color(0.1, 0.2, 0.3, 1.0);
        gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        gl.matrix_mode(gl::PROJECTION);
        gl.ortho(0.0, 200.0, 0.0, 160.0, -10.0, 10.0);
        gl.matrix_mode(gl::MODELVIEW);
        gl.enable(gl::DEPTH_TEST);
        let mut ids = [0u32; 4];
        gl.gen_queries(4, &mut ids);
        let mut counts = [0u32; 4];
        let passes = gl.draw_stats().passes;
        // (query, first object, end object): query 0 twice, query 3 around objects that are
        // all behind what is drawn.
        let ranges = [
            (0, 10, 40),
            (1, 60, 120),
            (2, 130, 200),
            (0, 210, 260),
            (3, 270, 280),
        ];
        for k in 0..300usize {
            for &(q, lo, hi) in &ranges {
                if k == lo {
                    gl.begin_query(gl::SAMPLES_PASSED, ids[q]);
                }
                if k == hi {
                    gl.end_query(gl::SAMPLES_PASSED);
                    if read_at_once && !(q == 0 && lo == 10) {
                        let mut n = [0u32];
                        gl.get_query_objectuiv(ids[q], gl::QUERY_RESULT, &mut n);
                        counts[q] = n[0];
                    }
                }
            }
            if k == 150 {
                let px: Vec<u8> = (0..4 * 30 * 20).map(|i| (i * 7) as u8).collect();
                gl.raster_pos3f(20.5, 30.5, -9.0);
                gl.draw_pixels(30, 20, gl::RGBA, gl::UNSIGNED_BYTE, &px);
            }
            gl.load_identity();
            // Query 3's objects lie outside the window: no fragment.
            let x = match (270..280).contains(&k) {
                true => -500.0,
                false => (k * 37 % 190) as f32,
            };
            let y = (k * 53 % 150) as f32;
            gl.translatef(x, y, (k % 9) as f32 - 4.0);
            gl.rotatef((k * 13 % 360) as f32, 0.0, 0.0, 1.0);
            let s = 4.0 + (k % 5) as f32 * 7.0;
            gl.color3f((k % 7) as f32 / 7.0, 0.5, (k % 3) as f32 / 3.0);
            gl.rectf(-s, -s, s, s);
        }
        if !read_at_once {
            for (q, count) in counts.iter_mut().enumerate() {
                let mut n = [0u32];
                gl.get_query_objectuiv(ids[q], gl::QUERY_RESULT, &mut n);
                *count = n[0];
            }
        }
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        let image = gl.to_image().into_raw();
        (image, counts, gl.draw_stats().passes - passes)
    }
    let (late, late_counts, late_passes) = frame(false);
    let (once, once_counts, _) = frame(true);
    assert_eq!(late_counts, once_counts, "query results");
    assert!(late == once, "the images differ");
    assert!(late_counts[..3].iter().all(|&n| n > 100), "{late_counts:?}");
    assert_eq!(late_counts[3], 0, "{late_counts:?}");
    // The pixel rectangle rasterises the scene once; the results' reads once more.
    assert_eq!(late_passes, 2, "passes");
}

/// Bitmaps binned into the scene (`Renderer::bitmap`, plain ones) give the pixels of every
/// bitmap drawn in place at its call (`draw_pixel_rect`, the test hook `bitmaps_in_place`):
/// random interleavings of depth-tested triangles, bitmaps at random raster positions (across
/// tile edges, partly off the window), colour masks, draw buffers (back, front, both, none),
/// the scissor test, bitmaps made not plain (depth test, blending, fog) between plain ones,
/// clears, reads in the middle of the frame, and bursts of bitmaps past `SCENE_PARTS`. The
/// back, front and depth buffers must match byte for byte.
#[test]
fn binned_bitmaps_are_the_bitmaps_drawn_in_place() {
    let mut gen = crate::cpu::testgen::Gen(77);
    let mut next = move || gen.next() as u32;
    let config = ContextConfig {
        double_buffered: true,
        ..ContextConfig::default()
    };
    let (w, h) = (150i32, 110i32);
    // Passes of each route: binning leaves fewer.
    let mut passes = [0u64; 2];
    for case in 0..60 {
        // One script of steps, replayed on both contexts.
        let steps: Vec<[u32; 12]> = (0..60).map(|_| std::array::from_fn(|_| next())).collect();
        let mut images = Vec::new();
        for in_place in [false, true] {
            let mut gl = Context::with_config(w as u32, h as u32, config).expect("context");
            gl.renderer.bitmaps_in_place = in_place;
            gl.matrix_mode(gl::PROJECTION);
            gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
            gl.matrix_mode(gl::MODELVIEW);
            gl.clear_color(0.1, 0.2, 0.3, 0.4);
            gl.draw_buffer(gl::FRONT_AND_BACK);
            gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
            gl.draw_buffer(gl::BACK);
            gl.depth_func(gl::LEQUAL);
            gl.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
            gl.fogfv(gl::FOG_COLOR, &[0.9, 0.1, 0.5, 1.0]);
            let data: Vec<u8> = (0..2000).map(|k| (k * 131 % 251) as u8 ^ 0x5A).collect();
            let mut px = [0u8; 4];
            for s in &steps {
                let unit = |v: u32| (v % 1001) as f32 / 1000.0;
                match s[0] % 16 {
                    0..=2 => {
                        // A triangle, depth-tested when the test is on.
                        gl.color4f(unit(s[1]), unit(s[2]), unit(s[3]), unit(s[4]));
                        gl.begin(gl::TRIANGLES);
                        for k in 0..3 {
                            let (x, y) = (s[5 + 2 * k] % 200, s[6 + 2 * k] % 160);
                            let z = unit(s[11] >> (k * 4)) * 1.8 - 0.9;
                            gl.vertex3f(x as f32 - 25.0, y as f32 - 25.0, z);
                        }
                        gl.end();
                    }
                    3..=8 => {
                        // A bitmap.
                        gl.color4f(unit(s[1]), unit(s[2]), unit(s[3]), unit(s[4]));
                        let z = unit(s[5]) * 1.8 - 0.9;
                        gl.window_pos3f(
                            (s[6] % 190) as f32 - 20.0 + 0.5 * (s[7] % 2) as f32,
                            (s[8] % 150) as f32 - 20.0,
                            z,
                        );
                        let (bw, bh) = (1 + (s[9] % 40) as i32, 1 + (s[10] % 40) as i32);
                        let off = (s[11] % 400) as usize;
                        gl.bitmap(bw, bh, 0.0, 0.0, 3.0, 1.0, Some(&data[off..]));
                    }
                    9 => gl.color_mask(s[1] % 4 != 0, s[2] % 4 != 0, s[3] % 4 != 0, s[4] % 4 != 0),
                    10 => gl.draw_buffer(
                        [gl::BACK, gl::FRONT, gl::FRONT_AND_BACK, gl::NONE, gl::BACK]
                            [s[1] as usize % 5],
                    ),
                    11 => {
                        match s[1] % 3 == 0 {
                            true => gl.disable(gl::SCISSOR_TEST),
                            false => gl.enable(gl::SCISSOR_TEST),
                        }
                        let (x, y) = ((s[2] % 120) as i32, (s[3] % 90) as i32);
                        gl.scissor(x, y, (s[4] % 100) as i32, (s[5] % 80) as i32);
                    }
                    12 => {
                        // State that makes bitmaps not plain, or plain again.
                        let cap = [gl::DEPTH_TEST, gl::BLEND, gl::FOG][s[1] as usize % 3];
                        match s[2] % 2 == 0 {
                            true => gl.enable(cap),
                            false => gl.disable(cap),
                        }
                    }
                    13 => gl.clear(gl::COLOR_BUFFER_BIT | ((s[1] % 2) * gl::DEPTH_BUFFER_BIT)),
                    14 => {
                        let (x, y) = ((s[1] % w as u32) as i32, (s[2] % h as u32) as i32);
                        gl.read_pixels(x, y, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
                    }
                    _ => {
                        // A burst of small bitmaps, past SCENE_PARTS when it comes twice.
                        gl.window_pos2f((s[1] % 100) as f32, (s[2] % 100) as f32);
                        for k in 0..700 {
                            gl.color3f(unit(s[3] ^ k), 0.5, unit(s[4] ^ (k * 7)));
                            let (bw, bh) = (1 + (k % 9) as i32, 1 + (k % 7) as i32);
                            let step = [1.0, -1.0][k as usize % 2];
                            gl.bitmap(
                                bw,
                                bh,
                                0.0,
                                0.0,
                                step,
                                0.5 * step,
                                Some(&data[k as usize..]),
                            );
                        }
                    }
                }
            }
            assert_eq!(gl.get_error(), gl::NO_ERROR, "case {case}");
            passes[usize::from(in_place)] += gl.draw_stats().passes;
            let mut depth = vec![0u8; (w * h * 4) as usize];
            gl.read_pixels(
                0,
                0,
                w,
                h,
                gl::DEPTH_COMPONENT,
                gl::UNSIGNED_INT,
                &mut depth,
            );
            images.push((gl.to_image().into_raw(), gl.front_rgba(), depth));
        }
        let [a, b] = [&images[0], &images[1]];
        assert!(a.0 == b.0, "case {case}: the back buffers differ");
        assert!(a.1 == b.1, "case {case}: the front buffers differ");
        assert!(a.2 == b.2, "case {case}: the depth buffers differ");
    }
    assert!(
        passes[0] != passes[1],
        "passes binned and in place: {passes:?}"
    );
    // A plain bitmap between two triangles makes no pass of its own: the three are
    // rasterised in one pass when the framebuffer is read (in place, the bitmap rasterises
    // the first triangle before it is drawn).
    for (in_place, want) in [(false, 1), (true, 2)] {
        let mut gl = Context::new(100, 100).expect("context");
        gl.renderer.bitmaps_in_place = in_place;
        let before = gl.draw_stats().passes;
        let triangle = |gl: &mut Context| {
            gl.begin(gl::TRIANGLES);
            gl.vertex2f(-1.0, -1.0);
            gl.vertex2f(1.0, -1.0);
            gl.vertex2f(0.0, 1.0);
            gl.end();
        };
        triangle(&mut gl);
        gl.window_pos2f(10.0, 10.0);
        gl.bitmap(8, 8, 0.0, 0.0, 0.0, 0.0, Some(&[0xF0; 32]));
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        gl.color3f(1.0, 0.0, 0.0);
        triangle(&mut gl);
        let mut px = [0u8; 4];
        gl.read_pixels(12, 12, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
        assert_eq!(
            gl.draw_stats().passes - before,
            want,
            "in place: {in_place}"
        );
    }
}
