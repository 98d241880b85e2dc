//! The scene registry: named drawings that the CLI renders on either backend, compares and
//! benchmarks, each with the tolerance its comparison must meet.
//!
//! A scene is a plain function making GL calls on a [`Context`]; the runner records them
//! (`Context::start_recording`) and replays the same `Call` stream on the real driver, so one
//! drawing function serves both backends. Design decision: the registry is a static slice, so
//! adding a scene is one entry (and usually one new file under `src/scenes/`) with no
//! registration code.

use crate::{gl, Call, Context, ContextConfig, Error};

pub mod gaussian;
pub mod lights;
pub mod primitives;
pub mod shapes;
pub mod sphere;
pub mod surface;
pub mod transforms;
// Display-list and glut-shapes scenes (scenes/lists.rs)
pub mod lists;
// Seed 004's VBO/EBO examples
pub mod arrays;
pub mod fbo;
pub mod fragment;
pub mod projective;
pub mod texture;
// 1D and 3D textures (scenes/targets.rs)
pub mod targets;
// Pixel rectangles, bitmaps, CopyPixels (scenes/pixels.rs)
pub mod pixels;
// Selection: scenes/picking.rs
pub mod picking;
// Evaluators: scenes/evaluators.rs
pub mod evaluators;
// Line and polygon stipple (scenes/stipple.rs)
pub mod stipple;
// GLU quadrics (scenes/quadrics.rs)
pub mod quadrics;
// GLUT text (scenes/text.rs)
pub mod text;
// GLU tessellator (scenes/tessellation.rs)
pub mod tessellation;
// Smooth points, lines and polygons (scenes/antialiasing.rs)
pub mod antialiasing;
// Point sprites and point parameters (scenes/sprites.rs)
pub mod sprites;
// Accumulation buffer: motion blur, depth of field (scenes/accum.rs)
pub mod accum;
// Occlusion queries driving what is drawn (scenes/occlusion.rs)
pub mod occlusion;

/// The lecture scenes' target: at most 0.05% of pixels off by more than 2/255 from the driver.
pub const LECTURE: Tolerance = Tolerance {
    channel: 2,
    max_percent: 0.05,
};

/// The framebuffer most scenes draw on: `ContextConfig::default()` (single-buffered RGBA8,
/// depth and stencil, no accumulation buffer).
pub const DEFAULT_CONFIG: ContextConfig = ContextConfig {
    double_buffered: false,
    depth: true,
    stencil: true,
    accum: false,
    alpha: true,
};

/// How close the CPU and GL renderings of a scene must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// A pixel differs when some channel differs by more than this.
    pub channel: u8,
    /// The comparison passes when at most this percentage of pixels differ.
    pub max_percent: f64,
}

/// One named drawing.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    /// Command-line name (`fixedgl render <name>`).
    pub name: &'static str,
    /// One line saying what it shows and which GL features it exercises.
    pub summary: &'static str,
    /// The comparison's pass criterion.
    pub tolerance: Tolerance,
    /// Framebuffer size when the command line gives none.
    pub default_size: (u32, u32),
    /// Makes the scene's GL calls on a fresh context of the chosen size.
    pub draw: fn(&mut Context),
    /// For a scene that moves: its calls at `t` seconds into the animation (`fixedgl view`).
    /// At `t = 0` it makes exactly the calls of `draw`, so the still image is frame 0.
    pub animate: Option<fn(&mut Context, f32)>,
    /// The framebuffer's buffers, on both backends ([`DEFAULT_CONFIG`] for most; the
    /// accumulation scenes ask for an accumulation buffer).
    pub config: ContextConfig,
}

impl Scene {
    /// Draws the scene on a new `width` x `height` CPU context, returning the context (its
    /// framebuffer holds the CPU rendering) and the recorded calls.
    pub fn record(&self, width: u32, height: u32) -> Result<(Context, Vec<Call>), Error> {
        let mut ctx = Context::with_config(width, height, self.config)?;
        ctx.start_recording();
        (self.draw)(&mut ctx);
        let calls = ctx.stop_recording();
        Ok((ctx, calls))
    }

    /// Makes the scene's calls at `t` seconds into its animation (`draw` for a still scene).
    pub fn draw_at(&self, gl: &mut Context, t: f32) {
        match self.animate {
            Some(animate) => animate(gl, t),
            None => (self.draw)(gl),
        }
    }

    /// Like [`Scene::record`], at `t` seconds into the animation.
    pub fn record_at(
        &self,
        width: u32,
        height: u32,
        t: f32,
    ) -> Result<(Context, Vec<Call>), Error> {
        let mut ctx = Context::with_config(width, height, self.config)?;
        ctx.start_recording();
        self.draw_at(&mut ctx, t);
        let calls = ctx.stop_recording();
        Ok((ctx, calls))
    }
}

