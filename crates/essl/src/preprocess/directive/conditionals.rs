//! Conditional directives: `#if`, `#ifdef`, `#ifndef`, `#elif`, `#else`, `#endif`.

use super::Directive;
use crate::diagnostic::{Diagnostic, Fix};
use crate::diagnostic_code::Code;
use crate::lex::Punct;
use crate::preprocess::expr::ExprParser;
use crate::preprocess::{describe, Pp};

impl Pp<'_> {
    pub(super) fn d_if(&mut self, d: &Directive, kind: &'static str) {
        let span = d.name_span();
        if self.skipping() {
            self.conds.push(crate::preprocess::Cond {
                span,
                kind,
                else_span: None,
                skip_block: true,
                skip_group: true,
                found_valid: false,
            });
            return;
        }
        let v = match kind {
            "#if" => self.eval_if(d, "#if"),
            "#ifdef" => self.eval_ifdef(d, kind).unwrap_or(false),
            _ => self.eval_ifdef(d, kind).map(|v| !v).unwrap_or(false),
        };
        self.conds.push(crate::preprocess::Cond {
            span,
            kind,
            else_span: None,
            skip_block: false,
            skip_group: !v,
            found_valid: v,
        });
    }

    /// The value of an `#if`/`#elif` line; false after an error.
    fn eval_if(&mut self, d: &Directive, what: &'static str) -> bool {
        if d.args().is_empty() {
            self.push_diag(
                Diagnostic::error(
                    Code::MissingExpression,
                    format!("`{what}` needs an expression"),
                    d.name_span(),
                )
                .with_label(format!("expected an expression after `{what}`"))
                .with_help("write an integer expression, such as `defined(NAME)` or `NAME > 1`")
                .with_token("\n"),
            );
            return false;
        }
        let (toks, failed) = self.expand_line(d, true);
        if failed {
            return false;
        }
        let mut p = ExprParser::new(&toks, what, false);
        let Some(v) = p.parse(&mut self.diags) else {
            return false;
        };
        if !p.at_end() {
            let t = p.current();
            let last = &toks[toks.len() - 2];
            let mut e = Diagnostic::error(
                Code::ExtraTokens,
                format!(
                    "unexpected {} after the `{what}` expression",
                    describe(&t.t)
                ),
                t.t.span.to(last.t.span),
            )
            .with_label("the expression ends before this")
            .with_token(&*t.t.text);
            e = if t.t.is(Punct::Equal) && !t.t.from_macro {
                e.with_help("did you mean `==`?").with_fix(Fix::suggested(
                    "write `==`",
                    t.t.span,
                    "==",
                ))
            } else {
                e.with_help("remove them, or make them a comment")
            };
            self.push_diag(e);
            return false;
        }
        !p.invalid && v != 0
    }

    /// Whether the macro an `#ifdef`/`#ifndef` names is defined; `None` after an error.
    fn eval_ifdef(&mut self, d: &Directive, what: &str) -> Option<bool> {
        let name = self.macro_name(d, what)?;
        if d.args().len() > 1 {
            self.extra_tokens(d, 2, &format!("{what} {}", name.text));
        }
        Some(self.macros.contains_key(&name.text))
    }

    pub(super) fn d_elif(&mut self, d: &Directive) {
        let Some(c) = self.conds.last() else {
            self.push_diag(
                Diagnostic::error(Code::ElifWithoutIf, "`#elif` without `#if`", d.name_span())
                    .with_label("no `#if` is open here")
                    .with_help("remove it, or add the `#if` it belongs to")
                    .with_token("elif"),
            );
            return;
        };
        if c.skip_block {
            return;
        }
        if let Some(e) = c.else_span {
            self.push_diag(
                Diagnostic::error(Code::ElifAfterElse, "`#elif` after `#else`", d.name_span())
                    .with_label("the `#else` group must be the last one")
                    .with_secondary(e, "the `#else` is here")
                    .with_help("move this group before the `#else`, or start a new `#if`")
                    .with_token("elif"),
            );
            return;
        }
        if c.found_valid {
            // A group was taken: the expression is not evaluated.
            self.conds.last_mut().expect("open").skip_group = true;
            return;
        }
        let v = self.eval_if(d, "#elif");
        let c = self.conds.last_mut().expect("open");
        c.skip_group = !v;
        c.found_valid = v;
    }

    pub(super) fn d_else(&mut self, d: &Directive) {
        let Some(c) = self.conds.last_mut() else {
            self.push_diag(
                Diagnostic::error(Code::ElseWithoutIf, "`#else` without `#if`", d.name_span())
                    .with_label("no `#if` is open here")
                    .with_help("remove it, or add the `#if` it belongs to")
                    .with_token("else"),
            );
            return;
        };
        if c.skip_block {
            return;
        }
        if let Some(e) = c.else_span {
            self.push_diag(
                Diagnostic::error(Code::ElseAfterElse, "`#else` after `#else`", d.name_span())
                    .with_label("a second `#else`")
                    .with_secondary(e, "the first `#else` is here")
                    .with_help("remove one of them, or close the conditional with `#endif` first")
                    .with_token("else"),
            );
            return;
        }
        c.else_span = Some(d.name_span());
        c.skip_group = c.found_valid;
        c.found_valid = true;
        if !d.args().is_empty() {
            self.extra_tokens(d, 1, "#else");
        }
    }

    pub(super) fn d_endif(&mut self, d: &Directive) {
        if self.conds.pop().is_none() {
            self.push_diag(
                Diagnostic::error(
                    Code::EndifWithoutIf,
                    "`#endif` without `#if`",
                    d.name_span(),
                )
                .with_label("no `#if` is open here")
                .with_fix(Fix::suggested("remove it", d.whole_line(), ""))
                .with_token("endif"),
            );
            return;
        }
        if !d.args().is_empty() {
            self.extra_tokens(d, 1, "#endif");
        }
    }
}
