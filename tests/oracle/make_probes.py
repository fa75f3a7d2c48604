#!/usr/bin/env python3
"""Write the WebGL2 probe shaders into tests/oracle/probes/ and ask the oracle about them.

Run from the repository root:  python3 tests/oracle/make_probes.py
Writes tests/oracle/probes/NAME.vert + NAME.frag (one pair per question; the stage that is not
under test is a trivial valid shader) and tests/oracle/probes.json (output of
../shared/tools/webgl2-oracle.py tests/oracle/probes, keys `tests/oracle/probes/NAME.{vert,frag}`
for compiles and `tests/oracle/probes/NAME` for links). Conclusions: tests/oracle/PROBES.md.

Name prefixes: u- active uniforms, a- active attributes, c- compile errors, l- link errors.
"""
import os, shutil, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DIR = os.path.join("tests", "oracle", "probes")
NBSP = "\u00a0"

V = "#version 300 es\n"
VS0 = V + "in vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n"
FS_HEAD = V + "precision mediump float;\nout vec4 o;\n"
FS0 = FS_HEAD + "void main() {\n  o = vec4(1.0);\n}\n"


def fs(decls, body):
    """Fragment shader: mediump default precision, one output `o`."""
    return FS_HEAD + decls + "void main() {\n" + body + "}\n"


def vs(decls, body):
    return V + "in vec4 a_position;\n" + decls + "void main() {\n" + body + "}\n"


P = {}  # name -> (vertex source, fragment source)


def probe(name, vert=VS0, frag=FS0):
    assert name not in P, name
    P[name] = (vert, frag)


# ---------------------------------------------------------------- 1. active uniforms
probe("u-unused-declared", frag=fs("uniform float u_unused;\nuniform float u_used;\n", "  o = vec4(u_used);\n"))
probe("u-used-only-in-uncalled-function", frag=fs(
    "uniform float u_inFunction;\nuniform float u_used;\nfloat helper() {\n  return u_inFunction;\n}\n",
    "  o = vec4(u_used);\n"))
probe("u-used-only-in-if-false", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n",
    "  o = vec4(u_used);\n  if (false) {\n    o = vec4(u_dead);\n  }\n"))
probe("u-used-times-zero", frag=fs(
    "uniform float u_zero;\nuniform float u_used;\n", "  o = vec4(u_used + u_zero * 0.0);\n"))
probe("u-declared-both-stages-used-in-vertex",
      vert=vs("uniform highp vec4 u_shared;\nuniform vec4 u_vertexOnly;\n",
              "  gl_Position = a_position + u_shared + u_vertexOnly;\n"),
      frag=fs("uniform highp vec4 u_shared;\nuniform vec4 u_fragment;\n", "  o = u_fragment;\n"))
probe("u-declared-both-stages-used-in-fragment",
      vert=vs("uniform highp vec4 u_shared;\n", "  gl_Position = a_position;\n"),
      frag=fs("uniform highp vec4 u_shared;\n", "  o = u_shared;\n"))
probe("u-array-used-index-1", frag=fs("uniform vec3 u_a[4];\n", "  o = vec4(u_a[1], 1.0);\n"))
probe("u-array-used-index-0", frag=fs("uniform vec3 u_a[4];\n", "  o = vec4(u_a[0], 1.0);\n"))
probe("u-array-used-index-3", frag=fs("uniform vec3 u_a[4];\n", "  o = vec4(u_a[3], 1.0);\n"))
probe("u-array-dynamic-index", frag=fs("uniform vec3 u_a[4];\nuniform int u_i;\n", "  o = vec4(u_a[u_i], 1.0);\n"))
probe("u-array-loop-first-two", frag=fs(
    "uniform vec3 u_a[4];\n",
    "  vec3 s = vec3(0.0);\n  for (int i = 0; i < 2; ++i) {\n    s += u_a[i];\n  }\n  o = vec4(s, 1.0);\n"))
probe("u-array-of-float", frag=fs("uniform float u_f[3];\n", "  o = vec4(u_f[0] + u_f[2]);\n"))
probe("u-array-of-mat", frag=fs("uniform mat2 u_m[2];\n", "  o = vec4(u_m[1][0], u_m[0][1]);\n"))
STRUCT_LIGHT = "struct Light {\n  vec3 position;\n  vec3 color;\n  float intensity;\n};\n"
probe("u-struct-one-field-used", frag=fs(STRUCT_LIGHT + "uniform Light light;\n", "  o = vec4(light.color, 1.0);\n"))
probe("u-struct-all-fields-used", frag=fs(
    STRUCT_LIGHT + "uniform Light light;\n", "  o = vec4(light.color * light.intensity + light.position, 1.0);\n"))
probe("u-struct-whole-passed-to-function", frag=fs(
    STRUCT_LIGHT + "uniform Light light;\nvec3 f(Light l) {\n  return l.color;\n}\n", "  o = vec4(f(light), 1.0);\n"))
STRUCT_S = "struct S {\n  vec3 position;\n  vec3 color;\n};\n"
probe("u-struct-array-loop", frag=fs(
    STRUCT_S + "uniform S u_spots[2];\n",
    "  vec3 s = vec3(0.0);\n  for (int i = 0; i < 2; ++i) {\n    s += u_spots[i].position;\n  }\n  o = vec4(s, 1.0);\n"))
probe("u-struct-array-one-element-one-field", frag=fs(STRUCT_S + "uniform S u_spots[2];\n", "  o = vec4(u_spots[1].color, 1.0);\n"))
probe("u-struct-array-dynamic-index", frag=fs(
    STRUCT_S + "uniform S u_spots[3];\nuniform int u_i;\n", "  o = vec4(u_spots[u_i].color, 1.0);\n"))
probe("u-struct-nested", frag=fs(
    "struct Inner {\n  vec3 a;\n  float b;\n};\nstruct Outer {\n  Inner inner;\n  vec2 c;\n  Inner arr[2];\n};\n"
    "uniform Outer u_o;\n",
    "  o = vec4(u_o.inner.b, u_o.arr[1].a);\n"))
probe("u-struct-with-array-field", frag=fs(
    "struct T {\n  float w[3];\n  vec2 v;\n};\nuniform T u_t;\n", "  o = vec4(u_t.w[1], u_t.v, 1.0);\n"))
probe("u-struct-with-sampler", frag=fs(
    "struct M {\n  sampler2D tex;\n  float k;\n  vec2 uv;\n};\nuniform M u_m;\n",
    "  o = texture(u_m.tex, u_m.uv) * u_m.k;\n"))
probe("u-types-scalar-vector-matrix", frag=fs(
    "uniform bool u_bool;\nuniform bvec3 u_bvec3;\nuniform uint u_uint;\nuniform uvec2 u_uvec2;\nuniform int u_int;\n"
    "uniform ivec4 u_ivec4;\nuniform mat3 u_mat3;\nuniform mat2x3 u_mat2x3;\nuniform mat4x2 u_mat4x2;\nuniform mat4 u_mat4;\n",
    "  float f = u_bool ? 1.0 : 0.0;\n  if (any(u_bvec3)) f += 1.0;\n  f += float(u_uint) + float(u_uvec2.y) + float(u_int) + float(u_ivec4.w);\n"
    "  f += u_mat3[0][0] + u_mat2x3[1][2] + u_mat4x2[3][1] + u_mat4[2][3];\n  o = vec4(f);\n"))
