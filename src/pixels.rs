//! Pixel rectangles in client memory (GL 2.1 §3.6.4, §4.3.2) and the pixel transfer operations
//! (§3.6.5): the formats and types of tables 3.5 to 3.8, the byte (or bit) layout of an image
//! under the pixel storage modes, the reading of one group, the transfer state (scale and bias,
//! index shift and offset, the ten pixel maps) and its application to colours, indices and depths.
//!
//! DrawPixels, Bitmap, CopyPixels, ReadPixels, TexImage/TexSubImage (`crate::texture::unpack_into`)
//! and GetTexImage share this module, and so do the GL backend's guards (how many bytes the
//! driver will read): one table of formats and types, one layout computation
//! (`crate::pixel_store`), one transfer.
//!
//! Design decision: validation follows GL 2.1 in Mesa's order. BITMAP with a format that is not
//! an index is INVALID_ENUM, a packed type whose component count the format does not have is
//! INVALID_OPERATION (both checked on the type first, as Mesa's `_mesa_error_check_format_and_type`
//! does), then an unknown format or a type the format does not take is INVALID_ENUM. What GL 2.1
//! does not have (HALF_FLOAT, RG, the integer formats) is INVALID_ENUM here; Mesa takes some of
//! it, and the GL backend raises the GL 2.1 error itself. GL_EXT_packed_depth_stencil's
//! DEPTH_STENCIL format and UNSIGNED_INT_24_8 type are taken, as Mesa takes them in its GL 1.5
//! context: each only with the other (UNSIGNED_INT_24_8 with another format is
//! INVALID_OPERATION, DEPTH_STENCIL with another type INVALID_ENUM, as Mesa answers).

use std::sync::Arc;

use crate::convert;
use crate::gl;
use crate::pixel_store::{Layout, PixelModes};

/// `MAX_PIXEL_MAP_TABLE` (GL 2.1 table 6.37: at least 32; Mesa's 256).
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// A colour component's place in an RGBA group, or luminance (§3.6.4 "Conversion to RGB").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// Red.
    R,
    /// Green.
    G,
    /// Blue.
    B,
    /// Alpha.
    A,
    /// Luminance: red, green and blue.
    L,
}

/// What the groups of a format are (table 3.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// Colour components, in the order the format stores them.
    Color(&'static [Slot]),
    /// COLOR_INDEX: one colour index.
    Index,
    /// STENCIL_INDEX: one stencil index.
    Stencil,
    /// DEPTH_COMPONENT: one depth.
    Depth,
    /// GL_EXT_packed_depth_stencil's DEPTH_STENCIL: a depth and a stencil index (type
    /// UNSIGNED_INT_24_8 only).
    DepthStencil,
}

impl Group {
    /// The group of a GL 2.1 pixel format (table 3.6), or None (INVALID_ENUM).
    pub fn of(format: u32) -> Option<Group> {
        use Slot::*;
        Some(match format {
            gl::COLOR_INDEX => Group::Index,
            gl::STENCIL_INDEX => Group::Stencil,
            gl::DEPTH_COMPONENT => Group::Depth,
            gl::DEPTH_STENCIL => Group::DepthStencil,
            gl::RED => Group::Color(&[R]),
            gl::GREEN => Group::Color(&[G]),
            gl::BLUE => Group::Color(&[B]),
            gl::ALPHA => Group::Color(&[A]),
            gl::RGB => Group::Color(&[R, G, B]),
            gl::RGBA => Group::Color(&[R, G, B, A]),
            gl::BGR => Group::Color(&[B, G, R]),
            gl::BGRA => Group::Color(&[B, G, R, A]),
            gl::ABGR_EXT => Group::Color(&[A, B, G, R]),
            gl::LUMINANCE => Group::Color(&[L]),
            gl::LUMINANCE_ALPHA => Group::Color(&[L, A]),
            _ => return None,
        })
    }

    /// Components per group.
    pub fn components(self) -> usize {
        match self {
            Group::Color(c) => c.len(),
            Group::DepthStencil => 2,
            _ => 1,
        }
    }

    /// An index format (COLOR_INDEX or STENCIL_INDEX: BITMAP's formats).
    pub fn is_index(self) -> bool {
        matches!(self, Group::Index | Group::Stencil)
    }
}

/// One element's type, for the types with an element per component (table 3.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scalar {
    /// UNSIGNED_BYTE.
    U8,
    /// BYTE.
    I8,
    /// UNSIGNED_SHORT.
    U16,
    /// SHORT.
    I16,
    /// UNSIGNED_INT.
    U32,
    /// INT.
    I32,
    /// FLOAT.
    F32,
}

impl Scalar {
    /// Bytes per element.
    pub fn size(self) -> usize {
        match self {
            Scalar::U8 | Scalar::I8 => 1,
            Scalar::U16 | Scalar::I16 => 2,
            _ => 4,
        }
    }
}

/// A pixel type (table 3.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ty {
    /// BITMAP: one bit per group (index formats only).
    Bitmap,
    /// One element per component.
    Scalar(Scalar),
    /// One element of `size` bytes holds a whole group: each component's (shift, bits), in the
    /// order of the format's components (table 3.8).
    Packed {
        /// Bytes per element.
        size: usize,
        /// (shift, bits) of the format's first, second, ... component.
        fields: &'static [(u32, u32)],
    },
}

impl Ty {
    /// The type named `ty` in GL 2.1, or None (INVALID_ENUM; HALF_FLOAT came with GL 3.0).
    pub fn of(ty: u32) -> Option<Ty> {
        Some(match ty {
            gl::BITMAP => Ty::Bitmap,
            gl::UNSIGNED_BYTE => Ty::Scalar(Scalar::U8),
            gl::BYTE => Ty::Scalar(Scalar::I8),
            gl::UNSIGNED_SHORT => Ty::Scalar(Scalar::U16),
            gl::SHORT => Ty::Scalar(Scalar::I16),
            gl::UNSIGNED_INT => Ty::Scalar(Scalar::U32),
            gl::INT => Ty::Scalar(Scalar::I32),
            gl::FLOAT => Ty::Scalar(Scalar::F32),
            _ => return Ty::packed(ty),
        })
    }

