#!/usr/bin/env bash
# Object-count scaling and POV-Ray on the same field of random spheres
# (bench/povray/sphere_field.py): for each N, zeroset renders the field as N
# instances of one shared sphere and as N separate objects, 400×300, all
# threads, no anti-aliasing; POV-Ray 3.7 renders the same spheres. Prints
# median trace times (zeroset's from its summary, POV-Ray's own "Trace
# Time") and the POV-Ray ÷ zeroset ratio. OLD=path/to/an/older/zeroset adds
# a column for it on the objects form up to N = 1000 (before the BVH, every
# ray tested every object). Needs python3, povray and ./build/zeroset.
set -euo pipefail
cd "$(dirname "$0")/.."
counts=${COUNTS:-"10 100 1000 4000 10000 100000"}
runs=${RUNS:-3}
threads=${THREADS:-$(nproc)}
old=${OLD:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v povray >/dev/null || { echo "compare_spheres: povray is not installed (apt-get install povray)" >&2; exit 1; }

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# The trace seconds of a zeroset render, from its summary line.
zeroset_trace() {
  local binary=$1 scene=$2
  for _ in $(seq "$runs"); do
    "$binary" render "$scene" -o "$work/z.png" --threads "$threads" 2>&1 | tail -1 |
      sed -n 's/.*trace \([0-9.]*\) s).*/\1/p; s/.* threads\{0,1\}: \([0-9.]*\) s;.*/\1/p'
  done | median
}
povray_trace() {
  for _ in $(seq "$runs"); do
    povray "+I$1" "+O$work/p.png" +W400 +H300 -A -D "+WT$threads" 2>&1 |
      sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
  done | median
}

printf '%8s %12s %12s %12s %12s %10s\n' N instances objects povray old-linear "pov/inst"
for n in $counts; do
  python3 bench/povray/sphere_field.py "$n" --zs "$work/i.zs" --pov "$work/s.pov"
  python3 bench/povray/sphere_field.py "$n" --zs "$work/o.zs" --style objects
  ti=$(zeroset_trace ./build/zeroset "$work/i.zs")
  to=$(zeroset_trace ./build/zeroset "$work/o.zs")
  tp=$(povray_trace "$work/s.pov")
  tl="-"
  if [ -n "$old" ] && [ "$n" -le 1000 ]; then tl=$(zeroset_trace "$old" "$work/o.zs"); fi
  printf '%8s %10.3f s %10.3f s %10.3f s %12s %10.2f\n' "$n" "$ti" "$to" "$tp" "$tl" "$(echo "$tp / $ti" | bc -l)"
done
