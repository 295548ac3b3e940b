#!/usr/bin/env bash
# Reproduces Kovalčík & Sochor's Table 1 ("Fast rendering of complex dynamic
# scenes", section 4) for the `bsp` family with `gridcull bench`: time per
# frame, object parts rendered and occlusion queries per frame for Full
# (bsp-oq), Simple OC (bsp-oq-simple) and VFC only (bsp-vfc), on the moving
# bunnies (scenes/bunnies-3d.json, 300 frames) and on the plant standing in
# for the power plant (scenes/plant-3d.json, 400 frames), with two query
# backends:
#  - software: the shared rasterizer draws the parts and answers the queries
#    (exact at the oracle's pixel centres); the exact oracle runs in the first
#    run, so PVS quality and false culls are in the table;
#  - gl: the same cullers as NAME-gl on OpenGL (Mesa llvmpipe under xvfb-run
#    here): parts drawn depth-only into a framebuffer, queries as
#    GL_ANY_SAMPLES_PASSED, glFinish at the frame's end, so the time per frame
#    includes the drawing, as the paper's does. No oracle (--no-quality).
# Both draw at --oracle-res RES pixels on the long side (the family's
# --bsp-res follows it), default 640 (the paper's screen is not given).
# Prints and writes ratios.md: the targets (Full's queries at most 0.3x Simple
# OC's; Full's time at most 0.2x VFC's on the bunnies) as ratios of means in
# one bench run, and table1.md (the paper's layout, one table a backend).
# Writes to OUT_DIR: each bench's table (.txt) and per-frame CSV, summary.csv,
# the PNGs (time, parts and queries per frame: the paper's Figures 6, 8, 9).
# Needs python3, gnuplot (Debian's gnuplot-nox, installed when missing) and
# xvfb-run (xvfb) with Mesa for the gl backend.
#
# usage: scripts/bsp-table1.sh BUILD_DIR OUT_DIR [RUNS [RES]]
#   BUILD_DIR  build tree to build gridcull in and run it from (configured
#              RelWithDebInfo when it has no CMakeCache.txt)
#   OUT_DIR    where the results go (e.g. docs/results/bsp-oq)
#   RUNS       runs of each software bench (default 3; gl benches run once
#              more than half as many, at least 1)
#   RES        image pixels on the long side (default 640)
# FRAMES=N in the environment runs only the first N frames of each scene (a
# quick check of the script; the published figures run whole paths).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -lt 2 ]; then
    echo "usage: scripts/bsp-table1.sh BUILD_DIR OUT_DIR [RUNS [RES]]" >&2
    exit 2
fi
build=$1
out=$2
runs=${3:-3}
res=${4:-640}
for v in "$runs" "$res"; do
    case "$v" in '' | *[!0-9]* | 0*) echo "RUNS and RES must be positive integers, not '$v'" >&2; exit 2 ;; esac
done
gl_runs=$(( (runs + 1) / 2 ))
frames=()
[ -z "${FRAMES:-}" ] || frames=(--frames "$FRAMES")
mkdir -p "$build" "$out"
build=$(cd "$build" && pwd)
out=$(cd "$out" && pwd)
cd "$root"

