//! The GLU tessellator (GLU 1.3 §5): `gluNewTess`, `gluTessProperty`, `gluTessNormal`,
//! `gluTessCallback`, `gluTessBeginPolygon` / `BeginContour` / `Vertex` / `EndContour` /
//! `EndPolygon`, and the GLU 1.1 `gluBeginPolygon` / `gluNextContour` / `gluEndPolygon`.
//!
//! It follows the algorithm of SGI's libGLU (the one Mesa ships): a single contour of at most
//! 100 vertices that is convex (all turns the same way) is sent as one fan (or triangle, or
//! line loop); anything else goes through a plane sweep over a half-edge mesh
//! (`tess_sweep.rs`, `tess_mesh.rs`) that splits the contours at their intersections (calling
//! COMBINE for each new vertex), classifies the regions by the winding rule, cuts each inside
//! region into monotone pieces and those into triangles, which are emitted as the longest fans
//! and strips found around each triangle, the rest as one GL_TRIANGLES batch — the same
//! primitives, vertices and order as libGLU (`tests/it/glu_tess.rs` compares the two on the
//! same input, and the driver draws both).
//!
//! Design decisions: callbacks are Rust closures. The `_DATA` forms receive the polygon data
//! given to `begin_polygon` (`Option<&mut P>`: `None` when the polygon was begun implicitly,
//! as libGLU passes NULL); `end_polygon` hands that data back. Vertex data is any `V: Clone`;
//! COMBINE returns `Option<V>` (libGLU's `*outData`, `None` being NULL). Coordinates that are
//! NaN are taken as 0 with GLU_TESS_COORD_TOO_LARGE (libGLU's sweep has no answer for them).

use super::tess_mesh::{sym, Mesh, NIL};
use super::tess_sweep::{edge_sign, p2, vert_leq, Sweep, SweepHost, MAX_COORD};
use crate::gl;

/// `GLU_TESS_BEGIN`.
pub const GLU_TESS_BEGIN: u32 = 100_100;
/// `GLU_TESS_VERTEX`.
pub const GLU_TESS_VERTEX: u32 = 100_101;
/// `GLU_TESS_END`.
pub const GLU_TESS_END: u32 = 100_102;
/// `GLU_TESS_ERROR`.
pub const GLU_TESS_ERROR: u32 = 100_103;
/// `GLU_TESS_EDGE_FLAG`.
pub const GLU_TESS_EDGE_FLAG: u32 = 100_104;
/// `GLU_TESS_COMBINE`.
pub const GLU_TESS_COMBINE: u32 = 100_105;
/// `GLU_TESS_BEGIN_DATA`.
pub const GLU_TESS_BEGIN_DATA: u32 = 100_106;
/// `GLU_TESS_VERTEX_DATA`.
pub const GLU_TESS_VERTEX_DATA: u32 = 100_107;
/// `GLU_TESS_END_DATA`.
pub const GLU_TESS_END_DATA: u32 = 100_108;
/// `GLU_TESS_ERROR_DATA`.
pub const GLU_TESS_ERROR_DATA: u32 = 100_109;
/// `GLU_TESS_EDGE_FLAG_DATA`.
pub const GLU_TESS_EDGE_FLAG_DATA: u32 = 100_110;
/// `GLU_TESS_COMBINE_DATA`.
pub const GLU_TESS_COMBINE_DATA: u32 = 100_111;
/// `GLU_TESS_WINDING_ODD`.
pub const GLU_TESS_WINDING_ODD: u32 = 100_130;
/// `GLU_TESS_WINDING_NONZERO`.
pub const GLU_TESS_WINDING_NONZERO: u32 = 100_131;
/// `GLU_TESS_WINDING_POSITIVE`.
pub const GLU_TESS_WINDING_POSITIVE: u32 = 100_132;
/// `GLU_TESS_WINDING_NEGATIVE`.
pub const GLU_TESS_WINDING_NEGATIVE: u32 = 100_133;
/// `GLU_TESS_WINDING_ABS_GEQ_TWO`.
pub const GLU_TESS_WINDING_ABS_GEQ_TWO: u32 = 100_134;
/// `GLU_TESS_WINDING_RULE`.
pub const GLU_TESS_WINDING_RULE: u32 = 100_140;
/// `GLU_TESS_BOUNDARY_ONLY`.
pub const GLU_TESS_BOUNDARY_ONLY: u32 = 100_141;
/// `GLU_TESS_TOLERANCE`.
pub const GLU_TESS_TOLERANCE: u32 = 100_142;
/// `GLU_TESS_MISSING_BEGIN_POLYGON`.
pub const GLU_TESS_MISSING_BEGIN_POLYGON: u32 = 100_151;
/// `GLU_TESS_MISSING_BEGIN_CONTOUR`.
pub const GLU_TESS_MISSING_BEGIN_CONTOUR: u32 = 100_152;
/// `GLU_TESS_MISSING_END_POLYGON`.
pub const GLU_TESS_MISSING_END_POLYGON: u32 = 100_153;
/// `GLU_TESS_MISSING_END_CONTOUR`.
pub const GLU_TESS_MISSING_END_CONTOUR: u32 = 100_154;
/// `GLU_TESS_COORD_TOO_LARGE`.
pub const GLU_TESS_COORD_TOO_LARGE: u32 = 100_155;
/// `GLU_TESS_NEED_COMBINE_CALLBACK`.
pub const GLU_TESS_NEED_COMBINE_CALLBACK: u32 = 100_156;
/// `GLU_TESS_MAX_COORD`: coordinates are clamped to ±1e150.
pub const GLU_TESS_MAX_COORD: f64 = MAX_COORD;
/// GLU 1.1 contour types for `next_contour` (ignored, as in libGLU).
pub const GLU_CW: u32 = 100_120;
/// `GLU_CCW`.
pub const GLU_CCW: u32 = 100_121;
/// `GLU_INTERIOR`.
pub const GLU_INTERIOR: u32 = 100_122;
/// `GLU_EXTERIOR`.
pub const GLU_EXTERIOR: u32 = 100_123;
/// `GLU_UNKNOWN`.
pub const GLU_UNKNOWN: u32 = 100_124;

