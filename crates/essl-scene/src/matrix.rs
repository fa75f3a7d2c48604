//! float64 vector and matrix maths in FORMAT.md's exact order of operations: `dot`, `cross`,
//! `normalize`, `radians`, `cos_deg`, column-major [`Mat4`] products, the model, look-at view and
//! perspective matrices, gl-matrix's cofactor inverse, and the derived-value table ([`Derived`]).
//!
//! Every function evaluates its expression left to right exactly as FORMAT.md (and
//! `webgl2-render.py`) writes it, so rounding each result to `f32` once gives the very bits the
//! tool uploads. Sums start from `0.0`, which also fixes the signs of zeros.

use std::f64::consts::PI;
use std::fmt;

use crate::error::SceneError;

/// `radians(d) = (d * π) / 180`.
pub fn radians(deg: f64) -> f64 {
    deg * PI / 180.0
}

/// `cos(radians(d))`, the value of a `{"cos_deg": d}` uniform.
pub fn cos_deg(deg: f64) -> f64 {
    radians(deg).cos()
}

/// `dot(a, b) = ((0 + a0·b0) + a1·b1) + …`, over the shorter of the two lengths.
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut s = 0.0;
    for (x, y) in a.iter().zip(b) {
        s += x * y;
    }
    s
}

/// `cross(a, b) = (a1·b2 − a2·b1, a2·b0 − a0·b2, a0·b1 − a1·b0)`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `normalize(v) = (v0 / L, v1 / L, …)` with `L = sqrt(dot(v, v))`, any length;
/// [`SceneError::ZeroVector`] (naming `what`) when `L == 0` (an empty `v` included).
pub fn normalize(v: &[f64], what: &str) -> Result<Vec<f64>, SceneError> {
    let length = dot(v, v).sqrt();
    if length == 0.0 {
        return Err(SceneError::ZeroVector {
            what: what.to_string(),
        });
    }
    Ok(v.iter().map(|x| x / length).collect())
}

/// [`normalize`] for a 3-vector.
pub fn normalize3(v: [f64; 3], what: &str) -> Result<[f64; 3], SceneError> {
    let n = normalize(&v, what)?;
    Ok([n[0], n[1], n[2]])
}

/// A 4×4 float64 matrix, column-major: element (row `r`, column `c`) at index `c*4 + r`, i.e.
/// the array given to `uniformMatrix4fv(loc, false, m)`.
#[derive(Clone, Copy, PartialEq)]
pub struct Mat4(pub [f64; 16]);

impl fmt::Debug for Mat4 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Mat4{:?}", self.0)
    }
}

impl Default for Mat4 {
    fn default() -> Self {
        Mat4::IDENTITY
    }
}

