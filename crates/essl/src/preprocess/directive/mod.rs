//! Directives: one line from `#` to the end of the line, read whole, then handled.
//!
//! The preprocessor's `impl` is spread over the files of this module by directive family:
//! conditionals, macros, and version/extension/line; this file reads a directive, dispatches
//! it and handles `#error`, `#pragma` and unknown directives.

mod conditionals;
mod macros;
mod version;

use crate::diagnostic_code::Code;
use crate::Name;

use crate::diagnostic::{Applicability, Diagnostic, Edit, Fix};
use crate::lex::{PpKind, PpToken, Punct};
use crate::source::Span;
use crate::Stage;

use super::expand::{Expander, Origin, Tok};
use super::{describe, Pp, Version};

/// The directives of GLSL ES 3.00.
const DIRECTIVES: &[&str] = &[
    "define",
    "undef",
    "if",
    "ifdef",
    "ifndef",
    "else",
    "elif",
    "endif",
    "error",
    "pragma",
    "extension",
    "version",
    "line",
];

/// A directive line.
pub(super) struct Directive {
    /// The `#`.
    hash: PpToken,
    /// The tokens after `#` (the directive's name first).
    line: Vec<PpToken>,
    /// What ends the line: a `Newline`, or `Eof`.
    eol: PpToken,
}

impl Directive {
    /// From `#` to the last token.
    fn span(&self) -> Span {
        match self.line.last() {
            Some(t) => self.hash.span.to(t.span),
            None => self.hash.span,
        }
    }

    /// `#` and the name.
    fn name_span(&self) -> Span {
        self.hash.span.to(self.line[0].span)
    }

    /// The tokens after the name.
    fn args(&self) -> &[PpToken] {
        &self.line[1..]
    }

    /// The empty span after the last token.
    fn end(&self) -> Span {
        self.span().end_point()
    }

    /// The whole line with its line break, for removing it.
    fn whole_line(&self) -> Span {
        Span::new(self.hash.span.start, self.eol.span.end)
    }
}

/// Tokens joined as written, one space where there was white space.
fn join(tokens: &[PpToken]) -> String {
    let mut s = String::new();
    for (i, t) in tokens.iter().enumerate() {
        if i > 0 && t.space_before {
            s.push(' ');
        }
        s.push_str(&t.text);
    }
    s
}

