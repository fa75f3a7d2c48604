//! Shader and program objects, linking a [`ProgramLayout`] from the front end, and the
//! program's uniform storage (`get_uniform_location`, `uniform*`).
//!
//! A linked program keeps a CPU image of its default uniform block, laid out as the layout's
//! [`UniformStorage::Buffer`] offsets say, and the texture unit of each sampler slot. Draws
//! copy the image into a per-batch buffer.

use essl::program::{ProgramLayout, UniformStorage};
use essl::types::GlType;

use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::{Id, Program, Shader, UniformLocation};
use crate::shader_patch::{output_needs_widening, wrap_entry_point};

/// The scalar kind of a shader input or output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum ValueKind {
    Float,
    Sint,
    Uint,
}

/// A vertex shader input, read from the naga module's entry point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ShaderInput {
    pub(crate) location: u32,
    pub(crate) kind: ValueKind,
    pub(crate) components: u8,
}

/// A shader object (`WebGLShader`).
pub(crate) struct ShaderObject {
    pub(crate) ty: u32,
    pub(crate) source: String,
    /// The source of the last `compile_shader` and whether it compiled. `link_program`
    /// compiles it again (the front end's `Shader` is not `Send`; a `Context` is).
    pub(crate) compiled: Option<(String, bool)>,
    pub(crate) info_log: String,
    /// The file name validation warnings give the shader ([`Context::set_shader_name`]).
    pub(crate) name: Option<String>,
}

/// A program object (`WebGLProgram`).
#[derive(Default)]
pub(crate) struct ProgramObject {
    pub(crate) attached: Vec<Id>,
    /// `bind_attrib_location` requests, applied at the next link.
    pub(crate) attrib_bindings: Vec<(String, u32)>,
    pub(crate) linked: Option<LinkedProgram>,
    pub(crate) link_status: bool,
    /// The result of the last `validate_program`.
    pub(crate) validate_status: bool,
    pub(crate) info_log: String,
}

/// The result of a successful link.
pub(crate) struct LinkedProgram {
    /// Unique per link within the context: keys pipelines and uniform locations.
    pub(crate) serial: u64,
    pub(crate) layout: ProgramLayout,
    pub(crate) vertex_module: wgpu::ShaderModule,
    pub(crate) fragment_module: wgpu::ShaderModule,
    pub(crate) inputs: Vec<ShaderInput>,
    /// Kind and width of the fragment output at location 0, if any.
    pub(crate) output0: Option<(ValueKind, u8)>,
    pub(crate) uniform_data: Vec<u8>,
    /// Bumped when `uniform_data` changes.
    pub(crate) uniform_version: u64,
    pub(crate) sampler_units: Vec<u32>,
    /// The `UNIFORM_BUFFER` binding point of each uniform block (`uniformBlockBinding`).
    pub(crate) block_bindings: Vec<u32>,
    /// Where the current uniform image was last put: (batch, version, chunk, offset).
    pub(crate) uploaded: Option<(u64, u64, u64, u32)>,
    /// The shaders' names and texts as linked (`link_program`; `None` for a layout linked
    /// directly), from which validation extracts the uniform preconditions when it is on.
    pub(crate) sources: Option<Box<crate::validation::LinkedSources>>,
    /// The runtime checks of uniform values, built at the first draw with validation on.
    pub(crate) checks: Option<Box<crate::validation::ProgramChecks>>,
}

fn value_kind(scalar: naga::Scalar) -> Option<ValueKind> {
    match scalar.kind {
        naga::ScalarKind::Float => Some(ValueKind::Float),
        naga::ScalarKind::Sint => Some(ValueKind::Sint),
        naga::ScalarKind::Uint => Some(ValueKind::Uint),
        _ => None,
    }
}

/// The kind and width of a scalar or vector type.
pub(crate) fn type_shape(
    module: &naga::Module,
    ty: naga::Handle<naga::Type>,
) -> Option<(ValueKind, u8)> {
    match module.types[ty].inner {
        naga::TypeInner::Scalar(s) => Some((value_kind(s)?, 1)),
        naga::TypeInner::Vector { size, scalar } => Some((value_kind(scalar)?, size as u8)),
        _ => None,
    }
}

/// The entry point `main` of a module (the first one if none is so named).
pub(crate) fn main_entry(module: &naga::Module) -> Option<&naga::EntryPoint> {
    module
        .entry_points
        .iter()
        .find(|e| e.name == "main")
        .or(module.entry_points.first())
}

fn shader_inputs(module: &naga::Module) -> Vec<ShaderInput> {
    let Some(ep) = main_entry(module) else {
        return Vec::new();
    };
    ep.function
        .arguments
        .iter()
        .filter_map(|arg| match arg.binding {
            Some(naga::Binding::Location { location, .. }) => {
                let (kind, components) = type_shape(module, arg.ty)?;
                Some(ShaderInput {
                    location,
                    kind,
                    components,
                })
            }
            _ => None,
        })
        .collect()
}

fn output0(module: &naga::Module) -> Option<(ValueKind, u8)> {
    let result = main_entry(module)?.function.result.as_ref()?;
    if let Some(naga::Binding::Location { location: 0, .. }) = result.binding {
        return type_shape(module, result.ty);
    }
    if let naga::TypeInner::Struct { members, .. } = &module.types[result.ty].inner {
        for m in members {
            if let Some(naga::Binding::Location { location: 0, .. }) = m.binding {
                return type_shape(module, m.ty);
            }
        }
    }
    None
}