    /// The packed types of GL 1.2 (table 3.8): the first component in the high bits, or with
    /// _REV in the low bits.
    fn packed(ty: u32) -> Option<Ty> {
        let (size, fields): (usize, &'static [(u32, u32)]) = match ty {
            gl::UNSIGNED_BYTE_3_3_2 => (1, &[(5, 3), (2, 3), (0, 2)]),
            gl::UNSIGNED_BYTE_2_3_3_REV => (1, &[(0, 3), (3, 3), (6, 2)]),
            gl::UNSIGNED_SHORT_5_6_5 => (2, &[(11, 5), (5, 6), (0, 5)]),
            gl::UNSIGNED_SHORT_5_6_5_REV => (2, &[(0, 5), (5, 6), (11, 5)]),
            gl::UNSIGNED_SHORT_4_4_4_4 => (2, &[(12, 4), (8, 4), (4, 4), (0, 4)]),
            gl::UNSIGNED_SHORT_4_4_4_4_REV => (2, &[(0, 4), (4, 4), (8, 4), (12, 4)]),
            gl::UNSIGNED_SHORT_5_5_5_1 => (2, &[(11, 5), (6, 5), (1, 5), (0, 1)]),
            gl::UNSIGNED_SHORT_1_5_5_5_REV => (2, &[(0, 5), (5, 5), (10, 5), (15, 1)]),
            gl::UNSIGNED_INT_8_8_8_8 => (4, &[(24, 8), (16, 8), (8, 8), (0, 8)]),
            gl::UNSIGNED_INT_8_8_8_8_REV => (4, &[(0, 8), (8, 8), (16, 8), (24, 8)]),
            gl::UNSIGNED_INT_10_10_10_2 => (4, &[(22, 10), (12, 10), (2, 10), (0, 2)]),
            gl::UNSIGNED_INT_2_10_10_10_REV => (4, &[(0, 10), (10, 10), (20, 10), (30, 2)]),
            // GL_EXT_packed_depth_stencil: the depth in the high 24 bits, the index in the low 8.
            gl::UNSIGNED_INT_24_8 => (4, &[(8, 24), (0, 8)]),
            _ => return None,
        };
        Some(Ty::Packed { size, fields })
    }
}

/// A validated format and type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Format {
    /// The groups.
    pub group: Group,
    /// The type.
    pub ty: Ty,
}

/// The format/type check of DrawPixels and ReadPixels (GL 2.1 §3.6.4, §4.3.2; Mesa's order, see
/// the module docs): `Err` with INVALID_ENUM or INVALID_OPERATION.
pub fn check(format: u32, ty: u32) -> Result<Format, u32> {
    let group = Group::of(format);
    let t = Ty::of(ty);
    // DEPTH_STENCIL takes UNSIGNED_INT_24_8 only: any other type, packed ones included, is
    // INVALID_ENUM (the driver's answer).
    if group == Some(Group::DepthStencil) && ty != gl::UNSIGNED_INT_24_8 {
        return Err(gl::INVALID_ENUM);
    }
    match t {
        Some(Ty::Bitmap) if !group.is_some_and(Group::is_index) => return Err(gl::INVALID_ENUM),
        // Table 3.8: a packed type needs a format with as many components (RGB for the
        // three-component types; RGBA, BGRA or EXT_abgr's ABGR for the four-component ones, as
        // Mesa; DEPTH_STENCIL for UNSIGNED_INT_24_8).
        Some(Ty::Packed { fields, .. }) => {
            let ok = match fields.len() {
                2 => format == gl::DEPTH_STENCIL,
                3 => format == gl::RGB,
                _ => matches!(format, gl::RGBA | gl::BGRA | gl::ABGR_EXT),
            };
            if !ok {
                return Err(gl::INVALID_OPERATION);
            }
        }
        _ => {}
    }
    match (group, t) {
        (Some(group), Some(ty)) => Ok(Format { group, ty }),
        _ => Err(gl::INVALID_ENUM),
    }
}

/// Where an image's groups lie in client memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageLayout {
    /// Byte-aligned groups (every type but BITMAP).
    Bytes(Layout),
    /// One bit per group (BITMAP).
    Bits(BitLayout),
}

impl ImageLayout {
    /// Bytes the image spans from the start of the client buffer.
    pub fn need(&self) -> usize {
        match self {
            ImageLayout::Bytes(l) => l.need,
            ImageLayout::Bits(b) => b.need,
        }
    }
}

/// A bitmap's layout (§3.6.4 with type BITMAP): rows of bits, `stride` bytes apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BitLayout {
    /// Byte where the first row starts (SKIP_ROWS rows in).
    pub offset: usize,
    /// Bytes between row starts: ALIGNMENT · ceil(l / (8 · ALIGNMENT)) for rows of l bits.
    pub stride: usize,
    /// Bits skipped at the start of each row (SKIP_PIXELS).
    pub skip: usize,
    /// Bit order within a byte: least significant first (LSB_FIRST).
    pub lsb_first: bool,
    /// Bytes the whole bitmap spans.
    pub need: usize,
}

impl BitLayout {
    /// Bit (`i`, `j`) of the bitmap in `data` (false past its end).
    #[inline]
    pub fn bit(&self, data: &[u8], i: usize, j: usize) -> bool {
        let b = self.skip + i;
        let at = self.offset + j * self.stride + b / 8;
        let Some(&byte) = data.get(at) else {
            return false;
        };
        let k = (b % 8) as u32;
        let mask = if self.lsb_first {
            1u8 << k
        } else {
            0x80u8 >> k
        };
        byte & mask != 0
    }

    /// Bits (`i`, `j`) for each `i` of `cols`, appended to `out` as 0 or 1: what [`Self::bit`]
    /// gives for each, with the row's start found once.
    pub fn push_row(&self, data: &[u8], cols: &[usize], j: usize, out: &mut Vec<u8>) {
        // A row starting past the data (or whose start overflows) has no bits set, as `bit`
        // finds no byte for any of its columns.
        let row = j
            .checked_mul(self.stride)
            .and_then(|r| r.checked_add(self.offset))
            .and_then(|r| data.get(r..))
            .unwrap_or(&[]);
        let lsb = self.lsb_first;
        out.extend(cols.iter().map(|&i| {
            let b = self.skip.wrapping_add(i);
            let byte = row.get(b / 8).copied().unwrap_or(0);
            let k = (b % 8) as u32;
            let bit = if lsb { byte >> k } else { byte >> (7 - k) };
            bit & 1
        }));
    }

    /// Bits (`i`, `j`) for `i` in `i0..i0 + n`, appended to `out` as 0 or 1: what
    /// [`Self::push_row`] gives for those columns, a byte of the row at a time.
    pub fn push_run(&self, data: &[u8], i0: usize, n: usize, j: usize, out: &mut Vec<u8>) {
        let row = j
            .checked_mul(self.stride)
            .and_then(|r| r.checked_add(self.offset))
            .and_then(|r| data.get(r..))
            .unwrap_or(&[]);
        // Byte k of `byte · ONES & select` keeps the byte's bit for the row's bit 8·(b / 8) + k
        // (bit k LSB first, bit 7 − k MSB first); + 0x7F carries a kept bit (at most 0x80)
        // into bit 7 of its byte without touching the next, which >> 7 makes 0 or 1.
        const ONES: u64 = 0x0101_0101_0101_0101;
        let select: u64 = if self.lsb_first {
            0x8040_2010_0804_0201
        } else {
            0x0102_0408_1020_4080
        };
        let mut b = self.skip.wrapping_add(i0);
        let mut left = n;
        while left > 0 {
            let byte = u64::from(row.get(b / 8).copied().unwrap_or(0));
            let kept = byte.wrapping_mul(ONES) & select;
            let bits = ((kept + 0x7F7F_7F7F_7F7F_7F7F) >> 7) & ONES;
            let k0 = b % 8;
            let take = (8 - k0).min(left);
            out.extend_from_slice(bits.to_le_bytes().get(k0..k0 + take).unwrap_or(&[]));
            b = b.wrapping_add(take);
            left -= take;
        }
    }
}

