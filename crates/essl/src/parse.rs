//! A recursive-descent parser for GLSL ES 3.00 that reports every syntax error in one run.
//!
//! Recovery, as rustc does it: a missing `;` whose next token is on a later line is reported at
//! the end of the line that lacks it (with a certain fix) and parsing goes on as if it were
//! there; any other syntax error skips to the end of the statement or declaration (`;` or
//! `}`), and errors inside the skipped part are not reported (no cascades).

use std::collections::HashSet;
use std::sync::Arc;

use crate::ast::*;
use crate::diagnostic::{Diagnostic, Fix};
use crate::lex::Punct;
use crate::source::{SourceFile, Span};
use crate::token::{Kw, Tok, Token};
use crate::types::{Precision, SamplerType, ScalarKind};
use crate::Stage;

/// How deeply expressions and statements may nest before the parser gives up on them (this
/// bounds the recursion of every later pass too).
pub const MAX_NESTING: u32 = 256;

/// Parses a shader's tokens (ending with `Eof`) into a syntax tree, collecting diagnostics.
pub fn parse(
    file: &SourceFile,
    tokens: Vec<Token>,
    stage: Stage,
) -> (TranslationUnit, Vec<Diagnostic>) {
    let mut p = Parser {
        file,
        toks: tokens,
        pos: 0,
        diags: Vec::new(),
        suppress: false,
        type_names: vec![HashSet::new()],
        depth: 0,
        too_deep_reported: false,
        stage,
    };
    if p.toks.last().is_none_or(|t| t.tok != Tok::Eof) {
        let end = file.text().len() as u32;
        p.toks.push(Token {
            tok: Tok::Eof,
            span: Span::empty(end),
            text: Arc::from(""),
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
    file: &'a SourceFile,
    toks: Vec<Token>,
    pos: usize,
    diags: Vec<Diagnostic>,
    /// After an error, until the next synchronisation point: don't report more.
    suppress: bool,
    /// Struct names visible in each open scope.
    type_names: Vec<HashSet<Arc<str>>>,
    depth: u32,
    too_deep_reported: bool,
    stage: Stage,
}

fn type_keyword(kw: Kw) -> Option<TypeName> {
    use ScalarKind::*;
    Some(match kw {
        Kw::Void => TypeName::Void,
        Kw::Float => TypeName::Scalar(Float),
        Kw::Int => TypeName::Scalar(Int),
        Kw::Uint => TypeName::Scalar(Uint),
        Kw::Bool => TypeName::Scalar(Bool),
        Kw::Vec2 => TypeName::Vector(Float, 2),
        Kw::Vec3 => TypeName::Vector(Float, 3),
        Kw::Vec4 => TypeName::Vector(Float, 4),
        Kw::Ivec2 => TypeName::Vector(Int, 2),
        Kw::Ivec3 => TypeName::Vector(Int, 3),
        Kw::Ivec4 => TypeName::Vector(Int, 4),
        Kw::Uvec2 => TypeName::Vector(Uint, 2),
        Kw::Uvec3 => TypeName::Vector(Uint, 3),
        Kw::Uvec4 => TypeName::Vector(Uint, 4),
        Kw::Bvec2 => TypeName::Vector(Bool, 2),
        Kw::Bvec3 => TypeName::Vector(Bool, 3),
        Kw::Bvec4 => TypeName::Vector(Bool, 4),
        Kw::Mat2 | Kw::Mat2x2 => TypeName::Matrix { cols: 2, rows: 2 },
        Kw::Mat3 | Kw::Mat3x3 => TypeName::Matrix { cols: 3, rows: 3 },
        Kw::Mat4 | Kw::Mat4x4 => TypeName::Matrix { cols: 4, rows: 4 },
        Kw::Mat2x3 => TypeName::Matrix { cols: 2, rows: 3 },
        Kw::Mat2x4 => TypeName::Matrix { cols: 2, rows: 4 },
        Kw::Mat3x2 => TypeName::Matrix { cols: 3, rows: 2 },
        Kw::Mat3x4 => TypeName::Matrix { cols: 3, rows: 4 },
        Kw::Mat4x2 => TypeName::Matrix { cols: 4, rows: 2 },
        Kw::Mat4x3 => TypeName::Matrix { cols: 4, rows: 3 },
        _ => return SamplerType::from_name(kw.as_str()).map(TypeName::Sampler),
    })
}

fn is_qualifier_kw(kw: Kw) -> bool {
    matches!(
        kw,
        Kw::Const
            | Kw::In
            | Kw::Out
            | Kw::Inout
            | Kw::Uniform
            | Kw::Centroid
            | Kw::Flat
            | Kw::Smooth
            | Kw::Invariant
            | Kw::Lowp
            | Kw::Mediump
            | Kw::Highp
            | Kw::Layout
    )
}

fn binary_op(p: Punct) -> Option<(BinaryOp, u8)> {
    use BinaryOp::*;
    Some(match p {
        Punct::OrOr => (Or, 1),
        Punct::XorXor => (Xor, 2),
        Punct::AndAnd => (And, 3),
        Punct::Pipe => (BitOr, 4),
        Punct::Caret => (BitXor, 5),
        Punct::Ampersand => (BitAnd, 6),
        Punct::EqualEqual => (Eq, 7),
        Punct::BangEqual => (NotEq, 7),
        Punct::Less => (Less, 8),
        Punct::Greater => (Greater, 8),
        Punct::LessEqual => (LessEq, 8),
        Punct::GreaterEqual => (GreaterEq, 8),
        Punct::LeftShift => (Shl, 9),
        Punct::RightShift => (Shr, 9),
        Punct::Plus => (Add, 10),
        Punct::Minus => (Sub, 10),
        Punct::Star => (Mul, 11),
        Punct::Slash => (Div, 11),
        Punct::Percent => (Mod, 11),
        _ => return None,
    })
}

fn assign_op(p: Punct) -> Option<Option<BinaryOp>> {
    use BinaryOp::*;
    Some(match p {
        Punct::Equal => None,
        Punct::PlusEqual => Some(Add),
        Punct::MinusEqual => Some(Sub),
        Punct::StarEqual => Some(Mul),
        Punct::SlashEqual => Some(Div),
        Punct::PercentEqual => Some(Mod),
        Punct::LeftShiftEqual => Some(Shl),
        Punct::RightShiftEqual => Some(Shr),
        Punct::AmpersandEqual => Some(BitAnd),
        Punct::PipeEqual => Some(BitOr),
        Punct::CaretEqual => Some(BitXor),
        _ => return None,
    })
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
        self.peek().tok == Tok::P(p)
    }

    fn at_kw(&self, kw: Kw) -> bool {
        self.peek().tok == Tok::Kw(kw)
    }

    fn at_eof(&self) -> bool {
        self.peek().tok == Tok::Eof
    }

    fn bump(&mut self) -> Token {
        let t = self.peek().clone();
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
        t
    }

    fn eat(&mut self, p: Punct) -> bool {
        if self.at(p) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn eat_kw(&mut self, kw: Kw) -> bool {
        if self.at_kw(kw) {
            self.bump();
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
            Tok::Ident(n) => format!("identifier `{n}`"),
            Tok::Int(..) | Tok::Float(_) => format!("number `{}`", t.text),
            Tok::Kw(k) => format!("`{}`", k.as_str()),
            Tok::Reserved(r) => format!("reserved word `{r}`"),
            Tok::P(p) => format!("`{}`", p.as_str()),
            Tok::Error => format!("`{}`", t.text),
        }
    }

    fn is_type_name(&self, name: &str) -> bool {
        self.type_names.iter().any(|s| s.contains(name))
    }

    fn push_scope(&mut self) {
        self.type_names.push(HashSet::new());
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
        if t.tok == Tok::Error {
            // Already reported by the lexer or number parser.
            self.suppress = true;
            return Failed;
        }
        let mut d = Diagnostic::error(
            "syntax-error",
            format!("expected {what}, found {}", Self::describe(&t)),
            t.span,
        )
        .with_label(format!("expected {what}"))
        .with_token(&*t.text);
        let prev = self.prev_span();
        let prev_text = self.file.slice(prev);
        if t.tok == Tok::P(Punct::Star) && prev_text == "*" && prev.end == t.span.start {
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
                "missing-semicolon",
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
            "syntax-error",
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
            Ok(self.bump().span)
        } else {
            Err(self.expected(&format!("`{}`", p.as_str())))
        }
    }

    /// Expects a closing delimiter, pointing back at the opening one.
    fn expect_close(&mut self, close: Punct, open: Span) -> PResult<Span> {
        if self.at(close) {
            return Ok(self.bump().span);
        }
        let t = self.peek().clone();
        if t.tok == Tok::Error {
            self.suppress = true;
            return Err(Failed);
        }
        let open_text = self.file.slice(open).to_string();
        let d = Diagnostic::error(
            "syntax-error",
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
        let t = self.peek().clone();
        match &t.tok {
            Tok::Ident(name) => {
                self.bump();
                Ok(Ident {
                    name: name.clone(),
                    span: t.span,
                })
            }
            Tok::Reserved(name) => {
                self.bump();
                self.reserved_word(name, t.span);
                Ok(Ident {
                    name: name.clone(),
                    span: t.span,
                })
            }
            Tok::Kw(k) => {
                let d = Diagnostic::error(
                    "keyword-as-identifier",
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
        let mut d = Diagnostic::error(
            "reserved-word",
            format!("`{name}` is a reserved word in GLSL ES 3.00"),
            span,
        )
        .with_label("reserved for future use")
        .with_token(name);
        d = match name {
            "attribute" => d.with_help("`attribute` is GLSL ES 1.00; in 3.00 a vertex input is declared with `in`"),
            "varying" => d.with_help(
                "`varying` is GLSL ES 1.00; in 3.00 use `out` in the vertex shader and `in` in the fragment shader",
            ),
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
                    self.bump();
                    break;
                }
                Tok::P(Punct::LeftBrace) => depth += 1,
                Tok::P(Punct::RightBrace) => {
                    if depth == 0 {
                        break;
                    }
                    depth -= 1;
                    if depth == 0 {
                        self.bump();
                        // `struct S { … } x;` and blocks end with `;`; a function body ends here.
                        if self.at(Punct::Semicolon) {
                            self.bump();
                        }
                        break;
                    }
                }
                _ => {}
            }
            self.bump();
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
                        "nesting-too-deep",
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
                self.bump();
            }
            return Err(Failed);
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    // ----- top level -----

    fn translation_unit(&mut self) -> TranslationUnit {
        let mut unit = TranslationUnit::default();
        while !self.at_eof() {
            let start = self.pos;
            match self.external() {
                Ok(Some(item)) => unit.items.push(item),
                Ok(None) => {}
                Err(Failed) => self.synchronize(),
            }
            if self.pos == start && !self.at_eof() {
                // Never loop without progress.
                let t = self.peek().clone();
                self.report(
                    Diagnostic::error(
                        "syntax-error",
                        format!("unexpected {}", Self::describe(&t)),
                        t.span,
                    )
                    .with_label("not expected here")
                    .with_token(&*t.text),
                );
                self.bump();
                self.synchronize();
            }
        }
        unit
    }

    fn external(&mut self) -> PResult<Option<ExternalDecl>> {
        if self.at(Punct::Semicolon) {
            let s = self.bump().span;
            self.report(
                Diagnostic::error("syntax-error", "unexpected `;` at global scope", s)
                    .with_label("an empty declaration")
                    .with_fix(Fix::certain("remove it", s, ""))
                    .with_token(";"),
            );
            self.suppress = false;
            return Ok(None);
        }
        if self.at(Punct::RightBrace) {
            let s = self.bump().span;
            self.report(
                Diagnostic::error("syntax-error", "unmatched `}`", s)
                    .with_label("no block to close here")
                    .with_token("}"),
            );
            self.suppress = false;
            return Ok(None);
        }
        let start = self.peek().span;
        if self.at_kw(Kw::Precision) {
            return Ok(Some(ExternalDecl::Declaration(self.precision_statement()?)));
        }
        if self.at_kw(Kw::Invariant) && matches!(self.peek_at(1).tok, Tok::Ident(_)) {
            return Ok(Some(ExternalDecl::Declaration(self.invariant_statement()?)));
        }
        let qualifiers = self.qualifiers()?;
        // Interface block: `uniform Name {`.
        if !qualifiers.is_empty() {
            if let Tok::Ident(name) = self.tok().clone() {
                if self.peek_at(1).tok == Tok::P(Punct::LeftBrace) && !self.is_type_name(&name) {
                    return Ok(Some(ExternalDecl::Declaration(
                        self.block(qualifiers, start)?,
                    )));
                }
            }
            if self.at(Punct::Semicolon) {
                self.bump();
                return Ok(Some(ExternalDecl::Declaration(Declaration::Qualifiers {
                    qualifiers,
                    span: self.span_from(start),
                })));
            }
        }
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        if let Tok::Ident(_) | Tok::Reserved(_) = self.tok() {
            if self.peek_at(1).tok == Tok::P(Punct::LeftParen) {
                let name = self.ident("a function name")?;
                return self.function(ty, name, start).map(Some);
            }
        }
        let decl = self.declarators(ty, start)?;
        Ok(Some(ExternalDecl::Declaration(decl)))
    }

    fn precision_statement(&mut self) -> PResult<Declaration> {
        let start = self.bump().span;
        let precision = match self.tok() {
            Tok::Kw(Kw::Lowp) => Precision::Low,
            Tok::Kw(Kw::Mediump) => Precision::Medium,
            Tok::Kw(Kw::Highp) => Precision::High,
            _ => return Err(self.expected("`lowp`, `mediump` or `highp`")),
        };
        self.bump();
        let ty = self.type_spec()?;
        self.expect_semicolon("the `precision` statement")?;
        Ok(Declaration::Precision {
            precision,
            ty,
            span: self.span_from(start),
        })
    }

    fn invariant_statement(&mut self) -> PResult<Declaration> {
        let start = self.bump().span;
        let mut names = vec![self.ident("a variable name")?];
        while self.eat(Punct::Comma) {
            names.push(self.ident("a variable name")?);
        }
        self.expect_semicolon("the `invariant` declaration")?;
        Ok(Declaration::Invariant {
            names,
            span: self.span_from(start),
        })
    }

    /// Parses qualifiers in any order (the checker enforces ES 3.00's order).
    fn qualifiers(&mut self) -> PResult<Vec<(Qualifier, Span)>> {
        let mut out = Vec::new();
        loop {
            let t = self.peek().clone();
            let q = match &t.tok {
                Tok::Kw(Kw::Const) => Qualifier::Storage(Storage::Const),
                Tok::Kw(Kw::In) => Qualifier::Storage(Storage::In),
                Tok::Kw(Kw::Out) => Qualifier::Storage(Storage::Out),
                Tok::Kw(Kw::Inout) => Qualifier::Storage(Storage::Inout),
                Tok::Kw(Kw::Uniform) => Qualifier::Storage(Storage::Uniform),
                Tok::Kw(Kw::Centroid) => Qualifier::Centroid,
                Tok::Kw(Kw::Flat) => Qualifier::Interpolation(Interpolation::Flat),
                Tok::Kw(Kw::Smooth) => Qualifier::Interpolation(Interpolation::Smooth),
                Tok::Kw(Kw::Invariant) => Qualifier::Invariant,
                Tok::Kw(Kw::Lowp) => Qualifier::Precision(Precision::Low),
                Tok::Kw(Kw::Mediump) => Qualifier::Precision(Precision::Medium),
                Tok::Kw(Kw::Highp) => Qualifier::Precision(Precision::High),
                Tok::Kw(Kw::Layout) => {
                    self.bump();
                    let open = self.expect(Punct::LeftParen)?;
                    let mut items = Vec::new();
                    loop {
                        let name = self.ident("a layout qualifier")?;
                        let value = if self.eat(Punct::Equal) {
                            Some(self.unary()?)
                        } else {
                            None
                        };
                        items.push(LayoutItem { name, value });
                        if !self.eat(Punct::Comma) {
                            break;
                        }
                    }
                    self.expect_close(Punct::RightParen, open)?;
                    out.push((Qualifier::Layout(items), self.span_from(t.span)));
                    continue;
                }
                Tok::Reserved(name) if &**name == "attribute" || &**name == "varying" => {
                    // ES 1.00 qualifiers: report once, then read them as their ES 3.00 twins.
                    let replacement = match (&**name, self.stage) {
                        ("attribute", _) | ("varying", Stage::Fragment) => "in",
                        _ => "out",
                    };
                    let d = Diagnostic::error(
                        "es100-qualifier",
                        format!("`{name}` is GLSL ES 1.00 and is reserved in GLSL ES 3.00"),
                        t.span,
                    )
                    .with_label("not a qualifier in GLSL ES 3.00")
                    .with_fix(Fix::certain(
                        format!("write `{replacement}`"),
                        t.span,
                        replacement,
                    ))
                    .with_token(&**name);
                    if !self.suppress {
                        self.push_diag(d);
                    }
                    Qualifier::Storage(if replacement == "in" {
                        Storage::In
                    } else {
                        Storage::Out
                    })
                }
                _ => break,
            };
            self.bump();
            out.push((q, t.span));
        }
        Ok(out)
    }

    /// Parses a type specifier: a type keyword, a struct name or a struct definition, with an
    /// optional array size.
    fn type_spec(&mut self) -> PResult<TypeSpec> {
        let t = self.peek().clone();
        let name = match &t.tok {
            Tok::Kw(Kw::Struct) => TypeName::Struct(Arc::new(self.struct_decl()?)),
            Tok::Kw(k) => match type_keyword(*k) {
                Some(n) => {
                    self.bump();
                    n
                }
                None => return Err(self.expected("a type")),
            },
            Tok::Ident(name) if self.is_type_name(name) => {
                self.bump();
                TypeName::Named(Ident {
                    name: name.clone(),
                    span: t.span,
                })
            }
            Tok::Ident(name) => {
                let d = Diagnostic::error("unknown-type", format!("unknown type `{name}`"), t.span)
                    .with_label("not a type")
                    .with_token(&**name);
                let d = match &**name {
                    "sampler" | "texture2D" => d,
                    "half" | "double" => d.with_help("use `float`"),
                    _ => d.with_help("declare the struct before this line, or use a built-in type"),
                };
                self.report(d);
                return Err(Failed);
            }
            Tok::Reserved(name) => {
                self.bump();
                self.reserved_word(&name.clone(), t.span);
                self.suppress = true;
                return Err(Failed);
            }
            _ => return Err(self.expected("a type")),
        };
        let array = if self.at(Punct::LeftBracket) {
            Some(self.array_size()?)
        } else {
            None
        };
        Ok(TypeSpec {
            name,
            array,
            span: self.span_from(t.span),
        })
    }

    fn array_size(&mut self) -> PResult<ArraySize> {
        let open = self.expect(Punct::LeftBracket)?;
        let size = if self.at(Punct::RightBracket) {
            None
        } else {
            Some(Box::new(self.conditional()?))
        };
        self.expect_close(Punct::RightBracket, open)?;
        Ok(ArraySize {
            size,
            span: self.span_from(open),
        })
    }

    fn struct_decl(&mut self) -> PResult<StructDecl> {
        let start = self.bump().span; // `struct`
        let name = match self.tok() {
            Tok::Ident(_) | Tok::Reserved(_) => Some(self.ident("a struct name")?),
            _ => None,
        };
        let open = self.expect(Punct::LeftBrace)?;
        let members = self.member_list(open)?;
        if let Some(n) = &name {
            self.type_names
                .last_mut()
                .expect("scope")
                .insert(n.name.clone());
        }
        Ok(StructDecl {
            name,
            members,
            span: self.span_from(start),
        })
    }

    /// Member declarations up to and including the closing `}`.
    fn member_list(&mut self, open: Span) -> PResult<Vec<MemberDecl>> {
        let mut members = Vec::new();
        while !self.at(Punct::RightBrace) && !self.at_eof() {
            let start = self.peek().span;
            let qualifiers = self.qualifiers()?;
            let spec = self.type_spec()?;
            let ty = FullType {
                span: start.to(spec.span),
                qualifiers,
                spec,
            };
            let mut names = Vec::new();
            loop {
                let n = self.ident("a member name")?;
                let a = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                names.push((n, a));
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
            self.expect_semicolon("the member declaration")?;
            members.push(MemberDecl {
                ty: Box::new(FullTypeEq(ty)),
                names,
                span: self.span_from(start),
            });
        }
        self.expect_close(Punct::RightBrace, open)?;
        Ok(members)
    }

    fn block(&mut self, qualifiers: Vec<(Qualifier, Span)>, start: Span) -> PResult<Declaration> {
        let name = self.ident("a block name")?;
        let open = self.expect(Punct::LeftBrace)?;
        let members = self.member_list(open)?;
        let instance = match self.tok() {
            Tok::Ident(_) | Tok::Reserved(_) => {
                let n = self.ident("an instance name")?;
                let a = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                Some((n, a))
            }
            _ => None,
        };
        self.expect_semicolon("the uniform block")?;
        Ok(Declaration::Block {
            qualifiers,
            name,
            members,
            instance,
            span: self.span_from(start),
        })
    }

    /// `name [array] [= init], …;` after a type; an empty list declares only a struct.
    fn declarators(&mut self, ty: FullType, start: Span) -> PResult<Declaration> {
        let mut declarators = Vec::new();
        if !self.at(Punct::Semicolon) {
            loop {
                let name = self.ident("a variable name")?;
                let array = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                let init = if self.eat(Punct::Equal) {
                    match self.assignment() {
                        Ok(e) => Some(e),
                        Err(Failed) => {
                            // Keep the variable, so later uses of it are not reported as
                            // undeclared (no cascade), and skip the rest of the statement.
                            let span = self.span_from(name.span);
                            declarators.push(Declarator {
                                span,
                                name,
                                array,
                                init: Some(Expr {
                                    kind: ExprKind::Error,
                                    span,
                                }),
                            });
                            self.synchronize();
                            return Ok(Declaration::Variables {
                                ty,
                                declarators,
                                span: self.span_from(start),
                            });
                        }
                    }
                } else {
                    None
                };
                declarators.push(Declarator {
                    span: self.span_from(name.span),
                    name,
                    array,
                    init,
                });
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_semicolon("the declaration")?;
        Ok(Declaration::Variables {
            ty,
            declarators,
            span: self.span_from(start),
        })
    }

    fn function(&mut self, ret: FullType, name: Ident, start: Span) -> PResult<ExternalDecl> {
        let open = self.expect(Punct::LeftParen)?;
        let mut params = Vec::new();
        if self.at_kw(Kw::Void) && self.peek_at(1).tok == Tok::P(Punct::RightParen) {
            self.bump();
        } else if !self.at(Punct::RightParen) {
            loop {
                params.push(self.param()?);
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_close(Punct::RightParen, open)?;
        let proto = FunctionProto {
            ret,
            name,
            params,
            span: self.span_from(start),
        };
        if self.at(Punct::LeftBrace) {
            self.push_scope();
            let body = self.block_stmts();
            self.pop_scope();
            let body = body?;
            Ok(ExternalDecl::Function(FunctionDef { proto, body }))
        } else {
            self.expect_semicolon("the function prototype")?;
            Ok(ExternalDecl::Prototype(proto))
        }
    }

    fn param(&mut self) -> PResult<Param> {
        let start = self.peek().span;
        let qualifiers = self.qualifiers()?;
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        let name = match self.tok() {
            Tok::Ident(_) | Tok::Reserved(_) => Some(self.ident("a parameter name")?),
            _ => None,
        };
        let array = if name.is_some() && self.at(Punct::LeftBracket) {
            Some(self.array_size()?)
        } else {
            None
        };
        Ok(Param {
            ty,
            name,
            array,
            span: self.span_from(start),
        })
    }

    // ----- statements -----

    /// `{ statements }` — the caller manages the scope.
    fn block_stmts(&mut self) -> PResult<Block> {
        let open = self.expect(Punct::LeftBrace)?;
        let mut stmts = Vec::new();
        while !self.at(Punct::RightBrace) && !self.at_eof() {
            let before = self.pos;
            match self.statement() {
                Ok(s) => stmts.push(s),
                Err(Failed) => {
                    self.synchronize();
                    stmts.push(Stmt {
                        kind: StmtKind::Error,
                        span: self.span_from(self.toks[before].span),
                    });
                }
            }
            if self.pos == before {
                let t = self.bump();
                self.report(
                    Diagnostic::error(
                        "syntax-error",
                        format!("unexpected {}", Self::describe(&t)),
                        t.span,
                    )
                    .with_label("not expected here")
                    .with_token(&*t.text),
                );
                self.synchronize();
            }
        }
        self.expect_close(Punct::RightBrace, open)?;
        Ok(Block {
            stmts,
            span: self.span_from(open),
        })
    }

    /// Whether the tokens ahead start a declaration (not an expression).
    fn at_declaration(&self) -> bool {
        match self.tok() {
            Tok::Kw(k) if is_qualifier_kw(*k) || *k == Kw::Struct || *k == Kw::Precision => true,
            Tok::Reserved(r) if &**r == "attribute" || &**r == "varying" => true,
            Tok::Kw(k) if type_keyword(*k).is_some() => self.type_then_name(),
            Tok::Ident(n) if self.is_type_name(n) => self.type_then_name(),
            _ => false,
        }
    }

    /// After a type name: an identifier (declaration) rather than `(` (constructor). Skips a
    /// bracketed array size.
    fn type_then_name(&self) -> bool {
        let mut i = 1;
        if self.peek_at(1).tok == Tok::P(Punct::LeftBracket) {
            let mut depth = 0;
            loop {
                match &self.peek_at(i).tok {
                    Tok::P(Punct::LeftBracket) => depth += 1,
                    Tok::P(Punct::RightBracket) => {
                        depth -= 1;
                        if depth == 0 {
                            i += 1;
                            break;
                        }
                    }
                    Tok::Eof | Tok::P(Punct::Semicolon) => return true,
                    _ => {}
                }
                i += 1;
            }
        }
        !matches!(
            self.peek_at(i).tok,
            Tok::P(Punct::LeftParen) | Tok::P(Punct::Dot)
        )
    }

    fn statement(&mut self) -> PResult<Stmt> {
        self.enter()?;
        let r = self.statement_inner();
        self.leave();
        r
    }

    fn statement_inner(&mut self) -> PResult<Stmt> {
        let start = self.peek().span;
        let kind = match self.tok().clone() {
            Tok::P(Punct::LeftBrace) => {
                self.push_scope();
                let b = self.block_stmts();
                self.pop_scope();
                StmtKind::Block(b?)
            }
            Tok::P(Punct::Semicolon) => {
                self.bump();
                StmtKind::Empty
            }
            Tok::Kw(Kw::If) => {
                self.bump();
                let open = self.expect(Punct::LeftParen)?;
                let cond = self.expr()?;
                self.expect_close(Punct::RightParen, open)?;
                let then = self.scoped_statement()?;
                let els = if self.eat_kw(Kw::Else) {
                    Some(Box::new(self.scoped_statement()?))
                } else {
                    None
                };
                StmtKind::If(cond, Box::new(then), els)
            }
            Tok::Kw(Kw::Switch) => {
                self.bump();
                let open = self.expect(Punct::LeftParen)?;
                let e = self.expr()?;
                self.expect_close(Punct::RightParen, open)?;
                self.push_scope();
                let body = self.block_stmts();
                self.pop_scope();
                StmtKind::Switch(e, body?)
            }
            Tok::Kw(Kw::Case) => {
                self.bump();
                let e = self.expr()?;
                self.expect(Punct::Colon)?;
                StmtKind::Case(e)
            }
            Tok::Kw(Kw::Default) => {
                self.bump();
                self.expect(Punct::Colon)?;
                StmtKind::Default
            }
            Tok::Kw(Kw::While) => {
                self.bump();
                let open = self.expect(Punct::LeftParen)?;
                self.push_scope();
                let r = (|| {
                    let cond = self.condition()?;
                    self.expect_close(Punct::RightParen, open)?;
                    let body = self.statement_no_new_scope()?;
                    Ok(StmtKind::While(cond, Box::new(body)))
                })();
                self.pop_scope();
                r?
            }
            Tok::Kw(Kw::Do) => {
                self.bump();
                let body = self.scoped_statement()?;
                if !self.eat_kw(Kw::While) {
                    return Err(self.expected("`while` after the body of `do`"));
                }
                let open = self.expect(Punct::LeftParen)?;
                let cond = self.expr()?;
                self.expect_close(Punct::RightParen, open)?;
                self.expect_semicolon("the `do`-`while` loop")?;
                StmtKind::DoWhile(Box::new(body), cond)
            }
            Tok::Kw(Kw::For) => {
                self.bump();
                let open = self.expect(Punct::LeftParen)?;
                self.push_scope();
                let r = (|| {
                    let init_start = self.peek().span;
                    let init = if self.at(Punct::Semicolon) {
                        self.bump();
                        Stmt {
                            kind: StmtKind::Empty,
                            span: init_start,
                        }
                    } else if self.at_declaration() {
                        let d = self.local_declaration()?;
                        Stmt {
                            kind: StmtKind::Decl(d),
                            span: self.span_from(init_start),
                        }
                    } else {
                        let e = self.expr()?;
                        self.expect(Punct::Semicolon)?;
                        Stmt {
                            kind: StmtKind::Expr(e),
                            span: self.span_from(init_start),
                        }
                    };
                    let cond = if self.at(Punct::Semicolon) {
                        None
                    } else {
                        Some(self.condition()?)
                    };
                    self.expect(Punct::Semicolon)?;
                    let step = if self.at(Punct::RightParen) {
                        None
                    } else {
                        Some(self.expr()?)
                    };
                    self.expect_close(Punct::RightParen, open)?;
                    let body = self.statement_no_new_scope()?;
                    Ok(StmtKind::For {
                        init: Box::new(init),
                        cond,
                        step,
                        body: Box::new(body),
                    })
                })();
                self.pop_scope();
                r?
            }
            Tok::Kw(Kw::Continue) => {
                self.bump();
                self.expect_semicolon("`continue`")?;
                StmtKind::Continue
            }
            Tok::Kw(Kw::Break) => {
                self.bump();
                self.expect_semicolon("`break`")?;
                StmtKind::Break
            }
            Tok::Kw(Kw::Discard) => {
                self.bump();
                self.expect_semicolon("`discard`")?;
                StmtKind::Discard
            }
            Tok::Kw(Kw::Return) => {
                self.bump();
                let e = if self.at(Punct::Semicolon) {
                    None
                } else {
                    Some(self.expr()?)
                };
                self.expect_semicolon("the `return` statement")?;
                StmtKind::Return(e)
            }
            _ if self.at_declaration() => StmtKind::Decl(self.local_declaration()?),
            _ => {
                let e = self.expr()?;
                self.expect_semicolon("the expression")?;
                StmtKind::Expr(e)
            }
        };
        Ok(Stmt {
            kind,
            span: self.span_from(start),
        })
    }

    /// A sub-statement of `if`/`else`/`do`: a scope of its own.
    fn scoped_statement(&mut self) -> PResult<Stmt> {
        self.push_scope();
        let s = self.statement();
        self.pop_scope();
        s
    }

    /// A loop body: shares the scope the loop's header opened (ES 3.00: the body of a `for` or
    /// `while` with a compound statement does not open a new scope for redeclaring the
    /// loop variable).
    fn statement_no_new_scope(&mut self) -> PResult<Stmt> {
        self.statement()
    }

    fn condition(&mut self) -> PResult<Condition> {
        if self.at_declaration() {
            let start = self.peek().span;
            let qualifiers = self.qualifiers()?;
            let spec = self.type_spec()?;
            let ty = FullType {
                span: start.to(spec.span),
                qualifiers,
                spec,
            };
            let name = self.ident("a variable name")?;
            self.expect(Punct::Equal)?;
            let init = self.assignment()?;
            Ok(Condition::Decl(ty, name, init))
        } else {
            Ok(Condition::Expr(self.expr()?))
        }
    }

    fn local_declaration(&mut self) -> PResult<Declaration> {
        let start = self.peek().span;
        if self.at_kw(Kw::Precision) {
            return self.precision_statement();
        }
        if self.at_kw(Kw::Invariant) && matches!(self.peek_at(1).tok, Tok::Ident(_)) {
            return self.invariant_statement();
        }
        let qualifiers = self.qualifiers()?;
        if !qualifiers.is_empty() {
            if let Tok::Ident(name) = self.tok().clone() {
                if self.peek_at(1).tok == Tok::P(Punct::LeftBrace) && !self.is_type_name(&name) {
                    return self.block(qualifiers, start);
                }
            }
        }
        let spec = self.type_spec()?;
        let ty = FullType {
            span: start.to(spec.span),
            qualifiers,
            spec,
        };
        if let (Tok::Ident(_), Tok::P(Punct::LeftParen)) = (self.tok(), &self.peek_at(1).tok) {
            let name = self.ident("a function name")?;
            let d = Diagnostic::error(
                "nested-function",
                format!(
                    "function `{}` is declared inside another function",
                    name.name
                ),
                name.span,
            )
            .with_label("functions can only be declared at global scope")
            .with_token(&*name.name);
            self.report(d);
            return Err(Failed);
        }
        self.declarators(ty, start)
    }

    // ----- expressions -----

    fn expr(&mut self) -> PResult<Expr> {
        let mut e = self.assignment()?;
        while self.at(Punct::Comma) {
            self.bump();
            let rhs = self.assignment()?;
            let span = e.span.to(rhs.span);
            e = Expr {
                kind: ExprKind::Comma(Box::new(e), Box::new(rhs)),
                span,
            };
        }
        Ok(e)
    }

    fn assignment(&mut self) -> PResult<Expr> {
        self.enter()?;
        let r = self.assignment_inner();
        self.leave();
        r
    }

    fn assignment_inner(&mut self) -> PResult<Expr> {
        let lhs = self.conditional()?;
        if let Tok::P(p) = self.tok() {
            if let Some(op) = assign_op(*p) {
                self.bump();
                let rhs = self.assignment()?;
                let span = lhs.span.to(rhs.span);
                return Ok(Expr {
                    kind: ExprKind::Assign(op, Box::new(lhs), Box::new(rhs)),
                    span,
                });
            }
        }
        Ok(lhs)
    }

    fn conditional(&mut self) -> PResult<Expr> {
        let c = self.binary(0)?;
        if self.at(Punct::Question) {
            self.bump();
            let a = self.expr()?;
            self.expect(Punct::Colon)?;
            let b = self.assignment()?;
            let span = c.span.to(b.span);
            return Ok(Expr {
                kind: ExprKind::Ternary(Box::new(c), Box::new(a), Box::new(b)),
                span,
            });
        }
        Ok(c)
    }

    fn binary(&mut self, min_prec: u8) -> PResult<Expr> {
        let mut lhs = self.unary()?;
        // Each operator of a left-associative chain deepens the tree by one level, which
        // counts as nesting (later passes recurse over the tree).
        let mut chain = 0;
        let result = loop {
            let Tok::P(p) = self.tok() else { break Ok(()) };
            let Some((op, prec)) = binary_op(*p) else {
                break Ok(());
            };
            if prec <= min_prec {
                break Ok(());
            }
            self.bump();
            if let Err(f) = self.enter() {
                break Err(f);
            }
            chain += 1;
            let rhs = match self.binary(prec) {
                Ok(r) => r,
                Err(f) => break Err(f),
            };
            let span = lhs.span.to(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        };
        for _ in 0..chain {
            self.leave();
        }
        result.map(|_| lhs)
    }

    fn unary(&mut self) -> PResult<Expr> {
        let t = self.peek().clone();
        let op = match t.tok {
            Tok::P(Punct::Plus) => Some(UnaryOp::Plus),
            Tok::P(Punct::Minus) => Some(UnaryOp::Neg),
            Tok::P(Punct::Bang) => Some(UnaryOp::Not),
            Tok::P(Punct::Tilde) => Some(UnaryOp::BitNot),
            Tok::P(Punct::PlusPlus) => Some(UnaryOp::PreInc),
            Tok::P(Punct::MinusMinus) => Some(UnaryOp::PreDec),
            _ => None,
        };
        if let Some(op) = op {
            self.bump();
            self.enter()?;
            let e = self.unary();
            self.leave();
            let e = e?;
            let span = t.span.to(e.span);
            return Ok(Expr {
                kind: ExprKind::Unary(op, Box::new(e)),
                span,
            });
        }
        let p = self.primary()?;
        self.postfix(p)
    }

    fn postfix(&mut self, e: Expr) -> PResult<Expr> {
        // Each postfix operator deepens the tree by one level, which counts as nesting.
        let mut applied = 0;
        let r = self.postfix_ops(e, &mut applied);
        for _ in 0..applied {
            self.leave();
        }
        r
    }

    fn postfix_ops(&mut self, mut e: Expr, applied: &mut u32) -> PResult<Expr> {
        loop {
            if matches!(
                self.tok(),
                Tok::P(Punct::LeftBracket | Punct::Dot | Punct::PlusPlus | Punct::MinusMinus)
            ) {
                self.enter()?;
                *applied += 1;
            }
            match self.tok() {
                Tok::P(Punct::LeftBracket) => {
                    let open = self.bump().span;
                    let i = self.expr()?;
                    self.expect_close(Punct::RightBracket, open)?;
                    let span = self.span_from(e.span);
                    e = Expr {
                        kind: ExprKind::Index(Box::new(e), Box::new(i)),
                        span,
                    };
                }
                Tok::P(Punct::Dot) => {
                    self.bump();
                    let name = match self.tok().clone() {
                        // `v.length()` and swizzles/members named like keywords are not a thing,
                        // but give a clear message.
                        Tok::Ident(_) | Tok::Reserved(_) => self.ident("a field name")?,
                        _ => return Err(self.expected("a field name or swizzle after `.`")),
                    };
                    if &*name.name == "length" && self.at(Punct::LeftParen) {
                        let open = self.bump().span;
                        self.expect_close(Punct::RightParen, open)?;
                        let span = self.span_from(e.span);
                        e = Expr {
                            kind: ExprKind::Call(Callee::Length(Box::new(e)), Vec::new()),
                            span,
                        };
                    } else if self.at(Punct::LeftParen) {
                        let d = Diagnostic::error(
                            "method-call",
                            format!(
                                "`{}` is not a method: GLSL ES 3.00 has only `.length()`",
                                name.name
                            ),
                            name.span,
                        )
                        .with_label("no such method")
                        .with_token(&*name.name);
                        self.report(d);
                        return Err(Failed);
                    } else {
                        let span = e.span.to(name.span);
                        e = Expr {
                            kind: ExprKind::Field(Box::new(e), name),
                            span,
                        };
                    }
                }
                Tok::P(Punct::PlusPlus) => {
                    let s = self.bump().span;
                    let span = e.span.to(s);
                    e = Expr {
                        kind: ExprKind::Unary(UnaryOp::PostInc, Box::new(e)),
                        span,
                    };
                }
                Tok::P(Punct::MinusMinus) => {
                    let s = self.bump().span;
                    let span = e.span.to(s);
                    e = Expr {
                        kind: ExprKind::Unary(UnaryOp::PostDec, Box::new(e)),
                        span,
                    };
                }
                _ => return Ok(e),
            }
        }
    }

    fn call_args(&mut self) -> PResult<Vec<Expr>> {
        let open = self.expect(Punct::LeftParen)?;
        let mut args = Vec::new();
        if self.at_kw(Kw::Void) && self.peek_at(1).tok == Tok::P(Punct::RightParen) {
            self.bump();
        } else if !self.at(Punct::RightParen) {
            loop {
                args.push(self.assignment()?);
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_close(Punct::RightParen, open)?;
        Ok(args)
    }

    fn primary(&mut self) -> PResult<Expr> {
        let t = self.peek().clone();
        let kind = match &t.tok {
            Tok::Int(v, u) => {
                self.bump();
                ExprKind::Int(*v, *u)
            }
            Tok::Float(f) => {
                self.bump();
                ExprKind::Float(*f)
            }
            Tok::Kw(Kw::True) => {
                self.bump();
                ExprKind::Bool(true)
            }
            Tok::Kw(Kw::False) => {
                self.bump();
                ExprKind::Bool(false)
            }
            Tok::P(Punct::LeftParen) => {
                let open = self.bump().span;
                let e = self.expr()?;
                let close = self.expect_close(Punct::RightParen, open)?;
                return Ok(Expr {
                    kind: e.kind,
                    span: open.to(close),
                });
            }
            Tok::Ident(name) if self.is_type_name(name) => {
                let spec = self.type_spec()?;
                if !self.at(Punct::LeftParen) {
                    return Err(self.expected("`(` after a type name (a constructor)"));
                }
                let args = self.call_args()?;
                match spec.array {
                    None => {
                        let TypeName::Named(id) = spec.name else {
                            unreachable!()
                        };
                        ExprKind::Call(Callee::Name(id), args)
                    }
                    Some(_) => ExprKind::Call(Callee::Type(spec), args),
                }
            }
            Tok::Ident(_) | Tok::Reserved(_) => {
                let id = self.ident("an expression")?;
                if self.at(Punct::LeftParen) {
                    let args = self.call_args()?;
                    ExprKind::Call(Callee::Name(id), args)
                } else {
                    ExprKind::Ident(id)
                }
            }
            Tok::Kw(Kw::Struct) => {
                let d = Diagnostic::error(
                    "syntax-error",
                    "a struct cannot be defined inside an expression",
                    t.span,
                )
                .with_label("not expected here")
                .with_token("struct");
                self.report(d);
                return Err(Failed);
            }
            Tok::Kw(k) if type_keyword(*k).is_some() => {
                let spec = self.type_spec()?;
                if !self.at(Punct::LeftParen) {
                    return Err(self.expected("`(` after a type name (a constructor)"));
                }
                let args = self.call_args()?;
                ExprKind::Call(Callee::Type(spec), args)
            }
            _ => return Err(self.expected("an expression")),
        };
        Ok(Expr {
            kind,
            span: self.span_from(t.span),
        })
    }
}
