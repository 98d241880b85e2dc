//! The examples of examples/c/ (a C/GLUT program, a C OSMesa program, a PyOpenGL script) and
//! glxgears, run unmodified on fixedgl (the drop-in directory first on LD_LIBRARY_PATH) and on
//! Mesa (the system's libraries, llvmpipe), each image compared within the scenes' tolerance
//! (at most 0.05% of the pixels off by more than 2/255). Windows run on a private Xvfb and are
//! read back from the X server (XGetImage), so what is compared is what the program showed.

mod xsupport;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;
use std::time::Duration;

use xsupport::{
    assert_close, available, has_header, has_program, on, run, Gl, Image, Running, Xvfb,
};

const LIMIT: Duration = Duration::from_secs(120);

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/c")
}

/// A scratch directory of this test under target/<profile>/c-examples.
fn scratch(test: &str) -> PathBuf {
    let dir = xsupport::profile_dir().join("c-examples").join(test);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// examples/c/<name>.c compiled with `cc` (once per test binary); `None`: skipped for a missing
/// compiler or header.
fn compile(name: &str, headers: &[&str], libs: &[&str]) -> Option<PathBuf> {
    static BUILT: Mutex<Option<HashMap<String, PathBuf>>> = Mutex::new(None);
    if !available(has_program("cc"), "a C compiler (cc)") {
        return None;
    }
    for h in headers {
        if !available(
            has_header(h),
            &format!("the header {h} (freeglut3-dev, libosmesa6-dev)"),
        ) {
            return None;
        }
    }
    let mut built = BUILT.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(p) = built.get_or_insert_with(HashMap::new).get(name) {
        return Some(p.clone());
    }
    let out = scratch("bin").join(name);
    let mut cc = Command::new("cc");
    cc.args(["-O2", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&out)
        .arg(examples().join(format!("{name}.c")))
        .args(libs);
    run(cc, LIMIT);
    built
        .get_or_insert_with(HashMap::new)
        .insert(name.into(), out.clone());
    Some(out)
}

/// What the GLUT example showed: its window read back from the X server, and its own
/// glReadPixels screenshot of the same frame.
fn gaussian_frame(x: &Xvfb, bin: &Path, gl: Gl, shading: &str, dir: &Path) -> (Image, Image) {
    let shot = dir.join(format!("{gl:?}-{shading}.ppm"));
    let mut cmd = on(gl, Command::new(bin));
    cmd.env("DISPLAY", &x.display)
        .args([
            "--size",
            "400x400",
            "--frames",
            "3",
            shading,
            "--wait",
            "--screenshot",
        ])
        .arg(&shot);
    let mut p = Running::start(cmd);
    p.wait_for(LIMIT, |l| l == "ready");
    let conn = x.open();
    let window = conn.window_named("gaussian", LIMIT);
    let shown = conn.read(window);
    p.finish(LIMIT);
    conn.wait_gone("gaussian", LIMIT);
    (shown, Image::load_ppm(&shot))
}

/// The lecture's gaussian surface as a C/GLUT program (freeglut, GLX 1.3 FBConfigs, double
/// buffered): FLAT and SMOOTH frames on fixedgl match Mesa's, in the window and in the program's
/// own glReadPixels; and fixedgl's window shows exactly what fixedgl drew.
#[test]
fn gaussian_glut_matches_mesa() {
    let Some(bin) = compile(
        "gaussian",
        &["GL/glut.h"],
        &["-lglut", "-lGLU", "-lGL", "-lm"],
    ) else {
        return;
    };
    let Some(x) = Xvfb::start() else { return };
    let dir = scratch("gaussian");
    for shading in ["--flat", "--smooth"] {
        let (fx_window, fx_shot) = gaussian_frame(&x, &bin, Gl::Fixedgl, shading, &dir);
        let (mesa_window, mesa_shot) = gaussian_frame(&x, &bin, Gl::Mesa, shading, &dir);
        assert_eq!((fx_window.width, fx_window.height), (400, 400));
        assert_close(
            &format!("gaussian {shading} window"),
            &fx_window,
            &mesa_window,
        );
        assert_close(
            &format!("gaussian {shading} glReadPixels"),
            &fx_shot,
            &mesa_shot,
        );
        assert_eq!(
            xsupport::diff(&fx_window, &fx_shot).max,
            0,
            "fixedgl's window differs from what fixedgl drew"
        );
        // Not a blank frame: the surface (about 35000 pixels, most bluish) on white.
        let surface = fx_window
            .rgb
            .chunks_exact(3)
            .filter(|p| p.iter().any(|&c| c < 250))
            .count();
        let bluish = fx_window
            .rgb
            .chunks_exact(3)
            .filter(|p| u16::from(p[2]) > u16::from(p[0]) + 40)
            .count();
        assert!(
            (30_000..45_000).contains(&surface) && bluish > 10_000,
            "{shading}: {surface} surface pixels, {bluish} of them bluish"
        );
    }
}

/// The framebuffer follows the window: resized by the X server (as a user or window manager
/// does) smaller and then larger than it started, the GLUT program's next frames fill the new
/// size, as on Mesa.
#[test]
fn gaussian_follows_window_resize() {
    let Some(bin) = compile(
        "gaussian",
        &["GL/glut.h"],
        &["-lglut", "-lGLU", "-lGL", "-lm"],
    ) else {
        return;
    };
    let Some(x) = Xvfb::start() else { return };
    let mut shown: HashMap<(Gl, u32), Image> = HashMap::new();
    for gl in [Gl::Fixedgl, Gl::Mesa] {
        let mut cmd = on(gl, Command::new(&bin));
        cmd.env("DISPLAY", &x.display)
            .args(["--size", "300x300", "--print-frames", "--flat"]);
        let mut p = Running::start(cmd);
        p.wait_for(LIMIT, |l| l.ends_with(" 300x300"));
        let conn = x.open();
        let window = conn.window_named("gaussian", LIMIT);
        for (i, (w, h)) in [(360u32, 240u32), (480, 420)].into_iter().enumerate() {
            conn.resize(window, w, h);
            let size = format!(" {w}x{h}");
            p.wait_for(LIMIT, |l| l.ends_with(&size));
            // That frame may have been drawn before the program handled the resize (the size
            // is asked after drawing). A key sent now reaches it after the resize: the frame
            // drawn after its answer is drawn at the new size.
            conn.press(window, 'f');
            p.wait_for(LIMIT, |l| l.starts_with("FLAT shading"));
            p.wait_for(LIMIT, |l| l.ends_with(&size));
            let image = conn.read(window);
            assert_eq!((image.width, image.height), (w, h));
            shown.insert((gl, i as u32), image);
        }
        drop(p);
        conn.wait_gone("gaussian", LIMIT);
    }
    for i in 0..2 {
        let (fx, mesa) = (&shown[&(Gl::Fixedgl, i)], &shown[&(Gl::Mesa, i)]);
        assert_close(
            &format!("gaussian resized to {}x{}", fx.width, fx.height),
            fx,
            mesa,
        );
    }
}

/// Pixels whose colour is clearly red, green or blue (glxgears' three gears).
fn gear_pixels(image: &Image) -> [usize; 3] {
    let mut n = [0; 3];
    for p in image.rgb.chunks_exact(3) {
        let (r, g, b) = (i32::from(p[0]), i32::from(p[1]), i32::from(p[2]));
        if r > 60 && r > 2 * g && r > 2 * b {
            n[0] += 1;
        } else if g > 60 && g > 2 * r && g > 2 * b {
            n[1] += 1;
        } else if b > 60 && b > 2 * r && b > 2 * g {
            n[2] += 1;
        }
    }
    n
}

/// glxgears (mesa-utils: GLX 1.2 ChooseVisual/CreateContext/MakeCurrent, its own X event loop)
/// runs on fixedgl and shows its three gears. The gears turn with time, so the two frames are
/// not compared pixel by pixel: the red, green and blue areas must be there and about as large
/// as Mesa's.
#[test]
fn glxgears_shows_gears() {
    if !available(has_program("glxgears"), "glxgears (package mesa-utils)") {
        return;
    }
    let Some(x) = Xvfb::start() else { return };
    let mut counts = Vec::new();
    for gl in [Gl::Fixedgl, Gl::Mesa] {
        let mut cmd = on(gl, Command::new("glxgears"));
        cmd.env("DISPLAY", &x.display)
            .args(["-geometry", "300x300+0+0"]);
        let p = Running::start(cmd);
        let conn = x.open();
        let window = conn.window_named("glxgears", LIMIT);
        std::thread::sleep(Duration::from_millis(1500));
        let image = conn.read(window);
        let mut p = p;
        assert!(
            p.child.try_wait().ok().flatten().is_none(),
            "glxgears on {gl:?} exited early"
        );
        drop(p);
        conn.wait_gone("glxgears", LIMIT);
        let n = gear_pixels(&image);
        eprintln!(
            "glxgears on {gl:?}: red, green, blue gear pixels {n:?} of {}",
            300 * 300
        );
        if gl == Gl::Fixedgl {
            image.save_ppm(&scratch("glxgears").join("fixedgl.ppm"));
        }
        counts.push(n);
    }
    for (c, (fx, mesa)) in counts[0].iter().zip(&counts[1]).enumerate() {
        let (fx, mesa) = (*fx as f64, *mesa as f64);
        assert!(fx > 900.0, "gear {c}: {fx} pixels on fixedgl");
        assert!(
            (fx / mesa - 1.0).abs() < 0.25,
            "gear {c}: {fx} pixels on fixedgl, {mesa} on Mesa"
        );
    }
}

/// A headless C program written for Mesa's OSMesa renders the same image on fixedgl's
/// libOSMesa.so.8 as on Mesa's.
#[test]
fn osmesa_demo_matches_mesa() {
    let Some(bin) = compile("osmesa_demo", &["GL/osmesa.h"], &["-lOSMesa", "-lm"]) else {
        return;
    };
    let dir = scratch("osmesa_demo");
    let mut images = Vec::new();
    for gl in [Gl::Fixedgl, Gl::Mesa] {
        let out = dir.join(format!("{gl:?}.ppm"));
        let mut cmd = on(gl, Command::new(&bin));
        cmd.env_remove("DISPLAY").arg(&out);
        let log = run(cmd, LIMIT);
        let renderer = if gl == Gl::Fixedgl {
            "fixedgl"
        } else {
            "llvmpipe"
        };
        assert!(
            log.contains(renderer),
            "{gl:?} ran on something else:\n{log}"
        );
        images.push(Image::load_ppm(&out));
    }
    assert_eq!((images[0].width, images[0].height), (400, 300));
    assert_close("osmesa_demo", &images[0], &images[1]);
}

/// The PyOpenGL script (PYOPENGL_PLATFORM=osmesa: every gl* looked up in libOSMesa, client
/// arrays read at draw time) renders the same image on fixedgl as on Mesa.
#[test]
fn pyopengl_demo_matches_mesa() {
    let python = "/usr/bin/python3";
    let has_pyopengl = Path::new(python).is_file()
        && Command::new(python)
            .args(["-c", "import OpenGL.GL"])
            .env("PYOPENGL_PLATFORM", "osmesa")
            .output()
            .is_ok_and(|o| o.status.success());
    if !available(
        has_pyopengl,
        "PyOpenGL for /usr/bin/python3 (package python3-opengl)",
    ) {
        return;
    }
    let dir = scratch("pyopengl_demo");
    let mut images = Vec::new();
    for gl in [Gl::Fixedgl, Gl::Mesa] {
        let out = dir.join(format!("{gl:?}.ppm"));
        let mut cmd = on(gl, Command::new(python));
        cmd.env_remove("DISPLAY")
            .env("PYOPENGL_PLATFORM", "osmesa")
            .arg(examples().join("pyopengl_demo.py"))
            .arg(&out);
        let log = run(cmd, LIMIT);
        let renderer = if gl == Gl::Fixedgl {
            "fixedgl"
        } else {
            "llvmpipe"
        };
        assert!(
            log.contains(renderer),
            "{gl:?} ran on something else:\n{log}"
        );
        images.push(Image::load_ppm(&out));
    }
    assert_eq!((images[0].width, images[0].height), (320, 240));
    assert_close("pyopengl_demo", &images[0], &images[1]);
}
