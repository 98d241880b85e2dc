//! Image comparison of a CPU rendering against the real driver's: per-channel error metrics, the
//! count of pixels outside a tolerance, PSNR, an amplified difference heat map and a labelled
//! side-by-side strip (CPU | GL | difference).
//!
//! This is not a GL feature (nothing in the spec): it is how fixedgl measures its fidelity to the
//! driver. The one design decision to know: images of different sizes are a *result*, not an
//! error — [`Comparison::size_mismatch`] is set, the metrics cover the overlapping rectangle with
//! every pixel outside it counted as differing by 255, and such a comparison never passes.

use image::{Rgba, RgbaImage};

/// The outcome of [`compare`]: how far two renderings of the same scene are apart.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Width and height of the first (CPU) image.
    pub cpu_size: (u32, u32),
    /// Width and height of the second (GL) image.
    pub gl_size: (u32, u32),
    /// Per channel (R, G, B, A): the largest absolute difference over all pixels.
    pub max_diff: [u8; 4],
    /// Per channel (R, G, B, A): the mean absolute difference over all pixels.
    pub mean_diff: [f64; 4],
    /// The tolerance the pixel count below was taken against.
    pub tolerance: u8,
    /// Pixels where some channel differs by more than `tolerance`.
    pub differing_pixels: u64,
    /// `differing_pixels` as a percentage of all pixels (0 for empty images).
    pub differing_percent: f64,
    /// Peak signal-to-noise ratio in dB over R, G and B: `10 log10(255² / MSE)`; infinite when the
    /// colour channels are identical.
    pub psnr: f64,
    /// The largest channel difference of each pixel of the compared area (row-major, top-down,
    /// `max(cpu_size, gl_size)`), the input of the heat map.
    per_pixel: Vec<u8>,
    /// Width of the compared area (`per_pixel` row length).
    area_width: u32,
}

/// How many times a difference is magnified in the heat map: a difference of 16 (of 255) is
/// already full brightness, so the 1-2 LSB differences that rounding produces are visible.
pub const HEAT_GAIN: u32 = 16;

/// Compares `cpu` with `gl` channel by channel. A pixel "differs" when any channel's absolute
/// difference exceeds `tolerance`. Never panics: differently sized images give a comparison with
/// [`Comparison::size_mismatch`] set.
pub fn compare(cpu: &RgbaImage, gl: &RgbaImage, tolerance: u8) -> Comparison {
    let (cw, ch) = cpu.dimensions();
    let (gw, gh) = gl.dimensions();
    let (w, h) = (cw.max(gw), ch.max(gh));
    let pixels = w as u64 * h as u64;
    let mut per_pixel = Vec::with_capacity(pixels as usize);
    let mut max_diff = [0u8; 4];
    let mut sum = [0u64; 4];
    let mut squared = 0u64;
    let mut differing = 0u64;
    for y in 0..h {
        for x in 0..w {
            let d: [u8; 4] = match (cpu.get_pixel_checked(x, y), gl.get_pixel_checked(x, y)) {
                (Some(a), Some(b)) => std::array::from_fn(|c| a.0[c].abs_diff(b.0[c])),
                // Outside the overlap: everything differs by the full range.
                _ => [255; 4],
            };
            for c in 0..4 {
                max_diff[c] = max_diff[c].max(d[c]);
                sum[c] += u64::from(d[c]);
            }
            squared += d[..3]
                .iter()
                .map(|&v| u64::from(v) * u64::from(v))
                .sum::<u64>();
            let worst = d.iter().copied().max().unwrap_or(0);
            if worst > tolerance {
                differing += 1;
            }
            per_pixel.push(worst);
        }
    }
    let n = pixels.max(1) as f64;
    let mse = squared as f64 / (3.0 * n);
    let psnr = if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0f64 * 255.0 / mse).log10()
    };
    Comparison {
        cpu_size: (cw, ch),
        gl_size: (gw, gh),
        max_diff,
        mean_diff: sum.map(|s| s as f64 / n),
        tolerance,
        differing_pixels: differing,
        differing_percent: if pixels == 0 {
            0.0
        } else {
            100.0 * differing as f64 / pixels as f64
        },
        psnr,
        per_pixel,
        area_width: w,
    }
}

