#!/usr/bin/env bash
# The sandbox in a browser (WebAssembly, WebGL 2).
#   scripts/web.sh build         install what is missing, build into build-web/ (a static folder:
#                                index.html and everything it loads)
#   scripts/web.sh serve [PORT]  serve build-web/ on 127.0.0.1 (default port 8080), print the URL
#   scripts/web.sh deps          only install what the browser build and its tests need
# Dear ImGui's sources come from Debian's source package (Debian ships only the compiled
# library), fetched once through a private deb-src list into a cache outside the tree:
# ${SANDBOX_WEB_CACHE:-~/.cache/collision-sandbox}. Nothing is downloaded while building.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
out=${SANDBOX_WEB_OUT:-$root/build-web}
cache=${SANDBOX_WEB_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/collision-sandbox}
imgui_version=1.86+ds-1
imgui_dir=$cache/imgui-$imgui_version

# emscripten (emcc 3.1.6, clang 14, binaryen), chromium and python3-websocket (the browser
# tests drive Chromium over the DevTools protocol), python3-pil (they read its screenshots), and
# the header-only packages the build uses.
web_packages=(emscripten chromium python3-websocket python3-pil xz-utils
  nlohmann-json3-dev libcli11-dev libstb-dev fonts-dejavu-core cmake)
# axe-core (npm), which the browser tests inject into the page to check its accessibility; kept
# in the cache, where tests/web/browser_test.py looks for it.
axe_version=4.14.1
axe_dir=$cache/npm

install_deps() {
  local missing=() p
  for p in "${web_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  echo "web.sh: installing ${missing[*]}"
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
    --no-install-recommends "${missing[@]}"
}

install_axe() {
  grep -qs "\"version\": \"$axe_version\"" "$axe_dir/node_modules/axe-core/package.json" && return 0
  echo "web.sh: installing axe-core $axe_version (npm) into $axe_dir"
  command -v npm >/dev/null || { echo "web.sh: npm is missing (Node.js's package manager)" >&2; return 1; }
  mkdir -p "$axe_dir"
  npm install --no-audit --no-fund --silent --prefix "$axe_dir" "axe-core@$axe_version"
}

# Dear ImGui 1.86's sources from Debian's source package, without touching apt's configuration.
fetch_imgui() {
  [ -f "$imgui_dir/imgui.cpp" ] && return 0
  echo "web.sh: fetching Dear ImGui's sources (Debian source package imgui $imgui_version)"
  local tmp
  tmp=$(mktemp -d)
  mkdir -p "$tmp/lists/partial"
  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' >"$tmp/src.sources"
  local apt_opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$tmp"
    -o "Dir::State::Lists=$tmp/lists" -o Debug::NoLocking=1)
  apt-get "${apt_opts[@]}" update -qq
  (cd "$tmp" && apt-get "${apt_opts[@]}" source --download-only -qq "imgui=$imgui_version" 2>&1 |
    grep -v "unsandboxed" || true)
  local tarball=("$tmp"/imgui_*.orig.tar.xz)
  [ -f "${tarball[0]}" ] || { echo "web.sh: apt-get source imgui failed" >&2; exit 1; }
  mkdir -p "$tmp/src"
  tar -xJf "${tarball[0]}" -C "$tmp/src" --strip-components=1
  grep -q '#define IMGUI_VERSION *"1.86"' "$tmp/src/imgui.h" ||
    { echo "web.sh: the source package is not Dear ImGui 1.86" >&2; exit 1; }
  mkdir -p "$cache"
  rm -rf "$imgui_dir"
  mv "$tmp/src" "$imgui_dir"
  rm -rf "$tmp"
}

build() {
  install_deps
  install_axe
  fetch_imgui
  # Debian's emcc with Node 20: its JS optimizer finds acorn only through NODE_PATH.
  export NODE_PATH=/usr/share/nodejs
  emcmake cmake -S . -B "$out/cmake" -DCMAKE_BUILD_TYPE=Release -DSANDBOX_WERROR=ON -DSANDBOX_BUILD_APP=ON \
    "-DSANDBOX_IMGUI_SOURCE_DIR=$imgui_dir" "-DSANDBOX_WEB_OUT=$out" "$@" >/dev/null
  cmake --build "$out/cmake" -j"$(nproc)"
  echo "web.sh: built $out (serve it with scripts/web.sh serve)"
}

serve() {
  local port=${1:-8080}
  [ -f "$out/index.html" ] || { echo "web.sh: $out/index.html is missing: run scripts/web.sh build" >&2; exit 1; }
  echo "web.sh: serving $out at http://127.0.0.1:$port/ (Ctrl+C stops)"
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$out"
}

case "${1:-build}" in
  build) shift || true; build "$@" ;;
  serve) shift; serve "$@" ;;
  deps) install_deps; install_axe ;;
  *) echo "usage: scripts/web.sh build | serve [PORT] | deps" >&2; exit 2 ;;
esac
