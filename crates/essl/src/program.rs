//! A linked program, lowered for a GPU API: the contract between the front end and `essl-gl`.
//!
//! The front end links a vertex and a fragment shader the way WebGL2 does and lowers both to
//! naga modules that follow the conventions below; a renderer (`essl-gl`) only has to create
//! pipelines from these modules and feed the bindings described here.
//!
//! # Conventions of the lowered modules
//! - Each module has one entry point named `main` (stage vertex or fragment).
//! - Vertex inputs are entry-point arguments with `Binding::Location { location }` equal to the
//!   attribute's location in [`ProgramLayout::attributes`]. The shader-side type of an input is
//!   the declared GLSL type (`vec4` stays `vec4` even when the buffer feeds 3 floats).
//! - Varyings use `Binding::Location` numbers assigned by the linker (the same in both stages).
//!   The vertex stage writes `BuiltIn::Position` in the GPU API's clip space: the lowering has
//!   already remapped GL's depth range (z from −w..w to 0..w) when
//!   [`LowerOptions::zero_to_one_depth`] is set, and negated y when [`LowerOptions::flip_clip_y`]
//!   is.
//! - A vertex shader that writes `gl_ClipDistance` writes `BuiltIn::ClipDistances` (eight
//!   floats; wgpu's `CLIP_DISTANCES`). A fragment shader that reads it gets the values through
//!   two `vec4` varyings at the locations after the others (the GPU APIs have clip distances as
//!   vertex outputs only).
//! - Fragment outputs use `Binding::Location` equal to the GLSL output's location.
//! - All loose (default-block) uniforms of both stages live in one uniform buffer at
//!   `@group(0) @binding(0)`, laid out as [`UniformBlock`] says; both stages declare the same
//!   struct type. Uniform *blocks* declared in the shader get bindings `1..` in group 0, in
//!   [`ProgramLayout::blocks`] order.
//! - Each sampler (each element of a sampler array) becomes a texture at
//!   `@group(1) @binding(2 * slot)` and a sampler at `@group(1) @binding(2 * slot + 1)`, where
//!   `slot` indexes [`ProgramLayout::samplers`].

use crate::types::GlType;

/// Options for lowering a linked program to naga modules.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LowerOptions {
    /// Remap clip-space z from GL's −w..w to 0..w (Vulkan, Metal, D3D, WebGPU).
    pub zero_to_one_depth: bool,
    /// Flip `gl_FragCoord.y` so that it counts from the bottom of the framebuffer, as in GL,
    /// on an API whose framebuffer y points down. Reads [`InternalUniform::FramebufferHeight`].
    pub flip_frag_coord_y: bool,
    /// Negate `gl_Position.y` and flip `gl_PointCoord.y`: the image is drawn upside down on an
    /// API whose framebuffer y points down, so that a framebuffer's rows are stored bottom row
    /// first, in GL's order — what sampling a rendered texture, `readPixels` and blits expect.
    /// Use it with `flip_frag_coord_y` off: `gl_FragCoord` and `dFdy` then need no change. The
    /// renderer must also swap the winding of front faces.
    pub flip_clip_y: bool,
    /// Vertex outputs transform feedback captures (`transformFeedbackVaryings`): each is
    /// written by the lowered vertex shader even when the fragment shader does not read it,
    /// and [`ProgramLayout::captured`] says where. Names are GLSL's: a variable, an element
    /// of an array output (`v[2]`), `gl_Position` or `gl_PointSize`.
    pub transform_feedback: Vec<String>,
    /// Declare integer cube samplers (`isamplerCube`, `usamplerCube`) as 2D array textures
    /// of six layers, one a face in GL's order (+X, −X, +Y, −Y, +Z, −Z): the renderer binds
    /// a 2D array view of the cube texture, and lookups load the nearest texel of the face
    /// and level they select (`textureLod` takes its level). Off, they stay cube textures
    /// and lookups gather from level 0, as naga can neither sample nor load an integer cube.
    pub integer_cube_as_array: bool,
    /// Read which clip distances the API has enabled (`enable(CLIP_DISTANCEi_WEBGL)`) from
    /// [`InternalUniform::ClipDistancesEnabled`]: a vertex shader's `gl_ClipDistance[i]` clips
    /// only where bit `i` is set. Off, every distance clips, as a WebGPU pipeline does.
    pub clip_distance_switches: bool,
    /// Declare `EXT_clip_control`'s state as two pipeline-overridable constants of the vertex
    /// stage, [`CLIP_UPPER_LEFT`] and [`CLIP_ZERO_TO_ONE`] (false unless the pipeline sets
    /// them): `UPPER_LEFT_EXT` takes back the negation [`LowerOptions::flip_clip_y`] makes (or
    /// makes one without it), `ZERO_TO_ONE_EXT` keeps z as the shader wrote it where
    /// [`LowerOptions::zero_to_one_depth`] would map it.
    pub clip_control: bool,
    /// Clamp the bias of `texture(s, p, bias)` to ±[`MAX_TEXTURE_LOD_BIAS`], as GL clamps it
    /// to its `MAX_TEXTURE_LOD_BIAS`: a renderer that reports that limit then samples what it
    /// says for any bias (WGSL's own clamp is at 15.99).
    pub clamp_lod_bias: bool,
}

