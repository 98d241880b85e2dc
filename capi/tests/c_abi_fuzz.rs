//! Random calls through the C entry points never crash the process (issue #12): every GL 1.0–1.5
//! command, with random enums and values, NULL pointers, and pointers to memory that holds what
//! the call's sizes say (GL's contract with a C caller, which the fuzzer keeps: NULL is the bad
//! pointer it covers), on contexts made through EGL (the surfaceless platform, pbuffers of random
//! sizes, no surface at all) and OSMesa (every format), switched, destroyed (also while current)
//! and released between bursts of calls; and the window-system entry points themselves with NULL
//! pointers, foreign handles and odd attributes.
//!
//! `random_c_calls_never_crash` runs 1,000,000 calls with a fixed seed in a child process (this test
//! binary again), so that a crash (a signal, an abort) is reported rather than taking the test
//! run down; a panic inside fixedgl, even one the entry point catches, a call that takes more
//! than 5 s, and a malformed `glGetString` answer fail it too. On a failure the child runs again
//! with a trace of every call, and the message names the call (command and arguments) that
//! failed and how to replay it. `--ignored` adds `random_c_calls_never_crash_long`: 4 more seeds
//! of 20,000,000 calls. `FIXEDGL_FUZZ_SEED` and `FIXEDGL_FUZZ_CALLS` change the seed and the
//! number of calls; `FIXEDGL_FUZZ_TRACE=FILE` writes each call to FILE before it is made.
//! `edge_c_calls_never_crash` makes, the same way, calls at the edges GL allows (huge sizes with
//! NULL data, huge counts and ranges with nothing to draw, extreme widths and viewports) with the
//! state that makes them bite, which random calls reach rarely; `a_crash_is_reported_with_its_call`
//! checks that a crash inside a call is caught and named.
//!
//! A call still running after 30 s aborts the child, naming it (a hang). The fuzzer compiles no
//! list calls into display lists: lists calling lists can make one call take exponential time
//! (legal GL that hangs any driver). The generated part (`c_abi_fuzz/gl_calls.rs`: each command's
//! C prototype and how its arguments are drawn) comes from gl.xml by `c_abi_fuzz/gen.rs`.

#[rustfmt::skip]
#[path = "c_abi_fuzz/gl_calls.rs"]
mod gl_calls;

use std::ffi::{c_char, c_void, CStr};
use std::fmt::Debug;
use std::io::Write as _;
use std::process::Command;
use std::ptr::{null, null_mut};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use fixedgl::gl;
use fixedgl_capi::egl::*;
use fixedgl_capi::glx::glXGetProcAddressARB;
use fixedgl_capi::osmesa::*;

/// Commands drawn more often (a third of the calls): what makes fragments reach the framebuffer
/// and the state they go through, so that random calls draw rather than mostly set state.
const FOCUS: &[&str] = &[
    "glBegin",
    "glEnd",
    "glVertex2f",
    "glVertex3fv",
    "glVertex4d",
    "glColor4ub",
    "glColor3fv",
    "glNormal3f",
    "glTexCoord2f",
    "glMultiTexCoord2f",
    "glDrawArrays",
    "glDrawElements",
    "glDrawRangeElements",
    "glArrayElement",
    "glEnableClientState",
    "glVertexPointer",
    "glColorPointer",
    "glTexCoordPointer",
    "glNormalPointer",
    "glInterleavedArrays",
    "glBindBuffer",
    "glBufferData",
    "glEnable",
    "glDisable",
    "glBindTexture",
    "glTexImage2D",
    "glTexSubImage2D",
    "glCopyTexImage2D",
    "glTexImage1D",
    "glTexImage3D",
    "glTexSubImage3D",
    "glCopyTexSubImage3D",
    "glTexParameteri",
    "glTexEnvi",
    "glBlendFunc",
    "glPolygonMode",
    "glLineWidth",
    "glPointSize",
    "glViewport",
    "glReadPixels",
    "glClear",
    "glNewList",
    "glEndList",
    "glCallList",
    "glPushAttrib",
    "glPopAttrib",
    "glLoadIdentity",
    "glOrtho",
    "glRotatef",
];

/// The seed CI uses.
const SEED: u64 = 0x5eed_0c0d_e12a_b1e5;
/// The calls CI makes (about a second).
const CALLS: u64 = 1_000_000;
/// Input memory: small integers (indices, names, counts) in the first half of the first MiB,
/// floats in [-1.5, 1.5] (with an infinity or NaN now and then) in the second half, zeros after.
/// Pointers point into the first MiB; a call may read up to 31 MiB past its pointer.
const INPUT_BYTES: usize = 32 << 20;
const SMALL_BYTES: usize = 512 << 10;
const PATTERN_BYTES: usize = 1 << 20;
/// Output memory for what GL writes, as large.
const OUTPUT_BYTES: usize = 32 << 20;
/// Pointers in the table `pointers()` hands out (MultiDrawElements' per-draw indices).
const TABLE: usize = 64;
/// A call slower than this is a failure (a loop over a huge count, a huge allocation).
const SLOW: Duration = Duration::from_secs(5);

/// A call still running after this long is a hang: the process says which and aborts.
const HANG: Duration = Duration::from_secs(30);

/// The call being made (for the panic hook and the hang watchdog): its number, its command, and
/// when it began (milliseconds since `EPOCH`).
static CALL: AtomicU64 = AtomicU64::new(0);
static CALL_COMMAND: AtomicUsize = AtomicUsize::new(0);
static CALL_START: AtomicU64 = AtomicU64::new(0);
static EPOCH: OnceLock<Instant> = OnceLock::new();

fn now_ms() -> u64 {
    EPOCH.get_or_init(Instant::now).elapsed().as_millis() as u64
}

/// Whether the current context may be compiling a display list: `GL_LIST_INDEX` is non-zero,
/// or cannot be asked (between Begin and End, where a query is an error and writes nothing).
fn compiling() -> bool {
    let mut list = -1;
    // SAFETY: one value written.
    unsafe { fixedgl_capi::manual::glGetIntegerv(0x0B33, &mut list) };
    list != 0
}

/// Aborts the process, naming the call, when one call runs longer than `HANG`; until the
/// returned guard is dropped.
fn watchdog() -> impl Drop {
    struct Stop(std::sync::Arc<std::sync::atomic::AtomicBool>);
    impl Drop for Stop {
        fn drop(&mut self) {
            self.0.store(true, Ordering::Relaxed);
        }
    }
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let stopped = stop.clone();
    std::thread::spawn(move || loop {
        std::thread::sleep(Duration::from_millis(500));
        if stopped.load(Ordering::Relaxed) {
            return;
        }
        let (call, start) = (
            CALL.load(Ordering::Relaxed),
            CALL_START.load(Ordering::Relaxed),
        );
        if now_ms().saturating_sub(start) > HANG.as_millis() as u64
            && CALL.load(Ordering::Relaxed) == call
        {
            let name = match CALL_COMMAND.load(Ordering::Relaxed) {
                usize::MAX => "an edge call",
                i => gl_calls::NAMES[i],
            };
            let _ = writeln!(
                std::io::stderr(),
                "fixedgl-fuzz: call #{call} ({name}) has run for more than {HANG:?}: a hang"
            );
            std::process::abort();
        }
    });
    Stop(stop)
}

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len())]
    }

    fn percent(&mut self, p: usize) -> bool {
        self.below(100) < p
    }
}

/// What the generated calls draw their arguments from.
pub struct Fuzz {
    rng: Rng,
    /// Whether the call's sizes must stay small (a non-null pointer, or a command that keeps
    /// something later calls read through): set by the generated code before it draws them.
    pub bounded: bool,
    input: *const u8,
    output: *mut u8,
    table: *const *const c_void,
    trace: Option<std::fs::File>,
    call: u64,
    /// FIXEDGL_FUZZ_CRASH_AT: the call at which to abort (the reporting's own test).
    crash_at: Option<u64>,
}

