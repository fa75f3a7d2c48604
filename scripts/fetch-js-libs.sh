#!/usr/bin/env bash
# Installs the JavaScript libraries the tests read (deck.gl and luma.gl for the `luma` preset,
# three.js for the `three` preset), at the versions tests/js/package-lock.json pins, into
# tests/js/node_modules (git-ignored). Needs Node.js and npm, and the npm registry. Does nothing
# when the installed tree already matches the lock file.
set -euo pipefail
cd "$(dirname "$0")/../tests/js"
if ! command -v npm >/dev/null; then
    echo "fetch-js-libs: npm is not installed; the tests that read these libraries skip" >&2
    exit 0
fi
stamp=node_modules/.essl-lock
if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; then
    exit 0
fi
npm ci --no-audit --no-fund --ignore-scripts --loglevel=error
cp package-lock.json "$stamp"
