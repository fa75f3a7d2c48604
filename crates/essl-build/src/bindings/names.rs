//! Rust names and types for GLSL ones: identifiers (raw where Rust reserves the word), the
//! Rust type of a uniform, and the struct definitions that the generated `types` module holds.

use std::collections::HashMap;
use std::fmt::Write as _;

use essl::hir::Module;
use essl::types::{ScalarKind, StructDef, StructId, Type};

/// One active uniform leaf: its WebGL name, the Rust expression of its value in `u` and the
/// statement that uploads it.
pub(super) struct Leaf {
    pub(super) name: String,
    pub(super) upload: String,
}

/// A field of `Uniforms`: one uniform variable.
pub(super) struct Field {
    pub(super) ident: String,
    pub(super) glsl: String,
    pub(super) rust_type: String,
    pub(super) zero: String,
}

/// Rust names for GLSL structs, shared by both stages when their definitions are the same.
#[derive(Default)]
pub(super) struct StructNames {
    /// (stage, struct id) → Rust name.
    pub(super) names: HashMap<(u8, u32), String>,
    /// Each Rust name: its stage, id and definition text (emitted in `types`).
    pub(super) defs: Vec<(String, String)>,
    pub(super) taken: HashMap<String, (u8, u32)>,
}

impl StructNames {
    pub(super) fn name(&mut self, stage: u8, id: StructId, modules: [&Module; 2]) -> String {
        if let Some(n) = self.names.get(&(stage, id.0)) {
            return n.clone();
        }
        let structs = &modules[stage as usize].structs;
        let def = &structs[id.0 as usize];
        let base = match &def.name {
            Some(n) => type_ident(n),
            None => format!("Anonymous{}", id.0),
        };
        // The same name in the other stage with the same definition is the same type.
        let mut candidate = base.clone();
        let mut n = 1;
        while let Some(&(s, other)) = self.taken.get(&candidate) {
            let theirs = &modules[s as usize].structs;
            if essl::link::same_type(
                &Type::Struct(id),
                structs,
                &Type::Struct(StructId(other)),
                theirs,
            ) {
                self.names.insert((stage, id.0), candidate.clone());
                return candidate;
            }
            n += 1;
            candidate = format!("{base}{n}");
        }
        self.taken.insert(candidate.clone(), (stage, id.0));
        self.names.insert((stage, id.0), candidate.clone());
        let text = self.struct_text(&candidate, stage, def, modules);
        self.defs.push((candidate.clone(), text));
        candidate
    }

    pub(super) fn struct_text(
        &mut self,
        name: &str,
        stage: u8,
        def: &StructDef,
        modules: [&Module; 2],
    ) -> String {
        let structs = &modules[stage as usize].structs;
        let mut fields = String::new();
        let mut zero = String::new();
        for m in &def.members {
            let (ty, z) = self.rust_type(&m.ty, stage, modules, "");
            let _ = writeln!(
                fields,
                "        /// `{}`\n        pub {}: {ty},",
                declaration(&m.ty, &m.name, structs),
                field_ident(&m.name)
            );
            let _ = write!(zero, "\n            {}: {z},", field_ident(&m.name));
        }
        let glsl = def.name.as_deref().unwrap_or("(anonymous)");
        format!(
            "    /// GLSL `struct {glsl}`.\n    #[derive(Clone, Copy, Debug, PartialEq)]\n    \
             pub struct {name} {{\n{fields}    }}\n\n    impl {name} {{\n        \
             /// Every member zero (false), as a uniform is before it is set.\n        \
             pub const ZERO: Self = Self {{{zero}\n        }};\n    }}\n\n    \
             impl ::core::default::Default for {name} {{\n        \
             fn default() -> Self {{\n            Self::ZERO\n        }}\n    }}\n"
        )
    }

