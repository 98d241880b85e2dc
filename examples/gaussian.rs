//! The lecture's JOGL `Rendering` example (seed 000) rendered to PNG: the three pictures of the
//! slides, 800x800 each.
//!
//! ```text
//! cargo run --release --example gaussian [OUT_DIR]
//! ```
//!
//! writes `gauss-flat-40.png` (FLAT, one normal per cell, 40x40 cells), `gauss-smooth-40.png`
//! (SMOOTH, a normal per vertex) and `gauss-smooth-400.png` (SMOOTH, 400x400 cells). The port
//! itself, JOGL line by JOGL line, is `fixedgl::scenes::gaussian` (`init`, `lighting`, `display`).

use std::path::PathBuf;

use fixedgl::scenes::gaussian::{display, init, Shading};
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    for (name, cells, shading) in [
        ("gauss-flat-40", 40, Shading::Flat),
        ("gauss-smooth-40", 40, Shading::Smooth),
        ("gauss-smooth-400", 400, Shading::Smooth),
    ] {
        // JOGL's GLCanvas: an 800x800 drawable; init() once, then display() for the frame.
        let mut gl = Context::new(800, 800)?;
        init(&mut gl, shading);
        display(&mut gl, cells, shading);
        let path = out.join(format!("{name}.png"));
        gl.to_image().save(&path)?;
        println!("{}", path.display());
    }
    Ok(())
}
