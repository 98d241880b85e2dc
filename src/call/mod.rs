//! The recorded call stream: one `Call` variant per GL command, arguments owned.
//!
//! A `Vec<Call>` is what a context records, what a display list holds, what the real-GL backend
//! replays and what a recording file stores. The enum, its names and its classifiers are
//! generated from the command table (`crate::commands`), and so are the front end's and the GL
//! backend's matches over it, each exhaustive (no `_ =>` arm).
//!
//! Variants are named as the GL function without `gl` (`glNormal3f` → `Normal3f`) and take the
//! GL types one to one; vector forms whose length GL fixes keep their own variant with an array
//! (`Normal3fv([f32; 3])`), so a replay calls exactly the entry point the user called. Forms whose
//! length depends on a pname (`Lightfv`) own a `Vec` holding exactly the slice the caller passed.
//!
//! Size matters: a frame of the 400x400 lecture surface records 1.6M calls, and every replay
//! streams them from memory, so `size_of::<Call>()` is a per-call cost. Rare calls with large
//! arguments (the 16-element matrices, `Frustum`/`Ortho`, the texture image calls) keep them boxed
//! (the `box`, `pack` and `tuple` annotations), which holds every call to 40 bytes instead of 136
//! (the test below keeps it there).

/// `TexImage2D`'s arguments: target, level, internalformat, width, height, border, format, type,
/// pixels (`None`: a NULL pointer).
pub type TexImage2DArgs = (u32, i32, i32, i32, i32, i32, u32, u32, Option<Vec<u8>>);
/// `TexSubImage2D`'s arguments: target, level, xoffset, yoffset, width, height, format, type,
/// pixels.
pub type TexSubImage2DArgs = (u32, i32, i32, i32, i32, i32, u32, u32, Vec<u8>);
/// `TexImage1D`'s arguments: target, level, internalformat, width, border, format, type, pixels
/// (`None`: a NULL pointer).
pub type TexImage1DArgs = (u32, i32, i32, i32, i32, u32, u32, Option<Vec<u8>>);
/// `TexImage3D`'s arguments: target, level, internalformat, width, height, depth, border,
/// format, type, pixels (`None`: a NULL pointer).
pub type TexImage3DArgs = (u32, i32, i32, i32, i32, i32, i32, u32, u32, Option<Vec<u8>>);
/// `TexSubImage1D`'s arguments: target, level, xoffset, width, format, type, pixels.
pub type TexSubImage1DArgs = (u32, i32, i32, i32, u32, u32, Vec<u8>);
/// `TexSubImage3D`'s arguments: target, level, xoffset, yoffset, zoffset, width, height, depth,
/// format, type, pixels.
pub type TexSubImage3DArgs = (u32, i32, i32, i32, i32, i32, i32, i32, u32, u32, Vec<u8>);

/// `CompressedTexImage1D`'s arguments: target, level, internalformat, width, border, imageSize,
/// data (`None`: a NULL pointer; otherwise the bytes as the caller passed them).
pub type CompressedTexImage1DArgs = (u32, i32, u32, i32, i32, i32, Option<Vec<u8>>);
/// `CompressedTexImage2D`'s arguments: target, level, internalformat, width, height, border,
/// imageSize, data (as `CompressedTexImage1DArgs`).
pub type CompressedTexImage2DArgs = (u32, i32, u32, i32, i32, i32, i32, Option<Vec<u8>>);
/// `CompressedTexImage3D`'s arguments: target, level, internalformat, width, height, depth,
/// border, imageSize, data (as `CompressedTexImage1DArgs`).
pub type CompressedTexImage3DArgs = (u32, i32, u32, i32, i32, i32, i32, i32, Option<Vec<u8>>);
/// `CompressedTexSubImage1D`'s arguments: target, level, xoffset, width, format, imageSize,
/// data (as `CompressedTexImage1DArgs`).
pub type CompressedTexSubImage1DArgs = (u32, i32, i32, i32, u32, i32, Option<Vec<u8>>);
/// `CompressedTexSubImage2D`'s arguments: target, level, xoffset, yoffset, width, height,
/// format, imageSize, data (as `CompressedTexImage1DArgs`).
pub type CompressedTexSubImage2DArgs = (u32, i32, i32, i32, i32, i32, u32, i32, Option<Vec<u8>>);
/// `CompressedTexSubImage3D`'s arguments: target, level, xoffset, yoffset, zoffset, width,
/// height, depth, format, imageSize, data (as `CompressedTexImage1DArgs`).
pub type CompressedTexSubImage3DArgs = (
    u32,
    i32,
    i32,
    i32,
    i32,
    i32,
    i32,
    i32,
    u32,
    i32,
    Option<Vec<u8>>,
);

/// `MultiDrawArrays`' arguments: mode, first, count, drawcount (the slices as the caller passed
/// them, however long).
pub type MultiDrawArraysArgs = (u32, Vec<i32>, Vec<i32>, i32);
/// `PrioritizeTextures`' arguments: n, textures, priorities (the slices as the caller passed
/// them, however long).
pub type PrioritizeTexturesArgs = (i32, Vec<u32>, Vec<f32>);
/// `MultiDrawElements`' arguments: mode, count, type, indices (one pointer per draw: client
/// bytes or an offset into the element buffer), drawcount.
pub type MultiDrawElementsArgs = (u32, Vec<i32>, u32, Vec<crate::arrays::Pointer>, i32);

/// `Map1f`'s arguments: target, u1, u2, stride, order, points (the slice as the caller passed
/// it; the map copies `order` points of it).
pub type Map1fArgs = (u32, f32, f32, i32, i32, Vec<f32>);
/// `Map1d`'s arguments, as `Map1fArgs`.
pub type Map1dArgs = (u32, f64, f64, i32, i32, Vec<f64>);
/// `Map2f`'s arguments: target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points.
pub type Map2fArgs = (u32, f32, f32, i32, i32, f32, f32, i32, i32, Vec<f32>);
/// `Map2d`'s arguments, as `Map2fArgs`.
pub type Map2dArgs = (u32, f64, f64, i32, i32, f64, f64, i32, i32, Vec<f64>);
/// `MapGrid2d`'s arguments: un, u1, u2, vn, v1, v2 (boxed: four doubles would grow every call).
pub type MapGrid2dArgs = (i32, f64, f64, i32, f64, f64);

/// What a program wrote through a MapBuffer mapping, recorded with the `UnmapBuffer` that ends
/// it: the offset of the first byte that changed and the bytes from there to the last one that
/// changed (`(0, [])`: nothing written). See `Context::map_buffer`.
pub type MapWrites = (usize, Vec<u8>);

mod generated;

pub use generated::{Call, NAMES, WINSYS};

/// What an argument of a call holds, for the recording format to write it readably (from the
/// registry's type and enum group of the parameter).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ArgKind {
    /// A number as it is.
    Plain,
    /// A GL enum: its name, or hex when it has none.
    Enum,
    /// A primitive mode: POINTS..POLYGON (whose values 0 and 1 also name FALSE, ZERO, ...).
    Prim,
    /// A blend factor: ZERO and ONE by those names.
    Blend,
    /// A `Clear` mask: buffer bit names joined by `|`.
    ClearBits,
}

#[cfg(test)]
mod tests {
    /// A replay streams every recorded call from memory: a variant that grows `Call` (say, an
    /// inline 16-element matrix) makes every `Vertex3f` of a 1.6M-call frame pay for it.
    #[test]
    fn call_stays_small() {
        assert!(
            std::mem::size_of::<super::Call>() <= 40,
            "{}",
            std::mem::size_of::<super::Call>()
        );
    }
}
