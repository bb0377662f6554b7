#!/usr/bin/env bash
# Meshing benchmark (issue 12): `zeroset mesh` on the shared bear.vm within
# its bounds (bench/scenes/bear.zs) at resolutions 128, 256 and 512, by each
# method (METHODS, default "dual tetrahedra") — median wall time of RUNS
# runs (default 3), triangles and vertices. Needs a
# built ./build and the shared models beside the repository.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
if [ ! -f ../shared/models/bear.vm ]; then
  echo "mesh_bench.sh: skipped: ../shared/models/bear.vm is not beside the repository" >&2
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

printf '%-11s %-10s %10s %12s %12s\n' method resolution seconds triangles vertices
for method in ${METHODS:-dual tetrahedra}; do
  for r in 128 256 512; do
    for _ in $(seq "$runs"); do
      ./build/zeroset mesh bench/scenes/bear.zs -o "$work/bear.ply" --resolution "$r" --method "$method" 2> "$work/log.txt"
      sed -n 's/.* in \([0-9.]*\) s;.*/\1/p' "$work/log.txt"
    done | median > "$work/median.txt"
    triangles=$(sed -n 's/.* — \([0-9]*\) triangles.*/\1/p' "$work/log.txt")
    vertices=$(sed -n 's/.*triangles, \([0-9]*\) vertices.*/\1/p' "$work/log.txt")
    printf '%-11s %-10s %10s %12s %12s\n' "$method" "$r" "$(cat "$work/median.txt")" "$triangles" "$vertices"
  done
done