impl PixelModes {
    /// The layout of a `width` x `height` bitmap under these modes (§3.6.4, type BITMAP; SWAP_BYTES
    /// does not apply to bits). None when a byte count does not fit a usize.
    pub fn bitmap_layout(&self, width: i32, height: i32) -> Option<BitLayout> {
        let w = usize::try_from(width.max(0)).ok()?;
        let h = usize::try_from(height.max(0)).ok()?;
        let l = if self.row_length > 0 {
            usize::try_from(self.row_length).ok()?
        } else {
            w
        };
        let a = usize::try_from(self.alignment.clamp(1, 8)).ok()?;
        let stride = l.div_ceil(8).checked_next_multiple_of(a)?;
        let skip = usize::try_from(self.skip_pixels.max(0)).ok()?;
        let offset = stride.checked_mul(usize::try_from(self.skip_rows.max(0)).ok()?)?;
        let need = if w == 0 || h == 0 {
            0
        } else {
            offset
                .checked_add(stride.checked_mul(h - 1)?)?
                .checked_add(skip.checked_add(w)?.div_ceil(8))?
        };
        Some(BitLayout {
            offset,
            stride,
            skip,
            lsb_first: self.lsb_first,
            need,
        })
    }

    /// The layout of a `width` x `height` image of `f` under these modes, or None when its byte
    /// count does not fit a usize.
    pub fn image_layout(&self, f: Format, width: i32, height: i32) -> Option<ImageLayout> {
        Some(match f.ty {
            Ty::Bitmap => ImageLayout::Bits(self.bitmap_layout(width, height)?),
            Ty::Scalar(s) => {
                ImageLayout::Bytes(self.layout(width, height, f.group.components(), s.size())?)
            }
            Ty::Packed { size, .. } => ImageLayout::Bytes(self.layout(width, height, 1, size)?),
        })
    }
}

/// An image in client memory, validated: `data` holds at least `layout.need()` bytes.
#[derive(Clone, Copy, Debug)]
pub struct Image<'a> {
    /// The client's bytes.
    pub data: &'a [u8],
    /// Format and type.
    pub format: Format,
    /// Where the groups lie.
    pub layout: ImageLayout,
}

/// The 8-bit colour of one UNSIGNED_BYTE group `b` of components `slots` (`Image::bytes`):
/// each byte in the channels its slot names, a missing R, G, B 0 and A 255. `K` 4 says the
/// slots are R, G, B, A and 3 R, G, B (then `b` is copied as it is; a `b` of another length
/// gives (0, 0, 0, 255)); 0 reads the slots.
#[inline(always)]
fn group_bytes<const K: usize>(b: &[u8], slots: &[Slot]) -> [u8; 4] {
    match (K, b) {
        (4, &[r, g, b, a]) => [r, g, b, a],
        (3, &[r, g, b]) => [r, g, b, 255],
        (3 | 4, _) => [0, 0, 0, 255],
        _ => {
            let mut c = [0, 0, 0, 255];
            for (&byte, s) in b.iter().zip(slots) {
                match s {
                    Slot::R => c[0] = byte,
                    Slot::G => c[1] = byte,
                    Slot::B => c[2] = byte,
                    Slot::A => c[3] = byte,
                    Slot::L => {
                        c[0] = byte;
                        c[1] = byte;
                        c[2] = byte;
                    }
                }
            }
            c
        }
    }
}

/// An element of `size` bytes at `at`, in the host's order (SWAP_BYTES applied), as a u32
/// (0 past the end of `data`).
#[inline]
fn element(data: &[u8], at: usize, size: usize, layout: &Layout) -> u32 {
    let mut e = [0u8; 4];
    let n = size.min(4);
    if let Some(src) = data.get(at..at + n) {
        e[..n].copy_from_slice(src);
    }
    layout.order(&mut e[..n]);
    match n {
        1 => u32::from(e[0]),
        2 => u32::from(u16::from_ne_bytes([e[0], e[1]])),
        _ => u32::from_ne_bytes(e),
    }
}

/// Each unsigned byte c as c / 255 (table 2.9), rounded once from double precision as
/// [`normalized`] computes it.
const U8_UNIT: [f32; 256] = {
    let mut t = [0.0f32; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = (i as f64 / 255.0) as f32;
        i += 1;
    }
    t
};

/// The unsigned byte `c` as c / 255, exactly as an UNSIGNED_BYTE component unpacks.
pub fn unit_u8(c: u8) -> f32 {
    U8_UNIT[usize::from(c)]
}

/// An element's bits as a normalised float (table 2.9 for integers; FLOAT as it is).
#[inline]
fn normalized(s: Scalar, bits: u32) -> f32 {
    let (u8max, u16max, u32max) = (f64::from(u8::MAX), f64::from(u16::MAX), f64::from(u32::MAX));
    let c = match s {
        Scalar::U8 => convert::unsigned_to_unit(f64::from(bits), u8max),
        Scalar::I8 => convert::signed_to_unit(f64::from(bits as u8 as i8), u8max),
        Scalar::U16 => convert::unsigned_to_unit(f64::from(bits), u16max),
        Scalar::I16 => convert::signed_to_unit(f64::from(bits as u16 as i16), u16max),
        Scalar::U32 => convert::unsigned_to_unit(f64::from(bits), u32max),
        Scalar::I32 => convert::signed_to_unit(f64::from(bits as i32), u32max),
        Scalar::F32 => return f32::from_bits(bits),
    };
    c as f32
}

/// An element's bits as an index (§3.6.5 "Arithmetic on Indices": an integer as it is, a float
/// truncated to an integer, as Mesa converts it).
#[inline]
fn index_value(s: Scalar, bits: u32) -> i64 {
    match s {
        Scalar::U8 | Scalar::U16 | Scalar::U32 => i64::from(bits),
        Scalar::I8 => i64::from(bits as u8 as i8),
        Scalar::I16 => i64::from(bits as u16 as i16),
        Scalar::I32 => i64::from(bits as i32),
        Scalar::F32 => f32::from_bits(bits) as i64,
    }
}

