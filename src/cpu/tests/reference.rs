//! Scenes for a side-by-side check against Mesa llvmpipe: `#[ignore]`d, they write raw
//! bottom-up RGBA to /tmp/cpu-<scene>.rgba for an external comparison (the real-GL backend
//! automates this; these scenes pin down line, point, clipping and polygon-mode rules).

use glam::{Mat4, Vec4};

use super::*;

fn c3(r: f32, g: f32, b: f32) -> Vec4 {
    Vec4::new(r, g, b, 1.0)
}

fn dump(r: &Renderer, name: &str) {
    let raw: Vec<u8> = r.color().iter().flatten().copied().collect();
    let _ = std::fs::write(format!("/tmp/cpu-{name}.rgba"), raw);
}

fn star_and_strip(r: &mut Renderer, st: &State) {
    let mut vs = Vec::new();
    for k in 0..16 {
        let a = (k as f32 * 22.5 + 3.0) * std::f32::consts::PI / 180.0;
        vs.push(([0.03, -0.02, 0.0], c3(1.0, 0.0, 0.0)));
        vs.push(([0.9 * a.cos(), 0.9 * a.sin(), 0.0], c3(0.0, 1.0, 0.0)));
    }
    draw(r, st, gl::LINES, &vs);
    let strip: Vec<_> = (0..6)
        .map(|k| {
            let y = if k % 2 == 1 { -0.6 } else { -0.93 };
            ([-0.95 + 0.37 * k as f32, y, 0.0], c3(0.0, 0.0, 1.0))
        })
        .collect();
    draw(r, st, gl::LINE_STRIP, &strip);
}

#[test]
#[ignore = "writes /tmp/cpu-*.rgba for comparison with llvmpipe"]
fn reference_scenes() {
    let (mut r, mut st) = setup(64, 64);
    star_and_strip(&mut r, &st);
    dump(&r, "lines");

    let mut r = Renderer::new(64, 64);
    st.line_width = 3.0;
    star_and_strip(&mut r, &st);
    dump(&r, "wide");

    let (mut r, mut st) = setup(64, 64);
    for sz in 1..=4 {
        st.point_size = sz as f32;
        let vs: Vec<_> = (0..5)
            .map(|k| {
                let p = [
                    -0.9 + 0.41 * k as f32 + 0.013 * sz as f32,
                    -0.8 + 0.4 * sz as f32 + 0.021 * k as f32,
                    0.0,
                ];
                (p, c3(1.0, sz as f32 / 4.0, k as f32 / 4.0))
            })
            .collect();
        draw(&mut r, &st, gl::POINTS, &vs);
    }
    dump(&r, "points");

    let (mut r, mut st) = setup(64, 64);
    *st.projection.top_mut() = Mat4::from_cols_array(&[
        1.5,
        0.0,
        0.0,
        0.0,
        0.0,
        1.5,
        0.0,
        0.0,
        0.0,
        0.0,
        -1.222_222_2,
        -1.0,
        0.0,
        0.0,
        -0.222_222_22,
        0.0,
    ]);
    st.enables.depth_test = true;
    draw(
        &mut r,
        &st,
        gl::QUADS,
        &[
            ([-1.0, -0.6, 0.5], c3(1.0, 0.0, 0.0)),
            ([1.0, -0.6, 0.5], c3(0.0, 1.0, 0.0)),
            ([1.0, -0.6, -6.0], c3(0.0, 0.0, 1.0)),
            ([-1.0, -0.6, -6.0], c3(1.0, 1.0, 1.0)),
        ],
    );
    st.shade_model = gl::FLAT;
    draw(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[
            ([-0.8, -0.7, -2.0], c3(1.0, 1.0, 0.0)),
            ([0.6, -0.2, -3.0], c3(0.0, 1.0, 1.0)),
            ([-0.3, 0.9, -2.5], c3(1.0, 0.0, 1.0)),
        ],
    );
    dump(&r, "persp");

    let (mut r, mut st) = setup(64, 64);
    st.enables.cull_face = true;
    st.cull_face_mode = gl::FRONT;
    st.polygon_mode[1] = gl::LINE;
    let red = c3(1.0, 0.0, 0.0);
    let green = c3(0.0, 1.0, 0.0);
    draw(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[
            ([-0.9, -0.9, 0.0], red),
            ([-0.1, 0.8, 0.0], red),
            ([0.7, -0.7, 0.0], red),
            ([-0.5, 0.1, 0.0], green),
            ([0.6, 0.1, 0.0], green),
            ([0.0, 0.95, 0.0], green),
        ],
    );
    st.enables.cull_face = false;
    st.polygon_mode = [gl::POINT, gl::POINT];
    let blue = c3(0.0, 0.0, 1.0);
    draw(
        &mut r,
        &st,
        gl::QUADS,
        &[
            ([0.2, -0.95, 0.0], blue),
            ([0.95, -0.95, 0.0], blue),
            ([0.95, -0.2, 0.0], blue),
            ([0.2, -0.2, 0.0], blue),
        ],
    );
    dump(&r, "modes");
}
