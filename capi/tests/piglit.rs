//! piglit's GL 1.x tests on fixedgl through the C ABI (issue #12): the 275 tests of
//! `piglit/core.tsv` run headless, exactly as Mesa's CI runs llvmpipe (`PIGLIT_PLATFORM=
//! surfaceless_egl PIGLIT_NO_WINDOW=1 <test> -auto`), with the C ABI library built with this test
//! first on LD_LIBRARY_PATH under the names libGL.so.1, libEGL.so.1, libOpenGL.so.0 and
//! libOSMesa.so.8.
//!
//! piglit is looked for in `FIXEDGL_PIGLIT_DIR` (a piglit directory with `bin/` and `lib/`, or a
//! tree with `usr/lib/<arch>/piglit`), else in `<target>/piglit`, where `.ci/run` extracts
//! Debian's package. Without piglit the run is skipped (said on stderr), unless
//! `FIXEDGL_REQUIRE_GL` is set: then it fails.
//!
//! The run fails on any crash (a signal), any timeout (`FIXEDGL_PIGLIT_TIMEOUT` seconds, 60 by
//! default), and any result that differs from `piglit/expected.tsv`, in either direction: a test
//! that passes where the file says it does not asks for the file to be ratcheted
//! (`FIXEDGL_BLESS=1`), so that the file always says what fixedgl does. Each test's output is
//! kept in `<target>/<profile>/piglit-results/`. `FIXEDGL_PIGLIT_JOBS` (2 by default) tests run
//! at a time; `FIXEDGL_PIGLIT_FILTER=text` runs only the tests whose name contains `text`.
//!
//! The same test keeps the piglit section of docs/conformance.md in step with the expectations
//! (rewritten by FIXEDGL_BLESS=1) and checks that every test llvmpipe passes but fixedgl does not
//! names its reason and the issue that covers it.

#[path = "piglit/harness.rs"]
mod harness;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use harness::{Expected, Outcome, Setup, Test};

fn env_flag(name: &str) -> bool {
    std::env::var_os(name).is_some_and(|v| !v.is_empty() && v != "0")
}

/// A message on stderr that libtest does not capture (a skip must stay visible).
fn say(msg: &str) {
    let _ = writeln!(std::io::stderr(), "{msg}");
}

#[test]
fn piglit_core() {
    let core = harness::load_core();
    assert_eq!(core.len(), 275, "core.tsv lists 275 tests");
    let mut expected = harness::load_expected();
    check_rows_match(&core, &expected);

    if let Some(runs) = run_piglit(&core) {
        let bless = env_flag("FIXEDGL_BLESS");
        let filtered = runs.len() != core.len();
        let problems = compare(&core, &expected, &runs);
        if bless && !filtered {
            for (t, r) in core.iter().zip(&runs) {
                if let Outcome::Result(now) = &r.outcome {
                    let row = expected.get_mut(&t.name).expect("checked above");
                    if row.result != *now {
                        row.reason.clear();
                    }
                    row.result = now.clone();
                    if now == "pass" {
                        row.reason.clear();
                    }
                }
            }
            harness::write_expected(&core, &expected);
            say("piglit: FIXEDGL_BLESS: wrote capi/tests/piglit/expected.tsv");
        }
        let fatal: Vec<&String> = problems
            .iter()
            .filter(|(kind, _)| !(bless && *kind == Change::Result))
            .map(|(_, msg)| msg)
            .collect();
        assert!(
            fatal.is_empty(),
            "piglit: {} problem(s):\n{}",
            fatal.len(),
            fatal
                .iter()
                .map(|s| s.as_str())
                .collect::<Vec<_>>()
                .join("")
        );
    }

    check_reasons(&core, &expected);
    check_docs(&core, &expected);
}

/// expected.tsv has exactly core.tsv's tests.
fn check_rows_match(core: &[Test], expected: &BTreeMap<String, Expected>) {
    let names: std::collections::BTreeSet<&str> = core.iter().map(|t| t.name.as_str()).collect();
    let missing: Vec<&str> = names
        .iter()
        .filter(|n| !expected.contains_key(**n))
        .copied()
        .collect();
    let extra: Vec<&String> = expected
        .keys()
        .filter(|n| !names.contains(n.as_str()))
        .collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "expected.tsv and core.tsv differ: missing {missing:?}, not in core.tsv {extra:?}"
    );
}

/// Every test llvmpipe passes as GL 1.5 that fixedgl does not names why and what covers it.
fn check_reasons(core: &[Test], expected: &BTreeMap<String, Expected>) {
    let bad: Vec<String> = core
        .iter()
        .filter(|t| t.llvmpipe == "pass")
        .filter_map(|t| {
            let e = &expected[&t.name];
            (e.result != "pass" && harness::reason_cover(&e.reason).is_none())
                .then(|| format!("  {}\t{}\t{:?}\n", t.name, e.result, e.reason))
        })
        .collect();
    assert!(
        bad.is_empty(),
        "capi/tests/piglit/expected.tsv: {} test(s) llvmpipe passes need a reason \
         (`#N: ...`, `bug: ...` or `none: ...`):\n{}",
        bad.len(),
        bad.concat()
    );
}

