//! Renders the `primitives` scene to `primitives.png` (800x800): the ten Begin/End modes, a colour per vertex, SMOOTH.
//!
//! ```text
//! cargo run --release --example primitives [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare primitives`.

use std::path::PathBuf;

use fixedgl::gl::SMOOTH;
use fixedgl::scenes::primitives::primitives;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    primitives(&mut gl, SMOOTH);
    let path = out.join("primitives.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
