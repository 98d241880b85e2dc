//! Renders the `two-side` scene to `two-side.png` (800x800): an open bowl with gold FRONT and blue BACK materials, LIGHT_MODEL_TWO_SIDE off and on (seed 003).
//!
//! ```text
//! cargo run --release --example two-side [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare two-side`.

use std::path::PathBuf;

use fixedgl::scenes::lights::two_side;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    two_side(&mut gl);
    let path = out.join("two-side.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
