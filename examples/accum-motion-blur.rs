//! Renders the `accum-motion-blur` scene to `accum-motion-blur.png` (512x384): twelve positions of a bouncing ball and a turning bar folded into the accumulation buffer (Accum LOAD, MULT, ACCUM, RETURN): a fading motion trail.
//!
//! ```text
//! cargo run --release --example accum-motion-blur [OUT_DIR]
//! ```
//!
//! The context is made with an accumulation buffer (`ContextConfig { accum: true, .. }`, GLUT's
//! `GLUT_ACCUM`): the scene's `config`. The ported GL calls are in `src/scenes/accum.rs`; the
//! CPU-vs-driver comparison of the same calls is `cargo run --release -- compare accum-motion-blur`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("accum-motion-blur")
        .ok_or("the accum-motion-blur scene is registered")?;
    let mut gl = Context::with_config(512, 384, scene.config)?;
    (scene.draw)(&mut gl);
    let path = out.join("accum-motion-blur.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
