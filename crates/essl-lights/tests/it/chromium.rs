//! The float64 reference against Chromium: the shared seed scenes' own shaders, written as f64
//! closures (`essl_lights::seeds`), rendered by the reference renderer and compared with
//! `shared/scenes/reference/*.png` (Chromium, ANGLE on SwiftShader).
//!
//! Skips with a message when `../shared` is absent; fails then if the `CI` variable is set.

use std::path::PathBuf;

use essl_lights::reference::{compare_rgba8, render, CompareOptions, Geometry};
use essl_lights::seeds::seed_shader;

fn shared_scenes() -> Option<PathBuf> {
    essl_testdata::scenes()
}

/// (scene, largest error allowed away from silhouettes, pixels allowed past 1/255)
const SCENES: [(&str, f64, usize); 7] = [
    // The spot scenes have a few pixels at step thresholds: article 000's step(0.1, light)
    // specular gate, and spot-hard's step(u_limit, d) edge, where float32 and float64 fall on
    // different sides.
    ("spot-smooth", 255.0, 8),
    ("spot-hard", 255.0, 8),
    ("spot-linear", 255.0, 8),
    ("spot-cookie", 1.5, 0),
    ("phong-positional", 1.5, 4),
    ("gouraud-lambert", 1.5, 0),
    ("gouraud-lambert-coarse", 1.5, 0),
];

#[test]
fn seed_scenes_match_chromium() {
    let Some(dir) = shared_scenes() else { return };
    eprintln!("scene                   |  max  | rms  |  p99 | >1/255 px | silhouette px");
    for (name, max_allowed, over_allowed) in SCENES {
        let scene = essl_scene::Scene::load(dir.join(format!("{name}.json"))).unwrap();
        let shader = seed_shader(&scene).unwrap().expect("a modelled scene");
        let image = render(&scene, shader.as_ref(), Geometry::Mesh).unwrap();
        let png = essl_scene::read_png(&dir.join(format!("reference/{name}.png"))).unwrap();
        let all = compare_rgba8(&png, &image, CompareOptions::default()).unwrap();
        let d = compare_rgba8(
            &png,
            &image,
            CompareOptions {
                ignore_silhouettes: true,
            },
        )
        .unwrap();
        eprintln!(
            "{name:23} | {:5.1} | {:.2} | {:.2} | {:3} ({:.3}%) | {} (all pixels: max {:.1}, {} past 1/255)",
            d.max, d.rms, d.p99, d.over_one, d.over_one_percent, d.ignored, all.max, all.over_one
        );
        assert!(d.p99 <= 0.75, "{name}: {d:?}");
        assert!(d.rms <= 1.0, "{name}: {d:?}");
        assert!(d.max <= max_allowed, "{name}: {d:?}");
        assert!(d.over_one <= over_allowed, "{name}: {d:?}");
        // Everywhere, silhouettes included, only a handful of pixels differ.
        assert!(all.over_one_percent < 0.05, "{name}: {all:?}");
    }
}
