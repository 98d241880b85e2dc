//! The setup stage's two builds (`Route::Baseline`, and `Route::Avx2` where the CPU has AVX2)
//! against each other: the same primitives, floats and bins, bit for bit (every NaN counted as
//! one value, as `lighting::nan_bits` explains).

use glam::{Mat4, Vec3, Vec4};

use crate::cpu::batch::Batch;
use crate::cpu::framebuffer::scissor_rect;
use crate::cpu::setup::{SetupCtx, Worker};
use crate::cpu::vertex::{process_by, Layout, Route};
use crate::gl;
use crate::state::{Current, State};

use super::lighting::Rng;

/// Random strips, fans, triangles, quads and polygons (some crossing the view volume's planes,
/// so that clipping runs, many a pixel or two wide, so that the 2x2 coverage runs) under random
/// culling, facing, FLAT, polygon offset, PolygonMode LINE and POINT (the edge flags), scissor,
/// lighting, texturing on one to four units, the secondary colour and fog, set up by both
/// routes and from the triangles `assemble` makes: every primitive's fields, every float of the
/// pool, every touched bin and the area are the same.
#[test]
fn both_routes_set_up_the_same_primitives() {
    let wide = Route::best();
    if wide != Route::Avx2 {
        eprintln!("no AVX2 on this CPU: the baseline route is compared with itself");
    }
    let mut rng = Rng(0x7f4a_7c15);
    let modes = [
        gl::TRIANGLE_STRIP,
        gl::TRIANGLES,
        gl::QUADS,
        gl::TRIANGLE_FAN,
        gl::POLYGON,
        gl::QUAD_STRIP,
    ];
    let mut prims = 0;
    for case in 0..200 {
        let mut st = culled_state(case);
        st.shade_model = if case % 5 == 2 { gl::FLAT } else { gl::SMOOTH };
        st.enables.polygon_offset_fill = case % 6 == 3;
        st.polygon_mode = match case % 11 {
            3 => [gl::LINE, gl::FILL],
            7 => [gl::POINT, gl::LINE],
            _ => [gl::FILL; 2],
        };
        st.polygon_offset_factor = rng.range(-2.0, 2.0);
        st.polygon_offset_units = rng.range(-2.0, 2.0);
        st.enables.scissor_test = case % 7 == 4;
        st.scissor = [20, 10, 200, 150];
        st.enables.lighting = case % 3 == 0;
        st.enables.lights[0] = true;
        st.light_model.two_side = case % 2 == 0;
        // Many varyings: textures on several units (in groups of four, one, two or four
        // units), the secondary colour (FLAT with it: eight flat varyings), the fog coordinate
        // (a lone varying at the end).
        for u in 0..4 {
            st.enables.texture_2d[u] =
                case % 4 == 2 || (case % 8 == 5 && u % 2 == 1) || (case % 8 == 7);
        }
        if case % 3 == 0 && case % 4 != 0 {
            st.light_model.color_control = gl::SEPARATE_SPECULAR_COLOR;
        }
        st.enables.color_sum = case % 7 == 1;
        st.enables.fog = case % 5 == 0 || case % 8 == 7;
        // Small cells (many triangles of a pixel or two) or large ones.
        let scale = if case % 2 == 0 { 0.02 } else { 0.6 };
        *st.projection.top_mut() = Mat4::perspective_rh_gl(1.2, 1.5, 0.5, 20.0);
        *st.modelview.top_mut() = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0));
        let mut b = Batch::default();
        for _ in 0..12 {
            let mode = modes[(rng.next() * modes.len() as f32) as usize % modes.len()];
            let n = 3 + (rng.next() * 20.0) as usize;
            b.begin(mode);
            b.note_materials(&st.materials);
            let (cx, cy) = (rng.range(-2.5, 2.5), rng.range(-2.0, 2.0));
            for k in 0..n {
                let p = Vec4::new(
                    cx + scale * (k as f32 * 0.5 + rng.range(-1.0, 1.0)),
                    cy + scale * rng.range(-1.0, 1.0),
                    rng.range(-1.0, 2.9) * if rng.next() < 0.1 { 2.0 } else { 1.0 },
                    1.0,
                );
                // (The random values drawn in the order they always were.)
                let mut c = Current::default();
                c.inputs_mut().color = Vec4::new(rng.next(), rng.next(), rng.next(), rng.next());
                c.normal = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
                c.inputs_mut().tex_coords = [Vec4::new(rng.next(), rng.next(), 0.0, 1.0); 4];
                c.inputs_mut().edge_flag = rng.next() < 0.8;
                b.vertex(p, &c);
            }
            b.end();
        }
        prims += compare_routes(&st, &b, case, wide);
    }
    assert!(prims > 5000, "only {prims} primitives compared");
}

/// A 300x200 state with its viewport, culling (case 1 mod 4), the culled face and the front
/// face chosen by `case`.
fn culled_state(case: usize) -> State {
    let (w, h) = (300, 200);
    let mut st = State::new(w, h);
    st.viewport = [0, 0, w as i32, h as i32];
    st.enables.cull_face = case % 4 == 1;
    st.cull_face_mode = [gl::BACK, gl::FRONT][case % 2];
    st.front_face = [gl::CCW, gl::CW][(case / 2) % 2];
    st
}

