#!/bin/bash
# The lesson in the real window under Xvfb: `sandbox --lesson lecture3`; PageDown moves to the
# next step and PageUp back (the screen changes, the caption says so: the --verbose log prints
# the caption bar's heading), End goes to the last step, a number and Enter jump, R restarts the
# step and it pauses again in exactly the same picture; on the platformer step (the scene has a
# player) Right is the player's key, not a step.
#   xvfb_lesson.sh SANDBOX PNG_DIFF CONVERT LESSON WORKDIR
set -u
sandbox=$1 png_diff=$2 convert=$3 lesson=$4 work=$5
. "$(dirname "$0")/xvfb_common.sh"
start_app --lesson "$lesson"

wait_for "window ready" 30
# The panel is 350 px wide at UI scale 1; the caption bar runs across the top of the scene.
caption_region="360 0 900 60"
scene_region="360 120 900 560"
focus_window
sleep 0.5
shot step1

# Step 1 opens at its setup: PageDown plays it, again goes to its moment, again to step 2.
xdotool key Next; sleep 0.3; xdotool key Next; sleep 0.3
xdotool key Next; wait_for "lesson step 2 / " 30
sleep 1; shot step2
[ "$(differing step1 step2 $caption_region)" -gt 0 ] || fail "PageDown: the caption did not change"
[ "$(differing step1 step2 $scene_region)" -gt 0 ] || fail "PageDown: the scene did not change"
echo "ok: PageDown shows step 2 ($(grep "lesson step 2" "$log" | head -1))"

xdotool key Prior; wait_for "lesson step 1 / " 30
sleep 1; shot back1
[ "$(differing step2 back1 $caption_region)" -gt 0 ] || fail "PageUp: the caption did not change"
[ "$(differing step1 back1 $caption_region)" -eq 0 ] || fail "PageUp: not step 1's caption"
echo "ok: PageUp goes back to step 1"

# End goes to the last step. Typing 2 6 Enter jumps to step 26 (the platformer, no timings on
# screen), which opens paused at its setup; PageDown plays it and it pauses by itself at t = 12 s;
# R brings it back to its setup, PageDown plays it again and it pauses at the same state: the
# same picture.
pauses() { grep -c "^paused" "$log"; }
# wait_pause N: until the log has more than N "paused" lines.
wait_pause() {
    for _ in $(seq 600); do [ "$(pauses)" -gt "$1" ] && return 0; sleep 0.1; done
    fail "$2"
}
xdotool key End; wait_for "lesson step 27 / "
echo "ok: End goes to the last step"
n=$(pauses)
xdotool key 2 6 Return; wait_for "lesson step 26 / "
echo "ok: 2 6 Enter goes to step 26"
xdotool key Next
wait_pause "$n" "step 26 did not pause by itself"
sleep 0.3; shot last_a
n=$(pauses)
xdotool key r; wait_for "lesson restart 26"
sleep 0.3; shot restarted
xdotool key Next
wait_pause "$n" "the restarted step did not pause again"
sleep 0.3; shot last_b
[ "$(differing last_a restarted $scene_region)" -gt 0 ] || fail "R: the step did not restart"
[ "$(differing last_a last_b $scene_region)" -eq 0 ] || fail "R: a different state at the pause"
echo "ok: R restarts the step and it pauses in the same state"

# Step 26's scene has a player: Right is its key (the step's script plays it) and does not step
# the lesson; PageDown still steps.
count() { grep -c -- "$1" "$log"; }
# wait_more PATTERN N: until the log has more than N lines matching PATTERN.
wait_more() {
    for _ in $(seq 300); do [ "$(count "$1")" -gt "$2" ] && return 0; sleep 0.1; done
    fail "no new '$1' in the log"
}
steps=$(count "^lesson step")
xdotool keydown Right; sleep 0.5; xdotool keyup Right
sleep 0.3
[ "$(count "^lesson step")" -eq "$steps" ] || fail "Right stepped the lesson on the platformer"
echo "ok: with a player, Right is its key and does not step the lesson"
n=$(count "lesson step 27 / ")
xdotool key Next; wait_more "lesson step 27 / " "$n"
echo "ok: PageDown steps on"

kill "$app_pid" 2>/dev/null
wait "$app_pid" 2>/dev/null
app_pid=
echo "PASS"
