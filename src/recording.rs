//! The recording file format: a `Vec<Call>` as text, one call per line.
//!
//! ```text
//! # fixedgl recording
//! Begin(TRIANGLES)
//! Lightfv(LIGHT0, POSITION, [1.0, 1.5, -0.5, 1.0])
//! Normal3fv((0.0, 0.0, 1.0))
//! Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT)
//! ```
//!
//! Each line is one [`Call`] in RON syntax (fixed-length arrays are RON tuples `(..)`, slices are
//! lists `[..]`), except that GL enum arguments are written by name (`gl::NAMES`; a value with no
//! name as hex) and bitfields as `A | B`. Blank lines and `#` comments are ignored. Floats are
//! written in Rust's shortest round-trip form, so a write → read cycle gives back the same bits
//! (NaN aside, whose payload is not kept).
//!
//! Design decision: RON does the structural work through `Call`'s serde derive, so a variant added
//! to `Call` needs nothing here to be recorded and read back. This module only rewrites argument
//! tokens: on writing, integers in the positions the command table marks as enums become names; on
//! reading, every GL name (anywhere) becomes its number.
//!
//! Hostile input: a line longer than [`MAX_LINE_BYTES`] is a parse error before it is stored, so
//! memory stays proportional to the input and every vector is bounded by its line; RON's
//! recursion limit bounds nesting.

use std::collections::HashMap;
use std::io::{BufRead, BufReader, BufWriter, Read, Write};
use std::path::Path;

use crate::call::Call;
use crate::gl;
use crate::Error;

/// The longest line `read_recording` accepts, in bytes (a texture image of a few megabytes fits).
pub const MAX_LINE_BYTES: usize = 16 << 20;

use crate::call::ArgKind as Kind;

/// The kinds of the arguments of the call named `variant`, from the command table (the
/// registry's parameter types and enum groups); positions past the slice are `Plain`.
fn arg_kinds(variant: &str) -> &'static [Kind] {
    crate::call::arg_kinds(variant).unwrap_or(&[])
}

/// The buffer bits `Clear` takes, by name.
const CLEAR_BITS: [(&str, u32); 4] = [
    ("COLOR_BUFFER_BIT", gl::COLOR_BUFFER_BIT),
    ("DEPTH_BUFFER_BIT", gl::DEPTH_BUFFER_BIT),
    ("STENCIL_BUFFER_BIT", gl::STENCIL_BUFFER_BIT),
    ("ACCUM_BUFFER_BIT", gl::ACCUM_BUFFER_BIT),
];

/// The primitive modes in value order (GL 2.1 §2.6.1).
const PRIMS: [&str; 10] = [
    "POINTS",
    "LINES",
    "LINE_LOOP",
    "LINE_STRIP",
    "TRIANGLES",
    "TRIANGLE_STRIP",
    "TRIANGLE_FAN",
    "QUADS",
    "QUAD_STRIP",
    "POLYGON",
];

/// The first name `gl::NAMES` gives `value`, if any, bitfield names (`*_BIT`) aside: those
/// share values with enums (COLOR_BUFFER_BIT is LIGHT0's 0x4000).
fn enum_name(value: u32) -> Option<&'static str> {
    gl::NAMES
        .iter()
        .find(|&&(n, v)| v == value && !n.ends_with("_BIT"))
        .map(|&(n, _)| n)
}

/// Writes the integer token `tok` as `kind` says.
fn write_arg(out: &mut String, tok: &str, kind: Kind) {
    let Ok(value) = tok.parse::<u32>() else {
        out.push_str(tok);
        return;
    };
    match kind {
        Kind::Plain => out.push_str(tok),
        Kind::Prim => match PRIMS.get(value as usize) {
            Some(name) => out.push_str(name),
            None => out.push_str(&format!("{value:#x}")),
        },
        Kind::Blend | Kind::Enum => {
            let name = match value {
                0 if kind == Kind::Blend => Some("ZERO"),
                1 if kind == Kind::Blend => Some("ONE"),
                // 0 and 1 name a dozen unrelated things; hex says "a value" without guessing.
                0 | 1 => None,
                _ => enum_name(value),
            };
            match name {
                Some(name) => out.push_str(name),
                None => out.push_str(&format!("{value:#x}")),
            }
        }
        Kind::ClearBits => {
            let mut parts: Vec<String> = Vec::new();
            let mut rest = value;
            for (name, bit) in CLEAR_BITS {
                if rest & bit != 0 {
                    parts.push(name.to_string());
                    rest &= !bit;
                }
            }
            if rest != 0 || parts.is_empty() {
                parts.push(format!("{rest:#x}"));
            }
            out.push_str(&parts.join(" | "));
        }
    }
}

