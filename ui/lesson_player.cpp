#include "ui/lesson_player.h"

#include <algorithm>
#include <cassert>

namespace gridcull {

void LessonPlayer::start(Lesson lesson) {
    assert(!lesson.steps.empty());
    lesson_ = std::move(lesson);
    active_ = true;
    auto_play_ = false;
    step_ = -1;
    go(0);
}

bool LessonPlayer::go(int index) {
    index = std::clamp(index, 0, stepCount() - 1);
    const bool changed = index != step_;
    step_ = index;
    animation_value_ = step().animate.from;
    clock_ = 0.0;
    return changed;
}

void LessonPlayer::finishAnimation() { animation_value_ = step().animate.to; }

bool LessonPlayer::animating() const {
    return !step().animate.flag.empty() && animation_value_ < step().animate.to;
}

void LessonPlayer::setAutoPlay(bool on) {
    auto_play_ = on;
    clock_ = 0.0;
}

LessonPlayer::Tick LessonPlayer::advance(double seconds) {
    Tick tick;
    if (!active_) return tick;
    clock_ += std::max(seconds, 0.0);
    if (animating()) {
        const double per_value = step().animate.seconds_per_value;
        // A slow frame may skip values, never the last one.
        while (animating() && clock_ >= per_value) {
            clock_ -= per_value;
            ++animation_value_;
            tick.animation_changed = true;
        }
        return tick;
    }
    if (!auto_play_ || clock_ < step().seconds) return tick;
    if (lastStep()) {
        auto_play_ = false;
        return tick;
    }
    tick.step_changed = go(step_ + 1);
    return tick;
}

}  // namespace gridcull
