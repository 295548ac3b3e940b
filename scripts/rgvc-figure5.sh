#!/usr/bin/env bash
# Reproduces Batagelo & Wu's Figure 5 (section 6) for the regular-grid culler
# `rgvc` with `gridcull bench`, and checks the issue's targets on the result:
#  - left:   median and 95th-percentile cull time per frame against the number of
#            hidden dynamic objects (generators[0].count of scenes/hidden-movers-2d
#            and -3d set to each of $counts), rgvc against vfc and all ("ZB");
#  - centre: cull time per frame of the walkthrough (scenes/walkthrough-3d) with
#            the scene's 50 x 30 x 50 grid and with 100 x 60 x 100
#            (rgvc:rgvc-grid-res=100), against all and vfc, in one bench run;
#  - right:  PVS size per frame of the same run against the exact visible set and
#            vfc.
# Writes each bench's table (.txt), its per-frame CSV, hidden-movers.csv (the
# left plot's points), the PNGs and ratios.md (the table of ratios printed at the
# end) to docs/results/rgvc-figure5/ (or OUT_DIR). Cull time only: bench draws
# nothing, so `all` costs next to nothing here, unlike the paper's z-buffer.
# Needs gnuplot (Debian's gnuplot-nox, installed when missing, as
# scripts/lazy-grid-figures.sh does: scripts/install-deps.sh does not list it).
# About 2 minutes on 2 shared cores with the default 5 runs, after the build.
#
# usage: scripts/rgvc-figure5.sh [BUILD_DIR] [OUT_DIR] [RUNS]
#   BUILD_DIR  build tree to build gridcull in and run it from (default: build;
#              configured RelWithDebInfo when it has no CMakeCache.txt)
#   OUT_DIR    where the results go (default: docs/results/rgvc-figure5)
#   RUNS       runs (default 5): each hidden-movers scene RUNS times, one bench
#              process a run, the scenes in turn; the walkthrough with --runs RUNS
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
out=${2:-"$root/docs/results/rgvc-figure5"}
runs=${3:-5}
counts="1000 2000 5000 10000"  # hidden dynamic objects; the first and last are the target's
case "$runs" in '' | *[!0-9]* | 0*) echo "RUNS must be a positive integer, not '$runs'" >&2; exit 2 ;; esac
mkdir -p "$build" "$out"
build=$(cd "$build" && pwd)
out=$(cd "$out" && pwd)
cd "$root"

scripts/install-deps.sh
if ! command -v gnuplot >/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends gnuplot-nox
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build" --target gridcull -j2 >/dev/null
exe=$build/app/gridcull
# What is measured: the build's source tree, its commit and uncommitted changes.
src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
if commit=$(git -C "$src" rev-parse --short HEAD 2>/dev/null); then
    changed=$(git -C "$src" status --porcelain --untracked-files=no | wc -l)
    source_state="commit $commit"
    [ "$changed" -eq 0 ] || source_state+=" with $changed files changed"
else
    source_state="$src, not a git checkout"
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
start=$(date +%s)
# Everything below is regenerated: no result of an earlier run stays behind.
rm -f "$out"/hidden-movers*.csv "$out"/hidden-movers-*.txt "$out"/walkthrough-3d.csv \
    "$out"/walkthrough-3d.txt "$out"/figure5-*.png "$out"/ratios.md

# The scene with the first "count" after "generators" (generators[0].count) set to
# $3. Fails when there is none, so a reshaped scene cannot go by unnoticed.
with_count() {  # scene out-file count
    awk -v n="$3" '
        /"generators"/ { in_generators = 1 }
        in_generators && !done && /"count": *[0-9]+/ {
            sub(/"count": *[0-9]+/, "\"count\": " n); done = 1 }
        { print }
        END { if (!done) { print "no generators[0].count in " FILENAME > "/dev/stderr"; exit 1 } }' \
        "$1" >"$2"
}

# One column of one algorithm's rows of a bench CSV, one value a line.
column() {  # csv algo column-name
    awk -F, -v algo="$2" -v name="$3" '
        NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) col = i; next }
        $1 == algo && col { print $col; found = 1 }
        END { if (!found) { print "no " name " of " algo " in " FILENAME > "/dev/stderr"; exit 1 } }' "$1"
}

# "median p95" of a column over frames, as bench computes them from the per-frame
# medians over runs (app/bench_table.cpp): the middle value (the mean of the two
# middle ones for an even count), and the value at index floor(0.95 n) of the sorted list.
stats() {  # csv algo column-name
    column "$@" | sort -g | awk '
        { v[NR] = $1 }
        END {
            n = NR; mid = int(n / 2) + 1
            median = (n % 2) ? v[mid] : (v[mid] + v[mid - 1]) / 2
            i = int(0.95 * n) + 1; if (i > n) i = n
            printf "%.6g %.6g\n", median, v[i] }'
}

