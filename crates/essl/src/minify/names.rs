//! Which names are renamed, and to what.
//!
//! A name is renamed when every declaration the checked module has of it is a local variable,
//! a parameter, a user function other than `main`, or a plain or `const` global (none of which
//! WebGL sees), and nothing else in the text may spell it: not a uniform, input, output or
//! uniform-block member, a struct or block name, a struct or block member, a macro, a name a directive
//! tests or a `defines` option mentions, a layout qualifier, a built-in, a keyword or reserved
//! word. Every occurrence of a renamed name is renamed the same way, except fields and
//! swizzles after a `.`, so the renaming is a one-to-one map from names to new names that
//! appear nowhere in the text: GLSL resolves names by their spelling alone, and scopes,
//! shadowing and overloads come out as they were.
//!
//! An occurrence in code the preprocessor skips under these settings (an `#if` branch not
//! taken) keeps its name from being renamed: under other macros that code may declare it as
//! a uniform. Occurrences inside `#define` bodies are renamed with the rest.

use rustc_hash::{FxHashMap, FxHashSet};

use super::emit::{after_dot, Line};
use crate::hir::{GlobalKind, Module};
use crate::lex::PpKind;
use crate::Name;

/// Identifiers of layout qualifiers, which are not names of anything declared.
const LAYOUT_WORDS: &[&str] = &[
    "location",
    "std140",
    "shared",
    "packed",
    "row_major",
    "column_major",
    "binding",
];

/// Macros the preprocessor defines itself.
const PREDEFINED: &[&str] = &[
    "GL_ES",
    "__VERSION__",
    "__LINE__",
    "__FILE__",
    "GL_FRAGMENT_PRECISION_HIGH",
];

/// Parts of the original text where code is compiled under the shader's settings: the spans
/// of the preprocessor's output tokens (a macro call's tokens span the whole call).
pub(super) struct Active {
    spans: Vec<(u32, u32)>,
}

impl Active {
    /// From the preprocessed tokens' spans.
    pub fn new(mut spans: Vec<(u32, u32)>) -> Active {
        spans.sort_unstable();
        let mut merged: Vec<(u32, u32)> = Vec::with_capacity(spans.len());
        for (s, e) in spans {
            match merged.last_mut() {
                Some(last) if s <= last.1 => last.1 = last.1.max(e),
                _ => merged.push((s, e)),
            }
        }
        Active { spans: merged }
    }

    /// Whether the token starting at `offset` is inside compiled code.
    fn contains(&self, offset: u32) -> bool {
        let i = self.spans.partition_point(|&(s, _)| s <= offset);
        i > 0 && offset < self.spans[i - 1].1.max(self.spans[i - 1].0 + 1)
    }
}

