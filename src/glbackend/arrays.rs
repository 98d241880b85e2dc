//! Vertex arrays and buffer objects on the driver (GL 2.1 §2.8, §2.9).
//!
//! The backend keeps a shadow [`ArrayState`] that every array call is first applied to, with the
//! front end's own validation: a call the front end refuses (a draw that would read past the
//! data, a short slice) is refused here with the same error and never reaches the driver, which
//! would read out of bounds.
//!
//! Design decision: the driver's client pointers point into the shadow's copies of the recorded
//! bytes (a recorded `Call` does not outlive `execute`), and after any call that changes array
//! state the driver's whole array state is re-sent from the shadow (`sync_arrays`), so one
//! function, not one per command, keeps those pointers valid. `GenBuffers` is not sent: the
//! shadow reserves the recorded names and `BindBuffer` binds them, which the compatibility
//! profile allows for any name (GL 2.1 §2.9), so driver and front end agree on names.

use std::ffi::c_void;

use super::GlBackend;
use crate::arrays::{ArrayState, ClientArray, Pointer};
use crate::gl;
use crate::Call;

/// The pointer the driver gets for an array or index argument: client bytes (which live in the
/// shadow or the recorded call), or the offset as GL 1.5 reads it with a buffer bound.
fn ptr(p: &Pointer) -> *const c_void {
    match p {
        Pointer::Data(d) => d.as_ptr().cast(),
        Pointer::Offset(o) => *o as *const c_void,
        // Never recorded (a recording holds the bytes a draw read), so never replayed.
        Pointer::Client(_) => std::ptr::null(),
    }
}

impl GlBackend {
    /// Replays one call of the arrays area.
    pub(super) fn arrays_call(&mut self, call: &Call) {
        if self.inside_begin_end && !matches!(call, Call::ArrayElement(_)) {
            return self.raise(gl::INVALID_OPERATION);
        }
        let unit = self.client_unit();
        let mut shadow = std::mem::take(&mut self.arrays);
        let result = self.arrays_apply(&mut shadow, call, unit);
        self.arrays = shadow;
        if let Err(code) = result {
            self.raise(code);
        }
    }

    /// The driver's CLIENT_ACTIVE_TEXTURE unit (outside Begin/End).
    fn client_unit(&self) -> usize {
        if self.inside_begin_end {
            return 0;
        }
        let mut v = [gl::TEXTURE0 as i32];
        // SAFETY: context current (see `execute`); CLIENT_ACTIVE_TEXTURE writes one integer.
        unsafe {
            self.raw
                .GetIntegerv(gl::CLIENT_ACTIVE_TEXTURE, v.as_mut_ptr())
        };
        (v[0] as u32).wrapping_sub(gl::TEXTURE0) as usize
    }