probe("u-types-samplers", frag=fs(
    "precision highp sampler3D;\nprecision highp sampler2DShadow;\nprecision highp isampler2D;\n"
    "precision highp usampler2D;\nprecision highp sampler2DArray;\n"
    "uniform sampler2D u_s2d;\nuniform samplerCube u_cube;\nuniform sampler3D u_s3d;\nuniform sampler2DShadow u_shadow;\n"
    "uniform isampler2D u_is2d;\nuniform usampler2D u_us2d;\nuniform sampler2DArray u_s2da;\n",
    "  o = texture(u_s2d, vec2(0.5)) + texture(u_cube, vec3(1.0)) + texture(u_s3d, vec3(0.5));\n"
    "  o += vec4(texture(u_shadow, vec3(0.5)));\n  o += vec4(texture(u_is2d, vec2(0.5))) + vec4(texture(u_us2d, vec2(0.5)));\n"
    "  o += texture(u_s2da, vec3(0.5));\n"))
probe("u-types-samplers-vertex", vert=vs(
    "uniform sampler2D u_vtex;\nuniform highp isampler2D u_vitex;\n",
    "  gl_Position = a_position + texture(u_vtex, vec2(0.5)) + vec4(texelFetch(u_vitex, ivec2(0), 0));\n"))
probe("u-sampler-array-used-index-2", frag=fs("uniform sampler2D u_tex[3];\n", "  o = texture(u_tex[2], vec2(0.5));\n"))
probe("u-sampler-array-used-index-0-and-2", frag=fs(
    "uniform sampler2D u_tex[3];\n", "  o = texture(u_tex[0], vec2(0.5)) + texture(u_tex[2], vec2(0.5));\n"))
probe("u-block-instance-one-member-used", frag=fs(
    "uniform Block {\n  vec4 a;\n  vec4 b;\n} blk;\nuniform float u_plain;\n", "  o = blk.a * u_plain;\n"))
probe("u-block-no-instance-std140", frag=fs(
    "layout(std140) uniform Lights {\n  vec4 colorA;\n  mat4 m;\n  float k[2];\n};\n", "  o = colorA * k[1];\n"))
probe("u-block-unused", frag=fs(
    "uniform Unused {\n  vec4 x;\n};\nuniform float u_plain;\n", "  o = vec4(u_plain);\n"))
# ordering of the active list
probe("u-order-same-type-decl-vs-use", frag=fs(
    "uniform float u_z;\nuniform float u_a;\nuniform float u_m;\n", "  o = vec4(u_m, u_z, u_a, 1.0);\n"))
ORDER_DECLS = ("uniform mat4 u1_mat4;\nuniform vec4 u2_vec4;\nuniform float u3_float;\nuniform sampler2D u4_tex;\n"
               "uniform vec2 u5_vec2;\nuniform mat3 u6_mat3;\nuniform int u7_int;\nuniform vec3 u8_vec3;\n"
               "uniform bool u9_bool;\nuniform mat2 u10_mat2;\n")
probe("u-order-types-fragment", frag=fs(ORDER_DECLS,
    "  float f = u1_mat4[0][0] + u2_vec4.x + u3_float + texture(u4_tex, u5_vec2).x + u6_mat3[0][0];\n"
    "  f += float(u7_int) + u8_vec3.x + (u9_bool ? 1.0 : 0.0) + u10_mat2[1][1];\n  o = vec4(f);\n"))
probe("u-order-types-vertex", vert=vs(ORDER_DECLS,
    "  float f = u1_mat4[0][0] + u2_vec4.x + u3_float + texture(u4_tex, u5_vec2).x + u6_mat3[0][0];\n"
    "  f += float(u7_int) + u8_vec3.x + (u9_bool ? 1.0 : 0.0) + u10_mat2[1][1];\n  gl_Position = a_position * f;\n"))
probe("u-order-stages",
      vert=vs("uniform vec4 u_v2;\nuniform highp vec4 u_both;\nuniform vec4 u_v1;\n",
              "  gl_Position = a_position + u_v2 + u_both + u_v1;\n"),
      frag=fs("uniform vec4 u_f1;\nuniform highp vec4 u_both;\nuniform vec4 u_f0;\n", "  o = u_f1 + u_both + u_f0;\n"))
probe("u-order-precision", frag=fs(
    "uniform highp float u_high;\nuniform lowp float u_low;\nuniform mediump float u_medium;\nuniform float u_default;\n",
    "  o = vec4(u_high, u_low, u_medium, u_default);\n"))
probe("u-order-gouraud-phong-like", vert=V +
    "precision mediump float;\nuniform mat4 uModelViewMatrix;\nuniform mat4 uProjectionMatrix;\nuniform mat4 uNormalMatrix;\n"
    "uniform vec3 uLightDirection;\nuniform vec4 uLightAmbient;\nuniform vec4 uLightDiffuse;\nuniform float shininess;\n"
    "in vec3 aVertexPosition;\nin vec3 aVertexNormal;\nout vec4 vVertexColor;\n"
    "void main(void) {\n  vec3 N = vec3(uNormalMatrix * vec4(aVertexNormal, 1.0));\n"
    "  vVertexColor = uLightAmbient + uLightDiffuse * pow(max(dot(N, uLightDirection), 0.0), shininess);\n"
    "  gl_Position = uProjectionMatrix * uModelViewMatrix * vec4(aVertexPosition, 1.0);\n}\n",
    frag=FS_HEAD + "in vec4 vVertexColor;\nvoid main() {\n  o = vVertexColor;\n}\n")
probe("u-order-struct-vs-plain", frag=fs(
    STRUCT_LIGHT + "uniform vec2 u_first;\nuniform Light u_light;\nuniform float u_last;\n",
    "  o = vec4(u_first, u_light.intensity + u_last, u_light.position.x);\n"))

# more on what counts as active
probe("u-used-only-in-if-const-var-false", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\nconst bool k = false;\n",
    "  o = vec4(u_used);\n  if (k) {\n    o = vec4(u_dead);\n  }\n"))
probe("u-used-only-in-if-const-compare", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n",
    "  o = vec4(u_used);\n  if (1.0 < 0.0) {\n    o = vec4(u_dead);\n  }\n"))
