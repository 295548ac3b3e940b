// The scene view's split (ui/scene_panes.h): one pane unless comparing or both
// cameras are asked for; two halves side by side with a gap, covering the view.
#include <gtest/gtest.h>

#include "ui/scene_panes.h"

namespace gridcull {
namespace {

constexpr WindowRect kView{0, 0, 901, 604};

TEST(ScenePanes, OnePaneUnlessComparingOrBothCameras) {
    const ScenePanes one = splitSceneView(kView, ViewMode::Fly, false);
    ASSERT_EQ(one.count, 1);
    EXPECT_EQ(one.pane[0].mode, ViewMode::Fly);
    EXPECT_EQ(one.pane[0].rect.width, kView.width);
}

TEST(ScenePanes, BothCamerasSplitTheViewObserverLeft) {
    const ScenePanes two = splitSceneView(kView, ViewMode::Cameras, false);
    ASSERT_EQ(two.count, 2);
    EXPECT_EQ(two.pane[0].mode, ViewMode::Overview);
    EXPECT_EQ(two.pane[1].mode, ViewMode::CullingCamera);
    EXPECT_FALSE(two.pane[0].compared || two.pane[1].compared);
    EXPECT_EQ(two.pane[0].rect.x, kView.x);
    EXPECT_EQ(two.pane[1].rect.x + two.pane[1].rect.width, kView.x + kView.width);
    EXPECT_EQ(two.pane[1].rect.x - (two.pane[0].rect.x + two.pane[0].rect.width), kPaneGap);
    EXPECT_EQ(two.pane[0].rect.height, kView.height);
}

TEST(ScenePanes, ComparingBothPanesLookTheSameWayBOnTheRight) {
    ScenePanes ab = splitSceneView(kView, ViewMode::Overview, true);
    ASSERT_EQ(ab.count, 2);
    EXPECT_EQ(ab.pane[0].mode, ViewMode::Overview);
    EXPECT_EQ(ab.pane[1].mode, ViewMode::Overview);
    EXPECT_FALSE(ab.pane[0].compared);
    EXPECT_TRUE(ab.pane[1].compared);
    ab = splitSceneView(kView, ViewMode::Cameras, true);
    EXPECT_EQ(ab.pane[0].mode, ViewMode::CullingCamera);
    EXPECT_EQ(ab.pane[1].mode, ViewMode::CullingCamera);
}

}  // namespace
}  // namespace gridcull
