//! Display lists (GL 2.1 §5.4): `GenLists`, `NewList`, `EndList`, `CallList`, `CallLists`,
//! `ListBase`, `DeleteLists`, `IsList`.
//!
//! A display list is a `Vec<Call>`, the very stream a recording holds. While a list is being
//! defined, every entry point's `record!` line appends its call to the list (and, under COMPILE,
//! returns before the call is validated or executed), so errors in compiled commands are raised
//! when the list runs, as §5.4 requires; only NewList and EndList check anything at compile time.
//! The commands §5.4 says are "executed immediately" (GenLists, DeleteLists, NewList, EndList,
//! client state, pixel store, Flush, Finish; queries and ReadPixels are not recorded at all) are
//! the ones [`Call::executes_immediately`] lists: recorded, never compiled.
//!
//! Design decision: names are not allocated one by one. A `GenLists` range is kept as one run of
//! reserved names, and only lists actually defined by EndList hold a vector, so memory is bounded
//! by what the caller compiles, whatever range it asks for. As in Mesa, `GenLists` hands out the
//! names after the largest one ever used while they fit, and otherwise the first free gap.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::Context;
use crate::call::Call;
use crate::gl;

/// `MAX_LIST_NESTING` (GL 2.1 table 6.35: at least 64): how deep CallList may nest at run time.
pub const MAX_LIST_NESTING: u32 = 64;

/// The defined lists by name.
pub(crate) type ListMap = BTreeMap<u32, Arc<List>>;

/// The display-list namespace and the list being compiled.
#[derive(Debug, Default)]
pub(crate) struct DisplayLists {
    /// Defined lists (by EndList); an empty one is a used name with nothing in it.
    defined: BTreeMap<u32, Arc<List>>,
    /// Names reserved by GenLists as empty lists: `(first, count)` runs, disjoint.
    reserved: Vec<(u32, u32)>,
    /// The largest name ever used (GenLists hands out names above it while they fit).
    max_used: u32,
    /// The list between NewList and EndList, if any.
    pub(crate) compiling: Option<Compiling>,
    /// How many CallList levels are executing now (0: the caller's own calls).
    pub(crate) depth: u32,
    /// Lists run on the baseline route even where the CPU has AVX2 (`Context::replay_by`
    /// with `Route::Baseline` sets it, so that the routes test compares the lists' loop too).
    pub(crate) baseline: bool,
    /// Emptied call buffers of the lists `Context::reset` dropped, for the lists compiled
    /// next (a frame that compiles its lists again after each reset, as display-list does,
    /// then grows no buffer from empty); at most [`SPARE_BUFFERS`].
    spare: Vec<Vec<Call>>,
}

/// Call buffers kept across `Context::reset` (see `DisplayLists::spare`).
const SPARE_BUFFERS: usize = 256;

/// A list being defined.
#[derive(Debug)]
pub(crate) struct Compiling {
    name: u32,
    /// COMPILE or COMPILE_AND_EXECUTE.
    pub(crate) mode: u32,
    pub(crate) calls: Vec<Call>,
    /// The calls a vertex-array draw compiled into, as `(first, end)` index ranges of `calls`.
    pub(crate) draws: Vec<(usize, usize)>,
}

/// A defined display list.
#[derive(Debug, Default)]
pub(crate) struct List {
    calls: Vec<Call>,
    /// The ranges of `calls` a DrawArrays or DrawElements compiled into: the current
    /// attributes (and the materials COLOR_MATERIAL tracks) they set are put back after them,
    /// as after the draw itself (Mesa compiles such a draw as a vertex list that does not
    /// update the current values).
    draws: Vec<(usize, usize)>,
}

impl DisplayLists {
    /// A new namespace (no list, no name in use) that keeps the call buffers of this one's
    /// lists that nothing else holds (not shared with a share group or a running CallList),
    /// emptied: what `Context::reset` puts in place.
    pub(crate) fn emptied(self) -> DisplayLists {
        let mut spare = self.spare;
        // Pushed in descending name order, so that lists compiled in ascending order get
        // back the buffers they had.
        let lists = self
            .defined
            .into_values()
            .rev()
            .filter_map(|l| Arc::try_unwrap(l).ok());
        for mut calls in self
            .compiling
            .map(|c| c.calls)
            .into_iter()
            .chain(lists.map(|l| l.calls))
        {
            if spare.len() >= SPARE_BUFFERS {
                break;
            }
            calls.clear();
            spare.push(calls);
        }
        DisplayLists {
            spare,
            ..Default::default()
        }
    }

