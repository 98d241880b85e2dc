//! Renders the `light-model` scene to `light-model.png` (800x800): global ambient 0 vs 0.2 and LOCAL_VIEWER off vs on (seed 003).
//!
//! ```text
//! cargo run --release --example light-model [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare light-model`.

use std::path::PathBuf;

use fixedgl::scenes::lights::light_model;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    light_model(&mut gl);
    let path = out.join("light-model.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
