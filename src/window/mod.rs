//! Windows and animation (cargo feature `window`): a fixedgl [`Context`] shown in a window, driven
//! the way JOGL drives a `GLCanvas`, so that a lecture example ports method by method.
//!
//! ```text
//! JOGL                                   fixedgl::window
//! class R implements GLEventListener     impl GlEventListener for R
//!   init(GLAutoDrawable d)                 fn init(&mut self, gl: &mut Context, d: &mut Drawable)
//!   display(GLAutoDrawable d)              fn display(&mut self, gl: &mut Context, d: &mut Drawable)
//!   reshape(d, x, y, w, h)                 fn reshape(&mut self, gl, d, x, y, w, h)
//!   dispose(GLAutoDrawable d)              fn dispose(&mut self, gl, d)
//! KeyListener, MouseListener,            key_pressed / key_released / key_typed, mouse_pressed /
//!   MouseMotionListener,                   released / clicked / moved / dragged / entered / exited,
//!   MouseWheelListener                     mouse_wheel_moved: methods of the same trait
//! new GLCanvas(caps) + JFrame            GlCanvas::new(800, 800).title("...")
//! new FPSAnimator(canvas, 60).start()    .animator(Animator::Fps(60.0))
//! animator.getLastFPS()                  d.fps()
//! canvas.display() / repaint()           d.repaint()
//! frame.setVisible(true)                 .run(&mut listener)?
//! ```
//!
//! What the window shows is the context's colour buffer, copied to the window with softbuffer after
//! each `display` (so it is double-buffered: a frame is never seen half drawn). winit opens the
//! window and delivers its events; no GPU is involved, so it works on X11, Wayland and Xvfb alike.
//!
//! The design decisions to know:
//! - **Order of calls.** As JOGL's `GLDrawableHelper`: `init` once, then `reshape(0, 0, w, h)`
//!   with `glViewport(0, 0, w, h)` already made, then `display` for every frame; `reshape` again
//!   (viewport first) whenever the window's size changes; `dispose` when the window closes.
//! - **Resizing.** The context's framebuffer follows the window (`Context::resize`): its GL state
//!   is kept, the buffers take the new size, and `reshape` is called (viewport first).
//! - **Time.** [`Drawable::time`] is the animation clock. It is wall-clock seconds since the
//!   first frame, except when frames are counted or recorded ([`GlCanvas::frames`],
//!   [`GlCanvas::record_frames`]): then every frame advances it by a fixed step (1/target FPS,
//!   1/30 s without a target), so that frame N is the same picture on every machine, and a
//!   recording plays at its nominal rate however slowly it was rendered.
//! - **Events** reach the listener between frames, on the same thread, without the context (as in
//!   JOGL, where key and mouse listeners run on the AWT thread and change fields that `display`
//!   reads); a listener asks for a new frame with [`Drawable::repaint`] when no animator runs.
//! - **One event loop per process.** winit allows a single event loop per process; fixedgl keeps
//!   it for the thread that first opened a window and reuses it for later windows on that thread
//!   (one window at a time). Another thread gets an [`Error::Window`] saying so.

use std::path::PathBuf;

use image::RgbaImage;

use crate::{Context, ContextConfig, Error};

mod input;
mod runner;
pub mod view;

pub use input::{Key, KeyEvent, Modifiers, MouseButton, MouseButtons, MouseEvent};

/// A program drawn in a window: JOGL's `GLEventListener`, `KeyListener`, `MouseListener`,
/// `MouseMotionListener` and `MouseWheelListener` in one trait. Only `display` is required; every
/// other method does nothing by default, as a JOGL adapter class would.
///
/// The GL methods receive the window's [`Context`] (JOGL's `drawable.getGL().getGL2()`) and the
/// [`Drawable`] (size, frame counter, clock, measured FPS, and requests to the window).
pub trait GlEventListener {
    /// Called once, after the window and its context exist and before the first `reshape`; and
    /// again whenever the context had to be recreated (see the module docs on resizing).
    fn init(&mut self, gl: &mut Context, drawable: &mut Drawable) {
        let _ = (gl, drawable);
    }

    /// Draws one frame. The context's colour buffer is presented when it returns (or the image
    /// given to [`Drawable::present_image`]).
    fn display(&mut self, gl: &mut Context, drawable: &mut Drawable);

    /// The drawable is now `width` x `height` (after `init`, and after each resize). The viewport
    /// has already been set to the whole drawable, as JOGL does before calling `reshape`.
    fn reshape(
        &mut self,
        gl: &mut Context,
        drawable: &mut Drawable,
        x: i32,
        y: i32,
        width: u32,
        height: u32,
    ) {
        let _ = (gl, drawable, x, y, width, height);
    }

