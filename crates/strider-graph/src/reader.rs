//! A small RON (Rusty Object Notation) reader that keeps a byte span on every value.
//!
//! Why not the `ron` crate: its serde deserializer reports a position only for syntax
//! errors and exposes no span for a deserialized value, so semantic diagnostics ("unknown
//! pin `foo`" on line 40) could not point at their source. This reader produces a
//! [`Spanned<Value>`] tree instead; the loader turns that tree into document types and
//! uses the spans (through [`LineIndex`]) for its own messages.
//!
//! The tree borrows from the source text: identifiers, field names and strings without
//! escapes are slices of it. Its lists (and the strings with escapes) live in an arena
//! ([`Bump`]) the caller passes in: each list is one bump of a pointer, and the whole tree is
//! freed at once with the arena, however many lists it has. The tree is `Copy` and has
//! nothing to drop.
//!
//! It is a single recursive-descent cursor over the source text. Nesting is limited to
//! 128 levels so hostile input yields a [`ParseError`] rather than a stack overflow.

/// The arena [`parse`] allocates a document's lists in (re-exported for its callers).
pub use bumpalo::Bump;
use std::borrow::Cow;
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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spanned<T> {
    /// The value itself.
    pub value: T,
    /// Where the value appears in the source.
    pub span: Span,
}

