//! Uniform values: what a renderer sets for a scene seen from a view, by the names of
//! [`crate::names`], in float64 (rounded to float32 once, on upload), plus the cookie textures
//! bound to the samplers.

use glam::DVec3;

use essl_scene::{Mat4, Matrices, Scene};

use crate::error::LightsError;
use crate::names;
use crate::program::GlslType;
use crate::scene::{
    CookieImage, CookieKind, Light, LightShape, LitScene, PreparedScene, Reflection,
};
use crate::uber::UBER_MAX_LIGHTS;

/// The camera and canvas a scene is drawn with.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// The scene's matrices (model, view, projection and products; float64).
    pub matrices: Matrices,
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
}

impl View {
    /// The view of a loaded scene file (its camera, model transform and canvas).
    pub fn of_scene(scene: &Scene) -> View {
        View {
            matrices: scene.matrices.clone(),
            width: scene.width(),
            height: scene.height(),
        }
    }

    /// `transpose(inverse(model))`'s upper-left 3×3, column-major: normals to world space.
    pub fn normal_matrix(&self) -> Result<[f64; 9], LightsError> {
        let m = self
            .matrices
            .model
            .inverse("normal matrix")
            .map_err(|e| LightsError::View(format!("the model matrix is singular ({e})")))?;
        Ok(m.transpose().upper_left_3x3())
    }

    /// `(1 / width, 1 / height)`.
    pub fn inv_viewport(&self) -> Result<[f64; 2], LightsError> {
        inv_viewport(f64::from(self.width), f64::from(self.height))
    }
}

/// `(1 / width, 1 / height)`; an error unless both are at least 1 (a screen-space cookie would
/// divide by zero).
pub fn inv_viewport(width: f64, height: f64) -> Result<[f64; 2], LightsError> {
    if !(width >= 1.0 && height >= 1.0) {
        return Err(LightsError::View(format!(
            "the viewport is {width}x{height}: a screen-space cookie needs both sides at least 1"
        )));
    }
    Ok([1.0 / width, 1.0 / height])
}

/// A uniform's value.
#[derive(Clone, Debug, PartialEq)]
pub enum UniformData {
    /// `float`, `vecN` and matrices (column-major), arrays flattened.
    Floats(Vec<f64>),
    /// `int`, arrays flattened.
    Ints(Vec<i32>),
    /// A sampler: the texture unit it reads.
    Sampler(u32),
}

impl UniformData {
    /// The values as float32, as uploaded (`None` for samplers and ints).
    pub fn as_f32(&self) -> Option<Vec<f32>> {
        match self {
            UniformData::Floats(v) => Some(v.iter().map(|&x| x as f32).collect()),
            _ => None,
        }
    }
}

/// One uniform to set.
#[derive(Clone, Debug, PartialEq)]
pub struct UniformSetting {
    /// The name (without `[0]`).
    pub name: String,
    /// The declared type.
    pub ty: GlslType,
    /// The value.
    pub data: UniformData,
}

/// A texture bound to a sampler uniform.
#[derive(Clone, Debug, PartialEq)]
pub struct CookieBinding {
    /// The sampler uniform's name.
    pub sampler: String,
    /// The texture unit (units follow the sorted order of the sampler names, as in the scene
    /// format).
    pub unit: u32,
    /// The image.
    pub image: CookieImage,
}

/// Everything to set before drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Uniforms {
    /// Value uniforms and samplers, in a fixed order.
    pub values: Vec<UniformSetting>,
    /// The textures for the samplers.
    pub cookies: Vec<CookieBinding>,
}

impl Uniforms {
    /// The setting of that name.
    pub fn get(&self, name: &str) -> Option<&UniformSetting> {
        self.values.iter().find(|u| u.name == name)
    }

    /// The float values of that name (panics if absent or not floats; for tests and the CPU
    /// mirrors).
    pub fn floats(&self, name: &str) -> &[f64] {
        match self.get(name).map(|u| &u.data) {
            Some(UniformData::Floats(v)) => v,
            other => panic!("uniform {name}: expected floats, got {other:?}"),
        }
    }

    fn push_f(&mut self, name: impl Into<String>, ty: GlslType, v: Vec<f64>) {
        self.values.push(UniformSetting {
            name: name.into(),
            ty,
            data: UniformData::Floats(v),
        });
    }

    fn push_i(&mut self, name: impl Into<String>, v: Vec<i32>) {
        self.values.push(UniformSetting {
            name: name.into(),
            ty: GlslType::Int,
            data: UniformData::Ints(v),
        });
    }

    fn bind(&mut self, sampler: String, image: CookieImage) {
        self.cookies.push(CookieBinding {
            sampler,
            unit: 0,
            image,
        });
    }

