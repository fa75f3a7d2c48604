//! essl-translate: WebGL shaders (GLSL ES 3.00 and 1.00) to WGSL, SPIR-V, MSL, HLSL and
//! desktop GLSL, for people moving a WebGL app to WebGPU, wgpu or a native API.
//!
//! essl already lowers every shader WebGL2 accepts to validated naga IR that follows the
//! conventions of [`essl::program`]; naga's backends do the writing. What this crate adds is
//! what makes the output worth keeping:
//! - **names**: naga's namers append `_` to every name that ends in a digit and a counter to
//!   a name used twice in one module (`u_light0` becomes `u_light0_`, a second local `i`
//!   becomes `i_1`). [`names`] gives the GLSL names back wherever the target does not reserve
//!   them and nothing in scope would clash.
//! - **comments** ([`comments`]) where the lowering added something the GLSL did not say: the
//!   uniform buffer that holds the loose uniforms, each `sampler2D` split into a texture and a
//!   sampler, the clip-depth remap, the `gl_FragCoord.y` flip.
//! - **std140 offsets** ([`layout`]): `@size` where WGSL's own layout of a uniform struct
//!   would differ from the std140 layout essl lowered (naga's writer drops IR offsets).
//! - **points** ([`points`]): WGSL has no `gl_PointSize` or `gl_PointCoord`; WebGPU's points
//!   are one pixel, and the WGSL says so.
//! - **a binding map** ([`bindings`]): for each WebGL uniform name its group, binding, byte
//!   offset and type; for each attribute its location; for each sampler its texture and sampler
//!   bindings — what the host side needs to upload the same data.
//!
//! Programs (`NAME.vert` + `NAME.frag`) are linked first, so that varyings get matching
//! locations and both stages share one uniform buffer; a lone shader is lowered on its own.
//! [`roundtrip`] feeds the WGSL text back through naga's WGSL front end, which is how the tests
//! run the dEQP value cases and the shared scenes on the *text* rather than on essl's IR.

#![warn(missing_docs)]

pub mod bindings;
pub mod comments;
mod ir;
pub mod layout;
pub mod names;
pub mod points;
pub mod roundtrip;
pub mod source;
mod wgsl;
mod wgsl_text;
mod write;

use essl::program::LowerOptions;
use essl::{Shader, Stage};
use thiserror::Error;

pub use bindings::BindingMap;

/// A language to translate to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Target {
    /// WGSL, for WebGPU and wgpu.
    Wgsl,
    /// SPIR-V 1.0 for Vulkan (clip-space y flipped by the writer, as wgpu's Vulkan backend does).
    SpirV,
    /// Metal Shading Language 2.1 (for `invariant`).
    Msl,
    /// HLSL, shader model 5.1.
    Hlsl,
    /// Desktop GLSL 4.50 core, with OpenGL's own conventions (no depth remap, no y flip).
    Glsl,
}

impl Target {
    /// Every target, in the order the CLI lists them.
    pub const ALL: [Target; 5] = [
        Target::Wgsl,
        Target::SpirV,
        Target::Msl,
        Target::Hlsl,
        Target::Glsl,
    ];

    /// The name the CLI takes (`wgsl`, `spirv`, `msl`, `hlsl`, `glsl`).
    pub fn name(self) -> &'static str {
        match self {
            Target::Wgsl => "wgsl",
            Target::SpirV => "spirv",
            Target::Msl => "msl",
            Target::Hlsl => "hlsl",
            Target::Glsl => "glsl",
        }
    }

    /// The target a CLI name stands for.
    pub fn from_name(name: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == name)
    }

    /// The file extension of its output (`wgsl`, `spv`, `metal`, `hlsl`, `glsl`).
    pub fn extension(self) -> &'static str {
        match self {
            Target::Wgsl => "wgsl",
            Target::SpirV => "spv",
            Target::Msl => "metal",
            Target::Hlsl => "hlsl",
            Target::Glsl => "glsl",
        }
    }

    /// Whether the target API's clip space and framebuffer differ from OpenGL's: z from 0 to
    /// w, framebuffer y pointing down. Then the WebGL-compatibility parts are on by default.
    pub fn needs_webgl_compat(self) -> bool {
        self != Target::Glsl
    }
}

