#!/usr/bin/env bash
# The main job: lint (compile, link, check numerical hazards) every shader in shaders-glsl/.
# Exits 1, because the verbatim seed shaders keep the errors their articles published; their
# `.fixed` twins and the composed shaders compile. Extra arguments go to `essl lint`
# (e.g. `--format json`, `--fix`, `--deny warnings`).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run --release --quiet -p essl-cli -- lint "$@" shaders-glsl/
