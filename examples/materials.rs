//! Renders the `materials` scene to `materials.png` (800x800): brass, gold, slide 57's yellow and GL's default material (seed 003).
//!
//! ```text
//! cargo run --release --example materials [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare materials`.

use std::path::PathBuf;

use fixedgl::scenes::lights::materials_scene;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    materials_scene(&mut gl);
    let path = out.join("materials.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
