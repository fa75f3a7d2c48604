//! One case per GLSL ES 1.00 rule, and per rule of WebGL's own, in the annotated form of
//! `rules.rs` (expected diagnostics under the line they point at). Shaders without
//! `#version 300 es` are GLSL ES 1.00; cases compile for WebGL 2 unless they say WebGL 1.

use crate::annotated;

use annotated::{check, check_with};
use essl::{CompileOptions, Extension, Stage, Target};

fn webgl1(extensions: &[Extension]) -> CompileOptions {
    CompileOptions {
        target: Target::WebGl1,
        extensions: extensions.to_vec(),
        ..CompileOptions::default()
    }
}

#[test]
fn accepts_a_webgl1_program_as_tutorials_write_it() {
    check(
        Stage::Vertex,
        r#"attribute vec4 a_position;
attribute vec2 a_uv;
uniform mat4 u_matrix;
varying vec2 v_uv;
void main() {
    v_uv = a_uv;
    gl_Position = u_matrix * a_position;
    gl_PointSize = 1.0;
}
"#,
    );
    check(
        Stage::Fragment,
        r#"precision mediump float;
uniform sampler2D u_texture;
uniform samplerCube u_env;
uniform vec4 u_colors[4];
varying vec2 v_uv;
void main() {
    vec4 c = texture2D(u_texture, v_uv) + textureCube(u_env, vec3(v_uv, 1.0));
    for (int i = 0; i < 4; i++) {
        c += u_colors[i] * texture2DProj(u_texture, vec3(v_uv, 1.0), 0.5);
    }
    gl_FragColor = c;
}
"#,
    );
}

#[test]
fn es300_features_in_an_es100_shader() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
uniform int u_n;
uniform sampler2D u_s;
uniform Lights { vec4 color; };
      //^^^^^^ error not-in-es100: a uniform block is GLSL ES 3.00: this shader is GLSL ES 1.00
void main() {
    int a = u_n % 2;
          //^^^^^^^ error not-in-es100: the integer modulus operator `%` is GLSL ES 3.00: this shader is GLSL ES 1.00
    uint b = 1;
  //^^^^ error unknown-type: unknown type `uint`
    float c[2] = float[2](1.0, 2.0);
               //^^^^^^^^^^^^^^^^^^ error not-in-es100: an array initializer is GLSL ES 3.00: this shader is GLSL ES 1.00
    gl_FragColor = texture(u_s, vec2(0.0));
                 //^^^^^^^ error undeclared-function: no function named `texture` is declared
}
"#,
    );
}

#[test]
fn es100_features_in_an_es300_shader() {
    check(
        Stage::Fragment,
        r#"#version 300 es
precision mediump float;
uniform sampler2D s;
  varying vec2 v_uv;
//^^^^^^^ error es100-qualifier: `varying` is GLSL ES 1.00 and is reserved in GLSL ES 3.00
out vec4 o;
void main() {
    o = texture2D(s, v_uv);
      //^^^^^^^^^ error undeclared-function: no function named `texture2D` is declared
}
"#,
    );
}

#[test]
fn attribute_and_varying_types() {
    check(
        Stage::Vertex,
        r#"attribute int a_index;
        //^^^ error invalid-interface-type: an `attribute` cannot be a `bool` or an integer
attribute vec4 a_corners[4];
             //^^^^^^^^^ error not-in-es100: GLSL ES 1.00 cannot declare `attribute` arrays
struct S { float x; };
varying S v_s;
      //^ error invalid-interface-type: a `varying` cannot be a struct
varying vec2 v_uv[2];
void main() {
    v_uv[0] = vec2(0.0);
    v_uv[1] = vec2(1.0);
    gl_Position = vec4(0.0);
}
"#,
    );
}

