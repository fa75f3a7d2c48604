//! The lints on the configurations a shader's `#ifdef`s select: the code a flag such as
//! `CLIPPLANE`, `ALPHATEST` or `USE_FOG` compiles in is code the application runs whenever it
//! sets that flag — engines build most shaders from one text that way — but a check with the
//! defines of one configuration never sees it.
//!
//! [`flags`] reads the conditional directives of a text and gives, for each group a flag turns
//! on, the macros that select it (its own flag and those of the groups around it). [`lint`]
//! compiles the text once per such configuration, with the macros defined as `1` before the
//! first line (as `-D NAME` would), lints it, and keeps the findings the configuration checked
//! already does not have, each with a note naming the macros. A configuration whose only
//! errors are names spelled as macros that nothing declares (Cesium's `SDF_EDGE`, which the
//! host defines with `SDF`) is compiled once more with those defined as `1.0`. So is, with the
//! macro defined as 1, a count the text lets its includer set (`#ifndef RAYMARCH_AO_SAMPLES`,
//! `#define RAYMARCH_AO_SAMPLES 5`, a loop's bound): one iteration is the fewest a user can ask
//! for, and where `1.0 / float(RAYMARCH_AO_SAMPLES - 1)` divides by zero; the front end's
//! warning of that folded division is a finding of `division-by-difference` there. And a
//! choice between functions (`#ifndef DIFFUSE_FNC`, `#define DIFFUSE_FNC diffuseLambert` under
//! one flag and `diffuseOrenNayar` under another) is compiled with each of them: the function
//! the flags' configurations leave uncalled is code an includer runs by choosing it. And a
//! level the conditionals compare (`#ifndef NUM_BONE_INFLUENCERS`, `#define
//! NUM_BONE_INFLUENCERS 0`, `#if NUM_BONE_INFLUENCERS > 0`) is compiled at the largest value one
//! comparison needs (which turns every `>` and `>=` group on), and with it any flag's configuration that does not compile
//! without (the groups that compare it declare what the flag's code uses).
//!
//! Written by hand: the directive lines are read with a line scanner, not the preprocessor,
//! because the groups inside skipped groups matter here and the preprocessor does not
//! evaluate them; an expression only gives names here, never a value.

use std::collections::{HashMap, HashSet};

use essl::diagnostic::Diagnostic;
use essl::source::{SourceFile, Span};
use essl::{CompileOptions, Shader};

use crate::LintOptions;

mod lines;
mod settings;

use lines::{directive_lines, first_name, identifiers, strip_comments, tested};

/// How many configurations of [`flags`] a check lints by default, besides the one it compiled
/// (and the one with all of them that compile): every group of the corpora's engine materials
/// (16 left hazards of Babylon's particles and normal material unreached), a bound on the cost
/// of a text with hundreds.
pub const DEFAULT: usize = 64;

/// The most macros one configuration defines: groups nested deeper than that in flags are left
/// alone.
const MAX_NAMES: usize = 32;

/// One configuration a group of conditional code needs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Variant {
    /// The macros to define, in the order the directives name them.
    pub defines: Vec<String>,
    /// The directive that opens its first group.
    pub directive: Span,
    /// The code of each group it turns on: from the end of the directive's line to the next
    /// directive of its block.
    pub groups: Vec<Span>,
    /// For a count rather than a flag (`settings::counts`): the value the text gives it unless
    /// it is defined before; the configuration defines it as 1.
    pub count: Option<String>,
    /// For a choice rather than a flag (`settings::choices`): the value the configuration
    /// defines the macro as, one of those the text chooses between.
    pub choice: Option<String>,
    /// For a level rather than a flag (`settings::levels`): the value the configuration defines
    /// the macro as, and the value the text gives it unless it is defined before.
    pub level: Option<(String, String)>,
}

/// A conditional block being read.
struct Block {
    /// The macros the block's surroundings need.
    outer: Vec<String>,
    /// The macros whose definition turns the block's earlier groups off (for its `#else`).
    negated: Vec<String>,
    /// The macros the open group needs, its surroundings' included.
    current: Vec<String>,
    /// The open group, if it needs anything: its index in the output.
    open: Option<usize>,
}

