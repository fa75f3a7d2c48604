//! The WGSL writer writes a value where it is used only where it cannot change in between.
//! One program per hazard: its text keeps the `let` that holds the value where naga
//! evaluates it, and the program drawn from the WGSL text (essl-gl through naga's WGSL front
//! end, on lavapipe) is green — the shader checks its own values, as GLSL defines them.
//! (The loop-carried value is checked on the IR: `wgsl::bake`'s unit tests.) The drawing
//! skips, with a message, without a Vulkan adapter unless `ESSL_REQUIRE_ADAPTER=1`.

use essl::source::SourceFile;
use essl::{CompileOptions, Stage};
use essl_gl::{gl, Context};

/// A triangle over the whole 4×4 framebuffer, from `gl_VertexID`.
const VERTEX: &str = "#version 300 es
void main() {
    vec2 p = vec2(float(gl_VertexID % 2) * 4.0 - 1.0, float(gl_VertexID / 2) * 4.0 - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
";

fn fragment(body: &str) -> String {
    format!(
        "#version 300 es
precision highp float;
out vec4 color;
float g = 1.0;
float twice() {{ g *= 2.0; return 0.0; }}
void main() {{
{body}
}}
"
    )
}

fn compile(text: &str, stage: Stage) -> essl::Shader {
    let s = essl::compile(
        SourceFile::new("hazard", text.to_owned()),
        stage,
        &CompileOptions::default(),
    );
    assert!(s.ok(), "{text}");
    s
}

/// The fragment shader's WGSL.
fn wgsl(body: &str) -> String {
    let vs = compile(VERTEX, Stage::Vertex);
    let fs = compile(&fragment(body), Stage::Fragment);
    let t = essl_translate::translate_program(&vs, &fs, &essl_translate::Options::default())
        .expect("translates");
    let text = t.fragment.as_text().expect("text").to_owned();
    essl_translate::roundtrip::read_wgsl(&text, Stage::Fragment).expect("reads back");
    text
}

/// The colour the program draws from its WGSL text; `None` without an adapter.
fn drawn(body: &str) -> Option<[u8; 4]> {
    let mut ctx = essl_testdata::with_adapter(|| Context::new(4, 4))?;
    let options = essl_translate::Options::default();
    ctx.set_program_filter(Some(Box::new(move |layout| {
        essl_translate::roundtrip::through_wgsl(layout, &options).map_err(|e| e.to_string())
    })));
    let program = ctx.create_program();
    for (ty, source) in [
        (gl::VERTEX_SHADER, VERTEX.to_owned()),
        (gl::FRAGMENT_SHADER, fragment(body)),
    ] {
        let s = ctx.create_shader(ty).expect("a shader");
        ctx.shader_source(s, &source);
        ctx.compile_shader(s);
        ctx.attach_shader(program, s);
    }
    ctx.link_program(program);
    ctx.use_program(Some(program));
    ctx.viewport(0, 0, 4, 4);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    let mut pixels = vec![0u8; 4 * 4 * 4];
    ctx.read_pixels(0, 0, 4, 4, gl::RGBA, gl::UNSIGNED_BYTE, &mut pixels);
    Some([pixels[20], pixels[21], pixels[22], pixels[23]])
}

const GREEN: [u8; 4] = [0, 255, 0, 255];

fn green_when(check: &str) -> String {
    format!("    color = ({check}) ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);")
}

#[test]
fn a_load_before_a_store_to_the_same_variable_stays_before_it() {
    // `x++` reads x, stores x + 1, and gives the value it read.
    let body = format!(
        "    float x = 1.0;\n    float y = x++;\n    float z = x;\n{}",
        green_when("y == 1.0 && z == 2.0")
    );
    let text = wgsl(&body);
    assert!(!text.contains("let y = x;"), "{text}");
    assert!(text.contains("let y = _e"), "{text}");
    if let Some(c) = drawn(&body) {
        assert_eq!(c, GREEN, "{text}");
    }
}

#[test]
fn a_load_stays_before_a_call_that_stores_to_it() {
    // `g += twice()` reads g (1.0), then twice() doubles it, then g = 1.0 + 0.0.
    let body = format!("    g += twice();\n{}", green_when("g == 1.0"));
    let text = wgsl(&body);
    assert!(!text.contains("g += twice()"), "{text}");
    assert!(text.contains("g = g + twice();"), "{text}");
    if let Some(c) = drawn(&body) {
        assert_eq!(c, GREEN, "{text}");
    }
}

#[test]
fn loads_and_calls_keep_their_order() {
    // Left to right: g (1.0), twice() (g becomes 2.0), g (2.0).
    let body = format!("    float s = g + twice() + g;\n{}", green_when("s == 3.0"));
    let text = wgsl(&body);
    assert!(text.contains("let s = g + twice() + g;"), "{text}");
    if let Some(c) = drawn(&body) {
        assert_eq!(c, GREEN, "{text}");
    }
}

#[test]
fn a_value_read_before_a_loop_is_not_read_again_in_it() {
    // The condition of the loop reads `n` once per iteration, as GLSL does; the body's `n++`
    // must not be folded into a value read before the loop.
    let body = format!(
        "    int n = 0;\n    int seen = 0;\n    for (int i = n++; i < 3; i++) {{ seen += n; n++; }}\n{}",
        green_when("seen == 1 + 2 + 3 && n == 4")
    );
    let text = wgsl(&body);
    // `i` starts from the value `n++` read, held in a `let` before the loop; the body reads
    // `n` afresh.
    assert!(text.contains("for (var i = _e"), "{text}");
    assert!(text.contains("seen += n;"), "{text}");
    if let Some(c) = drawn(&body) {
        assert_eq!(c, GREEN, "{text}");
    }
}
