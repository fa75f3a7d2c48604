"""Shaders of the webgl2fundamentals lessons (gfxfundamentals/webgl2-fundamentals).

Every JS template literal whose text (after leading whitespace) starts with
`#version 300 es`, in `webgl/*.html` and `webgl/resources/*.js`, files in path order.
A shader whose text was already seen (same SHA-1) is kept once, at its first place.
The stage is read from the source: `gl_Position` means vertex, an `out` of a vec4 type
means fragment, anything else (transform-feedback programs, empty fragment shaders)
has no detectable stage. `templated` marks sources that still hold `${...}`.
"""

import hashlib
import os
import re
import shutil

VERSION = '#version 300 es'
FRAG_OUT_RE = re.compile(r'\bout\s+(?:(?:lowp|mediump|highp)\s+)?[iu]?vec4\b')


def _stage(src):
    if 'gl_Position' in src:
        return 'vertex'
    if FRAG_OUT_RE.search(src):
        return 'fragment'
    return None


def _template_literals(text):
    """(start, end) of every shader in a backquoted literal, start at `#version`."""
    pos = 0
    while True:
        i = text.find(VERSION, pos)
        if i < 0:
            return
        j = i
        while j > 0 and text[j - 1] in ' \t\r\n':
            j -= 1
        pos = i + len(VERSION)
        if j == 0 or text[j - 1] != '`':
            continue
        k = pos
        while k < len(text) and text[k] != '`':
            k += 2 if text[k] == '\\' else 1
        yield i, k
        pos = k + 1


def lesson_files(root):
    out = []
    for sub in ('webgl', 'webgl/resources'):
        d = os.path.join(root, sub)
        for fn in os.listdir(d):
            if (sub == 'webgl' and fn.endswith('.html')) or (sub != 'webgl' and fn.endswith('.js')):
                if os.path.isfile(os.path.join(d, fn)):
                    out.append(sub + '/' + fn)
    return sorted(out)


def extract(root, commit, skip_files=()):
    seen = set()
    for rel in lesson_files(root):
        if rel in skip_files:
            continue
        with open(os.path.join(root, rel), encoding='utf-8', newline='') as f:
            text = f.read()
        for start, end in _template_literals(text):
            src = text[start:end]
            sha1 = hashlib.sha1(src.encode('utf-8')).hexdigest()
            if sha1 in seen:
                continue
            seen.add(sha1)
            yield {'file': rel, 'commit': commit, 'stage': _stage(src), 'source': src,
                   'templated': '${' in src, 'sha1': sha1, 'expect_compile': True}


def copy_pages(root, dest, skip_pages=()):
    """Copies the lesson pages (webgl/*.html) byte for byte, with the project's LICENSE."""
    os.makedirs(dest, exist_ok=True)
    n = 0
    d = os.path.join(root, 'webgl')
    for fn in sorted(os.listdir(d)):
        if fn.endswith('.html') and fn not in skip_pages and os.path.isfile(os.path.join(d, fn)):
            shutil.copyfile(os.path.join(d, fn), os.path.join(dest, fn))
            n += 1
    shutil.copyfile(os.path.join(root, 'LICENSE'), os.path.join(dest, 'LICENSE'))
    return n
