//! The idioms of real shaders, one fixture each, annotated the way rust-analyzer's diagnostics
//! tests are: the expected finding sits under the code it points at,
//!
//! ```text
//!   float s = pow(dot(n, h), k);
//!   //            ^^^^^^^^^^^ warning pow-negative-base
//! ```
//!
//! (`note` for a note; a fixture with no annotation must be clean, notes included). Each idiom
//! is written here after the real code `docs/lints/corpus.md` cites for it.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};
use essl_lint::{lint, LintOptions};

/// (line, first column, last column + 1, severity, rule), columns in bytes from 0.
type Finding = (usize, usize, usize, String, String);

/// The findings the `// ^^^ severity rule` lines of `text` expect.
fn expected(text: &str) -> Vec<Finding> {
    let mut out = Vec::new();
    let mut target = 0;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start();
        let Some(rest) = t.strip_prefix("//") else {
            target = i;
            continue;
        };
        let Some(first) = line.find('^') else {
            target = i;
            continue;
        };
        if !rest.trim_start().starts_with('^') {
            target = i;
            continue;
        }
        let carets = line[first..].chars().take_while(|c| *c == '^').count();
        let mut words = line[first + carets..].split_whitespace();
        let severity = words.next().expect("a severity").to_string();
        let rule = words.next().expect("a rule").to_string();
        out.push((target + 1, first, first + carets, severity, rule));
    }
    out.sort();
    out
}

/// The findings of `text`, notes included, as [`expected`] writes them.
fn found(text: &str) -> Vec<Finding> {
    let shader = compile(
        SourceFile::new("idiom.frag", text),
        Stage::Fragment,
        &CompileOptions::default(),
    );
    assert!(
        shader.ok(),
        "does not compile:\n{text}\n{:#?}",
        shader.diagnostics
    );
    let starts: Vec<usize> = std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .collect();
    let mut out: Vec<Finding> = lint(&shader, &LintOptions::default().notes(true))
        .iter()
        .map(|d| {
            let (s, e) = (d.span.start as usize, d.span.end as usize);
            let line = starts.partition_point(|&x| x <= s);
            let col = s - starts[line - 1];
            (
                line,
                col,
                col + (e - s),
                d.severity.as_str().to_string(),
                d.code.to_string(),
            )
        })
        .collect();
    out.sort();
    out
}

#[track_caller]
fn check(text: &str) {
    assert_eq!(found(text), expected(text), "in:\n{text}");
}

// ----- facts along the statements -----

#[test]
fn a_clamp_on_the_line_before_guards_the_base() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_hdr;
uniform float u_exposure;
in vec2 v_uv;
out vec4 o;
vec3 tonemap(vec3 color) {
  color = clamp(u_exposure * color, 0.0, 1.0);
  color = pow(color, vec3(1.0 / 2.2));
  return color;
}
vec3 cineon(vec3 color) {
  color = max(vec3(0.0), color - 0.004);
  return pow((color * (6.2 * color + 0.5)) / (color * (6.2 * color + 1.7) + 0.06), vec3(2.2));
}
void main() {
  vec3 c = texture(u_hdr, v_uv).rgb - 0.5;
  o = vec4(tonemap(c) + cineon(c), 1.0);
}
"#,
    );
}

#[test]
fn an_output_written_then_converted_keeps_its_sign() {
    check(
        r#"#version 300 es
precision highp float;
uniform vec3 diffuse;
uniform float opacity;
layout(location = 0) out highp vec4 pc_fragColor;
vec4 toSRGB(in vec4 value) {
  return vec4(mix(pow(value.rgb, vec3(0.41666)) * 1.055 - vec3(0.055), value.rgb * 12.92,
      vec3(lessThanEqual(value.rgb, vec3(0.0031308)))), value.a);
}
vec4 toOutput(vec4 value) {
  return toSRGB(vec4(value.rgb * mat3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0), value.a));
}
void main() {
  vec3 light = vec3(0.0);
  light += vec3(1.0);
  light *= diffuse;
  pc_fragColor = vec4(light, opacity);
  pc_fragColor = toOutput(pc_fragColor);
}
"#,
    );
}

