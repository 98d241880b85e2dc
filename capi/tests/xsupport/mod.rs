//! What the GLX and C-example tests share: a private Xvfb, reading a window back from the X
//! server, the drop-in directory, running a program with a time limit, PPM files, and the image
//! comparison with the scenes' tolerance.
//!
//! A tool that is missing (Xvfb, cc, a header, PyOpenGL) skips the test with a visible
//! `SKIPPED:` line, unless `FIXEDGL_REQUIRE_GL` is set (CI), where it fails the test.

#![allow(dead_code)] // each test binary uses part of it

use std::ffi::{c_char, c_int, c_ulong, CStr, CString};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use x11_dl::xlib::{self, Display, Xlib};

/// The scenes' tolerance (fixedgl's LECTURE): a pixel is off when a channel differs by more
/// than 2/255, and at most 0.05% of the pixels may be off.
pub const CHANNEL: u8 = 2;
pub const MAX_PERCENT: f64 = 0.05;

/// `true` when `ok`; otherwise a skip (`false`) with the reason on stderr, or a failure under
/// FIXEDGL_REQUIRE_GL.
pub fn available(ok: bool, what: &str) -> bool {
    if ok {
        return true;
    }
    if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() {
        panic!("FIXEDGL_REQUIRE_GL is set but {what} is missing");
    }
    let _ = writeln!(std::io::stderr(), "SKIPPED: {what} is missing");
    false
}

/// Whether `program` runs (is on PATH).
pub fn has_program(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

/// Whether the C compiler finds `header` (`GL/glut.h`).
pub fn has_header(header: &str) -> bool {
    ["/usr/include", "/usr/local/include"]
        .iter()
        .any(|d| Path::new(d).join(header).is_file())
}

/// target/<profile>: where this test binary and libfixedgl_capi.so are.
pub fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    // target/<profile>/deps/<test>
    exe.parent()
        .and_then(Path::parent)
        .expect("target/<profile>")
        .to_path_buf()
}

/// The drop-in directory: libfixedgl_capi.so under every name a program loads GL by (the
/// versioned sonames, and the bare `.so` names PyOpenGL tries first).
pub fn dropin() -> PathBuf {
    let dir = profile_dir().join("dropin-tests");
    // `cargo test` builds the cdylib next to the test binaries (deps/) without copying it up to
    // target/<profile>/ as `cargo build` does: the one in deps/ is the one built with this test.
    let lib = [profile_dir().join("deps"), profile_dir()]
        .map(|d| d.join("libfixedgl_capi.so"))
        .into_iter()
        .find(|l| l.is_file())
        .unwrap_or_else(|| {
            panic!(
                "libfixedgl_capi.so is missing from {}",
                profile_dir().display()
            )
        });
    std::fs::create_dir_all(&dir).expect("the drop-in directory");
    for name in [
        "libGL.so.1",
        "libEGL.so.1",
        "libOpenGL.so.0",
        "libOSMesa.so.8",
        "libGL.so",
        "libEGL.so",
        "libOpenGL.so",
        "libOSMesa.so",
    ] {
        let link = dir.join(name);
        if std::fs::read_link(&link).is_ok_and(|t| t == lib) {
            continue;
        }
        // Made aside and renamed into place: tests racing here each see a whole link.
        let tmp = dir.join(format!(
            ".{name}.{}.{:?}",
            std::process::id(),
            std::thread::current().id()
        ));
        let _ = std::fs::remove_file(&tmp);
        std::os::unix::fs::symlink(&lib, &tmp).expect("a symlink");
        std::fs::rename(&tmp, &link).expect("the symlink in place");
    }
    dir
}

/// Which GL a program runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Gl {
    Fixedgl,
    Mesa,
}

/// `command` set up to run on `gl`: fixedgl's drop-in directory first on LD_LIBRARY_PATH, or the
/// system's Mesa (llvmpipe) with no LD_LIBRARY_PATH of ours.
pub fn on(gl: Gl, mut command: Command) -> Command {
    match gl {
        Gl::Fixedgl => {
            let mut paths = vec![dropin()];
            if let Some(old) = std::env::var_os("LD_LIBRARY_PATH") {
                paths.extend(std::env::split_paths(&old));
            }
            command.env(
                "LD_LIBRARY_PATH",
                std::env::join_paths(paths).expect("paths"),
            );
        }
        Gl::Mesa => {
            command
                .env_remove("LD_LIBRARY_PATH")
                .env("LIBGL_ALWAYS_SOFTWARE", "1")
                .env("GALLIUM_DRIVER", "llvmpipe");
        }
    }
    command
}