const SMALL: [i64; 16] = [-1, 0, 1, 2, 3, 4, 5, 7, 8, 16, 17, 31, 32, 33, 63, 64];
const HUGE: [i64; 8] = [
    i32::MAX as i64,
    i32::MIN as i64,
    1 << 16,
    1 << 20,
    1 << 24,
    -(1 << 20),
    i64::MAX,
    u32::MAX as i64,
];
const ODD: [i64; 6] = [-1000, 65535, 0x1234_5678, 255, 256, 1 << 30];
const FLOATS: [f32; 16] = [
    0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    0.25,
    10.0,
    100.0,
    -100.0,
    1e30,
    -1e30,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::NAN,
    f32::MIN_POSITIVE,
    -0.0,
];

impl Fuzz {
    /// An enum: of the parameter's group mostly, else any GL 1.x enum, a small number, or one
    /// no enum has.
    pub fn enum_(&mut self, group: &[u32]) -> u32 {
        let r = self.rng.below(100);
        if r < 60 && !group.is_empty() {
            self.rng.pick(group)
        } else if r < 85 {
            self.rng.pick(gl_calls::ENUMS_1X)
        } else if r < 93 {
            self.rng.below(16) as u32
        } else {
            self.rng
                .pick(&[u32::MAX, 0x7fff_ffff, 0x8000_0000, 0x1_0000, 0xdead_beef])
        }
    }

    /// A GLbitfield: attribute and buffer bits, all of them, or any number.
    pub fn bits(&mut self) -> u32 {
        match self.rng.below(6) {
            0 => u32::MAX,
            1 => self.rng.next() as u32,
            2 => self.rng.pick(&[
                gl::COLOR_BUFFER_BIT,
                gl::DEPTH_BUFFER_BIT,
                gl::STENCIL_BUFFER_BIT,
                gl::ACCUM_BUFFER_BIT,
                0x000f_ffff,
                0,
            ]),
            _ => 1 << self.rng.below(32),
        }
    }

    /// A GLboolean: TRUE, FALSE, or another byte.
    pub fn boolean(&mut self) -> u8 {
        self.rng.pick(&[0, 1, 1, 0, 2, 255])
    }

    /// An object or list name: small mostly.
    pub fn name(&mut self) -> u32 {
        if self.rng.percent(90) {
            self.rng.below(8) as u32
        } else {
            self.rng
                .pick(&[u32::MAX, 1000, 0x8000_0000, self.rng.0 as u32])
        }
    }

    /// An integer: a size (small, or huge when the call has no non-null pointer and keeps
    /// nothing), or any other integer (small, an enum's value, or an extreme).
    pub fn int(&mut self, size: bool) -> i64 {
        let r = self.rng.below(100);
        if self.bounded {
            self.rng.pick(&SMALL)
        } else if size {
            if r < 80 {
                self.rng.pick(&SMALL)
            } else {
                self.rng.pick(&HUGE)
            }
        } else if r < 50 {
            self.rng.pick(&SMALL)
        } else if r < 75 {
            i64::from(self.rng.pick(gl_calls::ENUMS_1X))
        } else if r < 90 {
            self.rng.pick(&HUGE)
        } else {
            self.rng.pick(&ODD)
        }
    }

    /// A float: a value lectures use, an extreme, an infinity, NaN, or any in [-2, 2].
    pub fn float(&mut self) -> f32 {
        if self.rng.percent(50) {
            self.rng.pick(&FLOATS)
        } else {
            (self.rng.next() % 4001) as f32 / 1000.0 - 2.0
        }
    }

    fn null(&mut self) -> bool {
        self.rng.percent(8)
    }

    /// Memory GL reads: NULL, or 8-aligned input memory.
    pub fn input<T>(&mut self) -> *const T {
        if self.null() {
            return null();
        }
        let at = 8 * self.rng.below(PATTERN_BYTES / 8);
        // SAFETY: within the input allocation.
        unsafe { self.input.add(at) }.cast()
    }

    /// Memory GL reads as indices (or buffer data, which may become indices): NULL, or the
    /// small integers.
    pub fn indices<T>(&mut self) -> *const T {
        if self.null() {
            return null();
        }
        let at = 8 * self.rng.below((SMALL_BYTES - (64 << 10)) / 8);
        // SAFETY: within the input allocation.
        unsafe { self.input.add(at) }.cast()
    }

    /// Memory GL writes: NULL, or 8-aligned output memory.
    pub fn output<T>(&mut self) -> *mut T {
        if self.null() {
            return null_mut();
        }
        let at = 8 * self.rng.below(PATTERN_BYTES / 8);
        // SAFETY: within the output allocation.
        unsafe { self.output.add(at) }.cast()
    }

    /// An array of pointers to indices (some NULL), or NULL.
    pub fn pointers(&mut self) -> *const *const c_void {
        if self.null() {
            null()
        } else {
            self.table
        }
    }

    /// Writes the call to the trace file, if there is one, before it is made.
    pub fn trace(&mut self, i: usize, args: &[&dyn Debug]) {
        if let Some(f) = self.trace.as_mut() {
            let _ = writeln!(f, "#{} {}{:?}", self.call, gl_calls::NAMES[i], args);
        }
        if self.crash_at == Some(self.call) {
            // `a_crash_is_reported_with_its_call`: a crash inside this call, as fixedgl's would be.
            std::process::abort();
        }
    }

    /// `glGetString`'s answer: NULL, or a NUL-terminated string of printable ASCII.
    pub fn string(&mut self, p: *const u8) {
        if p.is_null() {
            return;
        }
        // SAFETY: GL returns a static NUL-terminated string.
        let s = unsafe { CStr::from_ptr(p.cast::<c_char>()) };
        assert!(
            s.to_bytes().len() < 1 << 16 && s.to_bytes().iter().all(|b| (32..127).contains(b)),
            "glGetString returned {s:?}"
        );
    }

    fn trace_line(&mut self, line: std::fmt::Arguments) {
        if let Some(f) = self.trace.as_mut() {
            let _ = writeln!(f, "#{} {line}", self.call);
        }
    }
}

/// Memory that lives as long as the process: GL keeps pointers (client arrays, selection and
/// feedback buffers) that later calls use.
fn memory() -> (*const u8, *mut u8, *const *const c_void) {
    let mut input = vec![0u8; INPUT_BYTES];
    let mut rng = Rng(0x1234);
    for (k, w) in input[..SMALL_BYTES].chunks_exact_mut(4).enumerate() {
        w.copy_from_slice(&((k % 8) as u32).to_le_bytes());
    }
    for w in input[SMALL_BYTES..PATTERN_BYTES].chunks_exact_mut(4) {
        let v = if rng.below(64) == 0 {
            rng.pick(&[f32::INFINITY, f32::NAN, 1e30, -1e30])
        } else {
            (rng.next() % 3001) as f32 / 1000.0 - 1.5
        };
        w.copy_from_slice(&v.to_le_bytes());
    }
    let input: &'static mut [u8] = input.leak();
    let output: &'static mut [u8] = vec![0u8; OUTPUT_BYTES].leak();
    let table: Vec<*const c_void> = (0..TABLE)
        .map(|k| {
            if k % 16 == 15 {
                null()
            } else {
                input[8 * k * 97..].as_ptr().cast()
            }
        })
        .collect();
    let table: &'static [*const c_void] = table.leak();
    (input.as_ptr(), output.as_mut_ptr(), table.as_ptr())
}

const EGL_NONE: i32 = 0x3038;
const EGL_WIDTH: i32 = 0x3057;
const EGL_HEIGHT: i32 = 0x3056;
const OSMESA_FORMATS: [(u32, usize, u32); 6] = [
    (gl::RGBA, 4, gl::UNSIGNED_BYTE),
    (0x1, 4, gl::UNSIGNED_BYTE),        // BGRA
    (0x2, 4, gl::UNSIGNED_BYTE),        // ARGB
    (gl::RGB, 3, gl::UNSIGNED_BYTE),    // RGB
    (0x4, 3, gl::UNSIGNED_BYTE),        // BGR
    (0x5, 2, gl::UNSIGNED_SHORT_5_6_5), // RGB_565
];

