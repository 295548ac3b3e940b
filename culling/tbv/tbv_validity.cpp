#include "culling/tbv/tbv_validity.h"

#include <algorithm>

namespace gridcull {

void TbvValidityPeriods::reset(size_t n, TbvValidityMode mode, double initial, double floor) {
    mode_ = mode;
    floor_ = std::min(floor, initial);
    ceiling_ = initial * kTbvMaxPeriodFactor;
    periods_.assign(n, initial);
}

void TbvValidityPeriods::expired(int object) {
    if (mode_ != TbvValidityMode::Adaptive) return;
    double& p = periods_[size_t(object)];
    p = std::min(p * 2.0, ceiling_);
}

void TbvValidityPeriods::revealed(int object, double used) {
    if (mode_ != TbvValidityMode::Adaptive) return;
    double& p = periods_[size_t(object)];
    p = std::max(std::min(p, used) * 0.5, floor_);
}

}  // namespace gridcull
