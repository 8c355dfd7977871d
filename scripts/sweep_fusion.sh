#!/usr/bin/env bash
# Chooses the defaults of the fusion policy (docs/fusion.md): simplifies bunny, fandisk, nefertiti,
# cow and rocker-arm to 10% and 1% of their faces for every (mu, visual-weight) of a small grid, and
# ranks the pairs by their mean two-sided error, (mean_a_to_b_rel + mean_b_to_a_rel) / 2, divided by
# that of CGAL's gh on the same case, then averaged over the ten cases (so that each case counts
# the same whatever its scale).
#
# usage: scripts/sweep_fusion.sh [BIN_DIR] [OUT_DIR]
#   BIN_DIR  where simplify is (default build/bin)
#   OUT_DIR  where the raw results go (default out/sweep_fusion); results.tsv holds one line a run
# Environment: DATA (default the project's data/), SAMPLES per direction for --measure (default 50000),
#   MUS and WEIGHTS (the grid, space-separated), MESHES (default bunny fandisk nefertiti cow
#   rocker-arm). About 20 minutes on a busy 2-core machine.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${1:-$root/build/bin}"
out="${2:-$root/out/sweep_fusion}"
data="${DATA:-$root/data}"
samples="${SAMPLES:-50000}"
mus="${MUS:-0 0.5 2 8}"
weights="${WEIGHTS:-0 0.005 0.02}"
meshes="${MESHES:-bunny fandisk nefertiti cow rocker-arm}"
ratios="0.1 0.01"

[[ -x "$bin/simplify" ]] || { echo "sweep_fusion: $bin/simplify: not built" >&2; exit 2; }
mkdir -p "$out"
results="$out/results.tsv"
printf 'mesh\tratio\tpolicy\tmu\tvisual_weight\tfaces\tseconds\tmean_rel\thausdorff_rel\n' >"$results"

# run MESH RATIO POLICY MU WEIGHT [simplify options...]: appends one line to results.tsv.
run() {
  local mesh=$1 ratio=$2 policy=$3 mu=$4 weight=$5
  shift 5
  "$bin/simplify" "$data/$mesh.obj" "$out/last.obj" "$ratio" --policy "$policy" "$@" \
    --json --measure --quiet --samples "$samples" |
    jq -r --arg m "$mesh" --arg r "$ratio" --arg p "$policy" --arg mu "$mu" --arg w "$weight" \
      '[$m, $r, $p, $mu, $w, .output_faces, .seconds,
        (.mean_a_to_b_rel + .mean_b_to_a_rel) / 2, .hausdorff_rel] | @tsv' >>"$results"
}

for mesh in $meshes; do
  for ratio in $ratios; do
    echo "sweep_fusion: $mesh $ratio" >&2
    run "$mesh" "$ratio" gh - -
    for mu in $mus; do
      for weight in $weights; do
        run "$mesh" "$ratio" fusion "$mu" "$weight" --mu "$mu" --visual-weight "$weight"
      done
    done
  done
done

# The table: per pair, the mean over the cases of error / gh's error (mean and Hausdorff), and the
# mean error in % of the diagonal; best first.
awk -F'\t' '
  NR == 1 { next }
  $3 == "gh" { gh_mean[$1 " " $2] = $8; gh_haus[$1 " " $2] = $9; next }
  {
    key = $4 "\t" $5; c = $1 " " $2
    mean_ratio[key] += $8 / gh_mean[c]; haus_ratio[key] += $9 / gh_haus[c]
    mean_pct[key] += 100 * $8; cases[key]++
  }
  END {
    for (key in cases)
      printf "%s\t%.4f\t%.4f\t%.5f\n", key, mean_ratio[key] / cases[key],
             haus_ratio[key] / cases[key], mean_pct[key] / cases[key]
  }' "$results" | sort -t$'\t' -k3,3g |
  { printf 'mu\tw_v\tmean/gh\thausdorff/gh\tmean %%diag\n'; cat; } | column -t -s$'\t'
