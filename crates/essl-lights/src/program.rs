//! A generated program: the two shader texts and what they declare.

/// A GLSL type of a uniform, attribute or varying.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GlslType {
    /// `float`
    Float,
    /// `vec2`
    Vec2,
    /// `vec3`
    Vec3,
    /// `mat3`
    Mat3,
    /// `mat4`
    Mat4,
    /// `int`
    Int,
    /// `sampler2D`
    Sampler2D,
}

impl GlslType {
    /// The GLSL spelling.
    pub fn glsl(self) -> &'static str {
        match self {
            GlslType::Float => "float",
            GlslType::Vec2 => "vec2",
            GlslType::Vec3 => "vec3",
            GlslType::Mat3 => "mat3",
            GlslType::Mat4 => "mat4",
            GlslType::Int => "int",
            GlslType::Sampler2D => "sampler2D",
        }
    }

    /// Scalar components (0 for a sampler).
    pub fn components(self) -> usize {
        match self {
            GlslType::Float | GlslType::Int => 1,
            GlslType::Vec2 => 2,
            GlslType::Vec3 => 3,
            GlslType::Mat3 => 9,
            GlslType::Mat4 => 16,
            GlslType::Sampler2D => 0,
        }
    }

    /// Uniform vectors (vec4 slots) one value takes in the GLSL ES packing rules' worst case:
    /// a column or a scalar a slot.
    pub fn vectors(self) -> usize {
        match self {
            GlslType::Mat3 => 3,
            GlslType::Mat4 => 4,
            GlslType::Sampler2D => 0,
            _ => 1,
        }
    }
}

/// Which stages declare a uniform.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Stages {
    /// Declared in the vertex shader.
    pub vertex: bool,
    /// Declared in the fragment shader.
    pub fragment: bool,
}

/// A uniform a program declares.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct UniformDecl {
    /// The name (without `[0]`).
    pub name: String,
    /// The type.
    pub ty: GlslType,
    /// Array length, `None` for a plain uniform.
    pub array: Option<usize>,
    /// Where it is declared.
    pub stages: Stages,
}

impl UniformDecl {
    /// Array length, 1 for a plain uniform.
    pub fn len(&self) -> usize {
        self.array.unwrap_or(1)
    }

    /// Whether it is an array of length 0 (never generated).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The name WebGL's `getActiveUniform` reports (`name[0]` for arrays).
    pub fn active_name(&self) -> String {
        match self.array {
            Some(_) => format!("{}[0]", self.name),
            None => self.name.clone(),
        }
    }
}

/// A generated vertex + fragment shader pair and its interface.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderPair {
    /// The vertex shader, GLSL ES 3.00.
    pub vertex: String,
    /// The fragment shader, GLSL ES 3.00.
    pub fragment: String,
    /// Every uniform declared, each once, in declaration order (vertex first).
    pub uniforms: Vec<UniformDecl>,
    /// The vertex attributes, `(name, type)`.
    pub attributes: Vec<(String, GlslType)>,
    /// The varyings, `(name, type, array length)`.
    pub varyings: Vec<(String, GlslType, Option<usize>)>,
}

impl ShaderPair {
    /// The declared uniform of that name.
    pub fn uniform(&self, name: &str) -> Option<&UniformDecl> {
        self.uniforms.iter().find(|u| u.name == name)
    }

    /// Uniforms excluding samplers.
    pub fn value_uniform_count(&self) -> usize {
        self.uniforms
            .iter()
            .filter(|u| u.ty != GlslType::Sampler2D)
            .count()
    }

    /// Samplers.
    pub fn sampler_count(&self) -> usize {
        self.uniforms.len() - self.value_uniform_count()
    }

    /// Uniform vectors used in the vertex and fragment shader (worst-case packing: one vec4 per
    /// scalar, vector or matrix column).
    pub fn uniform_vectors(&self) -> (usize, usize) {
        let count = |f: fn(&Stages) -> bool| {
            self.uniforms
                .iter()
                .filter(|u| f(&u.stages))
                .map(|u| u.ty.vectors() * u.len())
                .sum()
        };
        (count(|s| s.vertex), count(|s| s.fragment))
    }

    /// Scalar components of all value uniforms (what the CPU uploads per draw).
    pub fn uniform_scalars(&self) -> usize {
        self.uniforms
            .iter()
            .map(|u| u.ty.components() * u.len())
            .sum()
    }
}
