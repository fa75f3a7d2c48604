//! A shader's lowered module with the type of each of its expressions, validated or not.
//!
//! naga's validator computes every expression's type as it checks the module, and that is
//! all a tool reading the IR without translating it (the lints) needs of it; the checking is
//! most of the validator's cost (on the Vite bench's 200 shaders, validation was 9.6 M of
//! `essl lint`'s 82.1 M instructions; typing them with the typifier, 2.9 M). A module lowered for such
//! a tool is typed by naga's typifier instead ([`Lowered::typified`]); one lowered for a GPU
//! or a translation is validated ([`Lowered::validated`]). Validation checks essl's lowering,
//! not the user's shader: the front end has said whether the shader is valid WebGL.

use naga::{Expression, Handle};

use super::LowerError;
use crate::Stage;

/// A shader lowered on its own to naga IR, with the type of every expression.
#[derive(Debug)]
pub struct Lowered {
    /// The module.
    pub module: naga::Module,
    types: Types,
}

/// Where the expressions' types come from.
#[derive(Debug)]
enum Types {
    /// naga's validation information.
    Validated(naga::valid::ModuleInfo),
    /// naga's typifier, one per function (the module's functions, then its entry points).
    Typified(Vec<naga::front::Typifier>),
}

impl Lowered {
    /// A module naga's validator accepted, with its validation information.
    pub fn validated(module: naga::Module, info: naga::valid::ModuleInfo) -> Lowered {
        Lowered {
            module,
            types: Types::Validated(info),
        }
    }

    /// A module typed by naga's typifier, not validated; an expression whose type naga cannot
    /// resolve is an error in essl's lowering.
    pub fn typified(module: naga::Module, stage: Stage) -> Result<Lowered, LowerError> {
        let functions = module.functions.iter().map(|(_, f)| f);
        let entries = module.entry_points.iter().map(|e| &e.function);
        let types = functions
            .chain(entries)
            .map(|f| {
                let ctx = naga::proc::ResolveContext::with_locals(
                    &module,
                    &f.local_variables,
                    &f.arguments,
                );
                let mut typifier = naga::front::Typifier::new();
                if let Some((last, _)) = f.expressions.iter().last() {
                    // naga's handles only name expressions appended before them, so each
                    // operand is typed before the expression that reads it.
                    typifier
                        .grow(last, &f.expressions, &ctx)
                        .map_err(|e| LowerError::Invalid {
                            stage: stage.as_str(),
                            message: e.to_string(),
                            span: Default::default(),
                        })?;
                }
                Ok(typifier)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Lowered {
            module,
            types: Types::Typified(types),
        })
    }

    /// naga's validation information, where the module was validated.
    pub fn info(&self) -> Option<&naga::valid::ModuleInfo> {
        match &self.types {
            Types::Validated(info) => Some(info),
            Types::Typified(_) => None,
        }
    }

    /// The types of function `id`'s expressions (the module's functions by index, then its
    /// entry points).
    pub fn function(&self, id: usize) -> FunctionTypes<'_> {
        let of = match &self.types {
            Types::Validated(info) => match self.module.functions.iter().nth(id) {
                Some((f, _)) => Of::Info(&info[f]),
                None => Of::Info(info.get_entry_point(id - self.module.functions.len())),
            },
            Types::Typified(types) => Of::Typifier(&types[id]),
        };
        FunctionTypes {
            of,
            types: &self.module.types,
        }
    }

    /// The type of expression `h` of function `id`.
    pub fn ty(&self, id: usize, h: Handle<Expression>) -> &naga::TypeInner {
        self.function(id).ty(h)
    }
}

/// The types of one function's expressions ([`Lowered::function`]).
#[derive(Clone, Copy, Debug)]
pub struct FunctionTypes<'a> {
    of: Of<'a>,
    types: &'a naga::UniqueArena<naga::Type>,
}

#[derive(Clone, Copy, Debug)]
enum Of<'a> {
    Info(&'a naga::valid::FunctionInfo),
    Typifier(&'a naga::front::Typifier),
}

impl<'a> FunctionTypes<'a> {
    /// The type of expression `h`, as naga resolves it.
    pub fn resolution(&self, h: Handle<Expression>) -> &'a naga::proc::TypeResolution {
        match self.of {
            Of::Info(info) => &info[h].ty,
            Of::Typifier(t) => &t[h],
        }
    }

    /// The type of expression `h`.
    pub fn ty(&self, h: Handle<Expression>) -> &'a naga::TypeInner {
        self.resolution(h).inner_with(self.types)
    }
}
