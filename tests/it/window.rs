//! Real windows (`fixedgl::window`, `fixedgl view`) on an X server: frames reach the screen as the
//! headless render of the same frame, a resize calls `reshape` with the new size, key and mouse
//! input reaches the listener, and without a display the error is clear.
//!
//! The screen is read back from the X server (GetImage, through x11rb), never from fixedgl's own
//! buffers. Each test uses `DISPLAY` when it is set, else starts its own Xvfb on a free display
//! (`Xvfb -displayfd`); without Xvfb it prints `SKIPPED: ...` and returns, unless
//! `FIXEDGL_REQUIRE_GL` is set (CI), which makes that a failure.
//!
//! winit allows one event loop per process, and the display must be chosen before it starts
//! (`DISPLAY`), so each window test runs in a child process: the parent test starts the X server
//! and runs this same test binary on one `child_*` test (ignored in normal runs; run with
//! `--ignored` outside a child, each does what its parent does) with `DISPLAY` pointing at it.
#![cfg(feature = "window")]

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use fixedgl::window::{Animator, Drawable, GlCanvas, GlEventListener, KeyEvent, MouseEvent};
use fixedgl::{gl, Context};
use image::RgbaImage;
use x11rb::connection::Connection;
use x11rb::protocol::xproto::{self, ConnectionExt as _};
use x11rb::protocol::xtest::ConnectionExt as _;
use x11rb::rust_connection::RustConnection;
use x11rb::wrapper::ConnectionExt as _;

// ---------------------------------------------------------------------------------------------
// The X server.

/// An Xvfb this test started; stopped when dropped.
struct Xvfb {
    child: Child,
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The display to open windows on, and the Xvfb serving it if the test started one; `None` after
/// printing why the test is skipped.
fn x_display() -> Option<(String, Option<Xvfb>)> {
    if let Some(d) = std::env::var("DISPLAY").ok().filter(|d| !d.is_empty()) {
        return Some((d, None));
    }
    // -noreset: by default Xvfb resets itself when its last client disconnects, and a client
    // that connects during the reset is dropped before its set-up is answered ("Failed to open
    // connection to X server"): a test that runs `fixedgl view` twice on one server hit that
    // window in a loaded CI run.
    let spawned = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "1280x1024x24",
            "-nolisten",
            "tcp",
            "-noreset",
        ])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn();
    let mut child = match spawned {
        Ok(c) => c,
        Err(e) if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() => panic!(
            "FIXEDGL_REQUIRE_GL is set, DISPLAY is not, and Xvfb cannot start ({e}): install \
             xvfb (.ci/run does)"
        ),
        Err(e) => {
            use std::io::Write as _;
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED: no DISPLAY and no Xvfb to start ({e}); apt-get install xvfb"
            );
            return None;
        }
    };
    // Xvfb writes the display number it chose to the -displayfd descriptor once it accepts
    // connections.
    let stdout = child.stdout.take();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        if let Some(out) = stdout {
            let _ = BufReader::new(out).read_line(&mut line);
        }
        let _ = tx.send(line);
    });
    let server = Xvfb { child };
    let line = rx.recv_timeout(Duration::from_secs(30));
    let number = match &line {
        Ok(l) => l.trim().parse::<u32>().ok(),
        Err(_) => None,
    };
    let Some(n) = number else {
        panic!("Xvfb started but did not report a display: {line:?}");
    };
    Some((format!(":{n}"), Some(server)))
}

