#!/bin/bash
# The lecture's keys in the real window under Xvfb, whatever had the focus before: `sandbox
# --lesson lecture3`; the panel's C slider dragged, then typed into (Ctrl+click): the digits go to
# the field, Enter takes the value, Esc undoes it, F5 and PageDown act and leave the field; then,
# the slider the last control worked, Right three times, Space, "1 3 Enter", S, Shift+R, F5
# twice, and the arrows on the platformer step (26). Each key is checked through the --verbose log: its "key"
# line names the action of the key table (app/gui/app/input_map.cpp), the lines it causes are
# those, and nothing else happens: the keyboard stays the scene's (no "keyboard:" line, no key
# taken by ImGui's keyboard navigation), no setting changes that the key does not change, and no
# focus ring shows in the panel (its colour counted in screenshots). Then the keyboard's handover:
# F6 gives it to the panel (the ring shows: the count can fail), the arrows are then the panel's,
# Esc gives it back; a click in the panel leaves it to the scene, a click in the scene takes it
# back from the panel.
#   xvfb_keys.sh SANDBOX PNG_DIFF CONVERT WORKDIR
set -u
sandbox=$1 png_diff=$2 convert=$3 work=$4
. "$(dirname "$0")/xvfb_common.sh"
app_timeout=400 # s: the whole test, with room on a loaded machine (each wait has its own limit)
start_app --lesson lecture3
wait_for "window ready" 60
focus_window
sleep 0.5

# The log's lines (the audio library's complaints left out) after line N.
lines() { grep -v -e "^ALSA" -e "^AL lib" "$log"; }
count_lines() { lines | wc -l; }
after() { lines | tail -n +"$(($1 + 1))"; }
# press KEY EXPECTED...: the key (xdotool's name), then each expected line, in order, within 30 s;
# then 0.5 s more for anything else it might do. Leaves its lines in $said.
press() {
    local key=$1 start
    shift
    start=$(count_lines)
    xdotool key "$key"
    for want in "$@"; do
        for _ in $(seq 300); do
            after "$start" | grep -q -- "$want" && break
            kill -0 "$app_pid" 2>/dev/null || fail "the app exited after $key"
            sleep 0.1
        done
        after "$start" | grep -q -- "$want" || fail "$key: no '$want' in the log"
    done
    sleep 0.5
    said=$(after "$start")
    echo "  $key done at ${SECONDS}s"
}
# only PATTERN...: every line $said holds matches one of the patterns (nothing else happened).
only() {
    local line p ok
    while IFS= read -r line; do
        ok=0
        for p in "$@"; do [[ $line =~ $p ]] && ok=1; done
        [ "$ok" -eq 1 ] || fail "unexpected line after the key: '$line' (all: $said)"
    done <<<"$said"
}
# never PATTERN: no line of $said matches it.
never() { ! grep -q -- "$1" <<<"$said" || fail "'$1' in the log: $said"; }
# The focus ring (ui_style.cpp: NavHighlight, dark theme, #ffd940) in the panel: its pixels.
ring_pixels() {
    shot "$1"
    "$convert" "$work/$1.png" -crop 350x720+0+0 +repage -fuzz 8% -fill black \
        +opaque "rgb(255,217,64)" -fill white -opaque "rgb(255,217,64)" \
        -format "%[fx:round(mean*w*h)]" info:
}
no_ring() { [ "$(ring_pixels "$1")" -eq 0 ] || fail "a focus ring in the panel ($1.png)"; }
# The key table's own lines: a key and what it did; the lecture's keys are never ImGui's.
lecture_keys_only() {
    never "keyboard navigation"
    never "^keyboard:"
    never "^mistakes"
}

