#!/usr/bin/env bash
# Frame times of the eight multi-pass call scripts (tests/gl-scripts/*.json) in Chromium's
# WebGL2 (ANGLE on SwiftShader) and in essl-gl (lavapipe), measured the same way on both sides:
# the frame's calls and a 1-pixel readPixels, the median of N frames (default 30). Each round
# runs every script in both, alternating; a side's figure is its best round (default 3), so a
# burst of load on the machine costs one round, not the table. Prints a Markdown table with the
# ratio Chromium / essl-gl.
#
#   scripts/bench-gl-scripts.sh [FRAMES [ROUNDS]]
#
# Needs Debian's chromium (CHROMIUM=... for another binary) and a Vulkan adapter (lavapipe).
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-30}
rounds=${2:-3}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
cargo build --release -q -p essl-gl-script --bin gl-script
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
ms() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["ms_per_frame"])' "$1"; }
declare -A chromium essl
for ((r = 1; r <= rounds; r++)); do
  for script in tests/gl-scripts/*.json; do
    name=$(basename "$script" .json)
    python3 tests/gl-scripts/run-chromium.py "$script" -o "$out/c.png" --results "$out/c.json" \
      --times "$frames" >/dev/null
    target/release/gl-script "$script" -o "$out/e.png" --results "$out/e.json" \
      --times "$frames" >/dev/null
    c=$(ms "$out/c.json")
    e=$(ms "$out/e.json")
    chromium[$name]=$(python3 -c "import sys; a=sys.argv[1]; b=float(sys.argv[2]); print(b if not a else min(float(a), b))" "${chromium[$name]:-}" "$c")
    essl[$name]=$(python3 -c "import sys; a=sys.argv[1]; b=float(sys.argv[2]); print(b if not a else min(float(a), b))" "${essl[$name]:-}" "$e")
  done
done
echo "| script | Chromium ms/frame | essl-gl ms/frame | Chromium / essl-gl |"
echo "|---|---:|---:|---:|"
for script in tests/gl-scripts/*.json; do
  name=$(basename "$script" .json)
  python3 -c "import sys; n, c, e = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]); print(f'| \`{n}\` | {c:.2f} | {e:.2f} | {c / e:.1f}× |')" \
    "$name" "${chromium[$name]}" "${essl[$name]}"
done
echo
echo "$frames frames a run, best of $rounds rounds; $(chromium --version 2>/dev/null || echo chromium), essl-gl $(git rev-parse --short HEAD) on $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
