//! A recursive-descent parser for GLSL ES (1.00 and 3.00) that reports every syntax error in one
//! run.
//!
//! Recovery, as rustc does it: a missing `;` whose next token is on a later line is reported at
//! the end of the line that lacks it (with a certain fix) and parsing goes on as if it were
//! there; any other syntax error skips to the end of the statement or declaration (`;` or
//! `}`), and errors inside the skipped part are not reported (no cascades).
//!
//! One `Parser` walks the tokens; this module holds its state, token access, error reporting
//! and recovery. The productions are methods on it, spread over the submodules by what they
//! parse: `declarations`, `types`, `statements` and `expressions`.

use crate::diagnostic_code::Code;
use crate::Name;
use rustc_hash::FxHashMap as HashMap;

use crate::ast::*;
use crate::diagnostic::{Diagnostic, Fix};
use crate::lex::Punct;
use crate::source::{SourceFile, Span};
use crate::target::Language;
use crate::token::{Kw, Tok, Token};
use crate::Stage;

mod declarations;
mod expressions;
mod statements;
mod types;

/// How deeply expressions and statements may nest before the parser gives up on them (this
/// bounds the recursion of every later pass too).
pub const MAX_NESTING: u32 = 256;

/// Parses a GLSL ES 3.00 shader's tokens (ending with `Eof`) into a syntax tree, collecting
/// diagnostics ([`parse_as`] for another language).
pub fn parse(
    file: &SourceFile,
    tokens: Vec<Token>,
    stage: Stage,
) -> (TranslationUnit, Vec<Diagnostic>) {
    parse_as(file, tokens, stage, &Language::es300())
}

/// Parses a shader's tokens (ending with `Eof`) into a syntax tree, collecting diagnostics.
pub fn parse_as(
    file: &SourceFile,
    tokens: Vec<Token>,
    stage: Stage,
    lang: &Language,
) -> (TranslationUnit, Vec<Diagnostic>) {
    let mut p = Parser {
        es100: lang.es100,
        file,
        toks: tokens,
        pos: 0,
        diags: Vec::new(),
        suppress: false,
        type_names: vec![HashMap::default()],
        any_struct: false,
        depth: 0,
        too_deep_reported: false,
        stage,
        lang: lang.clone(),
    };
    if p.toks.last().is_none_or(|t| !matches!(t.tok, Tok::Eof)) {
        let end = file.text().len() as u32;
        p.toks.push(Token {
            tok: Tok::Eof,
            span: Span::empty(end),
            text: Name::default(),
            from_macro: false,
        });
    }
    let mut unit = p.translation_unit();
    unit.truncated = p.too_deep_reported;
    (unit, p.diags)
}

/// Marker for "this production failed; an error has been reported (or suppressed)".
struct Failed;

type PResult<T> = Result<T, Failed>;

struct Parser<'a> {
    /// GLSL ES 1.00 (for the words of messages: which version reserves what).
    es100: bool,
    file: &'a SourceFile,
    toks: Vec<Token>,
    pos: usize,
    diags: Vec<Diagnostic>,
    /// After an error, until the next synchronisation point: don't report more.
    suppress: bool,
    /// Per open scope, the names declared in it: `true` for a struct, `false` for a variable or
    /// parameter, which hides a struct of the same name in the scopes around it (GLSL ES
    /// §4.2.2). Whether an identifier starts a declaration or an expression depends on it.
    type_names: Vec<HashMap<Name, bool>>,
    /// Whether a struct was declared yet. Until one is, no name is a type and none hides one,
    /// so variables need not be recorded: a struct declared later is in the same scope as
    /// the open ones' variables or in a scope inside them, and is found first either way.
    any_struct: bool,
    depth: u32,
    too_deep_reported: bool,
    stage: Stage,
    /// Where the shader enables `GL_NV_shader_noperspective_interpolation`, which makes the
    /// reserved word `noperspective` a qualifier.
    lang: Language,
}

impl<'a> Parser<'a> {
    // ----- token access -----

