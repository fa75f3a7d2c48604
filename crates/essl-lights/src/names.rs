//! The names of everything a generated program declares — one scheme for the specialised and
//! the uber-shader, so a renderer can set values by name.
//!
//! | name | type | value |
//! | --- | --- | --- |
//! | `a_position`, `a_normal` | `vec3` attributes | the mesh's position and normal streams |
//! | `u_modelViewProjection` | `mat4` | `projection · view · model` |
//! | `u_model` | `mat4` | model → world |
//! | `u_normalMatrix` | `mat3` | `transpose(inverse(model))`'s upper-left 3×3: normals to world |
//! | `u_eye` | `vec3` | the camera's position, world space |
//! | `u_invViewport` | `vec2` | `(1 / width, 1 / height)`, for screen-space cookies |
//! | `u_ambient` | `vec3` | ambient light × material ambient |
//! | `u_shininess` | `float` | the material's specular exponent |
//! | `u_light{i}_diffuse` | `vec3` | light `i`'s colour × material diffuse |
//! | `u_light{i}_specular` | `vec3` | light `i`'s specular colour × material specular |
//! | `u_light{i}_direction` | `vec3` | unit direction light `i` travels (directional, spot without projector) |
//! | `u_light{i}_position` | `vec3` | light `i`'s position (point, spot) |
//! | `u_light{i}_cosOuter` | `float` | `cos(outer half-angle)` (spot) |
//! | `u_light{i}_invRange` | `float` | `1 / (cos inner − cos outer)`, capped (linear and smooth edges) |
//! | `u_light{i}_basis` | `mat3` | projector columns left, up, forward (projected cookie) |
//! | `u_light{i}_cookieScale` | `float` | `1 / (2 · outer in radians)` (projected cookie) |
//! | `u_light{i}_cookie` | `sampler2D` | light `i`'s cookie |
//! | `v_position`, `v_normal` | varyings | world position and (unnormalised) normal (Phong shading) |
//! | `v_color` | varying | the lit colour (Gouraud shading) |
//! | `v_light{i}` | varying | light `i`'s colour before its screen cookie (Gouraud shading) |
//! | `o_color` | output | the fragment colour, alpha 1 |
//!
//! Products of constants (`ambient × material`, `light colour × material colour`) are formed on
//! the CPU in float64 and sent as one value: fewer uniforms and one rounding instead of three.
//! Light `i` is the `i`-th entry of [`crate::LitScene::lights`].
//!
//! The uber-shader uses the same transform, material and varying names, and for the lights
//! arrays of [`crate::uber::UBER_MAX_LIGHTS`] entries (see [`crate::uber`]): `u_lightCount`,
//! `u_lightKind[]`, `u_lightEdge[]`, `u_lightCookieKind[]`, `u_lightDiffuse[]`,
//! `u_lightSpecular[]`, `u_lightPosition[]`, `u_lightDirection[]`, `u_lightCosOuter[]`,
//! `u_lightInvRange[]`, `u_lightBasis[]`, `u_lightCookieScale[]`, samplers `u_cookie{k}`, and
//! `u_shading` / `u_reflection` selecting the models.

/// The position attribute.
pub const POSITION: &str = "a_position";
/// The normal attribute.
pub const NORMAL: &str = "a_normal";
/// `projection · view · model`.
pub const MODEL_VIEW_PROJECTION: &str = "u_modelViewProjection";
/// Model to world.
pub const MODEL: &str = "u_model";
/// Normals to world (mat3).
pub const NORMAL_MATRIX: &str = "u_normalMatrix";
/// The eye, world space.
pub const EYE: &str = "u_eye";
/// `(1 / width, 1 / height)`.
pub const INV_VIEWPORT: &str = "u_invViewport";
/// Ambient light × material ambient.
pub const AMBIENT: &str = "u_ambient";
/// Specular exponent.
pub const SHININESS: &str = "u_shininess";
/// World position varying.
pub const V_POSITION: &str = "v_position";
/// World normal varying.
pub const V_NORMAL: &str = "v_normal";
/// Gouraud colour varying.
pub const V_COLOR: &str = "v_color";
/// The fragment output.
pub const OUTPUT: &str = "o_color";

/// A per-light uniform of the specialised shader: `u_light{i}_{field}`.
pub fn light(i: usize, field: &str) -> String {
    format!("u_light{i}_{field}")
}

/// The varying carrying light `i`'s colour before its screen-space cookie (Gouraud shading).
pub fn light_varying(i: usize) -> String {
    format!("v_light{i}")
}

/// The uber-shader's cookie sampler for light slot `k`.
pub fn uber_cookie(k: usize) -> String {
    format!("u_cookie{k}")
}
