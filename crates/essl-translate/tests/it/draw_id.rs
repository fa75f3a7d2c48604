//! `gl_DrawID` (`GL_ANGLE_multi_draw`), which WGSL lacks, translates to a member of the loose
//! uniforms' buffer that the binding map names `draw_id`, for the host to write before each
//! draw; a shader of either language.

use essl::source::SourceFile;
use essl::{CompileOptions, Stage};

const VERT_300: &str = "#version 300 es
#extension GL_ANGLE_multi_draw : require
uniform float u_scale;
in vec2 p;
flat out int id;
void main() {
    id = gl_DrawID;
    gl_Position = vec4(p * u_scale, float(gl_DrawID), 1.0);
}
";

const FRAG_300: &str = "#version 300 es
precision highp float;
flat in int id;
out vec4 o;
void main() { o = vec4(float(id)); }
";

const VERT_100: &str = "#extension GL_ANGLE_multi_draw : require
attribute vec2 p;
void main() { gl_Position = vec4(p, float(gl_DrawID), 1.0); }
";

const FRAG_100: &str = "precision mediump float;
void main() { gl_FragColor = vec4(1.0); }
";

fn compile(text: &str, stage: Stage) -> essl::Shader {
    let s = essl::compile(
        SourceFile::new("draw_id", text.to_owned()),
        stage,
        &CompileOptions::default(),
    );
    assert!(s.ok(), "{:?}", s.diagnostics);
    s
}

#[test]
fn draw_id_is_a_uniform_the_binding_map_names() {
    for (vs, fs) in [(VERT_300, FRAG_300), (VERT_100, FRAG_100)] {
        let (vs, fs) = (compile(vs, Stage::Vertex), compile(fs, Stage::Fragment));
        let t = essl_translate::translate_program(&vs, &fs, &essl_translate::Options::default())
            .expect("translates");
        let vertex = t.vertex.as_text().expect("text");
        essl_translate::roundtrip::read_wgsl(vertex, Stage::Vertex).expect("reads back");
        assert!(vertex.contains("draw_id: i32"), "{vertex}");
        assert!(
            vertex.contains("the host writes gl_DrawID here"),
            "{vertex}"
        );
        let internal: Vec<_> = t
            .bindings
            .internal
            .iter()
            .map(|i| (i.value.as_str(), i.offset))
            .collect();
        // After the shader's own uniforms (u_scale at 0 in the first pair).
        let expected = if vertex.contains("u_scale") { 4 } else { 0 };
        assert_eq!(internal, [("draw_id", expected)], "{vertex}");
    }
}

#[test]
fn draw_id_needs_the_directive() {
    let s = essl::compile(
        SourceFile::new(
            "draw_id",
            "#version 300 es\nvoid main() { gl_Position = vec4(float(gl_DrawID)); }\n".to_owned(),
        ),
        Stage::Vertex,
        &CompileOptions::default(),
    );
    assert!(!s.ok());
    assert!(
        s.diagnostics
            .iter()
            .any(|d| d.message.contains("gl_DrawID")),
        "{:?}",
        s.diagnostics
    );
}
