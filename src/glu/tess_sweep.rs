//! The plane sweep of the GLU tessellator: geometry predicates on the projected (s, t)
//! coordinates, the vertex priority queue, the dictionary of active edges, and the sweep that
//! turns the contours into a planar subdivision whose faces are monotone and marked inside or
//! outside by the winding rule (GLU 1.3 §5; the algorithm of SGI's libGLU `sweep.c`, with its
//! decisions — event order, tie breaks, which edge is split or merged first — kept, so the
//! same regions come out).

use super::tess_mesh::{sym, Mesh, NIL};

/// GLU_TESS_MAX_COORD.
pub(super) const MAX_COORD: f64 = 1.0e150;
const SENTINEL_COORD: f64 = 4.0 * MAX_COORD;

#[derive(Clone, Copy, Debug)]
pub(super) struct P2 {
    pub s: f64,
    pub t: f64,
}

#[inline]
pub(super) fn vert_eq(u: P2, v: P2) -> bool {
    u.s == v.s && u.t == v.t
}
#[inline]
pub(super) fn vert_leq(u: P2, v: P2) -> bool {
    u.s < v.s || (u.s == v.s && u.t <= v.t)
}
#[inline]
fn trans_leq(u: P2, v: P2) -> bool {
    u.t < v.t || (u.t == v.t && u.s <= v.s)
}

fn edge_eval(u: P2, v: P2, w: P2) -> f64 {
    let gap_l = v.s - u.s;
    let gap_r = w.s - v.s;
    if gap_l + gap_r > 0.0 {
        if gap_l < gap_r {
            (v.t - u.t) + (u.t - w.t) * (gap_l / (gap_l + gap_r))
        } else {
            (v.t - w.t) + (w.t - u.t) * (gap_r / (gap_l + gap_r))
        }
    } else {
        0.0
    }
}

pub(super) fn edge_sign(u: P2, v: P2, w: P2) -> f64 {
    let gap_l = v.s - u.s;
    let gap_r = w.s - v.s;
    if gap_l + gap_r > 0.0 {
        (v.t - w.t) * gap_l + (v.t - u.t) * gap_r
    } else {
        0.0
    }
}

fn trans_eval(u: P2, v: P2, w: P2) -> f64 {
    let gap_l = v.t - u.t;
    let gap_r = w.t - v.t;
    if gap_l + gap_r > 0.0 {
        if gap_l < gap_r {
            (v.s - u.s) + (u.s - w.s) * (gap_l / (gap_l + gap_r))
        } else {
            (v.s - w.s) + (w.s - u.s) * (gap_r / (gap_l + gap_r))
        }
    } else {
        0.0
    }
}

fn trans_sign(u: P2, v: P2, w: P2) -> f64 {
    let gap_l = v.t - u.t;
    let gap_r = w.t - v.t;
    if gap_l + gap_r > 0.0 {
        (v.s - w.s) * gap_l + (v.s - u.s) * gap_r
    } else {
        0.0
    }
}

/// libGLU's `Interpolate(a, x, b, y)`: x and y weighted by the other's distance.
fn interpolate(a: f64, x: f64, b: f64, y: f64) -> f64 {
    let a = if a < 0.0 { 0.0 } else { a };
    let b = if b < 0.0 { 0.0 } else { b };
    if a <= b {
        if b == 0.0 {
            (x + y) / 2.0
        } else {
            x + (y - x) * (a / (a + b))
        }
    } else {
        y + (x - y) * (b / (a + b))
    }
}

/// The intersection of edges o1-d1 and o2-d2 (`__gl_edgeIntersect`): s and t each found by
/// interpolating along the axis, so the result stays inside both edges' bounding boxes.
fn edge_intersect(o1: P2, d1: P2, o2: P2, d2: P2) -> P2 {
    let (mut o1, mut d1, mut o2, mut d2) = (o1, d1, o2, d2);
    let mut v = P2 { s: 0.0, t: 0.0 };
    if !vert_leq(o1, d1) {
        std::mem::swap(&mut o1, &mut d1);
    }
    if !vert_leq(o2, d2) {
        std::mem::swap(&mut o2, &mut d2);
    }
    if !vert_leq(o1, o2) {
        std::mem::swap(&mut o1, &mut o2);
        std::mem::swap(&mut d1, &mut d2);
    }
    if !vert_leq(o2, d1) {
        v.s = (o2.s + d1.s) / 2.0;
    } else if vert_leq(d1, d2) {
        let mut z1 = edge_eval(o1, o2, d1);
        let mut z2 = edge_eval(o2, d1, d2);
        if z1 + z2 < 0.0 {
            z1 = -z1;
            z2 = -z2;
        }
        v.s = interpolate(z1, o2.s, z2, d1.s);
    } else {
        let mut z1 = edge_sign(o1, o2, d1);
        let mut z2 = -edge_sign(o1, d2, d1);
        if z1 + z2 < 0.0 {
            z1 = -z1;
            z2 = -z2;
        }
        v.s = interpolate(z1, o2.s, z2, d2.s);
    }
    if !trans_leq(o1, d1) {
        std::mem::swap(&mut o1, &mut d1);
    }
    if !trans_leq(o2, d2) {
        std::mem::swap(&mut o2, &mut d2);
    }
    if !trans_leq(o1, o2) {
        std::mem::swap(&mut o1, &mut o2);
        std::mem::swap(&mut d1, &mut d2);
    }
    if !trans_leq(o2, d1) {
        v.t = (o2.t + d1.t) / 2.0;
    } else if trans_leq(d1, d2) {
        let mut z1 = trans_eval(o1, o2, d1);
        let mut z2 = trans_eval(o2, d1, d2);
        if z1 + z2 < 0.0 {
            z1 = -z1;
            z2 = -z2;
        }
        v.t = interpolate(z1, o2.t, z2, d1.t);
    } else {
        let mut z1 = trans_sign(o1, o2, d1);
        let mut z2 = -trans_sign(o1, d2, d1);
        if z1 + z2 < 0.0 {
            z1 = -z1;
            z2 = -z2;
        }
        v.t = interpolate(z1, o2.t, z2, d2.t);
    }
    v
}