/// How to translate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// The language to write.
    pub target: Target,
    /// Remap clip-space z from WebGL's −w..w to 0..w in the vertex shader, so that depth
    /// tests behave as in WebGL on an API whose clip z starts at 0.
    pub depth_remap: bool,
    /// Make `gl_FragCoord.y` (and `dFdy`) count from the bottom of the framebuffer as in WebGL,
    /// reading the framebuffer height from the uniform buffer.
    pub flip_y: bool,
    /// Write comments where the lowering added something.
    pub comments: bool,
    /// Give the GLSL names back where the target's namer changed them.
    pub restore_names: bool,
    /// How WGSL functions read the loose uniforms.
    pub uniforms: Uniforms,
}

/// How the WGSL reads the shader's loose uniforms, which live in one uniform buffer (a
/// `var<uniform>` of one struct: WGSL has no loose uniforms).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Uniforms {
    /// Through the buffer: `uniforms.u_color`.
    #[default]
    Buffer,
    /// By their GLSL names: each function that reads `u_color` starts with
    /// `let u_color = uniforms.u_color;` (a uniform read with a dynamic index, or whose name
    /// a local takes, stays `uniforms.NAME`).
    ModuleScope,
}

impl Options {
    /// The defaults for a target: WebGL's conventions kept on an API that differs from
    /// OpenGL's ([`Target::needs_webgl_compat`]), comments and GLSL names on.
    pub fn new(target: Target) -> Options {
        Options {
            target,
            depth_remap: target.needs_webgl_compat(),
            flip_y: target.needs_webgl_compat(),
            comments: true,
            restore_names: true,
            uniforms: Uniforms::Buffer,
        }
    }

    fn lower_options(&self) -> LowerOptions {
        LowerOptions {
            zero_to_one_depth: self.depth_remap,
            flip_frag_coord_y: self.flip_y,
            flip_clip_y: false,
            transform_feedback: Vec::new(),
            integer_cube_as_array: false,
            clip_distance_switches: false,
            clip_control: false,
            clamp_lod_bias: false,
        }
    }
}

impl Default for Options {
    /// WGSL with WebGL's conventions kept.
    fn default() -> Self {
        Options::new(Target::Wgsl)
    }
}

/// The code of one stage.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Code {
    /// Source text (WGSL, MSL, HLSL, GLSL).
    Text(String),
    /// A SPIR-V binary, in words.
    SpirV(Vec<u32>),
}

impl Code {
    /// The bytes to write to a file (SPIR-V words in little-endian order).
    pub fn to_bytes(&self) -> Vec<u8> {
        match self {
            Code::Text(t) => t.clone().into_bytes(),
            Code::SpirV(words) => words.iter().flat_map(|w| w.to_le_bytes()).collect(),
        }
    }

    /// The text, for a text target.
    pub fn as_text(&self) -> Option<&str> {
        match self {
            Code::Text(t) => Some(t),
            Code::SpirV(_) => None,
        }
    }
}

/// A translated program: both stages and the binding map.
#[derive(Clone, Debug)]
pub struct Translation {
    /// The vertex shader.
    pub vertex: Code,
    /// The fragment shader.
    pub fragment: Code,
    /// Where the host puts each uniform, sampler and attribute.
    pub bindings: BindingMap,
}

/// A program translated to one module.
#[derive(Clone, Debug)]
pub struct ProgramModule {
    /// Both stages: the vertex entry point `vs_main`, the fragment entry point `fs_main`.
    pub code: Code,
    /// Where the host puts each uniform, sampler and attribute ([`translate_program`]'s map).
    pub bindings: BindingMap,
}

/// A translated lone shader.
#[derive(Clone, Debug)]
pub struct ShaderTranslation {
    /// The shader's stage.
    pub stage: Stage,
    /// Its code.
    pub code: Code,
    /// Where the host puts each uniform and sampler, and each input's location.
    pub bindings: BindingMap,
}

