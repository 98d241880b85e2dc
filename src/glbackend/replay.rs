//! The replay proper: each [`Call`] variant becomes the driver call of the same name with the
//! same arguments (GL 2.1 §2.5 onwards; the variant name is the GL function minus `gl`).
//!
//! Adding a variant is mechanical, by the argument shape:
//! - scalars: `Call::Normal3f(x, y, z) => unsafe { gl.Normal3f(x, y, z) }`;
//! - fixed-length arrays: `Call::Normal3fv(v) => unsafe { gl.Normal3fv(v.as_ptr()) }` (the array
//!   has exactly the length GL reads);
//! - pname-dependent slices: through [`GlBackend::with_params`] with the pname's count from
//!   [`params`], which raises INVALID_VALUE instead of letting a short slice reach the driver:
//!   `Call::Lightfv(l, p, ref v) => self.with_params(v, params::light(p), false, |gl, v| unsafe
//!   { gl.Lightfv(l, p, v) })` (`true` for Materialfv/iv, the only ones allowed in Begin/End);
//! - `ShadeModel(mode) => self.shade_model(mode)` (PHONG_WIN is emulated).
//!
//! Design decision: the match is exhaustive (no `_ =>`), so a variant the front end gains cannot
//! compile until it is replayed here.

use super::{raw, GlBackend};
use crate::gl;
use crate::Call;

