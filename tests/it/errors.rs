//! Table-driven error tests for the set-side entry points: each row is `(name, setup, call,
//! expected error)`. After the row's call the sticky flag must hold the expected code and the
//! State must be exactly what it was before the call (GL 2.1 §2.5: an erroneous command has no
//! effect but setting the flag). Expected codes come from the GL 2.1 spec and reference pages.

use fixedgl::{gl, Context};

const IE: u32 = gl::INVALID_ENUM;
const IV: u32 = gl::INVALID_VALUE;
const IO: u32 = gl::INVALID_OPERATION;

type Step = fn(&mut Context);

fn none(_: &mut Context) {}

/// Opens a primitive: the call runs between Begin and End.
fn inside(c: &mut Context) {
    c.begin(gl::TRIANGLES);
}

/// Changes some state first, so that "unchanged" is not just "still the initial state".
fn lit(c: &mut Context) {
    c.enable(gl::LIGHTING);
    c.enable(gl::COLOR_MATERIAL);
    c.color4f(0.25, 0.5, 0.75, 1.0);
    c.lightfv(gl::LIGHT1, gl::DIFFUSE, &[0.5, 0.5, 0.5, 1.0]);
    c.shade_model(gl::FLAT);
    c.point_size(3.0);
    c.scissor(1, 2, 3, 4);
}

/// Leaves an INVALID_ENUM unread: a later error must not replace it.
fn enum_error_pending(c: &mut Context) {
    c.shade_model(0);
}

/// Leaves an INVALID_OPERATION unread, inside Begin/End.
fn inside_with_error(c: &mut Context) {
    c.begin(gl::POINTS);
    c.cull_face(gl::BACK);
}

