//! A loaded scene: the file's settings with every derived value computed — shader sources, mesh,
//! matrices, resolved uniforms and textures with their units.

use std::path::{Path, PathBuf};

use crate::error::SceneError;
use crate::format::{Camera, Model, SceneFile, Stream};
use crate::matrix::{Derived, DerivedValue, Matrices};
use crate::mesh::Mesh;
use crate::texture::{build_textures, Texture};
use crate::uniforms::{Resolved, UniformType, UniformValue, UploadValues};

/// A shader file of a scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderSource {
    /// The path as the scene writes it (what the tool uses as the file's name in `compile_log`).
    pub name: String,
    /// The file that was read: `name` resolved against the scene file's folder.
    pub path: PathBuf,
    /// The UTF-8 text, exactly as in the file.
    pub source: String,
}

impl ShaderSource {
    /// Reads `name` relative to `base_dir`; `what` (`vertex_shader` / `fragment_shader`) names it
    /// in errors.
    pub fn read(base_dir: &Path, name: &str, what: &'static str) -> Result<Self, SceneError> {
        let path = base_dir.join(name);
        let text = read_utf8(&path, what)?;
        Ok(ShaderSource {
            name: name.to_string(),
            path,
            source: text,
        })
    }
}

fn read_utf8(path: &Path, what: &'static str) -> Result<String, SceneError> {
    let bytes = std::fs::read(path).map_err(|source| SceneError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    String::from_utf8(bytes).map_err(|e| SceneError::NotUtf8 {
        what,
        path: path.to_path_buf(),
        source: e.utf8_error(),
    })
}

/// One entry of the scene's `uniforms`, resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct Uniform {
    /// The uniform's name (an array's `[0]` may be left off).
    pub name: String,
    /// The value as written.
    pub value: UniformValue,
    /// The value in float64 (see [`Resolved::upload`] to fit it to the active type).
    pub resolved: Resolved,
}

impl Uniform {
    /// The typed array this uniform receives when its active type is `ty` with `array_size`
    /// elements (see [`Resolved::upload`]).
    pub fn upload(&self, ty: UniformType, array_size: usize) -> Result<UploadValues, SceneError> {
        self.resolved.upload(&self.name, ty, array_size)
    }
}

/// A scene with everything derived, ready to upload.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The file as parsed (every setting, defaults filled in).
    pub file: SceneFile,
    /// The vertex shader.
    pub vertex_shader: ShaderSource,
    /// The fragment shader.
    pub fragment_shader: ShaderSource,
    /// The mesh, float64.
    pub mesh: Mesh,
    /// The matrices (model, view, projection and products).
    pub matrices: Matrices,
    /// The uniforms in file order, resolved.
    pub uniforms: Vec<Uniform>,
    /// The textures in unit order (sorted by name).
    pub textures: Vec<Texture>,
}

impl Scene {
    /// Reads a scene file, its two shaders (relative to the file's folder) and computes
    /// everything derived.
    pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
        let path = path.as_ref();
        let json = read_utf8(path, "scene")?;
        let base = path.parent().unwrap_or(Path::new(""));
        Scene::from_json(&json, base)
    }

    /// Parses scene JSON whose shader paths are relative to `base_dir`, reads the shaders and
    /// computes everything derived.
    pub fn from_json(json: &str, base_dir: &Path) -> Result<Scene, SceneError> {
        let file = SceneFile::parse(json)?;
        file.validate()?;
        let vs = ShaderSource::read(base_dir, &file.vertex_shader, "vertex_shader")?;
        let fs = ShaderSource::read(base_dir, &file.fragment_shader, "fragment_shader")?;
        Scene::build(file, vs, fs)
    }

    /// Validates a parsed file and computes everything derived, with the shader sources given
    /// (no file access).
    pub fn build(
        file: SceneFile,
        vertex_shader: ShaderSource,
        fragment_shader: ShaderSource,
    ) -> Result<Scene, SceneError> {
        file.validate()?;
        let mesh = Mesh::build(&file.mesh);
        let matrices = Matrices::new(&file.camera, &file.model, file.width, file.height)?;
        let uniforms = file
            .uniforms
            .iter()
            .map(|(name, value)| {
                Ok(Uniform {
                    name: name.to_string(),
                    value: value.clone(),
                    resolved: value.resolve(name, &matrices)?,
                })
            })
            .collect::<Result<Vec<_>, SceneError>>()?;
        let textures = build_textures(&file.textures);
        Ok(Scene {
            file,
            vertex_shader,
            fragment_shader,
            mesh,
            matrices,
            uniforms,
            textures,
        })
    }

    /// Canvas width.
    pub fn width(&self) -> u32 {
        self.file.width
    }

    /// Canvas height.
    pub fn height(&self) -> u32 {
        self.file.height
    }

    /// `clearColor`.
    pub fn clear_color(&self) -> [f64; 4] {
        self.file.clear_color
    }

    /// Whether `DEPTH_TEST` is on.
    pub fn depth_test(&self) -> bool {
        self.file.depth_test
    }

    /// Whether `CULL_FACE` (back faces) is on.
    pub fn cull_face(&self) -> bool {
        self.file.cull_face
    }

    /// The camera.
    pub fn camera(&self) -> &Camera {
        &self.file.camera
    }

    /// The model transform.
    pub fn model(&self) -> &Model {
        &self.file.model
    }

    /// Shader attribute name → stream, in file order.
    pub fn attributes(&self) -> impl Iterator<Item = (&str, Stream)> {
        self.file.attributes.iter().map(|(k, v)| (k, *v))
    }

    /// The resolved uniform of that name, if the scene sets it.
    pub fn uniform(&self, name: &str) -> Option<&Uniform> {
        self.uniforms.iter().find(|u| u.name == name)
    }

    /// The texture bound to that sampler name, if any.
    pub fn texture(&self, name: &str) -> Option<&Texture> {
        self.textures.iter().find(|t| t.name == name)
    }

    /// A derived value by name.
    pub fn derived(&self, d: Derived) -> Result<DerivedValue, SceneError> {
        self.matrices.derived(d)
    }
}
