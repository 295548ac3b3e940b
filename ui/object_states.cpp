#include "ui/object_states.h"

#include <algorithm>

namespace gridcull {

void classifyObjects(const Scene& scene, const std::vector<int>& pvs, const FrameResult& exact,
                     std::vector<ObjectState>& states, std::vector<int>& false_culled) {
    states.assign(scene.objects.size(), ObjectState::Culled);
    for (int id : pvs) {
        const int index = scene.indexOf(id);
        if (index >= 0) states[size_t(index)] = ObjectState::Hidden;
    }
    // Seen by the oracle: visible when the culler kept it, a false cull when not.
    false_culled.clear();
    for (int id : exact.pvs) {
        const int index = scene.indexOf(id);
        if (index < 0) continue;
        ObjectState& state = states[size_t(index)];
        if (state == ObjectState::Hidden) {
            state = ObjectState::Visible;
        } else if (state == ObjectState::Culled) {
            state = ObjectState::FalseCulled;
            false_culled.push_back(id);
        }
    }
    std::sort(false_culled.begin(), false_culled.end());
    for (const std::vector<int>* list : {&exact.sub_sample_visible, &exact.sub_sample_undecided}) {
        for (int id : *list) {
            const int index = scene.indexOf(id);
            if (index >= 0 && states[size_t(index)] == ObjectState::Culled)
                states[size_t(index)] = ObjectState::SubSample;
        }
    }
}

}  // namespace gridcull
