#!/usr/bin/env bash
# One command to see gridcull: installs what is missing, builds, and opens the
# window on the built-in default scene. With no display (a headless box) it renders
# the window under xvfb-run to a PNG and writes a short cull report instead, and
# prints where both are. Extra arguments go to gridcull (e.g. `view scenes/walls-2d.json`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exe=build/app/gridcull

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec "$exe" "$@"
fi

out=out/default
mkdir -p "$out"
scene=scenes/default.json
frame=40
echo "no display: rendering frame $frame of $scene headless"
LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x720x24" \
  "$exe" shot "$scene" --frame "$frame" --algo rgvc --out "$out/window.png"
"$exe" bench "$scene" --algo all,vfc,rgvc,exact --frames 20 --runs 1 > "$out/report.txt"
echo "screenshot: $PWD/$out/window.png"
echo "cull report: $PWD/$out/report.txt"
cat "$out/report.txt"
