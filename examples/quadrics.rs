//! Renders the `quadrics` scene to `quadrics.png` (800x800): spheres, cylinders, disks and a partial disk in every GLU draw style.
//!
//! ```text
//! cargo run --release --example quadrics [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/quadrics.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare quadrics`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("quadrics").ok_or("the quadrics scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("quadrics.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