impl Pp<'_> {
    /// Reads and handles the directive whose `#` is at `pos`; leaves `pos` at its line's end.
    pub(super) fn directive(&mut self) {
        let hash = self.toks[self.pos].clone();
        let start = self.pos + 1;
        let mut end = start;
        while !matches!(self.toks[end].kind, PpKind::Newline | PpKind::Eof) {
            end += 1;
        }
        let d = Directive {
            hash,
            line: self.toks[start..end].to_vec(),
            eol: self.toks[end].clone(),
        };
        self.pos = end;
        if d.line.is_empty() {
            // The null directive.
            self.past_first = true;
            return;
        }
        let name: Name = if d.line[0].kind == PpKind::Ident {
            d.line[0].text.clone()
        } else {
            Name::default()
        };
        let skipping = self.skipping();
        match &*name {
            "if" => self.d_if(&d, "#if"),
            "ifdef" => self.d_if(&d, "#ifdef"),
            "ifndef" => self.d_if(&d, "#ifndef"),
            "elif" => self.d_elif(&d),
            "else" => self.d_else(&d),
            "endif" => self.d_endif(&d),
            _ if skipping => {}
            "define" => self.d_define(&d, Origin::Shader),
            "undef" => self.d_undef(&d),
            "error" => self.d_error(&d),
            "pragma" => self.d_pragma(&d),
            "extension" => self.d_extension(&d),
            "version" => self.d_version(&d),
            "line" => self.d_line(&d),
            _ => self.d_unknown(&d),
        }
        self.past_first = true;
    }

    /// An error for tokens after what a directive takes (`line[from..]`).
    fn extra_tokens_diag(&self, d: &Directive, from: usize, what: &str) -> Diagnostic {
        let t = &d.line[from];
        let last = d.line.last().expect("non-empty");
        let one_line =
            self.file.line_index(d.hash.span.start) == self.file.line_index(d.eol.span.start);
        let fix = Fix {
            message: "turn the extra text into a comment".into(),
            edits: vec![Edit {
                span: Span::empty(t.span.start),
                replacement: "// ".into(),
            }],
            applicability: if one_line {
                Applicability::Certain
            } else {
                Applicability::Suggested
            },
        };
        Diagnostic::error(
            Code::ExtraTokens,
            format!("unexpected {} after `{what}`", describe(t)),
            t.span.to(last.span),
        )
        .with_label("not part of the directive")
        .with_fix(fix)
        .with_help("remove them, or make them a comment")
        .with_token(&*t.text)
    }

    fn extra_tokens(&mut self, d: &Directive, from: usize, what: &str) {
        let e = self.extra_tokens_diag(d, from, what);
        self.push_diag(e);
    }

    /// Expands a directive's arguments (for `#if`, `#elif`, `#line`): the tokens, ending with
    /// `Eof`, and whether a `defined` operator was malformed.
    fn expand_line(&mut self, d: &Directive, if_mode: bool) -> (Vec<Tok>, bool) {
        let mut list: Vec<Tok> = d.args().iter().cloned().map(Tok::raw).collect();
        list.push(Tok::raw(PpToken {
            kind: PpKind::Eof,
            span: d.end(),
            text: Name::default(),
            space_before: false,
            from_macro: false,
        }));
        let mut ex = Expander::list(list, if_mode, 0);
        let mut out = Vec::new();
        loop {
            let t = self.expand_next(&mut ex);
            let eof = t.t.kind == PpKind::Eof;
            out.push(t);
            if eof {
                break;
            }
        }
        (out, ex.failed)
    }

    // ---- conditionals ----

    // ---- macros ----

    fn d_error(&mut self, d: &Directive) {
        let text = join(d.args());
        self.push_diag(
            Diagnostic::error(
                Code::ErrorDirective,
                if text.is_empty() {
                    "`#error` directive".to_string()
                } else {
                    text
                },
                d.span(),
            )
            .with_label("`#error` stops the compilation")
            .with_help("the shader stops itself here: check the conditions around this `#error`")
            .with_token("#error"),
        );
    }

    fn d_pragma(&mut self, d: &Directive) {
        let args = d.args();
        let stdgl = args.first().is_some_and(|t| t.is_ident("STDGL"));
        let rest = if stdgl { &args[1..] } else { args };
        let Some(name) = rest.first().filter(|t| t.kind == PpKind::Ident) else {
            return;
        };
        let value =
            (rest.len() == 4 && rest[1].is(Punct::LeftParen) && rest[3].is(Punct::RightParen))
                .then(|| &rest[2]);
        let bad = |pp: &mut Self, msg: String| {
            pp.diags.push(
                Diagnostic::warning(Code::InvalidPragma, msg, d.span())
                    .with_label("this pragma is ignored")
                    .with_help("check the pragma's spelling; unknown pragmas are ignored")
                    .with_token(&*name.text),
            );
        };
        match (stdgl, &*name.text) {
            (true, "invariant") => {
                if !value.is_some_and(|v| v.is_ident("all")) {
                    bad(self, "`#pragma STDGL invariant` takes `(all)`".into());
                    return;
                }
                if self.invariant_all_span.is_none() {
                    self.invariant_all_span = Some(d.span());
                }
                if self.options.stage == Some(Stage::Fragment) && self.version == Version::Es300 {
                    self.push_diag(
                        Diagnostic::error(
                            Code::InvariantAllInFragmentShader,
                            "`#pragma STDGL invariant(all)` is not allowed in a fragment shader",
                            d.span(),
                        )
                        .with_label("in a fragment shader")
                        .with_note("GLSL ES 3.00 allows it only in vertex shaders")
                        .with_fix(Fix::suggested("remove it", d.whole_line(), ""))
                        .with_help(
                            "remove it; declare the vertex shader's outputs `invariant` instead",
                        )
                        .with_token("invariant"),
                    );
                }
            }
            (false, n @ ("debug" | "optimize"))
                if !value.is_some_and(|v| v.is_ident("on") || v.is_ident("off")) =>
            {
                bad(self, format!("`#pragma {n}` takes `(on)` or `(off)`"));
            }
            // Other pragmas are the implementation's business: ignored.
            _ => {}
        }
    }

    fn d_unknown(&mut self, d: &Directive) {
        let t = &d.line[0];
        if t.kind != PpKind::Ident {
            self.push_diag(
                Diagnostic::error(
                    Code::UnknownDirective,
                    format!("expected a directive name after `#`, found {}", describe(t)),
                    t.span,
                )
                .with_label("not a directive")
                .with_token(&*t.text),
            );
            return;
        }
        let name = &*t.text;
        let mut e = Diagnostic::error(
            Code::UnknownDirective,
            format!("unknown directive `#{name}`"),
            d.name_span(),
        )
        .with_label("not a GLSL ES directive")
        .with_token(name);
        let best = DIRECTIVES
            .iter()
            .map(|k| (crate::near::edit_distance(name, k), *k))
            .filter(|(dist, k)| *dist <= 2 && *dist < k.len())
            .min();
        if name == "include" {
            e = e.with_help("GLSL ES has no `#include`: put the code in the shader");
        } else if let Some((_, k)) = best {
            e = e
                .with_help(format!("did you mean `#{k}`?"))
                .with_fix(Fix::suggested(format!("write `#{k}`"), t.span, k));
        } else {
            e = e.with_help(
                "the directives are #define, #undef, #if, #ifdef, #ifndef, #elif, #else, #endif, #error, #pragma, #extension, #version and #line",
            );
        }
        self.push_diag(e);
    }
}
