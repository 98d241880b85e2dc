//! The CPU front end and the real driver give the same error for every pname-taking command of
//! the command table, with valid and invalid targets, pnames, values and vector lengths.
//!
//! The cases are made from `fixedgl::commands::COMMANDS`, not from a hand list: every
//! implemented command with a `pname` parameter is called with each first argument of its enum
//! group (valid ones and an invalid one), each pname any count function knows plus a few no
//! command takes, and each value of a pool (numbers, and the enums the validators accept), through
//! the scalar form and the vector form with a full and a short vector. Each call goes through the
//! recording reader (which builds the `Call` from its text, as a user's recording would), then to
//! a CPU `Context` and to the GL backend, and the two `get_error`s must be equal. Both sides run
//! the same stream, so the state each call meets is the same.
//!
//! BindTexture takes no pname, and texture queries are no `Call`s, so a second test walks
//! BindTexture over every target and kind of name and compares, after each call, the error and
//! what the texture queries answer (bindings, IsEnabled, GetTexParameterfv).

#![cfg(feature = "gl")]

use fixedgl::commands::{Command, COMMANDS};
use fixedgl::recording::read_recording;
use fixedgl::{gl, Call, Context};

/// The first arguments tried for a parameter of `group`: the valid ones and one invalid.
fn firsts(group: Option<&str>) -> &'static [&'static str] {
    match group {
        Some("LightName") => &["LIGHT0", "LIGHT7", "0x4008"],
        Some("MaterialFace") | Some("TriangleFace") => {
            &["FRONT", "BACK", "FRONT_AND_BACK", "LIGHT0"]
        }
        Some("TextureTarget") => &[
            "TEXTURE_1D",
            "TEXTURE_2D",
            "TEXTURE_3D",
            "TEXTURE_CUBE_MAP",
            "PROXY_TEXTURE_2D",
            "LIGHT0",
        ],
        Some("TextureEnvTarget") => &[
            "TEXTURE_ENV",
            "TEXTURE_FILTER_CONTROL",
            "POINT_SPRITE",
            "FOG",
        ],
        Some("TextureCoordName") => &["S", "T", "R", "Q", "TEXTURE_2D"],
        _ => &["0x1234"],
    }
}

/// Every pname some count function knows, and a few that no command takes.
const PNAMES: &[&str] = &[
    // Light and Material (tables 6.9, 6.10)
    "AMBIENT",
    "DIFFUSE",
    "SPECULAR",
    "POSITION",
    "SPOT_DIRECTION",
    "SPOT_EXPONENT",
    "SPOT_CUTOFF",
    "CONSTANT_ATTENUATION",
    "LINEAR_ATTENUATION",
    "QUADRATIC_ATTENUATION",
    "EMISSION",
    "SHININESS",
    "AMBIENT_AND_DIFFUSE",
    "COLOR_INDEXES",
    // LightModel
    "LIGHT_MODEL_AMBIENT",
    "LIGHT_MODEL_LOCAL_VIEWER",
    "LIGHT_MODEL_TWO_SIDE",
    "LIGHT_MODEL_COLOR_CONTROL",
    // PointParameter (table 6.11)
    "POINT_SIZE_MIN",
    "POINT_SIZE_MAX",
    "POINT_FADE_THRESHOLD_SIZE",
    "POINT_DISTANCE_ATTENUATION",
    "POINT_SPRITE_COORD_ORIGIN",
    // Fog (table 6.8)
    "FOG_COLOR",
    "FOG_MODE",
    "FOG_DENSITY",
    "FOG_START",
    "FOG_END",
    "FOG_INDEX",
    "FOG_COORD_SRC",
    // TexEnv (table 6.20)
    "TEXTURE_ENV_MODE",
    "TEXTURE_ENV_COLOR",
    "COMBINE_RGB",
    "COMBINE_ALPHA",
    "SRC0_RGB",
    "SRC1_ALPHA",
    "OPERAND0_RGB",
    "OPERAND2_ALPHA",
    "RGB_SCALE",
    "ALPHA_SCALE",
    "TEXTURE_LOD_BIAS",
    "COORD_REPLACE",
    // TexGen (table 6.15)
    "TEXTURE_GEN_MODE",
    "OBJECT_PLANE",
    "EYE_PLANE",
    // TexParameter (table 6.16)
    "TEXTURE_MIN_FILTER",
    "TEXTURE_MAG_FILTER",
    "TEXTURE_WRAP_S",
    "TEXTURE_WRAP_T",
    "TEXTURE_WRAP_R",
    "TEXTURE_BORDER_COLOR",
    "TEXTURE_PRIORITY",
    "TEXTURE_MIN_LOD",
    "TEXTURE_MAX_LOD",
    "TEXTURE_BASE_LEVEL",
    "TEXTURE_MAX_LEVEL",
    "DEPTH_TEXTURE_MODE",
    "TEXTURE_COMPARE_MODE",
    "TEXTURE_COMPARE_FUNC",
    "GENERATE_MIPMAP",
    // PixelStore (tables 3.1, 6.17, 6.18): all sixteen
    "UNPACK_SWAP_BYTES",
    "UNPACK_LSB_FIRST",
    "UNPACK_ROW_LENGTH",
    "UNPACK_SKIP_ROWS",
    "UNPACK_SKIP_PIXELS",
    "UNPACK_ALIGNMENT",
    "UNPACK_IMAGE_HEIGHT",
    "UNPACK_SKIP_IMAGES",
    "PACK_SWAP_BYTES",
    "PACK_LSB_FIRST",
    "PACK_ROW_LENGTH",
    "PACK_SKIP_ROWS",
    "PACK_SKIP_PIXELS",
    "PACK_ALIGNMENT",
    "PACK_IMAGE_HEIGHT",
    "PACK_SKIP_IMAGES",
    // PixelTransfer (table 3.2), and the imaging subset's POST_COLOR_MATRIX_RED_SCALE and
    // POST_CONVOLUTION_RED_BIAS, which neither fixedgl nor the driver takes
    "MAP_COLOR",
    "MAP_STENCIL",
    "INDEX_SHIFT",
    "INDEX_OFFSET",
    "RED_SCALE",
    "GREEN_BIAS",
    "BLUE_SCALE",
    "ALPHA_BIAS",
    "DEPTH_SCALE",
    "DEPTH_BIAS",
    "0x80B4",
    "0x8020",
    // No command takes these.
    "0x1234",
    "LIGHT0",
    "TEXTURE_2D",
];

