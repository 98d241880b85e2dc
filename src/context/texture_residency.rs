//! Texture residency (GL 2.1 §3.8.12 "Texture Objects", GL 1.1): `PrioritizeTextures` and
//! `AreTexturesResident`.
//!
//! Design decision: fixedgl has no texture memory to page out, so every texture object is
//! resident, as Mesa answers (its drivers report every object resident); priorities are kept as
//! the objects' TEXTURE_PRIORITY, clamped to [0, 1], and change nothing else. A name that
//! GenTextures returned but no BindTexture has made an object yet exists for
//! AreTexturesResident (Mesa makes its objects at GenTextures) but has no parameters to take a
//! priority, so PrioritizeTextures skips it as it skips 0 and unused names.

use super::Context;
use crate::call::Call;
use crate::gl;

impl Context {
    /// `glPrioritizeTextures`: sets TEXTURE_PRIORITY of the first `n` objects named in
    /// `textures` to the matching `priorities`, each clamped to [0, 1]; 0, unused names and
    /// names without an object yet are skipped (no error, as Mesa). `n < 0` or a slice shorter
    /// than `n` is INVALID_VALUE; between Begin and End, INVALID_OPERATION. Compiled into
    /// display lists (GL 2.1 §5.4 does not list it as immediate).
    pub fn prioritize_textures(&mut self, n: i32, textures: &[u32], priorities: &[f32]) {
        record!(
            self,
            Call::PrioritizeTextures(Box::new((n, textures.to_vec(), priorities.to_vec())))
        );
        if !self.outside_begin_end() {
            return;
        }
        let Ok(count) = usize::try_from(n) else {
            return self.error(gl::INVALID_VALUE);
        };
        if textures.len() < count || priorities.len() < count {
            return self.error(gl::INVALID_VALUE);
        }
        self.objects_txn(super::share::TEXTURES, &[], |ctx| {
            let objects = &mut ctx.state.textures.objects;
            for (name, p) in textures.iter().zip(priorities).take(count) {
                if let Some(o) = objects.get_mut(name) {
                    // A NaN priority clamps to NaN in Rust; Mesa's CLAMP keeps it too, so
                    // it is stored as 0 here to stay inside the range the query promises.
                    let p = if p.is_nan() { 0.0 } else { p.clamp(0.0, 1.0) };
                    std::sync::Arc::make_mut(o).priority = p;
                }
            }
        });
    }

    /// `glAreTexturesResident`: true when every one of the first `n` names in `textures` names
    /// a texture (all do here, so `residences` is left unwritten, as GL allows when the answer
    /// is true). `n < 0`, a slice shorter than `n`, or a name that is 0 or not a texture
    /// (neither generated nor bound) is INVALID_VALUE and false; between Begin and End,
    /// INVALID_OPERATION and false. A query: never compiled into a display list, not
    /// recorded (as `is_texture`). `residences` may be empty; it is not read.
    pub fn are_textures_resident(
        &mut self,
        n: i32,
        textures: &[u32],
        residences: &mut [bool],
    ) -> bool {
        let _ = residences;
        if self.begin_mode.is_some() {
            self.error(gl::INVALID_OPERATION);
            return false;
        }
        self.pull_objects();
        let Ok(count) = usize::try_from(n) else {
            self.error(gl::INVALID_VALUE);
            return false;
        };
        if textures.len() < count {
            self.error(gl::INVALID_VALUE);
            return false;
        }
        let t = &self.state.textures;
        let exists =
            |name: &u32| *name != 0 && (t.names.contains(*name) || t.objects.contains_key(name));
        if !textures.iter().take(count).all(exists) {
            self.error(gl::INVALID_VALUE);
            return false;
        }
        true
    }
}
