//! The recorded call stream: one `Call` variant per GL entry point, arguments owned.
//!
//! A `Vec<Call>` is what a context records, what a display list holds, what the real-GL backend
//! replays and what a recording file stores. Every consumer matches `Call` exhaustively (no `_ =>`
//! arm), so an entry point added here cannot be forgotten by a backend.
//!
//! Variants are named as the GL function without `gl` (`glNormal3f` → `Normal3f`) and take the
//! GL types one to one; vector forms whose length GL fixes keep their own variant with an array
//! (`Normal3fv([f32; 3])`), so a replay calls exactly the entry point the user called.
//!
//! Size matters: a frame of the 400x400 lecture surface records 1.6M calls, and every replay streams
//! them from memory, so `size_of::<Call>()` is a per-call cost. Rare calls with large arguments
//! (the 16-element matrices) keep them boxed, and so do `Frustum`/`Ortho` and the texture image calls, which holds every call to 40 bytes instead of 136 (the
//! test below keeps it there). Forms whose
//! length depends on a pname (`Lightfv`) own a `Vec` holding exactly the slice the caller passed.
//!
//! Variants are grouped by area of the spec, each with the module of `context` that validates it.

use serde::{Deserialize, Serialize};

use crate::arrays::Pointer;

/// `TexImage2D`'s arguments: target, level, internalformat, width, height, border, format, type,
/// pixels (`None`: a NULL pointer).
pub type TexImage2DArgs = (u32, i32, i32, i32, i32, i32, u32, u32, Option<Vec<u8>>);
/// `TexSubImage2D`'s arguments: target, level, xoffset, yoffset, width, height, format, type,
/// pixels.
pub type TexSubImage2DArgs = (u32, i32, i32, i32, i32, i32, u32, u32, Vec<u8>);