    fn arrays_apply(&mut self, a: &mut ArrayState, call: &Call, unit: usize) -> Result<(), u32> {
        use crate::arrays::Attr;
        let gl = &self.raw;
        // Every unsafe block below: the context is current; the shadow has validated the call,
        // so each pointer holds at least the bytes the driver reads: client data, index data and
        // buffer data are as long as the counts and sizes it checked.
        match *call {
            Call::EnableClientState(cap) => a.enable_client_state(cap, true, unit)?,
            Call::DisableClientState(cap) => a.enable_client_state(cap, false, unit)?,
            Call::VertexPointer(s, t, st, ref p) => a.pointer(Attr::Vertex, s, t, st, p)?,
            Call::NormalPointer(t, st, ref p) => a.pointer(Attr::Normal, 3, t, st, p)?,
            Call::ColorPointer(s, t, st, ref p) => a.pointer(Attr::Color, s, t, st, p)?,
            Call::SecondaryColorPointer(s, t, st, ref p) => {
                a.pointer(Attr::SecondaryColor, s, t, st, p)?
            }
            Call::TexCoordPointer(s, t, st, ref p) => {
                a.pointer(Attr::TexCoord(unit), s, t, st, p)?
            }
            Call::FogCoordPointer(t, st, ref p) => a.pointer(Attr::FogCoord, 1, t, st, p)?,
            Call::EdgeFlagPointer(st, ref p) => {
                a.pointer(Attr::EdgeFlag, 1, gl::UNSIGNED_BYTE, st, p)?
            }
            Call::IndexPointer(t, st, ref p) => a.pointer(Attr::Index, 1, t, st, p)?,
            Call::InterleavedArrays(f, st, ref p) => a.interleaved_arrays(f, st, p, unit)?,
            Call::ArrayElement(i) => {
                a.check_array_element(i)?;
                // SAFETY: the shadow checked that index `i` lies inside every enabled array.
                unsafe { gl.ArrayElement(i) };
                return Ok(());
            }
            Call::DrawArrays(mode, first, count) => {
                // With no array enabled there is nothing to read and nothing to draw.
                if a.check_draw_arrays(mode, first, count)?.is_some() && !a.sources(0).is_empty() {
                    self.before_begin();
                    // SAFETY: the shadow checked first + count against every enabled array.
                    unsafe { self.raw.DrawArrays(mode, first, count) };
                }
                return Ok(());
            }
            Call::DrawElements(mode, count, ty, ref p) => {
                if a.check_draw_elements(mode, count, ty, p, None)?.is_some()
                    && !a.sources(0).is_empty()
                {
                    self.before_begin();
                    // SAFETY: `p` holds `count` indices of `ty` (or is an offset into the bound
                    // element buffer), each inside every enabled array, as the shadow checked.
                    unsafe { self.raw.DrawElements(mode, count, ty, ptr(p)) };
                }
                return Ok(());
            }
            Call::DrawRangeElements(mode, s, e, count, ty, ref p) => {
                if a.check_draw_elements(mode, count, ty, p, Some((s, e)))?
                    .is_some()
                {
                    self.before_begin();
                    // SAFETY: as DrawElements: indices and arrays checked by the shadow.
                    unsafe { self.raw.DrawRangeElements(mode, s, e, count, ty, ptr(p)) };
                }
                return Ok(());
            }
            Call::MultiDrawArrays(ref args) => {
                let (mode, ref first, ref count, drawcount) = **args;
                let ranges = a.check_multi_draw_arrays(mode, first, count, drawcount)?;
                // The draws the shadow checked, each as (first, count): the call's own minus
                // those that draw nothing.
                let firsts: Vec<i32> = ranges.iter().map(|r| *r.start() as i32).collect();
                let counts: Vec<i32> = ranges
                    .iter()
                    .map(|r| (r.end() - r.start() + 1) as i32)
                    .collect();
                if !firsts.is_empty() && !a.sources(0).is_empty() {
                    self.before_begin();
                    // SAFETY: `firsts` and `counts` hold `firsts.len()` values each, and every
                    // range lies inside every enabled array, as the shadow checked.
                    unsafe {
                        self.raw.MultiDrawArrays(
                            mode,
                            firsts.as_ptr(),
                            counts.as_ptr(),
                            firsts.len() as i32,
                        )
                    };
                }
                return Ok(());
            }
            Call::MultiDrawElements(ref args) => {
                let (mode, ref count, ty, ref indices, drawcount) = **args;
                a.check_multi_draw_elements(mode, count, ty, indices, drawcount)?;
                let (counts, pointers): (Vec<i32>, Vec<*const c_void>) = count
                    .iter()
                    .zip(indices)
                    .take(drawcount.max(0) as usize)
                    .filter(|(&c, _)| c > 0)
                    .map(|(&c, p)| (c, ptr(p)))
                    .unzip();
                if !counts.is_empty() && !a.sources(0).is_empty() {
                    self.before_begin();
                    // SAFETY: one count and one pointer per draw; each pointer holds its count
                    // of indices of `ty` (or is an offset into the bound element buffer), each
                    // inside every enabled array, as the shadow checked.
                    unsafe {
                        self.raw.MultiDrawElements(
                            mode,
                            counts.as_ptr(),
                            ty,
                            pointers.as_ptr(),
                            counts.len() as i32,
                        )
                    };
                }
                return Ok(());
            }
            Call::GenBuffers(n, ref names) => {
                let n = usize::try_from(n).map_err(|_| gl::INVALID_VALUE)?;
                a.reserve(names.get(..n).ok_or(gl::INVALID_VALUE)?);
                return Ok(());
            }
            Call::DeleteBuffers(n, ref names) => {
                a.delete_buffers(n, names)?;
                // SAFETY: the shadow checked that `names` holds at least `n` names.
                unsafe { gl.DeleteBuffers(n, names.as_ptr()) };
            }
            Call::BindBuffer(target, name) => {
                a.bind_buffer(target, name)?;
                // SAFETY: no pointers.
                unsafe { gl.BindBuffer(target, name) };
                return Ok(());
            }
            Call::BufferData(target, size, ref p, usage) => {
                a.buffer_data(target, size, p, usage)?;
                let data = match **p {
                    Pointer::Data(_) => ptr(p),
                    Pointer::Offset(_) | Pointer::Client(_) => std::ptr::null(),
                };
                // SAFETY: `data` is null or holds `size` bytes, as the shadow checked.
                unsafe { gl.BufferData(target, size, data, usage) };
                return Ok(());
            }
            Call::MapBuffer(target, access) => {
                a.map_buffer(target, access)?;
                // SAFETY: no pointer is passed; the returned one is not kept (UnmapBuffer asks
                // the driver for it again).
                unsafe { gl.MapBuffer(target, access) };
                return Ok(());
            }
            Call::UnmapBuffer(target, ref written) => {
                let size = a.mapped_mut(target).map_or(0, |store| {
                    crate::context::write_into(store, written);
                    store.len()
                });
                a.unmap_buffer(target)?;
                let mut mapped: *mut c_void = std::ptr::null_mut();
                // The generated binding declares the output `*const *mut c_void`; the driver
                // writes one pointer through it.
                let out: *const *mut c_void = std::ptr::addr_of_mut!(mapped);
                // SAFETY: BUFFER_MAP_POINTER writes one pointer, into `mapped`.
                unsafe { gl.GetBufferPointerv(target, gl::BUFFER_MAP_POINTER, out) };
                if !mapped.is_null() {
                    // SAFETY: the driver maps the whole store of the buffer bound to `target`,
                    // whose size the shadow holds (`size`: the same BufferData made both), and
                    // `driver` is that mapping; no other reference to it exists.
                    let driver =
                        unsafe { std::slice::from_raw_parts_mut(mapped.cast::<u8>(), size) };
                    crate::context::write_into(driver, written);
                }
                // SAFETY: no pointers.
                unsafe { gl.UnmapBuffer(target) };
                return Ok(());
            }
            Call::BufferSubData(target, offset, size, ref p) => {
                a.buffer_sub_data(target, offset, size, p)?;
                // SAFETY: `p` holds `size` bytes, and offset + size fits the bound buffer, as
                // the shadow checked.
                unsafe { gl.BufferSubData(target, offset, size, ptr(p)) };
                return Ok(());
            }
            _ => return Ok(()),
        }
        self.sync_arrays(a, unit);
        Ok(())
    }

