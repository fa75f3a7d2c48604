//! Uniform values: the forms a scene writes ([`UniformValue`]), what they resolve to in float64
//! ([`Resolved`]), and how resolved values are fitted to an active uniform's type
//! ([`UniformType`], [`Resolved::upload`]) exactly as `webgl2-render.py`'s page does.

use std::fmt;

use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;

use crate::error::SceneError;
use crate::matrix::{cos_deg, normalize, upper_left_3x3, Derived, DerivedValue, Mat4, Matrices};

/// A uniform's value as written in the scene.
#[derive(Clone, Debug, PartialEq)]
pub enum UniformValue {
    /// A number, or a list of numbers (in a list, `true`/`false` count as 1/0): the values in
    /// order (matrices column-major, arrays flattened).
    Numbers(Vec<f64>),
    /// `true` / `false`: one value, 1 / 0.
    Bool(bool),
    /// A derived name (`"model_view"`, `"eye"`, …).
    Derived(Derived),
    /// `{"cos_deg": d}`: `cos(radians(d))`.
    CosDeg(f64),
    /// `{"normalize": [x, y, …]}`: `normalize(v)`, any length (an error when its length is 0).
    Normalize(Vec<f64>),
}

/// A list element: a number, or a bool counted as 1/0.
struct NumberOrBool(f64);

impl<'de> Deserialize<'de> for NumberOrBool {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = NumberOrBool;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_bool<E: de::Error>(self, v: bool) -> Result<Self::Value, E> {
                Ok(NumberOrBool(if v { 1.0 } else { 0.0 }))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(NumberOrBool(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(NumberOrBool(v as f64))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                Ok(NumberOrBool(v))
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for UniformValue {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = UniformValue;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(
                    "a number, a list of numbers, true/false, a derived name, \
                     {\"cos_deg\": d} or {\"normalize\": [...]}",
                )
            }
            fn visit_bool<E: de::Error>(self, v: bool) -> Result<Self::Value, E> {
                Ok(UniformValue::Bool(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(UniformValue::Numbers(vec![v as f64]))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(UniformValue::Numbers(vec![v as f64]))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                Ok(UniformValue::Numbers(vec![v]))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Derived::from_name(v)
                    .map(UniformValue::Derived)
                    .ok_or_else(|| {
                        let known: Vec<&str> = Derived::ALL.iter().map(|d| d.name()).collect();
                        E::custom(format_args!(
                            "unknown derived value {v:?} (known: {})",
                            known.join(", ")
                        ))
                    })
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut out = Vec::new();
                while let Some(NumberOrBool(x)) = seq.next_element()? {
                    out.push(x);
                }
                Ok(UniformValue::Numbers(out))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let Some(key) = map.next_key::<String>()? else {
                    return Err(de::Error::custom(
                        "expected {\"cos_deg\": d} or {\"normalize\": [...]}, got {}",
                    ));
                };
                let value = match key.as_str() {
                    "cos_deg" => UniformValue::CosDeg(map.next_value::<f64>()?),
                    "normalize" => UniformValue::Normalize(map.next_value::<Vec<f64>>()?),
                    other => {
                        return Err(de::Error::unknown_field(other, &["cos_deg", "normalize"]));
                    }
                };
                if let Some(extra) = map.next_key::<String>()? {
                    return Err(de::Error::custom(format_args!(
                        "unexpected key `{extra}`: a {{\"{key}\": …}} value has only that key"
                    )));
                }
                Ok(value)
            }
        }
        d.deserialize_any(V)
    }
}

/// A uniform's value resolved in float64, before it meets the active type.
#[derive(Clone, Debug, PartialEq)]
pub enum Resolved {
    /// Plain values (numbers, a bool's 1/0, `cos_deg`, `normalize`, `eye`, `viewport`).
    Values(Vec<f64>),
    /// A matrix-valued derived name: sent whole to a `mat4`, its upper-left 3×3 to a `mat3`.
    Matrix(Mat4),
}

impl UniformValue {
    /// Resolves the value against a scene's matrices; `name` is the uniform's, for errors.
    pub fn resolve(&self, name: &str, matrices: &Matrices) -> Result<Resolved, SceneError> {
        Ok(match self {
            UniformValue::Numbers(v) => Resolved::Values(v.clone()),
            UniformValue::Bool(b) => Resolved::Values(vec![if *b { 1.0 } else { 0.0 }]),
            UniformValue::CosDeg(d) => Resolved::Values(vec![cos_deg(*d)]),
            UniformValue::Normalize(v) => {
                Resolved::Values(normalize(v, &format!("uniforms.{name}"))?)
            }
            UniformValue::Derived(d) => match matrices.derived(*d)? {
                DerivedValue::Matrix(m) => Resolved::Matrix(m),
                DerivedValue::Vector(v) => Resolved::Values(v),
            },
        })
    }
}

/// The base type of an active uniform (`getActiveUniform(...).type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UniformType {
    /// `float`, `vec2`, `vec3`, `vec4`: the component count 1..4.
    Float(u8),
    /// `int`, `ivec2..4`.
    Int(u8),
    /// `uint`, `uvec2..4`.
    Uint(u8),
    /// `bool`, `bvec2..4` (set with `uniform*iv`).
    Bool(u8),
    /// `mat2`.
    Mat2,
    /// `mat3`.
    Mat3,
    /// `mat4`.
    Mat4,
    /// Any sampler: only settable through `textures`.
    Sampler,
}

impl UniformType {
    /// From a GLSL type name: `float`, `vec3`, `ivec2`, `uint`, `bvec4`, `mat3`, `sampler2D`, ….
    pub fn from_glsl(name: &str) -> Option<UniformType> {
        let vec_n = |rest: &str| match rest {
            "2" => Some(2),
            "3" => Some(3),
            "4" => Some(4),
            _ => None,
        };
        Some(match name {
            "float" => UniformType::Float(1),
            "int" => UniformType::Int(1),
            "uint" => UniformType::Uint(1),
            "bool" => UniformType::Bool(1),
            "mat2" | "mat2x2" => UniformType::Mat2,
            "mat3" | "mat3x3" => UniformType::Mat3,
            "mat4" | "mat4x4" => UniformType::Mat4,
            n if n.contains("sampler") => UniformType::Sampler,
            n => {
                if let Some(r) = n.strip_prefix("vec") {
                    UniformType::Float(vec_n(r)?)
                } else if let Some(r) = n.strip_prefix("ivec") {
                    UniformType::Int(vec_n(r)?)
                } else if let Some(r) = n.strip_prefix("uvec") {
                    UniformType::Uint(vec_n(r)?)
                } else if let Some(r) = n.strip_prefix("bvec") {
                    UniformType::Bool(vec_n(r)?)
                } else {
                    return None;
                }
            }
        })
    }

