#include "culling/baseline/baseline_family.h"

#include "culling/baseline/all_culler.h"
#include "culling/baseline/vfc_culler.h"

namespace gridcull {

FamilyEntry baselineFamily() {
    FamilyEntry family;
    family.id = "baseline";
    family.title = "Baselines";
    family.algorithms = {
        {"all", kRunsBoth, "no culling: every object (the plain z-buffer, \"ZB\")"},
        {"vfc", kRunsBoth, "view-frustum culling only (\"VFC\")"},
    };
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        if (request.algorithm == "all") return std::make_unique<AllCuller>();
        return std::make_unique<VfcCuller>();
    };
    return family;
}

}  // namespace gridcull