    /// Assigns units in the sorted order of the sampler names and adds the sampler settings.
    fn assign_units(&mut self) {
        let mut names: Vec<String> = self.cookies.iter().map(|c| c.sampler.clone()).collect();
        names.sort();
        for c in &mut self.cookies {
            c.unit = names.iter().position(|n| *n == c.sampler).unwrap_or(0) as u32;
        }
        for c in self.cookies.clone() {
            self.values.push(UniformSetting {
                name: c.sampler,
                ty: GlslType::Sampler2D,
                data: UniformData::Sampler(c.unit),
            });
        }
    }
}

fn v3(v: DVec3) -> Vec<f64> {
    v.to_array().to_vec()
}

fn mat4(m: &Mat4) -> Vec<f64> {
    m.0.to_vec()
}

fn mat3_cols(c: &[DVec3; 3]) -> Vec<f64> {
    c.iter().flat_map(|v| v.to_array()).collect()
}

/// The uniforms of the specialised program of `scene` drawn from `view`: exactly the uniforms
/// [`crate::generate`] declares for the scene's shape.
pub fn uniform_values(scene: &LitScene, view: &View) -> Result<Uniforms, LightsError> {
    let prepared = scene.prepare()?;
    let shape = &prepared.shape;
    let mut u = Uniforms {
        values: Vec::new(),
        cookies: Vec::new(),
    };
    let lit = !shape.lights.is_empty();
    let needs_view = shape.needs_view();
    u.push_f(
        names::MODEL_VIEW_PROJECTION,
        GlslType::Mat4,
        mat4(&view.matrices.model_view_projection),
    );
    if shape.needs_position() || needs_view {
        u.push_f(names::MODEL, GlslType::Mat4, mat4(&view.matrices.model));
    }
    if lit {
        u.push_f(
            names::NORMAL_MATRIX,
            GlslType::Mat3,
            view.normal_matrix()?.to_vec(),
        );
    }
    if needs_view {
        u.push_f(names::EYE, GlslType::Vec3, view.matrices.eye.to_vec());
        u.push_f(
            names::SHININESS,
            GlslType::Float,
            vec![scene.material.shininess],
        );
    }
    if shape.has_screen_cookie() {
        u.push_f(
            names::INV_VIEWPORT,
            GlslType::Vec2,
            view.inv_viewport()?.to_vec(),
        );
    }
    if let Some(a) = scene.ambient_light {
        u.push_f(
            names::AMBIENT,
            GlslType::Vec3,
            v3(a * scene.material.ambient),
        );
    }
    for (i, (light, p)) in scene.lights.iter().zip(&prepared.lights).enumerate() {
        u.push_f(
            names::light(i, "diffuse"),
            GlslType::Vec3,
            v3(p.color * scene.material.diffuse),
        );
        if scene.reflection != Reflection::Lambert {
            u.push_f(
                names::light(i, "specular"),
                GlslType::Vec3,
                v3(p.specular * scene.material.specular),
            );
        }
        match p.shape {
            LightShape::Directional => {
                u.push_f(
                    names::light(i, "direction"),
                    GlslType::Vec3,
                    v3(p.direction),
                );
            }
            LightShape::Point => {
                u.push_f(names::light(i, "position"), GlslType::Vec3, v3(p.position));
            }
            LightShape::Spot { edge, cookie } => {
                u.push_f(names::light(i, "position"), GlslType::Vec3, v3(p.position));
                u.push_f(
                    names::light(i, "cosOuter"),
                    GlslType::Float,
                    vec![p.cos_outer],
                );
                if edge != crate::EdgeProfile::Step {
                    u.push_f(
                        names::light(i, "invRange"),
                        GlslType::Float,
                        vec![p.inv_range],
                    );
                }
                if cookie == Some(CookieKind::Projected) {
                    u.push_f(
                        names::light(i, "basis"),
                        GlslType::Mat3,
                        mat3_cols(&p.basis),
                    );
                    u.push_f(
                        names::light(i, "cookieScale"),
                        GlslType::Float,
                        vec![p.cookie_scale],
                    );
                } else {
                    u.push_f(
                        names::light(i, "direction"),
                        GlslType::Vec3,
                        v3(p.direction),
                    );
                }
                if let Light::Spot(s) = light {
                    if let Some(c) = &s.cookie {
                        u.bind(names::light(i, "cookie"), c.image().clone());
                    }
                }
            }
        }
    }
    u.assign_units();
    Ok(u)
}