/// Values tried for every pname: numbers, and the enums the validators accept.
const VALUES: &[&str] = &[
    "0",
    "1",
    "-1",
    "2",
    "4",
    "8",
    "0.5",
    "1000",
    "NEAREST",
    "LINEAR",
    "LINEAR_MIPMAP_LINEAR",
    "REPEAT",
    "CLAMP",
    "CLAMP_TO_EDGE",
    "MIRRORED_REPEAT",
    "MODULATE",
    "REPLACE",
    "DECAL",
    "COMBINE",
    "ADD_SIGNED",
    "INTERPOLATE",
    "DOT3_RGB",
    "TEXTURE",
    "TEXTURE1",
    "TEXTURE3",
    "TEXTURE4",
    "PRIMARY_COLOR",
    "CONSTANT",
    "SRC_COLOR",
    "ONE_MINUS_SRC_ALPHA",
    "EXP",
    "EXP2",
    "FRAGMENT_DEPTH",
    "FOG_COORD",
    "EYE_LINEAR",
    "OBJECT_LINEAR",
    "SPHERE_MAP",
    "REFLECTION_MAP",
    "NORMAL_MAP",
    "SEPARATE_SPECULAR_COLOR",
    "SINGLE_COLOR",
    "COMPARE_R_TO_TEXTURE",
    "LEQUAL",
    "LUMINANCE",
    "INTENSITY",
];

/// Where fixedgl differs from the driver on purpose, until the issue named lands: the line's
/// prefix and why. Each must still disagree somewhere (the test fails when one no longer does,
/// so the list only shrinks).
const KNOWN: &[(&str, &str)] = &[];

/// The `Call` a recording line reads as (the reader is the table-driven constructor).
fn call(line: &str) -> Call {
    match read_recording(line.as_bytes()) {
        Ok(calls) if calls.len() == 1 => calls.into_iter().next().unwrap_or(Call::Flush),
        other => panic!("`{line}` does not read as one call: {other:?}"),
    }
}

/// A value literal of the C type `c_type` (float or integer form).
fn literal(value: &str, c_type: &str) -> String {
    let float = c_type.contains("GLfloat") || c_type.contains("GLdouble");
    match value.parse::<f64>() {
        Ok(v) if float => format!("{v:?}"),
        Ok(v) => format!("{}", v as i64),
        // An enum name: the reader takes names where numbers go, in float arguments too.
        Err(_) if float => format!("{}.0", enum_value(value)),
        Err(_) => value.to_string(),
    }
}

fn enum_value(name: &str) -> u32 {
    gl::NAMES
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(0, |&(_, v)| v)
}

