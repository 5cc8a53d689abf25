#!/usr/bin/env bash
# Sets up, builds and runs every test: the normal build, then the tests again under
# AddressSanitizer and UndefinedBehaviorSanitizer (all but the X server's: they drive the same
# editor as the offscreen ones, one at a time, over three minutes in the normal build alone, and
# several times that under the sanitizers, with which CI ran past its hour), then the file-reader fuzzer for a bounded time when clang is there
# (FUZZ_SECONDS, default 60; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests build
(cd build && ctest --output-on-failure -j2)

echo "== sanitizers (ASan + UBSan)"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DLINKAGE_SANITIZE=ON \
  -DLINKAGE_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j2 -E '^x11\.')

FUZZ_SECONDS=${FUZZ_SECONDS:-60}
if [ "$FUZZ_SECONDS" -gt 0 ]; then
  echo "== fuzzing the mechanism file reader for ${FUZZ_SECONDS} s"
  if ! command -v clang++ >/dev/null || ! dpkg-query -W libclang-rt-14-dev >/dev/null 2>&1; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
      clang libclang-rt-14-dev >/dev/null
  fi
  fuzz/run.sh "$FUZZ_SECONDS"
fi
echo "all tests passed"
