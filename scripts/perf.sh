#!/usr/bin/env bash
# The timed checks (ctest's `perf` label: the GUI thread while the light is dragged), alone on the
# machine, under Xvfb. Their figures belong in docs/PERFORMANCE.md; the default test run leaves them out.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/build.sh
xvfb-run -a ctest --test-dir build --output-on-failure -L perf "$@"
