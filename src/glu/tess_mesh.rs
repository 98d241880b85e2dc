//! The half-edge mesh under the GLU tessellator (the Guibas–Stolfi quad-edge structure,
//! restricted to one surface), kept in arenas: vertex 0, face 0 and half-edges 0/1 are the list
//! heads, half-edge `e ^ 1` is `e`'s twin (`Sym`), and `NIL` stands for a missing link.
//!
//! Nothing is freed: a removed vertex, face or edge is unlinked from its list and forgotten
//! (a mesh lives for one polygon). The operations and the order in which they link new
//! elements into the lists are those libGLU's mesh has, so a walk over a list meets the
//! elements in libGLU's order (which decides the triangles it emits).

pub(super) const NIL: usize = usize::MAX;

#[derive(Clone, Debug)]
pub(super) struct Vert {
    pub next: usize,
    pub prev: usize,
    pub an_edge: usize,
    /// Index of the client's data (in the tessellator's data list).
    pub data: Option<usize>,
    pub coords: [f64; 3],
    pub s: f64,
    pub t: f64,
    pub pq_handle: i64,
}

#[derive(Clone, Debug)]
pub(super) struct Face {
    pub next: usize,
    pub prev: usize,
    pub an_edge: usize,
    pub trail: usize,
    pub marked: bool,
    pub inside: bool,
}

#[derive(Clone, Debug)]
pub(super) struct Edge {
    pub next: usize,
    pub onext: usize,
    pub lnext: usize,
    pub org: usize,
    pub lface: usize,
    pub region: usize,
    pub winding: i32,
}

#[derive(Debug)]
pub(super) struct Mesh {
    pub v: Vec<Vert>,
    pub f: Vec<Face>,
    pub e: Vec<Edge>,
}

const fn blank_edge(next: usize) -> Edge {
    Edge {
        next,
        onext: NIL,
        lnext: NIL,
        org: NIL,
        lface: NIL,
        region: NIL,
        winding: 0,
    }
}

#[inline]
pub(super) fn sym(e: usize) -> usize {
    e ^ 1
}

impl Mesh {
    pub fn new() -> Mesh {
        Mesh {
            v: vec![Vert {
                next: 0,
                prev: 0,
                an_edge: NIL,
                data: None,
                coords: [0.0; 3],
                s: 0.0,
                t: 0.0,
                pq_handle: 0,
            }],
            f: vec![Face {
                next: 0,
                prev: 0,
                an_edge: NIL,
                trail: NIL,
                marked: false,
                inside: false,
            }],
            e: vec![blank_edge(0), blank_edge(1)],
        }
    }

    // Navigation (libGLU's macros).
    #[inline]
    pub fn onext(&self, e: usize) -> usize {
        self.e[e].onext
    }
    #[inline]
    pub fn lnext(&self, e: usize) -> usize {
        self.e[e].lnext
    }
    #[inline]
    pub fn org(&self, e: usize) -> usize {
        self.e[e].org
    }
    #[inline]
    pub fn dst(&self, e: usize) -> usize {
        self.e[e ^ 1].org
    }
    #[inline]
    pub fn lface(&self, e: usize) -> usize {
        self.e[e].lface
    }
    #[inline]
    pub fn rface(&self, e: usize) -> usize {
        self.e[e ^ 1].lface
    }
    #[inline]
    pub fn oprev(&self, e: usize) -> usize {
        self.e[e ^ 1].lnext
    }
    #[inline]
    pub fn lprev(&self, e: usize) -> usize {
        self.e[e].onext ^ 1
    }
    #[inline]
    pub fn dprev(&self, e: usize) -> usize {
        self.e[e].lnext ^ 1
    }
    #[inline]
    pub fn rprev(&self, e: usize) -> usize {
        self.e[e ^ 1].onext
    }
    #[inline]
    pub fn dnext(&self, e: usize) -> usize {
        self.rprev(e) ^ 1
    }

    /// A new edge pair forming its own loop, linked into the edge list before `e_next`.
    fn make_edge(&mut self, e_next: usize) -> usize {
        let e_next = e_next & !1;
        let e = self.e.len();
        let e_sym = e + 1;
        self.e.push(blank_edge(NIL));
        self.e.push(blank_edge(NIL));
        let e_prev = self.e[e_next ^ 1].next;
        self.e[e_sym].next = e_prev;
        self.e[e_prev ^ 1].next = e;
        self.e[e].next = e_next;
        self.e[e_next ^ 1].next = e_sym;
        self.e[e].onext = e;
        self.e[e].lnext = e_sym;
        self.e[e_sym].onext = e_sym;
        self.e[e_sym].lnext = e;
        e
    }

