#!/usr/bin/env bash
# Checks the house format (scripts/format_check.sh), builds everything with warnings as errors, runs
# every test (under Xvfb, for the tests that need a display), then the core tests again under the
# sanitizers and the fuzzers (scripts/sanitize.sh). Timed checks (the `perf` label) are left to
# scripts/perf.sh.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
stage() {  # stage NAME COMMAND...: runs it and says how long it took
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "test.sh: $name took $((SECONDS - start)) s"
}
stage "format check" scripts/format_check.sh
stage "build" scripts/build.sh
stage "tests" xvfb-run -a ctest --test-dir build --output-on-failure -j2 -LE perf
stage "sanitizers and fuzzers" scripts/sanitize.sh
