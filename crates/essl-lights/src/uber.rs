//! The uber-shader: one program for every scene of up to [`UBER_MAX_LIGHTS`] lights, the
//! models chosen by uniforms (`u_shading`, `u_reflection`, per light `u_lightKind[]`,
//! `u_lightEdge[]`, `u_lightCookieKind[]`) and branches — the baseline the specialised shaders
//! are compared with. It uses the same stable helpers as the specialised shaders, so both render
//! the same picture; only the cost differs.
//!
//! Codes: `u_shading` 0 Gouraud, 1 Phong; `u_reflection` 0 Lambert, 1 Phong, 2 Blinn–Phong;
//! `u_lightKind` 0 directional, 1 point, 2 spot; `u_lightEdge` 0 step, 1 linear, 2 smooth;
//! `u_lightCookieKind` 0 none, 1 projected, 2 screen. Slots at and after `u_lightCount` are
//! skipped.

use std::fmt::Write as _;

use crate::glsl;
use crate::names;
use crate::program::{GlslType, ShaderPair, Stages, UniformDecl};

/// Light slots of the uber-shader.
pub const UBER_MAX_LIGHTS: usize = 4;

/// `(name, type, array length)` of the uber-shader's uniforms, declared in both stages.
fn uber_uniforms() -> Vec<(String, GlslType, Option<usize>)> {
    let n = Some(UBER_MAX_LIGHTS);
    let mut u: Vec<(String, GlslType, Option<usize>)> = vec![
        (names::MODEL_VIEW_PROJECTION.into(), GlslType::Mat4, None),
        (names::MODEL.into(), GlslType::Mat4, None),
        (names::NORMAL_MATRIX.into(), GlslType::Mat3, None),
        (names::EYE.into(), GlslType::Vec3, None),
        (names::INV_VIEWPORT.into(), GlslType::Vec2, None),
        ("u_shading".into(), GlslType::Int, None),
        ("u_reflection".into(), GlslType::Int, None),
        (names::AMBIENT.into(), GlslType::Vec3, None),
        (names::SHININESS.into(), GlslType::Float, None),
        ("u_lightCount".into(), GlslType::Int, None),
        ("u_lightKind".into(), GlslType::Int, n),
        ("u_lightEdge".into(), GlslType::Int, n),
        ("u_lightCookieKind".into(), GlslType::Int, n),
        ("u_lightDiffuse".into(), GlslType::Vec3, n),
        ("u_lightSpecular".into(), GlslType::Vec3, n),
        ("u_lightPosition".into(), GlslType::Vec3, n),
        ("u_lightDirection".into(), GlslType::Vec3, n),
        ("u_lightCosOuter".into(), GlslType::Float, n),
        ("u_lightInvRange".into(), GlslType::Float, n),
        ("u_lightBasis".into(), GlslType::Mat3, n),
        ("u_lightCookieScale".into(), GlslType::Float, n),
    ];
    for k in 0..UBER_MAX_LIGHTS {
        u.push((names::uber_cookie(k), GlslType::Sampler2D, None));
    }
    u
}

fn uber_light_fn() -> String {
    let mut s = String::from(
        "\
// Light slot i's colour at P (unit normal N, unit view V), its screen cookie not applied.
vec3 el_light(int i, vec3 P, vec3 N, vec3 V) {
  int kind = u_lightKind[i];
  vec3 L = kind == 0 ? -u_lightDirection[i] : el_normalize(u_lightPosition[i] - P);
  vec3 a = vec3(1.0);
  if (kind == 2) {
    int cookie = u_lightCookieKind[i];
    vec3 q = -L * u_lightBasis[i];
    float d = cookie == 1 ? q.z : dot(L, -u_lightDirection[i]);
    int edge = u_lightEdge[i];
    float e;
    if (edge == 0) {
      e = step(u_lightCosOuter[i], d);
    } else {
      float t = clamp((d - u_lightCosOuter[i]) * u_lightInvRange[i], 0.0, 1.0);
      e = edge == 1 ? t : t * t * (3.0 - 2.0 * t);
    }
    a = vec3(e);
    if (cookie == 1) {
      a *= el_cookie(i, el_projectorUv(q, u_lightCookieScale[i]));
    }
  }
  float s = 0.0;
  if (u_reflection == 1) {
    s = el_power(dot(reflect(-L, N), V), u_shininess);
  } else if (u_reflection == 2) {
    s = el_power(dot(N, el_normalize(L + V)), u_shininess);
  }
  return a * max(dot(N, L), 0.0) * (u_lightDiffuse[i] + s * u_lightSpecular[i]);
}
",
    );
    s.insert_str(0, &uber_cookie_fn());
    s
}

fn uber_cookie_fn() -> String {
    let mut s = String::from(
        "// Cookie of light slot i (samplers take constant indices only).\nvec3 el_cookie(int i, vec2 uv) {\n",
    );
    for k in 0..UBER_MAX_LIGHTS - 1 {
        let _ = writeln!(
            s,
            "  if (i == {k}) return texture({}, uv).rgb;",
            names::uber_cookie(k)
        );
    }
    let _ = writeln!(
        s,
        "  return texture({}, uv).rgb;\n}}",
        names::uber_cookie(UBER_MAX_LIGHTS - 1)
    );
    s
}

