#include "ui/rgvc/rgvc_view.h"

#include <algorithm>
#include <initializer_list>

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
        case RgvcLayer::StaticOccluder:
            return "Os";
    }
    return "?";
}

bool rgvcLayerApplies(RgvcLayer layer, int dimensions) {
    return layer != RgvcLayer::StaticOccluder || dimensions == 3;
}

const char* rgvcLayerMeaning(RgvcLayer layer, int dimensions) {
    if (dimensions == 3) {
        // The 3D overlay: voxel boxes or a slice, every fill opaque.
        switch (layer) {
            case RgvcLayer::Occluder:
                return "opaque voxels";
            case RgvcLayer::StaticOccluder:
                return "opaque, static objects'";
            case RgvcLayer::Occlusion:
                return "occluded voxels";
            case RgvcLayer::Identifiers:
                return "object ids (slice: mark)";
            case RgvcLayer::Tbv:
                return "TBVs: 2 of Txy Txz Tyz";
            case RgvcLayer::Visited:
                return "traversed before (slice)";
            case RgvcLayer::CurrentLayer:
                return "the layer's voxels, shell";
            case RgvcLayer::Seed:
                return "its seed voxel (yellow box)";
            case RgvcLayer::LineOfSight:
                return "line of sight (dashed)";
            case RgvcLayer::PickedOccluder:
                return "picked voxel, its map cells";
            case RgvcLayer::Polygon:
                return "picked: cap, extrusion";
        }
        return "";
    }
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
            return "its seed voxel (yellow box)";
        case RgvcLayer::LineOfSight:
            return "line of sight (dashed)";
        case RgvcLayer::PickedOccluder:
            return "picked: extension steps";
        case RgvcLayer::Polygon:
            return "picked: occlusion polygon";
        case RgvcLayer::StaticOccluder:
            return "static opaque voxels";
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
        case RgvcLayer::Seed:  // on the line of sight (the Bresenham line gives it)
        case RgvcLayer::LineOfSight:
            return Swatch::Yellow;  // the culling camera's
        case RgvcLayer::PickedOccluder:
        case RgvcLayer::Polygon:  // picked things; vermillion is the false culls' alone
            return Swatch::SkyBlue;
        case RgvcLayer::StaticOccluder:
            return Swatch::Grey;
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

int rgvcOccluderAt(const RgvcSnapshot& snapshot, glm::ivec2 v) {
    const auto& list = snapshot.occluders;
    for (size_t k = 0; k < list.size(); ++k)
        if (list[k].occluder.initial == v) return int(k);
    for (size_t k = 0; k < list.size(); ++k)
        if (list[k].occluder.covers(v)) return int(k);
    return -1;
}

std::vector<OverlayPreset> rgvcOverlayPresets() {
    return {OverlayPreset::Occlusion, OverlayPreset::Traversal, OverlayPreset::Tbvs,
            OverlayPreset::All};
}

void rgvcApplyPreset(RgvcViewState& view, OverlayPreset preset, int dimensions) {
    const auto set = [&](std::initializer_list<RgvcLayer> layers) {
        for (bool& on : view.show) on = false;
        for (RgvcLayer l : layers) view.show[int(l)] = true;
    };
    using L = RgvcLayer;
    switch (preset) {
        case OverlayPreset::Occlusion:
            // Os folded into O: in 3D its grey boxes would cover O's dark ones.
            set({L::Occluder, L::Occlusion, L::PickedOccluder, L::Polygon});
            break;
        case OverlayPreset::Traversal:
            set({L::Visited, L::CurrentLayer, L::Seed, L::LineOfSight});
            // 2D: O under the traversal shows where it met its occluders; 3D
            // boxes of O would hide the layer's voxels.
            view.show[int(L::Occluder)] = dimensions == 2;
            break;
        case OverlayPreset::Tbvs:
            set({L::Tbv, L::Identifiers});
            break;
        case OverlayPreset::All:
            for (bool& on : view.show) on = true;
            break;
    }
    for (int l = 0; l < kRgvcLayerCount; ++l)
        if (!rgvcLayerApplies(RgvcLayer(l), dimensions)) view.show[l] = false;
}

int rgvcSliceIndex(const RgvcSnapshot& snapshot, const RgvcViewState& view) {
    const int axis = std::clamp(view.slice_axis, 0, 2);
    const int top = snapshot.grid.resolution[axis] - 1;
    if (view.slice_index >= 0) return std::clamp(view.slice_index, 0, top);
    const int64_t eye = axis == 0   ? snapshot.viewer_voxel.x
                        : axis == 1 ? snapshot.viewer_voxel.y
                                    : snapshot.viewer_voxel_z;
    return int(std::clamp<int64_t>(eye, 0, top));
}

int64_t rgvcShownLayer(const RgvcSnapshot& snapshot, int64_t requested) {
    if (!snapshot.valid || snapshot.last_layer < snapshot.first_layer) return -1;
    if (requested < 0) return snapshot.last_layer;
    return std::clamp(requested, snapshot.first_layer, snapshot.last_layer);
}

}  // namespace gridcull
