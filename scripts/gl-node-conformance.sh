#!/usr/bin/env bash
# The Khronos WebGL conformance suite in Node on essl-gl (crates/essl-gl-node), beside headless
# Chromium, in one run; writes the committed results (crates/essl-gl-node/conformance/results)
# and the tables of docs/conformance.md.
#
#   scripts/gl-node-conformance.sh [--from-git-dir GITDIR] [--jobs N] [--only SUBSTRING] [--every N] [--skip-chromium]
#
# The suite's sdk/tests come from KhronosGroup/WebGL at the commit scripts/fetch-test-data.sh
# pins: from GITDIR (a clone or bare mirror holding it), from $ESSL_WEBGL_SRC (a checkout),
# or cloned from GitHub; they are kept in test-data/webgl/sdk/tests (git-ignored), where the
# test suite's sample (crates/essl-gl-node/test/conformance.test.mjs) finds them.
# Needs Debian's chromium, Node.js and npm (npm ci installs jsdom and playwright-core).
# A full run of both contexts takes about two hours on 2 cores.
#
# The `gl` package (headless-gl) runs the same pages as a peer where it is installed in
# test-data/webgl/runs/gl: its install compiles ANGLE with node-gyp, and its contexts need an X
# display (xvfb-run gives one when DISPLAY is unset):
#   apt-get install build-essential python3 pkg-config libxi-dev libglu1-mesa-dev libglew-dev xvfb
#   npm i --prefix test-data/webgl/runs/gl gl@8.1.6
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
commit=f15a73f727d8ee66a3ec6d0bed9f02f08cacc2c1 # KhronosGroup/WebGL, as scripts/fetch-test-data.sh
gitdir="" jobs=2 only="" every="" chromium=1
while [ $# -gt 0 ]; do
    case "$1" in
        --from-git-dir) gitdir="$2"; shift 2 ;;
        --jobs) jobs="$2"; shift 2 ;;
        --only) only="$2"; shift 2 ;;
        --every) every="$2"; shift 2 ;;
        --skip-chromium) chromium=0; shift ;;
        *) echo "unknown argument: $1" >&2; exit 2 ;;
    esac
done
sdk="$root/test-data/webgl/sdk/tests"
if [ ! -f "$sdk/js/js-test-pre.js" ]; then
    mkdir -p "$root/test-data/webgl"
    if [ -n "$gitdir" ]; then
        git --git-dir="$gitdir" archive "$commit" sdk/tests | tar x -C "$root/test-data/webgl"
    elif [ -n "${ESSL_WEBGL_SRC:-}" ]; then
        cp -r "$ESSL_WEBGL_SRC/sdk" "$root/test-data/webgl/"
    else
        src="$root/test-data/sources/webgl"
        [ -d "$src/.git" ] || git clone --filter=blob:none --no-checkout https://github.com/KhronosGroup/WebGL.git "$src"
        git -C "$src" archive "$commit" sdk/tests | tar x -C "$root/test-data/webgl"
    fi
fi
cd crates/essl-gl-node
npm ci --no-audit --no-fund --loglevel=error
npm run build
runs="$root/test-data/webgl/runs"
mkdir -p "$runs"
filter=()
[ -n "$only" ] && filter=(--only "$only")
[ -n "$every" ] && filter+=(--every "$every")
for ctx in webgl2 webgl1; do
    if [ "$chromium" = 1 ]; then
        node conformance/run.mjs --impl chromium --context "$ctx" --jobs "$jobs" --timeout 180 "${filter[@]}" --out "$runs/chromium-$ctx.jsonl"
    fi
    node conformance/run.mjs --impl essl-gl --context "$ctx" --jobs "$jobs" --timeout 120 "${filter[@]}" --out "$runs/essl-gl-$ctx.jsonl"
    if [ -d "$runs/gl/node_modules/gl" ]; then
        display=()
        [ -z "${DISPLAY:-}" ] && display=(xvfb-run -a)
        ESSL_HEADLESS_GL="$runs/gl/node_modules/gl" "${display[@]}" node conformance/run.mjs --impl gl --context "$ctx" --jobs "$jobs" --timeout 120 "${filter[@]}" --out "$runs/gl-$ctx.jsonl"
    fi
done
sample=()
[ -n "$every" ] && sample=(--every "$every")
node conformance/report.mjs --runs "$runs" --write-results --markdown "$root/docs/conformance.md" --intro conformance/intro.md "${sample[@]}"