    /// The shared part (the lists and the names in use), for a share group (context/share.rs).
    pub(crate) fn store(&self) -> (&ListMap, &[(u32, u32)], u32) {
        (&self.defined, &self.reserved, self.max_used)
    }

    /// Replaces the shared part with a share group's.
    pub(crate) fn set_store(&mut self, defined: &ListMap, reserved: &[(u32, u32)], max_used: u32) {
        self.defined = defined.clone();
        self.reserved = reserved.to_vec();
        self.max_used = max_used;
    }

    /// Whether `name` is a display list (defined, or reserved by GenLists).
    fn is_list(&self, name: u32) -> bool {
        name != 0
            && (self.defined.contains_key(&name)
                || self
                    .reserved
                    .iter()
                    .any(|&(first, n)| name >= first && name - first < n))
    }

    /// The first name of `range` consecutive unused names, if there are that many.
    fn free_block(&self, range: u32) -> Option<u32> {
        if let Some(first) = self.max_used.checked_add(1) {
            if first.checked_add(range - 1).is_some() {
                return Some(first);
            }
        }
        // Every name up to u32::MAX has been used once: look for a gap between used names.
        let mut used: Vec<(u32, u32)> = self.reserved.clone();
        used.extend(self.defined.keys().map(|&k| (k, 1)));
        used.sort_unstable();
        let (mut next, range) = (1u64, u64::from(range));
        for (first, n) in used {
            let first = u64::from(first);
            if first >= next + range {
                return u32::try_from(next).ok();
            }
            next = next.max(first + u64::from(n));
        }
        // Names run up to u32::MAX inclusive.
        (next + range <= 1 << 32).then(|| u32::try_from(next).ok())?
    }

    /// Deletes every list named `first .. first + range` (names past u32::MAX do not exist).
    fn delete(&mut self, first: u32, range: u32) {
        let last = first.saturating_add(range - 1);
        let doomed: Vec<u32> = self.defined.range(first..=last).map(|(&k, _)| k).collect();
        for k in doomed {
            self.defined.remove(&k);
        }
        let mut kept = Vec::with_capacity(self.reserved.len() + 1);
        for &(a, n) in &self.reserved {
            let b = a + (n - 1);
            if b < first || a > last {
                kept.push((a, n));
                continue;
            }
            if a < first {
                kept.push((a, first - a));
            }
            if b > last {
                kept.push((last + 1, b - last));
            }
        }
        self.reserved = kept;
    }

    /// The calls of list `name`, or `None` if it has none (undefined names are ignored by
    /// CallList, GL 2.1 §5.4).
    fn calls(&self, name: u32) -> Option<Arc<List>> {
        self.defined.get(&name).cloned()
    }
}

/// The byte size of one name in a CallLists array of `ty`, or `None` if `ty` is not a type
/// CallLists accepts (GL 2.1 table 5.4).
pub(crate) fn name_size(ty: u32) -> Option<usize> {
    Some(match ty {
        gl::BYTE | gl::UNSIGNED_BYTE => 1,
        gl::SHORT | gl::UNSIGNED_SHORT | gl::GL_2_BYTES => 2,
        gl::GL_3_BYTES => 3,
        gl::INT | gl::UNSIGNED_INT | gl::FLOAT | gl::GL_4_BYTES => 4,
        _ => return None,
    })
}