// Priority queue of vertices: the initial vertices sorted once (libGLU's quicksort, with its
// pseudo-random pivots, so equal keys come out in its order), later ones in a binary heap.

fn leq_v(m: &Mesh, a: usize, b: usize) -> bool {
    vert_leq(p2(m, a), p2(m, b))
}

#[inline]
pub(super) fn p2(m: &Mesh, v: usize) -> P2 {
    P2 {
        s: m.v[v].s,
        t: m.v[v].t,
    }
}

#[derive(Default)]
struct Heap {
    /// nodes[i] = the handle at heap position i (1-based).
    nodes: Vec<usize>,
    /// handles[h] = (key, node); a free handle's node links the free list.
    keys: Vec<usize>,
    node_of: Vec<usize>,
    size: usize,
    free_list: usize,
}

impl Heap {
    fn new() -> Heap {
        Heap {
            nodes: vec![0, 1],
            keys: vec![NIL, NIL],
            node_of: vec![0, 0],
            size: 0,
            free_list: 0,
        }
    }
    fn float_down(&mut self, m: &Mesh, mut curr: usize) {
        let h_curr = self.nodes[curr];
        loop {
            let mut child = curr << 1;
            if child < self.size
                && leq_v(
                    m,
                    self.keys[self.nodes[child + 1]],
                    self.keys[self.nodes[child]],
                )
            {
                child += 1;
            }
            if child > self.size || leq_v(m, self.keys[h_curr], self.keys[self.nodes[child]]) {
                self.nodes[curr] = h_curr;
                self.node_of[h_curr] = curr;
                break;
            }
            let h_child = self.nodes[child];
            self.nodes[curr] = h_child;
            self.node_of[h_child] = curr;
            curr = child;
        }
    }
    fn float_up(&mut self, m: &Mesh, mut curr: usize) {
        let h_curr = self.nodes[curr];
        loop {
            let parent = curr >> 1;
            let h_parent = self.nodes[parent];
            if parent == 0 || leq_v(m, self.keys[h_parent], self.keys[h_curr]) {
                self.nodes[curr] = h_curr;
                self.node_of[h_curr] = curr;
                break;
            }
            self.nodes[curr] = h_parent;
            self.node_of[h_parent] = curr;
            curr = parent;
        }
    }
    fn insert(&mut self, m: &Mesh, key: usize) -> usize {
        self.size += 1;
        let curr = self.size;
        if self.nodes.len() <= curr + 1 {
            self.nodes.resize(curr + 2, 0);
        }
        let h = if self.free_list == 0 {
            curr
        } else {
            let h = self.free_list;
            self.free_list = self.node_of[h];
            h
        };
        if self.keys.len() <= h {
            self.keys.resize(h + 1, NIL);
            self.node_of.resize(h + 1, 0);
        }
        self.nodes[curr] = h;
        self.node_of[h] = curr;
        self.keys[h] = key;
        self.float_up(m, curr);
        h
    }
    fn minimum(&self) -> usize {
        if self.size == 0 {
            NIL
        } else {
            self.keys[self.nodes[1]]
        }
    }
    fn extract_min(&mut self, m: &Mesh) -> usize {
        if self.size == 0 {
            return NIL;
        }
        let h_min = self.nodes[1];
        let min = self.keys[h_min];
        self.nodes[1] = self.nodes[self.size];
        self.node_of[self.nodes[1]] = 1;
        self.keys[h_min] = NIL;
        self.node_of[h_min] = self.free_list;
        self.free_list = h_min;
        self.size -= 1;
        if self.size > 0 {
            self.float_down(m, 1);
        }
        min
    }
    fn delete(&mut self, m: &Mesh, h_curr: usize) {
        let curr = self.node_of[h_curr];
        self.nodes[curr] = self.nodes[self.size];
        self.node_of[self.nodes[curr]] = curr;
        self.size -= 1;
        if curr <= self.size {
            if curr <= 1
                || leq_v(
                    m,
                    self.keys[self.nodes[curr >> 1]],
                    self.keys[self.nodes[curr]],
                )
            {
                self.float_down(m, curr);
            } else {
                self.float_up(m, curr);
            }
        }
        self.keys[h_curr] = NIL;
        self.node_of[h_curr] = self.free_list;
        self.free_list = h_curr;
    }
}

struct PriorityQ {
    heap: Heap,
    keys: Vec<usize>,
    order: Vec<usize>,
    size: usize,
    initialized: bool,
}

impl PriorityQ {
    fn new() -> PriorityQ {
        PriorityQ {
            heap: Heap::new(),
            keys: Vec::new(),
            order: Vec::new(),
            size: 0,
            initialized: false,
        }
    }