const TESS_MAX_CACHE: usize = 100;

/// Optional polygon data handed to the `_DATA` callbacks.
pub type PolyData<'p, P> = Option<&'p mut P>;

type BeginFn = Box<dyn FnMut(u32)>;
type EdgeFlagFn = Box<dyn FnMut(bool)>;
type EndFn = Box<dyn FnMut()>;
type ErrorFn = Box<dyn FnMut(u32)>;
type BeginDataFn<P> = Box<dyn FnMut(u32, Option<&mut P>)>;
type EdgeFlagDataFn<P> = Box<dyn FnMut(bool, Option<&mut P>)>;
type EndDataFn<P> = Box<dyn FnMut(Option<&mut P>)>;
type ErrorDataFn<P> = Box<dyn FnMut(u32, Option<&mut P>)>;
type VertexFn<V> = Box<dyn FnMut(&V)>;
type VertexDataFn<V, P> = Box<dyn FnMut(&V, Option<&mut P>)>;
type CombineFn<V> = Box<dyn FnMut([f64; 3], [Option<&V>; 4], [f32; 4]) -> Option<V>>;
type CombineDataFn<V, P> =
    Box<dyn FnMut([f64; 3], [Option<&V>; 4], [f32; 4], Option<&mut P>) -> Option<V>>;

/// One tessellator callback (`gluTessCallback`'s `which` and function together).
pub enum TessCallback<V, P = ()> {
    /// GLU_TESS_BEGIN: the primitive type (TRIANGLES, TRIANGLE_FAN, TRIANGLE_STRIP, or
    /// LINE_LOOP with BOUNDARY_ONLY).
    Begin(BeginFn),
    /// The `_DATA` form of `Begin`: also gets the polygon data.
    BeginData(BeginDataFn<P>),
    /// GLU_TESS_EDGE_FLAG: whether the edges that follow lie on the boundary. Setting it makes
    /// the tessellator emit separate triangles only (as libGLU).
    EdgeFlag(EdgeFlagFn),
    /// The `_DATA` form of `EdgeFlag`: also gets the polygon data.
    EdgeFlagData(EdgeFlagDataFn<P>),
    /// GLU_TESS_VERTEX: a vertex's data.
    Vertex(VertexFn<V>),
    /// The `_DATA` form of `Vertex`: also gets the polygon data.
    VertexData(VertexDataFn<V, P>),
    /// GLU_TESS_END.
    End(EndFn),
    /// The `_DATA` form of `End`: also gets the polygon data.
    EndData(EndDataFn<P>),
    /// GLU_TESS_COMBINE: data for a new vertex at an intersection or merge, from up to four
    /// vertices' data and weights.
    Combine(CombineFn<V>),
    /// The `_DATA` form of `Combine`: also gets the polygon data.
    CombineData(CombineDataFn<V, P>),
    /// GLU_TESS_ERROR: a GLU or GLU_TESS_ error code.
    Error(ErrorFn),
    /// The `_DATA` form of `Error`: also gets the polygon data.
    ErrorData(ErrorDataFn<P>),
}

struct Callbacks<V, P> {
    begin: Option<BeginFn>,
    begin_data: Option<BeginDataFn<P>>,
    edge_flag: Option<EdgeFlagFn>,
    edge_flag_data: Option<EdgeFlagDataFn<P>>,
    vertex: Option<VertexFn<V>>,
    vertex_data: Option<VertexDataFn<V, P>>,
    end: Option<EndFn>,
    end_data: Option<EndDataFn<P>>,
    combine: Option<CombineFn<V>>,
    combine_data: Option<CombineDataFn<V, P>>,
    error: Option<ErrorFn>,
    error_data: Option<ErrorDataFn<P>>,
}

struct Out<'a, V, P> {
    cb: &'a mut Callbacks<V, P>,
    data: &'a mut Vec<V>,
    poly: &'a mut Option<P>,
}

