"""How extract-fresh.py assembles each library's shaders (see its docstring). Each function
yields (path in the package, stage, kind, text); kind is `shader` or `library`."""

import os
import re

GLSL_EXTS = (".glsl", ".vert", ".frag", ".vs", ".fs", ".vsh", ".fsh")
JS_EXTS = (".js", ".mjs", ".cjs", ".ts")
OUTPUT = re.compile(r"gl_FragColor|gl_FragData|gl_Position|^\s*(layout\s*\([^)]*\)\s*)?out\s", re.M)


def read(path):
    try:
        return open(path, encoding="utf-8").read()
    except (OSError, UnicodeDecodeError):
        return None


def walk(root, exts):
    for dirpath, dirnames, files in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d != "node_modules")
        for f in sorted(files):
            if f.endswith(exts) and not f.endswith(".d.ts"):
                yield os.path.join(dirpath, f)


def stage_of(text, path=""):
    if "gl_Position" in text:
        return "vertex"
    low = path.lower()
    if re.search(r"(vertex|\.vert|vs\.glsl|_vs\b|\.vs$)", low) and "gl_Frag" not in text:
        return "vertex"
    return "fragment"


def whole(text):
    return re.search(r"\bvoid\s+main\s*\(", text) is not None and OUTPUT.search(text) is not None


# ----- JavaScript string literals -----

def unescape(s):
    table = {"n": "\n", "t": "\t", "r": "", "\\": "\\", "'": "'", '"': '"', "`": "`", "0": "\0"}
    out, i = [], 0
    while i < len(s):
        c = s[i]
        if c == "\\" and i + 1 < len(s):
            n = s[i + 1]
            if n == "\n":
                i += 2
                continue
            out.append(table.get(n, n))
            i += 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


def js_literals(text):
    """(start, end, raw) of each string literal of a JavaScript text, comments skipped (regular
    expression literals are not told apart: a quote inside one may start a false string, which
    the shader test then drops)."""
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif c in "'\"`":
            j = i + 1
            while j < n and text[j] != c:
                if text[j] == "\\":
                    j += 1
                elif text[j] == "\n" and c != "`":
                    break
                j += 1
            yield i, j + 1, text[i : j + 1]
            i = j + 1
        else:
            i += 1


def js_strings(text):
    """String literals of a JavaScript text, `+`-joined pieces as one, unescaped."""
    pieces, last_end, current = [], None, None
    for start, end, raw in js_literals(text):
        if len(raw) < 2 or raw[-1] != raw[0] or raw[0] == "`" and "${" in raw:
            if current is not None:
                pieces.append(current)
            current, last_end = None, None
            continue
        body = unescape(raw[1:-1])
        between = text[last_end:start] if last_end is not None else None
        if current is not None and between is not None and between.strip() == "+":
            current += body
        else:
            if current is not None:
                pieces.append(current)
            current = body
        last_end = end
    if current is not None:
        pieces.append(current)
    return pieces


def complete(text, pixi=False):
    """The version and precision lines a runtime adds, where the text has none."""
    t = text.lstrip()
    if t.startswith("#version"):
        return t
    es3 = re.search(r"^\s*(in|out|flat in|flat out|layout)\s", t, re.M) is not None
    frag = stage_of(t) == "fragment"
    if es3 or pixi:
        head = "#version 300 es\n"
        if "precision " not in t:
            head += "precision highp float;\nprecision highp int;\n"
        return head + t
    if frag and not re.search(r"precision\s+\w+\s+float", t):
        return "precision mediump float;\n" + t
    return t


