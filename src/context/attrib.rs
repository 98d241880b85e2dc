//! Attribute stacks (GL 2.1 §6.1.14): `PushAttrib`, `PopAttrib`, `PushClientAttrib`,
//! `PopClientAttrib`.
//!
//! Which state belongs to which group is the "Attribute" column of GL 2.1 tables 6.5 to 6.31;
//! [`copy_groups`] and [`copy_client_groups`] are that column written out, one line per field.
//! The matrix stacks are in no group (TRANSFORM_BIT is the matrix mode, the clip planes and their
//! enables, NORMALIZE and RESCALE_NORMAL).
//!
//! Design decision: a stack entry is a whole `State` (built fresh, not cloned, so no matrix stack
//! or object store rides along) into which the pushed groups are copied, and PopAttrib copies the
//! same groups back with the same function. The one exception to "no object store": TEXTURE_BIT
//! puts a parameter-only stand-in (no images) of each unit's bound object of every target in the
//! entry. Adding a field to a group is therefore one line in
//! one table, and save and restore cannot disagree.

use std::sync::Arc;

use super::Context;
use crate::call::Call;
use crate::gl;
use crate::state::State;
use crate::texture::{TexObject, TARGETS};

/// `MAX_ATTRIB_STACK_DEPTH` and `MAX_CLIENT_ATTRIB_STACK_DEPTH` (GL 2.1 table 6.35: at least 16).
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;

/// The server and client attribute stacks: each entry the pushed mask and the saved values.
#[derive(Debug, Default)]
pub(crate) struct AttribStacks {
    server: Vec<(u32, Box<State>)>,
    client: Vec<(u32, Box<State>)>,
}

/// Copies `field` paths from `s` to `d`.
macro_rules! copy {
    ($d:ident, $s:ident; $($($f:ident).+),+ $(,)?) => {
        $( $d.$($f).+ = $s.$($f).+.clone(); )+
    };
}

