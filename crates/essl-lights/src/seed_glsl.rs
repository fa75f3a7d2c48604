//! The seeds' formulas as GLSL ES 3.00 programs, for the GPU: the twins of
//! [`crate::formulas::seed_fragment`], transplanted into the library's skeleton the same way
//! (`ambient + the article's light formula`), on the library's interface (attributes, the
//! transform uniforms, `u_ambient`, `u_light0_diffuse`, …), so the GPU column of the stiff
//! matrix and the report's "seed" variants draw exactly what the CPU column evaluates.
//!
//! Each program is Phong-shaded (per fragment), like the CPU matrix's evaluation; article 002's
//! Gouraud Lambert formula is evaluated per fragment as well. The light's parameters are what
//! the article's JavaScript would upload: unit directions and cone cosines computed in
//! float64, inner and outer as given (even swapped), the viewport as given (even 0×0). The
//! fragment shader declares the precision the article declares; lavapipe computes every
//! precision in 32 bits. The scene is not validated: these programs exist to draw what the
//! library refuses.

use std::fmt::Write as _;

use glam::DVec3;

use crate::error::LightsError;
use crate::formulas::Seed;
use crate::names;
use crate::program::{GlslType, ShaderPair, Stages, UniformDecl};
use crate::scene::{Cookie, Light, LitScene};
use crate::uniforms::{CookieBinding, UniformData, UniformSetting, Uniforms, View};

const VERTEX: &str = "\
#version 300 es
// essl-lights seed program: the library's Phong-shading vertex shader.
uniform mat4 u_modelViewProjection;
uniform mat4 u_model;
uniform mat3 u_normalMatrix;
in vec3 a_position;
in vec3 a_normal;
out vec3 v_position;
out vec3 v_normal;
void main() {
  vec4 p = vec4(a_position, 1.0);
  v_position = (u_model * p).xyz;
  v_normal = u_normalMatrix * a_normal;
  gl_Position = u_modelViewProjection * p;
}
";

/// The light formula of each seed, as its article writes it (see [`Seed`]); `c` is the light's
/// colour.
fn light_body(seed: Seed) -> &'static str {
    match seed {
        Seed::A002Directional => {
            "\
  vec3 l = normalize(u_light0_direction);
  float lambert = dot(nrm, -l);
  vec3 c = vec3(0.0);
  if (lambert > 0.0) {
    vec3 e = normalize(u_eye - P);
    vec3 r = reflect(l, nrm);
    float spec = pow(max(dot(r, e), 0.0), u_shininess);
    c = (u_light0_diffuse + spec * u_light0_specular) * lambert;
  }
"
        }
        Seed::A002Positional => {
            "\
  vec3 l = normalize(P - u_light0_position);
  float lambert = dot(nrm, -l);
  vec3 c = vec3(0.0);
  if (lambert > 0.0) {
    vec3 e = normalize(u_eye - P);
    vec3 r = reflect(l, nrm);
    float spec = pow(max(dot(r, e), 0.0), u_shininess);
    c = (u_light0_diffuse + spec * u_light0_specular) * lambert;
  }
"
        }
        Seed::A002Lambert => {
            "\
  vec3 l = normalize(u_light0_direction);
  vec3 c = u_light0_diffuse * dot(nrm, -l);
"
        }
        Seed::A001Step => {
            "\
  vec3 stl = normalize(u_light0_position - P);
  vec3 stv = normalize(u_eye - P);
  vec3 h = normalize(stl + stv);
  float d = dot(stl, -u_light0_direction);
  float inLight = step(u_cosOuter, d);
  float light = inLight * dot(nrm, stl);
  float spec = pow(dot(nrm, h), u_shininess);
  vec3 c = (u_light0_diffuse + spec * u_light0_specular) * light;
"
        }
        Seed::A001Linear => {
            "\
  vec3 stl = normalize(u_light0_position - P);
  vec3 stv = normalize(u_eye - P);
  vec3 h = normalize(stl + stv);
  float d = dot(stl, -u_light0_direction);
  float inLight = clamp((d - u_cosOuter) / (u_cosInner - u_cosOuter), 0.0, 1.0);
  float light = inLight * dot(nrm, stl);
  float spec = pow(dot(nrm, h), u_shininess);
  vec3 c = (u_light0_diffuse + spec * u_light0_specular) * light;
"
        }
        Seed::A000Smooth => {
            "\
  vec3 stl = normalize(u_light0_position - P);
  vec3 stv = normalize(u_eye - P);
  vec3 h = normalize(stl + stv);
  float d = dot(stl, -u_light0_direction);
  float inLight = smoothstep(u_cosOuter, u_cosInner, d);
  float light = inLight * dot(nrm, stl);
  float spec = pow(max(0.0, dot(nrm, h)), u_shininess);
  vec3 c = (u_light0_diffuse + spec * u_light0_specular) * light;
"
        }
        Seed::A003Projected => {
            "\
  vec3 l = normalize(u_light0_position - P);
  vec3 spotDir = -u_light0_direction;
  float d = dot(l, spotDir);
  float att = smoothstep(u_cosOuter, u_cosInner, d);
  vec3 k = vec3(1.0);
  if (att > 0.0) {
    float cone = acos(u_cosOuter);
    float y = 0.5 + (acos(dot(l, u_up)) - 3.14159265358979 / 2.0) / (2.0 * cone);
    vec3 left = normalize(cross(u_up, spotDir));
    float x = 0.5 + (acos(dot(l, left)) - 3.14159265358979 / 2.0) / (2.0 * cone);
    k = texture(u_light0_cookie, vec2(x, y)).rgb;
  }
  vec3 v = normalize(u_eye - P);
  vec3 h = normalize(l + v);
  float nl = clamp(dot(nrm, l), 0.0, 1.0);
  float nh = clamp(dot(nrm, h), 0.0, 1.0);
  float spec = pow(nh, u_shininess);
  vec3 c = k * att * ((u_light0_diffuse + spec * u_light0_specular) * nl);
"
        }
        Seed::A004Flashlight => {
            "\
  vec3 l = normalize(u_light0_position - P);
  float theta = dot(l, normalize(-u_light0_direction));
  float epsilon = u_cosInner - u_cosOuter;
  float intensity = clamp((theta - u_cosOuter) / epsilon, 0.0, 1.0);
  vec2 uv = gl_FragCoord.xy / u_viewport * vec2(1.0, -1.0);
  vec3 k = texture(u_light0_cookie, uv).rgb;
  float diff = max(dot(nrm, l), 0.0);
  vec3 view = normalize(u_eye - P);
  vec3 r = reflect(-l, nrm);
  float spec = pow(max(dot(view, r), 0.0), u_shininess);
  vec3 c = k * intensity * ((u_light0_diffuse + spec * u_light0_specular) * diff);
"
        }
    }
}

