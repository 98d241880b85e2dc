//! Contexts sharing objects through the C APIs: a C program written for Mesa makes two OSMesa
//! contexts, the second with the first as sharelist, draws in the second with a texture and a
//! display list made in the first, and checks what GL appendix D says (names seen, bindings per
//! context, deletion seen, a bad sharelist refused). Run on fixedgl's libOSMesa.so.8 and on
//! Mesa's; the two pictures are compared within the scenes' tolerance.

mod xsupport;

use std::path::Path;
use std::process::Command;
use std::time::Duration;

use xsupport::{assert_close, available, has_header, has_program, on, run, Gl, Image};

const LIMIT: Duration = Duration::from_secs(120);

#[test]
fn osmesa_sharelist_matches_mesa() {
    if !available(has_program("cc"), "a C compiler (cc)")
        || !available(has_header("GL/osmesa.h"), "the header GL/osmesa.h (libosmesa6-dev)")
    {
        return;
    }
    let dir = xsupport::profile_dir().join("c-share");
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let bin = dir.join("share_osmesa");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c_share/share_osmesa.c");
    let mut cc = Command::new("cc");
    cc.args(["-O2", "-Wall", "-Wextra", "-Werror", "-std=c99", "-o"])
        .arg(&bin)
        .arg(&src)
        .args(["-lOSMesa", "-lGL"]);
    run(cc, LIMIT);
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
        assert!(log.contains(renderer), "{gl:?} ran on something else:\n{log}");
        assert!(!log.contains("share"), "{gl:?} said something of sharing:\n{log}");
        images.push(Image::load_ppm(&out));
    }
    assert_eq!((images[0].width, images[0].height), (128, 96));
    assert_close("share_osmesa", &images[0], &images[1]);
}
