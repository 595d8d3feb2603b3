#!/usr/bin/env bash
# `fragsim play` end to end in a real window: Xvfb on a free display, a scripted 2-second route
# sent by xdotool (keys held for spans of simulated time, read from the window's title), a screenshot of the window (xwd) that must show
# the scene and the HUD, Esc, then the recorded flight replayed with `fragsim compare`: its `none`
# run must count the near-plane fragments and camera hits the HUD reported. Then the same without
# any display: one line, exit status 2.
# Usage: tests/play/play_window_test.sh FRAGSIM_BINARY SOURCE_DIR
set -euo pipefail
fragsim="$1"
root="$2"
scene="$root/data/scenes/front.ini"
here="$(cd "$(dirname "$0")" && pwd)"

tmp="$(mktemp -d)"
xvfb_pid=""
play_pid=""
cleanup() {
  [ -n "$play_pid" ] && kill "$play_pid" 2>/dev/null || true
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() {
  echo "play_window_test: $*" >&2
  for f in "$tmp"/play.out "$tmp"/play.err; do [ -s "$f" ] && sed 's/^/  | /' "$f" >&2; done
  exit 1
}

# No display at all: one line naming the problem, exit status 2, no window attempted.
set +e
env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$fragsim" play --scene "$scene" \
  >"$tmp/nodisplay.out" 2>"$tmp/nodisplay.err"
status=$?
set -e
[ "$status" -eq 2 ] || fail "without a display: exit status $status, expected 2"
[ "$(wc -l <"$tmp/nodisplay.err")" -eq 1 ] || fail "without a display: not one line: $(cat "$tmp/nodisplay.err")"
grep -q "^fragsim play: no display" "$tmp/nodisplay.err" || fail "without a display: $(cat "$tmp/nodisplay.err")"

# The variables set to empty strings name nothing: the same one line, never a window nobody sees
# (an empty SDL_VIDEODRIVER once let SDL fall back on its offscreen driver and wait forever).
set +e
env -u WAYLAND_DISPLAY DISPLAY= SDL_VIDEODRIVER= timeout 20 "$fragsim" play --scene "$scene" \
  >"$tmp/emptyvars.out" 2>"$tmp/emptyvars.err"
status=$?
set -e
[ "$status" -eq 2 ] || fail "with DISPLAY and SDL_VIDEODRIVER empty: exit status $status, expected 2"
[ "$(wc -l <"$tmp/emptyvars.err")" -eq 1 ] ||
  fail "with empty variables: not one line: $(cat "$tmp/emptyvars.err")"
grep -q "^fragsim play: no display" "$tmp/emptyvars.err" ||
  fail "with empty variables: $(cat "$tmp/emptyvars.err")"

# Xvfb picks a free display itself and writes its number to the descriptor.
exec 3>"$tmp/display"
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 3>&-
for _ in $(seq 1 200); do
  [ -s "$tmp/display" ] && break
  kill -0 "$xvfb_pid" 2>/dev/null || fail "Xvfb did not start: $(cat "$tmp/xvfb.log")"
  sleep 0.1
done
[ -s "$tmp/display" ] || fail "Xvfb gave no display number"
export DISPLAY=":$(head -n1 "$tmp/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER

cd "$tmp"
# Under AddressSanitizer, no leak check for the window's process: SDL dlopens the X libraries,
# whose loader allocations LeakSanitizer reports as leaks without symbols (and GCC 12's crashes
# scanning their thread-local storage). Memory errors are still checked; the session's own code
# is leak-checked headless (tests/play/play_session_test.cpp).
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  "$fragsim" play --scene "$scene" --strategy none --record "$tmp/flight.csv" \
  >"$tmp/play.out" 2>"$tmp/play.err" &
play_pid=$!
# The window may take long to appear on a loaded machine: wait for it, not for a guessed time.
window="$(timeout 120 xdotool search --sync --onlyvisible --name '^fragsim play' | head -n1)" ||
  fail "no play window appeared"
[ -n "$window" ] || fail "no play window appeared"
timeout 60 xdotool windowfocus --sync "$window" || fail "could not focus the play window"
xdotool mousemove --window "$window" 320 180

# The route is timed in simulated time, read from the window's title ("... - flight 1, none,
# 1.2 s"): a loaded machine flies fewer steps per second of the clock, so a route in wall-clock
# sleeps moved the camera less (and at 61 ms a frame, not enough); this way it only takes longer.
sim_s() {
  xdotool getwindowname "$window" | sed -nE 's/.*, ([0-9]+\.[0-9]) s$/\1/p'
}
# Waits until simulated time has gone `$1` s past what it is now (10 minutes at most).
fly_for() {
  local from now
  from="$(sim_s)"
  [ -n "$from" ] || fail "the window's title shows no flight time: $(xdotool getwindowname "$window")"
  for _ in $(seq 1 12000); do
    now="$(sim_s)"
    if [ -n "$now" ] && awk -v a="$now" -v b="$from" -v d="$1" 'BEGIN { exit !(a - b >= d) }'; then
      return 0
    fi
    sleep 0.05
  done
  fail "simulated time did not advance by $1 s in 10 minutes"
}
for _ in $(seq 1 1200); do [ -n "$(sim_s)" ] && break; sleep 0.1; done

# The route: 1 s forward, then 0.5 s strafing right, then 0.5 s strafing right while turning (the
# title's 0.1 s steps make each at least 0.1 s shorter in simulated time).
xdotool keydown w
fly_for 1.0
xdotool keyup w keydown d
fly_for 0.5
xdotool keydown e
fly_for 0.5
xdotool keyup e keyup d
fly_for 0.2

xwd -id "$window" -silent >"$tmp/shot.xwd" || fail "xwd could not take a screenshot"
python3 "$here/check_screenshot.py" "$tmp/shot.xwd" || fail "the screenshot is wrong"

xdotool key Escape
for _ in $(seq 1 600); do
  kill -0 "$play_pid" 2>/dev/null || break
  sleep 0.1
done
set +e
wait "$play_pid"
status=$?
set -e
play_pid=""
[ "$status" -eq 0 ] || fail "fragsim play exited with status $status"

# What the HUD showed last: "flight 1: none, T s (N steps): near X, cam Y".
line="$(grep '^flight 1: none' "$tmp/play.out")" || fail "no flight line"
near="$(sed -E 's/.*: near ([0-9]+), cam ([0-9]+)$/\1/' <<<"$line")"
cam="$(sed -E 's/.*: near ([0-9]+), cam ([0-9]+)$/\2/' <<<"$line")"
steps="$(sed -E 's/.*\(([0-9]+) steps\).*/\1/' <<<"$line")"
# A loaded machine (or a sanitizer build) slows simulated time: the counts must still agree, and
# the route still moves the camera, if less far.
[ "$steps" -ge 10 ] || fail "only $steps steps flown: $line"
grep -q "fragsim compare --scene $tmp/flight.ini" "$tmp/play.out" || fail "no replay command printed"
[ -s "$tmp/flight.csv" ] && [ -s "$tmp/flight.ini" ] || fail "the flight was not recorded"
# The route moved the camera forward (-z) and to the right (+x).
awk -F, 'NR == 2 { x0 = $4; z0 = $6 } END { if (!(z0 - $6 > 0.2 && $4 - x0 > 0.02)) exit 1 }' \
  "$tmp/flight.csv" || fail "the recorded track did not follow the keys"

"$fragsim" compare --scene "$tmp/flight.ini" --strategies none --no-occlusion >"$tmp/replay.out" ||
  fail "the replay failed: $(cat "$tmp/replay.out")"
grep -q " $steps steps of " "$tmp/replay.out" || fail "the replay has not $steps steps"
row="$(grep -E '^none ' "$tmp/replay.out")" || fail "no none row in the replay"
read -r _ r_near _ r_cam _ <<<"$row"
[ "$r_near" = "$near" ] || fail "replay counts $r_near near-plane fragments, the HUD $near"
[ "$r_cam" = "$cam" ] || fail "replay counts $r_cam camera hits, the HUD $cam"
echo "play_window_test: $steps steps, near $near, cam $cam, replayed the same"
