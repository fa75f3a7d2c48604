#!/usr/bin/env python3
"""Joins the lint findings on the real-world corpus with their hand classification and prints the
tables of docs/lints/corpus.md.

findings.jsonl: what `cargo run --release -p essl-lint --example lint-corpus -- CORPUS` prints
(one finding a line, then a summary line). triage.tsv: `rule<TAB>repository<TAB>line<TAB>source
line<TAB>class<TAB>why`, one line per distinct finding: the source line trimmed (white space
collapsed), and the line number where one text has findings of different classes (`*`
otherwise). The class is `real` (a hazard for inputs the program ordinarily passes),
`rounding` (only rounding reaches it), `input` (only some values the host passes reach it),
`spec` (undefined by the specification, computed the same by every driver: what
`smoothstep-reversed-constant` reports) or `fp` (no valid input reaches it). A finding with no
classification is listed and the script exits 1.

With --before BEFORE.jsonl (the findings of an earlier version on the same corpus), also lists
the findings classified `real` or `rounding` there that FINDINGS no longer reports (at the same
file, line and rule) and exits 1 if there is any.

With --hazards HAZARDS.tsv (hazards found by reading shaders, in the triage table's columns),
also prints how many of them FINDINGS reports (same rule, repository and source line), per
rule and in all, and lists the others. A `smoothstep-edges` hazard is reported by a
`smoothstep-reversed-constant` finding too: that rule takes the case of constant edges in
reversed order, which the readers' list of rules does not name. And a `mediump-overflow`
hazard on a line that stores or reads a variable is reported by that rule's note on the
variable's `lowp` declaration in the same file (the row's "why" begins with the file's path):
the hazard is the variable's precision, and readers name the line where a length enters it.

Usage: table.py FINDINGS.jsonl TRIAGE.tsv [--before BEFORE.jsonl] [--hazards HAZARDS.tsv]
"""

import collections
import json
import re
import sys

CLASSES = ["real", "rounding", "input", "spec", "fp"]

# The rules whose findings also report a hand-found hazard of another rule's id.
ALIASES = {"smoothstep-edges": ["smoothstep-reversed-constant"]}

# The message of a note on a variable declared `lowp` (essl-lint's lowp_range.rs).
LOWP = re.compile(r"^`(\w+)` is `lowp`, which need only hold")


def lowp_variables(findings):
    """(repository, file path, variable) of every note on a `lowp` declaration."""
    out = set()
    for f in findings:
        m = LOWP.match(f.get("message", ""))
        if f["rule"] == "mediump-overflow" and m and f.get("path"):
            out.add((f["repo"], f["path"], m.group(1)))
    return out


def lowp_hit(lowp, repo, text, why):
    """Whether a hand-found row's line stores or reads a variable a `lowp` note names."""
    return any(r == repo and why.startswith(path) and re.search(rf"\b{name}\b", text)
               for r, path, name in lowp)


def key(rule, repo, text):
    return (rule, repo, " ".join(text.split()))


def precision(t):
    """The share of findings that are not false positives."""
    n = t["findings"]
    return f"{100.0 * (n - t['fp']) / n:.1f} %" if n else "–"


def read(path):
    findings, summary = [], {}
    for line in open(path, encoding="utf-8"):
        row = json.loads(line)
        if row.get("kind") == "summary":
            summary = row
        else:
            findings.append(row)
    return findings, summary


