#!/usr/bin/env bash
# Builds fragsim for the web: the controller library (src/control) compiled to WebAssembly with
# emscripten, its JavaScript API as an npm package folder and tarball (src/web/package), the live
# demo page (examples/web: three.js and Rapier, from npm), and the library's replay program for
# Node, which the web tests run against the tool's dumps.
#
#   scripts/web_build.sh [OUT [NPM_PREFIX]]    defaults: build/web, OUT/npm
#
# Installs emscripten, Node.js and npm from Debian when they are missing, and the page's npm
# packages (pinned below) into NPM_PREFIX. Writes:
#   OUT/package/                   the npm package folder (fragsim.mjs, fragsim.d.ts, the module)
#   OUT/fragsim-control-X.Y.Z.tgz  what `npm pack` makes of it
#   OUT/page/index.html            the demo page: one file, opens from disk
#   OUT/replay.cjs                 tests/control/replay.c against the WebAssembly library
# docs/library.md ("In a web page") says why emscripten and how the module is built.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/build/web}")
npm_prefix=$(realpath -m "${2:-$out/npm}")
jobs=$(nproc)
# The page's npm packages. three is the report's pin (CMakeLists.txt, FRAGSIM_THREE_VERSION).
three=0.170.0
rapier=0.19.3

"$root/scripts/install_packages.sh" emscripten
command -v node >/dev/null 2>&1 || "$root/scripts/install_packages.sh" nodejs
command -v npm >/dev/null 2>&1 || "$root/scripts/install_packages.sh" npm
command -v python3 >/dev/null 2>&1 || "$root/scripts/install_packages.sh" python3 # the page
# emcc's JavaScript optimiser needs Debian's acorn, which a node not from Debian does not find.
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs

version=$(sed -n 's/^#define FRAGSIM_CONTROL_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p' \
  "$root/src/control/include/fragsim/control.h" | paste -sd.)
package_version=$(node -p "require('$root/src/web/package/package.json').version")
if [[ $version != "$package_version" ]]; then
  echo "web_build: src/web/package/package.json says $package_version, the library is $version" >&2
  exit 1
fi

# The library as the native build makes it (Release, -ffp-contract=off, warnings as errors), with
# WebAssembly's own exception handling (the library turns a failed allocation into
# FRAGSIM_ERROR_OUT_OF_MEMORY by catching std::bad_alloc) and its 128-bit SIMD, which the
# library's two-lane passes (strategies/lanes.hpp) compile to: 1.2 to 2.3 times faster, the
# same bits (docs/benchmarks.md, "In WebAssembly").
wasm_flags="-fwasm-exceptions -msimd128"
quiet() { "$@" >"$out/build.log" 2>&1 || { cat "$out/build.log" >&2; exit 1; }; }
mkdir -p "$out"
quiet emcmake cmake -S "$root/src/control" -B "$out/control" -DCMAKE_BUILD_TYPE=Release \
  -DFRAGSIM_WERROR=ON -DEigen3_DIR=/usr/share/eigen3/cmake -DCMAKE_CXX_FLAGS="$wasm_flags" \
  -Wno-dev
quiet cmake --build "$out/control" --target fragsim_control_static -j"$jobs"
library=$out/control/libfragsim_control.a

# The module: one ES module with the WebAssembly inside it (SINGLE_FILE), so that it loads from
# file:// and in Node with nothing to fetch. A library installs no process-wide handlers in Node
# (NODEJS_CATCH_*: emscripten's would rethrow every error of the program from inside the module,
# and Node would print the module's whole line of source with it).
rm -rf "$out/package"
mkdir -p "$out/package"
cp "$root/src/web/package/"{fragsim.mjs,fragsim.d.ts,package.json,README.md} "$root/LICENSE" \
  "$out/package/"
exported=_malloc,_free,_fragsim_version_string,_fragsim_status_string,_fragsim_controller_create
quiet emcc -O3 $wasm_flags -std=c99 -Wall -Wextra -Werror \
  -I"$root/src/control/include" "$root/src/web/binding/web_binding.c" "$library" \
  -o "$out/package/fragsim_control_wasm.mjs" \
  -sMODULARIZE=1 -sEXPORT_ES6=1 -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sFILESYSTEM=0 \
  -sNODEJS_CATCH_EXIT=0 -sNODEJS_CATCH_REJECTION=0 \
  -sEXPORTED_FUNCTIONS=$exported -sEXPORTED_RUNTIME_METHODS=UTF8ToString \
  --extern-pre-js "$root/src/web/binding/es_module_prelude.js"
(cd "$out/package" && quiet npm pack --silent --pack-destination "$out")

# The demo page, with three.js and Rapier inside it.
installed() { node -p "try { require('$npm_prefix/node_modules/$1/package.json').version } catch (e) { '' }"; }
if [[ $(installed three) != "$three" || $(installed @dimforge/rapier3d-compat) != "$rapier" ]]; then
  quiet npm install --no-audit --no-fund --silent --save-exact --prefix "$npm_prefix" \
    "three@$three" "@dimforge/rapier3d-compat@$rapier"
fi
quiet python3 "$root/examples/web/build_page.py" "$out/package" "$npm_prefix" "$out/page"

# The replay of the tool's dumps, as a Node program reading files from disk.
quiet emcc -O3 $wasm_flags -std=c99 -Wall -Wextra -Werror -I"$root/src/control/include" \
  "$root/tests/control/replay.c" "$library" -o "$out/replay.cjs" \
  -sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1 -sSINGLE_FILE=1
rm -f "$out/build.log"
echo "web_build: $out/package ($(du -k "$out/package/fragsim_control_wasm.mjs" | cut -f1) KB module)," \
  "$out/fragsim-control-$version.tgz, $out/page/index.html ($(du -k "$out/page/index.html" | cut -f1) KB)," \
  "$out/replay.cjs"
