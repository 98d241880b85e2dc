//! The HTML comparison report: a folder with `index.html` and, per scene, the CPU, GL and
//! difference PNGs, the metrics, pass/fail against the scene's tolerance and both renderer
//! strings. No external assets (styles inline, images relative), so the folder can be archived or
//! opened from CI artifacts as is.
//!
//! Design decision: the report only presents [`crate::compare::Comparison`]s computed elsewhere;
//! it decides nothing, so the CLI's exit status and the page always agree.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use image::RgbaImage;

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

/// Writes `dir/index.html` and the images of every result into `dir` (created if needed) and
/// returns the path of `index.html`.
pub fn write(dir: &Path, renderers: &Renderers, results: &[SceneResult]) -> Result<PathBuf, Error> {
    fs::create_dir_all(dir)?;
    for r in results {
        let stem = file_stem(&r.name);
        r.cpu.save(dir.join(format!("{stem}-cpu.png")))?;
        r.gl.save(dir.join(format!("{stem}-gl.png")))?;
        r.comparison
            .heat_map()
            .save(dir.join(format!("{stem}-diff.png")))?;
        r.comparison
            .side_by_side(&r.cpu, &r.gl)
            .save(dir.join(format!("{stem}-strip.png")))?;
    }
    let index = dir.join("index.html");
    fs::write(&index, html(renderers, results))?;
    Ok(index)
}

/// A file-name-safe version of a scene name.
fn file_stem(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// Minimal HTML escaping for text and attribute values.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn html(renderers: &Renderers, results: &[SceneResult]) -> String {
    let passed = results.iter().filter(|r| r.passed()).count();
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>fixedgl: CPU vs GL</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }}
table {{ border-collapse: collapse; }}
td, th {{ border: 1px solid #ccc; padding: 6px; vertical-align: top; background: #fff; }}
th {{ background: #eee; }}
img {{ image-rendering: pixelated; max-width: min(320px, 22vw); border: 1px solid #888; display: block;
  background: repeating-conic-gradient(#ccc 0 25%, #fff 0 50%) 0 0 / 16px 16px; }}
.pass {{ color: #080; font-weight: bold; }} .fail {{ color: #b00; font-weight: bold; }}
.m {{ font-family: monospace; white-space: pre; font-size: 90%; }}
</style></head><body>
<h1>fixedgl: CPU pipeline vs real GL driver</h1>
<p>CPU: <b>{}</b><br>GL: <b>{}</b> &mdash; {}</p>
<p>{passed} of {} scenes within tolerance. The difference images are magnified {}x
(black = identical; red &rarr; yellow &rarr; white as the largest channel difference grows);
the checkerboard shows through transparent pixels.</p>
<table><tr><th>scene</th><th>CPU</th><th>GL</th><th>difference</th><th>metrics</th></tr>
"#,
        esc(&renderers.cpu),
        esc(&renderers.gl),
        esc(&renderers.gl_version),
        results.len(),
        crate::compare::HEAT_GAIN,
    );
    for r in results {
        let stem = esc(&file_stem(&r.name));
        let c = &r.comparison;
        let (class, verdict) = if r.passed() {
            ("pass", "PASS")
        } else {
            ("fail", "FAIL")
        };
        let metrics = match c.size_mismatch() {
            Some(_) => c.to_string(),
            None => format!(
                "size      {}x{}\nmax diff  R {} G {} B {} A {}\nmean diff R {:.3} G {:.3} B {:.3} A {:.3}\n\
                 &gt; {}    {} px ({:.3}%)\nallowed   {:.3}%\nPSNR      {:.2} dB",
                c.cpu_size.0,
                c.cpu_size.1,
                c.max_diff[0],
                c.max_diff[1],
                c.max_diff[2],
                c.max_diff[3],
                c.mean_diff[0],
                c.mean_diff[1],
                c.mean_diff[2],
                c.mean_diff[3],
                c.tolerance,
                c.differing_pixels,
                c.differing_percent,
                r.tolerance.max_percent,
                c.psnr
            ),
        };
        let _ = writeln!(
            s,
            "<tr><td><b>{}</b><br><span class=\"{class}\">{verdict}</span><br><small>{}</small><br><a href=\"{stem}-strip.png\">side by side</a></td>\
             <td><img src=\"{stem}-cpu.png\" alt=\"CPU\"></td>\
             <td><img src=\"{stem}-gl.png\" alt=\"GL\"></td>\
             <td><img src=\"{stem}-diff.png\" alt=\"difference\"></td>\
             <td class=\"m\">{}</td></tr>",
            esc(&r.name),
            esc(&r.summary),
            metrics
        );
    }
    s.push_str("</table></body></html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::compare;

    #[test]
    fn report_lists_each_scene_with_verdict_and_images() {
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
        };
        // 1 of 16 pixels = 6.25% > 1%: fails; identical passes.
        let results = [result("same", &a), result("off/by", &b)];
        assert!(results[0].passed());
        assert!(!results[1].passed());
        let renderers = Renderers {
            cpu: "fixedgl".into(),
            gl: "llvmpipe".into(),
            gl_version: "4.5".into(),
        };
        let page = html(&renderers, &results);
        assert!(page.contains("1 of 2 scenes within tolerance"));
        assert!(page.contains("<span class=\"pass\">PASS</span>"));
        assert!(page.contains("<span class=\"fail\">FAIL</span>"));
        assert!(page.contains("src=\"off_by-diff.png\""));
        assert!(page.contains("a &lt;test&gt;"));
        assert!(page.contains("6.250%"));
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
        ] {
            assert!(dir.join(f).is_file(), "{f}");
        }
        let _ = fs::remove_dir_all(&dir);
    }
}
