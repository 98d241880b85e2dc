//! Writes `gl_calls.rs` from gl.xml (the Khronos registry, from `khronos_api`, read with
//! `roxmltree`, as src/commands/gen.rs reads it): every GL 1.0–1.5 command declared as C
//! declares it, and one function that calls command `i` with arguments drawn by `Fuzz`.
//!
//! How an argument is drawn depends on its C type and name:
//! - `GLenum`: from the parameter's enum group in gl.xml (most of the time), any GL 1.x enum, or
//!   a number no enum has;
//! - integers named like sizes (width, count, stride, n, ...) and every `GLsizei`: small values,
//!   and huge ones only when every pointer of the call is NULL and the command keeps nothing that
//!   a later call reads through a pointer (`BOUNDED`): GL trusts a non-null pointer to hold what
//!   the sizes say, and the fuzzer keeps that promise;
//! - pointers: NULL now and then, else memory of the fuzzer's that is large enough for any size
//!   it draws (input memory holds small numbers, so that indices stay within the arrays).

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write as _;

/// Commands whose sizes stay small whatever their pointers: they keep a pointer or a layout that
/// later calls read or write through (array pointers, pixel-store modes, selection and feedback
/// buffers), or draw from arrays set earlier, or loop over a range without touching memory.
const BOUNDED: &[&str] = &[
    "glArrayElement",
    "glDrawArrays",
    "glDrawElements",
    "glDrawRangeElements",
    "glMultiDrawArrays",
    "glMultiDrawElements",
    "glPixelStoref",
    "glPixelStorei",
    "glVertexPointer",
    "glNormalPointer",
    "glColorPointer",
    "glIndexPointer",
    "glTexCoordPointer",
    "glEdgeFlagPointer",
    "glSecondaryColorPointer",
    "glFogCoordPointer",
    "glInterleavedArrays",
    "glSelectBuffer",
    "glFeedbackBuffer",
    "glEvalMesh1",
    "glEvalMesh2",
    "glEvalPoint1",
    "glEvalPoint2",
];

/// Integer parameters that say how much memory a call touches.
const SIZE_NAMES: &[&str] = &[
    "width",
    "height",
    "depth",
    "count",
    "n",
    "size",
    "stride",
    "first",
    "start",
    "end",
    "range",
    "i",
    "j",
    "i1",
    "i2",
    "j1",
    "j2",
    "len",
    "mapsize",
    "order",
    "uorder",
    "vorder",
    "ustride",
    "vstride",
    "drawcount",
    "primcount",
    "un",
    "vn",
    "offset",
    "bufSize",
];

/// Input that must hold small integers: indices (a huge one would make GL read client arrays far
/// past their end, which a C caller never asks for), and buffer data (which may be used as
/// indices later).
fn small_ints(command: &str, param: &str) -> bool {
    // MultiDraw*'s first and count arrays are sizes in memory: GL reads count[i] elements or
    // indices, so they must be small, as the scalar sizes of a BOUNDED command are.
    param == "indices"
        || (command.starts_with("glMultiDraw") && matches!(param, "first" | "count"))
        || command == "glCallLists"
        || (matches!(command, "glBufferData" | "glBufferSubData") && param == "data")
}

struct Param {
    name: String,
    c_type: String,
    ptype: String,
    group: Option<String>,
}

struct Command {
    name: String,
    ret: String,
    params: Vec<Param>,
}

fn text_of(n: roxmltree::Node) -> String {
    n.descendants()
        .filter(|n| n.is_text())
        .filter_map(|n| n.text())
        .collect()
}

fn child_text<'a>(n: roxmltree::Node<'a, 'a>, tag: &str) -> Option<&'a str> {
    n.children()
        .find(|c| c.has_tag_name(tag))
        .and_then(|c| c.text())
}

/// Rust's type for a C scalar type.
fn scalar(ptype: &str) -> &'static str {
    match ptype {
        "GLenum" | "GLbitfield" | "GLuint" => "u32",
        "GLboolean" | "GLubyte" => "u8",
        "GLbyte" => "i8",
        "GLshort" => "i16",
        "GLushort" => "u16",
        "GLint" | "GLsizei" => "i32",
        "GLfloat" | "GLclampf" => "f32",
        "GLdouble" | "GLclampd" => "f64",
        "GLintptr" | "GLsizeiptr" => "isize",
        "void" | "GLvoid" => "c_void",
        other => panic!("no Rust type for {other}"),
    }
}

/// Rust's type for a C type: `const GLfloat *` → `*const f32`, `const void *const*` →
/// `*const *const c_void`.
fn rust_type(c_type: &str) -> String {
    let parts: Vec<&str> = c_type.split('*').collect();
    let base = parts[0]
        .split_whitespace()
        .rfind(|w| *w != "const")
        .unwrap_or("void");
    let mut out = scalar(base).to_string();
    let mut constant = parts[0].split_whitespace().any(|w| w == "const");
    for q in &parts[1..] {
        out = format!("*{} {out}", if constant { "const" } else { "mut" });
        constant = q.contains("const");
    }
    out
}

