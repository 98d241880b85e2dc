//! What the piglit runner (`capi/tests/piglit.rs`) is made of: the test list and the expectations
//! file, finding piglit and the cdylib, the drop-in directory, running one test with a timeout,
//! and reading its result.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The directory of this file's data: `capi/tests/piglit/`.
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/piglit")
}

/// One line of `core.tsv`.
#[derive(Clone, Debug)]
pub struct Test {
    /// piglit's name, `spec@!opengl 1.0@...`.
    pub name: String,
    /// The binary (in piglit's `bin/`) and its arguments; `-auto` is added when it runs.
    pub argv: Vec<String>,
    /// llvmpipe's result as GL 1.5.
    pub llvmpipe: String,
}

/// Reads `core.tsv`: every line that is not a `#` comment.
pub fn load_core() -> Vec<Test> {
    let path = data_dir().join("core.tsv");
    let text = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            assert!(f.len() >= 3, "{}: bad line {l:?}", path.display());
            Test {
                name: f[0].to_string(),
                argv: f[1].split_whitespace().map(str::to_string).collect(),
                llvmpipe: f[2].to_string(),
            }
        })
        .collect()
}

/// One row of `expected.tsv`: fixedgl's result and, for a test fixedgl does not pass, why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expected {
    pub result: String,
    pub reason: String,
}

/// The results a test may be expected to have (crashes and timeouts never are).
pub const RESULTS: [&str; 4] = ["pass", "fail", "skip", "warn"];

/// The header of `expected.tsv` (written again by FIXEDGL_BLESS=1).
pub const EXPECTED_HEADER: &str = "\
# fixedgl's result on each test of core.tsv, as capi/tests/piglit.rs measures it on every
# `cargo test` where piglit is present. Any difference fails that test: a test that stops passing,
# a crash or a timeout, and equally a test that now passes or skips where this file says otherwise,
# so that this file always says what fixedgl does. After a change that makes tests pass, ratchet:
#   FIXEDGL_BLESS=1 cargo test --profile ci -p fixedgl-capi --test piglit
# (that keeps the reasons of rows still not passing and leaves new ones empty, to be filled in).
# Columns: piglit's test name; fixedgl's result; for a test llvmpipe passes as GL 1.5 but fixedgl
# does not, why: `#N: ...` (the issue that brings what it needs), `bug: ...` (fixedgl does it
# wrong), `none: ...` (no issue covers it yet). The first blocker is named first.
";

/// Reads `expected.tsv` (test name → row). Panics on a malformed line or an unknown result.
pub fn load_expected() -> BTreeMap<String, Expected> {
    let path = data_dir().join("expected.tsv");
    let text = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut out = BTreeMap::new();
    for l in text.lines() {
        if l.starts_with('#') || l.trim().is_empty() {
            continue;
        }
        let f: Vec<&str> = l.split('\t').collect();
        assert!(
            f.len() == 2 || f.len() == 3,
            "{}: bad line {l:?}",
            path.display()
        );
        assert!(
            RESULTS.contains(&f[1]),
            "{}: unknown result {:?} for {}",
            path.display(),
            f[1],
            f[0]
        );
        let row = Expected {
            result: f[1].to_string(),
            reason: f.get(2).unwrap_or(&"").to_string(),
        };
        assert!(
            out.insert(f[0].to_string(), row).is_none(),
            "{}: {} twice",
            path.display(),
            f[0]
        );
    }
    out
}

