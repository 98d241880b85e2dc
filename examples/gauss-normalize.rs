//! Renders the `gauss-normalize` scene to `gauss-normalize.png` (800x800): seed 000's smooth gaussian bump with normals three times too long and `glEnable(GL_NORMALIZE)`.
//!
//! ```text
//! cargo run --release --example gauss-normalize [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare gauss-normalize`.

use std::path::PathBuf;

use fixedgl::scenes::surface::gauss_normalize;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    gauss_normalize(&mut gl, 3.0);
    let path = out.join("gauss-normalize.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
