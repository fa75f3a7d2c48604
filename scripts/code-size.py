#!/usr/bin/env python3
"""Report the functions and files of the workspace that are too large to read in one sitting.

Usage: scripts/code-size.py [--fn-limit N] [--file-limit N] [--all]

A function's length is counted from its `fn` line to its closing brace. A file's length
excludes a trailing `#[cfg(test)] mod tests { ... }` block, which is counted separately.
Files named in TABLES hold tables of data and are reported but not counted against the limit.
Exit status 1 when something is over a limit, so the script can gate CI if wanted.
"""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FN = re.compile(r"^\s*(pub(\([^)]*\))?\s+)?(const\s+)?(unsafe\s+)?fn\s+(\w+)")
TABLES = set()


def strip(line, state):
    """The line without string literals and comments; `state` carries block comments and
    string literals (plain or raw) that run over several lines."""
    out = []
    i = 0
    while i < len(line):
        if state["block"]:
            end = line.find("*/", i)
            if end < 0:
                return "".join(out)
            state["block"] = False
            i = end + 2
            continue
        if state["str"] is not None:
            close = state["str"]
            if close == '"':
                j = i
                while j < len(line) and line[j] != '"':
                    j += 2 if line[j] == "\\" else 1
                if j >= len(line):
                    return "".join(out)
                i = j + 1
            else:
                end = line.find(close, i)
                if end < 0:
                    return "".join(out)
                i = end + len(close)
            state["str"] = None
            continue
        c = line[i]
        if line.startswith("//", i):
            break
        if line.startswith("/*", i):
            state["block"] = True
            i += 2
            continue
        raw = re.match(r'b?r(#*)"', line[i:])
        if raw and (i == 0 or not (line[i - 1].isalnum() or line[i - 1] == "_")):
            state["str"] = '"' + raw.group(1)
            i += raw.end()
            continue
        if c == '"':
            state["str"] = '"'
            i += 1
            continue
        if c == "'" and i + 2 < len(line) and (line[i + 2] == "'" or line[i + 1] == "\\"):
            j = line.find("'", i + 2)
            i = (j + 1) if j > 0 else i + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)


def measure(path):
    lines = path.read_text().splitlines()
    state = {"block": False, "str": None}
    clean = [strip(line, state) for line in lines]
    test_start = None
    for i, line in enumerate(lines):
        if line.strip() == "#[cfg(test)]" and i + 1 < len(lines) and lines[i + 1].startswith("mod tests"):
            test_start = i
            break
    fns = []
    for i, line in enumerate(clean):
        m = FN.match(line)
        if not m or (test_start is not None and i >= test_start):
            continue
        depth = 0
        opened = False
        for j in range(i, len(clean)):
            if not opened and clean[j].rstrip().endswith(";"):
                break
            depth += clean[j].count("{") - clean[j].count("}")
            opened = opened or "{" in clean[j]
            if opened and depth <= 0:
                fns.append((j - i + 1, m.group(5), i + 1))
                break
    code = test_start if test_start is not None else len(lines)
    return code, len(lines) - code, fns


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--fn-limit", type=int, default=150)
    ap.add_argument("--file-limit", type=int, default=800)
    ap.add_argument("--all", action="store_true", help="list every file and function")
    args = ap.parse_args()
    over = 0
    for path in sorted(ROOT.glob("crates/*/src/**/*.rs")):
        rel = path.relative_to(ROOT)
        code, tests, fns = measure(path)
        if code > args.file_limit or args.all:
            table = " (table)" if str(rel) in TABLES else ""
            print(f"file {code:5} {rel}{table}  (+{tests} test lines)")
            over += code > args.file_limit and not table
        for n, name, line in sorted(fns, reverse=True):
            if n > args.fn_limit or args.all:
                print(f"  fn {n:5} {rel}:{line} {name}")
                over += n > args.fn_limit
    print(f"{over} over the limits (functions {args.fn_limit} lines, files {args.file_limit})")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
