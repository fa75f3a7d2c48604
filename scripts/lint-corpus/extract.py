#!/usr/bin/env python3
"""Extracts the `#version 300 es` shaders of a set of git repositories into one folder.

For each repository of `repos.txt` (`owner/name commit`, one a line), reads every file of that
commit (through `git show`, so that any clone or mirror with the commit works) and takes out:

- shader files (`.vert`, `.frag`, `.glsl`, `.vs`, `.fs`, …) that start with `#version 300 es`;
- shaders inside JavaScript, TypeScript and HTML: template literals (`` `#version 300 es …` ``,
  skipped when they interpolate `${…}`), quoted strings with `\\n` escapes, `<script>` elements
  and `<vertex>`/`<fragment>` elements (FunWithWebGL2's shader files).

Leading white space before `#version` is dropped (what the pages' loaders do with `trim()`).
The stage comes from the file extension, the element or the name of the variable the shader is
assigned to, corrected by the text (`gl_Position` is vertex, `gl_FragColor`/`gl_FragCoord`/
`discard` fragment). Identical texts (after collapsing white space) are kept once, and so are
texts that the shared corpora or this project's seeds already hold.

Writes `OUT/shaders/OWNER__NAME/NNN-PATH.{vert,frag}` and `OUT/manifest.jsonl`
(`file, repo, commit, path, index, stage`).

Usage: extract.py --repos repos.txt --mirror DIR --out OUT [--shared ../shared]
where DIR holds one git directory per repository as `DIR/OWNER+NAME/repo` (bare or not).
"""

import argparse
import json
import os
import re
import subprocess
import sys

SHADER_EXTS = (".vert", ".frag", ".glsl", ".vs", ".fs", ".vsh", ".fsh", ".shader", ".txt")
HOST_EXTS = (".js", ".mjs", ".ts", ".tsx", ".jsx", ".html", ".htm", ".vue", ".svelte")
VERSION = "#version 300 es"
MAX_BYTES = 2_000_000


def git(gitdir, *args):
    return subprocess.run(
        ["git", "--git-dir", gitdir, *args], check=True, capture_output=True
    ).stdout


def gitdir_of(mirror, repo):
    base = os.path.join(mirror, repo.replace("/", "+"), "repo")
    dotgit = os.path.join(base, ".git")
    return dotgit if os.path.isdir(dotgit) else base


def normalise(text):
    return " ".join(text.split())


def unescape_js(s):
    out, i = [], 0
    table = {"n": "\n", "t": "\t", "r": "", "\\": "\\", "'": "'", '"': '"', "`": "`", "0": "\0"}
    while i < len(s):
        c = s[i]
        if c == "\\" and i + 1 < len(s):
            n = s[i + 1]
            if n == "\n":
                i += 2
                continue
            out.append(table.get(n, n))
            i += 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


def stage_hint(before, path):
    """The stage the text before a shader (or the file name) names: the nearest mention wins."""
    best, where = None, -1
    pattern = r"(vertex|vert|vs|vsh|VS|VERTEX|Vertex)(?![a-z])|(fragment|frag|fs|fsh|FS|FRAGMENT|Fragment|pixel)(?![a-z])"
    for m in re.finditer(pattern, before):
        if m.start() > where:
            where = m.start()
            best = "vertex" if m.group(1) else "fragment"
    if best is None:
        low = path.lower()
        if re.search(r"(\.|_|-|/)(vert|vs|vsh)(\.|_|-|$)|vertex", low):
            best = "vertex"
        elif re.search(r"(\.|_|-|/)(frag|fs|fsh)(\.|_|-|$)|fragment", low):
            best = "fragment"
    return best


def stage_of(text, hint):
    code = re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
    if re.search(r"\bgl_Position\s*=", code):
        return "vertex"
    if re.search(r"\b(gl_FragColor|gl_FragCoord|gl_FragDepth|discard|dFdx|dFdy|fwidth)\b", code):
        return "fragment"
    return hint or "fragment"