    fn init(&mut self, m: &Mesh) {
        let key = |pq: &PriorityQ, i: isize| pq.keys[pq.order[i as usize]];
        let leq = |a: usize, b: usize| leq_v(m, a, b);
        self.order = (0..self.size).collect();
        let mut stack: Vec<(isize, isize)> = vec![(0, self.size as isize - 1)];
        let mut seed: u64 = 2_016_473_283;
        while let Some((mut p, mut r)) = stack.pop() {
            while r > p + 10 {
                seed = seed.wrapping_mul(1_539_415_821).wrapping_add(1);
                let i0 = p + (seed % (r - p + 1) as u64) as isize;
                self.order.swap(i0 as usize, p as usize);
                let piv = self.keys[self.order[p as usize]];
                let mut i = p - 1;
                let mut j = r + 1;
                loop {
                    loop {
                        i += 1;
                        // GT(**i, *piv) = !LEQ(**i, *piv)
                        if leq(key(self, i), piv) {
                            break;
                        }
                    }
                    loop {
                        j -= 1;
                        // LT(**j, *piv) = !LEQ(*piv, **j)
                        if leq(piv, key(self, j)) {
                            break;
                        }
                    }
                    self.order.swap(i as usize, j as usize);
                    if i >= j {
                        break;
                    }
                }
                self.order.swap(i as usize, j as usize);
                if i - p < r - j {
                    stack.push((j + 1, r));
                    r = i - 1;
                } else {
                    stack.push((p, i - 1));
                    p = j + 1;
                }
            }
            let mut i = p + 1;
            while i <= r {
                let piv_slot = self.order[i as usize];
                let piv = self.keys[piv_slot];
                let mut j = i;
                while j > p && !leq(piv, key(self, j - 1)) {
                    self.order[j as usize] = self.order[j as usize - 1];
                    j -= 1;
                }
                self.order[j as usize] = piv_slot;
                i += 1;
            }
        }
        self.initialized = true;
    }

    /// A handle: negative for the sorted part, positive for the heap.
    fn insert(&mut self, m: &Mesh, key: usize) -> i64 {
        if self.initialized {
            return self.heap.insert(m, key) as i64;
        }
        let curr = self.size;
        self.size += 1;
        self.keys.push(key);
        -(curr as i64 + 1)
    }

    fn sort_min(&self) -> usize {
        self.keys[self.order[self.size - 1]]
    }

    fn extract_min(&mut self, m: &Mesh) -> usize {
        if self.size == 0 {
            return self.heap.extract_min(m);
        }
        let sort_min = self.sort_min();
        if self.heap.size != 0 {
            let heap_min = self.heap.minimum();
            if leq_v(m, heap_min, sort_min) {
                return self.heap.extract_min(m);
            }
        }
        loop {
            self.size -= 1;
            if !(self.size > 0 && self.sort_min() == NIL) {
                break;
            }
        }
        sort_min
    }

    fn minimum(&self, m: &Mesh) -> usize {
        if self.size == 0 {
            return self.heap.minimum();
        }
        let sort_min = self.sort_min();
        if self.heap.size != 0 {
            let heap_min = self.heap.minimum();
            if leq_v(m, heap_min, sort_min) {
                return heap_min;
            }
        }
        sort_min
    }

    fn delete(&mut self, m: &Mesh, handle: i64) {
        if handle >= 0 {
            self.heap.delete(m, handle as usize);
            return;
        }
        let curr = (-(handle + 1)) as usize;
        self.keys[curr] = NIL;
        while self.size > 0 && self.sort_min() == NIL {
            self.size -= 1;
        }
    }
}

// The sweep.

#[derive(Clone, Debug)]
struct Region {
    e_up: usize,
    node_up: usize,
    winding_number: i32,
    inside: bool,
    dirty: bool,
    fix_upper_edge: bool,
}

#[derive(Clone, Debug)]
struct DictNode {
    key: usize,
    next: usize,
    prev: usize,
}

/// What the sweep asks of its caller: combining vertex data at intersections and merges, and
/// reporting an error (GLU_TESS_NEED_COMBINE_CALLBACK).
pub(super) trait SweepHost {
    /// The combine callback: new data for a vertex at `coords` from up to four vertices' data
    /// with weights; `None` when there is no callback or it gave nothing.
    fn combine(
        &mut self,
        coords: [f64; 3],
        data: [Option<usize>; 4],
        weights: [f32; 4],
    ) -> Option<usize>;
    fn error(&mut self, code: u32);
}

pub(super) struct Sweep<'a, H: SweepHost> {
    pub mesh: &'a mut Mesh,
    host: &'a mut H,
    winding_rule: u32,
    pub fatal_error: bool,
    regions: Vec<Region>,
    dict: Vec<DictNode>,
    pq: PriorityQ,
    event: usize,
}

use super::tess::{
    GLU_TESS_WINDING_ABS_GEQ_TWO, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_NONZERO,
    GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_POSITIVE,
};

fn l1dist(u: P2, v: P2) -> f64 {
    (u.s - v.s).abs() + (u.t - v.t).abs()
}

impl<'a, H: SweepHost> Sweep<'a, H> {
    pub fn new(mesh: &'a mut Mesh, host: &'a mut H, winding_rule: u32) -> Self {
        Sweep {
            mesh,
            host,
            winding_rule,
            fatal_error: false,
            regions: Vec::new(),
            dict: vec![DictNode {
                key: NIL,
                next: 0,
                prev: 0,
            }],
            pq: PriorityQ::new(),
            event: NIL,
        }
    }

    #[inline]
    fn p(&self, v: usize) -> P2 {
        p2(self.mesh, v)
    }

    fn below(&self, r: usize) -> usize {
        self.dict[self.dict[self.regions[r].node_up].prev].key
    }
    fn above(&self, r: usize) -> usize {
        self.dict[self.dict[self.regions[r].node_up].next].key
    }

    fn edge_leq_e(&self, e1: usize, e2: usize) -> bool {
        let m = &*self.mesh;
        let event = self.event;
        let ev = self.p(event);
        if m.dst(e1) == event {
            if m.dst(e2) == event {
                if vert_leq(self.p(m.org(e1)), self.p(m.org(e2))) {
                    return edge_sign(self.p(m.dst(e2)), self.p(m.org(e1)), self.p(m.org(e2)))
                        <= 0.0;
                }
                return edge_sign(self.p(m.dst(e1)), self.p(m.org(e2)), self.p(m.org(e1))) >= 0.0;
            }
            return edge_sign(self.p(m.dst(e2)), ev, self.p(m.org(e2))) <= 0.0;
        }
        if m.dst(e2) == event {
            return edge_sign(self.p(m.dst(e1)), ev, self.p(m.org(e1))) >= 0.0;
        }
        let t1 = edge_eval(self.p(m.dst(e1)), ev, self.p(m.org(e1)));
        let t2 = edge_eval(self.p(m.dst(e2)), ev, self.p(m.org(e2)));
        t1 >= t2
    }

