#include "culling/oracle/oracle_family.h"

#include "culling/oracle/exact_oracle.h"

namespace gridcull {

const KnobTable<OracleOptions>& oracleKnobs() {
    static const KnobTable<OracleOptions> table{
        knob("oracle-res", &OracleOptions::resolution, kMinOracleResolution, kMaxOracleResolution,
             "3D: pixels on the long side of the oracle's ID buffer; an object seen only "
             "through a gap narrower than a pixel is missed, so higher finds more false "
             "culls, at about quadratic cost"),
        knob("oracle-rays", &OracleOptions::rays_per_turn, kMinOracleRaysPerTurn,
             kMaxOracleRaysPerTurn,
             "2D: rays of the oracle's angular sweep per full turn; more resolve thinner "
             "slivers, at linear cost"),
        knob("oracle-refine", &OracleOptions::refine, 0, 1,
             "3D: 1 casts finer rays (Embree, up to 12 x 12 a pixel) wherever an object no "
             "pixel centre saw may show between centres, and reports what they see or "
             "cannot decide as sub-sample, at 0.5 to 2.5 s a frame on the shipped scenes; "
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
