//! `fixedgl`: list, render, compare and benchmark the registered scenes on the CPU pipeline and
//! on a real GL driver, and replay recording files.
//!
//! Exit status: 0 on success; 1 when a command fails doing its work (a GL backend that cannot
//! start, a PNG that cannot be written, `compare` over tolerance); 2 for input the user must fix,
//! as clap does for a bad command line: an unknown scene, or a recording that cannot be read
//! (`<file>: cannot read: <reason>`) or is malformed (`<file>:<line>:<col>: <message>`, one
//! line on stderr, like a compiler's diagnostic, so editors can jump to it).
//!
//! Design decision: every GL-side step goes through the small `gl_side` module, which is the real
//! backend with the `gl` feature and a clear "built without GL" error without it, so the rest of
//! the CLI is the same in both builds.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, Subcommand, ValueEnum};

/// Writes to standard output. A closed pipe (`fixedgl bench | head`) ends the program quietly
/// with status 141, what a program killed by SIGPIPE reports to the shell, where `print!`
/// would panic; another write error is reported and ends it with status 1.
fn emit(args: std::fmt::Arguments) {
    use std::io::Write as _;
    if let Err(e) = std::io::stdout().write_fmt(args) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(141);
        }
        eprintln!("fixedgl: cannot write to standard output: {e}");
        std::process::exit(1);
    }
}

