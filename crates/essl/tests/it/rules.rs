//! One case per GLSL ES 3.00 / WebGL2 rule. Each case is a shader whose expected diagnostics
//! are written under the line they point at, as rust-analyzer's tests do:
//!
//! ```text
//!   float x = 1;
//!           //^ error type-mismatch: cannot initialize a `float` with a `int`
//! ```
//!
//! The carets sit under the primary span (a `|` marks an empty span, an insertion point; a
//! span that runs past its line is marked to the line's end), followed by the severity, the
//! code and the message. Several annotations may follow one line, in the order of the
//! diagnostics. A span that starts in the first two columns leaves no room for the `//`:
//! indent the line. Cases with no annotation must compile cleanly.
//!
//! The check renders the annotations of the diagnostics the shader produces into its text
//! and compares the result with the case, so that a failure shows the case as it would pass.

use crate::annotated;

use annotated::{annotate, check};
use essl::diagnostic::Diagnostic;
use essl::source::SourceFile;
use essl::{compile, Stage};

fn frag(body: &str) -> String {
    format!("#version 300 es\nprecision mediump float;\nout vec4 o;\n{body}")
}

#[test]
fn annotations_mark_spans_and_empty_spans() {
    let src = "  float x = 1\n";
    let d = Diagnostic::error(
        essl::diagnostic_code::Code::MissingSemicolon,
        "expected `;`",
        essl::source::Span::empty(13),
    );
    assert_eq!(
        annotate(src, &[d]),
        "  float x = 1\n           //| error missing-semicolon: expected `;`\n"
    );
    let d = Diagnostic::rule_warning("w", "m", essl::source::Span::new(8, 9));
    assert_eq!(
        annotate(src, &[d]),
        "  float x = 1\n      //^ warning w: m\n"
    );
}

#[test]
fn accepts_precision_qualifiers_everywhere_es_allows_them() {
    check(
        Stage::Fragment,
        &frag(
            r#"highp float f(mediump float x, lowp int n) { return x * float(n); }
void main() { precision highp float; o = vec4(f(1.0, 2)); }
"#,
        ),
    );
}

#[test]
fn accepts_loose_uniforms_of_every_type() {
    check(
        Stage::Fragment,
        &frag(
            r#"struct L { vec3 p; float k[2]; };
uniform float a; uniform vec2 b; uniform ivec3 c; uniform uvec4 d; uniform bool e; uniform bvec2 g;
uniform mat2 m2; uniform mat3x4 m34; uniform float arr[3]; uniform L l; uniform L ls[2];
void main() { o = vec4(a + b.x + float(c.x) + float(d.x) + (e ? 1.0 : 0.0) + (g.x ? 1.0 : 0.0) + m2[0][0] + m34[0][0] + arr[1] + l.p.x + ls[1].k[1]); }
"#,
        ),
    );
}

#[test]
fn accepts_uniform_blocks_and_unlocated_inputs_and_outputs() {
    check(
        Stage::Vertex,
        r#"#version 300 es
layout(std140) uniform Light { vec4 color; mat4 m; } light;
uniform Other { float k; };
in vec4 a_position;
in vec3 a_normal;
out vec3 v_normal;
flat out int v_id;
void main() { v_normal = a_normal * k; v_id = gl_VertexID + gl_InstanceID; gl_Position = light.m * a_position + light.color; }
"#,
    );
}

#[test]
fn accepts_every_sampler_type_including_as_parameters() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform sampler2D s2; uniform samplerCube sc; uniform highp sampler3D s3; uniform highp sampler2DArray sa;
uniform highp sampler2DShadow ss; uniform highp samplerCubeShadow scs; uniform highp sampler2DArrayShadow sas;
uniform highp isampler2D i2; uniform highp usampler3D u3; uniform highp isamplerCube ic; uniform highp usampler2DArray ua;
vec4 look(sampler2D t, vec2 uv) { return texture(t, uv); }
void main() {
  o = look(s2, vec2(0.5)) + texture(sc, vec3(1.0)) + texture(s3, vec3(0.5)) + texture(sa, vec3(0.5)) +
      vec4(texture(ss, vec3(0.5)) + texture(scs, vec4(0.5)) + texture(sas, vec4(0.5))) +
      vec4(texelFetch(i2, ivec2(0), 0)) + vec4(texelFetch(u3, ivec3(0), 0)) + vec4(textureSize(ic, 0).x) + vec4(texture(ua, vec3(0.5)));
}
"#,
        ),
    );
}

#[test]
fn accepts_defines_and_conditionals() {
    check(
        Stage::Fragment,
        r#"#version 300 es
#define SCALE 2.0
#if defined(GL_ES) && __VERSION__ == 300
precision highp float;
#else
#error not ES 3.00
#endif
out vec4 o;
void main() { o = vec4(SCALE); }
"#,
    );
}

