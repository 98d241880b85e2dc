//! The pointer arguments of the generated entry points: array pointers (read at draw time),
//! index and buffer data (copied at the call, as GL reads them then), and pixel rectangles
//! (sized from format, type and the unpack modes). One function per command, named after its
//! `Context` method, taking the C arguments as they are.

use std::ffi::c_void;
use std::sync::Arc;

use fixedgl::arrays::{ClientMemory, ClientPointer};
use fixedgl::pixel_store::PixelModes;
use fixedgl::{gl, Pointer};

use crate::current::Gl;
use crate::read;

/// A C program's array memory, read when a draw happens.
struct RawMemory(usize);

impl ClientMemory for RawMemory {
    fn address(&self) -> usize {
        self.0
    }

    fn read(&self, len: usize) -> &[u8] {
        // SAFETY: GL's contract: the program keeps the array memory valid, holding what its
        // draws read, while the pointer is in use; NULL reads as nothing (the draw is then
        // INVALID_OPERATION).
        unsafe { read::bytes(self.0 as *const c_void, len) }
    }
}

/// An array pointer: an offset into the buffer bound to ARRAY_BUFFER, or the program's memory,
/// read at each draw.
fn array(gl: &Gl, pointer: *const c_void) -> Pointer {
    if gl.ctx.state().arrays.array_buffer != 0 {
        Pointer::Offset(pointer as usize)
    } else {
        Pointer::Client(Box::new(ClientPointer::new(Arc::new(RawMemory(
            pointer as usize,
        )))))
    }
}

/// Data read at the call: `len` bytes (none for NULL, which the command answers).
unsafe fn data(pointer: *const c_void, len: usize) -> Pointer {
    // SAFETY: the caller's promise that `len` bytes are there.
    Pointer::Data(unsafe { read::bytes(pointer, len) }.to_vec())
}

pub fn vertex_pointer(
    gl: &mut Gl,
    _size: i32,
    _ty: u32,
    _stride: i32,
    p: *const c_void,
) -> Pointer {
    array(gl, p)
}

