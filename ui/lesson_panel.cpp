#include "ui/lesson_panel.h"

#include <imgui.h>

#include "ui/palette.h"

namespace gridcull {

LessonAction drawLessonPanel(const LessonPlayer& lesson) {
    LessonAction action;
    const LessonStep& step = lesson.step();
    ImGui::TextDisabled("%s", lesson.lesson().title.c_str());
    const Rgb title = swatchColor(Swatch::SkyBlue);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(title.r, title.g, title.b, 1.0f));
    ImGui::TextWrapped("%d. %s", lesson.stepIndex() + 1, step.title.c_str());
    ImGui::PopStyleColor();
    ImGui::TextWrapped("%s", step.caption.c_str());
    ImGui::TextDisabled("%s", step.section.c_str());
    if (!step.animate.flag.empty())
        ImGui::Text("%s %d (counting from %d to %d)", step.animate.flag.c_str(),
                    lesson.animationValue(), step.animate.from, step.animate.to);

    ImGui::BeginDisabled(lesson.stepIndex() == 0);
    if (ImGui::Button("< Previous")) action.go_to = lesson.stepIndex() - 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(lesson.lastStep());
    if (ImGui::Button("Next >")) action.go_to = lesson.stepIndex() + 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    bool auto_play = lesson.autoPlay();
    if (ImGui::Checkbox("auto-play", &auto_play)) action.auto_play = auto_play ? 1 : 0;
    ImGui::SameLine();
    ImGui::TextDisabled("step %d of %d", lesson.stepIndex() + 1, lesson.stepCount());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("PageDown or N: next step, PageUp or P: previous step");
    ImGui::Separator();
    return action;
}

}  // namespace gridcull