impl Image<'_> {
    /// Component `k` (in format order) of group (`i`, `j`) for a byte layout: its raw bits and
    /// the number of bits of a packed field (None for a whole element).
    #[inline]
    fn raw(&self, l: &Layout, i: usize, j: usize, k: usize) -> (u32, Option<u32>) {
        let at = l.at(i, j);
        match self.format.ty {
            Ty::Packed { size, fields } => {
                let e = element(self.data, at, size, l);
                let (shift, bits) = fields.get(k).copied().unwrap_or((0, 1));
                ((e >> shift) & ((1u32 << bits) - 1), Some(bits))
            }
            Ty::Scalar(s) => (element(self.data, at + k * s.size(), s.size(), l), None),
            Ty::Bitmap => (0, None),
        }
    }

    /// Component `k` of group (`i`, `j`) as a normalised float.
    #[inline]
    fn norm(&self, i: usize, j: usize, k: usize) -> f32 {
        match (&self.layout, self.format.ty) {
            (ImageLayout::Bytes(l), Ty::Packed { .. }) => {
                let (v, bits) = self.raw(l, i, j, k);
                let max = f64::from((1u32 << bits.unwrap_or(1)) - 1);
                convert::unsigned_to_unit(f64::from(v), max) as f32
            }
            (ImageLayout::Bytes(l), Ty::Scalar(s)) => normalized(s, self.raw(l, i, j, k).0),
            (ImageLayout::Bits(b), _) => f32::from(u8::from(b.bit(self.data, i, j))),
            _ => 0.0,
        }
    }

    /// The RGBA colour of group (`i`, `j`) of a colour image, before any transfer: the
    /// format's components in their slots, a missing R, G or B 0 and a missing A 1, luminance
    /// in R, G and B (§3.6.4 "Conversion to RGB").
    pub fn color(&self, i: usize, j: usize) -> [f32; 4] {
        let mut c = [0.0, 0.0, 0.0, 1.0];
        if let Group::Color(slots) = self.format.group {
            // UNSIGNED_BYTE, the common case, by table: the group's bytes in one slice.
            let bytes = match (&self.layout, self.format.ty) {
                (ImageLayout::Bytes(l), Ty::Scalar(Scalar::U8)) => {
                    let at = l.at(i, j);
                    self.data.get(at..at + slots.len())
                }
                _ => None,
            };
            for (k, s) in slots.iter().enumerate() {
                let v = match bytes {
                    Some(b) => U8_UNIT[usize::from(b[k])],
                    None => self.norm(i, j, k),
                };
                match s {
                    Slot::R => c[0] = v,
                    Slot::G => c[1] = v,
                    Slot::B => c[2] = v,
                    Slot::A => c[3] = v,
                    Slot::L => {
                        c[0] = v;
                        c[1] = v;
                        c[2] = v;
                    }
                }
            }
        }
        c
    }

    /// [`Image::color`] of the groups (i, j) for every `j` of `rows` and `i` of `cols`, rows
    /// first, into `out` (which the caller reserved): the same values, with the format's
    /// components decoded once per image rather than per group for UNSIGNED_BYTE data.
    pub fn colors(&self, cols: &[usize], rows: &[usize], out: &mut Vec<[f32; 4]>) {
        let (ImageLayout::Bytes(l), Ty::Scalar(Scalar::U8), Group::Color(slots)) =
            (&self.layout, self.format.ty, self.format.group)
        else {
            for &j in rows {
                out.extend(cols.iter().map(|&i| self.color(i, j)));
            }
            return;
        };
        // Each component's destination channels.
        let dest: Vec<(usize, usize)> = slots
            .iter()
            .map(|s| match s {
                Slot::R => (0, 1),
                Slot::G => (1, 2),
                Slot::B => (2, 3),
                Slot::A => (3, 4),
                Slot::L => (0, 3),
            })
            .collect();
        let n = slots.len();
        for &j in rows {
            for &i in cols {
                let at = l.at(i, j);
                let mut c = [0.0, 0.0, 0.0, 1.0];
                if let Some(b) = self.data.get(at..at + n) {
                    for (&byte, &(lo, hi)) in b.iter().zip(&dest) {
                        let v = U8_UNIT[usize::from(byte)];
                        for slot in c.iter_mut().take(hi).skip(lo) {
                            *slot = v;
                        }
                    }
                }
                out.push(c);
            }
        }
    }

    /// For UNSIGNED_BYTE colour data only (None otherwise): the groups (i, j) for every `j` of
    /// `rows` and `i` of `cols`, rows first, as the 8-bit colours [`Image::color`] converts to
    /// with no transfer (c/255 back to 8 bits is c: the bytes themselves, in their channels, a
    /// missing R, G, B 0 and A 255), appended to `out`.
    pub fn bytes(&self, cols: &[usize], rows: &[usize], out: &mut Vec<[u8; 4]>) -> Option<()> {
        let (ImageLayout::Bytes(l), Ty::Scalar(Scalar::U8), Group::Color(slots)) =
            (&self.layout, self.format.ty, self.format.group)
        else {
            return None;
        };
        let n = slots.len();
        // RGBA and RGB (the common client formats) in the channels they name, known when the
        // loops below are compiled; any other order slot by slot.
        let kind = match slots {
            [Slot::R, Slot::G, Slot::B, Slot::A] => 4,
            [Slot::R, Slot::G, Slot::B] => 3,
            _ => 0,
        };
        let group = |b: &[u8]| match kind {
            4 => group_bytes::<4>(b, slots),
            3 => group_bytes::<3>(b, slots),
            _ => group_bytes::<0>(b, slots),
        };
        // Columns that are one run i0, i0 + 1, .. (a whole row, as TexImage reads): each row's
        // groups are then one run of bytes, `n` apart (UNSIGNED_BYTE: a group is its `n`
        // bytes), converted without a bounds check per group. A row not wholly inside `data`
        // takes the per-group route (whose missing groups are (0, 0, 0, 255)).
        let run = cols.first().copied().filter(|&i0| {
            n >= 1
                && l.pixel == n
                && cols
                    .iter()
                    .enumerate()
                    .all(|(q, &i)| i0.checked_add(q) == Some(i))
        });
        for &j in rows {
            if let Some(i0) = run {
                let at = l.at(i0, j);
                let end = cols
                    .len()
                    .checked_mul(n)
                    .and_then(|len| at.checked_add(len));
                if let Some(row) = end.and_then(|e| self.data.get(at..e)) {
                    let groups = row.chunks_exact(n);
                    match kind {
                        4 => out.extend(groups.map(|b| group_bytes::<4>(b, slots))),
                        3 => out.extend(groups.map(|b| group_bytes::<3>(b, slots))),
                        _ => out.extend(groups.map(|b| group_bytes::<0>(b, slots))),
                    }
                    continue;
                }
            }
            for &i in cols {
                let at = l.at(i, j);
                out.push(self.data.get(at..at + n).map_or([0, 0, 0, 255], group));
            }
        }
        Some(())
    }

    /// The depth of group (`i`, `j`) of a DEPTH_COMPONENT image, before any transfer (unsigned
    /// integers c / (2^b − 1), in double precision: 32-bit depths need more than a float).
    pub fn depth(&self, i: usize, j: usize) -> f64 {
        match (&self.layout, self.format.ty) {
            (ImageLayout::Bytes(l), Ty::Scalar(s)) => {
                let bits = self.raw(l, i, j, 0).0;
                match s {
                    Scalar::U32 => f64::from(bits) / f64::from(u32::MAX),
                    Scalar::I32 => {
                        convert::signed_to_unit(f64::from(bits as i32), f64::from(u32::MAX))
                    }
                    _ => f64::from(normalized(s, bits)),
                }
            }
            // UNSIGNED_INT_24_8: the 24-bit field over 2^24 − 1, in double precision.
            (ImageLayout::Bytes(l), Ty::Packed { .. }) => {
                let (v, bits) = self.raw(l, i, j, 0);
                f64::from(v) / f64::from((1u32 << bits.unwrap_or(1)) - 1)
            }
            _ => 0.0,
        }
    }

    /// The index of group (`i`, `j`) of a COLOR_INDEX, STENCIL_INDEX or DEPTH_STENCIL image,
    /// before any transfer (BITMAP: 0 or 1).
    pub fn index(&self, i: usize, j: usize) -> i64 {
        match (&self.layout, self.format.ty) {
            (ImageLayout::Bits(b), _) => i64::from(b.bit(self.data, i, j)),
            (ImageLayout::Bytes(l), Ty::Scalar(s)) => index_value(s, self.raw(l, i, j, 0).0),
            // UNSIGNED_INT_24_8: the low 8 bits, after the depth.
            (ImageLayout::Bytes(l), Ty::Packed { .. }) => i64::from(self.raw(l, i, j, 1).0),
            _ => 0,
        }
    }
}

