// The bsp view's colours, meanings, masks and node pick (ui/bsp_oq/bsp_oq_view.h).
#include "ui/bsp_oq/bsp_oq_view.h"

#include <algorithm>

#include "culling/scene/ray_intersect.h"

namespace gridcull {

Swatch bspNodeStateSwatch(BspNodeState state) {
    switch (state) {
        case BspNodeState::NotReached:
            return Swatch::Grey;
        case BspNodeState::FrustumCulled:
            return Swatch::DimGrey;
        case BspNodeState::Empty:
            return Swatch::LineGrey;
        case BspNodeState::ViewerInside:
            return Swatch::ReddishPurple;
        case BspNodeState::InFrustum:
            return Swatch::LightGrey;
        case BspNodeState::AssumedVisible:
            return Swatch::Orange;
        case BspNodeState::QueriedVisible:
            return Swatch::BluishGreen;
        case BspNodeState::QueriedHidden:
            return Swatch::White;
    }
    return Swatch::White;
}

float bspNodeStateAlpha(BspNodeState state) {
    // What no test decided recedes; what a query or coherence decided stands out.
    switch (state) {
        case BspNodeState::NotReached:
        case BspNodeState::FrustumCulled:
        case BspNodeState::Empty:
            return 0.45f;
        default:
            return 0.9f;
    }
}

float bspNodeStateWidth(BspNodeState state) {
    // Hidden nodes are what the queries bought: the one heavier line.
    return state == BspNodeState::QueriedHidden ? kFineLine : kHairline;
}

const char* bspNodeStateMeaning(BspNodeState state) {
    switch (state) {
        case BspNodeState::NotReached:
            return "skipped: an ancestor was culled";
        case BspNodeState::FrustumCulled:
            return "box outside the frustum";
        case BspNodeState::Empty:
            return "nothing in it to draw";
        case BspNodeState::ViewerInside:
            return "eye in the box: no query";
        case BspNodeState::InFrustum:
            return "bsp-vfc: drawn untested";
        case BspNodeState::AssumedVisible:
            return "query skipped (coherence)";
        case BspNodeState::QueriedVisible:
            return "query: some pixel passed";
        case BspNodeState::QueriedHidden:
            return "query: hidden, subtree culled";
    }
    return "";
}

Swatch bspQuerySwatch(bool visible) {
    return bspNodeStateSwatch(visible ? BspNodeState::QueriedVisible : BspNodeState::QueriedHidden);
}

std::vector<OverlayPreset> bspOqOverlayPresets() {
    return {OverlayPreset::Occlusion, OverlayPreset::Traversal, OverlayPreset::All};
}

void bspOqApplyPreset(BspOqViewState& view, OverlayPreset preset) {
    constexpr int kEvery = (1 << kBspNodeStateCount) - 1;
    switch (preset) {
        case OverlayPreset::Occlusion: {
            const BspOqViewState occlusion;
            setBspNodeMask(view, bspNodeMask(occlusion));
            view.show_queries = true;
            break;
        }
        case OverlayPreset::Traversal:
            setBspNodeMask(view, kEvery & ~(1 << int(BspNodeState::NotReached)));
            view.show_queries = false;
            break;
        case OverlayPreset::All:
            setBspNodeMask(view, kEvery);
            view.show_queries = true;
            break;
        case OverlayPreset::Tbvs:  // not offered: the toggles stay
            break;
    }
}

int bspNodeMask(const BspOqViewState& view) {
    int mask = 0;
    for (int k = 0; k < kBspNodeStateCount; ++k) mask |= view.show_nodes[k] ? 1 << k : 0;
    return mask;
}

void setBspNodeMask(BspOqViewState& view, int mask) {
    for (int k = 0; k < kBspNodeStateCount; ++k) view.show_nodes[k] = (mask >> k) & 1;
}

const BspNodeRecord* bspNodeOf(const BspOqSnapshot& snapshot, const BspNodeRef& ref) {
    const std::vector<BspNodeRecord>& nodes =
        ref.object_node ? snapshot.object_nodes : snapshot.scene_nodes;
    if (ref.record < 0 || size_t(ref.record) >= nodes.size()) return nullptr;
    return &nodes[size_t(ref.record)];
}

int bspShownTree(const BspOqSnapshot& snapshot, int object) {
    if (object < 0 || size_t(object) >= snapshot.object_first.size()) return -1;
    return snapshot.object_first[size_t(object)] >= 0 ? object : -1;
}

namespace {

struct Best {
    BspNodeRef ref;
    double entry = 0.0, volume = 0.0;
    int depth = 0;
};

double volumeOf(const Aabb& b) {
    const glm::dvec3 d = b.max - b.min;
    return d.x * d.y * d.z;
}

void consider(const BspNodeRecord& node, BspNodeRef ref, const glm::dvec3& origin,
              const glm::dvec3& direction, Best& best) {
    double s0 = 0.0, s1 = 0.0;
    if (!lineBox(origin, direction, node.box, s0, s1) || s0 <= 0.0) return;
    const double volume = volumeOf(node.box);
    const bool better = !best.ref.valid() || s0 < best.entry ||
                        (s0 == best.entry && (volume < best.volume ||
                                              (volume == best.volume && node.depth > best.depth)));
    if (better) best = {ref, s0, volume, node.depth};
}

}  // namespace

BspNodeRef pickBspNode(const BspOqSnapshot& snapshot, const BspOqViewState& view, int tree_object,
                       const glm::dvec3& origin, const glm::dvec3& direction) {
    Best best;
    forEachDrawnBspNode(snapshot, view, tree_object,
                        [&](const BspNodeRecord& node, BspNodeRef ref) {
                            consider(node, ref, origin, direction, best);
                        });
    return best.ref;
}

void bspHistoryMarks(const BspNodeRecord& node, char* out) {
    const int n = std::clamp(node.history_length, 0, kMaxBspHistory);
    for (int k = 0; k < n; ++k) out[k] = (node.history >> k) & 1u ? 'V' : 'H';
    out[n] = '\0';
}

}  // namespace gridcull
