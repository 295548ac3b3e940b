// The lesson panel, at the top of the column while a lesson plays: the step's
// title and caption (the paper's section under them), where the step stands in
// the lesson, the animated flag's value, and Previous / Next / Auto-play
// (PageUp / PageDown, as a presentation clicker sends, and P / N do the same).
#pragma once
#include "ui/lesson_player.h"

namespace gridcull {

struct LessonAction {
    int go_to = -1;         // >= 0: show this step
    int auto_play = -1;     // 0 or 1: turn auto-play off or on
};

// Draws into the current ImGui window. Cost: a few widgets.
LessonAction drawLessonPanel(const LessonPlayer& lesson);

}  // namespace gridcull
