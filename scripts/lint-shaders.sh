#!/usr/bin/env bash
# The main job: lint (compile, link, check numerical hazards) every shader in shaders-glsl/.
# Exits 1, because the verbatim seed shaders keep the errors their articles published, on
# purpose: they are the test cases. Their corrected `.fixed` twins and article 001's variants are
# lint-clean (no error, no warning); the shaders composed from articles 003 and 004's snippets
# compile, with the numerical-hazard warnings those snippets carry (docs/lints/README.md, "The
# seeds"). Extra arguments go to `essl lint` (e.g. `--format json`,
# `--deny warnings`); `--fix` is refused here, since it would rewrite the verbatim seeds.
set -euo pipefail
cd "$(dirname "$0")/.."
for arg in "$@"; do
  if [[ $arg == --fix ]]; then
    echo "lint-shaders.sh: not applying --fix: the verbatim seed shaders keep their published" \
      "errors on purpose, and their corrected .fixed twins are already lint-clean." >&2
    exit 2
  fi
done
cargo run --release --quiet -p essl-cli -- lint "$@" shaders-glsl/
