//! The HTML report in a real browser: headless Chromium opens a report as a user would, and the
//! pages' own state (not the HTML we wrote) is checked: the summary is there, fits a 1280-pixel
//! and a phone-sized window, lists the worst scene first and sorts by a clicked heading; a scene
//! page flips to GL, zooms, reads the RGBA values under the cursor and jumps to the differing
//! pixels with "next difference"; the difference its script computes agrees with `compare`'s
//! count. Screenshots of the summary
//! and of a zoomed scene page go to `target/report-screenshots/` for a person to look at.
//!
//! How: `chromium --headless --dump-dom` on `file://` URLs whose fragment drives the page: state
//! set directly (`#flip&show=gl&zoom=8&at=x,y`, `#next=1`) or user actions dispatched to the
//! page's own click, key and pointer handlers (`#do=click:mode-flip,tap:canvas-a,key:+`); the page
//! writes its state as JSON into `<pre id="state">`. `--screenshot` for the pictures. No DevTools-protocol crate: its dependency tree (websocket, TLS, async
//! runtime) would cost more to build than this whole test needs.
//!
//! Skips with `SKIPPED: ...` when no Chromium is found (`FIXEDGL_CHROMIUM`, else `chromium`,
//! `chromium-browser`, `google-chrome` on PATH) and `FIXEDGL_REQUIRE_GL` is unset; on CI
//! (`.ci/run` installs chromium and sets it) a missing browser fails.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use fixedgl::compare::compare;
use fixedgl::report::{self, Renderers, SceneResult};
use fixedgl::scenes::{self, Tolerance};
use image::{Rgba, RgbaImage};
use serde_json::Value;

fn find_chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("FIXEDGL_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    [
        "chromium",
        "chromium-browser",
        "google-chrome",
        "google-chrome-stable",
    ]
    .iter()
    .flat_map(|name| std::env::split_paths(&path).map(move |d| d.join(name)))
    .find(|p| p.is_file())
}

/// The browser, or `None` after printing why the test is skipped.
fn chromium() -> Option<PathBuf> {
    match find_chromium() {
        Some(p) => Some(p),
        None if std::env::var_os("FIXEDGL_REQUIRE_GL").is_some() => panic!(
            "FIXEDGL_REQUIRE_GL is set but no Chromium was found (set FIXEDGL_CHROMIUM or install \
             chromium; .ci/run does)"
        ),
        None => {
            eprintln!("SKIPPED: no Chromium (chromium, chromium-browser, google-chrome) on PATH");
            None
        }
    }
}

/// Runs headless Chromium on `url` with `args` in a `width` x `height` window; its stdout.
fn headless(browser: &Path, args: &[&str], url: &str, (width, height): (u32, u32)) -> String {
    let profile = tempdir("profile");
    let mut child = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--virtual-time-budget=10000",
            &format!("--window-size={width},{height}"),
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(url)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {}: {e}", browser.display()));
    // A browser that hangs must not hang the suite: wait at most a minute.
    let deadline = Instant::now() + Duration::from_secs(60);
    let stdout = child.stdout.take();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        if let Some(mut out) = stdout {
            let _ = std::io::Read::read_to_string(&mut out, &mut s);
        }
        s
    });
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(50)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                panic!("chromium did not finish {url} within 60 s");
            }
        }
    }
    let _ = std::fs::remove_dir_all(&profile);
    reader.join().unwrap_or_default()
}

fn tempdir(what: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "report-browser-{what}-{}-{:?}",
        std::process::id(),
        Instant::now()
    ));
    let _ = std::fs::create_dir_all(&d);
    d
}

fn url(path: &Path, fragment: &str) -> String {
    format!("file://{}{fragment}", path.display())
}