#[test]
fn inout_tone_mappers_chosen_by_a_switch() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_hdr;
uniform int u_mode;
uniform float u_exposure;
in vec2 v_uv;
out vec4 o;
void linearMap(inout vec3 color) {
  color *= u_exposure;
  color = pow(color, vec3(1.0 / 2.2));
}
void signedMap(inout vec3 color) {
  color = color * 2.0 - 1.0;
}
void main() {
  vec3 c = texture(u_hdr, v_uv).rgb;
  switch (u_mode) {
    case 0:
      signedMap(c);
      break;
    case 1:
      linearMap(c);
      break;
    default:
      break;
  }
  o = vec4(c, 1.0);
}
"#,
    );
}

#[test]
fn components_written_through_a_loop_counter() {
    // three.js's dispersion loop: `.rgb` through the counter, then `.a` read; the counter passed
    // to a function by value keeps its range, passed to an `inout` parameter it has none.
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_tex;
in vec2 v_uv;
out vec4 o;
float sampleAt(int k) { return texture(u_tex, v_uv)[k]; }
void bump(inout int k) { k += 0; }
void main() {
  vec4 light;
  for (int i = 0; i < 3; i++) {
    light[i] = sampleAt(i);
    light.a += 1.0;
  //^^^^^^^ warning uninitialised-read
  }
  vec4 all4;
  for (int j = 0; j < 3; j++) {
    bump(j);
    all4[j] = 1.0;
  }
  o = light + all4;
}
"#,
    );
}

#[test]
fn built_in_outputs_read_before_they_are_written() {
    // vtk.js's fragment template with its tags empty: `gl_FragData[0].a` tested before anything
    // writes it. Written by a helper first, `gl_FragColor` is read after the write.
    check(
        r#"precision mediump float;
varying vec4 v_color;
void main() {
  if (gl_FragData[0].a <= 0.0) { discard; }
  //  ^^^^^^^^^^^^^^^^ warning uninitialised-read
  gl_FragData[0] = v_color;
}
"#,
    );
    check(
        r#"precision mediump float;
varying vec4 v_color;
void shade() { gl_FragColor = v_color; }
void main() {
  shade();
  gl_FragColor.rgb *= gl_FragColor.a;
}
"#,
    );
}

// ----- guards -----

#[test]
fn the_sign_split_idiom() {
    check(
        r#"#version 300 es
precision highp float;
in vec2 v_uv;
out vec4 o;
void main() {
  float x = (v_uv.x - 0.5) * 2.0;
  float p = 0.25;
  x = x < 0.0 ? -pow(-x, p) : pow(x, p);
  float y = v_uv.y - 0.5;
  y = y >= 0.0 ? pow(y, p) : -pow(-y, p);
  o = vec4(x, y, 0.0, 1.0);
}
"#,
    );
}

#[test]
fn exp_abs_and_clamped_bases() {
    check(
        r#"#version 300 es
precision highp float;
in vec3 v_n;
in vec3 v_v;
in float v_d;
out vec4 o;
void main() {
  float c = dot(normalize(v_n), normalize(v_v));
  float a = pow(exp(c), 2.0) + pow(abs(c) / max(v_d, 1e-4), 3.0);
  float b = pow(clamp(c, 0.0, 1.0), 5.0) + pow(min(max(c, 0.0), 1.0), 0.5);
  float s = pow(c * c, 0.5);
  o = vec4(a, b, s, 1.0);
}
"#,
    );
}

#[test]
fn exposure_schlick_and_weighted_sums() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_hdr;
uniform float u_exposure;
uniform vec3 u_attenuation;
uniform float u_metalness;
in vec2 v_uv;
in vec3 v_n;
in vec3 v_l;
in vec3 v_v;
out vec4 o;
void main() {
  vec3 hdr = texture(u_hdr, v_uv).rgb;
  vec3 mapped = vec3(1.0) - exp(-hdr * u_exposure);
  vec3 n = normalize(v_n);
  vec3 l = normalize(v_l);
  vec3 h = normalize(l + normalize(v_v));
  float vdh = clamp(dot(normalize(v_v), h), 0.0, 1.0);
  vec3 f0 = mix(vec3(0.04), hdr, u_metalness);
  vec3 fresnel = f0 + (vec3(1.0) - f0) * pow(1.0 - vdh, 5.0);
  float d = length(v_l);
  float attenuation = 1.0 / dot(u_attenuation, vec3(1.0, d, d * d));
  vec3 diffuse = hdr * (1.0 - u_metalness) * (1.0 - fresnel) * attenuation;
  vec3 color = mapped + diffuse * max(dot(n, l), 0.0);
  o = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
"#,
    );
}

