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
//! What reads: names `[A-Za-z_][A-Za-z0-9_]*` (calls, GL names anywhere a number goes, `true`,
//! `false`, `Some`, `None`, `Data`, `Offset`); numbers as RON reads them (an optional sign, then
//! decimal with optional fraction and exponent, `0x`/`0o`/`0b` integers, `_` after a digit,
//! `inf` and `NaN`; RON's `f32`/`f64` type suffixes are not read, nor `nan`, `Infinity`); `A | B`
//! of non-negative integers; `( ) [ ] ,` with an optional trailing comma; spaces and tabs
//! between tokens, and a `\r` before the line's end. Anything else in a line before its `#` is
//! an error: control and non-ASCII characters, strings, a run of number/name characters that is
//! neither (`1.0f`, `LIGHT0.5`), a token after the call.
//!
//! Design decision: writing goes through RON and `Call`'s serde derive, and reading through the
//! same derive with this module's own `serde::Deserializer`, so a variant added to `Call` needs
//! nothing here to be recorded and read back. On writing, integers in the positions the command
//! table marks as enums (`Call::arg_kinds`, from the registry's types and enum groups) become
//! names. Reading was RON after a token rewrite (names to
//! numbers), which dropped the whitespace between tokens (`0.5 5` read as `0.55`), reported
//! columns in the rewritten text and RON's messages (every variant name for an unknown call);
//! the direct deserializer reads the user's tokens where they stand, so every error has the
//! user's line and column, names the argument (`argument 2 of Vertex3f: expected f32, found a
//! string`) and is one short line (an unknown call gets the nearest name by edit distance, not
//! the list). It is driven by the types the derive asks for, so nesting is bounded by `Call`'s
//! types, not by the input.
//!
//! Hostile input: a line longer than [`MAX_LINE_BYTES`] is a parse error before it is stored, and
//! tokens are read one at a time, so memory stays proportional to the line and every vector is
//! bounded by it.

use std::collections::HashMap;
use std::io::{BufRead, BufReader, BufWriter, Read, Write};
use std::path::Path;

use crate::call::Call;
use crate::gl;
use crate::Error;

/// The longest line `read_recording` accepts, in bytes (a texture image of a few megabytes fits).
pub const MAX_LINE_BYTES: usize = 16 << 20;

use crate::call::ArgKind as Kind;

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

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Lex {
    /// One of `( ) [ ] , |`.
    Punct(u8),
    /// `[A-Za-z_][A-Za-z0-9_]*`: a call, GL name, `true`, `Some`, ...
    Name,
    /// A number as RON writes or reads it (see `is_number`).
    Num,
    /// `"..."`: never valid, but named as such in the message.
    Str,
    /// The end of the line (of its part before a `#`).
    End,
}

/// One token: its kind, its text in the line, and its 1-based column there.
#[derive(Clone, Copy, Debug)]
struct Token<'a> {
    lex: Lex,
    text: &'a str,
    col: usize,
}

impl Token<'_> {
    /// The token for a message: "`TEXT`" (shortened), "a string", "the end of the line".
    fn describe(&self) -> String {
        match self.lex {
            Lex::End => "the end of the line".into(),
            Lex::Str => "a string".into(),
            _ => format!("`{}`", short(self.text)),
        }
    }
}

/// `text` cut to a length a one-line message can hold.
fn short(text: &str) -> String {
    const MAX: usize = 40;
    match text.get(..MAX) {
        Some(head) if text.len() > MAX => format!("{head}..."),
        _ => text.to_owned(),
    }
}

/// A reading error: the 1-based column in the user's line and a one-line message. Column 0
/// (only from serde's own constructors) means "where the reader stopped", filled in later.
#[derive(Debug)]
struct ParseError {
    col: usize,
    msg: String,
}

impl std::fmt::Display for ParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.msg)
    }
}

impl std::error::Error for ParseError {}

impl serde::de::Error for ParseError {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        ParseError {
            col: 0,
            msg: msg.to_string(),
        }
    }
}

fn err<T>(col: usize, msg: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError {
        col,
        msg: msg.into(),
    })
}