pub fn normal_pointer(gl: &mut Gl, _ty: u32, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

pub fn color_pointer(gl: &mut Gl, _size: i32, _ty: u32, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

pub fn secondary_color_pointer(
    gl: &mut Gl,
    _size: i32,
    _ty: u32,
    _stride: i32,
    p: *const c_void,
) -> Pointer {
    array(gl, p)
}

pub fn tex_coord_pointer(
    gl: &mut Gl,
    _size: i32,
    _ty: u32,
    _stride: i32,
    p: *const c_void,
) -> Pointer {
    array(gl, p)
}

pub fn fog_coord_pointer(gl: &mut Gl, _ty: u32, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

pub fn edge_flag_pointer(gl: &mut Gl, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

pub fn index_pointer(gl: &mut Gl, _ty: u32, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

pub fn interleaved_arrays(gl: &mut Gl, _format: u32, _stride: i32, p: *const c_void) -> Pointer {
    array(gl, p)
}

/// Bytes per index of a DrawElements type (0: not one, which the command answers).
fn index_size(ty: u32) -> usize {
    match ty {
        gl::UNSIGNED_BYTE => 1,
        gl::UNSIGNED_SHORT => 2,
        gl::UNSIGNED_INT => 4,
        _ => 0,
    }
}

/// Index data: an offset into the ELEMENT_ARRAY_BUFFER, or the `count` indices, read now.
unsafe fn indices(gl: &Gl, count: i32, ty: u32, p: *const c_void) -> Pointer {
    if gl.ctx.state().arrays.element_array_buffer != 0 {
        return Pointer::Offset(p as usize);
    }
    let n = usize::try_from(count).unwrap_or(0);
    // SAFETY: the caller's promise that `count` indices of `ty` are there.
    unsafe { data(p, n.saturating_mul(index_size(ty))) }
}

pub unsafe fn draw_elements(
    gl: &mut Gl,
    _mode: u32,
    count: i32,
    ty: u32,
    p: *const c_void,
) -> Pointer {
    // SAFETY: as `indices`.
    unsafe { indices(gl, count, ty, p) }
}

pub unsafe fn draw_range_elements(
    gl: &mut Gl,
    _mode: u32,
    _start: u32,
    _end: u32,
    count: i32,
    ty: u32,
    p: *const c_void,
) -> Pointer {
    // SAFETY: as `indices`.
    unsafe { indices(gl, count, ty, p) }
}

pub unsafe fn buffer_data(
    _gl: &mut Gl,
    _target: u32,
    size: isize,
    p: *const c_void,
    _usage: u32,
) -> Pointer {
    if p.is_null() {
        return Pointer::NULL;
    }
    // SAFETY: the caller's promise that `size` bytes are there.
    unsafe { data(p, usize::try_from(size).unwrap_or(0)) }
}

pub unsafe fn buffer_sub_data(
    _gl: &mut Gl,
    _target: u32,
    _offset: isize,
    size: isize,
    p: *const c_void,
) -> Pointer {
    // SAFETY: the caller's promise that `size` bytes are there.
    unsafe { data(p, usize::try_from(size).unwrap_or(0)) }
}

/// CallLists' names: `n` of `ty` (GL 2.1 §5.4 table 5.2).
pub unsafe fn call_lists(_gl: &mut Gl, n: i32, ty: u32, p: *const c_void) -> Vec<u8> {
    let size = match ty {
        gl::BYTE | gl::UNSIGNED_BYTE => 1,
        gl::SHORT | gl::UNSIGNED_SHORT | gl::GL_2_BYTES => 2,
        gl::GL_3_BYTES => 3,
        gl::INT | gl::UNSIGNED_INT | gl::FLOAT | gl::GL_4_BYTES => 4,
        _ => 0,
    };
    let n = usize::try_from(n).unwrap_or(0);
    // SAFETY: the caller's promise that `n` names of `ty` are there.
    unsafe { read::bytes(p, n.saturating_mul(size)) }.to_vec()
}

/// The bytes a `width` x `height` image of `format`/`ty` spans in client memory under
/// `modes` (§3.6.4; BITMAP rows are bits, §3.7), as the core lays it out. 0 when the format
/// or type is not one, or the size is negative (the command answers with its error, before it
/// reads anything).
pub fn image_bytes(modes: &PixelModes, width: i32, height: i32, format: u32, ty: u32) -> usize {
    fixedgl::pixels::check(format, ty)
        .ok()
        .and_then(|f| modes.image_layout(f, width, height))
        .map_or(0, |l| l.need())
}

/// The bytes `depth` images of `width` x `height` span under `modes` (TexImage3D, GL 2.1
/// §3.8.1): images IMAGE_HEIGHT rows apart (or `height`), SKIP_IMAGES of them skipped, each as
/// [`image_bytes`] lays a 2D image out. 0 as `image_bytes`, or when the count overflows.
pub fn image_bytes3(
    modes: &PixelModes,
    width: i32,
    height: i32,
    depth: i32,
    format: u32,
    ty: u32,
) -> usize {
    if width <= 0 || height <= 0 || depth <= 0 {
        return 0;
    }
    let img = if modes.image_height > 0 {
        i64::from(modes.image_height)
    } else {
        i64::from(height)
    };
    let rows = i64::from(depth - 1) * img + i64::from(height);
    let skip = i64::from(modes.skip_rows.max(0)) + i64::from(modes.skip_images.max(0)) * img;
    let (Ok(rows), Ok(skip)) = (i32::try_from(rows), i32::try_from(skip)) else {
        return 0;
    };
    let flat = PixelModes {
        skip_rows: skip,
        image_height: 0,
        skip_images: 0,
        ..*modes
    };
    image_bytes(&flat, width, rows, format, ty)
}

/// Pixels to unpack: NULL stays NULL (TexImage2D then leaves the image undefined).
unsafe fn unpack(
    gl: &Gl,
    w: i32,
    h: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    if p.is_null() {
        return None;
    }
    let len = image_bytes(&gl.ctx.state().unpack, w, h, format, ty);
    // SAFETY: the caller's promise that the image is there, as the unpack modes lay it out.
    Some(unsafe { read::bytes(p, len) }.to_vec())
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_image_2d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: i32,
    width: i32,
    height: i32,
    _border: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, height, format, ty, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_sub_image_2d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    _y: i32,
    width: i32,
    height: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Vec<u8> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, height, format, ty, p) }.unwrap_or_default()
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_image_1d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: i32,
    width: i32,
    _border: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, 1, format, ty, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_sub_image_1d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    width: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Vec<u8> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, 1, format, ty, p) }.unwrap_or_default()
}

/// A 3D image to unpack (IMAGE_HEIGHT and SKIP_IMAGES count); NULL stays NULL.
unsafe fn unpack3(
    gl: &Gl,
    w: i32,
    h: i32,
    d: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    if p.is_null() {
        return None;
    }
    let len = image_bytes3(&gl.ctx.state().unpack, w, h, d, format, ty);
    // SAFETY: the caller's promise that the image is there, as the unpack modes lay it out.
    Some(unsafe { read::bytes(p, len) }.to_vec())
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_image_3d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: i32,
    width: i32,
    height: i32,
    depth: i32,
    _border: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `unpack3`.
    unsafe { unpack3(gl, width, height, depth, format, ty, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn tex_sub_image_3d(
    gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    _y: i32,
    _z: i32,
    width: i32,
    height: i32,
    depth: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Vec<u8> {
    // SAFETY: as `unpack3`.
    unsafe { unpack3(gl, width, height, depth, format, ty, p) }.unwrap_or_default()
}

/// PolygonStipple's 32x32 mask, a bitmap read as the unpack modes lay it out; none for NULL
/// (the command then answers INVALID_OPERATION, as for a short mask).
pub unsafe fn polygon_stipple(gl: &mut Gl, p: *const u8) -> Vec<u8> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, 32, 32, gl::COLOR_INDEX, gl::BITMAP, p.cast()) }.unwrap_or_default()
}

/// Bitmap's bits, as the unpack modes lay out a `width` x `height` bitmap; None for NULL
/// (then Bitmap only moves the raster position, §3.7).
#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn bitmap(
    gl: &mut Gl,
    width: i32,
    height: i32,
    _xorig: f32,
    _yorig: f32,
    _xmove: f32,
    _ymove: f32,
    p: *const u8,
) -> Option<Vec<u8>> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, height, gl::COLOR_INDEX, gl::BITMAP, p.cast()) }
}

