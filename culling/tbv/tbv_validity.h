// Validity periods of temporal bounding volumes (Sudarsky & Gotsman, "Dynamic
// scene occlusion culling", section 3.4), per object, apart from any spatial
// structure.
//
// Fixed: every TBV gets the same period. Adaptive: a TBV that expired before it
// was seen was too short, so the object's next one is twice as long (up to
// kTbvMaxPeriodFactor times the initial period); one that was seen before it
// expired was too big, so the next one is half as long (down to the floor the
// caller gives, typically one frame). Objects in hidden regions are then sampled
// less and less often, and a period set too long corrects itself instead of
// having its TBV revealed every frame.
#pragma once
#include <cstddef>
#include <vector>

namespace gridcull {

constexpr double kTbvMaxPeriodFactor = 64.0;

enum class TbvValidityMode { Fixed, Adaptive };

class TbvValidityPeriods {
public:
    // Every object [0, n) starts at `initial` seconds; adaptive periods stay in
    // [floor, initial * kTbvMaxPeriodFactor] (floor is raised to at most initial).
    void reset(size_t n, TbvValidityMode mode, double initial, double floor);
    TbvValidityMode mode() const { return mode_; }
    // The period for the object's next TBV, seconds.
    double period(int object) const { return periods_[size_t(object)]; }
    // The object's TBV ran out before anything saw it.
    void expired(int object);
    // The object's TBV, made with a period of `used` seconds (the caller may
    // have shortened the object's period), was seen before it ran out.
    void revealed(int object, double used);

private:
    TbvValidityMode mode_ = TbvValidityMode::Fixed;
    double floor_ = 0.0;
    double ceiling_ = 0.0;
    std::vector<double> periods_;
};

}  // namespace gridcull