# The panel's C slider (the log's "widget" line: x y width height, step 1's layout).
read -r _ _ sx sy sw sh < <(grep -m1 "^widget bounciness" "$log")
[ -n "${sh:-}" ] || fail "no 'widget bounciness' line in the log"
cy=$((sy + sh / 2))
# click_slider [ctrl] X: a press on the slider at X (with Ctrl: it becomes a text field).
click_slider() {
    if [ "$1" = ctrl ]; then
        # Ctrl held over a few frames: pressed and let go within one frame, ImGui would see
        # the click without it.
        xdotool mousemove "$2" "$cy" keydown ctrl
        sleep 0.3
        xdotool click 1
        sleep 0.3
        xdotool keyup ctrl
    else
        xdotool mousemove "$1" "$cy" click 1
    fi
    sleep 0.3
    park
}
# type_into_slider TEXT...: a Ctrl+click on the slider (a text field, all selected), then the
# keys (xdotool names), each going to the field ("key N: typing"; the field takes each value as
# it is typed). Sets $start before the click.
type_into_slider() {
    start=$(count_lines)
    click_slider ctrl $((sx + sw / 4))
    for k in "$@"; do
        xdotool key "$k"
        sleep 0.2
    done
}
# wait_after PATTERN: a line matching it after $start, within 30 s.
wait_after() {
    for _ in $(seq 300); do
        after "$start" | grep -q -- "$1" && return 0
        kill -0 "$app_pid" 2>/dev/null || fail "the app exited waiting for '$1'"
        sleep 0.1
    done
    fail "no '$1' in the log: $(after "$start")"
}

# The slider dragged with the mouse (C = 0.5, its middle): the keyboard stays the scene's.
start=$(count_lines)
click_slider $((sx + sw / 2))
wait_after "^bounciness: 0\.[45]"
said=$(after "$start")
lecture_keys_only
echo "ok: a click on the C slider set C to its middle and left the keyboard to the scene"

# Typing into the slider (Ctrl+click): the digits are the field's, not the lesson's; Enter
# leaves the field with the value.
type_into_slider 0 period 7
wait_after "^key 0: typing$"
wait_after "^key 7: typing$"
wait_after "^bounciness: 0.7$"
press Return "^key Enter: typing$"
said=$(after "$start")
never "lesson step typed"
never "lesson-digit"
never "lesson-jump"
lecture_keys_only
echo "ok: typed into the C slider: the digits and Enter went to the field, C = 0.7"
# Esc while typing: the field undoes the typing and leaves, nothing else happens.
type_into_slider 0 period 3
wait_after "^key 3: typing$"
wait_after "^bounciness: 0.3$"
press Escape "^key Esc: escape$" "^escape: the field left$" "^bounciness: 0.7$"
only "^key Esc: escape$" "^escape: the field left$" "^bounciness: 0.7$"
echo "ok: Esc while typing undid the typing (C back to 0.7) and left the field"
# F5 while typing: present mode (the field left with what was typed), F5 again: back.
type_into_slider 0 period 6
wait_after "^bounciness: 0.6$"
press F5 "^key F5: present$" "^present mode: on$"
only "^key F5: present$" "^present mode: on$"
press F5 "^key F5: present$" "^present mode: off$"
only "^key F5: present$" "^present mode: off$"
echo "ok: F5 while typing is present mode (and back)"
# PageDown while typing: the lesson's next (step 1 plays), the field left with its 0.8.
type_into_slider 0 period 8
wait_after "^bounciness: 0.8$"
start=$(count_lines)
press Next "^key PageDown: lesson-next$" "^resumed$"
lecture_keys_only
echo "ok: PageDown while typing steps the lesson"
# The step plays to its moment and pauses there by itself (2.5 s of its run).
wait_after "^paused$"

# Right three times with the slider last worked: step 2, it plays, then its moment (Right while
# it runs) or step 3 (when it has paused there by itself already).
press Right "^key Right: lesson-next$" "^lesson step 2 / 27 "
lecture_keys_only
press Right "^key Right: lesson-next$" "^resumed$"
lecture_keys_only
press Right "^key Right: lesson-next$" "^\(paused\|lesson step 3 / 27 .*\)$"
lecture_keys_only
no_ring right3
echo "ok: Right three times steps the lesson (step 2, play, its moment or step 3); no focus ring"

# Space: slow motion, and nothing else (the bug ticked the no-approach-test mistake).
press space "^key Space: slow-motion$" "^slow motion: on$"
only "^key Space: slow-motion$" "^slow motion: on$"
no_ring space
echo "ok: Space is slow motion and nothing else"

