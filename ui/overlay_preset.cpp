#include "ui/overlay_preset.h"

namespace gridcull {

const char* overlayPresetTitle(OverlayPreset preset) {
    switch (preset) {
        case OverlayPreset::Occlusion:
            return "occlusion only";
        case OverlayPreset::Traversal:
            return "traversal";
        case OverlayPreset::Tbvs:
            return "TBVs";
        case OverlayPreset::All:
            return "all";
    }
    return "";
}

const char* overlayPresetKey(OverlayPreset preset) {
    switch (preset) {
        case OverlayPreset::Occlusion:
            return "occlusion";
        case OverlayPreset::Traversal:
            return "traversal";
        case OverlayPreset::Tbvs:
            return "tbvs";
        case OverlayPreset::All:
            return "all";
    }
    return "";
}

bool parseOverlayPreset(const std::string& key, OverlayPreset& preset) {
    for (int p = 0; p < kOverlayPresetCount; ++p) {
        if (key == overlayPresetKey(OverlayPreset(p))) {
            preset = OverlayPreset(p);
            return true;
        }
    }
    return false;
}

std::string overlayPresetKeys() {
    std::string keys;
    for (int p = 0; p < kOverlayPresetCount; ++p) {
        if (p > 0) keys += ", ";
        keys += overlayPresetKey(OverlayPreset(p));
    }
    return keys;
}

}  // namespace gridcull
