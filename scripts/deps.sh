#!/usr/bin/env bash
# Installs, with apt-get, the Debian 12 packages passlab needs, skipping what is already there.
# Idempotent: a second run installs nothing. Works as root (no sudo) or as a user with sudo.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglfw3-dev libglm-dev
  libopenimageio-dev
  libtomlplusplus-dev libimgui-dev libcli11-dev
  libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool   # the live tests run the window under Xvfb and press its keys
  graphviz
  python3
)
# `deps.sh --fuzz`: also clang and its libFuzzer/sanitizer runtime, for tests/fuzz/campaign.sh.
# `deps.sh --video`: also ffmpeg, for `passlab render --video FILE.mp4|.gif`.
# `deps.sh --browser`: also Chromium, whose headless mode the report test screenshots with.
for arg in "$@"; do
  case "$arg" in
    --fuzz) PACKAGES+=(clang libclang-rt-14-dev) ;;
    --video) PACKAGES+=(ffmpeg) ;;
    --browser) PACKAGES+=(chromium) ;;
    *) echo "deps.sh: unknown option $arg (known: --fuzz, --video, --browser)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "deps: need root or sudo to install: ${missing[*]}" >&2; exit 3
  fi
fi

echo "deps: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "deps: done"