/// `println!` through [`emit`].
macro_rules! out {
    () => {
        $crate::emit(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::emit(format_args!("{}\n", format_args!($($arg)*)))
    };
}

mod run;
use image::RgbaImage;
use sha2::Digest;

use fixedgl::compare::compare;
use fixedgl::report::{self, Renderers, SceneResult};
use fixedgl::scenes::{self, Scene};
use fixedgl::{Call, Context, ContextConfig, Error};

/// The OpenGL 1.x fixed-function pipeline on the CPU, compared with a real driver.
#[derive(Parser, Debug)]
#[command(name = "fixedgl", version, about)]
struct Cli {
    /// EGL device for the GL backend: `auto` (Mesa's software device if present), an index, or a
    /// name substring (see `fixedgl list`).
    #[arg(long, global = true, default_value = "auto")]
    device: String,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// List the scenes (and the EGL devices, with the `gl` feature).
    List,
    /// Render one scene to a PNG.
    Render {
        /// Scene name.
        scene: String,
        /// Which pipeline renders it.
        #[arg(long, value_enum, default_value_t = Backend::Cpu)]
        backend: Backend,
        /// Framebuffer size WxH (default: the scene's).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        /// Output file (default: <scene>-<backend>.png).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Write no file: print the SHA-256 of the image's RGBA8 bytes (top row first) and the
        /// scene's name, as `sha256sum` would print them; SCENE may be `all`. A regression
        /// check for work that must not change a pixel (speed work: hash before, hash after),
        /// never a test of correctness, which is the comparison with the driver.
        #[arg(long, conflicts_with = "output")]
        hash: bool,
    },
    /// Render scenes on both pipelines, print the metrics and write an HTML report; exits
    /// non-zero if a scene exceeds its tolerance.
    Compare {
        /// Scene names, or `all`.
        #[arg(required = true)]
        scenes: Vec<String>,
        /// Framebuffer size WxH for every scene (default: each scene's).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        /// Report folder (index.html, a page per scene, results.json, the PNGs).
        #[arg(long, default_value = "report")]
        out: PathBuf,
        /// Print results.json to stdout (the per-scene lines then go to stderr).
        #[arg(long)]
        json: bool,
        /// Also write the results as JUnit XML to this file, for CI systems.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
    },
    /// Median milliseconds per frame on the CPU and GL pipelines, measured interleaved: a frame
    /// is the scene's calls replayed from the initial state up to the return of glFinish, on
    /// both sides (no readback).
    Bench {
        /// Scene names (default: all).
        scenes: Vec<String>,
        /// Framebuffer size WxH (default: each scene's).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        /// Frames measured per backend (after one warm-up frame).
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u32).range(1..=100_000))]
        frames: u32,
        /// Threads of the CPU backend's pool (default: one per core).
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
        threads: Option<u32>,
        /// Print the results as one JSON object instead of the table.
        #[arg(long)]
        json: bool,
        /// Measure the CPU pipeline only (no driver frames; the gl columns are empty): for
        /// profiling and for `perf stat`, whose counts then are the CPU side's alone.
        #[arg(long)]
        cpu_only: bool,
        /// Time the CPU frame stage by stage instead (CPU only, no API timing): reset, replay
        /// (the front end and the draws it starts), glFinish (the final flush and the
        /// rasterisation of what is pending), then the readback (`to_image`, after the frame and
        /// not part of it), the draws, their time on the calling thread, its waits for the
        /// pool, how many of the draws were handed to the pool, and the rasterisation passes.
        #[arg(long)]
        stages: bool,
    },
    /// Run a C or Python program unmodified on fixedgl: its libGL, libEGL, libOpenGL and
    /// libOSMesa are fixedgl's C ABI library (see docs/c-abi.md).
    Run {
        /// Save every context's calls, with a marker at each presented frame (FILE, FILE.2, ...
        /// for the first, second, ... context).
        #[arg(long, value_name = "FILE")]
        record: Option<PathBuf>,
        /// Replay every presented frame on the real driver and write DIR/index.html comparing
        /// it with what fixedgl showed; exits non-zero when a frame is over tolerance.
        #[arg(long, value_name = "DIR")]
        compare: Option<PathBuf>,
        /// The program and its arguments, after `--`.
        #[arg(last = true, required = true, value_name = "PROGRAM")]
        program: Vec<std::ffi::OsString>,
    },
    /// Print the `export LD_LIBRARY_PATH=...` line that makes programs started from a shell use
    /// fixedgl (`eval "$(fixedgl env)"`).
    Env,
    /// Show scenes in a window, animated where the scene moves; with --compare, the CPU
    /// rendering, the driver's and their difference side by side, live. Press H in the window for
    /// the keys.
    View {
        /// Scene names, or `all` (N / P switch between them).
        #[arg(required = true)]
        scenes: Vec<String>,
        /// Show CPU | GL | difference (keys 1 2 3 0 choose, Space flips CPU and GL, + and -
        /// change the difference amplification).
        #[arg(long)]
        compare: bool,
        /// Size WxH each scene is rendered at (default: the scene's; with --compare scaled to fit
        /// three across).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        /// Frames a second for animated scenes (default 60).
        #[arg(long, value_parser = parse_fps)]
        fps: Option<f64>,
        /// Present N frames of each scene, then exit.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
        frames: Option<u64>,
        /// Write every presented frame to DIR as frame-00000.png, frame-00001.png, ...
        #[arg(long, value_name = "DIR")]
        record_frames: Option<PathBuf>,
    },
    /// Replay a recording file on one pipeline and write the image.
    Replay {
        /// The recording.
        file: PathBuf,
        /// Which pipeline replays it.
        #[arg(long, value_enum, default_value_t = Backend::Cpu)]
        backend: Backend,
        /// Framebuffer size WxH.
        #[arg(long, value_parser = parse_size, default_value = "256x256")]
        size: (u32, u32),
        /// Output file (default: <file stem>-<backend>.png).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Backend {
    /// fixedgl's CPU pipeline.
    Cpu,
    /// The real driver through EGL.
    Gl,
}

impl Backend {
    fn name(self) -> &'static str {
        match self {
            Backend::Cpu => "cpu",
            Backend::Gl => "gl",
        }
    }
}

/// `WxH` with both sides in 1..=16384.
pub(crate) fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("size must be WxH, e.g. 256x256, not {s:?}"))?;
    let side = |v: &str| -> Result<u32, String> {
        match v.trim().parse::<u32>() {
            Ok(n) if (1..=fixedgl::state::MAX_VIEWPORT_DIM).contains(&n) => Ok(n),
            _ => Err(format!(
                "each side must be 1..={}, got {v:?}",
                fixedgl::state::MAX_VIEWPORT_DIM
            )),
        }
    };
    Ok((side(w)?, side(h)?))
}

