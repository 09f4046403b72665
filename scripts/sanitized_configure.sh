# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: configures a clang build with AddressSanitizer
# and UndefinedBehaviorSanitizer, without the app or the benchmarks, -Werror.
# Usage: configure_sanitized BUILD_DIR [more cmake options].
# -O1 with line tables only, as the sanitizers' own documentation advises: reports still name
# file:line, and the build takes about a third less time than the default -O2 -g (CI time).
configure_sanitized() {
  local dir="$1"
  shift
  CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    -DSANDBOX_SANITIZE=address,undefined -DSANDBOX_BUILD_APP=OFF -DSANDBOX_BUILD_BENCH=OFF \
    -DSANDBOX_WERROR=ON "$@" >/dev/null
}
