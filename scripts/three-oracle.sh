#!/usr/bin/env bash
# Asks Chromium what it says of three.js's example shaders as WebGL2 receives them: the shader
# objects of examples/jsm/shaders (tests/js/three-assemble.mjs) and the materials the classes of
# examples/jsm make (tests/js/three-materials.mjs), each built by the pinned three.js's own
# WebGLProgram, compiled and linked in headless Chromium (../shared/tools/webgl2-oracle.py);
# writes what it answered to tests/oracle/three-shaders.json (`programs`, and `materials` with
# where each material's texts are written), which crates/essl-check/tests/it/three.rs compares
# essl's `three` preset against. Needs Node.js, npm, python3 and Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/fetch-js-libs.sh
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
node tests/js/three-assemble.mjs "$dir/glsl" >/dev/null
node tests/js/three-materials.mjs "$dir/materials" >/dev/null
python3 ../shared/tools/webgl2-oracle.py "$dir/glsl" -o "$dir/oracle.json"
python3 ../shared/tools/webgl2-oracle.py "$dir/materials" -o "$dir/materials-oracle.json"
python3 - "$dir/oracle.json" "$dir/materials-oracle.json" "$dir/materials/materials.json" \
    tests/js/package-lock.json > tests/oracle/three-shaders.json <<'PY'
import json, os, sys
lock = json.load(open(sys.argv[4]))["packages"]
name = lambda path: os.path.basename(path).rsplit(".", 1)[0]

def verdicts(oracle):
    out = {}
    for path, link in sorted(oracle["link"].items()):
        logs = [oracle["compile"].get(path + ext, {}).get("log", "") for ext in (".vert", ".frag")]
        out[name(path)] = {
            "vertex_compiled": oracle["compile"].get(path + ".vert", {}).get("ok"),
            "fragment_compiled": oracle["compile"].get(path + ".frag", {}).get("ok"),
            "linked": link.get("ok"),
            "uniforms": len(link.get("uniforms", [])),
            "attributes": len(link.get("attributes", [])),
            "log": "".join(l for l in logs if l).strip(),
        }
    return out

oracle = json.load(open(sys.argv[1]))
materials = verdicts(json.load(open(sys.argv[2])))
for n, at in json.load(open(sys.argv[3])).items():
    materials[n].update(at)
print(json.dumps({
    "renderer": oracle["renderer"],
    "versions": {"three": lock["node_modules/three"]["version"]},
    "programs": verdicts(oracle),
    "materials": materials,
}, indent=1))
PY
echo "wrote tests/oracle/three-shaders.json" >&2
