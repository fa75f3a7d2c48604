#!/usr/bin/env python3
"""Check the minimised cases in tests/differential/essl-wrong/ against essl (and Chromium).

usage: check_cases.py [DIR] [--chromium]

Each case's second line (the first is `#version 300 es`) says what Chromium answered
("Chromium: compiles" or "Chromium: rejects") and what essl answered. Prints, per case,
whether essl now agrees with Chromium's recorded answer (FIXED) or still differs (STILL WRONG);
with --chromium, asks Chromium again and flags any case whose recorded answer is stale.
Exit status 0 when every case still reads as recorded, 1 otherwise. Standard library only.
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
ESSL = os.path.join(ROOT, "target", "release", "essl")
# ../shared beside the repository.
ORACLE = os.path.join(ROOT, "..", "shared", "tools", "webgl2-oracle.py")


def main(argv):
    ask = "--chromium" in argv
    args = [a for a in argv if a != "--chromium"]
    folder = args[0] if args else os.path.join(ROOT, "tests", "differential", "essl-wrong")
    files = sorted(f for f in os.listdir(folder) if f.endswith((".frag", ".vert")))
    chrome = {}
    if ask:
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "o.json")
            subprocess.run([sys.executable, ORACLE, *files, "-o", out], cwd=folder, check=True,
                           capture_output=True)
            with open(out) as fh:
                chrome = {os.path.basename(k): v["ok"] for k, v in json.load(fh)["compile"].items()}
    p = subprocess.run([ESSL, "lint", "--format", "json", "--no-link", "--color", "never",
                        *[os.path.join(folder, f) for f in files]], capture_output=True, text=True)
    essl = {os.path.basename(o["file"]): o["ok"] for o in map(json.loads, p.stdout.splitlines())
            if o.get("kind") == "shader"}
    bad = 0
    for f in files:
        with open(os.path.join(folder, f)) as fh:
            head = fh.read().splitlines()[1]
        recorded = "Chromium: compiles" in head
        line = "%-45s chromium %s, essl now %s" % (f, "compiles" if recorded else "rejects",
                                                   "accepts" if essl.get(f) else "rejects")
        if f in chrome and chrome[f] != recorded:
            line += "  (STALE: Chromium now %s)" % ("compiles" if chrome[f] else "rejects")
            bad += 1
        if essl.get(f) == recorded:
            line += "  FIXED"
            bad += 1
        else:
            line += "  STILL WRONG"
        print(line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
