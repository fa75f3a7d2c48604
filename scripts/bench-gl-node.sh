#!/usr/bin/env bash
# Speed of essl-gl in Node (crates/essl-gl-node) beside headless Chromium, in one run on one
# machine: per-frame time of the three.js scenes (median of 30 frames, each with a 1-pixel
# readPixels), context creation time, and the memory of 100 contexts created and destroyed.
#
#   scripts/bench-gl-node.sh [--skip-build]
# Needs Debian's chromium, Node.js and npm. Prints the commit and machine first.
set -euo pipefail
cd "$(dirname "$0")/../crates/essl-gl-node"
if [ "${1:-}" != "--skip-build" ]; then
    npm ci --no-audit --no-fund --loglevel=error
    npm run build
fi
echo "commit $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (modified)'), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(chromium --version 2>/dev/null | head -1)"
node three/run.mjs --node --chromium --json /tmp/essl-gl-node-three-bench.json
node --expose-gc bench/contexts.mjs --chromium