/// The unpack modes of the tightly packed images a display list holds (§5.4): alignment 1, no
/// row length or skips, the host's byte order, bits most significant first.
pub const TIGHT: PixelModes = PixelModes {
    swap_bytes: false,
    lsb_first: false,
    row_length: 0,
    image_height: 0,
    skip_rows: 0,
    skip_pixels: 0,
    skip_images: 0,
    alignment: 1,
};

/// The image `data` of `f` unpacked under `modes`, repacked in the [`TIGHT`] layout, or None
/// when `data` is shorter than the image spans.
pub fn repack(modes: &PixelModes, f: Format, w: i32, h: i32, data: &[u8]) -> Option<Vec<u8>> {
    let from = modes
        .image_layout(f, w, h)
        .filter(|l| data.len() >= l.need())?;
    let to = TIGHT.image_layout(f, w, h)?;
    let mut out = Vec::new();
    out.try_reserve_exact(to.need()).ok()?;
    out.resize(to.need(), 0);
    let (w, h) = (w.max(0) as usize, h.max(0) as usize);
    match (from, to) {
        (ImageLayout::Bits(a), ImageLayout::Bits(b)) => {
            for j in 0..h {
                for i in 0..w {
                    if a.bit(data, i, j) {
                        let at = b.offset + j * b.stride + i / 8;
                        if let Some(byte) = out.get_mut(at) {
                            *byte |= 0x80 >> (i % 8);
                        }
                    }
                }
            }
        }
        (ImageLayout::Bytes(a), ImageLayout::Bytes(b)) => {
            let elem = a.size.max(1);
            for j in 0..h {
                for i in 0..w {
                    let (s, d) = (a.at(i, j), b.at(i, j));
                    for k in 0..a.pixel / elem {
                        let (s, d) = (s + k * elem, d + k * elem);
                        let (Some(src), Some(dst)) =
                            (data.get(s..s + elem), out.get_mut(d..d + elem))
                        else {
                            continue;
                        };
                        dst.copy_from_slice(src);
                        a.order(dst);
                    }
                }
            }
        }
        _ => return None,
    }
    Some(out)
}

/// The calls [`compile_unpacked`] may store as something else: DrawPixels and Bitmap. For
/// every other call it is `None` after this one test, so a display list being compiled stores
/// those as they are without calling it (`Context::capture`).
#[inline(always)]
pub fn unpacks_at_compile(call: &crate::Call) -> bool {
    matches!(call, crate::Call::DrawPixels(..) | crate::Call::Bitmap(..))
}

/// The call a display list stores for `call` (GL 2.1 §5.4): DrawPixels and Bitmap with their
/// groups unpacked under `modes` (the unpack modes at compile time) into the [`TIGHT`] layout,
/// which a call executed from a list is read under; None for every other call (stored as it
/// is). A DrawPixels whose format, type or size is in error is stored as it is, to raise its
/// error when the list runs; one whose data is short is stored with none, for the same reason.
pub fn compile_unpacked(modes: &PixelModes, call: &crate::Call) -> Option<crate::Call> {
    use crate::Call;
    if !unpacks_at_compile(call) {
        return None;
    }
    match call {
        Call::DrawPixels(w, h, format, ty, data) => {
            let f = check(*format, *ty).ok().filter(|_| *w >= 0 && *h >= 0)?;
            let tight = repack(modes, f, *w, *h, data).unwrap_or_default();
            Some(Call::DrawPixels(*w, *h, *format, *ty, Box::new(tight)))
        }
        Call::Bitmap(w, h, xo, yo, xm, ym, data) => {
            let bits = data.as_deref()?;
            if *w < 0 || *h < 0 {
                return None;
            }
            let f = Format {
                group: Group::Index,
                ty: Ty::Bitmap,
            };
            let tight = repack(modes, f, *w, *h, bits).unwrap_or_default();
            Some(Call::Bitmap(
                *w,
                *h,
                *xo,
                *yo,
                *xm,
                *ym,
                Box::new(Some(tight)),
            ))
        }
        _ => None,
    }
}

/// The pixel maps (GL 2.1 §3.6.3, table 6.24), in the order of their enums from
/// PIXEL_MAP_I_TO_I: I_TO_I, S_TO_S, I_TO_R, I_TO_G, I_TO_B, I_TO_A, R_TO_R, G_TO_G, B_TO_B,
/// A_TO_A. Each holds 1 to MAX_PIXEL_MAP_TABLE entries, initially one 0 (table 6.24). In no
/// attribute group.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelMaps {
    /// The tables, by `map - PIXEL_MAP_I_TO_I`; the colour tables' entries are clamped to [0, 1].
    pub tables: [Vec<f32>; 10],
}

