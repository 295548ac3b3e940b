// Shared between the files of the scene loader (scene_loader*.cpp); not a public
// interface. The loader reads in passes: header sections, listed objects,
// generator parameters; then, only when all of that is valid and within the
// limits, it numbers ids, generates objects and builds random walks.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "culling/generators/scene_generators.h"
#include "culling/io/scene_json.h"
#include "culling/scene/scene.h"

namespace gridcull {

struct MeshKey {
    std::string path;
    double scale;
    glm::dvec3 rotation_deg;
    bool operator<(const MeshKey& o) const {
        return std::tie(path, scale, rotation_deg.x, rotation_deg.y, rotation_deg.z) <
               std::tie(o.path, o.scale, o.rotation_deg.x, o.rotation_deg.y, o.rotation_deg.z);
    }
};

struct SceneLoadContext {
    ErrorList& errors;
    std::string base_dir;  // meshes are resolved against it
    int dimensions = 3;
    Scene& scene;  // header fields are filled before objects are read
    // Objects that name the same file with the same transform share one mesh.
    std::map<MeshKey, std::shared_ptr<const TriangleMesh>> meshes;
};

// An object read from `objects`, before ids are numbered.
struct ListedObject {
    SceneObject object;
    bool has_id = false;
    std::string path;  // "objects[3]"
};

// Reads `objects` (an array). Each valid object is appended to `out`; every
// problem is reported. Duplicate ids are reported here too.
void readObjects(const Json& objects, SceneLoadContext& context, std::vector<ListedObject>& out);

// Reads one `motion` object at `path` into `motion`, deriving max_speed (for
// random motion, segment velocities are built later, once ids are known).
bool readMotion(const Json& value, const std::string& path, SceneLoadContext& context,
                Motion& motion);

// Reads a mesh object's "file", optional `scale_key` (a number > 0, default 1;
// nullptr for none) and "rotation_deg" from `r`, loading each distinct
// (file, scale, rotation) once per scene. Reports problems; nullptr on failure.
std::shared_ptr<const TriangleMesh> loadSceneMesh(JsonObjectReader& r, SceneLoadContext& context,
                                                  const char* scale_key);
// The same for values already read; `path` is where problems are reported.
std::shared_ptr<const TriangleMesh> loadSceneMeshFile(const std::string& file, double scale,
                                                      const glm::dvec3& rotation_deg,
                                                      const std::string& path,
                                                      SceneLoadContext& context);

// Reads and validates `generators` (an array) without generating anything.
void readGenerators(const Json& generators, SceneLoadContext& context,
                    std::vector<GeneratorPlan>& out);

}  // namespace gridcull
