//! How many values each pname-dependent vector command reads: one function per family, shared by
//! the front end's validation, the GL backend's replay and the C ABI (Mesa's
//! `_mesa_tex_param_enum_to_count` and `get.c` tables play this part there).
//!
//! Each function answers `Some(n)` for a pname its commands take (GL 2.1 state tables 6.8 to
//! 6.20; §2.14.2, §2.14.3, §3.10, §3.8.4, §3.8.13, §2.11.4) and `None` for one they do not, which is
//! INVALID_ENUM. A slice shorter than `n` is INVALID_VALUE in the Rust API (C has no length to
//! check). Because every user of a count reads it here, the backends cannot disagree about it.

use crate::gl;

/// The most values any pname of these families reads (a 4x4 matrix); the GL backend pads every
/// vector it hands the driver to this length, so a pname the driver knows and this module does not
/// still reads initialised memory.
pub const MAX_VALUES: usize = 16;

/// `Light{fv,iv}` (table 6.10).
pub fn light(pname: u32) -> Option<usize> {
    match pname {
        gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::POSITION => Some(4),
        gl::SPOT_DIRECTION => Some(3),
        gl::SPOT_EXPONENT
        | gl::SPOT_CUTOFF
        | gl::CONSTANT_ATTENUATION
        | gl::LINEAR_ATTENUATION
        | gl::QUADRATIC_ATTENUATION => Some(1),
        _ => None,
    }
}

/// `Material{fv,iv}` (table 6.9).
pub fn material(pname: u32) -> Option<usize> {
    match pname {
        gl::AMBIENT | gl::DIFFUSE | gl::SPECULAR | gl::EMISSION | gl::AMBIENT_AND_DIFFUSE => {
            Some(4)
        }
        gl::COLOR_INDEXES => Some(3),
        gl::SHININESS => Some(1),
        _ => None,
    }
}

/// `LightModel{fv,iv}` (table 6.9).
pub fn light_model(pname: u32) -> Option<usize> {
    match pname {
        gl::LIGHT_MODEL_AMBIENT => Some(4),
        gl::LIGHT_MODEL_LOCAL_VIEWER | gl::LIGHT_MODEL_TWO_SIDE | gl::LIGHT_MODEL_COLOR_CONTROL => {
            Some(1)
        }
        _ => None,
    }
}

/// `PointParameter{fv,iv}` (table 6.11).
pub fn point_parameter(pname: u32) -> Option<usize> {
    match pname {
        gl::POINT_DISTANCE_ATTENUATION => Some(3),
        gl::POINT_SIZE_MIN
        | gl::POINT_SIZE_MAX
        | gl::POINT_FADE_THRESHOLD_SIZE
        | gl::POINT_SPRITE_COORD_ORIGIN => Some(1),
        _ => None,
    }
}

/// `Fog{fv,iv}` (table 6.8).
pub fn fog(pname: u32) -> Option<usize> {
    match pname {
        gl::FOG_COLOR => Some(4),
        gl::FOG_MODE
        | gl::FOG_DENSITY
        | gl::FOG_START
        | gl::FOG_END
        | gl::FOG_INDEX
        | gl::FOG_COORD_SRC => Some(1),
        _ => None,
    }
}

/// `TexEnv{fv,iv}` (table 6.20).
pub fn tex_env(pname: u32) -> Option<usize> {
    match pname {
        gl::TEXTURE_ENV_COLOR => Some(4),
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
        | gl::COORD_REPLACE => Some(1),
        _ => None,
    }
}

/// `TexGen{fv,iv,dv}` (table 6.15).
pub fn tex_gen(pname: u32) -> Option<usize> {
    match pname {
        gl::OBJECT_PLANE | gl::EYE_PLANE => Some(4),
        gl::TEXTURE_GEN_MODE => Some(1),
        _ => None,
    }
}

