#!/usr/bin/env bash
# The whole test suite on a fresh machine: system packages, formatting, clippy, every test, and
# a real editor (headless Neovim) driving `essl server`.
# GPU tests render on lavapipe (software Vulkan). Tests that need data outside the repository
# (corpora, scenes, seeds: ESSL_CORPORA / ESSL_SCENES / ESSL_SEEDS, else ../shared/...) skip
# with a message where it is absent; ESSL_REQUIRE_CORPORA=1 turns that skip into a failure, and
# ESSL_REQUIRE_ADAPTER=1 does the same for a missing Vulkan adapter (.ci/run sets both).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/fetch-js-libs.sh
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --quiet -- -D warnings
cargo test --workspace --quiet
# The Node.js addon (crates/essl-gl-node): node --test of the binding, three.js, conformance pages.
./scripts/test-gl-node.sh
ESSL="$PWD/target/debug/essl" ./scripts/editor-neovim.sh