probe("u-used-only-in-ternary-false", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n", "  o = vec4(false ? u_dead : u_used);\n"))
probe("u-used-only-after-return", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n", "  o = vec4(u_used);\n  return;\n  o = vec4(u_dead);\n"))
probe("u-used-only-in-zero-trip-loop", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n",
    "  o = vec4(u_used);\n  for (int i = 0; i < 0; ++i) {\n    o = vec4(u_dead);\n  }\n"))
probe("u-used-only-in-dead-local", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\n", "  float unused = u_dead;\n  o = vec4(u_used);\n"))
# A local referenced beyond its declaration keeps its stores, read or not; a chain of
# declarations nothing else references goes.
for name, body in [
    ("u-local-assigned-never-read", "  float x;\n  x = u_dead;\n"),
    ("u-local-component-stored-never-read", "  vec4 c = vec4(1.0);\n  c.a = u_dead;\n"),
    ("u-local-compound-assigned-never-read", "  float x = 1.0;\n  x += u_dead;\n"),
    ("u-dead-local-reassigned", "  float x = u_dead;\n  x = 2.0;\n"),
    ("u-dead-local-incremented", "  float x = u_dead;\n  x++;\n"),
    ("u-dead-local-chain", "  float a = u_dead;\n  float b = a;\n"),
]:
    probe(name, frag=fs("uniform float u_dead;\nuniform float u_used;\n",
                        body + "  o = vec4(u_used);\n"))
probe("u-used-only-in-function-called-from-if-false", frag=fs(
    "uniform float u_dead;\nuniform float u_used;\nfloat helper() {\n  return u_dead;\n}\n",
    "  o = vec4(u_used);\n  if (false) {\n    o = vec4(helper());\n  }\n"))
probe("u-used-only-in-vertex-output-unused-by-fragment",
      vert=vs("uniform vec4 u_toVarying;\nout vec4 v_unread;\n", "  v_unread = u_toVarying;\n  gl_Position = a_position;\n"),
      frag=fs("in vec4 v_unread;\n", "  o = vec4(1.0);\n"))
# ordering: precision groups and sizes
probe("u-order-precision-and-size", frag=V + "precision highp float;\nout vec4 o;\n"
    "uniform mat4 h_a;\nuniform mediump vec3 m_b;\nuniform float h_c;\nuniform mediump float m_d;\nuniform vec2 h_e;\n"
    "uniform lowp vec4 l_f;\nuniform mediump mat3 m_g;\nuniform int i_h;\nuniform bool n_i;\nuniform highp int hi_j;\n"
    "void main() {\n  o = h_a[0] + vec4(m_b, h_c) + vec4(m_d, h_e, float(i_h)) + l_f + vec4(m_g[1], n_i ? 1.0 : 0.0)"
    " + vec4(float(hi_j));\n}\n")
probe("u-order-size-arrays", frag=fs(
    "uniform float m_fa[8];\nuniform mat3 m_m3;\nuniform vec4 m_v4;\nuniform vec2 m_v2a[3];\nuniform float m_f;\n",
    "  o = vec4(m_fa[7], m_m3[2][2], m_v2a[2]) + m_v4 + vec4(m_f);\n"))
probe("u-order-size-structs", frag=fs(
    "struct Big {\n  mat4 m;\n  float f;\n};\nstruct Small {\n  float f;\n};\n"
    "uniform Big u_big;\nuniform vec4 u_v4;\nuniform Small u_small;\nuniform vec2 u_v2;\n",
    "  o = u_big.m[0] * u_big.f + u_v4 + vec4(u_small.f, u_v2, 1.0);\n"))
probe("u-order-interleaved-aggregates", frag=V + "precision highp float;\nout vec4 o;\n"
    "struct S {\n  mediump float f;\n};\n"
    "uniform float h1;\nuniform mediump float ma[2];\nuniform vec2 h2;\nuniform S s;\nuniform mediump vec4 mv;\n"
    "uniform vec3 ha[2];\nuniform mediump float m;\n"
    "void main() {\n  o = vec4(h1 + ma[1] + s.f + m, h2, ha[1].x) + mv;\n}\n")
probe("u-order-mat-shapes", frag=fs(
    "uniform mat4 m44;\nuniform mat4x2 m42;\nuniform mat3x4 m34;\nuniform mat2x4 m24;\nuniform mat3 m33;\nuniform mat3x2 m32;\n"
    "uniform mat2x3 m23;\nuniform mat2 m22;\nuniform vec4 v4;\nuniform vec3 v3;\n",
    "  o = vec4(m44[0][0] + m42[0][0] + m34[0][0] + m24[0][0] + m33[0][0] + m32[0][0] + m23[0][0] + m22[0][0]) + v4 + vec4(v3, 1.0);\n"))
probe("u-order-categories",
      vert=vs("uniform sampler2D v_tex;\nuniform vec4 v_vec;\nuniform VB {\n  vec4 vb;\n};\n",
              "  gl_Position = a_position + v_vec + vb + texture(v_tex, vec2(0.5));\n"),
      frag=fs("uniform FB {\n  vec4 fb;\n};\nuniform sampler2D f_tex;\nuniform vec4 f_vec;\n",
              "  o = f_vec + fb + texture(f_tex, vec2(0.5));\n"))
probe("u-order-samplers-precision", frag=fs(
    "uniform highp sampler2D s_high;\nuniform lowp sampler2D s_low;\nuniform mediump sampler2D s_medium;\nuniform samplerCube s_cube;\n",
    "  o = texture(s_high, vec2(0.5)) + texture(s_low, vec2(0.5)) + texture(s_medium, vec2(0.5)) + texture(s_cube, vec3(1.0));\n"))
probe("u-order-stages-mediump-vertex",
      vert=V + "precision mediump float;\nin vec4 a_position;\nuniform mat4 v_mat;\nuniform highp vec4 v_high;\nuniform float v_float;\n"
      "void main() {\n  gl_Position = v_mat * a_position + v_high * v_float;\n}\n",
      frag=V + "precision highp float;\nout vec4 o;\nuniform vec4 f_high;\nuniform mediump mat2 f_mat2;\nuniform mediump float f_float;\n"
      "void main() {\n  o = f_high + vec4(f_mat2[0], f_float, 1.0);\n}\n")
probe("u-order-shared-used-only-in-fragment",
      vert=vs("uniform vec4 u_v;\nuniform highp vec4 u_shared;\n", "  gl_Position = a_position + u_v;\n"),
      frag=fs("uniform highp vec4 u_f;\nuniform highp vec4 u_shared;\n", "  o = u_f + u_shared;\n"))

# ---------------------------------------------------------------- 2. active attributes
probe("a-unused-in", vert=V + "in vec4 a_unused;\nin vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n")
probe("a-mat4", vert=V + "in vec4 a_position;\nin mat4 a_matrix;\nin vec2 a_after;\n"
      "void main() {\n  gl_Position = a_matrix * a_position + vec4(a_after, 0.0, 0.0);\n}\n")
probe("a-mat-first", vert=V + "in mat3 a_m3;\nin mat2 a_m2;\nin vec4 a_position;\n"
      "void main() {\n  gl_Position = a_position + vec4(a_m3[2] + vec3(a_m2[1], 0.0), 0.0);\n}\n")
probe("a-layout-location-3", vert=V + "in vec4 a_first;\nlayout(location=3) in vec4 a_position;\nin vec2 a_last;\n"
      "void main() {\n  gl_Position = a_position + a_first + vec4(a_last, 0.0, 0.0);\n}\n")
probe("a-layout-location-0-on-second", vert=V + "in vec4 a_first;\nlayout(location = 0) in vec4 a_second;\n"
      "void main() {\n  gl_Position = a_first + a_second;\n}\n")
probe("a-order-decl-vs-use", vert=V + "in vec4 a_z;\nin vec4 a_a;\nin vec4 a_m;\n"
      "void main() {\n  gl_Position = a_m + a_z + a_a;\n}\n")
probe("a-order-types", vert=V + "in float a1_float;\nin vec4 a2_vec4;\nin ivec2 a3_ivec2;\nin vec3 a4_vec3;\nin uvec4 a5_uvec4;\nin vec2 a6_vec2;\n"
      "void main() {\n  gl_Position = vec4(a6_vec2, a1_float, 1.0) + a2_vec4 + vec4(vec2(a3_ivec2), 0.0, 0.0)\n"
      "    + vec4(a4_vec3, float(a5_uvec4.x));\n}\n")
probe("a-unused-mat4-first", vert=V + "in mat4 a_unusedMatrix;\nin vec4 a_position;\n"
      "void main() {\n  gl_Position = a_position;\n}\n")
probe("a-unused-between", vert=V + "in vec4 a_first;\nin vec3 a_unused;\nin vec2 a_last;\n"
      "void main() {\n  gl_Position = a_first + vec4(a_last, 0.0, 0.0);\n}\n")
probe("a-unused-with-layout-gap", vert=V + "in vec4 a_unused;\nlayout(location = 0) in vec4 a_fixed;\nin vec4 a_free;\n"
      "void main() {\n  gl_Position = a_fixed + a_free;\n}\n")
probe("a-order-precision", vert=V + "in highp vec4 a_high;\nin lowp vec4 a_low;\nin mediump vec4 a_medium;\nin mediump float a_mf;\n"
      "void main() {\n  gl_Position = a_high + a_low + a_medium * a_mf;\n}\n")
probe("a-array-attribute", vert=V + "in vec4 a_arr[2];\nvoid main() {\n  gl_Position = a_arr[1];\n}\n")
probe("a-mat2-around-fixed-location", vert=V + "layout(location = 1) in vec4 a_fixed;\nin mat2 a_m;\nin vec4 a_v;\n"
      "void main() {\n  gl_Position = a_fixed + vec4(a_m[0], a_m[1]) + a_v;\n}\n")
probe("a-layout-alias", vert=V + "layout(location=1) in vec4 a_x;\nlayout(location=1) in vec4 a_y;\n"
      "void main() {\n  gl_Position = a_x + a_y;\n}\n")
probe("a-layout-mat4-overlap", vert=V + "layout(location=0) in mat4 a_m;\nlayout(location=2) in vec4 a_v;\n"
      "void main() {\n  gl_Position = a_m * a_v;\n}\n")
probe("a-only-gl-vertexid", vert=V + "void main() {\n  gl_Position = vec4(float(gl_VertexID), float(gl_InstanceID), 0.0, 1.0);\n}\n")

# ---------------------------------------------------------------- 3. compile errors
BODY = "void main() {\n  o = vec4(1.0);\n}\n"
probe("c-version-on-line-2-after-empty-line", frag="\n" + FS0)
probe("c-version-after-comment-line", frag="// a comment\n" + FS0)
probe("c-version-after-block-comment-same-line", frag="/* c */ " + FS0)
probe("c-no-version", frag="precision mediump float;\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}\n",
      vert="attribute vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n")
probe("c-nbsp-in-line-comment", frag=FS_HEAD + "// no" + NBSP + "break space\n" + BODY)
probe("c-nbsp-in-block-comment", frag=FS_HEAD + "/* no" + NBSP + "break space */\n" + BODY)
probe("c-nonascii-in-comment", frag=FS_HEAD + "// 90\u00b0 \u2019quoted\u2019 \u2014 dash\n" + BODY)
probe("c-nbsp-in-code", frag=FS_HEAD + "void main() {\n" + NBSP + " o = vec4(1.0);\n}\n")
probe("c-nbsp-on-version-line", frag="#version 300 es" + NBSP + "\nprecision mediump float;\nout vec4 o;\n" + BODY)
probe("c-nbsp-in-disabled-if0", frag=FS_HEAD + "#if 0\nfloat x" + NBSP + "= 1.0;\n#endif\n" + BODY)
probe("c-float-init-from-int", frag=fs("", "  float x = 1;\n  o = vec4(x);\n"))
probe("c-no-precision-float-local", frag=V + "out highp vec4 o;\nvoid main() {\n  float x = 1.0;\n  o = vec4(x);\n}\n")
probe("c-no-precision-float-out", frag=V + "out vec4 o;\nvoid main() {\n  o = vec4(1.0);\n}\n")
probe("c-no-precision-float-uniform", frag=V + "uniform float u;\nout highp vec4 o;\nvoid main() {\n  o = vec4(u);\n}\n")
probe("c-no-precision-all-qualified", frag=V + "uniform highp float u;\nout highp vec4 o;\nvoid main() {\n  highp float x = u;\n  o = vec4(x);\n}\n")
probe("c-no-precision-sampler3d", frag=fs("uniform sampler3D u_s;\n", "  o = texture(u_s, vec3(0.5));\n"))
probe("c-recursion-direct", frag=fs("float f(float x) {\n  return x > 0.0 ? f(x - 1.0) : 0.0;\n}\n", "  o = vec4(f(2.0));\n"))
probe("c-recursion-mutual", frag=fs(
    "float g(float x);\nfloat f(float x) {\n  return g(x);\n}\nfloat g(float x) {\n  return x > 0.0 ? f(x - 1.0) : 0.0;\n}\n",
    "  o = vec4(f(2.0));\n"))
probe("c-recursion-uncalled", frag=fs("float f(float x) {\n  return f(x);\n}\n", "  o = vec4(1.0);\n"))
probe("c-reserved-class", frag=fs("", "  float class;\n  o = vec4(1.0);\n"))
probe("c-reserved-attribute", frag=fs("", "  float attribute;\n  o = vec4(1.0);\n"))
probe("c-reserved-varying", frag=fs("", "  float varying;\n  o = vec4(1.0);\n"))
probe("c-reserved-gl-prefix", frag=fs("", "  float gl_x;\n  o = vec4(1.0);\n"))
probe("c-reserved-double-underscore", frag=fs("", "  float a__b;\n  o = vec4(1.0);\n"))
probe("c-reserved-webgl-prefix", frag=fs("", "  float webgl_x;\n  o = vec4(1.0);\n"))
probe("c-reserved-underscore-webgl-prefix", frag=fs("", "  float _webgl_x;\n  o = vec4(1.0);\n"))
probe("c-define-double-underscore", frag=V + "#define __FOO 1\nprecision mediump float;\nout vec4 o;\n" + BODY)
probe("c-define-gl-prefix", frag=V + "#define GL_FOO 1\nprecision mediump float;\nout vec4 o;\n" + BODY)
probe("c-define-inner-double-underscore", frag=V + "#define FOO__BAR 1\nprecision mediump float;\nout vec4 o;\n" + BODY)
probe("c-texture2D", frag=fs("uniform sampler2D u_s;\n", "  o = texture2D(u_s, vec2(0.5));\n"))
probe("c-gl-FragColor", frag=V + "precision mediump float;\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}\n")
probe("c-write-uniform", frag=fs("uniform float u;\n", "  u = 1.0;\n  o = vec4(u);\n"))
probe("c-write-in", vert=V + "in vec4 a_position;\nout vec4 v;\nvoid main() {\n  v = a_position;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec4 v;\n", "  v = vec4(0.0);\n  o = v;\n"))
probe("c-write-attribute", vert=V + "in vec4 a_position;\nvoid main() {\n  a_position = vec4(0.0);\n  gl_Position = a_position;\n}\n")
probe("c-sampler-array-loop-index", frag=fs(
    "uniform sampler2D u_tex[3];\n",
    "  o = vec4(0.0);\n  for (int i = 0; i < 3; ++i) {\n    o += texture(u_tex[i], vec2(0.5));\n  }\n"))
probe("c-sampler-array-uniform-index", frag=fs(
    "uniform sampler2D u_tex[3];\nuniform int u_i;\n", "  o = texture(u_tex[u_i], vec2(0.5));\n"))
probe("c-sampler-array-const-index", frag=fs(
    "uniform sampler2D u_tex[3];\nconst int k = 1;\n", "  o = texture(u_tex[k + 1], vec2(0.5));\n"))
probe("c-two-outputs-no-location", frag=V + "precision mediump float;\nout vec4 a;\nout vec4 b;\n"
      "void main() {\n  a = vec4(1.0);\n  b = vec4(0.0);\n}\n")
probe("c-two-outputs-with-locations", frag=V + "precision mediump float;\nlayout(location = 0) out vec4 a;\n"
      "layout(location = 1) out vec4 b;\nvoid main() {\n  a = vec4(1.0);\n  b = vec4(0.0);\n}\n")
probe("c-int-varying-no-flat-vertex",
      vert=V + "in vec4 a_position;\nout int v_i;\nvoid main() {\n  v_i = 1;\n  gl_Position = a_position;\n}\n",
      frag=fs("flat in int v_i;\n", "  o = vec4(float(v_i));\n"))
probe("c-int-varying-no-flat-fragment",
      vert=V + "in vec4 a_position;\nflat out int v_i;\nvoid main() {\n  v_i = 1;\n  gl_Position = a_position;\n}\n",
      frag=fs("in int v_i;\n", "  o = vec4(float(v_i));\n"))
probe("c-int-varying-flat-both",
      vert=V + "in vec4 a_position;\nflat out int v_i;\nvoid main() {\n  v_i = 1;\n  gl_Position = a_position;\n}\n",
      frag=fs("flat in int v_i;\n", "  o = vec4(float(v_i));\n"))
probe("c-pow-vec3-float", frag=fs("", "  vec3 c = pow(vec3(0.5), 2.0);\n  o = vec4(c, 1.0);\n"))
probe("c-smoothstep-vec3-vec3-float", frag=fs("", "  vec3 c = smoothstep(vec3(0.0), vec3(1.0), 0.5);\n  o = vec4(c, 1.0);\n"))
probe("c-smoothstep-float-float-vec3", frag=fs("", "  vec3 c = smoothstep(0.0, 1.0, vec3(0.5));\n  o = vec4(c, 1.0);\n"))
probe("c-missing-main", frag=FS_HEAD + "void notMain() {\n  o = vec4(1.0);\n}\n")
probe("c-missing-semicolon-end-of-line", frag=fs("", "  float a = 1.0\n  float b = 2.0;\n  o = vec4(a + b);\n"))
probe("c-missing-semicolon-uniform", frag=FS_HEAD + "uniform float u_a\nuniform float u_b;\n" + "void main() {\n  o = vec4(u_a + u_b);\n}\n")
probe("c-undeclared-identifier", frag=fs("", "  o = vec4(notDeclared);\n"))
probe("c-call-before-declaration", frag=FS_HEAD + "void main() {\n  o = vec4(f());\n}\nfloat f() {\n  return 1.0;\n}\n")
probe("c-switch-no-statement-after-last-case", frag=fs(
    "uniform int u_i;\n", "  float x = 0.0;\n  switch (u_i) {\n    case 0:\n      x = 1.0;\n      break;\n    case 1:\n  }\n  o = vec4(x);\n"))
probe("c-switch-default-last-empty", frag=fs(
    "uniform int u_i;\n", "  float x = 0.0;\n  switch (u_i) {\n    case 0:\n      x = 1.0;\n      break;\n    default:\n  }\n  o = vec4(x);\n"))
probe("c-switch-ok", frag=fs(
    "uniform int u_i;\n", "  float x = 0.0;\n  switch (u_i) {\n    case 0:\n      x = 1.0;\n      break;\n    default:\n      break;\n  }\n  o = vec4(x);\n"))
probe("c-uint-from-int-literal", frag=fs("", "  uint u = 3;\n  o = vec4(float(u));\n"))
probe("c-int-division-by-const-zero", frag=fs("", "  int a = 1 / 0;\n  o = vec4(float(a));\n"))
probe("c-int-division-by-const-var-zero", frag=fs("const int z = 0;\nuniform int u_i;\n", "  int a = u_i / z;\n  o = vec4(float(a));\n"))
probe("c-int-modulo-by-const-zero", frag=fs("", "  int a = 7 % 0;\n  o = vec4(float(a));\n"))
probe("c-float-division-by-const-zero", frag=fs("", "  float a = 1.0 / 0.0;\n  o = vec4(a);\n"))
probe("c-array-index-out-of-range-const", frag=fs("", "  float a[3];\n  a[3] = 1.0;\n  o = vec4(a[0]);\n"))
probe("c-array-index-negative-const", frag=fs("", "  float a[3];\n  a[0] = 1.0;\n  o = vec4(a[-1]);\n"))
probe("c-vector-index-out-of-range-const", frag=fs("", "  vec4 v = vec4(1.0);\n  o = vec4(v[4]);\n"))
probe("c-uniform-array-index-out-of-range-const", frag=fs("uniform vec4 u_a[2];\n", "  o = u_a[2];\n"))
probe("c-const-init-builtin-call", frag=fs("const float c = sin(1.0);\nconst vec3 n = normalize(vec3(1.0, 2.0, 2.0));\n", "  o = vec4(n, c);\n"))
probe("c-const-init-uniform", frag=fs("uniform float u;\n", "  const float c = u;\n  o = vec4(c);\n"))
probe("c-global-init-uniform", frag=fs("uniform float u;\nfloat g = u * 2.0;\n", "  o = vec4(g);\n"))
probe("c-fragdepth-one-branch", frag=fs("uniform float u;\n", "  o = vec4(1.0);\n  if (u > 0.5) {\n    gl_FragDepth = 0.25;\n  }\n"))
probe("c-redefine-builtin-function", frag=fs("float sin(float x) {\n  return x;\n}\n", "  o = vec4(sin(1.0));\n"))
probe("c-overload-builtin-function", frag=fs("float sin(int x) {\n  return float(x);\n}\n", "  o = vec4(sin(1));\n"))
probe("c-redeclare-builtin-prototype", frag=fs("float sin(float x);\n", "  o = vec4(sin(1.0));\n"))
probe("c-overload-main", frag=FS_HEAD + "void main(int x) {\n}\nvoid main() {\n  o = vec4(1.0);\n}\n")
probe("c-main-returns-int", frag=FS_HEAD + "int main() {\n  o = vec4(1.0);\n  return 0;\n}\n")
probe("c-local-shadows-function", frag=fs("float f() {\n  return 1.0;\n}\n", "  float f = 2.0;\n  o = vec4(f);\n"))
probe("c-local-shadows-function-then-call", frag=fs("float f() {\n  return 1.0;\n}\n", "  float f = 2.0;\n  o = vec4(f());\n"))
probe("c-swizzle-on-float", frag=fs("", "  float f = 1.0;\n  o = vec4(f.x);\n"))
probe("c-swizzle-vec2-xyzw", frag=fs("", "  vec2 v = vec2(1.0);\n  o = v.xyzw;\n"))
probe("c-swizzle-mixed-sets", frag=fs("", "  vec2 v = vec2(1.0);\n  o = vec4(v.xg, 0.0, 1.0);\n"))
probe("c-swizzle-repeat-as-lvalue", frag=fs("", "  vec2 v = vec2(1.0);\n  v.xx = vec2(2.0);\n  o = vec4(v, 0.0, 1.0);\n"))
probe("c-int-literal-2147483647", frag=fs("", "  int a = 2147483647;\n  o = vec4(float(a));\n"))
probe("c-int-literal-2147483648", frag=fs("", "  int a = 2147483648;\n  o = vec4(float(a));\n"))
probe("c-int-literal-minus-2147483648", frag=fs("", "  int a = -2147483648;\n  o = vec4(float(a));\n"))
probe("c-int-literal-4294967295", frag=fs("", "  int a = 4294967295;\n  o = vec4(float(a));\n"))
probe("c-int-literal-0xFFFFFFFF", frag=fs("", "  int a = 0xFFFFFFFF;\n  o = vec4(float(a));\n"))
probe("c-int-literal-4294967296", frag=fs("", "  int a = 4294967296;\n  o = vec4(float(a));\n"))
probe("c-uint-literal-4294967296u", frag=fs("", "  uint a = 4294967296u;\n  o = vec4(float(a));\n"))
probe("c-invariant-varying-both-stages",
      vert=V + "in vec4 a_position;\ninvariant out vec4 v;\nvoid main() {\n  v = a_position;\n  gl_Position = a_position;\n}\n",
      frag=fs("invariant in vec4 v;\n", "  o = v;\n"))
probe("c-vec3-from-vec4", frag=fs("", "  vec3 v = vec4(1.0);\n  o = vec4(v, 1.0);\n"))
probe("c-frag-only-builtin-in-vertex", vert=V + "in vec4 a_position;\nvoid main() {\n  gl_Position = a_position + dFdx(a_position);\n}\n")
probe("c-discard-in-vertex", vert=V + "in vec4 a_position;\nvoid main() {\n  if (a_position.x > 0.0) discard;\n  gl_Position = a_position;\n}\n")
probe("c-error-count-many", frag=fs("", "  float a = 1;\n  int b = 1.0;\n  o = vec4(c);\n  float d = 1.0\n  o = vec4(a);\n"))

# ---------------------------------------------------------------- 4. link errors
VOUT = V + "in vec4 a_position;\n"
probe("l-varying-only-in-fragment-used", frag=fs("in vec3 v_missing;\n", "  o = vec4(v_missing, 1.0);\n"))
probe("l-varying-only-in-fragment-unused", frag=fs("in vec3 v_missing;\n", "  o = vec4(1.0);\n"))
probe("l-varying-only-in-vertex",
      vert=VOUT + "out vec3 v_extra;\nvoid main() {\n  v_extra = a_position.xyz;\n  gl_Position = a_position;\n}\n")
probe("l-varying-type-mismatch",
      vert=VOUT + "out vec3 v;\nvoid main() {\n  v = a_position.xyz;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec4 v;\n", "  o = v;\n"))
