//! The framebuffer's buffers against the driver: front and back colour buffers (DrawBuffer,
//! ReadBuffer, a swap, FRONT_AND_BACK with blending against each buffer's own contents,
//! ReadPixels and CopyTexImage from the read buffer), their errors, PushAttrib and display-list
//! behaviour and queries, framebuffers without depth or stencil, a resize, and the
//! accumulation buffer compared with Mesa's own glAccum (OSMesa, whose framebuffer has one)
//! and with the EGL backend's emulation of it. Skipped, with a note on stderr, where no GL
//! backend (or no OSMesa) can start.
#![cfg(feature = "gl")]

use fixedgl::glbackend::GlBackend;
use fixedgl::{gl, Call, Context, ContextConfig};

const DOUBLE: ContextConfig = ContextConfig {
    double_buffered: true,
    depth: true,
    stencil: true,
    accum: false,
    alpha: true,
};
const ACCUM: ContextConfig = ContextConfig {
    double_buffered: false,
    depth: true,
    stencil: true,
    accum: true,
    alpha: true,
};

fn ctx(w: u32, h: u32, config: ContextConfig) -> Context {
    match Context::with_config(w, h, config) {
        Ok(c) => c,
        Err(e) => panic!("CPU context: {e}"),
    }
}

/// Runs `calls` on both, requiring the same error after each call made outside Begin/End.
fn both(cpu: &mut Context, drv: &mut GlBackend, calls: &[Call]) {
    for call in calls {
        cpu.execute(call);
        drv.execute(call);
        if !cpu.inside_begin_end() {
            assert_eq!(cpu.get_error(), drv.get_error(), "after {call:?}");
        }
    }
}

/// One triangle covering most of a `w` x `h` window (identity matrices), colour `c`, at z.
fn triangle(c: [f32; 4], z: f32) -> Vec<Call> {
    vec![
        Call::Color4f(c[0], c[1], c[2], c[3]),
        Call::Begin(gl::TRIANGLES),
        Call::Vertex3f(-0.9, -0.9, z),
        Call::Vertex3f(0.9, -0.7, z),
        Call::Vertex3f(-0.2, 0.9, z),
        Call::End,
    ]
}

fn query(cpu: &mut Context, drv: &mut GlBackend, pname: u32) -> (i32, i32) {
    let (mut a, mut b) = ([-7; 4], [-7; 4]);
    cpu.get_integerv(pname, &mut a);
    drv.get_integerv(pname, &mut b);
    (a[0], b[0])
}

/// Back buffer (the image), front buffer and the read buffer's pixels agree.
fn same_buffers(cpu: &mut Context, drv: &mut GlBackend, what: &str) {
    let (w, h) = cpu.size();
    let (a, b) = (cpu.to_image().into_raw(), drv.read_image().into_raw());
    if a != b {
        for (i, (p, q)) in a.chunks(4).zip(b.chunks(4)).enumerate() {
            if p != q {
                eprintln!(
                    "pixel ({}, {} from the top): {p:?} vs {q:?}",
                    i as u32 % w,
                    i as u32 / w
                );
            }
        }
    }
    assert_eq!(a, b, "{what}: the default (back) buffer");
    assert_eq!(
        cpu.front_rgba(),
        drv.front_rgba(),
        "{what}: the front buffer"
    );
    let mut px = vec![0u8; (w * h * 4) as usize];
    cpu.read_pixels(
        0,
        0,
        w as i32,
        h as i32,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &mut px,
    );
    assert_eq!(cpu.get_error(), gl::NO_ERROR);
    assert_eq!(
        px,
        drv.read_rgba(0, 0, w as i32, h as i32),
        "{what}: ReadPixels from READ_BUFFER"
    );
}

