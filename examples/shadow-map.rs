//! Renders the `shadow-map` scene to `shadow-map.png` (800x800): spheres on a table lit by a spot of light, shadows by a depth texture: depth from the light copied with CopyTexSubImage2D, COMPARE_R_TO_TEXTURE, TexEnv BLEND dimming what the light does not see.
//!
//! ```text
//! cargo run --release --example shadow-map [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/projective.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare shadow-map`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("shadow-map").ok_or("the shadow-map scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("shadow-map.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
