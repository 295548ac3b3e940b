#!/bin/sh
# Rewrites the generated tables of the docs: the knob table of docs/LIMITS.md
# (between its "knobs: begin" and "knobs: end" markers) with `gridcull knobs
# --markdown`, the family registry's own listing, and the counter table of
# docs/ARCHITECTURE.md with `gridcull counters --markdown`.
# tests/app/limits_doc_test.cpp fails until this has been run after a knob or a
# counter changed.
#
# usage: scripts/update-doc-tables.sh [BUILD_DIR]     (default: build)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
cmake --build "$build" --target gridcull -j2 >/dev/null
table=$(mktemp)
trap 'rm -f "$table"' EXIT
rewrite() {  # name doc
    "$build/app/gridcull" "$1" --markdown >"$table"
    awk -v table="$table" -v name="$1" '
        $0 ~ "<!-- " name ": begin" { print; while ((getline line < table) > 0) print line; skip = 1; next }
        $0 ~ "<!-- " name ": end" { skip = 0 }
        !skip { print }' "$2" >"$2.tmp"
    mv "$2.tmp" "$2"
    echo "rewrote the $1 table of ${2#"$root"/}"
}
rewrite knobs "$root/docs/LIMITS.md"
rewrite counters "$root/docs/ARCHITECTURE.md"
