//! Framebuffer objects (GL_EXT_framebuffer_object under the GL 3.0 names): render to a texture
//! and sample it, colour and depth renderbuffers read back with ReadPixels, the statuses of
//! incomplete framebuffers and the errors, deletion while bound, and display lists — each
//! against the driver (Mesa llvmpipe), which replays the same recorded calls.

use fixedgl::{gl, Context};

fn ctx(w: u32) -> Context {
    match Context::new(w, w) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// A `size` x `size` RGBA8 texture with no data, NEAREST, bound to TEXTURE_2D; its name.
fn color_texture(c: &mut Context, size: i32) -> u32 {
    let mut tex = [0];
    c.gen_textures(1, &mut tex);
    c.bind_texture(gl::TEXTURE_2D, tex[0]);
    c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    c.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA8 as i32,
        size,
        size,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None,
    );
    tex[0]
}

/// Two overlapping triangles at different depths, the nearer drawn first, in a
/// `size`-pixel viewport: with the depth test the nearer (green) stays in front.
fn depth_scene(c: &mut Context, size: i32) {
    c.viewport(0, 0, size, size);
    c.clear_color(0.1, 0.2, 0.7, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    c.enable(gl::DEPTH_TEST);
    c.begin(gl::TRIANGLES);
    c.color3f(0.0, 1.0, 0.0);
    c.vertex3f(-0.9, -0.9, -0.5);
    c.vertex3f(0.9, -0.6, -0.5);
    c.vertex3f(0.0, 0.9, -0.5);
    c.color3f(1.0, 0.3, 0.2);
    c.vertex3f(-0.9, 0.9, 0.5);
    c.vertex3f(0.9, 0.9, 0.5);
    c.vertex3f(0.0, -0.9, 0.5);
    c.end();
    c.disable(gl::DEPTH_TEST);
}

/// Draws the 2D texture `tex` over the whole `size`-pixel window with REPLACE.
fn show_texture(c: &mut Context, tex: u32, size: i32) {
    c.viewport(0, 0, size, size);
    c.clear_color(0.0, 0.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.bind_texture(gl::TEXTURE_2D, tex);
    c.enable(gl::TEXTURE_2D);
    c.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
    c.begin(gl::QUADS);
    for (s, t) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        c.tex_coord2f(s, t);
        c.vertex2f(s * 1.8 - 0.9, t * 1.8 - 0.9);
    }
    c.end();
    c.disable(gl::TEXTURE_2D);
}

/// Render to a texture with a depth renderbuffer, then draw the window with that texture:
/// the texels are what was drawn (depth test included), pixel for pixel with the driver.
#[cfg(feature = "gl")]
#[test]
fn render_to_texture_then_sample_matches_the_driver() {
    let Some((bad, first)) = crate::common::cpu_vs_gl(64, 1, |c| {
        let tex = color_texture(c, 32);
        let (mut fb, mut rb) = ([0], [0]);
        c.gen_framebuffers(1, &mut fb);
        c.gen_renderbuffers(1, &mut rb);
        c.bind_renderbuffer(gl::RENDERBUFFER, rb[0]);
        c.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT24, 32, 32);
        c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
        c.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            tex,
            0,
        );
        c.framebuffer_renderbuffer(
            gl::FRAMEBUFFER,
            gl::DEPTH_ATTACHMENT,
            gl::RENDERBUFFER,
            rb[0],
        );
        assert_eq!(
            c.check_framebuffer_status(gl::FRAMEBUFFER),
            gl::FRAMEBUFFER_COMPLETE
        );
        let mut v = [0];
        c.get_integerv(gl::FRAMEBUFFER_BINDING, &mut v);
        assert_eq!(v[0] as u32, fb[0]);
        c.get_integerv(gl::DEPTH_BITS, &mut v);
        assert_eq!(v[0], 24, "the object's depth buffer");
        depth_scene(c, 32);
        c.bind_framebuffer(gl::FRAMEBUFFER, 0);
        show_texture(c, tex, 64);
    }) else {
        return;
    };
    assert_eq!(bad, 0, "{bad} pixels differ; first {first}");
}

