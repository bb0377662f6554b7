#!/usr/bin/env bash
# Renders a scene with POV-Ray 3.7 and with zeroset (each method, and for the
# Barth sextic the polynomial method with each solver), same size, same
# threads, no anti-aliasing, in the same run, and prints the median times
# and the ratios: wall-clock against wall-clock, and POV-Ray's own "Trace
# Time" against zeroset's render time from its summary (the fair figure:
# both leave out parsing, start-up and writing the image).
#   SCENE=barth (default): the Barth sextic at 512×512, POV-Ray's `polynomial … sturm`;
#   SCENE=blobs: zeroset's default scene (Figure 1's Blinn blobs and a floor)
#                at 800×600, POV-Ray's isosurface (bench/povray/blinn_blobs.pov).
# Needs POV-Ray (`apt-get install povray`) and a built zeroset (./build/zeroset).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${SCENE:-barth}
threads=${THREADS:-$(nproc)}
runs=${RUNS:-3}
methods=${METHODS:-"auto interval lg sphere"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

command -v povray >/dev/null || { echo "compare_povray: povray is not installed (apt-get install povray)" >&2; exit 1; }
case $scene in
  barth)
    width=${SIZE:-512}
    height=$width
    solvers=${SOLVERS-"closed sturm descartes laguerre fast"}
    python3 bench/povray/expand_barth.py > "$work/terms.txt"
    sed -e "/@TERMS@/{r $work/terms.txt" -e "d}" bench/povray/barth_sextic.pov.in > "$work/scene.pov"
    zs=scenes/algebraic/barth_sextic.zs
    pov_label="povray (sturm)" ;;
  blobs)
    width=${WIDTH:-800}
    height=${HEIGHT:-600}
    solvers=${SOLVERS:-""}
    cp bench/povray/blinn_blobs.pov "$work/scene.pov"
    zs=scenes/hart1993/blinn_blobs.zs
    pov_label="povray (isosurface)" ;;
  *) echo "compare_povray: unknown SCENE '$scene' (barth or blobs)" >&2; exit 1 ;;
esac

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

# POV-Ray: the median wall-clock time, and the median of its own trace times.
pov=$(median_time povray "+I$work/scene.pov" "+O$work/pov.png" "+W$width" "+H$height" -A -D "+WT$threads" -GA)
trace_times=()
for _ in $(seq "$runs"); do
  povray "+I$work/scene.pov" "+O$work/pov.png" "+W$width" "+H$height" -A -D "+WT$threads" +GS -GR -GD -GF -GW > /dev/null 2> "$work/pov.txt"
  trace_times+=("$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov.txt" | head -1)")
done
pov_trace=$(printf '%s\n' "${trace_times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
printf '%-34s %8.3f s   (its own trace time %.3f s)\n' "$pov_label" "$pov" "$pov_trace"
# One zeroset render: a label, then the render's extra options. Prints the
# median wall-clock time and the median render time from zeroset's summary
# (preparing the objects and tracing: like POV-Ray's trace time, it leaves
# out reading the scene and writing the image).
zeroset_row() {
  local label=$1
  shift
  local walls=() renders=()
  for _ in $(seq "$runs"); do
    local start end
    start=$(date +%s.%N)
    ./build/zeroset render "$zs" -o "$work/zs.png" --width "$width" --height "$height" --threads "$threads" "$@" \
      > "$work/log.txt" 2>&1 || { echo "compare_povray: failed: zeroset $*" >&2; cat "$work/log.txt" >&2; exit 1; }
    end=$(date +%s.%N)
    walls+=("$(echo "$end - $start" | bc -l)")
    renders+=("$(sed -n 's/.* threads\{0,1\}: \([0-9.]*\) s (prepare.*/\1/p' "$work/log.txt" | tail -1)")
  done
  local t r
  t=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  r=$(printf '%s\n' "${renders[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  printf '%-34s %8.3f s   povray/zeroset = %.2f; render %.3f s, trace time / render = %.2f\n' "$label" "$t" \
    "$(echo "$pov / $t" | bc -l)" "$r" "$(echo "$pov_trace / $r" | bc -l)"
}
for m in $methods; do zeroset_row "zeroset --method $m" --method "$m"; done
for s in $solvers; do zeroset_row "zeroset --method polynomial --solver $s" --method polynomial --solver "$s"; done