/// Whether `w` is a number RON reads: an optional sign, then `inf`, `NaN`, `0x`/`0o`/`0b`
/// digits, or a decimal with optional fraction and exponent; `_` may follow any digit.
fn is_number(w: &str) -> bool {
    let body = w.strip_prefix(['+', '-']).unwrap_or(w);
    if matches!(body, "inf" | "NaN") {
        return true;
    }
    let digits = |s: &str, radix: u32| {
        !s.is_empty() && !s.starts_with('_') && s.chars().all(|c| c == '_' || c.is_digit(radix))
    };
    if let Some((radix, rest)) = radix_prefix(body) {
        return digits(rest, radix);
    }
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    if let Some(e) = exponent {
        if !digits(e.strip_prefix(['+', '-']).unwrap_or(e), 10) {
            return false;
        }
    }
    match mantissa.split_once('.') {
        None => digits(mantissa, 10),
        Some((int, frac)) => {
            (int.is_empty() || digits(int, 10))
                && (frac.is_empty() || digits(frac, 10))
                && !(int.is_empty() && frac.is_empty())
        }
    }
}

/// For an infinity or NaN spelled in a way RON does not read (`nan`, `-Infinity`), the message
/// that says how to spell it.
fn float_spelling(text: &str) -> Option<String> {
    let body = text
        .strip_prefix(['+', '-'])
        .unwrap_or(text)
        .to_ascii_lowercase();
    matches!(body.as_str(), "nan" | "inf" | "infinity").then(|| {
        format!(
            "`{}` is not a number here: write `NaN`, `inf` or `-inf`",
            short(text)
        )
    })
}

/// `0x`, `0o`, `0b` (either case): the radix and the digits after it.
fn radix_prefix(body: &str) -> Option<(u32, &str)> {
    let (p, rest) = (body.get(..2)?, body.get(2..)?);
    match p {
        "0x" | "0X" => Some((16, rest)),
        "0o" | "0O" => Some((8, rest)),
        "0b" | "0B" => Some((2, rest)),
        _ => None,
    }
}

/// Splits a line into tokens, one at a time, with each token's column in the line as written.
/// Whitespace (space, tab) separates tokens and never joins them: a run of word characters
/// (`[A-Za-z0-9_.+-]`) is one token and must be a whole name or a whole number.
struct Lexer<'a> {
    src: &'a str,
    pos: usize,
}

impl<'a> Lexer<'a> {
    fn new(src: &'a str) -> Self {
        Lexer { src, pos: 0 }
    }

    fn next_token(&mut self) -> Result<Token<'a>, ParseError> {
        let bytes = self.src.as_bytes();
        while matches!(bytes.get(self.pos), Some(b' ' | b'\t')) {
            self.pos += 1;
        }
        let start = self.pos;
        let col = start + 1;
        let token = |lex, end: usize| Token {
            lex,
            text: self.src.get(start..end).unwrap_or(""),
            col,
        };
        let Some(&b) = bytes.get(start) else {
            return Ok(token(Lex::End, start));
        };
        let word = |c: u8| c.is_ascii_alphanumeric() || matches!(c, b'_' | b'.' | b'+' | b'-');
        let tok = match b {
            b'(' | b')' | b'[' | b']' | b',' | b'|' => token(Lex::Punct(b), start + 1),
            b'"' => match bytes
                .get(start + 1..)
                .and_then(|r| r.iter().position(|&c| c == b'"'))
            {
                Some(len) => token(Lex::Str, start + len + 2),
                None => return err(col, "unterminated string"),
            },
            _ if word(b) => {
                let len = bytes
                    .get(start..)
                    .map_or(0, |r| r.iter().take_while(|&&c| word(c)).count());
                let tok = token(Lex::Name, start + len);
                let name = (b.is_ascii_alphabetic() || b == b'_')
                    && tok
                        .text
                        .bytes()
                        .all(|c| c.is_ascii_alphanumeric() || c == b'_');
                if name {
                    tok
                } else if is_number(tok.text) {
                    Token {
                        lex: Lex::Num,
                        ..tok
                    }
                } else if let Some(hint) = float_spelling(tok.text) {
                    return err(col, hint);
                } else if b.is_ascii_alphabetic() || b == b'_' {
                    return err(
                        col,
                        format!("`{}` is neither a name nor a number", short(tok.text)),
                    );
                } else {
                    return err(col, format!("malformed number `{}`", short(tok.text)));
                }
            }
            _ => {
                let c = self
                    .src
                    .get(start..)
                    .and_then(|r| r.chars().next())
                    .unwrap_or('?');
                return err(
                    col,
                    if c.is_ascii_control() {
                        format!("control character U+{:04X}", u32::from(c))
                    } else if !c.is_ascii() {
                        format!("non-ASCII character U+{:04X}", u32::from(c))
                    } else {
                        format!("unexpected character `{c}`")
                    },
                );
            }
        };
        self.pos = start + tok.text.len();
        Ok(tok)
    }
}

