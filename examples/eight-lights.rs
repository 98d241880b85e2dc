//! Renders the `eight-lights` scene to `eight-lights.png` (800x800): GL_LIGHT0..7, coloured, positional and directional (seed 003).
//!
//! ```text
//! cargo run --release --example eight-lights [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare eight-lights`.

use std::path::PathBuf;

use fixedgl::scenes::lights::eight_lights;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    eight_lights(&mut gl);
    let path = out.join("eight-lights.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
