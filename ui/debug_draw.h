// The debug-draw interface every family's overlay is written against, after
// Jolt Physics' DebugRenderer: the overlay emits triangles, lines and text
// labels, and the rectangles, outlines, dashes, hatches, polygons and voxels
// built on them (an image cell is a rectangle from ImageFrame::pixelsToView),
// each with a Paint from the one palette (ui/palette.h). It never sees OpenGL: the app draws what
// it emitted (app/gl_debug_draw.h) and tests read it back from a DebugDrawBatch.
//
// Two spaces:
//   World  scene coordinates, through the view's camera (2D: the x-y plane, z = 0);
//   View   pixels of the scene view, origin at its top left, y down.
// Draw order is fixed, whatever order things are emitted in: per space (World,
// then View), all filled triangles in emission order, then lines by width,
// thinnest first, each width in emission order, then text. So an overlay that
// fills cells and outlines them gets outlines on top.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "grid/regular_grid.h"
#include "ui/palette.h"

namespace gridcull {

enum class DrawSpace : uint8_t { World, View };
constexpr int kDrawSpaceCount = 2;

// A rectangle in view pixels (continuous, origin top left): [x0, x1) x [y0, y1).
struct ViewRect {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

class DebugDraw {
public:
    virtual ~DebugDraw() = default;

    // The primitives.
    virtual void triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c, Paint paint) = 0;
    // `width` in view pixels (kHairline, kFineLine, kBoldLine, kHeavyLine).
    virtual void line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
                      float width) = 0;
    // A label whose top-left corner is at `at` (World: where `at` projects),
    // `scale` times the font's 7-pixel glyph height.
    virtual void text(DrawSpace space, const glm::dvec3& at, const char* text, Paint paint,
                      float scale = 2.0f) = 0;

    // Built on the primitives. Rectangles lie in the x-y plane (z = 0).
    void quad(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
              const glm::dvec3& d, Paint paint);  // as triangles (a, b, c) and (a, c, d)
    void fillRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint);
    void fillRect(const ViewRect& r, Paint paint) {
        fillRect(DrawSpace::View, r.x0, r.y0, r.x1, r.y1, paint);
    }
    // Sides in the order bottom, right, top, left from (x0, y0).
    void outlineRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint,
                     float width);
    void outlineRect(const ViewRect& r, Paint paint, float width) {
        outlineRect(DrawSpace::View, r.x0, r.y0, r.x1, r.y1, paint, width);
    }
    // Each side as dashes of `dash` with gaps of `gap` (units of the space).
    void dashedRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint,
                    float width, double dash, double gap);
    // Diagonal lines (x + y constant) across the rectangle, `spacing` apart.
    void hatchRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint,
                   float width, double spacing);
    // A convex polygon as a fan from its first corner.
    void fillConvexPolygon(DrawSpace space, const glm::dvec3* points, size_t count, Paint paint);
    // The open line through `points`, and the closed outline.
    void polyline(DrawSpace space, const glm::dvec3* points, size_t count, Paint paint,
                  float width);
    void outlinePolygon(DrawSpace space, const glm::dvec3* points, size_t count, Paint paint,
                        float width);
    // Voxel (x, y) of a 2D grid, filled (World space).
    void fillVoxel(const RegularGrid& grid, int x, int y, Paint paint);
    // The twelve edges of the axis-aligned box [lo, hi] (World space): tree
    // nodes, bounding volumes, highlighted voxels of the 3D overlays.
    void wireBox(const glm::dvec3& lo, const glm::dvec3& hi, Paint paint, float width);
};

// A DebugDraw that keeps what was emitted, per space and in draw order, for the
// app to draw and for tests to read. Clearing keeps every buffer's capacity, so
// a steady state allocates nothing.
class DebugDrawBatch final : public DebugDraw {
public:
    struct Vertex {
        glm::vec3 position;
        glm::vec4 color;  // linear RGBA
    };
    struct LineSet {
        float width = 1.0f;
        std::vector<Vertex> vertices;  // two per segment
    };
    struct Label {
        glm::dvec3 at{0.0};
        Paint paint;
        float scale = 1.0f;
        size_t text_begin = 0, text_end = 0;  // in texts()
    };
    struct Layer {
        std::vector<Vertex> fill;    // three per triangle
        std::vector<LineSet> lines;  // thinnest first; a set may be empty after clear()
        std::vector<Label> labels;
    };

    void clear();
    bool empty() const;
    const Layer& layer(DrawSpace space) const { return layers_[int(space)]; }
    const std::string& texts() const { return texts_; }
    std::string labelText(const Label& label) const {
        return texts_.substr(label.text_begin, label.text_end - label.text_begin);
    }

    void triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  Paint paint) override;
    void line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
              float width) override;
    void text(DrawSpace space, const glm::dvec3& at, const char* text, Paint paint,
              float scale = 2.0f) override;

private:
    Layer layers_[kDrawSpaceCount];
    std::string texts_;
};

}  // namespace gridcull
