//! `fixedgl view`: registered scenes in a window, animated where the scene has a time parameter
//! ([`Scene::animate`]); with `--compare`, the CPU rendering, the driver's rendering of the same
//! recorded calls and their difference side by side, live.
//!
//! Every frame draws the scene from GL's initial state on a cleared framebuffer, so a frame at
//! time `t` is exactly `Scene::record_at(w, h, t)`'s picture (and frame 0 is the still image that
//! `fixedgl render` writes). With `--compare` the frame's calls are recorded on the CPU context
//! and replayed on the GL backend, as `fixedgl compare` does, and the window shows
//! [`compose`]'s picture: a label bar, then the panels. Keys: see [`KEYS`].

use std::time::Instant;

use image::{Rgba, RgbaImage};

use super::{Animator, Drawable, GlCanvas, GlEventListener, Key, KeyEvent, Options, RunStats};
use crate::compare::{compare, font, HEAT_GAIN};
use crate::scenes::Scene;
use crate::{gl, Call, Context, ContextConfig, Error};

/// The keys of the viewer, as printed by `h`.
pub const KEYS: &str = "\
keys:  1 CPU  2 GL  3 difference at full size, 0 all three  (--compare)
       Tab  the next of these
       Space or F  flip CPU and GL in place                   (--compare)
       + or =  / -  difference amplification x2 / /2          (--compare)
       N Right PageDown  next scene    P Left PageUp  previous scene
       A  pause or resume the animation    R  restart it
       H F1  these keys    Q Escape  quit";

/// Pixels between panels.
pub const GUTTER: u32 = 8;
/// Height of the label bar above the panels (the 3x5 font at scale 2, 2 pixels around).
pub const BAR: u32 = font::HEIGHT * 2 + 4;
/// Largest panel the compare window starts with (the scene's size scaled down to fit).
const MAX_PANEL: (u32, u32) = (400, 800);

const BACKGROUND: Rgba<u8> = Rgba([40, 40, 40, 255]);
const LABEL: Rgba<u8> = Rgba([255, 255, 255, 255]);

/// What the compare window shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// CPU | GL | difference.
    All,
    /// The CPU rendering alone, the whole window.
    Cpu,
    /// The driver's rendering alone.
    Gl,
    /// The difference alone.
    Diff,
}

impl Layout {
    /// Panels across.
    fn panels(self) -> u32 {
        if self == Layout::All {
            3
        } else {
            1
        }
    }

    /// The size of one panel in a `window` of this layout (at least 1x1).
    pub fn panel_size(self, window: (u32, u32)) -> (u32, u32) {
        let n = self.panels();
        let w = window.0.saturating_sub((n - 1) * GUTTER) / n;
        (w.max(1), window.1.saturating_sub(BAR).max(1))
    }

    /// The window that holds panels of `panel` size.
    pub fn window_size(self, panel: (u32, u32)) -> (u32, u32) {
        let n = self.panels();
        (n * panel.0 + (n - 1) * GUTTER, panel.1 + BAR)
    }
}

/// One panel of the compare window: its picture and the label above it.
pub struct Panel<'a> {
    /// The picture (drawn opaque over the background, top-left aligned).
    pub image: &'a RgbaImage,
    /// Its label (upper case letters, digits, `.%:-/|=()`; other characters are blank).
    pub label: String,
}