/// DrawPixels' image, as the unpack modes lay it out; none for NULL (the command then answers
/// as for a short image).
pub unsafe fn draw_pixels(
    gl: &mut Gl,
    width: i32,
    height: i32,
    format: u32,
    ty: u32,
    p: *const c_void,
) -> Vec<u8> {
    // SAFETY: as `unpack`.
    unsafe { unpack(gl, width, height, format, ty, p) }.unwrap_or_default()
}

/// MultiDrawElements' index arrays: each an offset into the ELEMENT_ARRAY_BUFFER or
/// `count[i]` indices read now; none for NULL or a negative `drawcount` (the command answers).
pub unsafe fn multi_draw_elements(
    gl: &mut Gl,
    _mode: u32,
    count: *const i32,
    ty: u32,
    indices: *const *const c_void,
    drawcount: i32,
) -> Vec<Pointer> {
    let n = usize::try_from(drawcount).unwrap_or(0);
    // SAFETY: `drawcount` counts and pointers (the caller's promise).
    let (counts, pointers) = unsafe { (read::slice(count, n), read::slice(indices, n)) };
    counts
        .iter()
        .zip(pointers)
        // SAFETY: as `indices`.
        .map(|(&c, &p)| unsafe { self::indices(gl, c, ty, p) })
        .collect()
}

