#!/usr/bin/env bash
# scripts/sanitized_policies.sh ASAN_BUILD [RELEASE_BUILD]: runs simplify from ASAN_BUILD (an
# AddressSanitizer + UndefinedBehaviorSanitizer build, best at -O2 with CGAL's assertions on:
#   cmake -S . -B build-asan-o2 -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCGAL_POLICIES_SANITIZE=ON \
#     -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" -DBUILD_TESTING=OFF
#   cmake --build build-asan-o2 --target simplify)
# with every policy, and lt, gh and hausdorff with --fit, on every shipped mesh at the targets of
# the standard preset (10% and 1% for the others), and checks each output with RELEASE_BUILD's
# mesh_error (default build): valid, no non-manifold vertex, no degenerate face, nothing to
# repair when read back. Writes out/sanitized/results.tsv, a row per run, as it goes.
# SANITIZED_MESHES="bunny.obj dragon.ply" runs only those meshes, SANITIZED_RUNS="attributes lt+fit"
# only those runs, SANITIZED_RATIOS="0.01" only those targets (any of them appends to results.tsv). Outputs are OBJ files, so that a textured mesh
# carries its texture coordinates and normals through the run.
set -uo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || [ ! -x "$1/bin/simplify" ]; then
  echo "usage: scripts/sanitized_policies.sh ASAN_BUILD [RELEASE_BUILD] (see the comment at the top)" >&2
  exit 2
fi
simplify=$1/bin/simplify
mesh_error=${2:-build}/bin/mesh_error
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"
out=out/sanitized
mkdir -p $out
cases="cow.obj:0.1,0.01 spot.obj:0.1,0.01 bob_tri.obj:0.1,0.01 teapot.obj:0.1,0.01
woody.obj:0.1,0.01 fandisk.obj:0.1,0.02 rocker-arm.obj:0.1,0.01 alligator.obj:0.1,0.01
bunny.obj:0.5,0.1,0.01 nefertiti.obj:0.1,0.01 dragon_res2.ply:0.1,0.01 dragon.ply:0.1,0.01"
runs=${SANITIZED_RUNS:-"gh gh-prob lt classic curvature fusion fast hausdorff attributes lt+fit gh+fit hausdorff+fit"}
field() { grep -o "\"$1\": [^,}]*" "$2" | head -1 | awk '{print $2}' | tr -d '"'; }
header=$(printf 'mesh\tratio\trun\texit\tsan_errors\tseconds\tstop_reason\tout_faces\tvalid\tnon_manifold\tdegenerate\treread_repairs')
[ -n "${SANITIZED_MESHES:-}${SANITIZED_RUNS:-}${SANITIZED_RATIOS:-}" ] && [ -f $out/results.tsv ] ||
  echo "$header" >$out/results.tsv
for c in $cases; do
  mesh=${c%%:*}
  [ -n "${SANITIZED_MESHES:-}" ] && [[ " $SANITIZED_MESHES " != *" $mesh "* ]] && continue
  for ratio in $(echo "${c#*:}" | tr ',' ' '); do
    [ -n "${SANITIZED_RATIOS:-}" ] && [[ " $SANITIZED_RATIOS " != *" $ratio "* ]] && continue
    for run in $runs; do
      policy=${run%+fit}
      fit=""
      [ "$run" != "$policy" ] && fit="--fit"
      tag="${mesh%.*}-$ratio-$run"
      o=$out/$tag.obj
      $simplify data/$mesh $o $ratio --policy $policy $fit --json --force >$out/$tag.json 2>$out/$tag.err
      code=$?
      san=$(grep -c -E 'ERROR: AddressSanitizer|runtime error|ERROR: LeakSanitizer' $out/$tag.err)
      valid="" non_manifold="" degenerate="" repairs=""
      if [ -f $o ]; then
        $mesh_error data/$mesh $o --samples 1000 --json >$out/$tag.check.json 2>$out/$tag.check.err
        valid=$(field valid $out/$tag.check.json)
        non_manifold=$(field non_manifold_vertices $out/$tag.check.json)
        degenerate=$(field degenerate_faces $out/$tag.check.json)
        repairs=$(grep -c "$o" $out/$tag.check.err)
        rm -f $o
      fi
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' $mesh $ratio $run $code $san \
        "$(field seconds $out/$tag.json)" "$(field stop_reason $out/$tag.json)" \
        "$(field output_faces $out/$tag.json)" "$valid" "$non_manifold" "$degenerate" "$repairs" \
        >>$out/results.tsv
    done
  done
done