impl Default for PixelMaps {
    fn default() -> Self {
        Self {
            tables: std::array::from_fn(|_| vec![0.0]),
        }
    }
}

/// The table index of a pixel map enum, or None (INVALID_ENUM).
pub fn map_index(map: u32) -> Option<usize> {
    let k = map.checked_sub(gl::PIXEL_MAP_I_TO_I)? as usize;
    (k < 10).then_some(k)
}

/// I_TO_I and S_TO_S hold indices; the other eight tables colours.
pub fn is_index_map(k: usize) -> bool {
    k < 2
}

/// Index of the I_TO_R table (I_TO_G, I_TO_B, I_TO_A follow).
const I_TO_R: usize = 2;
/// Index of the R_TO_R table (G_TO_G, B_TO_B, A_TO_A follow).
const R_TO_R: usize = 6;
/// Index of the S_TO_S table.
const S_TO_S: usize = 1;

/// The pixel transfer parameters (GL 2.1 §3.6.3 table 3.2, state table 6.23, attribute "pixel")
/// and the zoom factors (§3.6.5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelTransfer {
    /// MAP_COLOR.
    pub map_color: bool,
    /// MAP_STENCIL.
    pub map_stencil: bool,
    /// INDEX_SHIFT.
    pub index_shift: i32,
    /// INDEX_OFFSET.
    pub index_offset: i32,
    /// RED_SCALE, GREEN_SCALE, BLUE_SCALE, ALPHA_SCALE.
    pub scale: [f32; 4],
    /// RED_BIAS, GREEN_BIAS, BLUE_BIAS, ALPHA_BIAS.
    pub bias: [f32; 4],
    /// DEPTH_SCALE.
    pub depth_scale: f32,
    /// DEPTH_BIAS.
    pub depth_bias: f32,
    /// ZOOM_X, ZOOM_Y.
    pub zoom: [f32; 2],
}

impl Default for PixelTransfer {
    fn default() -> Self {
        Self {
            map_color: false,
            map_stencil: false,
            index_shift: 0,
            index_offset: 0,
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            zoom: [1.0, 1.0],
        }
    }
}

/// A PixelTransfer parameter (table 3.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransferParam {
    /// MAP_COLOR.
    MapColor,
    /// MAP_STENCIL.
    MapStencil,
    /// INDEX_SHIFT.
    IndexShift,
    /// INDEX_OFFSET.
    IndexOffset,
    /// x_SCALE of component 0..3 (R, G, B, A).
    Scale(usize),
    /// x_BIAS of component 0..3.
    Bias(usize),
    /// DEPTH_SCALE.
    DepthScale,
    /// DEPTH_BIAS.
    DepthBias,
}

impl TransferParam {
    /// The parameter `pname` names, or None (INVALID_ENUM: the imaging subset's
    /// POST_CONVOLUTION_* and POST_COLOR_MATRIX_* are not supported, as in Mesa).
    pub fn of(pname: u32) -> Option<TransferParam> {
        use TransferParam::*;
        Some(match pname {
            gl::MAP_COLOR => MapColor,
            gl::MAP_STENCIL => MapStencil,
            gl::INDEX_SHIFT => IndexShift,
            gl::INDEX_OFFSET => IndexOffset,
            gl::RED_SCALE => Scale(0),
            gl::GREEN_SCALE => Scale(1),
            gl::BLUE_SCALE => Scale(2),
            gl::ALPHA_SCALE => Scale(3),
            gl::RED_BIAS => Bias(0),
            gl::GREEN_BIAS => Bias(1),
            gl::BLUE_BIAS => Bias(2),
            gl::ALPHA_BIAS => Bias(3),
            gl::DEPTH_SCALE => DepthScale,
            gl::DEPTH_BIAS => DepthBias,
            _ => return None,
        })
    }
}

impl PixelTransfer {
    /// Sets `p` from PixelTransferf's `v`: booleans are TRUE for any nonzero value, the index
    /// shift and offset truncate (as Mesa's `(GLint) param`, saturating here), the others take
    /// the float as it is.
    pub fn set(&mut self, p: TransferParam, v: f32) {
        match p {
            TransferParam::MapColor => self.map_color = v != 0.0,
            TransferParam::MapStencil => self.map_stencil = v != 0.0,
            TransferParam::IndexShift => self.index_shift = v as i32,
            TransferParam::IndexOffset => self.index_offset = v as i32,
            TransferParam::Scale(k) => {
                if let Some(s) = self.scale.get_mut(k) {
                    *s = v;
                }
            }
            TransferParam::Bias(k) => {
                if let Some(b) = self.bias.get_mut(k) {
                    *b = v;
                }
            }
            TransferParam::DepthScale => self.depth_scale = v,
            TransferParam::DepthBias => self.depth_bias = v,
        }
    }

    /// Whether a colour passes unchanged: scales 1, biases 0, MAP_COLOR off.
    pub fn color_is_identity(&self) -> bool {
        self.scale == [1.0; 4] && self.bias == [0.0; 4] && !self.map_color
    }

    /// Whether a depth passes unchanged.
    pub fn depth_is_identity(&self) -> bool {
        self.depth_scale == 1.0 && self.depth_bias == 0.0
    }

    /// Whether a stencil index passes unchanged (no shift, offset or map).
    pub fn stencil_is_identity(&self) -> bool {
        self.index_shift == 0 && self.index_offset == 0 && !self.map_stencil
    }

    /// An RGBA colour through the transfer (§3.6.5): scale and bias, then, with MAP_COLOR, each
    /// component clamped to [0, 1] and looked up in its R_TO_R .. A_TO_A table at
    /// round(c · (size − 1)) (ties to even, as Mesa's `_mesa_map_rgba`); then clamped to [0, 1]
    /// (the final conversion of §3.6.5).
    pub fn color(&self, maps: &PixelMaps, c: [f32; 4]) -> [f32; 4] {
        let mut out = [0.0; 4];
        for k in 0..4 {
            let mut v = c[k] * self.scale[k] + self.bias[k];
            if self.map_color {
                v = lookup(&maps.tables[R_TO_R + k], v);
            }
            out[k] = clamp01(v);
        }
        out
    }

    /// An index shifted by INDEX_SHIFT (left when positive, right when negative) and offset
    /// by INDEX_OFFSET (§3.6.5 "Arithmetic on Indices"), on 32-bit integers as Mesa does.
    pub fn shift_offset(&self, idx: i64) -> u32 {
        let v = idx as u32;
        let s = self.index_shift;
        let shifted = if s >= 0 {
            v.checked_shl(s as u32).unwrap_or(0)
        } else {
            v.checked_shr(s.unsigned_abs()).unwrap_or(0)
        };
        shifted.wrapping_add(self.index_offset as u32)
    }