impl Comparison {
    /// `Some((cpu_size, gl_size))` when the two images had different sizes.
    pub fn size_mismatch(&self) -> Option<((u32, u32), (u32, u32))> {
        (self.cpu_size != self.gl_size).then_some((self.cpu_size, self.gl_size))
    }

    /// True when the sizes agree and at most `max_percent` percent of the pixels differ by more
    /// than the tolerance.
    pub fn passes(&self, max_percent: f64) -> bool {
        self.size_mismatch().is_none() && self.differing_percent <= max_percent
    }

    /// The difference image: black where equal, then dark red → red → yellow → white as the
    /// largest channel difference grows, magnified [`HEAT_GAIN`] times (saturating).
    pub fn heat_map(&self) -> RgbaImage {
        self.heat_map_with_gain(HEAT_GAIN)
    }

    /// [`Comparison::heat_map`] magnified `gain` times instead of [`HEAT_GAIN`] (`fixedgl view
    /// --compare` changes it with keys); 0 counts as 1.
    pub fn heat_map_with_gain(&self, gain: u32) -> RgbaImage {
        let w = self.area_width;
        // `compare` pushes one value per pixel of the w x h area, row by row.
        debug_assert!(w == 0 || self.per_pixel.len() % w as usize == 0);
        let h = if w == 0 {
            0
        } else {
            (self.per_pixel.len() / w as usize) as u32
        };
        let mut img = RgbaImage::new(w, h);
        for (px, &d) in img.pixels_mut().zip(&self.per_pixel) {
            *px = heat_colour(d, gain.max(1));
        }
        img
    }

    /// One opaque image `CPU | GL | DIFF`, each panel under a label bar, separated by a 4-pixel
    /// gutter; the renderings are composited over an 8-pixel checkerboard so that transparent
    /// pixels show as such. A smaller input is drawn at the top-left of its panel.
    pub fn side_by_side(&self, cpu: &RgbaImage, gl: &RgbaImage) -> RgbaImage {
        let heat = self.heat_map();
        let label = format!("DIFF X{HEAT_GAIN}");
        let panels: [(&RgbaImage, &str); 3] = [(cpu, "CPU"), (gl, "GL"), (&heat, &label)];
        let pw = panels.iter().map(|(p, _)| p.width()).max().unwrap_or(0);
        let ph = panels.iter().map(|(p, _)| p.height()).max().unwrap_or(0);
        let scale = if pw >= 96 { 2 } else { 1 };
        let bar = font::HEIGHT * scale + 4;
        let gutter = 4;
        let mut out = RgbaImage::from_pixel(3 * pw + 2 * gutter, ph + bar, GUTTER);
        for (i, (panel, text)) in panels.iter().enumerate() {
            let x0 = i as u32 * (pw + gutter);
            for (x, y, px) in panel.enumerate_pixels() {
                out.put_pixel(x0 + x, bar + y, over_checker(*px, x, y));
            }
            font::draw(&mut out, x0 + 2, 2, scale, text, LABEL);
        }
        out
    }
}

impl std::fmt::Display for Comparison {
    /// One line: `max [r g b a] mean [..] >tol: n (p%) psnr x dB`, or the size mismatch.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let Some(((cw, ch), (gw, gh))) = self.size_mismatch() {
            return write!(f, "size mismatch: cpu {cw}x{ch} vs gl {gw}x{gh}");
        }
        let m = self.mean_diff;
        write!(
            f,
            "max {:?} mean [{:.3} {:.3} {:.3} {:.3}] >{}: {} px ({:.3}%) psnr {:.2} dB",
            self.max_diff,
            m[0],
            m[1],
            m[2],
            m[3],
            self.tolerance,
            self.differing_pixels,
            self.differing_percent,
            self.psnr
        )
    }
}

const GUTTER: Rgba<u8> = Rgba([40, 40, 40, 255]);
const LABEL: Rgba<u8> = Rgba([255, 255, 255, 255]);

/// `px` composited over a light checkerboard of 8-pixel squares (204 / 255 grey), opaque.
fn over_checker(px: Rgba<u8>, x: u32, y: u32) -> Rgba<u8> {
    let bg: u32 = if (x / 8 + y / 8) % 2 == 0 { 255 } else { 204 };
    let a = u32::from(px.0[3]);
    let mix = |c: u8| ((u32::from(c) * a + bg * (255 - a) + 127) / 255) as u8;
    Rgba([mix(px.0[0]), mix(px.0[1]), mix(px.0[2]), 255])
}

