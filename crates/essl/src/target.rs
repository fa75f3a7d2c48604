//! What a shader is compiled for: the WebGL version of the context, which decides the GLSL ES
//! versions it takes, the extensions it offers and the limits of the WebGL specification; and
//! the numbers of the implementation essl answers for.
//!
//! A WebGL 1 context compiles GLSL ES 1.00 only; a WebGL 2 context compiles GLSL ES 3.00
//! (`#version 300 es`) and GLSL ES 1.00. The WebGL 1 extensions a shader names with
//! `#extension` (`GL_OES_standard_derivatives`, …) exist only in a WebGL 1 context that has
//! enabled them (`getExtension`); WebGL 2 made them core in GLSL ES 3.00 and offers none of them
//! to GLSL ES 1.00 shaders.
//!
//! The limits come in two sets ([`Profile`]): what the reference implementation reports
//! (Chromium 156, ANGLE on SwiftShader, `getParameter`, recorded in
//! `tests/oracle/limits-webgl1.json` and `limits-webgl2.json`), past which a shader is an error
//! as it is there; and what the WebGL specification guarantees on every device, past which a
//! shader that compiles here is a warning (it may fail on a smaller GPU).

/// The WebGL version of the context a shader is compiled for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Target {
    /// A WebGL 1 context: GLSL ES 1.00 only, and the WebGL 1 extensions it enabled.
    WebGl1,
    /// A WebGL 2 context: GLSL ES 3.00 and GLSL ES 1.00.
    #[default]
    WebGl2,
}

impl Target {
    /// `"webgl1"` or `"webgl2"` (the CLI's and JSON output's spelling).
    pub fn as_str(self) -> &'static str {
        match self {
            Target::WebGl1 => "webgl1",
            Target::WebGl2 => "webgl2",
        }
    }

    /// `"WebGL 1"` or `"WebGL 2"`, for messages.
    pub fn display(self) -> &'static str {
        match self {
            Target::WebGl1 => "WebGL 1",
            Target::WebGl2 => "WebGL 2",
        }
    }

    /// The target spelt `webgl1` or `webgl2`.
    pub fn from_name(name: &str) -> Option<Target> {
        match name {
            "webgl1" => Some(Target::WebGl1),
            "webgl2" => Some(Target::WebGl2),
            _ => None,
        }
    }

    /// The longest token (identifier, macro name) the specification allows: 256 characters in
    /// WebGL 1 (WebGL 1.0 §6.? "Maximum GLSL Token Size"), 1024 in WebGL 2 for both language
    /// versions (WebGL 2.0 "Maximum GLSL Token Size").
    pub fn max_token_len(self) -> usize {
        match self {
            Target::WebGl1 => 256,
            Target::WebGl2 => 1024,
        }
    }

    /// The reference implementation's limits and the specification's guarantees.
    pub fn profile(self) -> &'static Profile {
        match self {
            Target::WebGl1 => &WEBGL1,
            Target::WebGl2 => &WEBGL2,
        }
    }
}

