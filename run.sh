#!/usr/bin/env bash
# ./run.sh demo | test | build — installs what is missing, builds (Release, in build/), then runs.
set -euo pipefail
cd "$(dirname "$0")"

# Required to build and test; the second list enables the optional features (viewer, benchmark
# peers and plots), which CI tests too.
required=(g++ make cmake libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev libgtest-dev
          clang-format libtinygltf-dev nlohmann-json3-dev)
optional=(libmeshoptimizer-dev libopenmesh-dev gnuplot-nox pkg-config libglfw3-dev libimgui-dev libosmesa6-dev libgl-dev
          libstb-dev)

install_missing() {
  local missing=() package
  for package in "${required[@]}" "${optional[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "run.sh: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

# Builds the given targets (everything when none is given).
build() {
  install_missing
  [ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >&2
  local targets=()
  [ $# -gt 0 ] && targets=(--target "$@")
  cmake --build build -j "$(nproc)" "${targets[@]}" >&2
}

case "${1:-}" in
  demo)
    # Only what the demo runs: the benchmark, and simplify for the picture.
    build simplify simplify_bench
    mkdir -p out/demo
    # Every policy of the suite beside CGAL's own, on the shipped cow at 10% of its faces: the
    # table (time against gh, two-sided errors, validity) ...
    build/bin/simplify_bench --mesh data/cow.obj --ratios 0.1 --out out/demo \
      --policies gh,gh-prob,lt,classic,curvature,fusion,fast,hausdorff,attributes
    # ... and the input beside the output of the Hausdorff-bounded policy, drawn offscreen.
    if build/bin/simplify data/cow.obj out/demo/cow_hausdorff.obj 0.1 --policy hausdorff \
         --measure --snapshot out/demo/cow_hausdorff.png --quiet --force; then
      echo "demo: table in out/demo/report.md, picture in out/demo/cow_hausdorff.png" >&2
    else
      echo "demo: table in out/demo/report.md (no picture: this build has no OpenGL viewer)" >&2
    fi
    ;;
  test)
    build
    ctest --test-dir build --output-on-failure -j "$(nproc)"
    ;;
  build)
    build
    ;;
  *)
    echo "usage: ./run.sh demo|test|build" >&2
    exit 2
    ;;
esac
