//! Xlib for GLX: libX11 and libXext loaded at run time (`x11-dl`, so that headless programs
//! need no X libraries), an error trap, and the drawables GLX renders to — their size, and
//! presenting a frame into them with `XPutImage` (or `XShmPutImage` when the MIT-SHM extension
//! is there and the display is local).
//!
//! Every call here goes through the program's own `Display*`, on the thread that made the
//! context current: Xlib's rule for a display without `XInitThreads`, which the program keeps
//! as it would with any GLX.

use std::ffi::{c_char, c_int, c_uint, c_ulong, CStr};
use std::sync::atomic::{AtomicU8, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

use fixedgl::Context;
use x11_dl::xlib::{self, Display, Visual, XErrorEvent, XImage, Xlib, GC};
use x11_dl::xshm::{XShmSegmentInfo, Xext};

use crate::current::Surface;

/// libX11's functions, loaded once; `None` (said once on stderr) without libX11.
pub(crate) fn xlib() -> Option<&'static Xlib> {
    static X: OnceLock<Option<Xlib>> = OnceLock::new();
    X.get_or_init(|| match Xlib::open() {
        Ok(x) => Some(x),
        Err(e) => {
            eprintln!("fixedgl: GLX needs libX11.so.6, which cannot be loaded ({e}); headless programs can use EGL or OSMesa");
            None
        }
    })
    .as_ref()
}

/// libXext's MIT-SHM functions, loaded once; `None` without libXext (XPutImage is used then).
fn xext() -> Option<&'static Xext> {
    static X: OnceLock<Option<Xext>> = OnceLock::new();
    X.get_or_init(|| Xext::open().ok()).as_ref()
}

// ----- The error trap -------------------------------------------------------------------------

/// The trap's state: the display and first request serial it watches, the error it caught, and
/// the handler it replaced (errors of the program's own earlier requests go on to that one).
static TRAP_LOCK: Mutex<()> = Mutex::new(());
static TRAP_DISPLAY: AtomicUsize = AtomicUsize::new(0);
static TRAP_FIRST: AtomicUsize = AtomicUsize::new(0);
static TRAP_CAUGHT: AtomicU8 = AtomicU8::new(0);
static TRAP_PREVIOUS: AtomicUsize = AtomicUsize::new(0);

type Handler = unsafe extern "C" fn(*mut Display, *mut XErrorEvent) -> c_int;

unsafe extern "C" fn trap_handler(dpy: *mut Display, event: *mut XErrorEvent) -> c_int {
    // SAFETY: Xlib hands the handler a valid event.
    let Some(e) = (unsafe { event.as_ref() }) else {
        return 0;
    };
    if dpy as usize == TRAP_DISPLAY.load(Ordering::SeqCst)
        && e.serial as usize >= TRAP_FIRST.load(Ordering::SeqCst)
    {
        // One of ours: remember the first error.
        let _ = TRAP_CAUGHT.compare_exchange(
            0,
            e.error_code.max(1),
            Ordering::SeqCst,
            Ordering::SeqCst,
        );
        return 0;
    }
    let previous = TRAP_PREVIOUS.load(Ordering::SeqCst);
    if previous == 0 {
        return 0;
    }
    // SAFETY: the address of the handler XSetErrorHandler returned (a function of that type).
    let previous: Handler = unsafe { std::mem::transmute::<usize, Handler>(previous) };
    // SAFETY: passing on what Xlib gave us, as Xlib would have.
    unsafe { previous(dpy, event) }
}

/// How `trapped` knows the server has answered `f`'s requests.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Wait {
    /// `f` ends with a request that has a reply (XGetGeometry): its errors came before it.
    Reply,
    /// `f`'s requests have no reply (XShmAttach): an XSync after them.
    Sync,
}

