//! Share groups (GL 2.1 appendix D): two contexts made with `Context::with_config_shared` see
//! the same display lists, texture objects and buffer objects; bindings and the rest of the
//! state stay each context's own. The picture a context draws with objects its partner made is
//! the one a single context draws making them itself, and the driver's (GL backend) for that
//! single stream.

use fixedgl::{checkerboard, gl, Call, Context, ContextConfig, ShareGroup};

fn pair(w: u32, h: u32) -> (Context, Context, ShareGroup) {
    let mut a = Context::new(w, h).expect("context A");
    let group = a.share_group();
    let b = Context::with_config_shared(w, h, ContextConfig::default(), &group).expect("B");
    (a, b, group)
}

#[test]
fn lists_textures_and_buffers_are_seen_by_both() {
    let (mut a, mut b, group) = pair(8, 8);
    assert!(a.is_shared() && b.is_shared());
    assert!(group.same(&b.share_group()));
    // A list made in A, before and after B exists.
    let l = a.gen_lists(2);
    assert!(b.is_list(l) && b.is_list(l + 1));
    a.new_list(l, gl::COMPILE);
    a.color3f(1.0, 0.0, 0.0);
    a.end_list();
    // (`list_calls` is no GL command: B looks at the group at its next one, IsList here.)
    assert!(b.is_list(l));
    assert_eq!(b.list_calls(l), Some(&[Call::Color3f(1.0, 0.0, 0.0)][..]));
    // B's GenLists never hands out A's names.
    let l2 = b.gen_lists(1);
    assert!(l2 > l + 1 && a.is_list(l2));
    // Textures: names, images and parameters.
    let mut t = [0u32; 2];
    a.gen_textures(2, &mut t);
    let mut u = [0u32; 1];
    b.gen_textures(1, &mut u);
    assert!(
        !t.contains(&u[0]),
        "B's name {} collides with A's {t:?}",
        u[0]
    );
    a.bind_texture(gl::TEXTURE_2D, t[0]);
    let img = checkerboard(4, 2, [255, 0, 0, 255], [0, 0, 255, 255]);
    a.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        4,
        4,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&img),
    );
    a.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    assert!(b.is_texture(t[0]));
    // Bindings are per context: B has nothing bound until it binds.
    let mut bound = [-1];
    b.get_integerv(gl::TEXTURE_BINDING_2D, &mut bound);
    assert_eq!(bound, [0]);
    b.bind_texture(gl::TEXTURE_2D, t[0]);
    let mut p = [0];
    b.get_tex_parameteriv(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, &mut p);
    assert_eq!(p, [gl::NEAREST as i32]);
    let mut w = [0];
    b.get_tex_level_parameteriv(gl::TEXTURE_2D, 0, gl::TEXTURE_WIDTH, &mut w);
    assert_eq!(w, [4]);
    // A change made in B is seen in A.
    b.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    a.get_tex_parameteriv(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, &mut p);
    assert_eq!(p, [gl::NEAREST as i32]);
    // Buffers: contents written in A are read in B.
    let mut buf = [0u32];
    a.gen_buffers(1, &mut buf);
    a.bind_buffer(gl::ARRAY_BUFFER, buf[0]);
    a.buffer_data(gl::ARRAY_BUFFER, 4, &[1u8, 2, 3, 4][..], gl::STATIC_DRAW);
    assert!(b.is_buffer(buf[0]));
    b.bind_buffer(gl::ARRAY_BUFFER, buf[0]);
    let mut out = [0u8; 4];
    b.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 4, &mut out);
    assert_eq!(out, [1, 2, 3, 4]);
    a.buffer_sub_data(gl::ARRAY_BUFFER, 1, 2, &[9u8, 9][..]);
    b.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 4, &mut out);
    assert_eq!(out, [1, 9, 9, 4]);
    // Deleting in one deletes for both.
    b.delete_lists(l, 1);
    assert!(!a.is_list(l) && a.is_list(l + 1));
    a.delete_textures(1, &t[..1]);
    assert!(!b.is_texture(t[0]));
    b.delete_buffers(1, &buf);
    assert!(!a.is_buffer(buf[0]));
    // LIST_BASE is per context.
    a.list_base(7);
    let mut base = [-1];
    b.get_integerv(gl::LIST_BASE, &mut base);
    assert_eq!(base, [0]);
    for c in [&mut a, &mut b] {
        assert_eq!(c.get_error(), gl::NO_ERROR);
    }
}

