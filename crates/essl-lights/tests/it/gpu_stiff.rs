//! The stiff cases on the GPU: every (light model, stiff case) row of
//! `docs/numerical-stability.md` drawn through essl-gl (lavapipe here) with the library's program
//! and the seed's, 65×65.
//!
//! The library's program must draw no NaN or infinite fragment (the NaN probe,
//! `gpu::probe_program`) and be within 1/255 of the float64 model away from silhouettes, or be
//! refused by the API; the seeds' failures are recorded (printed), and a few that are certain
//! on any IEEE GPU are asserted. Skips with a message when no Vulkan adapter exists, unless the
//! `CI` variable is set (then it fails).

use essl_lights::gpu::{self, count_probe, probe_program};
use essl_lights::gpu_stiff::{self, SIZE};
use essl_lights::program::{GlslType, ShaderPair, Stages, UniformDecl};
use essl_lights::stiff::{Case, Model, Outcome};
use essl_lights::{bridge, CookieBinding, CookieImage, UniformData, UniformSetting, Uniforms};
use essl_scene::SceneFile;

fn adapter() -> Option<String> {
    essl_testdata::with_adapter(gpu::adapter).map(|(name, _)| name)
}

/// A full-viewport quad whose fragment shader is NaN in the left quarter, +∞ in the next,
/// samples a texture at a NaN coordinate in the third and is finite in the last.
fn probe_check_program() -> (ShaderPair, Uniforms, SceneFile) {
    let vertex = "#version 300 es\nin vec3 a_position;\nin vec3 a_normal;\nvoid main() {\n  gl_Position = vec4(a_position.xy + 0.0 * a_normal.xy, 0.0, 1.0);\n}\n";
    let fragment = "#version 300 es\nprecision highp float;\nuniform float u_zero;\nuniform sampler2D u_tex;\nout vec4 o_color;\nvoid main() {\n  float x = gl_FragCoord.x;\n  vec3 color = vec3(0.5);\n  if (x < 8.0) {\n    color = vec3(u_zero / u_zero);\n  } else if (x < 16.0) {\n    color = vec3(1.0 / u_zero);\n  } else if (x < 24.0) {\n    color = texture(u_tex, vec2(u_zero / u_zero)).rgb;\n  }\n  o_color = vec4(color, 1.0);\n}\n";
    let decl = |name: &str, ty| UniformDecl {
        name: name.into(),
        ty,
        array: None,
        stages: Stages {
            vertex: false,
            fragment: true,
        },
    };
    let program = ShaderPair {
        vertex: vertex.into(),
        fragment: fragment.into(),
        uniforms: vec![
            decl("u_zero", GlslType::Float),
            decl("u_tex", GlslType::Sampler2D),
        ],
        attributes: vec![
            ("a_position".into(), GlslType::Vec3),
            ("a_normal".into(), GlslType::Vec3),
        ],
        varyings: vec![],
    };
    let uniforms = Uniforms {
        values: vec![
            UniformSetting {
                name: "u_zero".into(),
                ty: GlslType::Float,
                data: UniformData::Floats(vec![0.0]),
            },
            UniformSetting {
                name: "u_tex".into(),
                ty: GlslType::Sampler2D,
                data: UniformData::Sampler(0),
            },
        ],
        cookies: vec![CookieBinding {
            sampler: "u_tex".into(),
            unit: 0,
            image: CookieImage::solid([200, 100, 50, 255]),
        }],
    };
    let file = SceneFile::parse(
        r#"{
      "width": 32, "height": 8, "vertex_shader": "x.vert", "fragment_shader": "x.frag",
      "mesh": {"kind": "arrays",
               "attributes": {"position": [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0],
                              "normal": [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]},
               "indices": [0, 1, 2, 0, 2, 3]},
      "attributes": {"a_position": "position", "a_normal": "normal"},
      "camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0],
                 "fov_y_deg": 60, "near": 0.1, "far": 10}
    }"#,
    )
    .unwrap();
    (program, uniforms, file)
}

#[test]
fn the_probe_flags_nan_infinity_and_nan_coordinates() {
    if adapter().is_none() {
        return;
    }
    let (program, uniforms, file) = probe_check_program();
    let probe = probe_program(&program).unwrap();
    let scene = bridge::to_scene(&file, &probe, &uniforms).unwrap();
    let image = gpu::render(&scene).unwrap();
    for y in 0..8 {
        for x in 0..32 {
            let want = if x < 24 {
                gpu::PROBE_NON_FINITE
            } else {
                gpu::PROBE_FINITE
            };
            assert_eq!(image.pixel(x, y), want, "pixel ({x}, {y})");
        }
    }
    let c = count_probe(&image);
    assert_eq!((c.non_finite, c.finite, c.background), (24 * 8, 8 * 8, 0));
    // The program itself draws something for those pixels: the NaN is invisible without the
    // probe.
    let plain = gpu::render(&bridge::to_scene(&file, &program, &uniforms).unwrap()).unwrap();
    assert_eq!(count_probe(&plain).non_finite, 0);
}

#[test]
fn stiff_cases_on_the_gpu() {
    let Some(renderer) = adapter() else { return };
    let rows = gpu_stiff::run(SIZE).unwrap();
    eprintln!("GPU: {renderer}, {SIZE}×{SIZE}");
    eprintln!("{}", gpu_stiff::markdown(&rows));
    let (total, seed_fail, lib_fail) = gpu_stiff::summary(&rows);
    eprintln!("{total} rows: seed programs fail in {seed_fail}, the library's in {lib_fail}");
    let mut problems = Vec::new();
    for r in &rows {
        if !r.library.ok() {
            problems.push(format!(
                "{} / {}: library {} ({})",
                r.model.name(),
                r.case.name(),
                r.library.cell(),
                r.geometry
            ));
        }
        // The library refuses exactly what the CPU matrix says it refuses.
        let rejected = matches!(r.library, Outcome::Rejected(_));
        let cpu_rejected = matches!(r.cpu.library_highp, Outcome::Rejected(_));
        if rejected != cpu_rejected {
            problems.push(format!(
                "{} / {}: GPU rejected {rejected}, CPU rejected {cpu_rejected}",
                r.model.name(),
                r.case.name()
            ));
        }
        // Every measured library cell drew fragments.
        if let Outcome::Measured { samples, .. } = r.library {
            if samples == 0 {
                problems.push(format!(
                    "{} / {}: no fragment",
                    r.model.name(),
                    r.case.name()
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // Seed failures that do not depend on the GPU: normalize(0) is 0 · inversesqrt(0) = NaN,
    // a swapped cone lights the outside, a 0×0 viewport divides by zero.
    let seed = |m: Model, c: Case| {
        rows.iter()
            .find(|r| r.model == m && r.case == c)
            .map(|r| r.seed.clone())
            .unwrap()
    };
    for m in [Model::SpotStep, Model::SpotLinear, Model::SpotSmooth] {
        assert!(!seed(m, Case::ZeroNormal).finite(), "{m:?}");
    }
    assert!(!seed(Model::SpotSmooth, Case::Swapped).ok());
    assert!(!seed(Model::Flashlight, Case::ZeroViewport).finite());
    assert!(!seed(Model::SpotProjected, Case::UpParallel).finite());
}
