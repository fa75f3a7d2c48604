#!/usr/bin/env python3
"""Regenerate tests/oracle/webgl2fundamentals.json: what WebGL2 (headless Chromium, ANGLE on
SwiftShader) says about the webgl2fundamentals corpus.

Run from the repository root:  python3 tests/oracle/make_webgl2fundamentals.py
Reads ../shared/corpora/webgl2fundamentals_shaders.jsonl and runs
../shared/tools/webgl2-oracle.py (needs Debian's `chromium`).

Shaders: every corpus line with a stage (`vertex`/`fragment`) and `templated: false` is
compiled on its own; keys are corpus line indices (0-based). Lines without a stage (7) and
templated ones (3) are skipped and listed under "skipped".

Programs (pairing rule): a corpus `file` holds its shaders in page order, but not always as
alternating vertex/fragment (e.g. two vertex shaders then three fragment shaders, a fragment
shader shared by several vertex shaders, a fragment shader listed before its vertex shader).
So each vertex shader V is paired with ONE fragment shader F of the same file, chosen as:
  candidates = fragment shaders of the same file whose `in` variable names are all among V's
               `out` variable names (names only, from the declarations; comments stripped);
  F = the first candidate after V in corpus order, else the last candidate before V.
A vertex shader with no candidate stays unpaired (listed under "unpaired_vertex"). Then each
fragment shader that no vertex shader picked is paired with the nearest vertex shader of the
same file (earlier ones first, then later ones) whose `out` names cover its `in` names
(programs with "rule": "fragment"; the first pass gives "rule": "vertex"); fragment shaders
still left are listed under "unpaired_fragment". Only names are matched, so type/qualifier
mismatches still show up as link failures. Programs are listed sorted by (vertex, fragment).
"""
import json, os, re, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS = os.path.join(ROOT, "..", "shared", "corpora", "webgl2fundamentals_shaders.jsonl")
ORACLE = os.path.join(ROOT, "..", "shared", "tools", "webgl2-oracle.py")
OUT = os.path.join(ROOT, "tests", "oracle", "webgl2fundamentals.json")
EXT = {"vertex": ".vert", "fragment": ".frag"}


def strip_comments(src):
    src = re.sub(r"/\*.*?\*/", " ", src, flags=re.S)
    return re.sub(r"//[^\n]*", "", src)


def io_names(src, qual):
    """Names declared with storage qualifier `qual` ('in' or 'out') at global scope."""
    names = set()
    for m in re.finditer(r"^[ \t]*((?:layout\s*\([^)]*\)\s*)?(?:\w+\s+)*?)\b%s\s+([^;{]*);" % qual,
                         strip_comments(src), flags=re.M):
        decl = m.group(2)
        decl = re.sub(r"\[[^\]]*\]", "", decl)
        parts = decl.split()
        # drop precision/type words; remaining comma-separated names
        rest = " ".join(parts[1:]) if parts else ""
        if parts and parts[0] in ("lowp", "mediump", "highp"):
            rest = " ".join(parts[2:])
        names.update(n.strip() for n in rest.split(",") if n.strip())
    return names


def slug(s):
    return re.sub(r"[^a-z0-9]+", "-", os.path.basename(s).lower()).strip("-")[:60]


