//! `picking`: selection as lecture programs do it (GL 2.1 §5.2, GLU's gluPickMatrix). A 4x4
//! grid of lit GLUT solids, each with a name; a selection pass restricted by `glu::pick_matrix`
//! to a small box around a cursor collects the hit records; the nearest hit (smallest minimum
//! depth) is drawn highlighted, with the pick box and a crosshair over the cursor.
//!
//! The picked object comes from the CPU context's own hit records, so the recorded stream
//! carries the choice into the driver's replay; `tests/it/select.rs` checks that the driver's
//! selection pass over the same calls writes the same records.

use crate::gl::*;
use crate::{glu, glut, Context};

use super::{Scene, LECTURE};

/// The scenes of this module, for the registry.
pub const SCENES: [Scene; 1] = [Scene {
    name: "picking",
    summary: "Selection: picking — a 4x4 grid of named lit GLUT solids; RenderMode(SELECT) with gluPickMatrix (7x7 \
              around the cursor) and LoadName per object finds the objects under the cursor, the nearest hit drawn \
              highlighted, with the pick box",
    tolerance: LECTURE,
    default_size: (800, 800),
    draw: picking,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

/// The cursor, in window coordinates (y up, as GLUT programs compute `height - mouse_y`), at
/// the default 800x800 size: over two objects, one in front of the other.
pub const CURSOR: (f64, f64) = (300.0, 396.0);
/// The pick box's side, in pixels.
pub const PICK_SIZE: f64 = 7.0;

/// One hit record (GL 2.1 §5.2): the minimum and maximum window depth scaled to 2^32 − 1,
/// and the name stack.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hit {
    /// Minimum window z of the hit, scaled.
    pub z_min: u32,
    /// Maximum window z of the hit, scaled.
    pub z_max: u32,
    /// The names on the stack when the hit was recorded, bottom first.
    pub names: Vec<u32>,
}

/// The `count` hit records at the start of `buffer` (what RenderMode returned; nothing for -1).
pub fn hits(buffer: &[u32], count: i32) -> Vec<Hit> {
    let mut out = Vec::new();
    let mut at = 0usize;
    for _ in 0..count.max(0) {
        let Some(&n) = buffer.get(at) else { break };
        let n = n as usize;
        let (Some(&z_min), Some(&z_max)) = (buffer.get(at + 1), buffer.get(at + 2)) else {
            break;
        };
        let Some(names) = buffer.get(at + 3..at + 3 + n) else {
            break;
        };
        out.push(Hit {
            z_min,
            z_max,
            names: names.to_vec(),
        });
        at += 3 + n;
    }
    out
}

/// The nearest named hit's name: the object a program highlights.
pub fn nearest(hits: &[Hit]) -> Option<u32> {
    hits.iter()
        .filter_map(|h| Some((h.z_min, *h.names.last()?)))
        .min()
        .map(|(_, name)| name)
}

/// The objects' colours, one per column.
const COLOURS: [[f32; 3]; 4] = [
    [0.8, 0.25, 0.2],
    [0.25, 0.7, 0.3],
    [0.25, 0.4, 0.85],
    [0.75, 0.6, 0.2],
];

/// The projection, for both passes (the selection pass multiplies the pick matrix before it).
fn projection(gl: &mut Context) {
    glu::perspective(gl, 45.0, 1.0, 2.0, 40.0);
}

/// Draws the sixteen objects, object `i` (row-major, front row last) named `i + 1`, the
/// `picked` one highlighted.
fn objects(gl: &mut Context, picked: Option<u32>) {
    for i in 0..16u32 {
        let (row, col) = (i / 4, i % 4);
        let name = i + 1;
        gl.load_name(name);
        gl.push_matrix();
        gl.translatef(-4.5 + 3.0 * col as f32, 0.0, -4.5 + 3.0 * row as f32);
        let [r, g, b] = COLOURS[col as usize];
        if picked == Some(name) {
            gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &[1.0, 0.95, 0.3, 1.0]);
            gl.materialfv(FRONT, EMISSION, &[0.35, 0.3, 0.0, 1.0]);
        } else {
            gl.materialfv(FRONT, AMBIENT_AND_DIFFUSE, &[r, g, b, 1.0]);
            gl.materialfv(FRONT, EMISSION, &[0.0, 0.0, 0.0, 1.0]);
        }
        match (i + row) % 4 {
            0 => glut::solid_sphere(gl, 1.0, 24, 16),
            1 => glut::solid_cube(gl, 1.5),
            2 => glut::solid_torus(gl, 0.3, 0.8, 12, 24),
            _ => {
                gl.rotatef(-90.0, 1.0, 0.0, 0.0);
                glut::solid_cone(gl, 0.9, 1.8, 20, 4);
            }
        }
        gl.pop_matrix();
    }
}

