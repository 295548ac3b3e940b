// The sweep's loop: scene after scene, seeds base, base + 1, ... (each scene's
// seed is the base plus its counter, so a run is reproducible and one scene
// replays by its seed alone), made replayable (sweep_scenes.h), checked
// (sweep_check.h), on several threads until the time or the scene count is
// up. A scene with a false cull is written to the output folder as
// sweep-SEED.json, which `gridcull cull FILE --algo A --oracle-res R` replays.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/sweep/sweep_check.h"

namespace gridcull::sweep {

struct SweepOptions {
    uint64_t base_seed = 1;
    double seconds = 0.0;              // stop starting scenes after this long (0: no limit)
    int64_t scenes = -1;               // or after this many (-1: no limit)
    std::vector<uint64_t> only_seeds;  // when set, exactly these scenes
    int threads = 2;
    int resolution = 160;  // --oracle-res; image-space cullers follow it
    std::string out_dir = "sweep-out";
    std::vector<SweepAlgorithm> algorithms;  // conservativeAlgorithms() when empty
    double progress_seconds = 10.0;          // a progress line this often (0: none)
};

struct SweepFailure {
    uint64_t seed = 0;
    std::string kind;
    std::string file;  // the written scene, "" when it could not be written
    FalseCull cull;
};

struct SweepReport {
    std::vector<SweepAlgorithm> algorithms;
    std::vector<AlgorithmTally> tallies;  // one per algorithm
    AlgorithmTally oracle;
    int64_t scenes = 0;
    std::vector<SweepFailure> failures;
    std::vector<std::string> errors;    // scenes that could not be written, broken PVSs
    std::vector<std::string> rejected;  // generated scenes the loader refuses: not checked
    double elapsed = 0.0;               // wall clock, seconds
    double cpu_seconds = 0.0;           // the process's CPU time over all threads

    int64_t sceneFrames() const;
    int64_t falseCulls() const;
};

// The knobs of every culler and the oracle: the oracle's resolution.
KnobValues sweepKnobs(int resolution);

// "gridcull cull FILE --algo A --oracle-res R"
std::string replayCommand(const std::string& file, const std::string& algo, int resolution);

// Runs the sweep; progress lines go to `progress` (may be null).
SweepReport runSweep(const SweepOptions& options, std::FILE* progress);

// Checks one scene as the sweep does and adds it to `report` (a scene file
// given by hand, or one seed); a false cull is written under `out_dir` when
// `seed` names the scene (else the file given stands for itself).
void addScene(const Scene& scene, uint64_t seed, const SweepOptions& options,
              const std::string& given_file, SweepReport& report);

// The per-algorithm table, the totals, and each failure's replay commands.
void printReport(const SweepReport& report, const SweepOptions& options, std::FILE* out);

}  // namespace gridcull::sweep
