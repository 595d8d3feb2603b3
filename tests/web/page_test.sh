#!/usr/bin/env bash
# fragsim's web demo in a real browser: opens the page build_page.py wrote (examples/web) from
# disk in headless Chromium, driven through chromedriver by tests/web/page_test.py, and fails
# unless the scripted blast cuts the near plane in at least 8 of 10 seeds without the controller
# and in none with edge-min, the runs repeat exactly, the canvas draws, the live page steps its
# world and the console shows no error. Keeps a screenshot. Installs chromium, chromium-driver and
# python3 first if they are missing.
# Usage: tests/web/page_test.sh PAGE_HTML [SCREENSHOT.png]   (default: a temporary file)
# Exit status: 0 passed, 1 failed, 77 skipped (the packages are missing and cannot be installed:
# neither root nor sudo; ctest reports the test as skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: tests/web/page_test.sh PAGE_HTML [SCREENSHOT.png]" >&2
  exit 2
fi
page="$1"
screenshot="${2:-}"

packages=(chromium chromium-driver python3)
if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "page_test: skipped: ${missing[*]} missing, and neither root nor sudo to install them" \
         "(run scripts/install_packages.sh ${packages[*]} as root)" >&2
    exit 77
  fi
fi
"$root/scripts/install_packages.sh" "${packages[@]}"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 "$root/tests/web/page_test.py" "$page" "${screenshot:-$tmp/screenshot.png}"