/// Generates the uber-shader.
pub fn generate_uber() -> ShaderPair {
    let uniforms = uber_uniforms();
    // Transforms only in the vertex shader, the viewport only in the fragment shader; the rest
    // in both (Gouraud lights in one, Phong in the other).
    let stages_of = |name: &str| Stages {
        vertex: name != names::INV_VIEWPORT,
        fragment: ![
            names::MODEL_VIEW_PROJECTION,
            names::MODEL,
            names::NORMAL_MATRIX,
        ]
        .contains(&name),
    };
    let decls = |vertex: bool| {
        let mut decls = String::new();
        for (name, ty, arr) in &uniforms {
            let st = stages_of(name);
            if (vertex && !st.vertex) || (!vertex && !st.fragment) {
                continue;
            }
            let prec = if *ty == GlslType::Sampler2D {
                "highp "
            } else {
                ""
            };
            let arr = arr.map(|n| format!("[{n}]")).unwrap_or_default();
            let _ = writeln!(decls, "uniform {prec}{} {name}{arr};", ty.glsl());
        }
        decls
    };
    let helpers = format!(
        "{}{}{}{}",
        glsl::NORMALIZE,
        glsl::POWER,
        glsl::PROJECTOR_UV,
        uber_light_fn()
    );
    let n = UBER_MAX_LIGHTS;
    let header = "// essl-lights uber-shader: every model, chosen by uniforms.\n";

    let mut vs = format!("#version 300 es\n{header}{}", decls(true));
    vs.push_str("in vec3 a_position;\nin vec3 a_normal;\n");
    vs.push_str("out vec3 v_position;\nout vec3 v_normal;\nout vec3 v_color;\n");
    let _ = writeln!(vs, "out vec3 v_light[{n}];");
    vs.push_str(&helpers);
    vs.push_str(
        "void main() {
  vec4 p = vec4(a_position, 1.0);
  vec3 P = (u_model * p).xyz;
  vec3 n = u_normalMatrix * a_normal;
  v_position = P;
  v_normal = n;
  vec3 color = vec3(0.0);
",
    );
    for i in 0..n {
        let _ = writeln!(vs, "  v_light[{i}] = vec3(0.0);");
    }
    vs.push_str(
        "  if (u_shading == 0) {
    vec3 N = el_normalize(n);
    vec3 V = el_normalize(u_eye - P);
    color = u_ambient;
",
    );
    for i in 0..n {
        let _ = write!(
            vs,
            "    if ({i} < u_lightCount) {{
      vec3 c = el_light({i}, P, N, V);
      if (u_lightCookieKind[{i}] == 2) v_light[{i}] = c; else color += c;
    }}
"
        );
    }
    vs.push_str("  }\n  v_color = color;\n  gl_Position = u_modelViewProjection * p;\n}\n");

    let mut fs = format!(
        "#version 300 es\nprecision highp float;\nprecision highp int;\n{header}{}",
        decls(false)
    );
    fs.push_str("in vec3 v_position;\nin vec3 v_normal;\nin vec3 v_color;\n");
    let _ = writeln!(fs, "in vec3 v_light[{n}];");
    let _ = writeln!(fs, "out vec4 {};", names::OUTPUT);
    fs.push_str(&helpers);
    fs.push_str(glsl::SCREEN_UV);
    fs.push_str(
        "void main() {
  vec3 color;
  if (u_shading == 1) {
    vec3 P = v_position;
    vec3 N = el_normalize(v_normal);
    vec3 V = el_normalize(u_eye - P);
    color = u_ambient;
",
    );
    for i in 0..n {
        let _ = write!(
            fs,
            "    if ({i} < u_lightCount) {{
      vec3 c = el_light({i}, P, N, V);
      if (u_lightCookieKind[{i}] == 2) c *= el_cookie({i}, el_screenUv());
      color += c;
    }}
"
        );
    }
    fs.push_str("  } else {\n    color = v_color;\n");
    for i in 0..n {
        let _ = writeln!(
            fs,
            "    if ({i} < u_lightCount && u_lightCookieKind[{i}] == 2) color += el_cookie({i}, el_screenUv()) * v_light[{i}];"
        );
    }
    fs.push_str("  }\n  o_color = vec4(color, 1.0);\n}\n");

    ShaderPair {
        vertex: vs,
        fragment: fs,
        uniforms: uniforms
            .into_iter()
            .map(|(name, ty, array)| UniformDecl {
                stages: stages_of(&name),
                name,
                ty,
                array,
            })
            .collect(),
        attributes: vec![
            (names::POSITION.into(), GlslType::Vec3),
            (names::NORMAL.into(), GlslType::Vec3),
        ],
        varyings: vec![
            (names::V_POSITION.into(), GlslType::Vec3, None),
            (names::V_NORMAL.into(), GlslType::Vec3, None),
            (names::V_COLOR.into(), GlslType::Vec3, None),
            ("v_light".into(), GlslType::Vec3, Some(n)),
        ],
    }
}
