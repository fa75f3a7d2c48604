//! Milliseconds per frame of every scene, essl-gl against Chromium's WebGL2, at 256² and 1024²:
//!
//! ```text
//! cargo run --release -p essl-gl --example bench_scenes [-- --times N] [--sizes 256,1024]
//!     [--repeat K] [--scenes DIR] [--tool webgl2-render.py] [--no-chromium]
//! ```
//!
//! A frame is what `webgl2-render.py --times N` times: `clear` + the draw + `readPixels` of one
//! pixel (which waits for the GPU), after one untimed frame read in full; the figure is the
//! median of N frames. essl-gl renders through `essl_gl::scene` (lavapipe here); Chromium
//! renders with the tool (ANGLE on SwiftShader), run in the same invocation, one scene after
//! the other. The 1024² variant of a scene is the scene with `width` and `height` overridden
//! (derived values such as `viewport` follow). Both renders of each variant are also compared
//! (pixels within 3/255, mean absolute error). With `--repeat K` each side is run K times,
//! alternating, and the lowest of its K medians is reported (other load on a shared machine
//! only ever slows a run down).

use std::path::{Path, PathBuf};
use std::process::Command;

use essl_gl::scene::render_scene;
use essl_scene::{compare, RgbaImage, Scene};

struct Options {
    times: usize,
    repeat: usize,
    sizes: Vec<u32>,
    scenes: PathBuf,
    tool: PathBuf,
    chromium: bool,
}

fn options() -> Options {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared");
    let mut o = Options {
        times: 50,
        repeat: 1,
        sizes: vec![256, 1024],
        scenes: shared.join("scenes"),
        tool: shared.join("tools/webgl2-render.py"),
        chromium: true,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || args.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--times" => o.times = value().parse().expect("--times N"),
            "--repeat" => o.repeat = value().parse::<usize>().expect("--repeat K").max(1),
            "--sizes" => {
                o.sizes = value()
                    .split(',')
                    .map(|s| s.parse().expect("--sizes 256,1024"))
                    .collect()
            }
            "--scenes" => o.scenes = value().into(),
            "--tool" => o.tool = value().into(),
            "--no-chromium" => o.chromium = false,
            _ => panic!("unknown argument {a} (see the example's header)"),
        }
    }
    o
}

/// The scene at `size`² (the file's own size when equal).
fn resized(scene: &Scene, size: u32) -> Scene {
    let mut file = scene.file.clone();
    file.width = size;
    file.height = size;
    Scene::build(
        file,
        scene.vertex_shader.clone(),
        scene.fragment_shader.clone(),
    )
    .expect("a valid scene stays valid at another size")
}

/// Runs the tool on `json` (with its shaders copied beside it in `dir`), returning its
/// `ms_per_frame`, its image and the renderer it names.
fn chromium(
    o: &Options,
    scene: &Scene,
    json: &serde_json::Value,
    dir: &Path,
    name: &str,
) -> Result<(f64, RgbaImage, String), String> {
    for s in [&scene.vertex_shader, &scene.fragment_shader] {
        std::fs::write(dir.join(&s.name), &s.source).map_err(|e| e.to_string())?;
    }
    let path = dir.join(format!("{name}.json"));
    std::fs::write(&path, json.to_string()).map_err(|e| e.to_string())?;
    let png = dir.join(format!("{name}.chromium.png"));
    let out = Command::new("python3")
        .arg(&o.tool)
        .arg(&path)
        .arg("-o")
        .arg(&png)
        .arg("--times")
        .arg(o.times.to_string())
        .output()
        .map_err(|e| format!("cannot run {}: {e}", o.tool.display()))?;
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).into_owned());
    }
    let line: serde_json::Value =
        serde_json::from_slice(&out.stdout).map_err(|e| format!("tool output: {e}"))?;
    let ms = line["ms_per_frame"].as_f64().ok_or("no ms_per_frame")?;
    let renderer = line["renderer"].as_str().unwrap_or("?").to_owned();
    let image = RgbaImage::read_png(&png).map_err(|e| e.to_string())?;
    Ok((ms, image, renderer))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    let o = options();
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&o.scenes)?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<_, _>>()?;
    paths.retain(|p| p.extension().is_some_and(|e| e == "json"));
    paths.sort();
    let tmp = std::env::temp_dir().join(format!("essl-gl-bench-{}", std::process::id()));
    std::fs::create_dir_all(&tmp)?;

    let mut renderers = (String::new(), String::new());
    println!(
        "| scene | size | triangles | essl-gl ms | Chromium ms | Chromium / essl-gl | pixels within 3/255 | MAE/255 |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|");
    let mut ratios = Vec::new();
    for path in &paths {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let scene = Scene::load(path)?;
        let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path)?)?;
        for &size in &o.sizes {
            let scene = resized(&scene, size);
            let mut json = json.clone();
            json["width"] = size.into();
            json["height"] = size.into();
            let (mut ms, mut cms) = (f64::INFINITY, f64::INFINITY);
            let (mut ours, mut theirs) = (None, None);
            for _ in 0..o.repeat {
                let r = render_scene(&scene, o.times)?;
                ms = ms.min(r.ms_per_frame.unwrap_or(f64::NAN));
                renderers.0 = r.renderer.clone();
                ours = Some(r);
                if o.chromium {
                    match chromium(&o, &scene, &json, &tmp, &format!("{name}-{size}")) {
                        Ok((t, image, renderer)) => {
                            cms = cms.min(t);
                            renderers.1 = renderer;
                            theirs = Some(image);
                        }
                        Err(e) => eprintln!("{name} at {size}²: Chromium failed: {e}"),
                    }
                }
            }
            let ours = ours.expect("repeat ≥ 1");
            let (theirs, ratio, within, mae) = match theirs {
                Some(image) => {
                    let d = compare(&ours.image, &image, 3)?;
                    ratios.push(cms / ms);
                    (
                        format!("{cms:.3}"),
                        format!("{:.1}×", cms / ms),
                        format!("{:.3}%", d.fraction_within() * 100.0),
                        format!("{:.4}", d.mean_abs),
                    )
                }
                None => ("—".into(), "—".into(), "—".into(), "—".into()),
            };
            println!(
                "| {name} | {size}² | {} | {ms:.3} | {theirs} | {ratio} | {within} | {mae} |",
                ours.triangles
            );
        }
    }
    if !ratios.is_empty() {
        ratios.sort_by(f64::total_cmp);
        println!(
            "\nChromium / essl-gl: min {:.1}×, median {:.1}×, max {:.1}× ({} variants, best of {} runs of {} frames)",
            ratios[0],
            ratios[ratios.len() / 2],
            ratios[ratios.len() - 1],
            ratios.len(),
            o.repeat,
            o.times
        );
    }
    println!(
        "essl-gl: {}; Chromium: {}",
        renderers.0,
        if renderers.1.is_empty() {
            "not run"
        } else {
            &renderers.1
        }
    );
    let _ = std::fs::remove_dir_all(&tmp);
    Ok(())
}
