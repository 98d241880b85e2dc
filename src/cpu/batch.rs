//! The vertex batch: every vertex given since the last flush, with its attributes, in flat
//! structure-of-arrays form, plus the list of primitives (Begin/End pairs) over it.
//!
//! GL 2.1 §2.6–2.7: a vertex takes the current normal, colours, texture coordinates and edge
//! flag at the moment `Vertex` is called. Design decision: a vertex identical in every input to
//! one already batched (found through a small two-way set-associative cache, compared bit for
//! bit) is stored once and referenced by index, so the vertex stage lights it once: immediate-mode
//! meshes such as one strip per grid cell send each vertex up to four times, and the vertex
//! stage is a pure function of these inputs, so the result is exactly the same. A cache slot
//! holds only the serial number of a batched vertex (8-byte sets, 32 KB in all: the load of a
//! random set for every vertex is the front end's costliest, so the table is kept small), and a
//! candidate is confirmed against the batch's own position and normal arrays, whose recent
//! entries are warm; the other inputs (colours, texture coordinates, fog coordinate, edge flag,
//! material), which rarely change inside a mesh, are compared only with the previous vertex's
//! (and then only their stamps, unless one of them was written since: see `state::Current`):
//! a run of vertices with the same such inputs forms a span, and a hit counts only inside the
//! current span. The span is also the unit of storage: its colours, texture coordinates and fog
//! coordinate are stored once (`spans`), and a unique vertex stores its position, normal, edge
//! flag, material index and span index (about 40 bytes instead of 100: the batch is written at
//! the rate calls arrive, so its size is a per-vertex cost). The arrays are cleared, not freed,
//! at each flush, so steady-state drawing allocates nothing per vertex;
//! `Material` changes inside Begin/End (§2.14.3) are rare, so they are stored as whole snapshots
//! that vertices index.

use glam::{Vec3, Vec4};

use crate::state::{Current, Inputs, Material, MAX_TEXTURE_UNITS};

/// One Begin/End pair: `count` entries of `Batch::idx` from `first`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prim {
    /// The Begin mode (POINTS ..= POLYGON).
    pub mode: u32,
    /// Index of the first entry in `Batch::idx`.
    pub first: u32,
    /// Number of vertices.
    pub count: u32,
}

/// Sets in the vertex cache (a power of two); each holds two slots.
const SETS: usize = 1 << 12;

/// Serial numbers past which `clear` empties the cache and starts again from 0, so that the
/// serials of a batch fit in a slot's `u32` (`flush_if_large` draws a batch at a few tens of
/// thousands of vertices; in a batch of more than 2^31, the vertices past `u32::MAX` are not
/// cached).
const SERIAL_RESET: u64 = 1 << 31;

/// A vertex cache slot: the serial number of a batched vertex (its index plus
/// `Batch::serial0`), so that a slot left from an earlier batch is never a hit; its position and
/// normal are the batch's. (Slots holding the position and normal bits themselves made 64-byte
/// sets, 256 KB in all, and the load of a set was then the front end's worst stall: half of
/// `Context::replay`'s samples in gauss-smooth-400, on the 3 Dec fifth session's profile.)
type Slot = u32;

/// Never a hit: a hit needs a serial below the current vertex's, which is below `u32::MAX`.
const EMPTY: Slot = u32::MAX;

/// Two slots sharing one hash, the newer first (first in, first out: a hit changes nothing).
/// A mesh reuses a vertex a row later, after some hundreds of other vertices: two ways keep it
/// when another vertex lands on the same set, where one way lost about one vertex in six of
/// gauss-smooth-400 (each miss is one more vertex to store and light).
#[derive(Clone, Copy, Debug)]
#[repr(align(8))]
struct Set([Slot; 2]);

/// The bits of a normal as a vertex's cache key holds them: x and y as one 64-bit word, z.
#[derive(Clone, Copy, Debug)]
struct NormalBits {
    n01: u64,
    n2: u32,
}

/// Two 32-bit words as one 64-bit word, `lo` in the low half.
#[inline(always)]
fn word(lo: u32, hi: u32) -> u64 {
    u64::from(lo) | u64::from(hi) << 32
}

/// Writes `x` at index `i` of `v`, whose length is `i`, and takes it in.
///
/// # Safety
/// `v.len() == i` and `i < v.capacity()`.
#[inline(always)]
unsafe fn put<T>(v: &mut Vec<T>, i: usize, x: T) {
    debug_assert!(v.len() == i && i < v.capacity());
    // SAFETY: the caller's: slot `i` is allocated and past the length, so writing it drops
    // nothing, and once written the first `i + 1` elements are initialised.
    unsafe {
        v.as_mut_ptr().add(i).write(x);
        v.set_len(i + 1);
    }
}

/// Whether the batched position `p` and normal `n` have the bits of `position` and `normal`:
/// the positions as one 128-bit word each (one vector compare), the normals' words without a
/// branch between them.
#[inline(always)]
fn same_vertex(p: &Vec4, n: &Vec3, position: Vec4, normal: NormalBits) -> bool {
    let n = NormalBits::of(*n);
    (bits128(*p) == bits128(position)) & ((n.n01 ^ normal.n01) | u64::from(n.n2 ^ normal.n2) == 0)
}

/// The bits of `v` as one 128-bit word (a compare of two is one vector compare).
#[inline(always)]
fn bits128(v: Vec4) -> u128 {
    // SAFETY: four f32s and a u128 are both 16 bytes of plain data, every bit pattern valid in
    // either.
    unsafe { std::mem::transmute::<[f32; 4], u128>(v.to_array()) }
}

/// The 64-bit word read from memory holding two 32-bit words as `word(first, second)`: itself
/// on a little-endian machine, its halves swapped on a big-endian one.
#[inline(always)]
fn lo_first(w: u64) -> u64 {
    if cfg!(target_endian = "little") {
        w
    } else {
        w.rotate_left(32)
    }
}

// `Batch::vertex` reads the current normal's x and y as one aligned 64-bit word: the normal
// lies at an offset of `Current` that is a multiple of 8, in a type aligned to 8 or more.
const _: () = assert!(
    std::mem::offset_of!(Current, normal) % 8 == 0 && std::mem::align_of::<Current>() % 8 == 0
);