impl GlBackend {
    /// Sends one recorded call to the driver, exactly as the user's program would have made it.
    pub fn execute(&mut self, call: &Call) {
        self.make_current();
        if !phong_neutral(call) {
            self.phong_dirty = true;
        }
        // lists: the mirror of the display list being defined (lists.rs).
        self.mirror_call(call);
        // GL 2.1 §2.6.3, raised here rather than by the driver: inside Begin/End the driver's
        // error flag cannot be read, so an error it held could not be ordered against one this
        // backend raises itself (a short slice, an array element it refuses to read).
        if self.inside_begin_end && !call.allowed_between_begin_end() {
            self.list_needs_expansion();
            return self.raise(gl::INVALID_OPERATION);
        }
        let gl = &self.raw;
        // SAFETY: the context is current on this thread (GlBackend is not Send) and every pointer
        // passed below points to at least as many elements as the driver reads for the call.
        match *call {
            // lists: under NewList(COMPILE) the driver stores Begin/End, nothing opens.
            Call::Begin(mode) if self.compile_only() => unsafe { gl.Begin(mode) },
            Call::End if self.compile_only() => unsafe { gl.End() },
            Call::Begin(mode) => {
                // GL 2.1 §2.6.1 has ten modes; a 3.2+ compatibility driver also accepts the
                // adjacency modes and PATCHES (0xA..=0xE), so the GL 2.1 INVALID_ENUM is raised
                // here. Inside Begin/End the driver's INVALID_OPERATION comes first, as in GL.
                if mode > gl::POLYGON && !self.inside_begin_end {
                    return self.raise(gl::INVALID_ENUM);
                }
                self.before_begin();
                unsafe { self.raw.Begin(mode) };
                // The driver opened a primitive iff none was open (the mode is valid here).
                self.inside_begin_end = true;
            }
            Call::End => {
                unsafe { gl.End() };
                self.inside_begin_end = false;
            }
            Call::Vertex3f(x, y, z) => unsafe { gl.Vertex3f(x, y, z) },
            Call::Normal3f(x, y, z) => unsafe { gl.Normal3f(x, y, z) },
            Call::Color4f(r, g, b, a) => unsafe { gl.Color4f(r, g, b, a) },
            Call::Enable(cap) => unsafe { gl.Enable(cap) },
            Call::Disable(cap) => unsafe { gl.Disable(cap) },
            Call::MatrixMode(a) => unsafe { gl.MatrixMode(a) },
            Call::LoadIdentity => unsafe { gl.LoadIdentity() },
            Call::LoadMatrixf(ref v) => unsafe { gl.LoadMatrixf(v.as_ptr()) },
            Call::LoadMatrixd(ref v) => unsafe { gl.LoadMatrixd(v.as_ptr()) },
            Call::MultMatrixf(ref v) => unsafe { gl.MultMatrixf(v.as_ptr()) },
            Call::MultMatrixd(ref v) => unsafe { gl.MultMatrixd(v.as_ptr()) },
            Call::LoadTransposeMatrixf(ref v) => unsafe { gl.LoadTransposeMatrixf(v.as_ptr()) },
            Call::LoadTransposeMatrixd(ref v) => unsafe { gl.LoadTransposeMatrixd(v.as_ptr()) },
            Call::MultTransposeMatrixf(ref v) => unsafe { gl.MultTransposeMatrixf(v.as_ptr()) },
            Call::MultTransposeMatrixd(ref v) => unsafe { gl.MultTransposeMatrixd(v.as_ptr()) },
            Call::Translatef(a, b, c) => unsafe { gl.Translatef(a, b, c) },
            Call::Translated(a, b, c) => unsafe { gl.Translated(a, b, c) },
            Call::Rotatef(a, b, c, d) => unsafe { gl.Rotatef(a, b, c, d) },
            Call::Rotated(a, b, c, d) => unsafe { gl.Rotated(a, b, c, d) },
            Call::Scalef(a, b, c) => unsafe { gl.Scalef(a, b, c) },
            Call::Scaled(a, b, c) => unsafe { gl.Scaled(a, b, c) },
            Call::Frustum(ref p) => unsafe { gl.Frustum(p[0], p[1], p[2], p[3], p[4], p[5]) },
            Call::Ortho(ref p) => unsafe { gl.Ortho(p[0], p[1], p[2], p[3], p[4], p[5]) },
            Call::PushMatrix => unsafe { gl.PushMatrix() },
            Call::PopMatrix => unsafe { gl.PopMatrix() },
            Call::Viewport(a, b, c, d) => unsafe { gl.Viewport(a, b, c, d) },
            Call::DepthRange(a, b) => unsafe { gl.DepthRange(a, b) },
            Call::ClipPlane(a, ref b) => unsafe { gl.ClipPlane(a, b.as_ptr()) },
            Call::ActiveTexture(a) => unsafe { gl.ActiveTexture(a) },
            Call::ClientActiveTexture(a) => unsafe { gl.ClientActiveTexture(a) },
            Call::Vertex2s(a, b) => unsafe { gl.Vertex2s(a, b) },
            Call::Vertex2i(a, b) => unsafe { gl.Vertex2i(a, b) },
            Call::Vertex2f(a, b) => unsafe { gl.Vertex2f(a, b) },
            Call::Vertex2d(a, b) => unsafe { gl.Vertex2d(a, b) },
            Call::Vertex3s(a, b, c) => unsafe { gl.Vertex3s(a, b, c) },
            Call::Vertex3i(a, b, c) => unsafe { gl.Vertex3i(a, b, c) },
            Call::Vertex3d(a, b, c) => unsafe { gl.Vertex3d(a, b, c) },
            Call::Vertex4s(a, b, c, d) => unsafe { gl.Vertex4s(a, b, c, d) },
            Call::Vertex4i(a, b, c, d) => unsafe { gl.Vertex4i(a, b, c, d) },
            Call::Vertex4f(a, b, c, d) => unsafe { gl.Vertex4f(a, b, c, d) },
            Call::Vertex4d(a, b, c, d) => unsafe { gl.Vertex4d(a, b, c, d) },
            Call::Vertex2sv(ref v) => unsafe { gl.Vertex2sv(v.as_ptr()) },
            Call::Vertex2iv(ref v) => unsafe { gl.Vertex2iv(v.as_ptr()) },
            Call::Vertex2fv(ref v) => unsafe { gl.Vertex2fv(v.as_ptr()) },
            Call::Vertex2dv(ref v) => unsafe { gl.Vertex2dv(v.as_ptr()) },
            Call::Vertex3sv(ref v) => unsafe { gl.Vertex3sv(v.as_ptr()) },
            Call::Vertex3iv(ref v) => unsafe { gl.Vertex3iv(v.as_ptr()) },
            Call::Vertex3fv(ref v) => unsafe { gl.Vertex3fv(v.as_ptr()) },
            Call::Vertex3dv(ref v) => unsafe { gl.Vertex3dv(v.as_ptr()) },
            Call::Vertex4sv(ref v) => unsafe { gl.Vertex4sv(v.as_ptr()) },
            Call::Vertex4iv(ref v) => unsafe { gl.Vertex4iv(v.as_ptr()) },
            Call::Vertex4fv(ref v) => unsafe { gl.Vertex4fv(v.as_ptr()) },
            Call::Vertex4dv(ref v) => unsafe { gl.Vertex4dv(v.as_ptr()) },
            Call::Normal3b(a, b, c) => unsafe { gl.Normal3b(a, b, c) },
            Call::Normal3s(a, b, c) => unsafe { gl.Normal3s(a, b, c) },
            Call::Normal3i(a, b, c) => unsafe { gl.Normal3i(a, b, c) },
            Call::Normal3d(a, b, c) => unsafe { gl.Normal3d(a, b, c) },
            Call::Normal3bv(ref v) => unsafe { gl.Normal3bv(v.as_ptr()) },
            Call::Normal3sv(ref v) => unsafe { gl.Normal3sv(v.as_ptr()) },
            Call::Normal3iv(ref v) => unsafe { gl.Normal3iv(v.as_ptr()) },
            Call::Normal3fv(ref v) => unsafe { gl.Normal3fv(v.as_ptr()) },
            Call::Normal3dv(ref v) => unsafe { gl.Normal3dv(v.as_ptr()) },
            Call::Color3b(a, b, c) => unsafe { gl.Color3b(a, b, c) },
            Call::Color3s(a, b, c) => unsafe { gl.Color3s(a, b, c) },
            Call::Color3i(a, b, c) => unsafe { gl.Color3i(a, b, c) },
            Call::Color3f(a, b, c) => unsafe { gl.Color3f(a, b, c) },
            Call::Color3d(a, b, c) => unsafe { gl.Color3d(a, b, c) },
            Call::Color3ub(a, b, c) => unsafe { gl.Color3ub(a, b, c) },
            Call::Color3us(a, b, c) => unsafe { gl.Color3us(a, b, c) },
            Call::Color3ui(a, b, c) => unsafe { gl.Color3ui(a, b, c) },
            Call::Color3bv(ref v) => unsafe { gl.Color3bv(v.as_ptr()) },
            Call::Color3sv(ref v) => unsafe { gl.Color3sv(v.as_ptr()) },
            Call::Color3iv(ref v) => unsafe { gl.Color3iv(v.as_ptr()) },
            Call::Color3fv(ref v) => unsafe { gl.Color3fv(v.as_ptr()) },
            Call::Color3dv(ref v) => unsafe { gl.Color3dv(v.as_ptr()) },
            Call::Color3ubv(ref v) => unsafe { gl.Color3ubv(v.as_ptr()) },
            Call::Color3usv(ref v) => unsafe { gl.Color3usv(v.as_ptr()) },
            Call::Color3uiv(ref v) => unsafe { gl.Color3uiv(v.as_ptr()) },
            Call::Color4b(a, b, c, d) => unsafe { gl.Color4b(a, b, c, d) },
            Call::Color4s(a, b, c, d) => unsafe { gl.Color4s(a, b, c, d) },
            Call::Color4i(a, b, c, d) => unsafe { gl.Color4i(a, b, c, d) },
            Call::Color4d(a, b, c, d) => unsafe { gl.Color4d(a, b, c, d) },
            Call::Color4ub(a, b, c, d) => unsafe { gl.Color4ub(a, b, c, d) },
            Call::Color4us(a, b, c, d) => unsafe { gl.Color4us(a, b, c, d) },
            Call::Color4ui(a, b, c, d) => unsafe { gl.Color4ui(a, b, c, d) },
            Call::Color4bv(ref v) => unsafe { gl.Color4bv(v.as_ptr()) },
            Call::Color4sv(ref v) => unsafe { gl.Color4sv(v.as_ptr()) },
            Call::Color4iv(ref v) => unsafe { gl.Color4iv(v.as_ptr()) },
            Call::Color4fv(ref v) => unsafe { gl.Color4fv(v.as_ptr()) },
            Call::Color4dv(ref v) => unsafe { gl.Color4dv(v.as_ptr()) },
            Call::Color4ubv(ref v) => unsafe { gl.Color4ubv(v.as_ptr()) },
            Call::Color4usv(ref v) => unsafe { gl.Color4usv(v.as_ptr()) },
            Call::Color4uiv(ref v) => unsafe { gl.Color4uiv(v.as_ptr()) },
            Call::SecondaryColor3b(a, b, c) => unsafe { gl.SecondaryColor3b(a, b, c) },
            Call::SecondaryColor3s(a, b, c) => unsafe { gl.SecondaryColor3s(a, b, c) },
            Call::SecondaryColor3i(a, b, c) => unsafe { gl.SecondaryColor3i(a, b, c) },
            Call::SecondaryColor3f(a, b, c) => unsafe { gl.SecondaryColor3f(a, b, c) },
            Call::SecondaryColor3d(a, b, c) => unsafe { gl.SecondaryColor3d(a, b, c) },
            Call::SecondaryColor3ub(a, b, c) => unsafe { gl.SecondaryColor3ub(a, b, c) },
            Call::SecondaryColor3us(a, b, c) => unsafe { gl.SecondaryColor3us(a, b, c) },
            Call::SecondaryColor3ui(a, b, c) => unsafe { gl.SecondaryColor3ui(a, b, c) },
            Call::SecondaryColor3bv(ref v) => unsafe { gl.SecondaryColor3bv(v.as_ptr()) },
            Call::SecondaryColor3sv(ref v) => unsafe { gl.SecondaryColor3sv(v.as_ptr()) },
            Call::SecondaryColor3iv(ref v) => unsafe { gl.SecondaryColor3iv(v.as_ptr()) },
            Call::SecondaryColor3fv(ref v) => unsafe { gl.SecondaryColor3fv(v.as_ptr()) },
            Call::SecondaryColor3dv(ref v) => unsafe { gl.SecondaryColor3dv(v.as_ptr()) },
            Call::SecondaryColor3ubv(ref v) => unsafe { gl.SecondaryColor3ubv(v.as_ptr()) },
            Call::SecondaryColor3usv(ref v) => unsafe { gl.SecondaryColor3usv(v.as_ptr()) },
            Call::SecondaryColor3uiv(ref v) => unsafe { gl.SecondaryColor3uiv(v.as_ptr()) },
            Call::TexCoord1s(a) => unsafe { gl.TexCoord1s(a) },
            Call::TexCoord1i(a) => unsafe { gl.TexCoord1i(a) },
            Call::TexCoord1f(a) => unsafe { gl.TexCoord1f(a) },
            Call::TexCoord1d(a) => unsafe { gl.TexCoord1d(a) },
            Call::TexCoord2s(a, b) => unsafe { gl.TexCoord2s(a, b) },
            Call::TexCoord2i(a, b) => unsafe { gl.TexCoord2i(a, b) },
            Call::TexCoord2f(a, b) => unsafe { gl.TexCoord2f(a, b) },
            Call::TexCoord2d(a, b) => unsafe { gl.TexCoord2d(a, b) },
            Call::TexCoord3s(a, b, c) => unsafe { gl.TexCoord3s(a, b, c) },
            Call::TexCoord3i(a, b, c) => unsafe { gl.TexCoord3i(a, b, c) },
            Call::TexCoord3f(a, b, c) => unsafe { gl.TexCoord3f(a, b, c) },
            Call::TexCoord3d(a, b, c) => unsafe { gl.TexCoord3d(a, b, c) },
            Call::TexCoord4s(a, b, c, d) => unsafe { gl.TexCoord4s(a, b, c, d) },
            Call::TexCoord4i(a, b, c, d) => unsafe { gl.TexCoord4i(a, b, c, d) },
            Call::TexCoord4f(a, b, c, d) => unsafe { gl.TexCoord4f(a, b, c, d) },
            Call::TexCoord4d(a, b, c, d) => unsafe { gl.TexCoord4d(a, b, c, d) },
            Call::TexCoord1sv(ref v) => unsafe { gl.TexCoord1sv(v.as_ptr()) },
            Call::TexCoord1iv(ref v) => unsafe { gl.TexCoord1iv(v.as_ptr()) },
            Call::TexCoord1fv(ref v) => unsafe { gl.TexCoord1fv(v.as_ptr()) },
            Call::TexCoord1dv(ref v) => unsafe { gl.TexCoord1dv(v.as_ptr()) },
            Call::TexCoord2sv(ref v) => unsafe { gl.TexCoord2sv(v.as_ptr()) },
            Call::TexCoord2iv(ref v) => unsafe { gl.TexCoord2iv(v.as_ptr()) },
            Call::TexCoord2fv(ref v) => unsafe { gl.TexCoord2fv(v.as_ptr()) },
            Call::TexCoord2dv(ref v) => unsafe { gl.TexCoord2dv(v.as_ptr()) },
            Call::TexCoord3sv(ref v) => unsafe { gl.TexCoord3sv(v.as_ptr()) },
            Call::TexCoord3iv(ref v) => unsafe { gl.TexCoord3iv(v.as_ptr()) },
            Call::TexCoord3fv(ref v) => unsafe { gl.TexCoord3fv(v.as_ptr()) },
            Call::TexCoord3dv(ref v) => unsafe { gl.TexCoord3dv(v.as_ptr()) },
            Call::TexCoord4sv(ref v) => unsafe { gl.TexCoord4sv(v.as_ptr()) },
            Call::TexCoord4iv(ref v) => unsafe { gl.TexCoord4iv(v.as_ptr()) },
            Call::TexCoord4fv(ref v) => unsafe { gl.TexCoord4fv(v.as_ptr()) },
            Call::TexCoord4dv(ref v) => unsafe { gl.TexCoord4dv(v.as_ptr()) },
            Call::FogCoordf(a) => unsafe { gl.FogCoordf(a) },
            Call::FogCoordd(a) => unsafe { gl.FogCoordd(a) },
            Call::FogCoordfv(ref v) => unsafe { gl.FogCoordfv(v.as_ptr()) },
            Call::FogCoorddv(ref v) => unsafe { gl.FogCoorddv(v.as_ptr()) },
            Call::EdgeFlag(a) => unsafe { gl.EdgeFlag(u8::from(a)) },
            Call::EdgeFlagv(v) => {
                let flag = u8::from(v[0]);
                unsafe { gl.EdgeFlagv(&flag) }
            }
            Call::Materialf(a, b, c) => unsafe { gl.Materialf(a, b, c) },
            Call::Materiali(a, b, c) => unsafe { gl.Materiali(a, b, c) },
            Call::Materialfv(a, p, ref v) => {
                self.with_params(v, params::material(p), true, |gl, v| unsafe {
                    gl.Materialfv(a, p, v)
                })
            }
            Call::Materialiv(a, p, ref v) => {
                self.with_params(v, params::material(p), true, |gl, v| unsafe {
                    gl.Materialiv(a, p, v)
                })
            }
            Call::Lightf(a, b, c) => unsafe { gl.Lightf(a, b, c) },
            Call::Lighti(a, b, c) => unsafe { gl.Lighti(a, b, c) },
            Call::Lightfv(a, p, ref v) => {
                self.with_params(v, params::light(p), false, |gl, v| unsafe {
                    gl.Lightfv(a, p, v)
                })
            }
            Call::Lightiv(a, p, ref v) => {
                self.with_params(v, params::light(p), false, |gl, v| unsafe {
                    gl.Lightiv(a, p, v)
                })
            }
            Call::LightModelf(a, b) => unsafe { gl.LightModelf(a, b) },
            Call::LightModeli(a, b) => unsafe { gl.LightModeli(a, b) },
            Call::LightModelfv(p, ref v) => {
                self.with_params(v, params::light_model(p), false, |gl, v| unsafe {
                    gl.LightModelfv(p, v)
                })
            }
            Call::LightModeliv(p, ref v) => {
                self.with_params(v, params::light_model(p), false, |gl, v| unsafe {
                    gl.LightModeliv(p, v)
                })
            }
            Call::ColorMaterial(a, b) => unsafe { gl.ColorMaterial(a, b) },
            Call::ShadeModel(mode) => self.shade_model(mode),
            Call::FrontFace(a) => unsafe { gl.FrontFace(a) },
            Call::CullFace(a) => unsafe { gl.CullFace(a) },
            Call::PolygonMode(a, b) => unsafe { gl.PolygonMode(a, b) },
            Call::PolygonOffset(a, b) => unsafe { gl.PolygonOffset(a, b) },
            Call::PointSize(a) => unsafe { gl.PointSize(a) },
            Call::LineWidth(a) => unsafe { gl.LineWidth(a) },
            Call::ClearColor(a, b, c, d) => unsafe { gl.ClearColor(a, b, c, d) },
            Call::ClearDepth(a) => unsafe { gl.ClearDepth(a) },
            Call::ClearStencil(a) => unsafe { gl.ClearStencil(a) },
            Call::Clear(a) => unsafe { gl.Clear(a) },
            Call::DepthFunc(a) => unsafe { gl.DepthFunc(a) },
            Call::DepthMask(a) => unsafe { gl.DepthMask(u8::from(a)) },
            Call::ColorMask(a, b, c, d) => unsafe {
                gl.ColorMask(u8::from(a), u8::from(b), u8::from(c), u8::from(d))
            },
            Call::Scissor(a, b, c, d) => unsafe { gl.Scissor(a, b, c, d) },
            Call::Hint(target, mode) => self.hint(target, mode),
            Call::PixelStorei(a, b) => unsafe { gl.PixelStorei(a, b) },
            Call::PixelStoref(a, b) => unsafe { gl.PixelStoref(a, b) },
            Call::Flush => unsafe { gl.Flush() },
            Call::Finish => unsafe { gl.Finish() },
            // Display lists, attribute stacks (glbackend/lists.rs)
            Call::GenLists(range) => unsafe {
                gl.GenLists(range);
            },
            Call::NewList(list, mode) => self.new_list(list, mode),
            Call::EndList => self.end_list(),
            Call::CallList(list) => self.call_list(list),
            Call::CallLists(n, ty, ref names) => self.call_lists(n, ty, names),
            Call::ListBase(base) => self.list_base(base),
            Call::DeleteLists(list, range) => self.delete_lists(list, range),
            Call::PushAttrib(mask) => self.push_attrib(mask),
            Call::PopAttrib => self.pop_attrib(),
            Call::PushClientAttrib(mask) => unsafe { gl.PushClientAttrib(mask) },
            Call::PopClientAttrib => unsafe { gl.PopClientAttrib() },
            Call::EnableClientState(..)
            | Call::DisableClientState(..)
            | Call::VertexPointer(..)
            | Call::NormalPointer(..)
            | Call::ColorPointer(..)
            | Call::SecondaryColorPointer(..)
            | Call::TexCoordPointer(..)
            | Call::FogCoordPointer(..)
            | Call::EdgeFlagPointer(..)
            | Call::InterleavedArrays(..)
            | Call::ArrayElement(..)
            | Call::DrawArrays(..)
            | Call::DrawElements(..)
            | Call::DrawRangeElements(..)
            | Call::GenBuffers(..)
            | Call::DeleteBuffers(..)
            | Call::BindBuffer(..)
            | Call::BufferData(..)
            | Call::BufferSubData(..) => self.arrays_call(call),
            // GL 2.1 (glFog reference page) takes FOG_COLOR only through the vector forms; Mesa
            // also takes it here. Raised here as for Begin, so both backends agree.
            Call::Fogf(gl::FOG_COLOR, _) | Call::Fogi(gl::FOG_COLOR, _)
                if !self.inside_begin_end =>
            {
                self.raise(gl::INVALID_ENUM)
            }
            Call::Fogf(p, v) => unsafe { gl.Fogf(p, v) },
            Call::Fogi(p, v) => unsafe { gl.Fogi(p, v) },
            Call::Fogfv(p, ref v) => {
                self.with_params(v, params::fog(p), false, |gl, v| unsafe { gl.Fogfv(p, v) })
            }
            Call::Fogiv(p, ref v) => {
                self.with_params(v, params::fog(p), false, |gl, v| unsafe { gl.Fogiv(p, v) })
            }
            Call::AlphaFunc(f, r) => unsafe { gl.AlphaFunc(f, r) },
            Call::StencilFunc(f, r, m) => unsafe { gl.StencilFunc(f, r, m) },
            Call::StencilFuncSeparate(face, f, r, m) => unsafe {
                gl.StencilFuncSeparate(face, f, r, m)
            },
            Call::StencilOp(a, b, c) => unsafe { gl.StencilOp(a, b, c) },
            Call::StencilOpSeparate(face, a, b, c) => unsafe {
                gl.StencilOpSeparate(face, a, b, c)
            },
            Call::StencilMask(m) => unsafe { gl.StencilMask(m) },
            Call::StencilMaskSeparate(face, m) => unsafe { gl.StencilMaskSeparate(face, m) },
            // SRC_ALPHA_SATURATE is a source factor only in GL 2.1 (§4.1.8); a driver with
            // ARB_blend_func_extended takes it as a destination too.
            Call::BlendFunc(_, gl::SRC_ALPHA_SATURATE)
            | Call::BlendFuncSeparate(_, gl::SRC_ALPHA_SATURATE, _, _)
            | Call::BlendFuncSeparate(_, _, _, gl::SRC_ALPHA_SATURATE)
                if !self.inside_begin_end =>
            {
                self.raise(gl::INVALID_ENUM)
            }
            Call::BlendFunc(s, d) => unsafe { gl.BlendFunc(s, d) },
            Call::BlendFuncSeparate(a, b, c, d) => unsafe { gl.BlendFuncSeparate(a, b, c, d) },
            Call::BlendEquation(m) => unsafe { gl.BlendEquation(m) },
            Call::BlendEquationSeparate(a, b) => unsafe { gl.BlendEquationSeparate(a, b) },
            Call::BlendColor(r, g, b, a) => unsafe { gl.BlendColor(r, g, b, a) },
            Call::LogicOp(op) => unsafe { gl.LogicOp(op) },
            Call::GenTextures(n) => self.gen_textures(n),
            Call::DeleteTextures(n, ref v) => self.delete_textures(n, v),
            Call::BindTexture(a, b) => unsafe { gl.BindTexture(a, b) },
            Call::TexImage2D(ref args) => {
                let (t, l, i, w, h, b, f, ty, ref p) = **args;
                self.tex_image_2d(t, l, i, w, h, b, f, ty, p.as_deref())
            }
            Call::TexSubImage2D(ref args) => {
                let (t, l, x, y, w, h, f, ty, ref p) = **args;
                self.tex_sub_image_2d(t, l, x, y, w, h, f, ty, p)
            }
            Call::CopyTexImage2D(t, l, i, x, y, w, h, b) => unsafe {
                gl.CopyTexImage2D(t, l, i, x, y, w, h, b)
            },
            Call::CopyTexSubImage2D(t, l, xo, yo, x, y, w, h) => unsafe {
                gl.CopyTexSubImage2D(t, l, xo, yo, x, y, w, h)
            },
            Call::TexParameteri(a, b, c) => unsafe { gl.TexParameteri(a, b, c) },
            Call::TexParameterf(a, b, c) => unsafe { gl.TexParameterf(a, b, c) },
            Call::TexParameteriv(a, p, ref v) => {
                self.with_params(v, params::tex_parameter(p), false, |gl, v| unsafe {
                    gl.TexParameteriv(a, p, v)
                })
            }
            Call::TexParameterfv(a, p, ref v) => {
                self.with_params(v, params::tex_parameter(p), false, |gl, v| unsafe {
                    gl.TexParameterfv(a, p, v)
                })
            }
            Call::TexEnvi(a, b, c) => unsafe { gl.TexEnvi(a, b, c) },
            Call::TexEnvf(a, b, c) => unsafe { gl.TexEnvf(a, b, c) },
            Call::TexEnviv(a, p, ref v) => {
                self.with_params(v, params::tex_env(p), false, |gl, v| unsafe {
                    gl.TexEnviv(a, p, v)
                })
            }
            Call::TexEnvfv(a, p, ref v) => {
                self.with_params(v, params::tex_env(p), false, |gl, v| unsafe {
                    gl.TexEnvfv(a, p, v)
                })
            }
            Call::TexGeni(a, b, c) => unsafe { gl.TexGeni(a, b, c) },
            Call::TexGenf(a, b, c) => unsafe { gl.TexGenf(a, b, c) },
            Call::TexGend(a, b, c) => unsafe { gl.TexGend(a, b, c) },
            Call::TexGeniv(a, p, ref v) => {
                self.with_params(v, params::tex_gen(p), false, |gl, v| unsafe {
                    gl.TexGeniv(a, p, v)
                })
            }
            Call::TexGenfv(a, p, ref v) => {
                self.with_params(v, params::tex_gen(p), false, |gl, v| unsafe {
                    gl.TexGenfv(a, p, v)
                })
            }
            Call::TexGendv(a, p, ref v) => {
                self.with_params(v, params::tex_gen(p), false, |gl, v| unsafe {
                    gl.TexGendv(a, p, v)
                })
            }
            Call::MultiTexCoord1s(t, a0) => unsafe { gl.MultiTexCoord1s(t, a0) },
            Call::MultiTexCoord1sv(t, ref v) => unsafe { gl.MultiTexCoord1sv(t, v.as_ptr()) },
            Call::MultiTexCoord1i(t, a0) => unsafe { gl.MultiTexCoord1i(t, a0) },
            Call::MultiTexCoord1iv(t, ref v) => unsafe { gl.MultiTexCoord1iv(t, v.as_ptr()) },
            Call::MultiTexCoord1f(t, a0) => unsafe { gl.MultiTexCoord1f(t, a0) },
            Call::MultiTexCoord1fv(t, ref v) => unsafe { gl.MultiTexCoord1fv(t, v.as_ptr()) },
            Call::MultiTexCoord1d(t, a0) => unsafe { gl.MultiTexCoord1d(t, a0) },
            Call::MultiTexCoord1dv(t, ref v) => unsafe { gl.MultiTexCoord1dv(t, v.as_ptr()) },
            Call::MultiTexCoord2s(t, a0, a1) => unsafe { gl.MultiTexCoord2s(t, a0, a1) },
            Call::MultiTexCoord2sv(t, ref v) => unsafe { gl.MultiTexCoord2sv(t, v.as_ptr()) },
            Call::MultiTexCoord2i(t, a0, a1) => unsafe { gl.MultiTexCoord2i(t, a0, a1) },
            Call::MultiTexCoord2iv(t, ref v) => unsafe { gl.MultiTexCoord2iv(t, v.as_ptr()) },
            Call::MultiTexCoord2f(t, a0, a1) => unsafe { gl.MultiTexCoord2f(t, a0, a1) },
            Call::MultiTexCoord2fv(t, ref v) => unsafe { gl.MultiTexCoord2fv(t, v.as_ptr()) },
            Call::MultiTexCoord2d(t, a0, a1) => unsafe { gl.MultiTexCoord2d(t, a0, a1) },
            Call::MultiTexCoord2dv(t, ref v) => unsafe { gl.MultiTexCoord2dv(t, v.as_ptr()) },
            Call::MultiTexCoord3s(t, a0, a1, a2) => unsafe { gl.MultiTexCoord3s(t, a0, a1, a2) },
            Call::MultiTexCoord3sv(t, ref v) => unsafe { gl.MultiTexCoord3sv(t, v.as_ptr()) },
            Call::MultiTexCoord3i(t, a0, a1, a2) => unsafe { gl.MultiTexCoord3i(t, a0, a1, a2) },
            Call::MultiTexCoord3iv(t, ref v) => unsafe { gl.MultiTexCoord3iv(t, v.as_ptr()) },
            Call::MultiTexCoord3f(t, a0, a1, a2) => unsafe { gl.MultiTexCoord3f(t, a0, a1, a2) },
            Call::MultiTexCoord3fv(t, ref v) => unsafe { gl.MultiTexCoord3fv(t, v.as_ptr()) },
            Call::MultiTexCoord3d(t, a0, a1, a2) => unsafe { gl.MultiTexCoord3d(t, a0, a1, a2) },
            Call::MultiTexCoord3dv(t, ref v) => unsafe { gl.MultiTexCoord3dv(t, v.as_ptr()) },
            Call::MultiTexCoord4s(t, a0, a1, a2, a3) => unsafe {
                gl.MultiTexCoord4s(t, a0, a1, a2, a3)
            },
            Call::MultiTexCoord4sv(t, ref v) => unsafe { gl.MultiTexCoord4sv(t, v.as_ptr()) },
            Call::MultiTexCoord4i(t, a0, a1, a2, a3) => unsafe {
                gl.MultiTexCoord4i(t, a0, a1, a2, a3)
            },
            Call::MultiTexCoord4iv(t, ref v) => unsafe { gl.MultiTexCoord4iv(t, v.as_ptr()) },
            Call::MultiTexCoord4f(t, a0, a1, a2, a3) => unsafe {
                gl.MultiTexCoord4f(t, a0, a1, a2, a3)
            },
            Call::MultiTexCoord4fv(t, ref v) => unsafe { gl.MultiTexCoord4fv(t, v.as_ptr()) },
            Call::MultiTexCoord4d(t, a0, a1, a2, a3) => unsafe {
                gl.MultiTexCoord4d(t, a0, a1, a2, a3)
            },
            Call::MultiTexCoord4dv(t, ref v) => unsafe { gl.MultiTexCoord4dv(t, v.as_ptr()) },
        }
    }

