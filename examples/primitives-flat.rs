//! Renders the `primitives-flat` scene to `primitives-flat.png` (800x800): the ten Begin/End modes, a colour per vertex, FLAT (provoking vertex).
//!
//! ```text
//! cargo run --release --example primitives-flat [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare primitives-flat`.

use std::path::PathBuf;

use fixedgl::gl::FLAT;
use fixedgl::scenes::primitives::primitives;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    primitives(&mut gl, FLAT);
    let path = out.join("primitives-flat.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
