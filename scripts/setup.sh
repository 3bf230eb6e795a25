#!/usr/bin/env bash
# Installs the Debian 12 packages ShadowLab needs, only those missing. Safe to run again.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  libglm-dev nlohmann-json3-dev libcli11-dev libassimp-dev
  libpng-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev libembree-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  assimp-testmodels openarena-081-maps  # real models for the tests (tests/corpus): Assimp's corpus, three game levels
  libvtk9-dev libvtk9-qt-dev qtbase5-dev libgl-dev
  xvfb xauth
  fonts-dejavu-core  # labels and captions: Greek letters (γ, ε) and superscripts the built-in VTK fonts lack
  clang libclang-rt-14-dev llvm  # the sanitizer build and the fuzzer; llvm-symbolizer for their reports
  clang-format  # the house format, checked by scripts/format_check.sh
  chromium  # the interactive lesson's browser test (headless, WebGL by SwiftShader)
  pybind11-dev python3-dev python3-numpy  # the Python module (python/), for Debian's /usr/bin/python3
  python3-pandas python3-dask python3-distributed  # its corpus runs on Dask (shadowlab.evaluate, bench --scheduler)
)
# The interactive lesson's script is bundled by npm and esbuild at build time (web/bundle.sh):
# Debian's node 18 and npm 9, unless a node with its own npm (NodeSource's) is installed already.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