/// The window is untouched while an object is bound, and drawing resumes there after.
#[test]
fn the_window_is_untouched_while_an_object_is_bound() {
    let mut c = ctx(16);
    c.clear_color(1.0, 0.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    let tex = color_texture(&mut c, 8);
    let mut fb = [0];
    c.gen_framebuffers(1, &mut fb);
    c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
    c.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        tex,
        0,
    );
    c.clear_color(0.0, 0.0, 1.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    let mut px = [0u8; 4];
    c.read_pixels(7, 7, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [0, 0, 255, 255], "the object's colour buffer");
    let img = c.to_image();
    assert_eq!(
        img.get_pixel(3, 3).0,
        [255, 0, 0, 255],
        "to_image is the window's"
    );
    c.bind_framebuffer(gl::FRAMEBUFFER, 0);
    c.read_pixels(12, 12, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(px, [255, 0, 0, 255], "the window kept its pixels");
    // The texture holds what was cleared.
    let mut texels = vec![0u8; 8 * 8 * 4];
    c.get_tex_image(gl::TEXTURE_2D, 0, gl::RGBA, gl::UNSIGNED_BYTE, &mut texels);
    assert!(texels.chunks(4).all(|p| p == [0, 0, 255, 255]));
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

/// RGBA8 and DEPTH_COMPONENT16 renderbuffers: colour and depth read back with ReadPixels
/// from the object equal the driver's.
#[cfg(feature = "gl")]
#[test]
fn renderbuffers_read_back_as_the_driver() {
    let Some(mut drv) = crate::common::test_backend(32, 32) else {
        return;
    };
    let mut c = ctx(32);
    c.start_recording();
    let (mut fb, mut rb) = ([0], [0; 2]);
    c.gen_framebuffers(1, &mut fb);
    c.gen_renderbuffers(2, &mut rb);
    c.bind_renderbuffer(gl::RENDERBUFFER, rb[0]);
    c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, 24, 20);
    c.bind_renderbuffer(gl::RENDERBUFFER, rb[1]);
    c.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT16, 24, 20);
    c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
    c.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::RENDERBUFFER,
        rb[0],
    );
    c.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        rb[1],
    );
    depth_scene(&mut c, 24);
    // Away and back: the renderbuffers keep what was drawn.
    c.bind_framebuffer(gl::FRAMEBUFFER, 0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
    drv.replay(&c.stop_recording());
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(drv.get_error(), gl::NO_ERROR);
    assert_eq!(
        drv.check_framebuffer_status(gl::FRAMEBUFFER),
        c.check_framebuffer_status(gl::FRAMEBUFFER)
    );
    let n = 24 * 20;
    let mut cpu_rgba = vec![0u8; n * 4];
    c.read_pixels(0, 0, 24, 20, gl::RGBA, gl::UNSIGNED_BYTE, &mut cpu_rgba);
    let drv_rgba = drv.read_rgba(0, 0, 24, 20);
    let bad = cpu_rgba
        .iter()
        .zip(&drv_rgba)
        .filter(|(a, b)| a.abs_diff(**b) > 1)
        .count();
    assert_eq!(bad, 0, "colour components differ");
    let (mut a, mut b) = (vec![0u32; n], vec![0u32; n]);
    let mut bytes = vec![0u8; n * 4];
    c.read_pixels(
        0,
        0,
        24,
        20,
        gl::DEPTH_COMPONENT,
        gl::UNSIGNED_INT,
        &mut bytes,
    );
    for (v, q) in a.iter_mut().zip(bytes.chunks(4)) {
        *v = u32::from_ne_bytes([q[0], q[1], q[2], q[3]]);
    }
    // SAFETY: the backend's context is current (replay made it so); the driver writes 24x20
    // 4-byte values into `b`.
    unsafe {
        drv.raw().ReadPixels(
            0,
            0,
            24,
            20,
            gl::DEPTH_COMPONENT,
            gl::UNSIGNED_INT,
            b.as_mut_ptr().cast(),
        )
    };
    assert_eq!(drv.get_error(), gl::NO_ERROR);
    // 16-bit depth on the driver, 24-bit here: compare at 16 bits.
    let worst = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x >> 16).abs_diff(y >> 16))
        .max()
        .unwrap_or(0);
    assert!(worst <= 1, "depth differs by {worst} at 16 bits");
}