/// The lines to try for one command row.
fn lines(cmd: &Command) -> Vec<String> {
    let name = cmd.name.trim_start_matches("gl");
    let pname_at = cmd.params.iter().position(|p| p.name == "pname");
    let Some(pname_at) = pname_at else {
        return Vec::new();
    };
    let value = cmd.params.last().map_or("", |p| p.c_type);
    let vector = value.contains('*');
    let leads: Vec<&str> = match pname_at {
        0 => vec![""],
        _ => firsts(cmd.params[0].group).to_vec(),
    };
    let mut out = Vec::new();
    for lead in &leads {
        let lead = if lead.is_empty() {
            String::new()
        } else {
            format!("{lead}, ")
        };
        for pname in PNAMES {
            for v in VALUES {
                let lit = literal(v, value);
                if vector {
                    out.push(format!(
                        "{name}({lead}{pname}, [{lit}, {lit}, {lit}, {lit}])"
                    ));
                    out.push(format!("{name}({lead}{pname}, [{lit}])"));
                } else {
                    out.push(format!("{name}({lead}{pname}, {lit})"));
                }
            }
            if vector {
                out.push(format!("{name}({lead}{pname}, [])"));
            }
        }
    }
    out
}

#[test]
fn cpu_and_driver_agree_on_every_pname_error() {
    let Some(mut driver) = crate::common::test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).expect("an 8x8 context");
    // A texture object bound, as lecture code has when it sets parameters.
    for c in [Call::GenTextures(1), Call::BindTexture(gl::TEXTURE_2D, 1)] {
        cpu.execute(&c);
        driver.execute(&c);
    }
    let commands: Vec<&Command> = COMMANDS
        .iter()
        .filter(|c| c.method.is_some() && c.params.iter().any(|p| p.name == "pname"))
        .collect();
    // Light, Material, LightModel, Fog, PointParameter, TexParameter, TexEnv and TexGen in
    // their f, i, fv and iv forms (TexGen also d, dv), PixelStore and PixelTransfer: 38 rows.
    assert_eq!(commands.len(), 38, "pname-taking commands");
    let (mut cases, mut mismatches) = (0, Vec::new());
    let mut known_seen = vec![0usize; KNOWN.len()];
    for cmd in commands {
        for line in lines(cmd) {
            let c = call(&line);
            cpu.execute(&c);
            driver.execute(&c);
            let (a, b) = (cpu.get_error(), driver.get_error());
            cases += 1;
            if a == b {
                continue;
            }
            match KNOWN
                .iter()
                .position(|(prefix, _)| line.starts_with(prefix))
            {
                Some(k) => known_seen[k] += 1,
                None => mismatches.push(format!("{line}: CPU {a:#x}, driver {b:#x}")),
            }
        }
    }
    assert!(cases > 10_000, "{cases} cases");
    let known: usize = known_seen.iter().sum();
    eprintln!("error agreement: {cases} calls, {known} in KNOWN differences, the rest agree");
    for ((prefix, why), seen) in KNOWN.iter().zip(&known_seen) {
        assert!(
            *seen > 0,
            "`{prefix}` ({why}) agrees now: remove it from KNOWN"
        );
    }
    // One line per command, first argument and pname (the values that disagree counted).
    let mut groups: Vec<(String, usize, String)> = Vec::new();
    for m in &mismatches {
        let key = m
            .split_once(", [")
            .or_else(|| m.rsplit_once(", "))
            .map_or(m.as_str(), |p| p.0);
        match groups.last_mut() {
            Some((k, n, _)) if k == key => *n += 1,
            _ => groups.push((key.to_string(), 1, m.clone())),
        }
    }
    let report: Vec<String> = groups
        .iter()
        .map(|(_, n, first)| format!("{first} (and {} more)", n - 1))
        .collect();
    assert!(
        mismatches.is_empty(),
        "{} of {cases} cases disagree, in {} groups:\n{}",
        mismatches.len(),
        groups.len(),
        report.join("\n")
    );
}

/// The texture queries both backends answer.
trait TextureQueries {
    fn binding(&mut self, pname: u32) -> i32;
    fn enabled(&mut self, cap: u32) -> bool;
    fn param(&mut self, target: u32, pname: u32) -> f32;
}

impl TextureQueries for Context {
    fn binding(&mut self, pname: u32) -> i32 {
        let mut v = [0];
        self.get_integerv(pname, &mut v);
        v[0]
    }
    fn enabled(&mut self, cap: u32) -> bool {
        self.is_enabled(cap)
    }
    fn param(&mut self, target: u32, pname: u32) -> f32 {
        let mut v = [0.0];
        self.get_tex_parameterfv(target, pname, &mut v);
        v[0]
    }
}

impl TextureQueries for fixedgl::glbackend::GlBackend {
    fn binding(&mut self, pname: u32) -> i32 {
        let mut v = [0];
        self.get_integerv(pname, &mut v);
        v[0]
    }
    fn enabled(&mut self, cap: u32) -> bool {
        self.is_enabled(cap)
    }
    fn param(&mut self, target: u32, pname: u32) -> f32 {
        let mut v = [0.0];
        self.get_tex_parameterfv(target, pname, &mut v);
        v[0]
    }
}

