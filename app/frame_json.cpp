#include "app/frame_json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gridcull {

namespace {

void appendNumber(std::string& out, double v) {
    char buf[32];
    if (!std::isfinite(v)) {
        out += "null";  // JSON has no NaN or infinity; never expected, never invalid JSON
        return;
    }
    // %.17g always reads back exactly; try shorter forms first for readability.
    for (int precision = 6; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    out += buf;
}

void appendVector(std::string& out, const glm::dvec3& v, int dimensions) {
    out += '[';
    for (int i = 0; i < dimensions; ++i) {
        if (i) out += ", ";
        appendNumber(out, v[i]);
    }
    out += ']';
}

// , "name": [ids]
void appendIds(std::string& out, const char* name, const std::vector<int>& ids) {
    out += ", \"";
    out += name;
    out += "\": [";
    for (size_t i = 0; i < ids.size(); ++i) {
        if (i) out += ", ";
        out += std::to_string(ids[i]);
    }
    out += ']';
}

}  // namespace

void appendFrameJson(std::string& line, int frame, double t, const char* algo,
                     const Camera& camera, const FrameResult& result) {
    line += "{\"frame\": ";
    line += std::to_string(frame);
    line += ", \"t\": ";
    appendNumber(line, t);
    line += ", \"algo\": \"";
    line += algo;  // algorithm names are plain identifiers: nothing to escape
    line += "\", \"camera\": {\"position\": ";
    appendVector(line, camera.position, camera.dimensions);
    line += ", \"target\": ";
    appendVector(line, camera.target, camera.dimensions);
    line += "}, \"pvs\": [";
    for (size_t i = 0; i < result.pvs.size(); ++i) {
        if (i) line += ", ";
        line += std::to_string(result.pvs[i]);
    }
    line += "]";
    // The oracle's sub-sample objects (their counts are among its counters).
    if (result.stats.has(Counter::SubSampleUndecided)) {
        appendIds(line, "sub_sample_visible", result.sub_sample_visible);
        appendIds(line, "sub_sample_undecided", result.sub_sample_undecided);
    }
    line += ", \"stats\": {\"cull_ms\": ";
    appendNumber(line, result.stats.cull_ms);
    for (int c = 0; c < kCounterCount; ++c) {
        if (!result.stats.has(Counter(c))) continue;
        line += ", \"";
        line += counterName(Counter(c));
        line += "\": ";
        line += std::to_string(result.stats.get(Counter(c)));
    }
    line += "}}\n";
}

}  // namespace gridcull
