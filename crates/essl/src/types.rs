//! The GLSL ES 3.00 type system: scalars, vectors, matrices, samplers, structs and arrays,
//! and WebGL's names for them (`FLOAT_VEC3`, `SAMPLER_2D`, …).

use std::fmt;

/// The kind of a scalar or of a vector's components.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ScalarKind {
    /// `float`
    Float,
    /// `int`
    Int,
    /// `uint`
    Uint,
    /// `bool`
    Bool,
}

impl ScalarKind {
    /// The GLSL keyword of the scalar type.
    pub fn name(self) -> &'static str {
        match self {
            ScalarKind::Float => "float",
            ScalarKind::Int => "int",
            ScalarKind::Uint => "uint",
            ScalarKind::Bool => "bool",
        }
    }

    /// The prefix of the vector types of this kind (`vec`, `ivec`, `uvec`, `bvec`).
    pub fn vector_prefix(self) -> &'static str {
        match self {
            ScalarKind::Float => "vec",
            ScalarKind::Int => "ivec",
            ScalarKind::Uint => "uvec",
            ScalarKind::Bool => "bvec",
        }
    }

    /// Whether precision qualifiers apply to this kind (all but `bool`).
    pub fn has_precision(self) -> bool {
        !matches!(self, ScalarKind::Bool)
    }
}

/// A precision qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Precision {
    /// `lowp`
    Low,
    /// `mediump`
    Medium,
    /// `highp`
    High,
}

impl Precision {
    /// The GLSL keyword.
    pub fn name(self) -> &'static str {
        match self {
            Precision::Low => "lowp",
            Precision::Medium => "mediump",
            Precision::High => "highp",
        }
    }
}

/// The dimensionality of a sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerDim {
    /// `sampler2D`, `isampler2D`, `usampler2D`, `sampler2DShadow`
    D2,
    /// `sampler3D`, `isampler3D`, `usampler3D`
    D3,
    /// `samplerCube`, `isamplerCube`, `usamplerCube`, `samplerCubeShadow`
    Cube,
    /// `sampler2DArray`, `isampler2DArray`, `usampler2DArray`, `sampler2DArrayShadow`
    D2Array,
}

impl SamplerDim {
    /// Number of coordinates that address a texel (without the array layer): 2 or 3.
    pub fn coord_dims(self) -> u8 {
        match self {
            SamplerDim::D2 => 2,
            SamplerDim::D3 | SamplerDim::Cube => 3,
            SamplerDim::D2Array => 2,
        }
    }
}

/// An opaque sampler type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SamplerType {
    /// The dimensionality.
    pub dim: SamplerDim,
    /// The kind of value sampling returns (`Float`, `Int` or `Uint`).
    pub kind: ScalarKind,
    /// A depth-comparison sampler (`…Shadow`).
    pub shadow: bool,
}

impl SamplerType {
    /// The GLSL keyword of the sampler type.
    pub fn name(self) -> &'static str {
        use SamplerDim::*;
        use ScalarKind::*;
        match (self.kind, self.dim, self.shadow) {
            (Float, D2, false) => "sampler2D",
            (Float, D3, false) => "sampler3D",
            (Float, Cube, false) => "samplerCube",
            (Float, D2Array, false) => "sampler2DArray",
            (Float, D2, true) => "sampler2DShadow",
            (Float, Cube, true) => "samplerCubeShadow",
            (Float, D2Array, true) => "sampler2DArrayShadow",
            (Int, D2, _) => "isampler2D",
            (Int, D3, _) => "isampler3D",
            (Int, Cube, _) => "isamplerCube",
            (Int, D2Array, _) => "isampler2DArray",
            (Uint, D2, _) => "usampler2D",
            (Uint, D3, _) => "usampler3D",
            (Uint, Cube, _) => "usamplerCube",
            (Uint, D2Array, _) => "usampler2DArray",
            _ => "sampler",
        }
    }

    /// Parses a sampler keyword.
    pub fn from_name(name: &str) -> Option<SamplerType> {
        use SamplerDim::*;
        use ScalarKind::*;
        let (kind, dim, shadow) = match name {
            "sampler2D" => (Float, D2, false),
            "sampler3D" => (Float, D3, false),
            "samplerCube" => (Float, Cube, false),
            "sampler2DArray" => (Float, D2Array, false),
            "sampler2DShadow" => (Float, D2, true),
            "samplerCubeShadow" => (Float, Cube, true),
            "sampler2DArrayShadow" => (Float, D2Array, true),
            "isampler2D" => (Int, D2, false),
            "isampler3D" => (Int, D3, false),
            "isamplerCube" => (Int, Cube, false),
            "isampler2DArray" => (Int, D2Array, false),
            "usampler2D" => (Uint, D2, false),
            "usampler3D" => (Uint, D3, false),
            "usamplerCube" => (Uint, Cube, false),
            "usampler2DArray" => (Uint, D2Array, false),
            _ => return None,
        };
        Some(SamplerType { dim, kind, shadow })
    }

    /// Whether ES 3.00 gives this sampler type a default precision (`lowp` for `sampler2D`
    /// and `samplerCube` in both stages); all others need an explicit precision.
    pub fn has_default_precision(self) -> bool {
        self.kind == ScalarKind::Float
            && !self.shadow
            && matches!(self.dim, SamplerDim::D2 | SamplerDim::Cube)
    }
}

