// Angle helpers shared by the 2D oracle's exact envelope and its sampled sweep.
#pragma once

namespace gridcull {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.141592653589793238462643383279;

// The signed angle of a turn, wrapped into (-pi, pi].
inline double wrapTurn(double a) {
    while (a > kPi) a -= kTwoPi;
    while (a <= -kPi) a += kTwoPi;
    return a;
}

}  // namespace gridcull
