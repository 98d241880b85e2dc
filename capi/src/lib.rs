//! fixedgl behind the C ABI: one shared library that C (and Python, through ctypes) programs
//! load in place of the system's `libGL.so.1`, `libEGL.so.1`, `libOpenGL.so.0` and
//! `libOSMesa.so.8` (`fixedgl run` puts symlinks of those names on `LD_LIBRARY_PATH`).
//!
//! Layers:
//! - `generated.rs` (from the command table, `src/commands/gen.rs`): one `extern "C"` function
//!   per GL 1.0–1.5 command. An implemented one turns its C arguments into the `Call` (or the
//!   `Context` method call) the Rust API takes: fixed-length pointers read as arrays,
//!   pname-dependent ones through the shared count functions (`fixedgl::counts`), pixel and array
//!   data through `args.rs`. One that fixedgl does not implement exists (so that libraries linked
//!   with BIND_NOW load), does nothing, says so once on stderr, and is NULL from GetProcAddress.
//! - `manual.rs`: the commands that answer through pointers or return values (queries, names).
//! - `ext_vertex_array.rs`: GL_EXT_vertex_array's `gl*PointerEXT` (the GL 1.1 commands with an
//!   unused count), re-exported by `manual.rs` so that the GetProcAddress table finds them.
//! - `current.rs`: contexts, the current one per thread, and the panic boundary.
//! - `egl.rs`, `osmesa.rs`, `glx.rs`: the window-system APIs that make contexts current on
//!   surfaces; `xwin.rs`: Xlib (loaded at run time) and the X drawables GLX presents into.
//!
//! Safety: every entry point trusts its pointers exactly as a GL implementation does (a C
//! caller promises that each points at what the command reads or writes); NULL is checked
//! where GL would read or write through it, and raises a GL error instead of crashing. No panic
//! crosses the boundary: each entry point runs under `catch_unwind`.

// C names and C calling conventions throughout; the safety contract is the module's (above).
#![allow(non_snake_case, clippy::missing_safety_doc)]

mod args;
mod current;
pub mod egl;
mod ext_vertex_array;
mod generated;
pub mod glx;
pub mod manual;
pub mod osmesa;
mod read;
mod record;
mod xwin;

pub use generated::proc_address;

use std::collections::HashSet;
use std::sync::Mutex;

/// Names of the functions that have said they are not implemented (once each).
static SAID: Mutex<Option<HashSet<&'static str>>> = Mutex::new(None);

/// Says once per function, on stderr, that a program called a GL command fixedgl does not
/// implement. Nothing else happens: no state changes, no error is raised.
pub(crate) fn unimplemented(name: &'static str) {
    if say_once(name) {
        eprintln!("fixedgl: {name} is not implemented; the call does nothing");
    }
}

/// Whether `key` is new (then remembered): for messages printed once.
pub(crate) fn say_once(key: &'static str) -> bool {
    let Ok(mut said) = SAID.lock() else {
        return false;
    };
    said.get_or_insert_with(HashSet::new).insert(key)
}
