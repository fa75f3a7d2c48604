//! The binding map: where the host side puts what WebGL's API set by name.
//!
//! A WebGL app uploads `gl.uniform3fv(gl.getUniformLocation(p, "u_spots[0].position"), …)`;
//! after translation that value is 12 bytes at some offset of a uniform buffer at some group
//! and binding. The map says, for every active uniform under its WebGL name, its group,
//! binding, byte offset and strides (std140) or, for a sampler, the texture and sampler
//! bindings of each element; for every attribute its location; for every uniform block its
//! binding and size; and what the translation itself needs the host to write (the framebuffer
//! height of the `gl_FragCoord.y` flip). It serialises to JSON (`essl translate --bindings
//! json`) and reads back with serde.

use essl::program::{InternalUniform, ProgramLayout, UniformStorage};
use essl::types::GlType;
use essl::Shader;
use serde::{Deserialize, Serialize};

use crate::Options;

/// Everything the host needs to feed a translated program or shader.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct BindingMap {
    /// The target language (`wgsl`, `spirv`, …).
    pub target: String,
    /// Whether clip-space z is remapped to 0..w in the vertex shader.
    pub depth_remap: bool,
    /// Whether `gl_FragCoord.y` is flipped (then [`BindingMap::internal`] holds the height).
    pub flip_y: bool,
    /// The buffer of loose uniforms, if the shaders have any.
    pub uniform_buffer: Option<Buffer>,
    /// Active uniforms under WebGL's names, in WebGL's order (`getActiveUniform`).
    pub uniforms: Vec<Uniform>,
    /// The shader's own uniform blocks.
    pub blocks: Vec<Buffer>,
    /// Values of the uniform buffer that the host writes for the translation's sake.
    pub internal: Vec<Internal>,
    /// Vertex attributes (a program's, or a lone vertex shader's inputs).
    pub attributes: Vec<Attribute>,
    /// Fragment outputs: location and WebGL type.
    pub outputs: Vec<Output>,
}

/// A uniform buffer.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Buffer {
    /// The block's name (`_essl_DefaultUniforms` for the loose uniforms).
    pub name: String,
    /// Bind group.
    pub group: u32,
    /// Binding in the group.
    pub binding: u32,
    /// Size in bytes (std140, a multiple of 16).
    pub size: u32,
}

/// One active uniform.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Uniform {
    /// WebGL's name (`u_spots[0].position`, `u_weights[0]`).
    pub name: String,
    /// WebGL's type (`FLOAT_VEC3`, `SAMPLER_2D`).
    #[serde(rename = "type")]
    pub ty: String,
    /// Array length (1 when not an array).
    pub size: u32,
    /// Where its value goes.
    #[serde(flatten)]
    pub place: Place,
}

/// Where a uniform's value goes.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "storage", rename_all = "snake_case")]
pub enum Place {
    /// Bytes of a uniform buffer (std140: `bool` as a 4-byte 0 or 1, matrices by column).
    Buffer {
        /// Bind group of the buffer.
        group: u32,
        /// Binding of the buffer.
        binding: u32,
        /// Byte offset of element 0.
        offset: u32,
        /// Bytes from one array element to the next (16-aligned).
        array_stride: u32,
        /// Bytes from one matrix column to the next (16); 0 for a non-matrix.
        matrix_stride: u32,
    },
    /// A sampler: element `i` is the texture at `textures[i]` and the sampler at
    /// `samplers[i]`, both in `group`.
    Sampler {
        /// Bind group of the textures and samplers.
        group: u32,
        /// Texture binding of each element.
        textures: Vec<u32>,
        /// Sampler binding of each element.
        samplers: Vec<u32>,
        /// Whether the sampler compares depth (a comparison sampler).
        comparison: bool,
    },
    /// A member of one of the shader's uniform blocks: the buffer bound to the block holds it.
    Block {
        /// The block's name.
        block: String,
    },
}

impl Place {
    /// `count` sampler elements from slot `first`: each slot's texture at group 1, binding
    /// `2 * slot`, its sampler at `2 * slot + 1` (the conventions of [`essl::program`]).
    fn sampler(first: u32, count: u32, comparison: bool) -> Place {
        let slots = first..first + count;
        Place::Sampler {
            group: 1,
            textures: slots.clone().map(|s| 2 * s).collect(),
            samplers: slots.map(|s| 2 * s + 1).collect(),
            comparison,
        }
    }
}

