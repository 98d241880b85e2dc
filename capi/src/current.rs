//! Contexts made by the C APIs, the one current per thread, and the panic boundary.
//!
//! A context handed to C is a `Box<Gl>` turned into a raw pointer; the handle is kept in a
//! registry of live contexts, so that a stale or foreign handle passed back is refused, not
//! dereferenced. The current context of a thread lives in a `const`-initialised thread-local
//! `Cell` with no destructor: freeglut makes a context current from an `atexit` handler, after
//! Rust's thread-local destructors have run, where `LocalKey::with` would panic (`try_with` is
//! used throughout).

use std::cell::Cell;
use std::collections::HashSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Mutex;
use std::thread::ThreadId;

use fixedgl::{gl, Context, ContextConfig};

/// Where a context's frames go when it presents.
pub trait Surface: Send {
    /// The drawable's size, as last read (see `refresh`).
    fn size(&self) -> (u32, u32);
    /// Reads the drawable's size again where it can change (a window: one round trip to the X
    /// server). Called at MakeCurrent and glViewport; a window also reads it after each present.
    fn refresh(&mut self) {}
    /// Whether the drawable is double-buffered (presents at SwapBuffers) or single-buffered
    /// (presents at glFlush/glFinish).
    fn double_buffered(&self) -> bool;
    /// Shows the frame: `ctx`'s colour buffer, read bottom-up as RGBA8. A window then reads its
    /// size and resizes `ctx`'s framebuffer if it changed (for the next frame).
    fn present(&mut self, ctx: &mut Context);
}

/// One context of the C APIs.
pub struct Gl {
    /// The GL state and framebuffer.
    pub ctx: Context,
    /// The surface it draws to while current, if any.
    pub surface: Option<Box<dyn Surface>>,
    /// The thread it is current on.
    pub(crate) thread: Option<ThreadId>,
    /// Destroyed while current on a thread: freed when released (EGL and GLX's rule).
    pub(crate) doomed: bool,
    /// Whether the context has been made current before: GL sets the viewport and scissor to
    /// the drawable's size at the first MakeCurrent only.
    pub(crate) bound_once: bool,
    /// `fixedgl run --record/--compare`'s output, when asked for.
    recorder: Option<crate::record::Recorder>,
    /// The program's selection and feedback buffers (address, size in values), filled from
    /// the context's own when RenderMode leaves SELECT or FEEDBACK.
    pub(crate) select_out: (usize, usize),
    pub(crate) feedback_out: (usize, usize),
}

impl Gl {
    /// A context of `width` x `height` with the buffers `config` names (a double-buffered GLX
    /// visual's context has a back buffer), or `None` when it cannot be made (the reason on
    /// stderr). It shares display lists, texture objects and buffer objects with `share` (a
    /// live handle the caller has checked), or with nothing when `share` is null.
    pub fn with_config_shared(
        width: u32,
        height: u32,
        config: ContextConfig,
        share: *mut Gl,
    ) -> Option<Gl> {
        let (w, h) = (width.max(1), height.max(1));
        let made = match share_group(share) {
            Some(group) => Context::with_config_shared(w, h, config, &group),
            None => Context::with_config(w, h, config),
        };
        let made = made.map(|mut ctx| {
            // Every framebuffer a C ABI context draws into by default is a window-system one
            // (GLX drawable, EGL surface, OSMesa buffer), which llvmpipe draws upside down
            // (Mesa's Y_0_TOP): lines with ends on pixel centres follow it there.
            ctx.set_window_system_framebuffer(true);
            ctx
        });
        match made {
            Ok(mut ctx) => Some(Gl {
                recorder: crate::record::Recorder::from_env(&mut ctx),
                ctx,
                surface: None,
                thread: None,
                doomed: false,
                bound_once: false,
                select_out: (0, 0),
                feedback_out: (0, 0),
            }),
            Err(e) => {
                eprintln!("fixedgl: cannot create a context: {e}");
                None
            }
        }
    }