#[test]
fn front_and_back_buffers_draw_read_and_swap_as_the_driver() {
    let (w, h) = (16, 12);
    let mut cpu = ctx(w, h, DOUBLE);
    let Some(mut drv) = crate::common::test_backend_with(w, h, DOUBLE) else {
        return;
    };
    assert_eq!(
        query(&mut cpu, &mut drv, gl::DRAW_BUFFER),
        (gl::BACK as i32, gl::BACK as i32)
    );
    assert_eq!(
        query(&mut cpu, &mut drv, gl::READ_BUFFER),
        (gl::BACK as i32, gl::BACK as i32)
    );
    assert_eq!(query(&mut cpu, &mut drv, gl::DOUBLEBUFFER), (1, 1));
    let mut calls = vec![
        // The back buffer dark red, the front one dark green.
        Call::ClearColor(0.5, 0.0, 0.0, 1.0),
        Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT),
        Call::DrawBuffer(gl::FRONT),
        Call::ClearColor(0.0, 0.5, 0.0, 1.0),
        Call::Clear(gl::COLOR_BUFFER_BIT),
        // Both, each blended over its own contents.
        Call::DrawBuffer(gl::FRONT_AND_BACK),
        Call::Enable(gl::BLEND),
        Call::BlendFunc(gl::ONE, gl::ONE),
    ];
    calls.extend(triangle([0.0, 0.25, 0.5, 1.0], 0.0));
    calls.extend([
        Call::Disable(gl::BLEND),
        // A yellow square in the back buffer only.
        Call::DrawBuffer(gl::BACK_LEFT),
        Call::Enable(gl::SCISSOR_TEST),
        Call::Scissor(2, 2, 4, 4),
        Call::ClearColor(1.0, 1.0, 0.0, 1.0),
        Call::Clear(gl::COLOR_BUFFER_BIT),
        Call::Disable(gl::SCISSOR_TEST),
        // LEFT is both on a double-buffered framebuffer.
        Call::DrawBuffer(gl::LEFT),
        Call::Color4f(1.0, 1.0, 1.0, 1.0),
        Call::Begin(gl::POINTS),
        Call::Vertex2f(0.5, 0.5),
        Call::End,
        Call::ReadBuffer(gl::FRONT),
    ]);
    both(&mut cpu, &mut drv, &calls);
    let back = cpu.to_image().into_raw();
    let front = cpu.front_rgba();
    assert_ne!(back, front, "the two buffers hold different pictures");
    same_buffers(&mut cpu, &mut drv, "drawn");
    assert_eq!(
        query(&mut cpu, &mut drv, gl::DRAW_BUFFER),
        (gl::LEFT as i32, gl::LEFT as i32)
    );
    assert_eq!(
        query(&mut cpu, &mut drv, gl::READ_BUFFER),
        (gl::FRONT as i32, gl::FRONT as i32)
    );

    // CopyTexImage reads the read buffer (the front one) too: its texels drawn into the back.
    let tex = [
        Call::DrawBuffer(gl::BACK),
        // 8x4 texels from (4, 2), drawn 1:1 over pixels (8..16, 6..10): every sample at a
        // texel centre, no ties between neighbours.
        Call::CopyTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA, 4, 2, 8, 4, 0),
        Call::TexParameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32),
        Call::TexParameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32),
        Call::Enable(gl::TEXTURE_2D),
        Call::Begin(gl::QUADS),
        Call::TexCoord2f(0.0, 0.0),
        Call::Vertex2f(0.0, 0.0),
        Call::TexCoord2f(1.0, 0.0),
        Call::Vertex2f(1.0, 0.0),
        Call::TexCoord2f(1.0, 1.0),
        Call::Vertex2f(1.0, 2.0 / 3.0),
        Call::TexCoord2f(0.0, 1.0),
        Call::Vertex2f(0.0, 2.0 / 3.0),
        Call::End,
        Call::Disable(gl::TEXTURE_2D),
    ];
    both(&mut cpu, &mut drv, &tex);
    assert_ne!(cpu.to_image().into_raw(), back, "the copy was drawn");
    same_buffers(&mut cpu, &mut drv, "after CopyTexImage from FRONT");

    // A swap: the front buffer shows the back one, which keeps its contents.
    let back = cpu.to_image().into_raw();
    both(&mut cpu, &mut drv, &[Call::SwapBuffers]);
    assert_eq!(cpu.front_rgba(), back);
    assert_eq!(cpu.to_image().into_raw(), back);
    same_buffers(&mut cpu, &mut drv, "after a swap");

    // DrawBuffer(NONE): no colour anywhere, but the depth test and writes go on.
    let mut none = vec![
        Call::DrawBuffer(gl::NONE),
        Call::Enable(gl::DEPTH_TEST),
        Call::ClearDepth(1.0),
    ];
    none.extend(triangle([0.0, 0.0, 1.0, 1.0], 0.0));
    none.push(Call::DrawBuffer(gl::BACK));
    // Behind the invisible triangle: hidden where it covers.
    none.extend(triangle([1.0, 0.0, 1.0, 1.0], 0.5));
    none.push(Call::Disable(gl::DEPTH_TEST));
    let before = cpu.to_image().into_raw();
    both(&mut cpu, &mut drv, &none);
    assert_eq!(
        cpu.to_image().into_raw(),
        before,
        "hidden by the NONE triangle's depth"
    );
    same_buffers(&mut cpu, &mut drv, "after DrawBuffer(NONE)");
}

