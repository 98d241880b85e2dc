//! Renders the `picking` scene to `picking.png` (800x800): a 4x4 grid of named lit GLUT solids, a selection pass with gluPickMatrix around a cursor, the nearest hit highlighted.
//!
//! ```text
//! cargo run --release --example picking [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/picking.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare picking`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("picking").ok_or("the picking scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("picking.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