/// The uniforms of the uber-shader ([`crate::uber::generate_uber`]) for `scene` drawn from
/// `view`. Fails for more than [`UBER_MAX_LIGHTS`] lights.
pub fn uber_uniform_values(scene: &LitScene, view: &View) -> Result<Uniforms, LightsError> {
    let prepared: PreparedScene = scene.prepare()?;
    if scene.lights.len() > UBER_MAX_LIGHTS {
        return Err(LightsError::TooManyLights {
            count: scene.lights.len(),
            max: UBER_MAX_LIGHTS,
        });
    }
    let n = UBER_MAX_LIGHTS;
    let mut u = Uniforms {
        values: Vec::new(),
        cookies: Vec::new(),
    };
    let m = &view.matrices;
    u.push_f(
        names::MODEL_VIEW_PROJECTION,
        GlslType::Mat4,
        mat4(&m.model_view_projection),
    );
    u.push_f(names::MODEL, GlslType::Mat4, mat4(&m.model));
    u.push_f(
        names::NORMAL_MATRIX,
        GlslType::Mat3,
        view.normal_matrix()?.to_vec(),
    );
    u.push_f(names::EYE, GlslType::Vec3, m.eye.to_vec());
    let inv = if prepared.shape.has_screen_cookie() {
        view.inv_viewport()?
    } else {
        view.inv_viewport().unwrap_or([0.0, 0.0])
    };
    u.push_f(names::INV_VIEWPORT, GlslType::Vec2, inv.to_vec());
    u.push_i(
        "u_shading",
        vec![match scene.shading {
            crate::Shading::Gouraud => 0,
            crate::Shading::Phong => 1,
        }],
    );
    u.push_i(
        "u_reflection",
        vec![match scene.reflection {
            Reflection::Lambert => 0,
            Reflection::Phong => 1,
            Reflection::BlinnPhong => 2,
        }],
    );
    let ambient = scene
        .ambient_light
        .map(|a| a * scene.material.ambient)
        .unwrap_or(DVec3::ZERO);
    u.push_f(names::AMBIENT, GlslType::Vec3, v3(ambient));
    u.push_f(
        names::SHININESS,
        GlslType::Float,
        vec![scene.material.shininess],
    );
    u.push_i("u_lightCount", vec![scene.lights.len() as i32]);
    let mut kind = vec![0; n];
    let mut edge = vec![0; n];
    let mut cookie = vec![0; n];
    let (mut diffuse, mut specular, mut position, mut direction) = (
        vec![0.0; 3 * n],
        vec![0.0; 3 * n],
        vec![0.0; 3 * n],
        vec![0.0; 3 * n],
    );
    let (mut cos_outer, mut inv_range, mut scale) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut basis = vec![0.0; 9 * n];
    for (i, (light, p)) in scene.lights.iter().zip(&prepared.lights).enumerate() {
        diffuse[3 * i..3 * i + 3].copy_from_slice(&(p.color * scene.material.diffuse).to_array());
        specular[3 * i..3 * i + 3]
            .copy_from_slice(&(p.specular * scene.material.specular).to_array());
        position[3 * i..3 * i + 3].copy_from_slice(&p.position.to_array());
        direction[3 * i..3 * i + 3].copy_from_slice(&p.direction.to_array());
        cos_outer[i] = p.cos_outer;
        inv_range[i] = p.inv_range;
        scale[i] = p.cookie_scale;
        basis[9 * i..9 * i + 9].copy_from_slice(&mat3_cols(&p.basis));
        match p.shape {
            LightShape::Directional => kind[i] = 0,
            LightShape::Point => kind[i] = 1,
            LightShape::Spot { edge: e, cookie: c } => {
                kind[i] = 2;
                edge[i] = match e {
                    crate::EdgeProfile::Step => 0,
                    crate::EdgeProfile::Linear => 1,
                    crate::EdgeProfile::Smooth => 2,
                };
                cookie[i] = match c {
                    None => 0,
                    Some(CookieKind::Projected) => 1,
                    Some(CookieKind::Screen) => 2,
                };
            }
        }
        if let Light::Spot(s) = light {
            if let Some(c) = &s.cookie {
                u.bind(names::uber_cookie(i), c.image().clone());
            }
        }
    }
    u.push_i("u_lightKind", kind);
    u.push_i("u_lightEdge", edge);
    u.push_i("u_lightCookieKind", cookie);
    u.push_f("u_lightDiffuse", GlslType::Vec3, diffuse);
    u.push_f("u_lightSpecular", GlslType::Vec3, specular);
    u.push_f("u_lightPosition", GlslType::Vec3, position);
    u.push_f("u_lightDirection", GlslType::Vec3, direction);
    u.push_f("u_lightCosOuter", GlslType::Float, cos_outer);
    u.push_f("u_lightInvRange", GlslType::Float, inv_range);
    u.push_f("u_lightBasis", GlslType::Mat3, basis);
    u.push_f("u_lightCookieScale", GlslType::Float, scale);
    u.assign_units();
    Ok(u)
}
