// The registry's table. Adding a family: one line in builtInFamilies() below.
#include "culling/registry/registry.h"

#include "culling/baseline/baseline_family.h"
#include "culling/bsp_oq/bsp_oq_family.h"
#include "culling/hzb_tbv/hzb_tbv_family.h"
#include "culling/lazy_grid/lazy_grid_family.h"
#include "culling/oracle/oracle_family.h"
#include "culling/rgvc/rgvc_family.h"

namespace gridcull {

namespace {

std::vector<FamilyEntry> builtInFamilies() {
    return {baselineFamily(), oracleFamily(), rgvcFamily(), lazyGridFamily(), hzbTbvFamily(),
            bspOqFamily()};
}

// The window starts with regular-grid culling: it runs on 2D and 3D scenes and
// shows the most (its matrices, traversal and occluders). View-frustum culling
// runs on every scene.
const std::string kDefaultAlgorithm = "rgvc";
const std::string kLastResortAlgorithm = "vfc";

struct Table {
    std::vector<FamilyEntry> families = builtInFamilies();
    size_t built_in = families.size();
};

Table& table() {
    static Table t;
    return t;
}

bool fitsDimension(const AlgorithmEntry& algorithm, int dimensions) {
    if (dimensions == 2) return (algorithm.dimensions & kRuns2d) != 0;
    if (dimensions == 3) return (algorithm.dimensions & kRuns3d) != 0;
    return true;
}

}  // namespace

const std::vector<FamilyEntry>& families() {
    return table().families;
}

bool registerFamily(FamilyEntry entry, std::string& error) {
    const std::string family = "family '" + entry.id + "': ";
    if (entry.id.empty() || entry.algorithms.empty() || !entry.make) {
        error = family + "needs an id, at least one algorithm and a factory";
        return false;
    }
    if (findFamily(entry.id)) {
        error = "a family '" + entry.id + "' is registered already";
        return false;
    }
    for (size_t i = 0; i < entry.algorithms.size(); ++i) {
        const AlgorithmEntry& a = entry.algorithms[i];
        bool repeated = false;
        for (size_t j = 0; j < i; ++j) repeated = repeated || entry.algorithms[j].name == a.name;
        if (a.name.empty() || repeated || familyOfAlgorithm(a.name)) {
            error = family + "the algorithm name '" + a.name + "' is taken";
            return false;
        }
        if (a.name.size() > 3 && a.name.compare(a.name.size() - 3, 3, "-gl") == 0) {
            error = family + "'" + a.name + "': names ending in -gl are the OpenGL variants'";
            return false;
        }
        if ((a.dimensions & kRunsBoth) == 0 || (a.dimensions & ~kRunsBoth) != 0) {
            error = family + "'" + a.name + "' must run on 2D or 3D scenes or both";
            return false;
        }
    }
    // A knob's flag starts with the family's prefix, so that no two families'
    // knobs, nor a knob and a command's own option, ever share a name.
    const std::string prefix = entry.id.substr(0, entry.id.find('-')) + "-";
    for (size_t i = 0; i < entry.knobs.size(); ++i) {
        const Knob& k = entry.knobs[i];
        bool repeated = false;
        for (size_t j = 0; j < i; ++j) repeated = repeated || entry.knobs[j].flag == k.flag;
        if (k.flag.compare(0, prefix.size(), prefix) != 0 || k.flag.size() == prefix.size()) {
            error = family + "the knob --" + k.flag + " must start with '" + prefix + "'";
            return false;
        }
        if (repeated || findKnob(k.flag)) {
            error = family + "the knob --" + k.flag + " is taken";
            return false;
        }
    }
    table().families.push_back(std::move(entry));
    return true;
}

void unregisterFamily(const std::string& id) {
    Table& t = table();
    for (size_t i = t.built_in; i < t.families.size(); ++i)
        if (t.families[i].id == id) {
            t.families.erase(t.families.begin() + std::ptrdiff_t(i));
            return;
        }
}

const FamilyEntry* findFamily(std::string_view id) {
    for (const FamilyEntry& f : families())
        if (f.id == id) return &f;
    return nullptr;
}

const FamilyEntry* familyOfAlgorithm(std::string_view name, const AlgorithmEntry** algorithm) {
    for (const FamilyEntry& f : families())
        for (const AlgorithmEntry& a : f.algorithms)
            if (a.name == name) {
                if (algorithm) *algorithm = &a;
                return &f;
            }
    return nullptr;
}

std::vector<std::string> algorithmNames(int dimensions) {
    std::vector<std::string> names;
    for (const FamilyEntry& f : families())
        for (const AlgorithmEntry& a : f.algorithms)
            if (fitsDimension(a, dimensions)) names.push_back(a.name);
    return names;
}

std::string algorithmList(int dimensions) {
    std::string list;
    for (const std::string& name : algorithmNames(dimensions))
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

bool algorithmFits(std::string_view name, const Scene& scene, std::string& why) {
    const AlgorithmEntry* algorithm = nullptr;
    if (!familyOfAlgorithm(name, &algorithm)) {
        why = "unknown algorithm '" + std::string(name) + "', expected one of: " + algorithmList();
        return false;
    }
    if (fitsDimension(*algorithm, scene.dimensions)) return true;
    const int other = scene.dimensions == 2 ? 3 : 2;
    why = std::string(name) + " runs on " + std::to_string(other) +
          "D scenes only, and this scene is " + std::to_string(scene.dimensions) +
          "D; algorithms for it: " + algorithmList(scene.dimensions);
    return false;
}

std::vector<const Knob*> allKnobs() {
    std::vector<const Knob*> knobs;
    for (const FamilyEntry& f : families())
        for (const Knob& k : f.knobs) knobs.push_back(&k);
    return knobs;
}

const Knob* findKnob(std::string_view flag) {
    const FamilyEntry* family = familyOfKnob(flag);
    if (!family) return nullptr;
    for (const Knob& k : family->knobs)
        if (k.flag == flag) return &k;
    return nullptr;
}

const FamilyEntry* familyOfKnob(std::string_view flag) {
    for (const FamilyEntry& f : families())
        for (const Knob& k : f.knobs)
            if (k.flag == flag) return &f;
    return nullptr;
}

const std::string& referenceAlgorithm() {
    for (const FamilyEntry& f : families())
        if (f.reference) return f.algorithms.front().name;
    static const std::string none;
    return none;
}

const std::string& defaultAlgorithm() {
    return kDefaultAlgorithm;
}

const std::string& lastResortAlgorithm() {
    return kLastResortAlgorithm;
}

int referenceResolution(const KnobValues& knobs) {
    return oracleOptions(knobs).resolution;
}

std::unique_ptr<Culler> makeCuller(std::string_view name, const KnobValues& knobs,
                                   std::string& error, std::unique_ptr<ImageTarget> target,
                                   const std::string& display_name) {
    const FamilyEntry* family = familyOfAlgorithm(name);
    if (!family) {
        error =
            "unknown algorithm '" + std::string(name) + "', expected one of: " + algorithmList();
        return nullptr;
    }
    if (target && !family->draws_image) {
        error = std::string(name) + " draws no image, so it takes no image target";
        return nullptr;
    }
    CullerRequest request;
    request.algorithm = std::string(name);
    request.name = display_name.empty() ? request.algorithm : display_name;
    request.knobs = &knobs;
    request.reference_resolution = referenceResolution(knobs);
    request.target = std::move(target);
    std::unique_ptr<Culler> culler = family->make(request);
    if (!culler) error = "family '" + family->id + "' made no culler for " + std::string(name);
    return culler;
}

}  // namespace gridcull