impl Mat4 {
    /// The identity.
    pub const IDENTITY: Mat4 = Mat4([
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);

    /// Element (row `r`, column `c`).
    pub fn get(&self, r: usize, c: usize) -> f64 {
        self.0[c * 4 + r]
    }

    /// `(self · b)[r, c] = Σ_{k=0..3} self[r, k] · b[k, c]`, summed from `0.0` in order k = 0..3.
    pub fn mul(&self, b: &Mat4) -> Mat4 {
        let a = &self.0;
        let b = &b.0;
        let mut out = [0.0; 16];
        for c in 0..4 {
            for r in 0..4 {
                let mut s = 0.0;
                for k in 0..4 {
                    s += a[k * 4 + r] * b[c * 4 + k];
                }
                out[c * 4 + r] = s;
            }
        }
        Mat4(out)
    }

    /// The transpose.
    pub fn transpose(&self) -> Mat4 {
        let mut out = [0.0; 16];
        for c in 0..4 {
            for r in 0..4 {
                out[c * 4 + r] = self.0[r * 4 + c];
            }
        }
        Mat4(out)
    }

    /// The inverse by the cofactor formulas of gl-matrix's `mat4.invert` (the tool's `inverse`),
    /// term by term in the same order; [`SceneError::Singular`] (naming `what`) when the
    /// determinant is exactly 0.
    pub fn inverse(&self, what: &str) -> Result<Mat4, SceneError> {
        // aRC is the element at index R*4 + C (column R, row C), as in gl-matrix.
        let [a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33] =
            self.0;
        let b00 = a00 * a11 - a01 * a10;
        let b01 = a00 * a12 - a02 * a10;
        let b02 = a00 * a13 - a03 * a10;
        let b03 = a01 * a12 - a02 * a11;
        let b04 = a01 * a13 - a03 * a11;
        let b05 = a02 * a13 - a03 * a12;
        let b06 = a20 * a31 - a21 * a30;
        let b07 = a20 * a32 - a22 * a30;
        let b08 = a20 * a33 - a23 * a30;
        let b09 = a21 * a32 - a22 * a31;
        let b10 = a21 * a33 - a23 * a31;
        let b11 = a22 * a33 - a23 * a32;
        let det = b00 * b11 - b01 * b10 + b02 * b09 + b03 * b08 - b04 * b07 + b05 * b06;
        if det == 0.0 {
            return Err(SceneError::Singular {
                what: what.to_string(),
            });
        }
        let d = 1.0 / det;
        Ok(Mat4([
            (a11 * b11 - a12 * b10 + a13 * b09) * d,
            (a02 * b10 - a01 * b11 - a03 * b09) * d,
            (a31 * b05 - a32 * b04 + a33 * b03) * d,
            (a22 * b04 - a21 * b05 - a23 * b03) * d,
            (a12 * b08 - a10 * b11 - a13 * b07) * d,
            (a00 * b11 - a02 * b08 + a03 * b07) * d,
            (a32 * b02 - a30 * b05 - a33 * b01) * d,
            (a20 * b05 - a22 * b02 + a23 * b01) * d,
            (a10 * b10 - a11 * b08 + a13 * b06) * d,
            (a01 * b08 - a00 * b10 - a03 * b06) * d,
            (a30 * b04 - a31 * b02 + a33 * b00) * d,
            (a21 * b02 - a20 * b04 - a23 * b00) * d,
            (a11 * b07 - a10 * b09 - a12 * b06) * d,
            (a00 * b09 - a01 * b07 + a02 * b06) * d,
            (a31 * b01 - a30 * b03 - a32 * b00) * d,
            (a20 * b03 - a21 * b01 + a22 * b00) * d,
        ]))
    }

    /// Each element rounded once to `f32` (round to nearest, ties to even): what is uploaded.
    pub fn as_f32(&self) -> [f32; 16] {
        self.0.map(|x| x as f32)
    }

    /// The upper-left 3×3, column-major (indices 0,1,2, 4,5,6, 8,9,10): what a `mat3` uniform
    /// bound to this matrix receives.
    pub fn upper_left_3x3(&self) -> [f64; 9] {
        upper_left_3x3(&self.0)
    }

    /// `T = [1,0,0,0, 0,1,0,0, 0,0,1,0, tx,ty,tz,1]`.
    pub fn translation(t: [f64; 3]) -> Mat4 {
        let mut m = Mat4::IDENTITY;
        m.0[12] = t[0];
        m.0[13] = t[1];
        m.0[14] = t[2];
        m
    }

    /// `S = [sx,0,0,0, 0,sy,0,0, 0,0,sz,0, 0,0,0,1]`.
    pub fn scale(s: [f64; 3]) -> Mat4 {
        let mut m = Mat4::IDENTITY;
        m.0[0] = s[0];
        m.0[5] = s[1];
        m.0[10] = s[2];
        m
    }

    /// The rotation about axis 0 (X), 1 (Y) or 2 (Z, and anything else) by `deg` degrees,
    /// as FORMAT.md's `Rx`, `Ry`, `Rz` with `c = cos(radians(deg))`, `s = sin(radians(deg))`.
    pub fn rotation(axis: usize, deg: f64) -> Mat4 {
        let (c, s) = (radians(deg).cos(), radians(deg).sin());
        Mat4(match axis {
            0 => [
                1.0, 0.0, 0.0, 0.0, 0.0, c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0,
            ],
            1 => [
                c, 0.0, -s, 0.0, 0.0, 1.0, 0.0, 0.0, s, 0.0, c, 0.0, 0.0, 0.0, 0.0, 1.0,
            ],
            _ => [
                c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
            ],
        })
    }

    /// `model = (((T · Rz) · Ry) · Rx) · S`: scale, rotate about X, then Y, then Z, translate.
    pub fn model(translate: [f64; 3], rotate_deg: [f64; 3], scale: [f64; 3]) -> Mat4 {
        Mat4::translation(translate)
            .mul(&Mat4::rotation(2, rotate_deg[2]))
            .mul(&Mat4::rotation(1, rotate_deg[1]))
            .mul(&Mat4::rotation(0, rotate_deg[0]))
            .mul(&Mat4::scale(scale))
    }

    /// The right-handed look-at view: `z = normalize(eye − target)`,
    /// `x = normalize(cross(up, z))`, `y = cross(z, x)` (not re-normalised),
    /// `[x0,y0,z0,0, x1,y1,z1,0, x2,y2,z2,0, -dot(x,eye),-dot(y,eye),-dot(z,eye),1]`.
    pub fn look_at(eye: [f64; 3], target: [f64; 3], up: [f64; 3]) -> Result<Mat4, SceneError> {
        let z = normalize3(
            [eye[0] - target[0], eye[1] - target[1], eye[2] - target[2]],
            "camera eye - target",
        )?;
        let x = normalize3(
            cross(up, z),
            "camera: cross(up, eye - target) (up parallel to the view direction?)",
        )?;
        let y = cross(z, x);
        Ok(Mat4([
            x[0],
            y[0],
            z[0],
            0.0,
            x[1],
            y[1],
            z[1],
            0.0,
            x[2],
            y[2],
            z[2],
            0.0,
            -dot(&x, &eye),
            -dot(&y, &eye),
            -dot(&z, &eye),
            1.0,
        ]))
    }

    /// The OpenGL perspective: `f = 1.0 / tan(radians(fov_y_deg) / 2.0)`,
    /// `[f/aspect,0,0,0, 0,f,0,0, 0,0,(near+far)/(near-far),-1, 0,0,((2·near)·far)/(near-far),0]`.
    pub fn perspective(fov_y_deg: f64, aspect: f64, near: f64, far: f64) -> Mat4 {
        let f = 1.0 / (radians(fov_y_deg) / 2.0).tan();
        Mat4([
            f / aspect,
            0.0,
            0.0,
            0.0,
            0.0,
            f,
            0.0,
            0.0,
            0.0,
            0.0,
            (near + far) / (near - far),
            -1.0,
            0.0,
            0.0,
            2.0 * near * far / (near - far),
            0.0,
        ])
    }
}

/// The upper-left 3×3 of a column-major 4×4 (indices 0,1,2, 4,5,6, 8,9,10), column-major:
/// what a `mat3` uniform receives from a matrix-valued derived name.
pub fn upper_left_3x3<T: Copy>(m: &[T; 16]) -> [T; 9] {
    [m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]]
}

