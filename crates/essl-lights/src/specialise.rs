//! The specialised generator: a scene's [`Shape`] to a vertex and fragment shader that contain
//! only what the scene uses — no uniform, sampler, varying, function or statement for an absent
//! light kind, edge profile, cookie or reflection term (nothing for the driver to strip, unlike
//! three.js's `#define NUM_SPOT_LIGHTS` blocks, which still declare every struct field).
//!
//! Lights are emitted one block each, with their uniforms named by index
//! ([`crate::names`]); the stable helpers of [`crate::glsl`] are included only when called.

use std::fmt::Write as _;

use crate::error::LightsError;
use crate::glsl;
use crate::names;
use crate::program::{GlslType, ShaderPair, Stages, UniformDecl};
use crate::scene::{CookieKind, EdgeProfile, LightShape, LitScene, Reflection, Shading, Shape};

/// Generates the specialised program of a scene (validated first).
pub fn generate(scene: &LitScene) -> Result<ShaderPair, LightsError> {
    scene.validate()?;
    generate_shape(&scene.shape())
}

/// Generates the specialised program of a shape. Fails only for more than
/// [`crate::MAX_LIGHTS`] lights.
pub fn generate_shape(shape: &Shape) -> Result<ShaderPair, LightsError> {
    if shape.lights.len() > crate::MAX_LIGHTS {
        return Err(LightsError::TooManyLights {
            count: shape.lights.len(),
            max: crate::MAX_LIGHTS,
        });
    }
    Ok(Generator::new(shape).run())
}

/// A helper function, in the order they are emitted (callees first).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Helper {
    Normalize,
    Power,
    Direct,
    EdgeLinear,
    EdgeSmooth,
    ProjectorUv,
    ScreenUv,
}

/// One shader being built.
#[derive(Default)]
struct Stage {
    uniforms: Vec<(String, GlslType)>,
    helpers: Vec<Helper>,
    body: String,
}

impl Stage {
    fn uniform(&mut self, name: &str, ty: GlslType) -> String {
        if !self.uniforms.iter().any(|(n, _)| n == name) {
            self.uniforms.push((name.to_string(), ty));
        }
        name.to_string()
    }

    fn helper(&mut self, h: Helper) {
        if !self.helpers.contains(&h) {
            self.helpers.push(h);
        }
    }

    fn line(&mut self, indent: usize, text: &str) {
        let _ = writeln!(self.body, "{:width$}{text}", "", width = indent * 2);
    }
}

struct Generator<'a> {
    shape: &'a Shape,
    vs: Stage,
    fs: Stage,
    varyings: Vec<(String, GlslType)>,
}

fn describe(shape: &Shape) -> String {
    let shading = match shape.shading {
        Shading::Gouraud => "Gouraud shading",
        Shading::Phong => "Phong shading",
    };
    let reflection = match shape.reflection {
        Reflection::Lambert => "Lambert reflection",
        Reflection::Phong => "Phong reflection",
        Reflection::BlinnPhong => "Blinn-Phong reflection",
    };
    let lights: Vec<String> = shape
        .lights
        .iter()
        .enumerate()
        .map(|(i, l)| format!("{i}: {}", light_label(*l)))
        .collect();
    let lights = if lights.is_empty() {
        "none".to_string()
    } else {
        lights.join("; ")
    };
    format!(
        "// essl-lights: {shading}, {reflection}{}; lights {lights}.\n",
        if shape.ambient { ", ambient" } else { "" }
    )
}

fn light_label(l: LightShape) -> String {
    match l {
        LightShape::Directional => "directional".into(),
        LightShape::Point => "point".into(),
        LightShape::Spot { edge, cookie } => {
            let edge = match edge {
                EdgeProfile::Step => "step",
                EdgeProfile::Linear => "linear",
                EdgeProfile::Smooth => "smooth",
            };
            let cookie = match cookie {
                None => "",
                Some(CookieKind::Projected) => ", projected cookie",
                Some(CookieKind::Screen) => ", screen cookie",
            };
            format!("spot ({edge} edge{cookie})")
        }
    }
}

