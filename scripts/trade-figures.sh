#!/usr/bin/env bash
# The figures of docs/results/trade.md: for each scene, every family's speed /
# accuracy trade with `gridcull trade` (the picks for PVS/exact 1.5 and 2.0,
# CSV and plots), and the frame-time table with `gridcull bench --draw gl`
# (cull, draw, frame; ratios against `all`, the plain z-buffer, and `limit`,
# the exact visible set drawn). Drawing is OpenGL, Mesa's llvmpipe under
# xvfb-run when there is no display. Writes OUT_DIR/<scene>/ (trade.csv, the
# PNGs, trade.txt) and OUT_DIR/<scene>-frame.txt / .csv.
#
# usage: scripts/trade-figures.sh BUILD_DIR OUT_DIR [FRAMES [RUNS]]
#   FRAMES  frames of each 3D scene (default 60; figure1-2d runs all 200)
#   RUNS    runs of each setting and bench (default 2)
# SCENES="a b" redoes only those scenes (default all three), e.g. after one changed.
# About 25 minutes on the 2-core development machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$1
out=$2
frames=${3:-60}
runs=${4:-2}
[ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target gridcull -j2 >/dev/null
exe=$build/app/gridcull
run() {  # the command, under xvfb-run when there is no display
    if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1280x720x24" "$@"; fi
}
mkdir -p "$out"
figure() {  # scene-name frames algorithms
    local scene=$1 n=$2 algos=$3
    echo "== $scene: trade of $algos, $n frames, $runs runs"
    run "$exe" trade "$root/scenes/$scene.json" --algo "$algos" --frames "$n" --runs "$runs" \
        --draw gl --target 1.5,2.0 --out "$out/$scene" | tee "$out/$scene/trade.txt.tmp"
    mv "$out/$scene/trade.txt.tmp" "$out/$scene/trade.txt"
    echo "== $scene: frame times"
    run "$exe" bench "$root/scenes/$scene.json" --algo "all,$algos" --frames "$n" --runs "$runs" \
        --draw gl --baseline all --csv "$out/$scene-frame.csv" | tee "$out/$scene-frame.txt"
}
scenes=" ${SCENES:-figure1-2d forest-walk-3d city-walk-3d} "
for scene in $scenes; do
    case "$scene" in
    figure1-2d | forest-walk-3d | city-walk-3d) mkdir -p "$out/$scene" ;;
    *) echo "SCENES: '$scene' is not one of figure1-2d forest-walk-3d city-walk-3d" >&2; exit 2 ;;
    esac
done
wanted() { [[ "$scenes" == *" $1 "* ]]; }
if wanted figure1-2d; then figure figure1-2d 200 vfc,rgvc; fi
if wanted forest-walk-3d; then figure forest-walk-3d "$frames" vfc,rgvc,hzb-tbv,lazy-grid,bsp-oq; fi
if wanted city-walk-3d; then figure city-walk-3d "$frames" vfc,rgvc,hzb-tbv,lazy-grid,bsp-oq; fi
