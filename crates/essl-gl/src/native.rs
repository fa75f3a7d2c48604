//! essl-gl's own methods, outside WebGL's API: what a Rust program that is not porting WebGL
//! calls — programs from a layout the front end produced, uniform values by byte offset,
//! a step between lowering and installing, the shading language's target, and a plain RGBA8
//! read. The WebGL methods are in the modules named for what they do; these are kept here so
//! that the WebGL surface reads like the specification.

use essl::program::ProgramLayout;

use crate::array::ArrayType;
use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::Program;
use crate::program::ProgramFilter;
use crate::readback::ReadRequest;

impl Context {
    /// Puts a step between lowering and installing every program [`Context::link_program`]
    /// links from now on (`None` removes it): the step may change the lowered modules (the
    /// translation tests write them as WGSL text and read them back) as long as they keep the
    /// conventions of [`essl::program`]; an `Err` fails the link with that message in the info
    /// log. Programs installed with [`Context::link_program_from_layout`] do not go through it.
    pub fn set_program_filter(&mut self, filter: Option<ProgramFilter>) {
        self.linker.filter = filter;
    }

    /// Creates a program and links it from a layout the front end produced: see
    /// [`Context::link_program_from_layout`].
    pub fn program_from_layout(&mut self, layout: ProgramLayout) -> Program {
        let program = self.create_program();
        self.link_program_from_layout(program, layout);
        program
    }

    /// Completes `linkProgram`: installs a program linked and lowered by the front end.
    ///
    /// The layout must follow the conventions of [`essl::program`]. essl-gl creates the wgpu
    /// shader modules (wgpu validates them); a module wgpu rejects, or a program needing more
    /// than the device offers, makes the link fail (`LINK_STATUS` false, the reason in the
    /// info log). Uniforms start at zero and samplers at unit 0; earlier uniform locations
    /// become invalid.
    pub fn link_program_from_layout(&mut self, program: Program, layout: ProgramLayout) {
        let Some(p) = self.program_id(program, "linkProgram") else {
            return;
        };
        let feedback = self
            .objects
            .programs
            .get_any(p)
            .map(|o| o.feedback_varyings.clone())
            .unwrap_or_default();
        let result = self.link(layout, &feedback);
        let obj = self.objects.programs.get_any_mut(p).expect("live");
        match result {
            Ok(linked) => {
                obj.linked = Some(linked);
                obj.link_status = true;
                obj.validate_status = false;
                obj.info_log.clear();
            }
            Err(e) => {
                obj.link_status = false;
                obj.validate_status = false;
                obj.info_log = e.to_string();
            }
        }
    }

    /// Low-level: stores 32-bit words at `byte_offset` of a program's default uniform block
    /// image. Out-of-range writes → `INVALID_VALUE`. The `uniform*` functions call this with
    /// offsets from [`UniformStorage::Buffer`].
    pub fn set_uniform_words(&mut self, program: Program, byte_offset: u32, words: &[u32]) {
        const F: &str = "setUniformWords";
        let Some(linked) = self.linked_program_mut(program, F) else {
            return;
        };
        let start = byte_offset as usize;
        let end = start + words.len() * 4;
        if byte_offset % 4 != 0 || end > linked.uniform_data.len() {
            return self.error(gl::INVALID_VALUE, F, "outside the uniform block");
        }
        linked.uniform_data[start..end].copy_from_slice(bytemuck::cast_slice(words));
        linked.uniform_version += 1;
    }

    /// Low-level: stores floats at `byte_offset` of a program's uniform block image.
    pub fn set_uniform_f32s(&mut self, program: Program, byte_offset: u32, values: &[f32]) {
        self.set_uniform_words(program, byte_offset, bytemuck::cast_slice(values));
    }

    /// Low-level: stores signed integers at `byte_offset` of a program's uniform block image.
    pub fn set_uniform_i32s(&mut self, program: Program, byte_offset: u32, values: &[i32]) {
        self.set_uniform_words(program, byte_offset, bytemuck::cast_slice(values));
    }

    /// Low-level: stores unsigned integers at `byte_offset` of a program's uniform block image.
    pub fn set_uniform_u32s(&mut self, program: Program, byte_offset: u32, values: &[u32]) {
        self.set_uniform_words(program, byte_offset, values);
    }

    /// Low-level: sets the texture unit sampler slot `slot` reads (what `uniform1i` on a
    /// sampler does). A slot or unit out of range → `INVALID_VALUE`.
    pub fn set_sampler_unit(&mut self, program: Program, slot: u32, unit: u32) {
        const F: &str = "setSamplerUnit";
        let Some(linked) = self.linked_program_mut(program, F) else {
            return;
        };
        if slot as usize >= linked.sampler_units.len() || unit >= MAX_TEXTURE_UNITS {
            return self.error(gl::INVALID_VALUE, F, "slot or unit out of range");
        }
        linked.sampler_units[slot as usize] = unit;
    }

    /// Reads a rectangle that lies inside the framebuffer as tightly packed RGBA8 rows,
    /// bottom row first (GL's order). A convenience over [`Context::read_pixels`] for
    /// normalized colour buffers.
    pub fn read_pixels_rgba8(&mut self, x: u32, y: u32, width: u32, height: u32) -> Vec<u8> {
        let mut out = vec![0u8; width as usize * height as usize * 4];
        let before = self.pixel_store.pack_alignment;
        let (rl, sr, sp) = (
            self.pixel_store.pack_row_length,
            self.pixel_store.pack_skip_rows,
            self.pixel_store.pack_skip_pixels,
        );
        let p = &mut self.pixel_store;
        (
            p.pack_alignment,
            p.pack_row_length,
            p.pack_skip_rows,
            p.pack_skip_pixels,
        ) = (1, 0, 0, 0);
        let request = ReadRequest {
            x: x as i32,
            y: y as i32,
            width: width as i32,
            height: height as i32,
            format: gl::RGBA,
            ty: gl::UNSIGNED_BYTE,
            array: Some(ArrayType::Uint8),
        };
        if self.bindings.buffer(gl::PIXEL_PACK_BUFFER).is_none() {
            self.read_into(&request, &mut out, "readPixels");
        }
        let p = &mut self.pixel_store;
        (
            p.pack_alignment,
            p.pack_row_length,
            p.pack_skip_rows,
            p.pack_skip_pixels,
        ) = (before, rl, sr, sp);
        out
    }

    /// The WebGL version whose shading languages `compile_shader` and `link_program` accept:
    /// [`essl::Target::WebGl2`] unless [`Context::set_shader_target`] changed it.
    pub fn shader_target(&self) -> essl::Target {
        self.linker.shaders.target
    }

    /// Compiles and links shaders as a WebGL 1 or a WebGL 2 context does from now on. A
    /// WebGL 1 context compiles GLSL ES 1.00 only (`#version 300 es` is refused), and a
    /// shader may enable with `#extension` (and sees the macro of) only the `extensions` the
    /// application turned on with `getExtension` (`OES_standard_derivatives`, …); a WebGL 2
    /// context compiles both languages and takes only WebGL 2's extensions from `extensions`
    /// (`WEBGL_clip_cull_distance`). Only the shading language
    /// changes: the rest of the API stays WebGL2's. Shaders compiled before keep their status
    /// until compiled again.
    pub fn set_shader_target(&mut self, target: essl::Target, extensions: &[essl::Extension]) {
        self.linker.shaders = essl::CompileOptions {
            target,
            extensions: extensions.to_vec(),
            ..essl::CompileOptions::default()
        };
    }
}
