//! `gl_ClipDistance` (`GL_ANGLE_clip_cull_distance`) translates with essl's own WGSL writer:
//! the module names the `clip_distances` extension before its declarations, naga's WGSL front
//! end reads it back, and the fragment stage reads the distances from the varyings the vertex
//! stage writes them to.

use essl::source::SourceFile;
use essl::{CompileOptions, Stage};

const VERT: &str = "#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
in vec2 p;
void main() {
    gl_Position = vec4(p, 0.0, 1.0);
    gl_ClipDistance[0] = p.x + 0.5;
}
";

const FRAG: &str = "#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
precision highp float;
out vec4 o;
void main() { o = vec4(gl_ClipDistance[0]); }
";

fn compile(text: &str, stage: Stage) -> essl::Shader {
    let s = essl::compile(
        SourceFile::new("clip", text.to_owned()),
        stage,
        &CompileOptions::default(),
    );
    assert!(s.ok(), "{:?}", s.diagnostics);
    s
}

#[test]
fn clip_distances_are_written_by_essls_own_writer() {
    let (vs, fs) = (compile(VERT, Stage::Vertex), compile(FRAG, Stage::Fragment));
    let t = essl_translate::translate_program(&vs, &fs, &essl_translate::Options::default())
        .expect("translates");
    let vertex = t.vertex.as_text().expect("text");
    let fragment = t.fragment.as_text().expect("text");
    for (text, stage) in [(vertex, Stage::Vertex), (fragment, Stage::Fragment)] {
        assert!(!text.contains("Written by naga's WGSL writer"), "{text}");
        essl_translate::roundtrip::read_wgsl(text, stage).expect("reads back");
    }
    assert!(vertex.contains("enable clip_distances;"), "{vertex}");
    assert!(vertex.contains("@builtin(clip_distances)"), "{vertex}");
    assert!(!fragment.contains("clip_distances"), "{fragment}");
    assert!(fragment.contains("gl_ClipDistance_0"), "{fragment}");
}