/// A context the fuzzer made.
enum Ctx {
    Egl {
        ctx: *mut c_void,
        /// NULL: current without a surface (EGL_KHR_surfaceless_context).
        surface: *mut c_void,
    },
    Os {
        ctx: *mut c_void,
        buffer: Vec<u8>,
        ty: u32,
        size: (i32, i32),
    },
}

struct Contexts {
    dpy: *mut c_void,
    config: *mut c_void,
    live: Vec<Ctx>,
    current: Option<usize>,
    /// OSMesa buffers of contexts destroyed while current, kept until the next switch.
    graveyard: Vec<Vec<u8>>,
}

impl Contexts {
    fn new() -> Contexts {
        // SAFETY: the EGL calls as EGL documents them, with valid pointers.
        unsafe {
            let dpy = eglGetPlatformDisplay(0x31DD, null_mut(), null());
            assert!(!dpy.is_null(), "eglGetPlatformDisplay(SURFACELESS)");
            assert_eq!(eglInitialize(dpy, null_mut(), null_mut()), 1);
            assert_eq!(eglBindAPI(0x30A2), 1);
            let attribs = [0x3033, 1, 0x3040, 8, EGL_NONE];
            let mut config = null_mut();
            let mut n = 0;
            assert_eq!(
                eglChooseConfig(dpy, attribs.as_ptr(), &mut config, 1, &mut n),
                1
            );
            assert_eq!(n, 1);
            Contexts {
                dpy,
                config,
                live: Vec::new(),
                current: None,
                graveyard: Vec::new(),
            }
        }
    }

    fn pbuffer(&self, w: i32, h: i32) -> *mut c_void {
        let attribs = [EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE];
        // SAFETY: a valid attribute list.
        let s = unsafe { eglCreatePbufferSurface(self.dpy, self.config, attribs.as_ptr()) };
        assert!(!s.is_null(), "eglCreatePbufferSurface {w}x{h}");
        s
    }

    fn make_current(&mut self, i: Option<usize>) {
        self.graveyard.clear();
        match i.map(|i| &mut self.live[i]) {
            None => {
                assert_eq!(
                    eglMakeCurrent(self.dpy, null_mut(), null_mut(), null_mut()),
                    1
                );
                OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0);
            }
            Some(Ctx::Egl { ctx, surface }) => {
                assert_eq!(eglMakeCurrent(self.dpy, *surface, *surface, *ctx), 1);
            }
            Some(Ctx::Os {
                ctx,
                buffer,
                ty,
                size,
            }) => {
                let ok = OSMesaMakeCurrent(*ctx, buffer.as_mut_ptr().cast(), *ty, size.0, size.1);
                assert_eq!(ok, 1, "OSMesaMakeCurrent");
            }
        }
        self.current = i;
    }

    fn create(&mut self, r: &mut Rng, f: &mut Fuzz) {
        let (w, h) = (1 + r.below(64) as i32, 1 + r.below(64) as i32);
        let c = if r.percent(50) {
            let attribs = [0x3098, 1, 0x30FB, r.below(6) as i32, EGL_NONE];
            // SAFETY: a valid attribute list.
            let ctx =
                unsafe { eglCreateContext(self.dpy, self.config, null_mut(), attribs.as_ptr()) };
            assert!(!ctx.is_null(), "eglCreateContext");
            let surface = if r.percent(80) {
                self.pbuffer(w, h)
            } else {
                null_mut()
            };
            f.trace_line(format_args!(
                "create EGL context, surface {w}x{h} ({surface:?})"
            ));
            Ctx::Egl { ctx, surface }
        } else {
            let (format, bpp, ty) = r.pick(&OSMESA_FORMATS);
            let ctx = OSMesaCreateContextExt(format, 24, 8, 0, null_mut());
            assert!(!ctx.is_null(), "OSMesaCreateContextExt({format:#x})");
            f.trace_line(format_args!("create OSMesa context {format:#x} {w}x{h}"));
            Ctx::Os {
                ctx,
                buffer: vec![0; w as usize * h as usize * bpp],
                ty,
                size: (w, h),
            }
        };
        self.live.push(c);
        self.make_current(Some(self.live.len() - 1));
    }

    fn destroy(&mut self, i: usize, release_first: bool) {
        if release_first && self.current == Some(i) {
            self.make_current(None);
        }
        let c = self.live.remove(i);
        match c {
            Ctx::Egl { ctx, surface } => {
                assert_eq!(eglDestroyContext(self.dpy, ctx), 1);
                if !surface.is_null() {
                    assert_eq!(eglDestroySurface(self.dpy, surface), 1);
                }
            }
            Ctx::Os { ctx, buffer, .. } => {
                OSMesaDestroyContext(ctx);
                self.graveyard.push(buffer);
            }
        }
        self.current = match self.current {
            Some(c) if c == i => None,
            Some(c) if c > i => Some(c - 1),
            other => other,
        };
    }

    /// Something that changes which context the calls go to.
    fn shuffle(&mut self, r: &mut Rng, f: &mut Fuzz) {
        let n = self.live.len();
        match r.below(100) {
            _ if n == 0 => self.create(r, f),
            0..=39 => {
                let i = r.below(n);
                f.trace_line(format_args!("make context {i} current"));
                self.make_current(Some(i));
            }
            40..=54 if n < 4 => self.create(r, f),
            40..=64 => {
                // Destroyed while current (EGL defers it, OSMesa frees it) or after release.
                let i = r.below(n);
                let release = r.percent(50);
                f.trace_line(format_args!(
                    "destroy context {i} (released first: {release})"
                ));
                self.destroy(i, release);
            }
            65..=74 => {
                f.trace_line(format_args!("release the current context"));
                self.make_current(None);
            }
            75..=84 => {
                // The current EGL context onto a new pbuffer of another size.
                if let Some(i) = self.current {
                    let (w, h) = (1 + r.below(64) as i32, 1 + r.below(64) as i32);
                    if let Ctx::Egl { surface, .. } = self.live[i] {
                        let new = self.pbuffer(w, h);
                        f.trace_line(format_args!("context {i} onto a {w}x{h} pbuffer"));
                        if let Ctx::Egl { surface: s, .. } = &mut self.live[i] {
                            *s = new;
                        }
                        self.make_current(Some(i));
                        if !surface.is_null() {
                            assert_eq!(eglDestroySurface(self.dpy, surface), 1);
                        }
                    }
                }
            }
            _ => {
                let calls = 1 + r.below(12);
                for _ in 0..calls {
                    window_system_call(self, r, f);
                }
                // Whatever those did to the current context, back to the fuzzer's.
                let cur = self.current;
                self.make_current(cur);
            }
        }
    }

    fn close(&mut self) {
        while !self.live.is_empty() {
            self.destroy(0, true);
        }
        assert_eq!(eglTerminate(self.dpy), 1);
    }
}

