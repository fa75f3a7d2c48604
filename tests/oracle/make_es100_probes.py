#!/usr/bin/env python3
"""Write the GLSL ES 1.00 and WebGL-limit probe shaders into tests/oracle/es100/ and ask
Chromium about them in each context.

Run from the repository root:  python3 tests/oracle/make_es100_probes.py
Writes tests/oracle/es100/NAME.vert + NAME.frag (one pair per question; the stage not under
test is a trivial valid shader) and, with tests/oracle/webgl-oracle.py:
- es100-webgl1.json: a WebGL 1 context with no extension enabled;
- es100-webgl1-ext.json: a WebGL 1 context after getExtension of OES_standard_derivatives,
  EXT_shader_texture_lod, EXT_frag_depth and WEBGL_draw_buffers;
- es100-webgl2.json: a WebGL 2 context;
- limits-webgl1.json, limits-webgl2.json: getParameter of the limits, supported extensions.
Conclusions: tests/oracle/ES100.md.
"""
import os, shutil, subprocess, sys

DIR = os.path.join("tests", "oracle", "es100")
ORACLE = os.path.join("tests", "oracle", "webgl-oracle.py")
EXTS = "OES_standard_derivatives,EXT_shader_texture_lod,EXT_frag_depth,WEBGL_draw_buffers"

VS0 = "attribute vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n"
FS0 = "precision mediump float;\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}\n"
V3 = "#version 300 es\n"
VS3 = V3 + "in vec4 a_position;\nvoid main() {\n  gl_Position = a_position;\n}\n"
FS3 = V3 + "precision mediump float;\nout vec4 o;\nvoid main() {\n  o = vec4(1.0);\n}\n"


def fs(decls, body, head="precision mediump float;\n"):
    return head + decls + "void main() {\n" + body + "}\n"


def vs(decls, body):
    return "attribute vec4 a_position;\n" + decls + "void main() {\n" + body + "}\n"


P = {}


def probe(name, vert=VS0, frag=FS0):
    assert name not in P, name
    P[name] = (vert, frag)


# ------------------------------------------------------------ built-in constants (sizes read
# back through an active uniform array's size)
for c in ["gl_MaxVertexAttribs", "gl_MaxVertexUniformVectors", "gl_MaxVaryingVectors",
          "gl_MaxVertexTextureImageUnits", "gl_MaxCombinedTextureImageUnits",
          "gl_MaxTextureImageUnits", "gl_MaxFragmentUniformVectors", "gl_MaxDrawBuffers"]:
    probe("k-" + c, vert=vs("uniform float u_k[%s];\n" % c, "  gl_Position = a_position * u_k[0];\n"))
for c in ["gl_MaxVertexAttribs", "gl_MaxVertexUniformVectors", "gl_MaxVertexOutputVectors",
          "gl_MaxFragmentInputVectors", "gl_MaxVertexTextureImageUnits",
          "gl_MaxCombinedTextureImageUnits", "gl_MaxTextureImageUnits",
          "gl_MaxFragmentUniformVectors", "gl_MaxDrawBuffers"]:
    probe("k3-" + c, vert=V3 + "in vec4 a_position;\nuniform float u_k[%s];\nvoid main() {\n  gl_Position = a_position * u_k[0];\n}\n" % c, frag=FS3)


# ------------------------------------------------------------ token length and character set
L257 = "a" * 257
L300 = "b" * 300
probe("t-long-identifier-in-skipped-group", frag=fs("#if 0\nfloat %s;\n#endif\n" % L257, "  gl_FragColor = vec4(1.0);\n"))
probe("t-long-number", frag=fs("", "  gl_FragColor = vec4(0.%s);\n" % ("1" * 300)))
probe("t-long-identifier-in-comment", frag=fs("// %s\n" % L257, "  gl_FragColor = vec4(1.0);\n"))
probe("t-long-macro-parameter-unused", frag=fs("#define F(%s) 1.0\n" % L257, "  gl_FragColor = vec4(1.0);\n"))
probe("t-long-undef", frag=fs("#undef %s\n" % L257, "  gl_FragColor = vec4(1.0);\n"))
probe("t-1025-define", vert="#define X%s 1\n" % ("x" * 1024) + VS0)
probe("t-dollar-in-code", frag=fs("", "  float $a = 1.0;\n  gl_FragColor = vec4(1.0);\n"))
probe("t-quote-in-skipped-group", frag=fs('#if 0\n#line 42 "foo.glsl"\n#endif\n', "  gl_FragColor = vec4(1.0);\n"))
probe("t-at-in-comment", frag=fs("// @ $ ` \" '\n", "  gl_FragColor = vec4(1.0);\n"))
probe("t-non-ascii-in-comment", frag=fs("// \u00e9\u4f60\u597d\n", "  gl_FragColor = vec4(1.0);\n"))
probe("t-backslash-continuation", frag=fs("float f() { return 1.0 + \\\n 2.0; }\n", "  gl_FragColor = vec4(f());\n"))
probe("t-backslash-in-code", frag=fs("", "  float a = 1.0; \\ a = 2.0;\n  gl_FragColor = vec4(a);\n"))
probe("t-quote-in-define-unused", frag=fs('#define Q "x"\n', "  gl_FragColor = vec4(1.0);\n"))