/// `picking`: set-up, the selection pass at [`CURSOR`] (scaled to the viewport), the render
/// pass with the nearest hit highlighted, the pick box.
pub fn picking(gl: &mut Context) {
    picking_at(gl, CURSOR);
}

/// [`picking`] with the cursor at `cursor` (for 800x800; scaled to the viewport).
pub fn picking_at(gl: &mut Context, cursor: (f64, f64)) {
    let mut vp = [0i32; 4];
    gl.get_integerv(VIEWPORT, &mut vp);
    let (cx, cy) = (
        cursor.0 * f64::from(vp[2]) / 800.0,
        cursor.1 * f64::from(vp[3]) / 800.0,
    );
    gl.clear_color(0.12, 0.12, 0.16, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    projection(gl);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 7.0, 13.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &[2.0, 4.0, 3.0, 0.0]);
    gl.lightfv(LIGHT0, SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.materialfv(FRONT, SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(FRONT, SHININESS, 30.0);
    gl.enable(NORMALIZE);

    // The selection pass: the same objects, through a pick matrix around the cursor.
    gl.select_buffer(256);
    gl.render_mode(SELECT);
    gl.init_names();
    gl.push_name(0);
    gl.matrix_mode(PROJECTION);
    gl.push_matrix();
    gl.load_identity();
    glu::pick_matrix(gl, cx, cy, PICK_SIZE, PICK_SIZE, vp);
    projection(gl);
    gl.matrix_mode(MODELVIEW);
    objects(gl, None);
    gl.matrix_mode(PROJECTION);
    gl.pop_matrix();
    gl.matrix_mode(MODELVIEW);
    let count = gl.render_mode(RENDER);
    let picked = nearest(&hits(gl.selection_buffer(), count));

    // The render pass.
    objects(gl, picked);

    // The pick box, in window coordinates, a quarter pixel off the pixel centres.
    gl.disable(LIGHTING);
    gl.disable(DEPTH_TEST);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::ortho_2d(gl, 0.0, f64::from(vp[2]), 0.0, f64::from(vp[3]));
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    let h = (PICK_SIZE / 2.0) as f32;
    let (x, y) = (cx as f32 + 0.25, cy as f32 + 0.25);
    gl.color3f(1.0, 1.0, 1.0);
    gl.begin(LINE_LOOP);
    gl.vertex2f(x - h, y - h);
    gl.vertex2f(x + h, y - h);
    gl.vertex2f(x + h, y + h);
    gl.vertex2f(x - h, y + h);
    gl.end();
    gl.begin(LINES);
    for (dx, dy) in [(-1.0, 0.0), (1.0, 0.0), (0.0, -1.0), (0.0, 1.0)] {
        gl.vertex2f(x + dx * (h + 2.0), y + dy * (h + 2.0));
        gl.vertex2f(x + dx * (h + 12.0), y + dy * (h + 12.0));
    }
    gl.end();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_records_parse_and_the_nearest_wins() {
        let buf = [1, 900, 950, 4, 2, 100, 700, 0, 9, 0, 5, 6];
        let h = hits(&buf, 3);
        assert_eq!(h.len(), 3);
        assert_eq!(h[1].names, [0, 9]);
        assert_eq!(nearest(&h), Some(9));
        // An overflowed selection returns -1: no records to trust.
        assert!(hits(&buf, -1).is_empty());
    }

    #[test]
    fn the_cursor_picks_two_objects_and_the_front_one_wins() {
        let mut gl = Context::new(800, 800).expect("context");
        picking(&mut gl);
        assert_eq!(gl.get_error(), NO_ERROR);
        // The selection buffer still holds the pass's records after RenderMode(RENDER).
        let buf = gl.selection_buffer().to_vec();
        let mut count = 0;
        let mut at = 0;
        while at < buf.len() {
            at += 3 + buf[at] as usize;
            count += 1;
        }
        let h = hits(&buf, count);
        assert!(h.len() >= 2, "the pick box covers two objects: {h:?}");
        let front = nearest(&h);
        assert!(front.is_some());
        // The nearest is in a row nearer the eye than some other hit's.
        let rows: Vec<u32> = h
            .iter()
            .filter_map(|x| x.names.last())
            .map(|n| (n - 1) / 4)
            .collect();
        let front_row = front.map(|n| (n - 1) / 4).unwrap_or(0);
        assert!(rows.iter().any(|&r| r < front_row), "{h:?}");
    }
}