impl<'a> Generator<'a> {
    fn new(shape: &'a Shape) -> Self {
        Generator {
            shape,
            vs: Stage::default(),
            fs: Stage::default(),
            varyings: Vec::new(),
        }
    }

    fn varying(&mut self, name: &str, ty: GlslType) {
        self.varyings.push((name.to_string(), ty));
    }

    fn run(mut self) -> ShaderPair {
        let shape = self.shape;
        let lit = !shape.lights.is_empty();
        let needs_view = shape.needs_view();
        let needs_position = shape.needs_position() || needs_view;
        let gouraud = shape.shading == Shading::Gouraud;

        // Vertex shader prologue.
        self.vs.line(1, "vec4 p = vec4(a_position, 1.0);");
        if gouraud {
            // Lighting in the vertex shader.
            if needs_position {
                self.vs.uniform(names::MODEL, GlslType::Mat4);
                self.vs.line(1, "vec3 P = (u_model * p).xyz;");
            }
            let terms = self.lighting(Lighting::Vertex, needs_view);
            if terms.base {
                self.varying(names::V_COLOR, GlslType::Vec3);
                self.vs.line(1, "v_color = color;");
            }
            // Fragment: the interpolated colour plus the screen-cookie lights.
            self.fs.line(
                1,
                if terms.base {
                    "vec3 color = v_color;"
                } else {
                    "vec3 color = vec3(0.0);"
                },
            );
            for &i in &terms.screen_lights {
                let v = names::light_varying(i);
                self.varying(&v, GlslType::Vec3);
                let cookie = self
                    .fs
                    .uniform(&names::light(i, "cookie"), GlslType::Sampler2D);
                self.fs.uniform(names::INV_VIEWPORT, GlslType::Vec2);
                self.fs.helper(Helper::ScreenUv);
                self.fs.line(
                    1,
                    &format!("color += texture({cookie}, el_screenUv()).rgb * {v};"),
                );
            }
        } else {
            if needs_position {
                self.vs.uniform(names::MODEL, GlslType::Mat4);
                self.varying(names::V_POSITION, GlslType::Vec3);
                self.vs.line(1, "v_position = (u_model * p).xyz;");
            }
            if lit {
                self.vs.uniform(names::NORMAL_MATRIX, GlslType::Mat3);
                self.varying(names::V_NORMAL, GlslType::Vec3);
                self.vs.line(1, "v_normal = u_normalMatrix * a_normal;");
            }
            if needs_position {
                self.fs.line(1, "vec3 P = v_position;");
            }
            self.lighting(Lighting::Fragment, needs_view);
        }
        self.vs
            .uniform(names::MODEL_VIEW_PROJECTION, GlslType::Mat4);
        self.vs.line(1, "gl_Position = u_modelViewProjection * p;");
        self.fs.line(1, "o_color = vec4(color, 1.0);");
        self.finish()
    }

