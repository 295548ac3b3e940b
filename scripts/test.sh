#!/usr/bin/env bash
# One command to pass every test: installs what is missing, builds, and runs
#  1. the core libraries (grid, culling) built alone with GRIDCULL_CORE_ONLY=ON,
#     which proves they need no GL, GLFW or ImGui, and with GRIDCULL_SANITIZE=ON:
#     their tests (the extremes suite among them) run under AddressSanitizer,
#     LeakSanitizer and UndefinedBehaviorSanitizer, and any report fails them (the
#     long random sweeps on a fifth of their scenes: tests/common/test_seeds.h);
#  2. the full build's tests, the screenshot tests among them (under xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs="$(nproc)"

echo "== core libraries alone (no GL, GLFW or ImGui), under ASan + UBSan =="
# Exported before building too: gtest_discover_tests runs core_tests at build time.
# LeakSanitizer cannot work under ptrace (a debugger, strace, some sandboxes): there
# it would fail every test, so leak checking is turned off with a note instead.
detect_leaks=1
if grep -q '^TracerPid:[[:space:]]*[1-9]' /proc/$$/status 2>/dev/null; then
  echo "note: running under ptrace, LeakSanitizer disabled (detect_leaks=0)"
  detect_leaks=0
fi
export ASAN_OPTIONS="detect_leaks=$detect_leaks:check_initialization_order=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
GRIDCULL_BUILD_DIR=build-core-asan scripts/build.sh -DGRIDCULL_CORE_ONLY=ON -DGRIDCULL_SANITIZE=ON
ctest --test-dir build-core-asan --output-on-failure -j"$jobs"
unset ASAN_OPTIONS UBSAN_OPTIONS

echo "== full build =="
scripts/build.sh
export LIBGL_ALWAYS_SOFTWARE=1
if [ -z "${DISPLAY:-}" ]; then
  xvfb-run -a -s "-screen 0 1280x720x24" ctest --test-dir build --output-on-failure -j"$jobs"
else
  ctest --test-dir build --output-on-failure -j"$jobs"
fi