/// Copies the server attribute groups in `mask` from `s` to `d` (GL 2.1 tables 6.5 to 6.31,
/// "Attribute" column). A field of state in a group is one line here.
pub(crate) fn copy_groups(mask: u32, d: &mut State, s: &State) {
    let has = |bit: u32| mask & bit != 0;
    if has(gl::CURRENT_BIT) {
        // Table 6.5: current colour, secondary colour, normal, texture coordinates, fog
        // coordinate, edge flag; the raster position and its associated data.
        copy!(d, s; current, raster_pos);
    }
    if has(gl::ENABLE_BIT) {
        // Every Enable flag is in the enable group as well as in its own.
        copy!(d, s; enables);
    }
    if has(gl::TRANSFORM_BIT) {
        // Table 6.7 (the matrices themselves are in no group).
        copy!(d, s; matrix_mode, clip_planes, enables.clip_planes, enables.normalize,
            enables.rescale_normal);
    }
    if has(gl::VIEWPORT_BIT) {
        copy!(d, s; viewport, depth_range);
    }
    if has(gl::LIGHTING_BIT) {
        // Tables 6.9, 6.10.
        copy!(d, s; shade_model, lights, light_model, materials, color_material_face,
            color_material_mode, enables.lighting, enables.lights, enables.color_material);
    }
    if has(gl::POINT_BIT) {
        // Table 6.11.
        copy!(d, s; point_size, point, enables.point_smooth, enables.point_sprite);
    }
    if has(gl::LINE_BIT) {
        // Table 6.12.
        copy!(d, s; line_width, enables.line_smooth, enables.line_stipple,
            stipple.line_pattern, stipple.line_repeat);
    }
    if has(gl::POLYGON_BIT) {
        // Table 6.13.
        copy!(d, s; front_face, cull_face_mode, polygon_mode, polygon_offset_factor,
            polygon_offset_units, enables.cull_face, enables.polygon_smooth,
            enables.polygon_stipple, enables.polygon_offset_fill, enables.polygon_offset_line,
            enables.polygon_offset_point);
    }
    if has(gl::POLYGON_STIPPLE_BIT) {
        // Table 6.13: the stipple pattern (its enable is in POLYGON_BIT and ENABLE_BIT).
        copy!(d, s; stipple.polygon);
    }
    if has(gl::TEXTURE_BIT) {
        // Tables 6.15 to 6.20: the selected unit and every unit's enables.
        copy!(d, s; active_texture, enables.texture_1d, enables.texture_2d, enables.texture_3d,
            enables.texture_cube_map, enables.texture_gen);
        // Each unit's bindings (every target), environment and TexGen, then the bound objects'
        // parameters.
        copy!(d, s; textures.units);
        copy_bound_params(d, s);
    }
    if has(gl::SCISSOR_BIT) {
        // Table 6.21.
        copy!(d, s; scissor, enables.scissor_test);
    }
    if has(gl::COLOR_BUFFER_BIT) {
        // Tables 6.21, 6.22.
        copy!(d, s; color_mask, clear_color, clear_index, index_writemask, enables.alpha_test, enables.blend, enables.dither,
            enables.color_logic_op, enables.index_logic_op);
        copy!(d, s; alpha, blend, logic_op);
        // Table 6.22: DRAW_BUFFER.
        copy!(d, s; draw_buffer);
    }
    if has(gl::DEPTH_BUFFER_BIT) {
        copy!(d, s; depth_func, depth_mask, clear_depth, enables.depth_test);
    }
    if has(gl::STENCIL_BUFFER_BIT) {
        copy!(d, s; stencil_writemask, clear_stencil, enables.stencil_test, stencil);
    }
    if has(gl::FOG_BIT) {
        // Table 6.8: fog, and COLOR_SUM.
        copy!(d, s; enables.fog, enables.color_sum, fog);
    }
    if has(gl::HINT_BIT) {
        copy!(d, s; hints);
    }
    if has(gl::EVAL_BIT) {
        copy!(d, s; enables.auto_normal, enables.map1, enables.map2, eval_grid);
    }
    if has(gl::MULTISAMPLE_BIT) {
        // Table 6.15: the enables, SAMPLE_COVERAGE_VALUE and _INVERT.
        copy!(d, s; enables.multisample, enables.sample_alpha_to_coverage,
            enables.sample_alpha_to_one, enables.sample_coverage);
        copy!(d, s; sample_coverage_value, sample_coverage_invert);
    }
    if has(gl::LIST_BIT) {
        copy!(d, s; list_base);
    }
    if has(gl::PIXEL_MODE_BIT) {
        // Table 6.23: the pixel transfer parameters and the zoom (the pixel maps are in no
        // group); table 6.26: READ_BUFFER.
        copy!(d, s; pixel, read_buffer);
    }
    if has(gl::ACCUM_BUFFER_BIT) {
        // Table 6.22: ACCUM_CLEAR_VALUE.
        copy!(d, s; accum_clear);
    }
}

/// Copies the parameters (table 6.16, attribute "texture") of the texture object bound to each
/// target (TEXTURE_1D, _2D, _3D, _CUBE_MAP) on each unit of `s` to the object of the same name in
/// `d`, as Mesa does (GL 2.1 §6.1.14 lists the bindings and these parameters in TEXTURE_BIT). Run
/// after the bindings are copied, so `d` binds the same names. In a pushed entry (a fresh State)
/// the object is a parameter-only stand-in; on pop, a name deleted since the push is created
/// again with the saved target, as BindTexture would (§3.8.12), with the saved parameters and no
/// images. A name that meanwhile became an object of another target cannot be bound to this one
/// (§3.8.12), so that binding reverts to the target's default texture instead.
fn copy_bound_params(d: &mut State, s: &State) {
    for unit in 0..s.textures.units.len() {
        for (k, &target) in TARGETS.iter().enumerate() {
            let Some(params) = s.textures.bound(unit, target).map(|o| o.params()) else {
                continue;
            };
            let Some(name) = d
                .textures
                .units
                .get(unit)
                .and_then(|u| u.bindings.get(k))
                .copied()
            else {
                continue;
            };
            if name != 0 {
                match d.textures.objects.get(&name) {
                    None => {
                        d.textures.names.insert(name);
                        d.textures
                            .objects
                            .insert(name, Arc::new(TexObject::new(target)));
                    }
                    Some(o) if o.target != target => {
                        if let Some(b) = d
                            .textures
                            .units
                            .get_mut(unit)
                            .and_then(|u| u.bindings.get_mut(k))
                        {
                            *b = 0;
                        }
                        continue;
                    }
                    Some(_) => {}
                }
            }
            // Only when they differ, so an object shared with a snapshot is not copied for
            // nothing.
            if d.textures.bound(unit, target).map(|o| o.params()) != Some(params) {
                if let Some(obj) = d.textures.bound_mut(unit, target) {
                    obj.set_params(&params);
                }
            }
        }
    }
}