fn ident(name: &str) -> String {
    match name {
        "type" => "type_".into(),
        "ref" => "ref_".into(),
        other => other.to_string(),
    }
}

fn const_name(group: &str) -> String {
    let mut s = String::from("G_");
    for (i, c) in group.chars().enumerate() {
        if c.is_ascii_uppercase() && i > 0 {
            s.push('_');
        }
        s.push(c.to_ascii_uppercase());
    }
    s
}

/// The generated file.
pub fn generate() -> String {
    let text = std::str::from_utf8(khronos_api::GL_XML).expect("gl.xml is UTF-8");
    let doc = roxmltree::Document::parse(text).expect("gl.xml parses");
    let root = doc.root_element();

    let mut values: HashMap<&str, u32> = HashMap::new();
    for e in root.descendants().filter(|n| n.has_tag_name("enum")) {
        let (Some(name), Some(v)) = (e.attribute("name"), e.attribute("value")) else {
            continue;
        };
        if e.attribute("api").is_some_and(|a| a != "gl") {
            continue;
        }
        let v = v.trim_start_matches("0x").trim_start_matches("0X");
        if let Ok(v) = u64::from_str_radix(v, 16) {
            values.entry(name).or_insert(v as u32);
        }
    }
    let mut groups: HashMap<&str, BTreeSet<u32>> = HashMap::new();
    for g in root.descendants().filter(|n| n.has_tag_name("group")) {
        let Some(name) = g.attribute("name") else {
            continue;
        };
        let set = groups.entry(name).or_default();
        for e in g.children().filter(|n| n.has_tag_name("enum")) {
            if let Some(v) = e.attribute("name").and_then(|n| values.get(n)) {
                set.insert(*v);
            }
        }
    }

    let mut protos: HashMap<String, Command> = HashMap::new();
    for cmd in root.descendants().filter(|n| n.has_tag_name("command")) {
        let Some(proto) = cmd.children().find(|n| n.has_tag_name("proto")) else {
            continue;
        };
        let name = child_text(proto, "name").unwrap_or_default().to_string();
        let ret = text_of(proto)
            .trim_end()
            .strip_suffix(name.as_str())
            .unwrap_or("")
            .trim()
            .to_string();
        let params = cmd
            .children()
            .filter(|n| n.has_tag_name("param"))
            .map(|p| {
                let pname = child_text(p, "name").unwrap_or_default().to_string();
                let c_type = text_of(p)
                    .trim_end()
                    .strip_suffix(pname.as_str())
                    .unwrap_or("")
                    .trim()
                    .to_string();
                Param {
                    name: pname,
                    ptype: child_text(p, "ptype").unwrap_or("void").to_string(),
                    c_type,
                    group: p.attribute("group").map(str::to_string),
                }
            })
            .collect();
        protos.insert(name.clone(), Command { name, ret, params });
    }

    let mut commands = Vec::new();
    let mut enums_1x = BTreeSet::new();
    let mut seen = BTreeSet::new();
    for f in root.descendants().filter(|n| n.has_tag_name("feature")) {
        let number = f.attribute("number").unwrap_or("");
        if f.attribute("api") != Some("gl") || !number.starts_with("1.") {
            continue;
        }
        for req in f.children().filter(|n| n.has_tag_name("require")) {
            for c in req.children() {
                let Some(name) = c.attribute("name") else {
                    continue;
                };
                if c.has_tag_name("enum") {
                    if let Some(v) = values.get(name) {
                        enums_1x.insert(*v);
                    }
                } else if c.has_tag_name("command") && seen.insert(name.to_string()) {
                    commands.push(protos.remove(name).expect("a required command exists"));
                }
            }
        }
    }

    // The enum groups the commands use (empty ones fall back to every GL 1.x enum).
    let mut used: BTreeMap<String, Vec<u32>> = BTreeMap::new();
    for c in &commands {
        for p in &c.params {
            if p.ptype == "GLenum" && !p.c_type.contains('*') {
                if let Some(g) = &p.group {
                    let set = groups.get(g.as_str()).cloned().unwrap_or_default();
                    if !set.is_empty() {
                        used.insert(g.clone(), set.into_iter().collect());
                    }
                }
            }
        }
    }

    let mut s = String::from(
        "// @generated by capi/tests/c_abi_fuzz/gen.rs from gl.xml (khronos_api).\n\
         // Do not edit: `FIXEDGL_BLESS=1 cargo test -p fixedgl-capi --test c_abi_fuzz_gen` rewrites it.\n\
         //! Every GL 1.0-1.5 command as C declares it (the C ABI library exports them all), and\n\
         //! `call(i, fuzz)`: command `i` with arguments drawn by `Fuzz`.\n\
         #![allow(clippy::all, unused_unsafe, non_snake_case)]\n\n\
         use std::ffi::c_void;\n\n\
         use super::Fuzz;\n\n",
    );
    let _ = writeln!(
        s,
        "/// Every enum of GL 1.0-1.5 ({}).\npub const ENUMS_1X: &[u32] = &{:?};\n",
        enums_1x.len(),
        enums_1x.iter().collect::<Vec<_>>()
    );
    for (g, v) in &used {
        let _ = writeln!(
            s,
            "/// gl.xml's group {g}.\nconst {}: &[u32] = &{v:?};",
            const_name(g)
        );
    }
    s.push_str("\nextern \"C\" {\n");
    for c in &commands {
        let params: Vec<String> = c
            .params
            .iter()
            .map(|p| format!("{}: {}", ident(&p.name), rust_type(&p.c_type)))
            .collect();
        let ret = rust_type(&c.ret);
        let ret = if ret == "c_void" {
            String::new()
        } else {
            format!(" -> {ret}")
        };
        let _ = writeln!(s, "    pub fn {}({}){ret};", c.name, params.join(", "));
    }
    s.push_str("}\n\n");
    let _ = writeln!(
        s,
        "/// The commands' names, in `call`'s numbering.\npub const NAMES: [&str; {}] = [",
        commands.len()
    );
    for c in &commands {
        let _ = writeln!(s, "    {:?},", c.name);
    }
    s.push_str("];\n\n");
    s.push_str(
        "/// Calls command `i` of `NAMES` with arguments drawn by `fz` (traced first when asked).\n\
         pub unsafe fn call(i: usize, fz: &mut Fuzz) {\n    match i {\n",
    );
    for (i, c) in commands.iter().enumerate() {
        let _ = writeln!(s, "        {i} => {{");
        // Pointers first: whether any is non-null decides how large the sizes may be.
        let mut ptrs = Vec::new();
        for p in &c.params {
            let t = rust_type(&p.c_type);
            if !t.starts_with('*') {
                continue;
            }
            let v = ident(&p.name);
            let draw = if t.starts_with("*const *const") {
                "fz.pointers()".to_string()
            } else if t.starts_with("*const") && small_ints(&c.name, &p.name) {
                format!("fz.indices::<{}>()", t.strip_prefix("*const ").unwrap())
            } else if t.starts_with("*const") {
                format!("fz.input::<{}>()", t.strip_prefix("*const ").unwrap())
            } else {
                format!("fz.output::<{}>()", t.strip_prefix("*mut ").unwrap())
            };
            let _ = writeln!(s, "            let {v}: {t} = {draw};");
            ptrs.push(v);
        }
        let bounded = BOUNDED.contains(&c.name.as_str());
        let cond = if bounded {
            "true".to_string()
        } else if ptrs.is_empty() {
            "false".to_string()
        } else {
            ptrs.iter()
                .map(|p| format!("!{p}.is_null()"))
                .collect::<Vec<_>>()
                .join(" || ")
        };
        let _ = writeln!(s, "            fz.bounded = {cond};");
        for p in &c.params {
            let t = rust_type(&p.c_type);
            if t.starts_with('*') {
                continue;
            }
            let v = ident(&p.name);
            let size = p.ptype == "GLsizei" || SIZE_NAMES.contains(&p.name.as_str());
            let draw = match p.ptype.as_str() {
                "GLenum" => match p.group.as_deref().filter(|g| used.contains_key(*g)) {
                    Some(g) => format!("fz.enum_({})", const_name(g)),
                    None => "fz.enum_(&[])".to_string(),
                },
                "GLbitfield" => "fz.bits()".to_string(),
                "GLboolean" => "fz.boolean()".to_string(),
                "GLfloat" | "GLclampf" => "fz.float()".to_string(),
                "GLdouble" | "GLclampd" => "fz.float() as f64".to_string(),
                "GLintptr" | "GLsizeiptr" => format!("fz.int({size}) as isize"),
                "GLuint" if !size => "fz.name()".to_string(),
                _ => format!("fz.int({size}) as {t}"),
            };
            let _ = writeln!(s, "            let {v}: {t} = {draw};");
        }
        let args: Vec<String> = c.params.iter().map(|p| ident(&p.name)).collect();
        let dbg: Vec<String> = args.iter().map(|a| format!("&{a}")).collect();
        let _ = writeln!(s, "            fz.trace({i}, &[{}]);", dbg.join(", "));
        let call = format!("{}({})", c.name, args.join(", "));
        if c.name == "glGetString" {
            let _ = writeln!(s, "            fz.string({call});");
        } else {
            let _ = writeln!(s, "            let _ = {call};");
        }
        s.push_str("        }\n");
    }
    s.push_str("        _ => unreachable!(\"command {i}\"),\n    }\n}\n");
    s
}