    /// A NULL pointer where the command reads values: INVALID_VALUE (GL would crash).
    pub fn null_pointer(&mut self) {
        self.ctx.raise_error(gl::INVALID_VALUE);
    }

    /// Reads the surface's size again and gives the framebuffer that size if it changed (a
    /// window was resized): at MakeCurrent and glViewport. The surface's size; `None` without
    /// one. Not between Begin and End, where the batched vertices must survive.
    pub(crate) fn fit_surface(&mut self) -> Option<(u32, u32)> {
        let s = self.surface.as_mut()?;
        if self.ctx.inside_begin_end() {
            return Some(s.size());
        }
        s.refresh();
        let (w, h) = s.size();
        if self.ctx.size() != (w.max(1), h.max(1)) {
            if let Err(e) = self.ctx.resize(w.max(1), h.max(1)) {
                eprintln!("fixedgl: cannot resize the framebuffer to {w}x{h}: {e}");
            }
        }
        Some((w, h))
    }

    /// Presents to the surface if it is single-buffered (glFlush, glFinish).
    pub(crate) fn flushed(&mut self) {
        if self.surface.as_ref().is_some_and(|s| !s.double_buffered()) {
            self.present_frame();
        }
    }

    /// A frame is done (SwapBuffers, or a flush of a single-buffered drawable): recorded when
    /// `fixedgl run` asks, then shown on the surface (which may then give the framebuffer a
    /// resized window's new size, so the recording comes first).
    pub(crate) fn present_frame(&mut self) {
        if let Some(r) = self.recorder.as_mut() {
            r.presented(&mut self.ctx);
        }
        if let Some(s) = self.surface.as_mut() {
            s.present(&mut self.ctx);
        }
    }
}

/// The share group of context `share` (null: none), made now if it has none yet. A context
/// current on another thread that has no group yet cannot be given one safely (its objects are
/// in use there): the new context then shares nothing, and says so.
fn share_group(share: *mut Gl) -> Option<fixedgl::ShareGroup> {
    if !is_live(share) {
        return None;
    }
    // SAFETY: a live handle. If it is current on another thread, only its `thread` (written
    // under the C API's rules at MakeCurrent) and `ctx.share_group()`'s existing group (fixed
    // once made) are read: see below.
    let gl = unsafe { &mut *share };
    let me = std::thread::current().id();
    if gl.thread.is_some_and(|t| t != me) && !gl.ctx.is_shared() {
        if crate::say_once("share busy") {
            eprintln!("fixedgl: the share context is current on another thread and shares nothing yet; the new context gets its own display lists and textures (make the share context current here, or release it, while creating the one that shares)");
        }
        return None;
    }
    Some(gl.ctx.share_group())
}

thread_local! {
    /// The thread's current context (null: none).
    static CURRENT: Cell<*mut Gl> = const { Cell::new(std::ptr::null_mut()) };
}

/// The live contexts' addresses.
static LIVE: Mutex<Option<HashSet<usize>>> = Mutex::new(None);

fn live<R>(f: impl FnOnce(&mut HashSet<usize>) -> R) -> R {
    let mut guard = LIVE.lock().unwrap_or_else(|e| e.into_inner());
    f(guard.get_or_insert_with(HashSet::new))
}

/// Hands a new context to C: its handle.
pub(crate) fn register(gl: Gl) -> *mut Gl {
    let p = Box::into_raw(Box::new(gl));
    live(|l| l.insert(p as usize));
    p
}

/// Whether `p` is a live context handle.
pub(crate) fn is_live(p: *const Gl) -> bool {
    !p.is_null() && live(|l| l.contains(&(p as usize)))
}

/// The thread's current context handle (null: none, or the thread is exiting).
pub(crate) fn current() -> *mut Gl {
    CURRENT.try_with(Cell::get).unwrap_or(std::ptr::null_mut())
}

