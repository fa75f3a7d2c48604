#!/usr/bin/env bash
# Prints the stamp of the fresh lint corpus's assembly: a hash of the pinned packages and the
# scripts that extract and assemble their shaders. fetch-fresh.sh writes it beside the
# manifest; scripts/test.sh rebuilds a corpus whose stamp differs (one assembled by older
# scripts, whose findings the triage tables no longer describe).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cat "$here/fresh-packages.txt" "$here/extract-fresh.py" "$here/fresh_assemble.py" \
    | sha256sum | cut -d' ' -f1
