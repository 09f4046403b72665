#!/bin/sh
# Rewrites every golden image from tests/golden/cases.txt with the given sandbox-offscreen.
#   tests/golden/regenerate.sh build/app/gui/sandbox-offscreen
# (or: cmake --build build --target regenerate-goldens). Look at the images before committing.
set -eu
exe=${1:?usage: regenerate.sh path/to/sandbox-offscreen}
dir=$(cd "$(dirname "$0")" && pwd)
grep -v '^#' "$dir/cases.txt" | while read -r name args; do
    [ -n "$name" ] || continue
    # shellcheck disable=SC2086  # the arguments are meant to split
    env -u DISPLAY "$exe" $args --screenshot "$dir/$name.png" >/dev/null
    echo "wrote $dir/$name.png"
done