/// A WebGL extension that adds to the shading language, as a context enables it: the WebGL 1
/// extensions add to GLSL ES 1.00 in a WebGL 1 context; `WEBGL_clip_cull_distance` adds to
/// GLSL ES 3.00 in a WebGL 2 context (`WEBGL_clip_cull_distance`, `EXT_conservative_depth`,
/// `NV_shader_noperspective_interpolation`);
/// `WEBGL_multi_draw` adds to both languages in both.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Extension {
    /// `OES_standard_derivatives`: `dFdx`, `dFdy`, `fwidth` in fragment shaders.
    OesStandardDerivatives,
    /// `EXT_shader_texture_lod`: `texture2DLodEXT`, `…GradEXT` in fragment shaders.
    ExtShaderTextureLod,
    /// `EXT_frag_depth`: `gl_FragDepthEXT`.
    ExtFragDepth,
    /// `WEBGL_draw_buffers`: `gl_FragData[n]` for n > 0 (`GL_EXT_draw_buffers` in shaders).
    WebglDrawBuffers,
    /// `WEBGL_clip_cull_distance` (WebGL 2): `gl_ClipDistance[8]` and `gl_CullDistance`
    /// (`GL_ANGLE_clip_cull_distance` in shaders), with no cull distances
    /// (`gl_MaxCullDistances` is 0, as the extension allows).
    WebglClipCullDistance,
    /// `WEBGL_multi_draw` (both contexts): `highp int gl_DrawID` in vertex shaders of either
    /// language (`GL_ANGLE_multi_draw` in shaders), the index of the draw within a multi-draw
    /// call and 0 for any other draw.
    WebglMultiDraw,
    /// `EXT_conservative_depth` (WebGL 2): `layout(depth_any | depth_greater | depth_less) out
    /// float gl_FragDepth;` in GLSL ES 3.00 fragment shaders, a promise about how the shader
    /// moves depth (WebGL's extension leaves out `depth_unchanged`).
    ExtConservativeDepth,
    /// `NV_shader_noperspective_interpolation` (WebGL 2): the `noperspective` interpolation
    /// qualifier in GLSL ES 3.00 (linear interpolation in screen space).
    NvShaderNoperspectiveInterpolation,
}

impl Extension {
    /// Every extension essl knows.
    pub const ALL: [Extension; 8] = [
        Extension::OesStandardDerivatives,
        Extension::ExtShaderTextureLod,
        Extension::ExtFragDepth,
        Extension::WebglDrawBuffers,
        Extension::WebglClipCullDistance,
        Extension::WebglMultiDraw,
        Extension::ExtConservativeDepth,
        Extension::NvShaderNoperspectiveInterpolation,
    ];

    /// Whether a context of `target` offers it: the WebGL 1 extensions only WebGL 1 (WebGL 2
    /// made them core), `WEBGL_clip_cull_distance` only WebGL 2, `WEBGL_multi_draw` both.
    pub fn offered_by(self, target: Target) -> bool {
        match self {
            Extension::WebglMultiDraw => true,
            Extension::WebglClipCullDistance
            | Extension::ExtConservativeDepth
            | Extension::NvShaderNoperspectiveInterpolation => target == Target::WebGl2,
            _ => target == Target::WebGl1,
        }
    }

    /// Whether a GLSL ES 1.00 (`es100`) or 3.00 shader of a `target` context may use it: a
    /// WebGL 1 extension in GLSL ES 1.00 and a WebGL 2 one in GLSL ES 3.00 only;
    /// `WEBGL_multi_draw` in either.
    pub fn usable_in(self, target: Target, es100: bool) -> bool {
        self.offered_by(target)
            && (self == Extension::WebglMultiDraw || (target == Target::WebGl1) == es100)
    }

    /// The name a shader's `#extension` directive uses (also its macro).
    pub fn directive_name(self) -> &'static str {
        match self {
            Extension::OesStandardDerivatives => "GL_OES_standard_derivatives",
            Extension::ExtShaderTextureLod => "GL_EXT_shader_texture_lod",
            Extension::ExtFragDepth => "GL_EXT_frag_depth",
            Extension::WebglDrawBuffers => "GL_EXT_draw_buffers",
            Extension::WebglClipCullDistance => "GL_ANGLE_clip_cull_distance",
            Extension::WebglMultiDraw => "GL_ANGLE_multi_draw",
            Extension::ExtConservativeDepth => "GL_EXT_conservative_depth",
            Extension::NvShaderNoperspectiveInterpolation => {
                "GL_NV_shader_noperspective_interpolation"
            }
        }
    }

    /// The name `getExtension` takes.
    pub fn webgl_name(self) -> &'static str {
        match self {
            Extension::OesStandardDerivatives => "OES_standard_derivatives",
            Extension::ExtShaderTextureLod => "EXT_shader_texture_lod",
            Extension::ExtFragDepth => "EXT_frag_depth",
            Extension::WebglDrawBuffers => "WEBGL_draw_buffers",
            Extension::WebglClipCullDistance => "WEBGL_clip_cull_distance",
            Extension::WebglMultiDraw => "WEBGL_multi_draw",
            Extension::ExtConservativeDepth => "EXT_conservative_depth",
            Extension::NvShaderNoperspectiveInterpolation => {
                "NV_shader_noperspective_interpolation"
            }
        }
    }

    /// The extension whose `#extension` name or WebGL name is `name`.
    pub fn from_name(name: &str) -> Option<Extension> {
        Extension::ALL
            .into_iter()
            .find(|e| e.directive_name() == name || e.webgl_name() == name)
    }
}

