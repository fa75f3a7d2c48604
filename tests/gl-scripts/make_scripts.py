#!/usr/bin/env python3
"""Write the WebGL2 call scripts of tests/gl-scripts/ (format: docs/gl-scripts.md).

usage: make_scripts.py [--out DIR] [--jitter PX]

Writes NAME.json for each multi-pass program beside this file, and probes/NAME.json for each
probe (probes.py). Shaders are hand-written files beside the scripts; this generator writes the
calls and the data they upload: meshes, matrices, particle seeds, computed in float64 and written
with 7 significant digits (the number in the JSON is the number uploaded; Float32Array rounds it).

--out DIR writes the multi-pass scripts into DIR instead (shader paths made relative to DIR), and
--jitter PX moves every perspective or orthographic projection by PX pixels (PX texels for shadow
maps and cube faces) right and up: a variant to measure how many pixels of a picture depend on
sub-pixel rasterisation (see docs/gl-scripts.md, "How robust the pictures are").
"""
import argparse, json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
JITTER = 0.0


# ---------- values ----------

def num(x):
    """A float as its 7 significant digits (an int stays an int)."""
    if isinstance(x, int):
        return x
    v = float(f"{x:.7g}")
    return 0.0 if v == 0 else v


def F32(values):
    return {"f32": [num(float(v)) for v in values]}


def U16(values):
    return {"u16": list(values)}


def U32(values):
    return {"u32": list(values)}


def I32(values):
    return {"i32": list(values)}


def R(name):
    return {"ref": name}


def OR(*names):
    return {"or": list(names)}


def OUT(kind, length, fill=0):
    return {"out": kind, "length": length, **({"fill": fill} if fill else {})}


class File:
    """A shader file beside this generator; written as a path relative to the script's folder."""

    def __init__(self, name):
        self.name = name


# ---------- float64 matrices: flat lists of 16, column-major (element [row r, column c] at c*4+r) ----------

def mul(a, b):
    return [sum(a[k * 4 + r] * b[c * 4 + k] for k in range(4)) for c in range(4) for r in range(4)]


def mul_all(*ms):
    out = ms[0]
    for m in ms[1:]:
        out = mul(out, m)
    return out


def translate(x, y, z):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]


def scale(x, y=None, z=None):
    y = x if y is None else y
    z = x if z is None else z
    return [x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1]


def rotate_y(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1]


def rotate_x(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1]


def rotate_z(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(v):
    n = math.sqrt(dot(v, v))
    return [x / n for x in v]


def look_at(eye, target, up):
    z = unit(sub(eye, target))
    x = unit(cross(up, z))
    y = cross(z, x)
    return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]


def jittered(projection, size):
    """The projection moved JITTER pixels right and up in a viewport of size pixels."""
    d = 2.0 * JITTER / size
    return mul(translate(d, d, 0), projection) if JITTER else projection


def perspective(fov_y_deg, aspect, near, far, size):
    f = 1.0 / math.tan(math.radians(fov_y_deg) / 2)
    return jittered([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (near + far) / (near - far), -1,
                     0, 0, 2 * near * far / (near - far), 0], size)


def ortho(half, near, far, size=None):
    """size: the viewport's size in pixels, for --jitter; None: never moved (a lookup, not a draw)."""
    m = [1 / half, 0, 0, 0, 0, 1 / half, 0, 0, 0, 0, -2 / (far - near), 0,
         0, 0, -(far + near) / (far - near), 1]
    return jittered(m, size) if size else m


def inverse(m):
    """Gauss-Jordan with partial pivoting on the row-major copy of a column-major matrix."""
    a = [[m[c * 4 + r] for c in range(4)] + [1.0 if r == k else 0.0 for k in range(4)] for r in range(4)]
    for col in range(4):
        piv = max(range(col, 4), key=lambda r: abs(a[r][col]))
        a[col], a[piv] = a[piv], a[col]
        p = a[col][col]
        a[col] = [x / p for x in a[col]]
        for r in range(4):
            if r != col:
                f = a[r][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col])]
    return [a[r][4 + c] for c in range(4) for r in range(4)]


def project(m, p, width, height):
    """Window coordinates (x right, y up, in pixels) of point p under the matrix m."""
    c = [sum(m[k * 4 + r] * (list(p) + [1])[k] for k in range(4)) for r in range(4)]
    return ((c[0] / c[3] * 0.5 + 0.5) * width, (c[1] / c[3] * 0.5 + 0.5) * height)


# ---------- meshes: interleaved position (3) + normal (3) floats, UNSIGNED_SHORT triangle indices ----------

def box(hx, hy, hz):
    verts, idx = [], []
    faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
    h = (hx, hy, hz)
    for f, (n, r, u) in enumerate(faces):
        for sr, su in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            verts += [h[k] * (n[k] + sr * r[k] + su * u[k]) for k in range(3)] + list(n)
        idx += [4 * f, 4 * f + 1, 4 * f + 2, 4 * f, 4 * f + 2, 4 * f + 3]
    return verts, idx


def sphere(radius, segments, rings):
    verts, idx = [], []
    for j in range(rings + 1):
        t = math.pi * j / rings
        for i in range(segments + 1):
            p = 2 * math.pi * i / segments
            n = [math.sin(t) * math.sin(p), math.cos(t), math.sin(t) * math.cos(p)]
            verts += [radius * x for x in n] + n
    for j in range(rings):
        for i in range(segments):
            a = j * (segments + 1) + i
            b, c = a + 1, a + segments + 1
            if j:
                idx += [a, c, b]
            if j != rings - 1:
                idx += [b, c, c + 1]
    return verts, idx


def plane(half):
    verts = []
    for x, z in ((-1, 1), (1, 1), (1, -1), (-1, -1)):
        verts += [half * x, 0, half * z, 0, 1, 0]
    return verts, [0, 1, 2, 0, 2, 3]


# ---------- a script under construction ----------

