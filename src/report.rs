//! The HTML comparison report, read as people read image diffs: `index.html` is a sortable
//! summary table (worst first), each row linking to a page per scene with the CPU, GL and
//! difference images, flip and slider modes, zoom and pan, the RGBA values under the cursor and a
//! "next difference" control. Beside them: `results.json` (machine-readable, schema in
//! `docs/results.schema.json`), and on request a JUnit XML file ([`junit`]).
//!
//! Self-contained: styles and the page script (`src/report/page.js`, `src/report/index.js`) are
//! inlined, and each detail page carries its two PNGs as `data:` URIs, because a canvas that drew
//! an `<img>` loaded from a `file://` URL is tainted in Chromium and `getImageData` would fail.
//! The page's script computes the difference image, the regions and the readouts from those two
//! images; the PNG files written beside the pages are for people and CI artifacts.
//!
//! Design decisions: the report only presents [`crate::compare::Comparison`]s computed elsewhere;
//! it decides nothing, so the CLI's exit status and the page always agree. The detail page
//! generator ([`write_pages`]) takes a generic list of [`PageItem`]s (title, CPU image, GL image,
//! metrics), so that frames of an animation can get the same pages as scenes.
//!
//! Test hook: a detail page reads its URL fragment on load (`#mode=flip&show=gl&zoom=8&next=1&
//! at=x,y&gain=4&split=0.5`, and `do=click:ID,key:K,tap:CANVAS,hover:CANVAS@fx/fy`, user actions
//! dispatched to its own event handlers) and writes its resulting state as JSON into
//! `<pre id="state">`, so a headless browser's `--dump-dom` shows what a user would see
//! (tests/it/report_browser.rs).

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use image::RgbaImage;
use serde::Serialize;

use crate::compare::Comparison;
use crate::scenes::Tolerance;
use crate::Error;

/// One compared scene.
#[derive(Clone, Debug)]
pub struct SceneResult {
    /// Scene name (also the stem of its image files).
    pub name: String,
    /// The scene's one-line summary.
    pub summary: String,
    /// The tolerance it was judged against.
    pub tolerance: Tolerance,
    /// The metrics.
    pub comparison: Comparison,
    /// The CPU rendering.
    pub cpu: RgbaImage,
    /// The driver's rendering.
    pub gl: RgbaImage,
    /// Milliseconds the CPU pipeline took for this frame, when measured.
    pub cpu_ms: Option<f64>,
    /// Milliseconds the driver took to replay the frame (up to glFinish), when measured.
    pub gl_ms: Option<f64>,
}

impl SceneResult {
    /// Whether the comparison meets the scene's tolerance.
    pub fn passed(&self) -> bool {
        self.comparison.passes(self.tolerance.max_percent)
    }
}

/// Who rendered what, shown at the top of the report.
#[derive(Clone, Debug, Default)]
pub struct Renderers {
    /// The CPU renderer's description (crate name and version).
    pub cpu: String,
    /// The driver's `GL_RENDERER`.
    pub gl: String,
    /// The driver's `GL_VERSION`.
    pub gl_version: String,
}

/// One pair of pictures for a detail page: a scene of `fixedgl compare`, or one frame of an
/// animation compared frame by frame.
#[derive(Clone, Copy, Debug)]
pub struct PageItem<'a> {
    /// The page's file stem (`<stem>.html`); must be file-name safe (see [`file_stem`]).
    pub stem: &'a str,
    /// Heading of the page.
    pub title: &'a str,
    /// One line under the heading.
    pub subtitle: &'a str,
    /// The CPU rendering.
    pub cpu: &'a RgbaImage,
    /// The driver's rendering.
    pub gl: &'a RgbaImage,
    /// Their metrics.
    pub comparison: &'a Comparison,
    /// The tolerance they were judged against.
    pub tolerance: Tolerance,
}

impl PageItem<'_> {
    fn passed(&self) -> bool {
        self.comparison.passes(self.tolerance.max_percent)
    }
}

