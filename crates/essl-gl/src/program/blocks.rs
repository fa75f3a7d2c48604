//! Program introspection beyond names and locations: `get_uniform_indices`,
//! `get_active_uniforms`, `get_active_uniform_block_name`,
//! `get_active_uniform_block_parameter`, `get_frag_data_location` and `get_uniform`.

use essl::program::UniformStorage;
use essl::types::GlType;

use super::interface::uniform_shape;
use crate::context::Context;
use crate::gl;
use crate::objects::{Program, UniformLocation};
use crate::query::Parameter;

impl Context {
    /// The index of each named uniform among the active ones, `INVALID_INDEX` for a name that
    /// is not (`getUniformIndices`). An array is named with or without its `[0]`.
    pub fn get_uniform_indices(&self, program: Program, names: &[&str]) -> Option<Vec<u32>> {
        let id = self.program_id(program, "getUniformIndices")?;
        let Some(linked) = self.objects.linked(id) else {
            return Some(vec![gl::INVALID_INDEX; names.len()]);
        };
        let uniforms = &linked.layout.uniforms;
        Some(
            names
                .iter()
                .map(|n| {
                    uniforms
                        .iter()
                        .position(|u| {
                            u.name == *n || u.name.strip_suffix("[0]").is_some_and(|b| b == *n)
                        })
                        .map_or(gl::INVALID_INDEX, |i| i as u32)
                })
                .collect(),
        )
    }

    /// A property of several active uniforms (`getActiveUniforms`): `UNIFORM_TYPE`,
    /// `UNIFORM_SIZE` ([`Parameter::Uints`]); `UNIFORM_BLOCK_INDEX`, `UNIFORM_OFFSET`,
    /// `UNIFORM_ARRAY_STRIDE`, `UNIFORM_MATRIX_STRIDE` ([`Parameter::Ints`], −1 outside
    /// blocks); `UNIFORM_IS_ROW_MAJOR` ([`Parameter::Bools`]). An index out of range →
    /// `INVALID_VALUE`; another `pname` → `INVALID_ENUM`.
    pub fn get_active_uniforms(
        &self,
        program: Program,
        indices: &[u32],
        pname: u32,
    ) -> Option<Parameter> {
        const F: &str = "getActiveUniforms";
        let id = self.program_id(program, F)?;
        let uniforms = self
            .objects
            .linked(id)
            .map(|l| l.layout.uniforms.clone())
            .unwrap_or_default();
        if indices.iter().any(|&i| i as usize >= uniforms.len()) {
            self.error(gl::INVALID_VALUE, F, "index out of range");
            return None;
        }
        let picked = indices.iter().map(|&i| &uniforms[i as usize]);
        let block = |s: &UniformStorage| match *s {
            UniformStorage::Block {
                block,
                offset,
                array_stride,
                matrix_stride,
                row_major,
            } => Some((
                block as i32,
                offset as i32,
                array_stride as i32,
                matrix_stride as i32,
                row_major,
            )),
            _ => None,
        };
        Some(match pname {
            gl::UNIFORM_TYPE => Parameter::Uints(picked.map(|u| u.ty as u32).collect()),
            gl::UNIFORM_SIZE => Parameter::Uints(picked.map(|u| u.size).collect()),
            gl::UNIFORM_BLOCK_INDEX => Parameter::Ints(
                picked
                    .map(|u| block(&u.storage).map_or(-1, |b| b.0))
                    .collect(),
            ),
            gl::UNIFORM_OFFSET => Parameter::Ints(
                picked
                    .map(|u| block(&u.storage).map_or(-1, |b| b.1))
                    .collect(),
            ),
            gl::UNIFORM_ARRAY_STRIDE => Parameter::Ints(
                picked
                    .map(|u| {
                        block(&u.storage).map_or(-1, |b| {
                            if u.size > 1 || u.name.ends_with("[0]") {
                                b.2
                            } else {
                                0
                            }
                        })
                    })
                    .collect(),
            ),
            gl::UNIFORM_MATRIX_STRIDE => Parameter::Ints(
                picked
                    .map(|u| block(&u.storage).map_or(-1, |b| b.3))
                    .collect(),
            ),
            gl::UNIFORM_IS_ROW_MAJOR => Parameter::Bools(
                picked
                    .map(|u| block(&u.storage).is_some_and(|b| b.4))
                    .collect(),
            ),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                return None;
            }
        })
    }

    /// The name of uniform block `index` (`getActiveUniformBlockName`); an index out of
    /// range → `INVALID_VALUE`.
    pub fn get_active_uniform_block_name(&self, program: Program, index: u32) -> Option<String> {
        const F: &str = "getActiveUniformBlockName";
        let id = self.program_id(program, F)?;
        let name = self
            .objects
            .linked(id)
            .and_then(|l| l.layout.blocks.get(index as usize))
            .map(|b| b.name.clone());
        if name.is_none() {
            self.error(gl::INVALID_VALUE, F, "index out of range");
        }
        name
    }

    /// A property of uniform block `index` (`getActiveUniformBlockParameter`):
    /// `UNIFORM_BLOCK_BINDING`, `UNIFORM_BLOCK_DATA_SIZE`, `UNIFORM_BLOCK_ACTIVE_UNIFORMS`
    /// ([`Parameter::Int`]), `UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES` ([`Parameter::Uints`]),
    /// `UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER`, `…_FRAGMENT_SHADER`
    /// ([`Parameter::Bool`]).
    pub fn get_active_uniform_block_parameter(
        &self,
        program: Program,
        index: u32,
        pname: u32,
    ) -> Option<Parameter> {
        const F: &str = "getActiveUniformBlockParameter";
        let id = self.program_id(program, F)?;
        let Some(linked) = self.objects.linked(id) else {
            self.error(gl::INVALID_VALUE, F, "index out of range");
            return None;
        };
        let Some(b) = linked.layout.blocks.get(index as usize) else {
            self.error(gl::INVALID_VALUE, F, "index out of range");
            return None;
        };
        let members: Vec<u32> = linked
            .layout
            .uniforms
            .iter()
            .enumerate()
            .filter(
                |(_, u)| matches!(u.storage, UniformStorage::Block { block, .. } if block == index),
            )
            .map(|(i, _)| i as u32)
            .collect();
        let value = match pname {
            gl::UNIFORM_BLOCK_BINDING => {
                Parameter::Int(linked.block_bindings[index as usize] as i64)
            }
            gl::UNIFORM_BLOCK_DATA_SIZE => Parameter::Int(b.size as i64),
            gl::UNIFORM_BLOCK_ACTIVE_UNIFORMS => Parameter::Int(members.len() as i64),
            gl::UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES => Parameter::Uints(members),
            gl::UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER => Parameter::Bool(b.vertex),
            gl::UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER => Parameter::Bool(b.fragment),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                return None;
            }
        };
        Some(value)
    }

    /// The location of a fragment output, or −1 (`getFragDataLocation`): `"color"`,
    /// `"colors[2]"`. A program that is not linked → `INVALID_OPERATION`.
    pub fn get_frag_data_location(&self, program: Program, name: &str) -> i32 {
        if !self.valid_name(name, true, "getFragDataLocation") {
            return -1;
        }
        let Some(linked) = self.linked_program(program, "getFragDataLocation") else {
            return -1;
        };
        for (n, first, size) in &linked.layout.fragment_output_names {
            if n == name {
                return *first as i32;
            }
            let element = name
                .strip_prefix(n.as_str())
                .and_then(|r| r.strip_prefix('['))
                .and_then(|r| r.strip_suffix(']'))
                .and_then(|k| k.parse::<u32>().ok());
            if let Some(k) = element.filter(|k| k < size) {
                return (*first + k) as i32;
            }
        }
        -1
    }

    /// The value of a uniform (`getUniform`), as WebGL returns it: a number or boolean for
    /// scalars, a typed array for vectors and matrices (column by column), the texture unit
    /// for samplers. A location of another program, or of an earlier link →
    /// `INVALID_OPERATION`.
    pub fn get_uniform(&self, program: Program, location: UniformLocation) -> Option<Parameter> {
        const F: &str = "getUniform";
        let id = self.program_id(program, F)?;
        if location.ctx != self.id || location.program != id {
            self.error(
                gl::INVALID_OPERATION,
                F,
                "the location belongs to another program",
            );
            return None;
        }
        let Some(linked) = self.objects.linked(id) else {
            self.error(gl::INVALID_OPERATION, F, "program is not linked");
            return None;
        };
        if linked.serial != location.link {
            self.error(
                gl::INVALID_OPERATION,
                F,
                "the location is from an earlier link",
            );
            return None;
        }
        let u = linked.layout.uniforms.get(location.uniform as usize)?;
        let e = location.element;
        match u.storage {
            UniformStorage::Sampler { first_slot } => {
                let unit = linked
                    .sampler_units
                    .get((first_slot + e) as usize)
                    .copied()?;
                Some(Parameter::Int(unit as i64))
            }
            UniformStorage::Buffer {
                offset,
                array_stride,
                matrix_stride,
            } => {
                let at = (offset + e * array_stride) as usize;
                Some(read_value(
                    &linked.uniform_data,
                    at,
                    matrix_stride as usize,
                    u.ty,
                ))
            }
            UniformStorage::Block { .. } => None,
        }
    }
}