/// The implementation-dependent numbers a shader is checked against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// `MAX_VERTEX_ATTRIBS`.
    pub vertex_attribs: u32,
    /// `MAX_VERTEX_UNIFORM_VECTORS`: rows of the uniform packing grid of a vertex shader.
    pub vertex_uniform_vectors: u32,
    /// `MAX_FRAGMENT_UNIFORM_VECTORS`.
    pub fragment_uniform_vectors: u32,
    /// `MAX_VARYING_VECTORS`: rows of the varying packing grid.
    pub varying_vectors: u32,
    /// `MAX_VERTEX_TEXTURE_IMAGE_UNITS`: samplers a vertex shader may use.
    pub vertex_texture_units: u32,
    /// `MAX_TEXTURE_IMAGE_UNITS`: samplers a fragment shader may use.
    pub fragment_texture_units: u32,
    /// `MAX_COMBINED_TEXTURE_IMAGE_UNITS`.
    pub combined_texture_units: u32,
    /// `MAX_DRAW_BUFFERS` (WebGL 1: `MAX_DRAW_BUFFERS_WEBGL`, with `WEBGL_draw_buffers`).
    pub draw_buffers: u32,
}

/// A target's limits: the reference implementation's and the specification's minimums.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Profile {
    /// What Chromium 156 (ANGLE on SwiftShader) reports: past these, an error.
    pub implementation: Limits,
    /// What the WebGL specification guarantees (the GL ES minimums): past these, a warning.
    pub guaranteed: Limits,
}

/// What Chromium's WebGL 1 and WebGL 2 contexts both answer on this machine (ANGLE on
/// SwiftShader; `tests/oracle/limits-webgl{1,2}.json`).
const CHROMIUM: Limits = Limits {
    vertex_attribs: 16,
    vertex_uniform_vectors: 4096,
    fragment_uniform_vectors: 4096,
    varying_vectors: 31,
    vertex_texture_units: 32,
    fragment_texture_units: 32,
    combined_texture_units: 64,
    draw_buffers: 8,
};

/// WebGL 1: `tests/oracle/limits-webgl1.json`; the minimums of OpenGL ES 2.0 §6.2 table 6.19
/// (WebGL 1.0 defers to them), `MAX_DRAW_BUFFERS_WEBGL` ≥ 4 from `WEBGL_draw_buffers`.
const WEBGL1: Profile = Profile {
    implementation: CHROMIUM,
    guaranteed: Limits {
        vertex_attribs: 8,
        vertex_uniform_vectors: 128,
        fragment_uniform_vectors: 16,
        varying_vectors: 8,
        vertex_texture_units: 0,
        fragment_texture_units: 8,
        combined_texture_units: 8,
        draw_buffers: 4,
    },
};

