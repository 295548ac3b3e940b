// `gridcull bench SCENE --algo A[,B...] --seek F[,G...]`: what scrubbing costs
// in the window. For each algorithm and each frame F, R times: a step forward
// from F-1 into F, and a step back from F+1 into F, through the window's own
// culling session (ui/debugger_session.h: its checkpoints, its oracle), timed
// with a steady clock. Prints the medians and 95th percentiles, back over
// forward, the frames each step culled, and the checkpoints' count, spacing
// and memory once every frame up to the last F has been visited.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/app_cullers.h"
#include "app/cli.h"
#include "app/cli_commands.h"
#include "ui/debugger_session.h"

namespace gridcull {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    const size_t i = std::min(values.size() - 1, size_t(p * double(values.size() - 1) + 0.5));
    return values[i];
}

bool parseFrames(const std::string& list, int frames, std::vector<int>& out, std::string& error) {
    std::stringstream in(list);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long value = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || value < 1 || value > frames - 2) {
            error = "--seek: '" + item + "' is not a frame from 1 to " +
                    std::to_string(frames - 2) + " (a step back into F starts at F+1)";
            return false;
        }
        out.push_back(int(value));
    }
    if (out.empty()) error = "--seek: no frame given";
    return !out.empty();
}

}  // namespace

int runSeekBench(const BenchCommand& c, const Scene& scene, const std::vector<AlgoVariant>& algos) {
    std::string error;
    std::vector<int> frames;
    if (!parseFrames(c.seek, scene.frames, frames, error)) return usageError("bench", error);
    const int runs = int(c.runs);
    std::printf("scene: %s, %d frames; steps into frames %s, %d runs each\n", scene.name.c_str(),
                scene.frames, c.seek.c_str(), runs);
    std::printf("%-16s %6s %12s %12s %12s %12s %8s %9s %9s\n", "algorithm", "frame", "fwd med ms",
                "fwd p95 ms", "back med ms", "back p95 ms", "back/fwd", "fwd culls", "back culls");
    for (const AlgoVariant& algo : algos) {
        if (registryAlgorithmOf(algo.name) != algo.name)
            return usageError("bench",
                              "--seek times the window's session, which runs "
                              "software cullers only: '" +
                                  algo.label + "' is not one");
        DebuggerSession session(algo.knobs);
        if (!session.open(scene, "", algo.name, error)) {
            std::cerr << "gridcull bench: " << algo.label << ": " << error << "\n";
            return kExitFailure;
        }
        for (const int frame : frames) {
            std::vector<double> forward, back;
            int forward_culls = 0, back_culls = 0;
            for (int run = 0; run < runs; ++run) {
                session.seek(frame - 1);
                auto start = std::chrono::steady_clock::now();
                session.step();
                forward.push_back(msSince(start));
                forward_culls = std::max(forward_culls, session.lastReplayedFrames());
                session.step();
                start = std::chrono::steady_clock::now();
                session.seek(frame);
                back.push_back(msSince(start));
                back_culls = std::max(back_culls, session.lastReplayedFrames());
            }
            const double fwd = percentile(forward, 0.5), bck = percentile(back, 0.5);
            std::printf("%-16s %6d %12.2f %12.2f %12.2f %12.2f %8.2f %9d %9d\n", algo.label.c_str(),
                        frame, fwd, percentile(forward, 0.95), bck, percentile(back, 0.95),
                        fwd > 0.0 ? bck / fwd : 0.0, forward_culls, back_culls);
        }
        const CullerCheckpoints& saved = session.checkpoints();
        if (saved.enabled())
            std::printf(
                "%-16s checkpoints: %d, every %d frames near the current one, widest "
                "gap %d, %.1f MiB (budget %.0f MiB)\n",
                algo.label.c_str(), saved.count(), saved.interval(), saved.widestGap(),
                double(saved.bytes()) / (1 << 20), double(saved.budget()) / (1 << 20));
        else
            std::printf("%-16s checkpoints: none (the culler cannot be copied)\n",
                        algo.label.c_str());
        std::fflush(stdout);
    }
    return kExitOk;
}

}  // namespace gridcull
