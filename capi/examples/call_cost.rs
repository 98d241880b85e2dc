//! What a GL call costs through the C ABI next to the Rust method: the lecture's immediate-mode
//! surface (400 x 400 cells, one triangle strip of four vertices per cell with a normal each:
//! 1.6M calls a frame) drawn by `Context` methods and by the exported `gl*` functions of the
//! C ABI on an OSMesa context of the same size, frames interleaved.
//!
//! `cargo run --release -p fixedgl-capi --example call_cost [FRAMES]`

use std::ffi::c_void;
use std::time::Instant;

use fixedgl::{gl, Context};
use fixedgl_capi::manual::glFinish;
use fixedgl_capi::osmesa::{OSMesaCreateContextExt, OSMesaMakeCurrent};

extern "C" {
    fn glBegin(mode: u32);
    fn glEnd();
    fn glNormal3f(x: f32, y: f32, z: f32);
    fn glVertex3f(x: f32, y: f32, z: f32);
    fn glClear(mask: u32);
    fn glEnable(cap: u32);
    fn glMatrixMode(mode: u32);
    fn glLoadIdentity();
    fn glOrtho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64);
}

const N: usize = 400;
const SIZE: i32 = 400;

fn height(x: f32, y: f32) -> f32 {
    (-(x * x + y * y) * 4.0).exp()
}

/// The surface's calls, through `begin`, `normal`, `vertex`, `end`.
fn surface(
    begin: &mut dyn FnMut(),
    normal: &mut dyn FnMut(f32, f32, f32),
    vertex: &mut dyn FnMut(f32, f32, f32),
    end: &mut dyn FnMut(),
) -> usize {
    let step = 2.0 / N as f32;
    let mut calls = 0;
    for i in 0..N {
        for j in 0..N {
            begin();
            for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let x = -1.0 + (i + di) as f32 * step;
                let y = -1.0 + (j + dj) as f32 * step;
                normal(x, y, 1.0);
                vertex(x, y, height(x, y));
            }
            end();
            calls += 10;
        }
    }
    calls
}

fn main() {
    let frames: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5);
    let mut ctx = Context::new(SIZE as u32, SIZE as u32).expect("a context");
    ctx.enable(gl::LIGHTING);
    ctx.enable(gl::LIGHT0);
    ctx.enable(gl::DEPTH_TEST);
    let mut buffer = vec![0u8; (SIZE * SIZE * 4) as usize];
    let osm = OSMesaCreateContextExt(gl::RGBA, 24, 8, 0, std::ptr::null_mut());
    assert_eq!(
        OSMesaMakeCurrent(
            osm,
            buffer.as_mut_ptr().cast::<c_void>(),
            gl::UNSIGNED_BYTE,
            SIZE,
            SIZE
        ),
        1,
        "OSMesaMakeCurrent"
    );
    // SAFETY: an OSMesa context is current on this thread.
    unsafe {
        glEnable(gl::LIGHTING);
        glEnable(gl::LIGHT0);
        glEnable(gl::DEPTH_TEST);
        glMatrixMode(gl::PROJECTION);
        glLoadIdentity();
        glOrtho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
        glMatrixMode(gl::MODELVIEW);
    }
    ctx.matrix_mode(gl::PROJECTION);
    ctx.ortho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
    ctx.matrix_mode(gl::MODELVIEW);
    let (mut rust_s, mut c_s, mut calls) = (Vec::new(), Vec::new(), 0);
    for _ in 0..frames {
        let t = Instant::now();
        ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        let c = std::cell::RefCell::new(&mut ctx);
        calls = surface(
            &mut || c.borrow_mut().begin(gl::TRIANGLE_STRIP),
            &mut |x, y, z| c.borrow_mut().normal3f(x, y, z),
            &mut |x, y, z| c.borrow_mut().vertex3f(x, y, z),
            &mut || c.borrow_mut().end(),
        );
        ctx.finish();
        let _ = ctx.to_image();
        rust_s.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        // SAFETY: the OSMesa context is current on this thread.
        unsafe {
            glClear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
            surface(
                &mut || glBegin(gl::TRIANGLE_STRIP),
                &mut |x, y, z| glNormal3f(x, y, z),
                &mut |x, y, z| glVertex3f(x, y, z),
                &mut || glEnd(),
            );
            glFinish();
        }
        c_s.push(t.elapsed().as_secs_f64());
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (r, c) = (median(&mut rust_s), median(&mut c_s));
    println!("{calls} calls a frame, {frames} frames, median:");
    println!(
        "  Rust methods: {:8.2} ms a frame, {:6.1} ns a call",
        r * 1e3,
        r * 1e9 / calls as f64
    );
    println!(
        "  C ABI (gl*):  {:8.2} ms a frame, {:6.1} ns a call ({:.2}x the Rust method)",
        c * 1e3,
        c * 1e9 / calls as f64,
        c / r
    );
}
