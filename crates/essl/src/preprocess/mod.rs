//! The GLSL ES preprocessor (1.00 and 3.00): directives, conditionals and macro expansion.
//!
//! Input: the lexer's tokens. Output: the tokens the parser sees (no newlines, ending with one
//! `Eof`), each with a span into the original text; a token produced by a macro expansion
//! carries the span of the macro's invocation (its name, or the whole `NAME(args)`; for nested
//! expansions the outermost invocation in the text) and `from_macro = true`. Arguments
//! substituted into a replacement list keep their own spans, where they are written in the
//! text (an argument written inside another macro's replacement list has that macro's
//! invocation span): an expression inside `saturate(…)` is reported where it is written.
//!
//! Rules follow the GLSL ES 3.00 specification (section 3.4) as WebGL2 implementations
//! (ANGLE) apply them and as the dEQP and WebGL conformance tests check them:
//!
//! - `#version 300 es` must be the first thing in the shader and on its first line (comments and
//!   white space may precede it on that line). Without it (or with `#version 100`) a WebGL
//!   shader is GLSL ES 1.00. Any other version is an error, and so is `#version 300 es` for a
//!   WebGL 1 context.
//! - Every identifier and number, wherever it is (a directive, a skipped group), may be at most
//!   as long as the target allows ([`Target::max_token_len`]: 256 characters in WebGL 1, 1024 in
//!   WebGL 2), as ANGLE's tokenizer checks it.
//! - Directives in skipped groups are ignored, except the conditional ones, which only track
//!   nesting. Invalid characters, stray `#` and everything else in skipped groups are ignored.
//! - `#if` expressions: 32-bit integers, C precedence, short-circuit `&&` and `||`; an
//!   identifier left after macro expansion (an undefined macro) is an error where evaluated, so
//!   are division by zero and shifts outside 0..=31; `defined` coming out of a macro expansion
//!   is an error.
//! - Macro names starting with `GL_`, and `defined`, are reserved (error); names containing `__`
//!   are allowed with a warning; predefined macros (`__LINE__`, `__FILE__`, `__VERSION__`,
//!   `GL_ES`, `GL_FRAGMENT_PRECISION_HIGH`, supported extensions) cannot be redefined or
//!   undefined. A redefinition must be identical (same parameters, same tokens, same white-space
//!   separation).
//! - `#extension` must come before any code; `all` only takes `warn` or `disable`; an extension
//!   not in [`PreprocessOptions::extensions`] is an error with `require` and a warning otherwise.
//!   `#extension` and `#pragma` lines are not macro-expanded; `#if`, `#elif` and `#line` are.
//! - `#line L [S]` takes integer expressions: the line after the directive is line `L`, and
//!   `__FILE__` is `S` from there on (see [`Preprocessed::presumed_line`]).
//! - Invalid characters and `#`/`##` that reach the parser are errors (a `#define` may hold
//!   them as long as it is not used: `##` there gets a warning, since GLSL has no token pasting).
//!   Invalid characters stay in the output (the parser takes them as already reported errors);
//!   `#` and `##` are dropped.
//!
//! Every error is reported with recovery (a bad directive is skipped to the end of its line).
//! The work is linear in the input plus the tokens macros produce, which is bounded.

mod defined;
mod directive;
mod expand;
mod expr;

use crate::diagnostic_code::Code;
use crate::Name;

use crate::diagnostic::{self, Diagnostic, Fix};
use crate::lex::{Lexed, PpKind, PpToken, Punct};
use crate::source::{SourceFile, Span};
use crate::target::{Extension, Target};
use crate::Stage;

use expand::{Dynamic, Expander, Tok};

