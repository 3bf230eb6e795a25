#!/usr/bin/env bash
# Builds ShadowLab and starts it on the bundled default scene (arguments go to `shadowlab`).
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/build.sh shadowlab
exec build/app/shadowlab "$@"
