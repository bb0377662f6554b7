#!/usr/bin/env bash
# Sanitizer jobs of CI (docs/fuzzing.md), built with the same g++ as the
# normal build:
#   asan — AddressSanitizer and UndefinedBehaviorSanitizer; the whole suite.
#   tsan — ThreadSanitizer; the render and command-line tests, the ones that
#          run the renderer's worker threads.
# Any report aborts the test that made it, so the job fails.
# Usage: scripts/sanitize.sh asan|tsan
set -euo pipefail
cd "$(dirname "$0")/.."

job="${1:-}"
case "$job" in
  asan) sanitizers=address,undefined ;;
  tsan) sanitizers=thread ;;
  *) echo "usage: scripts/sanitize.sh asan|tsan" >&2; exit 2 ;;
esac
build="build-$job"

bash scripts/install-deps.sh
# -O1 with line tables (-g1, set with the sanitizers) builds in about half
# the time of -O3 -g and still runs the suite in a few minutes; asserts stay
# on. Warnings are not errors here: instrumented code makes GCC's flow
# analysis report false "maybe uninitialized" in std::regex. Without MPI:
# Open MPI's own allocations and threads are not instrumented, so the
# sanitizers would report them (its tests are skipped here; NOTES.md).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
  -DZEROSET_SANITIZE="$sanitizers" -DZEROSET_BUILD_BENCH=OFF -DZEROSET_WERROR=OFF -DZEROSET_MPI=OFF >/dev/null

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"

if [ "$job" = asan ]; then
  cmake --build "$build" --parallel "$(nproc)"
  ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" --timeout 1200
else
  cmake --build "$build" --parallel "$(nproc)" --target render_tests apps_tests zeroset_app
  # Run from the build folder, as CTest does.
  (cd "$build" && tests/render_tests --gtest_brief=1 && tests/apps_tests --gtest_brief=1)
fi