    fn peek(&self) -> &Token {
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }

    fn peek_at(&self, n: usize) -> &Token {
        &self.toks[(self.pos + n).min(self.toks.len() - 1)]
    }

    fn tok(&self) -> &Tok {
        &self.peek().tok
    }

    fn at(&self, p: Punct) -> bool {
        matches!(self.peek().tok, Tok::P(q) if q == p)
    }

    fn at_kw(&self, kw: Kw) -> bool {
        matches!(self.peek().tok, Tok::Kw(q) if q == kw)
    }

    fn at_eof(&self) -> bool {
        matches!(self.peek().tok, Tok::Eof)
    }

    fn bump(&mut self) -> Token {
        let t = self.peek().clone();
        self.advance();
        t
    }

    /// Moves past the current token and gives its span (no copy of the token).
    fn bump_span(&mut self) -> Span {
        let span = self.peek().span;
        self.advance();
        span
    }

    /// Moves past the current token (never past the final `Eof`).
    fn advance(&mut self) {
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
    }

    fn eat(&mut self, p: Punct) -> bool {
        if self.at(p) {
            self.advance();
            true
        } else {
            false
        }
    }

    fn eat_kw(&mut self, kw: Kw) -> bool {
        if self.at_kw(kw) {
            self.advance();
            true
        } else {
            false
        }
    }

    /// Span of the last consumed token.
    fn prev_span(&self) -> Span {
        if self.pos == 0 {
            Span::empty(0)
        } else {
            self.toks[self.pos - 1].span
        }
    }

    fn span_from(&self, start: Span) -> Span {
        start.to(self.prev_span())
    }

    /// How a token is described in a message: `` `uniform` ``, ``identifier `x` ``, …
    fn describe(t: &Token) -> String {
        match &t.tok {
            Tok::Eof => "end of file".into(),
            Tok::Ident => format!("identifier `{}`", t.text),
            Tok::Int(..) | Tok::Float(_) => format!("number `{}`", t.text),
            Tok::Kw(k) => format!("`{}`", k.as_str()),
            Tok::Reserved => format!("reserved word `{}`", t.text),
            Tok::P(p) => format!("`{}`", p.as_str()),
            Tok::Error => format!("`{}`", t.text),
        }
    }

    fn is_type_name(&self, name: &str) -> bool {
        if !self.any_struct {
            return false;
        }
        self.type_names
            .iter()
            .rev()
            .find_map(|s| s.get(name).copied())
            .unwrap_or(false)
    }

    /// Whether `name` is a struct's name hidden by a variable or parameter in an inner scope.
    fn hides_type(&self, name: &str) -> bool {
        if !self.any_struct {
            return false;
        }
        let mut hits = self.type_names.iter().rev().filter_map(|s| s.get(name));
        hits.next() == Some(&false) && hits.any(|t| *t)
    }

    /// Records a struct's name (`is_type`) or a variable's or parameter's in the innermost
    /// scope.
    fn declare_name(&mut self, name: &Name, is_type: bool) {
        self.any_struct |= is_type;
        if !self.any_struct {
            return;
        }
        if let Some(scope) = self.type_names.last_mut() {
            scope.insert(name.clone(), is_type);
        }
    }

    fn push_scope(&mut self) {
        self.type_names.push(HashMap::default());
    }

    fn pop_scope(&mut self) {
        if self.type_names.len() > 1 {
            self.type_names.pop();
        }
    }

    // ----- errors -----

    /// Adds a diagnostic unless enough were collected ([`crate::diagnostic::MAX_DIAGNOSTICS`]).
    fn push_diag(&mut self, d: Diagnostic) {
        crate::diagnostic::push_capped(&mut self.diags, d);
    }

    fn report(&mut self, d: Diagnostic) {
        if !self.suppress && !self.too_deep_reported {
            self.push_diag(d);
        }
        self.suppress = true;
    }

