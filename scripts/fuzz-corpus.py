#!/usr/bin/env python3
"""Seed the fuzzing corpora from the conformance corpora and the project's own shaders.

usage: scripts/fuzz-corpus.py [CORPORA_DIR] (default: $ESSL_CORPORA or ../shared/corpora)

Writes one file per shader into fuzz/corpus/compile/ (the `compile` target reads any bytes as a
shader) and one file per program into fuzz/corpus/link/ (vertex source, a NUL byte, fragment
source: what the `link` target splits). Both folders are ignored by git. Sources are taken as
written: the targets add a `#version 300 es` line of their own, so a leading one is removed
to keep inputs short.
"""
import glob, hashlib, json, os, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
corpora = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("ESSL_CORPORA", os.path.join(ROOT, "..", "shared", "corpora"))
out_compile = os.path.join(ROOT, "fuzz", "corpus", "compile")
out_link = os.path.join(ROOT, "fuzz", "corpus", "link")
os.makedirs(out_compile, exist_ok=True)
os.makedirs(out_link, exist_ok=True)


def strip_version(src):
    lines = src.split("\n", 1)
    return lines[1] if lines[0].startswith("#version") and len(lines) > 1 else src


def write(folder, data):
    data = data.encode("utf-8")
    name = hashlib.sha1(data).hexdigest()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


shaders = programs = 0
for path in sorted(glob.glob(os.path.join(corpora, "*.jsonl"))):
    for line in open(path, encoding="utf-8"):
        case = json.loads(line)
        vs = case.get("vertex_source") or (case.get("source") if case.get("stage") == "vertex" else None)
        fs = case.get("fragment_source") or (case.get("source") if case.get("stage") == "fragment" else None)
        for src in (vs, fs):
            if src:
                write(out_compile, strip_version(src))
                shaders += 1
        if vs and fs:
            write(out_link, strip_version(vs) + "\0" + strip_version(fs))
            programs += 1
for path in sorted(glob.glob(os.path.join(ROOT, "shaders-glsl", "*.*"))):
    if path.endswith((".vert", ".frag")):
        write(out_compile, strip_version(open(path, encoding="utf-8").read()))
        shaders += 1
print(f"{shaders} shaders -> {out_compile} ({len(os.listdir(out_compile))} distinct)")
print(f"{programs} programs -> {out_link} ({len(os.listdir(out_link))} distinct)")