#[rustfmt::skip]
const ROWS: &[(&str, Step, Step, u32)] = &[
    // Begin/End (GL 2.1 §2.6.1, §2.6.3).
    ("Begin inside Begin", inside, |c| c.begin(gl::POINTS), IO),
    ("End without Begin", none, |c| c.end(), IO),
    ("End twice", |c| { c.begin(gl::LINES); c.end(); }, |c| c.end(), IO),
    ("Begin past POLYGON", none, |c| c.begin(gl::POLYGON + 1), IE),
    ("Begin u32::MAX", none, |c| c.begin(u32::MAX), IE),
    ("Begin bad mode inside", inside, |c| c.begin(u32::MAX), IO),
    ("Enable bogus cap", none, |c| c.enable(0x1234), IE),
    ("Disable LIGHT8", none, |c| c.disable(gl::LIGHT7 + 1), IE),
    ("Enable inside", inside, |c| c.enable(gl::LIGHTING), IO),
    ("Disable inside", inside, |c| c.disable(gl::DEPTH_TEST), IO),
    ("GetError inside", inside, |c| { c.get_error(); }, IO),
    // Material (GL 2.1 §2.14.2).
    ("Material bad face", none, |c| c.materialfv(gl::LEFT, gl::AMBIENT, &[1.0; 4]), IE),
    ("Material bad pname", none, |c| c.materialfv(gl::FRONT, gl::POSITION, &[1.0; 4]), IE),
    ("Materialf AMBIENT, bad face", none, |c| c.materialf(gl::LEFT, gl::AMBIENT, 1.0), IE),
    ("Materialf SPOT_EXPONENT", none, |c| c.materialf(gl::FRONT_AND_BACK, gl::SPOT_EXPONENT, 1.0), IE),
    ("Materialf shininess > 128", none, |c| c.materialf(gl::FRONT, gl::SHININESS, 128.5), IV),
    ("Materialf shininess < 0", none, |c| c.materialf(gl::FRONT, gl::SHININESS, -0.5), IV),
    ("Materialf shininess NaN", none, |c| c.materialf(gl::FRONT, gl::SHININESS, f32::NAN), IV),
    ("Materiali shininess 129", lit, |c| c.materiali(gl::BACK, gl::SHININESS, 129), IV),
    ("Materialfv shininess 200", none, |c| c.materialfv(gl::FRONT, gl::SHININESS, &[200.0]), IV),
    ("Materialfv short AMBIENT", none, |c| c.materialfv(gl::FRONT, gl::AMBIENT, &[1.0, 2.0, 3.0]), IV),
    ("Materialfv short COLOR_INDEXES", none, |c| c.materialfv(gl::FRONT, gl::COLOR_INDEXES, &[1.0, 2.0]), IV),
    ("Materialiv empty SHININESS", none, |c| c.materialiv(gl::BACK, gl::SHININESS, &[]), IV),
    ("Materialiv short A_AND_D", lit, |c| c.materialiv(gl::FRONT, gl::AMBIENT_AND_DIFFUSE, &[1]), IV),
    ("Material inside, bad shininess", inside, |c| c.materialf(gl::FRONT, gl::SHININESS, -1.0), IV),
    ("Material inside, bad face", inside, |c| c.materialf(gl::RIGHT, gl::SHININESS, 1.0), IE),
    ("Material inside, short vector", inside, |c| c.materialfv(gl::FRONT, gl::EMISSION, &[1.0]), IV),
    // Light (GL 2.1 §2.14.2, glLight reference page).
    ("Light LIGHT8", none, |c| c.lightf(gl::LIGHT7 + 1, gl::SPOT_EXPONENT, 1.0), IE),
    ("Light below LIGHT0", none, |c| c.lightf(gl::LIGHT0 - 1, gl::SPOT_EXPONENT, 1.0), IE),
    ("Light light 0", none, |c| c.lightfv(0, gl::AMBIENT, &[1.0; 4]), IE),
    // A scalar form takes a vector pname as Mesa does ([param, 0, 0, 0]), the light still checked.
    ("Lightf POSITION, bad light", none, |c| c.lightf(gl::LIGHT0 + 8, gl::POSITION, 1.0), IE),
    ("Lighti AMBIENT, bad pname", none, |c| c.lighti(gl::LIGHT0, gl::EMISSION, 1), IE),
    ("Lightf SPOT_DIRECTION inside", inside, |c| c.lightf(gl::LIGHT0, gl::SPOT_DIRECTION, 1.0), IO),
    ("Lightf SHININESS", none, |c| c.lightf(gl::LIGHT0, gl::SHININESS, 1.0), IE),
    ("Lightfv bad pname", none, |c| c.lightfv(gl::LIGHT2, gl::EMISSION, &[1.0; 4]), IE),
    ("Light spot exponent < 0", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_EXPONENT, -1.0), IV),
    ("Light spot exponent > 128", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_EXPONENT, 128.01), IV),
    ("Lighti spot exponent 129", lit, |c| c.lighti(gl::LIGHT3, gl::SPOT_EXPONENT, 129), IV),
    ("Light cutoff 90.5", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_CUTOFF, 90.5), IV),
    ("Light cutoff -1", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_CUTOFF, -1.0), IV),
    ("Light cutoff 179.9", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_CUTOFF, 179.9), IV),
    ("Lighti cutoff 181", none, |c| c.lighti(gl::LIGHT0, gl::SPOT_CUTOFF, 181), IV),
    ("Light cutoff NaN", none, |c| c.lightf(gl::LIGHT0, gl::SPOT_CUTOFF, f32::NAN), IV),
    ("Light constant att < 0", none, |c| c.lightf(gl::LIGHT0, gl::CONSTANT_ATTENUATION, -0.001), IV),
    ("Light linear att < 0", none, |c| c.lighti(gl::LIGHT0, gl::LINEAR_ATTENUATION, -1), IV),
    ("Light quadratic att NaN", none, |c| c.lightf(gl::LIGHT0, gl::QUADRATIC_ATTENUATION, f32::NAN), IV),
    ("Light quadratic att -inf", none, |c| c.lightfv(gl::LIGHT0, gl::QUADRATIC_ATTENUATION, &[f32::NEG_INFINITY]), IV),
    ("Lightfv short POSITION", none, |c| c.lightfv(gl::LIGHT0, gl::POSITION, &[1.0, 2.0, 3.0]), IV),
    ("Lightfv short SPOT_DIRECTION", none, |c| c.lightfv(gl::LIGHT0, gl::SPOT_DIRECTION, &[1.0, 2.0]), IV),
    ("Lightfv empty SPOT_CUTOFF", none, |c| c.lightfv(gl::LIGHT0, gl::SPOT_CUTOFF, &[]), IV),
    ("Lightiv short DIFFUSE", lit, |c| c.lightiv(gl::LIGHT1, gl::DIFFUSE, &[1]), IV),
    ("Light inside", inside, |c| c.lightfv(gl::LIGHT0, gl::AMBIENT, &[1.0; 4]), IO),
    ("Light bad light inside", inside, |c| c.lightf(99, 99, 1.0), IO),
    // LightModel (GL 2.1 §2.14.2, table 2.10).
    ("LightModelf bad pname", none, |c| c.light_modelf(gl::AMBIENT, 1.0), IE),
    ("LightModel bogus pname", none, |c| c.light_modeli(gl::LIGHTING, 1), IE),
    ("LightModelfv short AMBIENT", none, |c| c.light_modelfv(gl::LIGHT_MODEL_AMBIENT, &[1.0, 2.0, 3.0]), IV),
    ("LightModeliv empty TWO_SIDE", none, |c| c.light_modeliv(gl::LIGHT_MODEL_TWO_SIDE, &[]), IV),
    ("LightModel color control 0", none, |c| c.light_modeli(gl::LIGHT_MODEL_COLOR_CONTROL, 0), IE),
    ("LightModel color control FLAT", lit, |c| c.light_modeli(gl::LIGHT_MODEL_COLOR_CONTROL, gl::FLAT as i32), IE),
    ("LightModelf color control off by 0.5", none,
        |c| c.light_modelf(gl::LIGHT_MODEL_COLOR_CONTROL, gl::SINGLE_COLOR as f32 + 0.5), IE),
    ("LightModel inside", inside, |c| c.light_modeli(gl::LIGHT_MODEL_TWO_SIDE, 1), IO),
    // ColorMaterial (GL 2.1 §2.14.3).
    ("ColorMaterial bad face", none, |c| c.color_material(gl::LEFT, gl::AMBIENT), IE),
    ("ColorMaterial SHININESS", none, |c| c.color_material(gl::FRONT, gl::SHININESS), IE),
    ("ColorMaterial POSITION", lit, |c| c.color_material(gl::FRONT, gl::POSITION), IE),
    ("ColorMaterial inside", inside, |c| c.color_material(gl::FRONT, gl::DIFFUSE), IO),
    // ShadeModel (GL 2.1 §2.14.7).
    ("ShadeModel PHONG_HINT_WIN", none, |c| c.shade_model(gl::PHONG_HINT_WIN), IE),
    ("ShadeModel 0", lit, |c| c.shade_model(0), IE),
    ("ShadeModel inside", inside, |c| c.shade_model(gl::FLAT), IO),
    // Rasterisation (GL 2.1 §3.3 to §3.5).
    ("FrontFace FRONT", none, |c| c.front_face(gl::FRONT), IE),
    ("FrontFace inside", inside, |c| c.front_face(gl::CW), IO),
    ("CullFace CW", none, |c| c.cull_face(gl::CW), IE),
    ("CullFace inside", inside, |c| c.cull_face(gl::FRONT_AND_BACK), IO),
    ("PolygonMode bad face", none, |c| c.polygon_mode(gl::LEFT, gl::LINE), IE),
    ("PolygonMode bad mode", none, |c| c.polygon_mode(gl::FRONT, gl::FRONT), IE),
    ("PolygonMode mode 0", lit, |c| c.polygon_mode(gl::FRONT_AND_BACK, 0), IE),
    ("PolygonMode inside", inside, |c| c.polygon_mode(gl::FRONT_AND_BACK, gl::LINE), IO),
    ("PolygonOffset inside", inside, |c| c.polygon_offset(1.0, 1.0), IO),
    ("PointSize 0", none, |c| c.point_size(0.0), IV),
    ("PointSize -1", lit, |c| c.point_size(-1.0), IV),
    ("PointSize -inf", none, |c| c.point_size(f32::NEG_INFINITY), IV),
    ("PointSize inside", inside, |c| c.point_size(2.0), IO),
    ("LineWidth 0", none, |c| c.line_width(0.0), IV),
    ("LineWidth -0", none, |c| c.line_width(-0.0), IV),
    ("LineWidth inside", inside, |c| c.line_width(2.0), IO),
    // Framebuffer control (GL 2.1 §4.1, §4.2).
    ("Clear bit 0", none, |c| c.clear(0x1), IV),
    ("Clear colour plus stray bit", none, |c| c.clear(gl::COLOR_BUFFER_BIT | 0x8000), IV),
    ("Clear all bits", lit, |c| c.clear(u32::MAX), IV),
    ("Clear inside", inside, |c| c.clear(gl::COLOR_BUFFER_BIT), IO),
    ("ClearColor inside", inside, |c| c.clear_color(1.0, 1.0, 1.0, 1.0), IO),
    ("ClearDepth inside", inside, |c| c.clear_depth(0.5), IO),
    ("ClearStencil inside", inside, |c| c.clear_stencil(1), IO),
    ("DepthFunc below NEVER", none, |c| c.depth_func(gl::NEVER - 1), IE),
    ("DepthFunc past ALWAYS", none, |c| c.depth_func(gl::ALWAYS + 1), IE),
    ("DepthFunc inside", inside, |c| c.depth_func(gl::LEQUAL), IO),
    ("DepthMask inside", inside, |c| c.depth_mask(false), IO),
    ("ColorMask inside", inside, |c| c.color_mask(false, false, false, false), IO),
    ("Scissor negative width", none, |c| c.scissor(0, 0, -1, 1), IV),
    ("Scissor negative height", lit, |c| c.scissor(0, 0, 1, -1), IV),
    ("Scissor inside", inside, |c| c.scissor(0, 0, 1, 1), IO),
    // Hint, PixelStore, Flush, Finish (GL 2.1 §5.6, §3.6.1, §5.5).
    ("Hint mode 0", none, |c| c.hint(gl::FOG_HINT, 0), IE),
    ("Hint mode FLAT", none, |c| c.hint(gl::PHONG_HINT_WIN, gl::FLAT), IE),
    ("Hint bogus target", none, |c| c.hint(0x1234, gl::NICEST), IE),
    ("Hint inside", inside, |c| c.hint(gl::FOG_HINT, gl::NICEST), IO),
    ("PixelStore alignment 3", none, |c| c.pixel_storei(gl::PACK_ALIGNMENT, 3), IV),
    ("PixelStore alignment 0", none, |c| c.pixel_storei(gl::UNPACK_ALIGNMENT, 0), IV),
    ("PixelStore alignment 16", none, |c| c.pixel_storei(gl::UNPACK_ALIGNMENT, 16), IV),
    ("PixelStore alignment -4", none, |c| c.pixel_storei(gl::UNPACK_ALIGNMENT, -4), IV),
    ("PixelStore unknown pname", none, |c| c.pixel_storei(gl::PIXEL_PACK_BUFFER, 0), IE),
    ("PixelStore SKIP_ROWS -1", none, |c| c.pixel_storei(gl::PACK_SKIP_ROWS, -1), IV),
    ("PixelStoref ROW_LENGTH NaN", none, |c| c.pixel_storef(gl::UNPACK_ROW_LENGTH, f32::NAN), IV),
    ("PixelStoref NaN", none, |c| c.pixel_storef(gl::PACK_ALIGNMENT, f32::NAN), IV),
    ("PixelStoref 2.6 rounds to 3", none, |c| c.pixel_storef(gl::PACK_ALIGNMENT, 2.6), IV),
    ("PixelStore inside", inside, |c| c.pixel_storei(gl::PACK_ALIGNMENT, 4), IO),
    ("Flush inside", inside, |c| c.flush(), IO),
    ("Finish inside", inside, |c| c.finish(), IO),
    // The first error sticks (GL 2.1 §2.5).
    ("sticky: INVALID_VALUE after INVALID_ENUM", enum_error_pending, |c| c.point_size(0.0), IE),
    ("sticky: INVALID_OPERATION after INVALID_ENUM", enum_error_pending, |c| c.end(), IE),
    ("sticky: INVALID_ENUM after INVALID_OPERATION", inside_with_error, |c| c.materialf(gl::LEFT, gl::SHININESS, 1.0), IO),
    ("sticky: get_error inside keeps the flag", inside_with_error, |c| { c.get_error(); }, IO),
];

