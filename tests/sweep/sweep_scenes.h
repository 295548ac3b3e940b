// The sweep's random scenes: one seed, one scene, from the random generators
// the differential tests already use (each header says what it covers), in
// turn by seed: 2D and 3D regular-grid scenes (tests/culling/rgvc), the lazy
// grid's occluders and crowds (tests/culling/lazy_grid), rooms with chairs
// and movers (tests/culling/hzb_tbv), complex moving meshes
// (tests/culling/bsp_oq), and the edges in 2D and 3D (sweep_extremes.h).
//
// A generated scene is made replayable (replayable()) before it is checked:
// its mesh vertices rounded to floats (as the loader's OBJ reader reads them),
// then written and loaded again, so that the scene the
// sweep checks is the one its file loads as (random walks rebuilt the loader's
// way, everything else unchanged).
#pragma once
#include <cstdint>
#include <string>

#include "culling/scene/scene.h"

namespace gridcull::sweep {

constexpr int kSceneKinds = 7;

// The kind of scene `seed` makes, e.g. "rgvc-2d", "extremes-3d".
const char* sceneKind(uint64_t seed);

// The scene of `seed` as generated (not yet replayable).
Scene generatedScene(uint64_t seed);

// Rounds every mesh vertex to the nearest float (each mesh copied once, so
// shared meshes stay shared).
void snapMeshes(Scene& scene);

// The scene as written to `work_file` and loaded back; false and `error` (the
// writer's or loader's message) when that fails, with `*rejected` set when it
// was the loader that refused the scene (a generator's scene the file format
// does not allow, e.g. a polygon too small to enclose an area at its
// coordinates' precision: it cannot be replayed, so it is not checked).
bool replayable(const Scene& scene, const std::string& work_file, Scene& out, std::string& error,
                bool* rejected = nullptr);

}  // namespace gridcull::sweep
