//! Renders the `evaluators` scene to `evaluators.png` (600x600): the Red Book's Bézier curve with its control polygon, the bezmesh patch lit with AUTO_NORMAL (EvalMesh2 FILL), bezsurf's wireframe (EvalMesh2 LINE) and a textured rational patch (Map1f/Map2f/MapGrid/EvalCoord/EvalPoint).
//!
//! ```text
//! cargo run --release --example evaluators [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/evaluators.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare evaluators`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("evaluators").ok_or("the evaluators scene is registered")?;
    let mut gl = Context::new(600, 600)?;
    (scene.draw)(&mut gl);
    let path = out.join("evaluators.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