/// The statuses of incomplete framebuffers, the errors of the entry points, and
/// INVALID_FRAMEBUFFER_OPERATION for drawing into an incomplete one: each step's error and
/// status equal the driver's.
#[cfg(feature = "gl")]
#[test]
fn statuses_and_errors_match_the_driver() {
    let Some(mut drv) = crate::common::test_backend(16, 16) else {
        return;
    };
    let mut c = ctx(16);
    type Step = Box<dyn Fn(&mut Context)>;
    let steps: Vec<(&str, Step)> = vec![
        (
            "bind bad target",
            Box::new(|c| c.bind_framebuffer(gl::TEXTURE_2D, 1)),
        ),
        (
            "attach to the window",
            Box::new(|c| {
                c.framebuffer_texture_2d(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::TEXTURE_2D,
                    0,
                    0,
                )
            }),
        ),
        (
            "storage with renderbuffer 0",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, 4, 4)),
        ),
        ("gen -1", Box::new(|c| c.gen_framebuffers(-1, &mut []))),
        (
            "bind 5 (never generated)",
            Box::new(|c| c.bind_framebuffer(gl::FRAMEBUFFER, 5)),
        ),
        (
            "clear, missing attachment",
            Box::new(|c| c.clear(gl::COLOR_BUFFER_BIT)),
        ),
        (
            "begin, missing attachment",
            Box::new(|c| {
                c.begin(gl::TRIANGLES);
                c.end();
            }),
        ),
        (
            "bind renderbuffer 7",
            Box::new(|c| c.bind_renderbuffer(gl::RENDERBUFFER, 7)),
        ),
        (
            "storage bad format",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::LUMINANCE8, 4, 4)),
        ),
        (
            "storage negative",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, -1, 4)),
        ),
        (
            "storage too big",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, 1 << 20, 4)),
        ),
        (
            "storage 0 x 0",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGB8, 0, 0)),
        ),
        (
            "attach empty colour",
            Box::new(|c| {
                c.framebuffer_renderbuffer(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::RENDERBUFFER,
                    7,
                )
            }),
        ),
        (
            "attach unknown renderbuffer",
            Box::new(|c| {
                c.framebuffer_renderbuffer(
                    gl::FRAMEBUFFER,
                    gl::DEPTH_ATTACHMENT,
                    gl::RENDERBUFFER,
                    99,
                )
            }),
        ),
        (
            "attach bad point",
            Box::new(|c| {
                c.framebuffer_renderbuffer(gl::FRAMEBUFFER, gl::DEPTH, gl::RENDERBUFFER, 7)
            }),
        ),
        (
            "attach bad renderbuffer target",
            Box::new(|c| {
                c.framebuffer_renderbuffer(gl::FRAMEBUFFER, gl::DEPTH_ATTACHMENT, gl::TEXTURE_2D, 7)
            }),
        ),
        (
            "storage 8 x 8",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::RGB8, 8, 8)),
        ),
        (
            "depth 4 x 4 renderbuffer 8",
            Box::new(|c| {
                c.bind_renderbuffer(gl::RENDERBUFFER, 8);
                c.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT, 4, 4);
                c.framebuffer_renderbuffer(
                    gl::FRAMEBUFFER,
                    gl::DEPTH_ATTACHMENT,
                    gl::RENDERBUFFER,
                    8,
                );
            }),
        ),
        (
            "depth buffer as colour",
            Box::new(|c| {
                c.framebuffer_renderbuffer(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::RENDERBUFFER,
                    8,
                )
            }),
        ),
        (
            "colour back",
            Box::new(|c| {
                c.framebuffer_renderbuffer(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::RENDERBUFFER,
                    7,
                )
            }),
        ),
        (
            "depth 8 x 8",
            Box::new(|c| c.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT16, 8, 8)),
        ),
        ("draw buffer FRONT", Box::new(|c| c.draw_buffer(gl::FRONT))),
        (
            "draw buffer bad enum",
            Box::new(|c| c.draw_buffer(gl::RGBA)),
        ),
        ("read buffer BACK", Box::new(|c| c.read_buffer(gl::BACK))),
        (
            "clear, complete",
            Box::new(|c| c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT)),
        ),
        (
            "texture of the wrong target",
            Box::new(|c| {
                let mut t = [0];
                c.gen_textures(1, &mut t);
                c.bind_texture(gl::TEXTURE_1D, t[0]);
                c.framebuffer_texture_2d(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::TEXTURE_2D,
                    t[0],
                    0,
                );
            }),
        ),
        (
            "texture that does not exist",
            Box::new(|c| {
                c.framebuffer_texture_2d(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::TEXTURE_2D,
                    77,
                    0,
                )
            }),
        ),
        (
            "texture level -1",
            Box::new(|c| {
                let mut t = [0];
                c.gen_textures(1, &mut t);
                c.bind_texture(gl::TEXTURE_2D, t[0]);
                c.framebuffer_texture_2d(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::TEXTURE_2D,
                    t[0],
                    -1,
                );
            }),
        ),
        (
            "texture without an image",
            Box::new(|c| {
                let mut t = [0];
                c.get_integerv(gl::TEXTURE_BINDING_2D, &mut [0]);
                c.gen_textures(1, &mut t);
                c.bind_texture(gl::TEXTURE_2D, t[0]);
                c.framebuffer_texture_2d(
                    gl::FRAMEBUFFER,
                    gl::COLOR_ATTACHMENT0,
                    gl::TEXTURE_2D,
                    t[0],
                    0,
                );
            }),
        ),
        (
            "read pixels, incomplete",
            Box::new(|c| c.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut [0; 4])),
        ),
        (
            "generate mipmap bad target",
            Box::new(|c| c.generate_mipmap(gl::PROXY_TEXTURE_2D)),
        ),
        ("delete -1", Box::new(|c| c.delete_framebuffers(-1, &[]))),
        (
            "delete the bound",
            Box::new(|c| c.delete_framebuffers(1, &[5])),
        ),
        (
            "clear the window",
            Box::new(|c| c.clear(gl::COLOR_BUFFER_BIT)),
        ),
    ];
    for (label, step) in &steps {
        c.start_recording();
        step(&mut c);
        let calls = c.stop_recording();
        drv.replay(&calls);
        if *label == "read pixels, incomplete" {
            // ReadPixels is not recorded: the driver reads too.
            let mut px = [0u8; 4];
            // SAFETY: the backend's context is current (replay made it so); one RGBA8 pixel.
            unsafe {
                drv.raw().ReadPixels(
                    0,
                    0,
                    1,
                    1,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    px.as_mut_ptr().cast(),
                )
            };
        }
        let (ce, de) = (c.get_error(), drv.get_error());
        let (cs, ds) = (
            c.check_framebuffer_status(gl::FRAMEBUFFER),
            drv.check_framebuffer_status(gl::FRAMEBUFFER),
        );
        assert_eq!(ce, de, "{label}: error {ce:#x} (driver {de:#x})");
        assert_eq!(cs, ds, "{label}: status {cs:#x} (driver {ds:#x})");
        let (mut a, mut b) = ([0], [0]);
        c.get_integerv(gl::FRAMEBUFFER_BINDING, &mut a);
        drv.get_integerv(gl::FRAMEBUFFER_BINDING, &mut b);
        assert_eq!(a, b, "{label}: binding");
    }
}