impl<V, P> Out<'_, V, P> {
    fn begin(&mut self, ty: u32) {
        if let Some(f) = self.cb.begin_data.as_mut() {
            f(ty, self.poly.as_mut());
        } else if let Some(f) = self.cb.begin.as_mut() {
            f(ty);
        }
    }
    fn vertex(&mut self, d: Option<usize>) {
        // libGLU passes NULL data through; fixedgl's data always exists except after a
        // failed combine, whose polygon is never drawn (fatal error).
        let Some(v) = d.and_then(|i| self.data.get(i)) else {
            return;
        };
        if let Some(f) = self.cb.vertex_data.as_mut() {
            f(v, self.poly.as_mut());
        } else if let Some(f) = self.cb.vertex.as_mut() {
            f(v);
        }
    }
    fn edge_flag(&mut self, b: bool) {
        if let Some(f) = self.cb.edge_flag_data.as_mut() {
            f(b, self.poly.as_mut());
        } else if let Some(f) = self.cb.edge_flag.as_mut() {
            f(b);
        }
    }
    fn end(&mut self) {
        if let Some(f) = self.cb.end_data.as_mut() {
            f(self.poly.as_mut());
        } else if let Some(f) = self.cb.end.as_mut() {
            f();
        }
    }
    fn error(&mut self, code: u32) {
        if let Some(f) = self.cb.error_data.as_mut() {
            f(code, self.poly.as_mut());
        } else if let Some(f) = self.cb.error.as_mut() {
            f(code);
        }
    }
}

impl<V: Clone, P> SweepHost for Out<'_, V, P> {
    fn combine(
        &mut self,
        coords: [f64; 3],
        data: [Option<usize>; 4],
        weights: [f32; 4],
    ) -> Option<usize> {
        let vd = &*self.data;
        let refs = data.map(|d| d.and_then(|i| vd.get(i)));
        let out = if let Some(f) = self.cb.combine_data.as_mut() {
            f(coords, refs, weights, self.poly.as_mut())
        } else if let Some(f) = self.cb.combine.as_mut() {
            f(coords, refs, weights)
        } else {
            None
        };
        out.map(|v| {
            self.data.push(v);
            self.data.len() - 1
        })
    }
    fn error(&mut self, code: u32) {
        Out::error(self, code);
    }
}

#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum State {
    Dormant,
    InPolygon,
    InContour,
}

/// A tessellation object (`GLUtesselator`). `V` is the vertex data, `P` the polygon data the
/// `_DATA` callbacks receive. Dropping it is `gluDeleteTess`.
pub struct Tess<V, P = ()> {
    state: State,
    last_edge: usize,
    mesh: Option<Mesh>,
    normal: [f64; 3],
    rel_tolerance: f64,
    winding_rule: u32,
    flag_boundary: bool,
    boundary_only: bool,
    empty_cache: bool,
    cache: Vec<([f64; 3], usize)>,
    cb: Callbacks<V, P>,
    data: Vec<V>,
    poly: Option<P>,
}

impl<V, P> std::fmt::Debug for Tess<V, P> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tess")
            .field("state", &self.state)
            .field("winding_rule", &self.winding_rule)
            .field("boundary_only", &self.boundary_only)
            .field("tolerance", &self.rel_tolerance)
            .field("normal", &self.normal)
            .finish()
    }
}

/// `gluNewTess`: winding rule ODD, no boundary-only, tolerance 0, normal (0, 0, 0) (computed
/// from the vertices), no callbacks.
pub fn new_tess<V: Clone, P>() -> Tess<V, P> {
    Tess::new()
}

/// `gluDeleteTess`: ends any polygon in progress (with the errors libGLU reports) and drops
/// the tessellator.
pub fn delete_tess<V: Clone, P>(mut tess: Tess<V, P>) {
    tess.require_state(State::Dormant);
}

impl<V: Clone, P> Default for Tess<V, P> {
    fn default() -> Self {
        Self::new()
    }
}

impl<V: Clone, P> Tess<V, P> {
    /// `gluNewTess`.
    pub fn new() -> Self {
        Tess {
            state: State::Dormant,
            last_edge: NIL,
            mesh: None,
            normal: [0.0; 3],
            rel_tolerance: 0.0,
            winding_rule: GLU_TESS_WINDING_ODD,
            flag_boundary: false,
            boundary_only: false,
            empty_cache: false,
            cache: Vec::new(),
            cb: Callbacks {
                begin: None,
                begin_data: None,
                edge_flag: None,
                edge_flag_data: None,
                vertex: None,
                vertex_data: None,
                end: None,
                end_data: None,
                combine: None,
                combine_data: None,
                error: None,
                error_data: None,
            },
            data: Vec::new(),
            poly: None,
        }
    }