#[test]
fn user_defines_come_from_the_api() {
    let src = r#"#version 300 es
precision highp float;
out vec4 o;
void main() { o = vec4(LIGHTS); }
"#;
    let opts = essl::CompileOptions {
        defines: vec![("LIGHTS".into(), "3.0".into())],
        ..essl::CompileOptions::default()
    };
    let sh = compile(SourceFile::new("t", src), Stage::Fragment, &opts);
    assert!(sh.ok(), "{:?}", sh.diagnostics);
    let without = compile(
        SourceFile::new("t", src),
        Stage::Fragment,
        &Default::default(),
    );
    assert_eq!(without.diagnostics[0].code, "undeclared-identifier");
}

// ----- what WebGL2 rejects -----

#[test]
fn implicit_conversions() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  float x = 1;
          //^ error type-mismatch: cannot initialize a `float` with a `int`
  uint u = 3;
         //^ error type-mismatch: cannot initialize a `uint` with a `int`
  o = vec4(x) * float(u);
}
"#,
        ),
    );
}

#[test]
fn missing_default_float_precision_in_a_fragment_shader() {
    check(
        Stage::Fragment,
        r#"#version 300 es
out vec4 o;
       //^ error missing-precision: no precision specified for `float`
void main() { o = vec4(1.0); }
"#,
    );
}

#[test]
fn samplers_without_default_precision() {
    check(
        Stage::Vertex,
        r#"#version 300 es
uniform sampler3D s;
                //^ error missing-precision: no precision specified for `sampler3D`
void main() { gl_Position = texture(s, vec3(0.0)); }
"#,
    );
}

#[test]
fn recursion_even_in_functions_never_called() {
    check(
        Stage::Fragment,
        &frag(
            r#"float g(float x);
float f(float x) { return g(x); }
float g(float x) { return f(x); }
    //^ error recursion: recursive call chain: g → f → g
void main() { o = vec4(1.0); }
"#,
        ),
    );
}

#[test]
fn reserved_words_and_names() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  float class = 1.0;
      //^^^^^ error reserved-word: `class` is a reserved word in GLSL ES 3.00
  float gl_x = 1.0;
      //^^^^ error reserved-name: `gl_x` starts with `gl_`, which is reserved for built-in names
  float a__b = 1.0;
      //^^^^ error reserved-name: `a__b` contains `__`, which is reserved in GLSL ES 3.00
  o = vec4(gl_x);
}
"#,
        ),
    );
}

#[test]
fn es100_names() {
    check(
        Stage::Vertex,
        r#"#version 300 es
  attribute vec4 a;
//^^^^^^^^^ error es100-qualifier: `attribute` is GLSL ES 1.00 and is reserved in GLSL ES 3.00
  varying vec4 v;
//^^^^^^^ error es100-qualifier: `varying` is GLSL ES 1.00 and is reserved in GLSL ES 3.00
uniform sampler2D s;
void main() { v = texture2D(s, a.xy); gl_Position = a; }
                //^^^^^^^^^ error undeclared-function: no function named `texture2D` is declared
"#,
    );
    check(
        Stage::Fragment,
        &frag(
            r#"void main() { gl_FragColor = vec4(1.0); }
            //^^^^^^^^^^^^ error undeclared-identifier: `gl_FragColor` is not declared
"#,
        ),
    );
}

#[test]
fn writes_to_uniforms_and_inputs() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform float u;
in float v;
void main() {
  u = 1.0;
//^ error not-assignable: cannot assign to uniform `u`
  v = 2.0;
//^ error not-assignable: cannot assign to input `v`
  o = vec4(u + v);
}
"#,
        ),
    );
}

#[test]
fn dynamic_sampler_indexing() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform sampler2D t[3];
uniform int k;
void main() {
  const int c = 1;
  o = texture(t[c + 1], vec2(0.0));
  for (int i = 0; i < 3; i++) { o += texture(t[i], vec2(0.0)); }
                                             //^ error dynamic-sampler-index: arrays of samplers can only be indexed with constant integral expressions
}
"#,
        ),
    );
}

#[test]
fn several_fragment_outputs_need_locations() {
    check(
        Stage::Fragment,
        r#"#version 300 es
precision mediump float;
out vec4 a;
       //^ error output-location-required: fragment output `a` needs a `layout(location = N)`
out vec4 b;
       //^ error output-location-required: fragment output `b` needs a `layout(location = N)`
void main() { a = vec4(1.0); b = a; }
"#,
    );
    check(
        Stage::Fragment,
        r#"#version 300 es
precision mediump float;
layout(location = 0) out vec4 a;
layout(location = 1) out vec4 b;
void main() { a = vec4(1.0); b = a; }
"#,
    );
}

#[test]
fn integer_varyings_must_be_flat() {
    check(
        Stage::Vertex,
        r#"#version 300 es
out int v_i;
      //^^^ error integer-varying-not-flat: an integer vertex shader output must be `flat`
void main() { v_i = 1; gl_Position = vec4(0.0); }
"#,
    );
    check(
        Stage::Fragment,
        &frag(
            r#"in uvec2 v_u;
       //^^^ error integer-varying-not-flat: an integer fragment shader input must be `flat`
void main() { o = vec4(v_u.x); }
"#,
        ),
    );
}

