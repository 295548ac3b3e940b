#!/usr/bin/env bash
# Fuzzes the scene loader for SECONDS seconds (docs/FUZZING.md):
#   scripts/fuzz.sh SECONDS [more libFuzzer flags]
# Builds tests/fuzz/scene_loader_fuzzer with clang (libFuzzer + ASan + UBSan)
# into build-fuzz/ (or $GRIDCULL_BUILD_DIR), seeds a corpus from scenes/*.json,
# tests/scenes/bad/*.json and tests/scenes/fuzz-regressions/*.json, and runs.
# FUZZ_TARGET=obj_mesh_fuzzer fuzzes the OBJ mesh reader instead, seeded from
# scenes/meshes/*.obj and tests/scenes/meshes/*.obj.
# A crash, hang (> 25 s on one input), leak or out-of-memory (> 2 GiB) stops it
# with status != 0 and leaves the input in build-fuzz/artifacts/; copy it into
# tests/scenes/fuzz-regressions/ once fixed. Not part of scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh SECONDS [libFuzzer flags...]" >&2
  exit 2
fi
seconds="$1"
shift
build_dir="${GRIDCULL_BUILD_DIR:-build-fuzz}"
target="${FUZZ_TARGET:-scene_loader_fuzzer}"
if ! command -v clang++ >/dev/null; then
  echo "scripts/fuzz.sh needs clang++ (Debian: apt-get install clang libclang-rt-14-dev)" >&2
  exit 2
fi

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DGRIDCULL_CORE_ONLY=ON -DGRIDCULL_TESTS=OFF -DGRIDCULL_FUZZ=ON >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target "$target"

# The corpus grows as the fuzzer finds new paths; the seeds are copied in each
# run, so a fresh checkout and a long-lived corpus both start from them.
artifacts="$build_dir/artifacts"
case "$target" in
  scene_loader_fuzzer)
    corpus="$build_dir/corpus"
    mkdir -p "$corpus"
    cp scenes/*.json tests/scenes/bad/*.json tests/scenes/fuzz-regressions/*.json "$corpus"/
    extra=(-dict=tests/fuzz/scene.dict -max_len=16384)
    ;;
  obj_mesh_fuzzer)
    corpus="$build_dir/corpus-obj"
    mkdir -p "$corpus"
    cp scenes/meshes/*.obj tests/scenes/meshes/*.obj "$corpus"/
    extra=(-max_len=131072)
    ;;
  *)
    echo "unknown FUZZ_TARGET '$target' (scene_loader_fuzzer or obj_mesh_fuzzer)" >&2
    exit 2
    ;;
esac
mkdir -p "$artifacts"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
"$build_dir/tests/fuzz/$target" "$corpus" "${extra[@]}" \
  -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=25 \
  -print_final_stats=1 -artifact_prefix="$artifacts/" "$@"
