//! Mesa's off-screen interface, OSMesa (`libOSMesa.so.8`), as a second way to reach llvmpipe:
//! a context whose window-system framebuffer is a plain memory buffer and, unlike any EGL
//! config, can have an accumulation buffer (16 bits a channel, Mesa's own `main/accum.c`).
//! `GlBackend::osmesa` replays on it, so the accumulation buffer is compared with the driver's
//! own arithmetic rather than with the EGL backend's emulation of it.
//!
//! Design decision: the library is opened at run time (libloading), so builds and machines
//! without it lose only this backend (`Error::Backend` says what to install). OSMesa's
//! framebuffer is single-buffered; its GL entry points are Mesa's dispatch stubs, as EGL's are,
//! so each backend makes its own context current before every call (`GlBackend::make_current`).

use std::ffi::{c_char, c_void, CString};

use libloading::Library;

use crate::Error;

/// What to install on Debian/Ubuntu for OSMesa.
pub const OSMESA_HINT: &str = "install Mesa's OSMesa: apt-get install libosmesa6";

type CreateContextExt = unsafe extern "C" fn(
    format: u32,
    depth: i32,
    stencil: i32,
    accum: i32,
    share: *mut c_void,
) -> *mut c_void;
type MakeCurrent =
    unsafe extern "C" fn(ctx: *mut c_void, buffer: *mut c_void, ty: u32, w: i32, h: i32) -> u8;
type DestroyContext = unsafe extern "C" fn(ctx: *mut c_void);
type GetProcAddress = unsafe extern "C" fn(name: *const c_char) -> *const c_void;

/// OSMESA_RGBA (= GL_RGBA).
const OSMESA_RGBA: u32 = 0x1908;
/// GL_UNSIGNED_BYTE.
const UNSIGNED_BYTE: u32 = 0x1401;

/// An OSMesa context and the memory its framebuffer's colour buffer lives in.
pub(super) struct OsMesaContext {
    ctx: *mut c_void,
    /// The colour buffer: `width * height * 4` bytes, allocated here and freed in `Drop` after
    /// the context is destroyed (the driver writes into it while the context is current).
    buffer: *mut u8,
    len: usize,
    width: i32,
    height: i32,
    make_current: MakeCurrent,
    destroy: DestroyContext,
    get_proc: GetProcAddress,
    /// Kept loaded while the context lives (last field: dropped last).
    _lib: Library,
}

impl std::fmt::Debug for OsMesaContext {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("OsMesaContext")
            .field("size", &(self.width, self.height))
            .finish_non_exhaustive()
    }
}

/// A `len`-byte zeroed buffer, handed over as a raw pointer (freed by `free_buffer`).
fn alloc_buffer(len: usize) -> *mut u8 {
    Box::into_raw(vec![0u8; len].into_boxed_slice()).cast()
}

/// Frees a buffer `alloc_buffer` made.
///
/// # Safety
///
/// `ptr` and `len` come from one `alloc_buffer` call and nothing uses the buffer any more.
unsafe fn free_buffer(ptr: *mut u8, len: usize) {
    drop(Box::from_raw(std::ptr::slice_from_raw_parts_mut(ptr, len)));
}