/// A window-system entry point with NULL pointers, foreign handles and odd values.
fn window_system_call(cx: &mut Contexts, r: &mut Rng, f: &mut Fuzz) {
    static FOREIGN: [u64; 4] = [0; 4];
    let foreign = FOREIGN.as_ptr() as *mut c_void;
    let handle = |r: &mut Rng, real: *mut c_void| -> *mut c_void {
        r.pick(&[real, real, null_mut(), foreign, 1usize as *mut c_void])
    };
    let ctx_handle = |r: &mut Rng, cx: &Contexts| -> *mut c_void {
        match cx.live.get(r.below(cx.live.len() + 1)) {
            Some(Ctx::Egl { ctx, .. }) | Some(Ctx::Os { ctx, .. }) => *ctx,
            None => r.pick(&[null_mut(), foreign]),
        }
    };
    let surface_handle = |r: &mut Rng, cx: &Contexts| -> *mut c_void {
        match cx.live.get(r.below(cx.live.len() + 1)) {
            Some(Ctx::Egl { surface, .. }) => *surface,
            _ => r.pick(&[null_mut(), foreign]),
        }
    };
    let value = |r: &mut Rng| -> i32 {
        r.pick(&[
            0x3020,
            0x3025,
            0x3026,
            0x3028,
            0x3033,
            0x3040,
            0x3056,
            0x3057,
            0x3098,
            0x30FB,
            0x30FD,
            0x3097,
            0x3086,
            0x3038,
            0,
            -1,
            1,
            64,
            0x7fff_ffff,
        ])
    };
    let mut out = [0i32; 64];
    let mut handles = [null_mut::<c_void>(); 8];
    let outp = |r: &mut Rng, out: &mut [i32; 64]| -> *mut i32 {
        if r.percent(30) {
            null_mut()
        } else {
            out.as_mut_ptr()
        }
    };
    // An attribute list: pairs of odd values, EGL_NONE-terminated (the API's contract).
    let mut attribs = [EGL_NONE; 9];
    for k in 0..r.below(4) {
        attribs[2 * k] = value(r);
        attribs[2 * k + 1] = value(r);
    }
    let attribs_p = if r.percent(20) {
        null()
    } else {
        attribs.as_ptr()
    };
    let names: [&CStr; 6] = [
        c"glBegin",
        c"glTexImage3D",
        c"eglGetPlatformDisplay",
        c"",
        c"glFooBar",
        c"OSMesaGetColorBuffer",
    ];
    let name = |r: &mut Rng| -> *const c_char {
        if r.percent(20) {
            null()
        } else {
            r.pick(&names).as_ptr()
        }
    };
    let which = r.below(24);
    f.trace_line(format_args!("window-system call {which}"));
    let dpy = handle(r, cx.dpy);
    let cfg = handle(r, cx.config);
    // SAFETY: each call with NULL or valid pointers to what it reads or writes, and handles that
    // are the APIs' to check (EGL refuses foreign ones); OSMesa calls get its own contexts.
    unsafe {
        match which {
            0 => {
                let _ = eglQueryString(dpy, value(r));
            }
            1 => {
                let _ = eglGetConfigAttrib(dpy, cfg, value(r), outp(r, &mut out));
            }
            2 => {
                let hp = if r.percent(30) {
                    null_mut()
                } else {
                    handles.as_mut_ptr()
                };
                let _ = eglGetConfigs(dpy, hp, r.pick(&[0, 1, 8, -1]), outp(r, &mut out));
            }
            3 => {
                let hp = if r.percent(30) {
                    null_mut()
                } else {
                    handles.as_mut_ptr()
                };
                let _ = eglChooseConfig(
                    dpy,
                    attribs_p,
                    hp,
                    r.pick(&[0, 1, 8, -1]),
                    outp(r, &mut out),
                );
            }
            4 => {
                let _ = eglQuerySurface(dpy, surface_handle(r, cx), value(r), outp(r, &mut out));
            }
            5 => {
                let _ = eglQueryContext(dpy, ctx_handle(r, cx), value(r), outp(r, &mut out));
            }
            6 => {
                let _ = (
                    eglGetCurrentContext(),
                    eglGetCurrentDisplay(),
                    eglQueryAPI(),
                );
                let _ = eglGetCurrentSurface(value(r));
                let _ = eglGetError();
            }
            7 => {
                let _ = eglBindAPI(r.pick(&[0x30A2, 0x30A0, 0x30A1, 0, u32::MAX]));
                let _ = eglBindAPI(0x30A2);
            }
            8 => {
                let _ = eglSwapBuffers(dpy, surface_handle(r, cx));
                let _ = eglSwapInterval(dpy, value(r));
            }
            9 => {
                let _ = (eglWaitClient(), eglWaitGL(), eglWaitNative(value(r)));
            }
            10 => {
                let _ = eglGetProcAddress(name(r));
                let _ = glXGetProcAddressARB(name(r));
                let _ = OSMesaGetProcAddress(name(r));
            }
            11 => {
                let s = eglCreatePbufferSurface(dpy, cfg, attribs_p);
                if !s.is_null() {
                    assert_eq!(eglDestroySurface(cx.dpy, s), 1);
                }
            }
            12 => {
                let share = ctx_handle(r, cx);
                let c = eglCreateContext(dpy, cfg, share, attribs_p);
                if !c.is_null() {
                    assert_eq!(eglDestroyContext(cx.dpy, c), 1);
                }
            }
            13 => {
                // Foreign handles: refused, nothing made current.
                let _ = eglMakeCurrent(
                    dpy,
                    r.pick(&[foreign, null_mut()]),
                    r.pick(&[foreign, null_mut()]),
                    foreign,
                );
            }
            14 => {
                let _ = eglDestroySurface(dpy, r.pick(&[foreign, null_mut()]));
                let _ = eglDestroyContext(dpy, r.pick(&[foreign, null_mut()]));
            }
            15 => {
                let _ = eglInitialize(
                    r.pick(&[foreign, null_mut()]),
                    outp(r, &mut out),
                    null_mut(),
                );
                let _ = eglTerminate(r.pick(&[foreign, null_mut()]));
                let _ = eglInitialize(cx.dpy, outp(r, &mut out), outp(r, &mut out));
            }
            16 => {
                let _ = eglGetDisplay(r.pick(&[null_mut(), foreign]));
                let _ = eglGetPlatformDisplay(
                    r.pick(&[0x31DD, 0x31D5, 0, u32::MAX]),
                    null_mut(),
                    null(),
                );
            }
            17 => {
                OSMesaGetIntegerv(
                    r.pick(&[0x20, 0x21, 0x22, 0x23, 0x24, 0x25, 0, -1]),
                    outp(r, &mut out),
                );
            }
            18 => {
                let p = |r: &mut Rng, out: &mut [i32; 64]| -> *mut i32 {
                    if r.percent(30) {
                        null_mut()
                    } else {
                        out.as_mut_ptr()
                    }
                };
                let mut buf = null_mut();
                let bp = if r.percent(30) {
                    null_mut()
                } else {
                    &mut buf as *mut _
                };
                let c = ctx_handle(r, cx);
                let mut a = [0i32; 64];
                let mut b = [0i32; 64];
                let _ = OSMesaGetColorBuffer(c, p(r, &mut out), p(r, &mut a), p(r, &mut b), bp);
                let _ = OSMesaGetDepthBuffer(c, p(r, &mut out), p(r, &mut a), p(r, &mut b), bp);
            }
            19 => {
                // Y_UP, or ROW_LENGTH no longer than the buffer's rows (the API's contract).
                if r.percent(50) {
                    OSMesaPixelStore(0x11, r.pick(&[0, 1, 2, -1]));
                } else {
                    OSMesaPixelStore(0x10, 0);
                }
                OSMesaPixelStore(r.pick(&[0x12, 0, -1, 0x20]), r.pick(&[0, 1, 1 << 20]));
            }
            20 => {
                let _ = OSMesaGetCurrentContext();
                // NULL buffer: refused.
                let c = ctx_handle(r, cx);
                if !c.is_null() && c != foreign {
                    let _ = OSMesaMakeCurrent(c, null_mut(), gl::UNSIGNED_BYTE, 4, 4);
                }
            }
            21 => {
                let mut list = [0i32; 9];
                for k in 0..r.below(4) {
                    list[2 * k] = r.pick(&[0x22, 0x30, 0x31, 0x32, 0x33, 0x36, 0x37, 0x99, -1]);
                    list[2 * k + 1] = r.pick(&[0, 1, 2, 5, 0x34, 0x1908, -1]);
                }
                let lp = if r.percent(20) { null() } else { list.as_ptr() };
                let c = OSMesaCreateContextAttribs(lp, null_mut());
                if !c.is_null() {
                    OSMesaDestroyContext(c);
                }
            }
            22 => {
                let c = OSMesaCreateContextExt(
                    r.pick(&[
                        gl::RGBA,
                        0x1,
                        0x2,
                        gl::RGB,
                        0x4,
                        0x5,
                        0,
                        gl::LUMINANCE,
                        u32::MAX,
                    ]),
                    r.pick(&[0, 16, 24, 32, -1]),
                    r.pick(&[0, 8, -1]),
                    r.pick(&[0, 16, -1]),
                    null_mut(),
                );
                if !c.is_null() {
                    OSMesaDestroyContext(c);
                }
            }
            _ => {
                // The GL entry points reached through GetProcAddress are the exported ones.
                let p = eglGetProcAddress(c"glGetError".as_ptr());
                if !p.is_null() {
                    let get_error: extern "C" fn() -> u32 = std::mem::transmute(p);
                    let _ = get_error();
                }
            }
        }
    }
}

