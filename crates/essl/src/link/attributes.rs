//! Attributes: locations from `layout(location)` and `bindAttribLocation`, the rest placed
//! without aliasing, within `MAX_VERTEX_ATTRIBS`.

use super::{location_count, ActiveAttribute, Linker, MAX_VERTEX_ATTRIBS};
use crate::builtins::BuiltinVar;
use crate::diagnostic::Label;
use crate::diagnostic_code::Code;
use crate::hir::{GlobalId, GlobalKind};
use crate::types::GlType;
use crate::Stage;

impl Linker<'_> {
    /// Puts an attribute at `loc` (taking `n` locations) unless that aliases another one.
    fn place_attribute(
        &mut self,
        taken: &mut [Option<GlobalId>],
        locations: &mut Vec<(GlobalId, u32)>,
        gi: GlobalId,
        loc: u32,
        n: u32,
    ) {
        let vm = &self.vs.module;
        for l in loc..loc + n {
            if let Some(Some(other)) = taken.get(l as usize) {
                let (name, span) = (vm.globals[gi].name.clone(), vm.globals[gi].span);
                let (other_name, other_span) =
                    (vm.globals[*other].name.clone(), vm.globals[*other].span);
                let d = self.error(
                    Some(Stage::Vertex),
                    span,
                    Code::AttributeLocationAlias,
                    format!("attribute `{name}` overlaps `{other_name}` at location {l}"),
                    format!("Attribute '{name}' aliases attribute '{other_name}' at location {l}"),
                );
                d.label = "location already taken".into();
                d.secondary.push(Label {
                    span: other_span,
                    message: format!("`{other_name}` is here"),
                });
                return;
            }
        }
        for l in loc..loc + n {
            if let Some(t) = taken.get_mut(l as usize) {
                *t = Some(gi);
            }
        }
        locations.push((gi, loc));
    }

    /// Gives every active attribute a location: its binding or `layout(location)`, else the
    /// first free slots; the active attributes and the locations.
    pub(super) fn link_attributes(
        &mut self,
        bindings: &[(String, u32)],
    ) -> (Vec<ActiveAttribute>, Vec<(GlobalId, u32)>) {
        let vm = &self.vs.module;
        let inputs: Vec<GlobalId> = vm
            .globals
            .iter()
            .enumerate()
            .filter(|(_, g)| g.kind == GlobalKind::Input)
            .map(|(i, _)| i)
            .collect();
        let mut taken: Vec<Option<GlobalId>> = vec![None; 64];
        let mut locations: Vec<(GlobalId, u32)> = Vec::new();
        // Explicit: `layout(location)` first, then `bindAttribLocation`.
        for &gi in &inputs {
            let g = &self.vs.module.globals[gi];
            let n = location_count(&g.ty, &self.vs.module.structs);
            let bound = bindings
                .iter()
                .find(|(name, _)| **name == *g.name)
                .map(|b| b.1);
            if let Some(loc) = g.location.or(bound) {
                self.place_attribute(&mut taken, &mut locations, gi, loc, n);
            }
        }
        for &gi in &inputs {
            if locations.iter().any(|(x, _)| *x == gi) {
                continue;
            }
            let g = &self.vs.module.globals[gi];
            let n = location_count(&g.ty, &self.vs.module.structs);
            match (0..64u32)
                .find(|&s| (s..s + n).all(|l| taken.get(l as usize).is_some_and(|t| t.is_none())))
            {
                Some(start) => self.place_attribute(&mut taken, &mut locations, gi, start, n),
                None => {
                    let (name, span) = (g.name.clone(), g.span);
                    self.error(
                        Some(Stage::Vertex),
                        span,
                        Code::TooManyAttributes,
                        "no free attribute location".into(),
                        format!("Too many attributes ({name})"),
                    );
                }
            }
        }
        let vm = &self.vs.module;
        let end = |gi: usize, loc: u32| loc + location_count(&vm.globals[gi].ty, &vm.structs);
        let guaranteed = self.vs.target.profile().guaranteed.vertex_attribs;
        if let Some((gi, _)) = locations
            .iter()
            .find(|(gi, loc)| end(*gi, *loc) > MAX_VERTEX_ATTRIBS)
        {
            let g = &vm.globals[*gi];
            let (name, span) = (g.name.clone(), g.span);
            let d = self.error(
                Some(Stage::Vertex),
                span,
                Code::TooManyAttributes,
                format!("attribute `{name}` needs a location beyond the {MAX_VERTEX_ATTRIBS} of `MAX_VERTEX_ATTRIBS`"),
                format!("Too many attributes ({name})"),
            );
            d.label = "out of attribute locations".into();
        } else if let Some((gi, _)) = locations
            .iter()
            .find(|(gi, loc)| vm.globals[*gi].used && end(*gi, *loc) > guaranteed)
        {
            let g = &vm.globals[*gi];
            let (name, span) = (g.name.clone(), g.span);
            let target = self.vs.target.display();
            let d = self.warning(
                Some(Stage::Vertex),
                span,
                Code::TooManyAttributes,
                format!("attribute `{name}` needs a location beyond the {guaranteed} {target} guarantees"),
                String::new(),
            );
            d.label = "past the guaranteed attribute locations".into();
            d.notes.push(format!("this implementation has {MAX_VERTEX_ATTRIBS}, so the program links here, but a device with the minimum `MAX_VERTEX_ATTRIBS` would refuse it"));
        }
        let mut attributes: Vec<ActiveAttribute> = inputs
            .iter()
            .map(|&gi| (gi, &vm.globals[gi]))
            .filter(|(_, g)| g.used)
            .filter_map(|(gi, g)| {
                let loc = locations.iter().find(|(x, _)| *x == gi)?.1;
                Some(ActiveAttribute {
                    name: g.name.to_string(),
                    ty: g.ty.gl_type()?,
                    size: 1,
                    location: loc as i32,
                    global: Some(gi),
                })
            })
            .collect();
        for b in [BuiltinVar::VertexId, BuiltinVar::InstanceId] {
            if vm.used_builtins.contains(&b) {
                attributes.push(ActiveAttribute {
                    name: b.name().into(),
                    ty: GlType::INT,
                    size: 1,
                    location: -1,
                    global: None,
                });
            }
        }
        (attributes, locations)
    }
}
