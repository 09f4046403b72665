#!/usr/bin/env bash
# The app's frame time under llvmpipe (offscreen, OSMesa) with 1,000 blocks: the default view,
# the teaching overlays of issue 5 (plots, vectors, trails, inspector, com, poi, sidebyside,
# timeline) and every overlay window (the same plus cost), at 1280x720 and on a projector
# (1920x1080, UI scale 1.5). Each case runs RUNS times (default 7) for FRAMES frames (default
# 150) and prints the fastest and the median run: the machine's other work only ever adds time.
# Usage: scripts/bench_app.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${RUNS:-7}
frames=${FRAMES:-150}
exe="$build/app/gui/sandbox-offscreen"
[ -x "$exe" ] || { echo "bench_app: $exe not found (build first)" >&2; exit 1; }
scene=$(mktemp --suffix=.json)
trap 'rm -f "$scene"' EXIT
python3 tools/make_gas_scene.py 40 25 > "$scene" # 1,000 blocks

overlays=plots,vectors,trails,inspector,com,poi,sidebyside,timeline
measure() { # label, then sandbox-offscreen arguments
  local label=$1
  shift
  for _ in $(seq "$runs"); do
    env -u DISPLAY "$exe" "$scene" --benchmark-frames "$frames" "$@" |
      awk '/ms\/frame/ {print $1}'
  done | sort -n | awk -v label="$label" '{t[NR] = $1}
    END {m = t[int((NR + 1) / 2)];
         printf "%-44s fastest %6.2f ms  median %6.2f ms  (%.0f frames/s)\n", label, t[1], m, 1000 / m}'
}

echo "1,000 blocks, llvmpipe, $runs runs of $frames frames each"
measure "1280x720 default view"
measure "1280x720 teaching overlays" --show "$overlays"
measure "1280x720 every overlay window (+ cost)" --show "$overlays,cost"
measure "1920x1080 UI 1.5 teaching overlays" --size 1920x1080 --ui-scale 1.5 --show "$overlays"