    fn splice_raw(&mut self, a: usize, b: usize) {
        let a_onext = self.e[a].onext;
        let b_onext = self.e[b].onext;
        self.e[a_onext ^ 1].lnext = b;
        self.e[b_onext ^ 1].lnext = a;
        self.e[a].onext = b_onext;
        self.e[b].onext = a_onext;
    }

    fn make_vertex(&mut self, e_orig: usize, v_next: usize) {
        let v_new = self.v.len();
        let v_prev = self.v[v_next].prev;
        self.v.push(Vert {
            next: v_next,
            prev: v_prev,
            an_edge: e_orig,
            data: None,
            coords: [0.0; 3],
            s: 0.0,
            t: 0.0,
            pq_handle: 0,
        });
        self.v[v_prev].next = v_new;
        self.v[v_next].prev = v_new;
        let mut e = e_orig;
        loop {
            self.e[e].org = v_new;
            e = self.e[e].onext;
            if e == e_orig {
                break;
            }
        }
    }

    fn make_face(&mut self, e_orig: usize, f_next: usize) {
        let f_new = self.f.len();
        let f_prev = self.f[f_next].prev;
        let inside = self.f[f_next].inside;
        self.f.push(Face {
            next: f_next,
            prev: f_prev,
            an_edge: e_orig,
            trail: NIL,
            marked: false,
            inside,
        });
        self.f[f_prev].next = f_new;
        self.f[f_next].prev = f_new;
        let mut e = e_orig;
        loop {
            self.e[e].lface = f_new;
            e = self.e[e].lnext;
            if e == e_orig {
                break;
            }
        }
    }

    fn kill_edge(&mut self, e_del: usize) {
        let e_del = e_del & !1;
        let e_next = self.e[e_del].next;
        let e_prev = self.e[e_del ^ 1].next;
        self.e[e_next ^ 1].next = e_prev;
        self.e[e_prev ^ 1].next = e_next;
    }

    fn kill_vertex(&mut self, v_del: usize, new_org: usize) {
        let e_start = self.v[v_del].an_edge;
        let mut e = e_start;
        loop {
            self.e[e].org = new_org;
            e = self.e[e].onext;
            if e == e_start {
                break;
            }
        }
        let (p, n) = (self.v[v_del].prev, self.v[v_del].next);
        self.v[n].prev = p;
        self.v[p].next = n;
    }

    fn kill_face(&mut self, f_del: usize, new_lface: usize) {
        let e_start = self.f[f_del].an_edge;
        let mut e = e_start;
        loop {
            self.e[e].lface = new_lface;
            e = self.e[e].lnext;
            if e == e_start {
                break;
            }
        }
        let (p, n) = (self.f[f_del].prev, self.f[f_del].next);
        self.f[n].prev = p;
        self.f[p].next = n;
    }

    /// One edge, two vertices and a loop (`__gl_meshMakeEdge`).
    pub fn make_edge_full(&mut self) -> usize {
        let e = self.make_edge(0);
        self.make_vertex(e, 0);
        self.make_vertex(e ^ 1, 0);
        self.make_face(e, 0);
        e
    }

    /// `__gl_meshSplice`: exchanges `e_org.onext` and `e_dst.onext`, merging or splitting
    /// vertices and loops.
    pub fn splice(&mut self, e_org: usize, e_dst: usize) {
        if e_org == e_dst {
            return;
        }
        let mut joining_vertices = false;
        let mut joining_loops = false;
        if self.org(e_dst) != self.org(e_org) {
            joining_vertices = true;
            let (d, o) = (self.org(e_dst), self.org(e_org));
            self.kill_vertex(d, o);
        }
        if self.lface(e_dst) != self.lface(e_org) {
            joining_loops = true;
            let (d, o) = (self.lface(e_dst), self.lface(e_org));
            self.kill_face(d, o);
        }
        self.splice_raw(e_dst, e_org);
        if !joining_vertices {
            let o = self.org(e_org);
            self.make_vertex(e_dst, o);
            self.v[o].an_edge = e_org;
        }
        if !joining_loops {
            let f = self.lface(e_org);
            self.make_face(e_dst, f);
            self.f[f].an_edge = e_org;
        }
    }