/// Calls at the edges GL allows (huge sizes with NULL data, huge counts with nothing to draw,
/// huge ranges, extreme widths and viewports), each traced as `#N edge: <call>`, on an EGL
/// pbuffer context and on an OSMesa one. The random calls reach these rarely with the state
/// that makes them bite (a bound buffer, enabled arrays), so they are also made on purpose.
fn edge_calls(f: &mut Fuzz) {
    use gl_calls::*;
    type Edge = (&'static str, unsafe fn());
    let edges: &[Edge] = &[
        ("glBindBuffer(ARRAY_BUFFER, 1); glBufferData(ARRAY_BUFFER, isize::MAX, NULL, STATIC_DRAW)", || unsafe {
            glBindBuffer(gl::ARRAY_BUFFER, 1);
            glBufferData(gl::ARRAY_BUFFER, isize::MAX, null(), gl::STATIC_DRAW);
        }),
        ("glBufferData(ARRAY_BUFFER, 1 << 40, NULL, STATIC_DRAW)", || unsafe {
            glBindBuffer(gl::ARRAY_BUFFER, 1);
            glBufferData(gl::ARRAY_BUFFER, 1 << 40, null(), gl::STATIC_DRAW);
        }),
        ("glBufferData(ARRAY_BUFFER, -1, NULL, STATIC_DRAW)", || unsafe {
            glBufferData(gl::ARRAY_BUFFER, -1, null(), gl::STATIC_DRAW);
        }),
        ("glBufferSubData(ARRAY_BUFFER, isize::MAX, 16, NULL)", || unsafe {
            glBufferData(gl::ARRAY_BUFFER, 64, null(), gl::STATIC_DRAW);
            glBufferSubData(gl::ARRAY_BUFFER, isize::MAX, 16, null());
            glBufferSubData(gl::ARRAY_BUFFER, 60, isize::MAX, null());
        }),
        ("glGetBufferSubData(ARRAY_BUFFER, 1 << 40, isize::MAX, NULL)", || unsafe {
            glGetBufferSubData(gl::ARRAY_BUFFER, 1 << 40, isize::MAX, null_mut());
        }),
        ("glTexImage2D(TEXTURE_2D, 0, RGBA, 2048, 2048, 0, RGBA, FLOAT, NULL)", || unsafe {
            glTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA as i32, 2048, 2048, 0, gl::RGBA, gl::FLOAT, null());
        }),
        ("glTexImage2D(TEXTURE_2D, 0, RGBA, i32::MAX, i32::MAX, 0, RGBA, UNSIGNED_BYTE, NULL)", || unsafe {
            glTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA as i32, i32::MAX, i32::MAX, 0, gl::RGBA, gl::UNSIGNED_BYTE, null());
        }),
        ("glPixelStorei(UNPACK_ROW_LENGTH/SKIP_ROWS/SKIP_PIXELS, i32::MAX); glTexImage2D(.., 4, 4, .., NULL)", || unsafe {
            for p in [gl::UNPACK_ROW_LENGTH, gl::UNPACK_SKIP_ROWS, gl::UNPACK_SKIP_PIXELS] {
                glPixelStorei(p, i32::MAX);
            }
            glTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA as i32, 4, 4, 0, gl::RGBA, gl::UNSIGNED_BYTE, null());
            glTexSubImage2D(gl::TEXTURE_2D, 0, 0, 0, 4, 4, gl::RGBA, gl::UNSIGNED_BYTE, null());
            for p in [gl::UNPACK_ROW_LENGTH, gl::UNPACK_SKIP_ROWS, gl::UNPACK_SKIP_PIXELS] {
                glPixelStorei(p, 0);
            }
        }),
        ("glPixelStorei(PACK_ROW_LENGTH/SKIP_*, i32::MAX); glReadPixels(0, 0, 4, 4, .., NULL); glGetTexImage(.., NULL)", || unsafe {
            for p in [gl::PACK_ROW_LENGTH, gl::PACK_SKIP_ROWS, gl::PACK_SKIP_PIXELS] {
                glPixelStorei(p, i32::MAX);
            }
            glReadPixels(0, 0, 4, 4, gl::RGBA, gl::UNSIGNED_BYTE, null_mut());
            glGetTexImage(gl::TEXTURE_2D, 0, gl::RGBA, gl::FLOAT, null_mut());
            for p in [gl::PACK_ROW_LENGTH, gl::PACK_SKIP_ROWS, gl::PACK_SKIP_PIXELS] {
                glPixelStorei(p, 0);
            }
        }),
        ("glTexImage3D(TEXTURE_3D, 0, RGBA, 2048, 2048, 2048, 0, RGBA, FLOAT, NULL); i32::MAX sizes", || unsafe {
            glTexImage3D(gl::TEXTURE_3D, 0, gl::RGBA as i32, 2048, 2048, 2048, 0, gl::RGBA, gl::FLOAT, null());
            glTexImage3D(gl::TEXTURE_3D, 0, gl::RGBA as i32, i32::MAX, i32::MAX, i32::MAX, 0, gl::RGBA, gl::UNSIGNED_BYTE, null());
            glTexImage1D(gl::TEXTURE_1D, 0, gl::RGBA as i32, i32::MAX, 0, gl::RGBA, gl::UNSIGNED_BYTE, null());
        }),
        ("glPixelStorei(UNPACK_IMAGE_HEIGHT/SKIP_IMAGES, i32::MAX); glTexImage3D(.., 4, 4, 4, .., NULL)", || unsafe {
            for p in [gl::UNPACK_IMAGE_HEIGHT, gl::UNPACK_SKIP_IMAGES] {
                glPixelStorei(p, i32::MAX);
            }
            glTexImage3D(gl::TEXTURE_3D, 0, gl::RGBA as i32, 4, 4, 4, 0, gl::RGBA, gl::UNSIGNED_BYTE, null());
            glTexSubImage3D(gl::TEXTURE_3D, 0, 0, 0, 0, 4, 4, 4, gl::RGBA, gl::UNSIGNED_BYTE, null());
            glCopyTexSubImage3D(gl::TEXTURE_3D, 0, 0, 0, 0, i32::MAX, i32::MAX, 4, 4);
            for p in [gl::UNPACK_IMAGE_HEIGHT, gl::UNPACK_SKIP_IMAGES] {
                glPixelStorei(p, 0);
            }
        }),
        ("glReadPixels(i32::MIN, i32::MIN, i32::MAX, i32::MAX, RGBA, FLOAT, NULL)", || unsafe {
            glReadPixels(i32::MIN, i32::MIN, i32::MAX, i32::MAX, gl::RGBA, gl::FLOAT, null_mut());
        }),
        ("glCopyTexImage2D(TEXTURE_2D, 0, RGBA, i32::MIN, i32::MIN, 2048, 2048, 0)", || unsafe {
            glCopyTexImage2D(gl::TEXTURE_2D, 0, gl::RGBA, i32::MIN, i32::MIN, 2048, 2048, 0);
            glCopyTexSubImage2D(gl::TEXTURE_2D, 0, 0, 0, i32::MAX, i32::MAX, 2048, 2048);
        }),
        ("glGenLists(i32::MAX); glDeleteLists(1, i32::MAX); glDeleteLists(u32::MAX, i32::MAX)", || unsafe {
            let _ = glGenLists(i32::MAX);
            glDeleteLists(1, i32::MAX);
            glDeleteLists(u32::MAX, i32::MAX);
        }),
        ("glCallLists(i32::MAX, UNSIGNED_INT, NULL); glCallLists(3, 0x1409 (4_BYTES), NULL)", || unsafe {
            glCallLists(i32::MAX, gl::UNSIGNED_INT, null());
            glCallLists(3, 0x1409, null());
        }),
        ("glListBase(u32::MAX); glCallList(u32::MAX); glNewList(u32::MAX, COMPILE)", || unsafe {
            glListBase(u32::MAX);
            let lists = [1u32, 2, 3];
            glCallLists(3, gl::UNSIGNED_INT, lists.as_ptr().cast());
            glListBase(0);
            glCallList(u32::MAX);
            glNewList(u32::MAX, gl::COMPILE);
            glEndList();
        }),
        ("glDrawArrays(POINTS, 0, i32::MAX) with no array enabled, then with a NULL vertex array", || unsafe {
            glDisableClientState(gl::VERTEX_ARRAY);
            glDrawArrays(gl::POINTS, 0, i32::MAX);
            glDrawArrays(gl::POINTS, i32::MAX, i32::MAX);
            glBindBuffer(gl::ARRAY_BUFFER, 0);
            glVertexPointer(3, gl::FLOAT, 0, null());
            glEnableClientState(gl::VERTEX_ARRAY);
            glDrawArrays(gl::TRIANGLES, 0, 3);
            glDrawArrays(gl::TRIANGLES, i32::MAX - 1, 3);
            glArrayElement(i32::MAX);
            glDisableClientState(gl::VERTEX_ARRAY);
        }),
        ("glDrawElements(TRIANGLES, i32::MAX, UNSIGNED_INT, NULL), with and without an element buffer", || unsafe {
            glDrawElements(gl::TRIANGLES, i32::MAX, gl::UNSIGNED_INT, null());
            glBindBuffer(gl::ELEMENT_ARRAY_BUFFER, 2);
            glBufferData(gl::ELEMENT_ARRAY_BUFFER, 12, null(), gl::STATIC_DRAW);
            glDrawElements(gl::TRIANGLES, i32::MAX, gl::UNSIGNED_INT, null());
            glDrawElements(gl::TRIANGLES, 3, gl::UNSIGNED_INT, usize::MAX as *const c_void);
            glDrawRangeElements(gl::TRIANGLES, 0, u32::MAX, 3, gl::UNSIGNED_INT, (usize::MAX - 3) as *const c_void);
            glBindBuffer(gl::ELEMENT_ARRAY_BUFFER, 0);
        }),
        ("a vertex array in a buffer object at offset usize::MAX - 8, drawn", || unsafe {
            glBindBuffer(gl::ARRAY_BUFFER, 3);
            glBufferData(gl::ARRAY_BUFFER, 36, null(), gl::STATIC_DRAW);
            glVertexPointer(3, gl::FLOAT, i32::MAX, (usize::MAX - 8) as *const c_void);
            glVertexPointer(3, gl::FLOAT, 2048, (usize::MAX - 8) as *const c_void);
            glEnableClientState(gl::VERTEX_ARRAY);
            glDrawArrays(gl::TRIANGLES, 0, 3);
            glDisableClientState(gl::VERTEX_ARRAY);
            glBindBuffer(gl::ARRAY_BUFFER, 0);
        }),
        ("glInterleavedArrays(T2F_C4F_N3F_V3F, -1 / i32::MAX, NULL); glDrawArrays", || unsafe {
            glInterleavedArrays(gl::T2F_C4F_N3F_V3F, -1, null());
            glInterleavedArrays(gl::T2F_C4F_N3F_V3F, i32::MAX, null());
            glInterleavedArrays(gl::T2F_C4F_N3F_V3F, 0, null());
            glDrawArrays(gl::TRIANGLES, 0, 3);
            for c in [gl::VERTEX_ARRAY, gl::NORMAL_ARRAY, gl::COLOR_ARRAY, gl::TEXTURE_COORD_ARRAY] {
                glDisableClientState(c);
            }
        }),
        ("glLineWidth(1e30); glPointSize(1e30); a line, a point and a wide-line triangle", || unsafe {
            glLineWidth(1e30);
            glPointSize(1e30);
            glPolygonMode(gl::FRONT_AND_BACK, gl::LINE);
            glBegin(gl::LINES);
            glVertex2f(-1.0, -1.0);
            glVertex2f(1.0, 1.0);
            glEnd();
            glBegin(gl::POINTS);
            glVertex2f(0.0, 0.0);
            glEnd();
            glBegin(gl::TRIANGLES);
            glVertex2f(-1.0, -1.0);
            glVertex2f(1.0, -1.0);
            glVertex2f(0.0, 1.0);
            glEnd();
            glPolygonMode(gl::FRONT_AND_BACK, gl::FILL);
            glLineWidth(1.0);
            glPointSize(1.0);
        }),
        ("glViewport(i32::MIN/2, i32::MIN/2, i32::MAX, i32::MAX); glDepthRange(NaN, inf); a triangle", || unsafe {
            glViewport(i32::MIN / 2, i32::MIN / 2, i32::MAX, i32::MAX);
            glDepthRange(f64::NAN, f64::INFINITY);
            glBegin(gl::TRIANGLES);
            glVertex3f(-1e30, -1e30, 0.0);
            glVertex3f(1e30, -1.0, f32::NAN);
            glVertex3f(0.0, f32::INFINITY, 0.0);
            glEnd();
            glViewport(0, 0, 16, 16);
            glDepthRange(0.0, 1.0);
        }),
        ("glScissor(i32::MIN, i32::MIN, i32::MAX, i32::MAX); glClear(all)", || unsafe {
            glEnable(gl::SCISSOR_TEST);
            glScissor(i32::MIN, i32::MIN, i32::MAX, i32::MAX);
            glClear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
            glScissor(i32::MAX, i32::MAX, i32::MAX, i32::MAX);
            glClear(gl::COLOR_BUFFER_BIT);
            glDisable(gl::SCISSOR_TEST);
        }),
        ("glGetPointerv / glGetIntegerv / glGetString / glGetTexLevelParameteriv with NULL", || unsafe {
            glGetPointerv(gl::VERTEX_ARRAY_POINTER, null_mut());
            glGetIntegerv(gl::VIEWPORT, null_mut());
            glGetFloatv(gl::MODELVIEW_MATRIX, null_mut());
            glGetDoublev(gl::PROJECTION_MATRIX, null_mut());
            glGetBooleanv(gl::COLOR_WRITEMASK, null_mut());
            glGetTexLevelParameteriv(gl::TEXTURE_2D, 0, gl::TEXTURE_WIDTH, null_mut());
            glGetLightfv(gl::LIGHT0, gl::POSITION, null_mut());
            glGetClipPlane(gl::CLIP_PLANE0, null_mut());
            glGenTextures(i32::MAX, null_mut());
            glDeleteTextures(i32::MAX, null());
            glGenBuffers(i32::MAX, null_mut());
            glDeleteBuffers(i32::MAX, null());
            for name in [0, gl::VENDOR, gl::RENDERER, gl::VERSION, gl::EXTENSIONS, u32::MAX] {
                let _ = glGetString(name);
            }
        }),
        ("glSelectBuffer(i32::MAX, NULL); glRenderMode(SELECT); glFeedbackBuffer(i32::MAX, 3D, NULL); glRenderMode(FEEDBACK)", || unsafe {
            glSelectBuffer(i32::MAX, null_mut());
            let _ = glRenderMode(gl::SELECT);
            glBegin(gl::TRIANGLES);
            glVertex2f(0.0, 0.0);
            glVertex2f(1.0, 0.0);
            glVertex2f(0.0, 1.0);
            glEnd();
            let _ = glRenderMode(gl::RENDER);
            glFeedbackBuffer(i32::MAX, 0x0601 /* GL_3D */, null_mut());
            let _ = glRenderMode(gl::FEEDBACK);
            glBegin(gl::POINTS);
            glVertex2f(0.0, 0.0);
            glEnd();
            let _ = glRenderMode(gl::RENDER);
        }),
        ("glMap1f/glMap2f with huge orders and NULL points; glEvalMesh2 over a huge grid of none", || unsafe {
            glMap1f(0x0D97, 0.0, 1.0, i32::MAX, i32::MAX, null());
            glMap2f(0x0DB7, 0.0, 1.0, i32::MAX, i32::MAX, 0.0, 1.0, i32::MAX, i32::MAX, null());
            glMapGrid2f(i32::MAX, 0.0, 1.0, i32::MAX, 0.0, 1.0);
        }),
        ("glBitmap(i32::MAX, i32::MAX, .., NULL); glDrawPixels(i32::MAX, i32::MAX, .., NULL); glCopyPixels(huge)", || unsafe {
            glBitmap(i32::MAX, i32::MAX, 0.0, 0.0, 1e30, 1e30, null());
            glDrawPixels(i32::MAX, i32::MAX, gl::RGBA, gl::FLOAT, null());
            glCopyPixels(i32::MIN, i32::MIN, i32::MAX, i32::MAX, gl::COLOR);
            glPolygonStipple(null());
            glGetPolygonStipple(null_mut());
        }),
        ("glPushAttrib(ALL) / glPushClientAttrib(ALL) 100 times, then 100 pops, then another pop", || unsafe {
            for _ in 0..100 {
                glPushAttrib(u32::MAX);
                glPushClientAttrib(u32::MAX);
                glPushMatrix();
            }
            for _ in 0..101 {
                glPopAttrib();
                glPopClientAttrib();
                glPopMatrix();
            }
        }),
    ];
    let mut cx = Contexts::new();
    for kind in 0..2 {
        let (w, h) = (16, 16);
        if kind == 0 {
            // SAFETY: a valid attribute list.
            let ctx = unsafe { eglCreateContext(cx.dpy, cx.config, null_mut(), null()) };
            let surface = cx.pbuffer(w, h);
            cx.live.push(Ctx::Egl { ctx, surface });
        } else {
            let ctx = OSMesaCreateContextExt(gl::RGBA, 24, 8, 0, null_mut());
            cx.live.push(Ctx::Os {
                ctx,
                buffer: vec![0; (w * h * 4) as usize],
                ty: gl::UNSIGNED_BYTE,
                size: (w, h),
            });
        }
        cx.make_current(Some(cx.live.len() - 1));
        for (k, (what, call)) in edges.iter().enumerate() {
            f.call = (kind * edges.len() + k) as u64;
            CALL.store(f.call, Ordering::Relaxed);
            CALL_COMMAND.store(usize::MAX, Ordering::Relaxed);
            CALL_START.store(now_ms(), Ordering::Relaxed);
            f.trace_line(format_args!("edge: {what}"));
            let t = Instant::now();
            // SAFETY: NULL, or memory as large as the sizes say, for every pointer.
            unsafe { call() };
            let took = t.elapsed();
            assert!(took < SLOW, "edge call {what} took {took:?}");
            // SAFETY: no arguments.
            while unsafe { glGetError() } != 0 {}
        }
    }
    cx.close();
}

