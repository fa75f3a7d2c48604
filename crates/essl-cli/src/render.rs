//! `essl render SCENE.json -o OUT.png [--times N]`: renders a scene of the
//! `docs/scene-format.md` format through essl-gl's WebGL2 API and writes a PNG; prints one
//! JSON line like `webgl2-render.py` (scene, png, size, triangles, logs, warnings, ms per frame,
//! renderer), so that the two can be compared line for line.

use std::path::Path;

use serde_json::json;

/// Renders `scene` to `out` (PNG); `times` frames are timed after the first. Returns the exit
/// status: 0 rendered, 1 the scene's shaders do not compile or link or WebGL reports an error,
/// 2 the scene file is unreadable or malformed, or no adapter exists.
pub fn run(scene: &Path, out: &Path, times: usize) -> i32 {
    let loaded = match essl_scene::Scene::load(scene) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: cannot load `{}`: {e}", scene.display());
            return 2;
        }
    };
    let rendered = match essl_gl::scene::render_scene(&loaded, times) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: cannot render `{}`: {e}", scene.display());
            return match e {
                essl_gl::scene::SceneRenderError::Context(_) => 2,
                _ => 1,
            };
        }
    };
    if let Err(e) = rendered.image.write_png(out) {
        eprintln!("error: cannot write `{}`: {e}", out.display());
        return 2;
    }
    for w in &rendered.warnings {
        eprintln!("warning: {w}");
    }
    let compile_log: serde_json::Map<String, serde_json::Value> = rendered
        .compile_log
        .iter()
        .map(|(k, v)| (k.clone(), json!(v)))
        .collect();
    let line = json!({
        "scene": scene.display().to_string(),
        "png": out.display().to_string(),
        "width": rendered.image.width,
        "height": rendered.image.height,
        "triangles": rendered.triangles,
        "compile_log": compile_log,
        "link_log": rendered.link_log,
        "warnings": rendered.warnings,
        "ms_per_frame": rendered.ms_per_frame,
        "renderer": rendered.renderer,
    });
    println!("{line}");
    0
}
