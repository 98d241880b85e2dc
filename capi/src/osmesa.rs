//! OSMesa (Mesa's off-screen API, removed from Mesa 25.1): contexts that render into a buffer
//! the caller owns. The frame is copied into that buffer at glFlush and glFinish (as Mesa's
//! gallium OSMesa did) and at `OSMesaMakeCurrent`, laid out as `OSMesaPixelStore` says
//! (ROW_LENGTH in pixels, Y_UP: row 0 at the bottom, the default).

use std::ffi::{c_char, c_void, CStr};

use fixedgl::{gl, Context};

use crate::current::{self, guard, Gl, Surface};
use crate::read;

const OSMESA_BGRA: u32 = 0x1;
const OSMESA_ARGB: u32 = 0x2;
const OSMESA_BGR: u32 = 0x4;
const OSMESA_RGB_565: u32 = 0x5;
const OSMESA_ROW_LENGTH: i32 = 0x10;
const OSMESA_Y_UP: i32 = 0x11;
const OSMESA_WIDTH: i32 = 0x20;
const OSMESA_HEIGHT: i32 = 0x21;
const OSMESA_FORMAT: i32 = 0x22;
const OSMESA_TYPE: i32 = 0x23;
const OSMESA_MAX_WIDTH: i32 = 0x24;
const OSMESA_MAX_HEIGHT: i32 = 0x25;
const OSMESA_DEPTH_BITS: i32 = 0x30;
const OSMESA_STENCIL_BITS: i32 = 0x31;
const OSMESA_ACCUM_BITS: i32 = 0x32;
const OSMESA_PROFILE: i32 = 0x33;
const OSMESA_CORE_PROFILE: i32 = 0x34;
const OSMESA_CONTEXT_MAJOR_VERSION: i32 = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: i32 = 0x37;
/// The largest buffer side (fixedgl's MAX_VIEWPORT_DIMS).
const MAX_SIDE: i32 = 16384;

/// The caller's colour buffer, as OSMesaMakeCurrent describes it.
#[derive(Clone, Copy, Debug)]
struct Buffer {
    address: usize,
    format: u32,
    ty: u32,
    width: u32,
    height: u32,
    /// Pixels between rows (OSMESA_ROW_LENGTH; 0: the width).
    row_length: u32,
    y_up: bool,
}

impl Buffer {
    fn bytes_per_pixel(&self) -> usize {
        match (self.format, self.ty) {
            (OSMESA_RGB_565, _) => 2,
            (gl::RGB | OSMESA_BGR, _) => 3,
            _ => 4,
        }
    }

    fn row_pixels(&self) -> usize {
        if self.row_length > 0 {
            self.row_length as usize
        } else {
            self.width as usize
        }
    }

    /// Copies the colour buffer into the caller's memory.
    fn write(&self, ctx: &mut Context) {
        let image = ctx.to_image();
        let (w, h) = (self.width as usize, self.height as usize);
        if image.width() as usize != w || image.height() as usize != h || self.address == 0 {
            return;
        }
        let bpp = self.bytes_per_pixel();
        let stride = self.row_pixels() * bpp;
        let len = stride * (h - 1) + w * bpp;
        // SAFETY: OSMesaMakeCurrent's contract: the buffer holds `height` rows of the row
        // length at the format's size, and stays valid while it is current.
        let out = unsafe { read::slice_mut(self.address as *mut u8, len) };
        if out.len() != len {
            return;
        }
        let src = image.as_raw();
        for row in 0..h {
            // `image` is top row first; Y_UP puts GL's bottom row first in memory.
            let src_row = if self.y_up { h - 1 - row } else { row };
            let s = &src[src_row * w * 4..(src_row + 1) * w * 4];
            let d = &mut out[row * stride..row * stride + w * bpp];
            for (px, o) in s.chunks_exact(4).zip(d.chunks_exact_mut(bpp)) {
                let [r, g, b, a] = [px[0], px[1], px[2], px[3]];
                match self.format {
                    OSMESA_BGRA => o.copy_from_slice(&[b, g, r, a]),
                    OSMESA_ARGB => o.copy_from_slice(&[a, r, g, b]),
                    OSMESA_BGR => o.copy_from_slice(&[b, g, r]),
                    gl::RGB => o.copy_from_slice(&[r, g, b]),
                    OSMESA_RGB_565 => {
                        // Each 8-bit value rounded to 5 or 6 bits, as Mesa's OSMesa stored a
                        // colour in its B5G6R5 buffer (round(c·31), round(c·63); measured with
                        // libOSMesa 8: a clear to (0.06, 0.5, 0.1) is 2, 32, 3, where taking the
                        // top bits of the 8-bit value gives 1, 32, 3).
                        let to = |v: u8, max: u32| ((u32::from(v) * max + 127) / 255) as u16;
                        let v = (to(r, 31) << 11) | (to(g, 63) << 5) | to(b, 31);
                        o.copy_from_slice(&v.to_ne_bytes());
                    }
                    _ => o.copy_from_slice(&[r, g, b, a]),
                }
            }
        }
    }
}

