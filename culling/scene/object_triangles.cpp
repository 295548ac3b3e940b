#include "culling/scene/object_triangles.h"

namespace gridcull {

int64_t trianglesOf(const SceneObject& object) {
    switch (object.shape) {
        case ShapeKind::Sphere:
            return kSphereTriangles;
        case ShapeKind::Box:
            return kBoxTriangles;
        case ShapeKind::Mesh:
            return object.mesh ? int64_t(object.mesh->indices.size() / 3) : 0;
        case ShapeKind::Polygon:
            return 0;
    }
    return 0;
}

}  // namespace gridcull
