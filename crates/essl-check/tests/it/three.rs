//! The `three` preset on three.js's own example shaders (`three/examples/jsm`, 0.187.0 as
//! `scripts/fetch-js-libs.sh` installs it): every shader object built as three.js's
//! WebGLProgram builds it, with an error exactly where Chromium reports one
//! (`tests/oracle/three-shaders.json`, written by `scripts/three-oracle.sh`) and the same active
//! uniforms and attributes where it links; the same for the materials the classes of
//! `examples/jsm` make (postprocessing passes, objects, lines, …), matched by where their
//! texts are written; a program whose `defines` the script computes is left unchecked with a
//! note; and errors planted in a material's shader, in an `#include <chunk>` and in a chunk
//! override reported on their lines.

use std::collections::BTreeMap;
use std::path::Path;

use essl::diagnostic::Severity;
use essl_check::{CheckOptions, CheckedUnit, Overrides, Preset, Run};

use crate::{check, lines};

fn three() -> Overrides {
    Overrides {
        preset: Some(Preset::Three),
        ..Overrides::default()
    }
}

/// The export a shader object of `file` is, as `FILE-EXPORT` (the oracle's name): the nearest
/// `NAME = {` before `at`.
fn export_name(file: &Path, at: usize) -> String {
    let text = std::fs::read_to_string(file).unwrap();
    let before = &text[..at];
    let open = before.rfind("= {").expect("an object before the shader");
    let name = before[..open]
        .trim_end()
        .rsplit(|c: char| !(c.is_alphanumeric() || c == '_'))
        .next()
        .unwrap();
    let stem = file.file_stem().unwrap().to_string_lossy();
    format!("{stem}-{name}")
}

/// Whether each stage of a program compiled, and whether it linked with its uniform and
/// attribute counts.
type Verdict = (bool, bool, Option<(usize, usize)>);

/// Each program of a run with its verdict, under the name `name` gives its vertex and
/// fragment shaders (none: left out); several programs may share a name.
fn verdicts(
    run: &Run<CheckedUnit>,
    name: impl Fn(&essl_check::CheckedShader, &essl_check::CheckedShader) -> Option<String>,
) -> BTreeMap<String, Vec<Verdict>> {
    let mut out: BTreeMap<String, Vec<Verdict>> = BTreeMap::new();
    for unit in &run.results {
        for p in &unit.programs {
            let (vs, fs) = (&unit.shaders[p.vertex], &unit.shaders[p.fragment]);
            let ok = |s: &essl_check::CheckedShader| !s.all().any(|(_, d)| d.is_error());
            let linked = p
                .program
                .as_ref()
                .filter(|prog| prog.ok && p.linked)
                .map(|prog| (prog.uniforms.len(), prog.attributes.len()));
            if let Some(n) = name(vs, fs) {
                out.entry(n).or_default().push((ok(vs), ok(fs), linked));
            }
        }
    }
    out
}

