#include "app/app_cullers.h"

#include "app/gl_context.h"
#include "app/gl_image_target.h"
#include "culling/registry/registry.h"

namespace gridcull {

namespace {

// The registry algorithm of a -gl name, or "".
std::string glBaseOf(std::string_view name) {
    if (name.size() <= kGlSuffix.size() || name.substr(name.size() - kGlSuffix.size()) != kGlSuffix)
        return "";
    const std::string base(name.substr(0, name.size() - kGlSuffix.size()));
    const FamilyEntry* family = familyOfAlgorithm(base);
    return family && family->draws_image ? base : "";
}

}  // namespace

std::vector<std::string> appAlgorithmNames() {
    std::vector<std::string> names = algorithmNames();
    for (const FamilyEntry& family : families())
        if (family.draws_image)
            for (const AlgorithmEntry& a : family.algorithms)
                names.push_back(a.name + std::string(kGlSuffix));
    return names;
}

std::string registryAlgorithmOf(std::string_view name) {
    if (familyOfAlgorithm(name)) return std::string(name);
    return glBaseOf(name);
}

std::unique_ptr<Culler> makeAppCuller(std::string_view name, const KnobValues& knobs,
                                      std::string& error) {
    const std::string base = glBaseOf(name);
    if (base.empty()) return makeCuller(name, knobs, error);
    if (!ensureHiddenGlContext(error)) {
        error = "the -gl algorithms need an OpenGL context: " + error;
        return nullptr;
    }
    auto target = std::make_unique<GlImageTarget>();
    if (!target->init(error)) return nullptr;
    return makeCuller(base, knobs, error, std::move(target), std::string(name));
}

}  // namespace gridcull
