#!/usr/bin/env python3
"""Draws shaders of a lint corpus for a blind reading (docs/lints/corpus.md, "Recall").

    python3 scripts/lint-corpus/draw.py SEED [N] [--corpus DIR] [--hazards TSV] [--essl BIN]

Takes random.sample(manifest, N) (default 60) of the corpus's manifest.jsonl under
random.seed(SEED), keeps the entries essl compiles (`essl lint --format json` says "ok") and
that no "# reviewed" line of the hazards table lists, and prints them as
"key<TAB>file<TAB>stage" lines (key: the package without "npm:", a colon, the path).
"""
import argparse
import json
import random
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def reviewed(hazards):
    """The keys every "# reviewed" line of a hazards table lists."""
    seen = set()
    for line in open(hazards, encoding="utf-8"):
        if not line.startswith("# reviewed"):
            continue
        line = line.rstrip("\n")
        rest = line.split("): ", 1)[1] if "): " in line else line.split(": ", 1)[1]
        seen.update(x.strip() for x in rest.split(","))
    return seen


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("seed", type=int)
    ap.add_argument("n", type=int, nargs="?", default=60)
    ap.add_argument("--corpus", default=str(ROOT.parent / "lint-corpus" / "fresh"))
    ap.add_argument("--hazards", default=str(ROOT / "docs/lints/corpus-fresh-hazards.tsv"))
    ap.add_argument("--essl", default=str(ROOT / "target/release/essl"))
    a = ap.parse_args()
    corpus = Path(a.corpus)
    manifest = [json.loads(l) for l in open(corpus / "manifest.jsonl", encoding="utf-8")]
    random.seed(a.seed)
    sample = random.sample(manifest, a.n)
    seen = reviewed(a.hazards)
    kept = 0
    for m in sample:
        key = m["repo"].removeprefix("npm:") + ":" + m["path"]
        if key in seen:
            continue
        path = corpus / m["file"]
        r = subprocess.run([a.essl, "lint", "--format", "json", str(path)],
                           capture_output=True, text=True)
        first = r.stdout.splitlines()[0] if r.stdout else ""
        if not json.loads(first or "{}").get("ok"):
            continue
        print(f"{key}\t{path}\t{m['stage']}")
        kept += 1
    print(f"{len(sample)} drawn, {kept} kept", file=sys.stderr)


if __name__ == "__main__":
    main()
