//! Renders the `draw-pixels` scene to `draw-pixels.png` (800x800): a procedural photo drawn with DrawPixels as it is, zoomed, mirrored and flipped, through scale and bias and colour maps, an indexed image through pixel maps, a depth image against a plane, CopyPixels of a region and Bitmap labels.
//!
//! ```text
//! cargo run --release --example draw-pixels [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/pixels.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare draw-pixels`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("draw-pixels").ok_or("the draw-pixels scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("draw-pixels.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