/// One GL call with its arguments.
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Call {
    // Begin/End and capabilities (GL 2.1 §2.6, §2.12)
    Begin(u32),
    End,
    Enable(u32),
    Disable(u32),
    MatrixMode(u32),
    LoadIdentity,
    LoadMatrixf(Box<[f32; 16]>),
    LoadMatrixd(Box<[f64; 16]>),
    MultMatrixf(Box<[f32; 16]>),
    MultMatrixd(Box<[f64; 16]>),
    LoadTransposeMatrixf(Box<[f32; 16]>),
    LoadTransposeMatrixd(Box<[f64; 16]>),
    MultTransposeMatrixf(Box<[f32; 16]>),
    MultTransposeMatrixd(Box<[f64; 16]>),
    Translatef(f32, f32, f32),
    Translated(f64, f64, f64),
    Rotatef(f32, f32, f32, f32),
    Rotated(f64, f64, f64, f64),
    Scalef(f32, f32, f32),
    Scaled(f64, f64, f64),
    /// left, right, bottom, top, near, far (boxed: see the module docs on size).
    Frustum(Box<[f64; 6]>),
    /// left, right, bottom, top, near, far (boxed: see the module docs on size).
    Ortho(Box<[f64; 6]>),
    PushMatrix,
    PopMatrix,
    Viewport(i32, i32, i32, i32),
    DepthRange(f64, f64),
    ClipPlane(u32, [f64; 4]),
    ActiveTexture(u32),
    ClientActiveTexture(u32),

    // Vertex attributes (GL 2.1 §2.7): context/vertex.rs
    Vertex2s(i16, i16),
    Vertex2i(i32, i32),
    Vertex2f(f32, f32),
    Vertex2d(f64, f64),
    Vertex3s(i16, i16, i16),
    Vertex3i(i32, i32, i32),
    Vertex3f(f32, f32, f32),
    Vertex3d(f64, f64, f64),
    Vertex4s(i16, i16, i16, i16),
    Vertex4i(i32, i32, i32, i32),
    Vertex4f(f32, f32, f32, f32),
    Vertex4d(f64, f64, f64, f64),
    Vertex2sv([i16; 2]),
    Vertex2iv([i32; 2]),
    Vertex2fv([f32; 2]),
    Vertex2dv([f64; 2]),
    Vertex3sv([i16; 3]),
    Vertex3iv([i32; 3]),
    Vertex3fv([f32; 3]),
    Vertex3dv([f64; 3]),
    Vertex4sv([i16; 4]),
    Vertex4iv([i32; 4]),
    Vertex4fv([f32; 4]),
    Vertex4dv([f64; 4]),

    Normal3b(i8, i8, i8),
    Normal3s(i16, i16, i16),
    Normal3i(i32, i32, i32),
    Normal3f(f32, f32, f32),
    Normal3d(f64, f64, f64),
    Normal3bv([i8; 3]),
    Normal3sv([i16; 3]),
    Normal3iv([i32; 3]),
    Normal3fv([f32; 3]),
    Normal3dv([f64; 3]),

    Color3b(i8, i8, i8),
    Color3s(i16, i16, i16),
    Color3i(i32, i32, i32),
    Color3f(f32, f32, f32),
    Color3d(f64, f64, f64),
    Color3ub(u8, u8, u8),
    Color3us(u16, u16, u16),
    Color3ui(u32, u32, u32),
    Color3bv([i8; 3]),
    Color3sv([i16; 3]),
    Color3iv([i32; 3]),
    Color3fv([f32; 3]),
    Color3dv([f64; 3]),
    Color3ubv([u8; 3]),
    Color3usv([u16; 3]),
    Color3uiv([u32; 3]),
    Color4b(i8, i8, i8, i8),
    Color4s(i16, i16, i16, i16),
    Color4i(i32, i32, i32, i32),
    Color4f(f32, f32, f32, f32),
    Color4d(f64, f64, f64, f64),
    Color4ub(u8, u8, u8, u8),
    Color4us(u16, u16, u16, u16),
    Color4ui(u32, u32, u32, u32),
    Color4bv([i8; 4]),
    Color4sv([i16; 4]),
    Color4iv([i32; 4]),
    Color4fv([f32; 4]),
    Color4dv([f64; 4]),
    Color4ubv([u8; 4]),
    Color4usv([u16; 4]),
    Color4uiv([u32; 4]),

    SecondaryColor3b(i8, i8, i8),
    SecondaryColor3s(i16, i16, i16),
    SecondaryColor3i(i32, i32, i32),
    SecondaryColor3f(f32, f32, f32),
    SecondaryColor3d(f64, f64, f64),
    SecondaryColor3ub(u8, u8, u8),
    SecondaryColor3us(u16, u16, u16),
    SecondaryColor3ui(u32, u32, u32),
    SecondaryColor3bv([i8; 3]),
    SecondaryColor3sv([i16; 3]),
    SecondaryColor3iv([i32; 3]),
    SecondaryColor3fv([f32; 3]),
    SecondaryColor3dv([f64; 3]),
    SecondaryColor3ubv([u8; 3]),
    SecondaryColor3usv([u16; 3]),
    SecondaryColor3uiv([u32; 3]),

    TexCoord1s(i16),
    TexCoord1i(i32),
    TexCoord1f(f32),
    TexCoord1d(f64),
    TexCoord2s(i16, i16),
    TexCoord2i(i32, i32),
    TexCoord2f(f32, f32),
    TexCoord2d(f64, f64),
    TexCoord3s(i16, i16, i16),
    TexCoord3i(i32, i32, i32),
    TexCoord3f(f32, f32, f32),
    TexCoord3d(f64, f64, f64),
    TexCoord4s(i16, i16, i16, i16),
    TexCoord4i(i32, i32, i32, i32),
    TexCoord4f(f32, f32, f32, f32),
    TexCoord4d(f64, f64, f64, f64),
    TexCoord1sv([i16; 1]),
    TexCoord1iv([i32; 1]),
    TexCoord1fv([f32; 1]),
    TexCoord1dv([f64; 1]),
    TexCoord2sv([i16; 2]),
    TexCoord2iv([i32; 2]),
    TexCoord2fv([f32; 2]),
    TexCoord2dv([f64; 2]),
    TexCoord3sv([i16; 3]),
    TexCoord3iv([i32; 3]),
    TexCoord3fv([f32; 3]),
    TexCoord3dv([f64; 3]),
    TexCoord4sv([i16; 4]),
    TexCoord4iv([i32; 4]),
    TexCoord4fv([f32; 4]),
    TexCoord4dv([f64; 4]),

    FogCoordf(f32),
    FogCoordd(f64),
    FogCoordfv([f32; 1]),
    FogCoorddv([f64; 1]),

    EdgeFlag(bool),
    EdgeFlagv([bool; 1]),

    // Lighting and shading (GL 2.1 §2.14): context/lighting.rs
    Materialf(u32, u32, f32),
    Materiali(u32, u32, i32),
    Materialfv(u32, u32, Vec<f32>),
    Materialiv(u32, u32, Vec<i32>),
    Lightf(u32, u32, f32),
    Lighti(u32, u32, i32),
    Lightfv(u32, u32, Vec<f32>),
    Lightiv(u32, u32, Vec<i32>),
    LightModelf(u32, f32),
    LightModeli(u32, i32),
    LightModelfv(u32, Vec<f32>),
    LightModeliv(u32, Vec<i32>),
    ColorMaterial(u32, u32),
    ShadeModel(u32),

    // Rasterisation (GL 2.1 §3.3 to §3.5): context/raster.rs
    FrontFace(u32),
    CullFace(u32),
    PolygonMode(u32, u32),
    PolygonOffset(f32, f32),
    PointSize(f32),
    LineWidth(f32),

    // Framebuffer and per-fragment control (GL 2.1 §4.1, §4.2): context/framebuffer.rs
    ClearColor(f32, f32, f32, f32),
    ClearDepth(f64),
    ClearStencil(i32),
    Clear(u32),
    DepthFunc(u32),
    DepthMask(bool),
    ColorMask(bool, bool, bool, bool),
    Scissor(i32, i32, i32, i32),

    // Hints, pixel store, flush (GL 2.1 §5.6, §3.6.1, §5.5): context/control.rs
    Hint(u32, u32),
    PixelStorei(u32, i32),
    PixelStoref(u32, f32),
    Flush,
    Finish,

    // Display lists, attribute stacks (GL 2.1 §5.4, §6.1.14): context/lists.rs, attrib.rs
    GenLists(i32),
    NewList(u32, u32),
    EndList,
    CallList(u32),
    /// `n`, `type`, and the bytes of the names array (exactly the `n` names GL reads, or the
    /// caller's shorter slice, which is INVALID_VALUE).
    CallLists(i32, u32, Vec<u8>),
    ListBase(u32),
    DeleteLists(u32, i32),
    PushAttrib(u32),
    PopAttrib,
    PushClientAttrib(u32),
    PopClientAttrib,

    // Vertex arrays (GL 2.1 §2.8) and buffer objects (§2.9).
    // A `Pointer` holds the bytes the caller handed over, or an offset into a bound buffer.
    EnableClientState(u32),
    DisableClientState(u32),
    VertexPointer(i32, u32, i32, Pointer),
    NormalPointer(u32, i32, Pointer),
    ColorPointer(i32, u32, i32, Pointer),
    SecondaryColorPointer(i32, u32, i32, Pointer),
    TexCoordPointer(i32, u32, i32, Pointer),
    FogCoordPointer(u32, i32, Pointer),
    EdgeFlagPointer(i32, Pointer),
    InterleavedArrays(u32, i32, Pointer),
    ArrayElement(i32),
    DrawArrays(u32, i32, i32),
    DrawElements(u32, i32, u32, Pointer),
    /// The index pointer is boxed, as in the next two: see the module docs on size.
    DrawRangeElements(u32, u32, u32, i32, u32, Box<Pointer>),
    /// `GenBuffers(n, names)`: the names the call returned (empty when it failed), so that a
    /// replay can check it gets the same ones.
    GenBuffers(i32, Vec<u32>),
    DeleteBuffers(i32, Vec<u32>),
    BindBuffer(u32, u32),
    BufferData(u32, isize, Box<Pointer>, u32),
    BufferSubData(u32, isize, isize, Box<Pointer>),
    // Fog and per-fragment operations (GL 2.1 §3.10, §4.1): context/fragment.rs
    Fogf(u32, f32),
    Fogi(u32, i32),
    Fogfv(u32, Vec<f32>),
    Fogiv(u32, Vec<i32>),
    AlphaFunc(u32, f32),
    StencilFunc(u32, i32, u32),
    StencilFuncSeparate(u32, u32, i32, u32),
    StencilOp(u32, u32, u32),
    StencilOpSeparate(u32, u32, u32, u32),
    StencilMask(u32),
    StencilMaskSeparate(u32, u32),
    BlendFunc(u32, u32),
    BlendFuncSeparate(u32, u32, u32, u32),
    BlendEquation(u32),
    BlendEquationSeparate(u32, u32),
    BlendColor(f32, f32, f32, f32),
    LogicOp(u32),

    GenTextures(i32),
    DeleteTextures(i32, Vec<u32>),
    BindTexture(u32, u32),
    /// target, level, internalformat, width, height, border, format, type, pixels (None: NULL);
    /// boxed, as the next one: eight integers would grow every call (see the module docs).
    TexImage2D(Box<TexImage2DArgs>),
    /// target, level, xoffset, yoffset, width, height, format, type, pixels.
    TexSubImage2D(Box<TexSubImage2DArgs>),
    /// target, level, internalformat, x, y, width, height, border.
    CopyTexImage2D(u32, i32, u32, i32, i32, i32, i32, i32),
    /// target, level, xoffset, yoffset, x, y, width, height.
    CopyTexSubImage2D(u32, i32, i32, i32, i32, i32, i32, i32),
    TexParameteri(u32, u32, i32),
    TexParameterf(u32, u32, f32),
    TexParameteriv(u32, u32, Vec<i32>),
    TexParameterfv(u32, u32, Vec<f32>),
    TexEnvi(u32, u32, i32),
    TexEnvf(u32, u32, f32),
    TexEnviv(u32, u32, Vec<i32>),
    TexEnvfv(u32, u32, Vec<f32>),
    TexGeni(u32, u32, i32),
    TexGenf(u32, u32, f32),
    TexGend(u32, u32, f64),
    TexGeniv(u32, u32, Vec<i32>),
    TexGenfv(u32, u32, Vec<f32>),
    TexGendv(u32, u32, Vec<f64>),
    MultiTexCoord1s(u32, i16),
    MultiTexCoord1sv(u32, [i16; 1]),
    MultiTexCoord1i(u32, i32),
    MultiTexCoord1iv(u32, [i32; 1]),
    MultiTexCoord1f(u32, f32),
    MultiTexCoord1fv(u32, [f32; 1]),
    MultiTexCoord1d(u32, f64),
    MultiTexCoord1dv(u32, [f64; 1]),
    MultiTexCoord2s(u32, i16, i16),
    MultiTexCoord2sv(u32, [i16; 2]),
    MultiTexCoord2i(u32, i32, i32),
    MultiTexCoord2iv(u32, [i32; 2]),
    MultiTexCoord2f(u32, f32, f32),
    MultiTexCoord2fv(u32, [f32; 2]),
    MultiTexCoord2d(u32, f64, f64),
    MultiTexCoord2dv(u32, [f64; 2]),
    MultiTexCoord3s(u32, i16, i16, i16),
    MultiTexCoord3sv(u32, [i16; 3]),
    MultiTexCoord3i(u32, i32, i32, i32),
    MultiTexCoord3iv(u32, [i32; 3]),
    MultiTexCoord3f(u32, f32, f32, f32),
    MultiTexCoord3fv(u32, [f32; 3]),
    MultiTexCoord3d(u32, f64, f64, f64),
    MultiTexCoord3dv(u32, [f64; 3]),
    MultiTexCoord4s(u32, i16, i16, i16, i16),
    MultiTexCoord4sv(u32, [i16; 4]),
    MultiTexCoord4i(u32, i32, i32, i32, i32),
    MultiTexCoord4iv(u32, [i32; 4]),
    MultiTexCoord4f(u32, f32, f32, f32, f32),
    MultiTexCoord4fv(u32, [f32; 4]),
    MultiTexCoord4d(u32, f64, f64, f64, f64),
    MultiTexCoord4dv(u32, [f64; 4]),
}

