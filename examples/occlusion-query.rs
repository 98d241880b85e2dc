//! Renders the `occlusion-query` scene to `occlusion-query.png` (640x480): objects drawn only where a proxy box's occlusion query says samples passed, with the counts shown.
//!
//! ```text
//! cargo run --release --example occlusion-query [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/occlusion.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare occlusion-query`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("occlusion-query")
        .ok_or("the occlusion-query scene is registered")?;
    let mut gl = Context::new(640, 480)?;
    (scene.draw)(&mut gl);
    let path = out.join("occlusion-query.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