# Sum of PVS sizes over sum of exact visible counts, as bench's pvs/exact.
pvs_over_exact() {  # csv algo
    awk -F, -v algo="$2" '
        NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "pvs") p = i; if ($i == "exact") e = i }; next }
        $1 == algo { pvs += $p; exact += $e }
        END { if (exact <= 0) { print "no exact counts for " algo " in " FILENAME > "/dev/stderr"; exit 1 }
              printf "%.4g\n", pvs / exact }' "$1"
}

mean() {  # csv algo column-name
    column "$@" | awk '{ s += $1 } END { printf "%.6g\n", s / NR }'
}

false_culls() {  # csv algo
    column "$1" "$2" false_culls | awk '{ s += $1 } END { print s + 0 }'
}

# "frame value" lines of one algorithm, for gnuplot.
series() {  # csv algo column-name
    awk -F, -v algo="$2" -v name="$3" '
        NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) col = i; next }
        $1 == algo && col { print $2, $col }' "$1"
}

# --- left: hidden dynamic objects ------------------------------------------------
# The target compares scenes, so different processes: each run is its own bench
# process (--runs 1), and the runs go round all scenes in turn, so that a busy
# spell of a shared machine falls on every count alike. Only the first round asks
# the oracle for the exact set. Then, per scene, each frame's median over the
# runs, as bench computes it within one process (merge_runs).
merge_runs() {  # out-csv run-csv...
    local out_csv=$1
    shift
    awk -F, -v OFS=, '
        FNR == 1 {
            if (NR == 1) {
                header = $0
                for (i = 1; i <= NF; ++i) {
                    if ($i == "cull_ms_median") cm = i
                    if ($i == "cull_ms_min") cn = i
                }
            } else if ($0 != header) {
                print "the runs of " FILENAME " differ in their columns" > "/dev/stderr"
                exit 1
            }
            next
        }
        {
            key = $1 SUBSEP $2
            v[key, ++n[key]] = $cm + 0
            if (FILENAME == ARGV[1]) { row[key] = $0; order[++rows] = key }
        }
        END {
            print header
            for (r = 1; r <= rows; ++r) {
                key = order[r]; m = n[key]
                for (i = 1; i <= m; ++i) a[i] = v[key, i]
                for (i = 2; i <= m; ++i) {  # insertion sort: m is the run count
                    x = a[i]
                    for (j = i - 1; j >= 1 && a[j] > x; --j) a[j + 1] = a[j]
                    a[j + 1] = x
                }
                mid = int(m / 2) + 1
                median = (m % 2) ? a[mid] : (a[mid] + a[mid - 1]) / 2
                nf = split(row[key], f, ",")
                f[cm] = sprintf("%.6g", median)
                f[cn] = sprintf("%.6g", a[1])
                line = f[1]
                for (i = 2; i <= nf; ++i) line = line OFS f[i]
                print line
            }
        }' "$@" >"$out_csv"
}

left_algos=all,vfc,rgvc
for dims in 2d 3d; do
    for n in $counts; do
        with_count "scenes/hidden-movers-$dims.json" "$tmp/hidden-movers-$dims-$n.json" "$n"
    done
done
for run in $(seq 1 "$runs"); do
    quality=""
    [ "$run" -eq 1 ] || quality=--no-quality
    for dims in 2d 3d; do
        for n in $counts; do
            name=hidden-movers-$dims-$n
            echo "== $name: $left_algos, run $run of $runs"
            # shellcheck disable=SC2086  # $quality is one flag or none
            "$exe" bench "$tmp/$name.json" --algo "$left_algos" --runs 1 $quality \
                --csv "$tmp/$name.run$run.csv" >"$tmp/$name.run$run.txt"
            [ "$run" -gt 1 ] || cat "$tmp/$name.run1.txt"
        done
    done