probe("l-varying-type-mismatch-unused",
      vert=VOUT + "out vec3 v;\nvoid main() {\n  v = a_position.xyz;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec4 v;\n", "  o = vec4(1.0);\n"))
probe("l-varying-flat-mismatch",
      vert=VOUT + "flat out vec3 v;\nvoid main() {\n  v = a_position.xyz;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec3 v;\n", "  o = vec4(v, 1.0);\n"))
probe("l-varying-centroid-mismatch",
      vert=VOUT + "centroid out vec3 v;\nvoid main() {\n  v = a_position.xyz;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec3 v;\n", "  o = vec4(v, 1.0);\n"))
probe("l-varying-precision-mismatch",
      vert=VOUT + "out highp vec3 v;\nvoid main() {\n  v = a_position.xyz;\n  gl_Position = a_position;\n}\n",
      frag=fs("in lowp vec3 v;\n", "  o = vec4(v, 1.0);\n"))
probe("l-varying-array-size-mismatch",
      vert=VOUT + "out float v[2];\nvoid main() {\n  v[0] = 1.0;\n  v[1] = 2.0;\n  gl_Position = a_position;\n}\n",
      frag=fs("in float v[3];\n", "  o = vec4(v[0] + v[2]);\n"))
probe("l-uniform-type-mismatch",
      vert=vs("uniform vec3 u;\n", "  gl_Position = a_position + vec4(u, 0.0);\n"),
      frag=fs("uniform highp vec4 u;\n", "  o = u;\n"))
