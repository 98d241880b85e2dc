//! The recording file format: write → read gives back the same calls bit for bit, malformed
//! lines are reported with their 1-based number, hostile input neither panics nor allocates
//! without bound, and replaying a recording on a fresh context reproduces the same State.

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
    fn any_calls_round_trip(seed in any::<u64>(), n in 0..20usize) {
        // Every variant, arguments with the extremes: the soak's generator, seeded.
        let mut gen = crate::soak::Gen::new(seed);
        let calls: Vec<Call> = (0..n).map(|_| gen.any_call()).collect();
        let text = write(&calls);
        let back = read(&text);
        prop_assert!(matches!(&back, Ok(b) if same_calls(b, &calls)), "{}\n{:?}", text, back);
    }
}

/// The line, column and message of a parse error.
fn parse_error(result: Result<Vec<Call>, Error>) -> Option<(usize, usize, String)> {
    match result {
        Err(Error::Parse {
            line,
            column,
            message,
        }) => Some((line, column, message)),
        _ => None,
    }
}

/// Malformed lines: each reports its line, the column in the line as written, and a short
/// one-line message naming the problem.
#[test]
fn malformed_lines_say_where_and_what() {
    let long = format!(
        "Lightfv(LIGHT0, AMBIENT, [{}])",
        "1.0, ".repeat(MAX_LINE_BYTES / 5)
    );
    #[rustfmt::skip]
    let cases: &[(&str, usize, usize, &str)] = &[
        // Whitespace separates tokens and never joins them.
        ("Color3f(0.5 5, 1, 1)", 1, 13, "expected `,` after argument 1 of Color3f, found `5`"),
        ("Flush\nViewport(1 2, 3, 4, 5)", 2, 12, "expected `,` after argument 1 of Viewport, found `2`"),
        // Columns are the user's, leading blanks and names included.
        ("  Lightfv(LIGHT0, NOT_A_NAME, [1.0])", 1, 19, "argument 2 of Lightfv: unknown GL name `NOT_A_NAME`"),
        ("Lightfv(LIGHT0, POSITON, [1.0])", 1, 17, "did you mean `POSITION`?"),
        // Unknown call: the nearest name, never the whole list.
        ("Lightfvv(LIGHT0, POSITION, [1.0])", 1, 1, "unknown call `Lightfvv`; did you mean `Lightfv`?"),
        ("End\n\tBegni(POINTS)", 2, 2, "unknown call `Begni`; did you mean `Begin`?"),
        ("vertex3f(1, 2, 3)", 1, 1, "did you mean `Vertex3f`?"),
        ("Xyzzyplugh(1)", 1, 1, "unknown call `Xyzzyplugh`"),
        ("5(1)", 1, 1, "expected a call name, found `5`"),
        // Missing parentheses.
        ("Begin TRIANGLES", 1, 7, "expected `(` after `Begin`, found `TRIANGLES`"),
        ("Begin", 1, 6, "expected `(` after `Begin`, found the end of the line"),
        ("End()", 1, 4, "`End` takes no arguments"),
        // Argument counts.
        ("Vertex3f(1.0, 2.0, 3.0, 4.0)", 1, 25, "too many arguments: `Vertex3f` takes 3"),
        ("Vertex3f(1.0, 2.0)", 1, 18, "`Vertex3f` takes 3 arguments, found 2"),
        ("Vertex3f()", 1, 10, "`Vertex3f` takes 3 arguments, found 0"),
        ("ShadeModel()", 1, 12, "`ShadeModel` takes 1 argument, found 0"),
        ("ShadeModel(FLAT, SMOOTH)", 1, 18, "too many arguments: `ShadeModel` takes 1"),
        ("Normal3fv((1.0, 2.0))", 1, 20, "argument 1 of Normal3fv: expected 3 elements, found 2"),
        ("Normal3fv((1.0, 2.0, 3.0, 4.0))", 1, 27, "argument 1 of Normal3fv: expected 3 elements, found more"),
        // Types.
        ("Vertex3f(1.0, \"2\", 3.0)", 1, 15, "argument 2 of Vertex3f: expected f32, found a string"),
        ("Vertex2i(1, 2.5)", 1, 13, "argument 2 of Vertex2i: expected i32, found `2.5`"),
        ("Scissor(1, 2, 3, true)", 1, 18, "argument 4 of Scissor: expected i32, found `true`"),
        ("EdgeFlag(1)", 1, 10, "argument 1 of EdgeFlag: expected `true` or `false`, found `1`"),
        ("Lightfv(LIGHT0, AMBIENT, (1.0))", 1, 26, "argument 3 of Lightfv: expected a list `[..]`, found `(`"),
        ("Lightfv(LIGHT0, AMBIENT, [[1.0]])", 1, 27, "argument 3 of Lightfv, element 1: expected f32, found `[`"),
        ("VertexPointer(3, FLOAT, 0, Dat([1]))", 1, 28, "unknown Pointer `Dat`; expected `Data` or `Offset`"),
        ("VertexPointer(3, FLOAT, 0, Data([1, 2, 256]))", 1, 40, "argument 4 of VertexPointer, element 3: 256 is out of range for u8"),
        // Ranges.
        ("Normal3bv((1, 2, 300))", 1, 18, "argument 1 of Normal3bv, element 3: 300 is out of range for i8"),
        ("Color4ui(4294967296, 0, 0, 0)", 1, 10, "argument 1 of Color4ui: 4294967296 is out of range for u32"),
        ("Vertex2i(2147483648, 0)", 1, 10, "argument 1 of Vertex2i: 2147483648 is out of range for i32"),
        ("Vertex2i(-2147483649, 0)", 1, 10, "-2147483649 is out of range for i32"),
        ("Begin(-1)", 1, 7, "argument 1 of Begin: -1 is out of range for u32"),
        ("Vertex2i(99999999999999999999999999999999999999999, 0)", 1, 10, "is out of range for i32"),
        ("Begin(0x100000000)", 1, 7, "4294967296 is out of range for u32"),
        // Brackets and trailing text.
        ("Lightfv(LIGHT0, AMBIENT, [1.0, 2.0", 1, 26, "unclosed `[`"),
        ("Flush\nEnd(", 2, 4, "`End` takes no arguments"),
        ("Vertex3f(1.0, 2.0, 3.0", 1, 9, "unclosed `(`"),
        ("Lightfv(LIGHT0, AMBIENT, [1.0, 2.0)", 1, 35, "expected `,` or `]`, found `)`"),
        ("Vertex3f(1.0, 2.0, 3.0) x", 1, 25, "unexpected `x` after the end of the call"),
        ("Vertex3f(1.0, 2.0, 3.0))", 1, 24, "unmatched `)`"),
        ("Flush Flush", 1, 7, "unexpected `Flush` after the end of the call"),
        // Bitfields.
        ("Clear(COLOR_BUFFER_BIT |)", 1, 25, "expected a value after `|`, found `)`"),
        ("Clear(| COLOR_BUFFER_BIT)", 1, 7, "argument 1 of Clear: expected u32, found `|`"),
        ("Clear(-1 | 2)", 1, 7, "`|` joins non-negative integers"),
        // Numbers that are not numbers.
        ("Vertex3f(1.0f, 2.0, 3.0)", 1, 10, "malformed number `1.0f`"),
        ("Vertex3f(1.0.0, 2.0, 3.0)", 1, 10, "malformed number `1.0.0`"),
        ("Lightf(LIGHT0.5, SPOT_CUTOFF, 1)", 1, 8, "`LIGHT0.5` is neither a name nor a number"),
        ("Begin(0xZZ)", 1, 7, "malformed number `0xZZ`"),
        ("Vertex3f(nan, 1.0, 1.0)", 1, 10, "write `NaN`, `inf` or `-inf`"),
        ("Vertex3f(-infinity, 1.0, 1.0)", 1, 10, "write `NaN`, `inf` or `-inf`"),
        ("Vertex3f(Infinity, 1.0, 1.0)", 1, 10, "write `NaN`, `inf` or `-inf`"),
        ("Vertex2i(NaN, 1)", 1, 10, "argument 1 of Vertex2i: expected i32, found `NaN`"),
        // Characters the format never uses.
        ("Vertex3f(1.0;, 2.0, 3.0)", 1, 13, "unexpected character `;`"),
        ("Vertex3f(1.0,\u{7} 2.0, 3.0)", 1, 14, "control character U+0007"),
        ("Flush\n\u{feff}Flush", 2, 1, "non-ASCII character U+FEFF"),
        ("Vertex3f(1.0, 2.0, 3.0\u{a0})", 1, 23, "non-ASCII character U+00A0"),
        ("Vertex3f(1.0, \"2.0, 3.0)", 1, 15, "unterminated string"),
        ("Flush\nFinish\n\n# fine\n", 0, 0, ""),
        (&long, 1, MAX_LINE_BYTES + 1, "line longer than"),
    ];
    let mut failures = Vec::new();
    for &(text, line, column, message) in cases {
        let result = read(text);
        let ok = if line == 0 {
            result.is_ok()
        } else {
            matches!(&result, Err(Error::Parse { line: l, column: c, message: m })
                if *l == line && *c == column && m.contains(message) && !m.contains('\n')
                    && m.len() < 200)
        };
        if !ok {
            let shown: String = text.chars().take(80).collect();
            let got = parse_error(result);
            failures.push(format!(
                "{shown:?}: expected {line}:{column}: ..{message}.., got {got:?}"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// An unknown call name gets one suggestion at most, never the list of every call.
#[test]
fn unknown_call_message_is_short() {
    for text in [
        "Lightfvv(LIGHT0, POSITION, [1.0])",
        "Qqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqq(1)",
        "A",
        "Pointer(1)",
    ] {
        let got = parse_error(read(text));
        assert!(
            matches!(&got, Some((1, 1, m)) if m.starts_with("unknown call") && m.len() < 200),
            "{text}: {got:?}"
        );
    }
}

/// What RON reads, hand-written forms included, still reads: infinities and NaN in RON's
/// spellings, hex/octal/binary, `_` separators, trailing commas, integers and GL names where a
/// float goes, tabs, CRLF line ends.
#[test]
fn hand_written_forms_read() {
    let text = "Vertex3f(inf, +inf, -inf)\r\n\tVertex4d(NaN, -NaN, +NaN, 1_000.5)\n\
                Color3f(1, .5, 2.)\nVertex2i(0b101, -0o17)\nBegin(0X4,)\n\
                Vertex3f(1e3, 1E-3, 2.5e+2,)\nLightf(LIGHT0, SPOT_CUTOFF, LIGHT0)\n\
                Lightfv( LIGHT0 , AMBIENT , [ 1.0 , 2.0 , ] )\nNormal3fv((1.0, 2.0, 3.0,))\n\
                TexImage2D((TEXTURE_2D, 0, RGBA, 1, 1, 0, RGBA, UNSIGNED_BYTE, Some([1, 2, 3, 4])))\n\
                DrawElements(TRIANGLES, 3, UNSIGNED_BYTE, Offset(0))\nClear(0x100 | 0x4000 | 1)\n";
    let back = read(text);
    let Ok(calls) = back else { panic!("{back:?}") };
    let shown = format!("{calls:?}");
    assert_eq!(calls.len(), 12, "{shown}");
    assert!(
        matches!(calls[0], Call::Vertex3f(a, b, c)
        if a == f32::INFINITY && b == f32::INFINITY && c == f32::NEG_INFINITY),
        "{shown}"
    );
    assert!(
        matches!(calls[1], Call::Vertex4d(a, b, c, d)
        if a.is_nan() && b.is_nan() && b.is_sign_negative() && c.is_nan() && d == 1000.5),
        "{shown}"
    );
    assert_eq!(calls[2], Call::Color3f(1.0, 0.5, 2.0));
    assert_eq!(calls[3], Call::Vertex2i(5, -15));
    assert_eq!(calls[4], Call::Begin(gl::TRIANGLES));
    assert_eq!(calls[5], Call::Vertex3f(1e3, 1e-3, 250.0));
    assert_eq!(
        calls[6],
        Call::Lightf(gl::LIGHT0, gl::SPOT_CUTOFF, gl::LIGHT0 as f32)
    );
    assert_eq!(
        calls[7],
        Call::Lightfv(gl::LIGHT0, gl::AMBIENT, vec![1.0, 2.0])
    );
    assert_eq!(calls[8], Call::Normal3fv([1.0, 2.0, 3.0]));
    assert_eq!(
        calls[9],
        Call::TexImage2D(Box::new((
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            1,
            1,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Some(vec![1, 2, 3, 4])
        )))
    );
    assert_eq!(
        calls[10],
        Call::DrawElements(
            gl::TRIANGLES,
            3,
            gl::UNSIGNED_BYTE,
            fixedgl::Pointer::Offset(0)
        )
    );
    assert_eq!(calls[11], Call::Clear(0x4101));
}

/// A small deterministic generator (xorshift64*), so the fuzz cases are the same every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Every outcome of reading hostile text is a call list or a parse error with a line in the
/// text, a column, and a one-line message; never a panic.
fn check_outcome(bytes: &[u8]) {
    let lines = bytes.split(|&b| b == b'\n').count();
    match read_recording(bytes) {
        Ok(_) => {}
        Err(Error::Parse {
            line,
            column,
            message,
        }) => {
            assert!(
                (1..=lines).contains(&line) && column >= 1 && !message.contains('\n'),
                "{bytes:?}: {line}:{column}: {message}"
            );
            assert!(message.len() < 200, "{bytes:?}: {message}");
        }
        Err(e) => panic!("{bytes:?}: {e:?}"),
    }
}

/// Fuzzing, bounded: random bytes, and random mutations of lines the writer wrote.
#[test]
fn random_and_mutated_lines_never_panic() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let Ok(mut ctx) = Context::new(8, 8) else {
        panic!("context")
    };
    ctx.start_recording();
    scene(&mut ctx);
    let mut calls = ctx.stop_recording();
    calls.extend([
        Call::Normal3f(f32::NAN, -f32::NAN, f32::INFINITY),
        Call::Normal3bv([i8::MIN, 0, i8::MAX]),
        Call::Clear(gl::COLOR_BUFFER_BIT | 0x8000_0000),
        Call::LoadMatrixd(Box::new([0.1; 16])),
        Call::DrawRangeElements(
            gl::LINES,
            0,
            3,
            4,
            gl::UNSIGNED_SHORT,
            Box::new(fixedgl::Pointer::Data(vec![0, 1, 2, 255])),
        ),
    ]);
    let text = write(&calls);
    let lines: Vec<&[u8]> = text.as_bytes().split(|&b| b == b'\n').collect();
    let alphabet: &[u8] =
        b"()[],|\"# \t\r\n0123456789.-+_exXabfNaNinfLIGHT0Begin\x00\x07\x7f\xc3\xa9\xff";
    for case in 0..20_000 {
        let bytes: Vec<u8> = if case % 4 == 0 {
            let len = rng.below(48);
            (0..len)
                .map(|_| match rng.below(4) {
                    0 => rng.next() as u8,
                    _ => alphabet[rng.below(alphabet.len())],
                })
                .collect()
        } else {
            let mut line = lines[rng.below(lines.len())].to_vec();
            for _ in 0..1 + rng.below(3) {
                let at = rng.below(line.len() + 1);
                let byte = alphabet[rng.below(alphabet.len())];
                match rng.below(4) {
                    0 if at < line.len() => line[at] = byte,
                    1 if at < line.len() => {
                        line.remove(at);
                    }
                    2 => {
                        let end = (at + rng.below(8)).min(line.len());
                        let chunk = line[at..end].to_vec();
                        line.splice(at..at, chunk);
                    }
                    _ => line.insert(at, byte),
                }
            }
            line
        };
        check_outcome(&bytes);
    }
}

/// `fixedgl replay`: a malformed recording exits 2 with one `file:line:col: message` line on
/// stderr, a missing one exits 2 with one line naming it, a good one renders (exit 0).
#[cfg(feature = "cli")]
#[test]
fn replay_cli_reports_malformed_recordings_in_one_line() {
    use std::process::Command;
    let dir = std::env::temp_dir().join(format!("fixedgl-replay-cli-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let bad = dir.join("bad.fglrec");
    let good = dir.join("good.fglrec");
    let missing = dir.join("missing.fglrec");
    let png = dir.join("out.png");
    let written = std::fs::write(&bad, "# header\nFlush\nColor3f(0.5 5, 1, 1)\n")
        .and_then(|()| std::fs::write(&good, "Clear(COLOR_BUFFER_BIT)\nFlush\n"));
    assert!(written.is_ok(), "{written:?}");
    let run = |file: &std::path::Path| {
        Command::new(env!("CARGO_BIN_EXE_fixedgl"))
            .args(["replay", "--backend", "cpu", "--size", "4x4", "-o"])
            .arg(&png)
            .arg(file)
            .output()
    };
    let (bad_run, missing_run, good_run) = (run(&bad), run(&missing), run(&good));
    let _ = std::fs::remove_dir_all(&dir);

    let Ok(out) = bad_run else {
        panic!("{bad_run:?}")
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(
        stderr,
        format!(
            "{}:3:13: expected `,` after argument 1 of Color3f, found `5`\n",
            bad.display()
        )
    );
    assert!(out.stdout.is_empty());

    let Ok(out) = missing_run else {
        panic!("{missing_run:?}")
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with(&format!("{}: cannot read: ", missing.display())),
        "{stderr}"
    );

    let Ok(out) = good_run else {
        panic!("{good_run:?}")
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
}
