#!/usr/bin/env python3
"""Differential test: essl against glslangValidator on generated GLSL ES 3.00 shaders,
with Chromium's WebGL2 (ANGLE) as the referee.

usage: run.py --count N --seed S [--workers 2] [--out DIR] [--check-agreements F]

Generates N shaders (gen.py) into a temporary folder, runs `essl lint --format json
--no-link` and `glslangValidator` on each (WORKERS processes), asks Chromium
(tools/webgl2-oracle.py, batched) about every shader where the two differ (and about a
fraction F of the others, to find shaders both tools get wrong), classifies each case and
writes OUT/report.json; every shader where essl disagrees with Chromium is copied to
OUT/essl-wrong/. Standard library only.
"""
import argparse
import collections
import concurrent.futures as cf
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gen  # noqa: E402
import known_glslang_differences as known  # noqa: E402

ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
DEFAULT_ESSL = os.path.join(ROOT, "target", "release", "essl")
# ../shared beside the repository.
DEFAULT_ORACLE = os.path.join(ROOT, "..", "shared", "tools", "webgl2-oracle.py")


def essl_check(essl, files):
    """{basename: (ok, [error codes], [error messages])} for a batch of files."""
    p = subprocess.run([essl, "lint", "--format", "json", "--no-link", "--color", "never", *files],
                       capture_output=True, text=True, timeout=600)
    res = {}
    for line in p.stdout.splitlines():
        try:
            o = json.loads(line)
        except ValueError:
            continue
        if o.get("kind") == "shader":
            errs = [d for d in o["diagnostics"] if d.get("severity") == "error"]
            res[os.path.basename(o["file"])] = (bool(o["ok"]), [d["code"] for d in errs],
                                                ["%s:%s %s" % (d.get("line"), d["code"], d["message"])
                                                 for d in errs][:5])
    for f in files:  # a crash or a missing line is an answer too
        res.setdefault(os.path.basename(f), (False, ["essl-crash"], [p.stderr[-300:]]))
    return res


def glslang_check(path):
    try:
        p = subprocess.run(["glslangValidator", path], capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return False, ["timeout"]
    errs = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("ERROR:")
            and "compilation terminated" not in l and "compilation errors" not in l]
    return p.returncode == 0, errs[:5]


def work_chunk(args):
    seed, indices, folder, essl, rate = args
    files, meta = [], {}
    for i in indices:
        path, muts = gen.write(seed, i, folder, rate)
        files.append(path)
        meta[os.path.basename(path)] = muts
    t0 = time.time()
    es = essl_check(essl, files)
    t1 = time.time()
    out = []
    for f in files:
        b = os.path.basename(f)
        gok, glog = glslang_check(f)
        out.append({"file": b, "index": int(b.split("_")[1].split(".")[0]), "stage": b.rsplit(".", 1)[1],
                    "mutations": meta[b], "essl_ok": es[b][0], "essl_codes": es[b][1], "essl_log": es[b][2],
                    "glslang_ok": gok, "glslang_log": glog})
    return out, t1 - t0, time.time() - t1


def ask_chromium(oracle, folder, names, batch):
    res = {}
    for k in range(0, len(names), batch):
        part = names[k:k + batch]
        with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as tf:
            outp = tf.name
        for attempt in range(3):
            p = subprocess.run([sys.executable, oracle, *part, "-o", outp], cwd=folder,
                               capture_output=True, text=True, timeout=900)
            if p.returncode == 0:
                break
            time.sleep(2)
        else:
            raise SystemExit("webgl2-oracle failed: " + p.stderr[-500:])
        with open(outp) as fh:
            d = json.load(fh)
        os.unlink(outp)
        for name, r in d["compile"].items():
            res[os.path.basename(name)] = (bool(r["ok"]), r["log"] or "")
        print("  chromium: %d/%d" % (min(k + batch, len(names)), len(names)), file=sys.stderr, flush=True)
    return res


def signature(c):
    """A short, number-free description of why essl and Chromium differ on a case."""
    import re
    if c["chromium_ok"]:
        m = c["essl_log"][0] if c["essl_log"] else "?"
        m = m.split(" ", 1)[-1]
    else:
        m = next((l for l in c["chromium_log"].splitlines() if l.startswith("ERROR")), "?")
        m = re.sub(r"ERROR: \d+:\d+: ", "", m)
    m = re.sub(r"\[\d+\]", "[N]", m)
    m = re.sub(r"Function \[N\] '\w+' is invalid: ", "", m)
    m = re.sub(r"`\w+`|'\w*\d\w*'", "X", m)
    return ("chromium accepts, essl: " if c["chromium_ok"] else "chromium rejects, essl accepts: ") + m[:150]