def main():
    rows = [json.loads(l) for l in open(CORPUS, encoding="utf-8")]
    use, skipped = {}, {}
    for i, r in enumerate(rows):
        if r.get("templated"):
            skipped[str(i)] = "templated"
        elif r.get("stage") not in EXT:
            skipped[str(i)] = "no stage"
        else:
            use[i] = r
    # pairing
    pairs, picked = [], set()
    by_file = {}
    for i, r in use.items():
        by_file.setdefault(r["file"], []).append(i)
    unpaired_v = []
    for i, r in use.items():
        if r["stage"] != "vertex":
            continue
        outs = io_names(r["source"], "out")
        frags = [j for j in by_file[r["file"]] if use[j]["stage"] == "fragment"
                 and io_names(use[j]["source"], "in") <= outs]
        after = [j for j in frags if j > i]
        before = [j for j in frags if j < i]
        f = after[0] if after else (before[-1] if before else None)
        if f is None:
            unpaired_v.append(i)
        else:
            pairs.append((i, f, "vertex"))
            picked.add(f)
    unpaired_f = []
    for j, r in use.items():
        if r["stage"] != "fragment" or j in picked:
            continue
        ins = io_names(r["source"], "in")
        verts = [i for i in by_file[r["file"]] if use[i]["stage"] == "vertex"
                 and ins <= io_names(use[i]["source"], "out")]
        before = [i for i in verts if i < j]
        after = [i for i in verts if i > j]
        v = before[-1] if before else (after[0] if after else None)
        if v is None:
            unpaired_f.append(j)
        else:
            pairs.append((v, j, "fragment"))
    pairs.sort()

    with tempfile.TemporaryDirectory() as tmp:
        sdir, pdir = os.path.join(tmp, "shaders"), os.path.join(tmp, "programs")
        os.makedirs(sdir), os.makedirs(pdir)
        names = {}
        for i, r in use.items():
            # a stage-specific suffix keeps single shaders from pairing up by name
            n = "%03d-%s-%s%s" % (i, slug(r["file"]), r["stage"][0], EXT[r["stage"]])
            names[i] = n
            with open(os.path.join(sdir, n), "w", encoding="utf-8") as fh:
                fh.write(r["source"])
        for v, f, _ in pairs:
            for i in (v, f):
                with open(os.path.join(pdir, "%03d-%03d%s" % (v, f, EXT[use[i]["stage"]])), "w",
                          encoding="utf-8") as fh:
                    fh.write(use[i]["source"])
        res = {}
        for d in (sdir, pdir):
            o = os.path.join(tmp, os.path.basename(d) + ".json")
            subprocess.run([sys.executable, ORACLE, d, "-o", o], check=True, cwd=tmp)
            res[os.path.basename(d)] = json.load(open(o))
    comp = {os.path.basename(k): v for k, v in res["shaders"]["compile"].items()}
    link = {os.path.basename(k): v for k, v in res["programs"]["link"].items()}
    out = {
        "source": "gfxfundamentals/webgl2-fundamentals e6e08aa via ../shared/corpora/webgl2fundamentals_shaders.jsonl",
        "renderer": res["shaders"]["renderer"],
        "pairing_rule": "rule 'vertex': each vertex shader with the first later fragment shader of the same "
                        "file whose `in` names are all among the vertex shader's `out` names, else the last "
                        "earlier such one; rule 'fragment': each fragment shader left over with the nearest "
                        "such vertex shader of its file (earlier first); see make_webgl2fundamentals.py",
        "shaders": {str(i): {"stage": use[i]["stage"], "ok": comp[names[i]]["ok"], "log": comp[names[i]]["log"]}
                    for i in sorted(use)},
        "programs": [],
        "skipped": skipped,
        "unpaired_vertex": unpaired_v,
        "unpaired_fragment": unpaired_f,
    }
    for v, f, rule in pairs:
        l = link["%03d-%03d" % (v, f)]
        p = {"vertex": v, "fragment": f, "file": use[v]["file"], "rule": rule, "ok": l["ok"], "log": l["log"]}
        if l["ok"]:
            p["uniforms"], p["attributes"] = l["uniforms"], l["attributes"]
        out["programs"].append(p)
    with open(OUT, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    n_ok = sum(s["ok"] for s in out["shaders"].values())
    p_ok = sum(p["ok"] for p in out["programs"])
    print("shaders: %d/%d compile; programs: %d/%d link; unpaired vertex %d, fragment %d" % (
        n_ok, len(out["shaders"]), p_ok, len(out["programs"]), len(unpaired_v), len(unpaired_f)))


if __name__ == "__main__":
    main()
