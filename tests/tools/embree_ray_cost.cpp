// What one Embree ray per pixel centre would cost the 3D oracle, against the
// rasterized oracle it would replace (the figure in culling/oracle/exact_oracle.h,
// "Sub-sample objects"; run by scripts/refine-cost.sh). On the same first
// FRAMES frames of each scene, each frame: the oracle's cull, then the objects
// placed for Embree (as the refinement does each frame) and one ray through
// every pixel centre of the oracle's image. Prints the medians over frames.
//
// usage: embree_ray_cost FRAMES SCENE...
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/trigonometric.hpp>

#include "culling/io/scene_loader.h"
#include "culling/oracle/embree_rays.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/raster/id_depth_buffer.h"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    using namespace gridcull;
    const int frames = argc > 1 ? std::atoi(argv[1]) : 0;
    if (argc < 3 || frames < 1) {
        std::fprintf(stderr, "usage: embree_ray_cost FRAMES SCENE...\n");
        return 2;
    }
    for (int a = 2; a < argc; ++a) {
        const SceneLoadResult loaded = loadSceneFile(argv[a]);
        if (!loaded.scene) {
            for (const std::string& error : loaded.errors) std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        const Scene& scene = *loaded.scene;
        if (scene.dimensions != 3) continue;
        const OracleOptions options;
        ExactOracle oracle(options);
        oracle.reset(scene);
        EmbreeRays rays;
        FrameResult out;
        std::vector<glm::dvec3> shifts(scene.objects.size());
        int width = 0, height = 0;
        imageSizeForAspect(options.resolution, scene.camera.aspect, width, height);
        std::vector<double> raster_ms, ray_ms;
        for (int frame = 0; frame < std::min(frames, scene.frames); ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            Clock::time_point start = Clock::now();
            oracle.cull(scene, camera, t, out);
            raster_ms.push_back(msSince(start));

            start = Clock::now();
            for (size_t i = 0; i < scene.objects.size(); ++i)
                shifts[i] = scene.displacementAt(scene.objects[i], t);
            rays.place(scene, shifts, camera.position);
            glm::dvec3 right, up, forward;
            camera.basis(right, up, forward);
            const double tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5);
            const double tan_x = tan_y * camera.aspect;
            int hits = 0;
            for (int py = 0; py < height; ++py)
                for (int px = 0; px < width; ++px) {
                    const double u = (2.0 * (px + 0.5) / width - 1.0) * tan_x;
                    const double v = (1.0 - 2.0 * (py + 0.5) / height) * tan_y;
                    double depth = 0.0;
                    hits += rays.nearest(forward + u * right + v * up, camera.near, camera.far,
                                         depth) >= 0;
                }
            ray_ms.push_back(msSince(start));
            if (hits < 0) std::abort();  // keeps the loop's result live
        }
        const double raster = median(raster_ms), traced = median(ray_ms);
        std::printf("%-24s %4d x %-4d rasterized oracle %8.2f ms   Embree, a ray a pixel %8.2f ms"
                    "   %5.1fx\n",
                    scene.name.c_str(), width, height, raster, traced, traced / raster);
    }
    return 0;
}
