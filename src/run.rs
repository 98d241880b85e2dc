//! `fixedgl run` and `fixedgl env` (part of the binary, not the library): unmodified C and
//! Python programs on fixedgl through the C ABI library (`capi/`, built next to the binary as
//! `libfixedgl_capi.so` by `cargo build --release`).
//!
//! The drop-in directory `fixedgl-dropin/` beside the library holds the names programs load —
//! `libGL.so.1` (GL and GLX), `libEGL.so.1`, `libOpenGL.so.0` (what libGLU links) and
//! `libOSMesa.so.8` — as symlinks to the one library, so the dynamic loader maps it once and
//! there is one current context per thread whichever name a call came through. `run` puts that
//! directory first on `LD_LIBRARY_PATH` and starts the program; with `--record FILE` the library
//! writes each context's calls with a marker per presented frame, and with `--compare DIR` every
//! presented frame is replayed on the driver and compared, in `DIR/index.html`.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use image::RgbaImage;

use fixedgl::compare::compare;
use fixedgl::report::{self, Renderers, SceneResult};
use fixedgl::scenes::Tolerance;
use fixedgl::{Call, Error};

use crate::CliError;

/// The names the dynamic loader looks for, all pointing at the one library: the sonames
/// programs are linked against, and the unversioned names that loaders opening libraries by hand
/// try first (PyOpenGL opens `libOSMesa.so` before `libOSMesa.so.8`).
const DROP_IN_NAMES: [&str; 8] = [
    "libGL.so.1",
    "libEGL.so.1",
    "libOpenGL.so.0",
    "libOSMesa.so.8",
    "libGL.so",
    "libEGL.so",
    "libOpenGL.so",
    "libOSMesa.so",
];
const LIBRARY: &str = "libfixedgl_capi.so";
/// A frame passes when at most this share of its pixels differ by more than 2/255 (the
/// lecture scenes' tolerance).
const FRAME_TOLERANCE: Tolerance = Tolerance {
    channel: 2,
    max_percent: 0.05,
};

/// The drop-in directory, made (or refreshed) beside the library next to this executable.
pub fn drop_in_dir() -> Result<PathBuf, CliError> {
    let exe = std::env::current_exe().map_err(|e| CliError::Fixedgl(e.into()))?;
    let dir = exe.parent().unwrap_or(Path::new(".")).to_path_buf();
    let lib = dir.join(LIBRARY);
    if !lib.exists() {
        return Err(CliError::Usage(format!(
            "the C ABI library {} is not built: run `cargo build --release` (it builds the \
             `fixedgl-capi` workspace member next to this binary)",
            lib.display()
        )));
    }
    let dropin = dir.join("fixedgl-dropin");
    std::fs::create_dir_all(&dropin).map_err(|e| CliError::Fixedgl(e.into()))?;
    for name in DROP_IN_NAMES {
        let link = dropin.join(name);
        let target = Path::new("..").join(LIBRARY);
        if std::fs::read_link(&link).ok().as_deref() != Some(target.as_path()) {
            let _ = std::fs::remove_file(&link);
            std::os::unix::fs::symlink(&target, &link).map_err(|e| {
                CliError::Fixedgl(Error::Backend(format!(
                    "cannot link {}: {e}",
                    link.display()
                )))
            })?;
        }
    }
    Ok(dropin)
}

/// `LD_LIBRARY_PATH` with `dir` first, keeping what was there.
fn library_path(dir: &Path) -> OsString {
    let mut v = dir.as_os_str().to_os_string();
    if let Some(old) = std::env::var_os("LD_LIBRARY_PATH").filter(|o| !o.is_empty()) {
        v.push(":");
        v.push(old);
    }
    v
}

/// `fixedgl env`: the line a shell evaluates to run programs on fixedgl.
pub fn env() -> Result<ExitCode, CliError> {
    let dir = drop_in_dir()?;
    out!(
        "export LD_LIBRARY_PATH={}",
        shell_quote(&library_path(&dir).to_string_lossy())
    );
    Ok(ExitCode::SUCCESS)
}