/// A frame rate in (0, 1000].
fn parse_fps(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(f) if f > 0.0 && f <= 1000.0 => Ok(f),
        _ => Err(format!("frames a second must be in (0, 1000], got {s:?}")),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let device = cli.device.as_str();
    let result = match cli.command {
        Command::List => list(),
        Command::Render {
            scene,
            backend,
            size,
            output,
            hash,
        } => match hash {
            true => render_hashes(&scene, backend, size, device),
            false => render(&scene, backend, size, output, device),
        },
        Command::Compare {
            scenes,
            size,
            out,
            json,
            junit,
        } => compare_scenes(&scenes, size, &out, json, junit.as_deref(), device),
        Command::Bench {
            scenes,
            size,
            frames,
            threads,
            json: _,
            cpu_only: _,
            stages: true,
        } => bench_stages(&scenes, size, frames, threads),
        Command::Bench {
            scenes,
            size,
            frames,
            threads,
            json,
            cpu_only,
            stages: false,
        } => bench(&scenes, size, frames, threads, json, cpu_only, device),
        Command::View {
            scenes,
            compare,
            size,
            fps,
            frames,
            record_frames,
        } => select(&scenes, false).and_then(|selected| {
            view(&selected, compare, size, fps, frames, record_frames, device)
        }),
        Command::Replay {
            file,
            backend,
            size,
            output,
        } => replay(&file, backend, size, output, device),
        Command::Run {
            record,
            compare,
            program,
        } => run::run(&program, record.as_deref(), compare.as_deref(), device),
        Command::Env => run::env(),
    };
    match result {
        Ok(code) => code,
        Err(CliError::Input(m)) => {
            eprintln!("{m}");
            ExitCode::from(2)
        }
        Err(e @ CliError::Usage(_)) => {
            eprintln!("fixedgl: {e}");
            ExitCode::from(2)
        }
        Err(e) => {
            eprintln!("fixedgl: {e}");
            ExitCode::FAILURE
        }
    }
}

fn list() -> Result<ExitCode, CliError> {
    for s in scenes::scenes() {
        let (w, h) = s.default_size;
        out!("{:<20} {w}x{h}  {}", s.name, s.summary);
    }
    match gl_side::devices() {
        Ok(devices) if devices.is_empty() => out!("\nEGL devices: none"),
        Ok(devices) => {
            out!("\nEGL devices (--device):");
            for d in devices {
                out!("  {d}");
            }
        }
        Err(e) => out!("\nEGL devices: unavailable ({e})"),
    }
    Ok(ExitCode::SUCCESS)
}

/// What a command can fail with: a fixedgl error, a bad command line, or an input file that
/// cannot be used (the message is the whole diagnostic line, file name first).
#[derive(Debug)]
pub(crate) enum CliError {
    Fixedgl(Error),
    Usage(String),
    Input(String),
}

impl std::fmt::Display for CliError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CliError::Fixedgl(e) => e.fmt(f),
            CliError::Usage(m) | CliError::Input(m) => f.write_str(m),
        }
    }
}

impl From<Error> for CliError {
    fn from(e: Error) -> Self {
        CliError::Fixedgl(e)
    }
}

impl From<image::ImageError> for CliError {
    fn from(e: image::ImageError) -> Self {
        CliError::Fixedgl(e.into())
    }
}

fn find_scene(name: &str) -> Result<&'static Scene, CliError> {
    scenes::find(name).ok_or_else(|| {
        let names: Vec<&str> = scenes::scenes().iter().map(|s| s.name).collect();
        CliError::Usage(format!(
            "no scene {name:?}; scenes: {} (see `fixedgl list`)",
            names.join(", ")
        ))
    })
}

/// The scenes named on the command line (`all` = every scene; empty = every scene if
/// `empty_means_all`).
fn select(names: &[String], empty_means_all: bool) -> Result<Vec<&'static Scene>, CliError> {
    if (names.is_empty() && empty_means_all) || names.iter().any(|n| n == "all") {
        return Ok(scenes::scenes().iter().collect());
    }
    names.iter().map(|n| find_scene(n)).collect()
}

