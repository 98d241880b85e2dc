//! Renders the `rect-wire` scene to `rect-wire.png` (800x800): seed 004 rectangle: two triangles from a VBO and UNSIGNED_BYTE EBO [0,1,3, 1,2,3], PolygonMode(FRONT_AND_BACK, LINE).
//!
//! ```text
//! cargo run --release --example rect-wire [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/arrays.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare rect-wire`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("rect-wire").ok_or("the rect-wire scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("rect-wire.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
