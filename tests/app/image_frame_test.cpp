// Where the culling camera's image, and so each lazy grid cell, lies in the view
// through the culling camera (ui/image_frame.h, ui/lazy_grid/lazy_grid_overlay.h):
// the cells tile the image, the image fills a view of the camera's aspect and is
// centred with bars in any other, and every pixel centre lands where the view
// camera's own projection draws what that pixel sees.
#include "ui/image_frame.h"

#include <cmath>

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "app/view_camera.h"
#include "culling/scene/camera.h"
#include "ui/lazy_grid/lazy_grid_overlay.h"

namespace gridcull {
namespace {

constexpr double kPixelTolerance = 1e-6;  // view pixels
constexpr double kAspect = 16.0 / 9.0;

void expectRect(const ViewRect& r, double x0, double y0, double x1, double y1) {
    EXPECT_NEAR(r.x0, x0, kPixelTolerance);
    EXPECT_NEAR(r.y0, y0, kPixelTolerance);
    EXPECT_NEAR(r.x1, x1, kPixelTolerance);
    EXPECT_NEAR(r.y1, y1, kPixelTolerance);
}

// A 640 x 360 image with 32-pixel cells: 20 x 12 cells, the last row 8 pixels high.
LazyGridSnapshot gridOf(int width, int height, int cell_size) {
    LazyGridSnapshot s;
    s.valid = true;
    s.width = width;
    s.height = height;
    s.cell_size = cell_size;
    s.cells_x = (width + cell_size - 1) / cell_size;
    s.cells_y = (height + cell_size - 1) / cell_size;
    s.cells.resize(size_t(s.cells_x) * size_t(s.cells_y));
    return s;
}

TEST(CameraImageFrame, ViewOfTheCamerasAspectIsCoveredExactly) {
    const LazyGridSnapshot s = gridOf(640, 360, 32);
    const ImageFrame frame = cullingImageFrame(kAspect, 1280, 720, s.width, s.height);
    expectRect(frame.area, 0, 0, 1280, 720);
    // Scale 2 on both axes: cell (cx, cy) is [64 cx, 64 cx + 64) x [64 cy, 64 cy + 64).
    expectRect(lazyCellInView(frame, s, 0, 0), 0, 0, 64, 64);
    expectRect(lazyCellInView(frame, s, 2, 1), 128, 64, 192, 128);
    // The last row holds pixels 352..359 only.
    expectRect(lazyCellInView(frame, s, 19, 11), 1216, 704, 1280, 720);
}

TEST(CameraImageFrame, NarrowerViewHasBarsAboveAndBelow) {
    // The window's scene view beside the panels: 900 x 720.
    const LazyGridSnapshot s = gridOf(640, 360, 32);
    const ImageFrame frame = cullingImageFrame(kAspect, 900, 720, s.width, s.height);
    const double h = 900.0 / kAspect, y = 0.5 * (720.0 - h);
    expectRect(frame.area, 0, y, 900, y + h);
    const double cell_w = 32.0 * 900.0 / 640.0, cell_h = 32.0 * h / 360.0;
    EXPECT_NEAR(cell_w, cell_h, 1e-9) << "square pixels stay square";
    expectRect(lazyCellInView(frame, s, 3, 2), 3 * cell_w, y + 2 * cell_h, 4 * cell_w,
               y + 3 * cell_h);
}

TEST(CameraImageFrame, WiderViewHasBarsLeftAndRight) {
    const LazyGridSnapshot s = gridOf(1024, 576, 32);
    const ImageFrame frame = cullingImageFrame(kAspect, 1600, 600, s.width, s.height);
    const double w = 600.0 * kAspect, x = 0.5 * (1600.0 - w);
    expectRect(frame.area, x, 0, x + w, 600);
    expectRect(lazyCellInView(frame, s, 31, 17), x + 31 * 32 * w / 1024, 17 * 32 * 600.0 / 576,
               x + w, 600);
}

TEST(CameraImageFrame, CellsTileTheImage) {
    // 100 x 70 pixels in cells of 16: the last column 4 pixels wide, the last row 6 high.
    const LazyGridSnapshot s = gridOf(100, 70, 16);
    const ImageFrame frame = cullingImageFrame(100.0 / 70.0, 333, 250, s.width, s.height);
    double area = 0.0;
    for (int cy = 0; cy < s.cells_y; ++cy)
        for (int cx = 0; cx < s.cells_x; ++cx) {
            const ViewRect r = lazyCellInView(frame, s, cx, cy);
            area += (r.x1 - r.x0) * (r.y1 - r.y0);
            if (cx + 1 < s.cells_x) {
                EXPECT_NEAR(r.x1, lazyCellInView(frame, s, cx + 1, cy).x0, kPixelTolerance);
            }
            if (cy + 1 < s.cells_y) {
                EXPECT_NEAR(r.y1, lazyCellInView(frame, s, cx, cy + 1).y0, kPixelTolerance);
            }
        }
    const ViewRect& a = frame.area;
    EXPECT_NEAR(area, (a.x1 - a.x0) * (a.y1 - a.y0), 1e-6);
}

// The frame agrees with what ViewCamera draws: the point a pixel centre of the
// culling camera's image sees projects, through the view's matrices, onto that
// pixel centre's place in the frame, for views wider and narrower than the camera.
TEST(CameraImageFrame, PixelCentresLandWhereTheViewDrawsThem) {
    Camera camera;
    camera.position = {3.0, 1.7, -2.0};
    camera.target = {40.0, 4.0, 30.0};
    camera.fov_deg = 60.0;
    camera.aspect = kAspect;
    camera.near = 0.1;
    camera.far = 400.0;
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    const double tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5), tan_x = tan_y * kAspect;
    const int image_w = 640, image_h = 360;
    ViewCamera view_camera;
    for (const glm::dvec2 view : {glm::dvec2(900, 720), glm::dvec2(1280, 720),
                                  glm::dvec2(1600, 600), glm::dvec2(500, 900)}) {
        const ImageFrame frame = cullingImageFrame(kAspect, view.x, view.y, image_w, image_h);
        const ViewMatrices m =
            view_camera.matrices(ViewMode::CullingCamera, camera, view.x / view.y);
        for (const glm::ivec2 px : {glm::ivec2(0, 0), glm::ivec2(639, 359), glm::ivec2(17, 300),
                                    glm::ivec2(320, 180), glm::ivec2(600, 5)}) {
            // The ray through the pixel centre, as the oracle and the lazy grid cast it.
            const double u = (2.0 * (px.x + 0.5) / image_w - 1.0) * tan_x;
            const double v = (1.0 - 2.0 * (px.y + 0.5) / image_h) * tan_y;
            const glm::dvec3 seen = camera.position + 10.0 * (forward + u * right + v * up);
            const glm::dvec4 clip = m.view_projection * glm::dvec4(seen, 1.0);
            const double x = (clip.x / clip.w + 1.0) * 0.5 * view.x;
            const double y = (1.0 - clip.y / clip.w) * 0.5 * view.y;
            const glm::dvec2 expected = frame.toView(px.x + 0.5, px.y + 0.5);
            EXPECT_NEAR(x, expected.x, 1e-6) << view.x << "x" << view.y << " pixel " << px.x;
            EXPECT_NEAR(y, expected.y, 1e-6) << view.x << "x" << view.y << " pixel " << px.y;
        }
    }
}

}  // namespace
}  // namespace gridcull
