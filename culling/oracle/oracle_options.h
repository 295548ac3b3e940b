// The exact oracle's knobs (culling/oracle/exact_oracle.h): how finely it
// samples in 3D, and in 2D whether it samples at all, which is the limit of what
// any test or the window can call a false cull. They apply wherever the oracle
// runs (the window's false-cull check, bench's quality columns), not only to
// `--algo exact`.
#pragma once
#include "culling/api/knobs.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

// The default image side of the oracle, and so of every image-space culler
// that follows it.
constexpr int kDefaultOracleResolution = kDefaultImageResolution;
// The smallest value --oracle-res takes: below it the oracle resolves too little
// to be worth calling exact. --oracle-rays takes 0 (exact, no sampling) and up;
// a sampled wedge gets at least 64 rays (ExactOracle::rayCount).
constexpr int kMinOracleResolution = 16;
// The largest the oracle honours, so that no option can ask for more memory than
// a desktop has: 8192 x 4608 pixels take about 470 MiB (depth, id and parity per
// pixel), 2^22 rays about 64 MiB.
constexpr int kMaxOracleResolution = kMaxImageResolution;
constexpr int kMaxOracleRaysPerTurn = 1 << 22;

struct OracleOptions {
    int resolution = kDefaultOracleResolution;  // 3D: pixels on the long side of the ID buffer
    // 2D: 0 = the exact angular envelope (culling/oracle/exact_oracle_2d.h); N > 0 =
    // the sampled angular sweep with N rays per full turn, a cross-check.
    int rays_per_turn = 0;
    int refine = 0;  // 3D: 1 asks about the objects that may show between pixel centres
};

const KnobTable<OracleOptions>& oracleKnobs();
// The oracle's options out of `values` (defaults where unset).
OracleOptions oracleOptions(const KnobValues& values);

}  // namespace gridcull