/// One call as a line (without the newline).
fn format_call(call: &Call) -> Result<String, Error> {
    // Neither can fail for a `Call` (no maps, no strings); reported as I/O errors all the same.
    let invalid = |e: String| std::io::Error::new(std::io::ErrorKind::InvalidData, e);
    let ron = ron::to_string(call).map_err(|e| invalid(format!("{call:?}: {e}")))?;
    let mut lexer = Lexer::new(&ron);
    let mut variant = None;
    let mut out = String::with_capacity(ron.len() + 16);
    let (mut depth, mut arg) = (0usize, 0usize);
    loop {
        let tok = lexer.next_token().map_err(|e| invalid(e.msg))?;
        let kinds = call.arg_kinds();
        match tok.lex {
            Lex::End => break,
            Lex::Punct(c) => {
                out.push(char::from(c));
                match c {
                    b'(' | b'[' => depth += 1,
                    b')' | b']' => depth = depth.saturating_sub(1),
                    b',' => {
                        out.push(' ');
                        if depth == 1 {
                            arg += 1;
                        }
                    }
                    _ => {}
                }
            }
            _ if variant.is_none() => {
                variant = Some(tok.text);
                out.push_str(tok.text);
            }
            _ if depth == 1 => write_arg(
                &mut out,
                tok.text,
                kinds.get(arg).copied().unwrap_or(Kind::Plain),
            ),
            _ => out.push_str(tok.text),
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

/// The candidate closest to `word` by edit distance (adjacent swaps count one, case is
/// ignored), if it is close enough to be a likely typo.
fn nearest<'n>(word: &str, candidates: impl IntoIterator<Item = &'n str>) -> Option<&'n str> {
    let word = word.to_ascii_lowercase();
    let limit = if word.len() <= 3 {
        1
    } else {
        2.max(word.len() / 4)
    };
    let mut best: Option<(usize, &str)> = None;
    for c in candidates {
        if c.len().abs_diff(word.len()) > limit {
            continue;
        }
        let d = edit_distance(word.as_bytes(), c.to_ascii_lowercase().as_bytes());
        if d <= limit && best.map_or(true, |(b, _)| d < b) {
            best = Some((d, c));
        }
    }
    best.map(|(_, c)| c)
}

/// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
/// adjacent bytes each cost one.
fn edit_distance(a: &[u8], b: &[u8]) -> usize {
    let mut rows = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in rows.iter_mut().enumerate() {
        if let Some(first) = row.first_mut() {
            *first = i;
        }
    }
    if let Some(row) = rows.first_mut() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = j;
        }
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut d = (rows[i - 1][j] + 1)
                .min(rows[i][j - 1] + 1)
                .min(rows[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(rows[i - 2][j - 2] + 1);
            }
            rows[i][j] = d;
        }
    }
    rows[a.len()][b.len()]
}

