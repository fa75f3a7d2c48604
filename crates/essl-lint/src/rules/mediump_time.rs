//! `mediump-time`: the animation's time in a `mediump` or `lowp` uniform, whose steps grow with
//! the time itself.
//!
//! The rule reads the checked module only (a uniform's name, type and precision, declared or
//! by default) and reports at the declaration: how much time passes between two values the
//! variable can hold is the host's business, not any expression's.

use essl::diagnostic::{Diagnostic, Fix};
use essl::hir::GlobalKind;
use essl::source::Span;
use essl::types::{Precision, Type};

use super::rule::declare_rule;
use super::Cx;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports a `float` uniform whose name says it holds the time since the animation started
    /// (`iTime`, `u_time`, `time`, `iGlobalTime`, `uElapsedTime`) when it is `mediump` or `lowp`,
    /// declared so or by the shader's default precision (`precision mediump float;`).
    ///
    /// ## Why is this bad?
    /// Phones run `mediump` as 16-bit floats: 11 significant bits. The time a page has been open
    /// then moves in steps of 0.25 s after 4 minutes, 0.5 s after 8.5 minutes and 2 s after 34
    /// minutes, so `sin(iTime * 3.0)` stops animating smoothly, then jumps, and noise scrolled by
    /// the time freezes between steps. Desktop GPUs compute `mediump` in 32 bits and show nothing.
    /// A host that passes milliseconds (`performance.now()` as it comes) breaks it within a
    /// minute: steps of 32 ms after 33 s, infinity after 65.5 s. (Past 65504 s, 18 hours, a time
    /// in seconds is infinite; what `iTime * 30.0` reaches after an hour is `mediump-overflow`'s.)
    ///
    /// ## Example
    /// ```glsl
    /// precision mediump float;
    /// uniform float iTime;
    /// …
    /// float wave = sin(iTime * 3.0 + uv.x * 10.0);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// precision mediump float;
    /// uniform highp float iTime;
    /// …
    /// highp float phase = iTime * 3.0;
    /// float wave = sin(phase + uv.x * 10.0);
    /// ```
    /// Declare the uniform `highp` (the fix does), and keep `highp` the arithmetic that needs the
    /// time's precision: an operation takes the precision of its operands. Or have the host wrap
    /// the time to a period the animation repeats with (`(now / 1000) % 60.0`). In WebGL 1,
    /// `highp` in a fragment shader needs `#ifdef GL_FRAGMENT_PRECISION_HIGH`.
    ///
    /// ## What it does not flag
    /// - A `highp` time, and a time in a vertex shader (where `float` defaults to `highp`) that does
    ///   not ask for less.
    /// - Names of other quantities that hold small values: `deltaTime`, `timeScale`, `fadeTime`,
    ///   `lifetime`, `timeOffset`.
    /// - A time the entry point never reads.
    ///
    /// Severity: a note. How long a page stays open, and whether the host wraps the time, is the
    /// program's to know.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §4.5.2 Precision Qualifiers (`mediump`: relative precision
    ///   2^-10).
    /// - IEEE 754 binary16: 11 significant bits.
    pub(crate) struct MediumpTime {
        id: "mediump-time",
        summary: "the animation's time in a `mediump` or `lowp` uniform, which moves in steps of seconds once a page has been open half an hour",
        default_level: Level::Note,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let text = cx.file.text();
    for g in &cx.hir.globals {
        let low = matches!(g.precision, Some(Precision::Medium | Precision::Low));
        let uniform = matches!(g.kind, GlobalKind::Uniform | GlobalKind::BlockMember(..));
        if !g.used || !low || !uniform || g.span.is_empty() || g.ty != Type::FLOAT {
            continue;
        }
        if !crate::analysis::names::says_time(&g.name) {
            continue;
        }
        // A block's member is declared at the block: its own name in it.
        let span = name_in(text, g.span, &g.name);
        let p = if g.precision == Some(Precision::Low) {
            "lowp"
        } else {
            "mediump"
        };
        let mut d = Diagnostic::rule_note(
            MediumpTime::RULE.id,
            format!("the animation's time `{}` is `{p}`: in 16 bits it moves in steps of 0.5 s after 8.5 minutes, 2 s after 34", g.name),
            span,
        )
        .with_label(format!("a time in seconds, `{p}`"))
        .with_note("phones run mediump and lowp as 16-bit floats (11 significant bits); desktop GPUs run them in 32 bits")
        .with_help("declare it `highp` and compute with it in `highp`, or wrap the time on the host");
        if let Some(fix) = highp_fix(text, span, p) {
            d = d.with_fix(fix);
        }
        out.push(d);
    }
}

/// Where `name` is, as a word, in the text at `span` (the span itself where it is not).
fn name_in(text: &str, span: Span, name: &str) -> Span {
    let (s, e) = (span.start as usize, span.end as usize);
    let Some(within) = text.get(s..e) else {
        return span;
    };
    find_word(within, name).map_or(span, |i| {
        Span::new((s + i) as u32, (s + i + name.len()) as u32)
    })
}

/// Where `w` is in `text` as a word of its own (not part of a longer name).
fn find_word(text: &str, w: &str) -> Option<usize> {
    let b = text.as_bytes();
    let part = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    text.match_indices(w)
        .map(|(i, _)| i)
        .find(|&i| (i == 0 || !part(b[i - 1])) && (i + w.len() == b.len() || !part(b[i + w.len()])))
}

/// The edit that declares the variable named at `span` `highp`: its `mediump` or `lowp`
/// replaced, or `highp ` inserted before `float` where the default precision made it `p`.
/// `None` where the declaration is not `[qualifiers] [precision] float name` on one line.
fn highp_fix(text: &str, span: Span, p: &str) -> Option<Fix> {
    let (start, decl) = super::lowp_range::declaration_before(text, span)?;
    let at = |i: usize, len: usize| Span::new((start + i) as u32, (start + i + len) as u32);
    if let Some(i) = find_word(decl, p) {
        return Some(Fix::suggested(
            "declare it `highp`",
            at(i, p.len()),
            "highp",
        ));
    }
    let i = find_word(decl, "float")?;
    Some(Fix::suggested("declare it `highp`", at(i, 0), "highp "))
}
