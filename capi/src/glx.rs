//! GLX: `glXGetProcAddress` (what piglit and GL loaders resolve every gl* through). The GLX
//! calls that open windows on an X server are not here yet: each fails (no visual, no
//! context, False) and says so once on stderr.

use std::ffi::{c_char, c_void, CStr};

use crate::current::guard;

/// Says once that a GLX call is not available yet; what it returns is the call's failure value.
fn missing(name: &'static str) {
    if crate::say_once(name) {
        eprintln!(
            "fixedgl: {name}: GLX windows are not supported yet; use EGL (surfaceless) or OSMesa"
        );
    }
}

#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(name: *const c_char) -> *const c_void {
    guard("glXGetProcAddress", std::ptr::null(), || {
        if name.is_null() {
            return std::ptr::null();
        }
        // SAFETY: a NUL-terminated name (the API's contract).
        let name = unsafe { CStr::from_ptr(name) }.to_bytes();
        crate::proc_address(name).unwrap_or(std::ptr::null())
    })
}

#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(name: *const c_char) -> *const c_void {
    // SAFETY: the same contract.
    unsafe { glXGetProcAddress(name) }
}

macro_rules! unavailable {
    ($($name:ident($($arg:ident: $t:ty),*) -> $ret:ty = $fail:expr;)*) => {$(
        #[no_mangle]
        pub extern "C" fn $name($($arg: $t),*) -> $ret {
            $(let _ = $arg;)*
            missing(stringify!($name));
            $fail
        }
    )*};
}

unavailable! {
    glXChooseVisual(dpy: *mut c_void, screen: i32, attribs: *const i32) -> *mut c_void = std::ptr::null_mut();
    glXCreateContext(dpy: *mut c_void, vis: *mut c_void, share: *mut c_void, direct: i32) -> *mut c_void = std::ptr::null_mut();
    glXCreateNewContext(dpy: *mut c_void, config: *mut c_void, render_type: i32, share: *mut c_void, direct: i32) -> *mut c_void = std::ptr::null_mut();
    glXCreatePixmap(dpy: *mut c_void, config: *mut c_void, pixmap: usize, attribs: *const i32) -> usize = 0;
    glXDestroyContext(dpy: *mut c_void, ctx: *mut c_void) -> () = ();
    glXGetCurrentDisplay() -> *mut c_void = std::ptr::null_mut();
    glXGetCurrentDrawable() -> usize = 0;
    glXGetFBConfigAttrib(dpy: *mut c_void, config: *mut c_void, attribute: i32, value: *mut i32) -> i32 = 2;
    glXGetFBConfigs(dpy: *mut c_void, screen: i32, n: *mut i32) -> *mut c_void = std::ptr::null_mut();
    glXGetVisualFromFBConfig(dpy: *mut c_void, config: *mut c_void) -> *mut c_void = std::ptr::null_mut();
    glXMakeCurrent(dpy: *mut c_void, drawable: usize, ctx: *mut c_void) -> i32 = 0;
    glXQueryExtension(dpy: *mut c_void, error_base: *mut i32, event_base: *mut i32) -> i32 = 0;
    glXQueryExtensionsString(dpy: *mut c_void, screen: i32) -> *const c_char = c"".as_ptr();
    glXQueryVersion(dpy: *mut c_void, major: *mut i32, minor: *mut i32) -> i32 = 0;
}