/// A name of FORMAT.md's derived-value table, usable as a uniform's value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Derived {
    /// `model`.
    Model,
    /// `view`.
    View,
    /// `projection`.
    Projection,
    /// `projection · view`.
    ViewProjection,
    /// `view · model`.
    ModelView,
    /// `(projection · view) · model`.
    ModelViewProjection,
    /// `transpose(inverse(model))`.
    ModelInverseTranspose,
    /// `transpose(inverse(view · model))`.
    NormalMatrix,
    /// `camera.eye` (vec3).
    Eye,
    /// `(width, height)` (vec2).
    Viewport,
}

impl Derived {
    /// Every derived name, in FORMAT.md's table order.
    pub const ALL: [Derived; 10] = [
        Derived::Model,
        Derived::View,
        Derived::Projection,
        Derived::ViewProjection,
        Derived::ModelView,
        Derived::ModelViewProjection,
        Derived::ModelInverseTranspose,
        Derived::NormalMatrix,
        Derived::Eye,
        Derived::Viewport,
    ];

    /// The name as written in a scene (`"model_view_projection"`).
    pub fn name(self) -> &'static str {
        match self {
            Derived::Model => "model",
            Derived::View => "view",
            Derived::Projection => "projection",
            Derived::ViewProjection => "view_projection",
            Derived::ModelView => "model_view",
            Derived::ModelViewProjection => "model_view_projection",
            Derived::ModelInverseTranspose => "model_inverse_transpose",
            Derived::NormalMatrix => "normal_matrix",
            Derived::Eye => "eye",
            Derived::Viewport => "viewport",
        }
    }

    /// The derived value of that name, if it is one.
    pub fn from_name(name: &str) -> Option<Derived> {
        Derived::ALL.into_iter().find(|d| d.name() == name)
    }
}