/// Chromium's answers (`tests/oracle/three-shaders.json`).
fn oracle() -> serde_json::Value {
    let path = essl_testdata::repo_root().join("tests/oracle/three-shaders.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn three_js_example_shaders_compile_and_link_as_in_chromium() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let oracle = oracle();
    let dir = js.join("node_modules/three/examples/jsm/shaders");
    let run = check(&dir, three(), CheckOptions::default());
    let checked = verdicts(&run, |vs, _| {
        Some(export_name(&vs.path, vs.embedded_at? as usize))
    });
    let unchecked: Vec<String> = lines(&dir, &run)
        .into_iter()
        .filter(|l| l.ends_with("preset-unchecked"))
        .collect();
    for (name, chromium) in oracle["programs"].as_object().unwrap() {
        let Some(&[(vs, fs, linked)]) = checked.get(name).map(Vec::as_slice) else {
            continue;
        };
        assert_eq!(vs, chromium["vertex_compiled"], "{name}: {chromium}");
        assert_eq!(fs, chromium["fragment_compiled"], "{name}: {chromium}");
        if chromium["linked"] == true {
            let (uniforms, attributes) = linked.expect(name);
            assert_eq!(uniforms as u64, chromium["uniforms"], "{name}");
            assert_eq!(attributes as u64, chromium["attributes"], "{name}");
        }
    }
    let missing: Vec<&String> = oracle["programs"]
        .as_object()
        .unwrap()
        .keys()
        .filter(|n| !checked.contains_key(*n))
        .collect();
    // Every shader object is checked but the one whose `defines` a function computes
    // (PoissonDenoiseShader's `SAMPLE_VECTORS`) and the one whose text is sliced from a chunk
    // (SubsurfaceScatteringShader), each with its note.
    assert_eq!(
        missing,
        [
            "PoissonDenoiseShader-PoissonDenoiseShader",
            "SubsurfaceScatteringShader-SubsurfaceScatteringShader"
        ]
    );
    assert_eq!(unchecked.len(), 2, "{unchecked:?}");
    assert!(unchecked[0].starts_with("PoissonDenoiseShader.js:"));
    assert!(unchecked[1].starts_with("SubsurfaceScatteringShader.js:"));
    // Chromium rejects three of them (its logs: `'SAMPLES' : undeclared identifier`, `global
    // variable initializers must be constant expressions`, `'sample' : Illegal use of reserved
    // word`, `'texture' : function name expected`); essl reports each on the author's line.
    let mut errors: Vec<String> = Vec::new();
    for s in run.results.iter().flat_map(|u| &u.shaders) {
        for (file, d) in s.all().filter(|(_, d)| d.severity == Severity::Error) {
            let lc = file.line_col(d.span.start);
            let name = Path::new(file.name()).strip_prefix(&dir).unwrap().display();
            errors.push(format!("{name}:{}:{} {}", lc.line, lc.column, d.code));
        }
    }
    errors.sort();
    assert_eq!(
        errors,
        [
            "BokehShader2.js:97:23 undeclared-identifier",
            "BokehShader2.js:98:21 undeclared-identifier",
            "FreiChenShader.js:47:16 non-constant-initializer",
            "FreiChenShader.js:79:9 reserved-word",
            "FreiChenShader.js:84:6 reserved-word",
            "FreiChenShader.js:85:33 reserved-word",
            "TriangleBlurShader.js:68:14 not-a-function",
        ]
    );
}

/// Where a shader's text is written: its file relative to `jsm` and the byte it starts at, as
/// `scripts/three-oracle.sh` writes it (`FILE@BYTE`).
fn written_at(jsm: &Path, s: &essl_check::CheckedShader) -> Option<String> {
    let file = s.path.strip_prefix(jsm).ok()?;
    Some(format!("{}@{}", file.display(), s.embedded_at?))
}

#[test]
fn three_js_example_materials_compile_and_link_as_in_chromium() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let oracle = oracle();
    let jsm = js.join("node_modules/three/examples/jsm");
    let run = check(&jsm, three(), CheckOptions::default());
    // Each program essl checked, by where its fragment shader's text is written.
    let by_fragment = verdicts(&run, |_, fs| written_at(&jsm, fs));
    let notes: Vec<String> = lines(&jsm, &run)
        .into_iter()
        .filter(|l| l.ends_with("preset-unchecked"))
        .collect();
    let noted = |file: &str| notes.iter().any(|l| l.starts_with(&format!("{file}:")));
    let (mut checked, mut computed, mut unchecked, mut differ) = (0, 0, Vec::new(), Vec::new());
    for (name, chromium) in oracle["materials"].as_object().unwrap() {
        let Some(fragment) = chromium["fragment"].as_str() else {
            // A text the script computes or rewrites (a ShaderLib entry, a joined array,
            // OutlinePass's DEPTH_TO_VIEW_Z replaced): not the text as written.
            computed += 1;
            continue;
        };
        let Some(verdicts) = by_fragment.get(fragment) else {
            // Texts as written but `defines` computed: a note in the class's file or in the
            // file the text is written in.
            let class_file = name.split('-').next().unwrap().replacen('_', "/", 1) + ".js";
            let text_file = fragment.split('@').next().unwrap();
            assert!(
                noted(&class_file) || noted(text_file),
                "{name}: no note: {notes:#?}"
            );
            unchecked.push(name.as_str());
            continue;
        };
        checked += 1;
        for &(vs, fs, linked) in verdicts {
            let counts = linked.map(|(u, a)| (u as u64, a as u64));
            let want = chromium["uniforms"]
                .as_u64()
                .zip(chromium["attributes"].as_u64());
            if vs != chromium["vertex_compiled"]
                || fs != chromium["fragment_compiled"]
                || (chromium["linked"] == true && counts != want)
            {
                differ.push(format!(
                    "{name}: essl {vs} {fs} {linked:?}, Chromium {chromium}"
                ));
            }
        }
    }
    assert!(differ.is_empty(), "{differ:#?}");
    // 41 materials: Chromium compiles and links every one; essl checks 29 of them with the same
    // verdicts and numbers of active uniforms and attributes, 3 have texts a script computes or rewrites,
    // and 9 have `defines` a script computes (BloomPass's kernel size, GTAOPass's Poisson
    // samples, OutlinePass's and UnrealBloomPass's kernels and mip counts).
    assert_eq!(
        (checked, computed, unchecked.len()),
        (29, 3, 9),
        "{unchecked:?}"
    );
}

