# Shared by the window tests under Xvfb (sourced): start Xvfb on a free display, run the app with
# a log, and helpers to wait for log lines, take screenshots (xwd) and compare regions. Every wait
# has a timeout; Xvfb and the app are stopped on exit.
# Needs: sandbox, png_diff, convert and work set by the caller.
rm -rf "$work"
mkdir -p "$work/config"
log=$work/app.log
xvfb_pid= app_pid=

cleanup() {
    [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
    wait 2>/dev/null
}
trap cleanup EXIT

fail() {
    echo "FAIL: $*"
    echo "--- app log ($log)"
    cat "$log" 2>/dev/null
    echo "--- screenshots in $work"
    exit 1
}

# A free display number: no lock file and no socket; Xvfb must come up within 10 s.
for n in $(seq 91 140); do
    [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ] && continue
    Xvfb ":$n" -screen 0 1280x800x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
    xvfb_pid=$!
    for _ in $(seq 100); do
        [ -e "/tmp/.X11-unix/X$n" ] && break
        kill -0 "$xvfb_pid" 2>/dev/null || break
        sleep 0.1
    done
    if [ -e "/tmp/.X11-unix/X$n" ] && kill -0 "$xvfb_pid" 2>/dev/null; then
        export DISPLAY=":$n"
        break
    fi
    kill "$xvfb_pid" 2>/dev/null
    xvfb_pid=
done
[ -n "$xvfb_pid" ] || fail "could not start Xvfb"
echo "Xvfb on $DISPLAY"
export XDG_CONFIG_HOME=$work/config

# start_app ARGS...: the app with --verbose into the log, at 1280x720, in the background.
start_app() {
    timeout 150 "$sandbox" "$@" --verbose --size 1280x720 >"$log" 2>&1 &
    app_pid=$!
}

# wait_for TEXT [SECONDS]: until a log line contains TEXT.
wait_for() {
    local limit=$((${2:-10} * 10))
    for _ in $(seq "$limit"); do
        grep -q -- "$1" "$log" && return 0
        kill -0 "$app_pid" 2>/dev/null || fail "the app exited while waiting for '$1'"
        sleep 0.1
    done
    fail "no '$1' in the log"
}
shot() { xwd -root -silent | "$convert" xwd:- "png:$work/$1.png" || fail "screenshot $1"; }
# differing PNG_A PNG_B X Y W H: number of differing pixels in the region.
differing() { "$png_diff" "$work/$1.png" "$work/$2.png" "$3" "$4" "$5" "$6" || fail "png_diff $1 $2"; }

# With no window manager, keys go to the window under the pointer: keep it inside the window,
# below the arena's bottom wall (nothing there to hover), and give the window the focus.
park() { xdotool mousemove 1275 715; }
focus_window() {
    park
    win=$(xdotool search --sync --limit 1 --name "Collision sandbox") || fail "no window found"
    xdotool windowfocus --sync "$win" 2>/dev/null || true
}