/// Options of the preprocessor.
#[derive(Clone, Debug, Default)]
pub struct PreprocessOptions {
    /// Macros defined before the first line, as `(name, replacement text)` (like `-DNAME=VALUE`;
    /// `name` may be `F(a,b)` for a function-like macro). The shader may redefine them: a
    /// different `#define` replaces the option's value with a warning (`option-macro-redefined`),
    /// and `#undef` removes them.
    pub defines: Vec<(String, String)>,
    /// Extensions the consumer implements (`GL_OVR_multiview2`, …). Each is predefined as a
    /// macro with value 1 and may be required or enabled. Others are unsupported: `require` is an
    /// error, `enable`/`warn`/`disable` a warning. Empty by default.
    pub extensions: Vec<String>,
    /// The shader's stage, where known: `#pragma STDGL invariant(all)` is an error in a GLSL ES
    /// 3.00 fragment shader.
    pub stage: Option<Stage>,
    /// The WebGL version: the versions it accepts and the longest token.
    pub target: Target,
}

impl PreprocessOptions {
    /// The extension macros a target's context defines: the directive names of the extensions
    /// it enabled that it offers (a WebGL 2 context defines none of WebGL 1's).
    pub fn extension_macros(target: Target, enabled: &[Extension]) -> Vec<String> {
        enabled
            .iter()
            .filter(|e| e.offered_by(target))
            .map(|e| e.directive_name().to_string())
            .collect()
    }
}

/// The language version a shader declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Version {
    /// `#version 300 es` on the first line.
    Es300,
    /// No `#version` on the first line: GLSL ES 1.00.
    Es100,
    /// Another `#version` (e.g. `310 es`, `330`): the number and whether `es` followed.
    Other(u32, bool),
}

impl Version {
    /// The version number (`__VERSION__`).
    pub fn number(self) -> u32 {
        match self {
            Version::Es300 => 300,
            Version::Es100 => 100,
            Version::Other(n, _) => n,
        }
    }

    fn from_parts(n: u32, es: bool) -> Version {
        match (n, es) {
            (300, true) => Version::Es300,
            (100, false) => Version::Es100,
            _ => Version::Other(n, es),
        }
    }
}

/// An `#extension` directive's behaviour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExtensionBehavior {
    /// `require`
    Require,
    /// `enable`
    Enable,
    /// `warn`
    Warn,
    /// `disable`
    Disable,
}

impl ExtensionBehavior {
    /// The behaviour's name.
    pub fn as_str(self) -> &'static str {
        match self {
            ExtensionBehavior::Require => "require",
            ExtensionBehavior::Enable => "enable",
            ExtensionBehavior::Warn => "warn",
            ExtensionBehavior::Disable => "disable",
        }
    }

    fn from_str(s: &str) -> Option<ExtensionBehavior> {
        Some(match s {
            "require" => ExtensionBehavior::Require,
            "enable" => ExtensionBehavior::Enable,
            "warn" => ExtensionBehavior::Warn,
            "disable" => ExtensionBehavior::Disable,
            _ => return None,
        })
    }
}

/// A valid `#line` directive.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LineDirective {
    /// The directive, from `#` to its last token.
    pub span: Span,
    /// Byte offset where the renumbered line (the one after the directive) starts.
    pub next_line_start: u32,
    /// The number that line gets.
    pub line: i64,
    /// The source string number, if the directive gives one.
    pub source: Option<i64>,
    /// The source string number from here on (`source`, or the previous one; 0 at first).
    pub source_string: i64,
}

/// What the preprocessor produced.
#[derive(Debug)]
pub struct Preprocessed {
    /// Tokens for the parser: no `Newline`, exactly one final `Eof`.
    pub tokens: Vec<PpToken>,
    /// The version the shader is compiled as, as WebGL decides it: `Es300` only for a valid
    /// `#version 300 es` on the first line; `Es100` without a valid, well-placed `#version`
    /// (missing, misplaced or malformed: each is an error); `Other` for another number.
    pub version: Version,
    /// Span of the first `#version` directive, if any (also when it is misplaced).
    pub version_span: Option<Span>,
    /// What that `#version` directive says, where its number could be read (also when it is
    /// misplaced or malformed and `version` is therefore `Es100`).
    pub declared_version: Option<Version>,
    /// `#extension NAME : behavior` directives in order, with their spans: the well-formed ones
    /// that come before any code (supported or not).
    pub extensions: Vec<(String, ExtensionBehavior, Span)>,
    /// `#pragma STDGL invariant(all)` was given.
    pub invariant_all: bool,
    /// Where that pragma is (the first one).
    pub invariant_all_span: Option<Span>,
    /// Valid `#line` directives, in order.
    pub line_directives: Vec<LineDirective>,
    /// Errors and warnings (the lexer's included), sorted by position.
    pub diagnostics: Vec<Diagnostic>,
    /// The invocations in the text of macros the shader defines, in order.
    pub expansions: Vec<Expansion>,
}

