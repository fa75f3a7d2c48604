#!/usr/bin/env bash
# node --test of the Node.js addon (crates/essl-gl-node): the binding's own tests, the three.js
# scenes against Chromium's committed pictures, and a fixed sample of the WebGL conformance
# suite's pages against the committed results. Builds the addon (debug, as `cargo test` does)
# and installs the package's pinned devDependencies (package-lock.json) when they changed.
# The conformance pages draw with 2D canvases too: jsdom takes them from the `canvas` package,
# whose addon is fetched prebuilt or compiled (Debian: build-essential libcairo2-dev
# libpango1.0-dev libjpeg-dev libgif-dev librsvg2-dev); where it cannot be had, the sample of
# conformance pages skips with a message.
# Without Node.js and npm it skips with a message; ESSL_REQUIRE_CORPORA=1 makes that a failure,
# as it does for the conformance suite's sdk/tests (test-data/webgl/sdk/tests, or
# ESSL_WEBGL_SDK), which scripts/gl-node-conformance.sh fetches.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "test-gl-node: Node.js and npm are not installed; the essl-gl-node tests skip" >&2
    [ "${ESSL_REQUIRE_CORPORA:-}" = 1 ] && exit 1
    exit 0
fi
# The addon as the workspace's test build resolves features: `cargo build -p essl-gl-node` would
# resolve them for that package alone and compile naga, wgpu and essl's crates once more
# (about 40 units); after `cargo test` this builds the two Node addons and nothing else.
cargo build --workspace --lib --tests --quiet
target="$(cargo metadata --format-version 1 --no-deps | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).target_directory))')"
addon="$target/debug/essl-gl.linux-x64-gnu.node"
cp "$target/debug/libessl_gl_node.so" "$addon"
cd crates/essl-gl-node
stamp=node_modules/.essl-lock
if ! { [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; }; then
    npm ci --no-audit --no-fund --ignore-scripts --loglevel=error
    # node-gyp takes Node's headers from the installation when it has them, rather than
    # downloading them from nodejs.org.
    nodedir="$(dirname "$(dirname "$(command -v node)")")"
    if [ -f "$nodedir/include/node/node_api.h" ]; then export npm_config_nodedir="$nodedir"; fi
    if ! npm rebuild canvas --loglevel=error >/dev/null 2>&1; then
        echo "test-gl-node: the canvas package did not build; it is removed (jsdom then has no 2D canvas)" >&2
        rm -rf node_modules/canvas
    fi
    cp package-lock.json "$stamp"
fi
ESSL_GL_NODE_BINARY="$addon" node --test test/
