//! The uniforms each stage may use, as ANGLE counts them when linking (`UniformLinker`): the
//! active uniforms of the default block take one row per vector (a matrix one per column,
//! unpacked) and must fit in `MAX_VERTEX_UNIFORM_VECTORS` or `MAX_FRAGMENT_UNIFORM_VECTORS`;
//! their samplers in `MAX_VERTEX_TEXTURE_IMAGE_UNITS` or `MAX_TEXTURE_IMAGE_UNITS`. Past the
//! implementation's numbers the program does not link; past what WebGL guarantees — the
//! uniforms packed as Appendix A §7 packs them ([`super::packing`]) — it links with a warning.

use super::packing::{items_of, pack, PackItem};
use super::Linker;
use crate::diagnostic_code::Code;
use crate::hir::{GlobalKind, Module};
use crate::source::Span;
use crate::types::{StructDef, Type};
use crate::Stage;

/// Rows (unpacked) and samplers of a value of type `ty`.
fn count(ty: &Type, structs: &[StructDef]) -> (u64, u64) {
    match ty {
        Type::Sampler(_) => (0, 1),
        Type::Matrix { cols, .. } => (u64::from(*cols), 0),
        Type::Array(el, n) => {
            let (r, s) = count(el, structs);
            (
                r.saturating_mul(u64::from(*n)),
                s.saturating_mul(u64::from(*n)),
            )
        }
        Type::Struct(id) => structs
            .get(id.0 as usize)
            .map_or(&[][..], |s| &s.members)
            .iter()
            .fold((0, 0), |(r, s), m| {
                let (mr, ms) = count(&m.ty, structs);
                (r.saturating_add(mr), s.saturating_add(ms))
            }),
        _ => (1, 0),
    }
}

/// What the active default-block uniforms of one stage take.
struct Usage {
    /// Rows, unpacked.
    rows: u64,
    /// Samplers.
    samplers: u64,
    /// Rectangles for packing (samplers left out).
    items: Vec<PackItem>,
    /// The uniform with the most rows, and the first sampler.
    largest: Span,
    first_sampler: Span,
}

fn active_uniforms(m: &Module) -> Usage {
    let mut u = Usage {
        rows: 0,
        samplers: 0,
        items: Vec::new(),
        largest: Span::default(),
        first_sampler: Span::default(),
    };
    let mut most = 0;
    for g in m
        .globals
        .iter()
        .filter(|g| g.kind == GlobalKind::Uniform && g.used)
    {
        let (r, s) = count(&g.ty, &m.structs);
        u.rows = u.rows.saturating_add(r);
        if s > 0 && u.samplers == 0 {
            u.first_sampler = g.span;
        }
        u.samplers = u.samplers.saturating_add(s);
        if r > most {
            most = r;
            u.largest = g.span;
        }
        if s == 0 {
            u.items.extend(items_of(&g.name, &g.ty, &m.structs, g.span));
        }
    }
    u
}

impl Linker<'_> {
    /// Checks both stages' uniforms and samplers against the target's limits.
    pub(super) fn check_uniform_limits(&mut self) {
        for stage in [Stage::Vertex, Stage::Fragment] {
            let shader = if stage == Stage::Vertex {
                self.vs
            } else {
                self.fs
            };
            let profile = shader.target.profile();
            let (imp, min) = (&profile.implementation, &profile.guaranteed);
            let (max_vectors, min_vectors, max_units, min_units, name, units) = match stage {
                Stage::Vertex => (
                    imp.vertex_uniform_vectors,
                    min.vertex_uniform_vectors,
                    imp.vertex_texture_units,
                    min.vertex_texture_units,
                    "VERTEX",
                    "MAX_VERTEX_TEXTURE_IMAGE_UNITS",
                ),
                Stage::Fragment => (
                    imp.fragment_uniform_vectors,
                    min.fragment_uniform_vectors,
                    imp.fragment_texture_units,
                    min.fragment_texture_units,
                    "FRAGMENT",
                    "MAX_TEXTURE_IMAGE_UNITS",
                ),
            };
            let u = active_uniforms(&shader.module);
            let (rows, samplers) = (u.rows, u.samplers);
            let target = shader.target.display();
            let vectors = format!("MAX_{name}_UNIFORM_VECTORS");
            if rows > u64::from(max_vectors) {
                let d = self.error(
                    Some(stage),
                    u.largest,
                    Code::TooManyUniforms,
                    format!("the {} shader's active uniforms take {rows} vectors; `{vectors}` is {max_vectors}", stage.as_str()),
                    format!("{name} shader uniforms count exceeds {vectors}({max_vectors})"),
                );
                d.help = Some("use fewer or smaller uniforms, or a uniform block (WebGL 2)".into());
            } else if let Err(item) = pack(&u.items, min_vectors) {
                let d = self.warning(
                    Some(stage),
                    item.span,
                    Code::TooManyUniforms,
                    format!("the {} shader's active uniforms do not pack into the {min_vectors} vectors {target} guarantees (`{vectors}`)", stage.as_str()),
                    String::new(),
                );
                d.label = "does not fit".into();
                d.notes.push(format!("this implementation has {max_vectors}, so the program links here, but a device with the minimum would refuse it"));
            }
            if samplers > u64::from(max_units) {
                let d = self.error(
                    Some(stage),
                    u.first_sampler,
                    Code::TooManyUniforms,
                    format!(
                        "the {} shader uses {samplers} samplers; `{units}` is {max_units}",
                        stage.as_str()
                    ),
                    format!("{name} shader texture image units count exceeds {units}({max_units})"),
                );
                d.help = Some("sample fewer textures, or combine them into an atlas".into());
            } else if samplers > u64::from(min_units) {
                let d = self.warning(
                    Some(stage),
                    u.first_sampler,
                    Code::TooManyUniforms,
                    format!("the {} shader uses {samplers} samplers; {target} guarantees {min_units} (`{units}`)", stage.as_str()),
                    String::new(),
                );
                d.notes.push(format!("this implementation has {max_units}, so the program links here, but a device with the minimum would refuse it"));
            }
        }
    }
}