/// Deleting a texture attached to the bound framebuffer detaches it (missing attachment);
/// deleting the bound framebuffer binds the window, where drawing then goes. The pictures,
/// errors and statuses agree with the driver's.
#[cfg(feature = "gl")]
#[test]
fn deletion_while_bound_matches_the_driver() {
    let Some((bad, first)) = crate::common::cpu_vs_gl(32, 1, |c| {
        let tex = color_texture(c, 16);
        let mut fb = [0];
        c.gen_framebuffers(1, &mut fb);
        c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
        c.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            tex,
            0,
        );
        c.clear_color(0.0, 1.0, 0.0, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.delete_textures(1, &[tex]);
        assert_eq!(
            c.check_framebuffer_status(gl::FRAMEBUFFER),
            gl::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT
        );
        let mut v = [0];
        c.get_framebuffer_attachment_parameteriv(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            &mut v,
        );
        assert_eq!(v[0] as u32, gl::NONE);
        let tex2 = color_texture(c, 16);
        c.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            tex2,
            0,
        );
        c.clear_color(1.0, 1.0, 0.0, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.delete_framebuffers(1, &fb);
        c.get_integerv(gl::FRAMEBUFFER_BINDING, &mut v);
        assert_eq!(v[0], 0);
        assert!(!c.is_framebuffer(fb[0]));
        show_texture(c, tex2, 32);
    }) else {
        return;
    };
    assert_eq!(bad, 0, "{bad} pixels differ; first {first}");
}