#[test]
fn draw_and_read_buffer_errors_as_gl_2_1() {
    // GL 2.1 §4.2.1 and §4.3.2 (table 4.4), where llvmpipe (GLX, measured) differs only in
    // taking BACK and BACK_LEFT on a single-buffered window and NONE and FRONT_AND_BACK in
    // ReadBuffer: fixedgl raises the spec's errors, and the GL backend, whose FBO the driver
    // would judge by other rules, validates with the same table.
    const E: u32 = gl::INVALID_ENUM;
    const O: u32 = gl::INVALID_OPERATION;
    const N: u32 = gl::NO_ERROR;
    // (buffer, DrawBuffer single, double, ReadBuffer single, double)
    let table = [
        (gl::NONE, N, N, E, E),
        (gl::FRONT, N, N, N, N),
        (gl::BACK, O, N, O, N),
        (gl::LEFT, N, N, N, N),
        (gl::RIGHT, O, O, O, O),
        (gl::FRONT_LEFT, N, N, N, N),
        (gl::FRONT_RIGHT, O, O, O, O),
        (gl::BACK_LEFT, O, N, O, N),
        (gl::BACK_RIGHT, O, O, O, O),
        (gl::FRONT_AND_BACK, N, N, E, E),
        (gl::AUX0, O, O, O, O),
        (gl::AUX3, O, O, O, O),
        (gl::AUX3 + 1, E, E, E, E),
        // COLOR_ATTACHMENT0 (GL_EXT_framebuffer_object): a buffer the window lacks, as Mesa.
        (gl::COLOR_ATTACHMENT0, O, O, O, O),
        (gl::TRIANGLES, E, E, E, E),
    ];
    for (config, double) in [(ContextConfig::default(), false), (DOUBLE, true)] {
        let mut cpu = ctx(4, 4, config);
        let Some(mut drv) = crate::common::test_backend_with(4, 4, config) else {
            return;
        };
        for &(buf, ds, dd, rs, rd) in &table {
            let (want_draw, want_read) = if double { (dd, rd) } else { (ds, rs) };
            for (call, want, pname) in [
                (Call::DrawBuffer(buf), want_draw, gl::DRAW_BUFFER),
                (Call::ReadBuffer(buf), want_read, gl::READ_BUFFER),
            ] {
                let before = query(&mut cpu, &mut drv, pname);
                cpu.execute(&call);
                drv.execute(&call);
                let what = format!("{call:?}, double-buffered {double}");
                assert_eq!(cpu.get_error(), want, "{what}");
                assert_eq!(drv.get_error(), want, "{what} on the driver");
                let after = query(&mut cpu, &mut drv, pname);
                assert_eq!(after.0, after.1, "{what}: the value");
                if want == N {
                    assert_eq!(after.0, buf as i32, "{what}: the value as given");
                } else {
                    assert_eq!(after, before, "{what}: an error changes nothing");
                }
            }
        }
        // Inside Begin/End: INVALID_OPERATION and no change.
        let calls = [
            Call::Begin(gl::POINTS),
            Call::DrawBuffer(gl::FRONT),
            Call::End,
        ];
        for c in &calls {
            cpu.execute(c);
            drv.execute(c);
        }
        assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
        assert_eq!(drv.get_error(), gl::INVALID_OPERATION);
    }
}

