//! The `luma` preset on deck.gl's own layers (`@deck.gl/layers` 9.4.0 `src/`, with the
//! luma.gl 9.4.2 that `scripts/fetch-js-libs.sh` installs): every layer's program assembled as
//! luma.gl assembles it, compiled and linked with no error where Chromium compiles and links
//! it (`tests/oracle/deck-layers.json`, written by `scripts/deck-oracle.sh`), with the same
//! active uniforms and attributes; and an error planted in a layer's shader reported on its
//! line.

use std::path::{Path, PathBuf};

use essl_check::{CheckOptions, Overrides, Preset};

use crate::{check, lines};

fn luma() -> Overrides {
    Overrides {
        preset: Some(Preset::Luma),
        ..Overrides::default()
    }
}

fn layers(js: &Path) -> PathBuf {
    js.join("node_modules/@deck.gl/layers/src")
}

/// A program's name as the oracle script names it: `scatterplot-layer-vertex.glsl.ts` →
/// `scatterplot`, `solid-polygon-layer-vertex-top.glsl.ts` → `solid-polygon-top`.
fn program_name(vertex: &Path) -> String {
    let file = vertex.file_name().unwrap().to_string_lossy();
    let stem = file.split('.').next().unwrap();
    stem.replace("-layer-vertex", "")
}

#[test]
fn deck_gl_layers_compile_and_link_as_in_chromium() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let oracle: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(essl_testdata::repo_root().join("tests/oracle/deck-layers.json"))
            .unwrap(),
    )
    .unwrap();
    let dir = layers(&js);
    let run = check(&dir, luma(), CheckOptions::default());
    // Lint findings read one by one in deck.gl's code, kept here so that a change shows:
    // - the haversine `a` of the arc layer is negative only for latitudes beyond ±90°;
    // - the multi-icon layer's `fragColor`, unwritten in picking mode, is read by
    //   `DECKGL_FILTER_COLOR`, whose picking hook replaces it: read, never shown;
    // - the solid polygon layer's top shader with `IS_SIDE_VERTEX` defined (a configuration
    //   deck.gl builds only from the side shader): `normalize` of its constant normal times
    //   `project.commonUnitsPerWorldUnit` is zero only for a zero scale (a note).
    // (The path layer's `rotationMatrix`, written by `project_needs_rotation` exactly where
    // `needsRotation = !billboard && project_needs_rotation(…)` holds, is not reported: the
    // analysis follows what a `bool` local set once says.)
    // The library's own files are named by their path under `node_modules`.
    const KNOWN: [&str; 3] = [
        "arc-layer/arc-layer-vertex.glsl.ts:86:26 domain-sqrt",
        "text-layer/multi-icon-layer/multi-icon-layer-fragment.glsl.ts:49:23 uninitialised-read",
        "solid-polygon-layer/solid-polygon-layer-vertex-main.glsl.ts:24:22 normalize-zero",
    ];
    let found = lines(&dir, &run);
    for known in KNOWN {
        assert!(
            found.iter().any(|l| l.ends_with(known)),
            "{known} is no longer reported"
        );
    }
    let errors: Vec<String> = found
        .into_iter()
        .filter(|l| {
            !KNOWN.iter().any(|k| l.ends_with(k))
                && !l.contains("asin-domain")
                && !l.contains("division")
                && !l.contains("smoothstep")
        })
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let mut linked = 0;
    for unit in &run.results {
        for p in &unit.programs {
            let vs = &unit.shaders[p.vertex];
            let name = program_name(&vs.path);
            let chromium = &oracle["programs"][&name];
            assert_eq!(chromium["linked"], true, "{name}: {chromium}");
            let program = p.program.as_ref().unwrap();
            assert!(program.ok && p.linked, "{name}: {}", program.log);
            assert_eq!(
                program.uniforms.len() as u64,
                chromium["uniforms"],
                "{name}"
            );
            assert_eq!(
                program.attributes.len() as u64,
                chromium["attributes"],
                "{name}"
            );
            linked += 1;
        }
    }
    // Every layer with shaders of its own (grid-cell draws with column's).
    assert_eq!(linked, 12);
}

#[test]
fn an_error_planted_in_a_layer_shader_is_on_its_line() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let project = tempfile::tempdir().unwrap();
    let root = project.path();
    std::os::unix::fs::symlink(js.join("node_modules"), root.join("node_modules")).unwrap();
    let from = layers(&js).join("scatterplot-layer");
    let to = root.join("src/scatterplot-layer");
    std::fs::create_dir_all(&to).unwrap();
    for entry in std::fs::read_dir(&from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
    }
    let vertex = to.join("scatterplot-layer-vertex.glsl.ts");
    let text = std::fs::read_to_string(&vertex).unwrap();
    let planted = text.replacen(
        "void main(void) {",
        "void main(void) {\n  vec3 n = normalise(vec3(1.0));",
        1,
    );
    assert_ne!(
        planted, text,
        "the layer's main is where the test expects it"
    );
    std::fs::write(&vertex, &planted).unwrap();
    let line = planted
        .lines()
        .position(|l| l.contains("normalise"))
        .unwrap()
        + 1;
    let run = check(&root.join("src"), luma(), CheckOptions::default());
    let errors: Vec<String> = lines(&root.join("src"), &run)
        .into_iter()
        .filter(|l| l.contains("undeclared"))
        .collect();
    assert_eq!(
        errors,
        [format!(
            "scatterplot-layer/scatterplot-layer-vertex.glsl.ts:{line}:12 undeclared-function"
        )]
    );
}

#[test]
fn luma_gl_modules_are_found_and_checked_as_chunks() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let dir = js.join("node_modules/@luma.gl/shadertools/src");
    let configs = essl_check::Configs::new(luma());
    let found = essl_check::find(
        std::slice::from_ref(&dir),
        &essl_check::FindOptions::new(),
        &configs,
    )
    .unwrap();
    // The two literals left are built from a function's parameters (`${primaryPrefix}`), known
    // only when the function runs.
    assert_eq!(found.skipped.len(), 2, "{:?}", found.skipped);
    let run = check(&dir, luma(), CheckOptions::default());
    let shaders: usize = run.results.iter().map(|u| u.shaders.len()).sum();
    assert!(shaders >= 40, "{shaders} shaders and chunks");
    let mut errors: Vec<String> = Vec::new();
    for unit in &run.results {
        for s in &unit.shaders {
            for (file, d) in s.all().filter(|(_, d)| d.is_error()) {
                let lc = file.line_col(d.span.start);
                let name = Path::new(file.name())
                    .strip_prefix(&dir)
                    .unwrap()
                    .display()
                    .to_string();
                errors.push(format!("{name}:{}:{} {}", lc.line, lc.column, d.code));
            }
        }
    }
    errors.sort();
    // Each is an error in luma.gl 9.4.2 itself: the lambert material's fragment code defines
    // `lighting_getLightColor(vec3, vec3, vec3, vec3)` twice (Chromium: "function already has
    // a body"), and the unexported `projection` module declares `varying`s beside a uniform
    // block, which no GLSL ES version has both of.
    assert_eq!(
        errors,
        [
            "modules/engine/project/project.ts:77:1 es100-qualifier",
            "modules/engine/project/project.ts:78:1 es100-qualifier",
            "modules/lighting/lambert-material/lambert-shaders-glsl.ts:25:6 function-redefined",
        ]
    );
}
