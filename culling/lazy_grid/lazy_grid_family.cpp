#include "culling/lazy_grid/lazy_grid_family.h"

#include "culling/lazy_grid/lazy_grid_culler.h"
#include "culling/lazy_grid/lazy_grid_options.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

namespace {

struct Variant {
    const char* name;
    LazyGridVariant variant;
    LazyGridUpdate update;
    const char* summary;
};

constexpr Variant kVariants[] = {
    {"lazy-grid", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy,
     "lazy occlusion grid, occlusion-buffer variant (Hey et al.)"},
    {"lazy-grid-z", LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy,
     "lazy occlusion grid, z-buffer variant"},
    {"busy-grid", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy,
     "the same grid with the paper's busy update, for comparison"},
    {"busy-grid-tight", LazyGridVariant::OcclusionBuffer, LazyGridUpdate::BusyTight,
     "busy update of only the cells drawn into, a stronger baseline"},
};

}  // namespace

const KnobTable<LazyGridOptions>& lazyGridKnobs() {
    static const KnobTable<LazyGridOptions> table{
        swept(derivedKnob("lazy-res", &LazyGridOptions::resolution, kMinLazyResolution,
                          kMaxImageResolution, "oracle", "the --oracle-res value",
                          "pixels on the long side of the grid's image; below the oracle's, an "
                          "object seen only between its pixel centres may be dropped"),
              {256, 512, 1024, 2048}),
        swept(knob(kLazyCellSizeFlag, &LazyGridOptions::cell_size, 1, kMaxLazyCellSize,
                   "cell side in pixels; smaller: more cells to read, fewer pixels per query"),
              {8, 16, 32, 64}),
        swept(knob("lazy-prob", &LazyGridOptions::probability_threshold, 0.0, 1.0,
                   "section 6: rate a cell free without a pixel query while less than this "
                   "fraction of it was drawn into (0: off); saves queries, culls less"),
              {0, 0.25, 0.5, 0.75}),
        swept(knob("lazy-border-whole", &LazyGridOptions::border_whole_fraction, 0.0, 1.0,
                   "section 6: query a border cell whole when the box covers more than this "
                   "fraction of it (0: off)"),
              {0, 0.5, 0.9}),
        swept(knob("lazy-large-box", &LazyGridOptions::large_box_fraction, 0.0, 1.0,
                   "section 6: border cells count as internal for a box over this fraction "
                   "of the image (0: off)"),
              {0, 0.25, 0.5}),
    };
    return table;
}

FamilyEntry lazyGridFamily() {
    FamilyEntry family;
    family.id = "lazy-grid";
    family.title = "Lazy occlusion grid (Hey, Tobler & Purgathofer)";
    for (const Variant& v : kVariants) family.algorithms.push_back({v.name, kRuns3d, v.summary});
    family.knobs = lazyGridKnobs().knobs();
    family.draws_image = true;
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        for (const Variant& v : kVariants) {
            if (request.algorithm != v.name) continue;
            return std::make_unique<LazyGridCuller>(
                v.variant, v.update, lazyGridKnobs().read(*request.knobs),
                request.reference_resolution, std::move(request.target), request.name);
        }
        return nullptr;
    };
    return family;
}

}  // namespace gridcull