#[test]
fn push_attrib_and_display_lists_keep_draw_and_read_buffer() {
    let (w, h) = (8, 8);
    let mut cpu = ctx(w, h, DOUBLE);
    let Some(mut drv) = crate::common::test_backend_with(w, h, DOUBLE) else {
        return;
    };
    let calls = [
        Call::NewList(1, gl::COMPILE),
        Call::DrawBuffer(gl::FRONT),
        Call::ReadBuffer(gl::FRONT),
        // Compiled, so its error comes when the list runs.
        Call::DrawBuffer(gl::RIGHT),
        Call::EndList,
        Call::PushAttrib(gl::COLOR_BUFFER_BIT | gl::PIXEL_MODE_BIT),
        Call::CallList(1),
    ];
    for c in &calls {
        cpu.execute(c);
        drv.execute(c);
    }
    assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
    assert_eq!(drv.get_error(), gl::INVALID_OPERATION);
    assert_eq!(
        query(&mut cpu, &mut drv, gl::DRAW_BUFFER),
        (gl::FRONT as i32, gl::FRONT as i32)
    );
    assert_eq!(
        query(&mut cpu, &mut drv, gl::READ_BUFFER),
        (gl::FRONT as i32, gl::FRONT as i32)
    );
    let more = [
        Call::ClearColor(1.0, 0.0, 0.0, 1.0),
        Call::Clear(gl::COLOR_BUFFER_BIT),
        // Only DRAW_BUFFER is in COLOR_BUFFER_BIT, READ_BUFFER in PIXEL_MODE_BIT.
        Call::PushAttrib(gl::PIXEL_MODE_BIT),
        Call::ReadBuffer(gl::BACK),
        Call::PopAttrib,
        Call::PopAttrib,
        Call::ClearColor(0.0, 0.0, 1.0, 1.0),
        Call::Enable(gl::SCISSOR_TEST),
        Call::Scissor(0, 0, 4, 8),
        Call::Clear(gl::COLOR_BUFFER_BIT),
    ];
    both(&mut cpu, &mut drv, &more);
    assert_eq!(
        query(&mut cpu, &mut drv, gl::DRAW_BUFFER),
        (gl::BACK as i32, gl::BACK as i32)
    );
    assert_eq!(
        query(&mut cpu, &mut drv, gl::READ_BUFFER),
        (gl::BACK as i32, gl::BACK as i32)
    );
    same_buffers(&mut cpu, &mut drv, "after PopAttrib");
    assert_ne!(cpu.front_rgba(), cpu.to_image().into_raw());
}

#[test]
fn framebuffers_without_depth_or_stencil_behave_as_the_driver() {
    let (w, h) = (12, 12);
    for (depth, stencil) in [(false, true), (true, false), (false, false)] {
        let config = ContextConfig {
            depth,
            stencil,
            ..ContextConfig::default()
        };
        let mut cpu = ctx(w, h, config);
        let Some(mut drv) = crate::common::test_backend_with(w, h, config) else {
            return;
        };
        assert_eq!(
            query(&mut cpu, &mut drv, gl::DEPTH_BITS),
            (24 * i32::from(depth), 24 * i32::from(depth))
        );
        assert_eq!(
            query(&mut cpu, &mut drv, gl::STENCIL_BITS),
            (8 * i32::from(stencil), 8 * i32::from(stencil))
        );
        let mut calls = vec![
            Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT),
            Call::Enable(gl::DEPTH_TEST),
            Call::Enable(gl::STENCIL_TEST),
            Call::StencilFunc(gl::EQUAL, 1, 0xFF),
            Call::StencilOp(gl::INCR, gl::INCR, gl::INCR),
        ];
        // Near, then far: without a depth buffer the far one covers it; without a stencil
        // buffer both pass the EQUAL 1 test that a cleared stencil buffer would fail.
        calls.extend(triangle([1.0, 0.0, 0.0, 1.0], -0.5));
        calls.extend(triangle([0.0, 1.0, 0.0, 1.0], 0.5));
        both(&mut cpu, &mut drv, &calls);
        assert_eq!(
            cpu.to_image().into_raw(),
            drv.read_image().into_raw(),
            "depth {depth}, stencil {stencil}"
        );
        let mut out = [0u8; 4];
        cpu.read_pixels(0, 0, 1, 1, gl::DEPTH_COMPONENT, gl::FLOAT, &mut out);
        let want = if depth {
            gl::NO_ERROR
        } else {
            gl::INVALID_OPERATION
        };
        assert_eq!(cpu.get_error(), want, "ReadPixels(DEPTH_COMPONENT)");
        cpu.read_pixels(0, 0, 1, 1, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, &mut out);
        let want = if stencil {
            gl::NO_ERROR
        } else {
            gl::INVALID_OPERATION
        };
        assert_eq!(cpu.get_error(), want, "ReadPixels(STENCIL_INDEX)");
    }
}

