//! Renders the `stipple` scene to `stipple.png` (800x800): the Red Book lines.c and polys.c, dashed lines and stippled polygons.
//!
//! ```text
//! cargo run --release --example stipple [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/stipple.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare stipple`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("stipple").ok_or("the stipple scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("stipple.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
