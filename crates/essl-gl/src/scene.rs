//! Rendering a scene of `webgl2-render.py` (an [`essl_scene::Scene`]) through essl-gl's
//! WebGL-like API, call for call as the tool's page does in Chromium.
//!
//! [`SceneRenderer::new`] does the page's set-up: a context of the scene's size, the program
//! (compile, attach, link, with the info logs), the uniforms set by their *active* type
//! (`getActiveUniform`: a 4×4 matrix goes whole to a `mat4` and its upper-left 3×3 to a `mat3`),
//! the textures on units in the sorted order of their names with `uniform1i`, one vertex array
//! with one tightly packed `FLOAT` buffer per attribute, the index buffer (`UNSIGNED_SHORT` up
//! to 65536 vertices, else `UNSIGNED_INT`) and the fixed state. Inactive and unset uniforms and
//! attributes are warnings with the tool's wording. [`SceneRenderer::frame`] is one frame
//! (`clear` + draw), [`SceneRenderer::read_image`] reads the framebuffer into PNG row order,
//! [`SceneRenderer::time_frames`] times frames as the tool's `--times N` does.
//! [`render_scene`] does all of it.
//!
//! ```no_run
//! let scene = essl_scene::Scene::load("../shared/scenes/spot-smooth.json")?;
//! let out = essl_gl::scene::render_scene(&scene, 0)?;
//! out.image.write_png(std::path::Path::new("spot-smooth.png"))?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::time::Instant;

use essl_scene::{Draw, IndexType, RgbaImage, Scene, UniformType, UploadValues};

use crate::context::Context;
use crate::error::{error_name, ContextError};
use crate::gl;
use crate::objects::Program;

/// Why a scene could not be rendered.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneRenderError {
    /// No context could be created (no Vulkan adapter, or a size the device refuses).
    #[error(transparent)]
    Context(#[from] ContextError),
    /// A shader did not compile; `log` is its info log.
    #[error("compile failed: {file}\n{log}")]
    Compile {
        /// The shader file as the scene names it.
        file: String,
        /// `getShaderInfoLog`.
        log: String,
    },
    /// The program did not link; `log` is its info log.
    #[error("link failed\n{log}")]
    Link {
        /// `getProgramInfoLog`.
        log: String,
    },
    /// A uniform's value does not fit its active type, or the uniform cannot be set from a
    /// scene (a sampler named in `uniforms`, a type the tool does not set).
    #[error("uniform {name}: {message}")]
    Uniform {
        /// The uniform's name.
        name: String,
        /// What is wrong.
        message: String,
    },
    /// The API recorded an error (a bug in essl-gl or in this module: the tool fails too).
    #[error("GL error {} while {during}: {}", error_name(*code), message.as_deref().unwrap_or(""))]
    Gl {
        /// The error code.
        code: u32,
        /// `setting up` or `drawing`.
        during: &'static str,
        /// The context's description of the error.
        message: Option<String>,
    },
    /// wgpu reported a validation error (a bug in essl-gl).
    #[error("wgpu validation error: {0}")]
    Backend(String),
}

/// What [`render_scene`] produced: the tool's output line, in Rust.
#[derive(Clone, Debug)]
pub struct SceneRender {
    /// The frame, RGBA8, top row first (PNG order; `readPixels` row `height - 1 - r` is row `r`).
    pub image: RgbaImage,
    /// The warnings, in the tool's order and wording (inactive or unset uniforms, unused
    /// textures, inactive or unfed attributes).
    pub warnings: Vec<String>,
    /// Shader file (as the scene names it) → info log, vertex shader first.
    pub compile_log: Vec<(String, String)>,
    /// The program's info log.
    pub link_log: String,
    /// Triangles drawn per frame.
    pub triangles: usize,
    /// The milliseconds of each timed frame (`clear` + draw + `readPixels` of one pixel).
    pub frame_ms: Vec<f64>,
    /// The median of `frame_ms` (the mean of the middle two for an even count), or `None` when
    /// no frame was timed: the tool's `ms_per_frame`.
    pub ms_per_frame: Option<f64>,
    /// The adapter that rendered (`"llvmpipe (LLVM …)"` for lavapipe).
    pub renderer: String,
}

/// A scene set up on a context, ready to draw frames.
pub struct SceneRenderer {
    ctx: Context,
    program: Program,
    draw: Draw,
    width: u32,
    height: u32,
    warnings: Vec<String>,
    compile_log: Vec<(String, String)>,
    link_log: String,
}

