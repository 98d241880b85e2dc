//! Renders the `projective-texture` scene to `projective-texture.png` (800x800): checkerboard projected onto spheres on a table: EYE_LINEAR TexGen on S, T, R, Q, texture matrix = bias · projection · view · inverse camera view, CLAMP_TO_BORDER, MODULATE over lighting.
//!
//! ```text
//! cargo run --release --example projective-texture [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/projective.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare projective-texture`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("projective-texture")
        .ok_or("the projective-texture scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("projective-texture.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
