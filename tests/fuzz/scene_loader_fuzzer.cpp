// libFuzzer target over the scene loader (docs/FUZZING.md): any byte string is
// handed to loadSceneText, and the result must satisfy the properties of
// scene_fuzz_checks.h (a scene xor clean errors, a scene as the loader
// promises, and, for small scenes, every culler free of false culls against
// the oracle); beyond that libFuzzer, ASan, LeakSanitizer and UBSan report any
// crash, hang, leak, out-of-memory or undefined behaviour.
// Mesh files are resolved against scenes/ in the source tree, so that the seed
// corpus's "meshes/bunny.obj" loads.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "culling/io/scene_loader.h"
#include "tests/fuzz/scene_fuzz_checks.h"

namespace {

const char* const kDisplayName = "fuzz.json";

void check(const std::string& problem) {
    if (problem.empty()) return;
    std::fprintf(stderr, "scene_loader_fuzzer: property violated: %s\n", problem.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace gridcull;
    const std::string text(reinterpret_cast<const char*>(data), size);
    const SceneLoadResult result = loadSceneText(text, kDisplayName, GRIDCULL_SOURCE_DIR "/scenes");
    check(fuzz::checkLoadResult(result, kDisplayName));
    if (result.scene && fuzz::smallEnoughToCull(*result.scene))
        check(fuzz::checkCulling(*result.scene));
    return 0;
}
