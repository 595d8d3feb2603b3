#!/usr/bin/env bash
# scripts/abi_check.sh must fail on an incompatible change and pass an addition. The library's ABI
# (the committed baseline, src/control/abi/) is compared against baselines that differ from it by
# one edit each, as if the library had changed from them:
#   struct      fragsim_step_stats.warnings was an int32_t       -> a struct changed: fails
#   signature   fragsim_controller_reserve took a uint32_t count -> a signature changed: fails
#   enum        FRAGSIM_OK was 1                                 -> an enumerator moved: fails
#   removed     the baseline had one more function               -> a function removed: fails
#   added       the baseline lacks fragsim_controller_reset      -> a function added: passes
#   enumerator  fragsim_status lacks its last value              -> an enum value added: passes
#   same        the baseline itself                              -> passes
#   tests/control/abi_check_test.sh        (exit 77 where abidiff is not installed)
set -euo pipefail
command -v abidiff >/dev/null 2>&1 || { echo "abi_check_test: abidiff not found: skipped"; exit 77; }
root=$(cd "$(dirname "$0")/../.." && pwd)
check=$root/scripts/abi_check.sh
major=$(sed -n 's/^#define FRAGSIM_CONTROL_VERSION_MAJOR \([0-9]*\).*/\1/p' \
  "$root/src/control/include/fragsim/control.h")
baseline=$root/src/control/abi/fragsim_control-$major.0.abi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# edit NAME PYTHON: writes $work/NAME.abi, the baseline with the Python edit applied to its text
# `s`; the edit must change something.
edit() {
  python3 - "$baseline" "$work/$1.abi" "$2" <<'EOF'
import re, sys
s = open(sys.argv[1]).read()
before = s
exec(sys.argv[3])
if s == before:
    sys.exit("abi_check_test: the edit changed nothing: the baseline's form moved")
open(sys.argv[2], "w").write(s)
EOF
}

# The type ids of the baseline's typedefs int32_t and uint32_t.
edit struct '
i32 = re.search(r"<typedef-decl name=.int32_t. type-id=.[^\x27]*. id=.([^\x27]*).", s).group(1)
stats = re.search(r"<class-decl name=.fragsim_step_stats.*?</class-decl>", s, re.S)
block = re.sub(r"(<var-decl name=.warnings. type-id=.)[^\x27]*", r"\g<1>" + i32, stats.group(0))
s = s[:stats.start()] + block + s[stats.end():]'
edit signature '
u32 = re.search(r"<typedef-decl name=.uint32_t. type-id=.[^\x27]*. id=.([^\x27]*).", s).group(1)
s = re.sub(r"(<function-decl name=.fragsim_controller_reserve.*?<parameter type-id=.[^\x27]*. "
           r"name=.controller./>\s*<parameter type-id=.)[^\x27]*", r"\g<1>" + u32, s, flags=re.S)'
edit enum '
s = s.replace("<enumerator name=\x27FRAGSIM_OK\x27 value=\x270\x27/>",
              "<enumerator name=\x27FRAGSIM_OK\x27 value=\x271\x27/>")'
edit removed '
for pattern in (r"\s*<elf-symbol name=.fragsim_controller_reset.[^>]*/>",
                r"\s*<function-decl name=.fragsim_controller_reset.*?</function-decl>"):
    m = re.search(pattern, s, re.S)
    s = s[:m.end()] + m.group(0).replace("fragsim_controller_reset", "fragsim_controller_gone") + s[m.end():]'
edit added '
s = re.sub(r"\s*<elf-symbol name=.fragsim_controller_reset.[^>]*/>", "", s)
s = re.sub(r"\s*<function-decl name=.fragsim_controller_reset.*?</function-decl>", "", s, flags=re.S)'
edit enumerator '
s = re.sub(r"\s*<enumerator name=.FRAGSIM_ERROR_STALE_ID. value=.7./>", "", s)'
cp "$baseline" "$work/same.abi"

failures=0
expect() {  # pass|fail, name
  local status=0
  "$check" --current "$baseline" --baseline "$work/$2.abi" >"$work/$2.out" 2>&1 || status=$?
  if [[ $status == 77 || $status == 2 ]]; then
    cat "$work/$2.out"; echo "abi_check_test: $2: the check did not run (status $status)"; exit 1
  fi
  if [[ ($1 == pass && $status == 0) || ($1 == fail && $status == 1) ]]; then
    local verb=passes; [[ $1 == fail ]] && verb=fails
    echo "ok   $2: $verb ($(tail -n 1 "$work/$2.out"))"
  else
    cat "$work/$2.out"
    echo "FAIL $2: expected the check to $1, it exited $status"
    failures=$((failures + 1))
  fi
}
expect fail struct
expect fail signature
expect fail enum
expect fail removed
expect pass added
expect pass enumerator
expect pass same
echo "$((7 - failures)) passed, $failures failed"
[[ $failures == 0 ]]
