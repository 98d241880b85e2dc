//! Renders the `render-to-texture` scene to `render-to-texture.png` (400x400): a lit teapot and torus drawn into a texture through a framebuffer object with a depth renderbuffer, then that texture on a cube.
//!
//! ```text
//! cargo run --release --example render-to-texture [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/fbo.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare render-to-texture`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("render-to-texture")
        .ok_or("the render-to-texture scene is registered")?;
    let mut gl = Context::new(400, 400)?;
    (scene.draw)(&mut gl);
    let path = out.join("render-to-texture.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
