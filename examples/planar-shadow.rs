//! Renders the `planar-shadow` scene to `planar-shadow.png` (800x800): seed 001: shadows projected onto the floor, stencil against double blending, blended darkening.
//!
//! ```text
//! cargo run --release --example planar-shadow [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/fragment.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare planar-shadow`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("planar-shadow").ok_or("the planar-shadow scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("planar-shadow.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