/// Runs the X requests of `f` on `dpy` with X errors caught instead of reaching the program's
/// handler (whose default ends the program): `Err(code)` when one of them failed. Errors of the
/// program's own earlier requests still go to its handler.
pub(crate) fn trapped<R>(
    x: &Xlib,
    dpy: *mut Display,
    wait: Wait,
    f: impl FnOnce() -> R,
) -> Result<R, u8> {
    let _lock = TRAP_LOCK.lock().unwrap_or_else(|e| e.into_inner());
    // SAFETY: `dpy` is the program's open display (GLX's contract); these are plain Xlib calls.
    unsafe {
        TRAP_DISPLAY.store(dpy as usize, Ordering::SeqCst);
        TRAP_FIRST.store((x.XNextRequest)(dpy) as usize, Ordering::SeqCst);
        TRAP_CAUGHT.store(0, Ordering::SeqCst);
        let previous = (x.XSetErrorHandler)(Some(trap_handler));
        TRAP_PREVIOUS.store(previous.map_or(0, |p| p as usize), Ordering::SeqCst);
        let r = f();
        if wait == Wait::Sync {
            (x.XSync)(dpy, xlib::False);
        }
        (x.XSetErrorHandler)(previous);
        TRAP_DISPLAY.store(0, Ordering::SeqCst);
        match TRAP_CAUGHT.swap(0, Ordering::SeqCst) {
            0 => Ok(r),
            code => Err(code),
        }
    }
}

// ----- Visuals --------------------------------------------------------------------------------

/// The 24-bit TrueColor visual of `screen` (XMatchVisualInfo), the one GLX offers.
pub(crate) fn true_color(x: &Xlib, dpy: *mut Display, screen: c_int) -> Option<xlib::XVisualInfo> {
    if dpy.is_null() {
        return None;
    }
    // SAFETY: an open display; XMatchVisualInfo fills the struct it is given.
    unsafe {
        if screen < 0 || screen >= (x.XScreenCount)(dpy) {
            return None;
        }
        let mut vi: xlib::XVisualInfo = std::mem::zeroed();
        if (x.XMatchVisualInfo)(dpy, screen, 24, xlib::TrueColor, &mut vi) == 0 {
            return None;
        }
        Some(vi)
    }
}

/// Whether fixedgl can present into a drawable of this visual class and depth: TrueColor (or
/// DirectColor) of depth 24 or 32 (what XPutImage of 32-bit pixels is written for).
pub(crate) fn presentable(class: c_int, depth: c_int) -> bool {
    (class == xlib::TrueColor || class == xlib::DirectColor) && (depth == 24 || depth == 32)
}

/// Whether `dpy` is a local connection (MIT-SHM shares memory with the server only there).
fn local_display(x: &Xlib, dpy: *mut Display) -> bool {
    // SAFETY: an open display; the string is Xlib's.
    let name = unsafe { (x.XDisplayString)(dpy) };
    if name.is_null() {
        return false;
    }
    // SAFETY: a NUL-terminated string owned by Xlib.
    let name = unsafe { CStr::from_ptr(name) }.to_bytes();
    name.starts_with(b":") || name.starts_with(b"unix:")
}

// ----- Drawables ------------------------------------------------------------------------------

/// What a GLX drawable is on the X side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// An X window (GLX 1.2) or a GLXWindow (GLX 1.3: the same XID here).
    Window,
    /// A GLXPixmap: an X pixmap, presented to at glFlush/glFinish.
    Pixmap,
    /// A GLXPbuffer: fixedgl's own, never shown.
    Pbuffer,
}

/// A frame buffer Xlib sends: ours (XPutImage) or shared with the server (XShmPutImage).
enum Image {
    Plain {
        image: Box<XImage>,
        /// The pixels `image.data` points at (owned here, kept alive with the image).
        _data: Vec<u32>,
    },
    Shm {
        image: *mut XImage,
        info: Box<XShmSegmentInfo>,
    },
}

impl Image {
    fn ximage(&mut self) -> *mut XImage {
        match self {
            Image::Plain { image, .. } => &mut **image,
            Image::Shm { image, .. } => *image,
        }
    }
}

