//! The settings a text lets its includer make, each compiled as a configuration of its own:
//! a choice between functions ([`choices`]), a count ([`counts`]) and a level the
//! conditionals compare ([`levels`]).

use std::collections::{HashMap, HashSet};

use essl::source::Span;
use essl::CompileOptions;

use super::lines::{first_name, Line};
use super::Variant;

/// The choices a text lets its includer make, each value as a configuration of its own: a
/// macro the text defines under `#ifndef` of the same name as one of several functions it
/// defines, depending on other flags (lygia's `DIFFUSE_FNC`, `diffuseLambert` on WebGL and
/// `diffuseOrenNayar` elsewhere), and the other functions of their family the text defines
/// ([`siblings`]: lygia's `specularGaussian` and `specularBeckmann`, which its `SPECULAR_FNC`
/// never defaults to). The function one configuration leaves uncalled is code the includer runs
/// by defining the macro.
pub(super) fn choices(text: &str, lines: &[Line], options: &CompileOptions) -> Vec<Variant> {
    // The open conditionals, innermost last: for an `#ifndef NAME`, its index in `blocks`.
    let mut open: Vec<Option<usize>> = Vec::new();
    // Each `#ifndef NAME`: the name, the directive, the functions defined as the name inside.
    let mut blocks: Vec<(String, Span, Vec<String>)> = Vec::new();
    // The functions the text defines, read once where a choice needs them.
    let functions = std::cell::OnceCell::new();
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
                    && functions
                        .get_or_init(|| defined_functions(text))
                        .contains(v);
                if function {
                    blocks[b].2.push(v.to_string());
                }
            }
            _ => {}
        }
    }
    let choice = |name: &str, directive, v: &str| Variant {
        defines: vec![name.to_string()],
        directive,
        groups: Vec::new(),
        count: None,
        choice: Some(v.to_string()),
        level: None,
    };
    let blocks: Vec<_> = blocks.into_iter().filter(|b| b.2.len() >= 2).collect();
    let mut out: Vec<Variant> = blocks
        .iter()
        .flat_map(|(name, directive, values)| values.iter().map(|v| choice(name, *directive, v)))
        .collect();
    // The values the text names first, then the rest of each family: a configuration budget
    // that ends among the families leaves out no value the text names.
    if let Some(defined) = functions.get().filter(|_| !blocks.is_empty()) {
        let mut sorted: Vec<&str> = defined.iter().copied().collect();
        sorted.sort_unstable();
        for (name, directive, values) in &blocks {
            out.extend(siblings(values, &sorted).map(|v| choice(name, *directive, v)));
        }
    }
    out
}

/// The names of the functions `text` defines or declares: `name(` right after a type's name
/// (`float diffuseOrenNayar(`), not after an operator, a comma or `return`. One pass over the
/// text's parentheses, whatever the number of names asked about.
fn defined_functions(text: &str) -> HashSet<&str> {
    let mut out = HashSet::new();
    for (j, _) in text.match_indices('(') {
        let head = text[..j].trim_end_matches([' ', '\t']);
        let name = &head[word_start(head)..];
        let before = &head[..head.len() - name.len()];
        let ty = before.trim_end_matches([' ', '\t']);
        let ty = &ty[word_start(ty)..];
        if !name.is_empty()
            && before.ends_with([' ', '\t'])
            && !ty.is_empty()
            && ty != "return"
            && !ty.as_bytes()[0].is_ascii_digit()
        {
            out.insert(name);
        }
    }
    out
}

/// How many other functions of a family [`siblings`] offers (of at most eight times as many
/// names it reads with the family's prefix: bounded work for each `#ifndef`).
const MAX_SIBLINGS: usize = 8;

/// The functions of `sorted` (the text's, in order) whose names extend the longest prefix
/// `values` share, at a word's boundary (`specular` of `specularCookTorrance` and
/// `specularBlinnPhongRoughness`, then `specularGaussian`, `specularBeckmann`): the other
/// choices a library offers for the macro, which no configuration of the text defines it as;
/// at most [`MAX_SIBLINGS`]. One that takes other arguments than the macro's uses is a
/// configuration that does not compile, and is left out.
fn siblings<'a, 't>(
    values: &'a [String],
    sorted: &'a [&'t str],
) -> impl Iterator<Item = &'t str> + 'a {
    let first = values[0].as_str();
    let mut len = values.iter().fold(first.len(), |n, v| {
        first
            .bytes()
            .zip(v.bytes())
            .take(n)
            .take_while(|(a, b)| a == b)
            .count()
    });
    // Back to a word's boundary: the prefix ends before an upper-case letter or an underscore.
    let boundary =
        |v: &str, n: usize| v[n..].starts_with(|c: char| c.is_ascii_uppercase() || c == '_');
    while len > 0 && !values.iter().all(|v| boundary(v, len)) {
        len -= 1;
    }
    let prefix = &first[..len];
    // The names with the prefix are one run of the sorted names.
    let from = if len < 4 {
        sorted.len()
    } else {
        sorted.partition_point(|d| *d < prefix)
    };
    sorted[from..]
        .iter()
        .copied()
        .take_while(move |d| d.starts_with(prefix))
        .take(MAX_SIBLINGS * 8)
        .filter(move |d| d.len() > len && boundary(d, len) && !values.iter().any(|v| v == d))
        .take(MAX_SIBLINGS)
}

/// Where the name `text` ends with begins (its length where it ends with none).
fn word_start(text: &str) -> usize {
    text.rfind(|c: char| !is_word(c)).map_or(0, |k| {
        k + text[k..].chars().next().map_or(1, char::len_utf8)
    })
}

