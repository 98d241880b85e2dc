//! Share groups (GL 2.1 appendix D; GLX/EGL/OSMesa "share context"): contexts that see the
//! same display lists, texture objects and buffer objects.
//!
//! Design decision: each context keeps its own copy of the objects (the maps in
//! `State::textures`, `State::arrays` and `DisplayLists`, read as before by every command and by
//! the CPU renderer, which therefore needs nothing new), and the group holds the authoritative
//! copy behind a mutex, with a generation counter bumped at every change. Objects are shared,
//! not copied: textures and display lists are `Arc`s (a copy is made only when one context
//! changes an object another still holds, by `Arc::make_mut`); a buffer's store is copied into
//! the group when it changes (stores stay plain `Vec`s, so MapBuffer's address stays stable).
//!
//! - A command that creates, changes or deletes objects (Gen*, Delete*, BindTexture,
//!   BindBuffer, TexImage*, TexSubImage*, CopyTex*, TexParameter, PopAttrib, EndList,
//!   BufferData, ...) runs as a transaction: under the group's lock, the context first takes the
//!   group's newer objects, runs, then writes what it changed back and bumps the generation.
//!   Two contexts on two threads therefore never hand out the same name twice.
//! - Every other command that may use an object (every command outside Begin/End, Begin,
//!   CallList, CallLists, Is*) first compares the group's generation with the one this context
//!   last saw (one atomic load) and takes the newer objects when they differ. A change made by
//!   one context is thus visible to another at its next such command: stronger than GL's
//!   "after the object is bound again" (appendix D).
//! - Bindings, LIST_BASE, the list being compiled, the attribute stacks and the mapping of a
//!   buffer are the context's own. A buffer mapped in one context is seen by the others as it
//!   was before MapBuffer until UnmapBuffer.
//! - A context without a group (the default) pays one `Option` test per command outside
//!   Begin/End and nothing else.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use super::Context;
use crate::arrays::BufferObject;
use crate::texture::{NameSet, TexObject, TARGETS};

/// Which kinds of objects a transaction may change.
pub(crate) const TEXTURES: u8 = 1;
/// Display lists.
pub(crate) const LISTS: u8 = 2;
/// Buffer objects (the names given to the transaction, and the reserved names).
pub(crate) const BUFFERS: u8 = 4;

/// The group's copy of the shared objects.
#[derive(Debug, Default)]
struct Objects {
    /// The generation at which the textures last changed.
    tex_gen: u64,
    tex_names: NameSet,
    tex_objects: BTreeMap<u32, Arc<TexObject>>,
    /// The default textures (name 0 of each target): shared too, as in Mesa.
    tex_defaults: Option<[Arc<TexObject>; 4]>,
    list_gen: u64,
    lists: super::lists::ListMap,
    list_reserved: Vec<(u32, u32)>,
    list_max_used: u32,
    buf_gen: u64,
    buf_reserved: NameSet,
    /// Each buffer with the generation it was last written at.
    buffers: BTreeMap<u32, (u64, BufferObject)>,
}

#[derive(Debug, Default)]
struct Group {
    /// Bumped (under the lock) at every change of `objects`.
    generation: AtomicU64,
    objects: Mutex<Objects>,
}

impl Group {
    fn lock(&self) -> MutexGuard<'_, Objects> {
        // A panic while the lock was held (caught at the C boundary) leaves plain data behind.
        self.objects.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// A share group: the display lists, texture objects and buffer objects that every context
/// made with it (and the context it came from) see, as a GLX/EGL "share context" gives them
/// (GL 2.1 appendix D). Cheap to clone (a handle); the objects live as long as a context of
/// the group or a handle does.
///
/// ```
/// # use fixedgl::{Context, ContextConfig};
/// let mut a = Context::new(64, 64).unwrap();
/// let list = a.gen_lists(1);
/// a.new_list(list, fixedgl::gl::COMPILE);
/// a.end_list();
/// // B shares A's objects: A's list is B's list.
/// let group = a.share_group();
/// let mut b = Context::with_config_shared(64, 64, ContextConfig::default(), &group).unwrap();
/// assert!(b.is_list(list));
/// ```
#[derive(Clone, Debug, Default)]
pub struct ShareGroup(Arc<Group>);

impl ShareGroup {
    /// A new, empty group (no objects yet).
    pub fn new() -> ShareGroup {
        ShareGroup::default()
    }

