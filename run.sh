#!/usr/bin/env bash
# ./run.sh demo | test | build | install PREFIX | install-headers PREFIX — installs what is
# missing, builds (Release, in build/), then runs or installs.
set -euo pipefail
cd "$(dirname "$0")"

# Required to build and test; the second list enables the optional features (viewer, benchmark
# peers and plots), which CI tests too.
required=(g++ make cmake libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev libgtest-dev
          clang-format libtinygltf-dev nlohmann-json3-dev libtbb-dev libmeshoptimizer-dev
          libdraco-dev)
optional=(libopenmesh-dev gnuplot-nox pkg-config libglfw3-dev libimgui-dev libosmesa6-dev libgl-dev
          libstb-dev python3-dev python3-pybind11 python3-numpy python3-pytest
          python3-distributed)

# Installs the given packages that are missing (default: both lists).
install_missing() {
  local missing=() package wanted=("$@")
  [ ${#wanted[@]} -eq 0 ] && wanted=("${required[@]}" "${optional[@]}")
  for package in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "run.sh: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

# The test gltf_validator's Khronos glTF-Validator, pinned, and node to run it: Debian's nodejs
# and npm, unless node and npm are there already (NodeSource's nodejs holds its own npm and
# conflicts with Debian's). npm installs the validator once, in build/tools, where the test looks;
# without it (no network) the test is skipped.
validator=gltf-validator@2.0.0-dev.3.10
install_validator() {
  command -v node >/dev/null && command -v npm >/dev/null || install_missing nodejs npm
  grep -qs '"version": "'"${validator#*@}"'"' build/tools/node_modules/gltf-validator/package.json &&
    return
  npm install --prefix build/tools --no-audit --no-fund "$validator" >&2 ||
    echo "run.sh: $validator not installed: the test gltf_validator will be skipped" >&2
}

# Builds the given targets (everything when none is given).
build() {
  install_missing
  [ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >&2
  local targets=()
  [ $# -gt 0 ] && targets=(--target "$@")
  cmake --build build -j "$(nproc)" "${targets[@]}" >&2
}

# The demo's best result of this suite: the lowest mean error (both directions) among the rows
# that are not CGAL's policies run alone nor a peer's, as "policy fit" (fit: yes or no).
best_of_ours() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { name = $col["policy"]; base = name; sub(/\+fit$/, "", base)
      if (name == base && (base == "gh" || base == "gh-prob" || base == "lt")) next
      if (base == "gh-envelope" || base == "meshopt" || base == "openmesh") next
      error = ($col["mean_a_to_b_rel"] + $col["mean_b_to_a_rel"]) / 2
      if (best == "" || error < best_error) { best = base " " (name == base ? "no" : "yes"); best_error = error } }
    END { print best }' "$1"
}

case "${1:-}" in
  demo)
    # Only what the demo runs: the benchmark, and simplify for the picture.
    build simplify simplify_bench
    mkdir -p out/demo
    # Every policy of the suite, each also followed by the fitting pass, beside CGAL's own and the
    # peers built in, on the shipped cow at 10% of its faces: the table (time against gh, two-sided
    # errors, validity) and its summary, which names the lowest mean error ...
    build/bin/simplify_bench --mesh data/cow.obj --ratios 0.1 --fit --out out/demo
    # ... and the input beside the best result of this suite's pipelines, drawn offscreen.
    read -r best fit <<<"$(best_of_ours out/demo/runs.csv)"
    fit_option=()
    [ "$fit" = yes ] && fit_option=(--fit)
    if build/bin/simplify data/cow.obj out/demo/cow_best.obj 0.1 --policy "$best" \
         "${fit_option[@]}" --measure --snapshot out/demo/cow_best.png --quiet --force; then
      echo "demo: table in out/demo/report.md, our best ($best, fit: $fit) in out/demo/cow_best.png" >&2
    else
      echo "demo: table in out/demo/report.md (no picture: this build has no OpenGL viewer)" >&2
    fi
    ;;
  test)
    build
    install_validator
    ctest --test-dir build --output-on-failure -j "$(nproc)"
    ;;
  build)
    build
    ;;
  install)
    # The library and the io target (find_package(cgal_policies COMPONENTS io)).
    [ $# -eq 2 ] || { echo "usage: ./run.sh install PREFIX" >&2; exit 2; }
    build cgal_policies_io
    cmake --install build --prefix "$2" >&2
    ;;
  install-headers)
    # The header-only library alone: CGAL and Eigen are all it needs.
    [ $# -eq 2 ] || { echo "usage: ./run.sh install-headers PREFIX" >&2; exit 2; }
    install_missing g++ make cmake libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
    cmake -S . -B build-headers -DCGAL_POLICIES_BUILD_APPS=OFF >&2
    cmake --install build-headers --prefix "$2" >&2
    ;;
  *)
    echo "usage: ./run.sh demo|test|build|install PREFIX|install-headers PREFIX" >&2
    exit 2
    ;;
esac