def generic_shaders(root, pixi=False):
    for path in walk(root, JS_EXTS + GLSL_EXTS):
        rel = os.path.relpath(path, root)
        # A vendored three.js is three.js's code, which the old corpus holds.
        if re.search(r"(^|/)three[./_-]|/three/", rel):
            continue
        text = read(path)
        if text is None or "main" not in text:
            continue
        if path.endswith(GLSL_EXTS):
            candidates = [text]
        else:
            candidates = js_strings(text)
        for i, c in enumerate(candidates):
            if len(c) > 200_000 or not whole(c):
                continue
            full = complete(c, pixi)
            # Minified shaders are re-flowed one statement a line, so that findings have
            # lines to point at.
            if max(len(line) for line in full.split("\n")) > 300:
                full = reflow(full)
            yield f"{rel}#{i}", stage_of(full, rel), "shader", full


# ----- lygia -----

TYPES = {
    "float", "vec2", "vec3", "vec4", "int", "ivec2", "ivec3", "ivec4", "uint", "uvec2", "uvec3",
    "uvec4", "bool", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "sampler2D",
    "samplerCube", "sampler3D", "sampler2DArray", "void",
}
KEYWORDS = {"if", "for", "while", "return", "else", "switch", "do"}


def expand_includes(path, done):
    """`path`'s text with its `#include "…"` lines replaced by the files (each once)."""
    real = os.path.realpath(path)
    if real in done:
        return ""
    done.add(real)
    text = read(path) or ""
    out = []
    for line in text.split("\n"):
        m = re.match(r'\s*#include\s+"([^"]+)"', line)
        if m:
            inc = os.path.join(os.path.dirname(path), m.group(1))
            out.append(expand_includes(inc, done) if os.path.exists(inc) else line)
        else:
            out.append(line)
    return "\n".join(out)


def lygia_arg(ty, structs, decls):
    """The argument the harness passes for a parameter of type `ty` (declaring its source)."""
    if ty == "SAMPLER_TYPE":
        ty = "sampler2D"
    if ty in ("float", "vec2", "vec3", "vec4"):
        decls.add(f"in highp {ty} lh_{ty};")
        return f"lh_{ty}"
    if ty in ("int", "ivec2", "ivec3", "ivec4", "uint", "uvec2", "uvec3", "uvec4"):
        decls.add(f"flat in highp {ty} lh_{ty};")
        return f"lh_{ty}"
    if ty == "bool":
        decls.add("in highp float lh_float;")
        return "(lh_float > 0.5)"
    if ty.startswith("bvec"):
        n = ty[-1]
        decls.add(f"in highp vec{n} lh_vec{n};")
        return f"greaterThan(lh_vec{n}, vec{n}(0.5))"
    if ty in structs:
        return struct_arg(ty, structs[ty], decls)
    if ty.startswith("mat") or ty.startswith("sampler"):
        decls.add(f"uniform {ty} lh_{ty};")
        return f"lh_{ty}"
    return None


FLOAT_TYPES = ("float", "vec2", "vec3", "vec4")


def struct_fields(body):
    """The `float`/`vecN` fields a struct declares outside any `#if` block."""
    fields, depth = [], 0
    for line in body.split("\n"):
        t = line.strip()
        if re.match(r"#\s*if", t):
            depth += 1
        elif re.match(r"#\s*endif", t):
            depth -= 1
        elif depth == 0 and not t.startswith("#"):
            for decl in t.split(";"):
                words = [w for w in decl.split("//")[0].split() if w not in ("highp", "mediump", "lowp")]
                if len(words) == 2 and words[0] in FLOAT_TYPES and re.fullmatch(r"\w+", words[1]):
                    fields.append((words[0], words[1]))
    return fields


def struct_arg(ty, body, decls):
    """A struct argument as a shader has it per pixel: the uniform's value with each `float` and
    `vecN` field read from an input of its own (a material's position and normal, a shading
    context's vectors vary across the surface)."""
    decls.add(f"uniform {ty} lh_{ty};")
    sets = []
    for fty, name in struct_fields(body):
        decls.add(f"in highp {fty} lh_{ty}_{name};")
        sets.append(f"s.{name} = lh_{ty}_{name};")
    if not sets:
        return f"lh_{ty}"
    decls.add(f"{ty} lh_make_{ty}() {{ {ty} s = lh_{ty}; {' '.join(sets)} return s; }}")
    return f"lh_make_{ty}()"