/// One drawable a context renders to, shared by the contexts made current on it.
pub(crate) struct XDrawable {
    pub dpy: *mut Display,
    pub xid: c_ulong,
    pub kind: Kind,
    /// The FBConfig it was made with (GLX 1.3 drawables and GLXPixmaps); `None` for an X
    /// window used directly, which takes its context's.
    pub config: Option<usize>,
    /// Width and height, as last read from the server.
    pub size: (u32, u32),
    visual: *mut Visual,
    depth: c_int,
    gc: GC,
    image: Option<Image>,
    /// MIT-SHM: unknown yet, usable, or not (XPutImage then).
    shm: Option<bool>,
    /// GLX_MESA_swap_control's interval (frames of 60 Hz between swaps; 0: no pacing).
    pub swap_interval: u32,
    last_swap: Option<Instant>,
    /// glXSelectEvent's mask (fixedgl sends no GLX events: pbuffers are never clobbered).
    pub event_mask: c_ulong,
    /// Destroyed by the program (glXDestroyWindow/Pixmap/Pbuffer): nothing more is sent.
    gone: bool,
    /// The size has been read since the last present (see `refresh`).
    checked: bool,
    /// The server said it has no such drawable (destroyed without glXDestroy*): nothing more
    /// is sent to it.
    lost: bool,
}

// SAFETY: the raw pointers are the program's Xlib display and visual, and Xlib images fixedgl
// made; they are used from the thread the drawable's context is current on, under the Mutex
// that holds the drawable (Xlib's own rule for a display shared between threads).
unsafe impl Send for XDrawable {}

impl XDrawable {
    /// An X window, as the server describes it; `Err` with the reason if it is not a window
    /// fixedgl can present to.
    pub fn window(
        x: &Xlib,
        dpy: *mut Display,
        xid: c_ulong,
        config: Option<usize>,
    ) -> Result<XDrawable, String> {
        if dpy.is_null() || xid == 0 {
            return Err("no display or no window".into());
        }
        // SAFETY: an open display; XGetWindowAttributes fills the struct.
        let mut wa: xlib::XWindowAttributes = unsafe { std::mem::zeroed() };
        let ok = trapped(x, dpy, Wait::Reply, || unsafe {
            (x.XGetWindowAttributes)(dpy, xid, &mut wa)
        });
        if !matches!(ok, Ok(s) if s != 0) {
            return Err(format!("{xid:#x} is not a window of this display"));
        }
        // SAFETY: the visual Xlib reported for the window.
        let class = unsafe { wa.visual.as_ref() }.map_or(-1, |v| v.class);
        if !presentable(class, wa.depth) {
            return Err(format!(
                "window {xid:#x} has a depth-{} visual of class {class}; fixedgl presents to 24- or 32-bit TrueColor windows",
                wa.depth
            ));
        }
        Ok(XDrawable {
            size: (wa.width.max(0) as u32, wa.height.max(0) as u32),
            visual: wa.visual,
            depth: wa.depth,
            ..XDrawable::new(dpy, xid, Kind::Window, config)
        })
    }

    /// An X pixmap drawn through `visual`; `Err` with the reason if it cannot be one.
    pub fn pixmap(
        x: &Xlib,
        dpy: *mut Display,
        xid: c_ulong,
        visual: *mut Visual,
        config: Option<usize>,
    ) -> Result<XDrawable, String> {
        let mut d = XDrawable {
            visual,
            ..XDrawable::new(dpy, xid, Kind::Pixmap, config)
        };
        let depth = d
            .query(x)
            .ok_or(format!("{xid:#x} is not a pixmap of this display"))?;
        // SAFETY: a visual of the display (GLX's contract for the visual or config given).
        let class = unsafe { visual.as_ref() }.map_or(-1, |v| v.class);
        if !presentable(class, depth) {
            return Err(format!(
                "pixmap {xid:#x} has depth {depth}; fixedgl renders to 24- or 32-bit pixmaps"
            ));
        }
        d.depth = depth;
        Ok(d)
    }

    /// A pbuffer of `w` x `h`, with `xid` a handle fixedgl chose.
    pub fn pbuffer(
        dpy: *mut Display,
        xid: c_ulong,
        size: (u32, u32),
        config: Option<usize>,
    ) -> XDrawable {
        XDrawable {
            size,
            ..XDrawable::new(dpy, xid, Kind::Pbuffer, config)
        }
    }

    fn new(dpy: *mut Display, xid: c_ulong, kind: Kind, config: Option<usize>) -> XDrawable {
        XDrawable {
            dpy,
            xid,
            kind,
            config,
            size: (0, 0),
            visual: std::ptr::null_mut(),
            depth: 0,
            gc: std::ptr::null_mut(),
            image: None,
            shm: None,
            swap_interval: 0,
            last_swap: None,
            event_mask: 0,
            gone: false,
            checked: false,
            lost: false,
        }
    }