# ------------------------------------------------------------ scoping (GLSL ES 1.00 / 3.00 §4.2)
SS = "struct S {\n  float x;\n};\n"
probe("s-local-hides-struct", frag=fs(SS, "  S S;\n  S.x = 1.0;\n  gl_FragColor = vec4(S.x);\n"))
probe("s-local-hides-struct-then-type", frag=fs(SS, "  S S;\n  S t;\n  gl_FragColor = vec4(1.0);\n"))
probe("s-local-hides-struct-inner-block", frag=fs(SS, "  S a;\n  a.x = 1.0;\n  {\n    float S = 2.0;\n    a.x += S;\n  }\n  S b = a;\n  gl_FragColor = vec4(b.x);\n"))
probe("s-param-hides-struct", frag=fs(SS + "float f(S S) {\n  return S.x;\n}\n", "  gl_FragColor = vec4(f(S(1.0)));\n"))
probe("s-member-named-as-struct", frag=fs(SS + "struct T {\n  S S;\n  S t;\n};\n", "  T v = T(S(1.0), S(2.0));\n  gl_FragColor = vec4(v.S.x + v.t.x);\n"))
probe("s-global-var-same-as-struct", frag=fs(SS + "float S;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("s-struct-hides-local", frag=fs("", "  float x = 1.0;\n  {\n    struct x {\n      float y;\n    };\n    x a = x(2.0);\n    gl_FragColor = vec4(a.y);\n  }\n"))
probe("s-local-hides-function", frag=fs("float f() {\n  return 1.0;\n}\n", "  float f = 2.0;\n  gl_FragColor = vec4(f);\n"))
probe("s-call-hidden-function", frag=fs("float f() {\n  return 1.0;\n}\n", "  float f = 2.0;\n  gl_FragColor = vec4(f());\n"))
probe("s-local-hides-builtin-function", frag=fs("", "  float sin = 2.0;\n  gl_FragColor = vec4(sin);\n"))
probe("s-global-hides-builtin-function", frag=fs("float sin = 2.0;\n", "  gl_FragColor = vec4(sin);\n"))
probe("s-function-named-as-struct", frag=fs(SS + "float S(float a) {\n  return a;\n}\n", "  gl_FragColor = vec4(1.0);\n"))
probe("s-struct-in-for-init-scope", frag=fs("", "  float s = 0.0;\n  for (int i = 0; i < 2; i++) {\n    float i2 = float(i);\n    s += i2;\n  }\n  gl_FragColor = vec4(s);\n"))
probe("s-redeclare-loop-index-in-body", frag=fs("", "  float s = 0.0;\n  for (int i = 0; i < 2; i++) {\n    int i = 3;\n    s += float(i);\n  }\n  gl_FragColor = vec4(s);\n"))
probe("s-redeclare-param-in-body", frag=fs("float f(float a) {\n  float a = 2.0;\n  return a;\n}\n", "  gl_FragColor = vec4(f(1.0));\n"))
probe("s-struct-constructor-hidden-by-local", frag=fs(SS, "  float S = 1.0;\n  gl_FragColor = vec4(S);\n"))
probe("s-local-struct-then-global-use", frag=fs("void g() {\n  struct S {\n    float x;\n  };\n  S a;\n}\n", "  S b;\n  gl_FragColor = vec4(1.0);\n"))
probe("s-variable-named-as-own-type", frag=fs(SS, "  S S = S(1.0);\n  gl_FragColor = vec4(S.x);\n"))

# ------------------------------------------------------------ uniform activity
probe("u-only-in-expression-statement", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  1.0 + u_dead;\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-comma-left", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  float a = (u_dead, u_used);\n  gl_FragColor = vec4(a);\n"))
probe("u-only-bare-statement", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  u_dead;\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-discarded-call", frag=fs("uniform float u_dead;\nuniform float u_used;\nfloat g(float a) { return a; }\n", "  g(u_dead);\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-discarded-swizzle", frag=fs("uniform vec4 u_dead;\nuniform float u_used;\n", "  u_dead.x;\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-for-step", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  for (int i = 0; i < 2; i++, u_dead) {}\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-discarded-ternary", frag=fs("uniform float u_dead;\nuniform float u_used;\nuniform bool u_b;\n", "  u_b ? u_dead : 1.0;\n  gl_FragColor = vec4(u_used);\n"))
probe("u-in-discarded-assignment", frag=fs("uniform float u_live;\n", "  float a;\n  a = u_live;\n  gl_FragColor = vec4(a);\n"))
probe("u-only-in-discarded-builtin", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  sin(u_dead);\n  gl_FragColor = vec4(u_used);\n"))
probe("u-only-in-nested-comma", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  float a = (1.0, u_dead, u_used);\n  gl_FragColor = vec4(a);\n"))
probe("u-only-in-comma-statement", frag=fs("uniform float u_dead;\nuniform float u_used;\n", "  float a;\n  a = 1.0, u_dead;\n  gl_FragColor = vec4(a + u_used);\n"))
probe("u-only-in-discarded-index", frag=fs("uniform float u_dead[2];\nuniform float u_used;\n", "  u_dead[1];\n  gl_FragColor = vec4(u_used);\n"))


# ------------------------------------------------------------ GLSL ES 1.00 rules
def fs3(decls, body):
    return V3 + "precision mediump float;\nout vec4 o;\n" + decls + "void main() {\n" + body + "}\n"


probe("e3-ternary-struct", vert=VS3, frag=fs3(SS + "uniform bool c;\n", "  S a = S(1.0);\n  S b = S(2.0);\n  S r = c ? a : b;\n  o = vec4(r.x);\n"))
probe("e1-ternary-struct", frag=fs(SS + "uniform bool c;\n", "  S a = S(1.0);\n  S b = S(2.0);\n  S r = c ? a : b;\n  gl_FragColor = vec4(r.x);\n"))
probe("e1-array-assign", frag=fs("", "  float a[2];\n  float b[2];\n  b[0] = 1.0;\n  b[1] = 2.0;\n  a = b;\n  gl_FragColor = vec4(a[0]);\n"))
probe("e1-array-equal", frag=fs("", "  float a[2];\n  float b[2];\n  a[0] = 1.0;\n  a[1] = 1.0;\n  b[0] = 1.0;\n  b[1] = 2.0;\n  gl_FragColor = vec4(a == b ? 1.0 : 0.0);\n"))
SA = "struct A {\n  float v[2];\n};\n"
probe("e1-struct-with-array-assign", frag=fs(SA, "  A a;\n  A b;\n  b.v[0] = 1.0;\n  b.v[1] = 1.0;\n  a = b;\n  gl_FragColor = vec4(a.v[0]);\n"))
probe("e1-struct-with-array-equal", frag=fs(SA, "  A a;\n  A b;\n  a.v[0] = 1.0;\n  a.v[1] = 1.0;\n  b.v[0] = 1.0;\n  b.v[1] = 1.0;\n  gl_FragColor = vec4(a == b ? 1.0 : 0.0);\n"))
probe("e1-struct-with-array-local-no-init", frag=fs(SA, "  A a;\n  a.v[0] = 1.0;\n  a.v[1] = 1.0;\n  gl_FragColor = vec4(a.v[0]);\n"))
probe("e1-array-length", frag=fs("", "  float a[2];\n  a[0] = 1.0;\n  a[1] = 1.0;\n  gl_FragColor = vec4(float(a.length()));\n"))
probe("e1-array-constructor", frag=fs("", "  float a[2] = float[2](1.0, 2.0);\n  gl_FragColor = vec4(a[0]);\n"))
probe("e1-first-class-array", frag=fs("", "  float[2] a;\n  a[0] = 1.0;\n  gl_FragColor = vec4(a[0]);\n"))
probe("e1-const-array", frag=fs("const float a[2];\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-unsized-array", frag=fs("uniform float a[];\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-uniform-block", frag=fs("uniform B {\n  vec4 c;\n};\n", "  gl_FragColor = c;\n"))
for name, expr in [("and", "1 & 2"), ("or", "1 | 2"), ("xor", "1 ^ 2"), ("shl", "1 << 2"), ("shr", "4 >> 1"), ("mod", "5 % 2"), ("not", "~1")]:
    probe("e1-bitwise-" + name, frag=fs("", "  int a = %s;\n  gl_FragColor = vec4(float(a));\n" % expr))
probe("e1-uint-literal", frag=fs("", "  int a = 1u;\n  gl_FragColor = vec4(float(a));\n"))
probe("e1-float-suffix", frag=fs("", "  float a = 1.0f;\n  gl_FragColor = vec4(a);\n"))
probe("e1-int-overflow-literal", frag=fs("", "  int a = 4294967296;\n  gl_FragColor = vec4(float(a));\n"))
probe("e1-int-large-literal", frag=fs("", "  int a = 3000000000;\n  gl_FragColor = vec4(float(a));\n"))
UF = "uniform float u;\n"
probe("e1-global-init-uniform", frag=fs(UF + "float g = u;\n", "  gl_FragColor = vec4(g);\n"))
probe("e1-global-init-global", frag=fs("float a = 1.0;\nfloat b = a;\n", "  gl_FragColor = vec4(b);\n"))
probe("e1-global-init-user-call", frag=fs("float f() { return 1.0; }\nfloat g = f();\n", "  gl_FragColor = vec4(g);\n"))
probe("e1-global-init-math", frag=fs(UF + "float g = sin(u) + 1.0;\n", "  gl_FragColor = vec4(g);\n"))
probe("e1-global-init-texture", frag=fs("uniform sampler2D s;\nvec4 g = texture2D(s, vec2(0.5));\n", "  gl_FragColor = g;\n"))
probe("e1-global-init-varying", frag=fs("varying float v;\nfloat g = v;\n", "  gl_FragColor = vec4(g);\n"), vert=vs("varying float v;\n", "  v = 1.0;\n  gl_Position = a_position;\n"))
probe("e1-global-init-attribute", vert=vs("vec4 g = a_position;\n", "  gl_Position = g;\n"))
probe("e1-global-init-fragcoord", frag=fs("vec4 g = gl_FragCoord;\n", "  gl_FragColor = g;\n"))
probe("e1-global-init-assignment", frag=fs("float a = 1.0;\nfloat b = (a = 2.0);\n", "  gl_FragColor = vec4(b);\n"))
probe("e1-global-init-ternary-uniform", frag=fs(UF + "float g = u > 0.0 ? u : 1.0;\n", "  gl_FragColor = vec4(g);\n"))
probe("e3-global-init-uniform", vert=VS3, frag=fs3(UF + "float g = u;\n", "  o = vec4(g);\n"))
probe("e1-attribute-int", vert="attribute int a_i;\n" + VS0)
probe("e1-attribute-bool", vert="attribute bool a_b;\n" + VS0)
probe("e1-attribute-array", vert="attribute vec4 a_arr[2];\n" + VS0)
probe("e1-attribute-struct", vert=SS + "attribute S a_s;\n" + VS0)
probe("e1-attribute-mat4", vert=vs("attribute mat4 a_m;\n", "  gl_Position = a_m * a_position;\n"))
probe("e1-attribute-in-fragment", frag="attribute vec4 a;\n" + FS0)
probe("e1-attribute-in-function", vert=vs("", "  attribute vec4 b;\n  gl_Position = a_position;\n"))
probe("e1-varying-struct", vert=SS + vs("varying S v;\n", "  gl_Position = a_position;\n"), frag=SS + fs("varying S v;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-varying-int", vert=vs("varying int v;\n", "  v = 1;\n  gl_Position = a_position;\n"), frag=fs("varying int v;\n", "  gl_FragColor = vec4(float(v));\n"))
probe("e1-varying-bool", vert=vs("varying bool v;\n", "  gl_Position = a_position;\n"), frag=fs("varying bool v;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-varying-array-mat", vert=vs("varying mat2 v[2];\n", "  v[0] = mat2(1.0);\n  v[1] = mat2(2.0);\n  gl_Position = a_position;\n"), frag=fs("varying mat2 v[2];\n", "  gl_FragColor = vec4(v[1][0], v[0][1]);\n"))
probe("e1-in-global", vert="in vec4 a;\n" + VS0)
probe("e1-out-global", frag="precision mediump float;\nout vec4 o;\nvoid main() {\n  o = vec4(1.0);\n}\n")
probe("e1-varying-written-in-fragment", vert=vs("varying float v;\n", "  v = 1.0;\n  gl_Position = a_position;\n"), frag=fs("varying float v;\n", "  v = 2.0;\n  gl_FragColor = vec4(v);\n"))
probe("e1-attribute-written", vert=vs("", "  a_position = vec4(1.0);\n  gl_Position = a_position;\n"))
probe("e1-invariant-varying-fragment", vert=vs("invariant varying float v;\n", "  v = 1.0;\n  gl_Position = a_position;\n"), frag=fs("invariant varying float v;\n", "  gl_FragColor = vec4(v);\n"))
probe("e1-invariant-fragcoord", frag=fs("invariant gl_FragCoord;\n", "  gl_FragColor = gl_FragCoord;\n"))
probe("e1-invariant-frontfacing", frag=fs("invariant gl_FrontFacing;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-invariant-pointcoord", frag=fs("invariant gl_PointCoord;\n", "  gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0);\n"))
probe("e1-invariant-uniform", frag=fs(UF + "invariant u;\n", "  gl_FragColor = vec4(u);\n"))
probe("e1-invariant-fragcolor-statement", frag=fs("invariant gl_FragColor;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-invariant-mismatch", vert=vs("invariant varying float v;\n", "  v = 1.0;\n  gl_Position = a_position;\n"), frag=fs("varying float v;\n", "  gl_FragColor = vec4(v);\n"))
probe("e1-invariant-mismatch-unused", vert=vs("invariant varying float v;\n", "  v = 1.0;\n  gl_Position = a_position;\n"), frag=fs("varying float v;\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-invariant-position-fragcoord", vert="invariant gl_Position;\n" + VS0, frag=fs("", "  gl_FragColor = gl_FragCoord;\n"))
probe("e1-invariant-position-fragcoord-both", vert="invariant gl_Position;\n" + VS0, frag=fs("invariant gl_FragCoord;\n", "  gl_FragColor = gl_FragCoord;\n"))
probe("e1-invariant-fragcoord-only", frag=fs("invariant gl_FragCoord;\n", "  gl_FragColor = gl_FragCoord;\n"), vert=VS0)
probe("e1-duplicate-prototype", frag=fs("float f(float a);\nfloat f(float a);\nfloat f(float a) { return a; }\n", "  gl_FragColor = vec4(f(1.0));\n"))
probe("e1-builtin-overload", frag=fs("float sin(int a) { return 1.0; }\n", "  gl_FragColor = vec4(sin(1) + sin(1.0));\n"))
probe("e1-builtin-redefine", frag=fs("float sin(float a) { return 1.0; }\n", "  gl_FragColor = vec4(sin(1.0));\n"))
probe("e3-builtin-overload", vert=VS3, frag=fs3("float sin(int a) { return 1.0; }\n", "  o = vec4(sin(1));\n"))
probe("e1-es3-builtin-name-free", frag=fs("float round(float a) { return floor(a + 0.5); }\nfloat texture(float a) { return a; }\n", "  gl_FragColor = vec4(round(1.2) + texture(1.0));\n"))
probe("e1-es3-builtin-call", frag=fs("", "  gl_FragColor = vec4(round(1.2));\n"))
probe("e1-int-abs", frag=fs("", "  int a = abs(-1);\n  gl_FragColor = vec4(float(a));\n"))
probe("e1-matrix-from-matrix", frag=fs("", "  mat3 m = mat3(mat4(1.0));\n  mat4 n = mat4(mat2(1.0));\n  gl_FragColor = vec4(m[0][0] + n[3][3]);\n"))
probe("e1-struct-return-with-array", frag=fs(SA + "A f() { A a; a.v[0] = 1.0; a.v[1] = 1.0; return a; }\n", "  gl_FragColor = vec4(1.0);\n"))
probe("e1-struct-param-with-array", frag=fs(SA + "float f(A a) { return a.v[1]; }\n", "  A a;\n  a.v[0] = 1.0;\n  a.v[1] = 1.0;\n  gl_FragColor = vec4(f(a));\n"))
probe("e1-while", frag=fs("", "  int k = 0;\n  while (k < 5) {\n    k++;\n  }\n  gl_FragColor = vec4(float(k));\n"))
probe("e1-do-while", frag=fs("", "  int k = 0;\n  do {\n    k++;\n  } while (k < 5);\n  gl_FragColor = vec4(float(k));\n"))
FOR = lambda head, body="    s += 1.0;\n", pre="": fs(UF + "uniform int n;\n", pre + "  float s = 0.0;\n  for (%s) {\n%s  }\n  gl_FragColor = vec4(s);\n" % (head, body))
probe("l-empty-for", frag=FOR(";;", "    s += 1.0;\n    break;\n"))
probe("l-uniform-bound", frag=FOR("int i = 0; i < n; i++"))
probe("l-float-index", frag=FOR("float f = 0.0; f < 2.5; f += 0.5"))
probe("l-plus-equals-2", frag=FOR("int i = 0; i < 10; i += 2"))
probe("l-i-equals-i-plus-1", frag=FOR("int i = 0; i < 10; i = i + 1"))
probe("l-times-equals", frag=FOR("int i = 1; i < 10; i *= 2"))
probe("l-reversed-condition", frag=FOR("int i = 0; 5 > i; i++"))
probe("l-compound-condition", frag=FOR("int i = 0; i < 5 && true; i++"))
probe("l-assign-index-in-body", frag=FOR("int i = 0; i < 5; i++", "    i = 3;\n"))
probe("l-index-out-param", frag=fs("void g(out int a) { a = 1; }\n", "  for (int i = 0; i < 5; i++) {\n    g(i);\n  }\n  gl_FragColor = vec4(1.0);\n"))
probe("l-index-inout-param", frag=fs("void g(inout int a) { a += 1; }\n", "  for (int i = 0; i < 5; i++) {\n    g(i);\n  }\n  gl_FragColor = vec4(1.0);\n"))
probe("l-index-in-param", frag=fs("float g(int a) { return float(a); }\n", "  float s = 0.0;\n  for (int i = 0; i < 5; i++) {\n    s += g(i);\n  }\n  gl_FragColor = vec4(s);\n"))
probe("l-index-declared-outside", frag=FOR("i = 0; i < 5; i++", pre="  int i;\n"))
probe("l-two-declarators", frag=FOR("int i = 0, j = 0; i < 5; i++"))
probe("l-nonconst-init", frag=FOR("int i = n; i < 5; i++"))
probe("l-const-var-bound", frag=FOR("int i = 0; i < K; i++", pre="  const int K = 3;\n"))
probe("l-uint-index", frag=FOR("int i = 0; i < 5; i++"))
probe("l-bool-index", frag=FOR("bool b = true; b != false; b = false"))
probe("l-equal-condition", frag=FOR("int i = 0; i != 5; i++"))
probe("l-decrement", frag=FOR("int i = 5; i >= 0; i--"))
probe("l-pre-increment", frag=FOR("int i = 0; i < 5; ++i"))
probe("l-no-step", frag=FOR("int i = 0; i < 5;", "    s += 1.0;\n    break;\n"))
probe("l-condition-other-var", frag=FOR("int i = 0; n < 5; i++"))
probe("l-step-nonconst", frag=FOR("int i = 0; i < 5; i += n"))
probe("l-index-assigned-in-nested-loop", frag=fs("", "  for (int i = 0; i < 5; i++) {\n    for (int j = 0; j < 2; j++) {\n      i++;\n    }\n  }\n  gl_FragColor = vec4(1.0);\n"))
probe("l-vertex-while", vert=vs("", "  int k = 0;\n  while (k < 5) {\n    k++;\n  }\n  gl_Position = a_position * float(k);\n"))
IDX = lambda decls, body: fs(decls + "uniform int n;\n", body)
probe("i-local-array-nonconst", frag=IDX("", "  float a[3];\n  a[0] = 1.0;\n  a[1] = 1.0;\n  a[2] = 1.0;\n  gl_FragColor = vec4(a[n]);\n"))
probe("i-uniform-array-nonconst-frag", frag=IDX("uniform float a[3];\n", "  gl_FragColor = vec4(a[n]);\n"))
probe("i-uniform-array-nonconst-vert", vert=vs("uniform float a[3];\nuniform int n;\n", "  gl_Position = a_position * a[n];\n"))
probe("i-local-array-nonconst-vert", vert=vs("uniform int n;\n", "  float a[3];\n  a[0] = 1.0;\n  a[1] = 1.0;\n  a[2] = 1.0;\n  gl_Position = a_position * a[n];\n"))
probe("i-vector-nonconst-vert", vert=vs("uniform int n;\n", "  gl_Position = vec4(a_position[n]);\n"))
probe("i-uniform-vector-nonconst-vert", vert=vs("uniform int n;\nuniform vec4 u;\n", "  gl_Position = vec4(u[n]);\n"))
probe("i-uniform-matrix-nonconst-vert", vert=vs("uniform int n;\nuniform mat4 m;\n", "  gl_Position = m[n];\n"))
probe("i-vector-nonconst-frag", frag=IDX("uniform vec4 v;\n", "  gl_FragColor = vec4(v[n]);\n"))
probe("i-loop-index-expression", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    s += a[i * 2 + 1] + a[i - (i / 2)];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-loop-index-constructor", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (float f = 0.0; f < 3.0; f++) {\n    s += a[int(f)];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-loop-index-builtin", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (float f = 0.0; f < 3.0; f++) {\n    s += a[int(floor(f))];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-loop-index-user-call", frag=IDX("uniform float a[8];\nint g(int x) { return x; }\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    s += a[g(i)];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-outer-loop-index", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    for (int j = 0; j < 2; j++) {\n      s += a[i + j];\n    }\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-const-local", frag=IDX("uniform float a[8];\n", "  const int k = 2;\n  gl_FragColor = vec4(a[k + 1]);\n"))
probe("i-index-in-for-condition", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    s += a[i];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-sampler-array-loop", frag=IDX("uniform sampler2D s[2];\n", "  vec4 c = vec4(0.0);\n  for (int i = 0; i < 2; i++) {\n    c += texture2D(s[i], vec2(0.5));\n  }\n  gl_FragColor = c;\n"))
probe("i-sampler-array-nonconst", frag=IDX("uniform sampler2D s[2];\n", "  gl_FragColor = texture2D(s[n], vec2(0.5));\n"))
probe("i-loop-index-in-step-of-other", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    int j = i;\n    s += a[j];\n  }\n  gl_FragColor = vec4(s);\n"))
probe("i-index-in-loop-condition-expr", frag=IDX("uniform float a[8];\n", "  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    s += a[i];\n  }\n  gl_FragColor = vec4(s + a[1]);\n"))
probe("i-global-nonconst-vert", vert=vs("uniform int n;\nfloat g[2];\n", "  g[0] = 1.0;\n  g[1] = 2.0;\n  gl_Position = a_position * g[n];\n"))
probe("i-varying-array-vert", vert=vs("uniform int n;\nvarying float v[2];\n", "  v[n] = 1.0;\n  gl_Position = a_position;\n"), frag=fs("varying float v[2];\n", "  gl_FragColor = vec4(v[0] + v[1]);\n"))
probe("i-varying-array-frag", vert=vs("varying float v[2];\n", "  v[0] = 1.0;\n  v[1] = 1.0;\n  gl_Position = a_position;\n"), frag=fs("varying float v[2];\nuniform int n;\n", "  gl_FragColor = vec4(v[n]);\n"))
probe("i-struct-uniform-array-field-vert", vert=SA + vs("uniform A u;\nuniform int n;\n", "  gl_Position = a_position * u.v[n];\n"))
probe("i-uniform-struct-array-vert", vert=SS + vs("uniform S u[2];\nuniform int n;\n", "  gl_Position = a_position * u[n].x;\n"))


# ------------------------------------------------------------ varying packing (both versions)
def vpair(decls, writes, reads, vextra="", fextra="", es3=False):
    if es3:
        vd = "".join("out %s;\n" % d for d in decls)
        fd = "".join("in %s;\n" % d for d in decls)
        return (V3 + "in vec4 a_position;\n" + vd + "void main() {\n" + writes + vextra + "  gl_Position = a_position;\n}\n",
                V3 + "precision mediump float;\nout vec4 o;\n" + fd + "void main() {\n  vec4 s = vec4(0.0);\n" + reads + fextra + "  o = s;\n}\n")
    vd = "".join("varying %s;\n" % d for d in decls)
    return (vs(vd, writes + vextra + "  gl_Position = a_position;\n"),
            fs(vd, "  vec4 s = vec4(0.0);\n" + reads + fextra + "  gl_FragColor = s;\n"))


def vecs(n, ty, count, es3=False, vextra="", fextra="", used=None):
    used = count if used is None else used
    decls = ["%s %s%d" % (ty, "v", i) for i in range(count)]
    zero = {"float": "0.0", "vec2": "vec2(0.0)", "vec3": "vec3(0.0)", "vec4": "vec4(0.0)", "mat2": "mat2(0.0)", "mat3": "mat3(0.0)", "mat4": "mat4(0.0)"}[ty]
    writes = "".join("  v%d = %s;\n" % (i, zero) for i in range(count))
    comp = {"float": "v%d", "vec2": "v%d.x", "vec3": "v%d.x", "vec4": "v%d.x", "mat2": "v%d[0][0]", "mat3": "v%d[0][0]", "mat4": "v%d[0][0]"}[ty]
    reads = "".join("  s.x += %s;\n" % (comp % i) for i in range(used))
    v, f = vpair(decls, writes, reads, vextra, fextra, es3)
    probe(n, vert=v, frag=f)


vecs("p-16-vec2", "vec2", 16)
vecs("p-62-vec2", "vec2", 62)
vecs("p-63-vec2", "vec2", 63)
vecs("p-31-vec4", "vec4", 31)
vecs("p-32-vec4", "vec4", 32)
vecs("p-32-vec4-31-used", "vec4", 32, used=31)
vecs("p-31-vec4-fragcoord", "vec4", 31, fextra="  s += gl_FragCoord;\n")
vecs("p-31-vec4-pointcoord", "vec4", 31, fextra="  s.xy += gl_PointCoord;\n")
vecs("p-31-vec4-frontfacing", "vec4", 31, fextra="  s.x += gl_FrontFacing ? 1.0 : 0.0;\n")
vecs("p-31-vec4-pointsize", "vec4", 31, vextra="  gl_PointSize = 1.0;\n")
vecs("p-124-float", "float", 124)
vecs("p-125-float", "float", 125)
vecs("p-41-vec3", "vec3", 41)
vecs("p-42-vec3", "vec3", 42)
vecs("p-15-mat2", "mat2", 15)
vecs("p-16-mat2", "mat2", 16)
vecs("p-10-mat3", "mat3", 10)
vecs("p-11-mat3", "mat3", 11)
vecs("p3-31-vec4", "vec4", 31, es3=True)
vecs("p3-32-vec4", "vec4", 32, es3=True)
vecs("p3-62-vec2", "vec2", 62, es3=True)
vecs("p3-63-vec2", "vec2", 63, es3=True)
vecs("p3-16-mat2", "mat2", 16, es3=True)
vecs("p3-31-vec4-fragcoord", "vec4", 31, es3=True, fextra="  s += gl_FragCoord;\n")
probe("p-float-array-32", vert=vs("varying float v[32];\n", "  for (int i = 0; i < 32; i++) { v[i] = 0.0; }\n  gl_Position = a_position;\n"), frag=fs("varying float v[32];\n", "  gl_FragColor = vec4(v[31]);\n"))
probe("p-float-array-31", vert=vs("varying float v[31];\n", "  for (int i = 0; i < 31; i++) { v[i] = 0.0; }\n  gl_Position = a_position;\n"), frag=fs("varying float v[31];\n", "  gl_FragColor = vec4(v[30]);\n"))
probe("p-mixed", vert=vs("varying vec3 a[10];\nvarying vec2 b[20];\nvarying float c[30];\nvarying vec4 d[5];\n", "  for (int i = 0; i < 10; i++) { a[i] = vec3(0.0); }\n  for (int i = 0; i < 20; i++) { b[i] = vec2(0.0); }\n  for (int i = 0; i < 30; i++) { c[i] = 0.0; }\n  for (int i = 0; i < 5; i++) { d[i] = vec4(0.0); }\n  gl_Position = a_position;\n"), frag=fs("varying vec3 a[10];\nvarying vec2 b[20];\nvarying float c[30];\nvarying vec4 d[5];\n", "  gl_FragColor = vec4(a[9].x + b[19].x + c[29] + d[4].x);\n"))

# ------------------------------------------------------------ WebGL limits
def nested(levels):
    out = "struct S0 {\n  float x;\n};\n"
    for i in range(1, levels):
        out += "struct S%d {\n  S%d s;\n};\n" % (i, i - 1)
    return out


probe("w-struct-nesting-4", frag=fs(nested(4) + "uniform S3 u;\n", "  gl_FragColor = vec4(u.s.s.s.x);\n"))
probe("w-struct-nesting-5", frag=fs(nested(5) + "uniform S4 u;\n", "  gl_FragColor = vec4(u.s.s.s.s.x);\n"))
probe("w-struct-nesting-5-unused", frag=fs(nested(5), "  gl_FragColor = vec4(1.0);\n"))
probe("w3-struct-nesting-5", vert=VS3, frag=fs3(nested(5), "  o = vec4(1.0);\n"))
probe("w3-struct-nesting-4", vert=VS3, frag=fs3(nested(4) + "uniform S3 u;\n", "  o = vec4(u.s.s.s.x);\n"))


def chain(n, used=True):
    out = "float f0(float x) { return x + 1.0; }\n"
    for i in range(1, n):
        out += "float f%d(float x) { return f%d(x) + 1.0; }\n" % (i, i - 1)
    return out


probe("w-call-depth-256", frag=fs(chain(256), "  gl_FragColor = vec4(f255(0.0));\n"))
probe("w-call-depth-257", frag=fs(chain(257), "  gl_FragColor = vec4(f256(0.0));\n"))
probe("w-call-depth-257-unused", frag=fs(chain(257), "  gl_FragColor = vec4(1.0);\n"))
probe("w3-call-depth-257", vert=VS3, frag=fs3(chain(257), "  o = vec4(f256(0.0));\n"))
probe("w-uniforms-4096-vec4", frag=fs("uniform vec4 u[4096];\n", "  gl_FragColor = u[4095];\n"))
probe("w-uniforms-4097-vec4", frag=fs("uniform vec4 u[4097];\n", "  gl_FragColor = u[4096];\n"))
probe("w-uniforms-4097-float", frag=fs("uniform float u[4097];\n", "  gl_FragColor = vec4(u[4096]);\n"))
probe("w-uniforms-4096-vec4-unused", frag=fs("uniform vec4 u[5000];\n", "  gl_FragColor = vec4(1.0);\n"))
probe("w-uniforms-2x2048-vec4", frag=fs("uniform vec4 u[2048];\nuniform vec4 w[2049];\n", "  gl_FragColor = u[1] + w[1];\n"))
probe("w-samplers-32", frag=fs("uniform sampler2D s[32];\n", "  gl_FragColor = texture2D(s[31], vec2(0.5));\n"))
probe("w-samplers-33", frag=fs("uniform sampler2D s[33];\n", "  gl_FragColor = texture2D(s[32], vec2(0.5));\n"))
probe("w-vertex-sampler", vert=vs("uniform sampler2D s;\n", "  gl_Position = a_position + texture2DLod(s, vec2(0.5), 0.0);\n"))
probe("w-attribute-name-uniform-name", vert=vs("attribute float x;\n", "  gl_Position = a_position * x;\n"), frag=fs("uniform float x;\n", "  gl_FragColor = vec4(x);\n"))
probe("w-attribute-name-uniform-unused", vert=vs("attribute float x;\n", "  gl_Position = a_position;\n"), frag=fs("uniform float x;\n", "  gl_FragColor = vec4(x);\n"))
probe("w3-attribute-name-uniform-name", vert=V3 + "in vec4 a_position;\nin float x;\nvoid main() {\n  gl_Position = a_position * x;\n}\n", frag=fs3("uniform float x;\n", "  o = vec4(x);\n"))
probe("w-webgl-prefix-function", frag=fs("float webgl_f() { return 1.0; }\n", "  gl_FragColor = vec4(webgl_f());\n"))
probe("w-webgl-prefix-field", frag=fs("struct T {\n  float webgl_x;\n};\n", "  T t = T(1.0);\n  gl_FragColor = vec4(t.webgl_x);\n"))
probe("w-webgl-prefix-macro", frag=fs("#define webgl_M 1.0\n", "  gl_FragColor = vec4(webgl_M);\n"))
probe("w-gl-prefix-macro", frag=fs("#define GL_M 1.0\n", "  gl_FragColor = vec4(GL_M);\n"))
probe("w-double-underscore-variable", frag=fs("", "  float a__b = 1.0;\n  gl_FragColor = vec4(a__b);\n"))
probe("w-double-underscore-macro", frag=fs("#define A__B 1.0\n", "  gl_FragColor = vec4(A__B);\n"))
probe("w-underscore-u-1021", frag=fs("", "  float _u%s = 1.0;\n  gl_FragColor = vec4(_u%s);\n" % ("x" * 1019, "x" * 1019)))
probe("w-underscore-u-1022", frag=fs("", "  float _u%s = 1.0;\n  gl_FragColor = vec4(_u%s);\n" % ("x" * 1020, "x" * 1020)))
probe("w-gl-fragdata-1-noext", frag=fs("", "  gl_FragData[1] = vec4(1.0);\n"))
probe("w-gl-fragdata-1-ext", frag="#extension GL_EXT_draw_buffers : require\n" + fs("", "  gl_FragData[1] = vec4(1.0);\n"))
probe("w-gl-fragdata-loop-ext", frag="#extension GL_EXT_draw_buffers : require\n" + fs("", "  for (int i = 0; i < 2; i++) {\n    gl_FragData[i] = vec4(1.0);\n  }\n"))
probe("w-gl-fragdata-0-nonconst", frag=fs("uniform int n;\n", "  gl_FragData[n] = vec4(1.0);\n"))
probe("w-fragdepth-ext", frag="#extension GL_EXT_frag_depth : enable\n" + fs("", "  gl_FragDepthEXT = 0.5;\n  gl_FragColor = vec4(1.0);\n"))
probe("w-fragdepth-ext-no-directive", frag=fs("", "  gl_FragDepthEXT = 0.5;\n  gl_FragColor = vec4(1.0);\n"))
probe("w-derivatives-ext", frag="#extension GL_OES_standard_derivatives : enable\n" + fs("varying vec2 v;\n", "  gl_FragColor = vec4(dFdx(v.x) + fwidth(v.y));\n"), vert=vs("varying vec2 v;\n", "  v = a_position.xy;\n  gl_Position = a_position;\n"))
probe("w-derivatives-ext-warn", frag="#extension GL_OES_standard_derivatives : warn\n" + fs("", "  gl_FragColor = vec4(dFdx(1.0));\n"))
probe("w-derivatives-ext-disable", frag="#extension GL_OES_standard_derivatives : disable\n" + fs("", "  gl_FragColor = vec4(dFdx(1.0));\n"))
probe("w-derivatives-ext-after-code", frag=fs("", "  gl_FragColor = vec4(dFdx(1.0));\n") + "#extension GL_OES_standard_derivatives : enable\n")
probe("w-derivatives-ext-all-warn", frag="#extension all : warn\n" + fs("", "  gl_FragColor = vec4(dFdx(1.0));\n"))
probe("w-texture-lod-ext", frag="#extension GL_EXT_shader_texture_lod : enable\n" + fs("uniform sampler2D s;\nuniform samplerCube c;\n", "  gl_FragColor = texture2DLodEXT(s, vec2(0.5), 1.0) + textureCubeGradEXT(c, vec3(1.0), vec3(0.0), vec3(0.0)) + texture2DProjLodEXT(s, vec4(1.0), 0.0);\n"))
probe("w-texture-lod-fragment-noext", frag=fs("uniform sampler2D s;\n", "  gl_FragColor = texture2DLod(s, vec2(0.5), 1.0);\n"))
probe("w-texture-bias-vertex", vert=vs("uniform sampler2D s;\n", "  gl_Position = a_position + texture2D(s, vec2(0.5), 1.0);\n"))
probe("w-texture2d-in-300es", vert=VS3, frag=fs3("uniform sampler2D s;\n", "  o = texture2D(s, vec2(0.5));\n"))
probe("w-mix-versions", vert=VS0, frag=FS3)
probe("w-version-100", vert="#version 100\n" + VS0, frag="#version 100\n" + FS0)
probe("w-pragma-invariant-all-fragment", frag="#pragma STDGL invariant(all)\n" + FS0)


def write():
    if os.path.isdir(DIR):
        shutil.rmtree(DIR)
    os.makedirs(DIR)
    for name, (v, f) in sorted(P.items()):
        for ext, text in (("vert", v), ("frag", f)):
            with open(os.path.join(DIR, f"{name}.{ext}"), "w") as fh:
                fh.write(text)


def run(out, *args):
    subprocess.run([sys.executable, ORACLE, *args, "-o", os.path.join("tests", "oracle", out)],
                   check=True)


if __name__ == "__main__":
    write()
    run("es100-webgl1.json", "--context", "webgl1", DIR)
    run("es100-webgl1-ext.json", "--context", "webgl1", "--extensions", EXTS, DIR)
    run("es100-webgl2.json", "--context", "webgl2", DIR)
    run("limits-webgl1.json", "--context", "webgl1", "--limits", "--extensions", EXTS)
    run("limits-webgl2.json", "--context", "webgl2", "--limits")