def accumulate(ty, call):
    if ty == "float":
        return f"lh_out.x += {call};"
    if ty in ("vec2", "vec3"):
        return f"lh_out.{'xyz'[: int(ty[-1])]} += {call};"
    if ty == "vec4":
        return f"lh_out += {call};"
    if ty in ("int", "uint"):
        return f"lh_out.x += float({call});"
    if ty[:-1] in ("ivec", "uvec"):
        return f"lh_out.x += float(({call}).x);"
    if ty == "bool":
        return f"lh_out.x += ({call}) ? 1.0 : 0.0;"
    if ty.startswith("mat"):
        return f"lh_out.x += ({call})[0][0];"
    return f"{call};"


def lygia_shaders(root):
    for path in walk(root, (".glsl",)):
        rel = os.path.relpath(path, root)
        if rel.startswith(("dist", "node_modules")):
            continue
        own = read(path) or ""
        body = expand_includes(path, set())
        structs = dict(re.findall(r"\bstruct\s+(\w+)\s*\{([^}]*)\}", body))
        decls, calls = set(), []
        fn = re.compile(
            r"^[ \t]*(?:(?:highp|mediump|lowp)\s+)?(\w+)\s+(\w+)\s*\(([^()]*)\)\s*\{", re.M
        )
        for m in fn.finditer(own):
            ret, name, params = m.group(1), m.group(2), m.group(3).strip()
            if name in KEYWORDS or ret in KEYWORDS or (ret not in TYPES and ret not in structs):
                continue
            args, pre, ok = [], [], True
            for i, p in enumerate([] if params in ("", "void") else params.split(",")):
                words = [w for w in p.replace("\n", " ").split() if w not in ("const", "highp", "mediump", "lowp")]
                mode = "in"
                if words and words[0] in ("in", "out", "inout"):
                    mode = words.pop(0)
                if len(words) != 2 or "[" in p:
                    ok = False
                    break
                ty = words[0]
                a = lygia_arg(ty, structs, decls)
                if a is None:
                    ok = False
                    break
                if mode != "in":
                    pre.append(f"{ty} lh_a{len(calls)}_{i} = {a};")
                    a = f"lh_a{len(calls)}_{i}"
                args.append(a)
            if ok:
                calls.append("\n    ".join(pre + [accumulate(ret, f"{name}({', '.join(args)})")]))
        if not calls:
            continue
        text = (
            "#version 300 es\nprecision highp float;\nprecision highp int;\n"
            "precision highp sampler3D;\nprecision highp sampler2DArray;\n"
            "#define PLATFORM_WEBGL\n#define HIGHP highp\n"
            + body
            + "\n\n// lint harness: every function of "
            + rel
            + "\n"
            + "\n".join(sorted(decls, key=lambda d: ("{" in d, d)))
            + "\nout vec4 lh_out;\nvoid main() {\n    lh_out = vec4(0.0);\n    "
            + "\n    ".join(calls)
            + "\n}\n"
        )
        yield rel, "fragment", "library", text


# ----- Babylon.js -----

STORE = re.compile(r'const name = "(\w+)";\s*const shader = `((?:[^`\\]|\\.)*)`', re.S)


def babylon_store(folder):
    out = {}
    for path in walk(folder, (".js",)):
        if "wgsl" in path.lower():
            continue
        m = STORE.search(read(path) or "")
        if m:
            out[m.group(1)] = (os.path.basename(path), unescape_template(m.group(2)))
    return out


def unescape_template(s):
    return s.replace("\\`", "`").replace("\\\\", "\\")


INCLUDE = re.compile(r"#include\s*<(\w+)>(\(([^)]*)\))?(\[(\w+)\.\.(\w+)\])?")