#[test]
fn the_depth_of_the_fragment_is_in_0_1() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_tex;
in vec2 v_uv;
out vec4 o;
void main() {
  float a = texture(u_tex, v_uv).a;
  float z = gl_FragCoord.z;
  float w = clamp(pow(min(1.0, a * 10.0) + 0.01, 3.0) * 1e8 * pow(1.0 - z * 0.9, 3.0), 1e-2, 3e3);
  o = vec4(w);
}
"#,
    );
}

#[test]
fn a_hemisphere_light_mixes_by_a_unit_dot_product() {
    check(
        r#"#version 300 es
precision highp float;
struct Hemi { vec3 direction; vec3 skyColor; vec3 groundColor; };
uniform Hemi u_hemi;
in vec3 v_n;
out vec4 o;
vec3 hemisphere(const in Hemi light, const in vec3 normal) {
  float w = 0.5 * dot(normal, light.direction) + 0.5;
  return mix(light.groundColor, light.skyColor, w);
}
void main() {
  vec3 c = hemisphere(u_hemi, normalize(v_n));
  o = vec4(pow(c, vec3(0.41666)), 1.0);
}
"#,
    );
}

// ----- facts that live in a called function -----

#[test]
fn what_a_function_returns_for_each_call() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_tex;
in vec3 v_n;
in vec2 v_uv;
out vec4 o;
float saturate01(float x) { return clamp(x, 0.0, 1.0); }
vec3 ambient(vec3 sky, vec3 ground) { return sky * 0.5 + ground * 0.5; }
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
void main() {
  float signedL = luminance(v_n * 2.0 - 1.0);
  vec3 texel = texture(u_tex, v_uv).rgb;
  float l = luminance(texel);
  float a = pow(saturate01(signedL), 2.2) + pow(l, 2.2);
  vec3 amb = pow(ambient(texel, texel.bgr), vec3(2.2));
  float b = pow(signedL, 2.2);
  //            ^^^^^^^ warning pow-negative-base
  o = vec4(a, b, amb.r, 1.0);
}
"#,
    );
}

#[test]
fn a_parameter_holds_what_every_call_passes() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_tex;
in vec3 v_n;
in vec3 v_l;
in vec2 v_uv;
out vec4 o;
float gammaOf(float x) { return pow(x, 1.0 / 2.2); }
float specular(float d, float k) { return pow(d, k); }
//                                            ^ warning pow-negative-base
void main() {
  float a = gammaOf(texture(u_tex, v_uv).r);
  float s = specular(dot(normalize(v_n), normalize(v_l)), 16.0);
  o = vec4(a, s, 0.0, 1.0);
}
"#,
    );
}

// ----- geometry -----

#[test]
fn an_up_axis_chosen_away_from_the_normal() {
    check(
        r#"#version 300 es
precision highp float;
uniform vec3 u_n;
in vec3 v_n;
out vec4 o;
void main() {
  vec3 n = normalize(u_n);
  vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 tangent = normalize(cross(up, n));
  vec3 tilted = normalize(vec3(0.001, 1.0, 0.001));
  vec3 surfaceTangent = normalize(cross(normalize(v_n), tilted));
  vec3 floorTangent = normalize(cross(normalize(v_n), vec3(0.0, 1.0, 0.0)));
  //                            ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning normalize-zero
  o = vec4(tangent + surfaceTangent + floorTangent, 1.0);
}
"#,
    );
}