def classify(records, work, seed, rate, out):
    """Classes of every record, counts of the known rules that matched, and the cases
    (records Chromium was asked about where at least one tool disagrees with it)."""
    classes, rule_counts, cases = collections.Counter(), collections.Counter(), []
    wrong_dir = os.path.join(out, "essl-wrong")
    os.makedirs(wrong_dir, exist_ok=True)
    for r in records:
        agree = r["essl_ok"] == r["glslang_ok"]
        if agree:
            classes["both accept" if r["essl_ok"] else "both reject"] += 1
        if "chromium_ok" not in r:
            continue
        cok = r["chromium_ok"]
        ew, gw = r["essl_ok"] != cok, r["glslang_ok"] != cok
        if agree and not ew:
            classes["agreement confirmed by chromium"] += 1
            continue
        path = os.path.join(work, r["file"])
        if os.path.exists(path):
            with open(path) as fh:
                src = fh.read()
        else:
            src = gen.generate(seed, r["index"], rate)[1]
        r.pop("known_rule", None)
        if ew and gw:
            cls = "both wrong"
        elif ew:
            cls = "essl wrong"
        else:
            rule = known.match(src, r["glslang_log"], r["chromium_log"], r["glslang_ok"], r["stage"])
            r["known_rule"] = rule
            if rule:
                rule_counts[rule] += 1
                cls = "glslang wrong (known)"
            else:
                cls = "glslang wrong (unexplained)"
        r["class"] = cls
        classes[cls] += 1
        if ew:
            with open(os.path.join(wrong_dir, r["file"]), "w") as fh:
                fh.write(src)
        cases.append(r)
    return classes, rule_counts, cases


def reclassify(a):
    out = os.path.dirname(os.path.abspath(a.reclassify))
    with open(a.reclassify) as fh:
        report = json.load(fh)
    with open(os.path.join(out, "records.jsonl")) as fh:
        records = [json.loads(l) for l in fh]
    classes, rule_counts, cases = classify(records, a.work or "/nonexistent", report["seed"],
                                           report["mutate_rate"], out)
    report.update(classes=dict(classes), known_rules=dict(rule_counts), cases=cases,
                  essl_wrong=[c["file"] for c in cases if c["class"] in ("essl wrong", "both wrong")])
    with open(a.reclassify, "w") as fh:
        json.dump(report, fh, indent=1)
    summary(report, out)
    return 0


