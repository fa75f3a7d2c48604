//! GLSL names in the output.
//!
//! naga's backends name everything through one `Namer`, which appends `_` to a name that ends
//! in a digit (`u_light0` → `u_light0_`), `_1`, `_2`… to a name used twice in a module (two
//! functions that each have a local `i`), and turns characters outside identifiers into
//! `u005b_` escapes. Those rules keep every output valid whatever the input, which is right
//! for a compiler and wrong for code a person keeps. No backend option turns them off, so this
//! module works on both sides of the writer:
//! - [`prepare`] gives the globals essl made up (one texture and one sampler per sampler
//!   uniform element, named `u_tex[2]`, `s.tex`, `u_tex[2]_sampler`) identifier names the
//!   namer keeps: `u_tex_2`, `s_tex`, `u_tex_2_sampler`.
//! - [`restore`] runs the WGSL writer's own namer again to learn which name it gave each
//!   item, then renames each item back to its GLSL name where that name is a WGSL identifier,
//!   is neither reserved nor a built-in, and appears nowhere in the item's scope (the whole
//!   module for module-scope items and struct members, the function's text for its locals
//!   and arguments; WGSL lets a local shadow a module-scope name). Anything else keeps the
//!   namer's choice, so the result is valid WGSL whenever the writer's was; the tests read
//!   every translated shader back through naga's WGSL front end.
//! - [`restore_in`] does the same for the MSL, HLSL and desktop GLSL texts, where only the
//!   namer's suffixes are undone.

use std::collections::{HashMap, HashSet};

use naga::proc::{NameKey, Namer};
use naga::{Handle, Module};

mod targets;
pub use targets::restore_in;

/// A copy of the module with the names a reader expects (see the module doc).
pub fn prepare(module: &Module) -> Module {
    let mut module = module.clone();
    let mut globals = HashSet::new();
    for (_, var) in module.global_variables.iter_mut() {
        if let Some(name) = &var.name {
            if name.contains(['[', ']', '.']) {
                var.name = Some(identifier(name));
            }
            globals.insert(var.name.clone().unwrap_or_default());
        }
    }
    // essl names a user function `NAME_` (clear of built-ins in its own IR); the namer keeps
    // the writer clear of them. The shader's `main` is called by the entry point `main`.
    for (_, f) in module.functions.iter_mut() {
        if let Some(name) = &f.name {
            f.name = Some(match name.as_str() {
                "main_" => "glsl_main".to_owned(),
                n => n.strip_suffix('_').unwrap_or(n).to_owned(),
            });
        }
    }
    // The entry point copies each input into a private global of the GLSL name, which the
    // shader's code reads: the argument gives way. A built-in's argument takes the built-in's
    // name in WGSL (`frag_coord` for `@builtin(position)` in a fragment shader).
    for ep in module.entry_points.iter_mut() {
        for arg in ep.function.arguments.iter_mut() {
            let builtin = match arg.binding {
                Some(naga::Binding::BuiltIn(naga::BuiltIn::Position { .. })) => Some("frag_coord"),
                Some(naga::Binding::BuiltIn(naga::BuiltIn::FrontFacing)) => Some("front_facing"),
                Some(naga::Binding::BuiltIn(naga::BuiltIn::VertexIndex)) => Some("vertex_index"),
                Some(naga::Binding::BuiltIn(naga::BuiltIn::InstanceIndex)) => {
                    Some("instance_index")
                }
                Some(naga::Binding::BuiltIn(naga::BuiltIn::PointCoord)) => Some("point_coord"),
                _ => None,
            };
            if let Some(b) = builtin.filter(|b| !globals.contains(*b)) {
                arg.name = Some(b.to_owned());
                continue;
            }
            if let Some(name) = &arg.name {
                if globals.contains(name) {
                    arg.name = Some(format!("{name}_in"));
                }
            }
        }
    }
    module
}

/// The name naga's WGSL writer gives each item of the module: its own namer, reset as the
/// writer resets it (WGSL's reserved words and built-ins, no `__` or `_naga` prefix).
pub fn wgsl_names(module: &Module) -> naga::FastHashMap<NameKey, String> {
    let mut names = naga::FastHashMap::default();
    Namer::default().reset(
        module,
        &naga::keywords::wgsl::RESERVED_SET,
        &naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET,
        naga::proc::CaseInsensitiveKeywordSet::empty(),
        &["__", "_naga"],
        &mut names,
    );
    names
}