    /// Whether `self` and `other` are the same group.
    pub fn same(&self, other: &ShareGroup) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// A context's membership of a group: what it has seen of it.
#[derive(Debug)]
pub(crate) struct Link {
    group: Arc<Group>,
    /// The group generation this context's copies reflect.
    seen: u64,
    tex_gen: u64,
    list_gen: u64,
    buf_gen: u64,
    /// The generation of each buffer as this context last copied or wrote it.
    buf_versions: BTreeMap<u32, u64>,
    /// Inside a transaction: nested ones (PopAttrib, a list executing TexImage) only run.
    in_txn: bool,
    /// Buffers deleted by another context while mapped here: kept until the context goes, so
    /// that the address MapBuffer returned stays valid (GL: the store lives while mapped).
    orphans: Vec<BufferObject>,
    /// Whether this context took objects another context made while recording (said once).
    told_recording: bool,
}

impl Context {
    /// The group this context's objects are shared through: made now (holding this context's
    /// lists, textures and buffers) if it has none yet. Give it to
    /// [`Context::with_config_shared`] to make contexts that share them.
    pub fn share_group(&mut self) -> ShareGroup {
        if let Some(link) = &self.share {
            return ShareGroup(link.group.clone());
        }
        let group = Arc::new(Group::default());
        self.share = Some(Box::new(Link {
            group: group.clone(),
            seen: 0,
            tex_gen: 0,
            list_gen: 0,
            buf_gen: 0,
            buf_versions: BTreeMap::new(),
            in_txn: false,
            orphans: Vec::new(),
            told_recording: false,
        }));
        {
            let mut g = group.lock();
            self.push(&mut g, TEXTURES | LISTS | BUFFERS, None);
        }
        ShareGroup(group)
    }

    /// A context as [`Context::with_config`] makes it, in share group `group`: it sees the
    /// display lists, texture objects (names, images, parameters; the default textures too, as
    /// in Mesa) and buffer objects of every context of the group, and they see its own (GL 2.1
    /// appendix D). Its bindings, LIST_BASE, attribute stacks and every other piece of state are
    /// its own. Changes one context makes are visible to another from its next command outside
    /// Begin/End (or Begin, CallList, Is*). Contexts of a group may live on different threads.
    pub fn with_config_shared(
        width: u32,
        height: u32,
        config: crate::ContextConfig,
        group: &ShareGroup,
    ) -> Result<Context, crate::Error> {
        let mut ctx = Context::with_config(width, height, config)?;
        ctx.join(group);
        Ok(ctx)
    }

    /// [`Context::new`] in share group `group` (see [`Context::with_config_shared`]).
    pub fn new_shared(
        width: u32,
        height: u32,
        group: &ShareGroup,
    ) -> Result<Context, crate::Error> {
        Self::with_config_shared(width, height, crate::ContextConfig::default(), group)
    }

    /// Joins `group` (a fresh context, whose own objects are dropped): takes its objects.
    fn join(&mut self, group: &ShareGroup) {
        self.share = Some(Box::new(Link {
            group: group.0.clone(),
            seen: u64::MAX,
            tex_gen: u64::MAX,
            list_gen: u64::MAX,
            buf_gen: u64::MAX,
            buf_versions: BTreeMap::new(),
            in_txn: false,
            orphans: Vec::new(),
            told_recording: false,
        }));
        self.state.arrays.buffers.clear();
        self.pull_objects();
    }

    /// Forgets what was seen of the group, so that the next check takes everything again
    /// (after `reset`, which dropped this context's copies).
    pub(crate) fn resync_share(&mut self) {
        if let Some(link) = self.share.as_mut() {
            link.seen = u64::MAX;
            link.tex_gen = u64::MAX;
            link.list_gen = u64::MAX;
            link.buf_gen = u64::MAX;
            link.buf_versions.clear();
        }
        self.pull_objects();
    }

    /// Takes the group's newer objects, if another context changed any since this one last
    /// looked: one atomic load when nothing changed, nothing at all without a group.
    #[inline]
    pub(crate) fn pull_objects(&mut self) {
        if let Some(link) = &self.share {
            if link.group.generation.load(Ordering::Acquire) != link.seen {
                self.pull_slow();
            }
        }
    }

    #[cold]
    fn pull_slow(&mut self) {
        let Some(group) = self.share.as_ref().map(|l| l.group.clone()) else {
            return;
        };
        // The vertices batched so far are drawn with the objects they were given under.
        if self.begin_mode.is_none() {
            self.renderer.flush(&self.state);
        }
        let g = group.lock();
        self.pull(&g);
    }

    /// Copies the group's objects that changed since this context last saw them (the lock held).
    fn pull(&mut self, g: &Objects) {
        let Some(mut link) = self.share.take() else {
            return;
        };
        let recording = self.recording.is_some();
        let mut took = false;
        if link.tex_gen != g.tex_gen {
            let t = &mut self.state.textures;
            t.names = g.tex_names.clone();
            t.objects = g.tex_objects.clone();
            if let Some(d) = &g.tex_defaults {
                t.defaults = d.clone();
            }
            link.tex_gen = g.tex_gen;
            took = true;
        }
        if link.list_gen != g.list_gen {
            self.lists
                .set_store(&g.lists, &g.list_reserved, g.list_max_used);
            link.list_gen = g.list_gen;
            took = true;
        }
        if link.buf_gen != g.buf_gen {
            let a = &mut self.state.arrays;
            a.reserved = g.buf_reserved.clone();
            // Gone from the group: deleted elsewhere (a store mapped here is kept alive).
            let gone: Vec<u32> = a
                .buffers
                .keys()
                .filter(|k| !g.buffers.contains_key(k))
                .copied()
                .collect();
            for name in gone {
                if let Some(b) = a.buffers.remove(&name) {
                    if b.mapped {
                        link.orphans.push(b);
                    }
                }
                link.buf_versions.remove(&name);
            }
            for (&name, (v, b)) in &g.buffers {
                if link.buf_versions.get(&name) == Some(v) {
                    continue;
                }
                // A store mapped here stays as it is until UnmapBuffer.
                if a.buffers.get(&name).is_some_and(|b| b.mapped) {
                    continue;
                }
                a.buffers.insert(name, b.clone());
                link.buf_versions.insert(name, *v);
            }
            link.buf_gen = g.buf_gen;
            took = true;
        }
        link.seen = link.group.generation.load(Ordering::Acquire);
        if took && recording && !link.told_recording && link.seen != 0 {
            link.told_recording = true;
            eprintln!(
                "fixedgl: a recording context shares objects with another context; its recording \
                 holds only the calls made on it, so a replay of it alone lacks the objects the \
                 other context made (see docs/c-abi.md, \"Shared contexts\")"
            );
        }
        self.share = Some(link);
    }