fn env_u64(name: &str) -> Option<u64> {
    let s = std::env::var(name).ok()?;
    let s = s.trim();
    match s.strip_prefix("0x") {
        Some(h) => u64::from_str_radix(h, 16).ok(),
        None => s.parse().ok(),
    }
}

/// The fuzz loop itself (in the child process). Panics (so the process fails) on a slow call
/// or a malformed answer; a crash ends the process.
fn fuzz(seed: u64, calls: u64, trace: Option<std::fs::File>) {
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let _ = writeln!(
            std::io::stderr(),
            "fixedgl-fuzz: a panic during call #{}",
            CALL.load(Ordering::Relaxed)
        );
        default_hook(info);
    }));
    let (input, output, table) = memory();
    let mut rng = Rng(seed ^ 0xc0ff_ee00);
    let mut f = Fuzz {
        rng: Rng(seed),
        bounded: false,
        input,
        output,
        table,
        trace,
        call: 0,
        crash_at: env_u64("FIXEDGL_FUZZ_CRASH_AT"),
    };
    f.trace_line(format_args!(
        "input memory at {input:?} (small integers for {SMALL_BYTES} bytes, then floats), \
         output memory at {output:?}, the pointer table at {table:?}"
    ));
    let mut cx = Contexts::new();
    CALL_START.store(now_ms(), Ordering::Relaxed);
    let _watchdog = watchdog();
    let mut next_shuffle = 0;
    let mut slow = Vec::new();
    let (mut with_context, mut no_error) = (0u64, 0u64);
    let n = gl_calls::NAMES.len();
    let focus: Vec<usize> = FOCUS
        .iter()
        .map(|name| {
            gl_calls::NAMES
                .iter()
                .position(|n| n == name)
                .unwrap_or_else(|| panic!("{name} is not a GL 1.x command"))
        })
        .collect();
    for call in 0..calls {
        f.call = call;
        CALL.store(call, Ordering::Relaxed);
        if call == next_shuffle {
            cx.shuffle(&mut rng, &mut f);
            next_shuffle = call + 1 + rng.below(3000) as u64;
        }
        let draw = |r: &mut Rng| {
            if r.percent(33) {
                r.pick(&focus)
            } else {
                r.below(n)
            }
        };
        let mut i = draw(&mut f.rng);
        // A display list that calls lists can make a call take exponential time (each call
        // of list 1 calling list 1 eight times, 64 deep): legal GL that hangs any driver. So no
        // list calls are compiled into lists.
        while matches!(gl_calls::NAMES[i], "glCallList" | "glCallLists") && compiling() {
            i = draw(&mut f.rng);
        }
        CALL_COMMAND.store(i, Ordering::Relaxed);
        CALL_START.store(now_ms(), Ordering::Relaxed);
        let t = Instant::now();
        // SAFETY: the arguments keep GL's contract with a C caller: NULL, or memory that holds
        // what the sizes say (see `Fuzz`).
        unsafe { gl_calls::call(i, &mut f) };
        let took = t.elapsed();
        if cx.current.is_some() {
            with_context += 1;
            // SAFETY: no arguments.
            if unsafe { fixedgl_capi::manual::glGetError() } == 0 {
                no_error += 1;
            }
        }
        if took > SLOW {
            let _ = writeln!(
                std::io::stderr(),
                "fixedgl-fuzz: call #{call} ({}) took {took:.1?}",
                gl_calls::NAMES[i]
            );
            slow.push(call);
        }
    }
    cx.close();
    let _ = writeln!(
        std::io::stderr(),
        "fixedgl-fuzz: {calls} calls, {with_context} of them on a current context, \
         {no_error} of those without a GL error"
    );
    assert!(slow.is_empty(), "slow calls: {slow:?}");
}