probe("l-uniform-type-mismatch-unused",
      vert=vs("uniform vec3 u;\n", "  gl_Position = a_position;\n"),
      frag=fs("uniform highp vec4 u;\n", "  o = vec4(1.0);\n"))
probe("l-uniform-precision-mismatch",
      vert=vs("uniform float u;\n", "  gl_Position = a_position * u;\n"),
      frag=fs("uniform mediump float u;\n", "  o = vec4(u);\n"))
probe("l-uniform-precision-mismatch-unused-in-fragment",
      vert=vs("uniform float u;\n", "  gl_Position = a_position * u;\n"),
      frag=fs("uniform mediump float u;\n", "  o = vec4(1.0);\n"))
probe("l-uniform-precision-mismatch-unused-both",
      vert=vs("uniform float u;\n", "  gl_Position = a_position;\n"),
      frag=fs("uniform mediump float u;\n", "  o = vec4(1.0);\n"))
probe("l-uniform-struct-field-mismatch",
      vert=vs("struct S {\n  highp float a;\n};\nuniform S u_s;\n", "  gl_Position = a_position * u_s.a;\n"),
      frag=fs("struct S {\n  highp float b;\n};\nuniform S u_s;\n", "  o = vec4(u_s.b);\n"))
probe("l-uniform-block-member-mismatch",
      vert=vs("uniform B {\n  vec4 x;\n};\n", "  gl_Position = a_position + x;\n"),
      frag=fs("uniform B {\n  highp vec4 y;\n};\n", "  o = y;\n"))
