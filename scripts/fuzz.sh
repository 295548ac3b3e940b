#!/usr/bin/env bash
# Fuzzes the scene loader or the OBJ reader for SECONDS seconds (docs/FUZZING.md):
#   scripts/fuzz.sh SECONDS [more libFuzzer flags]
# FUZZ_TARGET picks the target: scene_loader_fuzzer (the default), obj_mesh_fuzzer,
# or all (each in turn, SECONDS each). Builds it with clang (libFuzzer + ASan +
# UBSan) into build-fuzz/ (or $GRIDCULL_BUILD_DIR) and runs it from the corpus
# committed in tests/fuzz/corpus/ plus the seeds: scenes/*.json,
# tests/scenes/bad/*.json and tests/scenes/fuzz-regressions/*.json for the scene
# loader; scenes/meshes/*.obj and tests/scenes/meshes/*.obj for the OBJ reader.
# What the fuzzer adds goes to build-fuzz/corpus/TARGET/ (kept between runs, so
# a long-lived corpus starts further on); FUZZ_FRESH=1 empties it first, as
# scripts/test.sh does, so its runs start from the committed corpus alone.
# A crash, hang (> 25 s on one input), leak or out-of-memory (> 2 GiB) stops it
# with status != 0 and leaves the input in build-fuzz/artifacts/ (the message
# names the file); copy it into tests/scenes/fuzz-regressions/ once fixed.
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
case "$target" in
  all) targets=(scene_loader_fuzzer obj_mesh_fuzzer) ;;
  scene_loader_fuzzer | obj_mesh_fuzzer) targets=("$target") ;;
  *)
    echo "unknown FUZZ_TARGET '$target' (scene_loader_fuzzer, obj_mesh_fuzzer or all)" >&2
    exit 2
    ;;
esac
if ! command -v clang++ >/dev/null; then
  echo "scripts/fuzz.sh needs clang++ (Debian: apt-get install clang libclang-rt-14-dev)" >&2
  exit 2
fi

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DGRIDCULL_CORE_ONLY=ON -DGRIDCULL_TESTS=OFF -DGRIDCULL_FUZZ=ON >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target "${targets[@]}"

artifacts="$build_dir/artifacts"
mkdir -p "$artifacts"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"

for t in "${targets[@]}"; do
  # The working corpus comes first: libFuzzer writes what it finds into the
  # first folder only, so the committed corpus is read and never changed.
  corpus="$build_dir/corpus/$t"
  [ "${FUZZ_FRESH:-0}" = 1 ] && rm -rf "$corpus"
  mkdir -p "$corpus"
  case "$t" in
    scene_loader_fuzzer)
      committed=tests/fuzz/corpus/scene_loader
      cp scenes/*.json tests/scenes/bad/*.json tests/scenes/fuzz-regressions/*.json "$corpus"/
      extra=(-dict=tests/fuzz/scene.dict -max_len=16384)
      ;;
    obj_mesh_fuzzer)
      committed=tests/fuzz/corpus/obj_mesh
      cp scenes/meshes/*.obj tests/scenes/meshes/*.obj "$corpus"/
      extra=(-max_len=131072)
      ;;
  esac
  echo "== fuzzing $t for $seconds s (corpus $committed + $corpus) =="
  status=0
  "$build_dir/tests/fuzz/$t" "$corpus" "$committed" "${extra[@]}" \
    -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=25 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$t-" "$@" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "scripts/fuzz.sh: $t stopped with status $status: the input is in $artifacts/" \
         "(the line 'Test unit written to ...' above names it); replay it with" \
         "$build_dir/tests/fuzz/$t FILE" >&2
    exit "$status"
  fi
done
