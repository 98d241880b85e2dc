//! Renders the `spotlight` scene to `spotlight.png` (800x800): seed 003's LIGHT1 spotlight with attenuation over a floor and two spheres.
//!
//! ```text
//! cargo run --release --example spotlight [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare spotlight`.

use std::path::PathBuf;

use fixedgl::scenes::lights::spotlight;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    spotlight(&mut gl, [0.0, 0.0, 0.0]);
    let path = out.join("spotlight.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
