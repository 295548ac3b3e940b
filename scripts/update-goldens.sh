#!/bin/sh
# Regenerates the screenshot goldens (screenshots/*.png) from the cases in
# tests/screenshots/cases.txt, with the same renderer the test uses: Mesa's
# software OpenGL (LIBGL_ALWAYS_SOFTWARE=1), under xvfb-run when there is no
# X display. Look at every changed PNG before committing it.
#
# usage: scripts/update-goldens.sh [BUILD_DIR]     (default: build-goldens)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build-goldens"}

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target gridcull gridcull-toy -j2

run() {
    if [ -n "${DISPLAY:-}" ]; then
        "$@"
    else
        # -noreset: see scripts/test.sh (a reset drops clients connecting meanwhile).
        xvfb-run -a -s "-screen 0 1280x720x24 -noreset" "$@"
    fi
}

mkdir -p "$root/screenshots"
# Paths in a case's flags (a lesson file) are relative to the source tree.
cd "$root"
grep -v '^[[:space:]]*#' "$root/tests/screenshots/cases.txt" | grep -v '^[[:space:]]*$' |
while read -r name scene frame view algo width height extra; do
    echo "screenshots/$name.png: $scene frame $frame, view $view, algo $algo, ${width}x$height $extra"
    exe="$build/app/gridcull"
    case "$extra" in
    via:gridcull-toy*) exe="$build/tests/gridcull-toy"; extra=${extra#via:gridcull-toy} ;;
    esac
    # $extra unquoted: it is zero or more further shot flags.
    # shellcheck disable=SC2086
    LIBGL_ALWAYS_SOFTWARE=1 run "$exe" shot "$root/$scene" --frame "$frame" --view "$view" \
        --algo "$algo" --width "$width" --height "$height" $extra \
        --out "$root/screenshots/$name.png"
done
echo "done: look at the changed images (git status screenshots/) before committing them"
