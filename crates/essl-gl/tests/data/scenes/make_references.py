#!/usr/bin/env python3
"""Renders every scene of this folder in Chromium with ../../../../../../shared/tools/webgl2-render.py
(or $WEBGL2_RENDER) and writes reference/<name>.png and expected.json (the tool's warnings,
compile and link logs per scene), which tests/it/scenes.rs compares essl-gl against.

usage: python3 make_references.py
"""
import glob, json, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.environ.get("WEBGL2_RENDER", os.path.join(HERE, "../../../../../../shared/tools/webgl2-render.py"))

expected = {}
os.makedirs(os.path.join(HERE, "reference"), exist_ok=True)
for scene in sorted(glob.glob(os.path.join(HERE, "*.json"))):
    name = os.path.splitext(os.path.basename(scene))[0]
    if name == "expected":
        continue
    out = subprocess.run([sys.executable, TOOL, scene, "-o", os.path.join(HERE, "reference", name + ".png")],
                         capture_output=True, text=True, check=True)
    r = json.loads(out.stdout)
    expected[name] = {"warnings": r["warnings"], "compile_log": r["compile_log"], "link_log": r["link_log"],
                      "triangles": r["triangles"], "renderer": r["renderer"]}
with open(os.path.join(HERE, "expected.json"), "w") as fh:
    json.dump(expected, fh, indent=1, sort_keys=True)
    fh.write("\n")