/// An OSMesa context's drawable: the caller's buffer, single-buffered.
struct OsSurface(Buffer);

impl Surface for OsSurface {
    fn size(&self) -> (u32, u32) {
        (self.0.width, self.0.height)
    }

    fn double_buffered(&self) -> bool {
        false
    }

    fn present(&mut self, ctx: &mut Context) {
        self.0.write(ctx);
    }
}

/// What each OSMesa context remembers beyond its `Gl` (the format asked for at creation and the
/// current buffer), keyed by handle.
#[derive(Clone, Copy, Debug)]
struct Osm {
    format: u32,
    buffer: Option<Buffer>,
    row_length: u32,
    y_up: bool,
}

static CONTEXTS: std::sync::Mutex<Vec<(usize, Osm)>> = std::sync::Mutex::new(Vec::new());

fn with_osm<R>(ctx: usize, f: impl FnOnce(&mut Osm) -> R) -> Option<R> {
    let mut all = CONTEXTS.lock().unwrap_or_else(|e| e.into_inner());
    all.iter_mut().find(|(k, _)| *k == ctx).map(|(_, o)| f(o))
}

fn create(format: u32, depth: i32, stencil: i32, accum: i32, share: *mut c_void) -> *mut c_void {
    // sharelist: an OSMesa context whose display lists, textures and buffer objects the new one
    // shares (GL appendix D); anything else is refused (NULL), as Mesa does.
    if !share.is_null() && with_osm(share as usize, |_| ()).is_none() {
        eprintln!("fixedgl: OSMesa sharelist is not an OSMesa context");
        return std::ptr::null_mut();
    }
    if !matches!(
        format,
        gl::RGBA | gl::RGB | OSMESA_BGRA | OSMESA_ARGB | OSMESA_BGR | OSMESA_RGB_565
    ) {
        eprintln!("fixedgl: OSMesa format {format:#x} is not supported (colour-index and unknown formats)");
        return std::ptr::null_mut();
    }
    if depth > 24 || stencil > 8 || accum > 16 {
        eprintln!("fixedgl: OSMesa asks for {depth} depth, {stencil} stencil, {accum} accumulation bits; fixedgl has 24, 8 and 16");
        return std::ptr::null_mut();
    }
    // The formats without alpha get a framebuffer without alpha bits (ALPHA_BITS 0, the
    // destination alpha reading 1), as Mesa's OSMesa gave them.
    let config = fixedgl::ContextConfig {
        alpha: !matches!(format, gl::RGB | OSMESA_BGR | OSMESA_RGB_565),
        ..fixedgl::ContextConfig::default()
    };
    let Some(gl) = Gl::with_config_shared(1, 1, config, share.cast()) else {
        return std::ptr::null_mut();
    };
    let p = current::register(gl);
    let osm = Osm {
        format,
        buffer: None,
        row_length: 0,
        y_up: true,
    };
    CONTEXTS
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push((p as usize, osm));
    p.cast()
}

#[no_mangle]
pub extern "C" fn OSMesaCreateContext(format: u32, share: *mut c_void) -> *mut c_void {
    guard("OSMesaCreateContext", std::ptr::null_mut(), || {
        create(format, 24, 8, 0, share)
    })
}