#[test]
fn an_up_axis_a_uniform_can_be_parallel_to() {
    check(
        r#"#version 300 es
precision highp float;
uniform vec3 u_direction;
out vec4 o;
void main() {
  vec3 left = normalize(cross(vec3(0.0, 1.0, 0.0), u_direction));
  //                    ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning normalize-zero
  o = vec4(left, 1.0);
}
"#,
    );
}

#[test]
fn inputs_only_dead_code_reads_are_not_zero_vectors() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_tex;
uniform vec3 u_light;
in vec3 v_n;
in vec2 v_uv;
out vec4 o;
void main() {
  vec3 n = normalize(v_n);
  vec3 l = normalize(u_light);
  float unused = max(dot(n, l), 0.0);
  o = texture(u_tex, v_uv);
}
"#,
    );
}

// ----- smoothstep -----

#[test]
fn reversed_edges_are_a_quieter_rule() {
    check(
        r#"#version 300 es
precision highp float;
in vec2 v_uv;
out vec4 o;
void main() {
  vec2 d = v_uv - 0.5;
  float disc = smoothstep(0.25, 0.24, dot(d, d));
  //           ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ note smoothstep-reversed-constant
  float strength = 0.35;
  float w = 0.09;
  float square = smoothstep(strength + w, strength - w, max(abs(d.x), abs(d.y)));
  //             ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ note smoothstep-reversed-constant
  float hard = smoothstep(0.5, 0.5, v_uv.x);
  //           ^^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning smoothstep-edges
  o = vec4(disc, square, hard, 1.0);
}
"#,
    );
}

#[test]
fn one_uniform_gives_a_note_two_a_warning() {
    check(
        r#"#version 300 es
precision highp float;
struct Spot { float coneCos; float penumbraCos; float angle; };
uniform Spot u_spot;
uniform float u_power;
uniform float u_resolution;
uniform float u_near;
uniform float u_far;
in vec3 v_p;
in float v_d;
out vec4 o;
float attenuation(float coneCosine, float penumbraCosine, float angleCosine) {
  return smoothstep(coneCosine, penumbraCosine, angleCosine);
  //     ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning smoothstep-edges
}
void main() {
  float r = max(length(v_p) - 1.0, 0.0);
  float dr = pow(r, u_power - 1.0);
  //             ^ note pow-zero-base
  float plane = v_d / (u_resolution - 1.0);
  //                  ^^^^^^^^^^^^^^^^^^^^ note division-by-difference
  float depth = (v_d - u_near) / (u_far - u_near);
  //                             ^^^^^^^^^^^^^^^^ warning division-by-difference
  float cone = smoothstep(cos(u_spot.angle / 2.0), cos(0.0), v_d);
  //           ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ note smoothstep-edges
  float spot = attenuation(u_spot.coneCos, u_spot.penumbraCos, v_d);
  o = vec4(dr, plane, depth, cone + spot);
}
"#,
    );
}

// ----- hazards that stay -----

#[test]
fn real_hazards_and_rounding_are_still_reported() {
    check(
        r#"#version 300 es
precision highp float;
uniform vec2 u_mouse;
uniform vec3 u_camera;
uniform float u_falloff;
in vec2 v_uv;
in vec3 v_n;
in vec3 v_pos;
out vec4 o;
void main() {
  float m = pow(1.0 - distance(u_mouse, v_uv), 12.0);
  //            ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ warning pow-negative-base
  vec3 n = normalize(v_n);
  vec3 view = u_camera - v_pos;
  float edge = 1.0 - abs(dot(n, view));
  edge = pow(edge, u_falloff);
  //         ^^^^ warning pow-negative-base
  vec3 v = normalize(view);
  float fresnel = pow(1.0 - max(dot(n, v), 0.0), 5.0);
  //                  ^^^^^^^^^^^^^^^^^^^^^^^^^ warning pow-negative-base
  float angle = acos(dot(n, v));
  //                 ^^^^^^^^^ warning acos-domain
  o = vec4(m, edge, fresnel, angle);
}
"#,
    );
}

// ----- mediump -----