    /// `Hint`: PHONG_HINT_WIN (GL_WIN_phong_shading) is not a target the driver knows, so it is
    /// validated here with the rules of GL 2.1 §5.6 (INVALID_OPERATION inside Begin/End, then
    /// INVALID_ENUM for a bad mode) and, having no effect on the emulation, not sent on.
    fn hint(&mut self, target: u32, mode: u32) {
        if target != gl::PHONG_HINT_WIN {
            // SAFETY: the context is current (see `execute`); no pointers.
            return unsafe { self.raw.Hint(target, mode) };
        }
        // lists: the driver's list cannot hold this hint; its errors come when the list runs.
        self.list_needs_expansion();
        if self.compile_only() {
            return;
        }
        if self.inside_begin_end {
            self.raise(gl::INVALID_OPERATION);
        } else if !matches!(mode, gl::FASTEST | gl::NICEST | gl::DONT_CARE) {
            self.raise(gl::INVALID_ENUM);
        }
    }

    /// Calls the driver with a pname-dependent parameter slice `v` of which GL reads `needed`
    /// values, or — when `v` is shorter — records INVALID_VALUE as the CPU front end does and
    /// calls nothing. Between Begin and End a command not `allowed_in_begin_end` is an
    /// INVALID_OPERATION first (GL 2.1 §2.6.3), short slice or not. The driver always gets a
    /// buffer of at least 16 values (the slice, zero-padded), so an unknown pname (count 0, the
    /// driver raises INVALID_ENUM) can never make it read past the caller's data.
    pub(crate) fn with_params<T: Copy + Default>(
        &mut self,
        v: &[T],
        needed: usize,
        allowed_in_begin_end: bool,
        call: impl FnOnce(&raw::Gl, *const T),
    ) {
        if v.len() < needed {
            // lists: the driver's list cannot hold this call; its error comes when the list runs.
            self.list_needs_expansion();
            if self.compile_only() {
                return;
            }
            let code = if self.inside_begin_end && !allowed_in_begin_end {
                gl::INVALID_OPERATION
            } else {
                gl::INVALID_VALUE
            };
            return self.raise(code);
        }
        let mut padded = [T::default(); 16];
        if v.len() >= padded.len() {
            call(&self.raw, v.as_ptr());
        } else {
            padded[..v.len()].copy_from_slice(v);
            call(&self.raw, padded.as_ptr());
        }
    }
}

