//! Occlusion queries (GL 1.5, GL 2.1 §4.1.7 and §6.1.12): GenQueries, DeleteQueries, IsQuery,
//! BeginQuery, EndQuery, GetQueryiv, GetQueryObject{i,ui}v.
//!
//! A query counts the fragments that pass the depth test (and every test before it: scissor,
//! alpha, stencil) between BeginQuery(SAMPLES_PASSED) and EndQuery, as llvmpipe counts them: the
//! CPU renderer counts only while a query is active (`Renderer::start_counting_samples`), so a
//! program that never begins one pays nothing. EndQuery draws what is batched into the scene,
//! each flush tagged with the query's count, and reading the result (GetQueryObject) rasterises
//! the scene if it must, so a result is always available when GetQueryObject asks, and a frame
//! whose results are not read (a replay) makes no pass of its own for its queries.
//!
//! Design decision: query objects live in the context, beside display lists, not in `State`
//! (no attribute group holds them). Names are handed out as Mesa does (the block after the
//! largest name ever used), and, in the compatibility profile, BeginQuery with a name
//! GenQueries never returned creates the object (Mesa). Where GL 2.1 and Mesa's 4.5 context
//! differ (only SAMPLES_PASSED is a GL 2.1 target) fixedgl gives GL 2.1's INVALID_ENUM, and the
//! GL backend raises it before the driver.

use std::collections::BTreeMap;

use super::Context;
use crate::call::Call;
use crate::gl;

/// `QUERY_COUNTER_BITS` of SAMPLES_PASSED: llvmpipe's 64.
pub const QUERY_COUNTER_BITS: i32 = 64;

/// One query object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct QueryObject {
    /// The target of its first BeginQuery; 0 until then (a name GenQueries returned is not yet
    /// a query object for IsQuery, §6.1.12).
    target: u32,
    /// The count of the last query that ended on it, once read.
    result: u64,
    /// The renderer's number of that count while it is not read (`Renderer::take_samples`).
    count: Option<u64>,
}

/// The context's query objects and the active query.
#[derive(Debug, Default)]
pub(crate) struct Queries {
    objects: BTreeMap<u32, QueryObject>,
    /// The largest name ever used (Mesa hands out the names after it).
    max_name: u32,
    /// The query of SAMPLES_PASSED in progress.
    pub(super) active: Option<u32>,
}

