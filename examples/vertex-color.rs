//! Renders the `vertex-color` scene to `vertex-color.png` (800x800): seed 000's bump coloured by object position (the seed's GLSL shader as `glColor3f(x, y, z)`).
//!
//! ```text
//! cargo run --release --example vertex-color [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare vertex-color`.

use std::path::PathBuf;

use fixedgl::scenes::surface::vertex_color;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    vertex_color(&mut gl);
    let path = out.join("vertex-color.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