/// `u_tex[2].s` → `u_tex_2_s`.
pub(crate) fn identifier(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars() {
        let c = match c {
            '[' | '.' => '_',
            ']' => continue,
            c => c,
        };
        if !(c == '_' && out.ends_with('_')) {
            out.push(c);
        }
    }
    out.trim_end_matches('_').to_owned()
}

/// Where an item's name is visible.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
enum Scope {
    /// Module scope (types, constants, globals, functions, entry points).
    Module,
    /// A struct member (accessed as `.name`, declared inside its struct).
    Member,
    /// The arguments and locals of a function: its index in the text's function list.
    Function(usize),
}

/// One item the namer named.
struct Named {
    scope: Scope,
    original: String,
    emitted: String,
}

/// The WGSL text with GLSL names given back where that is safe (see the module doc); `names`
/// are the writer's ([`wgsl_names`]).
pub fn restore(module: &Module, names: &naga::FastHashMap<NameKey, String>, wgsl: &str) -> String {
    // Functions in the order the writer writes them: functions, then entry points.
    let mut function_index: HashMap<Handle<naga::Function>, usize> = HashMap::new();
    for (i, (h, _)) in module.functions.iter().enumerate() {
        function_index.insert(h, i);
    }
    let ep_base = module.functions.len();
    // Every named item's original, and the emitted names that belong to more than one
    // meaning (a member and a local, say).
    let mut items = Vec::new();
    let mut meanings: HashMap<&str, HashSet<String>> = HashMap::new();
    for (key, emitted) in names {
        let Some((scope, original)) = original_name(module, key, &function_index, ep_base) else {
            continue;
        };
        meanings
            .entry(emitted.as_str())
            .or_default()
            .insert(original.clone());
        if *emitted != original {
            items.push(Named {
                scope,
                original,
                emitted: emitted.clone(),
            });
        }
    }
    // A stable order: module scope first (its names are seen inside functions), then by name.
    items.sort_by(|a, b| {
        let rank = |s: Scope| match s {
            Scope::Module | Scope::Member => 0,
            Scope::Function(i) => 1 + i,
        };
        (rank(a.scope), &a.emitted).cmp(&(rank(b.scope), &b.emitted))
    });
    let mut tokens = Tokens::new(wgsl);
    for item in &items {
        if !renamable(&item.original)
            || meanings
                .get(item.emitted.as_str())
                .is_some_and(|m| m.len() > 1)
        {
            continue;
        }
        let range = match item.scope {
            Scope::Module | Scope::Member => 0..tokens.len(),
            Scope::Function(i) => match tokens.function(i) {
                Some(r) => r,
                None => continue,
            },
        };
        if tokens.any(range.clone(), &item.original) {
            continue;
        }
        tokens.rename(range, &item.emitted, &item.original);
    }
    tokens.text()
}

/// The scope and GLSL name of a namer key; `None` for what has no name of its own.
fn original_name(
    module: &Module,
    key: &NameKey,
    function_index: &HashMap<Handle<naga::Function>, usize>,
    ep_base: usize,
) -> Option<(Scope, String)> {
    let name = |n: &Option<String>| n.clone();
    let (scope, original) = match *key {
        NameKey::Constant(h) => (Scope::Module, name(&module.constants[h].name)),
        NameKey::GlobalVariable(h) => (Scope::Module, name(&module.global_variables[h].name)),
        NameKey::Type(h) => (Scope::Module, name(&module.types[h].name)),
        NameKey::StructMember(h, i) => match &module.types[h].inner {
            naga::TypeInner::Struct { members, .. } => {
                (Scope::Member, name(&members.get(i as usize)?.name))
            }
            _ => return None,
        },
        NameKey::Function(h) => (Scope::Module, name(&module.functions[h].name)),
        NameKey::FunctionArgument(h, i) => (
            Scope::Function(function_index[&h]),
            name(&module.functions[h].arguments.get(i as usize)?.name),
        ),
        NameKey::FunctionLocal(h, l) => (
            Scope::Function(function_index[&h]),
            name(&module.functions[h].local_variables[l].name),
        ),
        NameKey::EntryPoint(i) => (
            Scope::Module,
            Some(module.entry_points.get(i as usize)?.name.clone()),
        ),
        NameKey::EntryPointArgument(i, a) => {
            let f = &module.entry_points.get(i as usize)?.function;
            (
                Scope::Function(ep_base + i as usize),
                name(&f.arguments.get(a as usize)?.name),
            )
        }
        NameKey::EntryPointLocal(i, l) => {
            let f = &module.entry_points.get(i as usize)?.function;
            (
                Scope::Function(ep_base + i as usize),
                name(&f.local_variables[l].name),
            )
        }
        _ => return None,
    };
    Some((scope, original?))
}

