//! Vertex arrays and buffer objects as plain data with their validation (GL 2.1 §2.8, §2.9).
//!
//! [`ArrayState`] holds the client array pointers (VertexPointer ... EdgeFlagPointer, per
//! texture unit for TexCoordPointer), the client-state enables, the ARRAY_BUFFER and
//! ELEMENT_ARRAY_BUFFER bindings and the buffer objects with their contents. Every command is a
//! method that validates first and returns the GL error code or changes the state, so the CPU
//! front end (`Context`) and the GL backend's shadow copy (which must refuse the same draws before
//! the driver reads memory) share one implementation.
//!
//! Design decision: a pointer is a [`Pointer`]: either bytes the caller handed over
//! ([`Pointer::Data`], copied at the `*Pointer` call, since a Rust borrow cannot outlive the call)
//! or a byte offset into the buffer object bound to ARRAY_BUFFER ([`Pointer::Offset`], GL 1.5's
//! reading of the pointer argument). A recorded `*Pointer` call therefore carries its bytes, and
//! the stream replays on its own. GL reads out of bounds where a draw indexes past the data; here
//! a draw whose indices would read past the bytes an enabled array actually has (client bytes,
//! or the bound buffer's size past the offset) is INVALID_OPERATION and draws nothing, as is a
//! client pointer given while a buffer is bound (GL would take it as an offset) and a
//! DrawElements whose index data is too short. Nothing allocates more than the caller supplied,
//! except `BufferData` with no data, which is capped at [`MAX_BUFFER_SIZE`] (OUT_OF_MEMORY past it).
//!
//! Seed 004's VBO/EBO code ports line by line:
//!
//! ```
//! use fixedgl::{gl, Context, Pointer};
//! let mut ctx = Context::new(64, 64)?;
//! let vertices: [f32; 8] = [0.5, 0.5, 0.5, -0.5, -0.5, -0.5, -0.5, 0.5];
//! let indices: [u8; 6] = [0, 1, 3, 1, 2, 3];
//! let mut vbo = [0];
//! ctx.gen_buffers(1, &mut vbo);
//! ctx.bind_buffer(gl::ARRAY_BUFFER, vbo[0]);
//! ctx.buffer_data(gl::ARRAY_BUFFER, 32, &vertices, gl::STATIC_DRAW);
//! let mut ebo = [0];
//! ctx.gen_buffers(1, &mut ebo);
//! ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, ebo[0]);
//! ctx.buffer_data(gl::ELEMENT_ARRAY_BUFFER, 6, &indices, gl::STATIC_DRAW);
//! ctx.vertex_pointer(2, gl::FLOAT, 2 * 4, Pointer::NULL); // offset None
//! ctx.enable_client_state(gl::VERTEX_ARRAY);
//! ctx.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
//! ctx.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_BYTE, Pointer::NULL);
//! assert_eq!(ctx.get_error(), gl::NO_ERROR);
//! // Without buffers, the same arrays as client memory (copied at the call):
//! ctx.bind_buffer(gl::ARRAY_BUFFER, 0);
//! ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, 0);
//! ctx.vertex_pointer(2, gl::FLOAT, 0, &vertices);
//! ctx.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_BYTE, &indices);
//! assert_eq!(ctx.get_error(), gl::NO_ERROR);
//! # Ok::<(), fixedgl::Error>(())
//! ```

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::convert;
use crate::gl;
use crate::state::MAX_TEXTURE_UNITS;
use crate::texture::NameSet;

/// The largest buffer object `BufferData` creates without data (OUT_OF_MEMORY beyond).
pub const MAX_BUFFER_SIZE: usize = 256 << 20;
/// `MAX_ELEMENTS_VERTICES` and `MAX_ELEMENTS_INDICES`: the recommended DrawRangeElements sizes
/// (Mesa's value; larger ones work too).
pub const MAX_ELEMENTS: i32 = 3000;

/// The largest stride a `*Pointer` command accepts (`MAX_VERTEX_ATTRIB_STRIDE`, GL 4.4
/// §10.3.1). GL 2.1 sets no limit; Mesa applies this one to compatibility contexts of version
/// 4.4 and later, so the reference driver refuses larger strides with INVALID_VALUE, and so do we.
pub const MAX_VERTEX_ATTRIB_STRIDE: i32 = 2048;

/// A GL pointer argument: the caller's bytes, or an offset into a bound buffer object.
///
/// Built with `.into()` from a slice, array or `Vec` of any GL component type (copied in native
/// byte order, which is how GL reads client memory), or from a `usize` offset:
/// `ctx.vertex_pointer(2, FLOAT, 0, &vertices)`, `ctx.draw_elements(TRIANGLES, 6, UNSIGNED_BYTE, 0usize)`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Pointer {
    /// Client memory: the bytes GL may read.
    Data(Vec<u8>),
    /// A byte offset into the buffer object bound to the target (or, with none bound, an
    /// address with nothing behind it: a draw that reads it is INVALID_OPERATION).
    Offset(usize),
    /// Memory the caller keeps owning, read when a draw happens rather than copied at the
    /// `*Pointer` call: the C ABI's client arrays (a C program may fill its array after
    /// glVertexPointer). Never part of a recording: a recorded draw is preceded by the
    /// `*Pointer` calls with the bytes it read (see `Context::draw_arrays`), so streams stay
    /// self-contained; serialising one is an error.
    #[serde(skip)]
    Client(Box<ClientPointer>),
}

/// Memory a caller outside Rust owns, read by GL at draw time (see [`Pointer::Client`]).
///
/// The implementor vouches for the reads: a C caller promises, as GL requires, that the memory
/// behind its pointer holds what the draw reads until the draw returns.
pub trait ClientMemory: Send + Sync {
    /// The address, as `GetPointerv` reports it.
    fn address(&self) -> usize;
    /// The first `len` bytes, or fewer (none for a null pointer): a draw that needs more is
    /// INVALID_OPERATION.
    fn read(&self, len: usize) -> &[u8];
}

/// A [`ClientMemory`] with a byte offset into it (InterleavedArrays' parts).
#[derive(Clone)]
pub struct ClientPointer {
    memory: std::sync::Arc<dyn ClientMemory>,
    offset: usize,
}

impl ClientPointer {
    /// A pointer to the start of `memory`.
    pub fn new(memory: std::sync::Arc<dyn ClientMemory>) -> ClientPointer {
        ClientPointer { memory, offset: 0 }
    }

    /// The address GL reports for it.
    pub fn address(&self) -> usize {
        self.memory.address().wrapping_add(self.offset)
    }

    /// The first `len` bytes from the pointer on (fewer where the memory says so).
    pub fn read(&self, len: usize) -> &[u8] {
        let Some(end) = self.offset.checked_add(len) else {
            return &[];
        };
        self.memory.read(end).get(self.offset..).unwrap_or(&[])
    }

    fn offset_by(&self, bytes: usize) -> ClientPointer {
        ClientPointer {
            memory: self.memory.clone(),
            offset: self.offset.saturating_add(bytes),
        }
    }
}

impl PartialEq for ClientPointer {
    fn eq(&self, other: &ClientPointer) -> bool {
        self.address() == other.address()
    }
}

impl Eq for ClientPointer {}

