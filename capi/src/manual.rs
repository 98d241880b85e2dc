//! The GL commands that answer through the caller's memory or a return value: queries, object
//! names, pixel reads, strings, errors; Flush/Finish, which also present single-buffered
//! drawables; Viewport, where the framebuffer follows a resized window. Written by hand because
//! each needs the size of what it writes or does more than the command (the generator leaves
//! every `extern "C" fn gl*` defined here to this file).
//!
//! A query first copies the caller's values into a buffer of the size the pname has, runs the
//! `Context` method on it, and copies it back: on an error nothing changes, as GL requires. NULL
//! where values are written is handed on as an empty buffer, which the method answers with
//! INVALID_VALUE (after its enum checks).

use std::ffi::{c_void, CString};
use std::sync::OnceLock;

use fixedgl::{counts, gl, Context, Pointer};

use crate::args::{image_bytes, image_bytes3};
use crate::current::with_gl;
use crate::read;

// GL_EXT_vertex_array's own commands, which the GetProcAddress table names too.
pub use crate::ext_vertex_array::*;

/// Runs `f` on a copy of the `n` values at `out` and writes them back.
unsafe fn through<T: Copy>(out: *mut T, n: usize, f: impl FnOnce(&mut [T])) {
    // SAFETY: the caller's promise that the pname's `n` values may be written at `out`.
    let slot = unsafe { read::slice_mut(out, n) };
    let mut buf = slot.to_vec();
    f(&mut buf);
    slot.copy_from_slice(&buf);
}

/// As `through`, for GLboolean memory and a method taking `bool`s.
unsafe fn through_bool(out: *mut u8, n: usize, f: impl FnOnce(&mut [bool])) {
    // SAFETY: as `through`.
    let slot = unsafe { read::slice_mut(out, n) };
    let mut buf: Vec<bool> = slot.iter().map(|&b| b != 0).collect();
    f(&mut buf);
    for (o, b) in slot.iter_mut().zip(buf) {
        *o = u8::from(b);
    }
}