    /// The Rust type of a GLSL type and its zero value; `prefix` is the path to `types`.
    pub(super) fn rust_type(
        &mut self,
        ty: &Type,
        stage: u8,
        modules: [&Module; 2],
        prefix: &str,
    ) -> (String, String) {
        match ty {
            Type::Scalar(k) => (scalar(*k).into(), scalar_zero(*k).into()),
            Type::Vector(k, n) => (
                format!("[{}; {n}]", scalar(*k)),
                format!("[{}; {n}]", scalar_zero(*k)),
            ),
            Type::Matrix { cols, rows } => {
                let n = *cols as u32 * *rows as u32;
                (format!("[f32; {n}]"), format!("[0.0; {n}]"))
            }
            Type::Sampler(_) => ("i32".into(), "0".into()),
            Type::Struct(id) => {
                let name = self.name(stage, *id, modules);
                (format!("{prefix}{name}"), format!("{prefix}{name}::ZERO"))
            }
            Type::Array(el, n) => {
                let (t, z) = self.rust_type(el, stage, modules, prefix);
                (format!("[{t}; {n}]"), format!("[{z}; {n}]"))
            }
            Type::Void => ("()".into(), "()".into()),
        }
    }
}

pub(super) fn scalar(k: ScalarKind) -> &'static str {
    match k {
        ScalarKind::Float => "f32",
        ScalarKind::Int => "i32",
        ScalarKind::Uint => "u32",
        ScalarKind::Bool => "bool",
    }
}

pub(super) fn scalar_zero(k: ScalarKind) -> &'static str {
    match k {
        ScalarKind::Float => "0.0",
        ScalarKind::Int | ScalarKind::Uint => "0",
        ScalarKind::Bool => "false",
    }
}

/// Rust's keywords (strict, reserved and 2018+): GLSL may use any of them as a name.
const RUST_KEYWORDS: &[&str] = &[
    "abstract", "as", "async", "await", "become", "box", "break", "const", "continue", "crate",
    "do", "dyn", "else", "enum", "extern", "false", "final", "fn", "for", "gen", "if", "impl",
    "in", "let", "loop", "macro", "match", "mod", "move", "mut", "override", "priv", "pub", "ref",
    "return", "self", "Self", "static", "struct", "super", "trait", "true", "try", "type",
    "typeof", "union", "unsafe", "unsized", "use", "virtual", "where", "while", "yield",
];

/// Whether Rust reserves `name` (a module or field of that name needs another spelling).
pub(crate) fn is_keyword(name: &str) -> bool {
    RUST_KEYWORDS.contains(&name)
}

/// A GLSL name as a Rust field or constant name.
pub(super) fn field_ident(name: &str) -> String {
    match name {
        "self" | "Self" | "super" | "crate" | "_" => format!("{name}_"),
        n if RUST_KEYWORDS.contains(&n) => format!("r#{n}"),
        n => n.to_string(),
    }
}

/// A GLSL struct name as a Rust type name: not a keyword, and not a primitive type's name
/// (a struct called `f32` would shadow the primitive in the generated module).
pub(super) fn type_ident(name: &str) -> String {
    const PRIMITIVES: &[&str] = &[
        "bool", "char", "f32", "f64", "i8", "i16", "i32", "i64", "i128", "isize", "str", "u8",
        "u16", "u32", "u64", "u128", "usize", "ZERO",
    ];
    if PRIMITIVES.contains(&name) || RUST_KEYWORDS.contains(&name) || name == "_" {
        format!("{name}_")
    } else {
        name.to_string()
    }
}

/// A GLSL declaration of `name` with type `ty` (`Light u_lights[3]`, `mat4 u_world`).
pub(super) fn declaration(ty: &Type, name: &str, structs: &[StructDef]) -> String {
    match ty {
        Type::Array(el, n) => format!("{}[{n}]", declaration(el, name, structs)),
        Type::Struct(id) => match &structs[id.0 as usize].name {
            Some(s) => format!("{s} {name}"),
            None => format!("struct {{ … }} {name}"),
        },
        t => format!("{} {name}", t.display(structs)),
    }
}

/// The GLSL spelling of an attribute's WebGL type.
pub(super) fn glsl_of(ty: essl::types::GlType) -> String {
    ty.to_type().display(&[]).to_string()
}
