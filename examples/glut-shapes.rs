//! Renders the `glut-shapes` scene to `glut-shapes.png` (800x800): the GLUT solids lit side by side: sphere, cube, cone, torus, teapot.
//!
//! ```text
//! cargo run --release --example glut-shapes [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/lists.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare glut-shapes`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("glut-shapes").ok_or("the glut-shapes scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("glut-shapes.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