/// Whether a GLSL name can stand in WGSL as it is.
fn renamable(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name != "_"
        && !name.starts_with("__")
        && !naga::keywords::wgsl::RESERVED_SET.contains(name)
        && !naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET.contains(name)
}

/// WGSL text as identifier tokens and the text between them.
struct Tokens {
    /// Alternating: text, identifier, text, identifier, …, text.
    parts: Vec<String>,
    /// The parts of each function (from `fn` at module scope to its closing brace), in the
    /// order of the text.
    functions: Vec<std::ops::Range<usize>>,
}

impl Tokens {
    fn new(text: &str) -> Tokens {
        let mut parts = vec![String::new()];
        let mut functions = Vec::new();
        // Brace depth outside comments; the identifier index where the open function began.
        let mut depth = 0usize;
        let mut open: Option<usize> = None;
        let bytes = text.as_bytes();
        let mut i = 0;
        while i < bytes.len() {
            let c = bytes[i];
            if c == b'/' && bytes.get(i + 1) == Some(&b'/') {
                let end = text[i..].find('\n').map_or(text.len(), |n| i + n);
                parts.last_mut().expect("one part").push_str(&text[i..end]);
                i = end;
            } else if c.is_ascii_alphabetic() || c == b'_' {
                let end = text[i..]
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .map_or(text.len(), |n| i + n);
                let after_digit = parts
                    .last()
                    .and_then(|p| p.chars().last())
                    .is_some_and(|c| c.is_ascii_digit());
                if after_digit {
                    // A literal's suffix (`1u`, `2.5f`, `1e3`): not a name.
                    parts.last_mut().expect("one part").push_str(&text[i..end]);
                } else {
                    if depth == 0 && open.is_none() && &text[i..end] == "fn" {
                        open = Some(parts.len());
                    }
                    parts.push(text[i..end].to_owned());
                    parts.push(String::new());
                }
                i = end;
            } else {
                let ch = text[i..].chars().next().expect("in bounds");
                match ch {
                    '{' => depth += 1,
                    '}' => {
                        depth = depth.saturating_sub(1);
                        if depth == 0 {
                            if let Some(start) = open.take() {
                                functions.push(start..parts.len());
                            }
                        }
                    }
                    _ => {}
                }
                parts.last_mut().expect("one part").push(ch);
                i += ch.len_utf8();
            }
        }
        Tokens { parts, functions }
    }

    fn len(&self) -> usize {
        self.parts.len()
    }

    fn function(&self, i: usize) -> Option<std::ops::Range<usize>> {
        self.functions.get(i).cloned()
    }

    /// Whether `name` is an identifier in `range`.
    fn any(&self, range: std::ops::Range<usize>, name: &str) -> bool {
        range
            .filter(|k| k % 2 == 1)
            .any(|k| self.parts.get(k).is_some_and(|p| p == name))
    }

    fn rename(&mut self, range: std::ops::Range<usize>, from: &str, to: &str) {
        for k in range.filter(|k| k % 2 == 1) {
            if let Some(p) = self.parts.get_mut(k) {
                if p == from {
                    *p = to.to_owned();
                }
            }
        }
    }

    fn text(&self) -> String {
        self.parts.concat()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn made_up_names_become_identifiers() {
        assert_eq!(identifier("u_tex[2]"), "u_tex_2");
        assert_eq!(identifier("u_tex[2]_sampler"), "u_tex_2_sampler");
        assert_eq!(identifier("s.tex"), "s_tex");
        assert_eq!(identifier("s[1].t[0]"), "s_1_t_0");
    }

    #[test]
    fn tokens_skip_literal_suffixes_and_comments() {
        let t = Tokens::new("fn f() {\n    let a0_ = 1u + 2.5f; // a0_\n}\n");
        let ids: Vec<_> = t.parts.iter().skip(1).step_by(2).cloned().collect();
        assert_eq!(ids, ["fn", "f", "let", "a0_"]);
        assert_eq!(t.functions.len(), 1);
        assert_eq!(t.text(), "fn f() {\n    let a0_ = 1u + 2.5f; // a0_\n}\n");
    }

    #[test]
    fn reserved_and_builtin_names_stay_renamed() {
        assert!(renamable("u_light0"));
        assert!(!renamable("select"));
        assert!(!renamable("var"));
        assert!(!renamable("__x"));
        assert!(!renamable("x[0]"));
    }
}