/// A decimal, hex, octal or binary integer literal's value; `None` for a float literal,
/// `Some(Err(()))` past the 128-bit range.
fn int_literal(text: &str) -> Option<Result<i128, ()>> {
    let (negative, body) = match text.strip_prefix('-') {
        Some(body) => (true, body),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    let (radix, digits) = radix_prefix(body).unwrap_or((10, body));
    if !digits
        .bytes()
        .all(|c| c == b'_' || char::from(c).is_digit(radix))
    {
        return None;
    }
    let digits: String = digits.chars().filter(|&c| c != '_').collect();
    let magnitude = u128::from_str_radix(&digits, radix)
        .ok()
        .and_then(|m| i128::try_from(m).ok());
    Some(magnitude.map(|m| if negative { -m } else { m }).ok_or(()))
}

/// The float types an argument can have.
trait Float: std::str::FromStr {
    fn from_int(v: i128) -> Self;
}

impl Float for f32 {
    fn from_int(v: i128) -> Self {
        v as f32
    }
}

impl Float for f64 {
    fn from_int(v: i128) -> Self {
        v as f64
    }
}

/// Reads one call from a line, driven by `Call`'s serde derive (so every variant, present and
/// future, is read with no table here): the derive asks for "an enum of these variants", "a
/// tuple of 3", "an f32", and the parser answers from the next tokens, or says what it found
/// instead, where, and in which argument.
struct Parser<'a, 'n> {
    lexer: Lexer<'a>,
    peeked: Option<Token<'a>>,
    /// The column of the last token taken, for serde's own errors (which have no position).
    last_col: usize,
    names: &'n HashMap<&'static str, u32>,
    /// The call's name once read (empty before).
    call: &'static str,
    /// Where the parser is: the argument (0-based), then element indices inside it.
    path: Vec<usize>,
    /// The brackets taken and not yet closed, innermost last.
    open: Vec<Token<'a>>,
}

impl<'a, 'n> Parser<'a, 'n> {
    fn new(src: &'a str, names: &'n HashMap<&'static str, u32>) -> Self {
        Parser {
            lexer: Lexer::new(src),
            peeked: None,
            last_col: 1,
            names,
            call: "",
            path: Vec::new(),
            open: Vec::new(),
        }
    }

    fn peek(&mut self) -> Result<Token<'a>, ParseError> {
        if let Some(t) = self.peeked {
            return Ok(t);
        }
        let t = self.lexer.next_token()?;
        self.peeked = Some(t);
        Ok(t)
    }

    fn bump(&mut self) -> Result<Token<'a>, ParseError> {
        let t = self.peek()?;
        self.peeked = None;
        self.last_col = t.col;
        match t.lex {
            Lex::Punct(b'(' | b'[') => self.open.push(t),
            Lex::Punct(b')' | b']') => {
                self.open.pop();
            }
            _ => {}
        }
        Ok(t)
    }

    /// Whether the next token is the punctuation `c`.
    fn at_punct(&mut self, c: u8) -> Result<bool, ParseError> {
        Ok(self.peek()?.lex == Lex::Punct(c))
    }

    /// "argument 2 of Lightfv, element 3: " for where the parser is; empty outside arguments.
    fn at(&self) -> String {
        let Some((arg, elements)) = self.path.split_first() else {
            return String::new();
        };
        let mut s = format!("argument {} of {}", arg + 1, self.call);
        for e in elements {
            s.push_str(&format!(", element {}", e + 1));
        }
        s.push_str(": ");
        s
    }

    /// `expected` was wanted and `t` came. The end of the line inside a bracket is reported
    /// at that bracket, as left open.
    fn unexpected<T>(&self, t: Token<'_>, expected: &str) -> Result<T, ParseError> {
        match self.open.last() {
            Some(open) if t.lex == Lex::End => err(
                open.col,
                format!(
                    "unclosed `{}`: the line ends before it is closed",
                    open.text
                ),
            ),
            _ => err(
                t.col,
                format!("{}expected {expected}, found {}", self.at(), t.describe()),
            ),
        }
    }

    /// Takes the punctuation `c`, or fails saying `expected` was wanted.
    fn expect(&mut self, c: u8, expected: &str) -> Result<(), ParseError> {
        let t = self.peek()?;
        if t.lex != Lex::Punct(c) {
            return self.unexpected(t, expected);
        }
        self.bump()?;
        Ok(())
    }

    /// After the last element of a fixed-length group: an optional trailing `,`, then `close`;
    /// anything else is one value too many (`too_many` says so).
    fn close(
        &mut self,
        close: u8,
        too_many: impl FnOnce(&Self) -> String,
    ) -> Result<(), ParseError> {
        let mut t = self.peek()?;
        let comma = t.lex == Lex::Punct(b',');
        if comma {
            self.bump()?;
            t = self.peek()?;
        }
        if t.lex == Lex::Punct(close) {
            self.bump()?;
            return Ok(());
        }
        if comma && !matches!(t.lex, Lex::End | Lex::Punct(_)) {
            return err(t.col, too_many(self));
        }
        self.unexpected(t, &format!("`{}`", char::from(close)))
    }

    /// A name that is not a GL name where a number of type `ty` was wanted.
    fn bad_name<T>(&self, t: Token<'_>, ty: &str) -> Result<T, ParseError> {
        if matches!(t.text, "true" | "false" | "Some" | "None" | "inf" | "NaN") {
            return self.unexpected(t, ty);
        }
        if let Some(hint) = float_spelling(t.text) {
            return err(t.col, format!("{}{hint}", self.at()));
        }
        let mut msg = format!("{}unknown GL name `{}`", self.at(), short(t.text));
        if let Some(n) = nearest(t.text, gl::NAMES.iter().map(|&(n, _)| n)) {
            msg.push_str(&format!("; did you mean `{n}`?"));
        }
        err(t.col, msg)
    }

    /// One integer: a literal or a GL name.
    fn int_atom(&mut self, ty: &str) -> Result<(i128, Token<'a>), ParseError> {
        let t = self.peek()?;
        let v = match t.lex {
            Lex::Num => match int_literal(t.text) {
                Some(Ok(v)) => v,
                Some(Err(())) => {
                    let at = self.at();
                    return err(
                        t.col,
                        format!("{at}{} is out of range for {ty}", t.describe()),
                    );
                }
                None => return self.unexpected(t, ty),
            },
            Lex::Name => match self.names.get(t.text) {
                Some(&v) => i128::from(v),
                None => return self.bad_name(t, ty),
            },
            _ => return self.unexpected(t, ty),
        };
        self.bump()?;
        Ok((v, t))
    }

    /// An integer, or non-negative integers joined by `|` (a bitfield).
    fn int_expr(&mut self, ty: &str) -> Result<i128, ParseError> {
        let (mut v, mut t) = self.int_atom(ty)?;
        if !self.at_punct(b'|')? {
            return Ok(v);
        }
        let mut bits = 0;
        loop {
            if !(0..=i128::from(u64::MAX)).contains(&v) {
                let at = self.at();
                return err(
                    t.col,
                    format!("{at}`|` joins non-negative integers, not {}", t.describe()),
                );
            }
            bits |= v;
            if !self.at_punct(b'|')? {
                return Ok(bits);
            }
            self.bump()?;
            let next = self.peek()?;
            if !matches!(next.lex, Lex::Num | Lex::Name) {
                return self.unexpected(next, "a value after `|`");
            }
            (v, t) = self.int_atom(ty)?;
        }
    }

    /// An integer of type `T` (named `ty` in messages).
    fn int<T: TryFrom<i128>>(&mut self, ty: &str) -> Result<T, ParseError> {
        let col = self.peek()?.col;
        let v = self.int_expr(ty)?;
        T::try_from(v).or_else(|_| err(col, format!("{}{v} is out of range for {ty}", self.at())))
    }

    /// A float: a float literal (read as `F` directly, so the writer's shortest form gives back
    /// the same bits), `inf`/`NaN` with an optional sign, or an integer as above.
    fn float<F: Float>(&mut self, ty: &str) -> Result<F, ParseError> {
        let t = self.peek()?;
        let body = t.text.strip_prefix(['+', '-']).unwrap_or(t.text);
        let literal = match t.lex {
            Lex::Name => matches!(t.text, "inf" | "NaN"),
            Lex::Num => radix_prefix(body).is_none(),
            _ => false,
        };
        if literal {
            self.bump()?;
            let text: String = t.text.chars().filter(|&c| c != '_').collect();
            return text
                .parse()
                .or_else(|_| err(t.col, format!("malformed number {}", t.describe())));
        }
        Ok(F::from_int(self.int_expr(ty)?))
    }

    /// `( value )` after a newtype variant's name: one argument.
    fn group_of_one<T>(
        &mut self,
        name: &'static str,
        top: bool,
        read: impl FnOnce(&mut Self) -> Result<T, ParseError>,
    ) -> Result<T, ParseError> {
        self.open_args(name)?;
        if self.at_punct(b')')? {
            let col = self.peek()?.col;
            return err(col, self.count_message(name, top, 1, 0));
        }
        if top {
            self.path.push(0);
        }
        let v = read(self)?;
        if top {
            self.path.pop();
        }
        self.close(b')', |p| p.too_many(name, top, 1))?;
        Ok(v)
    }

    /// The `(` after a variant's name.
    fn open_args(&mut self, name: &str) -> Result<(), ParseError> {
        self.expect(b'(', &format!("`(` after `{name}`"))
    }

    /// "`Vertex3f` takes 3 arguments, found 2".
    fn count_message(&self, name: &str, top: bool, len: usize, found: usize) -> String {
        let s = if len == 1 { "" } else { "s" };
        if top {
            format!("`{name}` takes {len} argument{s}, found {found}")
        } else {
            format!("{}`{name}` takes {len} value{s}, found {found}", self.at())
        }
    }

    /// "too many arguments: `Vertex3f` takes 3".
    fn too_many(&self, name: &str, top: bool, len: usize) -> String {
        if top {
            format!("too many arguments: `{name}` takes {len}")
        } else {
            format!("{}too many values: `{name}` takes {len}", self.at())
        }
    }
}

