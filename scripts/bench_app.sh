#!/usr/bin/env bash
# The app's frame time under llvmpipe (offscreen, OSMesa) with 1,000 blocks: the default view,
# the teaching overlays of issue 5 (plots, vectors, trails, inspector, com, poi, sidebyside,
# timeline) and every overlay window (the same plus cost), at 1280x720 and on a projector
# (1920x1080, UI scale 1.5); then what each teaching overlay costs on the projector: the
# default view with that overlay alone, less the default view. Each case runs RUNS times
# (default 7; the per-overlay cases OVERLAY_RUNS, default 3, 0 to skip them) for FRAMES frames
# (default 150) and prints the fastest and the median run: the machine's other work only ever
# adds time. With the projector's teaching case, where its drawing time went (the median run's
# split: the frame worked out on the second thread, scene drawn, UI drawn, pixels waited for,
# the next frame waited for; see --benchmark-frames).
# Given several build directories (before and after), every case runs them in turn, run by run,
# so that the machine's load falls on all alike; the load average is printed before and after.
# Usage: scripts/bench_app.sh [BUILD_DIR ...]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -gt 0 ] || set -- build
runs=${RUNS:-7}
overlayRuns=${OVERLAY_RUNS:-3}
frames=${FRAMES:-150}
for build in "$@"; do
  [ -x "$build/app/gui/sandbox-offscreen" ] ||
    { echo "bench_app: $build/app/gui/sandbox-offscreen not found (build first)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=$work/gas.json
python3 tools/make_gas_scene.py 40 25 > "$scene" # 1,000 blocks

overlays=plots,vectors,trails,inspector,com,poi,sidebyside,timeline
projector=(--size 1920x1080 --ui-scale 1.5)

# measure LABEL RUNS ARGS...: each build's fastest and median ms per frame; the medians are
# kept in $work/median.N (N: the build's place in the arguments) for the per-overlay lines.
measure() {
  local label=$1 n=$2 i b
  shift 2
  for ((b = 0; b < ${#builds[@]}; b++)); do : > "$work/times.$b"; done
  for ((i = 0; i < n; i++)); do
    for ((b = 0; b < ${#builds[@]}; b++)); do
      env -u DISPLAY "${builds[b]}/app/gui/sandbox-offscreen" "$scene" --benchmark-frames "$frames" \
        "$@" | awk '/ms\/frame/ {t = $1} /drawing:/ {sub(/^ *drawing: */, ""); d = $0}
                    END {print t "\t" d}' >> "$work/times.$b"
    done
  done
  for ((b = 0; b < ${#builds[@]}; b++)); do
    local name=$label
    [ ${#builds[@]} -eq 1 ] || name="$label [${builds[b]}]"
    sort -n "$work/times.$b" | awk -F'\t' -v label="$name" -v out="$work/median.$b" \
      '{t[NR] = $1; d[NR] = $2}
       END {k = int((NR + 1) / 2); m = t[k];
            printf "%-60s fastest %6.2f ms  median %6.2f ms  (%.0f frames/s)\n", label, t[1], m, 1000 / m;
            if (d[k] != "" && label ~ /1920x1080 UI 1.5 teaching/) printf "%-60s %s\n", "", d[k];
            print m > out}'
  done
}

builds=("$@")
echo "1,000 blocks, llvmpipe, $runs runs of $frames frames each; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
measure "1280x720 default view" "$runs"
measure "1280x720 teaching overlays" "$runs" --show "$overlays"
measure "1280x720 every overlay window (+ cost)" "$runs" --show "$overlays,cost"
measure "1920x1080 UI 1.5 teaching overlays" "$runs" "${projector[@]}" --show "$overlays"
if [ "$overlayRuns" -gt 0 ]; then
  echo "What each teaching overlay adds to the 1920x1080 UI 1.5 default view ($overlayRuns runs each, medians):"
  measure "1920x1080 UI 1.5 default view" "$overlayRuns" "${projector[@]}"
  for ((b = 0; b < ${#builds[@]}; b++)); do cp "$work/median.$b" "$work/base.$b"; done
  for overlay in ${overlays//,/ }; do
    measure "  + $overlay" "$overlayRuns" "${projector[@]}" --show "$overlay" > "$work/lines"
    b=0
    while IFS= read -r line; do
      printf "%s  %+.2f ms\n" "$line" "$(awk -v m="$(cat "$work/median.$b")" -v d="$(cat "$work/base.$b")" 'BEGIN {print m - d}')"
      b=$((b + 1))
    done < "$work/lines"
  done
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