#[test]
fn resize_keeps_what_fits_and_not_the_viewport() {
    for config in [ContextConfig::default(), DOUBLE] {
        let mut cpu = ctx(10, 8, config);
        let Some(mut drv) = crate::common::test_backend_with(10, 8, config) else {
            return;
        };
        let mut calls = vec![
            Call::ClearColor(0.2, 0.4, 0.6, 1.0),
            Call::Clear(gl::COLOR_BUFFER_BIT),
        ];
        calls.extend(triangle([1.0, 0.5, 0.0, 1.0], 0.0));
        both(&mut cpu, &mut drv, &calls);
        for (w, h) in [(14, 6), (7, 12), (16, 16)] {
            assert!(cpu.resize(w, h).is_ok());
            assert!(drv.resize(w, h).is_ok());
            assert_eq!(cpu.size(), (w, h));
            assert_eq!(drv.size(), (w, h));
            same_buffers(&mut cpu, &mut drv, &format!("resized to {w}x{h}"));
            let (mut a, mut b) = ([0; 4], [0; 4]);
            cpu.get_integerv(gl::VIEWPORT, &mut a);
            drv.get_integerv(gl::VIEWPORT, &mut b);
            assert_eq!(
                (a, b),
                ([0, 0, 10, 8], [0, 0, 10, 8]),
                "the viewport is kept"
            );
        }
        // Drawing after the resize, with the program's new viewport.
        let mut calls = vec![Call::Viewport(0, 0, 16, 16), Call::SwapBuffers];
        calls.extend(triangle([0.0, 1.0, 1.0, 1.0], 0.0));
        both(&mut cpu, &mut drv, &calls);
        same_buffers(&mut cpu, &mut drv, "drawn after the resize");
        assert!(cpu.resize(0, 4).is_err());
        assert!(drv.resize(0, 4).is_err());
    }
}

/// A quad of flat colour `c` over window pixels [x0, x1) x [y0, y1) under a pixel-unit Ortho:
/// its edges a quarter pixel off the pixel centres, so no rasterisation tie can decide a pixel
/// (the accumulation is what is compared, not edge rules, which differ between llvmpipe's
/// window framebuffers and FBOs).
fn quad(c: [f32; 4], x0: f32, y0: f32, x1: f32, y1: f32) -> Vec<Call> {
    let (x0, y0, x1, y1) = (x0 + 0.25, y0 + 0.25, x1 + 0.25, y1 + 0.25);
    vec![
        Call::Color4f(c[0], c[1], c[2], c[3]),
        Call::Begin(gl::QUADS),
        Call::Vertex2f(x0, y0),
        Call::Vertex2f(x1, y0),
        Call::Vertex2f(x1, y1),
        Call::Vertex2f(x0, y1),
        Call::End,
    ]
}

