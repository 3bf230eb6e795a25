#!/usr/bin/env bash
# Builds everything and runs every test (under Xvfb, for the tests that need a display), then the
# core tests again under the sanitizers and the scene fuzzer for a minute (scripts/sanitize.sh).
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/build.sh
xvfb-run -a ctest --test-dir build --output-on-failure -j2
scripts/sanitize.sh
