//! The lecture's JOGL `Rendering` example (seed 000): the three pictures of the slides as PNGs, or
//! the program as the course runs it, in a window.
//!
//! ```text
//! cargo run --release --example gaussian [OUT_DIR]
//! cargo run --release --example gaussian -- --window [--frames N] [--record-frames DIR]
//! ```
//!
//! Without `--window` it writes `gauss-flat-40.png` (FLAT, one normal per cell, 40x40 cells),
//! `gauss-smooth-40.png` (SMOOTH, a normal per vertex) and `gauss-smooth-400.png` (SMOOTH,
//! 400x400 cells). With `--window` it opens the 800x800 canvas under a 60 FPS animator, as the
//! slides' `main` does, and adds the course's interaction: keys F, S and P switch FLAT, SMOOTH
//! and PHONG_WIN, M switches the 40 and 400 cell meshes, dragging with the left button turns the
//! surface, the light follows the pointer, R puts everything back, Q or Escape quits. Until the
//! first key or pointer event the window shows exactly the `gauss-smooth-40` picture.
//!
//! The port of the JOGL methods themselves, line by line, is `fixedgl::scenes::gaussian` (`init`,
//! `lighting`, `display`); the class below is the JOGL class's listener half.

use std::path::PathBuf;

use fixedgl::scenes::gaussian::{display, init, Shading};
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    if let Some(i) = args.iter().position(|a| a == "--window") {
        args.remove(i);
        return interactive::window(args);
    }
    let out = PathBuf::from(args.first().map_or("out", String::as_str));
    std::fs::create_dir_all(&out)?;
    for (name, cells, shading) in [
        ("gauss-flat-40", 40, Shading::Flat),
        ("gauss-smooth-40", 40, Shading::Smooth),
        ("gauss-smooth-400", 400, Shading::Smooth),
    ] {
        // JOGL's GLCanvas: an 800x800 drawable; init() once, then display() for the frame.
        let mut gl = Context::new(800, 800)?;
        init(&mut gl, shading);
        display(&mut gl, cells, shading);
        let path = out.join(format!("{name}.png"));
        gl.to_image().save(&path)?;
        println!("{}", path.display());
    }
    Ok(())
}

/// The interactive program (cargo feature `window`, on by default).
#[cfg(feature = "window")]
mod interactive {
    use super::*;
    use fixedgl::gl::*;
    use fixedgl::glu;
    use fixedgl::window::{
        Animator, Drawable, GlCanvas, GlEventListener, Key, KeyEvent, MouseButton, MouseEvent,
        Options,
    };

    /// The slides' `main`: the canvas, the listener, the 60 FPS animator, the 800x800 frame.
    pub fn window(mut args: Vec<String>) -> Result<(), Box<dyn std::error::Error>> {
        let options = &Options::take_from(&mut args)?;
        if let Some(extra) = args.first() {
            return Err(format!("unexpected argument {extra:?} with --window").into());
        }
        let mut rendering = Rendering::new();
        let stats = GlCanvas::new(800, 800) // new GLCanvas(caps); frame.setSize(800, 800);
            .title("Aplicação JOGL Simples") // new JFrame("Aplicação JOGL Simples");
            .animator(Animator::Fps(60.0)) // new FPSAnimator(canvas, 60); animator.start();
            .options(options) // --frames N, --record-frames DIR
            .run(&mut rendering)?; // canvas.addGLEventListener(new Rendering()); frame.setVisible(true);
        if options.frames.is_some() {
            println!("{} frames, {:.1} fps", stats.frames, stats.fps);
        }
        Ok(())
    }

    /// The JOGL class: `Rendering implements GLEventListener, KeyListener, MouseListener,
    /// MouseMotionListener`, its fields what the listeners change and `display` reads.
    struct Rendering {
        shading: Shading,
        cells: usize,
        /// Degrees about the vertical and the horizontal axis, from dragging.
        yaw: f32,
        pitch: f32,
        /// Where a drag last was.
        drag: Option<(f64, f64)>,
        /// LIGHT0 in eye coordinates once the pointer has moved (it follows the pointer); before
        /// that the seed's light at (1, 1.5, -0.5) in world coordinates.
        light_eye: Option<[f32; 4]>,
        /// The ortho volume's half width and height (reshape keeps the seed's 2.5 in the shorter
        /// direction).
        half: (f64, f64),
    }

    impl Rendering {
        fn new() -> Self {
            Rendering {
                shading: Shading::Smooth,
                cells: 40,
                yaw: 0.0,
                pitch: 0.0,
                drag: None,
                light_eye: None,
                half: (2.5, 2.5),
            }
        }

        fn title(&self, fps: f64) -> String {
            let shading = match self.shading {
                Shading::Flat => "FLAT",
                Shading::Smooth => "SMOOTH",
                Shading::Phong => "PHONG_WIN",
            };
            format!(
                "Aplicação JOGL Simples - {shading}, {0}x{0} cells - {fps:.1} fps - \
                 F S P shading, M mesh, drag to turn, R reset, Q quit",
                self.cells
            )
        }
    }

