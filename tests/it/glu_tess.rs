//! The GLU tessellator (`fixedgl::glu::Tess`) against the real libGLU (Mesa's libGLU 9.0,
//! loaded with `dlopen`): for concave polygons, polygons with holes, self-intersecting and
//! overlapping contours, coincident vertices, contours over libGLU's 100-vertex cache, tilted
//! planes with given and computed normals, under every winding rule, with and without
//! BOUNDARY_ONLY, EDGE_FLAG and COMBINE, and for a few hundred random polygons, both emit the
//! same callback stream: the same BEGIN types, vertices in the same order, END, edge flags,
//! COMBINE calls (coordinates, source data and weights bit for bit) and errors.
//!
//! Without libGLU.so.1 the comparisons print `SKIPPED` and return (the API tests run anyway).

use fixedgl::glu::{self, Tess, TessCallback};
use std::cell::RefCell;
use std::rc::Rc;

/// One callback event.
#[derive(Clone, Debug, PartialEq)]
enum Ev {
    Begin(u32),
    Vertex(i64),
    End,
    Flag(bool),
    /// new id, coordinate bits, source ids (-1 for none), weight bits
    Combine(i64, [u64; 3], [i64; 4], [u32; 4]),
    Error(u32),
}

/// One polygon and the tessellator settings to run it with.
#[derive(Clone, Debug)]
struct Case {
    rule: u32,
    boundary_only: bool,
    normal: [f64; 3],
    edge_flag: bool,
    combine: bool,
    contours: Vec<Vec<[f64; 3]>>,
}

const RULES: [u32; 5] = [
    glu::GLU_TESS_WINDING_ODD,
    glu::GLU_TESS_WINDING_NONZERO,
    glu::GLU_TESS_WINDING_POSITIVE,
    glu::GLU_TESS_WINDING_NEGATIVE,
    glu::GLU_TESS_WINDING_ABS_GEQ_TWO,
];

/// The vertex id of contour vertex `k` overall: 1, 2, ...; combined vertices count from 1000.
const FIRST_COMBINED: i64 = 1000;

/// fixedgl's stream, through the `_DATA` callbacks (polygon data = the event list).
fn run_fixedgl(c: &Case) -> Vec<Ev> {
    let mut t: Tess<i64, Vec<Ev>> = glu::new_tess();
    t.callback(TessCallback::BeginData(Box::new(|ty, d| {
        d.unwrap().push(Ev::Begin(ty))
    })));
    t.callback(TessCallback::VertexData(Box::new(|v, d| {
        d.unwrap().push(Ev::Vertex(*v))
    })));
    t.callback(TessCallback::EndData(Box::new(|d| {
        d.unwrap().push(Ev::End)
    })));
    t.callback(TessCallback::ErrorData(Box::new(|e, d| {
        if let Some(d) = d {
            d.push(Ev::Error(e))
        }
    })));
    if c.edge_flag {
        t.callback(TessCallback::EdgeFlagData(Box::new(|f, d| {
            d.unwrap().push(Ev::Flag(f))
        })));
    }
    if c.combine {
        let next = Rc::new(RefCell::new(FIRST_COMBINED));
        t.callback(TessCallback::CombineData(Box::new(
            move |coords, data, w, d| {
                let id = *next.borrow();
                *next.borrow_mut() += 1;
                d.unwrap().push(Ev::Combine(
                    id,
                    coords.map(f64::to_bits),
                    data.map(|x| x.copied().unwrap_or(-1)),
                    w.map(f32::to_bits),
                ));
                Some(id)
            },
        )));
    }
    t.property(glu::GLU_TESS_WINDING_RULE, f64::from(c.rule));
    t.property(
        glu::GLU_TESS_BOUNDARY_ONLY,
        f64::from(u8::from(c.boundary_only)),
    );
    t.normal(c.normal[0], c.normal[1], c.normal[2]);
    t.begin_polygon(Vec::new());
    let mut id = 1;
    for contour in &c.contours {
        t.begin_contour();
        for v in contour {
            t.vertex(*v, id);
            id += 1;
        }
        t.end_contour();
    }
    t.end_polygon().unwrap()
}