    /// Emits the lighting code into the stage that lights (`color` accumulates there).
    fn lighting(&mut self, at: Lighting, needs_view: bool) -> Terms {
        let shape = self.shape;
        let mut terms = Terms {
            base: shape.ambient,
            screen_lights: Vec::new(),
        };
        let st = match at {
            Lighting::Vertex => &mut self.vs,
            Lighting::Fragment => &mut self.fs,
        };
        if !shape.lights.is_empty() {
            match at {
                Lighting::Vertex => {
                    st.uniform(names::NORMAL_MATRIX, GlslType::Mat3);
                    st.line(1, "vec3 N = el_normalize(u_normalMatrix * a_normal);");
                }
                Lighting::Fragment => st.line(1, "vec3 N = el_normalize(v_normal);"),
            }
            st.helper(Helper::Normalize);
            st.helper(Helper::Direct);
            if needs_view {
                st.uniform(names::EYE, GlslType::Vec3);
                st.uniform(names::SHININESS, GlslType::Float);
                st.helper(Helper::Power);
                st.line(1, "vec3 V = el_normalize(u_eye - P);");
            }
        }
        let has_accumulated = shape.ambient
            || shape.lights.iter().any(|l| {
                !(at == Lighting::Vertex
                    && matches!(
                        l,
                        LightShape::Spot {
                            cookie: Some(CookieKind::Screen),
                            ..
                        }
                    ))
            });
        if shape.ambient {
            st.uniform(names::AMBIENT, GlslType::Vec3);
            st.line(1, "vec3 color = u_ambient;");
        } else if has_accumulated || at == Lighting::Fragment {
            st.line(1, "vec3 color = vec3(0.0);");
        }
        for (i, &light) in shape.lights.iter().enumerate() {
            let diffuse = st.uniform(&names::light(i, "diffuse"), GlslType::Vec3);
            let specular = if shape.reflection.has_specular() {
                Some(st.uniform(&names::light(i, "specular"), GlslType::Vec3))
            } else {
                None
            };
            st.line(1, &format!("// light {i}: {}", light_label(light)));
            st.line(1, "{");
            match light {
                LightShape::Directional => {
                    let dir = st.uniform(&names::light(i, "direction"), GlslType::Vec3);
                    st.line(2, &format!("vec3 L = -{dir};"));
                }
                LightShape::Point | LightShape::Spot { .. } => {
                    let pos = st.uniform(&names::light(i, "position"), GlslType::Vec3);
                    st.line(2, &format!("vec3 L = el_normalize({pos} - P);"));
                }
            }
            let mut factor = String::new();
            if let LightShape::Spot { edge, cookie } = light {
                let cos_outer = st.uniform(&names::light(i, "cosOuter"), GlslType::Float);
                if cookie == Some(CookieKind::Projected) {
                    let basis = st.uniform(&names::light(i, "basis"), GlslType::Mat3);
                    st.line(2, &format!("vec3 q = -L * {basis};"));
                    st.line(2, "float d = q.z;");
                } else {
                    let dir = st.uniform(&names::light(i, "direction"), GlslType::Vec3);
                    st.line(2, &format!("float d = dot(L, -{dir});"));
                }
                match edge {
                    EdgeProfile::Step => {
                        st.line(2, &format!("float a = step({cos_outer}, d);"));
                    }
                    EdgeProfile::Linear | EdgeProfile::Smooth => {
                        let inv = st.uniform(&names::light(i, "invRange"), GlslType::Float);
                        let (f, h) = if edge == EdgeProfile::Linear {
                            ("el_edgeLinear", Helper::EdgeLinear)
                        } else {
                            ("el_edgeSmooth", Helper::EdgeSmooth)
                        };
                        st.helper(h);
                        st.line(2, &format!("float a = {f}(d, {cos_outer}, {inv});"));
                    }
                }
                factor.push_str("a * ");
                match cookie {
                    Some(CookieKind::Projected) => {
                        let scale = st.uniform(&names::light(i, "cookieScale"), GlslType::Float);
                        let sampler = st.uniform(&names::light(i, "cookie"), GlslType::Sampler2D);
                        st.helper(Helper::ProjectorUv);
                        st.line(
                            2,
                            &format!(
                                "vec3 k = texture({sampler}, el_projectorUv(q, {scale})).rgb;"
                            ),
                        );
                        factor.push_str("k * ");
                    }
                    Some(CookieKind::Screen) if at == Lighting::Fragment => {
                        let sampler = st.uniform(&names::light(i, "cookie"), GlslType::Sampler2D);
                        st.uniform(names::INV_VIEWPORT, GlslType::Vec2);
                        st.helper(Helper::ScreenUv);
                        st.line(
                            2,
                            &format!("vec3 k = texture({sampler}, el_screenUv()).rgb;"),
                        );
                        factor.push_str("k * ");
                    }
                    _ => {}
                }
            }
            let direct = match &specular {
                Some(s) => format!("el_direct(N, L, V, {diffuse}, {s})"),
                None => format!("el_direct(N, L, {diffuse})"),
            };
            let screen_in_vertex = at == Lighting::Vertex
                && matches!(
                    light,
                    LightShape::Spot {
                        cookie: Some(CookieKind::Screen),
                        ..
                    }
                );
            if screen_in_vertex {
                // The cookie needs gl_FragCoord: this light's colour goes to its own varying.
                st.line(
                    2,
                    &format!("{} = {factor}{direct};", names::light_varying(i)),
                );
                terms.screen_lights.push(i);
            } else {
                st.line(2, &format!("color += {factor}{direct};"));
                terms.base = true;
            }
            st.line(1, "}");
        }
        terms
    }