/// A Red Book motion blur (four frames of a moving pair of quads, LOAD then ACCUM 0.25 each,
/// MULT, RETURN) and then every operation of §4.2.4 with odd values: ClearAccum through the
/// scissor box, ADD, ACCUM, RETURN through a colour mask and the scissor box, MULT by a
/// negative value, LOAD and ACCUM beyond 16 bits (Mesa wraps), a bad op.
fn accum_frames(w: u32, h: u32) -> Vec<Call> {
    let mut calls = vec![
        Call::MatrixMode(gl::PROJECTION),
        Call::Ortho(Box::new([0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0])),
        Call::MatrixMode(gl::MODELVIEW),
        // FLAT: each quad's colour exactly as given (smooth interpolation of a constant colour
        // can round differently at a unorm8 tie such as 0.9).
        Call::ShadeModel(gl::FLAT),
        Call::ClearAccum(0.0, 0.0, 0.0, 0.0),
        Call::Clear(gl::ACCUM_BUFFER_BIT),
    ];
    for i in 0..4 {
        let f = i as f32;
        calls.push(Call::ClearColor(0.1, 0.1, 0.2, 1.0));
        calls.push(Call::Clear(gl::COLOR_BUFFER_BIT));
        calls.extend(quad(
            [1.0, 0.6 - 0.1 * f, 0.2, 0.9],
            2.0 + 3.0 * f,
            3.0,
            12.0 + 3.0 * f,
            11.0,
        ));
        calls.extend(quad(
            [0.3, 0.9, 0.7 - 0.2 * f, 0.55],
            5.0,
            6.0 + 2.0 * f,
            9.0,
            17.0,
        ));
        let op = if i == 0 { gl::LOAD } else { gl::ACCUM };
        calls.push(Call::Accum(op, 0.25));
    }
    calls.extend([
        Call::Accum(gl::MULT, 0.9),
        Call::Accum(gl::RETURN, 1.0 / 0.9),
        Call::Enable(gl::SCISSOR_TEST),
        Call::Scissor(3, 3, 9, 7),
        Call::ClearAccum(0.3, -0.2, 1.5, 0.77),
        Call::Clear(gl::ACCUM_BUFFER_BIT),
        Call::Accum(gl::ADD, 0.123),
        Call::Accum(gl::ACCUM, 0.7),
        Call::Disable(gl::SCISSOR_TEST),
        Call::ColorMask(true, false, true, true),
        Call::Accum(gl::RETURN, 1.3),
        Call::ColorMask(true, true, true, true),
        Call::Accum(gl::ADD, 0.9),
        Call::Accum(gl::MULT, -1.7),
        Call::Accum(gl::LOAD, 2.5),
        Call::Accum(gl::ACCUM, 1.0),
        Call::Enable(gl::SCISSOR_TEST),
        Call::Scissor(0, 0, 10, 24),
        Call::Accum(gl::RETURN, 0.5),
        Call::Disable(gl::SCISSOR_TEST),
        Call::Accum(0x1234, 1.0),
        Call::Accum(gl::RETURN, -1.0),
    ]);
    calls
}

