#!/usr/bin/env bash
# Renders the Barth sextic at 512×512 with POV-Ray 3.7 (`polynomial … sturm`)
# and with zeroset (each method, and the polynomial method with each solver),
# same size, same threads, no anti-aliasing, in the same run, and prints the
# median times and the ratios. Needs POV-Ray
# (`apt-get install povray`) and a built zeroset (./build/zeroset).
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-512}
threads=${THREADS:-$(nproc)}
runs=${RUNS:-3}
methods=${METHODS:-"auto interval lg sphere"}
solvers=${SOLVERS:-"closed sturm descartes laguerre fast"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

command -v povray >/dev/null || { echo "compare_povray: povray is not installed (apt-get install povray)" >&2; exit 1; }
python3 bench/povray/expand_barth.py > "$work/terms.txt"
sed -e "/@TERMS@/{r $work/terms.txt" -e "d}" bench/povray/barth_sextic.pov.in > "$work/barth_sextic.pov"

# Median wall-clock seconds of `runs` runs of a command.
median_time() {
  local times=()
  for _ in $(seq "$runs"); do
    local start end
    start=$(date +%s.%N)
    "$@" > "$work/log.txt" 2>&1 || { echo "compare_povray: failed: $*" >&2; cat "$work/log.txt" >&2; exit 1; }
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc -l)")
  done
  printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}

pov=$(median_time povray "+I$work/barth_sextic.pov" "+O$work/pov.png" "+W$size" "+H$size" -A -D "+WT$threads" -GA)
printf '%-34s %8.3f s\n' "povray (sturm)" "$pov"
# One zeroset render: a label, then the render's extra options.
zeroset_row() {
  local label=$1
  shift
  local t
  t=$(median_time ./build/zeroset render scenes/algebraic/barth_sextic.zs -o "$work/zs.png" \
        --width "$size" --height "$size" --threads "$threads" -q "$@")
  printf '%-34s %8.3f s   povray/zeroset = %.2f\n' "$label" "$t" "$(echo "$pov / $t" | bc -l)"
}
for m in $methods; do zeroset_row "zeroset --method $m" --method "$m"; done
for s in $solvers; do zeroset_row "zeroset --method polynomial --solver $s" --method polynomial --solver "$s"; done