    /// A colour index made RGBA (§3.6.5, RGBA mode): shifted and offset, then looked up in the
    /// I_TO_R, I_TO_G, I_TO_B and I_TO_A tables at the index masked by (size − 1).
    pub fn index_to_rgba(&self, maps: &PixelMaps, idx: i64) -> [f32; 4] {
        let v = self.shift_offset(idx);
        std::array::from_fn(|k| {
            let t = &maps.tables[I_TO_R + k];
            let i = (v as usize) & (t.len().max(1) - 1);
            clamp01(t.get(i).copied().unwrap_or(0.0))
        })
    }

    /// A stencil index through the transfer: shifted and offset, then, with MAP_STENCIL, looked
    /// up in S_TO_S at the index masked by (size − 1); the result masked to the 8-bit buffer.
    pub fn stencil(&self, maps: &PixelMaps, idx: i64) -> u8 {
        let mut v = self.shift_offset(idx);
        if self.map_stencil {
            let t = &maps.tables[S_TO_S];
            let i = (v as usize) & (t.len().max(1) - 1);
            v = t.get(i).copied().unwrap_or(0.0) as i64 as u32;
        }
        (v & 0xFF) as u8
    }

    /// A depth through the transfer: scaled and biased, clamped to [0, 1].
    pub fn depth(&self, d: f64) -> f64 {
        let v = if self.depth_is_identity() {
            d
        } else {
            d * f64::from(self.depth_scale) + f64::from(self.depth_bias)
        };
        if v.is_nan() {
            0.0
        } else {
            v.clamp(0.0, 1.0)
        }
    }
}

