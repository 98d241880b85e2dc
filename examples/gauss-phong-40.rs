//! Renders the `gauss-phong-40` scene to `gauss-phong-40.png` (800x800): seed 000: the 40x40 bump with ShadeModel(PHONG_WIN), per-fragment lighting (the seed's GLSL Phong).
//!
//! ```text
//! cargo run --release --example gauss-phong-40 [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/gaussian.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare gauss-phong-40`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("gauss-phong-40").ok_or("the gauss-phong-40 scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("gauss-phong-40.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