/// An invocation in the text of a macro the shader defines: its tokens' span (the replacement
/// list's tokens carry it) and where the macro is defined.
#[derive(Clone, Debug)]
pub struct Expansion {
    /// The invocation: the name, or the whole `NAME(args)`.
    pub invocation: Span,
    /// The macro's name.
    pub name: Name,
    /// The name in its `#define`.
    pub defined: Span,
}

impl Preprocessed {
    /// The source string number and line number that `__FILE__`/`__LINE__` and WebGL's info log
    /// give for a byte offset, after `#line` directives.
    pub fn presumed_line(&self, file: &SourceFile, offset: u32) -> (i64, i64) {
        presumed(&self.line_directives, file, offset)
    }
}

fn presumed(dirs: &[LineDirective], file: &SourceFile, offset: u32) -> (i64, i64) {
    let physical = file.line_of(offset) as i64;
    let i = dirs.partition_point(|d| d.next_line_start <= offset);
    match i.checked_sub(1).map(|i| &dirs[i]) {
        None => (0, physical),
        Some(d) => {
            let base = file.line_of(d.next_line_start) as i64;
            (d.source_string, d.line.wrapping_add(physical - base))
        }
    }
}

/// Preprocesses a lexed shader.
pub fn preprocess(file: &SourceFile, lexed: Lexed, options: &PreprocessOptions) -> Preprocessed {
    // Macro calls nested in arguments recurse (up to `MAX_ARGUMENT_NESTING` levels).
    crate::shader::with_stack(|| preprocess_here(file, lexed, options))
}

fn preprocess_here(file: &SourceFile, lexed: Lexed, options: &PreprocessOptions) -> Preprocessed {
    let Lexed {
        mut tokens,
        diagnostics,
    } = lexed;
    if tokens.last().is_none_or(|t| t.kind != PpKind::Eof) {
        let end = file.text().len() as u32;
        tokens.push(PpToken {
            kind: PpKind::Eof,
            span: Span::empty(end),
            text: Name::default(),
            space_before: false,
            from_macro: false,
        });
    }
    let mut pp = Pp::new(file, tokens, options);
    pp.check_token_lengths();
    pp.predefine();
    pp.run();
    pp.finish(diagnostics)
}

/// A conditional block (`#if` … `#endif`) being read.
#[derive(Debug)]
struct Cond {
    /// `#if`, `#ifdef` or `#ifndef` with its name.
    span: Span,
    /// Which of them.
    kind: &'static str,
    /// The `#else`, once read.
    else_span: Option<Span>,
    /// The whole block is inside a skipped group.
    skip_block: bool,
    /// The current group is skipped.
    skip_group: bool,
    /// A group was taken already.
    found_valid: bool,
}

