//! Shader objects: `create_shader`, `shader_source`, `compile_shader` (the essl front end)
//! and WebGL's info log.

use super::ShaderObject;
use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Shader};

/// Runs the essl front end on a shader's text, with the context's WebGL version and
/// extensions.
pub(super) fn compile(
    options: &essl::CompileOptions,
    stage: essl::Stage,
    source: &str,
) -> essl::Shader {
    let file = essl::source::SourceFile::new(stage.as_str(), source);
    essl::compile(file, stage, options)
}

/// The stage of a shader object of type `ty` (`VERTEX_SHADER` or `FRAGMENT_SHADER`).
fn stage_of(ty: u32) -> essl::Stage {
    if ty == gl::VERTEX_SHADER {
        essl::Stage::Vertex
    } else {
        essl::Stage::Fragment
    }
}

/// WebGL's shader info log: `ERROR: 0:LINE: 'token' : message`, one line per diagnostic, in
/// source order.
pub(super) fn info_log(shader: &essl::Shader) -> String {
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
        let id = self.objects.shaders.insert(ShaderObject {
            ty,
            source: String::new(),
            compiled: None,
            info_log: String::new(),
            name: None,
        });
        Some(Shader { ctx: self.id, id })
    }

    pub(crate) fn shader_id(&self, shader: Shader, function: &str) -> Option<Id> {
        if !self.owns(shader.ctx, function) {
            return None;
        }
        // Chromium's ValidateWebGLProgramOrShader: a shader marked for deletion but still
        // attached stays usable; one that is gone → INVALID_VALUE (not INVALID_OPERATION as
        // for other objects).
        if self.objects.shaders.get_any(shader.id).is_none() {
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
            self.objects.shaders.get_any_mut(id).expect("live").source = source.to_owned();
        }
    }

    /// A shader's source (`getShaderSource`).
    pub fn get_shader_source(&self, shader: Shader) -> Option<String> {
        let id = self.shader_id(shader, "getShaderSource")?;
        self.objects.shaders.get_any(id).map(|s| s.source.clone())
    }

    /// Compiles a shader's source with the essl front end (`compileShader`); read the result
    /// with [`Context::get_shader_compile_status`] and [`Context::get_shader_info_log`].
    pub fn compile_shader(&mut self, shader: Shader) {
        let Some(id) = self.shader_id(shader, "compileShader") else {
            return;
        };
        let options = &self.linker.shaders;
        let s = self.objects.shaders.get_any_mut(id).expect("live");
        let compiled = compile(options, stage_of(s.ty), &s.source);
        s.info_log = info_log(&compiled);
        s.compiled = Some((s.source.clone(), compiled.ok()));
    }

    /// `WEBGL_debug_shaders`' `getTranslatedShaderSource`: the shader as the last successful
    /// compile lowered it, written as WGSL (the text wgpu is handed is naga IR; WGSL is its
    /// readable form). Empty before a compile and after a failed one; setting a new source
    /// changes nothing until it is compiled. Worked out when asked: compiles keep no copy.
    pub fn get_translated_shader_source(&self, shader: Shader) -> Option<String> {
        let id = self.shader_id(shader, "getTranslatedShaderSource")?;
        let s = self.objects.shaders.get_any(id)?;
        let Some((source, true)) = &s.compiled else {
            return Some(String::new());
        };
        let compiled = compile(&self.linker.shaders, stage_of(s.ty), source);
        let text = compiled.naga.as_ref().and_then(|lowered| {
            let info = lowered.info()?;
            naga::back::wgsl::write_string(
                &lowered.module,
                info,
                naga::back::wgsl::WriterFlags::empty(),
            )
            .ok()
        });
        Some(text.unwrap_or_default())
    }

    /// Whether the last compile succeeded (`getShaderParameter(COMPILE_STATUS)`).
    pub fn get_shader_compile_status(&self, shader: Shader) -> bool {
        self.shader_id(shader, "getShaderParameter")
            .and_then(|id| self.objects.shaders.get_any(id))
            .and_then(|s| s.compiled.as_ref())
            .is_some_and(|c| c.1)
    }

    /// The log of the last compile, in WebGL's `ERROR: 0:LINE: 'token' : message` form
    /// (`getShaderInfoLog`).
    pub fn get_shader_info_log(&self, shader: Shader) -> Option<String> {
        let id = self.shader_id(shader, "getShaderInfoLog")?;
        self.objects.shaders.get_any(id).map(|s| s.info_log.clone())
    }

    /// A shader's type (`getShaderParameter(SHADER_TYPE)`).
    pub fn get_shader_type(&self, shader: Shader) -> Option<u32> {
        let id = self.shader_id(shader, "getShaderParameter")?;
        self.objects.shaders.get_any(id).map(|s| s.ty)
    }

    /// Whether `shader` names a live shader (`isShader`).
    pub fn is_shader(&self, shader: Shader) -> bool {
        // A shader deleted while attached lives on until detached, and is one till then.
        shader.ctx == self.id && self.objects.shaders.get_any(shader.id).is_some()
    }

    /// Deletes a shader (`deleteShader`); a shader attached to a program lives on until
    /// detached.
    pub fn delete_shader(&mut self, shader: Shader) {
        if self.owns(shader.ctx, "deleteShader") {
            self.objects.delete_shader(shader.id);
        }
    }
}