/// Identifies a struct type declared in a shader (an index into the shader's struct table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StructId(pub u32);

/// A struct declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct StructDef {
    /// The struct's name (`None` for an anonymous struct in a declaration).
    pub name: Option<String>,
    /// Its members, in order.
    pub members: Vec<StructMember>,
}

/// A member of a struct.
#[derive(Clone, Debug, PartialEq)]
pub struct StructMember {
    /// The member's name.
    pub name: String,
    /// The member's type.
    pub ty: Type,
    /// The member's precision, where it has one.
    pub precision: Option<Precision>,
}

/// A GLSL ES 3.00 type.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    /// `void`: only as a function's return type.
    Void,
    /// A scalar.
    Scalar(ScalarKind),
    /// A vector of 2 to 4 components.
    Vector(ScalarKind, u8),
    /// A float matrix of `cols` columns of `rows` rows (`mat3x2` has 3 columns, 2 rows).
    Matrix {
        /// Number of columns, 2..=4.
        cols: u8,
        /// Number of rows, 2..=4.
        rows: u8,
    },
    /// An opaque sampler.
    Sampler(SamplerType),
    /// A struct.
    Struct(StructId),
    /// A sized one-dimensional array.
    Array(Box<Type>, u32),
}

impl Type {
    /// `float`
    pub const FLOAT: Type = Type::Scalar(ScalarKind::Float);
    /// `int`
    pub const INT: Type = Type::Scalar(ScalarKind::Int);
    /// `uint`
    pub const UINT: Type = Type::Scalar(ScalarKind::Uint);
    /// `bool`
    pub const BOOL: Type = Type::Scalar(ScalarKind::Bool);

    /// A scalar (`n == 1`) or a vector of `n` components.
    pub fn vec(kind: ScalarKind, n: u8) -> Type {
        if n == 1 {
            Type::Scalar(kind)
        } else {
            Type::Vector(kind, n)
        }
    }

    /// The scalar kind of a scalar, vector or matrix.
    pub fn scalar_kind(&self) -> Option<ScalarKind> {
        match self {
            Type::Scalar(k) | Type::Vector(k, _) => Some(*k),
            Type::Matrix { .. } => Some(ScalarKind::Float),
            _ => None,
        }
    }

    /// Number of components of a scalar (1) or a vector.
    pub fn vector_size(&self) -> Option<u8> {
        match self {
            Type::Scalar(_) => Some(1),
            Type::Vector(_, n) => Some(*n),
            _ => None,
        }
    }

    /// Total number of scalar components of a scalar, vector or matrix.
    pub fn component_count(&self) -> Option<u32> {
        match self {
            Type::Scalar(_) => Some(1),
            Type::Vector(_, n) => Some(*n as u32),
            Type::Matrix { cols, rows } => Some(*cols as u32 * *rows as u32),
            _ => None,
        }
    }