/// What the texture queries show of the active unit: the four bindings, each target's enable,
/// and parameters of the object bound to each target (NaN printed as NaN, so it compares).
fn texture_probe(q: &mut impl TextureQueries) -> String {
    let targets = [
        gl::TEXTURE_1D,
        gl::TEXTURE_2D,
        gl::TEXTURE_3D,
        gl::TEXTURE_CUBE_MAP,
    ];
    let b = [
        gl::TEXTURE_BINDING_1D,
        gl::TEXTURE_BINDING_2D,
        gl::TEXTURE_BINDING_3D,
        gl::TEXTURE_BINDING_CUBE_MAP,
    ]
    .map(|p| q.binding(p));
    let e = targets.map(|t| q.enabled(t));
    let p = targets.map(|t| {
        [
            gl::TEXTURE_LOD_BIAS,
            gl::TEXTURE_WRAP_R,
            gl::TEXTURE_MIN_FILTER,
        ]
        .map(|p| q.param(t, p))
    });
    format!("bindings {b:?} enabled {e:?} params {p:?}")
}

/// BindTexture with every target (the binding targets, a proxy, a cube-map face, a non-target)
/// and every kind of name (0, generated, never generated, bound to another target, deleted), on
/// two units, with TexParameter, Enable, PushAttrib(TEXTURE_BIT)/PopAttrib and DeleteTextures
/// between: after each call the error, the bindings (TEXTURE_BINDING_*), IsEnabled and the
/// bound objects' parameters (GetTexParameterfv) are the driver's.
#[test]
fn texture_targets_bindings_and_parameters_agree_with_the_driver() {
    let Some(mut driver) = crate::common::test_backend(8, 8) else {
        return;
    };
    let mut cpu = Context::new(8, 8).expect("an 8x8 context");
    let targets = [
        gl::TEXTURE_1D,
        gl::TEXTURE_2D,
        gl::TEXTURE_3D,
        gl::TEXTURE_CUBE_MAP,
        gl::PROXY_TEXTURE_2D,
        gl::TEXTURE_CUBE_MAP_POSITIVE_X,
        gl::LIGHT0,
    ];
    let mut calls = vec![Call::GenTextures(4)];
    let mut tag = 0.0f32;
    for unit in [gl::TEXTURE0, gl::TEXTURE1] {
        calls.push(Call::ActiveTexture(unit));
        for name in [0, 1, 2, 3, 9] {
            for &target in &targets {
                calls.push(Call::BindTexture(target, name));
                // Tag the bound object, to see which one later queries reach.
                tag += 0.25;
                calls.push(Call::TexParameterf(target, gl::TEXTURE_LOD_BIAS, tag));
                calls.push(Call::TexParameteri(
                    target,
                    gl::TEXTURE_WRAP_R,
                    gl::CLAMP_TO_EDGE as i32,
                ));
            }
        }
        for &target in &targets {
            calls.push(Call::Enable(target));
        }
        calls.push(Call::PushAttrib(gl::TEXTURE_BIT));
        for (k, &target) in targets.iter().enumerate() {
            calls.push(Call::Disable(target));
            calls.push(Call::BindTexture(target, 4 + k as u32));
            calls.push(Call::TexParameteri(
                target,
                gl::TEXTURE_MIN_FILTER,
                gl::LINEAR as i32,
            ));
        }
        calls.push(Call::BindTexture(gl::TEXTURE_2D, 1));
        calls.push(Call::TexParameterf(
            gl::TEXTURE_2D,
            gl::TEXTURE_LOD_BIAS,
            -9.0,
        ));
        calls.push(Call::PopAttrib);
    }
    calls.push(Call::DeleteTextures(3, vec![2, 3, 5]));
    calls.push(Call::ActiveTexture(gl::TEXTURE0));
    calls.push(Call::BindTexture(gl::TEXTURE_CUBE_MAP, 2));
    calls.push(Call::TexParameterf(
        gl::TEXTURE_CUBE_MAP,
        gl::TEXTURE_LOD_BIAS,
        f32::NAN,
    ));
    calls.push(Call::DeleteTextures(2, vec![1, 9]));
    let mut checked = 0;
    for (i, c) in calls.iter().enumerate() {
        cpu.execute(c);
        driver.execute(c);
        let (a, b) = (cpu.get_error(), driver.get_error());
        assert_eq!(a, b, "call {i} {c:?}: CPU {a:#x}, driver {b:#x}");
        let (cpu_probe, driver_probe) = (texture_probe(&mut cpu), texture_probe(&mut driver));
        assert_eq!(cpu_probe, driver_probe, "after call {i} {c:?}");
        assert_eq!(
            (cpu.get_error(), driver.get_error()),
            (gl::NO_ERROR, gl::NO_ERROR),
            "the queries after call {i}"
        );
        checked += 1;
    }
    assert!(checked > 150, "{checked} calls");
}