static SCENES: &[Scene] = &[
    Scene {
        name: "triangle",
        summary:
            "Primitives: colour interpolation — one smooth-shaded triangle with red, green and blue corners (Begin/Color4f/Vertex3f/End)",
        tolerance: Tolerance {
            channel: 2,
            max_percent: 0.5,
        },
        default_size: (256, 256),
        draw: triangle,
        animate: None,
        config: DEFAULT_CONFIG,
    },
    gaussian::SCENES[0],
    gaussian::SCENES[1],
    gaussian::SCENES[2],
    gaussian::SCENES[3],
    surface::SCENES[0],
    surface::SCENES[1],
    sphere::SCENES[0],
    lights::SCENES[0],
    lights::SCENES[1],
    lights::SCENES[2],
    lights::SCENES[3],
    lights::SCENES[4],
    lights::SCENES[5],
    sphere::SCENES[1],
    transforms::SCENES[0],
    primitives::SCENES[0],
    primitives::SCENES[1],
    lists::SCENES[0],
    lists::SCENES[1],
    arrays::SCENES[0],
    arrays::SCENES[1],
    fragment::SCENES[0],
    fragment::SCENES[1],
    fragment::SCENES[2],
    fragment::SCENES[3],
    texture::SCENES[0],
    targets::SCENES[0],
    projective::SCENES[0],
    projective::SCENES[1],
    fbo::SCENES[0],
    pixels::SCENES[0],
    picking::SCENES[0],
    evaluators::SCENES[0],
    stipple::SCENES[0],
    quadrics::SCENES[0],
    text::SCENES[0],
    tessellation::SCENES[0],
    antialiasing::SCENES[0],
    sprites::SCENES[0],
    accum::SCENES[0],
    accum::SCENES[1],
    occlusion::SCENES[0],
];

/// Every registered scene, in listing order.
pub fn scenes() -> &'static [Scene] {
    SCENES
}

/// The scene called `name`, if any.
pub fn find(name: &str) -> Option<&'static Scene> {
    SCENES.iter().find(|s| s.name == name)
}

/// `triangle`: a triangle in normalised device coordinates (identity matrices) with one colour
/// per corner, smooth shading.
fn triangle(gl: &mut Context) {
    gl.begin(gl::TRIANGLES);
    gl.color4f(1.0, 0.0, 0.0, 1.0);
    gl.vertex3f(-0.8, -0.8, 0.0);
    gl.color4f(0.0, 1.0, 0.0, 1.0);
    gl.vertex3f(0.8, -0.8, 0.0);
    gl.color4f(0.0, 0.0, 1.0, 1.0);
    gl.vertex3f(0.0, 0.8, 0.0);
    gl.end();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_names_are_unique_and_findable() {
        for (i, s) in scenes().iter().enumerate() {
            assert!(scenes()[..i].iter().all(|o| o.name != s.name), "{}", s.name);
            assert_eq!(find(s.name).map(|f| f.name), Some(s.name));
        }
        assert!(find("no-such-scene").is_none());
    }

    #[test]
    fn default_config_is_the_context_default() {
        assert_eq!(DEFAULT_CONFIG, ContextConfig::default());
    }

    #[test]
    fn triangle_records_its_calls() {
        let calls = find("triangle")
            .and_then(|s| s.record(8, 8).ok())
            .map(|(_, calls)| calls)
            .unwrap_or_default();
        assert_eq!(calls.len(), 8);
        assert_eq!(calls.first(), Some(&Call::Begin(gl::TRIANGLES)));
        assert_eq!(calls.get(2), Some(&Call::Vertex3f(-0.8, -0.8, 0.0)));
        assert_eq!(calls.last(), Some(&Call::End));
    }

    /// An animated scene's frame 0 is its still image call for call (so the registered pictures
    /// do not change), and later frames differ from it (so it does move). Drawn at 64x64 to be
    /// quick; the 400-cell surface makes the same calls as the 40-cell one but ten times more.
    #[test]
    fn animated_scenes_start_at_their_still_image_and_move() {
        let animated: Vec<&Scene> = scenes()
            .iter()
            .filter(|s| s.animate.is_some() && s.name != "gauss-smooth-400")
            .collect();
        assert!(animated.len() >= 6, "{}", animated.len());
        for s in animated {
            let (mut still, still_calls) = s.record(64, 64).unwrap();
            let (mut zero, zero_calls) = s.record_at(64, 64, 0.0).unwrap();
            assert!(
                still_calls == zero_calls,
                "{}: frame 0 is not the still scene",
                s.name
            );
            assert_eq!(still.to_image(), zero.to_image(), "{}", s.name);
            let (mut later, later_calls) = s.record_at(64, 64, 1.5).unwrap();
            assert!(later_calls != still_calls, "{}: no motion", s.name);
            assert_ne!(later.to_image(), still.to_image(), "{}: no motion", s.name);
        }
    }
}
