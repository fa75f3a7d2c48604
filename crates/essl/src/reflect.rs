//! Reflection: a shader's inputs, outputs and uniforms with WebGL's names and types, expanded
//! the way `getActiveUniform` enumerates them (`u_spots[0].position`, `u_a[0]` of size 4), and
//! whether the entry point uses each.

use crate::hir::{GlobalId, GlobalKind, Module};
use crate::types::{GlType, Precision, StructDef, Type};

/// One step from a uniform variable to a leaf inside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PathStep {
    /// A struct member, by index.
    Member(u32),
    /// An array element.
    Index(u32),
}

/// Where a uniform leaf lives.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UniformSource {
    /// A loose uniform (a global) and the path to the leaf.
    Default {
        /// The global.
        global: GlobalId,
        /// From the global to the leaf (the leaf itself may be an array of basic types).
        path: Vec<PathStep>,
    },
    /// A member of a uniform block.
    Block {
        /// The block's index in the module.
        block: usize,
        /// The member's index.
        member: usize,
        /// From the member to the leaf.
        path: Vec<PathStep>,
    },
}

/// One entry of the active-uniform list: a basic or sampler leaf.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UniformLeaf {
    /// WebGL's name (`light.position`, `u_a[0]`, `Block.member`).
    pub name: String,
    /// WebGL's type.
    pub ty: GlType,
    /// Array length (1 if not an array).
    pub size: u32,
    /// The leaf's precision.
    pub precision: Option<Precision>,
    /// Where it lives.
    pub source: UniformSource,
}

/// A shader input or output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InterfaceVar {
    /// Its name.
    pub name: String,
    /// The global in the module.
    pub global: GlobalId,
    /// Its type in GLSL syntax.
    pub type_name: String,
    /// WebGL's type, for basic types.
    pub ty: Option<GlType>,
    /// `layout(location = N)`.
    pub location: Option<u32>,
    /// The entry point uses it.
    pub used: bool,
}

/// What a shader declares and uses.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Reflection {
    /// `in` variables.
    pub inputs: Vec<InterfaceVar>,
    /// `out` variables.
    pub outputs: Vec<InterfaceVar>,
    /// Uniform leaves of loose uniforms, in declaration order, with `used` of their variable.
    pub uniforms: Vec<(UniformLeaf, bool)>,
    /// Uniform leaves of uniform blocks.
    pub block_uniforms: Vec<UniformLeaf>,
}

/// One expanded leaf: WebGL name, type, array size, precision, path from the variable.
pub type Leaf = (String, GlType, u32, Option<Precision>, Vec<PathStep>);

/// Expands a value of type `ty` named `name` into WebGL's uniform leaves.
pub fn expand(
    name: &str,
    ty: &Type,
    precision: Option<Precision>,
    structs: &[StructDef],
    path: &mut Vec<PathStep>,
    out: &mut Vec<Leaf>,
) {
    match ty {
        Type::Struct(id) => {
            for (i, m) in structs[id.0 as usize].members.iter().enumerate() {
                path.push(PathStep::Member(i as u32));
                expand(
                    &format!("{name}.{}", m.name),
                    &m.ty,
                    m.precision,
                    structs,
                    path,
                    out,
                );
                path.pop();
            }
        }
        Type::Array(el, n) => match &**el {
            Type::Struct(_) => {
                for i in 0..*n {
                    path.push(PathStep::Index(i));
                    expand(&format!("{name}[{i}]"), el, precision, structs, path, out);
                    path.pop();
                }
            }
            t => {
                if let Some(gl) = t.gl_type() {
                    out.push((format!("{name}[0]"), gl, *n, precision, path.clone()));
                }
            }
        },
        t => {
            if let Some(gl) = t.gl_type() {
                out.push((name.to_string(), gl, 1, precision, path.clone()));
            }
        }
    }
}

/// Reflects a checked module.
pub fn reflect(m: &Module) -> Reflection {
    let mut r = Reflection::default();
    for (gi, g) in m.globals.iter().enumerate() {
        let var = || InterfaceVar {
            name: g.name.to_string(),
            global: gi,
            type_name: g.ty.display(&m.structs).to_string(),
            ty: g.ty.gl_type(),
            location: g.location,
            used: g.used,
        };
        match g.kind {
            GlobalKind::Input => r.inputs.push(var()),
            GlobalKind::Output => r.outputs.push(var()),
            GlobalKind::Uniform => {
                let mut leaves = Vec::new();
                expand(
                    &g.name,
                    &g.ty,
                    g.precision,
                    &m.structs,
                    &mut Vec::new(),
                    &mut leaves,
                );
                for (name, ty, size, precision, path) in leaves {
                    r.uniforms.push((
                        UniformLeaf {
                            name,
                            ty,
                            size,
                            precision,
                            source: UniformSource::Default { global: gi, path },
                        },
                        g.used,
                    ));
                }
            }
            _ => {}
        }
    }
    for (bi, b) in m.blocks.iter().enumerate() {
        for (mi, (mname, ty, precision, _)) in b.members.iter().enumerate() {
            let base = match &b.instance {
                Some(_) => format!("{}.{}", b.name, mname),
                None => mname.to_string(),
            };
            let mut leaves = Vec::new();
            expand(
                &base,
                ty,
                *precision,
                &m.structs,
                &mut Vec::new(),
                &mut leaves,
            );
            for (name, ty, size, precision, path) in leaves {
                r.block_uniforms.push(UniformLeaf {
                    name,
                    ty,
                    size,
                    precision,
                    source: UniformSource::Block {
                        block: bi,
                        member: mi,
                        path,
                    },
                });
            }
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::SourceFile;
    use crate::Stage;

    fn uniforms(src: &str) -> Vec<(String, &'static str, u32, bool)> {
        let sh = crate::compile(
            SourceFile::new("t.frag", src),
            Stage::Fragment,
            &Default::default(),
        );
        assert!(sh.ok(), "{:?}", sh.diagnostics);
        reflect(&sh.module)
            .uniforms
            .into_iter()
            .map(|(l, used)| (l.name, l.ty.name(), l.size, used))
            .collect()
    }

    #[test]
    fn arrays_of_structs_expand_element_by_element() {
        let u = uniforms(
            "#version 300 es\nprecision mediump float;\nstruct S { vec3 position; float w[3]; };\nuniform S u_spots[2];\nuniform vec4 u_a[4];\nout vec4 o;\nvoid main() { o = vec4(u_spots[1].position, u_a[1].x); }\n",
        );
        let names: Vec<&str> = u.iter().map(|x| x.0.as_str()).collect();
        assert_eq!(
            names,
            [
                "u_spots[0].position",
                "u_spots[0].w[0]",
                "u_spots[1].position",
                "u_spots[1].w[0]",
                "u_a[0]"
            ]
        );
        assert_eq!(u[1].2, 3);
        assert_eq!(u[4], ("u_a[0]".to_string(), "FLOAT_VEC4", 4, true));
    }

    #[test]
    fn unused_uniforms_are_marked() {
        let u = uniforms("#version 300 es\nprecision mediump float;\nuniform float a;\nuniform float b;\nout vec4 o;\nvoid main() { if (false) { o = vec4(b); } o = vec4(a); }\n");
        assert_eq!(u.iter().map(|x| x.3).collect::<Vec<_>>(), [true, false]);
    }
}
