#!/usr/bin/env bash
# Fuzzes the scene loader (tests/fuzz/scene_fuzzer.cpp) with libFuzzer, ASan and UBSan for a bounded
# time (issue 7) and, side by side, the class poll's request handling (poll_fuzzer.cpp, issue 40)
# for half as long: clang into ./build-fuzz, seed corpus tests/fuzz/corpus (copied, so the run
# never changes the repository). Fails on any crash, leak, sanitizer report, timeout or out-of-memory;
# the reproducer is left in build-fuzz/artifacts/. Usage: scripts/fuzz.sh [SECONDS] (default 60);
# `scripts/fuzz.sh build` only builds the two fuzzers, `scripts/fuzz.sh run [SECONDS]` only runs
# them (.ci/run builds them beside the sanitizer stage, at the lowest priority, and runs them after).
set -euo pipefail
cd "$(dirname "$0")/.."
step=all
case "${1:-}" in
  build | run) step="$1" && shift ;;
esac
seconds="${1:-60}"
if [ "$step" != run ]; then
  source scripts/sanitized_configure.sh
  configure_sanitized build-fuzz -DSANDBOX_FUZZ=ON -DSANDBOX_BUILD_TESTS=ON
  cmake --build build-fuzz -j"$(nproc)" --target scene_fuzzer poll_fuzzer
fi
[ "$step" != build ] || exit 0
rm -rf build-fuzz/corpus build-fuzz/poll_corpus build-fuzz/artifacts
mkdir -p build-fuzz/corpus build-fuzz/poll_corpus build-fuzz/artifacts
cp tests/fuzz/corpus/* build-fuzz/corpus/
cp tests/fuzz/poll_corpus/* build-fuzz/poll_corpus/
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The two fuzzers run side by side, one core each (the machine's two: CI time); the poll's
# report is printed after the scene's, so the two never interleave.
build-fuzz/tests/fuzz/poll_fuzzer build-fuzz/poll_corpus \
  -max_total_time="$(( (seconds + 1) / 2 ))" -rss_limit_mb=2048 -max_len=8192 -timeout=10 \
  -artifact_prefix=build-fuzz/artifacts/ -print_final_stats=1 >build-fuzz/poll_fuzzer.log 2>&1 &
poll_pid=$!
scene_status=0
build-fuzz/tests/fuzz/scene_fuzzer build-fuzz/corpus \
  -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 -timeout=10 \
  -artifact_prefix=build-fuzz/artifacts/ -print_final_stats=1 || scene_status=$?
poll_status=0
wait "$poll_pid" || poll_status=$?
echo "fuzz.sh: the poll fuzzer's report (build-fuzz/poll_fuzzer.log):"
cat build-fuzz/poll_fuzzer.log
[ "$scene_status" -eq 0 ] || { echo "fuzz.sh: the scene fuzzer failed ($scene_status)" >&2; exit 1; }
[ "$poll_status" -eq 0 ] || { echo "fuzz.sh: the poll fuzzer failed ($poll_status)" >&2; exit 1; }