/// The heat colour of a largest-channel difference `d` magnified `gain` times (see
/// [`Comparison::heat_map`]).
fn heat_colour(d: u8, gain: u32) -> Rgba<u8> {
    if d == 0 {
        return Rgba([0, 0, 0, 255]);
    }
    // t in (0, 765]: three ramps of 255, red first, then green, then blue.
    let t = (u32::from(d).saturating_mul(gain).saturating_mul(3)).min(765);
    let ramp = |start: u32| (t.saturating_sub(start)).min(255) as u8;
    Rgba([ramp(0).max(64), ramp(255), ramp(510), 255])
}

/// A 3x5 bitmap font (upper case, digits, a little punctuation) for labels drawn into images, so
/// that a report needs no font files.
pub(crate) mod font {
    use image::{Rgba, RgbaImage};

    /// Glyph height in font pixels (width is 3, advance 4).
    pub const HEIGHT: u32 = 5;

    /// The five rows of a glyph, top first; bit 2 is the left column. Unknown characters are blank.
    fn glyph(c: char) -> [u8; 5] {
        match c.to_ascii_uppercase() {
            'A' => [2, 5, 7, 5, 5],
            'B' => [6, 5, 6, 5, 6],
            'C' => [3, 4, 4, 4, 3],
            'D' => [6, 5, 5, 5, 6],
            'E' => [7, 4, 6, 4, 7],
            'F' => [7, 4, 6, 4, 4],
            'G' => [3, 4, 5, 5, 3],
            'H' => [5, 5, 7, 5, 5],
            'I' => [7, 2, 2, 2, 7],
            'J' => [1, 1, 1, 5, 2],
            'K' => [5, 5, 6, 5, 5],
            'L' => [4, 4, 4, 4, 7],
            'M' => [5, 7, 7, 5, 5],
            'N' => [6, 5, 5, 5, 5],
            'O' => [2, 5, 5, 5, 2],
            'P' => [6, 5, 6, 4, 4],
            'Q' => [2, 5, 5, 6, 3],
            'R' => [6, 5, 6, 5, 5],
            'S' => [3, 4, 2, 1, 6],
            'T' => [7, 2, 2, 2, 2],
            'U' => [5, 5, 5, 5, 7],
            'V' => [5, 5, 5, 5, 2],
            'W' => [5, 5, 7, 7, 5],
            'X' => [5, 5, 2, 5, 5],
            'Y' => [5, 5, 2, 2, 2],
            'Z' => [7, 1, 2, 4, 7],
            '0' => [7, 5, 5, 5, 7],
            '1' => [2, 6, 2, 2, 7],
            '2' => [6, 1, 2, 4, 7],
            '3' => [6, 1, 2, 1, 6],
            '4' => [5, 5, 7, 1, 1],
            '5' => [7, 4, 6, 1, 6],
            '6' => [3, 4, 7, 5, 7],
            '7' => [7, 1, 2, 2, 2],
            '8' => [7, 5, 7, 5, 7],
            '9' => [7, 5, 7, 1, 6],
            '.' => [0, 0, 0, 0, 2],
            ',' => [0, 0, 0, 2, 4],
            '-' => [0, 0, 7, 0, 0],
            '_' => [0, 0, 0, 0, 7],
            ':' => [0, 2, 0, 2, 0],
            '%' => [5, 1, 2, 4, 5],
            '/' => [1, 1, 2, 4, 4],
            '|' => [2, 2, 2, 2, 2],
            '=' => [0, 7, 0, 7, 0],
            '(' => [2, 4, 4, 4, 2],
            ')' => [2, 1, 1, 1, 2],
            _ => [0; 5],
        }
    }