/// What a group of elements is, for its messages.
#[derive(Clone, Copy)]
enum Group {
    /// A call's arguments (`top`) or a nested variant's values.
    Args { name: &'static str, top: bool },
    /// A fixed-length tuple `( .. )`.
    Tuple,
    /// A list `[ .. ]`.
    List,
}

/// The elements of a group, handed to serde one at a time.
struct Elements<'p, 'a, 'n> {
    p: &'p mut Parser<'a, 'n>,
    group: Group,
    /// The exact count, for everything but lists.
    len: Option<usize>,
    count: usize,
}

impl Elements<'_, '_, '_> {
    fn too_few(&self, col: usize) -> ParseError {
        let (len, found) = (self.len.unwrap_or(0), self.count);
        let msg = match self.group {
            Group::Args { name, top } => self.p.count_message(name, top, len, found),
            _ => format!("{}expected {len} elements, found {found}", self.p.at()),
        };
        ParseError { col, msg }
    }
}

impl<'de> serde::de::SeqAccess<'de> for Elements<'_, '_, '_> {
    type Error = ParseError;

    fn next_element_seed<S: serde::de::DeserializeSeed<'de>>(
        &mut self,
        seed: S,
    ) -> Result<Option<S::Value>, ParseError> {
        if self.len == Some(self.count) {
            return Ok(None);
        }
        let close = if matches!(self.group, Group::List) {
            b']'
        } else {
            b')'
        };
        let mut t = self.p.peek()?;
        if self.count > 0 {
            if t.lex == Lex::Punct(b',') {
                self.p.bump()?;
                t = self.p.peek()?;
            } else if t.lex != Lex::Punct(close) {
                let expected = match self.group {
                    Group::Args { top: true, .. } => {
                        format!("`,` after argument {} of {}", self.count, self.p.call)
                    }
                    _ => format!("`,` or `{}`", char::from(close)),
                };
                return self.p.unexpected(t, &expected);
            }
        }
        if t.lex == Lex::Punct(close) {
            return match self.len {
                Some(_) => Err(self.too_few(t.col)),
                None => Ok(None),
            };
        }
        self.p.path.push(self.count);
        let v = seed.deserialize(&mut *self.p)?;
        self.p.path.pop();
        self.count += 1;
        Ok(Some(v))
    }
}

