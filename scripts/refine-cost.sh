#!/usr/bin/env bash
# What the 3D oracle's sub-sample question costs (culling/oracle/exact_oracle.h,
# "Sub-sample objects"; docs/LIMITS.md, "Oracle"): for every shipped 3D scene,
# `gridcull bench` times the oracle alone (`exact`) and with refinement on
# (`exact:oracle-refine=1`) on the same first FRAMES frames, side by side, with
# the sub-sample counters per frame; then what one Embree ray per pixel centre
# would cost instead of the rasterized oracle (tests/tools/embree_ray_cost.cpp).
# Writes OUT_DIR/refine-cost.txt and OUT_DIR/embree-ray-cost.txt.
#
# usage: scripts/refine-cost.sh BUILD_DIR OUT_DIR [FRAMES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: scripts/refine-cost.sh BUILD_DIR OUT_DIR [FRAMES]}
out=${2:?usage: scripts/refine-cost.sh BUILD_DIR OUT_DIR [FRAMES]}
frames=${3:-48}
[ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target gridcull embree_ray_cost -j2 >/dev/null
mkdir -p "$out"
: >"$out/refine-cost.txt"
for scene in "$root"/scenes/*.json; do
    grep -q '"dimensions": 3' "$scene" || continue
    "$build/app/gridcull" bench "$scene" --algo exact,exact:oracle-refine=1 --no-quality \
        --runs 1 --frames "$frames" | grep -v '^options:' | tee -a "$out/refine-cost.txt"
done
"$build/tests/embree_ray_cost" "$frames" "$root"/scenes/*.json | tee "$out/embree-ray-cost.txt"