/// Writes `expected.tsv` in core.tsv's order.
pub fn write_expected(core: &[Test], rows: &BTreeMap<String, Expected>) {
    let mut text = String::from(EXPECTED_HEADER);
    for t in core {
        let r = &rows[&t.name];
        if r.reason.is_empty() {
            text += &format!("{}\t{}\n", t.name, r.result);
        } else {
            text += &format!("{}\t{}\t{}\n", t.name, r.result, r.reason);
        }
    }
    let path = data_dir().join("expected.tsv");
    fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

/// What covers a reason: its leading `#N`, `bug` or `none` (before the first `:`), if well formed.
pub fn reason_cover(reason: &str) -> Option<&str> {
    let (head, rest) = reason.split_once(": ")?;
    let ok = head == "bug"
        || head == "none"
        || (head.len() > 1
            && head.starts_with('#')
            && head[1..].bytes().all(|b| b.is_ascii_digit()));
    (ok && !rest.trim().is_empty()).then_some(head)
}

/// The cargo target directory and profile directory this test binary was built in: the binary is
/// `<target>/<profile>/deps/piglit-<hash>`.
pub fn build_dirs() -> (PathBuf, PathBuf) {
    let exe = std::env::current_exe().expect("current_exe");
    let deps = exe.parent().expect("deps dir").to_path_buf();
    let profile = deps.parent().expect("profile dir").to_path_buf();
    let target = profile.parent().expect("target dir").to_path_buf();
    (target, deps)
}

/// The C ABI library built with this test: cargo builds the `fixedgl_capi` lib target (cdylib
/// and rlib in one compilation) as the test's dependency, into `deps/`; `cargo build` also
/// copies it up into the profile directory.
pub fn cdylib() -> Option<PathBuf> {
    let (_, deps) = build_dirs();
    let name = "libfixedgl_capi.so";
    [deps.join(name), deps.parent()?.join(name)]
        .into_iter()
        .find(|p| p.is_file())
}

/// Where piglit is: its `bin/` and the library directories its programs need.
#[derive(Clone, Debug)]
pub struct Piglit {
    /// piglit's own directory (`bin/`, `lib/`).
    pub dir: PathBuf,
    /// Directories for LD_LIBRARY_PATH after the drop-in one: piglit's `lib/` (its RUNPATH names
    /// /usr) and the one above it when it holds an extracted `libwaffle-1.so.0`.
    pub libs: Vec<PathBuf>,
}

/// Where `.ci/run` extracts the Debian packages: `<target>/piglit`.
pub fn default_root() -> PathBuf {
    build_dirs().0.join("piglit")
}

/// piglit under `root`: `root` itself (a directory with `bin/` and `lib/`, such as
/// /usr/lib/x86_64-linux-gnu/piglit) or an extracted package tree (`root/usr/lib/*/piglit`).
pub fn find_piglit(root: &Path) -> Option<Piglit> {
    let mut candidates = vec![root.to_path_buf()];
    if let Ok(rd) = fs::read_dir(root.join("usr/lib")) {
        let mut more: Vec<PathBuf> = rd.flatten().map(|e| e.path().join("piglit")).collect();
        more.sort();
        candidates.extend(more);
    }
    let dir = candidates
        .into_iter()
        .find(|d| d.join("bin").is_dir() && d.join("lib").is_dir())?;
    let mut libs = vec![dir.join("lib")];
    if let Some(up) = dir.parent() {
        if up.join("libwaffle-1.so.0").exists() {
            libs.push(up.to_path_buf());
        }
    }
    Some(Piglit { dir, libs })
}

/// The names the C ABI library answers to, as symlinks in `dir` (made afresh): those
/// `fixedgl run` makes (docs/c-abi.md).
pub fn make_dropin(dir: &Path, lib: &Path) -> std::io::Result<()> {
    let _ = fs::remove_dir_all(dir);
    fs::create_dir_all(dir)?;
    let lib = fs::canonicalize(lib)?;
    for name in [
        "libGL.so.1",
        "libEGL.so.1",
        "libOpenGL.so.0",
        "libOSMesa.so.8",
        "libGL.so",
        "libEGL.so",
        "libOpenGL.so",
        "libOSMesa.so",
    ] {
        std::os::unix::fs::symlink(&lib, dir.join(name))?;
    }
    Ok(())
}

/// How one run of a test ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The `PIGLIT: {"result": ...}` it printed last (`pass`, `fail`, `skip`, `warn`), or `fail`
    /// when it exited without printing one.
    Result(String),
    /// Killed by a signal (its number).
    Crash(i32),
    /// Still running after the timeout (then killed).
    Timeout,
}

impl Outcome {
    /// The word for the summary and the results file.
    pub fn word(&self) -> String {
        match self {
            Outcome::Result(r) => r.clone(),
            Outcome::Crash(s) => format!("crash (signal {s})"),
            Outcome::Timeout => "timeout".into(),
        }
    }
}

/// One finished test.
#[derive(Clone, Debug)]
pub struct Run {
    pub outcome: Outcome,
    pub seconds: f64,
    /// Where its standard output and error went.
    pub log: PathBuf,
}

/// The last `PIGLIT: {"result": "<r>" }` line of `output`: `<r>`. As piglit's own runner
/// (framework/test/piglit_test.py), only a line that starts with `PIGLIT:` counts.
pub fn parse_result(output: &str) -> Option<String> {
    output.lines().rev().find_map(|l| {
        let rest = l.strip_prefix("PIGLIT:")?;
        let rest = rest.trim().strip_prefix('{')?.trim();
        let rest = rest.strip_prefix("\"result\"")?.trim().strip_prefix(':')?;
        let word = rest.trim().strip_prefix('"')?;
        Some(word.split('"').next()?.to_string())
    })
}

/// The environment and paths every test runs with.
pub struct Setup {
    pub piglit: Piglit,
    pub dropin: PathBuf,
    pub logs: PathBuf,
    pub timeout: Duration,
}