/// Copies the client attribute groups in `mask` from `s` to `d` (GL 2.1 tables 6.6 and 6.24).
pub(crate) fn copy_client_groups(mask: u32, d: &mut State, s: &State) {
    let has = |bit: u32| mask & bit != 0;
    if has(gl::CLIENT_PIXEL_STORE_BIT) {
        // Tables 6.17, 6.18: all eight modes of each direction.
        copy!(d, s; unpack, pack);
    }
    if has(gl::CLIENT_VERTEX_ARRAY_BIT) {
        copy!(d, s; client_active_texture);
        // Tables 6.6 to 6.9: every array's enable, size, type, stride, pointer and buffer
        // binding, and the two buffer bindings (not the buffers' contents).
        copy!(d, s; arrays.vertex, arrays.normal, arrays.color, arrays.secondary_color,
            arrays.fog_coord, arrays.edge_flag, arrays.index, arrays.tex_coords, arrays.array_buffer,
            arrays.element_array_buffer);
    }
}

impl Context {
    /// `glPushAttrib`: saves the groups in `mask` (ALL_ATTRIB_BITS for all).
    /// STACK_OVERFLOW when MAX_ATTRIB_STACK_DEPTH entries are already pushed.
    pub fn push_attrib(&mut self, mask: u32) {
        record!(self, Call::PushAttrib(mask));
        if !self.outside_begin_end() {
            return;
        }
        if self.attrib.server.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(gl::STACK_OVERFLOW);
        }
        let mut saved = Box::new(State::with_config(
            self.state.width,
            self.state.height,
            self.state.config,
        ));
        copy_groups(mask, &mut saved, &self.state);
        self.attrib.server.push((mask, saved));
    }

    /// `glPopAttrib`: restores the groups the matching PushAttrib saved.
    /// STACK_UNDERFLOW when the stack is empty.
    pub fn pop_attrib(&mut self) {
        record!(self, Call::PopAttrib);
        if !self.outside_begin_end() {
            return;
        }
        let Some((mask, saved)) = self.attrib.server.pop() else {
            return self.error(gl::STACK_UNDERFLOW);
        };
        // TEXTURE_BIT restores the bound objects' parameters: a change of shared objects.
        if mask & gl::TEXTURE_BIT != 0 {
            self.objects_txn(super::share::TEXTURES, &[], |ctx| {
                copy_groups(mask, &mut ctx.state, &saved)
            });
        } else {
            copy_groups(mask, &mut self.state, &saved);
        }
    }

    /// `glPushClientAttrib`: saves the client groups in `mask` (CLIENT_PIXEL_STORE_BIT,
    /// CLIENT_VERTEX_ARRAY_BIT). Executed immediately, never compiled (GL 2.1 §5.4).
    /// STACK_OVERFLOW when MAX_CLIENT_ATTRIB_STACK_DEPTH entries are already pushed.
    pub fn push_client_attrib(&mut self, mask: u32) {
        record!(self, Call::PushClientAttrib(mask));
        if !self.outside_begin_end() {
            return;
        }
        if self.attrib.client.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(gl::STACK_OVERFLOW);
        }
        let mut saved = Box::new(State::new(self.state.width, self.state.height));
        copy_client_groups(mask, &mut saved, &self.state);
        self.attrib.client.push((mask, saved));
    }

    /// `glPopClientAttrib`: restores what the matching PushClientAttrib saved.
    /// STACK_UNDERFLOW when the stack is empty.
    pub fn pop_client_attrib(&mut self) {
        record!(self, Call::PopClientAttrib);
        if !self.outside_begin_end() {
            return;
        }
        let Some((mask, saved)) = self.attrib.client.pop() else {
            return self.error(gl::STACK_UNDERFLOW);
        };
        copy_client_groups(mask, &mut self.state, &saved);
    }

    /// ATTRIB_STACK_DEPTH and CLIENT_ATTRIB_STACK_DEPTH (GL 2.1 table 6.36).
    pub(crate) fn attrib_stack_depths(&self) -> (usize, usize) {
        (self.attrib.server.len(), self.attrib.client.len())
    }
}
