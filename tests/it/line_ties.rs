//! Lines whose ends lie exactly on pixel centres' rows or columns (ties of the diamond-exit rule,
//! GL 2.1 §3.4.1), drawn as llvmpipe (Mesa 22.3.6) draws them: a framebuffer object as the
//! driver draws one (`GlBackend::new`'s EGL FBO), and a window-system framebuffer
//! (`Context::set_window_system_framebuffer`, what the C ABI's contexts are) as the driver draws
//! OSMesa's, GLX's and EGL's surfaces, upside down in its own coordinates (Mesa's `Y_0_TOP`).
//! Every picture is compared with the driver's, pixel for pixel: 256 segments of width 1 plain
//! and stippled and of width 3, and piglit linestipple's line loop.

use fixedgl::{gl, Context};

const W: u32 = 64;

/// 256 segments of every direction (the 8 octants, the axes and diagonals), with ends on pixel
/// centres, pixel edges and quarter points.
fn segments() -> Vec<[f32; 4]> {
    let pts = [0.0f32, 0.5, 0.25, 0.75];
    let dirs = [
        (20.0, 7.0),
        (-20.0, 7.0),
        (20.0, -7.0),
        (-20.0, -7.0),
        (7.0, 20.0),
        (-7.0, 20.0),
        (7.0, -20.0),
        (-7.0, -20.0),
        (15.0, 0.0),
        (-15.0, 0.0),
        (0.0, 15.0),
        (0.0, -15.0),
        (10.0, 10.0),
        (-10.0, -10.0),
        (10.0, -10.0),
        (-10.0, 10.0),
    ];
    let mut v = Vec::new();
    let mut k = 0u32;
    for &fa in &pts {
        for &fb in &pts {
            for (dx, dy) in dirs {
                let x0 = 22.0 + (k % 3) as f32 + fa;
                let y0 = 22.0 + (k % 5) as f32 + fb;
                k += 1;
                v.push([x0, y0, x0 + dx + fb, y0 + dy + fa]);
            }
        }
    }
    v
}

