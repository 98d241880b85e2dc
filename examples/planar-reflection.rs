//! Renders the `planar-reflection` scene to `planar-reflection.png` (800x800): seed 001: objects mirrored in the floor, confined by the stencil buffer, floor blended over them.
//!
//! ```text
//! cargo run --release --example planar-reflection [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/fragment.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare planar-reflection`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("planar-reflection")
        .ok_or("the planar-reflection scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("planar-reflection.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
