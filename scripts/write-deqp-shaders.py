#!/usr/bin/env python3
"""Write every `300 es` case of the dEQP corpus as caseNNNNN.vert + caseNNNNN.frag.

usage: scripts/write-deqp-shaders.py DEQP_JSONL OUT_DIR

The folder the benchmarks (scripts/bench-lint.sh, scripts/bench-ab.sh) time essl and
glslangValidator on. Prints the number of cases, files and KiB written.
"""
import json
import os
import sys

src, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
n = 0
for line in open(src, encoding="utf-8"):
    case = json.loads(line)
    if case.get("version") != "300 es":
        continue
    n += 1
    for key, ext in (("vertex_source", "vert"), ("fragment_source", "frag")):
        if case.get(key):
            with open(os.path.join(out, f"case{n:05}.{ext}"), "w", encoding="utf-8") as f:
                f.write(case[key])
names = os.listdir(out)
print(f"{n} cases, {len(names)} files, "
      f"{sum(os.path.getsize(os.path.join(out, p)) for p in names) // 1024} KiB")
