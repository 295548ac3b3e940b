#include "app/app_cullers.h"

#include "app/gl_context.h"
#include "app/gl_image_target.h"
#include "culling/lazy_grid/lazy_grid_culler.h"

namespace gridcull {

namespace {

struct GlCullerKind {
    const char* name;
    LazyGridVariant variant;
    LazyGridUpdate update;
};

constexpr GlCullerKind kGlCullers[] = {
    {"lazy-grid-gl", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy},
    {"lazy-grid-z-gl", LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy},
    {"busy-grid-gl", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy},
    {"busy-grid-tight-gl", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::BusyTight},
};

// One hidden window's context for every -gl culler of the process.
bool ensureGlContext(std::string& error) {
    static GlWindow* window = nullptr;
    if (window) return true;
    auto* made = new GlWindow;  // lives until exit: the cullers' GL objects need it
    if (!made->create(64, 64, "gridcull bench", false, error)) {
        delete made;
        error = "the -gl algorithms need an OpenGL context: " + error;
        return false;
    }
    window = made;
    return true;
}

}  // namespace

std::vector<std::string> appCullerNames() {
    std::vector<std::string> names = cullerNames();
    for (const GlCullerKind& kind : kGlCullers) names.emplace_back(kind.name);
    return names;
}

std::unique_ptr<Culler> makeAppCuller(std::string_view name, const CullerOptions& options,
                                      std::string& error) {
    for (const GlCullerKind& kind : kGlCullers) {
        if (name != kind.name) continue;
        if (!ensureGlContext(error)) return nullptr;
        auto target = std::make_unique<GlImageTarget>();
        if (!target->init(error)) return nullptr;
        return std::make_unique<LazyGridCuller>(kind.variant, kind.update, options,
                                                std::move(target), kind.name);
    }
    return makeCuller(name, options, error);
}

}  // namespace gridcull