def babylon_expand(text, includes, depth=0):
    if depth > 12:
        return text

    def one(m):
        name = m.group(1)
        if name.startswith("__decl__"):
            name = name[len("__decl__"):] + "Declaration"
        inc = includes.get(name)
        if inc is None:
            return m.group(0)
        body = inc[1]
        if m.group(3):
            parts = [p.strip() for p in m.group(3).split(",")]
            for a, b in zip(parts[0::2], parts[1::2]):
                body = body.replace(a, b)
        if m.group(4):
            lo = int(m.group(5)) if m.group(5).isdigit() else 0
            hi = int(m.group(6)) if m.group(6).isdigit() else 4
            body = "\n".join(body.replace("{X}", str(i)) for i in range(lo, hi))
        return babylon_expand(body, includes, depth + 1)

    return INCLUDE.sub(one, text)


def reflow(text):
    """One statement a line for a minified text (preprocessor lines kept as they are)."""
    out = []
    for line in text.split("\n"):
        if line.lstrip().startswith("#") or len(line) < 100:
            out.append(line)
            continue
        depth, cur = 0, []
        for ch in line:
            cur.append(ch)
            if ch == "(":
                depth += 1
            elif ch == ")":
                depth -= 1
            elif depth == 0 and ch in ";{}":
                out.append("".join(cur).strip())
                cur = []
        if "".join(cur).strip():
            out.append("".join(cur).strip())
    return "\n".join(out) + "\n"


def babylon_shaders(root, npm):
    core = None
    for entry in os.listdir(npm):
        folder = os.path.join(npm, entry, "package", "Shaders", "ShadersInclude")
        if entry.startswith("babylonjs-core-") and os.path.isdir(folder):
            core = folder
    includes = babylon_store(core) if core else {}
    includes.update(babylon_store(root))
    for path in walk(root, (".js",)):
        rel = os.path.relpath(path, root)
        if "wgsl" in rel.lower() or "ShadersInclude" in rel:
            continue
        m = STORE.search(read(path) or "")
        if not m or not m.group(1).endswith(("PixelShader", "VertexShader")):
            continue
        stage = "vertex" if m.group(1).endswith("VertexShader") else "fragment"
        text = babylon_expand(unescape_template(m.group(2)), includes)
        yield rel, stage, "shader", reflow(babylon_webgl2(text, stage))


def babylon_webgl2(text, stage):
    """What Babylon's WebGL2 shader processor makes of a shader: GLSL ES 3.00 names, the
    defines the engine always sets, no extensions."""
    text = re.sub(r"^\s*#extension[^\n]*$", "", text, flags=re.M)
    text = re.sub(r"\bvarying\b", "in" if stage == "fragment" else "out", text)
    text = re.sub(r"\battribute\b", "in", text)
    for old, new in (
        ("texture2DLodEXT", "textureLod"),
        ("textureCubeLodEXT", "textureLod"),
        ("texture2DGradEXT", "textureGrad"),
        ("textureCubeGradEXT", "textureGrad"),
        ("texture2D", "texture"),
        ("textureCube", "texture"),
        ("gl_FragDepthEXT", "gl_FragDepth"),
        ("gl_FragColor", "glFragColor"),
    ):
        text = re.sub(rf"\b{old}\b", new, text)
    # The counts the engine sets with a mesh's skeleton and morph targets: no bones unless the
    # includer says (a default the lints' variants raise to reach the skinning), an array of
    # bones wherever there are, and targets wherever MORPHTARGETS is set.
    head = "#version 300 es\n#define WEBGL2\n"
    head += "#ifndef NUM_BONE_INFLUENCERS\n#define NUM_BONE_INFLUENCERS 0\n#endif\n"
    head += "#if NUM_BONE_INFLUENCERS > 0\n#define BonesPerMesh 64\n#else\n#define BonesPerMesh 0\n#endif\n"
    head += "#ifdef MORPHTARGETS\n#define NUM_MORPH_INFLUENCERS 4\n#else\n#define NUM_MORPH_INFLUENCERS 0\n#endif\n"
    head += "precision highp float;\n"
    if stage == "fragment" and "glFragColor" in text:
        head += "out vec4 glFragColor;\n"
    return head + text


