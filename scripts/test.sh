#!/usr/bin/env bash
# Checks the house format (scripts/format_check.sh), builds everything with warnings as errors, runs
# every test (under Xvfb, for the tests that need a display), then the core tests again under the
# sanitizers and the fuzzers (scripts/sanitize.sh). Timed checks (the `perf` label) are left to
# scripts/perf.sh.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/format_check.sh
scripts/build.sh
xvfb-run -a ctest --test-dir build --output-on-failure -j2 -LE perf
scripts/sanitize.sh
