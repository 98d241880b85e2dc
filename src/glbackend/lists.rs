//! Display lists and attribute stacks on the driver (GL 2.1 §5.4, §6.1.14): NewList, EndList,
//! CallList and CallLists go to the driver, so it builds and runs its own lists.
//!
//! The backend's own bookkeeping (the open Begin/End pair, the PHONG_WIN emulation, its own
//! short-slice errors) follows the calls it sees, and a list run inside the driver hides its
//! calls. So the backend keeps a mirror of every list, the same `Vec<Call>` the front end keeps:
//! - while the driver compiles under COMPILE, Begin/End/ShadeModel change nothing of ours;
//! - after the driver runs a list, the mirror is walked to update the Begin/End phase and
//!   LIST_BASE as the driver's own run did;
//! - a list the driver could not hold faithfully (one compiled with PHONG_WIN in play, or with a
//!   call the backend answers itself: a short slice, PHONG_HINT_WIN) and every list run while
//!   PHONG_WIN is emulated are instead expanded: the mirror's calls are replayed one by one, so
//!   the emulation sees each Begin and every error is raised when the list runs, as in GL.
//!
//! Design decision: expansion is all or nothing per session — once any list needs it, every
//! CallList is expanded — which keeps the rule simple and never wrong, only slower.

use std::collections::HashMap;
use std::sync::Arc;

use super::replay::phong_neutral;
use super::GlBackend;
use crate::context::{name_offset as offset, name_size, proxy_image};
use crate::gl;
use crate::Call;

/// The nesting limit the front end uses (`MAX_LIST_NESTING`, GL 2.1 table 6.35).
const MAX_NESTING: u32 = crate::context::MAX_LIST_NESTING;
/// The attribute stack depth of the front end and of Mesa.
const MAX_ATTRIB: usize = crate::context::MAX_ATTRIB_STACK_DEPTH;

/// The backend's own state one PushAttrib saved: the PHONG_WIN flag if LIGHTING_BIT was
/// pushed, DRAW_BUFFER with COLOR_BUFFER_BIT, READ_BUFFER with PIXEL_MODE_BIT (the driver
/// saves and restores the attachments standing for them itself).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Pushed {
    phong: Option<bool>,
    draw_buffer: Option<u32>,
    read_buffer: Option<u32>,
}

/// The backend's mirror of the driver's display lists.
#[derive(Debug, Default)]
pub(crate) struct ListMirror {
    lists: HashMap<u32, Arc<Vec<Call>>>,
    /// The list being defined: name, mode, calls.
    compiling: Option<(u32, u32, Vec<Call>)>,
    /// Some list must be expanded rather than run by the driver (see the module docs).
    expand: bool,
    /// CallList nesting while expanding or walking.
    depth: u32,
    /// The driver's LIST_BASE.
    base: u32,
    /// For each PushAttrib the driver accepted: what of the backend's own state its groups
    /// hold (the PHONG_WIN flag, DRAW_BUFFER, READ_BUFFER).
    phong_stack: Vec<Pushed>,
}

impl GlBackend {
    /// Called first for every call: copies it into the mirror of the list being defined.
    pub(crate) fn mirror_call(&mut self, call: &Call) {
        // A TexImage or CompressedTexImage of its own proxy target is executed, not compiled
        // (GL 2.1 §5.4), by the driver too.
        if self.lists.depth > 0 || call.executes_immediately() || proxy_image(call) {
            return;
        }
        if self.lists.compiling.is_some() {
            // DrawPixels and Bitmap are kept with their groups unpacked now, under the driver's
            // unpack modes, as the driver's own list holds them (GL 2.1 §5.4); `expand` reads
            // them back under the tight modes.
            let stored = match call {
                Call::DrawPixels(..) | Call::Bitmap(..) => {
                    crate::pixels::compile_unpacked(&self.driver_unpack(), call)
                }
                _ => None,
            };
            let stored = stored.unwrap_or_else(|| call.clone());
            if let Some((_, _, calls)) = self.lists.compiling.as_mut() {
                calls.push(stored);
            }
            if self.phong || matches!(call, Call::ShadeModel(gl::PHONG_WIN)) {
                self.lists.expand = true;
            }
        }
    }