#[test]
fn mediump_counts_and_clamped_powers() {
    check(
        r#"#version 300 es
precision mediump float;
uniform sampler2D u_tex;
uniform int u_n;
uniform float u_x;
in vec2 v_uv;
out vec4 o;
void main() {
  float s = 0.0;
  int count = 0;
  for (int i = 0; i < 16; i++) {
    if (texture(u_tex, v_uv + float(i) * 0.01).r > 0.5) { s += 1.0; count++; }
  }
  if (count > 0) s = s / float(count);
  float t = 0.0;
  if (u_n > 0) t = 1.0 / float(u_n);
  float w = pow(clamp(u_x, 0.0, 1.0), 1.7);
  o = vec4(s, t, w, 1.0);
}
"#,
    );
}

#[test]
fn per_pixel_divisors_and_edges_are_not_per_draw_hazards() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_depth;
uniform float u_near;
uniform float u_far;
in vec2 v_uv;
in vec3 v_n;
out vec4 o;
float linearDepth(float depth, float near, float far) {
  float z = depth * 2.0 - 1.0;
  return (2.0 * near * far) / (far + near - z * (far - near));
}
void main() {
  float d = linearDepth(texture(u_depth, v_uv).r, u_near, u_far);
  vec2 coord = vec2(dot(normalize(v_n), vec3(0.0, 0.0, 1.0)) * 0.5 + 0.5, 0.0);
  vec2 fw = fwidth(coord) * 0.5;
  float band = smoothstep(0.7 - fw.x, 0.7 + fw.x, coord.x);
  //           ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ note smoothstep-edges
  o = vec4(d, band, 0.0, 1.0);
}
"#,
    );
}

#[test]
fn mediump_transforms_compose_and_correlated_quotients() {
    check(
        r#"#version 300 es
precision mediump float;
uniform mat4 u_view;
uniform mat4 u_model;
uniform vec4 u_direction;
uniform sampler2D u_color;
uniform float u_threshold;
uniform float u_knee;
in vec2 v_uv;
out vec4 o;
void main() {
  mat4 modelView = u_view * u_model;
  vec4 light = modelView * -u_direction;
  light = normalize(light);
  vec4 color = texture(u_color, v_uv);
  float brightness = dot(color.rgb, vec3(0.2126, 0.7152, 0.0722));
  float knee = u_threshold * u_knee;
  float source = clamp(brightness - u_threshold + knee, 0.0, 2.0 * knee);
  source = source * source / (4.0 * knee + 1e-4);
  o = vec4(light.xyz, source);
}
"#,
    );
}

#[test]
fn a_fraction_written_out_blends_two_levels() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_env;
uniform float u_roughness;
in vec2 v_uv;
out vec4 o;
void main() {
  float blend = clamp(u_roughness, 0.04, 1.0) * 6.0;
  float level0 = floor(blend);
  blend -= level0;
  vec3 a = textureLod(u_env, v_uv, level0).rgb;
  vec3 b = textureLod(u_env, v_uv, level0 + 1.0).rgb;
  o = vec4(pow(mix(a, b, blend), vec3(1.0 / 2.2)), 1.0);
}
"#,
    );
}

#[test]
fn a_neutral_tone_mapper_keeps_colours_non_negative() {
    check(
        r#"#version 300 es
precision highp float;
uniform sampler2D u_hdr;
uniform float u_exposure;
uniform float u_ior;
in vec2 v_uv;
out vec4 o;
vec3 neutral(vec3 color) {
  const float start = 0.76;
  const float desaturation = 0.15;
  color *= u_exposure;
  float x = min(color.r, min(color.g, color.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  color -= offset;
  float peak = max(color.r, max(color.g, color.b));
  if (peak < start) return color;
  float d = 1.0 - start;
  float newPeak = 1.0 - d * d / (peak + d - start);
  color *= newPeak / peak;
  float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
  return mix(color, vec3(newPeak), g);
}
void main() {
  vec3 c = neutral(texture(u_hdr, v_uv).rgb);
  float r = (u_ior - 1.0) / (u_ior + 1.0);
  float f0 = min(r * r, 1.0);
  o = vec4(pow(c, vec3(0.41666)) * (1.0 - f0), 1.0);
}
"#,
    );
}