    fn dict_insert_before(&mut self, mut node: usize, key: usize) -> usize {
        loop {
            node = self.dict[node].prev;
            let k = self.dict[node].key;
            if k == NIL || self.edge_leq_e(self.regions[k].e_up, self.regions[key].e_up) {
                break;
            }
        }
        let new = self.dict.len();
        let next = self.dict[node].next;
        self.dict.push(DictNode {
            key,
            next,
            prev: node,
        });
        self.dict[next].prev = new;
        self.dict[node].next = new;
        new
    }

    fn dict_delete(&mut self, node: usize) {
        let (p, n) = (self.dict[node].prev, self.dict[node].next);
        self.dict[n].prev = p;
        self.dict[p].next = n;
    }

    fn dict_search(&self, e: usize) -> usize {
        let mut node = 0;
        loop {
            node = self.dict[node].next;
            let k = self.dict[node].key;
            if k == NIL || self.edge_leq_e(e, self.regions[k].e_up) {
                return node;
            }
        }
    }

    fn delete_region(&mut self, reg: usize) {
        let e = self.regions[reg].e_up;
        self.mesh.e[e].region = NIL;
        let n = self.regions[reg].node_up;
        self.dict_delete(n);
    }

    fn fix_upper_edge(&mut self, reg: usize, new_edge: usize) {
        let e = self.regions[reg].e_up;
        self.mesh.delete(e);
        self.regions[reg].fix_upper_edge = false;
        self.regions[reg].e_up = new_edge;
        self.mesh.e[new_edge].region = reg;
    }

    fn top_left_region(&mut self, mut reg: usize) -> usize {
        let org = self.mesh.org(self.regions[reg].e_up);
        loop {
            reg = self.above(reg);
            if self.mesh.org(self.regions[reg].e_up) != org {
                break;
            }
        }
        if self.regions[reg].fix_upper_edge {
            let below = self.below(reg);
            let a = sym(self.regions[below].e_up);
            let b = self.mesh.lnext(self.regions[reg].e_up);
            let e = self.mesh.connect(a, b);
            self.fix_upper_edge(reg, e);
            reg = self.above(reg);
        }
        reg
    }

    fn top_right_region(&self, mut reg: usize) -> usize {
        let dst = self.mesh.dst(self.regions[reg].e_up);
        loop {
            reg = self.above(reg);
            if self.mesh.dst(self.regions[reg].e_up) != dst {
                return reg;
            }
        }
    }

    fn add_region_below(&mut self, reg_above: usize, e_new_up: usize) -> usize {
        let r = self.regions.len();
        self.regions.push(Region {
            e_up: e_new_up,
            node_up: NIL,
            winding_number: 0,
            inside: false,
            dirty: false,
            fix_upper_edge: false,
        });
        let n = self.regions[reg_above].node_up;
        let node = self.dict_insert_before(n, r);
        self.regions[r].node_up = node;
        self.mesh.e[e_new_up].region = r;
        r
    }

    fn is_winding_inside(&self, n: i32) -> bool {
        match self.winding_rule {
            GLU_TESS_WINDING_ODD => n & 1 != 0,
            GLU_TESS_WINDING_NONZERO => n != 0,
            GLU_TESS_WINDING_POSITIVE => n > 0,
            GLU_TESS_WINDING_NEGATIVE => n < 0,
            GLU_TESS_WINDING_ABS_GEQ_TWO => !(-1..=1).contains(&n),
            _ => false,
        }
    }

    fn compute_winding(&mut self, reg: usize) {
        let above = self.above(reg);
        let w = self.regions[above]
            .winding_number
            .wrapping_add(self.mesh.e[self.regions[reg].e_up].winding);
        self.regions[reg].winding_number = w;
        self.regions[reg].inside = self.is_winding_inside(w);
    }

    fn finish_region(&mut self, reg: usize) {
        let e = self.regions[reg].e_up;
        let f = self.mesh.lface(e);
        self.mesh.f[f].inside = self.regions[reg].inside;
        self.mesh.f[f].an_edge = e;
        self.delete_region(reg);
    }

    fn add_winding(&mut self, e_dst: usize, e_src: usize) {
        let w = self.mesh.e[e_src].winding;
        let ws = self.mesh.e[e_src ^ 1].winding;
        self.mesh.e[e_dst].winding = self.mesh.e[e_dst].winding.wrapping_add(w);
        self.mesh.e[e_dst ^ 1].winding = self.mesh.e[e_dst ^ 1].winding.wrapping_add(ws);
    }

    fn finish_left_regions(&mut self, reg_first: usize, reg_last: usize) -> usize {
        let mut reg_prev = reg_first;
        let mut e_prev = self.regions[reg_first].e_up;
        while reg_prev != reg_last {
            self.regions[reg_prev].fix_upper_edge = false;
            let reg = self.below(reg_prev);
            let mut e = self.regions[reg].e_up;
            if self.mesh.org(e) != self.mesh.org(e_prev) {
                if !self.regions[reg].fix_upper_edge {
                    self.finish_region(reg_prev);
                    break;
                }
                let a = self.mesh.lprev(e_prev);
                e = self.mesh.connect(a, sym(e));
                self.fix_upper_edge(reg, e);
            }
            if self.mesh.onext(e_prev) != e {
                let op = self.mesh.oprev(e);
                self.mesh.splice(op, e);
                self.mesh.splice(e_prev, e);
            }
            self.finish_region(reg_prev);
            e_prev = self.regions[reg].e_up;
            reg_prev = reg;
        }
        e_prev
    }