/// Runs the essl front end on a shader's text.
fn compile(stage: essl::Stage, source: &str) -> essl::Shader {
    let file = essl::source::SourceFile::new(stage.as_str(), source);
    essl::compile(file, stage, &essl::CompileOptions::default())
}

/// WebGL's shader info log: `ERROR: 0:LINE: 'token' : message`, one line per diagnostic, in
/// source order.
fn info_log(shader: &essl::Shader) -> String {
    let mut ordered: Vec<_> = shader.diagnostics.iter().collect();
    ordered.sort_by_key(|d| d.span.start);
    let end = shader.file.text().len() as u32;
    ordered
        .into_iter()
        .map(|d| {
            let kind = if d.is_error() { "ERROR" } else { "WARNING" };
            let line = shader.file.line_of(d.span.start.min(end));
            format!("{kind}: 0:{line}: '{}' : {}\n", d.token, d.message)
        })
        .collect()
}

/// What a `uniform*` call provides.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Call {
    Float(u8),
    Int(u8),
    Uint(u8),
    Matrix(u8, u8),
}

/// The values of a `uniform*` call.
#[derive(Clone, Copy)]
enum Values<'a> {
    F(&'a [f32]),
    I(&'a [i32]),
    U(&'a [u32]),
}

impl Values<'_> {
    fn len(&self) -> usize {
        match self {
            Values::F(v) => v.len(),
            Values::I(v) => v.len(),
            Values::U(v) => v.len(),
        }
    }

    /// Value `i` as the 32-bit word stored for a uniform of kind `ty`.
    fn word(&self, i: usize, boolean: bool) -> u32 {
        match (self, boolean) {
            (Values::F(v), true) => (v[i] != 0.0) as u32,
            (Values::I(v), true) => (v[i] != 0) as u32,
            (Values::U(v), true) => (v[i] != 0) as u32,
            (Values::F(v), false) => v[i].to_bits(),
            (Values::I(v), false) => v[i] as u32,
            (Values::U(v), false) => v[i],
        }
    }
}

/// Components and matrix shape of a uniform type.
pub(crate) fn uniform_shape(ty: GlType) -> (u8, Option<(u8, u8)>, bool) {
    use GlType::*;
    match ty {
        FLOAT | INT | UNSIGNED_INT => (1, None, false),
        BOOL => (1, None, true),
        FLOAT_VEC2 | INT_VEC2 | UNSIGNED_INT_VEC2 => (2, None, false),
        BOOL_VEC2 => (2, None, true),
        FLOAT_VEC3 | INT_VEC3 | UNSIGNED_INT_VEC3 => (3, None, false),
        BOOL_VEC3 => (3, None, true),
        FLOAT_VEC4 | INT_VEC4 | UNSIGNED_INT_VEC4 => (4, None, false),
        BOOL_VEC4 => (4, None, true),
        FLOAT_MAT2 => (4, Some((2, 2)), false),
        FLOAT_MAT3 => (9, Some((3, 3)), false),
        FLOAT_MAT4 => (16, Some((4, 4)), false),
        FLOAT_MAT2x3 => (6, Some((2, 3)), false),
        FLOAT_MAT2x4 => (8, Some((2, 4)), false),
        FLOAT_MAT3x2 => (6, Some((3, 2)), false),
        FLOAT_MAT3x4 => (12, Some((3, 4)), false),
        FLOAT_MAT4x2 => (8, Some((4, 2)), false),
        FLOAT_MAT4x3 => (12, Some((4, 3)), false),
        _ => (1, None, false),
    }
}

/// Whether a `uniform*` call may set a uniform of type `ty` (WebGL's type rules).
fn call_matches(call: Call, ty: GlType) -> bool {
    use GlType::*;
    let (n, matrix, boolean) = uniform_shape(ty);
    match call {
        Call::Matrix(c, r) => matrix == Some((c, r)),
        _ if matrix.is_some() => false,
        Call::Int(1) if ty.is_sampler() => true,
        _ if ty.is_sampler() => false,
        Call::Float(k) => {
            k == n && (boolean || matches!(ty, FLOAT | FLOAT_VEC2 | FLOAT_VEC3 | FLOAT_VEC4))
        }
        Call::Int(k) => k == n && (boolean || matches!(ty, INT | INT_VEC2 | INT_VEC3 | INT_VEC4)),
        Call::Uint(k) => {
            k == n
                && (boolean
                    || matches!(
                        ty,
                        UNSIGNED_INT | UNSIGNED_INT_VEC2 | UNSIGNED_INT_VEC3 | UNSIGNED_INT_VEC4
                    ))
        }
    }
}

/// The active uniform (its index) and the array element that WebGL's `name` designates
/// (`"u_color"`, `"u_lights[2].position"`, `"u_weights[3]"`); members of uniform blocks have
/// none.
pub(crate) fn find_uniform(layout: &ProgramLayout, name: &str) -> Option<(usize, u32)> {
    for (i, u) in layout.uniforms.iter().enumerate() {
        // Members of uniform blocks have no location in WebGL.
        if u.storage == UniformStorage::Block {
            continue;
        }
        let element = if u.name == name {
            Some(0)
        } else if let Some(base) = u.name.strip_suffix("[0]") {
            if name == base {
                Some(0)
            } else {
                name.strip_prefix(base)
                    .and_then(|rest| rest.strip_prefix('['))
                    .and_then(|rest| rest.strip_suffix(']'))
                    .filter(|k| !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()))
                    .and_then(|k| k.parse::<u32>().ok())
                    .filter(|&k| k < u.size)
            }
        } else {
            None
        };
        if let Some(element) = element {
            return Some((i, element));
        }
    }
    None
}

