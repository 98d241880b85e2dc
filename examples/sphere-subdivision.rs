//! Renders the `sphere-subdivision` scene to `sphere-subdivision.png` (800x800): seed 003's sphere by recursive subdivision of a tetrahedron, gold.
//! Optional arguments after OUT_DIR: the depths (default `1,2,3,5`) and `centroid` for slide
//! 48's centre-point split instead of slide 47's midpoints.
//!
//! ```text
//! cargo run --release --example sphere-subdivision [OUT_DIR]
//! ```
//!
//! The CPU-vs-driver comparison of the same calls is `cargo run --release -- compare sphere-subdivision`.

use std::path::PathBuf;

use fixedgl::scenes::shapes::Split;
use fixedgl::scenes::sphere::sphere_subdivision;
use fixedgl::Context;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let mut gl = Context::new(800, 800)?;
    sphere_subdivision(&mut gl, &depths(), split());
    let path = out.join("sphere-subdivision.png");
    gl.to_image().save(&path)?;
    println!("{}", path.display());
    Ok(())
}

/// The depths from the second argument (`1,2,3,5` when absent or unreadable).
fn depths() -> Vec<u32> {
    let parsed: Option<Vec<u32>> = std::env::args()
        .nth(2)
        .map(|a| a.split(',').filter_map(|d| d.trim().parse().ok()).collect());
    match parsed {
        Some(d) if !d.is_empty() => d,
        _ => vec![1, 2, 3, 5],
    }
}

/// `centroid` as the third argument picks slide 48's split.
fn split() -> Split {
    if std::env::args().nth(3).as_deref() == Some("centroid") {
        Split::Centroid
    } else {
        Split::Midpoint
    }
}