#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: u32,
    depth_bits: i32,
    stencil_bits: i32,
    accum_bits: i32,
    share: *mut c_void,
) -> *mut c_void {
    guard("OSMesaCreateContextExt", std::ptr::null_mut(), || {
        create(format, depth_bits, stencil_bits, accum_bits, share)
    })
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attribs: *const i32,
    share: *mut c_void,
) -> *mut c_void {
    guard("OSMesaCreateContextAttribs", std::ptr::null_mut(), || {
        let (mut format, mut depth, mut stencil, mut accum) = (gl::RGBA, 24, 8, 0);
        let (mut major, mut minor, mut core) = (1, 0, false);
        let mut i = 0;
        loop {
            // SAFETY: a zero-terminated list of pairs (the API's contract); NULL is empty.
            let pair = unsafe { read::array::<i32, 2>(attribs.wrapping_add(i)) };
            let Some([key, value]) = pair else { break };
            if key == 0 {
                break;
            }
            match key {
                OSMESA_FORMAT => format = value as u32,
                OSMESA_DEPTH_BITS => depth = value,
                OSMESA_STENCIL_BITS => stencil = value,
                OSMESA_ACCUM_BITS => accum = value,
                OSMESA_PROFILE => core = value == OSMESA_CORE_PROFILE,
                OSMESA_CONTEXT_MAJOR_VERSION => major = value,
                OSMESA_CONTEXT_MINOR_VERSION => minor = value,
                _ => {
                    eprintln!("fixedgl: OSMesaCreateContextAttribs: unknown attribute {key:#x}");
                    return std::ptr::null_mut();
                }
            }
            i += 2;
            if i > 64 {
                break;
            }
        }
        if core || (major, minor) > (1, 5) {
            eprintln!(
                "fixedgl: OSMesa asks for OpenGL {major}.{minor}{}; fixedgl is OpenGL 1.5 (compatibility)",
                if core { " core" } else { "" }
            );
            return std::ptr::null_mut();
        }
        create(format, depth, stencil, accum, share)
    })
}

#[no_mangle]
pub extern "C" fn OSMesaDestroyContext(ctx: *mut c_void) {
    guard("OSMesaDestroyContext", (), || {
        if current::destroy(ctx.cast()) {
            CONTEXTS
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .retain(|(k, _)| *k != ctx as usize);
        }
    })
}

#[no_mangle]
pub extern "C" fn OSMesaMakeCurrent(
    ctx: *mut c_void,
    buffer: *mut c_void,
    ty: u32,
    width: i32,
    height: i32,
) -> u8 {
    guard("OSMesaMakeCurrent", 0, || {
        if ctx.is_null() || buffer.is_null() {
            // Mesa: a NULL context or buffer is an error (use MakeCurrent(NULL...) to release).
            if ctx.is_null() {
                current::release_current();
            }
            return 0;
        }
        if !(1..=MAX_SIDE).contains(&width) || !(1..=MAX_SIDE).contains(&height) {
            return 0;
        }
        let Some(osm) = with_osm(ctx as usize, |o| *o) else {
            return 0;
        };
        let ok_type = match osm.format {
            OSMESA_RGB_565 => ty == gl::UNSIGNED_SHORT_5_6_5,
            _ => ty == gl::UNSIGNED_BYTE,
        };
        if !ok_type {
            eprintln!("fixedgl: OSMesaMakeCurrent: type {ty:#x} is not supported with format {:#x} (UNSIGNED_BYTE; UNSIGNED_SHORT_5_6_5 for RGB_565)", osm.format);
            return 0;
        }
        let b = Buffer {
            address: buffer as usize,
            format: osm.format,
            ty,
            width: width as u32,
            height: height as u32,
            row_length: osm.row_length,
            y_up: osm.y_up,
        };
        with_osm(ctx as usize, |o| o.buffer = Some(b));
        if current::make_current(ctx.cast(), Some(Box::new(OsSurface(b)))).is_err() {
            return 0;
        }
        1
    })
}

#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> *mut c_void {
    guard("OSMesaGetCurrentContext", std::ptr::null_mut(), || {
        let p = current::current();
        if with_osm(p as usize, |_| ()).is_some() {
            p.cast()
        } else {
            std::ptr::null_mut()
        }
    })
}

/// The current OSMesa context's buffer settings, changed by `f`, applied to its surface.
fn update_current(f: impl FnOnce(&mut Osm)) {
    let p = current::current();
    let Some(osm) = with_osm(p as usize, |o| {
        f(o);
        if let Some(b) = o.buffer.as_mut() {
            b.row_length = o.row_length;
            b.y_up = o.y_up;
        }
        *o
    }) else {
        return;
    };
    if let Some(b) = osm.buffer {
        // SAFETY: `p` is the thread's current context (checked by `with_osm` finding it).
        let gl = unsafe { &mut *p };
        gl.surface = Some(Box::new(OsSurface(b)));
    }
}

