//! Vertex arrays and buffer objects on the context (GL 2.1 §2.8, §2.9): the client-state
//! commands, the draws, and buffer objects.
//!
//! Each method records itself, checks the Begin/End phase, and hands validation and the state
//! change to [`ArrayState`](crate::arrays::ArrayState) (shared with the GL backend's shadow
//! copy, which must refuse the same draws before the driver reads memory).
//!
//! Design decision: a draw is exactly its GL 2.1 §2.8 definition, `Begin(mode)`, then
//! `ArrayElement(i)` for each index (current attributes set from the enabled arrays, then a
//! vertex), then `End`, fed to the renderer like immediate mode, so the batch and vertex stage
//! are shared. The whole draw is validated first, bounds included: an erroneous draw draws
//! nothing and changes nothing. Only the draw is recorded, never the vertices it makes.

use glam::{Vec3, Vec4};

use super::Context;
use crate::arrays::{ArrayState, Attr, GlResult, Pointer, Source};
use crate::call::{Call, MapWrites};
use crate::gl;

/// The calls [`Context::compile_draw`] may compile into something else (the vertex-array
/// draws and PolygonStipple); for every other call it returns `Ok(None)` without looking
/// further, so a display list being compiled stores those as they are after this one test
/// (`Context::capture`).
#[inline(always)]
pub(crate) fn compiles_draw(call: &Call) -> bool {
    matches!(
        call,
        Call::PolygonStipple(_)
            | Call::MultiDrawArrays(_)
            | Call::MultiDrawElements(_)
            | Call::ArrayElement(_)
            | Call::DrawArrays(..)
            | Call::DrawElements(..)
            | Call::DrawRangeElements(..)
    )
}

impl Context {
    /// Runs an `ArrayState` command outside Begin/End (GL 2.1 §2.6.3), raising its error.
    fn arrays_do(&mut self, f: impl FnOnce(&mut ArrayState, usize) -> GlResult<()>) {
        if !self.outside_begin_end() {
            return;
        }
        let unit = self.state.client_active_texture;
        if let Err(code) = f(&mut self.state.arrays, unit) {
            self.error(code);
        }
    }

    /// `glEnableClientState`: VERTEX_ARRAY, NORMAL_ARRAY, COLOR_ARRAY, SECONDARY_COLOR_ARRAY,
    /// FOG_COORD_ARRAY, EDGE_FLAG_ARRAY, or TEXTURE_COORD_ARRAY of the client active texture
    /// unit; INVALID_ENUM otherwise.
    pub fn enable_client_state(&mut self, cap: u32) {
        record!(self, Call::EnableClientState(cap));
        self.arrays_do(|a, u| a.enable_client_state(cap, true, u));
    }

    /// `glDisableClientState`.
    pub fn disable_client_state(&mut self, cap: u32) {
        record!(self, Call::DisableClientState(cap));
        self.arrays_do(|a, u| a.enable_client_state(cap, false, u));
    }