    fn finish(self) -> ShaderPair {
        let shape = self.shape;
        let header = describe(shape);
        let mut uniforms: Vec<UniformDecl> = Vec::new();
        for (stage, is_vs) in [(&self.vs, true), (&self.fs, false)] {
            for (name, ty) in &stage.uniforms {
                match uniforms.iter_mut().find(|u| &u.name == name) {
                    Some(u) => {
                        if is_vs {
                            u.stages.vertex = true;
                        } else {
                            u.stages.fragment = true;
                        }
                    }
                    None => uniforms.push(UniformDecl {
                        name: name.clone(),
                        ty: *ty,
                        array: None,
                        stages: Stages {
                            vertex: is_vs,
                            fragment: !is_vs,
                        },
                    }),
                }
            }
        }
        let uses_normal = !shape.lights.is_empty();
        let mut attributes = vec![(names::POSITION.to_string(), GlslType::Vec3)];
        if uses_normal {
            attributes.push((names::NORMAL.to_string(), GlslType::Vec3));
        }

        let mut vs = String::from("#version 300 es\n");
        vs.push_str(&header);
        for (name, ty) in &self.vs.uniforms {
            let _ = writeln!(vs, "uniform {} {name};", ty.glsl());
        }
        for (name, ty) in &attributes {
            let _ = writeln!(vs, "in {} {name};", ty.glsl());
        }
        for (name, ty) in &self.varyings {
            let _ = writeln!(vs, "out {} {name};", ty.glsl());
        }
        emit_helpers(&mut vs, &self.vs.helpers, shape.reflection);
        let _ = write!(vs, "void main() {{\n{}}}\n", self.vs.body);

        let mut fs = String::from("#version 300 es\nprecision highp float;\n");
        fs.push_str(&header);
        for (name, ty) in &self.fs.uniforms {
            let _ = writeln!(fs, "uniform {} {name};", ty.glsl());
        }
        for (name, ty) in &self.varyings {
            let _ = writeln!(fs, "in {} {name};", ty.glsl());
        }
        let _ = writeln!(fs, "out vec4 {};", names::OUTPUT);
        emit_helpers(&mut fs, &self.fs.helpers, shape.reflection);
        let _ = write!(fs, "void main() {{\n{}}}\n", self.fs.body);

        ShaderPair {
            vertex: vs,
            fragment: fs,
            uniforms,
            attributes,
            varyings: self
                .varyings
                .into_iter()
                .map(|(n, t)| (n, t, None))
                .collect(),
        }
    }
}

/// Which stage lights.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Lighting {
    Vertex,
    Fragment,
}

/// What the lighting stage produced.
struct Terms {
    /// Whether `color` holds anything (ambient or a light without a screen cookie).
    base: bool,
    /// Lights whose colour goes through a `v_light{i}` varying (Gouraud, screen cookie).
    screen_lights: Vec<usize>,
}

fn emit_helpers(out: &mut String, helpers: &[Helper], reflection: Reflection) {
    let mut sorted = helpers.to_vec();
    sorted.sort();
    for h in sorted {
        out.push_str(match h {
            Helper::Normalize => glsl::NORMALIZE,
            Helper::Power => glsl::POWER,
            Helper::Direct => match reflection {
                Reflection::Lambert => glsl::DIRECT_LAMBERT,
                Reflection::Phong => glsl::DIRECT_PHONG,
                Reflection::BlinnPhong => glsl::DIRECT_BLINN,
            },
            Helper::EdgeLinear => glsl::EDGE_LINEAR,
            Helper::EdgeSmooth => glsl::EDGE_SMOOTH,
            Helper::ProjectorUv => glsl::PROJECTOR_UV,
            Helper::ScreenUv => glsl::SCREEN_UV,
        });
    }
}
