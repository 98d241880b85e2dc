//! Renders the `blending` scene to `blending.png` (800x800): translucent panels sorted back to front over a lit sphere (BlendFunc SRC_ALPHA, ONE, CONSTANT_ALPHA; DepthMask).
//!
//! ```text
//! cargo run --release --example blending [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/fragment.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare blending`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("blending").ok_or("the blending scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("blending.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