/// Why a shader or program could not be translated.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum TranslateError {
    /// The shader has errors: WebGL would not compile it, so there is nothing to translate.
    #[error("the {stage} shader has {errors} error(s): fix them first (`essl lint` shows them)")]
    NotCompiled {
        /// `vertex` or `fragment`.
        stage: &'static str,
        /// How many errors.
        errors: usize,
    },
    /// The program does not link (WebGL's link log).
    #[error("the program does not link: {log}")]
    Link {
        /// The link log.
        log: String,
    },
    /// essl could not lower the shader to naga IR.
    #[error(transparent)]
    Lower(#[from] essl::lower::LowerError),
    /// A naga backend refused the module.
    #[error("naga's {target} writer refused the {stage} shader: {message}")]
    Write {
        /// The target's name.
        target: &'static str,
        /// `vertex` or `fragment`.
        stage: &'static str,
        /// naga's message.
        message: String,
    },
    /// One module for both stages was asked of a target other than WGSL.
    #[error("one module for both stages is written for WGSL only, not {target}")]
    SingleModule {
        /// The target's name.
        target: &'static str,
    },
    /// The WGSL text did not parse or validate again in naga's WGSL front end (a bug).
    #[error("the {stage} shader's WGSL does not read back: {message}")]
    Reparse {
        /// `vertex` or `fragment`.
        stage: &'static str,
        /// naga's message.
        message: String,
    },
}

/// Translates a program: links `vs` and `fs` as WebGL2 does, lowers both stages with the
/// options' conventions and writes each in the target language.
pub fn translate_program(
    vs: &Shader,
    fs: &Shader,
    options: &Options,
) -> Result<Translation, TranslateError> {
    let layout = lower_program(vs, fs, options)?;
    let bindings = BindingMap::from_program(&layout, options);
    let vertex = write::stage(
        &layout.vertex,
        &layout.vertex_info,
        Stage::Vertex,
        language(vs),
        options,
        &[vs],
    )?;
    let fragment = write::stage(
        &layout.fragment,
        &layout.fragment_info,
        Stage::Fragment,
        language(fs),
        options,
        &[fs],
    )?;
    Ok(Translation {
        vertex,
        fragment,
        bindings,
    })
}

/// Translates a program to one WGSL module, as WebGPU code usually keeps a pipeline's
/// shaders: the vertex entry point `vs_main` and the fragment entry point `fs_main` share the
/// structs and bindings, declared once (the loose uniforms as one struct of both stages'
/// members). The binding map is [`translate_program`]'s.
pub fn translate_program_module(
    vs: &Shader,
    fs: &Shader,
    options: &Options,
) -> Result<ProgramModule, TranslateError> {
    if options.target != Target::Wgsl {
        return Err(TranslateError::SingleModule {
            target: options.target.name(),
        });
    }
    let layout = lower_program(vs, fs, options)?;
    let bindings = BindingMap::from_program(&layout, options);
    let code = write::program_module(&layout, [vs, fs], language(vs), options)?;
    Ok(ProgramModule { code, bindings })
}

/// Translates one shader on its own: inputs and outputs get locations in declaration order,
/// its uniforms a buffer of their own (as [`essl::lower::lower_shader`] lowers it).
pub fn translate_shader(
    shader: &Shader,
    options: &Options,
) -> Result<ShaderTranslation, TranslateError> {
    compiled(shader)?;
    let (module, info) = essl::lower::lower_shader(shader, &options.lower_options())?;
    let bindings = BindingMap::from_shader(shader, &module, options);
    let code = write::stage(
        &module,
        &info,
        shader.stage,
        language(shader),
        options,
        &[shader],
    )?;
    Ok(ShaderTranslation {
        stage: shader.stage,
        code,
        bindings,
    })
}

/// The language a shader was written in, as the translation's header names it.
fn language(shader: &Shader) -> &'static str {
    match shader.version {
        essl::Version::Es100 => "GLSL ES 1.00",
        _ => "GLSL ES 3.00",
    }
}

/// Links and lowers a program with the options' conventions.
pub fn lower_program(
    vs: &Shader,
    fs: &Shader,
    options: &Options,
) -> Result<essl::program::ProgramLayout, TranslateError> {
    compiled(vs)?;
    compiled(fs)?;
    let linked = essl::link::link(vs, fs);
    if !linked.ok {
        return Err(TranslateError::Link { log: linked.log });
    }
    Ok(essl::lower::lower_program(
        vs,
        fs,
        &linked,
        &options.lower_options(),
    )?)
}

fn compiled(shader: &Shader) -> Result<(), TranslateError> {
    match shader.error_count() {
        0 => Ok(()),
        errors => Err(TranslateError::NotCompiled {
            stage: shader.stage.as_str(),
            errors,
        }),
    }
}
