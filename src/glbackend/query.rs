//! Occlusion queries on the driver (GL 1.5, GL 2.1 §4.1.7).
//!
//! `GenQueries` is not sent: the names were chosen by the front end and recorded, and the
//! driver's BeginQuery creates the object of any name in a compatibility context (as it does for
//! fixedgl's front end), so both hold the same names. `DeleteQueries` goes to the driver once
//! the slice is known to hold `n` names.

use super::GlBackend;
use crate::gl;

impl GlBackend {
    /// A recorded `GenQueries(n, names)`: the front end's errors (INVALID_VALUE for a negative
    /// `n`, or for a failed call that returned no names); nothing is sent. Executed even while
    /// a list is compiled (GL 2.1 §5.4), as the front end does.
    pub(super) fn gen_queries(&mut self, n: i32, names: &[u32]) {
        match usize::try_from(n) {
            Ok(n) if n <= names.len() => {}
            _ => self.raise(gl::INVALID_VALUE),
        }
    }

    /// `DeleteQueries`: a slice shorter than `n` is the front end's INVALID_VALUE, raised here;
    /// otherwise the driver deletes (and raises its own INVALID_VALUE for a negative `n`).
    pub(super) fn delete_queries(&mut self, n: i32, names: &[u32]) {
        if n > 0 && names.len() < n as usize {
            return self.raise(gl::INVALID_VALUE);
        }
        // SAFETY: the context is current (see `execute`); `names` holds at least `n` names
        // (or `n` is not positive and the driver reads none). Finish first: llvmpipe frees a
        // deleted query even while its rasteriser threads still count into it (see `Drop`).
        unsafe {
            self.raw.Finish();
            self.raw.DeleteQueries(n, names.as_ptr());
        }
    }
}