/// A value the host writes into the uniform buffer for the translation itself.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Internal {
    /// What it is: `framebuffer_height` (an `f32`, the render target's height in pixels) or
    /// `draw_id` (an `i32`, `gl_DrawID`: the index of the draw within a multi-draw call).
    pub value: String,
    /// Byte offset in the loose uniforms' buffer.
    pub offset: u32,
}

/// A vertex attribute.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Attribute {
    /// Its name.
    pub name: String,
    /// WebGL's type (`FLOAT_VEC3`, `FLOAT_MAT4`).
    #[serde(rename = "type")]
    pub ty: String,
    /// Its first location (a `matN` takes N).
    pub location: u32,
}

/// A fragment output.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Output {
    /// Its location (the colour attachment).
    pub location: u32,
    /// WebGL's type.
    #[serde(rename = "type")]
    pub ty: String,
}

impl BindingMap {
    /// The map of a linked, lowered program.
    pub fn from_program(layout: &ProgramLayout, options: &Options) -> BindingMap {
        let uniforms = layout
            .uniforms
            .iter()
            .map(|u| Uniform {
                name: u.name.clone(),
                ty: u.ty.name().to_owned(),
                size: u.size,
                place: match &u.storage {
                    UniformStorage::Buffer {
                        offset,
                        array_stride,
                        matrix_stride,
                    } => Place::Buffer {
                        group: 0,
                        binding: 0,
                        offset: *offset,
                        array_stride: *array_stride,
                        matrix_stride: *matrix_stride,
                    },
                    UniformStorage::Sampler { first_slot } => Place::sampler(
                        *first_slot,
                        u.size,
                        layout
                            .samplers
                            .get(*first_slot as usize)
                            .is_some_and(|s| s.comparison),
                    ),
                    UniformStorage::Block { block, .. } => Place::Block {
                        block: layout
                            .blocks
                            .get(*block as usize)
                            .map(|b| b.name.clone())
                            .unwrap_or_default(),
                    },
                },
            })
            .collect();
        BindingMap {
            target: options.target.name().to_owned(),
            depth_remap: options.depth_remap,
            flip_y: options.flip_y,
            uniform_buffer: layout.uniform_block.as_ref().map(|b| Buffer {
                name: "_essl_DefaultUniforms".into(),
                group: 0,
                binding: 0,
                size: b.size,
            }),
            uniforms,
            blocks: layout
                .blocks
                .iter()
                .enumerate()
                .map(|(i, b)| Buffer {
                    name: b.name.clone(),
                    group: 0,
                    binding: 1 + i as u32,
                    size: b.size,
                })
                .collect(),
            internal: layout
                .uniform_block
                .iter()
                .flat_map(|b| &b.internal)
                .map(|(k, offset)| Internal {
                    value: k.name().into(),
                    offset: *offset,
                })
                .collect(),
            attributes: layout
                .attributes
                .iter()
                .map(|a| Attribute {
                    name: a.name.clone(),
                    ty: a.ty.name().into(),
                    location: a.location,
                })
                .collect(),
            outputs: layout
                .fragment_outputs
                .iter()
                .map(|(location, ty)| Output {
                    location: *location,
                    ty: ty.name().into(),
                })
                .collect(),
        }
    }