    /// `__gl_meshDelete`: removes an edge, joining or splitting loops; isolated vertices go.
    pub fn delete(&mut self, e_del: usize) {
        let e_del_sym = e_del ^ 1;
        let mut joining_loops = false;
        if self.lface(e_del) != self.rface(e_del) {
            joining_loops = true;
            let (l, r) = (self.lface(e_del), self.rface(e_del));
            self.kill_face(l, r);
        }
        if self.onext(e_del) == e_del {
            let o = self.org(e_del);
            self.kill_vertex(o, NIL);
        } else {
            let rf = self.rface(e_del);
            self.f[rf].an_edge = self.oprev(e_del);
            let o = self.org(e_del);
            self.v[o].an_edge = self.onext(e_del);
            let op = self.oprev(e_del);
            self.splice_raw(e_del, op);
            if !joining_loops {
                let lf = self.lface(e_del);
                self.make_face(e_del, lf);
            }
        }
        if self.onext(e_del_sym) == e_del_sym {
            let o = self.org(e_del_sym);
            self.kill_vertex(o, NIL);
            let lf = self.lface(e_del_sym);
            self.kill_face(lf, NIL);
        } else {
            let lf = self.lface(e_del);
            self.f[lf].an_edge = self.oprev(e_del_sym);
            let o = self.org(e_del_sym);
            self.v[o].an_edge = self.onext(e_del_sym);
            let op = self.oprev(e_del_sym);
            self.splice_raw(e_del_sym, op);
        }
        self.kill_edge(e_del);
    }

    /// `__gl_meshAddEdgeVertex`: a new edge `eNew == eOrg.lnext` to a new vertex.
    pub fn add_edge_vertex(&mut self, e_org: usize) -> usize {
        let e_new = self.make_edge(e_org);
        let e_new_sym = e_new ^ 1;
        let ln = self.lnext(e_org);
        self.splice_raw(e_new, ln);
        let d = self.dst(e_org);
        self.e[e_new].org = d;
        self.make_vertex(e_new_sym, d);
        let lf = self.lface(e_org);
        self.e[e_new].lface = lf;
        self.e[e_new_sym].lface = lf;
        e_new
    }

    /// `__gl_meshSplitEdge`: splits `e_org` in two at a new vertex; returns the second half.
    pub fn split_edge(&mut self, e_org: usize) -> usize {
        let temp = self.add_edge_vertex(e_org);
        let e_new = temp ^ 1;
        let es = e_org ^ 1;
        let op = self.oprev(es);
        self.splice_raw(es, op);
        self.splice_raw(es, e_new);
        let no = self.org(e_new);
        self.e[es].org = no;
        let nd = self.dst(e_new);
        self.v[nd].an_edge = e_new ^ 1;
        let rf = self.rface(e_org);
        self.e[e_new ^ 1].lface = rf;
        self.e[e_new].winding = self.e[e_org].winding;
        self.e[e_new ^ 1].winding = self.e[es].winding;
        e_new
    }

    /// `__gl_meshConnect`: a new edge from `e_org.dst` to `e_dst.org`.
    pub fn connect(&mut self, e_org: usize, e_dst: usize) -> usize {
        let e_new = self.make_edge(e_org);
        let e_new_sym = e_new ^ 1;
        let mut joining_loops = false;
        if self.lface(e_dst) != self.lface(e_org) {
            joining_loops = true;
            let (d, o) = (self.lface(e_dst), self.lface(e_org));
            self.kill_face(d, o);
        }
        let ln = self.lnext(e_org);
        self.splice_raw(e_new, ln);
        self.splice_raw(e_new_sym, e_dst);
        self.e[e_new].org = self.dst(e_org);
        self.e[e_new_sym].org = self.org(e_dst);
        let lf = self.lface(e_org);
        self.e[e_new].lface = lf;
        self.e[e_new_sym].lface = lf;
        self.f[lf].an_edge = e_new_sym;
        if !joining_loops {
            self.make_face(e_new, lf);
        }
        e_new
    }
}