/// Writes into `dir` (created if needed): `index.html`, `results.json`, one `<scene>.html` per
/// result, and the CPU, GL, difference and side-by-side PNGs of each; returns the path of
/// `index.html`.
pub fn write(dir: &Path, renderers: &Renderers, results: &[SceneResult]) -> Result<PathBuf, Error> {
    fs::create_dir_all(dir)?;
    let stems = stems(results);
    for (r, stem) in results.iter().zip(&stems) {
        r.cpu.save(dir.join(format!("{stem}-cpu.png")))?;
        r.gl.save(dir.join(format!("{stem}-gl.png")))?;
        r.comparison
            .heat_map()
            .save(dir.join(format!("{stem}-diff.png")))?;
        r.comparison
            .side_by_side(&r.cpu, &r.gl)
            .save(dir.join(format!("{stem}-strip.png")))?;
    }
    let items: Vec<PageItem> = results
        .iter()
        .zip(&stems)
        .map(|(r, stem)| PageItem {
            stem,
            title: &r.name,
            subtitle: &r.summary,
            cpu: &r.cpu,
            gl: &r.gl,
            comparison: &r.comparison,
            tolerance: r.tolerance,
        })
        .collect();
    write_pages(dir, renderers, &items, "index.html", "all scenes")?;
    fs::write(dir.join("results.json"), results_json(renderers, results)?)?;
    let index = dir.join("index.html");
    fs::write(&index, index_html(renderers, results))?;
    Ok(index)
}

/// Writes one detail page `<stem>.html` per item into `dir`; each links back to `up_href`
/// (labelled `up_label`) and to the previous and next item in the order that the summary lists
/// them (worst first). Returns the pages' paths.
pub fn write_pages(
    dir: &Path,
    renderers: &Renderers,
    items: &[PageItem],
    up_href: &str,
    up_label: &str,
) -> Result<Vec<PathBuf>, Error> {
    fs::create_dir_all(dir)?;
    let order = worst_first(items.iter().map(|i| (i.passed(), i.comparison)));
    let mut paths = vec![PathBuf::new(); items.len()];
    for (pos, &i) in order.iter().enumerate() {
        let item = &items[i];
        let prev = pos.checked_sub(1).map(|p| &items[order[p]]);
        let next = order.get(pos + 1).map(|&n| &items[n]);
        let page = detail_html(renderers, item, (up_href, up_label), prev, next)?;
        let path = dir.join(format!("{}.html", item.stem));
        fs::write(&path, page)?;
        paths[i] = path;
    }
    Ok(paths)
}

/// The results as JSON (`results.json`, `fixedgl compare --json`); the schema is
/// `docs/results.schema.json`.
pub fn results_json(renderers: &Renderers, results: &[SceneResult]) -> Result<String, Error> {
    let stems = stems(results);
    let scenes = results
        .iter()
        .zip(&stems)
        .map(|(r, stem)| {
            let c = &r.comparison;
            JsonScene {
                name: &r.name,
                summary: &r.summary,
                pass: r.passed(),
                width: c.cpu_size.0,
                height: c.cpu_size.1,
                gl_width: c.gl_size.0,
                gl_height: c.gl_size.1,
                size_mismatch: c.size_mismatch().is_some(),
                tolerance: JsonTolerance {
                    channel: r.tolerance.channel,
                    max_percent: r.tolerance.max_percent,
                },
                metrics: JsonMetrics {
                    max_diff: c.max_diff,
                    mean_diff: c.mean_diff,
                    differing_pixels: c.differing_pixels,
                    differing_percent: c.differing_percent,
                    psnr_db: c.psnr.is_finite().then_some(c.psnr),
                },
                timings_ms: JsonTimings {
                    cpu: r.cpu_ms,
                    gl: r.gl_ms,
                },
                page: format!("{stem}.html"),
                images: JsonImages {
                    cpu: format!("{stem}-cpu.png"),
                    gl: format!("{stem}-gl.png"),
                    diff: format!("{stem}-diff.png"),
                    strip: format!("{stem}-strip.png"),
                },
            }
        })
        .collect();
    let failed = results.iter().filter(|r| !r.passed()).count();
    let doc = JsonResults {
        format: "fixedgl-results/1",
        fixedgl_version: env!("CARGO_PKG_VERSION"),
        cpu_renderer: &renderers.cpu,
        gl_renderer: &renderers.gl,
        gl_version: &renderers.gl_version,
        pass: failed == 0,
        total: results.len(),
        failed,
        scenes,
    };
    let mut s = serde_json::to_string_pretty(&doc).map_err(std::io::Error::from)?;
    s.push('\n');
    Ok(s)
}

