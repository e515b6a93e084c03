//! A small RON (Rusty Object Notation) reader that keeps a byte span on every value.
//!
//! Why not the `ron` crate: its serde deserializer reports a position only for syntax
//! errors and exposes no span for a deserialized value, so semantic diagnostics ("unknown
//! pin `foo`" on line 40) could not point at their source. This reader produces a
//! [`Spanned<Value>`] tree instead; the loader turns that tree into document types and
//! uses the spans (through [`LineIndex`]) for its own messages.
//!
//! It is a single recursive-descent cursor over the source text. Nesting is limited to
//! 128 levels so hostile input yields a [`ParseError`] rather than a stack overflow.

use std::fmt;

/// Deepest allowed nesting of `(`, `[` and `{`.
const MAX_DEPTH: usize = 128;

/// Byte range [start, end) in the source text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Span {
    /// First byte of the range.
    pub start: usize,
    /// One past the last byte of the range.
    pub end: usize,
}

/// A value together with the span of source text it was read from.
#[derive(Clone, Debug, PartialEq)]
pub struct Spanned<T> {
    /// The value itself.
    pub value: T,
    /// Where the value appears in the source.
    pub span: Span,
}

/// One RON value; children carry their own spans.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `true` or `false`.
    Bool(bool),
    /// An integer literal (decimal, `0x`, `0b` or `0o`) that fits in an `i64`.
    Int(i64),
    /// A float literal, including `inf`, `-inf` and `NaN`.
    Float(f64),
    /// A string literal (escapes resolved) or a raw string.
    String(String),
    /// A character literal such as `'a'`.
    Char(char),
    /// `()`
    Unit,
    /// A bare identifier that is not `true`/`false` and is not followed by `(`: `None`, `Z`, `Float`.
    Ident(String),
    /// `[a, b, c]`
    List(Vec<Spanned<Value>>),
    /// `{ key: value, ... }` in source order; duplicate keys are kept (the caller reports them).
    Map(Vec<(Spanned<Value>, Spanned<Value>)>),
    /// `Name(a, b)` or `(a, b)`; name is None for an anonymous tuple. `Some(x)` is
    /// Tuple(Some("Some"), [x]). `Name()` is Tuple(Some("Name"), []).
    Tuple(Option<Spanned<String>>, Vec<Spanned<Value>>),
    /// `Name(field: v, ...)` or `(field: v, ...)` in source order; duplicate fields kept.
    Struct(
        Option<Spanned<String>>,
        Vec<(Spanned<String>, Spanned<Value>)>,
    ),
}

impl Value {
    /// Short description of the kind for error messages: "a float", "a list",
    /// "struct `Foo`", "identifier `Z`", ...
    pub fn describe(&self) -> String {
        match self {
            Value::Bool(b) => format!("the boolean `{b}`"),
            Value::Int(_) => "an integer".to_string(),
            Value::Float(_) => "a float".to_string(),
            Value::String(_) => "a string".to_string(),
            Value::Char(_) => "a character".to_string(),
            Value::Unit => "the unit value `()`".to_string(),
            Value::Ident(name) => format!("identifier `{name}`"),
            Value::List(_) => "a list".to_string(),
            Value::Map(_) => "a map".to_string(),
            Value::Tuple(Some(name), _) => format!("tuple `{}`", name.value),
            Value::Tuple(None, _) => "a tuple".to_string(),
            Value::Struct(Some(name), _) => format!("struct `{}`", name.value),
            Value::Struct(None, _) => "an unnamed struct".to_string(),
        }
    }
}

/// A syntax error: where and what, worded for a person editing the file by hand
/// (e.g. "expected `,` or `)` after the value, found `foo`", "unterminated string",
/// "unexpected end of file: `(` opened at 3:5 is never closed").
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// The offending text (empty at the end of the file).
    pub span: Span,
    /// What went wrong, as a sentence fragment without a trailing period.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ParseError {}

/// Maps byte offsets to 1-based line and column (column counted in chars, not bytes).
#[derive(Clone, Debug)]
pub struct LineIndex {
    text: String,
    line_starts: Vec<usize>,
}

impl LineIndex {
    /// Indexes the line starts of `src` (keeps a copy of the text to count chars).
    pub fn new(src: &str) -> Self {
        let line_starts = std::iter::once(0)
            .chain(src.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        LineIndex {
            text: src.to_string(),
            line_starts,
        }
    }

    /// 1-based (line, column) of a byte offset; offsets past the end map to the end.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let mut offset = offset.min(self.text.len());
        while offset > 0 && !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self
            .line_starts
            .partition_point(|&start| start <= offset)
            .max(1);
        let start = self.line_starts.get(line - 1).copied().unwrap_or(0);
        let column = self
            .text
            .get(start..offset)
            .map_or(0, |s| s.chars().count())
            + 1;
        (line, column)
    }
}

/// Parses one RON value (the whole document), allowing trailing whitespace/comments only.
pub fn parse(src: &str) -> Result<Spanned<Value>, ParseError> {
    let mut p = Parser {
        src,
        bytes: src.as_bytes(),
        pos: 0,
        open: Vec::new(),
    };
    if src.starts_with('\u{feff}') {
        p.pos = '\u{feff}'.len_utf8();
    }
    p.attributes()?;
    p.skip_ws()?;
    let value = p.value()?;
    p.skip_ws()?;
    if p.pos < p.bytes.len() {
        let (span, found) = p.found();
        let message = format!(
            "unexpected {found} after the end of the document (a RON file holds one value)"
        );
        return Err(ParseError { span, message });
    }
    Ok(value)
}

type PResult<T> = Result<T, ParseError>;

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

fn is_raw_ident_byte(b: u8) -> bool {
    is_ident_byte(b) || matches!(b, b'.' | b'+' | b'-')
}

fn spanned(value: Value, start: usize, end: usize) -> Spanned<Value> {
    Spanned {
        value,
        span: Span { start, end },
    }
}