    fn add_right_edges(
        &mut self,
        reg_up: usize,
        e_first: usize,
        e_last: usize,
        e_top_left: usize,
        clean_up: bool,
    ) {
        let mut first_time = true;
        let mut e = e_first;
        loop {
            self.add_region_below(reg_up, sym(e));
            e = self.mesh.onext(e);
            if e == e_last {
                break;
            }
        }
        let e_top_left = if e_top_left == NIL {
            let b = self.below(reg_up);
            self.mesh.rprev(self.regions[b].e_up)
        } else {
            e_top_left
        };
        let mut reg_prev = reg_up;
        let mut e_prev = e_top_left;
        loop {
            let reg = self.below(reg_prev);
            e = sym(self.regions[reg].e_up);
            if self.mesh.org(e) != self.mesh.org(e_prev) {
                break;
            }
            if self.mesh.onext(e) != e_prev {
                let op = self.mesh.oprev(e);
                self.mesh.splice(op, e);
                let op = self.mesh.oprev(e_prev);
                self.mesh.splice(op, e);
            }
            let w = self.regions[reg_prev]
                .winding_number
                .wrapping_sub(self.mesh.e[e].winding);
            self.regions[reg].winding_number = w;
            self.regions[reg].inside = self.is_winding_inside(w);
            self.regions[reg_prev].dirty = true;
            if !first_time && self.check_for_right_splice(reg_prev) {
                self.add_winding(e, e_prev);
                self.delete_region(reg_prev);
                self.mesh.delete(e_prev);
            }
            first_time = false;
            reg_prev = reg;
            e_prev = e;
        }
        self.regions[reg_prev].dirty = true;
        if clean_up {
            self.walk_dirty_regions(reg_prev);
        }
    }

    fn call_combine(
        &mut self,
        isect: usize,
        data: [Option<usize>; 4],
        weights: [f32; 4],
        needed: bool,
    ) {
        let coords = self.mesh.v[isect].coords;
        self.mesh.v[isect].data = None;
        let out = self.host.combine(coords, data, weights);
        self.mesh.v[isect].data = out;
        if out.is_none() {
            if !needed {
                self.mesh.v[isect].data = data[0];
            } else if !self.fatal_error {
                self.host.error(super::tess::GLU_TESS_NEED_COMBINE_CALLBACK);
                self.fatal_error = true;
            }
        }
    }

    fn splice_merge_vertices(&mut self, e1: usize, e2: usize) {
        let data = [
            self.mesh.v[self.mesh.org(e1)].data,
            self.mesh.v[self.mesh.org(e2)].data,
            None,
            None,
        ];
        let o = self.mesh.org(e1);
        self.call_combine(o, data, [0.5, 0.5, 0.0, 0.0], false);
        self.mesh.splice(e1, e2);
    }

    fn vertex_weights(&mut self, isect: usize, org: usize, dst: usize) -> [f32; 2] {
        let pi = self.p(isect);
        let t1 = l1dist(self.p(org), pi);
        let t2 = l1dist(self.p(dst), pi);
        let w0 = (0.5 * t2 / (t1 + t2)) as f32;
        let w1 = (0.5 * t1 / (t1 + t2)) as f32;
        let (oc, dc) = (self.mesh.v[org].coords, self.mesh.v[dst].coords);
        let c = &mut self.mesh.v[isect].coords;
        for k in 0..3 {
            c[k] += f64::from(w0) * oc[k] + f64::from(w1) * dc[k];
        }
        [w0, w1]
    }

    fn get_intersect_data(
        &mut self,
        isect: usize,
        org_up: usize,
        dst_up: usize,
        org_lo: usize,
        dst_lo: usize,
    ) {
        let v = &self.mesh.v;
        let data = [
            v[org_up].data,
            v[dst_up].data,
            v[org_lo].data,
            v[dst_lo].data,
        ];
        self.mesh.v[isect].coords = [0.0; 3];
        let a = self.vertex_weights(isect, org_up, dst_up);
        let b = self.vertex_weights(isect, org_lo, dst_lo);
        self.call_combine(isect, data, [a[0], a[1], b[0], b[1]], true);
    }

    fn check_for_right_splice(&mut self, reg_up: usize) -> bool {
        let reg_lo = self.below(reg_up);
        let e_up = self.regions[reg_up].e_up;
        let e_lo = self.regions[reg_lo].e_up;
        let m = &*self.mesh;
        let (up_org, lo_org) = (m.org(e_up), m.org(e_lo));
        if vert_leq(self.p(up_org), self.p(lo_org)) {
            if edge_sign(self.p(m.dst(e_lo)), self.p(up_org), self.p(lo_org)) > 0.0 {
                return false;
            }
            if !vert_eq(self.p(up_org), self.p(lo_org)) {
                self.mesh.split_edge(sym(e_lo));
                let op = self.mesh.oprev(e_lo);
                self.mesh.splice(e_up, op);
                self.regions[reg_up].dirty = true;
                self.regions[reg_lo].dirty = true;
            } else if up_org != lo_org {
                let h = self.mesh.v[up_org].pq_handle;
                self.pq.delete(self.mesh, h);
                let op = self.mesh.oprev(e_lo);
                self.splice_merge_vertices(op, e_up);
            }
        } else {
            if edge_sign(self.p(m.dst(e_up)), self.p(lo_org), self.p(up_org)) < 0.0 {
                return false;
            }
            self.regions[reg_up].dirty = true;
            let a = self.above(reg_up);
            if a != NIL {
                self.regions[a].dirty = true;
            }
            self.mesh.split_edge(sym(e_up));
            let op = self.mesh.oprev(e_lo);
            self.mesh.splice(op, e_up);
        }
        true
    }