/// The preprocessor's state.
pub(super) struct Pp<'a> {
    file: &'a SourceFile,
    options: &'a PreprocessOptions,
    toks: Vec<PpToken>,
    /// Next token of `toks`.
    pos: usize,
    /// `pos` is at the start of a logical line.
    line_start: bool,
    /// Offset where the current line begins, and the lines skipped by conditionals so far
    /// (where a no-break space is harmless, as in a comment).
    line_begin: u32,
    skipped_lines: Vec<Span>,
    macros: defined::Defined,
    conds: Vec<Cond>,
    diags: Vec<Diagnostic>,
    out: Vec<PpToken>,
    version: Version,
    version_span: Option<Span>,
    declared_version: Option<Version>,
    /// A directive or code was read (a `#version` now is misplaced).
    past_first: bool,
    /// Code (a non-directive token outside skipped groups) was read.
    seen_code: bool,
    extensions: Vec<(String, ExtensionBehavior, Span)>,
    invariant_all_span: Option<Span>,
    line_directives: Vec<LineDirective>,
    /// The invocations in the text of the shader's macros.
    expansions: Vec<Expansion>,
    /// Tokens produced by macro expansions so far, and the limit.
    expanded: usize,
    budget: usize,
    budget_reported: bool,
    context_tokens_reported: bool,
    depth_reported: bool,
    eof_reached: bool,
}

/// Tokens that macro expansions may produce in all, besides four per token of the text: far
/// above what real shaders expand to (the largest corpus shader expands to a few thousand), and
/// a bound on the memory that object-like macros expanding to several copies of each other can
/// take (they are not bounded by [`expand::MAX_CONTEXT_TOKENS`]).
pub const MAX_EXPANDED_TOKENS: usize = 500_000;