/// Offset `i` of a CallLists array (GL 2.1 table 5.4): the multi-byte forms are big-endian byte
/// sequences; SHORT, INT and FLOAT are read in the machine's own byte order, as a C array would be.
pub(crate) fn name_offset(ty: u32, b: &[u8]) -> u32 {
    let get = |i: usize| b.get(i).copied().unwrap_or(0);
    let pair = [get(0), get(1)];
    let quad = [get(0), get(1), get(2), get(3)];
    match ty {
        gl::BYTE => get(0) as i8 as u32,
        gl::UNSIGNED_BYTE => u32::from(get(0)),
        gl::SHORT => i16::from_ne_bytes(pair) as u32,
        gl::UNSIGNED_SHORT => u32::from(u16::from_ne_bytes(pair)),
        gl::INT => i32::from_ne_bytes(quad) as u32,
        gl::UNSIGNED_INT => u32::from_ne_bytes(quad),
        // A float name converts as C's (GLuint)(GLint)f: truncation (saturating here).
        gl::FLOAT => f32::from_ne_bytes(quad) as i32 as u32,
        gl::GL_2_BYTES => u32::from(u16::from_be_bytes(pair)),
        gl::GL_3_BYTES => (u32::from(get(0)) << 16) | (u32::from(get(1)) << 8) | u32::from(get(2)),
        _ => u32::from_be_bytes(quad),
    }
}

impl Context {
    /// Appends `call` to the recording and to the list being compiled, as the `record!` macro
    /// does; returns true when the command must not be executed now (COMPILE mode).
    pub(crate) fn capture(&mut self, call: Call) -> bool {
        let Some(list) = self.lists.compiling.as_mut() else {
            // Recorded only (no list being defined): what `capture_any` does then.
            if let Some(rec) = self.recording.as_mut() {
                rec.push(call);
            }
            return false;
        };
        // The usual call while a list is compiled and nothing is recorded (a mesh's vertices,
        // normals, Begin, End): stored as it is, which is what `capture_any` does with it,
        // without its other cases' work and registers.
        if self.recording.is_none()
            && !call.executes_immediately()
            && !proxy_image(&call)
            && !crate::pixels::unpacks_at_compile(&call)
            && !super::arrays::compiles_draw(&call)
        {
            let compile = list.mode == gl::COMPILE;
            if list.calls.len() < list.calls.capacity() || list.calls.try_reserve(1).is_ok() {
                list.calls.push(call);
            } else {
                self.error(gl::OUT_OF_MEMORY);
            }
            return compile;
        }
        self.capture_any(call)
    }

    /// `capture` for every call: recorded, and compiled into the list being defined as §5.4
    /// says (a vertex-array draw into the data it reads now, pixels unpacked now).
    #[inline(never)]
    fn capture_any(&mut self, call: Call) -> bool {
        match self.lists.compiling.as_ref() {
            Some(_) if !call.executes_immediately() && !proxy_image(&call) => {
                if let Some(rec) = self.recording.as_mut() {
                    rec.push(call.clone());
                }
                // A vertex-array draw compiles into the data it reads now, and DrawPixels and
                // Bitmap into their groups unpacked now (GL 2.1 §5.4).
                let compiled = match self.compile_pixels(&call) {
                    Some(c) => Ok(Some(vec![c])),
                    None => self.compile_draw(&call),
                };
                let Some(list) = self.lists.compiling.as_mut() else {
                    return false;
                };
                let mode = list.mode;
                // The list grows by what the call holds; growth that cannot be allocated is
                // OUT_OF_MEMORY (raised now, the call left out of the list: the crate's rule is
                // that an OUT_OF_MEMORY command changes nothing) instead of an abort.
                let draw = !matches!(call, Call::ArrayElement(_));
                let stored = match compiled {
                    Ok(Some(calls)) => list
                        .calls
                        .try_reserve(calls.len())
                        .and_then(|()| list.draws.try_reserve(usize::from(draw)))
                        .map(|()| {
                            let first = list.calls.len();
                            list.calls.extend(calls);
                            if draw && list.calls.len() > first {
                                list.draws.push((first, list.calls.len()));
                            }
                        }),
                    Ok(None) => list.calls.try_reserve(1).map(|()| list.calls.push(call)),
                    Err(code) => {
                        self.error(code);
                        return mode == gl::COMPILE;
                    }
                };
                if stored.is_err() {
                    self.error(gl::OUT_OF_MEMORY);
                }
                mode == gl::COMPILE
            }
            _ => {
                if let Some(rec) = self.recording.as_mut() {
                    rec.push(call);
                }
                false
            }
        }
    }

