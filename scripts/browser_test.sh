#!/usr/bin/env bash
# The HTML report in a real browser: writes `fragsim compare --report` for a scene, opens
# index.html from disk in headless Chromium (driven through chromedriver by
# tests/browser/check_report.py) and fails if the console shows an error, an image did not load,
# a chart has no size or anything outside the report's folder was fetched, or if the 3D view is
# missing, reports no WebGL, draws only background or does not move with the time slider; keeps a
# full-page screenshot and one of the 3D view (SCREENSHOT.3d.png). Installs chromium,
# chromium-driver and python3 first if they are missing.
# Usage: scripts/browser_test.sh [FRAGSIM_BINARY [SCREENSHOT.png [SCENE.ini]]]
#   defaults: build/release/fragsim, a temporary file, data/scenes/thesis125.ini
# Exit status: 0 passed, 1 failed, 77 skipped (the packages are missing and cannot be installed:
# neither root nor sudo; ctest reports the test as skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
fragsim="${1:-$root/build/release/fragsim}"
screenshot="${2:-}"
scene="${3:-$root/data/scenes/thesis125.ini}"

packages=(chromium chromium-driver python3)
if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "browser_test: skipped: ${missing[*]} missing, and neither root nor sudo to install them" \
         "(run scripts/install_packages.sh ${packages[*]} as root)" >&2
    exit 77
  fi
fi
"$root/scripts/install_packages.sh" "${packages[@]}"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$fragsim" compare --scene "$scene" --report "$tmp/report" >"$tmp/compare.log" 2>&1 || {
  cat "$tmp/compare.log" >&2
  echo "browser_test: fragsim compare --report failed" >&2
  exit 1
}
python3 "$root/tests/browser/check_report.py" "$tmp/report/index.html" \
  "${screenshot:-$tmp/screenshot.png}"