    /// "expected X, found Y" at the current token.
    fn expected(&mut self, what: &str) -> Failed {
        let t = self.peek().clone();
        if matches!(t.tok, Tok::Error) {
            // Already reported by the lexer or number parser.
            self.suppress = true;
            return Failed;
        }
        let mut d = Diagnostic::error(
            Code::SyntaxError,
            format!("expected {what}, found {}", Self::describe(&t)),
            t.span,
        )
        .with_label(format!("expected {what}"))
        .with_token(&*t.text);
        let prev = self.prev_span();
        let prev_text = self.file.slice(prev);
        if matches!(t.tok, Tok::P(Punct::Star)) && prev_text == "*" && prev.end == t.span.start {
            // `a ** b`: markdown damage, or exponentiation from another language.
            d = d
                .with_note("`**` is not an operator in GLSL (a copy from a web page often turns `*` into `**`)")
                .with_help("write `*` for a product, or `pow(a, b)` for a power")
                .with_fix(Fix::suggested("remove the second `*`", t.span, ""));
        } else if matches!(t.tok, Tok::P(Punct::Plus | Punct::Minus | Punct::Star))
            && self.starts_line(t.span)
        {
            // A line that starts with `+`, `-` or `*` where a statement should start: a diff.
            d = d.with_note(format!(
                "this line starts with `{}`, like a line of a diff or a markdown list; remove the marker",
                t.text
            ));
        }
        self.report(d);
        Failed
    }

    /// Whether a token is the first thing on its line.
    fn starts_line(&self, span: Span) -> bool {
        let line = self.file.line_index(span.start);
        self.file.text()[self.file.line_start(line) as usize..span.start as usize]
            .trim()
            .is_empty()
    }

    /// Expects `;` to end `what` (`declaration`, `expression`, …). When the next token is on a
    /// later line (or closes a block), the `;` is taken as missing at the end of the previous
    /// token: reported there with a certain fix, and parsing goes on as if it were present.
    fn expect_semicolon(&mut self, what: &str) -> PResult<()> {
        if self.eat(Punct::Semicolon) {
            return Ok(());
        }
        let prev = self.prev_span();
        let next = self.peek().clone();
        let later_line = self.file.line_of(next.span.start)
            > self.file.line_of(prev.end.max(1) - 1)
            || matches!(next.tok, Tok::Eof | Tok::P(Punct::RightBrace));
        if later_line {
            let at = prev.end_point();
            let d = Diagnostic::error(
                Code::MissingSemicolon,
                format!("expected `;` after {what}"),
                at,
            )
            .with_label("expected `;` here")
            .with_secondary(
                next.span,
                match next.tok {
                    Tok::Eof => "the file ends here",
                    Tok::P(Punct::RightBrace) => "the block ends here",
                    _ if self.type_names.len() == 1 => "the next declaration starts here",
                    _ => "the next statement starts here",
                },
            )
            .with_fix(Fix::certain("add `;` at the end of the line", at, ";"))
            .with_token(&*next.text);
            if !self.suppress && !self.too_deep_reported {
                self.push_diag(d);
            }
            return Ok(());
        }
        let d = Diagnostic::error(
            Code::SyntaxError,
            format!("expected `;` after {what}, found {}", Self::describe(&next)),
            next.span,
        )
        .with_label("expected `;` before this")
        .with_token(&*next.text);
        self.report(d);
        Err(Failed)
    }

    fn expect(&mut self, p: Punct) -> PResult<Span> {
        if self.at(p) {
            Ok(self.bump_span())
        } else {
            Err(self.expected(&format!("`{}`", p.as_str())))
        }
    }

    /// Expects a closing delimiter, pointing back at the opening one.
    fn expect_close(&mut self, close: Punct, open: Span) -> PResult<Span> {
        if self.at(close) {
            return Ok(self.bump_span());
        }
        let t = self.peek().clone();
        if matches!(t.tok, Tok::Error) {
            self.suppress = true;
            return Err(Failed);
        }
        let open_text = self.file.slice(open).to_string();
        let d = Diagnostic::error(
            Code::SyntaxError,
            format!(
                "expected `{}`, found {}",
                close.as_str(),
                Self::describe(&t)
            ),
            t.span,
        )
        .with_label(format!("expected `{}`", close.as_str()))
        .with_secondary(open, format!("to close this `{open_text}`"))
        .with_token(&*t.text);
        self.report(d);
        Err(Failed)
    }

