#!/usr/bin/env python3
"""What Chromium draws for the `render: true` GLSL ES 1.00 WebGL conformance cases.

usage: python3 tests/oracle/render_es100.py [CORPUS.jsonl] [-o tests/oracle/es100-render.json]

For every case of webgl_conformance_es100.jsonl (default: ../shared/corpora/) with `render`
true, in a WebGL 1 and a WebGL 2 context, does what the conformance harness
(GLSLConformanceTester) does: a 32x32 canvas, both shaders compiled, `vPosition` bound to
location 0 and `texCoord0` to 1 when the vertex shader names them, the program linked and used,
a unit quad (two triangles, vec3 positions at 0, vec2 texture coordinates at 1) drawn after
clearing to white, then every pixel read back. Writes, per case `FILE#INDEX` and context,
whether it linked, whether every pixel is the case's `render_color` (green by default), and
the centre pixel. Needs Debian's chromium; uses only the standard library.
"""
import html
import json
import os
import subprocess
import sys
import tempfile

PAGE = r"""<!doctype html><canvas id=c1 width=32 height=32></canvas><canvas id=c2 width=32 height=32>
</canvas><pre id=out></pre><script>
const cases = %s;
const out = {};
const quad = new Float32Array([1,1,0, -1,1,0, -1,-1,0, 1,1,0, -1,-1,0, 1,-1,0]);
const uv = new Float32Array([1,1, 0,1, 0,0, 1,1, 0,0, 1,0]);
function draw(gl, c) {
  const sh = (type, src) => {
    const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s);
    return gl.getShaderParameter(s, gl.COMPILE_STATUS) ? s : null;
  };
  const vs = sh(gl.VERTEX_SHADER, c.vertex), fs = sh(gl.FRAGMENT_SHADER, c.fragment);
  if (!vs || !fs) return {linked: false};
  const p = gl.createProgram(); gl.attachShader(p, vs); gl.attachShader(p, fs);
  if (c.vertex.indexOf('vPosition') >= 0) gl.bindAttribLocation(p, 0, 'vPosition');
  if (c.vertex.indexOf('texCoord0') >= 0) gl.bindAttribLocation(p, 1, 'texCoord0');
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return {linked: false};
  gl.useProgram(p);
  const b0 = gl.createBuffer(); gl.bindBuffer(gl.ARRAY_BUFFER, b0);
  gl.bufferData(gl.ARRAY_BUFFER, quad, gl.STATIC_DRAW);
  gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
  const b1 = gl.createBuffer(); gl.bindBuffer(gl.ARRAY_BUFFER, b1);
  gl.bufferData(gl.ARRAY_BUFFER, uv, gl.STATIC_DRAW);
  gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 2, gl.FLOAT, false, 0, 0);
  gl.clearColor(1, 1, 1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.drawArrays(gl.TRIANGLES, 0, 6);
  const px = new Uint8Array(32 * 32 * 4);
  gl.readPixels(0, 0, 32, 32, gl.RGBA, gl.UNSIGNED_BYTE, px);
  let all = true;
  for (let i = 0; i < px.length; i += 4)
    for (let k = 0; k < 4; k++) if (px[i + k] != c.color[k]) all = false;
  const m = (16 * 32 + 16) * 4;
  gl.deleteProgram(p); gl.deleteShader(vs); gl.deleteShader(fs);
  gl.deleteBuffer(b0); gl.deleteBuffer(b1);
  return {linked: true, drawn: all, center: [px[m], px[m + 1], px[m + 2], px[m + 3]]};
}
const gl1 = document.getElementById('c1').getContext('webgl');
const gl2 = document.getElementById('c2').getContext('webgl2');
for (const c of cases) out[c.id] = {webgl1: draw(gl1, c), webgl2: draw(gl2, c)};
document.getElementById('out').textContent = 'RESULT' + JSON.stringify(out) + 'END';
</script>"""

FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage"]


def main(argv):
    corpus = os.path.join("..", "shared", "corpora", "webgl_conformance_es100.jsonl")
    out = os.path.join("tests", "oracle", "es100-render.json")
    it = iter(argv)
    for a in it:
        if a == "-o":
            out = next(it)
        else:
            corpus = a
    cases = []
    with open(corpus, encoding="utf-8") as fh:
        for line in fh:
            c = json.loads(line)
            if not c.get("render"):
                continue
            cases.append({
                "id": "%s#%s" % (c["file"], c["index"]),
                "vertex": c["vertex_source"],
                "fragment": c["fragment_source"],
                "color": c.get("render_color") or [0, 255, 0, 255],
            })
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, "render.html")
        with open(page, "w") as fh:
            fh.write(PAGE % json.dumps(cases).replace("</", "<\\/"))
        dom = subprocess.run(["chromium", *FLAGS, f"--user-data-dir={tmp}/profile",
                              "--dump-dom", "file://" + page],
                             capture_output=True, text=True, timeout=900).stdout
    start = dom.find('<pre id="out">RESULT')
    end = dom.find("END</pre>", start)
    if start < 0 or end < 0:
        sys.exit("render_es100: chromium gave no result")
    result = json.loads(html.unescape(dom[start + len('<pre id="out">RESULT'):end]))
    with open(out, "w") as fh:
        fh.write(json.dumps(result, indent=0, sort_keys=True) + "\n")
    drawn = {k: sum(1 for v in result.values() if v[k].get("drawn")) for k in ("webgl1", "webgl2")}
    print(f"{len(result)} cases; drawn in the expected colour: {drawn}")


if __name__ == "__main__":
    main(sys.argv[1:])
