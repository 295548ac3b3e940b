// What the overlay tests read back from a debug-draw batch by colour: which
// swatches its primitives use (the batch keeps colours, not swatches; every
// swatch's colour is its own, so the colour names the swatch), and the
// outlines of one paint and width.
#pragma once
#include <algorithm>
#include <set>
#include <vector>

#include <glm/vec4.hpp>

#include "ui/debug_draw.h"
#include "ui/palette.h"

namespace gridcull::test {

inline bool isSwatch(const glm::vec4& color, Swatch swatch) {
    const Rgb c = swatchColor(swatch);
    return color.r == c.r && color.g == c.g && color.b == c.b;
}

// The swatches of every triangle, line and label of the batch in `space`.
inline std::set<Swatch> swatchesIn(const DebugDrawBatch& batch, DrawSpace space) {
    std::set<Swatch> out;
    const auto add = [&](const glm::vec4& color) {
        for (int s = 0; s < kSwatchCount; ++s)
            if (isSwatch(color, Swatch(s))) out.insert(Swatch(s));
    };
    const DebugDrawBatch::Layer& layer = batch.layer(space);
    for (const DebugDrawBatch::Vertex& v : layer.fill) add(v.color);
    for (const DebugDrawBatch::LineSet& set : layer.lines)
        for (const DebugDrawBatch::Vertex& v : set.vertices) add(v.color);
    for (const DebugDrawBatch::Label& label : layer.labels) out.insert(label.paint.swatch);
    return out;
}

// Both spaces.
inline std::set<Swatch> swatchesIn(const DebugDrawBatch& batch) {
    std::set<Swatch> out = swatchesIn(batch, DrawSpace::World);
    for (Swatch s : swatchesIn(batch, DrawSpace::View)) out.insert(s);
    return out;
}

// The line vertices of `space` drawn in `swatch` at `width`, two a segment.
inline std::vector<DebugDrawBatch::Vertex> linesOf(const DebugDrawBatch& batch, DrawSpace space,
                                                   Swatch swatch, float width) {
    std::vector<DebugDrawBatch::Vertex> out;
    for (const DebugDrawBatch::LineSet& set : batch.layer(space).lines)
        if (set.width == width)
            for (const DebugDrawBatch::Vertex& v : set.vertices)
                if (isSwatch(v.color, swatch)) out.push_back(v);
    return out;
}

// The bounding box of `vertices` (x, y: lo; z, w: hi), for an outline's rectangle.
inline glm::vec4 boundsXY(const std::vector<DebugDrawBatch::Vertex>& vertices) {
    glm::vec4 b(1e30f, 1e30f, -1e30f, -1e30f);
    for (const DebugDrawBatch::Vertex& v : vertices) {
        b.x = std::min(b.x, v.position.x);
        b.y = std::min(b.y, v.position.y);
        b.z = std::max(b.z, v.position.x);
        b.w = std::max(b.w, v.position.y);
    }
    return b;
}

}  // namespace gridcull::test
