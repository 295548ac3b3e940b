// The extremes suite's harness: every algorithm of the registry runs
// a case's frames in order, and each frame's PVS is checked against the exact
// oracle (culling/oracle/exact_oracle.h) for false culls: an id the oracle reports that
// the algorithm left out. It must contain every such id, be sorted and unique,
// name only ids of the scene, and each frame must finish within kMaxFrameMs with
// its counters within their bounds (voxels_visited <= voxels of the grid,
// objects_tested <= objects).
//
// An algorithm the registry does not offer for the scene's dimension is not
// run (algorithmFits); its row says
// "skipped" and why, so a skip is visible in the output, never silent. `exact`
// is the reference itself: its row checks only that it finishes, and the case's
// must_see / must_hide ids, which state what the oracle has to report by
// construction of the scene.
//
// Each case prints one line per algorithm (run core_tests with
// --gtest_filter='Extremes*' to see them):
//   [extremes] CASE | ALGO | frames F | false culls N | pvs P / exact E | max X ms
// where P and E are summed over the frames.
//
// Random tests take their seeds from tests/common/test_seeds.h: GRIDCULL_SEED,
// when set, replaces the default seeds by that one, and a failing seed prints
// the one command that runs it again.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/io/scene_loader.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"

namespace gridcull::test {

// Generous even under ASan (about 3x slower): the point is "finishes", not speed.
constexpr double kMaxFrameMs = 5000.0;

struct ExtremeFrame {
    double t = 0.0;
    Camera camera;
    std::vector<int> must_see;   // the oracle must report these ids at this frame
    std::vector<int> must_hide;  // and must not report these
};

struct ExtremeCase {
    std::string name;
    Scene scene;                       // finalized
    std::vector<ExtremeFrame> frames;  // in increasing t
    KnobValues knobs;                  // for the reference oracle and every algorithm
};

// The scene's own camera at the given times.
inline std::vector<ExtremeFrame> framesAt(const Scene& scene, const std::vector<double>& times) {
    std::vector<ExtremeFrame> frames;
    for (const double t : times) frames.push_back({t, cameraAt(scene, t), {}, {}});
    return frames;
}

inline void expectAll(std::vector<ExtremeFrame>& frames, const std::vector<int>& see,
                      const std::vector<int>& hide) {
    for (ExtremeFrame& f : frames) {
        f.must_see = see;
        f.must_hide = hide;
    }
}

// One algorithm's results on one case.
struct ExtremeRow {
    std::string algo;
    bool skipped = false;
    std::string why;
    int frames = 0;
    int64_t false_culls = 0;
    int64_t pvs = 0;
    int64_t exact = 0;
    double max_ms = 0.0;
};

inline std::string idList(const std::vector<int>& ids) {
    std::string s;
    for (const int id : ids) s += (s.empty() ? "" : " ") + std::to_string(id);
    return "{" + s + "}";
}

inline void printRow(const std::string& case_name, const ExtremeRow& row) {
    if (row.skipped) {
        std::printf("[extremes] %s | %s | skipped: %s\n", case_name.c_str(), row.algo.c_str(),
                    row.why.c_str());
    } else {
        std::printf(
            "[extremes] %s | %s | frames %d | false culls %lld | pvs %lld / exact %lld | "
            "max %.1f ms\n",
            case_name.c_str(), row.algo.c_str(), row.frames, (long long)row.false_culls,
            (long long)row.pvs, (long long)row.exact, row.max_ms);
    }
    std::fflush(stdout);
}

// Checks the frame-independent validity of one PVS; returns its false culls.
// `late`: for an algorithm with late_frames 1 (its registry entry), the ids
// missed in the frame before; an id missed now but not then is one frame late,
// allowed, and comes back in it for the next frame. Null: every miss counts.
inline int64_t checkFrame(const Scene& scene, const std::vector<int>& reference,
                          const FrameResult& out, const std::string& where,
                          std::vector<int>* late = nullptr) {
    const std::vector<int>& pvs = out.pvs;
    EXPECT_TRUE(std::adjacent_find(pvs.begin(), pvs.end(), [](int a, int b) { return a >= b; }) ==
                pvs.end())
        << where << ": PVS not sorted and unique";
    for (const int id : pvs) EXPECT_GE(scene.indexOf(id), 0) << where << ": unknown id " << id;
    std::vector<int> missed;
    std::set_difference(reference.begin(), reference.end(), pvs.begin(), pvs.end(),
                        std::back_inserter(missed));
    if (late) {
        std::vector<int> again;  // missed in the frame before too: longer than one frame
        std::set_intersection(missed.begin(), missed.end(), late->begin(), late->end(),
                              std::back_inserter(again));
        *late = missed;
        missed = again;
    }
    EXPECT_TRUE(missed.empty()) << where << ": false culls " << idList(missed);
    if (out.stats.has(Counter::VoxelsVisited)) {
        EXPECT_LE(out.stats.get(Counter::VoxelsVisited), scene.grid.voxelCount())
            << where << ": visited more voxels than the grid has";
    }
    if (out.stats.has(Counter::ObjectsTested)) {
        EXPECT_LE(out.stats.get(Counter::ObjectsTested), int64_t(scene.objects.size())) << where;
    }
    for (int c = 0; c < kCounterCount; ++c)
        EXPECT_GE(out.stats.values[size_t(c)], 0)
            << where << ": negative " << counterName(Counter(c));
    EXPECT_LT(out.stats.cull_ms, kMaxFrameMs) << where << ": frame took too long";
    return int64_t(missed.size());
}

// Runs `c` for every algorithm and returns the rows (also printed).
inline std::vector<ExtremeRow> runExtremeCase(const ExtremeCase& c) {
    SCOPED_TRACE("case " + c.name);
    std::vector<ExtremeRow> rows;
    // The reference, one PVS per frame, from a fresh oracle.
    ExactOracle oracle{oracleOptions(c.knobs)};
    oracle.reset(c.scene);
    std::vector<std::vector<int>> reference;
    ExtremeRow exact_row;
    exact_row.algo = "exact";
    for (size_t f = 0; f < c.frames.size(); ++f) {
        const ExtremeFrame& frame = c.frames[f];
        FrameResult out;
        timedCull(oracle, c.scene, frame.camera, frame.t, out);
        const std::string where = c.name + " exact frame " + std::to_string(f);
        checkFrame(c.scene, {}, out, where);
        for (const int id : frame.must_see)
            EXPECT_TRUE(std::binary_search(out.pvs.begin(), out.pvs.end(), id))
                << where << ": the oracle misses id " << id << ", visible by construction; got "
                << idList(out.pvs);
        for (const int id : frame.must_hide)
            EXPECT_FALSE(std::binary_search(out.pvs.begin(), out.pvs.end(), id))
                << where << ": the oracle reports id " << id << ", hidden by construction";
        exact_row.frames++;
        exact_row.pvs += int64_t(out.pvs.size());
        exact_row.exact += int64_t(out.pvs.size());
        exact_row.max_ms = std::max(exact_row.max_ms, out.stats.cull_ms);
        reference.push_back(out.pvs);
    }
    for (const std::string& name : algorithmNames()) {
        if (name == "exact") {
            rows.push_back(exact_row);
            printRow(c.name, exact_row);
            continue;
        }
        std::string error;
        ExtremeRow row;
        row.algo = name;
        if (!algorithmFits(name, c.scene, row.why)) {
            row.skipped = true;
            rows.push_back(row);
            printRow(c.name, row);
            continue;
        }
        std::unique_ptr<Culler> culler = makeCuller(name, c.knobs, error);
        EXPECT_TRUE(culler) << error;
        if (!culler) continue;
        const AlgorithmEntry* entry = nullptr;
        familyOfAlgorithm(name, &entry);
        EXPECT_LE(entry->late_frames, 1) << name << ": the harness checks one late frame at most";
        std::vector<int> late;
        culler->reset(c.scene);
        FrameResult out;
        for (size_t f = 0; f < c.frames.size(); ++f) {
            const ExtremeFrame& frame = c.frames[f];
            timedCull(*culler, c.scene, frame.camera, frame.t, out);
            row.false_culls +=
                checkFrame(c.scene, reference[f], out,
                           c.name + " " + name + " frame " + std::to_string(f),
                           entry->late_frames > 0 ? &late : nullptr);
            row.frames++;
            row.pvs += int64_t(out.pvs.size());
            row.exact += int64_t(reference[f].size());
            row.max_ms = std::max(row.max_ms, out.stats.cull_ms);
        }
        rows.push_back(row);
        printRow(c.name, row);
    }
    return rows;
}

// Loads scene text and returns its errors joined by newlines ("" when it loaded).
inline std::string loadErrors(const std::string& text) {
    const SceneLoadResult result = loadSceneText(text, "extreme.json", ".");
    std::string joined;
    for (const std::string& e : result.errors) joined += e + "\n";
    return joined;
}

}  // namespace gridcull::test
