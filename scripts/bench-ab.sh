#!/usr/bin/env bash
# Compares the CPU time of two essl binaries on the dEQP corpus's `300 es` shaders, alternating
# them so that a change of the machine's load between runs does not bias the comparison.
#
# Writes the shaders as scripts/bench-lint.sh does, then runs `essl lint --format json
# --no-link` over the folder with A, then with B, ROUNDS times (default 15), and prints each
# binary's median user time (per shader too) and the median and quartiles of the per-round
# ratio B / A. THREADS (default: rayon's choice) sets RAYON_NUM_THREADS.
#
# Usage: scripts/bench-ab.sh OLD_ESSL NEW_ESSL [CORPORA_DIR] (default: ../shared/corpora)
# Build the old binary from a worktree: git worktree add /tmp/old COMMIT && cargo build
# --release -p essl-cli --manifest-path /tmp/old/Cargo.toml
# Needs: python3.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 OLD_ESSL NEW_ESSL [CORPORA_DIR]" >&2; exit 2; }
a="$(realpath "$1")"
b="$(realpath "$2")"
corpora="${3:-../shared/corpora}"

dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 scripts/write-deqp-shaders.py "$corpora/deqp_gles3.jsonl" "$dir" >/dev/null

python3 - "$a" "$b" "$dir" "${ROUNDS:-15}" "${THREADS:-}" <<'EOF'
import os, resource, statistics, subprocess, sys
a, b, folder, rounds, threads = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
env = dict(os.environ)
if threads:
    env["RAYON_NUM_THREADS"] = threads
files = len(os.listdir(folder))

def user_time(binary):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    subprocess.run([binary, "lint", "--format", "json", "--no-link", "."], cwd=folder, env=env,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before

times = {a: [], b: []}
for _ in range(rounds):
    for binary in (a, b):
        times[binary].append(user_time(binary))
ratios = [y / x for x, y in zip(times[a], times[b])]
for label, binary in (("A", a), ("B", b)):
    m = statistics.median(times[binary])
    print(f"{label} {binary}: median user time {m * 1e3:.0f} ms, {m / files * 1e6:.1f} µs a shader")
q = statistics.quantiles(ratios, n=4)
print(f"B / A per round, median of {rounds}: {statistics.median(ratios):.3f} "
      f"(quartiles {q[0]:.3f}-{q[2]:.3f})")
EOF