CONTEXT = {"antialias": False, "depth": True, "stencil": False, "alpha": True, "premultipliedAlpha": True,
           "preserveDrawingBuffer": True}


class Script:
    def __init__(self, name, description, width=128, height=128, context=None, extensions=()):
        self.name, self.description = name, description
        self.width, self.height = width, height
        self.context = dict(CONTEXT, **(context or {}))
        self.extensions = list(extensions)
        self.setup, self.frame = [], []
        self.calls = self.setup
        self.index_counts = {}

    def __call__(self, f, *a, as_=None, record=None, error=None, until=None, status=None):
        c = {"f": f}
        if a:
            c["a"] = list(a)
        for k, v in (("as", as_), ("record", record), ("error", error), ("until", until), ("status", status)):
            if v is not None:
                c[k] = v
        self.calls.append(c)

    def begin_frame(self):
        self.calls = self.frame

    def program(self, name, vert, frag, uniforms=(), varyings=None, mode="INTERLEAVED_ATTRIBS"):
        """Compile, (set transform feedback varyings,) link; uniform locations as NAME.UNIFORM."""
        for stage, src in (("VERTEX_SHADER", vert), ("FRAGMENT_SHADER", frag)):
            sh = f"{name}.{'vs' if stage[0] == 'V' else 'fs'}"
            self("createShader", stage, as_=sh)
            self("shaderSource", R(sh), File(src))
            self("compileShader", R(sh))
        self("createProgram", as_=name)
        self("attachShader", R(name), R(f"{name}.vs"))
        self("attachShader", R(name), R(f"{name}.fs"))
        if varyings:
            self("transformFeedbackVaryings", R(name), list(varyings), mode)
        self("linkProgram", R(name))
        for u in uniforms:
            self("getUniformLocation", R(name), u, as_=f"{name}.{u}")

    def mesh(self, name, mesh):
        """A vertex array: a_position at location 0, a_normal at 1, interleaved; triangle indices."""
        verts, idx = mesh
        self("createVertexArray", as_=name)
        self("bindVertexArray", R(name))
        self("createBuffer", as_=f"{name}.vertices")
        self("bindBuffer", "ARRAY_BUFFER", R(f"{name}.vertices"))
        self("bufferData", "ARRAY_BUFFER", F32(verts), "STATIC_DRAW")
        for loc, offset in ((0, 0), (1, 12)):
            self("enableVertexAttribArray", loc)
            self("vertexAttribPointer", loc, 3, "FLOAT", False, 24, offset)
        self("createBuffer", as_=f"{name}.indices")
        self("bindBuffer", "ELEMENT_ARRAY_BUFFER", R(f"{name}.indices"))
        self("bufferData", "ELEMENT_ARRAY_BUFFER", U16(idx), "STATIC_DRAW")
        self("bindVertexArray", None)
        self.index_counts[name] = len(idx)

    def draw_mesh(self, name):
        self("bindVertexArray", R(name))
        self("drawElements", "TRIANGLES", self.index_counts[name], "UNSIGNED_SHORT", 0)

    def matrix(self, loc, m):
        self("uniformMatrix4fv", R(loc), False, F32(m))

    def draw_objects(self, program, objects):
        """Each (mesh, model, uniforms): PROGRAM.u_model, then each uniform name -> (setter, value) in order,
        then the mesh's draw. The program is already in use."""
        for mesh, model, uniforms in objects:
            self.matrix(f"{program}.u_model", model)
            for name, (setter, value) in uniforms.items():
                self(setter, R(f"{program}.{name}"), value)
            self.draw_mesh(mesh)

    def texture(self, name, target, internal, width, height, filt="NEAREST", levels=1):
        """An immutable texture (texStorage2D), CLAMP_TO_EDGE, one filter for min and mag."""
        self("createTexture", as_=name)
        self("bindTexture", target, R(name))
        self("texStorage2D", target, levels, internal, width, height)
        for p, v in (("TEXTURE_MIN_FILTER", filt), ("TEXTURE_MAG_FILTER", filt),
                     ("TEXTURE_WRAP_S", "CLAMP_TO_EDGE"), ("TEXTURE_WRAP_T", "CLAMP_TO_EDGE")):
            self("texParameteri", target, p, v)

    def renderbuffer(self, name, internal, width, height, samples=0):
        self("createRenderbuffer", as_=name)
        self("bindRenderbuffer", "RENDERBUFFER", R(name))
        if samples:
            self("renderbufferStorageMultisample", "RENDERBUFFER", samples, internal, width, height)
        else:
            self("renderbufferStorage", "RENDERBUFFER", internal, width, height)

    def framebuffer(self, name, attachments, record=None):
        """A framebuffer of (attachment point, texture or renderbuffer name, kind) triples."""
        self("createFramebuffer", as_=name)
        self("bindFramebuffer", "FRAMEBUFFER", R(name))
        for point, obj, kind in attachments:
            if kind == "renderbuffer":
                self("framebufferRenderbuffer", "FRAMEBUFFER", point, "RENDERBUFFER", R(obj))
            else:
                self("framebufferTexture2D", "FRAMEBUFFER", point, kind, R(obj), 0)
        self("checkFramebufferStatus", "FRAMEBUFFER", record=record or f"{name}.status")

    def json(self, folder):
        def resolve(v):
            if isinstance(v, File):
                return {"file": os.path.relpath(os.path.join(HERE, v.name), folder).replace(os.sep, "/")}
            if isinstance(v, list):
                return [resolve(x) for x in v]
            if isinstance(v, dict):
                return {k: resolve(x) for k, x in v.items()}
            return v

        def calls(cs):
            return "[\n" + ",\n".join("  " + json.dumps(resolve(c)) for c in cs) + "\n ]"
        head = {"format": 1, "description": self.description, "width": self.width, "height": self.height,
                "context": self.context, "extensions": self.extensions}
        lines = [f" {json.dumps(k)}: {json.dumps(v)}" for k, v in head.items()]
        lines += [f' "setup": {calls(self.setup)}', f' "frame": {calls(self.frame)}']
        return "{\n" + ",\n".join(lines) + "\n}\n"