if ! command -v gnuplot >/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends gnuplot-nox
fi
command -v python3 >/dev/null || { echo "python3 is needed" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "xvfb-run is needed (Debian's xvfb)" >&2; exit 1; }
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build" --target gridcull -j2 >/dev/null
exe=$build/app/gridcull
start=$(date +%s)
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
rm -f "$out"/*.csv "$out"/*.txt "$out"/*.png "$out"/ratios.md "$out"/table1.md

# --- benches -----------------------------------------------------------------------
# The software bench also runs Full at the ends of --bsp-history (0: a query
# every frame for every visible node; 32: up to 32 frames skipped), the knob
# that trades queries for parts drawn late.
trade=bsp-oq:bsp-history=0,bsp-oq:bsp-history=32
for scene in bunnies plant; do
    file=scenes/$scene-3d.json
    echo "== $scene, software"
    "$exe" bench "$file" --algo bsp-oq,bsp-oq-simple,bsp-vfc,$trade --oracle-res "$res" \
        --runs "$runs" "${frames[@]}" --csv "$out/$scene-software.csv" >"$out/$scene-software.txt"
    echo "== $scene, gl"
    LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x720x24" \
        "$exe" bench "$file" --algo bsp-oq-gl,bsp-oq-simple-gl,bsp-vfc-gl --oracle-res "$res" \
        --runs "$gl_runs" "${frames[@]}" --no-quality --csv "$out/$scene-gl.csv" >"$out/$scene-gl.txt"
done

# --- summary, tables, ratios ---------------------------------------------------------
python3 - "$out" "$runs" "$gl_runs" "$res" <<'PY'
import csv, sys
out, runs, gl_runs, res = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
modes = [("bsp-oq", "Full"), ("bsp-oq-simple", "Simple OC"), ("bsp-vfc", "VFC only")]
def stats(v):
    v = sorted(v); n = len(v); mid = n // 2
    median = v[mid] if n % 2 else (v[mid - 1] + v[mid]) / 2
    return sum(v) / n, median, v[min(n - 1, int(0.95 * n))]
rows, summary = {}, []
for scene in ("bunnies", "plant"):
    for backend in ("software", "gl"):
        per = {}
        for r in csv.DictReader(open(f"{out}/{scene}-{backend}.csv")):
            per.setdefault(r["algo"].replace("-gl", ""), []).append(r)
        for algo, name in modes:
            rs = per[algo]
            mean_ms, med_ms, p95_ms = stats([float(r["cull_ms_median"]) for r in rs])
            m = lambda k: sum(float(r.get(k) or 0) for r in rs) / len(rs)
            q = lambda k: "-" if backend == "gl" else "%.3g" % m(k)
            fc = "-" if backend == "gl" else str(sum(int(float(r["false_culls"] or 0)) for r in rs))
            row = dict(scene=scene, backend=backend, algo=algo, mode=name, frames=len(rs),
                       mean_ms=mean_ms, median_ms=med_ms, p95_ms=p95_ms, parts=m("parts_drawn"),
                       queries=m("occlusion_queries"), hidden=m("queries_hidden"),
                       batches=m("query_batches"),
                       skips=m("coherence_skips"), triangles=m("triangles_drawn"),
                       pvs=m("pvs"), exact=q("exact"), false_culls=fc)
            rows[(scene, backend, algo)] = row
            summary.append(row)
keys = list(summary[0].keys())
with open(f"{out}/summary.csv", "w") as f:
    f.write(",".join(keys) + "\n")
    for r in summary:
        f.write(",".join(("%.6g" % r[k]) if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")

with open(f"{out}/table1.md", "w") as f:
    for backend, what in (("software", f"software backend ({runs} runs, oracle in the first)"),
                          ("gl", f"OpenGL backend on llvmpipe ({gl_runs} runs, no oracle)")):
        f.write(f"Table 1, {what}, {res} pixels on the long side; times are "
                "mean; median; p95 over the frames of each frame's median over the runs:\n\n")
        f.write("| scene | ms a frame, Full | Simple OC | VFC only | parts rendered, Full | "
                "Simple OC | VFC only | queries, Full | Simple OC | VFC only |\n")
        f.write("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n")
        for scene in ("bunnies", "plant"):
            r = [rows[(scene, backend, a)] for a, _ in modes]
            t = " | ".join("%.1f; %.1f; %.1f" % (x["mean_ms"], x["median_ms"], x["p95_ms"]) for x in r)
            p = " | ".join("%.0f" % x["parts"] for x in r)
            qq = " | ".join("%.0f" % x["queries"] for x in r)
            f.write(f"| {scene} | {t} | {p} | {qq} |\n")
        f.write("\n")
        f.write("| scene | mode | PVS | exact | false culls | triangles drawn | queries answered hidden | batches | coherence skips |\n")
        f.write("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n")
        for scene in ("bunnies", "plant"):
            for a, name in modes:
                x = rows[(scene, backend, a)]
                f.write(f"| {scene} | {name} | {x['pvs']:.1f} | {x['exact']} | {x['false_culls']} | "
                        f"{x['triangles']:.0f} | {x['hidden']:.0f} | {x['batches']:.0f} | {x['skips']:.0f} |\n")
        f.write("\n")

lines = ["| target | scene | backend | measured (ratio of means; of medians) | met |", "| --- | --- | --- | --- | --- |"]
for scene in ("bunnies", "plant"):
    for backend in ("software", "gl"):
        full, simple, vfc = (rows[(scene, backend, a)] for a, _ in modes)
        rq = full["queries"] / max(1e-9, simple["queries"])
        lines.append(f"| Full queries <= 0.3 x Simple OC | {scene} | {backend} | {rq:.3f} | "
                     f"{'yes' if rq <= 0.3 else 'no'} |")
        rt = full["mean_ms"] / vfc["mean_ms"]
        rm = full["median_ms"] / vfc["median_ms"]
        target = "Full time <= 0.2 x VFC" if scene == "bunnies" else "(Full time / VFC, no target)"
        met = ("yes" if rt <= 0.2 else "no") if scene == "bunnies" else "-"
        lines.append(f"| {target} | {scene} | {backend} | {rt:.3f}; {rm:.3f} | {met} |")
        rs = full["mean_ms"] / simple["mean_ms"]
        lines.append(f"| (Full time / Simple OC, no target) | {scene} | {backend} | {rs:.3f}; "
                     f"{full['median_ms'] / simple['median_ms']:.3f} | - |")
        lines.append(f"| (Full p95 / median, stalls) | {scene} | {backend} | "
                     f"{full['p95_ms'] / full['median_ms']:.2f} | - |")
lines += ["", "Full's history knob (software backend, same run):", "",
          "| scene | --bsp-history | queries | answered hidden | parts | time per frame, ms (mean; median; p95) | PVS | false culls |",
          "| --- | --- | --- | --- | --- | --- | --- | --- |"]
for scene in ("bunnies", "plant"):
    per = {}
    for r in csv.DictReader(open(f"{out}/{scene}-software.csv")):
        per.setdefault(r["algo"], []).append(r)
    for algo, h in (("bsp-oq:bsp-history=0", 0), ("bsp-oq", 8), ("bsp-oq:bsp-history=32", 32)):
        rs = per[algo]
        mean_ms, med_ms, p95_ms = stats([float(r["cull_ms_median"]) for r in rs])
        m = lambda k: sum(float(r.get(k) or 0) for r in rs) / len(rs)
        fc = sum(int(float(r["false_culls"] or 0)) for r in rs)
        lines.append(f"| {scene} | {h} | {m('occlusion_queries'):.0f} | {m('queries_hidden'):.0f} | "
                     f"{m('parts_drawn'):.0f} | "
                     f"{mean_ms:.1f}; {med_ms:.1f}; {p95_ms:.1f} | {m('pvs'):.1f} | {fc} |")
open(f"{out}/ratios.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY

# --- plots: per frame, software and gl, each scene --------------------------------
for scene in bunnies plant; do
    for backend in software gl; do
        csvf=$out/$scene-$backend.csv
        for what in time parts queries; do
            case $what in
                time) col=cull_ms_median; label="time per frame (ms)"; fig="Figure 6" ;;
                parts) col=parts_drawn; label="object parts rendered"; fig="Figure 8" ;;
                queries) col=occlusion_queries; label="occlusion queries"; fig="Figure 9" ;;
            esac
            python3 - "$csvf" "$col" >"$out/.plot.dat" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
algos = []
for r in rows:
    a = r["algo"].replace("-gl", "")
    if a not in algos: algos.append(a)
by = {a: {} for a in algos}
for r in rows: by[r["algo"].replace("-gl", "")][int(r["frame"])] = float(r[sys.argv[2]] or 0)
for f in sorted(by[algos[0]]):
    print(f, *(by[a].get(f, 0) for a in algos))
PY
            gnuplot <<GP
set terminal pngcairo size 900,420 font "DejaVu Sans,10"
set output "$out/$scene-$backend-$what.png"
set title "$scene, $backend backend: $label ($fig of the paper)"
set xlabel "frame"
set ylabel "$label"
set key top left
set grid
plot "$out/.plot.dat" using 1:2 with lines lw 1.5 title "Full (bsp-oq)", \
     "" using 1:3 with lines lw 1.5 title "Simple OC (bsp-oq-simple)", \
     "" using 1:4 with lines lw 1.5 title "VFC only (bsp-vfc)"
GP
        done
    done
done
rm -f "$out/.plot.dat"
end=$(date +%s)
echo "took $((end - start)) s; load average before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)" | tee "$out/run.txt"
