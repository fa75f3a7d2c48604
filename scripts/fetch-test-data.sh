#!/usr/bin/env bash
# Regenerates essl's test corpora from their upstream repositories.
#
#   scripts/fetch-test-data.sh [--out DIR] [--from-git-dir NAME=GITDIR]... [--include-held-back]
#   ESSL_CORPORA=$PWD/test-data/corpora cargo test
#
# Upstreams, at pinned commits:
#   webgl         KhronosGroup/WebGL f15a73f (sdk/tests): webgl_conformance_es300.jsonl,
#                 webgl_conformance_es100.jsonl, deqp_gles3.jsonl
#   glslang       KhronosGroup/glslang 90afccf (Test/, gtests/): glslang_es300.jsonl
#   fundamentals  gfxfundamentals/webgl2-fundamentals e6e08aa: webgl2fundamentals_shaders.jsonl,
#                 webgl2fundamentals-pages/
#
# Each upstream is cloned with --filter=blob:none and only the folders the extractor reads
# are checked out at the pinned commit. To work without network, point the script at local
# copies instead: --from-git-dir NAME=GITDIR (a clone or bare mirror holding the pinned
# commit), or a ready checkout through ESSL_WEBGL_SRC, ESSL_GLSLANG_SRC,
# ESSL_FUNDAMENTALS_SRC. Clones are kept in DIR/../sources for the next run.
#
# What cannot be regenerated here:
#   - webgl_conformance_es100.jsonl: the chromium_webgl1 / chromium_webgl2 fields record what
#     Chromium answered when the cases ran in a browser; this script extracts the upstream
#     fields only and leaves those two out.
#   - the WebGL conformance files are extracted by running the pages' own scripts in a small
#     JavaScript interpreter (scripts/testdata/jsmini.py). Pages it cannot run are reported
#     ("note: ...") and left out; at the pinned commit that is three pages that have no
#     cases in the shared corpora either (conditional-texture-fetch, texture-bias,
#     cube-map-uploads-out-of-order). Limits a page queries (gl.getParameter) are answered
#     with fixed values (texel offsets -8..7, 15 varyings, ...).
#   - ../shared/scenes and ../shared/seeds do not come from a public upstream repository and
#     are not fetched.
# By default the upstream files that the shared corpora hold back are left out too
# (scripts/testdata/selection.py), so the output matches ../shared/corpora: every case of
# every file agrees byte for byte (compare with scripts/testdata/compare.py DIR), except
# the browser fields above and webgl2fundamentals-pages/README.md, which is written here.
# --include-held-back keeps those files.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
out="$root/test-data/corpora"
extra=()
declare -A gitdir=()

while [ $# -gt 0 ]; do
    case "$1" in
        --out) out="$2"; shift 2 ;;
        --from-git-dir) gitdir["${2%%=*}"]="${2#*=}"; shift 2 ;;
        --include-held-back) extra+=(--include-held-back); shift ;;
        -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        *) echo "unknown argument: $1" >&2; exit 2 ;;
    esac
done

declare -A url=(
    [webgl]=https://github.com/KhronosGroup/WebGL.git
    [glslang]=https://github.com/KhronosGroup/glslang.git
    [fundamentals]=https://github.com/gfxfundamentals/webgl2-fundamentals.git
)
declare -A commit=(
    [webgl]=f15a73f727d8ee66a3ec6d0bed9f02f08cacc2c1
    [glslang]=90afccfbd49dff0349d86a41762e9de24e1df811
    [fundamentals]=e6e08aa0b1a53d45ba8e6258e9a832d67bf91b20
)
# The paths each extractor reads (git pathspecs).
declare -A paths=(
    [webgl]="sdk/tests specs/latest/1.0/webgl.idl specs/latest/2.0/webgl2.idl"
    [glslang]="Test gtests"
    [fundamentals]="LICENSE :(glob)webgl/*.html :(glob)webgl/resources/*.js"
)
declare -A envsrc=([webgl]=ESSL_WEBGL_SRC [glslang]=ESSL_GLSLANG_SRC [fundamentals]=ESSL_FUNDAMENTALS_SRC)

mkdir -p "$out"
sources="$(cd "$out/.." && pwd)/sources"

# checkout_from GITDIR NAME: the pinned commit's files of NAME into $sources/NAME.
checkout_from() {
    local g="$1" name="$2" c="${commit[$2]}"
    if ! git --git-dir="$g" cat-file -e "$c^{commit}" 2>/dev/null; then
        echo "error: $g does not hold commit $c of ${url[$name]}" >&2
        exit 1
    fi
    local wt="$sources/$name"
    mkdir -p "$sources"
    rm -rf "$wt"
    mkdir -p "$wt"
    # A private index: the git directory itself is only read.
    # shellcheck disable=SC2086
    GIT_INDEX_FILE="$sources/.$name.index" git --git-dir="$g" --work-tree="$wt" \
        checkout -q "$c" -- ${paths[$name]}
    rm -f "$sources/.$name.index"
    echo "$wt"
}

declare -A src=()
for name in webgl glslang fundamentals; do
    envname="${envsrc[$name]}"
    if [ -n "${!envname:-}" ]; then
        src[$name]="${!envname}"
        echo "$name: using checkout ${src[$name]}" >&2
    elif [ -n "${gitdir[$name]:-}" ]; then
        echo "$name: ${commit[$name]:0:7} from ${gitdir[$name]}" >&2
        src[$name]="$(checkout_from "${gitdir[$name]}" "$name")"
    else
        clone="$sources/$name.git"
        if [ ! -d "$clone" ]; then
            mkdir -p "$sources"
            echo "$name: cloning ${url[$name]} (blobless)" >&2
            git clone -q --bare --filter=blob:none "${url[$name]}" "$clone"
        fi
        if ! git --git-dir="$clone" cat-file -e "${commit[$name]}^{commit}" 2>/dev/null; then
            git --git-dir="$clone" fetch -q --filter=blob:none origin "${commit[$name]}"
        fi
        echo "$name: checking out ${commit[$name]:0:7}" >&2
        src[$name]="$(checkout_from "$clone" "$name")"
    fi
done

python3 "$here/testdata/extract.py" --out "$out" \
    --webgl "${src[webgl]}" --glslang "${src[glslang]}" --fundamentals "${src[fundamentals]}" \
    --fundamentals-commit "${commit[fundamentals]}" "${extra[@]+"${extra[@]}"}"

# The WebGL IDL, as ../shared/specs names it (crates/essl-gl-script/tests/it/idl.rs reads it).
specs="$(cd "$out/.." && pwd)/specs"
mkdir -p "$specs"
cp "${src[webgl]}/specs/latest/1.0/webgl.idl" "$specs/webgl1.idl"
cp "${src[webgl]}/specs/latest/2.0/webgl2.idl" "$specs/webgl2.idl"

cat <<NOTE
Wrote $out and $specs (ESSL_SPECS=$specs)
Not written: the chromium_webgl1/chromium_webgl2 fields of webgl_conformance_es100.jsonl
(they come from running the cases in Chromium), and the scenes and seeds of ../shared
(not from a public upstream repository).
Run the tests on these files with: ESSL_CORPORA=$out cargo test
NOTE
