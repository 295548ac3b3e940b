// Where a lesson (ui/lesson.h) stands while it plays: the step shown, the value
// its animation has reached, and auto-play's clock. Pure state: the window
// applies what it reports (app/debugger_lesson.cpp), and the lesson panel
// (ui/lesson_panel.h) shows it.
//
// On entering a step its animation (if any) starts at `from` and counts up one
// value per seconds_per_value to `to`, auto-play or not, so that a lecturer who
// clicks Next sees the chess layers build up. With auto-play on, the step then
// stays for its `seconds` and the next one follows; at the last step auto-play
// stops.
#pragma once
#include "ui/lesson.h"

namespace gridcull {

class LessonPlayer {
public:
    // Starts `lesson` (at least one step) at its first step, auto-play off.
    void start(Lesson lesson);
    void stop() { active_ = false; }
    bool active() const { return active_; }
    const Lesson& lesson() const { return lesson_; }
    int stepIndex() const { return step_; }
    int stepCount() const { return int(lesson_.steps.size()); }
    const LessonStep& step() const { return lesson_.steps[size_t(step_)]; }
    bool lastStep() const { return step_ + 1 >= stepCount(); }

    // Shows step `index`, clamped to the steps; its animation starts over.
    // True when the step changed.
    bool go(int index);
    // Ends the current step's animation (shots show a step as it ends).
    void finishAnimation();

    bool autoPlay() const { return auto_play_; }
    void setAutoPlay(bool on);

    // The animated flag's value now; meaningless when step().animate.flag is "".
    int animationValue() const { return animation_value_; }
    bool animating() const;

    struct Tick {
        bool step_changed = false;       // go() moved to another step
        bool animation_changed = false;  // animationValue() counted up
    };
    // Wall time goes by: the animation counts, auto-play moves on.
    Tick advance(double seconds);

private:
    Lesson lesson_;
    bool active_ = false;
    int step_ = 0;
    bool auto_play_ = false;
    int animation_value_ = 0;
    double clock_ = 0.0;  // seconds since the last change of step or value
};

}  // namespace gridcull