/// One segment as LINES of `width`, stippled with piglit linestipple's "Line loop" pattern or
/// not.
fn draw(c: &mut Context, s: [f32; 4], stipple: bool, width: f32) {
    c.clear_color(0.0, 0.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.matrix_mode(gl::PROJECTION);
    c.load_identity();
    c.ortho(0.0, f64::from(W), 0.0, f64::from(W), -1.0, 1.0);
    c.matrix_mode(gl::MODELVIEW);
    c.load_identity();
    // The driver's context is reused from case to case: every state a case sets is set.
    if stipple {
        c.enable(gl::LINE_STIPPLE);
        c.line_stipple(1, 0x8CEF);
    } else {
        c.disable(gl::LINE_STIPPLE);
    }
    c.line_width(width);
    c.begin(gl::LINES);
    c.vertex2f(s[0], s[1]);
    c.vertex2f(s[2], s[3]);
    c.end();
}

/// piglit linestipple's "Line loop": a 20-pixel square through pixel centres, pattern 0x8CEF,
/// whose closing (downward) segment's dashes start and end on pixel centres.
fn piglit_loop(c: &mut Context) {
    c.line_width(1.0);
    c.clear_color(0.0, 0.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.matrix_mode(gl::PROJECTION);
    c.load_identity();
    c.ortho(0.0, f64::from(W), 0.0, f64::from(W), -1.0, 1.0);
    c.enable(gl::LINE_STIPPLE);
    c.line_stipple(1, 0x8CEF);
    c.color3f(0.0, 1.0, 0.0);
    c.begin(gl::LINE_LOOP);
    for (x, y) in [(36.5, 10.5), (56.5, 10.5), (56.5, 30.5), (36.5, 30.5)] {
        c.vertex2f(x, y);
    }
    c.end();
}

fn cpu(window_system: bool) -> Context {
    let Ok(mut c) = Context::new(W, W) else {
        panic!("CPU context")
    };
    c.set_window_system_framebuffer(window_system);
    c
}

/// The pixels set in `im` as (x, y) with y up.
fn lit(im: &image::RgbaImage) -> Vec<(u32, u32)> {
    im.enumerate_pixels()
        .filter(|(_, _, p)| p.0[..3].iter().any(|&v| v > 0))
        .map(|(x, y, _)| (x, im.height() - 1 - y))
        .collect()
}

/// A named picture to draw.
#[cfg(feature = "gl")]
type Case = (String, Box<dyn Fn(&mut Context)>);

/// Draws each case on the CPU (as a window-system framebuffer or not) and on `backend`; the
/// cases whose pictures differ, and how many cases the other orientation would get wrong (so
/// that the comparison is known to tell the two apart).
#[cfg(feature = "gl")]
fn differing(
    backend: &mut fixedgl::glbackend::GlBackend,
    window_system: bool,
) -> (Vec<String>, usize) {
    let mut cases: Vec<Case> = Vec::new();
    for (stipple, width) in [(false, 1.0), (true, 1.0), (false, 3.0)] {
        for s in segments() {
            cases.push((
                format!("{s:?} stipple {stipple} width {width}"),
                Box::new(move |c: &mut Context| draw(c, s, stipple, width)),
            ));
        }
    }
    cases.push(("piglit line loop".into(), Box::new(piglit_loop)));
    let (mut bad, mut other_bad) = (Vec::new(), 0);
    for (name, f) in &cases {
        let mut c = cpu(window_system);
        c.start_recording();
        f(&mut c);
        let calls = c.stop_recording();
        assert_eq!(c.get_error(), gl::NO_ERROR);
        backend.replay(&calls);
        assert_eq!(backend.get_error(), gl::NO_ERROR);
        let (ci, gi) = (lit(&c.to_image()), lit(&backend.read_image()));
        if ci != gi {
            let only = |a: &[(u32, u32)], b: &[(u32, u32)]| {
                a.iter()
                    .filter(|p| !b.contains(p))
                    .copied()
                    .collect::<Vec<_>>()
            };
            bad.push(format!(
                "{name}: cpu only {:?}, driver only {:?}",
                only(&ci, &gi),
                only(&gi, &ci)
            ));
        }
        let mut o = cpu(!window_system);
        f(&mut o);
        if lit(&o.to_image()) != gi {
            other_bad += 1;
        }
    }
    (bad, other_bad)
}

#[cfg(feature = "gl")]
#[test]
fn line_ends_on_pixel_centres_as_llvmpipe_draws_a_framebuffer_object() {
    let Some(mut fbo) = crate::common::test_backend(W, W) else {
        return;
    };
    let (bad, other) = differing(&mut fbo, false);
    assert!(bad.is_empty(), "{} of 769 differ: {bad:#?}", bad.len());
    // Measured: 38 of the 512 width-1 pictures come out differently in the other orientation.
    assert!(
        other >= 30,
        "only {other} cases tell the orientations apart"
    );
}

#[cfg(feature = "gl")]
#[test]
fn line_ends_on_pixel_centres_as_llvmpipe_draws_a_window() {
    let Some(mut os) = crate::common::osmesa_backend(W, W, fixedgl::ContextConfig::default())
    else {
        return;
    };
    let (bad, other) = differing(&mut os, true);
    assert!(bad.is_empty(), "{} of 769 differ: {bad:#?}", bad.len());
    assert!(
        other >= 30,
        "only {other} cases tell the orientations apart"
    );
}

/// Some of the segments, moved by (dx, dy): lines with ties that the two orientations draw
/// differently.
fn some_lines(c: &mut Context, dx: f32, dy: f32) {
    c.begin(gl::LINES);
    for s in segments().iter().step_by(7) {
        c.vertex2f(s[0] + dx, s[1] + dy);
        c.vertex2f(s[2] + dx, s[3] + dy);
    }
    c.end();
}

/// `some_lines` moved by (-16, -16) on a 32 x 32 CPU framebuffer drawn in one orientation.
fn lines_32(window_system: bool) -> Vec<(u32, u32)> {
    let Ok(mut c) = Context::new(32, 32) else {
        panic!("CPU context")
    };
    c.set_window_system_framebuffer(window_system);
    c.matrix_mode(gl::PROJECTION);
    c.ortho(0.0, 32.0, 0.0, 32.0, -1.0, 1.0);
    some_lines(&mut c, -16.0, -16.0);
    lit(&c.to_image())
}

/// A framebuffer object is drawn as llvmpipe draws objects even when the window is a
/// window-system framebuffer, and the window goes back to its own orientation once the object
/// is unbound: lines into a texture shown in the window's lower-left quarter, then lines in
/// the upper-right quarter, against OSMesa.
#[cfg(feature = "gl")]
#[test]
fn a_framebuffer_object_is_drawn_as_an_object_under_a_window_system_window() {
    let scene = |c: &mut Context| {
        c.clear_color(0.0, 0.0, 0.0, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        let mut tex = [0];
        c.gen_textures(1, &mut tex);
        c.bind_texture(gl::TEXTURE_2D, tex[0]);
        c.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA8 as i32,
            32,
            32,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            None,
        );
        c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
        c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
        let mut fb = [0];
        c.gen_framebuffers(1, &mut fb);
        c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
        c.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            tex[0],
            0,
        );
        c.viewport(0, 0, 32, 32);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.matrix_mode(gl::PROJECTION);
        c.load_identity();
        c.ortho(0.0, 32.0, 0.0, 32.0, -1.0, 1.0);
        some_lines(c, -16.0, -16.0);
        c.bind_framebuffer(gl::FRAMEBUFFER, 0);
        // The texture's texels one to one onto the window's lower-left quarter...
        c.viewport(0, 0, W as i32, W as i32);
        c.load_identity();
        c.ortho(0.0, f64::from(W), 0.0, f64::from(W), -1.0, 1.0);
        c.enable(gl::TEXTURE_2D);
        c.begin(gl::QUADS);
        for (s, t) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            c.tex_coord2f(s, t);
            c.vertex2f(s * 32.0, t * 32.0);
        }
        c.end();
        c.disable(gl::TEXTURE_2D);
        // ... and the same lines in the window's upper-right quarter (scissored to it).
        c.enable(gl::SCISSOR_TEST);
        c.scissor(32, 32, 32, 32);
        some_lines(c, 16.0, 16.0);
    };
    let Some(mut os) = crate::common::osmesa_backend(W, W, fixedgl::ContextConfig::default())
    else {
        return;
    };
    let mut c = cpu(true);
    c.start_recording();
    scene(&mut c);
    let calls = c.stop_recording();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    os.replay(&calls);
    assert_eq!(os.get_error(), gl::NO_ERROR);
    let (ci, gi) = (lit(&c.to_image()), lit(&os.read_image()));
    assert_eq!(ci, gi);
    // The quarters show what each orientation draws, and the two differ.
    let quarter = |upper: bool| -> Vec<(u32, u32)> {
        let o = if upper { 32 } else { 0 };
        let mut q: Vec<_> = ci
            .iter()
            .filter(|(x, y)| (o..o + 32).contains(x) && (o..o + 32).contains(y))
            .map(|&(x, y)| (x - o, y - o))
            .collect();
        q.sort_unstable();
        q
    };
    let sorted = |mut v: Vec<(u32, u32)>| {
        v.sort_unstable();
        v
    };
    let (object, window) = (sorted(lines_32(false)), sorted(lines_32(true)));
    assert_ne!(object, window);
    assert_eq!(quarter(false), object);
    assert_eq!(quarter(true), window);
}

/// Without the driver: a vertical line from one pixel centre down to another, whose two
/// ends are both ties, draws rows 11–19 as an object (both end rows left out, as llvmpipe
/// does) and rows 11–20 in a window (start drawn, end not, as GL's diamond-exit rule says);
/// upward, rows 10–19 in both (measured on llvmpipe, Mesa 22.3.6: EGL FBO and OSMesa).
#[test]
fn a_vertical_line_between_pixel_centres_draws_the_driver_rows() {
    for (window_system, down, rows) in [
        (false, true, 11..=19),
        (true, true, 11..=20),
        (false, false, 10..=19),
        (true, false, 10..=19),
    ] {
        let mut c = cpu(window_system);
        let (a, b) = if down { (20.5, 10.5) } else { (10.5, 20.5) };
        draw(&mut c, [5.5, a, 5.5, b], false, 1.0);
        let want: Vec<(u32, u32)> = rows.map(|y| (5, y)).collect();
        let mut got = lit(&c.to_image());
        got.sort_by_key(|p| p.1);
        assert_eq!(got, want, "window-system {window_system}, downward {down}");
    }
}
