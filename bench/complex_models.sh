#!/usr/bin/env bash
# The benchmark table of issue 10 ("complex models fast"), in one run on this
# machine: whole renders and slices of real models, medians of RUNS runs
# (default 3; bear at 1024² once unless BEAR_RUNS says otherwise), plus the
# octree builds (bench/octree_bench) and the simple scenes against POV-Ray
# (bench/compare_povray.sh). Needs a built ./build (with bench/) and, for
# the last part, POV-Ray (`apt-get install povray`).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
bear_runs=${BEAR_RUNS:-1}
threads=${THREADS:-$(nproc)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
models=../shared/models
if [ ! -f "$models/bear.vm" ] || [ ! -f "$models/prospero.vm" ]; then
  echo "complex_models.sh: skipped: the shared models ($models/bear.vm, prospero.vm) are not beside the repository" >&2
  exit 0
fi

# The median of the numbers on stdin.
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# Runs a command n times and prints the median of the time that the sed
# pattern extracts from its stderr; the last stderr stays in $work/log.txt.
timed() {
  local n=$1 pattern=$2
  shift 2
  for _ in $(seq "$n"); do
    "$@" 2> "$work/log.txt"
    sed -n "$pattern" "$work/log.txt"
  done | median
}

render_row() {
  local label=$1 n=$2
  shift 2
  local t
  t=$(timed "$n" 's/.*: \([0-9.]*\) s (prepare.*/\1/p' ./build/zeroset render "$@" --threads "$threads" -o "$work/out.png")
  printf '| %s | %s s | %s |\n' "$label" "$t" "$(sed -n 's/.*objects: //p' "$work/log.txt")"
}

slice_row() {
  local label=$1 t=$2
  shift 2
  printf '| %s, %s thread(s) | %s ms | |\n' "$label" "$t" \
    "$(timed "$runs" 's/.* in \([0-9.]*\) ms.*/\1/p' ./build/zeroset slice "$@" --threads "$t" -o "$work/slice.png")"
}

python3 bench/models/molecule.py 50 > "$work/molecule.zs"
echo "| case | time | details |"
echo "| --- | --- | --- |"
render_row "bear.vm, 1024², shaded, shadows" "$bear_runs" bench/scenes/bear.zs --width 1024 --height 1024
render_row "50-atom exp molecule, 640×480" "$runs" "$work/molecule.zs"
slice_row "prospero.vm slice, 1024²" 1 ../shared/models/prospero.vm --size 1024
slice_row "prospero.vm slice, 1024²" 2 ../shared/models/prospero.vm --size 1024
echo
./build/bench/octree_bench --benchmark_repetitions="$runs" --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E "_median|Benchmark" || true
echo
if command -v povray >/dev/null; then
  SCENE=blobs METHODS=auto RUNS=$runs THREADS=$threads bash bench/compare_povray.sh
  SCENE=barth METHODS=auto SOLVERS= RUNS=$runs THREADS=$threads bash bench/compare_povray.sh
fi
