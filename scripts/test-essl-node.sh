#!/usr/bin/env bash
# The npm package `essl` (crates/essl-node): builds the addon (debug, beside the workspace's
# test build), installs the pinned bundlers (crates/essl-node/package-lock.json), and runs its
# node --test suites: the JavaScript API, and real Vite, Rollup and webpack builds. Needs
# Node.js >= 18 and npm; without them it says so and skips, unless ESSL_REQUIRE_CORPORA=1.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    if [ "${ESSL_REQUIRE_CORPORA:-}" = 1 ]; then
        echo "test-essl-node: Node.js and npm are required (ESSL_REQUIRE_CORPORA=1)" >&2
        exit 1
    fi
    echo "test-essl-node: Node.js or npm is not installed; the npm package's tests skip" >&2
    exit 0
fi
# The addon as the workspace's test build resolves features: `cargo build -p essl-node` would
# resolve them for that package alone and compile naga, wgpu and essl's crates once more
# (about 40 units); after `cargo test` this builds the two Node addons and nothing else.
cargo build --workspace --lib --tests --quiet
cd crates/essl-node
node scripts/build.mjs --no-build
stamp=node_modules/.essl-lock
if ! { [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; }; then
    npm ci --no-audit --no-fund --ignore-scripts --loglevel=error
    cp package-lock.json "$stamp"
fi
node --test test/*.test.mjs