#[test]
fn a_buffer_mapped_in_one_context_is_seen_as_before_until_unmapped() {
    let (mut a, mut b, _g) = pair(4, 4);
    let mut buf = [0u32];
    a.gen_buffers(1, &mut buf);
    a.bind_buffer(gl::ARRAY_BUFFER, buf[0]);
    a.buffer_data(gl::ARRAY_BUFFER, 2, &[5u8, 6][..], gl::STATIC_DRAW);
    b.bind_buffer(gl::ARRAY_BUFFER, buf[0]);
    let m = a
        .map_buffer(gl::ARRAY_BUFFER, gl::WRITE_ONLY)
        .expect("mapped");
    m[0] = 50;
    let mut out = [0u8; 2];
    b.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 2, &mut out);
    assert_eq!(out, [5, 6]);
    // B deleting it does not free the store A writes through.
    let mut c = [0u32];
    b.gen_buffers(1, &mut c);
    assert!(a.unmap_buffer(gl::ARRAY_BUFFER));
    b.get_buffer_sub_data(gl::ARRAY_BUFFER, 0, 2, &mut out);
    assert_eq!(out, [50, 6]);
    let m = a
        .map_buffer(gl::ARRAY_BUFFER, gl::READ_WRITE)
        .expect("mapped again");
    let p = m.as_mut_ptr();
    b.delete_buffers(1, &buf);
    a.flush();
    // The mapping's memory is still A's: writing through the old address is sound.
    // SAFETY: the store is kept alive while mapped (context/share.rs, orphans).
    unsafe { *p = 1 };
    assert!(!a.is_buffer(buf[0]));
    assert_eq!(a.get_error(), gl::NO_ERROR);
}

#[test]
fn lists_calling_each_other_across_contexts_stop_at_the_nesting_limit() {
    let (mut a, mut b, _g) = pair(4, 4);
    let l = a.gen_lists(2);
    a.new_list(l, gl::COMPILE);
    a.call_list(l + 1);
    a.end_list();
    b.new_list(l + 1, gl::COMPILE);
    b.call_list(l);
    b.end_list();
    // Each runs the other's list until MAX_LIST_NESTING: no hang, no overflow.
    a.call_list(l);
    b.call_list(l + 1);
    assert_eq!(a.get_error(), gl::NO_ERROR);
    assert_eq!(b.get_error(), gl::NO_ERROR);
}

#[test]
fn names_made_on_two_threads_never_collide() {
    let (mut a, mut b, _g) = pair(4, 4);
    let (ta, tb) = std::thread::scope(|s| {
        let ha = s.spawn(|| {
            let mut all = Vec::new();
            for _ in 0..200 {
                let mut t = [0u32; 3];
                a.gen_textures(3, &mut t);
                a.bind_texture(gl::TEXTURE_2D, t[0]);
                all.extend(t);
                all.push(a.gen_lists(2));
            }
            all
        });
        let hb = s.spawn(|| {
            let mut all = Vec::new();
            for _ in 0..200 {
                let mut t = [0u32; 2];
                b.gen_textures(2, &mut t);
                all.extend(t);
                all.push(b.gen_lists(2));
            }
            all
        });
        (ha.join().expect("A"), hb.join().expect("B"))
    });
    // Texture names and list names are separate namespaces: compare each kind.
    let tex = |v: &[u32]| -> Vec<u32> {
        v.chunks(4)
            .flat_map(|c| c[..c.len() - 1].to_vec())
            .collect()
    };
    let tex_b = |v: &[u32]| -> Vec<u32> { v.chunks(3).flat_map(|c| c[..2].to_vec()).collect() };
    let (xa, xb) = (tex(&ta), tex_b(&tb));
    let mut all: Vec<u32> = xa.iter().chain(&xb).copied().collect();
    all.sort_unstable();
    let n = all.len();
    all.dedup();
    assert_eq!(all.len(), n, "texture names handed out twice");
    let mut lists: Vec<u32> = ta
        .chunks(4)
        .map(|c| c[3])
        .chain(tb.chunks(3).map(|c| c[2]))
        .collect();
    lists.sort_unstable();
    lists.dedup();
    assert_eq!(lists.len(), 400);
}

