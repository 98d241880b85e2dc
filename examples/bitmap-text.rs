//! Renders the `bitmap-text` scene to `bitmap-text.png` (640x480): labels in the GLUT bitmap fonts over a lit teapot, and a stroke-font title.
//!
//! ```text
//! cargo run --release --example bitmap-text [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/text.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare bitmap-text`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("bitmap-text").ok_or("the bitmap-text scene is registered")?;
    let mut gl = Context::new(640, 480)?;
    (scene.draw)(&mut gl);
    let path = out.join("bitmap-text.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