impl<'a> Pp<'a> {
    fn new(file: &'a SourceFile, toks: Vec<PpToken>, options: &'a PreprocessOptions) -> Pp<'a> {
        let budget = MAX_EXPANDED_TOKENS + 4 * toks.len();
        // Most shaders expand to about as many tokens as they have.
        let out = Vec::with_capacity(toks.len());
        Pp {
            file,
            options,
            toks,
            pos: 0,
            line_start: true,
            line_begin: 0,
            skipped_lines: Vec::new(),
            macros: defined::Defined::default(),
            conds: Vec::new(),
            diags: Vec::new(),
            out,
            version: Version::Es100,
            version_span: None,
            declared_version: None,
            past_first: false,
            seen_code: false,
            extensions: Vec::new(),
            invariant_all_span: None,
            line_directives: Vec::new(),
            expansions: Vec::new(),
            expanded: 0,
            budget,
            budget_reported: false,
            context_tokens_reported: false,
            depth_reported: false,
            eof_reached: false,
        }
    }

    /// Defines the predefined macros, the supported extensions and the options' defines.
    fn predefine(&mut self) {
        let predefined = [
            ("__LINE__", "0", Some(Dynamic::Line)),
            ("__FILE__", "0", Some(Dynamic::File)),
            ("__VERSION__", "100", None),
            ("GL_ES", "1", None),
            ("GL_FRAGMENT_PRECISION_HIGH", "1", None),
        ];
        // The predefined macros, the extensions, and room for a shader's first `#define`s.
        self.macros
            .reserve(predefined.len() + self.options.extensions.len() + 8);
        for (name, value, dynamic) in predefined {
            self.macros.predefine(name, value, dynamic);
        }
        for ext in &self.options.extensions {
            if !self.macros.contains_key(ext.as_str()) {
                self.macros.predefine(ext, "1", None);
            }
        }
        for (name, value) in &self.options.defines {
            self.define_from_options(name, value);
        }
    }

    /// Sets `__VERSION__`.
    fn set_version_macro(&mut self, n: u32) {
        self.macros.predefine("__VERSION__", &n.to_string(), None);
    }

    /// Whether the current group is skipped.
    fn skipping(&self) -> bool {
        self.conds
            .last()
            .is_some_and(|c| c.skip_block || c.skip_group)
    }

    /// The source string and line number of an offset, after the `#line` directives so far.
    fn presumed(&self, offset: u32) -> (i64, i64) {
        presumed(&self.line_directives, self.file, offset)
    }

    /// The next token of code (outside skipped groups), processing directives on the way;
    /// `Eof` at the end, repeatedly.
    fn next_text_token(&mut self) -> Tok {
        loop {
            let kind = self.toks[self.pos].kind;
            match kind {
                PpKind::Eof => {
                    if !self.eof_reached {
                        self.eof_reached = true;
                        self.report_unterminated();
                    }
                    return Tok::raw(self.toks[self.pos].clone());
                }
                PpKind::Newline => {
                    let nl = self.toks[self.pos].span;
                    if self.skipping() {
                        self.skipped_lines
                            .push(Span::new(self.line_begin, nl.start));
                    }
                    self.line_begin = nl.end;
                    self.pos += 1;
                    self.line_start = true;
                    continue;
                }
                _ => {}
            }
            if self.line_start && kind == PpKind::Punct(Punct::Hash) {
                self.line_start = false;
                self.directive();
                continue;
            }
            if let PpKind::Invalid(c) = kind {
                if self.line_start && is_invisible(c) && !self.skipping() {
                    // A byte order mark or a zero-width character before a directive: reported,
                    // and skipped so that the directive is still one.
                    let t = Tok::raw(self.toks[self.pos].clone());
                    self.report_invalid_char(&t, c);
                    self.pos += 1;
                    continue;
                }
            }
            self.line_start = false;
            if self.skipping() {
                while !matches!(self.toks[self.pos].kind, PpKind::Newline | PpKind::Eof) {
                    self.pos += 1;
                }
                continue;
            }
            return Tok::raw(self.take_code_token());
        }
    }

    /// Consumes the token at `pos` as code (not a directive, not skipped).
    fn take_code_token(&mut self) -> PpToken {
        // Moved out: nothing reads a token behind `pos` again.
        let slot = &mut self.toks[self.pos];
        let t = PpToken {
            text: std::mem::take(&mut slot.text),
            ..*slot
        };
        self.pos += 1;
        self.line_start = false;
        self.past_first = true;
        self.seen_code = true;
        t
    }

    /// Expands the whole text into `out`.
    fn run(&mut self) {
        let mut ex = Expander::main();
        loop {
            if let Some(t) = self.plain_text_token(&ex) {
                self.out.push(t);
                continue;
            }
            let t = self.expand_next(&mut ex);
            match t.t.kind {
                PpKind::Eof => break,
                PpKind::Punct(Punct::Hash | Punct::HashHash) => self.report_stray_hash(&t),
                PpKind::Invalid(c) => {
                    self.report_invalid_char(&t, c);
                    self.out.push(t.t);
                }
                PpKind::Newline => {}
                _ => self.out.push(t.t),
            }
        }
        let eof = self.toks.last().expect("ends with Eof").clone();
        self.out.push(eof);
    }

    /// Adds a diagnostic unless enough were collected ([`crate::diagnostic::MAX_DIAGNOSTICS`]).
    fn push_diag(&mut self, d: Diagnostic) {
        crate::diagnostic::push_capped(&mut self.diags, d);
    }

    fn finish(mut self, lexer_diags: Vec<Diagnostic>) -> Preprocessed {
        let mut diagnostics = lexer_diags;
        for d in &mut diagnostics {
            let skipped = self
                .skipped_lines
                .iter()
                .any(|r| r.start <= d.span.start && d.span.end <= r.end);
            if d.code == Code::NoBreakSpace.as_str() && d.is_error() && skipped {
                // WebGL ignores the text of skipped groups: harmless there, as in a comment.
                d.severity = crate::diagnostic::Severity::Warning;
                d.message = "no-break space (U+00A0) in a group skipped by the preprocessor".into();
                d.notes = vec![
                    "harmless while the group is skipped, but an error if it is ever compiled"
                        .into(),
                ];
            }
        }
        diagnostics.append(&mut self.diags);
        diagnostic::sort(&mut diagnostics);
        Preprocessed {
            tokens: std::mem::take(&mut self.out),
            version: self.version,
            version_span: self.version_span,
            declared_version: self.declared_version,
            extensions: std::mem::take(&mut self.extensions),
            invariant_all: self.invariant_all_span.is_some(),
            invariant_all_span: self.invariant_all_span,
            line_directives: std::mem::take(&mut self.line_directives),
            diagnostics,
            expansions: std::mem::take(&mut self.expansions),
        }
    }

    /// Conditional blocks still open at the end of the text.
    fn report_unterminated(&mut self) {
        const MAX_REPORTED: usize = 16;
        let n = self.conds.len();
        let end = self.toks.last().map(|t| t.span).unwrap_or_default();
        for (i, c) in self.conds.iter().enumerate().take(MAX_REPORTED) {
            let mut d = Diagnostic::error(
                Code::UnterminatedConditional,
                format!("unterminated `{}`", c.kind),
                c.span,
            )
            .with_label("this conditional has no `#endif`")
            .with_help("add `#endif` where the conditional part ends")
            .with_token(c.kind);
            if i == 0 {
                d = d.with_fix(Fix::suggested(
                    if n == 1 {
                        "add `#endif` at the end".to_string()
                    } else {
                        format!("add {n} `#endif` at the end")
                    },
                    end,
                    "\n#endif".repeat(n) + "\n",
                ));
            }
            if i + 1 == MAX_REPORTED && n > MAX_REPORTED {
                d = d.with_note(format!(
                    "{} more conditionals are not closed",
                    n - MAX_REPORTED
                ));
            }
            crate::diagnostic::push_capped(&mut self.diags, d);
        }
    }

    fn report_stray_hash(&mut self, t: &Tok) {
        let text = &*t.t.text;
        let mut d = Diagnostic::error(
            Code::StrayHash,
            if text == "##" {
                "`##` is not an operator in GLSL ES: there is no token pasting".to_string()
            } else {
                "`#` is only allowed at the start of a directive line".to_string()
            },
            t.t.span,
        )
        .with_help("remove it; GLSL ES has no `#` or `##` operators")
        .with_token(text);
        if t.t.from_macro {
            d = d.with_label(format!("the expansion of this macro contains `{text}`"));
            if t.orig != t.t.span && !t.orig.is_empty() {
                d = d.with_secondary(t.orig, "written here");
            }
        } else {
            d = d.with_label("not at the start of a line");
        }
        self.push_diag(d);
    }

    fn report_invalid_char(&mut self, t: &Tok, c: char) {
        let mut d = Diagnostic::error(
            Code::InvalidCharacter,
            format!("invalid character {} in GLSL ES source", char_display(c)),
            t.t.span,
        )
        .with_token(char_token(c));
        if t.t.from_macro {
            d = d.with_label("the expansion of this macro contains it");
            if t.orig != t.t.span && !t.orig.is_empty() {
                d = d.with_secondary(t.orig, "written here");
            }
        } else {
            d = d.with_label("not part of GLSL ES's character set");
        }
        let invisible = is_invisible(c);
        let space = matches!(
            c,
            '\u{2000}'..='\u{200A}' | '\u{202F}' | '\u{205F}' | '\u{3000}'
        );
        let replacement = match c {
            '\u{2212}' | '\u{2013}' | '\u{2014}' => Some("-"),
            '\u{00D7}' => Some("*"),
            _ => None,
        };
        d = d.with_help(format!(
            "U+{:04X} is outside GLSL ES's character set: outside comments, only ASCII letters, digits, `_`, white space and the language's punctuation are allowed",
            c as u32
        ));
        if !t.t.from_macro {
            if invisible {
                d = d.with_fix(Fix::certain("remove the invisible character", t.t.span, ""));
            } else if space {
                d = d.with_fix(Fix::certain("replace it with a space", t.t.span, " "));
            } else if let Some(r) = replacement {
                d = d.with_fix(Fix::suggested(
                    format!("replace it with `{r}`"),
                    t.t.span,
                    r,
                ));
            }
        }
        self.push_diag(d);
    }

    /// Reports every identifier and number longer than the target allows, wherever it is (in
    /// a directive, in a skipped group), as ANGLE's tokenizer does.
    fn check_token_lengths(&mut self) {
        let max = self.options.target.max_token_len();
        let target = self.options.target.display();
        for i in 0..self.toks.len() {
            let t = &self.toks[i];
            // No more characters than bytes, and no more bytes than the token spans in the
            // text (line continuations are left out): most tokens need no count.
            if !matches!(t.kind, PpKind::Ident | PpKind::Number)
                || t.span.len() as usize <= max
                || t.text.len() <= max
            {
                continue;
            }
            let len = t.text.chars().count();
            if len <= max {
                continue;
            }
            let what = if t.kind == PpKind::Ident {
                "identifier"
            } else {
                "number"
            };
            let d = Diagnostic::error(
                Code::IdentifierTooLong,
                format!("{what} of {len} characters: {target} allows at most {max}"),
                t.span,
            )
            .with_label("too long")
            .with_note(format!(
                "{target} limits every token to {max} characters, even in a group the \
                 preprocessor skips"
            ))
            .with_help(if t.kind == PpKind::Ident {
                "use a shorter name"
            } else {
                "write the number with fewer digits"
            })
            .with_token(&*t.text);
            self.push_diag(d);
        }
    }
}

