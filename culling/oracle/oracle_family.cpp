#include "culling/oracle/oracle_family.h"

#include "culling/oracle/exact_oracle.h"

namespace gridcull {

const KnobTable<OracleOptions>& oracleKnobs() {
    static const KnobTable<OracleOptions> table{
        knob("oracle-res", &OracleOptions::resolution, kMinOracleResolution, kMaxOracleResolution,
             "3D: pixels on the long side of the oracle's ID buffer; an object seen only "
             "through a gap narrower than a pixel is missed, so higher finds more false "
             "culls, at about quadratic cost"),
        knob("oracle-rays", &OracleOptions::rays_per_turn, 0, kMaxOracleRaysPerTurn,
             "2D: 0 finds the visible set exactly (an angular envelope with no sampling); "
             "N > 0 samples N rays per full turn instead, a cross-check that misses "
             "slivers narrower than a ray, at cost linear in N"),
        knob("oracle-refine", &OracleOptions::refine, 0, 1,
             "3D: 1 casts finer rays (Embree, up to 12 x 12 a pixel) wherever an object no "
             "pixel centre saw may show between centres, and reports what they see or "
             "cannot decide as sub-sample, at 1.2x to 14x the oracle's time on the shipped "
             "scenes (8 to 170 ms a frame; 1.2 s on bunnies-3d); "
             "0 asks the pixel centres alone"),
    };
    return table;
}

OracleOptions oracleOptions(const KnobValues& values) {
    return oracleKnobs().read(values);
}

FamilyEntry oracleFamily() {
    FamilyEntry family;
    family.id = "oracle";
    family.title = "Exact visibility oracle";
    family.algorithms = {{"exact", kRunsBoth, "the exact visible set, the reference"}};
    family.knobs = oracleKnobs().knobs();
    family.reference = true;
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        return std::make_unique<ExactOracle>(oracleOptions(*request.knobs));
    };
    return family;
}

}  // namespace gridcull
