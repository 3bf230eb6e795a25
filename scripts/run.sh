#!/usr/bin/env bash
# Builds ShadowLab and opens the inspector on the bundled default scene (arguments go to
# `shadowlab`). Without a desktop (DISPLAY unset) the window opens on a virtual X server (Xvfb).
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/build.sh shadowlab
if [ -z "${DISPLAY:-}" ] && [ "$#" -eq 0 ]; then
  echo "run: no DISPLAY: opening the window on a virtual X server (xvfb-run); Ctrl-C to quit"
  exec xvfb-run -a -s "-screen 0 1920x1200x24" build/app/shadowlab gui
fi
exec build/app/shadowlab "$@"
