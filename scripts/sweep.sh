#!/usr/bin/env bash
# The long sweep (docs/ARCHITECTURE.md, "The long sweep"):
#   scripts/sweep.sh MINUTES [--seed N] [--res R] [--threads T] [--out DIR] ...
# Builds the `sweep` tool (tests/sweep) into build/ (or $GRIDCULL_BUILD_DIR,
# configured RelWithDebInfo if it is not yet) and runs every conservative
# algorithm of the family registry against the exact oracle on fresh seeded
# random scenes for MINUTES minutes. Prints the base seed, a progress line
# every 10 s, and per algorithm the scenes, scene-frames, false culls and
# time; a scene with a false cull is written to DIR (default
# BUILD/sweep-out/sweep-SEED.json) with the `gridcull cull` command that
# replays it. Exit status 1 if any false cull. Other flags go to the tool
# (`BUILD/tests/sweep --help`). Not part of scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+([.][0-9]+)?$ ]]; then
  echo "usage: scripts/sweep.sh MINUTES [--seed N] [--res R] [--threads T] [--out DIR]" >&2
  exit 2
fi
minutes="$1"
shift
build_dir="${GRIDCULL_BUILD_DIR:-build}"
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build_dir" -j"$(nproc)" --target sweep >/dev/null
out=()
if [[ " $* " != *" --out "* ]]; then out=(--out "$build_dir/sweep-out"); fi
exec "$build_dir/tests/sweep" "$minutes" --threads "$(nproc)" "${out[@]}" "$@"
