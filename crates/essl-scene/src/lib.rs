//! The scene format of `webgl2-render.py` (`shared/scenes/FORMAT.md`), exactly.
//!
//! A scene fixes everything a WebGL2 draw depends on. This crate parses one strictly (unknown
//! keys are errors, defaults as FORMAT.md's table says) and computes everything derived **bit for
//! bit as the reference tool does**: float64 in FORMAT.md's order of operations, rounded once to
//! `f32` when uploaded. The float64 values stay available (for a CPU reference renderer); the
//! `*_f32` / `as_f32` methods give what is uploaded.
//!
//! - [`format`](mod@format): the serde structs of the file ([`SceneFile`]) and their validation;
//! - [`mesh`]: `grid`, `sphere`, `cube`, `arrays` meshes ([`Mesh`]) and their draw call;
//! - [`matrix`]: [`Mat4`], model / look-at / perspective, gl-matrix's inverse, [`Derived`];
//! - [`uniforms`]: uniform value forms, their resolution and fitting to an active type;
//! - [`texture`]: `checker` / `pixels` texels and texture units;
//! - [`scene`]: [`Scene::load`], which ties them together;
//! - [`png_io`], [`compare`](mod@compare): PNG in/out in `readPixels` row order, and image differences.
//!
//! ```no_run
//! let scene = essl_scene::Scene::load("../shared/scenes/spot-smooth.json")?;
//! let mvp = scene.matrices.model_view_projection.as_f32();
//! let positions = scene.mesh.stream_f32(essl_scene::Stream::Position);
//! # let _ = (mvp, positions);
//! # Ok::<(), essl_scene::SceneError>(())
//! ```

#![warn(missing_docs)]

pub mod compare;
pub mod error;
pub mod format;
pub mod matrix;
pub mod mesh;
pub mod png_io;
pub mod scene;
pub mod texture;
pub mod uniforms;

pub use compare::{compare, diff_image, write_diff_png, ImageDiff};
pub use error::{ImageError, SceneError};
pub use format::{
    ArrayStreams, Camera, Filter, MeshSpec, Model, OrderedMap, SceneFile, Stream, TextureSpec, Wrap,
};
pub use matrix::{
    cos_deg, cross, dot, normalize, radians, upper_left_3x3, Derived, DerivedValue, Mat4, Matrices,
};
pub use mesh::{Draw, IndexType, Mesh};
pub use png_io::{read_png, write_png_gl_rows, RgbaImage};
pub use scene::{Scene, ShaderSource, Uniform};
pub use texture::{build_textures, checker_texels, Texture};
pub use uniforms::{Resolved, UniformType, UniformValue, UploadValues};