mod libglu {
    use super::*;
    use std::ffi::{c_char, c_int, c_void};

    extern "C" {
        fn dlopen(file: *const c_char, mode: c_int) -> *mut c_void;
        fn dlsym(handle: *mut c_void, name: *const c_char) -> *mut c_void;
    }
    const RTLD_NOW: c_int = 2;
    type T = *mut c_void;
    type Cb = *const c_void;
    type Op = unsafe extern "C" fn(T);
    type VertexFn = unsafe extern "C" fn(T, *const f64, *mut c_void);

    /// The libGLU entry points the tests call.
    pub struct LibGlu {
        new_tess: unsafe extern "C" fn() -> T,
        delete_tess: unsafe extern "C" fn(T),
        callback: unsafe extern "C" fn(T, u32, Cb),
        property: unsafe extern "C" fn(T, u32, f64),
        normal: unsafe extern "C" fn(T, f64, f64, f64),
        begin_polygon: unsafe extern "C" fn(T, *mut c_void),
        begin_contour: unsafe extern "C" fn(T),
        vertex: unsafe extern "C" fn(T, *const f64, *mut c_void),
        end_contour: unsafe extern "C" fn(T),
        end_polygon: unsafe extern "C" fn(T),
    }

    pub fn load() -> Option<LibGlu> {
        // SAFETY: dlopen/dlsym with NUL-terminated names; each symbol is cast to the type of
        // the libGLU function of that name (GL/glu.h; GLenum is u32, GLdouble f64).
        unsafe {
            let h = dlopen(c"libGLU.so.1".as_ptr(), RTLD_NOW);
            if h.is_null() {
                eprintln!("SKIPPED: libGLU.so.1 not found");
                return None;
            }
            macro_rules! sym {
                ($name:literal, $ty:ty) => {{
                    let p = dlsym(h, $name.as_ptr());
                    if p.is_null() {
                        eprintln!("SKIPPED: libGLU lacks {:?}", $name);
                        return None;
                    }
                    std::mem::transmute::<*mut c_void, $ty>(p)
                }};
            }
            Some(LibGlu {
                new_tess: sym!(c"gluNewTess", unsafe extern "C" fn() -> T),
                delete_tess: sym!(c"gluDeleteTess", Op),
                callback: sym!(c"gluTessCallback", unsafe extern "C" fn(T, u32, Cb)),
                property: sym!(c"gluTessProperty", unsafe extern "C" fn(T, u32, f64)),
                normal: sym!(c"gluTessNormal", unsafe extern "C" fn(T, f64, f64, f64)),
                begin_polygon: sym!(c"gluTessBeginPolygon", unsafe extern "C" fn(T, *mut c_void)),
                begin_contour: sym!(c"gluTessBeginContour", Op),
                vertex: sym!(c"gluTessVertex", VertexFn),
                end_contour: sym!(c"gluTessEndContour", Op),
                end_polygon: sym!(c"gluTessEndPolygon", Op),
            })
        }
    }