/// The framebuffer commands execute when a display list is compiled, not stored (GL 3.0
/// §5.4): the list holds only the drawing, which goes where the binding is when it runs.
#[cfg(feature = "gl")]
#[test]
fn display_lists_execute_framebuffer_commands_immediately() {
    let Some((bad, first)) = crate::common::cpu_vs_gl(32, 1, |c| {
        let tex = color_texture(c, 32);
        let mut fb = [0];
        c.gen_framebuffers(1, &mut fb);
        let list = c.gen_lists(1);
        c.new_list(list, gl::COMPILE);
        c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
        c.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            tex,
            0,
        );
        c.clear_color(1.0, 0.0, 1.0, 1.0);
        c.clear(gl::COLOR_BUFFER_BIT);
        c.end_list();
        let mut v = [0];
        c.get_integerv(gl::FRAMEBUFFER_BINDING, &mut v);
        assert_eq!(v[0] as u32, fb[0], "bound while compiling");
        c.call_list(list);
        c.bind_framebuffer(gl::FRAMEBUFFER, 0);
        show_texture(c, tex, 32);
    }) else {
        return;
    };
    assert_eq!(bad, 0, "{bad} pixels differ; first {first}");
}

/// Attachment and renderbuffer queries, the limits, and GenerateMipmap from a rendered level.
#[test]
fn queries_and_generate_mipmap() {
    let mut c = ctx(16);
    let mut v = [0];
    c.get_integerv(gl::MAX_COLOR_ATTACHMENTS, &mut v);
    assert_eq!(v[0], 1);
    c.get_integerv(gl::MAX_RENDERBUFFER_SIZE, &mut v);
    assert!(v[0] >= 16384);
    let (mut fb, mut rb) = ([0], [0]);
    c.gen_framebuffers(1, &mut fb);
    c.gen_renderbuffers(1, &mut rb);
    assert!(!c.is_framebuffer(fb[0]), "not an object until bound");
    c.bind_renderbuffer(gl::RENDERBUFFER, rb[0]);
    assert!(c.is_renderbuffer(rb[0]));
    c.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT16, 8, 4);
    for (pname, want) in [
        (gl::RENDERBUFFER_WIDTH, 8),
        (gl::RENDERBUFFER_HEIGHT, 4),
        (
            gl::RENDERBUFFER_INTERNAL_FORMAT,
            gl::DEPTH_COMPONENT16 as i32,
        ),
        (gl::RENDERBUFFER_DEPTH_SIZE, 24),
        (gl::RENDERBUFFER_RED_SIZE, 0),
    ] {
        c.get_renderbuffer_parameteriv(gl::RENDERBUFFER, pname, &mut v);
        assert_eq!(v[0], want, "{pname:#x}");
    }
    let tex = color_texture(&mut c, 8);
    c.bind_framebuffer(gl::FRAMEBUFFER, fb[0]);
    c.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        tex,
        0,
    );
    for (pname, want) in [
        (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, gl::TEXTURE as i32),
        (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, tex as i32),
        (gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, 0),
    ] {
        c.get_framebuffer_attachment_parameteriv(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            pname,
            &mut v,
        );
        assert_eq!(v[0], want, "{pname:#x}");
    }
    c.clear_color(1.0, 0.0, 0.0, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT);
    c.bind_framebuffer(gl::FRAMEBUFFER, 0);
    c.generate_mipmap(gl::TEXTURE_2D);
    let mut texels = [0u8; 4];
    c.get_tex_image(gl::TEXTURE_2D, 3, gl::RGBA, gl::UNSIGNED_BYTE, &mut texels);
    assert_eq!(
        texels,
        [255, 0, 0, 255],
        "level 3 from the rendered level 0"
    );
    assert_eq!(c.get_error(), gl::NO_ERROR);
}
