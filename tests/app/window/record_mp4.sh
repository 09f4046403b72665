#!/bin/sh
# --record with ffmpeg installed: numbered PNGs and an MP4 with one video frame per PNG.
#   record_mp4.sh SANDBOX_OFFSCREEN SCENE OUTDIR
set -eu
exe=$1 scene=$2 out=$3
rm -rf "$out"
env -u DISPLAY "$exe" "$scene" --record "$out" --frames 12 --size 320x180 >/dev/null
pngs=$(ls "$out"/frame_*.png | wc -l)
[ "$pngs" -eq 12 ] || { echo "expected 12 PNGs, found $pngs"; exit 1; }
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
    -of default=nokey=1:noprint_wrappers=1 "$out/recording.mp4")
[ "$frames" -eq 12 ] || { echo "expected 12 video frames, found $frames"; exit 1; }
echo "12 PNGs and a 12-frame MP4"