    /// `glGenLists`: reserves `range` consecutive unused names as empty lists and returns the
    /// first; 0 (and INVALID_VALUE) for a negative range, 0 for 0 or when no such block is free.
    pub fn gen_lists(&mut self, range: i32) -> u32 {
        // Executed immediately, never compiled (GL 2.1 §5.4): recorded only.
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::GenLists(range));
        }
        self.objects_txn(super::share::LISTS, &[], |ctx| ctx.gen_lists_now(range))
    }

    fn gen_lists_now(&mut self, range: i32) -> u32 {
        if !self.outside_begin_end() {
            return 0;
        }
        if range < 0 {
            self.error(gl::INVALID_VALUE);
            return 0;
        }
        let Ok(range @ 1..) = u32::try_from(range) else {
            return 0;
        };
        let Some(first) = self.lists.free_block(range) else {
            self.error(gl::OUT_OF_MEMORY);
            return 0;
        };
        self.lists.reserved.push((first, range));
        self.lists.max_used = self.lists.max_used.max(first + (range - 1));
        first
    }

    /// `glNewList`: starts defining list `list`; `mode` COMPILE stores the following commands,
    /// COMPILE_AND_EXECUTE also executes them. INVALID_VALUE for list 0, INVALID_ENUM for another
    /// mode, INVALID_OPERATION while a list is being defined (or inside Begin/End).
    pub fn new_list(&mut self, list: u32, mode: u32) {
        record!(self, Call::NewList(list, mode));
        if !self.outside_begin_end() {
            return;
        }
        if list == 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if mode != gl::COMPILE && mode != gl::COMPILE_AND_EXECUTE {
            return self.error(gl::INVALID_ENUM);
        }
        if self.lists.compiling.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        self.lists.compiling = Some(Compiling {
            name: list,
            mode,
            calls: self.lists.spare.pop().unwrap_or_default(),
            draws: Vec::new(),
        });
        self.sync_capturing();
    }

    /// `glEndList`: the list being defined replaces any earlier one of its name.
    /// INVALID_OPERATION when no list is being defined (or inside Begin/End).
    pub fn end_list(&mut self) {
        record!(self, Call::EndList);
        self.objects_txn(super::share::LISTS, &[], Self::end_list_now);
    }

    fn end_list_now(&mut self) {
        if !self.outside_begin_end() {
            return;
        }
        let Some(list) = self.lists.compiling.take() else {
            return self.error(gl::INVALID_OPERATION);
        };
        self.sync_capturing();
        let (mut calls, mut draws) = (list.calls, list.draws);
        // A buffer grown by doubling is kept as it is (it is handed on at the next reset); one
        // much larger than its list (a spare buffer of a larger list) gives its slack back.
        if calls.capacity() > 2 * calls.len().max(16) {
            calls.shrink_to_fit();
        }
        draws.shrink_to_fit();
        self.lists.max_used = self.lists.max_used.max(list.name);
        self.lists
            .defined
            .insert(list.name, Arc::new(List { calls, draws }));
    }

    /// `glCallList`: executes list `list` (nothing if it is not defined, or if the nesting
    /// depth MAX_LIST_NESTING is reached). Allowed between Begin and End (GL 2.1 §2.6.3).
    pub fn call_list(&mut self, list: u32) {
        record!(self, Call::CallList(list));
        self.pull_objects();
        self.run_list(list);
    }

    /// `glCallLists`: executes the lists `ListBase + lists[i]` for i < n, the names read from
    /// `lists` as `ty` (BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, INT, UNSIGNED_INT, FLOAT,
    /// 2_BYTES, 3_BYTES or 4_BYTES; the bytes as they lie in memory). INVALID_ENUM for another
    /// type (checked first, as Mesa does), INVALID_VALUE for a negative `n` or a `lists` shorter
    /// than `n` names.
    pub fn call_lists(&mut self, n: i32, ty: u32, lists: &[u8]) {
        let needed = name_size(ty).and_then(|s| usize::try_from(n).ok()?.checked_mul(s));
        let kept = lists.get(..needed.unwrap_or(0)).unwrap_or(lists);
        record!(self, Call::CallLists(n, ty, kept.to_vec()));
        // The type first, then n: GL 2.1 leaves the order open; Mesa checks the type first.
        let Some(size) = name_size(ty) else {
            return self.error(gl::INVALID_ENUM);
        };
        if n < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if needed.is_none() || needed.is_some_and(|needed| lists.len() < needed) {
            return self.error(gl::INVALID_VALUE);
        }
        self.pull_objects();
        for name in lists.chunks_exact(size).take(n as usize) {
            let list = self.state.list_base.wrapping_add(name_offset(ty, name));
            self.run_list(list);
        }
    }

    /// Executes list `name` one nesting level down (GL 2.1 §5.4), recording nothing of it.
    /// The loop, with the hot calls `execute_in_list` inlines (the vertex path and its
    /// batching), is compiled for the baseline or with AVX2 by `Route::best`, as
    /// `Context::replay` is: the same code, so the same calls and pixels
    /// (`both_replay_routes_draw_the_same_image`).
    fn run_list(&mut self, name: u32) {
        #[cfg(target_arch = "x86_64")]
        if !self.lists.baseline
            && crate::cpu::vertex::Route::best() == crate::cpu::vertex::Route::Avx2
        {
            // SAFETY: `Route::Avx2` is chosen only where the CPU has AVX2.
            unsafe { self.run_list_avx2(name) };
            return;
        }
        self.run_list_body(name);
    }

    /// [`Context::run_list_body`] compiled with AVX2.
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_list_avx2(&mut self, name: u32) {
        self.run_list_body(name);
    }

    /// [`Context::execute`] with what a display list of GLUT meshes holds inlined too (kept
    /// out of `execute` itself: more arms there made the replay loop's dispatch dearer).
    #[inline(always)]
    fn execute_in_list(&mut self, call: &Call) {
        match *call {
            Call::Vertex3fv(ref v) => self.vertex3fv(v),
            Call::Normal3fv(ref v) => self.normal3fv(v),
            Call::TexCoord2fv(ref v) => self.tex_coord2fv(v),
            _ => self.execute(call),
        }
    }

    #[inline(always)]
    fn run_list_body(&mut self, name: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(list) = self.lists.calls(name) else {
            return;
        };
        self.lists.depth += 1;
        let mut draws = list.draws.iter().peekable();
        let mut i = 0;
        while let Some(call) = list.calls.get(i) {
            let Some(&&(first, end)) = draws.peek().filter(|&&&(first, _)| first == i) else {
                self.execute_in_list(call);
                i += 1;
                continue;
            };
            draws.next();
            // A compiled draw run between Begin and End is INVALID_OPERATION as a whole: none
            // of its vertices joins the primitive under way (Mesa's vertex-list playback).
            if self.begin_mode.is_some() {
                self.error(gl::INVALID_OPERATION);
            } else {
                let kept = (self.state.current, self.state.materials);
                for call in list.calls.get(first..end).unwrap_or(&[]) {
                    self.execute_in_list(call);
                }
                (self.state.current, self.state.materials) = kept;
            }
            i = end;
        }
        self.lists.depth -= 1;
    }

    /// `glListBase`: the offset CallLists adds to every name.
    pub fn list_base(&mut self, base: u32) {
        record!(self, Call::ListBase(base));
        if !self.outside_begin_end() {
            return;
        }
        self.state.list_base = base;
    }

    /// `glDeleteLists`: deletes lists `list .. list + range`; unused names are ignored.
    /// INVALID_VALUE for a negative range.
    pub fn delete_lists(&mut self, list: u32, range: i32) {
        record!(self, Call::DeleteLists(list, range));
        self.objects_txn(super::share::LISTS, &[], |ctx| {
            ctx.delete_lists_now(list, range)
        });
    }

    fn delete_lists_now(&mut self, list: u32, range: i32) {
        if !self.outside_begin_end() {
            return;
        }
        if range < 0 {
            return self.error(gl::INVALID_VALUE);
        }
        if let Ok(range @ 1..) = u32::try_from(range) {
            self.lists.delete(list, range);
        }
    }

    /// `glIsList`: whether `list` names a display list (defined, or reserved by GenLists).
    /// Not recorded (a query). Inside Begin/End: INVALID_OPERATION and false.
    pub fn is_list(&mut self, list: u32) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.pull_objects();
        self.lists.is_list(list)
    }

    /// LIST_INDEX and LIST_MODE (GL 2.1 table 6.36): the list being defined and its mode, or 0.
    pub(crate) fn list_index_and_mode(&self) -> (u32, u32) {
        self.lists
            .compiling
            .as_ref()
            .map_or((0, 0), |c| (c.name, c.mode))
    }

    /// The calls of display list `name` as compiled (None if it is not defined). Not a GL entry
    /// point: for tests and tools.
    pub fn list_calls(&self, name: u32) -> Option<&[Call]> {
        self.lists.defined.get(&name).map(|c| c.calls.as_slice())
    }
}