/// The configurations that turn on each conditional group of `text` the options' defines and
/// the text's own `#define`s leave undecided, first seen first, each once, where a group holds
/// something a rule looks at (a call of a function other than a constructor, `discard`, a
/// division, a local declared without a value). Names reserved to the implementation (`GL_…`, `__…`) and
/// names the text defines itself are never defined.
pub fn flags(text: &str, options: &CompileOptions) -> Vec<Variant> {
    // Most shaders have no conditional: a search for `#if` is all they cost.
    let conditional = text.match_indices('#').any(|(i, _)| {
        let rest = text[i + 1..].trim_start_matches([' ', '\t']);
        rest.starts_with("if") || rest.starts_with("el")
    });
    if !conditional {
        return Vec::new();
    }
    let lines = directive_lines(text);
    let defined: HashSet<&str> = lines
        .iter()
        .filter(|l| l.name == "define")
        .filter_map(|l| identifiers(&l.args).next().map(|(w, _)| w))
        .chain(options.defines.iter().map(|(n, _)| n.as_str()))
        .collect();
    let usable = |w: &str| !w.starts_with("GL_") && !w.starts_with("__") && !defined.contains(w);
    let mut out: Vec<Variant> = Vec::new();
    let mut seen: HashMap<Vec<String>, usize> = HashMap::new();
    let mut blocks: Vec<Block> = Vec::new();
    for l in &lines {
        // A directive ends the open group of its block.
        let close = |blocks: &mut Vec<Block>, out: &mut Vec<Variant>| {
            if let Some(i) = blocks.last_mut().and_then(|b| b.open.take()) {
                if let Some(g) = out[i].groups.last_mut() {
                    g.end = l.span.start;
                }
            }
        };
        let (positive, negative): (Vec<String>, Vec<String>) = match l.name.as_str() {
            "ifdef" => (first_name(&l.args), Vec::new()),
            "ifndef" => (Vec::new(), first_name(&l.args)),
            "if" | "elif" => tested(&l.args),
            "else" => (Vec::new(), Vec::new()),
            "endif" => {
                close(&mut blocks, &mut out);
                blocks.pop();
                continue;
            }
            _ => continue,
        };
        if matches!(l.name.as_str(), "elif" | "else") {
            close(&mut blocks, &mut out);
        } else {
            let outer = blocks.last().map(|b| b.current.clone()).unwrap_or_default();
            blocks.push(Block {
                outer,
                negated: Vec::new(),
                current: Vec::new(),
                open: None,
            });
        }
        let Some(block) = blocks.last_mut() else {
            continue;
        };
        let mut needs = block.outer.clone();
        if l.name == "else" {
            needs.extend(block.negated.iter().cloned());
        } else {
            needs.extend(positive);
            block.negated.extend(negative);
        }
        needs.retain(|w| usable(w));
        let mut unique: Vec<String> = Vec::new();
        for w in needs {
            if !unique.contains(&w) {
                unique.push(w);
            }
        }
        if unique.len() > MAX_NAMES {
            // Past any real configuration (and quadratic in nesting a text can make deep).
            block.current = block.outer.clone();
            continue;
        }
        block.current = unique.clone();
        let mut key = unique.clone();
        key.sort();
        if unique.len() == block.outer.len() {
            continue;
        }
        let group = Span::new(l.next, text.len() as u32);
        let i = *seen.entry(key).or_insert_with(|| {
            out.push(Variant {
                defines: unique,
                directive: l.span,
                groups: Vec::new(),
                count: None,
                choice: None,
                level: None,
            });
            out.len() - 1
        });
        out[i].groups.push(group);
        block.open = Some(i);
    }
    out.retain(|v| v.groups.iter().any(|g| hazardous(&text[g.range()])));
    // A level first: the flags' configurations that need it set it too, and what its own
    // groups hold is then found with it alone.
    out.splice(0..0, settings::levels(&lines, options));
    out.extend(settings::counts(text, &lines, options));
    out.extend(settings::choices(text, &lines, options));
    out
}

