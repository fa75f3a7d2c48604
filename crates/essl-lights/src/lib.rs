//! essl-lights: describe a lit scene, get correct, stable, minimal GLSL ES 3.00 (WebGL2)
//! shaders — and a float64 reference to measure every GPU rendering against.
//!
//! - [`scene`]: the description — [`LitScene`] with [`Light`]s (directional, point, spot with
//!   an inner/outer cone and a [`EdgeProfile`], optionally a [`Cookie`]: projected with an up
//!   vector (article 003) or laid over the screen (article 004)), a [`Material`], [`Shading`]
//!   (Gouraud or Phong) and [`Reflection`] (Lambert, Phong, Blinn–Phong). Validation refuses
//!   what would render NaN ([`LightsError`]).
//! - [`specialise`]: [`generate`] writes a vertex + fragment shader containing only what the
//!   scene uses; [`uber`]: [`generate_uber`] writes one shader for every scene, chosen by
//!   uniforms. [`names`] is the uniform naming scheme, [`uniforms`] computes the values (in
//!   float64, rounded once on upload), [`glsl`] holds the stable building blocks, and
//!   [`verify`](mod@verify) checks a program with the `essl` front end (zero diagnostics, every
//!   declared uniform active, no unused function).
//! - [`ideal`]: the light model in exact float64, limits included; [`reference`](mod@reference): a float64
//!   ray-casting renderer of any [`essl_scene::Scene`] through float64 shaders ([`seeds`] for
//!   the shared scenes' own shaders, [`reference::LitShader`] for the library's model), with
//!   an exact-surface mode, coverage masks and the comparison of an RGBA8 image against it.
//! - [`real`], [`formulas`], [`stiff`]: the shader formulas generic over float64 / float32 /
//!   binary16 and the stiff-case matrix of `docs/numerical-stability.md`.
//! - [`bridge`]: a lit scene on a base scene's geometry as an [`essl_scene::Scene`] (and its
//!   JSON), for renderers of scene files; [`presets`]: the shared seed scenes as lit scenes.
//! - On the GPU (essl-gl: WebGL2's API on wgpu): [`gpu`] draws programs, times frames and
//!   makes the NaN probe of a program (an RGBA8 target cannot show NaN); [`seed_glsl`] writes the
//!   seeds' formulas as GLSL programs on the library's interface; [`gpu_stiff`] draws the
//!   stiff-case matrix with both (`docs/numerical-stability.md`, "The matrix on the GPU");
//!   [`report`] measures error against run time for shading, tessellation, edge profiles, precision,
//!   projector coordinates and specialised-vs-uber programs (`essl report`, `docs/report.md`).
//!
//! ```
//! use essl_lights::*;
//! use glam::DVec3;
//!
//! let scene = LitScene::new(Shading::Phong, Reflection::BlinnPhong, Material::default())
//!     .with_ambient(DVec3::splat(0.1))
//!     .with_light(Light::Spot(SpotLight {
//!         position: DVec3::new(0.0, 100.0, 0.0),
//!         direction: DVec3::NEG_Y,
//!         inner_deg: 10.0,
//!         outer_deg: 20.0,
//!         edge: EdgeProfile::Smooth,
//!         cookie: None,
//!         color: DVec3::ONE,
//!         specular: DVec3::ONE,
//!     }));
//! let program = generate(&scene)?;
//! assert!(verify(&program).is_minimal());
//!
//! // Geometry and camera come from a scene file; the bridge puts the program on them.
//! let file = essl_scene::SceneFile::parse(r#"{
//!     "width": 32, "height": 32, "vertex_shader": "v", "fragment_shader": "f",
//!     "mesh": {"kind": "grid", "size": 200, "cells": 4},
//!     "attributes": {"a_position": "position"},
//!     "camera": {"eye": [0, 140, 70], "target": [0, 0, 0], "up": [0, 1, 0],
//!                "fov_y_deg": 60, "near": 1, "far": 2000}
//! }"#)?;
//! let view = View {
//!     matrices: essl_scene::Matrices::new(&file.camera, &file.model, 32, 32)?,
//!     width: 32,
//!     height: 32,
//! };
//! let uniforms = uniform_values(&scene, &view)?;
//! let drawable = bridge::to_scene(&file, &program, &uniforms)?;
//! let reference = reference::render(
//!     &drawable,
//!     &reference::LitShader::new(&scene, &view)?,
//!     reference::Geometry::Mesh,
//! )?;
//! assert!(reference.covered(16, 16));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod bridge;
pub mod error;
pub mod formulas;
pub mod glsl;
pub mod gpu;
pub mod gpu_stiff;
pub mod ideal;
pub mod names;
pub mod presets;
pub mod program;
pub mod real;
pub mod reference;
pub mod report;
pub mod scene;
pub mod seed_glsl;
pub mod seeds;
pub mod specialise;
pub mod stiff;
pub mod uber;
pub mod uniforms;
pub mod verify;

pub use error::LightsError;
pub use program::{GlslType, ShaderPair, Stages, UniformDecl};
pub use scene::*;
pub use specialise::{generate, generate_shape};
pub use uber::{generate_uber, UBER_MAX_LIGHTS};
pub use uniforms::{
    uber_uniform_values, uniform_values, CookieBinding, UniformData, UniformSetting, Uniforms, View,
};
pub use verify::{verify, Verification};