/// Calls that can never change what the PHONG_WIN program depends on (LIGHTING, the light
/// enables, the light model, COLOR_MATERIAL), so they need not trigger a re-read before the next
/// Begin. Anything not listed here does: a new variant is correct by default, merely slower.
pub(super) fn phong_neutral(call: &Call) -> bool {
    // The vertex attributes, Material and ArrayElement: what GL allows between Begin and End,
    // except a display list, which may hold anything.
    matches!(call, Call::Begin(_))
        || (call.allowed_between_begin_end()
            && !matches!(call, Call::CallList(_) | Call::CallLists(..)))
}

/// How many values each pname-dependent vector command reads (GL 2.1 §2.14.2, §2.14.3, §3.10,
/// §3.8.4, §3.8.13, §2.11.4); 0 for a pname the command does not know, which the driver
/// rejects with INVALID_ENUM before reading anything.
pub(crate) mod params {
    use crate::gl;

    /// `Light{fv,iv}` (table 6.10).
    pub fn light(pname: u32) -> usize {
        match pname {
            gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::POSITION => 4,
            gl::SPOT_DIRECTION => 3,
            gl::SPOT_EXPONENT
            | gl::SPOT_CUTOFF
            | gl::CONSTANT_ATTENUATION
            | gl::LINEAR_ATTENUATION
            | gl::QUADRATIC_ATTENUATION => 1,
            _ => 0,
        }
    }

