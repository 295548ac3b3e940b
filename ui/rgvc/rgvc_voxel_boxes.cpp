#include "ui/rgvc/rgvc_voxel_boxes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

RgvcLayer rgvcBoxLayer(RgvcBoxKind kind) {
    switch (kind) {
        case RgvcBoxKind::Occluder:
        case RgvcBoxKind::None:
            return RgvcLayer::Occluder;
        case RgvcBoxKind::StaticOccluder:
            return RgvcLayer::StaticOccluder;
        case RgvcBoxKind::Occlusion:
            return RgvcLayer::Occlusion;
        case RgvcBoxKind::Tbv:
            return RgvcLayer::Tbv;
        case RgvcBoxKind::Shell:
            return RgvcLayer::CurrentLayer;
    }
    return RgvcLayer::Occluder;
}

RgvcBoxKind rgvcBoxKindAt(const RgvcSnapshot& s, const RgvcViewState& view,
                          const RgvcFrameIndex& index, int64_t layer, int x, int y, int z) {
    if (view.shown(RgvcLayer::Tbv) && s.tbvs) {
        bool t = index.revealedTbvAt(x, y, z);
        if (!t) rgvcForEachTbvIdAt3d(s, x, y, z, [&](int32_t) { t = true; });
        if (t) return RgvcBoxKind::Tbv;
    }
    if (rgvcOAt(s, x, y, z, layer)) {
        if (view.shown(RgvcLayer::StaticOccluder) && rgvcOsAt(s, x, y, z))
            return RgvcBoxKind::StaticOccluder;
        if (view.shown(RgvcLayer::Occluder)) return RgvcBoxKind::Occluder;
    }
    if (view.shown(RgvcLayer::Occlusion) && rgvcHAt(s, x, y, z, layer))
        return RgvcBoxKind::Occlusion;
    if (view.shown(RgvcLayer::CurrentLayer)) {
        const int32_t visit = index.visitOf(x, y, z);
        if (visit >= 0 && s.visits[size_t(visit)].layer == layer) return RgvcBoxKind::Shell;
    }
    return RgvcBoxKind::None;
}

glm::ivec3 rgvcVoxelOfPoint(const RegularGrid& grid, const glm::dvec3& p) {
    const glm::dvec3 d = grid.voxelSize();
    glm::ivec3 v;
    for (int a = 0; a < 3; ++a) {
        const double f = std::floor((p[a] - grid.world.min[a]) / d[a]);
        v[a] = int(std::clamp(f, -1e9, 1e9));
    }
    return v;
}

void RgvcVoxelBoxes::classify(const RgvcSnapshot& s, const RgvcViewState& view,
                              const RgvcFrameIndex& index, int64_t layer) {
    Key key;
    key.stamp = RgvcSnapshotStamp::of(s);
    key.layer = layer;
    for (const RgvcLayer l : {RgvcLayer::Tbv, RgvcLayer::Occluder, RgvcLayer::StaticOccluder,
                              RgvcLayer::Occlusion, RgvcLayer::CurrentLayer})
        key.toggles |= (view.shown(l) ? 1u : 0u) << unsigned(l);
    if (key == kinds_key_ && kinds_.size() == size_t(s.grid.voxelCount())) return;
    kinds_key_ = key;
    faces_valid_ = false;
    const glm::ivec3 res = s.grid.resolution;
    kinds_.resize(size_t(s.grid.voxelCount()));
    any_ = false;
    const bool t_shown = view.shown(RgvcLayer::Tbv) && s.tbvs;
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                // Most voxels hold nothing drawn: skip them on the bits alone.
                const int row = y + z * res.y;
                const bool maybe = t_shown || s.occluder->get(x, row) ||
                                   (s.occlusion && s.occlusion->get(x, row)) ||
                                   index.visitOf(x, y, z) >= 0;
                const RgvcBoxKind k =
                    maybe ? rgvcBoxKindAt(s, view, index, layer, x, y, z) : RgvcBoxKind::None;
                kinds_[rgvcLinear(s.grid, x, y, z)] = uint8_t(k);
                any_ = any_ || k != RgvcBoxKind::None;
            }
}

