//! Varyings: each fragment input matched to a vertex output by name, type and interpolation,
//! and the varyings packed into WebGL2's `MAX_VARYING_VECTORS`.

use crate::diagnostic_code::Code;
use std::collections::HashMap;

use super::{location_count, same_type, static_uses, Linker, Varying, MAX_VARYING_VECTORS};
use crate::hir::{GlobalId, GlobalKind};
use crate::source::Span;
use crate::Stage;

impl Linker<'_> {
    /// Matches each fragment input to a vertex output and packs the varyings.
    pub(super) fn link_varyings(&mut self) -> Vec<Varying> {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let fuse = static_uses(fm);
        let mut out = Vec::new();
        let mut next_location = 0u32;
        let outputs: HashMap<&str, GlobalId> = vm
            .globals
            .iter()
            .enumerate()
            .filter(|(_, g)| g.kind == GlobalKind::Output)
            .map(|(i, g)| (&*g.name, i))
            .collect();
        for (fi, fg) in fm.globals.iter().enumerate() {
            if fg.kind != GlobalKind::Input {
                continue;
            }
            let used = fuse[fi];
            let Some(&vi) = outputs.get(&*fg.name) else {
                if used {
                    let name = fg.name.clone();
                    let d = self.error(
                        Some(Stage::Fragment),
                        fg.span,
                        Code::VaryingNotWritten,
                        format!("fragment input `{name}` has no matching vertex shader output"),
                        format!("FRAGMENT varying {name} does not match any VERTEX varying"),
                    );
                    d.label = "read here but never declared `out` in the vertex shader".into();
                    d.help = Some(format!(
                        "declare `out {} {name};` in the vertex shader and write it",
                        fg.ty.display(&fm.structs)
                    ));
                }
                continue;
            };
            let vg = &vm.globals[vi];
            let name = fg.name.clone();
            if !same_type(&vg.ty, &vm.structs, &fg.ty, &fm.structs) {
                let (vt, ft) = (
                    vg.ty.display(&vm.structs).to_string(),
                    fg.ty.display(&fm.structs).to_string(),
                );
                let arrays = vg.ty.is_array() && fg.ty.is_array();
                let what = if arrays { "Array sizes" } else { "Types" };
                let msg = format!("varying `{name}` is `{vt}` in the vertex shader but `{ft}` in the fragment shader");
                let line = format!(
                    "{what} of varying '{name}' differ between VERTEX and FRAGMENT shaders."
                );
                let vspan = vg.span;
                if used {
                    let d = self.error(
                        Some(Stage::Fragment),
                        fg.span,
                        Code::VaryingTypeMismatch,
                        msg,
                        line,
                    );
                    d.label = format!("`{ft}` here");
                    d.notes
                        .push(format!("the vertex shader declares it as `{vt}`"));
                    self.log.push_str(&format!(
                        "FRAGMENT varying {name} does not match any VERTEX varying\n"
                    ));
                } else {
                    let d = self.warning(
                        Some(Stage::Fragment),
                        fg.span,
                        Code::VaryingTypeMismatch,
                        msg,
                        line,
                    );
                    d.label = format!("`{ft}` here (never read, so the program still links)");
                }
                let _ = vspan;
                continue;
            }
            let vflat = vg.interpolation == Some(crate::ast::Interpolation::Flat);
            let fflat = fg.interpolation == Some(crate::ast::Interpolation::Flat);
            if vflat != fflat {
                let msg = format!("varying `{name}` is `flat` in one shader only");
                let line = format!("Interpolation types of varying '{name}' differ between VERTEX and FRAGMENT shaders.");
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    Code::VaryingInterpolationMismatch,
                    msg,
                    line,
                );
                d.label = if fflat {
                    "`flat` here but not in the vertex shader"
                } else {
                    "not `flat` here but `flat` in the vertex shader"
                }
                .into();
                self.log.push_str(&format!(
                    "FRAGMENT varying {name} does not match any VERTEX varying\n"
                ));
                continue;
            }
            let n = location_count(&fg.ty, &fm.structs);
            out.push(Varying {
                name: name.to_string(),
                vertex: vi,
                fragment: fi,
                location: next_location,
            });
            next_location += n;
        }
        if next_location > MAX_VARYING_VECTORS {
            self.error(
                None,
                Span::default(),
                Code::TooManyVaryings,
                format!("the varyings need {next_location} vectors but WebGL2 guarantees {MAX_VARYING_VECTORS}"),
                "Could not pack varying".into(),
            );
        }
        out
    }
}
