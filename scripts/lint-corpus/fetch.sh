#!/usr/bin/env bash
# Builds the real-world lint corpus of docs/lints/corpus.md, outside the repository:
#   1. fetches each repository of repos.txt at its pinned commit (a shallow fetch of that one
#      commit into OUT/git/OWNER+NAME/repo), or reads it from a local mirror (MIRROR=DIR with
#      DIR/OWNER+NAME/repo, a bare or ordinary git directory);
#   2. extracts their `#version 300 es` shaders (extract.py);
#   3. assembles three.js 0.170.0's built-in materials from its npm package (three.mjs);
# and writes OUT/manifest.jsonl. Then lint it:
#   cargo run --release -p essl-lint --example lint-corpus -- OUT > findings.jsonl
#   python3 scripts/lint-corpus/table.py findings.jsonl docs/lints/corpus-triage.tsv
#
# Usage: scripts/lint-corpus/fetch.sh [OUT] (default ../lint-corpus/corpus)
# Needs: git, python3, node and npm (for three.js), network access to GitHub and npm.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="$(mkdir -p "${1:-$root/../lint-corpus/corpus}" && cd "${1:-$root/../lint-corpus/corpus}" && pwd)"
mirror="${MIRROR:-$out/git}"
three_version=0.170.0

if [ -z "${MIRROR:-}" ]; then
    grep -v '^#' "$here/repos.txt" | while read -r repo commit; do
        [ -n "$repo" ] || continue
        dir="$mirror/${repo/\//+}/repo"
        if git --git-dir "$dir" cat-file -e "$commit^{commit}" 2>/dev/null; then
            continue
        fi
        mkdir -p "$dir"
        git init --quiet --bare "$dir"
        git --git-dir "$dir" fetch --quiet --depth 1 "https://github.com/$repo" "$commit"
    done
fi

rm -rf "$out/shaders" "$out/manifest.jsonl"
python3 "$here/extract.py" --repos "$here/repos.txt" --mirror "$mirror" --out "$out" \
    --shared "$root/../shared" --seeds "$root/shaders-glsl"

# three.js: the npm package's shader chunks, assembled as WebGLProgram does.
npm_dir="$out/npm"
mkdir -p "$npm_dir"
if [ ! -d "$npm_dir/package" ]; then
    (cd "$npm_dir" && npm pack --silent "three@$three_version" >/dev/null && tar xzf "three-$three_version.tgz")
fi
node "$here/three.mjs" "$npm_dir/package" "$out/shaders/mrdoob__three.js"
python3 - "$out" "$three_version" <<'EOF'
import json, os, sys
out, version = sys.argv[1], sys.argv[2]
folder = os.path.join(out, "shaders", "mrdoob__three.js")
with open(os.path.join(out, "manifest.jsonl"), "a", encoding="utf-8") as m:
    for name in sorted(os.listdir(folder)):
        m.write(json.dumps({
            "file": f"shaders/mrdoob__three.js/{name}", "repo": "mrdoob/three.js",
            "commit": f"npm three@{version}", "path": name, "offset": 0,
            "stage": "vertex" if name.endswith(".vert") else "fragment",
        }) + "\n")
EOF
echo "corpus: $(wc -l < "$out/manifest.jsonl") shaders in $out"
