//! Renders the `fog` scene to `fog.png` (800x800): an avenue of cubes fogged LINEAR, EXP and EXP2 side by side (Fog, per-fragment |z_eye|).
//!
//! ```text
//! cargo run --release --example fog [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/fragment.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare fog`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("fog").ok_or("the fog scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("fog.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
