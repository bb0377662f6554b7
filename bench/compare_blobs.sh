#!/usr/bin/env bash
# The blob primitive's scale table (docs/blobs.md) and POV-Ray's blob on the
# same components: for each N, one blob of N POV-Ray-kernel components
# (bench/blobs/blob_scene.py, LAYOUT=cloud|surface|molecule) at 512×512, all
# threads, shadows on, no anti-aliasing. Prints zeroset's median render time
# (prepare + trace, from its summary: the scene's parsing is not in it), the
# components a ray came within reach of, the blob's memory, POV-Ray's own
# median "Trace Time" and the POV-Ray ÷ zeroset ratio. POVRAY_MAX=N skips
# POV-Ray above N components (default 10000). Needs python3, povray and
# ./build/zeroset.
set -euo pipefail
cd "$(dirname "$0")/.."
counts=${COUNTS:-"10 100 1000 10000 100000"}
runs=${RUNS:-3}
threads=${THREADS:-$(nproc)}
layout=${LAYOUT:-cloud}
povray_max=${POVRAY_MAX:-10000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v povray >/dev/null || { echo "compare_blobs: povray is not installed (apt-get install povray)" >&2; exit 1; }

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
zeroset_render() {
  for _ in $(seq "$runs"); do
    ./build/zeroset render "$1" -o "$work/z.png" --threads "$threads" 2>&1 | tail -1 > "$work/summary"
    sed -n 's/.* threads\{0,1\}: \([0-9.]*\) s (prepare.*/\1/p' "$work/summary"
  done | median
}
povray_trace() {
  for _ in $(seq "$runs"); do
    povray "+I$1" "+O$work/p.png" +W512 +H512 -A -D "+WT$threads" 2>&1 |
      sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
  done | median
}

printf '%8s %12s %14s %10s %12s %9s\n' N zeroset "components/ray" memory povray "pov/zs"
for n in $counts; do
  python3 bench/blobs/blob_scene.py "$n" --layout "$layout" --zs "$work/b.zs" --pov "$work/b.pov"
  tz=$(zeroset_render "$work/b.zs")
  per_ray=$(sed -n 's/.*; \([0-9.]*\) blob components a ray.*/\1/p' "$work/summary")
  memory=$(sed -n 's/.*nodes, \([0-9.]*\) MB.*/\1/p' "$work/summary")
  if [ "$n" -le "$povray_max" ]; then
    tp=$(povray_trace "$work/b.pov")
    ratio=$(echo "$tp / $tz" | bc -l)
    printf '%8s %10.3f s %14s %7s MB %10.3f s %9.2f\n' "$n" "$tz" "$per_ray" "$memory" "$tp" "$ratio"
  else
    printf '%8s %10.3f s %14s %7s MB %12s %9s\n' "$n" "$tz" "$per_ray" "$memory" "-" "-"
  fi
done