fn render(
    name: &str,
    backend: Backend,
    size: Option<(u32, u32)>,
    output: Option<PathBuf>,
    device: &str,
) -> Result<ExitCode, CliError> {
    let scene = find_scene(name)?;
    let (w, h) = size.unwrap_or(scene.default_size);
    let (mut ctx, calls) = scene.record(w, h)?;
    let img = match backend {
        Backend::Cpu => ctx.to_image(),
        Backend::Gl => gl_side::render(&calls, w, h, scene.config, device)?.0,
    };
    let out = output.unwrap_or_else(|| PathBuf::from(format!("{name}-{}.png", backend.name())));
    img.save(&out)?;
    out!("{}", out.display());
    Ok(ExitCode::SUCCESS)
}

/// `render --hash`: each selected scene's image hashed (see `Command::Render::hash`).
fn render_hashes(
    name: &str,
    backend: Backend,
    size: Option<(u32, u32)>,
    device: &str,
) -> Result<ExitCode, CliError> {
    for scene in select(&[name.to_owned()], false)? {
        let (w, h) = size.unwrap_or(scene.default_size);
        let (mut ctx, calls) = scene.record(w, h)?;
        let img = match backend {
            Backend::Cpu => ctx.to_image(),
            Backend::Gl => gl_side::render(&calls, w, h, scene.config, device)?.0,
        };
        out!("{:x}  {}", sha2::Sha256::digest(img.as_raw()), scene.name);
    }
    Ok(ExitCode::SUCCESS)
}

fn compare_scenes(
    names: &[String],
    size: Option<(u32, u32)>,
    out: &Path,
    json: bool,
    junit: Option<&Path>,
    device: &str,
) -> Result<ExitCode, CliError> {
    let selected = select(names, false)?;
    let mut results = Vec::new();
    let mut renderers = Renderers {
        cpu: format!("fixedgl {} (CPU)", env!("CARGO_PKG_VERSION")),
        ..Renderers::default()
    };
    let progress = selected.len() > 3;
    for (i, scene) in selected.iter().enumerate() {
        if progress {
            eprintln!("[{}/{}] {}", i + 1, selected.len(), scene.name);
        }
        let (w, h) = size.unwrap_or(scene.default_size);
        // One frame each, for the report's ms columns (the CPU figure includes recording the
        // calls; `fixedgl bench` measures properly).
        let start = Instant::now();
        let (mut ctx, calls) = scene.record(w, h)?;
        let cpu = ctx.to_image();
        let cpu_ms = start.elapsed().as_secs_f64() * 1e3;
        let (gl, info, gl_ms) = gl_side::render_timed(&calls, w, h, scene.config, device)?;
        renderers.gl = info.0;
        renderers.gl_version = info.1;
        let comparison = compare(&cpu, &gl, scene.tolerance.channel);
        let result = SceneResult {
            name: scene.name.to_owned(),
            summary: scene.summary.to_owned(),
            tolerance: scene.tolerance,
            comparison,
            cpu,
            gl,
            cpu_ms: Some(cpu_ms),
            gl_ms: Some(gl_ms),
        };
        let line = format!(
            "{:<20} {} {}",
            scene.name,
            if result.passed() { "PASS" } else { "FAIL" },
            result.comparison
        );
        if json {
            eprintln!("{line}");
        } else {
            out!("{line}");
        }
        results.push(result);
    }
    let index = report::write(out, &renderers, &results)?;
    if let Some(file) = junit {
        std::fs::write(file, report::junit(&renderers, &results)).map_err(Error::from)?;
    }
    if json {
        emit(format_args!(
            "{}",
            report::results_json(&renderers, &results)?
        ));
        eprintln!("report: {}", index.display());
    } else {
        out!("report: {}", index.display());
    }
    let failed = results.iter().filter(|r| !r.passed()).count();
    if failed > 0 {
        eprintln!(
            "{failed} of {} scenes exceed their tolerance",
            results.len()
        );
        return Ok(ExitCode::FAILURE);
    }
    Ok(ExitCode::SUCCESS)
}

fn median_ms(times: &mut [f64]) -> f64 {
    times.sort_by(f64::total_cmp);
    match times.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => times[n / 2],
        n => (times[n / 2 - 1] + times[n / 2]) / 2.0,
    }
}

/// One scene's medians.
struct BenchRow {
    name: &'static str,
    size: (u32, u32),
    cpu_ms: f64,
    gl_ms: f64,
}