    fn check_for_left_splice(&mut self, reg_up: usize) -> bool {
        let reg_lo = self.below(reg_up);
        let e_up = self.regions[reg_up].e_up;
        let e_lo = self.regions[reg_lo].e_up;
        let m = &*self.mesh;
        let (up_dst, lo_dst) = (m.dst(e_up), m.dst(e_lo));
        if vert_leq(self.p(up_dst), self.p(lo_dst)) {
            if edge_sign(self.p(up_dst), self.p(lo_dst), self.p(m.org(e_up))) < 0.0 {
                return false;
            }
            self.regions[reg_up].dirty = true;
            let a = self.above(reg_up);
            if a != NIL {
                self.regions[a].dirty = true;
            }
            let e = self.mesh.split_edge(e_up);
            self.mesh.splice(sym(e_lo), e);
            let lf = self.mesh.lface(e);
            self.mesh.f[lf].inside = self.regions[reg_up].inside;
        } else {
            if edge_sign(self.p(lo_dst), self.p(up_dst), self.p(m.org(e_lo))) > 0.0 {
                return false;
            }
            self.regions[reg_up].dirty = true;
            self.regions[reg_lo].dirty = true;
            let e = self.mesh.split_edge(e_lo);
            let ln = self.mesh.lnext(e_up);
            self.mesh.splice(ln, sym(e_lo));
            let rf = self.mesh.rface(e);
            self.mesh.f[rf].inside = self.regions[reg_up].inside;
        }
        true
    }

    fn check_for_intersect(&mut self, reg_up: usize) -> bool {
        let mut reg_up = reg_up;
        let mut reg_lo = self.below(reg_up);
        let e_up = self.regions[reg_up].e_up;
        let mut e_lo = self.regions[reg_lo].e_up;
        let m = &*self.mesh;
        let (org_up, org_lo, dst_up, dst_lo) = (m.org(e_up), m.org(e_lo), m.dst(e_up), m.dst(e_lo));
        let (pou, pol, pdu, pdl) = (
            self.p(org_up),
            self.p(org_lo),
            self.p(dst_up),
            self.p(dst_lo),
        );
        let event = self.event;
        let pev = self.p(event);

        if org_up == org_lo {
            return false;
        }
        let t_min_up = if pou.t <= pdu.t { pou.t } else { pdu.t };
        let t_max_lo = if pol.t >= pdl.t { pol.t } else { pdl.t };
        if t_min_up > t_max_lo {
            return false;
        }
        if vert_leq(pou, pol) {
            if edge_sign(pdl, pou, pol) > 0.0 {
                return false;
            }
        } else if edge_sign(pdu, pol, pou) < 0.0 {
            return false;
        }

        let mut isect = edge_intersect(pdu, pou, pdl, pol);
        if vert_leq(isect, pev) {
            isect = pev;
        }
        let org_min = if vert_leq(pou, pol) { pou } else { pol };
        if vert_leq(org_min, isect) {
            isect = org_min;
        }

        if vert_eq(isect, pou) || vert_eq(isect, pol) {
            self.check_for_right_splice(reg_up);
            return false;
        }

        if (!vert_eq(pdu, pev) && edge_sign(pdu, pev, isect) >= 0.0)
            || (!vert_eq(pdl, pev) && edge_sign(pdl, pev, isect) <= 0.0)
        {
            if dst_lo == event {
                self.mesh.split_edge(sym(e_up));
                self.mesh.splice(sym(e_lo), e_up);
                reg_up = self.top_left_region(reg_up);
                let b = self.below(reg_up);
                let e_up2 = self.regions[b].e_up;
                self.finish_left_regions(b, reg_lo);
                let op = self.mesh.oprev(e_up2);
                self.add_right_edges(reg_up, op, e_up2, e_up2, true);
                return true;
            }
            if dst_up == event {
                self.mesh.split_edge(sym(e_lo));
                let ln = self.mesh.lnext(e_up);
                let op = self.mesh.oprev(e_lo);
                self.mesh.splice(ln, op);
                reg_lo = reg_up;
                reg_up = self.top_right_region(reg_up);
                let b = self.below(reg_up);
                let e = self.mesh.rprev(self.regions[b].e_up);
                self.regions[reg_lo].e_up = self.mesh.oprev(e_lo);
                e_lo = self.finish_left_regions(reg_lo, NIL);
                let first = self.mesh.onext(e_lo);
                let last = self.mesh.rprev(e_up);
                self.add_right_edges(reg_up, first, last, e, true);
                return true;
            }
            if edge_sign(pdu, pev, isect) >= 0.0 {
                let a = self.above(reg_up);
                self.regions[a].dirty = true;
                self.regions[reg_up].dirty = true;
                self.mesh.split_edge(sym(e_up));
                let o = self.mesh.org(e_up);
                self.mesh.v[o].s = pev.s;
                self.mesh.v[o].t = pev.t;
            }
            if edge_sign(pdl, pev, isect) <= 0.0 {
                self.regions[reg_up].dirty = true;
                self.regions[reg_lo].dirty = true;
                self.mesh.split_edge(sym(e_lo));
                let o = self.mesh.org(e_lo);
                self.mesh.v[o].s = pev.s;
                self.mesh.v[o].t = pev.t;
            }
            return false;
        }

        self.mesh.split_edge(sym(e_up));
        self.mesh.split_edge(sym(e_lo));
        let op = self.mesh.oprev(e_lo);
        self.mesh.splice(op, e_up);
        let o = self.mesh.org(e_up);
        self.mesh.v[o].s = isect.s;
        self.mesh.v[o].t = isect.t;
        let h = self.pq.insert(self.mesh, o);
        self.mesh.v[o].pq_handle = h;
        self.get_intersect_data(o, org_up, dst_up, org_lo, dst_lo);
        let a = self.above(reg_up);
        self.regions[a].dirty = true;
        self.regions[reg_up].dirty = true;
        self.regions[reg_lo].dirty = true;
        false
    }

