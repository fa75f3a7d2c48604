//! Prints, for each shared seed scene: what the specialised generator emits for its library
//! equivalent (sizes, uniforms) next to the uber-shader, and how the float64 references agree
//! with Chromium's `reference/*.png`.
//!
//! `cargo run -p essl-lights --example seed_report [path/to/shared/scenes]`

use std::path::PathBuf;

use essl_lights::reference::{compare_rgba8, render, CompareOptions, Geometry, LitShader};
use essl_lights::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/scenes")
        });
    let uber = generate_uber();
    let (uv, uf) = uber.uniform_vectors();
    println!(
        "uber-shader: vs {} B, fs {} B, {} uniforms ({} samplers), {} scalars, vectors vs/fs {uv}/{uf}",
        uber.vertex.len(),
        uber.fragment.len(),
        uber.uniforms.len(),
        uber.sampler_count(),
        uber.uniform_scalars()
    );
    println!();
    println!("| scene | library program | vs B | fs B | uniforms (samplers) | scalars | vectors vs/fs | varyings | seed ref vs Chromium: max / rms / >1/255 px (silhouettes out) | library ref vs Chromium rms | mesh vs exact rms |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let opts = CompareOptions {
        ignore_silhouettes: true,
    };
    for name in [
        "spot-smooth",
        "spot-hard",
        "spot-linear",
        "spot-cookie",
        "phong-positional",
        "gouraud-lambert",
        "gouraud-lambert-coarse",
    ] {
        let scene = essl_scene::Scene::load(dir.join(format!("{name}.json")))?;
        let png = essl_scene::read_png(&dir.join(format!("reference/{name}.png")))?;
        let seed = seeds::seed_shader(&scene)?.expect("modelled");
        let seed_img = render(&scene, seed.as_ref(), Geometry::Mesh)?;
        let d = compare_rgba8(&png, &seed_img, opts)?;
        let lit = presets::seed_equivalent(&scene)?.expect("modelled");
        let p = generate(&lit)?;
        assert!(verify(&p).is_minimal());
        let view = View::of_scene(&scene);
        let u = uniform_values(&lit, &view)?;
        let lib_scene = bridge::to_scene(&scene.file, &p, &u)?;
        let shader = LitShader::new(&lit, &view)?;
        let lib_img = render(&lib_scene, &shader, Geometry::Mesh)?;
        let exact = render(&lib_scene, &shader, Geometry::Exact)?;
        let dl = compare_rgba8(&png, &lib_img, opts)?;
        let de = compare_rgba8(&lib_img.to_rgba8(), &exact, opts)?;
        let (vv, fv) = p.uniform_vectors();
        let header = p
            .fragment
            .lines()
            .nth(2)
            .unwrap_or("")
            .trim_start_matches("// essl-lights: ");
        println!(
            "| {name} | {header} | {} | {} | {} ({}) | {} | {vv}/{fv} | {} | {:.1} / {:.2} / {} | {:.2} | {:.2} |",
            p.vertex.len(),
            p.fragment.len(),
            p.uniforms.len(),
            p.sampler_count(),
            p.uniform_scalars(),
            p.varyings.len(),
            d.max,
            d.rms,
            d.over_one,
            dl.rms,
            de.rms,
        );
    }
    Ok(())
}