impl Context {
    /// `glGenQueries`: writes `n` unused names to `ids` (the block after the largest name used
    /// so far, as Mesa). INVALID_VALUE for a negative `n` or (Rust API) an `ids` shorter than
    /// `n`; OUT_OF_MEMORY when the names past the largest run out; INVALID_OPERATION between
    /// Begin and End. Not compiled into display lists (§5.4).
    pub fn gen_queries(&mut self, n: i32, ids: &mut [u32]) {
        let made = self.gen_queries_inner(n, ids);
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::GenQueries(n, made));
        }
    }

    fn gen_queries_inner(&mut self, n: i32, ids: &mut [u32]) -> Vec<u32> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return Vec::new();
        }
        let Ok(n) = usize::try_from(n) else {
            self.error(gl::INVALID_VALUE);
            return Vec::new();
        };
        let Some(out) = ids.get_mut(..n) else {
            self.error(gl::INVALID_VALUE);
            return Vec::new();
        };
        let q = &mut self.queries;
        let first = u64::from(q.max_name) + 1;
        if first + n as u64 > u64::from(u32::MAX) + 1 {
            self.error(gl::OUT_OF_MEMORY);
            return Vec::new();
        }
        for (k, slot) in out.iter_mut().enumerate() {
            let name = (first + k as u64) as u32;
            *slot = name;
            q.objects.insert(name, QueryObject::default());
            q.max_name = name;
        }
        out.to_vec()
    }

    /// A recorded `GenQueries(n, names)`: room for as many names as the recorded call got.
    pub(super) fn replay_gen_queries(&mut self, n: i32, names: &[u32]) {
        let mut out = vec![0; names.len()];
        self.gen_queries(n, &mut out);
    }

    /// `glDeleteQueries`: deletes the query objects named (0 and unused names are ignored); an
    /// active one ends first, its count dropped. INVALID_VALUE for a negative `n` or (Rust API)
    /// fewer than `n` names; INVALID_OPERATION between Begin and End. Not compiled into display
    /// lists.
    pub fn delete_queries(&mut self, n: i32, ids: &[u32]) {
        if let (Some(rec), 0) = (self.recording.as_mut(), self.lists.depth) {
            rec.push(Call::DeleteQueries(n, ids.to_vec()));
        }
        if !self.outside_begin_end() {
            return;
        }
        let Some(ids) = usize::try_from(n).ok().and_then(|n| ids.get(..n)) else {
            return self.error(gl::INVALID_VALUE);
        };
        for &id in ids {
            if self.queries.active == Some(id) && id != 0 {
                self.renderer.stop_counting_samples(&self.state);
                self.queries.active = None;
            }
            if let Some(n) = self.queries.objects.remove(&id).and_then(|q| q.count) {
                self.renderer.forget_samples(n);
            }
        }
    }

    /// `glIsQuery`: whether `id` names a query object, i.e. one BeginQuery has used (a name only
    /// generated is not one yet, §6.1.12). INVALID_OPERATION (and false) between Begin and End.
    pub fn is_query(&mut self, id: u32) -> bool {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.queries.objects.get(&id).is_some_and(|q| q.target != 0)
    }

    /// `glBeginQuery(SAMPLES_PASSED, id)` (§4.1.7): starts counting the fragments that pass the
    /// depth test into query `id`, creating it if need be. INVALID_ENUM for another target;
    /// INVALID_OPERATION between Begin and End, while a query is active, or for `id` 0.
    pub fn begin_query(&mut self, target: u32, id: u32) {
        record!(self, Call::BeginQuery(target, id));
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::SAMPLES_PASSED {
            return self.error(gl::INVALID_ENUM);
        }
        if self.queries.active.is_some() || id == 0 {
            return self.error(gl::INVALID_OPERATION);
        }
        let q = &mut self.queries;
        let object = q.objects.entry(id).or_default();
        let unread = object.count.take();
        q.max_name = q.max_name.max(id);
        q.active = Some(id);
        if let Some(n) = unread {
            self.renderer.forget_samples(n);
        }
        let count = self.renderer.start_counting_samples(&self.state);
        if let Some(object) = self.queries.objects.get_mut(&id) {
            *object = QueryObject {
                target,
                result: 0,
                count: Some(count),
            };
        }
    }

    /// Ends every query and forgets the objects' counts (`Context::reset`).
    pub(super) fn drop_queries(&mut self) {
        let queries = std::mem::take(&mut self.queries);
        if queries.active.is_some() {
            self.renderer.stop_counting_samples(&self.state);
        }
        for n in queries.objects.values().filter_map(|q| q.count) {
            self.renderer.forget_samples(n);
        }
    }

    /// `glEndQuery(SAMPLES_PASSED)`: ends the active query; its result is the count.
    /// INVALID_ENUM for another target; INVALID_OPERATION between Begin and End or with no
    /// query active.
    pub fn end_query(&mut self, target: u32) {
        record!(self, Call::EndQuery(target));
        if !self.outside_begin_end() {
            return;
        }
        if target != gl::SAMPLES_PASSED {
            return self.error(gl::INVALID_ENUM);
        }
        if self.queries.active.take().is_none() {
            return self.error(gl::INVALID_OPERATION);
        }
        // The count is taken when the result is read.
        self.renderer.stop_counting_samples(&self.state);
    }

    /// `glGetQueryiv(SAMPLES_PASSED, pname)`: QUERY_COUNTER_BITS (64, as llvmpipe) or
    /// CURRENT_QUERY (the active query's name, 0 for none) into `params[0]`. INVALID_ENUM for
    /// another target or pname; INVALID_OPERATION between Begin and End; INVALID_VALUE (Rust
    /// API) for an empty `params`.
    pub fn get_queryiv(&mut self, target: u32, pname: u32, params: &mut [i32]) {
        if self.begin_mode.is_some() {
            return self.error(gl::INVALID_OPERATION);
        }
        if target != gl::SAMPLES_PASSED {
            return self.error(gl::INVALID_ENUM);
        }
        let value = match pname {
            gl::QUERY_COUNTER_BITS => QUERY_COUNTER_BITS,
            gl::CURRENT_QUERY => self.queries.active.unwrap_or(0) as i32,
            _ => return self.error(gl::INVALID_ENUM),
        };
        match params.first_mut() {
            Some(p) => *p = value,
            None => self.error(gl::INVALID_VALUE),
        }
    }

    /// The value of GetQueryObject{i,ui}v, Mesa's checks in Mesa's order: INVALID_OPERATION
    /// between Begin and End, for id 0, a name that is no query object, or the active query;
    /// then INVALID_ENUM for a pname other than QUERY_RESULT and QUERY_RESULT_AVAILABLE.
    fn query_object(&mut self, id: u32, pname: u32) -> Option<u64> {
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return None;
        }
        let object = self.queries.objects.get(&id).copied();
        let Some(q) = object.filter(|q| q.target != 0 && self.queries.active != Some(id)) else {
            self.error(gl::INVALID_OPERATION);
            return None;
        };
        match pname {
            gl::QUERY_RESULT => Some(match q.count {
                // Read once: the scene is rasterised if it still holds flushes it counts.
                Some(n) => {
                    let result = self.renderer.take_samples(n);
                    if let Some(q) = self.queries.objects.get_mut(&id) {
                        *q = QueryObject {
                            count: None,
                            result,
                            ..*q
                        };
                    }
                    result
                }
                None => q.result,
            }),
            // The count is complete whenever it is read (the scene is rasterised then):
            // always available.
            gl::QUERY_RESULT_AVAILABLE => Some(1),
            _ => {
                self.error(gl::INVALID_ENUM);
                None
            }
        }
    }

    /// `glGetQueryObjectiv`: QUERY_RESULT (the count, saturated at i32::MAX as Mesa does) or
    /// QUERY_RESULT_AVAILABLE (always TRUE: the count is completed when read) of query `id`
    /// into `params[0]`. Errors as GL 2.1 §6.1.12 and Mesa: INVALID_OPERATION between Begin and
    /// End, for 0, a name that is no query object or the active query, then INVALID_ENUM for a
    /// pname; INVALID_VALUE (Rust API) for an empty `params`.
    pub fn get_query_objectiv(&mut self, id: u32, pname: u32, params: &mut [i32]) {
        if let Some(v) = self.query_object(id, pname) {
            match params.first_mut() {
                Some(p) => *p = i32::try_from(v).unwrap_or(i32::MAX),
                None => self.error(gl::INVALID_VALUE),
            }
        }
    }

    /// `glGetQueryObjectuiv`: as [`Context::get_query_objectiv`], saturated at u32::MAX.
    pub fn get_query_objectuiv(&mut self, id: u32, pname: u32, params: &mut [u32]) {
        if let Some(v) = self.query_object(id, pname) {
            match params.first_mut() {
                Some(p) => *p = u32::try_from(v).unwrap_or(u32::MAX),
                None => self.error(gl::INVALID_VALUE),
            }
        }
    }
}
