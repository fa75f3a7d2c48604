//! Macros and their expansion, as C99 expands them (GLSL has no `#` or `##` operators).
//!
//! The expander keeps a stack of contexts, one per macro being expanded; a macro is disabled
//! while its context is on the stack, and a name of a disabled macro met there is marked so that
//! it is never expanded afterwards (the "hide set" of the C standard, as ANGLE implements it).
//! Arguments are fully expanded before they are substituted; the result is rescanned with the
//! rest of the text. Everything is iterative except argument pre-expansion, whose nesting is
//! bounded ([`MAX_ARGUMENT_NESTING`]); the total number of tokens macros may produce is bounded
//! too, so that no input expands without end.

use crate::diagnostic_code::Code;
use crate::Name;
use std::cell::Cell;
use std::rc::Rc;

use crate::diagnostic::Diagnostic;
use crate::lex::{PpKind, PpToken, Punct};
use crate::source::Span;

use super::Pp;

/// How deeply macro calls may nest inside macro arguments (`F(F(F(...)))`): ANGLE's
/// `maxMacroExpansionDepth`; Chromium compiles 1,000 nested calls and refuses 1,001 ("macro
/// invocation chain too deep").
pub(super) const MAX_ARGUMENT_NESTING: u32 = 1000;

/// Why an argument could not be expanded (reported where it was found).
enum ArgFailure {
    /// Macro calls nested past [`MAX_ARGUMENT_NESTING`].
    TooDeep,
    /// More tokens than [`MAX_CONTEXT_TOKENS`] allow.
    TooLarge,
}

/// How many tokens the expansions in progress of one expander may hold at once, counting the
/// expanded arguments of the call being substituted: ANGLE's limit (`kMaxContextTokens`),
/// past which WebGL browsers refuse the shader ("out of memory"). It is what keeps a
/// function-like macro that repeats its argument, nested a few times, from growing
/// exponentially.
pub(super) const MAX_CONTEXT_TOKENS: usize = 10_000;

/// A token on its way through the expander.
#[derive(Clone, Debug)]
pub(super) struct Tok {
    /// The token as the parser will see it (span: the outermost macro invocation, if any, or
    /// for an argument's token where the argument is written).
    pub t: PpToken,
    /// Where the token "is" for `__LINE__`: its own offset, or, for a token from an expansion,
    /// that of the invocation's name (object-like) or closing parenthesis (function-like).
    pub loc: u32,
    /// Where the token was written (in a `#define` for a token of a replacement list).
    pub orig: Span,
    /// A name of a macro that was disabled when it was met: never expanded.
    pub no_expand: bool,
}

impl Tok {
    /// A token straight from the text.
    pub fn raw(t: PpToken) -> Tok {
        Tok {
            loc: t.span.start,
            orig: t.span,
            t,
            no_expand: false,
        }
    }
}

/// A piece of a replacement list.
#[derive(Clone, Debug)]
pub(super) enum Body {
    /// A token, as written (first token without leading space).
    Tok(PpToken),
    /// A parameter, replaced by its (expanded) argument.
    Param {
        /// Which parameter.
        index: usize,
        /// Whether white space precedes it in the replacement list.
        space_before: bool,
    },
}

/// A macro whose value is computed where it is used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Dynamic {
    /// `__LINE__`
    Line,
    /// `__FILE__`
    File,
}

/// Where a macro definition comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Origin {
    /// Predefined by the language (`__LINE__`, `GL_ES`, supported extensions): cannot be
    /// redefined or undefined.
    Predefined,
    /// From [`PreprocessOptions::defines`](super::PreprocessOptions::defines).
    Options,
    /// From a `#define` in the shader.
    Shader,
}