/// A project in a temporary folder with the pinned three.js, its `src/` holding `files`.
fn project(js: &Path, files: &[(&str, &str)]) -> tempfile::TempDir {
    let project = tempfile::tempdir().unwrap();
    let root = project.path();
    std::os::unix::fs::symlink(js.join("node_modules"), root.join("node_modules")).unwrap();
    for (name, text) in files {
        let path = root.join("src").join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    project
}

const MATERIALS: &str = r#"import { ShaderMaterial, RawShaderMaterial, InstancedMesh } from 'three';
import { Wave } from './wave.js';

export const misspelt = new ShaderMaterial( {
	vertexShader: /* glsl */`
		#include <common>
		void main() {
			#include <begin_vertex>
			#include <project_vertx>
			gl_Position = projectionMatrix * mvPosition;
		}`,
	fragmentShader: /* glsl */`void main() { gl_FragColor = vec4( 1.0 ); }`,
} );

export const outside = new ShaderMaterial( {
	defines: { SCALE: 2.0, USE_WAVE: true, OFF: false },
	vertexShader: Wave.vertexShader,
	fragmentShader: /* glsl */`
		#include <colorspace_fragment>
		void main() { gl_FragColor = vec4( vec3( SCALE ), 1.0 ); }`,
} );

export const raw = new RawShaderMaterial( {
	vertexShader: /* glsl */`
		uniform mat4 modelViewMatrix;
		uniform mat4 projectionMatrix;
		attribute vec3 position;
		void main() { gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 ); }`,
	fragmentShader: /* glsl */`
		precision mediump float;
		void main() { gl_FragColor = vec4( colour, 1.0 ); }`,
} );

export function instanced( count ) {
	const material = new ShaderMaterial( {
		defines: { COUNT: count },
		vertexShader: /* glsl */`void main() { gl_Position = instanceMatrix * vec4( position, 1.0 ); }`,
		fragmentShader: /* glsl */`void main() { gl_FragColor = vec4( 1.0 ); }`,
	} );
	return new InstancedMesh( undefined, material, count );
}
"#;

const WAVE: &str = r#"export const Wave = {
	vertexShader: /* glsl */`
		varying vec2 vUv;
		void main() {
			vUv = uv;
			#ifdef USE_WAVE
			gl_Position = projectionMatrix * modelViewMatrix * vec4( position * SCALE, 1.0 );
			#endif
			#ifdef OFF
			gl_Position = undefinedName;
			#endif
		}`,
	fragmentShader: /* glsl */`void main() { gl_FragColor = vec4( 0.0 ); }`,
};
"#;

const CHUNK: &str = r#"import { ShaderChunk } from 'three';

ShaderChunk.lights_fragment_begin = /* glsl */`
	vec3 total = vec3( 0.0 );
#if NUM_DIR_LIGHTS > 0
	total = directLight.color;
#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < 2; i ++ ) {
		total += vec3( float( UNROLLED_LOOP_INDEX ) );
	}
	#pragma unroll_loop_end
	vec3 broken = vec3( 1.0 ) +;
`;
"#;

#[test]
fn errors_planted_in_materials_and_chunks_are_on_their_lines() {
    let Some(js) = essl_testdata::js_libraries() else {
        return;
    };
    let project = project(
        &js,
        &[
            ("materials.js", MATERIALS),
            ("wave.js", WAVE),
            ("chunk.js", CHUNK),
        ],
    );
    let src = project.path().join("src");
    let run = check(&src, three(), CheckOptions::default());
    let found = lines(&src, &run);
    assert_eq!(
        found,
        [
            // The override's own text: a syntax error after the unrolled loop.
            "chunk.js:13:29 syntax-error",
            // `#include <colorspace_fragment>` outside `main`: its statement at global scope.
            "materials.js:19:1 unknown-type",
            // A raw material's undeclared name.
            "materials.js:31:38 undeclared-identifier",
            // `defines: { COUNT: count }`: known only when the script runs.
            "materials.js:35:39 preset-unchecked",
            // `#include <project_vertx>`: no such chunk.
            "materials.js:9:1 preset-assembly",
            // `SCALE: 2.0` is written `#define SCALE 2` by three.js: an int times a vec3.
            "wave.js:7:61 invalid-operands",
        ]
    );
}