def shaders_in(text, path):
    """(start offset, shader text, stage hint) of each `#version 300 es` shader in a file."""
    out = []
    is_shader_file = path.endswith(SHADER_EXTS) and not path.endswith(".txt")
    for m in re.finditer(re.escape(VERSION), text):
        start = m.start()
        j = start - 1
        while j >= 0 and text[j] in " \t\r\n":
            j -= 1
        opener = text[j] if j >= 0 else ""
        before = text[max(0, j - 160) : max(j, 0)]
        if opener == "":
            if is_shader_file:
                out.append((start, text[start:], stage_hint("", path)))
            continue
        if opener == "`":
            end = text.find("`", start)
            body = text[start:end] if end > 0 else ""
            if "${" in body or not body:
                continue
            out.append((start, unescape_js(body), stage_hint(before, path)))
        elif opener in "'\"":
            k = start
            while k < len(text) and text[k] != opener and text[k] != "\n":
                k += 2 if text[k] == "\\" else 1
            body = text[start:k]
            if "\\n" not in body or k >= len(text) or text[k] != opener:
                continue  # one line of an array or a concatenation: not a whole shader
            out.append((start, unescape_js(body), stage_hint(before, path)))
        elif opener == ">":
            tag = re.search(r"<\s*([A-Za-z][\w-]*)([^<>]*)$", text[max(0, j - 300) : j])
            if not tag:
                continue
            name = tag.group(1)
            end = text.find(f"</{name}", start)
            if end < 0:
                continue
            hint = {"vertex": "vertex", "fragment": "fragment"}.get(name.lower())
            hint = hint or stage_hint(tag.group(2), path)
            out.append((start, text[start:end], hint))
    return out


def shared_texts(shared):
    seen = set()
    corpora = os.path.join(shared, "corpora")
    for name in sorted(os.listdir(corpora)) if os.path.isdir(corpora) else []:
        if not name.endswith(".jsonl"):
            continue
        with open(os.path.join(corpora, name), encoding="utf-8") as f:
            for line in f:
                case = json.loads(line)
                for key in ("source", "vertex_source", "fragment_source"):
                    if isinstance(case.get(key), str):
                        seen.add(normalise(case[key]))
    return seen


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repos", required=True)
    ap.add_argument("--mirror", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--shared", default="../shared")
    ap.add_argument("--seeds", default="shaders-glsl")
    a = ap.parse_args()
    seen = shared_texts(a.shared)
    if os.path.isdir(a.seeds):
        for p in os.listdir(a.seeds):
            with open(os.path.join(a.seeds, p), encoding="utf-8", errors="replace") as f:
                seen.add(normalise(f.read()))
    known = len(seen)
    os.makedirs(os.path.join(a.out, "shaders"), exist_ok=True)
    manifest = open(os.path.join(a.out, "manifest.jsonl"), "w", encoding="utf-8")
    totals = []
    for line in open(a.repos, encoding="utf-8"):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        repo, commit = line.split()[:2]
        gd = gitdir_of(a.mirror, repo)
        try:
            listing = git(gd, "ls-tree", "-r", "-l", "--full-tree", commit).decode()
        except (subprocess.CalledProcessError, FileNotFoundError) as e:
            print(f"error: {repo}@{commit}: {e}", file=sys.stderr)
            continue
        folder = repo.replace("/", "__")
        os.makedirs(os.path.join(a.out, "shaders", folder), exist_ok=True)
        n = dup = 0
        for entry in listing.splitlines():
            meta, path = entry.split("\t", 1)
            parts = meta.split()
            if parts[1] != "blob" or not parts[3].isdigit() or int(parts[3]) > MAX_BYTES:
                continue
            if "node_modules/" in path or ".min." in path or not path.endswith(SHADER_EXTS + HOST_EXTS):
                continue
            try:
                text = git(gd, "cat-file", "blob", parts[2]).decode("utf-8")
            except (subprocess.CalledProcessError, UnicodeDecodeError):
                continue
            if VERSION not in text:
                continue
            for index, (offset, body, hint) in enumerate(shaders_in(text, path)):
                body = body.replace("\r\n", "\n")
                if not body.endswith("\n"):
                    body += "\n"
                key = normalise(body)
                if key in seen:
                    dup += 1
                    continue
                seen.add(key)
                stage = stage_of(body, hint)
                ext = "vert" if stage == "vertex" else "frag"
                safe = re.sub(r"[^A-Za-z0-9._-]+", "_", path)[-80:]
                name = f"{n:04}-{safe}-{index}.{ext}"
                with open(os.path.join(a.out, "shaders", folder, name), "w", encoding="utf-8") as f:
                    f.write(body)
                manifest.write(json.dumps({
                    "file": f"shaders/{folder}/{name}", "repo": repo, "commit": commit,
                    "path": path, "offset": offset, "stage": stage,
                }) + "\n")
                n += 1
        totals.append((repo, n, dup))
    manifest.close()
    for repo, n, dup in totals:
        print(f"{repo:50} {n:5} shaders ({dup} duplicates dropped)")
    print(f"{sum(t[1] for t in totals)} shaders from {sum(1 for t in totals if t[1])} repositories "
          f"({known} known texts excluded)")


if __name__ == "__main__":
    main()