/// What differs from the expectations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Change {
    /// A crash or a timeout: never acceptable, never blessed.
    Fatal,
    /// A different result (a regression or an improvement): FIXEDGL_BLESS=1 records it.
    Result,
}

/// Prints the summary and a line per change; the changes.
fn compare(
    core: &[Test],
    expected: &BTreeMap<String, Expected>,
    runs: &[harness::Run],
) -> Vec<(Change, String)> {
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    let mut problems = Vec::new();
    let mut report = String::new();
    for (t, r) in core.iter().zip(runs) {
        let word = r.outcome.word();
        let key = match &r.outcome {
            Outcome::Result(w) => w.clone(),
            Outcome::Crash(_) => "crash".into(),
            Outcome::Timeout => "timeout".into(),
        };
        *counts.entry(key).or_default() += 1;
        let want = &expected[&t.name].result;
        let (kind, msg) = match &r.outcome {
            Outcome::Crash(_) | Outcome::Timeout => (
                Change::Fatal,
                format!("  {}: {word} (expected {want})\n", t.name),
            ),
            Outcome::Result(now) if now == want => continue,
            Outcome::Result(now) if want == "pass" => (
                Change::Result,
                format!("  REGRESSION {}: {now}, expected pass\n", t.name),
            ),
            Outcome::Result(now) if now == "pass" => (
                Change::Result,
                format!(
                    "  NOW PASSES {}: expected {want}: ratchet expected.tsv \
                     (FIXEDGL_BLESS=1 cargo test --profile ci -p fixedgl-capi --test piglit)\n",
                    t.name
                ),
            ),
            Outcome::Result(now) => (
                Change::Result,
                format!(
                    "  CHANGED {}: {now}, expected {want}: say why in expected.tsv (FIXEDGL_BLESS=1)\n",
                    t.name
                ),
            ),
        };
        let msg = format!(
            "{msg}      command: {} -auto   log: {}\n{}",
            t.argv.join(" "),
            r.log.display(),
            harness::tail(&r.log, 6)
        );
        report += &msg;
        problems.push((kind, msg));
    }
    let n = |k: &str| counts.get(k).copied().unwrap_or(0);
    let mut summary = format!(
        "piglit: {} passed, {} failed, {} skipped",
        n("pass"),
        n("fail"),
        n("skip")
    );
    for k in ["warn", "crash", "timeout"] {
        if n(k) > 0 {
            let _ = write!(summary, ", {} {k}", n(k));
        }
    }
    let _ = write!(summary, " (of {} run)", runs.len());
    say(&summary);
    if !report.is_empty() {
        say(&format!("piglit: changes from expected.tsv:\n{report}"));
    }
    problems
}

