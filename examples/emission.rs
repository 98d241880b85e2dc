//! Renders the `emission` scene to `emission.png` (800x800): seed 003's emissive material next to a plain one, and an emissive bulb holding a light.
//!
//! ```text
//! cargo run --release --example emission [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare emission`.

use std::path::PathBuf;

use fixedgl::scenes::lights::emission;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    emission(&mut gl);
    let path = out.join("emission.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
