#!/usr/bin/env bash
# One-stop set-up for a fresh Debian 12 machine: installs the missing Debian packages, builds
# everything (Release, build/), then either runs the main job on a bundled surface (`demo`) or the
# whole test suite (`test`). README's quick start is these two commands.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { echo "usage: app/setup.sh demo|test|build" >&2; exit 2; }
[ $# -eq 1 ] || usage
mode=$1
case "$mode" in demo|test|build) ;; *) usage ;; esac

packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libtbb-dev libglm-dev nlohmann-json3-dev libcli11-dev libstb-dev
  libgtest-dev libbenchmark-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools spirv-tools
  libglfw3-dev libimgui-dev xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} missing Debian packages: ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then sudo=""; elif command -v sudo >/dev/null; then sudo="sudo"; else
    echo "setup: not root and no sudo: install these packages first: ${missing[*]}" >&2; exit 1
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

case "$mode" in
  demo)
    out=out/demo
    build/bin/paver run assets/surfaces/dome.obj --design assets/designs/dome_hex_d6.json --out "$out" --png
    echo
    echo "setup: results are in $(pwd)/$out (placements.csv, elements.ply/.obj, design.json, report.json,"
    echo "       preview.png: the paved surface, param.png: the pattern on the 2D map)"
    ;;
  test)
    if ! ctest --test-dir build --output-on-failure -j"$jobs"; then
      # A long log cuts a failure's text out of view: run the failed ones again, alone, so their
      # messages end the log (and a failure that passes alone shows itself as timing-dependent).
      echo
      echo "setup: tests failed; running the failed ones again, one at a time, with their output:"
      ctest --test-dir build --rerun-failed --output-on-failure -j1 || true
      exit 1
    fi
    ;;
  build) ;;
esac