/// `--threads N`: the CPU backend's pool gets N threads (before the first Context, which would
/// start it with one thread per core), pinned one to a CPU as the default pool's are when N is
/// the process's CPU count.
fn cpu_threads(threads: Option<u32>) -> Result<(), CliError> {
    if let Some(n) = threads {
        fixedgl::start_pool(Some(n as usize))
            .map_err(|e| CliError::Usage(format!("--threads {n}: {e}")))?;
    }
    Ok(())
}

/// `bench --stages`: a CPU frame's median time in each stage, in milliseconds.
fn bench_stages(
    names: &[String],
    size: Option<(u32, u32)>,
    frames: u32,
    threads: Option<u32>,
) -> Result<ExitCode, CliError> {
    let selected = select(names, true)?;
    cpu_threads(threads)?;
    out!(
        "{:<20} {:>7} {:>7} {:>7} {:>7} {:>8} {:>9} {:>9} {:>7} {:>8} {:>6}",
        "scene",
        "frame",
        "reset",
        "replay",
        "finish",
        "readback",
        "draws",
        "draw ms",
        "wait",
        "handoffs",
        "passes"
    );
    for scene in selected {
        let (w, h) = size.unwrap_or(scene.default_size);
        let (_, calls) = scene.record(w, h)?;
        let mut ctx = Context::with_config(w, h, scene.config)?;
        // Per frame: total (up to glFinish, as `bench` times it), reset, replay, finish,
        // to_image after it (not in the total), draws, draw ms, wait ms, hand-offs,
        // rasterisation passes.
        let mut rows: Vec<[f64; 10]> = Vec::new();
        for i in 0..=frames {
            let s0 = ctx.draw_stats();
            let t0 = Instant::now();
            ctx.reset();
            let t1 = Instant::now();
            ctx.replay(&calls);
            let t2 = Instant::now();
            ctx.finish();
            let t3 = Instant::now();
            let img = ctx.to_image();
            let t4 = Instant::now();
            drop(img);
            let s1 = ctx.draw_stats();
            let ms = |a: Instant, b: Instant| (b - a).as_secs_f64() * 1e3;
            let dms = |a: u64, b: u64| (b - a) as f64 / 1e6;
            if i > 0 {
                rows.push([
                    ms(t0, t3),
                    ms(t0, t1),
                    ms(t1, t2),
                    ms(t2, t3),
                    ms(t3, t4),
                    (s1.draws - s0.draws + s1.handoffs - s0.handoffs) as f64,
                    dms(s0.draw_ns, s1.draw_ns) + dms(s0.handoff_ns, s1.handoff_ns),
                    dms(s0.wait_ns, s1.wait_ns),
                    (s1.handoffs - s0.handoffs) as f64,
                    (s1.passes - s0.passes) as f64,
                ]);
            }
        }
        let med: Vec<f64> = (0..10)
            .map(|k| median_ms(&mut rows.iter().map(|r| r[k]).collect::<Vec<_>>()))
            .collect();
        out!(
            "{:<20} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>8.3} {:>9} {:>9.3} {:>7.3} {:>8} {:>6}",
            scene.name,
            med[0],
            med[1],
            med[2],
            med[3],
            med[4],
            med[5],
            med[6],
            med[7],
            med[8],
            med[9]
        );
    }
    Ok(ExitCode::SUCCESS)
}

