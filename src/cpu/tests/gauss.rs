//! The lecture's lit gaussian surface (seeds/000: JOGL `Rendering`), fed straight to the renderer:
//! a correctness smoke test at 40x40 cells and an `#[ignore]`d timing harness at 400x400.

use glam::{Mat4, Vec3, Vec4};

use super::*;
use crate::state::FRONT;

/// createMatrix(size) + calculateNormal: (size+2)² points and normals.
fn grid(size: usize) -> (Vec<Vec3>, Vec<Vec3>) {
    let n = size + 2;
    let mut p = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let x = (4.0 * j as f32) / (size as f32 + 2.0) - 2.0;
            let z = (4.0 * i as f32) / (size as f32 + 2.0) - 2.0;
            let y = ((-x * x) as f64).exp() as f32 * ((-z * z) as f64).exp() as f32;
            p.push(Vec3::new(x, y, z));
        }
    }
    let mut nrm = vec![Vec3::Y; n * n];
    for i in 1..n - 1 {
        for j in 1..n - 1 {
            let v1 = p[i * n + j];
            let v2 = p[i * n + j + 1];
            let v3 = p[(i + 1) * n + j];
            let a = v2 - v1;
            let b = v1 - v3;
            nrm[i * n + j] = a.cross(b).normalize();
        }
    }
    (p, nrm)
}

/// The scene's state after `init` and `display`'s material calls, `w` x `w` window.
pub(super) fn scene_state(w: u32) -> State {
    let mut st = State::new(w, w);
    let look = Mat4::look_at_rh(Vec3::new(1.5, 0.75, 1.0), Vec3::ZERO, Vec3::Y);
    *st.modelview.top_mut() = look;
    *st.projection.top_mut() = Mat4::orthographic_rh_gl(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5);
    st.clear_color = Vec4::ONE;
    st.enables.depth_test = true;
    st.enables.lighting = true;
    st.enables.lights[0] = true;
    st.lights[0].position = look * Vec4::new(1.0, 1.5, -0.5, 1.0);
    st.lights[0].ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    st.lights[0].diffuse = Vec4::ONE;
    st.lights[0].specular = Vec4::ONE;
    st.materials[FRONT].diffuse = Vec4::new(0.5, 0.5, 0.8, 1.0);
    st.materials[FRONT].specular = Vec4::ONE;
    st.materials[FRONT].shininess = 100.0;
    st
}

/// One frame: clear, then one 4-vertex TRIANGLE_STRIP per cell with per-vertex normals.
pub(super) fn frame(r: &mut Renderer, st: &State, size: usize, g: &(Vec<Vec3>, Vec<Vec3>)) {
    let (p, nrm) = g;
    let n = size + 2;
    r.clear(st, gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    let mut c = Current::default();
    for i in 1..n - 1 {
        for j in 1..n - 1 {
            r.begin(gl::TRIANGLE_STRIP);
            r.begin_materials(&st.materials);
            for k in [
                (i + 1) * n + j,
                (i + 1) * n + j + 1,
                i * n + j,
                i * n + j + 1,
            ] {
                c.normal = nrm[k];
                r.vertex(p[k].extend(1.0), &c);
            }
            r.end();
            // As `Context::end` does.
            r.flush_if_large(st);
        }
    }
    r.flush(st);
}

fn save(r: &mut Renderer, path: &str) {
    let (w, h) = r.size();
    let rows = r.color();
    let img = image::RgbaImage::from_fn(w, h, |x, y| {
        image::Rgba(rows[((h - 1 - y) * w + x) as usize])
    });
    let _ = img.save(path);
}

#[test]
fn gaussian_40_looks_right() {
    let st = scene_state(200);
    let mut r = Renderer::new(200, 200);
    let g = grid(40);
    frame(&mut r, &st, 40, &g);
    save(&mut r, "/tmp/cpu-gauss-40.png");
    // Background corner white; the surface is bluish (b > r = g) where it is lit diffusely.
    assert_eq!(px(&mut r, 0, 0), [255, 255, 255, 255]);
    assert_eq!(px(&mut r, 199, 199), [255, 255, 255, 255]);
    let bluish = r
        .color()
        .iter()
        .filter(|c| c[2] > c[0] && c[0] == c[1])
        .count();
    assert!(bluish > 5000, "{bluish}");
    // A specular streak: some near-white surface pixels.
    let white = r
        .color()
        .iter()
        .filter(|c| c[0] > 240 && c[2] > 240 && c[0] < 255)
        .count();
    assert!(white > 0);
}

#[test]
#[ignore = "timing harness: cargo test --release -- --ignored --nocapture gaussian_400_timing"]
fn gaussian_400_timing() {
    let st = scene_state(800);
    let mut r = Renderer::new(800, 800);
    let g = grid(400);
    frame(&mut r, &st, 400, &g);
    // Per-frame times; the minimum and the median are less sensitive to other processes
    // sharing the cores than the mean.
    let mut ms: Vec<f64> = (0..30)
        .map(|_| {
            let t = std::time::Instant::now();
            frame(&mut r, &st, 400, &g);
            t.elapsed().as_secs_f64() * 1000.0
        })
        .collect();
    ms.sort_by(f64::total_cmp);
    println!(
        "gaussian 400x400 cells (320k triangles) at 800x800: min {:.2} ms/frame, median {:.2}",
        ms[0],
        ms[ms.len() / 2]
    );
    save(&mut r, "/tmp/cpu-gauss-400.png");
    // Raw bottom-up RGBA, as glReadPixels returns it, for comparing with a reference render.
    let raw: Vec<u8> = r.color().iter().flatten().copied().collect();
    let _ = std::fs::write("/tmp/cpu-gauss400.rgba", raw);
}

#[test]
#[ignore = "writes /tmp/cpu-gaussflat40.rgba for comparison with llvmpipe"]
fn gaussian_flat_40_reference() {
    let mut st = scene_state(800);
    st.shade_model = gl::FLAT;
    let mut r = Renderer::new(800, 800);
    let (p, nrm) = grid(40);
    let n = 42;
    r.clear(&st, gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    let mut c = Current::default();
    for i in 1..n - 1 {
        for j in 1..n - 1 {
            // One normal per cell, set before the strip (the seed's flat variant).
            c.normal = nrm[i * n + j];
            r.begin(gl::TRIANGLE_STRIP);
            for k in [
                (i + 1) * n + j,
                (i + 1) * n + j + 1,
                i * n + j,
                i * n + j + 1,
            ] {
                r.vertex(p[k].extend(1.0), &c);
            }
            r.end();
        }
    }
    r.flush(&st);
    let raw: Vec<u8> = r.color().iter().flatten().copied().collect();
    let _ = std::fs::write("/tmp/cpu-gaussflat40.rgba", raw);
}