/// Whether `code` calls a function other than a constructor: a function the text defines
/// may hold the hazard (Cesium's `czm_nearFarScalar`, called only under
/// `EYE_DISTANCE_SCALING`), and a built-in one computes a value a finding elsewhere reads.
fn calls_a_function(code: &str) -> bool {
    const NOT_CALLS: [&str; 6] = ["if", "for", "while", "switch", "return", "layout"];
    code.match_indices('(').any(|(i, _)| {
        let before = code[..i].trim_end();
        // After the last character that is not part of a name (any width: the text may
        // hold U+FFFD where the file was not UTF-8).
        let start = before
            .char_indices()
            .rev()
            .find(|&(_, c)| !c.is_ascii_alphanumeric() && c != '_')
            .map_or(0, |(j, c)| j + c.len_utf8());
        let name = &before[start..];
        let constructor = ["float", "int", "uint", "bool"].contains(&name)
            || ["vec", "ivec", "uvec", "bvec", "mat"].iter().any(|p| {
                name.strip_prefix(p)
                    .is_some_and(|r| r.len() <= 3 && !r.is_empty())
            });
        !name.is_empty()
            && !name.starts_with(|c: char| c.is_ascii_digit())
            && !constructor
            && !NOT_CALLS.contains(&name)
    })
}

/// The built-in functions whose arguments a rule looks at, and `discard`.
const HAZARD_WORDS: [&str; 24] = [
    "pow",
    "acos",
    "asin",
    "atan",
    "smoothstep",
    "clamp",
    "normalize",
    "sqrt",
    "inversesqrt",
    "log",
    "log2",
    "mod",
    "texture",
    "texture2D",
    "textureCube",
    "textureProj",
    "texture2DProj",
    "texelFetch",
    "texelFetchOffset",
    "textureOffset",
    "dFdx",
    "dFdy",
    "fwidth",
    "discard",
];

/// Whether a group's code has something a rule looks at: a division or remainder, a call of
/// one of [`HAZARD_WORDS`] or of any function but a constructor, a local declared without a
/// value. A group with none (declarations, a constant, a colour) rarely changes a finding
/// elsewhere, and compiling its configuration
/// would be most of the cost on code without hazards (the dEQP preprocessor tests).
fn hazardous(text: &str) -> bool {
    let mut in_comment = false;
    let code: String = text
        .lines()
        .map(|l| strip_comments(l, &mut in_comment) + "\n")
        .collect();
    let code = code.as_str();
    let division = code.contains(['/', '%']);
    division
        || identifiers(code).any(|(w, _)| HAZARD_WORDS.contains(&w))
        || calls_a_function(code)
        || code.lines().any(|l| {
            // `float x;`: a local a path may read unwritten.
            let t = l.trim();
            t.ends_with(';')
                && !t.contains('=')
                && !t.contains('(')
                && t.split_whitespace().count() == 2
                && ["float", "int", "vec", "ivec", "uvec", "bool", "mat", "uint"]
                    .iter()
                    .any(|p| t.starts_with(p))
        })
}

/// A finding of a configuration the shader as compiled does not have.
#[derive(Clone, Debug)]
pub struct Found {
    /// The finding, with a note naming the configuration.
    pub diagnostic: Diagnostic,
    /// The macros the configuration defines.
    pub defines: Vec<String>,
}