    /// From a WebGL enum name as `--dump` writes it: `FLOAT_VEC3`, `INT`, `BOOL_VEC2`,
    /// `UNSIGNED_INT_VEC4`, `FLOAT_MAT4`, `SAMPLER_2D`, ….
    pub fn from_gl_name(name: &str) -> Option<UniformType> {
        if name.contains("SAMPLER") {
            return Some(UniformType::Sampler);
        }
        let (base, rest) = [("UNSIGNED_INT", 2u8), ("FLOAT", 0), ("INT", 1), ("BOOL", 3)]
            .into_iter()
            .find_map(|(p, k)| name.strip_prefix(p).map(|r| (k, r)))?;
        let n = match rest {
            "" => 1,
            "_VEC2" => 2,
            "_VEC3" => 3,
            "_VEC4" => 4,
            "_MAT2" if base == 0 => return Some(UniformType::Mat2),
            "_MAT3" if base == 0 => return Some(UniformType::Mat3),
            "_MAT4" if base == 0 => return Some(UniformType::Mat4),
            _ => return None,
        };
        Some(match base {
            0 => UniformType::Float(n),
            1 => UniformType::Int(n),
            2 => UniformType::Uint(n),
            _ => UniformType::Bool(n),
        })
    }

    /// The WebGL enum name (`FLOAT_VEC3`); samplers give `SAMPLER`.
    pub fn gl_name(self) -> String {
        let vec = |base: &str, n: u8| {
            if n == 1 {
                base.to_string()
            } else {
                format!("{base}_VEC{n}")
            }
        };
        match self {
            UniformType::Float(n) => vec("FLOAT", n),
            UniformType::Int(n) => vec("INT", n),
            UniformType::Uint(n) => vec("UNSIGNED_INT", n),
            UniformType::Bool(n) => vec("BOOL", n),
            UniformType::Mat2 => "FLOAT_MAT2".into(),
            UniformType::Mat3 => "FLOAT_MAT3".into(),
            UniformType::Mat4 => "FLOAT_MAT4".into(),
            UniformType::Sampler => "SAMPLER".into(),
        }
    }