    fn out(&mut self) -> Out<'_, V, P> {
        Out {
            cb: &mut self.cb,
            data: &mut self.data,
            poly: &mut self.poly,
        }
    }

    fn error(&mut self, code: u32) {
        self.out().error(code);
    }

    fn make_dormant(&mut self) {
        self.mesh = None;
        self.state = State::Dormant;
        self.last_edge = NIL;
        self.cache.clear();
        self.data.clear();
    }

    fn require_state(&mut self, new: State) {
        while self.state != new {
            if self.state < new {
                match self.state {
                    State::Dormant => {
                        self.error(GLU_TESS_MISSING_BEGIN_POLYGON);
                        self.begin_polygon_inner(None);
                    }
                    State::InPolygon => {
                        self.error(GLU_TESS_MISSING_BEGIN_CONTOUR);
                        self.begin_contour();
                    }
                    State::InContour => {}
                }
            } else {
                match self.state {
                    State::InContour => {
                        self.error(GLU_TESS_MISSING_END_CONTOUR);
                        self.end_contour();
                    }
                    State::InPolygon => {
                        self.error(GLU_TESS_MISSING_END_POLYGON);
                        self.make_dormant();
                    }
                    State::Dormant => {}
                }
            }
        }
    }

    /// `gluTessProperty`: GLU_TESS_WINDING_RULE (one of the five rules), GLU_TESS_BOUNDARY_ONLY
    /// (non-zero: emit the boundaries as line loops), GLU_TESS_TOLERANCE (0 to 1; stored, and
    /// as in libGLU not used: coincident vertices merge only when equal). A value out of range
    /// is GLU_INVALID_VALUE, another `which` GLU_INVALID_ENUM (through the ERROR callback).
    /// As libGLU does, an integral winding value that is not a rule falls through to
    /// BOUNDARY_ONLY (sets boundary-only to value ≠ 0, no error).
    pub fn property(&mut self, which: u32, value: f64) {
        match which {
            GLU_TESS_TOLERANCE => {
                if (0.0..=1.0).contains(&value) {
                    self.rel_tolerance = value;
                    return;
                }
            }
            GLU_TESS_WINDING_RULE => {
                let rule = value as u32;
                if f64::from(rule) == value {
                    match rule {
                        GLU_TESS_WINDING_ODD
                        | GLU_TESS_WINDING_NONZERO
                        | GLU_TESS_WINDING_POSITIVE
                        | GLU_TESS_WINDING_NEGATIVE
                        | GLU_TESS_WINDING_ABS_GEQ_TWO => self.winding_rule = rule,
                        _ => self.boundary_only = value != 0.0,
                    }
                    return;
                }
            }
            GLU_TESS_BOUNDARY_ONLY => {
                self.boundary_only = value != 0.0;
                return;
            }
            _ => {
                self.error(super::GLU_INVALID_ENUM as u32);
                return;
            }
        }
        self.error(super::GLU_INVALID_VALUE as u32);
    }

    /// `gluGetTessProperty`: the value of a property (0 and GLU_INVALID_ENUM for another).
    pub fn get_property(&mut self, which: u32) -> f64 {
        match which {
            GLU_TESS_TOLERANCE => self.rel_tolerance,
            GLU_TESS_WINDING_RULE => f64::from(self.winding_rule),
            GLU_TESS_BOUNDARY_ONLY => f64::from(u8::from(self.boundary_only)),
            _ => {
                self.error(super::GLU_INVALID_ENUM as u32);
                0.0
            }
        }
    }

    /// `gluTessNormal`: the plane's normal; (0, 0, 0) (the default) has it computed.
    pub fn normal(&mut self, x: f64, y: f64, z: f64) {
        self.normal = [x, y, z];
    }

    /// `gluTessCallback` with a function.
    pub fn callback(&mut self, cb: TessCallback<V, P>) {
        let c = &mut self.cb;
        match cb {
            TessCallback::Begin(f) => c.begin = Some(f),
            TessCallback::BeginData(f) => c.begin_data = Some(f),
            TessCallback::EdgeFlag(f) => {
                c.edge_flag = Some(f);
                self.flag_boundary = true;
            }
            TessCallback::EdgeFlagData(f) => {
                c.edge_flag_data = Some(f);
                self.flag_boundary = true;
            }
            TessCallback::Vertex(f) => c.vertex = Some(f),
            TessCallback::VertexData(f) => c.vertex_data = Some(f),
            TessCallback::End(f) => c.end = Some(f),
            TessCallback::EndData(f) => c.end_data = Some(f),
            TessCallback::Combine(f) => c.combine = Some(f),
            TessCallback::CombineData(f) => c.combine_data = Some(f),
            TessCallback::Error(f) => c.error = Some(f),
            TessCallback::ErrorData(f) => c.error_data = Some(f),
        }
    }

    /// `gluTessCallback(tess, which, NULL)`: removes a callback (GLU_INVALID_ENUM for an
    /// unknown `which`).
    pub fn clear_callback(&mut self, which: u32) {
        let c = &mut self.cb;
        match which {
            GLU_TESS_BEGIN => c.begin = None,
            GLU_TESS_BEGIN_DATA => c.begin_data = None,
            GLU_TESS_EDGE_FLAG => {
                c.edge_flag = None;
                self.flag_boundary = false;
            }
            GLU_TESS_EDGE_FLAG_DATA => {
                c.edge_flag_data = None;
                self.flag_boundary = false;
            }
            GLU_TESS_VERTEX => c.vertex = None,
            GLU_TESS_VERTEX_DATA => c.vertex_data = None,
            GLU_TESS_END => c.end = None,
            GLU_TESS_END_DATA => c.end_data = None,
            GLU_TESS_COMBINE => c.combine = None,
            GLU_TESS_COMBINE_DATA => c.combine_data = None,
            GLU_TESS_ERROR => c.error = None,
            GLU_TESS_ERROR_DATA => c.error_data = None,
            _ => self.error(super::GLU_INVALID_ENUM as u32),
        }
    }

    fn begin_polygon_inner(&mut self, data: Option<P>) {
        self.require_state(State::Dormant);
        self.state = State::InPolygon;
        self.cache.clear();
        self.data.clear();
        self.empty_cache = false;
        self.mesh = None;
        self.poly = data;
    }

    /// `gluTessBeginPolygon`: starts a polygon; `data` is what the `_DATA` callbacks get.
    pub fn begin_polygon(&mut self, data: P) {
        self.begin_polygon_inner(Some(data));
    }

    /// `gluTessBeginContour`.
    pub fn begin_contour(&mut self) {
        self.require_state(State::InPolygon);
        self.state = State::InContour;
        self.last_edge = NIL;
        if !self.cache.is_empty() {
            self.empty_cache = true;
        }
    }

    fn add_vertex(&mut self, coords: [f64; 3], data: usize) {
        let mesh = self.mesh.get_or_insert_with(Mesh::new);
        let e = if self.last_edge == NIL {
            let e = mesh.make_edge_full();
            mesh.splice(e, sym(e));
            e
        } else {
            mesh.split_edge(self.last_edge);
            mesh.lnext(self.last_edge)
        };
        let o = mesh.org(e);
        mesh.v[o].data = Some(data);
        mesh.v[o].coords = coords;
        mesh.e[e].winding = 1;
        mesh.e[e ^ 1].winding = -1;
        self.last_edge = e;
    }

    fn flush_cache(&mut self) {
        self.mesh = Some(Mesh::new());
        let cache = std::mem::take(&mut self.cache);
        for (c, d) in cache {
            self.add_vertex(c, d);
        }
        self.empty_cache = false;
    }

    /// `gluTessVertex`: a vertex of the current contour with its data (given back to VERTEX
    /// and COMBINE). Coordinates beyond ±GLU_TESS_MAX_COORD are clamped, with
    /// GLU_TESS_COORD_TOO_LARGE.
    pub fn vertex(&mut self, coords: [f64; 3], data: V) {
        self.require_state(State::InContour);
        if self.empty_cache {
            self.flush_cache();
            self.last_edge = NIL;
        }
        let mut too_large = false;
        let mut clamped = [0.0; 3];
        for (c, &x) in clamped.iter_mut().zip(coords.iter()) {
            let mut x = x;
            if x.is_nan() {
                x = 0.0;
                too_large = true;
            }
            if x < -MAX_COORD {
                x = -MAX_COORD;
                too_large = true;
            }
            if x > MAX_COORD {
                x = MAX_COORD;
                too_large = true;
            }
            *c = x;
        }
        if too_large {
            self.error(GLU_TESS_COORD_TOO_LARGE);
        }
        self.data.push(data);
        let d = self.data.len() - 1;
        if self.mesh.is_none() {
            if self.cache.len() < TESS_MAX_CACHE {
                self.cache.push((clamped, d));
                return;
            }
            self.flush_cache();
        }
        self.add_vertex(clamped, d);
    }

    /// `gluTessEndContour`.
    pub fn end_contour(&mut self) {
        self.require_state(State::InContour);
        self.state = State::InPolygon;
    }

    fn wants_rendering(&self) -> bool {
        let c = &self.cb;
        c.begin.is_some()
            || c.end.is_some()
            || c.vertex.is_some()
            || c.edge_flag.is_some()
            || c.begin_data.is_some()
            || c.end_data.is_some()
            || c.vertex_data.is_some()
            || c.edge_flag_data.is_some()
    }

    /// `gluTessEndPolygon`: tessellates and calls the callbacks; gives back the polygon data.
    pub fn end_polygon(&mut self) -> Option<P> {
        self.require_state(State::InPolygon);
        self.state = State::Dormant;
        if self.mesh.is_none() {
            if !self.flag_boundary && self.render_cache() {
                return self.finish();
            }
            self.flush_cache();
        }
        let Some(mut mesh) = self.mesh.take() else {
            return self.finish();
        };
        let normal = self.normal;
        project_polygon(&mut mesh, normal);
        let fatal = {
            let winding_rule = self.winding_rule;
            let mut out = Out {
                cb: &mut self.cb,
                data: &mut self.data,
                poly: &mut self.poly,
            };
            let mut sweep = Sweep::new(&mut mesh, &mut out, winding_rule);
            sweep.compute_interior();
            sweep.fatal_error
        };
        if !fatal {
            if self.boundary_only {
                set_winding_number(&mut mesh, 1, true);
            } else {
                tessellate_interior(&mut mesh);
            }
            if self.wants_rendering() {
                let flag_boundary = self.flag_boundary;
                let boundary_only = self.boundary_only;
                let mut out = self.out();
                if boundary_only {
                    render_boundary(&mut out, &mesh);
                } else {
                    render_mesh(&mut out, &mut mesh, flag_boundary);
                }
            }
        }
        self.finish()
    }

    fn finish(&mut self) -> Option<P> {
        self.mesh = None;
        self.cache.clear();
        self.data.clear();
        self.poly.take()
    }

    /// `gluBeginPolygon` (GLU 1.1): `begin_polygon` with no data, then `begin_contour`.
    pub fn begin_polygon_old(&mut self) {
        self.begin_polygon_inner(None);
        self.begin_contour();
    }

    /// `gluNextContour` (GLU 1.1): ends the contour and begins another (`type_` is ignored).
    pub fn next_contour(&mut self, _type_: u32) {
        self.end_contour();
        self.begin_contour();
    }

    /// `gluEndPolygon` (GLU 1.1): `end_contour`, then `end_polygon`.
    pub fn end_polygon_old(&mut self) {
        self.end_contour();
        self.end_polygon();
    }

    /// `__gl_renderCache`: a single small convex contour goes out as one primitive. Returns
    /// false when the contour is not convex (the sweep must run).
    fn render_cache(&mut self) -> bool {
        let n = self.cache.len();
        if n < 3 {
            return true;
        }
        let mut norm = self.normal;
        if norm == [0.0; 3] {
            cache_normal(&self.cache, &mut norm, false);
        }
        let sign = cache_normal(&self.cache, &mut norm, true);
        if sign == 2 {
            return false;
        }
        if sign == 0 {
            return true;
        }
        match self.winding_rule {
            GLU_TESS_WINDING_POSITIVE if sign < 0 => return true,
            GLU_TESS_WINDING_NEGATIVE if sign > 0 => return true,
            GLU_TESS_WINDING_ABS_GEQ_TWO => return true,
            _ => {}
        }
        let ty = if self.boundary_only {
            gl::LINE_LOOP
        } else if n > 3 {
            gl::TRIANGLE_FAN
        } else {
            gl::TRIANGLES
        };
        let cache = std::mem::take(&mut self.cache);
        let mut out = self.out();
        out.begin(ty);
        out.vertex(Some(cache[0].1));
        if sign > 0 {
            for c in &cache[1..] {
                out.vertex(Some(c.1));
            }
        } else {
            for c in cache[1..].iter().rev() {
                out.vertex(Some(c.1));
            }
        }
        out.end();
        true
    }
}