fn shell_quote(s: &str) -> String {
    if s.chars()
        .all(|c| c.is_ascii_alphanumeric() || "/._-:+=,".contains(c))
    {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// `fixedgl run [--record FILE] [--compare DIR] -- PROGRAM [ARGS...]`.
pub fn run(
    program: &[OsString],
    record: Option<&Path>,
    compare_dir: Option<&Path>,
    device: &str,
) -> Result<ExitCode, CliError> {
    let (prog, args) = program
        .split_first()
        .ok_or_else(|| CliError::Usage("name the program to run after `--`".into()))?;
    let dropin = drop_in_dir()?;
    let mut cmd = std::process::Command::new(prog);
    cmd.args(args).env("LD_LIBRARY_PATH", library_path(&dropin));
    let mut recording = record.map(Path::to_path_buf);
    let mut frames = None;
    if let Some(dir) = compare_dir {
        std::fs::create_dir_all(dir).map_err(|e| CliError::Fixedgl(e.into()))?;
        let calls = recording
            .get_or_insert_with(|| dir.join("calls.txt"))
            .clone();
        let f = dir.join("frames");
        // Frames of an earlier run must not be mistaken for this one's.
        let _ = std::fs::remove_dir_all(&f);
        remove_recordings(&calls);
        frames = Some(f);
    }
    if let Some(r) = &recording {
        cmd.env("FIXEDGL_RECORD", r);
    }
    if let Some(f) = &frames {
        cmd.env("FIXEDGL_FRAMES_DIR", f);
    }
    let status = cmd
        .status()
        .map_err(|e| CliError::Usage(format!("cannot run {}: {e}", Path::new(prog).display())))?;
    let mut code = match status.code() {
        Some(0) => ExitCode::SUCCESS,
        Some(c) => {
            eprintln!(
                "fixedgl: {} exited with status {c}",
                Path::new(prog).display()
            );
            ExitCode::from(u8::try_from(c).unwrap_or(1))
        }
        None => {
            eprintln!(
                "fixedgl: {} was killed by a signal ({status})",
                Path::new(prog).display()
            );
            ExitCode::FAILURE
        }
    };
    if let (Some(dir), Some(calls), Some(frames)) = (compare_dir, &recording, &frames) {
        let title = program
            .iter()
            .map(|a| a.to_string_lossy())
            .collect::<Vec<_>>()
            .join(" ");
        if !compare_frames(dir, calls, frames, &title, device)? {
            code = ExitCode::FAILURE;
        }
    }
    Ok(code)
}

/// The recording files of one run: FILE, FILE.2, FILE.3, ... (one per context).
fn recordings(first: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for n in 1.. {
        let path = if n == 1 {
            first.to_path_buf()
        } else {
            let mut name = first.file_name().unwrap_or_default().to_os_string();
            name.push(format!(".{n}"));
            first.with_file_name(name)
        };
        if !path.exists() {
            break;
        }
        out.push(path);
    }
    out
}

fn remove_recordings(first: &Path) {
    for p in recordings(first) {
        let _ = std::fs::remove_file(p);
    }
}

/// One presented frame of a recording: the calls since the previous frame and the size.
struct Frame {
    number: usize,
    size: (u32, u32),
    calls: Vec<Call>,
}

/// Splits a `run --record` file at its `# frame N WxH` markers (calls after the last marker
/// were never presented and are dropped).
fn frames_of(path: &Path) -> Result<Vec<Frame>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?;
    let mut out = Vec::new();
    let mut chunk = String::new();
    let mut first_line = 1;
    for (i, line) in text.lines().enumerate() {
        if let Some(rest) = line.strip_prefix("# frame ") {
            let mut words = rest.split_whitespace();
            let number = words.next().and_then(|n| n.parse().ok());
            let size = words.next().and_then(|s| crate::parse_size(s).ok());
            let (Some(number), Some(size)) = (number, size) else {
                return Err(CliError::Input(format!(
                    "{}:{}: a frame marker is `# frame N WxH`",
                    path.display(),
                    i + 1
                )));
            };
            let calls = fixedgl::recording::read_recording(chunk.as_bytes()).map_err(|e| {
                CliError::Input(format!("{}: from line {first_line}: {e}", path.display()))
            })?;
            out.push(Frame {
                number,
                size,
                calls,
            });
            chunk.clear();
            first_line = i + 2;
        } else {
            chunk.push_str(line);
            chunk.push('\n');
        }
    }
    Ok(out)
}

/// Replays every recorded frame on the driver, compares it with the frame the program showed,
/// and writes the report; whether every frame is within tolerance.
fn compare_frames(
    dir: &Path,
    calls: &Path,
    frames_dir: &Path,
    title: &str,
    device: &str,
) -> Result<bool, CliError> {
    let mut results = Vec::new();
    let mut renderers = Renderers {
        cpu: format!("fixedgl {} (C ABI)", env!("CARGO_PKG_VERSION")),
        ..Renderers::default()
    };
    for (k, path) in recordings(calls).iter().enumerate() {
        let context = k + 1;
        let frames = frames_of(path)?;
        let mut replayer = crate::gl_side::Replayer::default();
        for f in &frames {
            let shown = frames_dir.join(format!("ctx{context}-frame{:04}.png", f.number));
            let cpu: RgbaImage = match image::open(&shown) {
                Ok(img) => img.to_rgba8(),
                Err(e) => {
                    eprintln!("fixedgl: {}: {e}; frame skipped", shown.display());
                    continue;
                }
            };
            let (gl, info) = replayer.frame(f.size, &f.calls, device)?;
            renderers.gl = info.0;
            renderers.gl_version = info.1;
            let comparison = compare(&cpu, &gl, FRAME_TOLERANCE.channel);
            out!(
                "context {context} frame {:>4} {}x{}: {:.3}% pixels off (max {:?})",
                f.number,
                f.size.0,
                f.size.1,
                comparison.differing_percent,
                comparison.max_diff
            );
            results.push(SceneResult {
                name: format!("ctx{context}-frame{:04}", f.number),
                summary: format!("{title}: context {context}, frame {}", f.number),
                tolerance: FRAME_TOLERANCE,
                comparison,
                cpu,
                gl,
                cpu_ms: None,
                gl_ms: None,
            });
        }
    }
    if results.is_empty() {
        eprintln!("fixedgl: the program presented no frame (no SwapBuffers, no glFlush/glFinish of a single-buffered drawable, no eglSwapBuffers)");
        return Ok(false);
    }
    let index = report::write(dir, &renderers, &results)?;
    let failed = results.iter().filter(|r| !r.passed()).count();
    out!(
        "{} frames, {failed} over tolerance; report: {}",
        results.len(),
        index.display()
    );
    Ok(failed == 0)
}

/// Nanoseconds a call through the C ABI costs, measured as [`crate::api_call_ns`] measures the
/// Rust API: the library beside this binary opened with `dlopen`, an OSMesa context (RGBA,
/// 64x64, the library's own memory) made current, then five runs of 100k `glColor3f` +
/// `glVertex3f` pairs inside `glBegin(GL_POINTS)`/`glEnd`, every point clipped, up to
/// `glFinish`; the median. `Err` says why it could not be measured (library not built, a
/// symbol missing, no context).
pub fn capi_call_ns() -> Result<f64, String> {
    type Begin = unsafe extern "C" fn(u32);
    type Color3f = unsafe extern "C" fn(f32, f32, f32);
    type Vertex3f = unsafe extern "C" fn(f32, f32, f32);
    type NoArgs = unsafe extern "C" fn();
    type Create = unsafe extern "C" fn(u32, *mut std::ffi::c_void) -> *mut std::ffi::c_void;
    type MakeCurrent =
        unsafe extern "C" fn(*mut std::ffi::c_void, *mut std::ffi::c_void, u32, i32, i32) -> u8;
    type Destroy = unsafe extern "C" fn(*mut std::ffi::c_void);
    const PAIRS: u32 = 100_000;
    const SIDE: i32 = 64;
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let lib_path = exe.parent().unwrap_or(Path::new(".")).join(LIBRARY);
    if !lib_path.exists() {
        return Err(format!(
            "{} is not built (`cargo build --release` builds it)",
            lib_path.display()
        ));
    }
    // SAFETY: the library is this workspace's C ABI, whose initialisers only set up its own
    // statics; every symbol below is looked up with the signature it is exported with
    // (capi/src/generated.rs, capi/src/osmesa.rs), and the context is made current on this
    // thread with a buffer that outlives every call, then destroyed before the library closes.
    unsafe {
        let lib = libloading::Library::new(&lib_path).map_err(|e| e.to_string())?;
        fn sym<'l, T>(
            lib: &'l libloading::Library,
            name: &str,
        ) -> Result<libloading::Symbol<'l, T>, String> {
            // SAFETY: the caller names the type the symbol is exported with.
            unsafe { lib.get(name.as_bytes()) }.map_err(|e| format!("{name}: {e}"))
        }
        let create: libloading::Symbol<Create> = sym(&lib, "OSMesaCreateContext")?;
        let make_current: libloading::Symbol<MakeCurrent> = sym(&lib, "OSMesaMakeCurrent")?;
        let destroy: libloading::Symbol<Destroy> = sym(&lib, "OSMesaDestroyContext")?;
        let begin: libloading::Symbol<Begin> = sym(&lib, "glBegin")?;
        let color3f: libloading::Symbol<Color3f> = sym(&lib, "glColor3f")?;
        let vertex3f: libloading::Symbol<Vertex3f> = sym(&lib, "glVertex3f")?;
        let end: libloading::Symbol<NoArgs> = sym(&lib, "glEnd")?;
        let finish: libloading::Symbol<NoArgs> = sym(&lib, "glFinish")?;
        let ctx = create(fixedgl::gl::RGBA, std::ptr::null_mut());
        if ctx.is_null() {
            return Err("OSMesaCreateContext failed".into());
        }
        let mut buffer = vec![0u8; (SIDE * SIDE * 4) as usize];
        if make_current(
            ctx,
            buffer.as_mut_ptr().cast(),
            fixedgl::gl::UNSIGNED_BYTE,
            SIDE,
            SIDE,
        ) == 0
        {
            destroy(ctx);
            return Err("OSMesaMakeCurrent failed".into());
        }
        let mut runs: Vec<f64> = (0..5)
            .map(|_| {
                let start = std::time::Instant::now();
                begin(fixedgl::gl::POINTS);
                for i in 0..PAIRS {
                    let f = i as f32 * 1e-6;
                    color3f(f, 0.5, 0.25);
                    vertex3f(2.0 + f, 0.0, 0.0);
                }
                end();
                finish();
                start.elapsed().as_secs_f64() * 1e9 / f64::from(2 * PAIRS)
            })
            .collect();
        destroy(ctx);
        drop(buffer);
        Ok(crate::median_ms(&mut runs))
    }
}