    thread_local! {
        static LOG: RefCell<Vec<Ev>> = const { RefCell::new(Vec::new()) };
        static NEXT: RefCell<i64> = const { RefCell::new(FIRST_COMBINED) };
    }
    fn push(e: Ev) {
        LOG.with(|l| l.borrow_mut().push(e));
    }
    /// Vertex data are the ids themselves, as pointers (ids are never 0).
    fn id(p: *mut c_void) -> i64 {
        if p.is_null() {
            -1
        } else {
            p as usize as i64
        }
    }
    unsafe extern "C" fn begin(ty: u32) {
        push(Ev::Begin(ty));
    }
    unsafe extern "C" fn vertex(d: *mut c_void) {
        push(Ev::Vertex(id(d)));
    }
    unsafe extern "C" fn end() {
        push(Ev::End);
    }
    unsafe extern "C" fn flag(f: u8) {
        push(Ev::Flag(f != 0));
    }
    unsafe extern "C" fn error(e: u32) {
        push(Ev::Error(e));
    }
    unsafe extern "C" fn combine(
        coords: *const f64,
        data: *const *mut c_void,
        w: *const f32,
        out: *mut *mut c_void,
    ) {
        // SAFETY: libGLU passes 3 coordinates, 4 data pointers, 4 weights and an out pointer.
        unsafe {
            let c = std::slice::from_raw_parts(coords, 3);
            let d = std::slice::from_raw_parts(data, 4);
            let w = std::slice::from_raw_parts(w, 4);
            let new = NEXT.with(|n| {
                let v = *n.borrow();
                *n.borrow_mut() += 1;
                v
            });
            push(Ev::Combine(
                new,
                [c[0].to_bits(), c[1].to_bits(), c[2].to_bits()],
                [id(d[0]), id(d[1]), id(d[2]), id(d[3])],
                [
                    w[0].to_bits(),
                    w[1].to_bits(),
                    w[2].to_bits(),
                    w[3].to_bits(),
                ],
            ));
            *out = new as usize as *mut c_void;
        }
    }

    impl LibGlu {
        pub fn run(&self, c: &Case) -> Vec<Ev> {
            LOG.with(|l| l.borrow_mut().clear());
            NEXT.with(|n| *n.borrow_mut() = FIRST_COMBINED);
            // SAFETY: the tessellator is created and deleted here; the callbacks have the
            // signatures GLU documents for their `which`; vertex coordinates outlive the
            // polygon (libGLU copies them), vertex data are opaque ids.
            unsafe {
                let t = (self.new_tess)();
                assert!(!t.is_null());
                let cb = |which: u32, f: Cb| (self.callback)(t, which, f);
                cb(glu::GLU_TESS_BEGIN, begin as Cb);
                cb(glu::GLU_TESS_VERTEX, vertex as Cb);
                cb(glu::GLU_TESS_END, end as Cb);
                cb(glu::GLU_TESS_ERROR, error as Cb);
                if c.edge_flag {
                    cb(glu::GLU_TESS_EDGE_FLAG, flag as Cb);
                }
                if c.combine {
                    cb(glu::GLU_TESS_COMBINE, combine as Cb);
                }
                (self.property)(t, glu::GLU_TESS_WINDING_RULE, f64::from(c.rule));
                (self.property)(
                    t,
                    glu::GLU_TESS_BOUNDARY_ONLY,
                    f64::from(u8::from(c.boundary_only)),
                );
                (self.normal)(t, c.normal[0], c.normal[1], c.normal[2]);
                (self.begin_polygon)(t, std::ptr::null_mut());
                let mut id = 1usize;
                for contour in &c.contours {
                    (self.begin_contour)(t);
                    for v in contour {
                        (self.vertex)(t, v.as_ptr(), id as *mut c_void);
                        id += 1;
                    }
                    (self.end_contour)(t);
                }
                (self.end_polygon)(t);
                (self.delete_tess)(t);
            }
            LOG.with(|l| l.borrow().clone())
        }
    }
}

fn flat(points: &[(f64, f64)]) -> Vec<[f64; 3]> {
    points.iter().map(|&(x, y)| [x, y, 0.0]).collect()
}

fn star(cx: f64, cy: f64, r_out: f64, r_in: f64, points: usize, phase: f64) -> Vec<[f64; 3]> {
    (0..2 * points)
        .map(|k| {
            let r = if k % 2 == 0 { r_out } else { r_in };
            let a = phase + k as f64 * std::f64::consts::PI / points as f64;
            [cx + r * a.cos(), cy + r * a.sin(), 0.0]
        })
        .collect()
}