/// libGLU's `ComputeNormal` of `render.c` over the cached vertices: with `check` false, sums
/// the fan's cross products into `norm`; with `check` true, returns the sign of every turn
/// against `norm` (1, -1, 0 when all are flat, 2 when they disagree).
fn cache_normal(cache: &[([f64; 3], usize)], norm: &mut [f64; 3], check: bool) -> i32 {
    let mut sign = 0;
    if !check {
        *norm = [0.0; 3];
    }
    let v0 = cache[0].0;
    let mut c = [
        cache[1].0[0] - v0[0],
        cache[1].0[1] - v0[1],
        cache[1].0[2] - v0[2],
    ];
    for vc in &cache[2..] {
        let p = c;
        c = [vc.0[0] - v0[0], vc.0[1] - v0[1], vc.0[2] - v0[2]];
        let n = [
            p[1] * c[2] - p[2] * c[1],
            p[2] * c[0] - p[0] * c[2],
            p[0] * c[1] - p[1] * c[0],
        ];
        let dot = n[0] * norm[0] + n[1] * norm[1] + n[2] * norm[2];
        if !check {
            if dot >= 0.0 {
                norm[0] += n[0];
                norm[1] += n[1];
                norm[2] += n[2];
            } else {
                norm[0] -= n[0];
                norm[1] -= n[1];
                norm[2] -= n[2];
            }
        } else if dot != 0.0 {
            if dot > 0.0 {
                if sign < 0 {
                    return 2;
                }
                sign = 1;
            } else {
                if sign > 0 {
                    return 2;
                }
                sign = -1;
            }
        }
    }
    sign
}