/// How a diagnostic names a token: ``"`foo`"``, or "end of line".
fn describe(t: &PpToken) -> String {
    match t.kind {
        PpKind::Eof | PpKind::Newline => "end of line".to_string(),
        PpKind::Invalid(c) => format!("invalid character {}", char_display(c)),
        _ => format!("`{}`", t.text),
    }
}

/// A character and its code point for messages: ``"`$` (U+0024)"``, or for invisible ones
/// "U+200B (zero width space)".
fn char_display(c: char) -> String {
    let name = match c {
        '\u{200B}' => Some("zero width space"),
        '\u{200C}' => Some("zero width non-joiner"),
        '\u{200D}' => Some("zero width joiner"),
        '\u{2060}' => Some("word joiner"),
        '\u{FEFF}' => Some("byte order mark"),
        '\u{3000}' => Some("ideographic space"),
        '\u{2000}'..='\u{200A}' | '\u{202F}' | '\u{205F}' => Some("a space character"),
        c if c.is_control() => Some("a control character"),
        _ => None,
    };
    match name {
        Some(n) => format!("U+{:04X} ({n})", c as u32),
        None => format!("`{c}` (U+{:04X})", c as u32),
    }
}

/// Whether a character is invisible (zero width, byte order mark).
fn is_invisible(c: char) -> bool {
    matches!(
        c,
        '\u{200B}' | '\u{200C}' | '\u{200D}' | '\u{2060}' | '\u{FEFF}'
    )
}