    /// Reads the size (and depth) from the server: one XGetGeometry round trip. `None` when the
    /// drawable is gone (destroyed by the program): the size stays as it was.
    fn query(&mut self, x: &Xlib) -> Option<c_int> {
        if self.kind == Kind::Pbuffer {
            return Some(self.depth);
        }
        if self.gone {
            return None;
        }
        let (mut root, mut px, mut py, mut w, mut h, mut border, mut depth) = (0, 0, 0, 0, 0, 0, 0);
        let ok = trapped(x, self.dpy, Wait::Reply, || unsafe {
            // SAFETY: an open display; the out-pointers are locals.
            (x.XGetGeometry)(
                self.dpy,
                self.xid,
                &mut root,
                &mut px,
                &mut py,
                &mut w,
                &mut h,
                &mut border,
                &mut depth,
            )
        });
        if !matches!(ok, Ok(s) if s != 0) {
            self.lost = true;
            return None;
        }
        self.lost = false;
        self.size = (w, h);
        Some(depth as c_int)
    }

    /// Re-reads the size, once per frame: the first call after a present (or ever) asks the
    /// server, later ones in the same frame answer from the cache (a program may call
    /// glViewport many times a frame; each answer from the server is a round trip). `false`
    /// when the drawable no longer exists on the server.
    pub fn refresh(&mut self) -> bool {
        if self.checked {
            return !self.gone && !self.lost;
        }
        self.exists()
    }

    /// Asks the server now (uncached): whether the drawable exists, its size read on the way.
    pub fn exists(&mut self) -> bool {
        self.checked = true;
        xlib().is_some_and(|x| self.query(x).is_some())
    }

    /// The program destroyed the drawable (glXDestroyWindow ...): frees what fixedgl made on
    /// the server for it, while the display is still open, and sends nothing more.
    pub fn release(&mut self) {
        self.let_go(true);
    }

    /// As `release`; `detach`: whether to detach the shared-memory segment from the server too.
    /// Not when the display is closing: the server detaches it when the connection ends, and
    /// libXext may already have dropped the display's MIT-SHM record (XShmDetach would then
    /// make a new one that outlives the display, for a later display at the same address).
    fn let_go(&mut self, detach: bool) {
        if self.gone {
            return;
        }
        self.gone = true;
        let Some(x) = xlib() else { return };
        self.drop_image(x, detach);
        if !self.gc.is_null() {
            // SAFETY: a GC fixedgl made on this display.
            unsafe { (x.XFreeGC)(self.dpy, self.gc) };
            self.gc = std::ptr::null_mut();
        }
    }

    fn drop_image(&mut self, x: &Xlib, detach: bool) {
        match self.image.take() {
            Some(Image::Shm { image, info }) => {
                if let (Some(ext), true) = (xext(), detach) {
                    // SAFETY: the segment fixedgl attached on this display.
                    unsafe { (ext.XShmDetach)(self.dpy, &*info as *const _ as *mut _) };
                }
                // SAFETY: the image Xlib made for the segment, whose data (the segment) is
                // detached below, not freed by Xlib.
                unsafe {
                    (*image).data = std::ptr::null_mut();
                    (x.XDestroyImage)(image);
                }
                // SAFETY: the segment fixedgl attached to this process.
                unsafe { libc::shmdt(info.shmaddr as *const libc::c_void) };
            }
            Some(Image::Plain { .. }) | None => {}
        }
    }

    /// An image of `w` x `h` to send, made (or remade at a new size) on demand.
    fn image(&mut self, x: &Xlib, w: u32, h: u32) -> Option<&mut Image> {
        let fits = self.image.as_mut().is_some_and(|i| {
            // SAFETY: an image fixedgl made.
            let im = unsafe { &*i.ximage() };
            im.width == w as c_int && im.height == h as c_int
        });
        if !fits {
            self.drop_image(x, true);
            if self.shm.is_none() {
                self.shm = Some(
                    std::env::var_os("FIXEDGL_NO_SHM").is_none()
                        && local_display(x, self.dpy)
                        && xext().is_some_and(|e| unsafe { (e.XShmQueryExtension)(self.dpy) } != 0),
                );
            }
            if self.shm == Some(true) {
                match self.shm_image(x, w, h) {
                    Some(i) => self.image = Some(i),
                    None => self.shm = Some(false),
                }
            }
            if self.image.is_none() {
                self.image = Some(self.plain_image(x, w, h)?);
            }
        }
        self.image.as_mut()
    }

