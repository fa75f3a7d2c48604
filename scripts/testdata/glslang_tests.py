"""glslang's own tests (Test/ with Test/baseResults) whose shader is `#version 300 es`.

Each record holds the shader and what glslang's baseline says about it: the located
compile errors and warnings (`ERROR: S:L: 'token' : message`), the error count glslang
reported, and the errors of the link step that the gtest suite runs after compiling.
"""

import os
import re

STAGES = {'.vert': 'vertex', '.frag': 'fragment'}
VERSION_RE = re.compile(r'^\s*#\s*version\s+300\s+es\b')
LOCATED_RE = re.compile(r"^(ERROR|WARNING): (\d+):(\d+): '(.*?)' : (.*)$")
COUNT_RE = re.compile(r'^ERROR: (\d+) compilation errors\.')
LINKED_RE = re.compile(r'^Linked \S+ stage:$')
QUOTED_RE = re.compile(r'"([^"\s]+\.(?:vert|frag|geom|tesc|tese|comp|mesh|task))"')
GROUP_RE = re.compile(r'\{\s*("[^}]*")\s*\}')


def _read(path):
    with open(path, encoding='utf-8', errors='surrogateescape', newline='') as f:
        return f.read()


def _gtest_tables(root):
    """File name -> gtest source files naming it; file name -> its link group (if > 1 file)."""
    suites, groups = {}, {}
    gdir = os.path.join(root, 'gtests')
    for fn in sorted(os.listdir(gdir)):
        if not fn.endswith('.cpp'):
            continue
        text = _read(os.path.join(gdir, fn))
        for name in QUOTED_RE.findall(text):
            suites.setdefault(name, [])
            if fn not in suites[name]:
                suites[name].append(fn)
        if fn == 'Link.FromFile.cpp':
            for m in GROUP_RE.finditer(text):
                names = re.findall(r'"([^"]+)"', m.group(1))
                if len(names) > 1:
                    for n in names:
                        groups.setdefault(n, names)
    return suites, groups


def _split_baseline(lines, names):
    """Per file, the compile messages (between its name and its `Shader version:` line);
    and the rest: unlocated errors outside those parts are the link step's."""
    compile_part = {}
    link_errors = []
    current = None
    for l in lines:
        if l in names:
            current = l
            compile_part[current] = []
        elif l.startswith('Shader version:') or LINKED_RE.match(l):
            current = None
        elif current is not None:
            compile_part[current].append(l)
        elif l.startswith('ERROR: ') and l != 'ERROR: node is still EOpNull!':
            link_errors.append(l[len('ERROR: '):])
    return compile_part, link_errors


def _diag(m):
    return {'string': int(m.group(2)), 'line': int(m.group(3)), 'token': m.group(4),
            'message': m.group(5).rstrip(' ')}


def extract(root, skip_files=()):
    test = os.path.join(root, 'Test')
    suites, groups = _gtest_tables(root)
    for fn in sorted(os.listdir(test)):
        ext = os.path.splitext(fn)[1]
        path = os.path.join(test, fn)
        if ext not in STAGES or not os.path.isfile(path) or fn in skip_files:
            continue
        with open(path, encoding='utf-8', errors='surrogateescape') as f:
            source = f.read()  # universal newlines: the tests mix CRLF and LF
        src_lines = source.split('\n')
        vline = next((i + 1 for i, l in enumerate(src_lines) if VERSION_RE.match(l)), None)
        if vline is None:
            continue
        group = groups.get(fn)
        base_name = (group[0] if group else fn) + '.out'
        base_path = os.path.join(test, 'baseResults', base_name)
        if not os.path.exists(base_path):
            continue
        base = _read(base_path).replace('\r\n', '\n').split('\n')
        parts, link_errors = _split_baseline(base, set(group or [fn]))
        sec = parts.get(fn, [])
        errors, warnings, count = [], [], 0
        for l in sec:
            m = LOCATED_RE.match(l)
            if m:
                (errors if m.group(1) == 'ERROR' else warnings).append(_diag(m))
            m = COUNT_RE.match(l)
            if m:
                count = int(m.group(1))
        yield {
            'file': 'Test/' + fn, 'stage': STAGES[ext], 'source': source, 'version_line': vline,
            'link_group': group, 'gtest_suites': suites.get(fn, []),
            'baseline': 'Test/baseResults/' + base_name,
            'expect_compile': count == 0, 'error_count': count, 'errors': errors,
            'warnings': warnings, 'error_lines': sorted({e['line'] for e in errors}),
            'link_errors': link_errors, 'expect_link': count == 0 and not link_errors,
        }