impl OsMesaContext {
    /// Loads OSMesa and makes a `width` x `height` RGBA context with the given depth, stencil
    /// and accumulation bits current on this thread.
    pub fn new(
        width: u32,
        height: u32,
        depth: i32,
        stencil: i32,
        accum: i32,
    ) -> Result<Self, Error> {
        // SAFETY: loading Mesa's OSMesa runs its library constructors, which only initialise
        // Mesa itself.
        let lib =
            unsafe { Library::new("libOSMesa.so.8").or_else(|_| Library::new("libOSMesa.so")) }
                .map_err(|e| {
                    Error::Backend(format!("libOSMesa cannot be loaded ({e}); {OSMESA_HINT}"))
                })?;
        // SAFETY: the symbols are OSMesa's documented entry points with these C signatures
        // (GL/osmesa.h).
        let (create, make_current, destroy, get_proc) = unsafe {
            let sym = |name: &[u8]| {
                lib.get::<*const c_void>(name)
                    .map(|s| *s)
                    .map_err(|e| Error::Backend(format!("libOSMesa lacks an entry point: {e}")))
            };
            let create: CreateContextExt = std::mem::transmute(sym(b"OSMesaCreateContextExt\0")?);
            let make_current: MakeCurrent = std::mem::transmute(sym(b"OSMesaMakeCurrent\0")?);
            let destroy: DestroyContext = std::mem::transmute(sym(b"OSMesaDestroyContext\0")?);
            let get_proc: GetProcAddress = std::mem::transmute(sym(b"OSMesaGetProcAddress\0")?);
            (create, make_current, destroy, get_proc)
        };
        // SAFETY: plain OSMesa call; a null share context is allowed.
        let ctx = unsafe { create(OSMESA_RGBA, depth, stencil, accum, std::ptr::null_mut()) };
        if ctx.is_null() {
            return Err(Error::Backend(
                "OSMesaCreateContextExt failed (no RGBA context with these buffers)".into(),
            ));
        }
        let len = width as usize * height as usize * 4;
        let out = OsMesaContext {
            ctx,
            buffer: alloc_buffer(len),
            len,
            width: width as i32,
            height: height as i32,
            make_current,
            destroy,
            get_proc,
            _lib: lib,
        };
        if !out.make_current() {
            return Err(Error::Backend("OSMesaMakeCurrent failed".into()));
        }
        Ok(out)
    }

    /// Makes the context current on this thread with its buffer; false when OSMesa refuses.
    pub fn make_current(&self) -> bool {
        // SAFETY: `ctx` is live and `buffer` holds width * height RGBA8 pixels, and stays
        // allocated until after the context is destroyed.
        unsafe {
            (self.make_current)(
                self.ctx,
                self.buffer.cast(),
                UNSIGNED_BYTE,
                self.width,
                self.height,
            ) != 0
        }
    }

    /// Gives the framebuffer a new `width` x `height` buffer (zeroed), making the context
    /// current with it; false, with the old one kept, when OSMesa refuses.
    pub fn resize(&mut self, width: u32, height: u32) -> bool {
        let len = width as usize * height as usize * 4;
        let buffer = alloc_buffer(len);
        // SAFETY: as in `make_current`, with the new buffer.
        let ok = unsafe {
            (self.make_current)(
                self.ctx,
                buffer.cast(),
                UNSIGNED_BYTE,
                width as i32,
                height as i32,
            ) != 0
        };
        if !ok {
            // SAFETY: the new buffer was never handed to a context that kept it.
            unsafe { free_buffer(buffer, len) };
            self.make_current();
            return false;
        }
        // SAFETY: the context now uses the new buffer; nothing uses the old one.
        unsafe { free_buffer(self.buffer, self.len) };
        (self.buffer, self.len) = (buffer, len);
        (self.width, self.height) = (width as i32, height as i32);
        true
    }

    /// A lookup of GL entry points by name (null when unknown), valid while the library is
    /// loaded, i.e. while this context lives.
    pub fn loader(&self) -> impl Fn(&str) -> *const c_void {
        let get_proc = self.get_proc;
        move |name: &str| match CString::new(name) {
            // SAFETY: a NUL-terminated name; OSMesa only looks it up.
            Ok(c) => unsafe { get_proc(c.as_ptr()) },
            Err(_) => std::ptr::null(),
        }
    }
}

impl Drop for OsMesaContext {
    fn drop(&mut self) {
        // SAFETY: the context is ours; once destroyed nothing writes the buffer, which is then
        // freed; the library stays loaded until the fields drop after this.
        unsafe {
            (self.destroy)(self.ctx);
            free_buffer(self.buffer, self.len);
        }
    }
}