# ---------- 1. shadow-map ----------

def shadow_map():
    s = Script("shadow-map", "A depth texture (DEPTH_COMPONENT32F, 256x256) rendered from a directional light, "
               "then read through a comparison sampler object (COMPARE_REF_TO_TEXTURE, LEQUAL, NEAREST) in the "
               "lit pass: a box, a sphere and a thin slab cast soft-edged shadows (a sliding 7x7-texel window of "
               "comparisons) on a floor.")
    size = 256
    scene = [("floor", plane(12.0), translate(0, 0, 0), [0.80, 0.78, 0.72]),
             ("box", box(0.6, 0.6, 0.6), mul(translate(-0.9, 0.6, -0.3), rotate_y(28)), [0.85, 0.35, 0.25]),
             ("ball", sphere(0.65, 24, 16), translate(1.0, 0.65, 0.5), [0.30, 0.55, 0.85]),
             ("slab", box(0.9, 0.06, 0.35), mul(translate(0.2, 1.7, -1.2), rotate_y(-15)), [0.40, 0.75, 0.35])]
    to_light = unit([-0.75, 1.0, 0.55])
    light_view = look_at([x * 10 for x in to_light], [0, 0, 0], [0, 1, 0])
    light_vp = mul(ortho(9.0, 1.0, 24.0), light_view)  # the lookup
    light_vp_draw = mul(ortho(9.0, 1.0, 24.0, size), light_view)  # the same, but for --jitter
    view_proj = mul(perspective(45, 1.0, 0.5, 30.0, s.width), look_at([2.2, 7.0, 5.0], [0.1, 0.0, -0.5], [0, 1, 0]))

    s.program("depth", "common-depth.vert", "common-empty.frag", ["u_mvp"])
    s.program("lit", "common-mesh.vert", "shadow-map-lit.frag",
              ["u_model", "u_viewProjection", "u_shadowMap", "u_lightViewProjection", "u_toLight", "u_color"])
    for name, mesh, _, _ in scene:
        s.mesh(name, mesh)
    s.texture("shadowMap", "TEXTURE_2D", "DEPTH_COMPONENT32F", size, size)
    s.framebuffer("shadowFb", [("DEPTH_ATTACHMENT", "shadowMap", "TEXTURE_2D")])
    s("drawBuffers", ["NONE"])
    s("readBuffer", "NONE")
    s("createSampler", as_="compare")
    for p, v in (("TEXTURE_COMPARE_MODE", "COMPARE_REF_TO_TEXTURE"), ("TEXTURE_COMPARE_FUNC", "LEQUAL"),
                 ("TEXTURE_MIN_FILTER", "NEAREST"), ("TEXTURE_MAG_FILTER", "NEAREST"),
                 ("TEXTURE_WRAP_S", "CLAMP_TO_EDGE"), ("TEXTURE_WRAP_T", "CLAMP_TO_EDGE")):
        s("samplerParameteri", R("compare"), p, v)
    s("getSamplerParameter", R("compare"), "TEXTURE_COMPARE_MODE", record="sampler.compareMode")
    s("useProgram", R("lit"))
    s("uniform1i", R("lit.u_shadowMap"), 1)
    s.matrix("lit.u_viewProjection", view_proj)
    s.matrix("lit.u_lightViewProjection", light_vp)
    s("uniform3fv", R("lit.u_toLight"), F32(to_light))
    s("enable", "DEPTH_TEST")
    s("enable", "CULL_FACE")
    s("clearColor", 0.55, 0.72, 0.85, 1)

    s.begin_frame()
    s("bindFramebuffer", "FRAMEBUFFER", R("shadowFb"))
    s("viewport", 0, 0, size, size)
    s("clear", "DEPTH_BUFFER_BIT")
    s("useProgram", R("depth"))
    for name, _, model, _ in scene:
        s.matrix("depth.u_mvp", mul(light_vp_draw, model))
        s.draw_mesh(name)
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("viewport", 0, 0, s.width, s.height)
    s("clear", OR("COLOR_BUFFER_BIT", "DEPTH_BUFFER_BIT"))
    s("useProgram", R("lit"))
    s("activeTexture", "TEXTURE1")
    s("bindTexture", "TEXTURE_2D", R("shadowMap"))
    s("bindSampler", 1, R("compare"))
    s.draw_objects("lit", [(name, model, {"u_color": ("uniform3fv", F32(color))}) for name, _, model, color in scene])
    s("bindSampler", 1, None)
    s("bindVertexArray", None)
    return s


def hsv(h, s, v):
    k = [(n + h * 6) % 6 for n in (5, 3, 1)]
    return [v - v * s * max(0.0, min(x, 4 - x, 1.0)) for x in k]