def main():
    argv = sys.argv[1:]
    before = None
    if "--before" in argv:
        i = argv.index("--before")
        before = argv[i + 1]
        del argv[i : i + 2]
    hazards = None
    if "--hazards" in argv:
        i = argv.index("--hazards")
        hazards = argv[i + 1]
        del argv[i : i + 2]
    args = [a for a in argv if not a.startswith("--")]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    findings, summary = read(args[0])
    triage = {}
    for line in open(args[1], encoding="utf-8"):
        if not line.strip() or line.startswith("#"):
            continue
        rule, repo, at, text, cls, *_ = line.rstrip("\n").split("\t")
        if cls not in CLASSES:
            print(f"unknown class {cls!r} in: {line}", file=sys.stderr)
            return 2
        triage[key(rule, repo, text) + (at,)] = cls
    table = collections.defaultdict(collections.Counter)
    missing = set()
    lines = collections.defaultdict(set)
    for f in findings:
        k = key(f["rule"], f["repo"], f["text"])
        cls = triage.get(k + (str(f["line"]),), triage.get(k + ("*",)))
        if cls is None:
            missing.add(k)
            continue
        t = table[f["rule"]]
        t["findings"] += 1
        t[f["severity"]] += 1
        t[cls] += 1
        lines[f["rule"]].add(k)
    if missing:
        for m in sorted(missing):
            print("unclassified: " + "\t".join(m), file=sys.stderr)
        return 1
    print(f"{summary.get('shaders', 0)} shaders, {summary.get('compiled', 0)} compiled by essl, "
          f"from {summary.get('repositories', 0)} repositories")
    print()
    print("| rule | findings | warnings | notes | distinct lines | real | rounding-only | input-dependent | spec-only | false positives | precision |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    total = collections.Counter()
    distinct = 0
    for rule in sorted(table):
        t = table[rule]
        total.update(t)
        distinct += len(lines[rule])
        print(f"| {rule} | {t['findings']} | {t['warning']} | {t['note']} | {len(lines[rule])} | "
              f"{t['real']} | {t['rounding']} | {t['input']} | {t['spec']} | {t['fp']} | "
              f"{precision(t)} |")
    print(f"| **total** | **{total['findings']}** | **{total['warning']}** | **{total['note']}** | "
          f"**{distinct}** | **{total['real']}** | **{total['rounding']}** | **{total['input']}** | "
          f"**{total['spec']}** | **{total['fp']}** | **{precision(total)}** |")
    n = total["findings"]
    if n:
        print()
        print(f"False positives: {total['fp']} of {n} findings ({100.0 * total['fp'] / n:.1f} %).")
    if hazards:
        # A finding inside a macro's expansion reports the hazard on the `#define` it labels too.
        reported = {key(f["rule"], f["repo"], f["text"]) + (str(f["line"]),) for f in findings}
        reported |= {key(f["rule"], f["repo"], d["text"]) + (str(d["line"]),)
                     for f in findings for d in f.get("defined") or []}
        lowp = lowp_variables(findings)
        per_rule = collections.defaultdict(lambda: [0, 0])
        per_class = collections.defaultdict(lambda: [0, 0])
        missed = []
        for line in open(hazards, encoding="utf-8"):
            if not line.strip() or line.startswith("#"):
                continue
            rule, repo, at, text, cls, why, *_ = line.rstrip("\n").split("\t") + [""]
            ks = [key(r, repo, text) for r in [rule] + ALIASES.get(rule, [])]
            hit = any(r[:3] in ks and (at == "*" or r[3] == at) for r in reported)
            hit = hit or (rule == "mediump-overflow" and lowp_hit(lowp, repo, text, why))
            per_rule[rule][0] += hit
            per_rule[rule][1] += 1
            per_class[cls][0] += hit
            per_class[cls][1] += 1
            if not hit:
                missed.append(f"  [{rule}] {repo}: {text}")
        print()
        print("| rule | hand-found hazards | reported |")
        print("|---|---:|---:|")
        for rule in sorted(per_rule):
            hit, n = per_rule[rule]
            print(f"| {rule} | {n} | {hit} |")
        hit = sum(v[0] for v in per_rule.values())
        n = sum(v[1] for v in per_rule.values())
        print(f"| **total** | **{n}** | **{hit}** |")
        print()
        print(f"Recall on the hand-found hazards: {hit} of {n} ({100.0 * hit / max(n, 1):.1f} %).")
        print("By class: " + ", ".join(f"{c} {v[0]} of {v[1]}" for c, v in sorted(per_class.items())) + ".")
        for m in missed:
            print(m)
    if before:
        now = {(f["file"], f["line"], f["rule"]) for f in findings}
        lost = []
        for f in read(before)[0]:
            k = key(f["rule"], f["repo"], f["text"])
            cls = triage.get(k + (str(f["line"]),), triage.get(k + ("*",)))
            if cls in ("real", "rounding") and (f["file"], f["line"], f["rule"]) not in now:
                lost.append(f)
        hazard = ("real", "rounding", "input")
        def hazards(rows):
            out = set()
            for f in rows:
                k = key(f["rule"], f["repo"], f["text"])
                if triage.get(k + (str(f["line"]),), triage.get(k + ("*",))) in hazard:
                    out.add((f["file"], f["line"], f["rule"]))
            return out
        mine, theirs = hazards(findings), hazards(read(before)[0])
        both = mine | theirs
        print()
        print(f"Hazards (real, rounding-only, input-dependent) either version reports: {len(both)}; "
              f"this version {len(mine)} ({100.0 * len(mine) / max(len(both), 1):.1f} %), "
              f"{before} {len(theirs)} ({100.0 * len(theirs) / max(len(both), 1):.1f} %).")
        print()
        print(f"Real and rounding-only findings of {before} no longer reported: {len(lost)}.")
        for f in lost:
            print(f"  {f['file']}:{f['line']} [{f['rule']}] {f['text']}")
        if lost:
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