#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: i32, value: i32) {
    guard("OSMesaPixelStore", (), || match pname {
        OSMESA_ROW_LENGTH if value >= 0 => update_current(|o| o.row_length = value as u32),
        OSMESA_Y_UP => update_current(|o| o.y_up = value != 0),
        _ => eprintln!("fixedgl: OSMesaPixelStore({pname:#x}, {value}) is not a valid setting"),
    })
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: i32, value: *mut i32) {
    guard("OSMesaGetIntegerv", (), || {
        let p = current::current();
        let osm = with_osm(p as usize, |o| *o);
        let b = osm.and_then(|o| o.buffer);
        let v = match pname {
            OSMESA_WIDTH => b.map_or(0, |b| b.width as i32),
            OSMESA_HEIGHT => b.map_or(0, |b| b.height as i32),
            OSMESA_FORMAT => osm.map_or(0, |o| o.format as i32),
            OSMESA_TYPE => b.map_or(0, |b| b.ty as i32),
            OSMESA_ROW_LENGTH => osm.map_or(0, |o| o.row_length as i32),
            OSMESA_Y_UP => osm.map_or(1, |o| i32::from(o.y_up)),
            OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => MAX_SIDE,
            _ => return,
        };
        // SAFETY: one value.
        if let Some(slot) = unsafe { read::slice_mut(value, 1) }.first_mut() {
            *slot = v;
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    ctx: *mut c_void,
    width: *mut i32,
    height: *mut i32,
    format: *mut i32,
    buffer: *mut *mut c_void,
) -> u8 {
    guard("OSMesaGetColorBuffer", 0, || {
        let Some(Some(b)) = with_osm(ctx as usize, |o| o.buffer) else {
            return 0;
        };
        // SAFETY: one value each, where the caller gave a pointer.
        unsafe {
            for (p, v) in [
                (width, b.width as i32),
                (height, b.height as i32),
                (format, b.format as i32),
            ] {
                if let Some(s) = read::slice_mut(p, 1).first_mut() {
                    *s = v;
                }
            }
            if let Some(s) = read::slice_mut(buffer, 1).first_mut() {
                *s = b.address as *mut c_void;
            }
        }
        1
    })
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    ctx: *mut c_void,
    width: *mut i32,
    height: *mut i32,
    bytes_per_value: *mut i32,
    buffer: *mut *mut c_void,
) -> u8 {
    guard("OSMesaGetDepthBuffer", 0, || {
        // The depth buffer is fixedgl's own (tile-major, not a plain array a caller could
        // read), so there is none to hand out; Mesa answers the same for contexts without one.
        let _ = ctx;
        // SAFETY: one value each, where the caller gave a pointer.
        unsafe {
            for p in [width, height, bytes_per_value] {
                if let Some(s) = read::slice_mut(p, 1).first_mut() {
                    *s = 0;
                }
            }
            if let Some(s) = read::slice_mut(buffer, 1).first_mut() {
                *s = std::ptr::null_mut();
            }
        }
        0
    })
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(name: *const c_char) -> *const c_void {
    guard("OSMesaGetProcAddress", std::ptr::null(), || {
        if name.is_null() {
            return std::ptr::null();
        }
        // SAFETY: a NUL-terminated name (the API's contract).
        let name = unsafe { CStr::from_ptr(name) }.to_bytes();
        let f: *const c_void = match name {
            b"OSMesaCreateContext" => OSMesaCreateContext as *const c_void,
            b"OSMesaCreateContextExt" => OSMesaCreateContextExt as *const c_void,
            b"OSMesaCreateContextAttribs" => OSMesaCreateContextAttribs as *const c_void,
            b"OSMesaDestroyContext" => OSMesaDestroyContext as *const c_void,
            b"OSMesaMakeCurrent" => OSMesaMakeCurrent as *const c_void,
            b"OSMesaGetCurrentContext" => OSMesaGetCurrentContext as *const c_void,
            b"OSMesaPixelStore" => OSMesaPixelStore as *const c_void,
            b"OSMesaGetIntegerv" => OSMesaGetIntegerv as *const c_void,
            b"OSMesaGetColorBuffer" => OSMesaGetColorBuffer as *const c_void,
            b"OSMesaGetDepthBuffer" => OSMesaGetDepthBuffer as *const c_void,
            b"OSMesaGetProcAddress" => OSMesaGetProcAddress as *const c_void,
            _ => return crate::proc_address(name).unwrap_or(std::ptr::null()),
        };
        f
    })
}