probe("l-version-mismatch-100-frag",
      frag="precision mediump float;\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}\n")
probe("l-version-mismatch-100-vert",
      vert="attribute vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n")
probe("l-invariant-varying-vertex-only",
      vert=VOUT + "invariant out vec4 v;\nvoid main() {\n  v = a_position;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec4 v;\n", "  o = v;\n"))
probe("l-invariant-all-pragma-vertex-only",
      vert=V + "#pragma STDGL invariant(all)\nin vec4 a_position;\nout vec4 v;\nvoid main() {\n  v = a_position;\n  gl_Position = a_position;\n}\n",
      frag=fs("in vec4 v;\n", "  o = v;\n"))
probe("l-too-many-attributes-17-vec4",
      vert=V + "".join("in vec4 a%d;\n" % i for i in range(17)) + "void main() {\n  gl_Position = " +
      " + ".join("a%d" % i for i in range(17)) + ";\n}\n")


# ---------------------------------------------------------------- p. preprocessor limits
# ANGLE holds at most 10,000 tokens of macro expansions in progress (expanded arguments plus the
# replacement being built); past that the compile fails with "out of memory". Empty statements
# keep the expanded text valid, so only the limit decides.
TEN = "#define T(x) x x x x x x x x x x\n"
probe("p-macro-tenfold-4-levels", frag=fs(TEN, "  T(T(T(T(;))))\n  o = vec4(1.0);\n"))
probe("p-macro-tenfold-5-levels", frag=fs(TEN, "  T(T(T(T(T(;)))))\n  o = vec4(1.0);\n"))
probe("p-macro-tenfold-6-levels", frag=fs(TEN, "  T(T(T(T(T(T(;))))))\n  o = vec4(1.0);\n"))
probe("p-macro-argument-10000", frag=fs("#define I(x) x\n", "  I(" + "; " * 10000 + ")\n  o = vec4(1.0);\n"))
probe("p-macro-argument-10001", frag=fs("#define I(x) x\n", "  I(" + "; " * 10001 + ")\n  o = vec4(1.0);\n"))
probe("p-macro-replacement-3x5000", frag=fs("#define R(x) x x x\n", "  R(" + "; " * 5000 + ")\n  o = vec4(1.0);\n"))
probe("p-macro-replacement-3x5001", frag=fs("#define R(x) x x x\n", "  R(" + "; " * 5001 + ")\n  o = vec4(1.0);\n"))
probe("p-macro-object-fourfold-7-levels", frag=fs(
    "".join("#define E%d E%d E%d E%d E%d\n" % (i, i + 1, i + 1, i + 1, i + 1) for i in range(7)) + "#define E7 ;\n",
    "  E0\n  o = vec4(1.0);\n"))


# ---------------------------------------------------------------- s. variable size limits
# ANGLE refuses a variable of 2 GiB or more measured as a std140 member, a private variable (local,
# global, const, parameter, varying) of 64 KiB or more measured at 4 bytes per component, and
# private variables of more than 16 MiB in all. The pairs below sit on each boundary.
def local(decl, use):
    return fs("", "  %s\n  %s\n  o = vec4(1.0);\n" % (decl, use))
