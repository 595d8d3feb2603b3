#!/usr/bin/env bash
# Installs three.js, the npm package `three` at the version CMakeLists.txt pins
# (FRAGSIM_THREE_VERSION), into PREFIX (default build/npm), where configuring looks for it to embed
# in the report's 3D view. Configuring never reaches the network; this script is the step that
# does, and scripts/setup.sh runs it. Without npm or the registry it says so and exits 0: the
# build then goes on, and its reports have no 3D view.
# Usage: scripts/install_three.sh [PREFIX]
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=$(realpath -m "${1:-build/npm}")
version=$(sed -n 's/^set(FRAGSIM_THREE_VERSION \([0-9][0-9.]*\))$/\1/p' CMakeLists.txt)
if [ -z "$version" ]; then
  echo "install_three: no FRAGSIM_THREE_VERSION in CMakeLists.txt" >&2
  exit 1
fi
package="$prefix/node_modules/three/package.json"
if [ -f "$package" ] && grep -q "\"version\": \"$version\"" "$package"; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  echo "install_three: npm not found (scripts/setup.sh installs it): reports will have no 3D view" >&2
  exit 0
fi
if ! timeout 300 npm install --no-audit --no-fund --silent --prefix "$prefix" "three@$version"; then
  echo "install_three: npm install three@$version failed: reports will have no 3D view" >&2
fi
