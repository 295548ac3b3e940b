// Writes a Scene as a scene file (docs/scene-format.md) that the loader reads
// back as the same scene: every object listed (generated ones too), each
// distinct mesh as a Wavefront OBJ beside the file. Used to keep a scene made
// in code (a sweep's failing random scene) as a file `gridcull cull` replays.
//
// What survives the trip: ids, shapes, sizes, linear and keyframed motion,
// declared maximum speeds, the camera, grid, time and seed exactly (numbers are
// written as the shortest text that reads back to the same double). Two things
// are the loader's, not the writer's: a random walk is rebuilt from the seed,
// the object's id and max_speed with the loader's segment length, so a walk
// built in code with other segments comes back as the loader's walk; and the
// OBJ reader (Debian's tinyobjloader, its float build) reads mesh vertices as
// floats, so a mesh comes back exactly when its coordinates are floats, and
// rounded to the nearest float otherwise. A scene that was itself loaded (or
// written and loaded once) comes back identical.
#pragma once
#include <string>
#include <vector>

#include "culling/scene/scene.h"

namespace gridcull {

// The scene's JSON text. `mesh_files[k]` names the k-th distinct mesh (in the
// order meshesOf gives them), relative to the scene file.
std::string sceneJsonText(const Scene& scene, const std::vector<std::string>& mesh_files);

// The distinct meshes of the scene's objects, in order of first use.
std::vector<const TriangleMesh*> meshesOf(const Scene& scene);

// OBJ text of one mesh (its vertices as stored, faces 1-based).
std::string objText(const TriangleMesh& mesh);

// Writes `path` and, for each distinct mesh, STEM-meshK.obj beside it. False
// and `error` (naming the file) when a file cannot be written.
bool writeSceneFile(const Scene& scene, const std::string& path, std::string& error);

}  // namespace gridcull