# 1 3 Enter: step 13 (the bug opened the scene picker).
start=$(count_lines)
press 1 "^key 1: lesson-digit$" "^lesson step typed: 1$"
only "^key 1: lesson-digit$" "^lesson step typed: 1$"
press 3 "^key 3: lesson-digit$" "^lesson step typed: 13$"
only "^key 3: lesson-digit$" "^lesson step typed: 13$"
press Return "^key Enter: lesson-jump$" "^lesson step 13 / 27 "
lecture_keys_only
no_ring step13
echo "ok: 1 3 Enter goes to step 13; no focus ring"

# S: the next method, and nothing else.
press s "^key S: cycle-method$" "^method: move-and-correct$"
only "^key S: cycle-method$" "^method: move-and-correct$"
echo "ok: S cycles the method and does nothing else"

# Shift+R: the step as written (its method back too).
press shift+r "^key Shift+R: reset-to-file$" "^lesson step as written 13$" "^method: perfect$"
lecture_keys_only
never "^key R: "
echo "ok: Shift+R restores the step as written"

# F5: present mode on and off.
press F5 "^key F5: present$" "^present mode: on$"
only "^key F5: present$" "^present mode: on$"
press F5 "^key F5: present$" "^present mode: off$"
only "^key F5: present$" "^present mode: off$"
echo "ok: F5 toggles present mode"

# F6: the panel has the keyboard (the ring shows); the arrows move the ring, not the lesson; Esc
# gives the keyboard back and the arrows step the lesson again.
press F6 "^key F6: next-window$" "^keyboard: Controls$"
sleep 0.3
[ "$(ring_pixels f6)" -gt 50 ] || fail "F6 showed no focus ring in the panel (f6.png)"
press Down "^key Down: keyboard navigation$"
never "^lesson step"
press Right "^key Right: keyboard navigation$"
never "^lesson step"
press Escape "^key Esc: escape$" "^keyboard: scene$"
no_ring escape
echo "ok: F6 gives the panel the keyboard (its ring shows), Esc gives it back"

# A click in the panel (its scene's description: no control) leaves the keyboard to the scene;
# once F6 has given it to the panel, a click in the scene (empty space; the step is at its
# setup, no window docked there) gives it back.
start=$(count_lines)
xdotool mousemove 100 102 click 1
sleep 1
park
said=$(after "$start")
never "^keyboard:"
press F6 "^key F6: next-window$" "^keyboard: Controls$"
start=$(count_lines)
xdotool mousemove 1000 650 click 1
for _ in $(seq 100); do after "$start" | grep -q "^keyboard: scene$" && break; sleep 0.1; done
after "$start" | grep -q "^keyboard: scene$" || fail "a click in the scene did not give the keyboard back"
park
echo "ok: a click in the panel leaves the keyboard to the scene; a click in the scene takes it back from F6's panel"
press Right "^key Right: lesson-next$" "^resumed$"
lecture_keys_only
echo "ok: the arrows step the lesson again"

# Step 26, the platformer, which plays its player's keys itself: the arrows take the player over
# (Left: the step's own input never presses it), and do not step the lesson.
press 2 "^key 2: lesson-digit$"
press 6 "^key 6: lesson-digit$"
press Return "^key Enter: lesson-jump$" "^lesson step 26 / 27 "
press Next "^key PageDown: lesson-next$" "^resumed$"
start=$(count_lines)
xdotool keydown Left
sleep 0.6
xdotool keyup Left
for _ in $(seq 100); do after "$start" | grep -q "^player keys: none$" && break; sleep 0.1; done
said=$(after "$start")
grep -q "^key Left: thrust-left$" <<<"$said" || fail "Left: no key line ($said)"
grep -q "^player: the arrow keys drive it" <<<"$said" || fail "Left did not take the player over"
grep -q "^player keys: left$" <<<"$said" || fail "Left did not drive the player ($said)"
grep -q "^player keys: none$" <<<"$said" || fail "the player's key was not released ($said)"
never "^lesson step"
lecture_keys_only
echo "ok: on step 26 the arrow keys drive the player (and step no lesson)"

kill "$app_pid" 2>/dev/null
wait "$app_pid" 2>/dev/null
app_pid=
echo "PASS"