/// One RON value, borrowing its names and strings from the source text and its lists from
/// the arena given to [`parse`] (both live for `'a`); children carry their own spans.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value<'a> {
    /// `true` or `false`.
    Bool(bool),
    /// An integer literal (decimal, `0x`, `0b` or `0o`) that fits in an `i64`.
    Int(i64),
    /// A float literal, including `inf`, `-inf` and `NaN`.
    Float(f64),
    /// A string literal or a raw string: borrowed from the source, or in the arena when an
    /// escape was resolved.
    String(&'a str),
    /// A character literal such as `'a'`.
    Char(char),
    /// `()`
    Unit,
    /// A bare identifier that is not `true`/`false` and is not followed by `(`:
    /// `None`, `Z`, `Float`.
    Ident(&'a str),
    /// `[a, b, c]`
    List(&'a [Spanned<Value<'a>>]),
    /// `{ key: value, ... }` in source order; duplicate keys are kept (the caller reports them).
    Map(&'a [Entry<'a>]),
    /// `Name(a, b)` or `(a, b)`; name is None for an anonymous tuple. `Some(x)` is
    /// `Tuple(Some("Some"), [x])`. `Name()` is `Tuple(Some("Name"), [])`.
    Tuple(Option<Spanned<&'a str>>, &'a [Spanned<Value<'a>>]),
    /// `Name(field: v, ...)` or `(field: v, ...)` in source order; duplicate fields kept.
    Struct(Option<Spanned<&'a str>>, &'a [Field<'a>]),
}

impl Value<'_> {
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
    /// Whether the text is all ASCII: then a column is a byte count (graphs are mostly
    /// ASCII, and the compiler asks for the line and column of every node it emits).
    ascii: bool,
}

impl LineIndex {
    /// Indexes the line starts of `src` (keeps a copy of the text to count chars).
    pub fn new(src: &str) -> Self {
        Self::of(src.to_string())
    }

    /// Indexes the line starts of `text`, which it keeps to count chars.
    pub fn of(text: String) -> Self {
        let line_starts = std::iter::once(0)
            .chain(memchr::memchr_iter(b'\n', text.as_bytes()).map(|i| i + 1))
            .collect();
        let ascii = text.is_ascii();
        LineIndex {
            text,
            line_starts,
            ascii,
        }
    }

    /// The text indexed.
    #[must_use]
    pub fn text(&self) -> &str {
        &self.text
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
        let column = if self.ascii {
            offset.saturating_sub(start)
        } else {
            // A comment elsewhere may hold the text's only non-ASCII chars: most lines are
            // ASCII up to the offset, and then the column is a byte count again.
            let before = self.text.get(start..offset).unwrap_or_default();
            if before.is_ascii() {
                before.len()
            } else {
                before.chars().count()
            }
        } + 1;
        (line, column)
    }
}

/// Parses one RON value (the whole document), allowing trailing whitespace/comments only.
/// The value's lists, and its strings with escapes, are allocated in `arena`: a document's
/// thousands of lists cost a bump of a pointer each and are freed all at once with it.
pub fn parse<'a>(src: &'a str, arena: &'a Bump) -> Result<Spanned<Value<'a>>, ParseError> {
    let pos = if src.starts_with('\u{feff}') { 3 } else { 0 };
    let mut p = Parser {
        arena,
        src,
        bytes: src.as_bytes(),
        pos,
        open: Vec::new(),
        values: Vec::new(),
        fields: Vec::new(),
        entries: Vec::new(),
    };
    p.attributes()?;
    let value = p.value()?;
    p.skip_ws()?;
    if p.pos < p.bytes.len() {
        let (span, found) = p.found();
        let message = format!("unexpected {found} after the end of the document");
        return Err(ParseError {
            span,
            message: message + " (a RON file holds one value)",
        });
    }
    Ok(value)
}

type PResult<T> = Result<T, ParseError>;

fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r')
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

fn is_raw_ident_byte(b: u8) -> bool {
    is_ident_byte(b) || matches!(b, b'.' | b'+' | b'-')
}

fn sp(start: usize, end: usize) -> Span {
    Span { start, end }
}

fn spanned<T>(value: T, start: usize, end: usize) -> Spanned<T> {
    Spanned {
        value,
        span: sp(start, end),
    }
}

/// Recursive-descent cursor over the source; `pos` always sits on a char boundary.
struct Parser<'a> {
    /// Where the lists and the strings with escapes go.
    arena: &'a Bump,
    src: &'a str,
    bytes: &'a [u8],
    pos: usize,
    /// Open delimiters and their offsets, innermost last; its length is the nesting depth.
    open: Vec<(u8, usize)>,
    /// The items of the lists and tuples being read, innermost last (see
    /// [`Parser::sequence`]).
    values: Vec<Spanned<Value<'a>>>,
    /// The fields of the structs being read, innermost last.
    fields: Vec<Field<'a>>,
    /// The entries of the maps being read, innermost last.
    entries: Vec<Entry<'a>>,
}

/// A struct's field: its name and value.
pub type Field<'a> = (Spanned<&'a str>, Spanned<Value<'a>>);
/// A map's entry: its key and value.
pub type Entry<'a> = (Spanned<Value<'a>>, Spanned<Value<'a>>);

impl<'a> Parser<'a> {
    // ----- cursor helpers and diagnostics -------------------------------------------------

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    fn peek_at(&self, n: usize) -> Option<u8> {
        self.bytes.get(self.pos + n).copied()
    }

    fn eat(&mut self, b: u8) -> bool {
        let hit = self.peek() == Some(b);
        self.pos += usize::from(hit);
        hit
    }

    fn eat_while(&mut self, pred: impl Fn(u8) -> bool) {
        while self.peek().is_some_and(&pred) {
            self.pos += 1;
        }
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
            span: sp(start, end),
            message: message.into(),
        }
    }

    /// "line:column" of an offset, for messages that mention another place.
    fn position(&self, offset: usize) -> String {
        let (line, column) = LineIndex::new(self.src).line_col(offset);
        format!("{line}:{column}")
    }

    /// Describes the token at the cursor for "found ..." messages, with its span.
    fn found(&self) -> (Span, String) {
        let start = self.pos;
        let Some(c) = self.src.get(start..).and_then(|s| s.chars().next()) else {
            return (sp(start, start), "end of file".to_string());
        };
        let mut end = start + c.len_utf8();
        let text = match c {
            '"' => "a string".to_string(),
            c if c.is_whitespace() => "whitespace".to_string(),
            c if c.is_ascii_alphanumeric() || c == '_' => {
                let number = c.is_ascii_digit();
                let more = |b: &u8| is_ident_byte(*b) || (number && *b == b'.');
                end = start + self.bytes[start..].iter().take_while(|b| more(b)).count();
                format!("`{}`", self.slice(start, end))
            }
            c => format!("`{c}`"),
        };
        (sp(start, end), text)
    }

    /// "expected {what}, found {token}", or at the end of the file a message naming the
    /// innermost delimiter that is still open.
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
    #[inline]
    fn skip_ws(&mut self) -> PResult<()> {
        // Most calls find a token at the cursor at once.
        match self.peek() {
            Some(b) if is_space(b) || b == b'/' => self.skip_ws_run(),
            _ => Ok(()),
        }
    }

    fn skip_ws_run(&mut self) -> PResult<()> {
        loop {
            let rest = &self.bytes[self.pos..];
            match rest {
                [b, ..] if is_space(*b) => {
                    self.pos += rest
                        .iter()
                        .position(|&b| !is_space(b))
                        .unwrap_or(rest.len());
                }
                [b'/', b'/', ..] => self.pos += memchr::memchr(b'\n', rest).unwrap_or(rest.len()),
                [b'/', b'*', ..] => self.block_comment()?,
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
                (Some(b'/'), Some(b'*')) => (depth, self.pos) = (depth + 1, self.pos + 2),
                (Some(b'*'), Some(b'/')) => (depth, self.pos) = (depth - 1, self.pos + 2),
                _ => self.pos += 1,
            }
        }
        Ok(())
    }

    /// Skips leading `#![enable(...)]` attributes and the whitespace around them.
    fn attributes(&mut self) -> PResult<()> {
        loop {
            self.skip_ws()?;
            if !self.eat(b'#') {
                return Ok(());
            }
            self.skip_ws()?;
            if !self.eat(b'!') {
                return Err(self.expected("`!` after `#` (write `#![enable(..)]`)"));
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

    /// Parses one value at the cursor (leading whitespace already skipped).
    fn value(&mut self) -> PResult<Spanned<Value<'a>>> {
        let start = self.pos;
        match self.peek() {
            Some(b'(') => self.parenthesised(None, start),
            Some(b'[') => {
                self.enter(b'[')?;
                let items =
                    self.sequence(b']', "the list element", |p| &mut p.values, Self::value)?;
                Ok(spanned(Value::List(items), start, self.pos))
            }
            Some(b'{') => {
                self.enter(b'{')?;
                let entries =
                    self.sequence(b'}', "the map entry", |p| &mut p.entries, Self::map_entry)?;
                Ok(spanned(Value::Map(entries), start, self.pos))
            }
            Some(b'"') => self.string(),
            Some(b'\'') => self.char_literal(),
            Some(b'r') if matches!(self.peek_at(1), Some(b'"' | b'#')) => {
                let hashes = self.bytes[start + 1..]
                    .iter()
                    .take_while(|&&b| b == b'#')
                    .count();
                if self.peek_at(1 + hashes) == Some(b'"') {
                    self.raw_string(hashes)
                } else if hashes == 1 && self.peek_at(2).is_some_and(is_raw_ident_byte) {
                    self.word()
                } else {
                    let message = "expected `\"` (raw string) or an identifier after `r#`";
                    Err(self.err(start, start + 1 + hashes, message))
                }
            }
            Some(b'0'..=b'9' | b'+' | b'-' | b'.') => self.number(),
            Some(b) if is_ident_start(b) => self.word(),
            _ => Err(self.expected("a value")),
        }
    }

    /// Comma-separated items up to `close` (trailing comma allowed). The opening delimiter
    /// has been consumed by [`Parser::enter`]; this consumes the closing one. The items of
    /// every open sequence wait on one stack of their type (`stack`), and each sequence
    /// ends copied into the arena at its exact length.
    fn sequence<T: Copy>(
        &mut self,
        close: u8,
        after: &str,
        stack: fn(&mut Self) -> &mut Vec<T>,
        item: impl FnMut(&mut Self) -> PResult<T>,
    ) -> PResult<&'a [T]> {
        let base = stack(self).len();
        let read = self.sequence_items(close, after, stack, item);
        let arena = self.arena;
        let items = stack(self);
        let slice = read.map(|()| &*arena.alloc_slice_copy(&items[base..]));
        items.truncate(base);
        if slice.is_ok() {
            self.open.pop();
        }
        slice
    }

    /// [`Parser::sequence`]'s loop: pushes the items on `stack`.
    fn sequence_items<T>(
        &mut self,
        close: u8,
        after: &str,
        stack: fn(&mut Self) -> &mut Vec<T>,
        mut item: impl FnMut(&mut Self) -> PResult<T>,
    ) -> PResult<()> {
        loop {
            self.skip_ws()?;
            if self.eat(close) {
                return Ok(());
            }
            let x = item(self)?;
            stack(self).push(x);
            self.skip_ws()?;
            if self.eat(b',') {
                continue;
            }
            if self.eat(close) {
                return Ok(());
            }
            return Err(self.separator_error(close, after));
        }
    }

    fn separator_error(&self, close: u8, after: &str) -> ParseError {
        let mut err = self.expected(&format!("`,` or `{}` after {after}", close as char));
        match (self.peek(), self.open.last()) {
            (Some(b':'), _) if close == b')' => {
                err.message += " (field names are bare identifiers; maps use `{}`)";
            }
            (Some(b')' | b']' | b'}'), Some(&(open, at))) => {
                let note = format!(
                    " (`{}` opened at {} is still open)",
                    open as char,
                    self.position(at)
                );
                err.message += &note;
            }
            _ => {}
        }
        err
    }

    fn map_entry(&mut self) -> PResult<Entry<'a>> {
        let key = self.value()?;
        self.skip_ws()?;
        if !self.eat(b':') {
            return Err(self.expected("`:` after the map key"));
        }
        self.skip_ws()?;
        Ok((key, self.value()?))
    }

    fn field(&mut self) -> PResult<Field<'a>> {
        let Some(name) = self.ident() else {
            return Err(self.expected("a field name (`name: value`) or `)`"));
        };
        self.skip_ws()?;
        if !self.eat(b':') {
            return Err(self.expected(&format!("`:` after the field name `{}`", name.value)));
        }
        self.skip_ws()?;
        Ok((name, self.value()?))
    }

    /// Reads an identifier (`name` or `r#name`) if one is at the cursor.
    fn ident(&mut self) -> Option<Spanned<&'a str>> {
        let start = self.pos;
        let body = self.skip_ident()?;
        Some(spanned(self.slice(body, self.pos), start, self.pos))
    }

    /// Moves past an identifier (`name` or `r#name`) if one is at the cursor; returns where
    /// its name starts (after `r#`).
    fn skip_ident(&mut self) -> Option<usize> {
        let start = self.pos;
        let raw = self.peek() == Some(b'r')
            && self.peek_at(1) == Some(b'#')
            && self.peek_at(2).is_some_and(is_raw_ident_byte);
        if raw {
            self.pos += 2;
            self.eat_while(is_raw_ident_byte);
            Some(start + 2)
        } else if self.peek().is_some_and(is_ident_start) {
            self.eat_while(is_ident_byte);
            Some(start)
        } else {
            None
        }
    }

    /// An identifier-led value: bool, `inf`/`NaN`, a bare identifier or `Name(...)`.
    fn word(&mut self) -> PResult<Spanned<Value<'a>>> {
        let start = self.pos;
        let Some(name) = self.ident() else {
            return Err(self.expected("a value"));
        };
        let raw = name.span.end - name.span.start != name.value.len();
        let keyword = match name.value {
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
        name: Option<Spanned<&'a str>>,
        start: usize,
    ) -> PResult<Spanned<Value<'a>>> {
        self.enter(b'(')?;
        self.skip_ws()?;
        let value = if name.is_none() && self.eat(b')') {
            self.open.pop();
            Value::Unit
        } else if self.at_field() {
            Value::Struct(
                name,
                self.sequence(b')', "the field value", |p| &mut p.fields, Self::field)?,
            )
        } else {
            Value::Tuple(
                name,
                self.sequence(b')', "the value", |p| &mut p.values, Self::value)?,
            )
        };
        Ok(spanned(value, start, self.pos))
    }

    /// Lookahead: does `ident :` start at the cursor?
    fn at_field(&mut self) -> bool {
        let save = self.pos;
        let field =
            self.skip_ident().is_some() && self.skip_ws().is_ok() && self.peek() == Some(b':');
        self.pos = save;
        field
    }

    // ----- literals ----------------------------------------------------------------------

    fn number(&mut self) -> PResult<Spanned<Value<'a>>> {
        let start = self.pos;
        let negative = self.peek() == Some(b'-');
        self.pos += usize::from(matches!(self.peek(), Some(b'+' | b'-')));
        let sign = self.slice(start, self.pos);
        for (word, v) in [("inf", f64::INFINITY), ("NaN", f64::NAN)] {
            let rest = &self.bytes[self.pos..];
            if rest.starts_with(word.as_bytes()) && !rest.get(3).is_some_and(|&b| is_ident_byte(b))
            {
                self.pos += 3;
                let v = if negative { -v } else { v };
                return Ok(spanned(Value::Float(v), start, self.pos));
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
                let message = format!("`{text}` is not a valid number: write `{fixed}`");
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
        let mut float = self.eat(b'.');
        if float && self.peek().is_some_and(|b| b.is_ascii_digit()) {
            self.digits();
        }
        float |= self.exponent()?;
        if self.peek().is_some_and(|b| is_ident_byte(b) || b == b'.') {
            return Err(self.invalid_number(start));
        }
        let text = self.slice(start, self.pos);
        let text = if text.contains('_') {
            Cow::Owned(text.replace('_', ""))
        } else {
            Cow::Borrowed(text)
        };
        let value = if float {
            Value::Float(text.parse().map_err(|_| self.invalid_number(start))?)
        } else {
            Value::Int(text.parse().map_err(|_| self.overflow(start))?)
        };
        Ok(spanned(value, start, self.pos))
    }

    /// Consumes digits and `_` separators.
    fn digits(&mut self) {
        self.eat_while(|b| b.is_ascii_digit() || b == b'_');
    }

    /// Consumes an optional exponent; returns whether there was one.
    fn exponent(&mut self) -> PResult<bool> {
        let start = self.pos;
        if !self.eat(b'e') && !self.eat(b'E') {
            return Ok(false);
        }
        self.pos += usize::from(matches!(self.peek(), Some(b'+' | b'-')));
        let digits_start = self.pos;
        self.digits();
        if !self
            .slice(digits_start, self.pos)
            .bytes()
            .any(|b| b.is_ascii_digit())
        {
            let message = "expected digits after the exponent `e` of the number";
            return Err(self.err(start, self.pos, message));
        }
        Ok(true)
    }

    /// Digits after a `0x`/`0b`/`0o` prefix (already consumed).
    fn radix_integer(
        &mut self,
        start: usize,
        neg: bool,
        radix: u32,
        name: &str,
    ) -> PResult<Spanned<Value<'a>>> {
        let digits_start = self.pos;
        self.eat_while(is_ident_byte);
        let raw = self.slice(digits_start, self.pos);
        if let Some((i, c)) = raw
            .char_indices()
            .find(|&(_, c)| c != '_' && !c.is_digit(radix))
        {
            let text = self.slice(start, self.pos);
            let message = format!("invalid digit `{c}` in {name} number `{text}`");
            return Err(self.err(digits_start + i, digits_start + i + 1, message));
        }
        let digits = raw.replace('_', "");
        if digits.is_empty() {
            let prefix = self.slice(digits_start - 2, digits_start);
            let message = format!("expected {name} digits after `{prefix}`");
            return Err(self.err(start, self.pos, message));
        }
        if self.peek() == Some(b'.') {
            return Err(self.invalid_number(start));
        }
        let signed = if neg { format!("-{digits}") } else { digits };
        match i64::from_str_radix(&signed, radix) {
            Ok(i) => Ok(spanned(Value::Int(i), start, self.pos)),
            Err(_) => Err(self.overflow(start)),
        }
    }

    fn invalid_number(&mut self, start: usize) -> ParseError {
        self.eat_while(|b| is_ident_byte(b) || b == b'.');
        let message = format!("invalid number `{}`", self.slice(start, self.pos));
        self.err(start, self.pos, message)
    }

    fn overflow(&self, start: usize) -> ParseError {
        let text = self.slice(start, self.pos);
        let message = format!("integer `{text}` is out of the i64 range");
        self.err(start, self.pos, message)
    }

    fn string(&mut self) -> PResult<Spanned<Value<'a>>> {
        let start = self.pos;
        self.pos += 1;
        // Borrowed from the source unless an escape needs resolving.
        let mut out = Cow::Borrowed("");
        loop {
            // Takes the run of plain characters up to the next quote or backslash at once.
            let rest = &self.bytes[self.pos..];
            let Some(run) = memchr::memchr2(b'"', b'\\', rest) else {
                break;
            };
            let plain = self.slice(self.pos, self.pos + run);
            if out.is_empty() {
                out = Cow::Borrowed(plain);
            } else {
                out.to_mut().push_str(plain);
            }
            self.pos += run + 1;
            if rest[run] == b'"' {
                let out = match out {
                    Cow::Borrowed(text) => text,
                    Cow::Owned(text) => self.arena.alloc_str(&text),
                };
                return Ok(spanned(Value::String(out), start, self.pos));
            }
            let Some(c) = self.escape()? else { break };
            out.to_mut().push(c);
        }
        let message = "unterminated string: this `\"` is never closed";
        Err(self.err(start, start + 1, message))
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
            'x' | 'u' => {
                let braced = c == 'u' && self.eat(b'{');
                let digits_start = self.pos;
                let max = match (c, braced) {
                    ('x', _) => 2,
                    (_, true) => 6,
                    _ => 4,
                };
                while self.pos - digits_start < max
                    && self.peek().is_some_and(|b| b.is_ascii_hexdigit())
                {
                    self.pos += 1;
                }
                let digits = self.slice(digits_start, self.pos);
                let closed = if braced {
                    self.eat(b'}')
                } else {
                    digits.len() == max
                };
                let code = u32::from_str_radix(digits, 16)
                    .ok()
                    .filter(|&n| c == 'u' || n < 0x80);
                match code.and_then(char::from_u32) {
                    Some(ch) if closed => ch,
                    _ => {
                        let text = self.slice(start, self.pos);
                        let help = if c == 'x' {
                            "`\\x00` to `\\x7F`"
                        } else {
                            "`\\u{0}` to `\\u{10FFFF}`"
                        };
                        let message = format!("invalid escape `{text}`: use {help}");
                        return Err(self.err(start, self.pos, message));
                    }
                }
            }
            _ => {
                let message =
                    format!("unknown escape `\\{c}` (use \\n \\t \\r \\0 \\\\ \\\" \\' \\u{{..}})");
                return Err(self.err(start, self.pos, message));
            }
        };
        Ok(Some(resolved))
    }

    /// `r"..."`, `r#"..."#`, ...; the cursor is on the `r`.
    fn raw_string(&mut self, hashes: usize) -> PResult<Spanned<Value<'a>>> {
        let start = self.pos;
        let body = start + hashes + 2;
        let mut quote = body;
        loop {
            let Some(found) = self.bytes[quote..].iter().position(|&b| b == b'"') else {
                let close = format!("\"{}", "#".repeat(hashes));
                let message = format!("unterminated raw string: expected `{close}` to close it");
                return Err(self.err(start, body, message));
            };
            quote += found;
            let end = quote + 1 + hashes;
            if self
                .bytes
                .get(quote + 1..end)
                .is_some_and(|s| s.iter().all(|&b| b == b'#'))
            {
                self.pos = end;
                return Ok(spanned(Value::String(self.slice(body, quote)), start, end));
            }
            quote += 1;
        }
    }

    fn char_literal(&mut self) -> PResult<Spanned<Value<'a>>> {
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
            let line = self.slice(self.pos, self.bytes.len()).split('\n').next();
            if let Some(close) = line.and_then(|line| line.find('\'')) {
                let message = "a character literal holds one character; use \"...\" for a string";
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

    /// [`super::parse`] with an arena of its own, kept for the rest of the test run.
    fn parse(src: &str) -> Result<Spanned<Value<'_>>, ParseError> {
        super::parse(src, Box::leak(Box::default()))
    }

    /// Compact rendering of a value tree (spans dropped) for readable assertions.
    fn show(v: &Value) -> String {
        let join = |items: Vec<String>| items.join(", ");
        let list = |items: &[Spanned<Value>]| join(items.iter().map(|i| show(&i.value)).collect());
        let name = |n: &Option<Spanned<&str>>| n.as_ref().map_or("", |n| n.value).to_string();
        match v {
            Value::Bool(b) => b.to_string(),
            Value::Int(i) => i.to_string(),
            Value::Float(f) => format!("{f:?}"),
            Value::String(s) => format!("{s:?}"),
            Value::Char(c) => format!("{c:?}"),
            Value::Unit => "()".to_string(),
            Value::Ident(s) => s.to_string(),
            Value::List(items) => format!("[{}]", list(items)),
            Value::Map(entries) => {
                let e = entries
                    .iter()
                    .map(|(k, v)| format!("{}: {}", show(&k.value), show(&v.value)));
                format!("{{{}}}", join(e.collect()))
            }
            Value::Tuple(n, items) => format!("{}({})", name(n), list(items)),
            Value::Struct(n, fields) => {
                let f = fields
                    .iter()
                    .map(|(k, v)| format!("{}: {}", k.value, show(&v.value)));
                format!("{}({})", name(n), join(f.collect()))
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
        assert_eq!(ok("[None, r#type, r#true, _x1]"), "[None, type, true, _x1]");
        assert_eq!(parse("r#true").map(|v| v.value), Ok(Value::Ident("true")));
    }

    #[test]
    fn numbers() {
        assert_eq!(
            ok("[0, +7, -7, 1_000_000, 0xFF, -0x10, 0b1010, 0o17, 0x7fff_ffff_ffff_ffff]"),
            "[0, 7, -7, 1000000, 255, -16, 10, 15, 9223372036854775807]"
        );
        assert_eq!(
            ok("(9223372036854775807, -9223372036854775808, -0x8000000000000000)"),
            "(9223372036854775807, -9223372036854775808, -9223372036854775808)"
        );
        assert_eq!(
            ok("[1.0, -2.5e3, 1e-3, 2E+2, 1., 1_0.5_0, inf, -inf, +inf, NaN, -NaN]"),
            "[1.0, -2500.0, 0.001, 200.0, 1.0, 10.5, inf, -inf, inf, NaN, NaN]"
        );
        assert_eq!(parse("-0.0").map(|v| v.value), Ok(Value::Float(-0.0)));
    }

    #[test]
    fn strings_and_chars() {
        assert_eq!(
            ok(r#""a\n\t\\\"\'\0\u{1F600}\x41\u00e9""#),
            "\"a\\n\\t\\\\\\\"'\\0😀Aé\""
        );
        assert_eq!(ok("\"multi\nline é\""), "\"multi\\nline é\"");
        // Escapes first, between and last, around plain runs; the empty string.
        assert_eq!(ok(r#""\tab\"c\\""#), r#""\tab\"c\\""#);
        assert_eq!(ok("\"\""), "\"\"");
        let src = r#""no escapes""#;
        let Ok(Spanned {
            value: Value::String(s),
            ..
        }) = parse(src)
        else {
            panic!("a string");
        };
        assert_eq!(s, "no escapes");
        assert!(
            std::ptr::eq(s.as_ptr(), src[1..].as_ptr()),
            "borrowed: {s:?}"
        );
        assert_eq!(ok(r#"r"C:\path""#), r#""C:\\path""#);
        assert_eq!(ok(r###"r##"a "# b"##"###), r##""a \"# b""##);
        assert_eq!(ok("r#\"\"#"), "\"\"");
        assert_eq!(ok(r"['a', '\n', '\'', 'é']"), r"['a', '\n', '\'', 'é']");
    }

    #[test]
    fn compound_values() {
        assert_eq!(ok("( /* empty */ )"), "()");
        assert_eq!(
            parse("(1)").map(|v| v.value.describe()),
            Ok("a tuple".into())
        );
        assert_eq!(ok("(1, \"two\", 3.0,)"), "(1, \"two\", 3.0)");
        assert_eq!(
            ok("[Some(None), Some(x), Name(), Foo /* c */ (1), (y)]"),
            "[Some(None), Some(x), Name(), Foo(1), (y)]"
        );
        assert_eq!(
            ok("Name(a: 1, b: (x: 2), r#type: Z,)"),
            "Name(a: 1, b: (x: 2), type: Z)"
        );
        assert_eq!(ok("(a: 1, a /* c */ : 2)"), "(a: 1, a: 2)");
        assert_eq!(ok("[[], [1, [2, [3]], A,]]"), "[[], [1, [2, [3]], A]]");
        assert_eq!(
            ok("{ a: 1, \"b\": B(2), (1, 2): [3], Some(k): x, a: 4, }"),
            "{a: 1, \"b\": B(2), (1, 2): [3], Some(k): x, a: 4}"
        );
        assert_eq!(ok("{}"), "{}");
    }

    #[test]
    fn describe() {
        let d = |src: &str| parse(src).map(|v| v.value.describe()).unwrap_or_default();
        let kinds = [
            "1.5",
            "1",
            "[1]",
            "{}",
            "Z",
            "Foo(a: 1)",
            "(a: 1)",
            "Some(1)",
            "()",
            "true",
        ];
        let described: Vec<_> = kinds.iter().map(|src| d(src)).collect();
        assert_eq!(
            described,
            [
                "a float",
                "an integer",
                "a list",
                "a map",
                "identifier `Z`",
                "struct `Foo`",
                "an unnamed struct",
                "tuple `Some`",
                "the unit value `()`",
                "the boolean `true`"
            ]
        );
        assert_eq!([d("\"s\""), d("'c'")], ["a string", "a character"]);
    }

    #[test]
    fn spans_and_line_columns() {
        let src = "// head\nGraph(\n  nodes: {\n    \"é\": Sin(value: \"phase\"),\n  },\n)\n";
        let doc = parse(src).unwrap();
        let index = LineIndex::new(src);
        let at = |span: Span| (index.line_col(span.start), &src[span.start..span.end]);
        assert_eq!(
            doc.span,
            Span {
                start: 8,
                end: src.len() - 1
            }
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
        // Columns count chars: `"é"` is 3 chars but 4 bytes, so `Sin` starts at column 10.
        assert_eq!(at(node.span), ((4, 10), "Sin(value: \"phase\")"));
        let Value::Struct(_, inner) = &node.value else {
            panic!("{node:?}")
        };
        assert_eq!(at(inner[0].1.span), ((4, 21), "\"phase\""));
    }

    #[test]
    fn line_index_edges() {
        let index = LineIndex::new("ab\né\n");
        let cols: Vec<_> = [0, 2, 3, 4, 5, 6, 999].map(|o| index.line_col(o)).into();
        // Offset 4 is inside `é` and snaps back to its start; 999 maps to the end.
        assert_eq!(
            cols,
            [(1, 1), (1, 3), (2, 1), (2, 1), (2, 2), (3, 1), (3, 1)]
        );
        assert_eq!(LineIndex::new("").line_col(5), (1, 1));
        // All ASCII: columns are byte counts, the same edges.
        let ascii = LineIndex::new("ab\ncd");
        let cols: Vec<_> = [0, 2, 3, 4, 5, 999].map(|o| ascii.line_col(o)).into();
        assert_eq!(cols, [(1, 1), (1, 3), (2, 1), (2, 2), (2, 3), (2, 3)]);
        // Lines differ: `°` (2 bytes) and `—` (3 bytes) count one column each on their own
        // lines; the ASCII line between them counts bytes.
        let mixed = LineIndex::new("a°b\ncd\n—x");
        let cols: Vec<_> = [3, 4, 6, 7, 9, 11, 13].map(|o| mixed.line_col(o)).into();
        assert_eq!(
            cols,
            [(1, 3), (1, 4), (2, 2), (2, 3), (3, 1), (3, 2), (3, 3)]
        );
    }

    #[test]
    fn syntax_errors() {
        let cases = [
            " => 1:1 unexpected end of file: expected a value",
            "  // only a comment\n => 2:1 unexpected end of file: expected a value",
            "Graph(\n  a: 1,\n => 3:1 unexpected end of file: `(` opened at 1:6 is never closed",
            "[1, {a: ( => 1:10 unexpected end of file: `(` opened at 1:9 is never closed",
            "(1 foo) => 1:4 expected `,` or `)` after the value, found `foo`",
            "(a: 1\n b: 2) => 2:2 expected `,` or `)` after the field value, found `b`",
            "[1 2] => 1:4 expected `,` or `]` after the list element, found `2`",
            "{a: 1 b: 2} => 1:7 expected `,` or `}` after the map entry, found `b`",
            "{ a 1 } => 1:5 expected `:` after the map key, found `1`",
            "(a: 1, 2) => 1:8 expected a field name (`name: value`) or `)`, found `2`",
            "(a: 1, b) => 1:9 expected `:` after the field name `b`, found `)`",
            "[1,,2] => 1:4 expected a value, found `,`",
            "@ => 1:1 expected a value, found `@`",
            "1 2 => 1:3 unexpected `2` after the end of the document (a RON file holds one value)",
            "#[x] 1 => 1:2 expected `!` after `#` (write `#![enable(..)]`), found `[`",
            "\"abc => 1:1 unterminated string: this `\"` is never closed",
            "[\"a\\ => 1:2 unterminated string: this `\"` is never closed",
            "r#\"abc\" => 1:1 unterminated raw string: expected `\"#` to close it",
            "r#! => 1:1 expected `\"` (raw string) or an identifier after `r#`",
            "1 /* x /* y */ => 1:3 unterminated block comment: `/*` is never closed by `*/`",
            "(x: .5) => 1:5 `.5` is not a valid number: write `0.5`",
            "-.5e1 => 1:1 `-.5e1` is not a valid number: write `-0.5e1`",
            "\n9223372036854775808 => 2:1 integer `9223372036854775808` is out of the i64 range",
            "-0x8000000000000001 => 1:1 integer `-0x8000000000000001` is out of the i64 range",
            "0xFG => 1:4 invalid digit `G` in hexadecimal number `0xFG`",
            "0b102 => 1:5 invalid digit `2` in binary number `0b102`",
            "[0x] => 1:2 expected hexadecimal digits after `0x`",
            "12ab => 1:1 invalid number `12ab`",
            "1.5.2 => 1:1 invalid number `1.5.2`",
            "1e => 1:2 expected digits after the exponent `e` of the number",
            "- 1 => 1:2 expected a number after `-`, found whitespace",
            "\"a\\qb\" => 1:3 unknown escape `\\q` (use \\n \\t \\r \\0 \\\\ \\\" \\' \\u{..})",
            "\"\\u{110000}\" => 1:2 invalid escape `\\u{110000}`: use `\\u{0}` to `\\u{10FFFF}`",
            "\"\\u{12\" => 1:2 invalid escape `\\u{12`: use `\\u{0}` to `\\u{10FFFF}`",
            "\"\\x80\" => 1:2 invalid escape `\\x80`: use `\\x00` to `\\x7F`",
            "'ab' => 1:1 a character literal holds one character; use \"...\" for a string",
            "'' => 1:1 empty character literal `''`",
            "'a => 1:1 unterminated character literal: expected `'` after the character",
            "(1, 2] => 1:6 expected `,` or `)` after the value, found `]` \
             (`(` opened at 1:1 is still open)",
            "(\"a\": 1) => 1:5 expected `,` or `)` after the value, found `:` \
             (field names are bare identifiers; maps use `{}`)",
        ];
        for case in cases {
            let (src, expected) = case.split_once(" => ").unwrap_or_default();
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
            Value::List(items) | Value::Tuple(_, items) => children.extend(items.iter()),
            Value::Map(entries) => entries.iter().for_each(|(k, v)| children.extend([k, v])),
            Value::Struct(_, fields) => fields.iter().for_each(|(name, value)| {
                inside(name.span);
                children.push(value);
            }),
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
        let names: Vec<_> = fields.iter().map(|(k, _)| k.value).collect();
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
        let shown = show(&doc.value);
        assert!(shown.contains("\"pelvis\": GetTransform(bone: bone(\"pelvis\"), space: Global"));
        assert!(shown.contains("\"v\": (1.0, -2.0, 35.0)") && shown.contains("default: 4080"));
        for end in (0..DOC.len()).filter(|&i| DOC.is_char_boundary(i)) {
            if let Ok(v) = parse(&DOC[..end]) {
                check_spans(&DOC[..end], &v);
            }
        }
    }

    #[test]
    fn random_input_never_panics() {
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = move |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
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
        let mut parsed = 0;
        for round in 0..6000 {
            let len = next(48);
            let src: String = if round % 2 == 0 {
                (0..len).map(|_| chars[next(chars.len())]).collect()
            } else {
                (0..len).map(|_| tokens[next(tokens.len())]).collect()
            };
            match parse(&src) {
                Ok(v) => {
                    check_spans(&src, &v);
                    parsed += 1;
                }
                Err(e) => assert!(
                    e.span.start <= e.span.end && e.span.end <= src.len(),
                    "{src:?}: {e:?}"
                ),
            }
        }
        assert!(
            parsed > 0,
            "the generator should produce some valid documents"
        );
    }
}
