//! Renders the `cube-colors` scene to `cube-colors.png` (800x800): seed 004 cube: 24 interleaved position+colour vertices in a VBO, UNSIGNED_INT EBO, scale 1.1, rotate -45 about x and y, gluLookAt + gluPerspective 45, depth test.
//!
//! ```text
//! cargo run --release --example cube-colors [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/arrays.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare cube-colors`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("cube-colors").ok_or("the cube-colors scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("cube-colors.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