    /// An XImage over memory fixedgl owns, in the host's byte order (Xlib swaps if the server's
    /// differs).
    fn plain_image(&self, x: &Xlib, w: u32, h: u32) -> Option<Image> {
        // SAFETY: the visual the drawable was made with.
        let v = unsafe { self.visual.as_ref() }?;
        let mut data = Vec::new();
        data.try_reserve_exact(w as usize * h as usize).ok()?;
        data.resize(w as usize * h as usize, 0u32);
        let order = if cfg!(target_endian = "little") {
            xlib::LSBFirst
        } else {
            xlib::MSBFirst
        };
        // SAFETY: XImage is plain data (integers, pointers, optional functions): zero is valid.
        let mut image: Box<XImage> = Box::new(unsafe { std::mem::zeroed() });
        image.width = w as c_int;
        image.height = h as c_int;
        image.format = xlib::ZPixmap;
        image.data = data.as_mut_ptr().cast::<c_char>();
        image.byte_order = order;
        image.bitmap_unit = 32;
        image.bitmap_bit_order = order;
        image.bitmap_pad = 32;
        image.depth = self.depth;
        image.bytes_per_line = (w * 4) as c_int;
        image.bits_per_pixel = 32;
        image.red_mask = v.red_mask;
        image.green_mask = v.green_mask;
        image.blue_mask = v.blue_mask;
        // SAFETY: a filled XImage; XInitImage sets its functions.
        if unsafe { (x.XInitImage)(&mut *image) } == 0 {
            return None;
        }
        Some(Image::Plain { image, _data: data })
    }

    /// An XImage in a shared-memory segment the server attaches; `None` (XPutImage then) when
    /// the segment cannot be made or the server refuses it.
    fn shm_image(&self, x: &Xlib, w: u32, h: u32) -> Option<Image> {
        let ext = xext()?;
        let mut info: Box<XShmSegmentInfo> = Box::new(XShmSegmentInfo {
            shmseg: 0,
            shmid: -1,
            shmaddr: std::ptr::null_mut(),
            readOnly: xlib::False,
        });
        // SAFETY: an open display and one of its visuals; Xlib allocates the image header.
        let image = unsafe {
            (ext.XShmCreateImage)(
                self.dpy,
                self.visual,
                self.depth as c_uint,
                xlib::ZPixmap,
                std::ptr::null_mut(),
                &mut *info,
                w,
                h,
            )
        };
        if image.is_null() {
            return None;
        }
        // SAFETY: the image Xlib just made.
        let im = unsafe { &mut *image };
        let fail = |image: *mut XImage| {
            // SAFETY: Xlib's image, with no data of its own.
            unsafe {
                (*image).data = std::ptr::null_mut();
                (x.XDestroyImage)(image);
            }
            None
        };
        if im.bits_per_pixel != 32 {
            return fail(image);
        }
        let bytes = im.bytes_per_line as usize * im.height as usize;
        // SAFETY: plain System V shared memory calls; the segment is this process's.
        unsafe {
            info.shmid = libc::shmget(libc::IPC_PRIVATE, bytes, libc::IPC_CREAT | 0o600);
            if info.shmid < 0 {
                return fail(image);
            }
            let addr = libc::shmat(info.shmid, std::ptr::null(), 0);
            if addr as isize == -1 {
                libc::shmctl(info.shmid, libc::IPC_RMID, std::ptr::null_mut());
                return fail(image);
            }
            info.shmaddr = addr.cast();
            im.data = info.shmaddr;
            let attached = trapped(x, self.dpy, Wait::Sync, || {
                (ext.XShmAttach)(self.dpy, &mut *info)
            });
            // Marked for removal now: it goes when both sides have detached (or exited).
            libc::shmctl(info.shmid, libc::IPC_RMID, std::ptr::null_mut());
            if !matches!(attached, Ok(s) if s != 0) {
                libc::shmdt(addr);
                return fail(image);
            }
        }
        Some(Image::Shm { image, info })
    }