impl NormalBits {
    /// The bits of `n`.
    #[inline(always)]
    fn of(n: Vec3) -> NormalBits {
        NormalBits::new(n.to_array().map(f32::to_bits))
    }

    /// The normal.
    #[inline(always)]
    fn vec3(self) -> Vec3 {
        let [x, y, z] = [self.n01 as u32, (self.n01 >> 32) as u32, self.n2].map(f32::from_bits);
        Vec3::new(x, y, z)
    }

    /// The bits of the normal with components `n`.
    #[inline(always)]
    fn new(n: [u32; 3]) -> NormalBits {
        NormalBits {
            n01: word(n[0], n[1]),
            n2: n[2],
        }
    }
}

/// A vertex's cache key: the bits of its position and normal as 64-bit words (x and y, z and
/// w, the normal's), the form the hash mixes, so that the words are built once (mixing the
/// seven 32-bit words one by one, with a rotation each, cost about 35 instructions a vertex,
/// most of them moving words between registers and the stack). A hit compares the normal's
/// words, and the position as one vector (`Batch::vertex_in_span`).
#[derive(Clone, Copy, Debug)]
struct Key {
    xy: u64,
    zw: u64,
    normal: NormalBits,
}

impl Key {
    /// The key of the position with bits `pos` and the normal `normal`.
    #[cfg(test)]
    #[inline(always)]
    fn new(pos: [u32; 4], normal: NormalBits) -> Key {
        Key {
            xy: word(pos[0], pos[1]),
            zw: word(pos[2], pos[3]),
            normal,
        }
    }

    /// The key of `position` with the normal `normal`: the position's bits as two 64-bit
    /// words taken whole from its vector register (built from its four 32-bit words, each
    /// extracted, shifted and combined, they cost four instructions a vertex more).
    #[inline(always)]
    fn at(position: Vec4, normal: NormalBits) -> Key {
        // SAFETY: four f32s and two u64s are both 16 bytes of plain data, every bit pattern
        // valid in either.
        let [a, b] = unsafe { std::mem::transmute::<[f32; 4], [u64; 2]>(position.to_array()) };
        Key {
            xy: lo_first(a),
            zw: lo_first(b),
            normal,
        }
    }

    /// The key of a batched vertex.
    #[cfg(test)]
    #[inline(always)]
    fn of(pos: &Vec4, normal: &Vec3) -> Key {
        Key::new(pos.to_array().map(f32::to_bits), NormalBits::of(*normal))
    }

    /// The position.
    #[cfg(test)]
    #[inline(always)]
    fn position(self) -> Vec4 {
        let half = |w: u64| [w as u32, (w >> 32) as u32].map(f32::from_bits);
        let ([x, y], [z, w]) = (half(self.xy), half(self.zw));
        Vec4::new(x, y, z, w)
    }

    /// Whether every bit is the same: the words compared without a branch between them.
    #[cfg(test)]
    #[inline(always)]
    fn same(self, other: Key) -> bool {
        let (n, m) = (self.normal, other.normal);
        ((self.xy ^ other.xy) | (self.zw ^ other.zw) | (n.n01 ^ m.n01)) | u64::from(n.n2 ^ m.n2)
            == 0
    }

    /// The cache set: two 64-bit products, of the position's words and of the normal's (one
    /// word of each rotated, so that equal words such as a unit sphere's position and normal
    /// do not cancel), whose top bits depend on every bit.
    #[inline(always)]
    fn set(self) -> usize {
        let n = self.normal;
        let p = (self.xy ^ self.zw.rotate_left(21)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let n = (n.n01 ^ u64::from(n.n2).rotate_left(43)).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
        ((p ^ n) >> 52) as usize & (SETS - 1)
    }
}

/// The inputs a span of vertices shares besides its edge flag and material (which stay per
/// vertex for assembly and setup).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attribs {
    /// Current (primary) colour.
    pub color: Vec4,
    /// Current secondary colour.
    pub color2: Vec4,
    /// Texture coordinates of each unit.
    pub tex: [Vec4; MAX_TEXTURE_UNITS],
    /// Current fog coordinate (FOG_COORD_SRC = FOG_COORD, §3.10).
    pub fog: f32,
}

impl Attribs {
    /// Every input zero: the batch's first span (`Batch::span_in` with material 0).
    const ZERO: Attribs = Attribs {
        color: Vec4::ZERO,
        color2: Vec4::ZERO,
        tex: [Vec4::ZERO; MAX_TEXTURE_UNITS],
        fog: 0.0,
    };

    fn of(c: &Current) -> Self {
        Attribs {
            color: c.color,
            color2: c.secondary_color,
            tex: c.tex_coords,
            fog: c.fog_coord,
        }
    }
}

/// The batched vertices (object coordinates and current attributes) and primitives.
#[derive(Debug)]
pub struct Batch {
    /// Per vertex given, the index of its (unique) vertex in the attribute arrays.
    pub idx: Vec<u32>,
    /// Two-way set-associative cache: position and normal hash → batched vertices.
    cache: Box<[Set; SETS]>,
    /// Serial number of the batch's vertex 0 (the vertices of all earlier batches).
    serial0: u64,
    /// Serial number of the first vertex of the current span (see the module docs).
    span: u64,
    /// The inputs of the vertex that started the current span: its colours, texture
    /// coordinates, fog coordinate and edge flag are those of every batched vertex from
    /// `span` on (the last entry of `spans`; its position and normal are not used), and its
    /// stamp that of the latest such vertex (`Current::same_inputs_as`).
    span_in: Current,
    /// The material index of every batched vertex from `span` on. Whenever `cur_mat` is
    /// another, `span_in`'s stamp is forgotten (`Current::forget_stamp`), so that
    /// `check_span`'s one compare of stamps also stands for the material's.
    span_mat: u32,
    /// Object-coordinate positions.
    pos: Vec<Vec4>,
    /// Current normal at each vertex.
    normal: Vec<Vec3>,
    /// Index into `spans` of each vertex's other inputs.
    span_of: Vec<u32>,
    /// The other inputs of each span (see the module docs); never empty, and its last entry is
    /// the current span's.
    pub spans: Vec<Attribs>,
    /// Edge flag.
    edge: Vec<bool>,
    /// A length up to which `pos`, `normal`, `span_of` and `edge` all have room: the least of
    /// their capacities when a push last grew one (0 at first). Nothing changes those arrays
    /// but `vertex_in_span` (a push, or a write within `room`) and `clear` (which keeps their
    /// memory), so a capacity never falls below it; a unique vertex is then written to the
    /// four without testing each one's capacity and length (about fifteen instructions a
    /// stored vertex).
    room: usize,
    /// Index into `snapshots` of each vertex; filled only once `snapshots` is not empty (until
    /// then every vertex uses the state's materials, and `mat` stays empty).
    pub mat: Vec<u32>,
    /// The primitives, in call order.
    pub prims: Vec<Prim>,
    /// Material snapshots; empty when no Material call happened inside Begin/End in this batch,
    /// in which case every vertex uses the state's materials.
    pub snapshots: Vec<[Material; 2]>,
    /// The materials in effect at the last Begin (what vertices before the first in-Begin
    /// Material change use).
    base: Option<[Material; 2]>,
    cur_mat: u32,
}