    fn walk_dirty_regions(&mut self, reg_up: usize) {
        let mut reg_up = reg_up;
        let mut reg_lo = self.below(reg_up);
        loop {
            while self.regions[reg_lo].dirty {
                reg_up = reg_lo;
                reg_lo = self.below(reg_lo);
            }
            if !self.regions[reg_up].dirty {
                reg_lo = reg_up;
                reg_up = self.above(reg_up);
                if reg_up == NIL || !self.regions[reg_up].dirty {
                    return;
                }
            }
            self.regions[reg_up].dirty = false;
            let mut e_up = self.regions[reg_up].e_up;
            let mut e_lo = self.regions[reg_lo].e_up;

            if self.mesh.dst(e_up) != self.mesh.dst(e_lo) && self.check_for_left_splice(reg_up) {
                if self.regions[reg_lo].fix_upper_edge {
                    self.delete_region(reg_lo);
                    self.mesh.delete(e_lo);
                    reg_lo = self.below(reg_up);
                    e_lo = self.regions[reg_lo].e_up;
                } else if self.regions[reg_up].fix_upper_edge {
                    self.delete_region(reg_up);
                    self.mesh.delete(e_up);
                    reg_up = self.above(reg_lo);
                    e_up = self.regions[reg_up].e_up;
                }
            }
            if self.mesh.org(e_up) != self.mesh.org(e_lo) {
                if self.mesh.dst(e_up) != self.mesh.dst(e_lo)
                    && !self.regions[reg_up].fix_upper_edge
                    && !self.regions[reg_lo].fix_upper_edge
                    && (self.mesh.dst(e_up) == self.event || self.mesh.dst(e_lo) == self.event)
                {
                    if self.check_for_intersect(reg_up) {
                        return;
                    }
                } else {
                    self.check_for_right_splice(reg_up);
                }
            }
            if self.mesh.org(e_up) == self.mesh.org(e_lo)
                && self.mesh.dst(e_up) == self.mesh.dst(e_lo)
            {
                self.add_winding(e_lo, e_up);
                self.delete_region(reg_up);
                self.mesh.delete(e_up);
                reg_up = self.above(reg_lo);
            }
        }
    }

    fn connect_right_vertex(&mut self, reg_up: usize, e_bottom_left: usize) {
        let mut reg_up = reg_up;
        let mut e_bottom_left = e_bottom_left;
        let mut e_top_left = self.mesh.onext(e_bottom_left);
        let reg_lo = self.below(reg_up);
        let e_up = self.regions[reg_up].e_up;
        let e_lo = self.regions[reg_lo].e_up;
        let mut degenerate = false;

        if self.mesh.dst(e_up) != self.mesh.dst(e_lo) {
            self.check_for_intersect(reg_up);
        }
        let pev = self.p(self.event);
        if vert_eq(self.p(self.mesh.org(e_up)), pev) {
            let op = self.mesh.oprev(e_top_left);
            self.mesh.splice(op, e_up);
            reg_up = self.top_left_region(reg_up);
            let b = self.below(reg_up);
            e_top_left = self.regions[b].e_up;
            self.finish_left_regions(b, reg_lo);
            degenerate = true;
        }
        if vert_eq(self.p(self.mesh.org(e_lo)), pev) {
            let op = self.mesh.oprev(e_lo);
            self.mesh.splice(e_bottom_left, op);
            e_bottom_left = self.finish_left_regions(reg_lo, NIL);
            degenerate = true;
        }
        if degenerate {
            let first = self.mesh.onext(e_bottom_left);
            self.add_right_edges(reg_up, first, e_top_left, e_top_left, true);
            return;
        }
        let e_new = if vert_leq(self.p(self.mesh.org(e_lo)), self.p(self.mesh.org(e_up))) {
            self.mesh.oprev(e_lo)
        } else {
            e_up
        };
        let lp = self.mesh.lprev(e_bottom_left);
        let e_new = self.mesh.connect(lp, e_new);
        let on = self.mesh.onext(e_new);
        self.add_right_edges(reg_up, e_new, on, on, false);
        let r = self.mesh.e[sym(e_new)].region;
        self.regions[r].fix_upper_edge = true;
        self.walk_dirty_regions(reg_up);
    }

    fn connect_left_degenerate(&mut self, reg_up: usize, v_event: usize) {
        let e = self.regions[reg_up].e_up;
        let pev = self.p(v_event);
        if vert_eq(self.p(self.mesh.org(e)), pev) {
            let a = self.mesh.v[v_event].an_edge;
            self.splice_merge_vertices(e, a);
            return;
        }
        if !vert_eq(self.p(self.mesh.dst(e)), pev) {
            self.mesh.split_edge(sym(e));
            if self.regions[reg_up].fix_upper_edge {
                let on = self.mesh.onext(e);
                self.mesh.delete(on);
                self.regions[reg_up].fix_upper_edge = false;
            }
            let a = self.mesh.v[v_event].an_edge;
            self.mesh.splice(a, e);
            self.sweep_event(v_event);
            return;
        }
        let reg_up = self.top_right_region(reg_up);
        let reg = self.below(reg_up);
        let mut e_top_right = sym(self.regions[reg].e_up);
        let mut e_top_left = self.mesh.onext(e_top_right);
        let e_last = e_top_left;
        if self.regions[reg].fix_upper_edge {
            self.delete_region(reg);
            self.mesh.delete(e_top_right);
            e_top_right = self.mesh.oprev(e_top_left);
        }
        let a = self.mesh.v[v_event].an_edge;
        self.mesh.splice(a, e_top_right);
        // EdgeGoesLeft(eTopLeft)
        if !vert_leq(
            self.p(self.mesh.dst(e_top_left)),
            self.p(self.mesh.org(e_top_left)),
        ) {
            e_top_left = NIL;
        }
        let first = self.mesh.onext(e_top_right);
        self.add_right_edges(reg_up, first, e_last, e_top_left, true);
    }