impl std::fmt::Debug for ClientPointer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ClientPointer({:#x})", self.address())
    }
}

impl Pointer {
    /// The null pointer: offset 0 (no data for `BufferData`).
    pub const NULL: Pointer = Pointer::Offset(0);

    /// The pointer as a recording holds it: memory read at draw time ([`Pointer::Client`]) has
    /// no bytes yet and is recorded empty (its `*Pointer` call replays its errors; each draw
    /// that reads it records the bytes it read, see [`crate::Context::draw_arrays`]).
    pub fn recorded(&self) -> Pointer {
        match self {
            Pointer::Client(_) => Pointer::Data(Vec::new()),
            other => other.clone(),
        }
    }

    /// Whether it names client memory (bytes or a [`ClientPointer`]) rather than an offset.
    pub fn is_client(&self) -> bool {
        !matches!(self, Pointer::Offset(_))
    }

    /// The first `len` client bytes (fewer where there are fewer); `None` for an offset.
    pub fn client_bytes(&self, len: usize) -> Option<&[u8]> {
        match self {
            Pointer::Data(d) => Some(d.get(..len).unwrap_or(d)),
            Pointer::Client(c) => Some(c.read(len)),
            Pointer::Offset(_) => None,
        }
    }
}

/// A GL component type that can be handed over as client memory.
pub trait Element: Copy {
    /// Appends the value's bytes in native order.
    fn put(self, out: &mut Vec<u8>);
}

macro_rules! element {
    ($($t:ty),*) => {$(
        impl Element for $t {
            #[inline]
            fn put(self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_ne_bytes());
            }
        }
    )*};
}
element!(u8, i8, u16, i16, u32, i32, f32, f64);

impl Element for bool {
    /// A GLboolean: one byte, 0 or 1.
    #[inline]
    fn put(self, out: &mut Vec<u8>) {
        out.push(u8::from(self));
    }
}

fn bytes_of<T: Element>(v: &[T]) -> Vec<u8> {
    let mut out = Vec::with_capacity(std::mem::size_of_val(v));
    for &x in v {
        x.put(&mut out);
    }
    out
}

impl<T: Element> From<&[T]> for Pointer {
    fn from(v: &[T]) -> Self {
        Pointer::Data(bytes_of(v))
    }
}

impl<T: Element, const N: usize> From<&[T; N]> for Pointer {
    fn from(v: &[T; N]) -> Self {
        Pointer::Data(bytes_of(v))
    }
}

impl<T: Element> From<&Vec<T>> for Pointer {
    fn from(v: &Vec<T>) -> Self {
        Pointer::Data(bytes_of(v))
    }
}

impl From<usize> for Pointer {
    fn from(offset: usize) -> Self {
        Pointer::Offset(offset)
    }
}

/// One client array's state (GL 2.1 tables 6.6 to 6.8).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClientArray {
    /// Enabled by `EnableClientState`.
    pub enabled: bool,
    /// Components per element.
    pub size: i32,
    /// Component type.
    pub ty: u32,
    /// Bytes between elements as given (0: tightly packed).
    pub stride: i32,
    /// `*_ARRAY_BUFFER_BINDING`: the buffer bound to ARRAY_BUFFER at the pointer call.
    pub buffer: u32,
    /// The pointer argument.
    pub pointer: Pointer,
}

impl ClientArray {
    fn new(size: i32) -> Self {
        Self {
            enabled: false,
            size,
            ty: gl::FLOAT,
            stride: 0,
            buffer: 0,
            pointer: Pointer::NULL,
        }
    }
}

/// A buffer object (GL 2.1 table 6.9 of §2.9: BUFFER_SIZE, BUFFER_USAGE, BUFFER_ACCESS,
/// BUFFER_MAPPED) and its data store.
///
/// While the object is mapped (`mapped`), its store is never reallocated: BufferSubData is
/// refused, and the only commands that replace or free the store (BufferData, DeleteBuffers)
/// unmap it first, as GL 2.1 §2.9 says. So the address of `data` stays valid from MapBuffer
/// until the object is unmapped by UnmapBuffer, BufferData or DeleteBuffers (or the context is
/// reset or dropped), which is what a C caller holding MapBuffer's pointer relies on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BufferObject {
    /// The data store (its length is BUFFER_SIZE).
    pub data: Vec<u8>,
    /// `BUFFER_USAGE`.
    pub usage: u32,
    /// `BUFFER_ACCESS`: the access of the mapping; READ_WRITE when not mapped, as llvmpipe
    /// reports it after UnmapBuffer (GL 2.1 table 2.7 sets it at MapBuffer and says nothing of
    /// UnmapBuffer; Mesa derives it from the mapping's flags, which UnmapBuffer clears).
    pub access: u32,
    /// `BUFFER_MAPPED`.
    pub mapped: bool,
}

impl Default for BufferObject {
    fn default() -> Self {
        // GL 2.1 table 2.6: size 0, usage STATIC_DRAW, access READ_WRITE, not mapped.
        Self {
            data: Vec::new(),
            usage: gl::STATIC_DRAW,
            access: gl::READ_WRITE,
            mapped: false,
        }
    }
}

/// Which array an attribute is read from, in ArrayElement's order (GL 2.1 §2.8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attr {
    /// EDGE_FLAG_ARRAY.
    EdgeFlag,
    /// INDEX_ARRAY: colour indices, held and queried but read by no draw in RGBA mode (GL 2.1
    /// §2.8: ArrayElement's Index has no effect without colour-index buffers).
    Index,
    /// TEXTURE_COORD_ARRAY of a texture unit.
    TexCoord(usize),
    /// COLOR_ARRAY.
    Color,
    /// SECONDARY_COLOR_ARRAY.
    SecondaryColor,
    /// FOG_COORD_ARRAY.
    FogCoord,
    /// NORMAL_ARRAY.
    Normal,
    /// VERTEX_ARRAY.
    Vertex,
}

/// The vertex array state and the buffer objects.
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub struct ArrayState {
    pub vertex: ClientArray,
    pub normal: ClientArray,
    pub color: ClientArray,
    pub secondary_color: ClientArray,
    pub fog_coord: ClientArray,
    pub edge_flag: ClientArray,
    pub index: ClientArray,
    pub tex_coords: [ClientArray; MAX_TEXTURE_UNITS],
    /// `ARRAY_BUFFER_BINDING`.
    pub array_buffer: u32,
    /// `ELEMENT_ARRAY_BUFFER_BINDING`.
    pub element_array_buffer: u32,
    /// Buffer objects that exist (bound at least once), by name.
    pub buffers: BTreeMap<u32, BufferObject>,
    /// Names returned by GenBuffers that are not yet bound (GL 2.1 §2.9: not yet objects), as
    /// runs: a name only generated costs nothing of its own.
    pub reserved: NameSet,
}