/// A macro definition.
#[derive(Debug)]
pub(super) struct Macro {
    /// Its name.
    pub name: Name,
    /// Parameter names of a function-like macro; `None` for an object-like one.
    pub params: Option<Vec<Name>>,
    /// The replacement list.
    pub body: Vec<Body>,
    /// The name in its `#define` (empty at 0 for predefined macros and options).
    pub span: Span,
    /// Where it comes from.
    pub origin: Origin,
    /// For `__LINE__` and `__FILE__`.
    pub dynamic: Option<Dynamic>,
    /// Its expansion is in progress (its context is on a stack).
    pub disabled: Cell<bool>,
    /// Its arguments are being collected.
    pub invoking: Cell<u32>,
}

impl Macro {
    /// An object-like macro predefined with the given value.
    pub fn predefined(name: &str, value: &str, dynamic: Option<Dynamic>) -> Macro {
        Macro {
            name: Name::from(name),
            params: None,
            body: vec![Body::Tok(number_token(value, Span::empty(0), false))],
            span: Span::empty(0),
            origin: Origin::Predefined,
            dynamic,
            disabled: Cell::new(false),
            invoking: Cell::new(0),
        }
    }

    /// Whether two definitions are the same as GLSL ES (and C) count it: same kind, same
    /// parameter names, same replacement tokens with the same white-space separation.
    pub fn same_as(&self, other: &Macro) -> bool {
        self.params == other.params
            && self.body.len() == other.body.len()
            && self
                .body
                .iter()
                .zip(&other.body)
                .all(|(a, b)| match (a, b) {
                    (Body::Tok(a), Body::Tok(b)) => {
                        a.kind == b.kind && a.text == b.text && a.space_before == b.space_before
                    }
                    (
                        Body::Param {
                            index: i,
                            space_before: s,
                            ..
                        },
                        Body::Param {
                            index: j,
                            space_before: t,
                            ..
                        },
                    ) => i == j && s == t,
                    _ => false,
                })
    }
}

/// A number token made up by the preprocessor.
pub(super) fn number_token(text: &str, span: Span, from_macro: bool) -> PpToken {
    PpToken {
        kind: PpKind::Number,
        span,
        text: Name::from(text),
        space_before: true,
        from_macro,
    }
}

/// One macro expansion in progress. Dropping it re-enables the macro.
struct Ctx {
    mac: Rc<Macro>,
    /// The remaining tokens, in reverse order.
    toks: Vec<Tok>,
    /// How many tokens the expansion had (counted in [`Expander::in_contexts`] until popped).
    len: usize,
}

impl Drop for Ctx {
    fn drop(&mut self) {
        self.mac.disabled.set(false);
    }
}

/// Where an expander reads tokens that are not from a macro.
pub(super) enum Source {
    /// The shader text, with directives processed on the way.
    Main,
    /// A list of tokens (a directive's line, a macro argument) stored in reverse order, so
    /// that the next token is the last element; the first element is an `Eof` that stays.
    List(Vec<Tok>),
}

/// A macro expander over one source of tokens.
pub(super) struct Expander {
    source: Source,
    contexts: Vec<Ctx>,
    pending: Option<Tok>,
    /// The tokens of the expansions on `contexts` (their whole lengths, as ANGLE counts).
    in_contexts: usize,
    /// In an `#if` or `#elif` line: `defined` is an operator.
    if_mode: bool,
    /// How deeply this expander is nested in argument pre-expansion.
    depth: u32,
    /// A macro call in it was nested past [`MAX_ARGUMENT_NESTING`].
    too_deep: bool,
    /// An error in a macro call or a `defined` operator was reported: the line's value is
    /// unusable.
    pub failed: bool,
}

impl Expander {
    /// An expander over the shader text.
    pub fn main() -> Expander {
        Expander {
            source: Source::Main,
            contexts: Vec::new(),
            pending: None,
            in_contexts: 0,
            if_mode: false,
            depth: 0,
            too_deep: false,
            failed: false,
        }
    }

    /// An expander over a list of tokens, which must end with an `Eof` token.
    pub fn list(mut toks: Vec<Tok>, if_mode: bool, depth: u32) -> Expander {
        debug_assert!(toks.last().is_some_and(|t| t.t.kind == PpKind::Eof));
        toks.reverse();
        Expander {
            source: Source::List(toks),
            contexts: Vec::new(),
            pending: None,
            in_contexts: 0,
            if_mode,
            depth,
            too_deep: false,
            failed: false,
        }
    }
}

