//! The recording file format: write → read gives back the same calls bit for bit, malformed
//! lines are reported with their 1-based number, hostile input neither panics nor allocates
//! without bound, and replaying a recording on a fresh context reproduces the same State.

mod common;

use fixedgl::recording::{read_recording, write_recording, MAX_LINE_BYTES};
use fixedgl::{gl, Call, Context, Error};
use proptest::prelude::*;

fn write(calls: &[Call]) -> String {
    let mut out = Vec::new();
    let written = write_recording(calls, &mut out);
    assert!(written.is_ok(), "{written:?}");
    String::from_utf8(out).unwrap_or_default()
}

fn read(text: &str) -> Result<Vec<Call>, Error> {
    read_recording(text.as_bytes())
}

/// Equal including the sign of zero and NaN-ness (Debug prints `-0.0` and `NaN`).
fn same_calls(a: &[Call], b: &[Call]) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

/// The line number of a parse error, or `None` for success or another error.
fn error_line(result: Result<Vec<Call>, Error>) -> Option<usize> {
    match result {
        Err(Error::Parse { line, .. }) => Some(line),
        _ => None,
    }
}

#[test]
fn extreme_values_round_trip_exactly() {
    let calls = vec![
        Call::Begin(gl::QUAD_STRIP),
        Call::Vertex3f(0.1, 1.0 / 3.0, -0.0),
        Call::Vertex4f(f32::MAX, f32::MIN, f32::MIN_POSITIVE, 1e-45),
        Call::Vertex3d(0.1, std::f64::consts::PI, -1e300),
        Call::Normal3bv([i8::MIN, 0, i8::MAX]),
        Call::Color4ui(u32::MAX, 0, 1, 7),
        Call::Color4usv([u16::MAX, 0, 1, 2]),
        Call::TexCoord1dv([f64::MIN_POSITIVE]),
        Call::Vertex2i(i32::MIN, i32::MAX),
        Call::EdgeFlagv([false]),
        Call::Materialfv(gl::FRONT_AND_BACK, gl::AMBIENT_AND_DIFFUSE, vec![]),
        Call::Lightfv(gl::LIGHT7, gl::SPOT_DIRECTION, vec![1.0; 40]),
        Call::Lightiv(gl::LIGHT0, gl::AMBIENT, vec![i32::MIN, i32::MAX, 0, -1]),
        Call::End,
        Call::ClearColor(f32::INFINITY, f32::NEG_INFINITY, 0.25, 1.0),
        Call::ClearDepth(0.7),
        Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | 0x8000_0000),
        Call::Clear(0),
        Call::ShadeModel(0xdead_beef),
        Call::Hint(gl::PHONG_HINT_WIN, gl::NICEST),
        Call::ColorMask(true, false, true, false),
        Call::Flush,
    ];
    let text = write(&calls);
    let back = read(&text);
    assert!(
        matches!(&back, Ok(b) if same_calls(b, &calls)),
        "{text}\n{back:?}"
    );
}

#[test]
fn nan_reads_back_as_nan() {
    let text = write(&[Call::Normal3f(f32::NAN, -f32::NAN, 0.0)]);
    let back = read(&text);
    let ok = matches!(back.as_deref(), Ok([Call::Normal3f(x, y, z)])
        if x.is_nan() && y.is_nan() && *z == 0.0);
    assert!(ok, "{text}\n{back:?}");
}

#[test]
fn the_format_is_readable() {
    let text = write(&[
        Call::Lightfv(gl::LIGHT0, gl::POSITION, vec![1.0, 1.5, -0.5, 1.0]),
        Call::Begin(gl::TRIANGLE_STRIP),
        Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT),
    ]);
    let lines: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(
        lines,
        [
            "Lightfv(LIGHT0, POSITION, [1.0, 1.5, -0.5, 1.0])",
            "Begin(TRIANGLE_STRIP)",
            "Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT)",
        ]
    );
}

#[test]
fn hand_written_input_with_comments_hex_and_names_anywhere() {
    let text = "# a comment\n\n  Begin(0x4)   # TRIANGLES\nShadeModel(FLAT)\n\
                Lighti(LIGHT0 , SPOT_CUTOFF, 90)\nClear(DEPTH_BUFFER_BIT|COLOR_BUFFER_BIT)\nEnd\n";
    let back = read(text);
    let expected = vec![
        Call::Begin(gl::TRIANGLES),
        Call::ShadeModel(gl::FLAT),
        Call::Lighti(gl::LIGHT0, gl::SPOT_CUTOFF, 90),
        Call::Clear(0x4100),
        Call::End,
    ];
    assert!(matches!(&back, Ok(b) if *b == expected), "{back:?}");
}