/// The active type of a uniform as the tool's `SET` table knows it, or `None` for a type it
/// cannot set (a sampler is [`UniformType::Sampler`]).
fn uniform_type(ty: u32) -> Option<UniformType> {
    use UniformType::*;
    Some(match ty {
        gl::FLOAT => Float(1),
        gl::FLOAT_VEC2 => Float(2),
        gl::FLOAT_VEC3 => Float(3),
        gl::FLOAT_VEC4 => Float(4),
        gl::INT => Int(1),
        gl::INT_VEC2 => Int(2),
        gl::INT_VEC3 => Int(3),
        gl::INT_VEC4 => Int(4),
        gl::UNSIGNED_INT => Uint(1),
        gl::UNSIGNED_INT_VEC2 => Uint(2),
        gl::UNSIGNED_INT_VEC3 => Uint(3),
        gl::UNSIGNED_INT_VEC4 => Uint(4),
        gl::BOOL => Bool(1),
        gl::BOOL_VEC2 => Bool(2),
        gl::BOOL_VEC3 => Bool(3),
        gl::BOOL_VEC4 => Bool(4),
        gl::FLOAT_MAT2 => Mat2,
        gl::FLOAT_MAT3 => Mat3,
        gl::FLOAT_MAT4 => Mat4,
        t if essl::types::GlType::from_u32(t).is_some_and(|t| t.is_sampler()) => Sampler,
        _ => return None,
    })
}

/// WebGL's name of a type enum (`FLOAT_VEC3`), as the tool's `typeName` prints it.
fn type_name(ty: u32) -> String {
    essl::types::GlType::from_u32(ty).map_or_else(|| format!("0x{ty:04X}"), |t| t.name().into())
}

/// The median as Python's `statistics.median` computes it.
fn median(values: &[f64]) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    })
}

/// A linked program and the logs of its compile and link.
struct Linked {
    program: Program,
    /// Each shader file's name and info log.
    compile_log: Vec<(String, String)>,
    link_log: String,
}

/// Compiles the scene's shaders, attaches them and links: the program and the logs, or the
/// first compile error, or the link error.
fn compile_and_link(gl: &mut Context, scene: &Scene) -> Result<Linked, SceneRenderError> {
    let program = gl.create_program();
    let mut compile_log = Vec::new();
    let mut failed = None;
    for (ty, shader) in [
        (gl::VERTEX_SHADER, &scene.vertex_shader),
        (gl::FRAGMENT_SHADER, &scene.fragment_shader),
    ] {
        let sh = gl.create_shader(ty).expect("a valid shader type");
        // Validation warnings (if the context has them on) name the scene's files.
        gl.set_shader_name(sh, &shader.name);
        gl.shader_source(sh, &shader.source);
        gl.compile_shader(sh);
        let log = gl.get_shader_info_log(sh).unwrap_or_default();
        compile_log.push((shader.name.clone(), log.clone()));
        let ok = gl.get_shader_parameter(sh, gl::COMPILE_STATUS);
        if ok.and_then(|p| p.as_bool()) != Some(true) {
            failed = Some(SceneRenderError::Compile {
                file: shader.name.clone(),
                log,
            });
        }
        gl.attach_shader(program, sh);
    }
    if let Some(e) = failed {
        return Err(e);
    }
    gl.link_program(program);
    let link_log = gl.get_program_info_log(program).unwrap_or_default();
    let linked = gl.get_program_parameter(program, gl::LINK_STATUS);
    if linked.and_then(|p| p.as_bool()) != Some(true) {
        return Err(SceneRenderError::Link { log: link_log });
    }
    Ok(Linked {
        program,
        compile_log,
        link_log,
    })
}

/// An active uniform: name (an array's without its `[0]`), type, size, and whether the scene
/// set it.
type ActiveUniform = (String, u32, u32, bool);

/// The program's active uniforms, in getActiveUniform's order.
fn active_uniforms(gl: &mut Context, program: Program) -> Vec<ActiveUniform> {
    let count = gl
        .get_program_parameter(program, gl::ACTIVE_UNIFORMS)
        .and_then(|p| p.as_int())
        .unwrap_or(0);
    (0..count as u32)
        .filter_map(|i| gl.get_active_uniform(program, i))
        .map(|info| {
            let name = info.name;
            let key = name.strip_suffix("[0]").map_or(name.clone(), str::to_owned);
            (key, info.ty, info.size, false)
        })
        .collect()
}