#[test]
fn version_must_be_on_the_first_line() {
    check(
        Stage::Fragment,
        r#"
  #version 300 es
//^^^^^^^^^^^^^^^ error version-not-first-line: `#version 300 es` must be on the first line of the shader
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0); }
"#,
    );
}

#[test]
fn wrong_overloads_of_builtins() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  vec3 v = vec3(1.0);
  o = vec4(pow(v, 2.0), 1.0);
         //^^^ error no-matching-overload: no overload of `pow` takes (`vec3`, `float`)
  o += vec4(smoothstep(v, v, 0.5), 1.0);
          //^^^^^^^^^^ error no-matching-overload: no overload of `smoothstep` takes (`vec3`, `vec3`, `float`)
  o += vec4(smoothstep(0.0, 1.0, v), 1.0);
}
"#,
        ),
    );
}

#[test]
fn missing_semicolons_are_reported_at_the_end_of_the_line_that_lacks_them() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform float a
             //| error missing-semicolon: expected `;` after the declaration
uniform float b;
void main() {
  float x = a + b
               //| error missing-semicolon: expected `;` after the declaration
  o = vec4(x);
}
"#,
        ),
    );
}

#[test]
fn every_syntax_error_in_one_run_without_cascades() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  float x = (1.0 + ;
                 //^ error syntax-error: expected an expression, found `;`
  float y = 2.0 * * 3.0;
                //^ error syntax-error: expected an expression, found `*`
  o = vec4(x + y);
}
"#,
        ),
    );
}

#[test]
fn discard_only_in_fragment_shaders() {
    check(
        Stage::Vertex,
        r#"#version 300 es
void main() { discard; gl_Position = vec4(0.0); }
            //^^^^^^^^ error discard-in-vertex: `discard` is only allowed in fragment shaders
"#,
    );
}

#[test]
fn constant_expressions() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform float u;
const float c = sin(1.0);
float g = u * 2.0;
        //^^^^^^^ error non-constant-initializer: global variable initializers must be constant expressions
void main() {
  float a[3];
  a[3] = c;
  //^ error index-out-of-range: index 3 is out of range for a array of 3
  int n = 1 / 0;
        //^^^^^ warning division-by-zero: division by zero in a constant expression
  o = vec4(a[0] + g + float(n));
}
"#,
        ),
    );
}

#[test]
fn swizzles() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  float f = 1.0;
  vec2 v = vec2(f);
  o.x = f.x;
        //^ error invalid-field: `float` has no fields: `.x` needs a struct or a vector
  o.y = v.xyzw.x;
        //^^^^ error invalid-swizzle: swizzle `xyzw` reads past the end of a 2-component vector
  o.z = v.xg.x;
        //^^ error invalid-swizzle: swizzle `xg` mixes component sets
  v.xx = vec2(1.0);
//^^^^ error not-assignable: a swizzle with repeated components cannot be assigned
}
"#,
        ),
    );
}

#[test]
fn switch_rules() {
    check(
        Stage::Fragment,
        &frag(
            r#"uniform int k;
void main() {
  switch (k) {
    case 1: o = vec4(1.0); break;
    case 1: break;
  //^^^^^^^ error duplicate-case: duplicate `case 1`
    default:
  }
//^ error label-at-end-of-switch: no statement between the last `case` label and the end of the `switch`
}
"#,
        ),
    );
}

#[test]
fn webgl_forbids_ternary_and_sequence_on_arrays() {
    check(
        Stage::Fragment,
        &frag(
            r#"void main() {
  float a[2]; float b[2];
  float c[2] = true ? a : b;
             //^^^^^^^^^^^^ error webgl-forbidden-operand: the ternary operator `?:` cannot select arrays in WebGL
  o = vec4(c[0]);
}
"#,
        ),
    );
}

#[test]
fn no_break_spaces_are_one_error_per_line_and_harmless_in_comments() {
    let src = "#version 300 es\u{a0}\nprecision mediump float; // note\u{a0}\nout vec4 o;\nvoid main() {\n\u{a0}\u{a0}o = vec4(1.0);\n}\n";
    let sh = compile(
        SourceFile::new("t", src),
        Stage::Fragment,
        &Default::default(),
    );
    let got: Vec<(u32, &str, usize)> = sh
        .diagnostics
        .iter()
        .map(|d| {
            (
                sh.file.line_col(d.span.start).line,
                d.severity.as_str(),
                d.fix.as_ref().map_or(0, |f| f.edits.len()),
            )
        })
        .collect();
    // Line 5's two adjacent no-break spaces are one run: one edit that writes two spaces.
    assert_eq!(got, [(1, "error", 1), (2, "warning", 1), (5, "error", 1)]);
}