impl Call {
    /// Whether GL 2.1 §2.6.3 allows this command between Begin and End: the vertex attributes
    /// (Vertex, Normal, Color, SecondaryColor, TexCoord, MultiTexCoord, FogCoord, EdgeFlag),
    /// Material, ArrayElement, CallList(s) and End. Every other command raises INVALID_OPERATION
    /// there. The GL backend raises it itself rather than asking the driver, so that every error
    /// inside a Begin/End pair (where the driver's flag cannot be read) keeps its order.
    pub fn allowed_between_begin_end(&self) -> bool {
        matches!(
            self,
            Call::End
                | Call::Vertex2s(..)
                | Call::Vertex2i(..)
                | Call::Vertex2f(..)
                | Call::Vertex2d(..)
                | Call::Vertex3s(..)
                | Call::Vertex3i(..)
                | Call::Vertex3f(..)
                | Call::Vertex3d(..)
                | Call::Vertex4s(..)
                | Call::Vertex4i(..)
                | Call::Vertex4f(..)
                | Call::Vertex4d(..)
                | Call::Vertex2sv(..)
                | Call::Vertex2iv(..)
                | Call::Vertex2fv(..)
                | Call::Vertex2dv(..)
                | Call::Vertex3sv(..)
                | Call::Vertex3iv(..)
                | Call::Vertex3fv(..)
                | Call::Vertex3dv(..)
                | Call::Vertex4sv(..)
                | Call::Vertex4iv(..)
                | Call::Vertex4fv(..)
                | Call::Vertex4dv(..)
                | Call::Normal3b(..)
                | Call::Normal3s(..)
                | Call::Normal3i(..)
                | Call::Normal3f(..)
                | Call::Normal3d(..)
                | Call::Normal3bv(..)
                | Call::Normal3sv(..)
                | Call::Normal3iv(..)
                | Call::Normal3fv(..)
                | Call::Normal3dv(..)
                | Call::Color3b(..)
                | Call::Color3s(..)
                | Call::Color3i(..)
                | Call::Color3f(..)
                | Call::Color3d(..)
                | Call::Color3ub(..)
                | Call::Color3us(..)
                | Call::Color3ui(..)
                | Call::Color3bv(..)
                | Call::Color3sv(..)
                | Call::Color3iv(..)
                | Call::Color3fv(..)
                | Call::Color3dv(..)
                | Call::Color3ubv(..)
                | Call::Color3usv(..)
                | Call::Color3uiv(..)
                | Call::Color4b(..)
                | Call::Color4s(..)
                | Call::Color4i(..)
                | Call::Color4f(..)
                | Call::Color4d(..)
                | Call::Color4ub(..)
                | Call::Color4us(..)
                | Call::Color4ui(..)
                | Call::Color4bv(..)
                | Call::Color4sv(..)
                | Call::Color4iv(..)
                | Call::Color4fv(..)
                | Call::Color4dv(..)
                | Call::Color4ubv(..)
                | Call::Color4usv(..)
                | Call::Color4uiv(..)
                | Call::SecondaryColor3b(..)
                | Call::SecondaryColor3s(..)
                | Call::SecondaryColor3i(..)
                | Call::SecondaryColor3f(..)
                | Call::SecondaryColor3d(..)
                | Call::SecondaryColor3ub(..)
                | Call::SecondaryColor3us(..)
                | Call::SecondaryColor3ui(..)
                | Call::SecondaryColor3bv(..)
                | Call::SecondaryColor3sv(..)
                | Call::SecondaryColor3iv(..)
                | Call::SecondaryColor3fv(..)
                | Call::SecondaryColor3dv(..)
                | Call::SecondaryColor3ubv(..)
                | Call::SecondaryColor3usv(..)
                | Call::SecondaryColor3uiv(..)
                | Call::TexCoord1s(..)
                | Call::TexCoord1i(..)
                | Call::TexCoord1f(..)
                | Call::TexCoord1d(..)
                | Call::TexCoord2s(..)
                | Call::TexCoord2i(..)
                | Call::TexCoord2f(..)
                | Call::TexCoord2d(..)
                | Call::TexCoord3s(..)
                | Call::TexCoord3i(..)
                | Call::TexCoord3f(..)
                | Call::TexCoord3d(..)
                | Call::TexCoord4s(..)
                | Call::TexCoord4i(..)
                | Call::TexCoord4f(..)
                | Call::TexCoord4d(..)
                | Call::TexCoord1sv(..)
                | Call::TexCoord1iv(..)
                | Call::TexCoord1fv(..)
                | Call::TexCoord1dv(..)
                | Call::TexCoord2sv(..)
                | Call::TexCoord2iv(..)
                | Call::TexCoord2fv(..)
                | Call::TexCoord2dv(..)
                | Call::TexCoord3sv(..)
                | Call::TexCoord3iv(..)
                | Call::TexCoord3fv(..)
                | Call::TexCoord3dv(..)
                | Call::TexCoord4sv(..)
                | Call::TexCoord4iv(..)
                | Call::TexCoord4fv(..)
                | Call::TexCoord4dv(..)
                | Call::FogCoordf(..)
                | Call::FogCoordd(..)
                | Call::FogCoordfv(..)
                | Call::FogCoorddv(..)
                | Call::EdgeFlag(..)
                | Call::EdgeFlagv(..)
                | Call::Materialf(..)
                | Call::Materiali(..)
                | Call::Materialfv(..)
                | Call::Materialiv(..)
                | Call::CallList(..)
                | Call::CallLists(..)
                | Call::ArrayElement(..)
                | Call::MultiTexCoord1s(..)
                | Call::MultiTexCoord1sv(..)
                | Call::MultiTexCoord1i(..)
                | Call::MultiTexCoord1iv(..)
                | Call::MultiTexCoord1f(..)
                | Call::MultiTexCoord1fv(..)
                | Call::MultiTexCoord1d(..)
                | Call::MultiTexCoord1dv(..)
                | Call::MultiTexCoord2s(..)
                | Call::MultiTexCoord2sv(..)
                | Call::MultiTexCoord2i(..)
                | Call::MultiTexCoord2iv(..)
                | Call::MultiTexCoord2f(..)
                | Call::MultiTexCoord2fv(..)
                | Call::MultiTexCoord2d(..)
                | Call::MultiTexCoord2dv(..)
                | Call::MultiTexCoord3s(..)
                | Call::MultiTexCoord3sv(..)
                | Call::MultiTexCoord3i(..)
                | Call::MultiTexCoord3iv(..)
                | Call::MultiTexCoord3f(..)
                | Call::MultiTexCoord3fv(..)
                | Call::MultiTexCoord3d(..)
                | Call::MultiTexCoord3dv(..)
                | Call::MultiTexCoord4s(..)
                | Call::MultiTexCoord4sv(..)
                | Call::MultiTexCoord4i(..)
                | Call::MultiTexCoord4iv(..)
                | Call::MultiTexCoord4f(..)
                | Call::MultiTexCoord4fv(..)
                | Call::MultiTexCoord4d(..)
                | Call::MultiTexCoord4dv(..)
        )
    }
}