fn long_axis(v: [f64; 3]) -> usize {
    let mut i = 0;
    if v[1].abs() > v[0].abs() {
        i = 1;
    }
    if v[2].abs() > v[i].abs() {
        i = 2;
    }
    i
}

/// libGLU's `ComputeNormal` of `normal.c`: the largest cross product of the longest extent's
/// diagonal with each vertex.
fn mesh_normal(mesh: &Mesh) -> [f64; 3] {
    let mut max_val = [-2.0 * MAX_COORD; 3];
    let mut min_val = [2.0 * MAX_COORD; 3];
    let mut max_vert = [0usize; 3];
    let mut min_vert = [0usize; 3];
    let mut v = mesh.v[0].next;
    while v != 0 {
        for i in 0..3 {
            let c = mesh.v[v].coords[i];
            if c < min_val[i] {
                min_val[i] = c;
                min_vert[i] = v;
            }
            if c > max_val[i] {
                max_val[i] = c;
                max_vert[i] = v;
            }
        }
        v = mesh.v[v].next;
    }
    let mut i = 0;
    if max_val[1] - min_val[1] > max_val[0] - min_val[0] {
        i = 1;
    }
    if max_val[2] - min_val[2] > max_val[i] - min_val[i] {
        i = 2;
    }
    if min_val[i] >= max_val[i] {
        return [0.0, 0.0, 1.0];
    }
    let mut norm = [0.0; 3];
    let mut max_len2 = 0.0;
    let (v1, v2) = (mesh.v[min_vert[i]].coords, mesh.v[max_vert[i]].coords);
    let d1 = [v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]];
    let mut v = mesh.v[0].next;
    while v != 0 {
        let c = mesh.v[v].coords;
        let d2 = [c[0] - v2[0], c[1] - v2[1], c[2] - v2[2]];
        let t = [
            d1[1] * d2[2] - d1[2] * d2[1],
            d1[2] * d2[0] - d1[0] * d2[2],
            d1[0] * d2[1] - d1[1] * d2[0],
        ];
        let len2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
        if len2 > max_len2 {
            max_len2 = len2;
            norm = t;
        }
        v = mesh.v[v].next;
    }
    if max_len2 <= 0.0 {
        norm = [0.0; 3];
        norm[long_axis(d1)] = 1.0;
    }
    norm
}