fn case(contours: Vec<Vec<[f64; 3]>>) -> Case {
    Case {
        rule: glu::GLU_TESS_WINDING_ODD,
        boundary_only: false,
        normal: [0.0; 3],
        edge_flag: false,
        combine: true,
        contours,
    }
}

/// Fixed shapes: each runs under every rule, with and without BOUNDARY_ONLY and EDGE_FLAG.
fn shapes() -> Vec<Vec<Vec<[f64; 3]>>> {
    let square = flat(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]);
    let hole_cw = flat(&[(1.0, 1.0), (1.0, 3.0), (3.0, 3.0), (3.0, 1.0)]);
    let hole_ccw = flat(&[(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)]);
    let pentagram: Vec<[f64; 3]> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + k as f64 * 4.0 * std::f64::consts::PI / 5.0;
            [a.cos(), a.sin(), 0.0]
        })
        .collect();
    let circle: Vec<[f64; 3]> = (0..150)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 150.0;
            [2.0 * a.cos(), 2.0 * a.sin(), 0.0]
        })
        .collect();
    let tilt = |c: &[[f64; 3]]| -> Vec<[f64; 3]> {
        c.iter()
            .map(|p| [p[0], p[1] * 0.6, p[1] * 0.8 + p[0] * 0.1])
            .collect()
    };
    let mut star_hole = star(0.0, 0.0, 1.0, 0.45, 5, std::f64::consts::FRAC_PI_2);
    star_hole.reverse();
    vec![
        vec![flat(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)])],
        vec![flat(&[(0.0, 0.0), (0.0, 1.0), (1.0, 0.0)])],
        vec![flat(&[
            (0.0, 0.0),
            (3.0, 0.0),
            (3.0, 3.0),
            (2.0, 1.0),
            (1.0, 2.5),
            (0.0, 1.0),
        ])],
        vec![pentagram.clone()],
        vec![square.clone(), hole_cw.clone()],
        vec![square.clone(), hole_ccw],
        vec![
            square.clone(),
            flat(&[(2.0, 2.0), (6.0, 2.0), (6.0, 6.0), (2.0, 6.0)]),
        ],
        vec![
            star(0.0, 0.0, 1.0, 0.45, 5, std::f64::consts::FRAC_PI_2),
            flat(&[(-0.2, -0.2), (-0.2, 0.2), (0.2, 0.2), (0.2, -0.2)]),
        ],
        vec![
            star(0.0, 0.0, 1.0, 0.45, 5, std::f64::consts::FRAC_PI_2),
            star_hole
                .iter()
                .map(|p| [p[0] * 0.4, p[1] * 0.4, 0.0])
                .collect(),
        ],
        vec![circle.clone()],
        vec![circle, hole_cw.clone()],
        vec![tilt(&square), tilt(&hole_cw)],
        vec![tilt(&pentagram)],
        // Coincident vertices and edges: a bow tie through a shared point, a doubled edge.
        vec![flat(&[
            (0.0, 0.0),
            (2.0, 2.0),
            (2.0, 0.0),
            (0.0, 2.0),
            (0.0, 0.0),
            (1.0, 1.0),
        ])],
        vec![
            square.clone(),
            flat(&[(0.0, 0.0), (4.0, 0.0), (2.0, -2.0)]),
            flat(&[(4.0, 4.0), (0.0, 4.0), (2.0, 2.0)]),
        ],
        // Degenerate: collinear, a single point, two points.
        vec![flat(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)])],
        vec![flat(&[(1.0, 1.0)])],
        vec![flat(&[(1.0, 1.0), (2.0, 2.0)])],
        vec![],
    ]
}

/// A deterministic generator (64-bit LCG) for the random polygons.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 33
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

