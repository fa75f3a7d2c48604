//! The settings a text lets its includer make, each compiled as a configuration of its own:
//! a choice between functions ([`choices`]) and a count ([`counts`]).

use essl::source::Span;
use essl::CompileOptions;

use super::lines::{first_name, Line};
use super::Variant;

/// The choices a text lets its includer make, each value as a configuration of its own: a
/// macro the text defines under `#ifndef` of the same name as one of several functions it
/// defines, depending on other flags (lygia's `DIFFUSE_FNC`, `diffuseLambert` on WebGL and
/// `diffuseOrenNayar` elsewhere). The function one configuration leaves uncalled is code the
/// includer runs by defining the macro.
pub(super) fn choices(text: &str, lines: &[Line], options: &CompileOptions) -> Vec<Variant> {
    // The open conditionals, innermost last: for an `#ifndef NAME`, its index in `blocks`.
    let mut open: Vec<Option<usize>> = Vec::new();
    // Each `#ifndef NAME`: the name, the directive, the functions defined as the name inside.
    let mut blocks: Vec<(String, Span, Vec<String>)> = Vec::new();
    for l in lines {
        match l.name.as_str() {
            "ifndef" => {
                let block = match &first_name(&l.args)[..] {
                    [n] if !options.defines.iter().any(|(d, _)| d == n) => {
                        blocks.push((n.clone(), l.span, Vec::new()));
                        Some(blocks.len() - 1)
                    }
                    _ => None,
                };
                open.push(block);
            }
            "if" | "ifdef" => open.push(None),
            "endif" => {
                open.pop();
            }
            "define" => {
                let mut words = l.args.split_whitespace();
                let (Some(n), Some(v), None) = (words.next(), words.next(), words.next()) else {
                    continue;
                };
                // The `#ifndef` of the same name among the few innermost conditionals (the
                // choice sits under the flags that make it).
                let Some(b) = open
                    .iter()
                    .rev()
                    .take(4)
                    .flatten()
                    .copied()
                    .find(|&b| blocks[b].0 == n)
                else {
                    continue;
                };
                let function = v.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
                    && !v.as_bytes()[0].is_ascii_digit()
                    && !blocks[b].2.iter().any(|x| x == v)
                    && defines_function(text, v);
                if function {
                    blocks[b].2.push(v.to_string());
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    for (name, directive, values) in blocks {
        if values.len() < 2 {
            continue;
        }
        for v in values {
            out.push(Variant {
                defines: vec![name.clone()],
                directive,
                groups: Vec::new(),
                count: None,
                choice: Some(v),
            });
        }
    }
    out
}

/// Whether `text` defines or declares a function named `name`: `name(` right after a type's
/// name (`float diffuseOrenNayar(`), not after an operator, a comma or `return`.
fn defines_function(text: &str, name: &str) -> bool {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    text.match_indices(name).any(|(i, _)| {
        let after = text[i + name.len()..].trim_start_matches([' ', '\t']);
        let before = &text[..i];
        let ty = before
            .trim_end_matches([' ', '\t'])
            .rsplit(|c: char| !word(c))
            .next()
            .unwrap_or("");
        after.starts_with('(')
            && before.ends_with([' ', '\t'])
            && !ty.is_empty()
            && ty != "return"
            && !ty.as_bytes()[0].is_ascii_digit()
    })
}

/// The counts a text lets its includer set, each as a configuration that sets it to 1: a macro
/// the text defines as an integer above 1 right under `#ifndef` of the same name, and compares
/// a loop variable with (`i < RAYMARCH_AO_SAMPLES`, `< float(N)`). One iteration is the
/// fewest a count can ask for, and the value where `1.0 / float(N - 1)` divides by zero.
pub(super) fn counts(text: &str, lines: &[Line], options: &CompileOptions) -> Vec<Variant> {
    let mut out = Vec::new();
    for w in lines.windows(3) {
        let [open, define, close] = w else { continue };
        if open.name != "ifndef" || define.name != "define" || close.name != "endif" {
            continue;
        }
        let mut words = define.args.split_whitespace();
        let (Some(name), Some(value), None) = (words.next(), words.next(), words.next()) else {
            continue;
        };
        let above_one = value.len() < 10
            && value.bytes().all(|b| b.is_ascii_digit())
            && value.parse::<u32>().is_ok_and(|v| v > 1);
        if !above_one
            || first_name(&open.args) != [name]
            || options.defines.iter().any(|(n, _)| n == name)
            || !bounds_a_loop(text, name)
        {
            continue;
        }
        out.push(Variant {
            defines: vec![name.to_string()],
            directive: open.span,
            groups: Vec::new(),
            count: Some(value.to_string()),
            choice: None,
        });
    }
    out
}

/// Whether `text` compares something with `name` as a loop's bound does: `< name`, `<= name`,
/// `< float(name)`.
fn bounds_a_loop(text: &str, name: &str) -> bool {
    text.match_indices(name).any(|(i, _)| {
        let after = text[i + name.len()..].chars().next();
        if after.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
            return false;
        }
        let before = text[..i].trim_end();
        let before = before
            .strip_suffix('(')
            .map(|b| b.trim_end().trim_end_matches("float").trim_end())
            .unwrap_or(before);
        before.ends_with('<') || before.ends_with("<=")
    })
}