impl fmt::Display for Derived {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A derived value: a 4×4 matrix, or a vector (`eye`, `viewport`).
#[derive(Clone, Debug, PartialEq)]
pub enum DerivedValue {
    /// One of the matrices.
    Matrix(Mat4),
    /// `eye` (3 values) or `viewport` (2).
    Vector(Vec<f64>),
}

/// The matrices of a scene: the three it is built from and the products that follow, computed
/// once; the inverse transposes are computed on demand since they can fail (a singular model).
#[derive(Clone, Debug, PartialEq)]
pub struct Matrices {
    /// `(((T · Rz) · Ry) · Rx) · S`.
    pub model: Mat4,
    /// The look-at view.
    pub view: Mat4,
    /// The perspective projection.
    pub projection: Mat4,
    /// `projection · view`.
    pub view_projection: Mat4,
    /// `view · model`.
    pub model_view: Mat4,
    /// `(projection · view) · model`.
    pub model_view_projection: Mat4,
    /// `camera.eye`.
    pub eye: [f64; 3],
    /// `(width, height)` as float64.
    pub viewport: [f64; 2],
}

impl Matrices {
    /// Computes the matrices of a camera, model transform and canvas size; fails only when the
    /// look-at has a zero vector to normalize.
    pub fn new(
        camera: &crate::format::Camera,
        model: &crate::format::Model,
        width: u32,
        height: u32,
    ) -> Result<Matrices, SceneError> {
        let model = Mat4::model(model.translate, model.rotate_deg, model.scale);
        let view = Mat4::look_at(camera.eye, camera.target, camera.up)?;
        let aspect = f64::from(width) / f64::from(height);
        let projection = Mat4::perspective(camera.fov_y_deg, aspect, camera.near, camera.far);
        let view_projection = projection.mul(&view);
        Ok(Matrices {
            model,
            view,
            projection,
            view_projection,
            model_view: view.mul(&model),
            model_view_projection: view_projection.mul(&model),
            eye: camera.eye,
            viewport: [f64::from(width), f64::from(height)],
        })
    }

    /// `transpose(inverse(model))`.
    pub fn model_inverse_transpose(&self) -> Result<Mat4, SceneError> {
        Ok(self.model.inverse("model_inverse_transpose")?.transpose())
    }

    /// `transpose(inverse(view · model))`.
    pub fn normal_matrix(&self) -> Result<Mat4, SceneError> {
        Ok(self.model_view.inverse("normal_matrix")?.transpose())
    }

    /// The value of a derived name.
    pub fn derived(&self, d: Derived) -> Result<DerivedValue, SceneError> {
        Ok(DerivedValue::Matrix(match d {
            Derived::Model => self.model,
            Derived::View => self.view,
            Derived::Projection => self.projection,
            Derived::ViewProjection => self.view_projection,
            Derived::ModelView => self.model_view,
            Derived::ModelViewProjection => self.model_view_projection,
            Derived::ModelInverseTranspose => self.model_inverse_transpose()?,
            Derived::NormalMatrix => self.normal_matrix()?,
            Derived::Eye => return Ok(DerivedValue::Vector(self.eye.to_vec())),
            Derived::Viewport => return Ok(DerivedValue::Vector(self.viewport.to_vec())),
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_model_is_exactly_identity() {
        let m = Mat4::model([0.0; 3], [0.0; 3], [1.0; 3]);
        assert_eq!(m.0.map(f64::to_bits), Mat4::IDENTITY.0.map(f64::to_bits));
    }

    #[test]
    fn inverse_of_affine_round_trips() {
        let m = Mat4::model([1.0, -2.0, 3.0], [10.0, 20.0, 30.0], [2.0, 0.5, 1.5]);
        let p = m.mul(&m.inverse("m").unwrap());
        for (i, v) in p.0.iter().enumerate() {
            let want = if i % 5 == 0 { 1.0 } else { 0.0 };
            assert!((v - want).abs() < 1e-12, "{i}: {v}");
        }
    }

    #[test]
    fn singular_inverse_is_an_error() {
        let m = Mat4::scale([1.0, 0.0, 1.0]);
        assert!(matches!(
            m.inverse("model_inverse_transpose"),
            Err(SceneError::Singular { .. })
        ));
    }

    #[test]
    fn zero_length_normalize_is_an_error() {
        assert!(matches!(
            normalize(&[0.0, 0.0, 0.0], "x"),
            Err(SceneError::ZeroVector { .. })
        ));
        assert!(matches!(
            normalize(&[], "x"),
            Err(SceneError::ZeroVector { .. })
        ));
        assert_eq!(normalize(&[3.0, 4.0], "x").unwrap(), vec![0.6, 0.8]);
    }

    #[test]
    fn upper_left_takes_columns() {
        let m = Mat4(std::array::from_fn(|i| i as f64));
        assert_eq!(
            m.upper_left_3x3(),
            [0.0, 1.0, 2.0, 4.0, 5.0, 6.0, 8.0, 9.0, 10.0]
        );
        assert_eq!(m.get(1, 2), 9.0);
    }

    #[test]
    fn derived_names_round_trip() {
        for d in Derived::ALL {
            assert_eq!(Derived::from_name(d.name()), Some(d));
        }
        assert_eq!(Derived::from_name("normal"), None);
    }
}
