//! The event loop behind [`GlCanvas::run`]: winit's window and events, softbuffer's presentation,
//! the animator's schedule, and the JOGL order of listener calls (see the module docs of
//! `window`).

use std::cell::RefCell;
use std::collections::VecDeque;
use std::num::NonZeroU32;
use std::path::Path;
use std::rc::Rc;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use image::RgbaImage;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::error::EventLoopError;
use winit::event::{ElementState, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::platform::run_on_demand::EventLoopExtRunOnDemand;
use winit::window::{Window, WindowId};

use super::input::{self, MouseButton, MouseButtons, MouseEvent};
use super::{follow_size, Animator, Drawable, GlCanvas, GlEventListener, Modifiers, RunStats};
use crate::{Context, Error};

type Surface = softbuffer::Surface<Rc<Window>, Rc<Window>>;

thread_local! {
    /// The process's one winit event loop, on the thread that created it (see the module docs).
    static EVENT_LOOP: RefCell<Option<EventLoop<()>>> = const { RefCell::new(None) };
}

/// Why the event loop could not be created, when it could not: winit refuses a second attempt in
/// the same process, so later attempts report the first reason again.
static LOOP_FAILURE: OnceLock<String> = OnceLock::new();

/// The colour around a presented image smaller than the window.
const BACKGROUND: u32 = 0x0028_2828;

/// How far (pixels) the pointer may move between press and release for a click.
const CLICK_SLOP: f64 = 2.0;

pub(super) fn run<L: GlEventListener>(
    canvas: GlCanvas,
    listener: &mut L,
) -> Result<RunStats, Error> {
    EVENT_LOOP.with(|cell| {
        let mut slot = cell.try_borrow_mut().map_err(|_| {
            Error::Window(
                "a window is already running on this thread; fixedgl runs one window at a time"
                    .into(),
            )
        })?;
        if slot.is_none() {
            *slot = Some(create_event_loop()?);
        }
        let Some(event_loop) = slot.as_mut() else {
            return Err(Error::Window("the event loop is missing".into()));
        };
        let mut app = App::new(canvas, listener);
        let result = event_loop.run_app_on_demand(&mut app);
        if let Some(e) = app.error.take() {
            return Err(e);
        }
        result.map_err(|e| Error::Window(format!("the event loop failed: {e}")))?;
        Ok(app.stats())
    })
}

/// The event loop, or why there can be none: no display, or a window system that cannot start.
fn create_event_loop() -> Result<EventLoop<()>, Error> {
    if let Some(reason) = LOOP_FAILURE.get() {
        return Err(Error::Window(reason.clone()));
    }
    // winit panics (instead of returning an error) when a library it loads at run time is
    // missing, e.g. libxkbcommon-x11: caught, so that the caller gets an `Err` all the same.
    let built = std::panic::catch_unwind(|| {
        let mut builder = EventLoop::builder();
        // Any thread: the test harness and programs with their own main loop run windows off
        // the main thread, which X11 and Wayland allow.
        #[cfg(any(
            target_os = "linux",
            target_os = "dragonfly",
            target_os = "freebsd",
            target_os = "netbsd",
            target_os = "openbsd"
        ))]
        {
            use winit::platform::wayland::EventLoopBuilderExtWayland;
            use winit::platform::x11::EventLoopBuilderExtX11;
            EventLoopBuilderExtX11::with_any_thread(&mut builder, true);
            EventLoopBuilderExtWayland::with_any_thread(&mut builder, true);
        }
        builder.build()
    });
    let reason =
        match built {
            Ok(Ok(event_loop)) => return Ok(event_loop),
            Ok(Err(EventLoopError::RecreationAttempt)) => return Err(Error::Window(
                "another thread of this process already has the window event loop (winit allows \
                 one per process); open every window from that thread"
                    .into(),
            )),
            Ok(Err(e)) => format!(
                "no display to open a window on ({}); set DISPLAY (X11) or WAYLAND_DISPLAY \
             (Wayland), or run under xvfb-run. Rendering without a window (Context::new, \
             `fixedgl render`) needs neither",
                without_location(&e.to_string())
            ),
            Err(panic) => {
                let what = panic
                    .downcast_ref::<String>()
                    .map(String::as_str)
                    .or_else(|| panic.downcast_ref::<&str>().copied())
                    .unwrap_or("unknown reason");
                format!(
                "the window system could not start: {what} (on X11 winit needs libxkbcommon-x11; \
                 Debian: apt-get install libxkbcommon-x11-0)"
            )
            }
        };
    let _ = LOOP_FAILURE.set(reason.clone());
    Err(Error::Window(reason))
}