def git_head():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                              text=True).stdout.strip()
    except OSError:
        return "?"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=1000)
    ap.add_argument("--seed", default="1")
    ap.add_argument("--start", type=int, default=0, help="first shader index")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--chunk", type=int, default=100, help="shaders per essl invocation")
    ap.add_argument("--mutate-rate", type=float, default=0.35)
    ap.add_argument("--check-agreements", type=float, default=0.0,
                    help="fraction of agreeing shaders also sent to Chromium (finds 'both wrong')")
    ap.add_argument("--oracle-batch", type=int, default=500)
    ap.add_argument("--essl", default=DEFAULT_ESSL)
    ap.add_argument("--oracle", default=DEFAULT_ORACLE)
    ap.add_argument("--out", default="differential-out", help="folder for report.json and essl-wrong/")
    ap.add_argument("--work", help="folder for the generated shaders (default: a temporary one, removed)")
    ap.add_argument("--reclassify", metavar="REPORT", help="classify an earlier run's records.jsonl again "
                    "with the current rules (sources from --work, else regenerated) and rewrite its report")
    a = ap.parse_args()
    if a.reclassify:
        return reclassify(a)

    os.makedirs(a.out, exist_ok=True)
    commit = git_head()  # read now: the tree may move during a long run
    essl_built = time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime(os.stat(a.essl).st_mtime))
    work = a.work or tempfile.mkdtemp(prefix="essl-diff-")
    os.makedirs(work, exist_ok=True)
    t_start = time.time()
    idx = list(range(a.start, a.start + a.count))
    chunks = [(a.seed, idx[k:k + a.chunk], work, a.essl, a.mutate_rate) for k in range(0, len(idx), a.chunk)]
    records, t_essl, t_glslang = [], 0.0, 0.0
    with cf.ProcessPoolExecutor(a.workers) as ex:
        for out, te, tg in ex.map(work_chunk, chunks):
            records.extend(out)
            t_essl += te
            t_glslang += tg
            if len(records) % (a.chunk * 20) == 0:
                el = time.time() - t_start
                print("  checked %d/%d (%.1f shaders/s)" % (len(records), a.count, len(records) / el),
                      file=sys.stderr, flush=True)
    t_checked = time.time()

    with open(os.path.join(a.out, "records.jsonl"), "w") as fh:  # kept should Chromium fail
        fh.writelines(json.dumps(r) + "\n" for r in records)
    rng = random.Random("agree:%s" % a.seed)
    ask = [r["file"] for r in records if r["essl_ok"] != r["glslang_ok"] or rng.random() < a.check_agreements]
    chrome = ask_chromium(a.oracle, work, ask, a.oracle_batch) if ask else {}
    t_oracle = time.time()

    with open(os.path.join(a.out, "records.jsonl"), "w") as fh:
        for r in records:
            if r["file"] in chrome:
                r["chromium_ok"], r["chromium_log"] = chrome[r["file"]][0], chrome[r["file"]][1][:3000]
            fh.write(json.dumps(r) + "\n")
    classes, rule_counts, cases = classify(records, work, a.seed, a.mutate_rate, a.out)
    total = len(records)
    elapsed = time.time() - t_start
    report = {
        "commit": commit, "essl_binary_built": essl_built, "seed": a.seed, "start": a.start, "count": total,
        "mutate_rate": a.mutate_rate, "check_agreements": a.check_agreements,
        "seconds": {"total": round(elapsed, 1), "generate_and_check": round(t_checked - t_start, 1),
                    "chromium": round(t_oracle - t_checked, 1), "essl_cpu": round(t_essl, 1),
                    "glslang_cpu": round(t_glslang, 1)},
        "rate_shaders_per_s": round(total / max(t_checked - t_start, 1e-9), 2),
        "mutated": sum(1 for r in records if r["mutations"]),
        "disagreements": sum(1 for r in records if r["essl_ok"] != r["glslang_ok"]),
        "asked_chromium": len(ask),
        "classes": dict(classes), "known_rules": dict(rule_counts),
        "essl_wrong": [c["file"] for c in cases if c["class"] in ("essl wrong", "both wrong")],
        "cases": cases,
    }
    with open(os.path.join(a.out, "report.json"), "w") as fh:
        json.dump(report, fh, indent=1)
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)
    summary(report, a.out)
    return 0


def summary(report, out):
    classes, rule_counts, cases = report["classes"], collections.Counter(report["known_rules"]), report["cases"]
    total = report["count"]
    wrong_dir = os.path.join(out, "essl-wrong")
    t = report["seconds"]
    print("essl differential run: seed %s, commit %s" % (report["seed"], report["commit"]))
    print("generated %d shaders (%d mutated) in %.0f s: %.1f shaders/s; chromium %.0f s for %d shaders"
          % (total, report["mutated"], t["generate_and_check"], report["rate_shaders_per_s"],
             t["chromium"], report["asked_chromium"]))
    print("both accept %d, both reject %d, disagree %d (%.2f%%)" % (
        classes.get("both accept", 0), classes.get("both reject", 0), report["disagreements"],
        100.0 * report["disagreements"] / max(total, 1)))
    for c in ("essl wrong", "glslang wrong (known)", "glslang wrong (unexplained)", "both wrong"):
        print("  %-28s %d" % (c, classes.get(c, 0)))
    for rule, n in rule_counts.most_common():
        print("    known: %-32s %d" % (rule, n))
    un = [c for c in cases if c["class"] == "glslang wrong (unexplained)"]
    for c in un[:20]:
        print("  unexplained glslang: %s glslang=%s %s | chromium: %s" % (
            c["file"], c["glslang_ok"], (c["glslang_log"] or [""])[0][:100],
            c["chromium_log"].splitlines()[0][:100] if c["chromium_log"] else ""))
    sig = collections.Counter(signature(c) for c in cases if c["class"] in ("essl wrong", "both wrong"))
    print("essl-wrong cases by signature (chromium verdict / essl's first error or chromium's):")
    for s, n in sig.most_common():
        print("  %5d  %s" % (n, s))
    for c in cases:
        if c["class"] in ("essl wrong", "both wrong"):
            print("  ESSL WRONG [%s] %s: chromium %s, essl %s %s" % (
                c["class"], os.path.join(wrong_dir, c["file"]), "accepts" if c["chromium_ok"] else "rejects",
                "accepts" if c["essl_ok"] else "rejects", (c["essl_log"] or [""])[0][:120]
                if not c["essl_ok"] else c["chromium_log"].splitlines()[0][:120]))


if __name__ == "__main__":
    sys.exit(main())
