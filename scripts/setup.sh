#!/usr/bin/env bash
# Installs what essl's tests and renders need on a fresh Debian machine (Rust comes with the
# machine): a software Vulkan driver (Mesa's lavapipe) and the Vulkan loader, so that wgpu
# finds an adapter without a GPU; and Neovim, the headless editor scripts/editor-neovim.sh drives
# against `essl server`. Optional extras for benchmarks and oracle runs:
#   ESSL_SETUP_EXTRAS=1 also installs chromium (WebGL2 oracle/peer), glslang-tools and hyperfine.
# Idempotent: does nothing when everything is already there.
set -euo pipefail

need=()
dpkg -s mesa-vulkan-drivers >/dev/null 2>&1 || need+=(mesa-vulkan-drivers)
dpkg -s libvulkan1 >/dev/null 2>&1 || need+=(libvulkan1)
dpkg -s neovim >/dev/null 2>&1 || need+=(neovim)
if [ "${ESSL_SETUP_EXTRAS:-0}" = 1 ]; then
    for p in chromium glslang-tools hyperfine; do
        dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
    done
fi
if [ ${#need[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" = 0 ] || sudo="sudo"
    echo "setup: installing ${need[*]}" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
