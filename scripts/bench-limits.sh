#!/usr/bin/env bash
# Time and peak memory of `essl lint` on hostile inputs of at most 1 MiB each: floods of errors,
# macro bombs, deep nesting, huge declarations lists, no-break spaces, long lines; and host
# files (HTML pages, JS modules) holding thousands of shaders or one huge one.
#
# Writes the inputs into a temporary folder, builds essl in release mode, runs each once under
# GNU time and prints a Markdown table: input, size, wall seconds, CPU seconds (user, on every
# thread), peak resident memory (MiB), and the first diagnostic's code. Shader files are linted
# as they are (`NAME.frag` has no partner), host files with their pairs linked. docs/reliability.md shows the last run.
#
# Usage: scripts/bench-limits.sh   (needs python3 and /usr/bin/time, Debian's `time`)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v /usr/bin/time >/dev/null || { echo "error: /usr/bin/time is not installed (apt-get install time)" >&2; exit 2; }
cargo build --release -p essl-cli --quiet
essl="$PWD/target/release/essl"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
python3 - "$dir" <<'PY'
import os, sys
out, MB = sys.argv[1], 1 << 20
hdr = '#version 300 es\nprecision mediump float;\nout vec4 o;\n'
def w(name, s):
    with open(os.path.join(out, name + '.frag'), 'w', encoding='utf-8') as f:
        f.write(s[:MB])