/// The findings of the first `max` of `variants` (from [`flags`]) that the shader as compiled
/// does not have (`base`: its findings with the same options), then those of one more
/// configuration with the macros of every one of them that compiled (flags are set together as
/// often as alone: a clip plane's `discard` before a diffuse texture's lookup), in source order.
/// A configuration that does not compile is passed over: its errors are the front end's
/// business in that configuration, not a lint's.
pub fn lint(
    shader: &Shader,
    compile: &CompileOptions,
    options: &LintOptions,
    base: &[Diagnostic],
    variants: &[Variant],
    max: usize,
) -> Vec<Found> {
    let mut seen: HashSet<(&'static str, Span)> = base.iter().map(|d| (d.code, d.span)).collect();
    let mut out = Vec::new();
    let mut together: Vec<String> = Vec::new();
    let mut compiled = 0;
    // A flag's group may use what a level's declares (Babylon's baked vertex animation reads
    // the bone attributes `NUM_BONE_INFLUENCERS > 0` declares).
    let levels: Vec<(String, String)> = variants
        .iter()
        .filter_map(|v| Some((v.defines.first()?.clone(), v.level.as_ref()?.0.clone())))
        .collect();
    let singles = variants.iter().take(max);
    for v in singles {
        let flag = v.count.is_none() && v.choice.is_none() && v.level.is_none();
        let levels = if flag { &levels[..] } else { &[] };
        let cx = Context {
            shader,
            compile,
            options,
            levels,
        };
        if configuration(&cx, v, false, &mut seen, &mut out) && flag {
            compiled += 1;
            for w in &v.defines {
                if !together.contains(w) {
                    together.push(w.clone());
                }
            }
        }
    }
    if compiled > 1 {
        let all = Variant {
            defines: together,
            directive: Span::default(),
            groups: variants
                .iter()
                .take(max)
                .flat_map(|v| v.groups.iter().copied())
                .collect(),
            count: None,
            choice: None,
            level: None,
        };
        let cx = Context {
            shader,
            compile,
            options,
            levels: &[],
        };
        configuration(&cx, &all, true, &mut seen, &mut out);
    }
    out.sort_by_key(|f| (f.diagnostic.span.start, f.diagnostic.span.end));
    out
}

/// What every configuration of one shader is compiled and linted with.
struct Context<'a> {
    shader: &'a Shader,
    compile: &'a CompileOptions,
    options: &'a LintOptions,
    /// The levels to set, each (name, value), where the configuration does not compile
    /// without.
    levels: &'a [(String, String)],
}

