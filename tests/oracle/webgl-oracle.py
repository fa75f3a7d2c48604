#!/usr/bin/env python3
"""Ask headless Chromium what a WebGL 1 or WebGL 2 context says about shaders.

usage: webgl-oracle.py [--context webgl1|webgl2] [--extensions NAME,NAME] [--limits]
                       [-o OUT.json] DIR_OR_FILES...

Compiles every *.vert / *.frag given (or found in a given folder) and links each NAME.vert with
NAME.frag from the same folder, in a context of the given version (default webgl2) after
enabling the named WebGL extensions with getExtension (e.g. OES_standard_derivatives,
EXT_shader_texture_lod, EXT_frag_depth, WEBGL_draw_buffers). Writes JSON in the shape of
../shared/tools/webgl2-oracle.py's (`compile`, `link` with active uniforms and attributes),
plus `context`, `extensions` (those getExtension returned), and with --limits `limits`: the
getParameter values a shader limit depends on, and the supported extensions.

Needs Debian's chromium; uses only the standard library.
"""
import html
import json
import os
import subprocess
import sys
import tempfile

PAGE = r"""<!doctype html><canvas id=c width=4 height=4></canvas><pre id=out></pre><script>
const args = %s;
const gl = document.getElementById('c').getContext(args.context);
const res = {context: args.context, version: gl && gl.getParameter(gl.VERSION),
             shading_language: gl && gl.getParameter(gl.SHADING_LANGUAGE_VERSION),
             extensions: [], compile: {}, link: {}};
for (const e of args.extensions) if (gl.getExtension(e)) res.extensions.push(e);
const typeName = {};
for (const k in gl) if (/^[A-Z0-9_]+(x[234])?$/.test(k) && typeof gl[k] === 'number' &&
    /^(FLOAT|INT|UNSIGNED_INT|BOOL|SAMPLER)/.test(k) && !(gl[k] in typeName)) typeName[gl[k]] = k;
if (args.limits) {
  const names = ['MAX_VERTEX_ATTRIBS', 'MAX_VERTEX_UNIFORM_VECTORS', 'MAX_VARYING_VECTORS',
    'MAX_FRAGMENT_UNIFORM_VECTORS', 'MAX_VERTEX_TEXTURE_IMAGE_UNITS', 'MAX_TEXTURE_IMAGE_UNITS',
    'MAX_COMBINED_TEXTURE_IMAGE_UNITS', 'MAX_VERTEX_OUTPUT_COMPONENTS',
    'MAX_FRAGMENT_INPUT_COMPONENTS', 'MAX_VERTEX_UNIFORM_COMPONENTS',
    'MAX_FRAGMENT_UNIFORM_COMPONENTS', 'MAX_VERTEX_UNIFORM_BLOCKS',
    'MAX_FRAGMENT_UNIFORM_BLOCKS', 'MAX_COMBINED_UNIFORM_BLOCKS', 'MAX_UNIFORM_BLOCK_SIZE',
    'MAX_DRAW_BUFFERS', 'MIN_PROGRAM_TEXEL_OFFSET', 'MAX_PROGRAM_TEXEL_OFFSET'];
  res.limits = {};
  for (const n of names) if (gl[n] !== undefined) res.limits[n] = gl.getParameter(gl[n]);
  const db = gl.getExtension('WEBGL_draw_buffers');
  if (db) res.limits.MAX_DRAW_BUFFERS_WEBGL = gl.getParameter(db.MAX_DRAW_BUFFERS_WEBGL);
  res.supported_extensions = gl.getSupportedExtensions();
}
const sh = {};
for (const f in args.sources) {
  const s = gl.createShader(f.endsWith('.vert') ? gl.VERTEX_SHADER : gl.FRAGMENT_SHADER);
  gl.shaderSource(s, args.sources[f]); gl.compileShader(s); sh[f] = s;
  res.compile[f] = {ok: gl.getShaderParameter(s, gl.COMPILE_STATUS), log: gl.getShaderInfoLog(s)};
}
for (const f in args.sources) {
  if (!f.endsWith('.vert')) continue;
  const frag = f.replace(/\.vert$/, '.frag'); if (!(frag in sh)) continue;
  const p = gl.createProgram(); gl.attachShader(p, sh[f]); gl.attachShader(p, sh[frag]);
  gl.linkProgram(p);
  const r = {ok: gl.getProgramParameter(p, gl.LINK_STATUS), log: gl.getProgramInfoLog(p)};
  if (r.ok) {
    r.uniforms = []; r.attributes = [];
    for (let i = 0; i < gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS); i++) {
      const u = gl.getActiveUniform(p, i);
      r.uniforms.push({name: u.name, type: typeName[u.type] || u.type, size: u.size});
    }
    for (let i = 0; i < gl.getProgramParameter(p, gl.ACTIVE_ATTRIBUTES); i++) {
      const a = gl.getActiveAttrib(p, i);
      r.attributes.push({name: a.name, type: typeName[a.type] || a.type, size: a.size,
                         location: gl.getAttribLocation(p, a.name)});
    }
  }
  res.link[f.replace(/\.vert$/, '')] = r;
}
document.getElementById('out').textContent = 'RESULT' + JSON.stringify(res) + 'END';
</script>"""

FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage"]


def collect(paths):
    """The shader files named or found in the folders named, each with its text."""
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += [os.path.join(p, f) for f in sorted(os.listdir(p))
                      if f.endswith((".vert", ".frag"))]
        else:
            files.append(p)
    sources = {}
    for f in files:
        with open(f, encoding="utf-8", errors="replace") as fh:
            sources[os.path.relpath(f)] = fh.read()
    return sources


def ask(args):
    """Runs the page in headless Chromium and returns its result object."""
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, "oracle.html")
        with open(page, "w") as fh:
            fh.write(PAGE % json.dumps(args).replace("</", "<\\/"))
        dom = subprocess.run(["chromium", *FLAGS, f"--user-data-dir={tmp}/profile",
                              "--dump-dom", "file://" + page],
                             capture_output=True, text=True, timeout=600).stdout
    start = dom.find('<pre id="out">RESULT')
    end = dom.find("END</pre>", start)
    if start < 0 or end < 0:
        sys.exit("webgl-oracle: chromium gave no result (is the chromium package installed?)")
    return json.loads(html.unescape(dom[start + len('<pre id="out">RESULT'):end]))


def main(argv):
    args = {"context": "webgl2", "extensions": [], "limits": False}
    out, paths = None, []
    it = iter(argv)
    for a in it:
        if a == "-o":
            out = next(it)
        elif a == "--context":
            args["context"] = {"webgl1": "webgl", "webgl2": "webgl2"}[next(it)]
        elif a == "--extensions":
            args["extensions"] = [e for e in next(it).split(",") if e]
        elif a == "--limits":
            args["limits"] = True
        else:
            paths.append(a)
    args["sources"] = collect(paths)
    if not args["sources"] and not args["limits"]:
        sys.exit(__doc__)
    result = ask(args)
    result["context"] = "webgl1" if args["context"] == "webgl" else "webgl2"
    text = json.dumps(result, indent=1)
    if out:
        with open(out, "w") as fh:
            fh.write(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
