#!/usr/bin/env bash
# The controller library's ABI against its committed baseline (src/control/abi/), with libabigail.
#
#   scripts/abi_check.sh [--update] [--work DIR | --prefix DIR] [--current FILE] [--baseline FILE]
#
# Builds src/control alone with debug information (the types are read from it; no other flag
# changes the ABI), installs it into a temporary prefix, runs abidw on the installed
# libfragsim_control.so.<major> with the installed public headers (--headers-dir: only the types
# the headers declare count) and compares the result with the baseline with abidiff.
#   --update         writes the baseline instead of comparing (after a release that may change it:
#                    a new major; never within 1.x)
#   --work DIR       builds there, kept between runs (default: a temporary folder)
#   --prefix DIR     reads the library installed in DIR instead of building one (it must carry
#                    debug information: Control.Library.BuildsAlone installs its gcc build so)
#   --current FILE   compares FILE, an abidw output, instead of building (the check's own test)
#   --baseline FILE  compares against FILE instead of the committed baseline
#
# The rule of a 1.x release (fragsim/control.h): it may add functions, enum values and warning
# bits; it never changes a struct, a function's signature, a default or a refusal rule. So:
#   passes  no change; added functions (listed, as abidiff reports them); enumerators added to an
#           enum (libabigail files them as harmless and does not report them); #define bits are no
#           part of the ABI at all
#   fails   a removed function (abidiff's ABIDIFF_ABI_INCOMPATIBLE_CHANGE, 8) and any other
#           change abidiff reports (ABIDIFF_ABI_CHANGE, 4) once added functions are set aside: a
#           struct's size or member, a function's parameter or return type, an enum's value;
#           and abidiff's own errors (1, 2)
# A default or a refusal rule is not in the ABI: the API tests guard those.
# Exit 0: compatible; 1: incompatible or an error; 77: abidw or abidiff is not installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
update=0 work="" prefix="" current="" baseline=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --update) update=1 ;;
    --work) work=$2; shift ;;
    --prefix) prefix=$2; shift ;;
    --current) current=$2; shift ;;
    --baseline) baseline=$2; shift ;;
    *) echo "abi_check: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done

for tool in abidw abidiff; do
  if ! command -v $tool >/dev/null 2>&1; then
    echo "abi_check: $tool not found (Debian: apt-get install abigail-tools): skipped" >&2
    exit 77
  fi
done

major=$(sed -n 's/^#define FRAGSIM_CONTROL_VERSION_MAJOR \([0-9]*\).*/\1/p' \
  "$root/src/control/include/fragsim/control.h")
minor=$(sed -n 's/^#define FRAGSIM_CONTROL_VERSION_MINOR \([0-9]*\).*/\1/p' \
  "$root/src/control/include/fragsim/control.h")
# One baseline per major: the ABI of its x.0, which every x.y must keep.
baseline=${baseline:-$root/src/control/abi/fragsim_control-$major.0.abi}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [[ -z $current ]]; then
  if [[ -z $prefix ]]; then
    work=${work:-$tmp/build}
    prefix=$tmp/prefix
    # Debug: -O0 -g, the quickest build with the types in it.
    # The build's output is shown only when it fails.
    quiet() { "$@" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }; }
    quiet cmake -S "$root/src/control" -B "$work" -DCMAKE_BUILD_TYPE=Debug
    quiet cmake --build "$work" --target fragsim_control_shared fragsim_control_static -j"$(nproc)"
    quiet cmake --install "$work" --prefix "$prefix" --component control
  fi
  library=$prefix/lib/libfragsim_control.so.$major
  [[ -f $library ]] || { echo "abi_check: $library not installed (soname?)" >&2; exit 1; }
  current=$tmp/current.abi
  # The exported functions and the types they reach, as the installed headers declare them (not
  # the library's own C++ types); no paths, lines or architecture, so the same ABI gives the same
  # file on any machine and after any edit of a comment.
  abidw --headers-dir "$prefix/include/fragsim" --exported-interfaces-only --drop-private-types \
    --no-corpus-path --no-comp-dir-path --no-show-locs --no-architecture \
    --out-file "$current" "$library"
  # The translation unit's path without the checkout's folder.
  sed -i "s|\(<abi-instr [^>]* path='\)[^']*/|\1|" "$current"
fi

if [[ $update == 1 ]]; then
  if [[ $minor != 0 ]]; then
    echo "abi_check: the baseline is $major.0's; a $major.$minor release must keep it" >&2
    exit 1
  fi
  mkdir -p "$(dirname "$baseline")"
  cp "$current" "$baseline"
  echo "abi_check: wrote $baseline"
  exit 0
fi
[[ -f $baseline ]] || { echo "abi_check: no baseline $baseline (--update writes it)" >&2; exit 1; }

# The report, additions included.
set +e
abidiff "$baseline" "$current" >"$tmp/report.txt" 2>&1
full=$?
# The same without added functions and variables: what is left must be nothing.
abidiff --no-added-syms "$baseline" "$current" >"$tmp/changes.txt" 2>&1
changes=$?
set -e
cat "$tmp/report.txt"
if (( full & 3 || changes & 3 )); then
  echo "abi_check: abidiff failed (status $full)" >&2
  exit 1
fi
if (( full & 8 || changes & 12 )); then
  echo "abi_check: INCOMPATIBLE with $(basename "$baseline") (abidiff status $full):" \
       "a $major.x release may only add functions and enum values" >&2
  exit 1
fi
if (( full & 4 )); then
  echo "abi_check: compatible: additions only (abidiff status $full)"
else
  echo "abi_check: the same ABI as $(basename "$baseline")"
fi