    impl GlEventListener for Rendering {
        /// `init`: the seed's, unchanged (clear colour, depth test, camera, projection, lighting).
        fn init(&mut self, gl: &mut Context, _d: &mut Drawable) {
            init(gl, self.shading);
        }

        /// `reshape`: the seed's orthographic volume, widened along the longer side so that the
        /// surface keeps its shape in any window (the viewport is already the whole window).
        fn reshape(
            &mut self,
            gl: &mut Context,
            _d: &mut Drawable,
            _x: i32,
            _y: i32,
            w: u32,
            h: u32,
        ) {
            let aspect = f64::from(w) / f64::from(h);
            self.half = if aspect >= 1.0 {
                (2.5 * aspect, 2.5)
            } else {
                (2.5, 2.5 / aspect)
            };
            gl.matrix_mode(PROJECTION);
            gl.load_identity();
            gl.ortho(
                -self.half.0,
                self.half.0,
                -self.half.1,
                self.half.1,
                -4.5,
                4.5,
            );
        }

        /// `display`: the camera and the light for this frame, the drag rotation, then the seed's
        /// `display` (material, grid, strips).
        fn display(&mut self, gl: &mut Context, d: &mut Drawable) {
            gl.shade_model(match self.shading {
                Shading::Flat => FLAT,
                Shading::Smooth => SMOOTH,
                Shading::Phong => PHONG_WIN,
            });
            gl.matrix_mode(MODELVIEW);
            gl.load_identity();
            if let Some(light) = self.light_eye {
                gl.lightfv(LIGHT0, POSITION, &light); // identity modelview: eye coordinates
            }
            glu::look_at(gl, 1.5, 0.75, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
            if self.light_eye.is_none() {
                gl.lightfv(LIGHT0, POSITION, &[1.0, 1.5, -0.5, 1.0]); // the seed's light
            }
            if self.pitch != 0.0 {
                gl.rotatef(self.pitch, 1.0, 0.0, 0.0);
            }
            if self.yaw != 0.0 {
                gl.rotatef(self.yaw, 0.0, 1.0, 0.0);
            }
            display(gl, self.cells, self.shading);
            if d.frame() % 30 == 0 {
                d.set_title(self.title(d.fps()));
            }
        }

        /// `keyPressed`.
        fn key_pressed(&mut self, e: &KeyEvent, d: &mut Drawable) {
            match e.key {
                Key::Char('f') => self.shading = Shading::Flat,
                Key::Char('s') => self.shading = Shading::Smooth,
                Key::Char('p') => self.shading = Shading::Phong,
                Key::Char('m') => self.cells = if self.cells == 40 { 400 } else { 40 },
                Key::Char('r') => {
                    let half = self.half;
                    *self = Rendering::new();
                    self.half = half;
                }
                Key::Char('q') | Key::Escape => d.exit(),
                _ => return,
            }
            d.set_title(self.title(d.fps()));
        }

        /// `mousePressed`: a drag starts.
        fn mouse_pressed(&mut self, e: &MouseEvent, _d: &mut Drawable) {
            if e.button == Some(MouseButton::Left) {
                self.drag = Some((e.x, e.y));
            }
        }

        /// `mouseReleased`: the drag ends.
        fn mouse_released(&mut self, e: &MouseEvent, _d: &mut Drawable) {
            if e.button == Some(MouseButton::Left) {
                self.drag = None;
            }
        }

        /// `mouseDragged`: half a degree per pixel, up and down limited to ±85°.
        fn mouse_dragged(&mut self, e: &MouseEvent, _d: &mut Drawable) {
            if let Some((x, y)) = self.drag {
                self.yaw += (0.5 * (e.x - x)) as f32;
                self.pitch = (self.pitch + (0.5 * (e.y - y)) as f32).clamp(-85.0, 85.0);
                self.drag = Some((e.x, e.y));
            }
        }

        /// `mouseMoved`: the light goes to the pointer, in front of the surface.
        fn mouse_moved(&mut self, e: &MouseEvent, d: &mut Drawable) {
            let (w, h) = (f64::from(d.width()), f64::from(d.height()));
            let x = (2.0 * e.x / w - 1.0) * self.half.0;
            let y = (1.0 - 2.0 * e.y / h) * self.half.1;
            self.light_eye = Some([x as f32, y as f32, 3.0, 1.0]);
        }
    }
}

/// Built without the `window` feature: no window to open.
#[cfg(not(feature = "window"))]
mod interactive {
    pub fn window(_args: Vec<String>) -> Result<(), Box<dyn std::error::Error>> {
        Err("this build has no windows: build with the `window` feature (on by default)".into())
    }
}
