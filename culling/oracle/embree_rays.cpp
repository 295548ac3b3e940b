#include "culling/oracle/embree_rays.h"

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>

#include <embree3/rtcore.h>

namespace gridcull {

namespace {

void onEmbreeError(void*, RTCError code, const char* message) {
    // Only a broken installation or an exhausted memory gets here: the oracle
    // cannot answer without its rays, and must not answer wrongly.
    std::fprintf(stderr, "gridcull: Embree error %d: %s\n", int(code), message ? message : "");
    std::abort();
}

// One device for the process, made at first use and kept to the end: single
// threaded, so that the oracle's cost stays on the thread that asked.
RTCDevice sharedDevice() {
    static RTCDevice device = [] {
        RTCDevice d = rtcNewDevice("threads=1,set_affinity=0");
        if (!d) onEmbreeError(nullptr, rtcGetDeviceError(nullptr), "no Embree device");
        rtcSetDeviceErrorFunction(d, onEmbreeError, nullptr);
        return d;
    }();
    return device;
}

// The six faces of a box over its corners (bit 0 = max x, bit 1 = max y,
// bit 2 = max z), two triangles each.
constexpr unsigned kBoxTriangles[12][3] = {{0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3},
                                           {0, 4, 5}, {0, 5, 1}, {2, 3, 7}, {2, 7, 6},
                                           {0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}};

}  // namespace

struct EmbreeRays::Impl {
    RTCScene top = nullptr;
    RTCGeometry spheres = nullptr, boxes = nullptr;
    unsigned spheres_id = RTC_INVALID_GEOMETRY_ID, boxes_id = RTC_INVALID_GEOMETRY_ID;
    std::vector<int> sphere_object, box_object;  // per primitive: the object index
    std::vector<int> instance_object;            // per top-level geometry id: the object index
    std::map<const TriangleMesh*, RTCScene> mesh_scenes;

    ~Impl() {
        if (top) rtcReleaseScene(top);
        for (auto& [mesh, scene] : mesh_scenes) rtcReleaseScene(scene);
    }

    RTCScene meshScene(const TriangleMesh& mesh) {
        auto found = mesh_scenes.find(&mesh);
        if (found != mesh_scenes.end()) return found->second;
        RTCDevice device = sharedDevice();
        RTCScene scene = rtcNewScene(device);
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        const size_t vertices = mesh.vertices.size(), triangles = mesh.indices.size() / 3;
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), vertices));
        for (size_t i = 0; i < vertices; ++i)
            for (int a = 0; a < 3; ++a) v[4 * i + size_t(a)] = float(mesh.vertices[i][a]);
        auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
        for (size_t i = 0; i < 3 * triangles; ++i) index[i] = mesh.indices[i];
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene);
        mesh_scenes.emplace(&mesh, scene);
        return scene;
    }

    void build(const Scene& scene) {
        RTCDevice device = sharedDevice();
        top = rtcNewScene(device);
        rtcSetSceneFlags(top, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_LOW);
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& object = scene.objects[i];
            if (object.shape == ShapeKind::Sphere) sphere_object.push_back(int(i));
            if (object.shape == ShapeKind::Box) box_object.push_back(int(i));
        }
        if (!sphere_object.empty()) {
            spheres = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                    4 * sizeof(float), sphere_object.size());
            spheres_id = rtcAttachGeometry(top, spheres);
            rtcReleaseGeometry(spheres);  // the scene keeps it
        }
        if (!box_object.empty()) {
            boxes = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetNewGeometryBuffer(boxes, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    4 * sizeof(float), 8 * box_object.size());
            auto* index = static_cast<unsigned*>(
                rtcSetNewGeometryBuffer(boxes, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        3 * sizeof(unsigned), 12 * box_object.size()));
            for (size_t b = 0; b < box_object.size(); ++b)
                for (int t = 0; t < 12; ++t)
                    for (int c = 0; c < 3; ++c)
                        index[36 * b + size_t(3 * t + c)] = unsigned(8 * b + kBoxTriangles[t][c]);
            boxes_id = rtcAttachGeometry(top, boxes);
            rtcReleaseGeometry(boxes);
        }
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& object = scene.objects[i];
            if (object.shape != ShapeKind::Mesh || !object.mesh || object.mesh->indices.size() < 3)
                continue;
            RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(instance, meshScene(*object.mesh));
            const unsigned id = rtcAttachGeometry(top, instance);
            rtcReleaseGeometry(instance);
            if (instance_object.size() <= id) instance_object.resize(id + 1, -1);
            instance_object[id] = int(i);
        }
    }
};