/// `v` clamped to [0, 1] (NaN gives 0).
#[inline]
fn clamp01(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

/// The entry of colour table `t` for component `v` (§3.6.5 "RGBA to RGBA Lookup").
#[inline]
fn lookup(t: &[f32], v: f32) -> f32 {
    let n = t.len().max(1);
    let x = clamp01(v) * (n - 1) as f32;
    let i = (x.round_ties_even() as usize).min(n - 1);
    t.get(i).copied().unwrap_or(0.0)
}

/// A shared, copy-on-write handle to the maps: `State` clones it cheaply (PushAttrib entries,
/// background draws), and PixelMap copies it only while another holder still has the old one.
pub type SharedMaps = Arc<PixelMaps>;

#[cfg(test)]
mod tests {
    use super::*;

    /// `push_row` appends what `bit` gives for each column: random layouts (either bit order,
    /// skips, strides), columns in any order and past the row, rows past the data.
    #[test]
    fn push_row_is_bit_for_each_column() {
        let mut seed = 17u64;
        let mut next = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as usize
        };
        for case in 0..3000 {
            let data: Vec<u8> = (0..next() % 200).map(|_| next() as u8).collect();
            let l = BitLayout {
                offset: next() % 40,
                stride: 1 + next() % 12,
                skip: next() % 30,
                lsb_first: next() % 2 == 1,
                need: 0,
            };
            let cols: Vec<usize> = match case % 2 {
                0 => (next() % 9..next() % 120).collect(),
                _ => (0..next() % 60).map(|_| next() % 150).collect(),
            };
            let j = next() % 30;
            let mut out = vec![7u8];
            l.push_row(&data, &cols, j, &mut out);
            let want: Vec<u8> = std::iter::once(7)
                .chain(cols.iter().map(|&i| u8::from(l.bit(&data, i, j))))
                .collect();
            assert_eq!(out, want, "case {case}: {l:?} row {j}");
            // The same columns as a run, where they are one.
            if let (Some(&i0), true) = (cols.first(), case % 2 == 0) {
                let mut run = vec![7u8];
                l.push_run(&data, i0, cols.len(), j, &mut run);
                assert_eq!(run, want, "case {case}: run {l:?} row {j}");
            }
        }
    }

    #[test]
    fn format_and_type_errors_follow_gl_2_1_in_mesas_order() {
        assert!(check(gl::RGBA, gl::UNSIGNED_BYTE).is_ok());
        assert!(check(gl::COLOR_INDEX, gl::BITMAP).is_ok());
        assert!(check(gl::STENCIL_INDEX, gl::BITMAP).is_ok());
        assert_eq!(check(gl::RGBA, gl::BITMAP), Err(gl::INVALID_ENUM));
        assert!(check(gl::RGB, gl::UNSIGNED_SHORT_5_6_5).is_ok());
        assert!(check(gl::BGRA, gl::UNSIGNED_INT_2_10_10_10_REV).is_ok());
        assert_eq!(
            check(gl::RGBA, gl::UNSIGNED_SHORT_5_6_5),
            Err(gl::INVALID_OPERATION)
        );
        assert_eq!(
            check(gl::RGB, gl::UNSIGNED_INT_8_8_8_8),
            Err(gl::INVALID_OPERATION)
        );
        // The type's check comes first: a packed type with a bad format is INVALID_OPERATION.
        assert_eq!(
            check(gl::TRIANGLES, gl::UNSIGNED_BYTE_3_3_2),
            Err(gl::INVALID_OPERATION)
        );
        assert_eq!(
            check(gl::TRIANGLES, gl::UNSIGNED_BYTE),
            Err(gl::INVALID_ENUM)
        );
        assert_eq!(check(gl::RGBA, 0x140B), Err(gl::INVALID_ENUM)); // HALF_FLOAT
        assert_eq!(check(gl::RGBA, gl::RGBA), Err(gl::INVALID_ENUM));
    }

    #[test]
    fn bitmap_layout_and_bit_order() {
        let m = PixelModes {
            alignment: 2,
            skip_pixels: 3,
            skip_rows: 1,
            row_length: 20,
            ..PixelModes::default()
        };
        // Rows of 20 bits: 3 bytes, padded to 4 (alignment 2); one row skipped.
        let b = m.bitmap_layout(9, 2).unwrap();
        assert_eq!((b.offset, b.stride, b.skip), (4, 4, 3));
        // Last row: 4 + 4 bytes in, bits 3..12 of it: 2 bytes.
        assert_eq!(b.need, 4 + 4 + 2);
        let data = [0, 0, 0, 0, 0b0001_0000, 0, 0, 0, 0, 0b1000_0000];
        // MSB first: bit 3 of the first row is 0x10 of byte 4.
        assert!(b.bit(&data, 0, 0));
        assert!(!b.bit(&data, 1, 0));
        // Row 1, group 5: bit 8 → byte 9, MSB.
        assert!(b.bit(&data, 5, 1));
        let lsb = PixelModes {
            lsb_first: true,
            ..m
        }
        .bitmap_layout(9, 2)
        .unwrap();
        assert!(!lsb.bit(&data, 0, 0));
        // LSB first: bit 3 is 0x08.
        assert!(lsb.bit(&[0, 0, 0, 0, 0b0000_1000], 0, 0));
        assert_eq!(PixelModes::default().bitmap_layout(0, 5).unwrap().need, 0);
    }

    /// `bytes` of columns that are one run (each row's groups as one run of bytes) gives what
    /// the per-group route gives (the same columns in reverse order, a row's output reversed
    /// back): every UNSIGNED_BYTE colour format, random alignments, row lengths and skips,
    /// runs from any column, rows past the data and data cut short in a row (whose missing
    /// groups are (0, 0, 0, 255)).
    #[test]
    fn bytes_of_a_run_of_columns_are_the_per_group_route() {
        let mut seed = 0x2545_f491u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed as usize
        };
        let formats = [
            gl::RGBA,
            gl::RGB,
            gl::BGRA,
            gl::BGR,
            gl::ABGR_EXT,
            gl::RED,
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
        ];
        let mut runs = 0;
        for case in 0..3000 {
            let format = formats[case % formats.len()];
            let Ok(f) = check(format, gl::UNSIGNED_BYTE) else {
                continue;
            };
            let modes = PixelModes {
                alignment: [1, 2, 4, 8][next() % 4],
                row_length: (next() % 3 == 0) as i32 * (next() % 20) as i32,
                skip_pixels: (next() % 3) as i32,
                skip_rows: (next() % 3) as i32,
                ..PixelModes::default()
            };
            let (w, h) = (1 + next() % 19, 1 + next() % 9);
            let Some(layout) = modes.layout(w as i32, h as i32, f.group.components(), 1) else {
                continue;
            };
            // Mostly the whole image; sometimes cut short inside a row.
            let len = match case % 3 {
                0 => layout.need.saturating_sub(next() % 7),
                _ => layout.need,
            };
            let data: Vec<u8> = (0..len).map(|_| next() as u8).collect();
            let img = Image {
                data: &data,
                format: f,
                layout: ImageLayout::Bytes(layout),
            };
            let i0 = next() % w;
            let cols: Vec<usize> = (i0..w).collect();
            let rows: Vec<usize> = (0..h + 1).collect();
            let mut run = vec![[1, 2, 3, 4]];
            assert!(img.bytes(&cols, &rows, &mut run).is_some());
            let back: Vec<usize> = cols.iter().rev().copied().collect();
            let mut want = vec![[1, 2, 3, 4]];
            for &j in &rows {
                let mut row = Vec::new();
                assert!(img.bytes(&back, &[j], &mut row).is_some());
                want.extend(row.iter().rev());
            }
            assert_eq!(
                run, want,
                "case {case}: format {format:#x} {w}x{h} {layout:?}"
            );
            runs += 1;
        }
        assert!(runs > 2000, "{runs}");
    }

    #[test]
    fn packed_and_scalar_components() {
        let modes = PixelModes {
            alignment: 1,
            ..PixelModes::default()
        };
        let f = check(gl::RGB, gl::UNSIGNED_SHORT_5_6_5).unwrap();
        let layout = modes.image_layout(f, 1, 1).unwrap();
        // R = 31, G = 0, B = 1: 0b11111_000000_00001.
        let data = 0b1111_1000_0000_0001u16.to_ne_bytes();
        let img = Image {
            data: &data,
            format: f,
            layout,
        };
        assert_eq!(img.color(0, 0), [1.0, 0.0, 1.0 / 31.0, 1.0]);
        let f = check(gl::BGRA, gl::UNSIGNED_INT_8_8_8_8_REV).unwrap();
        let data = 0x80_40_20_10u32.to_ne_bytes();
        let layout = modes.image_layout(f, 1, 1).unwrap();
        let img = Image {
            data: &data,
            format: f,
            layout,
        };
        // B in bits 0..7 (0x10), G 0x20, R 0x40, A 0x80.
        let c = img.color(0, 0);
        assert_eq!(c, [64.0 / 255.0, 32.0 / 255.0, 16.0 / 255.0, 128.0 / 255.0]);
        let f = check(gl::LUMINANCE_ALPHA, gl::UNSIGNED_BYTE).unwrap();
        let layout = modes.image_layout(f, 1, 1).unwrap();
        let img = Image {
            data: &[51, 255],
            format: f,
            layout,
        };
        assert_eq!(img.color(0, 0), [0.2, 0.2, 0.2, 1.0]);
        // The table is the conversion.
        for c in 0..=255u8 {
            assert_eq!(
                U8_UNIT[usize::from(c)],
                normalized(Scalar::U8, u32::from(c))
            );
        }
    }

    #[test]
    fn transfer_scale_bias_maps_and_indices() {
        let mut maps = PixelMaps::default();
        let mut t = PixelTransfer::default();
        assert_eq!(
            t.color(&maps, [0.5, 2.0, -1.0, 0.25]),
            [0.5, 1.0, 0.0, 0.25]
        );
        t.set(TransferParam::Scale(0), 0.5);
        t.set(TransferParam::Bias(1), 0.25);
        assert_eq!(t.color(&maps, [1.0, 0.5, 0.0, 1.0]), [0.5, 0.75, 0.0, 1.0]);
        // A two-entry red map: 0.25·1 = 0.25 rounds to entry 0, 0.75 to entry 1.
        t = PixelTransfer::default();
        t.map_color = true;
        maps.tables[R_TO_R] = vec![0.1, 0.9];
        maps.tables[R_TO_R + 3] = vec![1.0];
        let c = t.color(&maps, [0.25, 0.0, 0.0, 0.3]);
        assert_eq!((c[0], c[3]), (0.1, 1.0));
        assert_eq!(t.color(&maps, [0.75, 0.0, 0.0, 0.0])[0], 0.9);
        // Indices: shift 2 then offset 1; an I_TO_R table of 4 entries masks with 3.
        t.index_shift = 2;
        t.index_offset = 1;
        assert_eq!(t.shift_offset(3), 13);
        t.index_shift = -1;
        assert_eq!(t.shift_offset(6), 4);
        t.index_shift = 0;
        t.index_offset = 0;
        maps.tables[I_TO_R] = vec![0.0, 0.25, 0.5, 0.75];
        assert_eq!(t.index_to_rgba(&maps, 6)[0], 0.5);
        // Stencil: masked to 8 bits; S_TO_S when MAP_STENCIL.
        assert_eq!(t.stencil(&maps, 0x1FF), 0xFF);
        t.map_stencil = true;
        maps.tables[S_TO_S] = vec![7.0, 9.0];
        assert_eq!(t.stencil(&maps, 3), 9);
        assert_eq!(t.depth(0.5), 0.5);
        t.depth_scale = 4.0;
        assert_eq!(t.depth(0.5), 1.0);
    }
}
