//! Names in the WGSL text: the GLSL names wherever WGSL takes them.
//!
//! Every name is the IR's (the GLSL name essl lowered) unless WGSL reserves it, predeclares
//! it (`vec3`, `select`), or something visible in the same place already has it; then a
//! suffix makes it unique (`_`, or `_1`, `_2`…). A GLSL name ending in a digit stays as it
//! is (naga's namer would write `u_light0_`). Module-scope names are given first, the user's
//! before essl's own (`_essl_DefaultUniforms` is written `Uniforms` where the shader has no
//! `Uniforms` of its own); struct members are unique within their struct; arguments, locals
//! and `let`s within their function and apart from every module-scope name.

use std::collections::{HashMap, HashSet};

use naga::proc::NameKey;
use naga::{Handle, Module, TypeInner};

/// What essl names the things it adds, and what the WGSL calls them when free.
const READABLE: &[(&str, &str)] = &[
    ("_essl_DefaultUniforms", "Uniforms"),
    ("_essl_uniforms", "uniforms"),
    ("_essl_VertexOutput", "VertexOutput"),
    ("_essl_FragmentOutput", "FragmentOutput"),
];

/// The module-scope names, and the members of each struct.
pub(crate) struct ModuleNames {
    pub map: HashMap<NameKey, String>,
    /// Every module-scope name.
    pub taken: HashSet<String>,
    /// The std140 copies of structs that WGSL lays out as std140 already: written as the
    /// struct itself (`Light_std140` is `Light`), and not declared.
    pub same_as: HashMap<Handle<naga::Type>, Handle<naga::Type>>,
}

impl ModuleNames {
    /// Names every type, member, constant, global, function and entry point of the module.
    pub(crate) fn new(module: &Module) -> ModuleNames {
        let mut names = ModuleNames {
            map: HashMap::new(),
            taken: HashSet::new(),
            same_as: std140_copies(module),
        };
        let predeclared: HashSet<Handle<naga::Type>> = module
            .special_types
            .predeclared_types
            .values()
            .copied()
            .collect();
        let mut items: Vec<(NameKey, String)> = Vec::new();
        for (h, t) in module.types.iter() {
            if let TypeInner::Struct { members, .. } = &t.inner {
                if predeclared.contains(&h) {
                    // `__modf_result_f32` and its `fract`, `whole`: WGSL's own names.
                    names
                        .map
                        .insert(NameKey::Type(h), t.name.clone().unwrap_or_default());
                    for (i, m) in members.iter().enumerate() {
                        let n = m.name.clone().unwrap_or_default();
                        names.map.insert(NameKey::StructMember(h, i as u32), n);
                    }
                    continue;
                }
                items.push((NameKey::Type(h), t.name.clone().unwrap_or("Struct".into())));
                let mut member_names: HashSet<String> = members
                    .iter()
                    .filter_map(|m| m.name.clone())
                    .filter(|n| !n.starts_with("_essl_"))
                    .collect();
                for (i, m) in members.iter().enumerate() {
                    let base = m.name.as_deref().unwrap_or("member");
                    let base = base.strip_prefix("_essl_").unwrap_or(base);
                    member_names.remove(base);
                    let n = unique(&sanitize(base), &member_names);
                    member_names.insert(n.clone());
                    names.map.insert(NameKey::StructMember(h, i as u32), n);
                }
            }
        }
        for (h, c) in module.constants.iter() {
            if let Some(n) = &c.name {
                items.push((NameKey::Constant(h), n.clone()));
            }
        }
        for (h, g) in module.global_variables.iter() {
            items.push((
                NameKey::GlobalVariable(h),
                g.name.clone().unwrap_or("global".into()),
            ));
        }
        for (h, f) in module.functions.iter() {
            items.push((
                NameKey::Function(h),
                f.name.clone().unwrap_or("function".into()),
            ));
        }
        for (i, ep) in module.entry_points.iter().enumerate() {
            items.push((NameKey::EntryPoint(i as u16), ep.name.clone()));
        }
        // Entry points first (`main` stays `main`), then the user's names, then essl's.
        let rank = |k: &NameKey, n: &str| match k {
            NameKey::EntryPoint(_) => 0,
            _ if n.starts_with("_essl_") || n.ends_with("_std140") => 2,
            _ => 1,
        };
        items.sort_by_key(|(k, n)| rank(k, n));
        for (key, original) in items {
            if let NameKey::Type(h) = key {
                if names.same_as.contains_key(&h) {
                    continue;
                }
            }
            // essl's names, and a struct's std140 copy where the struct itself is not used.
            let readable = READABLE
                .iter()
                .find(|(from, _)| *from == original)
                .map_or(original.as_str(), |(_, to)| to);
            let readable = readable.strip_suffix("_std140").unwrap_or(readable);
            let mut name = unique(&sanitize(readable), &names.taken);
            if name != readable && readable != original {
                name = unique(&sanitize(&original), &names.taken);
            }
            names.taken.insert(name.clone());
            names.map.insert(key, name);
        }
        for (&copy, &of) in &names.same_as {
            let name = names.get(NameKey::Type(of)).to_owned();
            names.map.insert(NameKey::Type(copy), name);
        }
        names
    }

    /// The name of an item.
    pub(crate) fn get(&self, key: NameKey) -> &str {
        self.map.get(&key).map_or("unnamed", String::as_str)
    }
}