/// Sets a uniform's values with the `uniform*` call of its active type.
fn upload_uniform(
    gl: &mut Context,
    loc: Option<crate::UniformLocation>,
    uty: UniformType,
    values: UploadValues,
) {
    match (uty, values) {
        (UniformType::Mat2, UploadValues::F32(v)) => gl.uniform_matrix2fv(loc, false, &v),
        (UniformType::Mat3, UploadValues::F32(v)) => gl.uniform_matrix3fv(loc, false, &v),
        (UniformType::Mat4, UploadValues::F32(v)) => gl.uniform_matrix4fv(loc, false, &v),
        (UniformType::Float(n), UploadValues::F32(v)) => match n {
            1 => gl.uniform1fv(loc, &v),
            2 => gl.uniform2fv(loc, &v),
            3 => gl.uniform3fv(loc, &v),
            _ => gl.uniform4fv(loc, &v),
        },
        (UniformType::Int(n) | UniformType::Bool(n), UploadValues::I32(v)) => match n {
            1 => gl.uniform1iv(loc, &v),
            2 => gl.uniform2iv(loc, &v),
            3 => gl.uniform3iv(loc, &v),
            _ => gl.uniform4iv(loc, &v),
        },
        (UniformType::Uint(n), UploadValues::U32(v)) => match n {
            1 => gl.uniform1uiv(loc, &v),
            2 => gl.uniform2uiv(loc, &v),
            3 => gl.uniform3uiv(loc, &v),
            _ => gl.uniform4uiv(loc, &v),
        },
        (t, v) => unreachable!("essl-scene fits {t:?} with {v:?}"),
    }
}

/// The set-up's bookkeeping: which active uniforms the scene set, and the warnings.
struct Setup {
    active: Vec<ActiveUniform>,
    warnings: Vec<String>,
}

impl Setup {
    /// Sets the scene's uniforms by their active type; an inactive one is a warning.
    fn set_uniforms(
        &mut self,
        gl: &mut Context,
        program: Program,
        scene: &Scene,
    ) -> Result<(), SceneRenderError> {
        for uniform in &scene.uniforms {
            let name = &uniform.name;
            let loc = gl.get_uniform_location(program, name);
            let Some(entry) = self
                .active
                .iter_mut()
                .find(|a| &a.0 == name)
                .filter(|_| loc.is_some())
            else {
                self.warnings.push(format!(
                    "uniform {name} is not active (getUniformLocation is null): not set"
                ));
                continue;
            };
            entry.3 = true;
            let (ty, size) = (entry.1, entry.2);
            let err = |message: String| SceneRenderError::Uniform {
                name: name.clone(),
                message,
            };
            let Some(uty) = uniform_type(ty) else {
                return Err(err(format!("unsupported type {}", type_name(ty))));
            };
            if uty == UniformType::Sampler {
                return Err(err("is a sampler: give it in \"textures\"".into()));
            }
            let values = uniform
                .upload(uty, size as usize)
                .map_err(|e| err(e.to_string()))?;
            upload_uniform(gl, loc, uty, values);
        }
        Ok(())
    }

