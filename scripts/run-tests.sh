#!/usr/bin/env bash
# Sets up, builds and runs every test: the normal build (the solver's, the command line's and the
# editor's tests, offscreen and in a real X server), then everything again but the X server's
# tests under AddressSanitizer and UndefinedBehaviorSanitizer (a debug build, assertions on,
# compiled with clang: g++ took 1.8 times as long on it; at -O1 with line tables only, as the
# sanitizers' own documentation advises: at -O0 Eigen's uninlined expressions made the tests run
# 100 to 200 times as long as the release build's, 43 minutes on two cores), then the file-reader fuzzer for a
# bounded time (FUZZ_SECONDS, default 60; 0 skips it). ASAN_EDITOR=0 leaves the editor out of
# the sanitizers' build (the solver's and the command line's tests alone: about half the time).
# Every build goes through ccache (scripts/setup.sh installs it; CMakeLists.txt uses it): a run
# after a small change compiles only what changed (CI keeps CCACHE_DIR between runs).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests build
(cd build && ctest --output-on-failure -j2)

# clang and its sanitizer and fuzzer runtimes (Debian's clang 14).
if ! command -v clang++ >/dev/null || ! dpkg-query -W libclang-rt-14-dev >/dev/null 2>&1; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    clang libclang-rt-14-dev >/dev/null
fi

echo "== sanitizers (ASan + UBSan)"
editor=ON
[ "${ASAN_EDITOR:-1}" = 0 ] && editor=OFF
cmake -S . -B build-asan -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
  -DLINKAGE_SANITIZE=ON -DLINKAGE_BUILD_BENCH=OFF -DLINKAGE_BUILD_UI=$editor >/dev/null
cmake --build build-asan
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j2 -E '^x11\.')

FUZZ_SECONDS=${FUZZ_SECONDS:-60}
if [ "$FUZZ_SECONDS" -gt 0 ]; then
  echo "== fuzzing the mechanism file reader for ${FUZZ_SECONDS} s"
  fuzz/run.sh "$FUZZ_SECONDS"
fi
echo "all tests passed"