/// `TexParameter{fv,iv}` (table 6.16).
pub fn tex_parameter(pname: u32) -> Option<usize> {
    match pname {
        gl::TEXTURE_BORDER_COLOR => Some(4),
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
        | gl::GENERATE_MIPMAP => Some(1),
        _ => None,
    }
}

/// The components of an evaluator map's points (`_mesa_evaluator_components`): 4 for
/// COLOR_4, VERTEX_4 and TEXTURE_COORD_4, 3 for NORMAL, VERTEX_3 and TEXTURE_COORD_3, 2 and 1
/// for TEXTURE_COORD_2 and _1, 1 for INDEX, of MAP1_* and MAP2_* alike; `None` for any other
/// target.
pub fn map_components(target: u32) -> Option<usize> {
    let i = match target {
        gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4 => target - gl::MAP1_COLOR_4,
        gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4 => target - gl::MAP2_COLOR_4,
        _ => return None,
    };
    Some(crate::state::EVAL_COMPONENTS[i as usize])
}

/// How many values `Map1{f,d}` reads from its points: `(order - 1) * stride + k`, or `None`
/// when the call fails before reading them (a target that is no MAP1_*, an order outside 1 to
/// MAX_EVAL_ORDER, a stride below the target's `k` components), or the count is past `usize`.
pub fn map1_points(target: u32, stride: i32, order: i32) -> Option<usize> {
    if !(gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4).contains(&target) {
        return None;
    }
    map_points(target, &[(stride, order)])
}

/// `Map2{f,d}`'s count: `(uorder - 1) * ustride + (vorder - 1) * vstride + k`, `None` as in
/// [`map1_points`].
pub fn map2_points(
    target: u32,
    ustride: i32,
    uorder: i32,
    vstride: i32,
    vorder: i32,
) -> Option<usize> {
    if !(gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4).contains(&target) {
        return None;
    }
    map_points(target, &[(ustride, uorder), (vstride, vorder)])
}

fn map_points(target: u32, dims: &[(i32, i32)]) -> Option<usize> {
    let k = map_components(target)?;
    let mut n = k;
    for &(stride, order) in dims {
        if !(1..=crate::state::MAX_EVAL_ORDER).contains(&order) || stride < k as i32 {
            return None;
        }
        n = n.checked_add((order as usize - 1).checked_mul(stride as usize)?)?;
    }
    Some(n)
}

/// How many values `GetMap{f,d,i}v(target, query)` writes for the map's orders (`uorder`,
/// `vorder`; 1 for a one-dimensional map): COEFF every component of every point, ORDER 1 or 2,
/// DOMAIN 2 or 4; `None` for a target or query that is none of these.
pub fn get_map(target: u32, query: u32, uorder: i32, vorder: i32) -> Option<usize> {
    let k = map_components(target)?;
    let two = target >= gl::MAP2_COLOR_4;
    match query {
        gl::COEFF => Some(uorder.max(0) as usize * vorder.max(0) as usize * k),
        gl::ORDER => Some(if two { 2 } else { 1 }),
        gl::DOMAIN => Some(if two { 4 } else { 2 }),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_follow_the_state_tables() {
        assert_eq!(light(gl::SPOT_DIRECTION), Some(3));
        assert_eq!(light(gl::QUADRATIC_ATTENUATION), Some(1));
        assert_eq!(material(gl::AMBIENT_AND_DIFFUSE), Some(4));
        assert_eq!(material(gl::COLOR_INDEXES), Some(3));
        assert_eq!(material(gl::POSITION), None);
        assert_eq!(light_model(gl::LIGHT_MODEL_AMBIENT), Some(4));
        assert_eq!(fog(gl::FOG_COLOR), Some(4));
        assert_eq!(tex_gen(gl::EYE_PLANE), Some(4));
        assert_eq!(tex_env(gl::TEXTURE_ENV_MODE), Some(1));
        assert_eq!(tex_parameter(gl::TEXTURE_BORDER_COLOR), Some(4));
        assert_eq!(tex_parameter(gl::TEXTURE_LOD_BIAS), Some(1));
    }
}
