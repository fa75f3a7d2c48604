#!/usr/bin/env bash
# The whole test suite on a fresh machine: system packages, the pinned JavaScript libraries, the
# fresh lint corpus (npm, beside the checkout), formatting, clippy, every test, the npm
# package's node --test suites, and a real editor (headless Neovim) driving `essl server`.
# GPU tests render on lavapipe (software Vulkan). Tests that need data outside the repository
# (corpora, scenes, seeds: ESSL_CORPORA / ESSL_SCENES / ESSL_SEEDS, else ../shared/...) skip
# with a message where it is absent; ESSL_REQUIRE_CORPORA=1 turns that skip into a failure, and
# ESSL_REQUIRE_ADAPTER=1 does the same for a missing Vulkan adapter (.ci/run sets both).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/fetch-js-libs.sh
# The fresh lint corpus (npm packages pinned by integrity; docs/lints/corpus.md) beside the
# checkout: the test that every classified true positive is still reported reads it.
export ESSL_LINT_CORPORA="${ESSL_LINT_CORPORA:-$(cd .. && pwd)/lint-corpus}"
# A corpus assembled by older scripts (its stamp differs) is assembled again.
if [ ! -f "$ESSL_LINT_CORPORA/fresh/manifest.jsonl" ] \
    || [ "$(cat "$ESSL_LINT_CORPORA/fresh/assembly.stamp" 2>/dev/null)" != "$(./scripts/lint-corpus/fresh-stamp.sh)" ]; then
    ./scripts/lint-corpus/fetch-fresh.sh "$ESSL_LINT_CORPORA/fresh" "$ESSL_LINT_CORPORA/old"
fi
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
cargo fmt --all -- --check
# Clippy's lints run inside the build of the tests, clippy-driver standing in for rustc on the
# workspace's own crates: one compilation of every crate and dependency instead of a
# `cargo clippy` check of them all beside the test build (on two cores that check was nearly
# half of a clean run). Same lints as `cargo clippy --workspace --all-targets -- -D warnings`.
RUSTC_WORKSPACE_WRAPPER="$(rustup which clippy-driver 2>/dev/null || command -v clippy-driver)"
export RUSTC_WORKSPACE_WRAPPER
export CLIPPY_ARGS="-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__"
cargo test --workspace --all-targets --no-run --quiet
cargo test --workspace --quiet
# The npm package (crates/essl-node): its API and real Vite, Rollup and webpack builds.
./scripts/test-essl-node.sh
# The Node.js addon (crates/essl-gl-node): node --test of the binding, three.js, conformance pages.
./scripts/test-gl-node.sh
ESSL="$PWD/target/debug/essl" ./scripts/editor-neovim.sh
