// A scene (docs/scene-format.md): objects with shape, motion and maximum
// speed, a camera path, and the grid the regular-grid algorithms use.
// World units throughout; 2D scenes live in the x-y plane with z = 0.
// Every object moves by translation only: its shape is given at t = 0 and
// displacementAt(t) shifts it rigidly.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "grid/aabb.h"
#include "grid/regular_grid.h"

namespace gridcull {

enum class ShapeKind { Sphere, Box, Polygon, Mesh };  // Sphere is the 2D "circle"
enum class MotionKind { Static, Linear, Keyframes, Random };

const char* shapeName(ShapeKind kind, int dimensions);  // "sphere"/"circle", "box", ...
const char* motionName(MotionKind kind);

struct PositionKey {
    double t = 0.0;
    glm::dvec3 position{0.0};
};

// A triangle mesh in object space, already scaled and rotated; shared between
// the copies that use it. Read-only once loaded.
struct TriangleMesh {
    std::string file;                  // as named in the scene file
    std::vector<glm::dvec3> vertices;  // relative to the object's position
    std::vector<uint32_t> indices;     // three per triangle
    bool closed = false;               // every edge shared by exactly two triangles
    Aabb bounds;                       // of `vertices`
};

struct Motion {
    MotionKind kind = MotionKind::Static;
    glm::dvec3 velocity{0.0};       // Linear
    std::vector<PositionKey> keys;  // Keyframes: positions of the anchor
    double max_speed = 0.0;         // the real one, or the larger declared one
    // Random: a seeded walk, precomputed as one velocity per segment.
    double segment_seconds = 1.0;
    std::vector<glm::dvec3> segment_velocities;
    // Random: the unreflected displacement at the start of each segment, one more
    // entry than segment_velocities (prefix sums, so displacementAt is O(1)).
    // Filled by buildRandomWalk (culling/scene/random_walk.h).
    std::vector<glm::dvec3> segment_offsets;
};

struct SceneObject {
    int id = 0;
    ShapeKind shape = ShapeKind::Sphere;
    // Geometry at t = 0 in world coordinates:
    glm::dvec3 center{0.0};                    // Sphere
    double radius = 0.0;                       // Sphere
    Aabb box;                                  // Box
    std::vector<glm::dvec3> points;            // Polygon, counter-clockwise, z = 0
    std::shared_ptr<const TriangleMesh> mesh;  // Mesh: vertices relative to `center`
    Motion motion;

    // The point that motion moves: the centre of a sphere, of a box's bounds, of a
    // polygon's bounds, a mesh's position. Keyframe positions are this point's.
    glm::dvec3 anchor{0.0};
    Aabb bounds;  // of the whole shape at t = 0

    bool isDynamic() const { return motion.kind != MotionKind::Static; }
};

// Sets object.anchor and object.bounds from its shape fields (center and
// radius, box, points, mesh and center); 2D spheres get a flat box.
void computeAnchorAndBounds(SceneObject& object, int dimensions);

// The fastest segment of a keyframe path (world units per second).
double keyframeSpeed(const std::vector<PositionKey>& keys);

struct CameraKey {
    double t = 0.0;
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, 1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};  // 3D only; +y unless the key says otherwise
};

struct CameraSpec {
    double fov_deg = 60.0;  // 3D: vertical, in (0, 180); 2D: the wedge, in (0, 360]
    double aspect = 16.0 / 9.0;
    double near = 0.1;
    double far = 1000.0;
    std::vector<CameraKey> path;  // increasing t, at least one key
};

struct Scene {
    std::string name;
    std::string source_path;  // the file it came from, "" for built-in scenes
    int dimensions = 3;
    RegularGrid grid;  // world box and resolution
    int frames = 100;
    double dt = 0.04;
    uint64_t seed = 1;
    CameraSpec camera;
    std::vector<SceneObject> objects;  // ids unique; order as loaded

    double timeOfFrame(int frame) const { return frame * dt; }
    // Index into `objects` of an id, or -1.
    int indexOf(int id) const;
    // How far the object has moved from where it stands at t = 0. Linear and
    // random motion fold back at the world bounds per axis (a triangle wave) so
    // the t = 0 bounding box stays inside; on an axis where that box is larger
    // than the world or already sticks out of it, the object does not move.
    // Keyframes: key position minus anchor, held outside the keys. Random: the
    // precomputed walk, held after its last segment. Allocates nothing;
    // O(1), O(log keys) for keyframes.
    glm::dvec3 displacementAt(const SceneObject& object, double t) const;
    glm::dvec3 positionAt(int id, double t) const;  // the anchor at t
    Aabb boundsAt(const SceneObject& object, double t) const;
    // Call after filling `objects`: builds the id index.
    void finalize();

private:
    std::unordered_map<int, int> index_of_id_;
};

}  // namespace gridcull
