#!/usr/bin/env bash
# Asks Chromium what it says of deck.gl's layer shaders as WebGL2 receives them: assembles each
# layer's shaders with the pinned deck.gl and luma.gl (tests/js/deck-assemble.mjs), compiles and
# links them in headless Chromium (../shared/tools/webgl2-oracle.py), and writes what it answered
# to tests/oracle/deck-layers.json, which crates/essl-check/tests/it/presets.rs compares essl's
# `luma` preset against. Needs Node.js, npm, python3 and Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/fetch-js-libs.sh
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
node tests/js/deck-assemble.mjs "$dir/glsl" >/dev/null
python3 ../shared/tools/webgl2-oracle.py "$dir/glsl" -o "$dir/oracle.json"
python3 - "$dir/oracle.json" tests/js/package-lock.json > tests/oracle/deck-layers.json <<'PY'
import json, os, sys
oracle = json.load(open(sys.argv[1]))
lock = json.load(open(sys.argv[2]))["packages"]
name = lambda path: os.path.basename(path).rsplit(".", 1)[0]
programs = {}
for path, link in sorted(oracle["link"].items()):
    n = name(path)
    programs[n] = {
        "vertex_compiled": oracle["compile"].get(path + ".vert", {}).get("ok"),
        "fragment_compiled": oracle["compile"].get(path + ".frag", {}).get("ok"),
        "linked": link.get("ok"),
        "uniforms": len(link.get("uniforms", [])),
        "attributes": len(link.get("attributes", [])),
    }
print(json.dumps({
    "renderer": oracle["renderer"],
    "versions": {p: lock[f"node_modules/{p}"]["version"] for p in
                 ["@deck.gl/core", "@deck.gl/layers", "@luma.gl/shadertools"]},
    "programs": programs,
}, indent=1))
PY
echo "wrote tests/oracle/deck-layers.json" >&2