/// Runs the ignored test `name` of this binary in a child process on `display` and fails with
/// its output unless it passed.
fn run_child(name: &str, display: &str) {
    let exe = std::env::current_exe().expect("the test binary's path");
    let out = Command::new(exe)
        .args([
            name,
            "--exact",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("DISPLAY", display)
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .env("FIXEDGL_WINDOW_CHILD", "1")
        .output()
        .expect("the child test runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stdout.contains("1 passed"),
        "child {name} failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
}

/// In a child test: true when the parent started it; otherwise (someone ran the ignored tests,
/// `cargo test -- --ignored`) runs `parent`, which starts the child properly, and is false.
fn in_child(parent: impl FnOnce()) -> bool {
    if std::env::var_os("FIXEDGL_WINDOW_CHILD").is_some() {
        return true;
    }
    parent();
    false
}

// ---------------------------------------------------------------------------------------------
// Reading the screen.

fn connect() -> (RustConnection, usize) {
    x11rb::connect(None).expect("the child connects to DISPLAY")
}

/// The top-level window titled `title` (searched through the whole tree, so that a window
/// manager's frames do not matter).
fn find_window(conn: &RustConnection, screen: usize, title: &str) -> Option<xproto::Window> {
    let net_wm_name = conn
        .intern_atom(false, b"_NET_WM_NAME")
        .ok()?
        .reply()
        .ok()?
        .atom;
    let mut stack = vec![conn.setup().roots[screen].root];
    while let Some(w) = stack.pop() {
        for atom in [net_wm_name, xproto::AtomEnum::WM_NAME.into()] {
            let name = conn
                .get_property(false, w, atom, xproto::AtomEnum::ANY, 0, 1024)
                .ok()
                .and_then(|c| c.reply().ok());
            if name.is_some_and(|p| p.value == title.as_bytes()) {
                return Some(w);
            }
        }
        if let Some(tree) = conn.query_tree(w).ok().and_then(|c| c.reply().ok()) {
            stack.extend(tree.children);
        }
    }
    None
}

/// What the X server shows in window `w`, as RGBA (alpha 255), through GetImage.
fn screenshot(conn: &RustConnection, w: xproto::Window) -> RgbaImage {
    let geometry = conn.get_geometry(w).unwrap().reply().unwrap();
    let (width, height) = (geometry.width, geometry.height);
    let image = conn
        .get_image(xproto::ImageFormat::Z_PIXMAP, w, 0, 0, width, height, !0)
        .unwrap()
        .reply()
        .unwrap();
    let setup = conn.setup();
    let format = setup
        .pixmap_formats
        .iter()
        .find(|f| f.depth == image.depth)
        .expect("a pixmap format for the window's depth");
    assert_eq!(format.bits_per_pixel, 32, "the test reads 32-bit pixels");
    let visual = setup
        .roots
        .iter()
        .flat_map(|s| &s.allowed_depths)
        .flat_map(|d| &d.visuals)
        .find(|v| v.visual_id == image.visual)
        .expect("the window's visual");
    let little = setup.image_byte_order == xproto::ImageOrder::LSB_FIRST;
    let channel = |px: u32, mask: u32| ((px & mask) >> mask.trailing_zeros()) as u8;
    let stride = image.data.len() / usize::from(height.max(1));
    RgbaImage::from_fn(u32::from(width), u32::from(height), |x, y| {
        let i = y as usize * stride + 4 * x as usize;
        let b: [u8; 4] = image.data[i..i + 4].try_into().unwrap();
        let px = if little {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        };
        image::Rgba([
            channel(px, visual.red_mask),
            channel(px, visual.green_mask),
            channel(px, visual.blue_mask),
            255,
        ])
    })
}

/// `img` as the window shows it: alpha dropped.
fn opaque(mut img: RgbaImage) -> RgbaImage {
    for p in img.pixels_mut() {
        p.0[3] = 255;
    }
    img
}

/// Screenshots window `title` until it shows `expected` (the server may still be drawing the last
/// request of the presenting connection), at most 5 s; the last screenshot otherwise.
fn screen_until(title: &str, expected: &RgbaImage) -> RgbaImage {
    let (conn, screen) = connect();
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        let shot = find_window(&conn, screen, title)
            .map(|w| screenshot(&conn, w))
            .unwrap_or_default();
        if &shot == expected || Instant::now() > deadline {
            return shot;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Fails with the first differing pixel unless the images are equal.
fn assert_same(what: &str, got: &RgbaImage, expected: &RgbaImage) {
    assert_eq!(got.dimensions(), expected.dimensions(), "{what}: size");
    let first = got
        .enumerate_pixels()
        .zip(expected.pixels())
        .find(|((_, _, a), b)| a != b)
        .map(|((x, y, a), b)| format!("({x}, {y}): screen {:?}, headless {:?}", a.0, b.0));
    let differing = got
        .pixels()
        .zip(expected.pixels())
        .filter(|(a, b)| a != b)
        .count();
    if differing > 0 {
        // Both pictures, for a person to look at.
        let dir = std::env::temp_dir();
        let stem = what.replace(|c: char| !c.is_ascii_alphanumeric(), "-");
        let _ = got.save(dir.join(format!("fixedgl-{stem}-screen.png")));
        let _ = expected.save(dir.join(format!("fixedgl-{stem}-headless.png")));
    }
    assert!(
        first.is_none(),
        "{what}: {differing} pixels differ, first at {first:?}"
    );
}

// ---------------------------------------------------------------------------------------------
// A JOGL-shaped program: init sets state once, display draws with the clock.

/// A smooth triangle turning about z with the clock, over a depth-tested quad: the state set in
/// `init` (clear colour, depth test, shading) persists, as in JOGL.
fn spinner_init(gl: &mut Context) {
    gl.clear_color(0.1, 0.2, 0.3, 1.0);
    gl.enable(gl::DEPTH_TEST);
    gl.shade_model(gl::SMOOTH);
}

fn spinner_display(gl: &mut Context, t: f64) {
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.matrix_mode(gl::MODELVIEW);
    gl.load_identity();
    gl.rotatef((90.0 * t) as f32, 0.0, 0.0, 1.0);
    gl.begin(gl::TRIANGLES);
    gl.color3f(1.0, 0.0, 0.0);
    gl.vertex3f(-0.7, -0.6, 0.0);
    gl.color3f(0.0, 1.0, 0.0);
    gl.vertex3f(0.7, -0.6, 0.0);
    gl.color3f(0.0, 0.0, 1.0);
    gl.vertex3f(0.0, 0.8, 0.0);
    gl.end();
    gl.load_identity();
    gl.begin(gl::QUADS);
    gl.color3f(1.0, 1.0, 0.0);
    for (x, y) in [(-0.9, -0.9), (-0.3, -0.9), (-0.3, -0.3), (-0.9, -0.3)] {
        gl.vertex3f(x, y, 0.5);
    }
    gl.end();
}

/// The headless render of frames 0..frames at `size` with the clock at `step` a frame: the same
/// calls on one context, as the window made them.
fn spinner_headless(size: (u32, u32), frames: u64, step: f64) -> RgbaImage {
    let mut gl = Context::new(size.0, size.1).unwrap();
    spinner_init(&mut gl);
    gl.viewport(0, 0, size.0 as i32, size.1 as i32);
    for k in 0..frames {
        spinner_display(&mut gl, k as f64 * step);
    }
    opaque(gl.to_image())
}

/// Makes the headless render a screenshot is compared with, from what the spinner saw.
type Expected = Box<dyn Fn(&Spinner) -> RgbaImage>;

/// Records what the runner called, and takes the screenshot in `dispose` (the window is still on
/// the screen then, showing the last presented frame).
#[derive(Default)]
struct Spinner {
    title: String,
    inits: u32,
    reshapes: Vec<(i32, i32, u32, u32)>,
    displays: Vec<(u64, f64, (u32, u32))>,
    /// Resizes to make, each at a frame: (frame, size, through the X server rather than the API).
    resizes: Vec<(u64, (u32, u32), bool)>,
    /// Exit after the first frame presented at this size (and one more).
    exit_at_size: Option<(u32, u32)>,
    frames_at_exit_size: u32,
    /// The screenshot and the headless render to compare it with, made in dispose.
    expected_in_dispose: Option<Expected>,
    shot: Option<(RgbaImage, RgbaImage)>,
}

impl GlEventListener for Spinner {
    fn init(&mut self, gl: &mut Context, _d: &mut Drawable) {
        self.inits += 1;
        spinner_init(gl);
    }

    fn reshape(&mut self, gl: &mut Context, d: &mut Drawable, x: i32, y: i32, w: u32, h: u32) {
        assert_eq!(gl.size(), (w, h), "the context follows the window");
        assert_eq!(d.size(), (w, h));
        let mut viewport = [0i32; 4];
        gl.get_integerv(gl::VIEWPORT, &mut viewport);
        assert_eq!(
            viewport,
            [0, 0, w as i32, h as i32],
            "viewport set before reshape"
        );
        self.reshapes.push((x, y, w, h));
    }

    fn display(&mut self, gl: &mut Context, d: &mut Drawable) {
        assert_eq!(gl.size(), d.size());
        self.displays.push((d.frame(), d.time(), d.size()));
        spinner_display(gl, d.time());
        for &(frame, (w, h), external) in &self.resizes {
            if frame != d.frame() {
                continue;
            }
            if external {
                // As a user dragging the border (or a window manager) would: the X server
                // resizes the window, winit reports it.
                let (conn, screen) = connect();
                let win = find_window(&conn, screen, &self.title).expect("our window");
                let aux = xproto::ConfigureWindowAux::new().width(w).height(h);
                conn.configure_window(win, &aux).unwrap();
                conn.flush().unwrap();
                conn.sync().unwrap();
            } else {
                d.set_size(w, h);
            }
        }
        if Some(d.size()) == self.exit_at_size {
            self.frames_at_exit_size += 1;
            if self.frames_at_exit_size >= 2 {
                d.exit();
            }
        }
    }

    fn dispose(&mut self, _gl: &mut Context, _d: &mut Drawable) {
        if let Some(expected) = self.expected_in_dispose.take() {
            let want = expected(self);
            let got = screen_until(&self.title, &want);
            self.shot = Some((got, want));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The tests.

/// A window is created, N frames are presented, and the screen then shows exactly the headless
/// render of frame N-1; init once, reshape once with the window's size, display N times on a
/// fixed clock.
#[test]
fn window_frames_reach_the_screen() {
    if let Some((display, _xvfb)) = x_display() {
        run_child("window::child_frames_reach_the_screen", &display);
    }
}

#[test]
#[ignore = "run in a child process by window::window_frames_reach_the_screen"]
fn child_frames_reach_the_screen() {
    if !in_child(window_frames_reach_the_screen) {
        return;
    }
    const N: u64 = 7;
    const SIZE: (u32, u32) = (240, 180);
    let step = 1.0 / 30.0;
    let mut spinner = Spinner {
        title: "fixedgl test: frames".into(),
        expected_in_dispose: Some(Box::new(move |_| spinner_headless(SIZE, N, step))),
        ..Spinner::default()
    };
    let stats = GlCanvas::new(SIZE.0, SIZE.1)
        .title(spinner.title.clone())
        .animator(Animator::Continuous)
        .frames(N)
        .run(&mut spinner)
        .expect("a window opens on the display");
    assert_eq!(stats.frames, N);
    assert_eq!(stats.size, SIZE);
    assert_eq!(spinner.inits, 1);
    assert_eq!(spinner.reshapes, vec![(0, 0, SIZE.0, SIZE.1)]);
    let frames: Vec<u64> = spinner.displays.iter().map(|d| d.0).collect();
    assert_eq!(frames, (0..N).collect::<Vec<_>>());
    for &(k, t, _) in &spinner.displays {
        assert_eq!(t, k as f64 * step, "the clock of a counted run is fixed");
    }
    let (got, want) = spinner.shot.take().expect("dispose took the screenshot");
    assert_same("the last frame on the screen", &got, &want);
    // The picture did change over the frames: frame 0 alone is another image.
    assert_ne!(want, spinner_headless(SIZE, 1, step));

    // The same thread opens a second window (the one event loop is reused), at the target FPS:
    // 6 frames at 20 FPS take at least 5 periods.
    let mut again = Spinner {
        title: "fixedgl test: second window".into(),
        ..Spinner::default()
    };
    let start = Instant::now();
    let stats = GlCanvas::new(64, 48)
        .title(again.title.clone())
        .animator(Animator::Fps(20.0))
        .frames(6)
        .run(&mut again)
        .expect("a second window on the same thread");
    assert_eq!(stats.frames, 6);
    assert!(
        start.elapsed() >= Duration::from_millis(240),
        "{:?}",
        start.elapsed()
    );
    assert!(
        stats.fps > 0.0 && stats.fps < 22.0,
        "measured {} fps",
        stats.fps
    );
    assert_eq!(again.displays.last().map(|d| d.1), Some(5.0 / 20.0));
}

/// Resizing the window (through the X server, as a user would, then through the API) calls
/// `reshape` with each new size, the context follows, and the screen shows the frame at the new
/// size exactly as the headless render.
#[test]
fn window_resize_calls_reshape() {
    if let Some((display, _xvfb)) = x_display() {
        run_child("window::child_resize_calls_reshape", &display);
    }
}

#[test]
#[ignore = "run in a child process by window::window_resize_calls_reshape"]
fn child_resize_calls_reshape() {
    if !in_child(window_resize_calls_reshape) {
        return;
    }
    let first = (200, 150);
    let external = (260, 190);
    let api = (150, 210);
    let mut spinner = Spinner {
        title: "fixedgl test: resize".into(),
        resizes: vec![(2, external, true)],
        exit_at_size: Some(api),
        ..Spinner::default()
    };
    spinner.expected_in_dispose = Some(Box::new(move |s: &Spinner| {
        // The last frame, at the final size: the context was made anew at that size (init ran
        // again), so the headless render is init then that one frame's display.
        let &(_, t, size) = s.displays.last().unwrap();
        let mut gl = Context::new(size.0, size.1).unwrap();
        spinner_init(&mut gl);
        spinner_display(&mut gl, t);
        opaque(gl.to_image())
    }));
    // Once the external resize has landed, ask for the API one.
    struct Then<'a>(&'a mut Spinner, (u32, u32), (u32, u32));
    impl GlEventListener for Then<'_> {
        fn init(&mut self, gl: &mut Context, d: &mut Drawable) {
            self.0.init(gl, d)
        }
        fn reshape(&mut self, gl: &mut Context, d: &mut Drawable, x: i32, y: i32, w: u32, h: u32) {
            self.0.reshape(gl, d, x, y, w, h);
            if (w, h) == self.1 {
                d.set_size(self.2 .0, self.2 .1);
            }
        }
        fn display(&mut self, gl: &mut Context, d: &mut Drawable) {
            self.0.display(gl, d)
        }
        fn dispose(&mut self, gl: &mut Context, d: &mut Drawable) {
            self.0.dispose(gl, d)
        }
    }
    let stats = GlCanvas::new(first.0, first.1)
        .title(spinner.title.clone())
        .animator(Animator::Continuous)
        .frames(500)
        .run(&mut Then(&mut spinner, external, api))
        .expect("a window opens on the display");
    let sizes: Vec<(u32, u32)> = spinner.reshapes.iter().map(|r| (r.2, r.3)).collect();
    assert_eq!(
        sizes,
        vec![first, external, api],
        "reshape follows every resize"
    );
    assert!(spinner.reshapes.iter().all(|r| (r.0, r.1) == (0, 0)));
    assert_eq!(stats.size, api);
    assert!(stats.frames < 500, "the resizes took effect");
    let (got, want) = spinner.shot.take().expect("dispose took the screenshot");
    assert_same("the frame after the resizes", &got, &want);
}

/// Keys and the mouse, sent through the X server's XTEST extension, reach the listener's
/// JOGL-style methods: pressed / typed / released, moved, pressed / released / clicked, dragged,
/// wheel.
#[test]
fn window_input_reaches_the_listener() {
    if let Some((display, _xvfb)) = x_display() {
        run_child("window::child_input_reaches_the_listener", &display);
    }
}

#[derive(Default)]
struct Recorder {
    title: String,
    events: Vec<String>,
    sent: bool,
}

impl Recorder {
    fn mouse(&mut self, what: &str, e: &MouseEvent) {
        self.events.push(format!(
            "{what} {:?} ({}, {}) left={} wheel={}",
            e.button, e.x, e.y, e.buttons.left, e.wheel_rotation
        ));
    }

    fn done(&self) -> bool {
        self.events.iter().any(|e| e.starts_with("wheel"))
    }
}

impl GlEventListener for Recorder {
    fn display(&mut self, gl: &mut Context, d: &mut Drawable) {
        gl.clear(gl::COLOR_BUFFER_BIT);
        if d.frame() == 3 && !self.sent {
            self.sent = true;
            send_input(&self.title);
        }
        if self.done() {
            d.exit();
        }
    }
    fn key_pressed(&mut self, e: &KeyEvent, _d: &mut Drawable) {
        self.events.push(format!("pressed {:?}", e.key));
    }
    fn key_typed(&mut self, e: &KeyEvent, _d: &mut Drawable) {
        self.events.push(format!("typed {:?}", e.text));
    }
    fn key_released(&mut self, e: &KeyEvent, _d: &mut Drawable) {
        self.events.push(format!("released {:?}", e.key));
    }
    fn mouse_moved(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("moved", e);
    }
    fn mouse_dragged(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("dragged", e);
    }
    fn mouse_pressed(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("pressed", e);
    }
    fn mouse_released(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("released", e);
    }
    fn mouse_clicked(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("clicked", e);
    }
    fn mouse_wheel_moved(&mut self, e: &MouseEvent, _d: &mut Drawable) {
        self.mouse("wheel", e);
    }
}

/// Through XTEST: the pointer to (50, 40) in the window, the key A (with Shift, so that typed and
/// key differ), a click there, a drag to (90, 70), one wheel notch down.
fn send_input(title: &str) {
    use x11rb::protocol::xproto::{BUTTON_PRESS_EVENT, BUTTON_RELEASE_EVENT};
    use x11rb::protocol::xproto::{KEY_PRESS_EVENT, KEY_RELEASE_EVENT, MOTION_NOTIFY_EVENT};
    let (conn, screen) = connect();
    let root = conn.setup().roots[screen].root;
    let win = find_window(&conn, screen, title).expect("our window");
    let origin = conn
        .translate_coordinates(win, root, 0, 0)
        .unwrap()
        .reply()
        .unwrap();
    let (ox, oy) = (origin.dst_x, origin.dst_y);
    // The keycodes of the keysyms `a` and Shift_L in the server's keymap.
    let (min, max) = (conn.setup().min_keycode, conn.setup().max_keycode);
    let map = conn
        .get_keyboard_mapping(min, max - min + 1)
        .unwrap()
        .reply()
        .unwrap();
    let per = usize::from(map.keysyms_per_keycode);
    let code_of = |sym: u32| {
        map.keysyms
            .chunks(per)
            .position(|c| c.first() == Some(&sym))
            .map(|i| min + i as u8)
            .expect("the keysym is in the keymap")
    };
    let (a, shift) = (code_of(0x61), code_of(0xffe1));
    // Keyboard focus on the window, as a window manager gives it on a click.
    conn.set_input_focus(xproto::InputFocus::PARENT, win, x11rb::CURRENT_TIME)
        .unwrap();
    let fake = |kind: u8, detail: u8, x: i16, y: i16| {
        conn.xtest_fake_input(kind, detail, 0, root, ox + x, oy + y, 0)
            .unwrap();
        conn.sync().unwrap();
    };
    fake(MOTION_NOTIFY_EVENT, 0, 50, 40);
    fake(KEY_PRESS_EVENT, shift, 0, 0);
    fake(KEY_PRESS_EVENT, a, 0, 0);
    fake(KEY_RELEASE_EVENT, a, 0, 0);
    fake(KEY_RELEASE_EVENT, shift, 0, 0);
    fake(BUTTON_PRESS_EVENT, 1, 0, 0);
    fake(BUTTON_RELEASE_EVENT, 1, 0, 0);
    fake(BUTTON_PRESS_EVENT, 1, 0, 0);
    fake(MOTION_NOTIFY_EVENT, 0, 90, 70);
    fake(BUTTON_RELEASE_EVENT, 1, 0, 0);
    fake(BUTTON_PRESS_EVENT, 5, 0, 0);
    fake(BUTTON_RELEASE_EVENT, 5, 0, 0);
}

#[test]
#[ignore = "run in a child process by window::window_input_reaches_the_listener"]
fn child_input_reaches_the_listener() {
    if !in_child(window_input_reaches_the_listener) {
        return;
    }
    let mut rec = Recorder {
        title: "fixedgl test: input".into(),
        ..Recorder::default()
    };
    GlCanvas::new(160, 120)
        .title(rec.title.clone())
        .animator(Animator::Fps(100.0))
        .frames(1000)
        .run(&mut rec)
        .expect("a window opens on the display");
    // Pointer moves before the test's own (the server's pointer may start over the window) are
    // not the test's business: keep the events from the first one at (50, 40).
    let start = rec
        .events
        .iter()
        .position(|e| e.starts_with("moved None (50, 40)"))
        .unwrap_or_else(|| panic!("no move to (50, 40): {:#?}", rec.events));
    let mut events: Vec<&str> = rec.events[start..]
        .iter()
        .map(String::as_str)
        .filter(|e| !e.contains("Shift"))
        .collect();
    // A move to where the pointer already is (the X server reports one on focus and crossing
    // changes) says nothing new.
    events.dedup_by(|b, a| a.starts_with("moved") && a == b);
    let expected = [
        "moved None (50, 40) left=false wheel=0",
        "pressed Char('a')",
        "typed Some('A')",
        "released Char('a')",
        "pressed Some(Left) (50, 40) left=true wheel=0",
        "released Some(Left) (50, 40) left=false wheel=0",
        "clicked Some(Left) (50, 40) left=false wheel=0",
        "pressed Some(Left) (50, 40) left=true wheel=0",
        "dragged None (90, 70) left=true wheel=0",
        "released Some(Left) (90, 70) left=false wheel=0",
    ];
    assert_eq!(
        &events[..expected.len()],
        expected,
        "all: {:#?}",
        rec.events
    );
    // One notch down. winit reports a wheel click that comes as buttons 4 and 5 (XTEST's, and
    // some mice's) on the press and again on the release; smooth-scrolling devices once.
    let wheel = &events[expected.len()..];
    assert!(
        (1..=2).contains(&wheel.len())
            && wheel
                .iter()
                .all(|e| *e == "wheel None (90, 70) left=false wheel=1"),
        "{wheel:#?}"
    );
}

/// Without a display, `view` and a window program fail with a clear message (exit 1, no panic),
/// and headless rendering still works.
#[cfg(feature = "cli")]
#[test]
fn no_display_is_a_clear_error() {
    let dir = std::env::temp_dir().join(format!("fixedgl-no-display-{}", std::process::id()));
    let png = dir.join("t.png");
    std::fs::create_dir_all(&dir).unwrap();
    for display in [None, Some(":4093")] {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_fixedgl"));
        cmd.args(["view", "triangle", "--frames", "1"])
            .env_remove("WAYLAND_DISPLAY")
            .env_remove("WAYLAND_SOCKET");
        match display {
            Some(d) => cmd.env("DISPLAY", d),
            None => cmd.env_remove("DISPLAY"),
        };
        let out = cmd.output().expect("fixedgl runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{display:?}: {stderr}");
        assert!(
            stderr.starts_with("fixedgl: window: no display to open a window on (")
                && stderr.contains("xvfb-run")
                && !stderr.contains("panicked"),
            "{display:?}: {stderr}"
        );
    }
    let out = Command::new(env!("CARGO_BIN_EXE_fixedgl"))
        .args(["render", "triangle", "--size", "16x16", "-o"])
        .arg(&png)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("fixedgl runs");
    let rendered = image::open(&png).map(|i| (i.width(), i.height()));
    let _ = std::fs::remove_dir_all(&dir);
    assert!(out.status.success(), "{out:?}");
    assert_eq!(rendered.ok(), Some((16, 16)));
}

/// The library says the same, as an `Err`: run in a child process without any display variable.
#[test]
fn no_display_is_an_err_from_the_library() {
    let exe = std::env::current_exe().expect("the test binary's path");
    let out = Command::new(exe)
        .args([
            "window::child_no_display_is_an_err",
            "--exact",
            "--ignored",
            "--nocapture",
        ])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .env("FIXEDGL_WINDOW_CHILD", "1")
        .output()
        .expect("the child test runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && stdout.contains("1 passed"),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
#[ignore = "run in a child process by window::no_display_is_an_err_from_the_library"]
fn child_no_display_is_an_err() {
    if !in_child(no_display_is_an_err_from_the_library) {
        return;
    }
    let mut spinner = Spinner::default();
    for _ in 0..2 {
        // Twice: winit refuses a second event loop after a failed one; the reason stays the same.
        let err = GlCanvas::new(10, 10)
            .frames(1)
            .run(&mut spinner)
            .unwrap_err();
        assert!(
            matches!(&err, fixedgl::Error::Window(m) if m.starts_with("no display")),
            "{err}"
        );
    }
    assert_eq!(spinner.inits, 0);
    // Headless rendering is untouched.
    let mut gl = Context::new(4, 4).unwrap();
    spinner_init(&mut gl);
    spinner_display(&mut gl, 0.0);
    assert_eq!(gl.get_error(), gl::NO_ERROR);
}

/// `fixedgl view`: `--frames N --record-frames DIR` exits 0 having presented N frames, each the
/// scene at `k / 60` s exactly as `Scene::record_at` renders it headless; with `--compare` the
/// panels are the CPU rendering and the driver's.
#[cfg(feature = "cli")]
#[test]
fn view_presents_the_scene_frames() {
    let Some((display, _xvfb)) = x_display() else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("fixedgl-view-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let view = |args: &[&str], out: &str| {
        let out_dir = dir.join(out);
        let status = Command::new(env!("CARGO_BIN_EXE_fixedgl"))
            .arg("view")
            .args(args)
            .arg("--record-frames")
            .arg(&out_dir)
            .env("DISPLAY", &display)
            .env_remove("WAYLAND_DISPLAY")
            .output()
            .expect("fixedgl runs");
        assert!(status.status.success(), "{args:?}: {status:?}");
        out_dir
    };
    let scene = fixedgl::scenes::find("cube-colors").unwrap();
    let frame = |dir: &std::path::Path, k: u32| {
        image::open(dir.join(format!("frame-{k:05}.png")))
            .unwrap()
            .to_rgba8()
    };
    let at = |k: u32| (f64::from(k) * (1.0 / 60.0)) as f32;

    let plain = view(
        &["cube-colors", "--size", "200x160", "--frames", "3"],
        "plain",
    );
    assert!(
        !plain.join("frame-00003.png").exists(),
        "3 frames, not more"
    );
    for k in 0..3 {
        let (mut ctx, _) = scene.record_at(200, 160, at(k)).unwrap();
        assert_same(
            &format!("view frame {k}"),
            &frame(&plain, k),
            &opaque(ctx.to_image()),
        );
    }

    // Two scenes, two frames each: the second starts its clock at 0 (its still picture).
    let two = view(
        &[
            "triangle",
            "cube-colors",
            "--size",
            "200x160",
            "--frames",
            "2",
        ],
        "two",
    );
    assert!(
        !two.join("frame-00004.png").exists(),
        "2 frames of each, not more"
    );
    let triangle = fixedgl::scenes::find("triangle").unwrap();
    let (mut still, _) = triangle.record(200, 160).unwrap();
    assert_same("first scene", &frame(&two, 1), &opaque(still.to_image()));
    let (mut still, _) = scene.record(200, 160).unwrap();
    assert_same(
        "second scene, frame 0",
        &frame(&two, 2),
        &opaque(still.to_image()),
    );
    let step = 1.0 / 60.0;
    let t = (3.0 * step - 2.0 * step) as f32;
    let (mut next, _) = scene.record_at(200, 160, t).unwrap();
    assert_same(
        "second scene, frame 1",
        &frame(&two, 3),
        &opaque(next.to_image()),
    );

    #[cfg(feature = "gl")]
    {
        use fixedgl::window::view::{BAR, GUTTER};
        let Some(mut gl) = crate::common::test_backend(120, 90) else {
            return;
        };
        let cmp = view(
            &[
                "cube-colors",
                "--compare",
                "--size",
                "120x90",
                "--frames",
                "2",
            ],
            "compare",
        );
        let shot = frame(&cmp, 1);
        assert_eq!(shot.dimensions(), (3 * 120 + 2 * GUTTER, 90 + BAR));
        let panel = |x0: u32| image::imageops::crop_imm(&shot, x0, BAR, 120, 90).to_image();
        let (mut ctx, calls) = scene.record_at(120, 90, at(1)).unwrap();
        assert_same("CPU panel", &panel(0), &opaque(ctx.to_image()));
        gl.replay(&calls);
        assert_same("GL panel", &panel(120 + GUTTER), &opaque(gl.read_image()));
        let diff = panel(2 * (120 + GUTTER));
        assert!(
            diff.pixels().all(|p| p.0[..3] == [0, 0, 0] || p.0[0] >= 64),
            "a heat map"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