/// The fuzz loop of one child process, with the parameters in the environment. `--ignored` runs
/// it in this process (`CALLS` calls unless FIXEDGL_FUZZ_CALLS says otherwise).
#[test]
#[ignore = "the child process of random_c_calls_never_crash (run with --ignored: in-process)"]
fn fuzz_child() {
    let seed = env_u64("FIXEDGL_FUZZ_SEED").unwrap_or(SEED);
    let calls = env_u64("FIXEDGL_FUZZ_CALLS").unwrap_or(CALLS);
    let trace = std::env::var_os("FIXEDGL_FUZZ_TRACE").map(|p| {
        std::fs::File::create(&p).unwrap_or_else(|e| panic!("{}: {e}", p.to_string_lossy()))
    });
    let start = Instant::now();
    if std::env::var_os("FIXEDGL_FUZZ_EDGE").is_some() {
        let (input, output, table) = memory();
        let mut f = Fuzz {
            rng: Rng(seed),
            bounded: false,
            input,
            output,
            table,
            trace,
            call: 0,
            crash_at: None,
        };
        let _watchdog = watchdog();
        edge_calls(&mut f);
        return;
    }
    fuzz(seed, calls, trace);
    let _ = writeln!(
        std::io::stderr(),
        "fixedgl-fuzz: {calls} calls with seed {seed:#x} in {:.1?}",
        start.elapsed()
    );
}

