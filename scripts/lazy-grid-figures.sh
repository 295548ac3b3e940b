#!/usr/bin/env bash
# Reproduces Hey, Tobler & Purgathofer's Fig. 7-9 (triangles drawn, pixel-level
# queries and time per frame; lazy vs busy vs no occlusion culling, two
# resolutions) on the forest and city walkthroughs, the cell-size curve (8..64
# pixels) and the section 6 extensions, with `gridcull bench`. Writes the tables
# (.txt), per-frame CSVs and PNG plots to docs/results/lazy-grid/ (or $1).
# Needs gnuplot for the plots (Debian's gnuplot-nox, installed when missing).
# "No occlusion culling" is vfc, as in the paper ("but also with hierarchical
# view frustum culling"). Takes about 10 minutes on one core.
# GRIDCULL_BUILD_DIR=DIR builds and runs the gridcull in DIR instead of build/.
#
# usage: scripts/lazy-grid-figures.sh [--plots-only] [OUT_DIR] [RUNS]
#   --plots-only   redraw the PNGs from the .csv / .txt files already in OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
plots_only=0
if [ "${1:-}" = "--plots-only" ]; then
    plots_only=1
    shift
fi
out=${1:-docs/results/lazy-grid}
runs=${2:-3}
scripts/install-deps.sh
if ! command -v gnuplot >/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends gnuplot-nox
fi
# The build users run (scripts/build.sh: RelWithDebInfo, asserts live), gridcull
# only, in build/ or $GRIDCULL_BUILD_DIR.
build_dir="${GRIDCULL_BUILD_DIR:-build}"
if [ "$plots_only" -eq 0 ]; then
    cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
    cmake --build "$build_dir" -j"$(nproc)" --target gridcull >/dev/null
fi
exe=$build_dir/app/gridcull
# Runs one bench into a table file, unless only the plots are redrawn.
bench() {  # table-file bench-arguments...
    local table=$1
    shift
    [ "$plots_only" -eq 1 ] && return 0
    "$exe" bench "$@" | tee "$table"
}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One column of one algorithm's rows, as "frame value" lines.
series() {  # csv algo column-name
    awk -F, -v algo="$2" -v name="$3" '
        NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) col = i; next }
        $1 == algo && col { print $2, $col }' "$1"
}

plot() {  # csv png title ylabel column logscale(0|1) algo...
    local csv=$1 png=$2 title=$3 ylabel=$4 column=$5 log=$6
    shift 6
    local cmd="" algo
    for algo in "$@"; do
        series "$csv" "$algo" "$column" >"$tmp/$algo.dat"
        cmd+="${cmd:+, }'$tmp/$algo.dat' using 1:2 with lines lw 2 title '$algo'"
    done
    gnuplot <<GP
set terminal png size 900,420 font ",11"
set output '$png'
set title '$title'
set xlabel 'frame'
set ylabel '$ylabel'
set key outside right
set grid
$([ "$log" -eq 1 ] && echo "set logscale y")
plot $cmd
GP
}

algos=vfc,busy-grid,busy-grid-tight,lazy-grid,lazy-grid-z
for scene in forest-walk-3d city-walk-3d; do
    for res in 640 1280; do
        name="$scene-$res"
        echo "== $name: $algos at $res pixels (4:3), $runs runs"
        bench "$out/$name.txt" "scenes/$scene.json" --algo "$algos" --runs "$runs" \
            --oracle-res "$res" --csv "$out/$name.csv"
        plot "$out/$name.csv" "$out/$name-triangles.png" "$scene at $res: triangles drawn (Fig. 7)" \
            "triangles (log scale)" pvs_triangles 1 vfc busy-grid lazy-grid lazy-grid-z
        plot "$out/$name.csv" "$out/$name-pixel-queries.png" \
            "$scene at $res: pixel-level queries (Fig. 8)" "queries" pixel_queries 0 busy-grid \
            busy-grid-tight lazy-grid lazy-grid-z
        plot "$out/$name.csv" "$out/$name-time.png" "$scene at $res: cull time (Fig. 9)" \
            "ms (median over runs)" cull_ms_median 0 busy-grid busy-grid-tight lazy-grid lazy-grid-z
    done
done

# The cell-size curve, and with the probability threshold, whose accuracy depends on it.
sizes="8 12 16 24 32 48 64"
for scene in forest-walk-3d city-walk-3d; do
    list=""
    for s in $sizes; do
        list+="${list:+,}busy-grid:lazy-cell-size=$s,busy-grid-tight:lazy-cell-size=$s"
        list+=",lazy-grid:lazy-cell-size=$s,lazy-grid:lazy-cell-size=$s:lazy-prob=0.5"
    done
    echo "== $scene: cell sizes $sizes at 640"
    bench "$out/$scene-cell-size.txt" "scenes/$scene.json" --algo "vfc,$list" --runs "$runs" \
        --oracle-res 640
    # Rows: label median ... pvs/exact (7th) ... pixel_queries=Q among the counters.
    # Tables written before the knobs were named after their family say "cell-size=".
    awk '$1 ~ /cell-size=/ {
            split($1, a, "cell-size="); split(a[2], b, ":"); kind = $1
            sub(/:(lazy-)?cell-size=[0-9]+/, "", kind)
            q = ""; for (i = 11; i <= NF; ++i) if ($i ~ /^pixel_queries=/) { q = $i; sub(/.*=/, "", q) }
            print kind, b[1], $2, q, $7 }' "$out/$scene-cell-size.txt" >"$tmp/cells.dat"
    for kind in busy-grid busy-grid-tight lazy-grid lazy-grid:lazy-prob=0.5; do
        awk -v k="$kind" '$1 == k { print $2, $3, $4, $5 }' "$tmp/cells.dat" >"$tmp/cells-$kind.dat"
    done
    gnuplot <<GP
set terminal png size 900,700 font ",11"
set output '$out/$scene-cell-size.png'
set multiplot layout 3,1 title '$scene at 640: cell size trade (median of $runs runs)'
set grid
set key outside right
set logscale x 2
set xtics (8, 12, 16, 24, 32, 48, 64)
set xrange [7:72]
set ylabel 'median ms'
plot for [k in "busy-grid busy-grid-tight lazy-grid lazy-grid:lazy-prob=0.5"] '$tmp/cells-'.k.'.dat' using 1:2 with linespoints lw 2 title k
set ylabel 'pixel queries'
plot for [k in "busy-grid busy-grid-tight lazy-grid lazy-grid:lazy-prob=0.5"] '$tmp/cells-'.k.'.dat' using 1:3 with linespoints lw 2 title k
set ylabel 'PVS / exact'
set xlabel 'cell size (pixels)'
plot for [k in "busy-grid busy-grid-tight lazy-grid lazy-grid:lazy-prob=0.5"] '$tmp/cells-'.k.'.dat' using 1:4 with linespoints lw 2 title k
unset multiplot
GP
done

# Section 6's extensions, each against the plain lazy grid in one run.
ext="lazy-grid,lazy-grid:lazy-prob=0.25,lazy-grid:lazy-prob=0.5,lazy-grid:lazy-prob=1"
ext+=",lazy-grid:lazy-border-whole=0.25,lazy-grid:lazy-border-whole=0.5"
ext+=",lazy-grid:lazy-large-box=0.1,lazy-grid:lazy-large-box=0.3,busy-grid,busy-grid-tight"
for scene in forest-walk-3d city-walk-3d; do
    echo "== $scene: section 6 extensions at 640"
    bench "$out/$scene-extensions.txt" "scenes/$scene.json" --algo "$ext" --runs "$runs" \
        --oracle-res 640
done
echo "results in $out"
