//! Directives about the shader's language and position: `#version` (first, and which
//! version), `#extension` (name, behavior, before any code) and `#line`.

use super::Directive;
use crate::diagnostic::{Applicability, Diagnostic, Edit, Fix, Severity};
use crate::diagnostic_code::Code;
use crate::lex::{PpKind, PpToken, Punct};
use crate::preprocess::expr::ExprParser;
use crate::preprocess::{describe, ExtensionBehavior, LineDirective, Pp, Version};
use crate::source::Span;
use crate::target::Target;

impl Pp<'_> {
    pub(super) fn d_extension(&mut self, d: &Directive) {
        let args = d.args();
        let Some(name) = self.extension_name(d) else {
            return;
        };
        let Some((bt, behavior)) = self.extension_behavior(d) else {
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
                    Code::ExtensionAfterCode.as_str(),
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
        if !self.check_extension_support(d, name, bt, behavior) {
            return;
        }
        self.extensions.push((n.to_string(), behavior, d.span()));
    }

    /// `#extension NAME :`: the extension's name token, or `None` (reported) when the name or
    /// the colon is missing.
    fn extension_name<'d>(&mut self, d: &'d Directive) -> Option<&'d PpToken> {
        let shape = "`#extension` takes `name : behavior`";
        let args = d.args();
        let name = match args.first() {
            None => {
                self.push_diag(
                    Diagnostic::error(Code::InvalidExtensionDirective, shape, d.name_span())
                        .with_label("expected an extension name")
                        .with_help("write `#extension NAME : behavior`")
                        .with_token("\n"),
                );
                return None;
            }
            Some(t) if t.kind != PpKind::Ident => {
                self.push_diag(
                    Diagnostic::error(
                        Code::InvalidExtensionName,
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
                return None;
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
                        Code::InvalidExtensionDirective,
                        format!("expected `:` after the extension name, found {found}"),
                        span,
                    )
                    .with_label("expected `:`")
                    .with_help(shape)
                    .with_token(token),
                );
                return None;
            }
        }
        Some(name)
    }

    /// The behavior after `:`: its token and value, or `None` (reported) when missing or
    /// unknown.
    fn extension_behavior<'d>(
        &mut self,
        d: &'d Directive,
    ) -> Option<(&'d PpToken, ExtensionBehavior)> {
        let args = d.args();
        let behaviors = "`require`, `enable`, `warn` or `disable`";
        let Some(bt) = args.get(2) else {
            self.push_diag(
                Diagnostic::error(
                    Code::InvalidExtensionBehavior,
                    format!("expected {behaviors} after `:`"),
                    d.end(),
                )
                .with_label("expected a behavior")
                .with_help("the behaviors are `require`, `enable`, `warn` and `disable`")
                .with_token("\n"),
            );
            return None;
        };
        let behavior = if bt.kind == PpKind::Ident {
            ExtensionBehavior::from_str(&bt.text)
        } else {
            None
        };
        let Some(behavior) = behavior else {
            let mut e = Diagnostic::error(
                Code::InvalidExtensionBehavior,
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
            return None;
        };
        Some((bt, behavior))
    }

    /// `all` takes only `warn` or `disable`; another extension must be one essl supports
    /// (reported, an error when required). `false` when the directive is to be dropped.
    fn check_extension_support(
        &mut self,
        d: &Directive,
        name: &PpToken,
        bt: &PpToken,
        behavior: ExtensionBehavior,
    ) -> bool {
        let n = &*name.text;
        if n == "all" {
            if matches!(
                behavior,
                ExtensionBehavior::Require | ExtensionBehavior::Enable
            ) {
                self.push_diag(
                    Diagnostic::error(
                        Code::ExtensionAllBehavior,
                        format!("`#extension all` cannot be `{}`", behavior.as_str()),
                        bt.span,
                    )
                    .with_label("`all` takes only `warn` or `disable`")
                    .with_help("name the extension to require or enable it")
                    .with_token(&*bt.text),
                );
                return false;
            }
        } else if !self.options.extensions.iter().any(|e| e == n) {
            let require = behavior == ExtensionBehavior::Require;
            let mut e = Diagnostic::new(
                if require {
                    Severity::Error
                } else {
                    Severity::Warning
                },
                Code::ExtensionNotSupported.as_str(),
                format!("extension `{n}` is not supported"),
                name.span,
            )
            .with_label(if require { "required here" } else { "ignored" })
            .with_token(n);
            e = match (crate::target::Extension::from_name(n), self.options.target) {
                (Some(ext), t) if ext.offered_by(t) => e
                    .with_note(format!(
                        "the {} context has not enabled `{}`",
                        t.display(),
                        ext.webgl_name()
                    ))
                    .with_help(format!(
                        "enable it in the context first: `gl.getExtension('{}')`",
                        ext.webgl_name()
                    )),
                (Some(ext), Target::WebGl1) => e
                    .with_note(format!(
                        "`{}` is a WebGL 2 extension, for GLSL ES 3.00 shaders",
                        ext.webgl_name()
                    ))
                    .with_help("write the shader in GLSL ES 3.00 for a WebGL 2 context"),
                (Some(_), Target::WebGl2) if self.version == Version::Es300 => e
                    .with_note("its features are part of GLSL ES 3.00, under their core names")
                    .with_help("remove the directive")
                    .with_fix(Fix::suggested("remove the directive", d.whole_line(), "")),
                (Some(_), Target::WebGl2) => e
                    .with_note(
                        "WebGL 2 made this WebGL 1 extension part of GLSL ES 3.00 and offers it \
                         to no GLSL ES 1.00 shader",
                    )
                    .with_help("write the shader in GLSL ES 3.00 (`#version 300 es`), which has its features built in"),
                (None, _) => e.with_help(format!(
                    "remove the directive, or use an extension {} and essl support",
                    self.options.target.display()
                )),
            };
            self.push_diag(e);
        }
        true
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

    pub(super) fn d_version(&mut self, d: &Directive) {
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
                        Code::InvalidVersion,
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
                    Code::InvalidVersion,
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
                    Code::VersionNotFirst,
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
                    Code::VersionNotFirstLine,
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
            Version::Es100 => {}
            Version::Es300 if self.options.target == Target::WebGl2 => {}
            Version::Es300 => self.push_diag(
                Diagnostic::error(
                    Code::UnsupportedVersion,
                    "`#version 300 es` is GLSL ES 3.00, which WebGL 1 does not compile",
                    number_span,
                )
                .with_label("GLSL ES 3.00")
                .with_note("a WebGL 1 context compiles GLSL ES 1.00 only; WebGL 2 compiles both")
                .with_help("compile it for WebGL 2, or write it in GLSL ES 1.00 (remove the `#version` line, and use `attribute`/`varying`, `texture2D` and `gl_FragColor`)")
                .with_token("300"),
            ),
            Version::Other(..) => self.push_diag(
                Diagnostic::error(
                    Code::UnsupportedVersion,
                    format!(
                        "GLSL version `{n}{}` is not supported by {}",
                        if es { " es" } else { "" },
                        self.options.target.display()
                    ),
                    number_span,
                )
                .with_label("not supported")
                .with_help(if self.options.target == Target::WebGl2 {
                    "WebGL 2 compiles `#version 300 es` and `#version 100` (GLSL ES 1.00)"
                } else {
                    "WebGL 1 compiles `#version 100` (GLSL ES 1.00)"
                })
                .with_fix(if self.options.target == Target::WebGl2 {
                    Fix::suggested("write `300 es`", number_span, "300 es")
                } else {
                    Fix::suggested("write `100`", number_span, "100")
                })
                .with_token(&*args[0].text),
            ),
        }
    }

    pub(super) fn d_line(&mut self, d: &Directive) {
        if d.args().is_empty() {
            self.push_diag(
                Diagnostic::error(
                    Code::InvalidLineDirective,
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
                    Code::ExtraTokens,
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
}
