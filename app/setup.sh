#!/usr/bin/env bash
# One-stop set-up for a fresh Debian 12 machine: installs the missing Debian packages, builds
# everything (Release, build/), then either runs the main job on a bundled surface (`demo`) or the
# whole test suite (`test`). README's quick start is these two commands. `sanitize` (CI's second
# stage) builds the engine, the CLI and the fuzz targets with clang under ASan+UBSan into
# build-sanitize/, runs their tests there and each fuzz target for PAVER_FUZZ_SECONDS (default 40).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { echo "usage: app/setup.sh demo|test|build|sanitize" >&2; exit 2; }
[ $# -eq 1 ] || usage
mode=$1
case "$mode" in demo|test|build|sanitize) ;; *) usage ;; esac
fuzz_seconds=${PAVER_FUZZ_SECONDS:-40}
[[ "$fuzz_seconds" =~ ^[0-9]+$ ]] || { echo "setup: PAVER_FUZZ_SECONDS must be a whole number of seconds, got '$fuzz_seconds'" >&2; exit 2; }

packages=(
  cmake ninja-build g++ pkg-config python3
  libeigen3-dev libtbb-dev libglm-dev nlohmann-json3-dev libcli11-dev libstb-dev
  libgtest-dev libbenchmark-dev libtinygltf-dev lib3mf-dev libcgal-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools spirv-tools
  libglfw3-dev libimgui-dev xvfb xauth fonts-dejavu-core
)
# libFuzzer and the sanitizer runtimes come with clang's compiler-rt.
[ "$mode" = sanitize ] && packages+=(clang libclang-rt-dev)
# The programs the tests open Paver's files with (tests/cli/client_programs_test.cpp); node runs
# the Khronos glTF validator, from npm below.
if [ "$mode" = test ]; then
  packages+=(prusa-slicer admesh blender python3-numpy)
  command -v npm >/dev/null || packages+=(nodejs npm)
fi
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
if [ "$mode" != sanitize ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build build -j"$jobs"
fi

case "$mode" in
  demo)
    out=out/demo
    build/bin/paver run assets/surfaces/dome.obj --design assets/designs/dome_hex_d6.json --out "$out" --png
    echo
    echo "setup: results are in $(pwd)/$out (placements.csv, stones.csv, elements.ply/.obj/.glb, paved.3mf,"
    echo "       design.json, report.json, report.html to print, preview.png: the paved surface, param.png: the"
    echo "       pattern on the 2D map)"
    ;;
  test)
    # The glTF validator is npm's, not Debian's: into build/clients, once. Without the registry
    # its test skips, loudly.
    if [ ! -d build/clients/node_modules/gltf-validator ]; then
      npm install --silent --no-audit --no-fund --prefix build/clients gltf-validator >/dev/null 2>&1 ||
        echo "setup: warning: could not install the glTF validator from npm; its test will skip" >&2
    fi
    export PAVER_GLTF_VALIDATOR_MODULES="$PWD/build/clients/node_modules"
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
  sanitize)
    # Without Vulkan: lavapipe and the validation layer are not ours to sanitize, and the Vulkan
    # path is covered by the main build's tests. Without CGAL (--subtract) likewise: its exact
    # arithmetic is not ours, and compiling it under the sanitizers would add minutes to CI.
    # -O1 with line tables only: what sanitizer builds are usually run at (readable stacks, half
    # the compile time of -O2 -g on these 2 cores).
    cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" \
      -DCMAKE_CXX_COMPILER=clang++ \
      -DPAVER_FUZZ=ON -DPAVER_WITH_VULKAN=OFF -DPAVER_WITH_CGAL=OFF -DPAVER_BUILD_BENCH=OFF -DPAVER_UNITY_BUILD=ON
    cmake --build build-sanitize -j"$jobs"
    # The leak suppressions are third-party only, each with its reason (tests/sanitize/lsan.supp).
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 \
      LSAN_OPTIONS=suppressions="$PWD/tests/sanitize/lsan.supp"
    # The pavements of the scanned bunny head (adaptive pattern, 10-35 s each under the
    # sanitizers, a third of this stage) run in the main build only: the sanitizers see the same
    # code on the bundled surfaces, and CI must stay under 30 minutes on 2 cores.
    # So do the coarse start's 20k-point lattice, in two tests (50 s and 41 s under the sanitizers;
    # the coarse start and collision resolution run in the bundled designs' tests here), and the
    # proximity search against its all-pairs reference on 9,000 elements (35 s, nearly all of it
    # the test's own 81 million pairs; the search runs here in the smaller proximity tests).
    # And three of the slowest left (15-24 s each, 63 s of the stage's 620 test-seconds): auto's
    # adaptive pass on a torn lattice and the closed bead in tri and hex; their code runs here in
    # the smaller topology, adaptive and bead tests (PaverRun.AClosedBead..., SeamlessBand...).
    sanitize_skip='[Bb]unny[Hh]ead|OnTheHead|ScannedSurface|bunny|ALargeLatticeRelaxesFromItsCoarseShape|ALargePatternEndsItsRoundsWhenFewPairsAreLeft|TheReportsOneSearchGivesTheAllPairsFigures'
    sanitize_skip+='|GrowsThePatternWhereTheLatticeTears|ClosedSurfaces.OnePavementWithNoContactAcrossTheSeam'
    if ! ctest --test-dir build-sanitize --output-on-failure -j"$jobs" -E "$sanitize_skip"; then
      echo
      echo "setup: tests failed under the sanitizers; running the failed ones again, one at a time:"
      ctest --test-dir build-sanitize --rerun-failed --output-on-failure -j1 -E "$sanitize_skip" || true
      exit 1
    fi
    # Each fuzz target from the committed seeds, into a scratch corpus that is removed afterwards
    # (the committed corpus stays as it is). A finding leaves its input in build-sanitize/fuzz-findings.
    scratch=$(mktemp -d)
    trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$scratch"' EXIT
    mkdir -p build-sanitize/fuzz-findings
    # Two targets at a time: libFuzzer runs one process on one core, and CI has two.
    fuzz_one() {
      local target=$1 log="$scratch/$1.log" status=0
      mkdir -p "$scratch/$target"
      build-sanitize/bin/fuzz_$target -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=3072 \
        -max_len=65536 -print_final_stats=1 -artifact_prefix=build-sanitize/fuzz-findings/$target- \
        "$scratch/$target" tests/fuzz/corpus/$target >"$log" 2>&1 || status=$?
      echo "$status" >"$scratch/$target.status"
    }
    targets=(obj off ply stl design)
    for ((i = 0; i < ${#targets[@]}; i += 2)); do
      pair=("${targets[@]:i:2}")
      echo "setup: fuzzing ${pair[*]} for ${fuzz_seconds} s"
      for target in "${pair[@]}"; do fuzz_one "$target" & done
      wait
      for target in "${pair[@]}"; do
        echo "setup: fuzz_$target:"
        grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)" "$scratch/$target.log" || true
        status=$(cat "$scratch/$target.status")
        if [ "$status" -ne 0 ]; then
          tail -n 60 "$scratch/$target.log"
          echo "setup: fuzz_$target found a problem (exit $status); its input is in build-sanitize/fuzz-findings"
          exit 1
        fi
      done
    done
    ;;
esac
