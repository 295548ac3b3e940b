// The one interface every culling algorithm implements (shared/design.md).
// A culler keeps its state between frames, so frames must be given in order;
// call reset() when the scene changes or time jumps backwards.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "culling/scene/camera.h"
#include "culling/api/cull_stats.h"
#include "culling/scene/scene.h"

namespace gridcull {

struct FrameResult {
    std::vector<int> pvs;  // potentially visible object ids, sorted ascending
    CullStats stats;
};

class Culler {
public:
    virtual ~Culler() = default;
    // The --algo name, e.g. "vfc".
    virtual const char* name() const = 0;
    // Whether this algorithm can run on `scene` (an algorithm built for one
    // dimension only, say). When it cannot, `why` says so; callers must not cull.
    virtual bool supports(const Scene& scene, std::string& why) const {
        (void)scene;
        (void)why;
        return true;
    }
    // Forget every frame seen so far and size buffers for `scene`.
    virtual void reset(const Scene& scene) = 0;
    // Computes the PVS at time t seen by `camera`. `out.pvs` is cleared and refilled
    // (its capacity is reused, so a steady state allocates nothing); out.stats is
    // reset, then filled with this algorithm's counters. cull_ms is set by timedCull.
    virtual void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) = 0;
};

// Options that trade speed for accuracy; each algorithm reads the ones it has.
struct CullerOptions {
    // exact, 3D: pixels on the long side of the oracle's ID buffer.
    int oracle_resolution = 1024;
    // exact, 2D: rays of the angular sweep per full turn (fewer for a narrower wedge).
    int oracle_rays_per_turn = 16384;
    // rgvc: validity period of a temporal bounding volume, seconds (> 0).
    double rgvc_validity_s = 0.5;
    // rgvc: voxels along the world's longest axis, the other axis in proportion;
    // 0 keeps the scene's grid.resolution.
    int rgvc_grid_resolution = 0;
    // lazy-grid, lazy-grid-z, busy-grid: pixels on the long side of the software
    // buffers, the other side from the camera's aspect; 0 = oracle_resolution (so
    // the window's false-cull check compares like with like).
    int lazy_resolution = 0;
    // lazy / busy grid: cell side in pixels (Hey et al. used 32).
    int lazy_cell_size = 32;
    // lazy / busy grid, Hey et al. section 6, each 0 = off: rate a cell free without
    // a pixel query while the area drawn into it is below this fraction of it...
    double lazy_probability_threshold = 0.0;
    // ...query a border cell whole when the box covers more than this fraction of it...
    double lazy_border_whole_fraction = 0.0;
    // ...treat border cells as internal for a box covering more than this fraction
    // of the image.
    double lazy_large_box_fraction = 0.0;
};

// Every algorithm name `--algo` accepts, in the order they are listed in help.
std::vector<std::string> cullerNames();
// Makes the named culler, or returns nullptr and sets `error`.
std::unique_ptr<Culler> makeCuller(std::string_view name, const CullerOptions& options,
                                   std::string& error);

// Runs culler.cull and sets out.stats.cull_ms from a steady clock.
void timedCull(Culler& culler, const Scene& scene, const Camera& camera, double t,
               FrameResult& out);

}  // namespace gridcull
