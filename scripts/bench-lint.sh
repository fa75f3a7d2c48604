#!/usr/bin/env bash
# Times `essl lint` against glslangValidator on the dEQP corpus's `300 es` shaders.
#
# Writes every `300 es` case of ../shared/corpora/deqp_gles3.jsonl as CASE.vert + CASE.frag into
# a temporary folder, builds essl in release mode, then times with hyperfine (in the same run):
#   essl lint --format json DIR              compile every file, link every CASE.vert + CASE.frag
#   essl lint --format json --no-link DIR    compile every file (the same work as glslang)
#   glslangValidator -t case*                one process, all files, its multi-threaded mode
#   xargs -P2 -n1 glslangValidator           one process per file, two at a time
# and prints the mean times, the CPU time per shader (user, and user + system) and the ratios,
# then the median ratio of interleaved rounds (ROUNDS,
# default 21). glslangValidator compiles each file on its own (no `-l`: `-l` links all inputs
# into one program, which is not what the corpus means).
#
# Usage: scripts/bench-lint.sh [CORPORA_DIR] (default: ../shared/corpora)
# Needs: python3, glslangValidator (Debian glslang-tools), hyperfine (Debian hyperfine).
set -euo pipefail
cd "$(dirname "$0")/.."

corpora="${1:-../shared/corpora}"
runs="${RUNS:-10}"
for tool in python3 glslangValidator hyperfine; do
    command -v "$tool" >/dev/null || { echo "error: $tool is not installed" >&2; exit 2; }
done

cargo build --release -p essl-cli --quiet
essl="$PWD/target/release/essl"

dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 scripts/write-deqp-shaders.py "$corpora/deqp_gles3.jsonl" "$dir/shaders"
(cd "$dir/shaders" && ls) > "$dir/files.txt"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "essl: $("$essl" --version); glslangValidator: $(glslangValidator --version | head -1)"

cd "$dir/shaders"
# The first three are fast: RUNS runs each after a warm-up. One process per file takes minutes,
# so it runs once (PER_FILE=0 skips it).
hyperfine --ignore-failure --warmup 1 --runs "$runs" --export-json "$dir/times.json" \
    -n "essl lint (compile + link pairs)" "$essl lint --format json . > /dev/null" \
    -n "essl lint --no-link" "$essl lint --format json --no-link . > /dev/null" \
    -n "glslangValidator -t, all files in one process" "glslangValidator -t case* > /dev/null"
if [ "${PER_FILE:-1}" != 0 ]; then
    hyperfine --ignore-failure --runs 1 --export-json "$dir/times-each.json" \
        -n "glslangValidator, one process per file (xargs -P2)" \
        "xargs -a $dir/files.txt -P2 -n1 glslangValidator > /dev/null"
fi

python3 - "$dir/times.json" "$dir/times-each.json" <<'EOF2'
import json, os, sys
results = []
for path in sys.argv[1:]:
    if os.path.exists(path):
        results += json.load(open(path))["results"]
mean = {x["command"]: x["mean"] for x in results}
files = len(os.listdir("."))
print()
for x in results:
    print(f"{x['command']:55} {x['mean'] * 1000:9.1f} ms ± {x['stddev'] * 1000 if x['stddev'] else 0:.1f}")
print()
# CPU per shader: the mean user time of the runs over the number of files (all threads
# together), and with the kernel's time added.
for x in results:
    user, system = x["user"] * 1e6 / files, x["system"] * 1e6 / files
    print(f"CPU per shader, {x['command'][:45]:45} {user:6.1f} µs user, {user + system:6.1f} µs user + system")
print()
essl, essl_nolink, g_all = list(mean.values())[:3]
print(f"glslangValidator -t (one process) / essl lint:           {g_all / essl:6.2f}x")
print(f"glslangValidator -t (one process) / essl lint --no-link: {g_all / essl_nolink:6.2f}x")
if len(mean) > 3:
    print(f"glslangValidator per file (xargs -P2) / essl lint:       {list(mean.values())[3] / essl:6.2f}x")
EOF2

# hyperfine runs all of one command, then all of the next: a change in the machine's load between
# those blocks moves the ratio (on the shared 2-core VM, glslangValidator's mean has moved by a
# third between two invocations). Interleaved rounds time the three commands back to back, in an
# order that rotates each round, and report the median of the per-round ratios, which a slow
# change of load does not bias.
python3 - "$essl" "${ROUNDS:-21}" <<'EOF3'
import glob, statistics, subprocess, sys, time
essl, rounds = sys.argv[1], int(sys.argv[2])
files = sorted(glob.glob("case*"))
cmds = {
    "link": [essl, "lint", "--format", "json", "."],
    "no-link": [essl, "lint", "--format", "json", "--no-link", "."],
    "glslang": ["glslangValidator", "-t", *files],
}
names = list(cmds)
ratios = {"link": [], "no-link": []}
for r in range(rounds):
    t = {}
    for name in names[r % 3:] + names[:r % 3]:
        start = time.perf_counter()
        subprocess.run(cmds[name], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        t[name] = time.perf_counter() - start
    for k in ratios:
        ratios[k].append(t["glslang"] / t[k])
print()
for k, label in (("link", "essl lint"), ("no-link", "essl lint --no-link")):
    q = statistics.quantiles(ratios[k], n=4)
    print(f"glslangValidator -t / {label:20} interleaved, median of {rounds} rounds: "
          f"{statistics.median(ratios[k]):5.2f}x (quartiles {q[0]:.2f}-{q[2]:.2f})")
EOF3