    /// Values per element: 1–4 for scalars and vectors, 4, 9, 16 for matrices, 0 for samplers.
    pub fn components(self) -> usize {
        match self {
            UniformType::Float(n)
            | UniformType::Int(n)
            | UniformType::Uint(n)
            | UniformType::Bool(n) => n as usize,
            UniformType::Mat2 => 4,
            UniformType::Mat3 => 9,
            UniformType::Mat4 => 16,
            UniformType::Sampler => 0,
        }
    }
}

/// The typed array a uniform call receives.
#[derive(Clone, Debug, PartialEq)]
pub enum UploadValues {
    /// `Float32Array`: `uniform{1..4}fv` or `uniformMatrix{2,3,4}fv(loc, false, …)`.
    F32(Vec<f32>),
    /// `Int32Array`: `uniform{1..4}iv` (ints and bools).
    I32(Vec<i32>),
    /// `Uint32Array`: `uniform{1..4}uiv`.
    U32(Vec<u32>),
}

impl UploadValues {
    /// The values as float64 (exact for every variant), e.g. to compare with a dump.
    pub fn to_f64(&self) -> Vec<f64> {
        match self {
            UploadValues::F32(v) => v.iter().map(|&x| f64::from(x)).collect(),
            UploadValues::I32(v) => v.iter().map(|&x| f64::from(x)).collect(),
            UploadValues::U32(v) => v.iter().map(|&x| f64::from(x)).collect(),
        }
    }
}

/// JavaScript's `ToUint32` of an integral float64 (what a `Uint32Array` stores).
fn to_uint32(v: f64) -> u32 {
    v.rem_euclid(4_294_967_296.0) as u32
}

impl Resolved {
    /// Fits the values to an active uniform of type `ty` and `array_size` elements, as the tool's
    /// page does: a matrix goes whole to a `mat4` and its upper-left 3×3 to a `mat3` (anything
    /// else is an error); the count must be `components × array_size`; integer types need
    /// integral values and store them as `Int32Array`/`Uint32Array` do (modulo 2³²); float types
    /// round each value once to `f32`. `name` is the uniform's, for errors.
    pub fn upload(
        &self,
        name: &str,
        ty: UniformType,
        array_size: usize,
    ) -> Result<UploadValues, SceneError> {
        let err = |message: String| SceneError::UniformType {
            name: name.to_string(),
            message,
        };
        if ty == UniformType::Sampler {
            return Err(err("is a sampler: give it in \"textures\"".into()));
        }
        let values: Vec<f64> = match self {
            Resolved::Values(v) => v.clone(),
            Resolved::Matrix(m) => match ty {
                UniformType::Mat4 => m.0.to_vec(),
                UniformType::Mat3 => upper_left_3x3(&m.0).to_vec(),
                _ => return Err(err(format!("a 4x4 matrix cannot set a {}", ty.gl_name()))),
            },
        };
        let want = ty.components() * array_size;
        if values.len() != want {
            let arr = if array_size > 1 {
                format!("[{array_size}]")
            } else {
                String::new()
            };
            return Err(err(format!(
                "is {}{arr} ({want} values) but the scene gives {}",
                ty.gl_name(),
                values.len()
            )));
        }
        let integral = || {
            if values.iter().all(|v| v.fract() == 0.0) {
                Ok(())
            } else {
                Err(err(format!("is {}: give integers", ty.gl_name())))
            }
        };
        Ok(match ty {
            UniformType::Int(_) | UniformType::Bool(_) => {
                integral()?;
                UploadValues::I32(values.iter().map(|&v| to_uint32(v) as i32).collect())
            }
            UniformType::Uint(_) => {
                integral()?;
                UploadValues::U32(values.iter().map(|&v| to_uint32(v)).collect())
            }
            _ => UploadValues::F32(values.iter().map(|&v| v as f32).collect()),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(s: &str) -> Result<UniformValue, serde_json::Error> {
        serde_json::from_str(s)
    }

    #[test]
    fn forms() {
        assert_eq!(parse("3").unwrap(), UniformValue::Numbers(vec![3.0]));
        assert_eq!(
            parse("[1, true, 0.5]").unwrap(),
            UniformValue::Numbers(vec![1.0, 1.0, 0.5])
        );
        assert_eq!(parse("false").unwrap(), UniformValue::Bool(false));
        assert_eq!(
            parse("\"normal_matrix\"").unwrap(),
            UniformValue::Derived(Derived::NormalMatrix)
        );
        assert_eq!(
            parse("{\"cos_deg\": 10}").unwrap(),
            UniformValue::CosDeg(10.0)
        );
        assert_eq!(
            parse("{\"normalize\": [0, -2, 0]}").unwrap(),
            UniformValue::Normalize(vec![0.0, -2.0, 0.0])
        );
    }

    #[test]
    fn bad_forms() {
        for bad in [
            "\"modelview\"",
            "{\"cos\": 1}",
            "{\"cos_deg\": 1, \"normalize\": [1]}",
            "{}",
            "[1, \"x\"]",
            "null",
            "{\"cos_deg\": true}",
            "{\"normalize\": 3}",
        ] {
            assert!(parse(bad).is_err(), "{bad} parsed");
        }
        let msg = parse("\"modelview\"").unwrap_err().to_string();
        assert!(msg.contains("known: model"), "{msg}");
    }

    #[test]
    fn type_names() {
        for (gl, glsl) in [
            ("FLOAT", "float"),
            ("FLOAT_VEC3", "vec3"),
            ("INT_VEC2", "ivec2"),
            ("UNSIGNED_INT", "uint"),
            ("UNSIGNED_INT_VEC4", "uvec4"),
            ("BOOL_VEC3", "bvec3"),
            ("FLOAT_MAT3", "mat3"),
            ("FLOAT_MAT4", "mat4"),
            ("SAMPLER_2D", "sampler2D"),
        ] {
            let t = UniformType::from_gl_name(gl).unwrap();
            assert_eq!(UniformType::from_glsl(glsl), Some(t), "{glsl}");
            if t != UniformType::Sampler {
                assert_eq!(t.gl_name(), gl);
            }
        }
        assert_eq!(UniformType::from_gl_name("INT_MAT3"), None);
        assert_eq!(UniformType::from_glsl("vec5"), None);
    }

    #[test]
    fn upload_fits_types() {
        let m = Resolved::Matrix(Mat4(std::array::from_fn(|i| i as f64)));
        assert_eq!(
            m.upload("m", UniformType::Mat3, 1).unwrap(),
            UploadValues::F32(vec![0.0, 1.0, 2.0, 4.0, 5.0, 6.0, 8.0, 9.0, 10.0])
        );
        assert!(m.upload("m", UniformType::Mat2, 1).is_err());
        assert!(m.upload("m", UniformType::Float(4), 4).is_err());
        let v = Resolved::Values(vec![1.0, -1.0, 4294967297.0]);
        assert_eq!(
            v.upload("v", UniformType::Int(3), 1).unwrap(),
            UploadValues::I32(vec![1, -1, 1])
        );
        assert_eq!(
            v.upload("v", UniformType::Uint(3), 1).unwrap(),
            UploadValues::U32(vec![1, u32::MAX, 1])
        );
        assert!(v.upload("v", UniformType::Int(2), 1).is_err());
        assert!(Resolved::Values(vec![0.5])
            .upload("v", UniformType::Int(1), 1)
            .is_err());
        assert_eq!(
            Resolved::Values(vec![0.1, 0.2])
                .upload("v", UniformType::Float(1), 2)
                .unwrap(),
            UploadValues::F32(vec![0.1, 0.2])
        );
        assert!(v.upload("v", UniformType::Sampler, 1).is_err());
    }
}