    /// Draws `text` with its top-left corner at (`x`, `y`), each font pixel a `scale` x `scale`
    /// square of `colour`; whatever falls outside `img` is clipped.
    pub fn draw(img: &mut RgbaImage, x: u32, y: u32, scale: u32, text: &str, colour: Rgba<u8>) {
        for (i, c) in text.chars().enumerate() {
            let gx = x.saturating_add((i as u32).saturating_mul(4 * scale));
            for (row, bits) in glyph(c).iter().enumerate() {
                for col in 0..3u32 {
                    if bits & (4 >> col) == 0 {
                        continue;
                    }
                    for dy in 0..scale {
                        for dx in 0..scale {
                            let px = gx.saturating_add(col * scale + dx);
                            let py = y.saturating_add(row as u32 * scale + dy);
                            if let Some(p) = img.get_pixel_mut_checked(px, py) {
                                *p = colour;
                            }
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solid(w: u32, h: u32, c: [u8; 4]) -> RgbaImage {
        RgbaImage::from_pixel(w, h, Rgba(c))
    }

    #[test]
    fn identical_images_have_zero_error_and_infinite_psnr() {
        let a = solid(4, 3, [10, 20, 30, 255]);
        let c = compare(&a, &a.clone(), 0);
        assert_eq!(c.max_diff, [0; 4]);
        assert_eq!(c.mean_diff, [0.0; 4]);
        assert_eq!(c.differing_pixels, 0);
        assert_eq!(c.differing_percent, 0.0);
        assert!(c.psnr.is_infinite() && c.psnr > 0.0);
        assert!(c.passes(0.0));
    }

    #[test]
    fn metrics_of_a_two_by_two_example_computed_by_hand() {
        // cpu: all (100,100,100,255). gl differs at three pixels:
        //   (0,0): R +10           -> d = [10,0,0,0], worst 10
        //   (1,0): G -3, B +4      -> d = [0,3,4,0],  worst 4
        //   (0,1): A -255          -> d = [0,0,0,255], worst 255
        //   (1,1): equal
        let cpu = solid(2, 2, [100, 100, 100, 255]);
        let mut gl = cpu.clone();
        gl.put_pixel(0, 0, Rgba([110, 100, 100, 255]));
        gl.put_pixel(1, 0, Rgba([100, 97, 104, 255]));
        gl.put_pixel(0, 1, Rgba([100, 100, 100, 0]));
        let c = compare(&cpu, &gl, 4);
        assert_eq!(c.max_diff, [10, 3, 4, 255]);
        assert_eq!(c.mean_diff, [2.5, 0.75, 1.0, 63.75]);
        // worst > 4 at (0,0) and (0,1) only: 2 of 4 pixels.
        assert_eq!(c.differing_pixels, 2);
        assert_eq!(c.differing_percent, 50.0);
        // RGB squared errors: 100 + 9 + 16 = 125 over 12 samples; PSNR = 10 log10(65025 * 12 / 125).
        let expected = 10.0 * (65025.0f64 * 12.0 / 125.0).log10();
        assert!((c.psnr - expected).abs() < 1e-9, "{} vs {expected}", c.psnr);
        assert!((c.psnr - 37.9528).abs() < 1e-3);
        assert!(c.passes(50.0));
        assert!(!c.passes(49.9));
        // With tolerance 3 the (1,0) pixel (worst 4) counts too.
        assert_eq!(compare(&cpu, &gl, 3).differing_pixels, 3);
    }

    #[test]
    fn different_sizes_are_a_result_not_a_panic() {
        let a = solid(2, 2, [0, 0, 0, 255]);
        let b = solid(3, 2, [0, 0, 0, 255]);
        let c = compare(&a, &b, 10);
        assert_eq!(c.size_mismatch(), Some(((2, 2), (3, 2))));
        // The overlap (4 px) is equal; the extra column (2 px) differs by 255 everywhere.
        assert_eq!(c.differing_pixels, 2);
        assert!((c.differing_percent - 100.0 * 2.0 / 6.0).abs() < 1e-12);
        assert_eq!(c.max_diff, [255; 4]);
        assert!(!c.passes(100.0));
        assert!(c.to_string().contains("size mismatch: cpu 2x2 vs gl 3x2"));
        assert_eq!(c.heat_map().dimensions(), (3, 2));
        // Empty against non-empty: still no panic.
        let e = RgbaImage::new(0, 0);
        let c = compare(&e, &a, 0);
        assert_eq!(c.differing_pixels, 4);
        assert_eq!(compare(&e, &e, 0).differing_percent, 0.0);
    }

    #[test]
    fn heat_map_colours() {
        // d=0 black; d=1: t = 48 -> red max(48,64)=64; d=5: t=240 -> (240,0,0);
        // d=10: t=480 -> (255,225,0); d=16: t=765 (capped) -> white.
        assert_eq!(heat_colour(0, HEAT_GAIN), Rgba([0, 0, 0, 255]));
        assert_eq!(heat_colour(1, HEAT_GAIN), Rgba([64, 0, 0, 255]));
        assert_eq!(heat_colour(5, HEAT_GAIN), Rgba([240, 0, 0, 255]));
        assert_eq!(heat_colour(10, HEAT_GAIN), Rgba([255, 225, 0, 255]));
        assert_eq!(heat_colour(16, HEAT_GAIN), Rgba([255, 255, 255, 255]));
        assert_eq!(heat_colour(255, HEAT_GAIN), Rgba([255, 255, 255, 255]));
        let a = solid(2, 1, [0, 0, 0, 255]);
        let mut b = a.clone();
        b.put_pixel(1, 0, Rgba([5, 0, 0, 255]));
        let heat = compare(&a, &b, 0).heat_map();
        assert_eq!(*heat.get_pixel(0, 0), Rgba([0, 0, 0, 255]));
        assert_eq!(*heat.get_pixel(1, 0), Rgba([240, 0, 0, 255]));
        // The gain scales the ramp: d=5 at gain 1 is t=15, the dark-red floor; at gain 64 white.
        let c = compare(&a, &b, 0);
        assert_eq!(
            *c.heat_map_with_gain(1).get_pixel(1, 0),
            Rgba([64, 0, 0, 255])
        );
        assert_eq!(
            *c.heat_map_with_gain(64).get_pixel(1, 0),
            Rgba([255, 255, 255, 255])
        );
        assert_eq!(c.heat_map_with_gain(HEAT_GAIN), heat);
    }

    #[test]
    fn side_by_side_layout_and_label() {
        let a = solid(10, 6, [200, 0, 0, 255]);
        let b = solid(10, 6, [0, 0, 200, 255]);
        let c = compare(&a, &b, 0);
        let strip = c.side_by_side(&a, &b);
        // Scale 1 (panels narrower than 96): bar = 5 + 4 = 9; width = 3*10 + 2*4 = 38.
        assert_eq!(strip.dimensions(), (38, 15));
        assert_eq!(*strip.get_pixel(0, 9), Rgba([200, 0, 0, 255]));
        assert_eq!(*strip.get_pixel(14, 9), Rgba([0, 0, 200, 255]));
        // Difference 200 saturates the heat map: white.
        assert_eq!(*strip.get_pixel(28, 14), Rgba([255, 255, 255, 255]));
        assert_eq!(*strip.get_pixel(10, 9), GUTTER);
        // "CPU" at (2,2): 'C' row 0 is 0b011 -> (3,2) lit, (2,2) not.
        assert_eq!(*strip.get_pixel(2, 2), GUTTER);
        assert_eq!(*strip.get_pixel(3, 2), LABEL);
        assert_eq!(*strip.get_pixel(4, 2), LABEL);
    }

    #[test]
    fn transparent_pixels_show_the_checkerboard() {
        // Fully transparent over square (0,0) (255) and square (1,0) (204); half-transparent
        // red (alpha 128) over 255: r = (255*128 + 255*127 + 127)/255 = 255,
        // g = b = (255*127 + 127)/255 = 127.
        assert_eq!(
            over_checker(Rgba([9, 9, 9, 0]), 0, 0),
            Rgba([255, 255, 255, 255])
        );
        assert_eq!(
            over_checker(Rgba([9, 9, 9, 0]), 8, 0),
            Rgba([204, 204, 204, 255])
        );
        assert_eq!(
            over_checker(Rgba([255, 0, 0, 128]), 7, 7),
            Rgba([255, 127, 127, 255])
        );
        assert_eq!(
            over_checker(Rgba([1, 2, 3, 255]), 9, 0),
            Rgba([1, 2, 3, 255])
        );
    }

    #[test]
    fn font_clips_at_the_image_edge() {
        let mut img = RgbaImage::new(3, 3);
        font::draw(&mut img, 1, 1, 3, "W8", LABEL);
        font::draw(&mut img, u32::MAX - 1, u32::MAX, 2, "X", LABEL);
        // 'W' row 0 is 0b101: font pixel (0,0) covers image (1..4, 1..4) clipped to (1..3, 1..3).
        assert_eq!(*img.get_pixel(1, 1), LABEL);
        assert_eq!(*img.get_pixel(2, 2), LABEL);
        assert_eq!(*img.get_pixel(0, 0), Rgba([0, 0, 0, 0]));
    }
}