/// The results as JUnit XML (`fixedgl compare --junit FILE`): one test suite, one test case per
/// scene, a `<failure>` with the metrics for each scene over its tolerance.
pub fn junit(renderers: &Renderers, results: &[SceneResult]) -> String {
    let failed = results.iter().filter(|r| !r.passed()).count();
    let secs = |r: &SceneResult| (r.cpu_ms.unwrap_or(0.0) + r.gl_ms.unwrap_or(0.0)) / 1e3;
    let total: f64 = results.iter().map(secs).sum();
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        s,
        "<testsuites name=\"fixedgl compare\" tests=\"{}\" failures=\"{failed}\" time=\"{total:.3}\">\n\
         <testsuite name=\"fixedgl.compare\" tests=\"{}\" failures=\"{failed}\" errors=\"0\" skipped=\"0\" time=\"{total:.3}\">\n\
         <properties>\n<property name=\"fixedgl_version\" value=\"{}\"/>\n<property name=\"cpu_renderer\" value=\"{}\"/>\n\
         <property name=\"gl_renderer\" value=\"{}\"/>\n<property name=\"gl_version\" value=\"{}\"/>\n</properties>",
        results.len(),
        results.len(),
        env!("CARGO_PKG_VERSION"),
        esc(&renderers.cpu),
        esc(&renderers.gl),
        esc(&renderers.gl_version),
    );
    for r in results {
        let _ = write!(
            s,
            "<testcase classname=\"fixedgl.compare\" name=\"{}\" time=\"{:.3}\"",
            esc(&r.name),
            secs(r)
        );
        if r.passed() {
            s.push_str("/>\n");
        } else {
            let c = &r.comparison;
            let message = match c.size_mismatch() {
                Some(_) => c.to_string(),
                None => format!(
                    "{:.3}% of pixels differ by more than {} (allowed {:.3}%)",
                    c.differing_percent, c.tolerance, r.tolerance.max_percent
                ),
            };
            let _ = write!(
                s,
                ">\n<failure message=\"{}\" type=\"tolerance\">{}</failure>\n</testcase>\n",
                esc(&message),
                esc(&c.to_string())
            );
        }
    }
    s.push_str("</testsuite>\n</testsuites>\n");
    s
}

#[derive(Serialize)]
struct JsonResults<'a> {
    format: &'static str,
    fixedgl_version: &'static str,
    cpu_renderer: &'a str,
    gl_renderer: &'a str,
    gl_version: &'a str,
    pass: bool,
    total: usize,
    failed: usize,
    scenes: Vec<JsonScene<'a>>,
}

#[derive(Serialize)]
struct JsonScene<'a> {
    name: &'a str,
    summary: &'a str,
    pass: bool,
    width: u32,
    height: u32,
    gl_width: u32,
    gl_height: u32,
    size_mismatch: bool,
    tolerance: JsonTolerance,
    metrics: JsonMetrics,
    timings_ms: JsonTimings,
    page: String,
    images: JsonImages,
}

#[derive(Serialize)]
struct JsonTolerance {
    channel: u8,
    max_percent: f64,
}

#[derive(Serialize)]
struct JsonMetrics {
    max_diff: [u8; 4],
    mean_diff: [f64; 4],
    differing_pixels: u64,
    differing_percent: f64,
    /// `None` (JSON null) when the colour channels are identical (infinite PSNR).
    psnr_db: Option<f64>,
}

#[derive(Serialize)]
struct JsonTimings {
    cpu: Option<f64>,
    gl: Option<f64>,
}

#[derive(Serialize)]
struct JsonImages {
    cpu: String,
    gl: String,
    diff: String,
    strip: String,
}

/// A file-name-safe version of a scene name (never `index`, the summary's name).
pub fn file_stem(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    match s.as_str() {
        "" => "_".into(),
        "index" | "results" => format!("{s}_"),
        _ => s,
    }
}

fn stems(results: &[SceneResult]) -> Vec<String> {
    results.iter().map(|r| file_stem(&r.name)).collect()
}

