#!/usr/bin/env bash
# Builds the fresh lint corpus of docs/lints/corpus.md outside the repository: packs each npm
# package of fresh-packages.txt at its pinned version, checks the tarball against the pinned
# sha512 integrity, unpacks it into OUT/npm/NAME-VERSION/package, and extracts the shaders
# (extract-fresh.py: whole shaders assembled as each library does, lygia's files with a
# generated main). Texts the old corpus holds are left out when it is at OLD.
# Then lint it:
#   cargo run --release -p essl-lint --example lint-corpus -- OUT > findings.jsonl
#   python3 scripts/lint-corpus/table.py findings.jsonl docs/lints/corpus-fresh-triage.tsv
#
# Usage: scripts/lint-corpus/fetch-fresh.sh [OUT] [OLD] (defaults ../lint-corpus/fresh and
# ../lint-corpus/old). Needs: npm, python3, network access to the npm registry.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="$(mkdir -p "${1:-$root/../lint-corpus/fresh}" && cd "${1:-$root/../lint-corpus/fresh}" && pwd)"
old="${2:-$root/../lint-corpus/old}"
npm_dir="$out/npm"
mkdir -p "$npm_dir"

grep -v '^#' "$here/fresh-packages.txt" | while read -r spec integrity; do
    [ -n "$spec" ] || continue
    name="${spec%@*}"
    version="${spec##*@}"
    tgz="$npm_dir/$(echo "${name#@}" | tr '/' '-')-$version.tgz"
    dest="$npm_dir/$(basename "$tgz" .tgz)"
    if [ ! -f "$tgz" ]; then
        (cd "$npm_dir" && npm pack --silent "$spec" >/dev/null)
    fi
    actual="sha512-$(openssl dgst -sha512 -binary "$tgz" | base64 -w0)"
    if [ "$actual" != "$integrity" ]; then
        echo "error: $spec: integrity $actual, expected $integrity" >&2
        exit 1
    fi
    if [ ! -d "$dest/package" ]; then
        mkdir -p "$dest"
        tar xzf "$tgz" -C "$dest"
    fi
done

rm -rf "$out/shaders" "$out/manifest.jsonl"
python3 "$here/extract-fresh.py" --npm "$npm_dir" --out "$out" --old "$old"
"$here/fresh-stamp.sh" > "$out/assembly.stamp"
echo "corpus: $(wc -l < "$out/manifest.jsonl") shaders in $out"
