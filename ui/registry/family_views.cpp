// The ui registry's table. Adding a family's view: one line in builtInViews().
#include "ui/registry/family_views.h"

#include "culling/registry/registry.h"
#include "ui/bsp_oq/bsp_oq_family_view.h"
#include "ui/hzb_tbv/hzb_tbv_family_view.h"
#include "ui/lazy_grid/lazy_grid_family_view.h"
#include "ui/rgvc/rgvc_family_view.h"

namespace gridcull {

namespace {

std::vector<FamilyViewEntry> builtInViews() {
    return {rgvcFamilyView(), lazyGridFamilyView(), hzbTbvFamilyView(), bspOqFamilyView()};
}

struct Table {
    std::vector<FamilyViewEntry> views = builtInViews();
    size_t built_in = views.size();
};

Table& table() {
    static Table t;
    return t;
}

}  // namespace

const std::vector<FamilyViewEntry>& familyViews() {
    return table().views;
}

const FamilyViewEntry* findFamilyView(std::string_view family) {
    for (const FamilyViewEntry& v : familyViews())
        if (v.family == family) return &v;
    return nullptr;
}

const FamilyViewEntry* familyViewOfAlgorithm(std::string_view algorithm) {
    const FamilyEntry* family = familyOfAlgorithm(algorithm);
    return family ? findFamilyView(family->id) : nullptr;
}

bool registerFamilyView(FamilyViewEntry entry, std::string& error) {
    if (findFamilyView(entry.family)) {
        error = "family '" + entry.family + "' has a view already";
        return false;
    }
    if (!findFamily(entry.family)) {
        error = "no family '" + entry.family + "' in the culling registry";
        return false;
    }
    if (!entry.make) {
        error = "the view of family '" + entry.family + "' needs a factory";
        return false;
    }
    // Like knobs, view flags start with the family's prefix and are unique.
    const std::string prefix = entry.family.substr(0, entry.family.find('-')) + "-";
    for (size_t i = 0; i < entry.flags.size(); ++i) {
        const std::string& flag = entry.flags[i].flag;
        bool repeated = false;
        for (size_t j = 0; j < i; ++j) repeated = repeated || entry.flags[j].flag == flag;
        if (flag.compare(0, prefix.size(), prefix) != 0 || flag.size() == prefix.size()) {
            error = "the view flag --" + flag + " must start with '" + prefix + "'";
            return false;
        }
        if (repeated || findViewFlag(flag) || findKnob(flag)) {
            error = "the flag --" + flag + " is taken";
            return false;
        }
    }
    table().views.push_back(std::move(entry));
    return true;
}

void unregisterFamilyView(const std::string& family) {
    Table& t = table();
    for (size_t i = t.built_in; i < t.views.size(); ++i)
        if (t.views[i].family == family) {
            t.views.erase(t.views.begin() + std::ptrdiff_t(i));
            return;
        }
}

bool checkViewFlags(const KnobValues& flags, const Scene& scene, std::string& error) {
    for (const FamilyViewEntry& entry : familyViews()) {
        bool given = false;
        for (const Knob& flag : entry.flags) given = given || flags.has(flag.flag);
        if (given && !entry.make()->applyFlags(flags, scene, error)) return false;
    }
    return true;
}

std::vector<const Knob*> allViewFlags() {
    std::vector<const Knob*> flags;
    for (const FamilyViewEntry& v : familyViews())
        for (const Knob& f : v.flags) flags.push_back(&f);
    return flags;
}

const Knob* findViewFlag(std::string_view flag) {
    for (const FamilyViewEntry& v : familyViews())
        for (const Knob& f : v.flags)
            if (f.flag == flag) return &f;
    return nullptr;
}

const FamilyViewEntry* familyViewOfFlag(std::string_view flag) {
    for (const FamilyViewEntry& v : familyViews())
        for (const Knob& f : v.flags)
            if (f.flag == flag) return &v;
    return nullptr;
}

}  // namespace gridcull