/// Indices of the items, worst first: size mismatches, then failures, then by the share of
/// pixels over tolerance, then by the largest channel difference, then by PSNR (lower first).
fn worst_first<'a>(items: impl Iterator<Item = (bool, &'a Comparison)>) -> Vec<usize> {
    let items: Vec<(bool, &Comparison)> = items.collect();
    let mut order: Vec<usize> = (0..items.len()).collect();
    order.sort_by(|&a, &b| {
        let (pa, ca) = items[a];
        let (pb, cb) = items[b];
        let key = |p: bool, c: &Comparison| {
            (
                c.size_mismatch().is_none(),
                p,
                std::cmp::Reverse(c.max_diff.iter().copied().max().unwrap_or(0)),
            )
        };
        key(pa, ca)
            .0
            .cmp(&key(pb, cb).0)
            .then(pa.cmp(&pb))
            .then(cb.differing_percent.total_cmp(&ca.differing_percent))
            .then(key(pa, ca).2.cmp(&key(pb, cb).2))
            .then(ca.psnr.total_cmp(&cb.psnr))
    });
    order
}

/// Minimal HTML/XML escaping for text and attribute values.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number for a table cell: fixed decimals, `∞` / `—` for what is not a finite number.
fn num(v: f64, decimals: usize) -> String {
    if v.is_nan() {
        "&mdash;".into()
    } else if v.is_infinite() {
        "&infin;".into()
    } else {
        format!("{v:.decimals$}")
    }
}

/// A sort key attribute value (infinity sorts as a large number, NaN / unknown as -1).
fn key(v: f64) -> String {
    if v.is_nan() {
        "-1".into()
    } else if v.is_infinite() {
        "1e9".into()
    } else {
        format!("{v}")
    }
}

const BASE_CSS: &str = include_str!("report/base.css");
const INDEX_JS: &str = include_str!("report/index.js");
const PAGE_JS: &str = include_str!("report/page.js");

fn head(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\
         <title>{}</title>\n<style>\n{BASE_CSS}</style></head>\n",
        esc(title)
    )
}