    /// Shows `ctx`'s colour buffer in the drawable (top-left aligned, clipped by the server),
    /// then reads the drawable's size again and gives the framebuffer the new size if the
    /// window was resized (a new frame is drawn after this; its contents are undefined anyway).
    pub fn present(&mut self, ctx: &mut Context) {
        if self.kind == Kind::Pbuffer || self.gone || self.lost {
            return;
        }
        let Some(x) = xlib() else { return };
        let frame = ctx.to_image();
        let (w, h) = frame.dimensions();
        if self.gc.is_null() {
            // SAFETY: an open display and a drawable of it.
            self.gc = unsafe { (x.XCreateGC)(self.dpy, self.xid, 0, std::ptr::null_mut()) };
            if self.gc.is_null() {
                return;
            }
        }
        let (dpy, xid, gc, depth) = (self.dpy, self.xid, self.gc, self.depth);
        let Some(image) = self.image(x, w, h) else {
            return;
        };
        let im = image.ximage();
        // SAFETY: the image made for this size: `bytes_per_line` x `height` bytes at `data`.
        let out = unsafe {
            std::slice::from_raw_parts_mut(
                (*im).data.cast::<u8>(),
                (*im).bytes_per_line as usize * h as usize,
            )
        };
        // SAFETY: as above.
        let layout = unsafe { Layout::of(&*im, depth) };
        layout.convert(frame.as_raw(), out, w as usize, h as usize);
        match image {
            Image::Plain { .. } => unsafe {
                // SAFETY: an open display, its drawable and GC, and a complete image.
                (x.XPutImage)(dpy, xid, gc, im, 0, 0, 0, 0, w, h);
            },
            Image::Shm { .. } => {
                if let Some(ext) = xext() {
                    // SAFETY: as above, with the attached segment.
                    unsafe { (ext.XShmPutImage)(dpy, xid, gc, im, 0, 0, 0, 0, w, h, xlib::False) };
                }
            }
        }
        // The frame is on the server when SwapBuffers (or glFlush) returns: another client
        // reading the window sees it, and the shared segment is free for the next frame.
        // SAFETY: an open display.
        unsafe { (x.XSync)(dpy, xlib::False) };
        // A new frame starts: the size is read now (a program that never calls glViewport
        // again still gets a framebuffer of the window's size) and once more at its first
        // MakeCurrent or glViewport (a reshape handler running on a ConfigureNotify that arrived
        // after this).
        self.checked = false;
        if self.query(x).is_some() {
            let (nw, nh) = (self.size.0.max(1), self.size.1.max(1));
            if (nw, nh) != ctx.size() {
                if let Err(e) = ctx.resize(nw, nh) {
                    eprintln!("fixedgl: cannot resize the framebuffer to {nw}x{nh}: {e}");
                }
            }
        }
    }

    /// GLX_MESA_swap_control: waits until `swap_interval` frames of a 60 Hz display have passed
    /// since the last swap.
    pub fn pace(&mut self) {
        let now = Instant::now();
        if self.swap_interval > 0 {
            if let Some(last) = self.last_swap {
                let due = last + Duration::from_micros(16_667 * u64::from(self.swap_interval));
                if due > now {
                    std::thread::sleep(due - now);
                }
            }
        }
        self.last_swap = Some(Instant::now());
    }
}

/// Where each 8-bit component goes in a 32-bit pixel of an XImage.
#[derive(Clone, Copy, Debug)]
struct Layout {
    red: (u32, u32),
    green: (u32, u32),
    blue: (u32, u32),
    /// The bits left over in a depth-32 visual: alpha.
    alpha: Option<(u32, u32)>,
    /// The image's byte order is not the host's.
    swap: bool,
}

/// A mask's (shift, width).
fn field(mask: c_ulong) -> (u32, u32) {
    let m = mask as u32;
    if m == 0 {
        return (0, 0);
    }
    (m.trailing_zeros(), m.count_ones())
}