def lcg(seed):
    """Numbers in [0, 1) from a 32-bit linear congruential generator (Numerical Recipes' constants)."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % (1 << 32)
        yield state / (1 << 32)


def fullscreen(s, program):
    s("useProgram", R(program))
    s("bindVertexArray", None)
    s("drawArrays", "TRIANGLES", 0, 3)


def bind_textures(s, textures):
    """Textures on units 0, 1, ... in order: (target, texture name)."""
    for unit, (target, name) in enumerate(textures):
        s("activeTexture", f"TEXTURE{unit}")
        s("bindTexture", target, R(name))


# ---------- 2. deferred ----------

def deferred():
    s = Script("deferred", "Deferred shading: a geometry pass into three colour targets at once (RGBA8 albedo and "
               "specular, RGBA16F normal, RGBA32F position; drawBuffers, layout(location = N) out) with a "
               "DEPTH_COMPONENT24 renderbuffer, then a full-screen pass that reads them with texelFetch and "
               "sums 32 point lights from a uniform buffer.", extensions=["EXT_color_buffer_float"])
    w, h = s.width, s.height
    scene = [("floor", plane(9.0), translate(0, 0, 0), [0.7, 0.7, 0.7], 0.2)]
    shapes = {"ball": sphere(0.45, 20, 12), "box": box(0.38, 0.38, 0.38)}
    for i in range(3):
        for j in range(3):
            kind = "ball" if (i + j) % 2 == 0 else "box"
            y = 0.45 if kind == "ball" else 0.38
            scene.append((kind, None, mul(translate(1.5 * (i - 1), y, 1.5 * (j - 1)), rotate_y(20 * i + 35 * j)),
                          hsv((i * 3 + j) / 9.0, 0.35, 0.9), 0.8 if kind == "ball" else 0.3))
    eye = [0.6, 6.0, 4.6]
    view_proj = mul(perspective(50, w / h, 0.5, 30.0, w), look_at(eye, [0, 0, -0.2], [0, 1, 0]))
    rnd = lcg(7)
    lights = []
    for k in range(32):
        a = 2 * math.pi * (k / 32.0) + 0.3 * next(rnd)
        r = 1.0 + 2.6 * next(rnd)
        lights.append(([r * math.cos(a), 0.25 + 0.9 * next(rnd), r * math.sin(a), 1.6 + 1.4 * next(rnd)],
                       hsv(next(rnd), 0.75, 1.0) + [0.0]))

    s.program("gbuffer", "common-mesh.vert", "deferred-gbuffer.frag",
              ["u_model", "u_viewProjection", "u_albedo", "u_specular"])
    s.program("light", "common-fullscreen.vert", "deferred-light.frag",
              ["u_albedo", "u_normal", "u_position", "u_eye"])
    s.mesh("floor", scene[0][1])
    for name, mesh in shapes.items():
        s.mesh(name, mesh)
    for name, internal in (("albedo", "RGBA8"), ("normal", "RGBA16F"), ("position", "RGBA32F")):
        s.texture(name, "TEXTURE_2D", internal, w, h)
    s.renderbuffer("depth", "DEPTH_COMPONENT24", w, h)
    s.framebuffer("gbufferFb", [("COLOR_ATTACHMENT0", "albedo", "TEXTURE_2D"),
                              ("COLOR_ATTACHMENT1", "normal", "TEXTURE_2D"),
                              ("COLOR_ATTACHMENT2", "position", "TEXTURE_2D"),
                              ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("drawBuffers", ["COLOR_ATTACHMENT0", "COLOR_ATTACHMENT1", "COLOR_ATTACHMENT2"])
    s("getParameter", "DRAW_BUFFER2", record="gbufferFb.drawBuffer2")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("createBuffer", as_="lights")
    s("bindBuffer", "UNIFORM_BUFFER", R("lights"))
    s("bufferData", "UNIFORM_BUFFER", F32([x for p, _ in lights for x in p] + [x for _, c in lights for x in c]),
      "STATIC_DRAW")
    s("getUniformBlockIndex", R("light"), "Lights", as_="light.Lights")
    s("getActiveUniformBlockParameter", R("light"), R("light.Lights"), "UNIFORM_BLOCK_DATA_SIZE",
      record="light.Lights.dataSize")
    s("uniformBlockBinding", R("light"), R("light.Lights"), 0)
    s("bindBufferBase", "UNIFORM_BUFFER", 0, R("lights"))
    s("useProgram", R("light"))
    for unit, name in enumerate(("u_albedo", "u_normal", "u_position")):
        s("uniform1i", R(f"light.{name}"), unit)
    s("uniform3fv", R("light.u_eye"), F32(eye))
    s("useProgram", R("gbuffer"))
    s.matrix("gbuffer.u_viewProjection", view_proj)
    s("enable", "CULL_FACE")

    s.begin_frame()
    s("bindFramebuffer", "FRAMEBUFFER", R("gbufferFb"))
    s("viewport", 0, 0, w, h)
    s("enable", "DEPTH_TEST")
    for i in range(3):
        s("clearBufferfv", "COLOR", i, F32([0, 0, 0, 0]))
    s("clearBufferfv", "DEPTH", 0, F32([1]))
    s("useProgram", R("gbuffer"))
    s.draw_objects("gbuffer", [(name, model, {"u_albedo": ("uniform3fv", F32(albedo)),
                                              "u_specular": ("uniform1f", specular)})
                               for name, _, model, albedo, specular in scene])
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("disable", "DEPTH_TEST")
    bind_textures(s, [("TEXTURE_2D", "albedo"), ("TEXTURE_2D", "normal"), ("TEXTURE_2D", "position")])
    fullscreen(s, "light")
    return s


# ---------- 3. blur-pingpong ----------

def blur_pingpong():
    s = Script("blur-pingpong", "A glow: an HDR picture drawn into an RGBA16F texture, blurred by a separable "
               "9-tap Gaussian ping-ponging between two RGBA16F framebuffers (six passes, horizontal then "
               "vertical, 1, 2 and 4 texels apart), then added to the sharp picture and tone mapped.",
               extensions=["EXT_color_buffer_float"])
    w, h = s.width, s.height
    weights = [math.exp(-0.5 * (i / 1.8) ** 2) for i in range(5)]
    total = weights[0] + 2 * sum(weights[1:])
    s.program("scene", "common-fullscreen.vert", "blur-scene.frag")
    s.program("blur", "common-fullscreen.vert", "blur-separable.frag", ["u_source", "u_step", "u_weights"])
    s.program("composite", "common-fullscreen.vert", "blur-composite.frag", ["u_sharp", "u_glow"])
    for name in ("sharp", "pingA", "pingB"):
        s.texture(name, "TEXTURE_2D", "RGBA16F", w, h)
        s.framebuffer(name + "Fb", [("COLOR_ATTACHMENT0", name, "TEXTURE_2D")])
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("useProgram", R("blur"))
    s("uniform1i", R("blur.u_source"), 0)
    s("uniform1fv", R("blur.u_weights"), F32([x / total for x in weights]))
    s("useProgram", R("composite"))
    s("uniform1i", R("composite.u_sharp"), 0)
    s("uniform1i", R("composite.u_glow"), 1)

    s.begin_frame()
    s("viewport", 0, 0, w, h)
    s("bindFramebuffer", "FRAMEBUFFER", R("sharpFb"))
    fullscreen(s, "scene")
    s("useProgram", R("blur"))
    s("activeTexture", "TEXTURE0")
    source = "sharp"
    for k, spread in enumerate((1, 1, 2, 2, 4, 4)):
        target = "pingA" if k % 2 == 0 else "pingB"
        s("bindFramebuffer", "FRAMEBUFFER", R(target + "Fb"))
        s("bindTexture", "TEXTURE_2D", R(source))
        s("uniform2iv", R("blur.u_step"), I32([spread, 0] if k % 2 == 0 else [0, spread]))
        s("drawArrays", "TRIANGLES", 0, 3)
        source = target
    s("bindFramebuffer", "FRAMEBUFFER", None)
    bind_textures(s, [("TEXTURE_2D", "sharp"), ("TEXTURE_2D", source)])
    fullscreen(s, "composite")
    return s


# ---------- 4. msaa-resolve ----------

def msaa_resolve():
    s = Script("msaa-resolve", "Multisampling: six thin spokes and a turned box drawn into a 4-sample RGBA8 "
               "renderbuffer (with a 4-sample DEPTH_COMPONENT24 one), resolved by blitFramebuffer into an RGBA8 "
               "texture, which a full-screen pass then shows with a vignette; a row of resolved pixels across "
               "spoke edges is recorded.")
    w, h = s.width, s.height
    verts = []
    for k in range(6):
        a0 = 2 * math.pi * (k + 0.13) / 6
        a1 = a0 + 0.16
        verts += [0.3 * math.cos(a0 + 0.08), 0.3 * math.sin(a0 + 0.08), 0.0, 0, 0, 1]
        for a in (a0, a1):
            verts += [0.9 * math.cos(a), 0.9 * math.sin(a), 0.0, 0, 0, 1]
    spokes = (verts, list(range(len(verts) // 6)))
    to_light = unit([0.3, 0.8, 0.6])
    s.program("flat", "common-mesh.vert", "common-flat.frag", ["u_model", "u_viewProjection", "u_color", "u_toLight"])
    s.program("show", "common-fullscreen.vert", "common-texture.frag", ["u_image"])
    s.mesh("spokes", spokes)
    s.mesh("box", box(0.27, 0.27, 0.27))
    for name, internal in (("msaaColor", "RGBA8"), ("msaaDepth", "DEPTH_COMPONENT24")):
        s.renderbuffer(name, internal, w, h, samples=4)
    s("getRenderbufferParameter", "RENDERBUFFER", "RENDERBUFFER_SAMPLES", record="msaaDepth.samples")
    s("getInternalformatParameter", "RENDERBUFFER", "RGBA8", "SAMPLES", record="RGBA8.samples")
    s.framebuffer("msaaFb", [("COLOR_ATTACHMENT0", "msaaColor", "renderbuffer"),
                             ("DEPTH_ATTACHMENT", "msaaDepth", "renderbuffer")])
    s("getParameter", "SAMPLES", record="msaaFb.SAMPLES")
    s.texture("resolved", "TEXTURE_2D", "RGBA8", w, h)
    s.framebuffer("resolveFb", [("COLOR_ATTACHMENT0", "resolved", "TEXTURE_2D")])
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("useProgram", R("flat"))
    s("uniform3fv", R("flat.u_toLight"), F32(to_light))
    s("useProgram", R("show"))
    s("uniform1i", R("show.u_image"), 0)
    s("enable", "DEPTH_TEST")

    view_proj = jittered(scale(1.0, 1.0, -0.5), w)
    s.begin_frame()
    s("bindFramebuffer", "FRAMEBUFFER", R("msaaFb"))
    s("viewport", 0, 0, w, h)
    s("clearColor", 0.12, 0.14, 0.2, 1)
    s("clear", OR("COLOR_BUFFER_BIT", "DEPTH_BUFFER_BIT"))
    s("useProgram", R("flat"))
    s.matrix("flat.u_viewProjection", view_proj)
    s.matrix("flat.u_model", translate(0, 0, 0.4))
    s("uniform3fv", R("flat.u_color"), F32([1.0, 0.85, 0.4]))
    s.draw_mesh("spokes")
    s.matrix("flat.u_model", mul_all(translate(0.02, -0.03, 0.0), rotate_z(17), rotate_x(35), rotate_y(40)))
    s("uniform3fv", R("flat.u_color"), F32([0.35, 0.75, 1.0]))
    s.draw_mesh("box")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("msaaFb"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("resolveFb"))
    s("blitFramebuffer", 0, 0, w, h, 0, 0, w, h, "COLOR_BUFFER_BIT", "NEAREST")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("resolveFb"))
    s("readPixels", 98, 70, 16, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 64), record="resolved.row98-113@70")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("disable", "DEPTH_TEST")
    bind_textures(s, [("TEXTURE_2D", "resolved")])
    fullscreen(s, "show")
    s("enable", "DEPTH_TEST")
    return s


# ---------- 5. stencil-outline ----------

def stencil_outline():
    s = Script("stencil-outline", "Outlines with the stencil buffer: a scene drawn into an RGBA8 texture with a "
               "DEPTH24_STENCIL8 renderbuffer at DEPTH_STENCIL_ATTACHMENT; two selected objects write 1 "
               "into the stencil (stencilFunc ALWAYS, stencilOp REPLACE, stencilMask 0xFF), then are drawn again "
               "10 % larger in a flat colour where the stencil is not 1 (NOTEQUAL, depth test off); the result "
               "is blitted to the canvas.")
    w, h = s.width, s.height
    scene = [("floor", plane(9.0), translate(0, 0, 0), [0.55, 0.6, 0.5], False),
             ("ball", sphere(0.6, 24, 16), translate(-1.0, 0.6, 0.3), [0.9, 0.4, 0.3], True),
             ("box", box(0.5, 0.5, 0.5), mul(translate(0.9, 0.5, -0.4), rotate_y(33)), [0.3, 0.5, 0.9], True),
             ("box", None, mul(translate(0.2, 0.5, 1.3), rotate_y(-12)), [0.8, 0.8, 0.3], False),
             ("ball", None, translate(-0.2, 0.6, -1.5), [0.5, 0.8, 0.5], False)]
    to_light = unit([0.4, 1.0, 0.7])
    view_proj = mul(perspective(45, w / h, 0.5, 30.0, w), look_at([1.2, 4.8, 5.2], [0, 0.2, 0], [0, 1, 0]))
    s.program("lit", "common-mesh.vert", "common-flat.frag", ["u_model", "u_viewProjection", "u_color", "u_toLight"])
    s.program("outline", "common-mesh.vert", "common-solid.frag", ["u_model", "u_viewProjection", "u_color"])
    s.mesh("floor", scene[0][1])
    s.mesh("ball", scene[1][1])
    s.mesh("box", scene[2][1])
    s.texture("color", "TEXTURE_2D", "RGBA8", w, h)
    s.renderbuffer("depthStencil", "DEPTH24_STENCIL8", w, h)
    s.framebuffer("sceneFb", [("COLOR_ATTACHMENT0", "color", "TEXTURE_2D"),
                              ("DEPTH_STENCIL_ATTACHMENT", "depthStencil", "renderbuffer")])
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "STENCIL_ATTACHMENT", "FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE",
      record="sceneFb.stencilSize")
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "DEPTH_ATTACHMENT", "FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE",
      record="sceneFb.depthSize")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("useProgram", R("lit"))
    s("uniform3fv", R("lit.u_toLight"), F32(to_light))
    s.matrix("lit.u_viewProjection", view_proj)
    s("useProgram", R("outline"))
    s.matrix("outline.u_viewProjection", view_proj)
    s("uniform4fv", R("outline.u_color"), F32([1.0, 0.6, 0.12, 1.0]))
    s("enable", "CULL_FACE")

    s.begin_frame()
    s("bindFramebuffer", "FRAMEBUFFER", R("sceneFb"))
    s("viewport", 0, 0, w, h)
    s("clearBufferfv", "COLOR", 0, F32([0.2, 0.22, 0.26, 1.0]))
    s("clearBufferfi", "DEPTH_STENCIL", 0, 1.0, 0)
    s("enable", "DEPTH_TEST")
    s("enable", "STENCIL_TEST")
    s("stencilFunc", "ALWAYS", 1, 255)
    s("stencilOp", "KEEP", "KEEP", "REPLACE")
    s("useProgram", R("lit"))
    for name, _, model, color, selected in scene:
        s("stencilMask", 255 if selected else 0)
        s.matrix("lit.u_model", model)
        s("uniform3fv", R("lit.u_color"), F32(color))
        s.draw_mesh(name)
    s("stencilFunc", "NOTEQUAL", 1, 255)
    s("stencilMask", 0)
    s("disable", "DEPTH_TEST")
    s("useProgram", R("outline"))
    for name, _, model, _, selected in scene:
        if selected:
            s.matrix("outline.u_model", mul(model, scale(1.1)))
            s.draw_mesh(name)
    s("disable", "STENCIL_TEST")
    s("stencilMask", 255)
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("sceneFb"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", None)
    s("blitFramebuffer", 0, 0, w, h, 0, 0, w, h, "COLOR_BUFFER_BIT", "NEAREST")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    return s


# ---------- 6. picking ----------

def picking():
    s = Script("picking", "Object ids: one pass writes a lit colour to an RGBA8 target and each object's id to an "
               "R32UI target; readPixels(RGBA_INTEGER, UNSIGNED_INT) from the id target at the top centre of each "
               "object and on the floor is recorded; a full-screen pass reads both targets (sampler2D, "
               "usampler2D) and outlines the object picked.")
    w, h = s.width, s.height
    scene = [("floor", plane(9.0), translate(0, 0, 0), [0.6, 0.6, 0.65], 1)]
    shapes = {"ball": sphere(0.5, 20, 12), "box": box(0.42, 0.42, 0.42)}
    spots = [(-1.4, -0.7), (0.0, -1.1), (1.4, -0.6), (-0.8, 0.9), (0.7, 1.0)]
    for k, (x, z) in enumerate(spots):
        kind = "ball" if k % 2 == 0 else "box"
        y = 0.5 if kind == "ball" else 0.42
        scene.append((kind, None, mul(translate(x, y, z), rotate_y(25 * k)), hsv(k / 5.0, 0.5, 0.9), 10 + k))
    eye = [0.0, 5.2, 4.4]
    view_proj = mul(perspective(48, w / h, 0.5, 30.0, w), look_at(eye, [0, 0.2, 0], [0, 1, 0]))
    to_light = unit([0.3, 1.0, 0.5])
    picked = 12
    s.program("idPass", "common-mesh.vert", "picking-ids.frag",
              ["u_model", "u_viewProjection", "u_color", "u_toLight", "u_id"])
    s.program("highlight", "common-fullscreen.vert", "picking-highlight.frag", ["u_color", "u_ids", "u_picked"])
    s.mesh("floor", scene[0][1])
    for name, mesh in shapes.items():
        s.mesh(name, mesh)
    s.texture("color", "TEXTURE_2D", "RGBA8", w, h)
    s.texture("ids", "TEXTURE_2D", "R32UI", w, h)
    s.renderbuffer("depth", "DEPTH_COMPONENT16", w, h)
    s.framebuffer("pickFb", [("COLOR_ATTACHMENT0", "color", "TEXTURE_2D"), ("COLOR_ATTACHMENT1", "ids", "TEXTURE_2D"),
                             ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("drawBuffers", ["COLOR_ATTACHMENT0", "COLOR_ATTACHMENT1"])
    s("readBuffer", "COLOR_ATTACHMENT1")
    s("getParameter", "IMPLEMENTATION_COLOR_READ_FORMAT", record="ids.readFormat")
    s("getParameter", "IMPLEMENTATION_COLOR_READ_TYPE", record="ids.readType")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("useProgram", R("idPass"))
    s.matrix("idPass.u_viewProjection", view_proj)
    s("uniform3fv", R("idPass.u_toLight"), F32(to_light))
    s("useProgram", R("highlight"))
    s("uniform1i", R("highlight.u_color"), 0)
    s("uniform1i", R("highlight.u_ids"), 1)
    s("uniform1ui", R("highlight.u_picked"), picked)
    s("enable", "CULL_FACE")

    s.begin_frame()
    s("bindFramebuffer", "FRAMEBUFFER", R("pickFb"))
    s("viewport", 0, 0, w, h)
    s("enable", "DEPTH_TEST")
    s("clearBufferfv", "COLOR", 0, F32([0.12, 0.12, 0.14, 1]))
    s("clearBufferuiv", "COLOR", 1, U32([0, 0, 0, 0]))
    s("clearBufferfv", "DEPTH", 0, F32([1]))
    s("useProgram", R("idPass"))
    s.draw_objects("idPass", [(name, model, {"u_color": ("uniform3fv", F32(color)), "u_id": ("uniform1ui", ident)})
                              for name, _, model, color, ident in scene])
    points = [("floor", (3, h - 3))]
    for name, _, model, _, ident in scene[1:]:
        top = 0.5 if name == "ball" else 0.42
        x, y = project(mul(view_proj, model), (0, top, 0), w, h)
        points.append((f"id{ident}", (int(x), int(y))))
    for label, (x, y) in points:
        s("readPixels", x, y, 1, 1, "RGBA_INTEGER", "UNSIGNED_INT", OUT("u32", 4), record=f"pick.{label}@{x},{y}")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("disable", "DEPTH_TEST")
    bind_textures(s, [("TEXTURE_2D", "color"), ("TEXTURE_2D", "ids")])
    fullscreen(s, "highlight")
    return s


# ---------- 7. tf-particles ----------

def tf_particles():
    n, steps, dt = 512, 8, 0.02
    s = Script("tf-particles", f"Particles on the GPU: {n} particles (position, velocity) stepped {steps} times a "
               "frame by transform feedback (transformFeedbackVaryings INTERLEAVED_ATTRIBS, "
               "beginTransformFeedback(POINTS), RASTERIZER_DISCARD) ping-ponging between two buffers, then drawn "
               "as 9-pixel soft points with additive blending; the first 16 particles after the frame "
               "(getBufferSubData) are recorded.")
    rnd = lcg(2024)
    seeds = []
    for _ in range(n):
        a, r = 2 * math.pi * next(rnd), 0.35 + 0.6 * next(rnd)
        speed = 0.4 + 0.5 * next(rnd)
        seeds += [r * math.cos(a), r * math.sin(a), -speed * math.sin(a) * r, speed * math.cos(a) * r]
    s.program("update", "tf-particles-update.vert", "common-empty.frag", ["u_dt"],
              varyings=["v_position", "v_velocity"])
    s("getProgramParameter", R("update"), "TRANSFORM_FEEDBACK_VARYINGS", record="update.varyings")
    s("getTransformFeedbackVarying", R("update"), 1, record="update.varying1")
    s.program("draw", "tf-particles-draw.vert", "tf-particles-draw.frag")
    for name, data in (("A", F32(seeds)), ("B", n * 16)):
        s("createBuffer", as_=f"particles{name}")
        s("bindBuffer", "ARRAY_BUFFER", R(f"particles{name}"))
        s("bufferData", "ARRAY_BUFFER", data, "DYNAMIC_COPY")
        s("createVertexArray", as_=f"vao{name}")
        s("bindVertexArray", R(f"vao{name}"))
        for loc, offset in ((0, 0), (1, 8)):
            s("enableVertexAttribArray", loc)
            s("vertexAttribPointer", loc, 2, "FLOAT", False, 16, offset)
    s("bindVertexArray", None)
    s("bindBuffer", "ARRAY_BUFFER", None)
    s("createTransformFeedback", as_="tf")
    s("useProgram", R("update"))
    s("uniform1f", R("update.u_dt"), dt)
    s("blendFunc", "ONE", "ONE")

    s.begin_frame()
    s("useProgram", R("update"))
    s("enable", "RASTERIZER_DISCARD")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf"))
    for k in range(steps):
        src, dst = ("A", "B") if k % 2 == 0 else ("B", "A")
        s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 0, R(f"particles{dst}"))
        s("bindVertexArray", R(f"vao{src}"))
        s("beginTransformFeedback", "POINTS")
        s("drawArrays", "POINTS", 0, n)
        s("endTransformFeedback")
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 0, None)
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)
    s("disable", "RASTERIZER_DISCARD")
    s("viewport", 0, 0, s.width, s.height)
    s("clearColor", 0.02, 0.02, 0.05, 1)
    s("clear", "COLOR_BUFFER_BIT")
    s("useProgram", R("draw"))
    s("bindVertexArray", R("vaoA"))
    s("enable", "BLEND")
    s("drawArrays", "POINTS", 0, n)
    s("disable", "BLEND")
    s("bindVertexArray", None)
    s("bindBuffer", "COPY_READ_BUFFER", R("particlesA"))
    s("getBufferSubData", "COPY_READ_BUFFER", 0, OUT("f32", 64), record="particlesA.first16")
    s("bindBuffer", "COPY_READ_BUFFER", None)
    return s


# ---------- 8. cubemap-render ----------

CUBE_FACES = [("POSITIVE_X", [1, 0, 0], [0, -1, 0]), ("NEGATIVE_X", [-1, 0, 0], [0, -1, 0]),
              ("POSITIVE_Y", [0, 1, 0], [0, 0, 1]), ("NEGATIVE_Y", [0, -1, 0], [0, 0, -1]),
              ("POSITIVE_Z", [0, 0, 1], [0, -1, 0]), ("NEGATIVE_Z", [0, 0, -1], [0, -1, 0])]


def cubemap_render():
    size = 256
    s = Script("cubemap-render", f"Rendering to a cube map: each face of a {size}x{size} RGBA8 cube map "
               "(framebufferTexture2D with TEXTURE_CUBE_MAP_POSITIVE_X ... NEGATIVE_Z) gets a sky and six "
               "coloured boxes seen from the centre with a 90-degree camera; then the canvas shows the cube map "
               "as the background and on a mirror sphere and box (samplerCube, reflect).")
    w, h = s.width, s.height
    boxes = [([5, 0, 0], [0.9, 0.25, 0.2]), ([-5, 0, 0], [0.2, 0.8, 0.8]), ([0, 5, 0], [0.9, 0.9, 0.9]),
             ([0, -5, 0], [0.3, 0.3, 0.3]), ([0, 0, 5], [0.25, 0.35, 0.95]), ([0, 0, -5], [0.95, 0.85, 0.2])]
    to_light = unit([0.5, 0.6, -0.6])
    eye = [2.6, 1.2, 4.4]
    view_proj = mul(perspective(45, w / h, 0.3, 30.0, w), look_at(eye, [0, 0, 0], [0, 1, 0]))
    s.program("envSky", "common-fullscreen.vert", "cubemap-env-sky.frag", ["u_inverseViewProjection"])
    s.program("flat", "common-mesh.vert", "common-flat.frag", ["u_model", "u_viewProjection", "u_color", "u_toLight"])
    s.program("sky", "common-fullscreen.vert", "cubemap-sky.frag",
              ["u_environment", "u_inverseViewProjection", "u_eye"])
    s.program("mirror", "common-mesh.vert", "cubemap-reflect.frag",
              ["u_model", "u_viewProjection", "u_environment", "u_eye", "u_color"])
    s.mesh("box", box(0.7, 0.7, 0.7))
    s.mesh("ball", sphere(0.9, 32, 20))
    s.texture("environment", "TEXTURE_CUBE_MAP", "RGBA8", size, size, filt="LINEAR")
    s.renderbuffer("faceDepth", "DEPTH_COMPONENT16", size, size)
    s.framebuffer("faceFb", [("COLOR_ATTACHMENT0", "environment", "TEXTURE_CUBE_MAP_POSITIVE_X"),
                             ("DEPTH_ATTACHMENT", "faceDepth", "renderbuffer")])
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT0",
      "FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE", record="faceFb.face")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("useProgram", R("flat"))
    s("uniform3fv", R("flat.u_toLight"), F32(to_light))
    s("useProgram", R("sky"))
    s("uniform1i", R("sky.u_environment"), 0)
    s.matrix("sky.u_inverseViewProjection", inverse(view_proj))
    s("uniform3fv", R("sky.u_eye"), F32(eye))
    s("useProgram", R("mirror"))
    s("uniform1i", R("mirror.u_environment"), 0)
    s.matrix("mirror.u_viewProjection", view_proj)
    s("uniform3fv", R("mirror.u_eye"), F32(eye))
    s("enable", "CULL_FACE")

    s.begin_frame()
    s("bindTexture", "TEXTURE_CUBE_MAP", None)
    s("bindFramebuffer", "FRAMEBUFFER", R("faceFb"))
    s("viewport", 0, 0, size, size)
    for face, forward, up in CUBE_FACES:
        face_vp = mul(perspective(90, 1.0, 0.2, 20.0, size), look_at([0, 0, 0], forward, up))
        s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", f"TEXTURE_CUBE_MAP_{face}", R("environment"), 0)
        s("clear", "DEPTH_BUFFER_BIT")
        s("disable", "DEPTH_TEST")
        s("useProgram", R("envSky"))
        s.matrix("envSky.u_inverseViewProjection", inverse(face_vp))
        s("drawArrays", "TRIANGLES", 0, 3)
        s("enable", "DEPTH_TEST")
        s("useProgram", R("flat"))
        s.matrix("flat.u_viewProjection", face_vp)
        for position, color in boxes:
            s.matrix("flat.u_model", mul(translate(*position), rotate_y(30)))
            s("uniform3fv", R("flat.u_color"), F32(color))
            s.draw_mesh("box")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("viewport", 0, 0, w, h)
    s("activeTexture", "TEXTURE0")
    s("bindTexture", "TEXTURE_CUBE_MAP", R("environment"))
    s("clear", "DEPTH_BUFFER_BIT")
    s("disable", "DEPTH_TEST")
    fullscreen(s, "sky")
    s("enable", "DEPTH_TEST")
    s("useProgram", R("mirror"))
    for mesh, model, color in (("ball", translate(-0.5, 0.1, 0.0), [1.0, 1.0, 1.0]),
                               ("box", mul_all(translate(1.2, -0.3, 0.9), rotate_y(35), rotate_x(20), scale(0.6)),
                                [1.0, 0.85, 0.6])):
        s.matrix("mirror.u_model", model)
        s("uniform3fv", R("mirror.u_color"), F32(color))
        s.draw_mesh(mesh)
    s("bindVertexArray", None)
    return s


SCRIPTS = [shadow_map, deferred, blur_pingpong, msaa_resolve, stencil_outline, picking, tf_particles, cubemap_render]


def main():
    global JITTER
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", help="write the multi-pass scripts here (default: beside this file)")
    ap.add_argument("--jitter", type=float, default=0.0, metavar="PX")
    args = ap.parse_args()
    JITTER = args.jitter
    folder = os.path.abspath(args.out or HERE)
    os.makedirs(folder, exist_ok=True)
    for make in SCRIPTS:
        s = make()
        with open(os.path.join(folder, s.name + ".json"), "w", encoding="utf-8") as fh:
            fh.write(s.json(folder))
    if not args.out:
        import probes
        probes.write_all(os.path.join(HERE, "probes"))


if __name__ == "__main__":
    main()
