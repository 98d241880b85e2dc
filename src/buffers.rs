//! The colour buffers `DrawBuffer` and `ReadBuffer` name (GL 2.1 §4.2.1, table 4.4, and
//! §4.3.2), and which of them a framebuffer has: the rules the front end validates with and the
//! GL backend replays with, so both raise the same errors.
//!
//! A fixedgl framebuffer has FRONT_LEFT, and BACK_LEFT when double-buffered: no right (stereo)
//! buffers and no AUX buffers (AUX_BUFFERS is 0).

use crate::gl;
use crate::state::ContextConfig;

/// The front left buffer.
pub const FRONT_LEFT: u8 = 1;
/// The back left buffer.
pub const BACK_LEFT: u8 = 2;
/// The front right buffer (never present).
pub const FRONT_RIGHT: u8 = 4;
/// The back right buffer (never present).
pub const BACK_RIGHT: u8 = 8;
/// An auxiliary buffer AUXi (never present).
pub const AUX: u8 = 16;

/// The buffers a `DrawBuffer` argument names (table 4.4), or `None` when it is none of the
/// values DrawBuffer accepts (NONE, FRONT_LEFT, FRONT_RIGHT, BACK_LEFT, BACK_RIGHT, FRONT,
/// BACK, LEFT, RIGHT, FRONT_AND_BACK, AUX0 to AUX3).
pub fn mask(buf: u32) -> Option<u8> {
    Some(match buf {
        gl::NONE => 0,
        gl::FRONT_LEFT => FRONT_LEFT,
        gl::FRONT_RIGHT => FRONT_RIGHT,
        gl::BACK_LEFT => BACK_LEFT,
        gl::BACK_RIGHT => BACK_RIGHT,
        gl::FRONT => FRONT_LEFT | FRONT_RIGHT,
        gl::BACK => BACK_LEFT | BACK_RIGHT,
        gl::LEFT => FRONT_LEFT | BACK_LEFT,
        gl::RIGHT => FRONT_RIGHT | BACK_RIGHT,
        gl::FRONT_AND_BACK => FRONT_LEFT | FRONT_RIGHT | BACK_LEFT | BACK_RIGHT,
        gl::AUX0..=gl::AUX3 => AUX,
        _ => return None,
    })
}

/// The one buffer a `ReadBuffer` argument names (§4.3.2: FRONT and LEFT the front left, BACK
/// the back left, RIGHT the front right buffer), or `None` when it is none of the values
/// ReadBuffer accepts in GL 2.1 (which are DrawBuffer's without NONE and FRONT_AND_BACK).
pub fn read_mask(buf: u32) -> Option<u8> {
    Some(match buf {
        gl::FRONT_LEFT | gl::FRONT | gl::LEFT => FRONT_LEFT,
        gl::FRONT_RIGHT | gl::RIGHT => FRONT_RIGHT,
        gl::BACK_LEFT | gl::BACK => BACK_LEFT,
        gl::BACK_RIGHT => BACK_RIGHT,
        gl::AUX0..=gl::AUX3 => AUX,
        _ => return None,
    })
}

/// The buffers a framebuffer of `config` has.
pub fn existing(config: &ContextConfig) -> u8 {
    if config.double_buffered {
        FRONT_LEFT | BACK_LEFT
    } else {
        FRONT_LEFT
    }
}

/// `DrawBuffer(buf)`'s error on a framebuffer of `config`, if any: INVALID_ENUM for a value
/// DrawBuffer does not take, INVALID_OPERATION when `buf` (not NONE) names no buffer the
/// framebuffer has (§4.2.1).
pub fn draw_error(buf: u32, config: &ContextConfig) -> Option<u32> {
    match mask(buf) {
        None if is_color_attachment(buf) => Some(gl::INVALID_OPERATION),
        None => Some(gl::INVALID_ENUM),
        Some(m) if buf != gl::NONE && m & existing(config) == 0 => Some(gl::INVALID_OPERATION),
        Some(_) => None,
    }
}