impl Context {
    /// Creates a shader object of type `VERTEX_SHADER` or `FRAGMENT_SHADER` (`createShader`);
    /// another type → `INVALID_ENUM` and `None`.
    pub fn create_shader(&mut self, ty: u32) -> Option<Shader> {
        if !matches!(ty, gl::VERTEX_SHADER | gl::FRAGMENT_SHADER) {
            self.error(
                gl::INVALID_ENUM,
                "createShader",
                format_args!("type 0x{ty:04X}"),
            );
            return None;
        }
        let id = self.shaders.insert(ShaderObject {
            ty,
            source: String::new(),
            compiled: None,
            info_log: String::new(),
            name: None,
        });
        Some(Shader { ctx: self.id, id })
    }

    pub(crate) fn shader_id(&mut self, shader: Shader, function: &str) -> Option<Id> {
        if !self.owns(shader.ctx, function) {
            return None;
        }
        // Chromium's ValidateWebGLProgramOrShader: a shader marked for deletion but still
        // attached stays usable; one that is gone → INVALID_VALUE (not INVALID_OPERATION as
        // for other objects).
        if self.shaders.get_any(shader.id).is_none() {
            self.error(
                gl::INVALID_VALUE,
                function,
                "attempt to use a deleted shader",
            );
            return None;
        }
        Some(shader.id)
    }

    /// Sets a shader's source (`shaderSource`).
    pub fn shader_source(&mut self, shader: Shader, source: &str) {
        if let Some(id) = self.shader_id(shader, "shaderSource") {
            self.shaders.get_any_mut(id).expect("live").source = source.to_owned();
        }
    }

    /// A shader's source (`getShaderSource`).
    pub fn get_shader_source(&mut self, shader: Shader) -> Option<String> {
        let id = self.shader_id(shader, "getShaderSource")?;
        self.shaders.get_any(id).map(|s| s.source.clone())
    }

    /// Compiles a shader's source with the essl front end (`compileShader`); read the result
    /// with [`Context::get_shader_compile_status`] and [`Context::get_shader_info_log`].
    pub fn compile_shader(&mut self, shader: Shader) {
        let Some(id) = self.shader_id(shader, "compileShader") else {
            return;
        };
        let s = self.shaders.get_any_mut(id).expect("live");
        let stage = if s.ty == gl::VERTEX_SHADER {
            essl::Stage::Vertex
        } else {
            essl::Stage::Fragment
        };
        let compiled = compile(stage, &s.source);
        s.info_log = info_log(&compiled);
        s.compiled = Some((s.source.clone(), compiled.ok()));
    }

    /// Whether the last compile succeeded (`getShaderParameter(COMPILE_STATUS)`).
    pub fn get_shader_compile_status(&mut self, shader: Shader) -> bool {
        self.shader_id(shader, "getShaderParameter")
            .and_then(|id| self.shaders.get_any(id))
            .and_then(|s| s.compiled.as_ref())
            .is_some_and(|c| c.1)
    }

    /// The log of the last compile, in WebGL's `ERROR: 0:LINE: 'token' : message` form
    /// (`getShaderInfoLog`).
    pub fn get_shader_info_log(&mut self, shader: Shader) -> Option<String> {
        let id = self.shader_id(shader, "getShaderInfoLog")?;
        self.shaders.get_any(id).map(|s| s.info_log.clone())
    }

    /// A shader's type (`getShaderParameter(SHADER_TYPE)`).
    pub fn get_shader_type(&mut self, shader: Shader) -> Option<u32> {
        let id = self.shader_id(shader, "getShaderParameter")?;
        self.shaders.get_any(id).map(|s| s.ty)
    }

    /// Deletes a shader (`deleteShader`); a shader attached to a program lives on until
    /// detached.
    pub fn delete_shader(&mut self, shader: Shader) {
        if self.owns(shader.ctx, "deleteShader") {
            self.shaders.delete(shader.id);
        }
    }

    /// Creates a program object (`createProgram`).
    pub fn create_program(&mut self) -> Program {
        Program {
            ctx: self.id,
            id: self.programs.insert(ProgramObject::default()),
        }
    }

    pub(crate) fn program_id(&mut self, program: Program, function: &str) -> Option<Id> {
        if !self.owns(program.ctx, function) {
            return None;
        }
        // As for shaders: a program marked for deletion but still current stays usable; one
        // that is gone → INVALID_VALUE.
        if self.programs.get_any(program.id).is_none() {
            self.error(
                gl::INVALID_VALUE,
                function,
                "attempt to use a deleted program",
            );
            return None;
        }
        Some(program.id)
    }

    /// Whether `program` names a live program (`isProgram`).
    pub fn is_program(&self, program: Program) -> bool {
        program.ctx == self.id && self.programs.is_live(program.id)
    }