    /// Whether the type is a scalar.
    pub fn is_scalar(&self) -> bool {
        matches!(self, Type::Scalar(_))
    }

    /// Whether the type is a scalar or a vector.
    pub fn is_scalar_or_vector(&self) -> bool {
        matches!(self, Type::Scalar(_) | Type::Vector(..))
    }

    /// Whether the type is a scalar, vector or matrix (a "basic" non-opaque type).
    pub fn is_numeric_basic(&self) -> bool {
        matches!(
            self,
            Type::Scalar(_) | Type::Vector(..) | Type::Matrix { .. }
        )
    }

    /// Whether the type is an array.
    pub fn is_array(&self) -> bool {
        matches!(self, Type::Array(..))
    }

    /// Whether the type is a sampler or contains one (in a struct member or array element).
    pub fn contains_sampler(&self, structs: &[StructDef]) -> bool {
        match self {
            Type::Sampler(_) => true,
            Type::Array(t, _) => t.contains_sampler(structs),
            Type::Struct(id) => structs[id.0 as usize]
                .members
                .iter()
                .any(|m| m.ty.contains_sampler(structs)),
            _ => false,
        }
    }

    /// Whether the type is or contains an array.
    pub fn contains_array(&self, structs: &[StructDef]) -> bool {
        match self {
            Type::Array(..) => true,
            Type::Struct(id) => structs[id.0 as usize]
                .members
                .iter()
                .any(|m| m.ty.contains_array(structs)),
            _ => false,
        }
    }

    /// Whether the type is or contains a struct.
    pub fn contains_struct(&self) -> bool {
        match self {
            Type::Struct(_) => true,
            Type::Array(t, _) => t.contains_struct(),
            _ => false,
        }
    }

    /// Whether the type is or contains a value of the given scalar kind.
    pub fn contains_kind(&self, kind: ScalarKind, structs: &[StructDef]) -> bool {
        match self {
            Type::Scalar(k) | Type::Vector(k, _) => *k == kind,
            Type::Matrix { .. } => kind == ScalarKind::Float,
            Type::Array(t, _) => t.contains_kind(kind, structs),
            Type::Struct(id) => structs[id.0 as usize]
                .members
                .iter()
                .any(|m| m.ty.contains_kind(kind, structs)),
            _ => false,
        }
    }

    /// The element type of an array, the column type of a matrix, the component type of a
    /// vector: what `x[i]` has.
    pub fn index_result(&self) -> Option<Type> {
        match self {
            Type::Array(t, _) => Some((**t).clone()),
            Type::Matrix { rows, .. } => Some(Type::Vector(ScalarKind::Float, *rows)),
            Type::Vector(k, _) => Some(Type::Scalar(*k)),
            _ => None,
        }
    }

    /// How many elements `x[i]` may index: array length, matrix columns, vector components.
    pub fn index_bound(&self) -> Option<u32> {
        match self {
            Type::Array(_, n) => Some(*n),
            Type::Matrix { cols, .. } => Some(*cols as u32),
            Type::Vector(_, n) => Some(*n as u32),
            _ => None,
        }
    }

    /// Formats the type as GLSL writes it, with struct names taken from `structs`.
    pub fn display<'a>(&'a self, structs: &'a [StructDef]) -> TypeDisplay<'a> {
        TypeDisplay { ty: self, structs }
    }

    /// WebGL's enum for a basic or sampler type (`None` for void, structs and arrays).
    pub fn gl_type(&self) -> Option<GlType> {
        GlType::of(self)
    }
}

/// Formats a [`Type`] in GLSL syntax.
pub struct TypeDisplay<'a> {
    ty: &'a Type,
    structs: &'a [StructDef],
}

impl fmt::Display for TypeDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.ty {
            Type::Void => f.write_str("void"),
            Type::Scalar(k) => f.write_str(k.name()),
            Type::Vector(k, n) => write!(f, "{}{}", k.vector_prefix(), n),
            Type::Matrix { cols, rows } if cols == rows => write!(f, "mat{cols}"),
            Type::Matrix { cols, rows } => write!(f, "mat{cols}x{rows}"),
            Type::Sampler(s) => f.write_str(s.name()),
            Type::Struct(id) => match self
                .structs
                .get(id.0 as usize)
                .and_then(|s| s.name.as_deref())
            {
                Some(name) => write!(f, "struct {name}"),
                None => f.write_str("struct"),
            },
            Type::Array(t, n) => write!(f, "{}[{}]", t.display(self.structs), n),
        }
    }
}

