//! Macro directives: `#define` (object-like and function-like, with the rules on which names
//! may be defined), `#undef`, and macros defined from the options.
use crate::diagnostic_code::Code;
use crate::Name;
use std::cell::Cell;

use super::Directive;
use crate::diagnostic::{Diagnostic, Fix};
use crate::lex::{PpKind, PpToken, Punct};
use crate::preprocess::expand::{Body, Macro, Origin};
use crate::preprocess::{describe, Pp};
use crate::source::{SourceFile, Span};

impl Pp<'_> {
    /// The macro name after `#define`, `#undef`, `#ifdef`, `#ifndef`.
    pub(super) fn macro_name(&mut self, d: &Directive, what: &str) -> Option<PpToken> {
        match d.args().first() {
            None => {
                self.push_diag(
                    Diagnostic::error(
                        Code::MissingMacroName,
                        format!("`{what}` needs a macro name"),
                        d.name_span(),
                    )
                    .with_label(format!("expected a name after `{what}`"))
                    .with_help("write the name of a macro")
                    .with_token("\n"),
                );
                None
            }
            Some(t) if t.kind != PpKind::Ident => {
                self.push_diag(
                    Diagnostic::error(
                        Code::InvalidMacroName,
                        format!("expected a macro name after `{what}`, found {}", describe(t)),
                        t.span,
                    )
                    .with_label("a macro name is an identifier")
                    .with_help("a macro name is an identifier: letters, digits and `_`, not starting with a digit")
                    .with_token(&*t.text),
                );
                None
            }
            Some(t) => Some(t.clone()),
        }
    }

    /// Whether a macro of this name may be defined (reports why not; warns about `__`).
    fn check_definable(&mut self, name: &PpToken) -> bool {
        let n = &*name.text;
        if self
            .macros
            .get(n)
            .is_some_and(|m| m.origin == Origin::Predefined)
        {
            self.push_diag(
                Diagnostic::error(
                    Code::PredefinedMacroRedefined,
                    format!("`{n}` is a predefined macro and cannot be redefined"),
                    name.span,
                )
                .with_label("predefined")
                .with_help("choose another name")
                .with_token(n),
            );
            return false;
        }
        if n == "defined" || n.starts_with("GL_") {
            self.push_diag(
                Diagnostic::error(
                    Code::ReservedMacroName,
                    format!("macro name `{n}` is reserved"),
                    name.span,
                )
                .with_label(if n == "defined" {
                    "`defined` is an operator of `#if`"
                } else {
                    "names starting with `GL_` are reserved for OpenGL"
                })
                .with_help("choose another name")
                .with_token(n),
            );
            return false;
        }
        if n.contains("__") {
            self.push_diag(
                Diagnostic::warning(
                    Code::DoubleUnderscoreMacroName,
                    format!("macro name `{n}` contains `__`, which is reserved"),
                    name.span,
                )
                .with_label("allowed, but the implementation may define the same name")
                .with_help("choose a name without two consecutive underscores")
                .with_token(n),
            );
        }
        true
    }

    /// The parameter list of a function-like macro (`args[1]` is its `(`): the names and the
    /// index in `args` after the `)`.
    fn parse_params(&mut self, d: &Directive, name: &PpToken) -> Option<(Vec<Name>, usize)> {
        let args = d.args();
        let open = args[1].span;
        let mut params: Vec<Name> = Vec::new();
        let mut i = 2;
        let unterminated = |pp: &mut Self| {
            pp.diags.push(
                Diagnostic::error(
                    Code::UnterminatedMacroParameters,
                    format!("missing `)` in the parameter list of macro `{}`", name.text),
                    d.end(),
                )
                .with_label("expected `)`")
                .with_secondary(open, "to close this `(`")
                .with_help("close the parameter list with `)` before the replacement")
                .with_token("\n"),
            );
        };
        if args.get(i).is_some_and(|t| t.is(Punct::RightParen)) {
            return Some((params, i + 1));
        }
        loop {
            match args.get(i) {
                None => {
                    unterminated(self);
                    return None;
                }
                Some(t) if t.kind == PpKind::Ident => {
                    if let Some(first) = params.iter().position(|p| **p == *t.text) {
                        let first_span = args[2..i]
                            .iter()
                            .filter(|a| a.kind == PpKind::Ident)
                            .nth(first)
                            .map(|a| a.span)
                            .unwrap_or(t.span);
                        self.push_diag(
                            Diagnostic::error(
                                Code::DuplicateMacroParameter,
                                format!(
                                    "parameter `{}` appears twice in macro `{}`",
                                    t.text, name.text
                                ),
                                t.span,
                            )
                            .with_label("a second parameter with this name")
                            .with_secondary(first_span, "the first one")
                            .with_help("give each parameter its own name")
                            .with_token(&*t.text),
                        );
                        return None;
                    }
                    params.push(t.text.clone());
                    i += 1;
                }
                Some(t) => {
                    self.push_diag(
                        Diagnostic::error(
                            Code::InvalidMacroParameters,
                            format!(
                                "expected a parameter name in macro `{}`, found {}",
                                name.text,
                                describe(t)
                            ),
                            t.span,
                        )
                        .with_label("expected a parameter name")
                        .with_help(
                            "write the parameters as `NAME(a, b)`, names separated by commas",
                        )
                        .with_token(&*t.text),
                    );
                    return None;
                }
            }
            match args.get(i) {
                Some(t) if t.is(Punct::Comma) => i += 1,
                Some(t) if t.is(Punct::RightParen) => return Some((params, i + 1)),
                None => {
                    unterminated(self);
                    return None;
                }
                Some(t) => {
                    self.push_diag(
                        Diagnostic::error(
                            Code::InvalidMacroParameters,
                            format!(
                                "expected `,` or `)` after parameter `{}`, found {}",
                                args[i - 1].text,
                                describe(t)
                            ),
                            t.span,
                        )
                        .with_label("expected `,` or `)`")
                        .with_help(
                            "write the parameters as `NAME(a, b)`, names separated by commas",
                        )
                        .with_token(&*t.text),
                    );
                    return None;
                }
            }
        }
    }

    pub(super) fn d_define(&mut self, d: &Directive, origin: Origin) {
        let Some(name) = self.macro_name(d, "#define") else {
            return;
        };
        if !self.check_definable(&name) {
            return;
        }
        let args = d.args();
        let mut params = None;
        let mut i = 1;
        if args
            .get(1)
            .is_some_and(|t| t.is(Punct::LeftParen) && !t.space_before)
        {
            let Some((p, next)) = self.parse_params(d, &name) else {
                return;
            };
            params = Some(p);
            i = next;
        }
        let mut body = Vec::with_capacity(args.len() - i);
        let mut warned = false;
        for (k, t) in args[i..].iter().enumerate() {
            let space_before = k > 0 && t.space_before;
            if t.kind == PpKind::Ident {
                if let Some(index) = params
                    .as_ref()
                    .and_then(|p: &Vec<Name>| p.iter().position(|p| **p == *t.text))
                {
                    body.push(Body::Param {
                        index,
                        space_before,
                    });
                    continue;
                }
            }
            if matches!(t.kind, PpKind::Punct(Punct::Hash | Punct::HashHash)) && !warned {
                warned = true;
                let pasting = t.is(Punct::HashHash);
                self.push_diag(
                    Diagnostic::warning(
                        Code::TokenPasting,
                        if pasting {
                            "GLSL ES has no `##` operator: this macro cannot paste tokens"
                        } else {
                            "GLSL ES has no `#` operator: this macro cannot make strings"
                        },
                        t.span,
                    )
                    .with_label(format!(
                        "kept as a `{}` token: using the macro is an error",
                        t.text
                    ))
                    .with_help("write the tokens out, or use a function-like macro")
                    .with_token(&*t.text),
                );
            }
            let mut t = t.clone();
            t.space_before = space_before;
            body.push(Body::Tok(t));
        }
        let m = Macro {
            name: name.text.clone(),
            params,
            body,
            span: name.span,
            origin,
            dynamic: None,
            disabled: Cell::new(false),
            invoking: Cell::new(0),
        };
        self.insert_macro(m);
    }

    fn insert_macro(&mut self, m: Macro) {
        let Some(old) = self.macros.get(&m.name) else {
            self.macros.insert(m);
            return;
        };
        if old.origin == Origin::Options {
            if m.origin == Origin::Shader && !old.same_as(&m) {
                self.push_diag(
                    Diagnostic::warning(
                        Code::OptionMacroRedefined,
                        format!(
                            "`#define {}` replaces the value given in the options",
                            m.name
                        ),
                        m.span,
                    )
                    .with_label("the shader's definition is used")
                    .with_help("the shader's `#define` wins; remove it to use the options' value")
                    .with_token(&*m.name),
                );
            }
            self.macros.insert(m);
            return;
        }
        if old.same_as(&m) {
            return;
        }
        let what = if old.params != m.params {
            if old.params.is_none() != m.params.is_none() {
                "as a different kind of macro"
            } else {
                "with different parameters"
            }
        } else {
            "with a different replacement list"
        };
        let mut e = Diagnostic::error(
            Code::MacroRedefinition,
            format!("macro `{}` is redefined {what}", m.name),
            m.span,
        )
        .with_label("redefined here")
        .with_note(
            "a macro may only be redefined identically (same tokens, same white-space separation)",
        )
        .with_help(format!(
            "`#undef {}` before redefining it, or make both definitions identical",
            m.name
        ))
        .with_token(&*m.name);
        if !old.span.is_empty() {
            e = e.with_secondary(old.span, "previous definition");
        }
        self.push_diag(e);
    }

    pub(super) fn d_undef(&mut self, d: &Directive) {
        let Some(name) = self.macro_name(d, "#undef") else {
            return;
        };
        if let Some(m) = self.macros.get(&name.text) {
            if m.origin == Origin::Predefined {
                self.push_diag(
                    Diagnostic::error(
                        Code::PredefinedMacroUndefined,
                        format!(
                            "`{}` is a predefined macro and cannot be undefined",
                            name.text
                        ),
                        name.span,
                    )
                    .with_label("predefined")
                    .with_fix(Fix::suggested("remove the directive", d.whole_line(), ""))
                    .with_help("predefined macros cannot be undefined: remove the directive")
                    .with_token(&*name.text),
                );
                return;
            }
            if m.disabled.get() || m.invoking.get() > 0 {
                self.push_diag(
                    Diagnostic::error(
                        Code::MacroUndefinedWhileExpanding,
                        format!("`#undef {}` inside a call of that macro", name.text),
                        name.span,
                    )
                    .with_label("the macro's arguments are still being read")
                    .with_help("move the `#undef` after the call")
                    .with_token(&*name.text),
                );
                return;
            }
            self.macros.remove(&name.text);
        }
        if d.args().len() > 1 {
            self.extra_tokens(d, 2, &format!("#undef {}", name.text));
        }
    }

    /// A `#define` from the options: lexed on its own, spans at 0.
    pub(in crate::preprocess) fn define_from_options(&mut self, name: &str, value: &str) {
        let text = format!("#define {name} {value}").replace(['\n', '\r'], " ");
        let f = SourceFile::new("<options>", text);
        let mut toks: Vec<PpToken> = crate::lex::lex(&f)
            .tokens
            .into_iter()
            .filter(|t| !matches!(t.kind, PpKind::Newline | PpKind::Eof))
            .map(|mut t| {
                t.span = Span::empty(0);
                t
            })
            .collect();
        if toks.len() < 2 {
            return;
        }
        let hash = toks.remove(0);
        let eol = PpToken {
            kind: PpKind::Newline,
            span: Span::empty(0),
            text: Name::new_static("\n"),
            space_before: false,
            from_macro: false,
        };
        let before = self.diags.len();
        self.d_define(
            &Directive {
                hash,
                line: toks,
                eol,
            },
            Origin::Options,
        );
        for d in &mut self.diags[before..] {
            d.notes
                .push(format!("in the define `{name}` = `{value}` of the options"));
        }
    }
}