/// The compare window's picture: a [`BAR`]-high label bar, then the panels left to right,
/// [`GUTTER`] apart, each `panel` sized (an image of another size is cut or padded).
pub fn compose(window: (u32, u32), panel: (u32, u32), panels: &[Panel<'_>]) -> RgbaImage {
    let mut out = RgbaImage::from_pixel(window.0, window.1, BACKGROUND);
    for (i, p) in panels.iter().enumerate() {
        let x0 = i as u32 * (panel.0 + GUTTER);
        font::draw(&mut out, x0 + 2, 2, 2, &p.label, LABEL);
        for (x, y, px) in p.image.enumerate_pixels() {
            if x < panel.0 && y < panel.1 {
                if let Some(o) = out.get_pixel_mut_checked(x0 + x, BAR + y) {
                    *o = Rgba([px.0[0], px.0[1], px.0[2], 255]);
                }
            }
        }
    }
    out
}

/// How the viewer runs.
#[derive(Clone, Debug)]
pub struct ViewConfig {
    /// Show CPU | GL | difference instead of the CPU rendering alone.
    pub compare: bool,
    /// The size each scene is rendered at (default: the scene's; in compare mode scaled down to
    /// fit three across).
    pub size: Option<(u32, u32)>,
    /// The EGL device for the GL side (`auto`, an index or a name), as `fixedgl --device`.
    pub device: String,
    /// Frames a second to animate at (default 60 for animated scenes; still scenes are drawn on
    /// demand).
    pub fps: Option<f64>,
    /// `--frames N` (N frames of each scene, one scene after the other, then exit) and
    /// `--record-frames DIR`.
    pub options: Options,
}

impl Default for ViewConfig {
    fn default() -> Self {
        ViewConfig {
            compare: false,
            size: None,
            device: "auto".into(),
            fps: None,
            options: Options::default(),
        }
    }
}

/// Opens the viewer on `scenes` (at least one).
pub fn run(scenes: &[&'static Scene], config: ViewConfig) -> Result<RunStats, Error> {
    let Some(first) = scenes.first() else {
        return Err(Error::Window("no scene to view".into()));
    };
    let mut viewer = SceneViewer::new(scenes, &config)?;
    let window = viewer.window_size(first);
    let animated = scenes.iter().any(|s| s.animate.is_some());
    let animator = match config.fps {
        Some(f) => Animator::Fps(f),
        None if animated => Animator::Fps(60.0),
        None => Animator::OnDemand,
    };
    let mut canvas = GlCanvas::new(window.0, window.1)
        .title(viewer.title(0.0))
        .animator(animator)
        .config(ContextConfig {
            double_buffered: true,
            ..viewer.framebuffer
        });
    if let Some(dir) = &config.options.record_frames {
        canvas = canvas.record_frames(dir.clone());
    }
    if let Some(n) = config.options.frames {
        canvas = canvas.frames(n.saturating_mul(scenes.len() as u64));
    }
    let stats = canvas.run(&mut viewer)?;
    match viewer.error.take() {
        Some(e) => Err(e),
        None => Ok(stats),
    }
}

/// The GL side of the comparison: the real backend with the `gl` feature (`None` only in unit
/// tests, which check sizes without a driver).
#[cfg(feature = "gl")]
struct GlSide(Option<crate::glbackend::GlBackend>);

#[cfg(feature = "gl")]
impl GlSide {
    fn new(w: u32, h: u32, config: ContextConfig, device: &str) -> Result<Self, Error> {
        let choice: crate::glbackend::DeviceChoice = device.parse().unwrap_or_default();
        crate::glbackend::GlBackend::with_config(w, h, &choice, config).map(|b| GlSide(Some(b)))
    }

    #[cfg(test)]
    fn unavailable() -> Self {
        GlSide(None)
    }

    fn size(&self) -> (u32, u32) {
        self.0.as_ref().map_or((0, 0), |b| b.size())
    }

    /// The frame's calls on the driver, from the state the backend started in.
    fn render(&mut self, calls: &[Call]) -> RgbaImage {
        match self.0.as_mut() {
            Some(b) => {
                b.replay_frame(calls);
                b.read_image()
            }
            None => RgbaImage::new(1, 1),
        }
    }
}

/// Without the `gl` feature there is nothing to compare with.
#[cfg(not(feature = "gl"))]
struct GlSide;

#[cfg(not(feature = "gl"))]
impl GlSide {
    fn new(_w: u32, _h: u32, _config: ContextConfig, _device: &str) -> Result<Self, Error> {
        Err(Error::Backend(
            "this fixedgl was built without the `gl` feature, so `view --compare` has no driver \
             to compare with; rebuild with default features"
                .into(),
        ))
    }

    #[cfg(test)]
    fn unavailable() -> Self {
        GlSide
    }

    fn size(&self) -> (u32, u32) {
        (0, 0)
    }

    fn render(&mut self, _calls: &[Call]) -> RgbaImage {
        RgbaImage::new(1, 1)
    }
}

/// The compare mode's renderers and what it measured.
struct Compare {
    cpu: Context,
    gl: GlSide,
    layout: Layout,
    flipped: bool,
    gain: u32,
    cpu_ms: Option<f64>,
    gl_ms: Option<f64>,
    percent_off: f64,
}

/// The viewer as a [`GlEventListener`].
struct SceneViewer {
    scenes: Vec<&'static Scene>,
    current: usize,
    size: Option<(u32, u32)>,
    device: String,
    comparing: bool,
    frames_per_scene: Option<u64>,
    frames_in_scene: u64,
    /// The drawable's clock when the current scene's animation started.
    started: f64,
    /// The scene time the next frame shows, from which the clock goes on (after a scene switch,
    /// a restart or a resume): `started` is set from it at that frame.
    pending: Option<f64>,
    /// The scene time shown while paused.
    paused: Option<f64>,
    compare: Option<Compare>,
    error: Option<Error>,
    /// The framebuffer every scene is drawn on: the default one, with an accumulation buffer
    /// when some scene asks for one (it changes nothing for the others).
    framebuffer: ContextConfig,
}

/// Running average weight of a new frame time.
const SMOOTHING: f64 = 0.2;

fn average(old: Option<f64>, new: f64) -> Option<f64> {
    Some(old.map_or(new, |o| o + SMOOTHING * (new - o)))
}

/// GL's initial state on a framebuffer as `Context::new` makes it: colour 0, depth 1, stencil 0
/// (the initial clear values), so that every frame is the picture of a fresh context.
fn fresh_frame(gl: &mut Context) {
    gl.reset();
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
}

impl SceneViewer {
    fn new(scenes: &[&'static Scene], config: &ViewConfig) -> Result<Self, Error> {
        let mut viewer = SceneViewer {
            scenes: scenes.to_vec(),
            current: 0,
            size: config.size,
            device: config.device.clone(),
            comparing: config.compare,
            frames_per_scene: config.options.frames,
            frames_in_scene: 0,
            started: 0.0,
            pending: None,
            paused: None,
            compare: None,
            error: None,
            framebuffer: ContextConfig {
                accum: scenes.iter().any(|s| s.config.accum),
                ..ContextConfig::default()
            },
        };
        if config.compare {
            // Made before the window opens, so that a missing driver is an error up front.
            let panel = viewer.panel_for(scenes[0]);
            viewer.compare = Some(Compare {
                cpu: Context::with_config(panel.0, panel.1, viewer.framebuffer)?,
                gl: GlSide::new(panel.0, panel.1, viewer.framebuffer, &config.device)?,
                layout: Layout::All,
                flipped: false,
                gain: HEAT_GAIN,
                cpu_ms: None,
                gl_ms: None,
                percent_off: 0.0,
            });
        }
        Ok(viewer)
    }

    fn scene(&self) -> &'static Scene {
        self.scenes[self.current]
    }

    /// The layout shown (side by side until a key picks one panel).
    fn layout(&self) -> Layout {
        self.compare.as_ref().map_or(Layout::All, |c| c.layout)
    }

    /// The size a scene is rendered at when its window opens or the layout changes: `--size`,
    /// else the scene's own size, scaled down to fit three across when three are shown.
    fn panel_for(&self, scene: &Scene) -> (u32, u32) {
        let (w, h) = self.size.unwrap_or(scene.default_size);
        if self.size.is_some() || !self.comparing || self.layout() != Layout::All {
            return (w, h);
        }
        let s = (f64::from(MAX_PANEL.0) / f64::from(w))
            .min(f64::from(MAX_PANEL.1) / f64::from(h))
            .min(1.0);
        let side = |v: u32| ((f64::from(v) * s).round() as u32).max(1);
        (side(w), side(h))
    }

    fn window_size(&self, scene: &Scene) -> (u32, u32) {
        let panel = self.panel_for(scene);
        if self.comparing {
            self.layout().window_size(panel)
        } else {
            panel
        }
    }

    /// The scene's clock: the drawable's since the scene started, or the paused time.
    fn scene_time(&self, d: &Drawable) -> f64 {
        self.paused.unwrap_or(d.time() - self.started)
    }

    fn title(&self, fps: f64) -> String {
        let scene = self.scene();
        let mut t = format!("fixedgl view: {}", scene.name);
        if self.scenes.len() > 1 {
            t += &format!(" ({}/{})", self.current + 1, self.scenes.len());
        }
        if let Some(c) = &self.compare {
            let (left, right) = if c.flipped {
                ("GL", "CPU")
            } else {
                ("CPU", "GL")
            };
            let shown = match c.layout {
                Layout::All => format!("{left} | {right} | diff x{}", c.gain),
                Layout::Cpu => format!("{left} (full size)"),
                Layout::Gl => format!("{right} (full size)"),
                Layout::Diff => format!("diff x{} (full size)", c.gain),
            };
            let rate = |ms: Option<f64>| ms.map_or("-".to_owned(), |ms| format!("{:.1}", 1e3 / ms));
            t += &format!(
                " - {shown} - CPU {} fps, GL {} fps - {:.3}% off",
                rate(c.cpu_ms),
                rate(c.gl_ms),
                c.percent_off
            );
        } else if fps > 0.0 {
            t += &format!(" - CPU {fps:.1} fps");
        }
        if self.paused.is_some() {
            t += " - paused";
        }
        t
    }

    /// Switches to scene `index` (wrapping), its clock at 0 from the next frame, and asks for
    /// its window size.
    fn show_scene(&mut self, index: usize, d: &mut Drawable) {
        self.current = index % self.scenes.len();
        self.frames_in_scene = 0;
        self.pending = Some(0.0);
        if self.paused.is_some() {
            self.paused = Some(0.0);
        }
        let size = self.window_size(self.scene());
        if size != d.size() {
            d.set_size(size.0, size.1);
        }
        d.repaint();
    }

    /// One compare frame: the scene on both sides, the difference, the picture.
    fn compare_frame(&mut self, t: f32, window: (u32, u32)) -> Result<RgbaImage, Error> {
        let scene = self.scene();
        let device = self.device.clone();
        let framebuffer = self.framebuffer;
        let Some(c) = self.compare.as_mut() else {
            return Err(Error::Window("not comparing".into()));
        };
        let panel = c.layout.panel_size(window);
        if c.cpu.size() != panel {
            crate::window::follow_size(&mut c.cpu, panel.0, panel.1)?;
        }
        if c.gl.size() != panel {
            c.gl = GlSide::new(panel.0, panel.1, framebuffer, &device)?;
        }
        let start = Instant::now();
        c.cpu.reset();
        c.cpu.start_recording();
        // Recorded, so that the driver's framebuffer starts from the same clear.
        c.cpu
            .clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
        scene.draw_at(&mut c.cpu, t);
        let calls = c.cpu.stop_recording();
        let cpu = c.cpu.to_image();
        c.cpu_ms = average(c.cpu_ms, start.elapsed().as_secs_f64() * 1e3);
        let start = Instant::now();
        let gl = c.gl.render(&calls);
        c.gl_ms = average(c.gl_ms, start.elapsed().as_secs_f64() * 1e3);
        let comparison = compare(&cpu, &gl, scene.tolerance.channel);
        c.percent_off = comparison.differing_percent;
        let diff = comparison.heat_map_with_gain(c.gain);
        let fps = |ms: Option<f64>| ms.map_or(String::new(), |ms| format!(" {:.1} FPS", 1e3 / ms));
        let cpu_panel = Panel {
            image: &cpu,
            label: format!("CPU{}", fps(c.cpu_ms)),
        };
        let gl_panel = Panel {
            image: &gl,
            label: format!("GL{}", fps(c.gl_ms)),
        };
        let diff_panel = Panel {
            image: &diff,
            label: format!("DIFF X{} {:.3}%", c.gain, c.percent_off),
        };
        let (first, second) = if c.flipped {
            (gl_panel, cpu_panel)
        } else {
            (cpu_panel, gl_panel)
        };
        let panels = match c.layout {
            Layout::All => vec![first, second, diff_panel],
            Layout::Cpu => vec![first],
            Layout::Gl => vec![second],
            Layout::Diff => vec![diff_panel],
        };
        Ok(compose(window, panel, &panels))
    }

    /// The compare keys; true when the key was one of them.
    fn compare_key(&mut self, key: Key, d: &mut Drawable) -> bool {
        let Some(c) = self.compare.as_mut() else {
            return false;
        };
        let layout = match key {
            Key::Char('1') => Some(Layout::Cpu),
            Key::Char('2') => Some(Layout::Gl),
            Key::Char('3') => Some(Layout::Diff),
            Key::Char('0') => Some(Layout::All),
            Key::Tab => Some(match c.layout {
                Layout::All => Layout::Cpu,
                Layout::Cpu => Layout::Gl,
                Layout::Gl => Layout::Diff,
                Layout::Diff => Layout::All,
            }),
            _ => None,
        };
        if let Some(layout) = layout {
            // One panel is shown at the scene's full size, three scaled to fit across: the
            // window is asked for that size, and the panels follow whatever it gets.
            c.layout = layout;
            let size = self.window_size(self.scene());
            if size != d.size() {
                d.set_size(size.0, size.1);
            }
        } else {
            match key {
                Key::Space | Key::Char('f') => c.flipped = !c.flipped,
                Key::Char('+') | Key::Char('=') => c.gain = (c.gain * 2).min(256),
                Key::Char('-') => c.gain = (c.gain / 2).max(1),
                _ => return false,
            }
        }
        d.repaint();
        true
    }
}

impl GlEventListener for SceneViewer {
    fn display(&mut self, gl: &mut Context, d: &mut Drawable) {
        if let Some(t0) = self.pending.take() {
            self.started = d.time() - t0;
        }
        let t = self.scene_time(d) as f32;
        if self.compare.is_some() {
            match self.compare_frame(t, d.size()) {
                Ok(image) => d.present_image(image),
                Err(e) => {
                    self.error = Some(e);
                    d.exit();
                }
            }
        } else {
            fresh_frame(gl);
            self.scene().draw_at(gl, t);
        }
        self.frames_in_scene += 1;
        d.set_title(self.title(d.fps()));
        // `--frames N` with several scenes: N of each, the next one asked for now so that its
        // window size is granted before its first frame.
        if self
            .frames_per_scene
            .is_some_and(|n| self.frames_in_scene >= n)
            && self.current + 1 < self.scenes.len()
        {
            self.show_scene(self.current + 1, d);
        }
    }

    fn key_pressed(&mut self, e: &KeyEvent, d: &mut Drawable) {
        if self.compare_key(e.key, d) {
            d.set_title(self.title(d.fps()));
            return;
        }
        match e.key {
            Key::Escape | Key::Char('q') => d.exit(),
            Key::Char('n') | Key::Right | Key::PageDown => self.show_scene(self.current + 1, d),
            Key::Char('p') | Key::Left | Key::PageUp => {
                self.show_scene(self.current + self.scenes.len() - 1, d)
            }
            Key::Char('a') => {
                self.paused = match self.paused {
                    Some(t) => {
                        self.pending = Some(t);
                        None
                    }
                    None => Some(self.scene_time(d)),
                };
                d.repaint();
            }
            Key::Char('r') => {
                self.pending = Some(0.0);
                if self.paused.is_some() {
                    self.paused = Some(0.0);
                }
                d.repaint();
            }
            Key::Char('h') | Key::F(1) => println!("{KEYS}"),
            _ => return,
        }
        d.set_title(self.title(d.fps()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_split_the_window_into_panels() {
        assert_eq!(Layout::All.window_size((400, 300)), (1216, 300 + BAR));
        assert_eq!(Layout::All.panel_size((1216, 300 + BAR)), (400, 300));
        assert_eq!(Layout::Cpu.panel_size((1216, 300 + BAR)), (1216, 300));
        assert_eq!(Layout::Diff.window_size((5, 5)), (5, 5 + BAR));
        assert_eq!(Layout::All.panel_size((3, 3)), (1, 1));
    }

    #[test]
    fn compose_puts_each_panel_under_the_bar_opaque() {
        let red = RgbaImage::from_pixel(2, 2, Rgba([255, 0, 0, 0]));
        let blue = RgbaImage::from_pixel(2, 2, Rgba([0, 0, 255, 255]));
        let window = Layout::All.window_size((2, 2));
        let panels = [
            Panel {
                image: &red,
                label: String::new(),
            },
            Panel {
                image: &blue,
                label: String::new(),
            },
        ];
        let img = compose(window, (2, 2), &panels);
        assert_eq!(img.dimensions(), window);
        assert_eq!(*img.get_pixel(1, BAR + 1), Rgba([255, 0, 0, 255]));
        assert_eq!(*img.get_pixel(2 + GUTTER, BAR), Rgba([0, 0, 255, 255]));
        assert_eq!(*img.get_pixel(2, BAR), BACKGROUND, "gutter");
        assert_eq!(
            *img.get_pixel(2 * (2 + GUTTER), BAR),
            BACKGROUND,
            "no third panel"
        );
    }

    #[test]
    fn compare_panels_are_scaled_to_fit_three_across() {
        let scene = crate::scenes::find("cube-colors").unwrap();
        let mut v = SceneViewer::new(&[scene], &ViewConfig::default()).unwrap();
        assert_eq!(v.window_size(scene), (800, 800));
        v.comparing = true;
        assert_eq!(v.panel_for(scene), (400, 400));
        assert_eq!(v.window_size(scene), (1216, 400 + BAR));
        v.compare = Some(Compare {
            cpu: Context::new(1, 1).unwrap(),
            gl: GlSide::unavailable(),
            layout: Layout::Gl,
            flipped: false,
            gain: HEAT_GAIN,
            cpu_ms: None,
            gl_ms: None,
            percent_off: 0.0,
        });
        assert_eq!(
            v.window_size(scene),
            (800, 800 + BAR),
            "one panel at full size"
        );
        v.size = Some((123, 45));
        assert_eq!(v.panel_for(scene), (123, 45), "--size is taken as it is");
    }
}
