//! The scene file as written: serde structs, one per JSON object of FORMAT.md, with
//! `deny_unknown_fields` everywhere and FORMAT.md's defaults.
//!
//! Deserializing checks shapes (types, vector lengths, known keys and kinds); ranges and
//! cross-checks (`cells` in 1..1024, `near < far`, …) are [`SceneFile::validate`]'s, and the
//! derived values are computed by [`crate::Scene`]. An optional key that is present must hold a
//! value of its type: `null` is an error as in `webgl2-render.py`, except for `mesh.indices`,
//! where the tool takes `null` as "no indices".

use std::fmt;
use std::marker::PhantomData;

use serde::de::{self, Deserializer, MapAccess, Visitor};
use serde::Deserialize;

use crate::error::SceneError;
use crate::uniforms::UniformValue;

/// A JSON object read as a list of `(key, value)` in the file's order; a key given twice is an
/// error (Python's `json` would silently keep the last).
#[derive(Clone, Debug, PartialEq)]
pub struct OrderedMap<T>(pub Vec<(String, T)>);

impl<T> Default for OrderedMap<T> {
    fn default() -> Self {
        OrderedMap(Vec::new())
    }
}

impl<T> OrderedMap<T> {
    /// The value under `key`.
    pub fn get(&self, key: &str) -> Option<&T> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// Whether `key` is present.
    pub fn contains_key(&self, key: &str) -> bool {
        self.get(key).is_some()
    }

    /// The entries in file order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &T)> {
        self.0.iter().map(|(k, v)| (k.as_str(), v))
    }

    /// How many entries.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for OrderedMap<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for V<T> {
            type Value = OrderedMap<T>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let mut out: Vec<(String, T)> = Vec::new();
                while let Some(key) = map.next_key::<String>()? {
                    if out.iter().any(|(k, _)| *k == key) {
                        return Err(de::Error::custom(format_args!("duplicate key `{key}`")));
                    }
                    let value = map.next_value()?;
                    out.push((key, value));
                }
                Ok(OrderedMap(out))
            }
        }
        d.deserialize_map(V(PhantomData))
    }
}

/// For optional keys: absent gives the default (through `#[serde(default)]`), present must be a
/// `T` (so `null` is refused).
fn present<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<T, D::Error> {
    T::deserialize(d)
}

/// A list of exactly `N` numbers, with a clear message otherwise (serde's own arrays report a
/// list that is too long as "trailing characters").
fn numbers<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<[f64; N], D::Error> {
    let v = Vec::<f64>::deserialize(d)?;
    <[f64; N]>::try_from(v.as_slice())
        .map_err(|_| de::Error::invalid_length(v.len(), &format!("a list of {N} numbers").as_str()))
}

fn vec3<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
    numbers::<D, 3>(d)
}

fn vec4<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 4], D::Error> {
    numbers::<D, 4>(d)
}

/// Two `[r, g, b, a]` colours, 0..255 each.
fn two_colors<'de, D: Deserializer<'de>>(d: D) -> Result<[[u8; 4]; 2], D::Error> {
    let v = Vec::<Vec<u8>>::deserialize(d)?;
    if v.len() != 2 {
        return Err(de::Error::invalid_length(v.len(), &"two colours"));
    }
    let mut out = [[0u8; 4]; 2];
    for (o, c) in out.iter_mut().zip(&v) {
        *o = <[u8; 4]>::try_from(c.as_slice())
            .map_err(|_| de::Error::invalid_length(c.len(), &"[r, g, b, a] integers 0..255"))?;
    }
    Ok(out)
}

fn default_clear_color() -> [f64; 4] {
    [0.0, 0.0, 0.0, 1.0]
}

fn default_true() -> bool {
    true
}

/// The top-level object of a scene file.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Free text, ignored.
    #[serde(default, deserialize_with = "present_opt")]
    pub description: Option<String>,
    /// Canvas and drawing-buffer width, 1..4096.
    pub width: u32,
    /// Canvas and drawing-buffer height, 1..4096.
    pub height: u32,
    /// `clearColor`, default `[0, 0, 0, 1]`.
    #[serde(default = "default_clear_color", deserialize_with = "vec4")]
    pub clear_color: [f64; 4],
    /// `DEPTH_TEST` (function `LESS`), default `true`.
    #[serde(default = "default_true", deserialize_with = "present")]
    pub depth_test: bool,
    /// `CULL_FACE` with `cullFace(BACK)`, `frontFace(CCW)`, default `false`.
    #[serde(default, deserialize_with = "present")]
    pub cull_face: bool,
    /// Vertex shader path, relative to the scene file's folder.
    pub vertex_shader: String,
    /// Fragment shader path, relative to the scene file's folder.
    pub fragment_shader: String,
    /// The mesh.
    pub mesh: MeshSpec,
    /// Shader attribute name → mesh stream; must not be empty.
    pub attributes: OrderedMap<Stream>,
    /// The camera.
    pub camera: Camera,
    /// The model transform, default identity.
    #[serde(default, deserialize_with = "present")]
    pub model: Model,
    /// Uniform name → value.
    #[serde(default, deserialize_with = "present")]
    pub uniforms: OrderedMap<UniformValue>,
    /// Sampler uniform name → texture.
    #[serde(default, deserialize_with = "present")]
    pub textures: OrderedMap<TextureSpec>,
}

