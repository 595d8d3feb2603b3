#!/usr/bin/env bash
# The controller library as a game would take it: installs a build into a temporary prefix, then
# builds and runs examples/minimal_c, examples/ode_world and examples/bullet against the installed
# package only (find_package(fragsim_control CONFIG)), the C example also through pkg-config,
# shared and static.
#   scripts/examples_test.sh [BUILD_DIR]     (default build/release)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" --component control >/dev/null
for f in include/fragsim/control.h include/fragsim/types.h lib/libfragsim_control.so.1 \
         lib/libfragsim_control.so lib/libfragsim_control.a \
         lib/cmake/fragsim_control/fragsim_control-config.cmake lib/pkgconfig/fragsim-control.pc; do
  [[ -e $prefix/$f ]] || { echo "examples_test: $f not installed" >&2; exit 1; }
done

# The examples see the installed package and nothing of the source tree or the build.
build_example() {  # name, extra cmake arguments...
  local name=$1; shift
  cmake -S "$root/examples/$name" -B "$work/$name$*" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$work/$name$*" >/dev/null
}

build_example minimal_c
"$work/minimal_c/minimal_c"
# ldd's output is taken whole first: `ldd | grep -q` under pipefail fails at random when grep
# exits at its match and ldd, still writing, dies of SIGPIPE.
libs=$(ldd "$work/minimal_c/minimal_c")
grep -q "$prefix/lib/libfragsim_control.so" <<<"$libs" ||
  { echo "examples_test: minimal_c does not use the installed shared library" >&2; exit 1; }

build_example minimal_c -Dfragsim_control_USE_STATIC=ON
# A C program linking the static C++ archive: CMake must bring the C++ runtime along.
"$work/minimal_c-Dfragsim_control_USE_STATIC=ON/minimal_c" >/dev/null
libs=$(ldd "$work/minimal_c-Dfragsim_control_USE_STATIC=ON/minimal_c")
! grep -q libfragsim_control <<<"$libs" ||
  { echo "examples_test: the static build still needs the shared library" >&2; exit 1; }

# pkg-config, shared and static.
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
cc -std=c99 -Wall -Wextra -Werror -o "$work/pc_shared" "$root/examples/minimal_c/main.c" \
  $(pkg-config --cflags --libs fragsim-control) -Wl,-rpath,"$prefix/lib"
"$work/pc_shared" >/dev/null
cc -std=c99 -Wall -Wextra -Werror -o "$work/pc_static" "$root/examples/minimal_c/main.c" \
  $(pkg-config --cflags fragsim-control) "$prefix/lib/libfragsim_control.a" \
  $(pkg-config --libs-only-other --libs-only-l --static fragsim-control | sed 's/-lfragsim_control//')
"$work/pc_static" >/dev/null

# The engine examples need their engine. By hand a missing one is skipped with a word; under ctest
# (FRAGSIM_EXAMPLES_REQUIRED=1, scripts/setup.sh installs both) it fails the test.
engine_missing() {  # example, pkg-config name
  if [[ ${FRAGSIM_EXAMPLES_REQUIRED:-0} == 1 ]]; then
    echo "examples_test: $2 not found by pkg-config: $1 cannot be built" >&2
    exit 1
  fi
  echo "examples_test: $2 not found by pkg-config: $1 skipped" >&2
}

if pkg-config --exists ode; then
  build_example ode_world
  "$work/ode_world/ode_world"
else
  engine_missing ode_world ode
fi

# The controller in Bullet: exits 1 unless the blasts hit the camera without it and never with it.
if pkg-config --exists bullet; then
  build_example bullet
  "$work/bullet/bullet_world"
else
  engine_missing bullet bullet
fi
echo "examples_test: ok"