w('function-macro-bomb-6-levels', hdr + '#define A(x) x x x x x x x x x x\nvoid main() { A(A(A(A(A(A(;)))))) o = vec4(1.0); }\n')
w('object-macro-chain-2^40', hdr + ''.join(f'#define E{i} E{i+1} E{i+1}\n' for i in range(40)) + '#define E40 ;\nvoid main() { E0 o = vec4(1.0); }\n')
w('object-macro-chain-100^5', hdr + ''.join(f'#define E{i} ' + ' '.join([f'E{i+1}'] * 100) + '\n' for i in range(5)) + '#define E5 ;\nvoid main() { E0 o = vec4(1.0); }\n')
w('valid-87k-statements', hdr + 'void main() { float x = 1.0; ' + ' x = x + 1.0;' * ((MB - 200) // 13) + ' o = vec4(x); }\n')
w('invalid-characters', hdr + 'void main() { ' + '@ ' * ((MB - 100) // 2) + '}\n')
w('undeclared-names', hdr + 'void main() { ' + 'y; ' * ((MB - 100) // 3) + '}\n')
w('type-errors-one-line', hdr + 'void main() { float x; ' + 'x = 1;' * ((MB - 100) // 6) + '}\n')
w('non-bool-conditions', hdr + 'uniform float u;\nvoid main() { ' + 'if (u) {} ' * ((MB - 100) // 11) + ' o = vec4(1.0); }\n')
w('60k-globals', hdr + ''.join(f'float g{i};\n' for i in range(60000)) + 'void main() { o = vec4(g0); }\n')
w('30k-structs', hdr + ''.join(f'struct S{i} {{ float a; }};\n' for i in range(30000)) + 'void main() { o = vec4(1.0); }\n')
w('25k-functions', hdr + ''.join(f'float f{i}(float x) {{ return x; }}\n' for i in range(25000)) + 'void main() { o = vec4(f0(1.0)); }\n')
w('60k-defines', hdr + ''.join(f'#define M{i} {i}\n' for i in range(60000)) + 'void main() { o = vec4(1.0); }\n')
# Settings a text lets its includer make (the lints' configurations read each kind once).
w('22k-ifndef-choices', hdr + ''.join(f'#ifndef N{i}\n#define N{i} f{i}\n#endif\n' for i in range(22000)) + 'void main() { o = vec4(1.0); }\n')
w('25k-ifndef-counts', hdr + ''.join(f'#ifndef C{i}\n#define C{i} 5\n#endif\n' for i in range(25000)) + 'void main() { o = vec4(1.0); }\n')
# Choices whose families share a prefix: each family's other functions are looked up in the
# sorted names, a bounded run of them.
w('8k-choice-families', hdr + ''.join(f'float famX{i}(float a) {{ return a; }}\n' for i in range(8000)) + ''.join(f'#ifndef N{i}\n#ifdef W\n#define N{i} famX{i}\n#else\n#define N{i} famX{i + 1}\n#endif\n#endif\n' for i in range(8000)) + 'void main() { o = vec4(1.0); }\n')
w('16k-ifndef-levels', hdr + ''.join(f'#ifndef L{i}\n#define L{i} 0\n#endif\n#if L{i} > 2\n#endif\n' for i in range(16000)) + 'void main() { o = vec4(1.0); }\n')
w('1-MiB-identifier', hdr + 'void main() { float ' + 'a' * (MB - 200) + ' = 1.0; o = vec4(1.0); }\n')
w('1-MiB-comment-line', hdr + '// ' + 'x' * (MB - 200) + '\nvoid main() { o = vec4(1.0); }\n')
w('nested-parentheses', hdr + 'void main() { o = vec4(' + '(' * (MB // 2 - 100) + '1.0' + ')' * (MB // 2 - 100) + '); }\n')
w('sum-chain', hdr + 'void main() { float x = 1.0' + ' + 1.0' * ((MB - 200) // 6) + '; o = vec4(x); }\n')
w('no-break-spaces-one-line', hdr + 'void main() {' + '\u00a0' * ((MB - 100) // 2) + ' o = vec4(1.0); }\n')
w('switch-30k-cases', hdr + 'void main() { int i = 0; switch (i) { ' + ''.join(f'case {k}: o = vec4({k}.0); break; ' for k in range(30000)) + '} }\n')
# Host files: shaders inside HTML and JS, checked one unit per file.
def host(name, s):
    with open(os.path.join(out, name), 'w', encoding='utf-8') as f:
        f.write(s[:MB])
tag = lambda i, stage, body: f'<script id="s{i}-{stage}-shader" type="x-shader/x-{stage}">#version 300 es\n{body}</script>\n'
vs = 'in vec4 p;\nvoid main() { gl_Position = p; }\n'
fs = 'precision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n'
host('page-5000-shader-tags.html', ''.join(tag(i // 2, 'vertex' if i % 2 == 0 else 'fragment', vs if i % 2 == 0 else fs) for i in range(5000)))
page, i = '', 0
while len(page) < MB - 400:
    page += tag(i, 'fragment', 'void main() { x = 1; }\n')
    i += 1
host('page-1-MiB-of-broken-tags.html', page)
script, i = '', 0
while len(script) < MB - 200:
    script += f'export const fs{i} = `#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() {{ c = vec4({i}.0); }}`;\n'
    i += 1
host('module-1-MiB-of-literals.js', script)
host('page-one-1-MiB-shader.html', '<script type="x-shader/x-fragment">' + hdr + 'void main() { float x = 1.0; ' + ' x = x + 1.0;' * ((MB - 300) // 13) + ' o = vec4(x); }\n</script>\n')
PY
echo "essl $("$essl" --version | cut -d' ' -f2) at $(git rev-parse --short HEAD), $(nproc) cores"
echo
echo "| input | bytes | wall s | CPU s | peak MiB | first diagnostic |"
echo "|---|---:|---:|---:|---:|---|"
for f in "$dir"/*.frag "$dir"/*.html "$dir"/*.js; do
    /usr/bin/time -f "%e %U %M" -o "$dir/time.txt" "$essl" lint --format json "$f" > "$dir/out.txt" 2>&1 || true
    read -r wall user kib < <(grep -v status "$dir/time.txt")
    code=$(grep -o '"code":"[^"]*"' "$dir/out.txt" | head -1 | cut -d'"' -f4 || true)
    name=$(basename "$f"); name=${name%.frag}
    echo "| \`$name\` | $(stat -c %s "$f") | $wall | $user | $((kib / 1024)) | ${code:-none} |"
done