/// The `MAX_TEXTURE_LOD_BIAS` that [`LowerOptions::clamp_lod_bias`] clamps to: 15.0, within
/// what WGSL takes (it clamps a bias to [−16, 15.99]) and what Vulkan devices such as
/// lavapipe (16) apply, and above the biases the conformance suite's pages draw with.
pub const MAX_TEXTURE_LOD_BIAS: f32 = 15.0;

/// The vertex stage's pipeline-overridable `bool` that is true under `EXT_clip_control`'s
/// `UPPER_LEFT_EXT` origin ([`LowerOptions::clip_control`]).
pub const CLIP_UPPER_LEFT: &str = "_essl_clip_upper_left";
/// The vertex stage's pipeline-overridable `bool` that is true under `EXT_clip_control`'s
/// `ZERO_TO_ONE_EXT` depth mode ([`LowerOptions::clip_control`]).
pub const CLIP_ZERO_TO_ONE: &str = "_essl_clip_zero_to_one";

impl Default for LowerOptions {
    fn default() -> Self {
        Self {
            zero_to_one_depth: true,
            flip_frag_coord_y: true,
            flip_clip_y: false,
            transform_feedback: Vec::new(),
            integer_cube_as_array: false,
            clip_distance_switches: false,
            clip_control: false,
            clamp_lod_bias: false,
        }
    }
}

/// Everything a renderer needs to bind and feed a linked, lowered program.
#[derive(Clone, Debug)]
pub struct ProgramLayout {
    /// The lowered vertex shader (entry point `main`).
    pub vertex: naga::Module,
    /// Validation info of [`ProgramLayout::vertex`].
    pub vertex_info: naga::valid::ModuleInfo,
    /// The lowered fragment shader (entry point `main`).
    pub fragment: naga::Module,
    /// Validation info of [`ProgramLayout::fragment`].
    pub fragment_info: naga::valid::ModuleInfo,
    /// The default uniform block (group 0, binding 0); `None` when the program has no loose
    /// uniform and no internal uniform.
    pub uniform_block: Option<UniformBlock>,
    /// Active uniforms in WebGL's enumeration order (`getActiveUniform(program, i)`).
    pub uniforms: Vec<ActiveUniform>,
    /// Active attributes in WebGL's enumeration order (`getActiveAttrib(program, i)`).
    pub attributes: Vec<ActiveAttribute>,
    /// Sampler slots: texture at group 1 binding `2 * slot`, sampler at `2 * slot + 1`.
    pub samplers: Vec<SamplerSlot>,
    /// Uniform blocks declared in the shaders, bound at group 0, binding `1 + index`.
    pub blocks: Vec<UniformBlockBinding>,
    /// Fragment outputs: (location, type). A renderer with one colour target uses location 0.
    pub fragment_outputs: Vec<(u32, GlType)>,
    /// The fragment outputs by name: (name, first location, array length or 1), for
    /// `getFragDataLocation`.
    pub fragment_output_names: Vec<(String, u32, u32)>,
    /// The outputs [`LowerOptions::transform_feedback`] asked for that the vertex shader
    /// has, in the order asked.
    pub captured: Vec<CapturedOutput>,
}

/// A vertex output kept for transform feedback, and where the lowered vertex shader writes
/// it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CapturedOutput {
    /// The name as asked (`v_velocity`, `v_pos[1]`, `gl_Position`).
    pub name: String,
    /// Its type (of one element for an array).
    pub ty: GlType,
    /// Array elements captured (1 for a non-array or an element).
    pub size: u32,
    /// Where the value is.
    pub source: CaptureSource,
}

/// Where a captured output is in the lowered vertex shader's outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CaptureSource {
    /// `count` consecutive locations from `first` (one per column, per array element).
    Location {
        /// The first location.
        first: u32,
        /// How many.
        count: u32,
    },
    /// `gl_Position` (the lowered value is the API's clip position: the renderer undoes the
    /// [`LowerOptions`] remapping to capture GL's).
    Position,
    /// `gl_PointSize`.
    PointSize,
}

/// The layout of the default uniform block (all loose uniforms of a program).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UniformBlock {
    /// Size of the buffer in bytes (a multiple of 16).
    pub size: u32,
    /// Values the renderer fills in itself, with their byte offsets.
    pub internal: Vec<(InternalUniform, u32)>,
}

/// A value of the default uniform block that the renderer, not the application, provides.
/// Deliberately exhaustive: a renderer must supply every one, so a new value is a change a
/// renderer has to see.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InternalUniform {
    /// The height of the framebuffer in pixels, as an `f32` (for `gl_FragCoord.y` flipping).
    FramebufferHeight,
    /// The clip distances enabled, as a `u32` whose bit `i` is `CLIP_DISTANCEi_WEBGL`
    /// ([`LowerOptions::clip_distance_switches`]).
    ClipDistancesEnabled,
    /// `gl_DrawID` as an `i32`: the index of the draw within a multi-draw call, 0 for any
    /// other draw (`WEBGL_multi_draw`).
    DrawId,
}