/// A variant, once its name is read.
struct Variant<'p, 'a, 'n> {
    p: &'p mut Parser<'a, 'n>,
    name: &'static str,
    /// The call itself (not an enum inside an argument).
    top: bool,
}

impl<'de> serde::de::EnumAccess<'de> for Variant<'_, '_, '_> {
    type Error = ParseError;
    type Variant = Self;

    fn variant_seed<S: serde::de::DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> Result<(S::Value, Self), ParseError> {
        let name = serde::de::IntoDeserializer::<ParseError>::into_deserializer(self.name);
        Ok((seed.deserialize(name)?, self))
    }
}

impl<'de> serde::de::VariantAccess<'de> for Variant<'_, '_, '_> {
    type Error = ParseError;

    fn unit_variant(self) -> Result<(), ParseError> {
        let t = self.p.peek()?;
        if t.lex == Lex::Punct(b'(') {
            let at = self.p.at();
            return err(t.col, format!("{at}`{}` takes no arguments", self.name));
        }
        Ok(())
    }

    fn newtype_variant_seed<S: serde::de::DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> Result<S::Value, ParseError> {
        self.p
            .group_of_one(self.name, self.top, |p| seed.deserialize(&mut *p))
    }

    fn tuple_variant<V: serde::de::Visitor<'de>>(
        self,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, ParseError> {
        let (name, top) = (self.name, self.top);
        self.p.open_args(name)?;
        let group = Group::Args { name, top };
        let v = visitor.visit_seq(Elements {
            p: &mut *self.p,
            group,
            len: Some(len),
            count: 0,
        })?;
        self.p.close(b')', |p| p.too_many(name, top, len))?;
        Ok(v)
    }

    fn struct_variant<V: serde::de::Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        _visitor: V,
    ) -> Result<V::Value, ParseError> {
        err(
            self.p.last_col,
            "struct variants are not part of the format",
        )
    }
}