/// Recursive-descent cursor. `pos` is always on a char boundary.
struct Parser<'a> {
    src: &'a str,
    bytes: &'a [u8],
    pos: usize,
    /// Open delimiters and their offsets, innermost last; its length is the nesting depth.
    open: Vec<(u8, usize)>,
}

impl<'a> Parser<'a> {
    // ----- low-level helpers -------------------------------------------------------------

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    fn peek_at(&self, n: usize) -> Option<u8> {
        self.bytes.get(self.pos + n).copied()
    }

    fn eat(&mut self, b: u8) -> bool {
        let hit = self.peek() == Some(b);
        if hit {
            self.pos += 1;
        }
        hit
    }

    fn next_char(&mut self) -> Option<char> {
        let c = self.src.get(self.pos..)?.chars().next()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    fn slice(&self, start: usize, end: usize) -> &'a str {
        self.src.get(start..end).unwrap_or("")
    }

    fn err(&self, start: usize, end: usize, message: impl Into<String>) -> ParseError {
        ParseError {
            span: Span { start, end },
            message: message.into(),
        }
    }

    fn position(&self, offset: usize) -> String {
        let (line, column) = LineIndex::new(self.src).line_col(offset);
        format!("{line}:{column}")
    }

    /// Describes the token at the cursor for "found ..." messages, with its span.
    fn found(&self) -> (Span, String) {
        let start = self.pos;
        let Some(c) = self.src.get(start..).and_then(|s| s.chars().next()) else {
            return (Span { start, end: start }, "end of file".to_string());
        };
        if c == '"' {
            return (
                Span {
                    start,
                    end: start + 1,
                },
                "a string".to_string(),
            );
        }
        if c.is_whitespace() {
            return (
                Span {
                    start,
                    end: start + c.len_utf8(),
                },
                "whitespace".to_string(),
            );
        }
        if c.is_ascii_alphanumeric() || c == '_' {
            let number = c.is_ascii_digit();
            let mut end = start;
            while self
                .bytes
                .get(end)
                .is_some_and(|&b| is_ident_byte(b) || (number && b == b'.'))
            {
                end += 1;
            }
            return (Span { start, end }, format!("`{}`", self.slice(start, end)));
        }
        (
            Span {
                start,
                end: start + c.len_utf8(),
            },
            format!("`{c}`"),
        )
    }

    /// "expected {what}, found {token}", or an end-of-file message naming the unclosed
    /// delimiter.
    fn expected(&self, what: &str) -> ParseError {
        let end = self.bytes.len();
        if self.pos < end {
            let (span, found) = self.found();
            return ParseError {
                span,
                message: format!("expected {what}, found {found}"),
            };
        }
        let message = match self.open.last() {
            Some(&(open, at)) => format!(
                "unexpected end of file: `{}` opened at {} is never closed",
                open as char,
                self.position(at)
            ),
            None => format!("unexpected end of file: expected {what}"),
        };
        self.err(end, end, message)
    }

    /// Consumes an opening delimiter, enforcing the nesting limit.
    fn enter(&mut self, open: u8) -> PResult<()> {
        if self.open.len() >= MAX_DEPTH {
            let message = format!("nesting is too deep (more than {MAX_DEPTH} levels of brackets)");
            return Err(self.err(self.pos, self.pos + 1, message));
        }
        self.open.push((open, self.pos));
        self.pos += 1;
        Ok(())
    }

    /// Skips whitespace, `//` line comments and nested `/* */` block comments.
    fn skip_ws(&mut self) -> PResult<()> {
        loop {
            match (self.peek(), self.peek_at(1)) {
                (Some(b' ' | b'\t' | b'\n' | b'\r'), _) => self.pos += 1,
                (Some(b'/'), Some(b'/')) => {
                    while self.peek().is_some_and(|b| b != b'\n') {
                        self.pos += 1;
                    }
                }
                (Some(b'/'), Some(b'*')) => self.block_comment()?,
                _ => return Ok(()),
            }
        }
    }

    fn block_comment(&mut self) -> PResult<()> {
        let start = self.pos;
        self.pos += 2;
        let mut depth = 1usize;
        while depth > 0 {
            match (self.peek(), self.peek_at(1)) {
                (None, _) => {
                    let message = "unterminated block comment: `/*` is never closed by `*/`";
                    return Err(self.err(start, start + 2, message));
                }
                (Some(b'/'), Some(b'*')) => {
                    depth += 1;
                    self.pos += 2;
                }
                (Some(b'*'), Some(b'/')) => {
                    depth -= 1;
                    self.pos += 2;
                }
                _ => self.pos += 1,
            }
        }
        Ok(())
    }

    /// Skips leading `#![enable(...)]` attributes.
    fn attributes(&mut self) -> PResult<()> {
        loop {
            self.skip_ws()?;
            if !self.eat(b'#') {
                return Ok(());
            }
            self.skip_ws()?;
            if !self.eat(b'!') {
                return Err(self.expected("`!` after `#` (attributes look like `#![enable(...)]`)"));
            }
            self.skip_ws()?;
            if self.peek() != Some(b'[') {
                return Err(self.expected("`[` after `#!`"));
            }
            self.enter(b'[')?;
            self.skip_ws()?;
            self.value()?;
            self.skip_ws()?;
            if !self.eat(b']') {
                return Err(self.expected("`]` to close the attribute"));
            }
            self.open.pop();
        }
    }

    // ----- values ------------------------------------------------------------------------