# ----- Cesium -----

GL_TYPES = {
    "FLOAT": "float", "FLOAT_VEC2": "vec2", "FLOAT_VEC3": "vec3", "FLOAT_VEC4": "vec4",
    "INT": "int", "INT_VEC2": "ivec2", "INT_VEC3": "ivec3", "INT_VEC4": "ivec4", "BOOL": "bool",
    "FLOAT_MAT2": "mat2", "FLOAT_MAT3": "mat3", "FLOAT_MAT4": "mat4", "SAMPLER_2D": "sampler2D",
    "SAMPLER_CUBE": "samplerCube",
}


# Components of the batch-table attributes Cesium defines other than with a
# `new GeometryInstanceAttribute({…})` (their own classes).
BATCH_TABLE_SIZES = {"color": 4, "pickColor": 4, "show": 1, "distanceDisplayCondition": 2, "depthFailColor": 4, "offset": 3, "width": 1}


def batch_table_sizes(src):
    """The number of components of each per-instance attribute the package defines."""
    sizes = dict(BATCH_TABLE_SIZES)
    for path in walk(src, (".js",)):
        text = read(path) or ""
        for m in re.finditer(r"(\w+)\s*[:=]\s*new GeometryInstanceAttribute\(\{(.*?)\}\)", text, re.S):
            c = re.search(r"componentsPerAttribute:\s*(\d)", m.group(2))
            if c:
                sizes.setdefault(m.group(1), int(c.group(1)))
    return sizes


def batch_table(names, sizes):
    """The batch-table functions `BatchTable.js` generates for the attributes `names` (a float
    texture one texel high, as WebGL2 has), so that a shader calling them compiles."""
    out = [
        "uniform highp sampler2D batchTexture;",
        "uniform vec4 batchTextureStep;",
        "vec2 computeSt(float batchId) {",
        "    float stepX = batchTextureStep.x;",
        "    float centerX = batchTextureStep.y;",
        f"    float numberOfAttributes = float({len(names)});",
        "    return vec2(centerX + (batchId * numberOfAttributes * stepX), 0.5);",
        "}",
    ]
    for i, name in enumerate(names):
        n = sizes.get(name, 4)
        ty = "float" if n == 1 else f"vec{n}"
        swizzle = ".xyzw"[: n + 1]
        out += [
            f"{ty} czm_batchTable_{name}(float batchId) {{",
            "    vec2 st = computeSt(batchId);",
            f"    st.x += batchTextureStep.x * float({i});",
            "    vec4 textureValue = texture(batchTexture, st);",
            f"    {ty} value = textureValue{swizzle};",
            "    return value;",
            "}",
        ]
    return "\n".join(out)


