#!/usr/bin/env bash
# The lints' share of compiling and linting the dEQP corpus's `300 es` shaders: the same
# process run twice, compiling every shader, then compiling and linting it, counted in
# instructions executed (valgrind's callgrind: independent of the machine's load) and timed with
# hyperfine in one run. share = (with lints - without) / with lints. The instructions are those of
# the example's `compile_all` alone: reading and parsing the corpus's JSON is in neither count
# (it is in the times).
#
# Usage: scripts/bench-lint-share.sh [CORPORA_DIR] (default: ../shared/corpora)
# Needs: valgrind; hyperfine for the times (skipped without it).
set -euo pipefail
cd "$(dirname "$0")/.."
corpora="$(cd "${1:-../shared/corpora}" && pwd)"
cargo build --release -q -p essl-lint --example lint-share
bin="$PWD/target/release/examples/lint-share"
count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        --toggle-collect='lint_share::compile_all' "$@" 2>&1 >/dev/null \
        | awk '/Collected :/ { print $4 }'
}
without=$(count "$bin" "$corpora")
with=$(count "$bin" --lint "$corpora")
"$bin" --lint "$corpora"
# As `essl lint` does the work: the front end alone, against the front end, the lowering the
# lints need (typed, where a rule on the IR has something to look at) and the lints.
front=$(count "$bin" --pipeline "$corpora")
piped=$(count "$bin" --pipeline --lint "$corpora")
python3 - "$without" "$with" "$front" "$piped" <<'PY'
import sys
without, with_, front, piped = (int(a) for a in sys.argv[1:])
print(f"instructions: compile {without / 1e6:.1f} M, compile + lints {with_ / 1e6:.1f} M")
print(f"lints' share: {100.0 * (with_ - without) / with_:.1f} %")
print(f"as essl lint: front end {front / 1e6:.1f} M, with the lints' lowering and the lints {piped / 1e6:.1f} M")
print(f"lints' share, their lowering counted: {100.0 * (piped - front) / piped:.1f} %")
PY
if command -v hyperfine >/dev/null; then
    hyperfine --warmup 1 --runs "${RUNS:-10}" -n compile "$bin $corpora" \
        -n "compile + lints" "$bin --lint $corpora"
fi