impl Default for Batch {
    fn default() -> Self {
        Batch {
            idx: Vec::new(),
            cache: Box::new([Set([EMPTY; 2]); SETS]),
            serial0: 0,
            span: 0,
            span_in: Current::new(
                Inputs {
                    color: Vec4::ZERO,
                    secondary_color: Vec4::ZERO,
                    tex_coords: [Vec4::ZERO; MAX_TEXTURE_UNITS],
                    fog_coord: 0.0,
                    edge_flag: false,
                },
                Vec3::ZERO,
                0.0,
            ),
            span_mat: 0,
            pos: Vec::new(),
            normal: Vec::new(),
            span_of: Vec::new(),
            // The all-zero inputs (`span_in`, edge flag false, and material 0).
            spans: vec![Attribs::ZERO],
            edge: Vec::new(),
            room: 0,
            mat: Vec::new(),
            prims: Vec::new(),
            snapshots: Vec::new(),
            base: None,
            cur_mat: 0,
        }
    }
}

impl Batch {
    /// Object-coordinate positions of the batched vertices. The per-vertex arrays (`pos`,
    /// `normal`, `span_of`, `edge`) are private to this module and read through accessors:
    /// `vertex_in_span`'s unchecked reads and writes rely on their lengths and capacities
    /// (`room`) changing only here.
    pub fn pos(&self) -> &[Vec4] {
        &self.pos
    }

    /// Current normal at each batched vertex.
    pub fn normal(&self) -> &[Vec3] {
        &self.normal
    }

    /// Edge flag of each batched vertex.
    pub fn edge(&self) -> &[bool] {
        &self.edge
    }

    /// Number of unique batched vertices.
    pub fn len(&self) -> usize {
        self.pos.len()
    }