/// One lexical token of a line: punctuation, or a word (number, name, literal).
#[derive(Debug, PartialEq)]
enum Token<'a> {
    Punct(char),
    Word(&'a str),
}

/// Splits `line` into tokens; an error at a character the format never uses.
fn tokenize(line: &str) -> Result<Vec<Token<'_>>, String> {
    let mut tokens = Vec::new();
    let mut chars = line.char_indices().peekable();
    while let Some(&(i, c)) = chars.peek() {
        if c.is_whitespace() {
            chars.next();
        } else if matches!(c, '(' | ')' | '[' | ']' | ',' | '|') {
            tokens.push(Token::Punct(c));
            chars.next();
        } else if c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '-' | '+') {
            let mut end = i;
            while let Some(&(j, d)) = chars.peek() {
                if d.is_ascii_alphanumeric() || matches!(d, '_' | '.' | '-' | '+') {
                    end = j + d.len_utf8();
                    chars.next();
                } else {
                    break;
                }
            }
            tokens.push(Token::Word(line.get(i..end).unwrap_or("")));
        } else {
            return Err(format!("unexpected character {c:?}"));
        }
    }
    Ok(tokens)
}

/// One call as a line (without the newline).
fn format_call(call: &Call) -> Result<String, Error> {
    // Neither can fail for a `Call` (no maps, no strings); reported as I/O errors all the same.
    let invalid = |e: String| std::io::Error::new(std::io::ErrorKind::InvalidData, e);
    let ron = ron::to_string(call).map_err(|e| invalid(format!("{call:?}: {e}")))?;
    let tokens = tokenize(&ron).map_err(invalid)?;
    let variant = match tokens.first() {
        Some(Token::Word(w)) => *w,
        _ => "",
    };
    let kinds = arg_kinds(variant);
    let mut out = String::with_capacity(ron.len() + 16);
    let (mut depth, mut arg) = (0usize, 0usize);
    for tok in &tokens {
        match *tok {
            Token::Punct(c) => {
                out.push(c);
                match c {
                    '(' | '[' => depth += 1,
                    ')' | ']' => depth = depth.saturating_sub(1),
                    ',' => {
                        out.push(' ');
                        if depth == 1 {
                            arg += 1;
                        }
                    }
                    _ => {}
                }
            }
            Token::Word(w) if depth == 1 => {
                write_arg(&mut out, w, kinds.get(arg).copied().unwrap_or(Kind::Plain))
            }
            Token::Word(w) => out.push_str(w),
        }
    }
    Ok(out)
}

/// Writes `calls`, one per line, after a `#` header line.
pub fn write_recording(calls: &[Call], mut out: impl Write) -> Result<(), Error> {
    writeln!(out, "# fixedgl recording: one GL call per line")?;
    for call in calls {
        writeln!(out, "{}", format_call(call)?)?;
    }
    out.flush()?;
    Ok(())
}