/// The token WebGL's info log quotes for a character: itself if ASCII, else `?`.
fn char_token(c: char) -> String {
    if c.is_ascii() && !c.is_ascii_control() {
        c.to_string()
    } else {
        "?".to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presumed_lines_follow_line_directives() {
        let f = SourceFile::new("t", "a\n#line 10 3\nb\nc\n#line 20\nd\n");
        let dirs = vec![
            LineDirective {
                span: Span::new(2, 12),
                next_line_start: 13,
                line: 10,
                source: Some(3),
                source_string: 3,
            },
            LineDirective {
                span: Span::new(17, 25),
                next_line_start: 26,
                line: 20,
                source: None,
                source_string: 3,
            },
        ];
        assert_eq!(presumed(&dirs, &f, 0), (0, 1));
        assert_eq!(presumed(&dirs, &f, 2), (0, 2));
        assert_eq!(f.slice(Span::new(2, 12)), "#line 10 3");
        assert_eq!(presumed(&dirs, &f, 13), (3, 10));
        assert_eq!(presumed(&dirs, &f, 15), (3, 11));
        assert_eq!(f.slice(Span::new(26, 27)), "d");
        assert_eq!(presumed(&dirs, &f, 26), (3, 20));
    }

    #[test]
    fn characters_are_named_with_their_code_points() {
        assert_eq!(char_display('$'), "`$` (U+0024)");
        assert_eq!(char_display('\u{200B}'), "U+200B (zero width space)");
        assert_eq!(char_token('$'), "$");
        assert_eq!(char_token('\u{2019}'), "?");
    }
}