/// Evaluator points: the values the map reads (`counts::map1_points`, `map2_points`); when it
/// reads none (its arguments fail first) a non-null pointer stands as one unread value, so
/// that the command fails as the driver does, not as for NULL (empty).
unsafe fn points<T: Copy + Default>(p: *const T, needed: Option<usize>) -> Vec<T> {
    match needed {
        // SAFETY: the caller's promise that the map's values are there.
        Some(n) => unsafe { read::slice(p, n) }.to_vec(),
        None if p.is_null() => Vec::new(),
        None => vec![T::default()],
    }
}

pub fn map1f(
    _: &mut Gl,
    target: u32,
    _: f32,
    _: f32,
    stride: i32,
    order: i32,
    p: *const f32,
) -> Vec<f32> {
    // SAFETY: as `points`.
    unsafe { points(p, fixedgl::counts::map1_points(target, stride, order)) }
}

pub fn map1d(
    _: &mut Gl,
    target: u32,
    _: f64,
    _: f64,
    stride: i32,
    order: i32,
    p: *const f64,
) -> Vec<f64> {
    // SAFETY: as `points`.
    unsafe { points(p, fixedgl::counts::map1_points(target, stride, order)) }
}

#[allow(clippy::too_many_arguments)]
pub fn map2f(
    _: &mut Gl,
    target: u32,
    _: f32,
    _: f32,
    ustride: i32,
    uorder: i32,
    _: f32,
    _: f32,
    vstride: i32,
    vorder: i32,
    p: *const f32,
) -> Vec<f32> {
    let n = fixedgl::counts::map2_points(target, ustride, uorder, vstride, vorder);
    // SAFETY: as `points`.
    unsafe { points(p, n) }
}

#[allow(clippy::too_many_arguments)]
pub fn map2d(
    _: &mut Gl,
    target: u32,
    _: f64,
    _: f64,
    ustride: i32,
    uorder: i32,
    _: f64,
    _: f64,
    vstride: i32,
    vorder: i32,
    p: *const f64,
) -> Vec<f64> {
    let n = fixedgl::counts::map2_points(target, ustride, uorder, vstride, vorder);
    // SAFETY: as `points`.
    unsafe { points(p, n) }
}

/// The most bytes of a compressed image the call keeps (64 MiB, a 4096 x 4096 RGBA8 image):
/// fixedgl offers no compressed format, so these commands never read their data; a recording
/// keeps it for the replay, and more than this is not copied (the recorded call then holds the
/// first 64 MiB, which the GL backend treats as a short image: fixedgl's error, no driver call).
const MAX_COMPRESSED_BYTES: usize = 1 << 26;

/// A compressed image's `imageSize` bytes (at most [`MAX_COMPRESSED_BYTES`]; none for a
/// negative size); None for NULL.
unsafe fn compressed(image_size: i32, p: *const c_void) -> Option<Vec<u8>> {
    if p.is_null() {
        return None;
    }
    let len = usize::try_from(image_size)
        .unwrap_or(0)
        .min(MAX_COMPRESSED_BYTES);
    // SAFETY: the caller's promise that `imageSize` bytes are there (GL reads as many).
    Some(unsafe { read::bytes(p, len) }.to_vec())
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_image_1d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: u32,
    _width: i32,
    _border: i32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_image_2d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: u32,
    _width: i32,
    _height: i32,
    _border: i32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_image_3d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _internal: u32,
    _width: i32,
    _height: i32,
    _depth: i32,
    _border: i32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_sub_image_1d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    _width: i32,
    _format: u32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_sub_image_2d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    _y: i32,
    _width: i32,
    _height: i32,
    _format: u32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}

#[allow(clippy::too_many_arguments)] // the C signature
pub unsafe fn compressed_tex_sub_image_3d(
    _gl: &mut Gl,
    _target: u32,
    _level: i32,
    _x: i32,
    _y: i32,
    _z: i32,
    _width: i32,
    _height: i32,
    _depth: i32,
    _format: u32,
    image_size: i32,
    p: *const c_void,
) -> Option<Vec<u8>> {
    // SAFETY: as `compressed`.
    unsafe { compressed(image_size, p) }
}
