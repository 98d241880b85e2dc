//! Renders the `textured-cube` scene to `textured-cube.png` (960x640): lit cube and floor, mipmapped checkerboard (gluBuild2DMipmaps, REPEAT), TexEnv MODULATE, one panel per MIN filter (NEAREST .. LINEAR_MIPMAP_LINEAR).
//!
//! ```text
//! cargo run --release --example textured-cube [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/texture.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare textured-cube`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("textured-cube").ok_or("the textured-cube scene is registered")?;
    let mut gl = Context::new(960, 640)?;
    (scene.draw)(&mut gl);
    let path = out.join("textured-cube.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