#[test]
fn appendix_a_loops() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
uniform int u_n;
void main() {
    float s = 0.0;
    for (int i = 0; i < 8; i += 2) { s += 1.0; }
    for (float f = 4.0; f >= 0.0; f--) { s += f; }
    const int N = 3;
    for (int i = 0; i < N + 1; ++i) { s += 1.0; }
    for (int i = 0; i < u_n; i++) { s += 1.0; }
                      //^^^ error unsupported-loop: the loop index must be compared with a constant expression
    for (int i = 0; i < 4; i = i + 1) { s += 1.0; }
                         //^^^^^^^^^ error unsupported-loop: the step must be `i++`, `i--`, `++i`, `--i`, `i += CONST` or `i -= CONST` on the loop index
    for (int i = 0; i < 4; i++) {
        if (s > 2.0) i = 4;
                   //^ error loop-index-assigned: the loop index `i` cannot be written in the loop's body
    }
    int k = 0;
    while (k < 4) { k++; }
  //^^^^^^^^^^^^^^^^^^^^^^ error unsupported-loop: `while` loops are not allowed in GLSL ES 1.00 for WebGL
    gl_FragColor = vec4(s);
}
"#,
    );
}

#[test]
fn appendix_a_indices() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
uniform vec4 u_colors[8];
uniform sampler2D u_tex[2];
uniform int u_n;
int pick(int i) { return i; }
void main() {
    vec4 c = vec4(0.0);
    for (int i = 0; i < 3; i++) {
        c += u_colors[i * 2 + 1] + texture2D(u_tex[i / 2], vec2(0.5));
        c += u_colors[pick(i)];
                    //^^^^^^^ error non-constant-index: an index cannot contain a call to a user function
    }
    c += u_colors[u_n];
                //^^^ error non-constant-index: `u_n` is not a constant
    gl_FragColor = c;
}
"#,
    );
    // A vertex shader may index its uniforms with anything, and nothing else.
    check(
        Stage::Vertex,
        r#"attribute float a_index;
uniform mat4 u_bones[8];
void main() {
    int i = int(a_index);
    vec4 p = vec4(1.0);
    gl_Position = u_bones[i] * p;
    gl_Position.x += p[i];
                     //^ error non-constant-index: `i` is neither a constant nor a loop index
}
"#,
    );
}

#[test]
fn frag_color_or_frag_data() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
invariant gl_FragColor;
void main() {
    gl_FragColor = vec4(1.0);
    gl_FragData[0] = vec4(0.0);
  //^^^^^^^^^^^ error frag-color-and-frag-data: a fragment shader cannot use both `gl_FragColor` and `gl_FragData`
}
"#,
    );
}

#[test]
fn webgl1_extensions_where_the_context_and_the_shader_enable_them() {
    let src = r#"#extension GL_OES_standard_derivatives : enable
#extension GL_EXT_frag_depth : enable
#extension GL_EXT_draw_buffers : require
#extension GL_EXT_shader_texture_lod : enable
precision mediump float;
uniform sampler2D s;
varying vec2 v_uv;
void main() {
    gl_FragData[1] = vec4(fwidth(v_uv), 0.0, 1.0) + texture2DLodEXT(s, v_uv, 1.0);
    gl_FragDepthEXT = 0.5;
}
"#;
    check_with(Stage::Fragment, src, &webgl1(&Extension::ALL));
    // The same shader in a WebGL 1 context that enabled none of them.
    check_with(
        Stage::Fragment,
        r#"#extension GL_OES_standard_derivatives : enable
         //^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning extension-not-supported: extension `GL_OES_standard_derivatives` is not supported
precision mediump float;
varying vec2 v_uv;
void main() {
    gl_FragData[1] = vec4(fwidth(v_uv), 0.0, 1.0);
              //^ error extension-required: `gl_FragData` can only be indexed with 0 without `GL_EXT_draw_buffers`
                        //^^^^^^ error extension-required: `fwidth` needs the `OES_standard_derivatives` extension
}
"#,
        &webgl1(&[]),
    );
}

#[test]
fn webgl_global_initializers() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
uniform float u_scale;
varying float v_t;
float f() { return 1.0; }
float a = u_scale * 2.0;
        //^^^^^^^^^^^^^ warning non-constant-initializer: a global variable's initializer should be a constant expression
float b = f();
        //^^^ error non-constant-initializer: global variable initializers must be constant expressions
float c = v_t;
        //^^^ error non-constant-initializer: global variable initializers must be constant expressions
void main() { gl_FragColor = vec4(a + b + c); }
"#,
    );
}