probe("s-local-float-16383", frag=local("float a[16383];", "a[0] = 1.0;"))
probe("s-local-float-16384", frag=local("float a[16384];", "a[0] = 1.0;"))
probe("s-local-vec3-5461", frag=local("vec3 a[5461];", "a[0] = vec3(1.0);"))
probe("s-local-vec3-5462", frag=local("vec3 a[5462];", "a[0] = vec3(1.0);"))
probe("s-local-mat4-1023", frag=local("mat4 a[1023];", "a[0] = mat4(1.0);"))
probe("s-local-mat4-1024", frag=local("mat4 a[1024];", "a[0] = mat4(1.0);"))
probe("s-local-struct-float-vec2-5461", frag=fs("struct S {\n  float b;\n  vec2 a;\n};\n", "  S s[5461];\n  s[0].b = 1.0;\n  o = vec4(s[0].b);\n"))
probe("s-local-struct-float-vec2-5462", frag=fs("struct S {\n  float b;\n  vec2 a;\n};\n", "  S s[5462];\n  s[0].b = 1.0;\n  o = vec4(s[0].b);\n"))
probe("s-local-int-2147483647", frag=local("int a[2147483647];", "a[0] = 1;"))
probe("s-global-unused-int-2147483647", frag=fs("int g[2147483647];\n", "  o = vec4(1.0);\n"))
probe("s-global-float-16384", frag=fs("float g[16384];\n", "  g[0] = 1.0;\n  o = vec4(g[0]);\n"))
probe("s-parameter-float-16384", frag=fs("float f(float p[16384]) {\n  return p[0];\n}\n", "  o = vec4(1.0);\n"))
probe("s-struct-type-only-float-20000", frag=fs("struct S {\n  float x[20000];\n};\n", "  o = vec4(1.0);\n"))
probe("s-varying-out-vec4-4095", vert=vs("out vec4 v[4095];\n", "  gl_Position = a_position;\n"))
probe("s-varying-out-vec4-4096", vert=vs("out vec4 v[4096];\n", "  gl_Position = a_position;\n"))
probe("s-uniform-float-134217727", frag=fs("uniform float u[134217727];\n", "  o = vec4(u[0]);\n"))
probe("s-uniform-float-134217728", frag=fs("uniform float u[134217728];\n", "  o = vec4(u[0]);\n"))
probe("s-total-private-262-locals", frag=fs("", "".join("  vec4 a%d[4000];\n" % i for i in range(262)) + "  o = vec4(1.0);\n"))
probe("s-total-private-263-locals", frag=fs("", "".join("  vec4 a%d[4000];\n" % i for i in range(263)) + "  o = vec4(1.0);\n"))

# What follows the last label of a `switch`: ANGLE removes `if (false) S` (no `else`) as it
# parses it, so a `switch` whose last label is followed only by such statements has none.
for i, stmt in enumerate([
    "if (false) break;", ";", "{}", "if (true) {}", "if (false) {} else {}",
    "{ if (false) break; }", "float x;", "if (false) o = vec4(2.0);", "if (1 > 2) break;",
    "if (u > 2) break;", "while (false) {}", "o;", "if (true) break;",
    "const bool k = false;\n      if (k) break;", "if (false) break;\n      if (false) break;",
    "if (isinf(10.0)) break;", "if (false ? u > 0 : false) break;", "if (!true) break;",
    "if (false && u > 0) break;", "if ((u, false)) break;", "if (bool(0)) break;",
]):
    probe("c-switch-last-label-then-%d" % i, frag=fs(
        "uniform int u;\n",
        "  o = vec4(0.0);\n  switch (u) {\n    case 0:\n      o = vec4(1.0);\n      break;\n"
        "    default:\n      %s\n  }\n" % stmt))

# A run-time index into a fragment output: Chromium refuses it into the output itself (an
# array or a vector), not into an element of an output array or a swizzle.
for name, decl, body in [
    ("vector", "", "  o = vec4(0.0);\n  o[u] = 1.0;\n"),
    ("vector-read", "", "  o = vec4(0.0);\n  float x = o[u];\n  o.x = x;\n"),
    ("loop-index", "", "  o = vec4(0.0);\n  for (int k = 0; k < 4; k++) o[k] = 1.0;\n"),
    ("const-index", "", "  o = vec4(0.0);\n  const int k = 2;\n  o[k] = 1.0;\n"),
    ("local-copy", "", "  vec4 t = vec4(0.0);\n  t[u] = 1.0;\n  o = t;\n"),
    ("swizzle", "", "  o = vec4(0.0);\n  o.xy[u] = 1.0;\n"),
]:
    probe("c-output-index-" + name, frag=FS_HEAD + "uniform int u;\n" + decl + "void main() {\n" + body + "}\n")
ARRAY_FS = V + "precision mediump float;\nuniform int u;\nlayout(location = 0) out vec4 o[2];\n"
probe("c-output-index-array", frag=ARRAY_FS + "void main() {\n  o[u] = vec4(1.0);\n}\n")
probe("c-output-index-array-element", frag=ARRAY_FS + "void main() {\n  o[0] = vec4(0.0);\n  o[1] = vec4(0.0);\n  o[1][u] = 1.0;\n}\n")

# Loops that cannot end (ANGLE's PruneInfiniteLoops, refused in WebGL): a `while` or `for`
# whose condition is missing or always true, with no `break` of it and no `return` inside.
for i, (decl, body) in enumerate([
    ("", "while (true) {}"), ("", "for (;;) {}"), ("", "while (true) { if (u > 0) break; }"),
    ("", "do {} while (true);"), ("", "for (;;) { discard; }"), ("", "while (true) { return; }"),
    ("", "while (1 > 0) {}"), ("", "for (int i = 0; i >= 0; i++) {}"),
    ("", "while (true) { for (int k = 0; k < 2; k++) { break; } }"),
    ("", "while (true) { switch (u) { default: break; } }"),
    ("", "const bool t = true; while (t) {}"), ("", "while (true) { continue; }"),
    ("", "while (false) {}"), ("uniform bool b;\n", "while (b) {}"),
    ("", "bool v = true; while (v) {}"), ("", "bool v = true; while (v) { v = false; }"),
    ("", "bool v = true; while (v) { o += vec4(1.0); } o.x = float(v);"),
    ("", "bool v = true; v = true; while (v) {}"), ("", "bool v = u > 0; while (v) {}"),
    ("bool g = true;\n", "while (g) {}"), ("", "bool v = true; for (int i = 0; v; v = false) {}"),
    ("void f(inout bool p) { p = false; }\n", "bool v = true; while (v) { f(v); }"),
    ("void g(bool p) { while (p) {} }\n", "g(true);"),
    ("void f() { while (true) {} }\n", ""),
    ("", "bool v = true; while (!v) {}"),
]):
    probe("c-infinite-loop-%d" % i, frag=fs("uniform int u;\n" + decl, "  o = vec4(0.0);\n  %s\n" % body))

# `+x` is a value: not assignable, not an `out` or `inout` argument.
for name, decl, body in [
    ("assign", "", "  int i = 1;\n  +i = 2;\n  o = vec4(i);\n"),
    ("increment", "", "  int i = 1;\n  (+i)++;\n  o = vec4(i);\n"),
    ("inout", "void f(inout int p) { p += 1; }\n", "  int i = 1;\n  f(+i);\n  o = vec4(i);\n"),
    ("in", "void f(int p) { o = vec4(p); }\n", "  int i = 1;\n  f(+i);\n"),
    ("read", "", "  int i = 1;\n  i = +i;\n  o = vec4(i);\n"),
]:
    probe("c-unary-plus-" + name, frag=fs(decl, body))

