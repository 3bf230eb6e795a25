#!/usr/bin/env bash
# Configures and builds ShadowLab in ./build (Release). Extra arguments name targets.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
# 2 cores and CGAL translation units of 1-4 GB: two jobs at most.
cmake --build build -j2 ${1:+--target "$@"}