/// "`Data` or `Offset`".
fn one_of(variants: &[&str]) -> String {
    let quoted: Vec<String> = variants.iter().map(|v| format!("`{v}`")).collect();
    match quoted.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => quoted.concat(),
    }
}

macro_rules! read_int {
    ($($method:ident $visit:ident $ty:ident),*) => {$(
        fn $method<V: serde::de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, ParseError> {
            let v: $ty = self.int(stringify!($ty))?;
            visitor.$visit(v)
        }
    )*};
}

impl<'de> serde::Deserializer<'de> for &mut Parser<'_, '_> {
    type Error = ParseError;

    fn deserialize_any<V: serde::de::Visitor<'de>>(self, _: V) -> Result<V::Value, ParseError> {
        let t = self.peek()?;
        err(
            t.col,
            format!("{}this value is not part of the format", self.at()),
        )
    }

    read_int!(
        deserialize_i8 visit_i8 i8, deserialize_i16 visit_i16 i16,
        deserialize_i32 visit_i32 i32, deserialize_i64 visit_i64 i64,
        deserialize_u8 visit_u8 u8, deserialize_u16 visit_u16 u16,
        deserialize_u32 visit_u32 u32, deserialize_u64 visit_u64 u64
    );

    fn deserialize_f32<V: serde::de::Visitor<'de>>(self, v: V) -> Result<V::Value, ParseError> {
        let x = self.float::<f32>("f32")?;
        v.visit_f32(x)
    }

    fn deserialize_f64<V: serde::de::Visitor<'de>>(self, v: V) -> Result<V::Value, ParseError> {
        let x = self.float::<f64>("f64")?;
        v.visit_f64(x)
    }

    fn deserialize_bool<V: serde::de::Visitor<'de>>(self, v: V) -> Result<V::Value, ParseError> {
        let t = self.peek()?;
        let b = match (t.lex, t.text) {
            (Lex::Name, "true") => true,
            (Lex::Name, "false") => false,
            _ => return self.unexpected(t, "`true` or `false`"),
        };
        self.bump()?;
        v.visit_bool(b)
    }

    fn deserialize_option<V: serde::de::Visitor<'de>>(self, v: V) -> Result<V::Value, ParseError> {
        let t = self.peek()?;
        match (t.lex, t.text) {
            (Lex::Name, "None") => {
                self.bump()?;
                v.visit_none()
            }
            (Lex::Name, "Some") => {
                self.bump()?;
                self.group_of_one("Some", false, |p| v.visit_some(p))
            }
            _ => self.unexpected(t, "`Some(..)` or `None`"),
        }
    }

    fn deserialize_seq<V: serde::de::Visitor<'de>>(self, v: V) -> Result<V::Value, ParseError> {
        self.expect(b'[', "a list `[..]`")?;
        let value = v.visit_seq(Elements {
            p: &mut *self,
            group: Group::List,
            len: None,
            count: 0,
        })?;
        self.expect(b']', "`]`")?;
        Ok(value)
    }

    fn deserialize_tuple<V: serde::de::Visitor<'de>>(
        self,
        len: usize,
        v: V,
    ) -> Result<V::Value, ParseError> {
        self.expect(b'(', &format!("a tuple `(..)` of {len}"))?;
        let value = v.visit_seq(Elements {
            p: &mut *self,
            group: Group::Tuple,
            len: Some(len),
            count: 0,
        })?;
        self.close(b')', |p| {
            format!("{}expected {len} elements, found more", p.at())
        })?;
        Ok(value)
    }

    fn deserialize_newtype_struct<V: serde::de::Visitor<'de>>(
        self,
        _name: &'static str,
        v: V,
    ) -> Result<V::Value, ParseError> {
        v.visit_newtype_struct(self)
    }

    fn deserialize_enum<V: serde::de::Visitor<'de>>(
        self,
        name: &'static str,
        variants: &'static [&'static str],
        v: V,
    ) -> Result<V::Value, ParseError> {
        let top = self.call.is_empty();
        let t = self.peek()?;
        if t.lex != Lex::Name {
            let expected = if top {
                "a call name".into()
            } else {
                one_of(variants)
            };
            return self.unexpected(t, &expected);
        }
        let Some(&variant) = variants.iter().find(|&&v| v == t.text) else {
            let what = if top { "call" } else { name };
            let mut msg = format!("{}unknown {what} `{}`", self.at(), short(t.text));
            if top {
                if let Some(n) = nearest(t.text, variants.iter().copied()) {
                    msg.push_str(&format!("; did you mean `{n}`?"));
                }
            } else {
                msg.push_str(&format!("; expected {}", one_of(variants)));
            }
            return err(t.col, msg);
        };
        self.bump()?;
        if top {
            self.call = variant;
        }
        v.visit_enum(Variant {
            p: self,
            name: variant,
            top,
        })
    }

    serde::forward_to_deserialize_any! {
        i128 u128 char str string bytes byte_buf unit unit_struct tuple_struct map struct
        identifier ignored_any
    }
}

