//! Build script: with the `gl` feature, generates the GL 2.1 compatibility-profile bindings the
//! real-GL backend replays recorded calls through (gl_generator, struct form: every entry point is
//! a function pointer loaded at run time through EGL, none is declared by hand).

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    #[cfg(feature = "gl")]
    generate_gl_bindings();
}

/// Writes `$OUT_DIR/gl_bindings.rs`: a `Gl` struct holding every GL 2.1 entry point (and
/// GL_ARB_framebuffer_object's), including the
/// fixed-function ones a core profile lacks (Begin, Lightfv, Materialfv, ...). `Fallbacks::All`
/// lets an entry point fall back to its ARB/EXT alias where a driver only exports that name.
#[cfg(feature = "gl")]
fn generate_gl_bindings() {
    use gl_generator::{Api, Fallbacks, Profile, Registry, StructGenerator};
    use std::fs::File;
    use std::io::BufWriter;
    use std::path::PathBuf;

    let Some(out_dir) = std::env::var_os("OUT_DIR") else {
        println!("cargo:warning=OUT_DIR is not set; cannot generate GL bindings");
        std::process::exit(1);
    };
    let path = PathBuf::from(out_dir).join("gl_bindings.rs");
    let result = File::create(&path).and_then(|file| {
        let mut out = BufWriter::new(file);
        // GL_ARB_framebuffer_object: the framebuffer-object commands under their GL 3.0 names
        // (the generated wrappers and glbackend/fbo.rs call them with raw names).
        let extensions = ["GL_ARB_framebuffer_object"];
        Registry::new(
            Api::Gl,
            (2, 1),
            Profile::Compatibility,
            Fallbacks::All,
            extensions,
        )
        .write_bindings(StructGenerator, &mut out)
    });
    if let Err(e) = result {
        println!("cargo:warning=writing {}: {e}", path.display());
        std::process::exit(1);
    }
}