#[test]
fn every_row_sets_its_error_and_changes_nothing() {
    assert!(ROWS.len() >= 80, "{} rows", ROWS.len());
    let mut failures = Vec::new();
    for &(name, setup, call, expected) in ROWS {
        let Ok(mut c) = Context::new(4, 4) else {
            panic!("context")
        };
        setup(&mut c);
        let before = c.state().clone();
        call(&mut c);
        let got = c.pending_error();
        if got != expected {
            failures.push(format!("{name}: expected {expected:#x}, got {got:#x}"));
        }
        if *c.state() != before {
            failures.push(format!("{name}: state changed"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn first_error_is_read_once_then_cleared() {
    let Ok(mut c) = Context::new(4, 4) else {
        panic!("context")
    };
    c.point_size(-1.0); // INVALID_VALUE
    c.shade_model(0); // INVALID_ENUM, dropped
    c.end(); // INVALID_OPERATION, dropped
    assert_eq!(c.get_error(), gl::INVALID_VALUE);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn errors_inside_begin_end_are_read_after_end() {
    let Ok(mut c) = Context::new(4, 4) else {
        panic!("context")
    };
    c.begin(gl::TRIANGLES);
    c.shade_model(gl::FLAT);
    assert_eq!(
        c.get_error(),
        gl::NO_ERROR,
        "GetError inside Begin/End reads nothing"
    );
    c.end();
    assert_eq!(c.get_error(), gl::INVALID_OPERATION);
    assert_eq!(c.state().shade_model, gl::SMOOTH);
}

#[test]
fn valid_calls_inside_begin_end_raise_nothing() {
    let Ok(mut c) = Context::new(4, 4) else {
        panic!("context")
    };
    c.begin(gl::TRIANGLES);
    c.vertex3f(0.0, 0.0, 0.0);
    c.normal3b(1, 2, 3);
    c.color4ub(1, 2, 3, 4);
    c.secondary_color3f(0.1, 0.2, 0.3);
    c.tex_coord2f(0.5, 0.5);
    c.fog_coordf(1.0);
    c.edge_flag(false);
    c.materialf(gl::FRONT, gl::SHININESS, 10.0);
    c.materialfv(gl::BACK, gl::AMBIENT, &[0.1, 0.2, 0.3, 1.0]);
    c.end();
    assert_eq!(c.get_error(), gl::NO_ERROR);
    assert_eq!(c.state().materials[0].shininess, 10.0);
    assert_eq!(
        c.state().materials[1].ambient.to_array(),
        [0.1, 0.2, 0.3, 1.0]
    );
}
