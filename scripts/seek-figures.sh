#!/usr/bin/env bash
# What scrubbing costs in the window (docs/results/seek.md): `gridcull bench
# --seek` times, for each family's culler with temporal state, a step forward
# into frames 100, 300 and 590 of scenes/forest-walk-3d.json and a step back
# into them, and into 103, 303 and 591 (three frames past a checkpoint, the
# most a step back replays with the default spacing of 4), R runs each, through
# the window's own session (checkpoints, oracle). Writes OUT_DIR/seek.txt.
#
# usage: scripts/seek-figures.sh BUILD_DIR OUT_DIR [RUNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: scripts/seek-figures.sh BUILD_DIR OUT_DIR [RUNS]}
out=${2:?usage: scripts/seek-figures.sh BUILD_DIR OUT_DIR [RUNS]}
runs=${3:-3}
[ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target gridcull -j2 >/dev/null
mkdir -p "$out"
"$build/app/gridcull" bench "$root/scenes/forest-walk-3d.json" --algo rgvc,hzb-tbv,lazy-grid,bsp-oq \
    --seek 100,300,590,103,303,591 --runs "$runs" | tee "$out/seek.txt"
