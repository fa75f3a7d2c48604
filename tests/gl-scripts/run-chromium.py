#!/usr/bin/env python3
"""Run a WebGL2 call script (docs/gl-scripts.md) in headless Chromium (ANGLE on SwiftShader).

usage: run-chromium.py SCRIPT.json -o OUT.png --results OUT.json [--times N] [--timeout S]

The page creates a WebGL2 context of the script's size and attributes, enables its extensions,
runs `setup`, then `frame` once, checking getError() after every call, and reads the default
framebuffer with readPixels(0, 0, width, height, RGBA, UNSIGNED_BYTE). This script writes that as
an 8-bit RGBA PNG whose first row is the top of the image, and the results as JSON: renderer,
version, records, failures, ms_per_frame. With --times N the frame runs N more times, each
followed by a 1-pixel readPixels, and ms_per_frame is the median of those N (not for a script
with `until` waits, which runs under virtual time).

Exit 0 when everything ran as the script expects; exit 1, with the reasons on stderr, when the
script is malformed, a call raised an exception, getError() answered other than expected, a
shader did not compile or a program did not link (info logs printed), an `until` wait ran out,
or Chromium gave no answer in --timeout seconds (it is then killed). The results JSON is still written when Chromium answered.
Needs Debian's chromium (`apt-get install chromium`); uses only the standard library.
"""
import argparse, base64, html, json, math, os, re, struct, subprocess, sys, tempfile, zlib

FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage"]
# Only `until` waits return to the event loop, and --dump-dom waits for them only with a virtual
# time budget (virtual time runs ahead while the page is idle). Under virtual time the clock stands
# still within a task, so a script with `until` cannot be timed.
VIRTUAL_TIME = "--virtual-time-budget=100000000"
CHROMIUM = os.environ.get("CHROMIUM", "chromium")

ENUM = re.compile(r"^[A-Z0-9_]+$")
TYPED = {"f32": "Float32Array", "u8": "Uint8Array", "i8": "Int8Array", "u16": "Uint16Array",
         "i16": "Int16Array", "u32": "Uint32Array", "i32": "Int32Array"}
INT_RANGE = {"u8": (0, 255), "i8": (-128, 127), "u16": (0, 65535), "i16": (-32768, 32767),
             "u32": (0, 4294967295), "i32": (-2147483648, 2147483647)}
CONTEXT_KEYS = ["alpha", "depth", "stencil", "antialias", "premultipliedAlpha", "preserveDrawingBuffer"]
CALL_KEYS = ["f", "a", "as", "record", "error", "until", "status"]
MAX_OUT = 1 << 24


class ScriptError(Exception):
    pass


