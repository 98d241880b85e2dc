//! GL_EXT_vertex_array (1995), the extension GL 1.1 made core: its `gl*PointerEXT` commands
//! take a `count` after the stride, which Mesa ignores, and so does fixedgl: each one is the
//! GL 1.1 command of the same name. The extension's other three commands (`glArrayElementEXT`,
//! `glDrawArraysEXT`, `glGetPointervEXT`) are gl.xml aliases of core ones, exported by
//! generated.rs. Old programs (and piglit's `gl-1.0-rendermode-feedback`) ask for
//! the extension by name before drawing with arrays.

use std::ffi::c_void;

use crate::generated::{
    glColorPointer, glEdgeFlagPointer, glIndexPointer, glNormalPointer, glTexCoordPointer,
    glVertexPointer,
};

/// `glVertexPointerEXT`: [`glVertexPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glVertexPointerEXT(
    size: i32,
    type_: u32,
    stride: i32,
    _count: i32,
    pointer: *const c_void,
) {
    glVertexPointer(size, type_, stride, pointer)
}

/// `glNormalPointerEXT`: [`glNormalPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glNormalPointerEXT(
    type_: u32,
    stride: i32,
    _count: i32,
    pointer: *const c_void,
) {
    glNormalPointer(type_, stride, pointer)
}

/// `glColorPointerEXT`: [`glColorPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glColorPointerEXT(
    size: i32,
    type_: u32,
    stride: i32,
    _count: i32,
    pointer: *const c_void,
) {
    glColorPointer(size, type_, stride, pointer)
}

/// `glIndexPointerEXT`: [`glIndexPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glIndexPointerEXT(
    type_: u32,
    stride: i32,
    _count: i32,
    pointer: *const c_void,
) {
    glIndexPointer(type_, stride, pointer)
}

/// `glTexCoordPointerEXT`: [`glTexCoordPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glTexCoordPointerEXT(
    size: i32,
    type_: u32,
    stride: i32,
    _count: i32,
    pointer: *const c_void,
) {
    glTexCoordPointer(size, type_, stride, pointer)
}

/// `glEdgeFlagPointerEXT`: [`glEdgeFlagPointer`]; `count` is not used.
#[no_mangle]
pub unsafe extern "C" fn glEdgeFlagPointerEXT(stride: i32, _count: i32, pointer: *const u8) {
    glEdgeFlagPointer(stride, pointer.cast())
}