/// A's part: a texture and a display list drawing a textured, lit-free quad with it.
fn define(ctx: &mut Context) -> (u32, u32) {
    let mut t = [0u32];
    ctx.gen_textures(1, &mut t);
    ctx.bind_texture(gl::TEXTURE_2D, t[0]);
    let img = checkerboard(16, 4, [230, 40, 20, 255], [20, 90, 220, 255]);
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        16,
        16,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&img),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::LINEAR as i32);
    ctx.bind_texture(gl::TEXTURE_2D, 0);
    let l = ctx.gen_lists(1);
    ctx.new_list(l, gl::COMPILE);
    ctx.begin(gl::QUADS);
    for (s, tc, x, y) in [
        (0.0, 0.0, -0.8, -0.7),
        (1.0, 0.0, 0.7, -0.8),
        (1.0, 1.0, 0.8, 0.7),
        (0.0, 1.0, -0.7, 0.8),
    ] {
        ctx.tex_coord2f(s, tc);
        ctx.vertex2f(x, y);
    }
    ctx.end();
    ctx.end_list();
    (t[0], l)
}

/// B's part: binds the texture, draws the list (rotated), and a second copy through CallLists.
fn draw(ctx: &mut Context, t: u32, l: u32) {
    ctx.clear_color(0.1, 0.1, 0.1, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.enable(gl::TEXTURE_2D);
    ctx.bind_texture(gl::TEXTURE_2D, t);
    ctx.matrix_mode(gl::MODELVIEW);
    ctx.rotatef(20.0, 0.0, 0.0, 1.0);
    ctx.call_list(l);
    ctx.scalef(0.4, 0.4, 1.0);
    ctx.tex_envi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
    ctx.list_base(l - 1);
    ctx.call_lists(1, gl::UNSIGNED_BYTE, &[1]);
}

#[test]
fn a_context_draws_with_its_partners_texture_and_list_as_one_context_does() {
    let (w, h) = (96, 96);
    let (mut a, mut b, _g) = pair(w, h);
    a.start_recording();
    let (t, l) = define(&mut a);
    let defs = a.stop_recording();
    b.start_recording();
    draw(&mut b, t, l);
    let uses = b.stop_recording();
    assert_eq!(b.get_error(), gl::NO_ERROR);
    let shared = b.to_image();
    // One context making and using them.
    let mut one = Context::new(w, h).expect("context");
    let (t1, l1) = define(&mut one);
    assert_eq!((t1, l1), (t, l));
    draw(&mut one, t1, l1);
    assert_eq!(
        shared.as_raw(),
        one.to_image().as_raw(),
        "shared != single-context"
    );
    // B's picture is textured (not the clear colour nor plain white).
    let px = shared.get_pixel(w / 2, h / 2).0;
    assert!(
        px != [25, 25, 25, 255] && px != [255, 255, 255, 255],
        "{px:?}"
    );
    // And the driver, replaying A's calls then B's on one context, draws the same.
    #[cfg(feature = "gl")]
    {
        let Some(mut gl) = crate::common::test_backend(w, h) else {
            return;
        };
        gl.replay(&defs);
        gl.replay(&uses);
        assert_eq!(gl.get_error(), gl::NO_ERROR);
        let cmp = fixedgl::compare::compare(&shared, &gl.read_image(), 2);
        eprintln!(
            "shared-context picture vs llvmpipe: {:.3}% of pixels differ",
            cmp.differing_percent
        );
        assert!(cmp.differing_percent <= 0.05, "{cmp:?}");
    }
    #[cfg(not(feature = "gl"))]
    let _ = (defs, uses);
}

#[test]
fn changes_after_a_bind_are_seen_and_reset_sees_the_group_again() {
    let (mut a, mut b, _g) = pair(8, 8);
    let (t, l) = define(&mut a);
    b.bind_texture(gl::TEXTURE_2D, t);
    // A redefines the image smaller: B sees the new size.
    a.bind_texture(gl::TEXTURE_2D, t);
    let img = [255u8; 2 * 2 * 4];
    a.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&img),
    );
    let mut wd = [0];
    b.get_tex_level_parameteriv(gl::TEXTURE_2D, 0, gl::TEXTURE_WIDTH, &mut wd);
    assert_eq!(wd, [2]);
    // A reset context is a new one of the group: it still sees the objects.
    b.reset();
    assert!(b.is_texture(t) && b.is_list(l));
    // An unshared context sees none of them.
    let mut c = Context::new(8, 8).expect("context");
    assert!(!c.is_texture(t) && !c.is_list(l));
}