fn bench(
    names: &[String],
    size: Option<(u32, u32)>,
    frames: u32,
    threads: Option<u32>,
    json: bool,
    cpu_only: bool,
    device: &str,
) -> Result<ExitCode, CliError> {
    let selected = select(names, true)?;
    cpu_threads(threads)?;
    if !json {
        out!(
            "{:<20} {:>11} {:>10} {:>10} {:>8}",
            "scene",
            "size",
            "cpu ms",
            "gl ms",
            "cpu/gl"
        );
    }
    let mut rows = Vec::new();
    for scene in selected {
        let (w, h) = size.unwrap_or(scene.default_size);
        let (_, calls) = scene.record(w, h)?;
        let mut gl = match cpu_only {
            true => None,
            false => Some(gl_side::Bench::new(w, h, scene.config, device)?),
        };
        // Like the GL side (one context, state restored around each frame), one CPU context
        // reset to its initial state before each frame; its framebuffer memory is reused. A
        // frame ends, on both sides, when glFinish returns: every pixel is in the framebuffer,
        // not yet read back (`--stages` gives the CPU read-back on its own).
        let mut ctx = Context::with_config(w, h, scene.config)?;
        let mut cpu_frame = || -> Result<f64, Error> {
            let start = Instant::now();
            ctx.reset();
            ctx.replay(&calls);
            ctx.finish();
            Ok(start.elapsed().as_secs_f64() * 1e3)
        };
        // One warm-up frame each (shader compilation, first-touch allocation), then interleaved.
        cpu_frame()?;
        let mut gl_frame = || gl.as_mut().map_or(f64::NAN, |gl| gl.frame(&calls));
        gl_frame();
        let mut cpu_times = Vec::new();
        let mut gl_times = Vec::new();
        for _ in 0..frames {
            cpu_times.push(cpu_frame()?);
            gl_times.push(gl_frame());
        }
        let row = BenchRow {
            name: scene.name,
            size: (w, h),
            cpu_ms: median_ms(&mut cpu_times),
            gl_ms: median_ms(&mut gl_times),
        };
        if !json {
            out!(
                "{:<20} {:>11} {:>10.3} {:>10.3} {:>8.2}",
                row.name,
                format!("{w}x{h}"),
                row.cpu_ms,
                row.gl_ms,
                row.cpu_ms / row.gl_ms
            );
        }
        rows.push(row);
    }
    let ratio = |r: &BenchRow| r.cpu_ms / r.gl_ms;
    // The geometric mean, as ratios are: 2x slower and 2x faster average to 1.
    let geomean =
        (rows.iter().map(|r| ratio(r).ln()).sum::<f64>() / rows.len().max(1) as f64).exp();
    let worst = rows.iter().max_by(|a, b| ratio(a).total_cmp(&ratio(b)));
    let cpu_threads = rayon::current_num_threads();
    // llvmpipe rasterises on LP_NUM_THREADS threads, one per core when it is unset.
    let gl_threads = std::env::var("LP_NUM_THREADS")
        .ok()
        .and_then(|v| v.parse::<usize>().ok())
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let api_ns = api_call_ns()?;
    let capi_ns = run::capi_call_ns();
    if json {
        let scenes: Vec<serde_json::Value> = rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "scene": r.name,
                    "width": r.size.0,
                    "height": r.size.1,
                    "cpu_ms": r.cpu_ms,
                    "gl_ms": r.gl_ms,
                    "ratio": ratio(r),
                })
            })
            .collect();
        let out = serde_json::json!({
            "frames": frames,
            "cpu_threads": cpu_threads,
            "gl_threads": gl_threads,
            "geomean_ratio": geomean,
            "worst": worst.map(|r| r.name),
            "rust_api_ns_per_call": api_ns,
            "c_abi_ns_per_call": capi_ns.as_ref().ok(),
            "scenes": scenes,
        });
        out!("{out}");
    } else {
        out!(
            "geometric mean cpu/gl {geomean:.2}; worst {}; threads: cpu {cpu_threads}, gl {gl_threads}",
            worst.map_or_else(|| "-".to_string(), |r| format!("{} ({:.2})", r.name, ratio(r)))
        );
        out!(
            "Rust API: {api_ns:.1} ns a call (Color3f + Vertex3f pairs, points outside the view \
             volume: validation, batching and the vertex stage, no fragments)"
        );
        match &capi_ns {
            Ok(ns) => out!(
                "C ABI: {ns:.1} ns a call (the same pairs through libfixedgl_capi.so's glColor3f \
                 and glVertex3f on an OSMesa context)"
            ),
            Err(why) => out!("C ABI: not measured: {why}"),
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// Nanoseconds a call of the Rust API costs: the median of five runs of 100k Color3f +
/// Vertex3f pairs inside Begin(POINTS)/End on a 64x64 context, every point beyond the far
/// right of the view volume (clipped: no fragments), up to Finish.
fn api_call_ns() -> Result<f64, Error> {
    const PAIRS: u32 = 100_000;
    let mut ctx = Context::new(64, 64)?;
    let mut runs: Vec<f64> = (0..5)
        .map(|_| {
            let start = Instant::now();
            ctx.begin(fixedgl::gl::POINTS);
            for i in 0..PAIRS {
                let f = i as f32 * 1e-6;
                ctx.color3f(f, 0.5, 0.25);
                ctx.vertex3f(2.0 + f, 0.0, 0.0);
            }
            ctx.end();
            ctx.finish();
            start.elapsed().as_secs_f64() * 1e9 / f64::from(2 * PAIRS)
        })
        .collect();
    Ok(median_ms(&mut runs))
}

fn replay(
    file: &Path,
    backend: Backend,
    (w, h): (u32, u32),
    output: Option<PathBuf>,
    device: &str,
) -> Result<ExitCode, CliError> {
    let calls = fixedgl::recording::load(file).map_err(|e| {
        CliError::Input(match e {
            Error::Parse {
                line,
                column,
                message,
            } => format!("{}:{line}:{column}: {message}", file.display()),
            Error::Io(e) => format!("{}: cannot read: {e}", file.display()),
            e => format!("{}: {e}", file.display()),
        })
    })?;
    let img = match backend {
        Backend::Cpu => {
            let mut ctx = Context::new(w, h)?;
            ctx.replay(&calls);
            ctx.to_image()
        }
        Backend::Gl => gl_side::render(&calls, w, h, ContextConfig::default(), device)?.0,
    };
    let stem = file
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("replay");
    let out = output.unwrap_or_else(|| PathBuf::from(format!("{stem}-{}.png", backend.name())));
    img.save(&out)?;
    out!("{}", out.display());
    Ok(ExitCode::SUCCESS)
}

/// `fixedgl view`: the scenes in a window (fixedgl::window::view).
#[cfg(feature = "window")]
fn view(
    selected: &[&'static Scene],
    compare: bool,
    size: Option<(u32, u32)>,
    fps: Option<f64>,
    frames: Option<u64>,
    record_frames: Option<PathBuf>,
    device: &str,
) -> Result<ExitCode, CliError> {
    use fixedgl::window::{view, Options};
    let config = view::ViewConfig {
        compare,
        size,
        device: device.to_owned(),
        fps,
        options: Options {
            frames,
            record_frames,
        },
    };
    let stats = view::run(selected, config)?;
    if frames.is_some() {
        out!(
            "{} frames in {:.2} s ({:.1} fps)",
            stats.frames,
            stats.seconds,
            stats.fps
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Without the `window` feature there is no window to open.
#[cfg(not(feature = "window"))]
fn view(
    _selected: &[&'static Scene],
    _compare: bool,
    _size: Option<(u32, u32)>,
    _fps: Option<f64>,
    _frames: Option<u64>,
    _record_frames: Option<PathBuf>,
    _device: &str,
) -> Result<ExitCode, CliError> {
    Err(Error::Window(
        "this fixedgl was built without the `window` feature; rebuild with default features \
         (cargo build --features window) to open windows"
            .into(),
    )
    .into())
}

/// The GL side of every command: the real backend with the `gl` feature.
#[cfg(feature = "gl")]
mod gl_side {
    use super::*;
    use fixedgl::glbackend::{list_devices, DeviceChoice, DeviceInfo, GlBackend};

    fn backend(w: u32, h: u32, device: &str) -> Result<GlBackend, Error> {
        backend_with(w, h, ContextConfig::default(), device)
    }

    /// A backend whose framebuffer has the buffers `config` names.
    fn backend_with(
        w: u32,
        h: u32,
        config: ContextConfig,
        device: &str,
    ) -> Result<GlBackend, Error> {
        let choice: DeviceChoice = device.parse().unwrap_or_default();
        GlBackend::with_config(w, h, &choice, config)
    }

    /// The EGL devices.
    pub fn devices() -> Result<Vec<DeviceInfo>, Error> {
        list_devices()
    }

    /// `calls` replayed on a fresh backend: the image and (GL_RENDERER, GL_VERSION).
    pub fn render(
        calls: &[Call],
        w: u32,
        h: u32,
        config: ContextConfig,
        device: &str,
    ) -> Result<(RgbaImage, (String, String)), Error> {
        let (img, info, _) = render_timed(calls, w, h, config, device)?;
        Ok((img, info))
    }

    /// Like [`render`], with the milliseconds the replay took up to glFinish (context creation
    /// and read-back not included).
    pub fn render_timed(
        calls: &[Call],
        w: u32,
        h: u32,
        config: ContextConfig,
        device: &str,
    ) -> Result<(RgbaImage, (String, String), f64), Error> {
        let mut gl = backend_with(w, h, config, device)?;
        let start = Instant::now();
        gl.replay(calls);
        gl.finish();
        let ms = start.elapsed().as_secs_f64() * 1e3;
        let info = (gl.renderer().to_owned(), gl.version().to_owned());
        Ok((gl.read_image(), info, ms))
    }

    /// Replays a program's frames one after the other on one backend (a fresh one when the
    /// drawable's size changes, replaying the frames before at the new size).
    #[derive(Default)]
    pub struct Replayer {
        backend: Option<((u32, u32), GlBackend)>,
        history: Vec<Call>,
    }

    impl Replayer {
        /// The image after `calls`, which follow the calls of the frames before.
        pub fn frame(
            &mut self,
            size: (u32, u32),
            calls: &[Call],
            device: &str,
        ) -> Result<(RgbaImage, (String, String)), Error> {
            if self.backend.as_ref().map(|(s, _)| *s) != Some(size) {
                let mut gl = backend(size.0, size.1, device)?;
                gl.replay(&self.history);
                self.backend = Some((size, gl));
            }
            self.history.extend_from_slice(calls);
            let Some((_, gl)) = self.backend.as_mut() else {
                unreachable!("made above")
            };
            gl.replay(calls);
            gl.finish();
            let info = (gl.renderer().to_owned(), gl.version().to_owned());
            Ok((gl.read_image(), info))
        }
    }

    /// One backend reused across benchmark frames.
    pub struct Bench(GlBackend);

    impl Bench {
        pub fn new(w: u32, h: u32, config: ContextConfig, device: &str) -> Result<Self, Error> {
            Ok(Bench(backend_with(w, h, config, device)?))
        }

        /// Milliseconds for one frame: the calls replayed from the initial state, up to
        /// glFinish.
        pub fn frame(&mut self, calls: &[Call]) -> f64 {
            let start = Instant::now();
            self.0.replay_frame(calls);
            self.0.finish();
            start.elapsed().as_secs_f64() * 1e3
        }
    }
}

/// Without the `gl` feature every GL-side step is a clear error.
#[cfg(not(feature = "gl"))]
mod gl_side {
    use super::*;

    fn unavailable() -> Error {
        Error::Backend(
            "this fixedgl was built without the `gl` feature; rebuild with default features \
             (cargo build --features gl) for the real-GL backend"
                .into(),
        )
    }

    /// No devices without the backend.
    pub fn devices() -> Result<Vec<String>, Error> {
        Err(unavailable())
    }

    /// Always an error.
    pub fn render(
        _calls: &[Call],
        _w: u32,
        _h: u32,
        _config: ContextConfig,
        _device: &str,
    ) -> Result<(RgbaImage, (String, String)), Error> {
        Err(unavailable())
    }

    /// Always an error.
    pub fn render_timed(
        _calls: &[Call],
        _w: u32,
        _h: u32,
        _config: ContextConfig,
        _device: &str,
    ) -> Result<(RgbaImage, (String, String), f64), Error> {
        Err(unavailable())
    }

    /// Never makes an image.
    #[derive(Default)]
    pub struct Replayer;

    impl Replayer {
        /// Always an error.
        pub fn frame(
            &mut self,
            _size: (u32, u32),
            _calls: &[Call],
            _device: &str,
        ) -> Result<(RgbaImage, (String, String)), Error> {
            Err(unavailable())
        }
    }

    /// Never constructed.
    pub struct Bench;

    impl Bench {
        pub fn new(_w: u32, _h: u32, _config: ContextConfig, _device: &str) -> Result<Self, Error> {
            Err(unavailable())
        }

        pub fn frame(&mut self, _calls: &[Call]) -> f64 {
            f64::NAN
        }
    }
}