/// Whether `c` can be part of a name.
fn is_word(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Each name of `text` (a maximal run of name characters) with where it starts.
fn words(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let bytes = text.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < bytes.len() && !is_word(bytes[i] as char) {
            i += 1;
        }
        let start = i;
        while i < bytes.len() && is_word(bytes[i] as char) {
            i += 1;
        }
        (i > start).then(|| (start, &text[start..i]))
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
    // The names the text compares a loop variable with, read once where a count needs them.
    let bounds = std::cell::OnceCell::new();
    for (open, name, value) in defaults(lines, options) {
        let above_one = value.len() < 10
            && value.bytes().all(|b| b.is_ascii_digit())
            && value.parse::<u32>().is_ok_and(|v| v > 1);
        if !above_one || !bounds.get_or_init(|| loop_bounds(text)).contains(name) {
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

/// The names `text` compares something with as a loop's bound does: `< name`, `<= name`,
/// `< float(name)`. One pass over the text's names.
fn loop_bounds(text: &str) -> HashSet<&str> {
    words(text)
        .filter(|&(i, _)| {
            let before = text[..i].trim_end();
            let before = before
                .strip_suffix('(')
                .map(|b| b.trim_end().trim_end_matches("float").trim_end())
                .unwrap_or(before);
            before.ends_with('<') || before.ends_with("<=")
        })
        .map(|(_, w)| w)
        .collect()
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
    // The value each name compared with integers needs, over every `#if` and `#elif`.
    let mut needs: HashMap<&str, u32> = HashMap::new();
    for l in lines.iter().filter(|l| l.name == "if" || l.name == "elif") {
        for (name, n) in turning_on(&l.args) {
            let need = needs.entry(name).or_insert(n);
            *need = (*need).max(n);
        }
    }
    for (open, name, value) in defaults(lines, options) {
        let Ok(default) = value.parse::<u32>() else {
            continue;
        };
        let Some(&need) = needs.get(name).filter(|&&n| n > default) else {
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

/// Each name an `#if`'s expression `args` compares with an integer, with the least value that
/// makes that comparison hold (`N > 4` needs 5, `N >= 2` and `N == 2` need 2, `4 < N` needs 5).
fn turning_on(args: &str) -> Vec<(&str, u32)> {
    let number = |s: &str| -> Option<u32> {
        let digits: String = s
            .trim_start()
            .chars()
            .take_while(|c| c.is_ascii_digit())
            .collect();
        digits.parse().ok()
    };
    let mut out = Vec::new();
    for (i, name) in words(args) {
        let before = &args[..i];
        let right = args[i + name.len()..].trim_start();
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
            out.push((name, n));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{defined_functions, loop_bounds, siblings, turning_on};

    #[test]
    fn the_least_value_each_comparison_needs() {
        let n = |a: &str| {
            turning_on(a)
                .into_iter()
                .filter(|&(w, _)| w == "N")
                .map(|(_, v)| v)
                .max()
        };
        assert_eq!(n(" N > 4"), Some(5));
        assert_eq!(n(" N>0 && defined(X)"), Some(1));
        assert_eq!(n(" N >= 2 || N == 7"), Some(7));
        assert_eq!(n(" 4 < N"), Some(5));
        assert_eq!(n(" 2 <= N"), Some(2));
        assert_eq!(n(" NN > 4 || M_N > 2"), None);
        assert_eq!(n(" defined(N)"), None);
        assert_eq!(n(" N > 4294967295"), None);
    }

    #[test]
    fn functions_a_text_defines() {
        let f = defined_functions(
            "float orenNayar(float a) { return lambert(a); }\nvec3 c = mix(a, b, t);\n\
             vec3 xlambert (vec3 n);",
        );
        let mut names: Vec<&str> = f.into_iter().collect();
        names.sort();
        assert_eq!(names, ["orenNayar", "xlambert"]);
    }

    /// The other functions of a choice's family: past the values' common prefix at a word's
    /// boundary.
    #[test]
    fn the_other_choices_of_a_family() {
        let defined = defined_functions(
            "float specularCookTorrance(S s) { return 1.0; }\n\
             float specularBlinnPhong(S s) { return 1.0; }\n\
             float specularGaussian(float r) { return 1.0; }\n\
             float specularGaussian(S s) { return specularGaussian(s.r); }\n\
             float specularity(S s) { return 1.0; }\n\
             vec3 specular(S s) { return vec3(SPECULAR_FNC(s)); }\n\
             float diffuseLambert(S s) { return 1.0; }",
        );
        let values = [
            "specularCookTorrance".to_string(),
            "specularBlinnPhong".to_string(),
        ];
        let mut sorted: Vec<&str> = defined.into_iter().collect();
        sorted.sort_unstable();
        let found: Vec<&str> = siblings(&values, &sorted).collect();
        assert_eq!(found, ["specularGaussian"]);
        let short = ["fooA".to_string(), "fooB".to_string()];
        assert_eq!(siblings(&short, &sorted).count(), 0);
    }

    #[test]
    fn names_a_loop_is_bounded_by() {
        let b = loop_bounds(
            "for (int i = 0; i < N; i++) {}\nfor (float j = 0.0; j <= float( M ); j++) {}\n\
             x = K + 1; y = y<NN ? 1 : 0;",
        );
        for name in ["M", "N", "NN"] {
            assert!(b.contains(name), "{name}");
        }
        assert!(!b.contains("K") && !b.contains("x") && !b.contains("i"));
    }
}
