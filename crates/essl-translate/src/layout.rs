//! std140 offsets in WGSL text.
//!
//! essl lays out uniform buffers as std140 and says so in naga IR with explicit member offsets
//! and struct sizes. WGSL has no offsets: it computes them from the member types, and naga's
//! WGSL writer (30.0) writes none of the IR's, so a struct whose std140 layout differs from
//! WGSL's own would come out with other offsets than the binding map's — or be rejected in
//! the uniform address space. This pass puts `@size(N)` on each member of a struct used in a
//! uniform buffer where the next member (or the struct's end) would otherwise land elsewhere
//! than the IR says; WGSL then computes exactly the IR's offsets. (Array strides already agree:
//! essl pads array elements smaller than 16 bytes into 16-byte structs.)

use std::collections::{HashMap, HashSet};

use naga::proc::{Layouter, NameKey};
use naga::{Handle, Module, TypeInner};

/// Where a uniform struct's WGSL layout needs help to have the IR's offsets.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sizes {
    /// Bytes before the first member (the other stage's uniforms, in a program's buffer).
    pub lead: u32,
    /// `@size(N)` of members, by index.
    pub sizes: HashMap<usize, u32>,
}

/// The `@size`s each struct used in a uniform buffer needs (only those that need any).
pub fn struct_sizes(module: &Module) -> HashMap<Handle<naga::Type>, Sizes> {
    let mut out = HashMap::new();
    let mut layouter = Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return out;
    }
    let mut structs = HashSet::new();
    for (_, g) in module.global_variables.iter() {
        if g.space == naga::AddressSpace::Uniform {
            reach(module, g.ty, &mut structs);
        }
    }
    for h in structs {
        let TypeInner::Struct { members, span } = &module.types[h].inner else {
            continue;
        };
        let mut sizes = HashMap::new();
        for (i, m) in members.iter().enumerate() {
            let end = m.offset + layouter[m.ty].size;
            let (next, next_align) = match members.get(i + 1) {
                Some(n) => (n.offset, layouter[n.ty].alignment),
                None => (*span, layouter[h].alignment),
            };
            if next_align.round_up(end) != next {
                sizes.insert(i, next - m.offset);
            }
        }
        let lead = members.first().map_or(0, |m| m.offset);
        if !sizes.is_empty() || lead > 0 {
            out.insert(h, Sizes { lead, sizes });
        }
    }
    out
}

/// The WGSL text with `@size` attributes where the IR's struct layout needs them.
/// `names` are the WGSL writer's ([`crate::names::wgsl_names`]).
pub fn sized_members(
    module: &Module,
    names: &naga::FastHashMap<NameKey, String>,
    wgsl: &str,
) -> String {
    let mut layouter = Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return wgsl.to_owned();
    }
    // The structs reachable from uniform buffers.
    let mut structs = HashSet::new();
    for (_, g) in module.global_variables.iter() {
        if g.space == naga::AddressSpace::Uniform {
            reach(module, g.ty, &mut structs);
        }
    }
    let mut text = wgsl.to_owned();
    let mut handles: Vec<_> = structs.into_iter().collect();
    handles.sort();
    for h in handles {
        let TypeInner::Struct { members, span } = &module.types[h].inner else {
            continue;
        };
        let mut sizes = Vec::new();
        for (i, m) in members.iter().enumerate() {
            let size = layouter[m.ty].size;
            let end = m.offset + size;
            let (next, next_align) = match members.get(i + 1) {
                Some(n) => (n.offset, layouter[n.ty].alignment),
                None => (*span, layouter[h].alignment),
            };
            if next_align.round_up(end) != next {
                sizes.push((i, next - m.offset));
            }
        }
        // WGSL's first member is at 0: bytes before the IR's first member (those of the other
        // stage's uniforms, in a program's shared buffer) become a member of their own.
        let lead = members.first().map_or(0, |m| m.offset);
        if sizes.is_empty() && lead == 0 {
            continue;
        }
        let Some(name) = names.get(&NameKey::Type(h)) else {
            continue;
        };
        let header = format!("struct {name} {{\n");
        let Some(start) = text.find(&header) else {
            continue;
        };
        let body_start = start + header.len();
        let Some(body_len) = text[body_start..].find("\n}") else {
            continue;
        };
        let mut body: Vec<String> = text[body_start..body_start + body_len]
            .split('\n')
            .map(str::to_owned)
            .collect();
        for (i, size) in sizes {
            let member = &names[&NameKey::StructMember(h, i as u32)];
            if let Some(line) = body
                .iter_mut()
                .find(|l| l.trim_start().starts_with(&format!("{member}: ")))
            {
                let indent = line.len() - line.trim_start().len();
                line.insert_str(indent, &format!("@size({size}) "));
            }
        }
        if lead > 0 {
            body.insert(0, format!("    @size({lead}) _essl_padding: u32,"));
        }
        text.replace_range(body_start..body_start + body_len, &body.join("\n"));
    }
    text
}

/// Adds the structs inside `ty` to `out`.
fn reach(module: &Module, ty: Handle<naga::Type>, out: &mut HashSet<Handle<naga::Type>>) {
    match &module.types[ty].inner {
        TypeInner::Struct { members, .. } if out.insert(ty) => {
            for m in members {
                reach(module, m.ty, out);
            }
        }
        TypeInner::Array { base, .. } | TypeInner::BindingArray { base, .. } => {
            reach(module, *base, out)
        }
        _ => {}
    }
}
