// The Debugger playing a lesson (ui/lesson_player.h): each step sets the scene,
// the cullers, the frame, the view, the overlay preset and the family's view
// flags, in that order, all in the foreground so that a step always shows the
// same picture.
#include "app/debugger.h"

namespace gridcull {

void Debugger::startLesson(Lesson lesson) {
    lesson_.start(std::move(lesson));
    showLessonStep();
}

void Debugger::goToLessonStep(int index, bool finished) {
    if (!lesson_.active()) return;
    lesson_.go(index);
    if (finished) lesson_.finishAnimation();
    showLessonStep();
}

void Debugger::setLessonAutoPlay(bool on) {
    if (lesson_.active()) lesson_.setAutoPlay(on);
}

void Debugger::showLessonStep() {
    const LessonStep& step = lesson_.step();
    playing_ = false;
    session_.cancelSeek();
    if (step.scene != session_.sceneFile()) openSceneFile(step.scene);
    if (step.algo != session_.algo()) {
        // From frame 0, so the new culler does not re-run up to the old frame.
        session_.seek(0);
        selectAlgorithm(step.algo);
    }
    session_.seek(step.frame);
    const std::string compared = compare_ ? compare_->algo() : "";
    std::string error;
    if (step.compare != compared && !setCompare(step.compare, error)) scene_errors_ = {error};
    syncCompare(true);
    setViewMode(step.view);
    if (step.has_overlays) applyOverlayPreset(step.overlays);
    applyLessonFlags();
}

void Debugger::applyLessonFlags() {
    const LessonStep& step = lesson_.step();
    KnobValues flags = step.flags;
    if (!step.animate.flag.empty()) flags.set(step.animate.flag, lesson_.animationValue());
    std::string error;
    // The step's culler's family view takes them: the lesson file's check made
    // sure they are that family's.
    if (family_view_ && !family_view_->applyFlags(flags, session_.scene(), error))
        scene_errors_ = {error};
}

}  // namespace gridcull