    /// After `PopClientAttrib`: the shadow's client arrays and bindings return to `saved` (the
    /// buffer objects, which are not client state, stay as they are; a binding to one deleted
    /// since reverts to 0), and the driver is re-sent the whole array state, because the
    /// pointers it restored may point into copies the shadow has since dropped.
    pub(super) fn restore_client_arrays(&mut self, saved: ArrayState) {
        let buffers = std::mem::take(&mut self.arrays.buffers);
        let reserved = std::mem::take(&mut self.arrays.reserved);
        let mut a = saved;
        a.buffers = buffers;
        a.reserved = reserved;
        let exists = |n: u32, a: &ArrayState| n == 0 || a.buffers.contains_key(&n);
        if !exists(a.array_buffer, &a) {
            a.array_buffer = 0;
        }
        if !exists(a.element_array_buffer, &a) {
            a.element_array_buffer = 0;
        }
        let names: Vec<u32> = [
            &a.vertex,
            &a.normal,
            &a.color,
            &a.secondary_color,
            &a.fog_coord,
            &a.edge_flag,
            &a.index,
        ]
        .into_iter()
        .chain(a.tex_coords.iter())
        .map(|c| c.buffer)
        .filter(|&n| !exists(n, &a))
        .collect();
        for n in names {
            // Reverts every array bound to the vanished buffer, as deleting it would have.
            a.buffers.insert(n, Default::default());
            let _ = a.delete_buffers(1, &[n]);
        }
        let unit = self.client_unit();
        self.sync_arrays(&a, unit);
        self.arrays = a;
    }