/// WebGL 2: `tests/oracle/limits-webgl2.json`; the minimums of OpenGL ES 3.0 §6.2 tables
/// 6.31–6.33, which WebGL 2.0 defers to.
const WEBGL2: Profile = Profile {
    implementation: CHROMIUM,
    guaranteed: Limits {
        vertex_attribs: 16,
        vertex_uniform_vectors: 256,
        fragment_uniform_vectors: 224,
        varying_vectors: 15,
        vertex_texture_units: 16,
        fragment_texture_units: 16,
        combined_texture_units: 32,
        draw_buffers: 4,
    },
};

/// What the front end's passes need to know about the language they read: the GLSL ES version
/// (decided by the preprocessor), the target, and the extensions this shader may use (enabled
/// by the context and by an `#extension` directive). [`crate::compile`] works it out; tools
/// that run one pass at a time ([`crate::passes`]) build it with [`Language::of`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Language {
    /// GLSL ES 1.00 (`false`: GLSL ES 3.00).
    pub es100: bool,
    /// The context's WebGL version.
    pub target: Target,
    /// The `#extension` directives about extensions the context enabled, in order: the
    /// extension, where the directive is, and whether it enables (`enable`, `require`, `warn`)
    /// or disables it. An extension is usable after a directive that enables it, as ANGLE reads
    /// a shader front to back.
    pub directives: Vec<(Extension, u32, bool)>,
    /// Extensions the context enabled (whether or not the shader enables them).
    pub context: Vec<Extension>,
}

impl Language {
    /// The language of a preprocessed shader, for `target` with the context's `enabled`
    /// extensions: GLSL ES 1.00 unless it declared `#version 300 es` (or another version from
    /// 300 on); the enabled extensions its last `#extension` directive for each (or for `all`)
    /// enables, requires or warns about. WebGL 2 offers none of them.
    pub fn of(pp: &crate::passes::Preprocessed, target: Target, enabled: &[Extension]) -> Language {
        use crate::preprocess::ExtensionBehavior as B;
        // A misplaced or malformed `#version 300 es` (an error) still says what the author
        // meant: check the rest as GLSL ES 3.00 rather than report it line by line.
        let es100 = match (pp.version, pp.declared_version) {
            (crate::Version::Es100, Some(crate::Version::Es300)) => false,
            (crate::Version::Es100, Some(crate::Version::Other(n, _))) if n >= 300 => false,
            (crate::Version::Es300, _) => false,
            (crate::Version::Es100, _) => true,
            (crate::Version::Other(n, _), _) => n < 300,
        };
        let mut directives = Vec::new();
        // The extensions this shader's context and language take.
        let offered: Vec<Extension> = enabled
            .iter()
            .copied()
            .filter(|e| e.usable_in(target, es100))
            .collect();
        for (name, behavior, span) in &pp.extensions {
            let on = matches!(behavior, B::Enable | B::Require | B::Warn);
            for &e in &offered {
                if name == e.directive_name() || name == "all" {
                    directives.push((e, span.start, on));
                }
            }
        }
        Language {
            es100,
            target,
            directives,
            context: offered,
        }
    }

    /// GLSL ES 3.00 for WebGL 2, no extension: what a pass run on its own assumes.
    pub fn es300() -> Language {
        Language {
            es100: false,
            target: Target::WebGl2,
            directives: Vec::new(),
            context: Vec::new(),
        }
    }

    /// Whether the context enabled `e`.
    pub fn context_has(&self, e: Extension) -> bool {
        self.context.contains(&e)
    }

    /// Whether the shader may use `e` at byte `offset`: the last directive about it before
    /// that point enables it.
    pub fn has_at(&self, e: Extension, offset: u32) -> bool {
        self.directives
            .iter()
            .rev()
            .find(|(x, at, _)| *x == e && *at <= offset)
            .is_some_and(|(_, _, on)| *on)
    }

    /// `"GLSL ES 1.00"` or `"GLSL ES 3.00"`, for messages.
    pub fn name(&self) -> &'static str {
        if self.es100 {
            "GLSL ES 1.00"
        } else {
            "GLSL ES 3.00"
        }
    }
}
