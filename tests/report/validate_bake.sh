#!/usr/bin/env bash
# The bake checked as the glTF ecosystem checks files: bakes shipped scenes with `fragsim compare
# --bake` (thesis125, its 125 grid cubes, every strategy: one file each) and `fragsim run --bake`
# (voronoi's Voronoi cells; hulls imported from a file `fracture` wrote, itself checked too; front,
# the default scene's 1,728 pieces, which must stay under 20 MB), then runs the Khronos glTF
# validator (npm package gltf-validator, pinned below) under node on every file written, through
# tests/report/validate_gltf.js; fails if the validator reports an error in any of them. Installs
# Debian's nodejs and npm when node or npm is missing, and the validator into NPM_PREFIX.
# Usage: tests/report/validate_bake.sh FRAGSIM_BINARY NPM_PREFIX
# Exit status: 0 passed, 1 failed, 77 skipped (node or npm missing and neither root nor sudo to
# install them; ctest reports the test as skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
fragsim="$1"
prefix="$2"
version=2.0.0-dev.3.10

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
    echo "validate_bake: skipped: node or npm missing, and neither root nor sudo to install them" \
         "(run scripts/install_packages.sh nodejs npm as root)" >&2
    exit 77
  fi
  "$root/scripts/install_packages.sh" nodejs npm
fi
installed="$(node -p "try { require('$prefix/node_modules/gltf-validator/package.json').version }
                      catch (e) { '' }")"
if [ "$installed" != "$version" ]; then
  npm install --no-audit --no-fund --silent --prefix "$prefix" "gltf-validator@$version"
fi

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
bake() {
  "$fragsim" "$@" --no-occlusion >"$tmp/log" 2>&1 || {
    cat "$tmp/log" >&2
    echo "validate_bake: fragsim $* failed" >&2
    exit 1
  }
}
bake compare --scene "$root/data/scenes/thesis125.ini" --bake "$tmp/thesis125.glb"
bake run --scene "$root/data/scenes/voronoi.ini" --strategy edge-min --bake "$tmp/voronoi.glb"
# Imported hulls: 40 Voronoi cells written by `fracture`, read back as object.mesh_file.
"$fragsim" fracture --scene "$root/data/scenes/thesis125.ini" --object.pattern voronoi \
  --object.pieces 40 --out "$tmp/pieces.glb" >"$tmp/log" 2>&1 || {
  cat "$tmp/log" >&2
  echo "validate_bake: fragsim fracture failed" >&2
  exit 1
}
bake run --scene "$root/data/scenes/thesis125.ini" --object.mesh_file "$tmp/pieces.glb" \
  --strategy edge-min --bake "$tmp/hull.glb"
# The default scene at full size: 1,728 pieces keyed at 181 steps must stay under 20 MB.
bake run --scene "$root/data/scenes/front.ini" --strategy edge-min --bake "$tmp/front.glb"
size="$(stat -c %s "$tmp/front.glb")"
if [ "$size" -gt 20000000 ]; then
  echo "validate_bake: front.ini's bake is $size bytes, over 20 MB" >&2
  exit 1
fi
files=("$tmp"/*.glb)
[ "${#files[@]}" -eq 11 ] || { echo "validate_bake: expected 11 files, got ${#files[@]}" >&2; exit 1; }
NODE_PATH="$prefix/node_modules" node "$root/tests/report/validate_gltf.js" "${files[@]}"