    /// Parses one value at the cursor (no leading whitespace).
    fn value(&mut self) -> PResult<Spanned<Value>> {
        let Some(b) = self.peek() else {
            return Err(self.expected("a value"));
        };
        match b {
            b'(' => self.parenthesised(None, self.pos),
            b'[' => self.list(),
            b'{' => self.map(),
            b'"' => self.string(),
            b'\'' => self.char_literal(),
            b'r' if matches!(self.peek_at(1), Some(b'"' | b'#')) => {
                let rest = self.bytes.get(self.pos + 1..).unwrap_or_default();
                let hashes = rest.iter().take_while(|&&b| b == b'#').count();
                if self.peek_at(1 + hashes) == Some(b'"') {
                    self.raw_string(hashes)
                } else if hashes == 1 && self.peek_at(2).is_some_and(is_raw_ident_byte) {
                    self.word()
                } else {
                    let message = "expected `\"` (raw string) or an identifier after `r#`";
                    Err(self.err(self.pos, self.pos + 1 + hashes, message))
                }
            }
            b'0'..=b'9' | b'+' | b'-' | b'.' => self.number(),
            b if is_ident_start(b) => self.word(),
            _ => Err(self.expected("a value")),
        }
    }

    /// Reads an identifier (`name` or `r#name`) if one is at the cursor.
    fn ident(&mut self) -> Option<Spanned<String>> {
        let start = self.pos;
        let raw = self.peek() == Some(b'r')
            && self.peek_at(1) == Some(b'#')
            && self.peek_at(2).is_some_and(is_raw_ident_byte);
        let body = if raw { start + 2 } else { start };
        if !raw && !self.peek().is_some_and(is_ident_start) {
            return None;
        }
        let allowed = if raw {
            is_raw_ident_byte
        } else {
            is_ident_byte
        };
        let mut end = body;
        while self.bytes.get(end).is_some_and(|&b| allowed(b)) {
            end += 1;
        }
        self.pos = end;
        Some(Spanned {
            value: self.slice(body, end).to_string(),
            span: Span { start, end },
        })
    }

    /// An identifier-led value: bool, `inf`/`NaN`, a bare identifier or `Name(...)`.
    fn word(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        let Some(name) = self.ident() else {
            return Err(self.expected("a value"));
        };
        let raw = name.span.end - name.span.start != name.value.len();
        let keyword = match name.value.as_str() {
            _ if raw => None,
            "true" => Some(Value::Bool(true)),
            "false" => Some(Value::Bool(false)),
            "inf" => Some(Value::Float(f64::INFINITY)),
            "NaN" => Some(Value::Float(f64::NAN)),
            _ => None,
        };
        if let Some(value) = keyword {
            return Ok(spanned(value, start, self.pos));
        }
        let after = self.pos;
        if self.skip_ws().is_ok() && self.peek() == Some(b'(') {
            return self.parenthesised(Some(name), start);
        }
        self.pos = after;
        Ok(Spanned {
            value: Value::Ident(name.value),
            span: name.span,
        })
    }

    /// `(...)` after an optional name: unit, tuple or struct. The cursor is on `(`.
    fn parenthesised(
        &mut self,
        name: Option<Spanned<String>>,
        start: usize,
    ) -> PResult<Spanned<Value>> {
        self.enter(b'(')?;
        self.skip_ws()?;
        let value = if self.eat(b')') {
            match name {
                None => Value::Unit,
                Some(name) => Value::Tuple(Some(name), Vec::new()),
            }
        } else if self.at_field() {
            Value::Struct(name, self.fields()?)
        } else {
            let mut items = Vec::new();
            loop {
                self.skip_ws()?;
                if self.eat(b')') {
                    break;
                }
                items.push(self.value()?);
                if !self.separator(b')', "the value")? {
                    break;
                }
            }
            Value::Tuple(name, items)
        };
        self.open.pop();
        Ok(spanned(value, start, self.pos))
    }

    /// Lookahead: does `ident :` start at the cursor?
    fn at_field(&mut self) -> bool {
        let save = self.pos;
        let field = self.ident().is_some() && self.skip_ws().is_ok() && self.peek() == Some(b':');
        self.pos = save;
        field
    }

    fn fields(&mut self) -> PResult<Vec<(Spanned<String>, Spanned<Value>)>> {
        let mut fields = Vec::new();
        loop {
            self.skip_ws()?;
            if self.eat(b')') {
                break;
            }
            let Some(name) = self.ident() else {
                return Err(self.expected("a field name (`name: value`) or `)`"));
            };
            self.skip_ws()?;
            if !self.eat(b':') {
                return Err(self.expected(&format!("`:` after the field name `{}`", name.value)));
            }
            self.skip_ws()?;
            let value = self.value()?;
            fields.push((name, value));
            if !self.separator(b')', "the field value")? {
                break;
            }
        }
        Ok(fields)
    }

    fn list(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        self.enter(b'[')?;
        let mut items = Vec::new();
        loop {
            self.skip_ws()?;
            if self.eat(b']') {
                break;
            }
            items.push(self.value()?);
            if !self.separator(b']', "the list element")? {
                break;
            }
        }
        self.open.pop();
        Ok(spanned(Value::List(items), start, self.pos))
    }

    fn map(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        self.enter(b'{')?;
        let mut entries = Vec::new();
        loop {
            self.skip_ws()?;
            if self.eat(b'}') {
                break;
            }
            let key = self.value()?;
            self.skip_ws()?;
            if !self.eat(b':') {
                return Err(self.expected("`:` after the map key"));
            }
            self.skip_ws()?;
            let value = self.value()?;
            entries.push((key, value));
            if !self.separator(b'}', "the map entry")? {
                break;
            }
        }
        self.open.pop();
        Ok(spanned(Value::Map(entries), start, self.pos))
    }

    /// After an item: `,` (more may follow → true) or the closing delimiter (→ false).
    fn separator(&mut self, close: u8, after: &str) -> PResult<bool> {
        self.skip_ws()?;
        if self.eat(b',') {
            return Ok(true);
        }
        if self.eat(close) {
            return Ok(false);
        }
        let mut err = self.expected(&format!("`,` or `{}` after {after}", close as char));
        match (self.peek(), self.open.last()) {
            (Some(b':'), _) if close == b')' => err.message.push_str(
                " (field names must be bare identifiers; use `{ key: value }` for a map)",
            ),
            (Some(b')' | b']' | b'}'), Some(&(open, at))) => {
                let note = format!(
                    " (`{}` opened at {} is still open)",
                    open as char,
                    self.position(at)
                );
                err.message.push_str(&note);
            }
            _ => {}
        }
        Err(err)
    }