/// `__gl_projectPolygon`: (s, t) = the coordinates along the two axes other than the normal's
/// longest; with a computed normal, t is flipped when the contours' signed area is negative.
fn project_polygon(mesh: &mut Mesh, normal: [f64; 3]) {
    let mut norm = normal;
    let mut computed = false;
    if norm == [0.0; 3] {
        norm = mesh_normal(mesh);
        computed = true;
    }
    let i = long_axis(norm);
    let mut s_unit = [0.0; 3];
    let mut t_unit = [0.0; 3];
    s_unit[(i + 1) % 3] = 1.0;
    s_unit[(i + 2) % 3] = 0.0;
    t_unit[(i + 1) % 3] = if norm[i] > 0.0 { -0.0 } else { 0.0 };
    t_unit[(i + 2) % 3] = if norm[i] > 0.0 { 1.0 } else { -1.0 };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let mut v = mesh.v[0].next;
    while v != 0 {
        let c = mesh.v[v].coords;
        mesh.v[v].s = dot(c, s_unit);
        mesh.v[v].t = dot(c, t_unit);
        v = mesh.v[v].next;
    }
    if computed {
        // CheckOrientation
        let mut area = 0.0;
        let mut f = mesh.f[0].next;
        while f != 0 {
            let start = mesh.f[f].an_edge;
            if mesh.e[start].winding > 0 {
                let mut e = start;
                loop {
                    let (o, d) = (mesh.org(e), mesh.dst(e));
                    area += (mesh.v[o].s - mesh.v[d].s) * (mesh.v[o].t + mesh.v[d].t);
                    e = mesh.lnext(e);
                    if e == start {
                        break;
                    }
                }
            }
            f = mesh.f[f].next;
        }
        if area < 0.0 {
            let mut v = mesh.v[0].next;
            while v != 0 {
                mesh.v[v].t = -mesh.v[v].t;
                v = mesh.v[v].next;
            }
        }
    }
}

fn goes_left(m: &Mesh, e: usize) -> bool {
    vert_leq(p2(m, m.dst(e)), p2(m, m.org(e)))
}
fn goes_right(m: &Mesh, e: usize) -> bool {
    vert_leq(p2(m, m.org(e)), p2(m, m.dst(e)))
}

/// `__gl_meshTessellateMonoRegion`: triangulates one monotone face by connecting vertices
/// from the left, as libGLU does.
fn tessellate_mono_region(m: &mut Mesh, face: usize) {
    let mut up = m.f[face].an_edge;
    if m.lnext(up) == up || m.lnext(m.lnext(up)) == up {
        return;
    }
    while goes_left(m, up) {
        up = m.lprev(up);
    }
    while goes_right(m, up) {
        up = m.lnext(up);
    }
    let mut lo = m.lprev(up);
    while m.lnext(up) != lo {
        if vert_leq(p2(m, m.dst(up)), p2(m, m.org(lo))) {
            while m.lnext(lo) != up
                && (goes_left(m, m.lnext(lo))
                    || edge_sign(
                        p2(m, m.org(lo)),
                        p2(m, m.dst(lo)),
                        p2(m, m.dst(m.lnext(lo))),
                    ) <= 0.0)
            {
                let ln = m.lnext(lo);
                lo = sym(m.connect(ln, lo));
            }
            lo = m.lprev(lo);
        } else {
            while m.lnext(lo) != up
                && (goes_right(m, m.lprev(up))
                    || edge_sign(
                        p2(m, m.dst(up)),
                        p2(m, m.org(up)),
                        p2(m, m.org(m.lprev(up))),
                    ) >= 0.0)
            {
                let lp = m.lprev(up);
                up = sym(m.connect(up, lp));
            }
            up = m.lnext(up);
        }
    }
    while m.lnext(m.lnext(lo)) != up {
        let ln = m.lnext(lo);
        lo = sym(m.connect(ln, lo));
    }
}

fn tessellate_interior(m: &mut Mesh) {
    let mut f = m.f[0].next;
    while f != 0 {
        let next = m.f[f].next;
        if m.f[f].inside {
            tessellate_mono_region(m, f);
        }
        f = next;
    }
}

/// `__gl_meshSetWindingNumber`: boundary edges get ±value; others 0 or (boundary only)
/// removed.
fn set_winding_number(m: &mut Mesh, value: i32, keep_only_boundary: bool) {
    let mut e = m.e[0].next;
    while e != 0 {
        let e_next = m.e[e].next;
        let (l, r) = (m.f[m.lface(e)].inside, m.f[m.rface(e)].inside);
        if r != l {
            m.e[e].winding = if l { value } else { -value };
        } else if !keep_only_boundary {
            m.e[e].winding = 0;
        } else {
            m.delete(e);
        }
        e = e_next;
    }
}

fn render_boundary<V, P>(out: &mut Out<'_, V, P>, m: &Mesh) {
    let mut f = m.f[0].next;
    while f != 0 {
        if m.f[f].inside {
            out.begin(gl::LINE_LOOP);
            let start = m.f[f].an_edge;
            let mut e = start;
            loop {
                out.vertex(m.v[m.org(e)].data);
                e = m.lnext(e);
                if e == start {
                    break;
                }
            }
            out.end();
        }
        f = m.f[f].next;
    }
}

