//! Renders the `display-list` scene to `display-list.png` (800x800): a ring of eight lit GLUT solids, each a display list, the ring one list calling them through ListBase + CallLists (NewList/CallList/PushAttrib).
//!
//! ```text
//! cargo run --release --example display-list [OUT_DIR]
//! ```
//!
//! The ported GL calls are in `src/scenes/lists.rs`; the CPU-vs-driver comparison of the same calls is
//! `cargo run --release -- compare display-list`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene =
        fixedgl::scenes::find("display-list").ok_or("the display-list scene is registered")?;
    let mut gl = Context::new(800, 800)?;
    (scene.draw)(&mut gl);
    let path = out.join("display-list.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