/// `st`'s batch `b` set up by the baseline route and by `wide`, assembled on the fly
/// (`assemble_by`) and from `assemble`'s triangles (`run_by`): every primitive's fields, every
/// float of the pool, every touched bin and the area the same. Returns the primitives.
fn compare_routes(st: &State, b: &Batch, case: usize, wide: Route) -> usize {
    let (w, h) = (st.viewport[2] as u32, st.viewport[3] as u32);
    let layout = Layout::for_state(st);
    let tiles = (w.div_ceil(64) as usize, h.div_ceil(64) as usize);
    let ctx = SetupCtx::new(st, layout, scissor_rect(st), tiles);
    let (mut vout, mut wins) = (Vec::new(), Vec::new());
    process_by(
        st,
        b,
        &layout,
        &ctx,
        &mut vout,
        &mut wins,
        true,
        Route::Baseline,
    );
    let run = |route| {
        let mut wk = Worker::default();
        wk.assemble_by(&ctx, &vout, &wins, b, &b.prims, route);
        wk
    };
    let (a, c) = (run(Route::Baseline), run(wide));
    // The same triangles assembled first and set up by `run` (the route a flush takes
    // when one primitive dominates): the same primitives again, by both routes.
    let mut asm = Vec::new();
    crate::cpu::assembly::assemble(&b.prims, &b.idx, b.edge(), ctx.quads_split_last, &mut asm);
    let run_asm = |route| {
        let mut wk = Worker::default();
        wk.run_by(&ctx, &vout, &wins, &b.mat, &asm, route);
        wk
    };
    let (d, e) = (run_asm(Route::Baseline), run_asm(wide));
    let fields = |wk: &Worker| {
        wk.prims
            .iter()
            .map(|p| {
                (
                    p.kind,
                    p.flags,
                    p.bbox,
                    p.mat,
                    p.voff,
                    p.xy,
                    p.owns,
                    p.cover,
                    p.z.map(super::lighting::nan_bits),
                )
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(fields(&a), fields(&c), "case {case}: primitives differ");
    assert_eq!(
        fields(&a),
        fields(&d),
        "case {case}: run's primitives differ"
    );
    assert_eq!(
        fields(&a),
        fields(&e),
        "case {case}: run's primitives differ (route)"
    );
    let bits = |wk: &Worker| {
        wk.pool
            .iter()
            .map(|&v| super::lighting::nan_bits(v))
            .collect::<Vec<_>>()
    };
    for (o, name) in [(&c, "route"), (&d, "run"), (&e, "run by route")] {
        assert_eq!(bits(&a), bits(o), "case {case}: pools differ ({name})");
        assert_eq!(a.touched, o.touched, "case {case} ({name})");
        for &t in &a.touched {
            assert_eq!(
                a.bins[t as usize], o.bins[t as usize],
                "case {case}, tile {t} ({name})"
            );
        }
        assert_eq!(a.area, o.area, "case {case} ({name})");
    }
    a.prims.len()
}

/// Dense strips of a smooth colour-only layout (lit, no texture: `SetupCtx::colour_strips`,
/// the strips' own AVX2 route, `Worker::strip_tri_avx2`), cells of a pixel or two and some of
/// several, under random culling and facing, set up by both routes: the same primitives.
/// Cells cross the 64-pixel tile edges, some vertices repeat (triangles without area, boxes
/// without a centre), and some are far outside or not numbers (clipped, `general`).
#[test]
fn strip_route_is_fast_tri() {
    let wide = Route::best();
    let mut rng = Rng(0x2c1b_3a55);
    let mut prims = 0;
    for case in 0..60 {
        let mut st = culled_state(case);
        st.enables.lighting = true;
        st.enables.lights[0] = true;
        st.light_model.two_side = case % 3 == 0;
        st.enables.polygon_offset_fill = case % 5 == 3;
        st.polygon_offset_factor = rng.range(-2.0, 2.0);
        st.polygon_offset_units = rng.range(-2.0, 2.0);
        let (w, h) = (st.viewport[2] as f32, st.viewport[3] as f32);
        *st.projection.top_mut() = Mat4::orthographic_rh_gl(0.0, w, 0.0, h, -1.0, 1.0);
        let mut b = Batch::default();
        let cell = [0.6, 1.1, 1.7, 4.0][case % 4];
        for _ in 0..40 {
            let (x0, y0) = (rng.range(-4.0, w), rng.range(-4.0, h));
            let n = 4 + (rng.next() * 12.0) as usize;
            b.begin(gl::TRIANGLE_STRIP);
            b.note_materials(&st.materials);
            let mut last = Vec4::ZERO;
            for k in 0..n {
                let jit = |r: &mut Rng| r.range(-0.3, 0.3) * cell;
                let mut p = Vec4::new(
                    x0 + (k / 2) as f32 * cell + jit(&mut rng),
                    y0 + (k % 2) as f32 * cell + jit(&mut rng),
                    rng.range(-0.9, 0.9),
                    1.0,
                );
                match (rng.next() * 40.0) as usize {
                    0 => p.x = 1e9,
                    1 => p.y = f32::NAN,
                    2 if k > 0 => p = last,
                    _ => {}
                }
                last = p;
                let mut c = Current::default();
                c.inputs_mut().color = Vec4::new(rng.next(), rng.next(), rng.next(), 1.0);
                c.normal = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
                b.vertex(p, &c);
            }
            b.end();
        }
        prims += compare_routes(&st, &b, case, wide);
    }
    assert!(prims > 5000, "only {prims} primitives compared");
}