fn index_html(renderers: &Renderers, results: &[SceneResult]) -> String {
    let passed = results.iter().filter(|r| r.passed()).count();
    let failed = results.len() - passed;
    let mut s = head("fixedgl: CPU vs GL");
    let _ = write!(
        s,
        "<body class=\"index\">\n<header><h1>fixedgl: CPU pipeline vs real GL driver</h1>\n\
         <p class=\"verdict {}\">{passed} of {} scenes within tolerance{}</p>\n\
         <p class=\"who\">CPU: <b>{}</b> &middot; GL: <b>{}</b> &middot; {}</p></header>\n\
         <p class=\"hint\">Worst first; click a column heading to sort. A scene's name opens its \
         page: flip, slider, zoom, values under the cursor, next difference. \
         Machine-readable: <a href=\"results.json\">results.json</a>.</p>\n\
         <div class=\"scroll\"><table id=\"summary\" class=\"summary\">\n<thead><tr>\
         <th data-type=\"text\">scene</th>\
         <th data-type=\"num\" title=\"FAIL sorts first\">result</th>\
         <th data-type=\"num\" title=\"pixels where some channel differs by more than the scene's channel tolerance\">over tol.</th>\
         <th data-type=\"num\" class=\"opt\">pixels</th>\
         <th data-type=\"num\" title=\"the most that may be over tolerance\">allowed</th>\
         <th data-type=\"num\" title=\"largest channel difference (of 255); tooltip: R G B A\">max &Delta;</th>\
         <th data-type=\"num\" class=\"opt\" title=\"mean difference over R, G and B; tooltip: R G B A\">mean &Delta;</th>\
         <th data-type=\"num\" class=\"opt\" title=\"PSNR over RGB\">PSNR dB</th>\
         <th data-type=\"num\" class=\"opt\" title=\"one frame on fixedgl's CPU pipeline (fixedgl bench measures properly)\">CPU ms</th>\
         <th data-type=\"num\" class=\"opt\" title=\"the driver replaying the frame, up to glFinish\">GL ms</th>\
         </tr></thead>\n<tbody>\n",
        if failed == 0 { "pass" } else { "fail" },
        results.len(),
        if failed == 0 {
            String::new()
        } else {
            format!(" &mdash; <b>{failed} over tolerance</b>")
        },
        esc(&renderers.cpu),
        esc(&renderers.gl),
        esc(&renderers.gl_version),
    );
    let order = worst_first(results.iter().map(|r| (r.passed(), &r.comparison)));
    for (rank, &i) in order.iter().enumerate() {
        let r = &results[i];
        let c = &r.comparison;
        let stem = esc(&file_stem(&r.name));
        let (class, verdict) = if r.passed() {
            ("pass", "PASS")
        } else {
            ("fail", "FAIL")
        };
        let max = c.max_diff.iter().copied().max().unwrap_or(0);
        let mean_rgb = (c.mean_diff[0] + c.mean_diff[1] + c.mean_diff[2]) / 3.0;
        let ms = |v: Option<f64>| {
            let v = v.unwrap_or(f64::NAN);
            format!(
                "<td class=\"opt\" data-key=\"{}\">{}</td>",
                key(v),
                num(v, 1)
            )
        };
        let over = match c.size_mismatch() {
            Some(((cw, ch), (gw, gh))) => format!("size {cw}x{ch} vs {gw}x{gh}"),
            None => format!("{:.3}%", c.differing_percent),
        };
        let _ = writeln!(
            s,
            "<tr class=\"{class}\" data-rank=\"{rank}\"><td data-key=\"{}\"><a href=\"{stem}.html\">{}</a>\
             <div class=\"sub\">{}</div></td>\
             <td data-key=\"{}\"><span class=\"badge {class}\">{verdict}</span></td>\
             <td data-key=\"{}\">{over}</td>\
             <td class=\"opt\" data-key=\"{}\">{}</td>\
             <td data-key=\"{}\">{:.3}%</td>\
             <td data-key=\"{max}\" title=\"R {} G {} B {} A {}\">{max}</td>\
             <td class=\"opt\" data-key=\"{}\" title=\"R {:.3} G {:.3} B {:.3} A {:.3}\">{:.3}</td>\
             <td class=\"opt\" data-key=\"{}\">{}</td>{}{}</tr>",
            esc(&r.name),
            esc(&r.name),
            esc(&r.summary),
            u8::from(r.passed()),
            key(c.differing_percent),
            c.differing_pixels,
            c.differing_pixels,
            key(r.tolerance.max_percent),
            r.tolerance.max_percent,
            c.max_diff[0],
            c.max_diff[1],
            c.max_diff[2],
            c.max_diff[3],
            key(mean_rgb),
            c.mean_diff[0],
            c.mean_diff[1],
            c.mean_diff[2],
            c.mean_diff[3],
            mean_rgb,
            key(-c.psnr),
            num(c.psnr, 2),
            ms(r.cpu_ms),
            ms(r.gl_ms),
        );
    }
    let _ = write!(
        s,
        "</tbody></table></div>\n<script>\n{INDEX_JS}</script>\n</body></html>\n"
    );
    s
}

/// What the page script needs besides the two images.
#[derive(Serialize)]
struct PageData {
    tol: u8,
    gain: u32,
    cpu: String,
    gl: String,
}

