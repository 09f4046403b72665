#!/usr/bin/env bash
# Fresh Debian 12 machine to passing tests: install packages, build, run every test with ctest.
# The browser build (scripts/web.sh: emscripten, headless Chromium) is built too, so its tests
# in ctest (WebBrowser.*) run rather than skip.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/web.sh deps
scripts/build.sh
scripts/web.sh build
ctest --test-dir build --output-on-failure -j"$(nproc)"