/// Runs the tests (all, or those FIXEDGL_PIGLIT_FILTER names) if piglit is there; `None` when
/// the run is skipped.
fn run_piglit(core: &[Test]) -> Option<Vec<harness::Run>> {
    let require = env_flag("FIXEDGL_REQUIRE_GL");
    let root = std::env::var_os("FIXEDGL_PIGLIT_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(harness::default_root);
    let Some(piglit) = harness::find_piglit(&root) else {
        let msg = format!(
            "piglit not found in {} (set FIXEDGL_PIGLIT_DIR, or run .ci/run, which extracts it there)",
            root.display()
        );
        assert!(!require, "FIXEDGL_REQUIRE_GL is set: {msg}");
        say(&format!("SKIPPED: {msg}"));
        return None;
    };
    let lib = harness::cdylib().unwrap_or_else(|| {
        panic!(
            "libfixedgl_capi.so not found beside the test binary ({}): cargo builds it with the tests",
            harness::build_dirs().1.display()
        )
    });
    let profile = harness::build_dirs().1.parent().unwrap().to_path_buf();
    let dropin = profile.join("piglit-dropin");
    harness::make_dropin(&dropin, &lib)
        .unwrap_or_else(|e| panic!("drop-in directory {}: {e}", dropin.display()));
    let logs = profile.join("piglit-results");
    let _ = std::fs::remove_dir_all(&logs);
    std::fs::create_dir_all(&logs).unwrap_or_else(|e| panic!("{}: {e}", logs.display()));
    let timeout = std::env::var("FIXEDGL_PIGLIT_TIMEOUT")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    let jobs = std::env::var("FIXEDGL_PIGLIT_JOBS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2);
    let setup = Setup {
        piglit,
        dropin,
        logs: logs.clone(),
        timeout: Duration::from_secs(timeout),
    };
    let filter = std::env::var("FIXEDGL_PIGLIT_FILTER").unwrap_or_default();
    let tests: Vec<Test> = core
        .iter()
        .filter(|t| t.name.contains(&filter))
        .cloned()
        .collect();
    let start = Instant::now();
    let runs = harness::run_all(&setup, &tests, jobs);
    say(&format!(
        "piglit: ran {} tests from {} on {} in {:.1} s ({jobs} at a time); logs in {}",
        tests.len(),
        setup.piglit.dir.display(),
        lib.display(),
        start.elapsed().as_secs_f64(),
        logs.display()
    ));
    write_results(&logs, &tests, &runs);
    if tests.len() == core.len() {
        Some(runs)
    } else {
        // A filtered run: compare what ran, as if the rest matched.
        let exp = harness::load_expected();
        let problems = compare(&tests, &exp, &runs);
        assert!(
            problems.is_empty(),
            "piglit: {} problem(s) in the filtered run",
            problems.len()
        );
        None
    }
}

/// `results.tsv` beside the logs: test, result, seconds.
fn write_results(dir: &Path, tests: &[Test], runs: &[harness::Run]) {
    let mut s = String::from("# test\tresult\tseconds\n");
    for (t, r) in tests.iter().zip(runs) {
        let _ = writeln!(s, "{}\t{}\t{:.2}", t.name, r.outcome.word(), r.seconds);
    }
    let _ = std::fs::write(dir.join("results.tsv"), s);
}

const DOCS_BEGIN: &str =
    "<!-- piglit-summary: written by capi/tests/piglit.rs from capi/tests/piglit/expected.tsv (FIXEDGL_BLESS=1) -->";
const DOCS_END: &str = "<!-- piglit-summary end -->";

/// The generated part of docs/conformance.md's piglit section.
fn docs_summary(core: &[Test], expected: &BTreeMap<String, Expected>) -> String {
    let count = |pred: &dyn Fn(&Test, &Expected) -> bool| {
        core.iter().filter(|t| pred(t, &expected[&t.name])).count()
    };
    let ours = |r: &'static str| count(&move |_, e| e.result == r);
    let llvm = count(&|t, _| t.llvmpipe == "pass");
    let both = count(&|t, e| t.llvmpipe == "pass" && e.result == "pass");
    let misses = if llvm == both {
        "every one of them.\n\n".to_string()
    } else {
        format!(
            "the {} it misses, by what covers them (the first blocker of each test; test names \
             without `spec@!opengl 1.x@`):\n\n",
            llvm - both
        )
    };
    let mut s = format!(
        "fixedgl passes **{} of {}** (fails {}, skips {}, warns {}); llvmpipe passes {llvm} as GL 1.5 \
         (and 271 as GL 4.5 compatibility). Of llvmpipe's {llvm}, fixedgl passes {both}: {misses}",
        ours("pass"),
        core.len(),
        ours("fail"),
        ours("skip"),
        ours("warn"),
    );
    // cover → reason → tests
    let mut groups: BTreeMap<(u32, String), BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for t in core {
        let e = &expected[&t.name];
        if t.llvmpipe != "pass" || e.result == "pass" {
            continue;
        }
        let cover = harness::reason_cover(&e.reason).unwrap_or("?").to_string();
        let rank = match cover.strip_prefix('#') {
            Some(n) => n.parse().unwrap_or(0),
            None if cover == "bug" => 1000,
            None => 1001,
        };
        let reason = e
            .reason
            .split_once(": ")
            .map(|x| x.1)
            .unwrap_or("")
            .to_string();
        let short = t.name.rsplit('@').next().unwrap_or(&t.name).to_string();
        groups
            .entry((rank, cover))
            .or_default()
            .entry(reason)
            .or_default()
            .push(short);
    }
    for ((_, cover), reasons) in &groups {
        let n: usize = reasons.values().map(Vec::len).sum();
        let title = match cover.as_str() {
            "bug" => "fixedgl bugs".to_string(),
            "none" => "no issue yet".to_string(),
            c => format!("issue {c}"),
        };
        let _ = writeln!(s, "- **{title}** ({n}):");
        for (reason, tests) in reasons {
            let list: Vec<String> = tests.iter().map(|t| format!("`{t}`")).collect();
            let _ = writeln!(s, "  - {reason}: {}", list.join(", "));
        }
    }
    s
}

/// docs/conformance.md's generated piglit summary matches expected.tsv (FIXEDGL_BLESS=1
/// rewrites it).
fn check_docs(core: &[Test], expected: &BTreeMap<String, Expected>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/conformance.md");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let (Some(a), Some(b)) = (text.find(DOCS_BEGIN), text.find(DOCS_END)) else {
        panic!(
            "{}: the piglit section's markers are missing:\n{DOCS_BEGIN}\n{DOCS_END}",
            path.display()
        );
    };
    let start = a + DOCS_BEGIN.len();
    let want = format!("\n{}", docs_summary(core, expected));
    if text[start..b] == want {
        return;
    }
    if env_flag("FIXEDGL_BLESS") {
        let new = format!("{}{want}{}", &text[..start], &text[b..]);
        std::fs::write(&path, new).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        say("piglit: FIXEDGL_BLESS: rewrote the piglit summary in docs/conformance.md");
    } else {
        panic!(
            "docs/conformance.md's piglit summary is stale: run \
             FIXEDGL_BLESS=1 cargo test --profile ci -p fixedgl-capi --test piglit"
        );
    }
}
