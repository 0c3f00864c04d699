#!/usr/bin/env bash
# Installs every Debian package Terrasol needs to build, run and test.
# Idempotent: `apt-get update` runs only when something is missing.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config
  # window, input, GL loading (GLFW for the game, EGL + libepoxy for both)
  libglfw3-dev libepoxy-dev libegl-dev libgl-dev
  # Mesa: llvmpipe software GL and its EGL vendor, used headless by tests and tools
  libgl1-mesa-dri libegl-mesa0
  # math, images, models, JSON
  libglm-dev libopenimageio-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  # saves: chunk compression and checksums
  libzstd-dev libxxhash-dev
  # Minecraft saves: region chunks in gzip/zlib and LZ4
  zlib1g-dev liblz4-dev
  # resource packs shipped as .zip
  libzip-dev
  # sound: OpenAL Soft for playback, libvorbis to decode packs' .ogg files and to encode the default pack's
  libopenal-dev libvorbis-dev
  # the HUD, debug overlay and menus (Dear ImGui with its GLFW and OpenGL 3 backends)
  libimgui-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the format check (tools/check-format.sh): Debian 12's clang-format, version 14
  clang-format
  # a virtual display for windowed smoke tests, and a window manager so a test can minimise the game
  xvfb xauth twm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y --no-install-recommends "${missing[@]}"