    /// Makes the scene's textures, unit = index in the sorted list of names (essl-scene's
    /// order), and points their samplers at them.
    fn bind_textures(
        &mut self,
        gl: &mut Context,
        program: Program,
        scene: &Scene,
    ) -> Result<(), SceneRenderError> {
        for t in &scene.textures {
            let tex = gl.create_texture();
            gl.active_texture(gl::TEXTURE0 + t.unit);
            gl.bind_texture(gl::TEXTURE_2D, Some(tex));
            gl.pixel_storei(gl::UNPACK_FLIP_Y_WEBGL, 0);
            gl.pixel_storei(gl::UNPACK_PREMULTIPLY_ALPHA_WEBGL, 0);
            gl.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                gl::TEXTURE_2D,
                0,
                gl::RGBA8 as i32,
                t.width as i32,
                t.height as i32,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                Some(&t.texels),
            );
            let filter = match t.filter {
                essl_scene::Filter::Nearest => gl::NEAREST,
                essl_scene::Filter::Linear => gl::LINEAR,
            } as i32;
            let wrap = match t.wrap {
                essl_scene::Wrap::Clamp => gl::CLAMP_TO_EDGE,
                essl_scene::Wrap::Repeat => gl::REPEAT,
                essl_scene::Wrap::Mirror => gl::MIRRORED_REPEAT,
            } as i32;
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, filter);
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, filter);
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_WRAP_S, wrap);
            gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_WRAP_T, wrap);
            let loc = gl.get_uniform_location(program, &t.name);
            let entry = self.active.iter_mut().find(|a| a.0 == t.name);
            let Some(entry) = entry.filter(|_| loc.is_some()) else {
                self.warnings.push(format!(
                    "sampler {} is not active: texture bound to unit {} but unused",
                    t.name, t.unit
                ));
                continue;
            };
            if entry.1 != gl::SAMPLER_2D {
                return Err(SceneRenderError::Uniform {
                    name: t.name.clone(),
                    message: format!("is {}, not SAMPLER_2D", type_name(entry.1)),
                });
            }
            entry.3 = true;
            gl.uniform1i(loc, t.unit as i32);
        }
        Ok(())
    }

    /// Warns of the active uniforms the scene did not set.
    fn warn_unset_uniforms(&mut self) {
        for (name, ty, _, used) in &self.active {
            if !used {
                self.warnings.push(format!(
                    "active uniform {name} ({}) is not set by the scene: it stays 0",
                    type_name(*ty)
                ));
            }
        }
    }

    /// One tightly packed `FLOAT` buffer per mapped attribute, in one vertex array, and the
    /// index buffer; active attributes without a stream are warnings.
    fn bind_attributes(&mut self, gl: &mut Context, program: Program, scene: &Scene) {
        let vao = gl.create_vertex_array();
        gl.bind_vertex_array(Some(vao));
        let mut mapped = Vec::new();
        for (name, stream) in scene.attributes() {
            let loc = gl.get_attrib_location(program, name);
            if loc < 0 {
                self.warnings
                    .push(format!("attribute {name} is not active: not bound"));
                continue;
            }
            mapped.push(name.to_owned());
            let data = scene.mesh.stream_f32(stream).unwrap_or_default();
            let b = gl.create_buffer();
            gl.bind_buffer(gl::ARRAY_BUFFER, Some(b));
            gl.buffer_data(gl::ARRAY_BUFFER, &data, gl::STATIC_DRAW);
            gl.enable_vertex_attrib_array(loc as u32);
            let size = stream.components() as i32;
            gl.vertex_attrib_pointer(loc as u32, size, gl::FLOAT, false, 0, 0);
        }
        let attributes = gl
            .get_program_parameter(program, gl::ACTIVE_ATTRIBUTES)
            .and_then(|p| p.as_int())
            .unwrap_or(0);
        for i in 0..attributes as u32 {
            if let Some(crate::ActiveInfo { name, .. }) = gl.get_active_attrib(program, i) {
                if !mapped.contains(&name) {
                    self.warnings.push(format!(
                        "active attribute {name} has no stream: it reads the constant (0, 0, 0, 1)"
                    ));
                }
            }
        }
        if let Some(indices) = scene.mesh.index_bytes() {
            let ib = gl.create_buffer();
            gl.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ib));
            gl.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &indices, gl::STATIC_DRAW);
        }
    }
}

/// The fixed state the tool's page sets: viewport, depth test and culling as the scene asks,
/// no blending, scissor or stencil, and the clear colour.
fn set_fixed_state(gl: &mut Context, scene: &Scene) {
    let (width, height) = (scene.width(), scene.height());
    gl.viewport(0, 0, width as i32, height as i32);
    gl.disable(gl::BLEND);
    gl.disable(gl::SCISSOR_TEST);
    gl.disable(gl::STENCIL_TEST);
    if scene.depth_test() {
        gl.enable(gl::DEPTH_TEST);
    } else {
        gl.disable(gl::DEPTH_TEST);
    }
    gl.depth_func(gl::LESS);
    gl.depth_mask(true);
    gl.clear_depth(1.0);
    if scene.cull_face() {
        gl.enable(gl::CULL_FACE);
    } else {
        gl.disable(gl::CULL_FACE);
    }
    gl.cull_face(gl::BACK);
    gl.front_face(gl::CCW);
    let c = scene.clear_color();
    gl.clear_color(c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32);
}

impl SceneRenderer {
    /// Creates a context of the scene's size and sets the scene up on it, as the tool's page
    /// does before its first frame.
    pub fn new(scene: &Scene) -> Result<SceneRenderer, SceneRenderError> {
        let ctx = Context::new(scene.width(), scene.height())?;
        SceneRenderer::with_context(ctx, scene)
    }

    /// Sets the scene up on a fresh context (of the scene's size: a context of another size
    /// draws the scene's viewport in its lower-left corner).
    pub fn with_context(
        mut ctx: Context,
        scene: &Scene,
    ) -> Result<SceneRenderer, SceneRenderError> {
        let gl = &mut ctx;
        let Linked {
            program,
            compile_log,
            link_log,
        } = compile_and_link(gl, scene)?;
        gl.use_program(Some(program));
        let mut setup = Setup {
            active: active_uniforms(gl, program),
            warnings: Vec::new(),
        };
        setup.set_uniforms(gl, program, scene)?;
        setup.bind_textures(gl, program, scene)?;
        setup.warn_unset_uniforms();
        setup.bind_attributes(gl, program, scene);
        set_fixed_state(gl, scene);

        let mut renderer = SceneRenderer {
            program,
            draw: scene.mesh.draw(),
            width: scene.width(),
            height: scene.height(),
            warnings: setup.warnings,
            compile_log,
            link_log,
            ctx,
        };
        renderer.check("setting up")?;
        Ok(renderer)
    }