/// The two drivers the accumulation tests compare with: Mesa's own glAccum (OSMesa) and the EGL
/// backend's emulation, each `None` where it cannot start.
fn accum_drivers(w: u32, h: u32) -> [(&'static str, Option<GlBackend>); 2] {
    [
        (
            "OSMesa (Mesa's glAccum)",
            crate::common::osmesa_backend(w, h, ACCUM),
        ),
        (
            "EGL (emulated)",
            crate::common::test_backend_with(w, h, ACCUM),
        ),
    ]
}

/// The image after each RETURN of `calls` on a driver (errors read and dropped).
fn driver_returns(drv: &mut GlBackend, calls: &[Call]) -> Vec<Vec<u8>> {
    let mut images = Vec::new();
    for call in calls {
        drv.execute(call);
        let _ = drv.get_error();
        if matches!(call, Call::Accum(gl::RETURN, _)) {
            images.push(drv.read_image().into_raw());
        }
    }
    images
}

#[test]
fn accumulation_matches_mesas_own_accum_and_the_emulation() {
    let (w, h) = (24, 20);
    let calls = accum_frames(w, h);
    let mut cpu = ctx(w, h, ACCUM);
    let mut images = Vec::new();
    for (i, call) in calls.iter().enumerate() {
        cpu.execute(call);
        if cpu.inside_begin_end() {
            continue;
        }
        let e = cpu.get_error();
        let want = if matches!(call, Call::Accum(0x1234, _)) {
            gl::INVALID_ENUM
        } else {
            gl::NO_ERROR
        };
        assert_eq!(e, want, "call {i}: {call:?}");
        if matches!(call, Call::Accum(gl::RETURN, _)) {
            images.push(cpu.to_image().into_raw());
        }
    }
    assert!(
        images.windows(2).all(|p| p[0] != p[1]),
        "every RETURN shows something new"
    );
    let backends = accum_drivers(w, h);
    for (name, drv) in backends {
        let Some(mut drv) = drv else { continue };
        let got = driver_returns(&mut drv, &calls);
        for (k, (a, b)) in images.iter().zip(&got).enumerate() {
            if a != b {
                for (i, (p, q)) in a.chunks(4).zip(b.chunks(4)).enumerate() {
                    if p != q {
                        eprintln!("{name} RETURN {k}: pixel {i}: {p:?} vs {q:?}");
                    }
                }
                let n = a.iter().zip(b).filter(|(x, y)| x != y).count();
                let first = a.iter().zip(b).position(|(x, y)| x != y);
                panic!("{name}: RETURN {k}: {n} bytes differ, first at byte {first:?}");
            }
        }
        assert_eq!(got.len(), images.len(), "{name}");
        let (mut a, mut b) = ([0.0f32; 4], [0.0f32; 4]);
        cpu.get_floatv(gl::ACCUM_CLEAR_VALUE, &mut a);
        drv.get_floatv(gl::ACCUM_CLEAR_VALUE, &mut b);
        assert_eq!(a, b, "{name}: ACCUM_CLEAR_VALUE");
        let (mut a, mut b) = ([0i32; 4], [0i32; 4]);
        cpu.get_integerv(gl::ACCUM_CLEAR_VALUE, &mut a);
        drv.get_integerv(gl::ACCUM_CLEAR_VALUE, &mut b);
        // GL 2.1 table 4.9's ((2^32 - 1)f - 1) / 2 (fixedgl, every normalized query) and
        // Mesa's (GLint)(2147483647 f) agree on these non-negative components; on the negative
        // one (-0.2) Mesa's truncation toward zero gives one more.
        for k in [0, 2, 3] {
            assert_eq!(a[k], b[k], "{name}: ACCUM_CLEAR_VALUE[{k}] as an integer");
        }
        assert_eq!((a[1], b[1]), (-429_496_736, -429_496_735), "{name}");
        for p in [gl::ACCUM_RED_BITS, gl::ACCUM_ALPHA_BITS] {
            let (mut a, mut b) = ([0i32; 1], [0i32; 1]);
            cpu.get_integerv(p, &mut a);
            drv.get_integerv(p, &mut b);
            assert_eq!((a[0], b[0]), (16, 16), "{name}: {p:#x}");
        }
    }
}

/// The accumulation buffer of a window of several tiles, with scissor boxes whose edges cross
/// the tiles' (64-pixel) boundaries, against Mesa's own glAccum and the EGL emulation, every
/// RETURN byte for byte: fixedgl runs each operation tile by tile over rows of pixels.
#[test]
fn accumulation_across_tiles_and_scissor_boxes_matches_mesa() {
    let (w, h) = (150, 100);
    let mut calls = accum_frames(w, h);
    calls.extend(quad([0.8, 0.2, 0.5, 0.7], 50.0, 40.0, 120.0, 90.0));
    calls.extend([
        Call::Accum(gl::ACCUM, 0.5),
        Call::Enable(gl::SCISSOR_TEST),
        Call::Scissor(37, 5, 90, 80),
        Call::Accum(gl::MULT, 0.7),
        Call::Accum(gl::ADD, 0.1),
        Call::Scissor(60, 61, 80, 30),
        Call::Accum(gl::LOAD, 0.9),
        Call::ColorMask(true, false, true, false),
        Call::Scissor(63, 3, 3, 90),
        Call::Accum(gl::RETURN, 1.5),
        Call::ColorMask(true, true, true, true),
        Call::Scissor(1, 63, 148, 2),
        Call::Accum(gl::RETURN, 0.6),
        Call::Disable(gl::SCISSOR_TEST),
        Call::Accum(gl::RETURN, 1.0),
    ]);
    let mut cpu = ctx(w, h, ACCUM);
    let mut want = Vec::new();
    for call in &calls {
        cpu.execute(call);
        if matches!(call, Call::Accum(gl::RETURN, _)) {
            want.push(cpu.to_image().into_raw());
        }
    }
    assert!(
        want.windows(2).all(|p| p[0] != p[1]),
        "every RETURN shows something new"
    );
    let backends = accum_drivers(w, h);
    for (name, drv) in backends {
        let Some(mut drv) = drv else { continue };
        let got = driver_returns(&mut drv, &calls);
        assert_eq!(got.len(), want.len(), "{name}");
        for (k, (a, b)) in want.iter().zip(&got).enumerate() {
            let n = a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| p != q).count();
            assert_eq!(n, 0, "{name}: RETURN {k}: {n} pixels differ");
        }
    }
}