// Which calls a display list does not hold (GL 2.1 §5.4)
impl Call {
    /// Whether GL 2.1 §5.4 executes this command immediately instead of compiling it into the
    /// display list being defined: GenLists, DeleteLists, NewList, EndList, PixelStore, Flush,
    /// Finish, ClientActiveTexture, the client attribute stack, and (add them here) the other
    /// client-state and array-pointer commands (EnableClientState, *Pointer, InterleavedArrays),
    /// ReadPixels, RenderMode, GenTextures/DeleteTextures. The front end's `record!` and the GL
    /// backend both consult this one list.
    pub fn executes_immediately(&self) -> bool {
        matches!(
            self,
            Call::GenLists(..)
                | Call::DeleteLists(..)
                | Call::NewList(..)
                | Call::EndList
                | Call::PixelStorei(..)
                | Call::PixelStoref(..)
                | Call::Flush
                | Call::Finish
                | Call::ClientActiveTexture(..)
                | Call::PushClientAttrib(..)
                | Call::PopClientAttrib
                // Client state and buffer objects (GL 2.1 §5.4)
                | Call::EnableClientState(..)
                | Call::DisableClientState(..)
                | Call::VertexPointer(..)
                | Call::NormalPointer(..)
                | Call::ColorPointer(..)
                | Call::SecondaryColorPointer(..)
                | Call::TexCoordPointer(..)
                | Call::FogCoordPointer(..)
                | Call::EdgeFlagPointer(..)
                | Call::InterleavedArrays(..)
                | Call::GenBuffers(..)
                | Call::DeleteBuffers(..)
                | Call::BindBuffer(..)
                | Call::BufferData(..)
                | Call::BufferSubData(..)
                // Object names (GL 2.1 §5.4)
                | Call::GenTextures(..)
                | Call::DeleteTextures(..)
        )
    }
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
