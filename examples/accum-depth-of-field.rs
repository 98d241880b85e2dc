//! Renders the `accum-depth-of-field` scene to `accum-depth-of-field.png` (512x384): five teapots drawn through eight jittered frusta (accPerspective, the j8 table) and averaged in the accumulation buffer: depth of field.
//!
//! ```text
//! cargo run --release --example accum-depth-of-field [OUT_DIR]
//! ```
//!
//! The context is made with an accumulation buffer (`ContextConfig { accum: true, .. }`, GLUT's
//! `GLUT_ACCUM`): the scene's `config`. The ported GL calls are in `src/scenes/accum.rs`; the
//! CPU-vs-driver comparison of the same calls is `cargo run --release -- compare accum-depth-of-field`.

use std::path::PathBuf;

use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let scene = fixedgl::scenes::find("accum-depth-of-field")
        .ok_or("the accum-depth-of-field scene is registered")?;
    let mut gl = Context::with_config(512, 384, scene.config)?;
    (scene.draw)(&mut gl);
    let path = out.join("accum-depth-of-field.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}