/// The structs `X_std140` whose members are those of a struct `X` (by name and, through the
/// same rule, by type) and need no `@size`: WGSL's layout of `X` is then std140's.
fn std140_copies(module: &Module) -> HashMap<Handle<naga::Type>, Handle<naga::Type>> {
    let sized = crate::layout::struct_sizes(module);
    let by_name: HashMap<&str, Handle<naga::Type>> = module
        .types
        .iter()
        .filter(|(_, t)| matches!(t.inner, TypeInner::Struct { .. }))
        .filter_map(|(h, t)| Some((t.name.as_deref()?, h)))
        .collect();
    let mut same = HashMap::new();
    // Types come before the types that hold them: inner copies are known first.
    for (h, t) in module.types.iter() {
        let Some(base) = t.name.as_deref().and_then(|n| n.strip_suffix("_std140")) else {
            continue;
        };
        let Some(&of) = by_name.get(base) else {
            continue;
        };
        if !sized.contains_key(&h) && equivalent(module, h, of, &same) {
            same.insert(h, of);
        }
    }
    same
}

/// Whether two types are written the same once the std140 copies are their structs.
fn equivalent(
    module: &Module,
    a: Handle<naga::Type>,
    b: Handle<naga::Type>,
    same: &HashMap<Handle<naga::Type>, Handle<naga::Type>>,
) -> bool {
    let a = same.get(&a).copied().unwrap_or(a);
    let b = same.get(&b).copied().unwrap_or(b);
    if a == b {
        return true;
    }
    match (&module.types[a].inner, &module.types[b].inner) {
        (TypeInner::Struct { members: ma, .. }, TypeInner::Struct { members: mb, .. }) => {
            ma.len() == mb.len()
                && ma
                    .iter()
                    .zip(mb)
                    .all(|(x, y)| x.name == y.name && equivalent(module, x.ty, y.ty, same))
        }
        (
            TypeInner::Array {
                base: x, size: sx, ..
            },
            TypeInner::Array {
                base: y, size: sy, ..
            },
        ) => sx == sy && equivalent(module, *x, *y, same),
        _ => false,
    }
}

/// Names within one function (arguments, locals, `let`s), apart from the module's.
pub(crate) struct Scope<'a> {
    module: &'a HashSet<String>,
    taken: HashSet<String>,
}

impl<'a> Scope<'a> {
    /// An empty function scope beside the module's names.
    pub(crate) fn new(module: &'a HashSet<String>) -> Scope<'a> {
        Scope {
            module,
            taken: HashSet::new(),
        }
    }

    /// A name for `wanted`, unique in the function and apart from the module's names.
    pub(crate) fn name(&mut self, wanted: &str) -> String {
        let base = sanitize(wanted);
        let mut n = base.clone();
        let mut k = 0;
        while self.taken.contains(&n) || self.module.contains(&n) {
            k += 1;
            n = format!("{base}_{k}");
        }
        self.taken.insert(n.clone());
        n
    }

    /// Takes `name` as it is (a name already unique, given again in a disjoint scope).
    pub(crate) fn reuse(&mut self, name: &str) {
        self.taken.insert(name.to_owned());
    }

    /// Whether `name` is free in the function and the module.
    pub(crate) fn free(&self, name: &str) -> bool {
        !self.taken.contains(name) && !self.module.contains(name)
    }
}

/// `name` with a suffix (`_1`, `_2`…) until it is not in `taken`.
fn unique(name: &str, taken: &HashSet<String>) -> String {
    let mut n = name.to_owned();
    let mut k = 0;
    while taken.contains(&n) {
        k += 1;
        n = format!("{name}_{k}");
    }
    n
}

/// A WGSL identifier for `name`: characters outside identifiers become `_`, and a reserved
/// word or a predeclared name gets a `_`.
pub(crate) fn sanitize(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    while out.starts_with("__") {
        out.remove(0);
    }
    if out.is_empty() || out == "_" {
        out = "unnamed".into();
    }
    if out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    if naga::keywords::wgsl::RESERVED_SET.contains(&out)
        || naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET.contains(&out)
        || short_type(&out)
    {
        out.push('_');
    }
    out
}

/// Whether `name` is one of WGSL's predeclared type aliases (`vec3f`, `mat4x4h`), which the
/// writer spells types with.
fn short_type(name: &str) -> bool {
    let b = name.as_bytes();
    let size = |c: u8| (b'2'..=b'4').contains(&c);
    match b {
        [b'v', b'e', b'c', n, s] => size(*n) && b"fiuh".contains(s),
        [b'm', b'a', b't', c, b'x', r, s] => size(*c) && size(*r) && b"fh".contains(s),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glsl_names_stay() {
        assert_eq!(sanitize("u_light0"), "u_light0");
        assert_eq!(sanitize("select"), "select_");
        assert_eq!(sanitize("var"), "var_");
        assert_eq!(sanitize("vec3"), "vec3_");
        assert_eq!(sanitize("vec3f"), "vec3f_");
        assert_eq!(sanitize("mat4x4f"), "mat4x4f_");
        assert_eq!(sanitize("vec3fx"), "vec3fx");
        assert_eq!(sanitize("__x"), "_x");
        assert_eq!(sanitize("u_tex[0]"), "u_tex_0_");
    }

    #[test]
    fn scopes_add_suffixes() {
        let module: HashSet<String> = ["color".to_owned()].into();
        let mut s = Scope::new(&module);
        assert_eq!(s.name("i"), "i");
        assert_eq!(s.name("i"), "i_1");
        assert_eq!(s.name("color"), "color_1");
    }
}