    fn connect_left_vertex(&mut self, v_event: usize) {
        let an = self.mesh.v[v_event].an_edge;
        let node = self.dict_search(sym(an));
        let reg_up = self.dict[node].key;
        if reg_up == NIL {
            return;
        }
        let reg_lo = self.below(reg_up);
        if reg_lo == NIL {
            return;
        }
        let e_up = self.regions[reg_up].e_up;
        let e_lo = self.regions[reg_lo].e_up;
        let m = &*self.mesh;
        if edge_sign(self.p(m.dst(e_up)), self.p(v_event), self.p(m.org(e_up))) == 0.0 {
            self.connect_left_degenerate(reg_up, v_event);
            return;
        }
        let reg = if vert_leq(self.p(m.dst(e_lo)), self.p(m.dst(e_up))) {
            reg_up
        } else {
            reg_lo
        };
        if self.regions[reg_up].inside || self.regions[reg].fix_upper_edge {
            let e_new = if reg == reg_up {
                let ln = self.mesh.lnext(e_up);
                self.mesh.connect(sym(an), ln)
            } else {
                let dn = self.mesh.dnext(e_lo);
                sym(self.mesh.connect(dn, an))
            };
            if self.regions[reg].fix_upper_edge {
                self.fix_upper_edge(reg, e_new);
            } else {
                let r = self.add_region_below(reg_up, e_new);
                self.compute_winding(r);
            }
            self.sweep_event(v_event);
        } else {
            self.add_right_edges(reg_up, an, an, NIL, true);
        }
    }

    fn sweep_event(&mut self, v_event: usize) {
        self.event = v_event;
        let an = self.mesh.v[v_event].an_edge;
        let mut e = an;
        while self.mesh.e[e].region == NIL {
            e = self.mesh.onext(e);
            if e == an {
                self.connect_left_vertex(v_event);
                return;
            }
        }
        let r = self.mesh.e[e].region;
        let reg_up = self.top_left_region(r);
        let reg = self.below(reg_up);
        let e_top_left = self.regions[reg].e_up;
        let e_bottom_left = self.finish_left_regions(reg, NIL);
        if self.mesh.onext(e_bottom_left) == e_top_left {
            self.connect_right_vertex(reg_up, e_bottom_left);
        } else {
            let first = self.mesh.onext(e_bottom_left);
            self.add_right_edges(reg_up, first, e_top_left, e_top_left, true);
        }
    }

    fn add_sentinel(&mut self, t: f64) {
        let e = self.mesh.make_edge_full();
        let (o, d) = (self.mesh.org(e), self.mesh.dst(e));
        self.mesh.v[o].s = SENTINEL_COORD;
        self.mesh.v[o].t = t;
        self.mesh.v[d].s = -SENTINEL_COORD;
        self.mesh.v[d].t = t;
        self.event = d;
        let r = self.regions.len();
        self.regions.push(Region {
            e_up: e,
            node_up: NIL,
            winding_number: 0,
            inside: false,
            dirty: false,
            fix_upper_edge: false,
        });
        let node = self.dict_insert_before(0, r);
        self.regions[r].node_up = node;
    }

    fn remove_degenerate_edges(&mut self) {
        let mut e = self.mesh.e[0].next;
        while e != 0 {
            let mut e_next = self.mesh.e[e].next;
            let mut e_lnext = self.mesh.lnext(e);
            let m = &*self.mesh;
            if vert_eq(self.p(m.org(e)), self.p(m.dst(e))) && m.lnext(m.lnext(e)) != e {
                self.splice_merge_vertices(e_lnext, e);
                self.mesh.delete(e);
                e = e_lnext;
                e_lnext = self.mesh.lnext(e);
            }
            if self.mesh.lnext(e_lnext) == e {
                if e_lnext != e {
                    if e_lnext == e_next || e_lnext == sym(e_next) {
                        e_next = self.mesh.e[e_next].next;
                    }
                    self.mesh.delete(e_lnext);
                }
                if e == e_next || e == sym(e_next) {
                    e_next = self.mesh.e[e_next].next;
                }
                self.mesh.delete(e);
            }
            e = e_next;
        }
    }

    fn remove_degenerate_faces(&mut self) {
        let mut f = self.mesh.f[0].next;
        while f != 0 {
            let f_next = self.mesh.f[f].next;
            let e = self.mesh.f[f].an_edge;
            if self.mesh.lnext(self.mesh.lnext(e)) == e {
                let on = self.mesh.onext(e);
                self.add_winding(on, e);
                self.mesh.delete(e);
            }
            f = f_next;
        }
    }

    /// `__gl_computeInterior`: the sweep. Afterwards each face of the mesh is monotone and
    /// knows whether it is inside.
    pub fn compute_interior(&mut self) {
        self.fatal_error = false;
        self.remove_degenerate_edges();
        let mut v = self.mesh.v[0].next;
        while v != 0 {
            let h = self.pq.insert(self.mesh, v);
            self.mesh.v[v].pq_handle = h;
            v = self.mesh.v[v].next;
        }
        self.pq.init(self.mesh);
        self.add_sentinel(-SENTINEL_COORD);
        self.add_sentinel(SENTINEL_COORD);
        loop {
            let v = self.pq.extract_min(self.mesh);
            if v == NIL {
                break;
            }
            loop {
                let v_next = self.pq.minimum(self.mesh);
                if v_next == NIL || !vert_eq(self.p(v_next), self.p(v)) {
                    break;
                }
                let v_next = self.pq.extract_min(self.mesh);
                let (a, b) = (self.mesh.v[v].an_edge, self.mesh.v[v_next].an_edge);
                self.splice_merge_vertices(a, b);
            }
            self.sweep_event(v);
        }
        // DoneEdgeDict: the regions left (the sentinels, at most one fixable edge) go.
        loop {
            let r = self.dict[self.dict[0].next].key;
            if r == NIL {
                break;
            }
            self.delete_region(r);
        }
        self.remove_degenerate_faces();
    }
}