    /// `Material{fv,iv}` (table 6.9).
    pub fn material(pname: u32) -> usize {
        match pname {
            gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::EMISSION | gl::AMBIENT_AND_DIFFUSE => 4,
            gl::COLOR_INDEXES => 3,
            gl::SHININESS => 1,
            _ => 0,
        }
    }

    /// `LightModel{fv,iv}` (table 6.9).
    pub fn light_model(pname: u32) -> usize {
        match pname {
            gl::LIGHT_MODEL_AMBIENT => 4,
            gl::LIGHT_MODEL_LOCAL_VIEWER
            | gl::LIGHT_MODEL_TWO_SIDE
            | gl::LIGHT_MODEL_COLOR_CONTROL => 1,
            _ => 0,
        }
    }

    /// `Fog{fv,iv}` (table 6.8).
    pub fn fog(pname: u32) -> usize {
        match pname {
            gl::FOG_COLOR => 4,
            gl::FOG_MODE
            | gl::FOG_DENSITY
            | gl::FOG_START
            | gl::FOG_END
            | gl::FOG_INDEX
            | gl::FOG_COORD_SRC => 1,
            _ => 0,
        }
    }

    /// `TexEnv{fv,iv}` (table 6.20).
    pub fn tex_env(pname: u32) -> usize {
        match pname {
            gl::TEXTURE_ENV_COLOR => 4,
            gl::TEXTURE_ENV_MODE
            | gl::COMBINE_RGB
            | gl::COMBINE_ALPHA
            | gl::SRC0_RGB
            | gl::SRC1_RGB
            | gl::SRC2_RGB
            | gl::SRC0_ALPHA
            | gl::SRC1_ALPHA
            | gl::SRC2_ALPHA
            | gl::OPERAND0_RGB
            | gl::OPERAND1_RGB
            | gl::OPERAND2_RGB
            | gl::OPERAND0_ALPHA
            | gl::OPERAND1_ALPHA
            | gl::OPERAND2_ALPHA
            | gl::RGB_SCALE
            | gl::ALPHA_SCALE
            | gl::TEXTURE_LOD_BIAS
            | gl::COORD_REPLACE => 1,
            _ => 0,
        }
    }

