#!/usr/bin/env bash
# Makes the inputs of `simplify_bench --preset scale` (docs/scale.md) from data/dragon.ply:
#   dragon4.ply    the dragon split in four (scripts/split_in_four.py), 3.49M faces, 66 MB
#   dragon16.ply   that split again, 13.9M faces, 265 MB
#   dragon128.ply  eight copies of dragon16.ply side by side (scripts/tile_copies.py), 111.5M
#                  faces, 2.1 GB
# Each file is made only when missing, with what it is made from, and appears only once whole.
#
# usage: scripts/make_scale_inputs.sh [DIR [FILE...]]
#   DIR   where they go (default $CGAL_POLICIES_SCALE_INPUTS, else /tmp/cgal_policies_scale, where
#         simplify_bench looks for them)
#   FILE  which to make (default all three), e.g. dragon4.ply alone
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:-${CGAL_POLICIES_SCALE_INPUTS:-/tmp/cgal_policies_scale}}"
shift || true
files=("$@")
[ ${#files[@]} -gt 0 ] || files=(dragon4.ply dragon16.ply dragon128.ply)
mkdir -p "$dir"

# make_input FILE: runs the step that writes FILE, into a temporary name renamed once it is whole.
make_input() {
  local file="$1" partial="$dir/.$1.partial"
  [ -f "$dir/$file" ] && return
  case "$file" in
    dragon4.ply) "$root/scripts/split_in_four.py" "$root/data/dragon.ply" "$partial" ;;
    dragon16.ply)
      make_input dragon4.ply
      "$root/scripts/split_in_four.py" "$dir/dragon4.ply" "$partial" ;;
    dragon128.ply)
      make_input dragon16.ply
      "$root/scripts/tile_copies.py" "$dir/dragon16.ply" "$partial" 8 ;;
    *)
      echo "make_scale_inputs.sh: unknown input '$file' (dragon4.ply, dragon16.ply, dragon128.ply)" >&2
      exit 2 ;;
  esac
  mv "$partial" "$dir/$file"
  echo "made $dir/$file"
}

for file in "${files[@]}"; do make_input "$file"; done