    /// The window is closing: the last call with the context.
    fn dispose(&mut self, gl: &mut Context, drawable: &mut Drawable) {
        let _ = (gl, drawable);
    }

    /// A key went down (repeated while held: [`KeyEvent::repeat`]). JOGL `keyPressed`.
    fn key_pressed(&mut self, event: &KeyEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// A key went up. JOGL `keyReleased`.
    fn key_released(&mut self, event: &KeyEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// A key press produced a character, [`KeyEvent::text`] (with Shift and the layout applied).
    /// JOGL `keyTyped`.
    fn key_typed(&mut self, event: &KeyEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// A mouse button went down; [`MouseEvent::button`] says which. JOGL `mousePressed`.
    fn mouse_pressed(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// A mouse button went up. JOGL `mouseReleased`.
    fn mouse_released(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// A button went down and up without the pointer moving (more than 2 pixels) in between,
    /// reported after `mouse_released`. JOGL `mouseClicked`.
    fn mouse_clicked(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// The pointer moved with no button held. JOGL `mouseMoved`.
    fn mouse_moved(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// The pointer moved with a button held ([`MouseEvent::buttons`]). JOGL `mouseDragged`.
    fn mouse_dragged(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// The pointer entered the window. JOGL `mouseEntered`.
    fn mouse_entered(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// The pointer left the window. JOGL `mouseExited`.
    fn mouse_exited(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }

    /// The wheel turned by [`MouseEvent::wheel_rotation`] notches. JOGL `mouseWheelMoved`.
    fn mouse_wheel_moved(&mut self, event: &MouseEvent, drawable: &mut Drawable) {
        let _ = (event, drawable);
    }
}

/// When frames are drawn: JOGL's animators.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Animator {
    /// No animator: a frame is drawn when the window needs one (shown, resized, uncovered) or the
    /// program asks with [`Drawable::repaint`] (JOGL: no animator, `canvas.display()`).
    OnDemand,
    /// At most this many frames a second, on a steady schedule (JOGL's `FPSAnimator`). A frame
    /// that takes longer delays the next one; missed frames are not made up.
    Fps(f64),
    /// One frame after another as fast as they can be drawn (JOGL's `Animator`).
    Continuous,
}

/// What a [`GlEventListener`] sees of its window, and asks of it: JOGL's `GLAutoDrawable` with
/// the animator's `getLastFPS`. Requests (`repaint`, `exit`, `set_title`, ...) take effect when the
/// current callback returns.
#[derive(Debug)]
pub struct Drawable {
    pub(crate) size: (u32, u32),
    pub(crate) frame: u64,
    pub(crate) time: f64,
    pub(crate) fps: f64,
    pub(crate) animator: Animator,
    pub(crate) repaint: bool,
    pub(crate) exit: bool,
    pub(crate) title: Option<String>,
    pub(crate) requested_size: Option<(u32, u32)>,
    pub(crate) image: Option<RgbaImage>,
    pub(crate) pointer: (f64, f64),
}

impl Drawable {
    pub(crate) fn new(size: (u32, u32), animator: Animator) -> Self {
        Drawable {
            size,
            frame: 0,
            time: 0.0,
            fps: 0.0,
            animator,
            repaint: false,
            exit: false,
            title: None,
            requested_size: None,
            image: None,
            pointer: (0.0, 0.0),
        }
    }

    /// The drawable's width in pixels (JOGL `getSurfaceWidth`).
    pub fn width(&self) -> u32 {
        self.size.0
    }

    /// The drawable's height in pixels (JOGL `getSurfaceHeight`).
    pub fn height(&self) -> u32 {
        self.size.1
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// How many frames have been presented before this one (0 during the first `display`).
    pub fn frame(&self) -> u64 {
        self.frame
    }

    /// The animation clock in seconds: 0 at the first frame (see the module docs for when it
    /// advances by a fixed step instead of the wall clock).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Frames presented per second, measured over about the last second (0 until two frames
    /// have been presented). JOGL `animator.getLastFPS()`.
    pub fn fps(&self) -> f64 {
        self.fps
    }

    /// Where the pointer last was, in pixels from the top-left corner.
    pub fn pointer(&self) -> (f64, f64) {
        self.pointer
    }

    /// Asks for a new frame (JOGL `canvas.display()` / `repaint()`); needed only with
    /// [`Animator::OnDemand`], harmless otherwise.
    pub fn repaint(&mut self) {
        self.repaint = true;
    }

    /// Closes the window after the current callback: `dispose` runs, then `run` returns.
    pub fn exit(&mut self) {
        self.exit = true;
    }

    /// Changes the window title.
    pub fn set_title(&mut self, title: impl Into<String>) {
        self.title = Some(title.into());
    }

    /// The animator in use.
    pub fn animator(&self) -> Animator {
        self.animator
    }

    /// Switches animators (JOGL: `animator.stop()`, or starting another one).
    pub fn set_animator(&mut self, animator: Animator) {
        self.animator = animator;
        self.repaint = true;
    }

    /// Asks the window system for a new size; when it is granted, `reshape` follows.
    pub fn set_size(&mut self, width: u32, height: u32) {
        self.requested_size = Some((width.max(1), height.max(1)));
    }

    /// Presents `image` for this frame instead of the context's colour buffer: for programs that
    /// compose their own picture from several renderings (`fixedgl view --compare`). Call it from
    /// `display`. An image of another size than the drawable is drawn at the top-left corner, the
    /// rest of the window dark grey.
    pub fn present_image(&mut self, image: RgbaImage) {
        self.image = Some(image);
    }
}

/// A window for a [`GlEventListener`], configured builder-style and opened by [`GlCanvas::run`]:
/// JOGL's `GLCanvas` in its `JFrame`, with the animator.
#[derive(Clone, Debug)]
pub struct GlCanvas {
    pub(crate) title: String,
    pub(crate) size: (u32, u32),
    pub(crate) animator: Animator,
    pub(crate) frames: Option<u64>,
    pub(crate) record_dir: Option<PathBuf>,
    pub(crate) time_step: Option<f64>,
    pub(crate) config: ContextConfig,
}

/// The default recording rate without a target FPS: 1/30 s a frame.
const DEFAULT_STEP: f64 = 1.0 / 30.0;

impl GlCanvas {
    /// A `width` x `height` window (pixels), titled "fixedgl", drawn on demand.
    pub fn new(width: u32, height: u32) -> Self {
        GlCanvas {
            title: "fixedgl".to_owned(),
            size: (width.max(1), height.max(1)),
            animator: Animator::OnDemand,
            frames: None,
            record_dir: None,
            time_step: None,
            config: ContextConfig {
                double_buffered: true,
                ..ContextConfig::default()
            },
        }
    }

    /// The framebuffer, as `glutInitDisplayMode` chooses it (default: double-buffered with depth
    /// and stencil, `GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL`). A double-buffered window shows
    /// the front buffer, swapped after each `display`; a single-buffered one shows what `display`
    /// drew into its only buffer.
    pub fn config(mut self, config: ContextConfig) -> Self {
        self.config = config;
        self
    }

    /// The window title.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = title.into();
        self
    }

    /// When frames are drawn (default [`Animator::OnDemand`]).
    pub fn animator(mut self, animator: Animator) -> Self {
        self.animator = animator;
        self
    }

    /// Presents `n` frames, then closes the window and returns (tests, screenshots, recordings):
    /// the API form of `--frames N`. Frames are drawn one after another (at the target rate of an
    /// [`Animator::Fps`], else as fast as they can be), and the clock advances by a fixed step.
    pub fn frames(mut self, n: u64) -> Self {
        self.frames = Some(n);
        self
    }

    /// Writes every presented frame to `dir` as `frame-00000.png`, `frame-00001.png`, ... (the
    /// folder is created): the API form of `--record-frames DIR`. The PNGs are what the window
    /// shows, so opaque (alpha 255).
    pub fn record_frames(mut self, dir: impl Into<PathBuf>) -> Self {
        self.record_dir = Some(dir.into());
        self
    }

    /// Advances [`Drawable::time`] by `seconds` every frame instead of following the wall clock.
    pub fn fixed_time_step(mut self, seconds: f64) -> Self {
        self.time_step = Some(seconds);
        self
    }

    /// Applies command-line [`Options`] (`--frames`, `--record-frames`).
    pub fn options(mut self, options: &Options) -> Self {
        if let Some(n) = options.frames {
            self.frames = Some(n);
        }
        if let Some(dir) = &options.record_frames {
            self.record_dir = Some(dir.clone());
        }
        self
    }

    /// The time step the clock advances by each frame, if it is fixed (see the module docs).
    pub fn time_step(&self) -> Option<f64> {
        self.time_step.or_else(|| {
            (self.frames.is_some() || self.record_dir.is_some()).then(|| match self.animator {
                Animator::Fps(f) if f.is_finite() && f > 0.0 => 1.0 / f,
                _ => DEFAULT_STEP,
            })
        })
    }

    /// Opens the window and runs `listener` in it until the window is closed, the listener calls
    /// [`Drawable::exit`], or the frames asked for are presented. An [`Error::Window`] when there
    /// is no display (neither `DISPLAY` nor `WAYLAND_DISPLAY` names one that can be reached) or
    /// the window cannot be made; other errors as they come (a recorded frame that cannot be
    /// written, a context that cannot be allocated at the window's size).
    pub fn run<L: GlEventListener>(self, listener: &mut L) -> Result<RunStats, Error> {
        runner::run(self, listener)
    }
}

/// What a [`GlCanvas::run`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunStats {
    /// Frames presented.
    pub frames: u64,
    /// Wall-clock seconds from the first frame to the last.
    pub seconds: f64,
    /// The last measured FPS ([`Drawable::fps`]).
    pub fps: f64,
    /// The window's size when it closed.
    pub size: (u32, u32),
}

/// The window flags every fixedgl window program understands on its command line.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// `--frames N`: present N frames and exit.
    pub frames: Option<u64>,
    /// `--record-frames DIR`: write each presented frame to DIR as PNG.
    pub record_frames: Option<PathBuf>,
}

impl Options {
    /// Takes `--frames N` and `--record-frames DIR` (or `--frames=N`, `--record-frames=DIR`) out of
    /// `args` and leaves every other argument, in order, for the program. A missing or invalid
    /// value is an [`Error::Window`] that names the flag.
    pub fn take_from(args: &mut Vec<String>) -> Result<Options, Error> {
        let mut options = Options::default();
        let mut rest = Vec::with_capacity(args.len());
        let mut it = std::mem::take(args).into_iter();
        while let Some(arg) = it.next() {
            let (flag, inline) = match arg.split_once('=') {
                Some((f, v)) if f.starts_with("--") => (f.to_owned(), Some(v.to_owned())),
                _ => (arg.clone(), None),
            };
            if flag != "--frames" && flag != "--record-frames" {
                rest.push(arg);
                continue;
            }
            let value = inline
                .or_else(|| it.next())
                .ok_or_else(|| Error::Window(format!("{flag} needs a value")))?;
            if flag == "--frames" {
                let n = value
                    .parse::<u64>()
                    .ok()
                    .filter(|&n| n > 0)
                    .ok_or_else(|| {
                        Error::Window(format!(
                            "--frames needs a positive whole number, not {value:?}"
                        ))
                    })?;
                options.frames = Some(n);
            } else {
                options.record_frames = Some(PathBuf::from(value));
            }
        }
        *args = rest;
        Ok(options)
    }
}

/// The one place where a window's context takes the window's new size. Returns whether the GL
/// state was lost (then the runner calls `init` again): never, since `Context::resize` keeps the
/// state and only reallocates the buffers.
pub(crate) fn follow_size(gl: &mut Context, width: u32, height: u32) -> Result<bool, Error> {
    gl.resize(width, height).map(|()| false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn options_take_their_flags_and_leave_the_rest() {
        let mut a = args(&["--window", "--frames", "30", "x", "--record-frames=out/f"]);
        let o = Options::take_from(&mut a).unwrap();
        assert_eq!(o.frames, Some(30));
        assert_eq!(o.record_frames, Some(PathBuf::from("out/f")));
        assert_eq!(a, args(&["--window", "x"]));
        let mut a = args(&["--frames=7"]);
        assert_eq!(Options::take_from(&mut a).unwrap().frames, Some(7));
        assert!(a.is_empty());
    }

    #[test]
    fn options_reject_bad_values_by_name() {
        for bad in [
            &["--frames"][..],
            &["--frames", "0"],
            &["--frames", "x"],
            &["--record-frames"],
        ] {
            let mut a = args(bad);
            let e = Options::take_from(&mut a).unwrap_err().to_string();
            assert!(e.contains(bad[0]), "{e}");
        }
    }

    #[test]
    fn the_clock_is_fixed_when_frames_are_counted_or_recorded() {
        let c = GlCanvas::new(8, 8);
        assert_eq!(c.time_step(), None);
        assert_eq!(c.clone().frames(3).time_step(), Some(DEFAULT_STEP));
        let fps = c.clone().animator(Animator::Fps(50.0));
        assert_eq!(fps.clone().record_frames("d").time_step(), Some(0.02));
        assert_eq!(fps.fixed_time_step(0.5).time_step(), Some(0.5));
    }

    #[test]
    fn follow_size_gives_the_context_the_new_size() {
        let mut gl = Context::new(4, 4).unwrap();
        gl.clear_color(0.5, 0.0, 0.0, 1.0);
        assert!(!follow_size(&mut gl, 7, 3).unwrap(), "the GL state is kept");
        let mut c = [0.0f32; 4];
        gl.get_floatv(crate::gl::COLOR_CLEAR_VALUE, &mut c);
        assert_eq!(c, [0.5, 0.0, 0.0, 1.0]);
        assert_eq!(gl.size(), (7, 3));
        assert!(follow_size(&mut gl, 0, 3).is_err());
        assert_eq!(gl.size(), (7, 3), "a failed resize keeps the context");
    }
}