/// winit's message without the "os error at FILE:LINE: " prefix, which names winit's source.
fn without_location(message: &str) -> &str {
    message
        .strip_prefix("os error at ")
        .and_then(|rest| rest.splitn(3, ':').nth(2))
        .map_or(message, str::trim)
}

/// Frames per second over about the last second.
#[derive(Default)]
struct FpsMeter {
    times: VecDeque<Instant>,
}

impl FpsMeter {
    fn tick(&mut self, now: Instant) -> f64 {
        self.times.push_back(now);
        while self.times.len() > 2
            && self
                .times
                .front()
                .is_some_and(|t| now.duration_since(*t) > Duration::from_secs(1))
        {
            self.times.pop_front();
        }
        match (self.times.front(), self.times.len()) {
            (Some(first), n) if n >= 2 => {
                let s = now.duration_since(*first).as_secs_f64();
                if s > 0.0 {
                    (n - 1) as f64 / s
                } else {
                    0.0
                }
            }
            _ => 0.0,
        }
    }
}

struct App<'l, L: GlEventListener> {
    listener: &'l mut L,
    canvas: GlCanvas,
    step: Option<f64>,
    window: Option<Rc<Window>>,
    surface: Option<Surface>,
    surface_size: (u32, u32),
    gl: Option<Context>,
    d: Drawable,
    error: Option<Error>,
    presented: u64,
    first_frame: Option<Instant>,
    last_frame: Option<Instant>,
    next_due: Option<Instant>,
    redraw_pending: bool,
    need_reshape: bool,
    fps: FpsMeter,
    buttons: MouseButtons,
    modifiers: Modifiers,
    pressed_at: Vec<(MouseButton, (f64, f64))>,
    closed: bool,
}

impl<'l, L: GlEventListener> App<'l, L> {
    fn new(canvas: GlCanvas, listener: &'l mut L) -> Self {
        let d = Drawable::new(canvas.size, canvas.animator);
        App {
            listener,
            step: canvas.time_step(),
            canvas,
            window: None,
            surface: None,
            surface_size: (0, 0),
            gl: None,
            d,
            error: None,
            presented: 0,
            first_frame: None,
            last_frame: None,
            next_due: None,
            redraw_pending: false,
            need_reshape: true,
            fps: FpsMeter::default(),
            buttons: MouseButtons::default(),
            modifiers: Modifiers::default(),
            pressed_at: Vec::new(),
            closed: false,
        }
    }

    fn stats(&self) -> RunStats {
        let seconds = match (self.first_frame, self.last_frame) {
            (Some(a), Some(b)) => b.duration_since(a).as_secs_f64(),
            _ => 0.0,
        };
        RunStats {
            frames: self.presented,
            seconds,
            fps: self.d.fps,
            size: self.d.size,
        }
    }

    /// Opens the window, its surface and the context, then calls `init`.
    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<(), Error> {
        let (w, h) = self.canvas.size;
        let attributes = Window::default_attributes()
            .with_title(self.canvas.title.clone())
            .with_inner_size(PhysicalSize::new(w, h));
        let window = Rc::new(
            event_loop
                .create_window(attributes)
                .map_err(|e| Error::Window(format!("cannot create the window: {e}")))?,
        );
        let context = softbuffer::Context::new(window.clone())
            .map_err(|e| Error::Window(format!("cannot present to this display: {e}")))?;
        let surface = softbuffer::Surface::new(&context, window.clone())
            .map_err(|e| Error::Window(format!("cannot present to the window: {e}")))?;
        let size = window.inner_size();
        let (w, h) = if size.width == 0 || size.height == 0 {
            (w, h)
        } else {
            (size.width, size.height)
        };
        let mut gl = Context::with_config(w, h, self.canvas.config)?;
        self.d.size = (w, h);
        self.listener.init(&mut gl, &mut self.d);
        self.gl = Some(gl);
        self.surface = Some(surface);
        self.window = Some(window);
        self.need_reshape = true;
        self.request_redraw();
        Ok(())
    }