    /// `glVertexPointer`: size 2, 3 or 4 (else INVALID_VALUE); SHORT, INT, FLOAT or DOUBLE
    /// (else INVALID_ENUM); stride 0 to 2048 (else INVALID_VALUE; the upper bound is the
    /// reference driver's, see [`crate::arrays::MAX_VERTEX_ATTRIB_STRIDE`]). `pointer`: the caller's data
    /// (`&[f32]`, `&[i16; N]`, `&Vec<f64>`, ... copied now) or, with a buffer bound to
    /// ARRAY_BUFFER, a byte offset (`0usize`); client data with a buffer bound is
    /// INVALID_OPERATION.
    pub fn vertex_pointer(&mut self, size: i32, ty: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::VertexPointer(size, ty, stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::Vertex, size, ty, stride, &p));
    }

    /// `glNormalPointer`: BYTE, SHORT, INT, FLOAT or DOUBLE; otherwise as `vertex_pointer`.
    pub fn normal_pointer(&mut self, ty: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::NormalPointer(ty, stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::Normal, 3, ty, stride, &p));
    }

    /// `glColorPointer`: size 3 or 4; any of the eight integer and float types (integers
    /// normalised by GL 2.1 table 2.9); otherwise as `vertex_pointer`.
    pub fn color_pointer(&mut self, size: i32, ty: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::ColorPointer(size, ty, stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::Color, size, ty, stride, &p));
    }

    /// `glSecondaryColorPointer`: size 3; types as `color_pointer`.
    pub fn secondary_color_pointer(
        &mut self,
        size: i32,
        ty: u32,
        stride: i32,
        pointer: impl Into<Pointer>,
    ) {
        let p = pointer.into();
        record!(
            self,
            Call::SecondaryColorPointer(size, ty, stride, p.recorded())
        );
        self.arrays_do(|a, _| a.pointer(Attr::SecondaryColor, size, ty, stride, &p));
    }

    /// `glTexCoordPointer`, for the client active texture unit: size 1 to 4; SHORT, INT, FLOAT
    /// or DOUBLE; otherwise as `vertex_pointer`.
    pub fn tex_coord_pointer(
        &mut self,
        size: i32,
        ty: u32,
        stride: i32,
        pointer: impl Into<Pointer>,
    ) {
        let p = pointer.into();
        record!(self, Call::TexCoordPointer(size, ty, stride, p.recorded()));
        self.arrays_do(|a, u| a.pointer(Attr::TexCoord(u), size, ty, stride, &p));
    }

    /// `glFogCoordPointer`: FLOAT or DOUBLE.
    pub fn fog_coord_pointer(&mut self, ty: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::FogCoordPointer(ty, stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::FogCoord, 1, ty, stride, &p));
    }

    /// `glEdgeFlagPointer`: one GLboolean (byte) per element (`&[bool]` or `&[u8]`).
    pub fn edge_flag_pointer(&mut self, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::EdgeFlagPointer(stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::EdgeFlag, 1, gl::UNSIGNED_BYTE, stride, &p));
    }

    /// `glIndexPointer`: colour indices of UNSIGNED_BYTE, SHORT, INT, FLOAT or DOUBLE (else
    /// INVALID_ENUM). The array is held, enabled (INDEX_ARRAY) and queried as GL 2.1 table 6.7
    /// says; in RGBA mode no draw reads it, as on Mesa.
    pub fn index_pointer(&mut self, ty: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::IndexPointer(ty, stride, p.recorded()));
        self.arrays_do(|a, _| a.pointer(Attr::Index, 1, ty, stride, &p));
    }

    /// `glInterleavedArrays` (GL 2.1 §2.8, table 2.5): one of the 14 formats (else
    /// INVALID_ENUM), stride 0 to 2048 (else INVALID_VALUE); sets and enables the format's arrays
    /// (texture coordinates on the client active unit) and disables the others.
    pub fn interleaved_arrays(&mut self, format: u32, stride: i32, pointer: impl Into<Pointer>) {
        let p = pointer.into();
        record!(self, Call::InterleavedArrays(format, stride, p.recorded()));
        self.arrays_do(|a, u| a.interleaved_arrays(format, stride, &p, u));
    }

    /// `glArrayElement(i)` (GL 2.1 §2.8): the current attributes from element `i` of every
    /// enabled array, then a vertex if the vertex array is enabled. Allowed between Begin and
    /// End. INVALID_VALUE for a negative `i` and INVALID_OPERATION when an enabled array has no
    /// element `i` (GL leaves both undefined); nothing changes then.
    pub fn array_element(&mut self, i: i32) {
        // Memory read at draw time cannot be recorded as a pointer inside Begin/End: the
        // recording gets the attribute calls this element amounts to instead.
        if self.recording.is_some() && self.lists.depth == 0 && self.state.arrays.reads_client() {
            if let Ok(Some(calls)) = self.compile_draw(&Call::ArrayElement(i)) {
                let mut recording = self.recording.take();
                self.sync_capturing();
                self.array_element_now(i);
                if let Some(rec) = recording.as_mut() {
                    rec.extend(calls);
                }
                self.recording = recording;
                self.sync_capturing();
                return;
            }
        }
        self.array_element_now(i);
    }

    fn array_element_now(&mut self, i: i32) {
        record!(self, Call::ArrayElement(i));
        match self.state.arrays.check_array_element(i) {
            Ok(i) => self.draw(None, [i], i + 1),
            Err(code) => self.error(code),
        }
    }

    /// `glDrawArrays`: elements `first .. first + count`. INVALID_ENUM for a mode,
    /// INVALID_VALUE for a negative `first` or `count`, INVALID_OPERATION between Begin and End
    /// or when an enabled array is shorter than `first + count` elements.
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        if self.begin_mode.is_none() {
            if let Ok(Some(range)) = self.state.arrays.check_draw_arrays(mode, first, count) {
                self.record_client_arrays(range.end() + 1);
            }
        }
        record!(self, Call::DrawArrays(mode, first, count));
        if !self.outside_begin_end() {
            return;
        }
        match self.state.arrays.check_draw_arrays(mode, first, count) {
            Ok(Some(range)) => {
                let reach = range.end() + 1;
                self.draw(Some(mode), range, reach)
            }
            Ok(None) => {}
            Err(code) => self.error(code),
        }
    }

    /// `glDrawElements`: `count` indices of `ty` (UNSIGNED_BYTE, UNSIGNED_SHORT or
    /// UNSIGNED_INT, else INVALID_ENUM) from `indices` (client data, or a byte offset into the
    /// ELEMENT_ARRAY_BUFFER). INVALID_ENUM for a mode, INVALID_VALUE for a negative `count`,
    /// INVALID_OPERATION between Begin and End, when the index data is too short (or is client
    /// data while an element buffer is bound), or when an enabled array lacks an indexed element.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, indices: impl Into<Pointer>) {
        let p = indices.into();
        self.record_client_arrays_indexed(mode, count, ty, &p, None);
        record!(self, Call::DrawElements(mode, count, ty, p.clone()));
        self.draw_indexed(mode, count, ty, &p, None);
    }

    /// `glDrawRangeElements`: as `draw_elements`, and INVALID_VALUE when `end < start`.
    /// Indices outside `start..=end` are drawn all the same (GL leaves them undefined).
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        indices: impl Into<Pointer>,
    ) {
        let p = indices.into();
        self.record_client_arrays_indexed(mode, count, ty, &p, Some((start, end)));
        record!(
            self,
            Call::DrawRangeElements(mode, start, end, count, ty, Box::new(p.clone()))
        );
        self.draw_indexed(mode, count, ty, &p, Some((start, end)));
    }

    /// `glMultiDrawArrays` (GL 1.4, GL 2.1 §2.8): DrawArrays(mode, first[i], count[i]) for each
    /// of the first `drawcount` entries. INVALID_VALUE for a negative `drawcount` or slices
    /// shorter than it, INVALID_ENUM for a mode, INVALID_VALUE for a negative count,
    /// INVALID_OPERATION between Begin and End or when a draw would read outside an enabled
    /// array (a negative `first` with an array enabled, too: Mesa raises nothing there and reads
    /// before the array) or from a mapped buffer. Every draw is checked before any is drawn.
    pub fn multi_draw_arrays(&mut self, mode: u32, first: &[i32], count: &[i32], drawcount: i32) {
        if self.recording.is_some() && self.begin_mode.is_none() {
            let a = &self.state.arrays;
            if let Ok(ranges) = a.check_multi_draw_arrays(mode, first, count, drawcount) {
                let reach = ranges.iter().map(|r| r.end() + 1).max().unwrap_or(0);
                self.record_client_arrays(reach);
            }
        }
        record!(
            self,
            Call::MultiDrawArrays(Box::new((mode, first.to_vec(), count.to_vec(), drawcount)))
        );
        if !self.outside_begin_end() {
            return;
        }
        match self
            .state
            .arrays
            .check_multi_draw_arrays(mode, first, count, drawcount)
        {
            Ok(ranges) => {
                for r in ranges {
                    let reach = r.end() + 1;
                    self.draw(Some(mode), r, reach);
                }
            }
            Err(code) => self.error(code),
        }
    }

    /// `glMultiDrawElements` (GL 1.4, GL 2.1 §2.8): DrawElements(mode, count[i], type,
    /// indices[i]) for each of the first `drawcount` entries; each pointer is client data or an
    /// offset into the ELEMENT_ARRAY_BUFFER. INVALID_VALUE for a negative `drawcount` or slices
    /// shorter than it, INVALID_ENUM for a mode or type, INVALID_VALUE for a negative count,
    /// INVALID_OPERATION as DrawElements raises it for any of the draws. Every draw is checked
    /// before any is drawn.
    pub fn multi_draw_elements(
        &mut self,
        mode: u32,
        count: &[i32],
        ty: u32,
        indices: &[Pointer],
        drawcount: i32,
    ) {
        if self.recording.is_some() && self.begin_mode.is_none() {
            let a = &self.state.arrays;
            if let Ok(draws) = a.check_multi_draw_elements(mode, count, ty, indices, drawcount) {
                let reach = draws
                    .iter()
                    .flat_map(|d| d.iter().max())
                    .max()
                    .map_or(0, |&m| m as usize + 1);
                self.record_client_arrays(reach);
            }
        }
        record!(
            self,
            Call::MultiDrawElements(Box::new((
                mode,
                count.to_vec(),
                ty,
                indices.to_vec(),
                drawcount
            )))
        );
        if !self.outside_begin_end() {
            return;
        }
        match self
            .state
            .arrays
            .check_multi_draw_elements(mode, count, ty, indices, drawcount)
        {
            Ok(draws) => {
                for idx in draws {
                    let reach = idx.iter().max().map_or(0, |&m| m as usize + 1);
                    self.draw(Some(mode), idx.into_iter().map(|i| i as usize), reach);
                }
            }
            Err(code) => self.error(code),
        }
    }

    fn draw_indexed(&mut self, mode: u32, count: i32, ty: u32, p: &Pointer, r: Option<(u32, u32)>) {
        if !self.outside_begin_end() {
            return;
        }
        match self.state.arrays.check_draw_elements(mode, count, ty, p, r) {
            Ok(Some(idx)) => {
                let reach = idx.iter().max().map_or(0, |&m| m as usize + 1);
                self.draw(Some(mode), idx.into_iter().map(|i| i as usize), reach)
            }
            Ok(None) => {}
            Err(code) => self.error(code),
        }
    }

    /// Before a valid draw of DrawElements/DrawRangeElements is recorded: the client arrays
    /// it reads (see [`Context::record_client_arrays`]).
    fn record_client_arrays_indexed(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        p: &Pointer,
        range: Option<(u32, u32)>,
    ) {
        if self.recording.is_none() || self.lists.depth > 0 || self.begin_mode.is_some() {
            return;
        }
        if let Ok(Some(idx)) = self
            .state
            .arrays
            .check_draw_elements(mode, count, ty, p, range)
        {
            let reach = idx.iter().max().map_or(0, |&m| m as usize + 1);
            self.record_client_arrays(reach);
        }
    }

    /// A recorded stream holds bytes, never memory read at draw time ([`Pointer::Client`], the
    /// C ABI's client arrays): before a valid draw that reads `reach` elements is recorded,
    /// each enabled array backed by such memory is recorded as its `*Pointer` call with the
    /// bytes the draw reads (with ARRAY_BUFFER unbound around it, and the array's texture unit
    /// made the client active one), so that a replay draws what this draw drew.
    fn record_client_arrays(&mut self, reach: usize) {
        if self.recording.is_none() || self.lists.depth > 0 {
            return;
        }
        let a = &self.state.arrays;
        let mut calls = Vec::new();
        let mut tex_units = Vec::new();
        let lists: Vec<(Attr, &crate::arrays::ClientArray)> = [
            (Attr::Vertex, &a.vertex),
            (Attr::Normal, &a.normal),
            (Attr::Color, &a.color),
            (Attr::SecondaryColor, &a.secondary_color),
            (Attr::FogCoord, &a.fog_coord),
            (Attr::EdgeFlag, &a.edge_flag),
        ]
        .into_iter()
        .chain(
            a.tex_coords
                .iter()
                .enumerate()
                .map(|(u, t)| (Attr::TexCoord(u), t)),
        )
        .collect();
        for (attr, arr) in lists {
            let Pointer::Client(c) = &arr.pointer else {
                continue;
            };
            if !arr.enabled || arr.buffer != 0 {
                continue;
            }
            let elem = arr.size.max(0) as usize * crate::arrays::type_size(arr.ty);
            let stride = if arr.stride == 0 {
                elem
            } else {
                arr.stride as usize
            };
            let need = reach
                .checked_sub(1)
                .and_then(|l| l.checked_mul(stride))
                .and_then(|n| n.checked_add(elem))
                .unwrap_or(0);
            let data = Pointer::Data(c.read(need).to_vec());
            let (size, ty, stride) = (arr.size, arr.ty, arr.stride);
            if let Attr::TexCoord(u) = attr {
                tex_units.push(u);
                calls.push(Call::ClientActiveTexture(gl::TEXTURE0 + u as u32));
            }
            calls.push(match attr {
                Attr::Vertex => Call::VertexPointer(size, ty, stride, data),
                Attr::Normal => Call::NormalPointer(ty, stride, data),
                Attr::Color => Call::ColorPointer(size, ty, stride, data),
                Attr::SecondaryColor => Call::SecondaryColorPointer(size, ty, stride, data),
                Attr::FogCoord => Call::FogCoordPointer(ty, stride, data),
                Attr::EdgeFlag => Call::EdgeFlagPointer(stride, data),
                Attr::Index => Call::IndexPointer(ty, stride, data),
                Attr::TexCoord(_) => Call::TexCoordPointer(size, ty, stride, data),
            });
        }
        if calls.is_empty() {
            return;
        }
        if !tex_units.is_empty() {
            let unit = gl::TEXTURE0 + self.state.client_active_texture as u32;
            calls.push(Call::ClientActiveTexture(unit));
        }
        let bound = a.array_buffer;
        let rec = self.recording.as_mut().expect("checked above");
        if bound != 0 {
            rec.push(Call::BindBuffer(gl::ARRAY_BUFFER, 0));
        }
        rec.extend(calls);
        if bound != 0 {
            rec.push(Call::BindBuffer(gl::ARRAY_BUFFER, bound));
        }
    }

    /// `Begin(mode)` (when given), ArrayElement(i) for each index, `End`; the indices are
    /// already checked against every enabled array, and the largest is below `reach`.
    fn draw(&mut self, mode: Option<u32>, indices: impl IntoIterator<Item = usize>, reach: usize) {
        // GL 3.0 §4.4.4: nothing is drawn into an incomplete framebuffer object.
        if mode.is_some() && self.framebuffer_incomplete() {
            return;
        }
        let arrays = std::mem::take(&mut self.state.arrays);
        let sources = arrays.sources(reach);
        // DrawArrays and DrawElements leave the current attributes (and the materials
        // COLOR_MATERIAL tracks) as they were: GL 2.1 §2.8 makes them indeterminate after the
        // draw, and Mesa draws from the arrays without touching them. ArrayElement sets them.
        let kept = mode.map(|_| (self.state.current, self.state.materials));
        if !sources.is_empty() {
            if let Some(mode) = mode {
                self.begin_mode = Some(mode);
                self.renderer.begin(mode);
                self.renderer.begin_materials(&self.state.materials);
            }
            for i in indices {
                self.element(&sources, i);
            }
            if mode.is_some() {
                self.begin_mode = None;
                self.renderer.end();
                self.renderer.flush_if_large(&self.state);
            }
        }
        drop(sources);
        self.state.arrays = arrays;
        if let Some((current, materials)) = kept {
            self.state.current = current;
            self.state.materials = materials;
        }
    }

    /// What a vertex-array call compiles into a display list (GL 2.1 §5.4: "the array data are
    /// resolved at compile time"): for a draw that is valid against the arrays current now,
    /// the immediate-mode calls it amounts to — Begin, per element the enabled arrays' attribute
    /// calls and the vertex, End — so the list keeps this data whatever the arrays hold when it
    /// runs. `Ok(None)` for any other call, and for a draw that is erroneous now: that one is
    /// compiled as it is, to raise its error when the list runs. Texture coordinates of units
    /// other than 0 become MultiTexCoord calls.
    ///
    /// Memory: with no array enabled nothing is drawn and nothing is stored, whatever the count
    /// (DrawArrays' count is then bounded by nothing). Otherwise every index is checked against
    /// the enabled arrays (or read from the caller's index bytes), so the calls are bounded by
    /// the data handed over; they are reserved in one `try_reserve_exact`, and a failure is
    /// `Err(OUT_OF_MEMORY)` instead of an abort.
    pub(crate) fn compile_draw(&self, call: &Call) -> Result<Option<Vec<Call>>, u32> {
        if !compiles_draw(call) {
            return Ok(None);
        }
        // Not a draw, but resolved at compile time too: the stipple unpacked now (stipple.rs).
        if let Call::PolygonStipple(mask) = call {
            return Ok(self.compile_polygon_stipple(mask));
        }
        let arrays = &self.state.arrays;
        // A multiple draw compiles into its draws, one after the other (Mesa: DrawArrays and
        // DrawElements each), when it is valid as a whole now.
        let parts: Option<Vec<Call>> = match call {
            Call::MultiDrawArrays(args) => {
                let (mode, ref first, ref count, drawcount) = **args;
                match arrays.check_multi_draw_arrays(mode, first, count, drawcount) {
                    Ok(ranges) => Some(
                        ranges
                            .into_iter()
                            .map(|r| {
                                let n = r.end() - r.start() + 1;
                                Call::DrawArrays(mode, *r.start() as i32, n as i32)
                            })
                            .collect(),
                    ),
                    Err(gl::OUT_OF_MEMORY) => return Err(gl::OUT_OF_MEMORY),
                    Err(_) => return Ok(None),
                }
            }
            Call::MultiDrawElements(args) => {
                let (mode, ref count, ty, ref indices, drawcount) = **args;
                match arrays.check_multi_draw_elements(mode, count, ty, indices, drawcount) {
                    Ok(_) => Some(
                        count
                            .iter()
                            .zip(indices)
                            .take(drawcount.max(0) as usize)
                            .filter(|(&c, _)| c > 0)
                            .map(|(&c, p)| Call::DrawElements(mode, c, ty, p.clone()))
                            .collect(),
                    ),
                    Err(gl::OUT_OF_MEMORY) => return Err(gl::OUT_OF_MEMORY),
                    Err(_) => return Ok(None),
                }
            }
            _ => None,
        };
        if let Some(parts) = parts {
            let mut calls = Vec::new();
            for part in &parts {
                if let Some(mut c) = self.compile_draw(part)? {
                    calls.try_reserve(c.len()).map_err(|_| gl::OUT_OF_MEMORY)?;
                    calls.append(&mut c);
                }
            }
            return Ok(Some(calls));
        }
        // Checked first, as the draw itself would be: an erroneous draw compiles as it is.
        let (mode, indices) = match call {
            Call::ArrayElement(i) => match arrays.check_array_element(*i) {
                Ok(i) => (None, Indices::Range(i..=i)),
                Err(_) => return Ok(None),
            },
            Call::DrawArrays(mode, first, count) => {
                match arrays.check_draw_arrays(*mode, *first, *count) {
                    Ok(Some(range)) => (Some(*mode), Indices::Range(range)),
                    Ok(None) => (Some(*mode), Indices::List(Vec::new())),
                    Err(_) => return Ok(None),
                }
            }
            Call::DrawElements(mode, count, ty, p) => {
                match arrays.check_draw_elements(*mode, *count, *ty, p, None) {
                    Ok(idx) => (Some(*mode), Indices::List(idx.unwrap_or_default())),
                    Err(gl::OUT_OF_MEMORY) => return Err(gl::OUT_OF_MEMORY),
                    Err(_) => return Ok(None),
                }
            }
            Call::DrawRangeElements(mode, start, end, count, ty, p) => {
                match arrays.check_draw_elements(*mode, *count, *ty, p, Some((*start, *end))) {
                    Ok(idx) => (Some(*mode), Indices::List(idx.unwrap_or_default())),
                    Err(gl::OUT_OF_MEMORY) => return Err(gl::OUT_OF_MEMORY),
                    Err(_) => return Ok(None),
                }
            }
            _ => return Ok(None),
        };
        let reach = match &indices {
            Indices::Range(r) => r.end().saturating_add(1),
            Indices::List(v) => v.iter().max().map_or(0, |&m| m as usize + 1),
        };
        let sources = arrays.sources(reach);
        if sources.is_empty() {
            // Mesa compiles the Begin/End pair all the same: run between Begin and End, the
            // list raises INVALID_OPERATION as the draw would (piglit's dlist-beginend).
            return Ok(Some(
                mode.map_or_else(Vec::new, |m| vec![Call::Begin(m), Call::End]),
            ));
        }
        // One call per element per source that has an immediate-mode call, Begin and End.
        let per_index = sources.len();
        let total = indices
            .len()
            .checked_mul(per_index)
            .and_then(|n| n.checked_add(2))
            .ok_or(gl::OUT_OF_MEMORY)?;
        let mut calls = Vec::new();
        calls
            .try_reserve_exact(total)
            .map_err(|_| gl::OUT_OF_MEMORY)?;
        calls.extend(mode.map(Call::Begin));
        for i in indices.iter() {
            for s in &sources {
                let Some([x, y, z, w]) = s.fetch(i) else {
                    continue;
                };
                calls.extend(match s.attr {
                    Attr::EdgeFlag => Some(Call::EdgeFlag(x != 0.0)),
                    Attr::TexCoord(0) => Some(Call::TexCoord4f(x, y, z, w)),
                    Attr::TexCoord(u) => {
                        Some(Call::MultiTexCoord4f(gl::TEXTURE0 + u as u32, x, y, z, w))
                    }
                    Attr::Color => Some(Call::Color4f(x, y, z, w)),
                    Attr::SecondaryColor => Some(Call::SecondaryColor3f(x, y, z)),
                    Attr::FogCoord => Some(Call::FogCoordf(x)),
                    Attr::Normal => Some(Call::Normal3f(x, y, z)),
                    Attr::Vertex => Some(Call::Vertex4f(x, y, z, w)),
                    // Not a source: no draw reads colour indices in RGBA mode.
                    Attr::Index => None,
                });
            }
        }
        calls.extend(mode.map(|_| Call::End));
        debug_assert!(calls.len() <= total, "compile_draw reserved too little");
        Ok(Some(calls))
    }

    /// ArrayElement's body for an index already checked against every source.
    fn element(&mut self, sources: &[Source<'_>], i: usize) {
        for s in sources {
            let Some(v) = s.fetch(i) else { continue };
            let c = &mut self.state.current;
            match s.attr {
                Attr::EdgeFlag => c.inputs_mut().edge_flag = v[0] != 0.0,
                Attr::TexCoord(u) => {
                    if let Some(t) = c.inputs_mut().tex_coords.get_mut(u) {
                        *t = Vec4::from_array(v);
                    }
                }
                Attr::Color => {
                    c.inputs_mut().color = Vec4::from_array(v);
                    if self.state.enables.color_material {
                        self.track_color_material();
                    }
                }
                Attr::SecondaryColor => {
                    c.inputs_mut().secondary_color = Vec3::new(v[0], v[1], v[2]).extend(1.0)
                }
                Attr::FogCoord => c.inputs_mut().fog_coord = v[0],
                Attr::Normal => c.normal = Vec3::new(v[0], v[1], v[2]),
                Attr::Vertex => self.vertex(Vec4::from_array(v)),
                Attr::Index => {}
            }
        }
    }

    /// `glGenBuffers`: writes `n` unused names to `buffers`. INVALID_VALUE for a negative `n`
    /// or a `buffers` shorter than `n`.
    pub fn gen_buffers(&mut self, n: i32, buffers: &mut [u32]) {
        let mut made = Vec::new();
        self.objects_txn(super::share::BUFFERS, &[], |ctx| {
            ctx.arrays_do(|a, _| {
                a.gen_buffers(n, buffers)?;
                made = buffers.get(..n.max(0) as usize).unwrap_or(&[]).to_vec();
                Ok(())
            })
        });
        record!(self, Call::GenBuffers(n, made));
    }

    /// The name bound to buffer target `target` (0 for none or for a target that is none).
    fn buffer_binding(&self, target: u32) -> u32 {
        match target {
            gl::ARRAY_BUFFER => self.state.arrays.array_buffer,
            gl::ELEMENT_ARRAY_BUFFER => self.state.arrays.element_array_buffer,
            _ => 0,
        }
    }

    /// `glDeleteBuffers`: INVALID_VALUE for a negative `n` or fewer than `n` names.
    pub fn delete_buffers(&mut self, n: i32, buffers: &[u32]) {
        record!(self, Call::DeleteBuffers(n, buffers.to_vec()));
        self.objects_txn(super::share::BUFFERS, buffers, |ctx| {
            ctx.arrays_do(|a, _| a.delete_buffers(n, buffers))
        });
    }

    /// `glIsBuffer`: whether `buffer` names a buffer object (one bound at least once).
    pub fn is_buffer(&mut self, buffer: u32) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.pull_objects();
        self.state.arrays.is_buffer(buffer)
    }

    /// `glBindBuffer`: ARRAY_BUFFER or ELEMENT_ARRAY_BUFFER (else INVALID_ENUM).
    pub fn bind_buffer(&mut self, target: u32, buffer: u32) {
        record!(self, Call::BindBuffer(target, buffer));
        self.objects_txn(super::share::BUFFERS, &[buffer], |ctx| {
            ctx.arrays_do(|a, _| a.bind_buffer(target, buffer))
        });
    }

    /// `glBufferData`: `size` bytes from `data` (or zeros for [`Pointer::NULL`]) into the
    /// buffer bound to `target`, replacing its store. INVALID_ENUM for a target or usage,
    /// INVALID_VALUE for a negative size or a `data` shorter than `size`, INVALID_OPERATION with
    /// no buffer bound, OUT_OF_MEMORY past [`crate::arrays::MAX_BUFFER_SIZE`] without data.
    pub fn buffer_data(&mut self, target: u32, size: isize, data: impl Into<Pointer>, usage: u32) {
        let p = data.into();
        record!(
            self,
            Call::BufferData(target, size, Box::new(p.clone()), usage)
        );
        let name = [self.buffer_binding(target)];
        self.objects_txn(super::share::BUFFERS, &name, |ctx| {
            ctx.arrays_do(|a, _| a.buffer_data(target, size, &p, usage))
        });
    }

    /// `glBufferSubData`: INVALID_VALUE when `offset` or `size` is negative, the range passes
    /// the buffer's end, or `data` is shorter than `size`; otherwise as `buffer_data`.
    pub fn buffer_sub_data(
        &mut self,
        target: u32,
        offset: isize,
        size: isize,
        data: impl Into<Pointer>,
    ) {
        let p = data.into();
        record!(
            self,
            Call::BufferSubData(target, offset, size, Box::new(p.clone()))
        );
        let name = [self.buffer_binding(target)];
        self.objects_txn(super::share::BUFFERS, &name, |ctx| {
            ctx.arrays_do(|a, _| a.buffer_sub_data(target, offset, size, &p))
        });
    }

    /// `glGetBufferSubData` into `data` (a query: not recorded); errors as `buffer_sub_data`.
    pub fn get_buffer_sub_data(
        &mut self,
        target: u32,
        offset: isize,
        size: isize,
        data: &mut [u8],
    ) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.pull_objects();
        if let Err(code) = self
            .state
            .arrays
            .get_buffer_sub_data(target, offset, size, data)
        {
            self.error(code);
        }
    }

    /// `glGetBufferParameteriv`: BUFFER_SIZE, BUFFER_USAGE, BUFFER_ACCESS or BUFFER_MAPPED of
    /// the buffer bound to `target`. INVALID_ENUM for a target or pname, INVALID_OPERATION with
    /// none bound, INVALID_VALUE for an empty `params`.
    pub fn get_buffer_parameteriv(&mut self, target: u32, pname: u32, params: &mut [i32]) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.pull_objects();
        match self.state.arrays.buffer_parameter(target, pname) {
            Ok(v) => match params.first_mut() {
                Some(p) => *p = v,
                None => self.error(gl::INVALID_VALUE),
            },
            Err(code) => self.error(code),
        }
    }

    /// `glMapBuffer` (GL 1.5, GL 2.1 §2.9): maps the store of the buffer bound to `target`
    /// (ARRAY_BUFFER or ELEMENT_ARRAY_BUFFER) for `access` (READ_ONLY, WRITE_ONLY or
    /// READ_WRITE) and returns it. INVALID_ENUM for an access or a target; INVALID_OPERATION
    /// between Begin and End, with no buffer bound, for a buffer already mapped, and (as
    /// llvmpipe) for an empty one; `None` on any error.
    ///
    /// While mapped, BufferSubData and GetBufferSubData on the buffer, and every draw that reads
    /// it (an enabled array or the index data in it), are INVALID_OPERATION (§2.9). The store
    /// does not move until UnmapBuffer, BufferData or DeleteBuffers ends the mapping (or the
    /// context is reset or dropped): [`Context::mapped_buffer_mut`] hands it out again, and a C
    /// caller may keep its address until then. Not compiled into display lists (§5.4).
    ///
    /// Recording: the bytes written through the mapping are recorded with the `UnmapBuffer`
    /// that ends it (`Call::UnmapBuffer(target, written)`), so a replay — on another context or
    /// on the driver — writes the same bytes into its own mapping before unmapping.
    pub fn map_buffer(&mut self, target: u32, access: u32) -> Option<&mut [u8]> {
        // Executed immediately, never compiled (GL 2.1 §5.4): recorded only.
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::MapBuffer(target, access));
        }
        if !self.outside_begin_end() {
            return None;
        }
        match self.state.arrays.map_buffer(target, access) {
            Ok(name) => {
                if self.recording.is_some() {
                    let store = self.state.arrays.buffers.get(&name).map(|b| b.data.clone());
                    self.map_snapshots.insert(name, store.unwrap_or_default());
                }
                self.state.arrays.mapped_mut(target)
            }
            Err(code) => {
                self.error(code);
                None
            }
        }
    }

    /// The store of the buffer bound to `target` while it is mapped (`None` otherwise): what
    /// `map_buffer` returned, again. Not a GL command (GetBufferPointerv is its GL form); it
    /// raises no error and is not recorded.
    pub fn mapped_buffer_mut(&mut self, target: u32) -> Option<&mut [u8]> {
        self.state.arrays.mapped_mut(target)
    }

    /// `glUnmapBuffer` (GL 2.1 §2.9): ends the mapping of the buffer bound to `target`; true
    /// on success (fixedgl's store cannot be lost while mapped). INVALID_ENUM for a target,
    /// INVALID_OPERATION between Begin and End, with no buffer bound or one not mapped (false).
    pub fn unmap_buffer(&mut self, target: u32) -> bool {
        // Executed immediately, never compiled (GL 2.1 §5.4): recorded only.
        if self.recording.is_some() && self.lists.depth == 0 {
            let written = Box::new(self.map_writes(target));
            if let Some(rec) = self.recording.as_mut() {
                rec.push(Call::UnmapBuffer(target, written));
            }
        }
        let name = [self.buffer_binding(target)];
        self.objects_txn(super::share::BUFFERS, &name, |ctx| {
            ctx.unmap_buffer_now(target)
        })
    }

    fn unmap_buffer_now(&mut self, target: u32) -> bool {
        if !self.outside_begin_end() {
            return false;
        }
        match self.state.arrays.unmap_buffer(target) {
            Ok(name) => {
                self.map_snapshots.remove(&name);
                true
            }
            Err(code) => {
                self.error(code);
                false
            }
        }
    }

    /// What UnmapBuffer records: the bytes of the mapped store from its first to its last byte
    /// that differ from the store at MapBuffer (the whole store if the mapping began before the
    /// recording did); `(0, [])` when nothing changed or nothing is mapped.
    fn map_writes(&self, target: u32) -> MapWrites {
        let arrays = &self.state.arrays;
        let name = match target {
            gl::ARRAY_BUFFER => arrays.array_buffer,
            gl::ELEMENT_ARRAY_BUFFER => arrays.element_array_buffer,
            _ => 0,
        };
        let Some(b) = arrays.buffers.get(&name).filter(|b| b.mapped) else {
            return (0, Vec::new());
        };
        let Some(before) = self.map_snapshots.get(&name) else {
            return (0, b.data.clone());
        };
        let differs = |(a, b): (&u8, &u8)| a != b;
        let first = b.data.iter().zip(before).position(differs);
        let last = b.data.iter().zip(before).rposition(differs);
        match (first, last) {
            (Some(f), Some(l)) => (f, b.data.get(f..=l).unwrap_or(&[]).to_vec()),
            _ => (0, Vec::new()),
        }
    }

    /// A recorded `UnmapBuffer(target, written)`: when the buffer bound to `target` is mapped,
    /// the bytes the recorded program wrote through its mapping are written into this one (the
    /// part that fits), then `unmap_buffer` runs as the program called it.
    pub(super) fn replay_unmap_buffer(&mut self, target: u32, written: &MapWrites) {
        if self.begin_mode.is_none() {
            if let Some(store) = self.state.arrays.mapped_mut(target) {
                write_into(store, written);
            }
        }
        self.unmap_buffer(target);
    }

    /// `glGetBufferPointerv(target, BUFFER_MAP_POINTER)`: the address of the mapped store of the
    /// buffer bound to `target`, null when it is not mapped. INVALID_ENUM for a target or another
    /// pname, INVALID_OPERATION between Begin and End or with no buffer bound (null then).
    pub fn get_buffer_pointerv(&mut self, target: u32, pname: u32) -> *mut std::ffi::c_void {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return std::ptr::null_mut();
        }
        match self.state.arrays.buffer_pointer(target, pname) {
            Ok(Some(store)) => store.as_mut_ptr().cast(),
            Ok(None) => std::ptr::null_mut(),
            Err(code) => {
                self.error(code);
                std::ptr::null_mut()
            }
        }
    }

    /// `glGetPointerv`: the pointer of VERTEX_ARRAY_POINTER, NORMAL_ARRAY_POINTER,
    /// COLOR_ARRAY_POINTER, SECONDARY_COLOR_ARRAY_POINTER, FOG_COORD_ARRAY_POINTER,
    /// EDGE_FLAG_ARRAY_POINTER or TEXTURE_COORD_ARRAY_POINTER (client active unit): the bytes
    /// the context holds, or the offset. INVALID_ENUM (and [`Pointer::NULL`]) for another pname.
    pub fn get_pointerv(&mut self, pname: u32) -> Pointer {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return Pointer::NULL;
        }
        let a = &self.state.arrays;
        let array = match pname {
            gl::VERTEX_ARRAY_POINTER => Some(&a.vertex),
            gl::NORMAL_ARRAY_POINTER => Some(&a.normal),
            gl::COLOR_ARRAY_POINTER => Some(&a.color),
            gl::SECONDARY_COLOR_ARRAY_POINTER => Some(&a.secondary_color),
            gl::FOG_COORD_ARRAY_POINTER => Some(&a.fog_coord),
            gl::EDGE_FLAG_ARRAY_POINTER => Some(&a.edge_flag),
            gl::INDEX_ARRAY_POINTER => Some(&a.index),
            gl::TEXTURE_COORD_ARRAY_POINTER => a.tex_coords.get(self.state.client_active_texture),
            _ => None,
        };
        match array {
            Some(arr) => arr.pointer.clone(),
            None => {
                self.error(gl::INVALID_ENUM);
                Pointer::NULL
            }
        }
    }
}

/// Writes a recorded UnmapBuffer's bytes into a mapped store, the part that fits (all of it,
/// for a recording of the same program).
pub(crate) fn write_into(store: &mut [u8], (offset, bytes): &MapWrites) {
    if let Some(dst) = store.get_mut(*offset..) {
        let n = dst.len().min(bytes.len());
        if let (Some(d), Some(s)) = (dst.get_mut(..n), bytes.get(..n)) {
            d.copy_from_slice(s);
        }
    }
}

/// The indices a compiled draw visits: a checked range (DrawArrays, ArrayElement) is walked,
/// never collected, so its storage does not grow with the count.
enum Indices {
    Range(std::ops::RangeInclusive<usize>),
    List(Vec<u32>),
}

impl Indices {
    fn len(&self) -> usize {
        match self {
            Indices::Range(r) => r.end().saturating_sub(*r.start()).saturating_add(1),
            Indices::List(v) => v.len(),
        }
    }

    fn iter(&self) -> Box<dyn Iterator<Item = usize> + '_> {
        match self {
            Indices::Range(r) => Box::new(r.clone()),
            Indices::List(v) => Box::new(v.iter().map(|&i| i as usize)),
        }
    }
}