/// How a child run ended.
struct ChildRun {
    ok: bool,
    status: String,
    stderr: String,
}

fn run_child(
    seed: u64,
    calls: u64,
    env: &[(&str, String)],
    trace: Option<&std::path::Path>,
    limit: Duration,
) -> ChildRun {
    use std::os::unix::process::ExitStatusExt;
    let exe = std::env::current_exe().expect("current_exe");
    let dir = std::env::temp_dir().join(format!("fixedgl-fuzz-{}-{seed:x}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let (out, err) = (dir.join("stdout"), dir.join("stderr"));
    let mut cmd = Command::new(exe);
    cmd.args([
        "--exact",
        "fuzz_child",
        "--ignored",
        "--nocapture",
        "--test-threads=1",
    ])
    .env("FIXEDGL_FUZZ_SEED", seed.to_string())
    .env("FIXEDGL_FUZZ_CALLS", calls.to_string())
    .env("RUST_BACKTRACE", "1")
    .env_remove("FIXEDGL_FUZZ_TRACE")
    .env_remove("FIXEDGL_FUZZ_CRASH_AT")
    .envs(env.iter().map(|(k, v)| (k, v)))
    .stdout(std::fs::File::create(&out).expect("stdout file"))
    .stderr(std::fs::File::create(&err).expect("stderr file"));
    if let Some(t) = trace {
        cmd.env("FIXEDGL_FUZZ_TRACE", t);
    }
    let mut child = cmd.spawn().expect("spawn the fuzz child");
    let deadline = Instant::now() + limit;
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break Some(s);
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let stderr = String::from_utf8_lossy(&std::fs::read(&err).unwrap_or_default()).into_owned();
    let stdout = String::from_utf8_lossy(&std::fs::read(&out).unwrap_or_default()).into_owned();
    let _ = std::fs::remove_dir_all(&dir);
    let caught = stderr.contains("panicked at") || stderr.contains("failed inside fixedgl");
    let (ok, status) = match status {
        None => (false, format!("did not finish within {limit:?}")),
        Some(s) => match s.signal() {
            Some(sig) => (false, format!("killed by signal {sig}")),
            None if !s.success() => (false, format!("exited with {s}")),
            None if caught => (false, "a panic was caught inside fixedgl".to_string()),
            None => (true, "ok".to_string()),
        },
    };
    ChildRun {
        ok,
        status,
        stderr: format!("{stdout}{stderr}"),
    }
}

/// The child's output without the lines fixedgl prints once per unimplemented function or
/// call without a context.
fn quiet(s: &str) -> String {
    s.lines()
        .filter(|l| !l.contains("is not implemented; the call does nothing"))
        .filter(|l| !l.contains("called with no current context"))
        .collect::<Vec<_>>()
        .join("\n")
}

fn last_lines(s: &str, n: usize) -> String {
    let lines: Vec<&str> = s.lines().collect();
    lines[lines.len().saturating_sub(n)..].join("\n")
}

/// Runs the fuzz loop in a child; on a failure runs it again with a trace, and the message
/// names the call.
fn fuzz_in_child(seed: u64, calls: u64, env: &[(&str, String)]) -> Result<(), String> {
    let limit = Duration::from_secs(1200);
    let start = Instant::now();
    let run = run_child(seed, calls, env, None, limit);
    if run.ok {
        let _ = writeln!(
            std::io::stderr(),
            "fixedgl-fuzz: {calls} random C calls, seed {seed:#x}: no crash ({:.1?})",
            start.elapsed()
        );
        return Ok(());
    }
    let trace = std::env::temp_dir().join(format!(
        "fixedgl-fuzz-trace-{}-{seed:x}.txt",
        std::process::id()
    ));
    let again = run_child(seed, calls, env, Some(&trace), limit);
    let text = std::fs::read_to_string(&trace).unwrap_or_default();
    // The call a panic or a slow call names, else the last one begun.
    let named = again
        .stderr
        .lines()
        .chain(run.stderr.lines())
        .find_map(|l| {
            l.strip_prefix("fixedgl-fuzz: a panic during call #")
                .or_else(|| l.strip_prefix("fixedgl-fuzz: call #"))
                .and_then(|r| r.split(|c: char| !c.is_ascii_digit()).next())
                .map(str::to_string)
        });
    let around = match &named {
        Some(n) => {
            let key = format!("#{n} ");
            let at = text.lines().position(|l| l.starts_with(&key)).unwrap_or(0);
            let lines: Vec<&str> = text.lines().collect();
            lines[at.saturating_sub(12)..(at + 1).min(lines.len())].join("\n")
        }
        None => last_lines(&text, 12),
    };
    Err(format!(
        "random C calls (seed {seed:#x}, {calls} calls): {}\n\
         the call (the last line; the lines before it are the calls leading to it):\n{around}\n\
         the child's output ends:\n{}\n\
         replay: FIXEDGL_FUZZ_SEED={seed:#x} FIXEDGL_FUZZ_CALLS={calls} FIXEDGL_FUZZ_TRACE=trace.txt \
         cargo test --profile ci -p fixedgl-capi --test c_abi_fuzz fuzz_child -- --ignored --exact\n\
         (with the trace: {}, second run: {})",
        run.status,
        last_lines(&quiet(&run.stderr), 25),
        trace.display(),
        again.status
    ))
}

#[test]
fn random_c_calls_never_crash() {
    let seed = env_u64("FIXEDGL_FUZZ_SEED").unwrap_or(SEED);
    let calls = env_u64("FIXEDGL_FUZZ_CALLS").unwrap_or(CALLS);
    if let Err(e) = fuzz_in_child(seed, calls, &[]) {
        panic!("{e}");
    }
}

#[test]
#[ignore = "4 x 20,000,000 calls: a minute or more"]
fn random_c_calls_never_crash_long() {
    for k in 1..=4u64 {
        if let Err(e) = fuzz_in_child(SEED.wrapping_add(k * 0x1000_0001), 20_000_000, &[]) {
            panic!("{e}");
        }
    }
}

/// The reporting works: a child that crashes inside call 4321 fails the run, and the message
/// names that call with its arguments.
#[test]
fn a_crash_is_reported_with_its_call() {
    let env = [("FIXEDGL_FUZZ_CRASH_AT", "4321".to_string())];
    let Err(msg) = fuzz_in_child(SEED, 10_000, &env) else {
        panic!("a child that aborts was not reported");
    };
    assert!(msg.contains("killed by signal 6"), "{msg}");
    let call = msg
        .lines()
        .find(|l| l.starts_with("#4321 gl"))
        .unwrap_or_else(|| panic!("the message does not name call #4321:\n{msg}"));
    assert!(call.contains('['), "{call}");
}

/// The edge calls (`edge_calls`) never crash, hang or panic either.
#[test]
fn edge_c_calls_never_crash() {
    let env = [("FIXEDGL_FUZZ_EDGE", "1".to_string())];
    if let Err(e) = fuzz_in_child(SEED, 0, &env) {
        panic!("{e}");
    }
}
