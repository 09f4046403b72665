#!/usr/bin/env bash
# Fresh Debian 12 machine to the sandbox: install packages, build, open the default scene.
# With a display this opens the window; without one, it renders offscreen and prints the PNG path.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
if [ -x build/app/gui/sandbox ]; then
  exec build/app/gui/sandbox "$@"
fi
exec build/app/cli/sandbox-cli run app/scenes/bouncing_squares.json "$@"
