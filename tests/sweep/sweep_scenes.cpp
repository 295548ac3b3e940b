#include "tests/sweep/sweep_scenes.h"

#include <map>
#include <memory>

#include "culling/io/scene_loader.h"
#include "culling/io/scene_writer.h"
#include "tests/culling/bsp_oq/bsp_random_scenes.h"
#include "tests/culling/hzb_tbv/hzb_random_rooms.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"
#include "tests/sweep/sweep_extremes.h"

namespace gridcull::sweep {

const char* sceneKind(uint64_t seed) {
    static const char* const kKinds[kSceneKinds] = {"rgvc-2d",      "extremes-2d",  "rgvc-3d",
                                                    "lazy-grid-3d", "hzb-rooms-3d", "bsp-meshes-3d",
                                                    "extremes-3d"};
    return kKinds[seed % kSceneKinds];
}

Scene generatedScene(uint64_t seed) {
    Scene scene;
    switch (seed % kSceneKinds) {
        case 0:
            scene = test::rgvcRandomScene(seed);
            break;
        case 1:
            scene = extremesScene(seed, 2);
            break;
        case 2:
            scene = test::rgvcRandomScene3d(seed);
            break;
        case 3:
            scene = test::lazyGridRandomScene(seed);
            break;
        case 4:
            scene = test::hzbRandomRooms(seed);
            break;
        case 5:
            scene = test::bspRandomScene(seed);
            break;
        default:
            scene = extremesScene(seed, 3);
            break;
    }
    scene.name = std::string("sweep-") + sceneKind(seed) + "-" + std::to_string(seed);
    return scene;
}

void snapMeshes(Scene& scene) {
    std::map<const TriangleMesh*, std::shared_ptr<const TriangleMesh>> snapped;
    for (SceneObject& o : scene.objects) {
        if (o.shape != ShapeKind::Mesh || !o.mesh) continue;
        auto found = snapped.find(o.mesh.get());
        if (found == snapped.end()) {
            auto copy = std::make_shared<TriangleMesh>(*o.mesh);
            for (glm::dvec3& v : copy->vertices)
                for (int a = 0; a < 3; ++a) v[a] = double(float(v[a]));
            copy->bounds = Aabb{copy->vertices.front(), copy->vertices.front()};
            for (const glm::dvec3& v : copy->vertices) copy->bounds.merge(Aabb{v, v});
            found = snapped.emplace(o.mesh.get(), std::move(copy)).first;
        }
        o.mesh = found->second;
        computeAnchorAndBounds(o, scene.dimensions);
    }
}

bool replayable(const Scene& scene, const std::string& work_file, Scene& out, std::string& error,
                bool* rejected) {
    if (rejected) *rejected = false;
    Scene snapped = scene;
    snapMeshes(snapped);
    if (!writeSceneFile(snapped, work_file, error)) return false;
    SceneLoadResult loaded = loadSceneFile(work_file);
    if (!loaded.scene) {
        error = loaded.errors.empty() ? work_file + ": not loaded" : loaded.errors.front();
        if (rejected) *rejected = true;
        return false;
    }
    out = std::move(*loaded.scene);
    return true;
}

}  // namespace gridcull::sweep