/// Compiles and lints one configuration, adding the findings not `seen` yet; whether it
/// compiled.
fn configuration(
    cx: &Context,
    v: &Variant,
    together: bool,
    seen: &mut HashSet<(&'static str, Span)>,
    out: &mut Vec<Found>,
) -> bool {
    let Context {
        shader,
        compile,
        options,
        levels,
    } = *cx;
    let mut with = compile.clone();
    let value = (v.choice.clone())
        .or_else(|| v.level.as_ref().map(|l| l.0.clone()))
        .unwrap_or_else(|| "1".to_string());
    with.defines
        .extend(v.defines.iter().map(|n| (n.clone(), value.clone())));
    let file = || SourceFile::new(shader.file.name(), shader.file.text());
    // Lowered (typed, not validated) where a lint on the IR has something to look at, as
    // `essl lint` lowers the configuration as written.
    let typed = |with: &essl::CompileOptions| {
        let mut s = essl::compile_front_end(file(), shader.stage, with);
        if crate::needs_ir(&s) {
            s.lower_typed();
        }
        s
    };
    let mut compiled = typed(&with);
    let mut constants = Vec::new();
    if !compiled.ok() {
        // A group that uses constants the host defines with its flag (Cesium's `SDF_EDGE`
        // with `SDF`): once more with them defined as `1.0`.
        constants = host_constants(&compiled.diagnostics);
        with.defines
            .extend(constants.iter().map(|n| (n.clone(), "1.0".to_string())));
        if !constants.is_empty() {
            compiled = typed(&with);
        }
    }
    let mut leveled = false;
    if !compiled.ok() && !levels.is_empty() {
        with.defines.extend(levels.iter().cloned());
        compiled = typed(&with);
        leveled = true;
    }
    if !compiled.ok() {
        return false;
    }
    let mut names = named(&v.defines);
    if !constants.is_empty() {
        names = format!(
            "{names} (and {}, which the text uses without defining, as 1.0)",
            named(&constants)
        );
    }
    let also = if leveled {
        let set: Vec<String> = levels
            .iter()
            .map(|(n, x)| format!("`{n}` set to {x}"))
            .collect();
        format!(
            "; {} as well, for the groups that compare it declare what this code uses",
            set.join(", ")
        )
    } else {
        String::new()
    };
    let found = crate::lint(&compiled, options);
    let folded = folded_divisions(shader, &compiled, options, v.count.is_some());
    for d in found.into_iter().chain(folded) {
        // A constant the host defines is 1.0 here for want of its value: a divisor it makes
        // always 0 says nothing of the shader.
        if !constants.is_empty() && d.message == crate::rules::ZERO_DIVISOR {
            continue;
        }
        if !seen.insert((d.code, d.span)) {
            continue;
        }
        let inside = v
            .groups
            .iter()
            .any(|g| g.start <= d.span.start && d.span.end <= g.end);
        let note = if let Some(choice) = &v.choice {
            format!(
                "found by compiling the configuration with {names} defined as `{choice}`, one of \
                 the functions the text chooses between unless its includer defines it"
            )
        } else if let Some((value, default)) = &v.level {
            format!(
                "found by compiling the configuration with {names} defined as {value}, a level \
                 the text sets to {default} unless its includer defines it, which turns on every \
                 group that compares it"
            )
        } else if let Some(value) = &v.count {
            format!(
                "found by compiling the configuration with {names} defined as 1, a count the \
                 text sets to {value} unless its includer defines it"
            )
        } else if together {
            format!(
                "found by compiling the configuration with every flag that compiles alone \
                 defined ({names})"
            )
        } else if inside {
            format!(
                "in code compiled only with {names} defined, which the configuration checked \
                 leaves out"
            )
        } else {
            format!("found by compiling the configuration with {names} defined")
        };
        out.push(Found {
            diagnostic: d.with_note(note + &also),
            defines: v.defines.clone(),
        });
    }
    true
}

/// The front end's warnings of a division by zero in a constant expression that the shader as
/// compiled does not have, as findings of `division-by-difference` (its severity and
/// suppressions; a note for a count set to 1): a configuration's constants make the divisor 0
/// (`1.0 / float(RAYMARCH_AO_SAMPLES - 1)`), and the fold leaves no division for a rule to
/// see.
fn folded_divisions(
    shader: &Shader,
    compiled: &Shader,
    options: &LintOptions,
    count: bool,
) -> Vec<Diagnostic> {
    const CODE: &str = "division-by-zero";
    let Some(rule) = crate::rule("division-by-difference") else {
        return Vec::new();
    };
    let base = |d: &Diagnostic| {
        shader
            .diagnostics
            .iter()
            .any(|b| b.code == CODE && b.span == d.span)
    };
    let new: Vec<&Diagnostic> = compiled
        .diagnostics
        .iter()
        .filter(|d| d.code == CODE && !d.is_error() && !base(d))
        .collect();
    if new.is_empty() {
        return Vec::new();
    }
    let allowed = crate::suppress::Allowed::scan(&compiled.file);
    let mut out = Vec::new();
    for d in new {
        if allowed.silences(&compiled.file, d.span, rule.id) {
            continue;
        }
        let mut f = Diagnostic::rule_warning(rule.id, d.message.clone(), d.span)
            .with_label(d.label.clone())
            .with_help("the quotient is undefined: keep the divisor from 0 in this configuration");
        if count {
            f.severity = essl::diagnostic::Severity::Note;
        }
        match options.level(rule).severity(f.severity) {
            Some(essl::diagnostic::Severity::Note) if !options.shows_notes() => {}
            Some(s) => {
                f.severity = s;
                out.push(f);
            }
            None => {}
        }
    }
    out
}

/// The names a configuration's errors say are not declared, where every error is one and each
/// is spelled as a macro is (`SDF_EDGE`: capitals, digits and `_`, not `GL_…` or `__…`); empty
/// otherwise.
fn host_constants(diagnostics: &[Diagnostic]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for d in diagnostics.iter().filter(|d| d.is_error()) {
        let name = d
            .message
            .strip_suffix("` is not declared")
            .and_then(|m| m.strip_prefix('`'));
        let macro_like = name.is_some_and(|n| {
            n.len() > 1
                && !n.starts_with("GL_")
                && !n.starts_with("__")
                && n.bytes().any(|b| b.is_ascii_uppercase())
                && n.bytes()
                    .all(|b| b.is_ascii_uppercase() || b.is_ascii_digit() || b == b'_')
        });
        match name {
            Some(n) if d.code == "undeclared-identifier" && macro_like => {
                if !out.iter().any(|o| o == n) {
                    out.push(n.to_string());
                }
            }
            _ => return Vec::new(),
        }
    }
    out
}

/// The macros as a message names them: "`A`", "`A` and `B`", "`A`, `B`, `C`, `D` and 3 more".
fn named(defines: &[String]) -> String {
    const NAMED: usize = 4;
    let quoted: Vec<String> = defines.iter().map(|n| format!("`{n}`")).collect();
    match quoted.len() {
        0 => String::new(),
        1 => quoted[0].clone(),
        n if n <= NAMED => format!("{} and {}", quoted[..n - 1].join(", "), quoted[n - 1]),
        n => format!("{} and {} more", quoted[..NAMED].join(", "), n - NAMED),
    }
}

/// [`lint`] on the configurations of the shader's own text ([`flags`]): what a caller without
/// text of its own to leave out (a library's) runs.
pub fn lint_text(
    shader: &Shader,
    compile: &CompileOptions,
    options: &LintOptions,
    base: &[Diagnostic],
    max: usize,
) -> Vec<Found> {
    let variants = flags(shader.file.text(), compile);
    lint(shader, compile, options, base, &variants, max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(text: &str) -> Vec<Vec<String>> {
        flags(text, &CompileOptions::default())
            .into_iter()
            .map(|v| v.defines)
            .collect()
    }

    #[test]
    fn each_group_a_flag_turns_on() {
        let text = "#ifdef A\nx/a\n#elif defined(B) && !defined(C)\ny/b\n#else\nz/c\n#endif\n\
                    #ifndef D\n#else\nw/d\n#endif\n#if E > 0\nfloat e;\n#endif\n#ifdef F\nx = 1.0;\n#endif\n";
        assert_eq!(
            names(text),
            [vec!["A"], vec!["B"], vec!["C"], vec!["D"], vec!["E"]]
        );
    }

    #[test]
    fn a_wide_character_before_a_call() {
        // The text of a file that was not UTF-8 holds U+FFFD, three bytes wide.
        assert!(calls_a_function("x = \u{fffd}f(1.0);"));
        assert!(!calls_a_function("x = \u{fffd}vec4(1.0);"));
        assert!(!calls_a_function("\u{fffd}(1.0)"));
        let text = "#ifdef A\n  gl_Position = \u{fffd}f(1.0);\n#endif\n";
        assert_eq!(names(text), [vec!["A"]]);
    }

    #[test]
    fn nested_groups_need_the_outer_flag() {
        let text = "#ifdef A\n#ifdef B\nx%2\n#endif\n#endif\n#ifdef A // again\n#endif\n";
        assert_eq!(names(text), [vec!["A"], vec!["A", "B"]]);
    }

    #[test]
    fn leaves_out_what_is_defined_and_reserved_names() {
        let text = "#define A 1\n#ifdef A\npow\n#endif\n#ifdef GL_ES\npow\n#endif\n\
                    #ifndef B\n#define B\n#endif\n/*\n#ifdef C\n*/\n#ifdef D\npow\n#endif\n";
        assert_eq!(names(text), [vec!["D"]]);
    }

    #[test]
    fn groups_without_a_hazard_are_left_alone() {
        let text = "#ifdef A\nuniform float u; // a/b\nc = vec4(1.0); /* x */\n#endif\n\
                    #ifdef B\nfloat x;\n#endif\n#ifdef C\ny = normalize(d);\n#endif\n\
                    #ifdef D\nif (k) { c = mat3x2(1.0)[0].xyxy; }\n#endif\n\
                    #ifdef E\nc = scale(k);\n#endif\n";
        assert_eq!(names(text), [vec!["B"], vec!["C"], vec!["E"]]);
    }

    #[test]
    fn deep_nesting_is_bounded() {
        let n = 20_000;
        let mut text = String::new();
        for i in 0..n {
            text.push_str(&format!("#ifdef F{i}\n"));
        }
        text.push_str("discard;\n");
        text.push_str(&"#endif\n".repeat(n));
        let v = flags(&text, &CompileOptions::default());
        assert_eq!(v.len(), MAX_NAMES);
        assert!(v.iter().all(|v| v.defines.len() <= MAX_NAMES));
    }

    #[test]
    fn a_group_spans_up_to_the_next_directive() {
        let text = "#ifdef A\nx / y\n#else\ny\n#endif\n";
        let v = &flags(text, &CompileOptions::default())[0];
        assert_eq!(&text[v.groups[0].range()], "x / y\n");
    }
}