    fn request_redraw(&mut self) {
        if let Some(w) = &self.window {
            w.request_redraw();
            self.redraw_pending = true;
        }
    }

    /// One frame: follow the window's size, `reshape` if needed, `display`, present, record.
    fn frame(&mut self, event_loop: &ActiveEventLoop) -> Result<(), Error> {
        let (Some(window), Some(gl)) = (self.window.clone(), self.gl.as_mut()) else {
            return Ok(());
        };
        let size = window.inner_size();
        let (w, h) = (size.width, size.height);
        if w == 0 || h == 0 {
            return Ok(()); // Minimised: nothing to draw into.
        }
        self.d.size = (w, h);
        if gl.size() != (w, h) {
            if follow_size(gl, w, h)? {
                self.listener.init(gl, &mut self.d);
            }
            self.need_reshape = true;
        }
        if self.need_reshape {
            self.need_reshape = false;
            gl.viewport(0, 0, w as i32, h as i32);
            self.listener.reshape(gl, &mut self.d, 0, 0, w, h);
        }
        let start = Instant::now();
        let first = *self.first_frame.get_or_insert(start);
        self.d.frame = self.presented;
        self.d.time = match self.step {
            Some(step) => self.presented as f64 * step,
            None => start.duration_since(first).as_secs_f64(),
        };
        self.listener.display(gl, &mut self.d);
        let image = match self.d.image.take() {
            Some(image) => image,
            None if self.canvas.config.double_buffered => {
                gl.swap_buffers();
                RgbaImage::from_raw(w, h, gl.front_rgba())
                    .ok_or_else(|| Error::Window("the front buffer has the wrong size".into()))?
            }
            None => gl.to_image(),
        };
        self.present(&image, (w, h))?;
        if let Some(dir) = &self.canvas.record_dir {
            record(dir, self.presented, &image, (w, h))?;
        }
        let now = Instant::now();
        self.presented += 1;
        self.last_frame = Some(now);
        self.d.fps = self.fps.tick(now);
        if let Animator::Fps(fps) = self.d.animator {
            let period = Duration::from_secs_f64(1.0 / fps.clamp(0.001, 1000.0));
            let due = self.next_due.unwrap_or(start) + period;
            self.next_due = Some(due.max(now));
        }
        if self.canvas.frames.is_some_and(|n| self.presented >= n) {
            self.close(event_loop);
        }
        Ok(())
    }

    /// Copies `image` into the window's buffer (opaque; a smaller image at the top-left) and
    /// presents it.
    fn present(&mut self, image: &RgbaImage, (w, h): (u32, u32)) -> Result<(), Error> {
        let Some(surface) = self.surface.as_mut() else {
            return Ok(());
        };
        let fail = |e: softbuffer::SoftBufferError| Error::Window(format!("cannot present: {e}"));
        if self.surface_size != (w, h) {
            let (Some(nw), Some(nh)) = (NonZeroU32::new(w), NonZeroU32::new(h)) else {
                return Ok(());
            };
            surface.resize(nw, nh).map_err(fail)?;
            self.surface_size = (w, h);
        }
        let mut buffer = surface.buffer_mut().map_err(fail)?;
        let (iw, ih) = image.dimensions();
        let raw = image.as_raw();
        for (y, row) in buffer.chunks_exact_mut(w as usize).enumerate() {
            let y = y as u32;
            for (x, px) in row.iter_mut().enumerate() {
                let x = x as u32;
                *px = if x < iw && y < ih {
                    let i = 4 * (y as usize * iw as usize + x as usize);
                    match raw.get(i..i + 3) {
                        Some(&[r, g, b]) => {
                            (u32::from(r) << 16) | (u32::from(g) << 8) | u32::from(b)
                        }
                        _ => BACKGROUND,
                    }
                } else {
                    BACKGROUND
                };
            }
        }
        buffer.present().map_err(fail)
    }

