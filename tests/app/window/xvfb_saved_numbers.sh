#!/bin/bash
# Numbers kept as set (issue 41), in the real window under Xvfb: C typed into the bounciness
# slider (Ctrl+click, 0.44) and saved with Ctrl+S is written as 0.44, not as the float the slider
# holds (0.4399999976158142), and the scene's "duration" is kept; C dragged with the slider is
# saved with the digits the slider showed (at most two decimals).
#   xvfb_saved_numbers.sh SANDBOX PNG_DIFF CONVERT SCENE WORKDIR
set -u
sandbox=$1 png_diff=$2 convert=$3 scene=$4 work=$5
. "$(dirname "$0")/xvfb_common.sh"
mkdir -p "$work/saves"
cd "$work/saves" || fail "no $work/saves" # Save offers the working directory for a shipped scene
# open_scene: the app on the scene, and where its bounciness slider is (sx, sw, y). A save moves
# the panel's rows (its note), so each case starts the app afresh.
open_scene() {
    start_app "$scene"
    wait_for "window ready" 30
    focus_window
    read -r _ _ sx sy sw sh < <(grep -m1 "^widget bounciness" "$log")
    [ -n "${sh:-}" ] || fail "no slider position in the log"
    y=$((sy + sh / 2))
}
# quit: Ctrl+Q (nothing unsaved after a save: it quits at once).
quit() {
    park
    xdotool key ctrl+q
    for _ in $(seq 50); do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$app_pid" 2>/dev/null && fail "Ctrl+Q did not quit"
    wait "$app_pid"
    app_pid=
}

# saved_value FILE: the text of "bounciness" in the saved file, as written.
saved_value() {
    python3 -c 'import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
print(re.search(r"\"bounciness\": ([^,\n]+)", text).group(1))' "$1"
}
# save_as FILE: Ctrl+S, Enter (the offered name), until FILE is there.
save_as() {
    park
    xdotool key ctrl+s
    sleep 0.8 # the dialog opens with its field focused (no log line says so)
    xdotool key Return
    for _ in $(seq 50); do [ -s "$1" ] && return 0; sleep 0.1; done
    fail "Ctrl+S, Enter wrote no $1 ($(ls "$work/saves"))"
}

# Typed: Ctrl+click the slider opens it for typing; 0.44 and Enter.
open_scene
xdotool mousemove $((sx + sw / 2)) $y keydown ctrl click 1 keyup ctrl
sleep 0.3
xdotool type --delay 50 "0.44"
xdotool key Return
wait_for "bounciness: 0.44" 5
save_as lecture_example_1.json
value=$(saved_value lecture_example_1.json)
[ "$value" = "0.44" ] || fail "C typed as 0.44 was saved as $value"
grep -q '"duration": 3.0,' lecture_example_1.json || fail "the scene's duration was not saved"
echo "ok: 0.44 typed is saved as 0.44, the duration kept"

quit

# Dragged: whatever the slider shows, at most two decimals, is what is saved.
open_scene
xdotool mousemove $((sx + sw / 4)) $y sleep 0.3 mousedown 1 sleep 0.2 \
    mousemove $((sx + sw / 3)) $y sleep 0.2 mousemove $((sx + sw / 3 + 3)) $y sleep 0.2 mouseup 1
sleep 0.5
shown=$(grep "^bounciness: " "$log" | tail -1 | cut -d' ' -f2)
[ "$shown" != "0.44" ] || fail "the drag did not change C"
save_as lecture_example_1-2.json
value=$(saved_value lecture_example_1-2.json)
[ "$value" = "$shown" ] || fail "C dragged to $shown was saved as $value"
[[ "$value" =~ ^[01](\.[0-9]{1,2})?$ ]] || fail "C dragged was saved as $value: more digits than shown"
echo "ok: C dragged to $shown is saved as $value"
quit
echo "PASS"