fn present_opt<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
    d: D,
) -> Result<Option<T>, D::Error> {
    T::deserialize(d).map(Some)
}

/// A mesh stream: the name an attribute binds to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Stream {
    /// `position`, 3 floats a vertex.
    Position,
    /// `normal`, 3 floats a vertex.
    Normal,
    /// `uv`, 2 floats a vertex.
    Uv,
}

impl Stream {
    /// The three streams in the tool's order.
    pub const ALL: [Stream; 3] = [Stream::Position, Stream::Normal, Stream::Uv];

    /// Floats per vertex: 3, 3, 2 (the `size` of `vertexAttribPointer`).
    pub fn components(self) -> usize {
        match self {
            Stream::Position | Stream::Normal => 3,
            Stream::Uv => 2,
        }
    }

    /// The name as written in a scene.
    pub fn name(self) -> &'static str {
        match self {
            Stream::Position => "position",
            Stream::Normal => "normal",
            Stream::Uv => "uv",
        }
    }
}

impl fmt::Display for Stream {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The `mesh` object, by `kind`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
pub enum MeshSpec {
    /// A plane `y = 0` facing +y, `size` across, `cells` × `cells` squares (1..1024).
    Grid {
        /// Edge length, > 0.
        size: f64,
        /// Cells along each side, 1..1024.
        cells: u32,
    },
    /// A UV sphere at the origin.
    Sphere {
        /// Radius, > 0.
        radius: f64,
        /// Segments around (3..4096).
        segments: u32,
        /// Rings from pole to pole (2..4096).
        rings: u32,
    },
    /// An axis-aligned cube centred at the origin, 24 vertices.
    Cube {
        /// Edge length, > 0.
        size: f64,
    },
    /// Given data.
    Arrays {
        /// The streams given (any of them, same vertex count).
        attributes: ArrayStreams,
        /// Triangle indices; absent (or `null`) means `drawArrays`.
        #[serde(default)]
        indices: Option<Vec<u32>>,
    },
}

/// The `attributes` of an `arrays` mesh: flat number lists.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArrayStreams {
    /// 3 numbers a vertex.
    #[serde(default, deserialize_with = "present_opt")]
    pub position: Option<Vec<f64>>,
    /// 3 numbers a vertex.
    #[serde(default, deserialize_with = "present_opt")]
    pub normal: Option<Vec<f64>>,
    /// 2 numbers a vertex.
    #[serde(default, deserialize_with = "present_opt")]
    pub uv: Option<Vec<f64>>,
}

/// The `camera` object; every key is required.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    /// Eye position.
    #[serde(deserialize_with = "vec3")]
    pub eye: [f64; 3],
    /// Point looked at.
    #[serde(deserialize_with = "vec3")]
    pub target: [f64; 3],
    /// Up direction.
    #[serde(deserialize_with = "vec3")]
    pub up: [f64; 3],
    /// Vertical field of view in degrees, in (0, 180).
    pub fov_y_deg: f64,
    /// Near plane distance, > 0.
    pub near: f64,
    /// Far plane distance, > near.
    pub far: f64,
}

/// The `model` object.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Model {
    /// Translation, default 0.
    #[serde(default, deserialize_with = "vec3")]
    pub translate: [f64; 3],
    /// Rotation angles about X, Y, Z in degrees, default 0.
    #[serde(default, deserialize_with = "vec3")]
    pub rotate_deg: [f64; 3],
    /// Scale, default 1.
    #[serde(default = "default_scale", deserialize_with = "vec3")]
    pub scale: [f64; 3],
}

fn default_scale() -> [f64; 3] {
    [1.0; 3]
}

impl Default for Model {
    fn default() -> Self {
        Model {
            translate: [0.0; 3],
            rotate_deg: [0.0; 3],
            scale: default_scale(),
        }
    }
}

