//! The shared scenes drawn from their WGSL translation are the scenes drawn from essl's IR,
//! pixel for pixel: essl-gl links each program, writes both stages as WGSL (names, comments,
//! `@size` attributes and all), reads the text back with naga's WGSL front end and draws from
//! that. Skips, with a message, without the scenes or a Vulkan adapter, unless
//! `ESSL_REQUIRE_CORPORA=1` / `ESSL_REQUIRE_ADAPTER=1`.

use essl_gl::scene::SceneRenderer;
use essl_gl::Context;
use essl_scene::Scene;

fn draw(scene: &Scene, via_wgsl: bool) -> Option<Vec<u8>> {
    let mut ctx = essl_testdata::with_adapter(|| Context::new(scene.width(), scene.height()))?;
    if via_wgsl {
        let options = essl_translate::Options::default();
        ctx.set_program_filter(Some(Box::new(move |layout| {
            essl_translate::roundtrip::through_wgsl(layout, &options).map_err(|e| e.to_string())
        })));
    }
    let mut r = SceneRenderer::with_context(ctx, scene).expect("the scene sets up");
    r.frame();
    Some(r.read_image().expect("the frame reads back").data)
}

#[test]
fn scenes_from_wgsl_are_the_scenes_from_ir() {
    let Some(dir) = essl_testdata::scenes() else {
        return;
    };
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .expect("the scenes folder lists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no scene in {}", dir.display());
    for path in names {
        let scene = Scene::load(&path).expect("the scene loads");
        let Some(ir) = draw(&scene, false) else {
            return;
        };
        let wgsl = draw(&scene, true).expect("an adapter, as a moment ago");
        let lit = ir.chunks(4).filter(|p| p[..3] != [0, 0, 0]).count();
        assert!(lit > 100, "{}: only {lit} lit pixels", path.display());
        let differ = ir.iter().zip(&wgsl).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "{}: {differ} bytes differ", path.display());
        println!("{}: identical ({lit} lit pixels)", path.display());
    }
}