impl Layout {
    unsafe fn of(im: &XImage, depth: c_int) -> Layout {
        let rest = !(im.red_mask | im.green_mask | im.blue_mask) & 0xffff_ffff;
        let host = if cfg!(target_endian = "little") {
            xlib::LSBFirst
        } else {
            xlib::MSBFirst
        };
        Layout {
            red: field(im.red_mask),
            green: field(im.green_mask),
            blue: field(im.blue_mask),
            alpha: (depth == 32 && rest != 0).then(|| field(rest)),
            swap: im.byte_order != host,
        }
    }

    /// Converts `w` x `h` RGBA8 pixels, top row first, into the image's rows.
    fn convert(&self, src: &[u8], out: &mut [u8], w: usize, h: usize) {
        let put = |v: u8, (shift, bits): (u32, u32)| -> u32 {
            if bits == 0 {
                0
            } else if bits >= 8 {
                u32::from(v) << (shift + bits - 8)
            } else {
                u32::from(v >> (8 - bits)) << shift
            }
        };
        let stride = out.len().checked_div(h).unwrap_or(0);
        let standard = self.red == (16, 8) && self.green == (8, 8) && self.blue == (0, 8);
        for (row, line) in src.chunks_exact(w * 4).take(h).enumerate() {
            let Some(dst) = out.get_mut(row * stride..row * stride + w * 4) else {
                return;
            };
            for (px, o) in line.chunks_exact(4).zip(dst.chunks_exact_mut(4)) {
                let mut v = if standard {
                    u32::from(px[0]) << 16 | u32::from(px[1]) << 8 | u32::from(px[2])
                } else {
                    put(px[0], self.red) | put(px[1], self.green) | put(px[2], self.blue)
                };
                if let Some(a) = self.alpha {
                    v |= put(px[3], a);
                }
                if self.swap {
                    v = v.swap_bytes();
                }
                o.copy_from_slice(&v.to_ne_bytes());
            }
        }
    }
}

// ----- The drawables' registry ----------------------------------------------------------------

/// Drawables fixedgl has rendered to or made, by (display, XID).
type Shared = Arc<Mutex<XDrawable>>;
static DRAWABLES: Mutex<Vec<(usize, c_ulong, Shared)>> = Mutex::new(Vec::new());

fn drawables<R>(f: impl FnOnce(&mut Vec<(usize, c_ulong, Shared)>) -> R) -> R {
    f(&mut DRAWABLES.lock().unwrap_or_else(|e| e.into_inner()))
}

pub(crate) fn lock(d: &Shared) -> std::sync::MutexGuard<'_, XDrawable> {
    d.lock().unwrap_or_else(|e| e.into_inner())
}

/// The drawable `xid` of `dpy`, if fixedgl knows it.
pub(crate) fn find(dpy: *mut Display, xid: c_ulong) -> Option<Shared> {
    drawables(|all| {
        all.iter()
            .find(|(d, x, _)| *d == dpy as usize && *x == xid)
            .map(|(_, _, s)| s.clone())
    })
}

/// Keeps `d` (replacing an older drawable of the same XID: windows' XIDs are reused).
pub(crate) fn insert(d: XDrawable) -> Shared {
    watch_close(d.dpy);
    let key = (d.dpy as usize, d.xid);
    let shared = Arc::new(Mutex::new(d));
    drawables(|all| {
        all.retain(|(d, x, _)| (*d, *x) != key);
        all.push((key.0, key.1, shared.clone()));
    });
    shared
}

/// The displays whose closing fixedgl hears of (`XESetCloseDisplay`).
static WATCHED: Mutex<Vec<usize>> = Mutex::new(Vec::new());

/// Asks Xlib to tell fixedgl when `dpy` is closed (as Mesa's GLX does, through an extension
/// record of the display's own): its drawables are forgotten then. Without this, a display
/// opened later at the same address, on a server that hands out the same XIDs (a fresh server
/// does), would find the closed display's drawables, with their GCs and shared-memory segments
/// of a connection that no longer exists.
fn watch_close(dpy: *mut Display) {
    let Some(x) = xlib() else { return };
    let mut watched = WATCHED.lock().unwrap_or_else(|e| e.into_inner());
    if dpy.is_null() || watched.contains(&(dpy as usize)) {
        return;
    }
    // SAFETY: an open display; Xlib owns the record it returns and frees it at XCloseDisplay.
    unsafe {
        let codes = (x.XAddExtension)(dpy);
        if codes.is_null() {
            return;
        }
        (x.XESetCloseDisplay)(dpy, (*codes).extension, Some(display_closing));
    }
    watched.push(dpy as usize);
}

