#!/usr/bin/env bash
# The core tests under AddressSanitizer + UndefinedBehaviorSanitizer, then the scene fuzzer for a
# bounded time over the shipped scenes and the bad files (fuzz/scene_fuzzer.cpp). Any finding fails.
# Its own build, build-sanitize/ (clang, core and its tests only). Extra arguments go to the fuzzer.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/setup.sh
cmake -S . -B build-sanitize -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DSHADOWLAB_SANITIZE=ON -DSHADOWLAB_CORE_ONLY=ON -DSHADOWLAB_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-sanitize -j2

# Every core test: the slowest, the stability sweep, takes about 35 s under the sanitizers.
export UBSAN_OPTIONS=print_stacktrace=1
ctest --test-dir build-sanitize --output-on-failure -j2

# The fuzzer adds what it finds to the corpus: a copy, so the repository keeps only its seeds. A
# crashing input is kept in build-sanitize/fuzz-findings/ to reproduce with
# `build-sanitize/fuzz/scene_fuzzer <file>`.
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp data/scenes/*.json tests/data/bad/* fuzz/corpus/* "$corpus"/
mkdir -p build-sanitize/fuzz-findings
build-sanitize/fuzz/scene_fuzzer "$corpus" -max_total_time=60 -rss_limit_mb=4096 -timeout=10 \
  -dict=fuzz/scene.dict -artifact_prefix=build-sanitize/fuzz-findings/ -print_final_stats=1 "$@"