/// A uniform's value of type `ty` stored at byte `at` of a default block image.
fn read_value(data: &[u8], at: usize, matrix_stride: usize, ty: GlType) -> Parameter {
    use essl::types::{ScalarKind, Type};
    let word = |i: usize| {
        data.get(at + 4 * i..at + 4 * i + 4)
            .map_or(0, |b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
    };
    let (n, matrix, boolean) = uniform_shape(ty);
    if let Some((cols, rows)) = matrix {
        let stride = matrix_stride / 4;
        let v = (0..cols as usize)
            .flat_map(|c| (0..rows as usize).map(move |r| c * stride + r))
            .map(|i| f32::from_bits(word(i)))
            .collect();
        return Parameter::Floats(v);
    }
    let kind = match ty.to_type() {
        Type::Scalar(k) | Type::Vector(k, _) => k,
        _ => ScalarKind::Float,
    };
    let n = n as usize;
    match (boolean, kind, n) {
        (true, _, 1) => Parameter::Bool(word(0) != 0),
        (true, _, _) => Parameter::Bools((0..n).map(|i| word(i) != 0).collect()),
        (_, ScalarKind::Float, 1) => Parameter::Float(f32::from_bits(word(0))),
        (_, ScalarKind::Float, _) => {
            Parameter::Floats((0..n).map(|i| f32::from_bits(word(i))).collect())
        }
        (_, ScalarKind::Int, 1) => Parameter::Int(word(0) as i32 as i64),
        (_, ScalarKind::Int, _) => Parameter::Ints((0..n).map(|i| word(i) as i32).collect()),
        (_, _, 1) => Parameter::Int(word(0) as i64),
        _ => Parameter::Uints((0..n).map(word).collect()),
    }
}