/// The uniforms a seed's fragment shader declares, `(name, type)`, besides the transforms.
fn fragment_uniforms(seed: Seed) -> Vec<(&'static str, GlslType)> {
    let mut u = vec![
        ("u_ambient", GlslType::Vec3),
        ("u_light0_diffuse", GlslType::Vec3),
    ];
    let lambert_only = seed == Seed::A002Lambert;
    if !lambert_only {
        u.push(("u_light0_specular", GlslType::Vec3));
        u.push(("u_shininess", GlslType::Float));
        u.push(("u_eye", GlslType::Vec3));
    }
    if matches!(seed, Seed::A002Directional | Seed::A002Lambert) {
        u.push(("u_light0_direction", GlslType::Vec3));
        return u;
    }
    u.push(("u_light0_position", GlslType::Vec3));
    if seed == Seed::A002Positional {
        return u;
    }
    u.push(("u_light0_direction", GlslType::Vec3));
    u.push(("u_cosOuter", GlslType::Float));
    if seed != Seed::A001Step {
        u.push(("u_cosInner", GlslType::Float));
    }
    match seed {
        Seed::A003Projected => {
            u.push(("u_up", GlslType::Vec3));
            u.push(("u_light0_cookie", GlslType::Sampler2D));
        }
        Seed::A004Flashlight => {
            u.push(("u_viewport", GlslType::Vec2));
            u.push(("u_light0_cookie", GlslType::Sampler2D));
        }
        _ => {}
    }
    u
}

/// The seed's program (vertex + fragment shader and interface).
pub fn seed_program(seed: Seed) -> ShaderPair {
    let frag_uniforms = fragment_uniforms(seed);
    let mut fs = format!(
        "#version 300 es\nprecision {} float;\n// essl-lights seed program: {:?}, transplanted \
         (docs/numerical-stability.md).\n",
        seed.precision(),
        seed
    );
    for (n, t) in &frag_uniforms {
        let _ = writeln!(fs, "uniform {} {n};", t.glsl());
    }
    fs.push_str("in vec3 v_position;\nin vec3 v_normal;\nout vec4 o_color;\nvoid main() {\n");
    fs.push_str("  vec3 P = v_position;\n  vec3 nrm = normalize(v_normal);\n");
    fs.push_str(light_body(seed));
    fs.push_str("  vec3 color = u_ambient + c;\n  o_color = vec4(color, 1.0);\n}\n");
    let mut uniforms: Vec<UniformDecl> = [
        (names::MODEL_VIEW_PROJECTION, GlslType::Mat4),
        (names::MODEL, GlslType::Mat4),
        (names::NORMAL_MATRIX, GlslType::Mat3),
    ]
    .iter()
    .map(|(n, t)| UniformDecl {
        name: n.to_string(),
        ty: *t,
        array: None,
        stages: Stages {
            vertex: true,
            fragment: false,
        },
    })
    .collect();
    uniforms.extend(frag_uniforms.iter().map(|(n, t)| UniformDecl {
        name: n.to_string(),
        ty: *t,
        array: None,
        stages: Stages {
            vertex: false,
            fragment: true,
        },
    }));
    ShaderPair {
        vertex: VERTEX.to_string(),
        fragment: fs,
        uniforms,
        attributes: vec![
            (names::POSITION.into(), GlslType::Vec3),
            (names::NORMAL.into(), GlslType::Vec3),
        ],
        varyings: vec![
            (names::V_POSITION.into(), GlslType::Vec3, None),
            (names::V_NORMAL.into(), GlslType::Vec3, None),
        ],
    }
}

