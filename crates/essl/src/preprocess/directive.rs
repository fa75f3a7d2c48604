//! Directives: one line from `#` to the end of the line, read whole, then handled.

use std::cell::Cell;
use std::rc::Rc;
use std::sync::Arc;

use crate::diagnostic::{Applicability, Diagnostic, Edit, Fix, Severity};
use crate::lex::{PpKind, PpToken, Punct};
use crate::source::{SourceFile, Span};
use crate::Stage;

use super::expand::{Body, Expander, Macro, Origin, Tok};
use super::expr::ExprParser;
use super::{describe, ExtensionBehavior, LineDirective, Pp, Version};

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

/// Extensions of WebGL 1 whose features GLSL ES 3.00 has built in.
const PROMOTED: &[&str] = &[
    "GL_EXT_draw_buffers",
    "GL_EXT_frag_depth",
    "GL_EXT_shader_texture_lod",
    "GL_OES_standard_derivatives",
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

/// Edit distance between two short strings.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
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
        let name: Arc<str> = if d.line[0].kind == PpKind::Ident {
            d.line[0].text.clone()
        } else {
            Arc::from("")
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
            "extra-tokens",
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
            text: Arc::from(""),
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

    fn d_if(&mut self, d: &Directive, kind: &'static str) {
        let span = d.name_span();
        if self.skipping() {
            self.conds.push(super::Cond {
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
        self.conds.push(super::Cond {
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
                    "missing-expression",
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
                "extra-tokens",
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
        Some(self.macros.contains_key(&*name.text))
    }

    fn d_elif(&mut self, d: &Directive) {
        let Some(c) = self.conds.last() else {
            self.push_diag(
                Diagnostic::error("elif-without-if", "`#elif` without `#if`", d.name_span())
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
                Diagnostic::error("elif-after-else", "`#elif` after `#else`", d.name_span())
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

    fn d_else(&mut self, d: &Directive) {
        let Some(c) = self.conds.last_mut() else {
            self.push_diag(
                Diagnostic::error("else-without-if", "`#else` without `#if`", d.name_span())
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
                Diagnostic::error("else-after-else", "`#else` after `#else`", d.name_span())
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

    fn d_endif(&mut self, d: &Directive) {
        if self.conds.pop().is_none() {
            self.push_diag(
                Diagnostic::error("endif-without-if", "`#endif` without `#if`", d.name_span())
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

    // ---- macros ----

    /// The macro name after `#define`, `#undef`, `#ifdef`, `#ifndef`.
    fn macro_name(&mut self, d: &Directive, what: &str) -> Option<PpToken> {
        match d.args().first() {
            None => {
                self.push_diag(
                    Diagnostic::error(
                        "missing-macro-name",
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
                        "invalid-macro-name",
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
                    "predefined-macro-redefined",
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
                    "reserved-macro-name",
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
                    "double-underscore-macro-name",
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
    fn parse_params(&mut self, d: &Directive, name: &PpToken) -> Option<(Vec<Arc<str>>, usize)> {
        let args = d.args();
        let open = args[1].span;
        let mut params: Vec<Arc<str>> = Vec::new();
        let mut i = 2;
        let unterminated = |pp: &mut Self| {
            pp.diags.push(
                Diagnostic::error(
                    "unterminated-macro-parameters",
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
                                "duplicate-macro-parameter",
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
                            "invalid-macro-parameters",
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
                            "invalid-macro-parameters",
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

    fn d_define(&mut self, d: &Directive, origin: Origin) {
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
                    .and_then(|p: &Vec<Arc<str>>| p.iter().position(|p| **p == *t.text))
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
                        "token-pasting",
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
            self.macros.insert(m.name.clone(), Rc::new(m));
            return;
        };
        if old.origin == Origin::Options {
            if m.origin == Origin::Shader && !old.same_as(&m) {
                self.push_diag(
                    Diagnostic::warning(
                        "option-macro-redefined",
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
            self.macros.insert(m.name.clone(), Rc::new(m));
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
            "macro-redefinition",
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

    fn d_undef(&mut self, d: &Directive) {
        let Some(name) = self.macro_name(d, "#undef") else {
            return;
        };
        if let Some(m) = self.macros.get(&*name.text) {
            if m.origin == Origin::Predefined {
                self.push_diag(
                    Diagnostic::error(
                        "predefined-macro-undefined",
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
                        "macro-undefined-while-expanding",
                        format!("`#undef {}` inside a call of that macro", name.text),
                        name.span,
                    )
                    .with_label("the macro's arguments are still being read")
                    .with_help("move the `#undef` after the call")
                    .with_token(&*name.text),
                );
                return;
            }
            self.macros.remove(&*name.text);
        }
        if d.args().len() > 1 {
            self.extra_tokens(d, 2, &format!("#undef {}", name.text));
        }
    }

    /// A `#define` from the options: lexed on its own, spans at 0.
    pub(super) fn define_from_options(&mut self, name: &str, value: &str) {
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
            text: Arc::from("\n"),
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

    // ---- other directives ----

    fn d_error(&mut self, d: &Directive) {
        let text = join(d.args());
        self.push_diag(
            Diagnostic::error(
                "error-directive",
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
                Diagnostic::warning("invalid-pragma", msg, d.span())
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
                            "invariant-all-in-fragment-shader",
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

    fn d_extension(&mut self, d: &Directive) {
        let args = d.args();
        let shape = "`#extension` takes `name : behavior`";
        let name = match args.first() {
            None => {
                self.push_diag(
                    Diagnostic::error("invalid-extension-directive", shape, d.name_span())
                        .with_label("expected an extension name")
                        .with_help("write `#extension NAME : behavior`")
                        .with_token("\n"),
                );
                return;
            }
            Some(t) if t.kind != PpKind::Ident => {
                self.push_diag(
                    Diagnostic::error(
                        "invalid-extension-name",
                        format!(
                            "expected an extension name after `#extension`, found {}",
                            describe(t)
                        ),
                        t.span,
                    )
                    .with_label("expected a name")
                    .with_help("write `#extension NAME : behavior`")
                    .with_token(&*t.text),
                );
                return;
            }
            Some(t) => t,
        };
        match args.get(1) {
            Some(c) if c.is(Punct::Colon) => {}
            other => {
                let (span, found, token) = match other {
                    Some(t) => (t.span, describe(t), t.text.to_string()),
                    None => (
                        name.span.end_point(),
                        "end of line".to_string(),
                        "\n".to_string(),
                    ),
                };
                self.push_diag(
                    Diagnostic::error(
                        "invalid-extension-directive",
                        format!("expected `:` after the extension name, found {found}"),
                        span,
                    )
                    .with_label("expected `:`")
                    .with_help(shape)
                    .with_token(token),
                );
                return;
            }
        }
        let behaviors = "`require`, `enable`, `warn` or `disable`";
        let Some(bt) = args.get(2) else {
            self.push_diag(
                Diagnostic::error(
                    "invalid-extension-behavior",
                    format!("expected {behaviors} after `:`"),
                    d.end(),
                )
                .with_label("expected a behavior")
                .with_help("the behaviors are `require`, `enable`, `warn` and `disable`")
                .with_token("\n"),
            );
            return;
        };
        let behavior = if bt.kind == PpKind::Ident {
            ExtensionBehavior::from_str(&bt.text)
        } else {
            None
        };
        let Some(behavior) = behavior else {
            let mut e = Diagnostic::error(
                "invalid-extension-behavior",
                format!("unknown extension behavior {}", describe(bt)),
                bt.span,
            )
            .with_label(format!("expected {behaviors}"))
            .with_help("the behaviors are `require`, `enable`, `warn` and `disable`")
            .with_token(&*bt.text);
            let lower = bt.text.to_ascii_lowercase();
            if bt.kind == PpKind::Ident && ExtensionBehavior::from_str(&lower).is_some() {
                e = e.with_fix(Fix::certain(format!("write `{lower}`"), bt.span, lower));
            }
            self.push_diag(e);
            return;
        };
        if args.len() > 3 {
            self.extra_tokens(
                d,
                4,
                &format!("#extension {} : {}", name.text, behavior.as_str()),
            );
            return;
        }
        if self.seen_code {
            let sev = if self.version == Version::Es100 {
                Severity::Warning
            } else {
                Severity::Error
            };
            self.push_diag(
                Diagnostic::new(
                    sev,
                    "extension-after-code",
                    "`#extension` must come before any code",
                    d.span(),
                )
                .with_label("after the first declaration")
                .with_help("move the `#extension` directives to the top, after `#version`")
                .with_token(&*name.text),
            );
            if sev == Severity::Error {
                return;
            }
        }
        let n = &*name.text;
        if n == "all" {
            if matches!(
                behavior,
                ExtensionBehavior::Require | ExtensionBehavior::Enable
            ) {
                self.push_diag(
                    Diagnostic::error(
                        "extension-all-behavior",
                        format!("`#extension all` cannot be `{}`", behavior.as_str()),
                        bt.span,
                    )
                    .with_label("`all` takes only `warn` or `disable`")
                    .with_help("name the extension to require or enable it")
                    .with_token(&*bt.text),
                );
                return;
            }
        } else if !self.options.extensions.iter().any(|e| e == n) {
            let require = behavior == ExtensionBehavior::Require;
            let mut e = Diagnostic::new(
                if require {
                    Severity::Error
                } else {
                    Severity::Warning
                },
                "extension-not-supported",
                format!("extension `{n}` is not supported"),
                name.span,
            )
            .with_label(if require { "required here" } else { "ignored" })
            .with_help("remove the directive, or use an extension WebGL2 and essl support")
            .with_token(n);
            if PROMOTED.contains(&n) {
                e = e
                    .with_note("its features are part of GLSL ES 3.00, under their core names")
                    .with_fix(Fix::suggested("remove the directive", d.whole_line(), ""));
            }
            self.push_diag(e);
        }
        self.extensions.push((n.to_string(), behavior, d.span()));
    }

    /// A fix moving the `#version` directive to the first line.
    fn move_version(&self, d: &Directive, applicability: Applicability) -> Fix {
        let text = self.file.slice(d.span()).to_string();
        Fix {
            message: "move it to the first line".into(),
            edits: vec![
                Edit {
                    span: Span::empty(0),
                    replacement: format!("{text}\n"),
                },
                Edit {
                    span: d.whole_line(),
                    replacement: String::new(),
                },
            ],
            applicability,
        }
    }

    fn d_version(&mut self, d: &Directive) {
        if self.version_span.is_none() {
            self.version_span = Some(d.span());
        }
        let args = d.args();
        let mut errors = Vec::new();
        let mut parsed = None;
        match args.first() {
            Some(t) if t.kind == PpKind::Number && t.text.bytes().all(|b| b.is_ascii_digit()) => {
                let n = t.text.parse::<u32>().unwrap_or(u32::MAX);
                let es = args.get(1).is_some_and(|t| t.is_ident("es"));
                let mut next = 1;
                if es {
                    next = 2;
                } else if n >= 300 {
                    let found = args.get(1);
                    let mut e = Diagnostic::error(
                        "invalid-version",
                        format!("`#version {n}` needs the `es` profile"),
                        found.map(|f| f.span).unwrap_or(t.span.end_point()),
                    )
                    .with_label("expected `es`")
                    .with_help("the first line of a WebGL2 shader is `#version 300 es`")
                    .with_token(found.map(|f| f.text.to_string()).unwrap_or("\n".into()));
                    if n == 300 {
                        e = e.with_fix(Fix::certain("add `es`", t.span.end_point(), " es"));
                    }
                    errors.push(e);
                    next = args.len();
                }
                if next < args.len() {
                    let what = if es {
                        format!("#version {n} es")
                    } else {
                        format!("#version {n}")
                    };
                    errors.push(self.extra_tokens_diag(d, next + 1, &what));
                }
                parsed = Some((n, es));
            }
            other => {
                let (span, found, token) = match other {
                    Some(t) => (t.span, describe(t), t.text.to_string()),
                    None => (d.end(), "end of line".to_string(), "\n".to_string()),
                };
                let mut e = Diagnostic::error(
                    "invalid-version",
                    format!("expected a version number after `#version`, found {found}"),
                    span,
                )
                .with_label("expected `300 es`")
                .with_help("the first line of a WebGL2 shader is `#version 300 es`")
                .with_token(token);
                e = match other {
                    None => e.with_fix(Fix::suggested("write `300 es`", d.end(), " 300 es")),
                    Some(_) => e.with_fix(Fix::suggested(
                        "write `300 es`",
                        span.to(args.last().expect("non-empty").span),
                        "300 es",
                    )),
                };
                errors.push(e);
            }
        }
        if let Some((n, es)) = parsed {
            self.declared_version
                .get_or_insert(Version::from_parts(n, es));
        }
        if self.past_first {
            self.push_diag(
                Diagnostic::error(
                    "version-not-first",
                    "`#version` must come before anything else in the shader",
                    d.span(),
                )
                .with_label("after other code or directives")
                .with_note("WebGL2 compiles a shader without `#version 300 es` on its first line as GLSL ES 1.00")
                .with_fix(self.move_version(d, Applicability::Suggested))
                .with_help("make `#version 300 es` the first line")
                .with_token("version"),
            );
            return;
        }
        if !errors.is_empty() {
            self.diags.extend(errors);
            return;
        }
        let (n, es) = parsed.expect("no errors");
        let line = self.file.line_of(d.hash.span.start);
        if n >= 300 && line > 1 {
            self.push_diag(
                Diagnostic::error(
                    "version-not-first-line",
                    format!("`#version {n} es` must be on the first line of the shader"),
                    d.span(),
                )
                .with_label(format!("on line {line}"))
                .with_note("only comments and white space may precede it, on the same line; WebGL2 compiles the shader as GLSL ES 1.00 otherwise")
                .with_fix(self.move_version(d, Applicability::Certain))
                .with_help("make `#version 300 es` the first line; nothing, not even an empty line or a comment line, may come before it")
                .with_token("\n"),
            );
            return;
        }
        let v = Version::from_parts(n, es);
        self.version = v;
        self.set_version_macro(n);
        let number_span = args[0].span.to(args[if es { 1 } else { 0 }].span);
        match v {
            Version::Es300 => {}
            Version::Es100 => self.push_diag(
                Diagnostic::error(
                    "unsupported-version",
                    "`#version 100` is GLSL ES 1.00: essl compiles GLSL ES 3.00",
                    d.span(),
                )
                .with_label("GLSL ES 1.00")
                .with_help("port the shader to `#version 300 es`: `in`/`out` instead of `attribute`/`varying`, `texture` instead of `texture2D`, an `out vec4` instead of `gl_FragColor`")
                .with_fix(Fix::suggested("write `300 es`", number_span, "300 es"))
                .with_token("100"),
            ),
            Version::Other(..) => self.push_diag(
                Diagnostic::error(
                    "unsupported-version",
                    format!(
                        "GLSL version `{n}{}` is not supported: WebGL2 compiles `#version 300 es`",
                        if es { " es" } else { "" }
                    ),
                    number_span,
                )
                .with_label("not supported")
                .with_help("WebGL2 shaders are GLSL ES 3.00: write `#version 300 es`")
                .with_fix(Fix::suggested("write `300 es`", number_span, "300 es"))
                .with_token(&*args[0].text),
            ),
        }
    }

    fn d_line(&mut self, d: &Directive) {
        if d.args().is_empty() {
            self.push_diag(
                Diagnostic::error(
                    "invalid-line-directive",
                    "`#line` needs a line number",
                    d.name_span(),
                )
                .with_label("expected a line number")
                .with_help("write `#line LINE` or `#line LINE SOURCE`")
                .with_token("\n"),
            );
            return;
        }
        let (toks, failed) = self.expand_line(d, false);
        if failed {
            return;
        }
        let mut p = ExprParser::new(&toks, "#line", true);
        let Some(line) = p.parse(&mut self.diags) else {
            return;
        };
        let mut source = None;
        if !p.at_end() {
            let Some(s) = p.parse(&mut self.diags) else {
                return;
            };
            source = Some(s);
        }
        if !p.at_end() {
            let t = p.current();
            let last = &toks[toks.len() - 2];
            self.push_diag(
                Diagnostic::error(
                    "extra-tokens",
                    format!(
                        "unexpected {} after the source string number of `#line`",
                        describe(&t.t)
                    ),
                    t.t.span.to(last.t.span),
                )
                .with_label("`#line` takes a line number and an optional source string number")
                .with_help("remove them, or make them a comment")
                .with_token(&*t.t.text),
            );
            return;
        }
        if p.invalid {
            return;
        }
        let source = source.map(i64::from);
        let source_string =
            source.unwrap_or_else(|| self.line_directives.last().map_or(0, |l| l.source_string));
        self.line_directives.push(LineDirective {
            span: d.span(),
            next_line_start: d.eol.span.end,
            line: i64::from(line),
            source,
            source_string,
        });
    }

    fn d_unknown(&mut self, d: &Directive) {
        let t = &d.line[0];
        if t.kind != PpKind::Ident {
            self.push_diag(
                Diagnostic::error(
                    "unknown-directive",
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
            "unknown-directive",
            format!("unknown directive `#{name}`"),
            d.name_span(),
        )
        .with_label("not a GLSL ES directive")
        .with_token(name);
        let best = DIRECTIVES
            .iter()
            .map(|k| (distance(name, k), *k))
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
