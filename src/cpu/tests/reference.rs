//! Scenes for a side-by-side check against Mesa llvmpipe: `#[ignore]`d, they write raw
//! bottom-up RGBA to /tmp/cpu-<scene>.rgba for an external comparison (the real-GL backend
//! automates this; these scenes pin down line, point, clipping and polygon-mode rules).

use glam::{Mat4, Vec3, Vec4};

use crate::state::{BACK, FRONT};

use super::*;

fn c3(r: f32, g: f32, b: f32) -> Vec4 {
    Vec4::new(r, g, b, 1.0)
}

fn dump(r: &mut Renderer, name: &str) {
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
    dump(&mut r, "lines");

    let mut r = Renderer::new(64, 64);
    st.line_width = 3.0;
    star_and_strip(&mut r, &st);
    dump(&mut r, "wide");

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
    dump(&mut r, "points");

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
    dump(&mut r, "persp");

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
    dump(&mut r, "modes");
}

#[test]
#[ignore = "writes /tmp/cpu-lit.rgba for comparison with llvmpipe"]
fn reference_lit() {
    let (mut r, mut st) = setup(128, 128);
    *st.projection.top_mut() = Mat4::from_cols_array(&[
        2.0,
        0.0,
        0.0,
        0.0,
        0.0,
        2.0,
        0.0,
        0.0,
        0.0,
        0.0,
        -11.0 / 9.0,
        -1.0,
        0.0,
        0.0,
        -20.0 / 9.0,
        0.0,
    ]);
    let l0 = &mut st.lights[0];
    l0.position = Vec4::new(0.5, 0.5, 1.0, 1.0);
    l0.spot_direction = Vec3::new(-0.2, -0.2, -1.0);
    l0.spot_cutoff = 40.0;
    l0.spot_exponent = 8.0;
    l0.linear_attenuation = 0.2;
    l0.quadratic_attenuation = 0.1;
    l0.diffuse = Vec4::new(1.0, 0.9, 0.8, 1.0);
    l0.specular = Vec4::ONE;
    l0.ambient = Vec4::new(0.1, 0.1, 0.1, 1.0);
    let l1 = &mut st.lights[1];
    l1.position = Vec4::new(-1.0, 0.5, 0.5, 0.0);
    l1.diffuse = Vec4::new(0.2, 0.3, 0.9, 1.0);
    l1.specular = Vec4::new(0.5, 0.5, 0.5, 1.0);
    st.light_model.ambient = Vec4::new(0.1, 0.1, 0.15, 1.0);
    st.light_model.local_viewer = true;
    st.light_model.two_side = true;
    st.light_model.color_control = gl::SEPARATE_SPECULAR_COLOR;
    st.materials[FRONT].specular = Vec4::new(0.8, 0.8, 0.8, 1.0);
    st.materials[FRONT].shininess = 30.0;
    st.materials[FRONT].emission = Vec4::new(0.05, 0.0, 0.0, 1.0);
    st.materials[BACK].diffuse = Vec4::new(0.9, 0.2, 0.2, 1.0);
    st.materials[BACK].ambient = Vec4::new(0.2, 0.0, 0.0, 1.0);
    st.materials[BACK].specular = Vec4::new(0.3, 0.3, 0.3, 1.0);
    st.materials[BACK].shininess = 10.0;
    st.color_material_face = gl::FRONT;
    st.color_material_mode = gl::AMBIENT_AND_DIFFUSE;
    st.enables.color_material = true;
    st.enables.lighting = true;
    st.enables.lights[0] = true;
    st.enables.lights[1] = true;
    st.enables.depth_test = true;
    *st.modelview.top_mut() = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0));
    let g = 24;
    for j in 0..g {
        for half in 0..2 {
            r.begin(gl::TRIANGLE_STRIP);
            r.begin_materials(&st.materials);
            for i in 0..=g / 2 {
                for k in 0..2 {
                    let jj = if (half == 0) == (k == 0) { j + 1 } else { j };
                    let x = -1.0 + 2.0 * (i + half * g / 2) as f32 / g as f32;
                    let y = -1.0 + 2.0 * jj as f32 / g as f32;
                    let c = cur(
                        Vec4::new((x + 1.0) / 2.0, (y + 1.0) / 2.0, 0.5, 1.0),
                        Vec3::new(x * 0.5, y * 0.5, 1.0),
                    );
                    r.vertex(Vec4::new(x, y, 0.0, 1.0), &c);
                }
            }
            r.end();
        }
    }
    r.flush(&st);
    dump(&mut r, "lit");
}

#[test]
#[ignore = "writes /tmp/cpu-misc.rgba for comparison with llvmpipe"]
fn reference_misc() {
    let (mut r, mut st) = setup(64, 64);
    st.viewport = [4, 6, 56, 50];
    st.depth_range = [0.2, 0.8];
    st.enables.scissor_test = true;
    st.scissor = [2, 3, 58, 55];
    st.clip_planes[0] = glam::DVec4::new(1.0, 0.3, 0.0, 0.4);
    st.enables.clip_planes[0] = true;
    st.enables.depth_test = true;
    let p = [[-0.9, -0.9, -0.5], [0.9, -0.7, 0.6], [0.1, 0.9, 0.1]];
    let cols = [c3(1.0, 0.0, 0.0), c3(0.0, 1.0, 0.0), c3(0.0, 0.0, 1.0)];
    draw(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[(p[0], cols[0]), (p[1], cols[1]), (p[2], cols[2])],
    );
    st.enables.polygon_offset_line = true;
    st.polygon_offset_factor = -1.0;
    st.polygon_offset_units = -2.0;
    st.polygon_mode = [gl::LINE, gl::LINE];
    let w = Vec4::ONE;
    draw(
        &mut r,
        &st,
        gl::TRIANGLES,
        &[(p[0], w), (p[1], w), (p[2], w)],
    );
    dump(&mut r, "misc");
}

#[test]
#[ignore = "writes /tmp/cpu-ties.rgba for comparison with llvmpipe"]
fn reference_ties() {
    let (mut r, st) = setup(16, 16);
    let t = [
        [[2.5, 2.5], [8.5, 2.5], [2.5, 8.5]],
        [[13.5, 13.5], [9.5, 13.5], [13.5, 9.5]],
    ];
    let mut vs = Vec::new();
    for (k, tri) in t.iter().enumerate() {
        let c = c3(
            if k == 0 { 1.0 } else { 0.0 },
            if k == 1 { 1.0 } else { 0.0 },
            1.0,
        );
        for p in tri {
            vs.push(([p[0] / 8.0 - 1.0, p[1] / 8.0 - 1.0, 0.0], c));
        }
    }
    draw(&mut r, &st, gl::TRIANGLES, &vs);
    dump(&mut r, "ties");
}