    /// Whether a list is being compiled and not executed (NewList COMPILE): the driver stores
    /// the calls, so nothing of the backend's tracking may change.
    pub(crate) fn compile_only(&self) -> bool {
        self.lists.depth == 0 && matches!(self.lists.compiling, Some((_, gl::COMPILE, _)))
    }

    /// A call the backend answers itself (a short slice, PHONG_HINT_WIN) is in the list being
    /// defined: the driver's copy lacks it, so the list must be expanded when it runs.
    pub(crate) fn list_needs_expansion(&mut self) {
        if self.lists.depth == 0 && self.lists.compiling.is_some() {
            self.lists.expand = true;
        }
    }

    /// `NewList`: validated as the front end does, so the mirror opens exactly when the
    /// driver's list does.
    pub(crate) fn new_list(&mut self, list: u32, mode: u32) {
        // SAFETY: the context is current (see `execute`); no pointers.
        unsafe { self.raw.NewList(list, mode) };
        let ok = !self.inside_begin_end
            && list != 0
            && (mode == gl::COMPILE || mode == gl::COMPILE_AND_EXECUTE)
            && self.lists.compiling.is_none();
        if ok {
            self.lists.compiling = Some((list, mode, Vec::new()));
        }
    }

    /// `EndList`.
    pub(crate) fn end_list(&mut self) {
        // SAFETY: as in `new_list`.
        unsafe { self.raw.EndList() };
        if self.inside_begin_end {
            return;
        }
        if let Some((name, _, calls)) = self.lists.compiling.take() {
            self.lists.lists.insert(name, Arc::new(calls));
        }
    }

    /// `DeleteLists`.
    pub(crate) fn delete_lists(&mut self, list: u32, range: i32) {
        // SAFETY: as in `new_list`.
        unsafe { self.raw.DeleteLists(list, range) };
        if self.inside_begin_end || range <= 0 {
            return;
        }
        let last = list.saturating_add(range as u32 - 1);
        self.lists.lists.retain(|&k, _| k < list || k > last);
    }

    /// `CallList`.
    pub(crate) fn call_list(&mut self, list: u32) {
        if self.compile_only() {
            // SAFETY: as in `new_list`.
            return unsafe { self.raw.CallList(list) };
        }
        if self.must_expand() {
            return self.expand(list);
        }
        // SAFETY: as in `new_list`.
        unsafe { self.raw.CallList(list) };
        self.walk(list);
    }

    /// `CallLists` with the names' bytes as recorded.
    pub(crate) fn call_lists(&mut self, n: i32, ty: u32, bytes: &[u8]) {
        let size = name_size(ty).unwrap_or(0);
        let short = size > 0 && n > 0 && bytes.len() < n as usize * size;
        if short {
            // The front end's INVALID_VALUE for a short array: never let the driver read past it.
            if self.compile_only() {
                return self.list_needs_expansion();
            }
            self.list_needs_expansion();
            return self.raise(gl::INVALID_VALUE);
        }
        let ptr = if bytes.is_empty() {
            std::ptr::null()
        } else {
            bytes.as_ptr().cast()
        };
        if self.compile_only() {
            // SAFETY: the driver reads n names of `size` bytes; `bytes` holds them all.
            return unsafe { self.raw.CallLists(n, ty, ptr) };
        }
        if size == 0 || n <= 0 {
            // SAFETY: with a bad type or n <= 0 the driver reads nothing.
            return unsafe { self.raw.CallLists(n, ty, ptr) };
        }
        let names: Vec<u32> = bytes
            .chunks_exact(size)
            .take(n as usize)
            .map(|b| offset(ty, b))
            .collect();
        if self.must_expand() {
            for name in names {
                self.expand(self.lists.base.wrapping_add(name));
            }
            return;
        }
        // SAFETY: as above, `bytes` holds the n names the driver reads.
        unsafe { self.raw.CallLists(n, ty, ptr) };
        for name in names {
            self.walk(self.lists.base.wrapping_add(name));
        }
    }

    /// `ListBase`.
    pub(crate) fn list_base(&mut self, base: u32) {
        // SAFETY: as in `new_list`.
        unsafe { self.raw.ListBase(base) };
        if !self.compile_only() && !self.inside_begin_end {
            self.lists.base = base;
        }
    }