#[test]
fn accum_errors_and_attribs_as_the_driver() {
    // Without an accumulation buffer: INVALID_OPERATION, after INVALID_ENUM for a bad op.
    let none = ContextConfig::default();
    let mut cpu = ctx(4, 4, none);
    let backends = [
        crate::common::osmesa_backend(4, 4, none),
        crate::common::test_backend_with(4, 4, none),
    ];
    for mut drv in backends.into_iter().flatten() {
        for (op, want) in [
            (gl::ACCUM, gl::INVALID_OPERATION),
            (gl::RETURN, gl::INVALID_OPERATION),
            (gl::ADD + 1, gl::INVALID_ENUM),
        ] {
            cpu.accum(op, 1.0);
            drv.execute(&Call::Accum(op, 1.0));
            assert_eq!(
                (cpu.get_error(), drv.get_error()),
                (want, want),
                "Accum({op:#x})"
            );
        }
        // ClearAccum is state whether or not there is a buffer, clamped to [-1, 1], in
        // ACCUM_BUFFER_BIT.
        let calls = [
            Call::ClearAccum(2.0, -3.0, 0.5, 0.25),
            Call::PushAttrib(gl::ACCUM_BUFFER_BIT),
            Call::ClearAccum(0.0, 0.0, 0.0, 0.0),
            Call::PopAttrib,
            Call::Begin(gl::POINTS),
            Call::Accum(gl::LOAD, 1.0),
            Call::End,
        ];
        for c in &calls {
            cpu.execute(c);
            drv.execute(c);
        }
        assert_eq!(cpu.get_error(), gl::INVALID_OPERATION);
        assert_eq!(drv.get_error(), gl::INVALID_OPERATION);
        let (mut a, mut b) = ([0.0f32; 4], [0.0f32; 4]);
        cpu.get_floatv(gl::ACCUM_CLEAR_VALUE, &mut a);
        drv.get_floatv(gl::ACCUM_CLEAR_VALUE, &mut b);
        assert_eq!(a, [1.0, -1.0, 0.5, 0.25]);
        assert_eq!(a, b);
        cpu.clear_accum(0.0, 0.0, 0.0, 0.0);
    }
}

/// DrawPixels into both colour buffers through a colour mask, at zooms 1, 2 and −1, from bytes
/// and from floats, across tile boundaries: the rows where only the colour write applies
/// (`put_row` in src/cpu/pixels.rs) against the driver, both buffers.
#[test]
fn draw_pixels_into_both_buffers_through_a_colour_mask_as_the_driver() {
    let (w, h) = (90, 80);
    let mut cpu = ctx(w, h, DOUBLE);
    let Some(mut drv) = crate::common::test_backend_with(w, h, DOUBLE) else {
        return;
    };
    let (iw, ih) = (24i32, 16i32);
    let bytes: Vec<u8> = (0..iw * ih * 4).map(|i| (i * 37 % 251) as u8).collect();
    let floats: Vec<u8> = (0..iw * ih * 4)
        .flat_map(|i| ((i * 53 % 101) as f32 / 100.0).to_ne_bytes())
        .collect();
    let image = |ty: u32| {
        let data = if ty == gl::FLOAT { &floats } else { &bytes };
        Call::DrawPixels(iw, ih, gl::RGBA, ty, Box::new(data.clone()))
    };
    let calls = vec![
        Call::ClearColor(0.1, 0.2, 0.3, 1.0),
        Call::DrawBuffer(gl::FRONT_AND_BACK),
        Call::Clear(gl::COLOR_BUFFER_BIT),
        Call::PixelStorei(gl::UNPACK_ALIGNMENT, 1),
        Call::ColorMask(true, false, true, true),
        Call::WindowPos2i(3, 5),
        image(gl::UNSIGNED_BYTE),
        Call::WindowPos2i(55, 58),
        image(gl::FLOAT),
        Call::PixelZoom(2.0, 2.0),
        Call::WindowPos2i(40, 30),
        image(gl::FLOAT),
        Call::PixelZoom(-1.0, 1.0),
        Call::WindowPos2i(80, 50),
        image(gl::UNSIGNED_BYTE),
        Call::ColorMask(true, true, true, true),
        Call::DrawBuffer(gl::BACK),
        Call::PixelZoom(1.0, 1.0),
        Call::WindowPos2i(50, 2),
        image(gl::UNSIGNED_BYTE),
        Call::ReadBuffer(gl::FRONT),
    ];
    both(&mut cpu, &mut drv, &calls);
    same_buffers(&mut cpu, &mut drv, "DrawPixels");
}
