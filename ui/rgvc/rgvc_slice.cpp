#include "ui/rgvc/rgvc_slice.h"

#include <algorithm>

#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

namespace {

// Slice coordinates: u along axis b = (a + 1) % 3, w along c = (a + 2) % 3, in
// voxel-corner units, to world points on the slice's plane.
struct SlicePlane {
    int a, b, c;
    double plane;
    glm::dvec3 origin, size;
    glm::dvec3 at(double u, double w) const {
        glm::dvec3 p;
        p[a] = plane;
        p[b] = origin[b] + u * size[b];
        p[c] = origin[c] + w * size[c];
        return p;
    }
    void square(DebugDraw& draw, double u0, double w0, double u1, double w1, Paint paint) const {
        draw.quad(DrawSpace::World, at(u0, w0), at(u1, w0), at(u1, w1), at(u0, w1), paint);
    }
};

}  // namespace

RgvcSliceCell rgvcSliceCellAt(const RgvcSnapshot& s, const RgvcViewState& view,
                              const RgvcFrameIndex& index, int64_t layer, int x, int y, int z) {
    if (view.shown(RgvcLayer::Tbv) && s.tbvs) {
        bool t = index.revealedTbvAt(x, y, z);
        if (!t) rgvcForEachTbvIdAt3d(s, x, y, z, [&](int32_t) { t = true; });
        if (t) return RgvcSliceCell::Tbv;
    }
    if (rgvcOAt(s, x, y, z, layer)) {
        if (view.shown(RgvcLayer::StaticOccluder) && rgvcOsAt(s, x, y, z))
            return RgvcSliceCell::StaticOccluder;
        if (view.shown(RgvcLayer::Occluder)) return RgvcSliceCell::Occluder;
    }
    if (view.shown(RgvcLayer::Occlusion) && rgvcHAt(s, x, y, z, layer))
        return RgvcSliceCell::Occlusion;
    const int32_t visit = index.visitOf(x, y, z);
    if (visit >= 0) {
        const int32_t at = s.visits[size_t(visit)].layer;
        if (at == layer && view.shown(RgvcLayer::CurrentLayer)) return RgvcSliceCell::Layer;
        if (at < layer && view.shown(RgvcLayer::Visited)) return RgvcSliceCell::Visited;
    }
    return RgvcSliceCell::None;
}

RgvcLayer rgvcSliceCellLayer(RgvcSliceCell cell) {
    switch (cell) {
        case RgvcSliceCell::Tbv:
            return RgvcLayer::Tbv;
        case RgvcSliceCell::StaticOccluder:
            return RgvcLayer::StaticOccluder;
        case RgvcSliceCell::Occlusion:
            return RgvcLayer::Occlusion;
        case RgvcSliceCell::Layer:
            return RgvcLayer::CurrentLayer;
        case RgvcSliceCell::Visited:
            return RgvcLayer::Visited;
        case RgvcSliceCell::Occluder:
        case RgvcSliceCell::None:
            break;
    }
    return RgvcLayer::Occluder;
}

double rgvcSlicePlane(const RegularGrid& grid, int axis, int index) {
    return grid.world.min[axis] + (double(index) + 0.5) * grid.voxelSize()[axis];
}

void drawRgvcSlice(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
                   int64_t layer, DebugDraw& draw) {
    const RegularGrid& g = s.grid;
    const int a = std::clamp(view.slice_axis, 0, 2);
    const int n = rgvcSliceIndex(s, view);
    SlicePlane p{a, (a + 1) % 3, (a + 2) % 3, rgvcSlicePlane(g, a, n), g.world.min, g.voxelSize()};
    const int width = g.resolution[p.b], height = g.resolution[p.c];
    const auto voxel = [&](int u, int w) {
        glm::ivec3 v;
        v[a] = n;
        v[p.b] = u;
        v[p.c] = w;
        return v;
    };
    const auto cellAt = [&](int u, int w) {
        const glm::ivec3 v = voxel(u, w);
        return rgvcSliceCellAt(s, view, index, layer, v.x, v.y, v.z);
    };
    const auto paintOf = [](RgvcSliceCell cell) {
        return Paint{rgvcLayerSwatch(rgvcSliceCellLayer(cell)), 1.0f};
    };
    // The plane itself, so that the scene behind does not show through.
    p.square(draw, 0, 0, width, height, Paint{kRgvcSliceBackdrop, 1.0f});
    for (int w = 0; w < height; ++w) {
        int u = 0;
        while (u < width) {
            const RgvcSliceCell cell = cellAt(u, w);
            if (cell == RgvcSliceCell::None) {
                ++u;
                continue;
            }
            if (cell == RgvcSliceCell::Visited) {
                const double m = 0.5 * (1.0 - kRgvcTileFraction);
                p.square(draw, u + m, w + m, u + 1 - m, w + 1 - m, paintOf(cell));
                ++u;
                continue;
            }
            const int start = u;
            while (u < width && cellAt(u, w) == cell) ++u;
            p.square(draw, start, w, u, w + 1, paintOf(cell));
        }
    }
    if (view.shown(RgvcLayer::Identifiers)) {
        const Paint mark{rgvcLayerSwatch(RgvcLayer::Identifiers), 1.0f};
        const double m = 0.5 * (1.0 - kRgvcMarkFraction);
        for (int w = 0; w < height; ++w)
            for (int u = 0; u < width; ++u) {
                const glm::ivec3 v = voxel(u, w);
                bool has = false;
                rgvcForEachIdAt(s, v.x, v.y, v.z, layer, [&](int32_t) { has = true; });
                if (has) p.square(draw, u + m, w + m, u + 1 - m, w + 1 - m, mark);
            }
    }
    const glm::dvec3 corners[4] = {p.at(0, 0), p.at(width, 0), p.at(width, height),
                                   p.at(0, height)};
    draw.outlinePolygon(DrawSpace::World, corners, 4, Paint{Swatch::LineGrey, 1.0f}, kFineLine);
}

}  // namespace gridcull
