#!/usr/bin/env bash
# Builds the fuzzers with clang in build-fuzz/ and runs fuzz_model_reader for SECONDS seconds,
# seeded with the example mechanisms and the test data. Exits non-zero if the fuzzer finds a
# crash, a sanitizer report, a leak or a timeout; the reproducer is kept in build-fuzz/artifacts/.
#   fuzz/run.sh 60
set -euo pipefail

seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "usage: $0 SECONDS" >&2
  exit 2
fi

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-fuzz
cxx=${LINKAGE_FUZZ_CXX:-$(command -v clang++ || command -v clang++-14 || true)}
if [ -z "$cxx" ]; then
  echo "$0: clang++ not found (set LINKAGE_FUZZ_CXX)" >&2
  exit 2
fi

generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja > /dev/null; then generator=(-G Ninja); fi
cmake -S "$root" -B "$build" "${generator[@]}" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLINKAGE_FUZZ=ON \
  -DLINKAGE_BUILD_TESTS=OFF -DLINKAGE_BUILD_APPS=OFF -DLINKAGE_BUILD_BENCH=OFF > /dev/null
cmake --build "$build" --target fuzz_model_reader

corpus=$(mktemp -d "${TMPDIR:-/tmp}/linkage-fuzz-corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
shopt -s nullglob
seeds=("$root"/resources/examples/*.linkage.json "$root"/tests/data/*.json)
for seed in "${seeds[@]}"; do
  # Same base names may exist in both places: prefix with the directory.
  cp "$seed" "$corpus/$(basename "$(dirname "$seed")")-$(basename "$seed")"
done
echo "fuzz_model_reader: ${#seeds[@]} seed files, $seconds s"

artifacts=$build/artifacts
mkdir -p "$artifacts"
# ASAN_OPTIONS: fail on any report, including leaks; libFuzzer exits non-zero on a finding.
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
  "$build/fuzz/fuzz_model_reader" "$corpus" \
  -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
  -dict="$root/fuzz/model.dict" -artifact_prefix="$artifacts/" -print_final_stats=1