    /// Writes this context's objects of the kinds in `kinds` into the group (the lock held) and
    /// bumps the generation. For buffers only the names in `buffers` are written (all if None).
    fn push(&mut self, g: &mut Objects, kinds: u8, buffers: Option<&[u32]>) {
        let Some(link) = self.share.as_mut() else {
            return;
        };
        let gen = link.group.generation.load(Ordering::Acquire) + 1;
        if kinds & TEXTURES != 0 {
            let t = &self.state.textures;
            g.tex_names = t.names.clone();
            g.tex_objects = t.objects.clone();
            g.tex_defaults = Some(t.defaults.clone());
            g.tex_gen = gen;
            link.tex_gen = gen;
        }
        if kinds & LISTS != 0 {
            let (defined, reserved, max_used) = self.lists.store();
            g.lists = defined.clone();
            g.list_reserved = reserved.to_vec();
            g.list_max_used = max_used;
            g.list_gen = gen;
            link.list_gen = gen;
        }
        if kinds & BUFFERS != 0 {
            let a = &self.state.arrays;
            g.buf_reserved = a.reserved.clone();
            let all: Vec<u32>;
            let names = match buffers {
                Some(n) => n,
                None => {
                    all = a.buffers.keys().copied().collect();
                    &all
                }
            };
            for &name in names {
                match a.buffers.get(&name) {
                    // The group keeps the store as it was before MapBuffer until UnmapBuffer.
                    Some(b) if b.mapped => {}
                    Some(b) => {
                        g.buffers.insert(name, (gen, b.clone()));
                        link.buf_versions.insert(name, gen);
                    }
                    None if name != 0 => {
                        g.buffers.remove(&name);
                        link.buf_versions.remove(&name);
                    }
                    None => {}
                }
            }
            g.buf_gen = gen;
            link.buf_gen = gen;
        }
        link.group.generation.store(gen, Ordering::Release);
        link.seen = gen;
    }

    /// Runs `f`, a command that may create, change or delete objects of `kinds`, as one
    /// transaction of the group: under its lock, after taking the group's newer objects, and
    /// writing the changed kinds back after (for buffers, the names `buffers`). Without a group,
    /// or inside a transaction already, just runs `f`.
    #[inline]
    pub(crate) fn objects_txn<R>(
        &mut self,
        kinds: u8,
        buffers: &[u32],
        f: impl FnOnce(&mut Context) -> R,
    ) -> R {
        match &self.share {
            Some(link) if !link.in_txn => self.txn_slow(kinds, buffers, f),
            _ => f(self),
        }
    }

    fn txn_slow<R>(&mut self, kinds: u8, buffers: &[u32], f: impl FnOnce(&mut Context) -> R) -> R {
        let Some(group) = self.share.as_ref().map(|l| l.group.clone()) else {
            return f(self);
        };
        let mut g = group.lock();
        if self
            .share
            .as_ref()
            .is_some_and(|l| group.generation.load(Ordering::Acquire) != l.seen)
        {
            self.pull(&g);
        }
        if let Some(l) = self.share.as_mut() {
            l.in_txn = true;
        }
        // The flag is cleared and the objects written back even if `f` unwinds (the C ABI
        // catches panics): the group never keeps a half-made state hidden from the others,
        // and the next transaction does not skip its lock.
        struct Done<'a, 'b> {
            ctx: &'a mut Context,
            g: &'a mut MutexGuard<'b, Objects>,
            kinds: u8,
            buffers: &'a [u32],
        }
        impl Drop for Done<'_, '_> {
            fn drop(&mut self) {
                self.ctx.push(self.g, self.kinds, Some(self.buffers));
                if let Some(l) = self.ctx.share.as_mut() {
                    l.in_txn = false;
                }
            }
        }
        let done = Done {
            ctx: self,
            g: &mut g,
            kinds,
            buffers,
        };
        f(done.ctx)
    }

    /// Whether this context shares objects with a group (made by [`Context::share_group`] or
    /// [`Context::with_config_shared`]).
    pub fn is_shared(&self) -> bool {
        self.share.is_some()
    }
}

/// The targets' count, checked against the group's default-texture array.
const _: () = assert!(TARGETS.len() == 4);