    /// Attaches a shader (`attachShader`); a second shader of the same type, or the same
    /// shader twice → `INVALID_OPERATION`.
    pub fn attach_shader(&mut self, program: Program, shader: Shader) {
        const F: &str = "attachShader";
        let (Some(p), Some(s)) = (self.program_id(program, F), self.shader_id(shader, F)) else {
            return;
        };
        let ty = self.shaders.get_any(s).expect("live").ty;
        let attached = &self.programs.get_any(p).expect("live").attached;
        let clash = attached
            .iter()
            .any(|&a| a == s || self.shaders.get_any(a).is_some_and(|o| o.ty == ty));
        if clash {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "a shader of that type is already attached",
            );
        }
        self.shaders.add_ref(s);
        self.programs.get_any_mut(p).expect("live").attached.push(s);
    }

    /// Detaches a shader (`detachShader`); one not attached → `INVALID_OPERATION`.
    pub fn detach_shader(&mut self, program: Program, shader: Shader) {
        const F: &str = "detachShader";
        let (Some(p), Some(s)) = (self.program_id(program, F), self.shader_id(shader, F)) else {
            return;
        };
        let attached = &mut self.programs.get_any_mut(p).expect("live").attached;
        let Some(i) = attached.iter().position(|&a| a == s) else {
            return self.error(gl::INVALID_OPERATION, F, "shader not attached");
        };
        attached.remove(i);
        self.shaders.release(s);
    }

    /// The shaders attached to a program (`getAttachedShaders`).
    pub fn get_attached_shaders(&mut self, program: Program) -> Vec<Shader> {
        let Some(p) = self.program_id(program, "getAttachedShaders") else {
            return Vec::new();
        };
        let ctx = self.id;
        self.programs
            .get(p)
            .expect("live")
            .attached
            .iter()
            .map(|&id| Shader { ctx, id })
            .collect()
    }

    /// Deletes a program (`deleteProgram`). The current program is only marked for deletion
    /// (`DELETE_STATUS` true): it stays usable, with its shaders attached, until another
    /// program is made current, as in GL.
    pub fn delete_program(&mut self, program: Program) {
        if !self.owns(program.ctx, "deleteProgram") || !self.programs.is_live(program.id) {
            return;
        }
        if let Some(freed) = self.programs.delete_freeing(program.id) {
            self.detach_all(freed);
        }
    }

    /// Drops the references a freed program held on its shaders.
    fn detach_all(&mut self, freed: ProgramObject) {
        for s in freed.attached {
            self.shaders.release(s);
        }
    }

    /// Whether the last link succeeded (`getProgramParameter(LINK_STATUS)`).
    pub fn get_program_link_status(&mut self, program: Program) -> bool {
        self.program_id(program, "getProgramParameter")
            .and_then(|p| self.programs.get_any(p))
            .is_some_and(|p| p.link_status)
    }

    /// The log of the last link (`getProgramInfoLog`).
    pub fn get_program_info_log(&mut self, program: Program) -> Option<String> {
        let p = self.program_id(program, "getProgramInfoLog")?;
        self.programs.get_any(p).map(|p| p.info_log.clone())
    }

    /// Binds an attribute name to a location for the next link (`bindAttribLocation`).
    /// An index ≥ `MAX_VERTEX_ATTRIBS` → `INVALID_VALUE`; a reserved `gl_`/`webgl_` name →
    /// `INVALID_OPERATION`.
    pub fn bind_attrib_location(&mut self, program: Program, index: u32, name: &str) {
        const F: &str = "bindAttribLocation";
        let Some(p) = self.program_id(program, F) else {
            return;
        };
        if index >= self.max_vertex_attribs {
            return self.error(gl::INVALID_VALUE, F, "index ≥ MAX_VERTEX_ATTRIBS");
        }
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return self.error(gl::INVALID_OPERATION, F, "reserved name");
        }
        let bindings = &mut self.programs.get_any_mut(p).expect("live").attrib_bindings;
        bindings.retain(|(n, _)| n != name);
        bindings.push((name.to_owned(), index));
    }

    /// Links the attached shaders (`linkProgram`): the essl front end links them as WebGL2
    /// does and lowers them to a [`ProgramLayout`], which
    /// [`Context::link_program_from_layout`] installs. Failures set `LINK_STATUS` false with
    /// the reason in [`Context::get_program_info_log`].
    pub fn link_program(&mut self, program: Program) {
        let Some(p) = self.program_id(program, "linkProgram") else {
            return;
        };
        let obj = self.programs.get_any(p).expect("live");
        let shader = |ty: u32| {
            obj.attached
                .iter()
                .filter_map(|&s| self.shaders.get_any(s))
                .find(|s| s.ty == ty)
        };
        let mut sources = None;
        let result = match (shader(gl::VERTEX_SHADER), shader(gl::FRAGMENT_SHADER)) {
            (None, _) | (_, None) => {
                Err("a vertex and a fragment shader must be attached".to_owned())
            }
            (Some(vs), Some(fs)) => match (&vs.compiled, &fs.compiled) {
                (Some((v, true)), Some((f, true))) => {
                    sources = Some(Box::new(crate::validation::LinkedSources {
                        vertex: (vs.name.clone(), v.clone()),
                        fragment: (fs.name.clone(), f.clone()),
                    }));
                    let v = &compile(essl::Stage::Vertex, v);
                    let f = &compile(essl::Stage::Fragment, f);
                    let linked = essl::link::link_with_bindings(v, f, &obj.attrib_bindings);
                    if linked.ok {
                        essl::lower::lower_program(
                            v,
                            f,
                            &linked,
                            &essl::program::LowerOptions::default(),
                        )
                        .map_err(|e| e.to_string())
                        .and_then(|layout| {
                            match &mut self.program_filter {
                                Some(filter) => filter(layout),
                                None => Ok(layout),
                            }
                        })
                    } else {
                        Err(linked.log)
                    }
                }
                _ => Err("an attached shader is not compiled".to_owned()),
            },
        };
        match result {
            Ok(layout) => {
                self.link_program_from_layout(program, layout);
                if let Some(linked) = self.programs.get_any_mut(p).and_then(|o| o.linked.as_mut()) {
                    linked.sources = sources;
                }
            }
            Err(log) => {
                let obj = self.programs.get_any_mut(p).expect("live");
                obj.link_status = false;
                obj.validate_status = false;
                obj.info_log = log;
            }
        }
    }

    /// Puts a step between lowering and installing every program [`Context::link_program`]
    /// links from now on (`None` removes it): the step may change the lowered modules (the
    /// translation tests write them as WGSL text and read them back) as long as they keep the
    /// conventions of [`essl::program`]; an `Err` fails the link with that message in the info
    /// log. Programs installed with [`Context::link_program_from_layout`] do not go through it.
    pub fn set_program_filter(&mut self, filter: Option<crate::context::ProgramFilter>) {
        self.program_filter = filter;
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
        let result = self.link(layout);
        let obj = self.programs.get_any_mut(p).expect("live");
        match result {
            Ok(linked) => {
                obj.linked = Some(linked);
                obj.link_status = true;
                obj.validate_status = false;
                obj.info_log.clear();
            }
            Err(log) => {
                obj.link_status = false;
                obj.validate_status = false;
                obj.info_log = log;
            }
        }
    }

    fn link(&mut self, layout: ProgramLayout) -> Result<LinkedProgram, String> {
        let limits = &self.gpu.limits;
        if layout.samplers.len() as u32
            > limits
                .max_sampled_textures_per_shader_stage
                .min(MAX_TEXTURE_UNITS)
        {
            return Err(format!(
                "{} samplers: more than the device supports",
                layout.samplers.len()
            ));
        }
        let inputs = shader_inputs(&layout.vertex);
        if let Some(i) = inputs
            .iter()
            .find(|i| i.location >= self.max_vertex_attribs)
        {
            return Err(format!(
                "attribute location {} ≥ MAX_VERTEX_ATTRIBS",
                i.location
            ));
        }
        if layout.blocks.len() as u32 + 1 > limits.max_uniform_buffers_per_shader_stage {
            return Err(format!(
                "{} uniform blocks: more than the device supports",
                layout.blocks.len()
            ));
        }
        if let Some(b) = layout
            .blocks
            .iter()
            .find(|b| b.size as u64 > limits.max_uniform_buffer_binding_size)
        {
            return Err(format!(
                "uniform block {} of {} bytes is too large",
                b.name, b.size
            ));
        }
        if let Some(block) = &layout.uniform_block {
            if block.size > limits.max_uniform_buffer_binding_size as u32 {
                return Err(format!(
                    "default uniform block of {} bytes is too large",
                    block.size
                ));
            }
        }
        let device = &self.gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let vertex_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("essl-gl vertex"),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(layout.vertex.clone())),
        });
        // An RGBA target needs a vec4 output: widen a narrower one (alpha 1).
        let fragment = if output_needs_widening(&layout.fragment) {
            wrap_entry_point(&layout.fragment, &[], true)
        } else {
            layout.fragment.clone()
        };
        let fragment_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("essl-gl fragment"),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(fragment)),
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("the lowered shaders were rejected by wgpu: {e}"));
        }
        self.link_serial += 1;
        let size = layout.uniform_block.as_ref().map_or(0, |b| b.size as usize);
        Ok(LinkedProgram {
            serial: self.link_serial,
            output0: output0(&layout.fragment),
            inputs,
            uniform_data: vec![0; size],
            uniform_version: 0,
            sampler_units: vec![0; layout.samplers.len()],
            block_bindings: vec![0; layout.blocks.len()],
            uploaded: None,
            sources: None,
            checks: None,
            vertex_module,
            fragment_module,
            layout,
        })
    }

    /// The program in use (`getParameter(CURRENT_PROGRAM)`).
    pub fn get_current_program(&self) -> Option<Program> {
        self.current_program.map(|id| Program { ctx: self.id, id })
    }

    /// Makes a linked program current (`useProgram`); `None` for none. A program whose last
    /// link failed → `INVALID_OPERATION`.
    pub fn use_program(&mut self, program: Option<Program>) {
        const F: &str = "useProgram";
        let id = match program {
            None => None,
            Some(p) => {
                if !self.owns(p.ctx, F) {
                    return;
                }
                // Unlike most program functions, useProgram refuses a program marked for
                // deletion (Chromium's ValidateNullableWebGLObject).
                if !self.programs.is_live(p.id) {
                    return self.error(gl::INVALID_OPERATION, F, "attempt to use a deleted object");
                }
                if !self.programs.get(p.id).is_some_and(|p| p.link_status) {
                    return self.error(gl::INVALID_OPERATION, F, "program is not linked");
                }
                Some(p.id)
            }
        };
        if self.current_program == id {
            return;
        }
        if let Some(n) = id {
            self.programs.add_ref(n);
        }
        if let Some(old) = std::mem::replace(&mut self.current_program, id) {
            if let Some(freed) = self.programs.release_freeing(old) {
                self.detach_all(freed);
            }
        }
    }

    /// The linked state of a program, for the low-level setters.
    fn linked_mut(&mut self, program: Program, function: &str) -> Option<&mut LinkedProgram> {
        let id = self.program_id(program, function)?;
        if self.programs.get_any(id).is_none_or(|p| p.linked.is_none()) {
            self.error(gl::INVALID_OPERATION, function, "program is not linked");
            return None;
        }
        self.programs
            .get_any_mut(id)
            .and_then(|p| p.linked.as_mut())
    }

    /// Low-level: stores 32-bit words at `byte_offset` of a program's default uniform block
    /// image. Out-of-range writes → `INVALID_VALUE`. The `uniform*` functions call this with
    /// offsets from [`UniformStorage::Buffer`].
    pub fn set_uniform_words(&mut self, program: Program, byte_offset: u32, words: &[u32]) {
        const F: &str = "setUniformWords";
        let Some(linked) = self.linked_mut(program, F) else {
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
        let Some(linked) = self.linked_mut(program, F) else {
            return;
        };
        if slot as usize >= linked.sampler_units.len() || unit >= MAX_TEXTURE_UNITS {
            return self.error(gl::INVALID_VALUE, F, "slot or unit out of range");
        }
        linked.sampler_units[slot as usize] = unit;
    }

    /// The location of an active uniform or of an element of an active uniform array
    /// (`getUniformLocation`): `"u_color"`, `"u_lights[2].position"`, `"u_weights[3]"`.
    /// `None` for a name that is not active; an unlinked program → `INVALID_OPERATION`.
    pub fn get_uniform_location(
        &mut self,
        program: Program,
        name: &str,
    ) -> Option<UniformLocation> {
        const F: &str = "getUniformLocation";
        let id = self.program_id(program, F)?;
        let Some(linked) = self.programs.get_any(id).and_then(|p| p.linked.as_ref()) else {
            self.error(gl::INVALID_OPERATION, F, "program is not linked");
            return None;
        };
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return None;
        }
        let (i, element) = find_uniform(&linked.layout, name)?;
        Some(UniformLocation {
            ctx: self.id,
            program: id,
            link: linked.serial,
            uniform: i as u32,
            element,
        })
    }

    /// The index of a uniform block by name, or `INVALID_INDEX` (`getUniformBlockIndex`).
    pub fn get_uniform_block_index(&mut self, program: Program, name: &str) -> u32 {
        const F: &str = "getUniformBlockIndex";
        let Some(id) = self.program_id(program, F) else {
            return gl::INVALID_INDEX;
        };
        let Some(linked) = self.programs.get_any(id).and_then(|p| p.linked.as_ref()) else {
            self.error(gl::INVALID_OPERATION, F, "program is not linked");
            return gl::INVALID_INDEX;
        };
        linked
            .layout
            .blocks
            .iter()
            .position(|b| b.name == name)
            .map_or(gl::INVALID_INDEX, |i| i as u32)
    }

    /// Makes uniform block `block_index` read `UNIFORM_BUFFER` binding point `binding`
    /// (`uniformBlockBinding`). An index or binding out of range → `INVALID_VALUE`.
    pub fn uniform_block_binding(&mut self, program: Program, block_index: u32, binding: u32) {
        const F: &str = "uniformBlockBinding";
        let Some(id) = self.program_id(program, F) else {
            return;
        };
        let Some(linked) = self
            .programs
            .get_any_mut(id)
            .and_then(|p| p.linked.as_mut())
        else {
            return self.error(gl::INVALID_OPERATION, F, "program is not linked");
        };
        match linked.block_bindings.get_mut(block_index as usize) {
            Some(b) if binding < crate::context::MAX_UNIFORM_BUFFER_BINDINGS => *b = binding,
            _ => self.error(gl::INVALID_VALUE, F, "block index or binding out of range"),
        }
    }

    /// The index-th active attribute's name, type and size (`getActiveAttrib`).
    pub fn get_active_attrib(
        &mut self,
        program: Program,
        index: u32,
    ) -> Option<(String, u32, u32)> {
        let id = self.program_id(program, "getActiveAttrib")?;
        let linked = self.programs.get_any(id)?.linked.as_ref()?;
        match linked.layout.attributes.get(index as usize) {
            Some(a) => Some((a.name.clone(), a.ty as u32, a.size)),
            None => {
                self.error(gl::INVALID_VALUE, "getActiveAttrib", "index out of range");
                None
            }
        }
    }

    /// The index-th active uniform's name, type and size (`getActiveUniform`).
    pub fn get_active_uniform(
        &mut self,
        program: Program,
        index: u32,
    ) -> Option<(String, u32, u32)> {
        let id = self.program_id(program, "getActiveUniform")?;
        let linked = self.programs.get_any(id)?.linked.as_ref()?;
        match linked.layout.uniforms.get(index as usize) {
            Some(u) => Some((u.name.clone(), u.ty as u32, u.size)),
            None => {
                self.error(gl::INVALID_VALUE, "getActiveUniform", "index out of range");
                None
            }
        }
    }

    /// The location of an active attribute, or −1 (`getAttribLocation`). Built-in inputs
    /// (`gl_VertexID`, `gl_InstanceID`), which `get_active_attrib` lists, and every reserved
    /// `gl_`/`webgl_` name have none: −1, as in WebGL.
    pub fn get_attrib_location(&mut self, program: Program, name: &str) -> i32 {
        const F: &str = "getAttribLocation";
        let Some(id) = self.program_id(program, F) else {
            return -1;
        };
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return -1;
        }
        let Some(linked) = self.programs.get_any(id).and_then(|p| p.linked.as_ref()) else {
            self.error(gl::INVALID_OPERATION, F, "program is not linked");
            return -1;
        };
        linked
            .layout
            .attributes
            .iter()
            .find(|a| a.name == name)
            .map_or(-1, |a| a.location as i32)
    }

    /// Stores the values of a `uniform*` call, with WebGL's checks.
    fn uniform_impl(
        &mut self,
        location: Option<UniformLocation>,
        call: Call,
        values: Values<'_>,
        array_call: bool,
        transpose: bool,
        function: &str,
    ) {
        let Some(loc) = location else { return };
        if !self.owns(loc.ctx, function) {
            return;
        }
        let Some(current) = self.current_program else {
            return self.error(gl::INVALID_OPERATION, function, "no current program");
        };
        let linked = match self
            .programs
            .get_any(current)
            .and_then(|p| p.linked.as_ref())
        {
            Some(l) if loc.program == current && l.serial == loc.link => l,
            _ => {
                return self.error(
                    gl::INVALID_OPERATION,
                    function,
                    "location is not from the current program",
                );
            }
        };
        let u = &linked.layout.uniforms[loc.uniform as usize];
        if !call_matches(call, u.ty) {
            let msg = format!("function does not match the uniform's type {}", u.ty);
            return self.error(gl::INVALID_OPERATION, function, msg);
        }
        let per = match call {
            Call::Float(n) | Call::Int(n) | Call::Uint(n) => n as usize,
            Call::Matrix(c, r) => c as usize * r as usize,
        };
        let len = values.len();
        if len == 0 || len % per != 0 {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "value count is not a multiple of the type's size",
            );
        }
        let count = len / per;
        if count > 1 && u.size == 1 && array_call {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "several values for a non-array uniform",
            );
        }
        let (_, matrix, boolean) = uniform_shape(u.ty);
        let last = (loc.element as usize + count).min(u.size as usize);
        let storage = u.storage.clone();
        let is_sampler = u.ty.is_sampler();
        if is_sampler {
            let Values::I(v) = values else {
                unreachable!("checked by call_matches")
            };
            if v.iter()
                .take(last - loc.element as usize)
                .any(|&unit| unit < 0 || unit as u32 >= MAX_TEXTURE_UNITS)
            {
                return self.error(gl::INVALID_VALUE, function, "texture unit out of range");
            }
        }
        let linked = self
            .programs
            .get_any_mut(current)
            .and_then(|p| p.linked.as_mut())
            .expect("checked");
        match storage {
            UniformStorage::Block => {}
            UniformStorage::Sampler { first_slot } => {
                let Values::I(v) = values else { return };
                for (k, e) in (loc.element as usize..last).enumerate() {
                    linked.sampler_units[first_slot as usize + e] = v[k] as u32;
                }
            }
            UniformStorage::Buffer {
                offset,
                array_stride,
                matrix_stride,
            } => {
                for (k, e) in (loc.element as usize..last).enumerate() {
                    let base = offset as usize + e * array_stride as usize;
                    let mut put = |at: usize, word: u32| {
                        if let Some(dst) = linked.uniform_data.get_mut(at..at + 4) {
                            dst.copy_from_slice(&word.to_ne_bytes());
                        }
                    };
                    match matrix {
                        Some((cols, rows)) => {
                            let (cols, rows) = (cols as usize, rows as usize);
                            for c in 0..cols {
                                for r in 0..rows {
                                    let src = if transpose {
                                        r * cols + c
                                    } else {
                                        c * rows + r
                                    };
                                    put(
                                        base + c * matrix_stride as usize + r * 4,
                                        values.word(k * per + src, false),
                                    );
                                }
                            }
                        }
                        None => {
                            for i in 0..per {
                                put(base + i * 4, values.word(k * per + i, boolean));
                            }
                        }
                    }
                }
                linked.uniform_version += 1;
            }
        }
    }
}