impl Default for ArrayState {
    /// GL 2.1 tables 6.6 to 6.8: every array disabled, size 4 (secondary colour 3; normals,
    /// fog and edge flags have none), type FLOAT, stride 0, pointer 0, no buffer bound.
    fn default() -> Self {
        let mut normal = ClientArray::new(3);
        normal.ty = gl::FLOAT;
        let mut edge = ClientArray::new(1);
        edge.ty = gl::UNSIGNED_BYTE;
        Self {
            vertex: ClientArray::new(4),
            normal,
            color: ClientArray::new(4),
            secondary_color: ClientArray::new(3),
            fog_coord: ClientArray::new(1),
            edge_flag: edge,
            index: ClientArray::new(1),
            tex_coords: std::array::from_fn(|_| ClientArray::new(4)),
            array_buffer: 0,
            element_array_buffer: 0,
            buffers: BTreeMap::new(),
            reserved: NameSet::default(),
        }
    }
}

/// A GL error code.
pub type GlResult<T> = Result<T, u32>;

/// Bytes of one component of `ty`, for the types arrays accept.
pub(crate) fn type_size(ty: u32) -> usize {
    match ty {
        gl::BYTE | gl::UNSIGNED_BYTE => 1,
        gl::SHORT | gl::UNSIGNED_SHORT => 2,
        gl::DOUBLE => 8,
        _ => 4,
    }
}

/// The checks of GL 2.1 §2.8 for a `*Pointer` call: the accepted sizes and types per array
/// (INVALID_VALUE for a stride outside 0 to [`MAX_VERTEX_ATTRIB_STRIDE`], then INVALID_ENUM for
/// a type, then INVALID_VALUE for a size: Mesa's order).
fn check_format(attr: Attr, size: i32, ty: u32, stride: i32) -> GlResult<()> {
    use gl::{BYTE, DOUBLE, FLOAT, INT, SHORT, UNSIGNED_BYTE, UNSIGNED_INT, UNSIGNED_SHORT};
    let (sizes, types): (&[i32], &[u32]) = match attr {
        Attr::Vertex => (&[2, 3, 4], &[SHORT, INT, FLOAT, DOUBLE]),
        Attr::Normal => (&[3], &[BYTE, SHORT, INT, FLOAT, DOUBLE]),
        Attr::Color => (
            &[3, 4],
            &[
                BYTE,
                UNSIGNED_BYTE,
                SHORT,
                UNSIGNED_SHORT,
                INT,
                UNSIGNED_INT,
                FLOAT,
                DOUBLE,
            ],
        ),
        Attr::SecondaryColor => (
            &[3],
            &[
                BYTE,
                UNSIGNED_BYTE,
                SHORT,
                UNSIGNED_SHORT,
                INT,
                UNSIGNED_INT,
                FLOAT,
                DOUBLE,
            ],
        ),
        Attr::TexCoord(_) => (&[1, 2, 3, 4], &[SHORT, INT, FLOAT, DOUBLE]),
        Attr::FogCoord => (&[1], &[FLOAT, DOUBLE]),
        Attr::EdgeFlag => (&[1], &[UNSIGNED_BYTE]),
        Attr::Index => (&[1], &[UNSIGNED_BYTE, SHORT, INT, FLOAT, DOUBLE]),
    };
    if !(0..=MAX_VERTEX_ATTRIB_STRIDE).contains(&stride) {
        return Err(gl::INVALID_VALUE);
    }
    if !types.contains(&ty) {
        return Err(gl::INVALID_ENUM);
    }
    if !sizes.contains(&size) {
        return Err(gl::INVALID_VALUE);
    }
    Ok(())
}

/// GL 2.1 table 2.5: the arrays an `InterleavedArrays` format enables, as (size, type, offset
/// in floats; colour offsets count a 4-ubyte colour as one float) for texture coordinates,
/// colour, normal and vertex, and the tight stride in floats.
type Part = Option<(i32, u32, usize)>;
/// (texture coordinates, colour, normal, (vertex size, vertex offset), tight stride).
type Layout = (Part, Part, Part, (i32, usize), usize);
fn interleaved_format(format: u32) -> Option<Layout> {
    use gl::{FLOAT as F, UNSIGNED_BYTE as UB};
    // (tex, colour, normal, (vertex size, vertex offset), stride)
    Some(match format {
        gl::V2F => (None, None, None, (2, 0), 2),
        gl::V3F => (None, None, None, (3, 0), 3),
        gl::C4UB_V2F => (None, Some((4, UB, 0)), None, (2, 1), 3),
        gl::C4UB_V3F => (None, Some((4, UB, 0)), None, (3, 1), 4),
        gl::C3F_V3F => (None, Some((3, F, 0)), None, (3, 3), 6),
        gl::N3F_V3F => (None, None, Some((3, F, 0)), (3, 3), 6),
        gl::C4F_N3F_V3F => (None, Some((4, F, 0)), Some((3, F, 4)), (3, 7), 10),
        gl::T2F_V3F => (Some((2, F, 0)), None, None, (3, 2), 5),
        gl::T4F_V4F => (Some((4, F, 0)), None, None, (4, 4), 8),
        gl::T2F_C4UB_V3F => (Some((2, F, 0)), Some((4, UB, 2)), None, (3, 3), 6),
        gl::T2F_C3F_V3F => (Some((2, F, 0)), Some((3, F, 2)), None, (3, 5), 8),
        gl::T2F_N3F_V3F => (Some((2, F, 0)), None, Some((3, F, 2)), (3, 5), 8),
        gl::T2F_C4F_N3F_V3F => (
            Some((2, F, 0)),
            Some((4, F, 2)),
            Some((3, F, 6)),
            (3, 9),
            12,
        ),
        gl::T4F_C4F_N3F_V4F => (
            Some((4, F, 0)),
            Some((4, F, 4)),
            Some((3, F, 8)),
            (4, 11),
            15,
        ),
        _ => return None,
    })
}

/// One enabled array resolved for a draw: its bytes from the element at index 0 on.
#[derive(Clone, Copy, Debug)]
pub struct Source<'a> {
    /// The attribute it feeds.
    pub attr: Attr,
    bytes: &'a [u8],
    size: usize,
    ty: u32,
    stride: usize,
    /// How many whole elements the bytes hold.
    pub count: usize,
}

impl Source<'_> {
    /// Element `i`'s components (at most 4) as floats, normalised by GL 2.1 table 2.9 for
    /// colours and normals; missing components are (0, 0, 0, 1). `None` past the data.
    pub fn fetch(&self, i: usize) -> Option<[f32; 4]> {
        let normalized = matches!(self.attr, Attr::Color | Attr::SecondaryColor | Attr::Normal);
        let cs = type_size(self.ty);
        let base = i.checked_mul(self.stride)?;
        let mut out = [0.0, 0.0, 0.0, 1.0];
        for (c, slot) in out.iter_mut().enumerate().take(self.size) {
            let o = base.checked_add(c * cs)?;
            let b = self.bytes.get(o..o.checked_add(cs)?)?;
            *slot = decode(b, self.ty, normalized)?;
        }
        Some(out)
    }
}

