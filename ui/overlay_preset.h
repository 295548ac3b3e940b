// Overlay presets: a few named sets of a family's overlay toggles, so that a
// lecturer (or a lesson step) shows one idea at a time instead of every layer
// at once. The names are shared by every family; a family offers the ones that
// mean something for it (ui/family_view.h) and maps each to its own toggles.
#pragma once
#include <cstdint>
#include <string>

namespace gridcull {

enum class OverlayPreset : uint8_t {
    Occlusion,  // what is known to be occluded (matrices, cells, the pyramid, query results)
    Traversal,  // the order and reach of the search (chess layers, nodes visited, tests made)
    Tbvs,       // temporal bounding volumes and what they hold back
    All,        // every layer the family draws
};
constexpr int kOverlayPresetCount = 4;

// For the panel: "occlusion only", "traversal", "TBVs", "all".
const char* overlayPresetTitle(OverlayPreset preset);
// For files and flags: "occlusion", "traversal", "tbvs", "all".
const char* overlayPresetKey(OverlayPreset preset);
// By key; false for a name that is none.
bool parseOverlayPreset(const std::string& key, OverlayPreset& preset);
// The keys, "occlusion, traversal, tbvs, all", for messages.
std::string overlayPresetKeys();

}  // namespace gridcull
