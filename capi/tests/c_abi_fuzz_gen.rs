//! `c_abi_fuzz/gl_calls.rs`, the GL 1.0–1.5 commands as C declares them and the random calls
//! of `c_abi_fuzz.rs`, is what `c_abi_fuzz/gen.rs` makes of gl.xml. A test binary of its own, so
//! that it builds (and can rewrite the file) whatever state the file is in.

#[path = "c_abi_fuzz/gen.rs"]
mod gen;

/// gl_calls.rs is what gen.rs makes of gl.xml (FIXEDGL_BLESS=1 rewrites it).
#[test]
fn generated_calls_match_gl_xml() {
    let want = gen::generate();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c_abi_fuzz/gl_calls.rs");
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    if have == want {
        return;
    }
    if std::env::var_os("FIXEDGL_BLESS").is_some() {
        std::fs::write(&path, want).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    } else {
        panic!(
            "{} is stale: FIXEDGL_BLESS=1 cargo test -p fixedgl-capi --test c_abi_fuzz_gen",
            path.display()
        );
    }
}