EmbreeRays::EmbreeRays() = default;
EmbreeRays::~EmbreeRays() = default;
EmbreeRays::EmbreeRays(const EmbreeRays&) {}
EmbreeRays& EmbreeRays::operator=(const EmbreeRays& other) {
    if (this != &other) impl_.reset();
    return *this;
}

void EmbreeRays::reset() { impl_.reset(); }

void EmbreeRays::place(const Scene& scene, const std::vector<glm::dvec3>& shifts,
                       const glm::dvec3& eye) {
    if (!impl_) {
        impl_ = std::make_unique<Impl>();
        impl_->build(scene);
    }
    Impl& s = *impl_;
    if (s.spheres) {
        auto* v = static_cast<float*>(rtcGetGeometryBufferData(s.spheres, RTC_BUFFER_TYPE_VERTEX, 0));
        for (size_t k = 0; k < s.sphere_object.size(); ++k) {
            const size_t i = size_t(s.sphere_object[k]);
            const glm::dvec3 c = scene.objects[i].center + shifts[i] - eye;
            v[4 * k + 0] = float(c.x);
            v[4 * k + 1] = float(c.y);
            v[4 * k + 2] = float(c.z);
            v[4 * k + 3] = float(scene.objects[i].radius);
        }
        rtcUpdateGeometryBuffer(s.spheres, RTC_BUFFER_TYPE_VERTEX, 0);
        rtcCommitGeometry(s.spheres);
    }
    if (s.boxes) {
        auto* v = static_cast<float*>(rtcGetGeometryBufferData(s.boxes, RTC_BUFFER_TYPE_VERTEX, 0));
        for (size_t k = 0; k < s.box_object.size(); ++k) {
            const size_t i = size_t(s.box_object[k]);
            const Aabb box = scene.objects[i].box.translated(shifts[i] - eye);
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 p = box.corner(c);
                for (int a = 0; a < 3; ++a) v[4 * (8 * k + size_t(c)) + size_t(a)] = float(p[a]);
            }
        }
        rtcUpdateGeometryBuffer(s.boxes, RTC_BUFFER_TYPE_VERTEX, 0);
        rtcCommitGeometry(s.boxes);
    }
    for (size_t id = 0; id < s.instance_object.size(); ++id) {
        const int i = s.instance_object[id];
        if (i < 0) continue;
        const glm::dvec3 at = scene.objects[size_t(i)].center + shifts[size_t(i)] - eye;
        const float transform[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, float(at.x), float(at.y), float(at.z)};
        RTCGeometry instance = rtcGetGeometry(s.top, unsigned(id));
        rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform);
        rtcCommitGeometry(instance);
    }
    rtcCommitScene(s.top);
}

int EmbreeRays::nearest(const glm::dvec3& dir, double near, double far, double& depth) const {
    if (!impl_) return -1;
    const Impl& s = *impl_;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray{};
    ray.ray.dir_x = float(dir.x);
    ray.ray.dir_y = float(dir.y);
    ray.ray.dir_z = float(dir.z);
    ray.ray.tnear = float(near);
    ray.ray.tfar = float(far);
    ray.ray.mask = 0xFFFFFFFFu;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    ray.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s.top, &context, &ray);
    if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    depth = double(ray.ray.tfar);
    if (ray.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) return s.instance_object[ray.hit.instID[0]];
    if (ray.hit.geomID == s.spheres_id) return s.sphere_object[ray.hit.primID];
    if (ray.hit.geomID == s.boxes_id) return s.box_object[ray.hit.primID / 12];
    return -1;
}

}  // namespace gridcull
