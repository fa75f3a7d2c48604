//! Varyings: each fragment input matched to a vertex output by name, type and interpolation,
//! and the varyings packed into `MAX_VARYING_VECTORS` rows ([`super::packing`]).

use crate::diagnostic_code::Code;
use rustc_hash::FxHashMap as HashMap;

use super::packing::{items_of, pack, PackItem};
use super::{location_count, same_type, static_uses, Linker, Varying};
use crate::hir::{GlobalId, GlobalKind};
use crate::source::Span;
use crate::Stage;

impl Linker<'_> {
    /// Matches each fragment input to a vertex output and packs the varyings.
    pub(super) fn link_varyings(&mut self) -> Vec<Varying> {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let fuse = static_uses(fm);
        let mut out = Vec::new();
        let mut packed: Vec<PackItem> = Vec::new();
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
            if self.interpolation_differs(&name, vg, fg) {
                continue;
            }
            let es100 = fm.version == crate::Version::Es100;
            if es100 && used && vg.invariant != fg.invariant {
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    Code::InvariantMismatch,
                    format!("varying `{name}` is `invariant` in one shader only"),
                    format!("Invariances of varying '{name}' differ between VERTEX and FRAGMENT shaders."),
                );
                d.label = if fg.invariant {
                    "`invariant` here but not in the vertex shader"
                } else {
                    "not `invariant` here but `invariant` in the vertex shader"
                }
                .into();
                d.notes.push(
                    "GLSL ES 1.00 requires a varying's invariance to match across the stages"
                        .into(),
                );
                continue;
            }
            let n = location_count(&fg.ty, &fm.structs);
            if used {
                packed.extend(items_of(&name, &fg.ty, &fm.structs, fg.span));
            }
            out.push(Varying {
                name: name.to_string(),
                vertex: vi,
                fragment: fi,
                location: next_location,
            });
            next_location += n;
        }
        packed.extend(self.builtin_varyings());
        self.check_varying_packing(&packed);
        self.check_builtin_invariance();
        out
    }

    /// Reports a varying whose interpolation differs between the stages (`flat` and
    /// `noperspective` must match; `smooth` is what no qualifier means); whether it did.
    fn interpolation_differs(
        &mut self,
        name: &str,
        vg: &crate::hir::Global,
        fg: &crate::hir::Global,
    ) -> bool {
        use crate::ast::Interpolation as I;
        let (vq, fq) = (
            vg.interpolation.unwrap_or(I::Smooth),
            fg.interpolation.unwrap_or(I::Smooth),
        );
        if vq == fq {
            return false;
        }
        let q = if vq == I::Flat || fq == I::Flat {
            I::Flat
        } else {
            I::NoPerspective
        };
        let word = if q == I::Flat {
            "flat"
        } else {
            "noperspective"
        };
        let msg = format!("varying `{name}` is `{word}` in one shader only");
        let line = format!(
            "Interpolation types of varying '{name}' differ between VERTEX and FRAGMENT shaders."
        );
        let d = self.error(
            Some(Stage::Fragment),
            fg.span,
            Code::VaryingInterpolationMismatch,
            msg,
            line,
        );
        d.label = if fq == q {
            format!("`{word}` here but not in the vertex shader")
        } else {
            format!("not `{word}` here but `{word}` in the vertex shader")
        };
        self.log.push_str(&format!(
            "FRAGMENT varying {name} does not match any VERTEX varying\n"
        ));
        true
    }

    /// The built-in varyings ANGLE packs with the others when they are used: the fragment
    /// shader's `gl_FragCoord`, `gl_FrontFacing` and `gl_PointCoord`, the vertex shader's
    /// `gl_PointSize` (`tests/oracle/ES100.md`, "Varying packing").
    fn builtin_varyings(&self) -> Vec<PackItem> {
        use crate::builtins::BuiltinVar::{FragCoord, FrontFacing, PointCoord, PointSize};
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let used = [
            (FragCoord, fm.used_builtins.contains(&FragCoord)),
            (FrontFacing, fm.used_builtins.contains(&FrontFacing)),
            (PointCoord, fm.used_builtins.contains(&PointCoord)),
            (PointSize, vm.used_builtins.contains(&PointSize)),
        ];
        used.into_iter()
            .filter(|(_, u)| *u)
            .flat_map(|(b, _)| items_of(b.name(), &b.ty(), &[], Span::default()))
            .collect()
    }

    /// GLSL ES 1.00: `gl_FragCoord` may be invariant only if `gl_Position` is, `gl_PointCoord`
    /// only if `gl_PointSize` is (ANGLE's `LinkValidateBuiltInVaryingsInvariant`).
    fn check_builtin_invariance(&mut self) {
        use crate::builtins::BuiltinVar::{FragCoord, PointCoord, PointSize, Position};
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        if fm.version != crate::Version::Es100 {
            return;
        }
        let vertex = |b| vm.invariant_all || vm.invariant_builtins.contains(&b);
        for (frag, vert) in [(FragCoord, Position), (PointCoord, PointSize)] {
            if fm.invariant_builtins.contains(&frag) && !vertex(vert) {
                let (f, v) = (frag.name(), vert.name());
                let d = self.error(
                    Some(Stage::Fragment),
                    Span::default(),
                    Code::InvariantMismatch,
                    format!("`{f}` is declared `invariant` but the vertex shader's `{v}` is not"),
                    format!("{f} can only be declared invariant if and only if {v} is declared invariant."),
                );
                d.help = Some(format!("add `invariant {v};` to the vertex shader"));
            }
        }
    }

    /// The varyings the fragment shader uses must pack into the implementation's rows (an
    /// error otherwise) and should into those WebGL guarantees (a warning otherwise).
    fn check_varying_packing(&mut self, packed: &[PackItem]) {
        let target = self.vs.target;
        let profile = target.profile();
        let (max, min) = (
            profile.implementation.varying_vectors,
            profile.guaranteed.varying_vectors,
        );
        let rows: u32 = packed.iter().map(|i| i.rows).sum();
        match pack(packed, max) {
            Err(item) => {
                let (name, span) = (item.name.clone(), item.span);
                let d = self.error(
                    Some(Stage::Fragment),
                    span,
                    Code::TooManyVaryings,
                    format!("the varyings do not fit in the {max} rows of `MAX_VARYING_VECTORS` once packed: `{name}` does not"),
                    format!("Could not pack varying {name}"),
                );
                d.label = "does not fit".into();
                d.notes.push(format!(
                    "they hold {rows} vectors; packing puts up to four components in a row (GLSL ES 1.00 Appendix A §7)"
                ));
                d.help = Some("merge small varyings into `vec4`s, or drop some".into());
            }
            Ok(()) if pack(packed, min).is_err() => {
                let span = pack(packed, min).err().map_or(Span::default(), |i| i.span);
                let d = self.warning(
                    Some(Stage::Fragment),
                    span,
                    Code::TooManyVaryings,
                    format!(
                        "the varyings need more than the {min} rows {} guarantees once packed",
                        target.display()
                    ),
                    String::new(),
                );
                d.notes.push(format!(
                    "this implementation has {max}, so the program links here, but a device with \
                     the minimum `MAX_VARYING_VECTORS` would refuse it"
                ));
                d.help =
                    Some("merge small varyings into `vec4`s to stay within the minimum".into());
            }
            Ok(()) => {}
        }
    }
}