fn random_cases(n: usize) -> Vec<Case> {
    let mut g = Lcg(0x5eed);
    (0..n)
        .map(|i| {
            let contours = 1 + g.below(3) as usize;
            let grid = i % 2 == 0; // small integer grid: many coincidences
            let polys = (0..contours)
                .map(|_| {
                    let k = 3 + g.below(9) as usize;
                    (0..k)
                        .map(|_| {
                            if grid {
                                [g.below(6) as f64, g.below(6) as f64, 0.0]
                            } else {
                                [
                                    g.below(1 << 20) as f64 / 1024.0,
                                    g.below(1 << 20) as f64 / 1024.0,
                                    0.0,
                                ]
                            }
                        })
                        .collect()
                })
                .collect();
            Case {
                rule: RULES[i % 5],
                boundary_only: i % 7 == 3,
                normal: if i % 3 == 0 {
                    [0.0, 0.0, 1.0]
                } else {
                    [0.0; 3]
                },
                edge_flag: i % 11 == 5,
                combine: true,
                contours: polys,
            }
        })
        .collect()
}

fn all_cases() -> Vec<Case> {
    let mut out = Vec::new();
    for s in shapes() {
        for rule in RULES {
            for (boundary_only, edge_flag) in [(false, false), (true, false), (false, true)] {
                let mut c = case(s.clone());
                c.rule = rule;
                c.boundary_only = boundary_only;
                c.edge_flag = edge_flag;
                out.push(c);
            }
        }
    }
    // A given normal (either way up), and no combine callback where one is needed.
    let square_hole = shapes()[4].clone();
    for normal in [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [0.3, 0.2, 2.0]] {
        let mut c = case(square_hole.clone());
        c.normal = normal;
        out.push(c);
        let mut c = case(shapes()[3].clone());
        c.normal = normal;
        out.push(c);
    }
    let mut c = case(shapes()[3].clone());
    c.combine = false;
    out.push(c);
    out.extend(random_cases(400));
    out
}

#[test]
fn tess_matches_libglu() {
    let Some(lib) = libglu::load() else {
        return;
    };
    let cases = all_cases();
    let mut failures = 0;
    let (mut events, mut combines, mut strips) = (0, 0, 0);
    for (i, c) in cases.iter().enumerate() {
        let want = lib.run(c);
        let got = run_fixedgl(c);
        events += want.len();
        combines += want.iter().filter(|e| matches!(e, Ev::Combine(..))).count();
        strips += want
            .iter()
            .filter(|e| **e == Ev::Begin(fixedgl::gl::TRIANGLE_STRIP))
            .count();
        if want != got {
            failures += 1;
            if failures <= 3 {
                eprintln!("case {i}: {c:?}\nlibGLU:  {want:?}\nfixedgl: {got:?}");
            }
        }
    }
    eprintln!(
        "{} cases, {events} events ({combines} COMBINE, {strips} strips) compared",
        cases.len()
    );
    assert_eq!(failures, 0, "{failures} of {} cases differ", cases.len());
    assert!(combines > 100 && strips > 10 && events > 10_000);
}

