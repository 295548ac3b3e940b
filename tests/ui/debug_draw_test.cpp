// The debug-draw interface's helpers and its batch (ui/debug_draw.h): what each
// helper emits, the batch's fixed draw order (per space: fills in emission
// order, then lines by width, thinnest first) and its reuse of memory.
#include "ui/debug_draw.h"

#include <cmath>

#include <gtest/gtest.h>

namespace gridcull {
namespace {

constexpr double kTolerance = 1e-6;  // float vertices of small coordinates

const Paint kWhite{Swatch::White};

double segmentLength(const DebugDrawBatch::Vertex& a, const DebugDrawBatch::Vertex& b) {
    return std::hypot(double(b.position.x - a.position.x), double(b.position.y - a.position.y));
}

const DebugDrawBatch::LineSet* linesOfWidth(const DebugDrawBatch& batch, DrawSpace space,
                                            float width) {
    for (const DebugDrawBatch::LineSet& set : batch.layer(space).lines)
        if (set.width == width) return &set;
    return nullptr;
}

TEST(DebugDraw, RectanglesAreTwoTrianglesAndFourSides) {
    DebugDrawBatch batch;
    batch.fillRect(DrawSpace::View, 10, 20, 30, 60, {Swatch::Orange, 0.5f});
    const std::vector<DebugDrawBatch::Vertex>& fill = batch.layer(DrawSpace::View).fill;
    ASSERT_EQ(fill.size(), 6u);
    double area = 0.0;
    for (size_t k = 0; k < 6; k += 3) {
        const glm::vec3 a = fill[k].position, b = fill[k + 1].position, c = fill[k + 2].position;
        area += 0.5 * std::abs(double((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
    }
    EXPECT_NEAR(area, 20.0 * 40.0, kTolerance);
    const Rgb orange = swatchColor(Swatch::Orange);
    EXPECT_EQ(fill[0].color, glm::vec4(orange.r, orange.g, orange.b, 0.5f));
    EXPECT_TRUE(batch.layer(DrawSpace::World).fill.empty());

    batch.outlineRect(DrawSpace::World, 0, 0, 4, 3, kWhite, kBoldLine);
    const DebugDrawBatch::LineSet* outline = linesOfWidth(batch, DrawSpace::World, kBoldLine);
    ASSERT_NE(outline, nullptr);
    ASSERT_EQ(outline->vertices.size(), 8u);
    double perimeter = 0.0;
    for (size_t k = 0; k < 8; k += 2)
        perimeter += segmentLength(outline->vertices[k], outline->vertices[k + 1]);
    EXPECT_NEAR(perimeter, 14.0, kTolerance);
}

TEST(DebugDraw, DashesCoverTheirShareOfEachSide) {
    DebugDrawBatch batch;
    // Sides of 18 and 9: dashes of 5 with gaps of 4 cover 5 + 5 of 18 (the last
    // dash cut at the corner: 0-5, 9-14) and 5 of 9 (0-5).
    batch.dashedRect(DrawSpace::View, 0, 0, 18, 9, kWhite, kHairline, 5.0, 4.0);
    const DebugDrawBatch::LineSet* dashes = linesOfWidth(batch, DrawSpace::View, kHairline);
    ASSERT_NE(dashes, nullptr);
    double drawn = 0.0;
    for (size_t k = 0; k < dashes->vertices.size(); k += 2)
        drawn += segmentLength(dashes->vertices[k], dashes->vertices[k + 1]);
    EXPECT_NEAR(drawn, 2 * 10.0 + 2 * 5.0, kTolerance);
}

TEST(DebugDraw, HatchLinesStayInsideTheRectangle) {
    DebugDrawBatch batch;
    batch.hatchRect(DrawSpace::View, 100, 50, 130, 70, kWhite, kHairline, 7.0);
    const DebugDrawBatch::LineSet* hatch = linesOfWidth(batch, DrawSpace::View, kHairline);
    ASSERT_NE(hatch, nullptr);
    // x + y = 150 + d for d = 7, 14, ... below 30 + 20: seven lines.
    EXPECT_EQ(hatch->vertices.size(), 2u * 7u);
    for (const DebugDrawBatch::Vertex& v : hatch->vertices) {
        EXPECT_GE(v.position.x, 100.0f - 1e-4f);
        EXPECT_LE(v.position.x, 130.0f + 1e-4f);
        EXPECT_GE(v.position.y, 50.0f - 1e-4f);
        EXPECT_LE(v.position.y, 70.0f + 1e-4f);
    }
}

TEST(DebugDraw, PolygonsAndPolylines) {
    DebugDrawBatch batch;
    const glm::dvec3 square[4] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    batch.fillConvexPolygon(DrawSpace::World, square, 4, kWhite);
    EXPECT_EQ(batch.layer(DrawSpace::World).fill.size(), 6u);  // a fan of two triangles
    batch.polyline(DrawSpace::World, square, 4, kWhite, kFineLine);
    EXPECT_EQ(linesOfWidth(batch, DrawSpace::World, kFineLine)->vertices.size(), 6u);
    batch.outlinePolygon(DrawSpace::World, square, 4, kWhite, kHeavyLine);
    EXPECT_EQ(linesOfWidth(batch, DrawSpace::World, kHeavyLine)->vertices.size(), 8u);
}

TEST(DebugDraw, AVoxelIsItsWorldSquare) {
    RegularGrid grid;
    grid.dimensions = 2;
    grid.world = {{10, 20, 0}, {30, 40, 0}};
    grid.resolution = {4, 2, 1};  // voxels of 5 x 10
    DebugDrawBatch batch;
    batch.fillVoxel(grid, 2, 1, kWhite);
    const std::vector<DebugDrawBatch::Vertex>& fill = batch.layer(DrawSpace::World).fill;
    ASSERT_EQ(fill.size(), 6u);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const DebugDrawBatch::Vertex& v : fill) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    EXPECT_EQ(lo, glm::vec3(20, 30, 0));
    EXPECT_EQ(hi, glm::vec3(25, 40, 0));
}

// Whatever the emission order, lines come thinnest first, each width in the
// order it was emitted; labels keep their text; clearing keeps the memory.
TEST(DebugDrawBatch, DrawOrderIsFixedAndClearingKeepsCapacity) {
    DebugDrawBatch batch;
    batch.line(DrawSpace::View, {0, 0, 0}, {1, 0, 0}, kWhite, kHeavyLine);
    batch.line(DrawSpace::View, {0, 1, 0}, {1, 1, 0}, kWhite, kHairline);
    batch.line(DrawSpace::View, {0, 2, 0}, {1, 2, 0}, kWhite, kHeavyLine);
    batch.line(DrawSpace::View, {0, 3, 0}, {1, 3, 0}, kWhite, kBoldLine);
    batch.text(DrawSpace::World, {5, 6, 7}, "#12", {Swatch::Yellow}, 3.0f);
    const std::vector<DebugDrawBatch::LineSet>& sets = batch.layer(DrawSpace::View).lines;
    ASSERT_EQ(sets.size(), 3u);
    EXPECT_EQ(sets[0].width, kHairline);
    EXPECT_EQ(sets[1].width, kBoldLine);
    EXPECT_EQ(sets[2].width, kHeavyLine);
    ASSERT_EQ(sets[2].vertices.size(), 4u);
    EXPECT_EQ(sets[2].vertices[0].position.y, 0.0f);  // emission order within a width
    EXPECT_EQ(sets[2].vertices[2].position.y, 2.0f);
    const std::vector<DebugDrawBatch::Label>& labels = batch.layer(DrawSpace::World).labels;
    ASSERT_EQ(labels.size(), 1u);
    EXPECT_EQ(batch.labelText(labels[0]), "#12");
    EXPECT_EQ(labels[0].scale, 3.0f);
    EXPECT_FALSE(batch.empty());

    const size_t capacity = sets[2].vertices.capacity();
    batch.clear();
    EXPECT_TRUE(batch.empty());
    ASSERT_EQ(batch.layer(DrawSpace::View).lines.size(), 3u) << "widths are kept for next time";
    EXPECT_EQ(batch.layer(DrawSpace::View).lines[2].vertices.capacity(), capacity);
}

}  // namespace
}  // namespace gridcull
