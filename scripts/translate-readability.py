#!/usr/bin/env python3
"""How readable `essl translate`'s WGSL is, beside the glslang -> SPIR-V -> naga pipeline, on
the same shaders: the seeds' corrected programs (shaders-glsl/*.fixed.vert + .frag) and the
webgl2fundamentals shaders (../shared/corpora/webgl2fundamentals_shaders.jsonl).

Usage: scripts/translate-readability.py [--essl PATH] [--markdown]

For each set and each tool, over the shaders both tools translate (the same GLSL), and for
essl also over all it translates:
- lines: the WGSL's lines (all of them: code, comments, blank) and their ratio to the GLSL's;
- `let _eN`: lines that bind a temporary naga names `_eN` (machine output a reader must
  trace), and how many there are per 100 lines of WGSL;
- comments: the author's comment lines (each `//` line, each line of a `/* */`) whose text is
  in the WGSL.

essl: `essl translate` (the release binary, built if missing) on copies of the shaders, each
program linked as WebGL2 links it, each webgl2fundamentals shader on its own; default options.
The peer: `glslangValidator -V -R --amb --aml` (Debian's glslang-tools: SPIR-V for Vulkan with
the relaxed rules that accept loose uniforms, bindings and locations mapped automatically),
after rewriting `#version 300 es` to `#version 310 es` (glslang makes no SPIR-V from ES 3.00);
then naga's SPIR-V front end and WGSL writer (scripts/translate-readability/, naga 30.0.1 as
essl uses it). Each stage alone: the pipeline has no linking. essl's seeds are measured a
second time with `--module single` (one WGSL file per program).

Every WGSL file of every tool is then read back by naga's WGSL front end and validated
(`spv-to-wgsl --check`): the `valid` column. `fallback` (in the plain output) counts essl's
files that its own writer could not write (naga's writer wrote them, as their header says).
What the pipeline does not translate is listed on standard error with the first error.
"""
import argparse
import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared"
PEER = ROOT / "scripts" / "translate-readability"
LET_E = re.compile(r"^\s*let _e\d+\b")
FALLBACK = "Written by naga's WGSL writer"


def comment_lines(text):
    """The text of each comment line of a GLSL source (`//` lines, lines of `/* */`)."""
    out = []
    in_block = False
    for line in text.splitlines():
        rest = line
        if in_block:
            end = rest.find("*/")
            body = rest if end < 0 else rest[:end]
            body = body.strip().lstrip("*").strip()
            if body:
                out.append(body)
            if end < 0:
                continue
            in_block = False
            rest = rest[end + 2:]
        slash = rest.find("//")
        block = rest.find("/*")
        if slash >= 0 and (block < 0 or slash < block):
            body = rest[slash + 2:].strip()
            if body:
                out.append(body)
        elif block >= 0:
            after = rest[block + 2:]
            end = after.find("*/")
            body = (after if end < 0 else after[:end]).strip()
            if body:
                out.append(body)
            in_block = end < 0
    return out


def measure(pairs):
    """(glsl text, wgsl text) pairs -> figures."""
    glsl = sum(len(g.splitlines()) for g, _ in pairs)
    wgsl = sum(len(w.splitlines()) for _, w in pairs)
    lets = sum(sum(1 for l in w.splitlines() if LET_E.match(l)) for _, w in pairs)
    comments = [(c, w) for g, w in pairs for c in comment_lines(g)]
    kept = sum(1 for c, w in comments if c in w)
    return {
        "shaders": len(pairs),
        "glsl": glsl,
        "wgsl": wgsl,
        "ratio": wgsl / glsl if glsl else 0.0,
        "lets": lets,
        "lets_per_100": 100.0 * lets / wgsl if wgsl else 0.0,
        "comments": len(comments),
        "kept": kept,
        "fallback": sum(1 for _, w in pairs if FALLBACK in w),
    }


def seeds():
    """[(name, vertex text, fragment text)] of the seeds' corrected programs."""
    out = []
    for vert in sorted((ROOT / "shaders-glsl").glob("*.fixed.vert")):
        frag = vert.with_suffix(".frag")
        if frag.exists():
            out.append((vert.name[: -len(".vert")], vert.read_text(), frag.read_text()))
    return out


