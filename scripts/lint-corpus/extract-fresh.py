#!/usr/bin/env python3
"""Extracts the fresh lint corpus (docs/lints/corpus.md, "The fresh corpus") from npm packages
unpacked by fetch-fresh.sh: whole shaders, assembled the way each library's runtime assembles
them, and lygia's library files with a generated `main` that calls each function.

Per package (NPM/<name>-<version>/package):

- lygia: every `.glsl` file with its `#include`s expanded (relative paths, each file once), as
  a `#version 300 es` fragment shader whose `main` calls every function the file defines, with
  each parameter read from an input (`in`), a uniform for matrices, structs and samplers;
  `out` and `inout` arguments are locals initialised from inputs. Library files are counted as
  shaders of their own (`kind: library` in the manifest).
- @babylonjs/*: every shader of `Shaders/*.js` (GLSL ES 1.00, minified by the package) with
  `#include<name>` expanded from `Shaders/ShadersInclude` (`[0..maxSimultaneousLights]` as
  lights 0 to 3, `(a,b)` replacements, `__decl__X` as `XDeclaration`), no defines set, and
  re-flowed one statement a line so that findings have lines to point at.
- @cesium/engine: every `Source/Shaders/**/*.glsl` with a `main`, with the `czm_` functions,
  constants and structs it uses (recursively) and the automatic uniforms it reads declared
  (types from `Source/Renderer/AutomaticUniforms.js`), the `czm_batchTable_*` functions
  `BatchTable.js` generates for the per-instance attributes it calls, `out vec4 out_FragColor`
  for fragment shaders, as `#version 300 es`.
- maplibre-gl: every `src/shaders/glsl/*.glsl` pair, prelude and Mercator projection prelude
  first, `#pragma maplibre` expanded to the attribute-driven variant (as `shaders.ts` does).
- Any other package: every JavaScript string literal (template, or quoted with `\\n` escapes,
  `+`-joined pieces included) and `.glsl`/`.vert`/`.frag` file that holds a whole shader (a
  `main` and a stage's output), without `${...}` interpolation; pixi's filters get the
  `#version 300 es` and precision lines pixi adds.

Texts the same after collapsing white space are kept once, and so are texts the old corpus
(OLD/manifest.jsonl) already holds. Writes OUT/shaders/<package>/NNNN-<path>.{vert,frag} and
OUT/manifest.jsonl (`file, repo, commit, path, stage, kind`).

Usage: extract-fresh.py --npm NPM --out OUT [--old OLD_CORPUS]
"""

import argparse
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from fresh_assemble import (  # noqa: E402
    babylon_shaders,
    cesium_shaders,
    generic_shaders,
    lygia_shaders,
    maplibre_shaders,
)


def normalise(text):
    return " ".join(text.split())


def known_texts(old):
    out = set()
    manifest = os.path.join(old, "manifest.jsonl") if old else None
    if not manifest or not os.path.exists(manifest):
        return out
    for line in open(manifest, encoding="utf-8"):
        row = json.loads(line)
        try:
            out.add(normalise(open(os.path.join(old, row["file"]), encoding="utf-8").read()))
        except OSError:
            pass
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--npm", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--old")
    a = ap.parse_args()
    seen = known_texts(a.old)
    skipped_known = 0
    os.makedirs(os.path.join(a.out, "shaders"), exist_ok=True)
    rows = []
    for entry in sorted(os.listdir(a.npm)):
        root = os.path.join(a.npm, entry, "package")
        pj = os.path.join(root, "package.json")
        if not os.path.exists(pj):
            continue
        meta = json.load(open(pj, encoding="utf-8"))
        name, version = meta["name"], meta["version"]
        if name == "lygia":
            shaders = lygia_shaders(root)
        elif name.startswith("@babylonjs/"):
            shaders = babylon_shaders(root, a.npm)
        elif name in ("@cesium/engine", "cesium"):
            shaders = cesium_shaders(root)
        elif name == "maplibre-gl":
            shaders = maplibre_shaders(root)
        else:
            shaders = generic_shaders(root, pixi=name == "pixi-filters")
        folder = name.replace("/", "__").replace("@", "")
        n = 0
        for path, stage, kind, text in shaders:
            key = normalise(text)
            if key in seen:
                skipped_known += 1
                continue
            seen.add(key)
            n += 1
            safe = re.sub(r"[^A-Za-z0-9._-]+", "_", path)[-120:]
            ext = "vert" if stage == "vertex" else "frag"
            rel = f"shaders/{folder}/{n:04d}-{safe}.{ext}"
            os.makedirs(os.path.join(a.out, "shaders", folder), exist_ok=True)
            with open(os.path.join(a.out, rel), "w", encoding="utf-8") as f:
                f.write(text)
            rows.append(
                {
                    "file": rel,
                    "repo": f"npm:{name}",
                    "commit": f"npm {name}@{version}",
                    "path": path,
                    "stage": stage,
                    "kind": kind,
                }
            )
        print(f"{name}@{version}: {n} shaders", file=sys.stderr)
    with open(os.path.join(a.out, "manifest.jsonl"), "w", encoding="utf-8") as m:
        for r in rows:
            m.write(json.dumps(r) + "\n")
    print(f"{len(rows)} shaders ({skipped_known} already in the old corpus or seen)", file=sys.stderr)


if __name__ == "__main__":
    main()