/// `ReadBuffer(buf)`'s error on a framebuffer of `config`, if any: INVALID_ENUM for a value
/// ReadBuffer does not take, INVALID_OPERATION for a buffer the framebuffer lacks (§4.3.2).
pub fn read_error(buf: u32, config: &ContextConfig) -> Option<u32> {
    match read_mask(buf) {
        None if is_color_attachment(buf) => Some(gl::INVALID_OPERATION),
        None => Some(gl::INVALID_ENUM),
        Some(m) if m & existing(config) == 0 => Some(gl::INVALID_OPERATION),
        Some(_) => None,
    }
}

/// COLOR_ATTACHMENT0 to COLOR_ATTACHMENT15 (GL_EXT_framebuffer_object): buffers of a
/// framebuffer object, which the window's framebuffer lacks (INVALID_OPERATION there, as Mesa).
pub fn is_color_attachment(buf: u32) -> bool {
    (gl::COLOR_ATTACHMENT0..=gl::COLOR_ATTACHMENT15).contains(&buf)
}

/// `DrawBuffer(buf)`'s error while a framebuffer object is bound (GL 3.0 §4.2.1): NONE and
/// COLOR_ATTACHMENT0 (MAX_COLOR_ATTACHMENTS is 1) are taken; another attachment or a window
/// buffer (FRONT, BACK, ...) is INVALID_OPERATION; anything else INVALID_ENUM.
pub fn fbo_draw_error(buf: u32) -> Option<u32> {
    match buf {
        gl::NONE | gl::COLOR_ATTACHMENT0 => None,
        _ if is_color_attachment(buf) || mask(buf).is_some() => Some(gl::INVALID_OPERATION),
        _ => Some(gl::INVALID_ENUM),
    }
}

/// `ReadBuffer(buf)`'s error while a framebuffer object is bound: COLOR_ATTACHMENT0 is taken;
/// another attachment or a window buffer is INVALID_OPERATION; anything else (NONE among them,
/// as GL 2.1's ReadBuffer) INVALID_ENUM.
pub fn fbo_read_error(buf: u32) -> Option<u32> {
    match buf {
        gl::COLOR_ATTACHMENT0 => None,
        _ if is_color_attachment(buf) || read_mask(buf).is_some() => Some(gl::INVALID_OPERATION),
        _ => Some(gl::INVALID_ENUM),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draw_and_read_buffer_errors() {
        let single = ContextConfig::default();
        let double = ContextConfig {
            double_buffered: true,
            ..single
        };
        for (buf, s, d) in [
            (gl::NONE, None, None),
            (gl::FRONT, None, None),
            (gl::BACK, Some(gl::INVALID_OPERATION), None),
            (gl::LEFT, None, None),
            (
                gl::RIGHT,
                Some(gl::INVALID_OPERATION),
                Some(gl::INVALID_OPERATION),
            ),
            (gl::BACK_LEFT, Some(gl::INVALID_OPERATION), None),
            (gl::FRONT_AND_BACK, None, None),
            (
                gl::AUX0,
                Some(gl::INVALID_OPERATION),
                Some(gl::INVALID_OPERATION),
            ),
            (gl::AUX3 + 1, Some(gl::INVALID_ENUM), Some(gl::INVALID_ENUM)),
            (
                gl::TRIANGLES,
                Some(gl::INVALID_ENUM),
                Some(gl::INVALID_ENUM),
            ),
        ] {
            assert_eq!(draw_error(buf, &single), s, "DrawBuffer({buf:#x}) single");
            assert_eq!(draw_error(buf, &double), d, "DrawBuffer({buf:#x}) double");
        }
        assert_eq!(read_error(gl::NONE, &double), Some(gl::INVALID_ENUM));
        assert_eq!(
            read_error(gl::FRONT_AND_BACK, &double),
            Some(gl::INVALID_ENUM)
        );
        assert_eq!(read_error(gl::BACK, &single), Some(gl::INVALID_OPERATION));
        assert_eq!(read_error(gl::LEFT, &single), None);
        assert_eq!(read_error(gl::RIGHT, &double), Some(gl::INVALID_OPERATION));
    }
}
