#!/usr/bin/env bash
# Asks Chromium what it says of three.js's example shader objects as WebGL2 receives them:
# builds each with the pinned three.js's own WebGLProgram (tests/js/three-assemble.mjs),
# compiles and links them in headless Chromium (../shared/tools/webgl2-oracle.py), and writes
# what it answered to tests/oracle/three-shaders.json, which crates/essl-check/tests/it/three.rs
# compares essl's `three` preset against. Needs Node.js, npm, python3 and Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/fetch-js-libs.sh
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
node tests/js/three-assemble.mjs "$dir/glsl" >/dev/null
python3 ../shared/tools/webgl2-oracle.py "$dir/glsl" -o "$dir/oracle.json"
python3 - "$dir/oracle.json" tests/js/package-lock.json > tests/oracle/three-shaders.json <<'PY'
import json, os, sys
oracle = json.load(open(sys.argv[1]))
lock = json.load(open(sys.argv[2]))["packages"]
name = lambda path: os.path.basename(path).rsplit(".", 1)[0]
programs = {}
for path, link in sorted(oracle["link"].items()):
    n = name(path)
    logs = [oracle["compile"].get(path + ext, {}).get("log", "") for ext in (".vert", ".frag")]
    programs[n] = {
        "vertex_compiled": oracle["compile"].get(path + ".vert", {}).get("ok"),
        "fragment_compiled": oracle["compile"].get(path + ".frag", {}).get("ok"),
        "linked": link.get("ok"),
        "uniforms": len(link.get("uniforms", [])),
        "attributes": len(link.get("attributes", [])),
        "log": "".join(l for l in logs if l).strip(),
    }
print(json.dumps({
    "renderer": oracle["renderer"],
    "versions": {"three": lock["node_modules/three"]["version"]},
    "programs": programs,
}, indent=1))
PY
echo "wrote tests/oracle/three-shaders.json" >&2
