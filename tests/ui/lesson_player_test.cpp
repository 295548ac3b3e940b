// The lesson player (ui/lesson_player.h): steps clamp, an animation counts one
// value per period whether auto-play is on or not, auto-play moves on after a
// step's seconds and stops at the last step.
#include <gtest/gtest.h>

#include "ui/lesson_player.h"

namespace gridcull {
namespace {

Lesson threeSteps() {
    Lesson lesson;
    lesson.steps.resize(3);
    lesson.steps[1].animate = {"rgvc-layer", 2, 5, 0.5};
    for (LessonStep& step : lesson.steps) step.seconds = 4.0;
    return lesson;
}

TEST(LessonPlayer, StepsClampAndRestartTheirAnimation) {
    LessonPlayer player;
    player.start(threeSteps());
    EXPECT_EQ(player.stepIndex(), 0);
    EXPECT_FALSE(player.go(-3));
    EXPECT_TRUE(player.go(1));
    EXPECT_EQ(player.animationValue(), 2);
    EXPECT_TRUE(player.animating());
    player.finishAnimation();
    EXPECT_EQ(player.animationValue(), 5);
    EXPECT_FALSE(player.animating());
    EXPECT_TRUE(player.go(9));
    EXPECT_EQ(player.stepIndex(), 2);
    EXPECT_TRUE(player.lastStep());
}

TEST(LessonPlayer, AnAnimationCountsOneValuePerPeriodWithoutAutoPlay) {
    LessonPlayer player;
    player.start(threeSteps());
    player.go(1);
    EXPECT_FALSE(player.advance(0.4).animation_changed);
    EXPECT_TRUE(player.advance(0.2).animation_changed);
    EXPECT_EQ(player.animationValue(), 3);
    // A slow frame skips values, never past the last.
    player.advance(10.0);
    EXPECT_EQ(player.animationValue(), 5);
    // Without auto-play the step stays.
    EXPECT_FALSE(player.advance(100.0).step_changed);
    EXPECT_EQ(player.stepIndex(), 1);
}

TEST(LessonPlayer, AutoPlayMovesOnAfterTheStepsSecondsAndStopsAtTheEnd) {
    LessonPlayer player;
    player.start(threeSteps());
    player.setAutoPlay(true);
    EXPECT_FALSE(player.advance(3.9).step_changed);
    EXPECT_TRUE(player.advance(0.2).step_changed);
    EXPECT_EQ(player.stepIndex(), 1);
    // Step 1 animates first (3 values, 1.5 s), then holds for its 4 s.
    player.advance(0.5);
    player.advance(0.5);
    player.advance(0.5);
    EXPECT_EQ(player.animationValue(), 5);
    EXPECT_FALSE(player.advance(3.9).step_changed);
    EXPECT_TRUE(player.advance(0.2).step_changed);
    EXPECT_EQ(player.stepIndex(), 2);
    EXPECT_FALSE(player.advance(5.0).step_changed);
    EXPECT_FALSE(player.autoPlay());
}

}  // namespace
}  // namespace gridcull