    fn check(&mut self, during: &'static str) -> Result<(), SceneRenderError> {
        let code = self.ctx.get_error();
        if code != gl::NO_ERROR {
            let message = self.ctx.error_message();
            return Err(SceneRenderError::Gl {
                code,
                during,
                message,
            });
        }
        match self.ctx.backend_errors().first() {
            Some(e) => Err(SceneRenderError::Backend(e.clone())),
            None => Ok(()),
        }
    }

    /// One frame: `clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT)`, then `drawElements(TRIANGLES,
    /// count, type, 0)` or `drawArrays(TRIANGLES, 0, count)`. Recorded; the GPU runs it at the
    /// next read.
    pub fn frame(&mut self) {
        self.ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        match self.draw {
            Draw::Elements { index_type, count } => {
                let ty = match index_type {
                    IndexType::U16 => gl::UNSIGNED_SHORT,
                    IndexType::U32 => gl::UNSIGNED_INT,
                };
                self.ctx.draw_elements(gl::TRIANGLES, count as i32, ty, 0);
            }
            Draw::Arrays { count } => self.ctx.draw_arrays(gl::TRIANGLES, 0, count as i32),
        }
    }

    /// Reads the whole framebuffer (`readPixels(0, 0, width, height, RGBA, UNSIGNED_BYTE)`)
    /// as an image whose first row is the top, and checks that no GL error was recorded.
    pub fn read_image(&mut self) -> Result<RgbaImage, SceneRenderError> {
        let (w, h) = (self.width, self.height);
        let mut px = vec![0u8; w as usize * h as usize * 4];
        self.ctx.read_pixels(
            0,
            0,
            w as i32,
            h as i32,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            &mut px,
        );
        self.check("drawing")?;
        Ok(RgbaImage::from_gl_rows(w, h, &px).expect("the buffer has the framebuffer's size"))
    }

    /// Times `n` frames as the tool does: each is [`SceneRenderer::frame`] plus
    /// `readPixels(0, 0, 1, 1)`, which waits for the GPU. Returns each frame's milliseconds.
    pub fn time_frames(&mut self, n: usize) -> Vec<f64> {
        let mut one = [0u8; 4];
        (0..n)
            .map(|_| {
                let t0 = Instant::now();
                self.frame();
                self.ctx
                    .read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut one);
                t0.elapsed().as_secs_f64() * 1000.0
            })
            .collect()
    }

    /// The warnings of the set-up, in the tool's order and wording.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The program drawing the scene.
    pub fn program(&self) -> Program {
        self.program
    }

    /// The context, e.g. to query it.
    pub fn context(&mut self) -> &mut Context {
        &mut self.ctx
    }
}

/// Renders a scene as `webgl2-render.py SCENE -o OUT.png --times N` does: set-up, one frame
/// read in full, then `times` timed frames (none for 0).
pub fn render_scene(scene: &Scene, times: usize) -> Result<SceneRender, SceneRenderError> {
    let mut r = SceneRenderer::new(scene)?;
    r.frame();
    let image = r.read_image()?;
    let frame_ms = r.time_frames(times);
    r.check("drawing")?;
    Ok(SceneRender {
        image,
        triangles: scene.mesh.triangle_count(),
        ms_per_frame: median(&frame_ms),
        frame_ms,
        renderer: r.ctx.adapter_info().name.clone(),
        warnings: r.warnings,
        compile_log: r.compile_log,
        link_log: r.link_log,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_is_pythons() {
        assert_eq!(median(&[]), None);
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
    }

    #[test]
    fn uniform_types() {
        assert_eq!(uniform_type(gl::FLOAT_MAT3), Some(UniformType::Mat3));
        assert_eq!(uniform_type(gl::BOOL_VEC2), Some(UniformType::Bool(2)));
        assert_eq!(uniform_type(gl::SAMPLER_CUBE), Some(UniformType::Sampler));
        assert_eq!(uniform_type(gl::FLOAT_MAT2x3), None);
        assert_eq!(type_name(gl::FLOAT_VEC3), "FLOAT_VEC3");
    }
}
