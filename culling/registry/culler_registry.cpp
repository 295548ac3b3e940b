// The --algo names and the one place that maps them to culler classes.
#include <chrono>

#include "culling/baseline/all_culler.h"
#include "culling/api/culler.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/lazy_grid/lazy_grid_culler.h"
#include "culling/rgvc/rgvc_culler.h"
#include "culling/baseline/vfc_culler.h"

namespace gridcull {

std::vector<std::string> cullerNames() {
    return {"all", "vfc", "exact", "rgvc", "lazy-grid", "lazy-grid-z", "busy-grid", "busy-grid-tight"};
}

std::unique_ptr<Culler> makeCuller(std::string_view name, const CullerOptions& options,
                                   std::string& error) {
    if (name == "all") return std::make_unique<AllCuller>();
    if (name == "vfc") return std::make_unique<VfcCuller>();
    if (name == "exact") return std::make_unique<ExactOracle>(options);
    if (name == "rgvc") return std::make_unique<RgvcCuller>(options);
    if (name == "lazy-grid")
        return std::make_unique<LazyGridCuller>(LazyGridVariant::OcclusionBuffer,
                                                LazyGridUpdate::Lazy, options);
    if (name == "lazy-grid-z")
        return std::make_unique<LazyGridCuller>(LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy,
                                                options);
    if (name == "busy-grid")
        return std::make_unique<LazyGridCuller>(LazyGridVariant::OcclusionBuffer,
                                                LazyGridUpdate::Busy, options);
    if (name == "busy-grid-tight")
        return std::make_unique<LazyGridCuller>(LazyGridVariant::OcclusionBuffer,
                                                LazyGridUpdate::BusyTight, options);
    std::string known;
    for (const std::string& n : cullerNames()) known += (known.empty() ? "" : ", ") + n;
    error = "unknown algorithm '" + std::string(name) + "', expected one of: " + known;
    return nullptr;
}

void timedCull(Culler& culler, const Scene& scene, const Camera& camera, double t,
               FrameResult& out) {
    const auto start = std::chrono::steady_clock::now();
    culler.cull(scene, camera, t, out);
    const auto stop = std::chrono::steady_clock::now();
    out.stats.cull_ms = std::chrono::duration<double, std::milli>(stop - start).count();
}

}  // namespace gridcull