    /// `PushAttrib`: the PHONG_WIN flag is part of the lighting group's shade model.
    pub(crate) fn push_attrib(&mut self, mask: u32) {
        // SAFETY: as in `new_list`.
        unsafe { self.raw.PushAttrib(mask) };
        if !self.compile_only() {
            self.track_push(mask);
        }
    }

    /// `PopAttrib`.
    pub(crate) fn pop_attrib(&mut self) {
        // SAFETY: as in `new_list`.
        unsafe { self.raw.PopAttrib() };
        if !self.compile_only() {
            self.track_pop();
        }
    }

    fn track_push(&mut self, mask: u32) {
        if !self.inside_begin_end && self.lists.phong_stack.len() < MAX_ATTRIB {
            let saved = Pushed {
                phong: (mask & gl::LIGHTING_BIT != 0).then_some(self.phong),
                draw_buffer: (mask & gl::COLOR_BUFFER_BIT != 0).then_some(self.draw_buffer),
                read_buffer: (mask & gl::PIXEL_MODE_BIT != 0).then_some(self.read_buffer),
            };
            self.lists.phong_stack.push(saved);
        }
    }

    fn track_pop(&mut self) {
        if self.inside_begin_end {
            return;
        }
        let Some(pushed) = self.lists.phong_stack.pop() else {
            return;
        };
        if let Some(b) = pushed.draw_buffer {
            self.draw_buffer = b;
        }
        if let Some(b) = pushed.read_buffer {
            self.read_buffer = b;
        }
        if let Some(phong) = pushed.phong {
            if phong != self.phong {
                // The driver restored SMOOTH (what it was given for PHONG_WIN) or FLAT/SMOOTH.
                self.phong = phong;
                self.phong_dirty = true;
                if !phong {
                    // SAFETY: context current.
                    unsafe { glow::HasContext::use_program(&self.glow, None) };
                }
            }
        }
    }

    fn must_expand(&self) -> bool {
        self.phong
            || self.lists.expand
            || self.lists.phong_stack.iter().any(|p| p.phong == Some(true))
    }

    /// Replays list `name` call by call (the driver never sees the CallList).
    fn expand(&mut self, name: u32) {
        if self.lists.depth >= MAX_NESTING {
            return;
        }
        let Some(calls) = self.lists.lists.get(&name).cloned() else {
            return;
        };
        if self.lists.depth == 0 && self.lists.compiling.is_some() {
            // The driver is compiling the expanded calls in place of the CallList: its copy of
            // the list being defined is no longer the mirror's.
            self.lists.expand = true;
        }
        self.lists.depth += 1;
        for call in calls.iter() {
            if matches!(call, Call::DrawPixels(..) | Call::Bitmap(..)) {
                // The mirror's copy is tightly packed (see `mirror_call`).
                self.with_tight_unpack(|b| b.execute(call));
            } else {
                self.execute(call);
            }
        }
        self.lists.depth -= 1;
    }

    /// After the driver ran list `name`: the effect of its calls on the backend's tracking.
    fn walk(&mut self, name: u32) {
        if self.lists.depth >= MAX_NESTING {
            return;
        }
        let Some(calls) = self.lists.lists.get(&name).cloned() else {
            return;
        };
        self.lists.depth += 1;
        for call in calls.iter() {
            if !phong_neutral(call) {
                self.phong_dirty = true;
            }
            match *call {
                Call::Begin(mode) if mode <= gl::POLYGON => self.inside_begin_end = true,
                Call::End => self.inside_begin_end = false,
                Call::ListBase(b) if !self.inside_begin_end => self.lists.base = b,
                Call::PushAttrib(mask) => self.track_push(mask),
                Call::PopAttrib => self.track_pop(),
                Call::CallList(n) => self.walk(n),
                Call::CallLists(n, ty, ref bytes) => {
                    let size = name_size(ty).unwrap_or(1);
                    let count = usize::try_from(n).unwrap_or(0);
                    for b in bytes.chunks_exact(size).take(count) {
                        self.walk(self.lists.base.wrapping_add(offset(ty, b)));
                    }
                }
                _ => {}
            }
        }
        self.lists.depth -= 1;
    }
}