fn detail_html(
    renderers: &Renderers,
    item: &PageItem,
    (up_href, up_label): (&str, &str),
    prev: Option<&PageItem>,
    next: Option<&PageItem>,
) -> Result<String, Error> {
    let c = item.comparison;
    let (class, verdict) = if item.passed() {
        ("pass", "PASS")
    } else {
        ("fail", "FAIL")
    };
    let link = |p: Option<&PageItem>, rel: &str, arrow: &str| match p {
        Some(p) => format!(
            "<a rel=\"{rel}\" href=\"{}.html\">{arrow} {}</a>",
            esc(p.stem),
            esc(p.title)
        ),
        None => String::new(),
    };
    let data = PageData {
        tol: c.tolerance,
        gain: crate::compare::HEAT_GAIN,
        cpu: data_uri(item.cpu)?,
        gl: data_uri(item.gl)?,
    };
    // Inside <script type="application/json">: only "</" could end the element early.
    let data = serde_json::to_string(&data)
        .map_err(std::io::Error::from)?
        .replace("</", "<\\/");
    let mut s = head(&format!("{} — fixedgl CPU vs GL", item.title));
    let size = match c.size_mismatch() {
        Some(((cw, ch), (gw, gh))) => format!("<b>size mismatch</b>: CPU {cw}x{ch}, GL {gw}x{gh}"),
        None => format!("{}x{}", c.cpu_size.0, c.cpu_size.1),
    };
    let _ = write!(
        s,
        "<body class=\"page\">\n<nav class=\"crumbs\"><a rel=\"up\" href=\"{}\">&uarr; {}</a>{}{}</nav>\n\
         <header><h1>{} <span class=\"badge {class}\">{verdict}</span></h1><p class=\"sub\">{}</p>\n\
         <p class=\"metrics\">{size} &middot; over tolerance (&gt;{}): <b>{} px = {:.3}%</b> (allowed {:.3}%) \
         &middot; max &Delta; R {} G {} B {} A {} &middot; mean &Delta; {:.3} {:.3} {:.3} {:.3} &middot; PSNR {} dB</p>\n\
         <p class=\"who\">CPU: {} &middot; GL: {} &middot; {}</p></header>\n",
        esc(up_href),
        esc(up_label),
        link(prev, "prev", "&larr;"),
        link(next, "next", "&rarr;"),
        esc(item.title),
        esc(item.subtitle),
        c.tolerance,
        c.differing_pixels,
        c.differing_percent,
        item.tolerance.max_percent,
        c.max_diff[0],
        c.max_diff[1],
        c.max_diff[2],
        c.max_diff[3],
        c.mean_diff[0],
        c.mean_diff[1],
        c.mean_diff[2],
        c.mean_diff[3],
        num(c.psnr, 2),
        esc(&renderers.cpu),
        esc(&renderers.gl),
        esc(&renderers.gl_version),
    );
    s.push_str(PAGE_BODY);
    let _ = write!(
        s,
        "<script type=\"application/json\" id=\"frame-data\">{data}</script>\n<script>\n{PAGE_JS}</script>\n</body></html>\n"
    );
    Ok(s)
}

/// The detail page's controls and views (filled in by `page.js`).
const PAGE_BODY: &str = r#"<div class="bar" id="bar">
<div class="tools">
<span class="group" role="group" aria-label="mode">
<button id="mode-side" data-mode="side" title="CPU, GL and difference side by side (1)">side by side</button><button id="mode-flip" data-mode="flip" title="one image, click or F / space toggles CPU and GL (2)">flip</button><button id="mode-slider" data-mode="slider" title="CPU left of the handle, GL right (3)">slider</button>
</span>
<span class="group"><button id="zoom-out" title="zoom out (-)">&minus;</button><span id="zoom-label">1x</span><button id="zoom-in" title="zoom in (+)">+</button><button id="zoom-reset" title="whole image (0)">fit</button></span>
<label class="group" title="multiply the difference before colouring">diff &times;<select id="gain"><option>1</option><option>4</option><option>16</option><option>64</option><option>255</option></select></label>
<label class="group"><input type="checkbox" id="marks" checked> mark</label>
<span class="group"><button id="next-diff" title="zoom to the next differing region (N)">next difference</button> <span id="region-label"></span></span>
</div>
<div class="readout" id="readout">move over an image to read its pixels</div>
</div>
<div class="views" id="views">
<figure class="view" id="view-a"><figcaption id="cap-a">CPU</figcaption><canvas id="canvas-a"></canvas><input type="range" id="split" min="0" max="1000" value="500" aria-label="slider position"></figure>
<figure class="view" id="view-b"><figcaption>GL</figcaption><canvas id="canvas-b"></canvas></figure>
<figure class="view" id="view-d"><figcaption id="cap-d">difference</figcaption><canvas id="canvas-d"></canvas></figure>
</div>
<p class="hint">Drag to pan, wheel or +/&minus; to zoom (pixels stay square), F or click toggles in flip mode, N jumps to the next difference. The difference is the largest channel difference, black = equal, dark red &rarr; red &rarr; yellow &rarr; white as it grows, multiplied by the factor above; the boxes mark pixels over the scene's tolerance (or, where none are, every differing pixel).</p>
<pre id="state" hidden>{}</pre>
"#;

/// A PNG of `img` as a `data:image/png;base64,` URI.
fn data_uri(img: &RgbaImage) -> Result<String, Error> {
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)?;
    Ok(format!("data:image/png;base64,{}", base64(&png)))
}