/// The page's state JSON from a `--dump-dom` dump.
fn state(dom: &str) -> Value {
    let text = dom
        .split_once("<pre id=\"state\"")
        .and_then(|(_, rest)| rest.split_once('>'))
        .and_then(|(_, rest)| rest.split_once("</pre>"))
        .map(|(s, _)| {
            s.replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&")
        })
        .unwrap_or_else(|| panic!("no state in the page:\n{dom}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("state {text:?}: {e}"))
}

fn px(img: &RgbaImage, x: u32, y: u32) -> Value {
    Value::from(img.get_pixel(x, y).0.to_vec())
}

/// The differing block the "GL" picture gets: 6 x 4 pixels at (300, 100), red channel XOR 64.
const BLOCK: (u32, u32, u32, u32) = (300, 100, 6, 4);

/// A report of two scenes: textured-cube as the CPU renders it against a copy with `BLOCK`
/// changed (judged strictly, so it fails), and the triangle against itself (passes).
fn write_report(dir: &Path) -> (RgbaImage, RgbaImage, u64) {
    let render = |name: &str, w, h| {
        let scene = scenes::find(name).unwrap_or_else(|| panic!("no scene {name}"));
        let (mut ctx, _) = scene.record(w, h).unwrap_or_else(|e| panic!("{name}: {e}"));
        (scene, ctx.to_image())
    };
    let (cube, cpu) = render("textured-cube", 480, 320);
    let mut gl = cpu.clone();
    let (bx, by, bw, bh) = BLOCK;
    for y in by..by + bh {
        for x in bx..bx + bw {
            let Rgba([r, g, b, a]) = *gl.get_pixel(x, y);
            gl.put_pixel(x, y, Rgba([r ^ 64, g, b, a]));
        }
    }
    let strict = Tolerance {
        channel: 2,
        max_percent: 0.01,
    };
    let (tri, tri_img) = render("triangle", 200, 200);
    let results = vec![
        SceneResult {
            name: tri.name.into(),
            summary: tri.summary.into(),
            tolerance: tri.tolerance,
            comparison: compare(&tri_img, &tri_img, tri.tolerance.channel),
            cpu: tri_img.clone(),
            gl: tri_img,
            cpu_ms: Some(1.0),
            gl_ms: None,
        },
        SceneResult {
            name: cube.name.into(),
            summary: cube.summary.into(),
            tolerance: strict,
            comparison: compare(&cpu, &gl, strict.channel),
            cpu: cpu.clone(),
            gl: gl.clone(),
            cpu_ms: Some(2.0),
            gl_ms: Some(3.0),
        },
    ];
    let differing = results[1].comparison.differing_pixels;
    let renderers = Renderers {
        cpu: "fixedgl (CPU)".into(),
        gl: "the CPU image with a block changed (browser test)".into(),
        gl_version: "-".into(),
    };
    report::write(dir, &renderers, &results).unwrap_or_else(|e| panic!("report: {e}"));
    (cpu, gl, differing)
}

#[test]
fn report_reads_in_a_real_browser_summary_flip_zoom_values_next_difference() {
    let Some(browser) = chromium() else {
        return;
    };
    let shots = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/report-screenshots");
    let dir = shots.join("report");
    let _ = std::fs::remove_dir_all(&dir);
    let (cpu, gl, differing) = write_report(&dir);
    assert_eq!(differing, u64::from(BLOCK.2 * BLOCK.3));
    let index = dir.join("index.html");
    let page = dir.join("textured-cube.html");
    let dump = |path: &Path, fragment: &str, size| {
        headless(&browser, &["--dump-dom"], &url(path, fragment), size)
    };

    // The summary: there, worst (failing) scene first, no horizontal scrolling at 1280 px nor
    // on a phone.
    for size in [(1280, 900), (390, 844)] {
        let dom = dump(&index, "", size);
        assert!(dom.contains("1 of 2 scenes within tolerance"), "{dom}");
        assert!(
            dom.contains("data-fits=\"true\""),
            "summary overflows at {size:?}"
        );
        let first_row = dom.split("<tbody>").nth(1).unwrap_or_default();
        let cube = first_row.find("href=\"textured-cube.html\"");
        let tri = first_row.find("href=\"triangle.html\"");
        assert!(
            cube.is_some() && tri.is_some() && cube < tri,
            "not worst first:\n{dom}"
        );
    }

    // Sorting: "max Δ" clicked twice is ascending, so the identical triangle comes first.
    let dom = dump(&index, "#sort=5,5", (1280, 900));
    let rows = dom.split("<tbody>").nth(1).unwrap_or_default();
    let cube = rows.find("href=\"textured-cube.html\"");
    let tri = rows.find("href=\"triangle.html\"");
    assert!(
        cube.is_some() && tri.is_some() && tri < cube,
        "not sorted:\n{dom}"
    );
    assert!(dom.contains("aria-sort=\"ascending\""), "{dom}");

    // A scene page: the script's difference agrees with compare's count; it fits 1280 px.
    let s = state(&dump(&page, "", (1280, 900)));
    assert_eq!(s["ready"], true, "{s}");
    assert_eq!(s["mode"], "side");
    assert_eq!(s["over_tolerance"], differing, "{s}");
    assert_eq!(s["regions"], 1, "{s}");
    assert_eq!(s["fits"], true, "scene page overflows 1280 px: {s}");

    // Flip to GL, zoom 8x, cursor on a changed pixel: the values of both and their difference.
    let (x, y) = (BLOCK.0 + 2, BLOCK.1 + 1);
    let s = state(&dump(
        &page,
        &format!("#flip&show=gl&zoom=8&at={x},{y}"),
        (1280, 900),
    ));
    assert_eq!(
        (&s["mode"], &s["show"], &s["zoom"]),
        (&"flip".into(), &"gl".into(), &8.into())
    );
    assert_eq!(s["cursor"], Value::from(vec![x, y]));
    assert_eq!(s["values"]["cpu"], px(&cpu, x, y), "{s}");
    assert_eq!(s["values"]["gl"], px(&gl, x, y), "{s}");
    assert_eq!(s["values"]["diff"], Value::from(vec![64, 0, 0, 0]), "{s}");

    // "next difference": zoomed onto the changed block, cursor on one of its pixels.
    let s = state(&dump(&page, "#next=1", (1280, 900)));
    let b = &s["region_box"];
    let (bx, by, bw, bh) = BLOCK;
    let got: Vec<u64> = ["x0", "y0", "x1", "y1", "count"]
        .iter()
        .map(|k| b[k].as_u64().unwrap_or(u64::MAX))
        .collect();
    let want = [bx, by, bx + bw - 1, by + bh - 1].map(u64::from);
    assert_eq!(got, [&want[..], &[differing]].concat(), "{s}");
    assert!(s["zoom"].as_u64() >= Some(8), "{s}");
    assert_eq!(s["values"]["worst"], 64, "{s}");
    // The same as a user does it, through the page's own handlers: the flip button, a click on
    // the image (now GL), + three times (8x), the pointer over the middle of the image.
    let s = state(&dump(
        &page,
        "#do=click:mode-flip,tap:canvas-a,key:+,key:+,key:+,hover:canvas-a@0.5/0.5",
        (1280, 900),
    ));
    assert_eq!(
        (&s["mode"], &s["show"], &s["zoom"]),
        (&"flip".into(), &"gl".into(), &8.into()),
        "{s}"
    );
    let (w, h) = cpu.dimensions();
    assert_eq!(s["cursor"], Value::from(vec![w / 2, h / 2]), "{s}");
    assert_eq!(s["values"]["cpu"], px(&cpu, w / 2, h / 2), "{s}");
    assert_eq!(s["values"]["gl"], px(&gl, w / 2, h / 2), "{s}");
    // Key F in flip mode flips back to CPU; the "next difference" button selects the block.
    let s = state(&dump(
        &page,
        "#do=click:mode-flip,key:f,key:f,click:next-diff",
        (1280, 900),
    ));
    assert_eq!(
        (&s["show"], &s["region"]),
        (&"cpu".into(), &0.into()),
        "{s}"
    );
    assert_eq!(s["values"]["worst"], 64, "{s}");
    // Slider mode from the fragment.
    let s = state(&dump(&page, "#mode=slider&split=0.25", (1280, 900)));
    assert_eq!((&s["mode"], &s["split"]), (&"slider".into(), &0.25.into()));

    // Screenshots for people: the summary, and the scene page zoomed onto the difference.
    for (name, path, fragment) in [
        ("summary.png", &index, ""),
        ("scene-zoomed.png", &page, "#next=1&mode=flip&show=gl"),
    ] {
        let out = shots.join(name);
        let _ = std::fs::remove_file(&out);
        headless(
            &browser,
            &[&format!("--screenshot={}", out.display())],
            &url(path, fragment),
            (1280, 900),
        );
        let img = image::open(&out).unwrap_or_else(|e| panic!("{}: {e}", out.display()));
        assert_eq!(img.width(), 1280, "{name}");
        println!("screenshot: {}", out.display());
    }
}
