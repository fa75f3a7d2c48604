#!/usr/bin/env bash
# Installs what essl's tests and renders need on a fresh Debian machine (Rust comes with the
# machine): a software Vulkan driver (Mesa's lavapipe) and the Vulkan loader, so that wgpu
# finds an adapter without a GPU; and Neovim, the headless editor scripts/editor-neovim.sh drives
# against `essl server`; Node.js, npm and Chromium for the npm packages' tests. Optional extras
# for benchmarks: ESSL_SETUP_EXTRAS=1 also installs glslang-tools and hyperfine.
# Idempotent: does nothing when everything is already there.
set -euo pipefail

need=()
# Adds each Debian package not installed yet to `need`.
want() {
    for p in "$@"; do
        dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
    done
}
want mesa-vulkan-drivers libvulkan1 neovim
# The npm packages' tests: Node.js and npm, and Chromium for Vite's error overlay in a real
# browser (crates/essl-node/test/overlay.test.mjs).
command -v node >/dev/null 2>&1 || need+=(nodejs)
command -v npm >/dev/null 2>&1 || need+=(npm)
dpkg -s chromium >/dev/null 2>&1 || command -v chromium >/dev/null 2>&1 || need+=(chromium)
# The `canvas` package (jsdom's 2D canvas and image decoding, for crates/essl-gl-node's tests)
# builds from source where its prebuilt binary cannot be downloaded: Cairo's, Pango's and the
# image libraries' headers, and a C++ compiler.
want libcairo2-dev libpango1.0-dev libjpeg-dev libgif-dev librsvg2-dev g++ make
if [ "${ESSL_SETUP_EXTRAS:-0}" = 1 ]; then
    want glslang-tools hyperfine
fi
if [ ${#need[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" = 0 ] || sudo="sudo"
    echo "setup: installing ${need[*]}" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