/// XCloseDisplay's call-out (the display still works here): every drawable of `dpy` lets go of
/// its X resources and is marked gone (a context still current on one presents nothing), and is
/// forgotten.
unsafe extern "C" fn display_closing(dpy: *mut Display, _codes: *mut xlib::XExtCodes) -> c_int {
    WATCHED
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .retain(|d| *d != dpy as usize);
    let closing = drawables(|all| {
        let (closing, kept) = std::mem::take(all)
            .into_iter()
            .partition(|(d, _, _)| *d == dpy as usize);
        *all = kept;
        closing
    });
    for (_, _, s) in closing {
        lock(&s).let_go(false);
    }
    0
}

/// Forgets a drawable the program destroyed; what it was, if fixedgl knew it.
pub(crate) fn remove(dpy: *mut Display, xid: c_ulong, kind: Kind) -> Option<Shared> {
    drawables(|all| {
        let i = all
            .iter()
            .position(|(d, x, s)| *d == dpy as usize && *x == xid && lock(s).kind == kind)?;
        let (_, _, s) = all.remove(i);
        lock(&s).release();
        Some(s)
    })
}

/// A GLX drawable as a context's surface.
pub(crate) struct XSurface {
    pub drawable: Shared,
    /// Double-buffered (presents at SwapBuffers) or single (at glFlush/glFinish).
    pub double: bool,
}

impl Surface for XSurface {
    fn size(&self) -> (u32, u32) {
        lock(&self.drawable).size
    }

    fn refresh(&mut self) {
        lock(&self.drawable).refresh();
    }

    fn double_buffered(&self) -> bool {
        self.double
    }

    fn present(&mut self, ctx: &mut Context) {
        let mut d = lock(&self.drawable);
        if self.double {
            d.pace();
        }
        d.present(ctx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layout(r: c_ulong, g: c_ulong, b: c_ulong, depth: c_int, order: c_int) -> Layout {
        // SAFETY: zero is a valid XImage (plain data).
        let mut im: XImage = unsafe { std::mem::zeroed() };
        im.red_mask = r;
        im.green_mask = g;
        im.blue_mask = b;
        im.byte_order = order;
        // SAFETY: a filled image.
        unsafe { Layout::of(&im, depth) }
    }

    /// The usual visual (0xff0000, 0xff00, 0xff) on a little-endian host: B, G, R, pad bytes.
    #[test]
    fn bgrx_for_the_usual_visual() {
        let l = layout(0xff0000, 0xff00, 0xff, 24, xlib::LSBFirst);
        let mut out = [0u8; 8];
        l.convert(&[10, 20, 30, 40, 50, 60, 70, 80], &mut out, 2, 1);
        if cfg!(target_endian = "little") {
            assert_eq!(out, [30, 20, 10, 0, 70, 60, 50, 0]);
        }
    }

    /// Depth 32 carries alpha in the spare byte; a byte order unlike the host's is swapped;
    /// rows follow the image's stride.
    #[test]
    fn alpha_swap_and_stride() {
        let l = layout(0xff0000, 0xff00, 0xff, 32, xlib::MSBFirst);
        let mut out = [0u8; 16];
        l.convert(&[1, 2, 3, 4, 5, 6, 7, 8], &mut out, 1, 2);
        if cfg!(target_endian = "little") {
            assert_eq!(out[..4], [4, 1, 2, 3]);
            assert_eq!(out[8..12], [8, 5, 6, 7]);
            assert_eq!(out[4..8], [0; 4]);
        }
    }

    /// A 5-6-5 layout keeps each component's top bits.
    #[test]
    fn narrow_masks() {
        let l = layout(0xf800, 0x07e0, 0x001f, 24, xlib::LSBFirst);
        let mut out = [0u8; 4];
        l.convert(&[0xff, 0x80, 0x08, 0], &mut out, 1, 1);
        assert_eq!(
            u32::from_ne_bytes(out),
            0xf800 | (0x80 >> 2) << 5 | 0x08 >> 3
        );
    }
}
