#!/bin/sh
# Rewrites the knob table of docs/LIMITS.md (between its "knobs: begin" and
# "knobs: end" markers) with `gridcull knobs --markdown`, the family registry's
# own listing. tests/app/limits_doc_test.cpp fails until this has been run after
# a knob changed.
#
# usage: scripts/update-knob-table.sh [BUILD_DIR]     (default: build)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
cmake --build "$build" --target gridcull -j2 >/dev/null
doc="$root/docs/LIMITS.md"
table=$(mktemp)
trap 'rm -f "$table" "$doc.tmp"' EXIT
"$build/app/gridcull" knobs --markdown >"$table"
awk -v table="$table" '
    /<!-- knobs: begin/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
    /<!-- knobs: end/ { skip = 0 }
    !skip { print }' "$doc" >"$doc.tmp"
mv "$doc.tmp" "$doc"
echo "rewrote the knob table of docs/LIMITS.md"