void RgvcVoxelBoxes::findFaces(const RgvcSnapshot& s, const glm::ivec3& e) {
    if (faces_valid_ && e == faces_eye_) return;
    faces_valid_ = true;
    faces_eye_ = e;
    faces_.clear();
    sorted_.clear();
    if (!any_) return;
    const glm::ivec3 res = s.grid.resolution;
    const size_t stride[3] = {1, size_t(res.x), size_t(res.x) * size_t(res.y)};
    uint32_t key_min = UINT32_MAX, key_max = 0;
    size_t v = 0;
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x, ++v) {
                const uint8_t kind = kinds_[v];
                if (kind == 0) continue;
                const int c[3] = {x, y, z};
                const uint32_t key =
                    uint32_t(std::abs(int64_t(x) - e.x) + std::abs(int64_t(y) - e.y) +
                             std::abs(int64_t(z) - e.z));
                for (int a = 0; a < 3; ++a) {
                    if (c[a] == e[a]) continue;  // the eye lies between this axis' faces
                    const bool plus = e[a] > c[a];
                    const int n = c[a] + (plus ? 1 : -1);
                    if (n >= 0 && n < res[a] && kinds_[plus ? v + stride[a] : v - stride[a]] != 0)
                        continue;  // covered by the nearer neighbour's box
                    faces_.push_back({uint32_t(v), uint8_t(2 * a + (plus ? 0 : 1)), kind, key});
                    key_min = std::min(key_min, key);
                    key_max = std::max(key_max, key);
                }
            }
    if (faces_.empty()) return;
    // Counting sort, farthest first.
    counts_.assign(size_t(key_max - key_min) + 2, 0);
    for (Face& f : faces_) {
        f.key = key_max - f.key;
        ++counts_[size_t(f.key) + 1];
    }
    for (size_t k = 1; k < counts_.size(); ++k) counts_[k] += counts_[k - 1];
    sorted_.resize(faces_.size());
    for (const Face& f : faces_) sorted_[counts_[f.key]++] = f;
}

void RgvcVoxelBoxes::draw(const RgvcSnapshot& s, const RgvcViewState& view,
                          const RgvcFrameIndex& index, int64_t layer, const glm::dvec3& eye,
                          DebugDraw& draw) {
    const RegularGrid& g = s.grid;
    const glm::ivec3 res = g.resolution;
    classify(s, view, index, layer);
    findFaces(s, rgvcVoxelOfPoint(g, eye));
    const glm::dvec3 d = g.voxelSize();
    const Paint frame{kFrameSwatch, 1.0f};
    const bool framed = int64_t(sorted_.size()) <= kMaxFramedFaces;
    for (const Face& f : sorted_) {
        const int a = f.dir / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const bool plus = f.dir % 2 == 0;
        const glm::ivec3 v(int(f.voxel % uint32_t(res.x)),
                           int((f.voxel / uint32_t(res.x)) % uint32_t(res.y)),
                           int(f.voxel / (uint32_t(res.x) * uint32_t(res.y))));
        const glm::dvec3 lo = g.world.min + glm::dvec3(v) * d;
        glm::dvec3 p[4];
        const auto corner = [&](double u, double w) {
            glm::dvec3 q;
            q[a] = lo[a] + (plus ? d[a] : 0.0);
            q[b] = lo[b] + u * d[b];
            q[c] = lo[c] + w * d[c];
            return q;
        };
        p[0] = corner(0, 0), p[1] = corner(1, 0), p[2] = corner(1, 1), p[3] = corner(0, 1);
        const Paint paint{rgvcLayerSwatch(rgvcBoxLayer(RgvcBoxKind(f.kind))), 1.0f};
        if (!framed) {
            draw.quad(DrawSpace::World, p[0], p[1], p[2], p[3], paint);
            continue;
        }
        draw.quad(DrawSpace::World, p[0], p[1], p[2], p[3], frame);
        const double m = kFrame, n = 1.0 - kFrame;
        draw.quad(DrawSpace::World, corner(m, m), corner(n, m), corner(n, n), corner(m, n), paint);
    }
}

}  // namespace gridcull
