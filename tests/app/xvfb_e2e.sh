#!/bin/bash
# End-to-end test of the real window: start Xvfb on a free display, run `sandbox --verbose` on a
# scene, press P, R, S and Space and drag a slider with xdotool, and check through screenshots
# (xwd) and the app's --verbose log that each acted. Every wait has a timeout; Xvfb and the app
# are stopped on exit.
#   xvfb_e2e.sh SANDBOX PNG_DIFF CONVERT SCENE WORKDIR
set -u
sandbox=$1 png_diff=$2 convert=$3 scene=$4 work=$5
. "$(dirname "$0")/xvfb_common.sh"
start_app "$scene"

wait_for "window ready" 30
# The panel is 350 px wide at UI scale 1; the scene is right of it, the status badge at its top.
scene_region="360 40 900 660"
badge_region="350 0 500 36"
focus_window

# The scene moves.
shot moving_a; sleep 0.6; shot moving_b
[ "$(differing moving_a moving_b $scene_region)" -gt 0 ] || fail "the scene does not move"
echo "ok: the scene moves"

# P pauses: two screenshots are identical; P again resumes.
xdotool key p; wait_for "^paused"
sleep 0.3; shot paused_a; sleep 0.6; shot paused_b
[ "$(differing paused_a paused_b 0 0 1280 720)" -eq 0 ] || fail "P did not pause"
[ "$(differing moving_b paused_a $badge_region)" -gt 0 ] || fail "no PAUSED badge"
echo "ok: P pauses"

# S switches the method: the log says so and the badge changes.
xdotool key s; wait_for "method: move-and-correct"
sleep 0.3; shot method
[ "$(differing paused_b method $badge_region)" -gt 0 ] || fail "S did not change the label"
echo "ok: S switches the method"

# R resets while paused: the picture goes back to frame 0 (t = 0) and stays.
xdotool key r; wait_for "^reset"
sleep 0.3; shot reset_a
[ "$(differing method reset_a $scene_region)" -gt 0 ] || fail "R did not move the blocks back"
xdotool key p; wait_for "^resumed"; sleep 0.5; xdotool key p
wait_for "^paused"; grep -c "^paused" "$log" | grep -q 2 || fail "second pause missing"
xdotool key r; sleep 0.3; shot reset_b
[ "$(differing reset_a reset_b $scene_region)" -eq 0 ] || fail "two resets differ"
echo "ok: R resets"

# Space: slow motion on (log and badge), and the simulation still advances, slowly.
xdotool key space; wait_for "slow motion: on"
xdotool key p; wait_for "^resumed"
sleep 0.3; shot slow_a; sleep 1.0; shot slow_b
[ "$(differing reset_b slow_a $badge_region)" -gt 0 ] || fail "no slow-motion badge"
[ "$(differing slow_a slow_b $scene_region)" -gt 0 ] || fail "slow motion froze the scene"
xdotool key space; wait_for "slow motion: off"
echo "ok: Space slows down"

# Drag the bounciness slider to its left end: C goes down (the log reports each change).
read -r _ _ sx sy sw sh < <(grep -m1 "^widget bounciness" "$log")
[ -n "${sh:-}" ] || fail "no slider position in the log"
y=$((sy + sh / 2))
xdotool mousemove $((sx + sw * 3 / 4)) $y mousedown 1 sleep 0.2 \
    mousemove $((sx + sw / 2)) $y sleep 0.2 mousemove $((sx + 2)) $y sleep 0.2 mouseup 1
wait_for "bounciness: 0" 5
park
shot slider
echo "ok: the slider changes bounciness ($(grep "bounciness:" "$log" | tail -1))"

# Esc quits cleanly.
xdotool key Escape
for _ in $(seq 50); do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$app_pid" 2>/dev/null && fail "Esc did not quit"
wait "$app_pid"; code=$?
app_pid=
[ "$code" -eq 0 ] || fail "the app exited with $code"
grep -q "^quit" "$log" || fail "no quit in the log"
echo "ok: Esc quits"
echo "PASS"