def is_num(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def is_int(x):
    return isinstance(x, int) and not isinstance(x, bool)


class Loader:
    """Checks a script and resolves its `file` arguments into literal strings."""

    def __init__(self, path):
        self.base = os.path.dirname(os.path.abspath(path))
        self.names = set()
        self.records = set()

    def arg(self, a, what):
        if a is None or isinstance(a, bool) or is_num(a):
            return a
        if isinstance(a, float) or isinstance(a, int):
            raise ScriptError(f"{what}: numbers must be finite")
        if isinstance(a, str):
            return a
        if isinstance(a, list):
            return [self.arg(x, f"{what}[{i}]") for i, x in enumerate(a)]
        if not isinstance(a, dict) or not a:
            raise ScriptError(f"{what}: expected a number, boolean, null, string, list or one-key object")
        key = next(iter(a))
        if key == "out":
            if not {"out", "length"} <= set(a) <= {"out", "length", "fill"} or a["out"] not in TYPED \
                    or not is_int(a["length"]) or not 0 <= a["length"] <= MAX_OUT:
                raise ScriptError(f"{what}: expected {{\"out\": TYPE, \"length\": N}} (and optionally \"fill\") "
                                  f"with TYPE one of {', '.join(TYPED)} and 0 <= N <= {MAX_OUT}")
            fill = a.get("fill", 0)
            lo, hi = INT_RANGE.get(a["out"], (-math.inf, math.inf))
            if not is_num(fill) or not lo <= fill <= hi or (a["out"] in INT_RANGE and not is_int(fill)):
                raise ScriptError(f"{what}: fill must be a value of the {a['out']} array")
            return a
        if len(a) != 1:
            raise ScriptError(f"{what}: an object argument has exactly one key (or out + length), not {sorted(a)}")
        v = a[key]
        if key == "str":
            if not isinstance(v, str):
                raise ScriptError(f"{what}: str takes a string")
            return a
        if key == "file":
            if not isinstance(v, str) or not v or os.path.isabs(v):
                raise ScriptError(f"{what}: file takes a path relative to the script's folder")
            try:
                with open(os.path.join(self.base, v), encoding="utf-8") as fh:
                    return {"str": fh.read()}
            except (OSError, UnicodeDecodeError) as e:
                raise ScriptError(f"{what}: cannot read {v}: {e}")
        if key == "or":
            if not isinstance(v, list) or not v or not all(isinstance(x, str) and ENUM.match(x) for x in v):
                raise ScriptError(f"{what}: or takes a non-empty list of enum names")
            return a
        if key == "ref":
            if not isinstance(v, str) or v not in self.names:
                raise ScriptError(f"{what}: ref {v!r} names no object made by an earlier call's \"as\"")
            return a
        if key in TYPED:
            if not isinstance(v, list) or not all(is_num(x) for x in v):
                raise ScriptError(f"{what}: {key} takes a list of finite numbers")
            if key in INT_RANGE:
                lo, hi = INT_RANGE[key]
                bad = [x for x in v if not is_int(x) or not lo <= x <= hi]
                if bad:
                    raise ScriptError(f"{what}: {key} takes integers in {lo}..{hi}, not {bad[0]}")
            return a
        raise ScriptError(f"{what}: unknown argument object key {key!r}")

    def call(self, c, what):
        if not isinstance(c, dict):
            raise ScriptError(f"{what}: a call is an object")
        extra = [k for k in c if k not in CALL_KEYS]
        if extra or "f" not in c:
            raise ScriptError(f"{what}: " + (f"unknown key {extra[0]!r}" if extra else "missing \"f\""))
        if not isinstance(c["f"], str) or not re.match(r"^[a-z][A-Za-z0-9]*$", c["f"]):
            raise ScriptError(f"{what}: f must be a WebGL2 method name")
        what = f"{what} ({c['f']})"
        out = {"f": c["f"]}
        a = c.get("a", [])
        if not isinstance(a, list):
            raise ScriptError(f"{what}: a must be a list of arguments")
        out["a"] = [self.arg(x, f"{what} argument {i}") for i, x in enumerate(a)]
        if sum(1 for x in out["a"] if isinstance(x, dict) and "out" in x) > 1:
            raise ScriptError(f"{what}: at most one out argument a call")
        if "error" in c:
            if not isinstance(c["error"], str) or not ENUM.match(c["error"]):
                raise ScriptError(f"{what}: error must be an enum name such as INVALID_OPERATION")
            out["error"] = c["error"]
        if "until" in c:
            out["until"] = self.arg(c["until"], f"{what} until")
        if "status" in c:
            if c["f"] not in ("compileShader", "linkProgram") or not isinstance(c["status"], bool):
                raise ScriptError(f"{what}: status (true or false) belongs to compileShader and linkProgram")
            out["status"] = c["status"]
        for key, used, clash in (("record", self.records, "is a key another call already records"),
                                 ("as", self.names, "names an object another call already made")):
            if key in c:
                if not isinstance(c[key], str) or not c[key]:
                    raise ScriptError(f"{what}: {key} must be a non-empty string")
                if c[key] in used:
                    raise ScriptError(f"{what}: {key} {c[key]!r} {clash}")
                used.add(c[key])
                out[key] = c[key]
        return out


def load_script(path):
    try:
        with open(path, encoding="utf-8") as fh:
            s = json.load(fh)
    except (OSError, ValueError) as e:
        raise ScriptError(f"cannot read script: {e}")
    if not isinstance(s, dict):
        raise ScriptError("a script is a JSON object")
    known = ["format", "description", "width", "height", "context", "extensions", "setup", "frame"]
    extra = [k for k in s if k not in known]
    missing = [k for k in ("format", "width", "height", "setup", "frame") if k not in s]
    if extra or missing:
        raise ScriptError("; ".join(([f"unknown key {', '.join(extra)}"] if extra else []) +
                                    ([f"missing {', '.join(missing)}"] if missing else [])))
    if s["format"] != 1:
        raise ScriptError("format: this runner reads format 1")
    if not isinstance(s.get("description", ""), str):
        raise ScriptError("description: expected a string")
    for k in ("width", "height"):
        if not is_int(s[k]) or not 1 <= s[k] <= 4096:
            raise ScriptError(f"{k}: expected an integer in 1..4096")
    ctx = s.get("context", {})
    if not isinstance(ctx, dict) or any(k not in CONTEXT_KEYS or not isinstance(v, bool) for k, v in ctx.items()):
        raise ScriptError(f"context: expected an object of booleans with keys among {', '.join(CONTEXT_KEYS)}")
    exts = s.get("extensions", [])
    if not isinstance(exts, list) or not all(isinstance(e, str) and e for e in exts):
        raise ScriptError("extensions: expected a list of extension names")
    ld = Loader(path)
    phases = {}
    for phase in ("setup", "frame"):
        if not isinstance(s[phase], list):
            raise ScriptError(f"{phase}: expected a list of calls")
        phases[phase] = [ld.call(c, f"{phase}[{i}]") for i, c in enumerate(s[phase])]
    waits = any("until" in c for calls in phases.values() for c in calls)
    return {"width": s["width"], "height": s["height"], "context": ctx, "extensions": exts, "waits": waits, **phases}


PAGE = r"""<!doctype html><canvas id=c></canvas><pre id=out></pre><script>
(async function () {
const S = @SCRIPT@, TIMES = @TIMES@;
const R = {renderer: null, version: null, records: {}, failures: [], ms_per_frame: null, drawing_buffer: null};
const TYPED = {f32: Float32Array, u8: Uint8Array, i8: Int8Array, u16: Uint16Array, i16: Int16Array,
               u32: Uint32Array, i32: Int32Array};
const UNTIL_TRIES = 2500, UNTIL_SLEEP_MS = 4;
class ScriptError extends Error {}
let gl = null;
const exts = [], objs = {};
const errName = e => { for (const k of ['NO_ERROR', 'INVALID_ENUM', 'INVALID_VALUE', 'INVALID_OPERATION',
  'INVALID_FRAMEBUFFER_OPERATION', 'OUT_OF_MEMORY', 'CONTEXT_LOST_WEBGL']) if (gl[k] === e) return k;
  return '0x' + e.toString(16); };
function enumValue(name) {
  if (typeof gl[name] === 'number') return gl[name];
  for (const e of exts) if (typeof e[name] === 'number') return e[name];
  throw new ScriptError('unknown enum ' + name + ' (not on the context nor on an enabled extension)');
}
function arg(a, outs) {
  if (a === null || typeof a === 'number' || typeof a === 'boolean') return a;
  if (typeof a === 'string') return /^[A-Z0-9_]+$/.test(a) ? enumValue(a) : a;
  if (Array.isArray(a)) return a.map(x => arg(x, outs));
  if ('str' in a) return a.str;
  if ('or' in a) return a.or.reduce((v, n) => v | enumValue(n), 0) >>> 0;
  if ('ref' in a) { if (!(a.ref in objs)) throw new ScriptError('ref ' + a.ref + ': no such object yet'); return objs[a.ref]; }
  if ('out' in a) { const v = new TYPED[a.out](a.length).fill(a.fill || 0); outs.push(v); return v; }
  for (const k in TYPED) if (k in a) return new TYPED[k](a[k]);
  throw new ScriptError('bad argument ' + JSON.stringify(a));
}
function conv(v) {
  if (v === undefined || v === null) return null;
  if (typeof v === 'number') return Number.isFinite(v) ? v : String(v);
  if (typeof v === 'boolean' || typeof v === 'string') return v;
  if (ArrayBuffer.isView(v)) return Array.from(v, conv);
  if (Array.isArray(v)) return v.map(conv);
  const name = v.constructor ? v.constructor.name : '';
  if (name === 'WebGLActiveInfo') return {object: name, name: v.name, size: v.size, type: v.type};
  if (name === 'WebGLShaderPrecisionFormat')
    return {object: name, rangeMin: v.rangeMin, rangeMax: v.rangeMax, precision: v.precision};
  if (name.startsWith('WebGL')) return {object: name};
  const o = {};
  for (const k of Object.keys(v).sort()) o[k] = conv(v[k]);
  return o;
}
const sleep = ms => new Promise(r => setTimeout(r, ms));
function drainErrors() {
  const errs = [];
  for (let k = 0; k < 8; k++) { const e = gl.getError(); if (e === gl.NO_ERROR) break; errs.push(e); }
  return errs;
}
// One call. checked: the first run (errors checked, values recorded); else a timed run.
async function call(c, phase, i, checked) {
  const fail = msg => R.failures.push({phase, index: i, f: c.f, message: msg});
  const fn = gl[c.f];
  if (typeof fn !== 'function') throw new ScriptError(phase + '[' + i + ']: ' + c.f + ' is not a WebGL2 method');
  const outs = [], args = c.a.map(x => arg(x, outs));
  let ret;
  try { ret = fn.apply(gl, args); }
  catch (e) { throw new ScriptError(phase + '[' + i + '] ' + c.f + ' threw ' + (e instanceof Error ? e.name + ': ' + e.message : String(e))); }
  if ('until' in c) {
    const want = JSON.stringify(conv(arg(c.until, []))); let tries = 1;
    while (JSON.stringify(conv(ret)) !== want && tries < UNTIL_TRIES) { await sleep(UNTIL_SLEEP_MS); ret = fn.apply(gl, args); tries++; }
    if (JSON.stringify(conv(ret)) !== want) fail('until: still ' + JSON.stringify(conv(ret)) + ' after ' + tries + ' tries, not ' + want);
  }
  if ('as' in c) objs[c.as] = ret;
  if (!checked) return;
  const errs = drainErrors(), want = 'error' in c ? enumValue(c.error) : gl.NO_ERROR;
  const got = errs.length ? errs.map(errName).join(', then ') : 'NO_ERROR';
  if (want === gl.NO_ERROR ? errs.length : (errs[0] !== want || errs.length > 1))
    fail('getError: expected ' + errName(want) + ', got ' + got);
  if (c.f === 'compileShader' || c.f === 'linkProgram') {
    const compile = c.f === 'compileShader';
    const ok = compile ? gl.getShaderParameter(args[0], gl.COMPILE_STATUS) : gl.getProgramParameter(args[0], gl.LINK_STATUS);
    const log = compile ? gl.getShaderInfoLog(args[0]) : gl.getProgramInfoLog(args[0]);
    drainErrors();
    const wantOk = 'status' in c ? c.status : true;
    if (ok !== wantOk) fail((compile ? 'COMPILE_STATUS' : 'LINK_STATUS') + ' is ' + ok + ', expected ' + wantOk +
                            '; info log:\n' + log);
  }
  if ('record' in c) R.records[c.record] = conv(outs.length ? outs[0] : ret);
}
async function run(phase, checked) { for (let i = 0; i < S[phase].length; i++) await call(S[phase][i], phase, i, checked); }
// Read the default framebuffer; the bindings and pack state it changes are restored.
function readDefault(x, y, w, h, px) {
  const readFb = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING), pack = gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING);
  const names = ['PACK_ALIGNMENT', 'PACK_ROW_LENGTH', 'PACK_SKIP_PIXELS', 'PACK_SKIP_ROWS'];
  const saved = names.map(n => gl.getParameter(gl[n]));
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null); gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  names.forEach((n, k) => gl.pixelStorei(gl[n], k === 0 ? 4 : 0));
  gl.readPixels(x, y, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
  names.forEach((n, k) => gl.pixelStorei(gl[n], saved[k]));
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pack); gl.bindFramebuffer(gl.READ_FRAMEBUFFER, readFb);
}
try {
  const canvas = document.getElementById('c');
  canvas.width = S.width; canvas.height = S.height;
  gl = canvas.getContext('webgl2', S.context);
  if (!gl) throw new ScriptError('no WebGL2 context');
  const dri = gl.getExtension('WEBGL_debug_renderer_info');
  R.renderer = dri ? gl.getParameter(dri.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  R.version = gl.getParameter(gl.VERSION);
  R.drawing_buffer = [gl.drawingBufferWidth, gl.drawingBufferHeight];
  for (const name of S.extensions) {
    const e = gl.getExtension(name);
    if (!e) throw new ScriptError('extension ' + name + ' is not supported');
    exts.push(e);
  }
  const pending = drainErrors();
  if (pending.length) throw new ScriptError('GL error before setup: ' + pending.map(errName).join(', '));
  await run('setup', true);
  await run('frame', true);
  const px = new Uint8Array(S.width * S.height * 4);
  readDefault(0, 0, S.width, S.height, px);
  const after = drainErrors();
  if (after.length) R.failures.push({phase: 'readback', index: 0, f: 'readPixels', message: 'GL error ' + after.map(errName).join(', ')});
  let s = ''; for (let i = 0; i < px.length; i += 0x8000) s += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
  R.pixels = btoa(s);
  if (TIMES > 0) {
    const ms = [], one = new Uint8Array(4);
    for (let k = 0; k < TIMES; k++) {
      const t0 = performance.now();
      await run('frame', false);
      readDefault(0, 0, 1, 1, one);
      ms.push(performance.now() - t0);
    }
    const errs = drainErrors();
    if (errs.length && !S.frame.some(c => 'error' in c))
      R.failures.push({phase: 'timed', index: 0, f: null, message: 'GL error in the timed frames: ' + errs.map(errName).join(', ')});
    ms.sort((a, b) => a - b);
    R.ms_per_frame = ms.length % 2 ? ms[(ms.length - 1) / 2] : (ms[ms.length / 2 - 1] + ms[ms.length / 2]) / 2;
  }
} catch (e) {
  R.error = e instanceof ScriptError ? e.message : (e instanceof Error ? e.name + ': ' + e.message + '\n' + e.stack : String(e));
}
document.getElementById('out').textContent = 'RESULT' + JSON.stringify(R) + 'END';
})();
</script>"""


def run_chromium(script, times, timeout):
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, "script.html")
        with open(page, "w", encoding="utf-8") as fh:
            fh.write(PAGE.replace("@TIMES@", str(times)).replace("@SCRIPT@", json.dumps(script).replace("</", "<\\/")))
        try:
            flags = FLAGS + ([VIRTUAL_TIME] if script["waits"] else [])
            proc = subprocess.run([CHROMIUM, *flags, f"--user-data-dir={tmp}/profile", "--dump-dom", "file://" + page],
                                  capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            raise ScriptError(f"{CHROMIUM} gave no answer in {timeout} s (killed)")
        except OSError as e:
            raise ScriptError(f"cannot run {CHROMIUM}: {e} (is Debian's chromium package installed?)")
    dom = proc.stdout
    start, end = dom.find('<pre id="out">RESULT'), dom.rfind("END</pre>")
    if start < 0 or end < 0:
        raise ScriptError(f"chromium gave no result (exit status {proc.returncode}); its stderr ends:\n"
                          + proc.stderr[-2000:])
    return json.loads(html.unescape(dom[start + len('<pre id="out">RESULT'):end]))


def png_bytes(width, height, rgba_bottom_up):
    """8-bit RGBA PNG, filter 0 on every row; the first PNG row is the last readPixels row (the top)."""
    stride = width * 4
    raw = bytearray()
    for y in range(height):
        src = (height - 1 - y) * stride
        raw.append(0)
        raw += rgba_bottom_up[src:src + stride]

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def dumps(v, indent=0):
    """JSON with one key a line in objects and lists of scalars kept on one line."""
    pad = " " * (indent + 1)
    if isinstance(v, dict) and v:
        items = [f"{pad}{json.dumps(k)}: {dumps(x, indent + 1)}" for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    if isinstance(v, list) and any(isinstance(x, (dict, list)) for x in v):
        return "[\n" + ",\n".join(pad + dumps(x, indent + 1) for x in v) + "\n" + " " * indent + "]"
    return json.dumps(v, ensure_ascii=False)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("script")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--results", required=True, help="results JSON to write")
    ap.add_argument("--times", type=int, default=0, metavar="N", help="time N more frames; report the median")
    ap.add_argument("--timeout", type=float, default=300, metavar="S", help="seconds to wait for Chromium (300)")
    args = ap.parse_args(argv)
    if args.times < 0:
        ap.error("--times must be >= 0")
    name = os.path.basename(args.script)
    try:
        script = load_script(args.script)
        if args.times and script["waits"]:
            raise ScriptError("--times: a script with `until` waits cannot be timed (the virtual time that lets "
                              "Chromium wait for them stands still within a task)")
        r = run_chromium(script, args.times, args.timeout)
    except ScriptError as e:
        print(f"run-chromium: {args.script}: {e}", file=sys.stderr)
        return 1
    results = {"renderer": r["renderer"], "version": r["version"], "records": r["records"],
               "failures": r["failures"],
               "ms_per_frame": None if r["ms_per_frame"] is None else round(r["ms_per_frame"], 3)}
    problems = [f"{f['phase']}[{f['index']}] {f['f']}: {f['message']}" for f in r["failures"]]
    if r.get("error"):
        results["failures"].append({"phase": "runner", "index": 0, "f": None, "message": r["error"]})
        problems.append(r["error"])
    if r.get("drawing_buffer") not in (None, [script["width"], script["height"]]):
        problems.append(f"drawing buffer is {r['drawing_buffer']}, not the script's size")
    with open(args.results, "w", encoding="utf-8") as fh:
        fh.write(dumps(results) + "\n")
    if r.get("pixels") is not None:
        with open(args.output, "wb") as fh:
            fh.write(png_bytes(script["width"], script["height"], base64.b64decode(r["pixels"])))
    print(json.dumps({"script": args.script, "png": args.output if r.get("pixels") is not None else None,
                      "results": args.results, "records": len(r["records"]), "failures": len(problems),
                      "ms_per_frame": results["ms_per_frame"]}))
    if problems:
        print(f"run-chromium: {name}: {len(problems)} failure(s):\n  " + "\n  ".join(problems), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