/// A texture's `filter`, for both MIN and MAG, no mipmaps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Filter {
    /// `NEAREST`.
    Nearest,
    /// `LINEAR`.
    Linear,
}

impl Filter {
    /// The GL enum's name (`"NEAREST"`).
    pub fn gl_name(self) -> &'static str {
        match self {
            Filter::Nearest => "NEAREST",
            Filter::Linear => "LINEAR",
        }
    }
}

/// A texture's `wrap`, for both S and T.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Wrap {
    /// `CLAMP_TO_EDGE`.
    Clamp,
    /// `REPEAT`.
    Repeat,
    /// `MIRRORED_REPEAT`.
    Mirror,
}

impl Wrap {
    /// The GL enum's name (`"CLAMP_TO_EDGE"`).
    pub fn gl_name(self) -> &'static str {
        match self {
            Wrap::Clamp => "CLAMP_TO_EDGE",
            Wrap::Repeat => "REPEAT",
            Wrap::Mirror => "MIRRORED_REPEAT",
        }
    }
}

/// One entry of `textures`, by `kind`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
pub enum TextureSpec {
    /// `size`×`size` texels; texel (x, y) is
    /// `colors[((x*cells) div size + (y*cells) div size) mod 2]`.
    Checker {
        /// Width and height, 1..4096.
        size: u32,
        /// Cells along each side, 1..4096.
        cells: u32,
        /// The two colours, RGBA 0..255.
        #[serde(deserialize_with = "two_colors")]
        colors: [[u8; 4]; 2],
        /// Filter.
        filter: Filter,
        /// Wrap.
        wrap: Wrap,
    },
    /// Given texels, row 0 first.
    Pixels {
        /// Width, 1..4096.
        width: u32,
        /// Height, 1..4096.
        height: u32,
        /// `width*height*4` bytes.
        data: Vec<u8>,
        /// Filter.
        filter: Filter,
        /// Wrap.
        wrap: Wrap,
    },
}

/// `webgl2-render.py`'s `pos_int`.
fn int_in(value: u32, field: &str, lo: u32, hi: u32) -> Result<(), SceneError> {
    if (lo..=hi).contains(&value) {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            format!("expected an integer in {lo}..{hi}, got {value}"),
        ))
    }
}

/// `webgl2-render.py`'s `pos_num` (JSON numbers are always finite).
fn positive(value: f64, field: &str) -> Result<(), SceneError> {
    if value > 0.0 {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            format!("expected a positive number, got {value}"),
        ))
    }
}

impl SceneFile {
    /// Parses a scene from JSON text: shapes only (see [`SceneFile::validate`] for ranges).
    pub fn parse(json: &str) -> Result<SceneFile, SceneError> {
        Ok(serde_json::from_str(json)?)
    }

