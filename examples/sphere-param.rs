//! Renders the `sphere-param` scene to `sphere-param.png` (800x800): seed 004's parametric sphere, lit: SMOOTH, FLAT, wireframe and finer.
//!
//! ```text
//! cargo run --release --example sphere-param [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare sphere-param`.

use std::path::PathBuf;

use fixedgl::scenes::sphere::sphere_param;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    sphere_param(&mut gl, 24, 12);
    let path = out.join("sphere-param.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