impl InternalUniform {
    /// Every value.
    pub const ALL: [InternalUniform; 3] = [
        InternalUniform::FramebufferHeight,
        InternalUniform::ClipDistancesEnabled,
        InternalUniform::DrawId,
    ];

    /// A stable snake_case name for the value (`framebuffer_height`), for binding maps.
    pub fn name(self) -> &'static str {
        match self {
            InternalUniform::FramebufferHeight => "framebuffer_height",
            InternalUniform::ClipDistancesEnabled => "clip_distances_enabled",
            InternalUniform::DrawId => "draw_id",
        }
    }

    /// The name of its member of the default uniform block (`_essl_framebuffer_height`).
    pub fn member_name(self) -> &'static str {
        match self {
            InternalUniform::FramebufferHeight => "_essl_framebuffer_height",
            InternalUniform::ClipDistancesEnabled => "_essl_clip_distances_enabled",
            InternalUniform::DrawId => "_essl_draw_id",
        }
    }

    /// The vertex stage reads it (`gl_ClipDistance`'s switches, `gl_DrawID`), or the fragment
    /// stage (the framebuffer height).
    pub fn stage(self) -> crate::Stage {
        match self {
            InternalUniform::FramebufferHeight => crate::Stage::Fragment,
            InternalUniform::ClipDistancesEnabled | InternalUniform::DrawId => crate::Stage::Vertex,
        }
    }
}

/// How one active uniform is stored, as WebGL enumerates it (`u_spots[0].position`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveUniform {
    /// WebGL's name: arrays of basic types end in `[0]`; struct members are expanded.
    pub name: String,
    /// WebGL's type (`FLOAT_VEC3`, `SAMPLER_2D`, …).
    pub ty: GlType,
    /// Array length (1 for a non-array).
    pub size: u32,
    /// Where the values live.
    pub storage: UniformStorage,
}

/// Where the values of an active uniform live.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UniformStorage {
    /// In the default uniform block.
    Buffer {
        /// Byte offset of element 0.
        offset: u32,
        /// Byte distance between array elements (16-aligned, std140).
        array_stride: u32,
        /// Byte distance between matrix columns (16 in std140); 0 for non-matrices.
        matrix_stride: u32,
    },
    /// A sampler: element `i` of the array is sampler slot `first_slot + i`; its value is the
    /// texture unit set with `uniform1i`.
    Sampler {
        /// Slot of element 0 in [`ProgramLayout::samplers`].
        first_slot: u32,
    },
    /// A member of a uniform block: its value comes from the buffer bound to the block, not
    /// from `uniform*` calls. Offsets and strides are std140's, within the block.
    Block {
        /// The block's index in [`ProgramLayout::blocks`].
        block: u32,
        /// Byte offset of element 0 in the block.
        offset: u32,
        /// Byte distance between array elements (0 for a non-array).
        array_stride: u32,
        /// Byte distance between matrix columns (or rows when row-major); 0 for
        /// non-matrices.
        matrix_stride: u32,
        /// Whether a matrix is stored row by row (`layout(row_major)`).
        row_major: bool,
    },
}

/// How booleans and integers are stored in the default uniform block.
///
/// `bool`/`bvecN` are stored as 32-bit unsigned integers (0 or 1), `int` as i32, `uint` as
/// u32, floats as f32; matrices column by column with [`UniformStorage::Buffer::matrix_stride`].
pub const BOOL_STORAGE_BYTES: u32 = 4;

/// One sampler slot: a texture binding and a sampler binding.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SamplerSlot {
    /// The uniform element this slot belongs to (`u_tex[2]`, `u_cookie`).
    pub name: String,
    /// The sampler's GLSL type (`SAMPLER_2D`, `INT_SAMPLER_3D`, `SAMPLER_2D_SHADOW`, …).
    pub ty: GlType,
    /// Whether the sampler compares depth (`sampler2DShadow`, …): a comparison sampler.
    pub comparison: bool,
}

/// An active vertex attribute.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveAttribute {
    /// The attribute's name.
    pub name: String,
    /// WebGL's type (`FLOAT_VEC4`, `INT`, `FLOAT_MAT4`, …).
    pub ty: GlType,
    /// Array length (attributes cannot be arrays in ES 3.00: always 1).
    pub size: u32,
    /// The first location (a `matN` takes N consecutive locations).
    pub location: u32,
}

/// A uniform block declared in a shader (`uniform Lights { … } lights;`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UniformBlockBinding {
    /// The block's name (not the instance name).
    pub name: String,
    /// Minimum buffer size in bytes (std140).
    pub size: u32,
    /// Whether the vertex shader uses the block.
    pub vertex: bool,
    /// Whether the fragment shader uses the block.
    pub fragment: bool,
}
