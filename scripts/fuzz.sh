#!/usr/bin/env bash
# Builds the fuzz targets with clang, libFuzzer, ASan and UBSan, and runs each
# for FUZZ_SECONDS (default 60) from a copy of its seed corpus, with its
# dictionary. Any finding — a crash, a sanitizer report, an input slower than
# 10 s or one that takes more than 2.5 GiB — fails the script; libFuzzer
# leaves the input as crash-*, timeout-* or oom-* in build-fuzz/findings.
# Usage: scripts/fuzz.sh [target…]   (default: every target; docs/fuzzing.md)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${FUZZ_SECONDS:-60}"
build="${FUZZ_BUILD_DIR:-build-fuzz}"
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_parser vm_import render ray_list pov_import)

bash scripts/install-deps.sh --fuzz
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DZEROSET_FUZZ=ON -DZEROSET_BUILD_TESTS=OFF -DZEROSET_BUILD_BENCH=OFF -DZEROSET_WERROR=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
build="$(cd "$build" && pwd)"
source_dir="$PWD"

corpus_of() {
  case "$1" in
    scene_parser | render) echo scene ;;
    vm_import) echo vm ;;
    ray_list) echo rays ;;
    pov_import) echo pov ;;
    *) echo "fuzz.sh: unknown target $1" >&2; exit 2 ;;
  esac
}

findings="$build/findings"
mkdir -p "$findings"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

failed=()
for target in "${targets[@]}"; do
  kind="$(corpus_of "$target")"
  cp -r "fuzz/corpus/$kind" "$work/$target"
  echo "fuzz.sh: $target for ${seconds} s" >&2
  # Leak detection is off: interned expression nodes live for the whole run
  # by design, and LeakSanitizer would rescan them after every input.
  if ! (cd "$work/$target" && "$build/fuzz/fuzz_$target" . \
          -dict="$source_dir/fuzz/dict/$kind.dict" -max_total_time="$seconds" -timeout=10 \
          -rss_limit_mb=2560 -max_len=4096 -detect_leaks=0 -print_final_stats=1 \
          -artifact_prefix="$findings/$target-" 2>"$work/$target.log"); then
    failed+=("$target")
    tail -n 60 "$work/$target.log" >&2
  fi
  grep -E "DONE|^stat::(number_of_executed_units|peak_rss_mb)" "$work/$target.log" >&2 || true
done

if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz.sh: findings in ${failed[*]}; the inputs are in $findings" >&2
  exit 1
fi
echo "fuzz.sh: no findings in ${targets[*]}" >&2