#[test]
fn functions_prototypes_and_builtins() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
float g(float x);
float g(float x);
    //^ error function-redeclared: `g` is declared twice
float g(float x) { return x; }
float sin(int x) { return float(x); }
float cos(float x) { return x; }
    //^^^ error builtin-redeclared: `cos` redefines a built-in function
float round(float x) { return floor(x + 0.5); }
void main() { gl_FragColor = vec4(g(sin(1)) + sin(1.0) + round(0.5)); }
"#,
    );
}

#[test]
fn invariance() {
    check(
        Stage::Fragment,
        r#"precision mediump float;
invariant varying vec4 v_color;
varying vec4 v_other;
invariant v_other;
invariant gl_FragCoord;
invariant gl_FrontFacing;
        //^^^^^^^^^^^^^^ error invalid-invariant: `gl_FrontFacing` cannot be declared invariant
void main() { gl_FragColor = v_color + v_other + gl_FragCoord; }
"#,
    );
}

#[test]
fn variables_and_parameters_hide_struct_names() {
    // GLSL ES §4.2: a name in an inner scope hides a type name, and means the variable there.
    for version in ["", "#version 300 es\n"] {
        let out = if version.is_empty() {
            "gl_FragColor"
        } else {
            "o"
        };
        let decl = if version.is_empty() {
            ""
        } else {
            "out vec4 o;\n"
        };
        check(
            Stage::Fragment,
            &format!(
                r#"{version}precision mediump float;
{decl}struct S {{ float x; }};
struct T {{ S S; S t; }};
float f(S S) {{ return S.x; }}
void main() {{
    S S = S(1.0);
    S.x += f(S);
    {{
        float S = 2.0;
        {out} = vec4(S);
    }}
}}
"#
            ),
        );
    }
    check(
        Stage::Fragment,
        r#"precision mediump float;
struct S { float x; };
void main() {
    S S;
    S t;
  //^ error unknown-type: `S` is a variable here, not a type
    gl_FragColor = vec4(1.0);
}
"#,
    );
}

#[test]
fn webgl_limits_on_tokens_and_structs() {
    let long = "x".repeat(257);
    let src = format!(
        "precision mediump float;\nuniform float {long};\nvoid main() {{ gl_FragColor = vec4(1.0); }}\n"
    );
    let sh = essl::compile(
        essl::source::SourceFile::new("long", src.as_str()),
        Stage::Fragment,
        &webgl1(&[]),
    );
    assert_eq!(sh.diagnostics[0].code, "identifier-too-long");
    let sh = essl::compile(
        essl::source::SourceFile::new("long", src.as_str()),
        Stage::Fragment,
        &CompileOptions::default(),
    );
    assert!(
        sh.ok(),
        "WebGL 2 allows 1024 characters: {:?}",
        sh.diagnostics
    );
}

#[test]
fn webgl2_clip_distances_where_the_context_and_the_shader_enable_them() {
    let vs = r#"#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
in vec4 p;
void main() {
    gl_Position = p;
    for (int i = 0; i < gl_MaxClipDistances; i++) gl_ClipDistance[i] = p.x;
    if (gl_MaxCullDistances > 0) gl_CullDistance[0] = p.y;
}
"#;
    check_with(Stage::Vertex, vs, &CompileOptions::default());
    check_with(
        Stage::Fragment,
        r#"#version 300 es
#extension GL_ANGLE_clip_cull_distance : enable
precision mediump float;
out vec4 o;
void main() {
    o = vec4(gl_ClipDistance[0]);
    gl_ClipDistance[1] = 0.0;
  //^^^^^^^^^^^^^^^ error not-assignable: cannot assign to read-only built-in `gl_ClipDistance`
}
"#,
        &CompileOptions::default(),
    );
    // A WebGL 2 context that has not enabled WEBGL_clip_cull_distance.
    check_with(
        Stage::Vertex,
        r#"#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
         //^^^^^^^^^^^^^^^^^^^^^^^^^^^ error extension-not-supported: extension `GL_ANGLE_clip_cull_distance` is not supported
void main() {
    gl_ClipDistance[0] = 1.0;
  //^^^^^^^^^^^^^^^ error undeclared-identifier: `gl_ClipDistance` is not declared
}
"#,
        &CompileOptions {
            extensions: Vec::new(),
            ..CompileOptions::default()
        },
    );
}

