//! The vertex batch: every vertex given since the last flush, with its attributes, in flat
//! structure-of-arrays form, plus the list of primitives (Begin/End pairs) over it.
//!
//! GL 2.1 §2.6–2.7: a vertex takes the current normal, colours, texture coordinates and edge
//! flag at the moment `Vertex` is called. Design decision: a vertex identical in every input to
//! one already batched (found through a small direct-mapped cache, compared bit for bit) is
//! stored once and referenced by index, so the vertex stage lights it once: immediate-mode
//! meshes such as one strip per grid cell send each vertex up to four times, and the vertex
//! stage is a pure function of these inputs, so the result is exactly the same. The arrays are
//! cleared, not freed, at each flush, so steady-state drawing allocates nothing per vertex;
//! `Material` changes inside Begin/End (§2.14.3) are rare, so they are stored as whole snapshots
//! that vertices index.

use glam::{Vec3, Vec4};

use crate::state::{Current, Material};

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

/// Entries in the vertex cache (a power of two).
const CACHE: usize = 1 << 13;

/// The batched vertices (object coordinates and current attributes) and primitives.
#[derive(Debug)]
pub struct Batch {
    /// Per vertex given, the index of its (unique) vertex in the attribute arrays.
    pub idx: Vec<u32>,
    /// Direct-mapped cache: input hash → a vertex index (validated on use).
    cache: Box<[u32; CACHE]>,
    /// Object-coordinate positions.
    pub pos: Vec<Vec4>,
    /// Current normal at each vertex.
    pub normal: Vec<Vec3>,
    /// Current (primary) colour.
    pub color: Vec<Vec4>,
    /// Current secondary colour.
    pub color2: Vec<Vec4>,
    /// Texture coordinates of unit 0.
    pub tex: Vec<Vec4>,
    // --- texture: unit 1's coordinates (multitexture)
    /// Texture coordinates of unit 1.
    pub tex1: Vec<Vec4>,
    // --- end texture
    /// Edge flag.
    pub edge: Vec<bool>,
    /// Index into `snapshots`; meaningful only when `snapshots` is not empty.
    pub mat: Vec<u32>,
    // --- fragment ops
    /// Current fog coordinate (FOG_COORD_SRC = FOG_COORD, §3.10).
    pub fog: Vec<f32>,
    // --- end fragment ops
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
            cache: Box::new([u32::MAX; CACHE]),
            pos: Vec::new(),
            normal: Vec::new(),
            color: Vec::new(),
            color2: Vec::new(),
            tex: Vec::new(),
            tex1: Vec::new(),
            edge: Vec::new(),
            mat: Vec::new(),
            fog: Vec::new(), // fragment ops
            prims: Vec::new(),
            snapshots: Vec::new(),
            base: None,
            cur_mat: 0,
        }
    }
}

/// Bitwise equality (NaNs with equal bits are equal, -0 and 0 differ): identical inputs.
#[inline(always)]
fn same4(a: Vec4, b: Vec4) -> bool {
    a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits)
}

impl Batch {
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

    /// Appends a vertex with the current attributes to the open primitive.
    #[inline]
    pub fn vertex(&mut self, position: Vec4, c: &Current) {
        let Some(p) = self.prims.last_mut() else {
            return;
        };
        p.count += 1;
        // Hash position and normal (the attributes that vary across a mesh); a hit is then
        // compared in full.
        let bits = |v: f32| u64::from(v.to_bits());
        let h = (bits(position.x) | bits(position.y) << 32)
            ^ (bits(position.z) | bits(c.normal.x) << 32).rotate_left(17)
            ^ (bits(c.normal.y) | bits(c.normal.z) << 32).rotate_left(41);
        let slot = (h.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 51) as usize & (CACHE - 1);
        let hit = self.cache[slot] as usize;
        if hit < self.pos.len()
            && same4(self.pos[hit], position)
            && self.normal[hit].to_array().map(f32::to_bits)
                == c.normal.to_array().map(f32::to_bits)
            && same4(self.color[hit], c.color)
            && same4(self.color2[hit], c.secondary_color)
            && same4(self.tex[hit], c.tex_coords[0])
            && same4(self.tex1[hit], c.tex_coords[1])
            && self.edge[hit] == c.edge_flag
            && self.mat[hit] == self.cur_mat
            && self.fog[hit].to_bits() == c.fog_coord.to_bits()
        // fragment ops
        {
            self.idx.push(hit as u32);
            return;
        }
        let i = self.pos.len();
        self.cache[slot] = i as u32;
        self.idx.push(i as u32);
        self.pos.push(position);
        self.normal.push(c.normal);
        self.color.push(c.color);
        self.color2.push(c.secondary_color);
        self.tex.push(c.tex_coords[0]);
        self.tex1.push(c.tex_coords[1]);
        self.edge.push(c.edge_flag);
        self.mat.push(self.cur_mat);
        self.fog.push(c.fog_coord); // fragment ops
    }

    /// Closes the open primitive; an empty one is dropped.
    pub fn end(&mut self) {
        if self.prims.last().is_some_and(|p| p.count == 0) {
            self.prims.pop();
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
        }
        if self.snapshots.len() >= u32::MAX as usize {
            return;
        }
        self.snapshots.push(*m);
        self.cur_mat = (self.snapshots.len() - 1) as u32;
    }

    /// Empties the batch, keeping capacity (the front end flushes only outside Begin/End).
    pub fn clear(&mut self) {
        self.idx.clear();
        self.pos.clear();
        self.normal.clear();
        self.color.clear();
        self.color2.clear();
        self.tex.clear();
        self.tex1.clear();
        self.edge.clear();
        self.mat.clear();
        self.fog.clear(); // fragment ops
        self.prims.clear();
        if !self.snapshots.is_empty() {
            self.base = self.snapshots.last().copied();
        }
        self.snapshots.clear();
        self.cur_mat = 0;
    }
}