    // ----- literals ----------------------------------------------------------------------

    fn number(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        let negative = self.peek() == Some(b'-');
        if matches!(self.peek(), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        let sign = self.slice(start, self.pos);
        for (word, v) in [("inf", f64::INFINITY), ("NaN", f64::NAN)] {
            let rest = self.slice(self.pos, self.bytes.len()).as_bytes();
            if rest.starts_with(word.as_bytes())
                && !rest.get(word.len()).is_some_and(|&b| is_ident_byte(b))
            {
                self.pos += word.len();
                return Ok(spanned(
                    Value::Float(if negative { -v } else { v }),
                    start,
                    self.pos,
                ));
            }
        }
        match (self.peek(), self.peek_at(1)) {
            (Some(b'0'..=b'9'), _) => {}
            (Some(b'.'), Some(b'0'..=b'9')) => {
                let fraction = self.pos;
                self.pos += 1;
                self.digits();
                self.exponent()?;
                let text = self.slice(start, self.pos);
                let fixed = format!("{sign}0{}", self.slice(fraction, self.pos));
                let message = format!(
                    "`{text}` is not a valid number: RON needs a digit before the decimal point, write `{fixed}`"
                );
                return Err(self.err(start, self.pos, message));
            }
            _ if sign.is_empty() => return Err(self.expected("a value")),
            _ => return Err(self.expected(&format!("a number after `{sign}`"))),
        }
        let radix = match (self.peek(), self.peek_at(1)) {
            (Some(b'0'), Some(b'x')) => Some((16, "hexadecimal")),
            (Some(b'0'), Some(b'b')) => Some((2, "binary")),
            (Some(b'0'), Some(b'o')) => Some((8, "octal")),
            _ => None,
        };
        if let Some((radix, name)) = radix {
            self.pos += 2;
            return self.radix_integer(start, negative, radix, name);
        }
        self.digits();
        let mut float = false;
        if self.peek() == Some(b'.') {
            float = true;
            self.pos += 1;
            if self.peek().is_some_and(|b| b.is_ascii_digit()) {
                self.digits();
            }
        }
        float |= self.exponent()?;
        if self.peek().is_some_and(|b| is_ident_byte(b) || b == b'.') {
            return Err(self.invalid_number(start));
        }
        let text: String = self
            .slice(start, self.pos)
            .chars()
            .filter(|&c| c != '_')
            .collect();
        let value = if float {
            match text.parse::<f64>() {
                Ok(f) => Value::Float(f),
                Err(_) => return Err(self.invalid_number(start)),
            }
        } else {
            match text.parse::<i64>() {
                Ok(i) => Value::Int(i),
                Err(_) => return Err(self.overflow(start)),
            }
        };
        Ok(spanned(value, start, self.pos))
    }

    /// Consumes digits and `_` separators.
    fn digits(&mut self) {
        while self.peek().is_some_and(|b| b.is_ascii_digit() || b == b'_') {
            self.pos += 1;
        }
    }

    /// Consumes an optional exponent; returns whether there was one.
    fn exponent(&mut self) -> PResult<bool> {
        if !matches!(self.peek(), Some(b'e' | b'E')) {
            return Ok(false);
        }
        let start = self.pos;
        self.pos += 1;
        if matches!(self.peek(), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        let digits_start = self.pos;
        self.digits();
        if !self
            .slice(digits_start, self.pos)
            .bytes()
            .any(|b| b.is_ascii_digit())
        {
            return Err(self.err(
                start,
                self.pos,
                "expected digits after the exponent `e` of the number",
            ));
        }
        Ok(true)
    }

    fn radix_integer(
        &mut self,
        start: usize,
        negative: bool,
        radix: u32,
        name: &str,
    ) -> PResult<Spanned<Value>> {
        let digits_start = self.pos;
        while self.peek().is_some_and(is_ident_byte) {
            self.pos += 1;
        }
        let raw = self.slice(digits_start, self.pos);
        if let Some((i, c)) = raw
            .char_indices()
            .find(|&(_, c)| c != '_' && !c.is_digit(radix))
        {
            let text = self.slice(start, self.pos);
            let message = format!("invalid digit `{c}` in {name} number `{text}`");
            return Err(self.err(digits_start + i, digits_start + i + 1, message));
        }
        let digits: String = raw.chars().filter(|&c| c != '_').collect();
        if digits.is_empty() {
            let prefix = self.slice(digits_start - 2, digits_start);
            return Err(self.err(
                start,
                self.pos,
                format!("expected {name} digits after `{prefix}`"),
            ));
        }
        if self.peek() == Some(b'.') {
            return Err(self.invalid_number(start));
        }
        let signed = format!("{}{digits}", if negative { "-" } else { "" });
        match i64::from_str_radix(&signed, radix) {
            Ok(i) => Ok(spanned(Value::Int(i), start, self.pos)),
            Err(_) => Err(self.overflow(start)),
        }
    }

    fn invalid_number(&mut self, start: usize) -> ParseError {
        while self.peek().is_some_and(|b| is_ident_byte(b) || b == b'.') {
            self.pos += 1;
        }
        self.err(
            start,
            self.pos,
            format!("invalid number `{}`", self.slice(start, self.pos)),
        )
    }

    fn overflow(&self, start: usize) -> ParseError {
        let message = format!(
            "integer `{}` does not fit in 64 bits (the range is {}..={})",
            self.slice(start, self.pos),
            i64::MIN,
            i64::MAX
        );
        self.err(start, self.pos, message)
    }

    fn string(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        self.pos += 1;
        let mut out = String::new();
        loop {
            let c = match self.next_char() {
                Some('"') => break,
                Some('\\') => self.escape()?,
                Some(c) => Some(c),
                None => None,
            };
            match c {
                Some(c) => out.push(c),
                None => {
                    let message = "unterminated string: this `\"` is never closed";
                    return Err(self.err(start, start + 1, message));
                }
            }
        }
        Ok(spanned(Value::String(out), start, self.pos))
    }

    /// Resolves an escape; the cursor is just past the backslash. `None` at end of file.
    fn escape(&mut self) -> PResult<Option<char>> {
        let start = self.pos - 1;
        let Some(c) = self.next_char() else {
            return Ok(None);
        };
        let resolved = match c {
            'n' => '\n',
            't' => '\t',
            'r' => '\r',
            '0' => '\0',
            'b' => '\u{8}',
            'f' => '\u{c}',
            '\\' | '"' | '\'' => c,
            'x' => {
                let hex = self
                    .slice(self.pos, (self.pos + 2).min(self.bytes.len()))
                    .to_string();
                self.pos += hex.len();
                match u8::from_str_radix(&hex, 16) {
                    Ok(b) if hex.len() == 2 && b.is_ascii() => char::from(b),
                    _ => {
                        let message = "invalid escape: `\\x` needs two hex digits up to `7F`";
                        return Err(self.err(start, self.pos, message));
                    }
                }
            }
            'u' => {
                let braced = self.eat(b'{');
                let digits_start = self.pos;
                let max = if braced { 6 } else { 4 };
                while self.pos - digits_start < max
                    && self.peek().is_some_and(|b| b.is_ascii_hexdigit())
                {
                    self.pos += 1;
                }
                let digits = self.slice(digits_start, self.pos);
                let well_formed = if braced {
                    self.eat(b'}') && !digits.is_empty()
                } else {
                    digits.len() == 4
                };
                let code = u32::from_str_radix(digits, 16)
                    .ok()
                    .and_then(char::from_u32);
                match code {
                    Some(c) if well_formed => c,
                    _ => {
                        let text = self.slice(start, self.pos);
                        let message = format!(
                            "invalid unicode escape `{text}`: write `\\u{{...}}` with 1 to 6 hex digits of a valid character"
                        );
                        return Err(self.err(start, self.pos, message));
                    }
                }
            }
            _ => {
                let message = format!(
                    "unknown escape `\\{c}` (valid escapes: \\n \\t \\r \\0 \\\\ \\\" \\' \\u{{...}})"
                );
                return Err(self.err(start, self.pos, message));
            }
        };
        Ok(Some(resolved))
    }

    fn raw_string(&mut self, hashes: usize) -> PResult<Spanned<Value>> {
        let start = self.pos;
        let body = start + hashes + 2;
        let mut search = body;
        loop {
            let Some(quote) = self
                .bytes
                .get(search..)
                .and_then(|s| s.iter().position(|&b| b == b'"'))
            else {
                let message = format!(
                    "unterminated raw string: expected `\"{}` to close it",
                    "#".repeat(hashes)
                );
                return Err(self.err(start, body, message));
            };
            let quote = search + quote;
            let end = quote + 1 + hashes;
            if self
                .bytes
                .get(quote + 1..end)
                .is_some_and(|s| s.iter().all(|&b| b == b'#'))
            {
                self.pos = end;
                let text = self.slice(body, quote).to_string();
                return Ok(spanned(Value::String(text), start, end));
            }
            search = quote + 1;
        }
    }

    fn char_literal(&mut self) -> PResult<Spanned<Value>> {
        let start = self.pos;
        self.pos += 1;
        let c = match self.next_char() {
            Some('\'') => return Err(self.err(start, self.pos, "empty character literal `''`")),
            Some('\\') => self.escape()?,
            c => c,
        };
        if let Some(c) = c {
            if self.eat(b'\'') {
                return Ok(spanned(Value::Char(c), start, self.pos));
            }
            let rest = self.slice(self.pos, self.bytes.len());
            if let Some(close) = rest.split('\n').next().and_then(|line| line.find('\'')) {
                let message = "a character literal holds exactly one character; use double quotes for a string";
                return Err(self.err(start, self.pos + close + 1, message));
            }
        }
        let message = "unterminated character literal: expected `'` after the character";
        Err(self.err(start, start + 1, message))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Compact rendering of a value tree (spans dropped) for readable assertions.
    fn show(v: &Value) -> String {
        let list = |items: &[Spanned<Value>]| {
            items
                .iter()
                .map(|i| show(&i.value))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let name =
            |n: &Option<Spanned<String>>| n.as_ref().map_or("", |n| n.value.as_str()).to_string();
        match v {
            Value::Bool(b) => b.to_string(),
            Value::Int(i) => i.to_string(),
            Value::Float(f) => format!("{f:?}"),
            Value::String(s) => format!("{s:?}"),
            Value::Char(c) => format!("{c:?}"),
            Value::Unit => "()".to_string(),
            Value::Ident(s) => s.clone(),
            Value::List(items) => format!("[{}]", list(items)),
            Value::Map(entries) => {
                let e: Vec<_> = entries
                    .iter()
                    .map(|(k, v)| format!("{}: {}", show(&k.value), show(&v.value)))
                    .collect();
                format!("{{{}}}", e.join(", "))
            }
            Value::Tuple(n, items) => format!("{}({})", name(n), list(items)),
            Value::Struct(n, fields) => {
                let f: Vec<_> = fields
                    .iter()
                    .map(|(k, v)| format!("{}: {}", k.value, show(&v.value)))
                    .collect();
                format!("{}({})", name(n), f.join(", "))
            }
        }
    }

    fn ok(src: &str) -> String {
        match parse(src) {
            Ok(v) => show(&v.value),
            Err(e) => panic!("{src:?} failed: {e:?}"),
        }
    }

    /// "line:col message" of the error for `src`.
    fn err(src: &str) -> String {
        match parse(src) {
            Ok(v) => panic!("{src:?} parsed as {}", show(&v.value)),
            Err(e) => {
                let (line, col) = LineIndex::new(src).line_col(e.span.start);
                format!("{line}:{col} {}", e.message)
            }
        }
    }

    const DOC: &str = r#"// comment
#![enable(implicit_some)]
Graph(
    version: 1,
    name: "pelvis_bob",
    /* block /* nested */ comment */
    variables: {
        "Time": (type: Float, default: 0.0),
        "Amplitude": (type: Float, default: 5.0, tunable: (min: 0.0, max: 20.0)),
        "Mask": (type: Int, default: 0x0F_F0),
    },
    nodes: {
        "pelvis": GetTransform(bone: bone("pelvis"), space: Global, initial: true),
        "wave": Sin(value: "phase"),
        "phase": Mul(a: "Time", b: 6.283_185),
        "offset": MakeVector(z: "wave"),
        "scaled": Scale(vector: "offset", by: 'x'),
        "v": (1.0, -2.0, 3.5e1),
        "moved": Add(a: "pelvis", b: "scaled", note: r"raw \ text"),
        "empty": Nothing(),
        "maybe": Some(None),
        "unit": (),
    },
    edges: [
        ("wave", "offset"),
        ("offset", "scaled"), // trailing comment
    ],
    events: { forward: [ Set("Time", "t"), SetTransform(bone: bone("pelvis"), value: "moved") ] },
    limits: { min: -inf, max: inf, bad: NaN, steps: [0b1010, 0o17, -42, +7] },
    label: "tab\tnewline\nquote\" unicode \u{1F600}",
)
"#;

    #[test]
    fn comments_attributes_and_scalars() {
        assert_eq!(
            ok("#![enable(implicit_some)] // c\n /* a /* b */ c */ 5 // end"),
            "5"
        );
        assert_eq!(ok("# ! [ enable(a, b,) ]\n#![enable(c)] true"), "true");
        assert_eq!(ok("\u{feff}false"), "false");
        assert_eq!(ok("None"), "None");
        assert_eq!(ok("r#type"), "type");
        assert_eq!(ok("r#true"), "true");
        assert_eq!(
            parse("r#true").map(|v| v.value),
            Ok(Value::Ident("true".into()))
        );
    }

    #[test]
    fn integers() {
        for (src, v) in [
            ("0", 0),
            ("+7", 7),
            ("-7", -7),
            ("1_000_000", 1_000_000),
            ("0xFF", 255),
            ("-0x10", -16),
            ("0b1010", 10),
            ("0o17", 15),
            ("0x7fff_ffff_ffff_ffff", i64::MAX),
            ("9223372036854775807", i64::MAX),
            ("-9223372036854775808", i64::MIN),
            ("-0x8000000000000000", i64::MIN),
        ] {
            assert_eq!(parse(src).map(|v| v.value), Ok(Value::Int(v)), "{src}");
        }
    }

    #[test]
    fn floats() {
        for (src, v) in [
            ("1.0", 1.0),
            ("-2.5e3", -2500.0),
            ("1e-3", 0.001),
            ("2E+2", 200.0),
            ("1.", 1.0),
            ("1_0.5_0", 10.5),
            ("inf", f64::INFINITY),
            ("-inf", f64::NEG_INFINITY),
            ("+inf", f64::INFINITY),
        ] {
            assert_eq!(parse(src).map(|v| v.value), Ok(Value::Float(v)), "{src}");
        }
        for src in ["NaN", "-NaN"] {
            assert!(matches!(parse(src).map(|v| v.value), Ok(Value::Float(f)) if f.is_nan()));
        }
    }

    #[test]
    fn strings_and_chars() {
        assert_eq!(
            ok(r#""a\n\t\\\"\'\0\u{1F600}\x41\u00e9""#),
            "\"a\\n\\t\\\\\\\"'\\0😀Aé\""
        );
        assert_eq!(ok("\"multi\nline é\""), "\"multi\\nline é\"");
        assert_eq!(ok(r#"r"C:\path""#), r#""C:\\path""#);
        assert_eq!(ok(r###"r##"a "# b"##"###), r##""a \"# b""##);
        assert_eq!(ok("r#\"\"#"), "\"\"");
        assert_eq!(ok("'a'"), "'a'");
        assert_eq!(ok(r"'\n'"), r"'\n'");
        assert_eq!(ok(r"'\''"), r"'\''");
        assert_eq!(ok("'é'"), "'é'");
    }

    #[test]
    fn compound_values() {
        assert_eq!(ok("()"), "()");
        assert_eq!(ok("( /* empty */ )"), "()");
        assert_eq!(
            parse("(1)").map(|v| v.value.describe()),
            Ok("a tuple".into())
        );
        assert_eq!(ok("(1, \"two\", 3.0,)"), "(1, \"two\", 3.0)");
        assert_eq!(ok("Some(None)"), "Some(None)");
        assert_eq!(ok("Some(x)"), "Some(x)");
        assert_eq!(ok("Name()"), "Name()");
        assert_eq!(ok("Foo /* c */ (1)"), "Foo(1)");
        assert_eq!(
            ok("Name(a: 1, b: (x: 2), r#type: Z,)"),
            "Name(a: 1, b: (x: 2), type: Z)"
        );
        assert_eq!(ok("(a: 1, a: 2)"), "(a: 1, a: 2)");
        assert_eq!(ok("(a /* c */ : 1)"), "(a: 1)");
        assert_eq!(ok("[]"), "[]");
        assert_eq!(ok("[1, [2, [3]], A,]"), "[1, [2, [3]], A]");
        assert_eq!(ok("{}"), "{}");
        assert_eq!(
            ok("{ a: 1, \"b\": B(2), (1, 2): [3], Some(k): x, a: 4, }"),
            "{a: 1, \"b\": B(2), (1, 2): [3], Some(k): x, a: 4}"
        );
        assert_eq!(ok("[x, (y)]"), "[x, (y)]");
    }

    #[test]
    fn describe() {
        let d = |src: &str| parse(src).map(|v| v.value.describe()).unwrap_or_default();
        assert_eq!(d("1.5"), "a float");
        assert_eq!(d("1"), "an integer");
        assert_eq!(d("[1]"), "a list");
        assert_eq!(d("{}"), "a map");
        assert_eq!(d("Z"), "identifier `Z`");
        assert_eq!(d("Foo(a: 1)"), "struct `Foo`");
        assert_eq!(d("(a: 1)"), "an unnamed struct");
        assert_eq!(d("Some(1)"), "tuple `Some`");
        assert_eq!(d("()"), "the unit value `()`");
        assert_eq!(d("true"), "the boolean `true`");
        assert_eq!(d("\"s\""), "a string");
        assert_eq!(d("'c'"), "a character");
    }

    #[test]
    fn spans_and_line_columns() {
        let src = "// head\nGraph(\n  nodes: {\n    \"é\": Sin(value: \"phase\"),\n  },\n)\n";
        let doc = parse(src).unwrap();
        let index = LineIndex::new(src);
        let at = |span: Span| (index.line_col(span.start), &src[span.start..span.end]);
        assert_eq!(at(doc.span).0, (2, 1));
        assert!(
            src[doc.span.start..doc.span.end].starts_with("Graph(")
                && src[..doc.span.end].ends_with(')')
        );
        let Value::Struct(Some(name), fields) = &doc.value else {
            panic!("{doc:?}")
        };
        assert_eq!(at(name.span), ((2, 1), "Graph"));
        let (field, map) = &fields[0];
        assert_eq!(at(field.span), ((3, 3), "nodes"));
        assert_eq!(index.line_col(map.span.start), (3, 10));
        let Value::Map(entries) = &map.value else {
            panic!("{map:?}")
        };
        let (key, node) = &entries[0];
        assert_eq!(at(key.span), ((4, 5), "\"é\""));
        // Column counts chars: `"é"` is 3 chars but 4 bytes, so `Sin` starts at column 10.
        assert_eq!(at(node.span), ((4, 10), "Sin(value: \"phase\")"));
        let Value::Struct(_, inner) = &node.value else {
            panic!("{node:?}")
        };
        assert_eq!(at(inner[0].1.span), ((4, 21), "\"phase\""));
    }

    #[test]
    fn line_index_edges() {
        let index = LineIndex::new("ab\né\n");
        assert_eq!(index.line_col(0), (1, 1));
        assert_eq!(index.line_col(2), (1, 3));
        assert_eq!(index.line_col(3), (2, 1));
        assert_eq!(index.line_col(4), (2, 1)); // inside `é`: snaps back to its start
        assert_eq!(index.line_col(5), (2, 2));
        assert_eq!(index.line_col(6), (3, 1));
        assert_eq!(index.line_col(999), (3, 1));
        assert_eq!(LineIndex::new("").line_col(5), (1, 1));
    }

    #[test]
    fn syntax_errors() {
        for (src, expected) in [
            ("", "1:1 unexpected end of file: expected a value"),
            (
                "  // only a comment\n",
                "2:1 unexpected end of file: expected a value",
            ),
            (
                "Graph(\n  a: 1,\n",
                "3:1 unexpected end of file: `(` opened at 1:6 is never closed",
            ),
            (
                "[1, {a: (",
                "1:10 unexpected end of file: `(` opened at 1:9 is never closed",
            ),
            (
                "(1 foo)",
                "1:4 expected `,` or `)` after the value, found `foo`",
            ),
            (
                "(a: 1\n b: 2)",
                "2:2 expected `,` or `)` after the field value, found `b`",
            ),
            (
                "[1 2]",
                "1:4 expected `,` or `]` after the list element, found `2`",
            ),
            (
                "{a: 1 b: 2}",
                "1:7 expected `,` or `}` after the map entry, found `b`",
            ),
            ("{ a 1 }", "1:5 expected `:` after the map key, found `1`"),
            (
                "(a: 1, 2)",
                "1:8 expected a field name (`name: value`) or `)`, found `2`",
            ),
            (
                "(a: 1, b)",
                "1:9 expected `:` after the field name `b`, found `)`",
            ),
            ("[1,,2]", "1:4 expected a value, found `,`"),
            ("@", "1:1 expected a value, found `@`"),
            (
                "1 2",
                "1:3 unexpected `2` after the end of the document (a RON file holds one value)",
            ),
            (
                "#[x] 1",
                "1:2 expected `!` after `#` (attributes look like `#![enable(...)]`), found `[`",
            ),
            (
                "\"abc",
                "1:1 unterminated string: this `\"` is never closed",
            ),
            (
                "[\"a\\",
                "1:2 unterminated string: this `\"` is never closed",
            ),
            (
                "r#\"abc\"",
                "1:1 unterminated raw string: expected `\"#` to close it",
            ),
            (
                "r#!",
                "1:1 expected `\"` (raw string) or an identifier after `r#`",
            ),
            (
                "1 /* x /* y */",
                "1:3 unterminated block comment: `/*` is never closed by `*/`",
            ),
            (
                "(x: .5)",
                "1:5 `.5` is not a valid number: RON needs a digit before the decimal point, write `0.5`",
            ),
            (
                "-.5e1",
                "1:1 `-.5e1` is not a valid number: RON needs a digit before the decimal point, write `-0.5e1`",
            ),
            (
                "\n9223372036854775808",
                "2:1 integer `9223372036854775808` does not fit in 64 bits \
                 (the range is -9223372036854775808..=9223372036854775807)",
            ),
            (
                "0x1_0000_0000_0000_0000",
                "1:1 integer `0x1_0000_0000_0000_0000` does not fit in 64 bits \
                 (the range is -9223372036854775808..=9223372036854775807)",
            ),
            ("0xFG", "1:4 invalid digit `G` in hexadecimal number `0xFG`"),
            ("0b102", "1:5 invalid digit `2` in binary number `0b102`"),
            ("[0x]", "1:2 expected hexadecimal digits after `0x`"),
            ("12ab", "1:1 invalid number `12ab`"),
            ("1.5.2", "1:1 invalid number `1.5.2`"),
            (
                "1e",
                "1:2 expected digits after the exponent `e` of the number",
            ),
            ("- 1", "1:2 expected a number after `-`, found whitespace"),
            (
                "\"a\\qb\"",
                "1:3 unknown escape `\\q` (valid escapes: \\n \\t \\r \\0 \\\\ \\\" \\' \\u{...})",
            ),
            (
                "\"\\u{110000}\"",
                "1:2 invalid unicode escape `\\u{110000}`: write `\\u{...}` with 1 to 6 hex digits \
                 of a valid character",
            ),
            (
                "\"\\x80\"",
                "1:2 invalid escape: `\\x` needs two hex digits up to `7F`",
            ),
            (
                "'ab'",
                "1:1 a character literal holds exactly one character; use double quotes for a string",
            ),
            ("''", "1:1 empty character literal `''`"),
            (
                "'a",
                "1:1 unterminated character literal: expected `'` after the character",
            ),
            (
                "(\"a\": 1)",
                "1:5 expected `,` or `)` after the value, found `:` \
                 (field names must be bare identifiers; use `{ key: value }` for a map)",
            ),
            (
                "(1, 2]",
                "1:6 expected `,` or `)` after the value, found `]` (`(` opened at 1:1 is still open)",
            ),
        ] {
            assert_eq!(err(src), expected, "source: {src:?}");
        }
    }

    #[test]
    fn nesting_limit() {
        let nested = |n: usize| format!("{}{}", "[".repeat(n), "]".repeat(n));
        assert!(parse(&nested(MAX_DEPTH)).is_ok());
        assert_eq!(
            err(&nested(MAX_DEPTH + 1)),
            "1:129 nesting is too deep (more than 128 levels of brackets)"
        );
        assert!(parse(&"[(Some({a:".repeat(50_000)).is_err());
        assert!(parse(&"(".repeat(1_000_000)).is_err());
    }

    /// Every span is in bounds, on char boundaries, and children lie inside their parent.
    fn check_spans(src: &str, v: &Spanned<Value>) {
        let Span { start, end } = v.span;
        assert!(
            start <= end && src.get(start..end).is_some(),
            "bad span {:?}",
            v.span
        );
        let inside = |s: Span| {
            assert!(
                start <= s.start && s.end <= end,
                "{s:?} outside {:?}",
                v.span
            )
        };
        let mut children: Vec<&Spanned<Value>> = Vec::new();
        match &v.value {
            Value::List(items) | Value::Tuple(_, items) => children.extend(items),
            Value::Map(entries) => entries.iter().for_each(|(k, v)| children.extend([k, v])),
            Value::Struct(_, fields) => {
                for (name, value) in fields {
                    inside(name.span);
                    children.push(value);
                }
            }
            _ => {}
        }
        if let Value::Tuple(Some(name), _) | Value::Struct(Some(name), _) = &v.value {
            assert_eq!(name.span.start, start);
        }
        for child in children {
            inside(child.span);
            check_spans(src, child);
        }
    }

    #[test]
    fn realistic_document_and_all_prefixes() {
        let doc = parse(DOC).unwrap();
        check_spans(DOC, &doc);
        let Value::Struct(Some(name), fields) = &doc.value else {
            panic!("{doc:?}")
        };
        assert_eq!(name.value, "Graph");
        let names: Vec<_> = fields.iter().map(|(k, _)| k.value.as_str()).collect();
        assert_eq!(
            names,
            [
                "version",
                "name",
                "variables",
                "nodes",
                "edges",
                "events",
                "limits",
                "label"
            ]
        );
        assert!(ok(DOC).contains("\"pelvis\": GetTransform(bone: bone(\"pelvis\"), space: Global"));
        assert!(ok(DOC).contains("\"v\": (1.0, -2.0, 35.0)"));
        for end in (0..DOC.len()).filter(|&i| DOC.is_char_boundary(i)) {
            if let Ok(v) = parse(&DOC[..end]) {
                check_spans(&DOC[..end], &v);
            }
        }
    }

    #[test]
    fn random_input_never_panics() {
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let chars: Vec<char> = "()[]{},:\"'#!r/*\\ \n_-+.0123456789eExbouAZaé{}"
            .chars()
            .collect();
        let tokens = [
            "(",
            ")",
            "[",
            "]",
            "{",
            "}",
            ",",
            ": ",
            "\"s\"",
            "'c'",
            "1",
            "-2.5e3",
            "0x1F",
            "Foo",
            "a",
            "r#\"x\"#",
            "// c\n",
            "/*",
            "*/",
            " ",
            "\n",
            "true",
            "None",
            "\\",
            "\"",
            "é",
            "inf",
            ".5",
            "#![enable(x)]",
            "r#",
            "99999999999999999999",
            "\"\\u{",
            "'",
        ];
        for round in 0..6000 {
            let len = (next() % 48) as usize;
            let src: String = if round % 2 == 0 {
                (0..len)
                    .map(|_| chars[(next() % chars.len() as u64) as usize])
                    .collect()
            } else {
                (0..len)
                    .map(|_| tokens[(next() % tokens.len() as u64) as usize])
                    .collect()
            };
            match parse(&src) {
                Ok(v) => check_spans(&src, &v),
                Err(e) => assert!(
                    e.span.start <= e.span.end && e.span.end <= src.len(),
                    "{src:?}: {e:?}"
                ),
            }
        }
    }
}
