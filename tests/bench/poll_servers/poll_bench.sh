#!/usr/bin/env bash
# Builds the two servers the poll's HTTP library was measured against (cpp-httplib, civetweb:
# Debian's libcpp-httplib-dev and libcivetweb-dev, not needed otherwise) into build/poll_servers
# and runs tests/bench/poll_bench.py on all three. Everything on 127.0.0.1.
# Usage: tests/bench/poll_servers/poll_bench.sh [poll_bench.py options, e.g. --runs 3]
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=build/poll_servers
mkdir -p "$out"
g++ -O2 -std=c++17 -o "$out/httplib_server" tests/bench/poll_servers/httplib_server.cpp \
  $(pkg-config --cflags --libs cpp-httplib) -pthread
g++ -O2 -std=c++17 -o "$out/civetweb_server" tests/bench/poll_servers/civetweb_server.cpp \
  -lcivetweb -pthread
for server in poll httplib civetweb; do
  python3 tests/bench/poll_bench.py --server "$server" --bin "$out" "$@"
done