    /// Ends the run: `dispose`, then the window goes, then the event loop returns.
    fn close(&mut self, event_loop: &ActiveEventLoop) {
        if self.closed {
            return;
        }
        self.closed = true;
        // On X11 the last frame may still wait in the connection's queue: softbuffer's
        // `buffer_mut` returns once the server has taken the previous image, so after this the
        // window shows the last presented frame while `dispose` runs (a run of N frames ends
        // showing frame N, and a screenshot taken now sees it).
        if let (Some(surface), Some(window)) = (self.surface.as_mut(), &self.window) {
            if is_x11(window) {
                let _ = surface.buffer_mut();
            }
        }
        if let Some(gl) = self.gl.as_mut() {
            self.listener.dispose(gl, &mut self.d);
        }
        self.surface = None;
        self.window = None;
        event_loop.exit();
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, e: Error) {
        if self.error.is_none() {
            self.error = Some(e);
        }
        self.close(event_loop);
    }

    /// Carries out what the listener asked of the drawable in its last callback.
    fn apply_requests(&mut self, event_loop: &ActiveEventLoop) {
        if let (Some(title), Some(window)) = (self.d.title.take(), &self.window) {
            window.set_title(&title);
        }
        if let (Some((w, h)), Some(window)) = (self.d.requested_size.take(), &self.window) {
            // Applied now (Some) or later with a Resized event; a redraw follows either way.
            let _ = window.request_inner_size(PhysicalSize::new(w, h));
            self.d.repaint = true;
        }
        if std::mem::take(&mut self.d.repaint) && !self.closed {
            self.request_redraw();
        }
        if self.d.exit {
            self.close(event_loop);
        }
    }

    fn mouse_event(&self, button: Option<MouseButton>, wheel_rotation: f64) -> MouseEvent {
        MouseEvent {
            x: self.d.pointer.0,
            y: self.d.pointer.1,
            button,
            buttons: self.buttons,
            wheel_rotation,
            modifiers: self.modifiers,
        }
    }

    fn input(&mut self, event: WindowEvent) {
        match event {
            WindowEvent::KeyboardInput { event, .. } => {
                let e = super::KeyEvent {
                    key: input::key(&event.logical_key),
                    text: input::typed(event.text.as_deref(), event.state),
                    repeat: event.repeat,
                    modifiers: self.modifiers,
                };
                match event.state {
                    ElementState::Pressed => {
                        self.listener.key_pressed(&e, &mut self.d);
                        if e.text.is_some() {
                            self.listener.key_typed(&e, &mut self.d);
                        }
                    }
                    ElementState::Released => self.listener.key_released(&e, &mut self.d),
                }
            }
            WindowEvent::ModifiersChanged(m) => self.modifiers = input::modifiers(m.state()),
            WindowEvent::CursorMoved { position, .. } => {
                self.d.pointer = (position.x, position.y);
                let e = self.mouse_event(None, 0.0);
                if self.buttons.any() {
                    self.listener.mouse_dragged(&e, &mut self.d);
                } else {
                    self.listener.mouse_moved(&e, &mut self.d);
                }
            }
            WindowEvent::MouseInput { state, button, .. } => {
                let button = input::button(button);
                let at = self.d.pointer;
                match state {
                    ElementState::Pressed => {
                        self.buttons.set(button, true);
                        self.pressed_at.retain(|(b, _)| *b != button);
                        self.pressed_at.push((button, at));
                        let e = self.mouse_event(Some(button), 0.0);
                        self.listener.mouse_pressed(&e, &mut self.d);
                    }
                    ElementState::Released => {
                        self.buttons.set(button, false);
                        let e = self.mouse_event(Some(button), 0.0);
                        self.listener.mouse_released(&e, &mut self.d);
                        let pressed = self.pressed_at.iter().position(|(b, _)| *b == button);
                        if let Some(i) = pressed {
                            let (_, (px, py)) = self.pressed_at.swap_remove(i);
                            if (at.0 - px).abs() <= CLICK_SLOP && (at.1 - py).abs() <= CLICK_SLOP {
                                self.listener.mouse_clicked(&e, &mut self.d);
                            }
                        }
                    }
                }
            }
            WindowEvent::MouseWheel { delta, .. } => {
                // AWT: positive rotation is towards the user, where winit's line delta is
                // negative; a touchpad's pixels count 40 to the notch.
                let rotation = match delta {
                    MouseScrollDelta::LineDelta(_, y) => -f64::from(y),
                    MouseScrollDelta::PixelDelta(p) => -p.y / 40.0,
                };
                if rotation != 0.0 {
                    let e = self.mouse_event(None, rotation);
                    self.listener.mouse_wheel_moved(&e, &mut self.d);
                }
            }
            WindowEvent::CursorEntered { .. } => {
                let e = self.mouse_event(None, 0.0);
                self.listener.mouse_entered(&e, &mut self.d);
            }
            WindowEvent::CursorLeft { .. } => {
                let e = self.mouse_event(None, 0.0);
                self.listener.mouse_exited(&e, &mut self.d);
            }
            _ => {}
        }
    }
}