/// Turns a line's tokens back into plain RON: GL names and `|`-joined bitfields become decimal
/// numbers, hex becomes decimal.
fn to_ron(tokens: &[Token<'_>], names: &HashMap<&str, u32>) -> Result<String, String> {
    let mut out = String::new();
    let mut pending_or: Option<u64> = None;
    let mut i = 0;
    while let Some(tok) = tokens.get(i) {
        i += 1;
        let word = match *tok {
            Token::Punct('|') => return Err("`|` without a value before it".into()),
            Token::Punct(c) => {
                out.push(c);
                continue;
            }
            Token::Word(w) => w,
        };
        let value: Option<u64> = if i == 1 {
            None // the variant name
        } else if let Some(hex) = word.strip_prefix("0x").or_else(|| word.strip_prefix("0X")) {
            Some(u64::from_str_radix(hex, 16).map_err(|_| format!("bad hex number `{word}`"))?)
        } else if let Some(&v) = names.get(word) {
            Some(u64::from(v))
        } else if word.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && !matches!(word, "true" | "false" | "NaN" | "inf")
            // The variants of a `Pointer` argument
            && !matches!(word, "Data" | "Offset")
            && !matches!(word, "true" | "false" | "NaN" | "inf" | "Some" | "None")
        {
            return Err(format!("unknown GL name `{word}`"));
        } else {
            None
        };
        let joined = matches!(tokens.get(i), Some(Token::Punct('|')));
        match (value, joined) {
            (Some(v), true) => {
                pending_or = Some(pending_or.unwrap_or(0) | v);
                i += 1; // the `|`
            }
            (Some(v), false) => out.push_str(&(pending_or.take().unwrap_or(0) | v).to_string()),
            (None, true) => return Err(format!("`{word}` cannot be part of a `|` bitfield")),
            (None, false) if pending_or.is_some() => {
                return Err(format!("`{word}` cannot be part of a `|` bitfield"))
            }
            (None, false) => out.push_str(word),
        }
    }
    if pending_or.is_some() {
        return Err("`|` without a value after it".into());
    }
    Ok(out)
}

/// Reads a recording: one call per line, blank lines and `#` comments ignored. A line that is
/// not a call (or longer than [`MAX_LINE_BYTES`], or not UTF-8) is `Error::Parse` with its
/// 1-based number.
pub fn read_recording(mut input: impl BufRead) -> Result<Vec<Call>, Error> {
    let names: HashMap<&str, u32> = gl::NAMES.iter().copied().collect();
    let mut calls = Vec::new();
    let mut buf = Vec::new();
    let mut line_no = 0usize;
    loop {
        buf.clear();
        line_no += 1;
        let limit = MAX_LINE_BYTES as u64 + 1;
        let n = input.by_ref().take(limit).read_until(b'\n', &mut buf)?;
        if n == 0 {
            return Ok(calls);
        }
        let parse_error = |message: String| Error::Parse {
            line: line_no,
            message,
        };
        if buf.len() > MAX_LINE_BYTES {
            return Err(parse_error(format!(
                "line longer than {MAX_LINE_BYTES} bytes"
            )));
        }
        let text = std::str::from_utf8(&buf).map_err(|e| parse_error(format!("not UTF-8: {e}")))?;
        let text = text.split('#').next().unwrap_or("").trim();
        if text.is_empty() {
            continue;
        }
        let tokens = tokenize(text).map_err(parse_error)?;
        let ron = to_ron(&tokens, &names).map_err(parse_error)?;
        let call = ron::from_str::<Call>(&ron).map_err(|e| parse_error(e.to_string()))?;
        calls.push(call);
    }
}

/// Writes `calls` to the file at `path` (created or truncated).
pub fn save(calls: &[Call], path: impl AsRef<Path>) -> Result<(), Error> {
    let file = std::fs::File::create(path)?;
    write_recording(calls, BufWriter::new(file))
}

/// Reads the recording in the file at `path`.
pub fn load(path: impl AsRef<Path>) -> Result<Vec<Call>, Error> {
    let file = std::fs::File::open(path)?;
    read_recording(BufReader::new(file))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enum_arguments_are_named() {
        let line = format_call(&Call::Lightfv(
            gl::LIGHT0,
            gl::POSITION,
            vec![1.0, 1.5, -0.5, 1.0],
        ));
        assert_eq!(
            line.ok().as_deref(),
            Some("Lightfv(LIGHT0, POSITION, [1.0, 1.5, -0.5, 1.0])")
        );
        let line = format_call(&Call::Begin(gl::POINTS));
        assert_eq!(line.ok().as_deref(), Some("Begin(POINTS)"));
        let line = format_call(&Call::Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT));
        assert_eq!(
            line.ok().as_deref(),
            Some("Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT)")
        );
        let line = format_call(&Call::TexCoord1sv([-5]));
        assert_eq!(line.ok().as_deref(), Some("TexCoord1sv((-5))"));
        let line = format_call(&Call::ShadeModel(0x1234_5678));
        assert_eq!(line.ok().as_deref(), Some("ShadeModel(0x12345678)"));
    }
}