/// One component of type `ty` from its native-order bytes.
fn decode(b: &[u8], ty: u32, normalized: bool) -> Option<f32> {
    // GL 2.1 table 2.9: unsigned c/(2^b-1), signed (2c+1)/(2^b-1).
    fn u(x: f64, max: f64, n: bool) -> f32 {
        (if n {
            convert::unsigned_to_unit(x, max)
        } else {
            x
        }) as f32
    }
    fn s(x: f64, max: f64, n: bool) -> f32 {
        (if n {
            convert::signed_to_unit(x, max)
        } else {
            x
        }) as f32
    }
    Some(match ty {
        gl::UNSIGNED_BYTE => u(f64::from(*b.first()?), 255.0, normalized),
        gl::BYTE => s(
            f64::from(i8::from_ne_bytes([*b.first()?])),
            255.0,
            normalized,
        ),
        gl::UNSIGNED_SHORT => u(
            f64::from(u16::from_ne_bytes(b.try_into().ok()?)),
            65535.0,
            normalized,
        ),
        gl::SHORT => s(
            f64::from(i16::from_ne_bytes(b.try_into().ok()?)),
            65535.0,
            normalized,
        ),
        gl::UNSIGNED_INT => u(
            f64::from(u32::from_ne_bytes(b.try_into().ok()?)),
            f64::from(u32::MAX),
            normalized,
        ),
        gl::INT => s(
            f64::from(i32::from_ne_bytes(b.try_into().ok()?)),
            f64::from(u32::MAX),
            normalized,
        ),
        gl::FLOAT => f32::from_ne_bytes(b.try_into().ok()?),
        gl::DOUBLE => f64::from_ne_bytes(b.try_into().ok()?) as f32,
        _ => return None,
    })
}

/// A valid primitive mode (GL 2.1 §2.6.1).
pub fn valid_mode(mode: u32) -> bool {
    mode <= gl::POLYGON
}

fn valid_target(target: u32) -> bool {
    matches!(target, gl::ARRAY_BUFFER | gl::ELEMENT_ARRAY_BUFFER)
}

fn valid_usage(usage: u32) -> bool {
    matches!(
        usage,
        gl::STREAM_DRAW
            | gl::STREAM_READ
            | gl::STREAM_COPY
            | gl::STATIC_DRAW
            | gl::STATIC_READ
            | gl::STATIC_COPY
            | gl::DYNAMIC_DRAW
            | gl::DYNAMIC_READ
            | gl::DYNAMIC_COPY
    )
}

impl ArrayState {
    /// The array `cap` names for Enable/DisableClientState (texture coordinates: unit `unit`).
    pub fn array_mut(&mut self, cap: u32, unit: usize) -> Option<&mut ClientArray> {
        Some(match cap {
            gl::VERTEX_ARRAY => &mut self.vertex,
            gl::NORMAL_ARRAY => &mut self.normal,
            gl::COLOR_ARRAY => &mut self.color,
            gl::SECONDARY_COLOR_ARRAY => &mut self.secondary_color,
            gl::FOG_COORD_ARRAY => &mut self.fog_coord,
            gl::EDGE_FLAG_ARRAY => &mut self.edge_flag,
            gl::INDEX_ARRAY => &mut self.index,
            gl::TEXTURE_COORD_ARRAY => self.tex_coords.get_mut(unit)?,
            _ => return None,
        })
    }

    /// Whether the array `cap` names is enabled (`IsEnabled`), `None` if `cap` is not one.
    pub fn enabled(&self, cap: u32, unit: usize) -> Option<bool> {
        Some(match cap {
            gl::VERTEX_ARRAY => self.vertex.enabled,
            gl::NORMAL_ARRAY => self.normal.enabled,
            gl::COLOR_ARRAY => self.color.enabled,
            gl::SECONDARY_COLOR_ARRAY => self.secondary_color.enabled,
            gl::FOG_COORD_ARRAY => self.fog_coord.enabled,
            gl::EDGE_FLAG_ARRAY => self.edge_flag.enabled,
            gl::INDEX_ARRAY => self.index.enabled,
            gl::TEXTURE_COORD_ARRAY => self.tex_coords.get(unit)?.enabled,
            _ => return None,
        })
    }

    fn attr_mut(&mut self, attr: Attr) -> Option<&mut ClientArray> {
        Some(match attr {
            Attr::Vertex => &mut self.vertex,
            Attr::Normal => &mut self.normal,
            Attr::Color => &mut self.color,
            Attr::SecondaryColor => &mut self.secondary_color,
            Attr::FogCoord => &mut self.fog_coord,
            Attr::EdgeFlag => &mut self.edge_flag,
            Attr::Index => &mut self.index,
            Attr::TexCoord(u) => self.tex_coords.get_mut(u)?,
        })
    }

    /// `EnableClientState` / `DisableClientState` (GL 2.1 §2.8): INVALID_ENUM for an unknown cap.
    pub fn enable_client_state(&mut self, cap: u32, on: bool, unit: usize) -> GlResult<()> {
        let a = self.array_mut(cap, unit).ok_or(gl::INVALID_ENUM)?;
        a.enabled = on;
        Ok(())
    }

    /// A `*Pointer` command for `attr` (GL 2.1 §2.8, §2.9.1): format errors, then
    /// INVALID_OPERATION for client bytes while a buffer is bound to ARRAY_BUFFER.
    pub fn pointer(
        &mut self,
        attr: Attr,
        size: i32,
        ty: u32,
        stride: i32,
        pointer: &Pointer,
    ) -> GlResult<()> {
        check_format(attr, size, ty, stride)?;
        let buffer = self.array_buffer;
        if buffer != 0 && pointer.is_client() {
            return Err(gl::INVALID_OPERATION);
        }
        let a = self.attr_mut(attr).ok_or(gl::INVALID_ENUM)?;
        a.size = size;
        a.ty = ty;
        a.stride = stride;
        a.buffer = buffer;
        a.pointer = pointer.clone();
        Ok(())
    }

    /// `InterleavedArrays` (GL 2.1 §2.8, table 2.5): INVALID_ENUM for a format, INVALID_VALUE
    /// for a stride outside 0 to [`MAX_VERTEX_ATTRIB_STRIDE`]; then the pointers and enables of the format, on unit `unit`.
    pub fn interleaved_arrays(
        &mut self,
        format: u32,
        stride: i32,
        pointer: &Pointer,
        unit: usize,
    ) -> GlResult<()> {
        let (t, c, n, v, tight) = interleaved_format(format).ok_or(gl::INVALID_ENUM)?;
        if !(0..=MAX_VERTEX_ATTRIB_STRIDE).contains(&stride) {
            return Err(gl::INVALID_VALUE);
        }
        if self.array_buffer != 0 && pointer.is_client() {
            return Err(gl::INVALID_OPERATION);
        }
        let f = std::mem::size_of::<f32>();
        let stride = if stride == 0 {
            (tight * f) as i32
        } else {
            stride
        };
        let at = |floats: usize| match pointer {
            Pointer::Data(d) => Pointer::Data(d.get(floats * f..).unwrap_or(&[]).to_vec()),
            Pointer::Offset(o) => Pointer::Offset(o.saturating_add(floats * f)),
            Pointer::Client(c) => Pointer::Client(Box::new(c.offset_by(floats * f))),
        };
        let buffer = self.array_buffer;
        let set = |a: &mut ClientArray, part: Part| {
            a.enabled = part.is_some();
            if let Some((size, ty, off)) = part {
                a.size = size;
                a.ty = ty;
                a.stride = stride;
                a.buffer = buffer;
                a.pointer = at(off);
            }
        };
        self.edge_flag.enabled = false;
        self.index.enabled = false;
        self.secondary_color.enabled = false;
        self.fog_coord.enabled = false;
        if let Some(a) = self.tex_coords.get_mut(unit) {
            set(a, t);
        }
        set(&mut self.color, c);
        set(&mut self.normal, n);
        set(&mut self.vertex, Some((v.0, gl::FLOAT, v.1)));
        Ok(())
    }