#[derive(Clone, Copy)]
enum Render {
    Triangle,
    Fan,
    Strip,
}

fn marked(m: &Mesh, f: usize) -> bool {
    !m.f[f].inside || m.f[f].marked
}

fn add_to_trail(m: &mut Mesh, f: usize, trail: &mut usize) {
    m.f[f].trail = *trail;
    *trail = f;
    m.f[f].marked = true;
}

fn free_trail(m: &mut Mesh, mut t: usize) {
    while t != NIL {
        m.f[t].marked = false;
        t = m.f[t].trail;
    }
}

fn maximum_fan(m: &mut Mesh, e_orig: usize) -> (i64, usize, Render) {
    let mut size = 0;
    let mut trail = NIL;
    let mut e = e_orig;
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        add_to_trail(m, f, &mut trail);
        size += 1;
        e = m.onext(e);
    }
    e = e_orig;
    while !marked(m, m.rface(e)) {
        let f = m.rface(e);
        add_to_trail(m, f, &mut trail);
        size += 1;
        e = m.oprev(e);
    }
    free_trail(m, trail);
    (size, e, Render::Fan)
}

fn maximum_strip(m: &mut Mesh, e_orig: usize) -> (i64, usize, Render) {
    let mut head_size = 0i64;
    let mut tail_size = 0i64;
    let mut trail = NIL;
    let mut e = e_orig;
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        add_to_trail(m, f, &mut trail);
        tail_size += 1;
        e = m.dprev(e);
        if marked(m, m.lface(e)) {
            break;
        }
        let f = m.lface(e);
        add_to_trail(m, f, &mut trail);
        tail_size += 1;
        e = m.onext(e);
    }
    let e_tail = e;
    e = e_orig;
    while !marked(m, m.rface(e)) {
        let f = m.rface(e);
        add_to_trail(m, f, &mut trail);
        head_size += 1;
        e = m.oprev(e);
        if marked(m, m.rface(e)) {
            break;
        }
        let f = m.rface(e);
        add_to_trail(m, f, &mut trail);
        head_size += 1;
        e = m.dnext(e);
    }
    let e_head = e;
    let mut size = tail_size + head_size;
    let start = if tail_size & 1 == 0 {
        sym(e_tail)
    } else if head_size & 1 == 0 {
        e_head
    } else {
        size -= 1;
        m.onext(e_head)
    };
    free_trail(m, trail);
    (size, start, Render::Strip)
}

fn render_mesh<V, P>(out: &mut Out<'_, V, P>, m: &mut Mesh, flag_boundary: bool) {
    let mut lonely = NIL;
    let mut f = m.f[0].next;
    while f != 0 {
        m.f[f].marked = false;
        f = m.f[f].next;
    }
    let mut f = m.f[0].next;
    while f != 0 {
        if m.f[f].inside && !m.f[f].marked {
            // RenderMaximumFaceGroup
            let e = m.f[f].an_edge;
            let mut max = (1i64, e, Render::Triangle);
            if !flag_boundary {
                let (ln, lp) = (m.lnext(e), m.lprev(e));
                for cand in [
                    maximum_fan(m, e),
                    maximum_fan(m, ln),
                    maximum_fan(m, lp),
                    maximum_strip(m, e),
                    maximum_strip(m, ln),
                    maximum_strip(m, lp),
                ] {
                    if cand.0 > max.0 {
                        max = cand;
                    }
                }
            }
            match max.2 {
                Render::Triangle => {
                    let lf = m.lface(max.1);
                    add_to_trail(m, lf, &mut lonely);
                }
                Render::Fan => render_fan(out, m, max.1),
                Render::Strip => render_strip(out, m, max.1),
            }
        }
        f = m.f[f].next;
    }
    if lonely != NIL {
        // RenderLonelyTriangles
        let mut edge_state: i32 = -1;
        out.begin(gl::TRIANGLES);
        let mut f = lonely;
        while f != NIL {
            let start = m.f[f].an_edge;
            let mut e = start;
            loop {
                if flag_boundary {
                    let new_state = i32::from(!m.f[m.rface(e)].inside);
                    if edge_state != new_state {
                        edge_state = new_state;
                        out.edge_flag(edge_state != 0);
                    }
                }
                out.vertex(m.v[m.org(e)].data);
                e = m.lnext(e);
                if e == start {
                    break;
                }
            }
            f = m.f[f].trail;
        }
        out.end();
    }
}

fn render_fan<V, P>(out: &mut Out<'_, V, P>, m: &mut Mesh, mut e: usize) {
    out.begin(gl::TRIANGLE_FAN);
    out.vertex(m.v[m.org(e)].data);
    out.vertex(m.v[m.dst(e)].data);
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.onext(e);
        out.vertex(m.v[m.dst(e)].data);
    }
    out.end();
}

fn render_strip<V, P>(out: &mut Out<'_, V, P>, m: &mut Mesh, mut e: usize) {
    out.begin(gl::TRIANGLE_STRIP);
    out.vertex(m.v[m.org(e)].data);
    out.vertex(m.v[m.dst(e)].data);
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.dprev(e);
        out.vertex(m.v[m.org(e)].data);
        if marked(m, m.lface(e)) {
            break;
        }
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.onext(e);
        out.vertex(m.v[m.dst(e)].data);
    }
    out.end();
}
