#!/usr/bin/env python3
"""Compares regenerated corpora with a reference set, file by file.

    python3 scripts/testdata/compare.py NEW_DIR [REFERENCE_DIR (default ../shared/corpora)]

For each JSON Lines file: case counts, cases only on one side, and for the cases on both
sides how many agree exactly and which fields differ (fields only the reference has, such
as the browser's answers in webgl_conformance_es100.jsonl, are listed, not counted).
For webgl2fundamentals-pages/: files missing or differing byte for byte.
"""

import collections
import filecmp
import json
import os
import sys

KEYS = {
    'deqp_gles3.jsonl': ('file', 'name'),
    'glslang_es300.jsonl': ('file',),
    'webgl2fundamentals_shaders.jsonl': ('sha1',),
    'webgl_conformance_es300.jsonl': ('file', 'index', 'vertex_source', 'fragment_source'),
    'webgl_conformance_es100.jsonl': ('file', 'index', 'vertex_source', 'fragment_source'),
}
BROWSER_FIELDS = {'chromium_webgl1', 'chromium_webgl2'}


def load(path):
    rows = collections.OrderedDict()
    with open(path, encoding='utf-8') as f:
        for line in f:
            r = json.loads(line)
            rows[tuple(json.dumps(r.get(k)) for k in KEYS[os.path.basename(path)])] = r
    return rows


def compare_file(name, new_dir, ref_dir, verbose):
    new_p, ref_p = os.path.join(new_dir, name), os.path.join(ref_dir, name)
    if not os.path.exists(new_p) or not os.path.exists(ref_p):
        print('%-34s missing (%s)' % (name, new_p if not os.path.exists(new_p) else ref_p))
        return
    new, ref = load(new_p), load(ref_p)
    both = [k for k in ref if k in new]
    fields = collections.Counter()
    same = 0
    examples = {}
    for k in both:
        a, b = ref[k], new[k]
        diff = [f for f in a if f not in BROWSER_FIELDS and a[f] != b.get(f)]
        diff += ['+' + f for f in b if f not in a]
        if diff:
            for f in diff:
                fields[f] += 1
                examples.setdefault(f, k)
        else:
            same += 1
    only_ref = [k for k in ref if k not in new]
    only_new = [k for k in new if k not in ref]
    print('%-34s reference %5d  new %5d  matched %5d  identical %5d  only-reference %4d  only-new %4d'
          % (name, len(ref), len(new), len(both), same, len(only_ref), len(only_new)))
    for f, n in fields.most_common():
        print('    field %-24s differs in %d (e.g. %s)' % (f, n, examples[f][:2]))
    if verbose:
        for k in only_ref[:verbose]:
            print('    only in reference:', k[:2])
        for k in only_new[:verbose]:
            print('    only in new:', k[:2])
    if only_ref:
        c = collections.Counter(json.loads(k[0]) for k in only_ref)
        print('    reference-only cases by file:', ', '.join('%s %d' % (f, n) for f, n in c.most_common(8)),
              '...' if len(c) > 8 else '')


def compare_pages(new_dir, ref_dir):
    a, b = os.path.join(ref_dir, 'webgl2fundamentals-pages'), os.path.join(new_dir, 'webgl2fundamentals-pages')
    if not os.path.isdir(a) or not os.path.isdir(b):
        print('webgl2fundamentals-pages/ missing')
        return
    ra, rb = set(os.listdir(a)), set(os.listdir(b))
    same = [f for f in ra & rb if filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False)]
    print('%-34s reference %5d  new %5d  identical %5d  only-reference %s  only-new %s'
          % ('webgl2fundamentals-pages/', len(ra), len(rb), len(same), sorted(ra - rb), sorted(rb - ra)))
    differing = sorted((ra & rb) - set(same))
    if differing:
        print('    differ:', differing)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('-v')]
    verbose = 10 if any(a.startswith('-v') for a in sys.argv[1:]) else 0
    new_dir = args[0]
    here = os.path.dirname(os.path.abspath(__file__))
    ref_dir = args[1] if len(args) > 1 else os.path.join(here, '..', '..', '..', 'shared', 'corpora')
    for name in KEYS:
        compare_file(name, new_dir, ref_dir, verbose)
    compare_pages(new_dir, ref_dir)


if __name__ == '__main__':
    main()