    /// True when nothing is batched.
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty()
    }

    /// Opens a primitive.
    pub fn begin(&mut self, mode: u32) {
        self.prims.push(Prim {
            mode,
            first: self.idx.len() as u32,
            count: 0,
        });
    }

    /// Appends a vertex with the current attributes to the open primitive (the caller has
    /// opened one: `Context::vertex` draws nothing outside Begin/End). The primitive's count
    /// is taken at `end`. For `c` in memory, such as the state's current values: the front end
    /// stores the normal as its x and y in one 64-bit word and its z (`Normal3f`), and loading
    /// them as one wider word would stall store forwarding for ~15 cycles, so they are read in
    /// the same two pieces (volatile loads keep the compiler from merging or splitting them;
    /// `black_box` did too, but through a store and a reload), which are also the key's words
    /// (read as three 32-bit words, they were spilled and put together again: about eight
    /// instructions a vertex).
    #[inline(always)]
    pub fn vertex(&mut self, position: Vec4, c: &Current) {
        // The span first: the normal's words are loaded after it, where the hash takes them
        // (loaded before, they were held on the stack across it).
        self.check_span(c);
        let n = &c.normal;
        // SAFETY: `n` is an f32's reference, its address a multiple of 8 (the assertion on
        // `Current`'s layout above), so the u64 of its x and y is readable there; `n.z` is
        // readable as the u32 of its size and alignment.
        let normal = unsafe {
            NormalBits {
                n01: lo_first(std::ptr::read_volatile(std::ptr::from_ref(n).cast::<u64>())),
                n2: std::ptr::read_volatile(std::ptr::from_ref(&n.z).cast::<u32>()),
            }
        };
        self.vertex_in_span(Key::at(position, normal), position, c);
    }

    /// [`Batch::vertex`] for values the caller has just computed, such as an evaluator's
    /// vertex: the normal is read as the compiler likes (a volatile load would make it keep
    /// the whole `Current` in memory, about 35 instructions more a vertex there).
    #[inline(always)]
    pub fn vertex_computed(&mut self, position: Vec4, c: &Current) {
        self.check_span(c);
        self.vertex_in_span(Key::at(position, NormalBits::of(c.normal)), position, c);
    }

    /// Starts a span at the next vertex if `c`'s inputs other than position and normal are
    /// not the current span's: [`Batch::vertex`]'s first step.
    #[inline(always)]
    fn check_span(&mut self, c: &Current) {
        // The same stamp is the same inputs (`Current`'s docs) and the same material (the
        // stamp is forgotten when `cur_mat` leaves `span_mat`): the common case, one compare
        // instead of 25 floats, the edge flag and the material's index.
        if !self.span_in.same_stamp_as(c)
            && (!self.span_in.same_inputs_as(c) || self.cur_mat != self.span_mat)
        {
            self.new_span(c, self.serial0 + self.pos.len() as u64);
        }
    }

    /// [`Batch::vertex`] once `check_span(c)` ran: the vertex with bits `key` (of
    /// `position` and the normal) looked up in the cache, batched on a miss.
    #[inline(always)]
    fn vertex_in_span(&mut self, key: Key, position: Vec4, c: &Current) {
        let i = self.pos.len();
        let serial = self.serial0 + i as u64;
        {
            let Set(ways) = &mut self.cache[key.set()];
            // A hit: a vertex of this span (same other inputs, serial in `span..serial`: one
            // compare, as the serials wrap below `span`) with the same position and normal
            // bits. A serial of this span is at least `serial0` (`span` is `serial0` plus the
            // length at `new_span`, or `serial0` at `clear`), so its index is below the arrays'
            // length, and both are read without a test (two instructions a probe, and the
            // registers the compare then spilled less: 7.9M of gauss-smooth-400's whole
            // process; tested, they were 1.39% of it in the twentieth session, but other scenes
            // rose by up to 0.10% then, and they do not now). The position is compared as one
            // 128-bit word with the vector it came in (one vector compare; as the key's two
            // words, those held two more registers through the probe, and the compare spilled
            // about ten values around its loads).
            let (span, serial0) = (self.span, self.serial0);
            debug_assert!(serial0 <= span && span <= serial);
            let live = serial - span;
            let (positions, normals) = (&self.pos, &self.normal);
            debug_assert_eq!(normals.len(), positions.len());
            let hit = |s: Slot| {
                u64::from(s).wrapping_sub(span) < live && {
                    let k = (u64::from(s) - serial0) as usize;
                    debug_assert!(k < positions.len());
                    // SAFETY: `span` is set only to `serial0 + pos.len()` (`new_span`) or to
                    // `serial0` (`clear`, the one place `serial0` and the length change but
                    // for the pushes, which only grow it), so `serial0 <= span <= serial`, and
                    // the test above puts `s` in `span..serial`: `k < pos.len()`. `normal`
                    // has the same length (every vertex is written to both, both are cleared
                    // together, nothing else changes their lengths).
                    let (p, n) = unsafe { (positions.get_unchecked(k), normals.get_unchecked(k)) };
                    same_vertex(p, n, position, key.normal)
                }
            };
            let [newer, older] = *ways;
            let found = if hit(newer) {
                Some(newer)
            } else if hit(older) {
                Some(older)
            } else {
                None
            };
            if let Some(s) = found {
                self.idx.push((u64::from(s) - serial0) as u32);
                return;
            }
            // Past `u32::MAX` (see `SERIAL_RESET`) a vertex is not cached: a slot holds a
            // `u32`. (One cached before is still found, its serial being in the span: tested
            // only here, the test is paid by a stored vertex, not by every one.)
            if let Ok(serial) = u32::try_from(serial) {
                ways[1] = ways[0];
                ways[0] = serial;
            }
        }
        self.idx.push(i as u32);
        let (normal, span) = (key.normal.vec3(), self.spans.len().saturating_sub(1) as u32);
        debug_assert!([self.normal.len(), self.span_of.len(), self.edge.len()] == [i; 3]);
        if i < self.room {
            // SAFETY: `i` is the length of `pos`, `normal`, `span_of` and `edge` (pushed
            // together only here, cleared together only in `clear`), and below `room`, which is
            // at most each one's capacity (`room`'s docs): the slot at `i` of each is allocated,
            // and written before the length takes it in.
            unsafe {
                put(&mut self.pos, i, position);
                put(&mut self.normal, i, normal);
                put(&mut self.span_of, i, span);
                put(&mut self.edge, i, c.edge_flag);
            }
        } else {
            self.pos.push(position);
            self.normal.push(normal);
            self.span_of.push(span);
            self.edge.push(c.edge_flag);
            self.room = [
                self.pos.capacity(),
                self.normal.capacity(),
                self.span_of.capacity(),
                self.edge.capacity(),
            ]
            .into_iter()
            .min()
            .unwrap_or(0);
        }
        if !self.snapshots.is_empty() {
            self.mat.push(self.cur_mat);
        }
    }

    /// Starts a span at vertex `serial`: the inputs other than position and normal changed.
    /// Inline: a mesh whose every vertex has its own texture coordinates (GLUT's teapot)
    /// starts a span at nearly every vertex, and a call there cost its spills and arguments.
    #[inline(always)]
    fn new_span(&mut self, c: &Current, serial: u64) {
        self.span = serial;
        self.span_in = *c;
        self.span_mat = self.cur_mat;
        self.spans.push(Attribs::of(c));
    }

    /// The inputs other than position, normal, edge flag and material of unique vertex `i`.
    #[inline]
    pub fn attribs(&self, i: usize) -> Option<&Attribs> {
        let s = *self.span_of.get(i)?;
        self.spans.get(s as usize)
    }

    /// Closes the open primitive: its vertices are those given since its `begin`; an empty one
    /// is dropped.
    pub fn end(&mut self) {
        let given = self.idx.len() as u32;
        if let Some(p) = self.prims.last_mut() {
            // `first` was the length of `idx` at `begin`, which only grows until `clear`
            // empties both.
            debug_assert!(p.first <= given);
            p.count = given.wrapping_sub(p.first);
            if p.count == 0 {
                self.prims.pop();
            }
        }
    }

    /// Records the materials in effect at Begin (before any change inside the pair). Only the
    /// batch's first Begin needs recording: a Material call outside Begin/End flushes the batch,
    /// so every later Begin of the same batch starts with the same materials, or with the last
    /// snapshot if a change happened inside an earlier pair. (COLOR_MATERIAL updates of the
    /// state between Begins touch only the tracked property, which each vertex's colour
    /// replaces anyway.)
    pub fn note_materials(&mut self, m: &[Material; 2]) {
        if self.prims.len() <= 1 && self.snapshots.is_empty() {
            self.base = Some(*m);
        }
    }

    /// `Material` inside Begin/End: vertices from now on use `m`.
    pub fn materials_changed(&mut self, m: &[Material; 2]) {
        if self.snapshots.is_empty() {
            // Vertices so far (all with index 0) keep the materials current at Begin.
            self.snapshots.push(self.base.unwrap_or(*m));
            self.mat.clear();
            self.mat.resize(self.pos.len(), 0);
        }
        if self.snapshots.len() >= u32::MAX as usize {
            return;
        }
        self.snapshots.push(*m);
        self.cur_mat = (self.snapshots.len() - 1) as u32;
        // A new index, not the span's: the next vertex compares its span's inputs and material.
        self.span_in.forget_stamp();
    }

    /// Empties the batch, keeping capacity (the front end flushes only outside Begin/End).
    pub fn clear(&mut self) {
        self.serial0 += self.pos.len() as u64;
        if self.serial0 >= SERIAL_RESET {
            self.cache.fill(Set([EMPTY; 2]));
            self.serial0 = 0;
        }
        self.span = self.serial0;
        self.idx.clear();
        self.pos.clear();
        self.normal.clear();
        self.span_of.clear();
        // The current span carries over as span 0 (with `span_in` and `span_mat`).
        if let Some(cur) = self.spans.pop() {
            self.spans.clear();
            self.spans.push(cur);
        }
        self.edge.clear();
        self.mat.clear();
        self.prims.clear();
        if !self.snapshots.is_empty() {
            self.base = self.snapshots.last().copied();
        }
        self.snapshots.clear();
        self.cur_mat = 0;
        if self.span_mat != self.cur_mat {
            self.span_in.forget_stamp();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl;

    /// Indices given to `vertices` (position, colour red) in one triangle list.
    fn indices(b: &mut Batch, vertices: &[(f32, f32)]) -> Vec<u32> {
        b.begin(gl::TRIANGLES);
        let mut c = Current::default();
        for &(x, red) in vertices {
            c.inputs_mut().color.x = red;
            b.vertex(Vec4::new(x, 0.0, 0.0, 1.0), &c);
        }
        b.end();
        b.idx.clone()
    }

    /// The inputs a span shares, as bits (the reference for `Inputs::same_bits`): 25 floats and
    /// the edge flag.
    fn span_bits(c: &Current) -> Vec<u32> {
        let t = c.tex_coords;
        let mut v: Vec<u32> = [c.color, c.secondary_color, t[0], t[1], t[2], t[3]]
            .iter()
            .flat_map(|x| x.to_array().map(f32::to_bits))
            .collect();
        v.push(c.fog_coord.to_bits());
        v.push(u32::from(c.edge_flag));
        v
    }

    #[test]
    fn same_bits_is_equal_bits_of_the_span_inputs() {
        let mut g = crate::cpu::testgen::Gen(5);
        let (mut same, mut differ) = (0, 0);
        for _ in 0..20_000 {
            // 25 floats, the edge flag, and a normal and index that must not count.
            let mut f = [0f32; 30];
            for x in &mut f {
                *x = g.float();
            }
            let mut edge = g.next() % 2 == 0;
            let make = |f: &[f32; 30], edge: bool| {
                let v4 = |i: usize| Vec4::new(f[i], f[i + 1], f[i + 2], f[i + 3]);
                Current::new(
                    Inputs {
                        color: v4(0),
                        secondary_color: v4(4),
                        tex_coords: [v4(8), v4(12), v4(16), v4(20)],
                        fog_coord: f[24],
                        edge_flag: edge,
                    },
                    Vec3::new(f[25], f[26], f[27]),
                    f[28],
                )
            };
            let a = make(&f, edge);
            assert!(a.same_bits(&a) == (span_bits(&a) == span_bits(&a)));
            // One input changed (now and then to the same bits, or -0 for 0, NaN for NaN).
            let k = (g.next() % 30) as usize;
            if k == 29 {
                edge ^= g.next() % 2 == 0;
            } else {
                f[k] = match g.next() % 4 {
                    0 => f[k],
                    1 => -f[k],
                    _ => g.float(),
                };
            }
            let b = make(&f, edge);
            let want = span_bits(&a) == span_bits(&b);
            assert_eq!(a.same_bits(&b), want, "input {k}");
            assert_eq!(b.same_bits(&a), want, "input {k}");
            if want {
                same += 1;
            } else {
                differ += 1;
            }
        }
        assert!(same > 1000 && differ > 1000, "{same} same, {differ} differ");
    }

    /// The indices of the vertices at the origin given before and after `write` (inside one
    /// POINTS pair, unless `write` ends it), and the attributes and edge flag of the last
    /// unique vertex batched.
    fn around(write: impl FnOnce(&mut crate::Context)) -> (Vec<u32>, Attribs, bool) {
        let mut c = crate::Context::new(4, 4).unwrap_or_else(|e| panic!("{e}"));
        // A colour array alone, for ArrayElement (set up outside the pair, with no effect on
        // the other writers).
        let v = [0.5f32, 0.25, 0.125, 1.0];
        c.color_pointer(4, gl::FLOAT, 0, &v);
        c.enable_client_state(gl::COLOR_ARRAY);
        c.begin(gl::POINTS);
        c.vertex3f(0.0, 0.0, 0.0);
        write(&mut c);
        if !c.inside_begin_end() {
            c.begin(gl::POINTS);
        }
        c.vertex3f(0.0, 0.0, 0.0);
        c.end();
        let b = &c.renderer.batch;
        let last = b.len() - 1;
        let (attribs, edge) = (b.attribs(last).copied(), b.edge.get(last).copied());
        (
            b.idx.clone(),
            attribs.expect("a span"),
            edge.expect("an edge flag"),
        )
    }

    #[test]
    fn every_writer_of_the_span_inputs_starts_a_span() {
        let v = Vec4::new(0.5, 0.25, 0.125, 1.0);
        // Inside Begin/End: the vertex after the write is a new one, with the new value.
        type Write = fn(&mut crate::Context);
        type Check = fn(&Attribs, bool) -> bool;
        let inside: [(&str, Write, Check); 7] = [
            (
                "Color",
                |c| c.color4f(0.5, 0.25, 0.125, 1.0),
                |a, _| a.color == Vec4::new(0.5, 0.25, 0.125, 1.0),
            ),
            (
                "SecondaryColor",
                |c| c.secondary_color3f(0.5, 0.25, 0.125),
                |a, _| a.color2 == Vec4::new(0.5, 0.25, 0.125, 1.0),
            ),
            (
                "TexCoord",
                |c| c.tex_coord2f(0.5, 0.25),
                |a, _| a.tex[0] == Vec4::new(0.5, 0.25, 0.0, 1.0),
            ),
            (
                "MultiTexCoord",
                |c| c.multi_tex_coord2f(gl::TEXTURE2, 0.5, 0.25),
                |a, _| a.tex[2] == Vec4::new(0.5, 0.25, 0.0, 1.0),
            ),
            ("FogCoord", |c| c.fog_coordf(0.5), |a, _| a.fog == 0.5),
            ("EdgeFlag", |c| c.edge_flag(false), |_, e| !e),
            (
                "ArrayElement",
                |c| c.array_element(0),
                |a, _| a.color == Vec4::new(0.5, 0.25, 0.125, 1.0),
            ),
        ];
        for (name, write, check) in inside {
            let (idx, a, e) = around(write);
            assert_eq!(idx, [0, 1], "{name}");
            assert!(check(&a, e), "{name}: {a:?} {e}");
        }
        // An evaluator's vertex at the origin with its own colour.
        let (idx, a, _) = around(|c| {
            c.end();
            c.map1f(gl::MAP1_VERTEX_3, 0.0, 1.0, 3, 1, &[0.0; 3]);
            c.map1f(gl::MAP1_COLOR_4, 0.0, 1.0, 4, 1, &v.to_array());
            c.enable(gl::MAP1_VERTEX_3);
            c.enable(gl::MAP1_COLOR_4);
            c.begin(gl::POINTS);
            c.eval_coord1f(0.5);
        });
        // (Map1 and Enable flush: the evaluator's vertex is the new batch's 0, and the last, 1,
        // has the current colour again.)
        assert_eq!(idx, [0, 1], "EvalCoord");
        assert_eq!(a.color, Vec4::ONE, "EvalCoord");
        // PopAttrib (a flush between): the restored colour, whose stamp is older than the
        // span's.
        let (_, a, _) = around(|c| {
            c.end();
            c.color4f(0.5, 0.25, 0.125, 1.0);
            c.push_attrib(gl::CURRENT_BIT);
            c.color4f(0.0, 1.0, 0.0, 1.0);
            c.begin(gl::POINTS);
            c.vertex3f(1.0, 0.0, 0.0);
            c.end();
            c.pop_attrib();
        });
        assert_eq!(a.color, v, "PopAttrib");
        // A write of the value already there: the vertex is shared, as when only the inputs
        // were compared.
        let (idx, ..) = around(|c| c.color4f(1.0, 1.0, 1.0, 1.0));
        assert_eq!(idx, [0, 0]);
    }

    #[test]
    fn values_written_on_two_threads_never_share_a_stamp() {
        // Each thread's first write: a scheme counting per thread from the same start would
        // give both the same stamp, and the batch would take the second's inputs for the
        // first's.
        let write = |red: f32| {
            std::thread::spawn(move || {
                let mut c = Current::default();
                c.inputs_mut().color.x = red;
                c
            })
            .join()
            .unwrap_or_else(|_| panic!("thread"))
        };
        let (mut a, b) = (write(0.25), write(0.5));
        assert!(!a.same_inputs_as(&b));
        // The same inputs with another stamp: the same, and from then on at once.
        let mut c = b;
        c.inputs_mut().color.x = 0.5;
        assert!(c.same_inputs_as(&b));
        let d = a;
        assert!(a.same_inputs_as(&d));
    }

    #[test]
    fn a_vertex_is_shared_only_when_every_input_is_the_same() {
        let mut b = Batch::default();
        // Positions 0, 1, 0 (same colour: shared), then 0 with another colour (new), then 1
        // with that colour (new: its twin has the old colour), then -0 (differs from 0 in bits).
        let idx = indices(
            &mut b,
            &[
                (0.0, 1.0),
                (1.0, 1.0),
                (0.0, 1.0),
                (0.0, 0.5),
                (1.0, 0.5),
                (-0.0, 0.5),
            ],
        );
        assert_eq!(idx, [0, 1, 0, 2, 3, 4]);
        assert_eq!(b.len(), 5);
        // Back to the first colour: a new span, so vertex 0 is not reused (a copy is exact).
        b.begin(gl::TRIANGLES);
        let c = Current::default();
        b.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0), &c);
        b.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0), &c);
        assert_eq!(b.idx[6..], [5, 5]);
    }

    #[test]
    fn each_vertex_has_the_inputs_current_at_its_call() {
        let mut b = Batch::default();
        b.begin(gl::POINTS);
        // Every input zero: the batch's initial span, whose values must be the zeros too.
        let mut c = Current::default();
        *c.inputs_mut() = Inputs {
            color: Vec4::ZERO,
            secondary_color: Vec4::ZERO,
            tex_coords: [Vec4::ZERO; crate::state::MAX_TEXTURE_UNITS],
            fog_coord: 0.0,
            edge_flag: false,
        };
        b.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0), &c);
        c.inputs_mut().tex_coords[0] = Vec4::new(0.25, 0.5, 0.0, 1.0);
        b.vertex(Vec4::new(1.0, 0.0, 0.0, 1.0), &c);
        c.inputs_mut().color = Vec4::new(0.5, 0.0, 0.0, 1.0);
        c.inputs_mut().fog_coord = 2.0;
        b.vertex(Vec4::new(2.0, 0.0, 0.0, 1.0), &c);
        b.vertex(Vec4::new(3.0, 0.0, 0.0, 1.0), &c);
        b.end();
        let got = |b: &Batch, i| {
            b.attribs(i)
                .map(|a| (a.color, a.color2, a.tex[0], a.tex[1], a.fog))
        };
        let z = Vec4::ZERO;
        let t = Vec4::new(0.25, 0.5, 0.0, 1.0);
        let red = Vec4::new(0.5, 0.0, 0.0, 1.0);
        assert_eq!(got(&b, 0), Some((z, z, z, z, 0.0)));
        assert_eq!(got(&b, 1), Some((z, z, t, z, 0.0)));
        assert_eq!(got(&b, 2), Some((red, z, t, z, 2.0)));
        assert_eq!(got(&b, 3), Some((red, z, t, z, 2.0)));
        assert_eq!(b.attribs(4), None);
        // The next batch starts with the same inputs: they still read back.
        b.clear();
        b.begin(gl::POINTS);
        b.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0), &c);
        b.end();
        assert_eq!(got(&b, 0), Some((red, z, t, z, 2.0)));
    }

    /// Positions (x, 0, 0, 1) with the default normal, from x = 1 on, that fall in the same
    /// cache set as x = 0.
    fn colliding(n: usize) -> Vec<f32> {
        let key = |x: f32| Key::of(&Vec4::new(x, 0.0, 0.0, 1.0), &Vec3::new(0.0, 0.0, 1.0)).set();
        (1..1_000_000)
            .map(|x| x as f32)
            .filter(|&x| key(x) == key(0.0))
            .take(n)
            .collect()
    }

    #[test]
    fn two_vertices_of_one_set_are_both_kept_and_a_third_evicts_the_older() {
        let c = colliding(2);
        let (b1, b2) = (c[0], c[1]);
        let mut b = Batch::default();
        // 0 and b1 share a set: both stay, so 0 is found again.
        assert_eq!(
            indices(&mut b, &[(0.0, 1.0), (b1, 1.0), (0.0, 1.0), (b1, 1.0)]),
            [0, 1, 0, 1]
        );
        // b2 evicts 0 (the older): b1 is still found, 0 is stored again (an exact copy).
        b.begin(gl::TRIANGLES);
        let mut cur = Current::default();
        cur.inputs_mut().color.x = 1.0;
        for x in [b2, b1, 0.0] {
            b.vertex(Vec4::new(x, 0.0, 0.0, 1.0), &cur);
        }
        b.end();
        assert_eq!(b.idx[4..], [2, 1, 3]);
        assert_eq!(b.pos[3], Vec4::new(0.0, 0.0, 0.0, 1.0));
    }

    #[test]
    fn serial_numbers_start_again_without_false_hits() {
        let mut b = Batch::default();
        // 6.0 is cached with serial 1.
        assert_eq!(indices(&mut b, &[(5.0, 1.0), (6.0, 1.0)]), [0, 1]);
        b.clear();
        // Many batches later (none touching 6.0's set), the serials pass SERIAL_RESET.
        b.serial0 = SERIAL_RESET;
        b.clear();
        assert_eq!(b.serial0, 0);
        // Serial 1 is now 8.0: the old slot of 6.0 must not send 6.0 to it.
        assert_eq!(
            indices(&mut b, &[(7.0, 1.0), (8.0, 1.0), (6.0, 1.0)]),
            [0, 1, 2]
        );
        assert_eq!(b.pos[2], Vec4::new(6.0, 0.0, 0.0, 1.0));
    }

    #[test]
    fn the_key_holds_the_bits_it_was_made_of() {
        let mut g = crate::cpu::testgen::Gen(3);
        for _ in 0..10_000 {
            let p = [
                g.next() as u32,
                g.next() as u32,
                g.next() as u32,
                g.next() as u32,
            ];
            let n = [g.next() as u32, g.next() as u32, g.next() as u32];
            let k = Key::new(p, NormalBits::new(n));
            assert_eq!(k.position().to_array().map(f32::to_bits), p);
            assert_eq!(k.normal.vec3().to_array().map(f32::to_bits), n);
            assert!(k.same(Key::of(&k.position(), &k.normal.vec3())));
            // The position's words taken whole from its vector: the same key.
            let at = Key::at(k.position(), k.normal);
            assert_eq!((at.xy, at.zw), (k.xy, k.zw));
            let same = |k: Key, l: Key| {
                same_vertex(&k.position(), &k.normal.vec3(), l.position(), l.normal)
            };
            assert!(same(k, k));
            // One bit changed anywhere: another key.
            let bit = (g.next() % 224) as usize;
            let (mut p2, mut n2) = (p, n);
            if bit < 128 {
                p2[bit / 32] ^= 1 << (bit % 32);
            } else {
                n2[(bit - 128) / 32] ^= 1 << (bit % 32);
            }
            let other = Key::new(p2, NormalBits::new(n2));
            assert!(!k.same(other), "bit {bit}");
            // The hit test's compare: the key's, bit for bit.
            assert!(!same(k, other) && !same(other, k), "bit {bit}");
        }
    }

    /// Random vertex streams over a few positions, normals (-0 and NaNs among them) and
    /// colours, with batches cleared between and the serials passing `SERIAL_RESET`: every
    /// vertex given reads back from the batch with its own bits, and a shared vertex is one of
    /// the current span (the hit test reads the arrays without testing their lengths, so a
    /// wrong index there would read another vertex, or past the arrays).
    #[test]
    fn every_vertex_reads_back_its_own_inputs() {
        let mut g = crate::cpu::testgen::Gen(11);
        let mut b = Batch::default();
        let values = [0.0, -0.0, 1.0, 0.5, f32::NAN, -f32::NAN, 2.0];
        let mut shared = 0;
        for round in 0..400 {
            if round % 50 == 49 {
                // The serials start again after this batch (the span starting with it, as
                // `clear` leaves it: the hit test relies on `serial0 <= span`).
                b.serial0 = SERIAL_RESET - (g.next() % 64);
                b.span = b.serial0;
            }
            let mut c = Current::default();
            let mut given = Vec::new();
            let mut span_start = b.len();
            for _ in 0..(g.next() % 8) {
                b.begin(gl::TRIANGLES);
                for _ in 0..(g.next() % 40) {
                    let pick = |g: &mut crate::cpu::testgen::Gen| {
                        values[(g.next() % values.len() as u64) as usize]
                    };
                    if g.next() % 16 == 0 {
                        let red = pick(&mut g);
                        if red.to_bits() != c.color.x.to_bits() {
                            // A new span starts at the next vertex.
                            span_start = usize::MAX;
                        }
                        c.inputs_mut().color.x = red;
                    }
                    // A few positions and normals, each from a few values: vertices repeat.
                    let mut seeded = crate::cpu::testgen::Gen(g.next() % 12);
                    let p = Vec4::new(pick(&mut seeded), pick(&mut seeded), pick(&mut g), 1.0);
                    c.normal = Vec3::new(pick(&mut seeded), pick(&mut seeded), pick(&mut seeded));
                    let before = b.len();
                    b.vertex(p, &c);
                    if span_start == usize::MAX && b.len() > before {
                        span_start = before;
                    }
                    let k = b.idx.last().copied().unwrap_or(u32::MAX) as usize;
                    if k < before {
                        shared += 1;
                        assert!(k >= span_start.min(before), "{k} before span {span_start}");
                    }
                    given.push((p, c.normal, c.color.x));
                }
                b.end();
            }
            let bits4 = |v: Vec4| v.to_array().map(f32::to_bits);
            let bits3 = |v: Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(b.idx.len(), given.len());
            assert_eq!(b.normal.len(), b.len());
            for (&k, &(p, n, red)) in b.idx.iter().zip(&given) {
                let k = k as usize;
                assert_eq!(bits4(b.pos[k]), bits4(p));
                assert_eq!(bits3(b.normal[k]), bits3(n));
                let a = b.attribs(k).map(|a| a.color.x.to_bits());
                assert_eq!(a, Some(red.to_bits()));
            }
            b.clear();
        }
        assert!(shared > 1000, "{shared} shared");
    }

    /// Random streams of vertices over a few positions and normals, with colour, edge flag
    /// and in-pair `Material` changes, batches cleared between them: the batch written
    /// within `room` (its arrays starting from capacities of their own, so that `room` is
    /// every one's in turn, and grown as they fill) is bit for bit the batch written by pushes
    /// alone (`room` held at 0); and every vertex given reads back with its own position,
    /// normal, colour, edge flag and material, so a vertex is never shared across a material
    /// change (which `check_span` sees only through the forgotten stamp).
    #[test]
    fn a_batch_written_within_its_room_is_the_batch_pushed() {
        let mut g = crate::cpu::testgen::Gen(29);
        let (mut fast, mut slow) = (Batch::default(), Batch::default());
        let values = [0.0, -0.0, 1.0, 0.5, f32::NAN];
        let mut m = [Material::default(); 2];
        let mut mat = m[0].diffuse.x.to_bits();
        let (mut shared, mut written) = (0, 0);
        for round in 0..300 {
            if round % 3 == 0 {
                // Capacities of their own (0 to 40) for the four arrays.
                let mut cap = || (g.next() % 41) as usize;
                fast.pos = Vec::with_capacity(cap());
                fast.normal = Vec::with_capacity(cap());
                fast.span_of = Vec::with_capacity(cap());
                fast.edge = Vec::with_capacity(cap());
                fast.room = 0;
            }
            let mut c = Current::default();
            // Per vertex given: position, normal, colour, edge flag and material bits.
            let mut given = Vec::new();
            for _ in 0..(g.next() % 6) {
                fast.begin(gl::TRIANGLE_STRIP);
                slow.begin(gl::TRIANGLE_STRIP);
                fast.note_materials(&m);
                slow.note_materials(&m);
                for _ in 0..(g.next() % 60) {
                    let change = g.next() % 32;
                    let mut pick = || values[(g.next() % values.len() as u64) as usize];
                    match change {
                        0 => c.inputs_mut().color.y = pick(),
                        1 => c.inputs_mut().edge_flag ^= true,
                        2 => {
                            m[0].diffuse.x = pick();
                            fast.materials_changed(&m);
                            slow.materials_changed(&m);
                            mat = m[0].diffuse.x.to_bits();
                        }
                        _ => {}
                    }
                    let mut seeded = crate::cpu::testgen::Gen(g.next() % 10);
                    let mut pick = || values[(seeded.next() % values.len() as u64) as usize];
                    let p = Vec4::new(pick(), pick(), pick(), 1.0);
                    c.normal = Vec3::new(pick(), pick(), pick());
                    let (before, room) = (fast.len(), fast.room);
                    fast.vertex(p, &c);
                    slow.room = 0;
                    slow.vertex(p, &c);
                    written += usize::from(fast.len() > before && before < room);
                    given.push((p, c.normal, c.color.y, c.edge_flag, mat));
                }
                fast.end();
                slow.end();
            }
            let bits4 = |v: &Vec4| v.to_array().map(f32::to_bits);
            let bits3 = |v: &Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(fast.idx, slow.idx);
            assert_eq!(fast.prims, slow.prims);
            assert_eq!(fast.span_of, slow.span_of);
            assert_eq!(fast.edge, slow.edge);
            assert_eq!(fast.mat, slow.mat);
            let (fp, sp) = (fast.pos.iter(), slow.pos.iter());
            assert!(fp.map(bits4).eq(sp.map(bits4)));
            let (fn_, sn) = (fast.normal.iter(), slow.normal.iter());
            assert!(fn_.map(bits3).eq(sn.map(bits3)));
            let spans = |b: &Batch| b.spans.iter().map(|a| bits4(&a.color)).collect::<Vec<_>>();
            assert_eq!(spans(&fast), spans(&slow));
            let caps = [
                fast.pos.capacity(),
                fast.normal.capacity(),
                fast.span_of.capacity(),
                fast.edge.capacity(),
            ];
            assert!(
                caps.iter().all(|&c| fast.room <= c),
                "{} {caps:?}",
                fast.room
            );
            assert_eq!(fast.idx.len(), given.len());
            for (&k, &(p, n, green, edge, mat)) in fast.idx.iter().zip(&given) {
                let k = k as usize;
                shared += usize::from(fast.idx.iter().filter(|&&i| i as usize == k).count() > 1);
                assert_eq!(bits4(&fast.pos[k]), bits4(&p));
                assert_eq!(bits3(&fast.normal[k]), bits3(&n));
                let a = fast.attribs(k).map(|a| a.color.y.to_bits());
                assert_eq!(a, Some(green.to_bits()));
                assert_eq!(fast.edge[k], edge);
                // The vertex's material: the snapshot it indexes, once the batch has any
                // (until then every vertex has the materials current at Begin, unchanged).
                if !fast.snapshots.is_empty() {
                    let snapshot = fast
                        .mat
                        .get(k)
                        .and_then(|&i| fast.snapshots.get(i as usize));
                    assert_eq!(snapshot.map(|s| s[0].diffuse.x.to_bits()), Some(mat), "{k}");
                }
            }
            fast.clear();
            slow.clear();
        }
        assert!(
            shared > 1000 && written > 1000,
            "{shared} shared, {written} written"
        );
    }

    #[test]
    fn nothing_is_shared_with_an_earlier_batch() {
        let mut b = Batch::default();
        assert_eq!(indices(&mut b, &[(3.0, 1.0), (4.0, 1.0)]), [0, 1]);
        b.clear();
        // Vertex 0 of the new batch is 4.0; 3.0's slot (index 0 before) must not be a hit.
        assert_eq!(
            indices(&mut b, &[(4.0, 1.0), (3.0, 1.0), (4.0, 1.0)]),
            [0, 1, 0]
        );
        assert_eq!(b.pos.len(), 2);
        assert_eq!(b.pos[1], Vec4::new(3.0, 0.0, 0.0, 1.0));
    }
}