    /// The bytes behind an array's pointer: its client bytes, or its buffer's data from the
    /// offset on (empty when the offset is past the end or no buffer is behind it). Memory read
    /// at draw time ([`Pointer::Client`]) is read for the `need` bytes the draw reaches.
    fn bytes<'a>(&'a self, buffer: u32, pointer: &'a Pointer, need: usize) -> &'a [u8] {
        match pointer {
            Pointer::Data(d) if buffer == 0 => d,
            Pointer::Client(c) if buffer == 0 => c.read(need),
            Pointer::Offset(o) if buffer != 0 => self
                .buffers
                .get(&buffer)
                .and_then(|b| b.data.get(*o..))
                .unwrap_or(&[]),
            _ => &[],
        }
    }

    /// Every enabled array, in ArrayElement's order (GL 2.1 §2.8), with the number of whole
    /// elements its data holds; memory read at draw time ([`Pointer::Client`]) is read for the
    /// first `reach` elements.
    pub fn sources(&self, reach: usize) -> Vec<Source<'_>> {
        let mut list: Vec<(Attr, &ClientArray)> = vec![(Attr::EdgeFlag, &self.edge_flag)];
        for (u, a) in self.tex_coords.iter().enumerate() {
            list.push((Attr::TexCoord(u), a));
        }
        list.extend([
            (Attr::Color, &self.color),
            (Attr::SecondaryColor, &self.secondary_color),
            (Attr::FogCoord, &self.fog_coord),
            (Attr::Normal, &self.normal),
            (Attr::Vertex, &self.vertex),
        ]);
        list.into_iter()
            .filter(|(_, a)| a.enabled)
            .map(|(attr, a)| {
                let size = a.size.max(0) as usize;
                let elem = size * type_size(a.ty);
                let stride = if a.stride == 0 {
                    elem
                } else {
                    a.stride as usize
                };
                let need = reach
                    .checked_sub(1)
                    .and_then(|last| last.checked_mul(stride))
                    .and_then(|n| n.checked_add(elem))
                    .unwrap_or(0);
                let bytes = self.bytes(a.buffer, &a.pointer, need);
                let count = if elem == 0 || bytes.len() < elem {
                    0
                } else {
                    (bytes.len() - elem) / stride.max(1) + 1
                };
                Source {
                    attr,
                    bytes,
                    size,
                    ty: a.ty,
                    stride,
                    count,
                }
            })
            .collect()
    }

    /// Whether an enabled array is memory read at draw time ([`Pointer::Client`]).
    pub fn reads_client(&self) -> bool {
        let all = [
            &self.vertex,
            &self.normal,
            &self.color,
            &self.secondary_color,
            &self.fog_coord,
            &self.edge_flag,
        ];
        all.into_iter()
            .chain(self.tex_coords.iter())
            .any(|a| a.enabled && a.buffer == 0 && matches!(a.pointer, Pointer::Client(_)))
    }

    /// INVALID_OPERATION unless every enabled array holds element `max_index`.
    pub fn check_reads(&self, max_index: usize) -> GlResult<()> {
        let reach = max_index.saturating_add(1);
        if self.sources(reach).iter().all(|s| max_index < s.count) {
            Ok(())
        } else {
            Err(gl::INVALID_OPERATION)
        }
    }

    /// The indices of a DrawElements call: `count` of `ty` read from `indices` (client bytes,
    /// or an offset into the ELEMENT_ARRAY_BUFFER). INVALID_ENUM for a type, INVALID_OPERATION
    /// when the data is too short or is client bytes while an element buffer is bound.
    pub fn indices(&self, count: usize, ty: u32, indices: &Pointer) -> GlResult<Vec<u32>> {
        let size = match ty {
            gl::UNSIGNED_BYTE => 1,
            gl::UNSIGNED_SHORT => 2,
            gl::UNSIGNED_INT => 4,
            _ => return Err(gl::INVALID_ENUM),
        };
        let eb = self.element_array_buffer;
        if eb != 0 && indices.is_client() {
            return Err(gl::INVALID_OPERATION);
        }
        let needed = count.checked_mul(size).ok_or(gl::INVALID_OPERATION)?;
        let bytes = self.bytes(eb, indices, needed);
        let bytes = bytes.get(..needed).ok_or(gl::INVALID_OPERATION)?;
        // Up to 4 bytes of u32 per byte of UNSIGNED_BYTE indices the caller handed over: an
        // allocation that fails is OUT_OF_MEMORY, not an abort.
        let mut out = Vec::new();
        out.try_reserve_exact(count)
            .map_err(|_| gl::OUT_OF_MEMORY)?;
        out.extend(bytes.chunks_exact(size).map(|c| match *c {
            [a] => u32::from(a),
            [a, b] => u32::from(u16::from_ne_bytes([a, b])),
            [a, b, c, d] => u32::from_ne_bytes([a, b, c, d]),
            _ => 0,
        }));
        Ok(out)
    }

    /// DrawArrays' checks after the Begin/End phase (GL 2.1 §2.8): INVALID_ENUM for a mode,
    /// INVALID_VALUE for a negative `first` or `count`, INVALID_OPERATION when an enabled array
    /// lives in a mapped buffer (§2.9) or lacks an element. The index range to draw; `None` when there is nothing to draw.
    pub fn check_draw_arrays(
        &self,
        mode: u32,
        first: i32,
        count: i32,
    ) -> GlResult<Option<std::ops::RangeInclusive<usize>>> {
        if !valid_mode(mode) {
            return Err(gl::INVALID_ENUM);
        }
        let (Ok(first), Ok(count)) = (usize::try_from(first), usize::try_from(count)) else {
            return Err(gl::INVALID_VALUE);
        };
        if count == 0 {
            return Ok(None);
        }
        self.check_unmapped(None)?;
        let last = first.checked_add(count - 1).ok_or(gl::INVALID_OPERATION)?;
        self.check_reads(last)?;
        Ok(Some(first..=last))
    }

    /// DrawElements' and DrawRangeElements' (`range`) checks after the Begin/End phase:
    /// INVALID_ENUM for a mode or type, INVALID_VALUE for a negative count or `end < start`,
    /// INVALID_OPERATION for short index data or an index an enabled array lacks. The indices;
    /// `None` when there is nothing to draw.
    pub fn check_draw_elements(
        &self,
        mode: u32,
        count: i32,
        ty: u32,
        indices: &Pointer,
        range: Option<(u32, u32)>,
    ) -> GlResult<Option<Vec<u32>>> {
        if !valid_mode(mode) {
            return Err(gl::INVALID_ENUM);
        }
        let count = usize::try_from(count).map_err(|_| gl::INVALID_VALUE)?;
        if !matches!(
            ty,
            gl::UNSIGNED_BYTE | gl::UNSIGNED_SHORT | gl::UNSIGNED_INT
        ) {
            return Err(gl::INVALID_ENUM);
        }
        if range.is_some_and(|(s, e)| e < s) {
            return Err(gl::INVALID_VALUE);
        }
        if count == 0 {
            return Ok(None);
        }
        self.check_unmapped(Some(indices))?;
        let idx = self.indices(count, ty, indices)?;
        let max = idx.iter().copied().max().unwrap_or(0) as usize;
        self.check_reads(max)?;
        Ok(Some(idx))
    }

    /// MultiDrawArrays' checks after the Begin/End phase (GL 2.1 §2.8, Mesa's order):
    /// INVALID_VALUE for a negative `drawcount` or (ours) slices shorter than it, INVALID_ENUM
    /// for a mode, INVALID_VALUE for a negative count; then each draw as DrawArrays checks it,
    /// except that a negative `first` is no error of its own (Mesa raises none): with an array
    /// enabled it reads before the data, INVALID_OPERATION as any read outside it. The ranges
    /// to draw, one per draw with a positive count; nothing is drawn unless all pass.
    pub fn check_multi_draw_arrays(
        &self,
        mode: u32,
        first: &[i32],
        count: &[i32],
        drawcount: i32,
    ) -> GlResult<Vec<std::ops::RangeInclusive<usize>>> {
        let n = usize::try_from(drawcount).map_err(|_| gl::INVALID_VALUE)?;
        let (Some(first), Some(count)) = (first.get(..n), count.get(..n)) else {
            return Err(gl::INVALID_VALUE);
        };
        if !valid_mode(mode) {
            return Err(gl::INVALID_ENUM);
        }
        if count.iter().any(|&c| c < 0) {
            return Err(gl::INVALID_VALUE);
        }
        let enabled = !self.sources(0).is_empty();
        let mut ranges = Vec::new();
        for (&f, &c) in first.iter().zip(count) {
            if c == 0 {
                continue;
            }
            if f < 0 {
                if enabled {
                    return Err(gl::INVALID_OPERATION);
                }
                continue;
            }
            if let Some(r) = self.check_draw_arrays(mode, f, c)? {
                ranges.push(r);
            }
        }
        Ok(ranges)
    }

    /// MultiDrawElements' checks after the Begin/End phase (GL 2.1 §2.8, Mesa's order):
    /// INVALID_VALUE for a negative `drawcount` or (ours) slices shorter than it, INVALID_ENUM
    /// for a mode or type, INVALID_VALUE for a negative count; then each draw as DrawElements
    /// checks it. The indices of each draw with a positive count; nothing is drawn unless all
    /// pass.
    pub fn check_multi_draw_elements(
        &self,
        mode: u32,
        count: &[i32],
        ty: u32,
        indices: &[Pointer],
        drawcount: i32,
    ) -> GlResult<Vec<Vec<u32>>> {
        let n = usize::try_from(drawcount).map_err(|_| gl::INVALID_VALUE)?;
        let (Some(count), Some(indices)) = (count.get(..n), indices.get(..n)) else {
            return Err(gl::INVALID_VALUE);
        };
        if !valid_mode(mode)
            || !matches!(
                ty,
                gl::UNSIGNED_BYTE | gl::UNSIGNED_SHORT | gl::UNSIGNED_INT
            )
        {
            return Err(gl::INVALID_ENUM);
        }
        if count.iter().any(|&c| c < 0) {
            return Err(gl::INVALID_VALUE);
        }
        let mut draws = Vec::new();
        for (&c, p) in count.iter().zip(indices) {
            if let Some(idx) = self.check_draw_elements(mode, c, ty, p, None)? {
                draws.push(idx);
            }
        }
        Ok(draws)
    }

    /// ArrayElement's check: INVALID_VALUE for a negative index, INVALID_OPERATION when an
    /// enabled array lacks the element.
    pub fn check_array_element(&self, i: i32) -> GlResult<usize> {
        let i = usize::try_from(i).map_err(|_| gl::INVALID_VALUE)?;
        self.check_unmapped(None)?;
        self.check_reads(i)?;
        Ok(i)
    }

    /// `GenBuffers` into `out` (GL 2.1 §2.9): the `n` lowest unused names. INVALID_VALUE for a
    /// negative `n` or an `out` shorter than `n`; OUT_OF_MEMORY (nothing reserved) when fewer
    /// than `n` names are unused. The search skips each run of reserved names in one step, so
    /// it costs the names written plus the buffer objects that exist, never a scan of every
    /// name generated before (which wrapped around forever once all 2^32 - 1 were taken).
    pub fn gen_buffers(&mut self, n: i32, out: &mut [u32]) -> GlResult<()> {
        let n = usize::try_from(n).map_err(|_| gl::INVALID_VALUE)?;
        let out = out.get_mut(..n).ok_or(gl::INVALID_VALUE)?;
        // Free names come in spans between reserved runs and buffer objects: each span is
        // found with two lookups and filled without any.
        let mut spans: Vec<(u32, u32)> = Vec::new();
        let (mut filled, mut next) = (0usize, Some(1u32));
        while filled < n {
            let mut name = next.ok_or(gl::OUT_OF_MEMORY)?;
            loop {
                if let Some(last) = self.reserved.run_end(name) {
                    name = last.checked_add(1).ok_or(gl::OUT_OF_MEMORY)?;
                } else if self.buffers.contains_key(&name) {
                    name = name.checked_add(1).ok_or(gl::OUT_OF_MEMORY)?;
                } else {
                    break;
                }
            }
            // The span of free names from `name`: up to the next reserved run or buffer.
            let stop = [
                self.reserved.next_run_start(name),
                self.buffers.range(name..).next().map(|(&k, _)| k),
            ]
            .into_iter()
            .flatten()
            .min();
            let room = stop.map_or(u64::from(u32::MAX) - u64::from(name) + 1, |s| {
                u64::from(s - name)
            });
            let take = (n - filled).min(usize::try_from(room).unwrap_or(usize::MAX));
            let last = name + (take as u32 - 1);
            for (k, slot) in out.iter_mut().skip(filled).take(take).enumerate() {
                *slot = name + k as u32;
            }
            spans.push((name, last));
            filled += take;
            next = last.checked_add(1);
        }
        for (first, last) in spans {
            self.reserved.insert_range(first, last);
        }
        Ok(())
    }

    /// Marks `names` used, as a `GenBuffers` that returned them did (for replays).
    pub fn reserve(&mut self, names: &[u32]) {
        for &name in names {
            if name != 0 && !self.buffers.contains_key(&name) {
                self.reserved.insert(name);
            }
        }
    }

    /// `DeleteBuffers` (GL 2.1 §2.9): INVALID_VALUE for a negative `n` or fewer than `n` names;
    /// 0 and unused names are ignored; bindings to a deleted buffer revert to 0.
    pub fn delete_buffers(&mut self, n: i32, names: &[u32]) -> GlResult<()> {
        let n = usize::try_from(n).map_err(|_| gl::INVALID_VALUE)?;
        let names = names.get(..n).ok_or(gl::INVALID_VALUE)?;
        for &name in names {
            self.reserved.remove(name);
            if name == 0 || self.buffers.remove(&name).is_none() {
                continue;
            }
            for b in [&mut self.array_buffer, &mut self.element_array_buffer] {
                if *b == name {
                    *b = 0;
                }
            }
            let arrays = [
                &mut self.vertex,
                &mut self.normal,
                &mut self.color,
                &mut self.secondary_color,
                &mut self.fog_coord,
                &mut self.edge_flag,
                &mut self.index,
            ];
            for a in arrays.into_iter().chain(self.tex_coords.iter_mut()) {
                if a.buffer == name {
                    a.buffer = 0;
                }
            }
        }
        Ok(())
    }

    /// `IsBuffer`: whether `name` is a buffer object (bound at least once).
    pub fn is_buffer(&self, name: u32) -> bool {
        self.buffers.contains_key(&name)
    }

    /// `BindBuffer` (GL 2.1 §2.9): INVALID_ENUM for a target; binding an unused name creates
    /// the object (the compatibility profile allows names GenBuffers did not return).
    pub fn bind_buffer(&mut self, target: u32, name: u32) -> GlResult<()> {
        if !valid_target(target) {
            return Err(gl::INVALID_ENUM);
        }
        if name != 0 {
            self.reserved.remove(name);
            self.buffers.entry(name).or_default();
        }
        if target == gl::ARRAY_BUFFER {
            self.array_buffer = name;
        } else {
            self.element_array_buffer = name;
        }
        Ok(())
    }

    /// The buffer bound to `target`: INVALID_ENUM for a target, INVALID_OPERATION for none.
    fn bound(&mut self, target: u32) -> GlResult<&mut BufferObject> {
        let name = match target {
            gl::ARRAY_BUFFER => self.array_buffer,
            gl::ELEMENT_ARRAY_BUFFER => self.element_array_buffer,
            _ => return Err(gl::INVALID_ENUM),
        };
        self.buffers.get_mut(&name).ok_or(gl::INVALID_OPERATION)
    }

    /// `BufferData` (GL 2.1 §2.9): INVALID_ENUM for a target or usage, INVALID_VALUE for a
    /// negative size, INVALID_OPERATION with no buffer bound; INVALID_VALUE (ours) when `data`
    /// holds fewer than `size` bytes; OUT_OF_MEMORY for a data-less size over
    /// [`MAX_BUFFER_SIZE`].
    pub fn buffer_data(
        &mut self,
        target: u32,
        size: isize,
        data: &Pointer,
        usage: u32,
    ) -> GlResult<()> {
        if !valid_target(target) || !valid_usage(usage) {
            return Err(gl::INVALID_ENUM);
        }
        let size = usize::try_from(size).map_err(|_| gl::INVALID_VALUE)?;
        self.bound(target)?;
        let src = match data {
            Pointer::Data(_) | Pointer::Client(_) => {
                let d = data.client_bytes(size).unwrap_or(&[]);
                Some(d.get(..size).ok_or(gl::INVALID_VALUE)?)
            }
            Pointer::Offset(0) if size <= MAX_BUFFER_SIZE => None,
            Pointer::Offset(0) => return Err(gl::OUT_OF_MEMORY),
            Pointer::Offset(_) => return Err(gl::INVALID_VALUE),
        };
        // The store is reserved before anything changes: an allocation the machine cannot
        // make is OUT_OF_MEMORY (GL 2.1 §2.9) with the old store kept, not an abort.
        let mut store = Vec::new();
        store
            .try_reserve_exact(size)
            .map_err(|_| gl::OUT_OF_MEMORY)?;
        match src {
            Some(d) => store.extend_from_slice(d),
            None => store.resize(size, 0),
        }
        let b = self.bound(target)?;
        // A mapped store is unmapped first, not an error (GL 2.1 §2.9, and Mesa).
        *b = BufferObject {
            data: store,
            usage,
            ..BufferObject::default()
        };
        Ok(())
    }

    /// The byte range `offset..offset+size` of the buffer bound to `target`: errors of
    /// BufferSubData / GetBufferSubData (GL 2.1 §2.9), INVALID_OPERATION while it is mapped.
    fn range(
        &mut self,
        target: u32,
        offset: isize,
        size: isize,
    ) -> GlResult<(&mut BufferObject, std::ops::Range<usize>)> {
        if !valid_target(target) {
            return Err(gl::INVALID_ENUM);
        }
        let (Ok(o), Ok(s)) = (usize::try_from(offset), usize::try_from(size)) else {
            return Err(gl::INVALID_VALUE);
        };
        let b = self.bound(target)?;
        let end = o.checked_add(s).ok_or(gl::INVALID_VALUE)?;
        if end > b.data.len() {
            return Err(gl::INVALID_VALUE);
        }
        // The store of a mapped buffer belongs to the mapping (GL 2.1 §2.9); checked after the
        // range, as Mesa does.
        if b.mapped {
            return Err(gl::INVALID_OPERATION);
        }
        Ok((b, o..end))
    }

    /// `BufferSubData`: INVALID_VALUE also when `data` holds fewer than `size` bytes (ours).
    pub fn buffer_sub_data(
        &mut self,
        target: u32,
        offset: isize,
        size: isize,
        data: &Pointer,
    ) -> GlResult<()> {
        let (b, r) = self.range(target, offset, size)?;
        let d = data.client_bytes(r.len()).ok_or(gl::INVALID_VALUE)?;
        let src = d.get(..r.len()).ok_or(gl::INVALID_VALUE)?;
        if let Some(dst) = b.data.get_mut(r) {
            dst.copy_from_slice(src);
        }
        Ok(())
    }

    /// `GetBufferSubData` into `out`: INVALID_VALUE also when `out` is shorter than `size`.
    pub fn get_buffer_sub_data(
        &mut self,
        target: u32,
        offset: isize,
        size: isize,
        out: &mut [u8],
    ) -> GlResult<()> {
        let (b, r) = self.range(target, offset, size)?;
        let dst = out.get_mut(..r.len()).ok_or(gl::INVALID_VALUE)?;
        dst.copy_from_slice(b.data.get(r).unwrap_or(&[]));
        Ok(())
    }

    /// `GetBufferParameteriv`'s value: BUFFER_SIZE, BUFFER_USAGE, BUFFER_ACCESS, BUFFER_MAPPED.
    pub fn buffer_parameter(&mut self, target: u32, pname: u32) -> GlResult<i32> {
        if !valid_target(target) {
            return Err(gl::INVALID_ENUM);
        }
        if !matches!(
            pname,
            gl::BUFFER_SIZE | gl::BUFFER_USAGE | gl::BUFFER_ACCESS | gl::BUFFER_MAPPED
        ) {
            return Err(gl::INVALID_ENUM);
        }
        let b = self.bound(target)?;
        Ok(match pname {
            gl::BUFFER_SIZE => i32::try_from(b.data.len()).unwrap_or(i32::MAX),
            gl::BUFFER_USAGE => b.usage as i32,
            gl::BUFFER_ACCESS => b.access as i32,
            _ => i32::from(b.mapped),
        })
    }

    /// `MapBuffer`'s checks and state change (GL 2.1 §2.9): INVALID_ENUM for an access (checked
    /// first, as Mesa does) or a target; INVALID_OPERATION with no buffer bound, for a buffer
    /// already mapped and, as llvmpipe, for an empty one. Returns the name of the buffer now
    /// mapped.
    pub fn map_buffer(&mut self, target: u32, access: u32) -> GlResult<u32> {
        if !matches!(access, gl::READ_ONLY | gl::WRITE_ONLY | gl::READ_WRITE) {
            return Err(gl::INVALID_ENUM);
        }
        let name = self.binding(target)?;
        let b = self.buffers.get_mut(&name).ok_or(gl::INVALID_OPERATION)?;
        if b.mapped || b.data.is_empty() {
            return Err(gl::INVALID_OPERATION);
        }
        b.mapped = true;
        b.access = access;
        Ok(name)
    }

    /// `UnmapBuffer` (GL 2.1 §2.9): INVALID_ENUM for a target, INVALID_OPERATION with no buffer
    /// bound or one not mapped. Returns the name of the buffer unmapped.
    pub fn unmap_buffer(&mut self, target: u32) -> GlResult<u32> {
        let name = self.binding(target)?;
        let b = self.buffers.get_mut(&name).ok_or(gl::INVALID_OPERATION)?;
        if !b.mapped {
            return Err(gl::INVALID_OPERATION);
        }
        b.mapped = false;
        b.access = gl::READ_WRITE;
        Ok(name)
    }

    /// The store of the buffer bound to `target`, if it is mapped: what the mapping reads and
    /// writes (see [`BufferObject`] on why its address is stable while mapped).
    pub fn mapped_mut(&mut self, target: u32) -> Option<&mut [u8]> {
        let name = self.binding(target).ok()?;
        let b = self.buffers.get_mut(&name)?;
        b.mapped.then_some(&mut b.data[..])
    }

    /// `GetBufferPointerv`'s checks (GL 2.1 §6.1.13): INVALID_ENUM for a target or a pname other
    /// than BUFFER_MAP_POINTER, INVALID_OPERATION with no buffer bound. The mapped store, or
    /// `None` when the buffer is not mapped (GL's NULL).
    pub fn buffer_pointer(&mut self, target: u32, pname: u32) -> GlResult<Option<&mut [u8]>> {
        let name = self.binding(target)?;
        if pname != gl::BUFFER_MAP_POINTER {
            return Err(gl::INVALID_ENUM);
        }
        let b = self.buffers.get_mut(&name).ok_or(gl::INVALID_OPERATION)?;
        Ok(b.mapped.then_some(&mut b.data[..]))
    }

    /// The name bound to `target` (0 for none): INVALID_ENUM for a target.
    fn binding(&self, target: u32) -> GlResult<u32> {
        match target {
            gl::ARRAY_BUFFER => Ok(self.array_buffer),
            gl::ELEMENT_ARRAY_BUFFER => Ok(self.element_array_buffer),
            _ => Err(gl::INVALID_ENUM),
        }
    }

    /// Whether buffer `name` exists and is mapped.
    pub fn is_mapped(&self, name: u32) -> bool {
        self.buffers.get(&name).is_some_and(|b| b.mapped)
    }

    /// GL 2.1 §2.9: a command that dereferences a mapped buffer's store is INVALID_OPERATION.
    /// For a draw: an enabled array whose data lies in a mapped buffer, or (`indices`) index data
    /// in a mapped ELEMENT_ARRAY_BUFFER. Mesa's llvmpipe lets such draws read the store
    /// (`AllowMappedBuffersDuringExecution`); fixedgl gives the spec's error, and its GL backend
    /// raises it before the driver sees the draw.
    fn check_unmapped(&self, indices: Option<&Pointer>) -> GlResult<()> {
        let arrays = [
            &self.vertex,
            &self.normal,
            &self.color,
            &self.secondary_color,
            &self.fog_coord,
            &self.edge_flag,
        ];
        let array_mapped = arrays
            .into_iter()
            .chain(self.tex_coords.iter())
            .any(|a| a.enabled && a.buffer != 0 && self.is_mapped(a.buffer));
        let index_mapped = matches!(indices, Some(Pointer::Offset(_)))
            && self.element_array_buffer != 0
            && self.is_mapped(self.element_array_buffer);
        if array_mapped || index_mapped {
            return Err(gl::INVALID_OPERATION);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Expected values by hand: bytes in native order, table 2.9 for normalised types.
    #[test]
    fn fetch_decodes_each_type() {
        let mut a = ArrayState::default();
        let bytes: Pointer = (&[255u8, 0, 51, 7]).into();
        assert_eq!(
            a.pointer(Attr::Color, 3, gl::UNSIGNED_BYTE, 4, &bytes),
            Ok(())
        );
        a.color.enabled = true;
        let s = a.sources(usize::MAX);
        let src = s.first().copied();
        // 4 bytes, element size 3, stride 4: one whole element.
        assert_eq!(src.map(|s| s.count), Some(1));
        assert_eq!(src.and_then(|s| s.fetch(0)), Some([1.0, 0.0, 0.2, 1.0]));
        assert_eq!(src.and_then(|s| s.fetch(1)), None);
        assert_eq!(src.and_then(|s| s.fetch(usize::MAX)), None);
        // Signed normals: (2c + 1) / (2^16 - 1); vertices unnormalised.
        let n: Pointer = (&[32767i16, -32768, 0]).into();
        assert_eq!(a.pointer(Attr::Normal, 3, gl::SHORT, 0, &n), Ok(()));
        let v: Pointer = (&[-3i32, 9]).into();
        assert_eq!(a.pointer(Attr::Vertex, 2, gl::INT, 0, &v), Ok(()));
        a.normal.enabled = true;
        a.vertex.enabled = true;
        let s = a.sources(usize::MAX);
        let got: Vec<_> = s.iter().map(|s| (s.attr, s.fetch(0))).collect();
        assert_eq!(
            got,
            vec![
                (Attr::Color, Some([1.0, 0.0, 0.2, 1.0])),
                (
                    Attr::Normal,
                    Some([1.0, -1.0, (1.0 / 65535.0f64) as f32, 1.0])
                ),
                (Attr::Vertex, Some([-3.0, 9.0, 0.0, 1.0])),
            ]
        );
    }

    #[test]
    fn counts_follow_stride_and_offset() {
        let mut a = ArrayState::default();
        assert_eq!(a.bind_buffer(gl::ARRAY_BUFFER, 3), Ok(()));
        // 100 bytes; from offset 8, 92 bytes: elements of 12 bytes every 20: (92-12)/20+1 = 5.
        assert_eq!(
            a.buffer_data(gl::ARRAY_BUFFER, 100, &Pointer::NULL, gl::STATIC_DRAW),
            Ok(())
        );
        assert_eq!(
            a.pointer(Attr::Vertex, 3, gl::FLOAT, 20, &Pointer::Offset(8)),
            Ok(())
        );
        a.vertex.enabled = true;
        assert_eq!(a.sources(5).first().map(|s| s.count), Some(5));
        assert_eq!(a.check_reads(4), Ok(()));
        assert_eq!(a.check_reads(5), Err(gl::INVALID_OPERATION));
        // An offset past the end holds nothing.
        assert_eq!(
            a.pointer(Attr::Vertex, 3, gl::FLOAT, 0, &Pointer::Offset(usize::MAX)),
            Ok(())
        );
        assert_eq!(a.sources(5).first().map(|s| s.count), Some(0));
        assert_eq!(
            a.check_draw_arrays(gl::POINTS, i32::MAX, i32::MAX),
            Err(gl::INVALID_OPERATION)
        );
    }
}