#[test]
fn webgl2_conservative_depth_layouts_where_the_shader_enables_them() {
    let fs = |layout: &str, directive: bool| {
        format!(
            "#version 300 es\n{}precision mediump float;\nout vec4 o;\nlayout ({layout}) out float gl_FragDepth;\nvoid main() {{ o = vec4(1.0); gl_FragDepth = 0.5; }}\n",
            if directive {
                "#extension GL_EXT_conservative_depth : enable\n"
            } else {
                ""
            }
        )
    };
    let compile = |src: String| {
        essl::compile(
            essl::source::SourceFile::new("depth", src.as_str()),
            Stage::Fragment,
            &CompileOptions::default(),
        )
    };
    for layout in ["depth_any", "depth_greater", "depth_less"] {
        let sh = compile(fs(layout, true));
        assert!(sh.ok(), "{layout}: {:?}", sh.diagnostics);
        assert!(
            !compile(fs(layout, false)).ok(),
            "{layout} without the directive"
        );
    }
    // WebGL's EXT_conservative_depth has no depth_unchanged.
    let sh = compile(fs("depth_unchanged", true));
    assert!(!sh.ok());
    assert!(
        sh.diagnostics[0].message.contains("depth_any"),
        "{:?}",
        sh.diagnostics
    );
}

#[test]
fn draw_id_where_the_shader_enables_it_in_both_languages() {
    for (version, input) in [("#version 300 es\n", "in"), ("", "attribute")] {
        let vs = format!(
            "{version}#extension GL_ANGLE_multi_draw : require\n{input} vec4 p;\nvoid main() {{ gl_Position = p * float(gl_DrawID); }}\n"
        );
        let sh = essl::compile(
            essl::source::SourceFile::new("draw_id", vs.as_str()),
            Stage::Vertex,
            &CompileOptions::default(),
        );
        assert!(sh.ok(), "{version:?}: {:?}", sh.diagnostics);
        let fs = format!(
            "{version}#extension GL_ANGLE_multi_draw : require\nprecision mediump float;\nvoid main() {{ float d = float(gl_DrawID); }}\n"
        );
        let sh = essl::compile(
            essl::source::SourceFile::new("draw_id", fs.as_str()),
            Stage::Fragment,
            &CompileOptions::default(),
        );
        assert!(!sh.ok(), "gl_DrawID is a vertex shader's");
    }
}

#[test]
fn noperspective_where_the_shader_enables_it_and_both_stages_agree() {
    let vs = |q: &str| {
        format!("#version 300 es\n#extension GL_NV_shader_noperspective_interpolation : enable\n{q} out float v;\nin vec4 p;\nvoid main() {{ v = p.x; gl_Position = p; }}\n")
    };
    let fs = |q: &str| {
        format!("#version 300 es\n#extension GL_NV_shader_noperspective_interpolation : enable\nprecision highp float;\n{q} in float v;\nout vec4 o;\nvoid main() {{ o = vec4(v); }}\n")
    };
    let compile = |src: String, stage| {
        essl::compile(
            essl::source::SourceFile::new("np", src.as_str()),
            stage,
            &CompileOptions::default(),
        )
    };
    let (v, f) = (
        compile(vs("noperspective"), Stage::Vertex),
        compile(fs("noperspective"), Stage::Fragment),
    );
    assert!(v.ok() && f.ok(), "{:?} {:?}", v.diagnostics, f.diagnostics);
    assert!(essl::link::link(&v, &f).ok);
    let smooth = compile(fs(""), Stage::Fragment);
    let p = essl::link::link(&v, &smooth);
    assert!(!p.ok, "the qualifiers differ");
    assert!(
        p.log.contains("Interpolation types of varying 'v' differ"),
        "{}",
        p.log
    );
    let undirected = vs("noperspective").replace(
        "#extension GL_NV_shader_noperspective_interpolation : enable\n",
        "",
    );
    assert!(
        !compile(undirected, Stage::Vertex).ok(),
        "a reserved word without the directive"
    );
}