macro_rules! uniform_scalars {
    ($($(#[$doc:meta])* $name:ident($($arg:ident),+): $t:ty => $variant:ident, $call:ident, $n:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                pub fn $name(&mut self, location: Option<UniformLocation>, $($arg: $t),+) {
                    self.uniform_impl(location, Call::$call($n), Values::$variant(&[$($arg),+]), false, false, stringify!($name));
                }
            )*
        }
    };
}

uniform_scalars! {
    /// Sets a `float` (or `bool`) uniform (`uniform1f`).
    uniform1f(x): f32 => F, Float, 1;
    /// Sets a `vec2` (or `bvec2`) uniform (`uniform2f`).
    uniform2f(x, y): f32 => F, Float, 2;
    /// Sets a `vec3` (or `bvec3`) uniform (`uniform3f`).
    uniform3f(x, y, z): f32 => F, Float, 3;
    /// Sets a `vec4` (or `bvec4`) uniform (`uniform4f`).
    uniform4f(x, y, z, w): f32 => F, Float, 4;
    /// Sets an `int`, `bool` or sampler uniform (`uniform1i`); for a sampler, the texture unit.
    uniform1i(x): i32 => I, Int, 1;
    /// Sets an `ivec2` (or `bvec2`) uniform (`uniform2i`).
    uniform2i(x, y): i32 => I, Int, 2;
    /// Sets an `ivec3` (or `bvec3`) uniform (`uniform3i`).
    uniform3i(x, y, z): i32 => I, Int, 3;
    /// Sets an `ivec4` (or `bvec4`) uniform (`uniform4i`).
    uniform4i(x, y, z, w): i32 => I, Int, 4;
    /// Sets a `uint` (or `bool`) uniform (`uniform1ui`).
    uniform1ui(x): u32 => U, Uint, 1;
    /// Sets a `uvec2` (or `bvec2`) uniform (`uniform2ui`).
    uniform2ui(x, y): u32 => U, Uint, 2;
    /// Sets a `uvec3` (or `bvec3`) uniform (`uniform3ui`).
    uniform3ui(x, y, z): u32 => U, Uint, 3;
    /// Sets a `uvec4` (or `bvec4`) uniform (`uniform4ui`).
    uniform4ui(x, y, z, w): u32 => U, Uint, 4;
}