done
summary=$out/hidden-movers.csv
echo "dims,hidden_movers,objects,algo,median_ms,p95_ms,false_culls" >"$summary"
for dims in 2d 3d; do
    for n in $counts; do
        name=hidden-movers-$dims-$n
        merge_runs "$out/$name.csv" $(seq -f "$tmp/$name.run%g.csv" 1 "$runs")
        {
            echo "# bench's table of the first of $runs runs, each its own process; $name.csv"
            echo "# holds each frame's median over all of them (scripts/rgvc-figure5.sh)"
            cat "$tmp/$name.run1.txt"
        } >"$out/$name.txt"
        objects=$(sed -n 's/^scene: .*(.D, \([0-9]*\) objects).*/\1/p' "$out/$name.txt")
        for algo in ${left_algos//,/ }; do
            s=$(stats "$out/$name.csv" "$algo" cull_ms_median)
            f=$(false_culls "$out/$name.csv" "$algo")
            echo "${dims%d}D,$n,$objects,$algo,${s% *},${s#* },$f" >>"$summary"
        done
    done
done

left_panel() {  # dims title
    local algo
    for algo in ${left_algos//,/ }; do
        awk -F, -v d="${1%d}D" -v a="$algo" '$1 == d && $4 == a { print $2, $5, $6 }' "$summary" \
            >"$tmp/left-$1-$algo.dat"
    done
    cat <<GP
set title '$2'
plot '$tmp/left-$1-rgvc.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '#c00000' title 'rgvc median', \
     '$tmp/left-$1-rgvc.dat' using 1:3 with linespoints lw 2 pt 6 dt 2 lc rgb '#c00000' title 'rgvc p95', \
     '$tmp/left-$1-vfc.dat' using 1:2 with linespoints lw 2 pt 5 lc rgb '#0060c0' title 'vfc median', \
     '$tmp/left-$1-vfc.dat' using 1:3 with linespoints lw 2 pt 4 dt 2 lc rgb '#0060c0' title 'vfc p95', \
     '$tmp/left-$1-all.dat' using 1:2 with linespoints lw 2 pt 9 lc rgb '#208020' title 'all (ZB) median', \
     '$tmp/left-$1-all.dat' using 1:3 with linespoints lw 2 pt 8 dt 2 lc rgb '#208020' title 'all (ZB) p95'
GP
}
gnuplot <<GP
set terminal pngcairo size 1300,560 font ",10"
set output '$out/figure5-left.png'
set multiplot layout 1,2 title 'Figure 5 left: cull time per frame against hidden dynamic objects (each frame the median of $runs runs)'
set grid
set logscale y
set format y '%g'
set xlabel 'hidden dynamic objects'
set ylabel 'cull ms per frame (log scale)'
set xrange [0:$(echo "$counts" | awk '{ print $NF * 1.05 }')]
set xtics ($(echo "$counts" | awk '{ for (i = 1; i <= NF; ++i) printf "%s%d", (i > 1 ? ", " : ""), $i }'))
set key below vertical maxrows 2 samplen 4 height 1.5
$(left_panel 2d 'hidden-movers-2d (grid 100 x 100)')
$(left_panel 3d 'hidden-movers-3d (grid 50 x 30 x 50)')
unset multiplot
GP

# --- centre and right: the walkthrough, both grids in one run ---------------------
walk_algos=all,vfc,rgvc,rgvc:rgvc-grid-res=100
walk=$out/walkthrough-3d
echo "== walkthrough-3d: $walk_algos, $runs runs"
"$exe" bench scenes/walkthrough-3d.json --algo "$walk_algos" --runs "$runs" \
    --csv "$walk.csv" | tee "$walk.txt"
for algo in ${walk_algos//,/ }; do
    series "$walk.csv" "$algo" cull_ms_median >"$tmp/centre-$algo.dat"
    series "$walk.csv" "$algo" pvs >"$tmp/right-$algo.dat"
done
series "$walk.csv" rgvc exact >"$tmp/right-exact.dat"
gnuplot <<GP
set terminal pngcairo size 900,480 font ",10"
set output '$out/figure5-centre.png'
set title 'Figure 5 centre: walkthrough-3d, cull time per frame (median of $runs runs)'
set xlabel 'frame'
set xrange [0:$(($(series "$walk.csv" all pvs | wc -l) - 1))]
set ylabel 'cull ms (log scale)'
set logscale y
set format y '%g'
set grid
set key outside right
plot '$tmp/centre-rgvc.dat' using 1:2 with lines lw 2 lc rgb '#c00000' title 'rgvc 50x30x50', \
     '$tmp/centre-rgvc:rgvc-grid-res=100.dat' using 1:2 with lines lw 2 lc rgb '#e08000' title 'rgvc 100x60x100', \
     '$tmp/centre-vfc.dat' using 1:2 with lines lw 2 lc rgb '#0060c0' title 'vfc', \
     '$tmp/centre-all.dat' using 1:2 with lines lw 2 lc rgb '#208020' title 'all (ZB)'
set output '$out/figure5-right.png'
set title 'Figure 5 right: walkthrough-3d, objects in the PVS per frame'
set ylabel 'objects'
unset logscale y
set yrange [0:*]
plot '$tmp/right-vfc.dat' using 1:2 with lines lw 2 lc rgb '#0060c0' title 'vfc', \
     '$tmp/right-rgvc.dat' using 1:2 with lines lw 2 lc rgb '#c00000' title 'rgvc 50x30x50', \
     '$tmp/right-rgvc:rgvc-grid-res=100.dat' using 1:2 with lines lw 2 lc rgb '#e08000' title 'rgvc 100x60x100', \
     '$tmp/right-exact.dat' using 1:2 with lines lw 2 lc rgb '#000000' title 'exact'
GP

# --- the targets -------------------------------------------------------------------
first=${counts%% *}
last=${counts##* }
rows=""
row() {  # what value limit(<= this) detail
    local verdict
    verdict=$(awk -v v="$2" -v l="$3" 'BEGIN { print (v <= l) ? "met" : "**missed**" }')
    rows+="| $1 | $2 | <= $3 | $verdict | $4 |"$'\n'
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3g", (b > 0) ? a / b : 1e9 }'; }
for dims in 2d 3d; do
    D=${dims%d}D
    m1=$(awk -F, -v d="$D" -v n="$first" '$1 == d && $2 == n && $4 == "rgvc" { print $5 }' "$summary")
    m2=$(awk -F, -v d="$D" -v n="$last" '$1 == d && $2 == n && $4 == "rgvc" { print $5 }' "$summary")
    # The same from each frame's fastest run: less of a shared machine's load.
    l1=$(stats "$out/hidden-movers-$dims-$first.csv" rgvc cull_ms_min)
    l2=$(stats "$out/hidden-movers-$dims-$last.csv" rgvc cull_ms_min)
    row "$D hidden movers: rgvc median cull time, $last / $first movers" "$(ratio "$m2" "$m1")" 1.25 \
        "$m2 / $m1 ms; from each frame's fastest run: $(ratio "${l2% *}" "${l1% *}") (${l2% *} / ${l1% *} ms)"
    # The worst p95 / median over the counts.
    read -r worst at p95 median < <(awk -F, -v d="$D" '$1 == d && $4 == "rgvc" {
            r = ($5 > 0) ? $6 / $5 : 1e9; if (r > w) { w = r; n = $2; p = $6; m = $5 } }
        END { printf "%.3g %d %s %s\n", w, n, p, m }' "$summary")
    row "$D hidden movers: rgvc p95 / median cull time, worst of $(echo "$counts" | tr ' ' ',')" \
        "$worst" 3 "at $at movers: $p95 / $median ms"
done
s=$(stats "$walk.csv" rgvc cull_ms_median)
m50=${s% *}
s=$(stats "$walk.csv" rgvc:rgvc-grid-res=100 cull_ms_median)
m100=${s% *}
row "walkthrough: PVS / exact, rgvc 100x60x100" "$(pvs_over_exact "$walk.csv" rgvc:rgvc-grid-res=100)" \
    2.0 "50x30x50: $(pvs_over_exact "$walk.csv" rgvc), vfc: $(pvs_over_exact "$walk.csv" vfc)"
# The voxels visited explain most of it; a counter that is gone leaves them out.
voxels=""
if v50=$(mean "$walk.csv" rgvc voxels_visited 2>/dev/null) &&
    v100=$(mean "$walk.csv" rgvc:rgvc-grid-res=100 voxels_visited 2>/dev/null); then
    voxels="; voxels visited $(ratio "$v100" "$v50")x ($v100 / $v50 a frame)"
fi
row "walkthrough: rgvc median cull time, 100x60x100 / 50x30x50" "$(ratio "$m100" "$m50")" 1.5 \
    "$m100 / $m50 ms (one bench run)$voxels"
fc=0
for f in "$out"/hidden-movers-*.csv "$walk.csv"; do
    for algo in vfc rgvc rgvc:rgvc-grid-res=100; do
        if grep -q "^$algo," "$f"; then fc=$((fc + $(false_culls "$f" "$algo"))); fi
    done
done
{
    echo "| target | measured | limit | | detail |"
    echo "| --- | ---: | ---: | --- | --- |"
    printf '%s' "$rows"
    echo
    echo "False culls (vfc and rgvc, every bench above, against the exact oracle): $fc."
    echo "Frame time with drawing (the paper's frames per second): not measured; gridcull bench"
    echo "times culling only and has no --draw yet."
    echo "$runs runs; $(date -u +%Y-%m-%d), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg);"
    echo "source: $source_state."
} >"$out/ratios.md"
echo
echo "== targets (also in $out/ratios.md)"
cat "$out/ratios.md"
echo "results in $out ($(($(date +%s) - start)) s)"