# A comma expression as an l-value: ANGLE keeps the right operand of one whose left operand
# has no effect, which is then assignable if it is a local or a part of a variable, not a
# global or a parameter as such.
for i, body in enumerate([
    "(v, v) = 1.0;", "(g, g) = 1.0;", "(v, g) = 1.0;", "(g, v) = 1.0;", "(o, v) = 1.0;",
    "(v, o.x) = 1.0;", "(1.0, v) = 2.0;", "(w, v)++;", "(w += 1.0, v) = 3.0;", "(w, 1.0) = 2.0;",
    "f(v);", "f((w, v));",
]):
    probe("c-comma-lvalue-%d" % i, frag=fs(
        "float g = 0.0;\nvoid f(inout float p) {\n  (p, p) = 1.0;\n}\n" if body == "f(v);" else
        "float g = 0.0;\nvoid f(out float p) {\n  p = 2.0;\n}\n",
        "  float v = 0.0;\n  float w = 1.0;\n  %s\n  o = vec4(v, w, g, 1.0);\n" % body))

# ---------------------------------------------------------------- constant folding of undefined results
# ANGLE folds a division by zero (and `%` of a negative operand, `inf / inf`, an overflowing
# quotient) to a value, with a warning, and compiles. Each probe also tests the value: the array
# `a` has size 1 when it is what ANGLE's folding gives and -1 (an error) otherwise.
def folded(decl, test):
    return fs(decl + "\n", "  float a[%s ? 1 : -1];\n  a[0] = 1.0;\n  o = vec4(a[0]);\n" % test)
probe("f-int-div-zero", frag=folded("const int k = 1 / 0;", "k == 2147483647"))
probe("f-int-mod-zero-vector", frag=folded("const ivec2 c = ivec2(7) % ivec2(0, 2);", "c == ivec2(2147483647, 1)"))
probe("f-uint-div-zero", frag=folded("const uint u = 1u / (2u - 2u);", "u == 4294967295u"))
probe("f-int-min-div-minus-one", frag=folded("const int k = (-2147483647 - 1) / -1;", "k == 2147483647"))
probe("f-int-neg-mod", frag=folded("const int m = -7 % 3;", "m == 0"))
probe("f-int-mod-neg", frag=folded("const int m = 7 % -3;", "m == 0"))
probe("f-float-div-zero", frag=folded("const float f = 1.0 / 0.0;", "f > 3.4e38"))
probe("f-float-neg-div-zero", frag=folded("const float f = -2.0 / 0.0;", "f < -3.4e38"))
probe("f-float-div-neg-zero", frag=folded("const float f = 2.0 / -0.0;", "f < -3.4e38"))
probe("f-float-zero-by-zero", frag=folded("const float n = 0.0 / 0.0;", "n != n"))
probe("f-float-inf-by-inf", frag=folded("const float n = (1.0 / 0.0) / (1.0 / 0.0);", "n != n"))
probe("f-float-overflow", frag=folded("const float f = 1e38 / 1e-5;", "f > 3.4e38"))
probe("f-vector-div-zero", frag=folded("const vec2 w = vec2(1.0, 0.0) / vec2(0.0);", "w.x > 3.4e38 && w.y != w.y"))
# Built-in functions of constants: ANGLE folds a result GLSL ES leaves undefined to 0, and
# `round` with `roundf` (halves away from 0), `log2` as `logf(x) / logf(2.0f)`.
for name, call, test in [
    ("round-half", "round(0.5)", "x == 1.0"),
    ("round-minus-half", "round(-0.5)", "x == -1.0"),
    ("round-even", "roundEven(2.5)", "x == 2.0"),
    ("log2-exact", "log2(8.0)", "x == 3.0"),
    ("smoothstep-reversed", "smoothstep(1.0, 0.0, 0.25)", "x == 0.0"),
    ("smoothstep-equal", "smoothstep(0.5, 0.5, 0.7)", "x == 0.0"),
    ("clamp-reversed", "clamp(0.5, 1.0, 0.0)", "x == 0.0"),
    ("clamp-int-reversed", "float(clamp(5, 3, 1))", "x == 0.0"),
    ("normalize-zero", "normalize(vec3(0.0)).y", "x == 0.0"),
    ("pow-negative", "pow(-2.0, 2.0)", "x == 0.0"),
    ("pow-zero-zero", "pow(0.0, 0.0)", "x == 0.0"),
    ("atan-zero", "atan(0.0, 0.0)", "x == 0.0"),
    ("log-negative", "log(-1.0)", "x == 0.0"),
    ("log2-zero", "log2(0.0)", "x == 0.0"),
    ("sqrt-negative", "sqrt(-1.0)", "x == 0.0"),
    ("inversesqrt-zero", "inversesqrt(0.0)", "x == 0.0"),
    ("acos-outside", "acos(1.5)", "x == 0.0"),
    ("asin-one", "asin(1.0)", "x > 1.57"),
    ("atanh-one", "atanh(-1.0)", "x == 0.0"),
    ("acosh-below", "acosh(0.5)", "x == 0.0"),
    ("vector-partly-undefined", "sqrt(vec2(4.0, -4.0)).x + sqrt(vec2(4.0, -4.0)).y", "x == 2.0"),
]:
    probe("f-builtin-" + name, frag=folded("const float x = %s;" % call, test))
probe("f-mul-overflow", frag=folded("const float f = 1e38 * 10.0;", "f > 3.4e38"))
probe("f-add-overflow", frag=folded("const float f = 1e38 + 3e38;", "f > 3.4e38"))
probe("f-sub-inf-inf", frag=folded("const float n = (1.0 / 0.0) - (1.0 / 0.0);", "n != n"))
probe("f-mul-inf-zero", frag=folded("const float n = (1.0 / 0.0) * 0.0;", "n != n"))
probe("f-negative-to-uint", frag=folded("const uint u = uint(-1.0);", "u == 4294967295u"))
probe("f-negative-to-uvec", frag=folded("const uvec2 u = uvec2(vec3(-2.0, 1.0, -1.0));", "u == uvec2(4294967294u, 1u)"))
probe("f-global-int-div-zero", frag=fs("int g = 1 / 0;\n", "  o = vec4(float(g));\n"))
probe("f-local-int-div-zero", frag=fs("", "  int x = 5 / (6 % 0);\n  o = vec4(float(x));\n"))
probe("f-es100-div-zero", frag="precision mediump float;\nconst float f = 1.0 / 0.0;\nconst int k = 3 / 0;\nvoid main() {\n  float a[k == 2147483647 ? 1 : -1];\n  a[0] = f;\n  gl_FragColor = vec4(a[0]);\n}\n")

def main():
    os.chdir(ROOT)
    if os.path.isdir(DIR):
        shutil.rmtree(DIR)
    os.makedirs(DIR)
    for name, (v, f) in P.items():
        for ext, src in ((".vert", v), (".frag", f)):
            with open(os.path.join(DIR, name + ext), "w", encoding="utf-8", newline="") as fh:
                fh.write(src)
    subprocess.run([sys.executable, os.path.join("..", "shared", "tools", "webgl2-oracle.py"), DIR,
                    "-o", os.path.join("tests", "oracle", "probes.json")], check=True)
    print("%d probes" % len(P))


if __name__ == "__main__":
    main()
