#!/usr/bin/env bash
# The lazy occlusion grid with the paper's kind of pixel-level query: objects
# drawn with OpenGL, each query a glReadPixels of the depth buffer (Hey et al.
# section 7; app/gl_image_target.h). Times lazy against busy, both on OpenGL
# and next to the software target, on the forest and city walkthroughs at 640,
# and writes the tables to docs/results/lazy-grid/*-gl.txt (or $1). Renders with
# Mesa's software OpenGL under xvfb-run when there is no display. About 8 minutes.
#
# usage: scripts/lazy-grid-gl-bench.sh [OUT_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/results/lazy-grid}
runs=${2:-3}
scripts/install-deps.sh
scripts/build.sh >/dev/null
mkdir -p "$out"
export LIBGL_ALWAYS_SOFTWARE=1
run() {
    if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1280x720x24" "$@"; fi
}
algos=busy-grid-gl,busy-grid-tight-gl,lazy-grid-gl,lazy-grid-z-gl,busy-grid,lazy-grid
for scene in forest-walk-3d city-walk-3d; do
    echo "== $scene: $algos at 640, $runs runs"
    run build/app/gridcull bench "scenes/$scene.json" --algo "$algos" --runs "$runs" \
        --oracle-res 640 | tee "$out/$scene-gl.txt"
done
