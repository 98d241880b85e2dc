//! `fixedgl compare` as CI consumes it: results.json validates against docs/results.schema.json,
//! `--json` prints the same document, and `--junit` writes JUnit XML with one test case a scene.
//!
//! Runs the `fixedgl` binary on two scenes, so it needs the GL backend: where no EGL device
//! exists it prints `SKIPPED: ...`; `FIXEDGL_REQUIRE_GL=1` turns that into a failure.
#![cfg(all(feature = "gl", feature = "cli"))]

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn schema() -> Value {
    read_json(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/results.schema.json"))
}

/// The part of JSON Schema 2020-12 that docs/results.schema.json uses: `type` (one or a list),
/// `const`, `required`, `properties`, `additionalProperties: false`, `items`, `minItems`,
/// `maxItems`, `minimum`, `maximum`, `minLength` and local `$ref`s (`#/$defs/...`). A keyword
/// it does not know fails the check, so the schema cannot outgrow the validator unnoticed.
fn validate(root: &Value, schema: &Value, v: &Value, at: &str, errors: &mut Vec<String>) {
    let Some(obj) = schema.as_object() else {
        errors.push(format!("{at}: schema is not an object"));
        return;
    };
    for (k, s) in obj {
        match k.as_str() {
            "$schema" | "$id" | "title" | "description" | "$defs" => {}
            "$ref" => {
                let target = s
                    .as_str()
                    .and_then(|r| r.strip_prefix('#'))
                    .and_then(|p| root.pointer(p));
                match target {
                    Some(t) => validate(root, t, v, at, errors),
                    None => errors.push(format!("{at}: unresolvable $ref {s}")),
                }
            }
            "type" => {
                let types: Vec<&str> = match s {
                    Value::String(t) => vec![t.as_str()],
                    Value::Array(ts) => ts.iter().filter_map(Value::as_str).collect(),
                    _ => vec![],
                };
                let ok = types.iter().any(|t| match *t {
                    "object" => v.is_object(),
                    "array" => v.is_array(),
                    "string" => v.is_string(),
                    "boolean" => v.is_boolean(),
                    "null" => v.is_null(),
                    "number" => v.is_number(),
                    "integer" => v.is_u64() || v.is_i64(),
                    _ => false,
                });
                if !ok {
                    errors.push(format!("{at}: {v} is not of type {s}"));
                }
            }
            "const" if v != s => errors.push(format!("{at}: {v} is not {s}")),
            "const" => {}
            "required" => {
                for key in s.as_array().into_iter().flatten().filter_map(Value::as_str) {
                    if v.is_object() && v.get(key).is_none() {
                        errors.push(format!("{at}: missing required {key:?}"));
                    }
                }
            }
            "properties" => {
                for (key, sub) in s.as_object().into_iter().flatten() {
                    if let Some(x) = v.get(key) {
                        validate(root, sub, x, &format!("{at}/{key}"), errors);
                    }
                }
            }
            "additionalProperties" => {
                let known = obj.get("properties").and_then(Value::as_object);
                if let (Some(Value::Bool(false)), Some(map)) = (Some(s), v.as_object()) {
                    for key in map.keys() {
                        if !known.is_some_and(|p| p.contains_key(key)) {
                            errors.push(format!("{at}: unexpected property {key:?}"));
                        }
                    }
                }
            }
            "items" => {
                for (i, x) in v.as_array().into_iter().flatten().enumerate() {
                    validate(root, s, x, &format!("{at}/{i}"), errors);
                }
            }
            "minItems" | "maxItems" => {
                if let (Some(a), Some(n)) = (v.as_array(), s.as_u64()) {
                    let len = a.len() as u64;
                    if (k == "minItems" && len < n) || (k == "maxItems" && len > n) {
                        errors.push(format!("{at}: {len} items breaks {k} {n}"));
                    }
                }
            }
            "minimum" | "maximum" => {
                if let (Some(x), Some(n)) = (v.as_f64(), s.as_f64()) {
                    if (k == "minimum" && x < n) || (k == "maximum" && x > n) {
                        errors.push(format!("{at}: {x} breaks {k} {n}"));
                    }
                }
            }
            "minLength" => {
                if let (Some(x), Some(n)) = (v.as_str(), s.as_u64()) {
                    if (x.chars().count() as u64) < n {
                        errors.push(format!("{at}: {x:?} is shorter than {n}"));
                    }
                }
            }
            other => errors.push(format!("{at}: schema keyword {other:?} not checked here")),
        }
    }
}

fn schema_errors(v: &Value) -> Vec<String> {
    let schema = schema();
    let mut errors = Vec::new();
    validate(&schema, &schema, v, "", &mut errors);
    errors
}

#[test]
fn compare_writes_results_json_matching_the_schema_prints_it_and_writes_junit() {
    if crate::common::test_backend(8, 8).is_none() {
        return;
    }
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report-cli");
    let _ = std::fs::remove_dir_all(&dir);
    let junit = dir.join("junit.xml");
    let out = Command::new(env!("CARGO_BIN_EXE_fixedgl"))
        .args(["compare", "textured-cube", "triangle", "--json", "--out"])
        .arg(&dir)
        .arg("--junit")
        .arg(&junit)
        .output()
        .unwrap_or_else(|e| panic!("cannot run fixedgl: {e}"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "fixedgl compare failed: {stderr}");
    // Progress and the per-scene lines go to stderr; stdout is exactly results.json.
    let printed: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("--json printed no JSON ({e}); stderr: {stderr}"));
    let results = read_json(&dir.join("results.json"));
    assert_eq!(printed, results);

    let errors = schema_errors(&results);
    assert!(
        errors.is_empty(),
        "results.json breaks the schema:\n{}",
        errors.join("\n")
    );
    assert_eq!(results["total"], 2);
    assert_eq!(results["failed"], 0);
    assert_eq!(results["pass"], true);
    assert!(results["gl_renderer"]
        .as_str()
        .is_some_and(|s| !s.is_empty()));
    let scenes = results["scenes"].as_array().cloned().unwrap_or_default();
    assert_eq!(scenes[0]["name"], "textured-cube");
    assert_eq!(scenes[1]["name"], "triangle");
    // The NEAREST_MIPMAP panels differ from llvmpipe, within the scene's allowance.
    assert!(scenes[0]["metrics"]["differing_pixels"].as_u64() > Some(0));
    for s in &scenes {
        assert!(s["timings_ms"]["cpu"].as_f64() > Some(0.0), "{s}");
        assert!(s["timings_ms"]["gl"].as_f64() > Some(0.0), "{s}");
        let files = [&s["page"], &s["images"]["cpu"], &s["images"]["diff"]];
        for f in files.iter().filter_map(|f| f.as_str()) {
            assert!(dir.join(f).is_file(), "{f} missing");
        }
    }

    let xml = std::fs::read_to_string(&junit).unwrap_or_else(|e| panic!("junit.xml: {e}"));
    let doc = roxmltree::Document::parse(&xml).unwrap_or_else(|e| panic!("junit.xml: {e}"));
    let suite = doc
        .descendants()
        .find(|n| n.has_tag_name("testsuite"))
        .unwrap_or_else(|| panic!("no <testsuite> in {xml}"));
    assert_eq!(suite.attribute("tests"), Some("2"));
    assert_eq!(suite.attribute("failures"), Some("0"));
    let cases: Vec<&str> = suite
        .children()
        .filter(|n| n.has_tag_name("testcase"))
        .filter_map(|n| n.attribute("name"))
        .collect();
    assert_eq!(cases, ["textured-cube", "triangle"]);
}

#[test]
fn the_schema_check_catches_a_broken_document() {
    // The validator itself: a well-formed minimal document passes, each breakage is named.
    let good = serde_json::json!({
        "format": "fixedgl-results/1", "fixedgl_version": "0.1.0", "cpu_renderer": "c",
        "gl_renderer": "g", "gl_version": "v", "pass": true, "total": 1, "failed": 0,
        "scenes": [{
            "name": "s", "summary": "", "pass": true, "width": 2, "height": 2, "gl_width": 2,
            "gl_height": 2, "size_mismatch": false,
            "tolerance": { "channel": 2, "max_percent": 0.5 },
            "metrics": { "max_diff": [0, 0, 0, 0], "mean_diff": [0.0, 0.0, 0.0, 0.0],
                         "differing_pixels": 0, "differing_percent": 0.0, "psnr_db": null },
            "timings_ms": { "cpu": 1.0, "gl": null },
            "page": "s.html",
            "images": { "cpu": "a", "gl": "b", "diff": "c", "strip": "d" }
        }]
    });
    assert_eq!(schema_errors(&good), Vec::<String>::new());
    let mut bad = good.clone();
    bad["scenes"][0]["metrics"]["max_diff"] = serde_json::json!([0, 300, 0]);
    bad["scenes"][0]["extra"] = Value::Bool(true);
    bad["format"] = Value::from("other");
    if let Some(m) = bad.as_object_mut() {
        m.remove("pass");
    }
    let errors = schema_errors(&bad).join("\n");
    for expected in [
        "missing required \"pass\"",
        "/scenes/0/metrics/max_diff: 3 items breaks minItems 4",
        "/scenes/0/metrics/max_diff/1: 300 breaks maximum 255",
        "/scenes/0: unexpected property \"extra\"",
        "/format: \"other\" is not \"fixedgl-results/1\"",
    ] {
        assert!(errors.contains(expected), "{expected:?} not in:\n{errors}");
    }
}

/// `fixedgl bench --json`: one object with each scene's medians and ratio, their geometric mean,
/// the worst scene and both sides' thread counts; `--threads` sets the CPU side's.
#[test]
fn bench_json_gives_ratios_their_geometric_mean_the_worst_scene_and_threads() {
    if crate::common::test_backend(8, 8).is_none() {
        return;
    }
    let out = Command::new(env!("CARGO_BIN_EXE_fixedgl"))
        .args([
            "bench",
            "triangle",
            "rect-wire",
            "--frames",
            "1",
            "--threads",
            "1",
            "--json",
        ])
        .output()
        .unwrap_or_else(|e| panic!("cannot run fixedgl: {e}"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "fixedgl bench failed: {stderr}");
    let v: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("--json printed no JSON ({e}); stderr: {stderr}"));
    assert_eq!(v["cpu_threads"], 1);
    assert!(v["gl_threads"].as_u64().is_some_and(|n| n >= 1));
    let scenes = v["scenes"].as_array().map_or(&[][..], |a| a.as_slice());
    let names: Vec<&str> = scenes.iter().filter_map(|s| s["scene"].as_str()).collect();
    assert_eq!(names, ["triangle", "rect-wire"]);
    let ratios: Vec<f64> = scenes.iter().filter_map(|s| s["ratio"].as_f64()).collect();
    for s in scenes {
        let (c, g, r) = (
            s["cpu_ms"].as_f64(),
            s["gl_ms"].as_f64(),
            s["ratio"].as_f64(),
        );
        assert!(
            matches!((c, g, r), (Some(c), Some(g), Some(r)) if c > 0.0 && g > 0.0 && (r - c / g).abs() < 1e-9)
        );
    }
    let geomean = (ratios.iter().map(|r| r.ln()).sum::<f64>() / ratios.len() as f64).exp();
    assert!((v["geomean_ratio"].as_f64().unwrap_or(f64::NAN) - geomean).abs() < 1e-9);
    let worst = if ratios[0] >= ratios[1] {
        "triangle"
    } else {
        "rect-wire"
    };
    assert_eq!(v["worst"], worst);
    assert!(v["rust_api_ns_per_call"]
        .as_f64()
        .is_some_and(|ns| ns > 0.0));
}

/// `fixedgl bench` times a call through the C ABI library beside the binary (as `cargo build
/// --release` places them), and says why when there is none. Cargo keeps the test build's
/// library in `deps/`, so the test puts hard links of both side by side in a fresh folder (the
/// binary finds the library through its own path, which a symbolic link would not change).
#[test]
fn bench_times_a_call_through_the_c_abi_library_beside_it() {
    if crate::common::test_backend(8, 8).is_none() {
        return;
    }
    let exe = Path::new(env!("CARGO_BIN_EXE_fixedgl"));
    let lib = exe.with_file_name("deps").join("libfixedgl_capi.so");
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("bench-capi-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temporary folder");
    let linked = dir.join("fixedgl");
    std::fs::hard_link(exe, &linked).expect("hard link of the binary");
    let bench = |bin: &Path| -> Value {
        let out = Command::new(bin)
            .args(["bench", "triangle", "--frames", "1", "--cpu-only", "--json"])
            .output()
            .unwrap_or_else(|e| panic!("cannot run fixedgl: {e}"));
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).expect("JSON")
    };
    // No library beside it: no figure (the text output says why).
    assert!(bench(&linked)["c_abi_ns_per_call"].is_null());
    if !lib.exists() {
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            std::env::var_os("FIXEDGL_REQUIRE_GL").is_none(),
            "FIXEDGL_REQUIRE_GL is set but {} is not built",
            lib.display()
        );
        println!(
            "SKIPPED: {} is not built (cargo test --workspace builds it)",
            lib.display()
        );
        return;
    }
    std::fs::hard_link(&lib, dir.join("libfixedgl_capi.so")).expect("hard link of the library");
    let v = bench(&linked);
    let _ = std::fs::remove_dir_all(&dir);
    let ns = v["c_abi_ns_per_call"].as_f64();
    assert!(ns.is_some_and(|ns| ns > 0.0 && ns < 1e6), "{v}");
}

/// A closed standard output ends the command line quietly: a reader that stopped reading
/// (`fixedgl list | head -1`) gives status 141, as SIGPIPE would, and no panic message; a write
/// error (a full device) is reported on stderr with status 1.
#[test]
fn cli_output_to_a_closed_pipe_or_a_full_device_ends_quietly() {
    use std::process::Stdio;
    // The read end must be closed before the program writes anything, or a small output
    // fits in the pipe and the run succeeds: a shell waits for its standard input to close,
    // which happens after the read end is closed, and only then runs the program.
    let mut child = Command::new("sh")
        .args(["-c", "cat > /dev/null; exec \"$0\" list"])
        .arg(env!("CARGO_BIN_EXE_fixedgl"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run sh: {e}"));
    drop(child.stdout.take());
    drop(child.stdin.take());
    let out = child.wait_with_output().expect("fixedgl list");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(141), "stderr: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        let out = Command::new(env!("CARGO_BIN_EXE_fixedgl"))
            .arg("list")
            .stdout(full)
            .output()
            .expect("fixedgl list");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "stderr: {stderr}");
        assert!(
            stderr.contains("cannot write to standard output"),
            "{stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