/// A file name for a test's log.
fn log_name(name: &str) -> String {
    let s: String = name
        .trim_start_matches("spec@")
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '.' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{s}.log")
}

/// Runs one test headless, as Mesa's CI runs llvmpipe: `PIGLIT_PLATFORM=surfaceless_egl
/// PIGLIT_NO_WINDOW=1 <bin> <args> -auto`, the drop-in directory first on LD_LIBRARY_PATH.
pub fn run_one(setup: &Setup, test: &Test) -> Run {
    let log = setup.logs.join(log_name(&test.name));
    let start = Instant::now();
    let outcome = run_to(setup, test, &log);
    Run {
        outcome,
        seconds: start.elapsed().as_secs_f64(),
        log,
    }
}

fn run_to(setup: &Setup, test: &Test, log: &Path) -> Outcome {
    use std::os::unix::process::ExitStatusExt;
    let file = fs::File::create(log).unwrap_or_else(|e| panic!("{}: {e}", log.display()));
    let err = file.try_clone().expect("clone log handle");
    let mut path = vec![setup.dropin.clone()];
    path.extend(setup.piglit.libs.iter().cloned());
    if let Some(old) = std::env::var_os("LD_LIBRARY_PATH") {
        path.extend(std::env::split_paths(&old));
    }
    let ld = std::env::join_paths(path).expect("LD_LIBRARY_PATH");
    let bin = setup.piglit.dir.join("bin").join(&test.argv[0]);
    let mut child = match Command::new(&bin)
        .args(&test.argv[1..])
        .arg("-auto")
        .env("PIGLIT_PLATFORM", "surfaceless_egl")
        .env("PIGLIT_NO_WINDOW", "1")
        .env("LD_LIBRARY_PATH", ld)
        .current_dir(&setup.logs)
        .stdin(Stdio::null())
        .stdout(file)
        .stderr(err)
        .spawn()
    {
        Ok(c) => c,
        Err(e) => {
            let _ = fs::write(log, format!("cannot start {}: {e}\n", bin.display()));
            return Outcome::Result("fail".into());
        }
    };
    let deadline = Instant::now() + setup.timeout;
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break s,
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                return Outcome::Timeout;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => panic!("waiting for {}: {e}", test.name),
        }
    };
    if let Some(sig) = status.signal() {
        return Outcome::Crash(sig);
    }
    let out = fs::read(log).unwrap_or_default();
    let out = String::from_utf8_lossy(&out);
    Outcome::Result(parse_result(&out).unwrap_or_else(|| "fail".into()))
}

/// Runs `tests` on `jobs` threads; the runs in the tests' order.
pub fn run_all(setup: &Setup, tests: &[Test], jobs: usize) -> Vec<Run> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let next = AtomicUsize::new(0);
    let runs: Mutex<Vec<Option<Run>>> = Mutex::new(vec![None; tests.len()]);
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(t) = tests.get(i) else { break };
                let r = run_one(setup, t);
                runs.lock().unwrap()[i] = Some(r);
            });
        }
    });
    runs.into_inner()
        .unwrap()
        .into_iter()
        .map(|r| r.expect("every test ran"))
        .collect()
}

/// The last `n` lines of a log, indented, for a failure message.
pub fn tail(log: &Path, n: usize) -> String {
    let text = fs::read(log).unwrap_or_default();
    let text = String::from_utf8_lossy(&text);
    let lines: Vec<&str> = text.lines().collect();
    let from = lines.len().saturating_sub(n);
    lines[from..]
        .iter()
        .map(|l| format!("      | {}\n", l.chars().take(200).collect::<String>()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_results() {
        let out = "x\nPIGLIT: {\"subtest\": {\"a\" : \"fail\"}}\nPIGLIT: {\"result\": \"pass\" }\n";
        assert_eq!(parse_result(out).as_deref(), Some("pass"));
        assert_eq!(
            parse_result("PIGLIT: {\"result\": \"skip\" }").as_deref(),
            Some("skip")
        );
        assert_eq!(
            parse_result("PIGLIT: {\"subtest\": {\"a\" : \"fail\"}}"),
            None
        );
        assert_eq!(parse_result(""), None);
        assert_eq!(parse_result("GL_X_yPIGLIT: {\"result\": \"pass\" }"), None);
    }

    #[test]
    fn reasons() {
        assert_eq!(reason_cover("#13: glRasterPos2i"), Some("#13"));
        assert_eq!(reason_cover("bug: x"), Some("bug"));
        assert_eq!(reason_cover("none: FBOs"), Some("none"));
        assert_eq!(reason_cover("#: x"), None);
        assert_eq!(reason_cover("#13:"), None);
        assert_eq!(reason_cover("#13: "), None);
        assert_eq!(reason_cover("it fails"), None);
    }
}