def cesium_shaders(root):
    src = os.path.join(root, "Source")
    builtin = os.path.join(src, "Shaders", "Builtin")
    lib = {}
    for kind in ("Structs", "Constants", "Functions"):
        for path in walk(os.path.join(builtin, kind), (".glsl",)):
            name = "czm_" + os.path.basename(path)[: -len(".glsl")]
            lib[name] = (kind, read(path) or "")
    uniforms = {}
    auto = read(os.path.join(src, "Renderer", "AutomaticUniforms.js")) or ""
    for m in re.finditer(r"(czm_\w+): new AutomaticUniform\(\{\s*size:\s*(\d+),\s*datatype:\s*WebGLConstants\.(\w+)", auto):
        if m.group(3) in GL_TYPES:
            size = int(m.group(2))
            uniforms[m.group(1)] = GL_TYPES[m.group(3)] + ("" if size == 1 else f"[{size}]")

    sizes = batch_table_sizes(src)

    def needed(text, order, seen):
        code = re.sub(r"/\*.*?\*/|//[^\n]*", "", text, flags=re.S)
        for name in re.findall(r"\bczm_\w+", code):
            if name in seen or name not in lib:
                continue
            seen.add(name)
            needed(lib[name][1], order, seen)
            order.append(name)

    for path in walk(os.path.join(src, "Shaders"), (".glsl",)):
        rel = os.path.relpath(path, root)
        if "Builtin" in rel:
            continue
        text = read(path) or ""
        if not re.search(r"\bvoid\s+main\s*\(", text):
            continue
        order, seen = [], set()
        needed(text, order, seen)
        used = set(re.findall(r"\bczm_\w+", text + "".join(lib[n][1] for n in order)))
        stage = stage_of(text, rel)
        head = ["#version 300 es", "precision highp float;", "precision highp int;"]
        head += [f"uniform {t.split('[')[0]} {n}{'[' + t.split('[')[1] if '[' in t else ''};" for n, t in sorted(uniforms.items()) if n in used]
        if stage == "fragment" and "out_FragColor" in text and not re.search(r"out\s+vec4\s+out_FragColor", text):
            head.append("layout(location = 0) out vec4 out_FragColor;")
        parts = [lib[n][1] for n in order if lib[n][0] == "Structs"]
        parts += [lib[n][1] for n in order if lib[n][0] == "Constants"]
        parts += [lib[n][1] for n in order if lib[n][0] == "Functions"]
        # The per-instance attributes a primitive's batch table holds (`czm_batchTable_color`).
        code = re.sub(r"/\*.*?\*/|//[^\n]*", "", text, flags=re.S)
        batched = sorted(set(re.findall(r"\bczm_batchTable_(\w+)\s*\(", code)))
        if batched:
            parts.append(batch_table(batched, sizes))
        yield rel, stage, "shader", "\n".join(head) + "\n" + "\n".join(parts) + "\n" + text


# ----- MapLibre -----

PRAGMA = re.compile(r"#pragma maplibre: (\w+) (\w+) (\w+) (\w+)")


def maplibre_shaders(root):
    d = os.path.join(root, "src", "shaders", "glsl")
    prelude = {s: read(os.path.join(d, f"_prelude.{s}.glsl")) or "" for s in ("fragment", "vertex")}
    proj = {s: read(os.path.join(d, f"_projection_mercator.{s}.glsl")) or "" for s in ("fragment", "vertex")}
    for f in sorted(os.listdir(d)):
        if f.startswith("_") or not f.endswith(".glsl"):
            continue
        name, stage = f[: -len(".glsl")].rsplit(".", 1)
        text = read(os.path.join(d, f)) or ""
        frag_text = read(os.path.join(d, f"{name}.fragment.glsl")) or ""
        in_frag = {m.group(4) for m in PRAGMA.finditer(frag_text)}

        def expand(m):
            op, prec, ty, var = m.groups()
            if stage == "fragment":
                return f"in {prec} {ty} {var};" if op == "define" else ""
            attr = "vec2" if ty == "float" else "vec4"
            unpack = "color" if "color" in var else attr
            if op == "define":
                decl = f"uniform lowp float u_{var}_t;\nin {prec} {attr} a_{var};"
                return decl + (f"\nout {prec} {ty} {var};" if var in in_frag else "")
            value = f"a_{var}" if unpack == "vec4" else f"unpack_mix_{unpack}(a_{var}, u_{var}_t)"
            return f"{var} = {value};" if var in in_frag else f"{prec} {ty} {var} = {value};"

        body = PRAGMA.sub(expand, text)
        full = "#version 300 es\n" + prelude[stage] + "\n" + proj[stage] + "\n" + body
        yield f"src/shaders/glsl/{f}", stage, "shader", full