impl Pp<'_> {
    /// The next token without macro expansion (but from the contexts of expansions in
    /// progress): what argument collection and `defined` read.
    fn raw_get(&mut self, ex: &mut Expander) -> Tok {
        if let Some(t) = ex.pending.take() {
            return t;
        }
        while ex.contexts.last().is_some_and(|c| c.toks.is_empty()) {
            if let Some(c) = ex.contexts.pop() {
                ex.in_contexts -= c.len;
            }
        }
        if let Some(c) = ex.contexts.last_mut() {
            if let Some(mut t) = c.toks.pop() {
                // A name of a macro being expanded, read from an expansion, stays unexpanded
                // even when it is read as an argument after that expansion has ended
                // (`#define a m((a)` then `a)`: the argument's `a` is not expanded again).
                if t.t.kind == PpKind::Ident
                    && self.macros.get(&t.t.text).is_some_and(|m| m.disabled.get())
                {
                    t.no_expand = true;
                }
                return t;
            }
        }
        match &mut ex.source {
            Source::Main => self.next_text_token(),
            Source::List(toks) => {
                if toks.len() > 1 {
                    toks.pop().expect("non-empty")
                } else {
                    toks[0].clone()
                }
            }
        }
    }

    /// The next token of the text when all there is to do is pass it on, consumed: outside
    /// any expansion, in a group that is not skipped, not a line break, the end, a `#` or an
    /// invalid character, and not a macro's name. `None` (nothing consumed) otherwise, for
    /// [`Pp::expand_next`]. Most tokens of a shader take this path.
    pub(super) fn plain_text_token(&mut self, ex: &Expander) -> Option<PpToken> {
        if ex.pending.is_some() || !ex.contexts.is_empty() {
            return None;
        }
        let t = &self.toks[self.pos];
        match t.kind {
            PpKind::Eof
            | PpKind::Newline
            | PpKind::Invalid(_)
            | PpKind::Punct(Punct::Hash | Punct::HashHash) => return None,
            PpKind::Ident if self.macros.contains_key(&t.text) => return None,
            _ => {}
        }
        if self.skipping() {
            return None;
        }
        Some(self.take_code_token())
    }

    /// The next token after macro expansion (never a `Newline`; `Eof` at the end, repeatedly).
    pub(super) fn expand_next(&mut self, ex: &mut Expander) -> Tok {
        loop {
            let mut t = self.raw_get(ex);
            if t.t.kind != PpKind::Ident || t.no_expand {
                return t;
            }
            if ex.if_mode && &*t.t.text == "defined" {
                return self.defined_operator(ex, t);
            }
            let Some(m) = self.macros.get(&t.t.text).cloned() else {
                return t;
            };
            if m.disabled.get() {
                t.no_expand = true;
                return t;
            }
            if self.expanded > self.budget {
                return t;
            }
            let toks = match &m.params {
                None => self.object_expansion(&m, &t),
                Some(_) => {
                    let next = self.raw_get(ex);
                    if !next.t.is(Punct::LeftParen) {
                        // A function-like macro's name without `(`: an ordinary identifier.
                        ex.pending = Some(next);
                        return t;
                    }
                    m.invoking.set(m.invoking.get() + 1);
                    let call = self.collect_arguments(ex, &m, &t, &next);
                    m.invoking.set(m.invoking.get() - 1);
                    match call {
                        Some(toks) => toks,
                        // Reported; the invocation is dropped.
                        None => continue,
                    }
                }
            };
            if !t.t.from_macro && m.origin == Origin::Shader {
                // The replacement list's tokens carry the invocation's span, the union of all.
                let invocation = toks.iter().fold(t.t.span, |a, x| a.to(x.t.span));
                self.expansions.push(super::Expansion {
                    invocation,
                    name: m.name.clone(),
                    defined: m.span,
                });
            }
            self.expanded += toks.len();
            if self.expanded > self.budget && !self.budget_reported {
                self.report_budget(&m, &t);
            }
            let mut toks = toks;
            toks.reverse();
            m.disabled.set(true);
            let len = toks.len();
            ex.in_contexts += len;
            ex.contexts.push(Ctx { mac: m, toks, len });
        }
    }

    /// The replacement of an object-like macro invoked by `name`.
    fn object_expansion(&mut self, m: &Macro, name: &Tok) -> Vec<Tok> {
        let mut out = Vec::with_capacity(m.body.len());
        for b in &m.body {
            if let Body::Tok(pt) = b {
                let mut t = pt.clone();
                t.span = name.t.span;
                t.from_macro = true;
                if let Some(d) = m.dynamic {
                    let (source, line) = self.presumed(name.loc);
                    let v = if d == Dynamic::Line { line } else { source };
                    t.text = Name::from(v.to_string());
                }
                out.push(Tok {
                    t,
                    loc: name.loc,
                    orig: pt.span,
                    no_expand: false,
                });
            }
        }
        if let Some(first) = out.first_mut() {
            first.t.space_before = name.t.space_before;
        }
        out
    }

    /// Collects the arguments of a function-like macro (the `(` is read), checks their number,
    /// expands them and substitutes them: the replacement tokens, or `None` after an error.
    fn collect_arguments(
        &mut self,
        ex: &mut Expander,
        m: &Macro,
        name: &Tok,
        open: &Tok,
    ) -> Option<Vec<Tok>> {
        let params = m.params.as_ref().expect("function-like");
        let mut args: Vec<Vec<Tok>> = vec![Vec::new()];
        let mut depth = 1usize;
        let close = loop {
            let t = self.raw_get(ex);
            match t.t.kind {
                PpKind::Eof => {
                    self.report_unterminated_call(m, name, open);
                    ex.pending = Some(t);
                    ex.failed = true;
                    return None;
                }
                PpKind::Punct(Punct::LeftParen) => depth += 1,
                PpKind::Punct(Punct::RightParen) => {
                    depth -= 1;
                    if depth == 0 {
                        break t;
                    }
                }
                PpKind::Punct(Punct::Comma) if depth == 1 => {
                    args.push(Vec::new());
                    continue;
                }
                _ => {}
            }
            args.last_mut().expect("one argument at least").push(t);
        };
        if params.is_empty() && args.len() == 1 && args[0].is_empty() {
            args.clear();
        }
        let span = name.t.span.to(close.t.span);
        if args.len() != params.len() {
            self.report_argument_count(m, span, args.len());
            ex.failed = true;
            return None;
        }
        // The expanded arguments and the replacement count against the tokens that this
        // expander's expansions in progress hold, as in ANGLE.
        let room = MAX_CONTEXT_TOKENS.saturating_sub(ex.in_contexts);
        let mut expanded = Vec::with_capacity(args.len());
        let mut counted = 0;
        for a in args {
            match self.pre_expand(ex, a, name, room.saturating_sub(counted)) {
                Ok(a) => {
                    counted += a.len();
                    expanded.push(a);
                }
                Err(failure) => {
                    match failure {
                        ArgFailure::TooLarge => self.report_context_tokens(m, name),
                        ArgFailure::TooDeep => ex.too_deep = true,
                    }
                    // The call is dropped, as the calls around it will be.
                    ex.failed = true;
                    return None;
                }
            }
        }
        let args = expanded;
        let mut out = Vec::new();
        for b in &m.body {
            if out.len() > room {
                self.report_context_tokens(m, name);
                ex.failed = true;
                return None;
            }
            match b {
                Body::Tok(pt) => {
                    let mut t = pt.clone();
                    t.span = span;
                    t.from_macro = true;
                    out.push(Tok {
                        t,
                        loc: close.loc,
                        orig: pt.span,
                        no_expand: false,
                    });
                }
                Body::Param {
                    index,
                    space_before,
                    ..
                } => {
                    for (k, a) in args[*index].iter().enumerate() {
                        let mut a = a.clone();
                        // An argument keeps where it is written (or the span of the
                        // invocation in the text it comes from): a diagnostic of
                        // `normalize(v - p)` inside `saturate(…)` points at `v - p`.
                        a.t.from_macro = true;
                        a.loc = close.loc;
                        if k == 0 {
                            a.t.space_before = *space_before;
                        }
                        out.push(a);
                    }
                }
            }
        }
        if let Some(first) = out.first_mut() {
            first.t.space_before = name.t.space_before;
        }
        Some(out)
    }

    /// Fully expands one macro argument on its own, into at most `room` tokens.
    fn pre_expand(
        &mut self,
        outer: &mut Expander,
        arg: Vec<Tok>,
        name: &Tok,
        room: usize,
    ) -> Result<Vec<Tok>, ArgFailure> {
        if arg.is_empty() {
            return Ok(arg);
        }
        if outer.depth >= MAX_ARGUMENT_NESTING {
            if !self.depth_reported {
                self.report_nesting(name);
            }
            return Err(ArgFailure::TooDeep);
        }
        let end = arg.last().map(|t| t.t.span.end_point()).unwrap_or_default();
        let mut list = arg;
        list.push(Tok::raw(PpToken {
            kind: PpKind::Eof,
            span: end,
            text: Name::default(),
            space_before: false,
            from_macro: false,
        }));
        let mut sub = Expander::list(list, outer.if_mode, outer.depth + 1);
        let mut out = Vec::new();
        loop {
            let t = self.expand_next(&mut sub);
            if t.t.kind == PpKind::Eof {
                break;
            }
            if out.len() == room {
                outer.failed = true;
                return Err(ArgFailure::TooLarge);
            }
            out.push(t);
        }
        outer.failed |= sub.failed;
        if sub.too_deep {
            // A call nested too deep inside: drop the calls around it too.
            return Err(ArgFailure::TooDeep);
        }
        Ok(out)
    }

    #[cold]
    #[inline(never)]
    fn report_context_tokens(&mut self, m: &Macro, name: &Tok) {
        if self.context_tokens_reported {
            return;
        }
        self.context_tokens_reported = true;
        self.push_diag(
            Diagnostic::error(
                Code::MacroExpansionTooLarge,
                format!(
                    "expanding `{}` needs more than {MAX_CONTEXT_TOKENS} tokens at once",
                    m.name
                ),
                name.t.span,
            )
            .with_label("this call expands past the limit")
            .with_note(format!(
                "WebGL implementations hold at most {MAX_CONTEXT_TOKENS} tokens of macro \
                 expansions in progress; Chromium reports \"out of memory\" here"
            ))
            .with_help(
                "a macro that repeats its argument grows exponentially when nested: use a \
                 function instead",
            )
            .with_token(&*m.name),
        );
    }

    #[cold]
    #[inline(never)]
    fn report_budget(&mut self, m: &Macro, t: &Tok) {
        self.budget_reported = true;
        self.push_diag(
            Diagnostic::error(
                Code::MacroExpansionTooLarge,
                format!("macro expansion produces more than {} tokens", self.budget),
                t.t.span,
            )
            .with_label(format!("expanding `{}` goes past the limit", m.name))
            .with_note("macros are not expanded after this point")
            .with_help("check for macros that expand to several copies of each other")
            .with_token(&*m.name),
        );
    }

    #[cold]
    #[inline(never)]
    fn report_unterminated_call(&mut self, m: &Macro, name: &Tok, open: &Tok) {
        self.push_diag(
            Diagnostic::error(
                Code::UnterminatedMacroCall,
                format!("unterminated call of macro `{}`", m.name),
                open.t.span,
            )
            .with_label("this `(` is never closed")
            .with_secondary(name.t.span, "the macro")
            .with_help("add the missing `)`")
            .with_token(&*m.name),
        );
    }

    #[cold]
    #[inline(never)]
    fn report_argument_count(&mut self, m: &Macro, span: Span, given: usize) {
        let params = m.params.as_deref().unwrap_or_default();
        let n = params.len();
        let plural = |k: usize| if k == 1 { "argument" } else { "arguments" };
        let mut d = Diagnostic::error(
            Code::MacroArgumentCount,
            format!(
                "macro `{}` takes {n} {}, but {given} {} given",
                m.name,
                plural(n),
                if given == 1 { "was" } else { "were" }
            ),
            span,
        )
        .with_label(format!("{given} {} here", plural(given)))
        .with_help(format!("call it as `{}({})`", m.name, params.join(", ")))
        .with_token(&*m.name);
        if !m.span.is_empty() {
            d = d.with_secondary(m.span, "defined here");
        }
        self.push_diag(d);
    }

    #[cold]
    #[inline(never)]
    fn report_nesting(&mut self, name: &Tok) {
        self.depth_reported = true;
        self.push_diag(
            Diagnostic::error(
                Code::MacroNestingTooDeep,
                format!(
                    "macro calls nested more than {MAX_ARGUMENT_NESTING} levels deep in arguments"
                ),
                name.t.span,
            )
            .with_label("too deep here")
            .with_note("WebGL implementations refuse deeper macro calls (Chromium: \"macro invocation chain too deep\")")
            .with_token(&*name.t.text),
        );
    }

    /// `defined NAME` or `defined ( NAME )` in an `#if` line (`defined` is read): a number token
    /// `1` or `0`. The name is not expanded.
    fn defined_operator(&mut self, ex: &mut Expander, op: Tok) -> Tok {
        if op.t.from_macro && !ex.failed {
            ex.failed = true;
            let mut d = Diagnostic::error(
                Code::DefinedFromMacro,
                "`defined` produced by a macro expansion",
                op.t.span,
            )
            .with_label("this macro expands to `defined`")
            .with_note("GLSL ES 3.00 leaves this undefined; WebGL rejects it")
            .with_help("write `defined(NAME)` directly in the `#if` line")
            .with_token("defined");
            if op.orig != op.t.span && !op.orig.is_empty() {
                d = d.with_secondary(op.orig, "`defined` is written here");
            }
            self.push_diag(d);
        }
        let mut t = self.raw_get(ex);
        let paren = t.t.is(Punct::LeftParen);
        let open = t.clone();
        if paren {
            t = self.raw_get(ex);
        }
        let value = |span: Span, v: bool| Tok {
            t: number_token(if v { "1" } else { "0" }, span, op.t.from_macro),
            loc: op.loc,
            orig: span,
            no_expand: false,
        };
        if t.t.kind != PpKind::Ident {
            if !ex.failed {
                ex.failed = true;
                let found = super::describe(&t.t);
                self.push_diag(
                    Diagnostic::error(
                        Code::InvalidDefined,
                        format!("expected a macro name after `defined`, found {found}"),
                        if t.t.kind == PpKind::Eof {
                            op.t.span
                        } else {
                            t.t.span
                        },
                    )
                    .with_label("a macro name must follow `defined`")
                    .with_help("write `defined(NAME)` or `defined NAME`")
                    .with_token(&*t.t.text),
                );
            }
            if t.t.kind == PpKind::Eof {
                ex.pending = Some(t);
            }
            return value(op.t.span, false);
        }
        let v = self.macros.contains_key(&t.t.text);
        let mut span = op.t.span.to(t.t.span);
        if paren {
            let close = self.raw_get(ex);
            if !close.t.is(Punct::RightParen) {
                if !ex.failed {
                    ex.failed = true;
                    self.push_diag(
                        Diagnostic::error(
                            Code::InvalidDefined,
                            format!(
                                "expected `)` after `defined({}`, found {}",
                                t.t.text,
                                super::describe(&close.t)
                            ),
                            if close.t.kind == PpKind::Eof {
                                t.t.span.end_point()
                            } else {
                                close.t.span
                            },
                        )
                        .with_label("expected `)`")
                        .with_secondary(open.t.span, "to close this `(`")
                        .with_token(&*close.t.text),
                    );
                }
                ex.pending = Some(close);
            } else {
                span = span.to(close.t.span);
            }
        }
        value(span, v)
    }
}