/// Whether the window is on an X11 server.
fn is_x11(window: &Window) -> bool {
    use winit::raw_window_handle::{HasWindowHandle, RawWindowHandle};
    matches!(
        window.window_handle().map(|h| h.as_raw()),
        Ok(RawWindowHandle::Xlib(_) | RawWindowHandle::Xcb(_))
    )
}

/// Writes the presented frame `index` (what the window shows: opaque, the window's size).
fn record(dir: &Path, index: u64, image: &RgbaImage, (w, h): (u32, u32)) -> Result<(), Error> {
    std::fs::create_dir_all(dir)?;
    let shown = RgbaImage::from_fn(w, h, |x, y| match image.get_pixel_checked(x, y) {
        Some(p) => image::Rgba([p.0[0], p.0[1], p.0[2], 255]),
        None => {
            let [_, r, g, b] = BACKGROUND.to_be_bytes();
            image::Rgba([r, g, b, 255])
        }
    });
    shown.save(dir.join(format!("frame-{index:05}.png")))?;
    Ok(())
}

impl<L: GlEventListener> ApplicationHandler for App<'_, L> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() || self.closed {
            return;
        }
        if let Err(e) = self.open(event_loop) {
            self.fail(event_loop, e);
            return;
        }
        self.apply_requests(event_loop);
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, id: WindowId, event: WindowEvent) {
        // Events of an earlier run's window (its Destroyed, say) can arrive in this run.
        if self.closed || self.window.as_ref().map(|w| w.id()) != Some(id) {
            return;
        }
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => self.close(event_loop),
            WindowEvent::Resized(_) => self.request_redraw(),
            WindowEvent::RedrawRequested => {
                self.redraw_pending = false;
                if let Err(e) = self.frame(event_loop) {
                    self.fail(event_loop, e);
                }
            }
            other => self.input(other),
        }
        self.apply_requests(event_loop);
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.closed || self.window.is_none() {
            return;
        }
        // Counting frames needs frames: on demand then means one after another.
        let animator = match self.d.animator {
            Animator::OnDemand if self.canvas.frames.is_some() => Animator::Continuous,
            a => a,
        };
        match animator {
            Animator::OnDemand => event_loop.set_control_flow(ControlFlow::Wait),
            Animator::Continuous => {
                if !self.redraw_pending {
                    self.request_redraw();
                }
                event_loop.set_control_flow(ControlFlow::Wait);
            }
            Animator::Fps(_) => {
                let now = Instant::now();
                match self.next_due {
                    Some(due) if due > now => {
                        event_loop.set_control_flow(ControlFlow::WaitUntil(due))
                    }
                    _ => {
                        if !self.redraw_pending {
                            self.request_redraw();
                        }
                        event_loop.set_control_flow(ControlFlow::Wait);
                    }
                }
            }
        }
    }

    fn exiting(&mut self, event_loop: &ActiveEventLoop) {
        self.close(event_loop);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn winit_locations_are_left_out() {
        assert_eq!(
            without_location("os error at /x/src/linux/mod.rs:765: neither DISPLAY is set."),
            "neither DISPLAY is set."
        );
        assert_eq!(without_location("plain"), "plain");
    }

    #[test]
    fn fps_meter_counts_frames_over_the_last_second() {
        let mut m = FpsMeter::default();
        let t0 = Instant::now();
        assert_eq!(m.tick(t0), 0.0);
        let mut fps = 0.0;
        for i in 1..=100u64 {
            fps = m.tick(t0 + Duration::from_millis(20 * i));
        }
        assert!((fps - 50.0).abs() < 1.0, "{fps}");
    }
}
