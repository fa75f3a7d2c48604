//! The linker's settings and counter, and why a link fails.

/// Why a link failed; its text is the program's info log.
#[derive(Debug, thiserror::Error)]
pub(crate) enum LinkError {
    /// `linkProgram` without both shaders.
    #[error("a vertex and a fragment shader must be attached")]
    MissingShader,
    /// `linkProgram` with a shader whose last compile failed (or that was never compiled).
    #[error("an attached shader is not compiled")]
    NotCompiled,
    /// The front end refused to link the shaders: its WebGL-style log.
    #[error("{0}")]
    Front(String),
    /// The front end could not lower the linked program.
    #[error(transparent)]
    Lower(#[from] essl::lower::LowerError),
    /// The program filter
    /// ([`Context::set_program_filter`](crate::Context::set_program_filter)) refused the
    /// layout.
    #[error("{0}")]
    Filter(String),
    /// More sampler slots than the device binds.
    #[error("{0} samplers: more than the device supports")]
    TooManySamplers(usize),
    /// An attribute at a location past `MAX_VERTEX_ATTRIBS`.
    #[error("attribute location {0} ≥ MAX_VERTEX_ATTRIBS")]
    AttributeLocation(u32),
    /// More uniform blocks than the device binds.
    #[error("{0} uniform blocks: more than the device supports")]
    TooManyBlocks(usize),
    /// A uniform block larger than the device's largest uniform binding.
    #[error("uniform block {name} of {size} bytes is too large")]
    BlockTooLarge {
        /// The block's name.
        name: String,
        /// Its size in bytes.
        size: u32,
    },
    /// A default uniform block larger than the device's largest uniform binding.
    #[error("default uniform block of {0} bytes is too large")]
    DefaultBlockTooLarge(u32),
    /// The transform feedback varyings do not fit (ES 3.0's link errors for them).
    #[error("{0}")]
    Feedback(String),
    /// wgpu's validation refused the lowered modules.
    #[error("the lowered shaders were rejected by wgpu: {0}")]
    Rejected(String),
}

/// The linker's settings and counter: the serial that tells links apart (it keys pipelines
/// and uniform locations), the step between lowering and installing
/// ([`Context::set_program_filter`](crate::Context::set_program_filter)) and the WebGL
/// version shaders are compiled for
/// ([`Context::set_shader_target`](crate::Context::set_shader_target)).
pub(crate) struct Linker {
    serial: u64,
    pub(crate) filter: Option<ProgramFilter>,
    /// How shaders are compiled: the WebGL version and the extensions turned on.
    pub(crate) shaders: essl::CompileOptions,
}

impl Default for Linker {
    /// WebGL 2, with none of WebGL 2's shader extensions until `getExtension` turns them on.
    fn default() -> Linker {
        let mut shaders = essl::CompileOptions::default();
        shaders
            .extensions
            .retain(|e| !e.offered_by(essl::Target::WebGl2));
        Linker {
            serial: 0,
            filter: None,
            shaders,
        }
    }
}

impl Linker {
    /// A serial no earlier link of the context had.
    pub(super) fn next_serial(&mut self) -> u64 {
        self.serial += 1;
        self.serial
    }
}

/// A step between lowering and installing a program: see
/// [`Context::set_program_filter`](crate::Context::set_program_filter).
pub type ProgramFilter = Box<
    dyn FnMut(essl::program::ProgramLayout) -> Result<essl::program::ProgramLayout, String> + Send,
>;
