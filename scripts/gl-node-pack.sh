#!/usr/bin/env bash
# The npm package of the Node.js addon as users get it: builds the addon (release, stripped)
# with @napi-rs/cli, packs crates/essl-gl-node with `npm pack` into target/npm/, installs the
# tarball into a fresh temporary project with `npm i ./essl-gl-<version>.tgz` (nothing is
# compiled: the prebuilt essl-gl.linux-x64-gnu.node is inside), and runs the README's triangle
# example there, checking that it writes a PNG with the triangle's colour in the middle.
#
#   scripts/gl-node-pack.sh [--skip-build]
# Needs Node.js, npm, and a Vulkan driver (mesa-vulkan-drivers) to run the example.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
cd crates/essl-gl-node
stamp=node_modules/.essl-lock
if ! { [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; }; then
    npm ci --no-audit --no-fund --ignore-scripts --loglevel=error
    npm rebuild canvas --loglevel=error >/dev/null 2>&1 || rm -rf node_modules/canvas
    cp package-lock.json "$stamp"
fi
[ "${1:-}" = --skip-build ] || npm run build
mkdir -p "$root/target/npm"
tarball="$root/target/npm/$(npm pack --pack-destination "$root/target/npm" --loglevel=error | tail -1)"
app="$(mktemp -d)"
trap 'rm -rf "$app"' EXIT
cp "$tarball" "$app/"
sed -n '/^## A triangle to PNG/,/^## /p' README.md | sed -n '/^```js$/,/^```$/p' | sed '1d;$d' > "$app/triangle.mjs"
cd "$app"
npm init -y >/dev/null
npm i --no-audit --no-fund --loglevel=error "./$(basename "$tarball")"
node triangle.mjs
node -e '
// The middle pixel of triangle.png (8-bit RGBA, any row filters), as a PNG decoder reads it.
const { inflateSync } = require("node:zlib");
const b = require("node:fs").readFileSync("triangle.png");
if (b.readUInt32BE(0) !== 0x89504e47) throw new Error("triangle.png is not a PNG");
const w = b.readUInt32BE(16), h = b.readUInt32BE(20), stride = w * 4;
const idat = [];
for (let at = 8; at < b.length; ) { const n = b.readUInt32BE(at); if (b.toString("latin1", at + 4, at + 8) === "IDAT") idat.push(b.subarray(at + 8, at + 8 + n)); at += 12 + n; }
const raw = inflateSync(Buffer.concat(idat));
let prev = new Uint8Array(stride), row;
for (let y = 0; y <= h >> 1; y++) {
  const f = raw[y * (stride + 1)], src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
  row = new Uint8Array(stride);
  for (let i = 0; i < stride; i++) {
    const a = i >= 4 ? row[i - 4] : 0, up = prev[i], c = i >= 4 ? prev[i - 4] : 0;
    const p = a + up - c, pa = Math.abs(p - a), pb = Math.abs(p - up), pc = Math.abs(p - c);
    const pred = [0, a, up, (a + up) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? up : c][f];
    row[i] = (src[i] + pred) & 255;
  }
  prev = row;
}
const x = w >> 1, px = [...row.subarray(x * 4, x * 4 + 4)];
if (px[0] !== 255 || px[1] < 120 || px[1] > 136 || px[2] !== 0 || px[3] !== 255) throw new Error("middle pixel " + px);
console.log("triangle.png:", w, "x", h, "middle pixel", px.join(","));
'
echo "gl-node-pack: $tarball ($(du -h "$tarball" | cut -f1)) installs without compiling and draws"