    /// Sends the shadow's whole array state to the driver: each array's buffer, format,
    /// pointer and enable, then the ARRAY_BUFFER and ELEMENT_ARRAY_BUFFER bindings and the
    /// client active unit as they were.
    fn sync_arrays(&self, a: &ArrayState, unit: usize) {
        let gl = &self.raw;
        // SAFETY: context current; no pointers.
        let enable = |cap: u32, arr: &ClientArray| unsafe {
            if arr.enabled {
                gl.EnableClientState(cap);
            } else {
                gl.DisableClientState(cap);
            }
        };
        // SAFETY: context current; every client pointer points into the shadow, which keeps the
        // bytes alive and unmoved until the next change of that array (followed by a new sync).
        unsafe {
            let bind = |arr: &ClientArray| gl.BindBuffer(gl::ARRAY_BUFFER, arr.buffer);
            bind(&a.vertex);
            gl.VertexPointer(
                a.vertex.size,
                a.vertex.ty,
                a.vertex.stride,
                ptr(&a.vertex.pointer),
            );
            enable(gl::VERTEX_ARRAY, &a.vertex);
            bind(&a.normal);
            gl.NormalPointer(a.normal.ty, a.normal.stride, ptr(&a.normal.pointer));
            enable(gl::NORMAL_ARRAY, &a.normal);
            bind(&a.color);
            gl.ColorPointer(
                a.color.size,
                a.color.ty,
                a.color.stride,
                ptr(&a.color.pointer),
            );
            enable(gl::COLOR_ARRAY, &a.color);
            let s = &a.secondary_color;
            bind(s);
            gl.SecondaryColorPointer(s.size, s.ty, s.stride, ptr(&s.pointer));
            enable(gl::SECONDARY_COLOR_ARRAY, s);
            bind(&a.fog_coord);
            gl.FogCoordPointer(
                a.fog_coord.ty,
                a.fog_coord.stride,
                ptr(&a.fog_coord.pointer),
            );
            enable(gl::FOG_COORD_ARRAY, &a.fog_coord);
            bind(&a.edge_flag);
            gl.EdgeFlagPointer(a.edge_flag.stride, ptr(&a.edge_flag.pointer));
            enable(gl::EDGE_FLAG_ARRAY, &a.edge_flag);
            bind(&a.index);
            gl.IndexPointer(a.index.ty, a.index.stride, ptr(&a.index.pointer));
            enable(gl::INDEX_ARRAY, &a.index);
            for (u, t) in a.tex_coords.iter().enumerate() {
                gl.ClientActiveTexture(gl::TEXTURE0 + u as u32);
                bind(t);
                gl.TexCoordPointer(t.size, t.ty, t.stride, ptr(&t.pointer));
                enable(gl::TEXTURE_COORD_ARRAY, t);
            }
            gl.ClientActiveTexture(gl::TEXTURE0 + unit as u32);
            gl.BindBuffer(gl::ARRAY_BUFFER, a.array_buffer);
            gl.BindBuffer(gl::ELEMENT_ARRAY_BUFFER, a.element_array_buffer);
        }
    }
}
