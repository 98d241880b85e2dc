//! Renders the `transforms` scene to `transforms.png` (800x800): seed 004's cube under translate, scale and rotate.
//!
//! ```text
//! cargo run --release --example transforms [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare transforms`.

use std::path::PathBuf;

use fixedgl::scenes::transforms::{transforms, PANELS};
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    transforms(&mut gl, &PANELS);
    let path = out.join("transforms.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
