// The sweep's check of one scene: the exact oracle and every algorithm of the
// family registry that claims to be conservative run the scene's own frames
// (its camera path, t = frame * dt) in order, and each frame's PVS must
// contain every id the oracle reports. An algorithm whose registry entry
// allows `late_frames` (Sudarsky & Gotsman's implicit update: 1) may miss an
// id for that many frames in a row; a longer miss is a false cull, counted
// once per frame it lasts beyond the allowance.
//
// Options follow the oracle as the differential tests set them: one KnobValues
// for the oracle and every culler, so that image-space families draw at the
// oracle's resolution (CullerRequest::reference_resolution).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "culling/api/knobs.h"
#include "culling/scene/scene.h"

namespace gridcull::sweep {

// One algorithm the sweep holds to the oracle.
struct SweepAlgorithm {
    std::string name;
    int late_frames = 0;
};

// Every registered algorithm but the reference, in registry order. Each
// claims to drop nothing the oracle sees (beyond its late_frames).
std::vector<SweepAlgorithm> conservativeAlgorithms();

struct AlgorithmTally {
    int64_t scenes = 0;
    int64_t frames = 0;  // scene-frames checked
    int64_t false_culls = 0;
    double seconds = 0.0;  // in cull(), summed
};

// The first frame at which an algorithm falsely culled on a scene.
struct FalseCull {
    std::string algo;
    int frame = 0;
    double t = 0.0;
    std::vector<int> ids;  // the ids the oracle saw and the PVS lacked (beyond late_frames)
};

struct SceneCheck {
    std::vector<AlgorithmTally> tallies;  // one per algorithm given, in order
    AlgorithmTally oracle;
    std::vector<FalseCull> false_culls;  // the first one of each failing algorithm
    // Algorithms that could not be made, or broke the Culler contract (a PVS
    // not sorted and unique: their scene stops there).
    std::vector<std::string> errors;
};

// Runs the scene's frames for the oracle and each algorithm that fits the
// scene's dimension (algorithmFits; the others are skipped, their tallies
// untouched).
SceneCheck checkScene(const Scene& scene, const std::vector<SweepAlgorithm>& algorithms,
                      const KnobValues& knobs);

}  // namespace gridcull::sweep