/// One line's call; `None` for a line with nothing before its `#` comment.
fn parse_line(code: &str, names: &HashMap<&'static str, u32>) -> Result<Option<Call>, ParseError> {
    use serde::Deserialize;
    let mut p = Parser::new(code, names);
    if p.peek()?.lex == Lex::End {
        return Ok(None);
    }
    let call = match Call::deserialize(&mut p) {
        Ok(call) => call,
        Err(mut e) => {
            if e.col == 0 {
                e.col = p.last_col;
            }
            return Err(e);
        }
    };
    let t = p.peek()?;
    match t.lex {
        Lex::End => Ok(Some(call)),
        Lex::Punct(b')' | b']') => err(t.col, format!("unmatched `{}`", t.text)),
        _ => err(
            t.col,
            format!("unexpected {} after the end of the call", t.describe()),
        ),
    }
}

/// Reads a recording: one call per line, blank lines and `#` comments ignored. A line that is
/// not a call (or longer than [`MAX_LINE_BYTES`], or not UTF-8) is `Error::Parse` with its
/// 1-based line and column and a one-line message.
pub fn read_recording(mut input: impl BufRead) -> Result<Vec<Call>, Error> {
    let names: HashMap<&'static str, u32> = gl::NAMES.iter().copied().collect();
    let mut calls = Vec::new();
    let mut buf = Vec::new();
    let mut line = 0usize;
    loop {
        buf.clear();
        line += 1;
        let limit = MAX_LINE_BYTES as u64 + 1;
        let n = input.by_ref().take(limit).read_until(b'\n', &mut buf)?;
        if n == 0 {
            return Ok(calls);
        }
        let parse_error = |column: usize, message: String| Error::Parse {
            line,
            column,
            message,
        };
        if buf.last() == Some(&b'\n') {
            buf.pop();
            if buf.last() == Some(&b'\r') {
                buf.pop();
            }
        } else if buf.len() > MAX_LINE_BYTES {
            return Err(parse_error(
                MAX_LINE_BYTES + 1,
                format!("line longer than {MAX_LINE_BYTES} bytes"),
            ));
        }
        let text = std::str::from_utf8(&buf).map_err(|e| {
            let byte = buf.get(e.valid_up_to()).copied().unwrap_or(0);
            parse_error(
                e.valid_up_to() + 1,
                format!("not UTF-8 (byte 0x{byte:02x})"),
            )
        })?;
        let code = text.split('#').next().unwrap_or("");
        match parse_line(code, &names) {
            Ok(Some(call)) => calls.push(call),
            Ok(None) => {}
            Err(e) => return Err(parse_error(e.col, e.msg)),
        }
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

    #[test]
    fn numbers_are_whole_tokens() {
        for ok in [
            "1", "-1", "+1", "1.", ".5", "1.5e-3", "1E+3", "1_000", "0x1F", "0X1f", "-0b101",
            "0o17", "inf", "-inf", "+NaN", "-NaN",
        ] {
            assert!(is_number(ok), "{ok}");
        }
        for bad in [
            "", "-", ".", "1.0f", "1.0.0", "1e", "1e+", "0x", "0xG", "_1", "1-2", "nan", "-Inf",
            "1.0f32", "0b2",
        ] {
            assert!(!is_number(bad), "{bad}");
        }
    }

    #[test]
    fn suggestions_are_near_or_absent() {
        let names = ["Lightfv", "Lightf", "Begin", "Vertex3f", "End"];
        assert_eq!(nearest("Lightfvv", names), Some("Lightfv"));
        assert_eq!(nearest("Begni", names), Some("Begin"));
        assert_eq!(nearest("vertex3f", names), Some("Vertex3f"));
        assert_eq!(nearest("Xyzzyplugh", names), None);
        assert_eq!(edit_distance(b"abcd", b"acbd"), 1);
        assert_eq!(edit_distance(b"", b"abc"), 3);
    }
}