    fn ident(&mut self, what: &str) -> PResult<Ident> {
        if self.peek().tok == Tok::Ident {
            let ident = Ident {
                name: self.peek().text.clone(),
                span: self.peek().span,
            };
            self.advance();
            return Ok(ident);
        }
        let t = self.peek().clone();
        match &t.tok {
            Tok::Ident => {
                self.advance();
                Ok(Ident {
                    name: t.text.clone(),
                    span: t.span,
                })
            }
            Tok::Reserved => {
                self.advance();
                self.reserved_word(&t.text, t.span);
                Ok(Ident {
                    name: t.text.clone(),
                    span: t.span,
                })
            }
            Tok::Kw(k) => {
                let d = Diagnostic::error(
                    Code::KeywordAsIdentifier,
                    format!("`{}` is a keyword and cannot be used as {what}", k.as_str()),
                    t.span,
                )
                .with_label("a keyword")
                .with_help("choose another name")
                .with_token(&*t.text);
                self.report(d);
                Err(Failed)
            }
            _ => Err(self.expected(what)),
        }
    }

    fn reserved_word(&mut self, name: &str, span: Span) {
        let version = if self.es100 { "1.00" } else { "3.00" };
        let mut d = Diagnostic::error(
            Code::ReservedWord,
            format!("`{name}` is a reserved word in GLSL ES {version}"),
            span,
        )
        .with_label("reserved for future use")
        .with_token(name);
        d = match name {
            "attribute" => d.with_help("`attribute` is GLSL ES 1.00; in 3.00 a vertex input is declared with `in`"),
            "varying" => d.with_help(
                "`varying` is GLSL ES 1.00; in 3.00 use `out` in the vertex shader and `in` in the fragment shader",
            ),
            "switch" | "default" | "flat" | "sampler3D" | "sampler2DShadow" if self.es100 => d
                .with_help(format!(
                    "`{name}` is GLSL ES 3.00: start the shader with `#version 300 es` (WebGL 2) to use it"
                )),
            _ => d.with_help("choose another name"),
        };
        if !self.suppress {
            self.push_diag(d);
        }
    }

    /// Skips to the end of the current statement or declaration: past a `;` at this nesting
    /// level, or before a `}` that closes the enclosing block. Braces opened on the way are
    /// skipped whole. Ends error suppression.
    fn synchronize(&mut self) {
        let mut depth = 0i32;
        loop {
            match self.tok() {
                Tok::Eof => break,
                Tok::P(Punct::Semicolon) if depth == 0 => {
                    self.advance();
                    break;
                }
                Tok::P(Punct::LeftBrace) => depth += 1,
                Tok::P(Punct::RightBrace) => {
                    if depth == 0 {
                        break;
                    }
                    depth -= 1;
                    if depth == 0 {
                        self.advance();
                        // `struct S { … } x;` and blocks end with `;`; a function body ends here.
                        if self.at(Punct::Semicolon) {
                            self.advance();
                        }
                        break;
                    }
                }
                _ => {}
            }
            self.advance();
        }
        self.suppress = false;
    }

    fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            if !self.too_deep_reported {
                self.too_deep_reported = true;
                let span = self.peek().span;
                self.push_diag(
                    Diagnostic::error(
                        Code::NestingTooDeep,
                        format!(
                            "expressions or statements nested more than {MAX_NESTING} levels deep"
                        ),
                        span,
                    )
                    .with_label("too deep here")
                    .with_help("split the expression into variables")
                    .with_token(&*self.peek().text),
                );
            }
            self.suppress = true;
            // Skip everything: nothing sensible can be parsed at this depth.
            while !self.at_eof() {
                self.advance();
            }
            return Err(Failed);
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }
}
