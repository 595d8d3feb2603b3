#!/usr/bin/env bash
# The npm package as a user gets it: the tarball scripts/web_build.sh packs, installed into an
# empty folder; the README's example run from there; and TypeScript (npm typescript, pinned below,
# installed into NPM_PREFIX) checking tests/web/typed_example.ts and the README's example against
# the installed declarations.
# Usage: tests/web/package_test.sh WEB_DIR NPM_PREFIX     (WEB_DIR: scripts/web_build.sh's OUT)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
prefix="$2"
typescript=5.4.5

# The tarball of the library's version: the package's version is the library's.
version=$(sed -n 's/^#define FRAGSIM_CONTROL_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p' \
  "$root/src/control/include/fragsim/control.h" | paste -sd.)
tarball="$(realpath "$1")/fragsim-control-$version.tgz"
[[ -f $tarball ]] || { echo "package_test: no $tarball (scripts/web_build.sh makes it)" >&2; exit 1; }
# What the tarball holds: the files package.json lists, and nothing else.
listing=$(tar tzf "$tarball" | sort | tr '\n' ' ')
expected="package/LICENSE package/README.md package/fragsim.d.ts package/fragsim.mjs package/fragsim_control_wasm.mjs package/package.json "
[[ $listing == "$expected" ]] || {
  echo "package_test: the tarball holds: $listing; expected: $expected" >&2
  exit 1
}

installed="$(node -p "try { require('$prefix/node_modules/typescript/package.json').version }
                      catch (e) { '' }")"
if [[ $installed != "$typescript" ]]; then
  npm install --no-audit --no-fund --silent --prefix "$prefix" "typescript@$typescript"
fi
tsc="$prefix/node_modules/.bin/tsc"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
npm init -y >/dev/null
npm pkg set type=module
npm install --no-audit --no-fund --silent --offline "$tarball"

# The README's example, as a user would copy it.
python3 - "$tmp/node_modules/fragsim-control/README.md" >example.mjs <<'PY'
import re, sys
blocks = re.findall(r"```js\n(.*?)```", open(sys.argv[1]).read(), re.S)
assert len(blocks) == 1, f"the README has {len(blocks)} js blocks, not 1"
sys.stdout.write(blocks[0])
PY
[[ $(wc -l <example.mjs) -le 22 ]] || { echo "package_test: the README's example is over 20 lines" >&2; exit 1; }
output=$(node example.mjs)
echo "example.mjs: $output"
# Its first fragment flies straight into the camera's eye: edge-min must push it.
[[ $output =~ ^[1-9][0-9]*\ pushed ]] || { echo "package_test: the example pushed nothing" >&2; exit 1; }

cp "$root/tests/web/typed_example.ts" .
"$tsc" --noEmit --strict --target es2022 --module nodenext --moduleResolution nodenext \
  --allowJs --checkJs typed_example.ts example.mjs
echo "package_test: installed from $(basename "$tarball"), the example ran, tsc found no error"