def fundamentals():
    """[(name, stage, text)] of the webgl2fundamentals shaders with a stage and no template."""
    out = []
    path = SHARED / "corpora" / "webgl2fundamentals_shaders.jsonl"
    for i, line in enumerate(path.read_text().splitlines()):
        case = json.loads(line)
        if case.get("stage") in ("vertex", "fragment") and not case.get("templated"):
            out.append((f"w2f-{i:03}", case["stage"], case["source"]))
    return out


def run_essl(essl, programs, shaders, tmp):
    """essl's WGSL: {(set, name, stage): (glsl, wgsl path)}."""
    src = tmp / "essl-in"
    dst = tmp / "essl-out"
    src.mkdir()
    for name, v, f in programs:
        (src / f"{name}.vert").write_text(v)
        (src / f"{name}.frag").write_text(f)
    for name, stage, text in shaders:
        ext = "vert" if stage == "vertex" else "frag"
        (src / f"{name}.{ext}").write_text(text)
    subprocess.run([str(essl), "translate", str(src), "-o", str(dst)], capture_output=True)
    out = {}
    for name, v, f in programs:
        for stage, text in (("vert", v), ("frag", f)):
            p = dst / f"{name}.{stage}.wgsl"
            if p.exists():
                out[("seeds", name, stage)] = (text, p)
    for name, stage, text in shaders:
        ext = "vert" if stage == "vertex" else "frag"
        p = dst / f"{name}.{ext}.wgsl"
        if p.exists():
            out[("w2f", name, ext)] = (text, p)
    return out


def run_essl_single(essl, programs, tmp):
    """essl's WGSL with `--module single`: {("seeds", name, "program"): (glsl, wgsl path)}."""
    src = tmp / "essl-in"
    dst = tmp / "essl-single"
    dst.mkdir()
    out = {}
    for name, v, f in programs:
        p = dst / f"{name}.wgsl"
        subprocess.run(
            [str(essl), "translate", str(src / f"{name}.vert"), str(src / f"{name}.frag"),
             "--module", "single", "-o", str(p)],
            capture_output=True,
        )
        if p.exists():
            glsl = (v if v.endswith("\n") else v + "\n") + f
            out[("seeds", name, "program")] = (glsl, p)
    return out


def check(tool, results):
    """{path: None or naga's error} for every WGSL file, through naga's WGSL front end."""
    paths = [str(p) for res in results.values() for _, p in res.values()]
    verdict = {}
    for i in range(0, len(paths), 200):
        r = subprocess.run([str(tool), "--check", *paths[i:i + 200]],
                           capture_output=True, text=True, check=True)
        for line in r.stdout.splitlines():
            if line.startswith("ok "):
                verdict[line[3:]] = None
            else:
                path, _, message = line[len("error "):].partition(": ")
                verdict[path] = message
    return verdict


def first_error(text):
    """The first line of a tool's output that names an error."""
    lines = [l for l in text.splitlines() if "error" in l.lower()] or text.splitlines() or [""]
    return lines[0].strip()


def run_peer(tool, programs, shaders, tmp, failed):
    """The glslang -> SPIR-V -> naga pipeline's WGSL files, keyed as run_essl's."""
    work = tmp / "peer"
    work.mkdir()
    jobs = []
    for name, v, f in programs:
        jobs.append((("seeds", name, "vert"), "vert", v))
        jobs.append((("seeds", name, "frag"), "frag", f))
    for name, stage, text in shaders:
        ext = "vert" if stage == "vertex" else "frag"
        jobs.append((("w2f", name, ext), ext, text))
    out = {}
    for key, ext, text in jobs:
        stem = work / f"{key[0]}-{key[1]}"
        glsl = stem.with_suffix("." + ext)
        glsl.write_text(re.sub(r"#version\s+300\s+es", "#version 310 es", text, count=1))
        spv = stem.with_suffix(f".{ext}.spv")
        r = subprocess.run(
            ["glslangValidator", "-V", "-R", "--amb", "--aml", str(glsl), "-o", str(spv)],
            capture_output=True,
        )
        if r.returncode != 0:
            failed.append((key, first_error(r.stdout + r.stderr)))
            continue
        r = subprocess.run([str(tool), str(spv)], capture_output=True, text=True)
        if r.returncode == 0:
            wgsl = stem.with_suffix(f".{ext}.wgsl")
            wgsl.write_text(r.stdout)
            out[key] = (text, wgsl)
        else:
            failed.append((key, first_error(r.stderr.replace(f"{spv}: ", ""))))
    return out


