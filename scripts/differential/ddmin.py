#!/usr/bin/env python3
"""Shrink a shader on which essl disagrees with Chromium, keeping the disagreement.

usage: ddmin.py FILE [-o OUT] [--mode essl-rejects|essl-accepts] [--glslang-error REGEX]
                [--verify]

essl-rejects (Chromium accepts, essl rejects): a candidate is kept while essl still rejects it
with the same first error (its message with numbers blanked) and no other error code, and
glslangValidator accepts it (unless --no-glslang): a cheap stand-in for "Chromium accepts".
essl-accepts (Chromium rejects, essl accepts): a candidate is kept while essl accepts it and
glslangValidator rejects it with an error matching REGEX (by default its first error, numbers
blanked); use this only where glslang agrees with Chromium.
Removes chunks of lines (halving the chunk size down to one line), then single statements and
lines' trailing parts, until nothing more can go. --verify asks Chromium about the result.
Standard library only.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
ESSL = os.path.join(ROOT, "target", "release", "essl")
# ../shared beside the repository.
ORACLE = os.path.join(ROOT, "..", "shared", "tools", "webgl2-oracle.py")


def norm(msg):
    msg = re.sub(r"\[\d+\]", "[N]", msg)
    msg = re.sub(r"`[^`]*`", "`X`", msg)
    msg = re.sub(r"\d+", "N", msg)
    return msg


def essl(path):
    p = subprocess.run([ESSL, "lint", "--format", "json", "--no-link", "--color", "never", path],
                       capture_output=True, text=True)
    for line in p.stdout.splitlines():
        o = json.loads(line)
        if o.get("kind") == "shader":
            errs = [d for d in o["diagnostics"] if d["severity"] == "error"]
            return o["ok"], errs
    return False, [{"code": "essl-crash", "message": p.stderr[-200:]}]


def glslang(path):
    p = subprocess.run(["glslangValidator", path], capture_output=True, text=True)
    errs = [l for l in p.stdout.splitlines() if l.startswith("ERROR:") and "compilation" not in l]
    return p.returncode == 0, errs


def chromium(path):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "o.json")
        subprocess.run([sys.executable, ORACLE, path, "-o", out], capture_output=True, text=True,
                       cwd=os.path.dirname(os.path.abspath(path)))
        with open(out) as fh:
            r = list(json.load(fh)["compile"].values())[0]
    return r["ok"], r["log"]


def match_brace(body, i):
    """Index of the line closing the block that line i opens, or None."""
    if not body[i].rstrip().endswith("{"):
        return None
    depth = 0
    for j in range(i, len(body)):
        depth += body[j].count("{") - body[j].count("}")
        if depth == 0:
            return j
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--out")
    ap.add_argument("--mode", choices=["essl-rejects", "essl-accepts"])
    ap.add_argument("--glslang-error")
    ap.add_argument("--verify", action="store_true")
    ap.add_argument("--no-glslang", action="store_true",
                    help="essl-rejects: do not also require glslang to accept (where glslang is wrong too)")
    a = ap.parse_args()
    with open(a.file) as fh:
        lines = fh.read().splitlines()
    ext = os.path.splitext(a.file)[1]
    ok, errs = essl(a.file)
    mode = a.mode or ("essl-accepts" if ok else "essl-rejects")
    tmpdir = tempfile.mkdtemp(prefix="ddmin-")
    cand_path = os.path.join(tmpdir, "cand" + ext)
    if mode == "essl-rejects":
        want_code, want_msg = errs[0]["code"], norm(errs[0]["message"])

        def interesting(ls):
            with open(cand_path, "w") as fh:
                fh.write("\n".join(ls) + "\n")
            ok, es = essl(cand_path)
            return (not ok and norm(es[0]["message"]) == want_msg
                    and all(e["code"] == want_code for e in es)
                    and (a.no_glslang or glslang(cand_path)[0]))
    else:
        g_ok, g_errs = glslang(a.file)
        pat = re.compile(a.glslang_error or re.escape(norm(g_errs[0].split(":", 3)[-1])).replace("N", r"\d+"))

        def interesting(ls):
            with open(cand_path, "w") as fh:
                fh.write("\n".join(ls) + "\n")
            if not essl(cand_path)[0]:
                return False
            g_ok, ge = glslang(cand_path)
            return not g_ok and any(pat.search(norm(e.split(":", 3)[-1])) or pat.search(e) for e in ge)

    if not interesting(lines):
        sys.exit("ddmin: the file does not show the disagreement to begin with")
    head, body = lines[:1], lines[1:]  # keep #version
    n = max(1, len(body) // 2)
    while n > 1:  # coarse: chunks of lines
        i = 0
        while i < len(body):
            trial = body[:i] + body[i + n:]
            if interesting(head + trial):
                body = trial
            else:
                i += n
        n //= 2
    changed = True
    while changed:  # fine: a line, a whole { } block, or a block's braces alone
        changed = False
        i = 0
        while i < len(body):
            end = match_brace(body, i)
            trials = []
            if end is not None:
                trials.append(body[:i] + body[end + 1:])
                if body[i].strip() == "{" or re.match(r"\s*(if|for|while|do|else)\b", body[i]):
                    trials.append(body[:i] + body[i + 1:end] + body[end + 1:])
            elif body[i].strip() not in ("}",) and not body[i].rstrip().endswith("{"):
                trials.append(body[:i] + body[i + 1:])
            for t in trials:
                if interesting(head + t):
                    body = t
                    changed = True
                    break
            else:
                i += 1
    # inside lines: drop `, name = init` declarators and else-branches' contents are already gone;
    # try cutting each line at its last top-level operator
    for k in range(len(body)):
        for cut in (r",\s*[A-Za-z_]\w*\s*;$", r"\s*[-+*/]\s*[^-+*/;]+;$"):
            trial_line = re.sub(cut, ";", body[k])
            if trial_line != body[k] and interesting(head + body[:k] + [trial_line] + body[k + 1:]):
                body[k] = trial_line
    result = "\n".join(head + body) + "\n"
    if a.out:
        with open(a.out, "w") as fh:
            fh.write(result)
    else:
        sys.stdout.write(result)
    if a.verify:
        with open(cand_path, "w") as fh:
            fh.write(result)
        cok, clog = chromium(cand_path)
        eok = essl(cand_path)[0]
        print("chromium %s, essl %s%s" % ("accepts" if cok else "rejects", "accepts" if eok else "rejects",
                                          (": " + clog.strip().splitlines()[0]) if clog.strip() else ""),
              file=sys.stderr)
        if cok == eok:
            sys.exit(1)


if __name__ == "__main__":
    main()
