#!/usr/bin/env bash
# One command to pass every test: installs what is missing, builds, and runs
#  1. the core libraries (grid, culling) built alone with GRIDCULL_CORE_ONLY=ON, and
#     their tests (labelled "core"): the proof that they need no GL, GLFW or ImGui.
#     Not sanitized: stage 2 runs the same tests under the sanitizers, and these
#     are the full build's core tests (same compiler and flags), so stage 3 skips
#     them; the long random sweeps run here on all their scenes. Built in build/,
#     which stage 3 turns into the full build: the core's objects are reused, not
#     compiled twice;
#  2. the whole program built with GRIDCULL_SANITIZE=ON and every test but the
#     screenshots under AddressSanitizer and UndefinedBehaviorSanitizer, and
#     LeakSanitizer but in the app tests (the reason is below):
#     core (the long random sweeps on a fifth of their scenes: tests/common/
#     test_seeds.h), ui, app, and the real window driven headless through every
#     culler of the registry on 2D and 3D scenes (tests/app/window_tour_test.cpp).
#     Any report fails the run, in a child process too. The screenshot tests are
#     left to stage 3: they compare pictures, which the sanitizers do not change,
#     and would only add minutes here;
#  3. the full build's tests but the core ones (run in stage 1), the screenshot
#     tests among them;
#  4. each libFuzzer target (tests/fuzz/) for GRIDCULL_FUZZ_SECONDS seconds (60 by
#     default, 0 skips the stage) from the corpus committed in tests/fuzz/corpus/,
#     built with clang by scripts/fuzz.sh; a crash, leak or hang fails the run
#     and the message names the input, left in build-fuzz/artifacts/.
# Stages 2 and 3 need a display: xvfb-run provides one when DISPLAY is unset.
# Each stage prints its time; README.md ("Test it") gives them, measured.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs="$(nproc)"
fuzz_seconds="${GRIDCULL_FUZZ_SECONDS:-60}"
if ! [[ "$fuzz_seconds" =~ ^[0-9]+$ ]]; then
  echo "GRIDCULL_FUZZ_SECONDS must be a whole number of seconds, not '$fuzz_seconds'" >&2
  exit 2
fi
export LIBGL_ALWAYS_SOFTWARE=1
# -noreset: by default Xvfb resets itself whenever its last client disconnects, and
# a test that connects during that reset is dropped ("Failed to open display": one
# window test in a whole CI run). Four processes each opening and closing a display
# 300 times lost 39 of the 1200 connections that way; with -noreset, none.
with_display() {
  if [ -z "${DISPLAY:-}" ]; then
    xvfb-run -a -s "-screen 0 1280x720x24 -noreset" "$@"
  else
    "$@"
  fi
}
stage_start=$SECONDS
stage_done() { echo "== $1: $((SECONDS - stage_start)) s =="; stage_start=$SECONDS; }

echo "== 1. core libraries alone (no GL, GLFW or ImGui) =="
scripts/build.sh -DGRIDCULL_CORE_ONLY=ON
ctest --test-dir build --output-on-failure -j"$jobs"
stage_done "1. core libraries alone"

echo "== 2. the whole program under ASan + LSan + UBSan =="
# LeakSanitizer cannot work under ptrace (a debugger, strace, some sandboxes): there
# it would fail every test, so leak checking is turned off with a note instead.
detect_leaks=1
if grep -q '^TracerPid:[[:space:]]*[1-9]' /proc/$$/status 2>/dev/null; then
  echo "note: running under ptrace, LeakSanitizer disabled (detect_leaks=0)"
  detect_leaks=0
fi
# Every report goes to a file in $reports as well as failing its process (exit
# status 86, which no test expects: tests that run gridcull and expect it to fail
# with 1 or 2 cannot mistake a sanitizer's exit for the error they wait for). The
# files are checked after the tests, so a report in a child process whose status a
# test ignored still fails the run. Exported before building too: the test lists
# are read by running the test programs at build time.
reports="$PWD/build-asan/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
export ASAN_OPTIONS="detect_leaks=$detect_leaks:check_initialization_order=1:strict_string_checks=1:exitcode=86:log_path=$reports/asan"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=86:log_path=$reports/ubsan"
GRIDCULL_BUILD_DIR=build-asan scripts/build.sh -DGRIDCULL_SANITIZE=ON
status=0
with_display ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE "screenshots|app" ||
  status=$?
# The app tests (label "app": the window, GL, the gridcull executable) run with
# leak checking off. Mesa's software driver leaks a few blocks from its one-time
# set-up, allocated by its own code, which has no frame pointers and is unloaded
# at exit: LeakSanitizer reports them with no frame it can name (or names the
# wrong library), so no suppression can match them. ASan and UBSan still check
# every access and operation there; the core and ui tests above check leaks.
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=$detect_leaks/detect_leaks=0}" \
  with_display ctest --test-dir build-asan --output-on-failure -j"$jobs" -L app || status=$?
if [ -n "$(ls -A "$reports")" ]; then
  echo "sanitizer reports (in $reports):" >&2
  cat "$reports"/* >&2
  status=1
fi
[ "$status" -eq 0 ] || exit "$status"
unset ASAN_OPTIONS UBSAN_OPTIONS
stage_done "2. whole program sanitized"

echo "== 3. full build =="
# The same build directory as stage 1, with the rest switched on: grid/, culling/
# and core_tests are up to date, so only ui/, app/ and their tests compile here.
scripts/build.sh -DGRIDCULL_CORE_ONLY=OFF
with_display ctest --test-dir build --output-on-failure -j"$jobs" -LE core
stage_done "3. full build"

echo "== 4. fuzzing, $fuzz_seconds s per target =="
if [ "$fuzz_seconds" -gt 0 ]; then
  ASAN_OPTIONS="detect_leaks=$detect_leaks" UBSAN_OPTIONS="print_stacktrace=1" \
    FUZZ_FRESH=1 FUZZ_TARGET=all scripts/fuzz.sh "$fuzz_seconds"
fi
stage_done "4. fuzzing"
