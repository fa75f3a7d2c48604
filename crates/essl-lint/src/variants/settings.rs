//! The settings a text lets its includer make, each compiled as a configuration of its own:
//! a choice between functions ([`choices`]), a count ([`counts`]) and a level the
//! conditionals compare ([`levels`]).

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
                level: None,
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

/// The macros a text defines with a value right under `#ifndef` of the same name, which the
/// options do not define: each `#ifndef`, the name and the value (`#ifndef N` / `#define N 5` /
/// `#endif`).
fn defaults<'a>(
    lines: &'a [Line],
    options: &'a CompileOptions,
) -> impl Iterator<Item = (&'a Line, &'a str, &'a str)> {
    lines.windows(3).filter_map(|w| {
        let [open, define, close] = w else {
            return None;
        };
        if open.name != "ifndef" || define.name != "define" || close.name != "endif" {
            return None;
        }
        let mut words = define.args.split_whitespace();
        let (Some(name), Some(value), None) = (words.next(), words.next(), words.next()) else {
            return None;
        };
        let given = options.defines.iter().any(|(n, _)| n == name);
        (first_name(&open.args) == [name] && !given).then_some((open, name, value))
    })
}

/// The counts a text lets its includer set, each as a configuration that sets it to 1: a macro
/// the text defines as an integer above 1 right under `#ifndef` of the same name, and compares
/// a loop variable with (`i < RAYMARCH_AO_SAMPLES`, `< float(N)`). One iteration is the
/// fewest a count can ask for, and the value where `1.0 / float(N - 1)` divides by zero.
pub(super) fn counts(text: &str, lines: &[Line], options: &CompileOptions) -> Vec<Variant> {
    let mut out = Vec::new();
    for (open, name, value) in defaults(lines, options) {
        let above_one = value.len() < 10
            && value.bytes().all(|b| b.is_ascii_digit())
            && value.parse::<u32>().is_ok_and(|v| v > 1);
        if !above_one || !bounds_a_loop(text, name) {
            continue;
        }
        out.push(Variant {
            defines: vec![name.to_string()],
            directive: open.span,
            groups: Vec::new(),
            count: Some(value.to_string()),
            choice: None,
            level: None,
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

/// The levels a text lets its includer set, each as a configuration that sets it to the largest
/// value one comparison of it needs (every `>` and `>=` group on; of several `==`, the
/// largest): a macro the text defines as an integer right
/// under `#ifndef` of the same name (Babylon's `NUM_BONE_INFLUENCERS 0`, a mesh without bones)
/// and compares with integers in `#if` and `#elif` (`NUM_BONE_INFLUENCERS > 0`, `> 4`, `>= 2`,
/// `== 3`). The code under those groups (skinning, morph targets) runs for every mesh that has
/// them, and no flag turns it on.
pub(super) fn levels(lines: &[Line], options: &CompileOptions) -> Vec<Variant> {
    let mut out = Vec::new();
    for (open, name, value) in defaults(lines, options) {
        let Ok(default) = value.parse::<u32>() else {
            continue;
        };
        let need = lines
            .iter()
            .filter(|l| l.name == "if" || l.name == "elif")
            .filter_map(|l| least_turning_on(&l.args, name))
            .max();
        let Some(need) = need.filter(|&n| n > default) else {
            continue;
        };
        out.push(Variant {
            defines: vec![name.to_string()],
            directive: open.span,
            groups: Vec::new(),
            count: None,
            choice: None,
            level: Some((need.to_string(), value.to_string())),
        });
    }
    out
}

/// The least value of `name` that makes the comparisons of it in an `#if`'s expression
/// `args` with integers hold (`name > 4` needs 5, `name >= 2` and `name == 2` need 2, `4 < name`
/// needs 5); `None` where it is compared with none.
fn least_turning_on(args: &str, name: &str) -> Option<u32> {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut need: Option<u32> = None;
    for (i, _) in args.match_indices(name) {
        let before = &args[..i];
        let after = &args[i + name.len()..];
        if before.ends_with(word) || after.starts_with(word) {
            continue;
        }
        let number = |s: &str| -> Option<u32> {
            let digits: String = s
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_digit())
                .collect();
            digits.parse().ok()
        };
        let right = after.trim_start();
        let found = [(">=", 0), (">", 1), ("==", 0)]
            .iter()
            .find_map(|&(op, plus)| number(right.strip_prefix(op)?)?.checked_add(plus))
            .or_else(|| {
                // `4 < name`, `2 <= name`.
                let left = before.trim_end();
                let (rest, plus) = match left.strip_suffix("<=") {
                    Some(r) => (r, 0),
                    None => (left.strip_suffix('<')?, 1),
                };
                let digits: String = rest
                    .trim_end()
                    .chars()
                    .rev()
                    .take_while(|c| c.is_ascii_digit())
                    .collect();
                let n: u32 = digits.chars().rev().collect::<String>().parse().ok()?;
                n.checked_add(plus)
            });
        if let Some(n) = found {
            need = Some(need.map_or(n, |m| m.max(n)));
        }
    }
    need
}

#[cfg(test)]
mod tests {
    use super::least_turning_on;

    #[test]
    fn the_least_value_each_comparison_needs() {
        let n = |a: &str| least_turning_on(a, "N");
        assert_eq!(n(" N > 4"), Some(5));
        assert_eq!(n(" N>0 && defined(X)"), Some(1));
        assert_eq!(n(" N >= 2 || N == 7"), Some(7));
        assert_eq!(n(" 4 < N"), Some(5));
        assert_eq!(n(" 2 <= N"), Some(2));
        assert_eq!(n(" NN > 4 || M_N > 2"), None);
        assert_eq!(n(" defined(N)"), None);
        assert_eq!(n(" N > 4294967295"), None);
    }
}
