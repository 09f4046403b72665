#!/usr/bin/env bash
# Installs the Debian 12 packages the sandbox needs (only those missing). Run as root or with sudo.
set -euo pipefail

packages=(
  cmake g++ pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libstb-dev
  libimgui-dev libglfw3-dev libosmesa6-dev libgl-dev
  xvfb xdotool x11-apps imagemagick fonts-dejavu-core
  libopenal-dev libsndfile1-dev
  libbox2d-dev libchipmunk-dev
  libboost-dev libqrcodegencpp-dev zbar-tools
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
