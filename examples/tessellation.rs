//! Renders the `tessellation` scene to `tessellation.png` (800x800): a star with a hole, a pentagram and overlapping squares through the GLU tessellator.
//!
//! ```text
//! cargo run --release --example tessellation [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/tessellation.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare tessellation`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("tessellation").ok_or("the tessellation scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("tessellation.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