/// The identifiers of a `defines` option: its name and the words of its value.
fn define_words(defines: &[(String, String)]) -> impl Iterator<Item = &str> {
    defines.iter().flat_map(|(name, value)| {
        name.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .chain(value.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')))
            .filter(|w| !w.is_empty())
    })
}

/// The names the module declares that are not renamed.
fn kept_names<'a>(module: &'a Module, defines: &'a [(String, String)]) -> FxHashSet<&'a str> {
    let mut kept: FxHashSet<&str> = FxHashSet::default();
    kept.extend(
        module
            .globals
            .iter()
            .filter(|g| !private(g))
            .map(|g| g.name.as_str()),
    );
    for b in &module.blocks {
        kept.insert(&b.name);
        kept.extend(b.instance.as_deref());
        kept.extend(b.members.iter().map(|m| m.0.as_str()));
    }
    for s in &module.structs {
        kept.extend(s.name.as_deref());
        kept.extend(s.members.iter().map(|m| m.name.as_str()));
    }
    kept.extend(LAYOUT_WORDS);
    kept.extend(PREDEFINED);
    kept.extend(define_words(defines));
    kept.insert("main");
    kept
}

/// Whether a global is the shader's own (a plain or `const` global): WebGL cannot see its name.
fn private(g: &crate::hir::Global) -> bool {
    matches!(g.kind, GlobalKind::Private | GlobalKind::Const)
}

/// Whether a name is one the language or its built-ins take.
fn is_builtin(name: &str) -> bool {
    crate::token::is_taken_word(name)
        || crate::builtins::is_builtin_function(name)
        || crate::builtins::overloads_in(name, true).is_some()
        || name.starts_with("gl_")
        || name.starts_with("webgl_")
        || name.starts_with("_webgl_")
        || name.contains("__")
}

/// The renaming: each renamed name and its new one.
pub(super) fn plan(
    lines: &[Line<'_>],
    active: &Active,
    module: &Module,
    defines: &[(String, String)],
) -> FxHashMap<Name, Name> {
    let kept = kept_names(module, defines);
    let mut candidates: FxHashMap<&str, usize> = FxHashMap::default();
    for g in module.globals.iter().filter(|g| private(g)) {
        if !kept.contains(g.name.as_str()) && !is_builtin(&g.name) {
            candidates.insert(&g.name, 0);
        }
    }
    for f in &module.functions {
        let names = std::iter::once(&f.name)
            .chain(f.params.iter().map(|p| &p.name))
            .chain(f.locals.iter().map(|l| &l.name));
        for n in names {
            if !kept.contains(n.as_str()) && !is_builtin(n) {
                candidates.insert(n, 0);
            }
        }
    }
    let mut dropped: FxHashSet<&str> = FxHashSet::default();
    // Every word the text spells (fields and swizzles aside): no new name may be one of them.
    let mut taken: FxHashSet<&str> = define_words(defines).collect();
    for line in lines {
        let define = line.is_define();
        for (i, t) in line.tokens.iter().enumerate() {
            if t.kind != PpKind::Ident || after_dot(line.tokens, i) {
                continue;
            }
            let name = t.text.as_str();
            taken.insert(name);
            let Some(count) = candidates.get_mut(name) else {
                continue;
            };
            let renamable = if line.directive {
                // In `#define NAME(params) body`, the parameters and the body.
                define && i > 2
            } else {
                active.contains(t.span.start)
            };
            if renamable {
                *count += 1;
            } else {
                dropped.insert(name);
            }
        }
    }
    let mut order: Vec<(&str, usize)> = candidates
        .into_iter()
        .filter(|(n, c)| *c > 0 && !dropped.contains(n))
        .collect();
    // The most used names get the shortest new ones; ties in name order, for a stable output.
    order.sort_unstable_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
    let mut fresh = Fresh { next: 0 };
    order
        .into_iter()
        .map(|(name, _)| {
            let new = fresh.next_free(|n| taken.contains(n) || is_builtin(n));
            (Name::new(name), Name::new(new))
        })
        .collect()
}

/// Short names in order: `a`…`z`, `A`…`Z`, then two characters, three, …
struct Fresh {
    next: u64,
}

const FIRST: &[u8] = b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
const REST: &[u8] = b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_";

impl Fresh {
    /// The `n`th name of the sequence.
    fn name(mut n: u64) -> String {
        let mut s = vec![FIRST[(n % FIRST.len() as u64) as usize]];
        n /= FIRST.len() as u64;
        while n > 0 {
            n -= 1;
            s.push(REST[(n % REST.len() as u64) as usize]);
            n /= REST.len() as u64;
        }
        String::from_utf8(s).unwrap_or_default()
    }

    /// The next name for which `taken` is false.
    fn next_free(&mut self, taken: impl Fn(&str) -> bool) -> String {
        loop {
            let n = Fresh::name(self.next);
            self.next += 1;
            if !taken(&n) {
                return n;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Fresh;

    #[test]
    fn fresh_names_are_distinct_and_short() {
        let names: Vec<String> = (0..5000).map(Fresh::name).collect();
        let set: std::collections::HashSet<&String> = names.iter().collect();
        assert_eq!(set.len(), names.len());
        assert_eq!(names[0], "a");
        assert_eq!(names[51], "Z");
        assert_eq!(names[52].len(), 2);
        assert!(names[52 + 52 * 63 - 1].len() == 2 && names[52 + 52 * 63].len() == 3);
    }
}