#[test]
fn malformed_lines_name_their_line() {
    let cases: &[(&str, usize)] = &[
        ("Begin(POINTS)\nBegni(POINTS)\n", 2),
        ("# header\n\nVertex3f(1.0, 2.0)\n", 3),
        ("End\nEnd\nEnd\nLightfv(LIGHT0, NOT_A_NAME, [1.0])\n", 4),
        ("Clear(COLOR_BUFFER_BIT |)\n", 1),
        ("Flush\nClear(| COLOR_BUFFER_BIT)\n", 2),
        ("Flush\nFinish\nVertex3f(1.0, 2.0, 3.0, 4.0)\n", 3),
        ("Normal3bv((1, 2, 300))\n", 1),
        ("Begin(0xZZ)\n", 1),
        ("Begin(\"TRIANGLES\")\n", 1),
        ("Flush\nEnd(\n", 2),
        ("Scissor(1, 2, 3, true)\n", 1),
        ("Flush\n\u{feff}Flush\n", 2),
    ];
    for &(text, line) in cases {
        assert_eq!(error_line(read(text)), Some(line), "{text:?}");
    }
}

#[test]
fn invalid_utf8_is_a_parse_error() {
    let bytes: &[u8] = b"Flush\nFinish\n\xff\xfe\n";
    assert_eq!(error_line(read_recording(bytes)), Some(3));
}

#[test]
fn hostile_input_is_bounded() {
    // One line past the cap: rejected with its number, not stored whole.
    let mut long = String::from("Flush\nLightfv(LIGHT0, AMBIENT, [");
    while long.len() <= MAX_LINE_BYTES + 8 {
        long.push_str("1.0, 1.0, 1.0, 1.0, ");
    }
    assert_eq!(error_line(read(&long)), Some(2));
    // Deep nesting: RON's recursion limit, not a stack overflow.
    let deep = format!(
        "Lightfv(LIGHT0, AMBIENT, {}{})",
        "[".repeat(10_000),
        "]".repeat(10_000)
    );
    assert_eq!(error_line(read(&deep)), Some(1));
}

/// A short lit scene: enough state changes to make a replay mismatch visible.
fn scene(c: &mut Context) {
    c.clear_color(0.1, 0.2, 0.3, 1.0);
    c.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    c.enable(gl::LIGHTING);
    c.enable(gl::LIGHT0);
    c.lightfv(gl::LIGHT0, gl::POSITION, &[1.0, 1.5, -0.5, 0.0]);
    c.lightf(gl::LIGHT0, gl::SPOT_CUTOFF, 45.0);
    c.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1);
    c.materialfv(gl::FRONT, gl::DIFFUSE, &[0.8, 0.6, 0.2, 1.0]);
    c.materiali(gl::BACK, gl::SHININESS, 200); // INVALID_VALUE, recorded all the same
    c.shade_model(gl::FLAT);
    c.begin(gl::TRIANGLES);
    c.normal3b(0, 0, 127);
    c.color3ub(255, 128, 0);
    c.vertex3f(0.0, 0.0, 0.0);
    c.materialf(gl::FRONT, gl::SHININESS, 32.0);
    c.tex_coord2s(3, 4);
    c.vertex2d(1.0, 0.0);
    c.cull_face(gl::FRONT); // INVALID_OPERATION inside Begin/End
    c.vertex4iv(&[0, 1, 0, 1]);
    c.end();
    c.polygon_mode(gl::FRONT_AND_BACK, gl::LINE);
    c.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
    c.hint(gl::PERSPECTIVE_CORRECTION_HINT, gl::NICEST);
}

#[test]
fn replaying_a_saved_recording_reproduces_the_state() {
    let Ok(mut original) = Context::new(8, 8) else {
        panic!("context")
    };
    original.start_recording();
    scene(&mut original);
    let calls = original.stop_recording();
    assert_eq!(calls.len(), 23);

    let dir = std::env::temp_dir().join(format!("fixedgl-recording-{}", std::process::id()));
    let path = dir.join("scene.fglrec");
    let _ = std::fs::create_dir_all(&dir);
    let saved = fixedgl::recording::save(&calls, &path);
    assert!(saved.is_ok(), "{saved:?}");
    let loaded = fixedgl::recording::load(&path);
    let _ = std::fs::remove_dir_all(&dir);
    let Ok(loaded) = loaded else {
        panic!("{loaded:?}")
    };
    assert_eq!(loaded, calls);

    let Ok(mut replayed) = Context::new(8, 8) else {
        panic!("context")
    };
    replayed.replay(&loaded);
    assert_eq!(replayed.state(), original.state());
    // The first error (the shininess of 200) replays too.
    assert_eq!(replayed.get_error(), gl::INVALID_VALUE);
    assert_eq!(original.get_error(), gl::INVALID_VALUE);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn any_calls_round_trip(calls in prop::collection::vec(common::any_call(), 0..20)) {
        let text = write(&calls);
        let back = read(&text);
        prop_assert!(matches!(&back, Ok(b) if same_calls(b, &calls)), "{}\n{:?}", text, back);
    }
}