/// Runs `command` to its end within `limit`; its output (stdout + stderr) when it exits with
/// status 0, a panic with that output otherwise.
pub fn run(mut command: Command, limit: Duration) -> String {
    let what = format!("{command:?}");
    let mut child = command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let status = wait(&mut child, limit).unwrap_or_else(|| panic!("{what} ran over {limit:?}"));
    let mut out = String::new();
    if let Some(mut o) = child.stdout.take() {
        let _ = o.read_to_string(&mut out);
    }
    if let Some(mut e) = child.stderr.take() {
        let _ = e.read_to_string(&mut out);
    }
    assert!(status.success(), "{what} failed ({status}):\n{out}");
    out
}

/// Waits for `child` at most `limit`; `None` (the child killed) when it ran over.
pub fn wait(child: &mut Child, limit: Duration) -> Option<std::process::ExitStatus> {
    let start = Instant::now();
    loop {
        if let Ok(Some(s)) = child.try_wait() {
            return Some(s);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// A program left running (the GLUT example, glxgears): killed when dropped.
pub struct Running {
    pub child: Child,
    lines: std::sync::mpsc::Receiver<String>,
    pub what: String,
}

impl Running {
    /// Starts `command` with stdin and stdout piped; its stdout is read line by line.
    pub fn start(mut command: Command) -> Running {
        let what = format!("{command:?}");
        let mut child = command
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap_or_else(|e| panic!("{what}: {e}"));
        let out = child.stdout.take().expect("stdout");
        let (tx, lines) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(out).lines().map_while(Result::ok) {
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        Running { child, lines, what }
    }

    /// Waits (at most `limit`) for a line of output that `f` accepts.
    pub fn wait_for(&mut self, limit: Duration, f: impl Fn(&str) -> bool) -> String {
        let deadline = Instant::now() + limit;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok(line) if f(&line) => return line,
                Ok(_) => {}
                Err(_) => panic!("{}: no expected line within {limit:?}", self.what),
            }
        }
    }

    /// Sends a line to the program's stdin, then waits for it to exit with status 0.
    pub fn finish(mut self, limit: Duration) {
        if let Some(mut i) = self.child.stdin.take() {
            let _ = i.write_all(b"\n");
        }
        let status = wait(&mut self.child, limit);
        assert!(
            status.is_some_and(|s| s.success()),
            "{} did not end well: {status:?}",
            self.what
        );
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// libX11 for the tests' own X calls.
pub fn xlib() -> &'static Xlib {
    static X: std::sync::OnceLock<Xlib> = std::sync::OnceLock::new();
    X.get_or_init(|| Xlib::open().expect("libX11"))
}

/// A private X server (Xvfb, 24-bit, on a display number it picks itself), stopped when dropped.
pub struct Xvfb {
    child: Child,
    /// ":N"
    pub display: String,
}

impl Xvfb {
    /// Starts one; `None` (a skip, or a failure under FIXEDGL_REQUIRE_GL) without Xvfb.
    pub fn start() -> Option<Xvfb> {
        if !available(has_program("Xvfb"), "Xvfb (package xvfb)") {
            return None;
        }
        let mut child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1024x768x24",
                "-nolisten",
                "tcp",
                "-noreset",
            ])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("Xvfb starts");
        let mut line = String::new();
        let out = child.stdout.take().expect("stdout");
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut r = BufReader::new(out);
            let mut l = String::new();
            let _ = r.read_line(&mut l);
            let _ = tx.send(l);
            // Keep the pipe open (and drained) while the server runs.
            let _ = std::io::copy(&mut r, &mut std::io::sink());
        });
        if let Ok(l) = rx.recv_timeout(Duration::from_secs(20)) {
            line = l;
        }
        let n: u32 = match line.trim().parse() {
            Ok(n) => n,
            Err(_) => {
                let _ = child.kill();
                let _ = child.wait();
                panic!("Xvfb did not report its display number");
            }
        };
        Some(Xvfb {
            child,
            display: format!(":{n}"),
        })
    }

    /// A connection of the test's own.
    pub fn open(&self) -> Connection {
        let name = CString::new(self.display.clone()).expect("display name");
        // SAFETY: a NUL-terminated name.
        let dpy = unsafe { (xlib().XOpenDisplay)(name.as_ptr()) };
        assert!(!dpy.is_null(), "cannot open {}", self.display);
        Connection(dpy)
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// An open X display, closed when dropped.
pub struct Connection(pub *mut Display);

impl Drop for Connection {
    fn drop(&mut self) {
        // SAFETY: a display this test opened.
        unsafe { (xlib().XCloseDisplay)(self.0) };
    }
}

impl Connection {
    /// The top-level window named `name`, if there is one now.
    pub fn find_named(&self, name: &str) -> Option<c_ulong> {
        let x = xlib();
        // SAFETY: an open display; Xlib allocates the children list and the names.
        unsafe {
            let root = (x.XDefaultRootWindow)(self.0);
            let (mut r, mut p, mut children, mut n) = (0, 0, std::ptr::null_mut(), 0);
            if (x.XQueryTree)(self.0, root, &mut r, &mut p, &mut children, &mut n) == 0 {
                return None;
            }
            let mut found = None;
            if !children.is_null() {
                for &w in std::slice::from_raw_parts(children, n as usize) {
                    let mut title: *mut c_char = std::ptr::null_mut();
                    if (x.XFetchName)(self.0, w, &mut title) != 0 && !title.is_null() {
                        if CStr::from_ptr(title).to_bytes() == name.as_bytes() {
                            found = Some(w);
                        }
                        (x.XFree)(title.cast());
                    }
                }
                (x.XFree)(children.cast());
            }
            found
        }
    }

    /// The top-level window named `name`, waiting for it (at most `limit`).
    pub fn window_named(&self, name: &str, limit: Duration) -> c_ulong {
        let deadline = Instant::now() + limit;
        loop {
            if let Some(w) = self.find_named(name) {
                return w;
            }
            assert!(Instant::now() < deadline, "no window named {name}");
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Waits (at most `limit`) until no top-level window is named `name` (its program ended).
    pub fn wait_gone(&self, name: &str, limit: Duration) {
        let deadline = Instant::now() + limit;
        while self.find_named(name).is_some() {
            assert!(Instant::now() < deadline, "the window {name} stays");
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Resizes `window` (as a window manager would) and waits for the server to have done it.
    pub fn resize(&self, window: c_ulong, width: u32, height: u32) {
        let x = xlib();
        // SAFETY: an open display and a window of it.
        unsafe {
            (x.XResizeWindow)(self.0, window, width, height);
            (x.XSync)(self.0, xlib::False);
        }
    }

    /// Sends `window` a key press and release of `key` (an ASCII letter or digit), as a user
    /// typing would, and waits for the server to have sent them on.
    pub fn press(&self, window: c_ulong, key: char) {
        let x = xlib();
        let name = std::ffi::CString::new(key.to_string()).expect("a key without NUL");
        // SAFETY: an open display, a window of it; the event is plain data filled in here.
        unsafe {
            let sym = (x.XStringToKeysym)(name.as_ptr());
            let code = (x.XKeysymToKeycode)(self.0, sym);
            assert!(code != 0, "no key code for {key:?}");
            for (kind, mask) in [
                (xlib::KeyPress, xlib::KeyPressMask),
                (xlib::KeyRelease, xlib::KeyReleaseMask),
            ] {
                let mut e: xlib::XEvent = std::mem::zeroed();
                e.key = xlib::XKeyEvent {
                    type_: kind,
                    serial: 0,
                    send_event: xlib::True,
                    display: self.0,
                    window,
                    root: (x.XDefaultRootWindow)(self.0),
                    subwindow: 0,
                    time: xlib::CurrentTime,
                    x: 1,
                    y: 1,
                    x_root: 1,
                    y_root: 1,
                    state: 0,
                    keycode: u32::from(code),
                    same_screen: xlib::True,
                };
                (x.XSendEvent)(self.0, window, xlib::True, mask, &mut e);
            }
            (x.XSync)(self.0, xlib::False);
        }
    }

    /// Reads `drawable` back from the server (XGetImage): RGB, top row first.
    pub fn read(&self, drawable: c_ulong) -> Image {
        let x = xlib();
        // SAFETY: an open display and a drawable of it; Xlib allocates the image.
        unsafe {
            let (mut root, mut px, mut py, mut w, mut h, mut b, mut d) = (0, 0, 0, 0, 0, 0, 0);
            (x.XGetGeometry)(
                self.0, drawable, &mut root, &mut px, &mut py, &mut w, &mut h, &mut b, &mut d,
            );
            let im = (x.XGetImage)(
                self.0,
                drawable,
                0,
                0,
                w,
                h,
                (x.XAllPlanes)(),
                xlib::ZPixmap,
            );
            assert!(!im.is_null(), "XGetImage of {drawable:#x} failed");
            let (mut rm, mut gm, mut bm) = ((*im).red_mask, (*im).green_mask, (*im).blue_mask);
            if rm | gm | bm == 0 {
                // A pixmap has no visual: the server's usual 24-bit layout.
                (rm, gm, bm) = (0xff0000, 0xff00, 0xff);
            }
            let comp = |v: c_ulong, m: c_ulong| -> u8 {
                if m == 0 {
                    return 0;
                }
                ((v & m) >> m.trailing_zeros()) as u8
            };
            let mut rgb = Vec::with_capacity(w as usize * h as usize * 3);
            for y in 0..h as c_int {
                for xx in 0..w as c_int {
                    let v = (x.XGetPixel)(im, xx, y);
                    rgb.extend_from_slice(&[comp(v, rm), comp(v, gm), comp(v, bm)]);
                }
            }
            (x.XDestroyImage)(im);
            Image {
                width: w,
                height: h,
                rgb,
            }
        }
    }
}

/// An RGB8 image, top row first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

impl Image {
    /// A binary PPM (P6) file.
    pub fn load_ppm(path: &Path) -> Image {
        let data = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut fields = Vec::new();
        let mut i = 0;
        while fields.len() < 4 {
            while i < data.len() && data[i].is_ascii_whitespace() {
                i += 1;
            }
            if data.get(i) == Some(&b'#') {
                while i < data.len() && data[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            let start = i;
            while i < data.len() && !data[i].is_ascii_whitespace() {
                i += 1;
            }
            assert!(i > start, "{}: not a PPM", path.display());
            fields.push(String::from_utf8_lossy(&data[start..i]).into_owned());
        }
        assert_eq!(fields[0], "P6", "{}: not a binary PPM", path.display());
        let (w, h): (u32, u32) = (
            fields[1].parse().expect("width"),
            fields[2].parse().expect("height"),
        );
        let n = w as usize * h as usize * 3;
        let rgb = data[i + 1..]
            .get(..n)
            .unwrap_or_else(|| panic!("{}: short", path.display()))
            .to_vec();
        Image {
            width: w,
            height: h,
            rgb,
        }
    }

    /// Writes a binary PPM (for looking at a failure).
    pub fn save_ppm(&self, path: &Path) {
        let mut out = format!("P6\n{} {}\n255\n", self.width, self.height).into_bytes();
        out.extend_from_slice(&self.rgb);
        let _ = std::fs::write(path, out);
    }

    /// The pixel at (x, y).
    pub fn at(&self, x: u32, y: u32) -> [u8; 3] {
        let i = (y as usize * self.width as usize + x as usize) * 3;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }
}

/// How two images differ: pixels off by more than CHANNEL, their percentage, the largest
/// channel difference.
#[derive(Clone, Copy, Debug)]
pub struct Diff {
    pub off: usize,
    pub percent: f64,
    pub max: u8,
}

pub fn diff(a: &Image, b: &Image) -> Diff {
    assert_eq!(
        (a.width, a.height),
        (b.width, b.height),
        "image sizes differ"
    );
    let mut off = 0;
    let mut max = 0;
    for (p, q) in a.rgb.chunks_exact(3).zip(b.rgb.chunks_exact(3)) {
        let d = p
            .iter()
            .zip(q)
            .map(|(x, y)| x.abs_diff(*y))
            .max()
            .unwrap_or(0);
        max = max.max(d);
        if d > CHANNEL {
            off += 1;
        }
    }
    let total = (a.width as usize * a.height as usize).max(1);
    Diff {
        off,
        percent: 100.0 * off as f64 / total as f64,
        max,
    }
}

/// Asserts that fixedgl's image matches Mesa's within the tolerance, printing the figures (and
/// saving both images next to the test binary when they do not match).
pub fn assert_close(what: &str, fixedgl: &Image, mesa: &Image) {
    let d = diff(fixedgl, mesa);
    let _ =
        writeln!(
        std::io::stderr(),
        "{what}: {}x{}, {} pixels off by more than {CHANNEL}/255 ({:.4}%), largest difference {}",
        fixedgl.width, fixedgl.height, d.off, d.percent, d.max
    );
    if d.percent > MAX_PERCENT {
        let dir = profile_dir().join("c-examples");
        let _ = std::fs::create_dir_all(&dir);
        let name: String = what
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
            .collect();
        fixedgl.save_ppm(&dir.join(format!("{name}.fixedgl.ppm")));
        mesa.save_ppm(&dir.join(format!("{name}.mesa.ppm")));
        panic!(
            "{what}: {:.4}% of the pixels are off (at most {MAX_PERCENT}% may be); images in {}",
            d.percent,
            dir.display()
        );
    }
}
