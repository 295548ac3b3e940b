#include "ui/rgvc/rgvc_view.h"

#include <algorithm>

namespace gridcull {

const char* rgvcLayerName(RgvcLayer layer) {
    switch (layer) {
        case RgvcLayer::Occluder:
            return "O";
        case RgvcLayer::Occlusion:
            return "H";
        case RgvcLayer::Identifiers:
            return "I";
        case RgvcLayer::Tbv:
            return "T";
        case RgvcLayer::Visited:
            return "visited";
        case RgvcLayer::CurrentLayer:
            return "layer";
        case RgvcLayer::Seed:
            return "seed";
        case RgvcLayer::LineOfSight:
            return "sight";
        case RgvcLayer::PickedOccluder:
            return "occluder";
        case RgvcLayer::Polygon:
            return "polygon";
    }
    return "?";
}

const char* rgvcLayerMeaning(RgvcLayer layer) {
    switch (layer) {
        case RgvcLayer::Occluder:
            return "opaque voxels (dark)";
        case RgvcLayer::Occlusion:
            return "occluded voxels (light)";
        case RgvcLayer::Identifiers:
            return "voxels holding object ids";
        case RgvcLayer::Tbv:
            return "TBV curve voxels";
        case RgvcLayer::Visited:
            return "traversed up to the layer";
        case RgvcLayer::CurrentLayer:
            return "the current chess layer";
        case RgvcLayer::Seed:
            return "its seed voxel (white box)";
        case RgvcLayer::LineOfSight:
            return "line of sight (dashed)";
        case RgvcLayer::PickedOccluder:
            return "picked: extension steps";
        case RgvcLayer::Polygon:
            return "picked: occlusion polygon";
    }
    return "";
}

Swatch rgvcLayerSwatch(RgvcLayer layer) {
    switch (layer) {
        case RgvcLayer::Occluder:
            return Swatch::NearBlack;
        case RgvcLayer::Occlusion:
            return Swatch::LightGrey;
        case RgvcLayer::Identifiers:
            return Swatch::Orange;
        case RgvcLayer::Tbv:
            return Swatch::ReddishPurple;
        case RgvcLayer::Visited:
        case RgvcLayer::CurrentLayer:  // the same, solid
            return Swatch::BluishGreen;
        case RgvcLayer::Seed:
            return Swatch::White;
        case RgvcLayer::LineOfSight:
            return Swatch::Yellow;  // the camera's
        case RgvcLayer::PickedOccluder:
            return Swatch::SkyBlue;
        case RgvcLayer::Polygon:
            return Swatch::Vermillion;
    }
    return Swatch::White;
}

float rgvcLayerAlpha(RgvcLayer layer) {
    switch (layer) {
        case RgvcLayer::Occluder:
            return 0.80f;
        case RgvcLayer::Occlusion:
            return 0.40f;
        case RgvcLayer::Visited:
            return 0.35f;
        case RgvcLayer::Polygon:
            return 0.18f;
        default:
            return 1.0f;
    }
}

void describeRgvcVoxel(const RgvcSnapshot& snapshot, const Scene& scene, glm::ivec2 v,
                       RgvcVoxelInfo& out) {
    out.valid = false;
    out.voxel = v;
    out.o = out.os = out.h = false;
    out.ids_i.clear();
    out.ids_t.clear();
    out.visit_order = -1;
    out.layer = -1;
    out.visited_occluded = false;
    if (!snapshot.valid || !snapshot.occluder) return;
    const glm::ivec3 res = snapshot.grid.resolution;
    if (v.x < 0 || v.y < 0 || v.x >= res.x || v.y >= res.y) return;
    out.valid = true;
    out.o = snapshot.occluder->get(v.x, v.y);
    out.os = snapshot.static_occluder && snapshot.static_occluder->get(v.x, v.y);
    out.h = snapshot.occlusion && snapshot.occlusion->get(v.x, v.y);
    const auto idOf = [&](int32_t index) {
        return index >= 0 && size_t(index) < scene.objects.size() ? scene.objects[size_t(index)].id
                                                                  : int(index);
    };
    for (const IdListMatrix* m : {snapshot.identifiers_static, snapshot.identifiers_dynamic})
        if (m) m->forEach(v.x, v.y, [&](int32_t index) { out.ids_i.push_back(idOf(index)); });
    if (snapshot.tbvs)
        snapshot.tbvs->forEach(v.x, v.y, [&](int32_t index) { out.ids_t.push_back(idOf(index)); });
    std::sort(out.ids_i.begin(), out.ids_i.end());
    std::sort(out.ids_t.begin(), out.ids_t.end());
    for (size_t k = 0; k < snapshot.visits.size(); ++k) {
        const RgvcVisit& visit = snapshot.visits[k];
        if (visit.voxel != v) continue;
        out.visit_order = int64_t(k);
        out.layer = visit.layer;
        out.visited_occluded = visit.occluded;
        break;
    }
}

int rgvcOccluderAt(const RgvcSnapshot& snapshot, glm::ivec2 v) {
    const auto& list = snapshot.occluders;
    for (size_t k = 0; k < list.size(); ++k)
        if (list[k].occluder.initial == v) return int(k);
    for (size_t k = 0; k < list.size(); ++k)
        if (list[k].occluder.covers(v)) return int(k);
    return -1;
}

int64_t rgvcShownLayer(const RgvcSnapshot& snapshot, int64_t requested) {
    if (!snapshot.valid || snapshot.last_layer < snapshot.first_layer) return -1;
    if (requested < 0) return snapshot.last_layer;
    return std::clamp(requested, snapshot.first_layer, snapshot.last_layer);
}

}  // namespace gridcull