fn unit64(v: DVec3) -> DVec3 {
    let n = v.normalize();
    if n.is_finite() {
        n
    } else {
        DVec3::ZERO
    }
}

/// The values of [`seed_program`]'s uniforms for light 0 of `scene` seen from `view`, with
/// `viewport` the `u_viewport` the article's JavaScript passes (article 004). The scene is not
/// validated; the model matrix must be invertible.
pub fn seed_uniforms(
    seed: Seed,
    scene: &LitScene,
    view: &View,
    viewport: [f64; 2],
) -> Result<Uniforms, LightsError> {
    let light = scene
        .lights
        .first()
        .ok_or_else(|| LightsError::Reference("a seed program needs a light".into()))?;
    let m = &scene.material;
    let (position, direction, inner, outer, up, cookie) = match light {
        Light::Directional(d) => (DVec3::ZERO, d.direction, 0.0, 0.0, DVec3::Y, None),
        Light::Point(p) => (p.position, DVec3::NEG_Y, 0.0, 0.0, DVec3::Y, None),
        Light::Spot(s) => {
            let up = match &s.cookie {
                Some(Cookie::Projected { up, .. }) => *up,
                _ => DVec3::Y,
            };
            (
                s.position,
                s.direction,
                s.inner_deg,
                s.outer_deg,
                up,
                s.cookie.as_ref().map(|c| c.image().clone()),
            )
        }
    };
    let mut values = Vec::new();
    let mut f = |name: &str, ty: GlslType, v: Vec<f64>| {
        values.push(UniformSetting {
            name: name.to_string(),
            ty,
            data: UniformData::Floats(v),
        })
    };
    let v3 = |v: DVec3| v.to_array().to_vec();
    f(
        names::MODEL_VIEW_PROJECTION,
        GlslType::Mat4,
        view.matrices.model_view_projection.0.to_vec(),
    );
    f(names::MODEL, GlslType::Mat4, view.matrices.model.0.to_vec());
    f(
        names::NORMAL_MATRIX,
        GlslType::Mat3,
        view.normal_matrix()?.to_vec(),
    );
    let ambient = scene
        .ambient_light
        .map(|a| a * m.ambient)
        .unwrap_or(DVec3::ZERO);
    let wanted: Vec<&str> = fragment_uniforms(seed).iter().map(|(n, _)| *n).collect();
    let all: Vec<(&str, GlslType, Vec<f64>)> = vec![
        ("u_ambient", GlslType::Vec3, v3(ambient)),
        (
            "u_light0_diffuse",
            GlslType::Vec3,
            v3(light.color() * m.diffuse),
        ),
        (
            "u_light0_specular",
            GlslType::Vec3,
            v3(light.specular() * m.specular),
        ),
        ("u_shininess", GlslType::Float, vec![m.shininess]),
        ("u_eye", GlslType::Vec3, view.matrices.eye.to_vec()),
        ("u_light0_direction", GlslType::Vec3, v3(unit64(direction))),
        ("u_light0_position", GlslType::Vec3, v3(position)),
        (
            "u_cosOuter",
            GlslType::Float,
            vec![outer.to_radians().cos()],
        ),
        (
            "u_cosInner",
            GlslType::Float,
            vec![inner.to_radians().cos()],
        ),
        ("u_up", GlslType::Vec3, v3(unit64(up))),
        ("u_viewport", GlslType::Vec2, viewport.to_vec()),
    ];
    for (n, t, v) in all {
        if wanted.contains(&n) {
            f(n, t, v);
        }
    }
    let mut cookies = Vec::new();
    if wanted.contains(&"u_light0_cookie") {
        let image = cookie.ok_or_else(|| {
            LightsError::Reference(format!("{seed:?} needs a spot light with a cookie"))
        })?;
        cookies.push(CookieBinding {
            sampler: "u_light0_cookie".into(),
            unit: 0,
            image,
        });
        values.push(UniformSetting {
            name: "u_light0_cookie".into(),
            ty: GlslType::Sampler2D,
            data: UniformData::Sampler(0),
        });
    }
    Ok(Uniforms { values, cookies })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_seed_program_compiles_and_links_cleanly() {
        for seed in [
            Seed::A002Directional,
            Seed::A002Lambert,
            Seed::A002Positional,
            Seed::A001Step,
            Seed::A001Linear,
            Seed::A000Smooth,
            Seed::A003Projected,
            Seed::A004Flashlight,
        ] {
            let p = seed_program(seed);
            let v = crate::verify(&p);
            assert!(v.is_clean(), "{seed:?}: {v:#?}\n{}", p.fragment);
        }
    }
}
