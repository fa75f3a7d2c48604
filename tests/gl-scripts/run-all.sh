#!/usr/bin/env bash
# Regenerates every WebGL2 call script (make_scripts.py) and Chromium's answers to them:
# NAME.json -> chromium/NAME.{png,json}, probes/NAME.json -> probes/chromium/NAME.{png,json}.
# Exits 1 if any script fails (a GL error other than expected, a failed compile or link, no answer).
#
#   tests/gl-scripts/run-all.sh              regenerate everything (about 4 minutes on 2 cores)
#   tests/gl-scripts/run-all.sh --times N    time the multi-pass scripts instead: N frames each,
#                                            results in a temporary folder, a table on stdout
# Needs python3 and Debian's chromium (CHROMIUM=... to use another binary).
set -euo pipefail
cd "$(dirname "$0")"
times=0
if [[ $# -gt 0 ]]; then
  if [[ $# -ne 2 || $1 != --times || ! $2 =~ ^[1-9][0-9]*$ ]]; then
    echo "usage: run-all.sh [--times N]" >&2
    exit 2
  fi
  times=$2
fi
python3 make_scripts.py
failed=()
if [[ $times -gt 0 ]]; then
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
  printf '%-16s %10s\n' script ms/frame
  for script in *.json; do
    name=${script%.json}
    if python3 run-chromium.py "$script" -o "$out/$name.png" --results "$out/$name.json" --times "$times" \
        >/dev/null; then
      ms=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["ms_per_frame"])' "$out/$name.json")
      printf '%-16s %10s\n' "$name" "$ms"
    else
      failed+=("$name")
    fi
  done
else
  rm -f chromium/*.png chromium/*.json probes/chromium/*.png probes/chromium/*.json
  for script in *.json probes/*.json; do
    dir=$(dirname "$script")/chromium
    name=$(basename "$script" .json)
    python3 run-chromium.py "$script" -o "$dir/$name.png" --results "$dir/$name.json" >/dev/null || failed+=("$script")
  done
  echo "run-all: $(ls chromium/*.json probes/chromium/*.json | wc -l) results written"
fi
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "run-all: failed: ${failed[*]}" >&2
  exit 1
fi