/// Is `call` a TexImage with its own proxy target (TexImage1D of PROXY_TEXTURE_1D, TexImage2D
/// of PROXY_TEXTURE_2D or PROXY_TEXTURE_CUBE_MAP, TexImage3D of PROXY_TEXTURE_3D, and the
/// CompressedTexImage commands of their 1D, 2D, 3D proxy)? GL 2.1 §5.4:
/// those are executed immediately, not compiled, whatever the list's mode; another command's
/// proxy (an INVALID_ENUM) is compiled like any error.
pub(crate) fn proxy_image(call: &Call) -> bool {
    match call {
        Call::TexImage1D(a) => a.0 == gl::PROXY_TEXTURE_1D,
        Call::TexImage2D(a) => matches!(a.0, gl::PROXY_TEXTURE_2D | gl::PROXY_TEXTURE_CUBE_MAP),
        Call::TexImage3D(a) => a.0 == gl::PROXY_TEXTURE_3D,
        // CompressedTexImage as Mesa's `dlist.c` (`save_CompressedTexImage1D/2D/3D`): only the
        // command's own 1D, 2D or 3D proxy (not PROXY_TEXTURE_CUBE_MAP) runs immediately.
        Call::CompressedTexImage1D(a) => a.0 == gl::PROXY_TEXTURE_1D,
        Call::CompressedTexImage2D(a) => a.0 == gl::PROXY_TEXTURE_2D,
        Call::CompressedTexImage3D(a) => a.0 == gl::PROXY_TEXTURE_3D,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `capture` stores a call as it is in one inline test when nothing is recorded, and goes
    /// through `capture_any` (which compiles vertex-array draws, pixel rectangles, bitmaps and
    /// the stipple) when a recording is on: both give the same list, call for call, for a mix
    /// of calls stored as they are and calls compiled into something else.
    #[test]
    fn lists_compile_alike_recorded_or_not() {
        let compile = |record: bool| {
            let mut ctx = Context::new(16, 16).expect("context");
            let pos = [0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0];
            ctx.vertex_pointer(2, gl::FLOAT, 0, &pos);
            ctx.enable_client_state(gl::VERTEX_ARRAY);
            ctx.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
            if record {
                ctx.start_recording();
            }
            ctx.new_list(1, gl::COMPILE);
            ctx.color3f(0.5, 0.25, 1.0);
            ctx.begin(gl::TRIANGLES);
            ctx.normal3fv(&[0.0, 0.0, 1.0]);
            ctx.vertex3fv(&[0.0, 0.0, 0.0]);
            ctx.array_element(1);
            ctx.vertex2f(1.0, 1.0);
            ctx.end();
            ctx.draw_arrays(gl::TRIANGLES, 0, 3);
            ctx.draw_pixels(2, 1, gl::RGB, gl::UNSIGNED_BYTE, &[1, 2, 3, 4, 5, 6]);
            ctx.bitmap(3, 1, 0.0, 0.0, 3.0, 0.0, Some(&[0xa0]));
            ctx.polygon_stipple(&[0x55; 128]);
            ctx.tex_image_2d(
                gl::PROXY_TEXTURE_2D,
                0,
                gl::RGBA as i32,
                1,
                1,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                None,
            );
            ctx.pixel_storei(gl::UNPACK_ALIGNMENT, 4);
            ctx.end_list();
            assert_eq!(ctx.get_error(), gl::NO_ERROR);
            ctx.list_calls(1).expect("list 1").to_vec()
        };
        let (plain, recorded) = (compile(false), compile(true));
        assert_eq!(plain, recorded);
        // The draws were compiled (Begin, the elements, End), not stored as they are.
        assert!(!plain
            .iter()
            .any(|c| matches!(c, Call::DrawArrays(..) | Call::ArrayElement(_))));
        assert!(plain.iter().any(|c| matches!(c, Call::DrawPixels(..))));
    }

    /// `reset` keeps the call buffers of the lists it drops (and of one left open), emptied;
    /// a list compiled after it into such a buffer holds exactly its own calls.
    #[test]
    fn lists_compiled_after_reset_hold_only_their_calls() {
        let mut ctx = Context::new(16, 16).expect("context");
        for (name, n) in [(1, 50), (2, 10)] {
            ctx.new_list(name, gl::COMPILE);
            for i in 0..n {
                ctx.color3f(i as f32, 0.0, 0.0);
            }
            ctx.end_list();
        }
        ctx.new_list(3, gl::COMPILE);
        ctx.color3f(0.0, 1.0, 0.0);
        ctx.reset();
        assert_eq!(ctx.lists.spare.len(), 3);
        assert!(ctx.lists.spare.iter().all(Vec::is_empty));
        assert!(ctx.list_calls(1).is_none());
        // List 1 gets back its 50-call buffer (the last pushed) and stores 3 calls in it.
        ctx.new_list(1, gl::COMPILE);
        for i in 0..3 {
            ctx.color3f(0.0, 0.0, i as f32);
        }
        ctx.end_list();
        assert_eq!(ctx.get_error(), gl::NO_ERROR);
        let want: Vec<Call> = (0..3).map(|i| Call::Color3f(0.0, 0.0, i as f32)).collect();
        assert_eq!(ctx.list_calls(1).expect("list 1"), &want[..]);
        assert_eq!(ctx.lists.spare.len(), 2);
        ctx.call_list(1);
        assert_eq!(
            ctx.state().current.color,
            glam::Vec4::new(0.0, 0.0, 2.0, 1.0)
        );
    }

    #[test]
    fn offsets_follow_table_5_4() {
        assert_eq!(name_offset(gl::BYTE, &[0xff]), u32::MAX);
        assert_eq!(name_offset(gl::UNSIGNED_BYTE, &[0xff]), 255);
        assert_eq!(name_offset(gl::GL_2_BYTES, &[1, 2]), 258);
        assert_eq!(name_offset(gl::GL_3_BYTES, &[1, 2, 3]), 65536 + 512 + 3);
        assert_eq!(name_offset(gl::GL_4_BYTES, &[0, 0, 1, 0]), 256);
        assert_eq!(
            name_offset(gl::SHORT, &(-2i16).to_ne_bytes()),
            (-2i32) as u32
        );
        assert_eq!(
            name_offset(gl::UNSIGNED_SHORT, &65535u16.to_ne_bytes()),
            65535
        );
        assert_eq!(name_offset(gl::INT, &(-7i32).to_ne_bytes()), (-7i32) as u32);
        assert_eq!(name_offset(gl::UNSIGNED_INT, &9u32.to_ne_bytes()), 9);
        assert_eq!(name_offset(gl::FLOAT, &3.75f32.to_ne_bytes()), 3);
    }

    #[test]
    fn reserved_runs_split_on_delete() {
        let mut l = DisplayLists {
            reserved: vec![(10, 10)],
            max_used: 19,
            ..Default::default()
        };
        l.delete(12, 3);
        assert_eq!(l.reserved, vec![(10, 2), (15, 5)]);
        assert!(l.is_list(11) && !l.is_list(12) && !l.is_list(14) && l.is_list(15));
        assert!(l.is_list(19) && !l.is_list(20));
        // After the top name was used, a block is found in a gap instead.
        l.max_used = u32::MAX;
        assert_eq!(l.free_block(3), Some(1));
        assert_eq!(l.free_block(9), Some(1));
        assert_eq!(l.free_block(10), Some(20));
        l.delete(0, i32::MAX as u32);
        assert_eq!(l.free_block(u32::MAX), Some(1));
    }
}