/// Makes `p` (a live handle, or null to release) current on this thread, with `surface` as its
/// drawable. `Err` when `p` is current on another thread (EGL_BAD_ACCESS / BadAccess).
pub(crate) fn make_current(p: *mut Gl, surface: Option<Box<dyn Surface>>) -> Result<(), ()> {
    let me = std::thread::current().id();
    if !p.is_null() {
        if !is_live(p) {
            return Err(());
        }
        // SAFETY: live handle; only the thread it is current on (none, or this one) uses it.
        let gl = unsafe { &mut *p };
        if gl.thread.is_some_and(|t| t != me) {
            return Err(());
        }
    }
    release_current();
    if p.is_null() {
        return Ok(());
    }
    // SAFETY: checked above.
    let gl = unsafe { &mut *p };
    gl.thread = Some(me);
    gl.surface = surface;
    if let Some((w, h)) = gl.fit_surface() {
        if !gl.bound_once {
            gl.ctx.viewport(0, 0, w as i32, h as i32);
            gl.ctx.scissor(0, 0, w as i32, h as i32);
        }
        gl.bound_once = true;
    }
    let _ = CURRENT.try_with(|c| c.set(p));
    Ok(())
}

/// Releases the thread's current context (freeing it if it was destroyed meanwhile).
pub(crate) fn release_current() {
    let old = current();
    if old.is_null() {
        return;
    }
    let _ = CURRENT.try_with(|c| c.set(std::ptr::null_mut()));
    // SAFETY: the current handle is live (destroy defers while current).
    let gl = unsafe { &mut *old };
    gl.thread = None;
    gl.surface = None;
    if gl.doomed {
        free(old);
    }
}

/// Destroys a context: at once, or when released if it is current on some thread.
/// `false` for a handle that is not a live context.
pub(crate) fn destroy(p: *mut Gl) -> bool {
    if !is_live(p) {
        return false;
    }
    // SAFETY: live handle.
    let gl = unsafe { &mut *p };
    if gl.thread == Some(std::thread::current().id()) {
        release_current_if(p);
        free(p);
    } else if gl.thread.is_some() {
        gl.doomed = true;
    } else {
        free(p);
    }
    true
}

fn release_current_if(p: *mut Gl) {
    if current() == p {
        let _ = CURRENT.try_with(|c| c.set(std::ptr::null_mut()));
    }
}

fn free(p: *mut Gl) {
    if live(|l| l.remove(&(p as usize))) {
        // SAFETY: made by `register`, removed from the registry just now: freed once.
        drop(unsafe { Box::from_raw(p) });
    }
}

/// Runs a GL command on the current context: nothing (and `R::default()`) without one, as GL
/// leaves such calls without effect. A panic is caught here, logged once, and raised as
/// OUT_OF_MEMORY ("the state of the GL is undefined", GL 2.1 §2.5), never unwound into C.
#[inline]
pub(crate) fn with_gl<R: Default>(name: &'static str, f: impl FnOnce(&mut Gl) -> R) -> R {
    let p = current();
    if p.is_null() {
        if crate::say_once("no current context") {
            eprintln!("fixedgl: {name} called with no current context; GL calls do nothing until one is made current");
        }
        return R::default();
    }
    // SAFETY: the current handle is live and used by this thread only.
    let gl = unsafe { &mut *p };
    match catch_unwind(AssertUnwindSafe(|| f(gl))) {
        Ok(r) => r,
        Err(_) => {
            if crate::say_once(name) {
                eprintln!("fixedgl: {name} failed inside fixedgl (a bug: please report it); raised GL_OUT_OF_MEMORY");
            }
            // SAFETY: as above; the closure's borrow ended with the unwind.
            let gl = unsafe { &mut *p };
            let _ = catch_unwind(AssertUnwindSafe(|| gl.ctx.raise_error(gl::OUT_OF_MEMORY)));
            R::default()
        }
    }
}

/// Runs a window-system entry point (egl*, glX*, OSMesa*) under `catch_unwind`: `fallback` when
/// it panics (logged once).
pub(crate) fn guard<R>(name: &'static str, fallback: R, f: impl FnOnce() -> R) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(_) => {
            if crate::say_once(name) {
                eprintln!("fixedgl: {name} failed inside fixedgl (a bug: please report it)");
            }
            fallback
        }
    }
}