macro_rules! gl_types {
    ($($(#[$doc:meta])* $name:ident = $value:literal,)*) => {
        /// WebGL's type enums, as `getActiveUniform` and `getActiveAttrib` report them.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[allow(non_camel_case_types)]
        #[repr(u32)]
        pub enum GlType {
            $($(#[$doc])* $name = $value,)*
        }

        impl GlType {
            /// WebGL's name of the enum (`FLOAT_VEC3`).
            pub fn name(self) -> &'static str {
                match self {
                    $(GlType::$name => stringify!($name),)*
                }
            }

            /// The enum for a GL value (`0x8B51` → `FLOAT_VEC3`).
            pub fn from_u32(value: u32) -> Option<GlType> {
                match value {
                    $($value => Some(GlType::$name),)*
                    _ => None,
                }
            }
        }
    };
}

gl_types! {
    /// `float`
    FLOAT = 0x1406,
    /// `vec2`
    FLOAT_VEC2 = 0x8B50,
    /// `vec3`
    FLOAT_VEC3 = 0x8B51,
    /// `vec4`
    FLOAT_VEC4 = 0x8B52,
    /// `int`
    INT = 0x1404,
    /// `ivec2`
    INT_VEC2 = 0x8B53,
    /// `ivec3`
    INT_VEC3 = 0x8B54,
    /// `ivec4`
    INT_VEC4 = 0x8B55,
    /// `uint`
    UNSIGNED_INT = 0x1405,
    /// `uvec2`
    UNSIGNED_INT_VEC2 = 0x8DC6,
    /// `uvec3`
    UNSIGNED_INT_VEC3 = 0x8DC7,
    /// `uvec4`
    UNSIGNED_INT_VEC4 = 0x8DC8,
    /// `bool`
    BOOL = 0x8B56,
    /// `bvec2`
    BOOL_VEC2 = 0x8B57,
    /// `bvec3`
    BOOL_VEC3 = 0x8B58,
    /// `bvec4`
    BOOL_VEC4 = 0x8B59,
    /// `mat2`
    FLOAT_MAT2 = 0x8B5A,
    /// `mat3`
    FLOAT_MAT3 = 0x8B5B,
    /// `mat4`
    FLOAT_MAT4 = 0x8B5C,
    /// `mat2x3`
    FLOAT_MAT2x3 = 0x8B65,
    /// `mat2x4`
    FLOAT_MAT2x4 = 0x8B66,
    /// `mat3x2`
    FLOAT_MAT3x2 = 0x8B67,
    /// `mat3x4`
    FLOAT_MAT3x4 = 0x8B68,
    /// `mat4x2`
    FLOAT_MAT4x2 = 0x8B69,
    /// `mat4x3`
    FLOAT_MAT4x3 = 0x8B6A,
    /// `sampler2D`
    SAMPLER_2D = 0x8B5E,
    /// `sampler3D`
    SAMPLER_3D = 0x8B5F,
    /// `samplerCube`
    SAMPLER_CUBE = 0x8B60,
    /// `sampler2DShadow`
    SAMPLER_2D_SHADOW = 0x8B62,
    /// `sampler2DArray`
    SAMPLER_2D_ARRAY = 0x8DC1,
    /// `sampler2DArrayShadow`
    SAMPLER_2D_ARRAY_SHADOW = 0x8DC4,
    /// `samplerCubeShadow`
    SAMPLER_CUBE_SHADOW = 0x8DC5,
    /// `isampler2D`
    INT_SAMPLER_2D = 0x8DCA,
    /// `isampler3D`
    INT_SAMPLER_3D = 0x8DCB,
    /// `isamplerCube`
    INT_SAMPLER_CUBE = 0x8DCC,
    /// `isampler2DArray`
    INT_SAMPLER_2D_ARRAY = 0x8DCF,
    /// `usampler2D`
    UNSIGNED_INT_SAMPLER_2D = 0x8DD2,
    /// `usampler3D`
    UNSIGNED_INT_SAMPLER_3D = 0x8DD3,
    /// `usamplerCube`
    UNSIGNED_INT_SAMPLER_CUBE = 0x8DD4,
    /// `usampler2DArray`
    UNSIGNED_INT_SAMPLER_2D_ARRAY = 0x8DD7,
}

impl GlType {
    /// WebGL's enum for a basic or sampler type.
    pub fn of(ty: &Type) -> Option<GlType> {
        use GlType::*;
        use ScalarKind::*;
        Some(match ty {
            Type::Scalar(Float) => FLOAT,
            Type::Scalar(Int) => INT,
            Type::Scalar(Uint) => UNSIGNED_INT,
            Type::Scalar(Bool) => BOOL,
            Type::Vector(Float, 2) => FLOAT_VEC2,
            Type::Vector(Float, 3) => FLOAT_VEC3,
            Type::Vector(Float, 4) => FLOAT_VEC4,
            Type::Vector(Int, 2) => INT_VEC2,
            Type::Vector(Int, 3) => INT_VEC3,
            Type::Vector(Int, 4) => INT_VEC4,
            Type::Vector(Uint, 2) => UNSIGNED_INT_VEC2,
            Type::Vector(Uint, 3) => UNSIGNED_INT_VEC3,
            Type::Vector(Uint, 4) => UNSIGNED_INT_VEC4,
            Type::Vector(Bool, 2) => BOOL_VEC2,
            Type::Vector(Bool, 3) => BOOL_VEC3,
            Type::Vector(Bool, 4) => BOOL_VEC4,
            Type::Matrix { cols: 2, rows: 2 } => FLOAT_MAT2,
            Type::Matrix { cols: 3, rows: 3 } => FLOAT_MAT3,
            Type::Matrix { cols: 4, rows: 4 } => FLOAT_MAT4,
            Type::Matrix { cols: 2, rows: 3 } => FLOAT_MAT2x3,
            Type::Matrix { cols: 2, rows: 4 } => FLOAT_MAT2x4,
            Type::Matrix { cols: 3, rows: 2 } => FLOAT_MAT3x2,
            Type::Matrix { cols: 3, rows: 4 } => FLOAT_MAT3x4,
            Type::Matrix { cols: 4, rows: 2 } => FLOAT_MAT4x2,
            Type::Matrix { cols: 4, rows: 3 } => FLOAT_MAT4x3,
            Type::Sampler(s) => {
                use SamplerDim::*;
                match (s.kind, s.dim, s.shadow) {
                    (Float, D2, false) => SAMPLER_2D,
                    (Float, D3, false) => SAMPLER_3D,
                    (Float, Cube, false) => SAMPLER_CUBE,
                    (Float, D2Array, false) => SAMPLER_2D_ARRAY,
                    (Float, D2, true) => SAMPLER_2D_SHADOW,
                    (Float, Cube, true) => SAMPLER_CUBE_SHADOW,
                    (Float, D2Array, true) => SAMPLER_2D_ARRAY_SHADOW,
                    (Int, D2, _) => INT_SAMPLER_2D,
                    (Int, D3, _) => INT_SAMPLER_3D,
                    (Int, Cube, _) => INT_SAMPLER_CUBE,
                    (Int, D2Array, _) => INT_SAMPLER_2D_ARRAY,
                    (Uint, D2, _) => UNSIGNED_INT_SAMPLER_2D,
                    (Uint, D3, _) => UNSIGNED_INT_SAMPLER_3D,
                    (Uint, Cube, _) => UNSIGNED_INT_SAMPLER_CUBE,
                    (Uint, D2Array, _) => UNSIGNED_INT_SAMPLER_2D_ARRAY,
                    _ => return None,
                }
            }
            _ => return None,
        })
    }

    /// The GLSL type this enum names.
    pub fn to_type(self) -> Type {
        use GlType::*;
        use ScalarKind::*;
        let sampler = |dim, kind, shadow| Type::Sampler(SamplerType { dim, kind, shadow });
        match self {
            FLOAT => Type::Scalar(Float),
            FLOAT_VEC2 => Type::Vector(Float, 2),
            FLOAT_VEC3 => Type::Vector(Float, 3),
            FLOAT_VEC4 => Type::Vector(Float, 4),
            INT => Type::Scalar(Int),
            INT_VEC2 => Type::Vector(Int, 2),
            INT_VEC3 => Type::Vector(Int, 3),
            INT_VEC4 => Type::Vector(Int, 4),
            UNSIGNED_INT => Type::Scalar(Uint),
            UNSIGNED_INT_VEC2 => Type::Vector(Uint, 2),
            UNSIGNED_INT_VEC3 => Type::Vector(Uint, 3),
            UNSIGNED_INT_VEC4 => Type::Vector(Uint, 4),
            BOOL => Type::Scalar(Bool),
            BOOL_VEC2 => Type::Vector(Bool, 2),
            BOOL_VEC3 => Type::Vector(Bool, 3),
            BOOL_VEC4 => Type::Vector(Bool, 4),
            FLOAT_MAT2 => Type::Matrix { cols: 2, rows: 2 },
            FLOAT_MAT3 => Type::Matrix { cols: 3, rows: 3 },
            FLOAT_MAT4 => Type::Matrix { cols: 4, rows: 4 },
            FLOAT_MAT2x3 => Type::Matrix { cols: 2, rows: 3 },
            FLOAT_MAT2x4 => Type::Matrix { cols: 2, rows: 4 },
            FLOAT_MAT3x2 => Type::Matrix { cols: 3, rows: 2 },
            FLOAT_MAT3x4 => Type::Matrix { cols: 3, rows: 4 },
            FLOAT_MAT4x2 => Type::Matrix { cols: 4, rows: 2 },
            FLOAT_MAT4x3 => Type::Matrix { cols: 4, rows: 3 },
            SAMPLER_2D => sampler(SamplerDim::D2, Float, false),
            SAMPLER_3D => sampler(SamplerDim::D3, Float, false),
            SAMPLER_CUBE => sampler(SamplerDim::Cube, Float, false),
            SAMPLER_2D_SHADOW => sampler(SamplerDim::D2, Float, true),
            SAMPLER_2D_ARRAY => sampler(SamplerDim::D2Array, Float, false),
            SAMPLER_2D_ARRAY_SHADOW => sampler(SamplerDim::D2Array, Float, true),
            SAMPLER_CUBE_SHADOW => sampler(SamplerDim::Cube, Float, true),
            INT_SAMPLER_2D => sampler(SamplerDim::D2, Int, false),
            INT_SAMPLER_3D => sampler(SamplerDim::D3, Int, false),
            INT_SAMPLER_CUBE => sampler(SamplerDim::Cube, Int, false),
            INT_SAMPLER_2D_ARRAY => sampler(SamplerDim::D2Array, Int, false),
            UNSIGNED_INT_SAMPLER_2D => sampler(SamplerDim::D2, Uint, false),
            UNSIGNED_INT_SAMPLER_3D => sampler(SamplerDim::D3, Uint, false),
            UNSIGNED_INT_SAMPLER_CUBE => sampler(SamplerDim::Cube, Uint, false),
            UNSIGNED_INT_SAMPLER_2D_ARRAY => sampler(SamplerDim::D2Array, Uint, false),
        }
    }

    /// Whether this is a sampler type.
    pub fn is_sampler(self) -> bool {
        matches!(self.to_type(), Type::Sampler(_))
    }
}

impl fmt::Display for GlType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gl_type_round_trips_through_type() {
        for v in 0x1400..0x9000u32 {
            if let Some(t) = GlType::from_u32(v) {
                assert_eq!(GlType::of(&t.to_type()), Some(t), "{}", t.name());
            }
        }
    }

    #[test]
    fn displays_glsl_names() {
        assert_eq!(
            Type::Matrix { cols: 3, rows: 2 }.display(&[]).to_string(),
            "mat3x2"
        );
        assert_eq!(
            Type::Array(Box::new(Type::Vector(ScalarKind::Uint, 3)), 4)
                .display(&[])
                .to_string(),
            "uvec3[4]"
        );
    }
}
