#include "culling/api/knobs.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace gridcull {

namespace {

std::string numberText(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.15g", v);
    return text;
}

}  // namespace

std::string knobRangeText(const Knob& knob) {
    return "from " + numberText(knob.min) + " to " + numberText(knob.max);
}

std::string knobValueText(const Knob& knob, double value) {
    if (!knob.automatic.empty() && value == knob.default_value) return knob.automatic;
    return numberText(value);
}

std::string knobDefaultText(const Knob& knob) {
    return knob.automatic.empty() ? numberText(knob.default_value) : knob.automatic_meaning;
}

bool parseKnobValue(const Knob& knob, const std::string& text, double& value, std::string& error) {
    const bool integer = knob.kind == KnobKind::Integer;
    bool ok = !text.empty();
    double v = 0.0;
    if (ok) {
        char* end = nullptr;
        errno = 0;
        if (integer) {
            const long long parsed = std::strtoll(text.c_str(), &end, 10);
            v = double(parsed);
        } else {
            v = std::strtod(text.c_str(), &end);
        }
        ok = *end == '\0' && errno != ERANGE && std::isfinite(v) && v >= knob.min && v <= knob.max;
    }
    if (!ok) {
        error = "option --" + knob.flag + ": expected " + (integer ? "an integer " : "a number ") +
                knobRangeText(knob) + ", got '" + text + "'";
        return false;
    }
    value = v;
    return true;
}

}  // namespace gridcull
