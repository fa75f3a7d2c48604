#!/usr/bin/env bash
# The whole test suite on a fresh machine: system packages, formatting, clippy, every test.
# GPU tests render on lavapipe (software Vulkan); with CI set, a missing adapter or a missing
# ../shared folder fails the run instead of skipping.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --quiet -- -D warnings
cargo test --workspace --quiet