    /// Checks the ranges and cross-references FORMAT.md and `webgl2-render.py` require:
    /// canvas size 1..4096; mesh sizes positive, `cells` 1..1024, `segments` 3..4096, `rings`
    /// 2..4096; `arrays` streams with whole and equal vertex counts, at least one vertex, indices
    /// in range and a multiple of 3 (or a vertex count that is one without indices); attributes
    /// not empty and naming streams the mesh has; the camera's `fov_y_deg` in (0, 180),
    /// `0 < near < far`; texture sizes 1..4096 and `data` of `width*height*4` bytes; no name both
    /// a uniform and a texture.
    pub fn validate(&self) -> Result<(), SceneError> {
        int_in(self.width, "width", 1, 4096)?;
        int_in(self.height, "height", 1, 4096)?;
        let streams: Vec<Stream> = match &self.mesh {
            MeshSpec::Grid { size, cells } => {
                positive(*size, "mesh.size")?;
                int_in(*cells, "mesh.cells", 1, 1024)?;
                Stream::ALL.to_vec()
            }
            MeshSpec::Sphere {
                radius,
                segments,
                rings,
            } => {
                positive(*radius, "mesh.radius")?;
                int_in(*segments, "mesh.segments", 3, 4096)?;
                int_in(*rings, "mesh.rings", 2, 4096)?;
                Stream::ALL.to_vec()
            }
            MeshSpec::Cube { size } => {
                positive(*size, "mesh.size")?;
                Stream::ALL.to_vec()
            }
            MeshSpec::Arrays {
                attributes,
                indices,
            } => {
                let count = attributes.validate()?;
                if let Some(idx) = indices {
                    if let Some(bad) = idx.iter().find(|&&i| i as usize >= count) {
                        return Err(SceneError::invalid(
                            "mesh.indices",
                            format!(
                                "expected integers in 0..{}, got {bad}",
                                count.saturating_sub(1)
                            ),
                        ));
                    }
                    if idx.len() % 3 != 0 {
                        return Err(SceneError::invalid(
                            "mesh.indices",
                            format!("length {} is not a multiple of 3", idx.len()),
                        ));
                    }
                } else if count % 3 != 0 {
                    return Err(SceneError::invalid(
                        "mesh.attributes",
                        format!("vertex count {count} is not a multiple of 3 (no indices given)"),
                    ));
                }
                attributes.present()
            }
        };
        if self.attributes.is_empty() {
            return Err(SceneError::invalid(
                "attributes",
                "expected an object mapping attribute names to streams",
            ));
        }
        for (name, stream) in self.attributes.iter() {
            if !streams.contains(stream) {
                let has: Vec<&str> = streams.iter().map(|s| s.name()).collect();
                return Err(SceneError::invalid(
                    format!("attributes.{name}"),
                    format!(
                        "the mesh has no stream \"{stream}\" (has {})",
                        has.join(", ")
                    ),
                ));
            }
        }
        let cam = &self.camera;
        positive(cam.fov_y_deg, "camera.fov_y_deg")?;
        positive(cam.near, "camera.near")?;
        positive(cam.far, "camera.far")?;
        if cam.fov_y_deg >= 180.0 || cam.near >= cam.far {
            return Err(SceneError::invalid(
                "camera",
                "need fov_y_deg < 180 and near < far",
            ));
        }
        for (name, t) in self.textures.iter() {
            t.validate(&format!("textures.{name}"))?;
        }
        for (name, _) in self.uniforms.iter() {
            if self.textures.contains_key(name) {
                return Err(SceneError::invalid(
                    format!("uniforms.{name}"),
                    "also named in textures; a sampler's unit is set from textures only",
                ));
            }
        }
        Ok(())
    }
}

impl ArrayStreams {
    /// The streams given, in the order position, normal, uv.
    pub fn present(&self) -> Vec<Stream> {
        Stream::ALL
            .into_iter()
            .filter(|&s| self.get(s).is_some())
            .collect()
    }

    /// The data of one stream, if given.
    pub fn get(&self, s: Stream) -> Option<&Vec<f64>> {
        match s {
            Stream::Position => self.position.as_ref(),
            Stream::Normal => self.normal.as_ref(),
            Stream::Uv => self.uv.as_ref(),
        }
    }

    /// Checks the streams give one whole, non-zero vertex count, and returns it.
    pub fn validate(&self) -> Result<usize, SceneError> {
        let mut count: Option<usize> = None;
        for s in Stream::ALL {
            let Some(data) = self.get(s) else { continue };
            let per = s.components();
            if data.len() % per != 0 || count.is_some_and(|c| data.len() / per != c) {
                return Err(SceneError::invalid(
                    format!("mesh.attributes.{s}"),
                    format!(
                        "length {} does not give the same vertex count as the other streams \
                         ({per} floats a vertex)",
                        data.len()
                    ),
                ));
            }
            count = Some(data.len() / per);
        }
        match count {
            Some(c) if c > 0 => Ok(c),
            _ => Err(SceneError::invalid("mesh.attributes", "no vertices")),
        }
    }
}

impl TextureSpec {
    /// Checks sizes (1..4096) and the `data` length; `what` names the texture in errors.
    pub fn validate(&self, what: &str) -> Result<(), SceneError> {
        match self {
            TextureSpec::Checker { size, cells, .. } => {
                int_in(*size, &format!("{what}.size"), 1, 4096)?;
                int_in(*cells, &format!("{what}.cells"), 1, 4096)?;
            }
            TextureSpec::Pixels {
                width,
                height,
                data,
                ..
            } => {
                int_in(*width, &format!("{what}.width"), 1, 4096)?;
                int_in(*height, &format!("{what}.height"), 1, 4096)?;
                let want = *width as usize * *height as usize * 4;
                if data.len() != want {
                    return Err(SceneError::invalid(
                        format!("{what}.data"),
                        format!("expected width*height*4 = {want} bytes, got {}", data.len()),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The filter.
    pub fn filter(&self) -> Filter {
        match self {
            TextureSpec::Checker { filter, .. } | TextureSpec::Pixels { filter, .. } => *filter,
        }
    }

    /// The wrap mode.
    pub fn wrap(&self) -> Wrap {
        match self {
            TextureSpec::Checker { wrap, .. } | TextureSpec::Pixels { wrap, .. } => *wrap,
        }
    }
}