macro_rules! uniform_vectors {
    ($($(#[$doc:meta])* $name:ident: $t:ty => $variant:ident, $call:ident, $n:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                pub fn $name(&mut self, location: Option<UniformLocation>, values: &[$t]) {
                    self.uniform_impl(location, Call::$call($n), Values::$variant(values), true, false, stringify!($name));
                }
            )*
        }
    };
}

uniform_vectors! {
    /// Sets `float` uniforms from the location on (`uniform1fv`).
    uniform1fv: f32 => F, Float, 1;
    /// Sets `vec2` uniforms from the location on (`uniform2fv`).
    uniform2fv: f32 => F, Float, 2;
    /// Sets `vec3` uniforms from the location on (`uniform3fv`).
    uniform3fv: f32 => F, Float, 3;
    /// Sets `vec4` uniforms from the location on (`uniform4fv`).
    uniform4fv: f32 => F, Float, 4;
    /// Sets `int`, `bool` or sampler uniforms from the location on (`uniform1iv`).
    uniform1iv: i32 => I, Int, 1;
    /// Sets `ivec2` uniforms from the location on (`uniform2iv`).
    uniform2iv: i32 => I, Int, 2;
    /// Sets `ivec3` uniforms from the location on (`uniform3iv`).
    uniform3iv: i32 => I, Int, 3;
    /// Sets `ivec4` uniforms from the location on (`uniform4iv`).
    uniform4iv: i32 => I, Int, 4;
    /// Sets `uint` uniforms from the location on (`uniform1uiv`).
    uniform1uiv: u32 => U, Uint, 1;
    /// Sets `uvec2` uniforms from the location on (`uniform2uiv`).
    uniform2uiv: u32 => U, Uint, 2;
    /// Sets `uvec3` uniforms from the location on (`uniform3uiv`).
    uniform3uiv: u32 => U, Uint, 3;
    /// Sets `uvec4` uniforms from the location on (`uniform4uiv`).
    uniform4uiv: u32 => U, Uint, 4;
}