#[no_mangle]
pub unsafe extern "C" fn glGetBooleanv(pname: u32, data: *mut u8) {
    with_gl("glGetBooleanv", |gl| {
        let n = gl.ctx.get_count(pname).unwrap_or(0);
        // SAFETY: `n` values for this pname.
        unsafe { through_bool(data, n, |v| gl.ctx.get_booleanv(pname, v)) }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetIntegerv(pname: u32, data: *mut i32) {
    with_gl("glGetIntegerv", |gl| {
        let n = gl.ctx.get_count(pname).unwrap_or(0);
        // SAFETY: `n` values for this pname.
        unsafe { through(data, n, |v| gl.ctx.get_integerv(pname, v)) }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetFloatv(pname: u32, data: *mut f32) {
    with_gl("glGetFloatv", |gl| {
        let n = gl.ctx.get_count(pname).unwrap_or(0);
        // SAFETY: `n` values for this pname.
        unsafe { through(data, n, |v| gl.ctx.get_floatv(pname, v)) }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetDoublev(pname: u32, data: *mut f64) {
    with_gl("glGetDoublev", |gl| {
        let n = gl.ctx.get_count(pname).unwrap_or(0);
        // SAFETY: `n` values for this pname.
        unsafe { through(data, n, |v| gl.ctx.get_doublev(pname, v)) }
    })
}

/// The pname-counted getters of one object (`GetLightfv(light, pname, params)` ...).
macro_rules! getter {
    ($c:ident, $method:ident, $t:ty, $count:expr) => {
        #[no_mangle]
        pub unsafe extern "C" fn $c(first: u32, pname: u32, params: *mut $t) {
            with_gl(stringify!($c), |gl| {
                let n: Option<usize> = $count(pname);
                // SAFETY: the pname's values.
                unsafe { through(params, n.unwrap_or(0), |v| gl.ctx.$method(first, pname, v)) }
            })
        }
    };
}

getter!(glGetLightfv, get_lightfv, f32, counts::light);
getter!(glGetLightiv, get_lightiv, i32, counts::light);
getter!(glGetMaterialfv, get_materialfv, f32, counts::material);
getter!(glGetMaterialiv, get_materialiv, i32, counts::material);
getter!(glGetTexEnvfv, get_tex_envfv, f32, counts::tex_env);
getter!(glGetTexEnviv, get_tex_enviv, i32, counts::tex_env);
getter!(glGetTexGenfv, get_tex_genfv, f32, counts::tex_gen);
getter!(glGetTexGeniv, get_tex_geniv, i32, counts::tex_gen);
getter!(glGetTexGendv, get_tex_gendv, f64, counts::tex_gen);
getter!(
    glGetTexParameterfv,
    get_tex_parameterfv,
    f32,
    counts::tex_parameter
);
getter!(
    glGetTexParameteriv,
    get_tex_parameteriv,
    i32,
    counts::tex_parameter
);
getter!(glGetBufferParameteriv, get_buffer_parameteriv, i32, |_| {
    Some(1)
});

#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameteriv(
    target: u32,
    level: i32,
    pname: u32,
    params: *mut i32,
) {
    with_gl("glGetTexLevelParameteriv", |gl| {
        // SAFETY: one value.
        unsafe {
            through(params, 1, |v| {
                gl.ctx.get_tex_level_parameteriv(target, level, pname, v)
            })
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameterfv(
    target: u32,
    level: i32,
    pname: u32,
    params: *mut f32,
) {
    with_gl("glGetTexLevelParameterfv", |gl| {
        // SAFETY: one value.
        unsafe {
            through(params, 1, |v| {
                gl.ctx.get_tex_level_parameterfv(target, level, pname, v)
            })
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetClipPlane(plane: u32, equation: *mut f64) {
    with_gl("glGetClipPlane", |gl| {
        // SAFETY: four values.
        let slot = unsafe { read::slice_mut(equation, 4) };
        let Ok(slot) = <&mut [f64; 4]>::try_from(slot) else {
            return gl.null_pointer();
        };
        let mut v = *slot;
        gl.ctx.get_clip_plane(plane, &mut v);
        *slot = v;
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetPointerv(pname: u32, params: *mut *mut c_void) {
    with_gl("glGetPointerv", |gl| {
        let p = gl.ctx.get_pointerv(pname);
        let address = match &p {
            Pointer::Offset(o) => *o,
            Pointer::Client(c) => c.address(),
            Pointer::Data(d) => d.as_ptr() as usize,
        };
        // SAFETY: one pointer.
        if let Some(slot) = unsafe { read::slice_mut(params, 1) }.first_mut() {
            *slot = address as *mut c_void;
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetBufferSubData(
    target: u32,
    offset: isize,
    size: isize,
    data: *mut c_void,
) {
    with_gl("glGetBufferSubData", |gl| {
        let n = usize::try_from(size).unwrap_or(0);
        // SAFETY: `size` bytes.
        let out = unsafe { read::slice_mut(data.cast::<u8>(), n) };
        gl.ctx.get_buffer_sub_data(target, offset, size, out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glReadPixels(
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    format: u32,
    ty: u32,
    pixels: *mut c_void,
) {
    with_gl("glReadPixels", |gl| {
        let n = image_bytes(&gl.ctx.state().pack, width, height, format, ty);
        // SAFETY: the image as the pack modes lay it out.
        let out = unsafe { read::slice_mut(pixels.cast::<u8>(), n) };
        gl.ctx.read_pixels(x, y, width, height, format, ty, out);
    })
}

/// The entries of pixel map `map` (PIXEL_MAP_*_SIZE); 0 for what is not a map (the command
/// then answers INVALID_ENUM without writing).
fn pixel_map_len(ctx: &mut Context, map: u32) -> usize {
    if !(gl::PIXEL_MAP_I_TO_I..=gl::PIXEL_MAP_A_TO_A).contains(&map) {
        return 0;
    }
    // Each map's size query is 0x40 past it (PIXEL_MAP_I_TO_I_SIZE = PIXEL_MAP_I_TO_I + 0x40).
    let mut n = [0i32];
    ctx.get_integerv(map + 0x40, &mut n);
    usize::try_from(n[0]).unwrap_or(0)
}

macro_rules! get_pixel_map {
    ($name:ident, $method:ident, $t:ty) => {
        #[no_mangle]
        pub unsafe extern "C" fn $name(map: u32, values: *mut $t) {
            with_gl(stringify!($name), |gl| {
                let n = pixel_map_len(&mut gl.ctx, map);
                // SAFETY: the map's PIXEL_MAP_*_SIZE values, as GL defines the output.
                let out = unsafe { read::slice_mut(values, n) };
                gl.ctx.$method(map, out);
            })
        }
    };
}
get_pixel_map!(glGetPixelMapfv, get_pixel_mapfv, f32);
get_pixel_map!(glGetPixelMapuiv, get_pixel_mapuiv, u32);
get_pixel_map!(glGetPixelMapusv, get_pixel_mapusv, u16);

#[no_mangle]
pub unsafe extern "C" fn glGetPolygonStipple(mask: *mut u8) {
    with_gl("glGetPolygonStipple", |gl| {
        let n = image_bytes(&gl.ctx.state().pack, 32, 32, gl::COLOR_INDEX, gl::BITMAP);
        // SAFETY: the 32x32 bitmap as the pack modes lay it out.
        let out = unsafe { read::slice_mut(mask, n) };
        gl.ctx.get_polygon_stipple(out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetTexImage(
    target: u32,
    level: i32,
    format: u32,
    ty: u32,
    pixels: *mut c_void,
) {
    with_gl("glGetTexImage", |gl| {
        let (mut w, mut h, mut d) = ([0], [0], [0]);
        let pending = gl.ctx.get_error();
        gl.ctx
            .get_tex_level_parameteriv(target, level, gl::TEXTURE_WIDTH, &mut w);
        gl.ctx
            .get_tex_level_parameteriv(target, level, gl::TEXTURE_HEIGHT, &mut h);
        gl.ctx
            .get_tex_level_parameteriv(target, level, gl::TEXTURE_DEPTH, &mut d);
        // The size queries' own errors are GetTexImage's to raise, below.
        let _ = gl.ctx.get_error();
        if pending != gl::NO_ERROR {
            gl.ctx.raise_error(pending);
        }
        let n = if target == gl::TEXTURE_3D {
            image_bytes3(&gl.ctx.state().pack, w[0], h[0], d[0], format, ty)
        } else {
            image_bytes(&gl.ctx.state().pack, w[0], h[0], format, ty)
        };
        // SAFETY: the image as the pack modes lay it out.
        let out = unsafe { read::slice_mut(pixels.cast::<u8>(), n) };
        gl.ctx.get_tex_image(target, level, format, ty, out);
    })
}

/// `glGetCompressedTexImage`: no image fixedgl holds is compressed (no compressed format is
/// offered), so the command only raises its error and never writes through `img`.
#[no_mangle]
pub unsafe extern "C" fn glGetCompressedTexImage(target: u32, level: i32, img: *mut c_void) {
    let _ = img;
    with_gl("glGetCompressedTexImage", |gl| {
        gl.ctx.get_compressed_tex_image(target, level, &mut []);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGenTextures(n: i32, textures: *mut u32) {
    with_gl("glGenTextures", |gl| {
        // SAFETY: room for `n` names.
        let out = unsafe { read::slice_mut(textures, usize::try_from(n).unwrap_or(0)) };
        gl.ctx.gen_textures(n, out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGenBuffers(n: i32, buffers: *mut u32) {
    with_gl("glGenBuffers", |gl| {
        // SAFETY: room for `n` names.
        let out = unsafe { read::slice_mut(buffers, usize::try_from(n).unwrap_or(0)) };
        gl.ctx.gen_buffers(n, out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glIsEnabled(cap: u32) -> u8 {
    with_gl("glIsEnabled", |gl| u8::from(gl.ctx.is_enabled(cap)))
}

#[no_mangle]
pub unsafe extern "C" fn glIsList(list: u32) -> u8 {
    with_gl("glIsList", |gl| u8::from(gl.ctx.is_list(list)))
}

#[no_mangle]
pub unsafe extern "C" fn glIsTexture(texture: u32) -> u8 {
    with_gl("glIsTexture", |gl| u8::from(gl.ctx.is_texture(texture)))
}

#[no_mangle]
pub unsafe extern "C" fn glIsBuffer(buffer: u32) -> u8 {
    with_gl("glIsBuffer", |gl| u8::from(gl.ctx.is_buffer(buffer)))
}

#[no_mangle]
pub unsafe extern "C" fn glGetError() -> u32 {
    with_gl("glGetError", |gl| gl.ctx.get_error())
}

/// The four strings, NUL-terminated, made once.
fn strings() -> &'static [CString; 4] {
    static STRINGS: OnceLock<[CString; 4]> = OnceLock::new();
    STRINGS.get_or_init(|| {
        let mut ctx = Context::new(1, 1).ok();
        [gl::VENDOR, gl::RENDERER, gl::VERSION, gl::EXTENSIONS].map(|name| {
            let s = ctx.as_mut().and_then(|c| c.get_string(name)).unwrap_or("");
            CString::new(s).unwrap_or_default()
        })
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetString(name: u32) -> *const u8 {
    with_gl("glGetString", |gl| match gl.ctx.get_string(name) {
        Some(_) => {
            let i = (name - gl::VENDOR) as usize;
            strings()[i].as_ptr().cast()
        }
        None => std::ptr::null(),
    })
}

#[no_mangle]
pub unsafe extern "C" fn glViewport(x: i32, y: i32, width: i32, height: i32) {
    with_gl("glViewport", |gl| {
        // A program's reshape handler calls glViewport with the window's new size, and a GLX
        // program with its own event loop (glxgears) makes no other call then: the framebuffer
        // follows the window here.
        gl.fit_surface();
        gl.ctx.viewport(x, y, width, height);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glFlush() {
    with_gl("glFlush", |gl| {
        gl.ctx.flush();
        gl.flushed();
    })
}

#[no_mangle]
pub unsafe extern "C" fn glFinish() {
    with_gl("glFinish", |gl| {
        gl.ctx.finish();
        gl.flushed();
    })
}

#[no_mangle]
pub unsafe extern "C" fn glMapBuffer(target: u32, access: u32) -> *mut c_void {
    with_gl("glMapBuffer", |gl| {
        // The store does not move while it is mapped (see `Context::map_buffer`), so its
        // address stays valid for the program until UnmapBuffer, DeleteBuffers or BufferData.
        match gl.ctx.map_buffer(target, access) {
            Some(bytes) => bytes.as_mut_ptr().cast(),
            None => std::ptr::null_mut(),
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glUnmapBuffer(target: u32) -> u8 {
    with_gl("glUnmapBuffer", |gl| u8::from(gl.ctx.unmap_buffer(target)))
}

#[no_mangle]
pub unsafe extern "C" fn glGetBufferPointerv(target: u32, pname: u32, params: *mut *mut c_void) {
    with_gl("glGetBufferPointerv", |gl| {
        let p = gl.ctx.get_buffer_pointerv(target, pname);
        // SAFETY: one pointer.
        if let Some(slot) = unsafe { read::slice_mut(params, 1) }.first_mut() {
            *slot = p;
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGenQueries(n: i32, ids: *mut u32) {
    with_gl("glGenQueries", |gl| {
        // SAFETY: room for `n` names.
        let out = unsafe { read::slice_mut(ids, usize::try_from(n).unwrap_or(0)) };
        gl.ctx.gen_queries(n, out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glIsQuery(id: u32) -> u8 {
    with_gl("glIsQuery", |gl| u8::from(gl.ctx.is_query(id)))
}

getter!(glGetQueryiv, get_queryiv, i32, |_| Some(1));
getter!(glGetQueryObjectiv, get_query_objectiv, i32, |_| Some(1));
getter!(glGetQueryObjectuiv, get_query_objectuiv, u32, |_| Some(1));

#[no_mangle]
pub unsafe extern "C" fn glSelectBuffer(size: i32, buffer: *mut u32) {
    with_gl("glSelectBuffer", |gl| {
        let before = gl.ctx.state().render_mode;
        gl.ctx.select_buffer(size);
        // Taken only when the command is (SELECT mode and a negative size are its errors).
        if before != gl::SELECT && size >= 0 {
            gl.select_out = (buffer as usize, size as usize);
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glFeedbackBuffer(size: i32, ty: u32, buffer: *mut f32) {
    with_gl("glFeedbackBuffer", |gl| {
        let before = gl.ctx.state().render_mode;
        gl.ctx.feedback_buffer(size, ty);
        if before != gl::FEEDBACK && size >= 0 {
            gl.feedback_out = (buffer as usize, size as usize);
        }
    })
}

/// `glRenderMode`: the context keeps the hit records and feedback values; when the mode ends
/// they are copied into the program's buffer (as many as it holds).
#[no_mangle]
pub unsafe extern "C" fn glRenderMode(mode: u32) -> i32 {
    with_gl("glRenderMode", |gl| {
        let before = gl.ctx.state().render_mode;
        let result = gl.ctx.render_mode(mode);
        if gl.ctx.state().render_mode == before && before != mode {
            return result; // refused: nothing ended
        }
        match before {
            gl::SELECT => {
                let (at, size) = gl.select_out;
                // SAFETY: the buffer SelectBuffer was given holds `size` values.
                let out = unsafe { read::slice_mut(at as *mut u32, size) };
                let src = gl.ctx.selection_buffer();
                let n = src.len().min(out.len());
                out[..n].copy_from_slice(&src[..n]);
            }
            gl::FEEDBACK => {
                let (at, size) = gl.feedback_out;
                // SAFETY: the buffer FeedbackBuffer was given holds `size` values.
                let out = unsafe { read::slice_mut(at as *mut f32, size) };
                let src = gl.ctx.feedback_values();
                let n = src.len().min(out.len());
                out[..n].copy_from_slice(&src[..n]);
            }
            _ => {}
        }
        result
    })
}

/// The values `glGetMap*v(target, query)` writes: the map's orders size COEFF.
fn map_count(gl: &mut crate::current::Gl, target: u32, query: u32) -> usize {
    let maps = &gl.ctx.state().eval_maps;
    let map = match target {
        gl::MAP1_COLOR_4..=gl::MAP1_VERTEX_4 => maps.map1.get((target - gl::MAP1_COLOR_4) as usize),
        gl::MAP2_COLOR_4..=gl::MAP2_VERTEX_4 => maps.map2.get((target - gl::MAP2_COLOR_4) as usize),
        _ => None,
    };
    map.and_then(|m| counts::get_map(target, query, m.uorder, m.vorder))
        .unwrap_or(0)
}

#[no_mangle]
pub unsafe extern "C" fn glGetMapfv(target: u32, query: u32, v: *mut f32) {
    with_gl("glGetMapfv", |gl| {
        let n = map_count(gl, target, query);
        // SAFETY: the query's values.
        unsafe { through(v, n, |v| gl.ctx.get_mapfv(target, query, v)) }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetMapdv(target: u32, query: u32, v: *mut f64) {
    with_gl("glGetMapdv", |gl| {
        let n = map_count(gl, target, query);
        // SAFETY: the query's values.
        unsafe { through(v, n, |v| gl.ctx.get_mapdv(target, query, v)) }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGetMapiv(target: u32, query: u32, v: *mut i32) {
    with_gl("glGetMapiv", |gl| {
        let n = map_count(gl, target, query);
        // SAFETY: the query's values.
        unsafe { through(v, n, |v| gl.ctx.get_mapiv(target, query, v)) }
    })
}

/// `glAreTexturesResident(n, textures, residences)`: the front end's answer (every texture is
/// resident, so `residences` is never written); the names read as `n` of them.
#[no_mangle]
pub unsafe extern "C" fn glAreTexturesResident(
    n: i32,
    textures: *const u32,
    residences: *mut u8,
) -> u8 {
    let _ = residences;
    with_gl("glAreTexturesResident", |gl| {
        // SAFETY: the caller's promise that `n` names live at `textures` (none read for NULL
        // or a negative n).
        let names = unsafe { read::names(textures, n) };
        u8::from(gl.ctx.are_textures_resident(n, &names, &mut []))
    })
}

/// `glAreTexturesResidentEXT`: [`glAreTexturesResident`].
#[no_mangle]
pub unsafe extern "C" fn glAreTexturesResidentEXT(
    n: i32,
    textures: *const u32,
    residences: *mut u8,
) -> u8 {
    // SAFETY: as glAreTexturesResident.
    unsafe { glAreTexturesResident(n, textures, residences) }
}

// GL_EXT_framebuffer_object (fixedgl's context/fbo.rs). The generator exports the GL 3.0
// names of the recorded commands and gl.xml's EXT aliases of them and of these; BindFramebuffer
// and BindRenderbuffer have no alias in gl.xml (the EXT ones take names never generated), so
// their EXT names are here: fixedgl's bindings take any name, as the extension's.

#[no_mangle]
pub unsafe extern "C" fn glIsFramebuffer(framebuffer: u32) -> u8 {
    with_gl("glIsFramebuffer", |gl| {
        u8::from(gl.ctx.is_framebuffer(framebuffer))
    })
}

#[no_mangle]
pub unsafe extern "C" fn glIsRenderbuffer(renderbuffer: u32) -> u8 {
    with_gl("glIsRenderbuffer", |gl| {
        u8::from(gl.ctx.is_renderbuffer(renderbuffer))
    })
}

#[no_mangle]
pub unsafe extern "C" fn glCheckFramebufferStatus(target: u32) -> u32 {
    with_gl("glCheckFramebufferStatus", |gl| {
        gl.ctx.check_framebuffer_status(target)
    })
}

getter!(
    glGetRenderbufferParameteriv,
    get_renderbuffer_parameteriv,
    i32,
    |_| Some(1)
);

#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameteriv(
    target: u32,
    attachment: u32,
    pname: u32,
    params: *mut i32,
) {
    with_gl("glGetFramebufferAttachmentParameteriv", |gl| {
        // SAFETY: every pname has one value.
        unsafe {
            through(params, 1, |v| {
                gl.ctx
                    .get_framebuffer_attachment_parameteriv(target, attachment, pname, v)
            })
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn glBindFramebufferEXT(target: u32, framebuffer: u32) {
    // SAFETY: no pointers.
    unsafe { crate::generated::glBindFramebuffer(target, framebuffer) }
}

#[no_mangle]
pub unsafe extern "C" fn glBindRenderbufferEXT(target: u32, renderbuffer: u32) {
    // SAFETY: no pointers.
    unsafe { crate::generated::glBindRenderbuffer(target, renderbuffer) }
}

#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffers(n: i32, ids: *mut u32) {
    with_gl("glGenFramebuffers", |gl| {
        // SAFETY: room for `n` names.
        let out = unsafe { read::slice_mut(ids, usize::try_from(n).unwrap_or(0)) };
        gl.ctx.gen_framebuffers(n, out);
    })
}

#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffers(n: i32, ids: *mut u32) {
    with_gl("glGenRenderbuffers", |gl| {
        // SAFETY: room for `n` names.
        let out = unsafe { read::slice_mut(ids, usize::try_from(n).unwrap_or(0)) };
        gl.ctx.gen_renderbuffers(n, out);
    })
}