/// The plain (non-`_DATA`) callbacks, GLU 1.1's begin/next/end, and the state errors.
#[test]
fn tess_plain_callbacks_and_errors() {
    let log = Rc::new(RefCell::new(Vec::new()));
    let mut t: Tess<u32> = Tess::new();
    let l = log.clone();
    t.callback(TessCallback::Begin(Box::new(move |ty| {
        l.borrow_mut().push(format!("B{ty}"))
    })));
    let l = log.clone();
    t.callback(TessCallback::Vertex(Box::new(move |v| {
        l.borrow_mut().push(format!("V{v}"))
    })));
    let l = log.clone();
    t.callback(TessCallback::End(Box::new(move || {
        l.borrow_mut().push("E".into())
    })));
    let l = log.clone();
    t.callback(TessCallback::Error(Box::new(move |e| {
        l.borrow_mut().push(format!("R{e}"))
    })));
    t.begin_polygon_old();
    for (i, p) in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        .iter()
        .enumerate()
    {
        t.vertex(*p, i as u32);
    }
    t.end_polygon_old();
    assert_eq!(*log.borrow(), ["B4", "V0", "V1", "V2", "E"]);
    log.borrow_mut().clear();

    // A vertex with no polygon: MISSING_BEGIN_POLYGON, then MISSING_BEGIN_CONTOUR.
    t.vertex([0.0; 3], 9);
    t.end_polygon();
    assert_eq!(*log.borrow(), ["R100151", "R100152", "R100154"]);
    log.borrow_mut().clear();

    // Properties: range checks and the errors.
    t.property(glu::GLU_TESS_TOLERANCE, 2.0);
    t.property(glu::GLU_TESS_WINDING_RULE, 100_130.5);
    t.property(12345, 0.0);
    assert_eq!(t.get_property(12345), 0.0);
    assert_eq!(*log.borrow(), ["R100901", "R100901", "R100900", "R100900"]);
    t.property(glu::GLU_TESS_TOLERANCE, 0.25);
    assert_eq!(t.get_property(glu::GLU_TESS_TOLERANCE), 0.25);
    t.property(glu::GLU_TESS_WINDING_RULE, 100_131.0);
    assert_eq!(t.get_property(glu::GLU_TESS_WINDING_RULE), 100_131.0);
    assert_eq!(t.get_property(glu::GLU_TESS_BOUNDARY_ONLY), 0.0);
    log.borrow_mut().clear();

    // Too-large and NaN coordinates are clamped with COORD_TOO_LARGE.
    t.begin_polygon(());
    t.begin_contour();
    t.vertex([1e200, 0.0, 0.0], 1);
    t.vertex([0.0, f64::NAN, 0.0], 2);
    t.vertex([0.0, 1.0, 0.0], 3);
    t.end_contour();
    t.end_polygon();
    assert_eq!(&log.borrow()[..2], ["R100155", "R100155"]);
    t.clear_callback(777);
    glu::delete_tess(t);
}

/// GLU_TESS_ERROR text.
#[test]
fn tess_error_strings() {
    assert_eq!(
        glu::error_string(glu::GLU_TESS_NEED_COMBINE_CALLBACK),
        Some("need combine callback")
    );
}

/// Hostile input never panics or hangs: huge, tiny, infinite and NaN coordinates, many
/// coincident points, thousands of vertices, callbacks missing.
#[test]
fn tess_hostile_input() {
    let mut g = Lcg(7);
    let specials = [
        0.0,
        -0.0,
        1e150,
        -1e150,
        1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        1e-300,
        f64::MIN_POSITIVE,
        1e149,
        -3e149,
    ];
    for i in 0..300 {
        let contours: Vec<Vec<[f64; 3]>> = (0..1 + g.below(4))
            .map(|_| {
                (0..g.below(12))
                    .map(|_| {
                        let mut p = [0.0; 3];
                        for c in p.iter_mut().take(if i % 4 == 0 { 3 } else { 2 }) {
                            *c = if g.below(3) == 0 {
                                specials[g.below(specials.len() as u64) as usize]
                            } else {
                                g.below(5) as f64
                            };
                        }
                        p
                    })
                    .collect()
            })
            .collect();
        let mut c = case(contours);
        c.rule = RULES[i % 5];
        c.boundary_only = i % 6 == 1;
        c.edge_flag = i % 5 == 2;
        c.combine = i % 9 != 0;
        let _ = run_fixedgl(&c);
    }
    // A long contour: 20000 vertices of a zigzag.
    let big: Vec<[f64; 3]> = (0..20_000)
        .map(|k| {
            [
                k as f64,
                if k % 2 == 0 {
                    0.0
                } else {
                    1.0 + (k % 7) as f64
                },
                0.0,
            ]
        })
        .chain([[20_000.0, -5.0, 0.0], [0.0, -5.0, 0.0]])
        .collect();
    let out = run_fixedgl(&case(vec![big]));
    assert!(out.len() > 20_000);
}