macro_rules! uniform_matrices {
    ($($(#[$doc:meta])* $name:ident: $c:literal x $r:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                ///
                /// Values are column by column unless `transpose`.
                pub fn $name(&mut self, location: Option<UniformLocation>, transpose: bool, values: &[f32]) {
                    self.uniform_impl(location, Call::Matrix($c, $r), Values::F(values), true, transpose, stringify!($name));
                }
            )*
        }
    };
}

uniform_matrices! {
    /// Sets `mat2` uniforms (`uniformMatrix2fv`).
    uniform_matrix2fv: 2 x 2;
    /// Sets `mat3` uniforms (`uniformMatrix3fv`).
    uniform_matrix3fv: 3 x 3;
    /// Sets `mat4` uniforms (`uniformMatrix4fv`).
    uniform_matrix4fv: 4 x 4;
    /// Sets `mat2x3` uniforms (`uniformMatrix2x3fv`).
    uniform_matrix2x3fv: 2 x 3;
    /// Sets `mat2x4` uniforms (`uniformMatrix2x4fv`).
    uniform_matrix2x4fv: 2 x 4;
    /// Sets `mat3x2` uniforms (`uniformMatrix3x2fv`).
    uniform_matrix3x2fv: 3 x 2;
    /// Sets `mat3x4` uniforms (`uniformMatrix3x4fv`).
    uniform_matrix3x4fv: 3 x 4;
    /// Sets `mat4x2` uniforms (`uniformMatrix4x2fv`).
    uniform_matrix4x2fv: 4 x 2;
    /// Sets `mat4x3` uniforms (`uniformMatrix4x3fv`).
    uniform_matrix4x3fv: 4 x 3;
}