    /// `TexGen{fv,iv,dv}` (table 6.15).
    pub fn tex_gen(pname: u32) -> usize {
        match pname {
            gl::OBJECT_PLANE | gl::EYE_PLANE => 4,
            gl::TEXTURE_GEN_MODE => 1,
            _ => 0,
        }
    }

    /// `TexParameter{fv,iv}` (table 6.16).
    pub fn tex_parameter(pname: u32) -> usize {
        match pname {
            gl::TEXTURE_BORDER_COLOR => 4,
            gl::TEXTURE_MIN_FILTER
            | gl::TEXTURE_MAG_FILTER
            | gl::TEXTURE_WRAP_S
            | gl::TEXTURE_WRAP_T
            | gl::TEXTURE_WRAP_R
            | gl::TEXTURE_PRIORITY
            | gl::TEXTURE_MIN_LOD
            | gl::TEXTURE_MAX_LOD
            | gl::TEXTURE_BASE_LEVEL
            | gl::TEXTURE_MAX_LEVEL
            | gl::TEXTURE_LOD_BIAS
            | gl::DEPTH_TEXTURE_MODE
            | gl::TEXTURE_COMPARE_MODE
            | gl::TEXTURE_COMPARE_FUNC
            | gl::GENERATE_MIPMAP => 1,
            _ => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glbackend::DeviceChoice;
    use std::io::Write as _;

    fn light0_position(b: &GlBackend) -> [f32; 4] {
        let mut p = [f32::NAN; 4];
        // SAFETY: GetLightfv(POSITION) writes 4 floats.
        unsafe { b.raw().GetLightfv(gl::LIGHT0, gl::POSITION, p.as_mut_ptr()) };
        p
    }

    #[test]
    fn short_parameter_slices_never_reach_the_driver() {
        let mut b = match GlBackend::new(4, 4, &DeviceChoice::Auto) {
            Ok(b) => b,
            Err(e) => {
                let _ = writeln!(std::io::stderr(), "SKIPPED: GL backend unavailable: {e}");
                return;
            }
        };
        let lightfv = |pname: u32| {
            move |gl: &raw::Gl, v: *const f32| unsafe { gl.Lightfv(gl::LIGHT0, pname, v) }
        };
        // POSITION needs 4 values: 3 is INVALID_VALUE and the initial (0,0,1,0) stays.
        b.with_params(
            &[5.0, 5.0, 5.0],
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), [0.0, 0.0, 1.0, 0.0]);
        // Enough values: applied (identity modelview, so stored as given).
        let v = [1.0, 2.0, 3.0, 1.0];
        b.with_params(
            &v,
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        assert_eq!(b.get_error(), gl::NO_ERROR);
        assert_eq!(light0_position(&b), v);
        // An unknown pname needs nothing of ours: the driver's INVALID_ENUM.
        b.with_params(&[], params::light(0x1234), false, lightfv(0x1234));
        assert_eq!(b.get_error(), gl::INVALID_ENUM);
        // Between Begin and End a command not allowed there is INVALID_OPERATION first...
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(
            &[1.0],
            params::light(gl::POSITION),
            false,
            lightfv(gl::POSITION),
        );
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_OPERATION);
        // ...while Material, allowed there, reports the short slice.
        b.execute(&Call::Begin(gl::POINTS));
        b.with_params(
            &[1.0],
            params::material(gl::DIFFUSE),
            true,
            |gl, v| unsafe { gl.Materialfv(gl::FRONT, gl::DIFFUSE, v) },
        );
        b.execute(&Call::End);
        assert_eq!(b.get_error(), gl::INVALID_VALUE);
        assert_eq!(light0_position(&b), v);
    }

    #[test]
    fn parameter_counts_follow_the_state_tables() {
        assert_eq!(params::light(gl::SPOT_DIRECTION), 3);
        assert_eq!(params::light(gl::QUADRATIC_ATTENUATION), 1);
        assert_eq!(params::material(gl::AMBIENT_AND_DIFFUSE), 4);
        assert_eq!(params::material(gl::COLOR_INDEXES), 3);
        assert_eq!(params::material(gl::POSITION), 0);
        assert_eq!(params::light_model(gl::LIGHT_MODEL_AMBIENT), 4);
        assert_eq!(params::fog(gl::FOG_COLOR), 4);
        assert_eq!(params::tex_gen(gl::EYE_PLANE), 4);
        assert_eq!(params::tex_env(gl::TEXTURE_ENV_MODE), 1);
        assert_eq!(params::tex_parameter(gl::TEXTURE_BORDER_COLOR), 4);
    }
}
