use super::*;
use crate::Target;

fn run(text: &str, stage: Stage) -> Minified {
    minify(text, stage, &MinifyOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn frag(text: &str) -> String {
    run(text, Stage::Fragment).text
}

#[test]
fn comments_and_white_space_go_directives_keep_their_lines() {
    let text = "#version 300 es // a light\n/* block */ precision   highp float;\n\
        #define   SCALE  2.0 // twice\nuniform vec4 u_color;\nout vec4 outColor;\n\
        void main() {\n  outColor = u_color * SCALE;  // scaled\n}\n";
    insta::assert_snapshot!(frag(text), @r"
    #version 300 es
    precision highp float;
    #define SCALE 2.0
    uniform vec4 u_color;out vec4 outColor;void main(){outColor=u_color*SCALE;}
    ");
}

#[test]
fn locals_parameters_and_functions_are_renamed_interface_names_kept() {
    let text =
        "#version 300 es\nprecision highp float;\nstruct Light { vec3 position; vec3 color; };\n\
        uniform Light u_light;\nuniform Block { mat4 u_view; } block;\nin vec3 v_normal;\n\
        out vec4 outColor;\nfloat lambert(vec3 normal, vec3 toLight) {\n\
          float amount = max(dot(normal, toLight), 0.0);\n  return amount;\n}\n\
        void main() {\n  vec3 normal = normalize(v_normal);\n\
          vec3 toLight = normalize(u_light.position - (block.u_view * vec4(normal, 1)).xyz);\n\
          outColor = vec4(u_light.color * lambert(normal, toLight), 1);\n}\n";
    let m = run(text, Stage::Fragment);
    insta::assert_snapshot!(m.text, @r"
    #version 300 es
    precision highp float;struct Light{vec3 position;vec3 color;};uniform Light u_light;uniform Block{mat4 u_view;}block;in vec3 v_normal;out vec4 outColor;float d(vec3 a,vec3 b){float c=max(dot(a,b),0.);return c;}void main(){vec3 a=normalize(v_normal);vec3 b=normalize(u_light.position-(block.u_view*vec4(a,1)).xyz);outColor=vec4(u_light.color*d(a,b),1);}
    ");
    let names: Vec<&str> = m.renamed.iter().map(|(a, _)| a.as_str()).collect();
    assert_eq!(names, ["amount", "lambert", "normal", "toLight"]);
}

#[test]
fn new_names_collide_with_nothing_in_the_text() {
    // `a` and `b` are uniforms, `c` a struct member, `d` a macro: none may be taken.
    let text = "#version 300 es\nprecision highp float;\n#define d 1.0\nstruct S { float c; };\n\
        uniform float a;\nuniform S b;\nout vec4 o;\n\
        void main() { float value = a + b.c * d; float other = value; o = vec4(other); }\n";
    let m = run(text, Stage::Fragment);
    for (_, new) in &m.renamed {
        assert!(!["a", "b", "c", "d", "o"].contains(&new.as_str()), "{new}");
    }
    assert_eq!(m.renamed.len(), 2);
}

#[test]
fn a_name_shared_with_a_member_or_global_is_kept() {
    let text = "#version 300 es\nprecision highp float;\nstruct S { float color; };\n\
        uniform S u;\nuniform float scale;\nout vec4 o;\nfloat f(float scale) { return scale; }\n\
        void main() { float color = u.color; o = vec4(f(color)); }\n";
    let m = run(text, Stage::Fragment);
    let names: Vec<&str> = m.renamed.iter().map(|(a, _)| a.as_str()).collect();
    assert_eq!(names, ["f"]);
}

#[test]
fn names_in_skipped_branches_and_directives_are_kept() {
    // Under other macros `map` is a uniform; `USE_MAP` is tested by `#ifdef`.
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\n\
        #ifdef USE_MAP\nuniform sampler2D map;\n#endif\n\
        void main() { float map = 1.0; float k = map * 2.0; o = vec4(k); }\n";
    let m = run(text, Stage::Fragment);
    assert_eq!(m.renamed, [("k".to_string(), "a".to_string())]);
    assert!(m
        .text
        .contains("#ifdef USE_MAP\nuniform sampler2D map;\n#endif\n"));
}

#[test]
fn macro_bodies_are_renamed_with_the_code_and_function_like_macros_stay() {
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\n\
        #define TWICE(value) ((value) * 2.0)\n#define OBJ (1.0)\n\
        float helper(float value) { return TWICE(value) + OBJ; }\n\
        void main() { o = vec4(helper(0.5)); }\n";
    insta::assert_snapshot!(frag(text), @r"
    #version 300 es
    precision highp float;out vec4 o;
    #define TWICE(a)((a)*2.0)
    #define OBJ (1.0)
    float b(float a){return TWICE(a)+OBJ;}void main(){o=vec4(b(.5));}
    ");
}

#[test]
fn es100_attributes_and_varyings_are_kept() {
    let text = "attribute vec4 a_position;\nattribute vec2 a_uv;\nvarying vec2 v_uv;\n\
        uniform mat4 u_matrix;\nvec4 project(vec4 position) { return u_matrix * position; }\n\
        void main() {\n  // pass the coordinates on\n  v_uv = a_uv;\n  gl_Position = project(a_position);\n}\n";
    let options = MinifyOptions {
        compile: CompileOptions::for_target(Target::WebGl1),
        rename: true,
    };
    let m = minify(text, Stage::Vertex, &options).unwrap();
    insta::assert_snapshot!(m.text, @"attribute vec4 a_position;attribute vec2 a_uv;varying vec2 v_uv;uniform mat4 u_matrix;vec4 b(vec4 a){return u_matrix*a;}void main(){v_uv=a_uv;gl_Position=b(a_position);}");
}

#[test]
fn es100_extension_and_pragma_lines_stay_first() {
    let text = "#extension GL_OES_standard_derivatives : enable\n#pragma optimize(off)\n\
        precision mediump float;\nvoid main() { float w = fwidth(gl_FragCoord.x); gl_FragColor = vec4(w); }\n";
    let options = MinifyOptions {
        compile: CompileOptions::for_target(Target::WebGl1),
        rename: true,
    };
    let m = minify(text, Stage::Fragment, &options).unwrap();
    insta::assert_snapshot!(m.text, @r"
    #extension GL_OES_standard_derivatives:enable
    #pragma optimize(off)
    precision mediump float;void main(){float a=fwidth(gl_FragCoord.x);gl_FragColor=vec4(a);}
    ");
}

#[test]
fn rename_off_keeps_names() {
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { float value = 1.0; o = vec4(value); }\n";
    let options = MinifyOptions {
        rename: false,
        ..MinifyOptions::default()
    };
    let m = minify(text, Stage::Fragment, &options).unwrap();
    assert!(m.renamed.is_empty() && m.text.contains("value"));
}

#[test]
fn shaders_with_errors_are_not_minified() {
    let e = minify(
        "#version 300 es\nvoid main() { undeclared = 1; }\n",
        Stage::Fragment,
        &MinifyOptions::default(),
    )
    .unwrap_err();
    assert!(matches!(e, MinifyError::Invalid { errors: 1.., .. }), "{e}");
}

#[test]
fn line_macro_keeps_lines() {
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\n\n\
        void main() {\n  float line = float(__LINE__);\n  o = vec4(line);\n}\n";
    let m = run(text, Stage::Fragment);
    assert_eq!(m.text.lines().count(), text.lines().count());
}

#[test]
fn shadowing_and_overloads_come_out_the_same() {
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\n\
        float f(float x) { return x; }\nfloat f(vec2 x) { return x.x; }\n\
        void main() { float x = 1.0; { float x = 2.0; o.x = f(x); } o.y = f(vec2(x)); o.zw = vec2(0); }\n";
    insta::assert_snapshot!(frag(text), @r"
    #version 300 es
    precision highp float;out vec4 o;float b(float a){return a;}float b(vec2 a){return a.x;}void main(){float a=1.;{float a=2.;o.x=b(a);}o.y=b(vec2(a));o.zw=vec2(0);}
    ");
}

#[test]
fn defines_option_names_are_respected() {
    let options = MinifyOptions {
        compile: CompileOptions {
            defines: vec![("SCALE".into(), "factor".into())],
            ..CompileOptions::default()
        },
        rename: true,
    };
    let text = "#version 300 es\nprecision highp float;\nout vec4 o;\n\
        void main() { float factor = 2.0; o = vec4(SCALE); }\n";
    let m = minify(text, Stage::Fragment, &options).unwrap();
    assert!(m.renamed.is_empty(), "{:?}", m.renamed);
}

#[test]
fn plain_and_const_globals_are_renamed_interface_globals_kept() {
    let text =
        "#version 300 es\nprecision highp float;\nconst float SCALE = 2.0;\nfloat counter = 0.0;\n\
        uniform float u_gain;\nin vec2 v_uv;\nout vec4 color;\n\
        void main() { counter += SCALE * u_gain; color = vec4(v_uv, counter, 1); }\n";
    insta::assert_snapshot!(frag(text), @r"
    #version 300 es
    precision highp float;const float b=2.;float a=0.;uniform float u_gain;in vec2 v_uv;out vec4 color;void main(){a+=b*u_gain;color=vec4(v_uv,a,1);}
    ");
}