    /// The map of a shader lowered on its own ([`essl::lower::lower_shader`]): its loose
    /// uniforms in the buffer at group 0, binding 0 at the offsets of the lowered struct, its
    /// samplers in declaration order, its inputs (a vertex shader's attributes) and outputs at
    /// the locations the lowering gave them.
    pub fn from_shader(shader: &Shader, module: &naga::Module, options: &Options) -> BindingMap {
        let m = &shader.module;
        let reflection = essl::reflect::reflect(m);
        let default = default_block(module);
        let mut uniforms = Vec::new();
        let mut slot = 0u32;
        for (leaf, used) in &reflection.uniforms {
            let essl::reflect::UniformSource::Default { global, path } = &leaf.source else {
                continue;
            };
            let g = &m.globals[*global];
            if !used {
                continue;
            }
            let place = if leaf.ty.is_sampler() {
                let first = slot;
                slot += leaf.size;
                Place::sampler(first, leaf.size, leaf.ty.name().ends_with("_SHADOW"))
            } else {
                let Some(base) = default
                    .as_ref()
                    .and_then(|(_, members)| members.iter().find(|(n, _)| **n == *g.name))
                    .map(|(_, o)| *o)
                else {
                    continue;
                };
                let (offset, array_stride, matrix_stride) =
                    essl::lower::layout::leaf_layout(&g.ty, path, &m.structs);
                Place::Buffer {
                    group: 0,
                    binding: 0,
                    offset: base + offset,
                    array_stride,
                    matrix_stride,
                }
            };
            uniforms.push(Uniform {
                name: leaf.name.clone(),
                ty: leaf.ty.name().into(),
                size: leaf.size,
                place,
            });
        }
        let locations = |binding: &naga::Binding| match binding {
            naga::Binding::Location { location, .. } => Some(*location),
            _ => None,
        };
        let entry = module.entry_points.first();
        let interface = |name: &str, inputs: bool| -> Option<u32> {
            let f = &entry?.function;
            if inputs {
                f.arguments
                    .iter()
                    .find(|a| a.name.as_deref() == Some(name))
                    .and_then(|a| a.binding.as_ref())
                    .and_then(locations)
            } else {
                let r = f.result.as_ref()?;
                match &module.types[r.ty].inner {
                    naga::TypeInner::Struct { members, .. } => members
                        .iter()
                        .find(|m| m.name.as_deref() == Some(name))
                        .and_then(|m| m.binding.as_ref())
                        .and_then(locations),
                    _ => r.binding.as_ref().and_then(locations),
                }
            }
        };
        let gl = |ty: &Option<GlType>| ty.map_or("", |t| t.name()).to_owned();
        let attributes = if shader.stage == essl::Stage::Vertex {
            reflection
                .inputs
                .iter()
                .filter_map(|i| {
                    Some(Attribute {
                        name: i.name.clone(),
                        ty: gl(&i.ty),
                        location: interface(&i.name, true)?,
                    })
                })
                .collect()
        } else {
            Vec::new()
        };
        let outputs = if shader.stage == essl::Stage::Fragment {
            reflection
                .outputs
                .iter()
                .filter_map(|o| {
                    Some(Output {
                        location: interface(&o.name, false)?,
                        ty: gl(&o.ty),
                    })
                })
                .collect()
        } else {
            Vec::new()
        };
        let internal = default
            .iter()
            .flat_map(|(_, members)| members)
            .filter_map(|(n, offset)| {
                let what = InternalUniform::ALL
                    .into_iter()
                    .find(|u| u.member_name() == *n)?;
                Some(Internal {
                    value: what.name().into(),
                    offset: *offset,
                })
            })
            .collect();
        BindingMap {
            target: options.target.name().to_owned(),
            depth_remap: options.depth_remap,
            flip_y: options.flip_y,
            uniform_buffer: default.as_ref().map(|(size, _)| Buffer {
                name: "_essl_DefaultUniforms".into(),
                group: 0,
                binding: 0,
                size: *size,
            }),
            uniforms,
            blocks: module
                .global_variables
                .iter()
                .filter_map(|(_, g)| {
                    let b = g.binding.as_ref()?;
                    (g.space == naga::AddressSpace::Uniform && b.group == 0 && b.binding > 0).then(
                        || Buffer {
                            name: module.types[g.ty].name.clone().unwrap_or_default(),
                            group: 0,
                            binding: b.binding,
                            size: module.types[g.ty].inner.size(module.to_ctx()),
                        },
                    )
                })
                .collect(),
            internal,
            attributes,
            outputs,
        }
    }

    /// The map as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a binding map always serialises")
    }

    /// The uniform of this WebGL name (`u_color`, `u_weights[0]`, also `u_weights`).
    pub fn uniform(&self, name: &str) -> Option<&Uniform> {
        self.uniforms
            .iter()
            .find(|u| u.name == name || u.name.strip_suffix("[0]").is_some_and(|n| n == name))
    }
}

/// The loose uniforms' struct of a lowered module: its size and each member's name and offset.
fn default_block(module: &naga::Module) -> Option<(u32, Vec<(&str, u32)>)> {
    let g = module.global_variables.iter().find(|(_, g)| {
        g.space == naga::AddressSpace::Uniform
            && g.binding
                == Some(naga::ResourceBinding {
                    group: 0,
                    binding: 0,
                })
    })?;
    match &module.types[g.1.ty].inner {
        naga::TypeInner::Struct { members, span } => Some((
            span.div_ceil(16) * 16,
            members
                .iter()
                .map(|m| (m.name.as_deref().unwrap_or(""), m.offset))
                .collect(),
        )),
        _ => None,
    }
}
