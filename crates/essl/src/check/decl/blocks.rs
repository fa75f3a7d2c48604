//! Uniform blocks: `uniform Name { ... } instance;`, their members, layouts and limits.

use crate::diagnostic_code::Code;
use crate::Name;

use crate::ast::{self, Qualifier, Storage};
use crate::check::{Checker, Sym, Var};
use crate::diagnostic::Fix;
use crate::hir::{self, GlobalKind};
use crate::source::Span;
use crate::types::{Precision, Type};

/// A block member: name, type, precision and whether it is row-major.
type BlockMember = (Name, Type, Option<Precision>, bool);

impl Checker<'_> {
    /// Declares a uniform block: its qualifiers, members, instance name and array size.
    pub(super) fn uniform_block(
        &mut self,
        qualifiers: &[(Qualifier, Span)],
        name: &ast::Ident,
        members: &[ast::MemberDecl],
        instance: Option<&(ast::Ident, Option<ast::ArraySize>)>,
        span: Span,
    ) {
        self.check_qualifier_list(qualifiers);
        let (layout, block_row_major) = self.block_qualifiers(qualifiers);
        self.check_name(name);
        let hmembers = self.block_members(members, block_row_major);
        if self.blocks.iter().any(|b| *b.name == *name.name) {
            let d = self.error(
                Code::Redefinition,
                name.span,
                format!("uniform block `{}` is declared twice", name.name),
            );
            d.label = "a second block with this name".into();
            return;
        }
        let array = self.block_array_size(instance);
        let idx = self.blocks.len();
        self.blocks.push(hir::UniformBlock {
            name: name.name.clone(),
            instance: instance.map(|(i, _)| i.name.clone()),
            array,
            members: hmembers.clone(),
            layout,
            span,
            used: false,
        });
        self.declare_block_names(name, instance, idx, &hmembers, span);
    }

    /// The block's qualifiers: `uniform` and a layout (`std140`; `shared` and `packed` are
    /// reported, WebGL2 forbids them) with the default matrix layout (`row_major`?).
    fn block_qualifiers(&mut self, qualifiers: &[(Qualifier, Span)]) -> (hir::BlockLayout, bool) {
        // WebGL2 has only std140: a block without a layout qualifier is std140.
        let mut layout = hir::BlockLayout::Std140;
        let mut block_row_major = false;
        for (q, s) in qualifiers {
            match q {
                Qualifier::Storage(Storage::Uniform) => {}
                Qualifier::Layout(items) => {
                    for item in items {
                        match &*item.name.name {
                            "std140" => layout = hir::BlockLayout::Std140,
                            "shared" | "packed" => {
                                let which = item.name.name.clone();
                                let d = self.error(
                                    Code::WebglBlockLayout,
                                    item.name.span,
                                    format!("`{which}` uniform blocks are not allowed in WebGL2"),
                                );
                                d.label = "only `std140` is portable".into();
                                d.notes.push("WebGL2 forbids `shared` and `packed` layouts so that block layouts are the same everywhere".into());
                                d.fix =
                                    Some(Fix::certain("use `std140`", item.name.span, "std140"));
                                layout = if &*which == "shared" {
                                    hir::BlockLayout::Shared
                                } else {
                                    hir::BlockLayout::Packed
                                };
                            }
                            "row_major" => block_row_major = true,
                            "column_major" => block_row_major = false,
                            other => {
                                let d = self.error(
                                    Code::InvalidLayout,
                                    item.name.span,
                                    format!("`{other}` is not a uniform block layout"),
                                );
                                d.label =
                                    "expected std140, shared, packed, row_major or column_major"
                                        .into();
                            }
                        }
                    }
                }
                Qualifier::Storage(st) => {
                    let d = self.error(
                        Code::InvalidBlock,
                        *s,
                        format!(
                            "`{}` blocks are not allowed in GLSL ES 3.00: only uniform blocks",
                            st.as_str()
                        ),
                    );
                    d.label = "not `uniform`".into();
                }
                _ => {
                    let d = self.error(
                        Code::InvalidBlock,
                        *s,
                        "this qualifier cannot apply to a uniform block",
                    );
                    d.label = "not allowed here".into();
                }
            }
        }
        (layout, block_row_major)
    }

    /// The block's members with their types, precisions and matrix layouts; a member that is
    /// invalid (a sampler, unsized, declared twice) is reported and left out.
    fn block_members(
        &mut self,
        members: &[ast::MemberDecl],
        block_row_major: bool,
    ) -> Vec<BlockMember> {
        let mut hmembers = Vec::new();
        for m in members {
            let fty = &m.ty.0;
            let row_major = self.member_row_major(fty, block_row_major);
            if let ast::TypeName::Struct(inner) = &fty.spec.name {
                let d = self.error(
                    Code::EmbeddedStruct,
                    inner.span,
                    "structs cannot be defined inside a uniform block",
                );
                d.label = "define it before the block".into();
            }
            let Some(base) = self.resolve_type(&fty.spec) else {
                continue;
            };
            for (n, arr) in &m.names {
                let ty = match arr {
                    Some(a) => match self.array_of(base.clone(), a, n.span) {
                        Some(t) => t,
                        None => continue,
                    },
                    None => base.clone(),
                };
                if ty.contains_sampler(&self.structs) {
                    let d = self.error(
                        Code::SamplerInBlock,
                        n.span,
                        "a uniform block cannot contain a sampler",
                    );
                    d.label = "a sampler".into();
                    continue;
                }
                if matches!(ty, Type::Array(_, 0)) {
                    let d =
                        self.error(Code::UnsizedArray, n.span, "block members must have a size");
                    d.label = "unsized".into();
                    continue;
                }
                let precision = self.precision_for(&ty, fty.precision().map(|p| p.0), n.span);
                if hmembers
                    .iter()
                    .any(|(mn, ..): &BlockMember| **mn == *n.name)
                {
                    let d = self.error(
                        Code::Redefinition,
                        n.span,
                        format!("block member `{}` is declared twice", n.name),
                    );
                    d.label = "a second member with this name".into();
                    continue;
                }
                hmembers.push((n.name.clone(), ty, precision, row_major));
            }
        }
        hmembers
    }

    /// A member's qualifiers: a precision and a matrix layout; whether the member is row-major.
    fn member_row_major(&mut self, fty: &ast::FullType, block_row_major: bool) -> bool {
        let mut row_major = block_row_major;
        for (q, s) in &fty.qualifiers {
            match q {
                Qualifier::Precision(_) => {}
                Qualifier::Storage(Storage::Uniform) => {}
                Qualifier::Layout(items) => {
                    for item in items {
                        match &*item.name.name {
                            "row_major" => row_major = true,
                            "column_major" => row_major = false,
                            other => {
                                let d = self.error(
                                    Code::InvalidLayout,
                                    item.name.span,
                                    format!("`{other}` cannot qualify a block member"),
                                );
                                d.label = "only row_major or column_major here".into();
                            }
                        }
                    }
                }
                _ => {
                    let d = self.error(
                        Code::InvalidBlock,
                        *s,
                        "block members may only have a precision or a matrix layout",
                    );
                    d.label = "not allowed here".into();
                }
            }
        }
        row_major
    }

    /// The instance array's size (`uniform B { ... } b[2];`), if the instance is an array.
    fn block_array_size(
        &mut self,
        instance: Option<&(ast::Ident, Option<ast::ArraySize>)>,
    ) -> Option<u32> {
        match instance.and_then(|(_, a)| a.as_ref()) {
            Some(a) => match &a.size {
                Some(e) => self.array_size(e),
                None => {
                    let d = self.error(
                        Code::UnsizedArray,
                        a.span,
                        "a uniform block array needs a size",
                    );
                    d.label = "unsized".into();
                    None
                }
            },
            None => None,
        }
    }

    /// Declares the block's instance name, or without one each member as a global.
    fn declare_block_names(
        &mut self,
        name: &ast::Ident,
        instance: Option<&(ast::Ident, Option<ast::ArraySize>)>,
        idx: usize,
        hmembers: &[BlockMember],
        span: Span,
    ) {
        match instance {
            Some((inst, _)) => {
                self.check_name(inst);
                if *inst.name == *name.name {
                    let d = self.error(
                        Code::Redefinition,
                        inst.span,
                        "a block's instance name cannot be the block's name",
                    );
                    d.label = "same name as the block".into();
                }
                self.declare(inst, Sym::Block(idx));
            }
            None => {
                for (mi, (mname, ty, precision, _)) in hmembers.iter().enumerate() {
                    let g = hir::Global {
                        name: mname.clone(),
                        ty: ty.clone(),
                        kind: GlobalKind::BlockMember(idx, mi),
                        precision: *precision,
                        interpolation: None,
                        centroid: false,
                        invariant: false,
                        location: None,
                        init: None,
                        span,
                        used: false,
                    };
                    let id = self.globals.len();
                    self.globals.push(g);
                    self.declare(
                        &ast::Ident {
                            name: mname.clone(),
                            span,
                        },
                        Sym::Var(Var::Global(id)),
                    );
                }
            }
        }
    }
}