/// Standard base64 with padding (RFC 4648).
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * i)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::compare;

    fn results() -> (Renderers, Vec<SceneResult>) {
        let a = RgbaImage::from_pixel(4, 4, image::Rgba([0, 0, 0, 255]));
        let mut b = a.clone();
        b.put_pixel(0, 0, image::Rgba([9, 0, 0, 255]));
        let tol = Tolerance {
            channel: 2,
            max_percent: 1.0,
        };
        let result = |name: &str, gl: &RgbaImage| SceneResult {
            name: name.into(),
            summary: "a <test>".into(),
            tolerance: tol,
            comparison: compare(&a, gl, tol.channel),
            cpu: a.clone(),
            gl: gl.clone(),
            cpu_ms: Some(1.5),
            gl_ms: None,
        };
        let renderers = Renderers {
            cpu: "fixedgl".into(),
            gl: "llvmpipe".into(),
            gl_version: "4.5".into(),
        };
        // 1 of 16 pixels = 6.25% > 1%: fails; identical passes.
        (renderers, vec![result("same", &a), result("off/by", &b)])
    }

    #[test]
    fn summary_lists_each_scene_worst_first_with_verdict_and_link() {
        let (renderers, results) = results();
        assert!(results[0].passed());
        assert!(!results[1].passed());
        let page = index_html(&renderers, &results);
        assert!(page.contains("1 of 2 scenes within tolerance"));
        assert!(page.contains("<span class=\"badge pass\">PASS</span>"));
        assert!(page.contains("<span class=\"badge fail\">FAIL</span>"));
        assert!(page.contains("a &lt;test&gt;"));
        assert!(page.contains("6.250%"));
        // The failing scene's row comes first, linking to its page.
        let off = page.find("href=\"off_by.html\"");
        let same = page.find("href=\"same.html\"");
        assert!(off.is_some() && same.is_some() && off < same, "{page}");
        assert!(!page.contains("http://") && !page.contains("https://"));
    }

    #[test]
    fn report_folder_has_pages_images_and_results() {
        let (renderers, results) = results();
        let dir = std::env::temp_dir().join(format!("fixedgl-report-{}", std::process::id()));
        let index = write(&dir, &renderers, &results).map_err(|e| e.to_string());
        assert_eq!(
            index.as_deref().ok(),
            Some(dir.join("index.html").as_path())
        );
        for f in [
            "same-cpu.png",
            "same-gl.png",
            "off_by-diff.png",
            "off_by-strip.png",
            "off_by.html",
            "same.html",
            "results.json",
        ] {
            assert!(dir.join(f).is_file(), "{f}");
        }
        let page = fs::read_to_string(dir.join("off_by.html")).unwrap_or_default();
        assert!(page.contains("data:image/png;base64,"));
        assert!(page.contains("rel=\"up\" href=\"index.html\""));
        // Worst first: the failing page has no previous page and links to the passing one.
        assert!(page.contains("rel=\"next\" href=\"same.html\""));
        assert!(!page.contains("rel=\"prev\""));
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn results_json_and_junit_carry_the_metrics() {
        let (renderers, results) = results();
        let json = results_json(&renderers, &results).unwrap_or_default();
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["total"], 2);
        assert_eq!(v["failed"], 1);
        assert_eq!(v["pass"], false);
        assert_eq!(v["scenes"][1]["name"], "off/by");
        assert_eq!(v["scenes"][1]["metrics"]["differing_pixels"], 1);
        assert_eq!(v["scenes"][1]["metrics"]["max_diff"][0], 9);
        // Identical images: infinite PSNR is null.
        assert!(v["scenes"][0]["metrics"]["psnr_db"].is_null());
        assert_eq!(v["scenes"][0]["timings_ms"]["cpu"], 1.5);
        assert!(v["scenes"][0]["timings_ms"]["gl"].is_null());
        let xml = junit(&renderers, &results);
        assert!(xml.contains("tests=\"2\" failures=\"1\""));
        assert!(xml.contains("<testcase classname=\"fixedgl.compare\" name=\"same\""));
        assert!(xml.contains("<failure message=\"6.250% of pixels differ by more than 2"));
    }

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn file_stems_are_safe_and_never_the_index() {
        assert_eq!(file_stem("off/by"), "off_by");
        assert_eq!(file_stem("index"), "index_");
        assert_eq!(file_stem(""), "_");
    }
}