def build(essl):
    if essl is None:
        essl = ROOT / "target" / "release" / "essl"
        if not essl.exists():
            subprocess.run(["cargo", "build", "--release", "-p", "essl-cli"], cwd=ROOT, check=True)
    subprocess.run(["cargo", "build", "--release", "-q"], cwd=PEER, check=True)
    return pathlib.Path(essl), PEER / "target" / "release" / "spv-to-wgsl"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--essl", help="the essl binary (default: target/release/essl, built if missing)")
    ap.add_argument("--markdown", action="store_true", help="a table for docs/translate.md")
    args = ap.parse_args()
    if shutil.which("glslangValidator") is None:
        sys.exit("glslangValidator is missing: apt-get install glslang-tools")
    essl, tool = build(args.essl)
    programs, shaders = seeds(), fundamentals()
    inputs = {"seeds": 2 * len(programs), "w2f": len(shaders)}
    failed = []
    with tempfile.TemporaryDirectory() as t:
        tmp = pathlib.Path(t)
        results = {
            "essl translate": run_essl(essl, programs, shaders, tmp),
            "essl translate --module single": run_essl_single(essl, programs, tmp),
            "glslang -> SPIR-V -> naga": run_peer(tool, programs, shaders, tmp, failed),
        }
        verdict = check(tool, results)
        texts = {
            name: {k: (g, p.read_text(), verdict.get(str(p))) for k, (g, p) in res.items()}
            for name, res in results.items()
        }
    invalid = [(name, k, v[2]) for name, res in texts.items() for k, v in res.items() if v[2]]
    sets = {"seeds": "seeds' corrected shaders", "w2f": "webgl2fundamentals shaders"}
    # Each set over the shaders every tool translated, so that the tools read the same GLSL.
    common = {
        key: set.intersection(*(
            {k[1:] for k in res if k[0] == key}
            for name, res in texts.items() if not name.endswith("single")
        ))
        for key in sets
    }
    rows = []
    per_stage = ["essl translate", "glslang -> SPIR-V -> naga"]
    for key, label in sets.items():
        # (tool, over which shaders): first the shaders both translate, then all essl's.
        plan = [(name, "both translate") for name in per_stage]
        plan.append(("essl translate", "all"))
        if key == "seeds":
            plan.append(("essl translate --module single", "all"))
        for tool_name, over in plan:
            res = texts[tool_name]
            single = tool_name.endswith("single")
            chosen = [v for k, v in sorted(res.items()) if k[0] == key
                      and (over == "all" or k[1:] in common[key])]
            translated = sum(1 for k in res if k[0] == key)
            m = measure([(g, w) for g, w, _ in chosen])
            m["valid"] = sum(1 for _, _, v in chosen if v is None)
            m["translated"] = f"{translated}/{inputs[key] // 2 if single else inputs[key]}"
            m["over"] = over
            rows.append((label, tool_name, m))
    if args.markdown:
        print("| shaders | tool | translated | measured over | files | GLSL lines | WGSL lines | WGSL / GLSL "
              "| `let _eN` lines | per 100 WGSL lines | author's comment lines kept "
              "| valid WGSL (naga) |")
        print("|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for label, tool_name, m in rows:
            print(
                f"| {label} | {tool_name} | {m['translated']} | {m['over']} | {m['shaders']} "
                f"| {m['glsl']:,} "
                f"| {m['wgsl']:,} | {m['ratio']:.2f} | {m['lets']:,} | {m['lets_per_100']:.1f} | "
                f"{m['kept']}/{m['comments']} ({100.0 * m['kept'] / max(m['comments'], 1):.0f} %) "
                f"| {m['valid']}/{m['shaders']} |"
            )
    else:
        for label, tool_name, m in rows:
            print(f"{label:28} {tool_name:32} {m}")
    for key, message in failed:
        print(f"not translated by the pipeline: {'/'.join(key)}: {message}", file=sys.stderr)
    for name, key, message in invalid:
        print(f"invalid: {name} {'/'.join(key)}: {message}", file=sys.stderr)


if __name__ == "__main__":
    main()
