#!/usr/bin/env bash
# Installs the Debian packages fragsim needs that are missing, then configures and builds a preset
# (default: release): every target, or only TARGET when given (scripts/compare.sh builds the tool
# alone). Usage: scripts/setup.sh [preset [TARGET]]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
target=()
[ $# -ge 2 ] && target=(--target "$2")

packages=(cmake g++ make pkg-config libode-dev libbullet-dev libeigen3-dev
          libboost-program-options-dev googletest libgtest-dev libbenchmark-dev gnuplot-nox libpng-dev
          voro++-dev libqhull-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
          libsdl2-dev xvfb xdotool x11-apps python3)
scripts/install_packages.sh "${packages[@]}"
# node and npm for three.js, the report's 3D view, and for the glTF validator (the
# Bake.ValidatorFindsNoError test): Debian's, unless a node is already there (another
# distribution's nodejs package would conflict). three.js goes into build/npm before cmake runs,
# so that configuring, which never reaches the network, finds it.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  scripts/install_packages.sh nodejs npm
fi
scripts/install_three.sh

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j"$(nproc)" "${target[@]}"
