//! What a draw reads, collected from the program and the bound state: the buffer ranges of
//! its uniform blocks, where each vertex input's values come from, and the texture each
//! sampler slot samples. WebGL2's type rules are checked along the way (an input fed another
//! type than the shader's, a unit serving two sampler types, a texture of the wrong kind).

use essl::types::{SamplerDim, ScalarKind, Type};

use super::{Feed, SlotPlan, Source};
use crate::buffer::BufferRange;
use crate::context::Context;
use crate::framebuffer::DrawFormats;
use crate::gl;
use crate::objects::Id;
use crate::program::{ShaderInput, ValueKind};
use crate::shader_patch::{Norm32, Packed};
use crate::texture::{view_dimension, SampleKind};
use crate::vertex_array::{GenericAttrib, VertexAttrib};

/// The wgpu vertex format for an attribute array, and what the shader must still do.
fn feed_for(a: &VertexAttrib) -> Feed {
    use wgpu::VertexFormat as V;
    let n = a.size;
    // wgpu has no 3-component 8/16-bit formats: those are read as 4 components.
    let pick = |one: V, two: V, four: V| match n {
        1 => (one, 1),
        2 => (two, 2),
        _ => (four, 4),
    };
    if crate::vertex_array::packed(a.ty) {
        // One 32-bit word per element; the shader takes the four components apart.
        let signed = a.ty == gl::INT_2_10_10_10_REV;
        let (format, kind) = if signed {
            (V::Sint32, ValueKind::Sint)
        } else {
            (V::Uint32, ValueKind::Uint)
        };
        return Feed {
            format,
            kind,
            count: 1,
            used: 1,
            norm: None,
            packed: Some(Packed {
                signed,
                normalized: a.normalized,
            }),
        };
    }
    let (format, count, kind, norm) = match (a.ty, a.normalized && !a.integer) {
        (gl::FLOAT, _) => {
            let f = [V::Float32, V::Float32x2, V::Float32x3, V::Float32x4][n as usize - 1];
            (f, n, ValueKind::Float, None)
        }
        (gl::HALF_FLOAT, _) => {
            let (f, c) = pick(V::Float16, V::Float16x2, V::Float16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::BYTE, true) => {
            let (f, c) = pick(V::Snorm8, V::Snorm8x2, V::Snorm8x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::UNSIGNED_BYTE, true) => {
            let (f, c) = pick(V::Unorm8, V::Unorm8x2, V::Unorm8x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::SHORT, true) => {
            let (f, c) = pick(V::Snorm16, V::Snorm16x2, V::Snorm16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::UNSIGNED_SHORT, true) => {
            let (f, c) = pick(V::Unorm16, V::Unorm16x2, V::Unorm16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::BYTE, false) => {
            let (f, c) = pick(V::Sint8, V::Sint8x2, V::Sint8x4);
            (f, c, ValueKind::Sint, None)
        }
        (gl::UNSIGNED_BYTE, false) => {
            let (f, c) = pick(V::Uint8, V::Uint8x2, V::Uint8x4);
            (f, c, ValueKind::Uint, None)
        }
        (gl::SHORT, false) => {
            let (f, c) = pick(V::Sint16, V::Sint16x2, V::Sint16x4);
            (f, c, ValueKind::Sint, None)
        }
        (gl::UNSIGNED_SHORT, false) => {
            let (f, c) = pick(V::Uint16, V::Uint16x2, V::Uint16x4);
            (f, c, ValueKind::Uint, None)
        }
        (gl::INT, norm) => {
            let f = [V::Sint32, V::Sint32x2, V::Sint32x3, V::Sint32x4][n as usize - 1];
            (f, n, ValueKind::Sint, norm.then_some(Norm32::Signed))
        }
        (_, norm) => {
            let f = [V::Uint32, V::Uint32x2, V::Uint32x3, V::Uint32x4][n as usize - 1];
            (f, n, ValueKind::Uint, norm.then_some(Norm32::Unsigned))
        }
    };
    Feed {
        format,
        kind,
        count,
        used: n.min(count),
        norm,
        packed: None,
    }
}

/// The sampler type of a GLSL type, `None` for a type that is not a sampler.
fn sampler_type(ty: essl::types::GlType) -> Option<essl::types::SamplerType> {
    match ty.to_type() {
        Type::Sampler(s) => Some(s),
        _ => None,
    }
}

/// The texture target a sampler of dimension `dim` reads.
fn dim_target(dim: SamplerDim) -> u32 {
    match dim {
        SamplerDim::D2 => gl::TEXTURE_2D,
        SamplerDim::D3 => gl::TEXTURE_3D,
        SamplerDim::Cube => gl::TEXTURE_CUBE_MAP,
        SamplerDim::D2Array => gl::TEXTURE_2D_ARRAY,
    }
}

impl Context {
    /// The buffer range (buffer, offset, size) bound for each uniform block of program
    /// `pid`; a block without a buffer, or with too small a range → `INVALID_OPERATION`.
    pub(super) fn gather_blocks(&mut self, pid: Id, f: &str) -> Option<Vec<(Id, u64, u64)>> {
        let linked = self
            .objects
            .linked(pid)
            .expect("current programs are linked");
        // Uniform blocks read the buffer ranges bound to their binding points.
        let mut blocks = Vec::new();
        for (i, block) in linked.layout.blocks.iter().enumerate() {
            let point = linked.block_bindings[i] as usize;
            let Some(BufferRange {
                buffer,
                offset,
                size,
            }) = self.bindings.uniform_range(point)
            else {
                let msg = format!(
                    "uniform block {} has no buffer at binding point {point}",
                    block.name
                );
                return self.fail(gl::INVALID_OPERATION, f, msg);
            };
            let len = self
                .objects
                .buffers
                .get_any(buffer)
                .map_or(0, |b| b.len() as u64);
            let size = size.unwrap_or(len.saturating_sub(offset));
            if offset + size > len || size < block.size as u64 {
                let msg = format!(
                    "the buffer range of uniform block {} is too small",
                    block.name
                );
                return self.fail(gl::INVALID_OPERATION, f, msg);
            }
            blocks.push((buffer, offset, size));
        }
        Some(blocks)
    }

    /// Where each vertex input of program `pid` comes from; an array or generic value of
    /// another type than the shader's → `INVALID_OPERATION` (WebGL2).
    pub(super) fn gather_sources(
        &mut self,
        pid: Id,
        f: &str,
    ) -> Option<Vec<(ShaderInput, Source)>> {
        let linked = self
            .objects
            .linked(pid)
            .expect("current programs are linked");
        let mut sources = Vec::new();
        for input in &linked.inputs {
            let a = &self.vao().attribs[input.location as usize];
            let source = if a.enabled {
                let feed = feed_for(a);
                let ok = if a.integer {
                    feed.kind == input.kind
                } else {
                    input.kind == ValueKind::Float
                };
                if !ok {
                    let msg = format!(
                        "attribute {} is fed a type that does not match the shader's",
                        input.location
                    );
                    return self.fail(gl::INVALID_OPERATION, f, msg);
                }
                Source::Array {
                    buffer: a.buffer.expect("checked above"),
                    attrib: a.clone(),
                    feed,
                }
            } else {
                let g = self.state.generic_attribs[input.location as usize];
                let kind = match g {
                    GenericAttrib::Float(_) => ValueKind::Float,
                    GenericAttrib::Int(_) => ValueKind::Sint,
                    GenericAttrib::Uint(_) => ValueKind::Uint,
                };
                if kind != input.kind {
                    let msg = format!(
                        "generic value of attribute {} does not match the shader's type",
                        input.location
                    );
                    return self.fail(gl::INVALID_OPERATION, f, msg);
                }
                Source::Constant(g)
            };
            sources.push((*input, source));
        }
        Some(sources)
    }

    /// What each sampler slot of program `pid` reads. One unit may not serve two sampler
    /// types, and a complete texture must match its sampler's kind (`INVALID_OPERATION`).
    pub(super) fn gather_samplers(&mut self, pid: Id, f: &str) -> Option<Vec<SlotPlan>> {
        let linked = self
            .objects
            .linked(pid)
            .expect("current programs are linked");
        let mut slot_plans = Vec::new();
        let mut unit_targets: Vec<(u32, u32)> = Vec::new();
        for (s, slot) in linked.layout.samplers.iter().enumerate() {
            let Some(st) = sampler_type(slot.ty) else {
                return self.fail(
                    gl::INVALID_OPERATION,
                    f,
                    "sampler slot of a non-sampler type",
                );
            };
            let unit = linked.sampler_units[s];
            let target = dim_target(st.dim);
            if unit_targets.iter().any(|&(u, t)| u == unit && t != target) {
                return self.fail(
                    gl::INVALID_OPERATION,
                    f,
                    format_args!("texture unit {unit} used by samplers of two types"),
                );
            }
            unit_targets.push((unit, target));
            let kind = match (st.shadow || slot.comparison, st.kind) {
                (true, _) => SampleKind::Depth,
                (false, ScalarKind::Int) => SampleKind::Sint,
                (false, ScalarKind::Uint) => SampleKind::Uint,
                _ => SampleKind::Float,
            };
            let float_linear = self.extensions.texture_float_linear;
            let half_linear = !self.webgl1.on || self.webgl1.texture_half_float_linear;
            let bound = self.bindings.texture(unit, target);
            // As in Chromium, a texture whose format does not suit the sampler is an error
            // whether or not it is complete.
            let sampled = bound
                .and_then(|id| self.objects.textures.get_any(id))
                .and_then(|t| t.sampled_format());
            if let Some((format, stencil)) = sampled {
                let fits = match kind {
                    _ if stencil => kind == SampleKind::Uint,
                    SampleKind::Depth => format.has_depth(),
                    // Depth values read as floats, whatever the format stores.
                    _ if format.has_depth() => kind == SampleKind::Float,
                    k => format.kind() == k,
                };
                if !fits {
                    let msg = format!("texture on unit {unit} does not match its sampler's type");
                    return self.fail(gl::INVALID_OPERATION, f, msg);
                }
            }
            let texture = bound.and_then(|id| {
                let sampling = self.sampling_for(unit, id)?;
                self.objects
                    .textures
                    .get_any(id)
                    .and_then(|t| {
                        t.completeness(float_linear, half_linear, self.webgl1.on, &sampling)
                    })
                    .map(|c| (id, c, sampling))
            });
            if let Some((id, c, sampling)) = &texture {
                // Chromium checks shadow samplers against the compare mode at the draw: a
                // shadow sampler needs COMPARE_REF_TO_TEXTURE, another sampler of a depth
                // texture needs NONE (ES 3.0 leaves both undefined).
                let compares = sampling.compare_mode == gl::COMPARE_REF_TO_TEXTURE;
                if c.format.has_depth() && !c.stencil && compares != (kind == SampleKind::Depth) {
                    let msg = format!(
                        "the depth texture on unit {unit} has TEXTURE_COMPARE_MODE {}, its sampler is {}a shadow sampler",
                        if compares { "COMPARE_REF_TO_TEXTURE" } else { "NONE" },
                        if compares { "not " } else { "" }
                    );
                    return self.fail(gl::INVALID_OPERATION, f, msg);
                }
                if self.draws_into(*id, c.base..c.base + c.levels) {
                    let msg =
                        format!("the texture on unit {unit} is also drawn into: a feedback loop");
                    return self.fail(gl::INVALID_OPERATION, f, msg);
                }
            }
            // Integer cube samplers are 2D arrays of the six faces (`LOWER_OPTIONS`).
            let integer = matches!(kind, SampleKind::Sint | SampleKind::Uint);
            let dim = match view_dimension(target) {
                wgpu::TextureViewDimension::Cube if integer => wgpu::TextureViewDimension::D2Array,
                d => d,
            };
            slot_plans.push(SlotPlan { texture, dim, kind });
        }
        Some(slot_plans)
    }

    /// Checks that each fragment output that reaches a draw buffer has the buffer's kind:
    /// floats for normalized and float formats, signed or unsigned integers for integer
    /// formats (`INVALID_OPERATION`, WebGL2).
    pub(super) fn check_outputs(&mut self, pid: Id, formats: &DrawFormats, f: &str) -> Option<()> {
        let linked = self
            .objects
            .linked(pid)
            .expect("current programs are linked");
        for &(location, kind) in &linked.outputs {
            let Some(Some(format)) = formats.colors.get(location as usize) else {
                continue;
            };
            let wants = match format.kind() {
                SampleKind::Sint => ValueKind::Sint,
                SampleKind::Uint => ValueKind::Uint,
                _ => ValueKind::Float,
            };
            if kind != wants {
                let msg =
                    format!("fragment output {location} does not match its draw buffer's type");
                return self.fail(gl::INVALID_OPERATION, f, msg);
            }
        }
        // EXT_float_blend: blending into a 32-bit float draw buffer needs an adapter that
        // blends them (the extension is then offered, and on whether turned on or not).
        let float32 = |c: &crate::texture::InternalFormat| {
            c.comp == crate::texture::Comp::F32 && c.packing == crate::texture::Packing::None
        };
        let blended = |(i, c): (usize, &Option<crate::texture::InternalFormat>)| {
            c.as_ref().is_some_and(float32) && self.state.draw_buffer(i).blend
        };
        if !self.blends_float32() && formats.colors.iter().enumerate().any(blended) {
            let msg = "this adapter does not blend 32-bit float draw buffers (EXT_float_blend)";
            return self.fail(gl::INVALID_OPERATION, f, msg.to_string());
        }
        // WebGL 2 §5.24: a draw buffer that would be written needs an output of the shader
        // (nothing is written while the rasterizer discards, nor where the colour mask is
        // all off).
        if !self.state.rasterizer_discard {
            let written = |i: usize| self.state.draw_buffer(i).color_mask.iter().any(|&m| m);
            let missing = formats.colors.iter().enumerate().find(|(i, c)| {
                c.is_some() && written(*i) && !linked.outputs.iter().any(|&(l, _)| l as usize == *i)
            });
            if let Some((i, _)) = missing {
                let msg = format!("draw buffer {i} has no fragment output to write it");
                return self.fail(gl::INVALID_OPERATION, f, msg);
            }
        }
        Some(())
    }
}
